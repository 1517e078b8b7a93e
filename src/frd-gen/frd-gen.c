/*
 * frd-gen: Forced Random Dithering threshold matrices.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "frs.h"
#include "cli/cli.h"
#include "frd-gen/frdgen.h"
#include "frd-gen/frdgencl.h"
#include "frd-gen/frdq.h"
#include "frd-gen/vac.h"

static const char usage[] =
    "usage: frd-gen -s SIZE [-k 2|3] [-p P] [--tol EPS | --exact] [-S SEED]\n"
    "               [--reach R] [--reach-cap C] [--cutoff taper|hard]\n"
    "               [-j N] [--checkpoint FILE] [--device cpu|cl|cl:N] [-v]\n"
    "               [-o FILE]\n"
    "       frd-gen --field int32 -s SIZE [-k 2|3] [-p P] [-S SEED] ...\n"
    "       frd-gen --method vac -s SIZE [-k 2|3] [--vac-sigma S]\n"
    "               [--tol EPS | --exact] [-S SEED] [-v] [-o FILE]\n"
    "       frd-gen --quality FILE...\n"
    "       frd-gen --list-devices\n"
    "\n"
    "  -s, --size SIZE     N (N x N, or N^3 with -k 3), WxH or WxHxD\n"
    "  -k, --dims K        2 (default) or 3\n"
    "      --method M      frd (default: Forced Random Dithering) or vac\n"
    "                      (Ulichney's void-and-cluster, a baseline)\n"
    "      --vac-sigma S   vac: Gaussian filter sigma in cells (default 1.5)\n"
    "  -p, --fraction P    candidate fraction in (0, 1] (default 0.5;\n"
    "                      1 = always the global minimum)\n"
    "      --field F       double (default: f(r) = exp(-(r/S)^Q)) or int32\n"
    "                      (the thesis authors' integer table and reach)\n"
    "      --tol EPS       neglect forces below EPS * f(0) (default 1e-2;\n"
    "                      the radius at least S (EPS^(-1/Q) - 1) cells,\n"
    "                      with exp S (ln 1/EPS)^(1/Q));\n"
    "                      vac: the filter below EPS (default 1e-4, radius\n"
    "                      S sqrt(2 ln 1/EPS))\n"
    "      --exact         keep every contribution (frd: O(N^2); vac: the\n"
    "                      whole torus)\n"
    "      --reach R       radius at least R times the spacing of the values\n"
    "                      inserted so far (default 3, 0 = off)\n"
    "      --reach-cap C   radius at most C times the shortest side\n"
    "                      (default 0.333, 0 = off)\n"
    "      --cutoff K      taper (default: f(r) - f(R) inside the radius R)\n"
    "                      or hard (f(r))\n"
    "      --force F       power (default: f(r) = (1 + r/S)^-Q) or exp\n"
    "                      (the thesis's f(r) = exp(-(r/S)^Q))\n"
    "      --force-s S     default S = 1 (exp: 0.5)\n"
    "      --force-q Q     default Q = 4 (exp: 0.5)\n"
    "  -S, --seed N        random seed (default 1)\n"
    "  -j, --threads N     threads (default: all cores); same bytes for any N\n"
    "      --checkpoint F  resume from F if it holds a run with the same\n"
    "                      parameters; save progress there every minute\n"
    "      --checkpoint-every SEC  seconds between saves (default 60)\n"
    "      --device DEV    cpu (default), cl (first OpenCL device) or cl:N;\n"
    "                      the same bytes on every device (needs fp64)\n"
    "      --list-devices  list the OpenCL devices and exit\n"
    "  -v, --verbose       print time and quality figures on standard error\n"
    "      --quality FILE...  print the quality figures of matrices and exit\n"
    "  -o, --output FILE   output (default: standard output)\n"
    "  -q, --quiet         no progress bar or warnings\n"
    "      --progress      progress bar even when standard error is no tty\n"
    "  -h, --help          this help;  --version  the version\n";

/* "N", "WxH" or "WxHxD"; N means a cube for k = 3. */
static void parse_dims(const char *s, struct frdgen_params *pr)
{
	uint32_t sz[3];
	int given = cli_size3("-s", s, UINT32_MAX, sz);

	pr->w = sz[0];
	pr->h = sz[1];
	pr->d = given == 3 || (given == 1 && pr->dims == 3) ? sz[2] : 1;
}

