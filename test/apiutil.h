/*
 * What the tests of the public API (src/lib/frs.h) share: test_api_*.c
 * and test_api3.c, one program per topic.  The helpers that draw and
 * compare; the oracle, the library's stages run here without api.c
 * (frs_setup, frs_sample, frs_point), against which the API's samples
 * are compared bit for bit, as against those of frs-sample for the same
 * map, seed and options; EXPECT for the error codes; the group's setup
 * and teardown, the same for every program.
 * The programs come from $BIN (test/run.sh exports it); the current
 * directory is the source tree.
 */
#ifndef FRS_TEST_APIUTIL_H
#define FRS_TEST_APIUTIL_H

#include "testutil.h"

#include <fcntl.h>

#include "frs.h"
#include "api/api.h"
#include "formats/frdio.h"
#include "maps/imap.h"
#include "cli/ptsio.h"
#include "base/rng.h"
#include "maps/vol.h"
#include "maps/exrio.h"
#include "maps/mapload.h"
#include "sample/frscore.h"
#include "sample/frs3.h"
#include "base/par.h"

#define MATRIX "data/default.frd"
#define MATRIX3 "data/default3.frd"

static frs_mask *mask;		/* MATRIX, loaded once */
static struct frs_imap blob;	/* "blob" as frs-sample reads it: doubles */
static struct frs_matrix mat;	/* MATRIX, read for the oracle */
static struct frs_matrix mat3;	/* MATRIX3, read when first needed */

/* ---- helpers --------------------------------------------------------- */

static inline const char *bindir(void)
{
	const char *b = getenv("BIN");

	return b != NULL && *b ? b : "bin";
}

/* Run "$BIN/CMD" through the shell; it must succeed. */
static inline void prog(const char *fmt, ...) FRS_PRINTF(1, 2);
static inline void prog(const char *fmt, ...)
{
	char cmd[2048];
	int len = snprintf(cmd, sizeof cmd, "%s/", bindir());
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(cmd + len, sizeof cmd - (size_t)len, fmt, ap);
	va_end(ap);
	if (system(cmd) != 0) {
		print_error("command failed: %s\n", cmd);
		fail();
	}
}

/* "Nothing prints": standard error goes to a file from quiet_begin to
 * quiet_end, which fails the test when anything was written. */
