/*
 * frs-sample's runs (sets.c): M sets of a 2-D map or 3-D volume drawn
 * through the library's callback form and written to one points file,
 * and what came of them for the -v report (setsreport.c) and the
 * warnings.
 */
#ifndef FRS_SAMPLE_SETS_H
#define FRS_SAMPLE_SETS_H

#include <stdio.h>

#include "frs.h"

/* What frs-sample asks for: M sets of a 2-D map or 3-D volume, set i
 * with seed + i, written to one file (setsout.h: at most
 * SETS_MAX_POINTS samples in all). */
struct sets {
	unsigned dims;		/* the matrix's: 2 or 3 */
	const char *matrix, *imp;	/* imp NULL: constant */
	uint32_t size[3];	/* -s: the map's or volume's size */
	unsigned nsize;		/* sides given: 0, 1 (N), 2 or 3 */
	int flags;		/* frs_source_load's */
	struct frs_options opt;	/* its algorithm is alg's */
	enum frs_algorithm alg;	/* Sorted for flat1 */
	int flat1;		/* the device's Flat 1 (with a device only) */
	int cl, device;		/* OpenCL, its index (-1: the first) */
	uint64_t steps[16];
	unsigned nsteps;
	uint64_t seed, sets;
	int pdf, count_only, text, verbose;
	int level_col;		/* a column of each sample's level */
	const char *out;	/* NULL or "-": standard output */
	/* the matrix as sets_matrix loaded it */
	int loaded;		/* 0: sets_open loads it */
	frs_mask *mask;		/* taken by sets_open's run */
	int mask_rc;		/* frs_mask_load's code, its message: */
	frs_error mask_err;
	double tload;		/* seconds, counted in the run's setup */
	/* the map or volume as sets_map loaded it, taken by sets_open */
	struct frs_imap map;
	struct frs_imap_stats stats;	/* the map's, as checked */
	struct frs_vol vol;
};

/* What came of them, for the -v report and the warnings. */
struct sets_run {
	unsigned dims;
	frs_run *r;		/* set 0's run (frs_run_new) */
	struct frs_run_info info;	/* its setup of level 0 */
	struct frs_run_level lv[FRS_LEVELS_MAX];	/* and its levels */
	uint64_t lcount[FRS_LEVELS_MAX];	/* with -v: set 0's samples
						 * per level (lv's order) */
	double lreused[FRS_LEVELS_MAX];	/* and the share of them whose matrix
					 * element another of the level
					 * shows too (2-D), or -1 */
	const char *made_in;	/* a .frp that lacked lists made here */
	uint32_t made;		/* their block, 0 when none */
	double reused;		/* of set 0's samples: the share whose
				 * matrix element another shows too, or -1 */
	uint64_t total;
	double tsetup, tthr, tout, tnote;	/* seconds */
	struct frs_device_times ct;	/* OpenCL phases over the sets */
	const char *device;	/* the OpenCL device's name */
	const char *note;	/* frs_mask_note at load */
	/* inside */
	struct frs_options opt;	/* the sampler's */
	frs_mask *mask;
	frs_sampler *smp;
	frs_sampler3 *smp3;
	frs_device *dev;
};

/*
 * Take the matrix (sets_matrix's; standard input loaded here), load
 * the map or volume and the device, make the sampler and set 0's setup,
 * with the mask prepared for it (so that -v counts that in the setup,
 * with the matrix's loading); with FRS_RULE_EXACT the exact taus of set 0 only
 * with verbose (each set's run finds its own).  Warns of a stale twin
 * .frp and of patterns that repeat.  0; -1 after cli_fail; -2 when the
 * device could not be opened.
 */
int sets_open(const struct sets *a, struct sets_run *run);
/* Load a->matrix, opening it once, and set a->dims from its header (2
 * when it tells none); a failure is told by sets_open, where the
 * run needs the matrix.  Standard input is left to sets_open, which
 * may read a map from it before. */
void sets_matrix(struct sets *a);
/* Load the map or volume a->imp (NULL: constant) at a->size, a volume
 * when want is 3, a map when 2, and when 0 what a->imp is: its
 * dimensions, -1 after cli_fail. */
int sets_map(struct sets *a, unsigned want);
/* Load the default matrix for dims (frs_default_matrix) as sets_matrix
 * loads a named one: -1 when none is found, a->mask_err saying why. */
int sets_default_matrix(struct sets *a, unsigned dims);
void sets_unmap(struct sets *a);
/* Draw the sets and write them (--count-only: their counts, a line
 * each).  0; -1 after cli_fail. */
int sets_write(const struct sets *a, struct sets_run *run);
void sets_close(struct sets_run *run);

/* -v's report of a run (setsreport.c): set 0's setup, the tiles, the
 * sets' seeds, and the times of the steps; the program's, as the library
 * does not print. */
void sets_report(FILE *fp, const struct sets *a, const struct sets_run *run);

#endif
