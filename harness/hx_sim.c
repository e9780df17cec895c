/* The simulator's sampling chain and the text form of effects (hx_sim.h). */
#include "hx_sim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hx_profile.h"

#define PI 3.14159265358979323846

static const char *const k_ch_names[6] = { "ax", "ay", "az", "gx", "gy", "gz" };

/* ------------------------------------------------------------ FIR */

/* Modified Bessel function I0 by its power series (converges for any x). */
static double bessel_i0(double x)
{
    double s = 1.0, term = 1.0, q = 0.25 * x * x;
    int k;
    for (k = 1; k < 200; k++) {
        term *= q / ((double)k * (double)k);
        s += term;
        if (term < 1e-17 * s) {
            break;
        }
    }
    return s;
}

/* Kaiser-windowed sinc low-pass for decimation by M: cut-off at the output
 * Nyquist frequency, L = 2 K M + 1 taps, beta 5.65 (Kaiser's beta for a 60 dB
 * stop band; it measures 59.0 dB at the edge, scripts/sim_fir_response.py;
 * Kaiser's transition width (A - 7.95) / (14.36 (L - 1)) of the internal
 * rate = 0.18 f_s in total, centred on f_s / 2: pass band to 0.41 f_s, stop
 * band from 0.59 f_s), unit DC gain, linear phase (delay K output periods,
 * compensated by centring the filter on the output instant). */
static double *fir_design(int M, int K, int *L_out)
{
    int L = 2 * K * M + 1, n, c = K * M;
    double beta = 0.1102 * (60.0 - 8.7), i0b = bessel_i0(beta), sum = 0.0;
    double *h = (double *)malloc((size_t)L * sizeof *h);
    if (h == NULL) {
        return NULL;
    }
    for (n = 0; n < L; n++) {
        double x = (double)(n - c) / (double)M;
        double r = (double)(n - c) / (double)c;
        double sinc = (n == c) ? 1.0 : sin(PI * x) / (PI * x);
        h[n] = sinc * bessel_i0(beta * sqrt(1.0 - r * r)) / i0b;
        sum += h[n];
    }
    for (n = 0; n < L; n++) {
        h[n] /= sum;
    }
    *L_out = L;
    return h;
}

/* ------------------------------------------------------------ chain */

size_t hx_sim_ticks(const hx_sim_config_t *cfg)
{
    double T = cfg->duration_s > 0.0 ? cfg->duration_s : hx_motion_duration(cfg->motion);
    return (size_t)floor(T * (double)cfg->err.rate_hz + 1e-9) + 1;
}

typedef struct {
    const hx_motion_t *motion;
    fnav_imuerr_t *e;
    double f_int;
} gen_t;

/* Signal stage of internal sample n, the truth taken at n / f_int + dt. */
static void gen(const gen_t *g, long n, double dt, double y[6])
{
    hx_truth_t o;
    fnav_real_t f[3], w[3], r[6];
    int c;
    hx_motion_eval(g->motion, (double)n / g->f_int + dt, &o);
    for (c = 0; c < 3; c++) {
        f[c] = (fnav_real_t)o.f_b[c];
        w[c] = (fnav_real_t)o.w_b[c];
    }
    fnav_imuerr_signal(g->e, f, w, r);
    for (c = 0; c < 6; c++) {
        y[c] = (double)r[c];
    }
}

