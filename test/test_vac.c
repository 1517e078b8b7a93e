/* The void-and-cluster generator (src/frd-gen/vac.c) against a brute-force
 * oracle written here from the definition in vac.h (every energy
 * recomputed from scratch at every step, phase 3 from the energies of the
 * 0s), and the blue-noise properties of what it makes. */
#include "testutil.h"
#include "frsutil.h"
#include "cli/fft.h"
#include "frd-gen/vac.h"

static void params(struct vac_params *pr, uint32_t w, uint32_t h,
    uint32_t d, double sigma, double tol)
{
	vac_defaults(pr);
	TU_SIZES(pr, w, h, d);
	pr->sigma = sigma;
	pr->tol = tol;
	pr->seed = 42;
}

static void run(const struct vac_params *pr, struct frs_matrix *m)
{
	if (vac_run(pr, m, NULL, NULL) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(m->v);
}

/* ---- the oracle ------------------------------------------------------ */

struct oracle {
	const struct vac_params *pr;
	size_t n;
	int64_t *k;		/* n x n: the kernel between every two cells */
	uint32_t *key;
	unsigned char *bit;
	int64_t *e;
};

static uint32_t tdist(uint32_t a, uint32_t b, uint32_t n)
{
	uint32_t d = a > b ? a - b : b - a;
	return d < n - d ? d : n - d;
}

/* S of vac.h, computed here from its definition. */
static int scale_bits(const struct vac_params *pr)
{
	double a = 1.0 + sqrt(2.0 * PI) * pr->sigma, b = 1.0;
	uint32_t size[3] = { pr->w, pr->h, pr->d };
	int e = 0;

	for (unsigned i = 0; i < pr->dims; i++)
		b *= fmin((double)size[i], a);
	while (ldexp(1.0, e) <= b)
		e++;
	return 61 - e;
}

static void oracle_init(struct oracle *o, const struct vac_params *pr)
{
	double r2max = pr->tol > 0.0 ? 2.0 * pr->sigma * pr->sigma *
	    log(1.0 / pr->tol) : INFINITY;
	int s = scale_bits(pr);

	o->pr = pr;
	o->n = (size_t)pr->w * pr->h * pr->d;
	o->k = malloc(o->n * o->n * sizeof *o->k);
	o->key = malloc(o->n * sizeof *o->key);
	o->bit = calloc(o->n, 1);
	o->e = malloc(o->n * sizeof *o->e);
	assert_true(o->k && o->key && o->bit && o->e);
	for (size_t a = 0; a < o->n; a++) {
		o->key[a] = vac_tiekey(pr, (uint32_t)a);
		for (size_t b = 0; b < o->n; b++) {
			double dx = tdist(a % pr->w, b % pr->w, pr->w);
			double dy = tdist(a / pr->w % pr->h, b / pr->w % pr->h, pr->h);
			double dz = tdist(a / pr->w / pr->h, b / pr->w / pr->h, pr->d);
			double r2 = dx * dx + dy * dy + dz * dz;
			o->k[a * o->n + b] = r2 > r2max ? 0 : llround(ldexp(exp(-r2 /
			    (2.0 * pr->sigma * pr->sigma)), s));
		}
	}
}

static void oracle_free(struct oracle *o)
{
	free(o->k);
	free(o->key);
	free(o->bit);
	free(o->e);
}

/* The filter of the cells whose bit is "of" (1: the pattern, 0: the
 * pattern of 0s), from scratch. */
static void energies(struct oracle *o, int of)
{
	for (size_t c = 0; c < o->n; c++) {
		int64_t s = 0;
		for (size_t q = 0; q < o->n; q++)
			if (o->bit[q] == of)
				s += o->k[c * o->n + q];
		o->e[c] = s;
	}
}

/* Is a before b among cells of equal energy. */
static int tie_first(const struct oracle *o, size_t a, size_t b)
{
	return o->key[a] != o->key[b] ? o->key[a] < o->key[b] : a < b;
}

/* The cell with bit "bit" of the highest (dir 1) or lowest (dir -1)
 * energy, by a full scan. */
static uint32_t extreme(const struct oracle *o, int bit, int dir)
{
	size_t best = SIZE_MAX;

	for (size_t c = 0; c < o->n; c++) {
		if (o->bit[c] != bit)
			continue;
		if (best == SIZE_MAX || (dir > 0 ? o->e[c] > o->e[best] :
		    o->e[c] < o->e[best]) || (o->e[c] == o->e[best] &&
		    tie_first(o, c, best)))
			best = c;
	}
	assert_true(best != SIZE_MAX);
	return (uint32_t)best;
}

static uint32_t cluster(struct oracle *o)
{
	energies(o, 1);
	return extreme(o, 1, 1);
}

static uint32_t largest_void(struct oracle *o)
{
	energies(o, 1);
	return extreme(o, 0, -1);
}

static void oracle_run(struct oracle *o, uint32_t *rank)
{
	size_t ones = vac_ones(o->n);
	uint32_t *perm = malloc(o->n * sizeof *perm);
	unsigned char *proto = malloc(o->n);

	assert_true(perm && proto);
	vac_initial_cells(o->pr, perm);
	for (size_t i = 0; i < ones; i++)
		o->bit[perm[i]] = 1;
	for (size_t moves = 0; moves < o->n; moves++) {
		uint32_t t = cluster(o), v;
		o->bit[t] = 0;
		v = largest_void(o);
		o->bit[v] = 1;
		if (v == t)
			break;
	}
	memcpy(proto, o->bit, o->n);
	for (size_t r = ones; r-- > 0;) {
		uint32_t t = cluster(o);
		rank[t] = (uint32_t)r;
		o->bit[t] = 0;
	}
	memcpy(o->bit, proto, o->n);
	for (size_t r = ones; r < o->n / 2; r++) {
		uint32_t v = largest_void(o);
		rank[v] = (uint32_t)r;
		o->bit[v] = 1;
	}
	/* Phase 3 as Ulichney states it: the tightest cluster of 0s. */
	for (size_t r = o->n / 2; r < o->n; r++) {
		uint32_t z;
		energies(o, 0);
		z = extreme(o, 0, 1);
		rank[z] = (uint32_t)r;
		o->bit[z] = 1;
	}
	free(perm);
	free(proto);
}

static void against_oracle(uint32_t w, uint32_t h, uint32_t d, double sigma,
    double tol)
{
	struct vac_params pr;
	struct frs_matrix m;
	struct oracle o;
	uint32_t *ref;

	params(&pr, w, h, d, sigma, tol);
	oracle_init(&o, &pr);
	ref = malloc(o.n * sizeof *ref);
	assert_non_null(ref);
	oracle_run(&o, ref);
	run(&pr, &m);
	for (size_t i = 0; i < m.n; i++)
		if (m.v[i] != ref[i]) {
			print_error("%ux%ux%u sigma=%g tol=%g: cell %zu is %u, "
			    "oracle %u\n", w, h, d, sigma, tol, i, m.v[i], ref[i]);
			fail();
		}
	free(ref);
	oracle_free(&o);
	frd_free(&m);
}

/* ---- tests ------------------------------------------------------------ */

static void permutations(void **state)
{
	static const uint32_t sz[][3] = { { 16, 16, 1 }, { 17, 9, 1 },
	    { 2, 2, 1 }, { 3, 2, 1 }, { 64, 16, 1 }, { 100, 37, 1 },
	    { 8, 8, 8 }, { 5, 7, 3 }, { 2, 2, 2 }, { 20, 12, 6 } };
	static const double tols[] = { 1e-4, 0.0, 0.5 };
	(void)state;

	for (size_t i = 0; i < sizeof sz / sizeof sz[0]; i++)
		for (size_t t = 0; t < 3; t++) {
			struct vac_params pr;
			struct frs_matrix m;
			params(&pr, sz[i][0], sz[i][1], sz[i][2], 1.5, tols[t]);
			run(&pr, &m);
			assert_int_equal(m.dims, sz[i][2] > 1 ? 3 : 2);
			tu_assert_permutation(&m);
			assert_non_null(strstr(m.params, "method=vac\n"));
			assert_non_null(strstr(m.params, "sigma=1.5\n"));
			frd_free(&m);
		}
}

/* The same seed gives the same matrix, another seed another. */
static void seeds(void **state)
{
	struct vac_params pr;
	struct frs_matrix a, b;
	(void)state;

	params(&pr, 48, 40, 1, 1.5, 1e-4);
	run(&pr, &a);
	run(&pr, &b);
	assert_memory_equal(a.v, b.v, a.n * 4);
	frd_free(&b);
	pr.seed = 43;
	run(&pr, &b);
	assert_true(memcmp(a.v, b.v, a.n * 4) != 0);
	frd_free(&a);
	frd_free(&b);
}

/* No truncation: the whole torus, incremental against recomputed. */
static void oracle_exact(void **state)
{
	(void)state;
	against_oracle(16, 16, 1, 1.5, 0.0);
	against_oracle(8, 8, 8, 1.5, 0.0);
	against_oracle(13, 6, 1, 1.5, 0.0);	/* odd and even sides */
	against_oracle(5, 4, 1, 1.5, 0.0);	/* kernel wider than the torus */
	against_oracle(7, 5, 3, 1.5, 0.0);
	against_oracle(16, 16, 1, 4.0, 0.0);	/* another S */
}

/* Truncated kernels: windows that wrap, rows of different reach. */
static void oracle_truncated(void **state)
{
	(void)state;
	against_oracle(16, 16, 1, 1.5, 1e-4);	/* radius 6.4 */
	against_oracle(24, 10, 1, 1.5, 1e-2);	/* radius 4.6 */
	against_oracle(9, 6, 5, 1.5, 1e-3);
	against_oracle(12, 12, 1, 0.7, 0.3);	/* only the nearest cells */
}

/* The initial pattern after phase 0 (the cells of ranks below ones) is
 * stable: its tightest cluster, taken out, is its largest void. */
static void stable_initial(uint32_t w, uint32_t h, uint32_t d, double tol)
{
	struct vac_params pr;
	struct frs_matrix m;
	struct oracle o;
	size_t ones = 0;
	uint32_t t;

	params(&pr, w, h, d, 1.5, tol);
	run(&pr, &m);
	oracle_init(&o, &pr);
	for (size_t c = 0; c < m.n; c++) {
		o.bit[c] = m.v[c] < vac_ones(m.n);
		ones += o.bit[c];
	}
	assert_int_equal(ones, vac_ones(m.n));
	t = cluster(&o);
	o.bit[t] = 0;
	assert_int_equal(largest_void(&o), t);
	oracle_free(&o);
	frd_free(&m);
}

static void initial_stable(void **state)
{
	(void)state;
	stable_initial(40, 40, 1, 1e-4);
	stable_initial(33, 20, 1, 0.0);
	stable_initial(10, 9, 8, 1e-4);
}

/* Radial mean of the periodogram of the pattern "value < level" of a
 * 2-D matrix with power-of-two sides, over the rings 1 .. rmax; white
 * noise of that density gives about 1. */
static double low_power(const struct frs_matrix *m, uint32_t level,
    double rmax)
{
	double *x = calloc(2 * m->n, sizeof *x), s = 0.0, mean;
	size_t cnt = 0;

	assert_non_null(x);
	mean = (double)level / (double)m->n;
	for (size_t i = 0; i < m->n; i++)
		x[2 * i] = (m->v[i] < level ? 1.0 : 0.0) - mean;
	assert_int_equal(fft2(x, m->w, m->h, -1), 0);
	for (uint32_t j = 0; j < m->h; j++)
		for (uint32_t i = 0; i < m->w; i++) {
			double fx = i <= m->w / 2 ? i : (double)m->w - i;
			double fy = j <= m->h / 2 ? j : (double)m->h - j;
			double r = sqrt(fx * fx + fy * fy);
			size_t k = (size_t)j * m->w + i;
			if (r >= 0.5 && r < rmax + 0.5) {
				s += x[2 * k] * x[2 * k] + x[2 * k + 1] * x[2 * k + 1];
				cnt++;
			}
		}
	free(x);
	return s / (double)cnt / ((double)level * (1.0 - mean));
}

/* Smallest toroidal distance between the cells of values below level. */
static double min_dist(const struct frs_matrix *m, uint32_t level)
{
	double best = INFINITY;

	for (size_t a = 0; a < m->n; a++) {
		if (m->v[a] >= level)
			continue;
		for (size_t b = a + 1; b < m->n; b++) {
			double dx, dy;
			if (m->v[b] >= level)
				continue;
			dx = tdist(a % m->w, b % m->w, m->w);
			dy = tdist(a / m->w, b / m->w, m->h);
			best = fmin(best, sqrt(dx * dx + dy * dy));
		}
	}
	return best;
}

static void blue_noise(void **state)
{
	struct vac_params pr;
	struct frs_matrix m, white;
	static const double dens[] = { 0.1, 0.5 };
	double dv, dw;
	(void)state;

	params(&pr, 64, 64, 1, 1.5, 1e-4);
	run(&pr, &m);
	tu_perm_matrix(&white, 64, 64, 7);
	for (size_t i = 0; i < 2; i++) {
		uint32_t level = (uint32_t)(dens[i] * (double)m.n);
		double pv = low_power(&m, level, 4.0);
		double pw = low_power(&white, level, 4.0);
		print_message("density %g: low-frequency power %.4f, white %.4f\n",
		    dens[i], pv, pw);
		assert_true(pw > 0.5);
		assert_true(pv < 0.05 * pw);
	}
	dv = min_dist(&m, (uint32_t)(m.n / 10));
	dw = min_dist(&white, (uint32_t)(m.n / 10));
	print_message("10%%: smallest distance %.3f, white %.3f\n", dv, dw);
	assert_true(dv >= 2.0);
	assert_true(dv >= 1.5 * dw);
	frd_free(&m);
	frd_free(&white);
}

static void helpers(void **state)
{
	struct vac_params pr;
	char buf[512];
	uint32_t perm[90];
	unsigned char seen[90] = { 0 };
	(void)state;

	assert_int_equal(vac_ones(4), 1);
	assert_int_equal(vac_ones(10), 1);
	assert_int_equal(vac_ones(11), 2);
	assert_int_equal(vac_ones(65536), 6554);
	params(&pr, 10, 9, 1, 1.5, 1e-4);
	assert_int_equal(vac_scale_bits(&pr), scale_bits(&pr));
	assert_near(vac_radius(&pr), 1.5 * sqrt(2.0 * log(1e4)), 1e-12);
	pr.tol = 0.0;
	assert_true(isinf(vac_radius(&pr)));
	vac_initial_cells(&pr, perm);
	for (size_t i = 0; i < 90; i++) {
		assert_true(perm[i] < 90 && !seen[perm[i]]);
		seen[perm[i]] = 1;
	}
	vac_describe(&pr, buf, sizeof buf);
	assert_non_null(strstr(buf, "method=vac\nk=2\nsize=10x9x1\nsigma=1.5\n"
	    "tol=0\nseed=42\n"));
}

static void bad_params(void **state)
{
	struct vac_params pr;
	struct frs_matrix m;
	(void)state;

	params(&pr, 1, 16, 1, 1.5, 1e-4);
	assert_int_equal(vac_run(&pr, &m, NULL, NULL), -1);
	assert_err_has("at least 2");
	assert_null(m.v);
	params(&pr, 16, 16, 1, 0.0, 1e-4);
	assert_int_equal(vac_check(&pr), -1);
	assert_err_has("void-and-cluster sigma");
	pr.sigma = NAN;
	assert_int_equal(vac_check(&pr), -1);
	params(&pr, 16, 16, 1, 1.5, 1.0);
	assert_int_equal(vac_check(&pr), -1);
	assert_err_has("filter tolerance");
	params(&pr, 65536, 65536, 1, 1.5, 1e-4);
	assert_int_equal(vac_check(&pr), -1);
	assert_err_has("2^32");
	params(&pr, 16, 16, 4, 1.5, 1e-4);
	pr.dims = 4;
	assert_int_equal(vac_check(&pr), -1);
	assert_err_has("dimensions");
	/* The memory ceiling is frd-gen's, checked before vac_run (its
	 * refusal: t_frd-gen.sh, "vac memory that cannot be had"). */
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(permutations),
	cmocka_unit_test(seeds),
	cmocka_unit_test(oracle_exact),
	cmocka_unit_test(oracle_truncated),
	cmocka_unit_test(initial_stable),
	cmocka_unit_test(blue_noise),
	cmocka_unit_test(helpers),
	cmocka_unit_test(bad_params))
