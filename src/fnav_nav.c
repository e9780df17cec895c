/* Foot-mounted navigation: detector + alignment + UKF, stepped per sample
 * (fnav_nav.h). */
#include "footnav/fnav_nav.h"

/* The default: the generic MEMS profile (fnav_profile.h; the same as
 * fnav_profile_by_name("generic-mems") and docs/profiles/generic-mems.profile,
 * tested) with the AR(1) bias model, and the lever states. */
#define D2R FNAV_DEG2RAD
const fnav_nav_config_t fnav_nav_config_default = {
    FNAV_PROFILE_GENERIC_MEMS_INIT, /* profile: docs/navigation.md, "Bias model" */
    FNAV_BIAS_AR1, /* bias_model: see docs/navigation.md (evidence in docs/results.md) */
    FNAV_STANCE_CONFIG_DEFAULT_INIT, /* stance: the detector's own defaults */
    { FNAV_R(0.5), FNAV_R(5.0), FNAV_R(9.80665), FNAV_R(10.0), FNAV_R(0.2), FNAV_R(0.5) * D2R },
    FNAV_R(9.80665),    /* gravity_mps2 */
    FNAV_SAMPLE_INSTANT, /* sample_type: rate-output sensors (docs/navigation.md) */
    FNAV_R(0.02),       /* accel_motion_noise_mps2_rthz */
    FNAV_R(0.02) * D2R, /* gyro_motion_noise_rps_rthz */
    FNAV_R(0.01),       /* zupt_sigma_mps */
    1,                  /* lever */
    FNAV_R(0.1),        /* lever_sd_m */
    FNAV_R(0.002),      /* lever_rw_m_rts */
    1,                  /* settle: docs/navigation.md, "The landing" */
    FNAV_R(0.025),      /* settle_sd_mps */
    FNAV_R(0.03),       /* settle_tau_s */
    0,                  /* zaru */
    FNAV_R(0.01),       /* zaru_sigma_rps */
    FNAV_R(11.34),      /* zaru_gate: chi-square, 3 dof, 99 % */
    FNAV_R(0.0),        /* zaru_after_s */
    FNAV_R(3.0),        /* realign_min_s: docs/navigation.md, "Initial alignment" */
    FNAV_R(0.5) * D2R,  /* tilt_sd_rad */
    FNAV_R(0.001),      /* yaw_sd_rad */
    FNAV_R(0.01) * D2R, /* gyro_bias_sd_rps */
    FNAV_R(0.02),       /* accel_bias_sd_mps2 */
    FNAV_R(0.2),        /* max_gap_s */
    1,                  /* closed_form */
    FNAV_R(30.0),       /* diverge_speed_mps */
    20u                 /* diverge_undone */
};

/* An initial standard deviation the filter takes (fnav_ukf_start): finite
 * and positive, and so is its variance (fnav_ukf_start refuses an sd whose
 * square is 0 or infinite, and start_filter asserts it starts). */
static int sd_ok(fnav_real_t x)
{
    return fnav_isfinite(x) && x > FNAV_R(0.0) && fnav_isfinite(x * x) && x * x > FNAV_R(0.0);
}

static fnav_real_t rss(fnav_real_t a, fnav_real_t b)
{
    return fnav_sqrt(a * a + b * b);
}

static void ukf_config_from(const fnav_nav_config_t *c, fnav_ukf_config_t *u)
{
    int i;
    *u = fnav_ukf_config_default;
    for (i = 0; i < 3; i++) {
        u->gyro_noise_rps_rthz[i] = rss(c->profile.gyro_noise_rps_rthz[i], c->gyro_motion_noise_rps_rthz);
        u->accel_noise_mps2_rthz[i] = rss(c->profile.accel_noise_mps2_rthz[i], c->accel_motion_noise_mps2_rthz);
        u->gyro_tau_s[i] = c->profile.gyro_tau_s[i];
        u->accel_tau_s[i] = c->profile.accel_tau_s[i];
        u->gyro_bias_sigma_rps[i] = c->profile.gyro_bias_sigma_rps[i];
        u->accel_bias_sigma_mps2[i] = c->profile.accel_bias_sigma_mps2[i];
    }
    u->bias_model = c->bias_model;
    u->strapdown.gravity_mps2 = c->gravity_mps2;
    u->strapdown.sample_type = c->sample_type;
    u->zupt_sigma_mps = c->zupt_sigma_mps;
    u->zaru_sigma_rps = c->zaru_sigma_rps;
    u->zaru_gate = c->zaru_gate;
    u->closed_form = c->closed_form;
    u->lever = c->lever;
    u->lever_sd_m = c->lever_sd_m;
    u->lever_rw_m_rts = c->lever_rw_m_rts;
    u->settle = c->settle;
    u->settle_sd_mps = c->settle_sd_mps;
    u->settle_tau_s = c->settle_tau_s;
}

