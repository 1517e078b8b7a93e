#define _POSIX_C_SOURCE 200809L
#include "frd-prep/frdimport.h"
#include "cli/cli.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The values made a permutation by rank, or checked to be one:
 * IMPORT_RANKS when they are not, which --rank would mend. */
static int finish(struct frs_matrix *m, const char *name, int rank)
{
	if (rank)
		return frs_matrix_rank(m, NULL) == FRS_OK ? 0 : -1;
	if (frs_matrix_check(m, name, NULL) != FRS_OK)
		return IMPORT_RANKS;
	return 0;
}

int frd_import_raw32(const char *path, uint32_t w, uint32_t h, int rank,
    struct frs_matrix *m)
{
	const char *name;
	unsigned char *buf;
	size_t len;
	char params[128];
	int rc;

	memset(m, 0, sizeof *m);
	rc = cli_read_file(path, &name, &buf, &len);
	if (rc < 0)
		return -1;
	if (len == 0 || len % 4) {
		free(buf);
		return cli_fail("%s: %zu bytes is not a whole number of 32-bit "
		    "values", name, len);
	}
	if (w == 0) {
		uint64_t n = len / 4, s = (uint64_t)llround(sqrt((double)n));
		if (s * s != n) {
			free(buf);
			cli_fail("%s: %llu values are not a square", name,
			    (unsigned long long)n);
			return IMPORT_SIZE;
		}
		w = h = (uint32_t)s;
	}
	if ((uint64_t)w * h * 4 != len) {
		free(buf);
		return cli_fail("%s: %zu bytes, but %ux%u values need %llu", name,
		    len, w, h, (unsigned long long)w * h * 4);
	}
	snprintf(params, sizeof params, "imported=raw32\nsource=%.100s\n", name);
	if (frs_matrix_alloc(m, 2, w, h, 1, params, NULL) != FRS_OK) {
		free(buf);
		return cli_fail_context(name);
	}
	for (size_t i = 0; i < m->n; i++) {
		const unsigned char *p = buf + 4 * i;
		m->v[i] = (uint32_t)p[0] | (uint32_t)p[1] << 8 |
		    (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
	}
	free(buf);
	if ((rc = finish(m, name, rank)) < 0)
		frs_matrix_free(m);
	return rc;
}

/* Count the values of a line; -1 with an error on junk. */
static long parse_row(const char *name, unsigned long line, char *s,
    uint32_t *out, long max)
{
	long n = 0;

	for (;;) {
		char *end;
		unsigned long long v;
		while (isspace((unsigned char)*s))
			s++;
		if (*s == '\0')
			return n;
		errno = 0;
		if (*s == '-')
			return cli_fail("%s:%lu: negative value", name, line);
		v = strtoull(s, &end, 10);
		if (end == s || (*end && !isspace((unsigned char)*end)))
			return cli_fail("%s:%lu: '%.20s' is not an integer", name,
			    line, s);
		if (errno || v > UINT32_MAX)
			return cli_fail("%s:%lu: value out of range", name, line);
		if (out != NULL) {
			if (n == max)
				return cli_fail("%s:%lu: more than %ld values", name,
				    line, max);
			out[n] = (uint32_t)v;
		}
		n++;
		s = end;
	}
}

int frd_import_text(const char *path, int rank, struct frs_matrix *m)
{
	const char *name;
	unsigned char *buf;
	size_t len;
	uint32_t w = 0, h = 0;
	char *s, *line, *save = NULL;
	unsigned long ln = 0;
	int rc;

	memset(m, 0, sizeof *m);
	rc = cli_read_file(path, &name, &buf, &len);
	if (rc < 0)
		return -1;
	s = (char *)buf;	/* cli_read_file leaves room for a NUL */
	s[len] = '\0';
	/* First pass: the shape. */
	{
		char *copy = strdup(s);
		for (line = strtok_r(copy, "\n", &save); line; line = strtok_r(NULL,
		    "\n", &save)) {
			long k = parse_row(name, ++ln, line, NULL, 0);
			if (k < 0) {
				free(copy);
				free(s);
				return -1;
			}
			if (k == 0)
				continue;
			if (w == 0)
				w = (uint32_t)k;
			else if ((uint32_t)k != w) {
				free(copy);
				free(s);
				return cli_fail("%s:%lu: %ld values, the first row has "
				    "%u", name, ln, k, w);
			}
			h++;
		}
		free(copy);
	}
	if (w == 0 || frs_matrix_alloc(m, 2, w, h, 1, "imported=text\n",
	    NULL) != FRS_OK) {
		free(s);
		return w == 0 ? cli_fail("%s: empty file", name) :
		    cli_fail_context(name);
	}
	ln = 0;
	save = NULL;
	{
		uint32_t row = 0;
		for (line = strtok_r(s, "\n", &save); line; line = strtok_r(NULL,
		    "\n", &save))
			if (parse_row(name, ++ln, line, m->v + (size_t)row * w, w) > 0)
				row++;
	}
	free(s);
	if ((rc = finish(m, name, rank)) < 0)
		frs_matrix_free(m);
	return rc;
}
