#define _POSIX_C_SOURCE 200809L
#include "par.h"
#include "err.h"
#include "progress.h"

#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

/* Per thread, so that library calls in different threads (libfrs(3))
 * each use their own count; threads started here run with 1. */
static _Thread_local int nthreads = 1;

void frs_set_threads(int n)
{
	nthreads = n < 1 ? 1 : n;
}

int frs_threads(void)
{
	return nthreads;
}

struct job {
	uint64_t n, chunk;
	int (*fn)(void *, uint64_t, uint64_t);
	void *ctx;
	struct progress *pr;
	atomic_uint_fast64_t next;	/* next chunk to hand out */
	atomic_uint_fast64_t done;	/* items finished */
	atomic_int failed;
	char msg[1024];		/* the first failure's message */
};

static void job_init(struct job *j, uint64_t n, uint64_t chunk,
    int (*fn)(void *, uint64_t, uint64_t), void *ctx, struct progress *pr)
{
	j->n = n;
	j->chunk = chunk;
	j->fn = fn;
	j->ctx = ctx;
	j->pr = pr;
	atomic_init(&j->next, 0);
	atomic_init(&j->done, 0);
	atomic_init(&j->failed, 0);
}

static void run(struct job *j, int main_thread)
{
	for (;;) {
		uint64_t c = atomic_fetch_add(&j->next, 1), b, e;
		int rc;
		if (atomic_load(&j->failed) || c >= (j->n + j->chunk - 1) / j->chunk)
			break;
		b = c * j->chunk;
		e = j->n - b < j->chunk ? j->n : b + j->chunk;
		rc = j->fn(j->ctx, b, e);
		if (rc < 0) {
			/* Messages are per thread: keep the first for the
			 * caller (see job_result). */
			if (atomic_exchange(&j->failed, 1) == 0)
				snprintf(j->msg, sizeof j->msg, "%s",
				    frs_errmsg());
			break;
		}
		atomic_fetch_add(&j->done, e - b);
		if (main_thread && j->pr != NULL)
			progress_update(j->pr, atomic_load(&j->done));
	}
}

/* 0, or -1 with the first failed chunk's message in this thread. */
static int job_result(struct job *j)
{
	if (!atomic_load(&j->failed))
		return 0;
	return frs_fail("%s", j->msg);
}

static void *worker(void *arg)
{
	run(arg, 0);
	return NULL;
}

int frs_parallel(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx,
    struct progress *pr)
{
	struct job j;
	uint64_t nchunks;
	int nt, started = 0;
	pthread_t *tid;

	if (n == 0)
		return 0;
	if (chunk == 0)
		chunk = 1;
	nchunks = (n + chunk - 1) / chunk;
	nt = nchunks < (uint64_t)nthreads ? (int)nchunks : nthreads;
	job_init(&j, n, chunk, fn, ctx, pr);
	tid = nt > 1 ? malloc((size_t)(nt - 1) * sizeof *tid) : NULL;
	for (int t = 0; tid != NULL && t < nt - 1; t++)
		if (pthread_create(&tid[t], NULL, worker, &j) == 0)
			started++;
	run(&j, 1);	/* the calling thread works too */
	for (int t = 0; t < started; t++)
		pthread_join(tid[t], NULL);
	free(tid);
	return job_result(&j);
}

/* ---- a spinning team ---------------------------------------------- */

static struct team {
	int size;			/* threads besides the caller */
	pthread_t *tid;
	atomic_uint_fast64_t gen;	/* bumped for each job; odd never */
	atomic_int busy;		/* workers still on the current job */
	atomic_int quit;
	struct job *job;
} team;

static void *team_worker(void *arg)
{
	uint64_t seen = 0;
	(void)arg;

	for (;;) {
		uint64_t g;
		unsigned spins = 0;
		while ((g = atomic_load_explicit(&team.gen,
		    memory_order_acquire)) == seen) {
			if (atomic_load(&team.quit))
				return NULL;
			/* Spin a while, then let the core go. */
			if (++spins > 20000)
				sched_yield();
		}
		seen = g;
		run(team.job, 0);
		atomic_fetch_sub_explicit(&team.busy, 1, memory_order_release);
	}
}

int frs_team_start(void)
{
	team.size = 0;
	atomic_init(&team.gen, 0);
	atomic_init(&team.busy, 0);
	atomic_init(&team.quit, 0);
	if (nthreads <= 1)
		return 0;
	team.tid = malloc((size_t)(nthreads - 1) * sizeof *team.tid);
	if (team.tid == NULL)
		return frs_fail("out of memory for threads");
	for (int t = 0; t < nthreads - 1; t++) {
		if (pthread_create(&team.tid[t], NULL, team_worker, NULL) != 0)
			break;
		team.size++;
	}
	return 0;
}

int frs_team_run(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx)
{
	struct job j;

	if (chunk == 0)
		chunk = 1;
	job_init(&j, n, chunk, fn, ctx, NULL);
	if (team.size == 0 || n <= chunk) {
		run(&j, 1);
		return job_result(&j);
	}
	team.job = &j;
	atomic_store(&team.busy, team.size);
	atomic_fetch_add_explicit(&team.gen, 1, memory_order_release);
	run(&j, 1);
	/* Spin a while, then let the core go: on a busy machine the worker
	 * we wait for may need this very core to finish. */
	for (unsigned spins = 0; atomic_load_explicit(&team.busy,
	    memory_order_acquire) > 0; )
		if (++spins > 2000)
			sched_yield();
	return job_result(&j);
}

void frs_team_stop(void)
{
	atomic_store(&team.quit, 1);
	for (int t = 0; t < team.size; t++)
		pthread_join(team.tid[t], NULL);
	free(team.tid);
	team.tid = NULL;
	team.size = 0;
}
