#define _POSIX_C_SOURCE 200809L
#include "cli/cli.h"
#include "frs.h"
#include "base/err.h"
#include "base/mem.h"
#include "base/ocl.h"
#include "base/par.h"
#include "base/parse.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct cli_common cli = { NULL, 0, 1, 0, 0, 0 };
const char *cli_prog = "frs";
static const char *usage_text = "";
jmp_buf *cli_trap;
/* An error was reported: check_stdout stays quiet (see there). */
static int reported;

/* exit(status), or the fuzz target's longjmp (see cli.h). */
static noreturn void cli_exit(int status)
{
	if (cli_trap != NULL)
		longjmp(*cli_trap, status + 1);
	exit(status);
}

/*
 * Reports, --help and --version go to standard output through stdio,
 * which exit() flushes with the error ignored: a full disk or a closed
 * pipe (SIGPIPE ignored) would lose them and still give status 0.  So
 * check at exit, as gnulib's close_stdout does (output files check their
 * own errors in outfile.c).  After a reported error the buffer may still
 * hold what failed; a second message would only repeat it.
 */
static void check_stdout(void)
{
	if (reported)
		return;
	errno = 0;
	if (fflush(stdout) != 0 || ferror(stdout)) {
		fprintf(stderr, "%s: <stdout>: write error: %s\n", cli_prog,
		    errno ? strerror(errno) : "input/output error");
		outfile_cleanup_all();
		_exit(1);
	}
}

void cli_options_done(void)
{
	if (cli_trap != NULL)
		longjmp(*cli_trap, CLI_PARSED);
}

/* The bar cli_init installs (see cli.h). */
static struct cli_bar bar;

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

static void bar_draw(struct cli_bar *b, double now)
{
	double el = now - b->start;
	double frac = b->total ? (double)b->done / (double)b->total : 0.0;
	double rate = el > 0 ? (double)b->done / el : 0.0;
	char eta[32];
	int len = (int)(frac * 30.0 + 0.5);

	fmt_time(eta, sizeof eta, rate > 0 ? (double)(b->total - b->done) /
	    rate : -1);
	fprintf(stderr, "\r%s: %s [%-30.*s] %5.1f%% %.3g/s ETA %s ", cli_prog,
	    b->label, len, "##############################", 100.0 * frac,
	    rate, eta);
	fflush(stderr);
	b->drawn = 1;
}

void cli_bar_progress(void *ctx, const char *what, uint64_t done,
    uint64_t total)
{
	struct cli_bar *b = ctx;
	double now;

	if (b->active && done >= b->total) {	/* the end */
		now = cli_now();
		b->done = b->total;
		b->active = 0;
		if (b->on && (b->drawn || now - b->start >= 1.0)) {
			bar_draw(b, now);
			fputc('\n', stderr);
		}
		b->on = 0;
		return;
	}
	if (!b->active || done == 0) {		/* a task starts */
		b->active = 1;
		b->label = what;
		b->total = total;
		b->done = 0;
		b->start = b->last = cli_now();
		b->drawn = 0;
		b->on = !cli.quiet && (cli.progress || isatty(STDERR_FILENO));
		return;
	}
	b->done = done;
	if (!b->on)
		return;
	/* Nothing for the first second; then at most 10 redraws a second. */
	now = cli_now();
	if (now - b->start < 1.0 || now - b->last < 0.1)
		return;
	b->last = now;
	bar_draw(b, now);
}

void cli_init(const char *prog, const char *usage)
{
	static int registered;

	if (!registered) {
		registered = 1;
		atexit(check_stdout);
	}
	cli = (struct cli_common){ NULL, 0, 1, 0, 0, 0 };
	cli_prog = prog;
	usage_text = usage;
	bar = (struct cli_bar){ NULL, 0, 0, 0.0, 0.0, 0, 0, 0 };
	frs_set_progress(cli_bar_progress, &bar);
	cli.threads = cli_ncpu();
	frs_set_threads(cli.threads);
	frs_set_warn_prefix(prog);
}

int cli_ncpu(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);
	return n < 1 ? 1 : n > 1024 ? 1024 : (int)n;
}

void cli_mem_check(const char *what, uint64_t nmemb, uint64_t size)
{
	if (mem_check(what, nmemb, size) < 0)
		cli_die_lib();
}

void *cli_try_calloc(const char *what, uint64_t nmemb, uint64_t size)
{
	return mem_calloc(what, nmemb, size);
}

void *cli_calloc(const char *what, uint64_t nmemb, uint64_t size)
{
	void *p = mem_calloc(what, nmemb, size);

	if (p == NULL)
		cli_die_lib();
	return p;
}

noreturn void cli_usage(int status)
{
	FILE *fp = status ? stderr : stdout;

	if (status) {
		/* Only the synopsis on errors. */
		const char *nl = strchr(usage_text, '\n');
		int len = nl ? (int)(nl - usage_text) : (int)strlen(usage_text);
		fprintf(fp, "%.*s\nTry '%s --help' for more information.\n",
		    len, usage_text, cli_prog);
	} else {
		fputs(usage_text, fp);
	}
	cli_exit(status);
}

