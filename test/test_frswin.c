/*
 * The k-dimensional setup (frs_window_setup) against the 2-D and 3-D
 * setups it replaced, kept here as they were (frs.c's frs_setup and
 * scaled_stats, frs3.c's frs3_setup, vol_stats and offset at 5263242):
 * the same n_s, window, offsets, tau, level0 and statistics, to the bit,
 * and the same failures with the same messages (theirs here without the
 * program flags they named, "-n" and "--sigma"), over maps and volumes of
 * many shapes and values (constant, random, one bright cell, denormal,
 * near DBL_MAX) and counts and sigmas up to the limits.
 */
#include "testutil.h"
#include "formats/frdio.h"
#include "maps/imap.h"
#include "maps/vol.h"
#include "sample/frs3.h"
#include "sample/frscore.h"

static uint32_t min3(uint32_t a, uint32_t b, uint32_t c)
{
	uint32_t m = a < b ? a : b;
	return m < c ? m : c;
}

/* ---- the 2-D setup as it was ------------------------------------ */

/* Mean and maximum of the map times the power of two iscale (exact for
 * every value that stays normal), compensated sum (Neumaier). */
static void scaled_stats(const struct frs_imap *map, double iscale,
    double *mean, double *max)
{
	uint64_t n = (uint64_t)map->w * map->h;
	double sum = 0.0, c = 0.0, mx = 0.0;

	for (uint64_t i = 0; i < n; i++) {
		double v = map->v[i] * iscale, t = sum + v;
		c += fabs(sum) >= fabs(v) ? (sum - t) + v : (v - t) + sum;
		sum = t;
		mx = v > mx ? v : mx;
	}
	*mean = (sum + c) / (double)n;
	*max = mx;
}

static int old_setup(struct frs_setup *s, const struct frs_imap *map,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed)
{
	struct frs_imap_stats st;
	uint32_t small, large;
	double a, wmin, imax;
	uint64_t ns = 1, ux, uy;

	memset(s, 0, sizeof *s);
	if (mat->dims != 2)
		return frs_fail("a %u-D matrix cannot sample a 2-D map", mat->dims);
	if (n == 0)
		return frs_fail("the count must be at least 1");
	if (!(sigma >= 1.0 && isfinite(sigma)))
		return frs_fail("sigma %g is below 1", sigma);
	imap_stats(map, &st);
	if (!(st.max > 0.0) || st.nonfinite || st.negatives)
		return frs_fail("importance must be finite, non-negative and not "
		    "zero everywhere");
	/* Only ratios matter: scale an extreme map by a power of two, so
	 * that tau and the mean stay finite; the thresholds of every other
	 * map are those of the map as it is. */
	s->iscale = 1.0;
	s->imean = st.mean;
	imax = st.max;
	if (!(st.max >= 0x1p-900 && st.max <= 0x1p900)) {
		int e = -ilogb(st.max);	/* 1074 for the smallest denormal */
		s->iscale = ldexp(1.0, e < 1023 ? e : 1023);
		scaled_stats(map, s->iscale, &s->imean, &imax);
		st.mean = s->imean / s->iscale;
	}
	s->iw = map->w;
	s->ih = map->h;
	s->mw = mat->w;
	s->mh = mat->h;
	s->n = n;
	s->sigma = sigma;
	s->mean = st.mean;
	s->max = st.max;
	s->seed = seed;
	small = map->w < map->h ? map->w : map->h;
	large = map->w < map->h ? map->h : map->w;
	a = (double)large / small;
	wmin = ceil(sigma * sqrt((double)n * imax / (s->imean * a)));
	while ((double)small * (double)ns < wmin) {
		ns <<= 1;
		if (ns > ((uint64_t)1 << 31))
			return frs_fail("%llu samples: the window would need "
			    "more than 2^31 elements per pixel side",
			    (unsigned long long)n);
	}
	s->ns = (uint32_t)ns;
	s->sw = ns * map->w;
	s->sh = ns * map->h;
	/* A random multiple of n_s, or of the matrix when n_s exceeds it
	 * (every offset is then the same). */
	ux = ns < mat->w ? ns : mat->w;
	uy = ns < mat->h ? ns : mat->h;
	s->wx = (uint64_t)(frs_rand01(seed, FRS_STREAM_WINDOW, 0) *
	    (double)(mat->w / ux)) * ux;
	s->wy = (uint64_t)(frs_rand01(seed, FRS_STREAM_WINDOW, 1) *
	    (double)(mat->h / uy)) * uy;
	s->tau = (double)n * (double)s->mw * (double)s->mh /
	    ((double)s->sw * (double)s->sh * s->imean);
	s->level0 = (unsigned)floor(log2(fmin((double)ns, sigma)));
	return 0;
}


