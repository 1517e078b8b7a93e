/* Matrices and maps for the FRS tests (test_frs, test_frscl). */
#ifndef FRS_TEST_FRSUTIL_H
#define FRS_TEST_FRSUTIL_H

#include "testutil.h"
#include "frdio.h"
#include "imap.h"
#include "rng.h"

/* A random permutation matrix: the implementations must agree on any. */
static inline void tu_perm_matrix(struct frs_matrix *m, uint32_t w,
    uint32_t h, uint64_t seed)
{
	struct frs_rng r;
	assert_int_equal(frd_alloc(m, 2, w, h, 1, ""), 0);
	frs_rng_init(&r, seed, FRS_STREAM_TEST);
	for (uint32_t i = 0; i < m->n; i++)
		m->v[i] = i;
	for (uint32_t i = (uint32_t)m->n - 1; i > 0; i--) {
		uint32_t j = (uint32_t)frs_rng_below(&r, i + 1), t = m->v[i];
		m->v[i] = m->v[j];
		m->v[j] = t;
	}
}

/* A map from a spec, file or procedural, at w x h. */
static inline void tu_map_of(const char *spec, uint32_t w, uint32_t h,
    struct frs_imap *m)
{
	if (imap_load(spec, w, h, 0, m) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(m->v);
}

#endif
