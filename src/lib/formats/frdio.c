#define _POSIX_C_SOURCE 200809L
#include "formats/frdio.h"
#include "base/err.h"
#include "base/io.h"
#include "base/mem.h"
#include "base/num.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int frd_alloc(struct frs_matrix *m, unsigned dims, uint32_t w, uint32_t h,
    uint32_t d, const char *params)
{
	uint64_t n = (uint64_t)w * h * d;
	char what[64];

	memset(m, 0, sizeof *m);
	if (dims < 2 || dims > 3 || w == 0 || h == 0 || d == 0 ||
	    (dims == 2 && d != 1))
		return frs_fail("impossible matrix size %ux%ux%u (k = %u)", w, h,
		    d, dims);
	if (n > FRD_MAX_ELEMS || n > SIZE_MAX / sizeof(uint32_t))
		return frs_fail("matrix of %llu elements is too large",
		    (unsigned long long)n);
	snprintf(what, sizeof what, dims == 2 ? "%ux%u matrix" :
	    "%ux%ux%u matrix", w, h, d);
	if ((m->v = mem_calloc(what, n, sizeof *m->v)) == NULL)
		return -1;
	if ((m->params = strdup(params ? params : "")) == NULL) {
		frd_free(m);
		frs_fail("out of memory for a matrix's parameters");
		frs_set_errkind(FRS_ERRKIND_MEM);
		return -1;
	}
	m->dims = dims;
	m->w = w;
	m->h = h;
	m->d = d;
	m->n = (size_t)n;
	return 0;
}

void frd_free(struct frs_matrix *m)
{
	free(m->v);
	free(m->params);
	memset(m, 0, sizeof *m);
}

static int parse_header(const unsigned char *h, const char *name,
    unsigned *dims, uint32_t sz[3], uint32_t *plen)
{
	uint32_t version;

	if (memcmp(h, FRD_MAGIC, 8) != 0)
		return frs_fail("%s: not a threshold matrix (wrong magic)", name);
	version = io_get_u32(h + 8);
	if (version != FRD_VERSION)
		return frs_fail("%s: unsupported format version %u (this "
		    "program reads version %d)", name, version, FRD_VERSION);
	*dims = io_get_u32(h + 12);
	for (int i = 0; i < 3; i++)
		sz[i] = io_get_u32(h + 16 + 4 * i);
	*plen = io_get_u32(h + 28);
	if (*dims != 2 && *dims != 3)
		return frs_fail("%s: dimension count %u is not 2 or 3", name,
		    *dims);
	if (sz[0] == 0 || sz[1] == 0 || sz[2] == 0 || (*dims == 2 && sz[2] != 1))
		return frs_fail("%s: impossible size %ux%ux%u", name, sz[0],
		    sz[1], sz[2]);
	if ((uint64_t)sz[0] * sz[1] * sz[2] > FRD_MAX_ELEMS)
		return frs_fail("%s: size %ux%ux%u exceeds 2^32 elements", name,
		    sz[0], sz[1], sz[2]);
	if (*plen > FRD_MAX_PARAMS)
		return frs_fail("%s: parameter text of %u bytes is too long",
		    name, *plen);
	return 0;
}

static int read_params(FILE *fp, const char *name, uint32_t plen,
    char **out)
{
	char *p = malloc((size_t)plen + 1);

	if (p == NULL)
		return frs_fail("%s: out of memory", name);
	if (io_read_exact(fp, name, p, plen, "parameter text") < 0) {
		free(p);
		return -1;
	}
	p[plen] = '\0';
	if (memchr(p, '\0', plen) != NULL) {
		free(p);
		return frs_fail("%s: parameter text contains a NUL byte", name);
	}
	*out = p;
	return 0;
}

/* Value i of the scan below. */
static inline void scan_value(const struct frs_matrix *m, uint64_t *seen,
    size_t i, size_t *over, size_t *rep)
{
	uint32_t v = m->v[i];

	if (v >= m->n) {
		*over = *over < i ? *over : i;
		return;
	}
	if (seen == NULL)
		return;
	if (seen[v / 64] >> (v % 64) & 1)
		*rep = *rep < i ? *rep : i;
	seen[v / 64] |= (uint64_t)1 << (v % 64);
}

