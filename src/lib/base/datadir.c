/*
 * The shipped data's directories (datadir.h).  dladdr, which tells where
 * libfrs.so was loaded from, is a GNU extension: hence _GNU_SOURCE here
 * and nowhere else.
 */
#define _GNU_SOURCE
#include "base/datadir.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/err.h"
/* FRS_SRCDATA, FRS_SHAREDIR: written by the Makefile (build/VARIANT/gen),
 * rewritten only when SRCDATA or PREFIX change. */
#include "paths.h"

static void add(struct data_dirs *d, const char *dir)
{
	if (dir[0] == '\0' || strlen(dir) >= DATA_PATH_MAX ||
	    d->n == DATA_DIRS_MAX)
		return;
	for (size_t i = 0; i < d->n; i++)
		if (strcmp(d->dir[i], dir) == 0)
			return;
	strcpy(d->dir[d->n++], dir);
}

/* PREFIX/share/frs for a file PREFIX/X/FILE (a program in BINDIR, the
 * library in LIBDIR), file an absolute path without links. */
static void add_beside(struct data_dirs *d, const char *file)
{
	char dir[DATA_PATH_MAX];
	char *slash;
	int len;

	len = snprintf(dir, sizeof dir, "%s", file);
	if (len < 0 || (size_t)len >= sizeof dir)
		return;
	for (int up = 0; up < 2; up++) {
		if ((slash = strrchr(dir, '/')) == NULL)
			return;
		*slash = '\0';
	}
	if (strlen(dir) + sizeof "/share/frs" > sizeof dir)
		return;
	strcat(dir, "/share/frs");
	add(d, dir);
}

/* An address inside the library, for dladdr. */
static const char anchor;

void data_dirs(struct data_dirs *d)
{
	const char *env = getenv("FRS_DATA");
	char exe[PATH_MAX], lib[PATH_MAX];
	int have_exe;
	Dl_info info;

	d->n = 0;
	d->env = env != NULL && *env != '\0';
	if (d->env) {
		add(d, env);
		if (d->n == 0)	/* too long to use: still the only place */
			snprintf(d->dir[d->n++], DATA_PATH_MAX, "%s", env);
		return;
	}
	have_exe = realpath("/proc/self/exe", exe) != NULL;
	/* The library's own file, when it is a shared object: in a static
	 * link dladdr names the program. */
	if (dladdr(&anchor, &info) != 0 &&
	    info.dli_fname != NULL && strchr(info.dli_fname, '/') != NULL &&
	    realpath(info.dli_fname, lib) != NULL &&
	    (!have_exe || strcmp(lib, exe) != 0))
		add_beside(d, lib);
	if (have_exe)
		add_beside(d, exe);
	add(d, FRS_SRCDATA);
	add(d, FRS_SHAREDIR);
}

int data_find(const char *name, char *path, size_t cap)
{
	struct data_dirs d;
	char looked[1024] = "";
	size_t used = 0;

	data_dirs(&d);
	for (size_t i = 0; i < d.n; i++) {
		int len = snprintf(path, cap, "%s/%s", d.dir[i], name);

		if (len >= 0 && (size_t)len < cap && access(path, R_OK) == 0)
			return 0;
	}
	if (cap > 0)
		path[0] = '\0';
	for (size_t i = 0; i < d.n && used < sizeof looked; i++) {
		int len = snprintf(looked + used, sizeof looked - used,
		    "%s%s/%s%s", i == 0 ? "" : i + 1 < d.n ? ", " : " and ",
		    d.dir[i], name, d.env ? "; FRS_DATA is set" : "");

		if (len < 0)
			break;
		used += (size_t)len;
	}
	return frs_fail("looked for %s", looked);
}
