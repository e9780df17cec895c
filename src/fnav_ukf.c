/* 15-state unscented Kalman filter (USQUE-style attitude error), ZUPT/ZARU
 * updates in Joseph form, AR(1) biases (fnav_ukf.h). */
#include "footnav/fnav_ukf.h"
#include "footnav/fnav_port.h"

#define N FNAV_UKF_NMAX

/* NavChip noise densities of paper Table IV, converted (tau in samples at
 * 200 Hz -> s; deg -> rad). fnav_nav normally fills these from a profile. */
const fnav_ukf_config_t fnav_ukf_config_default = {
    { FNAV_R(3.3e-3) * FNAV_DEG2RAD, FNAV_R(3.7e-3) * FNAV_DEG2RAD, FNAV_R(4.2e-3) * FNAV_DEG2RAD },
    { FNAV_R(7.4e-4), FNAV_R(6.4e-4), FNAV_R(5.0e-4) },
    FNAV_BIAS_AR1,
    { FNAV_R(5.0), FNAV_R(5.0), FNAV_R(50.0) },
    { FNAV_R(10.0), FNAV_R(10.0), FNAV_R(10.0) },
    { FNAV_R(8.5e-5) * FNAV_DEG2RAD, FNAV_R(6.4e-5) * FNAV_DEG2RAD, FNAV_R(3.4e-5) * FNAV_DEG2RAD },
    { FNAV_R(1.3e-5), FNAV_R(9.7e-6), FNAV_R(7.3e-6) },
    { FNAV_R(9.80665), 1, FNAV_SAMPLE_INSTANT },
    FNAV_R(1.0), FNAV_R(2.0), FNAV_R(0.0),
    FNAV_R(0.01),
    FNAV_R(0.01),
    1,
    0,
    FNAV_R(0.1),
    FNAV_R(0.002),
    0,
    FNAV_R(0.025),
    FNAV_R(0.03),
    FNAV_R(11.34) /* zaru_gate: chi-square, 3 dof, 99 % (11.345) */
};

static int finite_nonneg(fnav_real_t x)
{
    return fnav_isfinite(x) && x >= FNAV_R(0.0);
}

static int finite_pos(fnav_real_t x)
{
    return fnav_isfinite(x) && x > FNAV_R(0.0);
}

/* A standard deviation whose variance is finite and positive as well (in
 * float32 an sd below about 2.6e-23 has a variance of 0, one above 1.8e19 an
 * infinite one, which the guard would make the maximum). */
static int sd_ok(fnav_real_t x)
{
    return finite_pos(x) && finite_pos(x * x);
}

/* A white-noise density or random walk (0 allowed) whose square, which the
 * prediction adds to the covariance, is finite (in float32 one above
 * 1.8e19 would make the first prediction's variance infinite and the guard
 * its maximum). */
static int noise_ok(fnav_real_t x)
{
    return finite_nonneg(x) && fnav_isfinite(x * x);
}

/* Active states of a configuration: velocity, position, attitude, the
 * biases with the AR(1) model, the lever. */
static inline FNAV_ALWAYS_INLINE int ukf_states(const fnav_ukf_config_t *cfg)
{
    return 9 + (cfg->bias_model == FNAV_BIAS_AR1 ? 6 : 0) + (cfg->lever ? 3 : 0);
}

/* n + lambda = alpha^2 (n + kappa), formed as that product: as n +
 * (alpha^2 (n + kappa) - n) it cancelled in float32 down to the spacing
 * of n (9.5e-7 at 15), 1.7 % off the weights at alpha = 1e-3 and 0 at
 * alpha = 1e-4 (refused); the defaults give lambda = 0 both ways
 * (test_ukf test_weights_small_alpha). gamma is its root. */
static inline FNAV_ALWAYS_INLINE fnav_real_t ukf_nl(const fnav_ukf_config_t *cfg)
{
    return cfg->alpha * cfg->alpha * ((fnav_real_t)ukf_states(cfg) + cfg->kappa);
}

fnav_quat_t fnav_ukf_grp_to_quat(fnav_vec3_t p)
{
    /* Crassidis & Markley 2003, eq. (33) with a = 1, f = 4 */
    fnav_real_t s = fnav_vec3_dot(p, p);
    fnav_real_t inv = FNAV_R(1.0) / (FNAV_R(16.0) + s);
    fnav_real_t w = (FNAV_R(16.0) - s) * inv;
    fnav_real_t k = FNAV_R(8.0) * inv;
    return fnav_quat(w, k * p.v[0], k * p.v[1], k * p.v[2]);
}

fnav_vec3_t fnav_ukf_quat_to_grp(fnav_quat_t q)
{
    /* eq. (32) with a = 1, f = 4: p = 4 q_v / (1 + q_w), q_w >= 0 */
    fnav_real_t k;
    if (q.q[0] < FNAV_R(0.0)) {
        q = fnav_quat(-q.q[0], -q.q[1], -q.q[2], -q.q[3]);
    }
    k = FNAV_R(4.0) / (FNAV_R(1.0) + q.q[0]);
    return fnav_vec3(k * q.q[1], k * q.q[2], k * q.q[3]);
}

/* q' = dq(a) * q, renormalised with one Newton step. */
static fnav_quat_t apply_att(fnav_quat_t q, fnav_vec3_t a)
{
    fnav_quat_t r = fnav_quat_mul(fnav_ukf_grp_to_quat(a), q);
    fnav_real_t n2 = r.q[0] * r.q[0] + r.q[1] * r.q[1] + r.q[2] * r.q[2] + r.q[3] * r.q[3];
    n2 = FNAV_R(0.5) * (FNAV_R(3.0) - n2);
    return fnav_quat(r.q[0] * n2, r.q[1] * n2, r.q[2] * n2, r.q[3] * n2);
}

/* Internal index of the first state of each triple, in packing order. */
static const unsigned char pack_order[6] = { FNAV_UKF_R, FNAV_UKF_V, FNAV_UKF_P, FNAV_UKF_BA, FNAV_UKF_BG, FNAV_UKF_A };

fnav_status_t fnav_ukf_init_tagged(fnav_ukf_t *f, const fnav_ukf_config_t *cfg, uint64_t build_tag, size_t obj_size,
                                   size_t cfg_size)
{
    size_t b;
    unsigned char *p = (unsigned char *)f;
    int i, n;
    fnav_real_t lambda, nl;
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_ukf_t) || cfg_size != sizeof(fnav_ukf_config_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (f == NULL || cfg == NULL) {
        return FNAV_E_ARG;
    }
    if (cfg->bias_model != FNAV_BIAS_AR1 && cfg->bias_model != FNAV_BIAS_OFF) {
        return FNAV_E_CONFIG;
    }
    for (i = 0; i < 3; i++) {
        if (!noise_ok(cfg->gyro_noise_rps_rthz[i]) || !noise_ok(cfg->accel_noise_mps2_rthz[i])) {
            return FNAV_E_CONFIG;
        }
        if (cfg->bias_model == FNAV_BIAS_AR1 &&
            (!finite_pos(cfg->gyro_tau_s[i]) || !finite_pos(cfg->accel_tau_s[i]) ||
             !sd_ok(cfg->gyro_bias_sigma_rps[i]) || !sd_ok(cfg->accel_bias_sigma_mps2[i]))) {
            return FNAV_E_CONFIG;
        }
    }
    if (!finite_pos(cfg->alpha) || !fnav_isfinite(cfg->beta) || !fnav_isfinite(cfg->kappa) ||
        !sd_ok(cfg->zupt_sigma_mps) || !sd_ok(cfg->zaru_sigma_rps) ||
        !finite_pos(cfg->strapdown.gravity_mps2) || (cfg->lever != 0 && cfg->lever != 1) ||
        (cfg->strapdown.sample_type != FNAV_SAMPLE_INSTANT && cfg->strapdown.sample_type != FNAV_SAMPLE_MEAN) ||
        (cfg->lever && (!sd_ok(cfg->lever_sd_m) || !noise_ok(cfg->lever_rw_m_rts))) ||
        (cfg->settle != 0 && cfg->settle != 1) || (cfg->closed_form != 0 && cfg->closed_form != 1) ||
        (cfg->settle && (!sd_ok(cfg->settle_sd_mps) || !finite_pos(cfg->settle_tau_s))) ||
        !finite_nonneg(cfg->zaru_gate)) {
        return FNAV_E_CONFIG;
    }
    n = ukf_states(cfg);
    nl = ukf_nl(cfg);
    lambda = nl - (fnav_real_t)n;
    /* n + lambda > 0: the pair weights Wi are positive; beta >= alpha^2,
     * formed as fnav_ukf_predict forms it: the predicted covariance S +
     * (beta - alpha^2) m m^T is a sum of positive semi-definite terms
     * (fnav_ukf.h); W0m = lambda / (n + lambda) finite, which also refuses
     * an infinite n + lambda (inf / inf) and one so small that W0m
     * overflows (alpha = 3e-20 in float: W0m = -inf; Wi = 0.5 / (n + lambda)
     * is then smaller in magnitude, n >= 9) */
    if (!(nl > FNAV_R(0.0)) || !fnav_isfinite(lambda / nl) || !(cfg->beta - cfg->alpha * cfg->alpha >= FNAV_R(0.0))) {
        return FNAV_E_CONFIG;
    }
    {
        /* every byte to 0 but the configuration's when cfg is the filter's
         * own, &f->cfg (a restart with it, as fnav_nav_init allows): zeroed
         * before the copy, the filter would run with gravity, the ZUPT's
         * sigma and alpha 0, or with the lever hit the assert below
         * (test_ukf test_reinit_own_config) */
        const size_t c0 = offsetof(fnav_ukf_t, cfg), c1 = c0 + sizeof f->cfg;
        const int own = cfg == &f->cfg;
        for (b = 0; b < sizeof *f; b++) {
            if (!own || b < c0 || b >= c1) {
                p[b] = 0;
            }
        }
        if (!own) {
            f->cfg = *cfg;
        }
    }
    f->n_act = 0;
    for (i = 0; i < N; i++) {
        f->pos[i] = -1;
    }
    /* packing order: lever, velocity, position, accelerometer bias, gyro
     * bias, attitude (fnav_ukf.h: every state before the attitude is
     * propagated in closed form) */
    for (b = 0; b < sizeof pack_order; b++) {
        int k0 = pack_order[b];
        int on = (k0 == FNAV_UKF_R && cfg->lever) || k0 == FNAV_UKF_V || k0 == FNAV_UKF_P || k0 == FNAV_UKF_A ||
                 ((k0 == FNAV_UKF_BG || k0 == FNAV_UKF_BA) && cfg->bias_model == FNAV_BIAS_AR1);
        for (i = k0; on && i < k0 + 3; i++) {
            f->pos[i] = (int16_t)f->n_act;
            f->act[f->n_act++] = (unsigned char)i;
        }
    }
    FNAV_ASSERT(f->n_act == n);
    f->n_lin = n - 3;
    f->gamma = fnav_sqrt(nl);
    f->w0m = lambda / nl;
    f->w0c = f->w0m + FNAV_R(1.0) - cfg->alpha * cfg->alpha + cfg->beta;
    f->wi = FNAV_R(0.5) / nl;
    f->q_nb = fnav_quat_identity();
    return FNAV_OK;
}

