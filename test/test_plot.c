/* Plots for dda --summary's page: text has the stated width and its
 * glyphs' cells, boxes map their range's ends to their edge pixels,
 * curves are connected and clamped to the box, NaN breaks them. */
#include "testutil.h"
#include "dda/plot.h"

static const uint8_t ink[3] = { 10, 20, 30 };

static int is_ink(const struct frs_raster *r, int x, int y)
{
	const uint8_t *p = r->px + ((size_t)y * r->w + (size_t)x) * 3;
	return p[0] == ink[0] && p[1] == ink[1] && p[2] == ink[2];
}

static size_t count_ink(const struct frs_raster *r)
{
	size_t n = 0;
	for (uint32_t y = 0; y < r->h; y++)
		for (uint32_t x = 0; x < r->w; x++)
			n += (size_t)is_ink(r, (int)x, (int)y);
	return n;
}

static void text_width(void **state)
{
	(void)state;
	assert_int_equal(plot_text_width("", 2), 0);
	assert_int_equal(plot_text_width("A", 1), 3);
	assert_int_equal(plot_text_width("128", 2), 3 * 8 - 2);
}

/* "1" at scale 1: .#. ##. .#. .#. ###, 8 cells; at scale 3 nine times
 * as many pixels; small letters are capitals; unknown characters '?'. */
static void text_glyphs(void **state)
{
	struct frs_raster r, q;
	(void)state;
	assert_int_equal(raster_alloc(&r, 40, 20, 3), 0);
	plot_text(&r, 1, 1, 1, "1", ink);
	assert_int_equal(count_ink(&r), 8);
	assert_true(is_ink(&r, 2, 1) && is_ink(&r, 1, 2) && is_ink(&r, 2, 2));
	assert_false(is_ink(&r, 1, 1) || is_ink(&r, 3, 2));
	assert_true(is_ink(&r, 1, 5) && is_ink(&r, 2, 5) && is_ink(&r, 3, 5));
	raster_free(&r);
	assert_int_equal(raster_alloc(&r, 40, 20, 3), 0);
	plot_text(&r, 0, 0, 3, "1", ink);
	assert_int_equal(count_ink(&r), 72);
	raster_free(&r);
	assert_int_equal(raster_alloc(&r, 40, 20, 3), 0);
	assert_int_equal(raster_alloc(&q, 40, 20, 3), 0);
	plot_text(&r, 0, 0, 1, "dx ~", ink);
	plot_text(&q, 0, 0, 1, "DX ?", ink);
	assert_memory_equal(r.px, q.px, 40 * 20 * 3);
	raster_free(&r);
	raster_free(&q);
	/* Clipped at the raster's edges, no write outside. */
	assert_int_equal(raster_alloc(&r, 4, 4, 3), 0);
	plot_text(&r, -2, -3, 2, "88", ink);
	plot_text(&r, 3, 3, 2, "88", ink);
	assert_true(count_ink(&r) > 0);
	raster_free(&r);
}

/* The 3 x 5 cells of c at scale 1 as a string of '#' and '.', row by
 * row: what a reader sees. */
static void cells_of(char c, char out[16])
{
	struct frs_raster r;
	char s[2] = { c, '\0' };

	assert_int_equal(raster_alloc(&r, 3, 5, 3), 0);
	plot_text(&r, 0, 0, 1, s, ink);
	for (int i = 0; i < 15; i++)
		out[i] = is_ink(&r, i % 3, i / 3) ? '#' : '.';
	out[15] = '\0';
	raster_free(&r);
}

/* Letters as a 3 x 5 font draws them, written out by hand: A with its
 * apex and crossbar, H with a bar in the middle, M with its two middle
 * rows full and N with three (as the Tom Thumb font draws them). */
static void text_letters(void **state)
{
	static const char *const want[][2] = {
		{ "A", ".#." "#.#" "###" "#.#" "#.#" },
		{ "H", "#.#" "#.#" "###" "#.#" "#.#" },
		{ "M", "#.#" "###" "###" "#.#" "#.#" },
		{ "N", "#.#" "###" "###" "###" "#.#" },
		{ "E", "###" "#.." "##." "#.." "###" },
		{ "1", ".#." "##." ".#." ".#." "###" },
	};
	char got[16];
	(void)state;
	for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
		cells_of(want[i][0][0], got);
		if (strcmp(got, want[i][1]) != 0)
			fail_msg("'%s' is %s, not %s", want[i][0], got, want[i][1]);
	}
}