/* Every byte of the navigator to 0: the state of static storage, which
 * nav_ready() tells from an initialised one; but its configuration when
 * keep_cfg (a restart with it: fnav_nav_init(&nav, &nav.cfg)). */
static void nav_zero(fnav_nav_t *nav, int keep_cfg)
{
    unsigned char *p = (unsigned char *)nav;
    const size_t c0 = offsetof(fnav_nav_t, cfg), c1 = c0 + sizeof nav->cfg;
    size_t b;
    for (b = 0; b < sizeof *nav; b++) {
        if (!keep_cfg || b < c0 || b >= c1) {
            p[b] = 0;
        }
    }
}

/* Initialised by a successful fnav_nav_init, which requires the gravity
 * positive: it is 0 in a zeroed object (static storage, a failed init),
 * and a NaN there fails the test too. An automatic object never
 * initialised holds whatever was on the stack: not detectable (fnav_nav.h). */
static int nav_ready(const fnav_nav_t *nav)
{
    return nav->cfg.gravity_mps2 > FNAV_R(0.0);
}

static fnav_status_t nav_init(fnav_nav_t *nav, const fnav_nav_config_t *cfg)
{
    fnav_stance_config_t sc;
    fnav_align_config_t ac;
    fnav_ukf_config_t uc;
    fnav_status_t st;
    if (fnav_profile_validate(&cfg->profile) != FNAV_OK || !fnav_isfinite(cfg->gravity_mps2) ||
        !(cfg->gravity_mps2 > FNAV_R(0.0)) || !fnav_isfinite(cfg->accel_motion_noise_mps2_rthz) ||
        cfg->accel_motion_noise_mps2_rthz < FNAV_R(0.0) || !fnav_isfinite(cfg->gyro_motion_noise_rps_rthz) ||
        cfg->gyro_motion_noise_rps_rthz < FNAV_R(0.0) || !sd_ok(cfg->tilt_sd_rad) || !sd_ok(cfg->yaw_sd_rad) ||
        !sd_ok(cfg->gyro_bias_sd_rps) || !sd_ok(cfg->accel_bias_sd_mps2) || !(cfg->max_gap_s > FNAV_R(0.0)) ||
        !fnav_isfinite(cfg->max_gap_s) ||
        !(cfg->diverge_speed_mps > FNAV_R(0.0)) || !fnav_isfinite(cfg->diverge_speed_mps) ||
        cfg->diverge_undone == 0u || (cfg->zaru != 0 && cfg->zaru != 1) || !(cfg->realign_min_s >= FNAV_R(0.0)) || !fnav_isfinite(cfg->realign_min_s) ||
        /* a still period ends at the alignment's max_still_s, so a longer
         * minimum would never renew */
        cfg->realign_min_s > cfg->align.max_still_s || !(cfg->zaru_after_s >= FNAV_R(0.0)) ||
        !fnav_isfinite(cfg->zaru_after_s) ||
        /* a time jump is longer than a gap (1.5 nominal intervals): below,
         * every interval would be a jump and the alignment never completes */
        (cfg->stance.rate_hz > FNAV_R(0.0) && !(cfg->max_gap_s * cfg->stance.rate_hz > FNAV_R(1.5)))) {
        return FNAV_E_CONFIG;
    }
    /* *cfg may be the navigator's own configuration (a restart with it):
     * it was zeroed here before it was read, and the init refused it */
    nav_zero(nav, cfg == &nav->cfg);
    if (cfg != &nav->cfg) {
        nav->cfg = *cfg;
    }
    nav->t_in_ns = INT64_MIN; /* no sample yet: none is behind it */
    sc = cfg->stance;
    sc.gravity_mps2 = cfg->gravity_mps2;
    ac = cfg->align;
    ac.gravity_mps2 = cfg->gravity_mps2;
    ukf_config_from(cfg, &uc);
    st = fnav_stance_init(&nav->stance, &sc);
    if (st != FNAV_OK) {
        return st;
    }
    st = fnav_align_init(&nav->align, &ac);
    if (st != FNAV_OK) {
        return st;
    }
    st = fnav_ukf_init(&nav->ukf, &uc);
    if (st != FNAV_OK) {
        return st;
    }
    /* the initial attitude sd fnav_ukf_start takes (its test, to the
     * rounding: fnav_nav_att_sd_max_rad) */
    if (cfg->tilt_sd_rad * nav->ukf.gamma > FNAV_UKF_ATT_GRP_MAX || cfg->yaw_sd_rad * nav->ukf.gamma > FNAV_UKF_ATT_GRP_MAX) {
        return FNAV_E_CONFIG;
    }
    return FNAV_OK;
}

