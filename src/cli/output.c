#define _POSIX_C_SOURCE 200809L
#include "cli/cli.h"

void cli_out_open(struct outfile *of, const char *path, int binary)
{
	cli_out_check(path, binary);
	if (outfile_open(of, path, binary) < 0)
		cli_die_lib();
}

void cli_out_commit(struct outfile *of, int rc)
{
	if (rc < 0) {
		outfile_abort(of);
		cli_die_lib();
	}
	if (outfile_commit(of) < 0)
		cli_die_lib();
}
