/*
 * hsw-sample: Hierarchical Sample Warping of a point set by an importance
 * map (Clarberg et al. 2005), the reference FRS is compared with.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "api/api.h"
#include "cli/cli.h"
#include "sample/hsw.h"
#include "sample/hswcl.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "base/mem.h"
#include "base/ocl.h"
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

enum { OPT_INPUT = OPT_FIRST_PRIVATE, OPT_PDF, OPT_DEVICE, OPT_LIST };

static const struct option longopts[] = {
	{ "count", required_argument, NULL, 'n' },
	{ "importance", required_argument, NULL, 'i' },
	{ "size", required_argument, NULL, 's' },
	{ "input", required_argument, NULL, OPT_INPUT },
	{ "pdf", no_argument, NULL, OPT_PDF },
	{ "device", required_argument, NULL, OPT_DEVICE },
	{ "list-devices", no_argument, NULL, OPT_LIST },
	{ "verbose", no_argument, NULL, 'v' },
	CLI_COMMON_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

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

static void parse_opts(int argc, char **argv, struct opts *o)
{
	int c;

	while ((c = cli_getopt(argc, argv, "n:i:s:v" CLI_COMMON_SHORTOPTS,
	    longopts)) != -1) {
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
		case OPT_LIST: cli_list_devices();
		case 'v': o->verbose = 1; break;
		default:
			if (!cli_common_opt(c, optarg))
				cli_usage(2);
		}
	}
	if (optind != argc)
		cli_usage_error("unexpected argument '%s'", argv[optind]);
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

/* Points per round of warping and writing: the record buffer (1.5 MiB
 * with --pdf), filled by all threads, then written at once. */
#define ROUND ((uint64_t)1 << 16)

/* Seconds spent warping and writing. */
struct times {
	double warp, out;
};

/*
 * Rounds of ROUND points: warped into the record buffer (x, y and the
 * density with --pdf) by all threads, or, with the device, warped there
 * beforehand (pts) and packed here; then written by one
 * pts_writer_put_n.  A point depends only on its index, so the bytes
 * are the same for any thread count, round or chunk size.
 */
static int write_rounds(const struct opts *o, const frs_hsw *hw,
    struct hswcl *hc, double *pts, struct pts_writer *w,
    struct times *tm)
{
	struct hsw_source src = { HSW_HALTON, o->n, cli.seed, pts };
	const struct frs_imap *map = o->pdf ? &hw->map : NULL;
	unsigned stride = o->pdf ? 3 : 2;
	uint64_t cap = o->n < ROUND ? o->n : ROUND;
	double *rec, t0 = progress_now(), mean = hsw_mean(&hw->t, &hw->map);
	int rc = -1;

	if (pts == NULL && o->input != INPUT_DART)
		src.kind = (enum hsw_input)o->input;
	if ((rec = mem_calloc("output buffer", cap, stride * sizeof *rec)) ==
	    NULL)
		return -1;
	if (hc != NULL && hswcl_warp_points(hc, pts, pts, o->n) < 0)
		goto out;
	for (uint64_t b = 0; b < o->n; b += ROUND) {
		uint64_t m = o->n - b < ROUND ? o->n - b : ROUND;
		double t1;

		if (hc == NULL) {
			if (hsw_sample(&hw->t, &src, map, b, b + m, rec) < 0)
				goto out;
		} else
			for (uint64_t q = 0; q < m; q++) {
				double *r = rec + q * stride;
				r[0] = pts[2 * (b + q)];
				r[1] = pts[2 * (b + q) + 1];
				if (map != NULL)
					r[2] = hsw_pdf_at(map, mean, r[0], r[1]);
			}
		t1 = progress_now();
		tm->warp += t1 - t0;
		if (pts_writer_put_n(w, rec, (size_t)m) < 0)
			goto out;
		t0 = progress_now();
		tm->out += t0 - t1;
	}
	rc = 0;
out:
	free(rec);
	return rc;
}

static void warp_and_write(const struct opts *o, const frs_hsw *hw,
    struct hswcl *hc, double *pts, struct times *tm)
{
	struct outfile of;
	struct pts_writer w;
	static const char *const names[] = { PTS_COL_PDF };
	double t0;

	if (outfile_open(&of, cli.out, !cli.text) < 0)
		cli_die_lib();
	if (pts_writer_begin(&w, of.fp, of.name, 2, (unsigned)o->pdf, names,
	    o->n, cli.text) < 0 || write_rounds(o, hw, hc, pts, &w, tm) < 0)
		goto fail;
	t0 = progress_now();
	if (pts_writer_end(&w) < 0)
		goto fail;
	if (outfile_commit(&of) < 0)
		cli_die_lib();
	tm->out += progress_now() - t0;
	return;
fail:
	outfile_abort(&of);
	cli_die_lib();
}

int main(int argc, char **argv)
{
	static const char *const names[] = { "random", "regular", "jittered",
	    "halton", "hammersley" };
	struct opts o = { NULL, NULL, HSW_HALTON, 0, 0, 0, 0, 0, 0, 0, -1 };
	struct frs_imap map;
	frs_hsw *hw;
	frs_error err;
	struct ocl dev;
	struct hswcl hc;
	double *pts = NULL, t0, t1;
	struct times tm = { 0, 0 };

	cli_init("hsw-sample", usage);
	parse_opts(argc, argv, &o);
	cli_options_done();
	if (o.cl && ocl_open(&dev, o.cl_index) < 0)
		cli_die_lib();
	if (imap_load(o.imp, o.w, o.h, 0, &map) < 0)
		cli_die_lib();
	t0 = progress_now();
	if (frs_hsw_new_f64(&hw, map.v, map.w, map.h, 0, &err) != FRS_OK)
		cli_die("%s: %s", o.imp, err.message);
	if (o.cl && hswcl_init(&hc, &dev, &hw->t) < 0)
		cli_die_lib();
	/* The sets are made on the fly, chunk by chunk, except for the
	 * device, which is handed them all. */
	if (o.file != NULL || o.input == INPUT_DART || o.cl)
		pts = make_input(&o);
	t1 = progress_now();
	warp_and_write(&o, hw, o.cl ? &hc : NULL, pts, &tm);
	if (o.verbose) {
		fprintf(stderr, "hsw-sample: map %ux%u padded to %ux%u "
		    "(%u levels), mean %.6g; input %s, %llu points, %d "
		    "threads\n", map.w, map.h, hw->t.size, hw->t.size,
		    hw->t.levels, hw->t.total / ((double)map.w * (double)map.h),
		    o.file ? o.file : o.input == INPUT_DART ? "dart" :
		    names[o.input], (unsigned long long)o.n,
		    frs_threads());
		fprintf(stderr, "hsw-sample: setup %.6f s, warping %.6f s, "
		    "output %.6f s\n", t1 - t0, tm.warp, tm.out);
		if (o.cl)
			fprintf(stderr, "hsw-sample: device %s: program and "
			    "tree %.6f s; points written %.6f s, kernel %.6f "
			    "s, read %.6f s\n", dev.name, hc.t_setup,
			    hc.t_write, hc.t_kernel, hc.t_read);
	}
	if (o.cl) {
		hswcl_free(&hc);
		ocl_close(&dev);
	}
	free(pts);
	frs_hsw_free(hw);
	imap_free(&map);
	return 0;
}