int hx_sim_run(const hx_sim_config_t *cfg, hx_sim_sink_fn sink, void *ctx, char *err, size_t err_size)
{
    fnav_imuerr_t e;
    gen_t g;
    size_t N, j;
    int M, pick, mean, K = HX_SIM_FIR_HALF, L = 1, status = 0, c;
    double prev_end[6];
    double *h = NULL, (*ring)[6] = NULL, rate;
    long n_next, half = 0;
    int64_t last_ns = INT64_MIN;
    hx_sim_tick_t tk;
    if (fnav_imuerr_init(&e, &cfg->err) != FNAV_OK) {
        snprintf(err, err_size, "invalid sensor error configuration (a parameter out of its range?)");
        return -1;
    }
    rate = (double)cfg->err.rate_hz;
    M = (int)fnav_imuerr_internal_factor(&cfg->err);
    mean = cfg->decim == HX_DECIM_MEAN && cfg->err.mask[FNAV_EFFECT_ALIAS] == 0u;
    pick = !mean && ((cfg->err.mask[FNAV_EFFECT_ALIAS] != 0u) || M == 1);
    if (!pick && cfg->err.mask[FNAV_EFFECT_JITTER] != 0u && cfg->err.jitter.sample_s > FNAV_R(0.0)) {
        snprintf(err, err_size,
                 "sampling-instant jitter (jitter:sample_s) needs point sampling: --oversample 1 or the alias effect");
        return -1;
    }
    g.motion = cfg->motion;
    g.e = &e;
    g.f_int = rate * M;
    N = hx_sim_ticks(cfg);
    if (!pick && !mean) {
        h = fir_design(M, K, &L);
        ring = (double(*)[6])malloc((size_t)L * sizeof *ring);
        if (h == NULL || ring == NULL) {
            free(h);
            free(ring);
            snprintf(err, err_size, "out of memory");
            return -1;
        }
        half = (long)K * M;
    }
    n_next = mean ? -(long)M : (pick ? 0 : -half);
    fnav_imuerr_signal_index(&e, (int32_t)n_next); /* the tone's phase is phase_rad at t = 0 */
    if (mean) {
        gen(&g, n_next++, 0.0, prev_end); /* the start of the first interval */
    }
    for (j = 0; j < N; j++) {
        fnav_imuerr_tick_t plan;
        fnav_real_t y[6];
        double yd[6];
        long center = (long)j * M;
        fnav_imuerr_tick(&e, &plan);
        if (mean) {
            /* trapezoidal mean of the internal samples over ((j-1) M, j M]:
             * the interval that ends at the stamp */
            double yi[6], inner[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
            for (; n_next <= center; n_next++) {
                gen(&g, n_next, 0.0, yi);
                for (c = 0; c < 6; c++) {
                    inner[c] += (n_next < center) ? yi[c] : 0.0;
                }
            }
            for (c = 0; c < 6; c++) {
                yd[c] = (0.5 * prev_end[c] + inner[c] + 0.5 * yi[c]) / (double)M;
                prev_end[c] = yi[c];
            }
        } else if (pick) {
            /* every internal sample passes the signal stage; the last one of
             * the output period is kept (no filter: what lies above the
             * output Nyquist frequency folds) */
            for (; n_next <= center; n_next++) {
                gen(&g, n_next, n_next == center ? (double)plan.sample_off_s : 0.0, yd);
            }
        } else {
            long i;
            for (; n_next <= center + half; n_next++) {
                long slot = ((n_next % L) + L) % L;
                gen(&g, n_next, 0.0, ring[slot]);
            }
            for (c = 0; c < 6; c++) {
                yd[c] = 0.0;
            }
            for (i = 0; i < L; i++) {
                long n = center - half + i, slot = ((n % L) + L) % L;
                for (c = 0; c < 6; c++) {
                    yd[c] += h[i] * ring[slot][c];
                }
            }
        }
        for (c = 0; c < 6; c++) {
            y[c] = (fnav_real_t)yd[c];
        }
        fnav_imuerr_sensor(&e, y);

        memset(&tk, 0, sizeof tk);
        tk.seq = (uint32_t)j;
        tk.t_s = (double)j / rate;
        hx_motion_eval(cfg->motion, tk.t_s, &tk.truth);
        tk.count = plan.count;
        {
            fnav_real_t b[6];
            fnav_imuerr_bias(&e, b);
            for (c = 0; c < 6; c++) {
                tk.bias[c] = (double)b[c];
            }
        }
        tk.meas.seq = (uint32_t)j;
        tk.meas.flags = FNAV_SAMPLE_HAS_SEQ;
        {
            int64_t ns = (int64_t)llround((tk.t_s + (double)plan.stamp_off_s) * 1e9);
            if (ns < last_ns) {
                ns = last_ns; /* stamps never go backwards (rounding) */
            }
            tk.meas.t_ns = ns;
            if (plan.count > 0u) {
                last_ns = ns;
            }
        }
        for (c = 0; c < 3; c++) {
            tk.meas.accel_mps2[c] = y[c];
            tk.meas.gyro_rps[c] = y[3 + c];
        }
        if (cfg->err.mask[FNAV_EFFECT_THERMAL] != 0u) {
            tk.meas.temp_c = e.temp_c;
            tk.meas.flags |= FNAV_SAMPLE_HAS_TEMP;
        }
        if (sink(ctx, &tk) != 0) {
            status = 1;
            break;
        }
    }
    free(h);
    free(ring);
    return status;
}

/* ------------------------------------------------------------ effect text */

uint32_t hx_channels_parse(const char *s)
{
    uint32_t m = 0u;
    const char *p = s;
    if (strcmp(s, "all") == 0) {
        return FNAV_CH_ALL;
    }
    if (strcmp(s, "acc") == 0) {
        return FNAV_CH_ACC;
    }
    if (strcmp(s, "gyro") == 0) {
        return FNAV_CH_GYRO;
    }
    while (*p != '\0') {
        int c, found = 0;
        for (c = 0; c < 6; c++) {
            if (strncmp(p, k_ch_names[c], 2) == 0 && (p[2] == '+' || p[2] == '\0')) {
                m |= 1u << c;
                p += 2;
                found = 1;
                break;
            }
        }
        if (!found) {
            return 0u;
        }
        if (*p == '+') {
            p++;
            if (*p == '\0') {
                return 0u;
            }
        }
    }
    return m;
}

/* an effect without a per-channel parameter acts on whole samples (jitter,
 * dropout, duplicate, alias): fnav_imuerr_enable gives it every channel */
static int effect_is_scalar(const fnav_effect_info_t *info)
{
    int k;
    for (k = 0; k < info->nparams; k++) {
        if (info->params[k].flags & FNAV_PARAM_PER_CHANNEL) {
            return 0;
        }
    }
    return 1;
}

static void effect_ch_refusal(const fnav_effect_info_t *info, char *err, size_t err_size)
{
    size_t len;
    int e;
    len = (size_t)snprintf(err, err_size, "effect %s acts on whole samples, not on channels: no ch= (ch= is for",
                           info->name);
    for (e = 0; e < FNAV_EFFECT_COUNT && len < err_size; e++) {
        const fnav_effect_info_t *o = fnav_imuerr_effect_info((fnav_effect_id_t)e);
        if (o != NULL && !effect_is_scalar(o)) {
            len += (size_t)snprintf(err + len, err_size - len, " %s", o->name);
        }
    }
    if (len < err_size) {
        snprintf(err + len, err_size - len, ")");
    }
}

int hx_effect_parse(fnav_imuerr_config_t *cfg, const char *spec, char *err, size_t err_size)
{
    char buf[512], *tok[32], *save = NULL, *t;
    int ntok = 0, i;
    fnav_effect_id_t id;
    const fnav_effect_info_t *info;
    uint32_t mask;
    if (strlen(spec) >= sizeof buf) {
        snprintf(err, err_size, "effect specification too long: %.40s...", spec);
        return -1;
    }
    strcpy(buf, spec);
    for (t = strtok_r(buf, ":", &save); t != NULL && ntok < 32; t = strtok_r(NULL, ":", &save)) {
        tok[ntok++] = t;
    }
    if (ntok == 0) {
        snprintf(err, err_size, "empty effect specification");
        return -1;
    }
    if (t != NULL) {
        /* refused, not the fields past the 32nd dropped without a word */
        snprintf(err, err_size, "effect specification with more than %d fields: %.40s...", ntok, spec);
        return -1;
    }
    id = fnav_imuerr_effect_find(tok[0]);
    info = fnav_imuerr_effect_info(id);
    if (info == NULL) {
        snprintf(err, err_size, "unknown effect '%s' (see --list-effects)", tok[0]);
        return -1;
    }
    if (ntok == 2 && strcmp(tok[1], "off") == 0) {
        fnav_imuerr_disable(cfg, id);
        return 0;
    }
    mask = info->allowed;
    for (i = 1; i < ntok; i++) {
        if (strncmp(tok[i], "ch=", 3) == 0 && effect_is_scalar(info)) {
            /* it acts on whole samples (their timing, their delivery):
             * refused, not ignored (dropout:ch=gz dropped every channel) */
            effect_ch_refusal(info, err, err_size);
            return -1;
        }
        if (strncmp(tok[i], "ch=", 3) == 0) {
            mask = hx_channels_parse(tok[i] + 3);
            if (mask == 0u) {
                snprintf(err, err_size, "effect %s: bad channel list '%s' (all, acc, gyro or ax+ay+az+gx+gy+gz)",
                         info->name, tok[i] + 3);
                return -1;
            }
            if ((mask & info->allowed) == 0u) {
                snprintf(err, err_size, "effect %s does not apply to channels '%s'", info->name, tok[i] + 3);
                return -1;
            }
            mask &= info->allowed;
        }
    }
    for (i = 1; i < ntok; i++) {
        char *eq = strchr(tok[i], '=');
        int k;
        double v = 0.0;
        uint32_t pm = mask;
        if (strncmp(tok[i], "ch=", 3) == 0) {
            continue;
        }
        if (eq == NULL) {
            snprintf(err, err_size, "effect %s: expected PARAM=VALUE, got '%s'", info->name, tok[i]);
            return -1;
        }
        *eq = '\0';
        k = fnav_imuerr_param_find(id, tok[i]);
        if (k < 0) {
            int q;
            size_t len;
            len = (size_t)snprintf(err, err_size, "effect %s has no parameter '%s' (parameters:", info->name, tok[i]);
            for (q = 0; q < info->nparams && len < err_size; q++) {
                len += (size_t)snprintf(err + len, err_size - len, " %s", info->params[q].name);
            }
            if (len < err_size) {
                snprintf(err + len, err_size - len, ")");
            }
            return -1;
        }
        if (hx_parse_number(eq + 1, &v) != 0) {
            snprintf(err, err_size, "effect %s: %s needs a number, got '%s'", info->name, tok[i], eq + 1);
            return -1;
        }
        if (id == FNAV_EFFECT_MISALIGN) {
            /* a channel's own axis is the scale factor's: left at 0 */
            int axis = tok[i][5] - 'x', c;
            for (c = 0; c < 6; c++) {
                if (c % 3 == axis) {
                    pm &= ~(1u << c);
                }
            }
            if (pm == 0u && v != 0.0) {
                /* every channel given is the parameter's own axis: refused,
                 * since the value would be dropped and the run go on */
                snprintf(err, err_size, "effect misalign: %s is the own axis of the %c channels (a%c, g%c: that is "
                         "the scale effect); give it for the other channels", tok[i], 'x' + axis, 'x' + axis,
                         'x' + axis);
                return -1;
            }
        }
        if ((info->params[k].flags & FNAV_PARAM_INTEGER) && v != floor(v)) {
            /* refused here by name, not later by fnav_imuerr_init as "the
             * effects are inconsistent (e.g. ...)", which does not name it */
            snprintf(err, err_size, "effect %s: %s needs a whole number, got '%s'", info->name, tok[i], eq + 1);
            return -1;
        }
        if (fnav_imuerr_param_set(cfg, id, k, pm, (fnav_real_t)v) != FNAV_OK) {
            snprintf(err, err_size, "effect %s: %s = %g is outside [%g, %g] (%s)", info->name, tok[i], v,
                     info->params[k].lo, info->params[k].hi, info->params[k].unit);
            return -1;
        }
    }
    if (fnav_imuerr_enable(cfg, id, mask) != FNAV_OK) {
        snprintf(err, err_size, "effect %s: no channel to apply it to", info->name);
        return -1;
    }
    return 0;
}

static int same_params(const fnav_imuerr_config_t *cfg, fnav_effect_id_t id, int a, int b)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info(id);
    int k;
    for (k = 0; k < info->nparams; k++) {
        if (fnav_imuerr_param_get(cfg, id, k, a) != fnav_imuerr_param_get(cfg, id, k, b)) {
            return 0;
        }
    }
    return 1;
}

