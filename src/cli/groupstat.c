#define _POSIX_C_SOURCE 200809L
#include <math.h>

#include "cli/groupstat.h"

size_t group_sets(enum pt_group g, const struct pt_set *sets, size_t nsets,
    size_t *group)
{
	size_t k = 0;

	for (size_t i = 0; i < nsets; i++) {
		size_t j = 0;
		/* The group of the first set of the same group, if any
		 * (pt_same_group is an equivalence). */
		while (j < i && !pt_same_group(g, &sets[j], &sets[i]))
			j++;
		group[i] = j < i ? group[j] : k++;
	}
	return k;
}

void group_stat(const struct pt_set *sets, size_t nsets, const size_t *group,
    size_t k, const double *v, double ref, struct group_stat *st)
{
	double m = 0, sn = 0, sum = 0, sa = 0, s2 = 0, max = 0, var = 0;
	size_t first = nsets;

	for (size_t j = 0; j < nsets; j++) {
		double e;
		if (group[j] != k)
			continue;
		if (first == nsets)
			first = j;
		e = v[j] - ref;
		m++, sn += (double)sets[j].n, sum += v[j];
		sa += fabs(e), s2 += e * e;
		max = v[j] > max ? v[j] : max;
	}
	st->first = first;
	st->sets = m;
	st->n = sn / m;
	st->mean = sum / m;
	st->max = max;
	/* Two passes: the deviations about the mean, not sum v^2 - m mean^2,
	 * which cancels. */
	for (size_t j = first; j < nsets; j++)
		if (group[j] == k) {
			double c = v[j] - st->mean;
			var += c * c;
		}
	st->se = m > 1 ? sqrt(var / (m - 1) / m) : NAN;
	st->abs_err = sa / m;
	st->rmse = sqrt(s2 / m);
}
