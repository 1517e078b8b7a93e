/* Rasters for stipple pictures: discs cover the area they should (pi r^2,
 * by exact coverage and against brute-force supersampling), are
 * symmetric, darkest where they are drawn, clip at the edges; the
 * importance background follows its formula; PNG and PNM files read back
 * to the same pixels. */
#include "testutil.h"
#include "maps/imap.h"
#include "maps/pngio.h"
#include "cli/raster.h"

static const uint8_t black[3] = { 0, 0, 0 };

/* sum(1 - v / 255) over the raster (grey). */
static double darkness(const struct frs_raster *r)
{
	double s = 0.0;
	for (size_t i = 0; i < (size_t)r->w * r->h * r->channels; i++)
		s += 1.0 - r->px[i] / 255.0;
	return s;
}

/* Brute-force coverage: an n x n grid of sub-pixel centres. */
static double brute_coverage(double x0, double y0, double x1, double y1,
    double rad, int n)
{
	long in = 0;
	for (int b = 0; b < n; b++)
		for (int a = 0; a < n; a++) {
			double x = x0 + (x1 - x0) * (a + 0.5) / n;
			double y = y0 + (y1 - y0) * (b + 0.5) / n;
			in += x * x + y * y < rad * rad;
		}
	return (double)in / ((double)n * n);
}

static void coverage_exact(void **state)
{
	static const double radii[] = { 0.3, 0.7, 1.0, 1.5, 2.25, 5.0 };
	(void)state;

	/* Whole pixel inside, outside, and the whole disc inside a pixel. */
	assert_near(raster_coverage(-0.5, -0.5, 0.5, 0.5, 2.0), 1.0, 1e-12);
	assert_near(raster_coverage(3.0, 3.0, 4.0, 4.0, 2.0), 0.0, 1e-12);
	assert_near(raster_coverage(-0.5, -0.5, 0.5, 0.5, 0.25),
	    PI * 0.0625, 1e-12);
	/* A quarter disc: the pixel's corner at the centre. */
	assert_near(raster_coverage(0.0, 0.0, 1.0, 1.0, 1.0), PI / 4, 1e-12);
	assert_near(raster_coverage(-1.0, -1.0, 0.0, 0.0, 1.0), PI / 4,
	    1e-12);
	/* Degenerate input. */
	assert_near(raster_coverage(0.0, 0.0, 1.0, 1.0, 0.0), 0.0, 0.0);
	assert_near(raster_coverage(0.0, 0.0, 0.0, 1.0, 1.0), 0.0, 0.0);

	for (size_t k = 0; k < sizeof radii / sizeof radii[0]; k++) {
		double rad = radii[k], cx = 0.37, cy = 0.81, sum = 0.0;
		int n = (int)ceil(rad) + 2;
		/* Pixel coverages of a disc add up to its area. */
		for (int j = -n; j <= n; j++)
			for (int i = -n; i <= n; i++)
				sum += raster_coverage(i - cx, j - cy, i + 1 - cx,
				    j + 1 - cy, rad);
		assert_near(sum, PI * rad * rad, 1e-9);
		/* And each agrees with supersampling. */
		for (int j = -n; j <= n; j++)
			for (int i = -n; i <= n; i++)
				assert_near(raster_coverage(i - cx, j - cy,
				    i + 1 - cx, j + 1 - cy, rad),
				    brute_coverage(i - cx, j - cy, i + 1 - cx,
				    j + 1 - cy, rad, 400), 2e-3);
	}
}

static void disc_area(void **state)
{
	static const double radii[] = { 0.7, 1.0, 1.5, 2.5, 4.0, 9.3 };
	struct frs_raster r;
	(void)state;

	for (size_t k = 0; k < sizeof radii / sizeof radii[0]; k++) {
		double rad = radii[k], want = PI * rad * rad;
		assert_int_equal(raster_alloc(&r, 64, 48, 1), 0);
		assert_near(darkness(&r), 0.0, 0.0);
		raster_disc(&r, 30.27, 21.61, rad, black);
		/* Exact coverage; only the 8-bit rounding of each pixel is
		 * left, at most 1/510 per pixel touched. */
		assert_near(darkness(&r), want, 0.01 * want);
		raster_free(&r);
	}
}

/* A disc centred in a pixel is symmetric about that pixel's centre:
 * mirror images in x, y and the diagonal. */
