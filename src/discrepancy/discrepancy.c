/*
 * discrepancy: D2 and Dinf of 2-D point sets for the shape classes of
 * the thesis (Sec. 6.2), and of 3-D sets for the star class, one table
 * row per point count (Eq. 6.3).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "discrepancy/disc.h"
#include "discrepancy/discint.h"

static const char usage[] =
    "usage: discrepancy [-c CLASS] [--grid S] [--shapes K] [--exact]\n"
    "                   [--d2-only | --dinf-only]\n"
    "                   [--sets N] [--per-set | --group n|file|all]\n"
    "                   [-S SEED] [-j N] [-q]\n"
    "                   [-o FILE] FILE...\n"
    "\n"
    "  -c, --class C     star (default), rect, quad, half or circle;\n"
    "                    3-D sets: star only\n"
    "      --grid S      grid size: star 3000, rect 500, half 3000 border\n"
    "                    points per side (thesis), 3-D star 100 (s^3\n"
    "                    boxes, at most 1000); with --exact, Dinf on\n"
    "                    this grid instead of the exact Dinf\n"
    "      --shapes K    random shapes per set for quad and circle\n"
    "                    (default 9000000)\n"
    "      --exact       closed-form D2 (star: Warnock; rect: all boxes)\n"
    "                    and exact Dinf over the critical boxes (star\n"
    "                    O(n^1.5), rect O(n^3)); 3-D star: D2\n"
    "                    O(n log^2 n), Dinf O(n^3), at most 4096 points\n"
    "      --d2-only     D2 alone (with --exact: no exact Dinf);\n"
    "                    the Dinf columns read nan\n"
    "      --dinf-only   Dinf alone; the D2 columns read nan\n"
    "      --sets N      split every file into sets of N points in\n"
    "                    file order (a file with a set column: its sets)\n"
    "      --per-set     a row per set instead of one per point count\n"
    "      --group G     a row per point count over all files (n), per\n"
    "                    input file (file) or for all sets (all); n is\n"
    "                    then the mean point count, e.g. of frs-sample\n"
    "                    sets; default a row per point count and file,\n"
    "                    with a file column for several files\n"
    "  -S, --seed N      seed of the random shapes (default 1)\n"
    "  -j, --threads N   threads (default: all cores)\n"
    "  -o, --output F    output (default standard output)\n"
    "  -q, --quiet       no notes;  --progress  a progress bar\n"
    "  -h, --help        this help;  --version  the version\n";

struct run {
	struct disc_ctx *ctx;
	const struct pt_set *sets;
	struct disc_result *res;
};

static int one_set(void *arg, uint64_t b, uint64_t e)
{
	struct run *r = arg;
	for (uint64_t i = b; i < e; i++)
		if (disc_set_dims(r->ctx, r->sets[i].xy, r->sets[i].n,
		    r->sets[i].dims, 0, &r->res[i]) < 0)
			return cli_fail_context(r->sets[i].file);
	return 0;
}

/* The method, and ":D2" or ":Dinf" when only that one was computed. */
static void method(const struct disc_opts *o, char *buf, size_t len)
{
	const char *only = o->no_dinf ? ":D2" : o->no_d2 ? ":Dinf" : "";

	if (o->cls == DISC_QUAD || o->cls == DISC_CIRCLE)
		snprintf(buf, len, "random%llu%s",
		    (unsigned long long)o->shapes, only);
	else if (o->cls == DISC_HALF)
		snprintf(buf, len, "border%u%s", o->grid, only);
	else if (o->exact_d2 && (o->exact_dinf || o->no_dinf))
		snprintf(buf, len, "exact%s", only);
	else if (o->exact_d2)
		snprintf(buf, len, "exact+grid%u", o->grid);
	else
		snprintf(buf, len, "grid%u%s", o->grid, only);
}

/* A discrepancy, or nan for one left out (printf's "nan" for NAN is
 * not promised by C for every libc; the table's is). */
