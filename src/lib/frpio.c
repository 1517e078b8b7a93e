#define _POSIX_C_SOURCE 200809L
#include "frscore.h"
#include "err.h"
#include "io.h"
#include "mem.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define FRP_VERSION 1
#define FRP_HEADER 40

static int put_u32s(FILE *fp, const uint32_t *v, size_t n)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
	for (size_t i = 0; i < n; i++) {
		unsigned char b[4];
		io_put_u32(b, v[i]);
		if (fwrite(b, 1, 4, fp) != 4)
			return -1;
	}
	return 0;
#else
	return fwrite(v, 4, n, fp) == n ? 0 : -1;
#endif
}

int frp_write(FILE *fp, const char *name, const struct frs_matrix *m,
    int minmap, const uint32_t *blocks, unsigned nblocks)
{
	unsigned char h[FRP_HEADER] = { 0 };
	struct frs_prep p;
	int rc = 0;

	if (m->dims != 2)
		return frs_fail("%s: only 2-D matrices can be prepared", name);
	if (frs_prepare(&p, m, minmap, 0) < 0)
		return frs_fail_context(name);
	memcpy(h, FRP_MAGIC, 8);
	io_put_u32(h + 8, FRP_VERSION);
	io_put_u32(h + 12, m->w);
	io_put_u32(h + 16, m->h);
	io_put_u32(h + 20, (minmap ? 1u : 0u) | (nblocks ? 2u : 0u));
	io_put_u64(h + 24, frd_checksum(m));
	io_put_u32(h + 32, nblocks);
	if (fwrite(h, 1, sizeof h, fp) != sizeof h || put_u32s(fp, m->v, m->n) < 0)
		rc = -1;
	for (unsigned l = 1; rc == 0 && minmap && l < p.nlev; l++)
		rc = put_u32s(fp, p.lev[l], (size_t)(m->w >> l) * (m->h >> l));
	frs_prep_free(&p);
	for (unsigned b = 0; rc == 0 && b < nblocks; b++) {
		struct frs_prep q;
		unsigned char bh[8] = { 0 };
		if (frs_prepare(&q, m, 0, blocks[b]) < 0)
			return frs_fail_context(name);
		io_put_u32(bh, blocks[b]);
		rc = fwrite(bh, 1, 8, fp) == 8 && put_u32s(fp, q.sval, m->n) == 0 &&
		    put_u32s(fp, q.sidx, m->n) == 0 ? 0 : -1;
		frs_prep_free(&q);
	}
	if (rc < 0)
		return frs_fail_errno("%s: write error", name);
	return 0;
}

static int read_u32s(FILE *fp, const char *name, uint32_t **out, size_t n,
    const char *what)
{
	*out = mem_calloc(what, n, sizeof **out);
	if (*out == NULL)
		return frs_fail_context(name);
	if (io_read_exact(fp, name, *out, n * 4, what) < 0) {
		free(*out);
		*out = NULL;
		return -1;
	}
	io_le_u32(*out, n);
	return 0;
}

static int read_header(FILE *fp, const char *name, uint32_t *w, uint32_t *h,
    uint32_t *flags, uint64_t *sum, uint32_t *nblocks)
{
	unsigned char hd[FRP_HEADER];

	if (io_read_exact(fp, name, hd, sizeof hd, "header") < 0)
		return -1;
	if (memcmp(hd, FRP_MAGIC, 8) != 0)
		return frs_fail("%s: not a prepared matrix (wrong magic)", name);
	if (io_get_u32(hd + 8) != FRP_VERSION)
		return frs_fail("%s: unsupported format version %u (this program "
		    "reads version %d)", name, io_get_u32(hd + 8), FRP_VERSION);
	*w = io_get_u32(hd + 12);
	*h = io_get_u32(hd + 16);
	*flags = io_get_u32(hd + 20);
	*sum = io_get_u64(hd + 24);
	*nblocks = io_get_u32(hd + 32);
	if (*w == 0 || *h == 0 || (uint64_t)*w * *h > UINT32_MAX ||
	    *nblocks > 32 || (*flags & ~3u))
		return frs_fail("%s: impossible header", name);
	return 0;
}

int frp_info(const char *path, uint32_t *w, uint32_t *h, uint64_t *sum)
{
	const char *name;
	FILE *fp = io_open_in(path, &name);
	uint32_t flags = 0, nb = 0;
	int rc;

	if (fp == NULL)
		return -1;
	rc = read_header(fp, name, w, h, &flags, sum, &nb);
	io_close_in(fp);
	return rc;
}

int frp_is(const char *path)
{
	unsigned char b[8];
	FILE *fp = fopen(path, "rb");
	size_t got;

	if (fp == NULL)
		return -1;
	got = fread(b, 1, 8, fp);
	fclose(fp);
	return got == 8 && memcmp(b, FRP_MAGIC, 8) == 0;
}

static int read_levels(FILE *fp, const char *name, const struct frs_matrix *m,
    struct frs_prep *p)
{
	p->lev[0] = m->v;
	p->nlev = 1;
	while ((m->w >> p->nlev) > 0 && (m->h >> p->nlev) > 0 && p->nlev < 32) {
		unsigned l = p->nlev;
		if (read_u32s(fp, name, &p->lev[l], (size_t)(m->w >> l) *
		    (m->h >> l), "minmap") < 0)
			return -1;
		p->nlev++;
	}
	return 0;
}

