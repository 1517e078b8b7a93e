/* Checks shared by the reference samplers' tests (test_refsamp,
 * test_refsamp3). */
#ifndef FRS_TEST_REFSAMPUTIL_H
#define FRS_TEST_REFSAMPUTIL_H

#include "testutil.h"
#include "cli/refsamp.h"

/* n points of kind k from seed, malloc'd; *placed gets their count. */
typedef double *(*tu_gen_fn)(enum refsamp_kind k, uint64_t n, uint64_t seed,
    uint64_t *placed);

/* Every kind gives the same points for the same seed and, but for the
 * regular grid, others for another seed (dims coordinates a point). */
static inline void tu_refsamp_deterministic(tu_gen_fn gen, unsigned dims)
{
	for (int k = REFSAMP_RANDOM; k <= REFSAMP_DART; k++) {
		uint64_t ma, mb, mc;
		double *a = gen((enum refsamp_kind)k, 500, 9, &ma);
		double *b = gen((enum refsamp_kind)k, 500, 9, &mb);
		double *c = gen((enum refsamp_kind)k, 500, 10, &mc);
		assert_int_equal(ma, mb);
		assert_memory_equal(a, b, dims * ma * sizeof *a);
		if (k != REFSAMP_REGULAR)
			assert_true(ma != mc ||
			    memcmp(a, c, dims * ma * sizeof *a) != 0);
		free(a);
		free(b);
		free(c);
	}
}

/* The squared distance of a and b on the unit torus of dims dimensions. */
static inline double tu_torus_d2(const double *a, const double *b,
    unsigned dims)
{
	double d2 = 0;
	for (unsigned k = 0; k < dims; k++) {
		double d = fabs(a[k] - b[k]);
		if (d > 0.5)
			d = 1 - d;
		d2 += d * d;
	}
	return d2;
}

/* The smallest squared torus distance between m points (1e9 for none):
 * brute force over all pairs, independent of the samplers' grids. */
static inline double tu_torus_min_d2(const double *p, uint64_t m,
    unsigned dims)
{
	double d2 = 1e9;
	for (uint64_t i = 0; i < m; i++)
		for (uint64_t j = i + 1; j < m; j++) {
			double d = tu_torus_d2(p + dims * i, p + dims * j, dims);
			if (d < d2)
				d2 = d;
		}
	return d2;
}

#endif
