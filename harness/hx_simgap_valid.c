/* Validation of the sim-to-real gap diagnosis on withheld effects
 * (hx_simgap_valid.h, docs/simgap.md). */
#include "hx_simgap_valid.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_motion.h"
#include "hx_sim.h"
#include "hx_simgap_nav.h"

static const sgv_effect_t k_eff[] = {
    { "quant", FNAV_EFFECT_QUANT, SGV_STATIC, 0 },
    { "quant_shaped", FNAV_EFFECT_QUANT, SGV_STATIC, 0 },
    { "flicker", FNAV_EFFECT_FLICKER, SGV_STATIC, 0 },
    { "rrw", FNAV_EFFECT_RRW, SGV_STATIC, 0 },
    { "ramp", FNAV_EFFECT_RAMP, SGV_STATIC, 0 },
    { "thermal", FNAV_EFFECT_THERMAL, SGV_STATIC, 0 },
    { "vibration", FNAV_EFFECT_VIBRATION, SGV_STATIC, 0 },
    { "jumps", FNAV_EFFECT_JUMPS, SGV_STATIC, 1 },
    { "jitter", FNAV_EFFECT_JITTER, SGV_TIMING, 0 },
    { "dropout", FNAV_EFFECT_DROPOUT, SGV_TIMING, 0 },
    { "duplicate", FNAV_EFFECT_DUPLICATE, SGV_TIMING, 0 },
    { "scale", FNAV_EFFECT_SCALE, SGV_MOTION, 0 },
    { "misalign", FNAV_EFFECT_MISALIGN, SGV_MOTION, 0 },
    { "gsens", FNAV_EFFECT_GSENS, SGV_MOTION, 0 },
    { "saturation", FNAV_EFFECT_SATURATION, SGV_MOTION, 0 },
};
#define NEFF ((int)(sizeof k_eff / sizeof k_eff[0]))

static const char *const k_cls[SGV_NCLASS] = { "static", "timing", "motion" };
static const char *const k_prof[3] = { "navchip", "mtx", "shimmer" };

const sgv_effect_t *sgv_effects(int *n)
{
    *n = NEFF;
    return k_eff;
}

sgv_opts_t sgv_opts_default(void)
{
    sgv_opts_t o;
    memset(&o, 0, sizeof o);
    o.cases = 40;
    o.seed = 1u;
    o.duration_s = 3600.0;
    o.rate_hz = 200.0;
    o.walk_duration_s = 60.0;
    o.walk_rate_hz = 200.0;
    o.walks = 1;
    o.statics = 1;
    o.seeds = 16;
    o.mag_lo = 1.0;
    o.mag_hi = 10.0;
    o.only = -1;
    return o;
}

/* ------------------------------------------------------------ threshold */

/* EDF of the overlapping Allan variance for white FM, NIST SP 1065 table 5
 * (N phase points, averaging factor m): the one gen_detectable.py uses. */
static double edf_white(double N, double m)
{
    return (3.0 * (N - 1.0) / (2.0 * m) - 2.0 * (N - 2.0) / N) * 4.0 * m * m / (4.0 * m * m + 5.0);
}

double sgv_detect_threshold(const sg_effect_t *e, int magp, double N, double sigma, double tau_s, double rate_hz,
                            double duration_s)
{
    const double Z = 5.0;
    double n = floor(duration_s * rate_hz + 0.5), best = INFINITY, m;
    sg_chmodel_t base;
    sg_effect_t u = *e;
    memset(&base, 0, sizeof base);
    base.n = 2;
    base.e[0].id = FNAV_EFFECT_WHITE;
    base.e[0].p[0] = N;
    base.e[1].id = FNAV_EFFECT_AR1;
    base.e[1].p[0] = tau_s;
    base.e[1].p[1] = sigma;
    u.p[magp] = 1.0;
    /* octaves tau = m / f_s with 2 m <= n / 10 */
    for (m = 1.0; n / m >= 20.0; m *= 2.0) {
        double s = sg_effect_avar_unit(&u, rate_hz, m, 0.0, n / rate_hz), need;
        if (!(s > 0.0)) {
            continue;
        }
        need = Z * sqrt(2.0 / edf_white(n + 1.0, m)) * sg_model_avar(&base, rate_hz, m, 0.0, n / rate_hz) / s;
        if (need < best) {
            best = need;
        }
    }
    return isfinite(best) ? sqrt(best) : (double)NAN;
}

/* ------------------------------------------------------------ cases */

typedef struct {
    hx_log_t *log;
    int oom;
    size_t cap;
} sink_t;

static int sink_fn(void *ctx, const hx_sim_tick_t *tk)
{
    sink_t *s = (sink_t *)ctx;
    hx_log_t *L = s->log;
    uint32_t k;
    for (k = 0; k < tk->count; k++) {
        size_t i;
        int c;
        if (L->n == s->cap) {
            size_t cap = s->cap ? 2 * s->cap : 65536;
            int64_t *t = (int64_t *)realloc(L->t_ns, cap * sizeof *t);
            uint32_t *q;
            double(*a)[3];
            double(*g)[3];
            double *tp;
            if (t == NULL) {
                s->oom = 1;
                return 1;
            }
            L->t_ns = t;
            q = (uint32_t *)realloc(L->seq, cap * sizeof *q);
            if (q == NULL) {
                s->oom = 1;
                return 1;
            }
            L->seq = q;
            a = (double(*)[3])realloc(L->acc, cap * sizeof *a);
            if (a == NULL) {
                s->oom = 1;
                return 1;
            }
            L->acc = a;
            g = (double(*)[3])realloc(L->gyr, cap * sizeof *g);
            if (g == NULL) {
                s->oom = 1;
                return 1;
            }
            L->gyr = g;
            tp = (double *)realloc(L->temp, cap * sizeof *tp);
            if (tp == NULL) {
                s->oom = 1;
                return 1;
            }
            L->temp = tp;
            s->cap = cap;
        }
        i = L->n++;
        L->t_ns[i] = tk->meas.t_ns;
        L->seq[i] = tk->meas.seq;
        for (c = 0; c < 3; c++) {
            L->acc[i][c] = (double)tk->meas.accel_mps2[c];
            L->gyr[i][c] = (double)tk->meas.gyro_rps[c];
        }
        L->temp[i] = (tk->meas.flags & FNAV_SAMPLE_HAS_TEMP) ? (double)tk->meas.temp_c : (double)NAN;
    }
    return 0;
}

/* Simulate a log: motion script, sensor configuration, sampling. */
int sgv_simulate(const char *script, const fnav_imuerr_config_t *err_cfg, int point, hx_log_t *log, char *err,
                    size_t err_size)
{
    hx_motion_config_t mc = hx_motion_config_default();
    hx_motion_t *m = hx_motion_create(&mc, script, 0.0, err, err_size);
    hx_sim_config_t sc;
    sink_t s;
    int rc;
    if (m == NULL) {
        return -1;
    }
    memset(log, 0, sizeof *log);
    memset(&s, 0, sizeof s);
    s.log = log;
    sc.motion = m;
    sc.err = *err_cfg;
    if (point) {
        sc.err.oversample = 1u;
    }
    sc.duration_s = 0.0;
    sc.decim = HX_DECIM_FIR;
    rc = hx_sim_run(&sc, sink_fn, &s, err, err_size);
    hx_motion_free(m);
    if (rc != 0 || s.oom) {
        if (s.oom) {
            snprintf(err, err_size, "out of memory");
        }
        hx_log_free(log);
        return -1;
    }
    log->meta.format = HX_FMT_BIN;
    log->meta.rate_hz = (double)err_cfg->rate_hz;
    log->meta.rate_nominal = 1;
    log->meta.has_seq = 1;
    snprintf(log->meta.sensor, sizeof log->meta.sensor, "simulated");
    log->status = FNAV_END;
    return 0;
}

