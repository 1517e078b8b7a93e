#define _POSIX_C_SOURCE 200809L
#include "maps/spec.h"
#include "maps/imap.h"
#include "maps/vol.h"
#include "base/err.h"
#include "base/num.h"
#include "base/parse.h"
#include "base/par.h"
#include "base/progress.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAXPARAM 6

struct param {
	const char *key;
	double def, min, max;
	const char *help;
};

/*
 * A source over a grid of k = 2 or 3 dimensions of sides n[0 .. k - 1]
 * (a map's w x h, a volume's w x h x d): eval fills the cell means of
 * the planes [r0, r1) of the last axis (the rows of a map, the slices of
 * a volume); out points at cell 0.
 */
typedef int spec_eval(const double *p, unsigned k, const uint32_t *n,
    uint32_t r0, uint32_t r1, double *out);

struct spec {
	const char *name;
	const char *help;
	unsigned dims;		/* 2 or 3, 0: both */
	struct param p[MAXPARAM];
	spec_eval *eval;
};

/* The cells of one plane of the last axis. */
static size_t plane_cells(unsigned k, const uint32_t *n)
{
	size_t c = 1;

	for (unsigned a = 0; a + 1 < k; a++)
		c *= n[a];
	return c;
}

/* ---- evaluators ------------------------------------------------------ */

static int eval_const(const double *p, unsigned k, const uint32_t *n,
    uint32_t r0, uint32_t r1, double *out)
{
	size_t c = plane_cells(k, n);

	for (size_t i = r0 * c; i < r1 * c; i++)
		out[i] = p[0];
	return 0;
}

/* Mean over [a, b] of exp(-(t-c)^2 / (2 s^2)), using erfc in the tails so
 * that far pixels keep their relative precision. */
static double gauss_mean(double a, double b, double c, double s)
{
	double k = 1.0 / (s * sqrt(2.0));
	double u = (a - c) * k, v = (b - c) * k, d;

	if (u >= 0.0)
		d = erfc(u) - erfc(v);
	else if (v <= 0.0)
		d = erfc(-v) - erfc(-u);
	else
		d = erf(v) - erf(u);
	return d * s * sqrt(NUM_PI / 2.0) / (b - a);
}

/* The Gaussian's means over the cells of axis a: g[i] over [i, i + 1) / m. */
static double *gauss_axis(const double *p, unsigned k, uint32_t m, unsigned a)
{
	double *g = malloc(m * sizeof *g);

	for (uint32_t i = 0; g != NULL && i < m; i++)
		g[i] = gauss_mean((double)i / m, (double)(i + 1) / m, p[a], p[k]);
	return g;
}

/* A separable Gaussian, p: the centre per axis, sigma, floor, peak; the
 * cell mean is the product of the axes' means, taken in axis order. */
static int eval_blob(const double *p, unsigned k, const uint32_t *n,
    uint32_t r0, uint32_t r1, double *out)
{
	double *g[2] = { NULL, NULL };
	size_t c = plane_cells(k, n);
	int rc = 0;

	for (unsigned a = 0; a + 1 < k; a++)
		if ((g[a] = gauss_axis(p, k, n[a], a)) == NULL)
			rc = frs_fail("out of memory");
	for (uint32_t r = r0; rc == 0 && r < r1; r++) {
		double gr = gauss_mean((double)r / n[k - 1],
		    (double)(r + 1) / n[k - 1], p[k - 1], p[k]);
		for (size_t i = 0; i < c; i++) {
			double v = p[k + 2];
			size_t q = i;
			for (unsigned a = 0; a + 1 < k; a++) {
				v *= g[a][q % n[a]];
				q /= n[a];
			}
			out[r * c + i] = v * gr + p[k + 1];
		}
	}
	free(g[0]);
	free(g[1]);
	return rc;
}