static void disc_symmetric(void **state)
{
	static const double radii[] = { 0.7, 1.3, 2.5, 6.1 };
	struct frs_raster r;
	(void)state;

	for (size_t k = 0; k < sizeof radii / sizeof radii[0]; k++) {
		assert_int_equal(raster_alloc(&r, 33, 33, 1), 0);
		raster_disc(&r, 16.5, 16.5, radii[k], black);
		for (int j = 0; j < 33; j++)
			for (int i = 0; i < 33; i++) {
				uint8_t v = r.px[j * 33 + i];
				assert_int_equal(v, r.px[j * 33 + (32 - i)]);
				assert_int_equal(v, r.px[(32 - j) * 33 + i]);
				assert_int_equal(v, r.px[i * 33 + j]);
			}
		assert_int_equal(r.px[16 * 33 + 16], 0);
		raster_free(&r);
	}
}

/* A dot at (x, y) of the unit square is darkest in the pixel containing
 * (x W, y H); y grows downward (row 0 at the top). */
static void disc_darkest_where_drawn(void **state)
{
	static const double pts[][2] = {
		{ 0.25, 0.75 }, { 0.01, 0.02 }, { 0.99, 0.5 }, { 0.613, 0.127 },
		{ 0.5, 0.999 }, { 0.3333, 0.6667 },
	};
	const uint32_t w = 40, h = 24;
	struct frs_raster r;
	(void)state;

	for (int rr = 0; rr < 2; rr++) {
		double rad = rr ? 1.0 : 0.7;
		for (size_t k = 0; k < sizeof pts / sizeof pts[0]; k++) {
			double cx = pts[k][0] * w, cy = pts[k][1] * h;
			uint32_t pi = (uint32_t)cx, pj = (uint32_t)cy;
			uint8_t at;
			assert_int_equal(raster_alloc(&r, w, h, 1), 0);
			raster_disc(&r, cx, cy, rad, black);
			at = r.px[pj * w + pi];
			assert_true(at < 255);
			for (size_t i = 0; i < (size_t)w * h; i++)
				assert_true(r.px[i] >= at);
			raster_free(&r);
		}
	}
	/* The continuous centroid of the darkness is the centre. */
	assert_int_equal(raster_alloc(&r, w, h, 1), 0);
	raster_disc(&r, 0.25 * w, 0.75 * h, 3.0, black);
	{
		double sx = 0.0, sy = 0.0, s = 0.0;
		for (uint32_t j = 0; j < h; j++)
			for (uint32_t i = 0; i < w; i++) {
				double d = 1.0 - r.px[j * w + i] / 255.0;
				sx += (i + 0.5) * d;
				sy += (j + 0.5) * d;
				s += d;
			}
		assert_near(sx / s, 10.0, 0.01);
		assert_near(sy / s, 18.0, 0.01);
	}
	raster_free(&r);
}

/* Discs over the edges are clipped, never wrapped, and never write out
 * of bounds (the sanitizers watch). */
static void disc_clipped(void **state)
{
	struct frs_raster r;
	double q;
	(void)state;

	assert_int_equal(raster_alloc(&r, 20, 10, 3), 0);
	/* Entirely outside, or nonsense: nothing changes. */
	raster_disc(&r, -5.0, 5.0, 2.0, black);
	raster_disc(&r, 25.0, 5.0, 2.0, black);
	raster_disc(&r, 10.0, -3.0, 2.0, black);
	raster_disc(&r, 10.0, 13.0, 2.9, black);
	raster_disc(&r, 10.0, 5.0, 0.0, black);
	raster_disc(&r, 10.0, 5.0, -1.0, black);
	raster_disc(&r, NAN, 5.0, 1.0, black);
	raster_disc(&r, 10.0, INFINITY, 1.0, black);
	raster_disc(&r, 10.0, 5.0, NAN, black);
	raster_disc(&r, -1e300, 1e300, 1.0, black);
	assert_near(darkness(&r), 0.0, 0.0);
	/* A disc at the corner (0, 0): a quarter of it is drawn, nothing
	 * wraps to the other corners. */
	raster_disc(&r, 0.0, 0.0, 3.0, black);
	q = PI * 9.0 / 4.0;
	assert_near(darkness(&r) / 3.0, q, 0.01 * q);
	assert_int_equal(r.px[(9 * 20 + 19) * 3], 255);
	assert_int_equal(r.px[(0 * 20 + 19) * 3], 255);
	assert_int_equal(r.px[(9 * 20 + 0) * 3], 255);
	raster_free(&r);
	/* Larger than the raster at every corner. */
	assert_int_equal(raster_alloc(&r, 3, 2, 1), 0);
	raster_disc(&r, 2.999, 1.999, 50.0, black);
	raster_disc(&r, 0.0, 0.0, 1e6, black);
	for (int i = 0; i < 6; i++)
		assert_int_equal(r.px[i], 0);
	raster_free(&r);
	/* A 1x1 raster. */
	assert_int_equal(raster_alloc(&r, 1, 1, 1), 0);
	raster_disc(&r, 0.5, 0.5, 0.25, black);
	assert_int_equal(r.px[0], (int)lround(255.0 * (1.0 - PI / 16)));
	raster_free(&r);
}