fnav_real_t fnav_nav_att_sd_max_rad(const fnav_nav_config_t *cfg)
{
    fnav_ukf_config_t uc;
    if (cfg == NULL) {
        return FNAV_R(0.0);
    }
    ukf_config_from(cfg, &uc);
    return fnav_ukf_att_sd_max(&uc);
}

fnav_status_t fnav_nav_init_tagged(fnav_nav_t *nav, const fnav_nav_config_t *cfg, uint64_t build_tag, size_t obj_size,
                                   size_t cfg_size)
{
    fnav_status_t st;
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_nav_t) || cfg_size != sizeof(fnav_nav_config_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (nav == NULL || cfg == NULL) {
        return FNAV_E_ARG;
    }
    st = nav_init(nav, cfg);
    if (st != FNAV_OK) {
        /* not initialised, whatever it was before: every later call says
         * FNAV_E_STATE instead of running a half-configured navigator (a
         * module's refusal came after the configuration was copied) */
        nav_zero(nav, 0);
    }
    return st;
}

fnav_status_t fnav_sample_check(const fnav_sample_t *s)
{
    fnav_status_t st = FNAV_OK;
    int i;
    if (s == NULL) {
        return FNAV_E_ARG;
    }
    for (i = 0; i < 3; i++) {
        if (!fnav_isfinite(s->accel_mps2[i]) || !fnav_isfinite(s->gyro_rps[i])) {
            return FNAV_E_NANINF;
        }
        if (fnav_fabs(s->accel_mps2[i]) > (fnav_real_t)FNAV_INPUT_MAX_ABS ||
            fnav_fabs(s->gyro_rps[i]) > (fnav_real_t)FNAV_INPUT_MAX_ABS) {
            st = FNAV_E_RANGE;
        }
    }
    if (s->t_ns > FNAV_T_NS_MAX || s->t_ns < -FNAV_T_NS_MAX) {
        st = FNAV_E_RANGE; /* a later difference would overflow */
    }
    return st;
}

/* 1 when every axis is within the widest MEMS ranges (fnav_config.h,
 * FNAV_NAV_GYRO_MAX_RPS): a rate or force past them is a glitch, which
 * integrated would turn the heading or throw the velocity. */
static int sample_plausible(const fnav_sample_t *s)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (fnav_fabs(s->gyro_rps[i]) > (fnav_real_t)FNAV_NAV_GYRO_MAX_RPS ||
            fnav_fabs(s->accel_mps2[i]) > (fnav_real_t)FNAV_NAV_ACCEL_MAX_MPS2) {
            return 0;
        }
    }
    return 1;
}

fnav_status_t fnav_nav_push(fnav_nav_t *nav, const fnav_sample_t *sample)
{
    fnav_status_t st;
    if (nav == NULL || sample == NULL) {
        return FNAV_E_ARG;
    }
    if (!nav_ready(nav) || nav->stance.finished) {
        /* not initialised (test_nav test_not_initialised), or the input
         * has ended: a call in the wrong state, whatever the
         * sample (a firmware loop that keeps pushing learns it from this
         * status, not from a sensor status); nothing counted, the stats
         * and health of the finished run stay as they were (fnav_nav.h) */
        return FNAV_E_STATE;
    }
    st = fnav_sample_check(sample);
    if (st == FNAV_E_NANINF) {
        nav->stats.nan_inputs++;
        nav->health |= FNAV_HEALTH_NANINF;
        return st;
    }
    if (st == FNAV_OK && !sample_plausible(sample)) {
        st = FNAV_E_RANGE;
    }
    if (st != FNAV_OK) {
        nav->stats.range_inputs++;
        nav->health |= FNAV_HEALTH_RANGE;
        return st;
    }
    if (sample->t_ns < nav->t_in_ns && nav->back_run + 1u < (uint32_t)FNAV_NAV_TIME_RESYNC) {
        /* a run of FNAV_NAV_TIME_RESYNC samples behind the last accepted
         * one is a new timeline (a corrupted stamp far ahead, a restarted
         * timer), whose first sample is accepted below: otherwise one stamp
         * 1 h ahead would have every later sample rejected for the rest of
         * the run (test_nav test_time_glitch_forward) */
        nav->back_run++;
        nav->stats.time_back++;
        nav->health |= FNAV_HEALTH_TIME_BACK;
        return FNAV_E_TIME;
    }
    st = fnav_stance_push(&nav->stance, sample);
    if (st != FNAV_OK) {
        return st;
    }
    nav->back_run = 0;
    nav->t_in_ns = sample->t_ns;
    nav->stats.samples++;
    return FNAV_OK;
}

