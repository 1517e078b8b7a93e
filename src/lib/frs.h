/*
 * libfrs: Forced Random Sampling in-process.  See libfrs(3).
 *
 * Opaque handles, no global state (but for each thread's progress
 * callback, off unless set): every function reports failure as a code,
 * with a message in the caller's frs_error when one is given; nothing
 * prints, nothing exits.  Thread safety is stated per function;
 * in short, a handle is built by one thread and then read by any number
 * at once, each with its own output buffers.
 */
#ifndef FRS_PUBLIC_H
#define FRS_PUBLIC_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FRS_API_VERSION_MAJOR 2
#define FRS_API_VERSION_MINOR 2

/* ---- errors ---------------------------------------------------------- */

enum frs_code {
	FRS_OK = 0,
	FRS_E_ARG,	/* a bad argument: NULL, a zero size, out of range */
	FRS_E_MAP,	/* the map: NaN, infinite, negative or all zero */
	FRS_E_BUFFER,	/* the caller's buffer is too small */
	FRS_E_NOMEM,	/* out of memory, or above the ceiling FRS_MAX_MEM */
	FRS_E_IO,	/* a file could not be opened or read */
	FRS_E_FORMAT,	/* a file is not what it should be */
	FRS_E_LIMIT,	/* a size beyond what the method supports */
	FRS_E_CALLBACK	/* the caller's callback asked to stop */
};

typedef struct frs_error {
	enum frs_code code;
	char message[512];	/* "context: problem", or "" */
} frs_error;

/* "FRS_E_ARG" and so on; thread-safe. */
const char *frs_code_name(int code);
/* The release, "major.minor.patch", as every program's --version
 * prints it; thread-safe. */
const char *frs_library_version(void);

/* ---- progress (since 1.2) ---------------------------------------------- */

/* Progress of a long task: what names it (a map spec's name such as
 * "aniso"; valid during the call only), done of total units finished.
 * A task calls once with done = 0 when it starts, then with done
 * increasing below total, and once with done = total (at least 1) when
 * it ends. */
typedef void (*frs_progress_fn)(void *ctx, const char *what, uint64_t done,
    uint64_t total);
/* Report the progress of the library work that this thread starts to
 * fn(ctx, ...), called in this thread; fn NULL (the default in every
 * thread) reports nothing.  Per thread: other threads keep their own.
 * See frs_set_progress(3). */
void frs_set_progress(frs_progress_fn fn, void *ctx);

/* ---- threshold matrices ---------------------------------------------- */

typedef struct frs_mask frs_mask;

/* Load an FRD matrix (.frd) or a prepared one (.frp, see frd(5)).  For a
 * .frd whose prepared twin NAME.frp lies beside it and was made from it,
 * the twin's precomputed lists are used; a stale or damaged twin is
 * ignored and frs_mask_note says so.  A 3-D .frd gives a mask for
 * frs_sampler3_new.  Thread-safe. */
int frs_mask_load(frs_mask **mask, const char *path, frs_error *err);
/* Use the caller's width x height values, row-major, which must be a
 * permutation of 0 .. width*height-1 with power-of-two sides.  Nothing
 * is copied: the values must stay unchanged while the mask lives.
 * Thread-safe. */
int frs_mask_wrap(frs_mask **mask, const uint32_t *values, uint32_t width,
    uint32_t height, frs_error *err);
void frs_mask_size(const frs_mask *mask, uint32_t *width,
    uint32_t *height);
/* 2 or 3; and the depth of a 3-D mask (1 for 2-D).  Since 0.2.0. */
unsigned frs_mask_dims(const frs_mask *mask);
void frs_mask_size3(const frs_mask *mask, uint32_t *width,
    uint32_t *height, uint32_t *depth);
/* A remark on the mask's twin .frp, or NULL: stale and ignored (at
 * load), or damaged and ignored (found when a draw first needed its
 * sorted lists; the lists are then made instead).  A .frp loaded as
 * such with damaged lists makes that draw fail with FRS_E_FORMAT. */
const char *frs_mask_note(const frs_mask *mask);
/* Not while a sampler made from it lives. */
void frs_mask_free(frs_mask *mask);
/* Since 2.2: frs_mask_load, and the dimension count of the file's
 * header in *dims, told also when the load fails past the header (0
 * when no header was read). */
int frs_mask_load_dims(frs_mask **mask, const char *path, unsigned *dims,
    frs_error *err);
/* Since 2.2: the block size of sorted lists that the mask's .frp lacked
 * and a draw made (0: none), and the file that lacked them (the .frp, or
 * the matrix loaded). */
uint32_t frs_mask_made(const frs_mask *mask, const char **file);
/*
 * Since 1.2: the default matrix, the one frs-sample uses without -m:
 * dims 2 (default.frd, 2048 x 2048) or 3 (default3.frd, 64^3).  It is
 * the file named by $FRS_MATRIX (dims 3: $FRS_MATRIX3) when set and not
 * empty; else the shipped one, looked for in $FRS_DATA (a directory)
 * when set and not empty, else in PREFIX/share/frs beside libfrs.so,
 * beside the program, in the source tree the library was built in and
 * in the PREFIX it was built for.  When path is not NULL its path goes
 * there (cap bytes, FRS_E_BUFFER when longer; "" when none is found,
 * the path also when loading fails); when mask is not NULL
 * it is loaded as by frs_mask_load.  Nothing found: FRS_E_IO, with every
 * place looked at in the message.  Thread-safe.
 */
int frs_default_matrix(frs_mask **mask, unsigned dims, char *path,
    size_t cap, frs_error *err);

/*
 * Since 2.1: a threshold matrix's values as a .frd file holds them
 * (frd(5)): w x h (x d) values, x fastest, a permutation of 0 .. n-1,
 * and the parameters of the generator that made them, "key=value" lines.
 */
