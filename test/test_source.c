/* Maps and volumes by the public API alone (frs_source_open(3), API
 * 2.2): statistics counted by hand, the checks, the pixel of a point
 * against a search over the pixels' intervals, .frv files made byte by
 * byte here and read back, the writers' bytes and round trips, raw and
 * checked loads, specs never shadowed by files, and the codes. */
#include "testutil.h"
#include "frs.h"

/* The message contains s. */
#define assert_msg(err, s) do {						\
	if (strstr((err).message, (s)) == NULL)				\
		fail_msg("message '%s' lacks '%s'", (err).message, (s));	\
} while (0)

static void put_u32(unsigned char *b, uint32_t v)
{
	for (int k = 0; k < 4; k++)
		b[k] = (unsigned char)(v >> (8 * k));
}

static uint32_t get_u32(const unsigned char *b)
{
	return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
	    (uint32_t)b[3] << 24;
}

/* A .frv of w x h x d floats vals, made by hand after frv(5). */
static const char *hand_frv(const char *name, uint32_t w, uint32_t h,
    uint32_t d, const float *vals)
{
	size_t n = (size_t)w * h * d;
	unsigned char *b = calloc(32 + 4 * n, 1);
	const char *path = tu_path(name);

	assert_non_null(b);
	memcpy(b, "\211FRV\r\n\032\n", 8);
	put_u32(b + 8, 1);
	put_u32(b + 12, w);
	put_u32(b + 16, h);
	put_u32(b + 20, d);
	for (size_t i = 0; i < n; i++) {
		uint32_t u;
		memcpy(&u, &vals[i], 4);
		put_u32(b + 32 + 4 * i, u);
	}
	tu_write(path, b, 32 + 4 * n);
	free(b);
	return path;
}

/* Counted by hand: 4 x 2 values with two negatives, a NaN, an infinity,
 * one zero. */
static void stats_by_hand(void **state)
{
	double v[8] = { 1.0, -2.0, NAN, 0.0, 3.0, INFINITY, 0.5, -0.25 };
	struct frs_imap m = { 4, 2, v };
	struct frs_imap_stats s;

	(void)state;
	frs_imap_stats(&m, &s);
	assert_int_equal(s.count, 8);
	assert_int_equal(s.zeros, 1);
	assert_int_equal(s.negatives, 2);
	assert_int_equal(s.nonfinite, 2);
	assert_true(s.min == -2.0 && s.max == 3.0);
	assert_true(s.sum == 2.25 && s.mean == 2.25 / 6);
	assert_true(s.min_negative == -2.0 && s.min_positive == 0.5);
	assert_true(s.bad_x == 2 && s.bad_y == 0 && isnan(s.bad_value));
	assert_true(s.neg_x == 1 && s.neg_y == 0);
}

static void check_values(void **state)
{
	double v[4] = { 1.0, -2.0, 0.0, 3.0 }, z[2] = { 0.0, 0.0 };
	double bad[4] = { 1.0, 1.0, 1.0, NAN };
	struct frs_imap m = { 2, 2, v }, mz = { 2, 1, z }, mb = { 2, 2, bad };
	struct frs_imap_stats s;
	frs_error err;

	(void)state;
	/* Strict: refused, the first negative pixel named, nothing
	 * changed. */
	assert_int_equal(frs_imap_check(&m, "m", FRS_MAP_STRICT, &s, &err),
	    FRS_E_MAP);
	assert_msg(err, "m: pixel (1, 0) is negative");
	assert_true(v[1] == -2.0);
	/* Clamped; the statistics those of the values left. */
	assert_int_equal(frs_imap_check(&m, "m", 0, &s, &err), FRS_OK);
	assert_true(v[0] == 1.0 && v[1] == 0.0 && v[2] == 0.0 && v[3] == 3.0);
	assert_true(s.negatives == 0 && s.zeros == 2 && s.sum == 4.0);
	assert_int_equal(frs_imap_check(&mb, "b", 0, NULL, &err), FRS_E_MAP);
	assert_msg(err, "b: pixel (1, 1) is NaN");
	assert_int_equal(frs_imap_check(&mz, "z", 0, NULL, &err), FRS_E_MAP);
	assert_msg(err, "zero everywhere");
	assert_int_equal(frs_imap_check(&mz, "z", FRS_MAP_ALLOW_ZERO, NULL,
	    &err), FRS_OK);
	assert_int_equal(frs_imap_check(NULL, "z", 0, NULL, &err), FRS_E_ARG);
}

