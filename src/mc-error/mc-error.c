/*
 * mc-error: Monte Carlo (or importance-sampling) estimates of integrals
 * over [0,1)^2 of test functions with known values, from point files,
 * and their error averaged over sets, as a TSV table.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "frs.h"
#include "cli/cli.h"
#include "mc-error/integrand.h"

static const char usage[] =
    "usage: mc-error [-f NAME[,NAME...]] [--sets N] [--group n|file|all]\n"
    "                [--weights | --no-pdf | --pdf-map MAP] [--env MAP]\n"
    "                [--strict] [-q]\n"
    "                [-o FILE]\n"
    "                FILE...\n"
    "\n"
    "  -f, --function F  integrands, repeatable or a comma list: gauss,\n"
    "                    disc, step, env (default all but env; env too\n"
    "                    with --env)\n"
    "      --env MAP     env's environment map, equirectangular: PNG,\n"
    "                    OpenEXR or a spec (default the shipped sunset.exr)\n"
    "      --strict      negative values in env's map are an error\n"
    "      --sets N      split every file into sets of N points in\n"
    "                    file order (a file with a set column: its sets)\n"
    "      --group G     a row per point count over all files (n), per\n"
    "                    input file (file) or for all sets (all);\n"
    "                    default a row per point count and file, with a\n"
    "                    file column for several files\n"
    "      --weights     require a pdf column and divide by it\n"
    "      --no-pdf      ignore a pdf column: the plain mean\n"
    "      --pdf-map MAP the density of a point: MAP's pixel there over\n"
    "                    MAP's mean, in place of a pdf column\n"
    "  -o, --output F    output (default standard output)\n"
    "  -q, --quiet       no notes\n"
    "  -h, --help        this help;  --version  the version\n";

/* env's map, when env is requested or --env given. */
static struct frs_imap envmap;
/* --pdf-map's map and its mean, the density of a point being its
 * pixel's value over the mean (as frs-sample --pdf writes it). */
static struct frs_imap pdfmap;
static struct map_pdf pdf;	/* of pdfmap */

#define ENV_BIT (1u << INTEGRAND_ENV)

enum pdfmode { PDF_AUTO, PDF_REQUIRE, PDF_IGNORE, PDF_MAP };

static void parse_functions(const char *arg, unsigned *mask)
{
	char buf[256], *tok, *save = NULL;

	if (strlen(arg) >= sizeof buf)
		cli_usage_error("-f: '%s' is too long", arg);
	strcpy(buf, arg);
	for (tok = strtok_r(buf, ",", &save); tok != NULL;
	    tok = strtok_r(NULL, ",", &save)) {
		size_t i;
		for (i = 0; i < INTEGRANDS && strcmp(tok, integrands[i].name) != 0;
		    i++)
			;
		if (i == INTEGRANDS)
			cli_usage_error("-f: unknown integrand '%s' (gauss, "
			    "disc, step or env)", tok);
		*mask |= 1u << i;
	}
	if (*mask == 0)
		cli_usage_error("-f: no integrand in '%s'", arg);
}

/* A file's sets (from first on) as the pdf mode wants them: a density
 * required by --weights, positive and finite when used (that of
 * --pdf-map's map too).  -1 with a message. */
static int check_pdf(void *ctx, const struct pt_sets *s, size_t file,
    size_t first)
{
	enum pdfmode mode = *(const enum pdfmode *)ctx;
	const char *path = s->set[first].file;

	(void)file;
	if (mode == PDF_REQUIRE && s->set[first].w == NULL)
		return cli_fail("%s: --weights: no pdf column", path);
	/* --pdf-map: every point's pixel must have a positive density. */
	for (size_t j = first; mode == PDF_MAP && j < s->n; j++)
		for (size_t i = 0; i < s->set[j].n; i++) {
			size_t px[2];
			double d = map_pdf_at(&pdf, s->set[j].xy[2 * i],
			    s->set[j].xy[2 * i + 1], px);
			if (!(d > 0) || !isfinite(d))
				return cli_fail("%s: point %zu: --pdf-map: "
				    "density %g in pixel (%zu, %zu) is not "
				    "positive and finite", path,
				    s->set[j].first + i, d, px[0], px[1]);
		}
	/* Points counted from 0 over the file, as its reader counts them. */
	for (size_t j = first; mode < PDF_IGNORE && j < s->n; j++)
		for (size_t i = 0; s->set[j].w != NULL && i < s->set[j].n; i++) {
			double d = s->set[j].w[i];
			if (!(d > 0) || !isfinite(d))
				return cli_fail("%s: point %zu: pdf %g is not "
				    "positive and finite", path,
				    s->set[j].first + i, d);
		}
	return 0;
}

/* One row per group of sets, in order of first appearance. */
static void rows(FILE *fp, const struct integrand *g, const struct pt_sets *s,
    const size_t *group, size_t ngroups, const double *est, int files)
{
	double exact = g->exact(&envmap);

	for (size_t k = 0; k < ngroups; k++) {
		struct group_stat st;
		group_stat(s->set, s->n, group, k, est, exact, &st);
		fprintf(fp, "%s\t%.10g\t%.0f\t%.9g\t%.9g\t%.9g\t%.9g",
		    g->name, st.n, st.sets, st.mean, st.abs_err, st.rmse,
		    st.rmse / fabs(exact));
		if (files) {
			fputc('\t', fp);
			pt_put_name(fp, s->set[st.first].file);
		}
		fputc('\n', fp);
	}
}

