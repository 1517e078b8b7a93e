/* Prepared matrices (.frp, sample/frscore.h): the layout of frd(5) read
 * back by hand, the minmap and sorted lists against brute force, the
 * round trip, and every kind of damage refused with the file named. */
#include "testutil.h"
#include "frsutil.h"
#include "base/io.h"
#include "sample/frpio.h"

#define W 32u
#define H 16u
#define HEADER 40

static struct frs_matrix mat;	/* W x H, a random permutation */
static const uint32_t blocks[] = { 4, 8 };

/* Level l of the minmap by brute force: the smallest value of each
 * 2^l x 2^l block. */
static uint32_t block_min(const struct frs_matrix *m, unsigned l, uint32_t x,
    uint32_t y)
{
	uint32_t best = UINT32_MAX, s = 1u << l;

	for (uint32_t j = y * s; j < (y + 1) * s; j++)
		for (uint32_t i = x * s; i < (x + 1) * s; i++)
			best = m->v[(size_t)j * m->w + i] < best ?
			    m->v[(size_t)j * m->w + i] : best;
	return best;
}

static int u32_cmp(const void *a, const void *b)
{
	uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
	return (x > y) - (x < y);
}

/* The minmap levels 1 .. while both sides last, each the block minima. */
static unsigned check_levels(const struct frs_prep *p)
{
	unsigned l;

	for (l = 1; (W >> l) > 0 && (H >> l) > 0; l++) {
		assert_true(l < p->nlev);
		for (uint32_t y = 0; y < (H >> l); y++)
			for (uint32_t x = 0; x < (W >> l); x++)
				assert_int_equal(p->lev[l][y * (W >> l) + x],
				    block_min(&mat, l, x, y));
	}
	assert_int_equal(p->nlev, l);
	return l - 1;
}

/* Each b x b block's list: its values ascending, each with its index
 * (y % b) b + x % b in the block. */
static void check_lists(const struct frs_prep *p, uint32_t b)
{
	uint32_t bb = b * b, vals[64];

	assert_int_equal(p->block, b);
	for (uint32_t blk = 0; blk < W * H / bb; blk++) {
		uint32_t bx = blk % (W / b), by = blk / (W / b);
		for (uint32_t k = 0; k < bb; k++)
			vals[k] = mat.v[(by * b + k / b) * W + bx * b + k % b];
		qsort(vals, bb, sizeof *vals, u32_cmp);
		for (uint32_t k = 0; k < bb; k++) {
			uint32_t i = p->sidx[blk * bb + k];
			assert_int_equal(p->sval[blk * bb + k], vals[k]);
			assert_int_equal(mat.v[(by * b + i / b) * W + bx * b + i % b],
			    vals[k]);
		}
	}
}

static const char *write_frp(const char *name, int minmap, unsigned nb)
{
	const char *path = tu_path(name);
	FILE *fp = tu_create(path);

	assert_int_equal(frp_write(fp, path, "mat", &mat, minmap, blocks, nb),
	    0);
	tu_close(fp);
	return path;
}

/* The bytes as frd(5) lays them out, and what frp_read makes of them. */
static void layout_and_round_trip(void **state)
{
	const char *path = write_frp("full.frp", 1, 2);
	struct frs_matrix m;
	struct frs_prep p;
	struct frp_summary s;
	unsigned char *b;
	size_t n, levels = 0;
	uint32_t w, h;
	uint64_t sum;
	FILE *fp;

	(void)state;
	b = tu_read(path, &n);
	assert_memory_equal(b, "\211FRP\r\n\032\n", 8);
	assert_int_equal(io_get_u32(b + 8), 1);
	assert_int_equal(io_get_u32(b + 12), W);
	assert_int_equal(io_get_u32(b + 16), H);
	assert_int_equal(io_get_u32(b + 20), 3);
	assert_true(io_get_u64(b + 24) == frd_checksum(&mat));
	assert_int_equal(io_get_u32(b + 32), 2);
	assert_int_equal(io_get_u32(b + 36), 0);
	for (size_t i = 0; i < mat.n; i++)
		assert_int_equal(io_get_u32(b + HEADER + 4 * i), mat.v[i]);
	for (unsigned l = 1; (W >> l) && (H >> l); l++)
		levels += (size_t)(W >> l) * (H >> l);
	assert_int_equal(n, HEADER + 4 * mat.n + 4 * levels + 2 * (8 + 8 *
	    mat.n));
	assert_int_equal(io_get_u32(b + HEADER + 4 * (mat.n + levels)), 4);
	free(b);

	for (unsigned k = 0; k < 2; k++) {
		assert_int_equal(frp_read(path, &m, &p, blocks[k]), 0);
		assert_memory_equal(m.v, mat.v, mat.n * sizeof *m.v);
		assert_true(m.dims == 2 && m.w == W && m.h == H);
		assert_int_equal(check_levels(&p), 4);
		check_lists(&p, blocks[k]);
		frs_prep_free(&p);
		frd_free(&m);
	}
	/* A block size the file lacks: no lists. */
	assert_int_equal(frp_read(path, &m, &p, 2), 0);
	assert_int_equal(p.block, 0);
	check_levels(&p);
	frs_prep_free(&p);
	frd_free(&m);

	assert_int_equal(frp_is(path), 1);
	assert_int_equal(frp_info(path, &w, &h, &sum), 0);
	assert_true(w == W && h == H && sum == frd_checksum(&mat));
	fp = fopen(path, "rb");
	assert_non_null(fp);
	assert_int_equal(frp_check_fp(fp, path, NULL, 0, &s), 0);
	fclose(fp);
	assert_true(s.w == W && s.h == H && s.sum == sum && s.minmap);
	assert_true(s.nblocks == 2 && s.blocks[0] == 4 && s.blocks[1] == 8);
}