struct frs_matrix {
	unsigned dims;		/* 2 or 3 */
	uint32_t w, h, d;	/* d = 1 when dims = 2 */
	size_t n;		/* w * h * d */
	char *params;		/* NUL-terminated, never NULL after a read */
	uint32_t *v;		/* n values */
	int perm;		/* the library's: 1 once found to be a
				 * permutation (the values then unchanged) */
};
/* Read a .frd file ("-": standard input), its values checked in the
 * same pass to be a permutation (FRS_E_FORMAT naming the first value
 * seen twice otherwise); *m zeroed on failure.  Thread-safe. */
int frs_matrix_read(struct frs_matrix *m, const char *path,
    frs_error *err);
/* Write m as a .frd file to fp (name: for messages): FRS_E_ARG for a
 * matrix a .frd cannot hold, FRS_E_IO when a write fails; fp is neither
 * flushed nor closed.  Thread-safe for distinct streams. */
int frs_matrix_write(const struct frs_matrix *m, FILE *fp, const char *name,
    frs_error *err);
/* Release what frs_matrix_read made; *m zeroed. */
void frs_matrix_free(struct frs_matrix *m);

/* ---- importance maps ------------------------------------------------- */

/* Load a map: a PNG or OpenEXR file (luminance), or a procedural spec
 * such as "blob" (see imap(1)).  width, height: resample to that size,
 * or 0, 0 for the file's own (128 x 128 for specs).  *map gets
 * (*width_out) x (*height_out) floats, row 0 at the top, to be released
 * with frs_map_free.  Thread-safe. */
int frs_map_load(const char *src, uint32_t width, uint32_t height,
    float **map, uint32_t *width_out, uint32_t *height_out, frs_error *err);
void frs_map_free(float *map);
/* Since 2.0: an equirectangular environment map (row 0 at the zenith)
 * as an importance over the unit square proportional to solid angle,
 * in place: row j times the mean of sin(theta) over its band of polar
 * angles, theta from pi j / height to pi (j + 1) / height; rows stride
 * elements apart (0: width).  What frs-sample --equirect does to a map
 * before sampling it.  Thread-safe. */
void frs_map_equirect(float *map, uint32_t width, uint32_t height,
    size_t stride);
void frs_map_equirect_f64(double *map, uint32_t width, uint32_t height,
    size_t stride);

/*
 * Since 2.1: a map in doubles, the form the programs and the samplers
 * hold: pixel (i, j) covers [i/w, (i+1)/w) x [j/h, (j+1)/h) of the unit
 * square, row j counted from the top; values are linear importance, RGB
 * as Rec. 709 luminance.
 */
struct frs_imap {
	uint32_t w, h;
	double *v;	/* w * h values, row-major, row 0 at the top */
};
/* How frs_imap_load reads and checks a source (or them together). */
enum frs_map_flag {
	FRS_MAP_SRGB = 1 << 0,		/* 8- and 16-bit PNG: sRGB decoded
					 * to linear */
	FRS_MAP_STRICT = 1 << 1,	/* a negative value is an error, not
					 * clamped to zero */
	FRS_MAP_EQUIRECT = 1 << 2,	/* rows weighted as frs_map_equirect
					 * weights them, before resampling */
	FRS_MAP_ALLOW_ZERO = 1 << 3	/* a map zero everywhere is no error */
};
/* The largest side and pixel count of a map. */
#define FRS_MAP_MAX_SIDE 65536u
#define FRS_MAP_MAX_PIXELS ((uint64_t)1 << 28)
/*
 * Load src as frs_map_load does (a PNG or OpenEXR file, "-" for standard
 * input, or a spec), at width x height (0, 0: the file's own size, 128 x
 * 128 for a spec; a file of another size is resampled by area), under
 * flags: its own pixels are checked first (NaN or infinity: FRS_E_MAP,
 * naming the pixel; negative values clamped to zero, or FRS_E_MAP under
 * FRS_MAP_STRICT), then weighted and resampled, and a map zero everywhere
 * is FRS_E_MAP unless FRS_MAP_ALLOW_ZERO.  A spec that does not parse is
 * FRS_E_ARG, a file that does not open FRS_E_IO, one that is no map
 * FRS_E_FORMAT.  The file is opened once.  *map to be released with
 * frs_imap_free (zeroed on failure).  Thread-safe.
 */
int frs_imap_load(struct frs_imap *map, const char *src, uint32_t width,
    uint32_t height, int flags, frs_error *err);
void frs_imap_free(struct frs_imap *map);

/* ---- Forced Random Sampling ------------------------------------------ */

enum frs_algorithm {
	FRS_ALG_SORTED = 0,	/* block-sorted lists (the default) */
	FRS_ALG_NAIVE, FRS_ALG_STACK, FRS_ALG_LEVEL1, FRS_ALG_LEVEL2
};
enum frs_jitter_mode {
	FRS_JIT_NONE = 0,	/* element centres */
	FRS_JIT_HALTON,		/* Halton offsets inside the element */
	FRS_JIT_RANDOM		/* random offsets inside the element */
};
enum frs_rule_mode {
	FRS_RULE_UNBIASED = 0,	/* n I / sum I samples per pixel */
	FRS_RULE_THESIS,	/* v < T, thesis Eq. 4.14 */
	FRS_RULE_EXACT		/* since 1.2: the unbiased rule with tau
				   moved so that exactly n samples pass
				   (each step of progressive sampling) */
};
/* How the window is laid over the mask (since 1.1; the multi-level
 * window and these values since 2.0).  0 is the default: since 2.0 a
 * zeroed struct frs_options is an initialised one. */
