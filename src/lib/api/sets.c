/*
 * frs-sample's work (frs-sample(1)): the matrix, map or volume and
 * device loaded, set 0's setup, then M sets through the draws' callback
 * form (frs_draw_each, api_draw3_each) into one points file: x, y [, z]
 * [, pdf] [, step + 1] [, set].  The program keeps the options and the
 * warnings that name them; its -v report is src/cli/setsreport.c.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"
#include "base/outfile.h"
#include "base/progress.h"
#include "formats/ptsio.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "maps/vol.h"

/* The output of the sets, and -v's share of set 0. */
struct out {
	const struct api_sets *a;
	struct api_sets_run *run;
	struct outfile of;
	struct pts_writer w;
	int open;
	uint64_t n;		/* samples of the set being drawn */
	uint64_t set;		/* and its index, from 0 */
	/* -v: how many samples of set 0 show each matrix element */
	uint32_t *uses;
	uint64_t nnoted;
	int collect;
	double *rec;		/* records with extra columns */
	size_t reccap;
};

/* -v: count the matrix element that sample (x, y) of set 0 shows (its
 * window element is floor(x S_W): jitter stays inside it). */
static void note_point(struct out *u, double x, double y)
{
	const struct frs_setup *s = &u->run->s0;
	uint64_t i;

	if (u->uses == NULL &&
	    (u->uses = calloc((size_t)s->mw * s->mh, sizeof *u->uses)) == NULL) {
		u->collect = 0;	/* -v goes without the share */
		return;
	}
	i = frs_matrix_index(s, (uint64_t)(x * (double)s->sw),
	    (uint64_t)(y * (double)s->sh));
	if (u->uses[i] < UINT32_MAX)
		u->uses[i]++;
	u->nnoted++;
}

/* The share of the noted samples whose matrix element another one
 * shows too: O(n + S_M^2), not a sort of the samples. */
static double reused_share(const struct out *u)
{
	uint64_t reused = 0;
	size_t n = (size_t)u->run->s0.mw * u->run->s0.mh;

	if (u->nnoted == 0 || u->uses == NULL)
		return 0.0;
	for (size_t i = 0; i < n; i++)
		reused += u->uses[i] >= 2 ? u->uses[i] : 0;
	return (double)reused / (double)u->nnoted;
}

/* Open the output at the first set: with one set its count goes into
 * the header; more sets announce 0 (unknown), which the writer replaces
 * by the total when the output can seek.  The extra columns, in their
 * order: pdf, step (progressive), set (M > 1). */
static int out_begin(struct out *u, uint64_t count)
{
	const struct api_sets *a = u->a;
	const char *names[3];
	unsigned extra = 0;

	if (u->open)
		return 0;
	if (a->pdf)
		names[extra++] = PTS_COL_PDF;
	if (a->nsteps > 1)
		names[extra++] = PTS_COL_STEP;
	if (a->sets > 1)
		names[extra++] = PTS_COL_SET;
	if (outfile_open(&u->of, a->out, !a->count_only && !a->text) < 0)
		return -1;
	u->open = 1;
	if (!a->count_only && pts_writer_begin(&u->w, u->of.fp, u->of.name,
	    u->run->dims, extra, names, a->sets == 1 ? count : 0, a->text) < 0)
		return -1;
	return 0;
}

/* The draws' callback: the records of k samples. */
static int out_batch(void *ctx, const double *p, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct out *u = ctx;
	double t0 = progress_now();
	int rc = out_begin(u, total), sets = u->a->sets > 1;
	unsigned dims = u->run->dims, ncol = dims + (pdf != NULL ? 1u : 0u) +
	    (step != NULL ? 1u : 0u) + (sets ? 1u : 0u);

	u->n = total;
	if (u->collect) {
		double t1 = progress_now();
		for (size_t i = 0; i < k && u->collect; i++)
			note_point(u, p[2 * i], p[2 * i + 1]);
		u->run->tnote += progress_now() - t1;
		t0 += progress_now() - t1;
	}
	if (rc == 0 && ncol == dims)
		rc = pts_writer_put_n(&u->w, p, k);
	else if (rc == 0 && k * ncol > u->reccap) {
		free(u->rec);
		u->reccap = k * ncol;
		if ((u->rec = malloc(u->reccap * sizeof *u->rec)) == NULL) {
			u->reccap = 0;
			rc = frs_fail("out of memory");
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
			if (sets)
				rec[c++] = (double)u->set;
		}
		rc = pts_writer_put_n(&u->w, u->rec, k);
	}
	u->run->tout += progress_now() - t0;
	return rc;
}

/* The warnings of set 0's setup: patterns that repeat, in the matrix or
 * the lattice of plain tiles. */