/* The derived data are not covered by the checksum: check that each
 * sorted list holds its block's values, ascending, at their places. */
static int check_sorted(const char *name, const struct frs_matrix *m,
    const struct frs_prep *p)
{
	uint32_t b = p->block, bw = m->w / b;
	uint64_t bb = (uint64_t)b * b;

	for (size_t i = 0; i < m->n; i++) {
		uint64_t blk = i / bb, k = p->sidx[i];
		size_t cell;
		if (k >= bb || (i % bb && p->sval[i] <= p->sval[i - 1]))
			return frs_fail("%s: damaged sorted list of block %llu", name,
			    (unsigned long long)blk);
		cell = ((blk / bw) * b + k / b) * m->w + (blk % bw) * b + k % b;
		if (m->v[cell] != p->sval[i])
			return frs_fail("%s: damaged sorted list of block %llu", name,
			    (unsigned long long)blk);
	}
	return 0;
}

/* Each minmap level must be the minimum of the one below. */
static int check_levels(const char *name, const struct frs_matrix *m,
    const struct frs_prep *p)
{
	for (unsigned l = 1; l < p->nlev; l++) {
		uint32_t w = m->w >> l, h = m->h >> l, pw = m->w >> (l - 1);
		const uint32_t *lo = p->lev[l - 1];
		for (uint32_t y = 0; y < h; y++)
			for (uint32_t x = 0; x < w; x++) {
				const uint32_t *q = lo + (size_t)2 * y * pw + 2 * x;
				uint32_t a = q[0] < q[1] ? q[0] : q[1];
				uint32_t c = q[pw] < q[pw + 1] ? q[pw] : q[pw + 1];
				if (p->lev[l][(size_t)y * w + x] != (a < c ? a : c))
					return frs_fail("%s: damaged minmap level %u", name,
					    l);
			}
	}
	return 0;
}

static int read_sorted(FILE *fp, const char *name, const struct frs_matrix *m,
    struct frs_prep *p, uint32_t nblocks, uint32_t want)
{
	for (uint32_t b = 0; b < nblocks; b++) {
		unsigned char bh[8];
		uint32_t size;
		if (io_read_exact(fp, name, bh, 8, "sorted lists") < 0)
			return -1;
		size = io_get_u32(bh);
		if (size == 0 || size > m->w || size > m->h || (size & (size - 1)))
			return frs_fail("%s: impossible block size %u", name, size);
		if (size != want) {
			if (fseek(fp, (long)(8 * m->n), SEEK_CUR) != 0)
				return frs_fail_errno("%s: seek", name);
			continue;
		}
		p->block = size;
		p->below = FRS_ALL_VALUES;
		if (read_u32s(fp, name, &p->sval, m->n, "sorted values") < 0 ||
		    read_u32s(fp, name, &p->sidx, m->n, "sorted indices") < 0 ||
		    (p->soff = mem_calloc("sorted lists", m->n / ((uint64_t)size *
		    size) + 1, sizeof *p->soff)) == NULL)
			return -1;
		for (uint64_t k = 0; k <= m->n / ((uint64_t)size * size); k++)
			p->soff[k] = (uint32_t)(k * size * size);
		return check_sorted(name, m, p);
	}
	return 0;
}

/* A regular file must hold at least the matrix its header announces:
 * checked before allocating, so that a damaged header cannot ask for
 * gigabytes. */
static int fits_file(FILE *fp, const char *name, uint32_t w, uint32_t h)
{
	struct stat st;
	uint64_t need = 40 + 4 * (uint64_t)w * h;

	if (fstat(fileno(fp), &st) == 0 && S_ISREG(st.st_mode) &&
	    (uint64_t)st.st_size < need)
		return frs_fail("%s: truncated: a %ux%u matrix needs %llu bytes, "
		    "the file has %lld", name, w, h, (unsigned long long)need,
		    (long long)st.st_size);
	return 0;
}

int frp_read(const char *path, struct frs_matrix *m, struct frs_prep *p,
    uint32_t block)
{
	const char *name;
	FILE *fp = io_open_in(path, &name);
	uint32_t w = 0, h = 0, flags = 0, nb = 0;
	uint64_t sum = 0;

	memset(m, 0, sizeof *m);
	memset(p, 0, sizeof *p);
	if (fp == NULL)
		return -1;
	if (read_header(fp, name, &w, &h, &flags, &sum, &nb) < 0 ||
	    fits_file(fp, name, w, h) < 0 ||
	    frd_alloc(m, 2, w, h, 1, "prepared") < 0 ||
	    io_read_exact(fp, name, m->v, m->n * 4, "matrix") < 0)
		goto fail;
	io_le_u32(m->v, m->n);
	if (frd_checksum(m) != sum) {
		frs_fail("%s: the matrix does not match its recorded checksum "
		    "(damaged file)", name);
		goto fail;
	}
	if (frd_check_permutation(m, name) < 0)
		goto fail;
	p->m = m;
	p->lev[0] = m->v;
	p->nlev = 1;
	if ((flags & 1) && (read_levels(fp, name, m, p) < 0 ||
	    check_levels(name, m, p) < 0))
		goto fail;
	if ((flags & 2) && read_sorted(fp, name, m, p, nb, block) < 0)
		goto fail;
	io_close_in(fp);
	return 0;
fail:
	io_close_in(fp);
	frs_prep_free(p);
	frd_free(m);
	return -1;
}
