/* The rows of discrepancy and mc-error over groups of sets: the groups
 * in order of first appearance for each --group, and their statistics
 * against values worked out by hand. */
#include "testutil.h"
#include "cli/groupstat.h"

#include <math.h>

static const char file_a[] = "a.pts", file_b[] = "b.pts";

/* Four sets: 4 points in a, 8 in a, 4 in b, 4 in a. */
static const struct pt_set sets[] = {
	{ NULL, NULL, 4, 2, file_a, 0 },
	{ NULL, NULL, 8, 2, file_a, 4 },
	{ NULL, NULL, 4, 2, file_b, 0 },
	{ NULL, NULL, 4, 2, file_a, 12 },
};
static const double v[] = { 1, 5, 2, 3 };

static void grouping(void **state)
{
	static const struct {
		enum pt_group g;
		size_t k, group[4];
	} want[] = {
		{ PT_GROUP_NFILE, 3, { 0, 1, 2, 0 } },
		{ PT_GROUP_N, 2, { 0, 1, 0, 0 } },
		{ PT_GROUP_FILE, 2, { 0, 0, 1, 0 } },
		{ PT_GROUP_ALL, 1, { 0, 0, 0, 0 } },
	};
	(void)state;

	for (size_t t = 0; t < sizeof want / sizeof want[0]; t++) {
		size_t group[4];
		assert_int_equal(group_sets(want[t].g, sets, 4, group),
		    want[t].k);
		assert_memory_equal(group, want[t].group, sizeof group);
	}
}

static void stats(void **state)
{
	size_t group[4];
	struct group_stat st;
	(void)state;

	/* Sets 0 and 3: values 1 and 3 about ref 2. */
	group_sets(PT_GROUP_NFILE, sets, 4, group);
	group_stat(sets, 4, group, 0, v, 2, &st);
	assert_int_equal(st.first, 0);
	assert_true(st.sets == 2 && st.n == 4 && st.mean == 2 && st.max == 3);
	assert_true(st.se == 1 && st.abs_err == 1 && st.rmse == 1);
	/* Set 1 alone: no standard error. */
	group_stat(sets, 4, group, 1, v, 2, &st);
	assert_int_equal(st.first, 1);
	assert_true(st.sets == 1 && st.n == 8 && st.mean == 5 && st.max == 5);
	assert_true(isnan(st.se) && st.abs_err == 3 && st.rmse == 3);
	/* By count: sets 0, 2 and 3, values 1, 2, 3. */
	group_sets(PT_GROUP_N, sets, 4, group);
	group_stat(sets, 4, group, 0, v, 2, &st);
	assert_true(st.sets == 3 && st.n == 4 && st.mean == 2);
	assert_near(st.se, sqrt(1.0 / 3), 1e-15);
	assert_near(st.abs_err, 2.0 / 3, 1e-15);
	assert_near(st.rmse, sqrt(2.0 / 3), 1e-15);
	/* All: the mean point count, and the largest value. */
	group_sets(PT_GROUP_ALL, sets, 4, group);
	group_stat(sets, 4, group, 0, v, 0, &st);
	assert_true(st.sets == 4 && st.n == 5 && st.max == 5);
	assert_near(st.mean, 2.75, 1e-15);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(grouping),
	cmocka_unit_test(stats))
