/*
 * frs-sample: Forced Random Sampling of an importance map.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "api/api.h"
#include "cli/cli.h"
#include "base/datadir.h"
#include "formats/frdio.h"
#include "sample/frscore.h"
#include "sample/frscl.h"
#include "sample/frs3.h"
#include "maps/imap.h"
#include "base/mem.h"
#include "base/outfile.h"
#include "base/progress.h"
#include "formats/ptsio.h"
#include "maps/vol.h"
#include "maps/mapload.h"

static const char usage[] =
    "usage: frs-sample -n COUNT [-i IMPORTANCE] [-m MATRIX] [-a ALGO]\n"
    "                  [--sigma S] [--jitter none|halton|random] [--pdf]\n"
    "                  [--progressive N1,N2,...] [--threshold unbiased|thesis]\n"
    "                  [--tiles auto|shuffled|plain] [--count-only]\n"
    "                  [--exact-count] [--sets M]\n"
    "                  [-s SIZE] [-S SEED] [-j N]\n"
    "                  [--device cpu|cl|cl:N] [-T] [-v] [-o FILE]\n"
    "       frs-sample --list-devices | --data-dir\n"
    "\n"
    "  -n, --count N        samples to make (about; see frs-sample(1);\n"
    "                       exactly with --exact-count)\n"
    "  -i, --importance M   map: PNG, OpenEXR or a spec such as blob\n"
    "                       (default const: uniform sampling); with a\n"
    "                       3-D matrix a volume: .frv or blob3, ramp3...\n"
    "  -m, --matrix FILE    threshold matrix .frd (default: the shipped\n"
    "                       2048x2048 default.frd; for a volume the\n"
    "                       64x64x64 default3.frd; see --data-dir)\n"
    "  -a, --algo A         naive, stack, level1, level2, sorted (default)\n"
    "                       or flat1 (OpenCL only)\n"
    "      --sigma S        sparsity: one of S^2 window elements passes at\n"
    "                       the maximum importance (default 8)\n"
    "      --jitter J       none (element centres), halton or random offsets\n"
    "      --pdf            add a column: the density of each sample over\n"
    "                       the unit square, I / mean I\n"
    "      --progressive L  counts N1 < N2 < ...: write the samples of each\n"
    "                       step in turn, with a column giving the step\n"
    "      --threshold R    unbiased (default) or thesis (Eq. 4.14)\n"
    "      --tiles T        a window larger than the matrix: shuffled\n"
    "                       (each tile turned, flipped and shifted by\n"
    "                       the seed), plain (default: repeated as it\n"
    "                       is, thesis Sec. 4.5) or auto (shuffled when\n"
    "                       n fits the matrix without repetition)\n"
    "      --count-only     print the count, make no points\n"
    "      --exact-count    exactly N samples (each step of --progressive):\n"
    "                       the N of smallest (M + u) / I, a subset or\n"
    "                       superset of the default set (unbiased rule)\n"
    "      --sets M         write M sets one after another, set i made\n"
    "                       with seed S+i (default 1); M > 1 adds a\n"
    "                       column, the set i\n"
    "  -s, --size WxH       size at which procedural maps are evaluated\n"
    "                       (default 128x128), or files resampled;\n"
    "                       N or WxHxD for volumes (default 32^3)\n"
    "      --equirect       weight map rows by sin(theta)\n"
    "      --strict         negative importance is an error\n"
    "      --device D       cpu (default), cl (the first OpenCL device) or\n"
    "                       cl:N; the output is the same bytes on all\n"
    "      --list-devices   list the OpenCL devices as cl:N and exit\n"
    "      --data-dir       print the directory of the shipped data (the\n"
    "                       default matrices, sunset.exr) and exit\n"
    "  -S, --seed N         seed (default 1)\n"
    "  -j, --threads N      threads (default all); same points for any N\n"
    "  -T, --text           text output\n"
    "  -v, --verbose        setup, count and phase times on standard error\n"
    "  -o, --output FILE    output (default standard output)\n"
    "  -q, --quiet          no warnings\n"
    "  -h, --help           this help;  --version  the version\n";

enum {
	OPT_SIGMA = OPT_FIRST_PRIVATE, OPT_JITTER, OPT_PDF, OPT_PROG,
	OPT_THRESHOLD, OPT_COUNT_ONLY, OPT_EQUIRECT, OPT_STRICT, OPT_SETS,
	OPT_DEVICE, OPT_LIST_DEVICES, OPT_TILES, OPT_DATA_DIR, OPT_EXACT
};

/* Most samples asked for in all the sets of one file (M * n): far inside
 * a 64-bit file offset at 32 bytes a record. */
#define SETS_MAX_TOTAL ((uint64_t)1 << 56)

