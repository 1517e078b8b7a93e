/* The quality figures of a threshold matrix (frd-gen/frdq.h) against brute
 * force on tiny matrices: the spread by all pairs of cells, the strata by
 * counting, the spectral figures by the DFT written out, and closed forms
 * for lattices. */
#include "testutil.h"
#include "frsutil.h"
#include "frd-gen/frdq.h"


static void matrix(struct frs_matrix *m, unsigned dims, uint32_t w,
    uint32_t h, uint32_t d, uint64_t seed)
{
	assert_int_equal(frd_alloc(m, dims, w, h, d, ""), 0);
	tu_perm_fill(m, seed);
}

/* Cell i's coordinate on axis a. */
static uint32_t coord(const struct frs_matrix *m, size_t i, int a)
{
	return a == 0 ? (uint32_t)(i % m->w) : a == 1 ?
	    (uint32_t)(i / m->w % m->h) : (uint32_t)(i / m->w / m->h);
}

/* The smallest toroidal distance between two cells of value below c,
 * over all pairs of cells. */
static double min_torus_dist(const struct frs_matrix *m, uint32_t c)
{
	uint32_t side[3] = { m->w, m->h, m->d };
	double best = INFINITY;

	for (size_t i = 0; i < m->n; i++)
		for (size_t j = 0; j < m->n; j++) {
			double s = 0.0;
			if (i == j || m->v[i] >= c || m->v[j] >= c)
				continue;
			for (int a = 0; a < 3; a++) {
				long d = labs((long)coord(m, i, a) - (long)coord(m, j, a));
				d = d < (long)side[a] - d ? d : (long)side[a] - d;
				s += (double)(d * d);
			}
			best = fmin(best, sqrt(s));
		}
	return best;
}

/* spread = the smallest distance over the hexagonal (2-D) or fcc (3-D)
 * spacing of c points in the matrix's area or volume. */
static void spread_brute_force(void **state)
{
	(void)state;
	for (uint64_t seed = 1; seed <= 6; seed++) {
		struct frs_matrix m;
		int three = seed > 3;
		double vol;
		if (three)
			matrix(&m, 3, 4, 6, 2, seed);
		else
			matrix(&m, 2, 8, 6, 1, seed);
		vol = (double)m.n;
		for (uint32_t c = 2; c <= m.n; c += 5) {
			double ideal = three ? cbrt(sqrt(2.0) * vol / c) :
			    sqrt(2.0 * vol / (sqrt(3.0) * c));
			assert_near(frdq_spread(&m, c), min_torus_dist(&m, c) / ideal,
			    1e-12);
		}
		assert_true(isnan(frdq_spread(&m, 1)));
		assert_true(isnan(frdq_spread(&m, (uint32_t)m.n + 1)));
		frd_free(&m);
	}
	/* Opposite corners are neighbours on the torus: sqrt 2 apart. */
	{
		struct frs_matrix m;
		assert_int_equal(frd_alloc(&m, 2, 8, 6, 1, ""), 0);
		for (size_t i = 0; i < m.n; i++)
			m.v[i] = (uint32_t)(i == 0 ? 0 : i == m.n - 1 ? 1 : i + 1);
		assert_near(frdq_spread(&m, 2), sqrt(2.0) / sqrt(2.0 * 48.0 /
		    (sqrt(3.0) * 2.0)), 1e-12);
		frd_free(&m);
	}
}

/* The square lattice of spacing 4 in 16 x 16 as the first 16 values:
 * spread 4 / sqrt(2 * 256 / (sqrt 3 * 16)), strata 1, and its
 * periodogram c at the lattice frequencies. */
static void lattice(void **state)
{
	struct frs_matrix m;
	struct frdq_level q;
	uint32_t next = 16, k = 0;

	(void)state;
	/* (x, y) with x % 4 == 0 and y % 4 == 0 first, by rows */
	assert_int_equal(frd_alloc(&m, 2, 16, 16, 1, ""), 0);
	for (size_t i = 0; i < m.n; i++)
		m.v[i] = (i % 16) % 4 == 0 && (i / 16) % 4 == 0 ? k++ : next++;
	tu_assert_permutation(&m);
	assert_near(frdq_spread(&m, 16), 4.0 / sqrt(512.0 / (sqrt(3.0) * 16)),
	    1e-12);
	assert_near(frdq_strata(&m, 0, 16), 1.0, 0);
	assert_int_equal(frdq_level(&m, 0, 16, &q), 0);
	assert_true(q.dots == 16 && q.spectral);
	assert_near(q.strata, 1.0, 0);
	/* all of c at the lattice frequencies, fp = 4 and beyond */
	assert_near(q.pmax, 16.0, 1e-9);
	assert_true(q.pmax_f >= 1.0 - 1e-12);
	frd_free(&m);
}

/* The strata grid of c = 2^k dots in a square matrix: 2^ceil(k/2)
 * columns (x first) and 2^floor(k/2) rows; the share of its cells with
 * exactly one dot, counted. */
