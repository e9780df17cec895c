/* fnav_strapdown: analytic motions with exact answers (rest, constant
 * rotation, constant acceleration, classical coning), a general motion with
 * a closed-form truth (convergence orders) and classical sculling, the gravity model
 * against published values, the trig-free quaternion series, bad input.
 *
 * Tolerances: the algorithm is exact for rest, constant rotation and
 * constant acceleration, so only rounding remains: per step about one
 * float32 ulp (1.2e-7 relative), accumulated over N steps as at most N ulp
 * (random-walk growth is smaller). The double build is held to 1e-9. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "footnav/fnav_port.h"
#include "footnav/fnav_strapdown.h"
#include "fnav_testdata.h"

#if FNAV_USE_DOUBLE
#define EPS 1e-15
#else
#define EPS 1.2e-7
#endif

static const double k_g = 9.80665;

static double quat_angle_between(fnav_quat_t a, fnav_quat_t b)
{
    /* angle of a^-1 b, rad */
    fnav_quat_t d = fnav_quat_mul(fnav_quat_conj(a), b);
    double vn = sqrt((double)d.q[1] * (double)d.q[1] + (double)d.q[2] * (double)d.q[2] + (double)d.q[3] * (double)d.q[3]);
    return 2.0 * atan2(vn, fabs((double)d.q[0]));
}

static fnav_strapdown_state_t state_at(fnav_quat_t q)
{
    fnav_strapdown_state_t x;
    x.q_nb = q;
    x.vel_mps = fnav_vec3_zero();
    x.pos_m = fnav_vec3_zero();
    return x;
}

/* At rest with any attitude, f_b = C_bn (0, 0, -g): nothing moves. */
static void test_rest(void **state)
{
    const int n = 1000;
    const fnav_real_t dt = FNAV_R(0.01);
    fnav_quat_t q0 = fnav_quat_from_euler(FNAV_R(0.3), FNAV_R(-0.2), FNAV_R(1.1));
    fnav_strapdown_state_t x = state_at(q0);
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_vec3_t f = fnav_quat_rotate(fnav_quat_conj(q0), fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g));
    int i;
    (void)state;
    for (i = 0; i < n; i++) {
        assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, fnav_vec3_zero(), f, dt), FNAV_OK);
    }
    /* the residual |C f + g| is a few ulp of g per step */
    for (i = 0; i < 3; i++) {
        FNAV_ASSERT_CLOSE(x.vel_mps.v[i], 0.0, 4.0 * EPS * k_g * 0.01 * n, 0.0);
        FNAV_ASSERT_CLOSE(x.pos_m.v[i], 0.0, 4.0 * EPS * k_g * 0.01 * n * 0.01 * n, 0.0);
    }
    assert_true(quat_angle_between(x.q_nb, q0) < 8.0 * EPS);
}

/* Constant rate about a fixed axis: q(T) = q0 * exp(w T) exactly (the coning
 * term vanishes because successive increments are parallel). */
static void test_constant_rotation(void **state)
{
    const int n = 2000;
    const double dt = 0.005, T = n * dt;
    const double w[3] = { 0.4, -1.3, 2.2 }; /* rad/s */
    fnav_quat_t q0 = fnav_quat_from_euler(FNAV_R(-0.1), FNAV_R(0.25), FNAV_R(-2.0));
    fnav_strapdown_state_t x = state_at(q0);
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_vec3_t wv = fnav_vec3((fnav_real_t)w[0], (fnav_real_t)w[1], (fnav_real_t)w[2]);
    fnav_quat_t qt;
    int i;
    (void)state;
    for (i = 0; i < n; i++) {
        /* specific force that keeps the body free-falling-compensated: f_n = -g_n */
        fnav_vec3_t f = fnav_quat_rotate(fnav_quat_conj(x.q_nb), fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g));
        assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, wv, f, (fnav_real_t)dt), FNAV_OK);
    }
    qt = fnav_quat_mul(q0, fnav_quat_from_rotvec(fnav_vec3((fnav_real_t)(w[0] * T), (fnav_real_t)(w[1] * T),
                                                            (fnav_real_t)(w[2] * T))));
    /* the total angle is 25.6 rad: one ulp of that is the floor of the reference */
    assert_true(quat_angle_between(x.q_nb, qt) < 4.0 * EPS * n + 30.0 * EPS);
    /* the attitude stays a unit quaternion: each step's Newton
     * renormalisation takes a norm error e to 1.5 e^2 plus the rounding of
     * the norm and the scaling (a few ulp), so after any number of steps
     * |q| is within a few ulp of 1 (1e-6 is 8 float32 ulp); the angle check
     * above cannot see the norm, which quat_angle_between divides out */
    {
        const fnav_quat_t q = x.q_nb;
        const double nq = sqrt((double)q.q[0] * (double)q.q[0] + (double)q.q[1] * (double)q.q[1] +
                               (double)q.q[2] * (double)q.q[2] + (double)q.q[3] * (double)q.q[3]);
        FNAV_ASSERT_CLOSE(nq, 1.0, 1e-6, 0.0);
    }
}

/* Constant acceleration a in n with a tilted constant attitude:
 * v = a T, p = a T^2 / 2 exactly with trapezoidal position integration. */
static void test_constant_acceleration(void **state)
{
    const int n = 500;
    const double dt = 0.004, T = n * dt;
    const double a[3] = { 1.5, -0.7, 0.3 };
    fnav_quat_t q0 = fnav_quat_from_euler(FNAV_R(0.2), FNAV_R(0.1), FNAV_R(-0.6));
    fnav_strapdown_state_t x = state_at(q0);
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_vec3_t fn = fnav_vec3((fnav_real_t)a[0], (fnav_real_t)a[1], (fnav_real_t)(a[2] - k_g));
    fnav_vec3_t fb = fnav_quat_rotate(fnav_quat_conj(q0), fn);
    int i;
    (void)state;
    for (i = 0; i < n; i++) {
        assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, fnav_vec3_zero(), fb, (fnav_real_t)dt),
                         FNAV_OK);
    }
    for (i = 0; i < 3; i++) {
        /* worst-case rounding: f_b carries ~2 ulp of g per step (4 EPS g T
         * in all), and each of the n additions rounds the running sum by at
         * most half an ulp of its final size */
        double tol_v = 4.0 * EPS * k_g * T + 0.5 * n * EPS * fabs(a[i]) * T;
        double tol_p = tol_v * T + 0.5 * n * EPS * 0.5 * fabs(a[i]) * T * T;
        FNAV_ASSERT_CLOSE(x.vel_mps.v[i], a[i] * T, tol_v, 0.0);
        FNAV_ASSERT_CLOSE(x.pos_m.v[i], 0.5 * a[i] * T * T, tol_p, 0.0);
    }
}

/* Rotation and acceleration together: constant body rate w and a constant
 * acceleration a in n. The accelerometer delivers the exact mean specific
 * force of each interval, dv_b = integral of C_bn(t) (a - g_n) dt (Simpson
 * quadrature on 64 sub-steps in double, error < 1e-12), so the only error
 * left is the algorithm's: the velocity must be a T (tests the rotation
 * compensation and sculling terms and their signs). */
/* The last run's velocity error (m/s, n) and its leading term (below). */
static double g_ra_err[3], g_ra_lead[3];