enum frs_tiling_mode {
	FRS_TILING_LEVELS = 0,	/* the multi-level window: elements whose
				   size follows the map, so that every
				   region thresholds the mask at a density
				   where it is blue noise (libfrs(3)) */
	FRS_TILING_SHUFFLED,	/* one level; each tile turned, flipped and
				   shifted by (seed, tile): no lattice of
				   repeats, but seams at the tile borders and
				   white noise where the map is dark */
	FRS_TILING_PLAIN	/* one level, the mask repeated as it is
				   (the thesis, Sec. 4.5) */
};

/* The largest sparsity sigma (the options' and frs-sample's). */
#define FRS_SIGMA_MAX 1024.0

struct frs_options {
	double sigma;			/* sparsity, 1 .. FRS_SIGMA_MAX,
					   default 8 (0: 8, since 2.0) */
	enum frs_algorithm algorithm;	/* default FRS_ALG_SORTED */
	enum frs_jitter_mode jitter;	/* default FRS_JIT_NONE */
	enum frs_rule_mode rule;	/* default FRS_RULE_UNBIASED */
	int threads;			/* per call, default 1 (0: 1) */
	enum frs_tiling_mode tiling;	/* default FRS_TILING_LEVELS */
	double level_blur;		/* since 2.0: how far the levels are
					   smoothed, in map pixels (volume
					   voxels), at most 1e4; 0: the
					   default, an eighth of the longest
					   side; below 0.5: not at all */
};
/* The defaults above. */
void frs_options_init(struct frs_options *opt);
/*
 * Since 2.1: the names the programs give the values of these enums
 * (frs-sample(1)'s -a, --jitter, --threshold and --tiles), indexed by
 * value and NULL-terminated; FRS_RULE_EXACT has none (frs-sample's
 * --exact-count).  NULL for another which.  Thread-safe.
 */
enum frs_names {
	FRS_NAMES_ALGORITHM,	/* enum frs_algorithm: "sorted", "naive", ... */
	FRS_NAMES_JITTER,	/* enum frs_jitter_mode */
	FRS_NAMES_RULE,		/* enum frs_rule_mode */
	FRS_NAMES_TILING,	/* enum frs_tiling_mode */
	FRS_NAMES_HSW_INPUT	/* since 2.2: enum frs_hsw_input, hsw-sample(1)'s
				   --input: "random", "regular", ... */
};
const char *const *frs_names(enum frs_names which);
/* The largest level_blur. */
#define FRS_LEVEL_BLUR_MAX 1e4

typedef struct frs_sampler frs_sampler;

/*
 * A sampler of the importance map width x height: map[y * stride + x],
 * row 0 at the top, stride >= width in elements (0: width); NULL for a
 * constant map (uniform sampling).  The map is copied; the mask must
 * outlive the sampler.  opt NULL: the defaults.  Thread-safe.
 */
int frs_sampler_new(frs_sampler **sampler, const frs_mask *mask,
    const float *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err);
/* The same with double values (as frs-sample reads them). */
int frs_sampler_new_f64(frs_sampler **sampler, const frs_mask *mask,
    const double *map, uint32_t width, uint32_t height, size_t stride,
    const struct frs_options *opt, frs_error *err);
/* Not while another thread uses the sampler. */
struct frs_imap_stats;
/* Since 2.2: a sampler of map (frs_imap_load's, frs_source_load's)
 * taken over, neither copied nor checked again: st, the statistics its
 * check gave (frs_imap_check's; NULL: it is checked here, negative
 * values refused).  *map is the sampler's, zeroed, or released on
 * failure.  Thread-safe. */
int frs_sampler_take(frs_sampler **sampler, const frs_mask *mask,
    struct frs_imap *map, const struct frs_imap_stats *st,
    const struct frs_options *opt, frs_error *err);
void frs_sampler_free(frs_sampler *sampler);

/*
 * About n samples (1 <= n <= 2^40, else FRS_E_ARG or FRS_E_LIMIT) with
 * this seed: (x, y) pairs in [0,1)^2 into xy (2 cap
 * doubles), and when pdf is not NULL each sample's density I / mean I
 * into pdf (cap doubles).  *count gets the number made.  When it exceeds
 * cap, nothing is written, *count says how many there are, and the code
 * is FRS_E_BUFFER: the same call with room for them gives them.  The
 * same (n, seed, options) give the same samples for any thread count,
 * as frs-sample(1) does.  Thread-safe: one sampler, many threads, each
 * with its own buffers.
 */
int frs_draw(const frs_sampler *sampler, uint64_t n, uint64_t seed,
    double *xy, double *pdf, size_t cap, size_t *count, frs_error *err);
/* Since 2.2: the bytes a sample takes in a draw's store before it is
 * converted, dims 2 or 3 (0 else): a run of n samples keeps about
 * 1.1 n of them. */
size_t frs_draw_bytes(unsigned dims);
/* Only the number frs_draw would make.  Thread-safe. */
int frs_count(const frs_sampler *sampler, uint64_t n, uint64_t seed,
    uint64_t *count, frs_error *err);

/* Progressive sampling: counts steps[0] < steps[1] < ... (nsteps <= 16);
 * the samples of each step come after those of the steps before, and
 * step, when not NULL, gets each sample's step (0, 1, ...).  A prefix of
 * the output is a complete sample set of steps[k].  Thread-safe. */
int frs_draw_progressive(const frs_sampler *sampler, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, double *xy, double *pdf,
    uint32_t *step, size_t cap, size_t *count, frs_error *err);

/* The callback form: the samples in batches of k, in the order frs_draw
 * and frs_draw_progressive give them (nsteps 1 for plain sampling); pdf
 * and step are NULL unless want_pdf, resp. nsteps > 1.  total is the
 * number of samples of the whole run, the same in every call (so that
 * the first call can size what follows); a run without samples makes no
 * call.  A callback that returns non-zero stops the run with
 * FRS_E_CALLBACK.  The callback runs in the calling thread.
 * Thread-safe. */
