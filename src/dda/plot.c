#define _POSIX_C_SOURCE 200809L
#include "dda/plot.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The glyphs, 5 rows of 3 cells each, top row first ('#' set). */
static const char font_chars[] =
    "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.,-+_/:=()%?";
static const char *const font_cells[] = {
	"####.##.##.####", ".#.##..#..#.###", "###..#####..###",
	"###..#.##..####", "#.##.####..#..#", "####..###..####",
	"####..####.####", "###..#..#.#..#.", "####.#####.####",
	"####.####..####",
	".#.#.#####.##.#", "##.#.###.#.###.", ".###..#..#...##",
	"##.#.##.##.###.", "####..##.#..###", "####..##.#..#..",
	".###..#.##.#.##", "#.##.#####.##.#", "###.#..#..#.###",
	"..#..#..##.#.#.", "#.##.###.#.##.#", "#..#..#..#..###",
	"#.########.##.#", "#.###########.#", ".#.#.##.##.#.#.",
	"##.#.###.#..#..", ".#.#.##.###..##", "##.#.###.#.##.#",
	".###...#...###.", "###.#..#..#..#.", "#.##.##.##.####",
	"#.##.##.##.#.#.", "#.##.########.#", "#.##.#.#.#.##.#",
	"#.##.#.#..#..#.", "###..#.#.#..###",
	".............#.", ".........#.#...", "......###......",
	"....#.###.#....", "............###", "..#..#.#.#..#..",
	"....#.....#....", "...###...###...", ".#.#..#..#...#.",
	".#...#..#..#.#.", "#.#..#.#.#..#.#", "###..#.#.....#.",
};

static const char *glyph(char c)
{
	const char *p;

	if (c >= 'a' && c <= 'z')
		c = (char)(c - 'a' + 'A');
	if (c == ' ')
		return NULL;
	p = c != '\0' ? strchr(font_chars, c) : NULL;
	if (p == NULL)
		p = strchr(font_chars, '?');
	return font_cells[p - font_chars];
}

static void put(struct frs_raster *r, int x, int y, const uint8_t *color)
{
	if (x < 0 || y < 0 || (uint32_t)x >= r->w || (uint32_t)y >= r->h)
		return;
	memcpy(r->px + ((size_t)y * r->w + (size_t)x) * r->channels, color,
	    r->channels);
}

int plot_text_width(const char *s, int scale)
{
	size_t n = strlen(s);

	return n == 0 ? 0 : (int)n * (PLOT_GLYPH_W + 1) * scale - scale;
}

void plot_text(struct frs_raster *r, int x, int y, int scale, const char *s,
    const uint8_t *color)
{
	for (; *s != '\0'; s++, x += (PLOT_GLYPH_W + 1) * scale) {
		const char *g = glyph(*s);
		if (g == NULL)
			continue;
		for (int i = 0; i < PLOT_GLYPH_W * PLOT_GLYPH_H; i++) {
			int gx = i % PLOT_GLYPH_W, gy = i / PLOT_GLYPH_W;
			if (g[i] != '#')
				continue;
			for (int v = 0; v < scale; v++)
				for (int u = 0; u < scale; u++)
					put(r, x + gx * scale + u,
					    y + gy * scale + v, color);
		}
	}
}

/* Characters a line of w pixels holds at scale, lines h pixels hold. */
static size_t fit_cols(int w, int scale)
{
	return w < 0 ? 0 : (size_t)((w + scale) / ((PLOT_GLYPH_W + 1) * scale));
}

static size_t fit_rows(int h, int scale)
{
	return h < 0 ? 0 : (size_t)((h + scale) / ((PLOT_GLYPH_H + 1) * scale));
}

/* s over lines of cols characters at scale; its first max characters. */
static void text_lines(struct frs_raster *r, int x, int y, int scale,
    const char *s, size_t max, size_t cols, const uint8_t *color)
{
	char line[256];
	size_t len = strlen(s);

	if (cols >= sizeof line)
		cols = sizeof line - 1;
	for (size_t at = 0; at < len && at < max; at += cols) {
		size_t k = len - at < cols ? len - at : cols;
		if (k > max - at)
			k = max - at;
		memcpy(line, s + at, k);
		line[k] = '\0';
		plot_text(r, x, y, scale, line, color);
		y += (PLOT_GLYPH_H + 1) * scale;
	}
}