static double strata_count(const struct frs_matrix *m, uint64_t lo,
    uint64_t hi, unsigned k)
{
	uint64_t gx = (uint64_t)1 << ((k + 1) / 2), gy = (uint64_t)1 << (k / 2);
	uint64_t one = 0;

	for (uint64_t cy = 0; cy < gy; cy++)
		for (uint64_t cx = 0; cx < gx; cx++) {
			unsigned in = 0;
			for (size_t i = 0; i < m->n; i++) {
				uint64_t x = i % m->w, y = i / m->w;
				in += m->v[i] >= lo && m->v[i] < hi &&
				    x * gx / m->w == cx && y * gy / m->h == cy;
			}
			one += in == 1;
		}
	return (double)one / (double)(gx * gy);
}

static void strata_brute_force(void **state)
{
	struct frs_matrix m;

	(void)state;
	matrix(&m, 2, 16, 16, 1, 9);
	for (unsigned k = 0; k <= 7; k++)
		for (uint64_t lo = 0; lo < 200; lo += 37) {
			uint64_t hi = lo + ((uint64_t)1 << k);
			assert_near(frdq_strata(&m, lo, hi), strata_count(&m, lo, hi, k),
			    0);
		}
	assert_true(isnan(frdq_strata(&m, 5, 5)));
	frd_free(&m);
}

/* The periodogram of the dots in [lo, hi) at integer frequency (u, v),
 * by the definition. */
static double power(const struct frs_matrix *m, uint64_t lo, uint64_t hi,
    long u, long v)
{
	double re = 0.0, im = 0.0, dots = 0.0;

	for (size_t i = 0; i < m->n; i++)
		if (m->v[i] >= lo && m->v[i] < hi) {
			double a = -2.0 * PI * ((double)(u * (long)(i % m->w)) /
			    m->w + (double)(v * (long)(i / m->w)) / m->h);
			re += cos(a);
			im += sin(a);
			dots++;
		}
	return (re * re + im * im) / dots;
}

/* frdq_lowpass's ratio: the mean power below fp / 2 over the mean in
 * [1.5 fp, 2.5 fp), fp = sqrt(dots), frequencies scaled to an isotropic
 * plane; and frdq_level's pmax over every frequency but 0. */
static void spectrum_brute_force(void **state)
{
	static const uint32_t sz[][2] = { { 16, 16 }, { 32, 8 }, { 8, 16 } };

	(void)state;
	for (int s = 0; s < 3; s++) {
		uint32_t w = sz[s][0], h = sz[s][1];
		struct frs_matrix m;
		struct frdq_level q;
		double ratio, peak, lo = 0, hi = 0, pmax = 0;
		size_t nlo = 0, nhi = 0;
		uint64_t dots;

		matrix(&m, 2, w, h, 1, 20 + (uint64_t)s);
		dots = m.n / 16;
		for (long y = 0; y < (long)h; y++)
			for (long x = 0; x < (long)w; x++) {
				long fx = x <= (long)w / 2 ? x : x - (long)w;
				long fy = y <= (long)h / 2 ? y : y - (long)h;
				double f = sqrt((double)(fx * fx) * h / w +
				    (double)(fy * fy) * w / h);
				double p = power(&m, 0, dots, x, y), fp = sqrt((double)dots);
				if (f > 0.0 && f < 0.5 * fp)
					lo += p, nlo++;
				else if (f >= 1.5 * fp && f < 2.5 * fp)
					hi += p, nhi++;
				if (f > 0.0)
					pmax = fmax(pmax, p);
			}
		assert_int_equal(frdq_lowpass(&m, 0.0, 1.0 / 16, &ratio), 0);
		assert_near(ratio, (lo / (double)nlo) / (hi / (double)nhi), 1e-9);
		assert_int_equal(frdq_spectrum(&m, 0.0, 1.0 / 16, &ratio, &peak), 0);
		assert_near(ratio, (lo / (double)nlo) / (hi / (double)nhi), 1e-9);
		assert_true(peak > 0.0);
		assert_int_equal(frdq_level(&m, 0, dots, &q), 0);
		assert_true(q.spectral && q.dots == dots);
		assert_near(q.pmax, pmax, 1e-9);
		frd_free(&m);
	}
}

/* What cannot be measured: non-power-of-two sides (the spectrum refused,
 * the level's strata only), no dots. */
static void refusals(void **state)
{
	struct frs_matrix m;
	struct frdq_level q;
	double ratio;

	(void)state;
	matrix(&m, 2, 12, 8, 1, 3);
	assert_int_equal(frdq_lowpass(&m, 0.0, 0.25, &ratio), -1);
	assert_err_has("power-of-two");
	assert_int_equal(frdq_level(&m, 0, 24, &q), 0);
	assert_false(q.spectral);
	assert_near(q.strata, frdq_strata(&m, 0, 24), 0);
	assert_int_equal(frdq_level(&m, 96, 200, &q), -1);
	assert_err_has("no values", "96");
	frd_free(&m);
	matrix(&m, 3, 4, 4, 4, 3);
	assert_int_equal(frdq_lowpass(&m, 0.0, 0.25, &ratio), -1);
	assert_int_equal(frdq_level(&m, 0, 8, &q), 0);
	assert_true(q.spectral && q.pmax > 0.0);
	frd_free(&m);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(spread_brute_force),
	cmocka_unit_test(lattice),
	cmocka_unit_test(strata_brute_force),
	cmocka_unit_test(spectrum_brute_force),
	cmocka_unit_test(refusals))
