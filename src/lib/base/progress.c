#define _POSIX_C_SOURCE 200809L
#include "base/progress.h"

#include <time.h>

/* Per thread, as frs_set_progress(3) says: work started by another
 * thread reports nothing to this thread's callback. */
static _Thread_local progress_fn progress_cb;
static _Thread_local void *progress_ctx;

void progress_set(progress_fn fn, void *ctx)
{
	progress_cb = fn;
	progress_ctx = fn != NULL ? ctx : NULL;
}

double progress_now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void progress_begin(struct progress *p, const char *label, uint64_t total)
{
	p->label = label;
	p->total = total;
	p->done = 0;
	p->fn = progress_cb;
	p->ctx = progress_ctx;
	/* An empty task is no task: total is at least 1 (frs.h). */
	p->on = p->fn != NULL && total > 0;
	if (p->on)
		p->fn(p->ctx, p->label, 0, p->total);
}

void progress_update(struct progress *p, uint64_t done)
{
	uint64_t was = p->done;

	p->done = done > p->total ? p->total : done;
	/* done = total is the end's call alone (progress_end). */
	if (p->on && p->done > was && p->done < p->total)
		p->fn(p->ctx, p->label, p->done, p->total);
}

void progress_end(struct progress *p)
{
	if (p->on) {
		p->done = p->total;
		p->fn(p->ctx, p->label, p->total, p->total);
	}
	p->on = 0;
}