/* Profile values of a channel: white density, AR(1) sigma and time. */
static void prof_channel(const fnav_profile_t *p, int ch, double *N, double *sig, double *tau)
{
    if (ch < 3) {
        *N = (double)p->accel_noise_mps2_rthz[ch];
        *sig = (double)p->accel_bias_sigma_mps2[ch];
        *tau = (double)p->accel_tau_s[ch];
    } else {
        *N = (double)p->gyro_noise_rps_rthz[ch - 3];
        *sig = (double)p->gyro_bias_sigma_rps[ch - 3];
        *tau = (double)p->gyro_tau_s[ch - 3];
    }
}

static double urand(fnav_rng_t *r)
{
    return (double)fnav_rng_uniform(r);
}

/* Set parameter k of effect id on the channels of mask; -1 with err
 * filled when the simulator refuses the value (outside its range). */
static int setk(fnav_imuerr_config_t *c, int id, int k, uint32_t mask, double v, char *err, size_t err_size)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)id);
    if (k < 0 || info == NULL || k >= info->nparams) {
        snprintf(err, err_size, "no such parameter");
        return -1;
    }
    if (fnav_imuerr_param_set(c, (fnav_effect_id_t)id, k, mask, (fnav_real_t)v) != FNAV_OK) {
        snprintf(err, err_size, "%s.%s %g is outside the simulator's range [%g, %g]", info->name,
                 info->params[k].name, v, info->params[k].lo, info->params[k].hi);
        return -1;
    }
    return 0;
}

static int setp(fnav_imuerr_config_t *c, int id, const char *name, uint32_t mask, double v, char *err,
                size_t err_size)
{
    return setk(c, id, fnav_imuerr_param_find((fnav_effect_id_t)id, name), mask, v, err, err_size);
}

/* Draw one static/timing case: configuration and truth; the log's error
 * model is seeded with log_seed (sgv_case_seeds), recorded in cs. */
static int draw_static(const sgv_opts_t *o, int type, uint32_t log_seed, fnav_rng_t *rng, sgv_case_t *cs,
                       fnav_imuerr_config_t *cfg, char *err, size_t err_size)
{
    fnav_profile_t prof;
    const double n = o->duration_s * o->rate_hz;
    const sgv_effect_t *E = type >= 0 ? &k_eff[type] : NULL;
    int ch;
    cs->log_seed = log_seed;
    cs->profile = (int)(urand(rng) * 3.0) % 3;
    snprintf(err, err_size, "the profile cannot be set up");
    if (fnav_profile_builtin(&prof, (fnav_profile_id_t)cs->profile) != FNAV_OK) {
        return -1;
    }
    *cfg = fnav_imuerr_config_default;
    cfg->rate_hz = (fnav_real_t)o->rate_hz;
    (void)fnav_rng_u32(rng); /* was the log's seed: drawn still, so the later draws are as before */
    cfg->seed = log_seed;
    if (fnav_imuerr_config_from_profile(cfg, &prof) != FNAV_OK) {
        return -1;
    }
    cs->mult = o->mag_lo * pow(o->mag_hi / o->mag_lo, urand(rng));
    if (E == NULL) {
        cs->mask = 0u;
        cs->cls = SGV_STATIC;
        return 0;
    }
    cs->cls = E->cls;
    if (E->cls == SGV_TIMING) {
        cs->mask = FNAV_CH_ALL;
        if (E->id == FNAV_EFFECT_JITTER) {
            /* the stamps' resolution is 1 ns: draw 0.1 us .. 100 us */
            double v = 1e-7 * pow(1000.0, urand(rng));
            cs->mult = v / 1e-7;
            for (ch = 0; ch < SG_NCH; ch++) {
                cs->value[ch] = v;
            }
            if (setp(cfg, E->id, "stamp_s", FNAV_CH_ALL, v, err, err_size) != 0 ||
                setp(cfg, E->id, "sample_s", FNAV_CH_ALL, 0.0, err, err_size) != 0) {
                return -1;
            }
        } else {
            /* counts: detectable from about 10 expected events */
            double v = cs->mult * 10.0 / n;
            for (ch = 0; ch < SG_NCH; ch++) {
                cs->value[ch] = v;
            }
            if (setp(cfg, E->id, "prob", FNAV_CH_ALL, v, err, err_size) != 0) {
                return -1;
            }
        }
        snprintf(err, err_size, "%s cannot be enabled", E->name);
        return fnav_imuerr_enable(cfg, (fnav_effect_id_t)E->id, FNAV_CH_ALL) == FNAV_OK ? 0 : -1;
    }
    /* channels: one, or a sensor's three */
    if (urand(rng) < 0.5) {
        cs->mask = 1u << ((int)(urand(rng) * 6.0) % 6);
    } else {
        cs->mask = urand(rng) < 0.5 ? FNAV_CH_ACC : FNAV_CH_GYRO;
    }
    {
        sg_effect_t e;
        int k;
        const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)E->id);
        double sign = urand(rng) < 0.5 ? -1.0 : 1.0;
        double vib_f = (0.05 + 0.35 * urand(rng)) * o->rate_hz;
        double th_tau = o->duration_s / 6.0;
        double jump_rate = 6.0 / o->duration_s;
        double quant_u = urand(rng);
        memset(&e, 0, sizeof e);
        e.id = E->id;
        for (k = 0; k < info->nparams && k < SG_MAX_PAR; k++) {
            e.p[k] = (double)fnav_imuerr_param_get(&fnav_imuerr_config_default, (fnav_effect_id_t)E->id, k, 0);
        }
        if (E->id == FNAV_EFFECT_QUANT) {
            e.p[1] = strcmp(E->name, "quant_shaped") == 0 ? 1.0 : 0.0;
        } else if (E->id == FNAV_EFFECT_VIBRATION) {
            e.p[1] = vib_f;
            e.p[2] = 2.0 * M_PI * urand(rng);
        } else if (E->id == FNAV_EFFECT_THERMAL) {
            e.p[2] = th_tau; /* warm-up inside the log (600 s for one hour) */
        } else if (E->id == FNAV_EFFECT_JUMPS) {
            e.p[0] = jump_rate; /* one step per 10 min for one hour */
        }
        for (ch = 0; ch < SG_NCH; ch++) {
            double N, sig, tau, thr, v;
            if (!((cs->mask >> ch) & 1u)) {
                continue;
            }
            prof_channel(&prof, ch, &N, &sig, &tau);
            if (E->id == FNAV_EFFECT_QUANT && e.p[1] == 0.0) {
                /* plain rounding: the lattice shows at any step above the
                 * float storage (10 ulp); draw from 30 ulp of the largest
                 * value to 3 sample standard deviations */
                double big = ch < 3 ? 12.0 : 0.1, lo = 30.0 * ldexp(1.0, (int)floor(log2(big)) - 23);
                double hi = 3.0 * N * sqrt(o->rate_hz);
                thr = lo;
                v = lo * pow(hi / lo, quant_u);
                cs->mult = v / lo;
            } else {
                thr = sgv_detect_threshold(&e, E->magp, N, sig, tau, o->rate_hz, o->duration_s);
                v = thr * cs->mult;
            }
            if (!(thr > 0.0)) {
                snprintf(err, err_size, "%s has no detectable magnitude on %s in %g s at %g Hz", E->name,
                         sg_channel_name(ch), o->duration_s, o->rate_hz);
                return -1;
            }
            if (E->id == FNAV_EFFECT_RAMP || E->id == FNAV_EFFECT_THERMAL) {
                v *= sign;
            }
            cs->value[ch] = v;
            for (k = 0; k < info->nparams && k < SG_MAX_PAR; k++) {
                double pv = (k == E->magp) ? v : e.p[k];
                if (setk(cfg, E->id, k, 1u << ch, pv, err, err_size) != 0) {
                    return -1;
                }
            }
        }
        snprintf(err, err_size, "%s cannot be enabled", E->name);
        return fnav_imuerr_enable(cfg, (fnav_effect_id_t)E->id, cs->mask) == FNAV_OK ? 0 : -1;
    }
}