static int eval_ramp(const double *p, unsigned k, const uint32_t *n,
    uint32_t y0, uint32_t y1, double *out)
{
	double a = p[2] * NUM_PI / 180.0, c = cos(a), s = sin(a);
	uint32_t w = n[0], h = n[1];
	double norm = fabs(c) + fabs(s);

	(void)k;
	/* Linear, so the pixel mean is the value at the pixel centre. */
	for (uint32_t j = y0; j < y1; j++)
		for (uint32_t i = 0; i < w; i++) {
			double x = (i + 0.5) / w - 0.5, y = (j + 0.5) / h - 0.5;
			double t = 0.5 + (x * c + y * s) / norm;
			out[(size_t)j * w + i] = p[0] + (p[1] - p[0]) * t;
		}
	return 0;
}

/* Pixel means of f by n x n stratified supersampling. */
static void supersample(double (*f)(const double *, double, double),
    const double *p, uint32_t w, uint32_t h, uint32_t y0, uint32_t y1,
    uint32_t n, double *out)
{
	for (uint32_t j = y0; j < y1; j++)
		for (uint32_t i = 0; i < w; i++) {
			double acc = 0.0;
			for (uint32_t b = 0; b < n; b++)
				for (uint32_t a = 0; a < n; a++)
					acc += f(p, (i + (a + 0.5) / n) / w,
					    (j + (b + 0.5) / n) / h);
			out[(size_t)j * w + i] = acc / ((double)n * n);
		}
}

static double aniso_at(const double *p, double x, double y)
{
	double a = p[0] * NUM_PI / 180.0;
	/* Distance from the line through the centre at angle a. */
	double d = -(x - 0.5) * sin(a) + (y - 0.5) * cos(a);
	return p[2] + exp(-d * d / (2.0 * p[1] * p[1]));
}

static uint32_t ss_for(double feature, uint32_t w, uint32_t h)
{
	double pix = 1.0 / (w < h ? w : h);
	double n = ceil(4.0 * pix / feature);
	return n < 4.0 ? 4 : n > 64.0 ? 64 : (uint32_t)n;
}

static int eval_aniso(const double *p, unsigned k, const uint32_t *n,
    uint32_t y0, uint32_t y1, double *out)
{
	(void)k;
	supersample(aniso_at, p, n[0], n[1], y0, y1, ss_for(p[1], n[0], n[1]),
	    out);
	return 0;
}

/*
 * An equirectangular sky: x is the azimuth phi = 2 pi x, y the polar angle
 * theta = pi y (zenith at the top).  Sky brightening towards the horizon,
 * a dim ground, and a sun lobe exp(-(gamma/size)^2) around the sun
 * direction, gamma the angle to it.
 */
static double sky_at(const double *p, double x, double y)
{
	double th = NUM_PI * y, ph = 2.0 * NUM_PI * x;
	double ts = (90.0 - p[0]) * NUM_PI / 180.0, ps = p[1] * NUM_PI / 180.0;
	double cg = sin(th) * sin(ts) * cos(ph - ps) + cos(th) * cos(ts);
	double g = acos(cg > 1.0 ? 1.0 : cg < -1.0 ? -1.0 : cg);
	double r = g / (p[2] * NUM_PI / 180.0);
	double base = th < NUM_PI / 2.0 ? 1.0 + 1.5 * (1.0 - cos(th)) : p[4];

	return base + p[3] * exp(-r * r);
}

static int eval_sky(const double *p, unsigned k, const uint32_t *n,
    uint32_t y0, uint32_t y1, double *out)
{
	(void)k;
	supersample(sky_at, p, n[0], n[1], y0, y1, ss_for(p[2] / 360.0, n[0],
	    n[1]), out);
	return 0;
}

/* Linear along one axis, so the voxel mean is the value at its centre. */
static int eval_ramp3(const double *p, unsigned k, const uint32_t *n,
    uint32_t z0, uint32_t z1, double *out)
{
	int axis = (int)p[2];
	uint32_t w = n[0], h = n[1];

	(void)k;
	if (p[2] != axis)
		return frs_fail("ramp3: axis %g is not 0 (x), 1 (y) or 2 (z)", p[2]);
	for (uint32_t l = z0; l < z1; l++)
		for (uint32_t j = 0; j < h; j++)
			for (uint32_t i = 0; i < w; i++) {
				uint32_t c = axis == 0 ? i : axis == 1 ? j : l;
				double t = (c + 0.5) / n[axis];
				out[((size_t)l * h + j) * w + i] = p[0] + (p[1] - p[0]) * t;
			}
	return 0;
}

