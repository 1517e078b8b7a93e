/*
 * What the programs share and the library does not, one header: each
 * program's name in messages, the common options (-h, --version, -o, -T,
 * -S, -j, -q, --progress), err(3)-style exits and number options that
 * reject junk (cli.c); the output step (output.c) over atomic output
 * files (outfile.c); the point files (ptsio.c), the point sets of the
 * programs that read them (ptsets.c, their options ptsopt.c), the
 * samplers' --sets writer (setsout.c) and the statistics over groups of
 * sets (groupstat.c); rasters (raster.c), the reference samplers
 * (refsamp.c), the FFT (fft.c); and the library's services in the
 * programs' words (services.c): the clock of -v's timings, a program's
 * own loops as tasks on the progress bar, parallel loops, the shipped
 * data files, the record of a failure and warnings, so that no program
 * includes base/progress.h, base/datadir.h or base/par.h, nor sees
 * struct progress.
 *
 * A program's files include this header alone of src/cli
 * (test/t_layout.sh checks it).  The modules keep their own headers
 * beside them, included here, rather than their declarations moved into
 * this one: each stays one .c and its .h, read and tested as such
 * (test/test_ptsio.c includes cli/ptsio.h, not all of this), and the
 * programs still have one door.  Every header of src/cli includes only
 * standard headers, frs.h and others of src/cli, never the library's
 * own (base/err.h and the like stay in src/cli's .c files), so that a
 * program sees of the library only what it includes itself, which
 * t_layout lists per program; but for the two below that this one
 * hands on, base/num.h and base/ocl.h (said why there).
 *
 * Exit status: 0 success, 1 error (bad input, failed output), 2 usage.
 */
#ifndef FRS_CLI_H
#define FRS_CLI_H

#include <getopt.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdnoreturn.h>

/*
 * The two headers of the library that this one hands to every program
 * (test/t_layout.sh allows these two, here alone), each one definition
 * for the library and the programs, neither a copy nor forwarders:
 * - base/num.h, the arithmetic kit (compensated sums num_add, num_total,
 *   num_sum, NUM_PI, NUM_CMP, ...): inlines and pure functions without
 *   state, so that a program's sums round as the library's do;
 * - base/ocl.h, the OpenCL plumbing (struct ocl, programs, kernels,
 *   buffers, arguments, fill, run, read and write) of the library's own
 *   device code (sample/frscl.c) and of the programs' (frd-gen's and
 *   hsw-sample's --device): the library cannot take it from src/cli, a
 *   copy in src/cli would be a second one to keep in step, and it is no
 *   API for libfrs's users.  It brings <CL/cl.h>, which the library is
 *   built with anyway.
 */
#include "base/num.h"
#include "base/ocl.h"

#include "cli/fft.h"
#include "cli/groupstat.h"
#include "cli/outfile.h"
#include "cli/ptsets.h"
#include "cli/ptsio.h"
#include "cli/raster.h"
#include "cli/refsamp.h"
#include "cli/setsout.h"

/* The format checks of the messages below (base/err.h has the library's
 * own, FRS_PRINTF, which this header leaves out). */
#if defined(__GNUC__)
#define CLI_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define CLI_PRINTF(a, b)
#endif

/*
 * Every long option of the toolchain, once: its name and whether it takes
 * a value are the same in every program that has it (DESIGN.md's core
 * options).  A program lists the ones it takes in a string of names in
 * the order of its usage text, "x=name" for one that also has the short
 * option -x:
 *
 *	static const char options[] = "s=size k=dims tol exact v=verbose";
 *
 * cli_getopt returns the letter for an option that has one, else OPT_ID
 * (OPT_TOL, OPT_EXACT).  The common options below are in every program;
 * another spelling of an option (--colour) is in cli.c's spellings.
 * test/t_options.sh checks every program's list against its -h text and
 * its manual.
 */
