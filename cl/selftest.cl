/* Kernels that check the runtime itself (test/test_ocl.c). */
__kernel void rand64(ulong seed, uint stream, ulong n, __global ulong *out)
{
	size_t i = get_global_id(0);
	if (i < n)
		out[i] = frs_rand64x(seed, stream, i, (uint)i & 7u);
}
