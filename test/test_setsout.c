/* The sets writer of the samplers' --sets M: set i's records followed by
 * i in a column named set, the bytes of the same records packed by hand
 * and written whole (pts_write), in both forms and in more records than
 * one of its pieces holds; one set writes the records as they are.  The
 * same from columns apart (sets_writer_put_cols: the points packed, the
 * values in an array of their own), and its check of the coordinates. */
#include "testutil.h"
#include "base/io.h"
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

/* As a sampler writes them: records side by side, or (cols) the points
 * and the values in arrays apart. */
static void write_sets(const char *path, unsigned sets, int text, int cols)
{
	static const char *const nm[] = { "v" };
	struct sets_writer w;
	double *rec = malloc((size_t)N * 3 * sizeof *rec);
	double *xy = malloc((size_t)N * 2 * sizeof *xy);
	double *v = malloc((size_t)N * sizeof *v);
	FILE *fp = fopen(path, "wb");

	assert_true(rec != NULL && xy != NULL && v != NULL && fp != NULL);
	assert_int_equal(sets_writer_begin(&w, fp, path, 2, 1, nm, sets,
	    (uint64_t)N * sets, text), 0);
	for (unsigned s = 0; s < sets; s++) {
		for (size_t i = 0; i < N; i++) {
			record(s, i, rec + 3 * i);
			xy[2 * i] = rec[3 * i];
			xy[2 * i + 1] = rec[3 * i + 1];
			v[i] = rec[3 * i + 2];
		}
		w.set = s;
		/* in two pieces, as a sampler's rounds come, the first more
		 * than the writer gathers at once */
		if (cols) {
			const double *c0[] = { v }, *c1[] = { v + 1400 };
			assert_int_equal(sets_writer_put_cols(&w, xy, c0, 1400), 0);
			assert_int_equal(sets_writer_put_cols(&w, xy + 2800, c1,
			    N - 1400), 0);
		} else {
			assert_int_equal(sets_writer_put(&w, rec, 1400), 0);
			assert_int_equal(sets_writer_put(&w, rec + 4200, N - 1400),
			    0);
		}
	}
	assert_int_equal(sets_writer_end(&w), 0);
	assert_int_equal(fclose(fp), 0);
	free(rec);
	free(xy);
	free(v);
}

static void sets_file(void **state)
{
	(void)state;
	for (int text = 0; text <= 1; text++)
		for (unsigned sets = 1; sets <= M; sets += M - 1)
			for (int cols = 0; cols <= 1; cols++) {
				unsigned char *a, *b;
				size_t la, lb;
				write_packed(tu_path("packed"), sets, text);
				write_sets(tu_path("sets"), sets, text, cols);
				a = tu_read(tu_path("packed"), &la);
				b = tu_read(tu_path("sets"), &lb);
				assert_int_equal(la, lb);
				assert_memory_equal(a, b, la);
				free(a);
				free(b);
			}
}

/* A coordinate outside [0, 1) is refused by columns as by records: the
 * same message naming the point, before any of them is written. */
static void cols_checked(void **state)
{
	double xy[2 * N], v[N], rec[3 * N];
	const double *c[] = { v };
	char msg[2][256];

	(void)state;
	for (size_t i = 0; i < N; i++) {
		record(0, i, rec + 3 * i);
		xy[2 * i] = rec[3 * i], xy[2 * i + 1] = rec[3 * i + 1];
		v[i] = rec[3 * i + 2];
	}
	xy[2 * 1200 + 1] = rec[3 * 1200 + 1] = 1.0;
	for (int cols = 0; cols <= 1; cols++) {
		struct pts_writer w;
		FILE *fp = tmpfile();
		static const char *const nm[] = { "v" };
		assert_non_null(fp);
		assert_int_equal(pts_writer_begin(&w, fp, "t.pts", 2, 1, nm, N, 0),
		    0);
		assert_int_equal(cols ? pts_writer_put_cols(&w, xy, 2,
		    (const struct pts_col[]){ { c[0], 1 } }, N) :
		    pts_writer_put_n(&w, rec, N), -1);
		snprintf(msg[cols], sizeof msg[cols], "%s", frs_errmsg());
		assert_int_equal(w.written, 0);
		assert_int_equal(fflush(fp), 0);
		assert_true(ftell(fp) < 100);	/* the header alone */
		fclose(fp);
	}
	assert_string_equal(msg[0], msg[1]);
	assert_non_null(strstr(msg[1], "coordinate 1 of point 1200"));
}

/* Points a record of three apart whose third value is not the column
 * written: the column's values go out, not the third ones (a stride of
 * the records' width does not make them the records). */
static void cols_at_record_stride(void **state)
{
	static const char *const nm[] = { "v" };
	double pts[3 * 4], v[4], want[3 * 4], got[3 * 4];
	struct pts_writer w;
	FILE *fp = tmpfile();
	long at;

	(void)state;
	assert_non_null(fp);
	for (int i = 0; i < 4; i++) {
		pts[3 * i] = want[3 * i] = 0.125 * i;
		pts[3 * i + 1] = want[3 * i + 1] = 0.5;
		pts[3 * i + 2] = -1.0;
		v[i] = want[3 * i + 2] = 10.0 + i;
	}
	assert_int_equal(pts_writer_begin(&w, fp, "t.pts", 2, 1, nm, 4, 0), 0);
	at = ftell(fp);
	assert_int_equal(pts_writer_put_cols(&w, pts, 3,
	    (const struct pts_col[]){ { v, 1 } }, 4), 0);
	assert_int_equal(fseek(fp, at, SEEK_SET), 0);
	assert_int_equal(fread(got, sizeof got, 1, fp), 1);
	io_le_f64(got, 12);	/* the file's little-endian doubles */
	assert_memory_equal(got, want, sizeof want);
	fclose(fp);
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(sets_file),
	cmocka_unit_test(cols_checked),
	cmocka_unit_test(cols_at_record_stride))
