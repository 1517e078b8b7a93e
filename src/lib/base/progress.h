/*
 * Progress of long library work, reported through the callback that the
 * calling thread set with frs_set_progress (frs.h, frs_set_progress(3));
 * nothing when none is set.  The library never draws anything itself:
 * the programs' bar on standard error is the callback cli.c installs.
 *
 * A task makes one call with done = 0 at progress_begin, calls with done
 * increasing below total from progress_update, and one last call with
 * done = total at progress_end; a task with total 0 reports nothing.
 * The callback is taken at progress_begin,
 * so begin, update and end a task from one thread (the one that began it).
 */
#ifndef FRS_PROGRESS_H
#define FRS_PROGRESS_H

#include <stdint.h>


/* The callback's type, frs_progress_fn of frs.h (where the library's
 * users set it: frs_set_progress, in api.c). */
typedef void (*progress_fn)(void *ctx, const char *what, uint64_t done,
    uint64_t total);

/* This thread's callback (NULL: none) and its context. */
void progress_set(progress_fn fn, void *ctx);

struct progress {
	const char *label;
	uint64_t total, done;
	progress_fn fn;	/* NULL: nobody listens */
	void *ctx;
	int on;			/* between begin and end, with a callback */
};

double progress_now(void);	/* monotonic seconds */
void progress_begin(struct progress *p, const char *label, uint64_t total);
void progress_update(struct progress *p, uint64_t done);
void progress_end(struct progress *p);

#endif
