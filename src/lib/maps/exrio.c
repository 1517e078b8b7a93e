/*
 * OpenEXR reading and writing through the OpenEXR 3.1 C API (OpenEXRCore).
 *
 * Reading works on a file already in memory.  Only the first part is
 * used; scanline and tiled parts (level 0 of tiled ones) with any
 * compression the library knows (OpenEXRCore 3.1 knows all but DWAA and
 * DWAB, which go through the C++ library: core_lacks_codec below).
 * The channels that make the map are
 * found by name ("Y", else "R", "G" and "B" as Rec. 709 luminance) and
 * decoded one at a time, each in its own type, into planar buffers; we
 * convert to double ourselves.  Why so cautious: the unpacking fast paths
 * of OpenEXRCore 3.1 go wrong for us.  Interleaved RGBA has been seen to
 * mis-order channels, and a half channel decoded to float while its
 * neighbours are skipped makes OpenEXRCore 3.1.5 write through the
 * skipped channels' NULL pointers (unpack_half_to_float_3chan_planar).
 * Without a type change, and with fewer channels filled than the part
 * has, the library takes its generic unpacker.
 *
 * Writing builds the whole file in memory, because the library writes at
 * offsets (the chunk offset table last) and the output may be a pipe.
 */
#include "maps/exrio.h"
#include "maps/imap.h"
#include "base/err.h"
#include "base/mem.h"
#include "maps/exrcxx.h"

#include <OpenEXRConfig.h>
#include <openexr.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A message the library reported; first member of the stream state so
 * that the error handler can find it through the context's user data. */
struct lib_msg {
	char text[256];
};

/* The error handler keeps the message for frs_fail instead of letting
 * the library print it.  Only the first one after the text was cleared:
 * a failure is reported at each level it passes ("DWA/B decompression
 * not yet implemented", then "Unable to decompress", then "Decode
 * pipeline unable to decompress data") and the first is the cause. */
static void on_error(exr_const_context_t ctxt, exr_result_t code,
    const char *msg)
{
	void *ud = NULL;
	struct lib_msg *lm;

	if (exr_get_user_data(ctxt, &ud) != EXR_ERR_SUCCESS || ud == NULL)
		return;
	lm = ud;
	if (lm->text[0] != '\0')
		return;
	snprintf(lm->text, sizeof lm->text, "%s",
	    msg != NULL ? msg : exr_get_default_error_message(code));
}

/* "name: what: detail", the detail being the library's own message when
 * it gave one; a missing feature names the library's version. */
static int lib_fail(const char *name, const struct lib_msg *lm,
    exr_result_t rv, const char *what)
{
	const char *detail = lm->text[0] != '\0' ? lm->text :
	    exr_get_default_error_message(rv);
	int maj = 0, min = 0, patch = 0;
	const char *extra = NULL;

	if (rv != EXR_ERR_FEATURE_NOT_IMPLEMENTED)
		return frs_fail("%s: %s: %s", name, what, detail);
	exr_get_library_version(&maj, &min, &patch, &extra);
	return frs_fail("%s: %s: %s (OpenEXRCore %d.%d.%d)", name, what,
	    detail, maj, min, patch);
}

/* ---------------------------------------------------------------- */
/* Reading */

struct mem_src {
	struct lib_msg msg;	/* must stay first, see on_error */
	const unsigned char *buf;
	size_t len;
};

/* pread-like: a short count past the end lets the library report the
 * truncation itself. */
static int64_t src_read(exr_const_context_t ctxt, void *ud, void *buffer,
    uint64_t sz, uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
	const struct mem_src *src = ud;
	uint64_t n;

	(void)ctxt;
	(void)error_cb;
	if (offset >= src->len)
		return 0;
	n = src->len - offset;
	if (n > sz)
		n = sz;
	memcpy(buffer, src->buf + offset, (size_t)n);
	return (int64_t)n;
}

static int64_t src_size(exr_const_context_t ctxt, void *ud)
{
	const struct mem_src *src = ud;

	(void)ctxt;
	return (int64_t)src->len;
}

/* The channels the map is made of: "Y" alone or "R", "G", "B". */
#define MAX_WANT 3

