/*
 * dda: spectral and spatial statistics of point sets (thesis Sec. 2.2,
 * 6.2-6.3): Fourier power spectra, differential domain analysis, radial
 * mean and anisotropy, density and the radial distribution function,
 * averaged over the sets given.  3-D sets: the density only.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "ddaspec.h"
#include "density.h"
#include "imap.h"
#include "outfile.h"
#include "progress.h"
#include "ptsets.h"
#include "spectrum.h"

static const char usage[] =
    "usage: dda [--fourier | --dda | --density | --rdf] [-i IMPORTANCE]\n"
    "           [-s WxH] [--size K] [--approx] [--eps E] [--sigma S]\n"
    "           [--bin W] [--torus] [--rmax R] [--bins B] [--png FILE]\n"
    "           [--radial FILE] [--db LO:HI] [--sets N] [-j N] [-q]\n"
    "           [-o FILE] FILE...\n"
    "\n"
    "  --fourier         power spectrum on integer frequencies (default)\n"
    "  --dda             differential domain analysis (Wei and Wang 2011)\n"
    "  --density         minimum distance and density rho (Eq. 6.21);\n"
    "                    the only analysis of 3-D sets (uniform, no -i)\n"
    "  --rdf             radial distribution function\n"
    "  -i, --importance M  map of adaptive sets (PNG, OpenEXR or a spec):\n"
    "                    --dda, --density and --rdf measure distances in\n"
    "                    local sample spacings\n"
    "  -s, --size-map WxH  size at which procedural maps are evaluated\n"
    "  --size K          frequencies |k| <= K (--fourier, default 128) or\n"
    "                    pixels from the centre (--dda, default 128)\n"
    "  --approx          --fourier by gridding and FFT instead of exact\n"
    "                    sums\n"
    "  --eps E           --dda: differentials up to E local spacings (12)\n"
    "  --sigma S         --dda: Gaussian splat of S pixels (1)\n"
    "  --bin W           annulus width of --radial: frequency units\n"
    "                    (--fourier, 2) or spacings (--dda, 2 pixels)\n"
    "  --torus           --density, --rdf: distances modulo 1\n"
    "  --rmax R          --rdf: up to R mean spacings (4)\n"
    "  --bins B          --rdf: bins (200)\n"
    "  --png FILE        --fourier, --dda: the image as an 8-bit PNG\n"
    "  --radial FILE     --fourier, --dda: radial mean and anisotropy\n"
    "  --db LO:HI        PNG grey scale in dB (-10:10)\n"
    "  --sets N          split every file into sets of N points (a file\n"
    "                    with a set column is split by it; N must agree)\n"
    "  -j, --threads N   threads (default: all cores)\n"
    "  -o, --output F    the table (default standard output)\n"
    "  -q, --quiet       no notes;  --progress  a progress bar\n"
    "  -h, --help        this help;  --version  the version\n";

enum mode { FOURIER, DDA, DENSITY, RDF };

enum {
	OPT_FOURIER = OPT_FIRST_PRIVATE, OPT_DDA, OPT_DENSITY, OPT_RDF,
	OPT_SIZE, OPT_APPROX, OPT_EPS, OPT_SIGMA, OPT_BIN, OPT_TORUS,
	OPT_RMAX, OPT_BINS, OPT_PNG, OPT_RADIAL, OPT_DB, OPT_SETS
};

static const struct option longopts[] = {
	{ "fourier", no_argument, NULL, OPT_FOURIER },
	{ "dda", no_argument, NULL, OPT_DDA },
	{ "density", no_argument, NULL, OPT_DENSITY },
	{ "rdf", no_argument, NULL, OPT_RDF },
	{ "importance", required_argument, NULL, 'i' },
	{ "size-map", required_argument, NULL, 's' },
	{ "size", required_argument, NULL, OPT_SIZE },
	{ "approx", no_argument, NULL, OPT_APPROX },
	{ "eps", required_argument, NULL, OPT_EPS },
	{ "sigma", required_argument, NULL, OPT_SIGMA },
	{ "bin", required_argument, NULL, OPT_BIN },
	{ "torus", no_argument, NULL, OPT_TORUS },
	{ "rmax", required_argument, NULL, OPT_RMAX },
	{ "bins", required_argument, NULL, OPT_BINS },
	{ "png", required_argument, NULL, OPT_PNG },
	{ "radial", required_argument, NULL, OPT_RADIAL },
	{ "db", required_argument, NULL, OPT_DB },
	{ "sets", required_argument, NULL, OPT_SETS },
	CLI_COMMON_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

struct opts {
	enum mode mode;
	int nmodes, approx, torus, have_size, have_bin;
	const char *imp, *png, *radial;
	uint32_t mw, mh, size;
	double eps, sigma, bin, rmax, lo_db, hi_db;
	size_t bins, per;
};

static void set_mode(struct opts *o, enum mode m)
{
	o->mode = m;
	o->nmodes++;
}

static void parse_db(struct opts *o, const char *s)
{
	char *end;
	o->lo_db = strtod(s, &end);
	if (end == s || *end != ':')
		cli_usage_error("--db: '%s' is not LO:HI", s);
	s = end + 1;
	o->hi_db = strtod(s, &end);
	if (end == s || *end != '\0' || !(o->hi_db > o->lo_db) ||
	    !isfinite(o->lo_db) || !isfinite(o->hi_db))
		cli_usage_error("--db: '%s' is not LO:HI with LO < HI", s);
}

static void parse(int argc, char **argv, struct opts *o)
{
	int c;

	while ((c = getopt_long(argc, argv, "i:s:" CLI_COMMON_SHORTOPTS,
	    longopts, NULL)) != -1) {
		switch (c) {
		case OPT_FOURIER: set_mode(o, FOURIER); break;
		case OPT_DDA: set_mode(o, DDA); break;
		case OPT_DENSITY: set_mode(o, DENSITY); break;
		case OPT_RDF: set_mode(o, RDF); break;
		case 'i': o->imp = optarg; break;
		case 's':
			cli_size("-s", optarg, IMAP_MAX_SIDE, &o->mw, &o->mh);
			break;
		case OPT_SIZE:
			o->size = (uint32_t)cli_u64("--size", optarg, 1, 4096);
			o->have_size = 1;
			break;
		case OPT_APPROX: o->approx = 1; break;
		case OPT_EPS:
			o->eps = cli_double("--eps", optarg, 1e-3, 1e3);
			break;
		case OPT_SIGMA:
			o->sigma = cli_double("--sigma", optarg, 0.05, 100);
			break;
		case OPT_BIN:
			o->bin = cli_double("--bin", optarg, 1e-6, 1e6);
			o->have_bin = 1;
			break;
		case OPT_TORUS: o->torus = 1; break;
		case OPT_RMAX:
			o->rmax = cli_double("--rmax", optarg, 1e-3, 1e4);
			break;
		case OPT_BINS:
			o->bins = (size_t)cli_u64("--bins", optarg, 1, 1000000);
			break;
		case OPT_PNG: o->png = optarg; break;
		case OPT_RADIAL: o->radial = optarg; break;
		case OPT_DB: parse_db(o, optarg); break;
		case OPT_SETS:
			o->per = (size_t)cli_u64("--sets", optarg, 1,
			    (uint64_t)1 << 40);
			break;
		default:
			if (!cli_common_opt(c, optarg))
				cli_usage(2);
		}
	}
	if (optind == argc)
		cli_usage_error("no point files");
	if (o->nmodes > 1)
		cli_usage_error("one of --fourier, --dda, --density, --rdf");
	if ((o->png || o->radial) && (o->mode == DENSITY || o->mode == RDF))
		cli_usage_error("--png and --radial go with --fourier or --dda");
	if (o->imp && o->mode == FOURIER)
		cli_usage_error("-i: the Fourier spectrum is for uniform sets; "
		    "use --dda for adaptive ones");
	if (o->approx && o->mode != FOURIER)
		cli_usage_error("--approx goes with --fourier");
	if (o->torus && (o->mode == FOURIER || o->mode == DDA))
		cli_usage_error("--torus goes with --density or --rdf");
	if (!o->have_size)
		o->size = 128;
}

/* Per-point scales of the Wei-Wang transform, or NULL without a map. */
static double *scales(const struct opts *o, const struct frs_imap *map,
    const struct pt_set *s)
{
	double *f;

	if (o->imp == NULL)
		return NULL;
	if ((f = malloc(s->n * sizeof *f)) == NULL)
		cli_die("no memory for %zu points", s->n);
	if (dens_scales(s->xy, s->n, map, f) < 0) {
		free(f);
		frs_fail_context(s->file);
		cli_die_lib();
	}
	return f;
}

