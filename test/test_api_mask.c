/*
 * Masks (frs_mask_wrap, .frp files and their twins against frs-sample
 * -m), and one sampler used by several threads at once, racing to make
 * a fresh mask's lazy parts.  The helpers: apiutil.h.
 */
#include "apiutil.h"

#include <pthread.h>

/* ---- masks ------------------------------------------------------------ */

/* frs_mask_wrap of the values of MATRIX: the samples of the loaded one. */
static void test_wrap(void **state)
{
	static const uint32_t v4[16] = { 0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1,
	    9, 15, 7, 13, 5 };
	struct frs_matrix m;
	frs_mask *mk;
	frs_sampler *s, *t;
	uint64_t n = 5000;
	uint32_t w = 0, h = 0;
	struct drawn a, b;

	(void)state;
	assert_int_equal(frd_read(MATRIX, &m), 0);
	assert_int_equal(frs_mask_wrap(&mk, m.v, m.w, m.h, NULL), FRS_OK);
	frs_mask_size(mk, &w, &h);
	assert_int_equal(w, 2048);
	assert_int_equal(h, 2048);
	assert_null(frs_mask_note(mk));
	s = sampler_f64(mk, &blob, NULL);
	t = sampler_f64(mask, &blob, NULL);
	a = draw(s, &n, 1, 3, 1);
	b = draw(t, &n, 1, 3, 1);
	assert_int_equal(a.n, b.n);
	assert_memory_equal(a.xy, b.xy, 2 * a.n * sizeof *a.xy);
	drawn_free(&a);
	drawn_free(&b);
	frs_sampler_free(s);
	frs_sampler_free(t);
	frs_mask_free(mk);
	frd_free(&m);
	/* A 4x4 one samples too. */
	assert_int_equal(frs_mask_wrap(&mk, v4, 4, 4, NULL), FRS_OK);
	frs_mask_size(mk, &w, &h);
	assert_int_equal(w, 4);
	assert_int_equal(h, 4);
	assert_int_equal(frs_sampler_new(&s, mk, NULL, 8, 8, 0, NULL, NULL),
	    FRS_OK);
	a = draw(s, &n, 1, 1, 0);
	for (size_t i = 0; i < 2 * a.n; i++)
		assert_true(a.xy[i] >= 0.0 && a.xy[i] < 1.0);
	drawn_free(&a);
	frs_sampler_free(s);
	frs_mask_free(mk);
}

/* A random 64x64 matrix (a permutation) in path. */
static void write_frd(const char *path, uint64_t seed)
{
	struct frs_matrix m;
	FILE *fp;

	assert_int_equal(frd_alloc(&m, 2, 64, 64, 1, "test"), 0);
	for (uint32_t i = 0; i < m.n; i++)
		m.v[i] = i;
	for (uint32_t i = (uint32_t)m.n - 1; i > 0; i--) {
		uint32_t j = (uint32_t)(frs_rand64(seed, FRS_STREAM_TEST, i) %
		    (i + 1)), t = m.v[i];
		m.v[i] = m.v[j];
		m.v[j] = t;
	}
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(frd_write(fp, path, &m), 0);
	assert_int_equal(fclose(fp), 0);
	frd_free(&m);
}

/* Samples of a mask file against frs-sample -m with the same file. */
static void compare_mask(const char *path, const char *algo,
    enum frs_algorithm a)
{
	const char *out = tu_path("m.pts");
	struct frs_options o;
	frs_mask *mk;
	frs_sampler *s;
	uint64_t n = 3000;
	struct drawn d;
	double *rec;
	frs_error e;

	if (frs_mask_load(&mk, path, &e) != FRS_OK) {
		print_error("frs_mask_load %s: %s %s\n", path,
		    frs_code_name((int)e.code), e.message);
		fail();
	}
	frs_options_init(&o);
	o.algorithm = a;
	s = sampler_f64(mk, &blob, &o);
	prog("frs-sample -q -m %s -i blob -a %s -n 3000 -S 2 -o %s", path, algo,
	    out);
	d = draw(s, &n, 1, 2, 0);
	rec = records(&d, 0, 0);
	same_as_file(out, rec, d.n, 0);
	free(rec);
	drawn_free(&d);
	frs_sampler_free(s);
	frs_mask_free(mk);
}