static inline int quiet_begin(void)
{
	int saved, fd;

	fflush(stderr);
	saved = dup(2);
	fd = open(tu_path("stderr.txt"), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	assert_true(saved >= 0 && fd >= 0);
	assert_int_equal(dup2(fd, 2), 2);
	close(fd);
	return saved;
}

static inline void quiet_end(int saved, const char *what)
{
	size_t n;
	unsigned char *text;

	fflush(stderr);
	assert_int_equal(dup2(saved, 2), 2);
	close(saved);
	text = tu_read(tu_path("stderr.txt"), &n);
	if (n > 0) {
		text[n] = '\0';
		print_error("%s printed: %s\n", what, (char *)text);
		free(text);
		fail();
	}
	free(text);
}

/* The records of a point file equal rec (n records of 2 + extra). */
static inline void same_as_file(const char *path, const double *rec, size_t n,
    unsigned extra)
{
	struct frs_points p;
	size_t k = 2 + extra;

	assert_int_equal(pts_read(path, &p), 0);
	assert_int_equal(p.dims, 2);
	assert_int_equal(p.extra, extra);
	if (p.n != n)
		print_error("%s: %zu points, the API made %zu\n", path, p.n, n);
	assert_int_equal(p.n, n);
	for (size_t i = 0; i < n; i++)
		if (memcmp(&p.x[i * k], &rec[i * k], k * sizeof *rec) != 0) {
			print_error("%s: point %zu is (%.17g, %.17g), the API's "
			    "(%.17g, %.17g)\n", path, i, p.x[i * k],
			    p.x[i * k + 1], rec[i * k], rec[i * k + 1]);
			fail();
		}
	pts_free(&p);
}

/* What one draw made. */
struct drawn {
	size_t n;
	double *xy, *pdf;
	uint32_t *step;
};

static inline void drawn_free(struct drawn *d)
{
	free(d->xy);
	free(d->pdf);
	free(d->step);
	memset(d, 0, sizeof *d);
}

/* frs_draw_progressive, sized by a first call with no room (which must
 * say FRS_E_BUFFER and the count). */
static inline struct drawn draw(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int want_pdf)
{
	struct drawn d = { 0, NULL, NULL, NULL };
	frs_error e;
	size_t cnt = 0;

	assert_int_equal(frs_draw_progressive(s, steps, nsteps, seed, NULL,
	    NULL, NULL, 0, &d.n, &e), FRS_E_BUFFER);
	assert_int_equal(e.code, FRS_E_BUFFER);
	assert_true(d.n > 0);
	d.xy = malloc(2 * d.n * sizeof *d.xy);
	d.pdf = want_pdf ? malloc(d.n * sizeof *d.pdf) : NULL;
	d.step = malloc(d.n * sizeof *d.step);
	assert_non_null(d.xy);
	assert_non_null(d.step);
	if (frs_draw_progressive(s, steps, nsteps, seed, d.xy, d.pdf, d.step,
	    d.n, &cnt, &e) != FRS_OK) {
		print_error("frs_draw_progressive: %s %s\n",
		    frs_code_name((int)e.code), e.message);
		fail();
	}
	assert_int_equal(e.code, FRS_OK);
	assert_string_equal(e.message, "");
	assert_int_equal(cnt, d.n);
	return d;
}

/* In frs-sample's layout: x, y, the density with --pdf, the step
 * (counted from 1) with --progressive. */
static inline double *records(const struct drawn *d, int pdf, int steps)
{
	size_t k = 2 + (size_t)pdf + (size_t)steps, j;
	double *r = malloc((d->n ? d->n : 1) * k * sizeof *r);

	assert_non_null(r);
	for (size_t i = 0; i < d->n; i++) {
		j = i * k;
		r[j++] = d->xy[2 * i];
		r[j++] = d->xy[2 * i + 1];
		if (pdf)
			r[j++] = d->pdf[i];
		if (steps)
			r[j++] = (double)d->step[i] + 1.0;
	}
	return r;
}

/* Two samplers' draws of n with seed and the densities: the same
 * count, points and densities. */
static inline void same_draw(const frs_sampler *s, const frs_sampler *t,
    uint64_t n, uint64_t seed)
{
	struct drawn a = draw(s, &n, 1, seed, 1), b = draw(t, &n, 1, seed, 1);

	assert_int_equal(a.n, b.n);
	assert_memory_equal(a.xy, b.xy, 2 * a.n * sizeof *a.xy);
	assert_memory_equal(a.pdf, b.pdf, a.n * sizeof *a.pdf);
	drawn_free(&a);
	drawn_free(&b);
}

/* "1000,3000" for --progressive. */
static inline const char *step_list(const uint64_t *steps, unsigned nsteps)
{
	static char buf[512];
	size_t len = 0;

	for (unsigned k = 0; k < nsteps; k++)
		len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%llu",
		    k ? "," : "", (unsigned long long)steps[k]);
	return buf;
}

/* frs-sample -m matrix ARGS with the counts, seed and --pdf, into out. */
static inline void frs_sample_prog(const char *matrix, const char *args,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int pdf,
    const char *out)
{
	if (nsteps > 1)
		prog("frs-sample -q -m %s %s --progressive %s -S %llu %s -o %s",
		    matrix, args, step_list(steps, nsteps),
		    (unsigned long long)seed, pdf ? "--pdf" : "", out);
	else
		prog("frs-sample -q -m %s %s -n %llu -S %llu %s -o %s", matrix,
		    args, (unsigned long long)steps[0], (unsigned long long)seed,
		    pdf ? "--pdf" : "", out);
}

/* ---- the oracle: the library's stages without api.c -------------- */