static void start_filter(fnav_nav_t *nav)
{
    const fnav_align_result_t *r = &nav->align.result;
    const fnav_nav_config_t *c = &nav->cfg;
    fnav_ukf_init_sd_t sd;
    fnav_status_t st;
    int i;
    for (i = 0; i < 3; i++) {
        /* AR(1) states: the in-run variation about the alignment value
         * (docs/navigation.md, "Bias model"), which starts small; the
         * alignment's own error (r->gyro_bias_sd_rps) is not re-estimated
         * from the ZUPTs, which attribute strapdown errors to it */
        sd.gyro_bias_rps[i] = c->gyro_bias_sd_rps;
        sd.accel_bias_mps2[i] = c->accel_bias_sd_mps2;
        sd.att_rad[i] = c->tilt_sd_rad;
    }
    sd.att_rad[2] = c->yaw_sd_rad;
    sd.vel_mps = c->zupt_sigma_mps;
    sd.pos_m = FNAV_R(0.001);
    st = fnav_ukf_start(&nav->ukf, r->q_nb, r->gyro_bias_rps, r->accel_bias_mps2, &sd);
    FNAV_ASSERT(st == FNAV_OK);
    (void)st;
    if (nav->have_hold) {
        /* after a reset: continue from the last good position and heading.
         * The alignment defines yaw 0; turn it about n's z by the psi that
         * brings it closest to the held attitude, min ||Rz(psi) C_new -
         * C_held||_F (Wahba's problem with the rotation restricted to the
         * vertical axis): with M = C_held C_new^T, trace(Rz(psi)^T M) =
         * cos(psi) (M00 + M11) + sin(psi) (M10 - M01) + M22, largest at
         * psi = atan2(M10 - M01, M00 + M11). Equal to the held ZYX yaw
         * when the tilts agree; unlike that yaw (the heading of b's x
         * axis), it is defined for every mounting, also with b's x axis
         * vertical, where yaw and roll split by the noise and holding the
         * yaw turned the path by 87 and 110 deg at the two renewals of the
         * xio short walk turned upright (test_nav test_realign_x_vertical). */
        fnav_mat3_t ch = fnav_quat_to_dcm(nav->hold_q_nb), cn = fnav_quat_to_dcm(nav->ukf.q_nb);
        fnav_real_t m00 = FNAV_R(0.0), m11 = FNAV_R(0.0), m10 = FNAV_R(0.0), m01 = FNAV_R(0.0), psi;
        fnav_quat_t qz;
        for (i = 0; i < 3; i++) {
            m00 += ch.m[0][i] * cn.m[0][i];
            m11 += ch.m[1][i] * cn.m[1][i];
            m10 += ch.m[1][i] * cn.m[0][i];
            m01 += ch.m[0][i] * cn.m[1][i];
        }
        psi = fnav_atan2(m10 - m01, m00 + m11);
        qz = fnav_quat_from_rotvec(fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), psi));
        nav->ukf.q_nb = fnav_quat_normalize(fnav_quat_mul(qz, nav->ukf.q_nb));
        nav->ukf.pos_m = nav->hold_pos_m;
        for (i = 0; i < 3; i++) {
            fnav_real_t v = nav->hold_pos_var_m2[i];
            if (fnav_isfinite(v) && v > fnav_ukf_cov(&nav->ukf, FNAV_UKF_P + i, FNAV_UKF_P + i)) {
                fnav_ukf_set_cov(&nav->ukf, FNAV_UKF_P + i, FNAV_UKF_P + i, v);
            }
        }
        /* after a reset the heading keeps its variance too: the walk went
         * on with it (a renewal holds none, unless a reset came before it:
         * before the first stride the heading is the frame's own
         * definition, nothing was navigated) */
        if (fnav_isfinite(nav->hold_yaw_var_rad2) &&
            nav->hold_yaw_var_rad2 > fnav_ukf_cov(&nav->ukf, FNAV_UKF_A + 2, FNAV_UKF_A + 2)) {
            /* no larger than the sigma points represent (FNAV_UKF_ATT_GRP_MAX):
             * the covariance guard's attitude maximum, pi rad, is above it */
            fnav_real_t lim = FNAV_UKF_ATT_GRP_MAX / nav->ukf.gamma, v = nav->hold_yaw_var_rad2;
            fnav_ukf_set_cov(&nav->ukf, FNAV_UKF_A + 2, FNAV_UKF_A + 2, v < lim * lim ? v : lim * lim);
        }
        nav->have_hold = 0;
    }
    nav->undone_run = 0;
    /* a landing seen before this start (a reset between a stance onset and
     * its first ZUPT) was the old filter's: the new one starts in a still
     * period (test_nav test_settle_pending_reset) */
    nav->settle_pending = 0;
    nav->aligned = 1;
    /* the walker may stand on: keep measuring the still periods */
    nav->renewing = nav->cfg.realign_min_s > FNAV_R(0.0);
    fnav_align_renew_start(&nav->align);
}

