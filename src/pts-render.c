/*
 * pts-render: draw a point set as a PNG stipple image, over its
 * importance map if one is given.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli/cli.h"
#include "cli/output.h"
#include "cli/ptsopt.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "base/outfile.h"
#include "formats/ptsets.h"
#include "formats/ptsio.h"
#include "analysis/raster.h"

static const char usage[] =
    "usage: pts-render [-q] [-s SIZE] [-r R] [-i MAP] [--color] [-o FILE] [PTS]\n"
    "                  [--log] [--srgb] [--equirect] [--strict]\n"
    "                  [--format png|pnm]\n"
    "                  [--axes xy|xz|yz] [--alpha A] [--set K [--sets N]]\n"
    "\n"
    "  PTS                 a point file, binary or text (default: standard\n"
    "                      input, also '-'); x, y are its first two\n"
    "                      coordinates, y growing downward\n"
    "      --set K         draw set K only (from 0): the points whose set\n"
    "                      column is K, or with --sets N the K-th run of\n"
    "                      N points of a file without one\n"
    "      --sets N        sets of N points in file order, for --set (a\n"
    "                      file with a set column: its sets)\n"
    "      --axes AB       the coordinates drawn across and down: xy\n"
    "                      (default), or xz or yz of a 3-D (or higher) set\n"
    "  -s, --size SIZE     image size, N (NxN) or WxH (default 512)\n"
    "  -r, --radius R      dot radius in pixels, the same for every dot\n"
    "                      (default: from the local spacing s of the\n"
    "                      points, s / 3 + 0.5, at most 1.5 * W / 512 but\n"
    "                      at least 0.7; denser is darker)\n"
    "      --alpha A       opacity of the dots, 0 to 1 (default 1)\n"
    "  -i, --importance MAP  draw over the importance map MAP (PNG, OpenEXR\n"
    "                      or a procedural spec such as blob) resampled to\n"
    "                      the image size: white for 0, light grey for its\n"
    "                      maximum\n"
    "      --log           shade the map by log10 of its positive values\n"
    "                      (for HDR maps)\n"
    "      --srgb          decode a PNG map from sRGB to linear\n"
    "      --equirect      weight the map's rows by sin(theta), as for an\n"
    "                      equirectangular environment map\n"
    "      --strict        negative importance is an error\n"
    "      --color         colour the dots by their order in the file,\n"
    "                      first blue to last red (RGB output); also\n"
    "                      --colour\n"
    "      --format FMT    png (default) or pnm (binary PGM, or PPM with\n"
    "                      --color); default pnm for a name ending in\n"
    "                      .pgm, .ppm or .pnm\n"
    "  -o, --output FILE   output file (default: standard output, never a\n"
    "                      terminal)\n"
    "  -q, --quiet         no warnings\n"
    "  -h, --help          this help;  --version  the version\n";

enum fmt { FMT_NONE, FMT_PNG, FMT_PNM };

static int is_stdin(const char *path)
{
	return path == NULL || strcmp(path, "-") == 0;
}

/* PNG unless asked otherwise or the name ends in a netpbm extension. */
static enum fmt format_of(enum fmt f, const char *path)
{
	const char *dot = path ? strrchr(path, '.') : NULL;

	if (f != FMT_NONE)
		return f;
	if (dot && (strcasecmp(dot, ".pgm") == 0 || strcasecmp(dot, ".ppm") ==
	    0 || strcasecmp(dot, ".pnm") == 0))
		return FMT_PNM;
	return FMT_PNG;
}

/* --axes: the coordinate indices drawn across (a[0]) and down (a[1]). */
static void parse_axes(const char *s, unsigned a[2])
{
	static const char *const name[] = { "xy", "xz", "yz" };
	static const unsigned pair[][2] = { { 0, 1 }, { 0, 2 }, { 1, 2 } };

	for (int k = 0; k < 3; k++)
		if (strcmp(s, name[k]) == 0) {
			a[0] = pair[k][0], a[1] = pair[k][1];
			return;
		}
	cli_usage_error("--axes: '%s' is not xy, xz or yz", s);
}

/* --set K: the records of set K (pt_split). */
static void pick_set(const struct frs_points *p, const char *name,
    size_t per, uint64_t set, size_t *first, size_t *count)
{
	struct pt_range *rg;
	size_t k;

	if (pts_column(p, PTS_COL_SET) < 0 && per == 0)
		cli_die("%s: --set %llu: the points have no set column; give "
		    "--sets N for sets of N points", name,
		    (unsigned long long)set);
	if (pt_split(p, name, per, &rg, &k) < 0)
		cli_die_lib();
	for (size_t i = 0; i < k; i++)
		if (rg[i].id == set) {
			*first = rg[i].first, *count = rg[i].n;
			free(rg);
			return;
		}
	free(rg);
	if (pts_column(p, PTS_COL_SET) >= 0)
		cli_die("%s: --set %llu: no point has that set", name,
		    (unsigned long long)set);
	cli_die("%s: --set %llu: the file has %zu sets of %zu points", name,
	    (unsigned long long)set, k, per);
}

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "s=size r=radius i=importance log color colour srgb equirect strict "
    "format axes alpha set sets";

