/* Strict number parsing: junk, NaN, overflow and range are rejected with a
 * message naming the option. */
#include "testutil.h"
#include "base/parse.h"

#include <float.h>
#include <limits.h>

static void ints(void **state)
{
	long long v;
	uint64_t u;
	(void)state;

	assert_int_equal(parse_ll("-n", "42", 0, 100, &v), 0);
	assert_int_equal(v, 42);
	assert_int_equal(parse_ll("-n", "-7", -10, 10, &v), 0);
	assert_int_equal(v, -7);
	assert_int_equal(parse_ll("-n", "12abc", 0, 100, &v), -1);
	assert_err_has("-n", "12abc", "not an integer");
	assert_int_equal(parse_ll("-n", "", 0, 100, &v), -1);
	assert_err_has("-n", "empty");
	assert_int_equal(parse_ll("-n", " 5", 0, 100, &v), -1);
	assert_int_equal(parse_ll("-n", "5 ", 0, 100, &v), -1);
	assert_int_equal(parse_ll("-n", "101", 0, 100, &v), -1);
	assert_err_has("out of range");
	assert_int_equal(parse_ll("-n", "99999999999999999999", 0, LLONG_MAX,
	    &v), -1);
	assert_err_has("out of range");
	assert_int_equal(parse_u64("-S", "18446744073709551615", 0, UINT64_MAX,
	    &u), 0);
	assert_true(u == UINT64_MAX);
	assert_int_equal(parse_u64("-S", "18446744073709551616", 0, UINT64_MAX,
	    &u), -1);
	assert_int_equal(parse_u64("-S", "-1", 0, UINT64_MAX, &u), -1);
	assert_err_has("negative");
	assert_int_equal(parse_u64("-n", "0x10", 0, 100, &u), 0);
	assert_int_equal(u, 16);
}

static void doubles(void **state)
{
	double d;
	(void)state;

	assert_int_equal(parse_double("-p", "0.25", 0, 1, &d), 0);
	assert_true(d == 0.25);
	assert_int_equal(parse_double("-p", "1e-3", 0, 1, &d), 0);
	assert_true(d == 1e-3);
	assert_int_equal(parse_double("-p", "nan", 0, 1, &d), -1);
	assert_err_has("-p", "not a finite number");
	assert_int_equal(parse_double("-p", "inf", -DBL_MAX, DBL_MAX, &d), -1);
	assert_int_equal(parse_double("-p", "1e999", -DBL_MAX, DBL_MAX, &d),
	    -1);
	assert_int_equal(parse_double("-p", "0.5x", 0, 1, &d), -1);
	assert_err_has("not a number");
	assert_int_equal(parse_double("-p", "1.5", 0, 1, &d), -1);
	assert_err_has("out of range");
	/* Subnormal results are numbers, not errors. */
	assert_int_equal(parse_double("-p", "1e-310", 0, 1, &d), 0);
	assert_true(d > 0.0);
}

/* (min, max]: min itself is out, and the range reads the same on
 * either side. */
static void doubles_above(void **state)
{
	double d;
	(void)state;

	assert_int_equal(parse_double_above("-p", "1", 0, 1, &d), 0);
	assert_true(d == 1.0);
	assert_int_equal(parse_double_above("-p", "1e-300", 0, 1, &d), 0);
	assert_true(d == 1e-300);
	assert_int_equal(parse_double_above("-p", "0", 0, 1, &d), -1);
	assert_err_has("-p: 0 is out of range (0, 1]");
	assert_int_equal(parse_double_above("-p", "-0", 0, 1, &d), -1);
	assert_int_equal(parse_double_above("-p", "2", 0, 1, &d), -1);
	assert_err_has("-p: 2 is out of range (0, 1]");
	assert_int_equal(parse_double_above("-p", "nan", 0, 1, &d), -1);
	assert_err_has("-p", "not a finite number");
	assert_int_equal(parse_double_above("-p", "x", 0, 1, &d), -1);
	assert_err_has("-p: 'x' is not a number");
}

static void sizes(void **state)
{
	uint32_t w, h;
	(void)state;

	assert_int_equal(parse_size("-s", "256", 65536, &w, &h), 0);
	assert_true(w == 256 && h == 256);
	assert_int_equal(parse_size("-s", "1024x512", 65536, &w, &h), 0);
	assert_true(w == 1024 && h == 512);
	assert_int_equal(parse_size("-s", "0x5", 65536, &w, &h), -1);
	assert_int_equal(parse_size("-s", "0", 65536, &w, &h), -1);
	assert_int_equal(parse_size("-s", "12x", 65536, &w, &h), -1);
	assert_int_equal(parse_size("-s", "x12", 65536, &w, &h), -1);
	assert_int_equal(parse_size("-s", "5x5x5", 65536, &w, &h), -1);
	assert_int_equal(parse_size("-s", "70000x1", 65536, &w, &h), -1);
	assert_err_has("-s");
	assert_int_equal(parse_size("-s", "-4", 65536, &w, &h), -1);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(ints),
	cmocka_unit_test(doubles),
	cmocka_unit_test(doubles_above),
	cmocka_unit_test(sizes))
