/*
 * Preparing matrices (API 2.2, frs_prepared_write(3)), each function
 * against what the test works out itself: ranks by counting, the
 * checksum by a FNV-1a loop of its own, a .frp's bytes by the layout of
 * frd(5) with the minmap and the block lists made here by brute force, a
 * PNG's grey levels written here with libpng, and the levels of a plan
 * against a sampler's frs_sampler_levels and against the table that
 * frd-prep --for printed at 3c04e07, before the plan was public.
 */
#include "testutil.h"
#include "frs.h"

#include <png.h>
#include <sys/stat.h>

/* ---- the test's own oracles ------------------------------------------ */

/* A permutation of 0 .. n-1 from seed (Fisher-Yates over a xorshift). */
static void shuffle(uint32_t *v, size_t n, uint64_t seed)
{
	uint64_t x = seed * 0x9e3779b97f4a7c15ull + 1;

	for (size_t i = 0; i < n; i++)
		v[i] = (uint32_t)i;
	for (size_t i = n; i > 1; i--) {
		size_t j;
		uint32_t t;
		x ^= x << 13;
		x ^= x >> 7;
		x ^= x << 17;
		j = (size_t)(x % i);
		t = v[i - 1];
		v[i - 1] = v[j];
		v[j] = t;
	}
}

/* The rank of each of n values by counting: those smaller, and those
 * equal before it. */
static void brute_rank(const uint64_t *in, uint32_t *out, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		uint32_t r = 0;
		for (size_t j = 0; j < n; j++)
			r += in[j] < in[i] || (in[j] == in[i] && j < i);
		out[i] = r;
	}
}

/* FNV-1a 64 of the 32-bit little-endian words dims, w, h, d and the
 * values, as frd(5) defines a .frp's checksum. */
static uint64_t fnv(const struct frs_matrix *m)
{
	uint64_t h = 14695981039346656037ull;
	uint32_t head[4] = { m->dims, m->w, m->h, m->d };

	for (size_t i = 0; i < 4 + m->n; i++) {
		uint32_t x = i < 4 ? head[i] : m->v[i - 4];
		for (int b = 0; b < 4; b++) {
			h ^= (x >> (8 * b)) & 0xff;
			h *= 1099511628211ull;
		}
	}
	return h;
}

static uint32_t get32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	    (uint32_t)p[3] << 24;
}

/* A whole file into a buffer (*len bytes). */
static unsigned char *slurp(const char *path, size_t *len)
{
	FILE *fp = fopen(path, "rb");
	unsigned char *b;
	long n;

	assert_non_null(fp);
	assert_int_equal(fseek(fp, 0, SEEK_END), 0);
	n = ftell(fp);
	assert_true(n >= 0);
	rewind(fp);
	b = malloc((size_t)n + 1);
	assert_non_null(b);
	assert_int_equal(fread(b, 1, (size_t)n, fp), (size_t)n);
	fclose(fp);
	*len = (size_t)n;
	return b;
}

static void spit(const char *path, const void *buf, size_t len)
{
	FILE *fp = fopen(path, "wb");

	assert_non_null(fp);
	assert_int_equal(fwrite(buf, 1, len, fp), len);
	assert_int_equal(fclose(fp), 0);
}

static const char *tmp(const char *name)
{
	static char path[8][256];
	static unsigned k;
	char *p = path[k++ % 8];

	snprintf(p, 256, "%s/%s", tu_dir(), name);
	return p;
}

/* A w x h matrix of the given values. */
static struct frs_matrix matrix(uint32_t w, uint32_t h, const uint32_t *v)
{
	struct frs_matrix m;

	assert_int_equal(frs_matrix_alloc(&m, 2, w, h, 1, "test=1\n", NULL),
	    FRS_OK);
	memcpy(m.v, v, m.n * sizeof *v);
	return m;
}

/* ---- frs_matrix_alloc ------------------------------------------------ */

