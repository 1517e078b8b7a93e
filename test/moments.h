/*
 * Sample moments against those of an importance map taken as a
 * piecewise-constant density (pixel centres plus the variance of a
 * uniform pixel): the centroid within 0.1 pixel and the standard
 * deviation within 1 %, the thesis-independent oracle of the samplers'
 * statistical tests.  Include after testutil.h.
 */
#ifndef FRS_MOMENTS_H
#define FRS_MOMENTS_H

#include "maps/imap.h"

struct moments {
	double n, sx, sy, sxx, syy;
};

static inline void mom_add(struct moments *m, double x, double y)
{
	m->n += 1;
	m->sx += x;
	m->sy += y;
	m->sxx += x * x;
	m->syy += y * y;
}

static inline void mom_check(const struct frs_imap *map,
    const struct moments *m, const char *label)
{
	double mw = 0, mx = 0, my = 0, mxx = 0, myy = 0;
	double cx, cy, ex, ey, dx, dy, wx, wy;
	double pw = 1.0 / (12.0 * map->w * map->w), ph = 1.0 /
	    (12.0 * map->h * map->h);

	for (uint32_t j = 0; j < map->h; j++)
		for (uint32_t i = 0; i < map->w; i++) {
			double v = map->v[(size_t)j * map->w + i];
			double x = (i + 0.5) / map->w, y = (j + 0.5) / map->h;
			mw += v;
			mx += v * x;
			my += v * y;
			mxx += v * (x * x + pw);
			myy += v * (y * y + ph);
		}
	cx = m->sx / m->n;
	cy = m->sy / m->n;
	ex = mx / mw;
	ey = my / mw;
	dx = sqrt(m->sxx / m->n - cx * cx);
	dy = sqrt(m->syy / m->n - cy * cy);
	wx = sqrt(mxx / mw - ex * ex);
	wy = sqrt(myy / mw - ey * ey);
	print_message("%s: n %.0f centroid (%.5f %.5f) map (%.5f %.5f), sd "
	    "(%.5f %.5f) map (%.5f %.5f)\n", label, m->n, cx, cy, ex, ey, dx,
	    dy, wx, wy);
	assert_true(fabs(cx - ex) < 0.1 / map->w && fabs(cy - ey) < 0.1 / map->h);
	assert_true(fabs(dx / wx - 1) < 0.01 && fabs(dy / wy - 1) < 0.01);
}

#endif
