/* PNG importance maps: every colour type and depth libpng can write is
 * read back to the values the test put in, by definition (v / maxval,
 * Rec. 709 luminance), and broken files are refused. */
#include "testutil.h"
#include "maps/imap.h"
#include "maps/pngio.h"

#include <png.h>

struct membuf {
	unsigned char *b;
	size_t n, cap;
};

static void mem_write(png_structp png, png_bytep data, size_t n)
{
	struct membuf *m = png_get_io_ptr(png);
	if (m->n + n > m->cap) {
		m->cap = (m->n + n) * 2;
		m->b = realloc(m->b, m->cap);
	}
	memcpy(m->b + m->n, data, n);
	m->n += n;
}

static void mem_flush(png_structp png) { (void)png; }

/* Sample s (0..maxval) of channel c at (x, y): distinct per channel. */
static unsigned sample(uint32_t x, uint32_t y, int c, unsigned maxval)
{
	return (x * 7u + y * 13u + (unsigned)c * 5u) % (maxval + 1u);
}

/* Encode a w x h image of the given type; returns the file in memory. */
static struct membuf encode(uint32_t w, uint32_t h, int ctype, int depth,
    int interlace, int with_trns)
{
	struct membuf mb = { NULL, 0, 0 };
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL,
	    NULL, NULL);
	png_infop info = png_create_info_struct(png);
	int ch = ctype == PNG_COLOR_TYPE_GRAY ? 1 :
	    ctype == PNG_COLOR_TYPE_GRAY_ALPHA ? 2 :
	    ctype == PNG_COLOR_TYPE_RGB ? 3 : ctype == PNG_COLOR_TYPE_RGBA ? 4 : 1;
	unsigned maxval = (1u << depth) - 1u;
	size_t rowbytes = ((size_t)w * (size_t)ch * (size_t)depth + 7) / 8;
	png_bytep row = calloc(rowbytes, 1);
	png_bytep *rows = calloc(h, sizeof *rows);

	assert_false(setjmp(png_jmpbuf(png)));
	png_set_write_fn(png, &mb, mem_write, mem_flush);
	png_set_IHDR(png, info, w, h, depth, ctype, interlace,
	    PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	if (ctype == PNG_COLOR_TYPE_PALETTE) {
		/* Entry k is (k, 2k, 3k) mod 256. */
		png_color pal[256];
		png_byte alpha[256];
		for (int k = 0; k < 256; k++) {
			pal[k].red = (png_byte)k;
			pal[k].green = (png_byte)(2 * k);
			pal[k].blue = (png_byte)(3 * k);
			alpha[k] = (png_byte)(255 - k);
		}
		png_set_PLTE(png, info, pal, 1 << depth);
		if (with_trns)
			png_set_tRNS(png, info, alpha, 1 << depth, NULL);
	}
	for (uint32_t y = 0; y < h; y++) {
		rows[y] = calloc(rowbytes, 1);
		for (uint32_t x = 0; x < w; x++)
			for (int c = 0; c < ch; c++) {
				unsigned s = sample(x, y, c, maxval);
				size_t bit = ((size_t)x * (size_t)ch + (size_t)c) *
				    (size_t)depth;
				if (depth == 16) {
					rows[y][bit / 8] = (png_byte)(s >> 8);
					rows[y][bit / 8 + 1] = (png_byte)s;
				} else {
					/* MSB first within a byte. */
					int shift = 8 - depth - (int)(bit % 8);
					rows[y][bit / 8] |= (png_byte)(s << shift);
				}
			}
	}
	png_write_info(png, info);
	png_write_image(png, rows);
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	for (uint32_t y = 0; y < h; y++)
		free(rows[y]);
	free(rows);
	free(row);
	return mb;
}

/* The value the reader must produce for pixel (x, y). */
static double expect(uint32_t x, uint32_t y, int ctype, int depth)
{
	double maxval = (double)((1u << depth) - 1u);
	if (ctype == PNG_COLOR_TYPE_PALETTE) {
		unsigned k = sample(x, y, 0, (1u << depth) - 1u);
		return imap_luma(k / 255.0, (2 * k % 256) / 255.0,
		    (3 * k % 256) / 255.0);
	}
	if (ctype == PNG_COLOR_TYPE_GRAY || ctype == PNG_COLOR_TYPE_GRAY_ALPHA)
		return sample(x, y, 0, (1u << depth) - 1u) / maxval;
	return imap_luma(sample(x, y, 0, (1u << depth) - 1u) / maxval,
	    sample(x, y, 1, (1u << depth) - 1u) / maxval,
	    sample(x, y, 2, (1u << depth) - 1u) / maxval);
}

static void check_type(int ctype, int depth, int interlace, int trns)
{
	const uint32_t w = 19, h = 11;	/* odd sizes exercise Adam7 */
	struct membuf mb = encode(w, h, ctype, depth, interlace, trns);
	struct frs_imap m;

	assert_int_equal(imap_read_png_mem(mb.b, mb.n, "t.png", 0, &m), 0);
	assert_int_equal(m.w, w);
	assert_int_equal(m.h, h);
	for (uint32_t y = 0; y < h; y++)
		for (uint32_t x = 0; x < w; x++)
			assert_double_equal(m.v[y * w + x],
			    expect(x, y, ctype, depth), 1e-12);
	imap_free(&m);
	free(mb.b);
}

