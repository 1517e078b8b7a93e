/*
 * imap: make, convert and describe importance maps.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "frs.h"
#include "cli/cli.h"

static const char usage[] =
    "usage: imap gen [-q] [-s SIZE] [--equirect] [--log]\n"
    "                [--format png|exr|frv] [-o FILE] SPEC\n"
    "       imap info [-s WxH] [--srgb] [--strict] [--equirect] FILE|SPEC\n"
    "       imap convert [-s WxH] [--srgb] [--strict] [--equirect] [--log]\n"
    "                    [--format png|exr] IN OUT\n"
    "\n"
    "  -s, --size WxH     size (N for NxN); specs default to 128x128,\n"
    "                     files keep their size unless -s resamples them;\n"
    "                     volumes: N (NxNxN) or WxHxD, default 32^3\n"
    "      --equirect     weight rows by sin(theta): an equirectangular\n"
    "                     environment map becomes an importance over the\n"
    "                     unit square proportional to solid angle\n"
    "      --format FMT   png (16-bit grey, scaled to its maximum), exr\n"
    "                     (float Y) or frv (a float volume, frv(5));\n"
    "                     default from the output's extension\n"
    "      --srgb         decode PNG values from sRGB to linear\n"
    "      --strict       negative values are an error, not clamped\n"
    "      --log          write log10 of the values over their positive\n"
    "                     range, zero as black: a picture of an HDR map\n"
    "                     for looking at, not an importance\n"
    "  -o, --output FILE  output file (default: standard output)\n"
    "  -q, --quiet        no warnings\n"
    "  -h, --help         this help;  --version  the version\n"
    "\n"
    "Procedural specs, NAME[:PARAM=VALUE,...] (the first parameter may\n"
    "omit its name, e.g. const:0.5); maps:\n";

enum fmt { FMT_NONE, FMT_PNG, FMT_EXR, FMT_FRV };

static uint32_t opt_w, opt_h, opt_d;
static int opt_nsz;	/* sizes -s gave, 0 if none */
static int opt_flags;
static enum fmt opt_format;
static int opt_log;

/* The source of a command, opened once (open_source): NULL for standard
 * input, which is opened when it is read (a map here, whatever it
 * holds), and for a file that did not open (src_failed: its message kept
 * for load_source, after the checks of the options). */
static frs_source *src;
static int src_failed;

/* log10 over the positive range mapped to (0, 1], zero stays zero. */
static void to_log(struct frs_imap *m)
{
	struct frs_imap_stats s;
	double lo, span;

	frs_imap_stats(m, &s);
	if (s.min_positive <= 0.0)
		return;
	lo = log10(s.min_positive);
	span = log10(s.max) - lo;
	for (size_t i = 0; i < (size_t)m->w * m->h; i++)
		if (m->v[i] > 0.0)
			m->v[i] = span > 0.0 ? (1.0 + 255.0 *
			    (log10(m->v[i]) - lo) / span) / 256.0 : 1.0;
}

static enum fmt format_of(const char *path)
{
	const char *dot = path ? strrchr(path, '.') : NULL;

	if (opt_format != FMT_NONE)
		return opt_format;
	if (dot && strcasecmp(dot, ".png") == 0)
		return FMT_PNG;
	if (dot && strcasecmp(dot, ".exr") == 0)
		return FMT_EXR;
	if (dot && strcasecmp(dot, ".frv") == 0)
		return FMT_FRV;
	if (path == NULL || strcmp(path, "-") == 0)
		cli_usage_error("cannot tell the format of standard output; "
		    "give --format png, exr or frv");
	cli_usage_error("%s: unknown extension (use .png, .exr or .frv, or "
	    "--format)", path);
}

static void write_map(const char *path, struct frs_imap *m)
{
	struct outfile o;
	enum fmt f = format_of(path);

	if (f == FMT_FRV)
		cli_usage_error("%s: a 2-D map cannot be written as a volume "
		    "(.frv)", path ? path : "<stdout>");
	if (opt_log)
		to_log(m);
	cli_out_open(&o, path, 1);
	cli_out_commit(&o, frs_imap_write(m, f == FMT_PNG ? FRS_FORMAT_PNG :
	    FRS_FORMAT_EXR, o.fp, o.name, NULL) == FRS_OK ? 0 : -1);
}

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "s=size equirect format srgb strict log";

static int parse_opts(int argc, char **argv)
{
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 's': {
			uint32_t sz[3];
			opt_nsz = cli_size3("-s", optarg, FRS_MAP_MAX_SIDE, sz);
			opt_w = sz[0];
			opt_h = sz[1];
			opt_d = sz[2];
			break;
		}
		case OPT_EQUIRECT:
			opt_flags |= FRS_MAP_EQUIRECT;
			break;
		case OPT_SRGB:
			opt_flags |= FRS_MAP_SRGB;
			break;
		case OPT_STRICT:
			opt_flags |= FRS_MAP_STRICT;
			break;
		case OPT_LOG:
			opt_log = 1;
			break;
		case OPT_FORMAT:
			opt_format = (enum fmt)(FMT_PNG + cli_choice("--format",
			    optarg, (const char *const[]){ "png", "exr", "frv",
			    NULL }));
			break;
		default:
			cli_common_only(c, optarg);
		}
	}
	return optind;
}