static void test_alloc(void **state)
{
	struct frs_matrix m;
	frs_error e;
	const char *params = "a=1\nb=2\n";

	(void)state;
	assert_int_equal(frs_matrix_alloc(&m, 2, 4, 3, 1, params, &e), FRS_OK);
	assert_int_equal(e.code, FRS_OK);
	assert_int_equal(m.dims, 2);
	assert_int_equal(m.w, 4);
	assert_int_equal(m.h, 3);
	assert_int_equal(m.d, 1);
	assert_int_equal(m.n, 12);
	assert_string_equal(m.params, params);
	assert_ptr_not_equal(m.params, params);
	for (size_t i = 0; i < m.n; i++)
		assert_int_equal(m.v[i], 0);
	frs_matrix_free(&m);
	assert_null(m.v);
	assert_int_equal(frs_matrix_alloc(&m, 3, 2, 3, 4, NULL, NULL), FRS_OK);
	assert_int_equal(m.n, 24);
	assert_string_equal(m.params, "");
	frs_matrix_free(&m);

	/* Sizes no .frd holds. */
	static const uint32_t bad[][4] = { { 1, 4, 4, 1 }, { 4, 4, 4, 1 },
	    { 2, 0, 4, 1 }, { 2, 4, 0, 1 }, { 2, 4, 4, 2 }, { 3, 4, 4, 0 } };
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
		memset(&e, 0, sizeof e);
		assert_int_equal(frs_matrix_alloc(&m, bad[k][0], bad[k][1],
		    bad[k][2], bad[k][3], NULL, &e), FRS_E_ARG);
		assert_int_equal(e.code, FRS_E_ARG);
		assert_string_not_equal(e.message, "");
		assert_null(m.v);
	}
	/* 2^33 values: beyond what distinct uint32 thresholds can be. */
	assert_int_equal(frs_matrix_alloc(&m, 3, 65536, 65536, 2, NULL, &e),
	    FRS_E_LIMIT);
	assert_null(m.v);
	/* The memory ceiling. */
	setenv("FRS_MAX_MEM", "1K", 1);
	assert_int_equal(frs_matrix_alloc(&m, 2, 64, 64, 1, NULL, &e),
	    FRS_E_NOMEM);
	assert_non_null(strstr(e.message, "FRS_MAX_MEM"));
	unsetenv("FRS_MAX_MEM");
	assert_int_equal(frs_matrix_alloc(NULL, 2, 4, 4, 1, NULL, &e), FRS_E_ARG);
}

/* ---- frs_matrix_check, frs_matrix_rank, frs_matrix_checksum ---------- */

static void test_check(void **state)
{
	static const uint32_t ok[6] = { 1, 0, 5, 3, 2, 4 };
	static const uint32_t rep[6] = { 1, 0, 5, 3, 0, 4 };
	static const uint32_t over[6] = { 1, 9, 5, 3, 0, 4 };
	struct frs_matrix m = matrix(3, 2, ok);
	frs_error e;

	(void)state;
	assert_int_equal(frs_matrix_check(&m, "x", &e), FRS_OK);
	frs_matrix_free(&m);
	/* The repeat at element 4: (1, 1). */
	m = matrix(3, 2, rep);
	assert_int_equal(frs_matrix_check(&m, "x", &e), FRS_E_FORMAT);
	assert_string_equal(e.message,
	    "x: not a permutation: value 0 repeats at (1, 1, 0)");
	assert_int_equal(frs_matrix_check(&m, NULL, &e), FRS_E_FORMAT);
	assert_int_equal(strncmp(e.message, "matrix: ", 8), 0);
	frs_matrix_free(&m);
	m = matrix(3, 2, over);
	assert_int_equal(frs_matrix_check(&m, "x", &e), FRS_E_FORMAT);
	assert_string_equal(e.message, "x: value 9 at element 1 is out of range");
	/* Sizes that disagree with n: no matrix. */
	m.n = 7;
	assert_int_equal(frs_matrix_check(&m, "x", &e), FRS_E_ARG);
	m.n = 6;
	frs_matrix_free(&m);
	assert_int_equal(frs_matrix_check(NULL, "x", &e), FRS_E_ARG);
}

static void test_rank(void **state)
{
	enum { W = 20, H = 15, N = W * H };
	uint64_t in[N];
	uint32_t want[N], perm[N];
	struct frs_matrix m;

	(void)state;
	/* Values 0 .. 9 with many ties, and some large. */
	shuffle(perm, N, 7);
	assert_int_equal(frs_matrix_alloc(&m, 2, W, H, 1, NULL, NULL), FRS_OK);
	for (size_t i = 0; i < N; i++) {
		m.v[i] = perm[i] % 10 == 9 ? 0xfffffff0u - perm[i] : perm[i] % 10;
		in[i] = m.v[i];
	}
	brute_rank(in, want, N);
	assert_int_equal(frs_matrix_rank(&m, NULL), FRS_OK);
	assert_memory_equal(m.v, want, sizeof want);
	assert_int_equal(frs_matrix_check(&m, "ranked", NULL), FRS_OK);
	/* A permutation is its own ranks. */
	memcpy(m.v, perm, sizeof perm);
	assert_int_equal(frs_matrix_rank(&m, NULL), FRS_OK);
	assert_memory_equal(m.v, perm, sizeof perm);
	frs_matrix_free(&m);
	/* 3-D, all equal: the positions. */
	assert_int_equal(frs_matrix_alloc(&m, 3, 2, 2, 2, NULL, NULL), FRS_OK);
	for (size_t i = 0; i < m.n; i++)
		m.v[i] = 77;
	assert_int_equal(frs_matrix_rank(&m, NULL), FRS_OK);
	for (size_t i = 0; i < m.n; i++)
		assert_int_equal(m.v[i], i);
	frs_matrix_free(&m);
	assert_int_equal(frs_matrix_rank(NULL, NULL), FRS_E_ARG);
}

