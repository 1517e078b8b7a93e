/*
 * tracer: the calls of a program built with -finstrument-functions, for
 * scripts/walk.sh.  Each entry and exit goes to $WALK_TRACE as "E OFF"
 * or "X OFF", OFF the function's offset in the executable (as nm shows
 * it), until the function at offset $WALK_STOP is entered.  Not itself
 * instrumented: compiled without the flag.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static FILE *out;
static uintptr_t base, stop;
static int done;

static int start(void *fn)
{
	const char *path = getenv("WALK_TRACE"), *s = getenv("WALK_STOP");
	Dl_info info;

	if (path == NULL || (out = fopen(path, "w")) == NULL ||
	    dladdr(fn, &info) == 0) {
		done = 1;
		return -1;
	}
	base = (uintptr_t)info.dli_fbase;
	stop = s != NULL ? (uintptr_t)strtoull(s, NULL, 16) : 0;
	return 0;
}

static void note(char kind, void *fn)
{
	uintptr_t off;

	if (done || (out == NULL && start(fn) < 0))
		return;
	off = (uintptr_t)fn - base;
	if (kind == 'E' && off == stop) {
		fclose(out);
		done = 1;
		return;
	}
	fprintf(out, "%c %016lx\n", kind, (unsigned long)off);
}

void __cyg_profile_func_enter(void *fn, void *site)
{
	(void)site;
	note('E', fn);
}

void __cyg_profile_func_exit(void *fn, void *site)
{
	(void)site;
	note('X', fn);
}
