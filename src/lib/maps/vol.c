#define _POSIX_C_SOURCE 200809L
#include "maps/vol.h"
#include "base/err.h"
#include "base/io.h"
#include "base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int vol_alloc(struct frs_vol *m, uint32_t w, uint32_t h, uint32_t d)
{
	uint64_t n = (uint64_t)w * h * d;

	memset(m, 0, sizeof *m);
	if (w == 0 || h == 0 || d == 0 || w > VOL_MAX_SIDE || h > VOL_MAX_SIDE ||
	    d > VOL_MAX_SIDE || n > VOL_MAX_VOXELS)
		return frs_fail("a %ux%ux%u volume is outside 1 to %u a side and "
		    "2^28 voxels", w, h, d, VOL_MAX_SIDE);
	m->v = mem_calloc("the volume", n, sizeof *m->v);
	if (m->v == NULL)
		return -1;
	m->w = w;
	m->h = h;
	m->d = d;
	return 0;
}

void vol_free(struct frs_vol *m)
{
	free(m->v);
	memset(m, 0, sizeof *m);
}

struct frs_imap vol_as_map(const struct frs_vol *m)
{
	struct frs_imap v = { m->w, m->h * m->d, m->v };
	return v;
}

int vol_is_file(const char *path)
{
	unsigned char b[8];
	FILE *fp;
	size_t got;

	if (strcmp(path, "-") == 0)
		return 0;
	if ((fp = fopen(path, "rb")) == NULL)
		return -1;
	got = fread(b, 1, sizeof b, fp);
	fclose(fp);
	return got == sizeof b && memcmp(b, FRV_MAGIC, 8) == 0;
}

static int read_header(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, uint32_t sz[3])
{
	unsigned char h[FRV_HEADER];
	long long fsize = io_file_size(fp);
	unsigned long long want;

	if (io_read_header(fp, name, pre, npre, h, sizeof h) < 0)
		return -1;
	if (memcmp(h, FRV_MAGIC, 8) != 0)
		return frs_fail("%s: not a volume (.frv): wrong magic", name);
	if (io_get_u32(h + 8) != FRV_VERSION)
		return frs_fail("%s: volume format version %u (this reads %u)",
		    name, io_get_u32(h + 8), FRV_VERSION);
	for (int k = 0; k < 3; k++)
		sz[k] = io_get_u32(h + 12 + 4 * k);
	if (io_get_u64(h + 24) != 0)
		return frs_fail("%s: reserved header field is not zero", name);
	if (sz[0] == 0 || sz[1] == 0 || sz[2] == 0 || sz[0] > VOL_MAX_SIDE ||
	    sz[1] > VOL_MAX_SIDE || sz[2] > VOL_MAX_SIDE ||
	    (uint64_t)sz[0] * sz[1] * sz[2] > VOL_MAX_VOXELS)
		return frs_fail("%s: impossible size %ux%ux%u", name, sz[0], sz[1],
		    sz[2]);
	want = FRV_HEADER + 4ull * sz[0] * sz[1] * sz[2];
	if (fsize >= 0 && (unsigned long long)fsize != want)
		return frs_fail("%s: file has %lld bytes but its header "
		    "(%ux%ux%u voxels) needs %llu", name, fsize, sz[0], sz[1],
		    sz[2], want);
	return 0;
}

int vol_read_pre(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frs_vol *m)
{
	uint32_t sz[3] = { 0, 0, 0 };
	unsigned char buf[4096];
	uint64_t n, i = 0;

	memset(m, 0, sizeof *m);
	if (read_header(fp, name, pre, npre, sz) < 0)
		return -1;
	if (vol_alloc(m, sz[0], sz[1], sz[2]) < 0)
		return frs_fail_context(name);
	n = (uint64_t)sz[0] * sz[1] * sz[2];
	while (i < n) {
		size_t k = n - i < sizeof buf / 4 ? (size_t)(n - i) : sizeof buf / 4;
		if (io_read_exact(fp, name, buf, 4 * k, "values") < 0) {
			vol_free(m);
			return -1;
		}
		for (size_t j = 0; j < k; j++) {
			uint32_t u = io_get_u32(buf + 4 * j);
			float f;
			memcpy(&f, &u, sizeof f);
			m->v[i + j] = f;
		}
		i += k;
	}
	if (fgetc(fp) != EOF) {
		vol_free(m);
		return frs_fail("%s: trailing data after the values", name);
	}
	return 0;
}

