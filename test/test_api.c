/*
 * The public API (src/lib/frs.h) against its contract: the samples of
 * the library's stages run here without api.c (frs_setup, frs_sample,
 * frs_point; frs3_*), and the same as the programs frs-sample and
 * hsw-sample for the same map, seed and options, bit for bit; every error
 * code that bad arguments reach, with and without an frs_error; one
 * sampler used by several threads at once.
 * The programs come from $BIN (test/run.sh exports it); the current
 * directory is the source tree.
 */
#include "testutil.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>

#include "frs.h"
#include "api/api.h"
#include "formats/frdio.h"
#include "maps/imap.h"
#include "formats/ptsio.h"
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

static const char *bindir(void)
{
	const char *b = getenv("BIN");

	return b != NULL && *b ? b : "bin";
}

/* Run "$BIN/CMD" through the shell; it must succeed. */
static void prog(const char *fmt, ...) FRS_PRINTF(1, 2);
static void prog(const char *fmt, ...)
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
static int quiet_begin(void)
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

static void quiet_end(int saved, const char *what)
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
static void same_as_file(const char *path, const double *rec, size_t n,
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

static void drawn_free(struct drawn *d)
{
	free(d->xy);
	free(d->pdf);
	free(d->step);
	memset(d, 0, sizeof *d);
}

/* frs_draw_progressive, sized by a first call with no room (which must
 * say FRS_E_BUFFER and the count). */
static struct drawn draw(const frs_sampler *s, const uint64_t *steps,
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
static double *records(const struct drawn *d, int pdf, int steps)
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

/* "1000,3000" for --progressive. */
static const char *step_list(const uint64_t *steps, unsigned nsteps)
{
	static char buf[512];
	size_t len = 0;

	for (unsigned k = 0; k < nsteps; k++)
		len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%llu",
		    k ? "," : "", (unsigned long long)steps[k]);
	return buf;
}

/* frs-sample -m matrix ARGS with the counts, seed and --pdf, into out. */
static void frs_sample_prog(const char *matrix, const char *args,
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
static enum frs_impl algo_of(enum frs_algorithm a)
{
	return a == FRS_ALG_NAIVE ? FRS_NAIVE : a == FRS_ALG_STACK ? FRS_STACK :
	    a == FRS_ALG_LEVEL1 ? FRS_LEVEL1 : a == FRS_ALG_LEVEL2 ? FRS_LEVEL2 :
	    FRS_SORTED;
}

static enum frs_rule rule_of(const struct frs_options *o)
{
	return o->rule == FRS_RULE_THESIS ? FRS_THESIS : FRS_UNBIASED;
}

static enum frs_place jitter_of(const struct frs_options *o)
{
	return o->jitter == FRS_JIT_HALTON ? FRS_PLACE_HALTON :
	    o->jitter == FRS_JIT_RANDOM ? FRS_PLACE_RANDOM : FRS_PLACE_CENTRE;
}

static enum frs_tiling tiling_of(const struct frs_options *o,
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

static const struct frs_prep *oracle_prep(int minmap, uint32_t b)
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
static unsigned oracle_top(uint32_t ns, const uint32_t *side,
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
static void oracle_levels_of(const struct frs_imap *map,
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

static void oracle_levels(const struct frs_imap *map,
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

static int naive_count(void *ctx, double tau, uint64_t *count)
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
static void oracle_setup(const struct frs_imap *map,
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
static struct drawn oracle_draw(const struct frs_imap *map,
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
static int rec_cmp(const void *a, const void *b)
{
	const double *p = a, *q = b;

	for (int i = 0; i < rec_k; i++)
		if (p[i] != q[i])
			return p[i] < q[i] ? -1 : 1;
	return 0;
}

static double *sort_recs(const double *rec, size_t n, size_t k)
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
static void compare(const frs_sampler *s, const struct frs_imap *map,
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

static frs_sampler *sampler_f64(const frs_mask *mk, const struct frs_imap *m,
    const struct frs_options *opt)
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
static const char *write_exr(const char *name, const struct frs_imap *m)
{
	const char *path = tu_path(name);
	FILE *fp = tu_create(path);

	assert_int_equal(imap_write_exr(fp, path, m), 0);
	tu_close(fp);
	return path;
}

/* ---- the same samples as frs-sample ------------------------------------ */

static void test_const_map(void **state)
{
	frs_sampler *s;
	struct frs_imap one;
	uint64_t n = 5000;

	(void)state;
	/* No map: importance 1 everywhere. */
	assert_int_equal(imap_alloc(&one, 128, 128), 0);
	for (size_t i = 0; i < (size_t)128 * 128; i++)
		one.v[i] = 1.0;
	assert_int_equal(frs_sampler_new(&s, mask, NULL, 128, 128, 0, NULL,
	    NULL), FRS_OK);
	compare(s, &one, NULL, &n, 1, 7, 0, "-i const");
	compare(s, &one, NULL, &n, 1, 7, 1, "-i const");
	frs_sampler_free(s);
	imap_free(&one);
}

static void test_blob_defaults(void **state)
{
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	uint64_t n[] = { 5000, 1, 100000 };

	(void)state;
	compare(s, &blob, NULL, &n[0], 1, 7, 0, "-i blob");
	compare(s, &blob, NULL, &n[0], 1, 1, 0, "-i blob");
	compare(s, &blob, NULL, &n[1], 1, 3, 1, "-i blob");
	compare(s, &blob, NULL, &n[2], 1, 9, 1, "-i blob");
	frs_sampler_free(s);
}

/* Each option as its frs-sample flag. */
static void test_options(void **state)
{
	static const struct {
		double sigma;
		enum frs_algorithm a;
		enum frs_jitter_mode j;
		enum frs_rule_mode r;
		int pdf;
		const char *args;
	} c[] = {
		{ 8, FRS_ALG_SORTED, FRS_JIT_RANDOM, FRS_RULE_UNBIASED, 1,
		    "--jitter random" },
		{ 8, FRS_ALG_SORTED, FRS_JIT_HALTON, FRS_RULE_UNBIASED, 0,
		    "--jitter halton" },
		{ 8, FRS_ALG_SORTED, FRS_JIT_NONE, FRS_RULE_THESIS, 1,
		    "--threshold thesis" },
		{ 4, FRS_ALG_SORTED, FRS_JIT_NONE, FRS_RULE_UNBIASED, 0,
		    "--sigma 4" },
		{ 13.5, FRS_ALG_LEVEL2, FRS_JIT_RANDOM, FRS_RULE_THESIS, 1,
		    "--sigma 13.5 -a level2 --jitter random --threshold thesis" },
		{ 8, FRS_ALG_NAIVE, FRS_JIT_NONE, FRS_RULE_UNBIASED, 0,
		    "-a naive" },
		{ 8, FRS_ALG_STACK, FRS_JIT_NONE, FRS_RULE_UNBIASED, 0,
		    "-a stack" },
		{ 8, FRS_ALG_LEVEL1, FRS_JIT_HALTON, FRS_RULE_UNBIASED, 0,
		    "-a level1 --jitter halton" },
		{ 8, FRS_ALG_LEVEL2, FRS_JIT_NONE, FRS_RULE_UNBIASED, 1,
		    "-a level2" },
	};
	uint64_t n = 3000;
	char args[256];

	(void)state;
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		struct frs_options o;
		frs_sampler *s;
		frs_options_init(&o);
		o.sigma = c[i].sigma;
		o.algorithm = c[i].a;
		o.jitter = c[i].j;
		o.rule = c[i].r;
		s = sampler_f64(mask, &blob, &o);
		/* Any thread count in the program: the same points. */
		snprintf(args, sizeof args, "-i blob %s -j %d", c[i].args,
		    1 + (int)(i % 2));
		compare(s, &blob, &o, &n, 1, 11 + i, c[i].pdf, args);
		frs_sampler_free(s);
	}
}

/* The thesis's threshold rule where it matters.  At n = 3000 the window
 * is the matrix once and no element sits at floor(T), so the two rules
 * give the same set; at 100000 the thesis's window (plain tiles) tiles it
 * 16 times and some do: there the thesis rule passes them all, the
 * unbiased rule by a coin.  (The levels, the default, through compare.) */
static void test_thesis_rule(void **state)
{
	uint64_t n = 100000;
	struct frs_options o;
	frs_sampler *thesis, *unbiased;
	struct drawn t, u;

	(void)state;
	frs_options_init(&o);
	o.rule = FRS_RULE_THESIS;
	thesis = sampler_f64(mask, &blob, &o);
	compare(thesis, &blob, &o, &n, 1, 5, 0, "-i blob --threshold thesis");
	frs_sampler_free(thesis);
	o.tiling = FRS_TILING_PLAIN;
	thesis = sampler_f64(mask, &blob, &o);
	o.rule = FRS_RULE_UNBIASED;
	unbiased = sampler_f64(mask, &blob, &o);
	t = draw(thesis, &n, 1, 5, 0);
	u = draw(unbiased, &n, 1, 5, 0);
	/* v < T passes every element v == floor(T): never fewer samples. */
	assert_true(t.n > u.n);
	drawn_free(&t);
	drawn_free(&u);
	frs_sampler_free(thesis);
	frs_sampler_free(unbiased);
}

static void test_progressive(void **state)
{
	static const uint64_t steps[] = { 1000, 3000, 5000 };
	static const uint64_t one[] = { 64, 20000 };
	struct frs_options o;
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	struct drawn d;

	(void)state;
	compare(s, &blob, NULL, steps, 3, 7, 1, "-i blob");
	compare(s, &blob, NULL, steps, 3, 8, 0, "-i blob");
	/* The steps come in order. */
	d = draw(s, steps, 3, 7, 0);
	for (size_t i = 1; i < d.n; i++)
		assert_true(d.step[i] >= d.step[i - 1]);
	assert_true(d.step[d.n - 1] <= 2);
	drawn_free(&d);
	frs_sampler_free(s);
	frs_options_init(&o);
	o.jitter = FRS_JIT_RANDOM;
	o.algorithm = FRS_ALG_STACK;
	s = sampler_f64(mask, &blob, &o);
	compare(s, &blob, &o, one, 2, 2, 1,
	    "-i blob -a stack --jitter random");
	frs_sampler_free(s);
}

/* A float map read from an EXR file by frs_map_load, and by frs-sample
 * from the same file. */
static void test_float_map(void **state)
{
	const char *path = write_exr("blob.exr", &blob);
	struct frs_imap f64, r64;
	frs_sampler *s;
	float *map;
	uint32_t w = 0, h = 0;
	uint64_t n = 6000;
	frs_error e;

	(void)state;
	assert_int_equal(frs_map_load(path, 0, 0, &map, &w, &h, &e), FRS_OK);
	assert_int_equal(w, 128);
	assert_int_equal(h, 128);
	assert_int_equal(imap_load(path, 0, 0, 0, &f64), 0);
	for (size_t i = 0; i < (size_t)w * h; i++)
		assert_true((double)map[i] == f64.v[i]);
	assert_int_equal(frs_sampler_new(&s, mask, map, w, h, 0, NULL, &e),
	    FRS_OK);
	{
		char args[600];
		snprintf(args, sizeof args, "-i %s", path);
		compare(s, &f64, NULL, &n, 1, 4, 1, args);
	}
	frs_sampler_free(s);
	frs_map_free(map);
	/* Resampled on loading: the values frs-sample would use, rounded. */
	assert_int_equal(frs_map_load(path, 48, 20, &map, &w, &h, NULL),
	    FRS_OK);
	assert_int_equal(w, 48);
	assert_int_equal(h, 20);
	assert_int_equal(imap_load(path, 48, 20, 0, &r64), 0);
	for (size_t i = 0; i < (size_t)w * h; i++)
		assert_true(map[i] == (float)r64.v[i]);
	frs_map_free(map);
	/* A spec, as frs-sample evaluates it, rounded to float. */
	assert_int_equal(frs_map_load("blob", 0, 0, &map, &w, &h, NULL),
	    FRS_OK);
	assert_int_equal(w, 128);
	for (size_t i = 0; i < (size_t)w * h; i++)
		assert_true(map[i] == (float)blob.v[i]);
	frs_map_free(map);
	imap_free(&r64);
	imap_free(&f64);
}

/* A row stride: the values between the rows are never read (NaN there
 * would be FRS_E_MAP). */
static void test_stride(void **state)
{
	struct frs_imap m;
	size_t stride = 128;
	double *wide;
	float *wf, *cf;
	frs_sampler *s, *t;
	uint64_t n = 4000;
	struct drawn a, b;

	(void)state;
	assert_int_equal(imap_load("blob", 100, 60, 0, &m), 0);
	wide = malloc(stride * m.h * sizeof *wide);
	wf = malloc(stride * m.h * sizeof *wf);
	cf = malloc((size_t)m.w * m.h * sizeof *cf);
	assert_non_null(wide);
	assert_non_null(wf);
	assert_non_null(cf);
	for (size_t i = 0; i < stride * m.h; i++) {
		wide[i] = NAN;
		wf[i] = NAN;
	}
	for (uint32_t y = 0; y < m.h; y++)
		for (uint32_t x = 0; x < m.w; x++) {
			wide[y * stride + x] = m.v[(size_t)y * m.w + x];
			wf[y * stride + x] = (float)m.v[(size_t)y * m.w + x];
			cf[(size_t)y * m.w + x] = wf[y * stride + x];
		}
	assert_int_equal(frs_sampler_new_f64(&s, mask, wide, m.w, m.h, stride,
	    NULL, NULL), FRS_OK);
	compare(s, &m, NULL, &n, 1, 6, 1, "-i blob -s 100x60");
	frs_sampler_free(s);
	assert_int_equal(frs_sampler_new(&s, mask, wf, m.w, m.h, stride,
	    NULL, NULL), FRS_OK);
	assert_int_equal(frs_sampler_new(&t, mask, cf, m.w, m.h, m.w, NULL,
	    NULL), FRS_OK);
	/* The map is copied: changing it afterwards changes nothing. */
	for (size_t i = 0; i < (size_t)m.w * m.h; i++)
		cf[i] = -1.0f;
	a = draw(s, &n, 1, 6, 1);
	b = draw(t, &n, 1, 6, 1);
	assert_int_equal(a.n, b.n);
	assert_memory_equal(a.xy, b.xy, 2 * a.n * sizeof *a.xy);
	assert_memory_equal(a.pdf, b.pdf, a.n * sizeof *a.pdf);
	drawn_free(&a);
	drawn_free(&b);
	frs_sampler_free(s);
	frs_sampler_free(t);
	free(wide);
	free(wf);
	free(cf);
	imap_free(&m);
}

/* options.threads: the same bytes for 0, 1, 2 and 3 threads. */
static void test_threads_option(void **state)
{
	struct drawn d[4];
	uint64_t n = 30000;

	(void)state;
	for (int t = 0; t < 4; t++) {
		struct frs_options o;
		frs_sampler *s;
		frs_options_init(&o);
		o.threads = t;
		o.jitter = FRS_JIT_RANDOM;
		s = sampler_f64(mask, &blob, &o);
		d[t] = draw(s, &n, 1, 5, 1);
		frs_sampler_free(s);
	}
	for (int t = 1; t < 4; t++) {
		assert_int_equal(d[t].n, d[0].n);
		assert_memory_equal(d[t].xy, d[0].xy, 2 * d[0].n * sizeof(double));
		assert_memory_equal(d[t].pdf, d[0].pdf, d[0].n * sizeof(double));
	}
	for (int t = 0; t < 4; t++)
		drawn_free(&d[t]);
}

/* frs_draw_each's batches, gathered. */
struct wave_gather {
	double *xy, *pdf;
	size_t n, cap;
};

static int wave_gather(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct wave_gather *g = ctx;

	assert_null(step);
	if (g->cap == 0) {
		g->cap = (size_t)total;
		g->xy = malloc(2 * g->cap * sizeof *g->xy);
		g->pdf = malloc(g->cap * sizeof *g->pdf);
		assert_non_null(g->xy);
		assert_non_null(g->pdf);
	}
	assert_true(g->n + k <= g->cap && total == g->cap);
	memcpy(g->xy + 2 * g->n, xy, 2 * k * sizeof *xy);
	memcpy(g->pdf + g->n, pdf, k * sizeof *pdf);
	g->n += k;
	return 0;
}

/* The records (x, y, pdf) of d in increasing order. */
static double *sorted_records(const struct drawn *d)
{
	double *r = records(d, 1, 0), *q = sort_recs(r, d->n, 3);

	free(r);
	return q;
}

/* Sorted with one step goes from the thresholding straight to the
 * caller (frs_draw) or in waves to the callback (frs_draw_each): the
 * samples of Naive through the store of the whole run (Sorted gives a
 * block's samples in value order, Naive in row order), and the same
 * bytes for 1 and 3 threads and waves of 1 to 2^20 samples (many chunks
 * to a wave, a chunk to a wave, chunks larger than a wave). */
static void test_direct_path(void **state)
{
	uint64_t n = 20000, waves[] = { (uint64_t)1 << 20, 1, 700, 5000 };
	struct frs_options o;
	struct drawn ref, first = { 0, NULL, NULL, NULL };
	frs_sampler *s;
	double *a, *b;

	(void)state;
	frs_options_init(&o);
	o.algorithm = FRS_ALG_NAIVE;
	o.jitter = FRS_JIT_RANDOM;
	s = sampler_f64(mask, &blob, &o);
	ref = draw(s, &n, 1, 3, 1);
	frs_sampler_free(s);
	o.algorithm = FRS_ALG_SORTED;
	for (int t = 1; t <= 3; t += 2)
		for (size_t w = 0; w < sizeof waves / sizeof *waves; w++) {
			struct wave_gather g = { NULL, NULL, 0, 0 };
			struct drawn d;
			frs_error e;
			o.threads = t;
			api_wave = waves[w];
			s = sampler_f64(mask, &blob, &o);
			d = draw(s, &n, 1, 3, 1);
			assert_int_equal(frs_draw_each(s, &n, 1, 3, 1, wave_gather,
			    &g, &e), FRS_OK);
			frs_sampler_free(s);
			if (first.n == 0)
				first = d;
			assert_int_equal(d.n, ref.n);
			assert_int_equal(g.n, ref.n);
			assert_memory_equal(d.xy, first.xy, 2 * ref.n * sizeof(double));
			assert_memory_equal(d.pdf, first.pdf, ref.n * sizeof(double));
			assert_memory_equal(g.xy, first.xy, 2 * ref.n * sizeof(double));
			assert_memory_equal(g.pdf, first.pdf, ref.n * sizeof(double));
			free(g.xy);
			free(g.pdf);
			if (d.xy != first.xy)
				drawn_free(&d);
		}
	api_wave = (uint64_t)1 << 20;
	a = sorted_records(&ref);
	b = sorted_records(&first);
	assert_memory_equal(a, b, 3 * ref.n * sizeof *a);
	free(a);
	free(b);
	drawn_free(&first);
	drawn_free(&ref);
}

/* s's draw of steps: a fresh mask's, whose lists are made for it. */
static void same_as_fresh(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, const struct frs_options *o)
{
	frs_mask *fresh;
	frs_sampler *f;
	struct drawn d, r;

	assert_int_equal(frs_mask_load(&fresh, MATRIX, NULL), FRS_OK);
	f = sampler_f64(fresh, &blob, o);
	d = draw(s, steps, nsteps, 5, 1);
	r = draw(f, steps, nsteps, 5, 1);
	assert_int_equal(d.n, r.n);
	assert_memory_equal(d.xy, r.xy, 2 * d.n * sizeof(double));
	drawn_free(&d);
	drawn_free(&r);
	frs_sampler_free(f);
	frs_mask_free(fresh);
}

/* One sampler's draws of growing and shrinking counts: each as a fresh
 * sampler's (its lists, made for the values the first draw reaches,
 * grow to the complete ones when a later draw needs more), and the
 * progressive draw nested in them. */
static void test_lists_grow(void **state)
{
	uint64_t ns[] = { 50, 3000, 200, 60000, 50 }, steps[2] = { 50, 3000 };
	struct frs_options o;
	frs_sampler *s;
	frs_mask *mk;

	(void)state;
	frs_options_init(&o);
	assert_int_equal(frs_mask_load(&mk, MATRIX, NULL), FRS_OK);
	s = sampler_f64(mk, &blob, &o);
	for (size_t i = 0; i < sizeof ns / sizeof *ns; i++)
		same_as_fresh(s, &ns[i], 1, &o);
	same_as_fresh(s, steps, 2, &o);
	frs_sampler_free(s);
	frs_mask_free(mk);
}

/* frs_count: frs-sample --count-only, and what frs_draw makes. */
static void test_count(void **state)
{
	const char *out = tu_path("count.txt");
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	uint64_t c = 0, n = 5000;
	unsigned long long pc = 0;
	struct drawn d;
	FILE *fp;

	(void)state;
	prog("frs-sample -q -m %s -i blob -n 5000 -S 7 --count-only -o %s",
	    MATRIX, out);
	fp = fopen(out, "r");
	assert_non_null(fp);
	assert_int_equal(fscanf(fp, "%llu", &pc), 1);
	fclose(fp);
	assert_int_equal(frs_count(s, n, 7, &c, NULL), FRS_OK);
	assert_int_equal(c, pc);
	d = draw(s, &n, 1, 7, 0);
	assert_int_equal(d.n, c);
	drawn_free(&d);
	/* "About n": within a few per cent here. */
	assert_true(c > 4500 && c < 5500);
	frs_sampler_free(s);
}

/* frs_sampler_info: the setup frs-sample -v prints. */
static void test_info(void **state)
{
	const char *err = tu_path("v.txt");
	frs_sampler *s = sampler_f64(mask, &blob, NULL);
	struct frs_info in;
	char line[1024];
	unsigned ns = 0;
	unsigned long long ww, wh, ox, oy;
	double tau = 0;
	int found = 0;
	FILE *fp;

	(void)state;
	prog("frs-sample -m %s -i blob -n 5000 -S 7 -v -o /dev/null 2>%s",
	    MATRIX, err);
	fp = fopen(err, "r");
	assert_non_null(fp);
	while (fgets(line, sizeof line, fp) != NULL) {
		const char *p = strstr(line, "n_s ");
		/* the first: level 0's (the thesis's) window */
		if (!found && p != NULL && sscanf(p, "n_s %u, window %llux%llu at "
		    "(%llu, %llu), tau %lg", &ns, &ww, &wh, &ox, &oy, &tau) == 6)
			found = 1;
	}
	fclose(fp);
	if (!found) {
		print_error("no 'n_s ..., window ..., tau' line in frs-sample "
		    "-v\n");
		fail();
	}
	assert_int_equal(frs_sampler_info(s, 5000, 7, &in, NULL), FRS_OK);
	assert_int_equal(in.ns, ns);
	assert_int_equal(in.window_w, ww);
	assert_int_equal(in.window_h, wh);
	assert_int_equal(in.offset_x, ox);
	assert_int_equal(in.offset_y, oy);
	assert_near(in.tau, tau, 1e-8 * fabs(tau));
	{
		struct frs_imap_stats st;
		imap_stats(&blob, &st);
		assert_near(in.mean, st.mean, 1e-12 * st.mean);
		assert_true(in.max == st.max);
	}
	assert_true(in.unique > 0);
	frs_sampler_free(s);
}

/* ---- masks ------------------------------------------------------------ */

/* frs_mask_wrap of the values of MATRIX: the samples of the loaded one. */
static void test_wrap(void **state)
{
	static const uint32_t v4[16] = { 0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1,
	    9, 15, 7, 13, 5 };
	struct frs_matrix m;
	frs_mask *mk;
	frs_sampler *s, *t;
	uint64_t n = 5000;
	uint32_t w = 0, h = 0;
	struct drawn a, b;

	(void)state;
	assert_int_equal(frd_read(MATRIX, &m), 0);
	assert_int_equal(frs_mask_wrap(&mk, m.v, m.w, m.h, NULL), FRS_OK);
	frs_mask_size(mk, &w, &h);
	assert_int_equal(w, 2048);
	assert_int_equal(h, 2048);
	assert_null(frs_mask_note(mk));
	s = sampler_f64(mk, &blob, NULL);
	t = sampler_f64(mask, &blob, NULL);
	a = draw(s, &n, 1, 3, 1);
	b = draw(t, &n, 1, 3, 1);
	assert_int_equal(a.n, b.n);
	assert_memory_equal(a.xy, b.xy, 2 * a.n * sizeof *a.xy);
	drawn_free(&a);
	drawn_free(&b);
	frs_sampler_free(s);
	frs_sampler_free(t);
	frs_mask_free(mk);
	frd_free(&m);
	/* A 4x4 one samples too. */
	assert_int_equal(frs_mask_wrap(&mk, v4, 4, 4, NULL), FRS_OK);
	frs_mask_size(mk, &w, &h);
	assert_int_equal(w, 4);
	assert_int_equal(h, 4);
	assert_int_equal(frs_sampler_new(&s, mk, NULL, 8, 8, 0, NULL, NULL),
	    FRS_OK);
	a = draw(s, &n, 1, 1, 0);
	for (size_t i = 0; i < 2 * a.n; i++)
		assert_true(a.xy[i] >= 0.0 && a.xy[i] < 1.0);
	drawn_free(&a);
	frs_sampler_free(s);
	frs_mask_free(mk);
}

/* A random 64x64 matrix (a permutation) in path. */
static void write_frd(const char *path, uint64_t seed)
{
	struct frs_matrix m;
	FILE *fp;

	assert_int_equal(frd_alloc(&m, 2, 64, 64, 1, "test"), 0);
	for (uint32_t i = 0; i < m.n; i++)
		m.v[i] = i;
	for (uint32_t i = (uint32_t)m.n - 1; i > 0; i--) {
		uint32_t j = (uint32_t)(frs_rand64(seed, FRS_STREAM_TEST, i) %
		    (i + 1)), t = m.v[i];
		m.v[i] = m.v[j];
		m.v[j] = t;
	}
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(frd_write(fp, path, &m), 0);
	assert_int_equal(fclose(fp), 0);
	frd_free(&m);
}

/* Samples of a mask file against frs-sample -m with the same file. */
static void compare_mask(const char *path, const char *algo,
    enum frs_algorithm a)
{
	const char *out = tu_path("m.pts");
	struct frs_options o;
	frs_mask *mk;
	frs_sampler *s;
	uint64_t n = 3000;
	struct drawn d;
	double *rec;
	frs_error e;

	if (frs_mask_load(&mk, path, &e) != FRS_OK) {
		print_error("frs_mask_load %s: %s %s\n", path,
		    frs_code_name((int)e.code), e.message);
		fail();
	}
	frs_options_init(&o);
	o.algorithm = a;
	s = sampler_f64(mk, &blob, &o);
	prog("frs-sample -q -m %s -i blob -a %s -n 3000 -S 2 -o %s", path, algo,
	    out);
	d = draw(s, &n, 1, 2, 0);
	rec = records(&d, 0, 0);
	same_as_file(out, rec, d.n, 0);
	free(rec);
	drawn_free(&d);
	frs_sampler_free(s);
	frs_mask_free(mk);
}

/* .frp files, and a .frd with a good, a stale and a damaged twin. */
static void test_prepared(void **state)
{
	char frd[256], frp[256], other[256], alone[256];
	frs_mask *mk;
	frs_error e;
	const char *note;

	(void)state;
	/* Copies: tu_path's buffers are reused. */
	snprintf(frd, sizeof frd, "%s", tu_path("M.frd"));
	snprintf(frp, sizeof frp, "%s", tu_path("M.frp"));
	snprintf(other, sizeof other, "%s", tu_path("O.frd"));
	snprintf(alone, sizeof alone, "%s", tu_path("P.frp"));
	write_frd(frd, 1);
	write_frd(other, 2);
	prog("frd-prep -a all %s -o %s", frd, alone);
	compare_mask(alone, "sorted", FRS_ALG_SORTED);
	compare_mask(alone, "level2", FRS_ALG_LEVEL2);
	compare_mask(frd, "stack", FRS_ALG_STACK);
	/* A good twin: used, no note. */
	prog("frd-prep -a all %s -o %s", frd, frp);
	assert_int_equal(frs_mask_load(&mk, frd, &e), FRS_OK);
	assert_null(frs_mask_note(mk));
	frs_mask_free(mk);
	compare_mask(frd, "sorted", FRS_ALG_SORTED);
	/* Stale: made from another matrix. */
	prog("frd-prep -a all %s -o %s", other, frp);
	assert_int_equal(frs_mask_load(&mk, frd, &e), FRS_OK);
	note = frs_mask_note(mk);
	assert_non_null(note);
	assert_non_null(strstr(note, "stale"));
	frs_mask_free(mk);
	compare_mask(frd, "level1", FRS_ALG_LEVEL1);
	/* Damaged: the right header, the matrix cut short (40 bytes of
	 * header, 64 x 64 values of 4).  The note may come when the damage
	 * is met, at the first draw. */
	prog("frd-prep -a all %s -o %s && truncate -s %d %s", frd, frp,
	    40 + 2 * 64 * 64, frp);
	compare_mask(frd, "sorted", FRS_ALG_SORTED);
	assert_int_equal(frs_mask_load(&mk, frd, &e), FRS_OK);
	{
		frs_sampler *s;
		uint64_t c;
		int q = quiet_begin();
		assert_int_equal(frs_sampler_new(&s, mk, NULL, 64, 64, 0, NULL,
		    NULL), FRS_OK);
		assert_int_equal(frs_count(s, 1000, 1, &c, NULL), FRS_OK);
		frs_sampler_free(s);
		quiet_end(q, "a mask with a damaged twin");
	}
	note = frs_mask_note(mk);
	if (note == NULL) {
		print_error("a damaged twin, ignored without a note\n");
		fail();
	}
	frs_mask_free(mk);
	/* Loaded directly, the damaged .frp is an error. */
	assert_int_equal(frs_mask_load(&mk, frp, &e), FRS_E_FORMAT);
	assert_null(mk);
}

/* ---- errors ----------------------------------------------------------- */

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

static void expect_code(const char *file, int line, const char *what,
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

static void test_code_names(void **state)
{
	static const char *const names[] = { "FRS_OK", "FRS_E_ARG",
	    "FRS_E_MAP", "FRS_E_BUFFER", "FRS_E_NOMEM", "FRS_E_IO",
	    "FRS_E_FORMAT", "FRS_E_LIMIT", "FRS_E_CALLBACK" };
	const char *v = frs_library_version();
	int a, b, c;

	(void)state;
	assert_int_equal(FRS_OK, 0);
	assert_int_equal(FRS_E_CALLBACK, 8);
	for (int i = 0; i <= FRS_E_CALLBACK; i++)
		assert_string_equal(frs_code_name(i), names[i]);
	/* Not a code: a name all the same, none of the above. */
	for (int i = -1; i < 200; i += 50) {
		const char *n = frs_code_name(i > 8 ? i : -1);
		assert_non_null(n);
		for (int k = 0; k <= FRS_E_CALLBACK; k++)
			assert_string_not_equal(n, names[k]);
	}
	assert_non_null(v);
	assert_int_equal(sscanf(v, "%d.%d.%d", &a, &b, &c), 3);
	assert_int_equal(FRS_API_VERSION_MAJOR, 2);
}

static void test_mask_errors(void **state)
{
	const char *junk = tu_path("junk.frd");
	static const uint32_t dup[16] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
	    12, 13, 14, 14 };
	static const uint32_t big[16] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
	    12, 13, 14, 16 };
	static const uint32_t v12[12] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,
	    11 };
	frs_mask *mk = NULL;

	(void)state;
	tu_write(junk, "this is no matrix at all\n", 25);
	EXPECT(FRS_E_ARG, frs_mask_load(NULL, MATRIX, E));
	EXPECT(FRS_E_ARG, frs_mask_load(&mk, NULL, E));
	EXPECT(FRS_E_IO, frs_mask_load(&mk, tu_path("missing.frd"), E));
	EXPECT(FRS_E_IO, frs_mask_load(&mk, tu_dir(), E));
	EXPECT(FRS_E_FORMAT, frs_mask_load(&mk, junk, E));
	EXPECT(FRS_E_FORMAT, frs_mask_load(&mk, "data/sunset.exr", E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(NULL, dup, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, NULL, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, dup, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, big, 4, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 4, 3, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 3, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 0, 4, E));
	EXPECT(FRS_E_ARG, frs_mask_wrap(&mk, v12, 4, 0, E));
	/* Nothing was made; freeing NULL is harmless. */
	frs_mask_free(NULL);
	frs_mask_size(NULL, NULL, NULL);
}

/* frs_default_matrix: FRS_MATRIX, then FRS_DATA alone, else the
 * directories of datadir.h (the source tree among them here). */
static void test_default_matrix(void **state)
{
	char path[4096], want[4200];
	frs_mask *mk = NULL;
	uint32_t w, h, d;
	frs_error e;

	(void)state;
	unsetenv("FRS_MATRIX");
	unsetenv("FRS_MATRIX3");
	setenv("FRS_DATA", "data", 1);
	assert_int_equal(frs_default_matrix(&mk, 2, path, sizeof path, &e),
	    FRS_OK);
	assert_string_equal(path, "data/default.frd");
	assert_string_equal(e.message, "");
	frs_mask_size(mk, &w, &h);
	assert_int_equal(w, 2048);
	assert_int_equal(h, 2048);
	assert_int_equal(frs_mask_dims(mk), 2);
	frs_mask_free(mk);
	assert_int_equal(frs_default_matrix(&mk, 3, NULL, 0, &e), FRS_OK);
	frs_mask_size3(mk, &w, &h, &d);
	assert_int_equal(frs_mask_dims(mk), 3);
	assert_int_equal(d, 64);
	frs_mask_free(mk);
	/* Only the path. */
	EXPECT(FRS_OK, frs_default_matrix(NULL, 3, path, sizeof path, E));
	assert_string_equal(path, "data/default3.frd");
	/* The path does not fit: nothing loaded. */
	mk = (frs_mask *)1;
	EXPECT(FRS_E_BUFFER, frs_default_matrix(&mk, 2, path, 16, E));
	assert_null(mk);
	EXPECT(FRS_OK, frs_default_matrix(NULL, 2, path, 17, E));
	EXPECT(FRS_E_ARG, frs_default_matrix(&mk, 1, NULL, 0, E));
	EXPECT(FRS_E_ARG, frs_default_matrix(&mk, 4, NULL, 0, E));
	EXPECT(FRS_E_ARG, frs_default_matrix(&mk, 2, path, 0, E));
	/* FRS_DATA is the only place looked at. */
	setenv("FRS_DATA", tu_dir(), 1);
	EXPECT(FRS_E_IO, frs_default_matrix(&mk, 2, NULL, 0, E));
	assert_int_equal(frs_default_matrix(&mk, 2, path, sizeof path, &e),
	    FRS_E_IO);
	assert_null(mk);
	snprintf(want, sizeof want, "no default matrix (looked for "
	    "%s/default.frd; FRS_DATA is set)", tu_dir());
	assert_string_equal(e.message, want);
	assert_string_equal(path, "");
	/* FRS_MATRIX wins, as it is: its path, then the load's error. */
	setenv("FRS_MATRIX", tu_path("missing.frd"), 1);
	EXPECT(FRS_E_IO, frs_default_matrix(&mk, 2, path, sizeof path, E));
	assert_string_equal(path, tu_path("missing.frd"));
	EXPECT(FRS_OK, frs_default_matrix(NULL, 2, path, sizeof path, E));
	setenv("FRS_MATRIX3", "data/default3.frd", 1);
	assert_int_equal(frs_default_matrix(&mk, 3, NULL, 0, &e), FRS_OK);
	assert_int_equal(frs_mask_dims(mk), 3);
	frs_mask_free(mk);
	unsetenv("FRS_MATRIX");
	unsetenv("FRS_MATRIX3");
	/* An empty FRS_DATA is unset: found without it (the source tree). */
	setenv("FRS_DATA", "", 1);
	EXPECT(FRS_OK, frs_default_matrix(NULL, 2, path, sizeof path, E));
	assert_true(strlen(path) > 12 &&
	    strcmp(path + strlen(path) - 12, "/default.frd") == 0);
	unsetenv("FRS_DATA");
}

static void test_map_errors(void **state)
{
	const char *junk = tu_path("junk.png");
	float *map = NULL;
	uint32_t w, h;

	(void)state;
	tu_write(junk, "\x89PNG\r\n\x1a\n but no more", 21);
	EXPECT(FRS_E_ARG, frs_map_load(NULL, 0, 0, &map, &w, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 0, NULL, &w, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 0, &map, NULL, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 0, &map, &w, NULL, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 16, 0, &map, &w, &h, E));
	EXPECT(FRS_E_ARG, frs_map_load("blob", 0, 16, &map, &w, &h, E));
	EXPECT(FRS_E_IO, frs_map_load(tu_path("missing.exr"), 0, 0, &map, &w,
	    &h, E));
	EXPECT(FRS_E_FORMAT, frs_map_load(junk, 0, 0, &map, &w, &h, E));
	EXPECT(FRS_E_FORMAT, frs_map_load(MATRIX, 0, 0, &map, &w, &h, E));
	frs_map_free(NULL);
}

/* Maps whose values are refused: NaN, infinity, a negative value, all
 * zero; as float and as double. */
static void test_bad_maps(void **state)
{
	static const double bad[] = { NAN, INFINITY, -INFINITY, -1.0, 0.0 };
	double d[64];
	float f[64];
	frs_sampler *s = NULL;
	frs_hsw *hw = NULL;

	(void)state;
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
		for (int i = 0; i < 64; i++) {
			/* one bad pixel, or (for 0) all of them */
			d[i] = bad[k] == 0.0 || i == 37 ? bad[k] : 1.0;
			f[i] = (float)d[i];
		}
		EXPECT(FRS_E_MAP, frs_sampler_new_f64(&s, mask, d, 8, 8, 0, NULL,
		    E));
		EXPECT(FRS_E_MAP, frs_sampler_new(&s, mask, f, 8, 8, 0, NULL,
		    E));
		/* HSW: negative values count as zero, the rest is refused. */
		if (bad[k] == -1.0) {
			/* Not EXPECT: it calls twice, which would leak. */
			assert_int_equal(frs_hsw_new_f64(&hw, d, 8, 8, 0, NULL),
			    FRS_OK);
			frs_hsw_free(hw);
			assert_int_equal(frs_hsw_new(&hw, f, 8, 8, 0, NULL),
			    FRS_OK);
			frs_hsw_free(hw);
		} else {
			EXPECT(FRS_E_MAP, frs_hsw_new_f64(&hw, d, 8, 8, 0, E));
			EXPECT(FRS_E_MAP, frs_hsw_new(&hw, f, 8, 8, 0, E));
		}
	}
	/* Only negative and zero values: nothing to sample. */
	for (int i = 0; i < 64; i++)
		d[i] = i % 2 ? -1.0 : 0.0;
	EXPECT(FRS_E_MAP, frs_hsw_new_f64(&hw, d, 8, 8, 0, E));
	/* The map files: any code but FRS_OK; see the report for which. */
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
		struct frs_imap m;
		const char *path;
		float *map = NULL;
		uint32_t w, h;
		frs_error e;
		int rc, q;
		assert_int_equal(imap_alloc(&m, 8, 8), 0);
		for (int i = 0; i < 64; i++)
			m.v[i] = bad[k] == 0.0 || i == 37 ? bad[k] : 1.0;
		path = write_exr("bad.exr", &m);
		q = quiet_begin();
		rc = frs_map_load(path, 0, 0, &map, &w, &h, &e);
		quiet_end(q, "frs_map_load");
		if (bad[k] == -1.0 && rc == FRS_OK) {
			/* Clamped to zero, as frs-sample does. */
			for (int i = 0; i < 64; i++)
				assert_true(map[i] == (i == 37 ? 0.0f : 1.0f));
			frs_map_free(map);
		} else if (rc != FRS_E_MAP) {
			print_error("frs_map_load of a map with %g: %s\n", bad[k],
			    frs_code_name(rc));
			fail();
		} else {
			assert_null(map);
		}
		imap_free(&m);
	}
}

static frs_sampler *blob_sampler(void)
{
	return sampler_f64(mask, &blob, NULL);
}

static void test_sampler_errors(void **state)
{
	static const double one[16] = { 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
	    1, 1, 1 };
	frs_sampler *s = NULL;
	struct frs_options o;

	(void)state;
	EXPECT(FRS_E_ARG, frs_sampler_new(NULL, mask, NULL, 8, 8, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, NULL, NULL, 8, 8, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 0, 8, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 0, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(NULL, mask, one, 4, 4, 0, NULL,
	    E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, NULL, one, 4, 4, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 0, 4, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 4, 0, 0, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 4, 4, 3, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_new_f64(&s, mask, one, 8, 2, 7, NULL, E));
	/* A size beyond what a map may have. */
	EXPECT(FRS_E_LIMIT, frs_sampler_new(&s, mask, NULL, 1u << 20, 1u << 20,
	    0, NULL, E));
	/* Options. */
	{
		static const double sig[] = { -1.0, 0.5, NAN, -INFINITY,
		    INFINITY, 1025.0 };
		for (size_t i = 0; i < sizeof sig / sizeof sig[0]; i++) {
			frs_options_init(&o);
			o.sigma = sig[i];
			EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0,
			    &o, E));
		}
	}
	frs_options_init(&o);
	o.algorithm = (enum frs_algorithm)5;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	o.algorithm = (enum frs_algorithm)-1;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	frs_options_init(&o);
	o.jitter = (enum frs_jitter_mode)3;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	frs_options_init(&o);
	o.rule = (enum frs_rule_mode)3;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	frs_options_init(&o);
	o.threads = -1;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	frs_options_init(&o);
	o.tiling = (enum frs_tiling_mode)3;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	frs_options_init(&o);
	o.level_blur = -1.0;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	o.level_blur = 1e4 + 1;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	o.level_blur = NAN;
	EXPECT(FRS_E_ARG, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E));
	/* The defaults, and a good call clears err. */
	frs_options_init(&o);
	assert_true(o.sigma == 8.0);
	assert_int_equal(o.algorithm, FRS_ALG_SORTED);
	assert_int_equal(o.jitter, FRS_JIT_NONE);
	assert_int_equal(o.rule, FRS_RULE_UNBIASED);
	assert_int_equal(o.threads, 1);
	assert_int_equal(o.tiling, FRS_TILING_LEVELS);
	assert_int_equal(FRS_TILING_LEVELS, 0);
	assert_true(o.level_blur == 0.0);
	EXPECT(FRS_OK, frs_sampler_new(&s, mask, NULL, 8, 8, 0, &o, E) ==
	    FRS_OK ? (frs_sampler_free(s), FRS_OK) : FRS_E_ARG);
	frs_sampler_free(NULL);
}

static void test_draw_errors(void **state)
{
	frs_sampler *s = blob_sampler();
	static const uint64_t st_eq[] = { 500, 500 }, st_dn[] = { 900, 500 },
	    st_zero[] = { 0, 500 };
	uint64_t st17[17], c64;
	struct frs_info in;
	double xy[16];
	size_t c;
	uint32_t step[8];

	(void)state;
	for (int i = 0; i < 17; i++)
		st17[i] = 100 * (uint64_t)(i + 1);
	EXPECT(FRS_E_ARG, frs_draw(s, 100, 1, xy, NULL, 8, NULL, E));
	EXPECT(FRS_E_ARG, frs_draw(s, 100, 1, NULL, NULL, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw(s, 0, 1, xy, NULL, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_count(s, 100, 1, NULL, E));
	EXPECT(FRS_E_ARG, frs_count(s, 0, 1, &c64, E));
	EXPECT(FRS_E_ARG, frs_sampler_info(s, 100, 1, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_info(s, 0, 1, &in, E));
	/* Steps. */
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, NULL, 1, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st17, 0, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st17, 17, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_eq, 2, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_dn, 2, 1, xy, NULL, step,
	    8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_zero, 2, 1, xy, NULL,
	    step, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(s, st_eq, 2, 1, xy, NULL, step,
	    8, NULL, E));
	/* Sixteen steps are allowed (too many samples for 8 here). */
	EXPECT(FRS_E_BUFFER, frs_draw_progressive(s, st17, 16, 1, xy, NULL,
	    step, 8, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_each(s, st17, 17, 1, 0, NULL, NULL, E));
	frs_sampler_free(s);
}

/* Run call(s, n) in a child process that must return one of the codes
 * want0, want1 within secs seconds: a call that would run for hours
 * fails the test instead of hanging it.  No cmocka in the child. */
static void in_child(const char *what, int (*call)(const frs_sampler *,
    uint64_t), const frs_sampler *s, uint64_t n, int want0, int want1)
{
	pid_t pid = fork();
	int st = 0;

	assert_true(pid >= 0);
	if (pid == 0) {
		int rc;
		alarm(10);
		rc = call(s, n);
		if (rc != want0 && rc != want1)
			fprintf(stderr, "%s of %llu: %s\n", what,
			    (unsigned long long)n, frs_code_name(rc));
		_exit(rc == want0 || rc == want1 ? 0 : 1);
	}
	assert_int_equal(waitpid(pid, &st, 0), pid);
	if (WIFSIGNALED(st) && WTERMSIG(st) == SIGALRM) {
		print_error("%s of %llu: still running after 10 s\n", what,
		    (unsigned long long)n);
		fail();
	}
	assert_true(WIFEXITED(st) && WEXITSTATUS(st) == 0);
}

static int huge_count(const frs_sampler *s, uint64_t n)
{
	uint64_t c;

	return frs_count(s, n, 1, &c, NULL);
}

static int huge_draw(const frs_sampler *s, uint64_t n)
{
	double xy[2];
	size_t c;
	frs_error e;
	int rc = frs_draw(s, n, 1, xy, NULL, 1, &c, &e);

	return e.code == (enum frs_code)rc ? rc : -1;
}

/* Counts far beyond any matrix: FRS_E_LIMIT (the draw may also say
 * FRS_E_NOMEM), soon. */
static void huge_n(uint64_t n)
{
	frs_sampler *s = blob_sampler();

	in_child("frs_count", huge_count, s, n, FRS_E_LIMIT, FRS_E_LIMIT);
	in_child("frs_draw", huge_draw, s, n, FRS_E_LIMIT, FRS_E_NOMEM);
	frs_sampler_free(s);
}

static void test_huge_n(void **state)
{
	(void)state;
	huge_n(UINT64_MAX);
	huge_n((uint64_t)1 << 62);
}

/* FRS_E_BUFFER: the count, nothing written; then that room is enough. */
static void test_buffer(void **state)
{
	frs_sampler *s = blob_sampler();
	uint64_t n = 2000, want = 0;
	size_t c = 0, c2 = 0;
	double *xy, *pdf, *xy2;
	frs_error e;

	(void)state;
	assert_int_equal(frs_count(s, n, 4, &want, NULL), FRS_OK);
	xy = malloc(2 * want * sizeof *xy);
	pdf = malloc(want * sizeof *pdf);
	xy2 = malloc(2 * want * sizeof *xy2);
	assert_non_null(xy);
	assert_non_null(pdf);
	assert_non_null(xy2);
	for (size_t i = 0; i < 2 * want; i++)
		xy[i] = 42.0;
	for (size_t i = 0; i < want; i++)
		pdf[i] = 42.0;
	EXPECT(FRS_E_BUFFER, frs_draw(s, n, 4, xy, pdf, want - 1, &c, E));
	assert_int_equal(c, want);
	for (size_t i = 0; i < 2 * want; i++)
		assert_true(xy[i] == 42.0);
	for (size_t i = 0; i < want; i++)
		assert_true(pdf[i] == 42.0);
	EXPECT(FRS_E_BUFFER, frs_draw(s, n, 4, xy, NULL, 10, &c, E));
	assert_int_equal(c, want);
	EXPECT(FRS_E_BUFFER, frs_draw(s, n, 4, NULL, NULL, 0, &c, E));
	assert_int_equal(c, want);
	assert_int_equal(frs_draw(s, n, 4, xy, pdf, c, &c2, &e), FRS_OK);
	assert_int_equal(c2, want);
	for (size_t i = 0; i < 2 * want; i++)
		assert_true(xy[i] >= 0.0 && xy[i] < 1.0);
	for (size_t i = 0; i < want; i++)
		assert_true(pdf[i] > 0.0);
	/* More room changes nothing; no pdf, the same points. */
	free(xy2);
	xy2 = malloc(2 * (want + 100) * sizeof *xy2);
	assert_non_null(xy2);
	assert_int_equal(frs_draw(s, n, 4, xy2, NULL, want + 100, &c2, NULL),
	    FRS_OK);
	assert_int_equal(c2, want);
	assert_memory_equal(xy, xy2, 2 * want * sizeof *xy);
	free(xy);
	free(xy2);
	free(pdf);
	frs_sampler_free(s);
}

/* The callback form: the batches make up frs_draw_progressive's output. */
struct gather {
	struct drawn d;
	size_t cap, calls, stop_at;
	uint64_t total;
	int want_pdf, steps, bad;
};

static int gather(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct gather *g = ctx;

	g->calls++;
	if (g->calls == 1)
		g->total = total;
	if (k == 0 || total != g->total || g->d.n + k > g->cap ||
	    (pdf != NULL) != g->want_pdf || (step != NULL) != g->steps)
		g->bad = 1;
	if (!g->bad) {
		memcpy(g->d.xy + 2 * g->d.n, xy, 2 * k * sizeof *xy);
		if (pdf)
			memcpy(g->d.pdf + g->d.n, pdf, k * sizeof *pdf);
		if (step)
			memcpy(g->d.step + g->d.n, step, k * sizeof *step);
		g->d.n += k;
	}
	return g->stop_at != 0 && g->calls == g->stop_at;
}

static void each_case(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, int want_pdf)
{
	struct drawn ref = draw(s, steps, nsteps, 3, want_pdf);
	struct gather g;

	memset(&g, 0, sizeof g);
	g.cap = ref.n;
	g.want_pdf = want_pdf;
	g.steps = nsteps > 1;
	g.d.xy = malloc(2 * ref.n * sizeof(double));
	g.d.pdf = malloc(ref.n * sizeof(double));
	g.d.step = malloc(ref.n * sizeof(uint32_t));
	EXPECT(FRS_OK, (g.d.n = 0, g.calls = 0, frs_draw_each(s, steps, nsteps,
	    3, want_pdf, gather, &g, E)));
	assert_false(g.bad);
	assert_int_equal(g.d.n, ref.n);
	assert_int_equal(g.total, ref.n);
	assert_true(g.calls >= 1);
	assert_memory_equal(g.d.xy, ref.xy, 2 * ref.n * sizeof(double));
	if (want_pdf)
		assert_memory_equal(g.d.pdf, ref.pdf, ref.n * sizeof(double));
	if (nsteps > 1)
		assert_memory_equal(g.d.step, ref.step,
		    ref.n * sizeof(uint32_t));
	drawn_free(&g.d);
	drawn_free(&ref);
}

static void test_each(void **state)
{
	frs_sampler *s = blob_sampler();
	static const uint64_t steps[] = { 2000, 9000, 20000 };
	uint64_t n = 20000;
	struct gather g;

	(void)state;
	each_case(s, &n, 1, 0);
	each_case(s, &n, 1, 1);
	each_case(s, steps, 3, 1);
	each_case(s, steps, 3, 0);
	/* A callback that asks to stop: no call after that one. */
	memset(&g, 0, sizeof g);
	g.cap = 40000;
	g.d.xy = malloc(2 * g.cap * sizeof(double));
	g.d.pdf = malloc(g.cap * sizeof(double));
	g.d.step = malloc(g.cap * sizeof(uint32_t));
	g.stop_at = 2;
	EXPECT(FRS_E_CALLBACK, (g.calls = 0, g.d.n = 0, frs_draw_each(s, &n, 1,
	    3, 0, gather, &g, E)));
	assert_int_equal(g.calls, 2);
	g.stop_at = 1;
	EXPECT(FRS_E_CALLBACK, (g.calls = 0, g.d.n = 0, frs_draw_each(s, &n, 1,
	    3, 0, gather, &g, E)));
	assert_int_equal(g.calls, 1);
	drawn_free(&g.d);
	EXPECT(FRS_E_ARG, frs_draw_each(s, &n, 1, 3, 0, NULL, NULL, E));
	EXPECT(FRS_E_ARG, frs_draw_each(s, NULL, 1, 3, 0, gather, &g, E));
	frs_sampler_free(s);
}

/* FRS_MAX_MEM below what a load needs: FRS_E_NOMEM. */
static void test_nomem(void **state)
{
	frs_mask *mk = NULL;
	frs_sampler *s = NULL;
	frs_hsw *hw = NULL;
	float *map = NULL;
	uint32_t w, h;

	(void)state;
	assert_int_equal(setenv("FRS_MAX_MEM", "1k", 1), 0);
	EXPECT(FRS_E_NOMEM, frs_mask_load(&mk, MATRIX, E));
	EXPECT(FRS_E_NOMEM, frs_map_load("blob", 0, 0, &map, &w, &h, E));
	EXPECT(FRS_E_NOMEM, frs_map_load("data/sunset.exr", 0, 0, &map, &w, &h,
	    E));
	EXPECT(FRS_E_NOMEM, frs_sampler_new_f64(&s, mask, blob.v, blob.w,
	    blob.h, 0, NULL, E));
	EXPECT(FRS_E_NOMEM, frs_hsw_new_f64(&hw, blob.v, blob.w, blob.h, 0,
	    E));
	assert_int_equal(unsetenv("FRS_MAX_MEM"), 0);
	EXPECT(FRS_OK, frs_map_load("blob", 0, 0, &map, &w, &h, E) == FRS_OK ?
	    (frs_map_free(map), FRS_OK) : FRS_E_ARG);
}

static int unset_max_mem(void **state)
{
	(void)state;
	return unsetenv("FRS_MAX_MEM");
}

/* ---- threads ---------------------------------------------------------- */

struct job {
	const frs_sampler *s;
	uint64_t n, seed;
	int pdf;
	struct drawn d;
	size_t cap;
	int rc;
};

static void *job_run(void *arg)
{
	struct job *j = arg;

	/* Several times, so that the calls overlap. */
	for (int r = 0; r < 3 && j->rc == FRS_OK; r++)
		j->rc = frs_draw(j->s, j->n, j->seed, j->d.xy, j->d.pdf, j->cap,
		    &j->d.n, NULL);
	return NULL;
}

/*
 * One sampler used by four threads at once, each with its own buffers,
 * two of them with the same seed; the mask fresh, so that the threads
 * also race to make its lazy parts (sorted lists, minmap).  The bytes of
 * sequential calls.
 */
static void test_thread_safety(void **state)
{
	frs_mask *mk;
	frs_sampler *s[2];
	struct frs_options o;
	struct job j[6];
	pthread_t t[6];

	(void)state;
	assert_int_equal(frs_mask_load(&mk, MATRIX, NULL), FRS_OK);
	frs_options_init(&o);
	o.jitter = FRS_JIT_RANDOM;
	s[0] = sampler_f64(mk, &blob, &o);
	o.algorithm = FRS_ALG_LEVEL1;
	o.threads = 2;
	s[1] = sampler_f64(mk, &blob, &o);
	for (int i = 0; i < 6; i++) {
		j[i] = (struct job){ s[i >= 4], 6000 + 1000 * (uint64_t)(i % 2),
		    i == 3 ? 1 : (uint64_t)i + 1, i % 2, { 0, NULL, NULL, NULL },
		    20000, FRS_OK };
		j[i].d.xy = malloc(2 * j[i].cap * sizeof(double));
		j[i].d.pdf = malloc(j[i].cap * sizeof(double));
		assert_non_null(j[i].d.xy);
		assert_non_null(j[i].d.pdf);
		if (!j[i].pdf) {
			free(j[i].d.pdf);
			j[i].d.pdf = NULL;
		}
	}
	for (int i = 0; i < 6; i++)
		assert_int_equal(pthread_create(&t[i], NULL, job_run, &j[i]), 0);
	for (int i = 0; i < 6; i++)
		assert_int_equal(pthread_join(t[i], NULL), 0);
	for (int i = 0; i < 6; i++) {
		struct drawn d = draw(j[i].s, &j[i].n, 1, j[i].seed, j[i].pdf);
		assert_int_equal(j[i].rc, FRS_OK);
		assert_int_equal(j[i].d.n, d.n);
		assert_memory_equal(j[i].d.xy, d.xy, 2 * d.n * sizeof(double));
		if (j[i].pdf)
			assert_memory_equal(j[i].d.pdf, d.pdf,
			    d.n * sizeof(double));
		drawn_free(&d);
		drawn_free(&j[i].d);
	}
	frs_sampler_free(s[0]);
	frs_sampler_free(s[1]);
	frs_mask_free(mk);
}

/* ---- HSW -------------------------------------------------------------- */

/* hsw-sample with ARGS, -n n and --pdf against the records of xy, pdf. */
static void compare_hsw(const double *xy, const double *pdf, size_t n,
    const char *args)
{
	const char *out = tu_path("hsw.pts");
	double *rec = malloc(3 * n * sizeof *rec);

	assert_non_null(rec);
	prog("hsw-sample -q %s -n %zu --pdf -o %s", args, n, out);
	for (size_t i = 0; i < n; i++) {
		rec[3 * i] = xy[2 * i];
		rec[3 * i + 1] = xy[2 * i + 1];
		rec[3 * i + 2] = pdf[i];
	}
	same_as_file(out, rec, n, 1);
	free(rec);
}

static void test_hsw_draw(void **state)
{
	static const char *const kinds[] = { "random", "regular", "jittered",
	    "halton", "hammersley" };
	size_t n = 777;
	double *xy = malloc(2 * n * sizeof *xy), *pdf = malloc(n * sizeof *pdf);
	double *xy2 = malloc(2 * n * sizeof *xy2);
	frs_hsw *hw, *hc;
	char args[256];

	(void)state;
	assert_non_null(xy);
	assert_non_null(pdf);
	assert_non_null(xy2);
	assert_int_equal(frs_hsw_new_f64(&hw, blob.v, blob.w, blob.h, 0, NULL),
	    FRS_OK);
	assert_int_equal(frs_hsw_new(&hc, NULL, 64, 64, 0, NULL), FRS_OK);
	for (int k = FRS_HSW_RANDOM; k <= FRS_HSW_HAMMERSLEY; k++) {
		assert_int_equal(frs_hsw_draw(hw, (enum frs_hsw_input)k, n, 3, xy,
		    pdf, 1, NULL), FRS_OK);
		snprintf(args, sizeof args, "-i blob --input %s -S 3", kinds[k]);
		compare_hsw(xy, pdf, n, args);
		/* Threads and no pdf: the same points. */
		assert_int_equal(frs_hsw_draw(hw, (enum frs_hsw_input)k, n, 3,
		    xy2, NULL, 2, NULL), FRS_OK);
		assert_memory_equal(xy, xy2, 2 * n * sizeof *xy);
		assert_int_equal(frs_hsw_draw(hc, (enum frs_hsw_input)k, n, 3, xy,
		    pdf, 0, NULL), FRS_OK);
		snprintf(args, sizeof args, "-i const -s 64x64 --input %s -S 3",
		    kinds[k]);
		compare_hsw(xy, pdf, n, args);
	}
	frs_hsw_free(hw);
	frs_hsw_free(hc);
	free(xy);
	free(xy2);
	free(pdf);
}

/* Given points: hsw-sample --input FILE; in place the same. */
static void test_hsw_warp(void **state)
{
	size_t n = 5000;
	double *in = tu_rnd_points(n, 5), *out = malloc(2 * n * sizeof *out);
	double *pdf = malloc(n * sizeof *pdf), *pdf2 = malloc(n * sizeof *pdf);
	const char *pin = tu_path("in.pts"), *exr = write_exr("hblob.exr",
	    &blob);
	struct frs_points p = { 2, 0, n, in, { "" }, 0 };
	frs_hsw *hw;
	float *map;
	uint32_t w, h;
	char args[700];
	FILE *fp;

	(void)state;
	assert_non_null(out);
	assert_non_null(pdf);
	assert_non_null(pdf2);
	fp = fopen(pin, "wb");
	assert_non_null(fp);
	assert_int_equal(pts_write(fp, pin, &p, 0), 0);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_hsw_new_f64(&hw, blob.v, blob.w, blob.h, 0,
	    NULL), FRS_OK);
	assert_int_equal(frs_hsw_warp(hw, in, out, pdf, n, 1, NULL), FRS_OK);
	snprintf(args, sizeof args, "-i blob --input %s", pin);
	compare_hsw(out, pdf, n, args);
	assert_int_equal(frs_hsw_warp(hw, in, in, pdf2, n, 2, NULL), FRS_OK);
	assert_memory_equal(in, out, 2 * n * sizeof *in);
	assert_memory_equal(pdf, pdf2, n * sizeof *pdf);
	frs_hsw_free(hw);
	/* A float map from a file. */
	assert_int_equal(frs_map_load(exr, 0, 0, &map, &w, &h, NULL), FRS_OK);
	assert_int_equal(frs_hsw_new(&hw, map, w, h, 0, NULL), FRS_OK);
	assert_int_equal(frs_hsw_draw(hw, FRS_HSW_HALTON, n, 9, out, pdf, 1,
	    NULL), FRS_OK);
	snprintf(args, sizeof args, "-i %s --input halton -S 9", exr);
	compare_hsw(out, pdf, n, args);
	frs_hsw_free(hw);
	frs_map_free(map);
	free(in);
	free(out);
	free(pdf);
	free(pdf2);
}

/* Negative values count as zero: the points of the map with zeros. */
static void test_hsw_negative(void **state)
{
	struct frs_imap m;
	frs_hsw *a, *b;
	size_t n = 3000;
	double *xa = malloc(2 * n * sizeof *xa), *xb = malloc(2 * n * sizeof *xb);
	double *pa = malloc(n * sizeof *pa), *pb = malloc(n * sizeof *pb);
	int q, rc;

	(void)state;
	assert_int_equal(imap_load("blob", 32, 32, 0, &m), 0);
	for (size_t i = 0; i < 1024; i += 3)
		m.v[i] = -0.5;
	q = quiet_begin();
	rc = frs_hsw_new_f64(&a, m.v, 32, 32, 0, NULL);
	quiet_end(q, "frs_hsw_new_f64");
	if (rc != FRS_OK) {
		print_error("frs_hsw_new_f64 refuses negative values\n");
		imap_free(&m);
		free(xa), free(xb), free(pa), free(pb);
		fail();
	}
	for (size_t i = 0; i < 1024; i += 3)
		m.v[i] = 0.0;
	assert_int_equal(frs_hsw_new_f64(&b, m.v, 32, 32, 0, NULL), FRS_OK);
	assert_int_equal(frs_hsw_draw(a, FRS_HSW_RANDOM, n, 1, xa, pa, 1,
	    NULL), FRS_OK);
	assert_int_equal(frs_hsw_draw(b, FRS_HSW_RANDOM, n, 1, xb, pb, 1,
	    NULL), FRS_OK);
	assert_memory_equal(xa, xb, 2 * n * sizeof *xa);
	assert_memory_equal(pa, pb, n * sizeof *pa);
	for (size_t i = 0; i < n; i++)
		assert_true(pa[i] > 0.0);
	frs_hsw_free(a);
	frs_hsw_free(b);
	imap_free(&m);
	free(xa);
	free(xb);
	free(pa);
	free(pb);
}

static void test_hsw_errors(void **state)
{
	double in[4] = { 0.5, 0.5, 0.25, 1.0 }, out[4], pdf[2], xy[8];
	double one[4] = { 1, 1, 1, 1 };
	frs_hsw *hw = NULL;

	(void)state;
	EXPECT(FRS_E_ARG, frs_hsw_new(NULL, NULL, 4, 4, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new(&hw, NULL, 0, 4, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new(&hw, NULL, 4, 0, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new_f64(NULL, one, 2, 2, 0, E));
	EXPECT(FRS_E_ARG, frs_hsw_new_f64(&hw, one, 2, 2, 1, E));
	EXPECT(FRS_E_LIMIT, frs_hsw_new(&hw, NULL, 1u << 20, 1u << 20, 0, E));
	assert_int_equal(frs_hsw_new_f64(&hw, one, 2, 2, 0, NULL), FRS_OK);
	EXPECT(FRS_E_ARG, frs_hsw_warp(NULL, in, out, pdf, 1, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, NULL, out, pdf, 1, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, NULL, pdf, 1, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 2, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 1, -1, E));
	in[0] = NAN;
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 1, 1, E));
	in[0] = -0.25;
	EXPECT(FRS_E_ARG, frs_hsw_warp(hw, in, out, pdf, 1, 1, E));
	EXPECT(FRS_OK, frs_hsw_warp(hw, in, out, pdf, 0, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(NULL, FRS_HSW_HALTON, 4, 1, xy, NULL, 1,
	    E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, FRS_HSW_HALTON, 4, 1, NULL, NULL, 1,
	    E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, (enum frs_hsw_input)5, 4, 1, xy,
	    NULL, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, (enum frs_hsw_input)-1, 4, 1, xy,
	    NULL, 1, E));
	EXPECT(FRS_E_ARG, frs_hsw_draw(hw, FRS_HSW_HALTON, 4, 1, xy, NULL, -3,
	    E));
	EXPECT(FRS_OK, frs_hsw_draw(hw, FRS_HSW_HALTON, 4, 1, xy, NULL, 1, E));
	frs_hsw_free(hw);
	frs_hsw_free(NULL);
}

/* A NULL sampler or mask for every function that takes one (last: a
 * crash here would end the run). */
static void test_null_handles(void **state)
{
	uint64_t n = 100, c64;
	double xy[8], pdf[4];
	uint32_t step[4];
	struct frs_info in;
	size_t c;
	uint32_t w = 7, h = 7;

	(void)state;
	EXPECT(FRS_E_ARG, frs_draw(NULL, n, 1, xy, NULL, 4, &c, E));
	EXPECT(FRS_E_ARG, frs_draw_progressive(NULL, &n, 1, 1, xy, pdf, step,
	    4, &c, E));
	EXPECT(FRS_E_ARG, frs_count(NULL, n, 1, &c64, E));
	EXPECT(FRS_E_ARG, frs_sampler_info(NULL, n, 1, &in, E));
	EXPECT(FRS_E_ARG, frs_draw_each(NULL, &n, 1, 3, 0, gather, NULL, E));
	assert_null(frs_mask_note(NULL));
	frs_mask_size(NULL, &w, &h);
	assert_int_equal(w, 0);
	assert_int_equal(h, 0);
}

/* ---- main ------------------------------------------------------------- */

static int setup(void **state)
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

static int teardown(void **state)
{
	frs_mask_free(mask);
	while (nprepared > 0)
		frs_prep_free(&prepared[--nprepared].p);
	frd_free(&mat);
	frd_free(&mat3);
	imap_free(&blob);
	return tu_teardown(state);
}

/* ---- three dimensions ------------------------------------------------ */

/* frs_draw3_progressive sized by a call with no room; records in
 * frs-sample's layout (x, y, z [, pdf] [, step + 1]). */
static double *draw3(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int pdf, size_t *n)
{
	size_t k = 3 + (size_t)pdf + (nsteps > 1), cnt = 0;
	double *xyz, *pd, *rec;
	uint32_t *st;
	frs_error e;

	assert_int_equal(frs_draw3_progressive(s, steps, nsteps, seed, NULL,
	    NULL, NULL, 0, n, &e), FRS_E_BUFFER);
	assert_true(*n > 0);
	xyz = malloc(3 * *n * sizeof *xyz);
	pd = malloc(*n * sizeof *pd);
	st = malloc(*n * sizeof *st);
	rec = malloc(k * *n * sizeof *rec);
	assert_true(xyz && pd && st && rec);
	assert_int_equal(frs_draw3_progressive(s, steps, nsteps, seed, xyz,
	    pdf ? pd : NULL, st, *n, &cnt, &e), FRS_OK);
	assert_int_equal(cnt, *n);
	for (size_t i = 0; i < *n; i++) {
		double *r = rec + i * k;
		memcpy(r, xyz + 3 * i, 3 * sizeof *r);
		if (pdf)
			r[3] = pd[i];
		if (nsteps > 1)
			r[3 + pdf] = (double)(st[i] + 1);
	}
	free(xyz);
	free(pd);
	free(st);
	return rec;
}

/* One record of oracle3: frs3_point, the density I / mean, the step. */
struct oracle3 {
	const struct frs3_setup *su;
	const struct frs_vol *vol;
	double *rec;
	size_t n, k;
	int pdf, steps;
};

static int put3(void *ctx, const struct frs3_elem *e)
{
	struct oracle3 *o = ctx;
	double *q = o->rec + o->n++ * o->k;
	uint32_t ns = o->su->ns;

	frs3_point(o->su, e, q);
	if (o->pdf)
		q[3] = o->vol->v[((size_t)(e->z / ns) * o->vol->h + e->y / ns) *
		    o->vol->w + e->x / ns] / o->su->mean;
	if (o->steps)
		q[3 + o->pdf] = (double)(e->step + 1);
	return 0;
}

/* oracle_draw in 3-D, as records in frs-sample's layout: frs3_setup with
 * the options, its levels (octree levels over voxels, as in 2-D), the
 * same implementation's elements of each level in the order of frs.h
 * (frs3_each, level by level), each by put3.  Exact counts: the search
 * of frs_exact_taus over the levels' Naive counts.  (Steps in turn over
 * the levels: compared as sets with progressive steps.) */
struct olev3 {
	unsigned n;
	struct frs3_setup su[FRS_LEVELS_MAX];
	struct frs_levels plan;
	const struct frs_vol *vol;
	struct frs3_prep none;
};

static int naive_count3(void *ctx, double tau, uint64_t *count)
{
	struct olev3 *lv = ctx;
	struct frs3_result r;

	*count = 0;
	for (unsigned i = 0; i < lv->n; i++) {
		struct frs3_setup *su = &lv->su[i];
		su->exact = (struct frs_xtau){ .n = 1, .steps = { su->n },
		    .tau = { tau } };
		if (frs3_sample(su, lv->vol, &lv->none, FRS_NAIVE, &su->n, 1, 1,
		    &r) < 0)
			return -1;
		*count += r.count;
		frs3_result_free(&r);
	}
	return 0;
}

static void oracle_levels3(const struct frs_vol *vol,
    const struct frs_options *o, const struct frs3_setup *s0,
    struct olev3 *lv)
{
	const uint32_t side[3] = { vol->w, vol->h, vol->d };
	uint32_t longest = vol->w > vol->h ? vol->w : vol->h;
	double blur;
	unsigned top = 0;

	longest = vol->d > longest ? vol->d : longest;
	blur = o->level_blur > 0.0 ? o->level_blur : (double)longest / 8.0;
	memset(lv, 0, sizeof *lv);
	lv->vol = vol;
	lv->none.m = &mat3;
	lv->n = 1;
	lv->su[0] = *s0;
	const uint32_t msz[3] = { s0->mw, s0->mh, s0->md };

	top = oracle_top(s0->ns, side, msz, 3);
	if (o->tiling != FRS_TILING_LEVELS || top == 0)
		return;
	assert_int_equal(frs_levels_plan(&lv->plan, 3, side, vol->v,
	    s0->tau * s0->iscale, top, (double)mat3.w * mat3.h * mat3.d,
	    s0->sigma, blur), 0);
	if (frs_levels_used(&lv->plan) == 1 && lv->plan.cells[0] > 0)
		return;
	lv->n = 0;
	for (unsigned l = 0; l <= top; l++) {
		struct frs3_setup *su = &lv->su[lv->n];
		if (lv->plan.cells[l] == 0)
			continue;
		if (l == 0)
			*su = *s0;
		else
			frs3_level_setup(su, s0, l, lv->plan.max[l]);
		su->max = lv->plan.max[l];
		su->lev = lv->plan.lev;
		su->cell0 = 0;
		su->cell1 = (uint64_t)vol->w * vol->h * vol->d;
		lv->n++;
	}
}

static double *oracle3(const struct frs_vol *vol, const struct frs_options *o,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int pdf, size_t *n)
{
	enum frs_impl a = o->algorithm == FRS_ALG_NAIVE ? FRS_NAIVE : FRS_SORTED;
	size_t k = 3 + (size_t)pdf + (nsteps > 1);
	struct frs3_setup s0;
	struct olev3 lv;
	struct frs3_result r[FRS_LEVELS_MAX];
	struct oracle3 o3 = { NULL, vol, NULL, 0, k, pdf, nsteps > 1 };
	uint64_t count = 0;

	if (mat3.v == NULL)
		assert_int_equal(frd_read(MATRIX3, &mat3), 0);
	assert_int_equal(frs3_setup(&s0, vol, &mat3, steps[nsteps - 1],
	    o->sigma, seed), 0);
	s0.rule = rule_of(o);
	s0.jitter = jitter_of(o);
	s0.tiles = tiling_of(o, FRS_TILES_PLAIN);
	oracle_levels3(vol, o, &s0, &lv);
	if (o->rule == FRS_RULE_EXACT) {
		struct frs_xtau x;
		double tau0[16];
		unsigned passes;
		uint64_t most = 0;
		for (unsigned i = 0; i < nsteps; i++)
			tau0[i] = frs3_tau(&s0, steps[i]);
		for (unsigned i = 0; i < lv.n; i++)
			for (uint64_t c = 0; c < (uint64_t)vol->w * vol->h * vol->d;
			    c++)
				most += vol->v[c] > 0.0 && frs_cell_here(lv.su[i].lev,
				    lv.su[i].level, c) ? (uint64_t)lv.su[i].ns *
				    lv.su[i].ns * lv.su[i].ns : 0;
		assert_int_equal(frs_exact_taus(steps, nsteps, tau0, most,
		    naive_count3, &lv, &x, &passes), 0);
		for (unsigned i = 0; i < lv.n; i++) {
			lv.su[i].exact = x;
			lv.su[i].tau = frs3_tau(&lv.su[i], lv.su[i].n);
		}
	}
	frs_set_threads(1);
	for (unsigned i = 0; i < lv.n; i++) {
		struct frs3_prep p;
		assert_int_equal(frs3_prepare(&p, &mat3, a == FRS_SORTED ?
		    frs3_block(&lv.su[i]) : 0), 0);
		assert_int_equal(frs3_sample(&lv.su[i], vol, &p, a, steps, nsteps,
		    0, &r[i]), 0);
		frs3_prep_free(&p);
		count += r[i].count;
	}
	o3.rec = malloc((count + 1) * k * sizeof *o3.rec);
	assert_non_null(o3.rec);
	for (unsigned i = 0; i < lv.n; i++) {
		o3.su = &lv.su[i];
		frs3_each(&r[i], nsteps, put3, &o3);
		frs3_result_free(&r[i]);
	}
	*n = o3.n;
	assert_true(*n == count);
	frs_levels_free(&lv.plan);
	return o3.rec;
}

/* The API's samples for a 3-D mask (s made from vol with the options o,
 * NULL: the defaults) are the oracle's and frs-sample's, bit for bit. */
static void compare3(const frs_sampler3 *s, const struct frs_vol *vol,
    const struct frs_options *o, const uint64_t *steps, unsigned nsteps,
    uint64_t seed, int pdf, const char *args)
{
	const char *out = tu_path("frs3.pts");
	size_t n, nref, k = 3 + (size_t)pdf + (nsteps > 1);
	double *rec, *ref;
	struct frs_points p;
	struct frs_options dflt;

	o = o != NULL ? o : (frs_options_init(&dflt), &dflt);
	frs_sample_prog(MATRIX3, args, steps, nsteps, seed, pdf, out);
	rec = draw3(s, steps, nsteps, seed, pdf, &n);
	ref = oracle3(vol, o, steps, nsteps, seed, pdf, &nref);
	assert_int_equal(n, nref);
	if (nsteps == 1) {
		assert_memory_equal(rec, ref, n * k * sizeof *rec);
	} else {	/* the oracle gives the levels' steps in turn */
		double *a = sort_recs(rec, n, k), *b = sort_recs(ref, n, k);
		assert_memory_equal(a, b, n * k * sizeof *rec);
		free(a);
		free(b);
	}
	assert_int_equal(pts_read(out, &p), 0);
	assert_int_equal(p.dims, 3);
	assert_int_equal(p.n, n);
	assert_int_equal(p.dims + p.extra, k);
	assert_memory_equal(p.x, rec, n * k * sizeof *rec);
	pts_free(&p);
	free(ref);
	free(rec);
}

static void test_sampler3(void **state)
{
	static const uint64_t steps[] = { 300, 1200, 4000 };
	struct frs_vol v, one;
	struct frs_options o;
	frs_mask *m3;
	frs_sampler3 *s;
	frs_error e;
	uint32_t w, h, d;
	uint64_t n = 3000, c1 = 0, c2 = 0;

	(void)state;
	assert_int_equal(frs_mask_load(&m3, MATRIX3, &e), FRS_OK);
	assert_int_equal(frs_mask_dims(m3), 3);
	assert_int_equal(frs_mask_dims(mask), 2);
	frs_mask_size3(m3, &w, &h, &d);
	assert_true(w == 64 && h == 64 && d == 64);
	frs_mask_size3(mask, &w, &h, &d);
	assert_true(w == 2048 && d == 1);
	assert_int_equal(vol_load("blob3:sigma=0.2", 16, 16, 16, 0, &v), 0);
	/* The default options, then each option as its flag. */
	assert_int_equal(frs_sampler3_new_f64(&s, m3, v.v, 16, 16, 16, NULL,
	    &e), FRS_OK);
	compare3(s, &v, NULL, &n, 1, 5, 1, "-i blob3:sigma=0.2 -s 16");
	compare3(s, &v, NULL, steps, 3, 2, 0, "-i blob3:sigma=0.2 -s 16");
	assert_int_equal(frs_count3(s, n, 5, &c1, &e), FRS_OK);
	frs_sampler3_free(s);
	frs_options_init(&o);
	o.sigma = 4;
	o.jitter = FRS_JIT_HALTON;
	o.algorithm = FRS_ALG_NAIVE;
	o.threads = 2;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, v.v, 16, 16, 16, &o, &e),
	    FRS_OK);
	compare3(s, &v, &o, &n, 1, 5, 0, "-i blob3:sigma=0.2 -s 16 --sigma 4 "
	    "--jitter halton -a naive");
	frs_sampler3_free(s);
	/* A float volume and a constant one (NULL). */
	{
		float *f = malloc(16 * 16 * 16 * sizeof *f);
		assert_non_null(f);
		for (size_t i = 0; i < 16 * 16 * 16; i++)
			f[i] = (float)v.v[i];
		assert_int_equal(frs_sampler3_new(&s, m3, f, 16, 16, 16, NULL,
		    &e), FRS_OK);
		assert_int_equal(frs_count3(s, n, 5, &c2, &e), FRS_OK);
		assert_true(c2 > n * 9 / 10 && c2 < n * 11 / 10);
		frs_sampler3_free(s);
		free(f);
	}
	assert_true(c1 > n * 9 / 10 && c1 < n * 11 / 10);
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 8, 8, 8, NULL, &e),
	    FRS_OK);
	/* No volume: importance 1 everywhere. */
	assert_int_equal(vol_alloc(&one, 8, 8, 8), 0);
	for (size_t i = 0; i < 8 * 8 * 8; i++)
		one.v[i] = 1.0;
	compare3(s, &one, NULL, &n, 1, 3, 1, "-s 8");
	frs_sampler3_free(s);
	vol_free(&one);
	vol_free(&v);
	frs_mask_free(m3);
}

/* Every error the 3-D functions reach. */
static void test_sampler3_errors(void **state)
{
	struct frs_options o;
	frs_mask *m3;
	frs_sampler3 *s = NULL;
	frs_sampler *s2 = NULL;
	frs_error e;
	double bad[8] = { 1, 1, 1, 1, 1, 1, 1, 0 };
	double xyz[3];
	size_t cnt;
	uint64_t c;

	(void)state;
	assert_int_equal(frs_mask_load(&m3, MATRIX3, &e), FRS_OK);
	/* The mask's dimension must fit the sampler. */
	assert_int_equal(frs_sampler3_new(&s, mask, NULL, 4, 4, 4, NULL, &e),
	    FRS_E_ARG);
	assert_non_null(strstr(e.message, "2-D mask"));
	assert_null(s);
	assert_int_equal(frs_sampler_new(&s2, m3, NULL, 4, 4, 0, NULL, &e),
	    FRS_E_ARG);
	assert_non_null(strstr(e.message, "3-D mask"));
	assert_null(s2);
	/* Arguments, options and values. */
	assert_int_equal(frs_sampler3_new(NULL, m3, NULL, 4, 4, 4, NULL, &e),
	    FRS_E_ARG);
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 4, 0, 4, NULL, &e),
	    FRS_E_ARG);
	frs_options_init(&o);
	o.algorithm = FRS_ALG_STACK;
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 4, 4, 4, &o, &e),
	    FRS_E_ARG);
	assert_non_null(strstr(e.message, "naive and sorted"));
	bad[3] = NAN;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, bad, 2, 2, 2, NULL, &e),
	    FRS_E_MAP);
	assert_non_null(strstr(e.message, "voxel (1, 1, 0)"));
	bad[3] = -1;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, bad, 2, 2, 2, NULL, &e),
	    FRS_E_MAP);
	memset(bad, 0, sizeof bad);
	assert_int_equal(frs_sampler3_new_f64(&s, m3, bad, 2, 2, 2, NULL, &e),
	    FRS_E_MAP);
	assert_null(s);
	/* Draws: no sampler, bad counts, too small a buffer, a count too
	 * large to visit. */
	assert_int_equal(frs_draw3(NULL, 10, 1, xyz, NULL, 1, &cnt, &e),
	    FRS_E_ARG);
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 2, 2, 2, NULL, &e),
	    FRS_OK);
	assert_int_equal(frs_draw3(s, 0, 1, xyz, NULL, 1, &cnt, &e), FRS_E_ARG);
	assert_int_equal(frs_draw3(s, 100, 1, xyz, NULL, 1, &cnt, &e),
	    FRS_E_BUFFER);
	assert_true(cnt > 50);
	assert_int_equal(frs_count3(s, (uint64_t)1 << 41, 1, &c, &e),
	    FRS_E_LIMIT);
	frs_sampler3_free(s);
	/* 2^40 samples at sigma 16 from 8 voxels: 2^36 blocks to visit. */
	frs_options_init(&o);
	o.sigma = 16;
	assert_int_equal(frs_sampler3_new(&s, m3, NULL, 2, 2, 2, &o, &e),
	    FRS_OK);
	assert_int_equal(frs_count3(s, (uint64_t)1 << 40, 1, &c, &e),
	    FRS_E_LIMIT);
	assert_non_null(strstr(e.message, "larger matrix"));
	assert_int_equal(frs_count3(s, 100, 1, NULL, &e), FRS_E_ARG);
	frs_sampler3_free(s);
	frs_sampler3_free(NULL);
	frs_mask_free(m3);
}