/* A spherical shell around the centre: floor + exp(-(r - R)^2 / 2w^2),
 * voxel means by s^3 stratified supersampling. */
static int eval_shell3(const double *p, unsigned k, const uint32_t *n,
    uint32_t z0, uint32_t z1, double *out)
{
	uint32_t w = n[0], h = n[1], d = n[2];
	uint32_t side = w < h ? (w < d ? w : d) : (h < d ? h : d);
	uint32_t s = ss_for(p[1], side, side);

	(void)k;
	s = s > 16 ? 16 : s;
	for (uint32_t l = z0; l < z1; l++)
		for (uint32_t j = 0; j < h; j++)
			for (uint32_t i = 0; i < w; i++) {
				double acc = 0.0;
				for (uint32_t c = 0; c < s * s * s; c++) {
					double x = (i + (c % s + 0.5) / s) / w - 0.5;
					double y = (j + (c / s % s + 0.5) / s) / h - 0.5;
					double z = (l + (c / (s * s) + 0.5) / s) / d - 0.5;
					double r = sqrt(x * x + y * y + z * z) - p[0];
					acc += exp(-r * r / (2.0 * p[1] * p[1]));
				}
				out[((size_t)l * h + j) * w + i] =
				    p[2] + acc / ((double)s * s * s);
			}
	return 0;
}

/* The blob's parameters after its centre. */
#define CENTRE(a) { #a, 0.5, -10.0, 10.0, "centre " #a }
#define BLOB_SHAPE \
	{ "sigma", 0.15, 1e-6, 100.0, "standard deviation" }, \
	{ "floor", 0.0, 0.0, 1e300, "constant added everywhere" }, \
	{ "peak", 1.0, 1e-300, 1e300, "height of the Gaussian" }

/* The maps' and the volumes' sources, in the order of their help. */
static const struct spec specs[] = {
	{ "const", "constant importance", 0, {
	    { "v", 1.0, 0.0, 1e300, "the value" } }, eval_const },
	{ "blob", "Gaussian blob (exact pixel means)", 2, {
	    CENTRE(x), CENTRE(y), BLOB_SHAPE }, eval_blob },
	{ "ramp", "linear gradient", 2, {
	    { "from", 0.0, 0.0, 1e300, "value at the start edge" },
	    { "to", 1.0, 0.0, 1e300, "value at the end edge" },
	    { "angle", 0.0, -360.0, 360.0,
	      "direction in degrees, 0 = left to right, 90 = top to bottom" } },
	    eval_ramp },
	{ "aniso", "thin ridge along a line through the centre", 2, {
	    { "angle", 30.0, -360.0, 360.0, "direction of the ridge, degrees" },
	    { "width", 0.02, 1e-4, 10.0, "Gaussian width across the ridge" },
	    { "floor", 0.001, 0.0, 1e300, "constant added everywhere" } },
	    eval_aniso },
	{ "sky", "equirectangular HDR sky with a sun", 2, {
	    { "elev", 30.0, -90.0, 90.0, "sun elevation, degrees" },
	    { "azim", 90.0, -360.0, 360.0, "sun azimuth, degrees (x = azim/360)" },
	    { "size", 2.0, 0.05, 90.0, "angular radius of the sun lobe, degrees" },
	    { "sun", 1e5, 0.0, 1e300, "sun peak over the zenith sky" },
	    { "ground", 0.05, 0.0, 1e300, "ground value below the horizon" } },
	    eval_sky },
	{ "blob3", "3-D Gaussian blob (exact voxel means)", 3, {
	    CENTRE(x), CENTRE(y), CENTRE(z), BLOB_SHAPE }, eval_blob },
	{ "ramp3", "linear gradient along one axis", 3, {
	    { "from", 0.0, 0.0, 1e300, "value at coordinate 0" },
	    { "to", 1.0, 0.0, 1e300, "value at coordinate 1" },
	    { "axis", 2.0, 0.0, 2.0, "0 = x, 1 = y, 2 = z" } },
	    eval_ramp3 },
	{ "shell3", "spherical shell around the centre", 3, {
	    { "r", 0.3, 0.0, 2.0, "radius" },
	    { "width", 0.03, 1e-4, 10.0, "Gaussian width across the shell" },
	    { "floor", 0.01, 0.0, 1e300, "constant added everywhere" } },
	    eval_shell3 },
};
#define NSPECS (sizeof specs / sizeof specs[0])

