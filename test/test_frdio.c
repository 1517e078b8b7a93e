/* The .frd reader and writer: round trip, and every malformed file is
 * refused with a message naming the file and the problem. */
#include "testutil.h"
#include "formats/frdio.h"
#include "base/io.h"
#include "cli/outfile.h"

static void write_matrix(const char *path, const struct frs_matrix *m)
{
	FILE *fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(frd_write(fp, path, m), 0);
	assert_int_equal(fclose(fp), 0);
}

/* A k x k permutation by a fixed odd multiplier (a bijection mod n). */
static void make_perm(struct frs_matrix *m, uint32_t w, uint32_t h)
{
	assert_int_equal(frd_alloc(m, 2, w, h, 1, "test=1\nsize=x"), 0);
	for (size_t i = 0; i < m->n; i++)
		m->v[i] = (uint32_t)((i * 2654435761u) % m->n);
}

static void roundtrip(void **state)
{
	struct frs_matrix a, b;
	const char *p = tu_path("rt.frd");
	size_t len;
	unsigned char *raw;
	(void)state;

	make_perm(&a, 16, 8);	/* n = 128, multiplier odd: permutation */
	assert_int_equal(frd_check_permutation(&a, "a"), 0);
	write_matrix(p, &a);
	raw = tu_read(p, &len);
	/* The layout is the contract: 32-byte header, params, values last. */
	assert_int_equal(len, 32 + strlen(a.params) + 4 * a.n);
	assert_memory_equal(raw, "\211FRD\r\n\032\n", 8);
	assert_int_equal(io_get_u32(raw + 16), 16);
	assert_int_equal(io_get_u32(raw + 20), 8);
	assert_int_equal(io_get_u32(raw + len - 4), a.v[a.n - 1]);
	free(raw);
	assert_int_equal(frd_read(p, &b), 0);
	assert_int_equal(b.w, 16);
	assert_int_equal(b.h, 8);
	assert_int_equal(b.d, 1);
	assert_int_equal(b.dims, 2);
	assert_string_equal(b.params, a.params);
	assert_memory_equal(b.v, a.v, 4 * a.n);
	assert_true(frd_checksum(&a) == frd_checksum(&b));
	frd_free(&b);
	/* 3-D */
	assert_int_equal(frd_alloc(&b, 3, 4, 3, 2, ""), 0);
	for (size_t i = 0; i < b.n; i++)
		b.v[i] = (uint32_t)(b.n - 1 - i);
	write_matrix(p, &b);
	frd_free(&b);
	assert_int_equal(frd_read(p, &b), 0);
	assert_int_equal(b.dims, 3);
	assert_int_equal(b.n, 24);
	assert_int_equal(b.v[0], 23);
	frd_free(&b);
	frd_free(&a);
}

static void permutation_and_checksum(void **state)
{
	struct frs_matrix a;
	uint64_t c0;
	(void)state;

	make_perm(&a, 8, 8);
	c0 = frd_checksum(&a);
	a.v[9] = a.v[20];	/* one repeat: (1, 1) now equals (4, 2) */
	assert_int_equal(frd_check_permutation(&a, "m.frd"), -1);
	assert_err_has("m.frd", "not a permutation", "repeats");
	assert_true(frd_checksum(&a) != c0);
	frd_free(&a);
}

/* Build a file from a valid one with one edit, read it, expect failure. */
static void expect_bad(const unsigned char *data, size_t n, const char *frag)
{
	struct frs_matrix m;
	const char *p = tu_path("bad.frd");

	tu_write(p, data, n);
	assert_int_equal(frd_read(p, &m), -1);
	assert_err_has(p, frag);
	assert_null(m.v);
}

static void malformed(void **state)
{
	struct frs_matrix a;
	const char *p = tu_path("good.frd");
	unsigned char *raw, *b;
	size_t len;
	(void)state;

	make_perm(&a, 4, 4);
	write_matrix(p, &a);
	raw = tu_read(p, &len);
	b = malloc(len + 8);
	assert_non_null(b);

	expect_bad(raw, 0, "empty file");
	expect_bad(raw, 20, "truncated header");
	expect_bad(raw, len - 3, "needs");	/* short payload */
	memcpy(b, raw, len);
	memcpy(b + len, "junk", 4);
	expect_bad(b, len + 4, "needs");	/* trailing bytes */
	memcpy(b, raw, len);
	b[1] = 'X';
	expect_bad(b, len, "wrong magic");
	memcpy(b, raw, len);
	io_put_u32(b + 8, 2);
	expect_bad(b, len, "version 2");
	memcpy(b, raw, len);
	io_put_u32(b + 12, 4);
	expect_bad(b, len, "dimension count 4");
	memcpy(b, raw, len);
	io_put_u32(b + 16, 0);
	expect_bad(b, len, "impossible size");
	memcpy(b, raw, len);
	io_put_u32(b + 24, 2);		/* depth 2 with k = 2 */
	expect_bad(b, len, "impossible size");
	memcpy(b, raw, len);		/* 65536 x 65536 x 2 overflows 2^32 */
	io_put_u32(b + 12, 3);
	io_put_u32(b + 16, 65536);
	io_put_u32(b + 20, 65536);
	io_put_u32(b + 24, 2);
	expect_bad(b, len, "exceeds 2^32");
	memcpy(b, raw, len);		/* sizes whose 32-bit product wraps */
	io_put_u32(b + 16, 65536);
	io_put_u32(b + 20, 65536);
	expect_bad(b, len, "needs");
	memcpy(b, raw, len);
	io_put_u32(b + 32 + strlen(a.params), 16);	/* value == n */
	expect_bad(b, len, "not below");
	memcpy(b, raw, len);
	b[33] = '\0';
	expect_bad(b, len, "NUL");
	memcpy(b, raw, len);
	io_put_u32(b + 28, 1u << 30);
	expect_bad(b, len, "too long");
	free(b);
	free(raw);
	frd_free(&a);
}

/* A pipe has no length to check: truncation shows while reading. */
static void truncated_stream(void **state)
{
	struct frs_matrix a, m;
	const char *p = tu_path("s.frd");
	char cmd[512];
	FILE *fp;
	(void)state;

	make_perm(&a, 8, 8);
	write_matrix(p, &a);
	snprintf(cmd, sizeof cmd, "head -c 200 '%s'", p);
	fp = popen(cmd, "r");
	assert_non_null(fp);
	assert_int_equal(frd_read_fp(fp, "<stdin>", &m), -1);
	assert_err_has("<stdin>", "truncated values");
	pclose(fp);
	snprintf(cmd, sizeof cmd, "cat '%s'", p);
	fp = popen(cmd, "r");
	assert_int_equal(frd_read_fp(fp, "<stdin>", &m), 0);
	assert_memory_equal(m.v, a.v, 4 * a.n);
	pclose(fp);
	frd_free(&m);
	frd_free(&a);
}

static void missing_file(void **state)
{
	struct frs_matrix m;
	(void)state;
	assert_int_equal(frd_read("/nonexistent/m.frd", &m), -1);
	assert_err_has("/nonexistent/m.frd", "No such file");
	assert_int_equal(frd_read(tu_dir(), &m), -1);
	assert_err_has("is a directory");
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(roundtrip),
	cmocka_unit_test(permutation_and_checksum),
	cmocka_unit_test(malformed),
	cmocka_unit_test(truncated_stream),
	cmocka_unit_test(missing_file))
