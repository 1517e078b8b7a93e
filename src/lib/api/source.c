/*
 * Maps and volumes by the public API (since 2.2): a source opened once
 * and loaded as a map or a volume, the checks and statistics of a map's
 * values, the specs' names and help, and the writers of imap(1)'s
 * formats.  The work is maps/'s; this maps its failures to codes.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdlib.h>
#include <string.h>

#include "api/api.h"
#include "base/err.h"
#include "maps/exrio.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "maps/pngio.h"
#include "maps/spec.h"
#include "maps/vol.h"

void frs_imap_stats(const struct frs_imap *map, struct frs_imap_stats *st)
{
	imap_stats(map, st);
}

int frs_imap_check(struct frs_imap *map, const char *name, int flags,
    struct frs_imap_stats *st, frs_error *err)
{
	struct frs_imap_stats own;

	if (map == NULL || name == NULL || map->v == NULL || map->w == 0 ||
	    map->h == 0)
		return api_arg_err(err, "frs_imap_check: NULL argument or an "
		    "empty map");
	if (imap_validate_stats(map, name, flags, st != NULL ? st : &own) < 0)
		return api_lib_err(err, FRS_E_MAP);
	return api_ok(err);
}

void frs_vol_free(struct frs_vol *vol)
{
	if (vol != NULL)
		vol_free(vol);
}

int frs_source_open(frs_source **source, const char *src, frs_error *err)
{
	struct frs_source *s;

	if (source == NULL || src == NULL)
		return api_arg_err(err, "frs_source_open: NULL argument");
	*source = NULL;
	if ((s = malloc(sizeof *s)) == NULL)
		return api_nomem(err);
	if (source_open(s, src) < 0) {
		free(s);
		return api_lib_err(err, FRS_E_IO);
	}
	*source = s;
	return api_ok(err);
}

int frs_source_kinds(const frs_source *source)
{
	return source != NULL ? source->kinds : 0;
}

/* frs_source_load's and frs_source_read's arguments, size NULL taken
 * as the source's own; *map, *vol and *dims zeroed. */
static int load_args(const char *fn, unsigned want, const uint32_t **size,
    unsigned *dims, struct frs_imap *map, struct frs_vol *vol,
    frs_error *err)
{
	static const uint32_t own[3] = { 0, 0, 0 };
	char msg[128];

	if (map != NULL)
		*map = (struct frs_imap){ 0 };
	if (vol != NULL)
		*vol = (struct frs_vol){ 0 };
	if (dims != NULL)
		*dims = 0;
	if (dims == NULL || want == 1 || want > 3 || (want != 3 &&
	    map == NULL) || (want != 2 && vol == NULL)) {
		snprintf(msg, sizeof msg, "%s: NULL argument or a want other "
		    "than 0, 2 or 3", fn);
		return api_arg_err(err, msg);
	}
	if (*size == NULL)
		*size = own;
	if ((*size)[0] != 0 && ((*size)[1] == 0 || (want == 3 &&
	    (*size)[2] == 0))) {
		snprintf(msg, sizeof msg, "%s: sides all 0 or all set", fn);
		return api_arg_err(err, msg);
	}
	return FRS_OK;
}

int frs_source_load(frs_source *source, unsigned want,
    const uint32_t size[3], int flags, unsigned *dims, struct frs_imap *map,
    struct frs_imap_stats *st, struct frs_vol *vol, frs_error *err)
{
	int rc = load_args("frs_source_load", want, &size, dims, map, vol, err);

	if (rc != FRS_OK)
		return rc;
	if (source == NULL)
		return api_arg_err(err, "frs_source_load: NULL argument or a "
		    "want other than 0, 2 or 3");
	if (source->used)
		return api_arg_err(err, "frs_source_load: the source was "
		    "loaded already");
	/* A spec that does not make a map is the caller's argument, a file
	 * that does not the file's format. */
	if ((rc = source_load(source, want, size, flags, map, st, vol)) < 0)
		return api_lib_err(err, source->fp == NULL && source->kinds != 0 ?
		    FRS_E_ARG : FRS_E_FORMAT);
	*dims = (unsigned)rc;
	return api_ok(err);
}