/* One pass over the values: the index of the first not below the
 * element count (*over) and, given seen (a zeroed bit per value), of
 * the first that repeats an earlier one (*rep); m->n where none is. */
static void scan_values(const struct frs_matrix *m, uint64_t *seen,
    size_t *over, size_t *rep)
{
	*over = *rep = m->n;
	for (size_t i = 0; i < m->n; i++)
		scan_value(m, seen, i, over, rep);
}

/* A zeroed bit per value of m, NULL (no message) when out of memory. */
static uint64_t *value_bits(const struct frs_matrix *m)
{
	size_t words = (m->n + 63) / 64;

	return calloc(words ? words : 1, sizeof(uint64_t));
}

/* The first repeated value, rep, and where it is. */
static int repeated(const struct frs_matrix *m, const char *name, size_t rep)
{
	return frs_fail("%s: not a permutation: value %u repeats at (%zu, "
	    "%zu, %zu)", name, m->v[rep], rep % m->w, rep / m->w % m->h,
	    rep / ((size_t)m->w * m->h));
}

/* scan_values' answer as frd_check_permutation's: 0, or -1 after
 * frs_fail naming the first value out of range or repeated. */
static int not_perm(const struct frs_matrix *m, const char *name,
    size_t over, size_t rep)
{
	if (over < rep)
		return frs_fail("%s: value %u at element %zu is out of range", name,
		    m->v[over], over);
	return rep < m->n ? repeated(m, name, rep) : 0;
}

/* Every value below n; m->perm found in the same pass, or required
 * (enum frd_perm). */
static int check_values(struct frs_matrix *m, const char *name, int perm)
{
	uint64_t *seen = perm != FRD_PERM_NO ? value_bits(m) : NULL;
	size_t over, rep;

	if (perm == FRD_PERM_NEED && seen == NULL)
		return frs_fail("%s: out of memory", name);
	scan_values(m, seen, &over, &rep);
	m->perm = seen != NULL && over == m->n && rep == m->n;
	free(seen);
	if (over < m->n)
		return frs_fail("%s: value %u at element %zu is not below the "
		    "element count %zu", name, m->v[over], over, m->n);
	if (perm == FRD_PERM_NEED && rep < m->n)
		return repeated(m, name, rep);
	return 0;
}

int frd_read_fp(FILE *fp, const char *name, struct frs_matrix *m)
{
	return frd_read_pre(fp, name, NULL, 0, m, FRD_PERM_NO);
}

int frd_read_pre(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, struct frs_matrix *m, int perm)
{
	unsigned char h[FRD_HEADER];
	unsigned dims = 0;
	uint32_t sz[3] = { 0, 0, 0 }, plen = 0;
	long long fsize = io_file_size(fp);
	char *params = NULL;
	int c;

	memset(m, 0, sizeof *m);
	if (io_read_header(fp, name, pre, npre, h, sizeof h) < 0)
		return -1;
	if (parse_header(h, name, &dims, sz, &plen) < 0)
		return -1;
	if (fsize >= 0) {
		unsigned long long want = FRD_HEADER + (unsigned long long)plen +
		    4ull * sz[0] * sz[1] * sz[2];
		if ((unsigned long long)fsize != want)
			return frs_fail("%s: file has %lld bytes but its header "
			    "(%ux%ux%u values) needs %llu", name, fsize, sz[0],
			    sz[1], sz[2], want);
	}
	if (read_params(fp, name, plen, &params) < 0)
		return -1;
	if (frd_alloc(m, dims, sz[0], sz[1], sz[2], params) < 0) {
		free(params);
		return frs_fail_context(name);
	}
	free(params);
	if (io_read_exact(fp, name, m->v, m->n * 4, "values") < 0)
		goto fail;
	io_le_u32(m->v, m->n);
	if ((c = fgetc(fp)) != EOF) {
		frs_fail("%s: trailing data after the values", name);
		goto fail;
	}
	if (check_values(m, name, perm) < 0)
		goto fail;
	return 0;
fail:
	frd_free(m);
	return -1;
}

static int read_matrix(FILE *fp, const char *name, void *m)
{
	return frd_read_fp(fp, name, m);
}

int frd_read(const char *path, struct frs_matrix *m)
{
	return io_read_path(path, read_matrix, m);
}

static int read_perm(FILE *fp, const char *name, void *m)
{
	return frd_read_pre(fp, name, NULL, 0, m, FRD_PERM_NEED);
}