#define CLI_OPTIONS(X) \
	X(ALGO, "algo", required_argument) \
	X(ALPHA, "alpha", required_argument) \
	X(APPROX, "approx", no_argument) \
	X(AXES, "axes", required_argument) \
	X(BIN, "bin", required_argument) \
	X(BINS, "bins", required_argument) \
	X(BLOCKS, "blocks", required_argument) \
	X(CHECK, "check", no_argument) \
	X(CHECKPOINT, "checkpoint", required_argument) \
	X(CHECKPOINT_EVERY, "checkpoint-every", required_argument) \
	X(CLASS, "class", required_argument) \
	X(COLOR, "color", no_argument) \
	X(COUNT, "count", required_argument) \
	X(COUNT_ONLY, "count-only", no_argument) \
	X(CUTOFF, "cutoff", required_argument) \
	X(D2_ONLY, "d2-only", no_argument) \
	X(DATA_DIR, "data-dir", no_argument) \
	X(DB, "db", required_argument) \
	X(DDA, "dda", no_argument) \
	X(DENSITY, "density", no_argument) \
	X(DENSITY_RULE, "density-rule", required_argument) \
	X(DEVICE, "device", required_argument) \
	X(DIMS, "dims", required_argument) \
	X(DINF_ONLY, "dinf-only", no_argument) \
	X(ENV, "env", required_argument) \
	X(EPS, "eps", required_argument) \
	X(EQUIRECT, "equirect", no_argument) \
	X(EXACT, "exact", no_argument) \
	X(EXACT_COUNT, "exact-count", no_argument) \
	X(FIELD, "field", required_argument) \
	X(FOR, "for", required_argument) \
	X(FORCE, "force", required_argument) \
	X(FORCE_Q, "force-q", required_argument) \
	X(FORCE_S, "force-s", required_argument) \
	X(FORMAT, "format", required_argument) \
	X(FOURIER, "fourier", no_argument) \
	X(FRACTION, "fraction", required_argument) \
	X(FUNCTION, "function", required_argument) \
	X(GRID, "grid", required_argument) \
	X(GROUP, "group", required_argument) \
	X(IMPORT, "import", required_argument) \
	X(IMPORTANCE, "importance", required_argument) \
	X(INPUT, "input", required_argument) \
	X(JITTER, "jitter", required_argument) \
	X(KIND, "kind", required_argument) \
	X(LEVEL_BLUR, "level-blur", required_argument) \
	X(LEVEL_COLUMN, "level-column", no_argument) \
	X(LIST_DEVICES, "list-devices", no_argument) \
	X(LOG, "log", no_argument) \
	X(MATRIX, "matrix", required_argument) \
	X(MAX_FAILURES, "max-failures", required_argument) \
	X(METHOD, "method", required_argument) \
	X(NO_PDF, "no-pdf", no_argument) \
	X(PDF, "pdf", no_argument) \
	X(PDF_MAP, "pdf-map", required_argument) \
	X(PER_SET, "per-set", no_argument) \
	X(PNG, "png", required_argument) \
	X(PROGRESSIVE, "progressive", required_argument) \
	X(QUALITY, "quality", required_argument) \
	X(RADIAL, "radial", required_argument) \
	X(RADIUS, "radius", required_argument) \
	X(RANK, "rank", no_argument) \
	X(RDF, "rdf", no_argument) \
	X(REACH, "reach", required_argument) \
	X(REACH_CAP, "reach-cap", required_argument) \
	X(RMAX, "rmax", required_argument) \
	X(SET, "set", required_argument) \
	X(SETS, "sets", required_argument) \
	X(SHAPES, "shapes", required_argument) \
	X(SIGMA, "sigma", required_argument) \
	X(SIZE, "size", required_argument) \
	X(SIZE_MAP, "size-map", required_argument) \
	X(SRGB, "srgb", no_argument) \
	X(STRICT, "strict", no_argument) \
	X(SUMMARY, "summary", no_argument) \
	X(THRESHOLD, "threshold", required_argument) \
	X(TILES, "tiles", required_argument) \
	X(TOL, "tol", required_argument) \
	X(TORUS, "torus", no_argument) \
	X(VAC_SIGMA, "vac-sigma", required_argument) \
	X(VERBOSE, "verbose", no_argument) \
	X(WEIGHTS, "weights", no_argument)