/* Hold the last frame's position, heading and position variance for the
 * next start_filter (a reset, a renewed alignment), if that frame is a
 * good one; with keep_yaw_var (a reset) the heading's variance as well. */
static void hold_last_frame(fnav_nav_t *nav, int keep_yaw_var)
{
    const fnav_nav_frame_t *g = &nav->last;
    int good = (g->flags & FNAV_FRAME_ALIGNED) != 0u;
    int i;
    for (i = 0; i < 3; i++) {
        good = good && fnav_isfinite(g->pos_m[i]) && fnav_isfinite(g->p_diag[FNAV_UKF_P + i]);
    }
    if (good) {
        nav->hold_pos_m = fnav_vec3(g->pos_m[0], g->pos_m[1], g->pos_m[2]);
        /* the frame's attitude as the filter had it is already in
         * hold_q_nb (fill_frame keeps it there while aligned), not rebuilt
         * from its ZYX angles: near pitch +-90 deg roll and yaw each carry
         * the quaternion's rounding / cos(pitch), and so does the attitude
         * they give back (in float32 1.2 deg off at 0.001 deg from 90, 10
         * deg at 1e-4, any heading at 90) */
        for (i = 0; i < 3; i++) {
            nav->hold_pos_var_m2[i] = g->p_diag[FNAV_UKF_P + i];
        }
        nav->hold_yaw_var_rad2 = keep_yaw_var ? g->p_diag[2] : -FNAV_R(1.0); /* frame order: attitude first */
        nav->have_hold = 1;
    }
}

/* Before the first stride, a clean still period of at least realign_min_s
 * that ends renews the alignment: roll, pitch and the biases from it, the
 * position and heading held (the alignment defines neither). The bias a
 * MEMS gyro has just after power-on drifts by several hundredths of a
 * degree per second in the first seconds, so the stillness just before the
 * walk is the better measurement (docs/navigation.md, "Initial alignment").
 * 1 when the filter was restarted at this sample. */
static int renew_alignment(fnav_nav_t *nav, const fnav_stance_out_t *o)
{
    /* written only with a renewal (no copy on the step's stack) */
    if (!fnav_align_renew(&nav->align, &o->sample, o->stance, o->stat, nav->cfg.realign_min_s,
                          &nav->align.result)) {
        return 0;
    }
    /* the state before this sample; its heading variance only after a
     * divergence reset, when the heading was navigated (the walk went on
     * from the last good frame): before the first stride of a log it is
     * the frame's own definition. Restarting it at yaw_sd^2 in a renewal
     * in the stand after a reset would undo the reset's hold
     * (test_nav_robust test_reset_then_renewal). */
    hold_last_frame(nav, nav->stats.resets > 0u);
    start_filter(nav);
    nav->stats.realigned++;
    return 1;
}

void fnav_nav_reset(fnav_nav_t *nav)
{
    fnav_status_t st;
    FNAV_ASSERT(nav != NULL);
    if (!nav_ready(nav)) {
        return; /* not initialised: the next call says FNAV_E_STATE */
    }
    if (nav->aligned) {
        /* the state that triggered the reset is the diverged one */
        hold_last_frame(nav, 1);
    }
    nav->aligned = 0;
    nav->undone_run = 0;
    nav->stance_s = FNAV_R(0.0);
    st = fnav_align_init(&nav->align, &nav->align.cfg);
    FNAV_ASSERT(st == FNAV_OK); /* the configuration was accepted at init */
    (void)st;
    nav->stats.resets++;
    nav->health |= FNAV_HEALTH_RESET;
}