/* The levels that --quality measures: the first c = 64, 128, ... N/4
 * values, and the last 2.5 % (the black dots of Fig. 3.1's 97.5 % grey). */
#define MAXLEVELS 40

struct levels {
	const struct frs_matrix *m;
	struct frdq_level q[MAXLEVELS];
	size_t n;
};

static int level_task(void *ctx, uint64_t b, uint64_t e)
{
	struct levels *l = ctx;
	for (uint64_t i = b; i < e; i++)
		if (frdq_level(l->m, l->q[i].lo, l->q[i].hi, &l->q[i]) < 0)
			return -1;
	return 0;
}

static int measure_levels(const struct frs_matrix *m, struct levels *l)
{
	l->m = m;
	l->n = 0;
	for (uint64_t c = 64; c <= m->n / 4 && l->n + 1 < MAXLEVELS; c *= 2) {
		l->q[l->n].lo = 0;
		l->q[l->n++].hi = c;
	}
	if (m->n >= 2560) {
		l->q[l->n].lo = m->n - m->n / 40;
		l->q[l->n++].hi = m->n;
	}
	return cli_parallel(l->n, 1, level_task, l, NULL);
}

static void print_level(FILE *fp, const struct frdq_level *q, const char *k)
{
	fprintf(fp, "strata_%s %.4f\n", k, q->strata);
	if (!q->spectral)
		return;
	fprintf(fp, "pmax_%s %.2f\npeak_%s %.3f\nring_%s %.3f\n"
	    "aniso_%s %.2f\n", k, q->pmax, k, q->peak, k, q->ring, k, q->aniso);
}

/* The bounds of frd-gen(1): a level with a periodogram maximum above 30 or
 * more than 95 % of its strata singly occupied looks like a lattice. */
#define PMAX_BOUND 30.0
#define STRATA_BOUND 0.95

static void print_levels(FILE *fp, const struct levels *l)
{
	const struct frdq_level *wp = NULL, *ws = NULL;
	char key[32];

	for (size_t i = 0; i < l->n; i++) {
		const struct frdq_level *q = &l->q[i];
		int last = q->lo > 0;
		if (last)
			snprintf(key, sizeof key, "last_2.5%%");
		else
			snprintf(key, sizeof key, "%llu", (unsigned long long)q->hi);
		print_level(fp, q, key);
		if (last)
			continue;
		if (q->spectral && (wp == NULL || q->pmax > wp->pmax))
			wp = q;
		if (ws == NULL || q->strata > ws->strata)
			ws = q;
	}
	if (wp != NULL)
		fprintf(fp, "pmax_worst %.2f\npmax_worst_at %llu\n", wp->pmax,
		    (unsigned long long)wp->hi);
	if (ws != NULL)
		fprintf(fp, "strata_worst %.4f\nstrata_worst_at %llu\n",
		    ws->strata, (unsigned long long)ws->hi);
	if (ws != NULL)
		fprintf(fp, "lattice_check %s\n", (wp != NULL && wp->pmax >
		    PMAX_BOUND) || ws->strata > STRATA_BOUND ? "fail" : "pass");
}

static int print_quality(FILE *fp, const struct frs_matrix *m,
    const char *name)
{
	static const uint32_t cs[] = { 16, 64, 256, 1024 };
	static const double levels[] = { 2.5, 10 };
	struct levels *l;
	double ratio, peak;

	fprintf(fp, "matrix %s\nsize %ux%ux%u\n", name, m->w, m->h, m->d);
	for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++)
		if (cs[i] <= m->n / 4)
			fprintf(fp, "spread_%u %.4f\n", cs[i],
			    frdq_spread(m, cs[i]));
	/* First and last values: the late ones show what the radius cuts. */
	for (size_t i = 0; i < sizeof levels / sizeof levels[0]; i++) {
		if (frdq_spectrum(m, 0.0, levels[i] / 100.0, &ratio, &peak) == 0)
			fprintf(fp, "lowpass_first_%g%% %.4f\npeak_first_%g%% %.3f\n",
			    levels[i], ratio, levels[i], peak);
		if (frdq_spectrum(m, 1.0 - levels[i] / 100.0, 1.0, &ratio,
		    &peak) == 0)
			fprintf(fp, "lowpass_last_%g%% %.4f\npeak_last_%g%% %.3f\n",
			    levels[i], ratio, levels[i], peak);
	}
	l = malloc(sizeof *l);
	if (l == NULL || measure_levels(m, l) < 0) {
		free(l);
		return -1;
	}
	print_levels(fp, l);
	free(l);
	return 0;
}