#define CLI_OPTION_ID_(id, name, has_arg) OPT_##id,
enum {
	OPT_VERSION = 0x1000,
	OPT_PROGRESS,
	CLI_OPTIONS(CLI_OPTION_ID_)
};

struct cli_common {
	const char *out;	/* -o, NULL for standard output */
	int text;		/* -T */
	uint64_t seed;		/* -S, default 1 */
	int threads;		/* -j, default: all cores */
	int quiet;		/* -q */
	int progress;		/* --progress */
};
extern struct cli_common cli;
extern const char *cli_prog;

/* Set the program name and the usage text printed by -h and on usage
 * errors (its first line is the synopsis). */
void cli_init(const char *prog, const char *usage);
/* getopt_long over the options named (see CLI_OPTIONS) and the common
 * ones, with getopt's messages naming the program as cli_init did (not
 * argv[0], a path).  A name that is not in CLI_OPTIONS aborts. */
int cli_getopt(int argc, char **argv, const char *options);
/* Handle a common option; returns 1 if c was one. */
int cli_common_opt(int c, const char *arg);
/* The default of a program's option switch: a common option, else a
 * usage error. */
void cli_common_only(int c, const char *arg);
/* No operands after the options: the first is a usage error. */
void cli_no_operands(int argc, char **argv);

noreturn void cli_usage(int status);
noreturn void cli_usage_error(const char *fmt, ...) CLI_PRINTF(1, 2);
/* Which of the words (NULL-terminated, at least two) option opt names:
 * its index; any other is a usage error "opt: 's' is not a, b or c". */
int cli_choice(const char *opt, const char *s, const char *const *words);
/* "prog: message", exit 1, removing unfinished output files. */
noreturn void cli_die(const char *fmt, ...) CLI_PRINTF(1, 2);
/* "prog: <library message>", exit 1; exit 2, a usage error, when it is
 * a procedural map spec that does not parse (an option's argument). */
noreturn void cli_die_lib(void);
/* The library's message of the last failure ("context: problem"), for a
 * message of the program's own around it. */
const char *cli_errmsg(void);
void cli_note(const char *fmt, ...) CLI_PRINTF(1, 2);	/* unless -q */

/* The file name of an output option: an empty one is a usage error. */
const char *cli_outname(const char *opt, const char *s);
/* Binary output (path NULL or "-": standard output) to a terminal: exit 1
 * naming -o, before the library's own refusal (cli_out_open calls it;
 * programs whose output the library opens call it themselves). */
void cli_out_check(const char *path, int binary);
/* Option values; a bad value is a usage error naming the option. */
long long cli_ll(const char *opt, const char *s, long long min, long long max);
uint64_t cli_u64(const char *opt, const char *s, uint64_t min, uint64_t max);
double cli_double(const char *opt, const char *s, double min, double max);
/* The same in (min, max]: for values that must be above min. */
double cli_double_above(const char *opt, const char *s, double min,
    double max);
/* The same with hint appended to the message when the value is a number
 * at or below min (or none at all): what would have been meant. */
double cli_double_above_hint(const char *opt, const char *s, double min,
    double max, const char *hint);
void cli_size(const char *opt, const char *s, uint32_t max, uint32_t *w,
    uint32_t *h);
/* "N", "WxH" or "WxHxD": the number of sizes given; "N" fills all three,
 * "WxH" sets sz[2] = W. */
int cli_size3(const char *opt, const char *s, uint32_t max, uint32_t sz[3]);

/* --device VALUE: 0 for cpu, 1 for OpenCL with *index (-1: the first
 * device); a bad value is a usage error. */
int cli_device(const char *arg, int *index);
/* --list-devices: print the OpenCL devices and exit 0, or exit 1 with
 * the reason (no platform, no writable PoCL cache). */
noreturn void cli_list_devices(void);
/* The OpenCL device of --device failed (to open, or to take the work):
 * "prog: --device: <library message>; see --list-devices", with ", or use
 * --device cpu" when the work runs on the CPU too (cpu_too), exit 1. */
