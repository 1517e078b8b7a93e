#define _POSIX_C_SOURCE 200809L
#include "base/num.h"

double num_sum(const double *v, size_t n)
{
	struct num_sum a = { 0.0, 0.0 };

	for (size_t i = 0; i < n; i++)
		num_add(&a, v[i]);
	return num_total(&a);
}

double num_radical_inverse(uint64_t i, unsigned b)
{
	double inv = 1.0 / b, f = inv, r = 0.0;

	while (i > 0) {
		r += (double)(i % b) * f;
		i /= b;
		f *= inv;
	}
	return r;
}
