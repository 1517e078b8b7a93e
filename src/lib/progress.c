#define _POSIX_C_SOURCE 200809L
#include "progress.h"
#include "cli.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

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
	p->start = p->last = progress_now();
	p->drawn = 0;
	p->on = !cli.quiet && (cli.progress || isatty(STDERR_FILENO));
}

static void fmt_time(char *buf, size_t n, double s)
{
	if (s < 0 || s > 1e7)
		snprintf(buf, n, "--:--");
	else if (s >= 3600)
		snprintf(buf, n, "%d:%02d:%02d", (int)s / 3600,
		    (int)s / 60 % 60, (int)s % 60);
	else
		snprintf(buf, n, "%02d:%02d", (int)s / 60, (int)s % 60);
}

static void draw(struct progress *p, double now)
{
	double el = now - p->start;
	double frac = p->total ? (double)p->done / (double)p->total : 0.0;
	double rate = el > 0 ? (double)p->done / el : 0.0;
	char eta[32];
	int bar = (int)(frac * 30.0 + 0.5);

	fmt_time(eta, sizeof eta, rate > 0 ? (double)(p->total - p->done) /
	    rate : -1);
	fprintf(stderr, "\r%s: %s [%-30.*s] %5.1f%% %.3g/s ETA %s ", cli_prog,
	    p->label, bar, "##############################", 100.0 * frac,
	    rate, eta);
	fflush(stderr);
	p->drawn = 1;
}

void progress_update(struct progress *p, uint64_t done)
{
	double now;

	p->done = done > p->total ? p->total : done;
	if (!p->on)
		return;
	now = progress_now();
	/* Nothing for the first second; then at most 10 redraws a second. */
	if (now - p->start < 1.0 || now - p->last < 0.1)
		return;
	p->last = now;
	draw(p, now);
}

void progress_end(struct progress *p)
{
	if (p->on && p->drawn) {
		p->done = p->total;
		draw(p, progress_now());
		fputc('\n', stderr);
	}
	p->on = 0;
}
