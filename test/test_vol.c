/* Importance volumes (maps/vol.h): the .frv layout of frv(5) read back by
 * hand, the round trip, damaged files refused with the file named, the
 * validation of values and the loader's choices. */
#include "testutil.h"
#include "base/io.h"
#include "maps/mapload.h"
#include "maps/vol.h"

/* A w x h x d volume of value(x, y, z) = 1 + x + 10 y + 100 z + 1/4:
 * every voxel different, all exact in float. */
static void numbered(struct frs_vol *v, uint32_t w, uint32_t h, uint32_t d)
{
	assert_int_equal(vol_alloc(v, w, h, d), 0);
	for (uint32_t z = 0; z < d; z++)
		for (uint32_t y = 0; y < h; y++)
			for (uint32_t x = 0; x < w; x++)
				v->v[((size_t)z * h + y) * w + x] = 1.25 + x + 10.0 * y +
				    100.0 * z;
}

static const char *write_vol(const char *name, const struct frs_vol *v)
{
	const char *path = tu_path(name);
	FILE *fp = tu_create(path);

	assert_int_equal(vol_write(fp, path, v), 0);
	tu_close(fp);
	return path;
}

static void alloc_and_view(void **state)
{
	struct frs_vol v;
	struct frs_imap m;

	(void)state;
	numbered(&v, 3, 4, 5);
	for (size_t i = 0; i < 60; i++)
		assert_true(v.v[i] > 0.0);
	/* The map view: slices stacked downwards, the same values. */
	m = vol_as_map(&v);
	assert_true(m.w == 3 && m.h == 20 && m.v == v.v);
	assert_near(m.v[(size_t)(2 * 4 + 1) * 3 + 2], 1.25 + 2 + 10 + 200, 0);
	vol_free(&v);
	assert_null(v.v);
	assert_true(v.w == 0 && v.h == 0 && v.d == 0);
	/* Sides 1 to 65536, at most 2^28 voxels. */
	assert_int_equal(vol_alloc(&v, 0, 4, 4), -1);
	assert_err_has("0x4x4", "2^28");
	assert_null(v.v);
	assert_int_equal(vol_alloc(&v, VOL_MAX_SIDE + 1, 1, 1), -1);
	assert_int_equal(vol_alloc(&v, 1024, 1024, 257), -1);
	assert_int_equal(vol_alloc(&v, VOL_MAX_SIDE, 1, 1), 0);
	vol_free(&v);
}

/* The bytes of frv(5), and the values back as written. */
static void layout_and_round_trip(void **state)
{
	struct frs_vol v, r;
	const char *path;
	unsigned char *b;
	size_t n;
	FILE *fp;

	(void)state;
	numbered(&v, 5, 3, 2);
	path = write_vol("n.frv", &v);
	b = tu_read(path, &n);
	assert_int_equal(n, FRV_HEADER + 4 * 30);
	assert_memory_equal(b, "\211FRV\r\n\032\n", 8);
	assert_int_equal(io_get_u32(b + 8), 1);
	assert_true(io_get_u32(b + 12) == 5 && io_get_u32(b + 16) == 3 &&
	    io_get_u32(b + 20) == 2);
	assert_true(io_get_u64(b + 24) == 0);
	for (size_t i = 0; i < 30; i++) {
		uint32_t u = io_get_u32(b + FRV_HEADER + 4 * i);
		float f;
		memcpy(&f, &u, sizeof f);
		assert_true((double)f == v.v[i]);
	}
	free(b);
	assert_int_equal(vol_is_file(path), 1);
	assert_true(vol_is_volume(path));
	assert_int_equal(vol_read(path, &r), 0);
	assert_true(r.w == 5 && r.h == 3 && r.d == 2);
	assert_memory_equal(r.v, v.v, 30 * sizeof *r.v);
	vol_free(&r);
	/* Doubles are rounded to float32 on the way. */
	v.v[7] = 0.1;
	path = write_vol("r.frv", &v);
	assert_int_equal(vol_read(path, &r), 0);
	assert_true(r.v[7] == (double)0.1f && r.v[7] != 0.1);
	vol_free(&r);
	/* What float32 cannot hold is refused, the voxel named. */
	fp = tu_create(tu_path("out.frv"));
	v.v[9] = 1e300;
	assert_int_equal(vol_write(fp, "big.frv", &v), -1);
	assert_err_has("big.frv", "1e+300", "voxel 9");
	v.v[9] = 1e-300;
	assert_int_equal(vol_write(fp, "tiny.frv", &v), -1);
	assert_err_has("tiny.frv", "voxel 9");
	fclose(fp);
	vol_free(&v);
	assert_int_equal(vol_is_file(tu_path("none.frv")), -1);
	assert_int_equal(vol_is_file("-"), 0);
}