/* The shortest decimal that reads back as v (%.9g would print the float
 * 0.05 as 0.0500000007 and the MTx density 8.9e-4 as 0.000890000025): what
 * parses back to the same fnav_real_t is the same value. */
static void shortest(char *out, size_t size, fnav_real_t v)
{
    const double a = fabs((double)v);
    /* at least the integer digits, so that 210 is not 2.1e+02 */
    int p, d = a >= 1.0 && a < 1e17 ? (int)floor(log10(a)) + 1 : 1;
    for (p = d; p < 17; p++) {
        snprintf(out, size, "%.*g", p, (double)v);
        if ((fnav_real_t)strtod(out, NULL) == v) {
            return;
        }
    }
    snprintf(out, size, "%.17g", (double)v);
}

size_t hx_effect_format(const fnav_imuerr_config_t *cfg, fnav_effect_id_t id, char *buf, size_t size)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info(id);
    uint32_t left;
    size_t len = 0;
    int first = 1, scalar = 1, k;
    if (size > 0) {
        buf[0] = '\0';
    }
    if (info == NULL || cfg->mask[id] == 0u) {
        return 0;
    }
    for (k = 0; k < info->nparams; k++) {
        if (info->params[k].flags & FNAV_PARAM_PER_CHANNEL) {
            scalar = 0;
        }
    }
    left = cfg->mask[id];
    while (left != 0u) {
        int c0 = 0, c;
        uint32_t group = 0u;
        while (!(left & (1u << c0))) {
            c0++;
        }
        for (c = c0; c < 6; c++) {
            if ((left & (1u << c)) && (scalar || same_params(cfg, id, c0, c))) {
                group |= 1u << c;
            }
        }
        left &= ~group;
#define APPEND(...)                                                                  \
    do {                                                                             \
        int w_ = snprintf(len < size ? buf + len : NULL, len < size ? size - len : 0, __VA_ARGS__); \
        len += (w_ > 0) ? (size_t)w_ : 0u;                                           \
    } while (0)
        APPEND("%s%s", first ? "" : " ", info->name);
        first = 0;
        if (!scalar) {
            if (group == FNAV_CH_ALL) {
                APPEND(":ch=all");
            } else if (group == FNAV_CH_ACC) {
                APPEND(":ch=acc");
            } else if (group == FNAV_CH_GYRO) {
                APPEND(":ch=gyro");
            } else {
                int sep = 0;
                APPEND(":ch=");
                for (c = 0; c < 6; c++) {
                    if (group & (1u << c)) {
                        APPEND("%s%s", sep ? "+" : "", k_ch_names[c]);
                        sep = 1;
                    }
                }
            }
        }
        for (k = 0; k < info->nparams; k++) {
            char v[40];
            shortest(v, sizeof v, fnav_imuerr_param_get(cfg, id, k, c0));
            APPEND(":%s=%s", info->params[k].name, v);
        }
#undef APPEND
    }
    return len;
}