typedef int (*frs_point_fn)(void *ctx, const double *xy, const double *pdf,
    const uint32_t *step, size_t k, uint64_t total);
int frs_draw_each(const frs_sampler *sampler, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int want_pdf, frs_point_fn fn,
    void *ctx, frs_error *err);

/* The setup for n samples (thesis Listing 5.1). */
struct frs_info {
	uint32_t ns;			/* window elements per pixel side */
	uint64_t window_w, window_h;	/* window size in elements */
	uint64_t offset_x, offset_y;	/* window offset in the tiled mask */
	double tau;			/* threshold scale */
	double mean, max;		/* of the map */
	double unique;			/* samples before patterns repeat */
};
int frs_sampler_info(const frs_sampler *sampler, uint64_t n, uint64_t seed,
    struct frs_info *info, frs_error *err);

/* Since 2.0: one level of the window of a run.  A run of one level
 * (plain or shuffled tiles, or a map whose pixels all stay at level 0)
 * has level 0 alone, whose setup frs_info gives. */
struct frs_level_info {
	unsigned level;		/* l: an element is 2^l x 2^l (x 2^l)
				   elements of level 0 */
	uint32_t ns;		/* its elements per pixel (voxel) side */
	uint64_t window[3];	/* its window in elements (depth 1 in 2-D) */
	uint64_t offset[3];	/* its offset in the tiled mask */
	uint64_t cells;		/* pixels (voxels) of non-zero importance
				   at this level */
	double tau;		/* its threshold scale: 4^l (8^l) times
				   level 0's */
};
/* The levels of the run of n samples with this seed, finest first:
 * *count gets how many there are (1 to 32), the first cap of them go to
 * levels (which may be NULL when cap is 0).  Thread-safe. */
int frs_sampler_levels(const frs_sampler *sampler, uint64_t n,
    uint64_t seed, struct frs_level_info *levels, unsigned cap,
    unsigned *count, frs_error *err);

/* ---- OpenCL devices (since 2.2) --------------------------------------- */

/* An OpenCL device for samplers to draw on (frs-sample(1) --device). */
typedef struct frs_device frs_device;
/* Open device number index as frs-sample --list-devices numbers them,
 * or the first (a GPU before a CPU) for index -1: FRS_E_IO when there is
 * no such device or it does not open.  Thread-safe. */
int frs_device_open(frs_device **dev, int index, frs_error *err);
/* Its name, as --list-devices gives it. */
const char *frs_device_name(const frs_device *dev);
/* Close it; no sampler may still draw on it.  NULL does nothing. */
void frs_device_free(frs_device *dev);
/* The seconds its draws spent, summed since it was opened: building the
 * program (the first draw), copying to the device (with the host's
 * thresholds), in kernels, copying back (with the host's offsets). */
struct frs_device_times {
	double build, upload, kernel, download;
};
void frs_device_times(const frs_device *dev, struct frs_device_times *t);
/* Flat 1 (thesis Sec. 5.4), the device's own walk, instead of the
 * options' algorithm: Stack's samples in Stack's order. */
#define FRS_DEVICE_FLAT1 1
/* Draw on dev (NULL: the CPU again): the same samples, bit for bit, as
 * on the CPU.  dev must outlive the sampler's draws, which run one at a
 * time on a device: a sampler on a device is not thread-safe (nor are
 * two samplers on one device).  flags: 0 or FRS_DEVICE_FLAT1. */
int frs_sampler_set_device(frs_sampler *sampler, frs_device *dev,
    int flags, frs_error *err);

/* ---- three dimensions (since 0.2.0) ---------------------------------- */

typedef struct frs_sampler3 frs_sampler3;

/*
 * A sampler of the importance volume width x height x depth over a 3-D
 * mask: volume[(z * height + y) * width + x], voxel (x, y, z) covering
 * [x/W, (x+1)/W) x [y/H, (y+1)/H) x [z/D, (z+1)/D); NULL for a constant
 * volume.  Copied and validated as a map is; opt as for frs_sampler_new,
 * the algorithm FRS_ALG_SORTED (default) or FRS_ALG_NAIVE.  A 2-D mask
 * is FRS_E_ARG (and a 3-D one for frs_sampler_new).  Thread-safe.
 */
int frs_sampler3_new(frs_sampler3 **sampler, const frs_mask *mask,
    const float *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err);
int frs_sampler3_new_f64(frs_sampler3 **sampler, const frs_mask *mask,
    const double *volume, uint32_t width, uint32_t height, uint32_t depth,
    const struct frs_options *opt, frs_error *err);
void frs_sampler3_free(frs_sampler3 *sampler);
/* As frs_draw, frs_draw_progressive and frs_count, with (x, y, z)
 * triples in [0,1)^3 (3 cap doubles in xyz) and pdf the density over the
 * unit cube; the samples of frs-sample(1) for the same seed and options.
 * Thread-safe. */
int frs_draw3(const frs_sampler3 *sampler, uint64_t n, uint64_t seed,
    double *xyz, double *pdf, size_t cap, size_t *count, frs_error *err);
int frs_draw3_progressive(const frs_sampler3 *sampler,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, double *xyz,
    double *pdf, uint32_t *step, size_t cap, size_t *count, frs_error *err);
int frs_count3(const frs_sampler3 *sampler, uint64_t n, uint64_t seed,
    uint64_t *count, frs_error *err);
/* Since 2.2: frs_draw_each for a volume, (x, y, z) triples in xyz,
 * in the order frs_draw3_progressive gives them.  Thread-safe. */
int frs_draw3_each(const frs_sampler3 *sampler, const uint64_t *steps,
    unsigned nsteps, uint64_t seed, int want_pdf, frs_point_fn fn,
    void *ctx, frs_error *err);
