/* Initial alignment from the first still seconds (fnav_align.h). */
#include "footnav/fnav_align.h"
#include "footnav/fnav_port.h"

const fnav_align_config_t fnav_align_config_default = {
    FNAV_R(0.5),    /* min_still_s, s */
    FNAV_R(5.0),    /* max_still_s, s */
    FNAV_R(9.80665), /* gravity_mps2, m/s^2 */
    FNAV_R(10.0),    /* still_ratio: one decade above the noise floor */
    FNAV_R(0.2),     /* short_still_s, s */
    FNAV_R(0.5) * FNAV_DEG2RAD /* gyro_bias_prior_sd_rps, rad/s */
};

static void reset_period(fnav_align_period_t *p)
{
    p->sa = p->sg = p->sa2 = p->sg2 = fnav_vec3_zero();
    p->a_ref = p->g_ref = fnav_vec3_zero();
    p->n = 0;
    p->sum_log_stat = FNAV_R(0.0);
    p->blk_cur = fnav_vec3_zero();
    p->blk_len = 1;
    p->blk_fill = 0;
    p->nblk = 0;
    p->t0_ns = p->t_last_ns = 0;
}

fnav_status_t fnav_align_init_tagged(fnav_align_t *al, const fnav_align_config_t *cfg, uint64_t build_tag,
                                     size_t obj_size, size_t cfg_size)
{
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_align_t) || cfg_size != sizeof(fnav_align_config_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (al == NULL || cfg == NULL) {
        return FNAV_E_ARG;
    }
    if (!(fnav_isfinite(cfg->min_still_s) && cfg->min_still_s > FNAV_R(0.0)) ||
        !(fnav_isfinite(cfg->max_still_s) && cfg->max_still_s >= cfg->min_still_s) ||
        !(fnav_isfinite(cfg->short_still_s) && cfg->short_still_s > FNAV_R(0.0) &&
          cfg->short_still_s <= cfg->min_still_s) ||
        !(fnav_isfinite(cfg->gravity_mps2) && cfg->gravity_mps2 > FNAV_R(0.0)) ||
        !(fnav_isfinite(cfg->still_ratio) && cfg->still_ratio > FNAV_R(1.0)) ||
        !(fnav_isfinite(cfg->gyro_bias_prior_sd_rps) && cfg->gyro_bias_prior_sd_rps >= FNAV_R(0.0)) ||
        /* a positive prior's square, the posterior's weight, positive and
         * finite (float32: an sd above 1.8e19 made the bias Inf / Inf = NaN,
         * one below about 2.6e-23 the plain mean; test_align
         * test_prior_square) */
        (cfg->gyro_bias_prior_sd_rps > FNAV_R(0.0) &&
         !(fnav_isfinite(cfg->gyro_bias_prior_sd_rps * cfg->gyro_bias_prior_sd_rps) &&
           cfg->gyro_bias_prior_sd_rps * cfg->gyro_bias_prior_sd_rps > FNAV_R(0.0)))) {
        return FNAV_E_CONFIG;
    }
    al->cfg = *cfg;
    al->done = 0;
    al->have_best = 0;
    al->best_log_stat = FNAV_R(0.0);
    al->refused_f_mps2 = FNAV_R(0.0);
    reset_period(&al->cur);
    return FNAV_OK;
}

fnav_status_t fnav_align_from_means(fnav_vec3_t f, fnav_vec3_t w, fnav_real_t g, fnav_align_result_t *out)
{
    fnav_real_t fn;
    fnav_real_t roll, pitch;
    /* a public function (the harness's axes check calls it): a NULL out,
     * a g that is not finite and positive (g = 0 with f = 0 would pass the
     * test below, 0 <= 0, and g = +Inf too, Inf <= Inf, with an
     * accelerometer bias of NaN or Inf) and a NaN rate (it would come back
     * as the gyro bias) are refused (test_align test_from_means_bad_args) */
    if (out == NULL || !fnav_isfinite(g) || !(g > FNAV_R(0.0))) {
        return FNAV_E_ARG;
    }
    if (!fnav_vec3_isfinite(w)) {
        return FNAV_E_NANINF;
    }
    fn = fnav_vec3_norm(f);
    if (!(fnav_fabs(fn - g) <= FNAV_ALIGN_GRAVITY_TOL * g)) { /* NaN, zero and not at rest on the Earth */
        return FNAV_E_RANGE;
    }
    /* f_b = C_bn (0, 0, -g) = -g (-sin p, sin r cos p, cos r cos p) */
    roll = fnav_atan2(-f.v[1], -f.v[2]);
    pitch = fnav_atan2(f.v[0], fnav_sqrt(f.v[1] * f.v[1] + f.v[2] * f.v[2]));
    out->q_nb = fnav_quat_from_euler(roll, pitch, FNAV_R(0.0));
    out->euler_rad = fnav_vec3(roll, pitch, FNAV_R(0.0));
    out->gyro_bias_rps = w;
    out->gyro_mean_rps = w;
    out->gyro_mean_se_rps = fnav_vec3_zero();
    out->gyro_bias_sd_rps = fnav_vec3_zero();
    out->accel_bias_mps2 = fnav_vec3_scale(f, (fn - g) / fn);
    out->accel_mean_mps2 = f;
    return FNAV_OK;
}

