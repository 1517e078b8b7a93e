/* Internal: points in cells for the random-shape classes. */
#ifndef FRS_DISCSHAPE_H
#define FRS_DISCSHAPE_H

#include <stddef.h>
#include <stdint.h>

#include "discrepancy/disc.h"

struct disc_cols {
	uint32_t g;		/* g x g cells of side 1/g */
	uint32_t *start;	/* cell (row r, column b): points
				 * [start[r g + b], start[r g + b + 1]) */
	double *x, *y;		/* points by cell, row by row */
};

static inline uint32_t disc_col(const struct disc_cols *c, double v)
{
	double f = v * (double)c->g;
	if (!(f > 0.0))
		return 0;
	return f >= (double)(c->g - 1) ? c->g - 1 : (uint32_t)f;
}

int disc_cols_make(struct disc_cols *c, const double *xy, size_t n);
void disc_cols_free(struct disc_cols *c);
uint64_t disc_count_quad(const struct disc_cols *c, const double q[8]);
uint64_t disc_count_circle(const struct disc_cols *c, const double e[3]);

#endif