/* Since 2.0: frs_sampler_levels for a volume (octree levels). */
int frs_sampler3_levels(const frs_sampler3 *sampler, uint64_t n,
    uint64_t seed, struct frs_level_info *levels, unsigned cap,
    unsigned *count, frs_error *err);

/* ---- the run of a sampler (since 2.2) --------------------------------- */

/*
 * The setup of the run that frs_draw_each (frs_draw3_each) makes for
 * steps with a seed, held to be looked at: its window, levels, threshold
 * scales and tiles, and for a sample its level and the matrix element it
 * shows (frs-sample(1) -v and --level-column).  The sampler must outlive
 * the run.  flags: FRS_RUN_EXACT finds the exact rule's taus now (its
 * count passes; else tau is the unbiased rule's).  Thread-safe.
 */
typedef struct frs_run frs_run;
#define FRS_RUN_EXACT 1
#define FRS_LEVELS_MAX 32		/* levels of a window, at most */
int frs_run_new(frs_run **run, const frs_sampler *sampler,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int flags,
    frs_error *err);
int frs_run3_new(frs_run **run, const frs_sampler3 *sampler,
    const uint64_t *steps, unsigned nsteps, uint64_t seed, int flags,
    frs_error *err);
void frs_run_free(frs_run *run);
/* Make the mask's minmaps and sorted lists the run reads, as its draws
 * would first (so that they spend their time thresholding): FRS_E_FORMAT
 * for damaged lists of a .frp, FRS_E_NOMEM.  Thread-safe. */
int frs_run_prepare(const frs_run *run, frs_error *err);
struct frs_run_info {
	unsigned dims;			/* 2 or 3 */
	uint32_t matrix[3];		/* the mask's sides (depth 1 in 2-D) */
	uint64_t n;			/* the last step's count */
	uint32_t ns;			/* level 0's elements per pixel side */
	uint64_t window[3], offset[3];	/* level 0's window and offset */
	double tau;			/* level 0's threshold scale */
	double tau_plain;		/* without the exact rule's passes */
	unsigned passes;		/* those count passes, 0 without */
	unsigned start_level;		/* Stack's first minmap level (2-D) */
	double mean, max;		/* of the map */
	double unique;			/* samples before patterns repeat */
	uint64_t tiles[3];		/* mask tiles level 0's window spans */
	int shuffled;			/* the tiles turned and flipped */
	unsigned levels;		/* levels of the window, 1 to 32 */
	int planned;			/* cells given levels (frs_run_level_of) */
	double blur;			/* the levels' smoothing, in pixels */
};
int frs_run_info(const frs_run *run, struct frs_run_info *info,
    frs_error *err);
/* Level i (0 .. levels - 1, finest first): frs_sampler_levels' info, and
 * the box lo .. hi (both in) of its cells in the grid of side[] cells
 * (the map's pixels without a plan: then the whole map). */
struct frs_run_level {
	struct frs_level_info info;
	uint32_t map[3];		/* the map's sides (depth 1 in 2-D) */
	uint32_t side[3];		/* the grid of the levels' cells */
	uint32_t lo[3], hi[3];
};
int frs_run_level(const frs_run *run, unsigned i, struct frs_run_level *level,
    frs_error *err);
/* The level (its index i) whose cells hold point p (2 or 3 coordinates
 * in [0,1)): a sample's.  0 for a run of one level. */
unsigned frs_run_level_of(const frs_run *run, const double *p);
/* The matrix element (y * width + x) that a sample p of level i shows:
 * the one under it in the level's window; UINT64_MAX for a 3-D run or no
 * such level. */
uint64_t frs_run_element(const frs_run *run, unsigned i, const double *p);

/* ---- Hierarchical Sample Warping ------------------------------------- */

typedef struct frs_hsw frs_hsw;

enum frs_hsw_input {
	FRS_HSW_RANDOM = 0, FRS_HSW_REGULAR, FRS_HSW_JITTERED, FRS_HSW_HALTON,
	FRS_HSW_HAMMERSLEY
};

/* The warping quadtree of a map, as frs_sampler_new takes it (map NULL:
 * constant).  Negative values count as zero.  Thread-safe. */
int frs_hsw_new(frs_hsw **hsw, const float *map, uint32_t width,
    uint32_t height, size_t stride, frs_error *err);
int frs_hsw_new_f64(frs_hsw **hsw, const double *map, uint32_t width,
    uint32_t height, size_t stride, frs_error *err);
void frs_hsw_free(frs_hsw *hsw);
/* Warp n points of [0,1)^2 (pairs) from in to out (may be the same);
 * pdf as in frs_draw.  threads: 0 or 1 for one.  Thread-safe. */
int frs_hsw_warp(const frs_hsw *hsw, const double *in, double *out,
    double *pdf, size_t n, int threads, frs_error *err);
/* n points of the given input set with this seed, warped: the points
 * hsw-sample(1) makes.  Thread-safe. */
int frs_hsw_draw(const frs_hsw *hsw, enum frs_hsw_input input, uint64_t n,
    uint64_t seed, double *xy, double *pdf, int threads, frs_error *err);
/* Since 2.2: the callback form of frs_hsw_draw, the points in index
 * order in batches of at most 2^16 (fn, total and FRS_E_CALLBACK as in
 * frs_draw_each, step NULL); in, when not NULL, the caller's n points
 * of [0,1)^2 (pairs) warped instead of the input set.  Thread-safe. */
int frs_hsw_draw_each(const frs_hsw *hsw, enum frs_hsw_input input,
    const double *in, uint64_t n, uint64_t seed, int want_pdf, int threads,
    frs_point_fn fn, void *ctx, frs_error *err);
