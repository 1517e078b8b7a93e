/*
 * Reference point sets: random, regular, jittered, Halton, Hammersley,
 * Owen-scrambled Sobol' and dart throwing, in 2-D and 3-D.  See
 * refsamp.h.
 */
#define _POSIX_C_SOURCE 200809L
#include "cli/refsamp.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/err.h"
#include "maps/imap.h"
#include "base/mem.h"
#include "base/num.h"
#include "base/rng.h"

static const char *const names[] = { "random", "regular", "jittered",
    "halton", "hammersley", "sobol", "dart", "relaxed-dart" };

int refsamp_parse(const char *name, enum refsamp_kind *k)
{
	for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
		if (strcmp(name, names[i]) == 0) {
			*k = (enum refsamp_kind)i;
			return 0;
		}
	return frs_fail("unknown kind '%s' (random, regular, jittered, halton, "
	    "hammersley, sobol, dart or relaxed-dart)", name);
}

const char *refsamp_name(enum refsamp_kind k)
{
	return (unsigned)k < sizeof names / sizeof names[0] ? names[k] : "?";
}

uint64_t refsamp_grid_side(uint64_t n)
{
	uint64_t k = (uint64_t)llround(sqrt((double)n));

	/* Exact rounding of sqrt(n) for large n. */
	while (k > 1 && (2 * k - 1) * (2 * k - 1) > 4 * n)
		k--;
	while ((2 * k + 1) * (2 * k + 1) <= 4 * n)
		k++;
	return k < 1 ? 1 : k;
}

uint64_t refsamp_count(enum refsamp_kind k, uint64_t n)
{
	if (k == REFSAMP_REGULAR || k == REFSAMP_JITTERED) {
		uint64_t s = refsamp_grid_side(n);
		return s * s;
	}
	return n;
}

double refsamp_dart_radius(uint64_t n)
{
	return 0.7 * sqrt(2.0 / (sqrt(3.0) * (double)n));
}

uint64_t refsamp_cube_side(uint64_t n)
{
	uint64_t k;

	/* Up to 2^60, (2k + 1)^3 and 8n fit in 64 bits. */
	if (n > (uint64_t)1 << 60)
		n = (uint64_t)1 << 60;
	k = (uint64_t)llround(cbrt((double)n));
	/* Exact: k - 1/2 <= cbrt(n) < k + 1/2, i.e. (2k-1)^3 <= 8n <
	 * (2k+1)^3; never a tie, an odd cube is not 8n. */
	while (k > 1 && (2 * k - 1) * (2 * k - 1) * (2 * k - 1) > 8 * n)
		k--;
	while ((2 * k + 1) * (2 * k + 1) * (2 * k + 1) <= 8 * n)
		k++;
	return k < 1 ? 1 : k;
}

double refsamp_dart_radius3(uint64_t n)
{
	/* FCC packs spheres of diameter d at density pi / (3 sqrt 2), one
	 * per volume d^3 / sqrt 2; n of them fill the cube at
	 * d = cbrt(sqrt(2) / n).  0.7 as in 2-D. */
	return 0.7 * cbrt(sqrt(2.0) / (double)n);
}

static uint32_t reverse32(uint32_t x)
{
	x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
	x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
	x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
	x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
	return (x >> 16) | (x << 16);
}

/* Laine and Karras (2011) hash permutation as refined by Burley (2020):
 * on bit-reversed values each bit depends only on the bits below it, so
 * reversed back it is a nested uniform (Owen) scramble. */
static uint32_t owen_scramble(uint32_t x, uint32_t key)
{
	x = reverse32(x);
	x += key;
	x ^= x * 0x6c50b47cu;
	x ^= x * 0xb82f1e52u;
	x ^= x * 0xc7afe638u;
	x ^= x * 0x8d22f6e6u;
	return reverse32(x);
}

void refsamp_sobol32(uint32_t i, uint32_t key_x, uint32_t key_y,
    uint32_t out[2])
{
	uint32_t g = i ^ (i >> 1), x = 0, y = 0, v = 0x80000000u;

	/* Dimension 1: van der Corput; dimension 2: primitive polynomial
	 * x + 1, v_1 = 1/2, v_k = v_{k-1} ^ (v_{k-1} >> 1). */
	for (unsigned k = 0; k < 32; k++) {
		if (g >> k & 1) {
			x ^= 0x80000000u >> k;
			y ^= v;
		}
		v ^= v >> 1;
	}
	if (key_x || key_y) {
		x = owen_scramble(x, key_x);
		y = owen_scramble(y, key_y);
	}
	out[0] = x;
	out[1] = y;
}

