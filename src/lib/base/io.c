#define _POSIX_C_SOURCE 200809L
#include "base/io.h"
#include "base/err.h"
#include "base/mem.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

FILE *io_open_in(const char *path, const char **name)
{
	FILE *fp;
	struct stat st;

	if (path == NULL || strcmp(path, "-") == 0) {
		*name = "<stdin>";
		return stdin;
	}
	*name = path;
	fp = fopen(path, "rb");
	if (fp == NULL) {
		frs_fail_errno("%s", path);
		frs_set_errkind(FRS_ERRKIND_IO);
		return NULL;
	}
	if (fstat(fileno(fp), &st) == 0 && S_ISDIR(st.st_mode)) {
		fclose(fp);
		frs_fail("%s: is a directory", path);
		frs_set_errkind(FRS_ERRKIND_IO);
		return NULL;
	}
	return fp;
}

void io_close_in(FILE *fp)
{
	if (fp != NULL && fp != stdin)
		fclose(fp);
}

long long io_file_size(FILE *fp)
{
	struct stat st;

	if (fstat(fileno(fp), &st) != 0 || !S_ISREG(st.st_mode))
		return -1;
	return (long long)st.st_size;
}

int io_read_exact(FILE *fp, const char *name, void *buf, size_t n,
    const char *what)
{
	size_t got = fread(buf, 1, n, fp);

	if (got == n)
		return 0;
	if (ferror(fp))
		return frs_fail_errno("%s: read error", name);
	if (got == 0 && strcmp(what, "header") == 0 && ftell(fp) <= 0)
		return frs_fail("%s: empty file", name);
	return frs_fail("%s: truncated %s (%zu of %zu bytes)", name, what,
	    got, n);
}

int io_read_header(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, unsigned char *buf, size_t n)
{
	size_t got;

	if (npre == 0)
		return io_read_exact(fp, name, buf, n, "header");
	memcpy(buf, pre, npre);
	got = fread(buf + npre, 1, n - npre, fp);
	if (ferror(fp))
		return frs_fail_errno("%s: read error", name);
	if (npre + got < n)
		return frs_fail("%s: truncated header (%zu of %zu bytes)", name,
		    npre + got, n);
	return 0;
}

int io_slurp(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, unsigned char **buf, size_t *len)
{
	size_t cap = 1 << 16, n = npre;
	unsigned char *b = malloc(cap);

	if (b == NULL)
		return frs_fail("%s: out of memory", name);
	if (npre > 0)	/* a peek's few bytes */
		memcpy(b, pre, npre);
	for (;;) {
		size_t got;
		if (n == cap) {
			unsigned char *nb;
			if (cap > SIZE_MAX / 2) {
				free(b);
				return frs_fail("%s: file too large", name);
			}
			nb = mem_realloc(name, b, cap, 2);
			if (nb == NULL) {
				free(b);
				return -1;
			}
			b = nb;
			cap *= 2;
		}
		/* n < cap here, so at the end too: room for a NUL. */
		got = fread(b + n, 1, cap - n, fp);
		n += got;
		if (got == 0)
			break;
	}
	if (ferror(fp)) {
		free(b);
		return frs_fail_errno("%s: read error", name);
	}
	*buf = b;
	*len = n;
	return 0;
}

int io_read_path(const char *path,
    int (*read)(FILE *fp, const char *name, void *obj), void *obj)
{
	const char *name;
	FILE *fp = io_open_in(path, &name);
	int rc;

	if (fp == NULL)
		return -1;
	rc = read(fp, name, obj);
	io_close_in(fp);
	return rc;
}

struct slurp {
	const char **name;
	unsigned char **buf;
	size_t *len;
};

static int slurp_fp(FILE *fp, const char *name, void *ctx)
{
	struct slurp *s = ctx;

	*s->name = name;
	return io_slurp(fp, name, NULL, 0, s->buf, s->len);
}

int io_slurp_path(const char *path, const char **name, unsigned char **buf,
    size_t *len)
{
	struct slurp s = { name, buf, len };

	return io_read_path(path, slurp_fp, &s);
}

uint32_t io_get_u32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	    (uint32_t)p[3] << 24;
}

uint64_t io_get_u64(const unsigned char *p)
{
	return (uint64_t)io_get_u32(p) | (uint64_t)io_get_u32(p + 4) << 32;
}

void io_put_u32(unsigned char *p, uint32_t v)
{
	for (int i = 0; i < 4; i++)
		p[i] = (unsigned char)(v >> (8 * i));
}

void io_put_u64(unsigned char *p, uint64_t v)
{
	io_put_u32(p, (uint32_t)v);
	io_put_u32(p + 4, (uint32_t)(v >> 32));
}

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
void io_le_u32(uint32_t *v, size_t n)
{
	for (size_t i = 0; i < n; i++)
		v[i] = __builtin_bswap32(v[i]);
}

void io_le_f64(double *v, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		uint64_t u;
		memcpy(&u, &v[i], 8);
		u = __builtin_bswap64(u);
		memcpy(&v[i], &u, 8);
	}
}
#else
void io_le_u32(uint32_t *v, size_t n)
{
	(void)v;
	(void)n;
}

void io_le_f64(double *v, size_t n)
{
	(void)v;
	(void)n;
}
#endif