/* Since 2.2: the input set frs_hsw_draw warps, before warping: n pairs of
 * [0,1)^2 into xy.  Thread-safe. */
int frs_hsw_input(enum frs_hsw_input input, uint64_t n, uint64_t seed,
    double *xy, frs_error *err);
/* Since 2.2: the density I / mean I at n points (pairs) of [0,1)^2: the
 * pdf of frs_hsw_warp for points warped elsewhere.  Thread-safe. */
int frs_hsw_pdf(const frs_hsw *hsw, const double *xy, double *pdf, size_t n,
    frs_error *err);
/* Since 2.2: the quadtree, for -v reports and for warping on a device of
 * one's own.  sums holds levels 0 (the root) to levels, level l's 4^l
 * node sums in Morton order, the children of node k of a level being
 * nodes 4k .. 4k+3 of the next (top-left, top-right, bottom-left,
 * bottom-right); the leaves are the map's pixels, zero in the padding.
 * It lives as long as the tree.  Thread-safe. */
struct frs_hsw_info {
	uint32_t width, height;	/* the map */
	uint32_t side;		/* the tree's: the least power of two >= both */
	unsigned levels;	/* log2 side */
	double total, mean;	/* of the map: the root's sum, total / pixels */
	const double *sums;
};
int frs_hsw_info(const frs_hsw *hsw, struct frs_hsw_info *info,
    frs_error *err);

/* ---- random numbers (since 2.2) -------------------------------------- */

/*
 * The library's random numbers, so that a user can draw the same ones:
 * Philox4x32-10 (Salmon et al., "Parallel random numbers: as easy as 1,
 * 2, 3", SC 2011), a counter-based generator.  A number is a pure
 * function of (seed, stream, index): the key is the seed (low word
 * first), the 128-bit counter (index low, index high, stream, sub), so
 * that it is the same for any thread count, work order or device.
 * Streams separate the uses of one seed; the toolchain's own use numbers
 * below 256 and 0x56414331 and 0x56414332 (frd-gen), which use owns
 * which not API.  See frs_rand64(3).  None can fail; all are
 * thread-safe, an frs_rng being one thread's at a time.
 */
/* One Philox4x32-10 block: out from counter ctr under key. */
void frs_philox4x32_10(const uint32_t ctr[4], const uint32_t key[2],
    uint32_t out[4]);
/* 64 bits at (seed, stream, index): words 0 and 1 of the block of
 * counter (index, stream, 0), word 0 the low half. */
uint64_t frs_rand64(uint64_t seed, uint32_t stream, uint64_t index);
/* The same with sub as the counter's fourth word. */
uint64_t frs_rand64x(uint64_t seed, uint32_t stream, uint64_t index,
    uint32_t sub);
/* A double in [0, 1): the top 53 bits of frs_rand64 times 2^-53. */
double frs_rand01(uint64_t seed, uint32_t stream, uint64_t index);
/* A sequential stream: indices 0, 1, 2, ... of one (seed, stream). */
struct frs_rng {
	uint64_t seed;
	uint64_t index;		/* the next index drawn */
	uint32_t stream;
};
void frs_rng_init(struct frs_rng *r, uint64_t seed, uint32_t stream);
/* frs_rand64 and frs_rand01 at the next index, which they advance. */
uint64_t frs_rng_next64(struct frs_rng *r);
double frs_rng_next01(struct frs_rng *r);
/* A uniform integer in [0, bound) (bound 0: 2^64, every value) without
 * modulo bias: x mod bound of the next frs_rng_next64 x below the
 * largest multiple of bound not above 2^64 - 1, the others drawn
 * again. */
uint64_t frs_rng_below(struct frs_rng *r, uint64_t bound);

/* ---- preparing matrices (since 2.2; frd-prep(1)) --------------------- */

/*
 * Since 2.2: what frd-prep(1) does, for a library user: make a matrix to
 * fill (an importer of a format of one's own), check and rank its values,
 * read the grey levels of a PNG dither mask, tell a .frd from a .frp and
 * check the latter, write a prepared matrix (.frp, frd(5)), and the plan
 * of the levels a sampler of a matrix and a map makes for n samples, with
 * what each of them reads of a prepared matrix.  See frs_prepared_write(3).
 */
/* A w x h (x d) matrix of zero values (to be filled, as a generator's,
 * and written with frs_matrix_write) with a copy of params ("" when
 * NULL): FRS_E_ARG for dims other than 2 or 3, a zero size or d != 1 in
 * 2-D, FRS_E_LIMIT above 2^32 values, FRS_E_NOMEM above the ceiling
 * FRS_MAX_MEM or out of memory.  Released with frs_matrix_free; *m
 * zeroed on failure.  Thread-safe. */
int frs_matrix_alloc(struct frs_matrix *m, unsigned dims, uint32_t w,
    uint32_t h, uint32_t d, const char *params, frs_error *err);
/* Whether m's values are a permutation of 0 .. n-1: FRS_OK, else
 * FRS_E_FORMAT with a message that names (name: "matrix" when NULL) the
 * first value out of range or repeated and where it lies.  Thread-safe. */
int frs_matrix_check(const struct frs_matrix *m, const char *name,
    frs_error *err);
/* Each value replaced by its rank among them, ties in the order of their
 * positions: any values become a permutation.  FRS_E_NOMEM.  Thread-safe
 * for distinct matrices. */
int frs_matrix_rank(struct frs_matrix *m, frs_error *err);
/* The 64-bit FNV-1a of the sizes and values by which a .frp names the
 * matrix it was made from (frd(5)).  Thread-safe. */
uint64_t frs_matrix_checksum(const struct frs_matrix *m);
/* A PNG dither mask (path, "-": standard input) as a 2-D matrix: its
 * grey levels (8 or 16 bits; RGB as Rec. 709 luminance), exactly, ranked
 * as frs_matrix_rank ranks them, with params "imported=png".  A file
 * that does not open FRS_E_IO, one that is no PNG FRS_E_FORMAT.
 * Thread-safe. */