fnav_real_t fnav_ukf_att_sd_max(const fnav_ukf_config_t *cfg)
{
    fnav_real_t nl;
    if (cfg == NULL) {
        return FNAV_R(0.0);
    }
    nl = ukf_nl(cfg); /* as fnav_ukf_init forms it */
    if (!(nl > FNAV_R(0.0)) || !fnav_isfinite(nl)) {
        return FNAV_R(0.0);
    }
    return FNAV_UKF_ATT_GRP_MAX / fnav_sqrt(nl);
}

/* Covariance element of internal states i, j (0 for an inactive state). */
fnav_real_t fnav_ukf_cov(const fnav_ukf_t *f, int i, int j)
{
    FNAV_ASSERT(f != NULL && i >= 0 && i < N && j >= 0 && j < N);
    if (f->pos[i] < 0 || f->pos[j] < 0) {
        return FNAV_R(0.0);
    }
    return f->P[f->pos[i]][f->pos[j]];
}

/* Set a covariance element (and its mirror) of active internal states. */
void fnav_ukf_set_cov(fnav_ukf_t *f, int i, int j, fnav_real_t v)
{
    FNAV_ASSERT(f != NULL && i >= 0 && i < N && j >= 0 && j < N && f->pos[i] >= 0 && f->pos[j] >= 0);
    f->P[f->pos[i]][f->pos[j]] = v;
    f->P[f->pos[j]][f->pos[i]] = v;
#if FNAV_UKF_YAW_CARRY
    if (i == FNAV_UKF_A + 2 && j == i) {
        f->p_yaw_carry_rad2 = FNAV_R(0.0); /* the remainder belonged to the old yaw variance */
    }
#endif
}

fnav_status_t fnav_ukf_start(fnav_ukf_t *f, fnav_quat_t q_nb, fnav_vec3_t bg_rps, fnav_vec3_t ba_mps2,
                             const fnav_ukf_init_sd_t *sd)
{
    int i, j;
    if (f == NULL || sd == NULL) {
        return FNAV_E_ARG;
    }
    if (f->n_act == 0) {
        /* never initialised (static storage; init sets 9 to 18 states):
         * it would run with a zero configuration, no gravity and no states
         * (test_ukf test_start_not_initialised) */
        return FNAV_E_STATE;
    }
    if (!fnav_vec3_isfinite(bg_rps) || !fnav_vec3_isfinite(ba_mps2) || !fnav_isfinite(q_nb.q[0]) ||
        !fnav_isfinite(q_nb.q[1]) || !fnav_isfinite(q_nb.q[2]) || !fnav_isfinite(q_nb.q[3])) {
        return FNAV_E_NANINF;
    }
    for (i = 0; i < 3; i++) {
        if (!sd_ok(sd->att_rad[i]) || !sd_ok(sd->gyro_bias_rps[i]) || !sd_ok(sd->accel_bias_mps2[i])) {
            return FNAV_E_ARG;
        }
        /* sigma points at gamma sd: beyond FNAV_UKF_ATT_GRP_MAX they near
         * 180 deg, where the prediction folds them back (a yaw sd of 90 deg
         * read 32.4 deg one sample later) */
        if (sd->att_rad[i] * f->gamma > FNAV_UKF_ATT_GRP_MAX) {
            return FNAV_E_ARG;
        }
    }
    if (!sd_ok(sd->vel_mps) || !sd_ok(sd->pos_m)) {
        return FNAV_E_ARG;
    }
    {
        /* a quaternion whose squared norm overflows or underflows is
         * scaled by its largest component first (fnav_quat_normalize makes
         * (1e20, 0, 0, 1e20) the zero quaternion); a unit one is normalised
         * by fnav_quat_normalize */
        fnav_real_t n2 = q_nb.q[0] * q_nb.q[0] + q_nb.q[1] * q_nb.q[1] + q_nb.q[2] * q_nb.q[2] + q_nb.q[3] * q_nb.q[3];
        if (!(n2 > FNAV_REAL_EPSILON) || !fnav_isfinite(n2)) {
            fnav_real_t m = FNAV_R(0.0);
            for (i = 0; i < 4; i++) {
                m = fnav_fabs(q_nb.q[i]) > m ? fnav_fabs(q_nb.q[i]) : m;
            }
            if (!(m > FNAV_R(0.0))) {
                return FNAV_E_ARG; /* the zero quaternion is no attitude */
            }
            for (i = 0; i < 4; i++) {
                q_nb.q[i] /= m;
            }
        }
    }
    f->q_nb = fnav_quat_normalize(q_nb);
    f->vel_mps = fnav_vec3_zero();
    f->pos_m = fnav_vec3_zero();
    f->bg_rps = bg_rps;
    f->ba_mps2 = ba_mps2;
    f->bg0_rps = bg_rps;
    f->ba0_mps2 = ba_mps2;
    f->lever_m = fnav_vec3_zero();
    f->settle_on = 0;
    f->settle_mps = FNAV_R(0.0);
    f->settle_var = FNAV_R(0.0);
#if FNAV_UKF_YAW_CARRY
    f->p_yaw_carry_rad2 = FNAV_R(0.0);
#endif
    f->hist.valid = 0;
    f->hist.have_sample = 0;
    for (i = 0; i < N; i++) {
        for (j = 0; j < N; j++) {
            f->P[i][j] = FNAV_R(0.0);
        }
    }
    for (i = 0; i < 3; i++) {
        fnav_ukf_set_cov(f, FNAV_UKF_V + i, FNAV_UKF_V + i, sd->vel_mps * sd->vel_mps);
        fnav_ukf_set_cov(f, FNAV_UKF_P + i, FNAV_UKF_P + i, sd->pos_m * sd->pos_m);
        fnav_ukf_set_cov(f, FNAV_UKF_A + i, FNAV_UKF_A + i, sd->att_rad[i] * sd->att_rad[i]);
        if (f->cfg.bias_model == FNAV_BIAS_AR1) {
            fnav_ukf_set_cov(f, FNAV_UKF_BG + i, FNAV_UKF_BG + i, sd->gyro_bias_rps[i] * sd->gyro_bias_rps[i]);
            fnav_ukf_set_cov(f, FNAV_UKF_BA + i, FNAV_UKF_BA + i, sd->accel_bias_mps2[i] * sd->accel_bias_mps2[i]);
        }
        if (f->cfg.lever) {
            fnav_ukf_set_cov(f, FNAV_UKF_R + i, FNAV_UKF_R + i, f->cfg.lever_sd_m * f->cfg.lever_sd_m);
        }
    }
    f->started = 1;
    return FNAV_OK;
}

fnav_status_t fnav_ukf_settle_start(fnav_ukf_t *f)
{
    int i;
    if (f == NULL) {
        return FNAV_E_ARG;
    }
    if (!f->started) {
        return FNAV_E_STATE;
    }
    if (f->cfg.settle) {
        for (i = 0; i < f->n_act; i++) {
            f->Pxs[i] = FNAV_R(0.0);
        }
        f->settle_mps = FNAV_R(0.0);
        f->settle_var = f->cfg.settle_sd_mps * f->cfg.settle_sd_mps;
        f->settle_on = 1;
    }
    return FNAV_OK;
}

/* Drop the settling state: marginalising it leaves the other states'
 * mean and covariance as they are. */
static void settle_drop(fnav_ukf_t *f)
{
    f->settle_on = 0;
    f->settle_mps = FNAV_R(0.0);
    f->settle_var = FNAV_R(0.0);
}

/* Upper-triangular Cholesky factor A = U U^T of the leading n x n block
 * (packed states); reads only the upper triangle of A. Column j of U is
 * non-zero in rows 0..j only. Returns 0, or -1 at the first pivot that is
 * not clearly positive. */
static int chol_upper(fnav_real_t A[N][N], fnav_real_t U[N][N], int n)
{
    int i, j;
    for (j = n - 1; j >= 0; j--) {
        fnav_real_t d = A[j][j], inv;
        const fnav_real_t *uj = U[j] + j + 1, *ue = U[j] + n, *p, *q;
        if (uj < ue) {
            p = uj;
            do {
                d -= *p * *p;
                p++;
            } while (p < ue);
        }
        if (!(d > FNAV_REAL_EPSILON * A[j][j]) || !fnav_isfinite(d)) {
            return -1;
        }
        d = fnav_sqrt(d);
        U[j][j] = d;
        inv = FNAV_R(1.0) / d;
        /* four rows at a time, then two (each element of row j loaded once
         * for all; every sum in the same order as row by row) */
        for (i = 0; i + 3 < j; i += 4) {
            fnav_real_t s0 = A[i][j], s1 = A[i + 1][j], s2 = A[i + 2][j], s3 = A[i + 3][j];
            const fnav_real_t *r = U[i + 1] + j + 1, *t = U[i + 2] + j + 1, *w = U[i + 3] + j + 1;
            p = uj;
            q = U[i] + j + 1;
            if (p < ue) {
                do {
                    fnav_real_t x = *p++;
                    s0 -= *q++ * x;
                    s1 -= *r++ * x;
                    s2 -= *t++ * x;
                    s3 -= *w++ * x;
                } while (p < ue);
            }
            U[i][j] = s0 * inv;
            U[i + 1][j] = s1 * inv;
            U[i + 2][j] = s2 * inv;
            U[i + 3][j] = s3 * inv;
        }
        for (; i + 1 < j; i += 2) {
            fnav_real_t s0 = A[i][j], s1 = A[i + 1][j];
            const fnav_real_t *r = U[i + 1] + j + 1;
            p = uj;
            q = U[i] + j + 1;
            if (p < ue) {
                do { /* tested at the bottom: one branch per product pair */
                    s0 -= *q++ * *p;
                    s1 -= *r++ * *p++;
                } while (p < ue);
            }
            U[i][j] = s0 * inv;
            U[i + 1][j] = s1 * inv;
        }
        if (i < j) {
            fnav_real_t sum = A[i][j];
            p = uj;
            q = U[i] + j + 1;
            if (p < ue) {
                do {
                    sum -= *q++ * *p++;
                } while (p < ue);
            }
            U[i][j] = sum * inv;
        }
        for (i = j + 1; i < n; i++) {
            U[i][j] = FNAV_R(0.0);
        }
    }
    return 0;
}

