#define _POSIX_C_SOURCE 200809L
#include "maps/pngio.h"
#include "maps/imap.h"
#include "base/err.h"
#include "base/mem.h"

#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

/* libpng reports errors through a callback and longjmp; keep its message
 * so that ours can carry it. */
struct pngctx {
	const unsigned char *buf;
	size_t len, pos;
	char msg[256];
	char warning[256];	/* libpng explains some errors only here */
	int ours;		/* the error is ours (e.g. the memory ceiling) */
};

static void on_error(png_structp png, png_const_charp msg)
{
	struct pngctx *c = png_get_error_ptr(png);
	if (c->warning[0])
		snprintf(c->msg, sizeof c->msg, "%s (%.120s)", msg, c->warning);
	else
		snprintf(c->msg, sizeof c->msg, "%s", msg);
	png_longjmp(png, 1);
}

/* Leave libpng with our own error (already recorded), not a PNG fault. */
static void our_error(png_structp png)
{
	struct pngctx *c = png_get_error_ptr(png);
	c->ours = 1;
	png_error(png, frs_errmsg());
}

static void on_warning(png_structp png, png_const_charp msg)
{
	struct pngctx *c = png_get_error_ptr(png);
	if (!c->warning[0])
		snprintf(c->warning, sizeof c->warning, "%s", msg);
}

static void read_mem(png_structp png, png_bytep out, size_t n)
{
	struct pngctx *c = png_get_io_ptr(png);
	if (n > c->len - c->pos)
		png_error(png, "truncated file");
	memcpy(out, c->buf + c->pos, n);
	c->pos += n;
}

static double srgb_to_linear(double v)
{
	return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

/* Convert decoded rows (1 or 3 channels, 8 or 16 bit) to luminance. */
static void rows_to_map(png_bytep *rows, int channels, int depth, int srgb,
    struct frs_imap *m)
{
	double maxval = depth == 16 ? 65535.0 : 255.0;

	for (uint32_t y = 0; y < m->h; y++) {
		const png_byte *r = rows[y];
		for (uint32_t x = 0; x < m->w; x++) {
			double c[3];
			for (int k = 0; k < channels; k++) {
				size_t at = ((size_t)x * (size_t)channels +
				    (size_t)k) * (depth == 16 ? 2 : 1);
				double v = depth == 16 ? (r[at] << 8 | r[at + 1]) :
				    r[at];
				v /= maxval;
				c[k] = srgb ? srgb_to_linear(v) : v;
			}
			m->v[(size_t)y * m->w + x] = channels == 1 ? c[0] :
			    imap_luma(c[0], c[1], c[2]);
		}
	}
}

int imap_read_png_mem(const unsigned char *buf, size_t len, const char *name,
    int srgb, struct frs_imap *m)
{
	struct pngctx ctx = { buf, len, 0, "", "", 0 };
	png_structp png;
	png_infop info = NULL;
	png_bytep *volatile rows = NULL;
	png_bytep volatile data = NULL;
	png_uint_32 w, h;
	int depth, ctype, channels;

	memset(m, 0, sizeof *m);
	png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error,
	    on_warning);
	if (png == NULL || (info = png_create_info_struct(png)) == NULL) {
		png_destroy_read_struct(&png, NULL, NULL);
		return frs_fail("%s: out of memory", name);
	}
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_read_struct(&png, &info, NULL);
		free(rows);
		free(data);
		imap_free(m);
		return frs_fail(ctx.ours ? "%s: %s" : "%s: bad PNG: %s", name,
		    ctx.msg);
	}
	png_set_read_fn(png, &ctx, read_mem);
	/* Our own limits, checked before any allocation. */
	png_set_user_limits(png, FRS_MAP_MAX_SIDE, FRS_MAP_MAX_SIDE);
	png_read_info(png, info);
	png_get_IHDR(png, info, &w, &h, &depth, &ctype, NULL, NULL, NULL);
	if ((uint64_t)w * h > FRS_MAP_MAX_PIXELS)
		png_error(png, "image too large");
	if (ctype == PNG_COLOR_TYPE_PALETTE)
		png_set_palette_to_rgb(png);
	if (ctype == PNG_COLOR_TYPE_GRAY && depth < 8)
		png_set_expand_gray_1_2_4_to_8(png);
	/* Alpha, including palette or grey transparency that the expansion
	 * above turns into alpha, is not importance. */
	if ((ctype & PNG_COLOR_MASK_ALPHA) ||
	    png_get_valid(png, info, PNG_INFO_tRNS))
		png_set_strip_alpha(png);
	png_set_interlace_handling(png);
	png_read_update_info(png, info);
	channels = png_get_channels(png, info);
	depth = png_get_bit_depth(png, info);
	if (channels != 1 && channels != 3)
		png_error(png, "unexpected channel layout");
	if (imap_alloc(m, w, h) < 0)
		our_error(png);
	if (mem_check("decoded image", png_get_rowbytes(png, info), h) < 0)
		our_error(png);
	data = malloc(png_get_rowbytes(png, info) * h);
	rows = malloc(h * sizeof *rows);
	if (data == NULL || rows == NULL)
		png_error(png, "out of memory");
	for (png_uint_32 y = 0; y < h; y++)
		rows[y] = data + (size_t)y * png_get_rowbytes(png, info);
	png_read_image(png, rows);
	png_read_end(png, NULL);
	rows_to_map(rows, channels, depth, srgb, m);
	png_destroy_read_struct(&png, &info, NULL);
	free(rows);
	free(data);
	return 0;
}