static void table(FILE *fp, unsigned mask, enum pt_group grp,
    const struct pt_sets *s, enum pdfmode mode, size_t nfiles)
{
	int files = pt_group_files(grp, nfiles);
	double *est = calloc(s->n, sizeof *est);
	size_t *group = calloc(s->n, sizeof *group), ngroups, most = 0;
	double *w = NULL;

	for (size_t i = 0; mode == PDF_MAP && i < s->n; i++)
		if (s->set[i].n > most)
			most = s->set[i].n;
	if (mode == PDF_MAP && (w = malloc(most * sizeof *w)) == NULL)
		cli_die("no memory for the densities of %zu points", most);
	if (est == NULL || group == NULL)
		cli_die("no memory for %zu sets", s->n);
	ngroups = group_sets(grp, s->set, s->n, group);
	fprintf(fp, "integrand\tn\tsets\testimate_mean\tabs_error\trmse\t"
	    "rel_rmse%s\n", files ? "\tfile" : "");
	for (size_t k = 0; k < INTEGRANDS; k++) {
		if (!(mask & 1u << k))
			continue;
		for (size_t i = 0; i < s->n; i++) {
			const double *d = mode == PDF_MAP ? w :
			    mode == PDF_IGNORE ? NULL : s->set[i].w;
			size_t px[2];
			for (size_t p = 0; mode == PDF_MAP && p < s->set[i].n;
			    p++)
				w[p] = map_pdf_at(&pdf, s->set[i].xy[2 * p],
				    s->set[i].xy[2 * p + 1], px);
			est[i] = integrand_estimate(&integrands[k], &envmap,
			    s->set[i].xy, d, s->set[i].n);
		}
		rows(fp, &integrands[k], s, group, ngroups, est, files);
	}
	free(est);
	free(group);
	free(w);
}

/* The default map: the shipped sunset.exr. */
static const char *default_env(void)
{
	static char path[CLI_PATH_MAX];

	if (cli_data_file("sunset.exr", path, sizeof path) < 0)
		cli_die("env: no default environment map (%s); give --env MAP",
		    cli_errmsg());
	return path;
}

/* Load env's map when env is requested or --env given.  It is radiance
 * over the sphere, whose integrand carries the sin(theta) of solid angle
 * itself: no --equirect here. */
static void load_env(const char *src, unsigned mask, int flags)
{
	if (src == NULL && !(mask & ENV_BIT))
		return;
	if (src == NULL)
		src = default_env();
	if (frs_imap_load(&envmap, src, 0, 0, flags, NULL) != FRS_OK)
		cli_die_lib();
}

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "f=function sets group weights no-pdf pdf-map env strict";

int main(int argc, char **argv)
{
	unsigned mask = 0;
	enum pt_group grp = PT_GROUP_NFILE;
	enum pdfmode mode = PDF_AUTO;
	int c, weights = 0, nopdf = 0, flags = 0;
	const char *env = NULL, *pmap = NULL;
	size_t per = 0;
	struct pt_sets s = { .max_dims = 2 };	/* the integrands are 2-D */
	struct outfile of;

	cli_init("mc-error", usage);
	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 'f': parse_functions(optarg, &mask); break;
		case OPT_SETS: per = cli_sets(optarg); break;
		case OPT_GROUP: grp = cli_group(optarg); break;
		case OPT_WEIGHTS: weights = 1; break;
		case OPT_NO_PDF: nopdf = 1; break;
		case OPT_ENV: env = optarg; break;
		case OPT_PDF_MAP: pmap = optarg; break;
		case OPT_STRICT: flags |= FRS_MAP_STRICT; break;
		default:
			cli_common_only(c, optarg);
		}
	}
	cli_need_files(argc);
	if (weights + nopdf + (pmap != NULL) > 1)
		cli_usage_error("--weights, --no-pdf and --pdf-map exclude each "
		    "other");
	mode = weights ? PDF_REQUIRE : nopdf ? PDF_IGNORE :
	    pmap != NULL ? PDF_MAP : PDF_AUTO;
	if (mask == 0)
		mask = ((1u << INTEGRANDS) - 1) & (env ? ~0u : ~ENV_BIT);
	if (flags && env == NULL && !(mask & ENV_BIT) && pmap == NULL)
		cli_usage_error("--strict: no map to read (it goes with env's, "
		    "-f env or --env MAP, or with --pdf-map MAP)");
	cli_options_done();

	load_env(env, mask, flags);
	if (pmap != NULL) {
		if (frs_imap_load(&pdfmap, pmap, 0, 0, flags, NULL) != FRS_OK)
			cli_die_lib();
		map_pdf_init(&pdf, &pdfmap);
	}
	cli_read_sets(&s, argc, argv, per, check_pdf, &mode);
	cli_out_open(&of, cli.out, 0);
	table(of.fp, mask, grp, &s, mode, (size_t)(argc - optind));
	cli_out_commit(&of, 0);
	pt_sets_free(&s);
	frs_imap_free(&envmap);
	frs_imap_free(&pdfmap);
	return 0;
}
