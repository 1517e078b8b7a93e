/*
 * Hierarchical Sample Warping on an OpenCL device (cl/hsw.cl): the same
 * points as frs_hsw_warp, bit for bit and in the same order.
 * The quadtree is built on the host (frs_hsw_new, described by
 * frs_hsw_info) and uploaded once; each
 * work-item warps one point by the CPU's operations in double.  A device
 * without double precision (cl_khr_fp64) is refused with a message: its
 * points could not equal the CPU's.
 */
#ifndef FRS_HSWCL_H
#define FRS_HSWCL_H

#include <stdint.h>

#include "frs.h"
#include "cli/cli.h"

struct hswcl {
	struct ocl *o;
	struct frs_hsw_info t;	/* the tree's shape and its sums */
	cl_program prog;
	cl_kernel k;
	cl_mem sum;		/* the tree's sums */
	cl_mem pts;		/* points, warped in place, one chunk at a time */
	uint64_t cap;		/* points pts holds */
	uint64_t max_chunk;	/* most points per chunk */
	size_t local;		/* work-group size */
	/* Seconds spent, summed over the calls: building the program and
	 * uploading the tree (hswcl_init), writing points, running the
	 * kernel, reading points back. */
	double t_setup, t_write, t_kernel, t_read;
};

/* Build the kernel on o's device and upload tree t (frs_hsw_info's),
 * whose frs_hsw must outlive h.  -1 with a message (no fp64, a tree too
 * large for the device, an OpenCL error). */
int hswcl_init(struct hswcl *h, struct ocl *o, const struct frs_hsw_info *t);
void hswcl_free(struct hswcl *h);

/* Warp n points (pairs x, y) from in to out (may be the same array): the
 * contract of frs_hsw_warp, on the device. */
int hswcl_warp_points(struct hswcl *h, const double *in, double *out,
    uint64_t n);

/* hswcl_init, hswcl_warp_points, hswcl_free in one. */
int hswcl_warp(struct ocl *o, const struct frs_hsw_info *t,
    const double *in, double *out, uint64_t n);

#endif
