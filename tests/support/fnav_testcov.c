/* Test helper: symmetry and positive definiteness of the UKF covariance. */
#include "fnav_testcov.h"

#include <math.h>

double fnav_test_chol(int n, double a[][FNAV_UKF_NMAX])
{
    double minpiv = (double)INFINITY;
    int i, j, k;
    for (j = 0; j < n; j++) {
        double d = a[j][j];
        for (k = 0; k < j; k++) {
            d -= a[j][k] * a[j][k];
        }
        if (!(d > 0.0)) {
            return d;
        }
        /* pivot relative to the diagonal: how far from singular */
        minpiv = fmin(minpiv, d / a[j][j]);
        a[j][j] = sqrt(d);
        for (i = j + 1; i < n; i++) {
            double s = a[i][j];
            for (k = 0; k < j; k++) {
                s -= a[i][k] * a[j][k];
            }
            a[i][j] = s / a[j][j];
        }
    }
    return minpiv;
}

double fnav_test_cov_spd(const fnav_ukf_t *u, double *asym)
{
    static double a[FNAV_UKF_NMAX][FNAV_UKF_NMAX];
    int n = u->n_act, i, j;
    *asym = 0.0;
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            double pij = (double)fnav_ukf_cov(u, u->act[i], u->act[j]);
            double pji = (double)fnav_ukf_cov(u, u->act[j], u->act[i]);
            double d = fabs(pij - pji);
            double r = (d == 0.0) ? 0.0 : (isfinite(d) && pji != 0.0 ? d / fabs(pji) : (double)INFINITY);
            *asym = r > *asym ? r : *asym;
            a[i][j] = pij;
        }
    }
    return fnav_test_chol(n, a);
}
