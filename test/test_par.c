/* Parallel loops: every index exactly once for any thread count, errors
 * stop the loop and reach the caller, counts and messages per thread, the
 * team's many small jobs, and the progress bar draws rate and ETA, of the
 * library's tasks and the programs' own (cli.h). */
#include "testutil.h"
#include "cli/cli.h"
#include "frs.h"
#include "base/par.h"
#include "base/progress.h"

#include <fcntl.h>
#include <pthread.h>
#include <stdatomic.h>
#include <time.h>

struct ctx {
	unsigned char *hit;
	uint64_t fail_at;
};

static int mark(void *p, uint64_t b, uint64_t e)
{
	struct ctx *c = p;
	for (uint64_t i = b; i < e; i++) {
		if (i == c->fail_at)
			return frs_fail("item %llu failed", (unsigned long long)i);
		c->hit[i]++;
	}
	return 0;
}

static void every_index_once(void **state)
{
	const uint64_t n = 10007;	/* prime: the last chunk is short */
	struct ctx c = { calloc(n, 1), UINT64_MAX };
	(void)state;

	for (int t = 1; t <= 8; t *= 2)
		for (uint64_t chunk = 1; chunk <= 4096; chunk *= 8) {
			memset(c.hit, 0, n);
			frs_set_threads(t);
			assert_int_equal(frs_parallel(n, chunk, mark, &c, NULL), 0);
			for (uint64_t i = 0; i < n; i++)
				assert_int_equal(c.hit[i], 1);
		}
	assert_int_equal(frs_parallel(0, 16, mark, &c, NULL), 0);
	free(c.hit);
}

static void failure_stops(void **state)
{
	const uint64_t n = 1000;
	struct ctx c = { calloc(n, 1), 500 };
	(void)state;

	frs_set_threads(4);
	assert_int_equal(frs_parallel(n, 10, mark, &c, NULL), -1);
	assert_err_has("item 500 failed");
	free(c.hit);
}

/* A thread's own count and message: one thread's -j and failure do not
 * reach another (libfrs(3) calls from many threads). */
static void *other_thread(void *arg)
{
	int *seen = arg;
	struct ctx c = { calloc(10, 1), 3 };

	seen[0] = frs_threads();	/* a new thread starts with 1 */
	frs_set_threads(2);
	seen[1] = frs_parallel(10, 1, mark, &c, NULL);
	free(c.hit);
	return NULL;
}

static void per_thread(void **state)
{
	pthread_t t;
	int seen[2];
	(void)state;

	frs_set_threads(3);
	frs_fail("mine");
	assert_int_equal(pthread_create(&t, NULL, other_thread, seen), 0);
	pthread_join(t, NULL);
	assert_int_equal(seen[0], 1);
	assert_int_equal(seen[1], -1);
	assert_int_equal(frs_threads(), 3);
	assert_string_equal(frs_errmsg(), "mine");
}

/* The team: many small jobs one after another (as frd-gen runs them),
 * each index once, whatever workers join late or never; a failure's
 * message reaches the caller. */
static void team_jobs(void **state)
{
	const uint64_t n = 257;
	struct ctx c = { calloc(n, 1), UINT64_MAX };
	(void)state;

	for (int t = 1; t <= 4; t++) {
		frs_set_threads(t);
		assert_int_equal(frs_team_start(), 0);
		for (int job = 0; job < 3000; job++) {
			uint64_t m = 1 + (uint64_t)job % n;
			memset(c.hit, 0, n);
			assert_int_equal(frs_team_run(m, 1 + (uint64_t)job % 7,
			    mark, &c), 0);
			for (uint64_t i = 0; i < n; i++)
				assert_int_equal(c.hit[i], i < m);
		}
		c.fail_at = 100;
		assert_int_equal(frs_team_run(n, 4, mark, &c), -1);
		assert_err_has("item 100 failed");
		c.fail_at = UINT64_MAX;
		frs_team_stop();
	}
	free(c.hit);
}

/* Teams per thread: two threads run teams at once (two libfrs draws in
 * parallel, each with its waves on a team), frs_parallel inside a team
 * uses it, a nested start is served by the running team and only the
 * outer stop ends it, and frs_team_run without a team still works. */
static pthread_barrier_t both;

/* Which threads ran chunks: a number a thread, never reused, so that
 * threads started anew for a job count apart from a team's. */