/* Every glyph of the font: the letters that are mirror images of
 * themselves are drawn so, every glyph has ink in its top and bottom
 * rows or is punctuation, and no two characters look the same. */
static void text_font(void **state)
{
	static const char all[] = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ"
	    ".,-+_/:=()%?";
	static const char mirror[] = "0AHIMOTUVWXY8";
	char g[sizeof all][16];
	(void)state;
	for (size_t i = 0; i < sizeof all - 1; i++)
		cells_of(all[i], g[i]);
	for (size_t i = 0; i < sizeof all - 1; i++)
		for (size_t j = 0; j < i; j++)
			if (strcmp(g[i], g[j]) == 0)
				fail_msg("'%c' and '%c' are the same glyph %s",
				    all[i], all[j], g[i]);
	for (const char *c = mirror; *c; c++) {
		char m[16];
		cells_of(*c, m);
		for (int y = 0; y < 5; y++)
			if (m[3 * y] != m[3 * y + 2])
				fail_msg("'%c' is not symmetric: %s", *c, m);
	}
	for (size_t i = 0; i < 36; i++)
		if (strchr(g[i], '#') > g[i] + 2 || strrchr(g[i], '#') < g[i] + 12)
			fail_msg("'%c' does not span the 5 rows: %s", all[i], g[i]);
}

/* The raster of plot_text's lines, one under another (6 s apart), for
 * comparing with plot_text_fit. */
static void lines_of(struct frs_raster *q, int x, int y, int scale,
    const char *const *line, size_t n)
{
	for (size_t i = 0; i < n; i++)
		plot_text(q, x, y + (int)i * (PLOT_GLYPH_H + 1) * scale, scale,
		    line[i], ink);
}

/* plot_text_fit in a box 23 x 13 at (2, 1): 3 characters a line at
 * scale 2 (one line), 6 at scale 1 (two lines). */
static void text_fit(void **state)
{
	static const struct {
		const char *s;
		int scale, lines;
		const char *line[2];
	} c[] = {
		{ "ABC", 2, 1, { "ABC" } },		/* fits as it is */
		{ "ABCD", 1, 1, { "ABCD" } },		/* a smaller scale */
		{ "ABCDEFGHIJKL", 1, 2, { "ABCDEF", "GHIJKL" } },	/* wrapped */
		{ "ABCDEFGHIJKLMNOPQRST", 1, 2, { "ABCDEF", "GHI..." } },
	};
	(void)state;
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		struct frs_raster r, q;
		assert_int_equal(raster_alloc(&r, 30, 20, 3), 0);
		assert_int_equal(raster_alloc(&q, 30, 20, 3), 0);
		assert_int_equal(plot_text_fit(&r, 2, 1, 23, 13, 2, c[i].s, ink),
		    c[i].lines);
		lines_of(&q, 2, 1, c[i].scale, c[i].line, (size_t)c[i].lines);
		if (memcmp(r.px, q.px, 30 * 20 * 3) != 0)
			fail_msg("'%s' is not drawn as %d line(s) at scale %d",
			    c[i].s, c[i].lines, c[i].scale);
		for (int y = 0; y < 20; y++)
			for (int x = 0; x < 30; x++)
				if (x < 2 || x >= 25 || y < 1 || y >= 14)
					assert_false(is_ink(&r, x, y));
		raster_free(&r);
		raster_free(&q);
	}
}

/* plot_range: whole steps around the data and the reference, NaN left
 * out, at least one step. */
static void range(void **state)
{
	double lo, hi;
	double a[] = { -28.5, NAN, -31.2, -29 };
	double b[] = { -6.5, 2.5, -3 };
	double z[] = { NAN };
	(void)state;
	plot_range(a, 4, -30.1, 10, &lo, &hi);
	assert_true(lo == -40 && hi == -20);
	plot_range(b, 3, -6.0, 5, &lo, &hi);
	assert_true(lo == -10 && hi == 5);
	plot_range(b, 3, 12, 10, &lo, &hi);
	assert_true(lo == -10 && hi == 20);
	plot_range(z, 1, 0, 10, &lo, &hi);	/* the reference alone */
	assert_true(lo == 0 && hi == 10);
	plot_range(z, 0, -20, 10, &lo, &hi);
	assert_true(lo == -20 && hi == -10);
}

