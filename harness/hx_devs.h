/**
 * @file hx_devs.h
 * @brief The frequency-stability deviations of a whole phase record, as
 *        Stable32 and NIST SP 1065 define them (harness side,
 *        `harness allan --deviation`; docs/allan.md "Other deviations").
 *
 * The record is the phase x_0 .. x_{n-1} of a series y sampled at tau0:
 * x_k = sum of y over the first k samples, in the unit of y times samples
 * (hx_allan_avar_record()). Averaging factor m, tau = m tau0. Every
 * variance is returned in the unit of y squared; TDEV's time variance is
 * tau^2 / 3 times MVAR (TTOT: MTOTVAR), which the caller scales
 * (hx_dev_scale()).
 *
 * The definitions are those of W. J. Riley, "Handbook of Frequency
 * Stability Analysis", NIST SP 1065 (2008), chapter 5:
 *  - ADEV, OADEV: Allan, second differences x_{i+2m} - 2 x_{i+m} + x_i,
 *    stride m and 1, AVAR = sum / (2 m^2 terms);
 *  - MDEV: modified Allan, the second differences summed over m
 *    consecutive i, stride 1, MVAR = sum / (2 m^4 terms), n - 3m + 1 terms;
 *  - TDEV: time deviation, tau / sqrt(3) MDEV;
 *  - HDEV, OHDEV: Hadamard, third differences x_{i+3m} - 3 x_{i+2m} +
 *    3 x_{i+m} - x_i, stride m and 1, HVAR = sum / (6 m^2 terms);
 *  - TOTDEV: total deviation, the second differences at i = 1 .. n - 2 of
 *    the record extended at both ends by odd reflection (x*_{-j} = 2 x_0 -
 *    x_j, x*_{n-1+j} = 2 x_{n-1} - x_{n-1-j}), TOTVAR = sum / (2 m^2 (n - 2));
 *  - PDEV: parabolic (Vernotte et al., IEEE TUFFC 63(4), 2016), from the
 *    least-squares frequency of each half: z_i = sum over k < m of
 *    ((m - 1) / 2 - k) (x_{i+k} - x_{i+m+k}), PVAR = 72 sum z_i^2 /
 *    (m^6 terms), i = 0 .. n - 2m - 1 (n - 2m terms: SigmaTheta's and
 *    allantools' count, one fewer than the record allows); at m = 1 the
 *    overlapping Allan variance;
 *  - MTOTDEV, TTOTDEV, HTOTDEV: the total forms (SP 1065 eqs. 27-29): per
 *    start, 3m phase (MTOT) or frequency (HTOT) values less the line through
 *    their half means, extended to 9m by uninverted even reflection, the
 *    mean of the 6m squared second differences of m-sample means; MTOTVAR =
 *    its mean over the n - 3m + 1 starts / (2 m^2), TTOT = tau / sqrt(3)
 *    MTOT, HTOTVAR = its mean over the n - 3m starts / 6 (at m = 1 the
 *    overlapping Hadamard variance). No bias correction.
 *
 * All in double, O(n) per tau except the total forms, O(n m)
 * (hx_dev_work()). Not for the core: the core's streaming estimator
 * computes the Allan variance alone, in fixed memory.
 */
#ifndef HX_DEVS_H
#define HX_DEVS_H

#include <stddef.h>
#include <stdint.h>

typedef enum {
    HX_DEV_ADEV = 0,
    HX_DEV_OADEV,
    HX_DEV_MDEV,
    HX_DEV_TDEV,
    HX_DEV_HDEV,
    HX_DEV_OHDEV,
    HX_DEV_TOTDEV,
    HX_DEV_PDEV,
    HX_DEV_MTOTDEV,
    HX_DEV_TTOTDEV,
    HX_DEV_HTOTDEV,
    HX_DEV_COUNT
} hx_dev_t;

/** Lower-case name ("adev", "mdev", ...); NULL when out of range. */
const char *hx_dev_name(hx_dev_t k);

/** Stable32's "Sigma Type" words for the deviation ("Modified Allan", ...). */
const char *hx_dev_title(hx_dev_t k);

/** Parse a name (as hx_dev_name()). @return 0, or -1 when unknown. */
int hx_dev_parse(const char *s, hx_dev_t *k);

/**
 * The variance of deviation k at averaging factor m from a phase record.
 * @param terms out: the number of terms summed (Stable32's "#"), 0 when m
 *              is too large for the record
 * @return the variance in the unit of y squared (TDEV: MVAR), NaN when
 *         there is no term.
 */
double hx_dev_var_record(hx_dev_t k, const double *x, size_t n, uint32_t m, uint32_t *terms);

/**
 * The work of hx_dev_var_record() for deviation k at averaging factor m, in
 * window terms: starts x 6m for MTOTDEV, TTOTDEV and HTOTDEV (m >= 2), whose
 * cost grows as n m; 0 for the others (O(n)) and where there is no term.
 */
uint64_t hx_dev_work(hx_dev_t k, size_t n, uint32_t m);

/** Factor from the deviation of hx_dev_var_record() to the one printed:
 *  tau / sqrt(3) for TDEV and TTOTDEV (tau = m / rate_hz, s), 1 otherwise. */
double hx_dev_scale(hx_dev_t k, uint32_t m, double rate_hz);

/**
 * Equivalent degrees of freedom of deviation k at averaging factor m for
 * power-law noise S_y ~ f^alpha, with n phase values: Greenhall & Riley's
 * algorithm (fnav_allan_edf_var(): d = 2 for the Allan family, 3 for the
 * Hadamard one, modified for MDEV and TDEV) and, for TOTDEV, SP 1065's
 * b N / m - c (Table 7: white, flicker and random-walk FM; for alpha > 0,
 * where the table has no row, the overlapping Allan variance's EDF); for
 * PDEV fnav_allan_edf_pvar(); for MTOTDEV and TTOTDEV SP 1065's Table 8
 * (b N / m - c, alpha +2 .. -2); for HTOTDEV, which has no published EDF
 * at hand, the overlapping Hadamard variance's (conservative).
 * @return the EDF, or a negative value when undefined.
 */
double hx_dev_edf(hx_dev_t k, int alpha, uint32_t m, size_t n);

#endif
