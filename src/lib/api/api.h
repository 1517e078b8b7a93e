/*
 * Inside the public API (src/lib/frs.h): the handles' contents, the
 * pieces the files of api/ share, and what the programs reach beyond the
 * public API (OpenCL devices, the 3-D callback form, the -v report).
 *
 * api.c: errors, options and the enum tables; mask.c: masks and their
 * prepared lists; prep.c: preparing matrices (frd-prep's work, public
 * since 2.2); map.c: maps, volumes and the samplers made of them;
 * draw.c, draw3.c: the 2-D and 3-D draws; store.c: a run's samples to
 * the caller (both); hsw.c: HSW; source.c: map and volume sources,
 * their checks and writers.
 */
#ifndef FRS_API_H
#define FRS_API_H

#include <pthread.h>
#include <stdio.h>

#include "frs.h"
#include "base/ocl.h"
#include "sample/frs3.h"
#include "sample/frscore.h"
#include "sample/hsw.h"
#include "sample/levels.h"

struct old_lists {
	struct frs_prep p;
	struct old_lists *next;
};

struct frs_mask {
	struct frs_matrix m;
	int wrapped;		/* m.v is the caller's */
	char *name;		/* the path it was loaded from, for messages */
	char *frp;		/* prepared file to take sorted lists from */
	FILE *frp_fp;		/* it, kept open since the load (a regular
				 * file), or NULL: opened again */
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

/* The last plan of levels a sampler made (lev.c): the sets of a run
 * share it, as they share their count. */
struct api_plan {
	pthread_mutex_t lock;
	int valid;
	double t0;		/* its key: level 0's threshold scale */
	uint32_t ns;		/* and n_s */
	struct frs_levels plan;
};

/* An OpenCL device (device.c) and the phases of its draws, summed. */
struct frs_device {
	struct ocl o;
	struct frs_device_times spent;
};
/* frs_sample_cl on the sampler's device, its phases added to it. */
int api_sample_cl(const frs_sampler *s, const struct frs_setup *su,
    const struct frs_imap *map, const struct frs_prep *p,
    const uint64_t *steps, unsigned nsteps, int count_only,
    struct frs_result *r);

struct frs_sampler {
	const frs_mask *mask;
	struct frs_imap map;
	struct frs_cells cells;	/* the map's frs_cell_stats, made once */
	int have_cells;		/* 0: each setup makes them (and fails) */
	struct frs_options opt;
	int algo;		/* enum frs_impl, FRS_FLAT1 on a device only */
	frs_device *dev;	/* frs_sampler_set_device's, or NULL */
	struct api_plan plan;
};

struct frs_sampler3 {
	const frs_mask *mask;
	struct frs_vol vol;
	struct frs_options opt;
	struct api_plan plan;
};

struct frs_hsw {
	struct hsw_tree t;
	struct frs_imap map;
};

/* ---- errors and options (api.c) ------------------------------------ */

/* The caller's frs_error (when not NULL) set to code and msg; code. */
int api_set_err(frs_error *err, enum frs_code code, const char *msg);
/* FRS_E_ARG with a message of our own. */
int api_arg_err(frs_error *err, const char *what);
/* The library's last message as code (NOMEM when the memory ceiling or
 * an allocation failed, MAP for a bad map, IO for a file that does not
 * open, whatever code the caller expected else). */
int api_lib_err(frs_error *err, enum frs_code code);
int api_ok(frs_error *err);
int api_nomem(frs_error *err);
/* The caller's options (NULL: the defaults) into o, checked.  A code. */
int api_options(struct frs_options *o, const struct frs_options *opt,
    frs_error *err);
/* The options' rule, jitter and tiling into a 2-D or 3-D setup, as they
 * are (api.c asserts that the values are the samplers'). */
#define API_MODES(su, o) do {						\
	(su)->rule = (enum frs_rule)(o)->rule;				\
	(su)->jitter = (enum frs_place)(o)->jitter;			\
	(su)->tiles = (enum frs_tiling)(o)->tiling;			\
} while (0)
/* What every run checks first: a sampler (have_s), 1 to 16 increasing
 * counts, at most 2^40; then the sampler's threads are set.  A code. */
int api_run_begin(int have_s, int threads, const uint64_t *steps,
    unsigned nsteps, frs_error *err);
/* frs_sampler_info's and the draws' limit. */
#define API_MAX_N ((uint64_t)1 << 40)
/* The checks of frs_sampler_info and frs_sampler_levels (fn in
 * messages): the pointers they need (have_args), n from 1 to API_MAX_N;
 * then the sampler's threads are set.  A code. */
int api_query_args(const char *fn, int have_args, uint64_t n, int threads,
    frs_error *err);


/* ---- masks (mask.c) ------------------------------------------------ */

/* A view of the mask prepared for an implementation: the minmap and the
 * sorted lists of block (0: none) holding at least the values below
 * below (FRS_ALL_VALUES: all), made on first use and kept. */
