/*
 * frs-sample -v's report of a run of sets (api_sets_open and
 * api_sets_write): set 0's setup, the tiles, the sets' seeds, and the
 * times of the steps.  The program's, not the library's: the library does
 * not print.
 */
#ifndef FRS_CLI_SETSREPORT_H
#define FRS_CLI_SETSREPORT_H

#include <stdio.h>

#include "api/api.h"

void cli_sets_report(FILE *fp, const struct api_sets *a,
    const struct api_sets_run *run);

#endif
