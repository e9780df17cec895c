/* Strapdown inertial navigation in a local-level frame (fnav_strapdown.h). */
#include "footnav/fnav_strapdown.h"
#include "footnav/fnav_port.h"

const fnav_strapdown_config_t fnav_strapdown_config_default = {
    FNAV_R(9.80665),    /* gravity_mps2: standard gravity, m/s^2 */
    1,                  /* coning: coning and sculling terms */
    FNAV_SAMPLE_INSTANT /* sample_type: rate-output sensors */
};

fnav_real_t fnav_gravity_wgs84(fnav_real_t lat_rad, fnav_real_t height_m)
{
    /* Somigliana closed form (Moritz 1980, WGS-84 constants):
     * g = ge (1 + k sin^2 lat) / sqrt(1 - e^2 sin^2 lat), then the free-air
     * gradient -3.086e-6 s^-2 (Groves 2013, eq. 2.134 first order). */
    const fnav_real_t ge = FNAV_R(9.7803253359);
    const fnav_real_t k = FNAV_R(0.00193185265241);
    const fnav_real_t e2 = FNAV_R(0.00669437999013);
    fnav_real_t s = fnav_sin(lat_rad);
    fnav_real_t s2 = s * s;
    return ge * (FNAV_R(1.0) + k * s2) / fnav_sqrt(FNAV_R(1.0) - e2 * s2) - FNAV_R(3.086e-6) * height_m;
}

fnav_quat_t fnav_strapdown_quat_exp(fnav_vec3_t phi)
{
    fnav_real_t a2 = fnav_vec3_dot(phi, phi);
    fnav_real_t c, s;
    fnav_quat_t q;
    int k = 0;
    if (!(a2 <= FNAV_R(0.04))) {
        /* Larger increments (over 0.2 rad, i.e. above about 2300 deg/s at
         * 200 Hz) without libm trigonometry, whose large-argument reduction
         * is the deepest stack path on a Cortex-M: the same rotation with
         * the angle wrapped to (-pi, pi] (fmod is exact), halved until the
         * series below is exact, then squared back (q(2x) = q(x)^2 about the
         * same axis). NaN or Inf give the identity (the UKF rejects them
         * before this point; this only keeps the function total). */
        fnav_real_t a = fnav_sqrt(a2);
        if (!fnav_isfinite(a)) {
            return fnav_quat_identity();
        }
        if (a > FNAV_PI) {
            fnav_real_t w = fnav_wrap_pi(a);
            phi = fnav_vec3_scale(phi, w / a);
            a2 = w * w;
        }
        while (a2 > FNAV_R(0.04)) { /* at most 4 halvings: pi / 2^4 < 0.2 */
            phi = fnav_vec3_scale(phi, FNAV_R(0.5));
            a2 *= FNAV_R(0.25);
            k++;
        }
    }
    /* cos(a/2) and sin(a/2)/a as series in a^2 (Titterton & Weston eq. 11.33);
     * the first omitted terms are a^8/10321920 and a^8/185794560. */
    c = FNAV_R(1.0) + a2 * (-FNAV_R(1.0) / FNAV_R(8.0) +
                            a2 * (FNAV_R(1.0) / FNAV_R(384.0) - a2 * (FNAV_R(1.0) / FNAV_R(46080.0))));
    s = FNAV_R(0.5) + a2 * (-FNAV_R(1.0) / FNAV_R(48.0) +
                            a2 * (FNAV_R(1.0) / FNAV_R(3840.0) - a2 * (FNAV_R(1.0) / FNAV_R(645120.0))));
    q = fnav_quat(c, s * phi.v[0], s * phi.v[1], s * phi.v[2]);
    while (k-- > 0) {
        q = fnav_quat_mul(q, q);
    }
    return q;
}