static fnav_real_t duration_s(const fnav_align_period_t *p)
{
    return fnav_i64_to_real(p->t_last_ns - p->t0_ns) * FNAV_R(1.0e-9);
}

/* Squared standard error of the mean rate of axis i: the larger of the
 * batch-means estimate (var of the block means / blocks) and the white-noise
 * value (var / n). */
static fnav_real_t mean_se2(const fnav_align_period_t *p, fnav_real_t var, int i)
{
    fnav_real_t se2 = var / (fnav_real_t)p->n;
    if (p->nblk >= 2) {
        fnav_real_t sm = FNAV_R(0.0), sq = FNAV_R(0.0), nb = (fnav_real_t)p->nblk;
        fnav_real_t inv = FNAV_R(1.0) / (fnav_real_t)p->blk_len;
        fnav_real_t vb;
        int k;
        for (k = 0; k < p->nblk; k++) {
            fnav_real_t m = p->blk[k].v[i] * inv;
            sm += m;
            sq += m * m;
        }
        sm /= nb;
        vb = (sq - nb * sm * sm) / (nb - FNAV_R(1.0));
        if (vb / nb > se2) {
            se2 = vb / nb;
        }
    }
    return se2;
}

/* The alignment of period p into *r. */
static fnav_status_t period_result(const fnav_align_t *al, const fnav_align_period_t *p, fnav_align_result_t *r)
{
    fnav_real_t inv = FNAV_R(1.0) / (fnav_real_t)p->n;
    fnav_vec3_t ma = fnav_vec3_scale(p->sa, inv), mg = fnav_vec3_scale(p->sg, inv);
    fnav_real_t s02 = al->cfg.gyro_bias_prior_sd_rps * al->cfg.gyro_bias_prior_sd_rps;
    fnav_status_t st;
    int i;
    st = fnav_align_from_means(fnav_vec3_add(p->a_ref, ma), fnav_vec3_add(p->g_ref, mg), al->cfg.gravity_mps2, r);
    if (st != FNAV_OK) {
        return st;
    }
    for (i = 0; i < 3; i++) {
        fnav_real_t k = (p->n > 1) ? FNAV_R(1.0) / (fnav_real_t)(p->n - 1) : FNAV_R(0.0);
        fnav_real_t va = (p->sa2.v[i] - p->sa.v[i] * ma.v[i]) * k;
        fnav_real_t vg = (p->sg2.v[i] - p->sg.v[i] * mg.v[i]) * k;
        fnav_real_t se2;
        va = va > FNAV_R(0.0) ? va : FNAV_R(0.0);
        vg = vg > FNAV_R(0.0) ? vg : FNAV_R(0.0);
        r->accel_sd_mps2.v[i] = fnav_sqrt(va);
        r->gyro_sd_rps.v[i] = fnav_sqrt(vg);
        /* posterior of a zero-mean prior (sd s0) and the mean (se) */
        se2 = mean_se2(p, vg, i);
        r->gyro_mean_se_rps.v[i] = fnav_sqrt(se2);
        if (s02 > FNAV_R(0.0) && duration_s(p) < al->cfg.min_still_s) {
            /* a period shorter than min_still_s (the walk starts early:
             * the quietest such period, fnav_align.h): the foot's
             * rotation before its first step, or within a stance, is a
             * smooth rate that no statistic of so short a window tells
             * from a bias (a sway angle of a degree over 0.3 s is 3 deg/s),
             * so the bias is the prior's, 0 with sd s0 */
            r->gyro_bias_rps.v[i] = FNAV_R(0.0);
            r->gyro_bias_sd_rps.v[i] = al->cfg.gyro_bias_prior_sd_rps;
        } else if (s02 > FNAV_R(0.0)) {
            r->gyro_bias_rps.v[i] = r->gyro_mean_rps.v[i] * s02 / (s02 + se2);
            /* through the weight s0^2 / (s0^2 + se^2), in [0, 1]: the
             * product s0^2 se^2 underflowed to a posterior sd of 0 for a
             * prior sd of 1e-20 in float (test_align test_prior_square) */
            r->gyro_bias_sd_rps.v[i] = fnav_sqrt(se2 * (s02 / (s02 + se2)));
        } else {
            r->gyro_bias_sd_rps.v[i] = r->gyro_mean_se_rps.v[i];
        }
    }
    r->samples = p->n;
    r->duration_s = duration_s(p);
    return FNAV_OK;
}

