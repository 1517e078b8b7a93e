/*
 * frs-sample: Forced Random Sampling of an importance map.  Read top to
 * bottom: the options; the inputs (the matrix and the map or volume,
 * each file opened once); set 0's run (the sampler, the setup, the
 * warnings of repeated patterns); main.  The sets are drawn and written
 * by sets.c, and -v's report is setsreport.c.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frs.h"
#include "cli/cli.h"
#include "frs-sample/sets.h"

static const char usage[] =
    "usage: frs-sample -n COUNT [-i IMPORTANCE] [-m MATRIX] [-a ALGO]\n"
    "                  [--sigma S] [--jitter none|halton|random] [--pdf]\n"
    "                  [--progressive N1,N2,...] [--threshold unbiased|thesis]\n"
    "                  [--tiles levels|plain|shuffled] [--level-blur R]\n"
    "                  [--level-column] [--count-only]\n"
    "                  [--exact-count] [--sets M]\n"
    "                  [-s SIZE] [-S SEED] [-j N]\n"
    "                  [--device cpu|cl|cl:N] [-T] [-v] [-o FILE]\n"
    "       frs-sample --list-devices | --data-dir\n"
    "\n"
    "  -n, --count N        samples to make (about; see frs-sample(1);\n"
    "                       exactly with --exact-count)\n"
    "  -i, --importance M   map: PNG, OpenEXR or a spec such as blob\n"
    "                       (default const: uniform sampling); with a\n"
    "                       3-D matrix a volume: .frv or blob3, ramp3...\n"
    "  -m, --matrix FILE    threshold matrix .frd (default: the shipped\n"
    "                       2048x2048 default.frd; for a volume the\n"
    "                       64x64x64 default3.frd; see --data-dir)\n"
    "  -a, --algo A         naive, stack, level1, level2, sorted (default)\n"
    "                       or flat1 (OpenCL only)\n"
    "      --sigma S        sparsity: one of S^2 window elements passes at\n"
    "                       the maximum importance (default 8)\n"
    "      --jitter J       none (element centres), halton or random offsets\n"
    "      --pdf            add a column: the density of each sample over\n"
    "                       the unit square, I / mean I\n"
    "      --progressive L  counts N1 < N2 < ...: write the samples of each\n"
    "                       step in turn, with a column giving the step\n"
    "      --threshold R    unbiased (default) or thesis (Eq. 4.14)\n"
    "      --tiles T        the window: levels (default: elements whose\n"
    "                       size follows the map, the multi-level\n"
    "                       window), plain (one level, the matrix\n"
    "                       repeated as it is, thesis Sec. 4.5) or\n"
    "                       shuffled (one level, each tile turned,\n"
    "                       flipped and shifted by the seed)\n"
    "      --level-blur R   smooth the levels over R map pixels (volume\n"
    "                       voxels; default 2 sigma; 0: each on its own)\n"
    "      --level-column   add a column: each sample's level\n"
    "      --count-only     print the count, make no points\n"
    "      --exact-count    exactly N samples (each step of --progressive):\n"
    "                       the N of smallest (M + u) / I, a subset or\n"
    "                       superset of the default set (unbiased rule)\n"
    "      --sets M         write M sets one after another, set i made\n"
    "                       with seed S+i (default 1); M > 1 adds a\n"
    "                       column, the set i\n"
    "  -s, --size WxH       size at which procedural maps are evaluated\n"
    "                       (default 128x128), or files resampled;\n"
    "                       N or WxHxD for volumes (default 32^3)\n"
    "      --equirect       weight map rows by sin(theta)\n"
    "      --strict         negative importance is an error\n"
    "      --device D       cpu (default), cl (the first OpenCL device) or\n"
    "                       cl:N; the output is the same bytes on all\n"
    "      --list-devices   list the OpenCL devices as cl:N and exit\n"
    "      --data-dir       print the directory of the shipped data (the\n"
    "                       default matrices, sunset.exr) and exit\n"
    "  -S, --seed N         seed (default 1)\n"
    "  -j, --threads N      threads (default all); same points for any N\n"
    "  -T, --text           text output\n"
    "  -v, --verbose        setup, count and phase times on standard error\n"
    "  -o, --output FILE    output (default standard output)\n"
    "  -q, --quiet          no warnings\n"
    "  -h, --help           this help;  --version  the version\n";

static void parse_steps(struct sets *o, const char *s)
{
	char buf[512], *tok, *save = NULL;

	if (snprintf(buf, sizeof buf, "%s", s) >= (int)sizeof buf)
		cli_usage_error("--progressive: list too long");
	o->nsteps = 0;
	for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",",
	    &save)) {
		if (o->nsteps == 16)
			cli_usage_error("--progressive: at most 16 steps");
		o->steps[o->nsteps] = cli_u64("--progressive", tok, 1,
		    (uint64_t)1 << 40);
		if (o->nsteps > 0 && o->steps[o->nsteps] <= o->steps[o->nsteps - 1])
			cli_usage_error("--progressive: counts must increase");
		o->nsteps++;
	}
	if (o->nsteps == 0)
		cli_usage_error("--progressive: no counts");
}

/* --data-dir: the directory the shipped default matrix is taken from
 * (the other shipped files lie beside it), and exit. */