static void sync_health(fnav_nav_t *nav)
{
    const fnav_ukf_health_t *h = &nav->ukf.health;
    nav->stats.chol_jitter = h->chol_jitter;
    nav->stats.chol_reset = h->chol_reset;
    nav->stats.diverged = h->diverged;
    nav->stats.update_reject = h->update_reject;
    nav->stats.cov_guard = h->cov_guard;
    nav->stats.zupts = h->zupts;
    nav->stats.zarus = h->zarus;
    nav->stats.zaru_gated = h->zaru_gated;
    if (h->chol_jitter) {
        nav->health |= FNAV_HEALTH_CHOL_JITTER;
    }
    if (h->chol_reset) {
        nav->health |= FNAV_HEALTH_CHOL_RESET;
    }
    if (h->diverged) {
        nav->health |= FNAV_HEALTH_DIVERGED;
    }
    if (h->update_reject) {
        nav->health |= FNAV_HEALTH_UPDATE_REJECT;
    }
    if (h->cov_guard) {
        nav->health |= FNAV_HEALTH_COV_GUARD;
    }
}

static void fill_frame(fnav_nav_t *nav, const fnav_stance_out_t *o, uint32_t flags, fnav_nav_frame_t *fr)
{
    int i;
    size_t b;
    unsigned char *p = (unsigned char *)fr;
    for (b = 0; b < sizeof *fr; b++) {
        p[b] = 0; /* padding too: frames are byte-for-byte reproducible */
    }
    fr->t_ns = o->sample.t_ns;
    fr->seq = o->sample.seq;
    fr->flags = flags;
    if (nav->aligned) {
        const fnav_ukf_t *u = &nav->ukf;
        fnav_vec3_t e = fnav_ukf_euler(u);
        fr->flags |= FNAV_FRAME_ALIGNED;
        /* this frame becomes nav->last (fnav_nav_pop); its attitude for
         * hold_last_frame, in the hold (unused while aligned: no extra RAM) */
        nav->hold_q_nb = u->q_nb;
        for (i = 0; i < 3; i++) {
            fr->pos_m[i] = u->pos_m.v[i];
            fr->vel_mps[i] = u->vel_mps.v[i];
            fr->euler_rad[i] = e.v[i];
            fr->gyro_bias_rps[i] = u->bg_rps.v[i];
            fr->accel_bias_mps2[i] = u->ba_mps2.v[i];
            fr->lever_m[i] = u->lever_m.v[i];
        }
        fnav_ukf_p_diag(u, fr->p_diag);
    } else {
        for (i = 0; i < 3; i++) {
            fr->pos_m[i] = fr->vel_mps[i] = fr->euler_rad[i] = FNAV_R(0.0);
            fr->gyro_bias_rps[i] = fr->accel_bias_mps2[i] = fr->lever_m[i] = FNAV_R(0.0);
        }
        for (i = 0; i < FNAV_UKF_N; i++) {
            fr->p_diag[i] = FNAV_R(0.0);
        }
        if (nav->have_hold) {
            /* re-aligning after a reset: the held position and heading */
            for (i = 0; i < 3; i++) {
                fr->pos_m[i] = nav->hold_pos_m.v[i];
                fr->p_diag[FNAV_UKF_P + i] = nav->hold_pos_var_m2[i];
            }
            fr->p_diag[2] = nav->hold_yaw_var_rad2 > FNAV_R(0.0) ? nav->hold_yaw_var_rad2 : FNAV_R(0.0);
            const fnav_quat_t *q = &nav->hold_q_nb; /* its ZYX yaw (fnav_quat_to_euler) */
            fr->euler_rad[2] = fnav_atan2(FNAV_R(2.0) * (q->q[0] * q->q[3] + q->q[1] * q->q[2]),
                                          FNAV_R(1.0) - FNAV_R(2.0) * (q->q[2] * q->q[2] + q->q[3] * q->q[3]));
        }
    }
    sync_health(nav);
    fr->health = nav->health;
}

