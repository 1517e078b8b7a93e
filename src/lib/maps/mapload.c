#define _POSIX_C_SOURCE 200809L
#include "maps/mapload.h"
#include "maps/exrio.h"
#include "maps/imap.h"
#include "maps/pngio.h"
#include "maps/spec.h"
#include "maps/vol.h"
#include "base/err.h"
#include "base/io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* A PNG or OpenEXR file in memory, by its magic. */
static int decode_image(const unsigned char *buf, size_t len,
    const char *name, int flags, struct frs_imap *m)
{
	if (len == 0)
		return frs_fail("%s: empty file", name);
	if (len >= 8 && memcmp(buf, "\211PNG\r\n\032\n", 8) == 0)
		return imap_read_png_mem(buf, len, name, flags & FRS_MAP_SRGB, m);
	if (len >= 4 && memcmp(buf, "\166\057\061\001", 4) == 0)
		return imap_read_exr_mem(buf, len, name, m);
	if (len >= 8 && memcmp(buf, FRV_MAGIC, 8) == 0)
		return frs_fail("%s: a volume (.frv) where a 2-D map is needed "
		    "(volumes go with 3-D matrices)", name);
	return frs_fail("%s: not a PNG or OpenEXR file", name);
}

/* What is asked of a source (want: 2, 3, or 0 for what it is) and what
 * it was (dims). */
struct ask {
	unsigned want, dims;
	int flags;
	struct frs_imap *m;
	struct frs_vol *v;
};

int source_open(struct frs_source *s, const char *src)
{
	struct stat st;

	memset(s, 0, sizeof *s);
	s->src = src;
	if (strcmp(src, "-") != 0 && stat(src, &st) != 0) {
		/* A spec, or nothing: the missing file's errno kept for the
		 * load's last message. */
		s->stat_errno = errno;
		s->kinds = (imap_is_spec(src) ? FRS_SOURCE_MAP : 0) |
		    (vol_is_spec(src) ? FRS_SOURCE_VOLUME : 0);
		return 0;
	}
	if ((s->fp = io_open_in(src, &s->name)) == NULL)
		return -1;
	/* One open: its first bytes say whether it is a volume, and the
	 * rest is read as that. */
	s->npre = fread(s->pre, 1, sizeof s->pre, s->fp);
	if (ferror(s->fp)) {
		frs_fail_errno("%s: read error", s->name);
		frs_set_errkind(FRS_ERRKIND_IO);
		source_close(s);
		return -1;
	}
	s->frv = s->npre == sizeof s->pre && memcmp(s->pre, FRV_MAGIC, 8) == 0;
	s->kinds = s->frv ? FRS_SOURCE_VOLUME : FRS_SOURCE_MAP;
	return 0;
}

void source_close(struct frs_source *s)
{
	if (s->fp != NULL)
		io_close_in(s->fp);
	s->fp = NULL;
}

/* The rest of an open file.  Both image decoders want random access, so
 * an image is buffered whole (standard input included). */
static int read_source(struct frs_source *s, struct ask *a)
{
	unsigned char *buf = NULL;
	size_t len = 0;
	int rc;

	a->dims = a->want != 0 ? a->want : s->frv ? 3 : 2;
	if (a->dims == 3) {
		/* Standard input has no other reading: the header's
		 * check names what is wrong. */
		if (!s->frv && strcmp(s->src, "-") != 0)
			return frs_fail("%s: not an importance volume (.frv)",
			    s->name);
		return vol_read_pre(s->fp, s->name, s->pre, s->npre, a->v);
	}
	if (io_slurp(s->fp, s->name, s->pre, s->npre, &buf, &len) < 0)
		return -1;
	rc = decode_image(buf, len, s->name, a->flags, a->m);
	free(buf);
	return rc;
}

/* A spec (no file of that name exists): a map's, at w x h (0: 128x128),
 * or a volume's. */
static int load_spec(const struct frs_source *s, struct ask *a,
    const uint32_t size[3])
{
	const char *src = s->src;

	a->dims = a->want != 0 ? a->want : vol_is_spec(src) &&
	    !imap_is_spec(src) ? 3 : 2;
	if (a->dims == 2 && imap_is_spec(src))
		return imap_spec(src, size[0] ? size[0] : 128,
		    size[1] ? size[1] : 128, a->m);
	if (a->dims == 2 && vol_is_spec(src))
		return frs_fail("%s: a procedural volume where a 2-D map is "
		    "needed (volumes go with 3-D matrices)", src);
	if (a->dims == 2) {
		frs_fail("%s: no such file, and not a procedural map (const, "
		    "blob, ramp, aniso, sky)", src);
		frs_set_errkind(FRS_ERRKIND_IO);
		return -1;
	}
	if (vol_is_spec(src))
		return vol_spec(src, size[0], size[1], size[2], a->v);
	if (imap_is_spec(src))
		return frs_fail("%s: a 2-D map where a volume is needed (.frv, "
		    "or const, blob3, ramp3, shell3)", src);
	errno = s->stat_errno;
	frs_fail_errno("%s", src);
	frs_set_errkind(FRS_ERRKIND_IO);
	return -1;
}

/* The source as it is: its dimensions, -1 after frs_fail.  A source is
 * read once. */
