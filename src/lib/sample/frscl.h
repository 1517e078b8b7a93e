/*
 * Forced Random Sampling on OpenCL (thesis Ch. 5, kernels in cl/frs.cl):
 * Naive, Stack, Level 1, Level 2 and Sorted give exactly what frs_sample
 * gives (the same elements in the same order), and Flat 1 (Sec. 5.4),
 * which has no CPU twin, gives Stack's elements in Stack's order.
 *
 * The host does the setup (frs_setup) and turns every pixel's thresholds
 * into integers (limit, floor(T), the coin threshold ceil(frac(T) 2^53)):
 * the device compares integers only and needs no fp64.  One work-item
 * per pixel counts its elements, the host turns the counts into offsets,
 * and a second pass writes them: buffers are sized exactly.  Flat 1
 * keeps a list of candidate blocks per minmap level, each sized from
 * counts as well, so it never truncates.
 */
#ifndef FRS_FRSCL_H
#define FRS_FRSCL_H

#include "sample/frscore.h"
#include "base/ocl.h"

/* frs_sample on device o; algo is an enum frs_impl, FRS_FLAT1 too.
 * Flat 1 needs the minmap in p. */
int frs_sample_cl(struct ocl *o, const struct frs_setup *s,
    const struct frs_imap *map, const struct frs_prep *p, int algo,
    const uint64_t *steps, unsigned nsteps, int count_only,
    struct frs_result *r);

/* Seconds spent in the last frs_sample_cl: building the program (the
 * first call for a device only), the thresholds and copying to the
 * device, in kernels, copying back (with the host's offset scans). */
struct frscl_times {
	double build, upload, kernel, download;
};
void frscl_last_times(struct frscl_times *t);

/* Release what frs_sample_cl keeps for o (the built program); call
 * before ocl_close. */
void frscl_release(struct ocl *o);

#endif