static void put_value(FILE *fp, double v, int skipped)
{
	if (skipped)
		fputs("nan", fp);
	else
		fprintf(fp, "%.9g", v);
}

static void per_set_rows(FILE *fp, const struct disc_opts *o,
    const struct pt_set *sets, const struct disc_result *res, size_t nsets,
    const char *meth, double tests)
{
	fprintf(fp, "class\tn\tset\tD2\tDinf\tshapes\tmethod\tfile\n");
	for (size_t i = 0; i < nsets; i++) {
		fprintf(fp, "%s\t%zu\t%zu\t", disc_class_name(o->cls),
		    sets[i].n, i);
		put_value(fp, res[i].d2, o->no_d2);
		fputc('\t', fp);
		put_value(fp, res[i].dinf, o->no_dinf);
		fprintf(fp, "\t%.17g\t%s\t", tests, meth);
		pt_put_name(fp, sets[i].file);
		fputc('\n', fp);
	}
}

/* The D2 and Dinf statistics of group k's row; its first set. */
static size_t group_row(FILE *fp, const struct disc_opts *o,
    const struct pt_set *sets, const size_t *group, size_t k,
    const double *v, size_t nsets)
{
	struct group_stat d2, dinf;

	group_stat(sets, nsets, group, k, v, 0, &d2);
	group_stat(sets, nsets, group, k, v + nsets, 0, &dinf);
	fprintf(fp, "%s\t%.10g\t%.0f\t", disc_class_name(o->cls), d2.n,
	    d2.sets);
	put_value(fp, d2.mean, o->no_d2);
	fputc('\t', fp);
	if (o->no_d2)
		fputs("nan", fp);
	else if (d2.sets > 1)
		fprintf(fp, "%.3g", d2.se);
	else
		fputc('-', fp);
	fputc('\t', fp);
	put_value(fp, dinf.max, o->no_dinf);
	fputc('\t', fp);
	put_value(fp, dinf.mean, o->no_dinf);
	return d2.first;
}

/* One row per group of sets (Eq. 6.3), in order of first appearance;
 * n is the mean point count of the group. */
static void group_rows(FILE *fp, const struct disc_opts *o, enum pt_group g,
    const struct pt_set *sets, const struct disc_result *res, size_t nsets,
    const char *meth, double tests, int files)
{
	size_t *group = calloc(nsets, sizeof *group), ngroups;
	double *v = calloc(nsets, 2 * sizeof *v);	/* D2s, then Dinfs */

	if (group == NULL || v == NULL)
		cli_die("no memory");
	for (size_t i = 0; i < nsets; i++)
		v[i] = res[i].d2, v[nsets + i] = res[i].dinf;
	ngroups = group_sets(g, sets, nsets, group);
	fprintf(fp, "class\tn\tsets\tD2\tD2_se\tDinf\tDinf_mean\tshapes\t"
	    "method%s\n", files ? "\tfile" : "");
	for (size_t k = 0; k < ngroups; k++) {
		size_t first = group_row(fp, o, sets, group, k, v, nsets);
		fprintf(fp, "\t%.17g\t%s", tests, meth);
		if (files) {
			fputc('\t', fp);
			pt_put_name(fp, sets[first].file);
		}
		fputc('\n', fp);
	}
	free(group);
	free(v);
}

/* The options that mend what disc_check refused of a set (its messages
 * name none), taken in disc_check's order. */
static const char *check_fix(const struct disc_opts *o, const struct pt_set *s)
{
	if (s->dims != 3 || s->n == 0)
		return "";
	if (o->cls != DISC_STAR)
		return " (-c star)";
	if (o->exact_d2 && !o->no_d2 && s->n > DISC3_MAX_EXACT_D2)
		return "";
	if (o->exact_dinf && !o->no_dinf && s->n > DISC3_MAX_EXACT_N)
		return "; use --grid S (with --exact: exact D2, Dinf on the "
		    "grid) or --d2-only";
	return "; set it with --grid S";
}

