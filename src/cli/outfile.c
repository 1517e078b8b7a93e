#define _POSIX_C_SOURCE 200809L
#include "cli/outfile.h"
#include "base/err.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* Temporary files alive now; the signal handler unlinks them, which is
 * async-signal-safe. */
#define MAXTMP 16
static char *volatile live[MAXTMP];
static int handlers_installed;

static void on_signal(int sig)
{
	for (int i = 0; i < MAXTMP; i++)
		if (live[i] != NULL)
			unlink(live[i]);
	signal(sig, SIG_DFL);
	raise(sig);
}

/* A signal the parent set to be ignored (SIGINT for a background job)
 * stays ignored. */
static void catch_unless_ignored(int sig, const struct sigaction *sa)
{
	struct sigaction old;

	if (sigaction(sig, NULL, &old) == 0 && old.sa_handler == SIG_IGN)
		return;
	sigaction(sig, sa, NULL);
}

static void install_handlers(void)
{
	struct sigaction sa;

	if (handlers_installed)
		return;
	handlers_installed = 1;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	catch_unless_ignored(SIGINT, &sa);
	catch_unless_ignored(SIGTERM, &sa);
	catch_unless_ignored(SIGHUP, &sa);
	catch_unless_ignored(SIGPIPE, &sa);
	atexit(outfile_cleanup_all);
}

static void track(char *tmp, int add)
{
	for (int i = 0; i < MAXTMP; i++) {
		if (add && live[i] == NULL) {
			live[i] = tmp;
			return;
		}
		if (!add && live[i] == tmp) {
			live[i] = NULL;
			return;
		}
	}
}

void outfile_cleanup_all(void)
{
	for (int i = 0; i < MAXTMP; i++)
		if (live[i] != NULL) {
			unlink(live[i]);
			live[i] = NULL;
		}
}

static int open_stdout(struct outfile *o, int binary)
{
	if (binary && isatty(STDOUT_FILENO))
		return frs_fail("<stdout>: refusing to write binary data to a "
		    "terminal (write to a file or a pipe)");
	o->fp = stdout;
	o->name = "<stdout>";
	return 0;
}

/* Open a new temporary NAME.tmp.XXXXXX beside the target.  The name is
 * tracked before the file exists, not after (as mkstemp would force):
 * a signal in between would otherwise leave the file behind.  Unlinking
 * a name not yet created is harmless. */
static int open_tmp(char *tmp, size_t len)
{
	static const char digits[] =
	    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
	static unsigned long counter;
	uint64_t x = (uint64_t)getpid() * 0x9E3779B97F4A7C15u ^
	    (uint64_t)time(NULL) ^ (uint64_t)(uintptr_t)tmp;

	for (int tries = 0; tries < 100; tries++) {
		int fd;
		x += 0x9E3779B97F4A7C15u * ++counter;
		for (int i = 0; i < 6; i++) {
			uint64_t z = x >> (6 * i);
			tmp[len - 6 + (size_t)i] = digits[z % 62];
		}
		track(tmp, 1);
		/* 0666 & ~umask, as for any new file. */
		fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
		if (fd >= 0)
			return fd;
		track(tmp, 0);
		if (errno != EEXIST)
			return -1;
	}
	errno = EEXIST;
	return -1;
}

static int make_tmp(struct outfile *o)
{
	size_t len = strlen(o->path);
	int fd;

	o->tmp = malloc(len + 16);
	if (o->tmp == NULL)
		return frs_fail("%s: out of memory", o->path);
	/* Same directory, so that rename() is atomic. */
	snprintf(o->tmp, len + 16, "%s.tmp.XXXXXX", o->path);
	fd = open_tmp(o->tmp, strlen(o->tmp));
	if (fd < 0) {
		frs_fail_errno("%s: cannot create", o->path);
		free(o->tmp);
		o->tmp = NULL;
		return -1;
	}
	o->fp = fdopen(fd, "wb");
	if (o->fp == NULL) {
		frs_fail_errno("%s: cannot open", o->path);
		close(fd);
		unlink(o->tmp);
		track(o->tmp, 0);
		free(o->tmp);
		o->tmp = NULL;
		return -1;
	}
	return 0;
}