/* One detector decision through alignment / filter. */
static void process(fnav_nav_t *nav, const fnav_stance_out_t *o, fnav_nav_frame_t *fr)
{
    const fnav_sample_t *s = &o->sample;
    fnav_real_t dt = FNAV_R(0.0), dt_used;
    fnav_real_t nominal = FNAV_R(1.0) / nav->stance.rate_hz;
    uint32_t flags = 0;
    fnav_status_t st;
    if (o->stance) {
        flags |= FNAV_FRAME_STANCE;
        nav->stats.stance_samples++;
    }
    if (o->segment_stance) {
        flags |= FNAV_FRAME_SEG_STANCE;
    }
    /* a landing the running filter sees (not the still period the
     * alignment ends in): the settling state starts with its first ZUPT,
     * which a duplicated sample may postpone */
    if (o->stance && !nav->prev_stance && nav->aligned) {
        nav->settle_pending = 1;
    } else if (!o->stance) {
        nav->settle_pending = 0;
    }
    nav->prev_stance = o->stance;
    if (o->events & FNAV_STANCE_EV_STRIDE) {
        flags |= FNAV_FRAME_STRIDE;
        nav->stats.strides++;
    }
    if (nav->have_prev) {
        dt = fnav_i64_to_real(s->t_ns - nav->t_prev_ns) * FNAV_R(1.0e-9); /* no __aeabi_l2f under 2.1 s */
        if (dt > nav->stats.max_gap_seen_s) {
            nav->stats.max_gap_seen_s = dt;
        }
        if (dt == FNAV_R(0.0)) {
            nav->stats.duplicates++;
            nav->health |= FNAV_HEALTH_DUPLICATE;
        } else if (dt < FNAV_R(0.0) || (dt > nav->cfg.max_gap_s && dt > FNAV_R(1.5) * nominal)) {
            /* (the second test for an estimated rate whose interval is
             * above max_gap_s: init refuses that with a configured rate;
             * a negative interval is the step back to a new timeline that
             * fnav_nav_push accepted: as unknown as a jump forward) */
            nav->stats.time_jumps++;
            nav->health |= FNAV_HEALTH_TIME_JUMP;
            dt = nominal; /* the motion inside the jump is unknown */
            if (!nav->aligned || nav->renewing) {
                /* and so is the stillness: a still period being collected
                 * for the alignment starts again after the jump (as a
                 * renewal's does), or it would count the jump as still time */
                fnav_align_renew_start(&nav->align);
            }
        } else if (dt > FNAV_R(1.5) * nominal) {
            nav->stats.gaps++;
            nav->health |= FNAV_HEALTH_GAP;
        }
    }
    nav->have_prev = 1;
    nav->t_prev_ns = s->t_ns;
    dt_used = dt;

    if (!nav->aligned) {
        /* after the input's end (fnav_nav_finish), each sample the detector
         * held back goes to the alignment, which then completes as soon as
         * its still period qualifies (fnav_align_finish), so that a log
         * whose still period reaches align_short_s only with these samples
         * aligns (fnav_nav_finish alone tries before them; test_nav
         * test_align_at_end) */
        if (fnav_align_push(&nav->align, s, o->stance, o->stat) != FNAV_OK &&
            !(nav->stance.finished && fnav_align_finish(&nav->align) == FNAV_OK)) {
            fill_frame(nav, o, flags, fr);
            return;
        }
        start_filter(nav);
        /* aligned on the still samples up to this one: if the foot moves at
         * this sample its interval is navigated, otherwise navigation starts
         * with the next interval */
        if (o->stance) {
            dt_used = FNAV_R(0.0);
        }
    } else if (nav->renewing) {
        if (o->events & FNAV_STANCE_EV_STRIDE) {
            nav->renewing = 0;
        } else if (renew_alignment(nav, o) && o->stance) {
            dt_used = FNAV_R(0.0); /* as at the first alignment */
        }
    }
    if (!o->stance) {
        nav->stance_s = FNAV_R(0.0); /* the ZARU's standstill clock */
    }
    if (dt_used > FNAV_R(0.0)) {
        st = fnav_ukf_predict(&nav->ukf, fnav_vec3_from(s->gyro_rps), fnav_vec3_from(s->accel_mps2), dt_used);
        /* problems are counted in the UKF's health; a run of undone steps or
         * an impossible speed is divergence: reset and re-align */
        nav->undone_run = (st == FNAV_E_DIVERGED) ? nav->undone_run + 1u : 0u;
        if (nav->undone_run >= nav->cfg.diverge_undone ||
            !(fnav_vec3_norm(nav->ukf.vel_mps) <= nav->cfg.diverge_speed_mps)) {
            fnav_nav_reset(nav);
            fill_frame(nav, o, flags, fr);
            return;
        }
        if (o->stance) {
            if (nav->settle_pending) {
                st = fnav_ukf_settle_start(&nav->ukf);
                (void)st; /* started: cannot fail */
                nav->settle_pending = 0;
            }
            if (fnav_ukf_zupt(&nav->ukf, fnav_vec3_from(s->gyro_rps)) == FNAV_OK) {
                flags |= FNAV_FRAME_ZUPT;
            }
            if (nav->stance_s < nav->cfg.zaru_after_s) {
                nav->stance_s += dt_used; /* saturates: a float sum of hours would lose the samples */
            }
            if (nav->cfg.zaru && nav->stance_s >= nav->cfg.zaru_after_s) {
                st = fnav_ukf_zaru(&nav->ukf, fnav_vec3_from(s->gyro_rps));
                (void)st;
            }
        }
    }
    fill_frame(nav, o, flags, fr);
}

