/* The statistics of Forced Random Sampling with the shipped 2048^2 matrix
 * and fixed seeds: moments and per-block counts against the map (FRS is
 * less dispersed than independent samples, so the bounds of independent
 * sampling are loose for it), unbiased counts in dark pixels, the hard
 * maps, and the density of uniform samples. */
#include "testutil.h"
#include "formats/frdio.h"
#include "sample/frscore.h"
#include "maps/imap.h"
#include "maps/mapload.h"
#include "moments.h"

static struct frs_matrix M;

static int load_matrix(void **state)
{
	(void)state;
	if (frd_read("data/default.frd", &M) != 0) {
		print_error("%s\n", frs_errmsg());
		return -1;
	}
	return 0;
}

static void free_preps(void);

static int free_matrix(void **state)
{
	(void)state;
	free_preps();
	frd_free(&M);
	return 0;
}

/* Sorted lists per block size, made once (sorting 2048^2 values under
 * the sanitizers is slow). */
static struct frs_prep preps[12];

static const struct frs_prep *prep_for(uint32_t block)
{
	unsigned l = 0;
	while ((1u << l) < block)
		l++;
	if (preps[l].m == NULL)
		assert_int_equal(frs_prepare(&preps[l], &M, 0, block), 0);
	return &preps[l];
}

static void sample(const struct frs_imap *map, uint64_t n, enum frs_rule rule,
    uint64_t seed, enum frs_impl a, struct frs_setup *s, struct frs_result *r)
{
	struct frs_prep p;
	assert_int_equal(frs_setup(s, map, &M, n, 8.0, seed), 0);
	s->rule = rule;
	if (a == FRS_SORTED) {
		assert_int_equal(frs_sample(s, map, prep_for(s->ns < 2048 ? s->ns :
		    2048), a, &n, 1, 0, r), 0);
		return;
	}
	assert_int_equal(frs_prepare(&p, &M, a != FRS_NAIVE, 0), 0);
	assert_int_equal(frs_sample(s, map, &p, a, &n, 1, 0, r), 0);
	frs_prep_free(&p);
}

static void free_preps(void)
{
	for (int l = 0; l < 12; l++)
		if (preps[l].m != NULL)
			frs_prep_free(&preps[l]);
}

/* Sample moments against the map's (see moments.h). */
static void moments(const char *spec)
{
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result r;
	struct moments m = { 0 };

	assert_int_equal(imap_load(spec, 128, 128, 0, &map), 0);
	sample(&map, 100000, FRS_UNBIASED, 5, FRS_SORTED, &s, &r);
	s.jitter = FRS_PLACE_RANDOM;
	for (uint64_t c = 0; c < r.nchunk; c++)
		for (uint64_t i = 0; i < r.chunk[c].n; i++) {
			double x, y;
			frs_point(&s, &r.chunk[c].e[i], &x, &y);
			mom_add(&m, x, y);
		}
	mom_check(&map, &m, spec);
	assert_true(fabs(m.n / 100000 - 1) < 0.01);
	frs_result_free(&r);
	imap_free(&map);
}

static void blob_moments(void **state)
{
	(void)state;
	moments("blob:x=0.35,y=0.6,sigma=0.12");
	moments("ramp:angle=30");
}

/* Counts per 8x8 block of pixels against n I / sum I, on real HDR maps
 * with dynamic ranges up to 1e13.  The thesis's rule inflates dark
 * pixels; the unbiased rule must not. */
