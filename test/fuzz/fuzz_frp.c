/* libFuzzer target: .frp prepared matrices (frp_read, frp_info,
 * frp_check_fp). */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"
#include "formats/frdio.h"
#include "sample/frscore.h"
#include "sample/frpio.h"

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
	/* All of it, as frd-prep --check reads it. */
	{
		FILE *fp = fopen(path, "rb");
		struct frp_summary s;
		if (fp != NULL) {
			(void)frp_check_fp(fp, path, NULL, 0, &s);
			fclose(fp);
		}
		frs_clearerr();
	}
	return 0;
}
