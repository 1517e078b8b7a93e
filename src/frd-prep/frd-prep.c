/*
 * frd-prep: validate, import and prepare threshold matrices.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdnoreturn.h>
#include <stdlib.h>
#include <string.h>

#include "frs.h"
#include "cli/cli.h"
#include "frd-prep/frdimport.h"

static const char usage[] =
    "usage: frd-prep [-a none|stack|level1|level2|sorted|all] [--check]\n"
    "                [--import frd|raw32|png16|text] [--rank] [-s WxH]\n"
    "                [--blocks LIST] [--for LIST [-i MAP] [--size-map WxH]\n"
    "                [--equirect] [--strict] [--sigma S]\n"
    "                [--tiles levels|plain|shuffled]]\n"
    "                [-o FILE] [IN]\n"
    "\n"
    "  -a, --algo A       prepare for A: the minmap (stack, level1, level2),\n"
    "                     block-sorted lists (sorted) or both (all), and\n"
    "                     write a .frp; none (default) writes a .frd\n"
    "      --import F     the input's format: frd (default), raw32\n"
    "                     (little-endian 32-bit values), png16 (a dither\n"
    "                     mask's grey levels, as ranks) or text (rows of\n"
    "                     integers)\n"
    "      --rank         turn any raw32 or text values into ranks\n"
    "  -s, --size WxH     size of a raw32 matrix (default: square)\n"
    "      --blocks LIST  block sizes of the sorted lists (default\n"
    "                     1,2,4,...,256 up to the matrix size)\n"
    "      --for LIST     the counts to prepare for: with -a sorted or\n"
    "                     all, the block sizes Sorted needs for them,\n"
    "                     level by level (a table of them under -v);\n"
    "                     without -a, only the table, on standard output\n"
    "  -i, --importance MAP  the map of --for (default const, 128x128)\n"
    "      --size-map WxH the size at which --for's map is evaluated or\n"
    "                     resampled, as frs-sample -s\n"
    "      --equirect     weight --for's map rows by sin(theta)\n"
    "      --strict       negative importance in --for's map is an error\n"
    "      --sigma S      the sigma of --for (default 8)\n"
    "      --tiles T      the window of --for, as frs-sample's (default\n"
    "                     levels)\n"
    "      --check        check that the values are a permutation\n"
    "  -v, --verbose      print the matrix size and checksum\n"
    "  -o, --output FILE  output (default standard output)\n"
    "  -q, --quiet        no warnings\n"
    "  -h, --help         this help;  --version  the version\n";

/* A comma-separated list of up to 32 integers in [min, max] for opt. */
static unsigned parse_list(const char *opt, const char *s, uint64_t *out,
    long long min, long long max)
{
	char buf[1024], *tok, *save = NULL;
	unsigned n = 0;

	if (strlen(s) >= sizeof buf)
		cli_usage_error("%s: list too long", opt);
	strcpy(buf, s);
	for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",",
	    &save)) {
		if (n == 32)
			cli_usage_error("%s: at most 32 values", opt);
		out[n++] = (uint64_t)cli_ll(opt, tok, min, max);
	}
	if (n == 0)
		cli_usage_error("%s: an empty list", opt);
	return n;
}

static unsigned parse_blocks(const char *s, uint32_t *out)
{
	uint64_t v[32];
	unsigned n = parse_list("--blocks", s, v, 1, 1 << 16);

	for (unsigned i = 0; i < n; i++) {
		if (v[i] & (v[i] - 1))
			cli_usage_error("--blocks: %llu is not a power of two",
			    (unsigned long long)v[i]);
		out[i] = (uint32_t)v[i];
	}
	return n;
}

/* --for's map, loaded as frs-sample loads it: its size (0: its own),
 * --equirect and --strict. */
struct mapopt {
	const char *imp;
	uint32_t w, h;
	int flags;
};

/*
 * The levels of the counts on the map, as frs-sample makes them with the
 * options o (sigma, tiles; frs_prepared_plan): the block size of Sorted's
 * lists for each that has them, into blocks (each size once); a table of
 * them on fp when fp is not NULL (block 0: the level scans or walks its
 * pixels, with the minmap); *minmap set when a level reads the minmap.
 */