void refsamp_sobol32_3(uint32_t i, const uint32_t key[3], uint32_t out[3])
{
	uint32_t g = i ^ (i >> 1), x = 0, y = 0, z = 0, v = 0x80000000u;
	uint32_t w = 0x80000000u, w1 = 0xc0000000u;

	/* Dimensions 1 and 2 as in refsamp_sobol32.  Dimension 3 (Joe and
	 * Kuo 2008, d = 3: s = 2, a = 1, m = 1, 3) in 32-bit direction
	 * numbers V_k = m_k 2^(32-k): V_1 = 1/2, V_2 = 3/4 and
	 * V_k = V_{k-1} ^ V_{k-2} ^ (V_{k-2} >> 2); w holds V_k, w1
	 * V_{k+1}. */
	for (unsigned k = 0; k < 32; k++) {
		uint32_t w2 = w1 ^ w ^ (w >> 2);
		if (g >> k & 1) {
			x ^= 0x80000000u >> k;
			y ^= v;
			z ^= w;
		}
		v ^= v >> 1;
		w = w1;
		w1 = w2;
	}
	if (key[0] || key[1] || key[2]) {
		x = owen_scramble(x, key[0]);
		y = owen_scramble(y, key[1]);
		z = owen_scramble(z, key[2]);
	}
	out[0] = x;
	out[1] = y;
	out[2] = z;
}

/* A Cranley-Patterson shift from the seed, zero for seed 0; u[0], u[1]
 * are the same for 2-D and 3-D, so that a 3-D set extends the 2-D one. */
static void seed_shift(uint64_t seed, double u[3])
{
	u[0] = u[1] = u[2] = 0;
	if (seed == 0)
		return;
	for (uint64_t a = 0; a < 3; a++)
		u[a] = (double)(frs_rand64x(seed, FRS_STREAM_REF, a, 1) >> 11) *
		    0x1p-53;
}

static double wrap(double v)
{
	if (v >= 1.0)
		v -= 1.0;
	return v < 1.0 ? v : 0.0;
}

static double below1(double v)
{
	return v < 1.0 ? v : nextafter(1.0, 0.0);
}

static int gen_dart(uint64_t n, uint64_t seed, uint64_t max_failures,
    double *xy, uint64_t *placed)
{
	double r = refsamp_dart_radius(n), r2 = r * r;
	uint64_t g = (uint64_t)ceil(sqrt(2.0) / r), got = 0, fails = 0, t = 0;
	int64_t *cell;
	int reach = 2, all;

	if (g < 1)
		g = 1;
	/* Cells of side 1/g <= r / sqrt 2 hold one point at most. */
	while (1.0 / (double)g > r / sqrt(2.0))
		g++;
	if (g > ((uint64_t)1 << 31) ||
	    (cell = malloc(g * g * sizeof *cell)) == NULL)
		return frs_fail("dart throwing: no memory for %llu cells",
		    (unsigned long long)(g * g));
	for (uint64_t c = 0; c < g * g; c++)
		cell[c] = -1;
	all = g < 2 * (uint64_t)reach + 1;
	while (got < n && fails < max_failures) {
		double x = frs_rand01(seed, FRS_STREAM_REF, 2 * t);
		double y = frs_rand01(seed, FRS_STREAM_REF, 2 * t + 1);
		int64_t cx = (int64_t)(x * (double)g), cy = (int64_t)(y * (double)g);
		int64_t lo = all ? 0 : -reach, hi = all ? (int64_t)g - 1 : reach;
		int ok = 1;

		t++;
		if (cx >= (int64_t)g)
			cx = (int64_t)g - 1;
		if (cy >= (int64_t)g)
			cy = (int64_t)g - 1;
		for (int64_t dy = lo; ok && dy <= hi; dy++)
			for (int64_t dx = lo; ok && dx <= hi; dx++) {
				int64_t ix = all ? dx : (cx + dx + (int64_t)g) %
				    (int64_t)g;
				int64_t iy = all ? dy : (cy + dy + (int64_t)g) %
				    (int64_t)g;
				int64_t p = cell[(uint64_t)iy * g + (uint64_t)ix];
				double ddx, ddy;
				if (p < 0)
					continue;
				ddx = fabs(xy[2 * p] - x);
				ddy = fabs(xy[2 * p + 1] - y);
				if (ddx > 0.5)
					ddx = 1.0 - ddx;
				if (ddy > 0.5)
					ddy = 1.0 - ddy;
				if (ddx * ddx + ddy * ddy < r2)
					ok = 0;
			}
		if (!ok) {
			fails++;
			continue;
		}
		fails = 0;
		cell[(uint64_t)cy * g + (uint64_t)cx] = (int64_t)got;
		xy[2 * got] = x;
		xy[2 * got + 1] = y;
		got++;
	}
	free(cell);
	*placed = got;
	return 0;
}

