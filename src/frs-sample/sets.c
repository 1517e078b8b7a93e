/*
 * frs-sample's sets (frs-sample(1)): with the run that frs-sample.c
 * set up, M sets through the draws' callback form (frs_draw_each,
 * frs_draw3_each) into one points file: x, y [, z] [, pdf] [, step + 1]
 * [, set].  Its -v report is setsreport.c.
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

/* k samples with the step and level columns: made into records of ncol
 * values (the points and densities alone go to the writer as they
 * are). */
static int put_records(struct out *u, const double *p, const double *pdf,
    const uint32_t *step, size_t k, unsigned ncol)
{
	unsigned dims = u->run->dims;
	double *rec;

	if (k * ncol > u->reccap) {
		free(u->rec);
		u->reccap = k * ncol;
		if ((u->rec = malloc(u->reccap * sizeof *u->rec)) == NULL) {
			u->reccap = 0;
			return cli_fail("out of memory");
		}
	}
	rec = u->rec;
	for (size_t i = 0; i < k; i++, rec += ncol) {
		unsigned c = dims;
		memcpy(rec, p + dims * i, dims * sizeof *rec);
		if (pdf != NULL)
			rec[c++] = pdf[i];
		if (step != NULL)
			rec[c++] = (double)(step[i] + 1);
		if (u->a->level_col)
			rec[c++] = (double)level_at(u->run, p + dims * i);
	}
	return sets_writer_put(&u->w, u->rec, k);
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
	else if (rc == 0 && ncol == dims + 1 && pdf != NULL)
		rc = sets_writer_put_cols(&u->w, p, &pdf, k);
	else if (rc == 0)
		rc = put_records(u, p, pdf, step, k, ncol);
	u->run->tout += cli_now() - t0;
	return rc;
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