/* --quality: the figures of one matrix file on standard output. */
static void quality(const char *path)
{
	struct frs_matrix m;

	if (frs_matrix_read(&m, path, NULL) != FRS_OK ||
	    print_quality(stdout, &m, path) < 0)
		cli_die_lib();
	frs_matrix_free(&m);
}

/* -v: the figures of the matrix just written, on standard error. */
static void report_quality(const struct frs_matrix *m)
{
	if (print_quality(stderr, m, cli.out ? cli.out : "<stdout>") < 0)
		cli_die_lib();
}

static void check_memory(const struct frdgen_params *pr, uint64_t bytes)
{
	char what[64];

	snprintf(what, sizeof what, "-s %ux%ux%u", pr->w, pr->h, pr->d);
	cli_mem_check(what, bytes, 1);
}

/* What the options asked for beyond struct frdgen_params. */
struct method_opts {
	int vac;		/* --method vac */
	int tol_set;		/* --tol or --exact given */
	double vac_sigma;	/* --vac-sigma, 0 when not given */
	const char *frd_only;	/* an option given that only frd uses */
	const char *dbl_only;	/* one that only --field double uses */
};

/* Everything the command line asked for. */
struct gen_opts {
	struct frdgen_params pr;
	struct method_opts mo;
	const char *size;	/* -s, read once -k is known */
	const char *qfile;	/* --quality: the first file */
	int verbose;
	int use_cl, dev;	/* --device */
	int s_set, q_set;	/* --force-s, --force-q given */
};

/* Which of two words an option names: 0 for a, 1 for b. */
static int parse_choice(const char *opt, const char *s, const char *a,
    const char *b)
{
	const char *const w[] = { a, b, NULL };

	return cli_choice(opt, s, w);
}

/* --tol: 0 would be --exact, which the hint names. */
static void parse_tol(struct frdgen_params *pr, const char *s)
{
	pr->tol = cli_double_above_hint("--tol", s, 0.0, 0.999999,
	    "; --exact keeps every contribution");
}

/* The options that another method or field refuses (check_method), each
 * noted as it comes: --tol and --exact are not for --field int32; -p,
 * --field and the checkpoints not for --method vac; the force's options
 * for neither.  1 if c is one of them. */
static int parse_frd_opt(struct gen_opts *g, int c)
{
	struct frdgen_params *pr = &g->pr;
	const char *opt;

	switch (c) {
	case OPT_TOL:
		parse_tol(pr, optarg);
		g->mo.tol_set = 1;
		g->mo.dbl_only = "--tol";
		return 1;
	case OPT_EXACT:
		pr->tol = 0.0;
		g->mo.tol_set = 1;
		g->mo.dbl_only = "--exact";
		return 1;
	case 'p':
		pr->p = cli_double_above("-p", optarg, 0.0, 1.0);
		g->mo.frd_only = "-p";
		return 1;
	case OPT_FIELD:
		pr->field = parse_choice("--field", optarg, "double", "int32") ?
		    FRDGEN_FIELD_INT32 : FRDGEN_FIELD_DOUBLE;
		g->mo.frd_only = "--field";
		return 1;
	case OPT_CHECKPOINT:
		pr->checkpoint = cli_outname("--checkpoint", optarg);
		g->mo.frd_only = "--checkpoint";
		return 1;
	case OPT_CHECKPOINT_EVERY:
		pr->checkpoint_every = cli_double("--checkpoint-every", optarg,
		    0.0, 1e9);
		g->mo.frd_only = "--checkpoint-every";
		return 1;
	case OPT_REACH:
		opt = "--reach";
		pr->reach = cli_double(opt, optarg, 0.0, 1e6);
		break;
	case OPT_REACH_CAP:
		opt = "--reach-cap";
		pr->cap = cli_double(opt, optarg, 0.0, 1e6);
		break;
	case OPT_CUTOFF:
		opt = "--cutoff";
		pr->taper = parse_choice(opt, optarg, "hard", "taper");
		break;
	case OPT_FORCE:
		opt = "--force";
		pr->force = parse_choice(opt, optarg, "power", "exp") ?
		    FRDGEN_FORCE_EXP : FRDGEN_FORCE_POWER;
		break;
	case OPT_FORCE_S:
		opt = "--force-s";
		pr->s = cli_double(opt, optarg, 1e-6, 1e6);
		g->s_set = 1;
		break;
	case OPT_FORCE_Q:
		opt = "--force-q";
		pr->q = cli_double(opt, optarg, 1e-3, 100.0);
		g->q_set = 1;
		break;
	default:
		return 0;
	}
	g->mo.frd_only = g->mo.dbl_only = opt;
	return 1;
}

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "s=size k=dims p=fraction tol exact reach force-s force-q "
    "checkpoint checkpoint-every quality device list-devices "
    "method vac-sigma field reach-cap cutoff force v=verbose";

