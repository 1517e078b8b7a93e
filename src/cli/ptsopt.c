#define _POSIX_C_SOURCE 200809L
#include <stdint.h>

#include "cli/cli.h"

size_t cli_sets(const char *arg)
{
	return (size_t)cli_u64("--sets", arg, 1, (uint64_t)1 << 40);
}

uint64_t cli_sets_m(const char *arg)
{
	return cli_u64("--sets", arg, 1, SETS_MAX_POINTS);
}

void cli_sets_check(uint64_t m, uint64_t n)
{
	if (m > SETS_MAX_POINTS / n)
		cli_usage_error("--sets %llu: %llu sets of %llu points exceed "
		    "the 2^56 points one file can hold", (unsigned long long)m,
		    (unsigned long long)m, (unsigned long long)n);
	if (m - 1 > UINT64_MAX - cli.seed)
		cli_usage_error("--sets %llu: the seeds from -S %llu would pass "
		    "2^64-1", (unsigned long long)m,
		    (unsigned long long)cli.seed);
}

enum pt_group cli_group(const char *arg)
{
	int g = pt_group_parse(arg);

	if (g < 0)
		cli_usage_error("--group: '%s' is not n, file or all", arg);
	return (enum pt_group)g;
}

void cli_need_files(int argc)
{
	if (optind == argc)
		cli_usage_error("no point files");
}

void cli_read_sets(struct pt_sets *s, int argc, char **argv, size_t per,
    int (*each)(void *ctx, const struct pt_sets *s, size_t file,
    size_t first), void *ctx)
{
	for (int i = optind; i < argc; i++) {
		size_t first = s->n;
		if (pt_sets_add(s, argv[i], per) < 0 || (each != NULL &&
		    each(ctx, s, (size_t)(i - optind), first) < 0))
			cli_die_lib();
	}
}