/* Relaxed dart throwing state.  Accepted points are kept by level of
 * their radius factor f = r / r0: level L holds f in [fmin 2^L,
 * fmin 2^(L+1)), each level a grid of linked lists (head per cell, next
 * per point) with cells about its largest radius, so that a candidate
 * looks at few cells of each level. */
#define RELAX_LEVELS 64

struct relax {
	const double *v;	/* importance */
	uint32_t w, h;
	double mean, fmin;
	double *xy, *f;		/* points; f: r / r0 of each point */
	uint64_t got;
	int64_t *head, *next;
	unsigned nl;		/* levels */
	uint64_t off[RELAX_LEVELS], cap[RELAX_LEVELS], g[RELAX_LEVELS];
	uint64_t cnt[RELAX_LEVELS];
	double fmax[RELAX_LEVELS];	/* largest f placed in each level */
};

static unsigned relax_level(const struct relax *s, double f)
{
	double q = f / s->fmin;
	unsigned l = 0;

	while (l + 1 < s->nl && q >= 2.0) {
		q *= 0.5;
		l++;
	}
	return l;
}

static void relax_insert(struct relax *s, uint64_t i)
{
	unsigned l = relax_level(s, s->f[i]);
	uint64_t g = s->g[l];
	uint64_t cx = (uint64_t)(s->xy[2 * i] * (double)g);
	uint64_t cy = (uint64_t)(s->xy[2 * i + 1] * (double)g);
	uint64_t c;

	if (cx >= g)
		cx = g - 1;
	if (cy >= g)
		cy = g - 1;
	c = s->off[l] + cy * g + cx;
	s->next[i] = s->head[c];
	s->head[c] = (int64_t)i;
}

/* (Re)build the grids for r0. */
static void relax_grid(struct relax *s, double r0)
{
	double cell = r0 * s->fmin * 2.0;

	for (unsigned l = 0; l < s->nl; l++, cell *= 2.0) {
		double gd = ceil(1.0 / cell);
		uint64_t g = gd < (double)s->cap[l] ? (uint64_t)gd : s->cap[l];
		if (g < 1)
			g = 1;
		s->g[l] = g;
		for (uint64_t c = 0; c < g * g; c++)
			s->head[s->off[l] + c] = -1;
	}
	for (uint64_t i = 0; i < s->got; i++)
		relax_insert(s, i);
}

/* Whether x, y with radius factor fx conflicts with an accepted point
 * under r0. */
static int relax_conflict(const struct relax *s, double x, double y,
    double fx, double r0)
{
	for (unsigned l = 0; l < s->nl; l++) {
		double reach, gd = (double)s->g[l];
		int64_t x0, x1, y0, y1, gm = (int64_t)s->g[l] - 1;

		if (s->cnt[l] == 0)
			continue;
		reach = r0 * (fx > s->fmax[l] ? fx : s->fmax[l]);
		x0 = (int64_t)floor(fmax(x - reach, 0.0) * gd);
		x1 = (int64_t)floor(fmin(x + reach, 1.0) * gd);
		y0 = (int64_t)floor(fmax(y - reach, 0.0) * gd);
		y1 = (int64_t)floor(fmin(y + reach, 1.0) * gd);
		if (x1 > gm)
			x1 = gm;
		if (y1 > gm)
			y1 = gm;
		for (int64_t cy = y0; cy <= y1; cy++)
			for (int64_t cx = x0; cx <= x1; cx++)
				for (int64_t p = s->head[s->off[l] +
				    (uint64_t)cy * s->g[l] + (uint64_t)cx];
				    p >= 0; p = s->next[p]) {
					double dx = s->xy[2 * p] - x;
					double dy = s->xy[2 * p + 1] - y;
					double fq = s->f[p];
					double r = r0 * (fx > fq ? fx : fq);
					if (dx * dx + dy * dy < r * r)
						return 1;
				}
	}
	return 0;
}