static void parse_opts(int argc, char **argv, struct gen_opts *g)
{
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		if (parse_frd_opt(g, c))
			continue;
		switch (c) {
		case 's': g->size = optarg; break;
		case 'k':
			g->pr.dims = (unsigned)cli_ll("-k", optarg, 2, 3);
			break;
		case OPT_METHOD:
			g->mo.vac = parse_choice("--method", optarg, "frd",
			    "vac");
			break;
		case OPT_VAC_SIGMA:
			g->mo.vac_sigma = cli_double_above("--vac-sigma", optarg,
			    0.0, 1e6);
			break;
		case OPT_QUALITY: g->qfile = optarg; break;
		case OPT_DEVICE: g->use_cl = cli_device(optarg, &g->dev); break;
		case OPT_LIST_DEVICES: cli_list_devices();
		case 'v': g->verbose = 1; break;
		default:
			cli_common_only(c, optarg);
		}
	}
}

/* Options of the other method or field are refused, not silently
 * ignored. */
static void check_method(const struct method_opts *mo,
    const struct frdgen_params *pr, int use_cl)
{
	if (pr->field == FRDGEN_FIELD_INT32) {
		if (mo->dbl_only != NULL)
			cli_usage_error("%s: not used by --field int32 (its "
			    "table fixes force and radius)", mo->dbl_only);
		if (mo->vac)
			cli_usage_error("--field: not used by --method vac");
	}
	if (!mo->vac) {
		if (mo->vac_sigma > 0.0)
			cli_usage_error("--vac-sigma: only with --method vac");
		return;
	}
	if (mo->frd_only != NULL)
		cli_usage_error("%s: not used by --method vac", mo->frd_only);
	if (use_cl)
		cli_usage_error("--device: --method vac runs on the CPU only");
}

/* The size, the seed and the defaults that depend on other options. */
static void check_opts(int argc, char **argv, struct gen_opts *g)
{
	cli_no_operands(argc, argv);
	if (g->size == NULL)
		cli_usage_error("-s SIZE is required");
	parse_dims(g->size, &g->pr);
	g->pr.seed = cli.seed;
	/* The thesis's force with its own parameters unless given. */
	if (g->pr.force == FRDGEN_FORCE_EXP) {
		g->pr.s = g->s_set ? g->pr.s : 0.5;
		g->pr.q = g->q_set ? g->pr.q : 0.5;
	}
	check_method(&g->mo, &g->pr, g->use_cl);
}

/* After a run: the progress bar closed, and if the run failed the
 * output removed. */
static void end_run(int rc, struct cli_task *task, struct outfile *of)
{
	cli_task_end(task);
	if (rc < 0) {
		outfile_abort(of);
		cli_die_lib();
	}
}

/* Write a finished matrix to the open output, or die removing it. */
static void write_matrix(struct outfile *of, const struct frs_matrix *m)
{
	cli_out_commit(of, frs_matrix_write(m, of->fp, of->name, NULL) ==
	    FRS_OK ? 0 : -1);
}

