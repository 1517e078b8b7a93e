/*
 * A progress bar with rate and ETA on standard error, drawn only when
 * standard error is a terminal or --progress was given, and only for work
 * that runs longer than about a second.  Not thread-safe: update it from
 * one thread.
 */
#ifndef FRS_PROGRESS_H
#define FRS_PROGRESS_H

#include <stdint.h>

struct progress {
	const char *label;
	uint64_t total, done;
	double start, last;
	int on, drawn;
};

double progress_now(void);	/* monotonic seconds */
void progress_begin(struct progress *p, const char *label, uint64_t total);
void progress_update(struct progress *p, uint64_t done);
void progress_end(struct progress *p);

#endif