int refsamp_relaxed_dart(uint64_t n, uint64_t seed, uint64_t max_failures,
    const struct frs_imap *map, double *xy, double *r0_out)
{
	static const double one = 1.0;
	struct relax s;
	double *cdf, total = 0, r0, imax = 0, iminp = 0, fmaxall;
	uint64_t np, fails = 0, t = 0, gcap, cells = 0;

	if (n < 1 || n > REFSAMP_MAX_N)
		return frs_fail("count %llu is not in 1 to %llu",
		    (unsigned long long)n, (unsigned long long)REFSAMP_MAX_N);
	if (max_failures < 1)
		return frs_fail("relaxed dart: max failures must be at least 1");
	memset(&s, 0, sizeof s);
	if (map != NULL) {
		s.v = map->v;
		s.w = map->w;
		s.h = map->h;
	} else {
		s.v = &one;
		s.w = s.h = 1;
	}
	np = (uint64_t)s.w * s.h;
	if (np == 0)
		return frs_fail("relaxed dart: empty importance map");
	if ((cdf = malloc(np * sizeof *cdf)) == NULL)
		return frs_fail("relaxed dart: no memory for %llu pixels",
		    (unsigned long long)np);
	for (uint64_t i = 0; i < np; i++) {
		double v = s.v[i];
		if (!isfinite(v) || v < 0) {
			free(cdf);
			return frs_fail("relaxed dart: importance %g at pixel "
			    "%llu is not finite and non-negative", v,
			    (unsigned long long)i);
		}
		total += v;
		cdf[i] = total;
		if (v > imax)
			imax = v;
		if (v > 0 && (iminp == 0 || v < iminp))
			iminp = v;
	}
	if (!(total > 0) || !isfinite(total)) {
		free(cdf);
		return frs_fail("relaxed dart: the importance map is zero "
		    "everywhere");
	}
	s.mean = total / (double)np;
	s.fmin = sqrt(s.mean / imax);
	fmaxall = sqrt(s.mean / iminp);
	s.nl = 1;
	for (double q = fmaxall / s.fmin; q >= 2.0 && s.nl < RELAX_LEVELS;
	    q *= 0.5)
		s.nl++;
	/* Grid side: level 0 at most about 2 sqrt(n) + 1 cells and 4096,
	 * halved at each level up. */
	gcap = (uint64_t)ceil(2.0 * sqrt((double)n)) + 1;
	if (gcap > 4096)
		gcap = 4096;
	for (unsigned l = 0; l < s.nl; l++) {
		s.cap[l] = l < 63 ? (gcap + ((uint64_t)1 << l) - 1) >> l : 1;
		s.off[l] = cells;
		cells += s.cap[l] * s.cap[l];
	}
	s.xy = xy;
	s.f = malloc(n * sizeof *s.f);
	s.next = malloc(n * sizeof *s.next);
	s.head = malloc(cells * sizeof *s.head);
	if (s.f == NULL || s.next == NULL || s.head == NULL) {
		MEM_FREE(cdf, s.f, s.next, s.head);
		return frs_fail("relaxed dart: no memory for %llu points",
		    (unsigned long long)n);
	}
	r0 = 2.0 * refsamp_dart_radius(n);
	relax_grid(&s, r0);
	while (s.got < n) {
		double u = frs_rand01(seed, FRS_STREAM_REF, 3 * t);
		double ux = frs_rand01(seed, FRS_STREAM_REF, 3 * t + 1);
		double uy = frs_rand01(seed, FRS_STREAM_REF, 3 * t + 2);
		double target = u * total, x, y, fx;
		uint64_t lo = 0, hi = np - 1, pix;
		unsigned l;

		t++;
		/* The first pixel whose cumulative sum exceeds target:
		 * never a zero-importance pixel. */
		while (lo < hi) {
			uint64_t mid = lo + (hi - lo) / 2;
			if (cdf[mid] > target)
				hi = mid;
			else
				lo = mid + 1;
		}
		pix = lo;
		if (!(s.v[pix] > 0))
			continue;	/* rounding at the top end */
		x = below1(((double)(pix % s.w) + ux) / (double)s.w);
		y = below1(((double)(pix / s.w) + uy) / (double)s.h);
		fx = sqrt(s.mean / s.v[pix]);
		if (relax_conflict(&s, x, y, fx, r0)) {
			if (++fails >= max_failures) {
				fails = 0;
				r0 *= REFSAMP_RELAX_FACTOR;
				relax_grid(&s, r0);
			}
			continue;
		}
		fails = 0;
		xy[2 * s.got] = x;
		xy[2 * s.got + 1] = y;
		s.f[s.got] = fx;
		l = relax_level(&s, fx);
		s.cnt[l]++;
		if (fx > s.fmax[l])
			s.fmax[l] = fx;
		relax_insert(&s, s.got);
		s.got++;
	}
	if (r0_out != NULL)
		*r0_out = r0;
	MEM_FREE(cdf, s.f, s.next, s.head);
	return 0;
}