/*
 * Follow a symbolic link to the file it names: the temporary file and the
 * rename must be beside that file, or the rename would replace the link
 * itself.  A chain that passes through /proc or /dev (/dev/stdout ->
 * /proc/self/fd/1) names an open file of some process: replacing that
 * file would lose what is written, so such a target is written in place
 * (*inplace = 1).  Returns a malloc'd path, or NULL with a message.
 */
static char *resolve(const char *path, int *inplace)
{
	char *cur = strdup(path);

	*inplace = 0;
	for (int hops = 0; cur != NULL && hops < 40; hops++) {
		struct stat st;
		char buf[4096], *next;
		ssize_t n;
		if (strncmp(cur, "/proc/", 6) == 0 || strncmp(cur, "/dev/", 5) == 0)
			*inplace = 1;
		if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
			return cur;
		n = readlink(cur, buf, sizeof buf - 1);
		if (n < 0) {
			frs_fail_errno("%s: cannot read the link", path);
			free(cur);
			return NULL;
		}
		buf[n] = '\0';
		if (buf[0] == '/' || strchr(cur, '/') == NULL)
			next = strdup(buf);
		else {
			size_t d = (size_t)(strrchr(cur, '/') - cur) + 1;
			next = malloc(d + (size_t)n + 1);
			if (next != NULL) {
				memcpy(next, cur, d);
				memcpy(next + d, buf, (size_t)n + 1);
			}
		}
		free(cur);
		cur = next;
	}
	if (cur == NULL)
		frs_fail("%s: out of memory", path);
	else {
		frs_fail("%s: too many levels of symbolic links", path);
		free(cur);
	}
	return NULL;
}

int outfile_open(struct outfile *o, const char *path, int binary)
{
	struct stat st;
	int inplace;

	memset(o, 0, sizeof *o);
	install_handlers();
	if (path == NULL || strcmp(path, "-") == 0)
		return open_stdout(o, binary);
	if (*path == '\0')
		return frs_fail("an empty output file name");
	o->path = strdup(path);
	if (o->path == NULL)
		return frs_fail("%s: out of memory", path);
	o->name = o->path;
	if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
		frs_fail("%s: is a directory", path);
		goto fail;
	}
	{
		char *real = resolve(path, &inplace);
		if (real == NULL)
			goto fail;
		free(o->path);
		o->path = real;
		o->name = o->path;
	}
	if (inplace || (stat(path, &st) == 0 && !S_ISREG(st.st_mode))) {
		o->fp = fopen(path, "wb");
		if (o->fp == NULL) {
			frs_fail_errno("%s: cannot open", path);
			goto fail;
		}
		return 0;
	}
	if (make_tmp(o) == 0)
		return 0;
fail:
	free(o->path);
	o->path = NULL;
	return -1;
}

static int finish_stream(struct outfile *o)
{
	int bad = fflush(o->fp) != 0 || ferror(o->fp);
	int saved = errno;

	if (o->fp != stdout) {
		if (fclose(o->fp) != 0 && !bad) {
			bad = 1;
			saved = errno;
		}
	}
	o->fp = NULL;
	if (bad) {
		errno = saved ? saved : EIO;
		return frs_fail_errno("%s: write error", o->name);
	}
	return 0;
}

/* Drop o's names; its temporary file (if any) removed when unlink_tmp
 * is set (not renamed into place). */
static void forget(struct outfile *o, int unlink_tmp)
{
	if (o->tmp != NULL) {
		if (unlink_tmp)
			unlink(o->tmp);
		track(o->tmp, 0);
		free(o->tmp);
		o->tmp = NULL;
	}
	free(o->path);
	o->path = NULL;
}

int outfile_commit(struct outfile *o)
{
	int rc;

	if (o->fp == NULL)
		return frs_fail("%s: output already closed", o->name);
	rc = finish_stream(o);
	if (rc == 0 && o->tmp != NULL && rename(o->tmp, o->path) != 0)
		rc = frs_fail_errno("%s: cannot rename temporary file", o->path);
	forget(o, rc != 0);
	return rc;
}

void outfile_abort(struct outfile *o)
{
	if (o->fp != NULL && o->fp != stdout)
		fclose(o->fp);
	else if (o->fp == stdout)
		fflush(stdout);
	o->fp = NULL;
	forget(o, 1);
}
