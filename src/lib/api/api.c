/*
 * The public API (src/lib/frs.h, libfrs(3)) over the library's own
 * modules: errors, version and options here, the rest in the files
 * api.h lists.  The internal functions report through the per-thread
 * message of err.c; here it becomes a code and the caller's frs_error.
 */
#define _POSIX_C_SOURCE 200809L
#include "frs.h"

#include <stdio.h>

#include "api/api.h"
#include "api/version.h"
#include "base/err.h"
#include "base/io.h"
#include "base/par.h"
#include "base/progress.h"
#include "sample/frscl.h"

/* ---- errors ---------------------------------------------------------- */

static const char *const code_names[] = {
	"FRS_OK", "FRS_E_ARG", "FRS_E_MAP", "FRS_E_BUFFER", "FRS_E_NOMEM",
	"FRS_E_IO", "FRS_E_FORMAT", "FRS_E_LIMIT", "FRS_E_CALLBACK"
};

const char *frs_code_name(int code)
{
	if (code < 0 || code >= (int)(sizeof code_names / sizeof code_names[0]))
		return "FRS_E_UNKNOWN";
	return code_names[code];
}

const char *frs_library_version(void)
{
	return FRS_VERSION;
}

/* frs_progress_fn and progress.h's progress_fn are the same type. */
void frs_set_progress(frs_progress_fn fn, void *ctx)
{
	progress_set(fn, ctx);
}

int api_set_err(frs_error *err, enum frs_code code, const char *msg)
{
	if (err != NULL) {
		err->code = code;
		snprintf(err->message, sizeof err->message, "%s", msg);
	}
	return (int)code;
}

int api_arg_err(frs_error *err, const char *what)
{
	return api_set_err(err, FRS_E_ARG, what);
}

int api_lib_err(frs_error *err, enum frs_code code)
{
	if (frs_errkind() == FRS_ERRKIND_MEM)
		code = FRS_E_NOMEM;
	else if (frs_errkind() == FRS_ERRKIND_MAP)
		code = FRS_E_MAP;
	else if (frs_errkind() == FRS_ERRKIND_IO)
		code = FRS_E_IO;
	return api_set_err(err, code, frs_errmsg());
}

int api_ok(frs_error *err)
{
	return api_set_err(err, FRS_OK, "");
}

int api_nomem(frs_error *err)
{
	return api_set_err(err, FRS_E_NOMEM, "out of memory");
}

/* ---- options --------------------------------------------------------- */

void frs_options_init(struct frs_options *opt)
{
	*opt = (struct frs_options){ .sigma = 8.0, .algorithm = FRS_ALG_SORTED,
	    .jitter = FRS_JIT_NONE, .rule = FRS_RULE_UNBIASED, .threads = 1,
	    .tiling = FRS_TILING_LEVELS, .level_blur = 0.0 };
}

static int check_options(const struct frs_options *o, frs_error *err)
{
	if (!(o->sigma >= 1.0 && o->sigma <= FRS_SIGMA_MAX))
		return api_arg_err(err, "options: sigma must lie in [1, 1024]");
	if ((unsigned)o->algorithm > FRS_ALG_LEVEL2)
		return api_arg_err(err, "options: unknown algorithm");
	if ((unsigned)o->jitter > FRS_JIT_RANDOM)
		return api_arg_err(err, "options: unknown jitter");
	if ((unsigned)o->rule > FRS_RULE_EXACT)
		return api_arg_err(err, "options: unknown rule");
	if ((unsigned)o->tiling > FRS_TILING_PLAIN)
		return api_arg_err(err, "options: unknown tiling");
	if (!(o->level_blur >= 0.0 && o->level_blur <= FRS_LEVEL_BLUR_MAX))
		return api_arg_err(err, "options: level_blur must lie in [0, 1e4]");
	if (o->threads < 0 || o->threads > 1024)
		return api_arg_err(err, "options: threads must lie in 0 .. 1024");
	return FRS_OK;
}

/* The caller's options, with the zeros that stand for a default made
 * the default (sigma 0: 8; threads 0: 1; the enums' 0 and level_blur 0
 * are their defaults as they are), so that a zeroed structure is an
 * initialised one. */
int api_options(struct frs_options *o, const struct frs_options *opt,
    frs_error *err)
{
	if (opt != NULL)
		*o = *opt;
	else
		frs_options_init(o);
	if (o->sigma == 0.0)
		o->sigma = 8.0;
	return check_options(o, err);
}