int refsamp_gen(enum refsamp_kind k, uint64_t n, uint64_t seed,
    uint64_t max_failures, double *xy, uint64_t *placed)
{
	double u[3];
	uint64_t s;

	if (n < 1 || n > REFSAMP_MAX_N)
		return frs_fail("count %llu is not in 1 to %llu",
		    (unsigned long long)n, (unsigned long long)REFSAMP_MAX_N);
	*placed = refsamp_count(k, n);
	seed_shift(seed, u);
	switch (k) {
	case REFSAMP_RANDOM:
		for (uint64_t i = 0; i < n; i++) {
			xy[2 * i] = frs_rand01(seed, FRS_STREAM_REF, 2 * i);
			xy[2 * i + 1] = frs_rand01(seed, FRS_STREAM_REF, 2 * i + 1);
		}
		return 0;
	case REFSAMP_REGULAR:
	case REFSAMP_JITTERED:
		s = refsamp_grid_side(n);
		for (uint64_t i = 0; i < s * s; i++) {
			double jx = 0.5, jy = 0.5;
			if (k == REFSAMP_JITTERED) {
				jx = frs_rand01(seed, FRS_STREAM_REF, 2 * i);
				jy = frs_rand01(seed, FRS_STREAM_REF, 2 * i + 1);
			}
			xy[2 * i] = below1(((double)(i % s) + jx) / (double)s);
			xy[2 * i + 1] = below1(((double)(i / s) + jy) / (double)s);
		}
		return 0;
	case REFSAMP_HALTON:
		for (uint64_t i = 0; i < n; i++) {
			xy[2 * i] = wrap(num_radical_inverse(i + 1, 2) + u[0]);
			xy[2 * i + 1] = wrap(num_radical_inverse(i + 1, 3) +
			    u[1]);
		}
		return 0;
	case REFSAMP_HAMMERSLEY:
		for (uint64_t i = 0; i < n; i++) {
			xy[2 * i] = wrap(((double)i + 0.5) / (double)n + u[0]);
			xy[2 * i + 1] = wrap(num_radical_inverse(i, 2) + u[1]);
		}
		return 0;
	case REFSAMP_SOBOL: {
		uint32_t kx = 0, ky = 0, p[2];
		if (seed != 0) {
			kx = (uint32_t)frs_rand64x(seed, FRS_STREAM_REF, 0, 2);
			ky = (uint32_t)frs_rand64x(seed, FRS_STREAM_REF, 1, 2);
		}
		for (uint64_t i = 0; i < n; i++) {
			refsamp_sobol32((uint32_t)i, kx, ky, p);
			xy[2 * i] = (double)p[0] * 0x1p-32;
			xy[2 * i + 1] = (double)p[1] * 0x1p-32;
		}
		return 0;
	}
	case REFSAMP_DART:
		return gen_dart(n, seed, max_failures, xy, placed);
	case REFSAMP_RELAXED_DART:
		return refsamp_relaxed_dart(n, seed, max_failures, NULL, xy,
		    NULL);
	}
	return frs_fail("unknown kind %d", (int)k);
}

