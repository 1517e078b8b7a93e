/* Point sets for the analysis programs (cli/ptsets.h): files cut into
 * sets by their set column or by a count, checked against the points the
 * test wrote; the pdf column; dimensions; the grouping rules. */
#include "testutil.h"
#include "cli/ptsets.h"
#include "cli/ptsio.h"

/* Point i of a file: x = i / 64 + 1/128, y = 1 - x. */
static double px(size_t i)
{
	return (double)i / 64.0 + 1.0 / 128.0;
}

/* A text point file of n points with a header line hdr (NULL: none)
 * and per point the extra values that cols writes after x and y. */
static const char *write_pts(const char *name, const char *hdr, size_t n,
    unsigned dims, void (*cols)(FILE *, size_t))
{
	const char *path = tu_path(name);
	FILE *fp = fopen(path, "w");

	assert_non_null(fp);
	if (hdr != NULL)
		fprintf(fp, "%s\n", hdr);
	for (size_t i = 0; i < n; i++) {
		fprintf(fp, "%.17g %.17g", px(i), 1.0 - px(i));
		if (dims == 3)
			fprintf(fp, " 0.5");
		if (cols != NULL)
			cols(fp, i);
		fputc('\n', fp);
	}
	assert_int_equal(fclose(fp), 0);
	return path;
}

/* The coordinates of set s are the file's points first .. first + n - 1. */
static void assert_points(const struct pt_set *s, size_t first, size_t n)
{
	assert_int_equal(s->first, first);
	assert_int_equal(s->n, n);
	for (size_t i = 0; i < n; i++) {
		assert_true(s->xy[s->dims * i] == px(first + i));
		assert_true(s->xy[s->dims * i + 1] == 1.0 - px(first + i));
		if (s->dims == 3)
			assert_true(s->xy[3 * i + 2] == 0.5);
	}
}

static void foo_pdf(FILE *fp, size_t i)
{
	fprintf(fp, " 7 %.17g", 2.0 + (double)i);
}

static void one_extra(FILE *fp, size_t i)
{
	fprintf(fp, " %.17g", 3.0 * (double)i);
}

/* A whole file is one set; the pdf is the column named pdf, in a file of
 * unnamed columns the first extra one; the extra values are dropped
 * from the packed coordinates. */
static void whole_files(void **state)
{
	struct pt_sets s = { 0 };
	const char *a = write_pts("a.pts", NULL, 10, 2, NULL);
	const char *b = write_pts("b.pts",
	    "#pts dims=2 extra=2 count=7 version=2 names=foo,pdf", 7, 2, foo_pdf);
	const char *c = write_pts("c.pts", "#pts dims=2 extra=1 count=5", 5, 2,
	    one_extra);
	const char *d = write_pts("d.pts",
	    "#pts dims=2 extra=1 count=5 version=2 names=foo", 5, 2, one_extra);

	(void)state;
	assert_int_equal(pt_sets_add(&s, a, 0), 0);
	assert_int_equal(pt_sets_add(&s, b, 0), 0);
	assert_int_equal(pt_sets_add(&s, c, 0), 0);
	assert_int_equal(pt_sets_add(&s, d, 0), 0);
	assert_int_equal(s.n, 4);
	assert_int_equal(s.dims, 2);
	for (size_t k = 0; k < 4; k++)
		assert_int_equal(s.set[k].dims, 2);
	assert_points(&s.set[0], 0, 10);
	assert_null(s.set[0].w);
	assert_ptr_equal(s.set[0].file, a);
	assert_points(&s.set[1], 0, 7);
	for (size_t i = 0; i < 7; i++)
		assert_true(s.set[1].w[i] == 2.0 + (double)i);
	assert_points(&s.set[2], 0, 5);
	assert_non_null(s.set[2].w);
	for (size_t i = 0; i < 5; i++)
		assert_true(s.set[2].w[i] == 3.0 * (double)i);
	assert_points(&s.set[3], 0, 5);
	assert_null(s.set[3].w);	/* named, but not pdf */
	pt_sets_free(&s);
	assert_true(s.n == 0 && s.nbuf == 0 && s.dims == 0 && s.set == NULL);
}