static void damaged_files_refused(void **state)
{
	static const struct {
		size_t at;
		uint32_t v;
		long len;
		const char *msg;
	} c[] = {
		{ 1, 0x41414141, 0, "wrong magic" },
		{ 8, 2, 0, "version 2" },
		{ 24, 1, 0, "reserved" },
		{ 12, 0, 0, "impossible size 0x3x2" },
		{ 16, 70000, 0, "impossible size" },
		{ 12, 6, 0, "needs 176" },	/* 32 + 4 * 36 */
		{ 0, 0, -4, "file has 148 bytes" },
		{ 0, 0, -100, "file has 52 bytes" },
		{ 0, 0, 1, "file has 153 bytes" },
		{ 0, 0, -140, "header" },
	};
	struct frs_vol v;
	unsigned char *good;
	size_t n;

	(void)state;
	numbered(&v, 5, 3, 2);
	good = tu_read(write_vol("good.frv", &v), &n);
	vol_free(&v);
	for (size_t k = 0; k < sizeof c / sizeof c[0]; k++) {
		unsigned char b[256];
		const char *path = tu_path("bad.frv");
		size_t len = n;
		memcpy(b, good, n);
		memset(b + n, 0, sizeof b - n);
		if (c[k].len < 0)
			len -= (size_t)-c[k].len;
		else if (c[k].len > 0)
			len += (size_t)c[k].len;
		else
			io_put_u32(b + c[k].at, c[k].v);
		tu_write(path, b, len);
		if (vol_read(path, &v) != -1) {
			print_error("case %zu read\n", k);
			fail();
		}
		assert_null(v.v);
		assert_err_has(path, c[k].msg);
	}
	free(good);
}

/* NaN and infinity name the voxel by its coordinates; negatives are
 * clamped (an error when strict); all zero is refused unless allowed. */
static void validation(void **state)
{
	struct frs_vol v;

	(void)state;
	numbered(&v, 4, 3, 2);
	v.v[(1 * 3 + 2) * 4 + 3] = NAN;
	assert_int_equal(vol_validate(&v, "nan.frv", 0), -1);
	assert_err_has("nan.frv", "(3, 2, 1)", "NaN");
	v.v[(1 * 3 + 2) * 4 + 3] = 1.0;
	v.v[(0 * 3 + 1) * 4 + 2] = -INFINITY;
	assert_int_equal(vol_validate(&v, "inf.frv", 0), -1);
	assert_err_has("inf.frv", "(2, 1, 0)", "infinite");
	v.v[(0 * 3 + 1) * 4 + 2] = -0.5;
	v.v[(1 * 3 + 0) * 4 + 1] = -2.0;
	assert_int_equal(vol_validate(&v, "neg.frv", FRS_MAP_STRICT), -1);
	assert_err_has("neg.frv", "negative", "2 negative voxels", "-2");
	assert_true(v.v[(1 * 3 + 0) * 4 + 1] == -2.0);
	{
		unsigned long warned = frs_warn_count();
		frs_set_quiet(1);
		assert_int_equal(vol_validate(&v, "neg.frv", 0), 0);
		frs_set_quiet(0);
		assert_true(frs_warn_count() == warned + 1);
	}
	for (size_t i = 0; i < 24; i++)
		assert_true(v.v[i] >= 0.0);
	assert_true(v.v[(1 * 3 + 0) * 4 + 1] == 0.0);
	assert_true(v.v[5] == 1.25 + 1 + 10);
	for (size_t i = 0; i < 24; i++)
		v.v[i] = 0.0;
	assert_int_equal(vol_validate(&v, "zero.frv", 0), -1);
	assert_err_has("zero.frv", "zero everywhere");
	assert_int_equal(vol_validate(&v, "zero.frv", FRS_MAP_ALLOW_ZERO), 0);
	vol_free(&v);
}

