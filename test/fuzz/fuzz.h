/*
 * Shared helpers of the libFuzzer targets (test/fuzz/fuzz_*.c): readers
 * that take a path get the input through one private temporary file per
 * process, created on first use and rewritten for every input.
 */
#ifndef FRS_FUZZ_H
#define FRS_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "base/err.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char fuzz_path[64];

static void fuzz_unlink(void)
{
	if (fuzz_path[0] != '\0')
		unlink(fuzz_path);
}

/* Once per process: no warnings, and the temporary file. */
static inline void fuzz_init(void)
{
	static int done;

	if (done)
		return;
	done = 1;
	frs_set_quiet(1);
	snprintf(fuzz_path, sizeof fuzz_path, "/tmp/frs-fuzz-XXXXXX");
	int fd = mkstemp(fuzz_path);
	if (fd < 0) {
		perror("fuzz: mkstemp");
		abort();
	}
	close(fd);
	atexit(fuzz_unlink);
}

/* The path of the temporary file, now holding data. */
static inline const char *fuzz_file(const uint8_t *data, size_t size)
{
	fuzz_init();
	FILE *fp = fopen(fuzz_path, "wb");
	if (fp == NULL || (size > 0 && fwrite(data, 1, size, fp) != size) ||
	    fclose(fp) != 0) {
		perror("fuzz: writing the temporary file");
		abort();
	}
	return fuzz_path;
}

#endif