static const struct option longopts[] = {
	{ "count", required_argument, NULL, 'n' },
	{ "importance", required_argument, NULL, 'i' },
	{ "matrix", required_argument, NULL, 'm' },
	{ "algo", required_argument, NULL, 'a' },
	{ "size", required_argument, NULL, 's' },
	{ "sigma", required_argument, NULL, OPT_SIGMA },
	{ "jitter", required_argument, NULL, OPT_JITTER },
	{ "pdf", no_argument, NULL, OPT_PDF },
	{ "progressive", required_argument, NULL, OPT_PROG },
	{ "threshold", required_argument, NULL, OPT_THRESHOLD },
	{ "count-only", no_argument, NULL, OPT_COUNT_ONLY },
	{ "exact-count", no_argument, NULL, OPT_EXACT },
	{ "equirect", no_argument, NULL, OPT_EQUIRECT },
	{ "strict", no_argument, NULL, OPT_STRICT },
	{ "sets", required_argument, NULL, OPT_SETS },
	{ "device", required_argument, NULL, OPT_DEVICE },
	{ "list-devices", no_argument, NULL, OPT_LIST_DEVICES },
	{ "data-dir", no_argument, NULL, OPT_DATA_DIR },
	{ "tiles", required_argument, NULL, OPT_TILES },
	{ "verbose", no_argument, NULL, 'v' },
	CLI_COMMON_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

struct opts {
	const char *imp, *matrix;
	uint64_t steps[16];
	unsigned nsteps;
	int algo;		/* enum frs_algo or FRSCL_FLAT1 */
	double sigma;
	enum frs_jitter jitter;
	enum frs_rule rule;
	int tiles;		/* enum frs_tiling_mode */
	int pdf, count_only, verbose, flags;
	int exact;		/* --exact-count */
	uint32_t w, h;
	uint32_t vsz[3];	/* -s for volumes, 0 if not given */
	int nsz;		/* sizes -s gave: 0, 1 (N), 2 or 3 */
	uint64_t sets;		/* --sets, default 1 */
	int cl, dev;		/* --device: OpenCL, its index (-1 first) */
};

static void parse_steps(struct opts *o, const char *s)
{
	char buf[512], *tok, *save = NULL;

	if (strlen(s) >= sizeof buf)
		cli_usage_error("--progressive: list too long");
	strcpy(buf, s);
	o->nsteps = 0;
	for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",",
	    &save)) {
		if (o->nsteps == 16)
			cli_usage_error("--progressive: at most 16 steps");
		o->steps[o->nsteps] = cli_u64("--progressive", tok, 1,
		    (uint64_t)1 << 40);
		if (o->nsteps > 0 && o->steps[o->nsteps] <= o->steps[o->nsteps - 1])
			cli_usage_error("--progressive: counts must increase");
		o->nsteps++;
	}
	if (o->nsteps == 0)
		cli_usage_error("--progressive: no counts");
}

/* --data-dir: the directory the shipped default matrix is taken from
 * (the other shipped files lie beside it), and exit. */
static noreturn void print_data_dir(void)
{
	char path[DATA_PATH_MAX];

	cli_options_done();	/* the fuzz target stops here */
	if (data_find("default.frd", path, sizeof path) < 0)
		cli_die("--data-dir: no shipped data (%s)", frs_errmsg());
	*strrchr(path, '/') = '\0';
	if (printf("%s\n", path) < 0 || fflush(stdout) == EOF)
		cli_die("<stdout>: write error");
	exit(0);
}

