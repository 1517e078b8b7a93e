/*
 * Hierarchical Sample Warping on an OpenCL device: see hswcl.h and
 * cl/hsw.cl.
 */
#define _POSIX_C_SOURCE 200809L
#include <string.h>

#include "hsw-sample/hswcl.h"
#include "cli/cli.h"

/* Most points per kernel launch (256 MiB of coordinates): larger sets
 * go in chunks, so that the buffer fits the device. */
#define HSWCL_CHUNK ((uint64_t)1 << 24)

/* Nodes of a tree of `levels` levels below the root: (4^(L+1) - 1) / 3. */
static uint64_t tree_nodes(unsigned levels)
{
	return (((uint64_t)1 << (2 * (levels + 1))) - 1) / 3;
}

int hswcl_init(struct hswcl *h, struct ocl *o, const struct frs_hsw_info *t)
{
	cl_ulong maxalloc = 0;
	size_t wg = 0;
	uint64_t bytes = tree_nodes(t->levels) * sizeof(double);
	double t0 = cli_now();

	memset(h, 0, sizeof *h);
	h->o = o;
	h->t = *t;
	if (!o->fp64)
		return cli_fail("OpenCL: %s has no double precision "
		    "(cl_khr_fp64), which hierarchical sample warping on the "
		    "device needs to give the CPU's points", o->name);
	if (clGetDeviceInfo(o->device, CL_DEVICE_MAX_MEM_ALLOC_SIZE,
	    sizeof maxalloc, &maxalloc, NULL) != CL_SUCCESS || maxalloc < 4096)
		maxalloc = (cl_ulong)1 << 27;	/* the minimum OpenCL allows */
	if (bytes > maxalloc)
		return cli_fail("OpenCL: the %ux%u quadtree (%llu bytes) is "
		    "larger than the largest buffer of %s (%llu bytes)",
		    t->side, t->side, (unsigned long long)bytes, o->name,
		    (unsigned long long)maxalloc);
	h->max_chunk = maxalloc / (2 * sizeof(double));
	if (h->max_chunk > HSWCL_CHUNK)
		h->max_chunk = HSWCL_CHUNK;
	if (ocl_program(o, "hsw", NULL, &h->prog) < 0)
		goto fail;
	if (ocl_kernel(h->prog, "hsw_warp", &h->k) < 0)
		goto fail;
	if (ocl_buffer(o, CL_MEM_READ_ONLY, (size_t)bytes,
	    t->sums, &h->sum) < 0)
		goto fail;
	h->local = 64;
	if (clGetKernelWorkGroupInfo(h->k, o->device, CL_KERNEL_WORK_GROUP_SIZE,
	    sizeof wg, &wg, NULL) == CL_SUCCESS && wg > 0 && wg < h->local)
		h->local = wg;
	h->t_setup = cli_now() - t0;
	return 0;
fail:
	hswcl_free(h);
	return -1;
}

void hswcl_free(struct hswcl *h)
{
	ocl_release_mem(&h->pts);
	ocl_release_mem(&h->sum);
	ocl_release_kernel(&h->k);
	ocl_release_program(&h->prog);
	h->cap = 0;
}

/* A point buffer for at least m points, filled before its first use. */
static int reserve(struct hswcl *h, uint64_t m)
{
	size_t bytes = (size_t)m * 2 * sizeof(double);

	if (h->pts != NULL && h->cap >= m)
		return 0;
	if (h->pts != NULL)
		clReleaseMemObject(h->pts);
	h->pts = NULL;
	h->cap = 0;
	if (ocl_buffer(h->o, CL_MEM_READ_WRITE, bytes, NULL, &h->pts) < 0)
		return -1;
	if (ocl_fill32(h->o, h->pts, bytes, 0) < 0)
		return -1;
	h->cap = m;
	return 0;
}

int hswcl_warp_points(struct hswcl *h, const double *in, double *out,
    uint64_t n)
{
	cl_uint levels = h->t.levels, w = h->t.width, ht = h->t.height;

	if (n == 0)
		return 0;
	if (reserve(h, n < h->max_chunk ? n : h->max_chunk) < 0)
		return -1;
	for (uint64_t p = 0; p < n; p += h->max_chunk) {
		cl_ulong m = n - p < h->max_chunk ? n - p : h->max_chunk;
		size_t bytes = (size_t)m * 2 * sizeof(double);
		double t0 = cli_now(), t1, t2;

		if (ocl_write(h->o, h->pts, bytes, in + 2 * p) < 0)
			return -1;
		t1 = cli_now();
		if (ocl_args(h->k, 6, sizeof h->sum, &h->sum, sizeof levels,
		    &levels, sizeof w, &w, sizeof ht, &ht, sizeof h->pts, &h->pts,
		    sizeof m, &m) < 0 ||
		    ocl_run(h->o, h->k, (size_t)m, h->local) < 0)
			return -1;
		t2 = cli_now();
		if (ocl_read(h->o, h->pts, bytes, out + 2 * p) < 0)
			return -1;
		h->t_write += t1 - t0;
		h->t_kernel += t2 - t1;
		h->t_read += cli_now() - t2;
	}
	return 0;
}

int hswcl_warp(struct ocl *o, const struct frs_hsw_info *t,
    const double *in, double *out, uint64_t n)
{
	struct hswcl h;
	int r;

	if (hswcl_init(&h, o, t) < 0)
		return -1;
	r = hswcl_warp_points(&h, in, out, n);
	hswcl_free(&h);
	return r;
}