/* Blocks of per points; the count must be a multiple.  A file cut into
 * more than one block draws one warning (no set column says where its
 * sets begin), one block none. */
static void fixed_size_sets(void **state)
{
	struct pt_sets s = { 0 };
	const char *a = write_pts("per.pts", NULL, 12, 2, NULL);
	unsigned long w0 = frs_warn_count();

	(void)state;
	assert_int_equal(pt_sets_add(&s, a, 4), 0);
	assert_int_equal(s.n, 3);
	for (size_t k = 0; k < 3; k++)
		assert_points(&s.set[k], 4 * k, 4);
	assert_int_equal(frs_warn_count(), w0 + 1);
	assert_int_equal(pt_sets_add(&s, a, 5), -1);
	assert_err_has(a, "12 points", "sets of 5");
	assert_int_equal(s.n, 3);
	assert_int_equal(pt_sets_add(&s, a, 12), 0);
	assert_int_equal(s.n, 4);
	assert_points(&s.set[3], 0, 12);
	assert_int_equal(frs_warn_count(), w0 + 1);
	pt_sets_free(&s);
}

/* The set values of the set-column cases: the runs of each. */
static const double set_ok[] = { 0, 0, 0, 2, 2, 5, 5, 5, 5, 6 };
static const double *setv;

static void set_col(FILE *fp, size_t i)
{
	fprintf(fp, " %.17g 0.25", setv[i]);
}

static const char *write_sets(const char *name, const double *v, size_t n)
{
	setv = v;
	return write_pts(name, "#pts dims=2 extra=2 version=2 names=set,pdf",
	    n, 2, set_col);
}

/* A set column: one set per run, its id the value (gaps allowed); out
 * of order, fractions, negatives refused with the point named. */
static void set_column(void **state)
{
	static const double dec[] = { 0, 1, 1, 0 };
	static const double frac[] = { 0, 0.5 };
	static const double neg[] = { -1, 0 };
	static const double even[] = { 0, 0, 1, 1, 3, 3 };
	struct pt_sets s = { 0 };
	struct pt_range *r;
	size_t k;
	const char *a = write_sets("set.pts", set_ok, 10), *b;
	unsigned long w0;

	(void)state;
	assert_int_equal(pt_sets_add(&s, a, 0), 0);
	assert_int_equal(s.n, 4);
	assert_points(&s.set[0], 0, 3);
	assert_points(&s.set[1], 3, 2);
	assert_points(&s.set[2], 5, 4);
	assert_points(&s.set[3], 9, 1);
	for (k = 0; k < 4; k++)
		assert_true(s.set[k].w != NULL && s.set[k].w[0] == 0.25);
	/* With per, the column's sets all the same, one warning when they
	 * are not per points, none when they are. */
	w0 = frs_warn_count();
	assert_int_equal(pt_sets_add(&s, a, 3), 0);
	assert_int_equal(s.n, 8);
	assert_points(&s.set[5], 3, 2);
	assert_int_equal(frs_warn_count(), w0 + 1);
	b = write_sets("even.pts", even, 6);
	assert_int_equal(pt_sets_add(&s, b, 2), 0);
	assert_int_equal(s.n, 11);
	assert_int_equal(frs_warn_count(), w0 + 1);
	pt_sets_free(&s);
	{
		/* The ranges with their ids. */
		struct frs_points p;
		static const uint64_t id[] = { 0, 2, 5, 6 };
		assert_int_equal(pts_read(a, &p), 0);
		assert_int_equal(pt_split(&p, a, 0, &r, &k), 0);
		assert_int_equal(k, 4);
		for (size_t i = 0; i < 4; i++)
			assert_true(r[i].id == id[i]);
		free(r);
		pts_free(&p);
	}
	assert_int_equal(pt_sets_add(&s, write_sets("dec.pts", dec, 4), 0), -1);
	assert_err_has("dec.pts", "point 3", "set 0 after set 1");
	assert_int_equal(pt_sets_add(&s, write_sets("frac.pts", frac, 2), 0),
	    -1);
	assert_err_has("frac.pts", "point 1", "not a whole number");
	assert_int_equal(pt_sets_add(&s, write_sets("neg.pts", neg, 2), 0), -1);
	assert_err_has("neg.pts", "point 0");
	assert_int_equal(s.n, 0);
	pt_sets_free(&s);
}

