#ifndef FRS_WIDE_H
#define FRS_WIDE_H

/*
 * FRS_WIDE before a function whose loops gain from vectors wider than the
 * build's base (SSE2 on x86-64): GCC and Clang compile it three times,
 * for AVX-512, AVX2 and the base, and the loader picks the one the
 * processor runs (target_clones, an ifunc).  So the default build stays
 * portable, as a package needs, and runs those loops as a -march=native
 * build does.  The bits are the same in every clone: C11 mode contracts
 * no a * b + c, and vector adds, multiplies and divides round as scalar
 * ones do.  Static functions only: Clang 14 gives an external one's
 * dispatcher another name than its callers in other files use.
 */
#if defined(__x86_64__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define FRS_WIDE __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
#endif
#ifndef FRS_WIDE
#define FRS_WIDE
#endif

#endif
