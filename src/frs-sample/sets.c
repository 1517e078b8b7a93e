/*
 * frs-sample's work (frs-sample(1)): the matrix, map or volume and
 * device loaded, set 0's setup, then M sets through the draws' callback
 * form (frs_draw_each, frs_draw3_each) into one points file: x, y [, z]
 * [, pdf] [, step + 1] [, set].  The program keeps the options and the
 * warnings that name them; its -v report is setsreport.c.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "frs-sample/sets.h"

/* The output of the sets, and -v's share of set 0. */
struct out {
	const struct sets *a;
	struct sets_run *run;
	struct outfile of;
	struct sets_writer w;	/* its set: the one being drawn */
	int open;
	uint64_t n;		/* samples of the set being drawn */
	/* -v: how many samples of set 0 show each matrix element, per
	 * level (2-D) */
	uint32_t *uses[FRS_LEVELS_MAX];
	int collect;
	double *rec;		/* records with extra columns */
	size_t reccap;
};

/* The level of point p (every set has set 0's levels: they do not
 * depend on the seed). */
static unsigned level_at(const struct sets_run *run, const double *p)
{
	return run->lv[frs_run_level_of(run->r, p)].info.level;
}

/* -v: count point p of set 0 in its level and (2-D) the matrix element
 * it shows (its window element is floor(x S_W): jitter stays inside
 * it). */
static void note_point(struct out *u, const double *p)
{
	struct sets_run *run = u->run;
	const uint32_t *side = run->info.matrix;
	unsigned i = frs_run_level_of(run->r, p);
	uint64_t m;

	run->lcount[i]++;
	if (run->dims != 2)
		return;
	if (u->uses[i] == NULL && (u->uses[i] = calloc((size_t)side[0] *
	    side[1], sizeof *u->uses[i])) == NULL) {
		u->collect = 0;	/* -v goes without the share */
		return;
	}
	m = frs_run_element(run->r, i, p);
	if (u->uses[i][m] < UINT32_MAX)
		u->uses[i][m]++;
}

/* The shares of the noted samples whose matrix element another one of
 * their level shows too, per level and in all: O(n + S_M^2) a level,
 * not a sort of the samples. */
static void reused_shares(struct out *u)
{
	struct sets_run *run = u->run;
	uint64_t all = 0, noted = 0;
	size_t n = (size_t)run->info.matrix[0] * run->info.matrix[1];

	run->reused = -1.0;
	for (unsigned i = 0; i < FRS_LEVELS_MAX; i++)
		run->lreused[i] = -1.0;
	for (unsigned i = 0; i < run->info.levels; i++) {
		uint64_t reused = 0;
		if (u->uses[i] == NULL)
			continue;
		for (size_t k = 0; k < n; k++)
			reused += u->uses[i][k] >= 2 ? u->uses[i][k] : 0;
		run->lreused[i] = (double)reused / (double)run->lcount[i];
		all += reused;
		noted += run->lcount[i];
	}
	if (noted > 0)
		run->reused = (double)all / (double)noted;
}

/* Open the output at the first set: with one set its count goes into
 * the header; more sets announce 0 (unknown), which the writer replaces
 * by the total when the output can seek.  The extra columns, in their
 * order: pdf, step (progressive), level (--level-column), and the
 * writer's set (M > 1). */
static int out_begin(struct out *u, uint64_t count)
{
	const struct sets *a = u->a;
	const char *names[3];
	unsigned extra = 0;

	if (u->open)
		return 0;
	if (a->pdf)
		names[extra++] = PTS_COL_PDF;
	if (a->nsteps > 1)
		names[extra++] = PTS_COL_STEP;
	if (a->level_col)
		names[extra++] = PTS_COL_LEVEL;
	if (outfile_open(&u->of, a->out, !a->count_only && !a->text) < 0)
		return -1;
	u->open = 1;
	if (!a->count_only && sets_writer_begin(&u->w, u->of.fp, u->of.name,
	    u->run->dims, extra, names, a->sets, a->sets == 1 ? count : 0,
	    a->text) < 0)
		return -1;
	return 0;
}