static atomic_int threads_seen;
static _Thread_local int my_number;
static unsigned char ran[1 << 16];

static int who(void *p, uint64_t b, uint64_t e)
{
	struct timespec ts = { 0, 200000 };	/* long enough for threads
						 * started late to join */
	(void)p;
	(void)b;
	(void)e;
	nanosleep(&ts, NULL);
	if (my_number == 0)
		my_number = atomic_fetch_add(&threads_seen, 1) + 1;
	if (my_number < (int)sizeof ran)
		ran[my_number] = 1;
	return 0;
}

static int threads_that_ran(void)
{
	int k = 0;
	for (size_t i = 0; i < sizeof ran; i++)
		k += ran[i];
	return k;
}

static void *team_thread(void *arg)
{
	const uint64_t n = 1009;
	struct ctx c = { calloc(n, 1), UINT64_MAX };
	int *bad = arg;

	frs_set_threads(2);
	*bad = frs_team_start() != 0;
	pthread_barrier_wait(&both);	/* both teams run from here */
	for (int job = 0; job < 2000 && !*bad; job++) {
		uint64_t m = 1 + (uint64_t)job * 7 % n;
		memset(c.hit, 0, n);
		if ((job & 1 ? frs_parallel(m, 3, mark, &c, NULL) :
		    frs_team_run(m, 5, mark, &c)) != 0)
			*bad = 1;
		for (uint64_t i = 0; i < n; i++)
			if (c.hit[i] != (i < m))
				*bad = 1;
	}
	pthread_barrier_wait(&both);
	frs_team_stop();
	free(c.hit);
	return NULL;
}

static void team_per_thread(void **state)
{
	const uint64_t n = 300;
	struct ctx c = { calloc(n, 1), UINT64_MAX };
	pthread_t t[2];
	int bad[2] = { 1, 1 };
	(void)state;

	pthread_barrier_init(&both, NULL, 2);
	for (int i = 0; i < 2; i++)
		assert_int_equal(pthread_create(&t[i], NULL, team_thread,
		    &bad[i]), 0);
	for (int i = 0; i < 2; i++)
		pthread_join(t[i], NULL);
	pthread_barrier_destroy(&both);
	assert_int_equal(bad[0], 0);
	assert_int_equal(bad[1], 0);

	frs_set_threads(3);
	assert_int_equal(frs_team_start(), 0);
	assert_int_equal(frs_team_start(), 0);	/* nested */
	frs_team_stop();			/* the team still serves: */
	memset(ran, 0, sizeof ran);		/* its 3 threads, no new ones */
	for (int job = 0; job < 20; job++)
		assert_int_equal(frs_parallel(16, 1, who, NULL, NULL), 0);
	assert_in_range(threads_that_ran(), 1, 3);
	assert_int_equal(frs_parallel(n, 2, mark, &c, NULL), 0);
	c.fail_at = 77;
	assert_int_equal(frs_parallel(n, 2, mark, &c, NULL), -1);
	assert_err_has("item 77 failed");
	frs_team_stop();
	c.fail_at = UINT64_MAX;
	memset(c.hit, 0, n);
	assert_int_equal(frs_team_run(n, 4, mark, &c), 0);	/* no team */
	for (uint64_t i = 0; i < n; i++)
		assert_int_equal(c.hit[i], 1);
	frs_team_stop();			/* none: nothing */
	memset(ran, 0, sizeof ran);		/* no team: threads anew */
	for (int job = 0; job < 20; job++)
		assert_int_equal(frs_parallel(16, 1, who, NULL, NULL), 0);
	assert_true(threads_that_ran() > 3);
	free(c.hit);
}

/* What the programs' bar, cli.c's callback, draws of the task draw
 * runs: into a file instead of the terminal, with --progress. */
static char *drawn(void (*draw)(struct cli_bar *bar))
{
	struct cli_bar bar = { NULL, 0, 0, 0.0, 0.0, 0, 0, 0 };
	const char *path = tu_path("progress.txt");
	int fd = open(path, O_CREAT | O_TRUNC | O_WRONLY, 0600), saved;
	size_t n;
	char *out;

	saved = dup(2);
	fflush(stderr);
	dup2(fd, 2);
	cli.progress = 1;
	frs_set_progress(cli_bar_progress, &bar);
	draw(&bar);
	frs_set_progress(NULL, NULL);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	close(fd);
	out = (char *)tu_read(path, &n);
	out[n] = '\0';
	return out;
}

