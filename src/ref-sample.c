/*
 * ref-sample: uniform 2-D and 3-D reference point sets (random, regular,
 * jittered, Halton, Hammersley, Owen-scrambled Sobol', dart throwing)
 * and adaptive 2-D relaxation dart throwing by an importance map.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/output.h"
#include "cli/ptsopt.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "base/mem.h"
#include "base/outfile.h"
#include "base/progress.h"
#include "formats/ptsio.h"
#include "formats/setsout.h"
#include "sample/refsamp.h"

static const char usage[] =
    "usage: ref-sample -n COUNT [-d DIMS] [-k KIND] [-i IMPORTANCE] [-s WxH]\n"
    "                  [--strict] [--equirect] [--max-failures F] [-S SEED]\n"
    "                  [-T] [-q] [--sets M] [-o FILE]\n"
    "\n"
    "  -n, --count N        points to make (regular and jittered: the\n"
    "                       nearest square, round(sqrt N)^2, or in 3-D\n"
    "                       cube, round(cbrt N)^3)\n"
    "  -d, --dims K         2 (default): points in [0,1)^2; 3: in [0,1)^3\n"
    "                       (every kind but relaxed-dart, no -i)\n"
    "      --sets M         write M sets one after another, set i made\n"
    "                       with seed S+i (default 1); M > 1 adds a\n"
    "                       column, the set i\n"
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

/* One set with the given seed into xy; *placed gets its size. */
static int make_set(enum refsamp_kind kind, unsigned dims, uint64_t n,
    uint64_t seed, uint64_t maxf, const struct frs_imap *map, double *xy,
    uint64_t *placed)
{
	if (kind == REFSAMP_RELAXED_DART) {
		if (refsamp_relaxed_dart(n, seed, maxf, map, xy, NULL) < 0)
			return -1;
		*placed = n;
		return 0;
	}
	return refsamp_gen_dims(kind, dims, n, seed, maxf, xy, placed);
}

/*
 * Dart throwing's time a point, in microseconds, measured with the
 * optimised build (make) on the development machine, two cores shared
 * with other work: it grows with the count as the grid and the points
 * leave the caches.  Between the counts measured it is linear in log n,
 * beyond them that of the nearest.  Only for the note of a long run.
 */
struct cost {
	double n, us;
};

static const struct cost dart2[] = {
	{ 1e5, 2.0 }, { 1e6, 4.6 }, { 4e6, 7.0 }, { 1e7, 9.5 }, { 3e7, 12.1 }
};
static const struct cost dart3[] = {
	{ 1e5, 8.5 }, { 1e6, 19.8 }, { 4e6, 20.9 }
};
static const struct cost relaxed[] = {
	{ 1e4, 11.0 }, { 1e5, 10.3 }, { 3e5, 12.1 }
};

/* Seconds: a run expected to take this long gets a note first. */
#define LONG_RUN 30.0

static double cost_us(const struct cost *c, size_t k, double n)
{
	if (n <= c[0].n)
		return c[0].us;
	for (size_t i = 1; i < k; i++)
		if (n <= c[i].n) {
			double t = log(n / c[i - 1].n) / log(c[i].n / c[i - 1].n);
			return c[i - 1].us + t * (c[i].us - c[i - 1].us);
		}
	return c[k - 1].us;
}

/* "about 45 seconds", "about 12 minutes", "about 3 hours". */
static void say_duration(char *buf, size_t size, double s)
{
	if (s < 120.0)
		snprintf(buf, size, "%.0f seconds", s);
	else if (s < 7200.0)
		snprintf(buf, size, "%.0f minutes", s / 60.0);
	else
		snprintf(buf, size, "%.0f hours", s / 3600.0);
}

/* Dart throwing shows no progress while it runs: say first how long a
 * long run will take, also where standard error is no terminal. */
static void note_time(enum refsamp_kind kind, unsigned dims, uint64_t n,
    uint64_t sets)
{
	double us, s;
	char when[32], in[48] = "";

	if (kind == REFSAMP_DART)
		us = dims == 3 ? cost_us(dart3, sizeof dart3 / sizeof *dart3,
		    (double)n) : cost_us(dart2, sizeof dart2 / sizeof *dart2,
		    (double)n);
	else if (kind == REFSAMP_RELAXED_DART)
		us = cost_us(relaxed, sizeof relaxed / sizeof *relaxed,
		    (double)n);
	else
		return;
	s = us * 1e-6 * (double)n * (double)sets;
	if (s < LONG_RUN)
		return;
	say_duration(when, sizeof when, s);
	if (sets > 1)
		snprintf(in, sizeof in, " in %llu sets",
		    (unsigned long long)sets);
	cli_note("%s: %llu points%s take about %s (%.2g microseconds a "
	    "point at this count, measured)", refsamp_name(kind),
	    (unsigned long long)n, in, when, us);
}

/* -d: exactly "2" or "3". */
static unsigned parse_dims(const char *s)
{
	if (strcmp(s, "2") == 0 || strcmp(s, "3") == 0)
		return (unsigned)(s[0] - '0');
	cli_usage_error("-d: '%s' is not 2 or 3 (points in [0,1)^2 or "
	    "[0,1)^3)", s);
}

/* What 3-D cannot do, as usage errors: both need an importance map,
 * which is an image. */