int api_mask_prep(const frs_mask *mk, int minmap, uint32_t block,
    uint64_t below, struct frs_prep *view);
/* The 3-D sorted lists of block size b (0: none), made on first use and
 * kept in the mask. */
int api_mask_prep3(const frs_mask *mk, uint32_t b, struct frs3_prep *view);
/* Whether lists of the values below `below` are read from a .frp that
 * has them (frs_prepare_below makes fewer faster). */
int api_lists_from_frp(const struct frs_matrix *m, uint64_t below);
/* The default matrix of dims 2 or 3 (frs_default_matrix): $FRS_MATRIX
 * or $FRS_MATRIX3 when set and not empty, as it is; else default.frd or
 * default3.frd where datadir.h finds it.  Its path into path (cap
 * bytes): 0; -1 after frs_fail ("looked for ..." or "... too long"). */
int api_default_matrix(unsigned dims, char *path, size_t cap);

/* ---- maps and volumes (map.c) -------------------------------------- */

/* The caller's map (floats f, doubles d, or constant 1 when both are
 * NULL) as the library's, validated with imap_validate's flags. */
int api_copy_map(struct frs_imap *m, const float *f, const double *d,
    uint32_t w, uint32_t h, size_t stride, int flags,
    struct frs_imap_stats *st, frs_error *err);
/* The caller's values for a sampler: floats f or doubles d (both NULL:
 * constant 1) of a w x h map, rows stride apart (0: w), or with depth
 * not 0 a w x h x depth volume, x fastest. */
struct api_values {
	const float *f;
	const double *d;
	uint32_t w, h, depth;
	size_t stride;
	/* Or a map the library loaded and validated itself (imap_load):
	 * taken over as it is, neither copied nor checked again; zeroed
	 * when the sampler has it. */
	struct frs_imap *own;
	const struct frs_imap_stats *own_stats;	/* its, as checked */
};
/* frs_sampler_new (dims 2, into *s2) and frs_sampler3_new (3, *s3): the
 * checks, the values copied and validated (or own taken).  A code; the
 * sampler NULL on failure. */
int api_sampler_make(unsigned dims, const frs_mask *mask,
    const struct api_values *v, const struct frs_options *opt,
    frs_sampler **s2, frs_sampler3 **s3, frs_error *err);
/* frs_sampler_free and frs_sampler3_free. */
void api_sampler_free(frs_sampler *s2, frs_sampler3 *s3);

/* ---- the levels of a run (lev.c) ----------------------------------- */

/*
 * The levels of a 2-D run (sample/levels.h): the setup and the map of
 * every level that has pixels, finest first.  A run of one level (plain
 * or shuffled tiles, or a map whose pixels all stay at level 0) has level
 * 0's setup, the thesis's; else each level's setup takes only the pixels
 * that the plan gives it.  Every level reads the sampler's map.  base is
 * level 0's
 * setup (frs_sampler_info's) whether level 0 has pixels or not.
 */
struct api_lev2 {
	unsigned n;
	struct frs_setup base;
	struct frs_setup su[FRS_LEVELS_MAX];
	struct frs_imap map;	/* the sampler's, for every level */
	struct frs_levels plan;	/* lev NULL with one level; the levels'
				 * setups point to it */
	uint32_t block[FRS_LEVELS_MAX];	/* Sorted's lists (api_lev2_block) */
};
/* The levels of level 0's setup s0 (for n, without exact taus) over the
 * sampler's map under the options o; the plan from cache when it has
 * the same, else made and kept there.  -1 after frs_fail. */
int api_lev2_make(const struct frs_options *o, const struct frs_setup *s0,
    const struct frs_imap *map, struct api_plan *cache, struct api_lev2 *lv);
void api_lev2_free(struct api_lev2 *lv);
/* The window elements of non-zero importance over the levels (exact
 * counts' most). */
uint64_t api_lev2_most(const struct api_lev2 *lv);
/* Level 0's exact taus x into every level (each takes 4^l times them). */
void api_lev2_exact(struct api_lev2 *lv, const struct frs_xtau *x);
/* The block of Sorted's lists for level i, or 0 for none (the level
 * scans or walks its pixels, frs_sorted_walk, which costs less than
 * making the lists for a window of few elements). */
uint32_t api_lev2_block(const struct api_lev2 *lv, unsigned i);
/* The values the lists must hold for the last of steps, tau times
 * margin: the most over the levels that read them (one block size). */
uint64_t api_lev2_below(const struct api_lev2 *lv, const uint64_t *steps,
    unsigned nsteps, double margin);

/* The same in 3-D, over voxels, with 8^l. */
struct api_lev3 {
	unsigned n;
	struct frs3_setup base;
	struct frs3_setup su[FRS_LEVELS_MAX];
	struct frs_vol vol;	/* the sampler's, for every level */
	struct frs_levels plan;
};
int api_lev3_make(const struct frs_options *o, const struct frs3_setup *s0,
    const struct frs_vol *vol, struct api_plan *cache, struct api_lev3 *lv);