/* ------------------------------------------------------------ scoring */

static int table_index(int id, int shaped)
{
    int i;
    if (id == FNAV_EFFECT_QUANT) {
        return shaped ? 1 : 0;
    }
    for (i = 0; i < NEFF; i++) {
        if (k_eff[i].id == id) {
            return i;
        }
    }
    return -2;
}


/* Top-ranked effect of a result: the selected effect with the largest
 * held-out gap reduction summed over channels; timing effects by their z^2. */
static void score(const sg_result_t *r, sgv_case_t *cs)
{
    double sc[32];
    int ch, i, best = -1;
    memset(sc, 0, sizeof sc);
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_chres_t *c = &r->ch[ch];
        for (i = 0; i < c->nsteps; i++) {
            const sg_step_t *st = &c->step[i];
            if (st->selected >= 0) {
                const sg_cand_t *cd = &st->cand[st->selected];
                int ti = table_index(cd->id, cd->id == FNAV_EFFECT_QUANT && cd->eff.p[1] != 0.0);
                if (ti >= 0) {
                    double d = cd->dG_rank; /* both folds' held-out reductions */
                    sc[ti] += d > 0.0 ? d : 1e-9;
                }
            }
        }
        if (c->active && c->gap) {
            cs->flagged |= 1u << ch;
        }
    }
    if (r->tim.significant) {
        static const int tid[SG_TIM_NKIND] = { FNAV_EFFECT_DUPLICATE, FNAV_EFFECT_DROPOUT, FNAV_EFFECT_JITTER };
        cs->timing_flagged = 1;
        for (i = 0; i < SG_TIM_NKIND; i++) {
            if (r->tim.sel[i]) {
                double z = r->tim.z[SG_FULL][i];
                sc[table_index(tid[i], 0)] += z * z < SG_ZCAP * SG_ZCAP ? z * z : SG_ZCAP * SG_ZCAP;
            }
        }
    }
    if (r->nav != NULL) {
        sg_nav_scores((const sg_nav_t *)r->nav, sc, NEFF, &cs->flagged);
    }
    for (i = 0; i < NEFF; i++) {
        if (sc[i] > 0.0 && (best < 0 || sc[i] > sc[best])) {
            best = i;
        }
    }
    /* a gap claimed: "too-short" is no answer, neither a detection nor,
     * on a control, a false alarm, nor an effect or a place (a 20 s walk at
     * 50 Hz, too short, was scored a top-1 saturation located exactly with
     * its parameter within 25 %: seed 1 case 7) */
    cs->detected = strcmp(r->verdict, "none") != 0 && strcmp(r->verdict, "too-short") != 0;
    if (strcmp(r->verdict, "too-short") == 0) {
        best = -1;
        cs->flagged = 0u;
        cs->timing_flagged = 0;
    }
    cs->pred = best;
    snprintf(cs->verdict, sizeof cs->verdict, "%s", r->verdict);
    /* location */
    if (cs->truth >= 0 && k_eff[cs->truth].cls == SGV_TIMING) {
        cs->jaccard = (cs->timing_flagged && cs->flagged == 0u) ? 1.0 : 0.0;
    } else if (cs->truth >= 0) {
        uint32_t in = cs->flagged & cs->mask, un = cs->flagged | cs->mask;
        int a = 0, b = 0;
        for (ch = 0; ch < SG_NCH; ch++) {
            a += (int)((in >> ch) & 1u);
            b += (int)((un >> ch) & 1u);
        }
        cs->jaccard = b > 0 ? (double)a / (double)b : 0.0;
    }
    /* parameter error and shrink on the right effect */
    cs->perr = cs->shrink = (double)NAN;
    if (cs->truth >= 0 && cs->pred >= 0 && k_eff[cs->pred].id == k_eff[cs->truth].id) {
        const sgv_effect_t *E = &k_eff[cs->truth];
        double pe[SG_NCH], sh[SG_NCH];
        int np = 0, ns = 0;
        if (E->cls == SGV_TIMING) {
            double est = E->id == FNAV_EFFECT_JITTER ? r->tim.stamp_s
                                                     : (E->id == FNAV_EFFECT_DROPOUT ? r->tim.drop_prob : r->tim.dup_prob);
            int d = E->id == FNAV_EFFECT_JITTER ? SG_TIM_JITTER : (E->id == FNAV_EFFECT_DROPOUT ? SG_TIM_DROP : SG_TIM_DUP);
            double zb = r->tim.z[SG_HOLD][d], za = r->tim.z_after[d];
            pe[np++] = fabs(est - cs->value[0]) / fabs(cs->value[0]);
            sh[ns++] = zb * zb > 1.0 ? (zb * zb - za * za) / (zb * zb - 1.0) : (double)NAN;
        } else if (E->cls == SGV_STATIC) {
            for (ch = 0; ch < SG_NCH; ch++) {
                const sg_chres_t *c = &r->ch[ch];
                int k = sg_model_find(&c->final, E->id);
                if (!((cs->mask >> ch) & 1u) || k < 0) {
                    continue;
                }
                pe[np++] = fabs(fabs(c->final.e[k].p[E->magp]) - fabs(cs->value[ch])) / fabs(cs->value[ch]);
                for (i = 0; i < c->nsel; i++) {
                    if (c->sel_id[i] == E->id) {
                        sh[ns++] = c->sel_expl[i];
                    }
                }
            }
        } else if (r->nav != NULL) {
            sg_nav_truth_errors((const sg_nav_t *)r->nav, E->id, cs->mask, cs->value, pe, &np, sh, &ns);
        }
        cs->perr = hx_median(pe, np);
        {
            int j, m = 0;
            for (j = 0; j < ns; j++) {
                if (sh[j] == sh[j]) {
                    sh[m++] = sh[j];
                }
            }
            cs->shrink = hx_median(sh, m);
        }
    }
}

