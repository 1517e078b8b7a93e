/*
 * libfrs in a program of one's own: sample an importance map (a PNG or
 * OpenEXR file, or a spec such as blob) with a threshold matrix and
 * print the points, one "x y" line each, as frs-sample -T does.
 *   cc api_example.c $(pkg-config --cflags --libs frs)
 *   ./a.out MAP MATRIX N SEED
 */
#include <stdio.h>
#include <stdlib.h>

#include <frs.h>

int main(int argc, char **argv)
{
	frs_error err;
	frs_mask *mask = NULL;
	frs_sampler *sampler = NULL;
	float *map = NULL;
	double *xy = NULL;
	uint32_t w, h;
	uint64_t n, seed;
	size_t count = 0;
	int rc;

	if (argc != 5) {
		fprintf(stderr, "usage: %s MAP MATRIX N SEED\n", argv[0]);
		return 2;
	}
	n = strtoull(argv[3], NULL, 10);
	seed = strtoull(argv[4], NULL, 10);
	if ((rc = frs_map_load(argv[1], 0, 0, &map, &w, &h, &err)) ||
	    (rc = frs_mask_load(&mask, argv[2], &err)) ||
	    (rc = frs_sampler_new(&sampler, mask, map, w, h, 0, NULL, &err)))
		goto out;
	/* With no room, FRS_E_BUFFER and how many samples there are. */
	rc = frs_draw(sampler, n, seed, NULL, NULL, 0, &count, &err);
	if (rc == FRS_E_BUFFER) {
		if ((xy = malloc(2 * count * sizeof *xy)) == NULL)
			return 1;
		rc = frs_draw(sampler, n, seed, xy, NULL, count, &count, &err);
	}
	for (size_t i = 0; rc == FRS_OK && i < count; i++)
		printf("%.17g %.17g\n", xy[2 * i], xy[2 * i + 1]);
out:
	if (rc != FRS_OK)
		fprintf(stderr, "%s: %s\n", frs_code_name(rc), err.message);
	free(xy);
	frs_sampler_free(sampler);
	frs_mask_free(mask);
	frs_map_free(map);
	return rc != FRS_OK;
}
