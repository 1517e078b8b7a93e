/*
 * The library's program-level services in the programs' words (cli.h):
 * the clock of -v's timings, tasks of a program's own on the progress
 * bar (base/progress.h), the shipped data files (base/datadir.h) and the
 * record of a failure (base/err.h), so that a program includes none of
 * these headers nor sees struct progress.
 */
#define _POSIX_C_SOURCE 200809L
#include "cli/cli.h"
#include "base/datadir.h"
#include "base/io.h"
#include "base/err.h"
#include "base/ocl.h"
#include "base/par.h"
#include "base/progress.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>

/* A program's buffers hold what the library's may (frs-sample's default
 * matrix from api_default_matrix, whose "too long" message names the
 * size). */
_Static_assert(CLI_PATH_MAX == DATA_PATH_MAX,
    "CLI_PATH_MAX is datadir.h's DATA_PATH_MAX");

struct cli_task {
	struct progress p;
};

double cli_now(void)
{
	return progress_now();
}

/*
 * Kept only when somebody listens: a thread with no callback (a worker,
 * a program's loop run by the tests) and an empty task get NULL, so that
 * their updates cost a test of the pointer, as progress_update's of
 * p->on did.  Allocated before the begin's report: a failure leaves no
 * task begun that nobody ends, only no bar.
 */
struct cli_task *cli_task_begin(const char *label, uint64_t total)
{
	struct cli_task *t = malloc(sizeof *t);

	if (t == NULL)
		return NULL;
	progress_begin(&t->p, label, total);
	if (t->p.on)
		return t;
	free(t);
	return NULL;
}

void cli_task_update(struct cli_task *t, uint64_t done)
{
	if (t != NULL)
		progress_update(&t->p, done);
}

void cli_task_end(struct cli_task *t)
{
	if (t != NULL)
		progress_end(&t->p);
	free(t);
}

void cli_task_drop(struct cli_task *t)
{
	free(t);
}

int cli_parallel(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx,
    struct cli_task *t)
{
	return frs_parallel(n, chunk, fn, ctx, t != NULL ? &t->p : NULL);
}

int cli_parallel_if(int par, uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx)
{
	return frs_parallel_if(par, n, chunk, fn, ctx);
}

int cli_team_start(void)
{
	return frs_team_start();
}

int cli_team_run(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx)
{
	return frs_team_run(n, chunk, fn, ctx);
}

void cli_team_stop(void)
{
	frs_team_stop();
}

int cli_threads(void)
{
	return frs_threads();
}

int cli_data_file(const char *name, char *path, size_t cap)
{
	return data_find(name, path, cap);
}

int cli_read_file(const char *path, const char **name, unsigned char **buf,
    size_t *len)
{
	return io_slurp_path(path, name, buf, len);
}

int cli_read_exact(FILE *fp, const char *name, void *buf, size_t n,
    const char *what)
{
	return io_read_exact(fp, name, buf, n, what);
}

int cli_fail(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	frs_vfail(fmt, ap, 0);
	va_end(ap);
	return -1;
}

int cli_fail_errno(const char *fmt, ...)
{
	int saved = errno;
	va_list ap;

	va_start(ap, fmt);
	errno = saved;
	frs_vfail(fmt, ap, 1);
	va_end(ap);
	return -1;
}

int cli_fail_context(const char *context)
{
	return frs_fail_context(context);
}

void cli_warn(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	frs_vwarn(fmt, ap);
	va_end(ap);
}

struct ocl *cli_device_open(int index, int cpu_too)
{
	struct ocl *o = cli_calloc("the OpenCL context", 1, sizeof *o);

	if (ocl_open(o, index) < 0)
		cli_die_device(cpu_too);
	return o;
}

const char *cli_device_name(const struct ocl *o)
{
	return o->name;
}

int cli_device_fp64(const struct ocl *o)
{
	return o->fp64;
}

void cli_device_close(struct ocl *o)
{
	if (o == NULL)
		return;
	ocl_close(o);
	free(o);
}