noreturn void cli_die_device(int cpu_too);
/* The OpenCL device of --device (index -1: the first), base/ocl.h's
 * context: opened, or the program ends as cli_die_device(cpu_too) says;
 * its name for messages, whether it has double precision
 * (cl_khr_fp64); closed and freed. */
struct ocl *cli_device_open(int index, int cpu_too);
const char *cli_device_name(const struct ocl *o);
int cli_device_fp64(const struct ocl *o);
void cli_device_close(struct ocl *o);

/* Called by every program when its options are parsed and checked,
 * before any file is opened or work begins.  Normally it does nothing.
 * The option-parsing fuzz target (test/fuzz/fuzz_opts.c) sets cli_trap:
 * then every exit above longjmps there with status + 1 instead, and
 * cli_options_done (and --list-devices) with CLI_PARSED, so that a
 * program's option parsing runs many times in one process. */
extern jmp_buf *cli_trap;
#define CLI_PARSED 1000
void cli_options_done(void);

/*
 * The programs' progress bar: a callback for frs_set_progress(3), which
 * cli_init installs for the calling thread with a bar of its own.  It
 * draws "prog: what [###   ]  50.0% 1.23e+04/s ETA 00:42" on standard
 * error, unless -q, when standard error is a terminal or --progress was
 * given (decided as each task starts), only after the task has run for a
 * second, at most 10 times a second, and a last time at 100 % with a
 * newline when a task that ran a second or more ends.  One task at a time.
 */
struct cli_bar {
	const char *label;
	uint64_t total, done;
	double start, last;	/* cli_now() seconds */
	int active, on, drawn;
};
void cli_bar_progress(void *ctx, const char *what, uint64_t done,
    uint64_t total);

/*
 * The library's services to the programs in their words (services.c),
 * so that none includes base/progress.h or base/datadir.h.
 */
/* Monotonic seconds, for -v's timings (and the bar's). */
double cli_now(void);

/*
 * A long loop of the program's own as a task on the progress bar,
 * reported as the library reports its own (base/progress.h): to the
 * callback of the thread that began it, which for a program is the bar
 * of cli_init on the main thread; a worker thread has none.  Begin,
 * update and end a task on that one thread.  cli_task_begin returns NULL
 * when nobody would be told (no callback on this thread, total 0, no
 * memory): every call below takes NULL and does nothing, so a hot loop
 * that tests the pointer before its update pays nothing without a bar.
 * An update reports done when it grew and is below total; the end
 * reports total and frees the task.  A task given up on a failure is
 * dropped instead: freed with no last report, the bar left as it stands
 * for the message that follows.
 */
struct cli_task;
struct cli_task *cli_task_begin(const char *label, uint64_t total);
void cli_task_update(struct cli_task *t, uint64_t done);
void cli_task_end(struct cli_task *t);
void cli_task_drop(struct cli_task *t);
/*
 * The library's parallel loops (base/par.h): [0, n) cut into chunks of a
 * fixed size that the -j threads take in turn, a result depending only
 * on its chunk.  cli_parallel runs fn(ctx, begin, end) on every chunk,
 * with task t (NULL: none) advanced by the items done, from the calling
 * thread: 0, or -1 after the first chunk that failed (its cli_fail
 * kept).  cli_parallel_if does the same when par is set, else the same
 * chunks in order on the calling thread.  A team (cli_team_start and
 * _stop around many tiny steps of cli_team_run) keeps the threads
 * spinning between them.  cli_threads: the threads they use.
 */
int cli_parallel(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx,
    struct cli_task *t);
int cli_parallel_if(int par, uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx);
int cli_team_start(void);
int cli_team_run(uint64_t n, uint64_t chunk,
    int (*fn)(void *ctx, uint64_t begin, uint64_t end), void *ctx);
void cli_team_stop(void);
int cli_threads(void);

/*
 * A step's failure in the programs' words: the library's error record
 * (base/err.h) that cli_die_lib and cli_errmsg report, so that a
 * function of a program returns -1 with its reason as the library's do.
 * cli_fail_errno appends ": strerror(errno)"; cli_fail_context puts
 * "context: " before the message recorded; cli_warn prints "prog:
 * warning: ..." on standard error unless -q.
 */