/* The pixel of a point: the one whose [i/w, (i+1)/w) x [j/h, (j+1)/h)
 * holds it, found by a search; 1 in the last. */
static uint64_t pixel_search(uint32_t w, uint32_t h, double x, double y)
{
	uint32_t i = w - 1, j = h - 1;

	for (uint32_t k = 0; k < w; k++)
		if ((double)k / w <= x && x < (double)(k + 1) / w) {
			i = k;
			break;
		}
	for (uint32_t k = 0; k < h; k++)
		if ((double)k / h <= y && y < (double)(k + 1) / h) {
			j = k;
			break;
		}
	return (uint64_t)j * w + i;
}

static void pixel_of(void **state)
{
	static const uint32_t sides[][2] = { { 5, 3 }, { 1, 7 }, { 8, 8 },
	    { 3, 1 } };
	double v[64] = { 0 };

	(void)state;
	for (size_t c = 0; c < sizeof sides / sizeof sides[0]; c++) {
		struct frs_imap m = { sides[c][0], sides[c][1], v };
		for (int a = 0; a <= 40; a++)
			for (int b = 0; b <= 40; b++) {
				/* The corners, the edges, the middles of the
				 * pixels and points between. */
				double x = a / 40.0, y = b == 40 ? 1.0 :
				    (b + 0.37) / 40.0;
				assert_int_equal(frs_imap_pixel_of(&m, x, y),
				    pixel_search(m.w, m.h, x, y));
			}
	}
}

/* A .frv made by hand: what it is, read as it is, refused as a map. */
static void volume_file(void **state)
{
	float vals[12];
	const char *path;
	frs_source *s;
	struct frs_imap m;
	struct frs_vol v;
	unsigned dims;
	frs_error err;

	(void)state;
	for (int i = 0; i < 12; i++)
		vals[i] = (float)(i - 2) * 0.5f;	/* -1, -0.5, 0, ... */
	path = hand_frv("a.frv", 3, 2, 2, vals);
	assert_int_equal(frs_source_open(&s, path, &err), FRS_OK);
	assert_int_equal(frs_source_kinds(s), FRS_SOURCE_VOLUME);
	assert_int_equal(frs_source_load(s, 0, NULL, FRS_MAP_RAW, &dims, &m,
	    NULL, &v, &err), FRS_OK);
	assert_int_equal(dims, 3);
	assert_true(v.w == 3 && v.h == 2 && v.d == 2 && m.v == NULL);
	for (int i = 0; i < 12; i++)
		assert_true(v.v[i] == (double)vals[i]);
	frs_vol_free(&v);
	/* Read once: a second load is refused. */
	assert_int_equal(frs_source_load(s, 0, NULL, 0, &dims, &m, NULL, &v,
	    &err), FRS_E_ARG);
	assert_null(v.v);
	frs_source_close(s);
	/* Checked: the two negatives clamped to zero. */
	assert_int_equal(frs_source_read(path, 3, NULL, 0, &dims, NULL, NULL,
	    &v, &err), FRS_OK);
	assert_true(v.v[0] == 0.0 && v.v[1] == 0.0 && v.v[2] == 0.0 &&
	    v.v[3] == 0.5 && v.v[11] == 4.5);
	frs_vol_free(&v);
	assert_null(v.v);
	assert_int_equal(frs_source_read(path, 3, NULL, FRS_MAP_STRICT, &dims,
	    NULL, NULL, &v, &err), FRS_E_MAP);
	assert_msg(err, "voxel (0, 0, 0) is negative");
	/* Another size: refused (volumes are not resampled); raw: its own. */
	assert_int_equal(frs_source_read(path, 3, (const uint32_t[3]){ 2, 2,
	    2 }, 0, &dims, NULL, NULL, &v, &err), FRS_E_FORMAT);
	assert_msg(err, "not the 2x2x2 asked for");
	assert_int_equal(frs_source_read(path, 0, (const uint32_t[3]){ 2, 2,
	    2 }, FRS_MAP_RAW, &dims, &m, NULL, &v, &err), FRS_OK);
	assert_true(dims == 3 && v.w == 3);
	frs_vol_free(&v);
	assert_int_equal(frs_source_read(path, 2, NULL, 0, &dims, &m, NULL,
	    NULL, &err), FRS_E_FORMAT);
	assert_msg(err, "a volume (.frv) where a 2-D map is needed");
	assert_true(m.v == NULL && dims == 0);
}