/* A period refused for its mean |f| (FNAV_E_RANGE): said in
 * refused_f_mps2, and discarded, or the next still sample would complete on
 * it together with the real samples. */
static void refuse(fnav_align_t *al, fnav_align_period_t *p)
{
    al->refused_f_mps2 = fnav_vec3_norm(fnav_vec3_add(p->a_ref, fnav_vec3_scale(p->sa, FNAV_R(1.0) / (fnav_real_t)p->n)));
    reset_period(p);
}

/* Complete the alignment on the current period (FNAV_E_RANGE: refused). */
static fnav_status_t complete(fnav_align_t *al)
{
    fnav_status_t st = period_result(al, &al->cur, &al->result);
    if (st == FNAV_OK) {
        al->done = 1;
    } else {
        refuse(al, &al->cur);
    }
    return st;
}

static fnav_real_t mean_log_stat(const fnav_align_period_t *p)
{
    return p->sum_log_stat / (fnav_real_t)p->n;
}

/* 1 when period p is a short-period candidate quieter than the kept one. */
static int better_short(const fnav_align_t *al, const fnav_align_period_t *p)
{
    return p->n >= 2 && duration_s(p) >= al->cfg.short_still_s &&
           (!al->have_best || mean_log_stat(p) < al->best_log_stat);
}

/* The current period ended before min_still_s: keep its alignment if it is
 * long enough and quieter than the kept one, then restart. */
static void end_short_period(fnav_align_t *al)
{
    fnav_align_period_t *c = &al->cur;
    if (better_short(al, c)) {
        if (period_result(al, c, &al->result) != FNAV_OK) {
            refuse(al, c);
            return;
        }
        al->have_best = 1;
        al->best_log_stat = mean_log_stat(c);
    }
    reset_period(c);
}

static void add_sample(fnav_align_period_t *p, const fnav_sample_t *s, fnav_real_t lstat)
{
    int i;
    if (p->n >= FNAV_ALIGN_PERIOD_MAX) {
        /* a period that long has stamps that do not advance (a sensor stuck
         * on one stamp: its duration stays 0 and it never ends); its count,
         * a long of 32 bits on the Cortex-M4F, would overflow after 2^31
         * samples (test_align test_stuck_stamp_period): start again with
         * this sample */
        reset_period(p);
    }
    if (p->n == 0) {
        p->a_ref = fnav_vec3_from(s->accel_mps2);
        p->g_ref = fnav_vec3_from(s->gyro_rps);
        p->t0_ns = s->t_ns;
    }
    for (i = 0; i < 3; i++) {
        fnav_real_t da = s->accel_mps2[i] - p->a_ref.v[i];
        fnav_real_t dg = s->gyro_rps[i] - p->g_ref.v[i];
        p->sa.v[i] += da;
        p->sa2.v[i] += da * da;
        p->sg.v[i] += dg;
        p->sg2.v[i] += dg * dg;
        p->blk_cur.v[i] += dg;
    }
    p->sum_log_stat += lstat;
    p->n++;
    p->t_last_ns = s->t_ns;
    /* batch means with doubling blocks: FNAV_ALIGN_BLOCKS full blocks are
     * merged pairwise into half as many blocks of twice the length */
    if (++p->blk_fill == p->blk_len) {
        p->blk[p->nblk++] = p->blk_cur;
        p->blk_cur = fnav_vec3_zero();
        p->blk_fill = 0;
        if (p->nblk == FNAV_ALIGN_BLOCKS) {
            int j = 0;
            for (i = 0; i < FNAV_ALIGN_BLOCKS / 2; i++) {
                p->blk[i] = fnav_vec3_add(p->blk[j], p->blk[j + 1]);
                j += 2;
            }
            p->nblk = FNAV_ALIGN_BLOCKS / 2;
            p->blk_len *= 2;
        }
    }
}