static void check_dims(unsigned dims, enum refsamp_kind kind,
    const char *imp)
{
	if (dims != 3)
		return;
	if (kind == REFSAMP_RELAXED_DART)
		cli_usage_error("-d 3: relaxed-dart is two-dimensional only (it "
		    "follows an importance map); -k dart makes 3-D Poisson-disk "
		    "points");
	if (imp != NULL)
		cli_usage_error("-d 3: -i is two-dimensional only (importance "
		    "maps are images); the 3-D kinds are uniform");
}

/* The note on a grid count that differs from -n. */
static void note_grid(enum refsamp_kind kind, unsigned dims, uint64_t n,
    uint64_t count)
{
	unsigned long long s = dims == 3 ? refsamp_cube_side(n) :
	    refsamp_grid_side(n);

	if (dims == 3)
		cli_note("%s: %llu points, the nearest cubic grid "
		    "(%llux%llux%llu) to %llu", refsamp_name(kind),
		    (unsigned long long)count, s, s, s, (unsigned long long)n);
	else
		cli_note("%s: %llu points, the nearest square grid (%llux%llu) "
		    "to %llu", refsamp_name(kind), (unsigned long long)count,
		    s, s, (unsigned long long)n);
}

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "n=count d=dims k=kind max-failures i=importance s=size "
    "strict equirect sets";

int main(int argc, char **argv)
{
	enum refsamp_kind kind = REFSAMP_RANDOM;
	uint64_t n = 0, maxf = 0, count, placed, sets = 1;
	unsigned dims = 2;
	int c, have_n = 0, flags = 0;
	const char *imp = NULL;
	uint32_t mw = 0, mh = 0;
	double *xy;
	char what[48];
	struct frs_imap map;
	int have_map = 0;
	struct outfile of;
	struct sets_writer w;
	struct progress pr;

	cli_init("ref-sample", usage);
	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 'n':
			n = cli_u64("-n", optarg, 1, REFSAMP_MAX_N);
			have_n = 1;
			break;
		case 'd': dims = parse_dims(optarg); break;
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
		case OPT_SETS:
			sets = cli_sets_m(optarg);
			break;
		default:
			cli_common_only(c, optarg);
		}
	}
	cli_no_operands(argc, argv);
	if (!have_n)
		cli_usage_error("-n COUNT is required");
	check_dims(dims, kind, imp);
	if (maxf == 0)
		maxf = kind == REFSAMP_RELAXED_DART ? REFSAMP_RELAXED_FAILURES :
		    REFSAMP_DART_FAILURES;
	count = refsamp_count_dims(kind, n, dims);
	cli_sets_check(sets, count);
	if (count != n)
		note_grid(kind, dims, n, count);
	cli_options_done();
	note_time(kind, dims, n, sets);
	snprintf(what, sizeof what, "%llu points", (unsigned long long)count);
	if ((xy = mem_calloc(what, count, dims * sizeof *xy)) == NULL)
		cli_die_lib();
	if (kind == REFSAMP_RELAXED_DART) {
		if (imap_load(imp ? imp : "const", mw, mh, flags, &map) < 0) {
			free(xy);
			cli_die_lib();
		}
		have_map = 1;
	}
	/* Set 0 before the output opens: with one set its size goes into
	 * the header, as without --sets. */
	if (make_set(kind, dims, n, cli.seed, maxf, have_map ? &map : NULL,
	    xy, &placed) < 0) {
		if (have_map)
			imap_free(&map);
		free(xy);
		cli_die("%s", frs_errmsg());
	}
	if (placed < count) {
		if (sets > 1) {
			free(xy);
			if (have_map)
				imap_free(&map);
			cli_die("dart, seed %llu: placed only %llu of %llu points "
			    "(%llu candidates in a row rejected); with --sets "
			    "every set needs them all: raise --max-failures or "
			    "lower -n", (unsigned long long)cli.seed,
			    (unsigned long long)placed, (unsigned long long)count,
			    (unsigned long long)maxf);
		}
		cli_note("dart: placed %llu of %llu points (%llu candidates in a "
		    "row rejected)", (unsigned long long)placed,
		    (unsigned long long)count, (unsigned long long)maxf);
	}
	cli_out_open(&of, cli.out, !cli.text);
	if (sets_writer_begin(&w, of.fp, of.name, dims, 0, NULL, sets,
	    sets > 1 ? sets * count : placed, cli.text) < 0)
		goto fail;
	progress_begin(&pr, "sets", sets);
	for (uint64_t set = 0; set < sets; set++) {
		if (set > 0) {
			uint64_t seed = cli.seed + set;
			if (make_set(kind, dims, n, seed, maxf,
			    have_map ? &map : NULL, xy, &placed) < 0) {
				outfile_abort(&of);
				free(xy);
				cli_die("%s", frs_errmsg());
			}
			if (placed < count) {
				outfile_abort(&of);
				free(xy);
				cli_die("dart, seed %llu: placed only %llu of %llu "
				    "points (%llu candidates in a row rejected); "
				    "with --sets every set needs them all: raise "
				    "--max-failures or lower -n",
				    (unsigned long long)seed,
				    (unsigned long long)placed,
				    (unsigned long long)count,
				    (unsigned long long)maxf);
			}
		}
		w.set = set;
		if (sets_writer_put(&w, xy, (size_t)placed) < 0)
			goto fail;
		progress_update(&pr, set + 1);
	}
	progress_end(&pr);
	if (sets_writer_end(&w) < 0)
		goto fail;
	cli_out_commit(&of, 0);
	if (have_map)
		imap_free(&map);
	free(xy);
	return 0;
fail:
	outfile_abort(&of);
	if (have_map)
		imap_free(&map);
	free(xy);
	cli_die_lib();
}