/* Every set before any work: a 3-D set with another class than star, or
 * beyond the limits of the 3-D methods, stops the run naming its file. */
static void check_sets(const struct disc_opts *o, const struct pt_set *sets,
    size_t nsets)
{
	for (size_t i = 0; i < nsets; i++)
		if (disc_check(o, sets[i].dims, sets[i].n) < 0) {
			cli_fail_context(sets[i].file);
			cli_die("%s%s", cli_errmsg(), check_fix(o, &sets[i]));
		}
}

/* --d2-only and --dinf-only: one of them, and not where the grid of
 * --exact --grid would give only what is left out, or --exact nothing. */
static void only_checks(const struct disc_opts *o, int have_grid)
{
	if (o->no_d2 && o->no_dinf)
		cli_usage_error("--d2-only and --dinf-only exclude each other");
	if (o->no_dinf && o->exact_d2 && have_grid)
		cli_usage_error("--d2-only: --grid with --exact is the grid of "
		    "Dinf, which --d2-only leaves out; drop --grid");
	if (o->no_d2 && o->exact_d2 && have_grid)
		cli_usage_error("--dinf-only: --exact with --grid is the exact "
		    "D2, which --dinf-only leaves out; drop --exact");
}

/* A file whose points carry a pdf (importance sampling) is measured all
 * the same against the plain area: its discrepancy says how far from
 * uniform the points are, not how well they follow their density. */
static int warn_pdf(void *ctx, const struct pt_sets *s, size_t file,
    size_t first)
{
	(void)ctx, (void)file;
	if (first < s->n && s->set[first].w != NULL)
		cli_warn("%s: the points have a pdf column, but D2 and Dinf "
		    "measure them against the plain area (uniform density), "
		    "not against their pdf", s->set[first].file);
	return 0;
}

/* Everything the command line asked for. */
struct prog_opts {
	struct disc_opts o;
	int have_grid;		/* --grid given */
	int have_shapes;	/* --shapes given */
	int per_set;		/* --per-set */
	enum pt_group group;	/* --group */
	size_t per;		/* --sets N, 0 for none */
};

/* The options it takes, besides the common ones (cli.h). */
static const char options[] =
    "c=class grid shapes exact d2-only dinf-only sets per-set "
    "group";

static void parse_opts(int argc, char **argv, struct prog_opts *a)
{
	struct disc_opts *o = &a->o;
	int c;

	while ((c = cli_getopt(argc, argv, options)) != -1) {
		switch (c) {
		case 'c':
			if (disc_parse_class(optarg, &o->cls) < 0)
				cli_usage_error("-c: %s", cli_errmsg());
			break;
		case OPT_GRID:
			o->grid = (uint32_t)cli_u64("--grid", optarg, 2,
			    DISC_MAX_GRID);
			a->have_grid = 1;
			break;
		case OPT_SHAPES:
			o->shapes = cli_u64("--shapes", optarg, 1,
			    (uint64_t)1 << 40);
			a->have_shapes = 1;
			break;
		case OPT_EXACT: o->exact_d2 = 1; break;
		case OPT_D2_ONLY: o->no_dinf = 1; break;
		case OPT_DINF_ONLY: o->no_d2 = 1; break;
		case OPT_SETS: a->per = cli_sets(optarg); break;
		case OPT_PER_SET: a->per_set = 1; break;
		case OPT_GROUP: a->group = cli_group(optarg); break;
		default:
			cli_common_only(c, optarg);
		}
	}
	cli_need_files(argc);
}

