/*
 * OpenCL runtime for the kernels in cl/ (see ocl.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/err.h"
#include "base/ocl.h"

const char *ocl_strerror(cl_int err)
{
	switch (err) {
#define E(x) case x: return #x;
	E(CL_SUCCESS) E(CL_DEVICE_NOT_FOUND) E(CL_DEVICE_NOT_AVAILABLE)
	E(CL_COMPILER_NOT_AVAILABLE) E(CL_MEM_OBJECT_ALLOCATION_FAILURE)
	E(CL_OUT_OF_RESOURCES) E(CL_OUT_OF_HOST_MEMORY)
	E(CL_BUILD_PROGRAM_FAILURE) E(CL_INVALID_VALUE)
	E(CL_INVALID_DEVICE) E(CL_INVALID_CONTEXT) E(CL_INVALID_PLATFORM)
	E(CL_INVALID_COMMAND_QUEUE) E(CL_INVALID_MEM_OBJECT)
	E(CL_INVALID_BINARY) E(CL_INVALID_BUILD_OPTIONS)
	E(CL_INVALID_PROGRAM) E(CL_INVALID_PROGRAM_EXECUTABLE)
	E(CL_INVALID_KERNEL_NAME) E(CL_INVALID_KERNEL)
	E(CL_INVALID_ARG_INDEX) E(CL_INVALID_ARG_VALUE)
	E(CL_INVALID_ARG_SIZE) E(CL_INVALID_KERNEL_ARGS)
	E(CL_INVALID_WORK_DIMENSION) E(CL_INVALID_WORK_GROUP_SIZE)
	E(CL_INVALID_WORK_ITEM_SIZE) E(CL_INVALID_GLOBAL_OFFSET)
	E(CL_INVALID_BUFFER_SIZE) E(CL_INVALID_GLOBAL_WORK_SIZE)
	E(CL_PLATFORM_NOT_FOUND_KHR)
#undef E
	default: return "an unknown OpenCL error";
	}
}

int ocl_fail(cl_int err, const char *what)
{
	return frs_fail("OpenCL: %s: %s (%d)", what, ocl_strerror(err),
	    (int)err);
}

/* PoCL caches compiled kernels and fails without a writable cache. */
static void pocl_cache(void)
{
	char dir[512];
	const char *base = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");

	if (getenv("POCL_CACHE_DIR") != NULL)
		return;
	if (base != NULL && *base)
		snprintf(dir, sizeof dir, "%s/frs-pocl", base);
	else if (home != NULL && *home) {
		char c[480];
		snprintf(c, sizeof c, "%s/.cache", home);
		mkdir(c, 0700);
		snprintf(dir, sizeof dir, "%s/frs-pocl", c);
	} else
		snprintf(dir, sizeof dir, "/tmp/frs-pocl-%lu",
		    (unsigned long)getuid());
	if ((mkdir(dir, 0700) == 0 || errno == EEXIST) &&
	    access(dir, W_OK) == 0)
		setenv("POCL_CACHE_DIR", dir, 0);
	else {
		snprintf(dir, sizeof dir, "/tmp/frs-pocl-%lu",
		    (unsigned long)getuid());
		mkdir(dir, 0700);
		setenv("POCL_CACHE_DIR", dir, 0);
	}
}

/* Every device, GPUs of each platform first: ids[0..*n-1]. */
static int devices(cl_device_id *ids, cl_platform_id *plat, unsigned max,
    unsigned *n)
{
	cl_platform_id p[16];
	cl_uint np = 0;
	cl_int err;

	pocl_cache();
	err = clGetPlatformIDs(16, p, &np);
	if (err == CL_PLATFORM_NOT_FOUND_KHR || (err == CL_SUCCESS && np == 0)) {
		const char *c = getenv("POCL_CACHE_DIR");
		if (c != NULL && access(c, W_OK) != 0)
			return frs_fail("OpenCL: no platform found; PoCL needs a "
			    "writable kernel cache and POCL_CACHE_DIR=%s is "
			    "not writable", c);
		return frs_fail("OpenCL: no platform found (is an ICD such as "
		    "pocl-opencl-icd installed?)");
	}
	if (err != CL_SUCCESS)
		return ocl_fail(err, "clGetPlatformIDs");
	*n = 0;
	for (cl_uint i = 0; i < np; i++) {
		static const cl_device_type types[2] = { CL_DEVICE_TYPE_GPU,
		    CL_DEVICE_TYPE_CPU | CL_DEVICE_TYPE_ACCELERATOR |
		    CL_DEVICE_TYPE_CUSTOM };
		for (int t = 0; t < 2; t++) {
			cl_uint nd = 0;
			if (*n >= max)
				break;
			if (clGetDeviceIDs(p[i], types[t], max - *n, ids + *n,
			    &nd) != CL_SUCCESS)
				continue;
			for (cl_uint d = 0; d < nd; d++)
				plat[*n + d] = p[i];
			*n += nd;
		}
	}
	if (*n == 0) {
		const char *c = getenv("POCL_CACHE_DIR");
		if (c != NULL && access(c, W_OK) != 0)
			return frs_fail("OpenCL: no device found; PoCL needs a "
			    "writable kernel cache and POCL_CACHE_DIR=%s is "
			    "not writable", c);
		return frs_fail("OpenCL: no device found");
	}
	return 0;
}