struct reader {
	exr_context_t ctxt;
	struct mem_src src;
	const char *name;
	exr_attr_box2i_t dw;
	uint32_t w, h;
	int nwant;
	const char *want[MAX_WANT];
	exr_pixel_type_t type[MAX_WANT];	/* decoded as stored */
	unsigned char *plane[MAX_WANT];	/* one chunk, room for 4 bytes a sample */
	size_t plane_cap;	/* samples each plane holds */
	exr_decode_pipeline_t dec;
	int dec_ready;
};

static const exr_attr_chlist_entry_t *find_channel(
    const exr_attr_chlist_t *cl, const char *want)
{
	for (int i = 0; i < cl->num_channels; i++)
		if (strcmp(cl->entries[i].name.str, want) == 0)
			return &cl->entries[i];
	return NULL;
}

/* "A, Z, ..." into buf, for the message when nothing fits. */
static void list_channels(const exr_attr_chlist_t *cl, char *buf, size_t n)
{
	size_t used = 0;

	buf[0] = '\0';
	for (int i = 0; i < cl->num_channels && used + 1 < n; i++) {
		int k = snprintf(buf + used, n - used, "%s%s", i ? ", " : "",
		    cl->entries[i].name.str);
		if (k < 0)
			break;
		used += (size_t)k;
	}
	if (cl->num_channels == 0)
		snprintf(buf, n, "none");
	else if (used + 1 >= n && n > 4)
		memcpy(buf + n - 4, "...", 4);
}

/* Pick Y, else R, G, B, by name; the others are left undecoded. */
static int choose_channels(struct reader *r)
{
	static const char *const rgb[MAX_WANT] = { "R", "G", "B" };
	const exr_attr_chlist_entry_t *e[MAX_WANT];
	const exr_attr_chlist_t *cl = NULL;
	exr_result_t rv;
	char names[200];

	rv = exr_get_channels(r->ctxt, 0, &cl);
	if (rv != EXR_ERR_SUCCESS || cl == NULL)
		return lib_fail(r->name, &r->src.msg, rv, "no channel list");
	if ((e[0] = find_channel(cl, "Y")) != NULL) {
		r->nwant = 1;
		r->want[0] = "Y";
	} else {
		for (int k = 0; k < MAX_WANT; k++)
			e[k] = find_channel(cl, rgb[k]);
		if (e[0] == NULL || e[1] == NULL || e[2] == NULL) {
			list_channels(cl, names, sizeof names);
			return frs_fail("%s: no usable channel (need Y or R, G, "
			    "B; file has %s)", r->name, names);
		}
		r->nwant = MAX_WANT;
		for (int k = 0; k < MAX_WANT; k++)
			r->want[k] = rgb[k];
	}
	for (int k = 0; k < r->nwant; k++) {
		if (e[k]->x_sampling != 1 || e[k]->y_sampling != 1)
			return frs_fail("%s: channel %s is subsampled (%dx%d), "
			    "which is not supported", r->name, r->want[k],
			    e[k]->x_sampling, e[k]->y_sampling);
		r->type[k] = e[k]->pixel_type;
	}
	return 0;
}

/* The map is the data window, row 0 its top (min.y) row. */
static int read_size(struct reader *r)
{
	int64_t w, h;
	exr_result_t rv = exr_get_data_window(r->ctxt, 0, &r->dw);

	if (rv != EXR_ERR_SUCCESS)
		return lib_fail(r->name, &r->src.msg, rv, "no data window");
	w = (int64_t)r->dw.max.x - r->dw.min.x + 1;
	h = (int64_t)r->dw.max.y - r->dw.min.y + 1;
	if (w <= 0 || h <= 0)
		return frs_fail("%s: empty data window (%lld x %lld)", r->name,
		    (long long)w, (long long)h);
	if (w > FRS_MAP_MAX_SIDE || h > FRS_MAP_MAX_SIDE ||
	    (uint64_t)w * (uint64_t)h > FRS_MAP_MAX_PIXELS)
		return frs_fail("%s: image of %lld x %lld is too large (at "
		    "most %u on a side and %llu pixels)", r->name,
		    (long long)w, (long long)h, FRS_MAP_MAX_SIDE,
		    (unsigned long long)FRS_MAP_MAX_PIXELS);
	r->w = (uint32_t)w;
	r->h = (uint32_t)h;
	return 0;
}