/* The options as frs.h defines them, in the internal names. */
static inline enum frs_impl algo_of(enum frs_algorithm a)
{
	return a == FRS_ALG_NAIVE ? FRS_NAIVE : a == FRS_ALG_STACK ? FRS_STACK :
	    a == FRS_ALG_LEVEL1 ? FRS_LEVEL1 : a == FRS_ALG_LEVEL2 ? FRS_LEVEL2 :
	    FRS_SORTED;
}

static inline enum frs_rule rule_of(const struct frs_options *o)
{
	return o->rule == FRS_RULE_THESIS ? FRS_THESIS : FRS_UNBIASED;
}

static inline enum frs_place jitter_of(const struct frs_options *o)
{
	return o->jitter == FRS_JIT_HALTON ? FRS_PLACE_HALTON :
	    o->jitter == FRS_JIT_RANDOM ? FRS_PLACE_RANDOM : FRS_PLACE_CENTRE;
}

static inline enum frs_tiling tiling_of(const struct frs_options *o,
    enum frs_tiling dflt)
{
	return o->tiling == FRS_TILING_PLAIN ? FRS_TILES_PLAIN :
	    o->tiling == FRS_TILING_SHUFFLED ? FRS_TILES_SHUFFLE : dflt;
}

/* The matrix prepared with or without the minmap and with lists of
 * block b (0: none), made on first use: the few kinds the tests use. */
static struct prepared {
	int minmap;
	uint32_t block;
	struct frs_prep p;
} prepared[32];
static size_t nprepared;

static inline const struct frs_prep *oracle_prep(int minmap, uint32_t b)
{
	struct prepared *q;

	for (q = prepared; q < prepared + nprepared; q++)
		if (q->minmap == minmap && q->block == b)
			return &q->p;
	assert_true(nprepared < sizeof prepared / sizeof prepared[0]);
	q = &prepared[nprepared++];
	q->minmap = minmap;
	q->block = b;
	assert_int_equal(frs_prepare(&q->p, &mat, minmap, b), 0);
	return &q->p;
}

/* The levels of a run as frs.h defines them (libfrs(3)): the plan of
 * frs_levels_plan for level 0's setup s0, smoothed as the options say
 * (0: an eighth of the longest side), and a setup per level that has
 * pixels (frs_level_setup), which reads the pixels of its level.  One
 * level (s0 as it is) without levels, or when every pixel is at 0. */
struct olev {
	unsigned n;
	struct frs_setup su[FRS_LEVELS_MAX];
	struct frs_levels plan;
};

/* The coarsest level a run needs (frs-sample(1), Levels): the finest at
 * which the window of the whole map, (n_s / 2^l) per pixel side, fits
 * the mw x mh matrix, or one element a pixel. */
static inline unsigned oracle_top(uint32_t ns, const uint32_t *side,
    const uint32_t *m, unsigned dims)
{
	unsigned l = 0;

	while ((ns >> l) > 1) {
		int fits = 1;
		for (unsigned a = 0; a < dims; a++)
			fits &= (uint64_t)(ns >> l) * side[a] <= m[a];
		if (fits)
			break;
		l++;
	}
	return l;
}

/* The same for a matrix of nm elements. */
static inline void oracle_levels_of(const struct frs_imap *map,
    const struct frs_options *o, const struct frs_setup *s0, double nm,
    struct olev *lv)
{	const uint32_t side[2] = { map->w, map->h };
	double blur = o->level_blur > 0.0 ? o->level_blur :
	    (double)(map->w > map->h ? map->w : map->h) / 8.0;
	unsigned top = 0;

	memset(lv, 0, sizeof *lv);
	lv->n = 1;
	lv->su[0] = *s0;
	const uint32_t msz[2] = { s0->mw, s0->mh };

