/* Internal to the discrepancy modules (disc*.c): the pieces they share;
 * and the progress bar of their parallel loops, which discrepancy(1)
 * sets. */
#ifndef FRS_DISCINT_H
#define FRS_DISCINT_H

#include <stddef.h>
#include <stdint.h>


/* A task of this label on the progress bar for each parallel loop inside
 * one set (NULL: none; cli.h's cli_task). */
void disc_set_progress(const char *label);
/* Chunks of [0, n) in order, on the thread team when par is set. */
int disc_run_chunks(uint64_t n, uint64_t chunk,
    int (*fn)(void *, uint64_t, uint64_t), void *ctx, int par);
/* ord[0..n-1]: the indices of v[i * stride], i < n, in ascending order
 * of the values, equal values by index (a stable radix sort, O(n)). */
int disc_order(const double *v, size_t n, size_t stride, uint32_t *ord);
/* Grid lines as the methods define them. */
double disc_star_line(uint32_t i, uint32_t s);	/* i/s */
double disc_rect_line(uint32_t a, uint32_t s);	/* a/(s-1) */
/* Grid bins: star, lines i/s (i = 1..s) at or below v; rect, the index
 * of the interval [a/(s-1), (a+1)/(s-1)) holding v. */
uint32_t disc_star_bin(double v, uint32_t s);
uint32_t disc_rect_bin(double v, uint32_t s);

/* Points grouped by a bin of one coordinate: the points of bin b are
 * idx[start[b] .. start[b+1]-1]. */
struct disc_rows {
	uint32_t *start, *idx;
};
int disc_rows_make(struct disc_rows *r, const uint32_t *bin, size_t n,
    uint32_t nbins);
void disc_rows_free(struct disc_rows *r);

#endif
