/*
 * A run of Hierarchical Sample Warping as hsw-sample(1) makes it: what
 * frs_hsw_draw does, with an OpenCL device, the caller's points or a set
 * made on the fly, records of x, y and the density handed out in rounds,
 * and the times -v reports.  The same records, bit for bit, on every
 * device and for any thread count.
 */
#ifndef FRS_HSW_SAMPLE_HSWRUN_H
#define FRS_HSW_SAMPLE_HSWRUN_H

#include <stddef.h>
#include <stdint.h>

#include "frs.h"
#include "hsw-sample/hswcl.h"

struct hsw_run {
	frs_hsw *hw;
	struct frs_hsw_info info;	/* hw's tree */
	int cl;			/* warping on dev */
	struct ocl *dev;	/* cli_device_open's, when cl */
	struct hswcl hc;
	/* Seconds spent: building the quadtree (and with the device, its
	 * program and upload), and warping, summed over the rounds. */
	double t_tree, t_warp;
};

/* Open the device when cl (cl_index, -1: the first), load the map src at
 * w x h (0, 0: its own size) with frs_imap_load's flags and build its
 * quadtree, there too with the device.  -1 with a message (those about
 * the map name src), -2 when the device cannot be opened or cannot take
 * the tree. */
int hsw_run_open(struct hsw_run *r, const char *src, uint32_t w,
    uint32_t h, int flags, int cl, int cl_index);
void hsw_run_close(struct hsw_run *r);

/* The points of one round: k of them, x, y in xy and with pdf the
 * densities I / mean I of their pixels in pdf (else NULL); non-zero stops
 * the run (-1, the message the callback's). */
typedef int (*hsw_rec_fn)(void *ctx, const double *xy, const double *pdf,
    size_t k);

/* The n points of input with seed (frs_hsw_input), made round by round,
 * or, where pts is not NULL, its n pairs (on the device warped in place;
 * the device needs them), warped and handed to fn in index order. */
int hsw_run_each(struct hsw_run *r, enum frs_hsw_input input, double *pts,
    uint64_t n, uint64_t seed, int pdf, hsw_rec_fn fn, void *ctx);

#endif