int cli_fail(const char *fmt, ...) CLI_PRINTF(1, 2);
int cli_fail_errno(const char *fmt, ...) CLI_PRINTF(1, 2);
int cli_fail_context(const char *context);
void cli_warn(const char *fmt, ...) CLI_PRINTF(1, 2);

/* A shipped data file's path (sunset.exr, default.frd) into path, cap
 * bytes, CLI_PATH_MAX enough for any: 0.  Else -1, the library's message
 * ("looked for D1/NAME, D2/NAME and D3/NAME", cli_errmsg) naming where it
 * looked ($FRS_DATA, beside the library and the program, the source
 * tree's data/, the install prefix). */
#define CLI_PATH_MAX 4096	/* also frs-sample's default matrix path */
int cli_data_file(const char *name, char *path, size_t cap);
/* The whole of a file (path, "-": standard input) into *buf (*len bytes,
 * with room for a NUL after them; to be freed), its name for messages
 * in *name: read as the library reads its inputs, with its messages (the
 * path and strerror, "is a directory", a read error) and its memory
 * ceiling.  -1 after cli_fail. */
int cli_read_file(const char *path, const char **name, unsigned char **buf,
    size_t *len);
/* Exactly n bytes of fp (name) into buf, what the part read ("header":
 * an empty file is said so): the library's reads and their messages (a
 * read error, "truncated WHAT (GOT of N bytes)").  -1 after cli_fail. */
int cli_read_exact(FILE *fp, const char *name, void *buf, size_t n,
    const char *what);

/* Number of online processors. */
int cli_ncpu(void);

/* The memory ceiling (FRS_MAX_MEM; base/mem.h's mem_check and
 * mem_calloc) for nmemb elements of size bytes, named what in its
 * message: checked, or the memory allocated, else the program ends with
 * the library's message. */
void cli_mem_check(const char *what, uint64_t nmemb, uint64_t size);
void *cli_calloc(const char *what, uint64_t nmemb, uint64_t size);
/* The same allocation for work that reports its own failures (a
 * parallel task, whose caller names the file): NULL after cli_fail,
 * the program goes on. */
void *cli_try_calloc(const char *what, uint64_t nmemb, uint64_t size);

/*
 * The output step (output.c): a file opened (outfile.h: written
 * beside its target and renamed into place), written, and committed, or
 * on any failure removed, the program ending with the library's message.
 */
/* path NULL or "-": standard output, which binary output refuses when it
 * is a terminal. */
void cli_out_open(struct outfile *of, const char *path, int binary);
/* rc: what writing of->fp gave (-1 after frs_fail: the file removed). */
void cli_out_commit(struct outfile *of, int rc);

/*
 * The options and inputs of the programs that read point sets (ptsopt.c;
 * dda, discrepancy, mc-error, pts-render; ptsets.h): --sets N,
 * --group G and the point files named after the options; and --sets M of
 * those that write them (frs-sample, hsw-sample, ref-sample;
 * setsout.h).
 */
/* --sets N: every file split into sets of N points. */
size_t cli_sets(const char *arg);
/* --sets M of a sampler: M sets one after another. */
uint64_t cli_sets_m(const char *arg);
/* M sets of n points each (n: the most a set can have) fit one file and
 * their seeds, from -S on, stay within 2^64 - 1; else a usage error. */
void cli_sets_check(uint64_t m, uint64_t n);
/* --group G: n, file or all. */
enum pt_group cli_group(const char *arg);
/* The files after the options: at least one, else a usage error. */
void cli_need_files(int argc);
/* Each file after the options read into s (pt_sets_add with per), then
 * handed to each (when not NULL) with its number among the files and its
 * first set; a failure of either ends the program with its message. */
void cli_read_sets(struct pt_sets *s, int argc, char **argv, size_t per,
    int (*each)(void *ctx, const struct pt_sets *s, size_t file,
    size_t first), void *ctx);

#endif
