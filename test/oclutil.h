/* The OpenCL device of the OpenCL tests (PoCL in make check), opened
 * once per test binary by the group setup. */
#ifndef FRS_TEST_OCLUTIL_H
#define FRS_TEST_OCLUTIL_H

#include "testutil.h"
#include "base/ocl.h"

static struct ocl tu_ocl;

/* Group setup and teardown: tu_ocl on the default device. */
static inline int tu_ocl_setup(void **state)
{
	(void)state;
	if (ocl_open(&tu_ocl, -1) != 0) {
		fprintf(stderr, "%s\n", frs_errmsg());
		return -1;
	}
	return 0;
}

static inline int tu_ocl_teardown(void **state)
{
	(void)state;
	ocl_close(&tu_ocl);
	return 0;
}

#endif