/* A file at its own size only, a volume spec at the size asked, a 2-D
 * map and anything else refused. */
static void loading(void **state)
{
	struct frs_vol v, r;
	const char *path;

	(void)state;
	numbered(&v, 4, 3, 2);
	path = write_vol("l.frv", &v);
	assert_int_equal(vol_load(path, 0, 0, 0, 0, &r), 0);
	assert_memory_equal(r.v, v.v, 24 * sizeof *r.v);
	vol_free(&r);
	assert_int_equal(vol_load(path, 4, 3, 2, 0, &r), 0);
	vol_free(&r);
	assert_int_equal(vol_load(path, 4, 3, 3, 0, &r), -1);
	assert_err_has(path, "4x3x2", "4x3x3", "not resampled");
	assert_null(r.v);
	vol_free(&v);
	assert_int_equal(vol_load("const", 2, 3, 4, 0, &r), 0);
	assert_true(r.w == 2 && r.h == 3 && r.d == 4);
	for (size_t i = 0; i < 24; i++)
		assert_true(r.v[i] == r.v[0] && r.v[0] > 0.0);
	vol_free(&r);
	assert_true(vol_is_volume("blob3"));
	assert_false(vol_is_volume("const"));	/* a 2-D spec too */
	assert_false(vol_is_volume("blob"));
	assert_int_equal(vol_load("blob", 4, 4, 4, 0, &r), -1);
	assert_err_has("blob", "2-D map");
	tu_write(tu_path("text.txt"), "not a volume\n", 13);
	assert_int_equal(vol_load(tu_path("text.txt"), 0, 0, 0, 0, &r), -1);
	assert_err_has("text.txt", "not an importance volume");
	assert_int_equal(vol_load(tu_path("missing.frv"), 0, 0, 0, 0, &r), -1);
	assert_err_has("missing.frv");
}

/* map_or_vol_load: what a source is (want 0) against what it was made
 * as; a kind asked for that it is not refused; the statistics handed
 * back those of the values as loaded. */
static void either_kind(void **state)
{
	const uint32_t own[3] = { 0, 0, 0 }, sz[3] = { 6, 5, 0 };
	struct frs_imap_stats st, want;
	struct frs_imap m;
	struct frs_vol v, r;
	const char *path;

	(void)state;
	numbered(&v, 4, 3, 2);
	path = write_vol("e.frv", &v);
	assert_int_equal(map_or_vol_load(path, 0, own, 0, &m, NULL, &r), 3);
	assert_memory_equal(r.v, v.v, 24 * sizeof *r.v);
	vol_free(&r);
	assert_null(m.v);
	assert_int_equal(map_or_vol_load(path, 2, own, 0, &m, NULL, &r), -1);
	assert_err_has("e.frv", "a volume (.frv) where a 2-D map");
	assert_int_equal(map_or_vol_load("blob3", 0, own, 0, &m, NULL, &r), 3);
	assert_true(r.w == 32 && r.h == 32 && r.d == 32);
	vol_free(&r);
	assert_int_equal(map_or_vol_load("blob3", 2, own, 0, &m, NULL, &r), -1);
	assert_err_has("blob3", "a procedural volume where a 2-D map");
	assert_int_equal(map_or_vol_load("blob", 0, sz, FRS_MAP_EQUIRECT, &m, &st,
	    &r), 2);
	assert_true(m.w == 6 && m.h == 5);
	assert_null(r.v);
	imap_stats(&m, &want);
	assert_true(st.mean == want.mean && st.max == want.max &&
	    st.count == 30);
	imap_free(&m);
	tu_write(tu_path("e.txt"), "not a map\n", 10);
	assert_int_equal(map_or_vol_load(tu_path("e.txt"), 0, own, 0, &m, NULL,
	    &r), -1);
	assert_err_has("e.txt", "not a PNG or OpenEXR file");
	vol_free(&v);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(alloc_and_view),
	cmocka_unit_test(layout_and_round_trip),
	cmocka_unit_test(damaged_files_refused),
	cmocka_unit_test(validation),
	cmocka_unit_test(loading),
	cmocka_unit_test(either_kind))