/* ---- progress ---------------------------------------------------------- */

struct prog_log {
	size_t calls;
	int bad;		/* a call out of order */
	uint64_t last, total;
	char what[32];
};

static void prog_record(void *ctx, const char *what, uint64_t done,
    uint64_t total)
{
	struct prog_log *l = ctx;

	if (l->calls == 0) {
		snprintf(l->what, sizeof l->what, "%s", what);
		l->total = total;
		l->bad |= done != 0;
	} else {
		/* Increasing, below total until the one last call. */
		l->bad |= done <= l->last || l->last == l->total ||
		    total != l->total || strcmp(what, l->what) != 0;
	}
	l->last = done;
	l->calls++;
}

static void *load_ramp(void *arg)
{
	float *map = NULL;
	uint32_t w, h;

	(void)arg;
	if (frs_map_load("ramp", 64, 1024, &map, &w, &h, NULL) != FRS_OK)
		return arg;
	frs_map_free(map);
	return NULL;
}

/* frs_set_progress: off by default; once set, a procedural map's rows
 * are reported, from 0 up to the last call at the total, in this thread
 * only. */
static void test_progress(void **state)
{
	struct prog_log l = { 0, 0, 0, 0, "" };
	float *map = NULL;
	uint32_t w, h;
	pthread_t t;
	void *res = &l;
	(void)state;

	assert_null(load_ramp(NULL));	/* nothing set: nothing to call */
	frs_set_progress(prog_record, &l);
	assert_int_equal(frs_map_load("ramp", 64, 1024, &map, &w, &h, NULL),
	    FRS_OK);
	frs_map_free(map);
	assert_string_equal(l.what, "ramp");
	assert_int_equal(l.total, 1024);
	assert_int_equal(l.last, 1024);
	assert_false(l.bad);
	assert_true(l.calls >= 3);	/* start, some rows, end */
	/* Another thread's work is not this thread's progress. */
	l = (struct prog_log){ 0, 0, 0, 0, "" };
	assert_int_equal(pthread_create(&t, NULL, load_ramp, NULL), 0);
	assert_int_equal(pthread_join(t, &res), 0);
	assert_null(res);
	assert_int_equal(l.calls, 0);
	/* Unset: silent again. */
	frs_set_progress(NULL, &l);
	assert_null(load_ramp(NULL));
	assert_int_equal(l.calls, 0);
}

