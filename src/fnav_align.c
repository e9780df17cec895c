/* Initial alignment from the first still seconds (fnav_align.h). */
#include "footnav/fnav_align.h"
#include "footnav/fnav_port.h"

const fnav_align_config_t fnav_align_config_default = {
    FNAV_R(0.5),    /* min_still_s, s */
    FNAV_R(5.0),    /* max_still_s, s */
    FNAV_R(9.80665), /* gravity_mps2, m/s^2 */
    FNAV_R(10.0)     /* still_ratio: one decade above the noise floor */
};

static void reset_period(fnav_align_t *al)
{
    al->sa = al->sg = al->sa2 = al->sg2 = fnav_vec3_zero();
    al->n = 0;
    al->sum_log_stat = FNAV_R(0.0);
}

fnav_status_t fnav_align_init(fnav_align_t *al, const fnav_align_config_t *cfg)
{
    if (al == NULL || cfg == NULL) {
        return FNAV_E_ARG;
    }
    if (!(fnav_isfinite(cfg->min_still_s) && cfg->min_still_s > FNAV_R(0.0)) ||
        !(fnav_isfinite(cfg->max_still_s) && cfg->max_still_s >= cfg->min_still_s) ||
        !(fnav_isfinite(cfg->gravity_mps2) && cfg->gravity_mps2 > FNAV_R(0.0)) ||
        !(fnav_isfinite(cfg->still_ratio) && cfg->still_ratio > FNAV_R(1.0))) {
        return FNAV_E_CONFIG;
    }
    al->cfg = *cfg;
    al->done = 0;
    al->t0_ns = al->t_last_ns = 0;
    al->a_ref = al->g_ref = fnav_vec3_zero();
    reset_period(al);
    return FNAV_OK;
}

fnav_status_t fnav_align_from_means(fnav_vec3_t f, fnav_vec3_t w, fnav_real_t g, fnav_align_result_t *out)
{
    fnav_real_t fn = fnav_vec3_norm(f);
    fnav_real_t roll, pitch;
    if (!(fn > FNAV_R(0.0)) || !fnav_isfinite(fn)) {
        return FNAV_E_RANGE;
    }
    /* f_b = C_bn (0, 0, -g) = -g (-sin p, sin r cos p, cos r cos p) */
    roll = fnav_atan2(-f.v[1], -f.v[2]);
    pitch = fnav_atan2(f.v[0], fnav_sqrt(f.v[1] * f.v[1] + f.v[2] * f.v[2]));
    out->q_nb = fnav_quat_from_euler(roll, pitch, FNAV_R(0.0));
    out->euler_rad = fnav_vec3(roll, pitch, FNAV_R(0.0));
    out->gyro_bias_rps = w;
    out->accel_bias_mps2 = fnav_vec3_scale(f, (fn - g) / fn);
    out->accel_mean_mps2 = f;
    return FNAV_OK;
}

static fnav_status_t complete(fnav_align_t *al)
{
    fnav_real_t inv = FNAV_R(1.0) / (fnav_real_t)al->n;
    fnav_vec3_t ma = fnav_vec3_scale(al->sa, inv), mg = fnav_vec3_scale(al->sg, inv);
    fnav_align_result_t *r = &al->result;
    fnav_status_t st;
    int i;
    st = fnav_align_from_means(fnav_vec3_add(al->a_ref, ma), fnav_vec3_add(al->g_ref, mg), al->cfg.gravity_mps2, r);
    if (st != FNAV_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        fnav_real_t k = (al->n > 1) ? FNAV_R(1.0) / (fnav_real_t)(al->n - 1) : FNAV_R(0.0);
        fnav_real_t va = (al->sa2.v[i] - al->sa.v[i] * ma.v[i]) * k;
        fnav_real_t vg = (al->sg2.v[i] - al->sg.v[i] * mg.v[i]) * k;
        r->accel_sd_mps2.v[i] = fnav_sqrt(va > FNAV_R(0.0) ? va : FNAV_R(0.0));
        r->gyro_sd_rps.v[i] = fnav_sqrt(vg > FNAV_R(0.0) ? vg : FNAV_R(0.0));
    }
    r->samples = al->n;
    r->duration_s = (fnav_real_t)(al->t_last_ns - al->t0_ns) * FNAV_R(1.0e-9);
    al->done = 1;
    return FNAV_OK;
}

fnav_status_t fnav_align_push(fnav_align_t *al, const fnav_sample_t *s, int still, fnav_real_t stat)
{
    fnav_real_t dur, lstat = FNAV_R(0.0);
    int i;
    if (al == NULL || s == NULL) {
        return FNAV_E_ARG;
    }
    if (al->done) {
        return FNAV_E_STATE;
    }
    if (still && stat > FNAV_R(0.0) && fnav_isfinite(stat)) {
        lstat = fnav_log10(stat);
        if (al->n > 0 && lstat > al->sum_log_stat / (fnav_real_t)al->n + fnav_log10(al->cfg.still_ratio)) {
            still = 0; /* the statistic left the noise floor: motion begins */
        }
    }
    if (!still) {
        dur = (fnav_real_t)(al->t_last_ns - al->t0_ns) * FNAV_R(1.0e-9);
        if (al->n >= 2 && dur >= al->cfg.min_still_s) {
            return complete(al);
        }
        reset_period(al);
        return FNAV_AGAIN;
    }
    if (al->n == 0) {
        al->a_ref = fnav_vec3_from(s->accel_mps2);
        al->g_ref = fnav_vec3_from(s->gyro_rps);
        al->t0_ns = s->t_ns;
    }
    for (i = 0; i < 3; i++) {
        fnav_real_t da = s->accel_mps2[i] - al->a_ref.v[i];
        fnav_real_t dg = s->gyro_rps[i] - al->g_ref.v[i];
        al->sa.v[i] += da;
        al->sa2.v[i] += da * da;
        al->sg.v[i] += dg;
        al->sg2.v[i] += dg * dg;
    }
    al->sum_log_stat += lstat;
    al->n++;
    al->t_last_ns = s->t_ns;
    dur = (fnav_real_t)(al->t_last_ns - al->t0_ns) * FNAV_R(1.0e-9);
    if (dur >= al->cfg.max_still_s) {
        return complete(al);
    }
    return FNAV_AGAIN;
}

fnav_status_t fnav_align_finish(fnav_align_t *al)
{
    if (al == NULL) {
        return FNAV_E_ARG;
    }
    if (al->done) {
        return FNAV_OK;
    }
    if (al->n < 2 || (fnav_real_t)(al->t_last_ns - al->t0_ns) * FNAV_R(1.0e-9) < al->cfg.min_still_s) {
        return FNAV_E_STATE;
    }
    return complete(al);
}