/* Room for the largest chunk: cw x ch samples in each wanted plane. */
static int alloc_planes(struct reader *r, uint64_t cw, uint64_t ch)
{
	uint64_t n = cw * ch;

	r->plane_cap = (size_t)n;
	for (int k = 0; k < r->nwant; k++) {
		r->plane[k] = mem_calloc("image chunk", n, 4);
		if (r->plane[k] == NULL)
			return frs_fail_context(r->name);
	}
	return 0;
}

/* Set up (first chunk) or re-target (later chunks) the decoder. */
static int prepare_decoder(struct reader *r, const exr_chunk_info_t *ci)
{
	exr_result_t rv;

	r->src.msg.text[0] = '\0';
	if (!r->dec_ready) {
		/* Destroy even after a failed start: it may have allocated. */
		r->dec_ready = 1;
		rv = exr_decoding_initialize(r->ctxt, 0, ci, &r->dec);
	} else {
		rv = exr_decoding_update(r->ctxt, 0, ci, &r->dec);
	}
	if (rv != EXR_ERR_SUCCESS)
		return lib_fail(r->name, &r->src.msg, rv, "cannot decode");
	return 0;
}

/* Decode channel want[k] alone into plane k, in the type it is stored
 * in.  Every other channel gets a NULL pointer (skipped) and its own type
 * back, so that no channel asks for a conversion. */
static int decode_channel(struct reader *r, int k, int32_t cw, int32_t ch)
{
	exr_coding_channel_info_t *c = NULL;
	exr_result_t rv;

	for (int i = 0; i < r->dec.channel_count; i++) {
		exr_coding_channel_info_t *d = &r->dec.channels[i];
		d->decode_to_ptr = NULL;
		d->user_data_type = d->data_type;
		d->user_bytes_per_element = d->bytes_per_element;
		d->user_pixel_stride = d->bytes_per_element;
		d->user_line_stride = d->bytes_per_element * d->width;
		if (strcmp(d->channel_name, r->want[k]) == 0)
			c = d;
	}
	if (c == NULL || c->width != cw || c->height != ch ||
	    c->data_type != (uint16_t)r->type[k])
		return frs_fail("%s: chunk of channel %s does not match the "
		    "header", r->name, r->want[k]);
	c->decode_to_ptr = r->plane[k];
	/* The unpacking routine depends on the pointers: choose again. */
	rv = exr_decoding_choose_default_routines(r->ctxt, 0, &r->dec);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_decoding_run(r->ctxt, 0, &r->dec);
	if (rv != EXR_ERR_SUCCESS)
		return lib_fail(r->name, &r->src.msg, rv, "cannot decode");
	return 0;
}

/* IEEE half (binary16) to double: normal, subnormal, zero, inf, NaN. */
static double half_to_double(uint16_t h)
{
	int exp = (h >> 10) & 0x1f;
	double man = h & 0x3ff;
	double v;

	if (exp == 0)
		v = ldexp(man, -24);
	else if (exp == 31)
		v = man == 0 ? HUGE_VAL : NAN;
	else
		v = ldexp(1024 + man, exp - 25);
	return (h & 0x8000) ? -v : v;
}

static double sample(const unsigned char *plane, size_t i,
    exr_pixel_type_t type)
{
	if (type == EXR_PIXEL_HALF) {
		uint16_t h;
		memcpy(&h, plane + 2 * i, 2);
		return half_to_double(h);
	} else if (type == EXR_PIXEL_UINT) {
		uint32_t u;
		memcpy(&u, plane + 4 * i, 4);
		return (double)u;
	} else {
		float f;
		memcpy(&f, plane + 4 * i, 4);
		return (double)f;
	}
}

/* Chunk planes -> map rectangle at (x0, y0), cw x ch. */
static void store_chunk(struct reader *r, struct frs_imap *m, uint32_t x0,
    uint32_t y0, uint32_t cw, uint32_t ch)
{
	for (uint32_t j = 0; j < ch; j++) {
		double *row = m->v + (size_t)(y0 + j) * m->w + x0;
		for (uint32_t i = 0; i < cw; i++) {
			size_t s = (size_t)j * cw + i;
			double v[MAX_WANT];
			for (int k = 0; k < r->nwant; k++)
				v[k] = sample(r->plane[k], s, r->type[k]);
			row[i] = r->nwant == 1 ? v[0] :
			    imap_luma(v[0], v[1], v[2]);
		}
	}
}