static double rotating_acceleration_dt(int instant, int algo_instant, double dt)
{
    const int n = (int)lround(5.0 / dt), sub = 64;
    const double T = n * dt;
    const double w[3] = { 3.0, -1.0, 2.0 }; /* rad/s: 3.7 rad/s, 18.7 rad in all */
    const double a[3] = { 0.8, -1.2, 0.5 };
    fnav_quat_t q0 = fnav_quat_from_euler(FNAV_R(0.4), FNAV_R(-0.3), FNAV_R(0.9));
    fnav_strapdown_state_t x = state_at(q0);
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_vec3_t wv = fnav_vec3((fnav_real_t)w[0], (fnav_real_t)w[1], (fnav_real_t)w[2]);
    fnav_strapdown_config_t cfg = fnav_strapdown_config_default;
    int k, j, i;
    double err = 0.0;
    cfg.sample_type = algo_instant ? FNAV_SAMPLE_INSTANT : FNAV_SAMPLE_MEAN;
    for (k = instant ? -1 : 0; k < n; k++) {
        double dvb[3] = { 0, 0, 0 };
        for (j = 0; j <= sub; j++) {
            double t = (k + (double)j / sub) * dt;
            double wt = (j == 0 || j == sub) ? 1.0 : (j % 2 ? 4.0 : 2.0);
            if (instant) {
                /* the specific force at the end of the interval itself */
                t = (k + 1) * dt;
                wt = j == sub ? 3.0 * sub : 0.0;
            }
            /* C_nb(t) = C_nb(0) exp([w x] t): f_b = exp(-[w x] t) C_bn(0) f_n */
            fnav_quat_t qt = fnav_quat_mul(q0, fnav_quat_from_rotvec(fnav_vec3((fnav_real_t)(w[0] * t), (fnav_real_t)(w[1] * t),
                                                                             (fnav_real_t)(w[2] * t))));
            double fn[3] = { a[0], a[1], a[2] - k_g };
            /* rotate f_n into b in double: v_b = q^-1 v_n q */
            double qw = qt.q[0], qx = -(double)qt.q[1], qy = -(double)qt.q[2], qz = -(double)qt.q[3];
            double tx = 2.0 * (qy * fn[2] - qz * fn[1]), ty = 2.0 * (qz * fn[0] - qx * fn[2]), tz = 2.0 * (qx * fn[1] - qy * fn[0]);
            double fb[3];
            fb[0] = fn[0] + qw * tx + (qy * tz - qz * ty);
            fb[1] = fn[1] + qw * ty + (qz * tx - qx * tz);
            fb[2] = fn[2] + qw * tz + (qx * ty - qy * tx);
            for (i = 0; i < 3; i++) {
                dvb[i] += wt * fb[i] * dt / (3.0 * sub);
            }
        }
        assert_int_equal(fnav_strapdown_step(&cfg, &x, &h, wv,
                                             fnav_vec3((fnav_real_t)(dvb[0] / dt), (fnav_real_t)(dvb[1] / dt),
                                                       (fnav_real_t)(dvb[2] / dt)),
                                             k < 0 ? FNAV_R(0.0) : (fnav_real_t)dt),
                         FNAV_OK);
    }
    for (i = 0; i < 3; i++) {
        double e = fabs((double)x.vel_mps.v[i] - a[i] * T);
        g_ra_err[i] = (double)x.vel_mps.v[i] - a[i] * T;
        err = e > err ? e : err;
    }
    /* the leading error (test_rotating_acceleration): w and f in n */
    {
        const double qw = (double)q0.q[0], qv[3] = { (double)q0.q[1], (double)q0.q[2], (double)q0.q[3] };
        const double fn[3] = { a[0], a[1], a[2] - k_g };
        double t[3], wn[3], wf[3];
        for (i = 0; i < 3; i++) { /* t = 2 q_v x w */
            t[i] = 2.0 * (qv[(i + 1) % 3] * w[(i + 2) % 3] - qv[(i + 2) % 3] * w[(i + 1) % 3]);
        }
        for (i = 0; i < 3; i++) { /* w_n = w + q_w t + q_v x t */
            wn[i] = w[i] + qw * t[i] + (qv[(i + 1) % 3] * t[(i + 2) % 3] - qv[(i + 2) % 3] * t[(i + 1) % 3]);
        }
        for (i = 0; i < 3; i++) {
            wf[i] = wn[(i + 1) % 3] * fn[(i + 2) % 3] - wn[(i + 2) % 3] * fn[(i + 1) % 3];
        }
        for (i = 0; i < 3; i++) {
            g_ra_lead[i] = -(T * dt * dt / 6.0) * (wn[(i + 1) % 3] * wf[(i + 2) % 3] - wn[(i + 2) % 3] * wf[(i + 1) % 3]);
        }
    }
    return err;
}

static double rotating_acceleration(int instant, int algo_instant)
{
    return rotating_acceleration_dt(instant, algo_instant, 0.005);
}

/* The error bound below (2e-4 g T) is an order estimate, 5.5 times the
 * error measured (1.77e-3 m/s); what the algorithm guarantees is its order:
 * second order in dt for the velocity, so halving dt (T kept) divides the
 * error by 4. In double, at dt = 10, 5 and 2.5 ms: measured ratios 3.994
 * and 3.997 (the means), held to 3.5 .. 4.5 as test_general_motion's; in
 * float the rounding of 2000 steps moves the second ratio by about 5 %
 * (4.19 measured), so it is held to the order only there. A first-order
 * error makes the ratio 2; the means' sculling term with its sign flipped
 * (a hand-made mutant) happens to cancel this motion's leading error
 * (test_rotating_acceleration's analytic check): 1.0e-5 m/s, ratio 8.0,
 * under the old bound, and now failing here. */
static void rotating_acceleration_order(int instant)
{
    const double e1 = rotating_acceleration_dt(instant, instant, 0.01);
    const double e2 = rotating_acceleration_dt(instant, instant, 0.005);
    const double e3 = rotating_acceleration_dt(instant, instant, 0.0025);
    print_message("rotating acceleration (%s): 10 / 5 / 2.5 ms: %.4e / %.4e / %.4e m/s, ratios %.3f %.3f\n",
                  instant ? "instantaneous" : "means", e1, e2, e3, e1 / e2, e2 / e3);
#if FNAV_USE_DOUBLE
    assert_true(e1 / e2 > 3.5 && e1 / e2 < 4.5);
    assert_true(e2 / e3 > 3.5 && e2 / e3 < 4.5);
#else
    assert_true(e1 / e2 > 3.5 && e1 / e2 < 4.5);
    assert_true(e2 / e3 > 3.0 && e2 / e3 < 5.0);
#endif
}

/* The readings are the exact interval means: algorithm error of the
 * two-sample sculling for |w dt| = 0.019 rad is O((w dt)^2) of g dt per
 * step, about 1e-4 of g T in all; the float32 build adds rounding of n steps
 * of g dt. */