static noreturn void print_data_dir(void)
{
	char path[CLI_PATH_MAX];

	cli_options_done();	/* the fuzz target stops here */
	if (cli_data_file("default.frd", path, sizeof path) < 0)
		cli_die("--data-dir: no shipped data (%s)", cli_errmsg());
	*strrchr(path, '/') = '\0';
	if (printf("%s\n", path) < 0 || fflush(stdout) == EOF)
		cli_die("<stdout>: write error");
	exit(0);
}

/* -a: the library's algorithms, or the device's flat1 (Sorted's
 * options on the CPU side). */
static void parse_algo(struct sets *o, const char *s)
{
	const char *const *w = frs_names(FRS_NAMES_ALGORITHM);

	o->flat1 = strcmp(s, "flat1") == 0;
	o->alg = FRS_ALG_SORTED;
	for (int i = 0; !o->flat1 && w[i] != NULL; i++)
		if (strcmp(s, w[i]) == 0) {
			o->alg = (enum frs_algorithm)i;
			return;
		}
	if (!o->flat1)
		cli_usage_error("-a: unknown implementation '%s' (naive, stack, "
		    "level1, level2, sorted, flat1)", s);
}

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "n=count i=importance m=matrix a=algo s=size sigma jitter pdf "
    "progressive threshold count-only exact-count equirect strict "
    "sets device list-devices data-dir tiles level-blur level-column "
    "v=verbose";

