#define _POSIX_C_SOURCE 200809L
#include "par.h"
#include "err.h"
#include "progress.h"

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

static struct team {
	int size;			/* threads besides the caller */
	pthread_t *tid;
	atomic_uint_fast64_t state;
	atomic_int quit;
	struct job *job;		/* valid while the job is open or
					 * joined */
} team;

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
	uint64_t seen = 0;
	unsigned spins = 0;
	(void)arg;

	while (!atomic_load(&team.quit)) {
		uint_fast64_t st = atomic_load_explicit(&team.state,
		    memory_order_acquire);
		uint64_t g = st >> ST_GEN_SHIFT;
		if (g == seen || (st & ST_CLOSED)) {
			seen = g;
			idle(&spins);
			continue;
		}
		if (!atomic_compare_exchange_weak_explicit(&team.state, &st,
		    st + 1, memory_order_acq_rel, memory_order_relaxed))
			continue;
		seen = g;
		spins = 0;
		run(team.job, 0);
		atomic_fetch_sub_explicit(&team.state, 1, memory_order_release);
	}
	return NULL;
}

int frs_team_start(void)
{
	team.size = 0;
	atomic_init(&team.state, 0);
	atomic_init(&team.quit, 0);
	if (nthreads <= 1)
		return 0;
	team.tid = malloc((size_t)(nthreads - 1) * sizeof *team.tid);
	if (team.tid == NULL)
		return frs_fail("out of memory for threads");
	for (int t = 0; t < nthreads - 1 && t < (int)ST_COUNT; t++) {
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
	uint_fast64_t st;
	unsigned spins = 0;

	if (chunk == 0)
		chunk = 1;
	job_init(&j, n, chunk, fn, ctx, NULL);
	if (team.size == 0 || n <= chunk) {
		run(&j, 1);
		return job_result(&j);
	}
	/* The count is 0 here: the last job was closed and left. */
	team.job = &j;
	st = atomic_load_explicit(&team.state, memory_order_relaxed);
	atomic_store_explicit(&team.state,
	    ((st >> ST_GEN_SHIFT) + 1) << ST_GEN_SHIFT, memory_order_release);
	run(&j, 1);
	st = atomic_fetch_or_explicit(&team.state, ST_CLOSED,
	    memory_order_acq_rel);
	while ((st & ST_COUNT) != 0) {
		if (++spins > 2000)
			sched_yield();
		st = atomic_load_explicit(&team.state, memory_order_acquire);
	}
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
