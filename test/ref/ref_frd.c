/*
 * ref_frd: the brute-force FRD reference as a program, for the benchmark:
 *   ref_frd W H P TOL REACH SEED > matrix.u32
 * writes the values as raw little-endian uint32.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>

#include "base/err.h"
#include "ref_frd.h"

int main(int argc, char **argv)
{
	struct frdgen_params pr;
	uint32_t *v;
	size_t n;

	if (argc != 7) {
		fprintf(stderr, "usage: ref_frd W H P TOL REACH SEED\n");
		return 2;
	}
	frdgen_defaults(&pr);
	pr.w = (uint32_t)atoi(argv[1]);
	pr.h = (uint32_t)atoi(argv[2]);
	pr.d = 1;
	pr.dims = 2;
	pr.p = atof(argv[3]);
	pr.tol = atof(argv[4]);
	pr.reach = atof(argv[5]);
	pr.seed = strtoull(argv[6], NULL, 10);
	if (frdgen_check(&pr) < 0) {
		fprintf(stderr, "ref_frd: %s\n", frs_errmsg());
		return 2;
	}
	n = (size_t)pr.w * pr.h;
	v = malloc(n * sizeof *v);
	if (v == NULL)
		return 1;
	reference(&pr, v);
	return fwrite(v, 4, n, stdout) == n ? 0 : 1;
}
