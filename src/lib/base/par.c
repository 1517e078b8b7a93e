#define _POSIX_C_SOURCE 200809L
#include "base/par.h"
#include "base/err.h"
#include "base/progress.h"

#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

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

/* The team the calling thread started, if any (frs_team_start): per
 * thread, so that library calls in different threads each have their
 * own; frs_parallel hands its jobs to it. */
struct team;
static _Thread_local struct team *mine;
static int team_job(struct team *tm, struct job *j);

static void *worker(void *arg)
{
	run(arg, 0);
	return NULL;
}

int frs_parallel_if(int par, uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx)
{
	if (par)
		return frs_parallel(n, chunk, fn, ctx, NULL);
	for (uint64_t b = 0; b < n; b += chunk)
		if (fn(ctx, b, n - b < chunk ? n : b + chunk) < 0)
			return -1;
	return 0;
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
	if (mine != NULL) {
		job_init(&j, n, chunk, fn, ctx, pr);
		return team_job(mine, &j);
	}
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

/*
 * The team's state, one atomic word: the job's generation (bits 17 and
 * up), a closed bit (16) and the workers inside the job (bits 0-15).  A
 * worker joins a job only while it is open, by raising the count; the
 * caller, once every chunk is handed out, closes the job and waits only
 * for the workers that joined.  A worker that the scheduler kept away
 * (another process holds the core) thus never holds the caller up: it
 * finds the job closed and waits for the next.
 */
#define ST_GEN_SHIFT 17
#define ST_CLOSED ((uint64_t)1 << 16)
#define ST_COUNT 0xffffu

struct team {
	int size;			/* threads besides the caller */
	int depth;			/* starts not yet stopped */
	pthread_t *tid;
	atomic_uint_fast64_t state;
	atomic_int quit;
	struct job *job;		/* valid while the job is open or
					 * joined */
};

/* Spin, then yield, then sleep: an idle worker must not keep a core
 * from other processes for long. */
static void idle(unsigned *spins)
{
	struct timespec ts = { 0, 50000 };

	if (++*spins < 2000)
		return;
	if (*spins < 20000)
		sched_yield();
	else
		nanosleep(&ts, NULL);
}

static void *team_worker(void *arg)
{
	struct team *tm = arg;
	uint64_t seen = 0;
	unsigned spins = 0;

	while (!atomic_load(&tm->quit)) {
		uint_fast64_t st = atomic_load_explicit(&tm->state,
		    memory_order_acquire);
		uint64_t g = st >> ST_GEN_SHIFT;
		if (g == seen || (st & ST_CLOSED)) {
			seen = g;
			idle(&spins);
			continue;
		}
		if (!atomic_compare_exchange_weak_explicit(&tm->state, &st,
		    st + 1, memory_order_acq_rel, memory_order_relaxed))
			continue;
		seen = g;
		spins = 0;
		run(tm->job, 0);
		atomic_fetch_sub_explicit(&tm->state, 1, memory_order_release);
	}
	return NULL;
}

int frs_team_start(void)
{
	struct team *tm;

	if (mine != NULL) {
		mine->depth++;	/* nested: the running team serves */
		return 0;
	}
	if ((tm = calloc(1, sizeof *tm)) == NULL)
		return frs_fail("out of memory for threads");
	atomic_init(&tm->state, 0);
	atomic_init(&tm->quit, 0);
	tm->depth = 1;
	mine = tm;
	if (nthreads <= 1)
		return 0;
	tm->tid = malloc((size_t)(nthreads - 1) * sizeof *tm->tid);
	if (tm->tid == NULL) {
		frs_team_stop();
		return frs_fail("out of memory for threads");
	}
	for (int t = 0; t < nthreads - 1 && t < (int)ST_COUNT; t++) {
		if (pthread_create(&tm->tid[t], NULL, team_worker, tm) != 0)
			break;
		tm->size++;
	}
	return 0;
}

/* The job on the team: the caller works too, then closes the job and
 * waits for the workers that joined it. */
static int team_job(struct team *tm, struct job *j)
{
	uint_fast64_t st;
	unsigned spins = 0;

	if (tm->size == 0 || j->n <= j->chunk) {
		run(j, 1);
		return job_result(j);
	}
	/* The count is 0 here: the last job was closed and left. */
	tm->job = j;
	st = atomic_load_explicit(&tm->state, memory_order_relaxed);
	atomic_store_explicit(&tm->state,
	    ((st >> ST_GEN_SHIFT) + 1) << ST_GEN_SHIFT, memory_order_release);
	run(j, 1);
	st = atomic_fetch_or_explicit(&tm->state, ST_CLOSED,
	    memory_order_acq_rel);
	while ((st & ST_COUNT) != 0) {
		if (++spins > 2000)
			sched_yield();
		st = atomic_load_explicit(&tm->state, memory_order_acquire);
	}
	return job_result(j);
}

int frs_team_run(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx)
{
	struct job j;

	if (mine == NULL)
		return frs_parallel(n, chunk, fn, ctx, NULL);
	job_init(&j, n, chunk == 0 ? 1 : chunk, fn, ctx, NULL);
	return team_job(mine, &j);
}

void frs_team_stop(void)
{
	struct team *tm = mine;

	if (tm == NULL || --tm->depth > 0)
		return;
	atomic_store(&tm->quit, 1);
	for (int t = 0; t < tm->size; t++)
		pthread_join(tm->tid[t], NULL);
	free(tm->tid);
	free(tm);
	mine = NULL;
}
