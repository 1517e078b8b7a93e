/* Point files: exact round trips in both forms, streams of unknown
 * length, and every malformed input refused with file and problem. */
#include "testutil.h"
#include "base/io.h"
#include "cli/ptsio.h"

#include <math.h>

static const double pts3[] = {
	0.0, 0.5, 0.25,
	0x1.fffffffffffffp-1, 1e-300, 0.1,	/* largest double below 1 */
	0.3333333333333333, 0.7071067811865476, 0.9999,
};

static void expect_bad(const char *name, const void *data, size_t n,
    const char *frag);

static void write_set(const char *path, unsigned dims, unsigned extra,
    const double *x, size_t n, int text)
{
	struct frs_points p = { dims, extra, n, (double *)x, { "" }, 0 };
	FILE *fp;

	for (unsigned j = 0; j < extra; j++)
		snprintf(p.names[j], sizeof p.names[j], "v%u", j + 1);
	fp = fopen(path, "wb");
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
		assert_int_equal(p.version, 2);
		assert_string_equal(p.names[0], "v1");
		/* Bit-exact, text included (shortest round-trip form). */
		assert_memory_equal(p.x, pts3, sizeof pts3);
		pts_free(&p);
	}
	/* Binary layout is the contract: version 2, the names block of 8
	 * bytes ("v1" and NULs), then the records. */
	{
		size_t len;
		unsigned char *raw = tu_read(tu_path("a.pts"), &len);
		assert_int_equal(len, 32 + 8 + 9 * 8);
		assert_memory_equal(raw, "\211PTS\r\n\032\n", 8);
		assert_int_equal(io_get_u32(raw + 8), 2);
		assert_int_equal(io_get_u32(raw + 12), 2);
		assert_int_equal(io_get_u32(raw + 16), 1);
		assert_int_equal(io_get_u32(raw + 20), 8);
		assert_true(io_get_u64(raw + 24) == 3);
		assert_memory_equal(raw + 32, "v1\0\0\0\0\0\0", 8);
		free(raw);
	}
}

/* Column names round-trip in both forms, whatever their lengths (the
 * names block padded to 8 bytes), and pts_column finds them. */
static void names_roundtrip(void **state)
{
	static const char *const names[] = { "pdf", "step", "set",
	    "a_name_of_thirty_one_characters" };
	double rec[6] = { 0.5, 0.25, 2.5, 3, 7, -1 };
	struct frs_points p;
	(void)state;

	for (int text = 0; text <= 1; text++) {
		const char *path = tu_path(text ? "nm.txt" : "nm.pts");
		struct pts_writer w;
		FILE *fp = fopen(path, "wb");
		assert_non_null(fp);
		assert_int_equal(pts_writer_begin(&w, fp, path, 2, 4, names, 0,
		    text), 0);
		assert_int_equal(pts_writer_put(&w, rec), 0);
		assert_int_equal(pts_writer_put(&w, rec), 0);
		assert_int_equal(pts_writer_end(&w), 0);
		assert_int_equal(fclose(fp), 0);
		assert_int_equal(pts_read(path, &p), 0);
		assert_int_equal(p.version, 2);
		assert_int_equal(p.extra, 4);
		assert_int_equal(p.n, 2);
		for (unsigned j = 0; j < 4; j++)
			assert_string_equal(p.names[j], names[j]);
		assert_int_equal(pts_column(&p, "pdf"), 2);
		assert_int_equal(pts_column(&p, "set"), 4);
		assert_int_equal(pts_column(&p, "sets"), -1);
		assert_memory_equal(p.x, rec, sizeof rec);
		assert_memory_equal(p.x + 6, rec, sizeof rec);
		pts_free(&p);
	}
	{
		size_t len;
		unsigned char *raw = tu_read(tu_path("nm.pts"), &len);
		/* 4 + 5 + 4 + 32 = 45 bytes of names, padded to 48 */
		assert_int_equal(io_get_u32(raw + 20), 48);
		assert_int_equal(len, 32 + 48 + 2 * 6 * 8);
		free(raw);
		raw = tu_read(tu_path("nm.txt"), &len);
		assert_true(len > 70);
		assert_memory_equal(raw, "#pts dims=2 extra=4 count=0 version=2 "
		    "names=pdf,step,set,a_name_of_thirty_one_characters\n", 86);
		free(raw);
	}
}

/* Files of version 1, as the writers before version 2 made them (pts(5)
 * of then: reserved 0 at offset 20, records right after the header; text
 * without version and names): still read, their extra columns unnamed. */
static void version1(void **state)
{
	unsigned char b[32 + 2 * 3 * 8];
	static const char txt[] = "#pts dims=2 extra=1 count=2\n"
	    "0.5 0.25 7\n0.125 0 2\n";
	double rec[6] = { 0.5, 0.25, 7, 0.125, 0, 2 };
	struct frs_points p;
	(void)state;

	memcpy(b, "\211PTS\r\n\032\n", 8);
	io_put_u32(b + 8, 1);
	io_put_u32(b + 12, 2);
	io_put_u32(b + 16, 1);
	io_put_u32(b + 20, 0);
	io_put_u64(b + 24, 2);
	{
		double le[6];
		memcpy(le, rec, sizeof le);
		io_le_f64(le, 6);
		memcpy(b + 32, le, sizeof le);
	}
	tu_write(tu_path("v1.pts"), b, sizeof b);
	tu_write(tu_path("v1.txt"), txt, sizeof txt - 1);
	for (int text = 0; text <= 1; text++) {
		assert_int_equal(pts_read(tu_path(text ? "v1.txt" : "v1.pts"),
		    &p), 0);
		assert_int_equal(p.version, 1);
		assert_int_equal(p.extra, 1);
		assert_int_equal(p.n, 2);
		assert_string_equal(p.names[0], "");
		assert_int_equal(pts_column(&p, "pdf"), -1);
		assert_memory_equal(p.x, rec, sizeof rec);
		pts_free(&p);
	}
	/* Version 1's reserved field is ignored, as that pts(5) said. */
	io_put_u32(b + 20, 8);
	tu_write(tu_path("v1r.pts"), b, sizeof b);
	assert_int_equal(pts_read(tu_path("v1r.pts"), &p), 0);
	assert_int_equal(p.n, 2);
	pts_free(&p);
}

