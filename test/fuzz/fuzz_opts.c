/* libFuzzer target: the option parsing of every program.  The first byte
 * picks the program; the rest, split at NUL bytes, is its argument list.
 * Each program's main runs until its options are parsed and checked
 * (cli_options_done) or until it exits with a usage error; cli_trap
 * turns both into a longjmp back here (src/cli/cli.h).  A program that
 * reaches its work without passing cli_options_done aborts the run. */
#define _POSIX_C_SOURCE 200809L
#include <getopt.h>
#include <setjmp.h>
#include <string.h>

#include "cli/cli.h"
#include "fuzz.h"

/* The programs' main functions, renamed at compile time (Makefile). */
int main_imap(int, char **);
int main_frd_gen(int, char **);
int main_frd_prep(int, char **);
int main_frs_sample(int, char **);
int main_pts_render(int, char **);
int main_ref_sample(int, char **);
int main_hsw_sample(int, char **);
int main_discrepancy(int, char **);
int main_dda(int, char **);
int main_mc_error(int, char **);

static const struct {
	const char *name;
	int (*main)(int, char **);
} prog[] = {
	{ "imap", main_imap }, { "frd-gen", main_frd_gen },
	{ "frd-prep", main_frd_prep }, { "frs-sample", main_frs_sample },
	{ "pts-render", main_pts_render }, { "ref-sample", main_ref_sample },
	{ "hsw-sample", main_hsw_sample }, { "discrepancy", main_discrepancy },
	{ "dda", main_dda }, { "mc-error", main_mc_error },
};
#define NPROG (sizeof prog / sizeof prog[0])
#define MAXARG 32

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static char buf[2048];
	char *argv[MAXARG + 2];
	int argc = 1;
	size_t p;
	jmp_buf trap;

	if (size < 1 || size >= sizeof buf)
		return 0;
	fuzz_init();
	memcpy(buf, data + 1, size - 1);
	buf[size - 1] = '\0';
	p = data[0] % NPROG;
	argv[0] = (char *)prog[p].name;
	for (size_t i = 0; i < size - 1 && argc <= MAXARG; ) {
		argv[argc++] = buf + i;
		i += strlen(buf + i) + 1;
	}
	argv[argc] = NULL;
	optind = 0;	/* GNU getopt: start afresh, as in a new process */
	opterr = 0;
	cli_trap = &trap;
	if (setjmp(trap) == 0) {
		prog[p].main(argc, argv);
		/* Returned without passing cli_options_done: it did work
		 * with options nobody checked. */
		abort();
	}
	cli_trap = NULL;
	fflush(stdout);
	frs_clearerr();
	return 0;
}