int ocl_list(FILE *fp)
{
	cl_device_id ids[64];
	cl_platform_id plat[64];
	unsigned n;

	if (devices(ids, plat, 64, &n) < 0)
		return -1;
	for (unsigned i = 0; i < n; i++) {
		char pn[256] = "", dn[256] = "", ext[4096] = "";
		cl_uint cu = 0;
		cl_ulong mem = 0;
		cl_device_type type = 0;
		clGetPlatformInfo(plat[i], CL_PLATFORM_NAME, sizeof pn, pn, NULL);
		clGetDeviceInfo(ids[i], CL_DEVICE_NAME, sizeof dn, dn, NULL);
		clGetDeviceInfo(ids[i], CL_DEVICE_MAX_COMPUTE_UNITS, sizeof cu,
		    &cu, NULL);
		clGetDeviceInfo(ids[i], CL_DEVICE_GLOBAL_MEM_SIZE, sizeof mem,
		    &mem, NULL);
		clGetDeviceInfo(ids[i], CL_DEVICE_TYPE, sizeof type, &type, NULL);
		clGetDeviceInfo(ids[i], CL_DEVICE_EXTENSIONS, sizeof ext, ext,
		    NULL);
		fprintf(fp, "cl:%u\t%s\t%s\t%s\t%u compute units\t%.1f GiB\t%s\n",
		    i, pn, dn, type & CL_DEVICE_TYPE_GPU ? "gpu" :
		    type & CL_DEVICE_TYPE_CPU ? "cpu" : "other", cu,
		    (double)mem / 1073741824.0,
		    strstr(ext, "cl_khr_fp64") ? "fp64" : "no fp64");
	}
	return 0;
}

int ocl_parse_device(const char *s, int *index)
{
	char *end;
	long v;

	if (strcmp(s, "cpu") == 0)
		return 0;
	if (strcmp(s, "cl") == 0) {
		*index = -1;
		return 1;
	}
	/* Any number N parses: whether device N exists is ocl_open's to say
	 * (one too large for an int is INT_MAX, which none has). */
	if (strncmp(s, "cl:", 3) == 0 && s[3] >= '0' && s[3] <= '9') {
		errno = 0;
		v = strtol(s + 3, &end, 10);
		if (*end == '\0') {
			*index = errno == ERANGE || v > INT_MAX ? INT_MAX : (int)v;
			return 1;
		}
	}
	return frs_fail("'%s' is not cpu, cl or cl:N", s);
}

int ocl_open(struct ocl *o, int index)
{
	cl_device_id ids[64];
	cl_platform_id plat[64];
	unsigned n, k;
	cl_int err;
	char ext[4096] = "";

	memset(o, 0, sizeof *o);
	if (devices(ids, plat, 64, &n) < 0)
		return -1;
	k = index < 0 ? 0 : (unsigned)index;
	if (k >= n && index == INT_MAX)
		return frs_fail("OpenCL: no device of so large a number (%u "
		    "device%s)", n, n == 1 ? "" : "s");
	if (k >= n)
		return frs_fail("OpenCL: no device cl:%u (%u device%s)", k, n,
		    n == 1 ? "" : "s");
	o->device = ids[k];
	o->platform = plat[k];
	clGetDeviceInfo(o->device, CL_DEVICE_NAME, sizeof o->name, o->name,
	    NULL);
	clGetDeviceInfo(o->device, CL_DEVICE_EXTENSIONS, sizeof ext, ext, NULL);
	o->fp64 = strstr(ext, "cl_khr_fp64") != NULL;
	o->ctx = clCreateContext(NULL, 1, &o->device, NULL, NULL, &err);
	if (err != CL_SUCCESS)
		return ocl_fail(err, "creating a context");
	o->q = clCreateCommandQueue(o->ctx, o->device, 0, &err);
	if (err != CL_SUCCESS) {
		clReleaseContext(o->ctx);
		o->ctx = NULL;
		return ocl_fail(err, "creating a queue");
	}
	return 0;
}

void ocl_close(struct ocl *o)
{
	if (o->q != NULL)
		clReleaseCommandQueue(o->q);
	if (o->ctx != NULL)
		clReleaseContext(o->ctx);
	o->q = NULL;
	o->ctx = NULL;
}

int ocl_program(struct ocl *o, const char *name, const char *options,
    cl_program *prog)
{
	const char *src = ocl_source(name);

	if (src == NULL)
		return frs_fail("OpenCL: no kernel source '%s'", name);
	return ocl_build(o, name, src, options, prog);
}

