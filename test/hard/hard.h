/*
 * Helpers of the hard-case suite (test/hard/): maps built by hand,
 * Forced Random Sampling through the library with a chosen matrix, the
 * share of the samples that falls on a set of pixels, and running the
 * programs of $BIN.  Include after testutil.h.
 *
 * The statistical bounds are those of independent (binomial) sampling at
 * 5 standard deviations: FRS is less dispersed than independent samples,
 * and HSW of a stratified input much less, so they are loose for both
 * and fail only when the density does not follow the importance.
 */
#ifndef FRS_HARD_H
#define FRS_HARD_H

#include <sys/stat.h>
#include <sys/wait.h>

#include "formats/frdio.h"
#include "sample/frscore.h"
#include "maps/imap.h"
#include "base/par.h"

/* The group setup of the suite: the samplers on 2 threads, whatever the
 * machine, so that the parallel paths run. */
static inline int hd_two_threads(void **state)
{
	(void)state;
	frs_set_threads(2);
	return 0;
}

/* A w x h map with every pixel v. */
static inline void hd_map(struct frs_imap *m, uint32_t w, uint32_t h,
    double v)
{
	assert_int_equal(imap_alloc(m, w, h), 0);
	for (uint64_t i = 0; i < (uint64_t)w * h; i++)
		m->v[i] = v;
}

/* |got - n p| within 5 binomial standard deviations (plus 2 for the
 * discreteness of small counts). */
static inline void hd_binom(const char *what, double got, double n, double p)
{
	double sd = sqrt(n * p * (1.0 - p)), z = (got - n * p) / (sd + 1e-300);

	print_message("%s: %.0f, expected %.6g (z %.2f)\n", what, got, n * p,
	    sd > 0 ? z : 0.0);
	if (!(fabs(got - n * p) <= 5.0 * sd + 2.0)) {
		print_error("%s: %.17g samples, expected %.17g +- %.3g\n", what,
		    got, n * p, 5.0 * sd + 2.0);
		fail();
	}
}

/* Share of the importance on the pixels where mask is set, in long
 * double (the maps span 1e-30 to 1e30 and more). */
static inline double hd_share(const struct frs_imap *m,
    const unsigned char *mask)
{
	long double in = 0, all = 0;

	for (uint64_t i = 0; i < (uint64_t)m->w * m->h; i++) {
		long double v = m->v[i] > 0 ? (long double)m->v[i] : 0.0L;
		all += v;
		if (mask[i])
			in += v;
	}
	return (double)(in / all);
}

/*
 * FRS of map with matrix mat through the library: setup, preparation
 * for algo (sorted lists of blocks of min(n_s, matrix side)), sampling.
 * The caller frees r.
 */
static inline void hd_frs(const struct frs_imap *map,
    const struct frs_matrix *mat, uint64_t n, uint64_t seed,
    enum frs_impl algo, int count_only, struct frs_setup *s,
    struct frs_result *r)
{
	struct frs_prep p;
	uint32_t side = mat->w < mat->h ? mat->w : mat->h, b = 0;

	if (frs_setup(s, map, mat, n, 8.0, seed) != 0)
		print_error("frs_setup: %s\n", frs_errmsg());
	assert_int_equal(s->n, n);
	if (algo == FRS_SORTED)
		b = s->ns < side ? s->ns : side;
	assert_int_equal(frs_prepare(&p, mat, algo != FRS_NAIVE &&
	    algo != FRS_SORTED, b), 0);
	if (frs_sample(s, map, &p, algo, &n, 1, count_only, r) != 0)
		print_error("frs_sample: %s\n", frs_errmsg());
	assert_non_null(r->chunk);
	frs_prep_free(&p);
}

/*
 * Every element of r as a point, with jitter none and random: finite, in
 * [0,1)^2 and inside the map pixel of its element; on a pixel of positive
 * importance.  in[pixel] counts the samples per map pixel (may be NULL).
 */
static inline void hd_points(struct frs_setup *s, const struct frs_imap *map,
    const struct frs_result *r, double *in)
{
	uint64_t k = 0;

	for (uint64_t c = 0; c < r->nchunk; c++)
		for (uint64_t i = 0; i < r->chunk[c].n; i++, k++) {
			const struct frs_elem *e = &r->chunk[c].e[i];
			uint64_t px = e->x / s->ns, py = e->y / s->ns;
			for (int j = 0; j < 2; j++) {
				double x, y;
				s->jitter = j ? FRS_PLACE_RANDOM : FRS_PLACE_CENTRE;
				frs_point(s, e, &x, &y);
				assert_true(isfinite(x) && isfinite(y));
				assert_true(x >= 0 && x < 1 && y >= 0 && y < 1);
				assert_true((uint64_t)(x * map->w) == px);
				assert_true((uint64_t)(y * map->h) == py);
			}
			assert_true(px < map->w && py < map->h);
			assert_true(map->v[py * map->w + px] > 0);
			if (in != NULL)
				in[py * map->w + px] += 1;
		}
	s->jitter = FRS_PLACE_CENTRE;
	assert_true(k == r->count);
}

/* Run a shell command line; its exit status (-1 if it did not exit). */
static inline int hd_sh(const char *fmt, ...)
{
	char cmd[4096];
	va_list ap;
	int st;

	va_start(ap, fmt);
	vsnprintf(cmd, sizeof cmd, fmt, ap);
	va_end(ap);
	st = system(cmd);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static inline int hd_exists(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0;
}

/* The file holds the fixed string s. */
static inline int hd_file_has(const char *path, const char *s)
{
	size_t n;
	unsigned char *b = tu_read(path, &n);
	int found;

	b[n] = 0;
	found = strstr((char *)b, s) != NULL;
	free(b);
	return found;
}

#endif
