/*
 * hsw-sample: Hierarchical Sample Warping of a point set by an importance
 * map (Clarberg et al. 2005), the reference FRS is compared with.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "frs.h"
#include "cli/cli.h"
#include "hsw-sample/hswrun.h"

static const char usage[] =
    "usage: hsw-sample -i IMPORTANCE -n COUNT [--input SET|FILE] [--pdf]\n"
    "                  [--sets M] [-s WxH] [--equirect] [--strict]\n"
    "                  [-S SEED] [-j N] [--device cpu|cl|cl:N]\n"
    "                  [-T] [-v] [-o FILE]\n"
    "       hsw-sample --list-devices\n"
    "\n"
    "  -i, --importance M   map: PNG, OpenEXR or a spec such as blob\n"
    "  -n, --count N        points to make (exactly; with --input FILE at\n"
    "                       most the file's count, default all of it)\n"
    "      --input SET      points to warp: random, regular, jittered,\n"
    "                       halton (default), hammersley, dart (uniform\n"
    "                       dart throwing of ref-sample -k dart, same\n"
    "                       seed), or a .pts FILE (its first two\n"
    "                       coordinates)\n"
    "      --pdf            add a column: I / mean I of each point's pixel\n"
    "      --sets M         write M sets one after another, set i made\n"
    "                       with seed S+i (default 1); M > 1 adds a\n"
    "                       column, the set i (random, jittered, dart)\n"
    "  -s, --size WxH       size at which procedural maps are evaluated\n"
    "                       (default 128x128), or files resampled\n"
    "      --equirect       weight map rows by sin(theta)\n"
    "      --strict         negative importance is an error\n"
    "  -S, --seed N         seed of random, jittered and dart (default 1)\n"
    "  -j, --threads N      threads (default all); same points for any N\n"
    "      --device D       cpu (default), cl (the first OpenCL device) or\n"
    "                       cl:N; the same points on every device\n"
    "      --list-devices   the OpenCL devices, numbered for cl:N\n"
    "  -T, --text           text output\n"
    "  -v, --verbose        setup and warping time on standard error\n"
    "  -o, --output FILE    output (default standard output)\n"
    "  -q, --quiet          no warnings\n"
    "  -h, --help           this help;  --version  the version\n";

/* --input dart: not an enum frs_hsw_input; ref-sample's dart throwing. */
#define INPUT_DART 100

struct opts {
	const char *imp, *file;
	int input;		/* enum frs_hsw_input, INPUT_DART, or -1 for file */
	uint64_t n, sets;
	int have_n, pdf, verbose;
	uint32_t w, h;
	int flags;		/* frs_imap_load's: --equirect, --strict */
	int cl, cl_index;	/* --device: OpenCL, and which (-1: first) */
};

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "n=count i=importance input pdf sets s=size equirect strict device "
    "list-devices v=verbose";

/* --sets M > 1: only inputs that the seed changes give M sets, not one
 * set M times. */
static void check_sets(const struct opts *o)
{
	if (o->sets == 1 || o->input == FRS_HSW_RANDOM ||
	    o->input == FRS_HSW_JITTERED || o->input == INPUT_DART)
		return;
	cli_usage_error("--sets %llu: --input %s is the same for every seed, "
	    "so the sets would all be one; use random, jittered or dart",
	    (unsigned long long)o->sets, o->file ? o->file :
	    frs_names(FRS_NAMES_HSW_INPUT)[o->input]);
}

/* --input's set by name (frs_names), or -1. */
static int input_of(const char *name)
{
	const char *const *w = frs_names(FRS_NAMES_HSW_INPUT);

	for (int i = 0; w[i] != NULL; i++)
		if (strcmp(name, w[i]) == 0)
			return i;
	return -1;
}