/* "prog: message\n" on standard error, the message escaped. */
static void say(const char *fmt, va_list ap)
{
	fprintf(stderr, "%s: ", cli_prog);
	frs_vprint_escaped(stderr, fmt, ap);
	fputc('\n', stderr);
}

noreturn void cli_usage_error(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	say(fmt, ap);
	va_end(ap);
	cli_usage(2);
}

int cli_choice(const char *opt, const char *s, const char *const *words)
{
	int n = 0;

	for (; words[n] != NULL; n++)
		if (strcmp(s, words[n]) == 0)
			return n;
	{
		char e[1024];
		frs_escape(e, sizeof e, s);
		fprintf(stderr, "%s: %s: '%s' is not ", cli_prog, opt, e);
	}
	for (int i = 0; i < n; i++)
		fprintf(stderr, "%s%s", words[i], i + 2 < n ? ", " :
		    i + 2 == n ? " or " : "\n");
	cli_usage(2);
}

noreturn void cli_die(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	say(fmt, ap);
	va_end(ap);
	outfile_cleanup_all();
	reported = 1;
	cli_exit(1);
}

noreturn void cli_die_lib(void)
{
	/* A procedural map spec that does not parse is a bad argument,
	 * though only loading the map finds it: a usage error. */
	if (frs_errkind() == FRS_ERRKIND_SPEC) {
		outfile_cleanup_all();
		reported = 1;
		cli_usage_error("%s", frs_errmsg());
	}
	cli_die("%s", frs_errmsg());
}

const char *cli_errmsg(void)
{
	return frs_errmsg();
}

void cli_note(const char *fmt, ...)
{
	va_list ap;

	if (cli.quiet)
		return;
	va_start(ap, fmt);
	say(fmt, ap);
	va_end(ap);
}

static const struct option common_options[] = {
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, OPT_VERSION },
	{ "output", required_argument, NULL, 'o' },
	{ "text", no_argument, NULL, 'T' },
	{ "seed", required_argument, NULL, 'S' },
	{ "threads", required_argument, NULL, 'j' },
	{ "quiet", no_argument, NULL, 'q' },
	{ "progress", no_argument, NULL, OPT_PROGRESS }
};

#define CLI_OPTION_ROW_(id, name, has_arg) { name, has_arg, NULL, OPT_##id },
static const struct option all_options[] = { CLI_OPTIONS(CLI_OPTION_ROW_) };

#define MAX_OPTIONS 48

/* Other spellings of an option: the same value, so that getopt_long does
 * not call their common prefix ambiguous. */
static const struct {
	const char *name, *same;
} spellings[] = {
	{ "colour", "color" }
};

static int token_is(const char *tok, size_t len, const char *name)
{
	return strlen(name) == len && memcmp(name, tok, len) == 0;
}

/* One option of a program's list: "name" or "x=name". */
static struct option option_entry(const char *tok, size_t len)
{
	const char *spelling = NULL;
	int letter = 0;

	if (len > 2 && tok[1] == '=') {
		letter = (unsigned char)tok[0];
		tok += 2;
		len -= 2;
	}
	for (size_t i = 0; i < sizeof spellings / sizeof *spellings; i++)
		if (token_is(tok, len, spellings[i].name)) {
			spelling = spellings[i].name;
			tok = spellings[i].same;
			len = strlen(tok);
		}
	for (size_t i = 0; i < sizeof all_options / sizeof *all_options; i++) {
		struct option o = all_options[i];

		if (token_is(tok, len, o.name)) {
			if (letter != 0)
				o.val = letter;
			if (spelling != NULL)
				o.name = spelling;
			return o;
		}
	}
	fprintf(stderr, "%s: internal error: no option '%.*s' in CLI_OPTIONS\n",
	    cli_prog, (int)len, tok);
	abort();
}

/* The getopt_long table and short options of a program's list and the
 * common options. */
static void option_table(const char *options, struct option *table,
    char *shortopts)
{
	size_t n = 0, ns = 0;

	for (const char *p = options; *p != '\0'; ) {
		size_t len = strcspn(p, " ");

		if (len > 0) {
			if (n == MAX_OPTIONS) {
				fprintf(stderr, "%s: internal error: more than %d "
				    "options\n", cli_prog, MAX_OPTIONS);
				abort();
			}
			table[n++] = option_entry(p, len);
		}
		p += len + (p[len] == ' ');
	}
	for (size_t i = 0; i < sizeof common_options / sizeof *common_options; i++)
		table[n++] = common_options[i];
	table[n] = (struct option){ NULL, 0, NULL, 0 };
	for (size_t i = 0; i < n; i++) {
		if (table[i].val >= 128 || !isalnum(table[i].val))
			continue;
		shortopts[ns++] = (char)table[i].val;
		if (table[i].has_arg == required_argument)
			shortopts[ns++] = ':';
	}
	shortopts[ns] = '\0';
}