static int load_raw(struct frs_source *s, struct ask *a,
    const uint32_t size[3])
{
	int rc;

	if (a->m != NULL)
		memset(a->m, 0, sizeof *a->m);
	if (a->v != NULL)
		memset(a->v, 0, sizeof *a->v);
	if (s->used)
		return frs_fail("%s: the source was read already", s->src);
	s->used = 1;
	if (s->fp != NULL)
		rc = read_source(s, a);
	else
		rc = load_spec(s, a, size);
	return rc < 0 ? -1 : (int)a->dims;
}

int imap_load_raw(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m)
{
	return map_or_vol_load(src, 2, (const uint32_t[3]){ w, h, 0 },
	    flags | FRS_MAP_RAW, m, NULL, NULL) < 0 ? -1 : 0;
}

/* The checks of a map as loaded: its own pixels first, so that messages
 * name them, not those of the resampled map; then the weighting and the
 * size asked for, checked again when they changed the values (a
 * weighting can underflow tiny values to zero). */
static int finish_map(const char *name, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m, struct frs_imap_stats *st)
{
	int resize = w != 0 && (w != m->w || h != m->h);
	int again = resize || (flags & FRS_MAP_EQUIRECT);
	int rc = imap_validate_stats(m, name, again ? flags | FRS_MAP_ALLOW_ZERO :
	    flags, st);

	if (rc == 0 && (flags & FRS_MAP_EQUIRECT))
		imap_equirect(m);
	if (rc == 0 && resize) {
		struct frs_imap r;
		rc = imap_resample(m, w, h, &r);
		imap_free(m);
		*m = r;
		if (rc < 0)
			frs_fail_context(name);
	}
	if (rc == 0 && again)
		rc = imap_validate_stats(m, name, flags, st);
	if (rc < 0)
		imap_free(m);
	return rc;
}

/* A volume as loaded: never resampled, so a file must have the size
 * asked for (a spec was made at it). */
static int finish_vol(const char *name, const uint32_t size[3], int flags,
    struct frs_vol *v)
{
	int rc;

	if (size[0] != 0 && (size[0] != v->w || size[1] != v->h ||
	    size[2] != v->d)) {
		rc = frs_fail("%s: the volume is %ux%ux%u, not the %ux%ux%u "
		    "asked for (volumes are not resampled)", name, v->w, v->h,
		    v->d, size[0], size[1], size[2]);
		vol_free(v);
		return rc;
	}
	rc = vol_validate(v, name, flags);
	if (rc < 0)
		vol_free(v);
	return rc;
}

/* A map or volume as loaded (dims 2 or 3) finished as flags ask: a
 * map's own pixels checked, then weighted and resized (FRS_MAP_RAW: its
 * statistics only), a volume checked.  dims; -1 after frs_fail, what was
 * loaded released. */
static int finish(const char *name, int dims, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v)
{
	struct frs_imap_stats own;

	if (dims == 2 && (flags & FRS_MAP_RAW)) {
		if (st != NULL)
			imap_stats(m, st);
		return dims;
	}
	if (dims == 2 && finish_map(name, size[0], size[1], flags, m,
	    st != NULL ? st : &own) < 0)
		return -1;
	if (dims == 3 && !(flags & FRS_MAP_RAW) &&
	    finish_vol(name, size, flags, v) < 0)
		return -1;
	return dims;
}

int source_load(struct frs_source *s, unsigned want, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v)
{
	struct ask a = { .want = want, .flags = flags, .m = m, .v = v };
	const char *name = strcmp(s->src, "-") == 0 ? "<stdin>" : s->src;
	int dims = load_raw(s, &a, size);

	return dims < 0 ? -1 : finish(name, dims, size, flags, m, st, v);
}

int spec_load(const char *spec, unsigned dims, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v)
{
	int rc = dims == 2 ? imap_spec(spec, size[0] ? size[0] : 128,
	    size[1] ? size[1] : 128, m) : vol_spec(spec, size[0], size[1],
	    size[2], v);

	return rc < 0 || finish(spec, (int)dims, size, flags, m, st, v) < 0 ?
	    -1 : 0;
}

int source_read(const char *src, unsigned want, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v, int *spec)
{
	struct frs_source s;
	int dims;

	if (spec != NULL)
		*spec = 0;
	if (source_open(&s, src) < 0) {
		if (m != NULL)
			memset(m, 0, sizeof *m);
		if (v != NULL)
			memset(v, 0, sizeof *v);
		return -1;
	}
	dims = source_load(&s, want, size, flags, m, st, v);
	if (spec != NULL)
		*spec = s.fp == NULL && s.kinds != 0;
	source_close(&s);
	return dims;
}

int map_or_vol_load(const char *src, unsigned want, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v)
{
	return source_read(src, want, size, flags, m, st, v, NULL);
}

int imap_load(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m)
{
	return map_or_vol_load(src, 2, (const uint32_t[3]){ w, h, 0 }, flags, m,
	    NULL, NULL) < 0 ? -1 : 0;
}

int vol_is_volume(const char *src)
{
	return vol_is_file(src) == 1 || (vol_is_spec(src) && !imap_is_spec(src));
}

int vol_load(const char *src, uint32_t w, uint32_t h, uint32_t d, int flags,
    struct frs_vol *m)
{
	return map_or_vol_load(src, 3, (const uint32_t[3]){ w, h, d }, flags, NULL,
	    NULL, m) < 0 ? -1 : 0;
}
