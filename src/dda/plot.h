/*
 * Line plots and text on an RGB raster (struct frs_raster, raster.h), for
 * the summary page of dda --summary: framed boxes with grid lines at
 * given ticks and numeric tick labels, polylines of data clipped to the
 * box, and text in a small block font.
 *
 * Text.  The font is 3 x 5 cells, drawn at an integer scale s (each cell
 * s x s pixels), one cell of space after each glyph: a character takes
 * 4 s pixels of width, a line 5 s.  It has the digits, the capital
 * letters, space and . , - + _ / : = ( ) % ?; small letters are drawn as
 * capitals, anything else as '?'.
 *
 * Coordinates.  A box maps data (x, y) in [x0, x1] x [y0, y1] onto the
 * pixels [px, px + w - 1] x [py, py + h - 1]: x0 at column px, x1 at
 * px + w - 1, y1 at the top row py and y0 at the bottom row (y grows
 * upward, as in a plot).  Values beyond the box are drawn at its edge
 * (a curve that leaves through the top runs along it), NaN breaks a
 * curve.
 */
#ifndef FRS_PLOT_H
#define FRS_PLOT_H

#include <stddef.h>
#include <stdint.h>

#include "cli/cli.h"

struct plot_box {
	int px, py, w, h;	/* pixels; w, h >= 2 */
	double x0, x1, y0, y1;	/* data range, x0 < x1, y0 < y1 */
};

#define PLOT_GLYPH_W 3
#define PLOT_GLYPH_H 5

/* Width in pixels of s at scale (4 scale per character, less the
 * trailing space; 0 for ""). */
int plot_text_width(const char *s, int scale);

/* Text with its top left corner at pixel (x, y); clipped to the raster.
 * color has the raster's channel count of values. */
void plot_text(struct frs_raster *r, int x, int y, int scale, const char *s,
    const uint8_t *color);

/* Text s fitted into the w x h pixels at (x, y): one line at scale if
 * it fits, else at the largest smaller scale at which it fits wrapped
 * over lines 6 scale apart (broken anywhere), else at scale 1 over the
 * lines there is room for, the last one cut and ending in "...".  The
 * number of lines drawn. */
int plot_text_fit(struct frs_raster *r, int x, int y, int w, int h,
    int scale, const char *s, const uint8_t *color);

/* The range [*lo, *hi] of a plot of the n values y (NaN and infinities left out) and
 * the reference line ref: whole multiples of step around them, at least
 * one step apart. */
void plot_range(const double *y, size_t n, double ref, double step,
    double *lo, double *hi);

/* The frame of the box, grid lines at the ticks (data values; those
 * outside the range are left out), and each tick's value (%g) left of
 * the box (y) or below it (x), in text of the given scale. */
void plot_axes(struct frs_raster *r, const struct plot_box *b,
    const double *xticks, size_t nx, const double *yticks, size_t ny,
    int scale);

/* A horizontal line across the box at data y (clamped to the box). */
void plot_hline(struct frs_raster *r, const struct plot_box *b, double y,
    const uint8_t *color);

/* The polyline through (x[i], y[i]), i = 0..n-1, in the box; points with
 * a NaN coordinate break it. */
void plot_curve(struct frs_raster *r, const struct plot_box *b,
    const double *x, const double *y, size_t n, const uint8_t *color);

#endif
