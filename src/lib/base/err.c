#define _POSIX_C_SOURCE 200809L
#include "base/err.h"

#include <errno.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>

/* One message per thread, so that library calls in different threads
 * (libfrs(3)) do not mix their errors; frs_parallel hands a worker's
 * message to the thread that called it.  errkind says what failed (see
 * err.h), for the public API's codes. */
static _Thread_local char errbuf[1024];
static _Thread_local int errkind;
/* Warnings print only once a program has named itself: the library used
 * from another program (libfrs(3)) never prints. */
static const char *warn_prefix;
static int quiet;
static atomic_ulong nwarn;

/* The length of the valid UTF-8 sequence at s that is not a C1 control
 * (U+0080 to U+009F), or 0. */
static size_t utf8_len(const unsigned char *s)
{
	unsigned c = s[0], n, cp;

	if (c >= 0xc2 && c <= 0xdf)
		n = 2, cp = c & 0x1f;
	else if (c >= 0xe0 && c <= 0xef)
		n = 3, cp = c & 0x0f;
	else if (c >= 0xf0 && c <= 0xf4)
		n = 4, cp = c & 0x07;
	else
		return 0;
	for (unsigned i = 1; i < n; i++) {
		if ((s[i] & 0xc0) != 0x80)
			return 0;
		cp = cp << 6 | (s[i] & 0x3fu);
	}
	if (cp < 0xa0 || (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) ||
	    (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff)
		return 0;
	return n;
}

size_t frs_escape(char *dst, size_t cap, const char *src)
{
	const unsigned char *s = (const unsigned char *)src;
	size_t len = 0;

	if (cap == 0)
		return 0;
	while (*s != '\0') {
		size_t n = *s >= 0x80 ? utf8_len(s) : 1;
		int esc = n == 0 || (*s < 0x20 && *s != '\n' && *s != '\t') ||
		    *s == 0x7f;
		if (esc) {
			if (len + 4 >= cap)
				break;
			snprintf(dst + len, 5, "\\x%02x", *s);
			len += 4;
			s++;
			continue;
		}
		if (len + n >= cap)
			break;
		memcpy(dst + len, s, n);
		len += n;
		s += n;
	}
	dst[len] = '\0';
	return len;
}

void frs_vprint_escaped(FILE *fp, const char *fmt, va_list ap)
{
	char raw[4096], out[4096];

	vsnprintf(raw, sizeof raw, fmt, ap);
	frs_escape(out, sizeof out, raw);
	fputs(out, fp);
}

static int vfail(const char *fmt, va_list ap, int with_errno, int saved)
{
	char tmp[sizeof errbuf];

	/* Through tmp: fmt's arguments may point into errbuf itself. */
	vsnprintf(tmp, sizeof tmp, fmt, ap);
	if (with_errno) {
		size_t len = strlen(tmp);
		snprintf(tmp + len, sizeof tmp - len, ": %s", strerror(saved));
	}
	/* Messages quote file content and names: never raw control bytes. */
	frs_escape(errbuf, sizeof errbuf, tmp);
	errkind = FRS_ERRKIND_OTHER;
	return -1;
}

int frs_fail(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vfail(fmt, ap, 0, 0);
	va_end(ap);
	return -1;
}

int frs_vfail(const char *fmt, va_list ap, int with_errno)
{
	vfail(fmt, ap, with_errno, errno);
	return -1;
}

int frs_fail_errno(const char *fmt, ...)
{
	int saved = errno;
	va_list ap;
	va_start(ap, fmt);
	vfail(fmt, ap, 1, saved);
	va_end(ap);
	return -1;
}

int frs_fail_context(const char *ctx)
{
	char context[sizeof errbuf];
	size_t clen = frs_escape(context, sizeof context, ctx),
	    mlen = strlen(errbuf);

	if (clen + 2 >= sizeof errbuf)
		clen = sizeof errbuf - 3;
	if (clen + 2 + mlen >= sizeof errbuf)
		mlen = sizeof errbuf - clen - 3;
	memmove(errbuf + clen + 2, errbuf, mlen);
	memcpy(errbuf, context, clen);
	errbuf[clen] = ':';
	errbuf[clen + 1] = ' ';
	errbuf[clen + 2 + mlen] = '\0';
	return -1;
}

const char *frs_errmsg(void)
{
	return errbuf[0] ? errbuf : "unknown error";
}

void frs_clearerr(void)
{
	errbuf[0] = '\0';
	errkind = FRS_ERRKIND_OTHER;
}

void frs_set_errkind(int kind)
{
	errkind = kind;
}

int frs_errkind(void)
{
	return errkind;
}

void frs_set_warn_prefix(const char *prog)
{
	warn_prefix = prog;
}

void frs_set_quiet(int q)
{
	quiet = q;
}

unsigned long frs_warn_count(void)
{
	return atomic_load(&nwarn);
}

void frs_warn(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	frs_vwarn(fmt, ap);
	va_end(ap);
}

void frs_vwarn(const char *fmt, va_list ap)
{
	atomic_fetch_add(&nwarn, 1);
	if (quiet || warn_prefix == NULL)
		return;
	fprintf(stderr, "%s: warning: ", warn_prefix);
	frs_vprint_escaped(stderr, fmt, ap);
	fputc('\n', stderr);
}
