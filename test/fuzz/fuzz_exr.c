/* libFuzzer target: OpenEXR importance maps through our loader
 * (imap_load_raw on a file, which detects the format by its magic). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "maps/imap.h"
#include "maps/mapload.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *path = fuzz_file(data, size);
	struct frs_imap m;

	if (imap_load_raw(path, 0, 0, 0, &m) == 0)
		imap_free(&m);
	frs_clearerr();
	return 0;
}