static void test_rotating_acceleration(void **state)
{
    const double T = 5.0, dt = 0.005;
    (void)state;
    assert_true(rotating_acceleration(0, 0) < 2e-4 * k_g * T + 2.0 * 1000 * EPS * k_g * dt);
#if FNAV_USE_DOUBLE
    /* The error itself, analytic: with a constant rate w and interval means,
     * the measured increment is v = T f - T^2/2 w x f + T^3/6 w x (w x f)
     * (f the body-frame specific force at the interval's start, T = dt),
     * the rotation compensation 1/2 (w T) x v adds T^2/2 w x f - T^3/4
     * w x (w x f), and the two-sample sculling -T^3/12 w x (w x f) (its
     * exact value for this motion too), so each step's increment misses
     * the exact T f by -T^3/6 w x (w x f): the second-order rotation term,
     * 1/2 int alpha x (alpha x f), that the algorithm leaves out (Savage
     * 1998, 7.2.2). In n that is the same vector every step (w_n and f_n
     * are constant), so the velocity error after the run is -(T_run dt^2
     * / 6) w_n x (w_n x f_n), each component. The terms left out are
     * |w| dt = 1.9 % of it each step (the next order), the first interval
     * (no previous sample for the sculling) 1 / n: held to (2 |w| dt + 2 /
     * n) of the leading error's norm; measured 0.46 % of it. Float: the
     * attitude's rounding over 18.7 rad, carried into |f| T_run = 47 m/s,
     * is of the error's size (3e-5 m/s measured), hence double only. */
    {
        const double wnorm = sqrt(3.0 * 3.0 + 1.0 + 2.0 * 2.0);
        double ln = 0.0;
        int i;
        for (i = 0; i < 3; i++) {
            ln += g_ra_lead[i] * g_ra_lead[i];
        }
        ln = sqrt(ln);
        {
            double worst = 0.0;
            for (i = 0; i < 3; i++) {
                worst = fmax(worst, fabs(g_ra_err[i] - g_ra_lead[i]) / ln);
            }
            print_message("rotating acceleration (means), 5 ms: error against its analytic leading term: %.2f %% of "
                          "its norm\n",
                          100.0 * worst);
        }
        for (i = 0; i < 3; i++) {
            FNAV_ASSERT_CLOSE(g_ra_err[i], g_ra_lead[i], (2.0 * wnorm * dt + 2.0 / 1000.0) * ln, 0.0);
        }
    }
#endif
    rotating_acceleration_order(0);
}

/* The readings are the instantaneous specific force at each sample time
 * (rate-output accelerometer): the instantaneous algorithm (trapezoid and
 * the sculling of linear profiles) meets the same bound; integrating the
 * same samples as interval means does not (half a sample ahead). */
static void test_rotating_acceleration_instant(void **state)
{
    const double T = 5.0, dt = 0.005;
    double e_inst = rotating_acceleration(1, 1), e_mis = rotating_acceleration(1, 0);
    (void)state;
    print_message("rotating acceleration, instantaneous samples: instant %.3e m/s, taken as means %.3e m/s\n", e_inst,
                  e_mis);
    assert_true(e_inst < 2e-4 * k_g * T + 2.0 * 1000 * EPS * k_g * dt);
    assert_true(e_mis > 5.0 * e_inst);
    rotating_acceleration_order(1);
}

/* Classical coning: q(t) = exp(beta u(t)), u = (cos Wt, sin Wt, 0). Its body
 * rate is w_b = W (-sin b sin Wt, sin b cos Wt, cos b - 1) and the exact
 * integral of w_b over each interval is fed as the mean rate (an integrating
 * gyro). The two-sample coning term must remove the coning drift that the
 * uncorrected single-sample algorithm accumulates. */
static double coning_error(int coning, int instant, double beta, double W, double dt, int n)
{
    fnav_strapdown_config_t cfg = fnav_strapdown_config_default;
    fnav_strapdown_state_t x;
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_quat_t qt;
    int k;
    cfg.coning = coning;
    cfg.sample_type = instant ? FNAV_SAMPLE_INSTANT : FNAV_SAMPLE_MEAN;
    x = state_at(fnav_quat_from_rotvec(fnav_vec3((fnav_real_t)beta, FNAV_R(0.0), FNAV_R(0.0))));
    for (k = instant ? 0 : 1; k <= n; k++) {
        double t0 = (k - 1) * dt, t1 = k * dt;
        double dth[3];
        fnav_vec3_t w;
        fnav_status_t st;
        if (instant) {
            /* the rate at t1 itself (a rate-output gyro); the sample at t = 0
             * only starts the history (dt = 0 for it) */
            dth[0] = -sin(beta) * W * sin(W * t1) * dt;
            dth[1] = sin(beta) * W * cos(W * t1) * dt;
        } else {
            dth[0] = sin(beta) * (cos(W * t1) - cos(W * t0));
            dth[1] = sin(beta) * (sin(W * t1) - sin(W * t0));
        }
        dth[2] = W * (cos(beta) - 1.0) * dt;
        w = fnav_vec3((fnav_real_t)(dth[0] / dt), (fnav_real_t)(dth[1] / dt), (fnav_real_t)(dth[2] / dt));
        if (k == 0) {
            st = fnav_strapdown_step(&cfg, &x, &h, w, fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g), FNAV_R(0.0));
            assert_int_equal(st, FNAV_OK);
            continue;
        }
        st = fnav_strapdown_step(&cfg, &x, &h, w, fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g), (fnav_real_t)dt);
        assert_int_equal(st, FNAV_OK);
    }
    qt = fnav_quat_from_rotvec(fnav_vec3((fnav_real_t)(beta * cos(W * n * dt)), (fnav_real_t)(beta * sin(W * n * dt)),
                                         FNAV_R(0.0)));
    return quat_angle_between(x.q_nb, qt);
}

static void test_coning(void **state)
{
    const double beta = 0.05, W = 2.0 * 3.14159265358979 * 5.0, dt = 0.005;
    const int n = 2000; /* 10 s */
    double e1 = coning_error(0, 0, beta, W, dt, n);
    double e2 = coning_error(1, 0, beta, W, dt, n);
    /* Single-sample drift rate for classical coning with integrated
     * increments (Savage 1998, eq. 7.1.1.2-8): 0.5 W beta^2 (1 - sin(l)/l),
     * l = W dt; the coning contribution of the error grows linearly. */
    double l = W * dt;
    double drift1 = 0.5 * W * sin(beta) * sin(beta) * (1.0 - sin(l) / l) * n * dt;
    (void)state;
    /* the formula holds to 4.6e-6 relative in float, 2.0e-6 in double here; 1e-3 (was 10 %)
     * leaves room for its neglected higher-order terms in beta^2 (2.5e-3 relative at most) */
    FNAV_ASSERT_CLOSE(e1, drift1, 0.0, 1e-3);
    /* the two-sample algorithm's residual is O(l^4): below a hundredth of it,
     * plus float rounding (one ulp per step of the 0.05 rad attitude) */
    assert_true(e2 < 0.01 * drift1 + 2.0 * EPS * n);
}

/* The same coning motion delivered as instantaneous rates (a rate-output
 * gyro sampled at t_k): the instantaneous algorithm (quadratic increments,
 * coning of the linear rate profile) stays below 2 % of the single-sample
 * drift (measured 1.3 %: the third-order interpolation error of a rate
 * rotating by l = W dt = 0.16 rad per step; the trapezoid alone leaves 100 %),
 * while taking the samples for interval means (the two-sample algorithm on
 * them) leaves an error at least 20 times larger. */
