/*
 * pts-render: draw a point set as a PNG stipple image, over its
 * importance map if one is given.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "frs.h"
#include "cli/cli.h"

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

/* Everything the command line asked for. */
struct render_opts {
	const char *in;		/* PTS, "-" for standard input */
	const char *imp;	/* -i, NULL for none */
	uint32_t w, h;		/* -s */
	double rad;		/* -r, 0 for each dot's from the spacing */
	double alpha;		/* --alpha */
	int logscale, color;	/* --log, --color */
	int flags;		/* the map's: --srgb, --equirect, --strict */
	enum fmt format;	/* --format */
	unsigned axis[2];	/* --axes, as indices */
	const char *axes;	/* --axes, as given */
	int have_set;		/* --set K given */
	uint64_t set;		/* K */
	size_t per;		/* --sets N, 0 for none */
};

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

static void parse_opts(int argc, char **argv, struct render_opts *o)
{
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 's':
			cli_size("-s", optarg, FRS_MAP_MAX_SIDE, &o->w, &o->h);
			break;
		case 'r':
			o->rad = cli_double("-r", optarg, 0.01, 65536.0);
			break;
		case 'i': o->imp = optarg; break;
		case OPT_LOG: o->logscale = 1; break;
		case OPT_COLOR: o->color = 1; break;
		case OPT_SRGB: o->flags |= FRS_MAP_SRGB; break;
		case OPT_EQUIRECT: o->flags |= FRS_MAP_EQUIRECT; break;
		case OPT_STRICT: o->flags |= FRS_MAP_STRICT; break;
		case OPT_ALPHA:
			o->alpha = cli_double("--alpha", optarg, 0.0, 1.0);
			break;
		case OPT_AXES:
			parse_axes(optarg, o->axis);
			o->axes = optarg;
			break;
		case OPT_SET:
			o->set = cli_u64("--set", optarg, 0, (uint64_t)1 << 53);
			o->have_set = 1;
			break;
		case OPT_SETS: o->per = cli_sets(optarg); break;
		case OPT_FORMAT:
			o->format = (enum fmt)(FMT_PNG + cli_choice("--format",
			    optarg, (const char *const[]){ "png", "pnm", NULL }));
			break;
		default:
			cli_common_only(c, optarg);
		}
	}
}

/* The operand, and the checks between options. */
static void check_opts(int argc, char **argv, struct render_opts *o)
{
	if (argc - optind > 1)
		cli_usage_error("one point file at most");
	if (o->per && !o->have_set)
		cli_usage_error("--sets N: give --set K, the set to draw");
	if (argc - optind == 1)
		o->in = argv[optind];
	if ((uint64_t)o->w * o->h > FRS_MAP_MAX_PIXELS)
		cli_usage_error("-s: %ux%u has more than %llu pixels", o->w,
		    o->h, (unsigned long long)FRS_MAP_MAX_PIXELS);
	if (o->imp != NULL && is_stdin(o->imp) && is_stdin(o->in))
		cli_usage_error("the points and the importance map cannot both "
		    "be standard input");
	if (o->imp == NULL && (o->logscale || (o->flags & ~FRS_MAP_ALLOW_ZERO)))
		cli_usage_error("--log, --srgb, --equirect and --strict need -i");
}

/* The points, with the coordinates --axes draws; their name for
 * messages. */
static const char *read_points(const struct render_opts *o,
    struct frs_points *p)
{
	const char *name = is_stdin(o->in) ? "<stdin>" : o->in;

	if (pts_read(o->in, p) < 0)
		cli_die_lib();
	if (p->dims < 2)
		cli_die("%s: points have %u coordinate%s, need 2", name, p->dims,
		    p->dims == 1 ? "" : "s");
	if (o->axis[1] >= p->dims)
		cli_die("%s: --axes %s: points have %u coordinates, no z; "
		    "2-D sets take only xy", name, o->axes, p->dims);
	return name;
}

/* -i: the importance map under the dots. */
static void draw_map(const struct render_opts *o, struct frs_raster *r)
{
	struct frs_imap m;

	if (frs_imap_load(&m, o->imp, o->w, o->h, o->flags, NULL) != FRS_OK)
		cli_die_lib();
	if (raster_fill_imap(r, &m, o->logscale) < 0)
		cli_die_lib();
	frs_imap_free(&m);
}

/* The dots of the points drawn (of set K with --set), in file order. */
static void draw_points(const struct render_opts *o,
    const struct frs_points *p, const char *name, struct frs_raster *r)
{
	struct raster_spacing sp;
	size_t first = 0, count = p->n, ncol = (size_t)p->dims + p->extra;

	if (o->have_set)
		pick_set(p, name, o->per, o->set, &first, &count);
	/* No -r: each dot's radius from the spacing around it. */
	if (o->rad == 0.0 && raster_spacing_init(&sp, p->x + first * ncol,
	    count, ncol, o->axis[0], o->axis[1], o->w, o->h) < 0)
		cli_die_lib();
	for (size_t k = 0; k < count; k++) {
		const double *x = p->x + (first + k) * ncol;
		double cx = x[o->axis[0]] * o->w, cy = x[o->axis[1]] * o->h;
		uint8_t ink[3] = { 0, 0, 0 };

		if (o->color)
			raster_ramp(k, count, ink);
		raster_disc_alpha(r, cx, cy, o->rad > 0.0 ? o->rad :
		    raster_spacing_radius(&sp, cx, cy), ink, o->alpha);
	}
	if (o->rad == 0.0)
		raster_spacing_free(&sp);
}

/* The image to the output opened before the work, as PNG or PNM. */
static void write_image(const struct render_opts *o, struct outfile *of,
    const struct frs_raster *r)
{
	int rc = format_of(o->format, cli.out) == FMT_PNM ?
	    raster_write_pnm(of->fp, of->name, r) :
	    raster_write_png(of->fp, of->name, r);

	cli_out_commit(of, rc);
}

int main(int argc, char **argv)
{
	struct render_opts o = { .in = "-", .w = 512, .h = 512, .alpha = 1.0,
	    .flags = FRS_MAP_ALLOW_ZERO, .axis = { 0, 1 }, .axes = "xy" };
	struct frs_points p;
	struct frs_raster r;
	struct outfile of;
	const char *name;

	cli_init("pts-render", usage);
	parse_opts(argc, argv, &o);
	check_opts(argc, argv, &o);
	/* The output first: a bad path fails before any work, and standard
	 * output is never a terminal. */
	cli_options_done();
	cli_out_open(&of, cli.out, 1);
	name = read_points(&o, &p);
	if (raster_alloc(&r, o.w, o.h, o.color ? 3 : 1) < 0)
		cli_die_lib();
	if (o.imp != NULL)
		draw_map(&o, &r);
	draw_points(&o, &p, name, &r);
	pts_free(&p);
	write_image(&o, &of, &r);
	raster_free(&r);
	return 0;
}