static void test_checksum(void **state)
{
	uint32_t v[64];
	struct frs_matrix m;

	(void)state;
	shuffle(v, 64, 3);
	m = matrix(8, 8, v);
	assert_true(frs_matrix_checksum(&m) == fnv(&m));
	/* The sizes count: 4 x 16 of the same values differs. */
	m.w = 4;
	m.h = 16;
	assert_true(frs_matrix_checksum(&m) == fnv(&m));
	m.w = m.h = 8;
	/* One bit of one value. */
	m.v[5] ^= 1;
	assert_true(frs_matrix_checksum(&m) == fnv(&m));
	frs_matrix_free(&m);
}

/* ---- frs_matrix_read_png --------------------------------------------- */

/* A w x h grey PNG of depth 8 or 16 with the levels g. */
static void write_png(const char *path, uint32_t w, uint32_t h, int depth,
    const uint32_t *g)
{
	FILE *fp = fopen(path, "wb");
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL,
	    NULL, NULL);
	png_infop info = png_create_info_struct(png);
	png_bytep row = malloc((size_t)w * 2);

	assert_non_null(fp);
	assert_non_null(row);
	assert_false(setjmp(png_jmpbuf(png)));
	png_init_io(png, fp);
	png_set_IHDR(png, info, w, h, depth, PNG_COLOR_TYPE_GRAY,
	    PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
	    PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (uint32_t y = 0; y < h; y++) {
		for (uint32_t x = 0; x < w; x++) {
			uint32_t s = g[(size_t)y * w + x];
			if (depth == 16) {
				row[2 * x] = (png_byte)(s >> 8);
				row[2 * x + 1] = (png_byte)s;
			} else
				row[x] = (png_byte)s;
		}
		png_write_row(png, row);
	}
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	free(row);
	assert_int_equal(fclose(fp), 0);
}

static void test_read_png(void **state)
{
	/* Neighbouring 16-bit levels across the whole range, the higher
	 * first: a level read inexactly ties with its neighbour, whose
	 * rank then comes first. */
	static const uint32_t g16[16] = { 65535, 65534, 32768, 32767, 1, 0,
	    256, 255, 40001, 40000, 12345, 12344, 60000, 59999, 515, 514 };
	static const uint32_t g8[12] = { 7, 3, 3, 255, 0, 7, 128, 127, 3, 0,
	    200, 1 };
	uint64_t in[16];
	uint32_t want[16];
	struct frs_matrix m;
	frs_error e;

	(void)state;
	write_png(tmp("g16.png"), 4, 4, 16, g16);
	assert_int_equal(frs_matrix_read_png(&m, tmp("g16.png"), &e), FRS_OK);
	assert_int_equal(m.dims, 2);
	assert_int_equal(m.w, 4);
	assert_int_equal(m.h, 4);
	assert_string_equal(m.params, "imported=png\n");
	for (size_t i = 0; i < 16; i++)
		in[i] = g16[i];
	brute_rank(in, want, 16);
	assert_memory_equal(m.v, want, 16 * sizeof *want);
	frs_matrix_free(&m);
	/* 8 bits, with ties: by position. */
	write_png(tmp("g8.png"), 4, 3, 8, g8);
	assert_int_equal(frs_matrix_read_png(&m, tmp("g8.png"), &e), FRS_OK);
	for (size_t i = 0; i < 12; i++)
		in[i] = g8[i];
	brute_rank(in, want, 12);
	assert_memory_equal(m.v, want, 12 * sizeof *want);
	frs_matrix_free(&m);
	/* All black is a mask too (no map's "zero everywhere"). */
	write_png(tmp("black.png"), 1, 1, 16, (const uint32_t[1]){ 0 });
	assert_int_equal(frs_matrix_read_png(&m, tmp("black.png"), &e), FRS_OK);
	assert_int_equal(m.n, 1);
	assert_int_equal(m.v[0], 0);
	frs_matrix_free(&m);
	/* Not there, not a PNG. */
	assert_int_equal(frs_matrix_read_png(&m, tmp("none.png"), &e),
	    FRS_E_IO);
	assert_null(m.v);
	spit(tmp("junk.png"), "no png at all", 13);
	assert_int_equal(frs_matrix_read_png(&m, tmp("junk.png"), &e),
	    FRS_E_FORMAT);
	assert_non_null(strstr(e.message, "junk.png"));
	assert_int_equal(frs_matrix_read_png(NULL, "x", &e), FRS_E_ARG);
}

/* ---- frs_prepared_write ---------------------------------------------- */

/* The .frp of m with its minmap and the lists of blocks, byte by byte
 * after frd(5). */
