/* Procedural maps against independent references: brute-force numeric
 * integration of the defining formulas, moments and symmetry. */
#include "testutil.h"
#include "maps/imap.h"
#include "maps/spec.h"


static void load(const char *spec, uint32_t w, uint32_t h, struct frs_imap *m)
{
	if (imap_spec(spec, w, h, m) != 0)
		print_error("%s\n", frs_errmsg());
	assert_non_null(m->v);
	assert_int_equal(m->w, w);
	assert_int_equal(m->h, h);
}

static void constant(void **state)
{
	struct frs_imap m;
	(void)state;
	load("const:0.25", 7, 3, &m);
	for (int i = 0; i < 21; i++)
		assert_true(m.v[i] == 0.25);
	imap_free(&m);
	load("const:v=3", 2, 2, &m);
	assert_true(m.v[3] == 3.0);
	imap_free(&m);
	load("const", 2, 2, &m);
	assert_true(m.v[0] == 1.0);
	imap_free(&m);
}

/* Pixel means equal a 40x40 midpoint integration of the formula. */
static void blob_means(void **state)
{
	const double cx = 0.3, cy = 0.65, s = 0.07, fl = 0.01, pk = 2.0;
	struct frs_imap m;
	(void)state;

	load("blob:x=0.3,y=0.65,sigma=0.07,floor=0.01,peak=2", 16, 12, &m);
	for (uint32_t j = 0; j < 12; j++)
		for (uint32_t i = 0; i < 16; i++) {
			double acc = 0.0;
			for (int b = 0; b < 40; b++)
				for (int a = 0; a < 40; a++) {
					double x = (i + (a + 0.5) / 40) / 16;
					double y = (j + (b + 0.5) / 40) / 12;
					double r2 = (x - cx) * (x - cx) +
					    (y - cy) * (y - cy);
					acc += fl + pk * exp(-r2 / (2 * s * s));
				}
			assert_double_equal(m.v[j * 16 + i], acc / 1600.0,
			    2e-4 * (acc / 1600.0));
		}
	imap_free(&m);
}

/* A blob well inside the square has its centroid at its centre and the
 * standard deviation sigma along each axis. */
static void blob_moments(void **state)
{
	struct frs_imap m;
	double sw = 0, sx = 0, sy = 0, sxx = 0;
	(void)state;

	load("blob:x=0.4,y=0.55,sigma=0.08", 256, 256, &m);
	for (uint32_t j = 0; j < 256; j++)
		for (uint32_t i = 0; i < 256; i++) {
			double v = m.v[j * 256 + i];
			double x = (i + 0.5) / 256, y = (j + 0.5) / 256;
			sw += v;
			sx += v * x;
			sy += v * y;
			sxx += v * x * x;
		}
	assert_double_equal(sx / sw, 0.4, 1e-6);
	assert_double_equal(sy / sw, 0.55, 1e-6);
	/* Pixel-mean sampling adds the box variance 1/(12 * 256^2). */
	assert_double_equal(sqrt(sxx / sw - (sx / sw) * (sx / sw)),
	    sqrt(0.08 * 0.08 + 1.0 / (12.0 * 65536.0)), 1e-5);
	imap_free(&m);
}

static void ramp(void **state)
{
	struct frs_imap m;
	struct frs_imap_stats s;
	(void)state;

	load("ramp", 10, 4, &m);
	imap_stats(&m, &s);
	assert_double_equal(s.mean, 0.5, 1e-12);
	for (uint32_t i = 0; i < 10; i++)
		assert_double_equal(m.v[i], (i + 0.5) / 10.0, 1e-12);
	assert_true(m.v[0] == m.v[30]);		/* constant along y */
	imap_free(&m);
	load("ramp:from=2,to=4,angle=90", 4, 8, &m);
	for (uint32_t j = 0; j < 8; j++)
		assert_double_equal(m.v[j * 4 + 2], 2.0 + 2.0 * (j + 0.5) / 8,
		    1e-12);
	imap_free(&m);
}

/* The ridge peaks on its line and is symmetric about the centre. */
static void aniso(void **state)
{
	struct frs_imap m;
	(void)state;

	load("aniso:angle=0,width=0.05,floor=0", 32, 32, &m);
	/* Horizontal ridge through y = 0.5: rows 15 and 16 are the peak. */
	for (uint32_t j = 0; j < 32; j++) {
		assert_double_equal(m.v[j * 32 + 3], m.v[(31 - j) * 32 + 3],
		    1e-12);
		if (j < 15)
			assert_true(m.v[j * 32] < m.v[(j + 1) * 32]);
	}
	imap_free(&m);
	load("aniso", 64, 64, &m);	/* 30 degrees: point symmetry */
	for (uint32_t k = 0; k < 64 * 64; k++)
		assert_double_equal(m.v[k], m.v[64 * 64 - 1 - k], 1e-9);
	imap_free(&m);
}

/* The brightest pixel is where the sun is; the ground is dim. */
static void sky(void **state)
{
	struct frs_imap m;
	size_t best = 0;
	(void)state;

	load("sky:elev=45,azim=180,size=2,sun=1e6,ground=0.01", 360, 180, &m);
	for (size_t k = 0; k < 360 * 180; k++)
		if (m.v[k] > m.v[best])
			best = k;
	assert_true(labs((long)(best % 360) - 180) <= 1);
	assert_true(labs((long)(best / 360) - 45) <= 1);
	assert_true(m.v[best] > 1e5);
	assert_double_equal(m.v[170 * 360 + 10], 0.01, 1e-9);
	assert_double_equal(m.v[0], 1.0, 1e-3);	/* zenith sky */
	imap_free(&m);
}

static void bad_specs(void **state)
{
	struct frs_imap m;
	(void)state;

	assert_int_equal(imap_spec("blub", 8, 8, &m), -1);
	assert_err_has("blub", "unknown map");
	assert_int_equal(imap_spec("blob:foo=1", 8, 8, &m), -1);
	assert_err_has("unknown parameter 'foo'", "sigma");
	assert_int_equal(imap_spec("blob:sigma=0", 8, 8, &m), -1);
	assert_err_has("blob:sigma=0", "sigma", "out of range");
	assert_int_equal(imap_spec("blob:sigma=abc", 8, 8, &m), -1);
	assert_err_has("not a number");
	assert_int_equal(imap_spec("blob:sigma=nan", 8, 8, &m), -1);
	assert_err_has("not a finite number");
	assert_int_equal(imap_spec("const:-1", 8, 8, &m), -1);
	assert_err_has("out of range");
	assert_int_equal(imap_spec("blob:0.5,0.5", 8, 8, &m), -1);
	assert_err_has("only the first parameter");
	assert_int_equal(imap_spec("blob:", 8, 8, &m), -1);
	assert_err_has("empty parameter list");
	assert_int_equal(imap_spec("blob", 0, 8, &m), -1);
	assert_null(m.v);
	assert_true(imap_is_spec("sky:elev=3"));
	assert_false(imap_is_spec("skyline.png"));
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(constant),
	cmocka_unit_test(blob_means),
	cmocka_unit_test(blob_moments),
	cmocka_unit_test(ramp),
	cmocka_unit_test(aniso),
	cmocka_unit_test(sky),
	cmocka_unit_test(bad_specs))