/* The writers' .frv, byte by byte; a value float cannot hold. */
static void write_volume(void **state)
{
	double vals[6] = { 0.0, 0.25, 1.0, 2.5, 1e6, 3.0 };
	struct frs_vol v = { 1, 2, 3, vals };
	const char *path = tu_path("w.frv");
	unsigned char *b;
	size_t n;
	FILE *fp;
	frs_error err;

	(void)state;
	fp = tu_create(path);
	assert_int_equal(frs_vol_write(&v, fp, path, &err), FRS_OK);
	tu_close(fp);
	b = tu_read(path, &n);
	assert_int_equal(n, 32 + 4 * 6);
	assert_memory_equal(b, "\211FRV\r\n\032\n", 8);
	assert_true(get_u32(b + 8) == 1 && get_u32(b + 12) == 1 &&
	    get_u32(b + 16) == 2 && get_u32(b + 20) == 3);
	for (int i = 0; i < 8; i++)
		assert_int_equal(b[24 + i], 0);
	for (int i = 0; i < 6; i++) {
		uint32_t u = get_u32(b + 32 + 4 * i);
		float f;
		memcpy(&f, &u, 4);
		assert_true((double)f == vals[i]);
	}
	free(b);
	vals[4] = 1e300;
	fp = tu_create(path);
	assert_int_equal(frs_vol_write(&v, fp, path, &err), FRS_E_MAP);
	assert_msg(err, "outside the float range");
	tu_close(fp);
	/* A stream that does not take writes. */
	vals[4] = 1.0;
	fp = fopen(path, "r");
	assert_non_null(fp);
	assert_int_equal(frs_vol_write(&v, fp, path, &err), FRS_E_IO);
	assert_msg(err, "write error");
	fclose(fp);
	v.d = 0;
	assert_int_equal(frs_vol_write(&v, stdout, "x", &err), FRS_E_ARG);
}

/* A map written and read back: PNG scaled so that the largest value is
 * 65535 (whole numbers come back as n / 65535), OpenEXR as floats;
 * negatives raw, clamped or refused; resampled by area. */
static void write_and_load_maps(void **state)
{
	double v[8] = { 0.0, 65535.0, 1.0, 257.0, 300.0, 2.0, 4.0, 3.0 };
	double e[8] = { 1.0, -2.0, 0.5, 0.25, 8.0, 3.0, 0.75, 1.5 };
	struct frs_imap m = { 4, 2, v }, me = { 4, 2, e }, r;
	struct frs_vol vol;
	struct frs_imap_stats st;
	const char *png = tu_path("m.png"), *exr = tu_path("m.exr");
	unsigned dims;
	frs_error err;
	frs_source *s;
	FILE *fp;

	(void)state;
	fp = tu_create(png);
	assert_int_equal(frs_imap_write(&m, FRS_FORMAT_PNG, fp, png, &err),
	    FRS_OK);
	tu_close(fp);
	fp = tu_create(exr);
	assert_int_equal(frs_imap_write(&me, FRS_FORMAT_EXR, fp, exr, &err),
	    FRS_OK);
	tu_close(fp);
	assert_int_equal(frs_source_open(&s, png, &err), FRS_OK);
	assert_int_equal(frs_source_kinds(s), FRS_SOURCE_MAP);
	assert_int_equal(frs_source_load(s, 2, NULL, 0, &dims, &r, NULL, NULL,
	    &err), FRS_OK);
	frs_source_close(s);
	assert_true(dims == 2 && r.w == 4 && r.h == 2);
	for (int i = 0; i < 8; i++)
		assert_true(r.v[i] == v[i] / 65535.0);
	frs_imap_free(&r);
	/* Raw: the negative kept, at the file's size whatever is asked. */
	assert_int_equal(frs_source_read(exr, 2, (const uint32_t[3]){ 2, 1,
	    0 }, FRS_MAP_RAW, &dims, &r, &st, NULL, &err), FRS_OK);
	assert_true(r.w == 4 && r.h == 2);
	for (int i = 0; i < 8; i++)
		assert_true(r.v[i] == e[i]);
	assert_true(st.negatives == 1 && st.min == -2.0 && st.neg_x == 1);
	frs_imap_free(&r);
	/* frs_imap_load takes the flag too. */
	assert_int_equal(frs_imap_load(&r, exr, 0, 0, FRS_MAP_RAW, &err),
	    FRS_OK);
	assert_true(r.w == 4 && r.v[1] == -2.0);
	frs_imap_free(&r);
	/* Checked and resampled to 2 x 1: the mean of each 2 x 2 block,
	 * the negative made zero first. */
	assert_int_equal(frs_source_read(exr, 0, (const uint32_t[3]){ 2, 1,
	    0 }, 0, &dims, &r, &st, &vol, &err), FRS_OK);
	assert_true(dims == 2 && vol.v == NULL);
	assert_true(r.w == 2 && r.h == 1);
	assert_near(r.v[0], (1.0 + 0.0 + 8.0 + 3.0) / 4, 1e-15);
	assert_near(r.v[1], (0.5 + 0.25 + 0.75 + 1.5) / 4, 1e-15);
	assert_true(st.negatives == 0 && st.count == 2);
	frs_imap_free(&r);
	assert_int_equal(frs_source_read(exr, 2, NULL, FRS_MAP_STRICT, &dims,
	    &r, NULL, NULL, &err), FRS_E_MAP);
	assert_msg(err, "pixel (1, 0) is negative");
	/* Values a format cannot hold; a format that is none. */
	e[3] = 1e300;
	fp = tu_create(exr);
	assert_int_equal(frs_imap_write(&me, FRS_FORMAT_EXR, fp, exr, &err),
	    FRS_E_MAP);
	assert_int_equal(frs_imap_write(&me, (enum frs_map_format)7, fp, exr,
	    &err), FRS_E_ARG);
	tu_close(fp);
}

