/* Point files: exact round trips in both forms, streams of unknown
 * length, and every malformed input refused with file and problem. */
#include "testutil.h"
#include "io.h"
#include "ptsio.h"

#include <math.h>

static const double pts3[] = {
	0.0, 0.5, 0.25,
	0x1.fffffffffffffp-1, 1e-300, 0.1,	/* largest double below 1 */
	0.3333333333333333, 0.7071067811865476, 0.9999,
};

static void write_set(const char *path, unsigned dims, unsigned extra,
    const double *x, size_t n, int text)
{
	struct frs_points p = { dims, extra, n, (double *)x };
	FILE *fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(pts_write(fp, path, &p, text), 0);
	assert_int_equal(fclose(fp), 0);
}

static void roundtrip(void **state)
{
	struct frs_points p;
	(void)state;

	for (int text = 0; text <= 1; text++) {
		const char *path = tu_path(text ? "a.txt" : "a.pts");
		write_set(path, 2, 1, pts3, 3, text);
		assert_int_equal(pts_read(path, &p), 0);
		assert_int_equal(p.dims, 2);
		assert_int_equal(p.extra, 1);
		assert_int_equal(p.n, 3);
		/* Bit-exact, text included (shortest round-trip form). */
		assert_memory_equal(p.x, pts3, sizeof pts3);
		pts_free(&p);
	}
	/* Binary layout is the contract. */
	{
		size_t len;
		unsigned char *raw = tu_read(tu_path("a.pts"), &len);
		assert_int_equal(len, 32 + 9 * 8);
		assert_memory_equal(raw, "\211PTS\r\n\032\n", 8);
		assert_int_equal(io_get_u32(raw + 12), 2);
		assert_int_equal(io_get_u32(raw + 16), 1);
		assert_true(io_get_u64(raw + 24) == 3);
		free(raw);
	}
}

/* The text form, byte for byte: frs_dtoa's shortest strings. */
static void text_form(void **state)
{
	static const char want[] = "#pts dims=2 extra=1 count=3\n"
	    "0 0.5 0.25\n0.9999999999999999 1e-300 0.1\n"
	    "0.3333333333333333 0.7071067811865476 0.9999\n";
	size_t len;
	unsigned char *raw;
	(void)state;

	write_set(tu_path("f.txt"), 2, 1, pts3, 3, 1);
	raw = tu_read(tu_path("f.txt"), &len);
	assert_int_equal(len, sizeof want - 1);
	assert_memory_equal(raw, want, len);
	free(raw);
}

/* Many records (past the writer's 32 KiB buffer): pts_writer_put_n and
 * record by record pts_writer_put give the same bytes, read back bit for
 * bit, extra values of any size and sign included. */
static void text_many(void **state)
{
	enum { N = 6000, NCOL = 4 };
	double *x = malloc(N * NCOL * sizeof *x);
	struct frs_points p;
	struct pts_writer w;
	unsigned char *a, *b;
	size_t la, lb;
	FILE *fp;
	(void)state;

	assert_non_null(x);
	for (size_t i = 0; i < N * NCOL; i++) {
		double u = frs_rand01(7, FRS_STREAM_TEST, i);
		x[i] = i % NCOL < 2 ? u : ldexp(u - 0.5, (int)(i % 600) - 300);
	}
	write_set(tu_path("n.txt"), 2, 2, x, N, 1);
	fp = fopen(tu_path("one.txt"), "wb");
	assert_non_null(fp);
	assert_int_equal(pts_writer_begin(&w, fp, "one", 2, 2, N, 1), 0);
	for (size_t i = 0; i < N; i++)
		assert_int_equal(pts_writer_put(&w, x + NCOL * i), 0);
	assert_int_equal(pts_writer_end(&w), 0);
	assert_int_equal(fclose(fp), 0);
	a = tu_read(tu_path("n.txt"), &la);
	b = tu_read(tu_path("one.txt"), &lb);
	assert_true(la > 100000);
	assert_int_equal(la, lb);
	assert_memory_equal(a, b, la);
	free(a);
	free(b);
	assert_int_equal(pts_read(tu_path("n.txt"), &p), 0);
	assert_int_equal(p.n, N);
	assert_memory_equal(p.x, x, N * NCOL * sizeof *x);
	pts_free(&p);
	free(x);
}

/* Text without a header: every column is a coordinate; comments and
 * blank lines are skipped; CRLF is accepted. */
static void plain_text(void **state)
{
	static const char txt[] = "# made by hand\n\n0.5 0.25\r\n  0.125\t0.75\n"
	    "# done\n";
	struct frs_points p;
	const char *path = tu_path("plain.txt");
	(void)state;

	tu_write(path, txt, sizeof txt - 1);
	assert_int_equal(pts_read(path, &p), 0);
	assert_int_equal(p.dims, 2);
	assert_int_equal(p.n, 2);
	assert_true(p.x[2] == 0.125 && p.x[3] == 0.75);
	pts_free(&p);
}