/* ---- the 3-D setup as it was ------------------------------------ */

/* The map statistics of the volume, scaled by a power of two when its
 * maximum is extreme (as frs_setup does for maps). */
static int vol_stats(struct frs3_setup *s, const struct frs_vol *vol,
    double *imax)
{
	struct frs_imap view = vol_as_map(vol);
	struct frs_imap_stats st;
	uint64_t n = (uint64_t)vol->w * vol->h * vol->d;

	imap_stats(&view, &st);
	if (!(st.max > 0.0) || st.nonfinite || st.negatives)
		return frs_fail("importance must be finite, non-negative and not "
		    "zero everywhere");
	s->iscale = 1.0;
	s->mean = st.mean;
	s->max = st.max;
	s->imean = st.mean;
	*imax = st.max;
	if (!(st.max >= 0x1p-900 && st.max <= 0x1p900)) {
		double sum = 0.0, c = 0.0, mx = 0.0;
		int e = -ilogb(st.max);
		s->iscale = ldexp(1.0, e < 1023 ? e : 1023);
		for (uint64_t i = 0; i < n; i++) {
			double v = vol->v[i] * s->iscale, t = sum + v;
			c += fabs(sum) >= fabs(v) ? (sum - t) + v : (v - t) + sum;
			sum = t;
			mx = v > mx ? v : mx;
		}
		s->imean = (sum + c) / (double)n;
		s->mean = s->imean / s->iscale;
		*imax = mx;
	}
	return 0;
}

static uint64_t old_offset(uint64_t seed, uint32_t axis, uint64_t ns,
    uint32_t m)
{
	uint64_t u = ns < m ? ns : m;
	return (uint64_t)(frs_rand01(seed, FRS_STREAM_WINDOW, axis) *
	    (double)(m / u)) * u;
}

static int old_setup3(struct frs3_setup *s, const struct frs_vol *vol,
    const struct frs_matrix *mat, uint64_t n, double sigma, uint64_t seed)
{
	uint32_t small = min3(vol->w, vol->h, vol->d);
	double a, wmin, imax = 0.0;
	uint64_t ns = 1;

	memset(s, 0, sizeof *s);
	if (mat->dims != 3)
		return frs_fail("a %u-D matrix cannot sample a volume", mat->dims);
	if (n == 0)
		return frs_fail("the count must be at least 1");
	if (!(sigma >= 1.0 && isfinite(sigma)))
		return frs_fail("sigma %g is below 1", sigma);
	if (vol_stats(s, vol, &imax) < 0)
		return -1;
	s->iw = vol->w;
	s->ih = vol->h;
	s->id = vol->d;
	s->mw = mat->w;
	s->mh = mat->h;
	s->md = mat->d;
	s->n = n;
	s->sigma = sigma;
	s->seed = seed;
	a = (double)vol->w * vol->h * vol->d / ((double)small * small * small);
	wmin = ceil(sigma * cbrt((double)n * imax / (s->imean * a)));
	while ((double)small * (double)ns < wmin) {
		ns <<= 1;
		if (ns > ((uint64_t)1 << 20))
			return frs_fail("%llu samples: the window would need "
			    "more than 2^20 elements per voxel side",
			    (unsigned long long)n);
	}
	s->ns = (uint32_t)ns;
	s->sw = ns * vol->w;
	s->sh = ns * vol->h;
	s->sd = ns * vol->d;
	/* Element ids (z S_H + y) S_W + x must fit 64 bits. */
	if ((double)s->sw * (double)s->sh * (double)s->sd >= 0x1p63)
		return frs_fail("%llu samples: the window of %llux%llux%llu "
		    "elements is too large", (unsigned long long)n, (unsigned long long)s->sw,
		    (unsigned long long)s->sh, (unsigned long long)s->sd);
	s->wx = old_offset(seed, 0, ns, mat->w);
	s->wy = old_offset(seed, 1, ns, mat->h);
	s->wz = old_offset(seed, 2, ns, mat->d);
	s->tau = (double)n * ((double)s->mw * s->mh * s->md) /
	    ((double)s->sw * (double)s->sh * (double)s->sd * s->imean);
	return 0;
}

/* ---- inputs ------------------------------------------------------- */

enum { NKIND = 11 };

/* Cell values of kind k: constant, uniform, one bright cell, denormal,
 * near DBL_MAX, below 2^-900 and above 2^900 (the scaled paths), one
 * positive cell among zeros; then the refused: all zero, a negative, a
 * NaN. */