void hx_effect_list(FILE *f)
{
    int id, k;
    fprintf(f, "Effects (--effect NAME[:ch=CH][:PARAM=VALUE]... ; NAME:off). Units SI; \"u\" is the\n"
               "channel's unit: m/s^2 for ax ay az, rad/s for gx gy gz. Defaults shown for\n"
               "channels ax / gy (docs/simulator.md).\n\n");
    for (id = 0; id < (int)FNAV_EFFECT_COUNT; id++) {
        const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)id);
        fprintf(f, "%-11s %s%s\n", info->name, info->brief, info->allowed == FNAV_CH_GYRO ? " (gyro channels)" : "");
        for (k = 0; k < info->nparams; k++) {
            const fnav_effect_param_t *p = &info->params[k];
            double a = (double)fnav_imuerr_param_get(&fnav_imuerr_config_default, (fnav_effect_id_t)id, k, 0);
            double g = (double)fnav_imuerr_param_get(&fnav_imuerr_config_default, (fnav_effect_id_t)id, k, 4);
            if (p->flags & FNAV_PARAM_PER_CHANNEL) {
                fprintf(f, "    %-10s %-16s default %-11.4g / %-11.4g range [%g, %g]\n", p->name, p->unit, a, g, p->lo,
                        p->hi);
            } else {
                fprintf(f, "    %-10s %-16s default %-25.4g range [%g, %g]\n", p->name, p->unit, a, p->lo, p->hi);
            }
        }
    }
}

/* ------------------------------------------------------------ options */

void hx_profile_bias_eq6(fnav_profile_t *p)
{
    int i;
    for (i = 0; i < 3; i++) {
        /* BS = sigma_bias sqrt(tau samples) (eq. 6), stationary sd = BS / 0.617 */
        p->accel_bias_sigma_mps2[i] = (fnav_real_t)((double)p->accel_bias_sigma_mps2[i] *
                                                    sqrt((double)p->accel_tau_s[i] * (double)p->rate_hz) / 0.617);
        p->gyro_bias_sigma_rps[i] = (fnav_real_t)((double)p->gyro_bias_sigma_rps[i] *
                                                  sqrt((double)p->gyro_tau_s[i] * (double)p->rate_hz) / 0.617);
    }
}

void hx_sim_warn_cut(const char *cmd, const hx_motion_t *m, const char *name, double duration_s)
{
    hx_truth_t at, end;
    double full = hx_motion_duration(m), moved = 0.0;
    int n, total = hx_motion_strides(m), i;
    if (!(duration_s > 0.0) || duration_s >= full) {
        return;
    }
    hx_motion_eval(m, duration_s, &at);
    hx_motion_eval(m, full, &end);
    n = hx_motion_strides_until(m, duration_s);
    for (i = 0; i < 3; i++) {
        moved += (end.pos_m[i] - at.pos_m[i]) * (end.pos_m[i] - at.pos_m[i]);
    }
    /* a 'walk' of 4 s would be 4 s of standing and a 'loop' of 20 s would
     * end 1.2 m from its start without a word; the sized scenarios' last
     * standing, cut by their whole strides, is no cut */
    if (n < total || sqrt(moved) > 1e-6 || fabs(remainder(end.euler_rad[2] - at.euler_rad[2], 6.283185307179586)) > 1e-9) {
        hx_warn(cmd, "--duration %g cuts the motion '%s' (%.1f s) short: the output ends after %d of its %d strides, "
                     "%.2f m from where the motion ends%s",
                duration_s, name, full, n, total, sqrt(moved), n == 0 ? " (no stride at all)" : "");
    }
}

