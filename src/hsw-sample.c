/*
 * hsw-sample: Hierarchical Sample Warping of a point set by an importance
 * map (Clarberg et al. 2005), the reference FRS is compared with.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "api/hswrun.h"
#include "cli/cli.h"
#include "cli/output.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "base/mem.h"
#include "base/outfile.h"
#include "base/par.h"
#include "base/progress.h"
#include "formats/ptsio.h"
#include "sample/refsamp.h"

static const char usage[] =
    "usage: hsw-sample -i IMPORTANCE -n COUNT [--input SET|FILE] [--pdf]\n"
    "                  [-s WxH] [-S SEED] [-j N] [--device cpu|cl|cl:N]\n"
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
    "  -s, --size WxH       size at which procedural maps are evaluated\n"
    "                       (default 128x128), or files resampled\n"
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

/* --input dart: not an enum hsw_input; ref-sample's dart throwing. */
#define INPUT_DART 100

struct opts {
	const char *imp, *file;
	int input;		/* enum hsw_input, INPUT_DART, or -1 for file */
	uint64_t n;
	int have_n, pdf, verbose;
	uint32_t w, h;
	int cl, cl_index;	/* --device: OpenCL, and which (-1: first) */
};

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "n=count i=importance s=size input pdf device list-devices "
    "v=verbose";

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
			cli_size("-s", optarg, IMAP_MAX_SIDE, &o->w, &o->h);
			break;
		case OPT_INPUT:
			o->input = hsw_input_parse(optarg);
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
}

/* The input set: 2n doubles. */
static double *make_input(struct opts *o)
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
	if ((pts = mem_calloc(what, o->n, 2 * sizeof *pts)) == NULL)
		cli_die_lib();
	if (o->input == INPUT_DART) {
		uint64_t placed;
		if (o->n > REFSAMP_MAX_N) {
			free(pts);
			cli_die("--input dart: -n %llu is over %llu",
			    (unsigned long long)o->n,
			    (unsigned long long)REFSAMP_MAX_N);
		}
		if (refsamp_gen(REFSAMP_DART, o->n, cli.seed,
		    REFSAMP_DART_FAILURES, pts, &placed) < 0) {
			free(pts);
			cli_die("--input dart: %s", frs_errmsg());
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
	hsw_input_make((enum hsw_input)o->input, o->n, cli.seed, pts);
	return pts;
}

/* The output, and the seconds spent writing it. */
struct output {
	struct outfile of;
	struct pts_writer w;
	double t_out;
};

static int put_round(void *ctx, const double *rec, size_t k)
{
	struct output *u = ctx;
	double t0 = progress_now();
	int rc = pts_writer_put_n(&u->w, rec, k);

	u->t_out += progress_now() - t0;
	return rc;
}

static void warp_and_write(const struct opts *o, struct hsw_run *r,
    double *pts, struct output *u)
{
	static const char *const names[] = { PTS_COL_PDF };
	double t0;

	int rc;

	cli_out_open(&u->of, cli.out, !cli.text);
	rc = pts_writer_begin(&u->w, u->of.fp, u->of.name, 2, (unsigned)o->pdf,
	    names, o->n, cli.text);
	if (rc == 0)
		rc = hsw_run_each(r, (enum hsw_input)(o->input == INPUT_DART ?
		    HSW_HALTON : o->input), pts, o->n, cli.seed, o->pdf,
		    put_round, u);
	t0 = progress_now();
	if (rc == 0)
		rc = pts_writer_end(&u->w);
	cli_out_commit(&u->of, rc);
	u->t_out += progress_now() - t0;
}

static void report(const struct opts *o, const struct hsw_run *r,
    double t_setup, double t_out)
{
	static const char *const names[] = { "random", "regular", "jittered",
	    "halton", "hammersley" };
	uint32_t w, h, side;
	unsigned levels;
	double mean;

	hsw_run_shape(r, &w, &h, &side, &levels, &mean);
	fprintf(stderr, "hsw-sample: map %ux%u padded to %ux%u (%u levels), "
	    "mean %.6g; input %s, %llu points, %d threads\n", w, h, side, side,
	    levels, mean, o->file ? o->file : o->input == INPUT_DART ? "dart" :
	    names[o->input], (unsigned long long)o->n, frs_threads());
	fprintf(stderr, "hsw-sample: setup %.6f s, warping %.6f s, output "
	    "%.6f s\n", t_setup, r->t_warp, t_out);
	if (r->cl)
		fprintf(stderr, "hsw-sample: device %s: program and tree %.6f "
		    "s; points written %.6f s, kernel %.6f s, read %.6f s\n",
		    r->dev.name, r->hc.t_setup, r->hc.t_write, r->hc.t_kernel,
		    r->hc.t_read);
}

int main(int argc, char **argv)
{
	struct opts o = { NULL, NULL, HSW_HALTON, 0, 0, 0, 0, 0, 0, 0, -1 };
	struct hsw_run r;
	struct output u = { .t_out = 0 };
	double *pts = NULL, t0, t_input;
	int rc;

	cli_init("hsw-sample", usage);
	parse_opts(argc, argv, &o);
	cli_options_done();
	if ((rc = hsw_run_open(&r, o.imp, o.w, o.h, o.cl, o.cl_index)) < 0)
		rc == -2 ? cli_die_device(1) : cli_die_lib();
	/* The sets are made on the fly, round by round, except for the
	 * device, which is handed them all. */
	t0 = progress_now();
	if (o.file != NULL || o.input == INPUT_DART || o.cl)
		pts = make_input(&o);
	t_input = progress_now() - t0;
	warp_and_write(&o, &r, pts, &u);
	if (o.verbose)
		report(&o, &r, r.t_tree + t_input, u.t_out);
	hsw_run_close(&r);
	free(pts);
	return 0;
}
