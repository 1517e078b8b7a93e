/* The memory ceiling (src/lib/base/mem.c): FRS_MAX_MEM parsed with its units,
 * requests above it refused with both figures, products that overflow
 * refused, and the readers refusing a header's size before allocating. */
#include "testutil.h"
#include "formats/frdio.h"
#include "maps/imap.h"
#include "base/io.h"
#include "base/mem.h"

#include <string.h>

static void limits(void **state)
{
	static const struct { const char *s; uint64_t v; } t[] = {
		{ "4096", 4096 }, { "100B", 100 }, { "1k", 1024 },
		{ "512M", 512ull << 20 }, { "8G", 8ull << 30 },
		{ "8GiB", 8ull << 30 }, { "1.5G", 3ull << 29 },
		{ "2T", 2ull << 40 }, { "abc", 0 }, { "0", 0 }, { "-5M", 0 },
		{ "5X", 0 }, { "5Mi", 0 }, { "1e30T", 0 },
	};
	(void)state;

	for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
		setenv("FRS_MAX_MEM", t[i].s, 1);
		if (mem_limit() != t[i].v)
			fail_msg("FRS_MAX_MEM=%s gave %llu, expected %llu", t[i].s,
			    (unsigned long long)mem_limit(),
			    (unsigned long long)t[i].v);
	}
	/* Unset: the physical memory, which is more than nothing. */
	unsetenv("FRS_MAX_MEM");
	assert_true(mem_limit() > (1u << 20));
}

static void checks(void **state)
{
	char buf[32];
	(void)state;

	setenv("FRS_MAX_MEM", "1M", 1);
	assert_int_equal(mem_check("x", 1024, 1024), 0);	/* exactly 1 MiB */
	assert_int_equal(mem_check("x", 1024 * 1024 + 1, 1), -1);
	assert_err_has("x: needs 1.0 MiB", "above the memory limit of 1.0 MiB",
	    "FRS_MAX_MEM");
	assert_int_equal(mem_check("big", 3, 1ull << 30), -1);
	assert_err_has("big: needs 3.0 GiB");
	/* A product that wraps around 2^64 is not small. */
	assert_int_equal(mem_check("wrap", 1ull << 33, 1ull << 33), -1);
	assert_err_has("wrap: needs more than 16 EiB");
	setenv("FRS_MAX_MEM", "lots", 1);
	assert_int_equal(mem_check("x", 1, 1), -1);
	assert_err_has("FRS_MAX_MEM=lots: not a size");
	unsetenv("FRS_MAX_MEM");
	assert_string_equal(mem_human(1023, buf), "1023 bytes");
	assert_string_equal(mem_human(1536, buf), "1.5 KiB");
	assert_string_equal(mem_human(5ull << 40, buf), "5.0 TiB");
}

static void allocs(void **state)
{
	unsigned char *p;
	(void)state;

	setenv("FRS_MAX_MEM", "64k", 1);
	p = mem_calloc("small", 1000, 64);
	assert_non_null(p);
	for (int i = 0; i < 64000; i++)
		assert_int_equal(p[i], 0);
	assert_null(mem_realloc("grow", p, 65537, 1));	/* p survives */
	p[63999] = 7;
	p = mem_realloc("grow", p, 65536, 1);
	assert_non_null(p);
	assert_int_equal(p[63999], 7);
	free(p);
	assert_null(mem_calloc("huge", 1ull << 20, 1));
	assert_err_has("huge: needs 1.0 MiB");
	unsetenv("FRS_MAX_MEM");
}

/* A .frd header that claims 65536x65536 elements, read from a pipe (no
 * file length to check it against): refused before the 16 GiB exist. */
static void frd_header_from_pipe(void **state)
{
	unsigned char h[FRD_HEADER] = { 0 };
	int fd[2];
	FILE *fp;
	struct frs_matrix m;
	(void)state;

	memcpy(h, FRD_MAGIC, 8);
	io_put_u32(h + 8, FRD_VERSION);
	io_put_u32(h + 12, 2);
	io_put_u32(h + 16, 65536);
	io_put_u32(h + 20, 65536);
	io_put_u32(h + 24, 1);
	assert_int_equal(pipe(fd), 0);
	assert_int_equal(write(fd[1], h, sizeof h), (ssize_t)sizeof h);
	close(fd[1]);
	fp = fdopen(fd[0], "rb");
	setenv("FRS_MAX_MEM", "1G", 1);
	assert_int_equal(frd_read_fp(fp, "pipe", &m), -1);
	assert_err_has("pipe: 65536x65536 matrix: needs 16.0 GiB",
	    "limit of 1.0 GiB");
	fclose(fp);
	unsetenv("FRS_MAX_MEM");
}

static void map_alloc(void **state)
{
	struct frs_imap m;
	(void)state;

	setenv("FRS_MAX_MEM", "1M", 1);
	assert_int_equal(imap_alloc(&m, 256, 512), 0);	/* 1 MiB of doubles */
	imap_free(&m);
	assert_int_equal(imap_alloc(&m, 257, 512), -1);
	assert_err_has("257x512 map: needs 1.0 MiB");
	unsetenv("FRS_MAX_MEM");
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(limits),
	cmocka_unit_test(checks),
	cmocka_unit_test(allocs),
	cmocka_unit_test(frd_header_from_pipe),
	cmocka_unit_test(map_alloc))
