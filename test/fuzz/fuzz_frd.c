/* libFuzzer target: .frd threshold matrices (frd_read), and the foreign
 * forms that frd-prep --import reads (text, raw32). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "formats/frdio.h"
#include "frd-prep/frdimport.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *path = fuzz_file(data, size);
	struct frs_matrix m;

	if (frd_read(path, &m) == 0) {
		(void)frd_check_permutation(&m, "fuzz");
		(void)frd_checksum(&m);
		frd_free(&m);
	}
	frs_clearerr();
	if (size <= 4096) {
		if (frd_import_text(path, (int)(size & 1), &m) == 0)
			frd_free(&m);
		frs_clearerr();
		if (frd_import_raw32(path, 0, 0, 1, &m) == 0)
			frd_free(&m);
		frs_clearerr();
	}
	return 0;
}
