/*
 * ref_dda: brute-force spectra and distances, the reference
 * implementation for the benchmark (scripts/bench-dda.sh).  Independent
 * of the library's dda code; libfrs only reads the point files.
 *
 *   ref_dda fourier K PER FILE   the periodogram of every set of PER
 *                                points, |kx|, |ky| <= K, by a direct
 *                                sum of cos and sin per frequency and
 *                                point, averaged; prints the mean power
 *                                over the frequencies and its maximum
 *                                off DC
 *   ref_dda dmin FILE            the minimum distance over all pairs
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/ptsets.h"
#include "base/err.h"

static void die(const char *msg)
{
	fprintf(stderr, "ref_dda: %s\n", msg);
	exit(1);
}

static void fourier(long k, const struct pt_sets *s)
{
	size_t side = (size_t)(2 * k + 1);
	double *p = calloc(side * side, sizeof *p), sum = 0, mx = 0;
	const double tau = 6.283185307179586476925;

	if (p == NULL)
		die("no memory");
	for (size_t q = 0; q < s->n; q++) {
		const double *xy = s->set[q].xy;
		size_t n = s->set[q].n;
		for (long ky = -k; ky <= k; ky++)
			for (long kx = -k; kx <= k; kx++) {
				double re = 0, im = 0;
				for (size_t j = 0; j < n; j++) {
					double a = -tau * ((double)kx * xy[2 * j] +
					    (double)ky * xy[2 * j + 1]);
					re += cos(a), im += sin(a);
				}
				p[(size_t)(ky + k) * side + (size_t)(kx + k)] +=
				    (re * re + im * im) / (double)n;
			}
	}
	for (size_t i = 0; i < side * side; i++) {
		p[i] /= (double)s->n;
		sum += p[i];
		if (i != side * side / 2 && p[i] > mx)
			mx = p[i];
	}
	printf("mean %.17g\nmax %.17g\n", sum / (double)(side * side), mx);
	free(p);
}

static void dmin(const struct pt_sets *s)
{
	const double *xy = s->set[0].xy;
	size_t n = s->set[0].n;
	double best = INFINITY;

	for (size_t i = 0; i < n; i++)
		for (size_t j = i + 1; j < n; j++) {
			double dx = xy[2 * i] - xy[2 * j];
			double dy = xy[2 * i + 1] - xy[2 * j + 1];
			double d = dx * dx + dy * dy;
			best = d < best ? d : best;
		}
	printf("dmin %.17g\n", sqrt(best));
}

int main(int argc, char **argv)
{
	struct pt_sets s = { 0 };

	if (argc == 5 && strcmp(argv[1], "fourier") == 0) {
		if (pt_sets_add(&s, argv[4], (size_t)atol(argv[3])) < 0)
			die(frs_errmsg());
		fourier(atol(argv[2]), &s);
	} else if (argc == 3 && strcmp(argv[1], "dmin") == 0) {
		if (pt_sets_add(&s, argv[2], 0) < 0)
			die(frs_errmsg());
		dmin(&s);
	} else
		die("usage: ref_dda fourier K PER FILE | ref_dda dmin FILE");
	pt_sets_free(&s);
	return 0;
}