/* Count 0 means "read to the end"; a seekable writer patches it. */
static void unknown_count(void **state)
{
	struct pts_writer w;
	struct frs_points p;
	const char *path = tu_path("stream.pts");
	FILE *fp = fopen(path, "wb");
	size_t len;
	unsigned char *raw;
	char cmd[512];
	(void)state;

	assert_int_equal(pts_writer_begin(&w, fp, path, 3, 0, 0, 0), 0);
	for (int i = 0; i < 3; i++)
		assert_int_equal(pts_writer_put(&w, pts3 + 3 * i), 0);
	assert_int_equal(pts_writer_end(&w), 0);
	fclose(fp);
	raw = tu_read(path, &len);
	assert_true(io_get_u64(raw + 24) == 3);
	/* Zero the count again and read through a pipe. */
	io_put_u64(raw + 24, 0);
	tu_write(path, raw, len);
	free(raw);
	/* Standard input from a pipe: no length to check, read to EOF. */
	snprintf(cmd, sizeof cmd, "cat '%s'", path);
	fp = popen(cmd, "r");
	assert_non_null(fp);
	{
		int saved = dup(0);
		assert_true(dup2(fileno(fp), 0) == 0);
		clearerr(stdin);
		assert_int_equal(pts_read("-", &p), 0);
		assert_true(dup2(saved, 0) == 0);
		close(saved);
		clearerr(stdin);
	}
	pclose(fp);
	assert_int_equal(p.n, 3);
	assert_memory_equal(p.x, pts3, sizeof pts3);
	pts_free(&p);
}

static void expect_bad(const char *name, const void *data, size_t n,
    const char *frag)
{
	struct frs_points p;
	const char *path = tu_path(name);

	tu_write(path, data, n);
	assert_int_equal(pts_read(path, &p), -1);
	assert_err_has(path, frag);
	assert_null(p.x);
}

static void bad_text(void **state)
{
	(void)state;
	expect_bad("e.txt", "", 0, "empty file");
	expect_bad("c1.txt", "0.5 1.0\n", 8, "outside [0,1)");
	expect_bad("c2.txt", "0.5 -0.1\n", 9, "outside [0,1)");
	expect_bad("nan.txt", "0.5 nan\n", 8, "not finite");
	expect_bad("word.txt", "0.5 0.2\n0.5 abc\n", 16, ":2: 'abc' is not a number");
	expect_bad("cols.txt", "0.5 0.2\n0.5\n", 12, ":2: 1 values, expected 2");
	expect_bad("more.txt", "0.5 0.2\n0.5 0.1 0.2\n", 20, "more than 2 values");
	expect_bad("hdr.txt", "#pts dims=0 extra=0\n", 20, "coordinates");
	expect_bad("cnt.txt", "#pts dims=1 extra=0 count=3\n0.5\n", 32,
	    "truncated: 1 of 3");
	expect_bad("cnt2.txt", "#pts dims=1 extra=0 count=1\n0.5\n0.25\n", 37,
	    ":3: more points than the header's count 1");
	expect_bad("bin.txt", "\x01\x02\x00\x03", 4, "not a point file");
}

static void bad_binary(void **state)
{
	unsigned char b[32 + 6 * 8];
	const char *good = tu_path("g.pts");
	size_t len;
	unsigned char *raw;
	double bad = 1.0;
	(void)state;

	write_set(good, 3, 0, pts3, 2, 0);
	raw = tu_read(good, &len);
	assert_int_equal(len, sizeof b);
	expect_bad("h.pts", raw, 20, "truncated header");
	memcpy(b, raw, len);
	io_put_u32(b + 8, 7);
	expect_bad("v.pts", b, len, "version 7");
	memcpy(b, raw, len);
	io_put_u32(b + 12, 0);
	expect_bad("d.pts", b, len, "coordinates");
	memcpy(b, raw, len);
	io_put_u32(b + 16, 40);
	expect_bad("x.pts", b, len, "extra");
	expect_bad("t.pts", raw, len - 8, "header says 2 points");
	memcpy(b, raw, len);
	io_put_u64(b + 24, 0);
	expect_bad("r.pts", b, len - 4, "truncated record");
	memcpy(b, raw, len);
	io_put_u64(b + 24, UINT64_MAX / 2);	/* count * 24 overflows */
	expect_bad("o.pts", b, len, "header says");
	memcpy(b, raw, len);
	memcpy(b + 32 + 8 * 4, &bad, 8);
	expect_bad("one.pts", b, len, "point 1: coordinate 2 is 1, outside");
	free(raw);
}

static void writer_checks(void **state)
{
	struct pts_writer w;
	FILE *fp = tmpfile();
	double out[2] = { 0.5, 1.0 };
	(void)state;

	assert_int_equal(pts_writer_begin(&w, fp, "o", 2, 0, 2, 0), 0);
	assert_int_equal(pts_writer_put(&w, out), -1);	/* 1.0 not in [0,1) */
	out[1] = 0.5;
	assert_int_equal(pts_writer_put(&w, out), 0);
	assert_int_equal(pts_writer_end(&w), -1);	/* 1 of 2 announced */
	assert_err_has("announced");
	fclose(fp);
	assert_int_equal(pts_writer_begin(&w, stdout, "o", 0, 0, 0, 0), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(roundtrip),
		cmocka_unit_test(text_form),
		cmocka_unit_test(text_many),
		cmocka_unit_test(plain_text),
		cmocka_unit_test(unknown_count),
		cmocka_unit_test(bad_text),
		cmocka_unit_test(bad_binary),
		cmocka_unit_test(writer_checks),
	};
	return cmocka_run_group_tests(tests, NULL, tu_teardown);
}
