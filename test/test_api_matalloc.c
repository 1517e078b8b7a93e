/*
 * frs_matrix_alloc (frs.h, API 2.2), through frs.h alone as a user has
 * it: the sizes and fields by hand, the values zeroed, the parameters
 * copied; a matrix filled and written read back the same; the refusals,
 * their codes and the ceiling's message with its figure worked out
 * here; the largest count allowed (2^32 values) and the first refused.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frs.h"

/* Every field of a zeroed matrix. */
static void assert_zeroed(const struct frs_matrix *m)
{
	assert_int_equal(m->dims, 0);
	assert_int_equal(m->w, 0);
	assert_int_equal(m->h, 0);
	assert_int_equal(m->d, 0);
	assert_int_equal(m->n, 0);
	assert_null(m->params);
	assert_null(m->v);
}

static void sizes(void **state)
{
	static const struct {
		unsigned dims;
		uint32_t w, h, d;
		const char *params;
	} t[] = {
		{ 2, 16, 8, 1, "method=test\n" },
		{ 2, 1, 1, 1, NULL },
		{ 3, 4, 5, 6, "" },
		{ 3, 7, 1, 1, "a=b\nc=d\n" },
	};
	(void)state;

	for (size_t i = 0; i < sizeof t / sizeof *t; i++) {
		struct frs_matrix m;
		frs_error err = { FRS_E_IO, "stale" };
		size_t n = (size_t)t[i].w * t[i].h * t[i].d;
		char mine[32] = "method=test\n";

		assert_int_equal(frs_matrix_alloc(&m, t[i].dims, t[i].w, t[i].h,
		    t[i].d, t[i].params ? mine : NULL, &err), FRS_OK);
		assert_int_equal(err.code, FRS_OK);
		assert_string_equal(err.message, "");
		assert_int_equal(m.dims, t[i].dims);
		assert_int_equal(m.w, t[i].w);
		assert_int_equal(m.h, t[i].h);
		assert_int_equal(m.d, t[i].d);
		assert_int_equal(m.n, n);
		for (size_t k = 0; k < n; k++)
			assert_int_equal(m.v[k], 0);
		/* A copy: the caller's text may change at once. */
		assert_string_equal(m.params, t[i].params ? "method=test\n" :
		    "");
		assert_true(m.params != mine);
		mine[0] = 'X';
		assert_true(m.params[0] != 'X');
		frs_matrix_free(&m);
		assert_zeroed(&m);
	}
}

/* Filled with a permutation (v = n - 1 - i) and written: the file read
 * back is the same matrix. */
static void fill_write_read(void **state)
{
	struct frs_matrix m, r;
	char path[] = "/tmp/frs-matalloc-XXXXXX";
	int fd = mkstemp(path);
	FILE *fp;
	(void)state;

	assert_true(fd >= 0);
	assert_non_null(fp = fdopen(fd, "wb"));
	assert_int_equal(frs_matrix_alloc(&m, 3, 4, 2, 3, "gen=mine\n", NULL),
	    FRS_OK);
	for (size_t i = 0; i < m.n; i++)
		m.v[i] = (uint32_t)(m.n - 1 - i);
	assert_int_equal(frs_matrix_write(&m, fp, path, NULL), FRS_OK);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_matrix_read(&r, path, NULL), FRS_OK);
	remove(path);
	assert_int_equal(r.dims, 3);
	assert_true(r.w == 4 && r.h == 2 && r.d == 3 && r.n == 24);
	assert_string_equal(r.params, "gen=mine\n");
	assert_memory_equal(r.v, m.v, 24 * sizeof *r.v);
	frs_matrix_free(&r);
	frs_matrix_free(&m);
}

static void refusals(void **state)
{
	static const struct {
		unsigned dims;
		uint32_t w, h, d;
		int code;
	} bad[] = {
		{ 1, 4, 4, 1, FRS_E_ARG }, { 4, 4, 4, 4, FRS_E_ARG },
		{ 0, 4, 4, 1, FRS_E_ARG }, { 2, 4, 4, 2, FRS_E_ARG },
		{ 2, 0, 4, 1, FRS_E_ARG }, { 2, 4, 0, 1, FRS_E_ARG },
		{ 3, 4, 4, 0, FRS_E_ARG },
		/* 2^33 values, under any ceiling: more than a .frd holds */
		{ 3, 65536, 65536, 2, FRS_E_LIMIT },
		{ 3, UINT32_MAX, UINT32_MAX, UINT32_MAX, FRS_E_LIMIT },
	};
	struct frs_matrix m;
	frs_error err;
	(void)state;

	for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
		memset(&m, 0x5a, sizeof m);
		assert_int_equal(frs_matrix_alloc(&m, bad[i].dims, bad[i].w,
		    bad[i].h, bad[i].d, "", &err), bad[i].code);
		assert_int_equal(err.code, bad[i].code);
		assert_true(err.message[0] != '\0');
		assert_zeroed(&m);
	}
	assert_int_equal(frs_matrix_alloc(NULL, 2, 4, 4, 1, "", &err),
	    FRS_E_ARG);
	assert_non_null(strstr(err.message, "NULL"));
	/* No frs_error: the code alone. */
	assert_int_equal(frs_matrix_alloc(&m, 5, 4, 4, 1, "", NULL),
	    FRS_E_ARG);
}

/* The ceiling: 64 x 64 values of 4 bytes are 16384 bytes, 16.0 KiB,
 * above 1k; 2^32 values (65536 x 65536) are not too many, only too
 * large for 1M: FRS_E_NOMEM, not FRS_E_LIMIT, and 16.0 GiB. */
static void ceiling(void **state)
{
	struct frs_matrix m;
	frs_error err;
	(void)state;

	assert_int_equal(setenv("FRS_MAX_MEM", "1k", 1), 0);
	memset(&m, 0x5a, sizeof m);
	assert_int_equal(frs_matrix_alloc(&m, 2, 64, 64, 1, "", &err),
	    FRS_E_NOMEM);
	assert_string_equal(err.message, "64x64 matrix: needs 16.0 KiB, "
	    "above the memory limit of 1.0 KiB (FRS_MAX_MEM)");
	assert_zeroed(&m);
	assert_int_equal(frs_matrix_alloc(&m, 2, 16, 16, 1, "", &err), FRS_OK);
	frs_matrix_free(&m);
	assert_int_equal(setenv("FRS_MAX_MEM", "1M", 1), 0);
	assert_int_equal(frs_matrix_alloc(&m, 2, 65536, 65536, 1, "", &err),
	    FRS_E_NOMEM);
	assert_non_null(strstr(err.message, "65536x65536 matrix: needs "
	    "16.0 GiB"));
	assert_int_equal(frs_matrix_alloc(&m, 3, 2, 65536, 32768, "", &err),
	    FRS_E_NOMEM);
	assert_non_null(strstr(err.message, "2x65536x32768 matrix"));
	assert_int_equal(unsetenv("FRS_MAX_MEM"), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sizes),
		cmocka_unit_test(fill_write_read),
		cmocka_unit_test(refusals),
		cmocka_unit_test(ceiling),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
