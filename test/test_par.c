/* Parallel loops: every index exactly once for any thread count, errors
 * stop the loop and reach the caller, counts and messages per thread, the
 * team's many small jobs, and the progress bar draws rate and ETA. */
#include "testutil.h"
#include "cli.h"
#include "par.h"
#include "progress.h"

#include <fcntl.h>
#include <pthread.h>

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

/* Draw into a file instead of the terminal and look at what came out:
 * the programs' bar, cli.c's callback, fed by the library's progress. */
static void progress_draws(void **state)
{
	struct progress p;
	struct cli_bar bar = { NULL, 0, 0, 0.0, 0.0, 0, 0, 0 };
	const char *path = tu_path("progress.txt");
	int fd = open(path, O_CREAT | O_TRUNC | O_WRONLY, 0600), saved;
	size_t n;
	char *out;
	(void)state;

	saved = dup(2);
	fflush(stderr);
	dup2(fd, 2);
	cli.progress = 1;
	frs_set_progress(cli_bar_progress, &bar);
	progress_begin(&p, "testing", 200);
	progress_update(&p, 10);		/* under a second: nothing */
	bar.start -= 2.0;			/* pretend 2 s have passed */
	bar.last -= 2.0;
	progress_update(&p, 100);
	progress_end(&p);
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
	close(fd);
	out = (char *)tu_read(path, &n);
	out[n] = '\0';
	assert_non_null(strstr(out, "testing"));
	assert_non_null(strstr(out, "50.0%"));
	assert_non_null(strstr(out, "ETA 00:0"));	/* 100 left at 50/s */
	assert_non_null(strstr(out, "100.0%"));
	assert_int_equal(out[n - 1], '\n');
	free(out);
	/* Off: neither a terminal nor --progress. */
	cli.progress = 0;
	progress_begin(&p, "quiet", 10);
	assert_int_equal(bar.on, isatty(2) && !cli.quiet);
	progress_end(&p);
	assert_int_equal(bar.active, 0);
	frs_set_progress(NULL, NULL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_index_once),
		cmocka_unit_test(failure_stops),
		cmocka_unit_test(per_thread),
		cmocka_unit_test(team_jobs),
		cmocka_unit_test(progress_draws),
	};
	return cmocka_run_group_tests(tests, NULL, tu_teardown);
}