int cli_getopt(int argc, char **argv, const char *options)
{
	static struct option table[MAX_OPTIONS + 9];
	static char shortopts[2 * (MAX_OPTIONS + 8) + 1];
	static const char *made_for;

	/* Once a list: the fuzz target runs several programs in one
	 * process, each with its own. */
	if (options != made_for) {
		option_table(options, table, shortopts);
		made_for = options;
	}
	/* getopt's own messages name argv[0]: the program's name instead of
	 * the path it was run by (or a command's name, as imap's). */
	if (argc > 0)
		argv[0] = (char *)cli_prog;
	return getopt_long(argc, argv, shortopts, table, NULL);
}

int cli_common_opt(int c, const char *arg)
{
	switch (c) {
	case 'h':
		cli_usage(0);
	case OPT_VERSION:
		printf("%s (frs) %s\n", cli_prog, frs_library_version());
		cli_exit(0);
	case 'o':
		cli.out = cli_outname("-o", arg);
		return 1;
	case 'T':
		cli.text = 1;
		return 1;
	case 'S':
		cli.seed = cli_u64("-S", arg, 0, UINT64_MAX);
		return 1;
	case 'j':
		cli.threads = (int)cli_ll("-j", arg, 1, 1024);
		frs_set_threads(cli.threads);
		return 1;
	case 'q':
		cli.quiet = 1;
		frs_set_quiet(1);
		return 1;
	case OPT_PROGRESS:
		cli.progress = 1;
		return 1;
	case '?':
		cli_usage(2);
	default:
		return 0;
	}
}

void cli_common_only(int c, const char *arg)
{
	if (!cli_common_opt(c, arg))
		cli_usage(2);
}

void cli_no_operands(int argc, char **argv)
{
	if (optind != argc)
		cli_usage_error("unexpected argument '%s'", argv[optind]);
}

const char *cli_outname(const char *opt, const char *s)
{
	if (*s == '\0')
		cli_usage_error("%s: an empty file name (- is standard output)",
		    opt);
	return s;
}

void cli_out_check(const char *path, int binary)
{
	if (binary && (path == NULL || strcmp(path, "-") == 0) &&
	    isatty(STDOUT_FILENO))
		cli_die("<stdout>: refusing to write binary data to a terminal "
		    "(use -o FILE or a pipe)");
}

long long cli_ll(const char *opt, const char *s, long long min, long long max)
{
	long long v;
	if (parse_ll(opt, s, min, max, &v) < 0)
		cli_usage_error("%s", frs_errmsg());
	return v;
}

uint64_t cli_u64(const char *opt, const char *s, uint64_t min, uint64_t max)
{
	uint64_t v;
	if (parse_u64(opt, s, min, max, &v) < 0)
		cli_usage_error("%s", frs_errmsg());
	return v;
}

double cli_double(const char *opt, const char *s, double min, double max)
{
	double v;
	if (parse_double(opt, s, min, max, &v) < 0)
		cli_usage_error("%s", frs_errmsg());
	return v;
}

double cli_double_above(const char *opt, const char *s, double min,
    double max)
{
	return cli_double_above_hint(opt, s, min, max, NULL);
}

double cli_double_above_hint(const char *opt, const char *s, double min,
    double max, const char *hint)
{
	double v;
	if (parse_double_above(opt, s, min, max, &v) < 0)
		cli_usage_error("%s%s", frs_errmsg(), hint != NULL &&
		    strtod(s, NULL) <= min ? hint : "");
	return v;
}

void cli_size(const char *opt, const char *s, uint32_t max, uint32_t *w,
    uint32_t *h)
{
	if (parse_size(opt, s, max, w, h) < 0)
		cli_usage_error("%s", frs_errmsg());
}

int cli_size3(const char *opt, const char *s, uint32_t max, uint32_t sz[3])
{
	const char *x1 = strchr(s, 'x'), *x2 = x1 ? strchr(x1 + 1, 'x') : NULL;
	char buf[64];
	size_t len;

	if (x2 == NULL) {
		cli_size(opt, s, max, &sz[0], &sz[1]);
		sz[2] = sz[0];
		return x1 == NULL ? 1 : 2;
	}
	len = (size_t)(x2 - s);
	if (len >= sizeof buf)
		cli_usage_error("%s: '%s' is not a size (N, WxH or WxHxD)", opt, s);
	memcpy(buf, s, len);
	buf[len] = '\0';
	cli_size(opt, buf, max, &sz[0], &sz[1]);
	sz[2] = (uint32_t)cli_ll(opt, x2 + 1, 1, max);
	return 3;
}

int cli_device(const char *arg, int *index)
{
	int cl = ocl_parse_device(arg, index);

	if (cl < 0)
		cli_usage_error("--device: %s", frs_errmsg());
	return cl;
}

noreturn void cli_die_device(int cpu_too)
{
	cli_die("--device: %s; see --list-devices%s", frs_errmsg(),
	    cpu_too ? ", or use --device cpu" : "");
}

noreturn void cli_list_devices(void)
{
	cli_options_done();	/* the fuzz target stops here */
	if (ocl_list(stdout) < 0)
		cli_die("--list-devices: %s", frs_errmsg());
	if (fflush(stdout) == EOF || ferror(stdout))
		cli_die("--list-devices: write error");
	cli_exit(0);
}