static void parse_opts(int argc, char **argv, struct opts *o)
{
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 'n':
			o->n = cli_u64("-n", optarg, 1, (uint64_t)1 << 36);
			o->have_n = 1;
			break;
		case 'i': o->imp = optarg; break;
		case 's':
			cli_size("-s", optarg, FRS_MAP_MAX_SIDE, &o->w, &o->h);
			break;
		case OPT_INPUT:
			o->input = input_of(optarg);
			o->file = NULL;
			if (strcmp(optarg, "dart") == 0)
				o->input = INPUT_DART;
			if (o->input >= 0)
				break;
			/* A file: a path with '/' or '.', "-", or one that
			 * exists; any other word is a misspelt set. */
			if (strchr(optarg, '/') || strchr(optarg, '.') ||
			    strcmp(optarg, "-") == 0 || access(optarg, F_OK) == 0)
				o->file = optarg;
			else
				cli_usage_error("--input: '%s' is not random, regular, "
				    "jittered, halton, hammersley, dart or a file",
				    optarg);
			break;
		case OPT_PDF: o->pdf = 1; break;
		case OPT_SETS: o->sets = cli_sets_m(optarg); break;
		case OPT_EQUIRECT: o->flags |= FRS_MAP_EQUIRECT; break;
		case OPT_STRICT: o->flags |= FRS_MAP_STRICT; break;
		case OPT_DEVICE:
			o->cl = cli_device(optarg, &o->cl_index);
			break;
		case OPT_LIST_DEVICES: cli_list_devices();
		case 'v': o->verbose = 1; break;
		default:
			cli_common_only(c, optarg);
		}
	}
	cli_no_operands(argc, argv);
	if (o->imp == NULL)
		cli_usage_error("-i IMPORTANCE is required");
	if (!o->have_n && o->file == NULL)
		cli_usage_error("-n COUNT is required");
	check_sets(o);
	if (o->have_n)
		cli_sets_check(o->sets, o->n);
}

/* The input set of seed: 2n doubles. */
static double *make_input(struct opts *o, uint64_t seed)
{
	char what[48];
	double *pts;

	if (o->file != NULL) {
		struct frs_points p;
		if (pts_read(o->file, &p) < 0)
			cli_die_lib();
		if (p.dims < 2) {
			pts_free(&p);
			cli_die("%s: points have %u coordinate, need 2", o->file,
			    p.dims);
		}
		if (!o->have_n)
			o->n = p.n;
		if (o->n == 0 || p.n < o->n) {
			size_t have = p.n;
			pts_free(&p);
			cli_die("%s: %zu points, need %llu", o->file, have,
			    (unsigned long long)(o->n ? o->n : 1));
		}
		pts = malloc((size_t)o->n * 2 * sizeof *pts);
		if (pts == NULL)
			cli_die("out of memory");
		for (uint64_t i = 0; i < o->n; i++) {
			const double *r = p.x + i * (p.dims + p.extra);
			if (!(r[0] >= 0 && r[0] < 1 && r[1] >= 0 && r[1] < 1)) {
				pts_free(&p);
				free(pts);
				cli_die("%s: point %llu is outside [0,1)^2", o->file,
				    (unsigned long long)i);
			}
			pts[2 * i] = r[0];
			pts[2 * i + 1] = r[1];
		}
		pts_free(&p);
		return pts;
	}
	snprintf(what, sizeof what, "-n %llu", (unsigned long long)o->n);
	pts = cli_calloc(what, o->n, 2 * sizeof *pts);
	if (o->input == INPUT_DART) {
		uint64_t placed;
		if (o->n > REFSAMP_MAX_N) {
			free(pts);
			cli_die("--input dart: -n %llu is over %llu",
			    (unsigned long long)o->n,
			    (unsigned long long)REFSAMP_MAX_N);
		}
		if (refsamp_gen(REFSAMP_DART, o->n, seed,
		    REFSAMP_DART_FAILURES, pts, &placed) < 0) {
			free(pts);
			cli_die("--input dart: %s", cli_errmsg());
		}
		if (placed < o->n && o->sets > 1) {
			free(pts);
			cli_die("--input dart, seed %llu: placed only %llu of %llu "
			    "points; with --sets every set needs them all: lower "
			    "-n", (unsigned long long)seed,
			    (unsigned long long)placed, (unsigned long long)o->n);
		}
		if (placed < o->n) {
			fprintf(stderr, "hsw-sample: --input dart placed %llu of "
			    "%llu points; warping those\n",
			    (unsigned long long)placed,
			    (unsigned long long)o->n);
			o->n = placed;
		}
		return pts;
	}
	if (frs_hsw_input((enum frs_hsw_input)o->input, o->n, seed, pts,
	    NULL) != FRS_OK)
		cli_die("--input: not an input set");	/* parse_opts' */
	return pts;
}

/* The sets are made on the fly, round by round, except those of a file,
 * dart throwing and the device, which is handed them all. */