/* Broken names: the names block and names= checked, the file named. */
static void bad_names(void **state)
{
	static const char *const two[] = { "pdf", "set" };
	static const char *const dup[] = { "set", "set" };
	static const char *const bad[] = { "a b" };
	unsigned char *raw;
	size_t len;
	struct pts_writer w;
	FILE *fp = tmpfile();
	(void)state;

	write_set(tu_path("bn.pts"), 2, 2, pts3, 1, 0);
	raw = tu_read(tu_path("bn.pts"), &len);
	io_put_u32(raw + 20, 0);
	expect_bad("bn0.pts", raw, len, "bytes of column names");
	io_put_u32(raw + 20, 12);
	expect_bad("bn12.pts", raw, len, "bytes of column names");
	io_put_u32(raw + 20, 8);
	memset(raw + 32 + 5, 'x', 3);	/* "v1", then "v2xxx" unended */
	expect_bad("bnx.pts", raw, len, "1 of 2 column names");
	memset(raw + 32 + 5, '\0', 3);
	raw[32 + 7] = 'x';	/* a byte after the names */
	expect_bad("bnm.pts", raw, len, "more than 2 column names");
	raw[32 + 7] = '\0';
	raw[32 + 2] = 'x';	/* "v1xv2", then an empty name */
	expect_bad("bne.pts", raw, len, "an empty column name");
	raw[32 + 2] = '\0';
	raw[32 + 3] = '1';	/* "v1", "1" */
	raw[32 + 4] = '\0';
	expect_bad("bnd.pts", raw, len, "bad column name");
	raw[32 + 3] = 'v';
	raw[32 + 4] = '1';	/* "v1" twice */
	expect_bad("bn2.pts", raw, len, "given twice");
	expect_bad("bnt.pts", raw, 36, "truncated header");
	free(raw);
	expect_bad("tn1.txt", "#pts dims=2 extra=2 names=pdf\n0.5 0.5 1 2\n",
	    42, ":1: header names 1 column for 2 extra values");
	expect_bad("tn2.txt", "#pts dims=2 extra=1 version=2\n0.5 0.5 1\n",
	    40, "header names 0 columns for 1 extra value");
	expect_bad("tn3.txt", "#pts dims=2 extra=2 names=pdf,pdf\n0.5 0.5 1 2\n",
	    46, "given twice: pdf");
	expect_bad("tn4.txt", "#pts dims=2 extra=1 names=p-f\n0.5 0.5 1\n",
	    40, "bad column name p-f");
	expect_bad("tn5.txt", "#pts dims=2 version=3\n0.5 0.5\n", 30,
	    "unsupported format version 3");
	/* The writer needs a valid, distinct name for every extra column. */
	assert_non_null(fp);
	assert_int_equal(pts_writer_begin(&w, fp, "o", 2, 2, two, 0, 0), 0);
	assert_int_equal(pts_writer_begin(&w, fp, "o", 2, 2, dup, 0, 0), -1);
	assert_err_has("two extra columns named set");
	assert_int_equal(pts_writer_begin(&w, fp, "o", 2, 1, bad, 0, 0), -1);
	assert_int_equal(pts_writer_begin(&w, fp, "o", 2, 1, NULL, 0, 0), -1);
	assert_err_has("no valid name");
	fclose(fp);
}

/* The text form, byte for byte: frs_dtoa's shortest strings. */
static void text_form(void **state)
{
	static const char want[] = "#pts dims=2 extra=1 count=3 version=2 "
	    "names=v1\n"
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
	{
		static const char *const nm[] = { "v1", "v2" };
		assert_int_equal(pts_writer_begin(&w, fp, "one", 2, 2, nm, N, 1),
		    0);
	}
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

	assert_int_equal(pts_writer_begin(&w, fp, path, 3, 0, NULL, 0, 0),
	    0);
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
	io_put_u32(b + 8, 0);
	expect_bad("v0.pts", b, len, "version 0");
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

	assert_int_equal(pts_writer_begin(&w, fp, "o", 2, 0, NULL, 2, 0),
	    0);
	assert_int_equal(pts_writer_put(&w, out), -1);	/* 1.0 not in [0,1) */
	out[1] = 0.5;
	assert_int_equal(pts_writer_put(&w, out), 0);
	assert_int_equal(pts_writer_end(&w), -1);	/* 1 of 2 announced */
	assert_err_has("announced");
	fclose(fp);
	assert_int_equal(pts_writer_begin(&w, stdout, "o", 0, 0, NULL, 0, 0),
	    -1);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(roundtrip),
	cmocka_unit_test(names_roundtrip),
	cmocka_unit_test(version1),
	cmocka_unit_test(bad_names),
	cmocka_unit_test(text_form),
	cmocka_unit_test(text_many),
	cmocka_unit_test(plain_text),
	cmocka_unit_test(unknown_count),
	cmocka_unit_test(bad_text),
	cmocka_unit_test(bad_binary),
	cmocka_unit_test(writer_checks))