/* The draws' callback: the records of k samples. */
static int out_batch(void *ctx, const double *p, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct out *u = ctx;
	double t0 = cli_now();
	int rc = out_begin(u, total), lcol = u->a->level_col;
	unsigned dims = u->run->dims, ncol = dims + (pdf != NULL ? 1u : 0u) +
	    (step != NULL ? 1u : 0u) + (lcol ? 1u : 0u);

	u->n = total;
	if (u->collect) {
		double t1 = cli_now();
		for (size_t i = 0; i < k && u->collect; i++)
			note_point(u, p + dims * i);
		u->run->tnote += cli_now() - t1;
		t0 += cli_now() - t1;
	}
	if (rc == 0 && ncol == dims)
		rc = sets_writer_put(&u->w, p, k);
	else if (rc == 0 && k * ncol > u->reccap) {
		free(u->rec);
		u->reccap = k * ncol;
		if ((u->rec = malloc(u->reccap * sizeof *u->rec)) == NULL) {
			u->reccap = 0;
			rc = cli_fail("out of memory");
		}
	}
	if (rc == 0 && ncol > dims) {
		double *rec = u->rec;
		for (size_t i = 0; i < k; i++, rec += ncol) {
			unsigned c = dims;
			memcpy(rec, p + dims * i, dims * sizeof *rec);
			if (pdf != NULL)
				rec[c++] = pdf[i];
			if (step != NULL)
				rec[c++] = (double)(step[i] + 1);
			if (lcol)
				rec[c++] = (double)level_at(u->run, p + dims * i);
		}
		rc = sets_writer_put(&u->w, u->rec, k);
	}
	u->run->tout += cli_now() - t0;
	return rc;
}

/* The levels of the run whose cells span more than the matrix on an
 * axis, as "2, 3", into buf; their number. */
static unsigned repeating(const struct sets_run *r, char *buf, size_t cap)
{
	unsigned k = 0;
	size_t len = 0;

	buf[0] = '\0';
	for (unsigned i = 0; i < r->info.levels; i++) {
		const struct frs_run_level *v = &r->lv[i];
		int over = 0;
		for (unsigned a = 0; a < r->dims; a++)
			over |= (uint64_t)(v->hi[a] - v->lo[a] + 1) * v->info.ns >
			    r->info.matrix[a];
		if (over && len < cap)
			len += (size_t)snprintf(buf + len, cap - len, "%s%u",
			    k ? ", " : "", v->info.level);
		k += (unsigned)over;
	}
	return k;
}

/* The matrix's sides as "WxH" or "WxHxD". */
static const char *msize(const struct sets_run *r, char *buf, size_t cap)
{
	if (r->dims == 2)
		snprintf(buf, cap, "%ux%u", r->info.matrix[0],
		    r->info.matrix[1]);
	else
		snprintf(buf, cap, "%ux%ux%u", r->info.matrix[0],
		    r->info.matrix[1], r->info.matrix[2]);
	return buf;
}

/* The warnings of set 0's setup: patterns that repeat.  Without levels,
 * the thesis's: more samples than the matrix gives without repetition
 * (Table 4.1), or plain tiles of a window larger than the matrix.  With
 * levels, the levels whose cells span more than the matrix on an axis:
 * their samples show the same matrix elements again, a lattice of the
 * matrix's period. */
static void warn_repeats(const struct sets_run *r, double sigma)
{
	const struct frs_run_info *f = &r->info;
	int levels = r->opt.tiling == FRS_TILING_LEVELS, over = 0;
	char which[256], m[64];
	unsigned k = levels ? repeating(r, which, sizeof which) : 0;

	msize(r, m, sizeof m);
	for (unsigned a = 0; a < r->dims; a++)
		over |= f->window[a] > r->info.matrix[a];
	if (k > 0)
		cli_warn("level%s %s of the multi-level window span%s more than "
		    "the %s matrix: %s samples repeat the matrix's patterns%s",
		    k > 1 ? "s" : "", which, k > 1 ? "" : "s", m,
		    k > 1 ? "their" : "its", (double)f->n > f->unique ? r->dims ==
		    2 ? " (n is past the samples it gives without repetition, "
		    "thesis Table 4.1)" : " (n is past the samples it gives "
		    "without repetition)" : "");
	else if (!levels && (double)f->n > f->unique)
		cli_warn(r->dims == 2 ? "%llu samples from a %s matrix with "
		    "sigma %g repeat its patterns (it gives %.0f without "
		    "repetition, thesis Table 4.1)" : "%llu samples from a %s "
		    "matrix with sigma %g repeat its patterns (it gives %.6g "
		    "without repetition)", (unsigned long long)f->n, m, sigma,
		    f->unique);
	else if (!levels && !f->shuffled && over && r->dims == 2)
		cli_warn("plain tiles: the window of %llux%llu repeats the %s "
		    "matrix as it is, a lattice of the tile's period where few "
		    "samples fall (shuffled tiles break it)",
		    (unsigned long long)f->window[0],
		    (unsigned long long)f->window[1], m);
	else if (!levels && !f->shuffled && over)
		cli_warn("plain tiles: the window of %llux%llux%llu repeats the "
		    "%s matrix as it is", (unsigned long long)f->window[0],
		    (unsigned long long)f->window[1],
		    (unsigned long long)f->window[2], m);
}