fnav_status_t fnav_nav_pop(fnav_nav_t *nav, fnav_nav_frame_t *frame)
{
    fnav_stance_out_t o;
    fnav_status_t st;
    if (nav == NULL || frame == NULL) {
        return FNAV_E_ARG;
    }
    st = fnav_stance_pop(&nav->stance, &o);
    if (st != FNAV_OK) {
        if (!nav_ready(nav)) {
            /* never initialised: its zeroed detector has nothing to pop
             * (the test is here, off the path of every frame) */
            return FNAV_E_STATE;
        }
        if (st == FNAV_END && !nav->aligned) {
            nav->health |= FNAV_HEALTH_NOT_ALIGNED;
        }
        return st;
    }
    process(nav, &o, frame);
    nav->last = *frame;
    nav->stats.frames++;
    return FNAV_OK;
}

void fnav_nav_finish(fnav_nav_t *nav)
{
    FNAV_ASSERT(nav != NULL);
    if (!nav_ready(nav)) {
        return; /* not initialised: the next call says FNAV_E_STATE */
    }
    fnav_stance_finish(&nav->stance);
    /* the input ended while the foot was still: align on that period if it
     * qualifies, so that the frames still held back are navigated; if not,
     * those frames' samples may still complete it (process) */
    if (!nav->aligned && fnav_align_finish(&nav->align) == FNAV_OK) {
        start_filter(nav);
    }
}

fnav_status_t fnav_nav_step(fnav_nav_t *nav, const fnav_sample_t *sample, fnav_nav_frame_t *frame)
{
    fnav_status_t st;
    int got = 0;
    if (frame == NULL) {
        return FNAV_E_ARG; /* before the push: the sample is not taken */
    }
    st = fnav_nav_push(nav, sample);
    if (st != FNAV_OK) {
        return st;
    }
    while (fnav_nav_pop(nav, frame) == FNAV_OK) {
        got = 1;
    }
    return got ? FNAV_OK : FNAV_AGAIN;
}

fnav_status_t fnav_nav_run(fnav_nav_t *nav, const fnav_port_t *port, long max_samples)
{
    fnav_sample_t s;
    fnav_nav_frame_t fr;
    fnav_status_t st, rd = FNAV_OK;
    long n = 0;
    if (nav == NULL || port == NULL) {
        return FNAV_E_ARG;
    }
    if (!nav_ready(nav) || nav->stance.finished) {
        /* not initialised, or its input has ended: every push would be
         * refused, so nothing is read */
        return FNAV_E_STATE;
    }
    for (;;) {
        if (max_samples > 0 && n >= max_samples) {
            break;
        }
        rd = fnav_port_read(port, &s);
        if (rd == FNAV_AGAIN) {
            continue;
        }
        if (rd != FNAV_OK) {
            break;
        }
        if (max_samples > 0) {
            n++; /* counted only against a limit: a long is 32 bits on a Cortex-M */
        }
        st = fnav_nav_push(nav, &s); /* rejected samples are counted in nav->stats */
        (void)st;
        while (fnav_nav_pop(nav, &fr) == FNAV_OK) {
            if (fnav_port_write_nav(port, &fr) != FNAV_OK) {
                return FNAV_E_IO;
            }
        }
    }
    fnav_nav_finish(nav);
    while (fnav_nav_pop(nav, &fr) == FNAV_OK) {
        if (fnav_port_write_nav(port, &fr) != FNAV_OK) {
            return FNAV_E_IO;
        }
    }
    return (rd == FNAV_OK || rd == FNAV_END) ? FNAV_OK : rd;
}