/* Guarded factorisation: 0 ok, 1 ok after jitter, 2 after a reset. */
static int factor(fnav_ukf_t *f)
{
    int n = f->n_act, i, j;
    if (chol_upper(f->P, f->U, n) == 0) {
        return 0;
    }
#if FNAV_UKF_YAW_CARRY
    f->p_yaw_carry_rad2 = FNAV_R(0.0); /* P is changed below (jitter or reset) */
#endif
    for (i = 0; i < n; i++) {
        for (j = i + 1; j < n; j++) {
            fnav_real_t sy = FNAV_R(0.5) * (f->P[i][j] + f->P[j][i]);
            f->P[i][j] = sy;
            f->P[j][i] = sy;
        }
        f->P[i][i] += FNAV_R(1.0e-6) * f->P[i][i];
    }
    if (chol_upper(f->P, f->U, n) == 0) {
        f->health.chol_jitter++;
        return 1;
    }
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            if (i != j) {
                f->P[i][j] = FNAV_R(0.0);
            }
        }
        if (!(f->P[i][i] > FNAV_R(1.0e-20)) || !fnav_isfinite(f->P[i][i])) {
            f->P[i][i] = FNAV_R(1.0e-20);
        }
    }
    f->health.chol_reset++;
    for (i = 0; i < n; i++) {
        f->Pxs[i] = FNAV_R(0.0); /* the settling's cross-covariances too */
    }
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            f->U[i][j] = (i == j) ? fnav_sqrt(f->P[i][i]) : FNAV_R(0.0);
        }
    }
    return 2;
}

static int state_finite(const fnav_strapdown_state_t *x)
{
    return fnav_vec3_isfinite(x->vel_mps) && fnav_vec3_isfinite(x->pos_m) && fnav_isfinite(x->q_nb.q[0]) &&
           fnav_isfinite(x->q_nb.q[1]) && fnav_isfinite(x->q_nb.q[2]) && fnav_isfinite(x->q_nb.q[3]);
}

/* S (upper) += w d d^T + w e e^T and m += w d + w e over the leading nnz
 * packed states: a sigma-point pair in one pass over S, each element
 * receiving d's term before e's (the order of two single updates). */
static void accumulate2(fnav_real_t S[N][N], fnav_real_t *m, const fnav_real_t *d, const fnav_real_t *e, int nnz,
                        fnav_real_t w)
{
    int a;
    for (a = 0; a < nnz; a++) {
        fnav_real_t wd = w * d[a], we = w * e[a];
        fnav_real_t *sa = S[a] + a, *se = S[a] + nnz;
        const fnav_real_t *db = d + a, *eb = e + a;
        m[a] += wd;
        m[a] += we;
        while (sa < se) {
            fnav_real_t v = *sa + wd * *db++;
            *sa++ = v + we * *eb++;
        }
    }
}

/* The closed form's last pass: the six attitude sigma points (their
 * differences D_p, in the order of the columns and signs, in the columns
 * p = 0..5 of D) with the mean m = sum w D_p first, then S (upper) +=
 * sum_p w D_p D_p^T + kmm m m^T and *chk += the new elements, one pass over
 * S. Every element and every m receives its terms in the order of
 * accumulate2 pair by pair followed by the mean's pass. */
static void accumulate6(fnav_real_t S[N][N], fnav_real_t *m, fnav_real_t D[N][N], int n, fnav_real_t w,
                        fnav_real_t kmm, fnav_real_t *chk)
{
    int a, b;
    fnav_real_t c = *chk;
    for (a = 0; a < n; a++) {
        m[a] += w * D[a][0];
        m[a] += w * D[a][1];
        m[a] += w * D[a][2];
        m[a] += w * D[a][3];
        m[a] += w * D[a][4];
        m[a] += w * D[a][5];
    }
    for (a = 0; a < n; a++) {
        const fnav_real_t w0 = w * D[a][0], w1 = w * D[a][1], w2 = w * D[a][2], w3 = w * D[a][3], w4 = w * D[a][4],
                          w5 = w * D[a][5], km = kmm * m[a];
        fnav_real_t *sa = S[a];
        b = a;
        do {
            const fnav_real_t *d = D[b];
            fnav_real_t v = sa[b];
            v += w0 * d[0];
            v += w1 * d[1];
            v += w2 * d[2];
            v += w3 * d[3];
            v += w4 * d[4];
            v += w5 * d[5];
            v += km * m[b];
            c += v;
            sa[b] = v;
        } while (++b < n);
    }
    *chk = c;
}

/* 3x3 block of C diag(dens^2) C^T dt added to the upper triangle of S at the
 * packed offset o; returns the term added to its last diagonal element (o + 2,
 * o + 2). */
static fnav_real_t add_rotated_noise(fnav_real_t S[N][N], int o, fnav_mat3_t C, const fnav_real_t dens[3],
                                     fnav_real_t dt)
{
    int i, j, k;
    fnav_real_t q = FNAV_R(0.0);
    for (i = 0; i < 3; i++) {
        for (j = i; j < 3; j++) {
            fnav_real_t s = FNAV_R(0.0);
            for (k = 0; k < 3; k++) {
                s += C.m[i][k] * C.m[j][k] * dens[k] * dens[k];
            }
            q = s * dt;
            S[o + i][o + j] += q;
        }
    }
    return q;
}

#if FNAV_UKF_YAW_CARRY
/* The yaw variance's prediction as a change of P (fnav_ukf_predict; docs/navigation.md, "The heading's
 * variance stops growing (corrected)"). Re-formed from the sigma points in float, S_yy loses some
 * 3 float spacings (ulps) of itself each prediction: the two yaw points come back 2 ulps of their
 * offset gamma U_yy short through the attitude parameters' round trip (GRP -> quaternion -> GRP),
 * and a stand's share N^2 dt of a few ulps is absorbed. Here the new S_yy is P_yy plus its change:
 *   S_yy = P_yy + s_lin + kl sum_{j >= nl} (2 U_yj b_j + b_j^2) + kmm m_y^2 + q,
 * s_lin the scatter of the points along the columns j < nl (their yaw differences are small and
 * formed without the offset), b_j the yaw the gyro-bias offset of the attitude column j adds, to
 * first order in it: with u = U_a,j (the column's attitude rows) and r = A_g U_bg,j (predict_linear's
 * A_g, bias_maps, as the closed form's columns), the point's difference is the GRP composition of
 * the offset gamma u with the rotation gamma r, whose part odd in the sign of the point is, to first
 * order in r, gamma (u + (1 - gamma^2 |u|^2 / 16) r + gamma^2 (u . r) u / 8) (from the MRP
 * composition rule with p = 4 MRP; the even part, gamma^2 (u x r) / 2, enters the mean and the
 * scatter at second order), so b_j = (1 - gamma^2 |u|^2 / 16) r_y + gamma^2 (u . r) u_y / 8;
 * kl = 2 Wi gamma^2, q the gyro noise's share. In exact arithmetic P_yy = sum_j U_yj^2 and this is
 * the re-formed value to first order in the bias offset. The sum is compensated across
 * predictions: the rounding of P_yy + t (TwoSum, exact) is kept in f->p_yaw_carry_rad2 and added to
 * the next change, otherwise a constant share on a variance with a constant ulp rounds the same
 * way every time (2.63 ulps -> 3, 0.53 -> 1). Not applied (the re-formed value kept, the
 * remainder dropped) when an attitude point may pass 180 degrees (gamma^2 trace P_aa >= 16, the
 * GRP of 180 degrees being 4: the round trip folds such a point) or when P_yy + t is not
 * positive. Returns the remainder to keep; m: the mean of the differences; G: the bias maps (NULL
 * without the biases). */
static fnav_real_t yaw_change(fnav_ukf_t *f, fnav_real_t s_lin, const fnav_real_t *m, fnav_real_t kmm, fnav_real_t q,
                              const fnav_real_t (*G)[3])
{
    const int n = f->n_act, nl = f->n_lin, y = n - 1, oa = f->pos[FNAV_UKF_A], obg = f->pos[FNAV_UKF_BG];
    const fnav_real_t kl = FNAV_R(2.0) * f->wi * f->gamma * f->gamma, p = f->P[y][y];
    fnav_real_t ch = FNAV_R(0.0), t, v, bb;
    int jj;
    if (!(f->gamma * f->gamma * (f->P[oa][oa] + f->P[oa + 1][oa + 1] + p) < FNAV_R(16.0))) {
        return FNAV_R(0.0);
    }
    if (G != NULL) {
        const fnav_real_t g16 = f->gamma * f->gamma * FNAV_R(0.0625), g8 = g16 + g16;
        for (jj = nl; jj < n; jj++) {
            const fnav_real_t u0 = f->U[obg][jj], u1 = f->U[obg + 1][jj], u2 = f->U[obg + 2][jj];
            const fnav_real_t ax = f->U[oa][jj], ay = f->U[oa + 1][jj], az = f->U[y][jj];
            const fnav_real_t bx = G[6][0] * u0 + G[7][0] * u1 + G[8][0] * u2;
            const fnav_real_t by = G[6][1] * u0 + G[7][1] * u1 + G[8][1] * u2;
            const fnav_real_t bz = G[6][2] * u0 + G[7][2] * u1 + G[8][2] * u2;
            const fnav_real_t b = (FNAV_R(1.0) - g16 * (ax * ax + ay * ay + az * az)) * bz +
                                  g8 * (ax * bx + ay * by + az * bz) * az;
            ch += (az + az + b) * b;
        }
    }
    t = s_lin + kl * ch + kmm * m[y] * m[y] + q + f->p_yaw_carry_rad2;
    v = p + t;
    if (!(v > FNAV_R(0.0))) {
        return FNAV_R(0.0);
    }
    f->S[y][y] = v;
    bb = v - p; /* TwoSum: v + the result = p + t exactly */
    return (p - (v - bb)) + (t - bb);
}
#endif

/* P = the upper triangle of A (from the diagonal on), mirrored: row i by
 * pointer, column i by row pointer. Inlined at both uses (a call cost the
 * prediction more than the loop). */
static inline FNAV_ALWAYS_INLINE void mirror_upper(fnav_real_t P[N][N], fnav_real_t A[N][N], int n)
{
    int i;
    for (i = 0; i < n; i++) {
        const fnav_real_t *a = A[i] + i, *ae = A[i] + n;
        fnav_real_t *r = P[i] + i;
        fnav_real_t (*cl)[N] = P + i;
        do {
            fnav_real_t v = *a++;
            *r++ = v;
            (*cl++)[i] = v;
        } while (a < ae);
    }
}

/* Largest standard deviation of each internal state kind (lever, velocity,
 * position, attitude error, gyro bias, accel bias): far beyond any walk,
 * small enough for float32 to keep the covariance's cancellations (updates
 * subtract terms of the size of the variance). */