/* ---- exact counts (FRS_RULE_EXACT, frs-sample --exact-count) ---------- */

static frs_sampler *exact_sampler(const struct frs_imap *m,
    enum frs_algorithm a, int threads, enum frs_rule_mode rule)
{
	struct frs_options o;

	frs_options_init(&o);
	o.algorithm = a;
	o.threads = threads;
	o.rule = rule;
	return sampler_f64(mask, m, &o);
}

static int pair_cmp(const void *a, const void *b)
{
	const double *p = a, *q = b;

	return p[0] < q[0] ? -1 : p[0] > q[0] ? 1 : p[1] < q[1] ? -1 :
	    p[1] > q[1];
}

/* The points of d, sorted (jitter none: one point per element). */
static double *sorted_xy(const struct drawn *d)
{
	double *xy = malloc((2 * d->n + 1) * sizeof *xy);

	assert_non_null(xy);
	memcpy(xy, d->xy, 2 * d->n * sizeof *xy);
	qsort(xy, d->n, 2 * sizeof *xy, pair_cmp);
	return xy;
}

/* frs_draw of n, also when it makes no samples (about n: n 1 may). */
static struct drawn draw_any(const frs_sampler *s, uint64_t n, uint64_t seed)
{
	struct drawn d = { 0, NULL, NULL, NULL };
	uint64_t c = 0;
	size_t cnt = 0;
	frs_error e;