/* A task of 200 drawn at 50 % after 2 s (pretended) and at its end. */
static void assert_drawn(char *out)
{
	size_t n = strlen(out);

	assert_non_null(strstr(out, "testing"));
	assert_non_null(strstr(out, "50.0%"));
	assert_non_null(strstr(out, "ETA 00:0"));	/* 100 left at 50/s */
	assert_non_null(strstr(out, "100.0%"));
	assert_true(n > 0 && out[n - 1] == '\n');
	free(out);
}

static void library_task(struct cli_bar *bar)
{
	struct progress p;

	progress_begin(&p, "testing", 200);
	progress_update(&p, 10);		/* under a second: nothing */
	bar->start -= 2.0;			/* pretend 2 s have passed */
	bar->last -= 2.0;
	progress_update(&p, 100);
	progress_end(&p);
}

/* The same through cli.h, as a program's own loop reports. */
static void program_task(struct cli_bar *bar)
{
	struct cli_task *t = cli_task_begin("testing", 200);

	assert_non_null(t);
	cli_task_update(t, 10);
	bar->start -= 2.0;
	bar->last -= 2.0;
	cli_task_update(t, 100);
	cli_task_end(t);
}

/* The library's progress and the programs' tasks draw on the bar. */
static void progress_draws(void **state)
{
	struct cli_bar bar = { NULL, 0, 0, 0.0, 0.0, 0, 0, 0 };
	struct progress p;
	(void)state;

	assert_drawn(drawn(library_task));
	assert_drawn(drawn(program_task));
	/* Off: neither a terminal nor --progress. */
	cli.progress = 0;
	frs_set_progress(cli_bar_progress, &bar);
	progress_begin(&p, "quiet", 10);
	assert_int_equal(bar.on, isatty(2) && !cli.quiet);
	progress_end(&p);
	assert_int_equal(bar.active, 0);
	frs_set_progress(NULL, NULL);
}

static void *worker_task(void *arg)
{
	(void)arg;
	return cli_task_begin("worker", 10);
}

/* cli.h's tasks: none where nobody listens, every call taking that
 * none; a parallel loop advancing one; one dropped leaves the bar
 * without its last report. */
static void program_tasks(void **state)
{
	struct cli_bar bar = { NULL, 0, 0, 0.0, 0.0, 0, 0, 0 };
	struct ctx c = { calloc(100, 1), UINT64_MAX };
	struct cli_task *t;
	pthread_t th;
	void *got = &bar;
	(void)state;

	cli.quiet = 1;				/* nothing drawn */
	frs_set_progress(NULL, NULL);
	assert_null(cli_task_begin("nobody", 10));
	frs_set_progress(cli_bar_progress, &bar);
	assert_null(cli_task_begin("empty", 0));
	assert_int_equal(bar.active, 0);
	cli_task_update(NULL, 5);
	cli_task_end(NULL);
	cli_task_drop(NULL);
	assert_int_equal(pthread_create(&th, NULL, worker_task, NULL), 0);
	pthread_join(th, &got);
	assert_null(got);			/* the callback is per thread */

	assert_non_null(t = cli_task_begin("loop", 100));
	assert_int_equal(bar.active, 1);
	assert_string_equal(bar.label, "loop");
	frs_set_threads(1);
	assert_int_equal(cli_parallel(100, 7, mark, &c, t), 0);
	assert_int_equal(bar.done, 98);		/* the end reports 100 */
	cli_task_end(t);
	assert_int_equal(bar.active, 0);
	assert_int_equal(bar.done, 100);
	assert_int_equal(cli_parallel(100, 7, mark, &c, NULL), 0);

	assert_non_null(t = cli_task_begin("dropped", 10));
	cli_task_update(t, 3);
	cli_task_drop(t);
	assert_int_equal(bar.active, 1);
	assert_int_equal(bar.done, 3);
	frs_set_progress(NULL, NULL);
	cli.quiet = 0;
	free(c.hit);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(every_index_once),
	cmocka_unit_test(failure_stops),
	cmocka_unit_test(per_thread),
	cmocka_unit_test(team_jobs),
	cmocka_unit_test(team_per_thread),
	cmocka_unit_test(progress_draws),
	cmocka_unit_test(program_tasks))