static void test_coning_instant(void **state)
{
    const double beta = 0.05, W = 2.0 * 3.14159265358979 * 5.0, dt = 0.005;
    const int n = 2000;
    double l = W * dt;
    double drift1 = 0.5 * W * sin(beta) * sin(beta) * (1.0 - sin(l) / l) * n * dt;
    double e_inst = coning_error(1, 1, beta, W, dt, n);
    double e_mis;
    (void)state;
    {
        /* instantaneous samples integrated as interval means */
        fnav_strapdown_config_t cfg = fnav_strapdown_config_default;
        fnav_strapdown_state_t x = state_at(fnav_quat_from_rotvec(fnav_vec3((fnav_real_t)beta, FNAV_R(0.0), FNAV_R(0.0))));
        fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
        fnav_quat_t qt;
        int k;
        cfg.sample_type = FNAV_SAMPLE_MEAN;
        for (k = 1; k <= n; k++) {
            double t1 = k * dt;
            fnav_vec3_t w = fnav_vec3((fnav_real_t)(-sin(beta) * W * sin(W * t1)), (fnav_real_t)(sin(beta) * W * cos(W * t1)),
                                      (fnav_real_t)(W * (cos(beta) - 1.0)));
            assert_int_equal(fnav_strapdown_step(&cfg, &x, &h, w, fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g),
                                                 (fnav_real_t)dt),
                             FNAV_OK);
        }
        qt = fnav_quat_from_rotvec(fnav_vec3((fnav_real_t)(beta * cos(W * n * dt)), (fnav_real_t)(beta * sin(W * n * dt)),
                                             FNAV_R(0.0)));
        e_mis = quat_angle_between(x.q_nb, qt);
    }
    print_message("coning, instantaneous samples: instant algorithm %.3e rad, taken as means %.3e rad, drift %.3e rad\n",
                  e_inst, e_mis, drift1);
    assert_true(e_inst < 0.02 * drift1 + 2.0 * EPS * n);
    assert_true(e_mis > 20.0 * e_inst);
}

/* Instantaneous samples with config.coning = 0 (make coverage: never run):
 * the same rotation and velocity increments as with it (the quadratic fit
 * does not depend on it), and no coning or sculling term; with it, the
 * terms of the linear profile, (1/12) (w0 T) x (w1 T) and (1/12) ((w0 T) x
 * (f1 T) + (f0 T) x (w1 T)) (fnav_strapdown.h), computed here in double
 * from the values the code sees (readings and T rounded to fnav_real_t).
 * Rounding (unit roundoff u = EPS / 2): each increment w T and each
 * product rounds once (3 u of every product), the differences and sums
 * once and the scaling by a rounded 1/12 twice; a cross-product element
 * may cancel, so the bound is relative to the sum of the magnitudes of its
 * products: 6 u of it for coning, 8 u for sculling (two cross products
 * added): 4 EPS of it for both. (It was 1e-5 relative in both builds:
 * 100 times the float rounding, 1e10 times the double's.) */
static void test_instant_coning_off(void **state)
{
    fnav_strapdown_config_t on = fnav_strapdown_config_default, off = fnav_strapdown_config_default;
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_strapdown_incr_t a, b;
    const double T = (double)(fnav_real_t)0.005, w0[3] = { 0.3, -1.2, 2.0 }, f0[3] = { 1.0, 0.5, -9.0 };
    const double w1[3] = { 0.5, -1.0, 1.5 }, f1[3] = { 1.5, 0.2, -9.5 };
    double cw[3], cs[3], mw[3], ms[3];
    int i;
    (void)state;
    assert_int_equal(on.sample_type, FNAV_SAMPLE_INSTANT);
    off.coning = 0;
    h.w2_rps = fnav_vec3(FNAV_R(0.2), FNAV_R(-1.3), FNAV_R(2.2));
    h.f2_mps2 = fnav_vec3(FNAV_R(0.8), FNAV_R(0.6), FNAV_R(-8.9));
    h.w_rps = fnav_vec3((fnav_real_t)w0[0], (fnav_real_t)w0[1], (fnav_real_t)w0[2]);
    h.f_mps2 = fnav_vec3((fnav_real_t)f0[0], (fnav_real_t)f0[1], (fnav_real_t)f0[2]);
    h.dt_prev_s = (fnav_real_t)T;
    h.have_sample = 2;
    h.valid = 1;
    fnav_strapdown_increments(&on, &h, fnav_vec3((fnav_real_t)w1[0], (fnav_real_t)w1[1], (fnav_real_t)w1[2]),
                              fnav_vec3((fnav_real_t)f1[0], (fnav_real_t)f1[1], (fnav_real_t)f1[2]), (fnav_real_t)T, &a);
    fnav_strapdown_increments(&off, &h, fnav_vec3((fnav_real_t)w1[0], (fnav_real_t)w1[1], (fnav_real_t)w1[2]),
                              fnav_vec3((fnav_real_t)f1[0], (fnav_real_t)f1[1], (fnav_real_t)f1[2]), (fnav_real_t)T, &b);
    for (i = 0; i < 3; i++) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        /* the readings as stored (rounded to fnav_real_t) */
        const double a0j = (double)(fnav_real_t)w0[j] * T, a0k = (double)(fnav_real_t)w0[k] * T;
        const double a1j = (double)(fnav_real_t)w1[j] * T, a1k = (double)(fnav_real_t)w1[k] * T;
        const double v0j = (double)(fnav_real_t)f0[j] * T, v0k = (double)(fnav_real_t)f0[k] * T;
        const double v1j = (double)(fnav_real_t)f1[j] * T, v1k = (double)(fnav_real_t)f1[k] * T;
        cw[i] = (a0j * a1k - a0k * a1j) / 12.0;
        cs[i] = ((a0j * v1k - a0k * v1j) + (v0j * a1k - v0k * a1j)) / 12.0;
        mw[i] = (fabs(a0j * a1k) + fabs(a0k * a1j)) / 12.0;
        ms[i] = (fabs(a0j * v1k) + fabs(a0k * v1j) + fabs(v0j * a1k) + fabs(v0k * a1j)) / 12.0;
        assert_true(a.theta_rad.v[i] == b.theta_rad.v[i]);
        assert_true(a.dv_mps.v[i] == b.dv_mps.v[i]);
        assert_true(b.coning.v[i] == FNAV_R(0.0));
        assert_true(b.scull.v[i] == FNAV_R(0.0));
        FNAV_ASSERT_CLOSE(a.coning.v[i], cw[i], 4.0 * EPS * mw[i], 0.0);
        FNAV_ASSERT_CLOSE(a.scull.v[i], cs[i], 4.0 * EPS * ms[i], 0.0);
    }
    assert_true(fabs(cw[2]) > 1e-7); /* the terms are not trivially zero */
}

/* Somigliana on WGS-84: 9.7803253359 m/s^2 at the equator and
 * 9.8321849378 m/s^2 at the poles (NIMA TR8350.2, table 3.4). */