int frs_matrix_read_png(struct frs_matrix *m, const char *path,
    frs_error *err);

/* What frs_matrix_read_file found. */
struct frs_file_info {
	int frp;		/* 1: a .frp (prepared), 0: a .frd */
	int checked;		/* 1: the .frp read whole and checked, the
				 * fields below its */
	uint32_t w, h;		/* the matrix's size */
	uint64_t checksum;	/* frs_matrix_checksum of the matrix */
	int minmap;		/* 1: it holds the minmap */
	unsigned nblocks;	/* its sets of sorted lists (0 to 32) */
	uint32_t blocks[32];	/* their block sizes, in the file's order */
};
/* How frs_matrix_read_file reads. */
enum frs_read_flag {
	FRS_READ_ANY_VALUES = 1 << 0,	/* a .frd's values only checked to
					 * lie below n (frs_matrix_check
					 * tells the rest) */
	FRS_READ_CHECK_FRP = 1 << 1	/* a .frp read whole and checked */
};
/*
 * Read path ("-": standard input), a .frd or a .frp, told apart by their
 * first bytes (the file is read once).  A .frd goes to m as
 * frs_matrix_read reads it, its values checked to be a permutation unless
 * flags has FRS_READ_ANY_VALUES; info->frp = 0.  A .frp leaves m zeroed
 * with info->frp = 1; under FRS_READ_CHECK_FRP the whole file is read and
 * checked (its length, the checksum, the permutation, every minmap level
 * and set of sorted lists: FRS_E_FORMAT naming the first fault) and what
 * it holds goes to info (checked = 1), else nothing more is read from it.
 * A file that does not open is FRS_E_IO, one that is neither
 * FRS_E_FORMAT.  Thread-safe.
 */
int frs_matrix_read_file(struct frs_matrix *m, const char *path, int flags,
    struct frs_file_info *info, frs_error *err);

/*
 * Write the 2-D matrix m prepared to fp as a .frp (frd(5)): with its
 * minmap when minmap is set, and block-sorted lists of each of the
 * nblocks block sizes in blocks (powers of two up to the shorter side,
 * at most 32 of them; blocks may be NULL when nblocks is 0), so that
 * frs_mask_load of the file need not make them.  name names the file,
 * src the matrix in messages.  The values should be a permutation
 * (frs_matrix_check): a .frp of others is written, but refused when read.
 * A 3-D matrix, sides that are not powers of two or bad blocks are
 * FRS_E_ARG, a failed write FRS_E_IO; fp is neither flushed nor closed.
 * Thread-safe for distinct streams.
 */
int frs_prepared_write(const struct frs_matrix *m, FILE *fp,
    const char *name, const char *src, int minmap, const uint32_t *blocks,
    unsigned nblocks, frs_error *err);

/* One level of frs_prepared_plan. */
struct frs_prepared_level {
	unsigned level;		/* l, as in struct frs_level_info */
	uint32_t ns;		/* its elements per pixel side */
	uint64_t window_w, window_h;	/* its window in elements */
	uint32_t block;		/* the block size of the sorted lists it
				 * reads, 0: none (it scans its window) */
	int minmap;		/* 1: it reads the minmap */
	uint64_t values;	/* the values its lists must hold (those
				 * below it, at most n of the matrix); 0
				 * without lists */
	int from_frp;		/* 1: its lists are read from a .frp that
				 * has them rather than made */
};
/*
 * The levels, finest first, of a run of n samples (1 <= n <= 2^40) over
 * the 2-D matrix m and the map (as frs_imap_load gives it) under opt
 * (NULL: the defaults), as a sampler of them makes them: what
 * frd-prep(1) --for prints.  *count gets how many there are (1 to 32),
 * the first cap of them go to levels (which may be NULL when cap is 0).
 * A 3-D matrix is FRS_E_ARG, a window beyond
 * the method's sizes FRS_E_LIMIT.  Thread-safe.
 */
int frs_prepared_plan(const struct frs_matrix *m, const struct frs_imap *map,
    uint64_t n, const struct frs_options *opt,
    struct frs_prepared_level *levels, unsigned cap, unsigned *count,
    frs_error *err);

/* ---- maps and volumes: sources, checks, writers (since 2.2) ----------- */

/*
 * A flag of frs_imap_load and frs_source_load (with enum frs_map_flag):
 * the values as stored, with none of the checks, the clamping, the
 * weighting or the resampling above; a file at its own size (width and
 * height then size only a spec).  What imap(1) info reports on.
 */
#define FRS_MAP_RAW (1 << 4)

/* The statistics of a map's values (a volume's: those of the w x (h d)
 * map of its slices stacked downwards, the same values). */
struct frs_imap_stats {
	uint64_t count;		/* w * h */
	uint64_t zeros, negatives, nonfinite;
	double min, max;	/* over finite values (0, 0 if none) */
	double sum, mean;	/* over finite values, compensated sum */
	double min_negative;	/* smallest value when negatives > 0 */
	double min_positive;	/* smallest value > 0, 0 if none */
	uint32_t bad_x, bad_y;	/* first non-finite pixel, row-major */
	double bad_value;
	uint32_t neg_x, neg_y;	/* first negative pixel */
};
/* The statistics of map's w * h values, one pass.  Thread-safe. */
void frs_imap_stats(const struct frs_imap *map, struct frs_imap_stats *st);
/*
 * The checks of frs_imap_load on a map in place (name: for messages):
 * a NaN or infinity is FRS_E_MAP naming the pixel; negative values are
 * clamped to zero (FRS_E_MAP under FRS_MAP_STRICT); then a map zero
 * everywhere is FRS_E_MAP unless FRS_MAP_ALLOW_ZERO.  st, when not NULL,
 * gets the statistics of the values left (after clamping).  The other
 * flags are ignored.  Thread-safe for distinct maps.
 */
