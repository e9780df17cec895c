/**
 * @file fnav_testdata.h
 * @brief Test helpers: locating ../shared/data and the repository's vectors,
 *        and comparing numbers with stated tolerances (CMocka has no double
 *        assertion).
 */
#ifndef FNAV_TESTDATA_H
#define FNAV_TESTDATA_H

#include <stddef.h>

/** Full path of a file under the shared data directory ($FNAV_DATA_DIR, else
 *  ../shared/data relative to the repository root, else /work/shared/data).
 *  Returns 0 and fills buf when the file exists, -1 otherwise. */
int fnav_testdata_path(const char *rel, char *buf, size_t size);

/** Full path of a file under the repository's vectors/ directory
 *  ($FNAV_VECTORS_DIR, else vectors/ in the working directory). 0 if it exists. */
int fnav_vector_path(const char *rel, char *buf, size_t size);

/** Print a visible skip notice (CMocka 1.1 skips silently otherwise); with
 *  FNAV_REQUIRE_DATA=1 in the environment (CI) fail the test instead. */
void fnav_test_skip_notice(const char *what);

/** |a - b| <= abs_tol + rel_tol * |b|, else fail the test with both values. */
void fnav_assert_close(double a, double b, double abs_tol, double rel_tol, const char *what,
                       const char *file, int line);

#define FNAV_ASSERT_CLOSE(a, b, abs_tol, rel_tol) \
    fnav_assert_close((double)(a), (double)(b), (abs_tol), (rel_tol), #a, __FILE__, __LINE__)

#endif /* FNAV_TESTDATA_H */
