#define _POSIX_C_SOURCE 200809L
#include "cli/ptsio.h"
#include "cli/dtoa.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/io.h"
#include "base/wide.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void pts_free(struct frs_points *p)
{
	free(p->x);
	memset(p, 0, sizeof *p);
}

/* ---- reading ---------------------------------------------------------- */

static int rd_getc(struct pts_reader *r)
{
	if (r->ppre < r->npre)
		return r->pre[r->ppre++];
	return getc(r->fp);
}

/* Next line into r->buf without its newline; 0 at end of input. */
static int rd_line(struct pts_reader *r)
{
	size_t n = 0;
	int c;

	while ((c = rd_getc(r)) != EOF && c != '\n') {
		if (n + 2 > r->cap) {
			size_t ncap = r->cap ? r->cap * 2 : 256;
			char *nb = realloc(r->buf, ncap);
			if (nb == NULL)
				return frs_fail("%s: out of memory", r->name);
			r->buf = nb;
			r->cap = ncap;
		}
		r->buf[n++] = (char)c;
	}
	if (c == EOF && ferror(r->fp))
		return frs_fail_errno("%s: read error", r->name);
	if (c == EOF && n == 0)
		return 0;
	if (r->buf == NULL) {
		r->buf = malloc(1);
		if (r->buf == NULL)
			return frs_fail("%s: out of memory", r->name);
	}
	if (n > 0 && r->buf[n - 1] == '\r')
		n--;
	r->buf[n] = '\0';
	r->line++;
	return 1;
}

static int blank_or_comment(const char *s)
{
	while (isspace((unsigned char)*s))
		s++;
	return *s == '\0' || *s == '#';
}

int pts_name_ok(const char *s)
{
	size_t n = 0;

	if (*s >= '0' && *s <= '9')
		return 0;
	for (; s[n] != '\0'; n++)
		if (!isalnum((unsigned char)s[n]) && s[n] != '_')
			return 0;
	return n >= 1 && n < PTS_NAMELEN;
}

/* A header problem: "file:line: what" in text, "file: what" in binary
 * (line 0). */
static int name_fail(const char *name, unsigned long line, const char *what,
    const char *arg)
{
	if (line != 0)
		return frs_fail("%s:%lu: %s%s", name, line, what, arg);
	return frs_fail("%s: %s%s", name, what, arg);
}

/* Names of the extra columns, nn of them so far: one more, valid and not
 * a repeat; -1 with a message naming the file (and line). */
static int add_name(char (*names)[PTS_NAMELEN], unsigned *nn,
    const char *s, size_t len, const char *name, unsigned long line)
{
	char buf[PTS_NAMELEN];

	if (*nn == PTS_MAXCOLS)
		return name_fail(name, line, "more than 16 column names", "");
	if (len == 0 || len >= sizeof buf)
		return name_fail(name, line, len == 0 ? "an empty column name" :
		    "a column name longer than 31 characters", "");
	memcpy(buf, s, len);
	buf[len] = '\0';
	if (!pts_name_ok(buf)) {
		int shown = line != 0;	/* text, and printable */
		for (size_t i = 0; i < len; i++)
			shown &= isprint((unsigned char)buf[i]) != 0;
		return name_fail(name, line, "bad column name ", shown ? buf :
		    "(not of A-Z, a-z, 0-9 and _)");
	}
	for (unsigned j = 0; j < *nn; j++)
		if (strcmp(names[j], buf) == 0)
			return name_fail(name, line, "column name given twice: ",
			    buf);
	memcpy(names[(*nn)++], buf, len + 1);
	return 0;
}