static void warn(const struct api_sets_run *r)
{
	const struct frs_setup *s = &r->s0;
	const struct frs3_setup *t = &r->s3;

	if (r->dims == 2 && (double)s->n > frs_unique(s))
		frs_warn("%llu samples from a %ux%u matrix with sigma %g repeat "
		    "its patterns (it gives %.0f without repetition, thesis "
		    "Table 4.1)", (unsigned long long)s->n, s->mw, s->mh,
		    s->sigma, frs_unique(s));
	else if (r->dims == 2 && s->tiles == FRS_TILES_PLAIN &&
	    (s->sw > s->mw || s->sh > s->mh))
		frs_warn("plain tiles: the window of %llux%llu repeats the "
		    "%ux%u matrix as it is, a lattice of the tile's period where "
		    "few samples fall (shuffled tiles break it)",
		    (unsigned long long)s->sw, (unsigned long long)s->sh, s->mw,
		    s->mh);
	else if (r->dims == 3 && (double)t->n > frs3_unique(t))
		frs_warn("%llu samples from a %ux%ux%u matrix with sigma %g repeat "
		    "its patterns (it gives %.6g without repetition)",
		    (unsigned long long)t->n, t->mw, t->mh, t->md, t->sigma,
		    frs3_unique(t));
	else if (r->dims == 3 && t->tiles == FRS_TILES_PLAIN &&
	    (t->sw > t->mw || t->sh > t->mh || t->sd > t->md))
		frs_warn("plain tiles: the window of %llux%llux%llu repeats the "
		    "%ux%ux%u matrix as it is", (unsigned long long)t->sw,
		    (unsigned long long)t->sh, (unsigned long long)t->sd, t->mw,
		    t->mh, t->md);
}

/* The mask, its note (a stale twin .frp) as a warning. */
static int load_mask(const struct api_sets *a, struct api_sets_run *run)
{
	frs_error err;

	if (frs_mask_load(&run->mask, a->matrix, &err) != FRS_OK)
		return frs_fail("%s", err.message);
	if ((run->note = frs_mask_note(run->mask)) != NULL)
		frs_warn("%s", run->note);
	return 0;
}

/* The OpenCL device asked for, if any: -2 when it cannot be opened. */
static int open_device(const struct api_sets *a, struct api_sets_run *run)
{
	if (!a->cl)
		return 0;
	if ((run->ocl = calloc(1, sizeof *run->ocl)) == NULL)
		return frs_fail("out of memory");
	if (ocl_open(run->ocl, a->device) == 0)
		return 0;
	free(run->ocl);
	run->ocl = NULL;
	return -2;
}

/* The sampler of a 2-D mask on the CPU or the device, and set 0's setup
 * with the mask prepared for it. */
static int open2(const struct api_sets *a, struct api_sets_run *run)
{
	struct frs_imap map;
	struct frs_prep view;
	struct frs_setup plain;
	frs_error err;
	double t0;
	int rc;

	if (imap_load(a->imp ? a->imp : "const", a->size[0], a->size[1],
	    a->flags, &map) < 0)
		return -1;
	if ((rc = open_device(a, run)) < 0) {
		imap_free(&map);
		return rc;
	}
	t0 = progress_now();
	rc = load_mask(a, run);
	if (rc == 0 && frs_sampler_new_f64(&run->smp, run->mask, map.v, map.w,
	    map.h, 0, &run->opt, &err) != FRS_OK)
		rc = frs_fail("%s", err.message);
	imap_free(&map);
	if (rc < 0)
		return -1;
	if (run->ocl != NULL)
		api_sampler_device(run->smp, run->ocl, a->alg);
	if ((a->opt.rule == FRS_RULE_EXACT && a->verbose ?
	    api_setup_steps(run->smp, a->steps, a->nsteps, a->seed, &run->s0) :
	    api_setup(run->smp, a->steps[a->nsteps - 1], a->seed, &run->s0)) < 0)
		return -1;
	if ((a->opt.rule != FRS_RULE_EXACT || a->verbose) &&
	    api_sampler_prep(run->smp, &run->s0, a->steps, a->nsteps, &view) < 0)
		return -1;
	warn(run);
	run->tsetup = progress_now() - t0;
	plain = run->s0;
	plain.exact.n = 0;
	run->tau0 = frs_tau(&plain, plain.n);
	return 0;
}

/* The same for a 3-D mask over a volume (the CPU only). */
static int open3(const struct api_sets *a, struct api_sets_run *run)
{
	double t0 = progress_now();
	struct frs3_prep view;
	struct frs3_setup plain;
	struct frs_vol v;
	frs_error err;

	if (load_mask(a, run) < 0 || vol_load(a->imp ? a->imp : "const",
	    a->nsize ? a->size[0] : 0, a->size[1], a->size[2], a->flags, &v) < 0)
		return -1;
	if (frs_sampler3_new_f64(&run->smp3, run->mask, v.v, v.w, v.h, v.d,
	    &run->opt, &err) != FRS_OK) {
		vol_free(&v);
		return frs_fail("%s", err.message);
	}
	vol_free(&v);
	if (api_setup3(run->smp3, a->steps, a->nsteps, a->seed, NULL,
	    &run->s3) < 0)
		return -1;
	warn(run);
	if (api_sampler3_prep(run->smp3, &run->s3, &view) < 0)
		return -1;
	plain = run->s3;
	plain.exact.n = 0;
	if (a->opt.rule == FRS_RULE_EXACT && a->verbose &&
	    api_setup3(run->smp3, a->steps, a->nsteps, a->seed, &view,
	    &run->s3) < 0)
		return -1;
	run->tau0 = frs3_tau(&plain, plain.n);
	run->tsetup = progress_now() - t0;
	return 0;
}

