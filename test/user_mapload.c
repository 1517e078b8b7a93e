/*
 * user_mapload SPEC WIDTH HEIGHT: load an importance map through the
 * public API alone, as a user's program linked with libfrs.a does, and
 * print nothing unless it fails (test/t_libquiet.sh runs it on a
 * terminal: the library must stay silent there too).
 */
#include <stdio.h>
#include <stdlib.h>

#include "frs.h"

int main(int argc, char **argv)
{
	frs_error err = { FRS_OK, "" };
	float *map = NULL;
	uint32_t w, h;
	int rc;

	if (argc != 4) {
		fprintf(stderr, "usage: user_mapload SPEC WIDTH HEIGHT\n");
		return 2;
	}
	rc = frs_map_load(argv[1], (uint32_t)strtoul(argv[2], NULL, 10),
	    (uint32_t)strtoul(argv[3], NULL, 10), &map, &w, &h, &err);
	if (rc != FRS_OK) {
		fprintf(stderr, "user_mapload: %s\n", err.message);
		return 1;
	}
	frs_map_free(map);
	return 0;
}
