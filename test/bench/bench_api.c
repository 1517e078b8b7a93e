/*
 * bench_api: Forced Random Sampling through the public API (src/lib/frs.h)
 * for scripts/bench-api.sh.
 *   bench_api MATRIX MAP N SEED THREADS REPEATS
 * prints, one per line, "what samples seconds":
 *   setup  the mask, the map (frs_map_load) and the sampler
 *   first  the first frs_draw, with no room: it counts, and prepares
 *          the mask's lists
 *   draw   frs_draw into the caller's buffer, the best of REPEATS
 *   each   frs_draw_each with a callback that sums, the best of REPEATS
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "frs.h"

static double now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void die(const char *what, const frs_error *e)
{
	fprintf(stderr, "bench_api: %s: %s: %s\n", what, frs_code_name(e->code),
	    e->message);
	exit(1);
}

/* The callback touches every point, as a consumer would. */
static int sum(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total)
{
	double *acc = ctx;

	(void)pdf;
	(void)step;
	(void)total;
	for (size_t i = 0; i < 2 * k; i++)
		*acc += xy[i];
	return 0;
}

int main(int argc, char **argv)
{
	struct frs_options opt;
	frs_error e;
	frs_mask *mask;
	frs_sampler *s;
	float *map;
	uint32_t w, h;
	uint64_t n, seed;
	size_t count = 0;
	double *xy, t0, best, acc = 0.0;
	int reps;

	if (argc != 7) {
		fprintf(stderr, "usage: bench_api MATRIX MAP N SEED THREADS "
		    "REPEATS\n");
		return 2;
	}
	n = strtoull(argv[3], NULL, 10);
	seed = strtoull(argv[4], NULL, 10);
	frs_options_init(&opt);
	opt.threads = atoi(argv[5]);
	reps = atoi(argv[6]);
	t0 = now();
	if (frs_mask_load(&mask, argv[1], &e) != FRS_OK)
		die(argv[1], &e);
	if (frs_map_load(argv[2], 0, 0, &map, &w, &h, &e) != FRS_OK)
		die(argv[2], &e);
	if (frs_sampler_new(&s, mask, map, w, h, 0, &opt, &e) != FRS_OK)
		die("frs_sampler_new", &e);
	printf("setup 0 %.6f\n", now() - t0);
	/* The first call, with no room, only counts (FRS_E_BUFFER); on the
	 * fresh mask it also prepares the lists. */
	t0 = now();
	if (frs_draw(s, n, seed, NULL, NULL, 0, &count, &e) != FRS_E_BUFFER)
		die("frs_draw", &e);
	printf("first %zu %.6f\n", count, now() - t0);
	if ((xy = malloc(2 * count * sizeof *xy)) == NULL)
		return 1;
	best = 1e30;
	for (int r = 0; r < reps; r++) {
		t0 = now();
		if (frs_draw(s, n, seed, xy, NULL, count, &count, &e) != FRS_OK)
			die("frs_draw", &e);
		t0 = now() - t0;
		best = t0 < best ? t0 : best;
	}
	printf("draw %zu %.6f\n", count, best);
	best = 1e30;
	for (int r = 0; r < reps; r++) {
		t0 = now();
		if (frs_draw_each(s, &n, 1, seed, 0, sum, &acc, &e) != FRS_OK)
			die("frs_draw_each", &e);
		t0 = now() - t0;
		best = t0 < best ? t0 : best;
	}
	printf("each %zu %.6f\n", count, best);
	/* acc keeps the callback's work from being optimised away. */
	fprintf(stderr, "bench_api: checksum %.6g\n", acc);
	free(xy);
	frs_sampler_free(s);
	frs_map_free(map);
	frs_mask_free(mask);
	return 0;
}