/* whether the motion of --motion and --duration takes a stride (walk: a
 * walking one), built with cfg and freed here: only asked for an
 * --impact-ms that would raise the internal rate or a walking gait out of
 * range; a script that cannot be built counts as striding, its error said
 * where the command builds it */
static int motion_has_strides(const hx_sim_setup_t *s, const hx_motion_config_t *cfg, int walk)
{
    char err[HX_ERR_SIZE];
    hx_motion_t *m = hx_motion_create(cfg, s->motion_name, s->duration_s, err, sizeof err);
    int n = m != NULL ? (walk ? hx_motion_walk_strides(m) : hx_motion_strides(m)) : 1;
    hx_motion_free(m);
    return n > 0;
}

void hx_sim_warn_unused(const char *cmd, const hx_args_t *a, const hx_motion_t *m, const char *name)
{
    static const char *const gait[] = { "--speed", "--cadence", "--stride" };
    char given[64] = "";
    size_t len = 0;
    int i, n = 0;
    for (i = 0; i < 3; i++) {
        if (hx_arg(a, gait[i]) != NULL && len < sizeof given) {
            len += (size_t)snprintf(given + len, sizeof given - len, "%s%s", n > 0 ? ", " : "", gait[i]);
            n++;
        }
    }
    if (n > 0 && hx_motion_walk_strides(m) == 0) {
        /* the run, stairs and turns keep their own gaits: said, not a
         * log identical to the one without them */
        hx_warn(cmd, "%s set%s the walking gait; the motion '%s' has no walking stride (%s): ignored", given,
                n == 1 ? "s" : "", name,
                hx_motion_strides(m) > 0 ? "run, stairs and turns keep their own gaits" : "no stride at all");
    }
    if (hx_arg(a, "--impact-ms") != NULL && hx_motion_strides(m) == 0) {
        hx_warn(cmd, "--impact-ms sets the landing of a stride; the motion '%s' has no stride: ignored", name);
    }
}

static int parse_triple(const char *s, double v[3])
{
    const char *end;
    int i;
    for (i = 0; i < 3; i++) {
        if (hx_scan_number(s, &end, &v[i]) != 0) {
            return -1;
        }
        s = end;
        if (i < 2) {
            if (*s != ',') {
                return -1;
            }
            s++;
        }
    }
    return *s == '\0' ? 0 : -1;
}