/* Colour blends per channel: bg * (1 - c) + color * c. */
static void disc_colour(void **state)
{
	struct frs_raster r;
	uint8_t rgb[3], grey = 200;
	(void)state;

	raster_ramp(0, 10, rgb);
	assert_int_equal(rgb[0], 0);
	assert_int_equal(rgb[1], 0);
	assert_int_equal(rgb[2], 255);
	raster_ramp(9, 10, rgb);
	assert_int_equal(rgb[0], 255);
	assert_int_equal(rgb[2], 0);
	raster_ramp(0, 1, rgb);
	assert_int_equal(rgb[2], 255);
	raster_ramp(1, 3, rgb);
	assert_int_equal(rgb[0], 128);
	assert_int_equal(rgb[2], 127);

	assert_int_equal(raster_alloc(&r, 8, 8, 3), 0);
	raster_fill(&r, (const uint8_t[3]){ grey, grey, grey });
	raster_ramp(9, 10, rgb);
	raster_disc(&r, 4.5, 4.5, 2.0, rgb);
	/* Inside: the colour itself. */
	assert_int_equal(r.px[(4 * 8 + 4) * 3 + 0], 255);
	assert_int_equal(r.px[(4 * 8 + 4) * 3 + 1], 0);
	assert_int_equal(r.px[(4 * 8 + 4) * 3 + 2], 0);
	/* An edge pixel: the blend of its coverage. */
	{
		double c = raster_coverage(6 - 4.5, 4 - 4.5, 7 - 4.5, 5 - 4.5, 2.0);
		const uint8_t *p = &r.px[(4 * 8 + 6) * 3];
		assert_true(c > 0.05 && c < 0.95);
		assert_int_equal(p[0], (int)lround(grey * (1 - c) + 255 * c));
		assert_int_equal(p[1], (int)lround(grey * (1 - c)));
		assert_int_equal(p[2], (int)lround(grey * (1 - c)));
	}
	/* Far away: the background. */
	assert_int_equal(r.px[0], grey);
	raster_free(&r);
}

static void background(void **state)
{
	struct frs_imap m;
	struct frs_raster r;
	(void)state;

	assert_int_equal(imap_alloc(&m, 4, 1), 0);
	m.v[0] = 0.0;
	m.v[1] = 2.0;
	m.v[2] = 1.0;
	m.v[3] = 0.02;
	assert_int_equal(raster_alloc(&r, 4, 1, 1), 0);
	assert_int_equal(raster_fill_imap(&r, &m, 0), 0);
	assert_int_equal(r.px[0], 255);
	assert_int_equal(r.px[1], 255 - RASTER_BG_RANGE);
	assert_int_equal(r.px[2], 255 - RASTER_BG_RANGE / 2);
	assert_int_equal(r.px[3], 255 - 1);	/* 0.8 rounds to 1 */
	/* Log: 0.02 .. 2 spans two decades; 0.2 would be halfway. */
	assert_int_equal(raster_fill_imap(&r, &m, 1), 0);
	assert_int_equal(r.px[0], 255);
	assert_int_equal(r.px[1], 255 - RASTER_BG_RANGE);
	assert_int_equal(r.px[3], 254);
	assert_int_equal(r.px[2],
	    254 - lround((RASTER_BG_RANGE - 1) * log10(50.0) / 2.0));
	raster_free(&r);
	/* RGB gets the grey in every channel. */
	assert_int_equal(raster_alloc(&r, 4, 1, 3), 0);
	assert_int_equal(raster_fill_imap(&r, &m, 0), 0);
	assert_int_equal(r.px[3], 255 - RASTER_BG_RANGE);
	assert_int_equal(r.px[4], 255 - RASTER_BG_RANGE);
	assert_int_equal(r.px[5], 255 - RASTER_BG_RANGE);
	raster_free(&r);
	/* All zero: white; one positive value in log scale: the darkest. */
	for (int i = 0; i < 4; i++)
		m.v[i] = 0.0;
	assert_int_equal(raster_alloc(&r, 4, 1, 1), 0);
	assert_int_equal(raster_fill_imap(&r, &m, 0), 0);
	assert_near(darkness(&r), 0.0, 0.0);
	assert_int_equal(raster_fill_imap(&r, &m, 1), 0);
	assert_near(darkness(&r), 0.0, 0.0);
	m.v[2] = 3.0;
	assert_int_equal(raster_fill_imap(&r, &m, 1), 0);
	assert_int_equal(r.px[2], 255 - RASTER_BG_RANGE);
	assert_int_equal(r.px[1], 255);
	raster_free(&r);
	/* A map of another size is refused. */
	assert_int_equal(raster_alloc(&r, 2, 2, 1), 0);
	assert_int_equal(raster_fill_imap(&r, &m, 0), -1);
	assert_err_has("internal error");
	raster_free(&r);
	imap_free(&m);
}