static fnav_real_t sd_max(int i)
{
    static const fnav_real_t m[6] = { FNAV_R(1.0), FNAV_R(100.0), FNAV_R(1.0e4), FNAV_R(3.14159265), FNAV_R(1.0),
                                      FNAV_R(10.0) };
    return m[i / 3];
}

/* Covariance guard (PX4 EKF2 style): a variance that is not finite or not
 * positive (float32 rounding after a long time without updates) resets its
 * state's row and column to zero and the variance to its maximum; a
 * variance above its maximum is clamped, its row and column scaled by the
 * same factor (the correlations are kept). Counted in health.cov_guard.
 * Nothing changes on a covariance within its limits. Off-diagonal entries
 * need no check: prediction and update reject non-finite results.
 * After an update (r2 > 0, the measurement variance per axis, f->K its
 * gain) a variance that rounding took to zero or below takes, instead of
 * the maximum, its lower bound in exact arithmetic, (K R K^T)_ii =
 * r2 |K_i|^2 (the Joseph form's (I - K H) P (I - K H)^T is positive
 * semi-definite). In float32 a prior variance more than 1 / FLT_EPSILON
 * times the measurement's (a velocity variance above 840 (m/s)^2 with the
 * 0.01 m/s ZUPT, after minutes without a stance) makes S = P + r2 round to
 * P, the gain 1 and the expanded Joseph form P - P - P + P = 0. With the
 * maximum, every later update would do the same (S = 1e4 + 1e-4 rounds to
 * 1e4): the velocity variance would stay at 1e4 (m/s)^2 for the rest of
 * the walk (test_ukf test_zupt_after_long_swing).
 * r2 = 0: the prediction (f->K holds its bias maps; guard_cov(), the
 * branch folded away); inlined in the update, so that the prediction's
 * code and cost stay as they were. */
static inline FNAV_ALWAYS_INLINE void guard_cov_r2(fnav_ukf_t *f, fnav_real_t r2)
{
    int n = f->n_act, i, j;
    for (i = 0; i < n; i++) {
        fnav_real_t mx = sd_max(f->act[i]), v = f->P[i][i];
        if (v > FNAV_R(0.0) && v <= mx * mx) {
            continue; /* the normal case: one comparison pair per state */
        }
        if (!(v > FNAV_R(0.0))) { /* also NaN */
            fnav_real_t lo = FNAV_R(0.0);
            if (r2 > FNAV_R(0.0)) {
                const fnav_real_t *k = f->K[i];
                lo = r2 * (k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
            }
            for (j = 0; j < n; j++) {
                f->P[i][j] = FNAV_R(0.0);
                f->P[j][i] = FNAV_R(0.0);
            }
            f->P[i][i] = (lo > FNAV_R(0.0) && lo <= mx * mx) ? lo : mx * mx;
            f->Pxs[i] = FNAV_R(0.0);
        } else {
            fnav_real_t k = mx / fnav_sqrt(v);
            for (j = 0; j < n; j++) {
                f->P[i][j] *= k;
                f->P[j][i] = f->P[i][j];
            }
            f->P[i][i] = mx * mx;
            f->Pxs[i] *= k;
        }
#if FNAV_UKF_YAW_CARRY
        if (i == n - 1) {
            f->p_yaw_carry_rad2 = FNAV_R(0.0); /* the yaw (packed last) was reset or clamped */
        }
#endif
        f->health.cov_guard++;
    }
}

static void guard_cov(fnav_ukf_t *f)
{
    guard_cov_r2(f, FNAV_R(0.0));
}

/* S (upper) = k sum_{j < nl} u_a,j u_b,j over the rows a, b < na (assigned:
 * the caller clears only the rest of S), the
 * products of row a taken from column st[a] on (the rows are zero before).
 * Its own function so that the dot products keep their registers. */
static FNAV_NOINLINE void scatter_lin(fnav_real_t S[N][N], fnav_real_t U[N][N], const unsigned char *st, int na, int nl,
                                      fnav_real_t k)
{
    /* In blocks of two rows by two columns (each element loaded once for
     * two products), each block's sums from the earliest first non-zero
     * column of its rows and of its columns: the extra products are exact
     * zeros, so every sum equals the one taken from its own first column,
     * in the same order. */
    int a, b;
    for (a = 0; a < na; a += 2) {
        const fnav_real_t *ua = U[a] + nl, *ue;
        int sa, j0;
        if (a + 1 == na) { /* the last row alone: its diagonal element */
            const fnav_real_t *pa = U[a] + st[a];
            fnav_real_t s0 = FNAV_R(0.0);
            if (pa < ua) {
                do {
                    s0 += *pa * *pa;
                    pa++;
                } while (pa < ua);
            }
            S[a][a] = k * s0;
            break;
        }
        ue = ua;
        sa = st[a] < st[a + 1] ? st[a] : st[a + 1];
        {
            /* the diagonal block (a, a), (a, a + 1), (a + 1, a + 1) */
            const fnav_real_t *pa = U[a] + sa, *pb = U[a + 1] + sa;
            fnav_real_t s00 = FNAV_R(0.0), s01 = FNAV_R(0.0), s11 = FNAV_R(0.0);
            if (pa < ue) {
                do {
                    fnav_real_t x = *pa++, y = *pb++;
                    s00 += x * x;
                    s01 += x * y;
                    s11 += y * y;
                } while (pa < ue);
            }
            S[a][a] = k * s00;
            S[a][a + 1] = k * s01;
            S[a + 1][a + 1] = k * s11;
        }
        for (b = a + 2; b < na; b += 2) {
            int two = b + 1 < na, sb = two && st[b + 1] < st[b] ? st[b + 1] : st[b];
            const fnav_real_t *pa, *pa1, *pb, *pc;
            fnav_real_t s00 = FNAV_R(0.0), s01 = FNAV_R(0.0), s10 = FNAV_R(0.0), s11 = FNAV_R(0.0);
            j0 = sa > sb ? sa : sb;
            pa = U[a] + j0;
            pa1 = U[a + 1] + j0;
            pb = U[b] + j0;
            if (two) {
                pc = U[b + 1] + j0;
                if (pa < ue) {
                    do {
                        fnav_real_t x = *pa++, y = *pa1++, u = *pb++, v = *pc++;
                        s00 += x * u;
                        s01 += x * v;
                        s10 += y * u;
                        s11 += y * v;
                    } while (pa < ue);
                }
                S[a][b + 1] = k * s01;
                S[a + 1][b + 1] = k * s11;
            } else {
                if (pa < ue) {
                    do {
                        fnav_real_t u = *pb++;
                        s00 += *pa++ * u;
                        s10 += *pa1++ * u;
                    } while (pa < ue);
                }
            }
            S[a][b] = k * s00;
            S[a + 1][b] = k * s10;
        }
    }
}

/* The strapdown's first-order maps of the bias errors over one interval
 * (predict_linear), transposed (G[j][i] = row i, column j): G[0..2] G_a,
 * G[3..5] G_g, G[6..8] A_g. C = C_nb at the start of the interval; with c^T
 * the row i of C, row i of C [x x] is (c x x)^T and row i of C [x x]^2 is
 * ((c x x) x x)^T. */
static void bias_maps(const fnav_ukf_t *f, const fnav_strapdown_incr_t *inc, fnav_real_t dt_s, fnav_real_t (*G)[3])
{
    const fnav_real_t *th = inc->theta_rad.v, *dv = inc->dv_mps.v, hd = FNAV_R(0.5) * dt_s;
    fnav_real_t ph[3];
    int i, j;
    fnav_mat3_t C = fnav_quat_to_dcm(f->q_nb);
    for (i = 0; i < 3; i++) {
        ph[i] = inc->theta_rad.v[i] + inc->coning.v[i];
    }
    for (i = 0; i < 3; i++) {
        const fnav_real_t *c = C.m[i];
        G[0][i] = -dt_s * (c[0] + FNAV_R(0.5) * (c[1] * th[2] - c[2] * th[1]));
        G[1][i] = -dt_s * (c[1] + FNAV_R(0.5) * (c[2] * th[0] - c[0] * th[2]));
        G[2][i] = -dt_s * (c[2] + FNAV_R(0.5) * (c[0] * th[1] - c[1] * th[0]));
        G[3][i] = hd * (c[1] * dv[2] - c[2] * dv[1]);
        G[4][i] = hd * (c[2] * dv[0] - c[0] * dv[2]);
        G[5][i] = hd * (c[0] * dv[1] - c[1] * dv[0]);
    }
    for (i = 0; i < 3; i++) {
        /* row i of A_g = -dt (c + u / 2 + w / 6)^T, u = c x phi, w = u x phi */
        const fnav_real_t *c = C.m[i];
        fnav_real_t u[3], w[3];
        u[0] = c[1] * ph[2] - c[2] * ph[1];
        u[1] = c[2] * ph[0] - c[0] * ph[2];
        u[2] = c[0] * ph[1] - c[1] * ph[0];
        w[0] = u[1] * ph[2] - u[2] * ph[1];
        w[1] = u[2] * ph[0] - u[0] * ph[2];
        w[2] = u[0] * ph[1] - u[1] * ph[0];
        for (j = 0; j < 3; j++) {
            G[6 + j][i] = -dt_s * (c[j] + FNAV_R(0.5) * u[j] + w[j] * (FNAV_R(1.0) / FNAV_R(6.0)));
        }
    }
}

/* The settling state's prediction (fnav_ukf.h): Pxs' = c F Pxs, Pss' = c^2
 * Pss, s' = c s, with F the strapdown's error-state map over the interval
 * (predict_linear's, to first order in the attitude error a, which rotates
 * the specific-force increment dvn: d(dv_n) = a x dvn):
 *   r' = r,  v' = v + a x dvn + G_a b_a + G_g b_g,
 *   p' = p + dt v + dt/2 (a x dvn + G_a b_a + G_g b_g),
 *   a' = a + A_g b_g,  b_g' = c_g b_g,  b_a' = c_a b_a.
 * G: the bias maps (bias_maps), unused without the biases. s is dropped
 * once Pss has decayed below 1e-4 of its start. */
static void settle_predict(fnav_ukf_t *f, fnav_vec3_t dvn, const fnav_real_t (*G)[3], fnav_real_t dt_s)
{
    fnav_real_t *x = f->Pxs, c, va[3], vb[3] = { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0) };
    const fnav_real_t *cb = f->ar1_c, hd = FNAV_R(0.5) * dt_s;
    const int n = f->n_act, ov = f->pos[FNAV_UKF_V], op = f->pos[FNAV_UKF_P], oa = f->pos[FNAV_UKF_A],
              obg = f->pos[FNAV_UKF_BG], oba = f->pos[FNAV_UKF_BA];
    int i, j;
    if (dt_s != f->settle_dt_s) {
        f->settle_c = fnav_exp_neg(dt_s / f->cfg.settle_tau_s);
        f->settle_dt_s = dt_s;
    }
    c = f->settle_c;
    va[0] = x[oa + 1] * dvn.v[2] - x[oa + 2] * dvn.v[1];
    va[1] = x[oa + 2] * dvn.v[0] - x[oa] * dvn.v[2];
    va[2] = x[oa] * dvn.v[1] - x[oa + 1] * dvn.v[0];
    if (obg >= 0) {
        for (i = 0; i < 3; i++) {
            fnav_real_t da = FNAV_R(0.0);
            for (j = 0; j < 3; j++) {
                vb[i] += G[j][i] * x[oba + j] + G[3 + j][i] * x[obg + j];
                da += G[6 + j][i] * x[obg + j];
            }
            x[oa + i] += da;
        }
        for (i = 0; i < 3; i++) {
            x[obg + i] *= cb[i];
            x[oba + i] *= cb[3 + i];
        }
    }
    for (i = 0; i < 3; i++) {
        x[op + i] += dt_s * x[ov + i] + hd * (va[i] + vb[i]);
        x[ov + i] += va[i] + vb[i];
    }
    for (i = 0; i < n; i++) {
        x[i] *= c;
    }
    f->settle_mps *= c;
    f->settle_var *= c * c;
    if (f->settle_var < FNAV_R(1.0e-4) * f->cfg.settle_sd_mps * f->cfg.settle_sd_mps) {
        settle_drop(f);
    }
}

