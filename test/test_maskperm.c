/* One check of a mask's values: loading a .frd finds whether they are a
 * permutation in the pass that checks them (m.perm), a .frp and a
 * wrapped mask know it from their own check, and a matrix known to be
 * one is not checked again (the preparations ask frd_check_permutation,
 * which answers at once). */
#include "frsutil.h"
#include "frs.h"
#include "api/api.h"
#include "sample/frpio.h"

/* A w x h permutation (tu_perm_matrix), written to path; with dup, one
 * value repeated. */
static void write_perm(const char *path, uint32_t w, uint32_t h, int dup)
{
	struct frs_matrix m;
	FILE *fp;

	tu_perm_matrix(&m, w, h, 1);
	if (dup)
		m.v[7] = m.v[3];
	assert_non_null(fp = fopen(path, "wb"));
	assert_int_equal(frd_write(fp, path, &m), 0);
	assert_int_equal(fclose(fp), 0);
	frd_free(&m);
}

static void read_finds_it(void **state)
{
	const char *p = tu_path("p.frd"), *q = tu_path("q.frd");
	struct frs_matrix m;
	FILE *fp;
	(void)state;

	write_perm(p, 16, 8, 0);
	write_perm(q, 16, 8, 1);
	assert_non_null(fp = fopen(p, "rb"));
	assert_int_equal(frd_read_pre(fp, p, NULL, 0, &m, FRD_PERM_FIND), 0);
	fclose(fp);
	assert_int_equal(m.perm, 1);
	frd_free(&m);
	/* Without the ask, nothing is known. */
	assert_int_equal(frd_read(p, &m), 0);
	assert_int_equal(m.perm, 0);
	frd_free(&m);
	/* In range but repeated: read, not a permutation, and the check
	 * says why. */
	assert_non_null(fp = fopen(q, "rb"));
	assert_int_equal(frd_read_pre(fp, q, NULL, 0, &m, FRD_PERM_FIND), 0);
	fclose(fp);
	assert_int_equal(m.perm, 0);
	assert_int_equal(frd_check_permutation(&m, q), -1);
	assert_err_has(q, "not a permutation");
	frd_free(&m);
	/* Required: the read's own pass refuses it, saying why, and takes
	 * the permutation. */
	frs_clearerr();		/* the check's message is not the read's */
	assert_non_null(fp = fopen(q, "rb"));
	assert_int_equal(frd_read_pre(fp, q, NULL, 0, &m, FRD_PERM_NEED), -1);
	fclose(fp);
	assert_err_has(q, "not a permutation: value");
	assert_non_null(fp = fopen(p, "rb"));
	assert_int_equal(frd_read_pre(fp, p, NULL, 0, &m, FRD_PERM_NEED), 0);
	fclose(fp);
	assert_int_equal(m.perm, 1);
	frd_free(&m);
}

/* A matrix known to be a permutation is not scanned again: the flag is
 * the answer (the values stay as they were checked). */
static void known_is_not_rechecked(void **state)
{
	struct frs_matrix m;
	(void)state;

	assert_int_equal(frd_alloc(&m, 2, 4, 4, 1, ""), 0);
	assert_int_equal(frd_check_permutation(&m, "zeros"), -1);
	m.perm = 1;
	assert_int_equal(frd_check_permutation(&m, "zeros"), 0);
	frd_free(&m);
}

static void masks_know_it(void **state)
{
	const char *p = tu_path("p.frd"), *fp_path = tu_path("p.frp");
	struct frs_matrix m;
	frs_mask *mk;
	frs_error err;
	uint32_t *v;
	FILE *fp;
	unsigned dims = 9;
	(void)state;

	write_perm(p, 16, 16, 0);
	assert_int_equal(frs_mask_load_dims(&mk, p, &dims, &err), FRS_OK);
	assert_int_equal(dims, 2);
	assert_int_equal(mk->m.perm, 1);
	frs_mask_free(mk);
	/* A .frp, checked by its reader. */
	assert_int_equal(frd_read(p, &m), 0);
	assert_non_null(fp = fopen(fp_path, "wb"));
	assert_int_equal(frp_write(fp, fp_path, p, &m, 1, NULL, 0), 0);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_mask_load(&mk, fp_path, &err), FRS_OK);
	assert_int_equal(mk->m.perm, 1);
	frs_mask_free(mk);
	/* A wrapped one, checked by frs_mask_wrap. */
	v = malloc(m.n * sizeof *v);
	assert_non_null(v);
	memcpy(v, m.v, m.n * sizeof *v);
	assert_int_equal(frs_mask_wrap(&mk, v, 16, 16, &err), FRS_OK);
	assert_int_equal(mk->m.perm, 1);
	frs_mask_free(mk);
	free(v);
	frd_free(&m);
}

/* The dimension count of a .frd's header comes back also when the rest
 * of the file is refused (frs-sample's checks of options against the
 * matrix come before the matrix's own error). */
static void dims_of_a_bad_file(void **state)
{
	const char *p = tu_path("t.frd");
	unsigned char h[40] = "\211FRD\r\n\032\n";
	frs_mask *mk;
	frs_error err;
	unsigned dims = 0;
	FILE *fp;
	(void)state;

	h[8] = 1;
	h[12] = 3;
	h[16] = h[20] = h[24] = 4;
	assert_non_null(fp = fopen(p, "wb"));
	assert_int_equal(fwrite(h, 1, sizeof h, fp), sizeof h);
	assert_int_equal(fclose(fp), 0);
	assert_int_equal(frs_mask_load_dims(&mk, p, &dims, &err), FRS_E_FORMAT);
	assert_null(mk);
	assert_int_equal(dims, 3);
	assert_int_equal(frs_mask_load_dims(&mk, "/nonexistent.frd", &dims, &err),
	    FRS_E_IO);
	assert_int_equal(dims, 0);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(read_finds_it),
	cmocka_unit_test(known_is_not_rechecked),
	cmocka_unit_test(masks_know_it),
	cmocka_unit_test(dims_of_a_bad_file))