static int check_steps(const uint64_t *steps, unsigned nsteps,
    frs_error *err)
{
	if (steps == NULL || nsteps == 0 || nsteps > 16)
		return api_arg_err(err, "steps: 1 to 16 counts");
	for (unsigned k = 0; k < nsteps; k++)
		if (steps[k] == 0 || (k > 0 && steps[k] <= steps[k - 1]))
			return api_arg_err(err, "steps: counts must be positive "
			    "and increase");
	if (steps[nsteps - 1] > API_MAX_N)
		return api_set_err(err, FRS_E_LIMIT, "n: more than 2^40 samples");
	return FRS_OK;
}

int api_run_begin(int have_s, int threads, const uint64_t *steps,
    unsigned nsteps, frs_error *err)
{
	int rc;

	if (!have_s)
		return api_arg_err(err, "NULL sampler");
	if ((rc = check_steps(steps, nsteps, err)) != FRS_OK)
		return rc;
	frs_set_threads(threads > 0 ? threads : 1);
	return FRS_OK;
}

int api_query_args(const char *fn, int have_args, uint64_t n, int threads,
    frs_error *err)
{
	char msg[96];

	if (!have_args) {
		snprintf(msg, sizeof msg, "%s: NULL argument", fn);
		return api_arg_err(err, msg);
	}
	if (n == 0) {
		snprintf(msg, sizeof msg, "%s: n must not be 0", fn);
		return api_arg_err(err, msg);
	}
	if (n > API_MAX_N)
		return api_set_err(err, FRS_E_LIMIT, "n: more than 2^40 samples");
	frs_set_threads(threads > 0 ? threads : 1);
	return FRS_OK;
}

/* ---- the enums: public to internal, the one table of each ----------- */

/* The programs' words for the public enums, in their order (the
 * algorithms' are the implementations' of frscore.h). */
static const char *const algo_words[] = { FRS_ALGO_NAMES, NULL };
static const char *const jitter_words[] = { "none", "halton", "random",
    NULL };
static const char *const rule_words[] = { "unbiased", "thesis", NULL };
static const char *const tiling_words[] = { "levels", "shuffled", "plain",
    NULL };
static const char *const hsw_input_words[] = { "random", "regular",
    "jittered", "halton", "hammersley", NULL };

const char *const *frs_names(enum frs_names which)
{
	switch (which) {
	case FRS_NAMES_ALGORITHM: return algo_words;
	case FRS_NAMES_JITTER: return jitter_words;
	case FRS_NAMES_RULE: return rule_words;
	case FRS_NAMES_TILING: return tiling_words;
	case FRS_NAMES_HSW_INPUT: return hsw_input_words;
	}
	return NULL;
}

/* One vocabulary: the public algorithms are the implementations' values
 * (enum frs_impl), so that a public value is taken as it is. */
_Static_assert((int)FRS_ALG_SORTED == (int)FRS_SORTED &&
    (int)FRS_ALG_NAIVE == (int)FRS_NAIVE &&
    (int)FRS_ALG_STACK == (int)FRS_STACK &&
    (int)FRS_ALG_LEVEL1 == (int)FRS_LEVEL1 &&
    (int)FRS_ALG_LEVEL2 == (int)FRS_LEVEL2, "enum frs_algorithm is enum frs_impl");

/* The jitter modes, the rules and the tilings are the samplers' too,
 * value for value: a setup takes the options as they are (API_MODES). */
_Static_assert((int)FRS_JIT_NONE == (int)FRS_PLACE_CENTRE &&
    (int)FRS_JIT_HALTON == (int)FRS_PLACE_HALTON &&
    (int)FRS_JIT_RANDOM == (int)FRS_PLACE_RANDOM,
    "enum frs_jitter_mode is enum frs_place");
_Static_assert((int)FRS_RULE_UNBIASED == (int)FRS_UNBIASED &&
    (int)FRS_RULE_THESIS == (int)FRS_THESIS &&
    (int)FRS_RULE_EXACT == (int)FRS_EXACT, "enum frs_rule_mode is enum frs_rule");
_Static_assert((int)FRS_TILING_LEVELS == (int)FRS_TILES_LEVELS &&
    (int)FRS_TILING_SHUFFLED == (int)FRS_TILES_SHUFFLE &&
    (int)FRS_TILING_PLAIN == (int)FRS_TILES_PLAIN,
    "enum frs_tiling_mode is enum frs_tiling");