static unsigned blocks_for(const struct frs_matrix *m, const struct mapopt *mo,
    const struct frs_options *o, const uint64_t *n, unsigned nn,
    uint32_t *blocks, int *minmap, FILE *fp)
{
	struct frs_imap map;
	unsigned nb = 0;

	if (frs_imap_load(&map, mo->imp, mo->w, mo->h, mo->flags,
	    NULL) != FRS_OK)
		cli_die_lib();
	if (fp != NULL)
		fprintf(fp, "n\tlevel\tn_s\twindow\tblock\tminmap\tvalues\t"
		    "from_frp\n");
	for (unsigned k = 0; k < nn; k++) {
		struct frs_prepared_level lv[32];
		unsigned nl;
		if (frs_prepared_plan(m, &map, n[k], o, lv, 32, &nl,
		    NULL) != FRS_OK)
			cli_die_lib();
		for (unsigned l = 0; l < nl && l < 32; l++) {
			const struct frs_prepared_level *t = &lv[l];
			uint32_t b = t->block;
			unsigned i;
			*minmap |= t->minmap;
			if (fp != NULL)
				fprintf(fp, "%llu\t%u\t%u\t%llux%llu\t%u\t%s\t%llu\t"
				    "%s\n", (unsigned long long)n[k], t->level, t->ns,
				    (unsigned long long)t->window_w,
				    (unsigned long long)t->window_h, b,
				    t->minmap ? "yes" : "no",
				    (unsigned long long)t->values,
				    t->from_frp ? "yes" : "no");
			for (i = 0; i < nb && blocks[i] != b; i++)
				;
			if (b != 0 && i == nb)
				blocks[nb++] = b;
		}
	}
	frs_imap_free(&map);
	return nb;
}

/*
 * A .frp (name, what frs_matrix_read_file found in it, s): under --check
 * read whole and checked, and one line saying what it holds written to
 * the output.  Anything else asked of a .frp needs its .frd, which is
 * said before the rest is read (read_frd asks the check only then).
 */
static noreturn void check_frp(const char *name,
    const struct frs_file_info *s, int check, int prep, int verbose)
{
	struct outfile o;

	if (prep)
		cli_die("%s: a prepared matrix (.frp): -a, --blocks and --for "
		    "need the .frd it was made from", name);
	if (!check)
		cli_die("%s: a prepared matrix (.frp): frd-prep --check checks "
		    "it; frd-prep reads a .frd otherwise", name);
	cli_out_open(&o, cli.out, 0);
	fprintf(o.fp, "%s: a valid prepared matrix: %ux%u, checksum %016llx, "
	    "%s, ", name, s->w, s->h, (unsigned long long)s->checksum,
	    s->minmap ? "a minmap" : "no minmap");
	if (s->nblocks == 0)
		fprintf(o.fp, "no sorted lists\n");
	for (unsigned i = 0; i < s->nblocks; i++)
		fprintf(o.fp, "%s%u%s", i ? "," : "sorted lists of blocks ",
		    s->blocks[i], i + 1 == s->nblocks ? "\n" : "");
	cli_out_commit(&o, 0);
	if (verbose)
		fprintf(stderr, "frd-prep: %ux%u matrix, checksum %016llx\n", s->w,
		    s->h, (unsigned long long)s->checksum);
	exit(0);
}

/* A .frd from path (name in messages), its values only checked to lie
 * below their count (--check checks the rest), or for a .frp
 * check_frp. */
static int read_frd(const char *path, const char *name, struct frs_matrix *m,
    int check, int prep, int verbose)
{
	struct frs_file_info s;
	int flags = FRS_READ_ANY_VALUES | (check && !prep ?
	    FRS_READ_CHECK_FRP : 0);

	if (frs_matrix_read_file(m, path, flags, &s, NULL) != FRS_OK)
		return -1;
	if (s.frp)
		check_frp(name, &s, check, prep, verbose);
	return 0;
}

/* The option that mends an import the program refused (rc: what the
 * import returned; its messages name none). */
