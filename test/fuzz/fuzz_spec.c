/* libFuzzer target: procedural importance specs ("blob:sigma=0.1"), the
 * input as a NUL-terminated string evaluated at 16 x 16, and as a volume
 * spec ("blob3:z=0.2") at 6 x 6 x 6. */
#define _POSIX_C_SOURCE 200809L
#include <string.h>

#include "fuzz.h"
#include "maps/imap.h"
#include "maps/vol.h"
#include "maps/spec.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct frs_imap m;
	char *s;

	if (size > 4096)
		return 0;
	fuzz_init();
	s = malloc(size + 1);
	if (s == NULL)
		return 0;
	memcpy(s, data, size);
	s[size] = '\0';
	(void)imap_is_spec(s);
	/* imap_spec itself: imap_load_raw would open a file of that name. */
	if (imap_spec(s, 16, 16, &m) == 0) {
		struct frs_imap_stats st;
		imap_stats(&m, &st);
		imap_free(&m);
	}
	frs_clearerr();
	(void)vol_is_spec(s);
	{
		struct frs_vol v;
		if (vol_spec(s, 6, 6, 6, &v) == 0) {
			(void)vol_validate(&v, "fuzz", FRS_MAP_ALLOW_ZERO);
			vol_free(&v);
		}
	}
	frs_clearerr();
	free(s);
	return 0;
}
