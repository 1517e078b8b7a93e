/*
 * Loading importance maps and volumes by source: the one place that picks
 * a reader, a PNG or OpenEXR file by its magic, a .frv volume, or a
 * procedural spec (spec.h) when no such file exists.
 */
#ifndef FRS_MAPLOAD_H
#define FRS_MAPLOAD_H

#include <stdint.h>
#include <stdio.h>

#include "maps/imap.h"
#include "maps/vol.h"

/*
 * Load an importance map from a PNG or OpenEXR file (detected by magic;
 * "-" reads standard input) or, when no such file exists, a procedural
 * spec (see imap_spec).  w, h: requested size, 0 for the file's own size
 * (and 128x128 for specs); a file of another size is resampled by area.
 * Then imap_validate.  flags: IMAP_* of imap.h.
 */
int imap_load(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m);

/* The source as it is, without checks or clamping: a file at its own
 * size (w, h ignored), a spec at w x h (0: 128x128). */
int imap_load_raw(const char *src, uint32_t w, uint32_t h, int flags,
    struct frs_imap *m);

/*
 * A source opened once (frs.h's frs_source): a file ("-": standard
 * input) opened with its first bytes read, or a name that is no file (a
 * spec, or nothing: the stat's errno kept for the message).
 */
struct frs_source {
	const char *src;	/* the caller's, not copied */
	const char *name;	/* for messages: "<stdin>" for "-" */
	FILE *fp;		/* NULL: no file */
	unsigned char pre[8];	/* its first bytes */
	size_t npre;
	int frv;		/* they are the .frv magic */
	int kinds;		/* FRS_SOURCE_ bits */
	int stat_errno;
	int used;		/* loaded (a source is read once) */
};
/* 0, or -1 after frs_fail (a file that does not open or read: kind
 * FRS_ERRKIND_IO). */
int source_open(struct frs_source *s, const char *src);
/* src as a 2-D map into m or a volume into v, as map_or_vol_load. */
int source_load(struct frs_source *s, unsigned want, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v);
void source_close(struct frs_source *s);
/* spec evaluated as a map (dims 2) or a volume (3), no file looked at,
 * then checked as source_load checks it: 0, or -1 after frs_fail. */
int spec_load(const char *spec, unsigned dims, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v);

/*
 * src as a 2-D map into m (imap_load) or a volume into v (vol_load): want
 * 2 or 3 asks for one, 0 takes what src is (a .frv file, or a spec that
 * only volumes have, is a volume; anything else a map).  size: the sides
 * asked for, size[0] 0 for the source's own.  A file is opened once.  A
 * map's statistics as checked go into st unless NULL.  FRS_MAP_RAW: the
 * source as it is (a file at its own size), not checked.  Returns 2 or 3,
 * -1 after frs_fail (nothing held).
 */
int map_or_vol_load(const char *src, unsigned want, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v);
/* The same (source_open, source_load, source_close), and *spec (unless
 * NULL) set when src was taken as a spec: no file of that name, a name
 * that some spec has.  A failure to open has kind FRS_ERRKIND_IO. */
int source_read(const char *src, unsigned want, const uint32_t size[3],
    int flags, struct frs_imap *m, struct frs_imap_stats *st,
    struct frs_vol *v, int *spec);

/* A .frv file or a spec that only volumes have (const is both). */
int vol_is_volume(const char *src);

/*
 * A .frv file (at its own size: w, h, d must be 0 or equal to it) or a
 * procedural spec, then vol_validate.  FRS_MAP_STRICT and FRS_MAP_ALLOW_ZERO
 * of imap.h apply.
 */
int vol_load(const char *src, uint32_t w, uint32_t h, uint32_t d, int flags,
    struct frs_vol *m);

#endif