/* Closed-form prediction of the sigma-point pairs along the columns j < nl
 * of U (fnav_ukf_predict); adds their scatter to the upper triangle of S.
 * Out of line so that its locals do not add to the deepest stack path
 * (the strapdown of the full sigma points). */
static FNAV_NOINLINE void predict_linear(fnav_ukf_t *f, const fnav_strapdown_incr_t *inc, fnav_real_t dt_s)
{
    const fnav_real_t *cb = f->ar1_c;
    int n = f->n_act, nl = f->n_lin, ov = f->pos[FNAV_UKF_V], op = f->pos[FNAV_UKF_P], i;
    /* The pairs +-gamma U_j, j < nl, leave the attitude at its centre
     * (U is upper triangular and the attitude is packed last), so they
     * differ from the centre only in lever, velocity, position and the
     * biases. The strapdown maps those linearly (fnav_strapdown_propagate
     * with d_dv = -b_a dt, d_theta = -b_g dt):
     *   r' = r,  b_a' = c_a b_a,  b_g' = c_g b_g,
     *   v' = v + G_a b_a + G_g b_g,  p' = p + dt v + dt/2 (G_a b_a + G_g b_g),
     *   a' = A_g b_g,
     * G_a = -dt C (I + [th x]/2)  (the velocity increment with its
     *   rotation compensation, exact),
     * G_g = dt/2 C [dv x]         (the compensation's th x dv / 2),
     * A_g = -dt C J(phi)          (the rotation increment; left Jacobian
     *   J(phi) = I + [phi x]/2 + [phi x]^2/6, truncated at |phi|^3/24),
     * C = C_nb at the start of the interval. The gyro-bias terms are the
     * first order of the full strapdown (the gyro bias linearised, so that
     * the model is partially linear with only the attitude nonlinear): the
     * terms they drop (th x dv / 2 with both increments
     * perturbed, the rotation's second order) are of relative order
     * e = gamma sigma_bg dt, the sigma spread of the rotation increment, a
     * few 1e-6 for a MEMS gyro at 200 Hz: below float32 resolution
     * (test_closed_form_equivalence, docs/navigation.md). Each pair adds
     * 2 W gamma^2 (F U_j)(F U_j)^T = (F U_j)(F U_j)^T to S and nothing to
     * the mean. F U_j is formed in place in the columns j < nl of U (their
     * attitude rows, zero in the factor, receive A_g b_g; the other sigma
     * points use only the columns >= nl). Row a of F U is zero in the columns
     * before st(a): a itself, the velocity's for position rows, the gyro
     * bias's first for attitude rows. */
    fnav_real_t kl = FNAV_R(2.0) * f->wi * f->gamma * f->gamma, hd = FNAV_R(0.5) * dt_s;
    int oba = f->pos[FNAV_UKF_BA], obg = f->pos[FNAV_UKF_BG], oat = f->pos[FNAV_UKF_A];
    int a, k;
    unsigned char st[N];
    for (k = ov; k < nl; k++) {
        /* F U_k in place; U_k is zero below row k, so only the columns
         * from the velocity's on reach the position rows */
        for (i = 0; i < 3; i++) {
            f->U[op + i][k] += dt_s * f->U[ov + i][k];
        }
    }
    if (obg >= 0) {
        /* the three maps (bias_maps) in the update's gain scratch, which is
         * free during the prediction (keeps them off the stack; the
         * settling's prediction reads them there too) */
        fnav_real_t (*G)[3] = f->K;
        bias_maps(f, inc, dt_s, G);
        for (k = oba; k < nl; k++) {
            /* the bias columns: velocity, position and attitude responses,
             * then the AR(1) decay of the biases themselves; an accelerometer
             * column (k < obg) has no gyro-bias rows (zero in the factor) */
            const fnav_real_t ua0 = f->U[oba][k], ua1 = f->U[oba + 1][k], ua2 = f->U[oba + 2][k];
            if (k < obg) {
                for (i = 0; i < 3; i++) {
                    fnav_real_t dvb = FNAV_R(0.0);
                    dvb += G[0][i] * ua0;
                    dvb += G[1][i] * ua1;
                    dvb += G[2][i] * ua2;
                    f->U[op + i][k] += hd * dvb;
                    f->U[ov + i][k] += dvb;
                    f->U[oat + i][k] = FNAV_R(0.0);
                }
            } else {
                const fnav_real_t ug0 = f->U[obg][k], ug1 = f->U[obg + 1][k], ug2 = f->U[obg + 2][k];
                for (i = 0; i < 3; i++) {
                    fnav_real_t dvb = FNAV_R(0.0), da = FNAV_R(0.0);
                    dvb += G[0][i] * ua0 + G[3][i] * ug0;
                    da += G[6][i] * ug0;
                    dvb += G[1][i] * ua1 + G[4][i] * ug1;
                    da += G[7][i] * ug1;
                    dvb += G[2][i] * ua2 + G[5][i] * ug2;
                    da += G[8][i] * ug2;
                    f->U[op + i][k] += hd * dvb;
                    f->U[ov + i][k] += dvb;
                    f->U[oat + i][k] = da;
                }
                for (i = 0; i < 3; i++) {
                    f->U[obg + i][k] *= cb[i];
                }
            }
            for (i = 0; i < 3; i++) {
                f->U[oba + i][k] *= cb[3 + i];
            }
        }
    }
    /* S += kl (F U_l)(F U_l)^T: rows 0..nl-1 and, with the biases, the
     * attitude rows; row a of F U is zero before column st(a): a itself,
     * the velocity's for a position row, the gyro bias's first for an
     * attitude row */
    for (a = 0; a < n; a++) {
        st[a] = (unsigned char)a;
    }
    for (i = 0; i < 3; i++) {
        st[op + i] = (unsigned char)(ov + i);
        st[oat + i] = (unsigned char)(obg >= 0 ? obg : nl);
    }
    scatter_lin(f->S, f->U, st, obg >= 0 ? n : nl, nl, kl);
}

/* Sigma-point offset of packed state i along column jj of U, scaled by g
 * (zero below the diagonal). */
static inline FNAV_ALWAYS_INLINE fnav_real_t sp_off(const fnav_ukf_t *f, int i, int jj, fnav_real_t g)
{
    return i <= jj ? g * f->U[i][jj] : FNAV_R(0.0);
}

/* The closed form's six attitude sigma points (fnav_ukf_predict): the
 * columns jj = nl..nl+2 of U, each with +gamma and -gamma, through the full
 * strapdown; the difference D_p of point p = 2 (jj - nl) + s from the
 * propagated centre x0 goes into column p of U (the closed form's columns,
 * consumed by predict_linear; nl >= 6), for accumulate6. The same
 * arithmetic as the full path's loop, element by element. */
static void sigma_att(fnav_ukf_t *f, const fnav_strapdown_incr_t *inc, const fnav_strapdown_state_t *x0,
                       fnav_quat_t q0inv, fnav_real_t dt_s)
{
    const fnav_real_t *cb = f->ar1_c;
    const int n = f->n_act, nl = f->n_lin, ov = f->pos[FNAV_UKF_V], op = f->pos[FNAV_UKF_P], oa = f->pos[FNAV_UKF_A],
              obg = f->pos[FNAV_UKF_BG], oba = f->pos[FNAV_UKF_BA];
    int jj, s, i;
    for (jj = nl; jj < n; jj++) {
        for (s = 0; s < 2; s++) {
            const fnav_real_t g = s == 0 ? f->gamma : -f->gamma;
            const int pt = 2 * (jj - nl) + s;
            fnav_strapdown_state_t xi;
            fnav_vec3_t dth = fnav_vec3_zero(), ddv = fnav_vec3_zero(), dv, dp, da;
            xi.q_nb = apply_att(f->q_nb, fnav_vec3(sp_off(f, oa, jj, g), sp_off(f, oa + 1, jj, g), sp_off(f, oa + 2, jj, g)));
            xi.vel_mps = fnav_vec3_add(f->vel_mps, fnav_vec3(g * f->U[ov][jj], g * f->U[ov + 1][jj], g * f->U[ov + 2][jj]));
            /* the offset only: positions relative to the start's (fnav_ukf_predict) */
            xi.pos_m = fnav_vec3(g * f->U[op][jj], g * f->U[op + 1][jj], g * f->U[op + 2][jj]);
            if (obg >= 0) {
                dth = fnav_vec3(g * f->U[obg][jj], g * f->U[obg + 1][jj], g * f->U[obg + 2][jj]);
                ddv = fnav_vec3(g * f->U[oba][jj], g * f->U[oba + 1][jj], g * f->U[oba + 2][jj]);
            }
            fnav_strapdown_propagate(&f->cfg.strapdown, &xi, inc, fnav_vec3_scale(dth, -dt_s), fnav_vec3_scale(ddv, -dt_s));
            dv = fnav_vec3_sub(xi.vel_mps, x0->vel_mps);
            dp = fnav_vec3_sub(xi.pos_m, x0->pos_m);
            da = fnav_ukf_quat_to_grp(fnav_quat_mul(xi.q_nb, q0inv));
            for (i = 0; i < nl; i++) {
                f->U[i][pt] = g * f->U[i][jj]; /* lever and biases; velocity, position overwritten */
            }
            for (i = 0; i < 3; i++) {
                f->U[ov + i][pt] = dv.v[i];
                f->U[op + i][pt] = dp.v[i];
                f->U[oa + i][pt] = da.v[i];
            }
            if (obg >= 0) {
                for (i = 0; i < 3; i++) {
                    f->U[obg + i][pt] *= cb[i];
                    f->U[oba + i][pt] *= cb[3 + i];
                }
            }
        }
    }
}