/* What src may be (FRS_SOURCE_ bits), from its name or a file's first
 * bytes: the one open of the file. */
static int open_source(const char *name)
{
	src = NULL;
	src_failed = 0;
	if (strcmp(name, "-") == 0)
		return FRS_SOURCE_MAP;
	if (frs_source_open(&src, name, NULL) != FRS_OK) {
		src_failed = 1;
		return FRS_SOURCE_MAP;
	}
	return frs_source_kinds(src);
}

/* The source opened, loaded as want asks (2 or 3) and closed; a failure
 * ends the program. */
static void load_source(const char *arg, unsigned want,
    const uint32_t size[3], int flags, struct frs_imap *m,
    struct frs_imap_stats *st, struct frs_vol *v)
{
	unsigned dims;
	int rc;

	if (src_failed || (src == NULL && frs_source_open(&src, arg,
	    NULL) != FRS_OK))
		cli_die_lib();
	rc = frs_source_load(src, want, size, flags, &dims, m, st, v, NULL);
	frs_source_close(src);
	src = NULL;
	if (rc != FRS_OK)
		cli_die_lib();
}

/* A volume source: a .frv file, or a spec only volumes have (and const
 * when a volume is written). */
static int is_volume(int kinds, enum fmt out)
{
	return kinds == FRS_SOURCE_VOLUME || (out == FMT_FRV &&
	    (kinds & FRS_SOURCE_VOLUME));
}

/* The -s size of a volume: N, WxHxD or none. */
static void vol_size(uint32_t sz[3])
{
	if (opt_nsz == 2)
		cli_usage_error("-s %ux%u: give N or WxHxD for a volume", opt_w,
		    opt_h);
	sz[0] = opt_nsz ? opt_w : 0;
	sz[1] = opt_h;
	sz[2] = opt_d;
}

/* -s for a 2-D map: not WxHxD. */
static void map_size(void)
{
	if (opt_nsz == 3)
		cli_usage_error("-s %ux%ux%u: a volume size for a 2-D map",
		    opt_w, opt_h, opt_d);
}

static int gen_volume(const char *spec)
{
	struct frs_vol v;
	struct outfile o;
	uint32_t sz[3];

	if (format_of(cli.out) != FMT_FRV)
		cli_usage_error("%s is a volume: write it as .frv (--format frv)",
		    spec);
	if (opt_log || (opt_flags & FRS_MAP_EQUIRECT))
		cli_usage_error("--log and --equirect are for 2-D maps");
	vol_size(sz);
	cli_options_done();
	/* A spec, even where a file of that name exists. */
	if (frs_spec_load(spec, 3, sz, opt_flags | FRS_MAP_ALLOW_ZERO, NULL,
	    NULL, &v, NULL) != FRS_OK)
		cli_die_lib();
	cli_out_open(&o, cli.out, 1);
	cli_out_commit(&o, frs_vol_write(&v, o.fp, o.name, NULL) == FRS_OK ?
	    0 : -1);
	frs_vol_free(&v);
	return 0;
}

static int cmd_gen(int argc, char **argv)
{
	struct frs_imap m;

	if (argc != 1)
		cli_usage_error("gen takes one SPEC");
	if (is_volume(open_source(argv[0]), cli.out != NULL ?
	    format_of(cli.out) : opt_format))
		return gen_volume(argv[0]);
	map_size();
	if (!(frs_spec_kinds(argv[0]) & FRS_SOURCE_MAP))
		cli_usage_error("'%s' is not a procedural map (const, blob, "
		    "ramp, aniso, sky)", argv[0]);
	format_of(cli.out);	/* fail on a bad name before any work */
	cli_options_done();
	load_source(argv[0], 2, (const uint32_t[3]){ opt_w, opt_h, 0 },
	    opt_flags | FRS_MAP_ALLOW_ZERO, &m, NULL, NULL);
	write_map(cli.out, &m);
	frs_imap_free(&m);
	return 0;
}

static int cmd_convert(int argc, char **argv)
{
	struct frs_imap m;
	const char *out = cli.out;

	if (argc == 2 && out == NULL)
		out = argv[1];
	else if (argc != 1 || out == NULL)
		cli_usage_error("convert takes IN and OUT");
	if (is_volume(open_source(argv[0]), FMT_NONE))
		cli_usage_error("%s: volumes are not converted", argv[0]);
	map_size();
	format_of(out);
	cli_options_done();
	load_source(argv[0], 2, (const uint32_t[3]){ opt_w, opt_h, 0 },
	    opt_flags | FRS_MAP_ALLOW_ZERO, &m, NULL, NULL);
	write_map(out, &m);
	frs_imap_free(&m);
	return 0;
}

