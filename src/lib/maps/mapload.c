#define _POSIX_C_SOURCE 200809L
#include "maps/mapload.h"
#include "maps/exrio.h"
#include "maps/imap.h"
#include "maps/pngio.h"
#include "maps/spec.h"
#include "maps/vol.h"
#include "base/err.h"
#include "base/io.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int file_exists(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0;
}

static int load_file(const char *path, int flags, struct frs_imap *m)
{
	const char *name;
	unsigned char *buf = NULL;
	size_t len = 0;
	/* Both decoders want random access, so buffer the whole input
	 * (standard input included). */
	int rc = io_slurp_path(path, &name, &buf, &len);

	if (rc < 0)
		return -1;
	if (len == 0)
		rc = frs_fail("%s: empty file", name);
	else if (len >= 8 && memcmp(buf, "\211PNG\r\n\032\n", 8) == 0)
		rc = imap_read_png_mem(buf, len, name, flags & IMAP_SRGB, m);
	else if (len >= 4 && memcmp(buf, "\166\057\061\001", 4) == 0)
		rc = imap_read_exr_mem(buf, len, name, m);
	else if (len >= 8 && memcmp(buf, FRV_MAGIC, 8) == 0)
		rc = frs_fail("%s: a volume (.frv) where a 2-D map is needed "
		    "(volumes go with 3-D matrices)", name);
	else
		rc = frs_fail("%s: not a PNG or OpenEXR file", name);
	free(buf);
	return rc;
}

int imap_load_raw(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m)
{
	memset(m, 0, sizeof *m);
	if (strcmp(src, "-") == 0 || file_exists(src))
		return load_file(src, flags, m);
	if (imap_is_spec(src))
		return imap_spec(src, w ? w : 128, h ? h : 128, m);
	return frs_fail("%s: no such file, and not a procedural map (const, "
	    "blob, ramp, aniso, sky)", src);
}

int imap_load(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m)
{
	const char *name = strcmp(src, "-") == 0 ? "<stdin>" : src;
	int rc = imap_load_raw(src, w, h, flags, m);

	/* Check the source's own pixels first, so that messages name its
	 * pixels, not those of the resampled map. */
	if (rc == 0)
		rc = imap_validate(m, name, flags | IMAP_ALLOW_ZERO);
	if (rc == 0 && (flags & IMAP_EQUIRECT))
		imap_equirect(m);
	if (rc == 0 && w != 0 && (w != m->w || h != m->h)) {
		struct frs_imap r;
		rc = imap_resample(m, w, h, &r);
		imap_free(m);
		*m = r;
		if (rc < 0)
			frs_fail_context(name);
	}
	if (rc == 0)
		rc = imap_validate(m, name, flags);
	if (rc < 0)
		imap_free(m);
	return rc;
}

int vol_is_volume(const char *src)
{
	return vol_is_file(src) == 1 || (vol_is_spec(src) && !imap_is_spec(src));
}

int vol_load(const char *src, uint32_t w, uint32_t h, uint32_t d, int flags,
    struct frs_vol *m)
{
	int rc, isf = vol_is_file(src);

	memset(m, 0, sizeof *m);
	if (isf == 1 || strcmp(src, "-") == 0) {
		if (vol_read(src, m) < 0)
			return -1;
		if (w != 0 && (w != m->w || h != m->h || d != m->d)) {
			rc = frs_fail("%s: the volume is %ux%ux%u, not the %ux%ux%u "
			    "asked for (volumes are not resampled)", src, m->w, m->h,
			    m->d, w, h, d);
			vol_free(m);
			return rc;
		}
	} else if (vol_is_spec(src)) {
		if (vol_spec(src, w, h, d, m) < 0)
			return -1;
	} else if (imap_is_spec(src)) {
		return frs_fail("%s: a 2-D map where a volume is needed (.frv, or "
		    "const, blob3, ramp3, shell3)", src);
	} else if (isf == 0) {
		return frs_fail("%s: not an importance volume (.frv)", src);
	} else {
		return frs_fail_errno("%s", src);
	}
	rc = vol_validate(m, strcmp(src, "-") == 0 ? "<stdin>" : src, flags);
	if (rc < 0)
		vol_free(m);
	return rc;
}