static const char *import_fix(int rc)
{
	if (rc == IMPORT_SIZE)
		return "; give the size with -s WxH";
	if (rc == IMPORT_RANKS)
		return " (--rank turns any values into ranks)";
	return "";
}

/* Everything the command line asked for. */
struct prep_opts {
	const char *fmt;	/* --import */
	const char *algo;	/* -a */
	const char *in;		/* IN, "-" for standard input */
	const char *src;	/* its name in messages and the .frp */
	uint32_t w, h;		/* -s */
	uint32_t blocks[32];	/* --blocks, or those --for needs */
	unsigned nblocks;
	uint64_t counts[32];	/* --for */
	unsigned ncounts;
	struct mapopt mo;	/* --for's map */
	struct frs_options opt;	/* --sigma, --tiles */
	int rank, check, verbose;
	int minmap, sorted;	/* what -a prepares */
};

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "a=algo import rank s=size blocks check for i=importance size-map "
    "equirect strict sigma tiles v=verbose";

static void parse_opts(int argc, char **argv, struct prep_opts *o)
{
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 'a': o->algo = optarg; break;
		case 's': cli_size("-s", optarg, 1u << 16, &o->w, &o->h); break;
		case OPT_IMPORT: o->fmt = optarg; break;
		case OPT_RANK: o->rank = 1; break;
		case OPT_BLOCKS:
			o->nblocks = parse_blocks(optarg, o->blocks);
			break;
		case OPT_CHECK: o->check = 1; break;
		case OPT_FOR:
			o->ncounts = parse_list("--for", optarg, o->counts, 1,
			    1LL << 40);
			break;
		case 'i': o->mo.imp = optarg; break;
		case OPT_SIZE_MAP:
			cli_size("--size-map", optarg, FRS_MAP_MAX_SIDE, &o->mo.w,
			    &o->mo.h);
			break;
		case OPT_EQUIRECT: o->mo.flags |= FRS_MAP_EQUIRECT; break;
		case OPT_STRICT: o->mo.flags |= FRS_MAP_STRICT; break;
		case OPT_SIGMA:
			o->opt.sigma = cli_double("--sigma", optarg, 1.0,
			    FRS_SIGMA_MAX);
			break;
		case OPT_TILES:
			o->opt.tiling = (enum frs_tiling_mode)cli_choice(
			    "--tiles", optarg, frs_names(FRS_NAMES_TILING));
			break;
		case 'v': o->verbose = 1; break;
		default:
			cli_common_only(c, optarg);
		}
	}
	if (argc - optind > 1)
		cli_usage_error("one input at most");
	if ((o->mo.w || o->mo.flags) && o->ncounts == 0)
		cli_usage_error("--size-map, --equirect and --strict are of "
		    "--for's map: give --for LIST");
	o->in = optind < argc ? argv[optind] : "-";
	o->src = strcmp(o->in, "-") ? o->in : "<stdin>";
}

/* -a: a minmap (stack, level1, level2), sorted lists, both or none. */
static void parse_algo(struct prep_opts *o)
{
	const char *a = o->algo;

	o->minmap = strcmp(a, "all") == 0 || strcmp(a, "stack") == 0 ||
	    strcmp(a, "level1") == 0 || strcmp(a, "level2") == 0;
	o->sorted = strcmp(a, "all") == 0 || strcmp(a, "sorted") == 0;
	if (!o->minmap && !o->sorted && strcmp(a, "none") != 0)
		cli_usage_error("-a: '%s' is not none, stack, level1, level2, "
		    "sorted or all", a);
}

/* The matrix in the format of --import; its values a permutation when
 * --check asks, or when they were imported. */