static int whole_input(const struct opts *o)
{
	return o->file != NULL || o->input == INPUT_DART || o->cl;
}

/* The output, and the seconds spent writing it and making the input
 * of sets after the first. */
struct output {
	struct outfile of;
	struct sets_writer w;
	double t_out, t_input;
};

static int put_round(void *ctx, const double *xy, const double *pdf,
    size_t k)
{
	struct output *u = ctx;
	double t0 = cli_now();
	int rc = sets_writer_put_cols(&u->w, xy, &pdf, k);

	u->t_out += cli_now() - t0;
	return rc;
}

/* The M sets, set i of seed S + i (pts: set 0's input, when made
 * beforehand), warped into one file. */
static void warp_and_write(struct opts *o, struct hsw_run *r, double *pts,
    struct output *u)
{
	static const char *const names[] = { PTS_COL_PDF };
	enum frs_hsw_input kind = (enum frs_hsw_input)(o->input == INPUT_DART ?
	    FRS_HSW_HALTON : o->input);
	struct cli_task *task;
	double t0;
	int rc;

	cli_out_open(&u->of, cli.out, !cli.text);
	rc = sets_writer_begin(&u->w, u->of.fp, u->of.name, 2,
	    (unsigned)o->pdf, names, o->sets, o->sets * o->n, cli.text);
	task = cli_task_begin("sets", o->sets);
	for (uint64_t set = 0; rc == 0 && set < o->sets; set++) {
		if (set > 0 && pts != NULL) {
			free(pts);
			t0 = cli_now();
			pts = make_input(o, cli.seed + set);
			u->t_input += cli_now() - t0;
		}
		u->w.set = set;
		rc = hsw_run_each(r, kind, pts, o->n, cli.seed + set, o->pdf,
		    put_round, u);
		cli_task_update(task, set + 1);
	}
	cli_task_end(task);
	free(pts);
	t0 = cli_now();
	if (rc == 0)
		rc = sets_writer_end(&u->w);
	cli_out_commit(&u->of, rc);
	u->t_out += cli_now() - t0;
}

static void report(const struct opts *o, const struct hsw_run *r,
    double t_setup, double t_out)
{
	const struct frs_hsw_info *t = &r->info;

	fprintf(stderr, "hsw-sample: map %ux%u padded to %ux%u (%u levels), "
	    "mean %.6g; input %s, %llu points, %llu set%s, %d threads\n",
	    t->width, t->height, t->side, t->side, t->levels, t->mean,
	    o->file ? o->file : o->input == INPUT_DART ? "dart" :
	    frs_names(FRS_NAMES_HSW_INPUT)[o->input], (unsigned long long)o->n,
	    (unsigned long long)o->sets, o->sets == 1 ? "" : "s",
	    cli_threads());
	fprintf(stderr, "hsw-sample: setup %.6f s, warping %.6f s, output "
	    "%.6f s\n", t_setup, r->t_warp, t_out);
	if (r->cl)
		fprintf(stderr, "hsw-sample: device %s: program and tree %.6f "
		    "s; points written %.6f s, kernel %.6f s, read %.6f s\n",
		    cli_device_name(r->dev), r->hc.t_setup, r->hc.t_write, r->hc.t_kernel,
		    r->hc.t_read);
}

int main(int argc, char **argv)
{
	struct opts o = { .input = FRS_HSW_HALTON, .sets = 1, .cl_index = -1 };
	struct hsw_run r;
	struct output u = { .t_out = 0 };
	double *pts = NULL, t0;
	int rc;

	cli_init("hsw-sample", usage);
	parse_opts(argc, argv, &o);
	cli_options_done();
	if ((rc = hsw_run_open(&r, o.imp, o.w, o.h, o.flags, o.cl,
	    o.cl_index)) < 0)
		rc == -2 ? cli_die_device(1) : cli_die_lib();
	/* Set 0's input before the output opens: its count (a file's, the
	 * darts placed) goes into the header. */
	t0 = cli_now();
	if (whole_input(&o))
		pts = make_input(&o, cli.seed);
	u.t_input = cli_now() - t0;
	warp_and_write(&o, &r, pts, &u);
	if (o.verbose)
		report(&o, &r, r.t_tree + u.t_input, u.t_out);
	hsw_run_close(&r);
	return 0;
}
