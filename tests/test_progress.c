/* The progress line of long commands (harness/hx_cli.h, hx_progress_text):
 * the percentage floored, and the time left at the rate so far. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "hx_cli.h"

static void expect_line(double frac, double elapsed_s, const char *want)
{
    char buf[128];
    const int n = hx_progress_text(buf, sizeof buf, "convert", frac, elapsed_s);
    assert_string_equal(buf, want);
    assert_int_equal(n, (int)strlen(want));
}

/* 9.6 % reads 9, not 10: rounded, the first line (at 9.6 %) and the
 * decile's line after it (at 10.0 %) both said "10 %"; 99.6 % is not
 * "100 %" before the end */
static void test_floored(void **state)
{
    (void)state;
    expect_line(0.096, 1.2, "convert:   9 % (1.2 s)");
    expect_line(0.100, 1.3, "convert:  10 % (1.3 s)");
    expect_line(0.996, 1.9, "convert:  99 % (1.9 s)");
    expect_line(1.0, 1.9, "convert: 100 % (1.9 s)");
    expect_line(0.0, 1.0, "convert:   0 % (1.0 s)");
    expect_line(29.0 / 100.0, 1.0, "convert:  29 % (1.0 s)"); /* 100 * 0.29 is 28.999999999999996 in double */
}

/* the time left is elapsed * (1 - f) / f, from 5 % and 2 s on, and not at
 * the end */
static void test_time_left(void **state)
{
    (void)state;
    expect_line(0.25, 3.0, "convert:  25 % (3.0 s, about 9 s left)");
    expect_line(0.5, 10.0, "convert:  50 % (10.0 s, about 10 s left)");
    expect_line(0.04, 30.0, "convert:   4 % (30.0 s)");   /* under 5 %: no rate to go by yet */
    expect_line(0.5, 1.5, "convert:  50 % (1.5 s)");      /* under 2 s */
    expect_line(1.0, 30.0, "convert: 100 % (30.0 s)");    /* done */
}

/* a buffer too small is cut, and the length it needed returned */
static void test_truncated(void **state)
{
    char buf[8];
    (void)state;
    assert_int_equal(hx_progress_text(buf, sizeof buf, "convert", 0.5, 1.0), 22);
    assert_string_equal(buf, "convert");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_floored),
        cmocka_unit_test(test_time_left),
        cmocka_unit_test(test_truncated),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