/* ------------------------------------------------------------ run */

/* Is name in the comma-separated list (NULL: everything)? */
static int listed(const char *list, const char *name)
{
    size_t n = strlen(name);
    const char *p = list;
    if (list == NULL) {
        return 1;
    }
    while (p != NULL && *p != '\0') {
        if (strncmp(p, name, n) == 0 && (p[n] == ',' || p[n] == '\0')) {
            return 1;
        }
        p = strchr(p, ',');
        if (p != NULL) {
            p++;
        }
    }
    return 0;
}

/* The case kinds drawn in turn: -1 a static control, -100 a walk control,
 * else an index into k_eff. Returns their number (types holds 2 + NEFF). */
static int case_types(const sgv_opts_t *o, int *types)
{
    int ntypes = 0, i;
    if (o->statics) {
        if (listed(o->effects, "control")) {
            types[ntypes++] = -1; /* static control */
        }
        for (i = 0; i < NEFF; i++) {
            if (k_eff[i].cls != SGV_MOTION && listed(o->effects, k_eff[i].name)) {
                types[ntypes++] = i;
            }
        }
    }
    if (o->walks) {
        if (listed(o->effects, "control")) {
            types[ntypes++] = -100; /* walk control */
        }
        for (i = 0; i < NEFF; i++) {
            if (k_eff[i].cls == SGV_MOTION && listed(o->effects, k_eff[i].name)) {
                types[ntypes++] = i;
            }
        }
    }
    return ntypes;
}

/* The kind of case i: an entry of types (the kinds in turn from an offset
 * the seed draws, so a run of fewer cases is a prefix of a longer one). */
static int case_type(const sgv_opts_t *o, const int *types, int ntypes, int i)
{
    fnav_rng_t r0;
    int off;
    fnav_rng_seed(&r0, o->seed, 0x5a5au);
    off = (int)(fnav_rng_u32(&r0) % (uint32_t)ntypes);
    return types[(i + off) % ntypes];
}

void sgv_case_seeds(const sgv_opts_t *o, int i, uint32_t *log_seed, uint32_t *diag_seed)
{
    /* unsigned: wraps past 4294967295 */
    const uint32_t d = o->seed + SGV_SEED_STRIDE * (uint32_t)i;
    if (diag_seed != NULL) {
        *diag_seed = d;
    }
    if (log_seed != NULL) {
        *log_seed = d + SG_SEED_SPAN;
    }
}

int sgv_check_opts(const sgv_opts_t *o, char *err, size_t err_size)
{
    int types[2 + NEFF], i, ntypes;
    if (o->effects != NULL) {
        const char *p = o->effects;
        for (;;) {
            const char *e = strchr(p, ',');
            const size_t len = e != NULL ? (size_t)(e - p) : strlen(p);
            int known = len == strlen("control") && strncmp(p, "control", len) == 0;
            for (i = 0; i < NEFF && !known; i++) {
                known = len == strlen(k_eff[i].name) && strncmp(p, k_eff[i].name, len) == 0;
            }
            if (!known) {
                size_t o2;
                if (len == 0) {
                    o2 = (size_t)snprintf(err, err_size, "--effects: an empty name in '%s'; known: control", o->effects);
                } else {
                    o2 = (size_t)snprintf(err, err_size, "--effects: unknown effect '%.*s'; known: control",
                                          len > 64 ? 64 : (int)len, p);
                }
                for (i = 0; i < NEFF && o2 < err_size; i++) {
                    o2 += (size_t)snprintf(err + o2, err_size - o2, ", %s", k_eff[i].name);
                }
                return -1;
            }
            if (e == NULL) {
                break;
            }
            p = e + 1;
        }
    }
    if ((ntypes = case_types(o, types)) == 0) {
        snprintf(err, err_size, "--effects %s draws no case%s (%s)", o->effects != NULL ? o->effects : "",
                 !o->walks ? " with --static-only" : (!o->statics ? " with --walk-only" : ""),
                 !o->walks ? "scale, misalign, gsens and saturation are walk effects"
                           : "the static and timing effects and their control need static cases");
        return -1;
    }
    /* case_types() lists the static kinds first */
    if ((types[0] == -1 || (types[0] >= 0 && k_eff[types[0]].cls != SGV_MOTION)) &&
        o->duration_s * o->rate_hz > SGV_MAX_STATIC_SAMPLES) {
        snprintf(err, err_size,
                 "--duration %g x --rate %g is %.0f samples per static case; at most %.0f (e.g. --duration %.0f at "
                 "this rate)",
                 o->duration_s, o->rate_hz, o->duration_s * o->rate_hz, SGV_MAX_STATIC_SAMPLES,
                 floor(SGV_MAX_STATIC_SAMPLES / o->rate_hz));
        return -1;
    }
    if (o->only >= o->cases) {
        snprintf(err, err_size, "--only %d must be below --cases %d (cases are numbered from 0)", o->only, o->cases);
        return -1;
    }
    /* the static cases' draws, dry (no simulation: cheap), so that a
     * magnitude the simulator refuses (--mag-range against a short log:
     * a dropout probability above 1) is a usage error before the run, not
     * the end of a run whose cases were lost; the walk cases' draws
     * simulate the walk and are checked as they come */
    for (i = 0; i < o->cases; i++) {
        int type = case_type(o, types, ntypes, i);
        fnav_rng_t rng;
        sgv_case_t cs;
        fnav_imuerr_config_t cfg;
        char e2[256];
        uint32_t lseed;
        if ((o->only >= 0 && i != o->only) || type == -100 || (type >= 0 && k_eff[type].cls == SGV_MOTION)) {
            continue;
        }
        memset(&cs, 0, sizeof cs);
        sgv_case_seeds(o, i, &lseed, NULL);
        fnav_rng_seed(&rng, o->seed, 0x10000u + (uint32_t)i);
        if (draw_static(o, type, lseed, &rng, &cs, &cfg, e2, sizeof e2) != 0) {
            snprintf(err, err_size, "case %d: %s at %.3g x its detectable threshold: %s (lower --mag-range, or "
                     "lengthen --duration)", i, type >= 0 ? k_eff[type].name : "control", cs.mult, e2);
            return -1;
        }
    }
    return 0;
}

/* A figure in `width` columns with `prec` decimals, or "-" where it is
 * undefined (NaN). */
static void fig(char *buf, size_t size, int width, int prec, double v)
{
    if (v == v) {
        snprintf(buf, size, "%*.*f", width, prec, v);
    } else {
        snprintf(buf, size, "%*s", width, "-");
    }
}

