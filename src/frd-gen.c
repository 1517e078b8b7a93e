/*
 * frd-gen: Forced Random Dithering threshold matrices.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "frdgen.h"
#include "frdgencl.h"
#include "frdio.h"
#include "frdq.h"
#include "mem.h"
#include "ocl.h"
#include "outfile.h"
#include "parse.h"
#include "progress.h"
#include "vac.h"

static const char usage[] =
    "usage: frd-gen -s SIZE [-k 2|3] [-p P] [--tol EPS | --exact] [-S SEED]\n"
    "               [-j N] [--checkpoint FILE] [--device cpu|cl|cl:N] [-v]\n"
    "               [-o FILE]\n"
    "       frd-gen --method vac -s SIZE [-k 2|3] [--vac-sigma S]\n"
    "               [--tol EPS | --exact] [-S SEED] [-v] [-o FILE]\n"
    "       frd-gen --quality FILE\n"
    "       frd-gen --list-devices\n"
    "\n"
    "  -s, --size SIZE     N (N x N, or N^3 with -k 3), WxH or WxHxD\n"
    "  -k, --dims K        2 (default) or 3\n"
    "      --method M      frd (default: Forced Random Dithering) or vac\n"
    "                      (Ulichney's void-and-cluster, a baseline)\n"
    "      --vac-sigma S   vac: Gaussian filter sigma in cells (default 1.5)\n"
    "  -p, --fraction P    candidate fraction in (0, 1] (default 0.5;\n"
    "                      1 = always the global minimum)\n"
    "      --tol EPS       neglect forces below EPS * f(0) (default 1e-3;\n"
    "                      radius (ln 1/EPS)^2 / 2 cells for the default f);\n"
    "                      vac: the filter below EPS (default 1e-4, radius\n"
    "                      S sqrt(2 ln 1/EPS))\n"
    "      --exact         keep every contribution (frd: O(N^2); vac: the\n"
    "                      whole torus)\n"
    "      --reach R       radius at least R times the spacing of the values\n"
    "                      inserted so far (default 0.7, 0 = off)\n"
    "      --force-s S     force f(r) = exp(-(r/S)^Q), default S = 0.5\n"
    "      --force-q Q     default Q = 0.5\n"

    "  -S, --seed N        random seed (default 1)\n"
    "  -j, --threads N     threads (default: all cores); same bytes for any N\n"
    "      --checkpoint F  resume from F if it holds a run with the same\n"
    "                      parameters; save progress there every minute\n"
    "      --checkpoint-every SEC  seconds between saves (default 60)\n"
    "      --device DEV    cpu (default), cl (first OpenCL device) or cl:N;\n"
    "                      the same bytes on every device (needs fp64)\n"
    "      --list-devices  list the OpenCL devices and exit\n"
    "  -v, --verbose       print time and quality figures on standard error\n"
    "      --quality FILE  print the quality figures of a matrix and exit\n"
    "  -o, --output FILE   output (default: standard output)\n"
    "  -q, --quiet         no progress bar or warnings\n"
    "      --progress      progress bar even when standard error is no tty\n"
    "  -h, --help          this help;  --version  the version\n";

enum {
	OPT_TOL = OPT_FIRST_PRIVATE, OPT_EXACT, OPT_REACH, OPT_FS, OPT_FQ,
	OPT_CKPT, OPT_CKPT_EVERY, OPT_QUALITY, OPT_DEVICE, OPT_LIST,
	OPT_METHOD, OPT_VAC_SIGMA
};

static const struct option longopts[] = {
	{ "size", required_argument, NULL, 's' },
	{ "dims", required_argument, NULL, 'k' },
	{ "fraction", required_argument, NULL, 'p' },
	{ "tol", required_argument, NULL, OPT_TOL },
	{ "exact", no_argument, NULL, OPT_EXACT },
	{ "reach", required_argument, NULL, OPT_REACH },
	{ "force-s", required_argument, NULL, OPT_FS },
	{ "force-q", required_argument, NULL, OPT_FQ },
	{ "checkpoint", required_argument, NULL, OPT_CKPT },
	{ "checkpoint-every", required_argument, NULL, OPT_CKPT_EVERY },
	{ "quality", required_argument, NULL, OPT_QUALITY },
	{ "device", required_argument, NULL, OPT_DEVICE },
	{ "list-devices", no_argument, NULL, OPT_LIST },
	{ "method", required_argument, NULL, OPT_METHOD },
	{ "vac-sigma", required_argument, NULL, OPT_VAC_SIGMA },

	{ "verbose", no_argument, NULL, 'v' },
	CLI_COMMON_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

/* "N", "WxH" or "WxHxD"; N means a cube for k = 3. */
static void parse_dims(const char *s, struct frdgen_params *pr)
{
	uint32_t sz[3];
	int given = cli_size3("-s", s, UINT32_MAX, sz);

	pr->w = sz[0];
	pr->h = sz[1];
	pr->d = given == 3 || (given == 1 && pr->dims == 3) ? sz[2] : 1;
}