static void check_frp_bytes(const unsigned char *b, size_t len,
    const struct frs_matrix *m, int minmap, const uint32_t *blocks,
    unsigned nblocks)
{
	static const unsigned char magic[8] = { 0x89, 'F', 'R', 'P', '\r',
	    '\n', 0x1a, '\n' };
	size_t at = 40, n = m->n;
	uint32_t *lev = malloc(n * sizeof *lev), *up = malloc(n * sizeof *up);
	uint64_t sum;

	assert_non_null(lev);
	assert_non_null(up);
	assert_true(len >= 40);
	assert_memory_equal(b, magic, 8);
	assert_int_equal(get32(b + 8), 1);
	assert_int_equal(get32(b + 12), m->w);
	assert_int_equal(get32(b + 16), m->h);
	assert_int_equal(get32(b + 20), (minmap ? 1u : 0u) |
	    (nblocks ? 2u : 0u));
	sum = (uint64_t)get32(b + 24) | (uint64_t)get32(b + 28) << 32;
	assert_true(sum == fnv(m));
	assert_int_equal(get32(b + 32), nblocks);
	assert_int_equal(get32(b + 36), 0);
	for (size_t i = 0; i < n; i++)
		assert_int_equal(get32(b + at + 4 * i), m->v[i]);
	at += 4 * n;
	/* Minmap level l: the least of each 2 x 2 of level l - 1. */
	memcpy(lev, m->v, n * sizeof *lev);
	for (unsigned l = 1; minmap && (m->w >> l) > 0 && (m->h >> l) > 0;
	    l++) {
		uint32_t w = m->w >> l, h = m->h >> l, pw = m->w >> (l - 1);
		for (uint32_t y = 0; y < h; y++)
			for (uint32_t x = 0; x < w; x++) {
				uint32_t a = lev[2 * y * pw + 2 * x];
				uint32_t c[3] = { lev[2 * y * pw + 2 * x + 1],
				    lev[(2 * y + 1) * pw + 2 * x],
				    lev[(2 * y + 1) * pw + 2 * x + 1] };
				for (int k = 0; k < 3; k++)
					a = c[k] < a ? c[k] : a;
				up[y * w + x] = a;
			}
		for (size_t i = 0; i < (size_t)w * h; i++) {
			assert_true(at + 4 * i + 4 <= len);
			assert_int_equal(get32(b + at + 4 * i), up[i]);
		}
		memcpy(lev, up, (size_t)w * h * sizeof *lev);
		at += 4 * (size_t)w * h;
	}
	/* Per block size B: B, 0, then block by block (row-major) its
	 * values ascending, then their indices y B + x in the block. */
	for (unsigned k = 0; k < nblocks; k++) {
		uint32_t B = blocks[k];
		size_t bb = (size_t)B * B, blk = 0;
		assert_true(at + 8 + 8 * n <= len);
		assert_int_equal(get32(b + at), B);
		assert_int_equal(get32(b + at + 4), 0);
		at += 8;
		for (uint32_t by = 0; by < m->h / B; by++)
			for (uint32_t bx = 0; bx < m->w / B; bx++, blk++)
				for (size_t r = 0; r < bb; r++) {
					/* The r-th smallest by selection. */
					uint32_t best = UINT32_MAX, bi = 0;
					for (size_t q = 0; q < bb; q++) {
						uint32_t v = m->v[((size_t)by * B + q / B) *
						    m->w + bx * B + q % B];
						uint32_t rank = 0;
						for (size_t t = 0; t < bb; t++)
							rank += m->v[((size_t)by * B + t / B) *
							    m->w + bx * B + t % B] < v;
						if (rank == r) {
							best = v;
							bi = (uint32_t)q;
						}
					}
					assert_int_equal(get32(b + at + 4 * (blk * bb +
					    r)), best);
					assert_int_equal(get32(b + at + 4 * (n + blk *
					    bb + r)), bi);
				}
		at += 8 * n;
	}
	assert_int_equal(at, len);
	free(lev);
	free(up);
}

