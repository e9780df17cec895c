/* Test helpers (see fnav_testdata.h). */
#include "fnav_testdata.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

static int exists(const char *p)
{
    return access(p, R_OK) == 0;
}

int fnav_testdata_path(const char *rel, char *buf, size_t size)
{
    const char *env = getenv("FNAV_DATA_DIR");
    static const char *const roots[] = { "../shared/data", "/work/shared/data" };
    size_t i;
    if (env != NULL && *env != '\0') {
        snprintf(buf, size, "%s/%s", env, rel);
        if (exists(buf)) {
            return 0;
        }
    }
    for (i = 0; i < sizeof roots / sizeof roots[0]; i++) {
        snprintf(buf, size, "%s/%s", roots[i], rel);
        if (exists(buf)) {
            return 0;
        }
    }
    return -1;
}

int fnav_vector_path(const char *rel, char *buf, size_t size)
{
    const char *env = getenv("FNAV_VECTORS_DIR");
    snprintf(buf, size, "%s/%s", (env != NULL && *env != '\0') ? env : "vectors", rel);
    return exists(buf) ? 0 : -1;
}

void fnav_test_skip_notice(const char *what)
{
    const char *req = getenv("FNAV_REQUIRE_DATA");
    if (req != NULL && strcmp(req, "1") == 0) {
        fail_msg("%s: shared data not found and FNAV_REQUIRE_DATA=1 (set FNAV_DATA_DIR)", what);
    }
    fprintf(stderr, "[  SKIP    ] %s (shared data not found; set FNAV_DATA_DIR)\n", what);
}

void fnav_assert_close(double a, double b, double abs_tol, double rel_tol, const char *what, const char *file,
                       int line)
{
    double tol = abs_tol + rel_tol * fabs(b);
    if (!(fabs(a - b) <= tol)) {
        fprintf(stderr, "%s:%d: %s = %.12g, expected %.12g (|diff| %.3g > tol %.3g)\n", file, line, what, a, b,
                fabs(a - b), tol);
        fail_msg("%s not within tolerance", what);
    }
}
