/*
 * The memory ceiling.  A request that a header or an option makes (a
 * matrix of s^2 elements, a map of WxH pixels, n points) is checked
 * against it before anything is allocated, and refused with the figure it
 * would have needed, instead of failing half-way or being killed.
 *
 * The ceiling is FRS_MAX_MEM, in bytes with an optional binary suffix
 * (k, M, G, T: 512M, 8G), or the machine's physical memory when unset.
 */
#ifndef FRS_MEM_H
#define FRS_MEM_H

#include <stddef.h>
#include <stdint.h>

/* The ceiling in bytes; 0 when FRS_MAX_MEM is not a size (mem_check
 * then fails naming the bad value). */
uint64_t mem_limit(void);
/* 0 if nmemb * size bytes are within the ceiling; otherwise -1 after
 * frs_fail("WHAT: needs X, above the memory limit of Y (FRS_MAX_MEM)").
 * Overflowing products count as too large. */
int mem_check(const char *what, uint64_t nmemb, uint64_t size);
/* calloc(nmemb, size) after mem_check; NULL after frs_fail naming what
 * when refused or out of memory. */
void *mem_calloc(const char *what, uint64_t nmemb, uint64_t size);
/* realloc to nmemb * size bytes, checked the same way; on failure p is
 * untouched. */
void *mem_realloc(const char *what, void *p, uint64_t nmemb, uint64_t size);
/* malloc for large buffers, in huge pages where available; free() frees
 * it.  No ceiling check (the caller's). */
void *mem_big(size_t bytes);
/* free() of every pointer named: MEM_FREE(g->a, g->b, g->c), for the
 * teardowns of structures that hold many buffers. */
#define MEM_FREE(...) \
	mem_free_n((void *[]){ __VA_ARGS__ }, \
	    sizeof((void *[]){ __VA_ARGS__ }) / sizeof(void *))
void mem_free_n(void *const *p, size_t n);
/* "12.5 GiB": bytes in the largest binary unit that keeps it >= 1. */
const char *mem_human(uint64_t bytes, char buf[32]);

#endif