/* A general motion with a closed-form truth: the
 * attitude turns about all three axes at once with varying rates (ZYX
 * Euler angles roll 0.3 sin 1.1t, pitch 0.2 sin(0.7t + 0.3), yaw 0.5t +
 * 0.4 sin 1.3t) while the position moves on p = (sin 0.9t, 0.5 cos 1.2t,
 * 0.2 sin 2t) m. The body rate is the Euler-rate kinematics
 * w_b = (r' - y' sin p, p' cos r + y' sin r cos p, -p' sin r + y' cos r cos p)
 * and the specific force f_b = C_bn (a_n - g_n), g_n = (0, 0, +g): nothing
 * in the truth goes through the strapdown. Fed either the instantaneous
 * readings or their interval means (5-point Gauss-Legendre, exact far below
 * the errors here), the matching algorithm must converge at its order:
 * attitude third order (halving dt divides the error by 8: quadratic
 * increments, or the two-sample coning on means), velocity and position
 * second order (by 4: the rotation compensation and sculling are exact to
 * second order; the trapezoid). Measured in double over 10 s
 * (error at 100 / 200 Hz): instantaneous 8.0e-8 / 1.0e-8 rad, 1.12e-4 /
 * 2.80e-5 m/s, 5.66e-4 / 1.41e-4 m; means 5.2e-8 / 6.5e-9 rad, 1.13e-4 /
 * 2.82e-5 m/s, 5.67e-4 / 1.42e-4 m (the same from samples and truth
 * computed by numpy/scipy from these formulas). A wrong sign of the
 * rotation compensation (velocity 4.3e-2 / 2.1e-2 m/s: first order) or the
 * attitude update composed on the wrong side (1.04 rad at both rates)
 * fails the orders (hand-made mutants). The sculling term of a smooth
 * motion is third order per step (w0 x f1 + f0 x w1 = O(dt)), so its sign
 * only moves these second-order constants: test_sculling below checks it.
 * In float32 rounding dominates (one ulp per step, the file's allowance:
 * about 3e-6 rad measured); only the double build checks the orders. */
/* 0: the general motion; 1: sculling (below) */
static int g_gm_motion;
static const double k_sc_phi = 0.05, k_sc_om = 2.0 * 3.14159265358979323846 * 5.0, k_sc_acc = 5.0;

static void gm_euler(double t, double e[3], double de[3])
{
    if (g_gm_motion == 1) {
        e[0] = k_sc_phi * sin(k_sc_om * t);
        de[0] = k_sc_phi * k_sc_om * cos(k_sc_om * t);
        e[1] = e[2] = de[1] = de[2] = 0.0;
        return;
    }
    e[0] = 0.3 * sin(1.1 * t);
    e[1] = 0.2 * sin(0.7 * t + 0.3);
    e[2] = 0.5 * t + 0.4 * sin(1.3 * t);
    de[0] = 0.33 * cos(1.1 * t);
    de[1] = 0.14 * cos(0.7 * t + 0.3);
    de[2] = 0.5 + 0.52 * cos(1.3 * t);
}

/* C_nb = Rz(yaw) Ry(pitch) Rx(roll), row-major. */
static void gm_dcm(const double e[3], double c[3][3])
{
    double cr = cos(e[0]), sr = sin(e[0]), cp = cos(e[1]), sp = sin(e[1]), cy = cos(e[2]), sy = sin(e[2]);
    c[0][0] = cy * cp;
    c[0][1] = cy * sp * sr - sy * cr;
    c[0][2] = cy * sp * cr + sy * sr;
    c[1][0] = sy * cp;
    c[1][1] = sy * sp * sr + cy * cr;
    c[1][2] = sy * sp * cr - cy * sr;
    c[2][0] = -sp;
    c[2][1] = cp * sr;
    c[2][2] = cp * cr;
}

static void gm_pva(double t, double p[3], double v[3], double a[3])
{
    if (g_gm_motion == 1) {
        p[0] = p[2] = v[0] = v[2] = a[0] = a[2] = 0.0;
        p[1] = -k_sc_acc / (k_sc_om * k_sc_om) * sin(k_sc_om * t);
        v[1] = -k_sc_acc / k_sc_om * cos(k_sc_om * t);
        a[1] = k_sc_acc * sin(k_sc_om * t);
        return;
    }
    p[0] = sin(0.9 * t);
    p[1] = 0.5 * cos(1.2 * t);
    p[2] = 0.2 * sin(2.0 * t);
    v[0] = 0.9 * cos(0.9 * t);
    v[1] = -0.6 * sin(1.2 * t);
    v[2] = 0.4 * cos(2.0 * t);
    a[0] = -0.81 * sin(0.9 * t);
    a[1] = -0.72 * cos(1.2 * t);
    a[2] = -0.8 * sin(2.0 * t);
}

/* Body rate and specific force at t. */
static void gm_imu(double t, double w[3], double f[3])
{
    double e[3], de[3], c[3][3], p[3], v[3], a[3];
    int i;
    gm_euler(t, e, de);
    gm_dcm(e, c);
    gm_pva(t, p, v, a);
    a[2] -= k_g;
    w[0] = de[0] - de[2] * sin(e[1]);
    w[1] = de[1] * cos(e[0]) + de[2] * sin(e[0]) * cos(e[1]);
    w[2] = -de[1] * sin(e[0]) + de[2] * cos(e[0]) * cos(e[1]);
    for (i = 0; i < 3; i++) {
        f[i] = c[0][i] * a[0] + c[1][i] * a[1] + c[2][i] * a[2];
    }
}

/* Attitude (rad), velocity (m/s) and position (m) errors after T s at rate
 * hz, instantaneous (mean = 0) or interval-mean readings (mean = 1). */
static double g_gm_dv[3], g_gm_dp[3]; /* general_motion's last velocity and position errors */

static void general_motion(double hz, int mean, int coning, double err[3])
{
    static const double gx[5] = { -0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                  0.9061798459386640 };
    static const double gw[5] = { 0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                  0.2369268850561891 };
    const double T = 10.0, dt = 1.0 / hz;
    const long n = lround(T * hz);
    fnav_strapdown_config_t cfg = fnav_strapdown_config_default;
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_strapdown_state_t x;
    double e[3], de[3], p[3], v[3], a[3], dv2 = 0.0, dp2 = 0.0;
    long k;
    int i, j;
    cfg.sample_type = mean ? FNAV_SAMPLE_MEAN : FNAV_SAMPLE_INSTANT;
    cfg.coning = coning;
    gm_euler(0.0, e, de);
    gm_pva(0.0, p, v, a);
    x.q_nb = fnav_quat_from_euler((fnav_real_t)e[0], (fnav_real_t)e[1], (fnav_real_t)e[2]);
    x.vel_mps = fnav_vec3((fnav_real_t)v[0], (fnav_real_t)v[1], (fnav_real_t)v[2]);
    x.pos_m = fnav_vec3((fnav_real_t)p[0], (fnav_real_t)p[1], (fnav_real_t)p[2]);
    for (k = 0; k <= n; k++) {
        double t = (double)k * dt, w[3] = { 0.0, 0.0, 0.0 }, f[3] = { 0.0, 0.0, 0.0 };
        if (!mean || k == 0) {
            gm_imu(t, w, f); /* the sample at t = 0 only starts the history (dt = 0) */
        } else {
            for (j = 0; j < 5; j++) {
                double wj[3], fj[3];
                gm_imu(t - 0.5 * dt * (1.0 - gx[j]), wj, fj);
                for (i = 0; i < 3; i++) {
                    w[i] += 0.5 * gw[j] * wj[i];
                    f[i] += 0.5 * gw[j] * fj[i];
                }
            }
        }
        assert_int_equal(fnav_strapdown_step(&cfg, &x, &h, fnav_vec3((fnav_real_t)w[0], (fnav_real_t)w[1], (fnav_real_t)w[2]),
                                             fnav_vec3((fnav_real_t)f[0], (fnav_real_t)f[1], (fnav_real_t)f[2]),
                                             k == 0 ? FNAV_R(0.0) : (fnav_real_t)dt),
                         FNAV_OK);
    }
    gm_euler(T, e, de);
    gm_pva(T, p, v, a);
    err[0] = quat_angle_between(x.q_nb, fnav_quat_from_euler((fnav_real_t)e[0], (fnav_real_t)e[1], (fnav_real_t)e[2]));
    for (i = 0; i < 3; i++) {
        g_gm_dv[i] = (double)x.vel_mps.v[i] - v[i];
        g_gm_dp[i] = (double)x.pos_m.v[i] - p[i];
        dv2 += g_gm_dv[i] * g_gm_dv[i];
        dp2 += g_gm_dp[i] * g_gm_dp[i];
    }
    err[1] = sqrt(dv2);
    err[2] = sqrt(dp2);
}