/* A family of procedural sources: the maps (2) or the volumes (3). */
struct family {
	unsigned dims;
	const char *names;	/* for messages */
	const char *what;
};

static const struct family maps = { 2, "const, blob, ramp, aniso, sky",
	"map" };
static const struct family vols = { 3, "const, blob3, ramp3, shell3",
	"volume" };

static int in_family(const struct family *f, const struct spec *sp)
{
	return sp->dims == 0 || sp->dims == f->dims;
}

static const struct spec *find_spec(const struct family *f, const char *s,
    size_t len)
{
	for (size_t i = 0; i < NSPECS; i++)
		if (in_family(f, &specs[i]) && strlen(specs[i].name) == len &&
		    strncmp(specs[i].name, s, len) == 0)
			return &specs[i];
	return NULL;
}

int imap_is_spec(const char *src)
{
	return find_spec(&maps, src, strcspn(src, ":")) != NULL;
}

static int set_param(const struct spec *sp, const char *spec, char *item,
    int pos, double *val)
{
	char *eq = strchr(item, '=');
	const char *key = item, *v = eq ? eq + 1 : item;
	int k = -1;

	if (eq == NULL) {
		if (pos != 0)
			return frs_fail("%s: '%s': only the first parameter may "
			    "omit its name", spec, item);
		k = 0;
	} else {
		*eq = '\0';
		for (int i = 0; i < MAXPARAM && sp->p[i].key; i++)
			if (strcmp(sp->p[i].key, key) == 0)
				k = i;
	}
	if (k < 0) {
		char known[128] = "";
		for (int i = 0; i < MAXPARAM && sp->p[i].key; i++) {
			strncat(known, i ? ", " : "", sizeof known - strlen(known) - 1);
			strncat(known, sp->p[i].key, sizeof known - strlen(known) - 1);
		}
		return frs_fail("%s: unknown parameter '%s' of %s (%s)", spec, key,
		    sp->name, known);
	}
	if (parse_double(sp->p[k].key, v, sp->p[k].min, sp->p[k].max,
	    &val[k]) < 0)
		return frs_fail_context(spec);
	/* An axis is a whole number: caught here, with the other errors
	 * of the spec, not by the evaluating threads. */
	if (strcmp(sp->p[k].key, "axis") == 0 && val[k] != floor(val[k]))
		return frs_fail("%s: axis: %s is not 0 (x), 1 (y) or 2 (z)",
		    spec, v);
	return 0;
}

static int parse_spec(const struct family *f, const char *spec,
    const struct spec **out, double *val)
{
	size_t nlen = strcspn(spec, ":");
	const struct spec *sp = find_spec(f, spec, nlen);
	char *copy, *item, *save = NULL;
	int pos = 0, rc = 0;

	if (sp == NULL) {
		frs_fail("%s: unknown %s '%.*s' (%s)", spec, f->what,
		    (int)nlen, spec, f->names);
		frs_set_errkind(FRS_ERRKIND_SPEC);
		return -1;
	}
	for (int i = 0; i < MAXPARAM; i++)
		val[i] = sp->p[i].def;
	*out = sp;
	if (spec[nlen] == '\0')
		return 0;
	copy = strdup(spec + nlen + 1);
	if (copy == NULL)
		return frs_fail("out of memory");
	for (item = strtok_r(copy, ",", &save); item && rc == 0;
	    item = strtok_r(NULL, ",", &save))
		rc = set_param(sp, spec, item, pos++, val);
	if (rc == 0 && pos == 0)
		rc = frs_fail("%s: empty parameter list", spec);
	free(copy);
	if (rc < 0)
		frs_set_errkind(FRS_ERRKIND_SPEC);
	return rc;
}

