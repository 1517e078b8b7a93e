/* frs-sample -v's report (sets.h). */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include "frs-sample/sets.h"

/* -v: set 0's setup. */
static void report_setup(FILE *fp, const struct sets *o,
    const struct sets_run *r)
{
	const struct frs_run_info *f = &r->info;
	const uint32_t *m = f->matrix, *v = r->lv[0].map;

	if (r->dims == 2)
		fprintf(fp, "frs-sample: matrix %s %ux%u, map %ux%u, mean "
		    "%.6g, max %.6g\nfrs-sample: n %llu, sigma %g, n_s %u, "
		    "window %llux%llu at (%llu, %llu), tau %.9g, start level "
		    "%u\n", o->matrix, m[0], m[1], v[0], v[1], f->mean, f->max,
		    (unsigned long long)f->n, o->opt.sigma, f->ns,
		    (unsigned long long)f->window[0],
		    (unsigned long long)f->window[1],
		    (unsigned long long)f->offset[0],
		    (unsigned long long)f->offset[1], f->tau, f->start_level);
	else
		fprintf(fp, "frs-sample: matrix %s %ux%ux%u, volume "
		    "%ux%ux%u, mean %.6g, max %.6g\nfrs-sample: n %llu, sigma "
		    "%g, n_s %u, window %llux%llux%llu at (%llu, %llu, %llu), "
		    "tau %.9g\n", o->matrix, m[0], m[1], m[2], v[0], v[1], v[2],
		    f->mean, f->max, (unsigned long long)f->n, o->opt.sigma,
		    f->ns, (unsigned long long)f->window[0],
		    (unsigned long long)f->window[1],
		    (unsigned long long)f->window[2],
		    (unsigned long long)f->offset[0],
		    (unsigned long long)f->offset[1],
		    (unsigned long long)f->offset[2], f->tau);
	if (o->opt.rule == FRS_RULE_EXACT)
		fprintf(fp, "frs-sample: --exact-count: tau %.9g instead of "
		    "%.9g after %u count passes\n", f->tau, f->tau_plain,
		    f->passes);
}

/* -v: set 0's levels, one line each: the level, its elements per cell
 * side, its window and offset, its cells and (when noted) samples. */
static void report_levels(FILE *fp, const struct sets *o,
    const struct sets_run *r)
{
	const struct frs_run_info *f = &r->info;
	int noted = !o->count_only;

	if (r->opt.tiling != FRS_TILING_LEVELS)
		return;
	if (f->levels == 1 && r->lv[0].info.level == 0) {
		fprintf(fp, "frs-sample: levels: every %s at level 0, the "
		    "thesis's window\n", r->dims == 2 ? "pixel" : "voxel");
		return;
	}
	fprintf(fp, "frs-sample: %u level%s of the multi-level window",
	    f->levels, f->levels == 1 ? "" : "s");
	if (f->blur > 0.0)
		fprintf(fp, ", smoothed over %g %s", f->blur, r->dims == 2 ?
		    "pixels" : "voxels");
	fputc('\n', fp);
	for (unsigned i = 0; i < f->levels; i++) {
		const struct frs_level_info *l = &r->lv[i].info;
		if (r->dims == 2)
			fprintf(fp, "frs-sample:   level %u: n_s %u, window "
			    "%llux%llu at (%llu, %llu), tau %.9g", l->level, l->ns,
			    (unsigned long long)l->window[0],
			    (unsigned long long)l->window[1],
			    (unsigned long long)l->offset[0],
			    (unsigned long long)l->offset[1], l->tau);
		else
			fprintf(fp, "frs-sample:   level %u: n_s %u, window "
			    "%llux%llux%llu at (%llu, %llu, %llu), tau %.9g",
			    l->level, l->ns, (unsigned long long)l->window[0],
			    (unsigned long long)l->window[1],
			    (unsigned long long)l->window[2],
			    (unsigned long long)l->offset[0],
			    (unsigned long long)l->offset[1],
			    (unsigned long long)l->offset[2], l->tau);
		if (f->planned)
			fprintf(fp, ", %llu %s", (unsigned long long)l->cells,
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
	const struct frs_run_info *f = &r->info;
	/* One level, level 0, is the thesis's window: its tiles line. */
	int levels = r->opt.tiling == FRS_TILING_LEVELS &&
	    (f->levels > 1 || r->lv[0].info.level > 0);

	report_setup(fp, o, r);
	report_levels(fp, o, r);
	if (r->dims == 2 && r->made != 0)
		fprintf(fp, "frs-sample: %s has no sorted lists of blocks of "
		    "%u: made them here (frd-prep -a sorted --for N makes a .frp "
		    "that has them)\n", r->made_in, r->made);
	if (r->dims == 2 && !levels)
		fprintf(fp, "frs-sample: %llu tiles (%llux%llu), %s",
		    (unsigned long long)(f->tiles[0] * f->tiles[1]),
		    (unsigned long long)f->tiles[0],
		    (unsigned long long)f->tiles[1], f->shuffled ? "shuffled" :
		    "plain");
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