static void fill(double *v, uint64_t n, int k, uint64_t seed)
{
	for (uint64_t i = 0; i < n; i++) {
		double u = frs_rand01(seed, FRS_STREAM_TEST, i);
		switch (k) {
		case 0: v[i] = 1.0; break;
		case 1: v[i] = u; break;
		case 2: v[i] = 1e-3; break;
		case 3: v[i] = ldexp(floor(u * 64.0), -1074); break;
		case 4: v[i] = 1e308 * (0.5 + u); break;
		case 5: v[i] = 1e-280 * u; break;
		case 6: v[i] = 1e290 * (1.0 + u); break;
		default: v[i] = 0.0; break;
		}
	}
	if (k == 2 || k == 7)
		v[seed % n] = k == 2 ? 1e12 : 3.0;
	if (k == 9)
		v[0] = -1.0;
	if (k == 10)
		v[n - 1] = NAN;
}

static const uint64_t counts[] = { 0, 1, 2, 3, 7, 100, 1000, 12345,
	((uint64_t)1 << 20) + 1, ((uint64_t)1 << 24) + 1, (uint64_t)1 << 32,
	((uint64_t)1 << 40) + 3, ((uint64_t)1 << 53) + 1, (uint64_t)1 << 56,
	((uint64_t)1 << 56) + ((uint64_t)1 << 40), (uint64_t)1 << 60,
	UINT64_MAX };
#define NCOUNTS (sizeof counts / sizeof counts[0])
static const double sigmas[] = { 0.5, 1.0, 1.5, 2.0, 4.0, 8.0, 8.5, 100.0,
	1e6, 1e300 };
#define NSIGMAS (sizeof sigmas / sizeof sigmas[0])

/* A count: the table's, or a random one of random size. */
static uint64_t count_at(unsigned c, uint64_t seed)
{
	if (c < NCOUNTS)
		return counts[c];
	return frs_rand64(seed, FRS_STREAM_TEST, c) >> (c * 7 % 64);
}

/* The message of a failure, kept across the next call. */
static char *msg_copy(int rc)
{
	char *m = strdup(rc < 0 ? frs_errmsg() : "");

	assert_non_null(m);
	return m;
}

static void same_msg(char *old, int rc)
{
	if (rc < 0 && strcmp(old, frs_errmsg()) != 0)
		fail_msg("'%s' is now '%s'", old, frs_errmsg());
	free(old);
}

/* Bitwise: -0, NaN and every rounding count. */
static int same_d(double a, double b)
{
	return memcmp(&a, &b, sizeof a) == 0;
}

/* One input: the cells (a volume, d = 1 for a map), a matrix, a count,
 * a sigma and a seed. */
struct input {
	const struct frs_vol *vol;
	struct frs_matrix m;
	uint64_t n;
	double sigma;
	uint64_t seed;
};

/*
 * Every input over the shapes (d = 0: a map) and the kinds of values,
 * the counts and the sigmas (NaN and infinity past the table's), with
 * the matrices of msize in turn (d = 0: a 2-D one); one(in) returns 0
 * when both setups succeeded.  Both ways must be taken many times.
 */
static void each_input(const uint32_t (*shape)[3], size_t nshape,
    const uint32_t (*msize)[3], size_t nm, int (*one)(const struct input *))
{
	unsigned ok = 0, failed = 0;

	for (size_t sh = 0; sh < nshape; sh++)
		for (int k = 0; k < NKIND; k++) {
			struct frs_vol vol = { shape[sh][0], shape[sh][1],
			    shape[sh][2] ? shape[sh][2] : 1, NULL };
			uint64_t n = (uint64_t)vol.w * vol.h * vol.d;
			uint64_t seed = sh * 16 + (uint64_t)k + 1000 * !!shape[sh][2];
			vol.v = malloc(n * sizeof *vol.v);
			assert_non_null(vol.v);
			fill(vol.v, n, k, seed);
			for (unsigned c = 0; c < NCOUNTS + 8; c++)
				for (size_t g = 0; g < NSIGMAS + 2; g++) {
					const uint32_t *ms = msize[(c + g + sh) % nm];
					struct input in = { &vol, { .dims = ms[2] ? 3 : 2,
					    .w = ms[0], .h = ms[1],
					    .d = ms[2] ? ms[2] : 1 }, count_at(c, seed), g < NSIGMAS ?
					    sigmas[g] : g == NSIGMAS ? NAN : INFINITY,
					    seed + c };
					one(&in) == 0 ? ok++ : failed++;
				}
			free(vol.v);
		}
	assert_true(ok > 3000 && failed > 3000);
}

