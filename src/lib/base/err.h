/*
 * Error reporting shared by the library and the programs.
 *
 * Library functions never print errors or exit: on failure they record one
 * message of the form "context: problem" (the context is usually a file
 * name) and return -1.  Programs print it as "prog: context: problem".
 * Warnings go straight to standard error through a hook the program sets.
 */
#ifndef FRS_ERR_H
#define FRS_ERR_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#if defined(__GNUC__)
#define FRS_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define FRS_PRINTF(a, b)
#endif

/* Record an error message; always returns -1 so that callers can
 * write "return frs_fail(...)". */
int frs_fail(const char *fmt, ...) FRS_PRINTF(1, 2);
/* Like frs_fail, appending ": strerror(errno)". */
int frs_fail_errno(const char *fmt, ...) FRS_PRINTF(1, 2);
/* frs_fail (with_errno: frs_fail_errno) of a va_list, for wrappers. */
int frs_vfail(const char *fmt, va_list ap, int with_errno);
/* Prefix the current message with "context: ". */
int frs_fail_context(const char *context);
const char *frs_errmsg(void);
void frs_clearerr(void);
/* What the last failure was about: every frs_fail sets OTHER; the memory
 * ceiling (mem.c) then sets MEM, a file that does not open (io.c, and a
 * map source that is neither a file nor a spec) IO, imap_validate MAP,
 * and the procedural specs (spec.c) SPEC for one that does not parse,
 * which a program reports as a usage error.  (frd-prep's importers say
 * what mends their failures by their return values, not here.) */
enum {
	FRS_ERRKIND_OTHER, FRS_ERRKIND_MEM, FRS_ERRKIND_MAP,
	FRS_ERRKIND_SPEC, FRS_ERRKIND_IO
};
void frs_set_errkind(int kind);
int frs_errkind(void);

/* Copy src to dst (cap bytes with the NUL, cut short at a whole
 * character) with every control byte but newline and tab, every byte of
 * invalid UTF-8 and every C1 control written as \xNN: what messages
 * quote (file content, names) never drives a terminal.  The length. */
size_t frs_escape(char *dst, size_t cap, const char *src);
/* vfprintf through frs_escape (up to 4095 bytes). */
void frs_vprint_escaped(FILE *fp, const char *fmt, va_list ap);

/* Warnings: printed as "prog: warning: ..." once frs_set_warn_prefix
 * has named the program, unless silenced; never before. */
void frs_warn(const char *fmt, ...) FRS_PRINTF(1, 2);
void frs_vwarn(const char *fmt, va_list ap);
void frs_set_warn_prefix(const char *prog);
void frs_set_quiet(int quiet);
/* Number of warnings issued so far (tests use it). */
unsigned long frs_warn_count(void);

#endif
