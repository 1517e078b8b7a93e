/* Error messages: what they quote never carries raw control bytes or
 * invalid UTF-8 (frs_escape), while valid UTF-8, newlines and tabs stay. */
#include "testutil.h"
#include "base/err.h"

#include <string.h>

static void escape(void **state)
{
	char out[64];
	(void)state;

	assert_int_equal(frs_escape(out, sizeof out, "plain text"), 10);
	assert_string_equal(out, "plain text");
	frs_escape(out, sizeof out, "a\007b\033[31m\001\177");
	assert_string_equal(out, "a\\x07b\\x1b[31m\\x01\\x7f");
	frs_escape(out, sizeof out, "keep\n\tthese");
	assert_string_equal(out, "keep\n\tthese");
	/* UTF-8: e-acute and the euro sign stay; C1 CSI (U+009B), a lone
	 * continuation byte, an overlong '/' and a surrogate do not. */
	frs_escape(out, sizeof out, "caf\303\251 \342\202\254");
	assert_string_equal(out, "caf\303\251 \342\202\254");
	frs_escape(out, sizeof out, "\302\233x\200\300\257\355\240\200");
	assert_string_equal(out, "\\xc2\\x9bx\\x80\\xc0\\xaf\\xed\\xa0\\x80");
	/* Cut short at a whole escape, never inside one. */
	assert_int_equal(frs_escape(out, 6, "ab\001cd"), 2);
	assert_string_equal(out, "ab");
	assert_int_equal(frs_escape(out, 8, "ab\001cd"), 7);
	assert_string_equal(out, "ab\\x01c");
}

static void messages(void **state)
{
	(void)state;

	frs_fail("%s:1: '%s' is not a number", "f.txt", "x\033]0;y\007");
	assert_string_equal(frs_errmsg(), "f.txt:1: 'x\\x1b]0;y\\x07' is not a number");
	frs_fail("problem");
	frs_fail_context("na\rme");
	assert_string_equal(frs_errmsg(), "na\\x0dme: problem");
}

TU_MAIN(NULL, NULL,
	cmocka_unit_test(escape),
	cmocka_unit_test(messages))