/* The cells of a k-D grid of sides n, filled by sp in bands of grain
 * planes of the last axis: planes are independent, so any thread may
 * fill any band. */
struct eval_job {
	const struct spec *sp;
	const double *val;
	unsigned k;
	const uint32_t *n;
	double *out;
};

static int eval_band(void *ctx, uint64_t r0, uint64_t r1)
{
	struct eval_job *j = ctx;
	return j->sp->eval(j->val, j->k, j->n, (uint32_t)r0, (uint32_t)r1,
	    j->out);
}

static int eval_grid(const struct spec *sp, const double *val, unsigned k,
    const uint32_t *n, double *out, uint64_t grain, struct progress *pr)
{
	struct eval_job job = { sp, val, k, n, out };

	return frs_parallel(n[k - 1], grain, eval_band, &job, pr);
}

int imap_spec(const char *spec, uint32_t w, uint32_t h, struct frs_imap *m)
{
	const struct spec *sp = NULL;
	const uint32_t n[2] = { w, h };
	double val[MAXPARAM];
	struct progress pr;
	int rc;

	memset(m, 0, sizeof *m);
	if (parse_spec(&maps, spec, &sp, val) < 0)
		return -1;
	if (imap_alloc(m, w, h) < 0)
		return frs_fail_context(spec);
	progress_begin(&pr, sp->name, h);
	rc = eval_grid(sp, val, 2, n, m->v, 16, &pr);
	progress_end(&pr);
	if (rc < 0) {
		imap_free(m);
		return frs_fail_context(spec);
	}
	return 0;
}

static void family_help(const struct family *f, char *buf, size_t size)
{
	size_t len = 0;

	for (size_t i = 0; i < NSPECS && len < size; i++) {
		const struct spec *sp = &specs[i];
		if (!in_family(f, sp))
			continue;
		len += (size_t)snprintf(buf + len, size - len, "  %-6s %s\n",
		    sp->name, sp->help);
		for (int k = 0; k < MAXPARAM && sp->p[k].key && len < size; k++)
			len += (size_t)snprintf(buf + len, size - len,
			    "         %s=%g  %s\n", sp->p[k].key, sp->p[k].def,
			    sp->p[k].help);
	}
}

const char *imap_spec_help(void)
{
	static char buf[4096];

	if (buf[0] == '\0')
		family_help(&maps, buf, sizeof buf);
	return buf;
}

int vol_is_spec(const char *src)
{
	return find_spec(&vols, src, strcspn(src, ":")) != NULL;
}

int vol_spec(const char *spec, uint32_t w, uint32_t h, uint32_t d,
    struct frs_vol *m)
{
	const struct spec *sp = NULL;
	double val[MAXPARAM];
	uint32_t n[3];

	memset(m, 0, sizeof *m);
	if (parse_spec(&vols, spec, &sp, val) < 0)
		return -1;
	if (w == 0)
		w = h = d = VOL_DEFAULT_SIDE;
	if (vol_alloc(m, w, h, d) < 0)
		return frs_fail_context(spec);
	n[0] = w;
	n[1] = h;
	n[2] = d;
	if (eval_grid(sp, val, 3, n, m->v, 1, NULL) < 0) {
		vol_free(m);
		return frs_fail_context(spec);
	}
	return 0;
}

const char *vol_spec_help(void)
{
	static char buf[4096];

	if (buf[0] == '\0')
		family_help(&vols, buf, sizeof buf);
	return buf;
}
