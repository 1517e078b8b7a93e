/* The FRD generator against a brute-force reference written here from the
 * definition (Listing 3.1 with the documented rank and tie rules), and
 * the quality properties of what it makes. */
#include "testutil.h"
#include "frsutil.h"
#include "cli/fft.h"
#include "frd-gen/frdgen.h"
#include "frd-gen/frdq.h"
#include "base/rng.h"

static void params(struct frdgen_params *pr, uint32_t w, uint32_t h,
    uint32_t d, double p, double tol)
{
	tu_frdgen_params(pr, w, h, d, p, tol, 42);
}

static void permutations(void **state)
{
	static const uint32_t sz[][4] = { { 16, 16, 1, 50 }, { 17, 9, 1, 50 },
	    { 2, 2, 1, 100 }, { 32, 32, 1, 10 }, { 8, 8, 8, 50 },
	    { 5, 7, 3, 100 }, { 64, 16, 1, 100 } };
	(void)state;

	for (size_t i = 0; i < sizeof sz / sizeof sz[0]; i++) {
		struct frdgen_params pr;
		struct frs_matrix m;
		params(&pr, sz[i][0], sz[i][1], sz[i][2], sz[i][3] / 100.0, 1e-4);
		assert_int_equal(frdgen_run(&pr, &m, NULL), 0);
		tu_assert_permutation(&m);
		frd_free(&m);
	}
}

#include "ref/ref_frd.h"

static void against_reference_pr(const struct frdgen_params *pr)
{
	struct frs_matrix m;
	uint32_t *ref = malloc((size_t)pr->w * pr->h * pr->d * sizeof *ref);
	char desc[512];

	reference(pr, ref);
	assert_int_equal(frdgen_run(pr, &m, NULL), 0);
	for (size_t i = 0; i < m.n; i++)
		if (m.v[i] != ref[i]) {
			frdgen_describe(pr, desc, sizeof desc);
			print_error("%s: cell %zu is %u, reference %u\n", desc, i,
			    m.v[i], ref[i]);
			fail();
		}
	free(ref);
	frd_free(&m);
}

static void against_reference(uint32_t w, uint32_t h, uint32_t d, double p,
    double tol, double reach)
{
	struct frdgen_params pr;

	params(&pr, w, h, d, p, tol);
	pr.reach = reach;
	against_reference_pr(&pr);
}

/* --field int32: the authors' integer table and tie rule, byte for byte
 * with the same random choices. */
static void int32_field(void **state)
{
	static const uint32_t sz[][3] = { { 16, 16, 1 }, { 32, 32, 1 },
	    { 24, 16, 1 }, { 8, 8, 6 } };
	struct frdgen_params pr;
	(void)state;

	for (size_t i = 0; i < sizeof sz / sizeof sz[0]; i++) {
		params(&pr, sz[i][0], sz[i][1], sz[i][2], 0.5, 0.0);
		pr.field = FRDGEN_FIELD_INT32;
		against_reference_pr(&pr);
	}
	/* The table: 1 / f(S/2) at S = 32, INT_MAX / 20 from S = 342 on,
	 * where it reaches 0 at r = ln(scale)^2 / 2 = 171 cells. */
	params(&pr, 32, 32, 1, 0.5, 0.0);
	pr.field = FRDGEN_FIELD_INT32;
	assert_double_equal(frdgen_int_scale(&pr), exp(4.0 * sqrt(2.0)) ,
	    1e-9 * exp(4.0 * sqrt(2.0)));
	assert_true(frdgen_force(&pr, 0.0) == floor(exp(4.0 * sqrt(2.0))));
	params(&pr, 512, 512, 1, 0.5, 0.0);
	pr.field = FRDGEN_FIELD_INT32;
	assert_true(frdgen_int_scale(&pr) == 107374182.0);
	assert_true(frdgen_force(&pr, 170.0) >= 1.0);
	assert_true(frdgen_force(&pr, 172.0) == 0.0);
	assert_double_equal(frdgen_radius(&pr), 171.0, 0.5);
}

/* The hard cut-off (--cutoff hard) and no cap, as before the taper. */
static void hard_cutoff(void **state)
{
	struct frdgen_params pr;
	(void)state;

	params(&pr, 32, 32, 1, 0.5, 1e-2);
	pr.taper = 0;
	against_reference_pr(&pr);
	params(&pr, 40, 24, 1, 1.0, 1e-3);
	pr.taper = 0;
	pr.cap = 0.0;
	pr.reach = 0.7;
	pr.force = FRDGEN_FORCE_EXP;
	pr.s = pr.q = 0.5;
	against_reference_pr(&pr);
	/* The thesis's force under the taper. */
	params(&pr, 32, 24, 1, 0.5, 1e-3);
	pr.force = FRDGEN_FORCE_EXP;
	pr.s = 0.5;
	pr.q = 0.7;
	against_reference_pr(&pr);
}