static void parse_opts(int argc, char **argv, struct opts *o)
{
	int c, have_n = 0;
	uint64_t n = 0;

	while ((c = cli_getopt(argc, argv, "n:i:m:a:s:v" CLI_COMMON_SHORTOPTS,
	    longopts)) != -1) {
		switch (c) {
		case 'n':
			n = cli_u64("-n", optarg, 1, (uint64_t)1 << 40);
			have_n = 1;
			break;
		case 'i': o->imp = optarg; break;
		case 'm': o->matrix = optarg; break;
		case 'a':
			if (frscl_algo_parse(optarg, &o->algo) < 0)
				cli_usage_error("%s", frs_errmsg());
			break;
		case 's':
			o->nsz = cli_size3("-s", optarg, IMAP_MAX_SIDE, o->vsz);
			o->w = o->vsz[0];
			o->h = o->vsz[1];
			break;
		case OPT_SIGMA:
			o->sigma = cli_double("--sigma", optarg, 1.0, 1024.0);
			break;
		case OPT_JITTER:	/* in the order of enum frs_jitter */
			o->jitter = (enum frs_jitter)cli_choice("--jitter", optarg,
			    (const char *const[]){ "none", "halton", "random", NULL });
			break;
		case OPT_PDF: o->pdf = 1; break;
		case OPT_PROG: parse_steps(o, optarg); break;
		case OPT_THRESHOLD:	/* enum frs_rule */
			o->rule = (enum frs_rule)cli_choice("--threshold", optarg,
			    (const char *const[]){ "unbiased", "thesis", NULL });
			break;
		case OPT_TILES:		/* enum frs_tiling_mode */
			o->tiles = cli_choice("--tiles", optarg, (const char *const[]){
			    "auto", "shuffled", "plain", NULL });
			break;
		case OPT_COUNT_ONLY: o->count_only = 1; break;
		case OPT_EXACT: o->exact = 1; break;
		case OPT_EQUIRECT: o->flags |= IMAP_EQUIRECT; break;
		case OPT_STRICT: o->flags |= IMAP_STRICT; break;
		case OPT_SETS:
			o->sets = cli_u64("--sets", optarg, 1, SETS_MAX_TOTAL);
			break;
		case OPT_DEVICE:
			o->cl = cli_device(optarg, &o->dev);
			break;
		case OPT_LIST_DEVICES:
			cli_list_devices();
		case OPT_DATA_DIR:
			print_data_dir();
		case 'v': o->verbose = 1; break;
		default:
			if (!cli_common_opt(c, optarg))
				cli_usage(2);
		}
	}
	if (optind != argc)
		cli_usage_error("unexpected argument '%s'", argv[optind]);
	if (o->algo == FRSCL_FLAT1 && !o->cl)
		cli_usage_error("-a flat1 runs on OpenCL only (--device cl)");
	if (o->exact && o->rule == FRS_THESIS)
		cli_usage_error("--exact-count needs --threshold unbiased: under "
		    "the thesis rule elements of equal importance share "
		    "thresholds, and counts jump past n");
	if (o->nsteps == 0) {
		if (!have_n)
			cli_usage_error("-n COUNT is required");
		o->steps[0] = n;
		o->nsteps = 1;
	} else if (have_n && n != o->steps[o->nsteps - 1]) {
		cli_usage_error("-n %llu differs from the last progressive count",
		    (unsigned long long)n);
	}
	n = o->steps[o->nsteps - 1];
	if (o->sets > SETS_MAX_TOTAL / n)
		cli_usage_error("--sets %llu: %llu sets of %llu samples exceed "
		    "the 2^56 one file can hold", (unsigned long long)o->sets,
		    (unsigned long long)o->sets, (unsigned long long)n);
	if (o->sets - 1 > UINT64_MAX - cli.seed)
		cli_usage_error("--sets %llu: the seeds from -S %llu would pass "
		    "2^64-1", (unsigned long long)o->sets,
		    (unsigned long long)cli.seed);
}

/* The default matrix: $FRS_MATRIX (or $FRS_MATRIX3 for a volume), else
 * the shipped one (datadir.h), as frs_default_matrix finds it. */
static const char *default_matrix(int volume)
{
	static char path[DATA_PATH_MAX];

	if (api_default_matrix(volume ? 3 : 2, path, sizeof path) < 0)
		cli_die("no default %smatrix (%s); give -m MATRIX",
		    volume ? "3-D " : "", frs_errmsg());
	return path;
}

static void print_setup(const struct frs_setup *s, const char *mname)
{
	fprintf(stderr, "frs-sample: matrix %s %ux%u, map %ux%u, mean %.6g, "
	    "max %.6g\n", mname, s->mw, s->mh, s->iw, s->ih, s->mean, s->max);
	fprintf(stderr, "frs-sample: n %llu, sigma %g, n_s %u, window %llux%llu "
	    "at (%llu, %llu), tau %.9g, start level %u\n",
	    (unsigned long long)s->n, s->sigma, s->ns,
	    (unsigned long long)s->sw, (unsigned long long)s->sh,
	    (unsigned long long)s->wx, (unsigned long long)s->wy, s->tau,
	    s->level0);
}

/* Refuse counts whose elements (size bytes each, with a tenth more for
 * the count's spread) could not be stored before spending the time. */
static void check_room(const struct opts *o, size_t size)
{
	uint64_t n = o->steps[o->nsteps - 1];
	char what[64];

	snprintf(what, sizeof what, "-n %llu (--count-only counts them)",
	    (unsigned long long)n);
	if (!o->count_only && mem_check(what, n + n / 10, size) < 0)
		cli_die_lib();
}

/* ---- OpenCL: what the public API does not cover -------------------- */

static int needs_minmap(int a)
{
	return a == FRS_STACK || a == FRS_LEVEL1 || a == FRS_LEVEL2 ||
	    a == FRSCL_FLAT1;
}

/* One set on the device: the sampler's setup and prepared matrix. */
static void sample_cl(struct ocl *ocl, const struct opts *o,
    const frs_sampler *smp, uint64_t seed, struct frs_setup *s,
    struct frs_result *r)
{
	struct frs_prep view;

	if (api_setup_steps(smp, o->steps, o->nsteps, seed, s) < 0)
		cli_die("%s", frs_errmsg());
	if (api_mask_prep(smp->mask, needs_minmap(o->algo),
	    o->algo == FRS_SORTED ? api_sorted_block(s) : 0,
	    api_lists_below(s, o->steps, o->nsteps), &view) < 0)
		cli_die_lib();	/* the message names the matrix */
	if (frs_sample_cl(ocl, s, &smp->map, &view, o->algo, o->steps,
	    o->nsteps, o->count_only, r) < 0)
		cli_die("%s", frs_errmsg());
}

