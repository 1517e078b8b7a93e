/* frs-sample -v's report (sets.h). */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include "frs-sample/sets.h"

/* -v: set 0's setup. */
static void report_setup(FILE *fp, const struct sets *o,
    const struct sets_run *r)
{
	const struct frs_setup *s = &r->s0;
	const struct frs3_setup *t = &r->s3;

	if (r->dims == 2)
		fprintf(fp, "frs-sample: matrix %s %ux%u, map %ux%u, mean "
		    "%.6g, max %.6g\nfrs-sample: n %llu, sigma %g, n_s %u, "
		    "window %llux%llu at (%llu, %llu), tau %.9g, start level "
		    "%u\n", o->matrix, s->mw, s->mh, s->iw, s->ih, s->mean,
		    s->max, (unsigned long long)s->n, s->sigma, s->ns,
		    (unsigned long long)s->sw, (unsigned long long)s->sh,
		    (unsigned long long)s->wx, (unsigned long long)s->wy, s->tau,
		    s->level0);
	else
		fprintf(fp, "frs-sample: matrix %s %ux%ux%u, volume "
		    "%ux%ux%u, mean %.6g, max %.6g\nfrs-sample: n %llu, sigma "
		    "%g, n_s %u, window %llux%llux%llu at (%llu, %llu, %llu), "
		    "tau %.9g\n", o->matrix, t->mw, t->mh, t->md, t->iw, t->ih,
		    t->id, t->mean, t->max, (unsigned long long)t->n, t->sigma,
		    t->ns, (unsigned long long)t->sw, (unsigned long long)t->sh,
		    (unsigned long long)t->sd, (unsigned long long)t->wx,
		    (unsigned long long)t->wy, (unsigned long long)t->wz, t->tau);
	if (o->opt.rule == FRS_RULE_EXACT)
		fprintf(fp, "frs-sample: --exact-count: tau %.9g instead of "
		    "%.9g after %u count passes\n", r->dims == 2 ? s->tau : t->tau,
		    r->tau0, r->dims == 2 ? s->exact.passes : t->exact.passes);
}

/* -v: set 0's levels, one line each: the level, its elements per cell
 * side, its window and offset, its cells and (when noted) samples. */
static void report_levels(FILE *fp, const struct sets *o,
    const struct sets_run *r)
{
	unsigned n = r->dims == 2 ? r->lv.n : r->lv3.n;
	int noted = !o->count_only;
	double blur = r->dims == 2 ? r->lv.plan.blur : r->lv3.plan.blur;

	if (r->opt.tiling != FRS_TILING_LEVELS)
		return;
	if (n == 1 && (r->dims == 2 ? r->lv.su[0].level :
	    r->lv3.su[0].level) == 0) {
		fprintf(fp, "frs-sample: levels: every %s at level 0, the "
		    "thesis's window\n", r->dims == 2 ? "pixel" : "voxel");
		return;
	}
	fprintf(fp, "frs-sample: %u level%s of the multi-level window", n,
	    n == 1 ? "" : "s");
	if (blur > 0.0)
		fprintf(fp, ", smoothed over %g %s", blur, r->dims == 2 ?
		    "pixels" : "voxels");
	fputc('\n', fp);
	for (unsigned i = 0; i < n; i++) {
		const struct frs_setup *s = &r->lv.su[i];
		const struct frs3_setup *t = &r->lv3.su[i];
		const struct frs_levels *L = r->dims == 2 ? &r->lv.plan :
		    &r->lv3.plan;
		unsigned l = r->dims == 2 ? s->level : t->level;
		uint64_t cells = L->lev != NULL ? L->cells[l] : 0;
		if (r->dims == 2)
			fprintf(fp, "frs-sample:   level %u: n_s %u, window "
			    "%llux%llu at (%llu, %llu), tau %.9g", l, s->ns,
			    (unsigned long long)s->sw, (unsigned long long)s->sh,
			    (unsigned long long)s->wx, (unsigned long long)s->wy,
			    s->tau);
		else
			fprintf(fp, "frs-sample:   level %u: n_s %u, window "
			    "%llux%llux%llu at (%llu, %llu, %llu), tau %.9g", l,
			    t->ns, (unsigned long long)t->sw,
			    (unsigned long long)t->sh, (unsigned long long)t->sd,
			    (unsigned long long)t->wx, (unsigned long long)t->wy,
			    (unsigned long long)t->wz, t->tau);
		if (L->lev != NULL)
			fprintf(fp, ", %llu %s", (unsigned long long)cells,
			    r->dims == 2 ? "pixels" : "voxels");
		if (noted)
			fprintf(fp, ", %llu samples", (unsigned long long)
			    r->lcount[i]);
		if (noted && r->lreused[i] >= 0.0)
			fprintf(fp, " (%.1f %% showing a matrix element another "
			    "shows too)", 100.0 * r->lreused[i]);
		fputc('\n', fp);
	}
}

void sets_report(FILE *fp, const struct sets *o,
    const struct sets_run *r)
{
	uint64_t tx = 0, ty = 0;
	uint64_t nt = r->dims == 2 ? frs_tiles(&r->s0, &tx, &ty) : 0;
	/* One level, level 0, is the thesis's window: its tiles line. */
	int levels = r->opt.tiling == FRS_TILING_LEVELS &&
	    (r->dims == 2 ? r->lv.n > 1 || r->lv.su[0].level > 0 :
	    r->lv3.n > 1 || r->lv3.su[0].level > 0);

	report_setup(fp, o, r);
	report_levels(fp, o, r);
	if (r->dims == 2 && r->made != 0)
		fprintf(fp, "frs-sample: %s has no sorted lists of blocks of "
		    "%u: made them here (frd-prep -a sorted --for N makes a .frp "
		    "that has them)\n", r->made_in, r->made);
	if (r->dims == 2 && !levels)
		fprintf(fp, "frs-sample: %llu tiles (%llux%llu), %s",
		    (unsigned long long)nt, (unsigned long long)tx,
		    (unsigned long long)ty, r->s0.tiles != FRS_TILES_SHUFFLE ?
		    "plain" : "shuffled");
	else if (r->dims == 2 && r->reused >= 0.0)
		fprintf(fp, "frs-sample: levels");
	if (r->dims == 2 && r->reused >= 0.0)
		fprintf(fp, "; %.1f %% of the samples show a matrix element "
		    "that another one %sshows too", 100.0 * r->reused, levels ?
		    "of their level " : "");
	if (r->dims == 2 && (!levels || r->reused >= 0.0))
		fputc('\n', fp);
	if (r->dims == 2 && o->sets > 1)
		fprintf(fp, "frs-sample: %llu sets, seeds %llu to %llu\n",
		    (unsigned long long)o->sets, (unsigned long long)o->seed,
		    (unsigned long long)(o->seed + o->sets - 1));
	fprintf(fp, "frs-sample: %llu samples (%s); setup %.6f s, "
	    "thresholding %.6f s, output %.6f s", (unsigned long long)r->total,
	    o->flat1 ? "flat1" : frs_names(FRS_NAMES_ALGORITHM)[o->alg],
	    r->tsetup, r->tthr, r->tout);
	if (r->tnote > 0.0)
		fprintf(fp, " (and %.6f s for -v's share)", r->tnote);
	fputc('\n', fp);
	if (r->device != NULL)
		fprintf(fp, "frs-sample: OpenCL device %s: build %.6f s, "
		    "to the device %.6f s, kernels %.6f s, back and offsets "
		    "%.6f s\n", r->device, r->ct.build, r->ct.upload,
		    r->ct.kernel, r->ct.download);
}