/* What the class allows, and the defaults that depend on it. */
static void check_opts(struct prog_opts *a)
{
	struct disc_opts *o = &a->o;
	int random_shapes = o->cls == DISC_QUAD || o->cls == DISC_CIRCLE;

	if (o->exact_d2 && !disc_has_exact_d2(o->cls))
		cli_usage_error("--exact: no closed form for class %s; use "
		    "--shapes or --grid", disc_class_name(o->cls));
	if (a->have_shapes && !random_shapes)
		cli_usage_error("--shapes: class %s tests a grid; use --grid",
		    disc_class_name(o->cls));
	if (a->have_grid && random_shapes)
		cli_usage_error("--grid: class %s tests random shapes; use "
		    "--shapes", disc_class_name(o->cls));
	if (o->cls == DISC_RECT && a->have_grid && o->grid > DISC_MAX_RECT_GRID)
		cli_usage_error("--grid: at most %d for rect",
		    DISC_MAX_RECT_GRID);
	only_checks(o, a->have_grid);
	o->exact_dinf = o->exact_d2 && !a->have_grid &&
	    disc_has_exact_dinf(o->cls);
	if (!a->have_grid)
		o->grid = o->cls == DISC_RECT ? DISC_RECT_GRID :
		    o->cls == DISC_HALF ? DISC_HALF_GRID : DISC_STAR_GRID;
	if (!a->have_shapes)
		o->shapes = DISC_SHAPES;
	o->seed = cli.seed;
}

/* The discrepancies of the sets: several sets in parallel, one set with
 * the threads inside it and its own progress bar. */
static struct disc_result *measure(const struct disc_opts *o,
    const struct pt_set *sets, size_t nsets)
{
	struct disc_result *res;
	struct run run;
	struct cli_task *task;

	if ((res = calloc(nsets, sizeof *res)) == NULL)
		cli_die("no memory for %zu sets", nsets);
	if ((run.ctx = disc_ctx_new(o)) == NULL)
		cli_die_lib();
	run.sets = sets, run.res = res;
	if (nsets > 1) {
		task = cli_task_begin("sets", nsets);
		if (cli_parallel(nsets, 1, one_set, &run, task) < 0)
			cli_die_lib();
		cli_task_end(task);
	} else {
		disc_set_progress("discrepancy");
		if (disc_set_dims(run.ctx, sets[0].xy, sets[0].n, sets[0].dims,
		    1, &res[0]) < 0) {
			cli_fail_context(sets[0].file);
			cli_die_lib();
		}
		disc_set_progress(NULL);
	}
	disc_ctx_free(run.ctx);
	return res;
}

/* The table: a row per set or per group; nfiles, the input files. */
static void write_table(const struct prog_opts *a, const struct pt_sets *ps,
    const struct disc_result *res, size_t nfiles)
{
	const struct disc_opts *o = &a->o;
	struct outfile of;
	char meth[64];
	double tests;

	method(o, meth, sizeof meth);
	tests = o->exact_d2 && (o->exact_dinf || o->no_dinf) ? 0.0 :
	    disc_tests_dims(o, ps->dims);
	cli_out_open(&of, cli.out, 0);
	if (a->per_set)
		per_set_rows(of.fp, o, ps->set, res, ps->n, meth, tests);
	else
		group_rows(of.fp, o, a->group, ps->set, res, ps->n, meth, tests,
		    pt_group_files(a->group, nfiles));
	cli_out_commit(&of, 0);
}

int main(int argc, char **argv)
{
	struct prog_opts a = { .o = { .cls = DISC_STAR },
	    .group = PT_GROUP_NFILE };
	struct pt_sets ps = { 0 };
	struct disc_result *res;

	cli_init("discrepancy", usage);
	parse_opts(argc, argv, &a);
	check_opts(&a);
	cli_options_done();
	ps.max_dims = 3;
	cli_read_sets(&ps, argc, argv, a.per, warn_pdf, NULL);
	if (ps.dims == 3 && !a.have_grid)
		a.o.grid = DISC3_STAR_GRID;
	check_sets(&a.o, ps.set, ps.n);
	res = measure(&a.o, ps.set, ps.n);
	write_table(&a, &ps, res, (size_t)(argc - optind));
	pt_sets_free(&ps);
	free(res);
	return 0;
}
