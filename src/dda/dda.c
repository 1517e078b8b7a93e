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

#include "frs.h"
#include "cli/cli.h"
#include "dda/ddaspec.h"
#include "dda/density.h"
#include "dda/plot.h"
#include "dda/spectrum.h"

static const char usage[] =
    "usage: dda [--fourier | --dda | --density | --rdf] [--summary]\n"
    "           [--density-rule geometric | max]\n"
    "           [-i IMPORTANCE] [-s WxH] [--equirect] [--strict] [--size K]\n"
    "           [--approx] [--eps E]\n"
    "           [--sigma S] [--bin W] [--torus] [--rmax R] [--bins B]\n"
    "           [--png FILE] [--radial FILE] [--db LO:HI] [--sets N] [-j N]\n"
    "           [-q] [-o FILE] FILE...\n"
    "\n"
    "  --fourier         power spectrum on integer frequencies (default)\n"
    "  --dda             differential domain analysis (Wei and Wang 2011)\n"
    "  --density         minimum distance and density rho (Eq. 6.21);\n"
    "                    the only analysis of 3-D sets (uniform, no -i)\n"
    "  --density-rule R  --density with -i: a pair's distance in the\n"
    "                    geometric mean of the two points' local spacings\n"
    "                    (geometric, default) or in the denser point's\n"
    "                    spacing (max: the larger scale)\n"
    "  --rdf             radial distribution function\n"
    "  --summary         all of them per file, one table (and one PNG page\n"
    "                    with --png): --fourier (or --dda), its radial\n"
    "                    mean and anisotropy, --density and --rdf\n"
    "  -i, --importance M  map of adaptive sets (PNG, OpenEXR or a spec):\n"
    "                    --dda, --density and --rdf measure distances in\n"
    "                    local sample spacings\n"
    "  -s, --size-map WxH  size at which procedural maps are evaluated\n"
    "                    (default 128x128), or files resampled\n"
    "  --equirect        weight map rows by sin(theta)\n"
    "  --strict          negative importance is an error\n"
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
    "  --png FILE        --fourier, --dda: the image as an 8-bit PNG;\n"
    "                    --summary: the page of pictures and curves\n"
    "  --radial FILE     --fourier, --dda: radial mean and anisotropy\n"
    "  --db LO:HI        PNG grey scale in dB (-10:10)\n"
    "  --sets N          split every file into sets of N points in\n"
    "                    file order (a file with a set column: its sets)\n"
    "  -j, --threads N   threads (default: all cores)\n"
    "  -o, --output F    the table (default standard output)\n"
    "  -q, --quiet       no notes;  --progress  a progress bar\n"
    "  -h, --help        this help;  --version  the version\n";

enum mode { FOURIER, DDA, DENSITY, RDF };