static void parse_opts(int argc, char **argv, struct sets *o)
{
	int c, have_n = 0, exact = 0;
	uint64_t n = 0;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 'n':
			n = cli_u64("-n", optarg, 1, (uint64_t)1 << 40);
			have_n = 1;
			break;
		case 'i': o->imp = optarg; break;
		case 'm': o->matrix = optarg; break;
		case 'a': parse_algo(o, optarg); break;
		case 's':
			o->nsize = (unsigned)cli_size3("-s", optarg, FRS_MAP_MAX_SIDE,
			    o->size);
			break;
		case OPT_SIGMA:
			o->opt.sigma = cli_double("--sigma", optarg, 1.0,
			    FRS_SIGMA_MAX);
			break;
		case OPT_JITTER:
			o->opt.jitter = (enum frs_jitter_mode)cli_choice("--jitter",
			    optarg, frs_names(FRS_NAMES_JITTER));
			break;
		case OPT_PDF: o->pdf = 1; break;
		case OPT_PROGRESSIVE: parse_steps(o, optarg); break;
		case OPT_THRESHOLD:
			o->opt.rule = (enum frs_rule_mode)cli_choice("--threshold",
			    optarg, frs_names(FRS_NAMES_RULE));
			break;
		case OPT_COUNT_ONLY: o->count_only = 1; break;
		case OPT_EXACT_COUNT: exact = 1; break;
		case OPT_TILES:
			o->opt.tiling = (enum frs_tiling_mode)cli_choice("--tiles",
			    optarg, frs_names(FRS_NAMES_TILING));
			break;
		case OPT_LEVEL_BLUR:
			o->opt.level_blur = cli_double("--level-blur", optarg, 0.0,
			    FRS_LEVEL_BLUR_MAX);
			/* 0: none, which the library's radii below 0.5 are
			 * (its 0 is the default). */
			if (o->opt.level_blur == 0.0)
				o->opt.level_blur = 0.25;
			break;
		case OPT_LEVEL_COLUMN: o->level_col = 1; break;
		case OPT_EQUIRECT: o->flags |= FRS_MAP_EQUIRECT; break;
		case OPT_STRICT: o->flags |= FRS_MAP_STRICT; break;
		case OPT_SETS:
			o->sets = cli_sets_m(optarg);
			break;
		case OPT_DEVICE: o->cl = cli_device(optarg, &o->device); break;
		case OPT_LIST_DEVICES: cli_list_devices();
		case OPT_DATA_DIR: print_data_dir();
		case 'v': o->verbose = 1; break;
		default:
			if (!cli_common_opt(c, optarg))
				cli_usage(2);
		}
	}
	if (optind != argc)
		cli_usage_error("unexpected argument '%s'", argv[optind]);
	if (o->flat1 && !o->cl)
		cli_usage_error("-a flat1 runs on OpenCL only (--device cl)");
	if (exact && o->opt.rule == FRS_RULE_THESIS)
		cli_usage_error("--exact-count needs --threshold unbiased: under "
		    "the thesis rule elements of equal importance share "
		    "thresholds, and counts jump past n");
	if (exact)
		o->opt.rule = FRS_RULE_EXACT;
	if (o->nsteps == 0) {
		if (!have_n)
			cli_usage_error("-n COUNT is required");
		o->steps[0] = n;
		o->nsteps = 1;
	} else if (have_n && n != o->steps[o->nsteps - 1]) {
		cli_usage_error("-n %llu differs from the last progressive count",
		    (unsigned long long)n);
	}
	n = o->steps[o->nsteps - 1];
	cli_sets_check(o->sets, n);
	o->opt.threads = cli.threads;
	o->seed = cli.seed;
	o->text = cli.text;
	o->out = cli.out;
}

/* Refuse counts whose elements (size bytes each, with a tenth more for
 * the count's spread) could not be stored before spending the time. */
static void check_room(const struct sets *o, size_t size)
{
	uint64_t n = o->steps[o->nsteps - 1];
	char what[64];

	snprintf(what, sizeof what, "-n %llu (--count-only counts them)",
	    (unsigned long long)n);
	if (!o->count_only)
		cli_mem_check(what, n + n / 10, size);
}

/* The checks that depend on the matrix's dimensions. */
static void check_dims(const struct sets *o)
{
	if (o->dims == 2 && o->nsize == 3)
		cli_die("-s %ux%ux%u: a volume size, but %s is a 2-D matrix",
		    o->size[0], o->size[1], o->size[2], o->matrix);
	if (o->dims == 2)
		return;
	if (o->cl)
		cli_die("--device: %s is a 3-D matrix; 3-D sampling runs on the "
		    "CPU only", o->matrix);
	if (o->flat1 || (o->alg != FRS_ALG_NAIVE && o->alg != FRS_ALG_SORTED))
		cli_die("-a %s: %s is a 3-D matrix; 3-D sampling has naive and "
		    "sorted", o->flat1 ? "flat1" :
		    frs_names(FRS_NAMES_ALGORITHM)[o->alg], o->matrix);
	if (o->flags & FRS_MAP_EQUIRECT)
		cli_die("--equirect: %s is a 3-D matrix; volumes have no "
		    "equirectangular form", o->matrix);
	if (o->nsize == 2)
		cli_die("-s %ux%u: %s is a 3-D matrix; give -s N or WxHxD",
		    o->size[0], o->size[1], o->matrix);
	/* main counted 2-D elements; 3-D ones are larger. */
	check_room(o, frs_draw_bytes(3));
}

/* Load a->matrix, opening it once, and set a->dims from its header (2
 * when it tells none); a failure is told when the run takes the matrix.
 * Standard input is left to the run, which may read a map from it
 * before. */