	assert_int_equal(frs_count(s, n, seed, &c, &e), FRS_OK);
	d.xy = malloc((2 * c + 1) * sizeof *d.xy);
	assert_non_null(d.xy);
	assert_int_equal(frs_draw(s, n, seed, d.xy, NULL, (size_t)c, &cnt, &e),
	    FRS_OK);
	assert_int_equal(cnt, c);
	d.n = cnt;
	return d;
}

/* Whether every point of the sorted set a (na) is in the sorted b. */
static int subset(const double *a, size_t na, const double *b, size_t nb)
{
	size_t j = 0;

	for (size_t i = 0; i < na; i++) {
		while (j < nb && pair_cmp(&b[2 * j], &a[2 * i]) < 0)
			j++;
		if (j == nb || pair_cmp(&b[2 * j], &a[2 * i]) != 0)
			return 0;
	}
	return 1;
}

/* Exactly n for several maps, seeds and counts, in frs_count and
 * frs_draw; the exact set nests with the default one (a subset of it
 * when the default has more, else a superset). */
static void test_exact_counts(void **state)
{
	static const char *const maps[] = { "blob", "ramp", "sky", "const" };
	static const uint64_t ns[] = { 1, 37, 1024, 4099 };

	(void)state;
	for (size_t mi = 0; mi < 4; mi++) {
		struct frs_imap m;
		frs_sampler *ex, *def;
		assert_int_equal(imap_load(maps[mi], 0, 0, 0, &m), 0);
		ex = exact_sampler(&m, FRS_ALG_SORTED, 1, FRS_RULE_EXACT);
		def = exact_sampler(&m, FRS_ALG_SORTED, 1, FRS_RULE_UNBIASED);
		for (size_t ni = 0; ni < 4; ni++)
			for (uint64_t seed = 1; seed <= 3; seed++) {
				uint64_t n = ns[ni], c = 0;
				struct drawn de, dd;
				double *a, *b;
				frs_error e;
				assert_int_equal(frs_count(ex, n, seed, &c, &e),
				    FRS_OK);
				if (c != n)
					print_error("%s n %llu seed %llu: %llu\n",
					    maps[mi], (unsigned long long)n,
					    (unsigned long long)seed,
					    (unsigned long long)c);
				assert_int_equal(c, n);
				de = draw(ex, &n, 1, seed, 0);
				dd = draw_any(def, n, seed);
				assert_int_equal(de.n, n);
				a = sorted_xy(&de);
				b = sorted_xy(&dd);
				if (dd.n >= n)
					assert_true(subset(a, de.n, b, dd.n));
				else
					assert_true(subset(b, dd.n, a, de.n));
				free(a);
				free(b);
				drawn_free(&de);
				drawn_free(&dd);
			}
		frs_sampler_free(ex);
		frs_sampler_free(def);
		imap_free(&m);
	}
}