uint64_t refsamp_count_dims(enum refsamp_kind k, uint64_t n, unsigned dims)
{
	if (dims == 3 && (k == REFSAMP_REGULAR || k == REFSAMP_JITTERED)) {
		uint64_t s = refsamp_cube_side(n);
		return s * s * s;
	}
	return refsamp_count(k, n);
}

/* 3-D dart throwing: a grid of g^3 cells of side at most r / sqrt 3, so
 * that a cell holds one point at most; cell[c] is 1 + the index of its
 * point, 0 when empty (so that a zeroed allocation is an empty grid). */
struct dart3 {
	double *p, r2;
	uint64_t *cell, g;
	int64_t reach;	/* cells a radius spans along an axis */
	int all;	/* the grid is too small to wrap: look at every cell */
};

static uint64_t cell_of(double v, uint64_t g)
{
	uint64_t c = (uint64_t)(v * (double)g);
	return c < g ? c : g - 1;	/* v * g may round up to g */
}

static uint64_t dart3_cell(const struct dart3 *s, const double x[3])
{
	return (cell_of(x[2], s->g) * s->g + cell_of(x[1], s->g)) * s->g +
	    cell_of(x[0], s->g);
}

/* Cell c + d along one axis, on the torus; d itself when all. */
static uint64_t wrap_cell(const struct dart3 *s, uint64_t c, int64_t d)
{
	int64_t g = (int64_t)s->g;
	return s->all ? (uint64_t)d : (uint64_t)(((int64_t)c + d + g) % g);
}

static double torus_gap(double a, double b)
{
	double d = fabs(a - b);
	return d > 0.5 ? 1.0 - d : d;
}

static int dart3_near(const struct dart3 *s, const double x[3], uint64_t c)
{
	uint64_t q = s->cell[c];
	double dx, dy, dz;

	if (q == 0)
		return 0;
	dx = torus_gap(s->p[3 * (q - 1)], x[0]);
	dy = torus_gap(s->p[3 * (q - 1) + 1], x[1]);
	dz = torus_gap(s->p[3 * (q - 1) + 2], x[2]);
	return dx * dx + dy * dy + dz * dz < s->r2;
}

/* Whether an accepted point lies within r of x on the torus. */
static int dart3_conflict(const struct dart3 *s, const double x[3])
{
	int64_t lo = s->all ? 0 : -s->reach;
	int64_t hi = s->all ? (int64_t)s->g - 1 : s->reach;
	uint64_t cx = cell_of(x[0], s->g), cy = cell_of(x[1], s->g);
	uint64_t cz = cell_of(x[2], s->g);

	for (int64_t dz = lo; dz <= hi; dz++)
		for (int64_t dy = lo; dy <= hi; dy++)
			for (int64_t dx = lo; dx <= hi; dx++) {
				uint64_t c = (wrap_cell(s, cz, dz) * s->g +
				    wrap_cell(s, cy, dy)) * s->g +
				    wrap_cell(s, cx, dx);
				if (dart3_near(s, x, c))
					return 1;
			}
	return 0;
}

static int gen_dart3(uint64_t n, uint64_t seed, uint64_t max_failures,
    double *xyz, uint64_t *placed)
{
	double r = refsamp_dart_radius3(n);
	struct dart3 s;
	uint64_t got = 0, fails = 0, t = 0;

	s.p = xyz;
	s.r2 = r * r;
	s.g = (uint64_t)ceil(sqrt(3.0) / r);
	if (s.g < 1)
		s.g = 1;
	while (1.0 / (double)s.g > r / sqrt(3.0))
		s.g++;
	/* A neighbour within r is at most ceil(r g) cells away per axis;
	 * when 2 reach + 1 cells would wrap onto themselves, look at all. */
	s.reach = (int64_t)ceil(r * (double)s.g);
	s.all = s.g < 2 * (uint64_t)s.reach + 1;
	if (s.g > ((uint64_t)1 << 21))
		return frs_fail("dart throwing: %llu^3 cells are too many",
		    (unsigned long long)s.g);
	if ((s.cell = mem_calloc("dart throwing cells", s.g * s.g * s.g,
	    sizeof *s.cell)) == NULL)
		return -1;
	while (got < n && fails < max_failures) {
		double x[3];
		for (uint64_t a = 0; a < 3; a++)
			x[a] = frs_rand01(seed, FRS_STREAM_REF, 3 * t + a);
		t++;
		if (dart3_conflict(&s, x)) {
			fails++;
			continue;
		}
		fails = 0;
		s.cell[dart3_cell(&s, x)] = got + 1;
		memcpy(xyz + 3 * got, x, sizeof x);
		got++;
	}
	free(s.cell);
	*placed = got;
	return 0;
}