int frd_read_perm(const char *path, struct frs_matrix *m)
{
	return io_read_path(path, read_perm, m);
}

int frd_write(FILE *fp, const char *name, const struct frs_matrix *m)
{
	unsigned char h[FRD_HEADER];
	size_t plen = strlen(m->params);
	int ok;

	if (plen > FRD_MAX_PARAMS)
		return frs_fail("%s: parameter text too long", name);
	memcpy(h, FRD_MAGIC, 8);
	io_put_u32(h + 8, FRD_VERSION);
	io_put_u32(h + 12, m->dims);
	io_put_u32(h + 16, m->w);
	io_put_u32(h + 20, m->h);
	io_put_u32(h + 24, m->d);
	io_put_u32(h + 28, (uint32_t)plen);
	ok = fwrite(h, 1, sizeof h, fp) == sizeof h &&
	    fwrite(m->params, 1, plen, fp) == plen;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
	for (size_t i = 0; ok && i < m->n; i++) {
		unsigned char b[4];
		io_put_u32(b, m->v[i]);
		ok = fwrite(b, 1, 4, fp) == 4;
	}
#else
	ok = ok && fwrite(m->v, 4, m->n, fp) == m->n;
#endif
	if (!ok)
		return frs_fail_errno("%s: write error", name);
	return 0;
}

int frd_check_permutation(const struct frs_matrix *m, const char *name)
{
	uint64_t *seen;
	size_t over, rep;

	if (m->perm)
		return 0;
	if ((seen = value_bits(m)) == NULL)
		return frs_fail("%s: out of memory", name);
	scan_values(m, seen, &over, &rep);
	free(seen);
	return not_perm(m, name, over, rep);
}

/* FNV-1a over the 4 little-endian bytes of v. */
static inline uint64_t fnv_u32(uint64_t h, uint32_t v)
{
	for (int b = 0; b < 4; b++)
		h = (h ^ ((v >> (8 * b)) & 0xff)) * 0x100000001b3ull;
	return h;
}

/* The sizes' part of the checksum. */
static uint64_t fnv_head(const struct frs_matrix *m)
{
	uint32_t head[4] = { m->dims, m->w, m->h, m->d };
	uint64_t h = 0xcbf29ce484222325ull;

	for (int i = 0; i < 4; i++)
		h = fnv_u32(h, head[i]);
	return h;
}

uint64_t frd_checksum(const struct frs_matrix *m)
{
	uint64_t h = fnv_head(m);

	for (size_t i = 0; i < m->n; i++)
		h = fnv_u32(h, m->v[i]);
	return h;
}

int frd_check_sum(const struct frs_matrix *m, const char *name,
    uint64_t want)
{
	uint64_t h = fnv_head(m), *seen = NULL;
	size_t over = m->n, rep = m->n;

	if (!m->perm && (seen = value_bits(m)) == NULL)
		return frs_fail("%s: out of memory", name);
	/* The chain of multiplications is latency-bound: the scan of
	 * scan_values runs beside it. */
	for (size_t i = 0; i < m->n; i++) {
		h = fnv_u32(h, m->v[i]);
		if (seen != NULL)
			scan_value(m, seen, i, &over, &rep);
	}
	free(seen);
	if (h != want)
		return frs_fail("%s: the matrix does not match its recorded "
		    "checksum (damaged file)", name);
	return not_perm(m, name, over, rep);
}

/* A value and its position, ranked by value, then position. */
struct rank_kv {
	uint64_t v;
	uint32_t i;
};

static int rank_cmp(const void *a, const void *b)
{
	const struct rank_kv *x = a, *y = b;

	return x->v != y->v ? NUM_CMP(x->v, y->v) : NUM_CMP(x->i, y->i);
}

int frd_rank(struct frs_matrix *m)
{
	struct rank_kv *t = malloc(m->n * sizeof *t);

	if (t == NULL)
		return frs_fail("out of memory");
	for (size_t i = 0; i < m->n; i++)
		t[i] = (struct rank_kv){ m->v[i], (uint32_t)i };
	qsort(t, m->n, sizeof *t, rank_cmp);
	for (size_t r = 0; r < m->n; r++)
		m->v[t[r].i] = (uint32_t)r;
	free(t);
	return 0;
}