/* One chunk at map position (x0, y0): check its geometry against the map
 * (hostile files must not write outside), decode, store. */
static int read_chunk(struct reader *r, struct frs_imap *m,
    const exr_chunk_info_t *ci, int64_t x0, int64_t y0)
{
	int64_t cw = ci->width, ch = ci->height;

	if (cw <= 0 || ch <= 0 || x0 < 0 || y0 < 0 || x0 + cw > r->w ||
	    y0 + ch > r->h || (uint64_t)(cw * ch) > r->plane_cap)
		return frs_fail("%s: chunk %d (%lld x %lld at %lld, %lld) lies "
		    "outside the data window", r->name, ci->idx, (long long)cw,
		    (long long)ch, (long long)x0, (long long)y0);
	if (prepare_decoder(r, ci) != 0)
		return -1;
	for (int k = 0; k < r->nwant; k++)
		if (decode_channel(r, k, (int32_t)cw, (int32_t)ch) != 0)
			return -1;
	store_chunk(r, m, (uint32_t)x0, (uint32_t)y0, (uint32_t)cw,
	    (uint32_t)ch);
	return 0;
}

static int read_scanlines(struct reader *r, struct frs_imap *m)
{
	int32_t lines = 0;
	exr_result_t rv = exr_get_scanlines_per_chunk(r->ctxt, 0, &lines);

	if (rv != EXR_ERR_SUCCESS || lines <= 0)
		return lib_fail(r->name, &r->src.msg, rv,
		    "no scanlines per chunk");
	if (alloc_planes(r, r->w, (uint64_t)lines < r->h ?
	    (uint64_t)lines : r->h) != 0)
		return -1;
	for (int64_t y = 0; y < r->h; y += lines) {
		exr_chunk_info_t ci;
		r->src.msg.text[0] = '\0';
		rv = exr_read_scanline_chunk_info(r->ctxt, 0,
		    (int)(r->dw.min.y + y), &ci);
		if (rv != EXR_ERR_SUCCESS)
			return lib_fail(r->name, &r->src.msg, rv,
			    "cannot read scanlines");
		if (read_chunk(r, m, &ci, 0,
		    (int64_t)ci.start_y - r->dw.min.y) != 0)
			return -1;
	}
	return 0;
}

/* Level 0 (mip level (0, 0)) tiles only: that is the full image. */
static int read_tiles(struct reader *r, struct frs_imap *m)
{
	uint32_t tx, ty;
	exr_tile_level_mode_t mode;
	exr_tile_round_mode_t round;
	exr_result_t rv;
	uint64_t ntx, nty;

	rv = exr_get_tile_descriptor(r->ctxt, 0, &tx, &ty, &mode, &round);
	if (rv != EXR_ERR_SUCCESS || tx == 0 || ty == 0)
		return lib_fail(r->name, &r->src.msg, rv, "no tile description");
	ntx = (r->w + (uint64_t)tx - 1) / tx;
	nty = (r->h + (uint64_t)ty - 1) / ty;
	if (alloc_planes(r, tx < r->w ? tx : r->w, ty < r->h ? ty : r->h) != 0)
		return -1;
	for (uint64_t j = 0; j < nty; j++) {
		for (uint64_t i = 0; i < ntx; i++) {
			exr_chunk_info_t ci;
			r->src.msg.text[0] = '\0';
			rv = exr_read_tile_chunk_info(r->ctxt, 0, (int)i,
			    (int)j, 0, 0, &ci);
			if (rv != EXR_ERR_SUCCESS)
				return lib_fail(r->name, &r->src.msg, rv,
				    "cannot read tiles");
			if (read_chunk(r, m, &ci, (int64_t)(i * tx),
			    (int64_t)(j * ty)) != 0)
				return -1;
		}
	}
	return 0;
}

