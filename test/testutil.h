/* Shared helpers for the cmocka tests. */
#ifndef FRS_TESTUTIL_H
#define FRS_TESTUTIL_H

#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <math.h>

/* pi, once for the tests (C11's math.h has no M_PI). */
#define PI 3.14159265358979323846

#include "base/err.h"
#include "base/rng.h"

/* A test program's main(): the cmocka tests given, one group with its
 * setup and teardown (NULL for none).  cmocka prints the summary. */
#define TU_MAIN(setup, teardown, ...) \
	int main(void) \
	{ \
		const struct CMUnitTest tests[] = { __VA_ARGS__ }; \
		return cmocka_run_group_tests(tests, setup, teardown); \
	}

/* n uniform random points, x y packed, from (seed, FRS_STREAM_TEST). */
static inline double *tu_rnd_points(size_t n, uint64_t seed)
{
	double *xy = malloc(2 * n * sizeof *xy);
	assert_non_null(xy);
	for (size_t i = 0; i < 2 * n; i++)
		xy[i] = frs_rand01(seed, FRS_STREAM_TEST, i);
	return xy;
}

/* The m x m grid of cell centres ((i + 1/2)/m, (j + 1/2)/m), point
 * i m + j. */
static inline double *tu_grid_points(size_t m)
{
	double *xy = malloc(2 * m * m * sizeof *xy);
	assert_non_null(xy);
	for (size_t i = 0; i < m; i++)
		for (size_t j = 0; j < m; j++) {
			xy[2 * (i * m + j)] = ((double)i + 0.5) / (double)m;
			xy[2 * (i * m + j) + 1] = ((double)j + 0.5) / (double)m;
		}
	return xy;
}

/* The m x m x m grid of cell centres, point (i m + j) m + l at
 * ((i + 1/2)/m, (j + 1/2)/m, (l + 1/2)/m). */
static inline double *tu_grid_points3(size_t m)
{
	double *x = malloc(3 * m * m * m * sizeof *x);
	size_t p = 0;

	assert_non_null(x);
	for (size_t i = 0; i < m; i++)
		for (size_t j = 0; j < m; j++)
			for (size_t l = 0; l < m; l++, p++) {
				x[3 * p] = ((double)i + 0.5) / (double)m;
				x[3 * p + 1] = ((double)j + 0.5) / (double)m;
				x[3 * p + 2] = ((double)l + 0.5) / (double)m;
			}
	return x;
}

/* A fresh temporary directory per test binary. */
static inline const char *tu_dir(void)
{
	static char dir[64];
	if (!dir[0]) {
		snprintf(dir, sizeof dir, "/tmp/frs-unit.XXXXXX");
		if (mkdtemp(dir) == NULL)
			abort();
	}
	return dir;
}

static inline const char *tu_path(const char *name)
{
	static char buf[8][256];
	static int k;
	k = (k + 1) % 8;
	snprintf(buf[k], sizeof buf[k], "%s/%s", tu_dir(), name);
	return buf[k];
}

/* A file opened for writing, and its closing checked. */
static inline FILE *tu_create(const char *path)
{
	FILE *fp = fopen(path, "wb");
	assert_non_null(fp);
	return fp;
}

static inline void tu_close(FILE *fp)
{
	assert_int_equal(fclose(fp), 0);
}

static inline void tu_write(const char *path, const void *data, size_t n)
{
	FILE *fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(fwrite(data, 1, n, fp), n);
	assert_int_equal(fclose(fp), 0);
}

/* Read a whole file; caller frees. */
static inline unsigned char *tu_read(const char *path, size_t *n)
{
	FILE *fp = fopen(path, "rb");
	unsigned char *b;
	long len;
	assert_non_null(fp);
	fseek(fp, 0, SEEK_END);
	len = ftell(fp);
	fseek(fp, 0, SEEK_SET);
	b = malloc((size_t)len + 1);
	assert_non_null(b);
	assert_int_equal(fread(b, 1, (size_t)len, fp), (size_t)len);
	fclose(fp);
	*n = (size_t)len;
	return b;
}

/* The file at path holds exactly the string s. */
static inline void tu_assert_file_is(const char *path, const char *s)
{
	size_t n;
	unsigned char *b = tu_read(path, &n);

	assert_int_equal(n, strlen(s));
	assert_memory_equal(b, s, n);
	free(b);
}

/* The last error message contains all the given fragments. */
#define assert_err_has(...) tu_err_has(__FILE__, __LINE__, __VA_ARGS__, NULL)
static inline void tu_err_has(const char *file, int line, ...)
{
	va_list ap;
	const char *frag;
	va_start(ap, line);
	while ((frag = va_arg(ap, const char *)) != NULL)
		if (strstr(frs_errmsg(), frag) == NULL) {
			va_end(ap);
			print_error("message '%s' lacks '%s'\n", frs_errmsg(),
			    frag);
			_fail(file, line);
			return;
		}
	va_end(ap);
	(void)file;
}

/* |a - b| <= tol; cmocka 1.1.5 has no assert_double_equal. */
#define assert_near(a, b, tol) tu_near(__FILE__, __LINE__, (a), (b), (tol))
static inline void tu_near(const char *file, int line, double a, double b,
    double tol)
{
	if (!(fabs(a - b) <= tol)) {
		print_error("%.17g != %.17g (tolerance %g)\n", a, b, tol);
		_fail(file, line);
	}
}
#ifndef assert_double_equal
#define assert_double_equal assert_near
#endif

static inline void tu_rm_rf(void)
{
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", tu_dir());
	if (system(cmd) != 0)
		fprintf(stderr, "could not remove %s\n", tu_dir());
}

/* Group teardown: remove the temporary directory. */
static inline int tu_teardown(void **state)
{
	(void)state;
	tu_rm_rf();
	return 0;
}

#endif