/* A curve from (x0, y0) to (x1, y1) of the box lights the bottom left
 * and top right pixels and is 8-connected; values beyond are clamped. */
static void curve_box(void **state)
{
	struct frs_raster r;
	struct plot_box b = { 5, 4, 21, 11, 0.0, 2.0, -1.0, 1.0 };
	double x[] = { 0.0, 2.0 }, y[] = { -1.0, 1.0 };
	double xc[] = { -5.0, 7.0 }, yc[] = { -9.0, 9.0 };
	(void)state;
	assert_int_equal(raster_alloc(&r, 40, 30, 3), 0);
	plot_curve(&r, &b, x, y, 2, ink);
	assert_true(is_ink(&r, 5, 14) && is_ink(&r, 25, 4));
	for (int px = 5; px <= 25; px++) {
		int col = 0;
		for (int py = 4; py <= 14; py++)
			col += is_ink(&r, px, py);
		assert_true(col >= 1);
	}
	for (int py = 4; py <= 14; py++) {
		int row = 0;
		for (int px = 5; px <= 25; px++)
			row += is_ink(&r, px, py);
		assert_true(row >= 1);
	}
	/* Nothing outside the box. */
	for (uint32_t py = 0; py < r.h; py++)
		for (uint32_t px = 0; px < r.w; px++)
			if (px < 5 || px > 25 || py < 4 || py > 14)
				assert_false(is_ink(&r, (int)px, (int)py));
	/* Clamped: the same line. */
	{
		struct frs_raster q;
		assert_int_equal(raster_alloc(&q, 40, 30, 3), 0);
		plot_curve(&q, &b, xc, yc, 2, ink);
		assert_memory_equal(r.px, q.px, 40 * 30 * 3);
		raster_free(&q);
	}
	raster_free(&r);
}

/* NaN breaks a curve: two points apart with a NaN between are two dots. */
static void curve_nan(void **state)
{
	struct frs_raster r;
	struct plot_box b = { 0, 0, 11, 11, 0.0, 10.0, 0.0, 10.0 };
	double x[] = { 0.0, NAN, 10.0 }, y[] = { 0.0, 5.0, 10.0 };
	(void)state;
	assert_int_equal(raster_alloc(&r, 11, 11, 3), 0);
	plot_curve(&r, &b, x, y, 3, ink);
	assert_int_equal(count_ink(&r), 2);
	assert_true(is_ink(&r, 0, 10) && is_ink(&r, 10, 0));
	raster_free(&r);
}

/* plot_axes: a black frame on the box's edge pixels and grey grid lines
 * at the ticks inside the range only. */
static void axes(void **state)
{
	struct frs_raster r;
	struct plot_box b = { 20, 2, 41, 21, 0.0, 4.0, 0.0, 2.0 };
	double xt[] = { 0.0, 2.0, 9.0 }, yt[] = { 1.0, -3.0 };
	const uint8_t *p;
	(void)state;
	assert_int_equal(raster_alloc(&r, 80, 40, 3), 0);
	plot_axes(&r, &b, xt, 3, yt, 2, 1);
	p = r.px + ((size_t)2 * r.w + 20) * 3;
	assert_int_equal(p[0], 0);
	p = r.px + ((size_t)22 * r.w + 60) * 3;
	assert_int_equal(p[0], 0);
	/* x = 2 at column 40, y = 1 at row 12: grid. */
	p = r.px + ((size_t)7 * r.w + 40) * 3;
	assert_int_equal(p[0], 225);
	p = r.px + ((size_t)12 * r.w + 30) * 3;
	assert_int_equal(p[0], 225);
	raster_free(&r);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(text_width),
	cmocka_unit_test(text_glyphs),
	cmocka_unit_test(text_letters),
	cmocka_unit_test(text_font),
	cmocka_unit_test(text_fit),
	cmocka_unit_test(range),
	cmocka_unit_test(curve_box),
	cmocka_unit_test(curve_nan),
	cmocka_unit_test(axes))
