/*
 * frs-sample's sets (sets.c): M sets of a 2-D map or 3-D volume drawn
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
	/* the matrix as frs-sample.c loaded it */
	int loaded;		/* 0: the run's opening loads it */
	frs_mask *mask;		/* taken by the run */
	int mask_rc;		/* frs_mask_load's code, its message: */
	frs_error mask_err;
	double tload;		/* seconds, counted in the run's setup */
	/* the map or volume as loaded, taken by the run */
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

/* Draw the sets and write them (--count-only: their counts, a line
 * each).  0; -1 after cli_fail. */
int sets_write(const struct sets *a, struct sets_run *run);

/* -v's report of a run (setsreport.c): set 0's setup, the tiles, the
 * sets' seeds, and the times of the steps; the program's, as the library
 * does not print. */
void sets_report(FILE *fp, const struct sets *a, const struct sets_run *run);

#endif