static void write_radial(const struct opts *o, const struct spec_img *im)
{
	struct spec_radial r;
	struct outfile of;
	double bin = o->have_bin ? o->bin : 2 * im->scale;

	if (spec_radial(im, bin, &r) < 0)
		cli_die_lib();
	if (outfile_open(&of, o->radial, 0) < 0)
		cli_die_lib();
	fprintf(of.fp, "%s\tpower\taniso_db\tcount\n",
	    o->mode == FOURIER ? "freq" : "dist");
	for (size_t i = 0; i < r.nbins; i++)
		if (r.count[i] > 1)
			fprintf(of.fp, "%.9g\t%.9g\t%.6g\t%llu\n", r.lo[i],
			    r.mean[i], r.aniso[i],
			    (unsigned long long)r.count[i]);
	if (outfile_commit(&of) < 0)
		cli_die_lib();
	spec_radial_free(&r);
}

static void write_png(const struct opts *o, const struct spec_img *im)
{
	struct outfile of;

	if (outfile_open(&of, o->png, 1) < 0)
		cli_die_lib();
	if (spec_write_png(of.fp, of.name, im, o->lo_db, o->hi_db) < 0) {
		outfile_abort(&of);
		cli_die_lib();
	}
	if (outfile_commit(&of) < 0)
		cli_die_lib();
}