static void env_counts(void **state)
{
	static const char *maps[] = { "sunset", "forest", "interior" };
	(void)state;

	for (int k = 0; k < 3; k++) {
		char path[512];
		struct frs_imap map;
		struct frs_imap_stats st;
		struct frs_setup s;
		struct frs_result r, t;
		double blocks[16][8] = { { 0 } }, worst = 0;
		const uint64_t n = 200000;
		snprintf(path, sizeof path, "data/%s.exr", maps[k]);
		frs_set_quiet(1);
		assert_int_equal(imap_load(path, 128, 64, FRS_MAP_EQUIRECT, &map), 0);
		imap_stats(&map, &st);
		sample(&map, n, FRS_UNBIASED, 11, FRS_SORTED, &s, &r);
		for (uint64_t c = 0; c < r.nchunk; c++)
			for (uint64_t i = 0; i < r.chunk[c].n; i++) {
				const struct frs_elem *e = &r.chunk[c].e[i];
				blocks[e->x / s.ns / 8][e->y / s.ns / 8] += 1;
			}
		for (int bx = 0; bx < 16; bx++)
			for (int by = 0; by < 8; by++) {
				double want = 0, z;
				for (int j = 0; j < 8; j++)
					for (int i = 0; i < 8; i++)
						want += map.v[(by * 8 + j) * 128 + bx * 8 + i];
				want *= (double)n / st.sum;
				z = fabs(blocks[bx][by] - want) / sqrt(want + 1);
				worst = z > worst ? z : worst;
			}
		sample(&map, n, FRS_THESIS, 11, FRS_SORTED, &s, &t);
		print_message("%s: %llu samples (thesis rule %llu), worst block "
		    "%.2f sd\n", maps[k], (unsigned long long)r.count,
		    (unsigned long long)t.count, worst);
		assert_true(worst < 4.0);
		assert_true(fabs((double)r.count / n - 1) < 0.01);
		frs_result_free(&r);
		frs_result_free(&t);
		imap_free(&map);
	}
}

/* One hot pixel among zeros: every sample inside it, count right. */
static void hot_pixel(void **state)
{
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result r;
	(void)state;

	assert_int_equal(imap_alloc(&map, 64, 64), 0);
	map.v[37 * 64 + 21] = 3.5;
	sample(&map, 1000, FRS_UNBIASED, 3, FRS_SORTED, &s, &r);
	for (uint64_t c = 0; c < r.nchunk; c++)
		for (uint64_t i = 0; i < r.chunk[c].n; i++) {
			assert_int_equal(r.chunk[c].e[i].x / s.ns, 21);
			assert_int_equal(r.chunk[c].e[i].y / s.ns, 37);
		}
	print_message("hot pixel: %llu of 1000\n", (unsigned long long)r.count);
	assert_true(r.count >= 970 && r.count <= 1030);
	frs_result_free(&r);
	imap_free(&map);
}

/* 1e-9 to 1e9 in one map: per-quadrant counts proportional. */
static void dynamic_range(void **state)
{
	static const double q[4] = { 1e-9, 1e-3, 1.0, 1e9 };
	struct frs_imap map;
	struct frs_setup s;
	struct frs_result r;
	double cnt[4] = { 0 }, sum = 0;
	(void)state;

	assert_int_equal(imap_alloc(&map, 64, 64), 0);
	for (uint32_t j = 0; j < 64; j++)
		for (uint32_t i = 0; i < 64; i++)
			sum += map.v[j * 64 + i] = q[(j / 32) * 2 + i / 32];
	sample(&map, 100000, FRS_UNBIASED, 9, FRS_SORTED, &s, &r);
	for (uint64_t c = 0; c < r.nchunk; c++)
		for (uint64_t i = 0; i < r.chunk[c].n; i++) {
			const struct frs_elem *e = &r.chunk[c].e[i];
			cnt[(e->y / s.ns / 32) * 2 + e->x / s.ns / 32] += 1;
		}
	for (int k = 0; k < 4; k++) {
		double want = 100000.0 * q[k] * 1024 / sum;
		print_message("quadrant %g: %.0f, expected %.6g\n", q[k], cnt[k], want);
		assert_true(fabs(cnt[k] - want) <= 4 * sqrt(want) + 2);
	}
	frs_result_free(&r);
	imap_free(&map);
}

/* Maps of one row or one column, and n = 1.  A one-pixel-wide window
 * reads one narrow strip of the matrix again and again, so one seed's
 * count strays by several per cent; the mean over 64 seeds (window
 * offsets) must stay within 2 per cent. */