static int one2(const struct input *in)
{
	struct frs_imap map = { in->vol->w, in->vol->h, in->vol->v };
	struct frs_setup a, b;
	int ra = old_setup(&a, &map, &in->m, in->n, in->sigma, in->seed);
	char *msg = msg_copy(ra);

	assert_int_equal(frs_setup(&b, &map, &in->m, in->n, in->sigma,
	    in->seed), ra);
	same_msg(msg, ra);
	if (ra < 0)
		return -1;
	assert_true(a.iw == b.iw && a.ih == b.ih);
	assert_true(a.mw == b.mw && a.mh == b.mh);
	assert_true(a.sw == b.sw && a.sh == b.sh);
	assert_true(a.wx == b.wx && a.wy == b.wy);
	assert_true(a.level0 == b.level0 && a.exact.n == 0 && b.exact.n == 0);
	assert_true(a.n == b.n && same_d(a.sigma, b.sigma) && a.seed == b.seed);
	assert_true(same_d(a.mean, b.mean) && same_d(a.max, b.max));
	assert_true(same_d(a.iscale, b.iscale) && same_d(a.imean, b.imean));
	assert_true(a.ns == b.ns && same_d(a.tau, b.tau));
	assert_true(a.rule == b.rule && a.jitter == b.jitter &&
	    a.tiles == b.tiles);
	return 0;
}

static int one3(const struct input *in)
{
	struct frs3_setup a, b;
	int ra = old_setup3(&a, in->vol, &in->m, in->n, in->sigma, in->seed);
	char *msg = msg_copy(ra);

	assert_int_equal(frs3_setup(&b, in->vol, &in->m, in->n, in->sigma,
	    in->seed), ra);
	same_msg(msg, ra);
	if (ra < 0)
		return -1;
	assert_true(a.iw == b.iw && a.ih == b.ih && a.id == b.id);
	assert_true(a.mw == b.mw && a.mh == b.mh && a.md == b.md);
	assert_true(a.sw == b.sw && a.sh == b.sh && a.sd == b.sd);
	assert_true(a.wx == b.wx && a.wy == b.wy && a.wz == b.wz);
	assert_true(a.exact.n == 0 && b.exact.n == 0);
	assert_true(a.n == b.n && same_d(a.sigma, b.sigma) && a.seed == b.seed);
	assert_true(same_d(a.mean, b.mean) && same_d(a.max, b.max));
	assert_true(same_d(a.iscale, b.iscale) && same_d(a.imean, b.imean));
	assert_true(a.ns == b.ns && same_d(a.tau, b.tau));
	assert_true(a.rule == b.rule && a.jitter == b.jitter &&
	    a.tiles == b.tiles);
	return 0;
}

/* Maps from 1 x 1 to 1000 x 1; matrices square, odd, thin, and a 3-D
 * one, refused. */
static void setup2_as_before(void **state)
{
	static const uint32_t shape[][3] = { { 1, 1, 0 }, { 1, 2, 0 },
	    { 2, 1, 0 }, { 3, 7, 0 }, { 7, 3, 0 }, { 64, 64, 0 },
	    { 1, 1000, 0 }, { 1000, 1, 0 }, { 17, 33, 0 }, { 256, 3, 0 } };
	static const uint32_t msize[][3] = { { 64, 64, 0 }, { 2048, 2048, 0 },
	    { 3, 5, 0 }, { 1, 256, 0 }, { 4096, 16, 0 }, { 16, 16, 16 } };

	(void)state;
	each_input(shape, 10, msize, 6, one2);
}

/* Volumes from 1 x 1 x 1 to thin and flat ones; matrices cubic, odd,
 * flat, 2^30 elements (sides only: no values are read), and a 2-D one,
 * refused. */
static void setup3_as_before(void **state)
{
	static const uint32_t shape[][3] = { { 1, 1, 1 }, { 2, 3, 5 },
	    { 16, 16, 16 }, { 1, 1, 64 }, { 64, 1, 1 }, { 7, 5, 3 },
	    { 32, 32, 8 }, { 1, 300, 2 } };
	static const uint32_t msize[][3] = { { 16, 16, 16 }, { 64, 64, 64 },
	    { 3, 5, 7 }, { 128, 128, 1 }, { 1024, 1024, 1024 }, { 64, 64, 0 } };

	(void)state;
	each_input(shape, 8, msize, 6, one3);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(setup2_as_before),
	cmocka_unit_test(setup3_as_before))