/* The image as a table: offset x, offset y, value. */
static void write_image(const struct opts *o, FILE *fp,
    const struct spec_img *im)
{
	uint32_t side = 2 * im->half + 1;

	fprintf(fp, o->mode == FOURIER ? "kx\tky\tpower\n" :
	    "dx\tdy\tvalue\n");
	for (uint32_t r = 0; r < side; r++)
		for (uint32_t c = 0; c < side; c++)
			fprintf(fp, "%.9g\t%.9g\t%.9g\n",
			    ((double)c - im->half) * im->scale,
			    ((double)r - im->half) * im->scale,
			    im->v[(size_t)r * side + c]);
}

static void spectrum(const struct opts *o, const struct pt_sets *ps,
    const struct frs_imap *map, FILE *out)
{
	struct spec_img im;
	struct progress pr;
	double scale = o->mode == FOURIER ? 1.0 : o->eps / o->size;
	size_t npx;

	if (spec_img_alloc(&im, o->size, scale) < 0)
		cli_die_lib();
	npx = (size_t)(2 * o->size + 1) * (2 * o->size + 1);
	progress_begin(&pr, o->mode == FOURIER ? "fourier" : "dda", ps->n);
	for (size_t i = 0; i < ps->n; i++) {
		const struct pt_set *s = &ps->set[i];
		int rc;
		if (o->mode == FOURIER)
			rc = o->approx ? spec_fourier_approx(s->xy, s->n, 1,
			    &im) : spec_fourier_exact(s->xy, s->n, 1, &im);
		else {
			double *f = scales(o, map, s);
			rc = dda_add(s->xy, s->n, f, o->eps, o->size,
			    o->sigma, 1, im.v);
			free(f);
		}
		if (rc < 0) {
			frs_fail_context(s->file);
			cli_die_lib();
		}
		progress_update(&pr, i + 1);
	}
	progress_end(&pr);
	for (size_t k = 0; k < npx; k++)
		im.v[k] /= (double)ps->n;
	if (o->png)
		write_png(o, &im);
	if (o->radial)
		write_radial(o, &im);
	write_image(o, out, &im);
	spec_img_free(&im);
}

/* 3-D sets have the density only, and no importance map. */
static void check_3d(const struct opts *o, const struct pt_sets *ps)
{
	static const char *const name[] = { "--fourier", "--dda",
	    "--density", "--rdf" };
	const char *file = ps->set[0].file;

	if (ps->dims != 3)
		return;
	if (o->mode != DENSITY)
		cli_die("%s: 3-dimensional points: %s is 2-D only; 3-D sets "
		    "take --density", file, name[o->mode]);
	if (o->imp != NULL)
		cli_die("%s: 3-dimensional points: -i is 2-D only; the 3-D "
		    "density is for uniform sets", file);
}