	top = oracle_top(s0->ns, side, msz, 2);
	if (o->tiling != FRS_TILING_LEVELS || top == 0)
		return;
	assert_int_equal(frs_levels_plan(&lv->plan, 2, side, map->v,
	    s0->tau * s0->iscale, top, nm, s0->sigma, blur), 0);
	if (frs_levels_used(&lv->plan) == 1 && lv->plan.cells[0] > 0)
		return;
	lv->n = 0;
	for (unsigned l = 0; l <= top; l++) {
		struct frs_setup *su = &lv->su[lv->n];
		if (lv->plan.cells[l] == 0)
			continue;
		if (l == 0)
			*su = *s0;
		else
			frs_level_setup(su, s0, l, lv->plan.max[l]);
		su->max = lv->plan.max[l];
		su->lev = lv->plan.lev;
		su->cell0 = 0;
		su->cell1 = (uint64_t)map->w * map->h;
		lv->n++;
	}
}

static inline void oracle_levels(const struct frs_imap *map,
    const struct frs_options *o, const struct frs_setup *s0, struct olev *lv)
{
	oracle_levels_of(map, o, s0, (double)mat.w * mat.h, lv);
}

/* Exact counts: Naive's count of every level at level 0's scale tau. */
struct naive_count {
	struct olev *lv;
	const struct frs_imap *map;
	const struct frs_prep *p;
};

static inline int naive_count(void *ctx, double tau, uint64_t *count)
{
	struct naive_count *c = ctx;
	struct frs_result r;

	*count = 0;
	for (unsigned i = 0; i < c->lv->n; i++) {
		struct frs_setup *su = &c->lv->su[i];
		su->exact = (struct frs_xtau){ .n = 1, .steps = { su->n },
		    .tau = { tau } };
		if (frs_sample(su, c->map, c->p, FRS_NAIVE, &su->n, 1, 1, &r) < 0)
			return -1;
		*count += r.count;
		frs_result_free(&r);
	}
	return 0;
}

/* Listing 5.1 (frs_setup) with the options, its levels; under
 * FRS_RULE_EXACT the taus at which Naive counts exactly each step over
 * all levels. */
static inline void oracle_setup(const struct frs_imap *map,
    const struct frs_options *o, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, struct olev *lv)
{
	struct naive_count c = { lv, map, oracle_prep(0, 0) };
	struct frs_setup su;
	struct frs_xtau x;
	double tau0[16];
	uint64_t most = 0;
	unsigned passes;

	assert_int_equal(frs_setup(&su, map, &mat, steps[nsteps - 1], o->sigma,
	    seed), 0);
	su.rule = rule_of(o);
	su.jitter = jitter_of(o);
	su.tiles = tiling_of(o, FRS_TILES_PLAIN);
	oracle_levels(map, o, &su, lv);
	if (o->rule != FRS_RULE_EXACT)
		return;
	for (unsigned k = 0; k < nsteps; k++)
		tau0[k] = frs_tau(&su, steps[k]);
	/* every window element of non-zero importance, level by level */
	for (unsigned i = 0; i < lv->n; i++) {
		const struct frs_setup *t = &lv->su[i];
		for (uint64_t p = 0; p < (uint64_t)map->w * map->h; p++)
			most += map->v[p] > 0.0 && frs_cell_here(t->lev, t->level,
			    p) ? (uint64_t)t->ns * t->ns : 0;
	}
	assert_int_equal(frs_exact_taus(steps, nsteps, tau0, most, naive_count,
	    &c, &x, &passes), 0);
	for (unsigned i = 0; i < lv->n; i++) {
		lv->su[i].exact = x;
		lv->su[i].tau = frs_tau(&lv->su[i], lv->su[i].n);
	}
}

/* What frs_draw_progressive promises for map and o: the window of each
 * level thresholded by the same implementation (on lists prepared here),
 * each element's point by frs_point, its density I / mean, in the order
 * of frs.h: the steps in turn, each level by level, each in row order.
 * *exact_order is cleared where the API may order a pixel's elements
 * otherwise (Sorted walks or scans a small level instead of its lists). */