static void alloc_limits(void **state)
{
	struct frs_raster r;
	(void)state;

	assert_int_equal(raster_alloc(&r, 0, 5, 1), -1);
	assert_null(r.px);
	assert_int_equal(raster_alloc(&r, 5, 0, 1), -1);
	assert_int_equal(raster_alloc(&r, FRS_MAP_MAX_SIDE + 1, 1, 1), -1);
	assert_int_equal(raster_alloc(&r, FRS_MAP_MAX_SIDE, FRS_MAP_MAX_SIDE, 1), -1);
	assert_err_has("impossible");
	assert_int_equal(raster_alloc(&r, 5, 5, 2), -1);
	assert_err_has("channels");
	assert_near(raster_default_radius(512), 1.5, 1e-15);
	assert_near(raster_default_radius(1024), 3.0, 1e-15);
	assert_near(raster_default_radius(100), 0.7, 1e-15);
	assert_near(raster_default_radius(1), 0.7, 1e-15);
}

/* raster_spacing, by its definition (raster.h) worked out by hand on a
 * grid of points at the odd pixels of a 1024x512 picture (R = 3): the
 * squares around an odd pixel reach 16 points between 7 pixels across
 * (3 x 3 points) and 9 (5 x 5), at 49 + 7/16 * 32 = 63 square pixels,
 * so s = sqrt(63/16) and r = s/3 + 1/2; around the corner pixel (0, 0),
 * clipped, between 7 x 7 (9 points) and 8 x 8 (16), at 64, s = 2; far
 * from every point r = R; a pile is measured in the pixel it covers and
 * leaves the grid 8 pixels away as it was. */
static void spacing_radius(void **state)
{
	const uint32_t w = 1024, h = 512;
	struct raster_spacing sp;
	double *x, grid = sqrt(63.0 / 16.0) / 3.0 + 0.5;
	size_t n = 0;
	(void)state;

	/* A 2-pixel grid over the left half, 3 points on the right half,
	 * and room for a pile of 1000. */
	x = malloc(sizeof *x * 2 * (256 * 256 + 3 + 1000));
	assert_non_null(x);
	for (uint32_t j = 0; j < 256; j++)
		for (uint32_t i = 0; i < 256; i++, n++) {
			x[2 * n] = (2.0 * i + 1.5) / w;
			x[2 * n + 1] = (2.0 * j + 1.5) / h;
		}
	for (int k = 0; k < 3; k++, n++) {
		x[2 * n] = 0.7 + 0.1 * k;
		x[2 * n + 1] = 0.5;
	}
	assert_int_equal(raster_spacing_init(&sp, x, n, 2, 0, 1, w, h), 0);
	assert_near(raster_spacing_radius(&sp, 257.5, 257.5), grid, 1e-12);
	assert_near(raster_spacing_radius(&sp, 0.5, 0.5), 2.0 / 3.0 + 0.5,
	    1e-12);
	assert_near(raster_spacing_radius(&sp, 900.0, 256.0), 3.0, 1e-15);
	raster_spacing_free(&sp);
	/* The pile on pixel (101, 101): 1001 points in it, so there the
	 * square is that pixel alone. */
	for (int k = 0; k < 1000; k++, n++) {
		x[2 * n] = 101.5 / w;
		x[2 * n + 1] = 101.5 / h;
	}
	assert_int_equal(raster_spacing_init(&sp, x, n, 2, 0, 1, w, h), 0);
	assert_near(raster_spacing_radius(&sp, 101.5, 101.5),
	    1.0 / (3.0 * sqrt(1001.0)) + 0.5, 1e-12);
	assert_near(raster_spacing_radius(&sp, 109.5, 101.5), grid, 1e-12);
	assert_near(raster_spacing_radius(&sp, 101.5, 93.5), grid, 1e-12);
	raster_spacing_free(&sp);
	free(x);
}

/* Opacity: a pixel under the whole disc goes alpha of the way to the
 * ink; alpha 1 is raster_disc. */