void sets_matrix(struct sets *a)
{
	double t0 = cli_now();
	unsigned dims = 0;

	a->loaded = strcmp(a->matrix, "-") != 0;
	if (a->loaded)
		a->mask_rc = frs_mask_load_dims(&a->mask, a->matrix, &dims,
		    &a->mask_err);
	a->dims = dims == 3 ? 3 : 2;
	a->tload = cli_now() - t0;
}

int sets_default_matrix(struct sets *a, unsigned dims)
{
	static char path[CLI_PATH_MAX];
	double t0 = cli_now();

	a->mask_rc = frs_default_matrix(&a->mask, dims, path, sizeof path,
	    &a->mask_err);
	if (path[0] == '\0')
		return -1;
	a->matrix = path;
	a->loaded = 1;
	/* One that fails to load is reported as sets_matrix's are. */
	a->dims = a->mask_rc == FRS_OK ? frs_mask_dims(a->mask) : dims;
	a->tload = cli_now() - t0;
	return 0;
}

int sets_map(struct sets *a, unsigned want)
{
	unsigned dims;

	if (frs_source_read(a->imp ? a->imp : "const", want, a->size, a->flags,
	    &dims, &a->map, &a->stats, &a->vol, NULL) != FRS_OK)
		return -1;
	return (int)dims;
}

void sets_unmap(struct sets *a)
{
	frs_imap_free(&a->map);
	frs_vol_free(&a->vol);
}

/* The mask (as sets_matrix loaded it), its note (a stale twin .frp)
 * as a warning. */
static int load_mask(const struct sets *a, struct sets_run *run)
{
	frs_error err = a->mask_err;
	int rc = a->loaded ? a->mask_rc : frs_mask_load(&run->mask, a->matrix,
	    &err);

	if (a->loaded)
		run->mask = a->mask;
	if (rc != FRS_OK)
		return cli_fail("%s", err.message);
	if ((run->note = frs_mask_note(run->mask)) != NULL)
		cli_warn("%s", run->note);
	return 0;
}

/* Set 0's run (prepared when prep), its setup and levels, and the
 * warnings of patterns that repeat. */
static int open_run(const struct sets *a, struct sets_run *run, int exact,
    int prep)
{
	frs_error err;
	int rc = run->dims == 2 ? frs_run_new(&run->r, run->smp, a->steps,
	    a->nsteps, a->seed, exact ? FRS_RUN_EXACT : 0, &err) :
	    frs_run3_new(&run->r, run->smp3, a->steps, a->nsteps, a->seed,
	    exact ? FRS_RUN_EXACT : 0, &err);

	if (rc == FRS_OK)
		rc = frs_run_info(run->r, &run->info, &err);
	for (unsigned i = 0; rc == FRS_OK && i < run->info.levels; i++)
		rc = frs_run_level(run->r, i, &run->lv[i], &err);
	if (rc != FRS_OK)
		return cli_fail("%s", err.message);
	/* 2-D warns after the preparing, 3-D before, as they always did. */
	if (run->dims == 3)
		warn_repeats(run, a->opt.sigma);
	if (prep && frs_run_prepare(run->r, &err) != FRS_OK)
		return cli_fail("%s", err.message);
	if (run->dims == 2)
		warn_repeats(run, a->opt.sigma);
	return 0;
}

/* The sampler of a 2-D mask on the CPU or the device, and set 0's
 * levels with the mask prepared for them. */
static int open2(const struct sets *a, struct sets_run *run)
{
	struct frs_imap map = a->map;	/* taken over */
	frs_error err;
	double t0;
	int rc, exact = a->opt.rule == FRS_RULE_EXACT;

	/* The OpenCL device asked for, if any (one that does not open ends
	 * the program). */
	if (a->cl && frs_device_open(&run->dev, a->device, NULL) != FRS_OK)
		cli_die_device(!a->flat1);
	t0 = cli_now();
	rc = load_mask(a, run);
	/* The map as sets_map checked it, handed over: no copy, no second
	 * check. */
	if (rc == 0 && frs_sampler_take(&run->smp, run->mask, &map, &a->stats,
	    &run->opt, &err) != FRS_OK)
		rc = cli_fail("%s", err.message);
	if (rc < 0) {
		frs_imap_free(&map);	/* not taken: its check failed */
		return -1;
	}
	if (run->dev != NULL && frs_sampler_set_device(run->smp, run->dev,
	    a->flat1 ? FRS_DEVICE_FLAT1 : 0, &err) != FRS_OK)
		return cli_fail("%s", err.message);
	/* Exact counts: set 0's taus only for -v (each set finds its own),
	 * and the mask prepared for them only then. */
	if (open_run(a, run, a->verbose, !exact || a->verbose) < 0)
		return -1;
	run->tsetup = cli_now() - t0 + a->tload;
	return 0;
}