/* dmin and rho of one set, 2-D or 3-D. */
static void min_distance(const struct opts *o, const struct pt_set *s,
    const double *f, double *dmin, double *rho)
{
	int rc = s->dims == 3 ?
	    dens_min_distance3(s->xy, s->n, o->torus, 1, dmin) :
	    dens_min_distance(s->xy, s->n, f, o->torus, 1, dmin);

	if (rc < 0) {
		frs_fail_context(s->file);
		cli_die_lib();
	}
	*rho = s->dims == 3 ? dens_rho3(*dmin, s->n) : dens_rho(*dmin, s->n);
}

static void density(const struct opts *o, const struct pt_sets *ps,
    const struct frs_imap *map, FILE *out)
{
	double sd = 0, sr = 0, sn = 0;

	fprintf(out, "set\tn\tdmin\trho\tfile\n");
	for (size_t i = 0; i < ps->n; i++) {
		const struct pt_set *s = &ps->set[i];
		double *f = scales(o, map, s), dmin, rho;
		if (s->n < 2)
			cli_die("%s: the density needs 2 points or more",
			    s->file);
		min_distance(o, s, f, &dmin, &rho);
		free(f);
		sd += dmin, sr += rho, sn += (double)s->n;
		fprintf(out, "%zu\t%zu\t%.9g\t%.9g\t%s\n", i, s->n, dmin, rho,
		    s->file);
	}
	fprintf(out, "mean\t%.10g\t%.9g\t%.9g\t-\n", sn / (double)ps->n,
	    sd / (double)ps->n, sr / (double)ps->n);
}

static void rdf(const struct opts *o, const struct pt_sets *ps,
    const struct frs_imap *map, FILE *out)
{
	size_t bins = o->bins ? o->bins : 200;
	double rmax = o->rmax > 0 ? o->rmax : 4.0;
	double *acc = calloc(bins, sizeof *acc);

	if (acc == NULL)
		cli_die("no memory for %zu bins", bins);
	for (size_t i = 0; i < ps->n; i++) {
		const struct pt_set *s = &ps->set[i];
		double *f = scales(o, map, s);
		if (s->n < 2)
			cli_die("%s: the distribution needs 2 points or more",
			    s->file);
		if (dens_rdf_add(s->xy, s->n, f, o->torus, rmax, bins, 1,
		    acc) < 0) {
			frs_fail_context(s->file);
			cli_die_lib();
		}
		free(f);
	}
	fprintf(out, "r\tg\n");
	for (size_t b = 0; b < bins; b++)
		fprintf(out, "%.9g\t%.9g\n", ((double)b + 0.5) * rmax /
		    (double)bins, acc[b] / (double)ps->n);
	free(acc);
}

int main(int argc, char **argv)
{
	struct opts o = { .mode = FOURIER, .eps = 12, .sigma = 1,
	    .lo_db = -10, .hi_db = 10 };
	struct pt_sets ps = { 0 };
	struct frs_imap map = { 0 };
	struct outfile of;

	cli_init("dda", usage);
	parse(argc, argv, &o);
	cli_options_done();
	ps.max_dims = 3;
	for (int i = optind; i < argc; i++)
		if (pt_sets_add(&ps, argv[i], o.per) < 0)
			cli_die_lib();
	check_3d(&o, &ps);
	if (o.imp && imap_load(o.imp, o.mw, o.mh, 0, &map) < 0)
		cli_die_lib();
	if (outfile_open(&of, cli.out, 0) < 0)
		cli_die_lib();
	switch (o.mode) {
	case FOURIER:
	case DDA: spectrum(&o, &ps, &map, of.fp); break;
	case DENSITY: density(&o, &ps, &map, of.fp); break;
	default: rdf(&o, &ps, &map, of.fp); break;
	}
	if (outfile_commit(&of) < 0)
		cli_die_lib();
	if (o.imp)
		imap_free(&map);
	pt_sets_free(&ps);
	return 0;
}