static int read_first_part(struct reader *r, struct frs_imap *m)
{
	exr_storage_t storage;
	exr_result_t rv = exr_get_storage(r->ctxt, 0, &storage);

	if (rv != EXR_ERR_SUCCESS)
		return lib_fail(r->name, &r->src.msg, rv, "no storage type");
	if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
		return frs_fail("%s: deep data is not supported", r->name);
	if (read_size(r) != 0 || choose_channels(r) != 0)
		return -1;
	if (imap_alloc(m, r->w, r->h) != 0)
		return frs_fail_context(r->name);
	if (storage == EXR_STORAGE_TILED)
		return read_tiles(r, m);
	return read_scanlines(r, m);
}

static void reader_free(struct reader *r)
{
	if (r->dec_ready)
		exr_decoding_destroy(r->ctxt, &r->dec);
	for (int k = 0; k < MAX_WANT; k++)
		free(r->plane[k]);
	if (r->ctxt != NULL)
		exr_finish(&r->ctxt);
}

/*
 * OpenEXRCore before 3.2 has no DWAA/DWAB decompressor, and lossy DWA is
 * what real HDR environment maps use; those parts go through the C++
 * library instead (exrcxx.cc), which reads them the same way: float
 * planes, channels by name.
 */
static int core_lacks_codec(struct reader *r)
{
	exr_compression_t c;

	if (exr_get_compression(r->ctxt, 0, &c) != EXR_ERR_SUCCESS)
		return 0;
#if OPENEXR_VERSION_MAJOR < 3 || \
    (OPENEXR_VERSION_MAJOR == 3 && OPENEXR_VERSION_MINOR < 2)
	return c == EXR_COMPRESSION_DWAA || c == EXR_COMPRESSION_DWAB;
#else
	(void)c;
	return 0;
#endif
}

int imap_read_exr_mem(const unsigned char *buf, size_t len, const char *name,
    struct frs_imap *m)
{
	static const unsigned char magic[4] = { 0x76, 0x2f, 0x31, 0x01 };
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	struct reader r;
	exr_result_t rv;
	int rc;

	memset(m, 0, sizeof *m);
	if (len < sizeof magic || memcmp(buf, magic, sizeof magic) != 0)
		return frs_fail("%s: not an OpenEXR file", name);
	memset(&r, 0, sizeof r);
	r.name = name;
	r.src.buf = buf;
	r.src.len = len;
	init.size = sizeof init;
	init.error_handler_fn = on_error;
	init.user_data = &r.src;
	init.read_fn = src_read;
	init.size_fn = src_size;
	rv = exr_start_read(&r.ctxt, name, &init);
	if (rv != EXR_ERR_SUCCESS) {
		rc = lib_fail(name, &r.src.msg, rv, "cannot read header");
		reader_free(&r);
		return rc;
	}
	if (core_lacks_codec(&r)) {
		reader_free(&r);
		return exr_cxx_read(buf, len, name, m);
	}
	rc = read_first_part(&r, m);
	reader_free(&r);
	if (rc != 0)
		imap_free(m);
	return rc;
}

/* ---------------------------------------------------------------- */
/* Writing */

struct mem_sink {
	struct lib_msg msg;	/* must stay first, see on_error */
	unsigned char *data;
	size_t len, cap;
};

static int sink_grow(struct mem_sink *s, size_t need)
{
	size_t cap = s->cap ? s->cap : 4096;
	unsigned char *p;

	while (cap < need)
		cap = cap > SIZE_MAX / 2 ? need : cap * 2;
	p = realloc(s->data, cap);
	if (p == NULL)
		return -1;
	s->data = p;
	s->cap = cap;
	return 0;
}

/* pwrite-like into the memory buffer; a gap left by a later offset is
 * zeroed (the library fills it in afterwards). */
static int64_t sink_write(exr_const_context_t ctxt, void *ud,
    const void *buffer, uint64_t sz, uint64_t offset,
    exr_stream_error_func_ptr_t error_cb)
{
	struct mem_sink *s = ud;
	size_t end;

	if (offset > SIZE_MAX || sz > SIZE_MAX - offset || sz > INT64_MAX) {
		error_cb(ctxt, EXR_ERR_WRITE_IO, "write past the addressable "
		    "size");
		return -1;
	}
	end = (size_t)(offset + sz);
	if (end > s->cap && sink_grow(s, end) != 0) {
		error_cb(ctxt, EXR_ERR_OUT_OF_MEMORY, "out of memory for "
		    "%zu bytes of output", end);
		return -1;
	}
	if (offset > s->len)
		memset(s->data + s->len, 0, (size_t)offset - s->len);
	if (sz > 0)
		memcpy(s->data + offset, buffer, (size_t)sz);
	if (end > s->len)
		s->len = end;
	return (int64_t)sz;
}