struct opts {
	enum mode mode;
	int nmodes, approx, torus, have_size, have_bin, summary;
	int flags;		/* frs_imap_load's: --equirect, --strict */
	const char *imp, *png, *radial;
	uint32_t mw, mh, size;
	double eps, sigma, bin, rmax, lo_db, hi_db;
	size_t bins, per;
	enum dens_rule rule;	/* --density-rule */
	int have_rule;
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

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "fourier dda density density-rule rdf i=importance s=size-map equirect strict size "
    "approx "
    "eps sigma bin torus rmax bins png radial db sets summary";

static void parse(int argc, char **argv, struct opts *o)
{
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case OPT_FOURIER: set_mode(o, FOURIER); break;
		case OPT_DDA: set_mode(o, DDA); break;
		case OPT_DENSITY: set_mode(o, DENSITY); break;
		case OPT_DENSITY_RULE: {
			static const char *const rules[] = { "geometric",
			    "max", NULL };
			o->rule = cli_choice("--density-rule", optarg, rules) ?
			    DENS_MAX : DENS_GEOMETRIC;
			o->have_rule = 1;
			break;
		}
		case OPT_RDF: set_mode(o, RDF); break;
		case OPT_SUMMARY: o->summary = 1; break;
		case 'i': o->imp = optarg; break;
		case 's':
			cli_size("-s", optarg, FRS_MAP_MAX_SIDE, &o->mw, &o->mh);
			break;
		case OPT_EQUIRECT: o->flags |= FRS_MAP_EQUIRECT; break;
		case OPT_STRICT: o->flags |= FRS_MAP_STRICT; break;
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
		case OPT_PNG: o->png = cli_outname("--png", optarg); break;
		case OPT_RADIAL: o->radial = cli_outname("--radial", optarg); break;
		case OPT_DB: parse_db(o, optarg); break;
		case OPT_SETS: o->per = cli_sets(optarg); break;
		default:
			cli_common_only(c, optarg);
		}
	}
	cli_need_files(argc);
	if (o->nmodes > 1)
		cli_usage_error("one of --fourier, --dda, --density, --rdf");
	if (o->summary && (o->mode == DENSITY || o->mode == RDF))
		cli_usage_error("--summary holds --density and --rdf; it goes "
		    "with --fourier or --dda alone");
	if (o->summary && o->radial)
		cli_usage_error("--radial: --summary writes the radial means "
		    "in its table");
	if ((o->png || o->radial) && (o->mode == DENSITY || o->mode == RDF))
		cli_usage_error("--png and --radial go with --fourier or --dda");
	if (o->have_rule && (o->mode != DENSITY || o->summary))
		cli_usage_error("--density-rule goes with --density");
	if (o->flags && o->imp == NULL)
		cli_usage_error("--equirect and --strict go with -i");
	if (o->imp && o->mode == FOURIER)
		cli_usage_error("-i: the Fourier spectrum is for uniform sets; "
		    "use --dda for adaptive ones");
	if (o->approx && o->mode != FOURIER)
		cli_usage_error("--approx goes with --fourier");
	if (o->torus && (o->mode == FOURIER || o->mode == DDA) &&
	    !o->summary)
		cli_usage_error("--torus goes with --density, --rdf or "
		    "--summary");
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
		cli_fail_context(s->file);
		cli_die_lib();
	}
	return f;
}

static void radial_of(const struct opts *o, const struct spec_img *im,
    struct spec_radial *r)
{
	double bin = o->have_bin ? o->bin : 2 * im->scale;

	if (spec_radial(im, bin, r) < 0)
		cli_die_lib();
}

/* The radial table; file: a last column naming the set's file, or NULL. */
static void print_radial(const struct opts *o, FILE *fp,
    const struct spec_radial *r, const char *file)
{
	fprintf(fp, "%s\tpower\taniso_db\tcount%s\n",
	    o->mode == FOURIER ? "freq" : "dist", file ? "\tfile" : "");
	for (size_t i = 0; i < r->nbins; i++) {
		if (r->count[i] <= 1)
			continue;
		fprintf(fp, "%.9g\t%.9g\t%.6g\t%llu", r->lo[i], r->mean[i],
		    r->aniso[i], (unsigned long long)r->count[i]);
		if (file)
			fprintf(fp, "\t%s", file);
		fputc('\n', fp);
	}
}

static void write_radial(const struct opts *o, const struct spec_img *im)
{
	struct spec_radial r;
	struct outfile of;

	radial_of(o, im, &r);
	cli_out_open(&of, o->radial, 0);
	print_radial(o, of.fp, &r, NULL);
	cli_out_commit(&of, 0);
	spec_radial_free(&r);
}