/* Regular (cell centres) or jittered (one uniform point per cell) on the
 * s^3 grid, x fastest, then y, then z. */
static void gen_grid3(int jitter, uint64_t n, uint64_t seed, double *xyz)
{
	uint64_t s = refsamp_cube_side(n);

	for (uint64_t i = 0; i < s * s * s; i++) {
		uint64_t c[3] = { i % s, i / s % s, i / (s * s) };
		for (uint64_t a = 0; a < 3; a++) {
			double j = jitter ?
			    frs_rand01(seed, FRS_STREAM_REF, 3 * i + a) : 0.5;
			xyz[3 * i + a] = below1(((double)c[a] + j) / (double)s);
		}
	}
}

static void gen_sobol3(uint64_t n, uint64_t seed, double *xyz)
{
	uint32_t key[3] = { 0, 0, 0 }, p[3];

	/* The keys of the 2-D set for x and y. */
	if (seed != 0)
		for (uint64_t a = 0; a < 3; a++)
			key[a] = (uint32_t)frs_rand64x(seed, FRS_STREAM_REF, a, 2);
	for (uint64_t i = 0; i < n; i++) {
		refsamp_sobol32_3((uint32_t)i, key, p);
		for (unsigned a = 0; a < 3; a++)
			xyz[3 * i + a] = (double)p[a] * 0x1p-32;
	}
}

static int gen3(enum refsamp_kind k, uint64_t n, uint64_t seed,
    uint64_t max_failures, double *xyz, uint64_t *placed)
{
	static const unsigned base[3] = { 2, 3, 5 };
	double u[3];

	seed_shift(seed, u);
	switch (k) {
	case REFSAMP_RANDOM:
		for (uint64_t i = 0; i < 3 * n; i++)
			xyz[i] = frs_rand01(seed, FRS_STREAM_REF, i);
		return 0;
	case REFSAMP_REGULAR:
	case REFSAMP_JITTERED:
		gen_grid3(k == REFSAMP_JITTERED, n, seed, xyz);
		return 0;
	case REFSAMP_HALTON:
		for (uint64_t i = 0; i < n; i++)
			for (unsigned a = 0; a < 3; a++)
				xyz[3 * i + a] = wrap(num_radical_inverse(i +
				    1, base[a]) + u[a]);
		return 0;
	case REFSAMP_HAMMERSLEY:
		for (uint64_t i = 0; i < n; i++) {
			xyz[3 * i] = wrap(((double)i + 0.5) / (double)n + u[0]);
			for (unsigned a = 1; a < 3; a++)
				xyz[3 * i + a] = wrap(num_radical_inverse(i,
				    base[a - 1]) + u[a]);
		}
		return 0;
	case REFSAMP_SOBOL:
		gen_sobol3(n, seed, xyz);
		return 0;
	case REFSAMP_DART:
		return gen_dart3(n, seed, max_failures, xyz, placed);
	case REFSAMP_RELAXED_DART:
		return frs_fail("relaxed-dart is two-dimensional only (it "
		    "follows an importance map)");
	}
	return frs_fail("unknown kind %d", (int)k);
}

int refsamp_gen_dims(enum refsamp_kind k, unsigned dims, uint64_t n,
    uint64_t seed, uint64_t max_failures, double *x, uint64_t *placed)
{
	if (dims == 2)
		return refsamp_gen(k, n, seed, max_failures, x, placed);
	if (dims != 3)
		return frs_fail("%u dimensions: 2 or 3 only", dims);
	if (n < 1 || n > REFSAMP_MAX_N)
		return frs_fail("count %llu is not in 1 to %llu",
		    (unsigned long long)n, (unsigned long long)REFSAMP_MAX_N);
	*placed = refsamp_count_dims(k, n, 3);
	return gen3(k, n, seed, max_failures, x, placed);
}