/* "#pts dims=K extra=E count=N [version=2] [names=A,B,...]" */
static int text_header(struct pts_reader *r)
{
	char *tok, *save = NULL;
	char *s = r->buf + 4;
	unsigned nn = 0;
	int have_names = 0;

	for (tok = strtok_r(s, " \t", &save); tok; tok = strtok_r(NULL, " \t",
	    &save)) {
		unsigned long long v;
		char key[16];
		char *end;
		const char *eq = strchr(tok, '=');
		if (eq == NULL || (size_t)(eq - tok) >= sizeof key)
			continue;
		memcpy(key, tok, (size_t)(eq - tok));
		key[eq - tok] = '\0';
		if (strcmp(key, "names") == 0) {
			const char *a = eq + 1, *c;
			have_names = 1;
			nn = 0;
			while (*a != '\0') {
				c = strchr(a, ',');
				if (add_name(r->names, &nn, a, c ? (size_t)(c - a) :
				    strlen(a), r->name, r->line) < 0)
					return -1;
				if (c == NULL)
					break;
				a = c + 1;
				if (*a == '\0')
					return frs_fail("%s:%lu: an empty column "
					    "name", r->name, r->line);
			}
			continue;
		}
		errno = 0;
		v = strtoull(eq + 1, &end, 10);
		if (*end != '\0' || errno != 0)
			return frs_fail("%s:%lu: bad header field '%s'", r->name,
			    r->line, tok);
		if (strcmp(key, "dims") == 0)
			r->dims = (unsigned)(v > 99 ? 99 : v);
		else if (strcmp(key, "extra") == 0)
			r->extra = (unsigned)(v > 99 ? 99 : v);
		else if (strcmp(key, "count") == 0)
			r->count = v;
		else if (strcmp(key, "version") == 0) {
			if (v < 1 || v > PTS_VERSION)
				return frs_fail("%s:%lu: unsupported format "
				    "version %llu (this program reads versions "
				    "1 to %d)", r->name, r->line, v, PTS_VERSION);
			r->version = (unsigned)v;
		}
	}
	if (r->dims < 1 || r->dims + r->extra > PTS_MAXCOLS)
		return frs_fail("%s:%lu: header gives %u coordinates and %u "
		    "extra values (1 to %d columns allowed)", r->name, r->line,
		    r->dims, r->extra, PTS_MAXCOLS);
	if ((have_names || r->version >= 2) && nn != r->extra)
		return frs_fail("%s:%lu: header names %u column%s for %u extra "
		    "value%s", r->name, r->line, nn, nn == 1 ? "" : "s",
		    r->extra, r->extra == 1 ? "" : "s");
	return 0;
}

static int count_fields(const char *s)
{
	int n = 0;

	for (;;) {
		while (*s == ' ' || *s == '\t')
			s++;
		if (*s == '\0')
			return n;
		n++;
		while (*s != '\0' && *s != ' ' && *s != '\t')
			s++;
	}
}

/* Find the layout of a text file: header line or the first data line. */
static int text_open(struct pts_reader *r)
{
	int rc;

	r->text = 1;
	r->version = 1;
	while ((rc = rd_line(r)) == 1) {
		if (strncmp(r->buf, "#pts", 4) == 0 && r->dims == 0) {
			if (text_header(r) < 0)
				return -1;
			continue;
		}
		if (blank_or_comment(r->buf))
			continue;
		r->have_line = 1;
		if (r->dims == 0) {
			int f = count_fields(r->buf);
			if (f > PTS_MAXCOLS)
				return frs_fail("%s:%lu: %d columns (at most %d)",
				    r->name, r->line, f, PTS_MAXCOLS);
			r->dims = (unsigned)f;
		}
		return 0;
	}
	if (rc < 0)
		return -1;
	if (r->dims == 0)
		return frs_fail("%s: empty file", r->name);
	return 0;
}

/* Version 2's names block, L bytes after the header: the extra columns'
 * names, each ended by a NUL, then NULs. */