static void write_png(const struct opts *o, const struct spec_img *im)
{
	struct outfile of;

	cli_out_open(&of, o->png, 1);
	cli_out_commit(&of, spec_write_png(of.fp, of.name, im, o->lo_db,
	    o->hi_db));
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

/* The mean spectrum (or DDA) of the nset sets at set into im. */
static void spectrum_of(const struct opts *o, const struct pt_set *set,
    size_t nset, const struct frs_imap *map, struct spec_img *im)
{
	struct cli_task *task;
	double scale = o->mode == FOURIER ? 1.0 : o->eps / o->size;
	size_t npx;

	if (spec_img_alloc(im, o->size, scale) < 0)
		cli_die_lib();
	npx = (size_t)(2 * o->size + 1) * (2 * o->size + 1);
	task = cli_task_begin(o->mode == FOURIER ? "fourier" : "dda", nset);
	for (size_t i = 0; i < nset; i++) {
		const struct pt_set *s = &set[i];
		int rc;
		if (o->mode == FOURIER)
			rc = o->approx ? spec_fourier_approx(s->xy, s->n, 1,
			    im) : spec_fourier_exact(s->xy, s->n, 1, im);
		else {
			double *f = scales(o, map, s);
			rc = dda_add(s->xy, s->n, f, o->eps, o->size,
			    o->sigma, 1, im->v);
			free(f);
		}
		if (rc < 0) {
			cli_fail_context(s->file);
			cli_die_lib();
		}
		cli_task_update(task, i + 1);
	}
	cli_task_end(task);
	for (size_t k = 0; k < npx; k++)
		im->v[k] /= (double)nset;
}

static void spectrum(const struct opts *o, const struct pt_sets *ps,
    const struct frs_imap *map, FILE *out)
{
	struct spec_img im;

	spectrum_of(o, ps->set, ps->n, map, &im);
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
	if (o->mode != DENSITY || o->summary)
		cli_die("%s: 3-dimensional points: %s is 2-D only; 3-D sets "
		    "take --density", file,
		    o->summary ? "--summary" : name[o->mode]);
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
	    dens_min_distance_rule(s->xy, s->n, f, o->rule, o->torus, 1,
	    dmin);

	if (rc < 0) {
		cli_fail_context(s->file);
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

static size_t rdf_bins(const struct opts *o)
{
	return o->bins ? o->bins : 200;
}

static double rdf_rmax(const struct opts *o)
{
	return o->rmax > 0 ? o->rmax : 4.0;
}

/* The RDF of the nset sets at set, the mean over them: rdf_bins(o)
 * values, to be freed. */
static double *rdf_of(const struct opts *o, const struct pt_set *set,
    size_t nset, const struct frs_imap *map)
{
	size_t bins = rdf_bins(o);
	double rmax = rdf_rmax(o);
	double *acc = calloc(bins, sizeof *acc);

	if (acc == NULL)
		cli_die("no memory for %zu bins", bins);
	for (size_t i = 0; i < nset; i++) {
		const struct pt_set *s = &set[i];
		double *f = scales(o, map, s);
		if (s->n < 2)
			cli_die("%s: the distribution needs 2 points or more",
			    s->file);
		if (dens_rdf_add(s->xy, s->n, f, o->torus, rmax, bins, 1,
		    acc) < 0) {
			cli_fail_context(s->file);
			cli_die_lib();
		}
		free(f);
	}
	for (size_t b = 0; b < bins; b++)
		acc[b] /= (double)nset;
	return acc;
}

/* The centre of RDF bin b, in mean spacings. */
static double rdf_r(const struct opts *o, size_t b)
{
	return ((double)b + 0.5) * rdf_rmax(o) / (double)rdf_bins(o);
}

static void print_rdf(const struct opts *o, FILE *fp, const double *g,
    const char *file)
{
	fprintf(fp, "r\tg%s\n", file ? "\tfile" : "");
	for (size_t b = 0; b < rdf_bins(o); b++) {
		fprintf(fp, "%.9g\t%.9g", rdf_r(o, b), g[b]);
		if (file)
			fprintf(fp, "\t%s", file);
		fputc('\n', fp);
	}
}

static void rdf(const struct opts *o, const struct pt_sets *ps,
    const struct frs_imap *map, FILE *out)
{
	double *g = rdf_of(o, ps->set, ps->n, map);

	print_rdf(o, out, g, NULL);
	free(g);
}

/* ---- --summary ---------------------------------------------------------
 * Per file (a group of consecutive sets): the mean spectrum (or DDA), its
 * radial mean and anisotropy, the density of every set and the mean RDF,
 * as one table of blocks, and with --png one page, a column per file. */

struct group {
	const struct pt_set *set;
	size_t nset;
	struct spec_radial rad;
	double *g;			/* rdf_bins values */
	double nmean, dmin, rho;	/* means over the sets */
	double peak, peak_r;		/* largest value off the centre */
	double gmax, gmax_r;		/* largest g and its r */
};

/* The page: layout in pixels (dda(1) states the size). */
#define PG_SCALE 2		/* text scale: 8 pixels a character */
#define PG_ML 44		/* left margin of a column (tick labels) */
#define PG_MR 16
#define PG_TOP 40		/* the image's top: two lines of title above */
#define PG_GAP 20		/* between the image and the first plot */
#define PG_PLOT_EXTRA 46	/* per plot: title 16 above, labels 30 below */

struct page {
	struct frs_raster r;
	uint32_t side, pw, ph, colw;
};

static uint32_t page_plot_w(uint32_t side)
{
	return side > 256 ? side : 256;
}

static void page_alloc(const struct opts *o, size_t ngroups,
    struct page *pg)
{
	uint64_t w, h;

	pg->side = 2 * o->size + 1;
	pg->pw = page_plot_w(pg->side);
	pg->ph = pg->pw / 2;
	pg->colw = PG_ML + pg->pw + PG_MR;
	w = (uint64_t)ngroups * pg->colw;
	h = PG_TOP + pg->side + PG_GAP + 3 * ((uint64_t)pg->ph + PG_PLOT_EXTRA);
	if (w > UINT32_MAX || raster_alloc(&pg->r, (uint32_t)w, (uint32_t)h,
	    3) < 0) {
		cli_fail("%s: a page of %llu x %llu pixels for %zu files is "
		    "too large (fewer files or a smaller --size)", o->png,
		    (unsigned long long)w, (unsigned long long)h, ngroups);
		cli_die_lib();
	}
}

/* The title: the file's name, fitted into two lines of the band above
 * the image (plot_text_fit), and the figures. */
static void page_title(struct page *pg, int x0, const struct group *gr)
{
	static const uint8_t ink[3] = { 0, 0, 0 };
	char line[256];

	plot_text_fit(&pg->r, x0 + 4, 8, (int)pg->colw - 8, 13, PG_SCALE,
	    gr->set[0].file, ink);
	snprintf(line, sizeof line, "%zu SET%s  N %.6g  RHO %.3f", gr->nset,
	    gr->nset == 1 ? "" : "S", gr->nmean, gr->rho);
	plot_text(&pg->r, x0 + 4, 22, PG_SCALE, line, ink);
}

/* One plot of the column at x0: the n-th, title above. */
static void page_plot(struct page *pg, int x0, int k, const char *title,
    double xmax, double y0, double y1, const double *yt, size_t nyt,
    double ref, const double *x, const double *y, size_t n,
    const uint8_t *color)
{
	static const uint8_t ink[3] = { 0, 0, 0 };
	static const uint8_t grey[3] = { 140, 140, 140 };
	double xt[3] = { 0, xmax / 2, xmax };
	int top = PG_TOP + (int)pg->side + PG_GAP +
	    k * ((int)pg->ph + PG_PLOT_EXTRA);
	struct plot_box b = { x0 + PG_ML, top + 16, (int)pg->pw, (int)pg->ph,
	    0, xmax, y0, y1 };

	plot_text(&pg->r, b.px, top, PG_SCALE, title, ink);
	plot_axes(&pg->r, &b, xt, 3, yt, nyt, PG_SCALE);
	plot_hline(&pg->r, &b, ref, grey);
	plot_curve(&pg->r, &b, x, y, n, color);
}

/* The anisotropy plot's axis, one for all the columns so that they
 * compare: its range around every curve and noise line (10 log10(1/m)
 * for m sets: lower for more sets), in whole steps of 5, 10, 20 or 50 dB,
 * at most 6 of them, and its ticks. */
struct aniso_axis {
	double lo, hi, tick[8];
	size_t ntick;
};

/* The values the axis must hold: every plotted anisotropy (annuli 1 on
 * with more than one pixel) and noise line; *n of them, to be freed. */
static double *aniso_values(const struct group *gr, size_t ngroups,
    size_t *n)
{
	size_t cap = 0, k = 0;
	double *v;

	for (size_t g = 0; g < ngroups; g++)
		cap += gr[g].rad.nbins + 1;
	if ((v = malloc(cap * sizeof *v)) == NULL)
		cli_die("no memory for the page");
	for (size_t g = 0; g < ngroups; g++) {
		v[k++] = 10 * log10(1.0 / (double)gr[g].nset);
		for (size_t i = 1; i < gr[g].rad.nbins; i++)
			if (gr[g].rad.count[i] > 1)
				v[k++] = gr[g].rad.aniso[i];
	}
	*n = k;
	return v;
}

static void aniso_axis(const struct group *gr, size_t ngroups,
    struct aniso_axis *ax)
{
	static const double steps[] = { 5, 10, 20, 50 };
	double step = 0, noise0 = 10 * log10(1.0 / (double)gr[0].nset);
	size_t n;
	double *v = aniso_values(gr, ngroups, &n);

	for (size_t i = 0; i < sizeof steps / sizeof steps[0]; i++) {
		step = steps[i];
		plot_range(v, n, noise0, step, &ax->lo, &ax->hi);
		if ((ax->hi - ax->lo) / step <= 6)
			break;
	}
	free(v);
	if ((ax->hi - ax->lo) / step > 6)	/* past 300 dB: the edges */
		ax->lo = ax->hi - 6 * step;
	ax->ntick = 0;
	for (double t = ax->lo; t <= ax->hi + step / 2; t += step)
		ax->tick[ax->ntick++] = t;
}

/* The title and the spectrum (or DDA) image of column col. */
static void page_image(const struct opts *o, struct page *pg, size_t col,
    const struct spec_img *im, const struct group *gr)
{
	int x0 = (int)(col * pg->colw);
	int ix = x0 + PG_ML + (int)(pg->pw - pg->side) / 2;

	page_title(pg, x0, gr);
	for (uint32_t r = 0; r < pg->side; r++)
		for (uint32_t c = 0; c < pg->side; c++) {
			uint8_t v = spec_grey(im->v[(size_t)r * pg->side + c],
			    o->lo_db, o->hi_db);
			memset(pg->r.px + ((size_t)(PG_TOP + r) * pg->r.w +
			    (size_t)ix + c) * 3, v, 3);
		}
}

/* The three plots of column col. */
static void page_plots(const struct opts *o, struct page *pg, size_t col,
    const struct group *gr, const struct aniso_axis *ax)
{
	static const uint8_t blue[3] = { 0, 0, 200 }, red[3] = { 200, 0, 0 },
	    green[3] = { 0, 130, 0 };
	static const double yt[] = { 0, 1, 2, 3, 4 };
	int x0 = (int)(col * pg->colw);
	size_t nb = gr->rad.nbins, ng = rdf_bins(o), m = 0;
	double *x = malloc((nb + ng + 1) * sizeof *x);
	double *y = malloc((nb + ng + 1) * sizeof *y);
	double bin = nb > 1 ? gr->rad.lo[1] - gr->rad.lo[0] : 0;
	double xmax = o->mode == FOURIER ? (double)o->size : o->eps;
	const char *unit = o->mode == FOURIER ? "FREQUENCY" : "SPACINGS";
	char title[64];

	if (x == NULL || y == NULL)
		cli_die("no memory for the page");
	/* Annulus 0 holds DC (or d = 0): the table has it, the plots not. */
	for (size_t i = 1; i < nb; i++)
		if (gr->rad.count[i] > 1) {
			x[m] = gr->rad.lo[i] + bin / 2;
			y[m++] = gr->rad.mean[i];
		}
	snprintf(title, sizeof title, "RADIAL MEAN VS %s", unit);
	page_plot(pg, x0, 0, title, xmax, 0, 4, yt, 5, 1.0, x, y, m, blue);
	for (size_t i = 1, j = 0; i < nb; i++)
		if (gr->rad.count[i] > 1)
			y[j++] = gr->rad.aniso[i];
	page_plot(pg, x0, 1, "ANISOTROPY DB", xmax, ax->lo, ax->hi, ax->tick,
	    ax->ntick, 10 * log10(1.0 / (double)gr->nset), x, y, m, red);
	for (size_t b = 0; b < ng; b++) {
		x[b] = rdf_r(o, b);
		y[b] = gr->g[b];
	}
	page_plot(pg, x0, 2, "RDF G(R) VS SPACINGS", rdf_rmax(o), 0, 4, yt, 5,
	    1.0, x, y, ng, green);
	free(x);
	free(y);
}

/* Everything of one group but the table and its plots; its image on
 * the page. */
static void group_run(const struct opts *o, const struct frs_imap *map,
    struct group *gr, double *dmin, double *rho, struct page *pg,
    size_t col)
{
	struct spec_img im;
	uint32_t side = 2 * o->size + 1;
	double sd = 0, sr = 0, sn = 0;

	for (size_t i = 0; i < gr->nset; i++) {
		const struct pt_set *s = &gr->set[i];
		double *f = scales(o, map, s);
		if (s->n < 2)
			cli_die("%s: the density needs 2 points or more",
			    s->file);
		min_distance(o, s, f, &dmin[i], &rho[i]);
		free(f);
		sd += dmin[i], sr += rho[i], sn += (double)s->n;
	}
	gr->nmean = sn / (double)gr->nset;
	gr->dmin = sd / (double)gr->nset;
	gr->rho = sr / (double)gr->nset;
	spectrum_of(o, gr->set, gr->nset, map, &im);
	radial_of(o, &im, &gr->rad);
	/* The peak off the centre within the radius of the radial means;
	 * values within 1e-9 of each other are equal, the nearer wins (a
	 * lattice's first frequency, not a rounding of its multiples). */
	gr->peak = -1;
	gr->peak_r = 0;
	for (uint32_t r = 0; r < side; r++)
		for (uint32_t c = 0; c < side; c++) {
			double v = im.v[(size_t)r * side + c];
			double d = hypot((double)c - o->size,
			    (double)r - o->size);
			if ((r == o->size && c == o->size) || d > o->size)
				continue;
			if (v > gr->peak * (1 + 1e-9) || (v >= gr->peak *
			    (1 - 1e-9) && d < gr->peak_r / im.scale)) {
				gr->peak = v;
				gr->peak_r = im.scale * d;
			}
		}
	gr->g = rdf_of(o, gr->set, gr->nset, map);
	gr->gmax = gr->g[0];
	gr->gmax_r = rdf_r(o, 0);
	for (size_t b = 1; b < rdf_bins(o); b++)
		if (gr->g[b] > gr->gmax) {
			gr->gmax = gr->g[b];
			gr->gmax_r = rdf_r(o, b);
		}
	if (pg != NULL)
		page_image(o, pg, col, &im, gr);
	spec_img_free(&im);
}

static void summary(const struct opts *o, const struct pt_sets *ps,
    const size_t *first, size_t ngroups, const struct frs_imap *map,
    FILE *out)
{
	struct group *gr = calloc(ngroups, sizeof *gr);
	double *dmin = malloc(ps->n * sizeof *dmin);
	double *rho = malloc(ps->n * sizeof *rho);
	const char *x = o->mode == FOURIER ? "freq" : "dist";
	struct page pg, *ppg = NULL;
	struct outfile of;

	if (gr == NULL || dmin == NULL || rho == NULL)
		cli_die("no memory for %zu sets", ps->n);
	if (o->png) {
		page_alloc(o, ngroups, &pg);
		ppg = &pg;
	}
	for (size_t k = 0; k < ngroups; k++) {
		gr[k].set = &ps->set[first[k]];
		gr[k].nset = first[k + 1] - first[k];
		group_run(o, map, &gr[k], dmin + first[k], rho + first[k],
		    ppg, k);
	}
	if (ppg != NULL) {
		struct aniso_axis ax;
		aniso_axis(gr, ngroups, &ax);
		for (size_t k = 0; k < ngroups; k++)
			page_plots(o, ppg, k, &gr[k], &ax);
	}
	fprintf(out, "# summary\nsets\tn\tdmin\trho\tpeak\tpeak_%s\tg_max\t"
	    "g_max_r\tfile\n", x);
	for (size_t k = 0; k < ngroups; k++)
		fprintf(out, "%zu\t%.10g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t%.9g\t"
		    "%s\n", gr[k].nset, gr[k].nmean, gr[k].dmin, gr[k].rho,
		    gr[k].peak, gr[k].peak_r, gr[k].gmax, gr[k].gmax_r,
		    gr[k].set[0].file);
	fprintf(out, "\n\n# density\nset\tn\tdmin\trho\tfile\n");
	for (size_t i = 0; i < ps->n; i++)
		fprintf(out, "%zu\t%zu\t%.9g\t%.9g\t%s\n", i, ps->set[i].n,
		    dmin[i], rho[i], ps->set[i].file);
	for (size_t k = 0; k < ngroups; k++) {
		fprintf(out, "\n\n# radial %s\n", gr[k].set[0].file);
		print_radial(o, out, &gr[k].rad, gr[k].set[0].file);
	}
	for (size_t k = 0; k < ngroups; k++) {
		fprintf(out, "\n\n# rdf %s\n", gr[k].set[0].file);
		print_rdf(o, out, gr[k].g, gr[k].set[0].file);
	}
	if (ppg != NULL) {
		cli_out_open(&of, o->png, 1);
		cli_out_commit(&of, raster_write_png(of.fp, of.name, &pg.r));
		raster_free(&pg.r);
	}
	for (size_t k = 0; k < ngroups; k++) {
		spec_radial_free(&gr[k].rad);
		free(gr[k].g);
	}
	free(gr);
	free(dmin);
	free(rho);
}

/* first[k + 1]: the sets of files 0 .. k. */
static int note_first(void *ctx, const struct pt_sets *s, size_t file,
    size_t first)
{
	size_t *f = ctx;

	(void)first;
	f[file + 1] = s->n;
	return 0;
}

int main(int argc, char **argv)
{
	struct opts o = { .mode = FOURIER, .eps = 12, .sigma = 1,
	    .lo_db = -10, .hi_db = 10 };
	struct pt_sets ps = { 0 };
	struct frs_imap map = { 0 };
	struct outfile of;
	size_t *first;

	cli_init("dda", usage);
	parse(argc, argv, &o);
	cli_options_done();
	ps.max_dims = 3;
	if ((first = calloc((size_t)(argc - optind) + 1, sizeof *first)) ==
	    NULL)
		cli_die("no memory");
	cli_read_sets(&ps, argc, argv, o.per, note_first, first);
	check_3d(&o, &ps);
	if (o.imp && frs_imap_load(&map, o.imp, o.mw, o.mh, o.flags,
	    NULL) != FRS_OK)
		cli_die_lib();
	cli_out_open(&of, cli.out, 0);
	if (o.summary)
		summary(&o, &ps, first, (size_t)(argc - optind), &map, of.fp);
	else switch (o.mode) {
	case FOURIER:
	case DDA: spectrum(&o, &ps, &map, of.fp); break;
	case DENSITY: density(&o, &ps, &map, of.fp); break;
	default: rdf(&o, &ps, &map, of.fp); break;
	}
	cli_out_commit(&of, 0);
	if (o.imp)
		frs_imap_free(&map);
	pt_sets_free(&ps);
	free(first);
	return 0;
}
