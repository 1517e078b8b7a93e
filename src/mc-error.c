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

#include "cli/cli.h"
#include "base/datadir.h"
#include "base/err.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "base/outfile.h"
#include "formats/ptsets.h"

static const char usage[] =
    "usage: mc-error [-f NAME[,NAME...]] [--sets N] [--group n|file|all]\n"
    "                [--weights | --no-pdf] [--env MAP] [-q] [-o FILE]\n"
    "                FILE...\n"
    "\n"
    "  -f, --function F  integrands, repeatable or a comma list: gauss,\n"
    "                    disc, step, env (default all but env; env too\n"
    "                    with --env)\n"
    "      --env MAP     env's environment map, equirectangular: PNG,\n"
    "                    OpenEXR or a spec (default the shipped sunset.exr)\n"
    "      --sets N      split every file into sets of N points (a file\n"
    "                    with a set column is split by it; N must agree)\n"
    "      --group G     a row per point count over all files (n), per\n"
    "                    input file (file) or for all sets (all);\n"
    "                    default a row per point count and file, with a\n"
    "                    file column for several files\n"
    "      --weights     require a pdf column and divide by it\n"
    "      --no-pdf      ignore a pdf column: the plain mean\n"
    "  -o, --output F    output (default standard output)\n"
    "  -q, --quiet       no notes\n"
    "  -h, --help        this help;  --version  the version\n";

enum {
	OPT_SETS = OPT_FIRST_PRIVATE, OPT_GROUP, OPT_WEIGHTS, OPT_NO_PDF,
	OPT_ENV
};