/* A sampler's cache of plans (cache may be NULL: none), made and
 * released with the sampler. */
int api_plan_init(struct api_plan *c);
void api_plan_free(struct api_plan *c);
void api_lev3_free(struct api_lev3 *lv);
uint64_t api_lev3_most(const struct api_lev3 *lv);
void api_lev3_exact(struct api_lev3 *lv, const struct frs_xtau *x);

/* ---- a run's samples to the caller (store.c) ----------------------- */

/* One run of a 2-D or 3-D sampler: its levels (lv or lv3, as dims says,
 * owned) and the stored elements of each. */
struct api_store {
	unsigned dims, nsteps, nparts;
	uint64_t count;
	struct api_lev2 *lv;
	struct frs_result r[FRS_LEVELS_MAX];
	struct api_lev3 *lv3;
	struct frs3_result r3[FRS_LEVELS_MAX];
};

/* The rest of st once the runs of its first nparts levels are made. */
void api_store_set(struct api_store *st, unsigned dims, unsigned nsteps,
    unsigned nparts);
/* Release the runs and the levels. */
void api_store_free(struct api_store *st);
/* Run sampler s (a frs_sampler or frs_sampler3) for steps with this
 * seed into st.  A code. */
typedef int (*api_run_fn)(const void *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int count_only, struct api_store *st,
    frs_error *err);

/* The draws of a sampler by its run function, named fn in messages:
 * frs_draw_progressive's buffers (and frs_draw3_progressive's),
 * frs_count's count, and frs_draw_each's batches (points of st->dims
 * coordinates each). */
int api_draw(api_run_fn run, const void *s, const char *fn,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, double *p,
    double *pdf, uint32_t *step, size_t cap, size_t *count, frs_error *err);
int api_count(api_run_fn run, const void *s, const char *fn, uint64_t n,
    uint64_t seed, uint64_t *count, frs_error *err);
int api_each(api_run_fn run, const void *s, const char *fn,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int want_pdf,
    frs_point_fn cb, void *ctx, frs_error *err);
/* The most samples of one call of frs_draw_each's callback. */
#define API_BATCH 4096
/* frs_draw's checks of its arguments, and its FRS_E_BUFFER. */
int api_draw_args(const char *fn, const double *p, size_t cap,
    size_t *count, frs_error *err);
int api_too_small(const char *fn, frs_error *err);

/* Samples per wave of frs_draw_each with Sorted and one step (a wave:
 * the chunks thresholded in parallel before the callback takes them);
 * tests lower it to cross wave boundaries. */
extern uint64_t api_wave;

/* ---- 2-D sampling (draw.c) ----------------------------------------- */

/* The setup of n samples with this seed, options applied; -1 after
 * frs_fail. */
int api_setup(const frs_sampler *s, uint64_t n, uint64_t seed,
    struct frs_setup *su);
/* api_setup for the last of steps, its levels, and with FRS_RULE_EXACT
 * and taus the exact taus of the steps (api_exact): what every run of the
 * sampler uses (taus 0: a report's setup without the count passes).  -1
 * after frs_fail; lv to be released with api_lev2_free. */
int api_setup_steps(const frs_sampler *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int taus, struct api_lev2 *lv);
/* The levels' exact taus for steps (the last lv->su[0].n) by Sorted's
 * count passes over all levels, whose lists it makes in the mask. */
int api_exact(const frs_sampler *s, const uint64_t *steps, unsigned nsteps,
    struct api_lev2 *lv);
/* The mask prepared for the sampler's runs of level i of lv (minmap,
 * sorted lists): what a run prepares first.  -1 after frs_fail (naming
 * the matrix). */
int api_sampler_prep(const frs_sampler *s, const struct api_lev2 *lv,
    unsigned i, const uint64_t *steps, unsigned nsteps,
    struct frs_prep *view);

/* The values Sorted's lists need for the last of steps: frs_lim_most. */
uint64_t api_lists_below(const struct frs_setup *su, const uint64_t *steps,
    unsigned nsteps);
/* The block of the sorted lists that a setup uses. */
uint32_t api_sorted_block(const struct frs_setup *su);
/* A sample's density I / mean I. */
double api_pdf(const struct frs_setup *su, const struct frs_imap *map,
    const struct frs_elem *e);

/* ---- 3-D sampling (draw3.c) ---------------------------------------- */

/* The levels of the steps with this seed, options applied, with
 * FRS_RULE_EXACT and exact their exact taus (whose passes prepare the
 * mask's lists); -1 after frs_fail, lv to be released with
 * api_lev3_free. */
int api_setup3(const frs_sampler3 *s, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int exact, struct api_lev3 *lv);
/* The mask's lists for the sampler's runs of su. */
int api_sampler3_prep(const frs_sampler3 *s, const struct frs3_setup *su,
    struct frs3_prep *view);

#endif
