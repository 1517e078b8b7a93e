/*
 * Small I/O helpers shared by the format readers: opening an input that
 * may be "-", little-endian fields, reading exactly n bytes.
 */
#ifndef FRS_IO_H
#define FRS_IO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Open path for reading ("-" is standard input).  *name is set to the
 * name used in messages.  Returns NULL after frs_fail. */
FILE *io_open_in(const char *path, const char **name);
void io_close_in(FILE *fp);
/* Size of a regular file behind fp, or -1 for a pipe or terminal. */
long long io_file_size(FILE *fp);
/* Read exactly n bytes; "truncated" error naming what otherwise. */
int io_read_exact(FILE *fp, const char *name, void *buf, size_t n,
    const char *what);
/* A header of n bytes whose first npre were already read (a peek at the
 * magic, pre): the rest from fp, messages as io_read_exact's. */
int io_read_header(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, unsigned char *buf, size_t n);
/* Read everything (for formats that need random access, e.g. EXR), after
 * the npre bytes pre that a peek at the kind of file already took.  The
 * buffer always has room for one byte past *len (a text's NUL). */
int io_slurp(FILE *fp, const char *name, const unsigned char *pre,
    size_t npre, unsigned char **buf, size_t *len);
/* Open path ("-": standard input), read(fp, name for messages, obj),
 * close it: read's result, or -1 when path does not open. */
int io_read_path(const char *path,
    int (*read)(FILE *fp, const char *name, void *obj), void *obj);
/* io_read_path with io_slurp: the whole input in *buf, and in *name the
 * name messages use (set once path opens). */
int io_slurp_path(const char *path, const char **name, unsigned char **buf,
    size_t *len);

uint32_t io_get_u32(const unsigned char *p);
uint64_t io_get_u64(const unsigned char *p);
void io_put_u32(unsigned char *p, uint32_t v);
void io_put_u64(unsigned char *p, uint64_t v);
/* Convert an array between little-endian and host order in place. */
void io_le_u32(uint32_t *v, size_t n);
void io_le_f64(double *v, size_t n);

#endif
