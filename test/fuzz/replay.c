/*
 * Replay driver for the libFuzzer targets without libFuzzer: calls
 * LLVMFuzzerTestOneInput once on every file given, or on every regular
 * file of every directory given, and prints "N inputs".  make check runs
 * it on the seed corpus and on test/fuzz/crashes/<target>/.
 *   replay_TARGET DIR|FILE...
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
	FILE *fp = fopen(path, "rb");
	unsigned char *buf = NULL;
	size_t len = 0, cap = 0;

	if (fp == NULL) {
		perror(path);
		return -1;
	}
	for (;;) {
		if (len == cap) {
			size_t ncap = cap ? 2 * cap : 4096;
			unsigned char *nb = realloc(buf, ncap);
			if (nb == NULL) {
				fprintf(stderr, "%s: out of memory\n", path);
				free(buf);
				fclose(fp);
				return -1;
			}
			buf = nb;
			cap = ncap;
		}
		size_t got = fread(buf + len, 1, cap - len, fp);
		len += got;
		if (got == 0)
			break;
	}
	if (ferror(fp)) {
		perror(path);
		free(buf);
		fclose(fp);
		return -1;
	}
	fclose(fp);
	/* An exact-size copy, so that ASan sees reads past the end. */
	unsigned char *in = malloc(len ? len : 1);
	if (in == NULL) {
		free(buf);
		return -1;
	}
	if (len > 0)
		memcpy(in, buf, len);
	free(buf);
	LLVMFuzzerTestOneInput(in, len);
	free(in);
	return 0;
}

static int cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

int main(int argc, char **argv)
{
	unsigned long n = 0;
	int rc = 0;

	for (int i = 1; i < argc; i++) {
		struct stat st;
		if (stat(argv[i], &st) != 0) {
			perror(argv[i]);
			rc = 1;
			continue;
		}
		if (!S_ISDIR(st.st_mode)) {
			if (run_file(argv[i]) < 0)
				rc = 1;
			else
				n++;
			continue;
		}
		DIR *d = opendir(argv[i]);
		if (d == NULL) {
			perror(argv[i]);
			rc = 1;
			continue;
		}
		char **names = NULL;
		size_t nn = 0;
		struct dirent *e;
		while ((e = readdir(d)) != NULL) {
			size_t l = strlen(argv[i]) + strlen(e->d_name) + 2;
			char *p = malloc(l);
			char **nv = realloc(names, (nn + 1) * sizeof *names);
			if (p == NULL || nv == NULL) {
				free(p);
				if (nv != NULL)
					names = nv;
				rc = 1;
				break;
			}
			names = nv;
			snprintf(p, l, "%s/%s", argv[i], e->d_name);
			names[nn++] = p;
		}
		closedir(d);
		if (nn > 0)
			qsort(names, nn, sizeof *names, cmp);
		for (size_t k = 0; k < nn; k++) {
			if (stat(names[k], &st) == 0 && S_ISREG(st.st_mode)) {
				if (run_file(names[k]) < 0)
					rc = 1;
				else
					n++;
			}
			free(names[k]);
		}
		free(names);
	}
	printf("%lu inputs\n", n);
	return rc;
}