static void print_quality(FILE *fp, const struct frs_matrix *m,
    const char *name)
{
	static const uint32_t cs[] = { 16, 64, 256, 1024 };
	static const double levels[] = { 2.5, 10 };
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
}

static int quality(const char *path)
{
	struct frs_matrix m;

	if (frd_read(path, &m) < 0 || frd_check_permutation(&m, path) < 0)
		cli_die_lib();
	print_quality(stdout, &m, path);
	frd_free(&m);
	return 0;
}

static void check_memory(const struct frdgen_params *pr, uint64_t bytes)
{
	char what[64];

	snprintf(what, sizeof what, "-s %ux%ux%u", pr->w, pr->h, pr->d);
	if (mem_check(what, bytes, 1) < 0)
		cli_die_lib();
}

/* What the options asked for beyond struct frdgen_params. */
struct method_opts {
	int vac;		/* --method vac */
	int tol_set;		/* --tol or --exact given */
	double vac_sigma;	/* --vac-sigma, 0 when not given */
	const char *frd_only;	/* an option given that only frd uses */
};

static int parse_method(const char *s)
{
	if (strcmp(s, "frd") == 0)
		return 0;
	if (strcmp(s, "vac") != 0)
		cli_usage_error("--method: '%s' is not frd or vac", s);
	return 1;
}