static void load_matrix(struct sets *a)
{
	double t0 = cli_now();
	unsigned dims = 0;

	a->loaded = strcmp(a->matrix, "-") != 0;
	if (a->loaded)
		a->mask_rc = frs_mask_load_dims(&a->mask, a->matrix, &dims,
		    &a->mask_err);
	a->dims = dims == 3 ? 3 : 2;
	a->tload = cli_now() - t0;
}

/* Load the default matrix for dims (frs_default_matrix) as load_matrix
 * loads a named one: -1 when none is found, a->mask_err saying why. */
static int default_matrix(struct sets *a, unsigned dims)
{
	static char path[CLI_PATH_MAX];
	double t0 = cli_now();

	a->mask_rc = frs_default_matrix(&a->mask, dims, path, sizeof path,
	    &a->mask_err);
	if (path[0] == '\0')
		return -1;
	a->matrix = path;
	a->loaded = 1;
	/* One that fails to load is reported as load_matrix's are. */
	a->dims = a->mask_rc == FRS_OK ? frs_mask_dims(a->mask) : dims;
	a->tload = cli_now() - t0;
	return 0;
}

/* Load the map or volume a->imp (NULL: constant) at a->size, a volume
 * when want is 3, a map when 2, and when 0 what a->imp is: its
 * dimensions, -1 after cli_fail. */
static int load_map(struct sets *a, unsigned want)
{
	unsigned dims;

	if (frs_source_read(a->imp ? a->imp : "const", want, a->size, a->flags,
	    &dims, &a->map, &a->stats, &a->vol, NULL) != FRS_OK)
		return -1;
	return (int)dims;
}

static void unload_map(struct sets *a)
{
	frs_imap_free(&a->map);
	frs_vol_free(&a->vol);
}

/* The matrix and the map, each file opened once: a matrix named says
 * whether the map is a volume; without one -s WxH or WxHxD, else the map
 * itself, says so and which shipped matrix to take. */
static void load_inputs(struct sets *o)
{
	unsigned want = o->nsize >= 2 ? o->nsize : 0;
	int dims;

	if (o->matrix != NULL) {
		load_matrix(o);
		check_dims(o);
		want = o->dims;
	}
	if ((dims = load_map(o, want)) < 0)
		cli_die_lib();
	if (o->matrix != NULL)
		return;
	if (default_matrix(o, (unsigned)dims) < 0)
		cli_die("%s; give -m MATRIX", o->mask_err.message);
	/* FRS_MATRIX (FRS_MATRIX3) named a matrix of the other kind: the
	 * source as that kind (a spec made again, a file read again). */
	if (o->dims != (unsigned)dims && (unload_map(o),
	    load_map(o, o->dims) < 0))
		cli_die_lib();
	check_dims(o);
}

/* The levels of the run whose cells span more than the matrix on an
 * axis, as "2, 3", into buf; their number. */
static unsigned repeating(const struct sets_run *r, char *buf, size_t cap)
{
	unsigned k = 0;
	size_t len = 0;

	buf[0] = '\0';
	for (unsigned i = 0; i < r->info.levels; i++) {
		const struct frs_run_level *v = &r->lv[i];
		int over = 0;
		for (unsigned a = 0; a < r->dims; a++)
			over |= (uint64_t)(v->hi[a] - v->lo[a] + 1) * v->info.ns >
			    r->info.matrix[a];
		if (over && len < cap)
			len += (size_t)snprintf(buf + len, cap - len, "%s%u",
			    k ? ", " : "", v->info.level);
		k += (unsigned)over;
	}
	return k;
}

/* The matrix's sides as "WxH" or "WxHxD". */
static const char *msize(const struct sets_run *r, char *buf, size_t cap)
{
	if (r->dims == 2)
		snprintf(buf, cap, "%ux%u", r->info.matrix[0],
		    r->info.matrix[1]);
	else
		snprintf(buf, cap, "%ux%ux%u", r->info.matrix[0],
		    r->info.matrix[1], r->info.matrix[2]);
	return buf;
}

/* The warnings of set 0's setup: patterns that repeat.  Without levels,
 * the thesis's: more samples than the matrix gives without repetition
 * (Table 4.1), or plain tiles of a window larger than the matrix.  With
 * levels, the levels whose cells span more than the matrix on an axis:
 * their samples show the same matrix elements again, a lattice of the
 * matrix's period. */