void frs_source_close(frs_source *source)
{
	if (source == NULL)
		return;
	source_close(source);
	free(source);
}

int frs_source_read(const char *src, unsigned want, const uint32_t size[3],
    int flags, unsigned *dims, struct frs_imap *map,
    struct frs_imap_stats *st, struct frs_vol *vol, frs_error *err)
{
	int spec, rc = load_args("frs_source_read", want, &size, dims, map, vol,
	    err);

	if (rc != FRS_OK)
		return rc;
	if (src == NULL)
		return api_arg_err(err, "frs_source_read: NULL argument");
	/* The one open and load: frs_source_open's and frs_source_load's
	 * work without their handle, a failure to open IO by its kind. */
	if ((rc = source_read(src, want, size, flags, map, st, vol, &spec)) < 0)
		return api_lib_err(err, spec ? FRS_E_ARG : FRS_E_FORMAT);
	*dims = (unsigned)rc;
	return api_ok(err);
}

int frs_spec_load(const char *spec, unsigned dims, const uint32_t size[3],
    int flags, struct frs_imap *map, struct frs_imap_stats *st,
    struct frs_vol *vol, frs_error *err)
{
	static const uint32_t own[3] = { 0, 0, 0 };

	if (map != NULL)
		*map = (struct frs_imap){ 0 };
	if (vol != NULL)
		*vol = (struct frs_vol){ 0 };
	if (spec == NULL || (dims != 2 && dims != 3) || (dims == 2 &&
	    map == NULL) || (dims == 3 && vol == NULL))
		return api_arg_err(err, "frs_spec_load: NULL argument or dims "
		    "other than 2 or 3");
	if (size == NULL)
		size = own;
	if (spec_load(spec, dims, size, flags, map, st, vol) < 0)
		return api_lib_err(err, FRS_E_ARG);
	return api_ok(err);
}

int frs_spec_kinds(const char *spec)
{
	if (spec == NULL)
		return 0;
	return (imap_is_spec(spec) ? FRS_SOURCE_MAP : 0) |
	    (vol_is_spec(spec) ? FRS_SOURCE_VOLUME : 0);
}

const char *frs_spec_help(unsigned dims)
{
	return dims == 2 ? imap_spec_help() : dims == 3 ? vol_spec_help() :
	    NULL;
}

/* A writer's failure: the values' (MAP) or the stream's (IO). */
static int write_err(frs_error *err)
{
	return api_lib_err(err, FRS_E_IO);
}

int frs_imap_write(const struct frs_imap *map, enum frs_map_format format,
    FILE *fp, const char *name, frs_error *err)
{
	int rc;

	if (map == NULL || fp == NULL || name == NULL || map->v == NULL ||
	    map->w == 0 || map->h == 0 || (format != FRS_FORMAT_PNG &&
	    format != FRS_FORMAT_EXR))
		return api_arg_err(err, "frs_imap_write: NULL argument, an "
		    "empty map or an unknown format");
	rc = format == FRS_FORMAT_PNG ? imap_write_png16(fp, name, map) :
	    imap_write_exr(fp, name, map);
	return rc < 0 ? write_err(err) : api_ok(err);
}

int frs_vol_write(const struct frs_vol *vol, FILE *fp, const char *name,
    frs_error *err)
{
	if (vol == NULL || fp == NULL || name == NULL || vol->v == NULL ||
	    vol->w == 0 || vol->h == 0 || vol->d == 0)
		return api_arg_err(err, "frs_vol_write: NULL argument or an "
		    "empty volume");
	return vol_write(fp, name, vol) < 0 ? write_err(err) : api_ok(err);
}
