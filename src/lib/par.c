#define _POSIX_C_SOURCE 200809L
#include "par.h"
#include "err.h"
#include "progress.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>

static int nthreads = 1;

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
};

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
			atomic_store(&j->failed, 1);
			break;
		}
		atomic_fetch_add(&j->done, e - b);
		if (main_thread && j->pr != NULL)
			progress_update(j->pr, atomic_load(&j->done));
	}
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
	j.n = n;
	j.chunk = chunk;
	j.fn = fn;
	j.ctx = ctx;
	j.pr = pr;
	atomic_init(&j.next, 0);
	atomic_init(&j.done, 0);
	atomic_init(&j.failed, 0);
	tid = nt > 1 ? malloc((size_t)(nt - 1) * sizeof *tid) : NULL;
	for (int t = 0; tid != NULL && t < nt - 1; t++)
		if (pthread_create(&tid[t], NULL, worker, &j) == 0)
			started++;
	run(&j, 1);	/* the calling thread works too */
	for (int t = 0; t < started; t++)
		pthread_join(tid[t], NULL);
	free(tid);
	return atomic_load(&j.failed) ? -1 : 0;
}