/* The same samples for every algorithm (as sets; in order for every
 * thread count) and as frs-sample --exact-count, also progressive, each
 * step exact and nested. */
static void test_exact_same(void **state)
{
	static const enum frs_algorithm algs[] = { FRS_ALG_SORTED,
	    FRS_ALG_NAIVE, FRS_ALG_STACK, FRS_ALG_LEVEL1, FRS_ALG_LEVEL2 };
	static const uint64_t steps[] = { 100, 1000, 3000 };
	uint64_t n = 3000;
	struct drawn d0, d;
	double *a, *b;
	frs_sampler *s;
	struct frs_options xo;

	(void)state;
	frs_options_init(&xo);
	xo.rule = FRS_RULE_EXACT;
	s = exact_sampler(&blob, FRS_ALG_SORTED, 1, FRS_RULE_EXACT);
	compare(s, &blob, &xo, &n, 1, 5, 1, "-i blob --exact-count");
	compare(s, &blob, &xo, steps, 3, 6, 0,
	    "-i blob --exact-count -j 2");
	d0 = draw(s, &n, 1, 5, 0);
	assert_int_equal(d0.n, n);
	a = sorted_xy(&d0);
	/* Progressive: each step exactly, the last the set of n. */
	d = draw(s, steps, 3, 5, 0);
	assert_int_equal(d.n, 3000);
	for (size_t i = 0; i < d.n; i++)
		assert_true(d.step[i] == (i < 100 ? 0u : i < 1000 ? 1u : 2u));
	b = sorted_xy(&d);
	assert_memory_equal(a, b, 2 * n * sizeof *a);
	free(b);
	drawn_free(&d);
	frs_sampler_free(s);
	for (size_t ai = 0; ai < 5; ai++) {
		struct drawn d1;
		s = exact_sampler(&blob, algs[ai], 1, FRS_RULE_EXACT);
		d1 = draw(s, &n, 1, 5, 0);
		frs_sampler_free(s);
		s = exact_sampler(&blob, algs[ai], 3, FRS_RULE_EXACT);
		d = draw(s, &n, 1, 5, 0);
		frs_sampler_free(s);
		assert_int_equal(d.n, n);
		assert_int_equal(d1.n, n);
		assert_memory_equal(d.xy, d1.xy, 2 * n * sizeof *d.xy);
		b = sorted_xy(&d);
		assert_memory_equal(a, b, 2 * n * sizeof *a);
		free(b);
		drawn_free(&d);
		drawn_free(&d1);
	}
	free(a);
	drawn_free(&d0);
}