static void test_prepared_write(void **state)
{
	uint32_t v[128];
	static const uint32_t blocks[2] = { 4, 1 };
	struct frs_matrix m, m3;
	unsigned char *b;
	size_t len;
	frs_error e;
	FILE *fp;

	(void)state;
	shuffle(v, 128, 11);
	m = matrix(16, 8, v);
	/* Minmap and two block sizes; either alone; neither. */
	for (int form = 0; form < 4; form++) {
		int minmap = form & 1;
		unsigned nb = form & 2 ? 2 : 0;
		assert_non_null(fp = fopen(tmp("w.frp"), "wb"));
		assert_int_equal(frs_prepared_write(&m, fp, "w.frp", "src", minmap,
		    nb ? blocks : NULL, nb, &e), FRS_OK);
		assert_int_equal(fclose(fp), 0);
		b = slurp(tmp("w.frp"), &len);
		check_frp_bytes(b, len, &m, minmap, blocks, nb);
		free(b);
	}

	/* What cannot be prepared. */
	assert_non_null(fp = fopen(tmp("bad.frp"), "wb"));
	assert_int_equal(frs_prepared_write(&m, fp, "f", "src", 1,
	    (const uint32_t[1]){ 3 }, 1, &e), FRS_E_ARG);
	assert_non_null(strstr(e.message, "src"));
	assert_int_equal(frs_prepared_write(&m, fp, "f", "src", 0,
	    (const uint32_t[1]){ 16 }, 1, &e), FRS_E_ARG);
	assert_int_equal(frs_prepared_write(&m, fp, "f", "src", 0, NULL, 1, &e),
	    FRS_E_ARG);
	assert_int_equal(frs_prepared_write(&m, fp, "f", "src", 0, blocks, 33,
	    &e), FRS_E_ARG);
	assert_int_equal(frs_matrix_alloc(&m3, 3, 4, 4, 4, NULL, NULL), FRS_OK);
	assert_int_equal(frs_prepared_write(&m3, fp, "f", "cube", 1, NULL, 0,
	    &e), FRS_E_ARG);
	assert_non_null(strstr(e.message, "cube"));
	frs_matrix_free(&m3);
	/* Sides of 12: the minmap needs powers of two; the values alone go. */
	assert_int_equal(frs_matrix_alloc(&m3, 2, 12, 8, 1, NULL, NULL), FRS_OK);
	for (size_t i = 0; i < m3.n; i++)
		m3.v[i] = (uint32_t)(m3.n - 1 - i);
	assert_int_equal(frs_prepared_write(&m3, fp, "f", "src", 1, NULL, 0, &e),
	    FRS_E_ARG);
	assert_int_equal(fclose(fp), 0);
	assert_non_null(fp = fopen(tmp("plain.frp"), "wb"));
	assert_int_equal(frs_prepared_write(&m3, fp, "f", "src", 0, NULL, 0, &e),
	    FRS_OK);
	assert_int_equal(fclose(fp), 0);
	b = slurp(tmp("plain.frp"), &len);
	check_frp_bytes(b, len, &m3, 0, NULL, 0);
	free(b);
	frs_matrix_free(&m3);
	/* A stream that takes nothing. */
	fp = fopen("/dev/full", "wb");
	if (fp != NULL) {
		setvbuf(fp, NULL, _IONBF, 0);
		assert_int_equal(frs_prepared_write(&m, fp, "full", "src", 1,
		    blocks, 2, &e), FRS_E_IO);
		assert_non_null(strstr(e.message, "full: write error"));
		fclose(fp);
	}
	assert_int_equal(frs_prepared_write(NULL, stdout, "f", "s", 0, NULL, 0,
	    &e), FRS_E_ARG);
	frs_matrix_free(&m);
}

/* ---- frs_matrix_read_file -------------------------------------------- */

static void write_frd(const char *path, const struct frs_matrix *m)
{
	FILE *fp = fopen(path, "wb");

	assert_non_null(fp);
	assert_int_equal(frs_matrix_write(m, fp, path, NULL), FRS_OK);
	assert_int_equal(fclose(fp), 0);
}