static int read_fp(FILE *fp, const char *name, void *vol)
{
	return vol_read_pre(fp, name, NULL, 0, vol);
}

int vol_read(const char *path, struct frs_vol *m)
{
	return io_read_path(path, read_fp, m);
}

int vol_write(FILE *fp, const char *name, const struct frs_vol *m)
{
	unsigned char h[FRV_HEADER] = { 0 }, buf[4096];
	uint64_t n = (uint64_t)m->w * m->h * m->d;
	int ok;

	memcpy(h, FRV_MAGIC, 8);
	io_put_u32(h + 8, FRV_VERSION);
	io_put_u32(h + 12, m->w);
	io_put_u32(h + 16, m->h);
	io_put_u32(h + 20, m->d);
	ok = fwrite(h, 1, sizeof h, fp) == sizeof h;
	for (uint64_t i = 0; ok && i < n; ) {
		size_t k = n - i < sizeof buf / 4 ? (size_t)(n - i) : sizeof buf / 4;
		for (size_t j = 0; j < k; j++) {
			double v = m->v[i + j];
			float f = (float)v;
			uint32_t u;
			/* float32 holds the values: refuse what it would turn
			 * into infinity or zero. */
			if (isfinite(v) && (isinf(f) || (f == 0.0f && v != 0.0))) {
				frs_fail("%s: value %g at voxel %llu is outside "
				    "the float range of .frv", name, v,
				    (unsigned long long)(i + j));
				frs_set_errkind(FRS_ERRKIND_MAP);
				return -1;
			}
			memcpy(&u, &f, sizeof u);
			io_put_u32(buf + 4 * j, u);
		}
		ok = fwrite(buf, 4, k, fp) == k;
		i += k;
	}
	if (!ok)
		return frs_fail_errno("%s: write error", name);
	return 0;
}

/* The voxel of index i of the W x (H D) view. */
static void voxel_of(const struct frs_vol *m, uint32_t x, uint32_t yv,
    uint32_t c[3])
{
	c[0] = x;
	c[1] = yv % m->h;
	c[2] = yv / m->h;
}

static int validate(struct frs_vol *m, const char *name, int flags)
{
	struct frs_imap view = vol_as_map(m);
	struct frs_imap_stats s;
	uint32_t c[3];

	imap_stats(&view, &s);
	if (s.nonfinite) {
		voxel_of(m, s.bad_x, s.bad_y, c);
		return frs_fail("%s: voxel (%u, %u, %u) is %s (%llu non-finite "
		    "voxels)", name, c[0], c[1], c[2], isnan(s.bad_value) ?
		    "NaN" : "infinite", (unsigned long long)s.nonfinite);
	}
	if (s.negatives && (flags & FRS_MAP_STRICT)) {
		voxel_of(m, s.neg_x, s.neg_y, c);
		return frs_fail("%s: voxel (%u, %u, %u) is negative; %llu "
		    "negative voxels, smallest %.6g", name, c[0], c[1], c[2],
		    (unsigned long long)s.negatives, s.min_negative);
	}
	return imap_clamp(&view, &s, name, "voxels", flags);
}

int vol_validate(struct frs_vol *m, const char *name, int flags)
{
	if (validate(m, name, flags) == 0)
		return 0;
	frs_set_errkind(FRS_ERRKIND_MAP);	/* the values, not the file */
	return -1;
}