/* A brute-force oracle: on a small matrix and map, every window
 * element's key (v + u) / (4^l I) over every level l (one with plain
 * tiles), u its coin, sorted; the n smallest are the exact set. */
struct keyed {
	double key;
	uint64_t l, x, y;
};

static int key_cmp(const void *a, const void *b)
{
	const struct keyed *p = a, *q = b;

	return p->key < q->key ? -1 : p->key > q->key;
}

static int elem_cmp(const void *a, const void *b)
{
	const uint64_t *p = a, *q = b;

	for (int i = 0; i < 3; i++)
		if (p[i] != q[i])
			return p[i] < q[i] ? -1 : 1;
	return 0;
}

/* Every window element of every level of lv over the 8 x 6 map m of the
 * matrix values v, keyed; their number. */
static uint64_t all_keys(const struct olev *lv, const struct frs_imap *m,
    const uint32_t *v, struct keyed *k)
{
	uint64_t nk = 0;

	for (unsigned i = 0; i < lv->n; i++) {
		const struct frs_setup *su = &lv->su[i];
		for (uint64_t y = 0; y < su->sh; y++)
			for (uint64_t x = 0; x < su->sw; x++) {
				uint64_t p = (y / su->ns) * 8 + x / su->ns;
				double imp = m->v[p];
				double u = frs_rand01(su->seed, FRS_STREAM_COIN,
				    y * su->sw + x);
				if (imp > 0.0 && frs_cell_here(su->lev, su->level, p))
					k[nk++] = (struct keyed){ ((double)v[
					    frs_matrix_index(su, x, y)] + u) /
					    (su->lfac * imp * su->iscale), i, x, y };
			}
	}
	return nk;
}