void fnav_strapdown_increments(const fnav_strapdown_config_t *cfg, const fnav_strapdown_hist_t *hist,
                               fnav_vec3_t gyro_rps, fnav_vec3_t accel_mps2, fnav_real_t dt_s,
                               fnav_strapdown_incr_t *out)
{
    const fnav_real_t k12 = FNAV_R(1.0) / FNAV_R(12.0);
    int have_prev = hist != NULL && hist->valid;
    int have_sample = hist != NULL && hist->have_sample;
    out->dt_s = dt_s;
    out->w_rps = gyro_rps;
    out->f_mps2 = accel_mps2;
    out->coning = fnav_vec3_zero();
    out->scull = fnav_vec3_zero();
    if (cfg->sample_type == FNAV_SAMPLE_INSTANT && have_sample) {
        /* Readings w0, f0 at the start and w1, f1 at the end of the interval,
         * linear in between: w(t) = w0 + (w1 - w0) t / T, likewise f.
         * theta(t) = int w, v(t) = int f. Then theta = (w0 + w1) T / 2,
         * dv = (f0 + f1) T / 2, and the second-order terms
         *   coning    = 1/2 int theta x w dt               = (1/12) (w0 T) x (w1 T),
         *   sculling  = int theta x f dt - 1/2 theta x dv  = (1/12) ((w0 T) x (f1 T) + (f0 T) x (w1 T))
         * (the integrals of the linear profiles, exact; Savage 1998 eq.
         * 7.1.1.1-1 and 7.2.2.2-10 for the definitions). */
        fnav_vec3_t a0 = fnav_vec3_scale(hist->w_rps, dt_s), a1 = fnav_vec3_scale(gyro_rps, dt_s);
        fnav_vec3_t v0 = fnav_vec3_scale(hist->f_mps2, dt_s), v1 = fnav_vec3_scale(accel_mps2, dt_s);
        fnav_real_t h = dt_s, h1 = hist->dt_prev_s;
        if (hist->have_sample >= 2 && h1 > FNAV_R(0.0) && h <= FNAV_R(2.0) * h1 && h1 <= FNAV_R(2.0) * h) {
            /* integral over [t_k-1, t_k] of the quadratic through the
             * readings at t_k-2 = t_k-1 - h1, t_k-1, t_k = t_k-1 + h
             * (Lagrange weights integrated):
             *   c2 = -h^3 / (6 h1 (h1 + h)), c1 = h^2 / (6 h1) + h / 2,
             *   c0 = (h^2 / 3 + h1 h / 2) / (h + h1);
             * h1 = h: h/12 (-1, 8, 5). Third order: the trapezoid's
             * attenuation of a fast rotating rate (coning) is O(dt^2). */
            fnav_real_t c2 = -h * h * h / (FNAV_R(6.0) * h1 * (h1 + h));
            fnav_real_t c1 = h * h / (FNAV_R(6.0) * h1) + FNAV_R(0.5) * h;
            fnav_real_t c0 = (h * h / FNAV_R(3.0) + FNAV_R(0.5) * h1 * h) / (h + h1);
            out->theta_rad = fnav_vec3_add(fnav_vec3_add(fnav_vec3_scale(hist->w2_rps, c2), fnav_vec3_scale(hist->w_rps, c1)),
                                           fnav_vec3_scale(gyro_rps, c0));
            out->dv_mps = fnav_vec3_add(fnav_vec3_add(fnav_vec3_scale(hist->f2_mps2, c2), fnav_vec3_scale(hist->f_mps2, c1)),
                                        fnav_vec3_scale(accel_mps2, c0));
        } else {
            out->theta_rad = fnav_vec3_scale(fnav_vec3_add(a0, a1), FNAV_R(0.5));
            out->dv_mps = fnav_vec3_scale(fnav_vec3_add(v0, v1), FNAV_R(0.5));
        }
        if (cfg->coning) {
            out->coning = fnav_vec3_scale(fnav_vec3_cross(a0, a1), k12);
            out->scull = fnav_vec3_scale(fnav_vec3_add(fnav_vec3_cross(a0, v1), fnav_vec3_cross(v0, a1)), k12);
        }
        return;
    }
    out->theta_rad = fnav_vec3_scale(gyro_rps, dt_s);
    out->dv_mps = fnav_vec3_scale(accel_mps2, dt_s);
    if (cfg->sample_type == FNAV_SAMPLE_MEAN && cfg->coning && have_prev) {
        /* Savage 1998, two-sample algorithms with the previous interval:
         * coning (eq. 7.1.1.1-13 form) and sculling (eq. 7.2.2.2-22 form). */
        fnav_vec3_t th_p = fnav_vec3_scale(hist->w_rps, hist->dt_prev_s); /* the previous interval's */
        fnav_vec3_t dv_p = fnav_vec3_scale(hist->f_mps2, hist->dt_prev_s); /* increments */
        out->coning = fnav_vec3_scale(fnav_vec3_cross(th_p, out->theta_rad), k12);
        out->scull = fnav_vec3_scale(fnav_vec3_add(fnav_vec3_cross(th_p, out->dv_mps), fnav_vec3_cross(dv_p, out->theta_rad)),
                                     k12);
    }
}

