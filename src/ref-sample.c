/*
 * ref-sample: uniform 2-D reference point sets (random, regular,
 * jittered, Halton, Hammersley, Owen-scrambled Sobol', dart throwing)
 * and adaptive relaxation dart throwing by an importance map.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "imap.h"
#include "outfile.h"
#include "ptsio.h"
#include "refsamp.h"

static const char usage[] =
    "usage: ref-sample -n COUNT [-k KIND] [-i IMPORTANCE] [-s WxH] [--strict]\n"
    "                  [--equirect] [--max-failures F] [-S SEED] [-T] [-q]\n"
    "                  [-o FILE]\n"
    "\n"
    "  -n, --count N        points to make (regular and jittered: the\n"
    "                       nearest square, round(sqrt N)^2)\n"
    "  -k, --kind K         random (default), regular, jittered, halton,\n"
    "                       hammersley, sobol, dart or relaxed-dart\n"
    "  -i, --importance M   relaxed-dart: map, PNG, OpenEXR or a spec such\n"
    "                       as blob (default const)\n"
    "  -s, --size WxH       size at which procedural maps are evaluated\n"
    "                       (default 128x128), or files resampled\n"
    "      --strict         negative importance is an error\n"
    "      --equirect       weight map rows by sin(theta)\n"
    "      --max-failures F dart: stop after F rejected candidates in a row\n"
    "                       (default 100000); relaxed-dart: shrink the\n"
    "                       radius after F in a row (default 1000)\n"
    "  -S, --seed N         seed (default 1); for halton and hammersley a\n"
    "                       random shift, for sobol an Owen scramble;\n"
    "                       -S 0 gives the classical unshifted sequences\n"
    "  -T, --text           text output\n"
    "  -o, --output FILE    output (default standard output)\n"
    "  -q, --quiet          no notes\n"
    "  -h, --help           this help;  --version  the version\n";

enum { OPT_MAX_FAILURES = OPT_FIRST_PRIVATE, OPT_STRICT, OPT_EQUIRECT };

static const struct option longopts[] = {
	{ "count", required_argument, NULL, 'n' },
	{ "kind", required_argument, NULL, 'k' },
	{ "max-failures", required_argument, NULL, OPT_MAX_FAILURES },
	{ "importance", required_argument, NULL, 'i' },
	{ "size", required_argument, NULL, 's' },
	{ "strict", no_argument, NULL, OPT_STRICT },
	{ "equirect", no_argument, NULL, OPT_EQUIRECT },
	CLI_COMMON_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

int main(int argc, char **argv)
{
	enum refsamp_kind kind = REFSAMP_RANDOM;
	uint64_t n = 0, maxf = 0, count, placed;
	int c, have_n = 0, flags = 0;
	const char *imp = NULL;
	uint32_t mw = 0, mh = 0;
	double *xy;
	struct outfile of;
	struct pts_writer w;

	cli_init("ref-sample", usage);
	while ((c = getopt_long(argc, argv, "n:k:i:s:" CLI_COMMON_SHORTOPTS,
	    longopts, NULL)) != -1) {
		switch (c) {
		case 'n':
			n = cli_u64("-n", optarg, 1, REFSAMP_MAX_N);
			have_n = 1;
			break;
		case 'k':
			if (refsamp_parse(optarg, &kind) < 0)
				cli_usage_error("-k: %s", frs_errmsg());
			break;
		case OPT_MAX_FAILURES:
			maxf = cli_u64("--max-failures", optarg, 1,
			    (uint64_t)1 << 40);
			break;
		case 'i': imp = optarg; break;
		case 's':
			cli_size("-s", optarg, IMAP_MAX_SIDE, &mw, &mh);
			break;
		case OPT_STRICT: flags |= IMAP_STRICT; break;
		case OPT_EQUIRECT: flags |= IMAP_EQUIRECT; break;
		default:
			if (!cli_common_opt(c, optarg))
				cli_usage(2);
		}
	}
	if (optind != argc)
		cli_usage_error("unexpected argument '%s'", argv[optind]);
	if (!have_n)
		cli_usage_error("-n COUNT is required");
	if (maxf == 0)
		maxf = kind == REFSAMP_RELAXED_DART ? REFSAMP_RELAXED_FAILURES :
		    REFSAMP_DART_FAILURES;
	count = refsamp_count(kind, n);
	if (count != n)
		cli_note("%s: %llu points, the nearest square grid (%llux%llu) "
		    "to %llu", refsamp_name(kind), (unsigned long long)count,
		    (unsigned long long)refsamp_grid_side(n),
		    (unsigned long long)refsamp_grid_side(n),
		    (unsigned long long)n);
	if ((xy = malloc(2 * count * sizeof *xy)) == NULL)
		cli_die("no memory for %llu points", (unsigned long long)count);
	if (kind == REFSAMP_RELAXED_DART) {
		struct frs_imap map;
		if (imap_load(imp ? imp : "const", mw, mh, flags, &map) < 0) {
			free(xy);
			cli_die_lib();
		}
		if (refsamp_relaxed_dart(n, cli.seed, maxf, &map, xy,
		    NULL) < 0) {
			imap_free(&map);
			free(xy);
			cli_die("%s", frs_errmsg());
		}
		imap_free(&map);
		placed = n;
	} else if (refsamp_gen(kind, n, cli.seed, maxf, xy, &placed) < 0)
		cli_die("%s", frs_errmsg());
	if (placed < count)
		cli_note("dart: placed %llu of %llu points (%llu candidates in a "
		    "row rejected)", (unsigned long long)placed,
		    (unsigned long long)count, (unsigned long long)maxf);
	if (outfile_open(&of, cli.out, !cli.text) < 0)
		cli_die_lib();
	if (pts_writer_begin(&w, of.fp, of.name, 2, 0, placed, cli.text) < 0)
		goto fail;
	for (uint64_t i = 0; i < placed; i++)
		if (pts_writer_put(&w, xy + 2 * i) < 0)
			goto fail;
	if (pts_writer_end(&w) < 0)
		goto fail;
	if (outfile_commit(&of) < 0)
		cli_die_lib();
	free(xy);
	return 0;
fail:
	outfile_abort(&of);
	cli_die_lib();
}