/* Without the minmap and lists: the matrix alone, the file that long. */
static void matrix_only(void **state)
{
	const char *path = write_frp("bare.frp", 0, 0);
	struct frs_matrix m;
	struct frs_prep p;
	unsigned char *b;
	size_t n;

	(void)state;
	b = tu_read(path, &n);
	assert_int_equal(n, HEADER + 4 * mat.n);
	assert_int_equal(io_get_u32(b + 20), 0);
	free(b);
	assert_int_equal(frp_read(path, &m, &p, 4), 0);
	assert_memory_equal(m.v, mat.v, mat.n * sizeof *m.v);
	assert_true(p.nlev == 1 && p.block == 0);
	frs_prep_free(&p);
	frd_free(&m);
	assert_int_equal(frp_is(tu_path("nothing.frp")), -1);
	tu_write(tu_path("text.frp"), "\211FRQ\r\n\032\n", 8);
	assert_int_equal(frp_is(tu_path("text.frp")), 0);
}

/* Damage at offset at: the u32 there set to v (or, len < 0: the file
 * cut by -len bytes; len > 0: len bytes appended). */
struct damage {
	const char *what;
	size_t at;
	uint32_t v;
	long len;
	const char *msg;
};

static void damaged_files_refused(void **state)
{
	size_t lev1 = HEADER + 4 * (size_t)W * H, levels = 0, sets;
	struct damage *d;
	unsigned char *good;
	size_t n;

	(void)state;
	for (unsigned l = 1; (W >> l) && (H >> l); l++)
		levels += (size_t)(W >> l) * (H >> l);
	sets = lev1 + 4 * levels;
	{
		struct damage cases[] = {
			{ "magic", 0, 0x12345678, 0, "wrong magic" },
			{ "version", 8, 2, 0, "version 2" },
			{ "flags", 20, 7, 0, "impossible header" },
			{ "width", 12, 0, 0, "impossible header" },
			{ "sets", 32, 33, 0, "impossible header" },
			{ "cut", 0, 0, -4, "truncated" },
			{ "cut header", 0, 0, -(long)(sets + 2 * (8 + 8 * W * H) - 20),
			    "" },
			{ "trailing", 0, 0, 3, "trailing data" },
			{ "matrix", HEADER + 8, 5, 0, "checksum" },
			{ "minmap", lev1, 77, 0, "damaged minmap level 1" },
			{ "block size", sets, 3, 0, "impossible block size 3" },
			{ "sorted value", sets + 8 + 4 * 17, 0, 0,
			    "damaged sorted list of block 1" },
			{ "sorted index", sets + 8 + 4 * W * H + 4 * 3, 9999, 0,
			    "damaged sorted list of block 0" },
		};
		good = tu_read(write_frp("good.frp", 1, 2), &n);
		for (d = cases; d < cases + sizeof cases / sizeof cases[0]; d++) {
			unsigned char *b = malloc(n + 8);
			const char *path = tu_path("bad.frp");
			struct frs_matrix m;
			struct frs_prep p;
			size_t len = n;
			FILE *fp;
			assert_non_null(b);
			memcpy(b, good, n);
			if (d->len < 0)
				len -= (size_t)-d->len;
			else if (d->len > 0)
				memset(b + n, 0, (size_t)d->len), len += (size_t)d->len;
			else
				io_put_u32(b + d->at, d->v);
			tu_write(path, b, len);
			free(b);
			if (frp_read(path, &m, &p, 4) != -1) {
				print_error("%s: read\n", d->what);
				fail();
			}
			assert_null(m.v);
			assert_err_has(path, d->msg);
			/* Every set checked, not only the one asked for. */
			fp = fopen(path, "rb");
			assert_non_null(fp);
			{
				struct frp_summary s;
				assert_int_equal(frp_check_fp(fp, "bad", NULL, 0, &s),
				    -1);
				assert_err_has("bad", d->msg);
			}
			fclose(fp);
		}
		free(good);
	}
	/* Two entries of a list swapped, values with their indices: each
	 * still names its cell, but the list is out of order. */
	{
		const char *path = write_frp("swapped.frp", 1, 1);
		unsigned char *b = tu_read(path, &n), t[4];
		struct frs_matrix m;
		struct frs_prep p;
		for (size_t off = sets + 8; off <= sets + 8 + 4 * W * H; off +=
		    4 * W * H) {
			memcpy(t, b + off, 4);
			memcpy(b + off, b + off + 4, 4);
			memcpy(b + off + 4, t, 4);
		}
		tu_write(path, b, n);
		free(b);
		assert_int_equal(frp_read(path, &m, &p, 4), -1);
		assert_err_has(path, "damaged sorted list of block 0");
	}
	/* A damaged list of a set not asked for is skipped by frp_read but
	 * found by frp_check_fp. */
	{
		const char *path = write_frp("second.frp", 1, 2);
		unsigned char *b = tu_read(path, &n);
		struct frs_matrix m;
		struct frs_prep p;
		struct frp_summary s;
		FILE *fp;
		io_put_u32(b + sets + 8 + 8 * W * H + 8 + 4 * 70, 0);
		tu_write(path, b, n);
		free(b);
		assert_int_equal(frp_read(path, &m, &p, 4), 0);
		frs_prep_free(&p);
		frd_free(&m);
		fp = fopen(path, "rb");
		assert_non_null(fp);
		assert_int_equal(frp_check_fp(fp, path, NULL, 0, &s), -1);
		assert_err_has(path, "damaged sorted list of block 1");
		fclose(fp);
	}
}