static int binary_names(struct pts_reader *r, uint32_t len)
{
	char blk[PTS_MAXNAMES];
	size_t got, at = 0;
	unsigned nn = 0;

	if (len % 8 != 0 || len > sizeof blk || (len == 0) != (r->extra == 0))
		return frs_fail("%s: header gives %u bytes of column names for "
		    "%u extra values (%s)", r->name, len, r->extra, r->extra ==
		    0 ? "0 needed" : "a multiple of 8 up to 512 needed");
	got = fread(blk, 1, len, r->fp);
	if (got != len) {
		if (ferror(r->fp))
			return frs_fail_errno("%s: read error", r->name);
		return frs_fail("%s: truncated header (%zu of %u bytes of "
		    "column names)", r->name, got, len);
	}
	while (nn < r->extra) {
		const char *e = memchr(blk + at, '\0', len - at);
		if (e == NULL)
			return frs_fail("%s: %u of %u column names in the "
			    "header", r->name, nn, r->extra);
		if (add_name(r->names, &nn, blk + at, (size_t)(e - (blk + at)),
		    r->name, 0) < 0)
			return -1;
		at = (size_t)(e - blk) + 1;
	}
	for (; at < len; at++)
		if (blk[at] != '\0')
			return frs_fail("%s: more than %u column names in the "
			    "header", r->name, r->extra);
	return 0;
}

static int binary_open(struct pts_reader *r)
{
	const unsigned char *h = r->pre;
	uint32_t version = io_get_u32(h + 8), namelen = 0;
	long long fsize = io_file_size(r->fp);

	r->npre = r->ppre = 0;
	if (version < 1 || version > PTS_VERSION)
		return frs_fail("%s: unsupported format version %u (this program "
		    "reads versions 1 to %d)", r->name, version, PTS_VERSION);
	r->version = version;
	r->dims = io_get_u32(h + 12);
	r->extra = io_get_u32(h + 16);
	r->count = io_get_u64(h + 24);
	if (r->dims < 1 || r->dims > PTS_MAXCOLS || r->extra > PTS_MAXCOLS ||
	    r->dims + r->extra > PTS_MAXCOLS)
		return frs_fail("%s: header gives %u coordinates and %u extra "
		    "values (1 to %d columns allowed)", r->name, r->dims,
		    r->extra, PTS_MAXCOLS);
	if (version >= 2) {
		namelen = io_get_u32(h + 20);
		if (binary_names(r, namelen) < 0)
			return -1;
	}
	if (fsize >= 0) {
		unsigned long long rec = 8ull * (r->dims + r->extra);
		unsigned long long body = (unsigned long long)fsize - PTS_HEADER -
		    namelen;
		if (r->count == 0 && body % rec != 0)
			return frs_fail("%s: truncated record at the end (%llu "
			    "bytes after the header are not a multiple of %llu)",
			    r->name, body, rec);
		if (r->count != 0 && r->count > UINT64_MAX / rec)
			return frs_fail("%s: header says %llu points but the file "
			    "holds %llu bytes of records (more than 2^64 needed)",
			    r->name, (unsigned long long)r->count, body);
		if (r->count != 0 && body != r->count * rec)
			return frs_fail("%s: header says %llu points but the file "
			    "holds %llu bytes of records (%llu needed)", r->name,
			    (unsigned long long)r->count, body,
			    (unsigned long long)(r->count * rec));
	}
	return 0;
}

int pts_reader_open(struct pts_reader *r, const char *path)
{
	memset(r, 0, sizeof *r);
	r->fp = io_open_in(path, &r->name);
	if (r->fp == NULL)
		return -1;
	r->npre = fread(r->pre, 1, PTS_HEADER, r->fp);
	if (ferror(r->fp)) {
		frs_fail_errno("%s: read error", r->name);
		goto fail;
	}
	if (r->npre == 0) {
		frs_fail("%s: empty file", r->name);
		goto fail;
	}
	if (r->npre >= 8 && memcmp(r->pre, PTS_MAGIC, 8) == 0) {
		if (r->npre < PTS_HEADER) {
			frs_fail("%s: truncated header (%zu of %d bytes)", r->name,
			    r->npre, PTS_HEADER);
			goto fail;
		}
		if (binary_open(r) < 0)
			goto fail;
		return 0;
	}
	if (memchr(r->pre, '\0', r->npre) != NULL || (r->pre[0] & 0x80)) {
		frs_fail("%s: not a point file (wrong magic, and not text)",
		    r->name);
		goto fail;
	}
	if (text_open(r) < 0)
		goto fail;
	return 0;
fail:
	pts_reader_close(r);
	return -1;
}