/* Options of the other method are refused, not silently ignored. */
static void check_method(const struct method_opts *mo, int use_cl)
{
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

/* Write a finished matrix to the open output, or die removing it. */
static void write_matrix(struct outfile *of, const struct frs_matrix *m)
{
	if (frd_write(of->fp, of->name, m) < 0) {
		outfile_abort(of);
		cli_die_lib();
	}
	if (outfile_commit(of) < 0)
		cli_die_lib();
}

/* --method vac: the void-and-cluster baseline (vac.h). */
static int run_vac(const struct frdgen_params *pr,
    const struct method_opts *mo, int verbose)
{
	struct vac_params vp;
	struct vac_stats st;
	struct frs_matrix m;
	struct outfile of;
	struct progress prog;
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
		cli_usage_error("%s", frs_errmsg());
	check_memory(pr, vac_memory(&vp));
	cli_options_done();
	if (outfile_open(&of, cli.out, 1) < 0)
		cli_die_lib();
	t0 = progress_now();
	progress_begin(&prog, "void-and-cluster", (uint64_t)vp.w * vp.h * vp.d);
	if (vac_run(&vp, &m, &prog, &st) < 0) {
		progress_end(&prog);
		outfile_abort(&of);
		cli_die_lib();
	}
	progress_end(&prog);
	write_matrix(&of, &m);
	if (verbose) {
		fprintf(stderr, "frd-gen: void-and-cluster %ux%ux%u in %.3f s "
		    "(sigma %g, radius %.1f, %llu initial cells, %llu moves)\n",
		    vp.w, vp.h, vp.d, progress_now() - t0, vp.sigma, st.radius,
		    (unsigned long long)st.ones, (unsigned long long)st.moves);
		print_quality(stderr, &m, cli.out ? cli.out : "<stdout>");
	}
	frd_free(&m);
	return 0;
}

int main(int argc, char **argv)
{
	struct frdgen_params pr;
	struct frs_matrix m;
	struct outfile of;
	struct progress prog;
	const char *size = NULL;
	int c, verbose = 0, use_cl = 0, dev = -1;
	struct ocl o;
	struct method_opts mo = { 0, 0, 0.0, NULL };
	double t0;

	cli_init("frd-gen", usage);
	frdgen_defaults(&pr);
	while ((c = getopt_long(argc, argv, "s:k:p:v" CLI_COMMON_SHORTOPTS,
	    longopts, NULL)) != -1) {
		switch (c) {
		case 's':
			size = optarg;
			break;
		case 'k':
			pr.dims = (unsigned)cli_ll("-k", optarg, 2, 3);
			break;
		case 'p':
			pr.p = cli_double("-p", optarg, 0.0, 1.0);
			if (pr.p <= 0.0)
				cli_usage_error("-p: %s is outside (0, 1]", optarg);
			mo.frd_only = "-p";
			break;
		case OPT_TOL:
			pr.tol = cli_double("--tol", optarg, 0.0, 0.999999);
			if (pr.tol <= 0.0)
				cli_usage_error("--tol: must be above 0 (use "
				    "--exact to keep every contribution)");
			mo.tol_set = 1;
			break;
		case OPT_EXACT:
			pr.tol = 0.0;
			mo.tol_set = 1;
			break;
		case OPT_REACH:
			pr.reach = cli_double("--reach", optarg, 0.0, 1e6);
			mo.frd_only = "--reach";
			break;
		case OPT_FS:
			pr.s = cli_double("--force-s", optarg, 1e-6, 1e6);
			mo.frd_only = "--force-s";
			break;
		case OPT_FQ:
			pr.q = cli_double("--force-q", optarg, 1e-3, 100.0);
			mo.frd_only = "--force-q";
			break;
		case OPT_CKPT:
			pr.checkpoint = optarg;
			mo.frd_only = "--checkpoint";
			break;
		case OPT_CKPT_EVERY:
			pr.checkpoint_every = cli_double("--checkpoint-every", optarg,
			    0.0, 1e9);
			mo.frd_only = "--checkpoint-every";
			break;
		case OPT_METHOD:
			mo.vac = parse_method(optarg);
			break;
		case OPT_VAC_SIGMA:
			mo.vac_sigma = cli_double("--vac-sigma", optarg, 0.0, 1e6);
			if (mo.vac_sigma <= 0.0)
				cli_usage_error("--vac-sigma: must be above 0");
			break;
		case OPT_QUALITY:
			cli_options_done();
			return quality(optarg);
		case OPT_DEVICE:
			use_cl = cli_device(optarg, &dev);
			break;
		case OPT_LIST:
			cli_list_devices();

		case 'v':
			verbose = 1;
			break;
		default:
			if (!cli_common_opt(c, optarg))
				cli_usage(2);
		}
	}
	if (optind != argc)
		cli_usage_error("unexpected argument '%s'", argv[optind]);
	if (size == NULL)
		cli_usage_error("-s SIZE is required");
	parse_dims(size, &pr);
	pr.seed = cli.seed;
	check_method(&mo, use_cl);
	if (mo.vac)
		return run_vac(&pr, &mo, verbose);
	if (frdgen_check(&pr) < 0)
		cli_usage_error("%s", frs_errmsg());
	if (use_cl && pr.checkpoint != NULL)
		cli_usage_error("--checkpoint: not available with --device cl");
	check_memory(&pr, frdgen_memory(&pr));
	cli_options_done();
	/* The device before the output: a missing one fails at once. */
	if (use_cl && ocl_open(&o, dev) < 0)
		cli_die_lib();
	/* Open the output first: a bad path fails before hours of work. */
	if (outfile_open(&of, cli.out, 1) < 0)
		cli_die_lib();
	t0 = progress_now();
	progress_begin(&prog, "inserting", (uint64_t)pr.w * pr.h * pr.d);
	if ((use_cl ? frdgen_run_cl(&pr, &o, &m, &prog) :
	    frdgen_run(&pr, &m, &prog)) < 0) {
		progress_end(&prog);
		outfile_abort(&of);
		cli_die_lib();
	}
	progress_end(&prog);
	if (use_cl)
		ocl_close(&o);
	write_matrix(&of, &m);
	if (pr.checkpoint != NULL)
		unlink(pr.checkpoint);
	if (verbose) {
		fprintf(stderr, "frd-gen: %ux%ux%u in %.3f s (radius %.1f) on "
		    "%s\n", pr.w, pr.h, pr.d, progress_now() - t0,
		    frdgen_radius(&pr), use_cl ? o.name : "the CPU");
		print_quality(stderr, &m, cli.out ? cli.out : "<stdout>");
	}
	frd_free(&m);
	return 0;
}