/* Values that are no permutation under a checksum that matches them (a
 * file made so, not damaged in passing): refused by the check made in
 * the checksum's pass, a repeat with its place, a value out of range. */
static void values_checked(void **state)
{
	static const struct {
		size_t at;
		uint32_t v;	/* UINT32_MAX: element 0's value */
		const char *msg;
	} c[] = { { 5, UINT32_MAX, "not a permutation: value" },
		  { 7, W * H, "value 512 at element 7 is out of range" } };

	(void)state;
	for (size_t k = 0; k < sizeof c / sizeof c[0]; k++) {
		const char *path = write_frp("values.frp", 0, 0);
		struct frs_matrix m, e;
		struct frs_prep p;
		unsigned char *b;
		size_t n;
		char where[64];
		b = tu_read(path, &n);
		assert_int_equal(frd_alloc(&e, 2, W, H, 1, ""), 0);
		memcpy(e.v, mat.v, (size_t)W * H * sizeof *e.v);
		e.v[c[k].at] = c[k].v == UINT32_MAX ? mat.v[0] : c[k].v;
		io_put_u32(b + HEADER + 4 * c[k].at, e.v[c[k].at]);
		io_put_u64(b + 24, frd_checksum(&e));
		tu_write(path, b, n);
		free(b);
		assert_int_equal(frp_read(path, &m, &p, 4), -1);
		assert_null(m.v);
		snprintf(where, sizeof where, "repeats at (%zu, 0, 0)", c[k].at);
		if (c[k].v == UINT32_MAX)
			assert_err_has(path, c[k].msg, where);
		else
			assert_err_has(path, c[k].msg);
		frd_free(&e);
	}
}

/* What cannot be prepared: 3-D, sides not powers of two. */
static void write_refusals(void **state)
{
	struct frs_matrix m;
	FILE *fp = tu_create(tu_path("no.frp"));

	(void)state;
	assert_int_equal(frd_alloc(&m, 3, 4, 4, 4, ""), 0);
	tu_perm_fill(&m, 2);
	assert_int_equal(frp_write(fp, "no.frp", "cube.frd", &m, 1, NULL, 0),
	    -1);
	assert_err_has("cube.frd", "2-D");
	frd_free(&m);
	tu_perm_matrix(&m, 12, 8, 2);
	assert_int_equal(frp_write(fp, "no.frp", "odd.frd", &m, 1, NULL, 0),
	    -1);
	assert_err_has("odd.frd");
	frd_free(&m);
	fclose(fp);
}

static int setup(void **state)
{
	(void)state;
	tu_perm_matrix(&mat, W, H, 11);
	return 0;
}

static int teardown(void **state)
{
	frd_free(&mat);
	return tu_teardown(state);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(layout_and_round_trip),
	cmocka_unit_test(matrix_only),
	cmocka_unit_test(damaged_files_refused),
	cmocka_unit_test(values_checked),
	cmocka_unit_test(write_refusals))