int plot_text_fit(struct frs_raster *r, int x, int y, int w, int h,
    int scale, const char *s, const uint8_t *color)
{
	size_t len = strlen(s), cols, rows;
	char end[256];

	if (len == 0)
		return 0;
	if (plot_text_width(s, scale) <= w && fit_rows(h, scale) >= 1) {
		plot_text(r, x, y, scale, s, color);
		return 1;
	}
	for (int k = scale - 1; k >= 1; k--) {
		cols = fit_cols(w, k), rows = fit_rows(h, k);
		if (cols > 0 && len <= cols * rows) {
			text_lines(r, x, y, k, s, len, cols, color);
			return (int)((len + cols - 1) / cols);
		}
	}
	/* Too long even at scale 1: the lines there is room for, the last
	 * one ending in "..." (a line too short for it is left as it is). */
	cols = fit_cols(w, 1), rows = fit_rows(h, 1);
	if (cols == 0 || rows == 0)
		return 0;
	text_lines(r, x, y, 1, s, (rows - 1) * cols, cols, color);
	if (cols > 3 && cols < sizeof end) {
		snprintf(end, sizeof end, "%.*s...", (int)(cols - 3),
		    s + (rows - 1) * cols);
		plot_text(r, x, y + (int)(rows - 1) * (PLOT_GLYPH_H + 1), 1, end,
		    color);
	}
	return (int)rows;
}

void plot_range(const double *y, size_t n, double ref, double step,
    double *lo, double *hi)
{
	double a = ref, b = ref;

	for (size_t i = 0; i < n; i++) {
		if (!isfinite(y[i]))
			continue;
		a = y[i] < a ? y[i] : a;
		b = y[i] > b ? y[i] : b;
	}
	*lo = floor(a / step) * step;
	*hi = ceil(b / step) * step;
	if (*hi <= *lo)
		*hi = *lo + step;
}

/* Data to pixel coordinates, clamped to the box. */
static double clampd(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

static int px_of(const struct plot_box *b, double x)
{
	double t = clampd((x - b->x0) / (b->x1 - b->x0), 0.0, 1.0);

	return b->px + (int)lround(t * (b->w - 1));
}

static int py_of(const struct plot_box *b, double y)
{
	double t = clampd((y - b->y0) / (b->y1 - b->y0), 0.0, 1.0);

	return b->py + (b->h - 1) - (int)lround(t * (b->h - 1));
}

/* Bresenham's line from (x0, y0) to (x1, y1), both ends drawn. */
static void line(struct frs_raster *r, int x0, int y0, int x1, int y1,
    const uint8_t *color)
{
	int dx = x1 > x0 ? x1 - x0 : x0 - x1, sx = x0 < x1 ? 1 : -1;
	int dy = y1 > y0 ? y0 - y1 : y1 - y0, sy = y0 < y1 ? 1 : -1;
	int e = dx + dy;

	for (;;) {
		int e2 = 2 * e;
		put(r, x0, y0, color);
		if (x0 == x1 && y0 == y1)
			break;
		if (e2 >= dy) {
			e += dy;
			x0 += sx;
		}
		if (e2 <= dx) {
			e += dx;
			y0 += sy;
		}
	}
}

void plot_axes(struct frs_raster *r, const struct plot_box *b,
    const double *xticks, size_t nx, const double *yticks, size_t ny,
    int scale)
{
	static const uint8_t grid[3] = { 225, 225, 225 };
	static const uint8_t ink[3] = { 0, 0, 0 };
	int x1 = b->px + b->w - 1, y1 = b->py + b->h - 1;
	char s[32];

	for (size_t i = 0; i < nx; i++) {
		int x;
		if (!(xticks[i] >= b->x0 && xticks[i] <= b->x1))
			continue;
		x = px_of(b, xticks[i]);
		line(r, x, b->py, x, y1, grid);
		snprintf(s, sizeof s, "%g", xticks[i]);
		plot_text(r, x - plot_text_width(s, scale) / 2,
		    y1 + 3 * scale, scale, s, ink);
	}
	for (size_t i = 0; i < ny; i++) {
		int y;
		if (!(yticks[i] >= b->y0 && yticks[i] <= b->y1))
			continue;
		y = py_of(b, yticks[i]);
		line(r, b->px, y, x1, y, grid);
		snprintf(s, sizeof s, "%g", yticks[i]);
		plot_text(r, b->px - 2 * scale - plot_text_width(s, scale),
		    y - PLOT_GLYPH_H * scale / 2, scale, s, ink);
	}
	line(r, b->px, b->py, x1, b->py, ink);
	line(r, b->px, y1, x1, y1, ink);
	line(r, b->px, b->py, b->px, y1, ink);
	line(r, x1, b->py, x1, y1, ink);
}

void plot_hline(struct frs_raster *r, const struct plot_box *b, double y,
    const uint8_t *color)
{
	int py = py_of(b, y);

	line(r, b->px + 1, py, b->px + b->w - 2, py, color);
}

void plot_curve(struct frs_raster *r, const struct plot_box *b,
    const double *x, const double *y, size_t n, const uint8_t *color)
{
	int have = 0, lx = 0, ly = 0;

	for (size_t i = 0; i < n; i++) {
		int cx, cy;
		if (isnan(x[i]) || isnan(y[i])) {
			have = 0;
			continue;
		}
		cx = px_of(b, x[i]);
		cy = py_of(b, y[i]);
		if (have)
			line(r, lx, ly, cx, cy, color);
		else
			put(r, cx, cy, color);
		lx = cx, ly = cy, have = 1;
	}
}