int sgv_run(const sgv_opts_t *o, sgv_case_t *cases, FILE *f, char *err, size_t err_size)
{
    int types[2 + NEFF], ntypes, i, told_short[2]; /* a too-short case of the static, walk domain explained */
    ntypes = case_types(o, types);
    if (ntypes == 0) {
        snprintf(err, err_size, "no case kinds selected");
        return -1;
    }
    for (i = 0; i < o->cases; i++) {
        cases[i].truth = SGV_NOT_RUN; /* until scored */
    }
    told_short[0] = told_short[1] = 0;
    for (i = 0; i < o->cases; i++) {
        sgv_case_t *cs = &cases[i];
        int type = case_type(o, types, ntypes, i);
        fnav_rng_t rng;
        fnav_imuerr_config_t cfg;
        hx_log_t log;
        sg_result_t *res;
        sg_opts_t so = sg_opts_default();
        char script[1024], e2[256];
        uint32_t lseed, dseed;
        double t0 = hx_now_s();
        if (o->only >= 0 && i != o->only) {
            continue;
        }
        if (o->stop != NULL && *o->stop) {
            return 1;
        }
        memset(cs, 0, sizeof *cs);
        cs->pred = -1;
        sgv_case_seeds(o, i, &lseed, &dseed);
        fnav_rng_seed(&rng, o->seed, 0x10000u + (uint32_t)i);
        cs->walk = (type == -100) || (type >= 0 && k_eff[type].cls == SGV_MOTION);
        cs->truth = type >= 0 ? type : -1;
        if (cs->walk) {
            if (sg_nav_draw_case(o, type >= 0 ? type : -1, lseed, &rng, cs, &cfg, script, sizeof script, e2,
                                 sizeof e2) != 0) {
                snprintf(err, err_size, "case %d: cannot draw a walk case: %s", i, e2);
                cs->truth = SGV_NOT_RUN;
                return -1;
            }
        } else {
            if (draw_static(o, type, lseed, &rng, cs, &cfg, e2, sizeof e2) != 0) {
                snprintf(err, err_size, "case %d: cannot draw a static case: %s", i, e2);
                cs->truth = SGV_NOT_RUN;
                return -1;
            }
            snprintf(script, sizeof script, "stand:%.0f", o->duration_s);
        }
        if (sgv_simulate(script, &cfg, !cs->walk, &log, e2, sizeof e2) != 0) {
            snprintf(err, err_size, "case %d: simulation failed: %s", i, e2);
            cs->truth = SGV_NOT_RUN;
            return -1;
        }
        res = (sg_result_t *)calloc(1, sizeof *res);
        if (res == NULL) {
            hx_log_free(&log);
            snprintf(err, err_size, "case %d: out of memory", i);
            cs->truth = SGV_NOT_RUN;
            return -1;
        }
        so.quiet = 1;
        so.seeds = o->seeds;
        so.seed = dseed; /* no case's twins or bootstrap meet another's, nor any log's */
        so.domain = cs->walk ? 2 : 1;
        so.cmd = "simgap-validate"; /* its remedy is --walk-duration, said below: not simgap's --fit-frac */
        if (sg_diagnose(&log, "case", &so, res, e2, sizeof e2) != 0) {
            snprintf(err, err_size, "case %d: diagnosis failed: %s", i, e2);
            cs->truth = SGV_NOT_RUN;
            hx_log_free(&log);
            free(res);
            return -1;
        }
        if (o->verbose && f != NULL) {
            sg_print_summary(f, res);
        }
        score(res, cs);
        cs->elapsed_s = hx_now_s() - t0;
        if (f != NULL) {
            char mk[32], mu[24], lo[24], pe[24], sh[24];
            int ch, m = 0;
            for (ch = 0; ch < SG_NCH; ch++) {
                if ((cs->mask >> ch) & 1u) {
                    m += snprintf(mk + m, sizeof mk - (size_t)m, "%s%s", m ? "+" : "", sg_channel_name(ch));
                }
            }
            if (m == 0) {
                snprintf(mk, sizeof mk, "-");
            }
            /* '-' where a figure is undefined, as the Markdown: no parameter
             * error or shrink without the right effect (it printed nan), and
             * a control has no effect, so no multiple of a threshold and no
             * place (it printed the unused draw, x1.83, and loc 0.00) */
            fig(mu, sizeof mu, 0, 2, cs->truth >= 0 ? cs->mult : (double)NAN);
            fig(lo, sizeof lo, 0, 2, cs->truth >= 0 ? cs->jaccard : (double)NAN);
            fig(pe, sizeof pe, 6, 2, cs->perr);
            fig(sh, sizeof sh, 6, 2, cs->shrink);
            fprintf(f, "case %3d  %-6s %-8s %-13s on %-9s x%-6s -> %-13s %-17s loc %-4s perr %s shrink %s (%.1f s)\n",
                    i, cs->walk ? "walk" : "static", k_prof[cs->profile % 3],
                    cs->truth >= 0 ? k_eff[cs->truth].name : "control", mk, mu,
                    cs->pred >= 0 ? k_eff[cs->pred].name : (cs->pred == -1 ? "none" : "other"), cs->verdict, lo, pe,
                    sh, cs->elapsed_s);
            /* why, at the first too-short case of each domain, not only in
             * the summary at the end of a run of them */
            if (strcmp(cs->verdict, "too-short") == 0 && !told_short[cs->walk ? 1 : 0]) {
                told_short[cs->walk ? 1 : 0] = 1;
                fprintf(f, "          too short for an answer: %s (a longer %s gives one)\n", res->why,
                        cs->walk ? "--walk-duration" : "--duration");
            }
            fflush(f);
        }
        hx_log_free(&log);
        sg_result_free(res);
        free(res);
    }
    return 0;
}

/* ------------------------------------------------------------ report */

/* The width of a confusion-matrix column: its name's, at least 3. */
static int conf_width(const char *name)
{
    int w = (int)strlen(name);
    return w > 3 ? w : 3;
}

/* Wilson score interval of k of n (95 %). */
static void wilson(int k, int n, double *lo, double *hi)
{
    const double z = 1.959964;
    double p, d, c, h;
    if (n == 0) {
        *lo = *hi = (double)NAN;
        return;
    }
    p = (double)k / (double)n;
    d = 1.0 + z * z / (double)n;
    c = (p + z * z / (2.0 * (double)n)) / d;
    h = z * sqrt(p * (1.0 - p) / (double)n + z * z / (4.0 * (double)n * (double)n)) / d;
    *lo = c - h;
    *hi = c + h;
}

typedef struct {
    int n, det, top1, loc_exact, pe_n, pe_ok, sh_n, sh_ok;
    double jac;
    double *pe_med_v, *sh_med_v; /* room for every case (NULL: no medians); with a fixed 1024
                                  * each, a larger class's medians would be its first cases' */
    int npe, nsh;
} agg_t;

static void agg_add(agg_t *a, const sgv_case_t *c)
{
    a->n++;
    a->det += c->detected;
    a->top1 += (c->truth >= 0 && c->pred >= 0 && k_eff[c->pred].id == k_eff[c->truth].id);
    a->jac += c->jaccard;
    a->loc_exact += c->jaccard >= 0.999;
    if (c->perr == c->perr) {
        a->pe_n++;
        a->pe_ok += c->perr <= 0.25;
        if (a->pe_med_v != NULL) {
            a->pe_med_v[a->npe++] = c->perr;
        }
    }
    if (c->shrink == c->shrink) {
        a->sh_n++;
        a->sh_ok += c->shrink >= 0.70;
        if (a->sh_med_v != NULL) {
            a->sh_med_v[a->nsh++] = c->shrink;
        }
    }
}