/* Header: one scanline part, float channel "Y", data window = display
 * window = (0, 0) - (w - 1, h - 1). */
static int write_header(exr_context_t ctxt, struct mem_sink *s,
    const char *name, const struct frs_imap *m, exr_compression_t comp)
{
	int part = 0;
	exr_result_t rv = exr_add_part(ctxt, NULL, EXR_STORAGE_SCANLINE, &part);

	if (rv == EXR_ERR_SUCCESS)
		rv = exr_initialize_required_attr_simple(ctxt, part,
		    (int32_t)m->w, (int32_t)m->h, comp);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_add_channel(ctxt, part, "Y", EXR_PIXEL_FLOAT,
		    EXR_PERCEPTUALLY_LINEAR, 1, 1);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_write_header(ctxt);
	if (rv != EXR_ERR_SUCCESS)
		return lib_fail(name, &s->msg, rv, "cannot write header");
	return 0;
}

/* Rows y0 .. y0 + n - 1 of the map as float. */
static void rows_to_float(const struct frs_imap *m, uint32_t y0, uint32_t n,
    float *out)
{
	const double *in = m->v + (size_t)y0 * m->w;

	for (size_t i = 0; i < (size_t)n * m->w; i++)
		out[i] = (float)in[i];
}

static int encode_chunk(exr_context_t ctxt, exr_encode_pipeline_t *enc,
    int *ready, const exr_chunk_info_t *ci, const float *rows,
    uint32_t w)
{
	exr_result_t rv;
	exr_coding_channel_info_t *c;

	if (!*ready) {
		*ready = 1;	/* destroy even after a failed start */
		rv = exr_encoding_initialize(ctxt, 0, ci, enc);
		if (rv != EXR_ERR_SUCCESS)
			return rv;
	} else {
		rv = exr_encoding_update(ctxt, 0, ci, enc);
		if (rv != EXR_ERR_SUCCESS)
			return rv;
	}
	c = &enc->channels[0];
	c->encode_from_ptr = (const uint8_t *)rows;
	c->user_pixel_stride = 4;
	c->user_line_stride = (int32_t)(4 * w);
	c->user_bytes_per_element = 4;
	c->user_data_type = EXR_PIXEL_FLOAT;
	rv = exr_encoding_choose_default_routines(ctxt, 0, enc);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_encoding_run(ctxt, 0, enc);
	return rv;
}

static int write_pixels(exr_context_t ctxt, struct mem_sink *s,
    const char *name, const struct frs_imap *m)
{
	exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
	int32_t lines = 0;
	int ready = 0, rc = 0;
	float *rows;
	exr_result_t rv = exr_get_scanlines_per_chunk(ctxt, 0, &lines);

	if (rv != EXR_ERR_SUCCESS || lines <= 0)
		return lib_fail(name, &s->msg, rv, "no scanlines per chunk");
	rows = malloc((size_t)m->w * (size_t)lines * sizeof *rows);
	if (rows == NULL)
		return frs_fail("%s: out of memory", name);
	for (uint32_t y = 0; y < m->h && rc == 0; y += (uint32_t)lines) {
		exr_chunk_info_t ci;
		uint32_t n = m->h - y < (uint32_t)lines ? m->h - y :
		    (uint32_t)lines;
		rows_to_float(m, y, n, rows);
		rv = exr_write_scanline_chunk_info(ctxt, 0, (int)y, &ci);
		if (rv == EXR_ERR_SUCCESS)
			rv = encode_chunk(ctxt, &enc, &ready, &ci, rows, m->w);
		if (rv != EXR_ERR_SUCCESS)
			rc = lib_fail(name, &s->msg, rv, "cannot encode");
	}
	if (ready)
		exr_encoding_destroy(ctxt, &enc);
	free(rows);
	return rc;
}