static inline struct drawn oracle_draw(const struct frs_imap *map,
    const struct frs_options *o, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int *exact_order)
{
	enum frs_impl a = algo_of(o->algorithm);
	struct olev lv;
	struct frs_result r[FRS_LEVELS_MAX];
	struct drawn d = { 0, NULL, NULL, NULL };
	uint64_t count = 0;

	oracle_setup(map, o, steps, nsteps, seed, &lv);
	*exact_order = a != FRS_SORTED || lv.plan.lev == NULL;
	frs_set_threads(1);
	for (unsigned i = 0; i < lv.n; i++) {
		const struct frs_setup *su = &lv.su[i];
		uint32_t b = 0;
		int minmap = a == FRS_STACK || a == FRS_LEVEL1 || a == FRS_LEVEL2;
		if (a == FRS_SORTED) {
			/* blocks of n_s, as far as the matrix and its tiling
			 * keep them whole; the minmap for the rest of each
			 * pixel */
			uint32_t t = frs_tile_max_block(su);
			b = su->ns < mat.w ? su->ns : mat.w;
			b = b < mat.h ? b : mat.h;
			b = b < t ? b : t;
			minmap = b < su->ns;
		}
		assert_int_equal(frs_sample(su, map, oracle_prep(minmap, b), a,
		    steps, nsteps, 0, &r[i]), 0);
		count += r[i].count;
	}
	d.xy = malloc(2 * (count + 1) * sizeof *d.xy);
	d.pdf = malloc((count + 1) * sizeof *d.pdf);
	d.step = malloc((count + 1) * sizeof *d.step);
	assert_true(d.xy && d.pdf && d.step);
	for (uint32_t k = 0; k < nsteps; k++)
		for (unsigned l = 0; l < lv.n; l++)
			for (uint64_t c = 0; c < r[l].nchunk; c++)
				for (uint64_t i = 0; i < r[l].chunk[c].n; i++) {
					const struct frs_elem *e = &r[l].chunk[c].e[i];
					const struct frs_setup *su = &lv.su[l];
					if (nsteps > 1 && e->step != k)
						continue;
					frs_point(su, e, &d.xy[2 * d.n],
					    &d.xy[2 * d.n + 1]);
					d.pdf[d.n] = map->v[(size_t)(e->y / su->ns) *
					    map->w + e->x / su->ns] / su->mean;
					d.step[d.n++] = e->step;
				}
	assert_true(d.n == count);
	for (unsigned l = 0; l < lv.n; l++)
		frs_result_free(&r[l]);
	frs_levels_free(&lv.plan);
	return d;
}

/* Records of k doubles, sorted (the same set in another order compares
 * equal). */
static int rec_k;
static inline int rec_cmp(const void *a, const void *b)
{
	const double *p = a, *q = b;

	for (int i = 0; i < rec_k; i++)
		if (p[i] != q[i])
			return p[i] < q[i] ? -1 : 1;
	return 0;
}

static inline double *sort_recs(const double *rec, size_t n, size_t k)
{
	double *s = malloc((n ? n : 1) * k * sizeof *s);

	assert_non_null(s);
	memcpy(s, rec, n * k * sizeof *s);
	rec_k = (int)k;
	qsort(s, n, k * sizeof *s, rec_cmp);
	return s;
}

/*
 * frs_draw_progressive of s, made from map with the options o (NULL: the
 * defaults), against the oracle and against frs-sample -m MATRIX ARGS
 * with the same counts, seed and --pdf: the same records, bit for bit.
 */
static inline void compare(const frs_sampler *s, const struct frs_imap *map,
    const struct frs_options *o, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int pdf, const char *args)
{
	const char *out = tu_path("frs.pts");
	struct frs_options dflt;
	struct drawn d, want;
	double *rec, *ref;
	size_t k = 2 + (size_t)pdf + (nsteps > 1);
	int in_order;

	o = o != NULL ? o : (frs_options_init(&dflt), &dflt);
	frs_sample_prog(MATRIX, args, steps, nsteps, seed, pdf, out);
	d = draw(s, steps, nsteps, seed, pdf);
	rec = records(&d, pdf, nsteps > 1);
	want = oracle_draw(map, o, steps, nsteps, seed, &in_order);
	ref = records(&want, pdf, nsteps > 1);
	if (want.n != d.n)
		print_error("%s: the API made %zu samples, the oracle %zu\n", args,
		    d.n, want.n);
	assert_int_equal(d.n, want.n);
	if (in_order) {
		assert_memory_equal(rec, ref, d.n * k * sizeof *rec);
	} else {
		double *a = sort_recs(rec, d.n, k), *b = sort_recs(ref, d.n, k);
		assert_memory_equal(a, b, d.n * k * sizeof *rec);
		free(a);
		free(b);
	}
	same_as_file(out, rec, d.n, (unsigned)pdf + (nsteps > 1));
	free(ref);
	free(rec);
	drawn_free(&want);
	drawn_free(&d);
}