/* Cells no force has reached yet (tolerance without reach): drawn
 * uniformly in the documented order. */
static void zero_field(void **state)
{
	(void)state;
	against_reference(32, 32, 1, 0.5, 0.1, 0.0);
	against_reference(40, 24, 1, 1.0, 1e-2, 0.7);
	against_reference(9, 6, 5, 0.5, 0.2, 0.0);
}

/* Exact, p = 1: the global minimum every time (Listing 3.1 with p = 1). */
static void exact_global_minimum(void **state)
{
	(void)state;
	against_reference(16, 16, 1, 1.0, 0.0, 0.0);
	against_reference(32, 32, 1, 1.0, 0.0, 0.0);
}

/* The K-th smallest by rank, the windowed adds that wrap around the
 * torus, and the growing radius. */
static void windows_and_ranks(void **state)
{
	(void)state;
	against_reference(16, 16, 1, 0.5, 0.0, 0.0);
	against_reference(32, 24, 1, 0.5, 1e-2, 0.0);	/* radius 10.6 */
	against_reference(40, 40, 1, 0.3, 0.1, 3.0);	/* growing radius */
	against_reference(9, 6, 5, 0.5, 0.05, 0.0);	/* 3-D windows */
}

/* The rank follows the truncated geometric law. */
static void rank_law(void **state)
{
	struct frdgen_params pr;
	unsigned cnt[4] = { 0 };
	(void)state;

	params(&pr, 8, 8, 1, 0.5, 0.0);
	for (uint64_t s = 0; s < 40000; s++) {
		uint64_t k = frdgen_rank(&pr, s, 1000000);
		if (k <= 3)
			cnt[k]++;
		assert_true(frdgen_rank(&pr, s, 3) <= 3);
		assert_true(frdgen_rank(&pr, s, 1) == 1);
	}
	/* 20000, 10000, 5000 expected; 5 sigma bounds */
	assert_true(cnt[1] > 19500 && cnt[1] < 20500);
	assert_true(cnt[2] > 9600 && cnt[2] < 10400);
	assert_true(cnt[3] > 4750 && cnt[3] < 5250);
	pr.p = 1.0;
	assert_true(frdgen_rank(&pr, 7, 100) == 1);
}

/* The first c values of a 256^2 matrix are spread evenly: smallest
 * toroidal distance over the hexagonal spacing, computed here. */
static void spread(void **state)
{
	struct frdgen_params pr;
	struct frs_matrix m;
	static const uint32_t cs[] = { 16, 64, 256, 1024 };
	uint32_t pos[1024][2];
	(void)state;

	params(&pr, 256, 256, 1, 0.5, 1e-4);
	assert_int_equal(frdgen_run(&pr, &m, NULL), 0);
	tu_assert_permutation(&m);
	for (size_t i = 0; i < m.n; i++)
		if (m.v[i] < 1024) {
			pos[m.v[i]][0] = (uint32_t)(i % 256);
			pos[m.v[i]][1] = (uint32_t)(i / 256);
		}
	for (size_t k = 0; k < 4; k++) {
		double best = 1e30, rho;
		for (uint32_t a = 0; a < cs[k]; a++)
			for (uint32_t b = a + 1; b < cs[k]; b++) {
				double dx = tdist(pos[a][0], pos[b][0], 256);
				double dy = tdist(pos[a][1], pos[b][1], 256);
				best = fmin(best, dx * dx + dy * dy);
			}
		rho = sqrt(best) / (256.0 * sqrt(2.0 / (sqrt(3.0) * cs[k])));
		print_message("rho_%u = %.3f\n", cs[k], rho);
		assert_true(rho >= 0.55);
		assert_double_equal(frdq_spread(&m, cs[k]), rho, 1e-12);
	}
	/* Blue noise at 97.5 %: low frequencies far below the plateau, and
	 * no lattice: the spectral peak stays low (a crystallised matrix,
	 * --reach 3, has 7). */
	{
		double ratio, peak;
		assert_int_equal(frdq_spectrum(&m, 0.0, 0.025, &ratio, &peak), 0);
		print_message("peak first 2.5%% = %.3f\n", peak);
		assert_true(peak < 3.0);
		assert_int_equal(frdq_lowpass(&m, 0.0, 0.025, &ratio), 0);
		print_message("lowpass first 2.5%% = %.3f\n", ratio);
		assert_true(ratio < 0.2);
		assert_int_equal(frdq_lowpass(&m, 0.975, 1.0, &ratio), 0);
		print_message("lowpass last 2.5%% = %.3f\n", ratio);
		assert_true(ratio < 0.2);
	}
	frd_free(&m);
}