static void test_read_file(void **state)
{
	uint32_t v[64];
	static const uint32_t blocks[2] = { 2, 4 };
	struct frs_matrix m, r;
	struct frs_file_info fi;
	unsigned char *b;
	size_t len;
	frs_error e;
	FILE *fp;

	(void)state;
	shuffle(v, 64, 5);
	m = matrix(16, 4, v);
	write_frd(tmp("a.frd"), &m);
	/* A .frd, as frs_matrix_read reads it. */
	assert_int_equal(frs_matrix_read_file(&r, tmp("a.frd"), 0, &fi, &e),
	    FRS_OK);
	assert_int_equal(fi.frp, 0);
	assert_int_equal(fi.checked, 0);
	assert_int_equal(r.w, 16);
	assert_int_equal(r.h, 4);
	assert_string_equal(r.params, "test=1\n");
	assert_memory_equal(r.v, v, sizeof v);
	frs_matrix_free(&r);
	/* One that is no permutation: refused, unless any values go. */
	m.v[7] = m.v[8];
	write_frd(tmp("dup.frd"), &m);
	assert_int_equal(frs_matrix_read_file(&r, tmp("dup.frd"), 0, &fi, &e),
	    FRS_E_FORMAT);
	assert_non_null(strstr(e.message, "not a permutation"));
	assert_null(r.v);
	assert_int_equal(frs_matrix_read_file(&r, tmp("dup.frd"),
	    FRS_READ_ANY_VALUES, &fi, &e), FRS_OK);
	assert_memory_equal(r.v, m.v, sizeof v);
	assert_int_equal(frs_matrix_check(&r, "dup", NULL), FRS_E_FORMAT);
	frs_matrix_free(&r);
	memcpy(m.v, v, sizeof v);

	/* A .frp: told, and checked when asked. */
	assert_non_null(fp = fopen(tmp("a.frp"), "wb"));
	assert_int_equal(frs_prepared_write(&m, fp, "a.frp", "a", 1, blocks, 2,
	    NULL), FRS_OK);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_matrix_read_file(&r, tmp("a.frp"),
	    FRS_READ_ANY_VALUES, &fi, &e), FRS_OK);
	assert_int_equal(fi.frp, 1);
	assert_int_equal(fi.checked, 0);
	assert_null(r.v);
	assert_int_equal(frs_matrix_read_file(&r, tmp("a.frp"),
	    FRS_READ_CHECK_FRP, &fi, &e), FRS_OK);
	assert_int_equal(fi.frp, 1);
	assert_int_equal(fi.checked, 1);
	assert_int_equal(fi.w, 16);
	assert_int_equal(fi.h, 4);
	assert_true(fi.checksum == fnv(&m));
	assert_int_equal(fi.minmap, 1);
	assert_int_equal(fi.nblocks, 2);
	assert_int_equal(fi.blocks[0], 2);
	assert_int_equal(fi.blocks[1], 4);
	assert_null(r.v);
	/* The same without a minmap or lists. */
	assert_non_null(fp = fopen(tmp("b.frp"), "wb"));
	assert_int_equal(frs_prepared_write(&m, fp, "b.frp", "b", 0, NULL, 0,
	    NULL), FRS_OK);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_matrix_read_file(&r, tmp("b.frp"),
	    FRS_READ_CHECK_FRP, &fi, &e), FRS_OK);
	assert_int_equal(fi.minmap, 0);
	assert_int_equal(fi.nblocks, 0);
	/* Damaged in its last list: found only by the check. */
	b = slurp(tmp("a.frp"), &len);
	b[len - 4 * 64 - 8] ^= 1;
	spit(tmp("bad.frp"), b, len);
	assert_int_equal(frs_matrix_read_file(&r, tmp("bad.frp"), 0, &fi, &e),
	    FRS_OK);
	assert_int_equal(fi.frp, 1);
	assert_int_equal(frs_matrix_read_file(&r, tmp("bad.frp"),
	    FRS_READ_CHECK_FRP, &fi, &e), FRS_E_FORMAT);
	assert_non_null(strstr(e.message, "bad.frp"));
	assert_int_equal(fi.checked, 0);
	/* Cut short. */
	spit(tmp("cut.frp"), b, len - 9);
	assert_int_equal(frs_matrix_read_file(&r, tmp("cut.frp"),
	    FRS_READ_CHECK_FRP, &fi, &e), FRS_E_FORMAT);
	free(b);
	/* Neither, not there, a directory. */
	spit(tmp("junk"), "just some text", 14);
	assert_int_equal(frs_matrix_read_file(&r, tmp("junk"),
	    FRS_READ_CHECK_FRP, &fi, &e), FRS_E_FORMAT);
	assert_int_equal(frs_matrix_read_file(&r, tmp("none.frd"), 0, &fi, &e),
	    FRS_E_IO);
	assert_int_equal(frs_matrix_read_file(&r, tu_dir(), 0, &fi, &e),
	    FRS_E_IO);
	assert_int_equal(frs_matrix_read_file(&r, tmp("a.frd"), 0, NULL, &e),
	    FRS_E_ARG);
	frs_matrix_free(&m);
}

/* ---- frs_prepared_plan ----------------------------------------------- */

/* The 128 x 128 matrix of frd-prep's table below: (7919 i) mod 2^14. */
static struct frs_matrix table_matrix(void)
{
	struct frs_matrix m;

	assert_int_equal(frs_matrix_alloc(&m, 2, 128, 128, 1, NULL, NULL),
	    FRS_OK);
	for (size_t i = 0; i < m.n; i++)
		m.v[i] = (uint32_t)(i * 7919 % m.n);
	return m;
}

/* A row of frd-prep --for's table: n, level, n_s, window side, block,
 * minmap, values, from_frp. */
struct row {
	uint64_t n;
	unsigned level;
	uint32_t ns;
	uint64_t side;
	uint32_t block;
	int minmap;
	uint64_t values;
	int from_frp;
};

/* The rows of spec's map at side x side (0: its own size) under sigma
 * and tiling. */