static void print_stats(const struct frs_imap_stats *s)
{
	printf("min %.9g\nmax %.9g\nmean %.9g\nsum %.9g\n", s->min, s->max,
	    s->mean, s->sum);
	printf("zeros %llu\nnegatives %llu\n", (unsigned long long)s->zeros,
	    (unsigned long long)s->negatives);
	if (s->negatives)
		printf("min_negative %.9g\n", s->min_negative);
	printf("nonfinite %llu\n", (unsigned long long)s->nonfinite);
	printf("min_positive %.9g\n", s->min_positive);
	printf("dynamic_range %.9g\n", s->min_positive > 0.0 ? s->max /
	    s->min_positive : 0.0);
	if (fflush(stdout) != 0 || ferror(stdout))
		cli_die("<stdout>: write error: %s", strerror(errno));
}

/* Statistics of a volume as it is: non-finite and negative voxels are
 * counted, not refused. */
static int info_volume(const char *arg, const char *name)
{
	struct frs_vol v;
	struct frs_imap none, view;
	struct frs_imap_stats s;
	uint32_t sz[3];

	vol_size(sz);
	cli_options_done();
	load_source(arg, 3, sz, FRS_MAP_RAW, &none, NULL, &v);
	/* A volume is a W x (H D) map, slices stacked downwards. */
	view = (struct frs_imap){ v.w, v.h * v.d, v.v };
	frs_imap_stats(&view, &s);
	printf("source %s\nwidth %u\nheight %u\ndepth %u\nvoxels %llu\n",
	    name, v.w, v.h, v.d, (unsigned long long)s.count);
	print_stats(&s);
	frs_vol_free(&v);
	return 0;
}

static int cmd_info(int argc, char **argv)
{
	struct frs_imap m;
	struct frs_imap_stats src_st, s;
	const char *name;

	if (argc != 1)
		cli_usage_error("info takes one FILE or SPEC");
	name = strcmp(argv[0], "-") == 0 ? "<stdin>" : argv[0];
	if (is_volume(open_source(argv[0]), opt_nsz == 3 ? FMT_FRV :
	    FMT_NONE))
		return info_volume(argv[0], name);
	map_size();
	cli_options_done();
	/* The statistics of the map as the programs use it: checked and
	 * clamped as the warning says, then weighted (as convert does);
	 * negatives and min_negative are those the clamping took away. */
	load_source(argv[0], 2, (const uint32_t[3]){ opt_w, opt_h, 0 },
	    opt_flags | FRS_MAP_RAW, &m, &src_st, NULL);
	if (frs_imap_check(&m, name, opt_flags | FRS_MAP_ALLOW_ZERO, &s,
	    NULL) != FRS_OK)
		cli_die_lib();
	if (opt_flags & FRS_MAP_EQUIRECT) {
		frs_map_equirect_f64(m.v, m.w, m.h, 0);
		frs_imap_stats(&m, &s);
	}
	s.negatives = src_st.negatives;
	s.min_negative = src_st.min_negative;
	printf("source %s\nwidth %u\nheight %u\npixels %llu\n", name, m.w, m.h,
	    (unsigned long long)s.count);
	print_stats(&s);
	frs_imap_free(&m);
	return 0;
}

int main(int argc, char **argv)
{
	static char help[12288];
	const char *cmd;
	int first;

	snprintf(help, sizeof help, "%s%svolumes:\n%s", usage, frs_spec_help(2),
	    frs_spec_help(3));
	cli_init("imap", help);
	/* Defaults set here, not only by static zeroing, so that main can
	 * run again in one process (test/fuzz/fuzz_opts.c). */
	opt_w = opt_h = opt_d = 0;
	opt_nsz = 0;
	opt_flags = 0;
	opt_format = FMT_NONE;
	opt_log = 0;
	/* A source the last run left open when an exit was trapped. */
	frs_source_close(src);
	src = NULL;
	src_failed = 0;
	if (argc < 2)
		cli_usage_error("no command (gen, info or convert)");
	cmd = argv[1];
	if (strcmp(cmd, "-h") == 0 || strcmp(cmd, "--help") == 0)
		cli_usage(0);
	if (strcmp(cmd, "--version") == 0)
		cli_common_opt(OPT_VERSION, NULL);
	first = parse_opts(argc - 1, argv + 1) + 1;
	argc -= first;
	argv += first;
	if (strcmp(cmd, "gen") == 0)
		return cmd_gen(argc, argv);
	if (strcmp(cmd, "info") == 0)
		return cmd_info(argc, argv);
	if (strcmp(cmd, "convert") == 0)
		return cmd_convert(argc, argv);
	cli_usage_error("unknown command '%s' (gen, info or convert)", cmd);
}