/* --method vac: the void-and-cluster baseline (vac.h). */
static int run_vac(const struct frdgen_params *pr,
    const struct method_opts *mo, int verbose)
{
	struct vac_params vp;
	struct vac_stats st;
	struct frs_matrix m;
	struct outfile of;
	struct cli_task *task;
	double t0;

	vac_defaults(&vp);
	vp.dims = pr->dims;
	vp.w = pr->w;
	vp.h = pr->h;
	vp.d = pr->d;
	vp.seed = pr->seed;
	if (mo->vac_sigma > 0.0)
		vp.sigma = mo->vac_sigma;
	if (mo->tol_set)
		vp.tol = pr->tol;
	if (vac_check(&vp) < 0)
		cli_usage_error("%s", cli_errmsg());
	check_memory(pr, vac_memory(&vp));
	cli_options_done();
	cli_out_open(&of, cli.out, 1);
	t0 = cli_now();
	task = cli_task_begin("void-and-cluster", (uint64_t)vp.w * vp.h * vp.d);
	end_run(vac_run(&vp, &m, task, &st), task, &of);
	write_matrix(&of, &m);
	if (verbose) {
		fprintf(stderr, "frd-gen: void-and-cluster %ux%ux%u in %.3f s "
		    "(sigma %g, radius %.1f, %llu initial cells, %llu moves)\n",
		    vp.w, vp.h, vp.d, cli_now() - t0, vp.sigma, st.radius,
		    (unsigned long long)st.ones, (unsigned long long)st.moves);
		report_quality(&m);
	}
	frs_matrix_free(&m);
	return 0;
}

/* --device cl: the device before the output, so that a missing one
 * fails at once. */
static struct ocl *open_device(int dev)
{
	struct ocl *o = cli_device_open(dev, 1);

	if (!cli_device_fp64(o))
		cli_die("--device: OpenCL: %s has no double precision "
		    "(cl_khr_fp64), which frd-gen needs to give the same matrix "
		    "as --device cpu", cli_device_name(o));
	return o;
}

/* -v: the time and the radius at the first and the last value. */
static void report_frd(const struct frdgen_params *pr,
    const struct frs_matrix *m, double secs, const char *where)
{
	double rt = frdgen_radius(pr);

	fprintf(stderr, "frd-gen: %ux%ux%u in %.3f s (radius %.1f to "
	    "%.1f) on %s\n", pr->w, pr->h, pr->d, secs,
	    frdgen_radius_after(pr, rt, 1), frdgen_radius_after(pr, rt, m->n),
	    where);
	report_quality(m);
}

/* --method frd (the default), on the CPU or the device. */
static int run_frd(const struct gen_opts *g)
{
	const struct frdgen_params *pr = &g->pr;
	struct frs_matrix m;
	struct outfile of;
	struct cli_task *task;
	struct ocl *o = NULL;
	double t0;

	if (frdgen_check(pr) < 0)
		cli_usage_error("%s", cli_errmsg());
	if (g->use_cl && pr->checkpoint != NULL)
		cli_usage_error("--checkpoint: not available with --device cl");
	check_memory(pr, frdgen_memory(pr));
	cli_options_done();
	if (g->use_cl)
		o = open_device(g->dev);
	/* Open the output first: a bad path fails before hours of work. */
	cli_out_open(&of, cli.out, 1);
	t0 = cli_now();
	task = cli_task_begin("inserting", (uint64_t)pr->w * pr->h * pr->d);
	end_run(g->use_cl ? frdgen_run_cl(pr, o, &m, task) :
	    frdgen_run(pr, &m, task), task, &of);
	write_matrix(&of, &m);
	if (pr->checkpoint != NULL)
		unlink(pr->checkpoint);
	if (g->verbose)
		report_frd(pr, &m, cli_now() - t0,
		    g->use_cl ? cli_device_name(o) : "the CPU");
	cli_device_close(o);
	frs_matrix_free(&m);
	return 0;
}

int main(int argc, char **argv)
{
	struct gen_opts g = { .dev = -1 };

	cli_init("frd-gen", usage);
	frdgen_defaults(&g.pr);
	parse_opts(argc, argv, &g);
	if (g.qfile != NULL) {
		cli_options_done();
		quality(g.qfile);
		for (int i = optind; i < argc; i++)
			quality(argv[i]);
		return 0;
	}
	check_opts(argc, argv, &g);
	if (g.mo.vac)
		return run_vac(&g.pr, &g.mo, g.verbose);
	return run_frd(&g);
}