static void thin_maps(void **state)
{
	static const uint32_t sz[2][2] = { { 1, 4096 }, { 4096, 1 } };
	double mean = 0;
	(void)state;

	for (int k = 0; k < 2; k++) {
		struct frs_imap map;
		double avg = 0;
		assert_int_equal(imap_load("ramp:from=1,to=3,angle=45", sz[k][0],
		    sz[k][1], 0, &map), 0);
		for (uint64_t seed = 1; seed <= 64; seed++) {
			struct frs_setup s;
			struct frs_result r, nv;
			sample(&map, 2000, FRS_UNBIASED, seed, FRS_SORTED, &s, &r);
			if (seed == 1) {
				sample(&map, 2000, FRS_UNBIASED, seed, FRS_NAIVE, &s, &nv);
				assert_true(r.count == nv.count);
				frs_result_free(&nv);
			}
			avg += (double)r.count / 64;
			frs_result_free(&r);
		}
		print_message("%ux%u: %.1f samples on average\n", sz[k][0], sz[k][1],
		    avg);
		assert_true(fabs(avg / 2000 - 1) < 0.02);
		imap_free(&map);
	}
	for (uint64_t seed = 0; seed < 200; seed++) {
		struct frs_imap map;
		struct frs_setup s;
		struct frs_result r;
		assert_int_equal(imap_load("blob", 32, 32, 0, &map), 0);
		sample(&map, 1, FRS_UNBIASED, seed, FRS_SORTED, &s, &r);
		mean += (double)r.count / 200;
		frs_result_free(&r);
		imap_free(&map);
	}
	print_message("n = 1: %.3f samples on average\n", mean);
	assert_true(fabs(mean - 1) < 0.2);
}

/* Uniform sampling, sigma 8, n 1024: density rho = d_min / sqrt(2 /
 * (sqrt(3) n)) with plain distance, averaged over 10 sets as in thesis
 * Table 6.1 (FRS: 0.65), at least 0.6.  (One set's rho is the distance of
 * a single closest pair and strays: 0.50 to 0.63 here, and 0.34 to 0.66
 * for the thesis authors' own matrix.) */
static void uniform_density(void **state)
{
	double mean = 0;
	(void)state;

	for (uint64_t seed = 1; seed <= 10; seed++) {
		struct frs_imap map;
		struct frs_setup s;
		struct frs_result r;
		double *p, best = 1e9, rho;
		uint64_t k = 0;
		assert_int_equal(imap_load("const", 128, 128, 0, &map), 0);
		sample(&map, 1024, FRS_UNBIASED, seed, FRS_SORTED, &s, &r);
		p = malloc(2 * r.count * sizeof *p);
		for (uint64_t c = 0; c < r.nchunk; c++)
			for (uint64_t i = 0; i < r.chunk[c].n; i++, k++)
				frs_point(&s, &r.chunk[c].e[i], &p[2 * k], &p[2 * k + 1]);
		for (uint64_t i = 0; i < k; i++)
			for (uint64_t j = i + 1; j < k; j++) {
				double dx = p[2 * i] - p[2 * j];
				double dy = p[2 * i + 1] - p[2 * j + 1];
				best = fmin(best, dx * dx + dy * dy);
			}
		rho = sqrt(best) / sqrt(2 / (sqrt(3.0) * 1024));
		print_message("uniform, seed %llu: %llu samples, rho %.3f\n",
		    (unsigned long long)seed, (unsigned long long)k, rho);
		mean += rho / 10;
		free(p);
		frs_result_free(&r);
		imap_free(&map);
	}
	print_message("uniform: mean rho %.3f\n", mean);
	assert_true(mean >= 0.6);
}

TU_MAIN(load_matrix, free_matrix,
	cmocka_unit_test(blob_moments),
	cmocka_unit_test(env_counts),
	cmocka_unit_test(hot_pixel),
	cmocka_unit_test(dynamic_range),
	cmocka_unit_test(thin_maps),
	cmocka_unit_test(uniform_density))