static void check_rows(const struct frs_matrix *m, const char *spec,
    uint32_t side, double sigma, enum frs_tiling_mode tiling,
    const struct row *rows, size_t nrows)
{
	struct frs_imap map;
	struct frs_options o;
	struct frs_prepared_level lv[32];
	size_t at = 0;

	frs_options_init(&o);
	o.sigma = sigma;
	o.tiling = tiling;
	assert_int_equal(frs_imap_load(&map, spec, side, side, 0, NULL),
	    FRS_OK);
	while (at < nrows) {
		uint64_t n = rows[at].n;
		unsigned count = 99;
		assert_int_equal(frs_prepared_plan(m, &map, n, &o, lv, 32, &count,
		    NULL), FRS_OK);
		for (unsigned l = 0; l < count; l++, at++) {
			assert_true(at < nrows);
			assert_true(rows[at].n == n);
			assert_int_equal(lv[l].level, rows[at].level);
			assert_int_equal(lv[l].ns, rows[at].ns);
			assert_int_equal(lv[l].window_w, rows[at].side);
			assert_int_equal(lv[l].window_h, rows[at].side);
			assert_int_equal(lv[l].block, rows[at].block);
			assert_int_equal(lv[l].minmap, rows[at].minmap);
			assert_int_equal(lv[l].values, rows[at].values);
			assert_int_equal(lv[l].from_frp, rows[at].from_frp);
		}
		assert_true(at == nrows || rows[at].n != n);
	}
	frs_imap_free(&map);
}

/* frd-prep --for's tables at 3c04e07 (the program then computed them
 * from the library's internals itself) for table_matrix, and for the
 * 8 x 8 matrix (29 i) mod 64 on a map of one pixel, whose lists would
 * hold more values than the matrix has (64: all of them). */
static void test_plan_table(void **state)
{
	static const struct row plain[] = {
		{ 100, 0, 2, 256, 2, 0, 177, 0 },
		{ 20000, 0, 32, 4096, 32, 0, 139, 0 } };
	static const struct row levels[] = {
		{ 20000, 1, 16, 2048, 16, 0, 554, 0 },
		{ 20000, 2, 8, 1024, 0, 1, 0, 0 },
		{ 20000, 3, 4, 512, 0, 1, 0, 0 },
		{ 20000, 4, 2, 256, 0, 1, 0, 0 },
		{ 300000, 1, 64, 8192, 32, 1, 519, 0 },
		{ 300000, 2, 32, 4096, 32, 0, 664, 0 },
		{ 300000, 3, 16, 2048, 0, 1, 0, 0 },
		{ 300000, 4, 8, 1024, 0, 1, 0, 0 } };
	static const struct row dense[] = {
		{ 200000, 0, 4, 512, 4, 0, 12500, 1 } };
	static const struct row shuffled[] = {
		{ 5000, 0, 4, 512, 4, 0, 623, 0 } };
	static const struct row pixel[] = {
		{ 1, 0, 1, 1, 1, 0, 64, 1 },
		{ 3, 0, 2, 2, 2, 0, 48, 1 },
		{ 10, 0, 4, 4, 4, 0, 40, 1 },
		{ 60, 0, 8, 8, 8, 0, 60, 1 },
		{ 1000, 0, 32, 32, 8, 1, 63, 1 } };
	struct frs_matrix m = table_matrix(), t;

	(void)state;
	check_rows(&m, "blob", 0, 8, FRS_TILING_PLAIN, plain, 2);
	check_rows(&m, "blob", 0, 8, FRS_TILING_LEVELS, levels, 8);
	check_rows(&m, "const", 0, 1, FRS_TILING_LEVELS, dense, 1);
	check_rows(&m, "ramp", 0, 4, FRS_TILING_SHUFFLED, shuffled, 1);
	frs_matrix_free(&m);
	assert_int_equal(frs_matrix_alloc(&t, 2, 8, 8, 1, NULL, NULL), FRS_OK);
	for (size_t i = 0; i < t.n; i++)
		t.v[i] = (uint32_t)(i * 29 % 64);
	check_rows(&t, "const", 1, 1, FRS_TILING_PLAIN, pixel, 5);
	frs_matrix_free(&t);
}

/* The levels against a sampler's of the same matrix, map and options,
 * and what a level's lists are against its block. */
