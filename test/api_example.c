/* sample.c: about 4096 points that follow an OpenEXR importance map. */
#include <stdio.h>
#include <stdlib.h>

#include <frs.h>

int main(int argc, char **argv)
{
	frs_error err = { FRS_OK, "" };
	frs_mask *mask = NULL;
	frs_sampler *sampler = NULL;
	float *map = NULL;
	double *xy = NULL, *bigger;
	uint32_t w, h;
	size_t cap = 4096, count = 0;
	int rc;

	if (argc < 2 || argc > 3) {
		fprintf(stderr, "usage: sample map.exr [matrix.frd]\n");
		return 2;
	}
	/* The matrix named, else the shipped one, found where frs-sample
	   finds it (FRS_DATA overrides). */
	if ((rc = frs_map_load(argv[1], 0, 0, &map, &w, &h, &err)) != FRS_OK ||
	    (rc = argc > 2 ? frs_mask_load(&mask, argv[2], &err) :
	    frs_default_matrix(&mask, 2, NULL, 0, &err)) != FRS_OK ||
	    (rc = frs_sampler_new(&sampler, mask, map, w, h, 0, NULL,
	    &err)) != FRS_OK)
		goto out;
	for (;;) {
		if ((bigger = realloc(xy, 2 * cap * sizeof *xy)) == NULL) {
			rc = FRS_E_NOMEM;
			snprintf(err.message, sizeof err.message,
			    "%zu points: out of memory", cap);
			goto out;
		}
		xy = bigger;
		rc = frs_draw(sampler, 4096, 1, xy, NULL, cap, &count, &err);
		if (rc != FRS_E_BUFFER)
			break;
		cap = count;	/* too small: count says how many */
	}
	for (size_t i = 0; rc == FRS_OK && i < count; i++)
		printf("%.17g %.17g\n", xy[2 * i], xy[2 * i + 1]);
out:
	if (rc != FRS_OK)
		fprintf(stderr, "sample: %s (%s)\n", err.message,
		    frs_code_name(rc));
	free(xy);
	if (sampler != NULL)
		frs_sampler_free(sampler);
	if (mask != NULL)
		frs_mask_free(mask);
	if (map != NULL)
		frs_map_free(map);
	if (fflush(stdout) == EOF) {
		perror("sample: <stdout>");
		return 1;
	}
	return rc == FRS_OK ? 0 : 1;
}