/* The spectral measure itself: a regular grid has no power below its
 * frequency (analytic), a random permutation is white (about 1). */
static void lowpass_measure(void **state)
{
	struct frs_matrix m;
	struct frs_rng r;
	double ratio;
	(void)state;

	assert_int_equal(frd_alloc(&m, 2, 256, 256, 1, ""), 0);
	/* Every 8th cell in x and y gets the smallest values: 1024 dots. */
	for (uint32_t i = 0, lo = 0, hi = 1024; i < m.n; i++)
		m.v[i] = (i % 8 == 0 && i / 256 % 8 == 0) ? lo++ : hi++;
	assert_int_equal(frdq_lowpass(&m, 0.0, 1024.0 / 65536.0, &ratio), 0);
	assert_true(ratio < 1e-20);
	frs_rng_init(&r, 5, FRS_STREAM_TEST);
	for (uint32_t i = 0; i < m.n; i++)
		m.v[i] = i;
	for (uint32_t i = (uint32_t)m.n - 1; i > 0; i--) {
		uint32_t j = (uint32_t)frs_rng_below(&r, i + 1), t = m.v[i];
		m.v[i] = m.v[j];
		m.v[j] = t;
	}
	assert_int_equal(frdq_lowpass(&m, 0.0, 0.025, &ratio), 0);
	assert_true(ratio > 0.8 && ratio < 1.25);
	frd_free(&m);
}

/* The level figures of frd-gen --quality (frdq_level), the bounds of
 * frd-gen(1): at most 30 for the periodogram maximum, at most 95 % of the
 * strata singly occupied. */
static int levels_pass(const struct frs_matrix *m, uint64_t cmax)
{
	for (uint64_t c = 64; c <= cmax; c *= 2) {
		struct frdq_level q;
		assert_int_equal(frdq_level(m, 0, c, &q), 0);
		assert_true(q.spectral);
		if (q.pmax > 30.0 || q.strata > 0.95) {
			print_message("c = %llu: pmax %.1f, strata %.3f\n",
			    (unsigned long long)c, q.pmax, q.strata);
			return 0;
		}
	}
	return 1;
}

/* The ordered-dither (Bayer) matrix: every prefix of 4^k values is a
 * square lattice. */
static void bayer(struct frs_matrix *m, uint32_t s)
{
	assert_int_equal(frd_alloc(m, 2, s, s, 1, ""), 0);
	for (uint32_t y = 0; y < s; y++)
		for (uint32_t x = 0; x < s; x++) {
			uint32_t v = 0;
			/* B_2n = (4 B, 4 B + 2; 4 B + 3, 4 B + 1): the finest
			 * bit of x and y gives the leading base-4 digit. */
			for (uint32_t b = 1; b < s; b *= 2) {
				uint32_t bx = (x & b) != 0, by = (y & b) != 0;
				v = 4 * v + (bx ^ by ? 2 + by : by);
			}
			m->v[y * s + x] = v;
		}
}

/* A random matrix whose first g^2 values lie one in each cell of a g x g
 * grid, cells in random order, at random places: a jittered grid. */
static void jittered(struct frs_matrix *m, uint32_t s, uint32_t g)
{
	struct frs_rng r;
	uint32_t cs = s / g, next = g * g, *cell = malloc(g * g * sizeof *cell);

	assert_int_equal(frd_alloc(m, 2, s, s, 1, ""), 0);
	frs_rng_init(&r, 9, FRS_STREAM_TEST);
	for (uint32_t i = 0; i < m->n; i++)
		m->v[i] = UINT32_MAX;
	for (uint32_t c = 0; c < g * g; c++)
		cell[c] = c;
	for (uint32_t c = g * g - 1; c > 0; c--) {
		uint32_t j = (uint32_t)frs_rng_below(&r, c + 1), t = cell[c];
		cell[c] = cell[j];
		cell[j] = t;
	}
	for (uint32_t c = 0; c < g * g; c++) {
		uint32_t x = cell[c] % g * cs + (uint32_t)frs_rng_below(&r, cs);
		uint32_t y = cell[c] / g * cs + (uint32_t)frs_rng_below(&r, cs);
		m->v[y * s + x] = c;
	}
	free(cell);
	for (uint32_t i = 0; i < m->n; i++)
		if (m->v[i] == UINT32_MAX)
			m->v[i] = next++;
	/* Shuffle the values above g^2 so that the rest is white noise. */
	for (uint32_t i = (uint32_t)m->n - 1; i > 0; i--) {
		uint32_t j = (uint32_t)frs_rng_below(&r, i + 1), t;
		if (m->v[i] < g * g || m->v[j] < g * g)
			continue;
		t = m->v[i];
		m->v[i] = m->v[j];
		m->v[j] = t;
	}
}

