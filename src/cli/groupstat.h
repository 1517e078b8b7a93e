/*
 * The statistics of a table row over a group of point sets (--group,
 * ptsets.h), for discrepancy(1) and mc-error(1): one value per set (a
 * discrepancy, an estimate), summed up over the sets of each group.  The
 * groups come in order of first appearance; their sets in file order.
 */
#ifndef FRS_GROUPSTAT_H
#define FRS_GROUPSTAT_H

#include <stddef.h>

#include "cli/ptsets.h"

/* Each set's group, 0 .. k - 1 numbered by first appearance, into
 * group[0 .. nsets - 1]; returns k. */
size_t group_sets(enum pt_group g, const struct pt_set *sets, size_t nsets,
    size_t *group);

struct group_stat {
	size_t first;		/* the group's first set */
	double sets;		/* the sets in it, m */
	double n;		/* their mean point count */
	double mean, max;	/* of the values (max at least 0) */
	double se;		/* the standard error of the mean, the
				 * deviations taken about it:
				 * sqrt(sum / (m - 1) / m); NaN for m = 1 */
	double abs_err, rmse;	/* the mean |v - ref|, and the square root
				 * of the mean (v - ref)^2 */
};

/* The statistics of v[i] (one value per set) over the sets i of group k
 * (group as group_sets made it), ref the value they should have. */
void group_stat(const struct pt_set *sets, size_t nsets, const size_t *group,
    size_t k, const double *v, double ref, struct group_stat *st);

#endif
