#define _POSIX_C_SOURCE 200809L
#include "base/parse.h"
#include "base/err.h"

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int empty_or_space(const char *what, const char *s)
{
	if (s == NULL || *s == '\0')
		return frs_fail("%s: empty value", what);
	if (isspace((unsigned char)*s))
		return frs_fail("%s: '%s': leading white space", what, s);
	return 0;
}

int parse_ll(const char *what, const char *s, long long min, long long max,
    long long *out)
{
	char *end;
	long long v;

	if (empty_or_space(what, s) < 0)
		return -1;
	errno = 0;
	v = strtoll(s, &end, 10);
	if (end == s || *end != '\0')
		return frs_fail("%s: '%s' is not an integer", what, s);
	if (errno == ERANGE || v < min || v > max)
		return frs_fail("%s: %s is out of range [%lld, %lld]", what, s,
		    min, max);
	*out = v;
	return 0;
}

int parse_u64(const char *what, const char *s, uint64_t min, uint64_t max,
    uint64_t *out)
{
	char *end;
	unsigned long long v;

	if (empty_or_space(what, s) < 0)
		return -1;
	if (*s == '-')
		return frs_fail("%s: %s is negative", what, s);
	errno = 0;
	v = strtoull(s, &end, 0);
	if (end == s || *end != '\0')
		return frs_fail("%s: '%s' is not an integer", what, s);
	if (errno == ERANGE || v < min || v > max)
		return frs_fail("%s: %s is out of range [%llu, %llu]", what, s,
		    (unsigned long long)min, (unsigned long long)max);
	*out = v;
	return 0;
}

int parse_double(const char *what, const char *s, double min, double max,
    double *out)
{
	char *end;
	double v;

	if (empty_or_space(what, s) < 0)
		return -1;
	errno = 0;
	v = strtod(s, &end);
	if (end == s || *end != '\0')
		return frs_fail("%s: '%s' is not a number", what, s);
	if (!isfinite(v))
		return frs_fail("%s: %s is not a finite number", what, s);
	if (errno == ERANGE && fabs(v) > 1.0)
		return frs_fail("%s: %s overflows", what, s);
	if (v < min || v > max)
		return frs_fail("%s: %s is out of range [%g, %g]", what, s,
		    min, max);
	*out = v;
	return 0;
}

int parse_double_above(const char *what, const char *s, double min,
    double max, double *out)
{
	double v = 0.0;	/* set on success; gcc -O3 cannot tell */

	if (parse_double(what, s, -DBL_MAX, DBL_MAX, &v) < 0)
		return -1;
	if (!(v > min && v <= max))
		return frs_fail("%s: %s is out of range (%g, %g]", what, s,
		    min, max);
	*out = v;
	return 0;
}

int parse_size(const char *what, const char *s, uint32_t max, uint32_t *w,
    uint32_t *h)
{
	char buf[64];
	const char *x;
	long long a, b;

	if (empty_or_space(what, s) < 0)
		return -1;
	x = strchr(s, 'x');
	if (x == NULL) {
		if (parse_ll(what, s, 1, max, &a) < 0)
			return -1;
		*w = *h = (uint32_t)a;
		return 0;
	}
	if ((size_t)(x - s) >= sizeof buf)
		return frs_fail("%s: '%s' is not a size (N or WxH)", what, s);
	memcpy(buf, s, (size_t)(x - s));
	buf[x - s] = '\0';
	if (parse_ll(what, buf, 1, max, &a) < 0 ||
	    parse_ll(what, x + 1, 1, max, &b) < 0)
		return frs_fail("%s: '%s' is not a size in [1, %u] (N or WxH)",
		    what, s, max);
	*w = (uint32_t)a;
	*h = (uint32_t)b;
	return 0;
}