fnav_status_t fnav_ukf_predict(fnav_ukf_t *f, fnav_vec3_t gyro_rps, fnav_vec3_t accel_mps2, fnav_real_t dt_s)
{
    const fnav_ukf_config_t *c;
    fnav_strapdown_incr_t inc;
    fnav_strapdown_state_t x0, xi;
    fnav_vec3_t vc;
    fnav_quat_t q0inv;
    fnav_real_t m[N];
    const fnav_real_t *cb, *qb;
    fnav_real_t kmm, g, chk = FNAV_R(0.0);
#if FNAV_UKF_YAW_CARRY
    fnav_real_t s_lin = FNAV_R(0.0), carry;
#endif
    int n, nl, i, j, jj, s, fr, ov, op, oa, obg, oba;
    if (f == NULL) {
        return FNAV_E_ARG;
    }
    if (!f->started) {
        return FNAV_E_STATE;
    }
    if (!fnav_vec3_isfinite(gyro_rps) || !fnav_vec3_isfinite(accel_mps2) || !fnav_isfinite(dt_s)) {
        f->health.nan_inputs++;
        return FNAV_E_NANINF;
    }
    if (dt_s < FNAV_R(0.0)) {
        return FNAV_E_TIME;
    }
    if (dt_s == FNAV_R(0.0)) {
        return FNAV_OK;
    }
    c = &f->cfg;
    n = f->n_act;
    nl = f->n_lin;
    ov = f->pos[FNAV_UKF_V];
    op = f->pos[FNAV_UKF_P];
    oa = f->pos[FNAV_UKF_A];
    obg = f->pos[FNAV_UKF_BG];
    oba = f->pos[FNAV_UKF_BA];
    guard_cov(f); /* e.g. a covariance set by a caller */
    fr = factor(f);

    fnav_strapdown_increments(&c->strapdown, &f->hist, fnav_vec3_sub(gyro_rps, f->bg_rps),
                              fnav_vec3_sub(accel_mps2, f->ba_mps2), dt_s, &inc);
    x0.q_nb = f->q_nb;
    x0.vel_mps = f->vel_mps;
    /* Positions relative to the start's: the flat-earth strapdown does not
     * read the position, so the centre and the sigma points are propagated
     * from 0 (the centre) and from their offsets alone, and their
     * differences D are formed between small numbers. Formed from f->pos_m,
     * 10 km away (float spacing 0.98 mm), the offsets and one-step
     * differences of a millimetre or less rounded away or to whole
     * millimetres, and the covariance's position rows went wrong
     * (test_ukf test_far_from_origin; docs/frames.md). The centre's sum
     * f->pos_m + increment + mean is formed in the same order as before. */
    x0.pos_m = fnav_vec3_zero();
    fnav_strapdown_propagate(&c->strapdown, &x0, &inc, fnav_vec3_zero(), fnav_vec3_zero());
    q0inv = fnav_quat_conj(x0.q_nb);

    /* AR(1) coefficients c = exp(-dt/tau) and driving variances
     * sigma^2 (1 - exp(-2 dt/tau)) (paper eqs. (3), (4) with c = e^(-1/tau)
     * for dt = one sample); the model off keeps the biases fixed. c comes
     * from fnav_one_minus_exp_neg, not the C library, so that host and
     * target agree bit for bit (fnav_math.h). */
    if (dt_s != f->ar1_dt_s) {
        /* recomputed only when the interval changes: never on a steady
         * clock, every sample where the stamps jitter by a nanosecond (the
         * NGIMU logs: six divisions and six short series per sample) */
        for (i = 0; i < 3; i++) {
            if (c->bias_model == FNAV_BIAS_AR1) {
                /* from d = 1 - c, exact to float's relative precision even
                 * for dt/tau of 1e-7: c = 1 - d, and 1 - c^2 = d (2 - d)
                 * without the cancellation of 1 - c*c */
                const fnav_real_t dg = fnav_one_minus_exp_neg(dt_s / c->gyro_tau_s[i]);
                const fnav_real_t da = fnav_one_minus_exp_neg(dt_s / c->accel_tau_s[i]);
                f->ar1_c[i] = FNAV_R(1.0) - dg;
                f->ar1_c[3 + i] = FNAV_R(1.0) - da;
                f->ar1_q[i] = c->gyro_bias_sigma_rps[i] * c->gyro_bias_sigma_rps[i] * (dg * (FNAV_R(2.0) - dg));
                f->ar1_q[3 + i] = c->accel_bias_sigma_mps2[i] * c->accel_bias_sigma_mps2[i] * (da * (FNAV_R(2.0) - da));
            } else {
                f->ar1_c[i] = f->ar1_c[3 + i] = FNAV_R(1.0);
                f->ar1_q[i] = f->ar1_q[3 + i] = FNAV_R(0.0);
            }
        }
        f->ar1_dt_s = dt_s;
    }
    cb = f->ar1_c;
    qb = f->ar1_q;

    /* S starts at zero; the closed form assigns the block of its rows and
     * columns (below nl, or all with the biases), the rest is cleared here */
    jj = !(c->closed_form && nl > 0) ? 0 : (obg >= 0 ? n : nl);
    for (i = 0; i < n; i++) {
        m[i] = FNAV_R(0.0);
        for (j = i < jj ? jj : i; j < n; j++) {
            f->S[i][j] = FNAV_R(0.0);
        }
    }
    if (c->closed_form && nl > 0) {
        predict_linear(f, &inc, dt_s);
    }
    /* the full sigma points: with the closed form the attitude's six
     * (sigma_att, into S together below); without it, along every column,
     * in packed order, each point's difference D from the propagated centre
     * formed in a row of f->Hm (free during the prediction) and a pair at a
     * time into S */
    if (c->closed_form) {
#if FNAV_UKF_YAW_CARRY
        s_lin = f->S[n - 1][n - 1]; /* the yaw's scatter of the columns j < nl (yaw_change) */
#endif
        sigma_att(f, &inc, &x0, q0inv, dt_s);
    }
    for (jj = 0; jj < n && !c->closed_form; jj++) {
#if FNAV_UKF_YAW_CARRY
        if (jj == nl) {
            s_lin = f->S[n - 1][n - 1]; /* as above, before the attitude columns */
        }
#endif
        for (s = 0; s < 2; s++) {
            fnav_real_t *d = f->Hm[s];
            g = s == 0 ? f->gamma : -f->gamma;
            for (i = 0; i < n; i++) {
                d[i] = (i <= jj) ? g * f->U[i][jj] : FNAV_R(0.0);
            }
            xi.q_nb = apply_att(f->q_nb, fnav_vec3_from(&d[oa]));
            xi.vel_mps = fnav_vec3_add(f->vel_mps, fnav_vec3_from(&d[ov]));
            xi.pos_m = fnav_vec3_from(&d[op]); /* relative to the start's, as x0's */
            fnav_strapdown_propagate(&c->strapdown, &xi, &inc,
                                     fnav_vec3_scale(obg >= 0 ? fnav_vec3_from(&d[obg]) : fnav_vec3_zero(), -dt_s),
                                     fnav_vec3_scale(oba >= 0 ? fnav_vec3_from(&d[oba]) : fnav_vec3_zero(), -dt_s));
            {
                fnav_vec3_t dv = fnav_vec3_sub(xi.vel_mps, x0.vel_mps);
                fnav_vec3_t dp = fnav_vec3_sub(xi.pos_m, x0.pos_m);
                fnav_vec3_t da = fnav_ukf_quat_to_grp(fnav_quat_mul(xi.q_nb, q0inv));
                for (i = 0; i < 3; i++) {
                    d[ov + i] = dv.v[i];
                    d[op + i] = dp.v[i];
                    d[oa + i] = da.v[i];
                }
                if (obg >= 0) {
                    for (i = 0; i < 3; i++) {
                        d[obg + i] *= cb[i];
                        d[oba + i] *= cb[3 + i];
                    }
                }
            }
        }
        accumulate2(f->S, m, f->Hm[0], f->Hm[1], n, f->wi);
    }
    /* With the propagated centre as reference (D_0 = 0) and the mean
     * m = sum_i W_i D_i, the scatter sum_i Wc_i (D_i - m)(D_i - m)^T equals
     * S - 2 m m^T + (1 - W0m) m m^T + W0c m m^T = S + (beta - alpha^2) m m^T,
     * S = sum_{i>0} W_i D_i D_i^T; with beta >= alpha^2 every term is PSD. */
    kmm = c->beta - c->alpha * c->alpha;
    if (c->closed_form) {
        accumulate6(f->S, m, f->U, n, f->wi, kmm, &chk);
    }
    for (i = 0; i < n && !c->closed_form; i++) {
        fnav_real_t km = kmm * m[i];
        fnav_real_t *si = f->S[i] + i, *se = f->S[i] + n;
        const fnav_real_t *mj = m + i;
        while (si < se) {
            *si += km * *mj++;
            chk += *si++; /* one check of the sum below */
        }
    }
#if FNAV_UKF_YAW_CARRY
    if (obg >= 0 && !c->closed_form) {
        bias_maps(f, &inc, dt_s, f->K); /* predict_linear did not run (yaw_change, settle_predict) */
    }
    {
        fnav_mat3_t C = fnav_quat_to_dcm(x0.q_nb);
        fnav_real_t q;
        (void)add_rotated_noise(f->S, ov, C, c->accel_noise_mps2_rthz, dt_s);
        q = add_rotated_noise(f->S, oa, C, c->gyro_noise_rps_rthz, dt_s);
        carry = yaw_change(f, s_lin, m, kmm, q, obg >= 0 ? (const fnav_real_t(*)[3])f->K : NULL);
    }
#else
    {
        fnav_mat3_t C = fnav_quat_to_dcm(x0.q_nb);
        (void)add_rotated_noise(f->S, ov, C, c->accel_noise_mps2_rthz, dt_s);
        (void)add_rotated_noise(f->S, oa, C, c->gyro_noise_rps_rthz, dt_s);
    }
#endif
    for (i = 0; i < 3; i++) {
        if (c->bias_model == FNAV_BIAS_AR1) {
            f->S[obg + i][obg + i] += qb[i];
            f->S[oba + i][oba + i] += qb[3 + i];
        }
        if (c->lever) {
            int orr = f->pos[FNAV_UKF_R];
            f->S[orr + i][orr + i] += c->lever_rw_m_rts * c->lever_rw_m_rts * dt_s;
        }
    }
    /* a NaN or an infinity anywhere in S makes the sum of its entries
     * non-finite (they are bounded far below overflow by the guard; the
     * process noise added after the sum is finite) */
    if (!fnav_isfinite(chk)) {
        f->health.diverged++;
        return FNAV_E_DIVERGED;
    }
    /* fold the mean into the nominal state (the bias and lever means are zero
     * by the symmetry of the sigma points) */
    vc = x0.vel_mps;
    x0.q_nb = apply_att(x0.q_nb, fnav_vec3_from(&m[oa]));
    x0.vel_mps = fnav_vec3_add(x0.vel_mps, fnav_vec3_from(&m[ov]));
    x0.pos_m = fnav_vec3_add(fnav_vec3_add(f->pos_m, x0.pos_m), fnav_vec3_from(&m[op]));
    if (!state_finite(&x0)) {
        f->health.diverged++;
        return FNAV_E_DIVERGED;
    }
    if (f->settle_on) {
        /* the specific-force velocity increment in n: the centre's change
         * less gravity's (the mean's second-order shift left out) */
        fnav_vec3_t dvn = fnav_vec3_sub(vc, f->vel_mps);
        dvn.v[2] -= c->strapdown.gravity_mps2 * dt_s;
#if !FNAV_UKF_YAW_CARRY
        if (obg >= 0 && !(c->closed_form && nl > 0)) {
            bias_maps(f, &inc, dt_s, f->K); /* predict_linear did not run */
        }
#endif
        settle_predict(f, dvn, (const fnav_real_t(*)[3])f->K, dt_s);
    }
    f->q_nb = x0.q_nb;
    f->vel_mps = x0.vel_mps;
    f->pos_m = x0.pos_m;
    for (i = 0; i < 3; i++) {
        f->bg_rps.v[i] = f->bg0_rps.v[i] + cb[i] * (f->bg_rps.v[i] - f->bg0_rps.v[i]);
        f->ba_mps2.v[i] = f->ba0_mps2.v[i] + cb[3 + i] * (f->ba_mps2.v[i] - f->ba0_mps2.v[i]);
    }
    mirror_upper(f->P, f->S, n);
#if FNAV_UKF_YAW_CARRY
    f->p_yaw_carry_rad2 = carry;
#endif
    guard_cov(f);
    fnav_strapdown_hist_push(&f->hist, &inc);
    f->health.predicts++;
    return fr == 2 ? FNAV_E_DECOMP : FNAV_OK;
}