static int check_record(struct pts_reader *r, const double *rec)
{
	for (unsigned i = 0; i < r->dims + r->extra; i++) {
		if (!isfinite(rec[i]))
			goto bad;
		if (i < r->dims && !(rec[i] >= 0.0 && rec[i] < 1.0))
			goto bad;
	}
	return 0;
bad:
	for (unsigned i = 0; i < r->dims + r->extra; i++)
		if (!isfinite(rec[i]) || (i < r->dims && !(rec[i] >= 0.0 &&
		    rec[i] < 1.0))) {
			if (r->text)
				return frs_fail("%s:%lu: %s %u is %.17g, %s",
				    r->name, r->line, i < r->dims ? "coordinate" :
				    "value", i + 1, rec[i], isfinite(rec[i]) ?
				    "outside [0,1)" : "not finite");
			return frs_fail("%s: point %llu: %s %u is %.17g, %s",
			    r->name, (unsigned long long)r->got,
			    i < r->dims ? "coordinate" : "value", i + 1, rec[i],
			    isfinite(rec[i]) ? "outside [0,1)" : "not finite");
		}
	return -1;
}

static int parse_line(struct pts_reader *r, double *rec)
{
	char *s = r->buf, *end;
	unsigned ncol = r->dims + r->extra;

	for (unsigned i = 0; i < ncol; i++) {
		while (*s == ' ' || *s == '\t')
			s++;
		if (*s == '\0')
			return frs_fail("%s:%lu: %u values, expected %u", r->name,
			    r->line, i, ncol);
		errno = 0;
		rec[i] = strtod(s, &end);
		if (end == s || (*end != '\0' && *end != ' ' && *end != '\t')) {
			int len = 0;
			while (s[len] && s[len] != ' ' && s[len] != '\t' &&
			    len < 40)
				len++;
			return frs_fail("%s:%lu: '%.*s' is not a number", r->name,
			    r->line, len, s);
		}
		s = end;
	}
	while (*s == ' ' || *s == '\t')
		s++;
	if (*s != '\0')
		return frs_fail("%s:%lu: more than %u values", r->name, r->line,
		    ncol);
	return 0;
}

static int text_next(struct pts_reader *r, double *rec)
{
	int rc;

	if (r->have_line)
		r->have_line = 0;
	else {
		do
			rc = rd_line(r);
		while (rc == 1 && blank_or_comment(r->buf));
		if (rc <= 0) {
			if (rc == 0 && r->count != 0 && r->got != r->count)
				return frs_fail("%s: truncated: %llu of %llu "
				    "points", r->name,
				    (unsigned long long)r->got,
				    (unsigned long long)r->count);
			return rc;
		}
	}
	if (r->count != 0 && r->got == r->count)
		return frs_fail("%s:%lu: more points than the header's count "
		    "%llu", r->name, r->line, (unsigned long long)r->count);
	if (parse_line(r, rec) < 0)
		return -1;
	return 1;
}

static int binary_next(struct pts_reader *r, double *rec)
{
	size_t ncol = r->dims + r->extra;
	size_t got;

	if (r->count != 0 && r->got == r->count) {
		/* A stream has no length to check up front. */
		if (getc(r->fp) != EOF)
			return frs_fail("%s: data after the %llu points of the "
			    "header", r->name, (unsigned long long)r->count);
		return 0;
	}
	got = fread(rec, 8, ncol, r->fp);
	if (got == 0 && !ferror(r->fp)) {
		if (r->count != 0)
			return frs_fail("%s: truncated: %llu of %llu points",
			    r->name, (unsigned long long)r->got,
			    (unsigned long long)r->count);
		return 0;
	}
	if (got != ncol) {
		if (ferror(r->fp))
			return frs_fail_errno("%s: read error", r->name);
		return frs_fail("%s: truncated record after %llu points",
		    r->name, (unsigned long long)r->got);
	}
	io_le_f64(rec, ncol);
	return 1;
}