int pngio_write(FILE *fp, const char *name, uint32_t w, uint32_t h,
    int depth, int channels, pngio_row_fn row, const void *rctx)
{
	struct pngctx ctx = { NULL, 0, 0, "", "", 0 };
	png_structp png;
	png_infop info = NULL;
	png_bytep volatile buf = NULL;

	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error,
	    on_warning);
	if (png == NULL || (info = png_create_info_struct(png)) == NULL) {
		png_destroy_write_struct(&png, NULL);
		return frs_fail("%s: out of memory", name);
	}
	errno = 0;
	if (setjmp(png_jmpbuf(png))) {
		/* A failed write reaches us as libpng's bare "Write Error":
		 * the reason (a full disk, a closed pipe) is in errno. */
		int saved = errno;

		png_destroy_write_struct(&png, &info);
		free(buf);
		if (ferror(fp)) {
			errno = saved;
			return frs_fail_errno("%s: write error", name);
		}
		return frs_fail("%s: cannot write PNG: %s", name, ctx.msg);
	}
	png_init_io(png, fp);
	png_set_IHDR(png, info, w, h, depth, channels == 1 ?
	    PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
	    PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	buf = malloc((size_t)w * (size_t)channels * (depth == 16 ? 2 : 1));
	if (buf == NULL)
		png_error(png, "out of memory");
	for (uint32_t y = 0; y < h; y++)
		png_write_row(png, row(rctx, y, buf));
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	free(buf);
	if (ferror(fp))
		return frs_fail_errno("%s: write error", name);
	return 0;
}

struct grey16 {
	const struct frs_imap *m;
	double maxv;
};

/* Row y of 16-bit grey, scaled so that the maximum is 65535. */
static const unsigned char *grey16_row(const void *ctx, uint32_t y,
    unsigned char *row)
{
	const struct grey16 *g = ctx;
	const struct frs_imap *m = g->m;

	for (uint32_t x = 0; x < m->w; x++) {
		double v = m->v[(size_t)y * m->w + x];
		unsigned q = g->maxv > 0.0 && v > 0.0 ?
		    (unsigned)lround(v / g->maxv * 65535.0) : 0;
		row[2 * x] = (unsigned char)(q >> 8);
		row[2 * x + 1] = (unsigned char)q;
	}
	return row;
}

static double max_value(const struct frs_imap *m)
{
	double maxv = 0.0;

	for (size_t i = 0; i < (size_t)m->w * m->h; i++)
		if (m->v[i] > maxv)
			maxv = m->v[i];
	return maxv;
}

int imap_write_png16(FILE *fp, const char *name, const struct frs_imap *m)
{
	struct grey16 g = { m, max_value(m) };

	return pngio_write(fp, name, m->w, m->h, 16, 1, grey16_row, &g);
}