int api_sets_open(const struct api_sets *a, struct api_sets_run *run)
{
	memset(run, 0, sizeof *run);
	run->dims = a->dims;
	run->reused = -1.0;
	/* Flat 1, no public algorithm, is the device's (api_sampler_device):
	 * the sampler's options name Sorted. */
	run->opt = a->opt;
	run->opt.algorithm = a->alg == API_ALG_FLAT1 ? FRS_ALG_SORTED :
	    (enum frs_algorithm)a->alg;
	return run->dims == 3 ? open3(a, run) : open2(a, run);
}

/* One set through the draws; its count, UINT64_MAX after frs_fail. */
static uint64_t one_set(struct out *u, uint64_t seed)
{
	const struct api_sets *a = u->a;
	const struct api_sets_run *run = u->run;
	frs_error err;
	uint64_t count = 0, n = a->steps[a->nsteps - 1];
	int rc;

	u->n = 0;
	if (a->count_only)
		rc = run->dims == 3 ? frs_count3(run->smp3, n, seed, &count, &err) :
		    frs_count(run->smp, n, seed, &count, &err);
	else
		rc = run->dims == 3 ? api_draw3_each(run->smp3, a->steps,
		    a->nsteps, seed, a->pdf, out_batch, u, &err) :
		    frs_draw_each(run->smp, a->steps, a->nsteps, seed, a->pdf,
		    out_batch, u, &err);
	if (rc == FRS_E_CALLBACK)
		return UINT64_MAX;	/* the writer's message */
	if (rc != FRS_OK) {
		frs_fail("%s", err.message);
		return UINT64_MAX;
	}
	if (!a->count_only)
		count = u->n;
	if (out_begin(u, count) < 0)
		return UINT64_MAX;
	if (a->count_only && fprintf(u->of.fp, "%llu\n",
	    (unsigned long long)count) < 0) {
		frs_fail_errno("%s: write error", u->of.name);
		return UINT64_MAX;
	}
	return count;
}

/* The OpenCL phases of the last set, added. */
static void add_times(struct api_sets_run *run)
{
	struct frscl_times ct;

	frscl_last_times(&ct);
	run->ct.build += ct.build;
	run->ct.upload += ct.upload;
	run->ct.kernel += ct.kernel;
	run->ct.download += ct.download;
}

static int write_sets(struct out *u)
{
	const struct api_sets *a = u->a;
	struct api_sets_run *run = u->run;
	struct progress pr;

	progress_begin(&pr, "sets", a->sets);
	for (uint64_t set = 0; set < a->sets; set++) {
		uint64_t c;
		u->collect = a->verbose && set == 0 && !a->count_only &&
		    run->dims == 2;
		u->set = set;
		c = one_set(u, a->seed + set);
		/* Every sample of set 0 noted; more sets report none. */
		run->reused = u->collect ? reused_share(u) : -1.0;
		u->collect = 0;
		if (c == UINT64_MAX)
			return -1;
		if (run->ocl != NULL)
			add_times(run);
		run->total += c;
		progress_update(&pr, set + 1);
	}
	progress_end(&pr);
	return 0;
}

int api_sets_write(const struct api_sets *a, struct api_sets_run *run)
{
	struct out u = { .a = a, .run = run };
	double t1 = progress_now(), t0;
	int rc = write_sets(&u);
	const frs_mask *mk = run->mask;

	/* A damaged twin .frp shows only when its lists are first read. */
	if (rc == 0 && frs_mask_note(mk) != NULL && run->note == NULL)
		frs_warn("%s", frs_mask_note(mk));
	t0 = progress_now();
	if (rc == 0 && !a->count_only && pts_writer_end(&u.w) < 0)
		rc = -1;
	if (rc < 0 && u.open)
		outfile_abort(&u.of);
	else if (rc == 0 && outfile_commit(&u.of) < 0)
		rc = -1;
	run->tout += progress_now() - t0;
	run->tthr = progress_now() - t1 - run->tout - run->tnote;
	run->made = mk->made;
	run->made_in = mk->frp != NULL ? mk->frp : a->matrix;
	run->device = run->ocl != NULL ? run->ocl->name : NULL;
	free(u.uses);
	free(u.rec);
	return rc;
}

void api_sets_close(struct api_sets_run *run)
{
	frs_sampler_free(run->smp);
	frs_sampler3_free(run->smp3);
	frs_mask_free(run->mask);
	if (run->ocl == NULL)
		return;
	frscl_release(run->ocl);
	ocl_close(run->ocl);
	free(run->ocl);
}