/* Specs: what they are, evaluated, never a file of their name. */
static void specs(void **state)
{
	struct frs_imap m;
	struct frs_vol v;
	unsigned dims;
	frs_error err;
	frs_source *s;
	char cwd[4096];

	(void)state;
	assert_int_equal(frs_spec_kinds("blob"), FRS_SOURCE_MAP);
	assert_int_equal(frs_spec_kinds("blob3:sigma=0.2"), FRS_SOURCE_VOLUME);
	assert_int_equal(frs_spec_kinds("const"), FRS_SOURCE_MAP |
	    FRS_SOURCE_VOLUME);
	assert_int_equal(frs_spec_kinds("nothing"), 0);
	assert_non_null(strstr(frs_spec_help(2), "aniso"));
	assert_non_null(strstr(frs_spec_help(3), "shell3"));
	assert_null(frs_spec_help(4));
	assert_int_equal(frs_spec_load("const:0.5", 2, (const uint32_t[3]){ 3,
	    2, 0 }, 0, &m, NULL, NULL, &err), FRS_OK);
	assert_true(m.w == 3 && m.h == 2);
	for (int i = 0; i < 6; i++)
		assert_true(m.v[i] == 0.5);
	frs_imap_free(&m);
	assert_int_equal(frs_spec_load("const:0", 3, NULL, 0, NULL, NULL, &v,
	    &err), FRS_E_MAP);
	assert_int_equal(frs_spec_load("const:0", 3, NULL, FRS_MAP_ALLOW_ZERO,
	    NULL, NULL, &v, &err), FRS_OK);
	assert_true(v.w == 32 && v.h == 32 && v.d == 32 && v.v[0] == 0.0);
	frs_vol_free(&v);
	assert_int_equal(frs_spec_load("blob3", 2, NULL, 0, &m, NULL, NULL,
	    &err), FRS_E_ARG);
	/* A file named as a spec: the source is the file, frs_spec_load
	 * the spec. */
	assert_non_null(getcwd(cwd, sizeof cwd));
	assert_int_equal(chdir(tu_dir()), 0);
	hand_frv("blob3", 1, 1, 1, (const float[]){ 7.0f });
	assert_int_equal(frs_source_open(&s, "blob3", &err), FRS_OK);
	assert_int_equal(frs_source_load(s, 0, NULL, 0, &dims, &m, NULL, &v,
	    &err), FRS_OK);
	frs_source_close(s);
	assert_true(dims == 3 && v.w == 1 && v.v[0] == 7.0);
	frs_vol_free(&v);
	assert_int_equal(frs_spec_load("blob3", 3, (const uint32_t[3]){ 4, 4,
	    4 }, 0, NULL, NULL, &v, &err), FRS_OK);
	assert_true(v.w == 4 && v.h == 4 && v.d == 4);
	frs_vol_free(&v);
	assert_int_equal(chdir(cwd), 0);
}