/* The leading velocity and position errors of the general motion at step
 * dt: lv = -(dt^2 / 6) int_0^T w_n x (w_n x f_n) dt, lp = its integral over
 * time (w_n = C_nb w, f_n = C_nb f), by the trapezoid on 20000 points. */
static void gm_lead(double T, double dt, double lv[3], double lp[3])
{
    const long N = 20000;
    const double h = T / (double)N;
    double prev[3] = { 0, 0, 0 }, cur[3];
    long k;
    int i;
    for (i = 0; i < 3; i++) {
        lv[i] = lp[i] = 0.0;
    }
    for (k = 0; k <= N; k++) {
        double t = (double)k * h, w[3], f[3], e[3], de[3], c[3][3], wn[3], fn[3], wf[3];
        gm_imu(t, w, f);
        gm_euler(t, e, de);
        gm_dcm(e, c);
        for (i = 0; i < 3; i++) {
            wn[i] = c[i][0] * w[0] + c[i][1] * w[1] + c[i][2] * w[2];
            fn[i] = c[i][0] * f[0] + c[i][1] * f[1] + c[i][2] * f[2];
        }
        for (i = 0; i < 3; i++) {
            wf[i] = wn[(i + 1) % 3] * fn[(i + 2) % 3] - wn[(i + 2) % 3] * fn[(i + 1) % 3];
        }
        for (i = 0; i < 3; i++) {
            cur[i] = -(dt * dt / 6.0) * (wn[(i + 1) % 3] * wf[(i + 2) % 3] - wn[(i + 2) % 3] * wf[(i + 1) % 3]);
            if (k > 0) {
                const double lv0 = lv[i];
                lv[i] += 0.5 * h * (prev[i] + cur[i]);
                lp[i] += 0.5 * h * (lv0 + lv[i]);
            }
            prev[i] = cur[i];
        }
    }
    {
        /* the position's trapezoid on the velocity: + (dt^2 / 12) (a(T) - a(0)) */
        double p0[3], v0[3], a0[3], p1[3], v1[3], a1[3];
        gm_pva(0.0, p0, v0, a0);
        gm_pva(T, p1, v1, a1);
        for (i = 0; i < 3; i++) {
            lp[i] += (dt * dt / 12.0) * (a1[i] - a0[i]);
        }
    }
}

/* (dt^3 / 24) |int C_nb w''' dt|: the quadratic rate integration's error */
static double gm_att_lead(double T, double dt)
{
    const long N = 20000;
    const double h = T / (double)N, d = 1e-2;
    double acc[3] = { 0, 0, 0 };
    long k;
    int i, j;
    for (k = 0; k <= N; k++) {
        double t = (double)k * h, e[3], de[3], c[3][3], w3[3], wm2[3], wm1[3], wp1[3], wp2[3], f[3];
        gm_euler(t, e, de);
        gm_dcm(e, c);
        gm_imu(t - 2.0 * d, wm2, f);
        gm_imu(t - d, wm1, f);
        gm_imu(t + d, wp1, f);
        gm_imu(t + 2.0 * d, wp2, f);
        for (i = 0; i < 3; i++) {
            w3[i] = (wp2[i] - 2.0 * wp1[i] + 2.0 * wm1[i] - wm2[i]) / (2.0 * d * d * d);
        }
        for (i = 0; i < 3; i++) {
            double v = 0.0;
            for (j = 0; j < 3; j++) {
                v += c[i][j] * w3[j];
            }
            acc[i] += (k == 0 || k == N ? 0.5 : 1.0) * h * v;
        }
    }
    return dt * dt * dt / 24.0 * sqrt(acc[0] * acc[0] + acc[1] * acc[1] + acc[2] * acc[2]);
}

/* The size bounds (derived, not measured numbers): the
 * velocity error's leading term is the second-order rotation term the
 * algorithm leaves out, lv = -(dt^2 / 6) int w_n x (w_n x f_n) dt (as for
 * test_rotating_acceleration, here along the motion: gm_lead); the
 * position's is its integral plus the trapezoid's (dt^2 / 12) (a(T) - a(0)).
 * In double each error vector is checked against its leading term: the
 * remainder must be third order (100 -> 200 Hz ratio 6..10; measured 8.0)
 * and, so, at 200 Hz within the 100 Hz remainder / 6 (the leading term is
 * analytic: a wrong coefficient of the same order fails here, not in the
 * order checks). The attitude's third-order error has two terms of the same
 * order: the quadratic rate integration's -(dt^3 / 24) int C_nb w''' dt
 * (the Lagrange remainder integrated over a step: w''' / 6 h^4 int_0^1
 * (s + 1) s (s - 1) ds = -h^4 w''' / 24; gm_att_lead, 6.9e-9 rad at 200 Hz)
 * and the coning correction's residual, not derived here; the bound is 3
 * times the first (measured 1.45 and 0.95 times it). Float: the same
 * leading terms with 10 % for the third-order remainder (the double build
 * measures under 2 %), plus one ulp per step (2000 steps at 200 Hz) on the
 * attitude, carried into velocity and position through g over the 10 s. */