/* The level index and window element of each drawn point, as (l, x, y). */
static void elems_of(const struct olev *lv, const struct drawn *d,
    uint64_t *got)
{
	for (size_t i = 0; i < d->n; i++) {
		uint64_t px = (uint64_t)(d->xy[2 * i] * 8.0);
		uint64_t py = (uint64_t)(d->xy[2 * i + 1] * 6.0), l = 0;
		while (!frs_cell_here(lv->su[l].lev, lv->su[l].level, py * 8 + px))
			l++;
		got[3 * i] = l;
		got[3 * i + 1] = (uint64_t)(d->xy[2 * i] * (double)lv->su[l].sw);
		got[3 * i + 2] = (uint64_t)(d->xy[2 * i + 1] *
		    (double)lv->su[l].sh);
	}
}

static void test_exact_oracle(void **state)
{
	static const uint64_t ns[] = { 1, 10, 50, 200, 1000 };
	uint32_t *v = malloc(64 * 64 * sizeof *v);
	struct frs_imap m;
	struct frs_rng r;
	frs_mask *mk;
	frs_error e;
	unsigned most = 0;

	(void)state;
	assert_non_null(v);
	for (uint32_t i = 0; i < 64 * 64; i++)
		v[i] = i;
	frs_rng_init(&r, 77, 0);
	for (uint32_t i = 64 * 64 - 1; i > 0; i--) {
		uint32_t j = (uint32_t)(frs_rng_next64(&r) % (i + 1)), t = v[i];
		v[i] = v[j];
		v[j] = t;
	}
	assert_int_equal(frs_mask_wrap(&mk, v, 64, 64, &e), FRS_OK);
	assert_int_equal(imap_alloc(&m, 8, 6), 0);
	for (uint32_t i = 0; i < 8 * 6; i++)	/* some zeros, one bright */
		m.v[i] = i % 7 == 3 ? 0.0 : i == 20 ? 9.0 :
		    0.05 + frs_rng_next01(&r);
	for (int levels = 0; levels < 2; levels++)
	for (size_t ni = 0; ni < 5; ni++)
		for (uint64_t seed = 1; seed <= 3; seed++) {
			struct frs_options o;
			struct frs_setup su;
			struct olev lv;
			struct drawn d;
			struct keyed *k;
			uint64_t n = ns[ni], nk, *got, *want;
			frs_sampler *s;
			frs_options_init(&o);
			o.rule = FRS_RULE_EXACT;
			o.level_blur = 0.25;	/* each pixel its own level */
			o.tiling = levels ? FRS_TILING_LEVELS : FRS_TILING_PLAIN;
			assert_int_equal(frs_sampler_new_f64(&s, mk, m.v, 8, 6, 0,
			    &o, &e), FRS_OK);
			assert_int_equal(api_setup(s, n, seed, &su), 0);
			oracle_levels_of(&m, &o, &su, 64.0 * 64.0, &lv);
			most = lv.n > most ? lv.n : most;
			k = malloc(lv.n * su.sw * su.sh * sizeof *k);
			assert_non_null(k);
			nk = all_keys(&lv, &m, v, k);
			qsort(k, nk, sizeof *k, key_cmp);
			assert_true(nk > n);
			want = malloc(3 * n * sizeof *want);
			got = malloc(3 * n * sizeof *got);
			assert_true(want && got);
			for (uint64_t i = 0; i < n; i++) {
				want[3 * i] = k[i].l;
				want[3 * i + 1] = k[i].x;
				want[3 * i + 2] = k[i].y;
			}
			d = draw(s, &n, 1, seed, 0);
			assert_int_equal(d.n, n);
			elems_of(&lv, &d, got);
			qsort(want, n, 3 * sizeof *want, elem_cmp);
			qsort(got, n, 3 * sizeof *got, elem_cmp);
			assert_memory_equal(want, got, 3 * n * sizeof *got);
			drawn_free(&d);
			frs_levels_free(&lv.plan);
			free(want);
			free(got);
			free(k);
			frs_sampler_free(s);
		}
	/* the levels were tried: several at some count */
	assert_true(most >= 3);
	imap_free(&m);
	frs_mask_free(mk);
	free(v);
}

