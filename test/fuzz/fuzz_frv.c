/* libFuzzer target: .frv importance volumes (vol_read), then the checks
 * a sampler makes of their values (vol_validate). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "maps/vol.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *path = fuzz_file(data, size);
	struct frs_vol v;

	(void)vol_is_file(path);
	if (vol_read(path, &v) == 0) {
		(void)vol_validate(&v, "fuzz", 0);
		vol_free(&v);
	}
	frs_clearerr();
	return 0;
}
