/* libFuzzer target: .frp prepared matrices (frp_read, frp_info). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "frdio.h"
#include "frscore.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *path = fuzz_file(data, size);
	struct frs_matrix m;
	struct frs_prep p;
	uint32_t w, h;
	uint64_t sum;

	(void)frp_is(path);
	(void)frp_info(path, &w, &h, &sum);
	frs_clearerr();
	/* Without sorted lists, then asking for the block size 2. */
	for (uint32_t block = 0; block <= 2; block += 2) {
		if (frp_read(path, &m, &p, block) == 0) {
			frs_prep_free(&p);
			frd_free(&m);
		}
		frs_clearerr();
	}
	return 0;
}