static void read_matrix(const struct prep_opts *o, struct frs_matrix *m)
{
	const char *fmt = o->fmt;
	int rc;

	if (strcmp(fmt, "frd") == 0)
		rc = read_frd(o->in, o->src, m, o->check, o->minmap || o->sorted ||
		    o->nblocks > 0 || o->ncounts > 0, o->verbose);
	else if (strcmp(fmt, "raw32") == 0)
		rc = frd_import_raw32(o->in, o->w, o->h, o->rank, m);
	else if (strcmp(fmt, "text") == 0)
		rc = frd_import_text(o->in, o->rank, m);
	else if (strcmp(fmt, "png16") == 0 || strcmp(fmt, "png") == 0)
		rc = frs_matrix_read_png(m, o->in, NULL) == FRS_OK ? 0 : -1;
	else
		cli_usage_error("--import: '%s' is not frd, raw32, png16 or text",
		    fmt);
	if (rc < 0)
		cli_die("%s%s", cli_errmsg(), import_fix(rc));
	if ((o->check || strcmp(fmt, "frd") != 0) &&
	    frs_matrix_check(m, o->src, NULL) != FRS_OK)
		cli_die_lib();
}

/* --blocks and --for: which -a each needs. */
static void check_lists(const struct prep_opts *o)
{
	if (o->nblocks > 0 && !o->sorted)
		cli_usage_error("--blocks needs -a sorted or -a all");
	if (o->nblocks > 0 && o->ncounts > 0)
		cli_usage_error("--blocks and --for: one or the other");
	if (o->ncounts > 0 && !o->sorted && o->minmap)
		cli_usage_error("--for needs -a sorted or -a all, or no -a");
}

/* --for without -a: the table of the levels' setups alone. */
static int print_table(struct prep_opts *o, struct frs_matrix *m)
{
	blocks_for(m, &o->mo, &o->opt, o->counts, o->ncounts, o->blocks,
	    &o->minmap, stdout);
	frs_matrix_free(m);
	if (fflush(stdout) != 0 || ferror(stdout))
		cli_die("<stdout>: write error");
	return 0;
}

/* The block sizes of the sorted lists: those --for needs, those of
 * --blocks, or by default 1, 2, 4 ... 256 up to the matrix size. */
static void choose_blocks(struct prep_opts *o, const struct frs_matrix *m)
{
	if (o->ncounts > 0)
		o->nblocks = blocks_for(m, &o->mo, &o->opt, o->counts,
		    o->ncounts, o->blocks, &o->minmap,
		    o->verbose ? stderr : NULL);
	if (o->sorted && o->nblocks == 0 && o->ncounts == 0)
		for (uint32_t b = 1; b <= 256 && b <= m->w && b <= m->h; b *= 2)
			o->blocks[o->nblocks++] = b;
	for (unsigned i = 0; i < o->nblocks; i++)
		if (o->blocks[i] > m->w || o->blocks[i] > m->h)
			cli_die("--blocks: %u exceeds the %ux%u matrix",
			    o->blocks[i], m->w, m->h);
}

/* The .frp of what -a asked for, or with -a none the .frd. */
static void write_matrix(const struct prep_opts *o,
    const struct frs_matrix *m)
{
	struct outfile of;
	int rc;

	cli_out_open(&of, cli.out, 1);
	rc = o->minmap || o->sorted ? frs_prepared_write(m, of.fp, of.name,
	    o->src, o->minmap, o->sorted && o->nblocks ? o->blocks : NULL,
	    o->sorted ? o->nblocks : 0, NULL) : frs_matrix_write(m, of.fp,
	    of.name, NULL);
	cli_out_commit(&of, rc == FRS_OK ? 0 : -1);
	if (o->verbose)
		fprintf(stderr, "frd-prep: %ux%u matrix, checksum %016llx\n",
		    m->w, m->h, (unsigned long long)frs_matrix_checksum(m));
}

int main(int argc, char **argv)
{
	struct prep_opts o = { .fmt = "frd", .algo = "none",
	    .mo = { "const", 0, 0, 0 } };
	struct frs_matrix m;

	cli_init("frd-prep", usage);
	frs_options_init(&o.opt);
	parse_opts(argc, argv, &o);
	cli_options_done();
	parse_algo(&o);
	read_matrix(&o, &m);
	check_lists(&o);
	if (o.ncounts > 0 && !o.sorted)
		return print_table(&o, &m);
	choose_blocks(&o, &m);
	write_matrix(&o, &m);
	frs_matrix_free(&m);
	return 0;
}