/* The default matrices pass the level bounds at every prefix; a planted
 * lattice and a planted jittered grid fail them. */
static void level_bounds(void **state)
{
	struct frdgen_params pr;
	struct frs_matrix m;
	(void)state;

	for (uint64_t seed = 1; seed <= 2; seed++) {
		frdgen_defaults(&pr);
		pr.w = pr.h = seed == 1 ? 128 : 256;
		pr.d = 1;
		pr.seed = seed;
		assert_int_equal(frdgen_run(&pr, &m, NULL), 0);
		assert_true(levels_pass(&m, m.n / 4));
		frd_free(&m);
	}
	bayer(&m, 128);
	tu_assert_permutation(&m);
	assert_false(levels_pass(&m, m.n / 4));
	frd_free(&m);
	jittered(&m, 128, 32);
	tu_assert_permutation(&m);
	assert_false(levels_pass(&m, m.n / 4));
	frd_free(&m);
}

/* The FFT against a direct DFT. */
static void fft_vs_dft(void **state)
{
	double x[2 * 16], y[2 * 16];
	(void)state;
	for (int i = 0; i < 16; i++) {
		x[2 * i] = sin(i * 1.3) + i % 3;
		x[2 * i + 1] = cos(i * 0.7);
	}
	memcpy(y, x, sizeof x);
	assert_int_equal(fft1(y, 16, 1, -1), 0);
	for (int k = 0; k < 16; k++) {
		double re = 0, im = 0;
		for (int j = 0; j < 16; j++) {
			double a = -2 * PI * j * k / 16;
			re += x[2 * j] * cos(a) - x[2 * j + 1] * sin(a);
			im += x[2 * j] * sin(a) + x[2 * j + 1] * cos(a);
		}
		assert_double_equal(y[2 * k], re, 1e-12);
		assert_double_equal(y[2 * k + 1], im, 1e-12);
	}
	assert_int_equal(fft1(y, 12, 1, -1), -1);
}

/* An interrupted run resumed from its checkpoint gives the same bytes. */
static void checkpoint_resume(void **state)
{
	struct frdgen_params pr;
	struct frs_matrix a, b;
	const char *ck = tu_path("ck");
	(void)state;

	params(&pr, 128, 128, 1, 0.5, 1e-3);
	assert_int_equal(frdgen_run(&pr, &a, NULL), 0);
	pr.checkpoint = ck;
	pr.checkpoint_every = 0.0;	/* save every 4096 steps */
	assert_int_equal(frdgen_run(&pr, &b, NULL), 0);
	frd_free(&b);
	assert_int_equal(access(ck, F_OK), 0);	/* left at step 12289 */
	assert_int_equal(frdgen_run(&pr, &b, NULL), 0);	/* resumes */
	assert_memory_equal(a.v, b.v, a.n * 4);
	frd_free(&b);
	/* Another parameter set refuses the checkpoint. */
	pr.seed = 7;
	assert_int_equal(frdgen_run(&pr, &b, NULL), -1);
	assert_err_has(ck, "another run");
	frd_free(&a);
}

static void bad_params(void **state)
{
	struct frdgen_params pr;
	struct frs_matrix m;
	(void)state;

	params(&pr, 1, 16, 1, 0.5, 1e-4);
	assert_int_equal(frdgen_run(&pr, &m, NULL), -1);
	assert_err_has("at least 2");
	params(&pr, 16, 16, 1, 0.0, 1e-4);
	assert_int_equal(frdgen_check(&pr), -1);
	assert_err_has("share p");
	pr.p = NAN;
	assert_int_equal(frdgen_check(&pr), -1);
	params(&pr, 65536, 65536, 1, 0.5, 1e-4);
	assert_int_equal(frdgen_check(&pr), -1);
	assert_err_has("2^32");
	params(&pr, 16, 16, 1, 0.5, 1.5);
	assert_int_equal(frdgen_check(&pr), -1);
	assert_err_has("force tolerance");
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(permutations),
	cmocka_unit_test(exact_global_minimum),
	cmocka_unit_test(windows_and_ranks),
	cmocka_unit_test(zero_field),
	cmocka_unit_test(int32_field),
	cmocka_unit_test(hard_cutoff),
	cmocka_unit_test(rank_law),
	cmocka_unit_test(spread),
	cmocka_unit_test(lowpass_measure),
	cmocka_unit_test(fft_vs_dft),
	cmocka_unit_test(level_bounds),
	cmocka_unit_test(checkpoint_resume),
	cmocka_unit_test(bad_params))