void fnav_strapdown_hist_push(fnav_strapdown_hist_t *hist, const fnav_strapdown_incr_t *inc)
{
    if (inc->dt_s > FNAV_R(0.0)) {
        if (hist->have_sample >= 1) {
            hist->w2_rps = hist->w_rps;
            hist->f2_mps2 = hist->f_mps2;
            hist->have_sample = 2;
        } else {
            hist->have_sample = 1;
        }
        hist->dt_prev_s = inc->dt_s;
        hist->valid = 1;
    } else if (hist->have_sample == 0) {
        hist->have_sample = 1;
    }
    hist->w_rps = inc->w_rps;
    hist->f_mps2 = inc->f_mps2;
}

void fnav_strapdown_propagate(const fnav_strapdown_config_t *cfg, fnav_strapdown_state_t *x,
                              const fnav_strapdown_incr_t *inc, fnav_vec3_t d_theta, fnav_vec3_t d_dv)
{
    fnav_vec3_t th = fnav_vec3_add(inc->theta_rad, d_theta);
    fnav_vec3_t dv = fnav_vec3_add(inc->dv_mps, d_dv);
    fnav_vec3_t phi = fnav_vec3_add(th, inc->coning);
    /* rotation compensation (T&W eq. 11.29 with the half-interval rotation) */
    fnav_vec3_t dvc = fnav_vec3_add(fnav_vec3_add(dv, fnav_vec3_scale(fnav_vec3_cross(th, dv), FNAV_R(0.5))),
                                    inc->scull);
    fnav_vec3_t dv_n = fnav_quat_rotate(x->q_nb, dvc);
    fnav_vec3_t v0 = x->vel_mps;
    fnav_quat_t q;
    fnav_real_t n2;
    dv_n.v[2] += cfg->gravity_mps2 * inc->dt_s; /* g_n = (0, 0, +g), z down */
    x->vel_mps = fnav_vec3_add(v0, dv_n);
    x->pos_m = fnav_vec3_add(x->pos_m, fnav_vec3_scale(fnav_vec3_add(v0, x->vel_mps), FNAV_R(0.5) * inc->dt_s));
    q = fnav_quat_mul(x->q_nb, fnav_strapdown_quat_exp(phi));
    /* one Newton step towards unit norm: |q| stays within 1e-7 of 1 without
     * a square root (the product of unit quaternions drifts by rounding only) */
    n2 = q.q[0] * q.q[0] + q.q[1] * q.q[1] + q.q[2] * q.q[2] + q.q[3] * q.q[3];
    n2 = FNAV_R(0.5) * (FNAV_R(3.0) - n2);
    x->q_nb = fnav_quat(q.q[0] * n2, q.q[1] * n2, q.q[2] * n2, q.q[3] * n2);
}

fnav_status_t fnav_strapdown_step(const fnav_strapdown_config_t *cfg, fnav_strapdown_state_t *x,
                                  fnav_strapdown_hist_t *hist, fnav_vec3_t gyro_rps, fnav_vec3_t accel_mps2,
                                  fnav_real_t dt_s)
{
    fnav_strapdown_incr_t inc;
    fnav_strapdown_state_t y;
    /* a public function returning a status: NULL and a configuration out
     * of its domain (a gravity of 0 or below, an unknown sample type) are
     * FNAV_E_ARG, not an FNAV_ASSERT (test_strapdown test_bad_args) */
    if (cfg == NULL || x == NULL || !fnav_isfinite(cfg->gravity_mps2) || !(cfg->gravity_mps2 > FNAV_R(0.0)) ||
        (cfg->sample_type != FNAV_SAMPLE_INSTANT && cfg->sample_type != FNAV_SAMPLE_MEAN)) {
        return FNAV_E_ARG;
    }
    if (!fnav_vec3_isfinite(gyro_rps) || !fnav_vec3_isfinite(accel_mps2) || !fnav_isfinite(dt_s)) {
        return FNAV_E_NANINF;
    }
    if (dt_s < FNAV_R(0.0)) {
        return FNAV_E_TIME;
    }
    fnav_strapdown_increments(cfg, hist, gyro_rps, accel_mps2, dt_s, &inc);
    y = *x;
    fnav_strapdown_propagate(cfg, &y, &inc, fnav_vec3_zero(), fnav_vec3_zero());
    /* finite readings and dt can still overflow (a dt of 1e30 s would
     * otherwise return FNAV_OK with an infinite state) */
    if (!fnav_vec3_isfinite(y.vel_mps) || !fnav_vec3_isfinite(y.pos_m) ||
        !fnav_isfinite(y.q_nb.q[0] + y.q_nb.q[1] + y.q_nb.q[2] + y.q_nb.q[3])) {
        return FNAV_E_RANGE;
    }
    *x = y;
    if (hist != NULL) {
        fnav_strapdown_hist_push(hist, &inc);
    }
    return FNAV_OK;
}