/* .frp files, and a .frd with a good, a stale and a damaged twin. */
static void test_prepared(void **state)
{
	char frd[256], frp[256], other[256], alone[256];
	frs_mask *mk;
	frs_error e;
	const char *note;

	(void)state;
	/* Copies: tu_path's buffers are reused. */
	snprintf(frd, sizeof frd, "%s", tu_path("M.frd"));
	snprintf(frp, sizeof frp, "%s", tu_path("M.frp"));
	snprintf(other, sizeof other, "%s", tu_path("O.frd"));
	snprintf(alone, sizeof alone, "%s", tu_path("P.frp"));
	write_frd(frd, 1);
	write_frd(other, 2);
	prog("frd-prep -a all %s -o %s", frd, alone);
	compare_mask(alone, "sorted", FRS_ALG_SORTED);
	compare_mask(alone, "level2", FRS_ALG_LEVEL2);
	compare_mask(frd, "stack", FRS_ALG_STACK);
	/* A good twin: used, no note. */
	prog("frd-prep -a all %s -o %s", frd, frp);
	assert_int_equal(frs_mask_load(&mk, frd, &e), FRS_OK);
	assert_null(frs_mask_note(mk));
	frs_mask_free(mk);
	compare_mask(frd, "sorted", FRS_ALG_SORTED);
	/* Stale: made from another matrix. */
	prog("frd-prep -a all %s -o %s", other, frp);
	assert_int_equal(frs_mask_load(&mk, frd, &e), FRS_OK);
	note = frs_mask_note(mk);
	assert_non_null(note);
	assert_non_null(strstr(note, "stale"));
	frs_mask_free(mk);
	compare_mask(frd, "level1", FRS_ALG_LEVEL1);
	/* Damaged: the right header, the matrix cut short (40 bytes of
	 * header, 64 x 64 values of 4).  The note may come when the damage
	 * is met, at the first draw. */
	prog("frd-prep -a all %s -o %s && truncate -s %d %s", frd, frp,
	    40 + 2 * 64 * 64, frp);
	compare_mask(frd, "sorted", FRS_ALG_SORTED);
	assert_int_equal(frs_mask_load(&mk, frd, &e), FRS_OK);
	{
		frs_sampler *s;
		uint64_t c;
		int q = quiet_begin();
		assert_int_equal(frs_sampler_new(&s, mk, NULL, 64, 64, 0, NULL,
		    NULL), FRS_OK);
		assert_int_equal(frs_count(s, 1000, 1, &c, NULL), FRS_OK);
		frs_sampler_free(s);
		quiet_end(q, "a mask with a damaged twin");
	}
	note = frs_mask_note(mk);
	if (note == NULL) {
		print_error("a damaged twin, ignored without a note\n");
		fail();
	}
	frs_mask_free(mk);
	/* Loaded directly, the damaged .frp is an error. */
	assert_int_equal(frs_mask_load(&mk, frp, &e), FRS_E_FORMAT);
	assert_null(mk);
}

/* ---- threads ---------------------------------------------------------- */

struct job {
	const frs_sampler *s;
	uint64_t n, seed;
	int pdf;
	struct drawn d;
	size_t cap;
	int rc;
};

static void *job_run(void *arg)
{
	struct job *j = arg;

	/* Several times, so that the calls overlap. */
	for (int r = 0; r < 3 && j->rc == FRS_OK; r++)
		j->rc = frs_draw(j->s, j->n, j->seed, j->d.xy, j->d.pdf, j->cap,
		    &j->d.n, NULL);
	return NULL;
}

/*
 * One sampler used by four threads at once, each with its own buffers,
 * two of them with the same seed; the mask fresh, so that the threads
 * also race to make its lazy parts (sorted lists, minmap).  The bytes of
 * sequential calls.
 */
static void test_thread_safety(void **state)
{
	frs_mask *mk;
	frs_sampler *s[2];
	struct frs_options o;
	struct job j[6];
	pthread_t t[6];

	(void)state;
	assert_int_equal(frs_mask_load(&mk, MATRIX, NULL), FRS_OK);
	frs_options_init(&o);
	o.jitter = FRS_JIT_RANDOM;
	s[0] = sampler_f64(mk, &blob, &o);
	o.algorithm = FRS_ALG_LEVEL1;
	o.threads = 2;
	s[1] = sampler_f64(mk, &blob, &o);
	for (int i = 0; i < 6; i++) {
		j[i] = (struct job){ s[i >= 4], 6000 + 1000 * (uint64_t)(i % 2),
		    i == 3 ? 1 : (uint64_t)i + 1, i % 2, { 0, NULL, NULL, NULL },
		    20000, FRS_OK };
		j[i].d.xy = malloc(2 * j[i].cap * sizeof(double));
		j[i].d.pdf = malloc(j[i].cap * sizeof(double));
		assert_non_null(j[i].d.xy);
		assert_non_null(j[i].d.pdf);
		if (!j[i].pdf) {
			free(j[i].d.pdf);
			j[i].d.pdf = NULL;
		}
	}
	for (int i = 0; i < 6; i++)
		assert_int_equal(pthread_create(&t[i], NULL, job_run, &j[i]), 0);
	for (int i = 0; i < 6; i++)
		assert_int_equal(pthread_join(t[i], NULL), 0);
	for (int i = 0; i < 6; i++) {
		struct drawn d = draw(j[i].s, &j[i].n, 1, j[i].seed, j[i].pdf);
		assert_int_equal(j[i].rc, FRS_OK);
		assert_int_equal(j[i].d.n, d.n);
		assert_memory_equal(j[i].d.xy, d.xy, 2 * d.n * sizeof(double));
		if (j[i].pdf)
			assert_memory_equal(j[i].d.pdf, d.pdf,
			    d.n * sizeof(double));
		drawn_free(&d);
		drawn_free(&j[i].d);
	}
	frs_sampler_free(s[0]);
	frs_sampler_free(s[1]);
	frs_mask_free(mk);
}

TU_MAIN(setup, teardown,
	cmocka_unit_test(test_wrap),
	cmocka_unit_test(test_prepared),
	cmocka_unit_test(test_thread_safety))
