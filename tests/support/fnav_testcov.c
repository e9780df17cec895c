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
    {
        double piv = fnav_test_chol(n, a);
        if (!(piv > 0.0) || !u->settle_on) {
            return piv;
        }
        /* with the landing settling active, the augmented covariance
         * [P Pxs; Pxs^T Pss] is positive definite when P is and the Schur
         * complement Pss - |L^-1 Pxs|^2 is positive (P = L L^T, L in a) */
        {
            double y[FNAV_UKF_NMAX], schur = (double)u->settle_var;
            for (i = 0; i < n; i++) {
                double t = (double)u->Pxs[i];
                for (j = 0; j < i; j++) {
                    t -= a[i][j] * y[j];
                }
                y[i] = t / a[i][i];
                schur -= y[i] * y[i];
            }
            return fmin(piv, schur / (double)u->settle_var);
        }
    }
}