int ocl_build(struct ocl *o, const char *name, const char *text,
    const char *options, cl_program *prog)
{
	const char *src[4] = { ocl_source("defs"), ocl_source("rng"),
	    ocl_source("tile"), text };
	cl_int err;

	*prog = clCreateProgramWithSource(o->ctx, 4, src, NULL, &err);
	if (err != CL_SUCCESS)
		return ocl_fail(err, name);
	err = clBuildProgram(*prog, 1, &o->device, options ? options : "",
	    NULL, NULL);
	if (err != CL_SUCCESS) {
		char log[4096] = "";
		size_t len = 0;
		clGetProgramBuildInfo(*prog, o->device, CL_PROGRAM_BUILD_LOG,
		    sizeof log - 1, log, &len);
		log[len < sizeof log ? len : sizeof log - 1] = '\0';
		while (len > 0 && (log[len - 1] == '\n' || log[len - 1] == '\0'))
			log[--len] = '\0';
		clReleaseProgram(*prog);
		*prog = NULL;
		return frs_fail("OpenCL: building cl/%s.cl for %s failed: %s%s%s",
		    name, o->name, ocl_strerror(err), *log ? ":\n" : "", log);
	}
	return 0;
}

int ocl_kernel(cl_program prog, const char *name, cl_kernel *k)
{
	cl_int err;

	*k = clCreateKernel(prog, name, &err);
	if (err != CL_SUCCESS)
		return ocl_fail(err, name);
	return 0;
}

void ocl_release_mem(cl_mem *b)
{
	if (*b != NULL)
		clReleaseMemObject(*b);
	*b = NULL;
}

void ocl_release_kernel(cl_kernel *k)
{
	if (*k != NULL)
		clReleaseKernel(*k);
	*k = NULL;
}

void ocl_release_program(cl_program *prog)
{
	if (*prog != NULL)
		clReleaseProgram(*prog);
	*prog = NULL;
}

int ocl_buffer(struct ocl *o, cl_mem_flags flags, size_t size,
    const void *host, cl_mem *b)
{
	cl_int err;

	if (host != NULL && size > 0 && !(flags & CL_MEM_USE_HOST_PTR))
		flags |= CL_MEM_COPY_HOST_PTR;
	if (size == 0)	/* one byte of nothing: there is no host data */
		flags &= ~(cl_mem_flags)(CL_MEM_COPY_HOST_PTR | CL_MEM_USE_HOST_PTR);
	*b = clCreateBuffer(o->ctx, flags, size ? size : 1,
	    size ? (void *)(uintptr_t)host : NULL, &err);
	if (err != CL_SUCCESS) {
		*b = NULL;
		return frs_fail("OpenCL: a buffer of %zu bytes on %s: %s", size,
		    o->name, ocl_strerror(err));
	}
	return 0;
}

int ocl_read(struct ocl *o, cl_mem b, size_t size, void *host)
{
	cl_int err;

	if (size == 0)
		return 0;
	err = clEnqueueReadBuffer(o->q, b, CL_TRUE, 0, size, host, 0, NULL,
	    NULL);
	return err == CL_SUCCESS ? 0 : ocl_fail(err, "reading a buffer");
}

int ocl_write(struct ocl *o, cl_mem b, size_t size, const void *host)
{
	cl_int err;

	if (size == 0)
		return 0;
	err = clEnqueueWriteBuffer(o->q, b, CL_TRUE, 0, size, host, 0, NULL,
	    NULL);
	return err == CL_SUCCESS ? 0 : ocl_fail(err, "writing a buffer");
}

int ocl_fill32(struct ocl *o, cl_mem b, size_t size, uint32_t value)
{
	cl_int err;

	if (size == 0)
		return 0;
	err = clEnqueueFillBuffer(o->q, b, &value, sizeof value, 0,
	    size & ~(size_t)3, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clFinish(o->q);
	return err == CL_SUCCESS ? 0 : ocl_fail(err, "filling a buffer");
}

int ocl_args(cl_kernel k, unsigned n, ...)
{
	va_list ap;
	cl_int err = CL_SUCCESS;

	va_start(ap, n);
	for (unsigned i = 0; i < n && err == CL_SUCCESS; i++) {
		size_t size = va_arg(ap, size_t);
		const void *p = va_arg(ap, const void *);
		err = clSetKernelArg(k, i, size, p);
		if (err != CL_SUCCESS) {
			va_end(ap);
			return frs_fail("OpenCL: kernel argument %u: %s", i,
			    ocl_strerror(err));
		}
	}
	va_end(ap);
	return 0;
}

int ocl_run(struct ocl *o, cl_kernel k, size_t global, size_t local)
{
	cl_int err;
	size_t g = global;

	if (global == 0)
		return 0;
	if (local > 0)
		g = (global + local - 1) / local * local;
	err = clEnqueueNDRangeKernel(o->q, k, 1, NULL, &g,
	    local > 0 ? &local : NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clFinish(o->q);
	return err == CL_SUCCESS ? 0 : ocl_fail(err, "running a kernel");
}