static void test_general_motion(void **state)
{
    int mean;
    (void)state;
    for (mean = 0; mean <= 1; mean++) {
        double e1[3], e2[3], lv1[3], lp1[3], lv2[3], lp2[3], dv1[3], dp1[3], rv[2] = { 0, 0 }, rp[2] = { 0, 0 };
        double nv = 0.0, np = 0.0, att;
        int i;
        general_motion(100.0, mean, 1, e1);
        for (i = 0; i < 3; i++) {
            dv1[i] = g_gm_dv[i];
            dp1[i] = g_gm_dp[i];
        }
        general_motion(200.0, mean, 1, e2);
        gm_lead(10.0, 1.0 / 100.0, lv1, lp1);
        gm_lead(10.0, 1.0 / 200.0, lv2, lp2);
        att = gm_att_lead(10.0, 1.0 / 200.0);
        for (i = 0; i < 3; i++) {
            rv[0] += (dv1[i] - lv1[i]) * (dv1[i] - lv1[i]);
            rp[0] += (dp1[i] - lp1[i]) * (dp1[i] - lp1[i]);
            rv[1] += (g_gm_dv[i] - lv2[i]) * (g_gm_dv[i] - lv2[i]);
            rp[1] += (g_gm_dp[i] - lp2[i]) * (g_gm_dp[i] - lp2[i]);
            nv += lv2[i] * lv2[i];
            np += lp2[i] * lp2[i];
        }
        nv = sqrt(nv);
        np = sqrt(np);
        print_message("general motion, %s: 100 Hz %.3e rad %.3e m/s %.3e m; 200 Hz %.3e rad %.3e m/s %.3e m\n",
                      mean ? "means" : "instantaneous", e1[0], e1[1], e1[2], e2[0], e2[1], e2[2]);
        print_message("  200 Hz leading terms %.3e rad (rate integration) %.3e m/s %.3e m; remainders %.2g %% and "
                      "%.2g %% of them (100 Hz: %.2g %%, %.2g %%)\n",
                      att, nv, np, 100.0 * sqrt(rv[1]) / nv, 100.0 * sqrt(rp[1]) / np, 100.0 * sqrt(rv[0]) / nv / 4.0,
                      100.0 * sqrt(rp[0]) / np / 4.0);
#if FNAV_USE_DOUBLE
        /* orders: third for the attitude, second for velocity and position */
        assert_true(e1[0] / e2[0] > 6.0 && e1[0] / e2[0] < 10.0);
        assert_true(e1[1] / e2[1] > 3.5 && e1[1] / e2[1] < 4.5);
        assert_true(e1[2] / e2[2] > 3.5 && e1[2] / e2[2] < 4.5);
        /* the leading terms: what is left of the errors is third order */
        assert_true(sqrt(rv[0] / rv[1]) > 6.0 && sqrt(rv[0] / rv[1]) < 10.0);
        assert_true(sqrt(rp[0] / rp[1]) > 6.0 && sqrt(rp[0] / rp[1]) < 10.0);
        for (i = 0; i < 3; i++) {
            FNAV_ASSERT_CLOSE(g_gm_dv[i], lv2[i], sqrt(rv[0]) / 6.0, 0.0);
            FNAV_ASSERT_CLOSE(g_gm_dp[i], lp2[i], sqrt(rp[0]) / 6.0, 0.0);
        }
        assert_true(e2[0] < 3.0 * att);
#else
        assert_true(e2[0] < 3.0 * att + 2000.0 * EPS);
        assert_true(e2[1] < 1.1 * nv + 2000.0 * EPS * k_g * 10.0);
        assert_true(e2[2] < 1.1 * np + 2000.0 * EPS * k_g * 10.0 * 10.0);
#endif
    }
}

/* Classical sculling: the body rolls phi = 0.05 sin(W t) (W = 2 pi 5 Hz)
 * while it accelerates along n's y axis in phase, a_y = 5 sin(W t) m/s^2,
 * closed-form truth as test_general_motion's (no vertical motion). In the
 * body the two rectify into a mean vertical specific force of phi A / 2 =
 * 0.125 m/s^2 that the strapdown must attribute to the rotation; the
 * sculling term is what does it between samples. At 100 Hz (W dt = 0.31
 * rad) over 10 s, with config.coning = 0 (no sculling; no coning either,
 * which a rotation about one axis does not have: the attitude error is the
 * same with and without), measured in double: instantaneous 6.8e-3 m/s
 * with the term, 2.27e-2 without; means 2.4e-3 against 2.15e-2. With the
 * sign of either sculling term flipped (hand-made mutants) the error is
 * 4.2e-2 and 4.1e-2 m/s, worse than none: without this test, the interval
 * means' flipped sign passes every test of this file (test_simnav sees it).
 * The bounds: under half (instantaneous) and a fifth (means) of the error
 * without the term, plus float rounding (an ulp of g dt per step). */
static void test_sculling(void **state)
{
    int mean;
    (void)state;
    g_gm_motion = 1;
    for (mean = 0; mean <= 1; mean++) {
        double on[3], off[3];
        general_motion(100.0, mean, 1, on);
        general_motion(100.0, mean, 0, off);
        print_message("sculling, %s: with %.3e rad %.3e m/s %.3e m; without %.3e rad %.3e m/s %.3e m\n",
                      mean ? "means" : "instantaneous", on[0], on[1], on[2], off[0], off[1], off[2]);
        assert_true(off[1] > 0.015); /* the motion does scull */
        assert_true(on[1] < (mean ? 0.2 : 0.5) * off[1] + 1000.0 * EPS * k_g * 0.01);
    }
    g_gm_motion = 0;
}

static void test_gravity(void **state)
{
    /* the published values have 10 decimals: 1e-10 is their own precision */
    (void)state;
    FNAV_ASSERT_CLOSE(fnav_gravity_wgs84(FNAV_R(0.0), FNAV_R(0.0)), 9.7803253359, 1e-10 + 2.0 * EPS * 10.0, 0.0);
    FNAV_ASSERT_CLOSE(fnav_gravity_wgs84((fnav_real_t)(3.14159265358979 / 2.0), FNAV_R(0.0)), 9.8321849378,
                      1e-10 + 4.0 * EPS * 10.0, 0.0);
    /* free-air: 1000 m lowers g by 3.086 mm/s^2 */
    FNAV_ASSERT_CLOSE(fnav_gravity_wgs84(FNAV_R(0.0), FNAV_R(0.0)) - fnav_gravity_wgs84(FNAV_R(0.0), FNAV_R(1000.0)),
                      3.086e-3, 4.0 * EPS * 10.0, 0.0);
}

/* The trig-free series agrees with the exact quaternion across its range. */
static void test_quat_exp_series(void **state)
{
    int i;
    (void)state;
    for (i = 0; i <= 40; i++) {
        double a = 0.2 * i / 40.0;
        fnav_vec3_t phi = fnav_vec3((fnav_real_t)(0.6 * a), (fnav_real_t)(-0.48 * a), (fnav_real_t)(0.64 * a));
        fnav_quat_t s = fnav_strapdown_quat_exp(phi);
        double ang = sqrt(fnav_vec3_dot(phi, phi));
        /* a few ulp (the series and libm each round once or twice) plus the
         * truncation, bounded by the first omitted term a^8 / 10321920 */
        double tol = 4.0 * EPS + pow(ang, 8.0) / 10321920.0;
        FNAV_ASSERT_CLOSE(s.q[0], cos(0.5 * ang), tol, 0.0);
        FNAV_ASSERT_CLOSE(s.q[1], ang > 0 ? sin(0.5 * ang) * (double)phi.v[0] / ang : 0.0, tol, 0.0);
        FNAV_ASSERT_CLOSE(s.q[3], ang > 0 ? sin(0.5 * ang) * (double)phi.v[2] / ang : 0.0, tol, 0.0);
    }
}

/* Beyond 0.2 rad the exponential wraps, halves and squares instead of
 * calling libm trigonometry: it still equals the exact quaternion of the
 * rotation (up to sign), for angles up to many turns, and stays total. */