/* The whole file, with the given compression, into a memory sink. */
static int encode_file(const struct frs_imap *m, const char *name,
    exr_compression_t comp, struct mem_sink *sink)
{
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	exr_context_t ctxt = NULL;
	exr_result_t rv;
	int rc;

	memset(sink, 0, sizeof *sink);
	init.size = sizeof init;
	init.error_handler_fn = on_error;
	init.user_data = sink;
	init.write_fn = sink_write;
	rv = exr_start_write(&ctxt, name, EXR_WRITE_FILE_DIRECTLY, &init);
	if (rv != EXR_ERR_SUCCESS)
		return lib_fail(name, &sink->msg, rv, "cannot start writing");
	rc = write_header(ctxt, sink, name, m, comp);
	if (rc == 0)
		rc = write_pixels(ctxt, sink, name, m);
	/* exr_finish writes the chunk offset table. */
	rv = exr_finish(&ctxt);
	if (rc == 0 && rv != EXR_ERR_SUCCESS)
		rc = lib_fail(name, &sink->msg, rv, "cannot finish");
	return rc;
}

/* 1 if the encoded file decodes to the map's float values, bit for bit. */
static int decodes_back(const struct mem_sink *sink, const char *name,
    const struct frs_imap *m)
{
	struct frs_imap back;
	int same;

	if (imap_read_exr_mem(sink->data, sink->len, name, &back) < 0)
		return 0;
	same = back.w == m->w && back.h == m->h;
	for (size_t i = 0; same && i < (size_t)m->w * m->h; i++) {
		float a = (float)m->v[i], b = (float)back.v[i];
		same = memcmp(&a, &b, sizeof a) == 0;
	}
	imap_free(&back);
	return same;
}

/*
 * The file holds floats: a finite value beyond FLT_MAX would be written as
 * infinity, a file that every reader refuses, and a map whose positive
 * values all lie below half the smallest float would be written as zero
 * everywhere.  NaN and infinity are written as they are.
 */
static int fits_float(const struct frs_imap *m, const char *name)
{
	double top = 0.0;

	for (size_t i = 0; i < (size_t)m->w * m->h; i++) {
		double v = m->v[i];
		if (isfinite(v) && fabs(v) > FLT_MAX)
			return frs_fail("%s: pixel (%zu, %zu) is %g, beyond the "
			    "largest float (%g) that OpenEXR holds", name,
			    i % m->w, i / m->w, v, (double)FLT_MAX);
		if (isfinite(v) && v > top)
			top = v;
	}
	if (top > 0.0 && (float)top == 0.0f)
		return frs_fail("%s: the largest value, %g, is below the "
		    "smallest float that OpenEXR holds: the map would be zero "
		    "everywhere", name, top);
	return 0;
}

int imap_write_exr(FILE *fp, const char *name, const struct frs_imap *m)
{
	struct mem_sink sink;
	int rc;

	if (m->w == 0 || m->h == 0 || m->w > FRS_MAP_MAX_SIDE ||
	    m->h > FRS_MAP_MAX_SIDE)
		return frs_fail("%s: cannot write a %ux%u map", name, m->w,
		    m->h);
	if (fits_float(m, name) < 0) {
		frs_set_errkind(FRS_ERRKIND_MAP);	/* the values */
		return -1;
	}
	/* The ZIP encoder of OpenEXRCore 3.1.5 corrupts some chunks (a
	 * 128x128 Gaussian blob reads back with NaNs), so every file is
	 * decoded again, and written uncompressed if it does not match. */
	rc = encode_file(m, name, EXR_COMPRESSION_ZIP, &sink);
	if (rc == 0 && !decodes_back(&sink, name, m)) {
		free(sink.data);
		rc = encode_file(m, name, EXR_COMPRESSION_NONE, &sink);
		if (rc == 0 && !decodes_back(&sink, name, m))
			rc = frs_fail("%s: the OpenEXR library wrote a file that "
			    "does not read back", name);
	}
	if (rc == 0 && (fwrite(sink.data, 1, sink.len, fp) != sink.len ||
	    fflush(fp) != 0))
		rc = frs_fail_errno("%s: write error", name);
	free(sink.data);
	return rc;
}
