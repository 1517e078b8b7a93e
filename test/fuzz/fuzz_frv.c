/* libFuzzer target: .frv importance volumes (vol_read), then the checks
 * a sampler makes of their values (vol_validate); and the same bytes
 * read as frs-sample reads a map without a matrix (map_or_vol_load: a
 * peek at the magic, then a volume or an image from one open). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "maps/mapload.h"
#include "maps/vol.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *path = fuzz_file(data, size);
	const uint32_t own[3] = { 0, 0, 0 };
	struct frs_imap m;
	struct frs_vol v;
	int dims;

	(void)vol_is_file(path);
	if (vol_read(path, &v) == 0) {
		(void)vol_validate(&v, "fuzz", 0);
		vol_free(&v);
	}
	dims = map_or_vol_load(path, 0, own, 0, &m, NULL, &v);
	if (dims == 2)
		imap_free(&m);
	else if (dims == 3)
		vol_free(&v);
	frs_clearerr();
	return 0;
}