static const struct option longopts[] = {
	{ "function", required_argument, NULL, 'f' },
	{ "sets", required_argument, NULL, OPT_SETS },
	{ "group", required_argument, NULL, OPT_GROUP },
	{ "weights", no_argument, NULL, OPT_WEIGHTS },
	{ "no-pdf", no_argument, NULL, OPT_NO_PDF },
	{ "env", required_argument, NULL, OPT_ENV },
	CLI_COMMON_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

#define PI 3.14159265358979323846
#define GAUSS_SIGMA 0.15
#define DISC_R 0.35

static double f_gauss(double x, double y)
{
	double dx = x - 0.5, dy = y - 0.5;
	return exp(-(dx * dx + dy * dy) / (2 * GAUSS_SIGMA * GAUSS_SIGMA));
}

static double f_disc(double x, double y)
{
	double dx = x - 0.5, dy = y - 0.5;
	return dx * dx + dy * dy < DISC_R * DISC_R ? 1.0 : 0.0;
}

/* The half-plane below the line from (0, 0.2) to (1, 0.7). */
static double f_step(double x, double y)
{
	return y < 0.2 + 0.5 * x ? 1.0 : 0.0;
}

static double exact_gauss(void)
{
	/* int_0^1 exp(-(x-1/2)^2 / (2 s^2)) dx, squared */
	double s = GAUSS_SIGMA;
	double one = s * sqrt(2 * PI) * erf(0.5 / (s * sqrt(2.0)));
	return one * one;
}

static double exact_disc(void)
{
	return PI * DISC_R * DISC_R;
}

static double exact_step(void)
{
	return 0.2 + 0.5 / 2;
}

/* env's map: an equirectangular environment map, row 0 at the zenith. */
static struct frs_imap envmap;

/*
 * The irradiance of an upward-facing diffuse surface: (u, v) is the
 * direction phi = 2 pi u, theta = pi v, and 2 pi^2 sin(theta) the
 * Jacobian from the unit square to the sphere.  L is piecewise constant,
 * the pixel containing (u, v).
 */
static double f_env(double u, double v)
{
	double c = cos(PI * v);
	size_t x = (size_t)(u * envmap.w), y = (size_t)(v * envmap.h);

	if (!(c > 0))
		return 0.0;
	if (x >= envmap.w)
		x = envmap.w - 1;
	if (y >= envmap.h)
		y = envmap.h - 1;
	return envmap.v[y * envmap.w + x] * c * sin(PI * v) * 2 * PI * PI;
}

/*
 * The exact integral of f_env over row y's band [a, b] of v, b clipped to
 * 1/2, per unit of L averaged over the row: 2 pi^2 int_a^b cos sin dv =
 * pi (sin^2(pi b) - sin^2(pi a)) = pi sin(pi (b - a)) sin(pi (a + b)),
 * the last form free of cancellation.
 */
static double env_row_weight(uint32_t y, uint32_t h)
{
	double a = (double)y / h, b = (double)(y + 1) / h;

	if (a >= 0.5)
		return 0.0;
	if (b > 0.5)
		b = 0.5;
	return PI * sin(PI * (b - a)) * sin(PI * (a + b));
}

/* The sum over pixels of L times its row's weight, in long double. */
static double exact_env(void)
{
	long double total = 0;

	for (uint32_t y = 0; y < envmap.h; y++) {
		long double row = 0;
		double wgt = env_row_weight(y, envmap.h);
		if (wgt == 0)
			break;
		for (uint32_t x = 0; x < envmap.w; x++)
			row += envmap.v[(size_t)y * envmap.w + x];
		total += row / envmap.w * wgt;
	}
	return (double)total;
}

static const struct integrand {
	const char *name;
	double (*f)(double, double);
	double (*exact)(void);
} fun[] = {
	{ "gauss", f_gauss, exact_gauss },
	{ "disc", f_disc, exact_disc },
	{ "step", f_step, exact_step },
	{ "env", f_env, exact_env },
};
#define NFUN (sizeof fun / sizeof fun[0])
#define ENV_BIT (1u << (NFUN - 1))

enum pdfmode { PDF_AUTO, PDF_REQUIRE, PDF_IGNORE };

static void parse_functions(const char *arg, unsigned *mask)
{
	char buf[256], *tok, *save = NULL;

	if (strlen(arg) >= sizeof buf)
		cli_usage_error("-f: '%s' is too long", arg);
	strcpy(buf, arg);
	for (tok = strtok_r(buf, ",", &save); tok != NULL;
	    tok = strtok_r(NULL, ",", &save)) {
		size_t i;
		for (i = 0; i < NFUN && strcmp(tok, fun[i].name) != 0; i++)
			;
		if (i == NFUN)
			cli_usage_error("-f: unknown integrand '%s' (gauss, "
			    "disc, step or env)", tok);
		*mask |= 1u << i;
	}
	if (*mask == 0)
		cli_usage_error("-f: no integrand in '%s'", arg);
}

/* Read a file as sets (pt_sets_add) and check its densities: required
 * by --weights, positive and finite when used.  -1 with a message. */
static int add_file(struct pt_sets *s, const char *path, size_t per,
    enum pdfmode mode)
{
	size_t first = s->n;

	if (pt_sets_add(s, path, per) < 0)
		return -1;
	if (mode == PDF_REQUIRE && s->set[first].w == NULL)
		return frs_fail("%s: --weights: no pdf column", path);
	/* Points counted from 0 over the file, as its reader counts them. */
	for (size_t j = first; mode != PDF_IGNORE && j < s->n; j++)
		for (size_t i = 0; s->set[j].w != NULL && i < s->set[j].n; i++) {
			double d = s->set[j].w[i];
			if (!(d > 0) || !isfinite(d))
				return frs_fail("%s: point %zu: pdf %g is not "
				    "positive and finite", path,
				    s->set[j].first + i, d);
		}
	return 0;
}

/* The estimate of one set: mean f, or mean f / pdf. */
static double estimate(const struct integrand *g, const struct pt_set *s,
    enum pdfmode mode)
{
	const double *w = mode == PDF_IGNORE ? NULL : s->w;
	double sum = 0;

	for (size_t i = 0; i < s->n; i++) {
		double v = g->f(s->xy[2 * i], s->xy[2 * i + 1]);
		sum += w ? v / w[i] : v;
	}
	return sum / (double)s->n;
}

/* One row per group of sets, in order of first appearance. */
static void rows(FILE *fp, const struct integrand *g, enum pt_group grp,
    const struct pt_sets *s, const double *est, char *done, int files)
{
	double exact = g->exact();

	memset(done, 0, s->n);
	for (size_t i = 0; i < s->n; i++) {
		double m = 0, sn = 0, se = 0, sa = 0, s2 = 0, rmse;
		if (done[i])
			continue;
		for (size_t j = i; j < s->n; j++) {
			double e;
			if (done[j] || !pt_same_group(grp, &s->set[i], &s->set[j]))
				continue;
			e = est[j] - exact;
			m++, sn += (double)s->set[j].n, se += est[j];
			sa += fabs(e), s2 += e * e;
			done[j] = 1;
		}
		rmse = sqrt(s2 / m);
		fprintf(fp, "%s\t%.10g\t%.0f\t%.9g\t%.9g\t%.9g\t%.9g",
		    g->name, sn / m, m, se / m, sa / m, rmse,
		    rmse / fabs(exact));
		if (files) {
			fputc('\t', fp);
			pt_put_name(fp, s->set[i].file);
		}
		fputc('\n', fp);
	}
}

static void table(FILE *fp, unsigned mask, enum pt_group grp,
    const struct pt_sets *s, enum pdfmode mode, size_t nfiles)
{
	int files = pt_group_files(grp, nfiles);
	double *est = calloc(s->n, sizeof *est);
	char *done = calloc(s->n, 1);

	if (est == NULL || done == NULL)
		cli_die("no memory for %zu sets", s->n);
	fprintf(fp, "integrand\tn\tsets\testimate_mean\tabs_error\trmse\t"
	    "rel_rmse%s\n", files ? "\tfile" : "");
	for (size_t k = 0; k < NFUN; k++) {
		if (!(mask & 1u << k))
			continue;
		for (size_t i = 0; i < s->n; i++)
			est[i] = estimate(&fun[k], &s->set[i], mode);
		rows(fp, &fun[k], grp, s, est, done, files);
	}
	free(est);
	free(done);
}

/* The default map: the shipped sunset.exr (datadir.h). */
static const char *default_env(void)
{
	static char path[DATA_PATH_MAX];

	if (data_find("sunset.exr", path, sizeof path) < 0)
		cli_die("env: no default environment map (%s); give --env MAP",
		    frs_errmsg());
	return path;
}

/* Load env's map when env is requested or --env given. */
static void load_env(const char *src, unsigned mask)
{
	if (src == NULL && !(mask & ENV_BIT))
		return;
	if (src == NULL)
		src = default_env();
	if (imap_load(src, 0, 0, 0, &envmap) < 0)
		cli_die_lib();
}

static enum pt_group parse_group(const char *arg)
{
	int g = pt_group_parse(arg);

	if (g < 0)
		cli_usage_error("--group: '%s' is not n, file or all", arg);
	return (enum pt_group)g;
}

int main(int argc, char **argv)
{
	unsigned mask = 0;
	enum pt_group grp = PT_GROUP_NFILE;
	enum pdfmode mode = PDF_AUTO;
	int c, weights = 0, nopdf = 0;
	const char *env = NULL;
	size_t per = 0;
	struct pt_sets s = { .max_dims = 2 };	/* the integrands are 2-D */
	struct outfile of;

	cli_init("mc-error", usage);
	while ((c = cli_getopt(argc, argv, "f:" CLI_COMMON_SHORTOPTS,
	    longopts)) != -1) {
		switch (c) {
		case 'f': parse_functions(optarg, &mask); break;
		case OPT_SETS:
			per = (size_t)cli_u64("--sets", optarg, 1,
			    (uint64_t)1 << 40);
			break;
		case OPT_GROUP: grp = parse_group(optarg); break;
		case OPT_WEIGHTS: weights = 1; break;
		case OPT_NO_PDF: nopdf = 1; break;
		case OPT_ENV: env = optarg; break;
		default:
			if (!cli_common_opt(c, optarg))
				cli_usage(2);
		}
	}
	if (optind == argc)
		cli_usage_error("no point files");
	if (weights && nopdf)
		cli_usage_error("--weights and --no-pdf exclude each other");
	mode = weights ? PDF_REQUIRE : nopdf ? PDF_IGNORE : PDF_AUTO;
	if (mask == 0)
		mask = ((1u << NFUN) - 1) & (env ? ~0u : ~ENV_BIT);
	cli_options_done();

	load_env(env, mask);
	for (int i = optind; i < argc; i++)
		if (add_file(&s, argv[i], per, mode) < 0)
			cli_die_lib();
	if (outfile_open(&of, cli.out, 0) < 0)
		cli_die_lib();
	table(of.fp, mask, grp, &s, mode, (size_t)(argc - optind));
	if (outfile_commit(&of) < 0)
		cli_die_lib();
	pt_sets_free(&s);
	imap_free(&envmap);
	return 0;
}
