/*
 * Parallel loops over an index range on a fixed number of threads.
 *
 * The range [0, n) is cut into chunks of a fixed size that the threads
 * take in turn; a result must depend only on the chunk, never on which
 * thread ran it or when, so that output is the same for any thread count.
 */
#ifndef FRS_PAR_H
#define FRS_PAR_H

#include <stdint.h>

struct progress;

/* Threads used by frs_parallel; the programs set it from -j. */
void frs_set_threads(int n);
int frs_threads(void);

/* fn(ctx, begin, end) for every chunk; returns 0, or -1 after the first
 * chunk that failed (its frs_fail message is kept; chunks not yet started
 * are skipped).  pr, if not NULL, is advanced by the items done. */
int frs_parallel(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx,
    struct progress *pr);
/* frs_parallel when par is set; else the same chunks, in order, on the
 * calling thread (the analyses' results do not depend on par, their
 * order of work does). */
int frs_parallel_if(int par, uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx);

/*
 * A team of threads kept spinning between many tiny parallel steps (one
 * FRD insertion is ~10 microseconds: creating threads for each would cost
 * more than the work), or between the waves of a draw.  Chunks are
 * handed out as by frs_parallel.  A team belongs to the thread that
 * started it; while it runs, that thread's frs_parallel and
 * frs_team_run use it (frs_team_run without a team is frs_parallel).  A
 * start inside a running team nests: the team serves until the matching
 * frs_team_stop of the first start ends it.
 */
int frs_team_start(void);
int frs_team_run(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx);
void frs_team_stop(void);

#endif
