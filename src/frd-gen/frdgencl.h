/*
 * Forced Random Dithering matrices with OpenCL (frd-gen --device cl).
 *
 * The same matrix as frdgen_run, byte for byte, for the same parameters:
 * the device keeps the force field, adds the force of every insertion
 * (entries of a force table computed on the host, one add per cell and
 * insertion, in insertion order, FP_CONTRACT OFF) and finds the minimum
 * and the zero count of every tile it touched; the host keeps those in a
 * min-tree and a Fenwick tree and makes every random choice (Geometric
 * rank, tie keys, zero-field draws) with the functions of frdgen.h.
 * One kernel launch and one transfer back per insertion (the minima,
 * zero counts and cells of the touched tiles), so a CPU device (PoCL)
 * is several times slower than frdgen_run: the round trip dominates.
 *
 * Needs a device with cl_khr_fp64.  Checkpoints are not supported
 * (par->checkpoint must be NULL).
 */
#ifndef FRS_FRDGENCL_H
#define FRS_FRDGENCL_H

#include "frd-gen/frdgen.h"
#include "cli/cli.h"

/* Generate on an open device; out is allocated.  task (cli.h) may be
 * NULL. */
int frdgen_run_cl(const struct frdgen_params *par, struct ocl *o,
    struct frs_matrix *out, struct cli_task *task);

#endif
