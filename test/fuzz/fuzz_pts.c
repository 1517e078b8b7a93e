/* libFuzzer target: .pts point files, binary and text (pts_read, and the
 * streaming reader). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "cli/ptsio.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *path = fuzz_file(data, size);
	struct frs_points p;
	struct pts_reader r;
	double rec[2 * PTS_MAXCOLS];

	if (pts_read(path, &p) == 0)
		pts_free(&p);
	frs_clearerr();
	if (pts_reader_open(&r, path) == 0) {
		while (pts_reader_next(&r, rec) > 0)
			;
		pts_reader_close(&r);
	}
	frs_clearerr();
	return 0;
}
