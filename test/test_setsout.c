/* The sets writer of the samplers' --sets M: set i's records followed by
 * i in a column named set, the bytes of the same records packed by hand
 * and written whole (pts_write), in both forms and in more records than
 * one of its pieces holds; one set writes the records as they are. */
#include "testutil.h"
#include "base/rng.h"
#include "cli/ptsio.h"
#include "cli/setsout.h"

enum { N = 1500, M = 3 };

/* Set s's record i: x, y and a value. */
static void record(unsigned s, size_t i, double *r)
{
	r[0] = frs_rand01(s + 1, FRS_STREAM_TEST, 2 * i);
	r[1] = frs_rand01(s + 1, FRS_STREAM_TEST, 2 * i + 1);
	r[2] = (double)i * 0.5 - 17;
}

/* The oracle: M sets (or one) packed with their set by hand. */
static void write_packed(const char *path, unsigned sets, int text)
{
	unsigned ncol = sets > 1 ? 4 : 3;
	struct frs_points p = { 2, ncol - 2, (size_t)N * sets, NULL,
	    { "v", "set" }, 0 };
	FILE *fp;

	p.x = malloc(p.n * ncol * sizeof *p.x);
	assert_non_null(p.x);
	for (unsigned s = 0; s < sets; s++)
		for (size_t i = 0; i < N; i++) {
			double *r = p.x + ((size_t)s * N + i) * ncol;
			record(s, i, r);
			if (sets > 1)
				r[3] = (double)s;
		}
	fp = fopen(path, "wb");
	assert_non_null(fp);
	assert_int_equal(pts_write(fp, path, &p, text), 0);
	assert_int_equal(fclose(fp), 0);
	free(p.x);
}

static void write_sets(const char *path, unsigned sets, int text)
{
	static const char *const nm[] = { "v" };
	struct sets_writer w;
	double *rec = malloc((size_t)N * 3 * sizeof *rec);
	FILE *fp = fopen(path, "wb");

	assert_true(rec != NULL && fp != NULL);
	assert_int_equal(sets_writer_begin(&w, fp, path, 2, 1, nm, sets,
	    (uint64_t)N * sets, text), 0);
	for (unsigned s = 0; s < sets; s++) {
		for (size_t i = 0; i < N; i++)
			record(s, i, rec + 3 * i);
		w.set = s;
		/* in two pieces, as a sampler's rounds come */
		assert_int_equal(sets_writer_put(&w, rec, 1000), 0);
		assert_int_equal(sets_writer_put(&w, rec + 3000, N - 1000), 0);
	}
	assert_int_equal(sets_writer_end(&w), 0);
	assert_int_equal(fclose(fp), 0);
	free(rec);
}

static void sets_file(void **state)
{
	(void)state;
	for (int text = 0; text <= 1; text++)
		for (unsigned sets = 1; sets <= M; sets += M - 1) {
			unsigned char *a, *b;
			size_t la, lb;
			write_packed(tu_path("packed"), sets, text);
			write_sets(tu_path("sets"), sets, text);
			a = tu_read(tu_path("packed"), &la);
			b = tu_read(tu_path("sets"), &lb);
			assert_int_equal(la, lb);
			assert_memory_equal(a, b, la);
			free(a);
			free(b);
		}
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(sets_file))
