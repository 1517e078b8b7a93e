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

#include "api/api.h"
#include "hsw-sample/hswcl.h"

struct hsw_run {
	frs_hsw *hw;
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

/* The records of one round: k of them, x, y and with pdf the density
 * I / mean I of the point's pixel (2 or 3 doubles each); non-zero stops
 * the run (-1, the message the callback's). */
typedef int (*hsw_rec_fn)(void *ctx, const double *rec, size_t k);

/* The n points of kind with seed (hsw_input_make), made round by round,
 * or, where pts is not NULL, its n pairs (on the device warped in place;
 * the device needs them), warped and handed to fn in index order. */
int hsw_run_each(struct hsw_run *r, enum hsw_input kind, double *pts,
    uint64_t n, uint64_t seed, int pdf, hsw_rec_fn fn, void *ctx);

/* For -v: the map's size, its padded side and levels, and its mean. */
void hsw_run_shape(const struct hsw_run *r, uint32_t *w, uint32_t *h,
    uint32_t *side, unsigned *levels, double *mean);

#endif