/* 2-D only by default; 2-D or 3-D with max_dims 3, one dimension per
 * run; a file without points refused. */
static void dimensions(void **state)
{
	struct pt_sets s = { 0 };
	const char *two = write_pts("two.pts", NULL, 4, 2, NULL);
	const char *three = write_pts("three.pts", NULL, 6, 3, NULL);

	(void)state;
	assert_int_equal(pt_sets_add(&s, three, 0), -1);
	assert_err_has("three.pts", "3-dimensional", "2 are needed");
	s.max_dims = 3;
	assert_int_equal(pt_sets_add(&s, three, 2), 0);
	assert_int_equal(s.n, 3);
	assert_int_equal(s.dims, 3);
	assert_points(&s.set[2], 4, 2);
	assert_int_equal(pt_sets_add(&s, two, 0), -1);
	assert_err_has("two.pts", "2-dimensional points after 3-dimensional");
	pt_sets_free(&s);
	s.max_dims = 3;
	assert_int_equal(pt_sets_add(&s, two, 0), 0);
	assert_int_equal(pt_sets_add(&s, three, 0), -1);
	assert_err_has("three.pts", "after 2-dimensional");
	pt_sets_free(&s);
	assert_int_equal(pt_sets_add(&s, write_pts("empty.pts", NULL, 0, 2,
	    NULL), 0), -1);
	assert_err_has("empty.pts", "empty");
	assert_int_equal(pt_sets_add(&s, write_pts("none.pts",
	    "#pts dims=2 extra=0", 0, 2, NULL), 0), -1);
	assert_err_has("none.pts", "no points");
}

/* The grouping rules, every case, against their definitions. */
static void grouping(void **state)
{
	const char *f1 = "f1", *f2 = "f2";
	struct pt_set set[4] = {
		{ NULL, NULL, 10, 2, "f1", 0 }, { NULL, NULL, 10, 2, "f1", 10 },
		{ NULL, NULL, 20, 2, "f1", 20 }, { NULL, NULL, 10, 2, "f2", 0 },
	};
	char *buf = NULL;
	size_t len = 0;
	FILE *fp;

	(void)state;
	set[0].file = set[1].file = set[2].file = f1;
	set[3].file = f2;
	assert_int_equal(pt_group_parse("n"), PT_GROUP_N);
	assert_int_equal(pt_group_parse("file"), PT_GROUP_FILE);
	assert_int_equal(pt_group_parse("all"), PT_GROUP_ALL);
	assert_int_equal(pt_group_parse("nfile"), -1);
	assert_int_equal(pt_group_parse(""), -1);
	for (int a = 0; a < 4; a++)
		for (int b = 0; b < 4; b++) {
			int n = set[a].n == set[b].n, f = set[a].file == set[b].file;
			assert_int_equal(pt_same_group(PT_GROUP_N, &set[a], &set[b]),
			    n);
			assert_int_equal(pt_same_group(PT_GROUP_FILE, &set[a],
			    &set[b]), f);
			assert_int_equal(pt_same_group(PT_GROUP_ALL, &set[a],
			    &set[b]), 1);
			assert_int_equal(pt_same_group(PT_GROUP_NFILE, &set[a],
			    &set[b]), n && f);
		}
	for (size_t nf = 1; nf < 4; nf++) {
		assert_true(pt_group_files(PT_GROUP_FILE, nf));
		assert_false(pt_group_files(PT_GROUP_N, nf));
		assert_false(pt_group_files(PT_GROUP_ALL, nf));
		assert_int_equal(pt_group_files(PT_GROUP_NFILE, nf), nf > 1);
	}
	fp = open_memstream(&buf, &len);
	assert_non_null(fp);
	pt_put_name(fp, "a\tb\nc d");
	fclose(fp);
	assert_string_equal(buf, "a?b?c d");
	free(buf);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(whole_files),
	cmocka_unit_test(fixed_size_sets),
	cmocka_unit_test(set_column),
	cmocka_unit_test(dimensions),
	cmocka_unit_test(grouping))