/* ---- output ------------------------------------------------------ */

/* The extra columns, in their order: pdf (--pdf), step (--progressive),
 * set (--sets M, M > 1); their count. */
static unsigned extra_names(const struct opts *o, const char *names[3])
{
	unsigned k = 0;

	if (o->pdf)
		names[k++] = PTS_COL_PDF;
	if (o->nsteps > 1)
		names[k++] = PTS_COL_STEP;
	if (o->sets > 1)
		names[k++] = PTS_COL_SET;
	return k;
}

struct out {
	const struct opts *o;
	struct outfile of;
	struct pts_writer w;
	int open;
	uint64_t n;		/* samples of the set being drawn */
	uint64_t set;		/* and its index, from 0 */
	int noted;		/* the mask's note was printed */
	double t;		/* seconds spent writing */
	double tnote;		/* and in note_point, apart from the phases */
	const frs_mask *mask;	/* for -v */
	struct frscl_times ct;	/* OpenCL phases, summed over the sets */
	/* -v: how many samples of set 0 show each matrix element */
	const struct frs_setup *s0;
	uint32_t *uses;
	uint64_t nnoted;
	int collect, have;
	double *rec;		/* records with extra columns */
	size_t reccap;
};

/* -v: count the matrix element that sample (x, y) of set 0 shows (its
 * window element is floor(x S_W): jitter stays inside it). */