/* The settling's part of the augmented P H^T (update(), after P H^T): its
 * row hp = H Pxs + Pss h_s, and with h_s = -e_z (hs) the packed rows' third
 * column less Pxs. Out of line, as settle_update: inlined, the extra live
 * values cost the hot loops of the update registers. */
static FNAV_NOINLINE void settle_pht(fnav_ukf_t *f, const fnav_real_t (*H)[N], const int *cols, int nc, int hs,
                                     fnav_real_t hp[3])
{
    const fnav_real_t *x = f->Pxs;
    int i, k, c;
    for (k = 0; k < 3; k++) {
        hp[k] = FNAV_R(0.0);
        if (H == NULL) {
            hp[k] = x[cols[k]];
        } else {
            for (c = 0; c < nc; c++) {
                hp[k] += H[k][cols[c]] * x[cols[c]];
            }
        }
    }
    if (hs) {
        hp[2] -= f->settle_var;
        for (i = 0; i < f->n_act; i++) {
            f->PHt[i][2] -= x[i];
        }
    }
}

/* The settling's gain ks = hp S^-1, its correction and, in the expanded
 * Joseph form of the packed states (update()), its new cross-covariances
 * Pxs - (P H^T) ks^T + K e and variance Pss + ks (e - hp^T), e = S ks^T -
 * hp^T; f->K and f->PHt hold the packed rows'. A result that is not finite
 * or a variance that is not positive drops the settling (the packed
 * states' own update is checked on its own). */
static FNAV_NOINLINE void settle_update(fnav_ukf_t *f, const fnav_real_t hp[3], const fnav_real_t (*si)[3],
                                        const fnav_real_t (*s)[3], fnav_vec3_t y)
{
    fnav_real_t ks[3], e[3], ds, pss = f->settle_var, chk;
    int i, k;
    for (k = 0; k < 3; k++) {
        ks[k] = hp[0] * si[0][k] + hp[1] * si[1][k] + hp[2] * si[2][k];
    }
    for (k = 0; k < 3; k++) {
        e[k] = ks[0] * s[0][k] + ks[1] * s[1][k] + ks[2] * s[2][k] - hp[k];
    }
    ds = ks[0] * y.v[0] + ks[1] * y.v[1] + ks[2] * y.v[2];
    pss += ks[0] * (e[0] - hp[0]) + ks[1] * (e[1] - hp[1]) + ks[2] * (e[2] - hp[2]);
    chk = ds;
    for (i = 0; i < f->n_act; i++) {
        fnav_real_t v = f->Pxs[i] + (f->K[i][0] * e[0] + f->K[i][1] * e[1] + f->K[i][2] * e[2]) -
                        (f->PHt[i][0] * ks[0] + f->PHt[i][1] * ks[1] + f->PHt[i][2] * ks[2]);
        chk += v;
        f->Pxs[i] = v;
    }
    f->settle_mps += ds;
    f->settle_var = pss;
    if (!(pss > FNAV_R(0.0)) || !fnav_isfinite(chk + pss)) {
        settle_drop(f);
    }
}

/* Linear update with a 3-row measurement matrix f->Hm over the packed states
 * (non-zero only in the packed columns cols[0..nc-1]), innovation y and
 * variance r2 per axis, in Joseph form (see below). With nc = 3 and
 * H = NULL the measurement matrix is the selection of the states cols[0..2]
 * (row k one at cols[k]): P H^T is then copied, not multiplied, and f->Hm
 * is not read. While the settling state is active the update is that of
 * the state augmented with it (fnav_ukf.h), whose measurement row 2 holds
 * -1 for it when hs = 1 (the ZUPT) and nothing otherwise. */
static fnav_status_t update(fnav_ukf_t *f, const fnav_real_t (*H)[N], const int *cols, int nc, fnav_vec3_t y,
                            fnav_real_t r2, int hs)
{
    int n = f->n_act, i, j, k, c, so = f->settle_on;
    fnav_real_t s[3][3], si[3][3], det, dx[N], dxi[N], chk = FNAV_R(0.0);
    fnav_real_t hp[3];
    fnav_real_t (*K)[3] = f->K;
    fnav_real_t (*PHt)[3] = f->PHt;
    fnav_real_t (*APHt)[3] = f->APHt;
    fnav_real_t (*Pn)[N] = f->U;
    /* P H^T (n x 3) */
    if (H == NULL) {
        for (i = 0; i < n; i++) {
            for (k = 0; k < 3; k++) {
                PHt[i][k] = f->P[i][cols[k]];
            }
        }
    } else {
        /* H's non-zero columns gathered first (into APHt, free until the
         * Joseph products; S below uses them too), so that each P element
         * is loaded once for the three rows; the sums run over c in the
         * same order */
        fnav_real_t (*hc)[3] = APHt;
        for (c = 0; c < nc; c++) {
            for (k = 0; k < 3; k++) {
                hc[c][k] = H[k][cols[c]];
            }
        }
        for (i = 0; i < n; i++) {
            const fnav_real_t *pi = f->P[i];
            const int *cp = cols, *ce = cols + nc;
            fnav_real_t (*h)[3] = hc;
            fnav_real_t s0 = FNAV_R(0.0), s1 = FNAV_R(0.0), s2 = FNAV_R(0.0);
            do { /* nc >= 1 */
                fnav_real_t pc = pi[*cp++];
                s0 += pc * (*h)[0];
                s1 += pc * (*h)[1];
                s2 += pc * (*h)[2];
                h++;
            } while (cp < ce);
            PHt[i][0] = s0;
            PHt[i][1] = s1;
            PHt[i][2] = s2;
        }
    }
    if (so) {
        settle_pht(f, H, cols, nc, hs, hp);
    }
    /* S = H P H^T + R (with H, over its gathered columns: each sum in the
     * order of c); with the settling, + h_s (the settling's row of P H^T) */
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            s[i][j] = (i == j) ? r2 : FNAV_R(0.0);
            if (H == NULL) {
                s[i][j] += PHt[cols[i]][j];
            }
        }
    }
    if (H != NULL) {
        for (c = 0; c < nc; c++) {
            const fnav_real_t *h = APHt[c], *ph = PHt[cols[c]];
            for (i = 0; i < 3; i++) {
                s[i][0] += h[i] * ph[0];
                s[i][1] += h[i] * ph[1];
                s[i][2] += h[i] * ph[2];
            }
        }
    }
    if (so && hs) {
        for (j = 0; j < 3; j++) {
            s[2][j] -= hp[j];
        }
    }
    s[0][1] = s[1][0] = FNAV_R(0.5) * (s[0][1] + s[1][0]);
    s[0][2] = s[2][0] = FNAV_R(0.5) * (s[0][2] + s[2][0]);
    s[1][2] = s[2][1] = FNAV_R(0.5) * (s[1][2] + s[2][1]);
    /* inverse of the symmetric 3x3 innovation covariance (adjugate) */
    si[0][0] = s[1][1] * s[2][2] - s[1][2] * s[2][1];
    si[0][1] = s[0][2] * s[2][1] - s[0][1] * s[2][2];
    si[0][2] = s[0][1] * s[1][2] - s[0][2] * s[1][1];
    si[1][1] = s[0][0] * s[2][2] - s[0][2] * s[2][0];
    si[1][2] = s[0][2] * s[1][0] - s[0][0] * s[1][2];
    si[2][2] = s[0][0] * s[1][1] - s[0][1] * s[1][0];
    det = s[0][0] * si[0][0] + s[0][1] * si[0][1] + s[0][2] * si[0][2];
    /* positive definite by Sylvester's criterion: the leading minors s00,
     * s00 s11 - s01^2 (= si[2][2]) and det positive. Without s00 > 0 an
     * indefinite S with two negative eigenvalues would pass (-1 0 2; 0 -1 0;
     * 2 0 -1: det 3, minor 1) and be inverted (test_ukf
     * test_zupt_indefinite_s) */
    if (!(det > FNAV_R(0.0)) || !fnav_isfinite(det) || !(s[0][0] > FNAV_R(0.0)) || !(si[0][0] > FNAV_R(0.0)) ||
        !(si[2][2] > FNAV_R(0.0))) {
        f->health.update_reject++;
        if (so) {
            settle_drop(f); /* the next update goes without it */
        }
        return FNAV_E_DECOMP;
    }
    det = FNAV_R(1.0) / det;
    si[1][0] = si[0][1];
    si[2][0] = si[0][2];
    si[2][1] = si[1][2];
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            si[i][j] *= det;
        }
    }
    /* the gain K = P H^T S^-1, the correction dx = K y and (for the Joseph
     * form below) SK = K S, row by row with the row's operands in locals */
    for (i = 0; i < n; i++) {
        const fnav_real_t p0 = PHt[i][0], p1 = PHt[i][1], p2 = PHt[i][2];
        const fnav_real_t k0 = p0 * si[0][0] + p1 * si[1][0] + p2 * si[2][0];
        const fnav_real_t k1 = p0 * si[0][1] + p1 * si[1][1] + p2 * si[2][1];
        const fnav_real_t k2 = p0 * si[0][2] + p1 * si[1][2] + p2 * si[2][2];
        K[i][0] = k0;
        K[i][1] = k1;
        K[i][2] = k2;
        dx[i] = k0 * y.v[0] + k1 * y.v[1] + k2 * y.v[2];
        if (!fnav_isfinite(dx[i])) {
            f->health.diverged++;
            return FNAV_E_DIVERGED;
        }
        APHt[i][0] = k0 * s[0][0] + k1 * s[1][0] + k2 * s[2][0];
        APHt[i][1] = k0 * s[0][1] + k1 * s[1][1] + k2 * s[2][1];
        APHt[i][2] = k0 * s[0][2] + k1 * s[1][2] + k2 * s[2][2];
    }
    /* Joseph form (I - K H) P (I - K H)^T + K R K^T, expanded:
     * P - K (P H^T)^T - (P H^T) K^T + K S K^T with S = H P H^T + R. It holds
     * for any gain K (not only the optimal one, unlike P - K H P), is
     * symmetric term by term, and only its upper triangle is computed
     * (APHt holds SK). */
    for (i = 0; i < n; i++) {
        /* row i's operands in locals: the stores to Pn could alias them */
        const fnav_real_t ki0 = K[i][0], ki1 = K[i][1], ki2 = K[i][2];
        const fnav_real_t pi0 = PHt[i][0], pi1 = PHt[i][1], pi2 = PHt[i][2];
        const fnav_real_t *pij = f->P[i] + i;
        fnav_real_t *pn = Pn[i] + i, *pe = Pn[i] + n;
        fnav_real_t (*kj)[3] = K + i, (*pj)[3] = PHt + i, (*sj)[3] = APHt + i;
        do {
            fnav_real_t v = *pij++ - (ki0 * (*pj)[0] + ki1 * (*pj)[1] + ki2 * (*pj)[2]) -
                            (pi0 * (*kj)[0] + pi1 * (*kj)[1] + pi2 * (*kj)[2]) +
                            (ki0 * (*sj)[0] + ki1 * (*sj)[1] + ki2 * (*sj)[2]);
            chk += v;
            *pn++ = v;
            kj++;
            pj++;
            sj++;
        } while (pn < pe);
    }
    if (!fnav_isfinite(chk)) { /* as in the prediction: one check of the sum */
        f->health.diverged++;
        return FNAV_E_DIVERGED;
    }
    if (so) {
        settle_update(f, hp, (const fnav_real_t(*)[3])si, (const fnav_real_t(*)[3])s, y);
    }
    mirror_upper(f->P, Pn, n);
    guard_cov_r2(f, r2);
    for (i = 0; i < N; i++) {
        dxi[i] = f->pos[i] >= 0 ? dx[f->pos[i]] : FNAV_R(0.0);
    }
    f->lever_m = fnav_vec3_add(f->lever_m, fnav_vec3_from(&dxi[FNAV_UKF_R]));
    f->vel_mps = fnav_vec3_add(f->vel_mps, fnav_vec3_from(&dxi[FNAV_UKF_V]));
    f->pos_m = fnav_vec3_add(f->pos_m, fnav_vec3_from(&dxi[FNAV_UKF_P]));
    f->q_nb = apply_att(f->q_nb, fnav_vec3_from(&dxi[FNAV_UKF_A]));
    f->bg_rps = fnav_vec3_add(f->bg_rps, fnav_vec3_from(&dxi[FNAV_UKF_BG]));
    f->ba_mps2 = fnav_vec3_add(f->ba_mps2, fnav_vec3_from(&dxi[FNAV_UKF_BA]));
    return FNAV_OK;
}

