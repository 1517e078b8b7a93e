/*
 * Inside the public API (src/lib/frs.h): the handles' contents and the
 * pieces the programs share with it.  The programs use the public API
 * for everything it covers; what it does not cover (OpenCL devices, the
 * -v report) reaches these.  frs-sample's 3-D path calls frs3.h itself:
 * it writes each set as it comes, which the 3-D draws (whole buffers,
 * no callback form) would make it compute twice; test_api checks that
 * both give the same bytes.
 */
#ifndef FRS_API_H
#define FRS_API_H

#include <pthread.h>

#include "frs.h"
#include "sample/frs3.h"
#include "sample/frscore.h"
#include "sample/hsw.h"

struct old_lists {
	struct frs_prep p;
	struct old_lists *next;
};

struct frs_mask {
	struct frs_matrix m;
	int wrapped;		/* m.v is the caller's */
	char *name;		/* the path it was loaded from, for messages */
	char *frp;		/* prepared file to take sorted lists from */
	int twin;		/* frp lies beside the .frd loaded */
	char note[1024];
	pthread_mutex_t lock;	/* over the lazily made parts below */
	unsigned nlev;		/* minmap levels, lev[0] = m.v */
	uint32_t *lev[32];
	struct frs_prep lists[32];	/* sorted lists by log2(block) */
	struct old_lists *old;	/* lists a later run outgrew: views of
				 * other threads may still read them */
	uint32_t made;		/* a block size frp lacked, made here */
	struct frs3_prep p3[32];	/* 3-D sorted lists by log2(block) */
};

struct frs_sampler {
	const frs_mask *mask;
	struct frs_imap map;
	struct frs_options opt;
};

struct frs_sampler3 {
	const frs_mask *mask;
	struct frs_vol vol;
	struct frs_options opt;
};

struct frs_hsw {
	struct hsw_tree t;
	struct frs_imap map;
};

/* Samples per wave of frs_draw_each with Sorted and one step (a wave:
 * the chunks thresholded in parallel before the callback takes them);
 * tests lower it to cross wave boundaries. */
extern uint64_t api_wave;

/* The setup of n samples with this seed, options applied; -1 after
 * frs_fail. */
int api_setup(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_setup *su);
/* api_setup for steps, and with FRS_RULE_EXACT the exact taus of the
 * steps (api_exact): the setup every run of the sampler uses. */
int api_setup_steps(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, struct frs_setup *su);
/* su->exact for steps (the last su->n) by Sorted's count passes, whose
 * lists it makes in the mask; su->tau the last step's. */
int api_exact(const frs_sampler *s, const uint64_t *steps, unsigned nsteps,
    struct frs_setup *su);
/* A view of the mask prepared for an implementation: the minmap and the
 * sorted lists of block (0: none) holding at least the values below
 * below (FRS_ALL_VALUES: all), made on first use and kept. */
int api_mask_prep(const frs_mask *mk, int minmap, uint32_t block,
    uint64_t below, struct frs_prep *view);
/* Whether lists of the values below `below` are read from a .frp that
 * has them (frs_prepare_below makes fewer faster). */
int api_lists_from_frp(const struct frs_matrix *m, uint64_t below);
/* The values Sorted's lists need for the last of steps: frs_lim_most. */
uint64_t api_lists_below(const struct frs_setup *su, const uint64_t *steps,
    unsigned nsteps);
const struct frs_matrix *api_mask_matrix(const frs_mask *mk);
/* The block of the sorted lists that a setup uses. */
uint32_t api_sorted_block(const struct frs_setup *su);
/* Whether Sorted wants the minmap too: its blocks are smaller than a
 * pixel (shuffled tiles), and the minmap skips dark pixels and blocks. */
int api_sorted_minmap(const struct frs_setup *su);
/* A sample's density I / mean I. */
/* A result's samples to fn in frs_draw_each's batches and order (the
 * steps in turn, each in map order); FRS_OK, FRS_E_NOMEM, or
 * FRS_E_CALLBACK when fn returned non-zero. */
int api_result_each(const struct frs_setup *su, const struct frs_imap *map,
    const struct frs_result *r, unsigned nsteps, int want_pdf,
    frs_point_fn fn, void *ctx);
double api_pdf(const struct frs_setup *su, const struct frs_imap *map,
    const struct frs_elem *e);
/* The default matrix of dims 2 or 3 (frs_default_matrix): $FRS_MATRIX
 * or $FRS_MATRIX3 when set and not empty, as it is; else default.frd or
 * default3.frd where datadir.h finds it.  Its path into path (cap
 * bytes): 0; -1 after frs_fail ("looked for ..." or "... too long"). */
int api_default_matrix(unsigned dims, char *path, size_t cap);
/* The densities of n warped points. */
void api_hsw_pdf(const struct hsw_tree *t, const struct frs_imap *map,
    const double *xy, double *pdf, size_t n);

#endif
