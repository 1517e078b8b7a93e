/* Atomic output: a target appears only complete; errors and aborts leave
 * nothing (not even a temporary), an old file survives a failed write. */
#include "testutil.h"
#include "cli/outfile.h"

#include <dirent.h>
#include <sys/stat.h>

static int count_entries(const char *dir)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	int n = 0;
	assert_non_null(d);
	while ((e = readdir(d)) != NULL)
		if (e->d_name[0] != '.')
			n++;
	closedir(d);
	return n;
}

static void commit(void **state)
{
	struct outfile o;
	const char *p = tu_path("c.txt");
	(void)state;

	assert_int_equal(outfile_open(&o, p, 0), 0);
	assert_true(access(p, F_OK) != 0);	/* not there before commit */
	fputs("hello\n", o.fp);
	assert_int_equal(outfile_commit(&o), 0);
	tu_assert_file_is(p, "hello\n");
	assert_int_equal(count_entries(tu_dir()), 1);
	unlink(p);
}

static void abort_keeps_old(void **state)
{
	struct outfile o;
	const char *p = tu_path("old.txt");
	(void)state;

	tu_write(p, "old", 3);
	assert_int_equal(outfile_open(&o, p, 1), 0);
	fputs("half of the new conte", o.fp);
	outfile_abort(&o);
	tu_assert_file_is(p, "old");
	assert_int_equal(count_entries(tu_dir()), 1);
	unlink(p);
}

static void bad_targets(void **state)
{
	struct outfile o;
	(void)state;

	assert_int_equal(outfile_open(&o, "/nonexistent/dir/x.png", 0), -1);
	assert_err_has("/nonexistent/dir/x.png", "No such file or directory");
	assert_int_equal(outfile_open(&o, tu_dir(), 0), -1);
	assert_err_has("is a directory");
}

/* /dev/full is a device: written in place, and the error shows at the
 * latest on commit. */
static void full_disk(void **state)
{
	struct outfile o;
	static char big[1 << 16];
	int rc = 0;
	(void)state;

	if (access("/dev/full", W_OK) != 0)
		skip();
	assert_int_equal(outfile_open(&o, "/dev/full", 1), 0);
	if (fwrite(big, 1, sizeof big, o.fp) != sizeof big)
		rc = -1;
	(void)rc;
	assert_int_equal(outfile_commit(&o), -1);
	assert_err_has("/dev/full", "No space left on device");
}

/* A symbolic link stays a link: its target gets the new contents.  A
 * link into /proc (as /dev/stdout is) is written through in place, never
 * replaced: a process's open file must not be swapped for another. */
static void symlinks(void **state)
{
	struct outfile o;
	const char *target = tu_path("target.txt"), *link = tu_path("link.txt");
	const char *fdlink = tu_path("fd.txt"), *sink = tu_path("sink.txt");
	char via[64];
	struct stat st;
	FILE *fp;
	(void)state;

	tu_write(target, "old\n", 4);
	assert_int_equal(symlink("target.txt", link), 0);
	assert_int_equal(outfile_open(&o, link, 0), 0);
	fputs("new\n", o.fp);
	assert_int_equal(outfile_commit(&o), 0);
	assert_int_equal(lstat(link, &st), 0);
	assert_true(S_ISLNK(st.st_mode));
	tu_assert_file_is(target, "new\n");

	/* a link to an open file descriptor: the bytes reach that file */
	fp = fopen(sink, "wb");
	assert_non_null(fp);
	snprintf(via, sizeof via, "/proc/self/fd/%d", fileno(fp));
	assert_int_equal(symlink(via, fdlink), 0);
	assert_int_equal(outfile_open(&o, fdlink, 0), 0);
	fputs("through\n", o.fp);
	assert_int_equal(outfile_commit(&o), 0);
	assert_int_equal(lstat(fdlink, &st), 0);
	assert_true(S_ISLNK(st.st_mode));
	fclose(fp);
	tu_assert_file_is(sink, "through\n");
	unlink(link), unlink(target), unlink(fdlink), unlink(sink);
}

TU_MAIN(NULL, tu_teardown,
	cmocka_unit_test(commit),
	cmocka_unit_test(abort_keeps_old),
	cmocka_unit_test(bad_targets),
	cmocka_unit_test(full_disk),
	cmocka_unit_test(symlinks))