static void disc_alpha(void **state)
{
	struct frs_raster a, b;
	const uint8_t grey = 100;
	(void)state;

	assert_int_equal(raster_alloc(&a, 32, 32, 1), 0);
	assert_int_equal(raster_alloc(&b, 32, 32, 1), 0);
	raster_disc_alpha(&a, 16.3, 15.8, 6.0, &grey, 0.25);
	assert_int_equal(a.px[16 * 32 + 16], 216);	/* 255 - 155 / 4 */
	raster_disc(&b, 16.3, 15.8, 6.0, &grey);
	raster_free(&a);
	assert_int_equal(raster_alloc(&a, 32, 32, 1), 0);
	raster_disc_alpha(&a, 16.3, 15.8, 6.0, &grey, 1.0);
	assert_memory_equal(a.px, b.px, 32 * 32);
	raster_free(&a);
	raster_free(&b);
}

/* A test picture: every grey level, and dots. */
static void picture(struct frs_raster *r, uint32_t w, uint32_t h,
    unsigned ch)
{
	assert_int_equal(raster_alloc(r, w, h, ch), 0);
	for (size_t i = 0; i < (size_t)w * h * ch; i++)
		r->px[i] = (uint8_t)((i * 37u + i / 7u) % 256u);
	raster_disc(r, w * 0.3, h * 0.6, 2.5, black);
}

static void png_round_trip(void **state)
{
	const char *path = tu_path("r.png");
	struct frs_raster r;
	struct frs_imap m;
	unsigned char *buf;
	size_t n;
	(void)state;

	for (unsigned ch = 1; ch <= 3; ch += 2) {
		FILE *fp = fopen(path, "wb");
		assert_non_null(fp);
		picture(&r, 37, 23, ch);
		assert_int_equal(raster_write_png(fp, path, &r), 0);
		assert_int_equal(fclose(fp), 0);
		buf = tu_read(path, &n);
		assert_int_equal(imap_read_png_mem(buf, n, path, 0, &m), 0);
		assert_int_equal(m.w, 37);
		assert_int_equal(m.h, 23);
		for (size_t i = 0; i < (size_t)37 * 23; i++) {
			const uint8_t *p = r.px + i * ch;
			double want = ch == 1 ? p[0] / 255.0 :
			    imap_luma(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0);
			assert_near(m.v[i], want, 1e-12);
		}
		/* The colour type is the raster's: byte 25 of the IHDR. */
		assert_int_equal(buf[25], ch == 1 ? 0 : 2);
		assert_int_equal(buf[24], 8);
		imap_free(&m);
		free(buf);
		raster_free(&r);
	}
	unlink(path);
}

static void pnm_round_trip(void **state)
{
	const char *path = tu_path("r.pgm");
	static const char head[] = "P5\n37 23\n255\n";
	struct frs_raster r;
	unsigned char *buf;
	size_t n, hl = sizeof head - 1;
	FILE *fp;
	(void)state;

	picture(&r, 37, 23, 1);
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(raster_write_pnm(fp, path, &r), 0);
	assert_int_equal(fclose(fp), 0);
	buf = tu_read(path, &n);
	assert_int_equal(n, hl + 37 * 23);
	assert_memory_equal(buf, head, hl);
	assert_memory_equal(buf + hl, r.px, 37 * 23);
	free(buf);
	raster_free(&r);
	unlink(path);
}

static void write_errors(void **state)
{
	struct frs_raster r;
	FILE *fp;
	(void)state;

	picture(&r, 300, 300, 3);
	fp = fopen("/dev/full", "wb");
	if (fp == NULL) {
		raster_free(&r);
		skip();
	}
	/* Unbuffered: the error shows in the writer, not only at fclose. */
	setvbuf(fp, NULL, _IONBF, 0);
	assert_int_equal(raster_write_png(fp, "/dev/full", &r), -1);
	assert_err_has("/dev/full", "write error");
	clearerr(fp);
	assert_int_equal(raster_write_pnm(fp, "/dev/full", &r), -1);
	assert_err_has("/dev/full", "write error");
	fclose(fp);
	raster_free(&r);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(coverage_exact),
	cmocka_unit_test(disc_area),
	cmocka_unit_test(disc_symmetric),
	cmocka_unit_test(disc_darkest_where_drawn),
	cmocka_unit_test(disc_clipped),
	cmocka_unit_test(disc_colour),
	cmocka_unit_test(background),
	cmocka_unit_test(alloc_limits),
	cmocka_unit_test(spacing_radius),
	cmocka_unit_test(disc_alpha),
	cmocka_unit_test(png_round_trip),
	cmocka_unit_test(pnm_round_trip),
	cmocka_unit_test(write_errors))