int pts_reader_next(struct pts_reader *r, double *rec)
{
	int rc = r->text ? text_next(r, rec) : binary_next(r, rec);

	if (rc != 1)
		return rc;
	if (check_record(r, rec) < 0)
		return -1;
	r->got++;
	return 1;
}

void pts_reader_close(struct pts_reader *r)
{
	io_close_in(r->fp);
	free(r->buf);
	memset(r, 0, sizeof *r);
}

#define PTS_PREALLOC ((uint64_t)1 << 16)

int pts_read(const char *path, struct frs_points *p)
{
	struct pts_reader r;
	size_t cap = 0, ncol;
	double rec[PTS_MAXCOLS];
	int rc;

	memset(p, 0, sizeof *p);
	if (pts_reader_open(&r, path) < 0)
		return -1;
	p->dims = r.dims;
	p->extra = r.extra;
	p->version = r.version;
	memcpy(p->names, r.names, sizeof p->names);
	ncol = r.dims + r.extra;
	/* The header's count only sizes the first buffer, and at most 2^16
	 * records of it: a damaged count must not allocate without bound;
	 * the buffer grows as the records arrive. */
	if (r.count != 0)
		cap = (size_t)(r.count < PTS_PREALLOC ? r.count : PTS_PREALLOC);
	while ((rc = pts_reader_next(&r, rec)) == 1) {
		if (p->n == cap || p->x == NULL) {
			size_t ncap = cap > p->n ? cap : (cap ? cap * 2 : 1024);
			double *nx = mem_realloc(r.name, p->x, ncap * ncol,
			    sizeof *nx);
			if (nx == NULL) {
				rc = -1;
				break;
			}
			p->x = nx;
			cap = ncap;
		}
		memcpy(p->x + p->n * ncol, rec, ncol * sizeof *rec);
		p->n++;
	}
	pts_reader_close(&r);
	if (rc < 0)
		pts_free(p);
	return rc < 0 ? -1 : 0;
}

int pts_column(const struct frs_points *p, const char *name)
{
	for (unsigned j = 0; j < p->extra; j++)
		if (strcmp(p->names[j], name) == 0)
			return (int)(p->dims + j);
	return -1;
}

/* ---- writing ---------------------------------------------------------- */

static void header_bytes(unsigned char *h, unsigned dims, unsigned extra,
    uint32_t namelen, uint64_t count)
{
	memcpy(h, PTS_MAGIC, 8);
	io_put_u32(h + 8, PTS_VERSION);
	io_put_u32(h + 12, dims);
	io_put_u32(h + 16, extra);
	io_put_u32(h + 20, namelen);
	io_put_u64(h + 24, count);
}

int pts_writer_begin(struct pts_writer *w, FILE *fp, const char *name,
    unsigned dims, unsigned extra, const char *const *names, uint64_t count,
    int text)
{
	char blk[PTS_MAXNAMES];
	size_t len = 0;

	memset(w, 0, sizeof *w);
	w->fp = fp;
	w->name = name;
	w->dims = dims;
	w->extra = extra;
	w->count = count;
	w->text = text;
	if (dims < 1 || dims + extra > PTS_MAXCOLS)
		return frs_fail("%s: %u coordinates and %u extra values per "
		    "point are not supported", name, dims, extra);
	memset(blk, 0, sizeof blk);
	for (unsigned j = 0; j < extra; j++) {
		const char *nm = names != NULL ? names[j] : NULL;
		if (nm == NULL || !pts_name_ok(nm))
			return frs_fail("%s: internal error: extra column %u has "
			    "no valid name", name, j + 1);
		for (unsigned i = 0; i < j; i++)
			if (strcmp(names[i], nm) == 0)
				return frs_fail("%s: internal error: two extra "
				    "columns named %s", name, nm);
		memcpy(blk + len, nm, strlen(nm));
		len += strlen(nm) + 1;
	}
	w->namelen = (uint32_t)((len + 7) / 8 * 8);
	if (text) {
		if (fprintf(fp, "#pts dims=%u extra=%u count=%llu version=%d",
		    dims, extra, (unsigned long long)count, PTS_VERSION) < 0)
			return frs_fail_errno("%s: write error", name);
		for (unsigned j = 0; j < extra; j++)
			if (fprintf(fp, "%s%s", j ? "," : " names=", names[j]) < 0)
				return frs_fail_errno("%s: write error", name);
		if (putc('\n', fp) == EOF)
			return frs_fail_errno("%s: write error", name);
		return 0;
	}
	{
		unsigned char h[PTS_HEADER];
		header_bytes(h, dims, extra, w->namelen, count);
		if (fwrite(h, 1, sizeof h, fp) != sizeof h ||
		    fwrite(blk, 1, w->namelen, fp) != w->namelen)
			return frs_fail_errno("%s: write error", name);
	}
	return 0;
}

