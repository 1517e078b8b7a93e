/* The OpenCL runtime on whatever device there is (PoCL in make check):
 * the kernels' Philox against rng.c, buffers filled before use, a build
 * failure with its log, a device that does not exist. */
#include "oclutil.h"

static void philox_matches(void **state)
{
	cl_program prog;
	cl_kernel k;
	cl_mem b;
	const size_t n = 1000;
	uint64_t out[1000], seed = 0x123456789abcdefULL, nn = n;
	uint32_t stream = 5;
	(void)state;
	assert_int_equal(ocl_program(&tu_ocl, "selftest", NULL, &prog), 0);
	assert_int_equal(ocl_kernel(prog, "rand64", &k), 0);
	assert_int_equal(ocl_buffer(&tu_ocl, CL_MEM_WRITE_ONLY, sizeof out,
	    NULL, &b), 0);
	assert_int_equal(ocl_fill32(&tu_ocl, b, sizeof out, 0xdeadbeef), 0);
	assert_int_equal(ocl_args(k, 4, sizeof seed, &seed, sizeof stream,
	    &stream, sizeof nn, &nn, sizeof b, &b), 0);
	assert_int_equal(ocl_run(&tu_ocl, k, n, 64), 0);
	assert_int_equal(ocl_read(&tu_ocl, b, sizeof out, out), 0);
	for (size_t i = 0; i < n; i++)
		assert_true(out[i] == frs_rand64x(seed, stream, i,
		    (uint32_t)i & 7));
	clReleaseMemObject(b);
	clReleaseKernel(k);
	clReleaseProgram(prog);
}

static void fill_is_visible(void **state)
{
	cl_mem b;
	uint32_t v[64];
	(void)state;
	assert_int_equal(ocl_buffer(&tu_ocl, CL_MEM_READ_WRITE, sizeof v, NULL,
	    &b), 0);
	assert_int_equal(ocl_fill32(&tu_ocl, b, sizeof v, 0x01020304), 0);
	assert_int_equal(ocl_read(&tu_ocl, b, sizeof v, v), 0);
	for (int i = 0; i < 64; i++)
		assert_true(v[i] == 0x01020304);
	clReleaseMemObject(b);
}

static void build_failure(void **state)
{
	cl_program prog;
	(void)state;
	assert_int_equal(ocl_build(&tu_ocl, "broken",
	    "__kernel void f(__global int *p) { p[0] = undefined_name; }\n",
	    NULL, &prog), -1);
	assert_err_has("building cl/broken.cl");
	assert_err_has("undefined_name");
	assert_int_equal(ocl_program(&tu_ocl, "no-such-kernel", NULL, &prog),
	    -1);
	assert_err_has("no kernel source 'no-such-kernel'");
}

static void devices(void **state)
{
	struct ocl x;
	int idx;
	FILE *fp = tmpfile();
	char line[512];
	(void)state;
	assert_int_equal(ocl_open(&x, 63), -1);
	assert_err_has("no device cl:63");
	assert_int_equal(ocl_parse_device("cpu", &idx), 0);
	assert_int_equal(ocl_parse_device("cl", &idx), 1);
	assert_int_equal(idx, -1);
	assert_int_equal(ocl_parse_device("cl:2", &idx), 1);
	assert_int_equal(idx, 2);
	assert_int_equal(ocl_parse_device("gpu", &idx), -1);
	assert_int_equal(ocl_parse_device("cl:x", &idx), -1);
	assert_non_null(fp);
	assert_int_equal(ocl_list(fp), 0);
	rewind(fp);
	assert_non_null(fgets(line, sizeof line, fp));
	assert_true(strncmp(line, "cl:0\t", 5) == 0);
	fclose(fp);
}

TU_MAIN(tu_ocl_setup, tu_ocl_teardown,
	cmocka_unit_test(philox_matches),
	cmocka_unit_test(fill_is_visible),
	cmocka_unit_test(build_failure),
	cmocka_unit_test(devices))