static inline frs_sampler *sampler_f64(const frs_mask *mk,
    const struct frs_imap *m, const struct frs_options *opt)
{
	frs_sampler *s = NULL;
	frs_error e;

	if (frs_sampler_new_f64(&s, mk, m->v, m->w, m->h, 0, opt, &e) !=
	    FRS_OK) {
		print_error("frs_sampler_new_f64: %s\n", e.message);
		fail();
	}
	return s;
}

/* The map as single-channel float EXR: its values as frs_map_load and
 * frs-sample read them alike. */
static inline const char *write_exr(const char *name, const struct frs_imap *m)
{
	const char *path = tu_path(name);
	FILE *fp = tu_create(path);

	assert_int_equal(imap_write_exr(fp, path, m), 0);
	tu_close(fp);
	return path;
}

/* ---- error codes ----------------------------------------------------- */

/* CALL, which uses E, returns CODE twice: with an frs_error (whose code
 * matches, with a message) and with err NULL. */
#define EXPECT(code, call) do { \
	for (int pass_ = 0; pass_ < 2; pass_++) { \
		frs_error e_ = { FRS_E_CALLBACK, "untouched" }; \
		frs_error *E = pass_ ? NULL : &e_; \
		int rc_ = (call); \
		expect_code(__FILE__, __LINE__, #call, rc_, (code), E); \
	} \
} while (0)

static inline void expect_code(const char *file, int line, const char *what,
    int rc, int code, const frs_error *e)
{
	if (rc != code) {
		print_error("%s: %s, expected %s (%s)\n", what, frs_code_name(rc),
		    frs_code_name(code), e ? e->message : "err NULL");
		_fail(file, line);
	}
	if (e != NULL && (int)e->code != code) {
		print_error("%s: err->code %s, returned %s\n", what,
		    frs_code_name((int)e->code), frs_code_name(rc));
		_fail(file, line);
	}
	if (e != NULL && code != FRS_OK && e->message[0] == '\0') {
		print_error("%s: %s without a message\n", what,
		    frs_code_name(code));
		_fail(file, line);
	}
	if (e != NULL && code == FRS_OK && e->message[0] != '\0') {
		print_error("%s: FRS_OK with the message '%s'\n", what,
		    e->message);
		_fail(file, line);
	}
}

/* Points (x, y) in increasing order. */
static inline int pair_cmp(const void *a, const void *b)
{
	const double *p = a, *q = b;

	return p[0] < q[0] ? -1 : p[0] > q[0] ? 1 : p[1] < q[1] ? -1 :
	    p[1] > q[1];
}

/* ---- the group's setup and teardown (every program's main) ---------- */

static inline int setup(void **state)
{
	frs_error e;

	(void)state;
	if (frs_mask_load(&mask, MATRIX, &e) != FRS_OK) {
		fprintf(stderr, "%s: %s\n", MATRIX, e.message);
		return -1;
	}
	if (frd_read(MATRIX, &mat) < 0)
		return -1;
	return imap_load("blob", 0, 0, 0, &blob);
}

static inline int teardown(void **state)
{
	frs_mask_free(mask);
	while (nprepared > 0)
		frs_prep_free(&prepared[--nprepared].p);
	frd_free(&mat);
	frd_free(&mat3);
	imap_free(&blob);
	return tu_teardown(state);
}

#endif