int frs_imap_check(struct frs_imap *map, const char *name, int flags,
    struct frs_imap_stats *st, frs_error *err);
/* The pixel (row-major index) of the point (x, y) of the unit square,
 * x across: a point on the far edge (1) goes to the last column or row;
 * the pixel whose density the samplers' pdf gives.  Inline, for hot
 * loops.  Thread-safe. */
static inline uint64_t frs_imap_pixel_of(const struct frs_imap *map,
    double x, double y)
{
	uint64_t px = (uint64_t)(x * map->w), py = (uint64_t)(y * map->h);

	px = px < map->w ? px : map->w - 1;
	py = py < map->h ? py : map->h - 1;
	return py * map->w + px;
}

/* An importance volume: voxel (i, j, l) covers [i/w, (i+1)/w) x
 * [j/h, (j+1)/h) x [l/d, (l+1)/d) of the unit cube; linear importance,
 * x fastest, then y, then z (frs_sampler3_new_f64's order). */
struct frs_vol {
	uint32_t w, h, d;
	double *v;	/* w * h * d values */
};
void frs_vol_free(struct frs_vol *vol);

/*
 * A source of a map or a volume, opened once: a PNG, OpenEXR or .frv
 * (frv(5)) file, "-" for standard input, or a procedural spec (imap(1):
 * "blob", "blob3", ...), a name that is no file.  frs_source_open opens
 * a file and reads its first bytes, which say what it is; a spec is only
 * named (it is evaluated by the load).  A file that does not open or
 * read is FRS_E_IO; a name that is neither a file nor a spec opens, with
 * kinds 0, and fails to load (FRS_E_IO, the message naming both).
 * Thread-safe for distinct sources.
 */
typedef struct frs_source frs_source;
enum frs_source_kind {
	FRS_SOURCE_MAP = 1,	/* a 2-D map: a PNG or OpenEXR file (or any
				 * file but a .frv: the load checks it),
				 * a map's spec */
	FRS_SOURCE_VOLUME = 2	/* a .frv file, a volume's spec ("const"
				 * is both) */
};
int frs_source_open(frs_source **source, const char *src, frs_error *err);
/* What the source may be loaded as: FRS_SOURCE_ bits. */
int frs_source_kinds(const frs_source *source);
/*
 * Load the source, once: as a map into *map (want 2), a volume into
 * *vol (want 3), or, want 0, what it is (a .frv file or a spec of
 * volumes alone is a volume, anything else a map); *dims gets 2 or 3.
 * size: the sides asked for, size[0] 0 for the source's own (a spec:
 * 128 x 128, 32^3); a map file of another size is resampled by area, a
 * volume never (a .frv file of another size is FRS_E_ARG).  flags as
 * frs_imap_load's, for volumes too (FRS_MAP_SRGB and FRS_MAP_EQUIRECT
 * for maps only): the values checked as frs_imap_check does (voxels
 * named as (x, y, z)), unless FRS_MAP_RAW.  st, when not NULL, gets the
 * statistics of a map's values as returned (a volume leaves it
 * unchanged).  Codes as for frs_imap_load; on failure *map and *vol are
 * zeroed.  map may be NULL when want is 3, vol when want is 2.
 */
int frs_source_load(frs_source *source, unsigned want,
    const uint32_t size[3], int flags, unsigned *dims, struct frs_imap *map,
    struct frs_imap_stats *st, struct frs_vol *vol, frs_error *err);
/* Close the file (standard input is left open); NULL does nothing. */
void frs_source_close(frs_source *source);
/* frs_source_open, frs_source_load and frs_source_close in one. */
int frs_source_read(const char *src, unsigned want, const uint32_t size[3],
    int flags, unsigned *dims, struct frs_imap *map,
    struct frs_imap_stats *st, struct frs_vol *vol, frs_error *err);
/* spec evaluated as a map (dims 2) or a volume (3) and checked as
 * frs_source_load does, the same way (FRS_MAP_RAW too), but never a file
 * of that name: a spec that does not parse (or names no spec of those
 * dims) is FRS_E_ARG. */
int frs_spec_load(const char *spec, unsigned dims, const uint32_t size[3],
    int flags, struct frs_imap *map, struct frs_imap_stats *st,
    struct frs_vol *vol, frs_error *err);
/* What a spec's name (before ':') makes: FRS_SOURCE_ bits, 0 for none;
 * no file is looked at.  Thread-safe. */
int frs_spec_kinds(const char *spec);
/* The specs of maps (dims 2) or volumes (3) and their parameters, as
 * imap(1) -h lists them; NULL for another dims.  Thread-safe. */
const char *frs_spec_help(unsigned dims);

/* The map formats frs_imap_write writes. */
enum frs_map_format {
	FRS_FORMAT_PNG = 1,	/* 16-bit grey, scaled so that the largest
				 * value is 65535 */
	FRS_FORMAT_EXR		/* one float channel "Y", ZIP compressed */
};
/* Write map to fp in format (name: for messages): FRS_E_ARG for a bad
 * argument or an empty map, FRS_E_MAP for values the format cannot hold,
 * FRS_E_IO when a write fails; fp is neither flushed nor closed.
 * Thread-safe for distinct streams. */
int frs_imap_write(const struct frs_imap *map, enum frs_map_format format,
    FILE *fp, const char *name, frs_error *err);
/* Write vol as a .frv file (frv(5)) to fp, the same way. */
int frs_vol_write(const struct frs_vol *vol, FILE *fp, const char *name,
    frs_error *err);

#ifdef __cplusplus
}
#endif

#endif
