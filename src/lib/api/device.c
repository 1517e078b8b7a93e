/*
 * OpenCL devices (frs.h's frs_device_*): a sampler's draws on a device
 * (sample/frscl.c), the same samples as on the CPU, and the seconds
 * each phase of them took, summed per device.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdlib.h>

#include "api/api.h"
#include "base/err.h"
#include "sample/frscl.h"

int frs_device_open(frs_device **dev, int index, frs_error *err)
{
	frs_device *d;

	if (dev == NULL)
		return api_arg_err(err, "frs_device_open: NULL argument");
	*dev = NULL;
	if (index < -1)
		return api_arg_err(err, "frs_device_open: index below -1");
	if ((d = calloc(1, sizeof *d)) == NULL)
		return api_nomem(err);
	if (ocl_open(&d->o, index) < 0) {
		free(d);
		return api_lib_err(err, FRS_E_IO);
	}
	*dev = d;
	return api_ok(err);
}

const char *frs_device_name(const frs_device *dev)
{
	return dev != NULL ? dev->o.name : NULL;
}

void frs_device_free(frs_device *dev)
{
	if (dev == NULL)
		return;
	frscl_release(&dev->o);	/* the program it keeps for the device */
	ocl_close(&dev->o);
	free(dev);
}

void frs_device_times(const frs_device *dev, struct frs_device_times *t)
{
	*t = dev != NULL ? dev->spent : (struct frs_device_times){ 0, 0, 0, 0 };
}

int frs_sampler_set_device(frs_sampler *s, frs_device *dev, int flags,
    frs_error *err)
{
	if (s == NULL)
		return api_arg_err(err, "frs_sampler_set_device: NULL argument");
	if (flags & ~FRS_DEVICE_FLAT1 || (flags && dev == NULL))
		return api_arg_err(err, "frs_sampler_set_device: unknown flags, "
		    "or flags without a device");
	s->dev = dev;
	s->algo = flags & FRS_DEVICE_FLAT1 ? FRS_FLAT1 : (int)s->opt.algorithm;
	return api_ok(err);
}

int api_sample_cl(const frs_sampler *s, const struct frs_setup *su,
    const struct frs_imap *map, const struct frs_prep *p,
    const uint64_t *steps, unsigned nsteps, int count_only,
    struct frs_result *r)
{
	struct frscl_times t;
	struct frs_device_times *sum = &s->dev->spent;
	int rc = frs_sample_cl(&s->dev->o, su, map, p, s->algo, steps, nsteps,
	    count_only, r);

	frscl_last_times(&t);
	sum->build += t.build;
	sum->upload += t.upload;
	sum->kernel += t.kernel;
	sum->download += t.download;
	return rc;
}
