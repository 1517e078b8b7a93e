/* libFuzzer target: PNG importance maps (imap_read_png_mem).  The
 * chunks' CRCs are recomputed first, so that mutated inputs get past
 * libpng's CRC check into the decoder and our conversion. */
#define _POSIX_C_SOURCE 200809L
#include <string.h>

#include "fuzz.h"
#include "maps/imap.h"
#include "maps/pngio.h"

static uint32_t crc_table[256];

static void crc_init(void)
{
	for (uint32_t n = 0; n < 256; n++) {
		uint32_t c = n;
		for (int k = 0; k < 8; k++)
			c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
		crc_table[n] = c;
	}
}

static uint32_t crc32_of(const unsigned char *p, size_t n)
{
	uint32_t c = 0xffffffffu;
	for (size_t i = 0; i < n; i++)
		c = crc_table[(c ^ p[i]) & 0xff] ^ (c >> 8);
	return c ^ 0xffffffffu;
}

/* Rewrite the CRC of every whole chunk after the signature. */
static void fix_crcs(unsigned char *b, size_t size)
{
	size_t pos = 8;

	while (size >= 12 && pos <= size - 12) {
		size_t len = (size_t)b[pos] << 24 | (size_t)b[pos + 1] << 16 |
		    (size_t)b[pos + 2] << 8 | b[pos + 3];
		if (len > size - 12 - pos)
			break;
		uint32_t c = crc32_of(b + pos + 4, len + 4);
		unsigned char *q = b + pos + 8 + len;
		q[0] = (unsigned char)(c >> 24);
		q[1] = (unsigned char)(c >> 16);
		q[2] = (unsigned char)(c >> 8);
		q[3] = (unsigned char)c;
		pos += len + 12;
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct frs_imap m;
	unsigned char *b;

	fuzz_init();
	if (crc_table[1] == 0)
		crc_init();
	b = malloc(size ? size : 1);
	if (b == NULL)
		return 0;
	if (size > 0)
		memcpy(b, data, size);
	fix_crcs(b, size);
	if (imap_read_png_mem(b, size, "fuzz", 0, &m) == 0) {
		imap_free(&m);
		if (imap_read_png_mem(b, size, "fuzz", 1, &m) == 0)
			imap_free(&m);
	}
	frs_clearerr();
	free(b);
	return 0;
}