int hx_sim_setup_from_args(const char *cmd, const hx_args_t *a, hx_sim_setup_t *s)
{
    char err[HX_ERR_SIZE];
    double rate = 200.0, dur = 0.0, over = 0.0, seed = 1.0, v;
    const char *bs;
    int i;
    memset(s, 0, sizeof *s);
    s->motion_cfg = hx_motion_config_default();
    s->motion_name = hx_arg(a, "--motion");
    if (s->motion_name == NULL) {
        s->motion_name = "walk";
    }
    if (hx_arg_double(a, "--rate", 1.0, 100000.0, &rate) != 0 || hx_arg_double(a, "--duration", 1e-3, 1e6, &dur) != 0 ||
        hx_arg_whole(a, "--oversample", 1.0, 1024.0, &over) != 0 ||
        hx_arg_whole(a, "--seed", 0.0, 4294967295.0, &seed) != 0) {
        return -1;
    }
    s->duration_s = dur;
    /* walking gait: two of speed, cadence, stride give the third */
    {
        double sp = 0.0, ca = 0.0, st = 0.0;
        hx_gait_t *w = &s->motion_cfg.walk;
        if (hx_arg_double(a, "--speed", 0.05, 10.0, &sp) != 0 || hx_arg_double(a, "--cadence", 20.0, 300.0, &ca) != 0 ||
            hx_arg_double(a, "--stride", 0.05, 5.0, &st) != 0) {
            return -1;
        }
        if (sp > 0.0 && ca > 0.0 && st > 0.0) {
            hx_error(cmd, "give at most two of --speed, --cadence, --stride");
            return -1;
        }
        if (ca > 0.0) {
            w->cadence_spm = ca;
        }
        if (st > 0.0) {
            w->stride_m = st;
        }
        if (sp > 0.0) {
            if (st > 0.0) {
                w->cadence_spm = 120.0 * sp / st;
            } else {
                w->stride_m = 120.0 * sp / w->cadence_spm;
            }
        }
        /* the derived figure keeps the range of its own option (--speed 10
         * --cadence 20 would walk 50 m strides, --speed 5 --stride 0.5 be
         * refused as "gait fractions leave no time to swing") */
        if ((w->cadence_spm < 20.0 || w->cadence_spm > 300.0 || w->stride_m < 0.05 || w->stride_m > 5.0)) {
            /* a motion without a walking stride ignores the gait (said by
             * hx_sim_warn_unused): not refused for a stride it never takes
             * (run --speed 5 was "a stride of 5.455 m, outside [0.05, 5]") */
            hx_motion_config_t trial = s->motion_cfg;
            trial.walk = hx_motion_config_default().walk;
            if (!motion_has_strides(s, &trial, 1)) {
                *w = trial.walk;
            }
        }
        if (w->cadence_spm < 20.0 || w->cadence_spm > 300.0) {
            hx_error(cmd, "--speed %g with a stride of %g m makes a cadence of %.4g steps/min, outside [20, 300]", sp,
                     w->stride_m, w->cadence_spm);
            return -1;
        }
        if (w->stride_m < 0.05 || w->stride_m > 5.0) {
            hx_error(cmd, "--speed %g at %g steps/min makes a stride of %.4g m, outside [0.05, 5]", sp, w->cadence_spm,
                     w->stride_m);
            return -1;
        }
    }
    v = 0.0;
    if (hx_arg_double(a, "--impact-ms", 0.5, 200.0, &v) != 0) {
        return -1;
    }
    if (v > 0.0) {
        hx_motion_config_t *m = &s->motion_cfg;
        const hx_gait_t *gs[5];
        const char *const gn[5] = { "walk", "run", "stairs up", "stairs down", "turn" };
        char caps[160];
        size_t len = 0;
        m->walk.impact_s = m->run.impact_s = m->stairs_up.impact_s = m->stairs_down.impact_s = m->turn.impact_s =
            v * 1e-3;
        gs[0] = &m->walk;
        gs[1] = &m->run;
        gs[2] = &m->stairs_up;
        gs[3] = &m->stairs_down;
        gs[4] = &m->turn;
        caps[0] = '\0';
        for (i = 0; i < 5; i++) {
            /* a stride lands in at most 30 % of the swing (hx_gait_max_impact_s): a
             * longer --impact-ms is said, not shortened without a word */
            const double cap_s = hx_gait_max_impact_s(gs[i]);
            if (v * 1e-3 > cap_s && len < sizeof caps) {
                len += (size_t)snprintf(caps + len, sizeof caps - len, "%s%s %.0f ms", len ? ", " : "", gn[i],
                                        cap_s * 1e3);
            }
        }
        if (len > 0) {
            hx_warn(cmd, "--impact-ms %g is longer than 30 %% of a swing, the longest landing: %s", v, caps);
        }
    }
    v = -1.0;
    if (hx_arg_double(a, "--ring-scale", 0.0, 100.0, &v) != 0) {
        return -1;
    }
    if (v >= 0.0) {
        hx_motion_config_t *m = &s->motion_cfg;
        m->walk.ring_mps2 *= v;
        m->run.ring_mps2 *= v;
        m->stairs_up.ring_mps2 *= v;
        m->stairs_down.ring_mps2 *= v;
        m->turn.ring_mps2 *= v;
    }
    if (hx_arg(a, "--mount") != NULL && parse_triple(hx_arg(a, "--mount"), s->motion_cfg.mount_deg) != 0) {
        hx_error(cmd, "--mount needs R,P,Y in degrees, e.g. --mount 0,10,90, not '%s'", hx_arg(a, "--mount"));
        return -1;
    }
    if (hx_arg(a, "--mount") != NULL) {
        /* ZYX Euler angles reach every mounting with roll and yaw in
         * [-180, 180] and pitch in [-90, 90]; a number outside is refused
         * (--mount 1e30,0,0 would simulate a sensor turned by 1e30 degrees,
         * exit 0) */
        const double *m = s->motion_cfg.mount_deg;
        if (!(fabs(m[0]) <= 180.0) || !(fabs(m[1]) <= 90.0) || !(fabs(m[2]) <= 180.0)) {
            hx_error(cmd, "--mount '%s': roll, pitch, yaw in degrees within [-180, 180], [-90, 90], [-180, 180]",
                     hx_arg(a, "--mount"));
            return -1;
        }
    }
    bs = hx_arg(a, "--bias-sigma");
    if (bs != NULL && strcmp(bs, "given") != 0 && strcmp(bs, "eq6") != 0) {
        hx_error(cmd, "--bias-sigma is given or eq6, not '%s'", bs);
        return -1;
    }
    s->bias_eq6 = bs != NULL && strcmp(bs, "eq6") == 0;
    {
        const char *d = hx_arg(a, "--decimation");
        if (d != NULL && strcmp(d, "fir") != 0 && strcmp(d, "mean") != 0) {
            hx_error(cmd, "--decimation is fir or mean, not '%s'", d);
            return -1;
        }
        s->decim = (d != NULL && strcmp(d, "mean") == 0) ? HX_DECIM_MEAN : HX_DECIM_FIR;
    }

    /* sensor model: profile baseline, then the effects in order */
    s->err = fnav_imuerr_config_default;
    s->err.rate_hz = (fnav_real_t)rate;
    s->err.seed = (uint32_t)seed;
    s->err.oversample = over > 0.0 ? (uint32_t)over : (uint32_t)ceil(2000.0 / rate - 1e-9);
    if (s->err.oversample < 1u) {
        s->err.oversample = 1u;
    }
    if (s->err.oversample > 1024u) {
        s->err.oversample = 1024u; /* fnav_imuerr's limit: below 1.95 Hz the default stays under 2 kHz */
    }
    s->profile_name = hx_arg(a, "--profile");
    if (s->profile_name == NULL) {
        s->profile_name = "navchip";
    }
    if (strcmp(s->profile_name, "none") != 0) {
        if (hx_profile_load(s->profile_name, &s->profile, err, sizeof err) != 0) {
            hx_error(cmd, "%s", err);
            return -1;
        }
        if (s->bias_eq6) {
            fnav_profile_t builtin;
            if (fnav_profile_by_name(&builtin, s->profile_name) != FNAV_OK) {
                /* a file's bias sd is most likely a stationary sd already
                 * (allan --profile writes one), which eq6 multiplies by
                 * sqrt(tau rate) / 0.617, so it is said */
                hx_warn(cmd, "--bias-sigma eq6 rereads the bias sd of the profile file %s as the paper Tables' "
                             "sigma_bias (eq. 6: x sqrt(tau_s rate_hz) / 0.617); a profile from `harness allan "
                             "--profile` holds the stationary sd already: leave eq6 out for it (docs/simulator.md)",
                        s->profile_name);
            }
            hx_profile_bias_eq6(&s->profile);
            {
                /* the bias sd read by eq. 6 within the limits a file's is
                 * held to (montecarlo's filter takes the same values) */
                char perr[HX_ERR_SIZE];
                if (hx_profile_check(&s->profile, perr, sizeof perr) != 0) {
                    hx_error(cmd, "profile %s read by --bias-sigma eq6: %s", s->profile_name, perr);
                    return -1;
                }
            }
        }
        if (fnav_imuerr_config_from_profile(&s->err, &s->profile) != FNAV_OK) {
            hx_error(cmd, "profile %s is not valid for the error model: a noise density, correlation time or bias sd "
                          "outside the ranges of its white and ar1 effects (sim --list-effects)",
                     s->profile_name);
            return -1;
        }
        s->has_profile = 1;
    } else if (s->bias_eq6) {
        /* eq6 rereads a profile's bias sd; the ideal sensor has none (the
         * option is ignored with a warning, not without a word) */
        hx_warn(cmd, "--bias-sigma eq6 rereads a profile's bias sd; --profile none has no bias model: ignored%s",
                strcmp(cmd, "montecarlo") == 0 ? " (the filter's profile is read as given)" : "");
    }
    for (i = 0; i < hx_arg_count(a, "--effect"); i++) {
        if (hx_effect_parse(&s->err, hx_arg_at(a, "--effect", i), err, sizeof err) != 0) {
            hx_error(cmd, "%s", err);
            return -1;
        }
    }
    {
        fnav_imuerr_t probe;
        if (fnav_imuerr_init(&probe, &s->err) != FNAV_OK) {
            hx_error(cmd, "the effects are inconsistent (e.g. jumps faster than the rate, flicker tau_lo_s >= "
                          "tau_hi_s, alias factor not whole)");
            return -1;
        }
    }
    if (over <= 0.0 && s->err.mask[FNAV_EFFECT_ALIAS] == 0u) {
        /* the default internal rate, raised where the signal has content
         * it would fold before the filter or the interval mean sees it: a
         * vibration tone (2.5 x its frequency: sampled at 2 kHz, 1990 Hz
         * reached the output as a full 10 Hz line) and impacts shorter
         * than 2.5 ms (5 internal samples to a landing: 2 ms at 2 kHz put
         * 12 m/s^2 of aliasing into a run's samples). Unchanged at the
         * defaults (impacts 5-8 ms, no vibration) */
        const hx_gait_t *gs[5];
        const char *why = "impacts shorter than 2.5 ms";
        double need = 0.0;
        gs[0] = &s->motion_cfg.walk;
        gs[1] = &s->motion_cfg.run;
        gs[2] = &s->motion_cfg.stairs_up;
        gs[3] = &s->motion_cfg.stairs_down;
        gs[4] = &s->motion_cfg.turn;
        for (i = 0; i < 5; i++) {
            need = gs[i]->impact_s > 0.0 && 5.0 / gs[i]->impact_s > need ? 5.0 / gs[i]->impact_s : need;
        }
        if (ceil(need / rate - 1e-9) > (double)s->err.oversample && !motion_has_strides(s, &s->motion_cfg, 0)) {
            /* no landing to resolve: not raised for an --impact-ms that
             * has none to act on (stand at 0.5 ms ran at 10 kHz, 5 times
             * as long; hx_sim_warn_unused says it is ignored) */
            need = 0.0;
        }
        for (i = 0; i < 6; i++) {
            const double f = (double)s->err.vibration.freq_hz[i];
            if ((s->err.mask[FNAV_EFFECT_VIBRATION] & (1u << i)) != 0u && 2.5 * f > need) {
                need = 2.5 * f;
                why = "the vibration tone";
            }
        }
        if (s->decim == HX_DECIM_MEAN && need < 2.0 * rate) {
            need = 2.0 * rate; /* a mean needs a sample inside its interval (at 2 kHz and above the default is 1) */
        }
        v = ceil(need / rate - 1e-9);
        if (v > (double)s->err.oversample) {
            const uint32_t was = s->err.oversample;
            s->err.oversample = v > 1024.0 ? 1024u : (uint32_t)v;
            if (s->err.oversample >= 4u * was) {
                /* the cost grows with it: said (the "internal xN" line
                 * alone did not say why a run took 10 times as long) */
                char note[256];
                snprintf(note, sizeof note,
                         "note: the internal rate is raised to %g Hz (x%u, the default x%u) for %s: the run takes "
                         "about %.0f times as long (--oversample sets it)\n",
                         rate * s->err.oversample, (unsigned)s->err.oversample, (unsigned)was, why,
                         (double)s->err.oversample / (double)was);
                hx_print_warnings(cmd, note);
            }
        }
    }
    {
        /* the chain of hx_sim_run: picking with alias or without
         * oversampling, else the interval mean or the anti-alias FIR */
        int alias = s->err.mask[FNAV_EFFECT_ALIAS] != 0u, mean, pick;
        if (alias && s->decim == HX_DECIM_MEAN) {
            /* said, not silently dropped; and the samples are then
             * instantaneous (montecarlo's filter is told so) */
            hx_warn(cmd, "the alias effect point-samples the signal: --decimation mean is not applied (the samples are "
                         "instantaneous values)");
            s->decim = HX_DECIM_FIR;
        }
        if (alias && over > 0.0 && (uint32_t)over != fnav_imuerr_internal_factor(&s->err)) {
            hx_warn(cmd, "the alias effect's factor sets the internal rate (x%u): --oversample %g is not applied",
                    (unsigned)fnav_imuerr_internal_factor(&s->err), over);
        }
        mean = s->decim == HX_DECIM_MEAN && !alias;
        pick = !mean && (alias || fnav_imuerr_internal_factor(&s->err) == 1u);
        /* sampling-instant jitter: refused here, before any output is
         * begun (hx_sim_run would refuse it after the log was created), with
         * the advice that fits the decimation (not --oversample 1 to a
         * --decimation mean run that has it) */
        if (!pick && s->err.mask[FNAV_EFFECT_JITTER] != 0u && s->err.jitter.sample_s > FNAV_R(0.0)) {
            hx_error(cmd, "sampling-instant jitter (jitter:sample_s) needs point sampling: %s",
                     mean ? "interval means (--decimation mean) average over the interval; use --decimation fir "
                            "with --oversample 1, or the alias effect"
                          : "--oversample 1 or the alias effect");
            return -1;
        }
        if (mean && fnav_imuerr_internal_factor(&s->err) == 1u) {
            /* the trapezoid of the interval's two ends, not its mean */
            hx_error(cmd, "interval means (--decimation mean) need internal samples between the output samples: "
                          "--oversample 2 or more (--oversample 1 would average the interval's two ends)");
            return -1;
        }
        for (i = 0; i < 6 && s->err.mask[FNAV_EFFECT_VIBRATION] != 0u && !alias; i++) {
            const int M = (int)fnav_imuerr_internal_factor(&s->err);
            const double f0 = (double)s->err.vibration.freq_hz[i], fi = rate * M;
            /* the tone as the internal rate samples it: above its Nyquist
             * frequency, folded before the filter or the mean sees it */
            const double f = fabs(f0 - fi * floor(f0 / fi + 0.5));
            char at[320] = "";
            int j, said = 0;
            if ((s->err.mask[FNAV_EFFECT_VIBRATION] & (1u << i)) == 0u) {
                continue;
            }
            for (j = 0; j < i; j++) {
                /* one warning for a frequency (the effect's default is
                 * every channel: six of one were printed) */
                said |= (s->err.mask[FNAV_EFFECT_VIBRATION] & (1u << j)) != 0u &&
                        s->err.vibration.freq_hz[j] == s->err.vibration.freq_hz[i];
            }
            if (said) {
                continue;
            }
            if (f != f0) {
                const double need = ceil(2.5 * f0 / rate - 1e-9);
                char more[64] = "";
                if (!pick && M < 1024 && need <= 1024.0) {
                    snprintf(more, sizeof more, " (--oversample %.0f or more keeps it as it is)", need);
                }
                if (pick) {
                    snprintf(at, sizeof at, "point samples (--oversample 1) fold it to %g Hz", f);
                } else {
                    snprintf(at, sizeof at, "it is sampled at %g Hz (%s %d), less than twice its frequency, and "
                                            "folds to %g Hz before %s sees it%s",
                             fi, M >= 1024 ? "--oversample's limit," : "--oversample", M, f,
                             mean ? "the interval mean" : "the filter", more);
                }
            }
            if (pick) {
                if (f0 > 0.5 * rate) {
                    hx_warn(cmd, "vibration at %g Hz lies above the output's Nyquist frequency (%g Hz at %g Hz): %s",
                            f0, 0.5 * rate, rate, at);
                }
                continue;
            }
            if (!mean && f > 0.41 * rate) {
                /* a tone in the filter's stop band never reaches the output;
                 * one in its transition band (0.41-0.59 f_s) passes
                 * attenuated, folded above f_s / 2 (the warning says so, not
                 * "filtered out" for both: 90 Hz at 200 Hz passes at 91 %) */
                int L, n;
                double *h = fir_design(M, HX_SIM_FIR_HALF, &L), gain = 0.0;
                if (h != NULL) {
                    for (n = 0; n < L; n++) {
                        gain += h[n] * cos(2.0 * PI * f / fi * (double)(n - (L - 1) / 2));
                    }
                    free(h);
                }
                gain = fabs(gain);
                if (gain < 1e-3) {
                    hx_warn(cmd, "vibration at %g Hz lies above the anti-alias pass band (%.0f Hz at %g Hz): filtered "
                                 "out%s%s; add --effect alias to fold it into the output band",
                            f0, 0.41 * rate, rate, at[0] != '\0' ? "; " : "", at);
                } else {
                    char fold[64] = "";
                    if (f > 0.5 * rate) {
                        snprintf(fold, sizeof fold, ", folded to %.4g Hz", fabs(f - rate * floor(f / rate + 0.5)));
                    }
                    hx_warn(cmd, "vibration at %g Hz%s%s%s the anti-alias filter's transition band (%.0f-%.0f Hz at "
                                 "%g Hz): it passes at %.1f %% of its amplitude%s",
                            f0, at[0] != '\0' ? ": " : "", at, at[0] != '\0' ? ", in" : " lies in", 0.41 * rate,
                            0.59 * rate, rate, 100.0 * gain, fold);
                }
                continue;
            }
            if (!mean && f != f0) {
                hx_warn(cmd, "vibration at %g Hz: %s, in the anti-alias filter's pass band: it passes whole", f0, at);
                continue;
            }
            if (mean && (f > 0.5 * rate || f != f0)) {
                /* the interval mean is no anti-alias filter: it passes the
                 * tone attenuated and folded (the warning says so, not
                 * "filtered out") */
                hx_warn(cmd, "vibration at %g Hz lies above the output's Nyquist frequency (%g Hz at %g Hz): %s%sthe "
                             "interval means (--decimation mean) attenuate it and fold it to %g Hz",
                        f0, 0.5 * rate, rate, at, at[0] != '\0' ? "; " : "", fabs(f - rate * floor(f / rate + 0.5)));
            }
        }
    }
    return 0;
}