static void test_quat_exp_large(void **state)
{
    static const double angles[] = { 0.2001, 0.35, 0.7, 1.5, 3.0, 3.14, 3.2, 6.0, 6.2831, 10.0, 100.0, 12345.6 };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof angles / sizeof angles[0]; i++) {
        double a = angles[i];
        fnav_vec3_t phi = fnav_vec3((fnav_real_t)(0.6 * a), (fnav_real_t)(-0.48 * a), (fnav_real_t)(0.64 * a));
        fnav_quat_t q = fnav_strapdown_quat_exp(phi);
        double ang = sqrt((double)fnav_vec3_dot(phi, phi)); /* the angle as rounded into phi */
        double c = cos(0.5 * ang), sn = sin(0.5 * ang);
        double sg = ((double)q.q[0] * c >= 0.0) ? 1.0 : -1.0; /* q and -q are the same rotation */
        /* each of at most 4 squarings doubles the error of the halved
         * angle's series: rounding (a few ulp) and truncation (at most
         * 0.2^8 / 10321920 = 2.5e-13); angles beyond pi also lose what
         * rounding lost in wrapping them (ulp of the angle) */
        double tol = 64.0 * EPS * (1.0 + ang) + 16.0 * pow(0.2, 8.0) / 10321920.0;
        FNAV_ASSERT_CLOSE(sg * (double)q.q[0], c, tol, 0.0);
        FNAV_ASSERT_CLOSE(sg * (double)q.q[1], sn * (double)phi.v[0] / ang, tol, 0.0);
        FNAV_ASSERT_CLOSE(sg * (double)q.q[2], sn * (double)phi.v[1] / ang, tol, 0.0);
        FNAV_ASSERT_CLOSE(sg * (double)q.q[3], sn * (double)phi.v[2] / ang, tol, 0.0);
    }
    {
        fnav_quat_t q = fnav_strapdown_quat_exp(fnav_vec3((fnav_real_t)NAN, FNAV_R(0.0), FNAV_R(0.0)));
        assert_true(q.q[0] == FNAV_R(1.0));
        q = fnav_strapdown_quat_exp(fnav_vec3((fnav_real_t)INFINITY, FNAV_R(0.0), FNAV_R(0.0)));
        assert_true(q.q[0] == FNAV_R(1.0));
        q = fnav_strapdown_quat_exp(fnav_vec3(FNAV_R(1.0e30), FNAV_R(0.0), FNAV_R(0.0)));
        assert_true(fnav_isfinite(q.q[0]) && fnav_isfinite(q.q[1]));
    }
}

/* NaN, negative dt and an overflowing step are rejected and leave the state
 * as it was. */
static void test_bad_input(void **state)
{
    fnav_strapdown_state_t x = state_at(fnav_quat_identity());
    fnav_strapdown_state_t x0 = x;
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_vec3_t nanv = fnav_vec3((fnav_real_t)NAN, FNAV_R(0.0), FNAV_R(0.0));
    (void)state;
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, nanv, fnav_vec3_zero(), FNAV_R(0.01)),
                     FNAV_E_NANINF);
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, fnav_vec3_zero(), nanv, FNAV_R(0.01)),
                     FNAV_E_NANINF);
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, fnav_vec3_zero(), fnav_vec3_zero(),
                                         (fnav_real_t)INFINITY),
                     FNAV_E_NANINF);
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, fnav_vec3_zero(), fnav_vec3_zero(),
                                         FNAV_R(-0.01)),
                     FNAV_E_TIME);
    /* finite readings and dt that overflow the state: refused, nothing
     * changed (not FNAV_OK with an infinite state) */
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, fnav_vec3_zero(),
                                         fnav_vec3(FNAV_R(1.0e3), FNAV_R(0.0), FNAV_R(0.0)), fnav_sqrt(FNAV_REAL_MAX)),
                     FNAV_E_RANGE);
    assert_memory_equal(&x, &x0, sizeof x);
    assert_int_equal(h.valid, 0);
    /* dt = 0 is a valid no-op */
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, &h, fnav_vec3(FNAV_R(1.0), FNAV_R(0.0), FNAV_R(0.0)),
                                         fnav_vec3(FNAV_R(3.0), FNAV_R(0.0), FNAV_R(0.0)), FNAV_R(0.0)),
                     FNAV_OK);
    assert_true(quat_angle_between(x.q_nb, x0.q_nb) < 2.0 * EPS);
    FNAV_ASSERT_CLOSE(fnav_vec3_norm(x.vel_mps), 0.0, 0.0, 0.0);
    assert_int_equal(h.valid, 0);
}

/* NULL pointers and a configuration out of its domain: FNAV_E_ARG, state
 * and history unchanged: not FNAV_ASSERT for a NULL cfg or x (a crash with
 * FNAV_ENABLE_ASSERT=0), not FNAV_OK for a gravity of 0 or -9.8 m/s^2 or an
 * unknown sample type (gravity pulling up; the interval-mean increments),
 * not FNAV_E_RANGE for a NaN or infinite gravity, as if the readings had
 * overflowed the state. */
static void test_bad_args(void **state)
{
    fnav_strapdown_state_t x = state_at(fnav_quat_identity());
    fnav_strapdown_state_t x0 = x;
    fnav_strapdown_hist_t h = { { { 0 } }, { { 0 } }, { { 0 } }, { { 0 } }, FNAV_R(0.0), 0, 0 };
    fnav_strapdown_hist_t h0 = h;
    const fnav_vec3_t w = fnav_vec3(FNAV_R(0.1), FNAV_R(0.0), FNAV_R(0.0));
    const fnav_vec3_t f = fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), (fnav_real_t)-k_g);
    const fnav_real_t bad_g[4] = { FNAV_R(0.0), (fnav_real_t)-k_g, (fnav_real_t)NAN, (fnav_real_t)INFINITY };
    fnav_strapdown_config_t c;
    int i;
    (void)state;
    assert_int_equal(fnav_strapdown_step(NULL, &x, &h, w, f, FNAV_R(0.01)), FNAV_E_ARG);
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, NULL, &h, w, f, FNAV_R(0.01)), FNAV_E_ARG);
    for (i = 0; i < 4; i++) {
        c = fnav_strapdown_config_default;
        c.gravity_mps2 = bad_g[i];
        assert_int_equal(fnav_strapdown_step(&c, &x, &h, w, f, FNAV_R(0.01)), FNAV_E_ARG);
    }
    c = fnav_strapdown_config_default;
    c.sample_type = (fnav_sample_type_t)2;
    assert_int_equal(fnav_strapdown_step(&c, &x, &h, w, f, FNAV_R(0.01)), FNAV_E_ARG);
    assert_memory_equal(&x, &x0, sizeof x);
    assert_memory_equal(&h, &h0, sizeof h);
    /* the history is optional (NULL: the reading held over the interval) */
    assert_int_equal(fnav_strapdown_step(&fnav_strapdown_config_default, &x, NULL, w, f, FNAV_R(0.01)), FNAV_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rest),
        cmocka_unit_test(test_constant_rotation),
        cmocka_unit_test(test_constant_acceleration),
        cmocka_unit_test(test_rotating_acceleration),
        cmocka_unit_test(test_rotating_acceleration_instant),
        cmocka_unit_test(test_coning),
        cmocka_unit_test(test_coning_instant),
        cmocka_unit_test(test_instant_coning_off),
        cmocka_unit_test(test_general_motion),
        cmocka_unit_test(test_sculling),
        cmocka_unit_test(test_gravity),
        cmocka_unit_test(test_quat_exp_series),
        cmocka_unit_test(test_quat_exp_large),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_bad_args),
    };
    return cmocka_run_group_tests_name("strapdown", tests, NULL, NULL);
}