static void test_plan_sampler(void **state)
{
	static const char *const specs[] = { "blob", "const", "ramp", "sky" };
	static const uint64_t counts[] = { 1, 100, 5000, 70000, 1000000 };
	struct frs_matrix m = table_matrix();
	frs_mask *mk;

	(void)state;
	assert_int_equal(frs_mask_wrap(&mk, m.v, m.w, m.h, NULL), FRS_OK);
	for (size_t s = 0; s < 4; s++)
		for (int t = 0; t < 3; t++) {
			struct frs_imap map;
			struct frs_options o;
			frs_sampler *sp;
			frs_options_init(&o);
			o.tiling = (enum frs_tiling_mode)t;
			o.sigma = 2 + 3 * s;
			assert_int_equal(frs_imap_load(&map, specs[s], 64, 32, 0,
			    NULL), FRS_OK);
			assert_int_equal(frs_sampler_new_f64(&sp, mk, map.v, map.w,
			    map.h, 0, &o, NULL), FRS_OK);
			for (size_t k = 0; k < 5; k++) {
				struct frs_prepared_level lv[32];
				struct frs_level_info li[32];
				unsigned nl = 0, ni = 0;
				assert_int_equal(frs_prepared_plan(&m, &map, counts[k],
				    &o, lv, 32, &nl, NULL), FRS_OK);
				assert_int_equal(frs_sampler_levels(sp, counts[k], 1, li,
				    32, &ni, NULL), FRS_OK);
				assert_int_equal(nl, ni);
				for (unsigned l = 0; l < nl; l++) {
					assert_int_equal(lv[l].level, li[l].level);
					assert_int_equal(lv[l].ns, li[l].ns);
					assert_int_equal(lv[l].window_w, li[l].window[0]);
					assert_int_equal(lv[l].window_h, li[l].window[1]);
					assert_true(lv[l].block <= lv[l].ns);
					assert_int_equal(lv[l].minmap, lv[l].block == 0 ||
					    lv[l].block < lv[l].ns);
					assert_int_equal(lv[l].values == 0,
					    lv[l].block == 0);
					assert_true(lv[l].values <= m.n);
					assert_int_equal(lv[l].from_frp, lv[l].block != 0 &&
					    lv[l].values >= m.n / 2);
				}
			}
			frs_sampler_free(sp);
			frs_imap_free(&map);
		}
	frs_mask_free(mk);
	frs_matrix_free(&m);
}

static void test_plan_args(void **state)
{
	struct frs_matrix m = table_matrix(), m3;
	struct frs_imap map;
	struct frs_options o;
	struct frs_prepared_level lv[2];
	unsigned count = 7;
	frs_error e;

	(void)state;
	assert_int_equal(frs_imap_load(&map, "blob", 0, 0, 0, NULL), FRS_OK);
	/* cap smaller than the levels: the count all the same, the first
	 * cap written (20000 of blob has 4, table above). */
	memset(lv, 0xab, sizeof lv);
	assert_int_equal(frs_prepared_plan(&m, &map, 20000, NULL, lv, 1, &count,
	    &e), FRS_OK);
	assert_int_equal(count, 4);
	assert_int_equal(lv[0].level, 1);
	assert_int_equal(lv[1].level, 0xabababab);
	assert_int_equal(frs_prepared_plan(&m, &map, 20000, NULL, NULL, 0,
	    &count, &e), FRS_OK);
	assert_int_equal(count, 4);
	/* Bad arguments. */
	assert_int_equal(frs_prepared_plan(&m, &map, 0, NULL, lv, 2, &count, &e),
	    FRS_E_ARG);
	assert_int_equal(count, 0);
	assert_int_equal(frs_prepared_plan(&m, &map, ((uint64_t)1 << 40) + 1,
	    NULL, lv, 2, &count, &e), FRS_E_LIMIT);
	assert_int_equal(frs_prepared_plan(&m, &map, ((uint64_t)1 << 40),
	    NULL, lv, 2, &count, &e), FRS_OK);
	assert_int_equal(frs_prepared_plan(NULL, &map, 10, NULL, lv, 2, &count,
	    &e), FRS_E_ARG);
	assert_int_equal(frs_prepared_plan(&m, NULL, 10, NULL, lv, 2, &count,
	    &e), FRS_E_ARG);
	assert_int_equal(frs_prepared_plan(&m, &map, 10, NULL, NULL, 2, &count,
	    &e), FRS_E_ARG);
	frs_options_init(&o);
	o.sigma = 0.5;
	assert_int_equal(frs_prepared_plan(&m, &map, 10, &o, lv, 2, &count, &e),
	    FRS_E_ARG);
	/* A 3-D matrix samples no map. */
	assert_int_equal(frs_matrix_alloc(&m3, 3, 8, 8, 8, NULL, NULL), FRS_OK);
	for (size_t i = 0; i < m3.n; i++)
		m3.v[i] = (uint32_t)i;
	assert_int_equal(frs_prepared_plan(&m3, &map, 10, NULL, lv, 2, &count,
	    &e), FRS_E_ARG);
	assert_string_equal(e.message, "a 3-D matrix cannot sample a 2-D map");
	frs_matrix_free(&m3);
	frs_imap_free(&map);
	frs_matrix_free(&m);
}

TU_MAIN(NULL, NULL,
    cmocka_unit_test(test_alloc),
    cmocka_unit_test(test_check),
    cmocka_unit_test(test_rank),
    cmocka_unit_test(test_checksum),
    cmocka_unit_test(test_read_png),
    cmocka_unit_test(test_prepared_write),
    cmocka_unit_test(test_read_file),
    cmocka_unit_test(test_plan_table),
    cmocka_unit_test(test_plan_sampler),
    cmocka_unit_test(test_plan_args))