/* The codes of sources that are none, and of bad arguments. */
static void codes(void **state)
{
	struct frs_imap m;
	struct frs_vol v;
	unsigned dims;
	frs_error err;
	frs_source *s;

	(void)state;
	assert_int_equal(frs_source_open(&s, tu_path("none.png"), &err),
	    FRS_OK);
	assert_int_equal(frs_source_kinds(s), 0);
	assert_int_equal(frs_source_load(s, 2, NULL, 0, &dims, &m, NULL, NULL,
	    &err), FRS_E_IO);
	assert_msg(err, "no such file, and not a procedural map");
	frs_source_close(s);
	assert_int_equal(frs_source_read(tu_path("none.frv"), 3, NULL, 0,
	    &dims, NULL, NULL, &v, &err), FRS_E_IO);
	tu_write(tu_path("t.txt"), "hello\n", 6);
	assert_int_equal(frs_source_read(tu_path("t.txt"), 0, NULL, 0, &dims,
	    &m, NULL, &v, &err), FRS_E_FORMAT);
	assert_msg(err, "not a PNG or OpenEXR file");
	assert_int_equal(frs_source_read("blob:nope=1", 0, NULL, 0, &dims, &m,
	    NULL, &v, &err), FRS_E_ARG);
	assert_int_equal(frs_source_read("blob", 1, NULL, 0, &dims, &m, NULL,
	    &v, &err), FRS_E_ARG);
	assert_int_equal(frs_source_read("blob", 2, (const uint32_t[3]){ 4, 0,
	    0 }, 0, &dims, &m, NULL, &v, &err), FRS_E_ARG);
	assert_int_equal(frs_source_read("blob", 2, NULL, 0, &dims, NULL, NULL,
	    &v, &err), FRS_E_ARG);
	assert_int_equal(frs_source_open(NULL, "blob", &err), FRS_E_ARG);
	frs_source_close(NULL);
	frs_vol_free(NULL);
}

/* frs_source_read and frs_imap_load give a failure the same code: a
 * file that does not open (a directory) or opens but does not read
 * (Linux's /proc/self/mem at offset 0) is IO, a file named
 * like a spec is a file (FORMAT when it is not an image), and a spec is
 * a name that some spec has, a volume's too (ARG where a map is asked
 * for). */
static void codes_alike(void **state)
{
	static const struct {
		const char *src;
		int code;
	} c[] = { { ".", FRS_E_IO }, { "/proc/self/mem", FRS_E_IO },
		  { "blob", FRS_E_FORMAT },
		  { "shell3", FRS_E_ARG }, { "blob:nope=1", FRS_E_ARG } };
	char cwd[4096];
	struct frs_imap m;
	unsigned dims;
	frs_error err;

	(void)state;
	assert_non_null(getcwd(cwd, sizeof cwd));
	assert_int_equal(chdir(tu_dir()), 0);
	tu_write("blob", "hello\n", 6);
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		if (access(c[i].src, F_OK) != 0 && c[i].code == FRS_E_IO)
			continue;	/* no /proc */
		assert_int_equal(frs_source_read(c[i].src, 2, NULL, 0, &dims, &m,
		    NULL, NULL, &err), c[i].code);
		assert_int_equal(frs_imap_load(&m, c[i].src, 0, 0, 0, &err),
		    c[i].code);
		assert_null(m.v);
	}
	assert_int_equal(chdir(cwd), 0);
}

TU_MAIN(NULL, tu_teardown,
    cmocka_unit_test(stats_by_hand),
    cmocka_unit_test(check_values),
    cmocka_unit_test(pixel_of),
    cmocka_unit_test(volume_file),
    cmocka_unit_test(write_volume),
    cmocka_unit_test(write_and_load_maps),
    cmocka_unit_test(specs),
    cmocka_unit_test(codes),
    cmocka_unit_test(codes_alike))