/* The ratio test: 1 when a still sample's statistic left the noise floor
 * of period c (a decade above its running geometric mean by default): the
 * clean stillness ends. *lstat = log10 of the statistic (0 when unusable). */
static int left_floor(const fnav_align_t *al, const fnav_align_period_t *c, int still, fnav_real_t stat,
                      fnav_real_t *lstat)
{
    *lstat = FNAV_R(0.0);
    if (!(still && stat > FNAV_R(0.0) && fnav_isfinite(stat))) {
        return 0;
    }
    *lstat = fnav_log10(stat);
    return c->n > 0 && *lstat > mean_log_stat(c) + fnav_log10(al->cfg.still_ratio);
}

fnav_status_t fnav_align_push(fnav_align_t *al, const fnav_sample_t *s, int still, fnav_real_t stat)
{
    fnav_align_period_t *c;
    fnav_real_t lstat;
    int ratio_break;
    if (al == NULL || s == NULL) {
        return FNAV_E_ARG;
    }
    if (al->done || !(al->cfg.still_ratio > FNAV_R(1.0))) {
        return FNAV_E_STATE; /* done, or never initialised (init requires still_ratio > 1) */
    }
    c = &al->cur;
    ratio_break = left_floor(al, c, still, stat, &lstat);
    if (!still || ratio_break) {
        if (c->n >= 2 && duration_s(c) >= al->cfg.min_still_s) {
            return complete(al);
        }
        end_short_period(al);
        if (!still && al->have_best) {
            /* the foot moves and no period reached min_still_s: the
             * quietest short period is all there is before the walk */
            al->done = 1;
            return FNAV_OK;
        }
        return FNAV_AGAIN;
    }
    add_sample(c, s, lstat);
    if (duration_s(c) >= al->cfg.max_still_s) {
        return complete(al);
    }
    return FNAV_AGAIN;
}

fnav_status_t fnav_align_finish(fnav_align_t *al)
{
    if (al == NULL) {
        return FNAV_E_ARG;
    }
    if (!(al->cfg.still_ratio > FNAV_R(1.0))) {
        return FNAV_E_STATE; /* never initialised */
    }
    if (al->done) {
        return FNAV_OK;
    }
    /* the current period when long enough, else the quietest period of at
     * least short_still_s, the current one included (nothing is discarded
     * when none qualifies; a current one off gravity, FNAV_ALIGN_GRAVITY_TOL,
     * does not qualify) */
    if (((al->cur.n >= 2 && duration_s(&al->cur) >= al->cfg.min_still_s) || better_short(al, &al->cur)) &&
        complete(al) == FNAV_OK) {
        return FNAV_OK;
    }
    if (al->have_best) {
        al->done = 1;
        return FNAV_OK;
    }
    return FNAV_E_STATE;
}

void fnav_align_renew_start(fnav_align_t *al)
{
    FNAV_ASSERT(al != NULL);
    reset_period(&al->cur);
}

int fnav_align_renew(fnav_align_t *al, const fnav_sample_t *s, int still, fnav_real_t stat, fnav_real_t min_s,
                     fnav_align_result_t *out)
{
    fnav_align_period_t *c;
    fnav_real_t lstat;
    int ended, ok = 0;
    if (al == NULL || s == NULL || out == NULL) {
        return 0;
    }
    c = &al->cur;
    ended = left_floor(al, c, still, stat, &lstat);
    if (still && !ended) {
        add_sample(c, s, lstat);
        ended = duration_s(c) >= al->cfg.max_still_s;
    } else {
        ended = 1;
    }
    if (ended) {
        ok = c->n >= 2 && duration_s(c) >= min_s && period_result(al, c, out) == FNAV_OK;
        reset_period(c);
    }
    return ok;
}