/* Clear the measurement matrix over the packed states. */
static void clear_h(fnav_ukf_t *f)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < f->n_act; j++) {
            f->Hm[i][j] = FNAV_R(0.0);
        }
    }
}

fnav_status_t fnav_ukf_zupt(fnav_ukf_t *f, fnav_vec3_t gyro_rps)
{
    int cols[9], nc = 0, i, j; /* velocity, lever, attitude */
    fnav_vec3_t y;
    fnav_status_t st;
    if (f == NULL) {
        return FNAV_E_ARG;
    }
    if (!f->started) {
        return FNAV_E_STATE;
    }
    if (!fnav_vec3_isfinite(gyro_rps)) {
        f->health.nan_inputs++;
        return FNAV_E_NANINF;
    }
    for (i = 0; i < 3; i++) {
        cols[nc++] = f->pos[FNAV_UKF_V] + i;
    }
    y = fnav_vec3_scale(f->vel_mps, -FNAV_R(1.0));
    if (f->cfg.lever) {
        /* h = v - C (w x r) = 0 with w = w_m - b_g; first-order error terms:
         * dh/dr = -C [w x], dh/da = [u x] with u = C (w x r) (attitude error
         * in n). The gyro bias's term, dh/db_g = -C [r x], is left out: its
         * effect |r| |db_g| (5 cm times a MEMS gyro's in-run bias sd, about
         * 1e-5 m/s) is three orders below the ZUPT noise, and its three
         * columns cost the step 1,400 instructions on the Cortex-M4F
         * (docs/navigation.md, "The rolling foot"). */
        fnav_vec3_t w = fnav_vec3_sub(gyro_rps, f->bg_rps);
        fnav_mat3_t C = fnav_quat_to_dcm(f->q_nb);
        fnav_mat3_t Hr = fnav_mat3_mul(C, fnav_mat3_skew(w));
        fnav_vec3_t u = fnav_mat3_mul_vec3(C, fnav_vec3_cross(w, f->lever_m));
        fnav_mat3_t Ha = fnav_mat3_skew(u);
        int orr = f->pos[FNAV_UKF_R], oa = f->pos[FNAV_UKF_A];
        y = fnav_vec3_sub(u, f->vel_mps);
        clear_h(f);
        for (i = 0; i < 3; i++) {
            f->Hm[i][cols[i]] = FNAV_R(1.0);
            for (j = 0; j < 3; j++) {
                f->Hm[i][orr + j] = -Hr.m[i][j];
                f->Hm[i][oa + j] = Ha.m[i][j];
            }
        }
        for (j = 0; j < 3; j++) {
            cols[nc++] = orr + j;
            cols[nc++] = oa + j;
        }
    }
    if (f->settle_on) {
        y.v[2] += f->settle_mps; /* h = ... - s e_z */
    }
    /* without the lever, H selects the velocity */
    st = update(f, f->cfg.lever ? (const fnav_real_t(*)[N])f->Hm : NULL, cols, nc, y,
                f->cfg.zupt_sigma_mps * f->cfg.zupt_sigma_mps, 1);
    if (st == FNAV_OK) {
        f->health.zupts++;
    }
    return st;
}

/* The ZARU innovation's normalised square y^T S^-1 y, S = P_bg + r2 I (the
 * ZARU's H selects the gyro-bias states; the settling state does not enter
 * its row), by the Cholesky factor of S; a factor that is not positive gives
 * +Inf, so the gate rejects and update() is not asked to invert it. */
static fnav_real_t zaru_nis(const fnav_ukf_t *f, int ob, fnav_vec3_t y, fnav_real_t r2)
{
    fnav_real_t l[3][3], z[3] = { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0) }, nis = FNAV_R(0.0);
    int i, j, k;
    for (i = 0; i < 3; i++) {
        for (j = 0; j <= i; j++) {
            fnav_real_t a = f->P[ob + i][ob + j] + (i == j ? r2 : FNAV_R(0.0));
            for (k = 0; k < j; k++) {
                a -= l[i][k] * l[j][k];
            }
            if (i == j) {
                if (!(a > FNAV_R(0.0))) {
                    return (fnav_real_t)INFINITY;
                }
                l[i][i] = fnav_sqrt(a);
            } else {
                l[i][j] = a / l[j][j];
            }
        }
    }
    for (i = 0; i < 3; i++) { /* z = L^-1 y, nis = |z|^2 */
        fnav_real_t a = y.v[i];
        for (k = 0; k < i; k++) {
            a -= l[i][k] * z[k];
        }
        z[i] = a / l[i][i];
        nis += z[i] * z[i];
    }
    return nis;
}

fnav_status_t fnav_ukf_zaru(fnav_ukf_t *f, fnav_vec3_t gyro_rps)
{
    int cols[3], i, ob;
    fnav_status_t st;
    fnav_vec3_t y;
    fnav_real_t r2;
    if (f == NULL) {
        return FNAV_E_ARG;
    }
    if (!f->started) {
        return FNAV_E_STATE;
    }
    if (!fnav_vec3_isfinite(gyro_rps)) {
        f->health.nan_inputs++;
        return FNAV_E_NANINF;
    }
    if (f->cfg.bias_model != FNAV_BIAS_AR1) {
        return FNAV_OK;
    }
    ob = f->pos[FNAV_UKF_BG];
    for (i = 0; i < 3; i++) {
        cols[i] = ob + i;
    }
    y = fnav_vec3_sub(gyro_rps, f->bg_rps);
    r2 = f->cfg.zaru_sigma_rps * f->cfg.zaru_sigma_rps;
    if (f->cfg.zaru_gate > FNAV_R(0.0) && !(zaru_nis(f, ob, y, r2) <= f->cfg.zaru_gate)) {
        f->health.zaru_gated++;
        return FNAV_E_RANGE;
    }
    st = update(f, NULL, cols, 3, y, r2, 0);
    if (st == FNAV_OK) {
        f->health.zarus++;
    }
    return st;
}

fnav_vec3_t fnav_ukf_euler(const fnav_ukf_t *f)
{
    return fnav_quat_to_euler(f->q_nb);
}

void fnav_ukf_p_diag(const fnav_ukf_t *f, fnav_real_t out[FNAV_UKF_N])
{
    int i;
    for (i = 0; i < 3; i++) {
        out[i] = fnav_ukf_cov(f, FNAV_UKF_A + i, FNAV_UKF_A + i);
        out[3 + i] = fnav_ukf_cov(f, FNAV_UKF_V + i, FNAV_UKF_V + i);
        out[6 + i] = fnav_ukf_cov(f, FNAV_UKF_P + i, FNAV_UKF_P + i);
        out[9 + i] = fnav_ukf_cov(f, FNAV_UKF_BG + i, FNAV_UKF_BG + i);
        out[12 + i] = fnav_ukf_cov(f, FNAV_UKF_BA + i, FNAV_UKF_BA + i);
    }
}