/* Coordinates outside [0, 1) are the writer's caller's bug: those of n
 * records, record k's at pts + k * stride. */
FRS_WIDE static int check_coords(const struct pts_writer *w,
    const double *pts, size_t stride, size_t n)
{
	int bad = 0;

	/* Packed: one pass without exits (it vectorises), then the
	 * culprit. */
	if (stride == w->dims) {
		for (size_t k = 0; k < w->dims * n; k++)
			bad |= !(pts[k] >= 0.0) | !(pts[k] < 1.0);
		if (!bad)
			return 0;
	}
	for (size_t k = 0; k < n; k++)
		for (unsigned i = 0; i < w->dims; i++) {
			double v = pts[k * stride + i];
			if (!(v >= 0.0 && v < 1.0))
				return frs_fail("%s: internal error: coordinate "
				    "%.17g of point %llu is outside [0,1)", w->name,
				    v, (unsigned long long)(w->written + k));
		}
	return 0;
}

/* Lines are gathered up to TEXT_CHUNK bytes and written by one fwrite;
 * the buffer has room for one more line past that (each value at most
 * FRS_DTOA_BUF - 1 characters and its separator, then frs_dtoa's NUL). */
#define TEXT_CHUNK 32768

/* n records as text lines: each value in frs_dtoa's shortest round-trip
 * form, blank-separated. */
static int put_text(const struct pts_writer *w, const double *recs,
    size_t n)
{
	unsigned ncol = w->dims + w->extra;
	char buf[TEXT_CHUNK + PTS_MAXCOLS * FRS_DTOA_BUF];
	size_t len = 0;

	for (size_t k = 0; k < n; k++, recs += ncol) {
		for (unsigned i = 0; i < ncol; i++) {
			len += frs_dtoa(recs[i], buf + len);
			buf[len++] = i + 1 < ncol ? ' ' : '\n';
		}
		if (len >= TEXT_CHUNK || k + 1 == n) {
			if (fwrite(buf, 1, len, w->fp) != len)
				return frs_fail_errno("%s: write error", w->name);
			len = 0;
		}
	}
	return 0;
}

/* n records side by side, checked: as text or little-endian doubles. */
static int put_records(struct pts_writer *w, const double *recs, size_t n)
{
	size_t nval = n * (w->dims + w->extra);

	if (w->text) {
		if (put_text(w, recs, n) < 0)
			return -1;
		w->written += n;
		return 0;
	}
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
	{
		double tmp[1024];
		for (size_t i = 0; i < nval; i += 1024) {
			size_t m = nval - i < 1024 ? nval - i : 1024;
			memcpy(tmp, recs + i, m * sizeof *tmp);
			io_le_f64(tmp, m);
			if (fwrite(tmp, 8, m, w->fp) != m)
				return frs_fail_errno("%s: write error", w->name);
		}
	}
#else
	if (fwrite(recs, 8, nval, w->fp) != nval)
		return frs_fail_errno("%s: write error", w->name);
#endif
	w->written += n;
	return 0;
}

int pts_writer_put_n(struct pts_writer *w, const double *recs, size_t n)
{
	if (check_coords(w, recs, w->dims + w->extra, n) < 0)
		return -1;
	return put_records(w, recs, n);
}

