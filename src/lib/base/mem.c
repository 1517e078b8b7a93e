#define _POSIX_C_SOURCE 200809L
/* madvise and MADV_HUGEPAGE (Linux) are outside POSIX. */
#define _DEFAULT_SOURCE
#include "base/mem.h"
#include "base/err.h"

#include <errno.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

/* Parse "123", "512M", "8G", "1.5T" (binary units); 0 when not a size. */
static uint64_t parse_size(const char *s)
{
	char *end;
	double v, mul = 1;

	errno = 0;
	v = strtod(s, &end);
	if (end == s || errno != 0 || !(v > 0))
		return 0;
	switch (*end) {
	case 'k': case 'K': mul = 0x1p10; end++; break;
	case 'm': case 'M': mul = 0x1p20; end++; break;
	case 'g': case 'G': mul = 0x1p30; end++; break;
	case 't': case 'T': mul = 0x1p40; end++; break;
	default: break;
	}
	if (mul > 1 && end[0] == 'i' && end[1] == 'B')	/* "8GiB" */
		end += 2;
	else if (*end == 'B')				/* "8GB", "100B" */
		end++;
	if (*end != '\0' || v * mul >= 0x1p64)
		return 0;
	return (uint64_t)(v * mul);
}

static uint64_t physical(void)
{
	long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);

	if (pages <= 0 || page <= 0)
		return UINT64_MAX;
	return (uint64_t)pages * (uint64_t)page;
}

void mem_free_n(void *const *p, size_t n)
{
	for (size_t i = 0; i < n; i++)
		free(p[i]);
}

uint64_t mem_limit(void)
{
	const char *s = getenv("FRS_MAX_MEM");

	if (s == NULL || *s == '\0')
		return physical();
	return parse_size(s);
}

const char *mem_human(uint64_t bytes, char buf[32])
{
	static const char *unit[] = { "bytes", "KiB", "MiB", "GiB", "TiB",
	    "PiB", "EiB" };
	double v = (double)bytes;
	int u = 0;

	while (v >= 1024 && u < 6) {
		v /= 1024;
		u++;
	}
	if (u == 0)
		snprintf(buf, 32, "%llu bytes", (unsigned long long)bytes);
	else
		snprintf(buf, 32, "%.1f %s", v, unit[u]);
	return buf;
}

int mem_check(const char *what, uint64_t nmemb, uint64_t size)
{
	uint64_t lim = mem_limit();
	char need[32], have[32];

	if (lim == 0)
		return frs_fail("FRS_MAX_MEM=%s: not a size (write e.g. 512M or "
		    "8G)", getenv("FRS_MAX_MEM"));
	if (size != 0 && nmemb > UINT64_MAX / size) {
		frs_fail("%s: needs more than 16 EiB of memory", what);
		frs_set_errkind(FRS_ERRKIND_MEM);
		return -1;
	}
	if (nmemb * size > lim || nmemb * size > SIZE_MAX) {
		frs_fail("%s: needs %s, above the memory limit of %s "
		    "(FRS_MAX_MEM)", what, mem_human(nmemb * size, need),
		    mem_human(lim, have));
		frs_set_errkind(FRS_ERRKIND_MEM);
		return -1;
	}
	return 0;
}

static void out_of_memory(const char *what, uint64_t nmemb, uint64_t size)
{
	char need[32];

	frs_fail("%s: out of memory (needed %s)", what,
	    mem_human(nmemb * size, need));
	frs_set_errkind(FRS_ERRKIND_MEM);
}

void *mem_calloc(const char *what, uint64_t nmemb, uint64_t size)
{
	void *p;

	if (mem_check(what, nmemb, size) < 0)
		return NULL;
	p = calloc(nmemb ? (size_t)nmemb : 1, size ? (size_t)size : 1);
	if (p == NULL)
		out_of_memory(what, nmemb, size);
	return p;
}

void *mem_realloc(const char *what, void *p, uint64_t nmemb, uint64_t size)
{
	void *q;

	if (mem_check(what, nmemb, size) < 0)
		return NULL;
	q = realloc(p, nmemb != 0 && size != 0 ? (size_t)(nmemb * size) : 1);
	if (q == NULL)
		out_of_memory(what, nmemb, size);
	return q;
}

/* Big buffers in 2 MiB pages where the system offers them
 * (transparent huge pages in "madvise" mode): a 16 MiB matrix then costs
 * 8 page faults instead of 4096, which for the sorted lists of one run
 * was a third of the setup. */
#define HUGE_PAGE ((size_t)2 << 20)

void *mem_big(size_t bytes)
{
	void *p = NULL;

	if (bytes < 2 * HUGE_PAGE)
		return malloc(bytes ? bytes : 1);
	if (posix_memalign(&p, HUGE_PAGE, (bytes + HUGE_PAGE - 1) &
	    ~(HUGE_PAGE - 1)) != 0)
		return NULL;
#ifdef MADV_HUGEPAGE
	(void)madvise(p, bytes, MADV_HUGEPAGE);	/* a hint: failure is fine */
#endif
	return p;
}
