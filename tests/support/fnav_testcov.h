/**
 * @file fnav_testcov.h
 * @brief Test helper: is the UKF's active covariance symmetric and positive
 *        definite? (a Cholesky factorisation in double).
 */
#ifndef FNAV_TESTCOV_H
#define FNAV_TESTCOV_H

#include "footnav/fnav_ukf.h"

/** Cholesky factorisation in double, in place: the lower triangle of the
 *  n x n matrix a becomes L (a = L L^T; the strict upper triangle is not
 *  used). Returns the smallest pivot relative to its diagonal element; a
 *  value <= 0 or NaN means not positive definite (the factorisation stops
 *  at the first such pivot and returns it). */
double fnav_test_chol(int n, double a[][FNAV_UKF_NMAX]);

/** Factorises the active covariance of u by Cholesky in double; while the
 *  landing settling is active, the covariance augmented with it (through
 *  its Schur complement, whose value relative to Pss counts as a pivot).
 *  Returns the smallest pivot relative to its diagonal element; a value
 *  <= 0 or NaN means not positive definite (the factorisation stops at the
 *  first such pivot and returns it). *asym receives the largest
 *  |P_ij - P_ji| / |P_ji| (0 for equal entries, infinite when an entry is
 *  not finite or P_ji is 0 and P_ij is not). */
double fnav_test_cov_spd(const fnav_ukf_t *u, double *asym);

#endif /* FNAV_TESTCOV_H */
