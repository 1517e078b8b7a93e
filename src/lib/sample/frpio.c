#define _POSIX_C_SOURCE 200809L
#include "sample/frpio.h"
#include "sample/frscore.h"
#include "base/err.h"
#include "base/io.h"
#include "base/mem.h"

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

int frp_write(FILE *fp, const char *name, const char *src,
    const struct frs_matrix *m, int minmap, const uint32_t *blocks,
    unsigned nblocks)
{
	unsigned char h[FRP_HEADER] = { 0 };
	struct frs_prep p;
	int rc = 0;

	if (m->dims != 2)
		return frs_fail("%s: only 2-D matrices can be prepared", src);
	if (frs_prepare(&p, m, minmap, 0) < 0)
		return frs_fail_context(src);
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
			return frs_fail_context(src);
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

/* A .frp's header fields. */
struct frp_head {
	uint32_t w, h, flags, nblocks;
	uint64_t sum;
};

/* The header, of which the first npre bytes were read already (pre). */
static int read_header(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frp_head *f)
{
	unsigned char hd[FRP_HEADER];

	if (io_read_header(fp, name, pre, npre, hd, sizeof hd) < 0)
		return -1;
	if (memcmp(hd, FRP_MAGIC, 8) != 0)
		return frs_fail("%s: not a prepared matrix (wrong magic)", name);
	if (io_get_u32(hd + 8) != FRP_VERSION)
		return frs_fail("%s: unsupported format version %u (this program "
		    "reads version %d)", name, io_get_u32(hd + 8), FRP_VERSION);
	f->w = io_get_u32(hd + 12);
	f->h = io_get_u32(hd + 16);
	f->flags = io_get_u32(hd + 20);
	f->sum = io_get_u64(hd + 24);
	f->nblocks = io_get_u32(hd + 32);
	if (f->w == 0 || f->h == 0 || (uint64_t)f->w * f->h > UINT32_MAX ||
	    f->nblocks > 32 || (f->flags & ~3u))
		return frs_fail("%s: impossible header", name);
	return 0;
}

int frp_info(const char *path, uint32_t *w, uint32_t *h, uint64_t *sum)
{
	const char *name;
	FILE *fp = io_open_in(path, &name);
	struct frp_head f;
	int rc;

	if (fp == NULL)
		return -1;
	rc = read_header(fp, name, NULL, 0, &f);
	io_close_in(fp);
	if (rc < 0)
		return -1;
	*w = f.w;
	*h = f.h;
	*sum = f.sum;
	return 0;
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

/* The number of minmap levels above the matrix of a w x h matrix. */
static unsigned minmap_levels(uint32_t w, uint32_t h)
{
	unsigned l = 1;

	while ((w >> l) > 0 && (h >> l) > 0 && l < 32)
		l++;
	return l - 1;
}

static int read_levels(FILE *fp, const char *name, const struct frs_matrix *m,
    struct frs_prep *p)
{
	unsigned top = minmap_levels(m->w, m->h);

	p->lev[0] = m->v;
	p->nlev = 1;
	while (p->nlev <= top) {
		unsigned l = p->nlev;
		char what[64];
		snprintf(what, sizeof what, "minmap level %u of %u", l, top);
		if (read_u32s(fp, name, &p->lev[l], (size_t)(m->w >> l) *
		    (m->h >> l), what) < 0)
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

/* Pass over n bytes: a seek in a regular file, reading them in a pipe
 * (so that a short one is caught). */
static int skip(FILE *fp, const char *name, int regular, uint64_t n,
    const char *what)
{
	unsigned char buf[1 << 14];

	if (regular)
		return fseeko(fp, (off_t)n, SEEK_CUR) == 0 ? 0 :
		    frs_fail_errno("%s: seek", name);
	while (n > 0) {
		size_t k = n < sizeof buf ? (size_t)n : sizeof buf;
		if (io_read_exact(fp, name, buf, k, what) < 0)
			return -1;
		n -= k;
	}
	return 0;
}

/*
 * The sets of sorted lists: those of block size want into p (checked),
 * or with all != NULL every set, each checked, its block size noted
 * there.  A regular file (its length checked before) is left after the
 * set wanted; a pipe is read to its end, so that every set is there.
 */
static int read_sorted(FILE *fp, const char *name, const struct frs_matrix *m,
    struct frs_prep *p, uint32_t nblocks, uint32_t want, int regular,
    struct frp_summary *all)
{
	for (uint32_t b = 0; b < nblocks; b++) {
		unsigned char bh[8];
		uint32_t size;
		char what[3][64];
		snprintf(what[0], sizeof what[0], "sorted lists (set %u of %u)",
		    b + 1, nblocks);
		snprintf(what[1], sizeof what[1], "sorted values (set %u of %u)",
		    b + 1, nblocks);
		snprintf(what[2], sizeof what[2], "sorted indices (set %u of %u)",
		    b + 1, nblocks);
		if (io_read_exact(fp, name, bh, 8, what[0]) < 0)
			return -1;
		size = io_get_u32(bh);
		if (size == 0 || size > m->w || size > m->h || (size & (size - 1)))
			return frs_fail("%s: impossible block size %u", name, size);
		if (all != NULL)
			all->blocks[all->nblocks++] = size;
		if (all == NULL && (size != want || p->block != 0)) {
			if (skip(fp, name, regular, 8 * (uint64_t)m->n, what[1]) < 0)
				return -1;
			continue;
		}
		p->block = size;
		p->below = FRS_ALL_VALUES;
		if (read_u32s(fp, name, &p->sval, m->n, what[1]) < 0 ||
		    read_u32s(fp, name, &p->sidx, m->n, what[2]) < 0 ||
		    (p->soff = mem_calloc("sorted lists", m->n / ((uint64_t)size *
		    size) + 1, sizeof *p->soff)) == NULL)
			return -1;
		for (uint64_t k = 0; k <= m->n / ((uint64_t)size * size); k++)
			p->soff[k] = (uint32_t)(k * size * size);
		if (check_sorted(name, m, p) < 0)
			return -1;
		if (all != NULL) {
			free(p->sval);
			free(p->sidx);
			free(p->soff);
			p->sval = p->sidx = p->soff = NULL;
			p->block = 0;
		} else if (regular) {
			return 0;
		}
	}
	return 0;
}

/*
 * A regular file must hold exactly what its header announces: checked
 * before allocating, so that a damaged header cannot ask for gigabytes,
 * and so that sets of sorted lists read only when needed are known to be
 * there.  The message says which part the file lacks.
 */
static int check_length(long long fsize, const char *name, uint32_t w,
    uint32_t h, int minmap, uint32_t nsets)
{
	uint64_t n = (uint64_t)w * h, end[3], need;
	unsigned top = minmap ? minmap_levels(w, h) : 0;
	char what[128];

	end[0] = FRP_HEADER + 4 * n;
	end[1] = end[0];
	for (unsigned l = 1; l <= top; l++)
		end[1] += 4 * (uint64_t)(w >> l) * (h >> l);
	end[2] = end[1] + nsets * (8 + 8 * n);
	need = end[2];
	if ((uint64_t)fsize == need)
		return 0;
	if (nsets == 0)
		snprintf(what, sizeof what, "a %ux%u matrix%s", w, h,
		    minmap ? " and its minmap" : "");
	else
		snprintf(what, sizeof what, "a %ux%u matrix%s and %u set%s of "
		    "sorted lists", w, h, minmap ? ", its minmap" : "", nsets,
		    nsets == 1 ? "" : "s");
	if ((uint64_t)fsize > need)
		return frs_fail("%s: %llu bytes of trailing data (the header "
		    "announces %llu bytes: %s)", name,
		    (unsigned long long)((uint64_t)fsize - need),
		    (unsigned long long)need, what);
	if ((uint64_t)fsize < end[0])
		return frs_fail("%s: truncated: the file has %lld bytes, the "
		    "header announces %llu (%s); the matrix is cut short",
		    name, fsize, (unsigned long long)need, what);
	if ((uint64_t)fsize < end[1]) {
		uint64_t e = end[0];
		unsigned l = 1;
		for (; l < top; l++) {
			e += 4 * (uint64_t)(w >> l) * (h >> l);
			if ((uint64_t)fsize < e)
				break;
		}
		return frs_fail("%s: truncated: the file has %lld bytes, the "
		    "header announces %llu (%s); minmap level %u of %u is cut "
		    "short", name, fsize, (unsigned long long)need, what, l,
		    top);
	}
	{
		uint32_t k = (uint32_t)(((uint64_t)fsize - end[1]) / (8 + 8 * n));
		char sets[64];
		if (k + 1 == nsets)
			snprintf(sets, sizeof sets, "set %u of %u is cut short",
			    k + 1, nsets);
		else
			snprintf(sets, sizeof sets, "sets %u to %u of %u are "
			    "missing or cut short", k + 1, nsets, nsets);
		return frs_fail("%s: truncated: the file has %lld bytes, the "
		    "header announces %llu (%s); sorted lists: %s", name,
		    fsize, (unsigned long long)need, what, sets);
	}
}

/*
 * The rest of a .frp after its header f.  known: a matrix the file was
 * read for before (the .frd it is the twin of, the mask it came from):
 * when the values read are known's, and known is a permutation, they
 * are not checked again.
 */
static int load_body(FILE *fp, const char *name, const struct frp_head *f,
    const struct frs_matrix *known, struct frs_matrix *m, struct frs_prep *p,
    uint32_t block, struct frp_summary *all)
{
	uint32_t nsets = f->flags & 2 ? f->nblocks : 0;
	long long fsize = io_file_size(fp);
	int regular = fsize >= 0;

	if ((regular && check_length(fsize, name, f->w, f->h, f->flags & 1,
	    nsets) < 0) || frd_alloc(m, 2, f->w, f->h, 1, "prepared") < 0 ||
	    io_read_exact(fp, name, m->v, m->n * 4, "matrix") < 0)
		goto fail;
	io_le_u32(m->v, m->n);
	m->perm = known != NULL && known->perm && known->n == m->n &&
	    memcmp(known->v, m->v, m->n * sizeof *m->v) == 0;
	if (frd_check_sum(m, name, f->sum) < 0)
		goto fail;
	m->perm = 1;
	p->m = m;
	p->lev[0] = m->v;
	p->nlev = 1;
	if ((f->flags & 1) && (read_levels(fp, name, m, p) < 0 ||
	    check_levels(name, m, p) < 0))
		goto fail;
	if (nsets > 0 && read_sorted(fp, name, m, p, nsets, block, regular,
	    all) < 0)
		goto fail;
	if (!regular && getc(fp) != EOF) {
		frs_fail("%s: trailing data after the last set of sorted lists",
		    name);
		goto fail;
	}
	if (all != NULL) {
		all->w = f->w;
		all->h = f->h;
		all->sum = f->sum;
		all->minmap = f->flags & 1;
	}
	return 0;
fail:
	frs_prep_free(p);
	frd_free(m);
	return -1;
}

static int frp_load(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, const struct frs_matrix *known, struct frs_matrix *m,
    struct frs_prep *p, uint32_t block, struct frp_summary *all)
{
	struct frp_head f;

	memset(m, 0, sizeof *m);
	memset(p, 0, sizeof *p);
	if (read_header(fp, name, pre, npre, &f) < 0)
		return -1;
	return load_body(fp, name, &f, known, m, p, block, all);
}

int frp_read_pre(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frs_matrix *m, struct frs_prep *p, uint32_t block)
{
	return frp_load(fp, name, pre, npre, NULL, m, p, block, NULL);
}

int frp_read_known(FILE *fp, const char *path,
    const struct frs_matrix *known, struct frs_matrix *m, struct frs_prep *p,
    uint32_t block)
{
	const char *name = path;
	FILE *in = fp != NULL ? fp : io_open_in(path, &name);
	int rc;

	memset(m, 0, sizeof *m);
	memset(p, 0, sizeof *p);
	if (in == NULL)
		return -1;
	clearerr(in);
	if (fp != NULL && fseeko(fp, 0, SEEK_SET) != 0)
		return frs_fail_errno("%s: seek", name);
	rc = frp_load(in, name, NULL, 0, known, m, p, block, NULL);
	if (fp == NULL)
		io_close_in(in);
	return rc;
}

int frp_read(const char *path, struct frs_matrix *m, struct frs_prep *p,
    uint32_t block)
{
	return frp_read_known(NULL, path, NULL, m, p, block);
}

int frp_read_twin(const char *path, const struct frs_matrix *m,
    struct frs_prep *p, FILE **keep)
{
	const char *name;
	FILE *fp = io_open_in(path, &name);
	struct frp_head f;
	struct frs_matrix tm;
	int rc = 1;

	*keep = NULL;
	memset(&tm, 0, sizeof tm);
	memset(p, 0, sizeof *p);
	if (fp != NULL && read_header(fp, name, NULL, 0, &f) == 0)
		rc = f.sum != frd_checksum(m) ? 2 :
		    load_body(fp, name, &f, m, &tm, p, 0, NULL);
	if (rc == 0 && io_file_size(fp) >= 0)
		*keep = fp;
	else
		io_close_in(fp);
	if (rc == 1)
		frs_clearerr();
	if (rc != 0)
		return rc;
	frd_free(&tm);
	p->m = m;
	p->lev[0] = m->v;
	return 0;
}

int frp_check_fp(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frp_summary *s)
{
	struct frs_matrix m;
	struct frs_prep p;

	memset(s, 0, sizeof *s);
	if (frp_load(fp, name, pre, npre, NULL, &m, &p, 0, s) < 0)
		return -1;
	frs_prep_free(&p);
	frd_free(&m);
	return 0;
}