static void warn_repeats(const struct sets_run *r, double sigma)
{
	const struct frs_run_info *f = &r->info;
	int levels = r->opt.tiling == FRS_TILING_LEVELS, over = 0;
	char which[256], m[64];
	unsigned k = levels ? repeating(r, which, sizeof which) : 0;

	msize(r, m, sizeof m);
	for (unsigned a = 0; a < r->dims; a++)
		over |= f->window[a] > r->info.matrix[a];
	if (k > 0)
		cli_warn("level%s %s of the multi-level window span%s more than "
		    "the %s matrix: %s samples repeat the matrix's patterns%s",
		    k > 1 ? "s" : "", which, k > 1 ? "" : "s", m,
		    k > 1 ? "their" : "its", (double)f->n > f->unique ? r->dims ==
		    2 ? " (n is past the samples it gives without repetition, "
		    "thesis Table 4.1)" : " (n is past the samples it gives "
		    "without repetition)" : "");
	else if (!levels && (double)f->n > f->unique)
		cli_warn(r->dims == 2 ? "%llu samples from a %s matrix with "
		    "sigma %g repeat its patterns (it gives %.0f without "
		    "repetition, thesis Table 4.1)" : "%llu samples from a %s "
		    "matrix with sigma %g repeat its patterns (it gives %.6g "
		    "without repetition)", (unsigned long long)f->n, m, sigma,
		    f->unique);
	else if (!levels && !f->shuffled && over && r->dims == 2)
		cli_warn("plain tiles: the window of %llux%llu repeats the %s "
		    "matrix as it is, a lattice of the tile's period where few "
		    "samples fall (shuffled tiles break it)",
		    (unsigned long long)f->window[0],
		    (unsigned long long)f->window[1], m);
	else if (!levels && !f->shuffled && over)
		cli_warn("plain tiles: the window of %llux%llux%llu repeats the "
		    "%s matrix as it is", (unsigned long long)f->window[0],
		    (unsigned long long)f->window[1],
		    (unsigned long long)f->window[2], m);
}

/* The mask (as load_matrix loaded it), its note (a stale twin .frp)
 * as a warning. */
static int load_mask(const struct sets *a, struct sets_run *run)
{
	frs_error err = a->mask_err;
	int rc = a->loaded ? a->mask_rc : frs_mask_load(&run->mask, a->matrix,
	    &err);

	if (a->loaded)
		run->mask = a->mask;
	if (rc != FRS_OK)
		return cli_fail("%s", err.message);
	if ((run->note = frs_mask_note(run->mask)) != NULL)
		cli_warn("%s", run->note);
	return 0;
}

/* Set 0's run (prepared when prep), its setup and levels, and the
 * warnings of patterns that repeat. */
static int open_run(const struct sets *a, struct sets_run *run, int exact,
    int prep)
{
	frs_error err;
	int rc = run->dims == 2 ? frs_run_new(&run->r, run->smp, a->steps,
	    a->nsteps, a->seed, exact ? FRS_RUN_EXACT : 0, &err) :
	    frs_run3_new(&run->r, run->smp3, a->steps, a->nsteps, a->seed,
	    exact ? FRS_RUN_EXACT : 0, &err);

	if (rc == FRS_OK)
		rc = frs_run_info(run->r, &run->info, &err);
	for (unsigned i = 0; rc == FRS_OK && i < run->info.levels; i++)
		rc = frs_run_level(run->r, i, &run->lv[i], &err);
	if (rc != FRS_OK)
		return cli_fail("%s", err.message);
	/* 2-D warns after the preparing, 3-D before, as they always did. */
	if (run->dims == 3)
		warn_repeats(run, a->opt.sigma);
	if (prep && frs_run_prepare(run->r, &err) != FRS_OK)
		return cli_fail("%s", err.message);
	if (run->dims == 2)
		warn_repeats(run, a->opt.sigma);
	return 0;
}

/* The sampler of a 2-D mask on the CPU or the device, and set 0's
 * levels with the mask prepared for them. */