static int triple_cmp(const void *a, const void *b)
{
	const double *p = a, *q = b;
	int c = pair_cmp(a, b);

	return c != 0 ? c : p[2] < q[2] ? -1 : p[2] > q[2];
}

/* 3-D: exactly n, Naive's set is Sorted's, frs-sample's bytes. */
static void test_exact3(void **state)
{
	static const uint64_t steps[] = { 300, 1200, 4000 };
	struct frs_vol v;
	struct frs_options o;
	frs_mask *m3;
	frs_sampler3 *s, *sn;
	frs_error e;
	uint64_t n = 3000, c = 0;
	size_t k1, k2;
	double *r1, *r2;

	(void)state;
	assert_int_equal(frs_mask_load(&m3, MATRIX3, &e), FRS_OK);
	assert_int_equal(vol_load("blob3:sigma=0.2", 16, 16, 16, 0, &v), 0);
	frs_options_init(&o);
	o.rule = FRS_RULE_EXACT;
	assert_int_equal(frs_sampler3_new_f64(&s, m3, v.v, 16, 16, 16, &o, &e),
	    FRS_OK);
	for (uint64_t seed = 1; seed <= 3; seed++) {
		assert_int_equal(frs_count3(s, n, seed, &c, &e), FRS_OK);
		assert_int_equal(c, n);
	}
	compare3(s, &v, &o, &n, 1, 5, 1,
	    "-i blob3:sigma=0.2 -s 16 --exact-count");
	compare3(s, &v, &o, steps, 3, 2, 0,
	    "-i blob3:sigma=0.2 -s 16 --exact-count");
	o.algorithm = FRS_ALG_NAIVE;
	o.threads = 2;
	assert_int_equal(frs_sampler3_new_f64(&sn, m3, v.v, 16, 16, 16, &o,
	    &e), FRS_OK);
	r1 = draw3(s, &n, 1, 4, 0, &k1);
	r2 = draw3(sn, &n, 1, 4, 0, &k2);
	assert_int_equal(k1, n);
	assert_int_equal(k2, n);
	qsort(r1, n, 3 * sizeof *r1, triple_cmp);
	qsort(r2, n, 3 * sizeof *r2, triple_cmp);
	assert_memory_equal(r1, r2, 3 * n * sizeof *r1);
	free(r1);
	free(r2);
	frs_sampler3_free(s);
	frs_sampler3_free(sn);
	vol_free(&v);
	frs_mask_free(m3);
}

/* ---- the levels and the map helpers of API 2.0 ------------------------ */

/* A zeroed struct frs_options is an initialised one: the same samples,
 * bit for bit, on a map of several levels. */
static void test_zeroed_options(void **state)
{
	struct frs_options z, d;
	frs_sampler *a, *b;
	struct drawn x, y;
	uint64_t n = 20000;

	(void)state;
	memset(&z, 0, sizeof z);
	frs_options_init(&d);
	a = sampler_f64(mask, &blob, &z);
	b = sampler_f64(mask, &blob, &d);
	x = draw(a, &n, 1, 3, 1);
	y = draw(b, &n, 1, 3, 1);
	assert_int_equal(x.n, y.n);
	assert_memory_equal(x.xy, y.xy, 2 * x.n * sizeof *x.xy);
	assert_memory_equal(x.pdf, y.pdf, x.n * sizeof *x.pdf);
	drawn_free(&x);
	drawn_free(&y);
	frs_sampler_free(a);
	frs_sampler_free(b);
}

/* frs_sampler_levels: the levels frs-sample -v lists (level, n_s,
 * window, offset, pixels, tau), their pixels all the map's pixels of
 * non-zero importance, tau 4^l times level 0's (frs_sampler_info's);
 * cap and count; one level with plain tiles, level 0's setup. */
static void test_levels(void **state)
{
	const char *err = tu_path("lv.txt");
	struct frs_imap sky;
	frs_sampler *s;
	struct frs_level_info lv[FRS_LEVELS_MAX];
	struct frs_info in;
	struct frs_options o;
	char line[1024];
	unsigned n = 0, k = 0, c1 = 0;
	uint64_t cells = 0;
	FILE *fp;

	(void)state;
	assert_int_equal(imap_load("sky", 0, 0, 0, &sky), 0);
	s = sampler_f64(mask, &sky, NULL);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, lv, FRS_LEVELS_MAX, &n,
	    NULL), FRS_OK);
	assert_int_equal(frs_sampler_info(s, 20000, 7, &in, NULL), FRS_OK);
	assert_true(n >= 3);
	prog("frs-sample -m %s -i sky -n 20000 -S 7 -v -o /dev/null 2>%s",
	    MATRIX, err);
	fp = fopen(err, "r");
	assert_non_null(fp);
	while (fgets(line, sizeof line, fp) != NULL) {
		unsigned l, ns;
		unsigned long long ww, wh, ox, oy, px;
		double tau;
		if (sscanf(line, "frs-sample:   level %u: n_s %u, window %llux%llu "
		    "at (%llu, %llu), tau %lg, %llu pixels", &l, &ns, &ww, &wh,
		    &ox, &oy, &tau, &px) != 8)
			continue;
		assert_true(k < n);
		assert_int_equal(lv[k].level, l);
		assert_int_equal(lv[k].ns, ns);
		assert_int_equal(lv[k].window[0], ww);
		assert_int_equal(lv[k].window[1], wh);
		assert_int_equal(lv[k].offset[0], ox);
		assert_int_equal(lv[k].offset[1], oy);
		assert_int_equal(lv[k].cells, px);
		assert_near(lv[k].tau, tau, 1e-8 * tau);
		assert_true(lv[k].tau == ldexp(in.tau, 2 * (int)l));
		assert_int_equal(lv[k].ns << l, in.ns);
		assert_true(k == 0 || lv[k].level > lv[k - 1].level);
		cells += lv[k].cells;
		k++;
	}
	fclose(fp);
	assert_int_equal(k, n);
	for (size_t i = 0; i < (size_t)sky.w * sky.h; i++)
		cells -= sky.v[i] > 0.0;
	assert_true(cells == 0);
	/* cap 1: one filled, the count still all; cap 0 with NULL */
	memset(lv, 0, sizeof lv);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, lv, 1, &c1, NULL),
	    FRS_OK);
	assert_int_equal(c1, n);
	assert_true(lv[0].ns > 0 && lv[1].ns == 0);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, NULL, 0, &c1, NULL),
	    FRS_OK);
	EXPECT(FRS_E_ARG, frs_sampler_levels(s, 20000, 7, NULL, 1, &c1, E));
	EXPECT(FRS_E_ARG, frs_sampler_levels(s, 20000, 7, lv, 1, NULL, E));
	EXPECT(FRS_E_ARG, frs_sampler_levels(NULL, 20000, 7, lv, 1, &c1, E));
	EXPECT(FRS_E_ARG, frs_sampler_levels(s, 0, 7, lv, 1, &c1, E));
	frs_sampler_free(s);
	frs_options_init(&o);
	o.tiling = FRS_TILING_PLAIN;
	s = sampler_f64(mask, &sky, &o);
	assert_int_equal(frs_sampler_levels(s, 20000, 7, lv, FRS_LEVELS_MAX, &n,
	    NULL), FRS_OK);
	assert_int_equal(n, 1);
	assert_int_equal(lv[0].level, 0);
	assert_int_equal(lv[0].ns, in.ns);
	assert_int_equal(lv[0].window[0], in.window_w);
	assert_true(lv[0].tau == in.tau);
	frs_sampler_free(s);
	imap_free(&sky);
}

/* frs_map_equirect: row j times the mean of sin over its band, in
 * closed form ((cos t0 - cos t1) / (t1 - t0)); the float and double
 * forms alike, stride kept; and frs-sample --equirect's samples are
 * those of a sampler of the weighted map. */
static void test_equirect(void **state)
{
	float f[3 * 5];
	double d[3 * 4];
	struct frs_imap m;
	frs_sampler *s;
	uint64_t n = 3000;

	(void)state;
	for (int i = 0; i < 15; i++)
		f[i] = 2.0f;
	for (int i = 0; i < 12; i++)
		d[i] = 1.0;
	frs_map_equirect(f, 4, 3, 5);
	frs_map_equirect_f64(d, 4, 3, 0);
	for (int j = 0; j < 3; j++) {
		const double pi = 3.14159265358979323846;
		double t0 = pi * j / 3, t1 = pi * (j + 1) / 3;
		double w = (cos(t0) - cos(t1)) / (t1 - t0);
		for (int i = 0; i < 4; i++) {
			assert_near(d[j * 4 + i], w, 1e-15);
			assert_near(f[j * 5 + i], 2.0 * w, 1e-6);
		}
		assert_true(f[j * 5 + 4] == 2.0f);	/* past the width */
	}
	/* (at the map's own size: --equirect weights it before resampling) */
	assert_int_equal(imap_load("data/sunset.exr", 0, 0, 0, &m), 0);
	frs_map_equirect_f64(m.v, m.w, m.h, 0);
	s = sampler_f64(mask, &m, NULL);
	prog("frs-sample -q -m %s -i data/sunset.exr --equirect -n 3000 -S 2 "
	    "-o %s", MATRIX, tu_path("eq.pts"));
	{
		struct drawn dr = draw(s, &n, 1, 2, 0);
		double *rec = records(&dr, 0, 0);
		same_as_file(tu_path("eq.pts"), rec, dr.n, 0);
		free(rec);
		drawn_free(&dr);
	}
	frs_sampler_free(s);
	imap_free(&m);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_code_names),
	cmocka_unit_test(test_const_map),
	cmocka_unit_test(test_blob_defaults),
	cmocka_unit_test(test_options),
	cmocka_unit_test(test_thesis_rule),
	cmocka_unit_test(test_progressive),
	cmocka_unit_test(test_float_map),
	cmocka_unit_test(test_stride),
	cmocka_unit_test(test_threads_option),
	cmocka_unit_test(test_direct_path),
	cmocka_unit_test(test_lists_grow),
	cmocka_unit_test(test_count),
	cmocka_unit_test(test_info),
	cmocka_unit_test(test_zeroed_options),
	cmocka_unit_test(test_levels),
	cmocka_unit_test(test_equirect),
	cmocka_unit_test(test_wrap),
	cmocka_unit_test(test_prepared),
	cmocka_unit_test(test_mask_errors),
	cmocka_unit_test(test_default_matrix),
	cmocka_unit_test(test_map_errors),
	cmocka_unit_test(test_bad_maps),
	cmocka_unit_test(test_sampler_errors),
	cmocka_unit_test(test_draw_errors),
	cmocka_unit_test(test_huge_n),
	cmocka_unit_test(test_buffer),
	cmocka_unit_test(test_each),
	cmocka_unit_test_teardown(test_nomem, unset_max_mem),
	cmocka_unit_test(test_thread_safety),
	cmocka_unit_test(test_hsw_draw),
	cmocka_unit_test(test_hsw_warp),
	cmocka_unit_test(test_hsw_negative),
	cmocka_unit_test(test_hsw_errors),
	cmocka_unit_test(test_null_handles),
	cmocka_unit_test(test_sampler3),
	cmocka_unit_test(test_sampler3_errors),
	cmocka_unit_test(test_progress),
	cmocka_unit_test(test_exact_counts),
	cmocka_unit_test(test_exact_same),
	cmocka_unit_test(test_exact_oracle),
	cmocka_unit_test(test_exact3))
