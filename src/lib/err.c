#define _POSIX_C_SOURCE 200809L
#include "err.h"

#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

/* One message for the process; worker threads may fail at once, so
 * writing it is serialised. */
static char errbuf[1024];
static pthread_mutex_t errlock = PTHREAD_MUTEX_INITIALIZER;
static const char *warn_prefix = "frs";
static int quiet;
static unsigned long nwarn;

static int vfail(const char *fmt, va_list ap, int with_errno, int saved)
{
	pthread_mutex_lock(&errlock);
	vsnprintf(errbuf, sizeof errbuf, fmt, ap);
	if (with_errno) {
		size_t len = strlen(errbuf);
		snprintf(errbuf + len, sizeof errbuf - len, ": %s", strerror(saved));
	}
	pthread_mutex_unlock(&errlock);
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
	return nwarn;
}

void frs_warn(const char *fmt, ...)
{
	va_list ap;
	nwarn++;
	if (quiet)
		return;
	fprintf(stderr, "%s: warning: ", warn_prefix);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
}
