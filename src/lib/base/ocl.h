/*
 * OpenCL runtime: platforms, devices, programs built from the kernels in
 * cl/ (embedded in the executables at build time), buffers, and OpenCL
 * errors turned into messages.  OpenCL C 1.2; the setup math stays on the
 * host (frs.c), kernels get integers and emit integers.
 *
 * Devices are named as for --device: "cpu" is not OpenCL; "cl" is the
 * first device of the first platform (GPU before CPU devices), "cl:N" the
 * N-th device in the order of ocl_list.  PoCL needs a writable kernel
 * cache: when POCL_CACHE_DIR is unset, ocl_open sets it to a private
 * directory ($XDG_CACHE_HOME/frs-pocl, or $HOME/.cache/frs-pocl, or
 * /tmp/frs-pocl-UID), created with mode 0700.
 */
#ifndef FRS_OCL_H
#define FRS_OCL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#ifndef CL_PLATFORM_NOT_FOUND_KHR
#define CL_PLATFORM_NOT_FOUND_KHR -1001
#endif

struct ocl {
	cl_platform_id platform;
	cl_device_id device;
	cl_context ctx;
	cl_command_queue q;
	char name[256];		/* device name, for messages */
	int fp64;		/* the device has cl_khr_fp64 */
};

/* Print platform, device, type, compute units, memory and fp64 of every
 * OpenCL device, numbered as for --device cl:N.  -1 with a message when
 * there is no OpenCL platform. */
int ocl_list(FILE *fp);

/* Parse a --device value: 0 for "cpu", 1 for OpenCL ("cl" gives *index
 * -1, "cl:N" gives N); -1 with a message otherwise. */
int ocl_parse_device(const char *s, int *index);

/* Open device index (-1: the first, GPUs first) with a context and an
 * in-order queue. */
int ocl_open(struct ocl *o, int index);
void ocl_close(struct ocl *o);

/* Build a program from the embedded kernel source of that name (the file
 * cl/NAME.cl), with options (may be NULL).  A build failure is an error
 * whose message holds the build log. */
int ocl_program(struct ocl *o, const char *name, const char *options,
    cl_program *prog);
/* The same from source text (after cl/defs.cl, cl/rng.cl and
 * cl/tile.cl); name for messages. */
int ocl_build(struct ocl *o, const char *name, const char *text,
    const char *options, cl_program *prog);
/* A kernel of a built program. */
int ocl_kernel(cl_program prog, const char *name, cl_kernel *k);

/* Buffers: create (optionally copied from host memory), read back,
 * write.  Sizes of 0 are allowed (a 1-byte buffer is made). */
int ocl_buffer(struct ocl *o, cl_mem_flags flags, size_t size,
    const void *host, cl_mem *b);
int ocl_read(struct ocl *o, cl_mem b, size_t size, void *host);
int ocl_write(struct ocl *o, cl_mem b, size_t size, const void *host);

/* Release what *x holds, if anything, and leave it NULL: for teardown of
 * objects that a failed setup may not have made. */
void ocl_release_mem(cl_mem *b);
void ocl_release_kernel(cl_kernel *k);
void ocl_release_program(cl_program *prog);
/* Fill a buffer with a 32-bit pattern (device buffers are never used
 * uninitialised: the authors' code was caught doing that on PoCL). */
int ocl_fill32(struct ocl *o, cl_mem b, size_t size, uint32_t value);

/* Set kernel arguments: n pairs (size, pointer). */
int ocl_args(cl_kernel k, unsigned n, ...);
/* Run a 1-D kernel over global work items (rounded up to a multiple of
 * local when local > 0; kernels check their index), and wait. */
int ocl_run(struct ocl *o, cl_kernel k, size_t global, size_t local);

/* The message for an OpenCL status code, e.g. "CL_OUT_OF_RESOURCES". */
const char *ocl_strerror(cl_int err);
/* frs_fail("what: CL_...") and -1. */
int ocl_fail(cl_int err, const char *what);

/* Embedded kernel sources: name (file name without .cl) -> text. */
const char *ocl_source(const char *name);

#endif
