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

#include "frs.h"
#include "cli/cli.h"

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

/* Everything the command line asked for. */
struct ref_opts {
	enum refsamp_kind kind;
	unsigned dims;		/* -d */
	uint64_t n;		/* -n, 0 when not given */
	uint64_t maxf;		/* --max-failures, 0 for the kind's default */
	uint64_t sets;		/* --sets M */
	uint64_t count;		/* the points of a set: n, or its grid's */
	const char *imp;	/* -i */
	uint32_t mw, mh;	/* -s */
	int flags;		/* --strict, --equirect */
};

/* A run: the points of the set at hand, and the map of relaxed-dart. */
struct ref_run {
	double *xy;
	uint64_t placed;	/* the points of xy */
	struct frs_imap map;
	int have_map;
};

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

static void parse_opts(int argc, char **argv, struct ref_opts *o)
{
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 'n':
			o->n = cli_u64("-n", optarg, 1, REFSAMP_MAX_N);
			break;
		case 'd': o->dims = parse_dims(optarg); break;
		case 'k':
			if (refsamp_parse(optarg, &o->kind) < 0)
				cli_usage_error("-k: %s", cli_errmsg());
			break;
		case OPT_MAX_FAILURES:
			o->maxf = cli_u64("--max-failures", optarg, 1,
			    (uint64_t)1 << 40);
			break;
		case 'i': o->imp = optarg; break;
		case 's':
			cli_size("-s", optarg, FRS_MAP_MAX_SIDE, &o->mw, &o->mh);
			break;
		case OPT_STRICT: o->flags |= FRS_MAP_STRICT; break;
		case OPT_EQUIRECT: o->flags |= FRS_MAP_EQUIRECT; break;
		case OPT_SETS:
			o->sets = cli_sets_m(optarg);
			break;
		default:
			cli_common_only(c, optarg);
		}
	}
	cli_no_operands(argc, argv);
}

/* The checks between options, the defaults that depend on the kind and
 * the count of a set. */
static void check_opts(struct ref_opts *o)
{
	if (o->n == 0)
		cli_usage_error("-n COUNT is required");
	check_dims(o->dims, o->kind, o->imp);
	if (o->maxf == 0)
		o->maxf = o->kind == REFSAMP_RELAXED_DART ?
		    REFSAMP_RELAXED_FAILURES : REFSAMP_DART_FAILURES;
	o->count = refsamp_count_dims(o->kind, o->n, o->dims);
	cli_sets_check(o->sets, o->count);
	if (o->count != o->n)
		note_grid(o->kind, o->dims, o->n, o->count);
}

/* The room for a set's points and relaxed-dart's map. */
static void open_run(const struct ref_opts *o, struct ref_run *r)
{
	char what[48];

	snprintf(what, sizeof what, "%llu points",
	    (unsigned long long)o->count);
	r->xy = cli_calloc(what, o->count, o->dims * sizeof *r->xy);
	if (o->kind != REFSAMP_RELAXED_DART)
		return;
	if (frs_imap_load(&r->map, o->imp ? o->imp : "const", o->mw, o->mh,
	    o->flags, NULL) != FRS_OK) {
		free(r->xy);
		cli_die_lib();
	}
	r->have_map = 1;
}

static void close_run(struct ref_run *r)
{
	if (r->have_map)
		frs_imap_free(&r->map);
	free(r->xy);
}

/* Before dying: the output, if open, removed and the run freed. */
static void drop_run(struct ref_run *r, struct outfile *of)
{
	if (of != NULL)
		outfile_abort(of);
	close_run(r);
}

/* Set i, made with seed S+i, into r->xy.  Dart throwing may place fewer
 * points than asked: a note with one set, the end of the run with
 * several, whose sets must all have the same count.  of: the output,
 * once open. */
static void make_set(const struct ref_opts *o, struct ref_run *r,
    uint64_t set, struct outfile *of)
{
	uint64_t seed = cli.seed + set;
	int rc;

	if (o->kind == REFSAMP_RELAXED_DART) {
		rc = refsamp_relaxed_dart(o->n, seed, o->maxf, &r->map, r->xy,
		    NULL);
		r->placed = o->n;
	} else
		rc = refsamp_gen_dims(o->kind, o->dims, o->n, seed, o->maxf,
		    r->xy, &r->placed);
	if (rc < 0) {
		drop_run(r, of);
		cli_die("%s", cli_errmsg());
	}
	if (r->placed >= o->count)
		return;
	if (o->sets == 1) {
		cli_note("dart: placed %llu of %llu points (%llu candidates in a "
		    "row rejected)", (unsigned long long)r->placed,
		    (unsigned long long)o->count, (unsigned long long)o->maxf);
		return;
	}
	drop_run(r, of);
	cli_die("dart, seed %llu: placed only %llu of %llu points (%llu "
	    "candidates in a row rejected); with --sets every set needs them "
	    "all: raise --max-failures or lower -n", (unsigned long long)seed,
	    (unsigned long long)r->placed, (unsigned long long)o->count,
	    (unsigned long long)o->maxf);
}

/* A failed write: the output removed. */
static noreturn void write_failed(struct ref_run *r, struct outfile *of)
{
	drop_run(r, of);
	cli_die_lib();
}

/* The sets, set 0 already made; the others one after another. */
static void write_sets(const struct ref_opts *o, struct ref_run *r)
{
	struct outfile of;
	struct sets_writer w;
	struct cli_task *task;

	cli_out_open(&of, cli.out, !cli.text);
	if (sets_writer_begin(&w, of.fp, of.name, o->dims, 0, NULL, o->sets,
	    o->sets > 1 ? o->sets * o->count : r->placed, cli.text) < 0)
		write_failed(r, &of);
	task = cli_task_begin("sets", o->sets);
	for (uint64_t set = 0; set < o->sets; set++) {
		if (set > 0)
			make_set(o, r, set, &of);
		w.set = set;
		if (sets_writer_put(&w, r->xy, (size_t)r->placed) < 0)
			write_failed(r, &of);
		cli_task_update(task, set + 1);
	}
	cli_task_end(task);
	if (sets_writer_end(&w) < 0)
		write_failed(r, &of);
	cli_out_commit(&of, 0);
}

int main(int argc, char **argv)
{
	struct ref_opts o = { .kind = REFSAMP_RANDOM, .dims = 2, .sets = 1 };
	struct ref_run r = { 0 };

	cli_init("ref-sample", usage);
	parse_opts(argc, argv, &o);
	check_opts(&o);
	cli_options_done();
	note_time(o.kind, o.dims, o.n, o.sets);
	open_run(&o, &r);
	/* Set 0 before the output opens: with one set its size goes into
	 * the header, as without --sets. */
	make_set(&o, &r, 0, NULL);
	write_sets(&o, &r);
	close_run(&r);
	return 0;
}