void sgv_report(FILE *f, const sgv_opts_t *o, const sgv_case_t *cases, int n, int md, double elapsed_s)
{
    agg_t *cls = (agg_t *)calloc(SGV_NCLASS, sizeof *cls), *bins = (agg_t *)calloc(3 * SGV_NCLASS, sizeof *bins);
    double *medv = (double *)malloc((size_t)(n > 0 ? n : 1) * 2 * SGV_NCLASS * sizeof *medv);
    int i, j, k, nctrl = 0, fa = 0, nctrl_w = 0, fa_w = 0, short_s = 0, short_w = 0, nrun = 0, incomplete;
    int short_cls[SGV_NCLASS] = { 0, 0, 0 }, nshort = 0; /* effect cases answered too-short, per class */
    int conf[NEFF + 1][NEFF + 2];
    double lo, hi;
    const char *sep = md ? " | " : "  ";
    if (cls == NULL || bins == NULL || medv == NULL) {
        free(cls);
        free(bins);
        free(medv);
        return;
    }
    for (k = 0; k < SGV_NCLASS; k++) {
        cls[k].pe_med_v = medv + (size_t)(2 * k) * (size_t)(n > 0 ? n : 1);
        cls[k].sh_med_v = medv + (size_t)(2 * k + 1) * (size_t)(n > 0 ? n : 1);
    }
    memset(conf, 0, sizeof conf);
    for (i = 0; i < n; i++) {
        const sgv_case_t *c = &cases[i];
        int row = c->truth >= 0 ? c->truth + 1 : 0, col = c->pred >= 0 ? c->pred + 1 : (c->pred == -1 ? 0 : NEFF + 1);
        if (c->truth == SGV_NOT_RUN) {
            continue; /* not run (--only) */
        }
        conf[row][col]++;
        nrun++;
        if (c->truth < 0 && strcmp(c->verdict, "too-short") == 0) {
            /* no answer: not in the false-alarm rate, counted apart */
            short_w += c->walk;
            short_s += !c->walk;
            continue;
        }
        if (c->truth < 0) {
            if (c->walk) {
                nctrl_w++;
                fa_w += c->detected;
            } else {
                nctrl++;
                fa += c->detected;
            }
            continue;
        }
        agg_add(&cls[k_eff[c->truth].cls], c);
        if (strcmp(c->verdict, "too-short") == 0) {
            short_cls[k_eff[c->truth].cls]++;
            nshort++;
        }
        {
            int b = c->mult < 2.0 ? 0 : (c->mult < 4.0 ? 1 : 2);
            agg_add(&bins[3 * k_eff[c->truth].cls + b], c);
        }
    }
    /* a stop or a failed case leaves cases unrun that --only did not skip */
    incomplete = o->only >= 0 ? nrun == 0 : nrun < n;
    if (md) {
        fprintf(f, "# Sim-to-real gap diagnosis: validation on withheld effects\n\n"
                   "Generated by `make simgap-validation` (do not edit by hand); the method, the targets' reading and "
                   "the discussion of this run are in docs/simgap.md.\n\n");
        char onl[32] = "";
        if (o->only >= 0) {
            snprintf(onl, sizeof onl, " --only %d", o->only);
        }
        fprintf(f, "Run: `bin/harness simgap-validate --cases %d --seed %u --duration %g --rate %g --walk-duration %g --walk-rate %g --seeds %d --mag-range %g,%g%s%s%s%s%s`; "
                   "%d case%s in %.0f s (%.1f s per case, one core of the shared machine)%s.\n\n",
                o->cases, o->seed, o->duration_s, o->rate_hz, o->walk_duration_s, o->walk_rate_hz, o->seeds, o->mag_lo,
                o->mag_hi, o->walks ? "" : " --static-only", o->statics ? "" : " --walk-only",
                o->effects != NULL ? " --effects " : "", o->effects != NULL ? o->effects : "", onl, nrun,
                nrun == 1 ? "" : "s", elapsed_s, nrun > 0 ? elapsed_s / (double)nrun : 0.0,
                incomplete ? "; **incomplete**: the run stopped early, and only the cases it ran are scored" : "");
        fprintf(f, "| class | cases | detected | top-1 (95 %% interval) | location exact / mean Jaccard | parameter within 25 %% "
                   "(median error) | held-out shrink >= 70 %% (median) |\n| --- | --- | --- | --- | --- | --- | --- |\n");
    } else {
        char onl[48] = "";
        if (o->only >= 0) {
            snprintf(onl, sizeof onl, "case %d of %d; ", o->only, o->cases);
        }
        fprintf(f, "\nsimgap-validate: %d case%s (%s%sseed %u): static logs of %g s at %g Hz, walks of %g s at %g Hz; magnitudes "
                   "%g-%g x the documented detectable threshold (log-uniform); %.0f s (%.1f s per case)\n",
                nrun, nrun == 1 ? "" : "s", incomplete ? "INCOMPLETE, the run stopped early; " : "", onl, o->seed,
                o->duration_s, o->rate_hz, o->walk_duration_s, o->walk_rate_hz, o->mag_lo, o->mag_hi, elapsed_s,
                nrun > 0 ? elapsed_s / (double)nrun : 0.0);
        fprintf(f, "class    cases  detected  top-1 (95 %% interval)        location exact/Jaccard  param <= 25 %% (median)   "
                   "shrink >= 70 %% (median)\n");
    }
    for (k = 0; k < SGV_NCLASS; k++) {
        agg_t *a = &cls[k];
        if (a->n == 0) {
            continue;
        }
        char pe_med[16] = "-", sh_med[16] = "-"; /* no case to take a median of: '-' (it printed nan) */
        wilson(a->top1, a->n, &lo, &hi);
        if (a->npe > 0) {
            snprintf(pe_med, sizeof pe_med, "%.2f", hx_median(a->pe_med_v, a->npe));
        }
        if (a->nsh > 0) {
            snprintf(sh_med, sizeof sh_med, "%.2f", hx_median(a->sh_med_v, a->nsh));
        }
        fprintf(f, "%s%-7s%s%5d%s%4d/%-4d%s%3d/%-3d = %5.1f %% (%4.1f..%5.1f %%)%s%3d/%-3d / %.2f%s%3d/%-3d (%s)%s%3d/%-3d (%s)%s\n",
                md ? "| " : "", k_cls[k], sep, a->n, sep, a->det, a->n, sep, a->top1, a->n, 100.0 * a->top1 / a->n,
                100.0 * lo, 100.0 * hi, sep, a->loc_exact, a->n, a->jac / a->n, sep, a->pe_ok, a->pe_n, pe_med, sep,
                a->sh_ok, a->sh_n, sh_med, md ? " |" : "");
    }
    if (nshort > 0) {
        /* a class's 0/8 with every case too short says why in the summary */
        fprintf(f, "%s", md ? "\nToo short for an answer: " : "too short for an answer: ");
        for (k = 0, j = 0; k < SGV_NCLASS; k++) {
            if (short_cls[k] > 0) {
                fprintf(f, "%s%s %d of %d", j++ ? ", " : "", k_cls[k], short_cls[k], cls[k].n);
            }
        }
        fprintf(f, " (scored as misses: no top-1, location or parameter; docs/simgap.md, \"Too short\")%s\n",
                md ? "." : "");
    }
    if (md) {
        fprintf(f, "\nControls (no effect): ");
    } else {
        fprintf(f, "controls: ");
    }
    if (nctrl + short_s > 0) {
        if (nctrl > 0) {
            wilson(fa, nctrl, &lo, &hi);
            fprintf(f, "static %d/%d false alarms (%.1f %%, 95 %%: %.1f..%.1f %%)", fa, nctrl, 100.0 * fa / nctrl,
                    100.0 * lo, 100.0 * hi);
        } else {
            fprintf(f, "static 0/0 false alarms");
        }
        if (short_s > 0) {
            fprintf(f, " (and %d too short for an answer, not counted)", short_s);
        }
    }
    if (nctrl_w + short_w > 0) {
        fprintf(f, "%s", nctrl + short_s > 0 ? "; " : "");
        if (nctrl_w > 0) {
            wilson(fa_w, nctrl_w, &lo, &hi);
            fprintf(f, "walk %d/%d false alarms (%.1f %%, 95 %%: %.1f..%.1f %%)", fa_w, nctrl_w,
                    100.0 * fa_w / nctrl_w, 100.0 * lo, 100.0 * hi);
        } else {
            fprintf(f, "walk 0/0 false alarms");
        }
        if (short_w > 0) {
            fprintf(f, " (and %d too short for an answer, not counted)", short_w);
        }
    }
    if (nctrl + short_s + nctrl_w + short_w == 0) {
        fprintf(f, "none drawn");
    }
    fprintf(f, "%s\n", md ? ".\n" : "");
    /* by magnitude */
    if (md) {
        /* the last column is open: quant's and jitter's multiples are not
         * drawn from --mag-range (hundreds of times; it said 4-10x) */
        fprintf(f, "Top-1 by magnitude (multiple of the detectable threshold; quant: of 30 ulp, jitter: of 0.1 us):\n\n"
                   "| class | 1-2x | 2-4x | >= 4x |\n| --- | --- | --- | --- |\n");
    } else {
        /* the counts under their column's name */
        fprintf(f, "top-1 by magnitude (multiple of the detectable threshold; quant: of 30 ulp, jitter: of 0.1 us):\n"
                   "  %-8s  %7s  %7s  %7s\n", "", "1-2x", "2-4x", ">= 4x");
    }
    for (k = 0; k < SGV_NCLASS; k++) {
        if (cls[k].n == 0) {
            continue;
        }
        fprintf(f, "%s%-8s", md ? "| " : "  ", k_cls[k]);
        for (j = 0; j < 3; j++) {
            agg_t *a = &bins[3 * k + j];
            if (md) {
                fprintf(f, "%s%3d/%-3d", sep, a->top1, a->n);
            } else {
                char kn[24];
                snprintf(kn, sizeof kn, "%d/%d", a->top1, a->n);
                fprintf(f, "%s%7s", sep, kn);
            }
        }
        fprintf(f, "%s\n", md ? " |" : "");
    }
    /* confusion matrix */
    if (md) {
        fprintf(f, "\nConfusion matrix (rows: the withheld effect; columns: the diagnosis's top-ranked effect):\n\n| truth \\ answer | none");
        for (j = 0; j < NEFF; j++) {
            fprintf(f, " | %s", k_eff[j].name);
        }
        fprintf(f, " | other |\n| ---");
        for (j = 0; j < NEFF + 2; j++) {
            fprintf(f, " | ---");
        }
        fprintf(f, " |\n");
    } else {
        /* each count under its column's name, right-aligned to it (not the
         * names on the title line, the counts 4 characters apart) */
        fprintf(f, "confusion (rows: the withheld effect; columns: the diagnosis's top-ranked effect):\n  %-13s %4s",
                "", "none");
        for (j = 0; j < NEFF; j++) {
            fprintf(f, " %*s", conf_width(k_eff[j].name), k_eff[j].name);
        }
        fprintf(f, " %5s\n", "other");
    }
    for (i = 0; i <= NEFF; i++) {
        int tot = 0;
        for (j = 0; j < NEFF + 2; j++) {
            tot += conf[i][j];
        }
        if (tot == 0) {
            continue;
        }
        fprintf(f, "%s%-13s", md ? "| " : "  ", i == 0 ? "control" : k_eff[i - 1].name);
        for (j = 0; j < NEFF + 2; j++) {
            if (md) {
                fprintf(f, " | %s", conf[i][j] ? "" : "");
                if (conf[i][j]) {
                    fprintf(f, "%d", conf[i][j]);
                }
            } else {
                fprintf(f, " %*d", j == 0 ? 4 : (j == NEFF + 1 ? 5 : conf_width(k_eff[j - 1].name)), conf[i][j]);
            }
        }
        fprintf(f, "%s\n", md ? " |" : "");
    }
    /* targets */
    {
        agg_t *s = &cls[SGV_STATIC], *m = &cls[SGV_MOTION];
        int allpe = 0, allpe_ok = 0, allsh = 0, allsh_ok = 0;
        for (k = 0; k < SGV_NCLASS; k++) {
            allpe += cls[k].pe_n;
            allpe_ok += cls[k].pe_ok;
            allsh += cls[k].sh_n;
            allsh_ok += cls[k].sh_ok;
        }
        fprintf(f, "%s", md ? "\nTargets (issue 6):\n\n| target | measured | met |\n| --- | --- | --- |\n" : "targets:\n");
        if (s->n > 0) {
            fprintf(f, "%s>= 90 %% top-1 on static-domain effects%s%.1f %% (%d/%d)%s%s%s\n", md ? "| " : "  ", sep,
                    100.0 * s->top1 / s->n, s->top1, s->n, sep, 10 * s->top1 >= 9 * s->n ? "yes" : "no", md ? " |" : "");
        }
        if (cls[SGV_TIMING].n > 0) {
            const agg_t *t = &cls[SGV_TIMING];
            fprintf(f, "%s>= 90 %% top-1 on timing effects (static logs)%s%.1f %% (%d/%d)%s%s%s\n", md ? "| " : "  ", sep,
                    100.0 * t->top1 / t->n, t->top1, t->n, sep, 10 * t->top1 >= 9 * t->n ? "yes" : "no", md ? " |" : "");
        }
        if (m->n > 0) {
            fprintf(f, "%s>= 80 %% top-1 on motion-domain effects%s%.1f %% (%d/%d)%s%s%s\n", md ? "| " : "  ", sep,
                    100.0 * m->top1 / m->n, m->top1, m->n, sep, 10 * m->top1 >= 8 * m->n ? "yes" : "no", md ? " |" : "");
        }
        if (nctrl + nctrl_w > 0) {
            fprintf(f, "%s<= 10 %% false alarms on controls%s%.1f %% (%d/%d)%s%s%s\n", md ? "| " : "  ", sep,
                    100.0 * (fa + fa_w) / (nctrl + nctrl_w), fa + fa_w, nctrl + nctrl_w, sep,
                    10 * (fa + fa_w) <= (nctrl + nctrl_w) ? "yes" : "no", md ? " |" : "");
        }
        if (allpe > 0) {
            fprintf(f, "%sparameters within 25 %% (right effect)%s%.1f %% (%d/%d)%s%s%s\n", md ? "| " : "  ", sep,
                    100.0 * allpe_ok / allpe, allpe_ok, allpe, sep, allpe_ok == allpe ? "yes" : "no", md ? " |" : "");
        }
        if (allsh > 0) {
            fprintf(f, "%sheld-out gap shrink >= 70 %% (right effect)%s%.1f %% (%d/%d)%s%s%s\n", md ? "| " : "  ", sep,
                    100.0 * allsh_ok / allsh, allsh_ok, allsh, sep, allsh_ok == allsh ? "yes" : "no", md ? " |" : "");
        }
    }
    if (md) {
        fprintf(f, "\nEvery case (magnitude as a multiple of the detectable threshold; location: Jaccard index of the "
                   "flagged channels against the effect's; parameter: relative error of the magnitude; shrink: fraction "
                   "of the held-out excess gap the right effect explains):\n\n"
                   "| case | log | profile | withheld effect | channels | x threshold | answer | verdict | location | "
                   "parameter error | shrink | time (s) |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
        for (i = 0; i < n; i++) {
            const sgv_case_t *c = &cases[i];
            char mk[32], mu[24], loc[24];
            int ch, m = 0;
            if (c->truth == SGV_NOT_RUN) {
                continue;
            }
            for (ch = 0; ch < SG_NCH; ch++) {
                if ((c->mask >> ch) & 1u) {
                    m += snprintf(mk + m, sizeof mk - (size_t)m, "%s%s", m ? "+" : "", sg_channel_name(ch));
                }
            }
            if (m == 0) {
                snprintf(mk, sizeof mk, "-");
            }
            /* a control has no effect: no multiple of a threshold, no
             * place (it showed the unused draw and a location of 0.00) */
            fig(mu, sizeof mu, 0, 2, c->truth >= 0 ? c->mult : (double)NAN);
            fig(loc, sizeof loc, 0, 2, c->truth >= 0 ? c->jaccard : (double)NAN);
            fprintf(f, "| %d | %s | %s | %s | %s | %s | %s | %s | %s | ", i, c->walk ? "walk" : "static",
                    k_prof[c->profile % 3], c->truth >= 0 ? k_eff[c->truth].name : "control", mk, mu,
                    c->pred >= 0 ? k_eff[c->pred].name : (c->pred == -1 ? "none" : "other"), c->verdict, loc);
            if (c->perr == c->perr) {
                fprintf(f, "%.3f | ", c->perr);
            } else {
                fprintf(f, "- | ");
            }
            if (c->shrink == c->shrink) {
                fprintf(f, "%.2f | ", c->shrink);
            } else {
                fprintf(f, "- | ");
            }
            fprintf(f, "%.1f |\n", c->elapsed_s);
        }
    }
    free(cls);
    free(bins);
    free(medv);
}

int sgv_write_json(const char *path, const sgv_opts_t *o, const sgv_case_t *cases, int n, double elapsed_s,
                   const char *error)
{
    cJSON *root = cJSON_CreateObject(), *arr;
    char err[HX_ERR_SIZE];
    int i, ch, rc, nrun = 0, complete;
    if (root == NULL) {
        return -1;
    }
    cJSON_AddStringToObject(root, "schema", "footnav-simgap-validate/1");
    for (i = 0; i < n; i++) {
        nrun += cases[i].truth != SGV_NOT_RUN;
    }
    cJSON_AddNumberToObject(root, "cases", nrun);
    complete = o->only >= 0 ? nrun == 1 : nrun == n;
    cJSON_AddBoolToObject(root, "complete", complete);
    if (error != NULL && !complete) {
        /* why the run stopped early, as the other commands' `error`, beside
         * complete false */
        cJSON_AddStringToObject(root, "error", error);
    }
    if (o->only >= 0) {
        cJSON_AddNumberToObject(root, "only", o->only);
    } else {
        cJSON_AddNullToObject(root, "only");
    }
    cJSON_AddNumberToObject(root, "seed", o->seed);
    cJSON_AddNumberToObject(root, "duration_s", o->duration_s);
    cJSON_AddNumberToObject(root, "rate_hz", o->rate_hz);
    cJSON_AddNumberToObject(root, "walk_duration_s", o->walk_duration_s);
    cJSON_AddNumberToObject(root, "walk_rate_hz", o->walk_rate_hz);
    cJSON_AddNumberToObject(root, "mag_lo", o->mag_lo);
    cJSON_AddNumberToObject(root, "mag_hi", o->mag_hi);
    cJSON_AddNumberToObject(root, "elapsed_s", elapsed_s);
    arr = cJSON_AddArrayToObject(root, "results");
    for (i = 0; i < n; i++) {
        const sgv_case_t *c = &cases[i];
        cJSON *o2, *v, *chs;
        uint32_t log_seed, diag_seed;
        if (c->truth == SGV_NOT_RUN) {
            continue;
        }
        o2 = cJSON_CreateObject();
        v = cJSON_CreateArray();
        chs = cJSON_CreateArray();
        sgv_case_seeds(o, i, &log_seed, &diag_seed);
        cJSON_AddNumberToObject(o2, "case", i);
        cJSON_AddNumberToObject(o2, "log_seed", log_seed);
        cJSON_AddNumberToObject(o2, "diagnosis_seed", diag_seed);
        cJSON_AddStringToObject(o2, "truth", c->truth >= 0 ? k_eff[c->truth].name : "control");
        cJSON_AddStringToObject(o2, "class", c->truth >= 0 ? k_cls[k_eff[c->truth].cls] : "control");
        cJSON_AddBoolToObject(o2, "walk", c->walk);
        cJSON_AddStringToObject(o2, "profile", k_prof[c->profile % 3]);
        for (ch = 0; ch < SG_NCH; ch++) {
            if ((c->mask >> ch) & 1u) {
                cJSON_AddItemToArray(chs, cJSON_CreateString(sg_channel_name(ch)));
                cJSON_AddItemToArray(v, cJSON_CreateNumber(c->value[ch]));
            }
        }
        cJSON_AddItemToObject(o2, "channels", chs);
        cJSON_AddItemToObject(o2, "values", v);
        cJSON_AddNumberToObject(o2, "multiple_of_threshold", c->mult);
        cJSON_AddStringToObject(o2, "answer", c->pred >= 0 ? k_eff[c->pred].name : (c->pred == -1 ? "none" : "other"));
        cJSON_AddStringToObject(o2, "verdict", c->verdict);
        cJSON_AddNumberToObject(o2, "location_jaccard", c->jaccard);
        if (c->perr == c->perr) {
            cJSON_AddNumberToObject(o2, "param_rel_error", c->perr);
        } else {
            cJSON_AddNullToObject(o2, "param_rel_error");
        }
        if (c->shrink == c->shrink) {
            cJSON_AddNumberToObject(o2, "held_out_shrink", c->shrink);
        } else {
            cJSON_AddNullToObject(o2, "held_out_shrink");
        }
        cJSON_AddNumberToObject(o2, "elapsed_s", c->elapsed_s);
        cJSON_AddItemToArray(arr, o2);
    }
    rc = hx_write_json(path, root, err, sizeof err);
    cJSON_Delete(root);
    if (rc != 0) {
        hx_error("simgap-validate", "%s", err);
    }
    return rc;
}