static void grey(void **state)
{
	(void)state;
	for (int d = 1; d <= 16; d *= 2)
		check_type(PNG_COLOR_TYPE_GRAY, d, PNG_INTERLACE_NONE, 0);
	check_type(PNG_COLOR_TYPE_GRAY, 8, PNG_INTERLACE_ADAM7, 0);
	check_type(PNG_COLOR_TYPE_GRAY, 16, PNG_INTERLACE_ADAM7, 0);
	check_type(PNG_COLOR_TYPE_GRAY_ALPHA, 8, PNG_INTERLACE_NONE, 0);
	check_type(PNG_COLOR_TYPE_GRAY_ALPHA, 16, PNG_INTERLACE_NONE, 0);
}

static void colour(void **state)
{
	(void)state;
	check_type(PNG_COLOR_TYPE_RGB, 8, PNG_INTERLACE_NONE, 0);
	check_type(PNG_COLOR_TYPE_RGB, 16, PNG_INTERLACE_ADAM7, 0);
	check_type(PNG_COLOR_TYPE_RGBA, 8, PNG_INTERLACE_NONE, 0);
	check_type(PNG_COLOR_TYPE_RGBA, 16, PNG_INTERLACE_NONE, 0);
	check_type(PNG_COLOR_TYPE_PALETTE, 8, PNG_INTERLACE_NONE, 0);
	check_type(PNG_COLOR_TYPE_PALETTE, 4, PNG_INTERLACE_ADAM7, 0);
	check_type(PNG_COLOR_TYPE_PALETTE, 8, PNG_INTERLACE_NONE, 1);
}

/* sRGB decoding: 8-bit 188 is 0.50289 linear by the sRGB formula. */
static void srgb(void **state)
{
	struct membuf mb = encode(19, 11, PNG_COLOR_TYPE_GRAY, 8, 0, 0);
	struct frs_imap m;
	(void)state;

	assert_int_equal(imap_read_png_mem(mb.b, mb.n, "s.png", 1, &m), 0);
	for (uint32_t i = 0; i < 19 * 11; i++) {
		double v = sample(i % 19, i / 19, 0, 255) / 255.0;
		double lin = v <= 0.04045 ? v / 12.92 :
		    pow((v + 0.055) / 1.055, 2.4);
		assert_double_equal(m.v[i], lin, 1e-12);
	}
	imap_free(&m);
	free(mb.b);
}

/* Our 16-bit writer scales the maximum to 65535. */
static void write_read(void **state)
{
	struct frs_imap a, b;
	FILE *fp = tmpfile();
	unsigned char *buf;
	long len;
	(void)state;

	assert_int_equal(imap_alloc(&a, 5, 3), 0);
	for (int i = 0; i < 15; i++)
		a.v[i] = 2.0 * i;	/* maximum 28 */
	assert_int_equal(imap_write_png16(fp, "o.png", &a), 0);
	len = ftell(fp);
	rewind(fp);
	buf = malloc((size_t)len);
	assert_int_equal(fread(buf, 1, (size_t)len, fp), (size_t)len);
	fclose(fp);
	assert_int_equal(imap_read_png_mem(buf, (size_t)len, "o.png", 0, &b), 0);
	for (int i = 0; i < 15; i++)
		assert_double_equal(b.v[i], a.v[i] / 28.0, 0.5 / 65535.0);
	imap_free(&a);
	imap_free(&b);
	free(buf);
}

static uint32_t crc32_of(const unsigned char *p, size_t n)
{
	uint32_t c = 0xffffffffu;
	for (size_t i = 0; i < n; i++) {
		c ^= p[i];
		for (int k = 0; k < 8; k++)
			c = c & 1 ? (c >> 1) ^ 0xedb88320u : c >> 1;
	}
	return ~c;
}

static void broken(void **state)
{
	struct membuf mb = encode(19, 11, PNG_COLOR_TYPE_RGB, 8, 0, 0);
	struct frs_imap m;
	unsigned char *b = malloc(mb.n);
	uint32_t crc;
	(void)state;

	/* Cut inside the image data. */
	assert_int_equal(imap_read_png_mem(mb.b, mb.n / 2, "cut.png", 0, &m), -1);
	/* (a failed assertion leaks the buffers; no matter in a test) */
	assert_err_has("cut.png", "bad PNG");
	assert_null(m.v);
	/* Only the signature. */
	assert_int_equal(imap_read_png_mem(mb.b, 8, "sig.png", 0, &m), -1);
	assert_err_has("sig.png");
	/* Width 0 in IHDR, with a correct CRC so that only the size is
	 * wrong. */
	memcpy(b, mb.b, mb.n);
	memset(b + 16, 0, 4);
	crc = crc32_of(b + 12, 17);
	b[29] = (unsigned char)(crc >> 24);
	b[30] = (unsigned char)(crc >> 16);
	b[31] = (unsigned char)(crc >> 8);
	b[32] = (unsigned char)crc;
	assert_int_equal(imap_read_png_mem(b, mb.n, "w0.png", 0, &m), -1);
	assert_err_has("w0.png", "width");
	/* A flipped bit in the IHDR is caught by its CRC. */
	memcpy(b, mb.b, mb.n);
	b[20] ^= 1;
	assert_int_equal(imap_read_png_mem(b, mb.n, "crc.png", 0, &m), -1);
	assert_err_has("crc.png");
	free(b);
	free(mb.b);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(grey),
	cmocka_unit_test(colour),
	cmocka_unit_test(srgb),
	cmocka_unit_test(write_read),
	cmocka_unit_test(broken))