/* The same for a 3-D mask over a volume (the CPU only). */
static int open3(const struct sets *a, struct sets_run *run)
{
	double t0 = cli_now();
	struct frs_vol v = a->vol;	/* taken over */
	frs_error err;

	if (load_mask(a, run) < 0) {
		frs_vol_free(&v);
		return -1;
	}
	if (frs_sampler3_new_f64(&run->smp3, run->mask, v.v, v.w, v.h, v.d,
	    &run->opt, &err) != FRS_OK) {
		frs_vol_free(&v);
		return cli_fail("%s", err.message);
	}
	frs_vol_free(&v);
	/* Exact counts: set 0's taus only for -v, as in 2-D. */
	if (open_run(a, run, a->verbose, 1) < 0)
		return -1;
	run->tsetup = cli_now() - t0 + a->tload;
	return 0;
}

int sets_open(const struct sets *a, struct sets_run *run)
{
	memset(run, 0, sizeof *run);
	run->dims = a->dims;
	run->reused = -1.0;
	/* Flat 1, no public algorithm, is the device's (FRS_DEVICE_FLAT1):
	 * a->alg, the sampler's options, names Sorted for it. */
	run->opt = a->opt;
	run->opt.algorithm = a->alg;
	return run->dims == 3 ? open3(a, run) : open2(a, run);
}

/* One set through the draws; its count, UINT64_MAX after cli_fail. */
static uint64_t one_set(struct out *u, uint64_t seed)
{
	const struct sets *a = u->a;
	const struct sets_run *run = u->run;
	frs_error err;
	uint64_t count = 0, n = a->steps[a->nsteps - 1];
	int rc;

	u->n = 0;
	if (a->count_only)
		rc = run->dims == 3 ? frs_count3(run->smp3, n, seed, &count, &err) :
		    frs_count(run->smp, n, seed, &count, &err);
	else
		rc = run->dims == 3 ? frs_draw3_each(run->smp3, a->steps,
		    a->nsteps, seed, a->pdf, out_batch, u, &err) :
		    frs_draw_each(run->smp, a->steps, a->nsteps, seed, a->pdf,
		    out_batch, u, &err);
	if (rc == FRS_E_CALLBACK)
		return UINT64_MAX;	/* the writer's message */
	if (rc != FRS_OK) {
		cli_fail("%s", err.message);
		return UINT64_MAX;
	}
	if (!a->count_only)
		count = u->n;
	if (out_begin(u, count) < 0)
		return UINT64_MAX;
	if (a->count_only && fprintf(u->of.fp, "%llu\n",
	    (unsigned long long)count) < 0) {
		cli_fail_errno("%s: write error", u->of.name);
		return UINT64_MAX;
	}
	return count;
}

static int write_sets(struct out *u)
{
	const struct sets *a = u->a;
	struct sets_run *run = u->run;
	struct cli_task *task = cli_task_begin("sets", a->sets);

	for (uint64_t set = 0; set < a->sets; set++) {
		uint64_t c;
		u->collect = a->verbose && set == 0 && !a->count_only;
		u->w.set = set;
		c = one_set(u, a->seed + set);
		/* Every sample of set 0 noted. */
		if (u->collect)
			reused_shares(u);
		u->collect = 0;
		if (c == UINT64_MAX) {
			cli_task_drop(task);	/* the message follows */
			return -1;
		}
		run->total += c;
		cli_task_update(task, set + 1);
	}
	cli_task_end(task);
	return 0;
}

int sets_write(const struct sets *a, struct sets_run *run)
{
	struct out u = { .a = a, .run = run };
	double t1 = cli_now(), t0;
	int rc = write_sets(&u);
	const frs_mask *mk = run->mask;

	/* A damaged twin .frp shows only when its lists are first read. */
	if (rc == 0 && frs_mask_note(mk) != NULL && run->note == NULL)
		cli_warn("%s", frs_mask_note(mk));
	t0 = cli_now();
	if (rc == 0 && !a->count_only && sets_writer_end(&u.w) < 0)
		rc = -1;
	if (rc < 0 && u.open)
		outfile_abort(&u.of);
	else if (rc == 0 && outfile_commit(&u.of) < 0)
		rc = -1;
	run->tout += cli_now() - t0;
	run->tthr = cli_now() - t1 - run->tout - run->tnote;
	run->made = frs_mask_made(mk, &run->made_in);
	run->device = frs_device_name(run->dev);
	frs_device_times(run->dev, &run->ct);
	for (unsigned i = 0; i < FRS_LEVELS_MAX; i++)
		free(u.uses[i]);
	free(u.rec);
	return rc;
}

void sets_close(struct sets_run *run)
{
	frs_run_free(run->r);
	frs_sampler_free(run->smp);
	frs_sampler3_free(run->smp3);
	frs_mask_free(run->mask);
	frs_device_free(run->dev);
}