int main(int argc, char **argv)
{
	const char *in = "-", *imp = NULL, *name;
	uint32_t w = 512, h = 512;
	double rad = 0.0, alpha = 1.0;
	struct raster_spacing sp;
	int c, logscale = 0, color = 0, flags = IMAP_ALLOW_ZERO;
	struct frs_points p;
	struct frs_raster r;
	struct outfile o;
	enum fmt format = FMT_NONE;
	size_t ncol;
	unsigned axis[2] = { 0, 1 };
	const char *axes = "xy";
	int rc, have_set = 0;
	uint64_t set = 0;
	size_t per = 0, first = 0, count;

	cli_init("pts-render", usage);
	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 's':
			cli_size("-s", optarg, IMAP_MAX_SIDE, &w, &h);
			break;
		case 'r':
			rad = cli_double("-r", optarg, 0.01, 65536.0);
			break;
		case 'i':
			imp = optarg;
			break;
		case OPT_LOG:
			logscale = 1;
			break;
		case OPT_COLOR:
			color = 1;
			break;
		case OPT_SRGB:
			flags |= IMAP_SRGB;
			break;
		case OPT_EQUIRECT:
			flags |= IMAP_EQUIRECT;
			break;
		case OPT_STRICT:
			flags |= IMAP_STRICT;
			break;
		case OPT_ALPHA:
			alpha = cli_double("--alpha", optarg, 0.0, 1.0);
			break;
		case OPT_AXES:
			parse_axes(optarg, axis);
			axes = optarg;
			break;
		case OPT_SET:
			set = cli_u64("--set", optarg, 0, (uint64_t)1 << 53);
			have_set = 1;
			break;
		case OPT_SETS:
			per = cli_sets(optarg);
			break;
		case OPT_FORMAT:
			format = (enum fmt)(FMT_PNG + cli_choice("--format",
			    optarg, (const char *const[]){ "png", "pnm", NULL }));
			break;
		default:
			cli_common_only(c, optarg);
		}
	}
	if (argc - optind > 1)
		cli_usage_error("one point file at most");
	if (per && !have_set)
		cli_usage_error("--sets N: give --set K, the set to draw");
	if (argc - optind == 1)
		in = argv[optind];
	if ((uint64_t)w * h > IMAP_MAX_PIXELS)
		cli_usage_error("-s: %ux%u has more than %llu pixels", w, h,
		    (unsigned long long)IMAP_MAX_PIXELS);
	if (imp != NULL && is_stdin(imp) && is_stdin(in))
		cli_usage_error("the points and the importance map cannot both "
		    "be standard input");
	if (imp == NULL && (logscale || (flags & ~IMAP_ALLOW_ZERO)))
		cli_usage_error("--log, --srgb, --equirect and --strict need -i");

	/* The output first: a bad path fails before any work, and standard
	 * output is never a terminal. */
	cli_options_done();
	cli_out_open(&o, cli.out, 1);

	name = is_stdin(in) ? "<stdin>" : in;
	if (pts_read(in, &p) < 0)
		cli_die_lib();
	if (p.dims < 2)
		cli_die("%s: points have %u coordinate%s, need 2", name, p.dims,
		    p.dims == 1 ? "" : "s");
	if (axis[1] >= p.dims)
		cli_die("%s: --axes %s: points have %u coordinates, no z; "
		    "2-D sets take only xy", name, axes, p.dims);

	if (raster_alloc(&r, w, h, color ? 3 : 1) < 0)
		cli_die_lib();
	if (imp != NULL) {
		struct frs_imap m;

		if (imap_load(imp, w, h, flags, &m) < 0)
			cli_die_lib();
		if (raster_fill_imap(&r, &m, logscale) < 0)
			cli_die_lib();
		imap_free(&m);
	}

	count = p.n;
	if (have_set)
		pick_set(&p, name, per, set, &first, &count);
	ncol = (size_t)p.dims + p.extra;
	/* No -r: each dot's radius from the spacing around it. */
	if (rad == 0.0 && raster_spacing_init(&sp, p.x + first * ncol, count,
	    ncol, axis[0], axis[1], w, h) < 0)
		cli_die_lib();
	for (size_t k = 0; k < count; k++) {
		const double *x = p.x + (first + k) * ncol;
		double cx = x[axis[0]] * w, cy = x[axis[1]] * h;
		uint8_t ink[3] = { 0, 0, 0 };

		if (color)
			raster_ramp(k, count, ink);
		raster_disc_alpha(&r, cx, cy, rad > 0.0 ? rad :
		    raster_spacing_radius(&sp, cx, cy), ink, alpha);
	}
	if (rad == 0.0)
		raster_spacing_free(&sp);
	pts_free(&p);

	format = format_of(format, cli.out);
	rc = format == FMT_PNM ? raster_write_pnm(o.fp, o.name, &r) :
	    raster_write_png(o.fp, o.name, &r);
	cli_out_commit(&o, rc);
	raster_free(&r);
	return 0;
}