static int open2(const struct sets *a, struct sets_run *run)
{
	struct frs_imap map = a->map;	/* taken over */
	frs_error err;
	double t0;
	int rc, exact = a->opt.rule == FRS_RULE_EXACT;

	/* The OpenCL device asked for, if any (one that does not open ends
	 * the program). */
	if (a->cl && frs_device_open(&run->dev, a->device, NULL) != FRS_OK)
		cli_die_device(!a->flat1);
	t0 = cli_now();
	rc = load_mask(a, run);
	/* The map as load_map checked it, handed over: no copy, no second
	 * check. */
	if (rc == 0 && frs_sampler_take(&run->smp, run->mask, &map, &a->stats,
	    &run->opt, &err) != FRS_OK)
		rc = cli_fail("%s", err.message);
	if (rc < 0) {
		frs_imap_free(&map);	/* not taken: its check failed */
		return -1;
	}
	if (run->dev != NULL && frs_sampler_set_device(run->smp, run->dev,
	    a->flat1 ? FRS_DEVICE_FLAT1 : 0, &err) != FRS_OK)
		return cli_fail("%s", err.message);
	/* Exact counts: set 0's taus only for -v (each set finds its own),
	 * and the mask prepared for them only then. */
	if (open_run(a, run, a->verbose, !exact || a->verbose) < 0)
		return -1;
	run->tsetup = cli_now() - t0 + a->tload;
	return 0;
}

/* The same for a 3-D mask over a volume (the CPU only). */
static int open3(const struct sets *a, struct sets_run *run)
{
	double t0 = cli_now();
	struct frs_vol v = a->vol;	/* taken over */
	frs_error err;

	if (load_mask(a, run) < 0) {
		frs_vol_free(&v);
		return -1;
	}
	if (frs_sampler3_new_f64(&run->smp3, run->mask, v.v, v.w, v.h, v.d,
	    &run->opt, &err) != FRS_OK) {
		frs_vol_free(&v);
		return cli_fail("%s", err.message);
	}
	frs_vol_free(&v);
	/* Exact counts: set 0's taus only for -v, as in 2-D. */
	if (open_run(a, run, a->verbose, 1) < 0)
		return -1;
	run->tsetup = cli_now() - t0 + a->tload;
	return 0;
}

/*
 * Take the matrix (load_matrix's; standard input loaded here), the map
 * or volume (load_map's) and the device, make the sampler and set 0's
 * setup, with the mask prepared for it (so that -v counts that in the
 * setup, with the matrix's loading); with FRS_RULE_EXACT the exact taus
 * of set 0 only with verbose (each set's run finds its own).  Warns of a
 * stale twin .frp and of patterns that repeat.  0; -1 after cli_fail; -2
 * when the device could not be opened.
 */
static int open_sets(const struct sets *a, struct sets_run *run)
{
	memset(run, 0, sizeof *run);
	run->dims = a->dims;
	run->reused = -1.0;
	/* Flat 1, no public algorithm, is the device's (FRS_DEVICE_FLAT1):
	 * a->alg, the sampler's options, names Sorted for it. */
	run->opt = a->opt;
	run->opt.algorithm = a->alg;
	return run->dims == 3 ? open3(a, run) : open2(a, run);
}

static void close_sets(struct sets_run *run)
{
	frs_run_free(run->r);
	frs_sampler_free(run->smp);
	frs_sampler3_free(run->smp3);
	frs_mask_free(run->mask);
	frs_device_free(run->dev);
}

int main(int argc, char **argv)
{
	struct sets o = { .alg = FRS_ALG_SORTED, .sets = 1, .device = -1 };
	struct sets_run run;
	int rc;

	frs_options_init(&o.opt);
	cli_init("frs-sample", usage);
	parse_opts(argc, argv, &o);
	check_room(&o, frs_draw_bytes(2));
	cli_options_done();
	load_inputs(&o);
	if ((rc = open_sets(&o, &run)) < 0)
		rc == -2 ? cli_die_device(!o.flat1) : cli_die_lib();
	cli_out_check(o.out, !o.count_only && !o.text);
	if (sets_write(&o, &run) < 0)
		cli_die_lib();
	if (o.verbose)
		sets_report(stderr, &o, &run);
	close_sets(&run);
	return 0;
}
