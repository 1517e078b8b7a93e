#define _POSIX_C_SOURCE 200809L
#include "err.h"

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

static int vfail(const char *fmt, va_list ap, int with_errno, int saved)
{
	char tmp[sizeof errbuf];

	/* Through tmp: fmt's arguments may point into errbuf itself. */
	vsnprintf(tmp, sizeof tmp, fmt, ap);
	if (with_errno) {
		size_t len = strlen(tmp);
		snprintf(tmp + len, sizeof tmp - len, ": %s", strerror(saved));
	}
	memcpy(errbuf, tmp, sizeof errbuf);
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

int frs_fail_errno(const char *fmt, ...)
{
	int saved = errno;
	va_list ap;
	va_start(ap, fmt);
	vfail(fmt, ap, 1, saved);
	va_end(ap);
	return -1;
}

int frs_fail_context(const char *context)
{
	size_t clen = strlen(context), mlen = strlen(errbuf);

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
	atomic_fetch_add(&nwarn, 1);
	if (quiet || warn_prefix == NULL)
		return;
	fprintf(stderr, "%s: warning: ", warn_prefix);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
}
