/* Matrices, maps and results for the FRS and FRD tests (test_frs,
 * test_frscl, test_frdgen, test_frdgencl, test/hard). */
#ifndef FRS_TEST_FRSUTIL_H
#define FRS_TEST_FRSUTIL_H

#include "testutil.h"
#include "base/num.h"
#include "formats/frdio.h"
#include "sample/frscore.h"
#include "sample/frs3.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "base/rng.h"
#include "frd-gen/frdgen.h"

/* The size fields of a generator's parameters (frdgen_params,
 * vac_params): d 1 is a 2-D matrix. */
#define TU_SIZES(pr, w_, h_, d_) ((pr)->dims = (d_) > 1 ? 3 : 2, \
	(pr)->w = (w_), (pr)->h = (h_), (pr)->d = (d_))

/* The generator's defaults for a w x h x d matrix with the candidate
 * fraction p, the tolerance tol and the seed. */
static inline void tu_frdgen_params(struct frdgen_params *pr, uint32_t w,
    uint32_t h, uint32_t d, double p, double tol, uint64_t seed)
{
	frdgen_defaults(pr);
	TU_SIZES(pr, w, h, d);
	pr->p = p;
	pr->tol = tol;
	pr->seed = seed;
}

/* The values of an allocated matrix a random permutation of 0 .. n-1. */
static inline void tu_perm_fill(struct frs_matrix *m, uint64_t seed)
{
	struct frs_rng r;
	frs_rng_init(&r, seed, FRS_STREAM_TEST);
	for (uint32_t i = 0; i < m->n; i++)
		m->v[i] = i;
	for (uint32_t i = (uint32_t)m->n - 1; i > 0; i--) {
		uint32_t j = (uint32_t)frs_rng_below(&r, i + 1), t = m->v[i];
		m->v[i] = m->v[j];
		m->v[j] = t;
	}
}

/* A random permutation matrix: the implementations must agree on any. */
static inline void tu_perm_matrix(struct frs_matrix *m, uint32_t w,
    uint32_t h, uint64_t seed)
{
	assert_int_equal(frd_alloc(m, 2, w, h, 1, ""), 0);
	tu_perm_fill(m, seed);
}

/* A map from a spec, file or procedural, at w x h. */
static inline void tu_map_of(const char *spec, uint32_t w, uint32_t h,
    struct frs_imap *m)
{
	if (imap_load(spec, w, h, 0, m) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(m->v);
}

/* Every value 0 .. n-1 exactly once. */
static inline void tu_assert_permutation(const struct frs_matrix *m)
{
	unsigned char *seen = calloc(m->n, 1);

	assert_non_null(seen);
	for (size_t i = 0; i < m->n; i++) {
		assert_true(m->v[i] < m->n);
		assert_int_equal(seen[m->v[i]], 0);
		seen[m->v[i]] = 1;
	}
	free(seen);
}

/* Elements by position: y, x, then step. */
static inline int tu_elem_cmp(const void *a, const void *b)
{
	const struct frs_elem *x = a, *y = b;

	return x->y != y->y ? NUM_CMP(x->y, y->y) :
	    x->x != y->x ? NUM_CMP(x->x, y->x) : NUM_CMP(x->step, y->step);
}

/* The elements of a result, 2-D (struct frs_result) or 3-D (struct
 * frs3_result), into out (room for r->count), in their order. */
#define TU_GATHER(out, r) do {						\
	uint64_t k_ = 0;						\
	for (uint64_t c_ = 0; c_ < (r)->nchunk; c_++)			\
		for (uint64_t i_ = 0; i_ < (r)->chunk[c_].n; i_++)	\
			(out)[k_++] = (r)->chunk[c_].e[i_];		\
	assert_true(k_ == (r)->count);					\
} while (0)

/* 3-D elements by position: z, y, x, then step. */
static inline int tu_elem3_cmp(const void *a, const void *b)
{
	const struct frs3_elem *x = a, *y = b;

	return x->z != y->z ? NUM_CMP(x->z, y->z) :
	    x->y != y->y ? NUM_CMP(x->y, y->y) :
	    x->x != y->x ? NUM_CMP(x->x, y->x) : NUM_CMP(x->step, y->step);
}

static inline void tu_sort_elems(void *e, uint64_t n, size_t size,
    int (*cmp)(const void *, const void *))
{
	if (cmp != NULL)
		qsort(e, (size_t)n, size, cmp);
}

/* All elements of a result, 2-D or 3-D, in a new array e: in their
 * order (cmp NULL), or sorted by cmp. */
#define TU_ELEMS(e, r, cmp) do {					\
	(e) = malloc(((r)->count + 1) * sizeof *(e));			\
	assert_non_null(e);						\
	TU_GATHER(e, r);						\
	tu_sort_elems(e, (r)->count, sizeof *(e), cmp);			\
} while (0)

/* Results a and b, 2-D or 3-D with elements of type T, hold the same
 * elements: in the same order (cmp NULL), or in any order. */
#define TU_SAME_ELEMS(T, a, b, cmp) do {				\
	T *ea_, *eb_;							\
	assert_true((a)->count == (b)->count);				\
	TU_ELEMS(ea_, a, cmp);						\
	TU_ELEMS(eb_, b, cmp);						\
	assert_memory_equal(ea_, eb_, (a)->count * sizeof *ea_);	\
	free(ea_);							\
	free(eb_);							\
} while (0)

/* All elements of a result in one array: in their order, or sorted by
 * position (tu_elem_cmp). */
static inline struct frs_elem *tu_elems(const struct frs_result *r,
    int sorted)
{
	struct frs_elem *e;

	TU_ELEMS(e, r, sorted ? tu_elem_cmp : NULL);
	return e;
}

/* a and b hold the same elements, in any order. */
static inline void tu_same_set(const struct frs_result *a,
    const struct frs_result *b)
{
	TU_SAME_ELEMS(struct frs_elem, a, b, tu_elem_cmp);
}

#endif