/* m values, one a stride apart, into every ncol-th place of r: a
 * column at a time keeps each loop a plain strided copy. */
static void gather(double *r, size_t ncol, const double *v, size_t stride,
    size_t m)
{
	for (size_t i = 0; i < m; i++)
		r[i * ncol] = v[i * stride];
}

/* Whether the columns are the records' own: each right after the
 * coordinates and the columns before it, a record apart. */
static int side_by_side(const struct pts_writer *w, const double *pts,
    size_t stride, const struct pts_col *col)
{
	if (stride != w->dims + w->extra)
		return 0;
	for (unsigned j = 0; j < w->extra; j++)
		if (col[j].v != pts + w->dims + j || col[j].stride != stride)
			return 0;
	return 1;
}

int pts_writer_put_cols(struct pts_writer *w, const double *pts,
    size_t stride, const struct pts_col *col, size_t n)
{
	unsigned dims = w->dims, ncol = dims + w->extra;
	double buf[4096];
	size_t per = sizeof buf / sizeof *buf / ncol;

	if (check_coords(w, pts, stride, n) < 0)
		return -1;
	if (side_by_side(w, pts, stride, col))
		return put_records(w, pts, n);
	/* Gathered a piece at a time into a buffer that stays in the
	 * cache: one pass over the caller's arrays. */
	for (size_t b = 0; b < n; b += per) {
		size_t m = n - b < per ? n - b : per;
		for (unsigned a = 0; a < dims; a++)
			gather(buf + a, ncol, pts + b * stride + a, stride, m);
		for (unsigned j = 0; j < w->extra; j++)
			gather(buf + dims + j, ncol, col[j].v + b * col[j].stride,
			    col[j].stride, m);
		if (put_records(w, buf, m) < 0)
			return -1;
	}
	return 0;
}

int pts_writer_put(struct pts_writer *w, const double *rec)
{
	unsigned ncol = w->dims + w->extra;

	if (check_coords(w, rec, ncol, 1) < 0)
		return -1;
	if (w->text) {
		if (put_text(w, rec, 1) < 0)
			return -1;
	} else {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
		double tmp[PTS_MAXCOLS];
		memcpy(tmp, rec, ncol * sizeof *tmp);
		io_le_f64(tmp, ncol);
		rec = tmp;
#endif
		if (fwrite(rec, 8, ncol, w->fp) != ncol)
			return frs_fail_errno("%s: write error", w->name);
	}
	w->written++;
	return 0;
}

int pts_writer_end(struct pts_writer *w)
{
	if (w->count != 0 && w->written != w->count)
		return frs_fail("%s: internal error: %llu points announced, %llu "
		    "written", w->name, (unsigned long long)w->count,
		    (unsigned long long)w->written);
	if (w->count == 0 && !w->text && w->written > 0) {
		/* Patch the true count in when the stream can seek. */
		long pos = ftell(w->fp);
		unsigned char h[PTS_HEADER];
		header_bytes(h, w->dims, w->extra, w->namelen, w->written);
		if (pos >= 0 && fseek(w->fp, 0, SEEK_SET) == 0) {
			if (fwrite(h, 1, sizeof h, w->fp) != sizeof h ||
			    fseek(w->fp, pos, SEEK_SET) != 0)
				return frs_fail_errno("%s: write error", w->name);
		}
	}
	if (fflush(w->fp) != 0)
		return frs_fail_errno("%s: write error", w->name);
	return 0;
}

int pts_write(FILE *fp, const char *name, const struct frs_points *p,
    int text)
{
	struct pts_writer w;
	const char *names[PTS_MAXCOLS];

	for (unsigned j = 0; j < p->extra && j < PTS_MAXCOLS; j++)
		names[j] = p->names[j];
	if (pts_writer_begin(&w, fp, name, p->dims, p->extra, names, p->n,
	    text) < 0)
		return -1;
	if (pts_writer_put_n(&w, p->x, p->n) < 0)
		return -1;
	return pts_writer_end(&w);
}