static void note_point(struct out *u, double x, double y)
{
	const struct frs_setup *s = u->s0;
	uint64_t i;

	if (!u->collect)
		return;
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
static double reused_share(struct out *u)
{
	uint64_t reused = 0;
	size_t n = (size_t)u->s0->mw * u->s0->mh;

	if (u->nnoted == 0 || u->uses == NULL)
		return 0.0;
	for (size_t i = 0; i < n; i++)
		reused += u->uses[i] >= 2 ? u->uses[i] : 0;
	return (double)reused / (double)u->nnoted;
}

/* Open the output at the first set: with one set its count goes into
 * the header; more sets announce 0 (unknown), which the writer replaces
 * by the total when the output can seek. */
static int out_begin(struct out *u, uint64_t count)
{
	const struct opts *o = u->o;
	const char *names[3];
	unsigned extra = extra_names(o, names);

	if (u->open)
		return 0;
	if (outfile_open(&u->of, cli.out, !o->count_only && !cli.text) < 0)
		cli_die_lib();
	u->open = 1;
	if (!o->count_only && pts_writer_begin(&u->w, u->of.fp, u->of.name, 2,
	    extra, names, o->sets == 1 ? count : 0, cli.text) < 0)
		return -1;
	return 0;
}

/* frs_draw_each's callback: records x, y [, pdf] [, step + 1] [, set]. */
static int out_batch(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	struct out *u = ctx;
	double t0 = progress_now();
	int rc = out_begin(u, total);
	int sets = u->o->sets > 1;
	unsigned ncol = 2u + (pdf != NULL ? 1u : 0u) + (step != NULL ? 1u : 0u) +
	    (sets ? 1u : 0u);

	u->n = total;
	if (u->collect) {
		double t1 = progress_now();
		for (size_t i = 0; i < k; i++)
			note_point(u, xy[2 * i], xy[2 * i + 1]);
		u->tnote += progress_now() - t1;
		t0 += progress_now() - t1;
	}
	if (rc == 0 && ncol == 2)
		rc = pts_writer_put_n(&u->w, xy, k);
	else if (rc == 0 && k * ncol > u->reccap) {
		free(u->rec);
		u->reccap = k * ncol;
		if ((u->rec = malloc(u->reccap * sizeof *u->rec)) == NULL) {
			u->reccap = 0;
			rc = frs_fail("out of memory");
		}
	}
	if (rc == 0 && ncol > 2) {
		double *rec = u->rec;
		for (size_t i = 0; i < k; i++, rec += ncol) {
			unsigned c = 2;
			rec[0] = xy[2 * i];
			rec[1] = xy[2 * i + 1];
			if (pdf != NULL)
				rec[c++] = pdf[i];
			if (step != NULL)
				rec[c++] = (double)(step[i] + 1);
			if (sets)
				rec[c++] = (double)u->set;
		}
		rc = pts_writer_put_n(&u->w, u->rec, k);
	}
	u->t += progress_now() - t0;
	return rc;
}

/* Write one set's points as frs_draw_each gives them, through
 * out_batch. */
static int put_set(struct out *u, const struct frs_setup *s,
    const struct frs_imap *map, const struct frs_result *r)
{
	int rc = api_result_each(s, map, r, u->o->nsteps, u->o->pdf, out_batch,
	    u);

	if (rc == FRS_E_NOMEM)
		return frs_fail("out of memory");
	return rc == FRS_OK ? 0 : -1;	/* else the writer's message */
}

/* ---- loading --------------------------------------------------------- */

static frs_mask *load_mask(const char *path)
{
	frs_mask *mk;
	frs_error err;

	if (frs_mask_load(&mk, path, &err) != FRS_OK)
		cli_die("%s", err.message);
	if (frs_mask_note(mk) != NULL)
		frs_warn("%s", frs_mask_note(mk));
	return mk;
}

static frs_sampler *make_sampler(const struct opts *o, const frs_mask *mk,
    const struct frs_imap *map)
{
	static const enum frs_algorithm alg[] = {
		[FRS_NAIVE] = FRS_ALG_NAIVE, [FRS_STACK] = FRS_ALG_STACK,
		[FRS_LEVEL1] = FRS_ALG_LEVEL1, [FRS_LEVEL2] = FRS_ALG_LEVEL2,
		[FRS_SORTED] = FRS_ALG_SORTED
	};
	struct frs_options opt;
	frs_sampler *smp;
	frs_error err;

	frs_options_init(&opt);
	opt.sigma = o->sigma;
	opt.algorithm = o->algo < FRS_NALGO ? alg[o->algo] : FRS_ALG_SORTED;
	opt.jitter = o->jitter == FRS_JITTER_HALTON ? FRS_JIT_HALTON :
	    o->jitter == FRS_JITTER_RANDOM ? FRS_JIT_RANDOM : FRS_JIT_NONE;
	opt.rule = o->rule == FRS_THESIS ? FRS_RULE_THESIS :
	    o->exact ? FRS_RULE_EXACT : FRS_RULE_UNBIASED;
	opt.threads = cli.threads;
	opt.tiling = (enum frs_tiling_mode)o->tiles;
	if (frs_sampler_new_f64(&smp, mk, map->v, map->w, map->h, 0, &opt,
	    &err) != FRS_OK)
		cli_die("%s", err.message);
	return smp;
}

/* The setup of set 0, checked before any work; the repetition warning.
 * The matrix's minmap or sorted lists, which the library prepares on
 * first use, are prepared here, so that -v counts them in the setup and
 * not in the thresholding.  --exact-count: the exact taus of set 0 only
 * with -v, which reports them (each set's run finds its own, making the
 * lists it needs: their time then counts in the thresholding). */
static void first_setup(const struct opts *o, const frs_sampler *smp,
    struct frs_setup *s0)
{
	struct frs_prep view;

	if ((o->exact && o->verbose ? api_setup_steps(smp, o->steps, o->nsteps,
	    cli.seed, s0) : api_setup(smp, o->steps[o->nsteps - 1], cli.seed,
	    s0)) < 0)
		cli_die("%s", frs_errmsg());
	if ((!o->exact || o->verbose) && api_mask_prep(smp->mask,
	    needs_minmap(o->algo) ||
	    (o->algo == FRS_SORTED && api_sorted_minmap(s0)),
	    o->algo == FRS_SORTED ? api_sorted_block(s0) : 0,
	    api_lists_below(s0, o->steps, o->nsteps), &view) < 0)
		cli_die_lib();	/* the message names the matrix */
	if ((double)s0->n > frs_unique(s0))
		frs_warn("%llu samples from a %ux%u matrix with sigma %g repeat "
		    "its patterns (it gives %.0f without repetition, thesis "
		    "Table 4.1)", (unsigned long long)s0->n, s0->mw, s0->mh,
		    s0->sigma, frs_unique(s0));
	else if (s0->tiles == FRS_TILES_PLAIN && (s0->sw > s0->mw ||
	    s0->sh > s0->mh))
		frs_warn("--tiles plain: the window of %llux%llu repeats the "
		    "%ux%u matrix as it is, a lattice of the tile's period where "
		    "few samples fall (--tiles shuffled breaks it)",
		    (unsigned long long)s0->sw,
		    (unsigned long long)s0->sh, s0->mw, s0->mh);
}

/* One set through the public API (CPU) or the device; its count. */
static uint64_t one_set(struct ocl *ocl, const struct opts *o,
    const frs_sampler *smp, uint64_t seed, struct out *u)
{
	frs_error err;
	uint64_t count = 0;

	if (o->cl) {
		struct frs_setup s;
		struct frs_result r;
		struct frscl_times ct;
		sample_cl(ocl, o, smp, seed, &s, &r);
		frscl_last_times(&ct);
		u->ct.build += ct.build;
		u->ct.upload += ct.upload;
		u->ct.kernel += ct.kernel;
		u->ct.download += ct.download;
		if (out_begin(u, r.count) < 0 || (o->count_only ? 0 :
		    put_set(u, &s, &smp->map, &r)) < 0) {
			frs_result_free(&r);
			return UINT64_MAX;
		}
		count = r.count;
		frs_result_free(&r);
	} else if (o->count_only) {
		if (frs_count(smp, o->steps[o->nsteps - 1], seed, &count,
		    &err) != FRS_OK)
			cli_die("%s", err.message);
	} else {
		int rc;
		u->n = 0;
		rc = frs_draw_each(smp, o->steps, o->nsteps, seed, o->pdf,
		    out_batch, u, &err);
		if (rc == FRS_E_CALLBACK)
			return UINT64_MAX;	/* the writer's message */
		if (rc != FRS_OK)
			cli_die("%s", err.message);
		count = u->n;
	}
	if (out_begin(u, count) < 0)
		return UINT64_MAX;
	if (o->count_only && fprintf(u->of.fp, "%llu\n",
	    (unsigned long long)count) < 0) {
		frs_fail_errno("%s: write error", u->of.name);
		return UINT64_MAX;
	}
	return count;
}

static void report(const struct opts *o, const struct frs_setup *s0,
    uint64_t total, double tsetup, double tthr, struct out *u,
    const struct ocl *ocl)
{
	uint64_t tx, ty, nt = frs_tiles(s0, &tx, &ty);

	print_setup(s0, o->matrix);
	if (o->exact) {
		struct frs_setup d = *s0;
		d.exact.n = 0;
		fprintf(stderr, "frs-sample: --exact-count: tau %.9g instead of "
		    "%.9g after %u count passes\n", s0->tau, frs_tau(&d, d.n),
		    s0->exact.passes);
	}
	if (u->mask != NULL && u->mask->made != 0)
		fprintf(stderr, "frs-sample: %s has no sorted lists of blocks of "
		    "%u: made them here (frd-prep -a sorted --for N makes a .frp "
		    "that has them)\n", u->mask->frp ? u->mask->frp : o->matrix,
		    u->mask->made);
	fprintf(stderr, "frs-sample: %llu tiles (%llux%llu), %s",
	    (unsigned long long)nt, (unsigned long long)tx,
	    (unsigned long long)ty, s0->tiles == FRS_TILES_PLAIN ? "plain" :
	    "shuffled");
	if (u->have)
		fprintf(stderr, "; %.1f %% of the samples show a matrix element "
		    "that another one shows too", 100.0 * reused_share(u));
	fputc('\n', stderr);
	if (o->sets > 1)
		fprintf(stderr, "frs-sample: %llu sets, seeds %llu to %llu\n",
		    (unsigned long long)o->sets, (unsigned long long)cli.seed,
		    (unsigned long long)(cli.seed + o->sets - 1));
	fprintf(stderr, "frs-sample: %llu samples (%s); setup %.6f s, "
	    "thresholding %.6f s, output %.6f s", (unsigned long long)total,
	    frscl_algo_name(o->algo), tsetup, tthr, u->t);
	if (u->tnote > 0.0)
		fprintf(stderr, " (and %.6f s for -v's share)", u->tnote);
	fputc('\n', stderr);
	if (o->cl)
		fprintf(stderr, "frs-sample: OpenCL device %s: build %.6f s, "
		    "to the device %.6f s, kernels %.6f s, back and offsets "
		    "%.6f s\n", ocl->name, u->ct.build, u->ct.upload,
		    u->ct.kernel, u->ct.download);
}

/* ---- 3-D matrices: volumes -------------------------------------- */

static void check3(const struct opts *o)
{
	if (o->cl)
		cli_die("--device: %s is a 3-D matrix; 3-D sampling runs on the "
		    "CPU only", o->matrix);
	if (o->algo != FRS_NAIVE && o->algo != FRS_SORTED)
		cli_die("-a %s: %s is a 3-D matrix; 3-D sampling has naive and "
		    "sorted", frscl_algo_name(o->algo), o->matrix);
	if (o->flags & IMAP_EQUIRECT)
		cli_die("--equirect: %s is a 3-D matrix; volumes have no "
		    "equirectangular form", o->matrix);
	if (o->nsz == 2)
		cli_die("-s %ux%u: %s is a 3-D matrix; give -s N or WxHxD",
		    o->w, o->h, o->matrix);
	/* main counted 2-D elements; 3-D ones are larger. */
	check_room(o, sizeof(struct frs3_elem));
}

static void load3(const struct opts *o, struct frs_matrix *m,
    struct frs_vol *v)
{
	if (frd_read(o->matrix, m) < 0 ||
	    frd_check_permutation(m, o->matrix) < 0)
		cli_die_lib();
	if (vol_load(o->imp ? o->imp : "const", o->nsz ? o->vsz[0] : 0,
	    o->vsz[1], o->vsz[2], o->flags, v) < 0)
		cli_die_lib();
}

/* The record of one element: x, y, z [, pdf] [, step + 1] [, set]. */
struct put3 {
	struct pts_writer *w;
	const struct opts *o;
	const struct frs3_setup *s;
	const struct frs_vol *v;
	uint64_t set;
};

static int put3_one(void *ctx, const struct frs3_elem *e)
{
	const struct put3 *p = ctx;
	double rec[6];
	unsigned k = 3;

	frs3_point(p->s, e, rec);
	if (p->o->pdf)
		rec[k++] = frs3_pdf(p->s, p->v, e);
	if (p->o->nsteps > 1)
		rec[k++] = (double)(e->step + 1);
	if (p->o->sets > 1)
		rec[k++] = (double)p->set;
	return pts_writer_put(p->w, rec) < 0 ? -1 : 0;
}

/* The records of one set, steps in turn. */
static int put3(struct pts_writer *w, const struct opts *o,
    const struct frs3_setup *s, const struct frs_vol *v,
    const struct frs3_result *r, uint64_t set)
{
	struct put3 p = { w, o, s, v, set };

	return frs3_each(r, o->nsteps, put3_one, &p);
}

static void setup3(const struct opts *o, const struct frs_vol *v,
    const struct frs_matrix *m, uint64_t seed, struct frs3_setup *s)
{
	if (frs3_setup(s, v, m, o->steps[o->nsteps - 1], o->sigma, seed) < 0)
		cli_die("%s", frs_errmsg());
	s->rule = o->rule;
	s->jitter = o->jitter;
	s->tiles = o->tiles == FRS_TILING_PLAIN ? FRS_TILES_PLAIN :
	    o->tiles == FRS_TILING_SHUFFLED ? FRS_TILES_SHUFFLE :
	    frs3_tiles_auto(s);
}

static void print_setup3(const struct frs3_setup *s, const char *mname)
{
	fprintf(stderr, "frs-sample: matrix %s %ux%ux%u, volume %ux%ux%u, "
	    "mean %.6g, max %.6g\n", mname, s->mw, s->mh, s->md, s->iw, s->ih,
	    s->id, s->mean, s->max);
	fprintf(stderr, "frs-sample: n %llu, sigma %g, n_s %u, window "
	    "%llux%llux%llu at (%llu, %llu, %llu), tau %.9g\n",
	    (unsigned long long)s->n, s->sigma, s->ns, (unsigned long long)s->sw,
	    (unsigned long long)s->sh, (unsigned long long)s->sd,
	    (unsigned long long)s->wx, (unsigned long long)s->wy,
	    (unsigned long long)s->wz, s->tau);
}

/* Sample every set and write it; the total count, UINT64_MAX on a write
 * error (the library's message).  t[0] gets the seconds spent
 * thresholding, t[1] those spent writing. */
static uint64_t sets3(const struct opts *o, const struct frs_vol *v,
    const struct frs_matrix *m, const struct frs3_prep *p,
    struct outfile *of, double t[2])
{
	struct pts_writer w;
	struct progress pr;
	uint64_t total = 0;

	progress_begin(&pr, "sets", o->sets);
	for (uint64_t set = 0; set < o->sets; set++) {
		struct frs3_setup s;
		struct frs3_result r;
		int rc = 0;
		double t0 = progress_now();
		setup3(o, v, m, cli.seed + set, &s);
		if (o->exact && frs3_exact(&s, v, p, o->steps, o->nsteps) < 0)
			cli_die("%s", frs_errmsg());
		if (frs3_sample(&s, v, p, (enum frs_algo)o->algo, o->steps,
		    o->nsteps, o->count_only, &r) < 0)
			cli_die("%s", frs_errmsg());
		t[0] += progress_now() - t0;
		t0 = progress_now();
		if (set == 0 && !o->count_only) {
			const char *names[3];
			unsigned extra = extra_names(o, names);
			rc = pts_writer_begin(&w, of->fp, of->name, 3, extra,
			    names, o->sets == 1 ? r.count : 0, cli.text);
		}
		if (rc == 0 && !o->count_only)
			rc = put3(&w, o, &s, v, &r, set);
		/* --count-only: a line per set, as in 2-D. */
		if (rc == 0 && o->count_only && fprintf(of->fp, "%llu\n",
		    (unsigned long long)r.count) < 0)
			rc = frs_fail_errno("%s: write error", of->name);
		total += r.count;
		frs3_result_free(&r);
		t[1] += progress_now() - t0;
		if (rc < 0) {
			progress_end(&pr);
			return UINT64_MAX;
		}
		progress_update(&pr, set + 1);
	}
	progress_end(&pr);
	if (o->count_only)
		return total;
	return pts_writer_end(&w) < 0 ? UINT64_MAX : total;
}

static int main3(const struct opts *o)
{
	struct frs_matrix m;
	struct frs_vol v;
	struct frs3_setup s0;
	struct frs3_prep p;
	struct outfile of;
	uint64_t total;
	double t0 = progress_now(), tsetup, t[2] = { 0.0, 0.0 };

	check3(o);
	load3(o, &m, &v);
	setup3(o, &v, &m, cli.seed, &s0);
	if ((double)s0.n > frs3_unique(&s0))
		frs_warn("%llu samples from a %ux%ux%u matrix with sigma %g repeat "
		    "its patterns (it gives %.6g without repetition)",
		    (unsigned long long)s0.n, s0.mw, s0.mh, s0.md, s0.sigma,
		    frs3_unique(&s0));
	else if (s0.tiles == FRS_TILES_PLAIN && frs3_tiles(&s0) > 1)
		frs_warn("--tiles plain: the window of %llux%llux%llu repeats the "
		    "%ux%ux%u matrix as it is", (unsigned long long)s0.sw,
		    (unsigned long long)s0.sh, (unsigned long long)s0.sd, s0.mw,
		    s0.mh, s0.md);
	if (frs3_prepare(&p, &m, o->algo == FRS_SORTED ? frs3_block(&s0) : 0) < 0)
		cli_die("%s: %s", o->matrix, frs_errmsg());
	if (o->exact && o->verbose &&
	    frs3_exact(&s0, &v, &p, o->steps, o->nsteps) < 0)
		cli_die("%s", frs_errmsg());
	tsetup = progress_now() - t0;
	if (outfile_open(&of, cli.out, !o->count_only && !cli.text) < 0)
		cli_die_lib();
	total = sets3(o, &v, &m, &p, &of, t);
	if (total == UINT64_MAX) {
		outfile_abort(&of);
		cli_die_lib();
	}
	t0 = progress_now();
	if (outfile_commit(&of) < 0)
		cli_die_lib();
	t[1] += progress_now() - t0;
	if (o->verbose) {
		print_setup3(&s0, o->matrix);
		if (o->exact) {
			struct frs3_setup d = s0;
			d.exact.n = 0;
			fprintf(stderr, "frs-sample: --exact-count: tau %.9g "
			    "instead of %.9g after %u count passes\n", s0.tau,
			    frs3_tau(&d, d.n), s0.exact.passes);
		}
		fprintf(stderr, "frs-sample: %llu samples (%s); setup %.6f s, "
		    "thresholding %.6f s, output %.6f s\n",
		    (unsigned long long)total, frscl_algo_name(o->algo), tsetup,
		    t[0], t[1]);
	}
	frs3_prep_free(&p);
	vol_free(&v);
	frd_free(&m);
	return 0;
}

int main(int argc, char **argv)
{
	struct opts o = { .algo = FRS_SORTED, .sigma = 8.0,
	    .tiles = FRS_TILING_PLAIN,
	    .jitter = FRS_JITTER_NONE, .rule = FRS_UNBIASED, .sets = 1,
	    .dev = -1 };
	struct ocl ocl = { NULL, NULL, NULL, NULL, "", 0 };
	struct frs_imap map;
	struct frs_setup s0;
	struct out u = { 0 };
	struct progress pr;
	frs_mask *mask;
	frs_sampler *smp;
	uint64_t total = 0;
	double t0, t1, tsetup;

	cli_init("frs-sample", usage);
	parse_opts(argc, argv, &o);
	check_room(&o, sizeof(struct frs_elem));
	cli_options_done();
	if (o.matrix == NULL)
		o.matrix = default_matrix((o.imp && vol_is_volume(o.imp)) || o.nsz == 3);
	if (frd_peek_dims(o.matrix) == 3)
		return main3(&o);
	if (o.nsz == 3)
		cli_die("-s %ux%ux%u: a volume size, but %s is a 2-D matrix",
		    o.vsz[0], o.vsz[1], o.vsz[2], o.matrix);
	if (imap_load(o.imp ? o.imp : "const", o.w, o.h, o.flags, &map) < 0)
		cli_die_lib();
	if (o.cl && ocl_open(&ocl, o.dev) < 0)
		cli_die("--device: %s", frs_errmsg());
	t0 = progress_now();
	mask = load_mask(o.matrix);
	u.noted = frs_mask_note(mask) != NULL;
	u.mask = mask;
	smp = make_sampler(&o, mask, &map);
	imap_free(&map);
	first_setup(&o, smp, &s0);
	tsetup = progress_now() - t0;
	u.o = &o;
	u.s0 = &s0;
	t1 = progress_now();
	progress_begin(&pr, "sets", o.sets);
	for (uint64_t set = 0; set < o.sets; set++) {
		uint64_t c;
		u.collect = o.verbose && set == 0 && !o.count_only;
		u.set = set;
		c = one_set(&ocl, &o, smp, cli.seed + set, &u);
		u.have = u.collect;	/* every sample of set 0 noted */
		u.collect = 0;
		if (c == UINT64_MAX)
			goto fail;
		total += c;
		progress_update(&pr, set + 1);
	}
	progress_end(&pr);
	/* A damaged twin .frp shows only when its lists are first read. */
	if (frs_mask_note(mask) != NULL && !u.noted)
		frs_warn("%s", frs_mask_note(mask));
	t0 = progress_now();
	if (!o.count_only && pts_writer_end(&u.w) < 0)
		goto fail;
	if (outfile_commit(&u.of) < 0)
		cli_die_lib();
	u.t += progress_now() - t0;
	if (o.verbose)
		report(&o, &s0, total, tsetup, progress_now() - t1 - u.t -
		    u.tnote, &u,
		    &ocl);
	if (o.cl) {
		frscl_release(&ocl);
		ocl_close(&ocl);
	}
	free(u.uses);
	free(u.rec);
	frs_sampler_free(smp);
	frs_mask_free(mask);
	return 0;
fail:
	if (u.open)
		outfile_abort(&u.of);
	cli_die_lib();
}
