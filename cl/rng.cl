/*
 * Philox4x32-10 (Salmon et al. 2011), as src/lib/base/rng.c: the key is the
 * 64-bit seed, the counter (index low, index high, stream, sub).  Every
 * kernel source is built after this one (and after cl/defs.cl, which
 * holds the streams).
 */

uint4 frs_philox(uint4 c, uint2 k)
{
	for (int r = 0; r < 10; r++) {
		uint hi0, lo0, hi1, lo1;
		if (r > 0) {
			k.x += 0x9E3779B9u;
			k.y += 0xBB67AE85u;
		}
		hi0 = mul_hi(0xD2511F53u, c.x);
		lo0 = 0xD2511F53u * c.x;
		hi1 = mul_hi(0xCD9E8D57u, c.z);
		lo1 = 0xCD9E8D57u * c.z;
		c = (uint4)(hi1 ^ c.y ^ k.x, lo1, hi0 ^ c.w ^ k.y, lo0);
	}
	return c;
}

/* 64 random bits at (seed, stream, index, sub), as frs_rand64x. */
ulong frs_rand64x(ulong seed, uint stream, ulong index, uint sub)
{
	uint4 o = frs_philox((uint4)((uint)index, (uint)(index >> 32), stream,
	    sub), (uint2)((uint)seed, (uint)(seed >> 32)));
	return (ulong)o.x | (ulong)o.y << 32;
}

/* The 53 bits of frs_rand01: the double is u * 2^-53. */
ulong frs_rand53(ulong seed, uint stream, ulong index)
{
	return frs_rand64x(seed, stream, index, 0) >> 11;
}
