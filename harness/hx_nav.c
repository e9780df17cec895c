/* Harness side of navigation: options, replay engine, resampler, summary,
 * JSON and plots (hx_nav.h). */
#include "hx_nav.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fnav_port_linux.h"
#include "hx_motion.h"
#include "hx_profile.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ------------------------------------------------------------ options */

int hx_nav_opts_from_args(const char *cmd, const hx_args_t *a, hx_nav_opts_t *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->profile = hx_arg(a, "--profile");
    o->bias_model = hx_arg(a, "--bias-model");
    o->detector = hx_arg(a, "--detector");
    o->samples = hx_arg(a, "--samples");
    if (hx_arg_double(a, "--rate", 1.0, 100000.0, &o->rate_hz) != 0) {
        return -1;
    }
    o->nparams = hx_arg_count(a, "--param");
    for (i = 0; i < o->nparams; i++) {
        o->params[i] = hx_arg_at(a, "--param", i);
        if (strcmp(o->params[i], "help") == 0) {
            hx_nav_param_help(stdout);
            return 1;
        }
    }
    (void)cmd; /* the values are checked by hx_nav_config, which every command calls */
    return 0;
}

/* --param table: key, unit scale (value * scale -> SI), help. */
typedef enum { P_REAL, P_INT } ptype_t;
typedef struct {
    const char *key;
    ptype_t type;
    double scale;
    const char *help;
} param_t;

static const param_t k_params[] = {
    { "gamma", P_REAL, 1.0, "SHOE threshold" },
    { "window_s", P_REAL, 1.0, "detector window, s" },
    { "sigma_a", P_REAL, 1.0, "SHOE accel weight, m/s^2" },
    { "sigma_g_dps", P_REAL, 3.14159265358979323846 / 180.0, "SHOE gyro weight, deg/s" },
    { "adaptive", P_INT, 1.0, "adaptive threshold 0/1" },
    { "floor_window_s", P_REAL, 1.0, "adaptive floor: minimum of log10 T over this window, s" },
    { "margin_dec", P_REAL, 1.0, "adaptive threshold above the floor, decades" },
    { "adapt_max_ratio", P_REAL, 1.0, "adaptive threshold at most gamma times this" },
    { "gyro_thresh_dps", P_REAL, 3.14159265358979323846 / 180.0, "threshold detector: RMS rate limit, deg/s" },
    { "accel_thresh", P_REAL, 1.0, "threshold detector: RMS ||f|-g| limit, m/s^2" },
    { "min_zupt_s", P_REAL, 1.0, "a stance shorter than this is ignored, s" },
    { "min_zupt_cycle", P_REAL, 1.0, "shortest ZUPT run as a fraction of the recent gait cycle (0: off; raises the latency)" },
    { "min_stance_s", P_REAL, 1.0, "segmentation: shortest stance, s" },
    { "min_swing_s", P_REAL, 1.0, "segmentation: shortest swing, s" },
    { "event_window_s", P_REAL, 1.0, "gait events: foot-off search after a swing begins, foot-strike search before a stance, s" },
    { "gravity", P_REAL, 1.0, "local gravity, m/s^2" },
    { "accel_motion_noise", P_REAL, 1.0, "extra accel process noise, m/s^2/sqrt(Hz)" },
    { "gyro_motion_noise_dps", P_REAL, 3.14159265358979323846 / 180.0, "extra gyro process noise, deg/s/sqrt(Hz)" },
    { "zupt_sigma", P_REAL, 1.0, "ZUPT noise, m/s" },
    { "lever", P_INT, 1.0, "estimate the rolling-foot lever 0/1 (ZUPT of the pivot)" },
    { "lever_sd", P_REAL, 1.0, "initial lever sd, m" },
    { "lever_rw", P_REAL, 1.0, "lever random walk, m/sqrt(s)" },
    { "settle", P_INT, 1.0, "landing settling state 0/1 (coloured ZUPT error at each stance onset)" },
    { "settle_sd", P_REAL, 1.0, "settling sd at the stance onset, m/s" },
    { "settle_tau", P_REAL, 1.0, "settling time constant, s" },
    { "zaru", P_INT, 1.0, "zero-angular-rate updates 0/1" },
    { "zaru_sigma_dps", P_REAL, 3.14159265358979323846 / 180.0, "ZARU noise, deg/s" },
    { "zaru_gate", P_REAL, 1.0, "ZARU gate on the innovation's NIS, chi-square 3 dof (0: none)" },
    { "zaru_after_s", P_REAL, 1.0, "ZARU only once a stance has lasted this long, s" },
    { "realign_min_s", P_REAL, 1.0, "renew the alignment on still periods this long before the first stride, s (0: off)" },
    { "tilt_sd_deg", P_REAL, 3.14159265358979323846 / 180.0, "initial roll/pitch sd, deg" },
    { "yaw_sd_deg", P_REAL, 3.14159265358979323846 / 180.0, "initial yaw sd, deg" },
    { "gyro_bias_sd_dps", P_REAL, 3.14159265358979323846 / 180.0, "initial sd of the AR(1) gyro bias states, deg/s" },
    { "accel_bias_sd", P_REAL, 1.0, "initial sd of the AR(1) accel bias states, m/s^2" },
    { "max_gap_s", P_REAL, 1.0, "longest interval integrated as it is, s" },
    { "closed_form", P_INT, 1.0, "UKF closed-form linear sigma points 0/1" },
    { "align_min_s", P_REAL, 1.0, "shortest still period for the alignment, s" },
    { "align_max_s", P_REAL, 1.0, "alignment ends after this much stillness, s" },
    { "align_short_s", P_REAL, 1.0, "alignment: shortest still period used when the walk starts early, s" },
    { "align_ratio", P_REAL, 1.0, "alignment: statistic limit over its running geometric mean" },
    { "gyro_bias_prior_dps", P_REAL, 3.14159265358979323846 / 180.0, "alignment: prior sd of the gyro turn-on bias, deg/s (0: plain mean)" },
    { NULL, P_REAL, 0.0, NULL }
};

static void *param_ptr(fnav_nav_config_t *c, const char *key)
{
    if (strcmp(key, "gamma") == 0) return &c->stance.gamma;
    if (strcmp(key, "window_s") == 0) return &c->stance.window_s;
    if (strcmp(key, "sigma_a") == 0) return &c->stance.sigma_a_mps2;
    if (strcmp(key, "sigma_g_dps") == 0) return &c->stance.sigma_g_rps;
    if (strcmp(key, "adaptive") == 0) return &c->stance.adaptive;
    if (strcmp(key, "margin_dec") == 0) return &c->stance.margin_dec;
    if (strcmp(key, "floor_window_s") == 0) return &c->stance.floor_window_s;
    if (strcmp(key, "adapt_max_ratio") == 0) return &c->stance.adapt_max_ratio;
    if (strcmp(key, "gyro_thresh_dps") == 0) return &c->stance.gyro_thresh_rps;
    if (strcmp(key, "accel_thresh") == 0) return &c->stance.accel_thresh_mps2;
    if (strcmp(key, "min_stance_s") == 0) return &c->stance.min_stance_s;
    if (strcmp(key, "min_zupt_s") == 0) return &c->stance.min_zupt_s;
    if (strcmp(key, "min_zupt_cycle") == 0) return &c->stance.min_zupt_cycle;
    if (strcmp(key, "min_swing_s") == 0) return &c->stance.min_swing_s;
    if (strcmp(key, "event_window_s") == 0) return &c->stance.event_window_s;
    if (strcmp(key, "gravity") == 0) return &c->gravity_mps2;
    if (strcmp(key, "accel_motion_noise") == 0) return &c->accel_motion_noise_mps2_rthz;
    if (strcmp(key, "gyro_motion_noise_dps") == 0) return &c->gyro_motion_noise_rps_rthz;
    if (strcmp(key, "zupt_sigma") == 0) return &c->zupt_sigma_mps;
    if (strcmp(key, "lever") == 0) return &c->lever;
    if (strcmp(key, "lever_sd") == 0) return &c->lever_sd_m;
    if (strcmp(key, "lever_rw") == 0) return &c->lever_rw_m_rts;
    if (strcmp(key, "settle") == 0) return &c->settle;
    if (strcmp(key, "settle_sd") == 0) return &c->settle_sd_mps;
    if (strcmp(key, "settle_tau") == 0) return &c->settle_tau_s;
    if (strcmp(key, "zaru") == 0) return &c->zaru;
    if (strcmp(key, "zaru_sigma_dps") == 0) return &c->zaru_sigma_rps;
    if (strcmp(key, "zaru_gate") == 0) return &c->zaru_gate;
    if (strcmp(key, "zaru_after_s") == 0) return &c->zaru_after_s;
    if (strcmp(key, "realign_min_s") == 0) return &c->realign_min_s;
    if (strcmp(key, "tilt_sd_deg") == 0) return &c->tilt_sd_rad;
    if (strcmp(key, "yaw_sd_deg") == 0) return &c->yaw_sd_rad;
    if (strcmp(key, "gyro_bias_sd_dps") == 0) return &c->gyro_bias_sd_rps;
    if (strcmp(key, "accel_bias_sd") == 0) return &c->accel_bias_sd_mps2;
    if (strcmp(key, "max_gap_s") == 0) return &c->max_gap_s;
    if (strcmp(key, "closed_form") == 0) return &c->closed_form;
    if (strcmp(key, "align_min_s") == 0) return &c->align.min_still_s;
    if (strcmp(key, "align_max_s") == 0) return &c->align.max_still_s;
    if (strcmp(key, "align_short_s") == 0) return &c->align.short_still_s;
    if (strcmp(key, "align_ratio") == 0) return &c->align.still_ratio;
    if (strcmp(key, "gyro_bias_prior_dps") == 0) return &c->align.gyro_bias_prior_sd_rps;
    return NULL;
}

int hx_nav_param_help_requested(int argc, char **argv)
{
    int i;
    for (i = 0; i < argc; i++) { /* argv holds the command's arguments only */
        if ((strcmp(argv[i], "--param") == 0 && i + 1 < argc && strcmp(argv[i + 1], "help") == 0) ||
            strcmp(argv[i], "--param=help") == 0) {
            hx_nav_param_help(stdout);
            return 1;
        }
    }
    return 0;
}

void hx_nav_param_help(FILE *f)
{
    fnav_nav_config_t c = fnav_nav_config_default;
    int i;
    fprintf(f, "navigation parameters (--param KEY=VALUE), with their defaults:\n");
    for (i = 0; k_params[i].key != NULL; i++) {
        void *p = param_ptr(&c, k_params[i].key);
        double v = k_params[i].type == P_INT ? (double)*(int *)p : (double)*(fnav_real_t *)p / k_params[i].scale;
        fprintf(f, "  %-22s %-12g %s\n", k_params[i].key, v, k_params[i].help);
    }
}

static int set_param(fnav_nav_config_t *c, const char *kv, char *err, size_t err_size)
{
    char key[64];
    const char *eq = strchr(kv, '=');
    double v = 0.0;
    int i;
    void *p;
    if (eq == NULL || (size_t)(eq - kv) >= sizeof key) {
        snprintf(err, err_size, "--param needs KEY=VALUE, not '%s'", kv);
        return -1;
    }
    memcpy(key, kv, (size_t)(eq - kv));
    key[eq - kv] = '\0';
    if (hx_parse_number(eq + 1, &v) != 0) {
        snprintf(err, err_size, "--param %s: '%s' is not a number", key, eq + 1);
        return -1;
    }
    for (i = 0; k_params[i].key != NULL; i++) {
        if (strcmp(k_params[i].key, key) == 0) {
            break;
        }
    }
    p = param_ptr(c, key);
    if (k_params[i].key == NULL || p == NULL) {
        snprintf(err, err_size, "--param: unknown key '%s' (list: --param help)", key);
        return -1;
    }
    if (k_params[i].type == P_INT) {
        /* every integer key is a 0/1 switch: zaru=0.5 was cast to 0 (off),
         * zaru=-1 or 2 to on, zaru=1e20 was an undefined conversion */
        if (v != 0.0 && v != 1.0) {
            snprintf(err, err_size, "--param %s is a switch: 0 or 1, not '%s'", key, eq + 1);
            return -1;
        }
        *(int *)p = (int)v;
    } else {
        *(fnav_real_t *)p = (fnav_real_t)(v * k_params[i].scale);
    }
    return 0;
}

int hx_nav_config(const hx_nav_opts_t *o, fnav_nav_config_t *cfg, char *err, size_t err_size)
{
    static fnav_nav_t probe; /* validates the configuration as the core will */
    static const char k_rejected[] = "navigation configuration rejected by the core";
    fnav_nav_config_t base;
    int i;
    *cfg = fnav_nav_config_default;
    /* the choices, checked here for every command (montecarlo fills the
     * options itself, without hx_nav_opts_from_args) */
    if (o->bias_model != NULL && strcmp(o->bias_model, "ar1") != 0 && strcmp(o->bias_model, "off") != 0) {
        snprintf(err, err_size, "--bias-model must be ar1 or off, not '%s'", o->bias_model);
        return -1;
    }
    if (o->samples != NULL && strcmp(o->samples, "instant") != 0 && strcmp(o->samples, "mean") != 0) {
        snprintf(err, err_size, "--samples must be instant or mean, not '%s'", o->samples);
        return -1;
    }
    if (o->detector != NULL && strcmp(o->detector, "shoe") != 0 && strcmp(o->detector, "threshold") != 0) {
        snprintf(err, err_size, "--detector must be shoe or threshold, not '%s'", o->detector);
        return -1;
    }
    if (o->profile != NULL && hx_profile_load(o->profile, &cfg->profile, err, err_size) != 0) {
        return -1;
    }
    if (o->bias_model != NULL) {
        cfg->bias_model = strcmp(o->bias_model, "off") == 0 ? FNAV_BIAS_OFF : FNAV_BIAS_AR1;
    }
    if (o->samples != NULL) {
        cfg->sample_type = strcmp(o->samples, "mean") == 0 ? FNAV_SAMPLE_MEAN : FNAV_SAMPLE_INSTANT;
    }
    if (o->detector != NULL) {
        cfg->stance.detector = strcmp(o->detector, "threshold") == 0 ? FNAV_DETECTOR_THRESHOLD : FNAV_DETECTOR_SHOE;
    }
    base = *cfg;
    for (i = 0; i < o->nparams; i++) {
        if (set_param(cfg, o->params[i], err, err_size) != 0) {
            return -1;
        }
    }
    if (o->rate_hz > 0.0) {
        cfg->stance.rate_hz = (fnav_real_t)o->rate_hz;
        base.stance.rate_hz = cfg->stance.rate_hz;
    }
    if (fnav_nav_init(&probe, cfg) != FNAV_OK) {
        hx_nav_init_error(cfg, " (--rate)", o->nparams > 0 ? " (a --param value out of range)" : "", err, err_size);
        /* the core says only that it refuses the whole configuration: name
         * the --param that it refuses on its own ("--param
         * event_window_s=0" was "rejected by the core (a --param value out
         * of range)", the key left to guess) */
        if (strncmp(err, k_rejected, sizeof k_rejected - 1) == 0) {
            for (i = 0; i < o->nparams; i++) {
                fnav_nav_config_t one = base;
                char ignored[8];
                if (set_param(&one, o->params[i], ignored, sizeof ignored) == 0 &&
                    fnav_nav_init(&probe, &one) != FNAV_OK) {
                    snprintf(err, err_size, "%s: --param %s is out of range", k_rejected, o->params[i]);
                    break;
                }
            }
        }
        return -1;
    }
    return 0;
}

void hx_nav_init_error(const fnav_nav_config_t *cfg, const char *rate_src, const char *other, char *err, size_t err_size)
{
    double rate = (double)cfg->stance.rate_hz, gap = (double)cfg->max_gap_s;
    const double att_max = (double)fnav_nav_att_sd_max_rad(cfg);
    const fnav_align_config_t *al = &cfg->align;
    /* the product in fnav_real_t, as fnav_nav_init forms it: 0.2f x 7.5 is
     * 1.5 exactly there and 1.50000002 in double ("rejected by the core"
     * at --rate 7.5, the documented limit) */
    if (rate > 0.0 && gap > 0.0 && !(cfg->max_gap_s * cfg->stance.rate_hz > FNAV_R(1.5))) {
        /* fnav_nav_init's rule: a time jump (max_gap_s) must be longer than
         * a gap of 1.5 intervals. Stamps of 10 s resolution gave a rate of
         * 2.9 Hz here and "check --param values" with no --param given. */
        snprintf(err, err_size,
                 "a sample rate of %.3g Hz%s is too low to navigate: an interval over max_gap_s = %g s counts as a "
                 "time jump, so the rate must be above %.3g Hz",
                 rate, rate_src, gap, 1.5 / gap);
    } else if (att_max > 0.0 && ((double)cfg->tilt_sd_rad > att_max || (double)cfg->yaw_sd_rad > att_max)) {
        /* fnav_nav_init's rule: the UKF's sigma points stay short of 180
         * deg (FNAV_UKF_ATT_GRP_MAX); a larger sd shrank at the first
         * prediction (yaw_sd_deg=90 read 32.4 deg a sample later) */
        const double r2d = 180.0 / 3.14159265358979323846;
        const int yaw = (double)cfg->yaw_sd_rad > att_max;
        snprintf(err, err_size,
                 "%s = %g deg is above %.1f deg, the largest initial attitude sd this filter's sigma points represent "
                 "(fewer states allow more: docs/navigation.md, \"States\")",
                 yaw ? "yaw_sd_deg" : "tilt_sd_deg", r2d * (double)(yaw ? cfg->yaw_sd_rad : cfg->tilt_sd_rad),
                 r2d * att_max);
    } else if (al->max_still_s >= al->min_still_s && al->short_still_s > FNAV_R(0.0) &&
               cfg->realign_min_s > al->max_still_s) {
        /* the rules between keys (fnav_nav_init, fnav_align_init), each
         * named with both keys: "--param align_max_s=2" was "rejected by
         * the core" for the default realign_min_s 3 */
        snprintf(err, err_size,
                 "realign_min_s = %g s is above align_max_s = %g s: a still period ends at align_max_s, so it would "
                 "never renew the alignment (give realign_min_s at most align_max_s, or 0: off)",
                 (double)cfg->realign_min_s, (double)al->max_still_s);
    } else if (al->min_still_s > FNAV_R(0.0) && al->max_still_s < al->min_still_s) {
        snprintf(err, err_size, "align_max_s = %g s is below align_min_s = %g s (the alignment's longest still "
                                "period must be at least its shortest)",
                 (double)al->max_still_s, (double)al->min_still_s);
    } else if (al->min_still_s > FNAV_R(0.0) && al->short_still_s > al->min_still_s) {
        snprintf(err, err_size, "align_short_s = %g s is above align_min_s = %g s (the fallback for a walk that "
                                "starts early is the shorter still period)",
                 (double)al->short_still_s, (double)al->min_still_s);
    } else {
        snprintf(err, err_size, "navigation configuration rejected by the core%s", other);
    }
}

/* A stance detector of cfg's configuration given the rate rate_hz and one
 * sample, so that it has set its window and durations in samples
 * (fnav_stance.c, set_rate): the core's own answer to what they are at a
 * rate, with no second copy of its rounding and caps here. NULL when the
 * core refuses the configuration. */
static const fnav_stance_t *stance_probe(const fnav_nav_config_t *cfg, double rate_hz)
{
    static fnav_stance_t probe;
    fnav_stance_config_t c = cfg->stance;
    fnav_sample_t s0;
    memset(&s0, 0, sizeof s0);
    c.rate_hz = (fnav_real_t)rate_hz;
    if (fnav_stance_init(&probe, &c) != FNAV_OK || fnav_stance_push(&probe, &s0) != FNAV_OK) {
        return NULL;
    }
    return &probe;
}

/* Whether the stance detector fits its configured window and minimum ZUPT
 * run into its ring at rate_hz, asked of the core itself (stance_probe),
 * and whether the navigation takes that rate (max_gap_s: fnav_nav_init). */
static int stance_fits(const fnav_nav_config_t *cfg, double rate_hz)
{
    const fnav_stance_t *probe;
    if (!((double)cfg->max_gap_s * rate_hz > 1.5) || (probe = stance_probe(cfg, rate_hz)) == NULL) {
        return 0;
    }
    /* the cycle-scaled run's cap (FNAV_STANCE_CUT_ZUPT_CYCLE) is said apart */
    return (fnav_stance_cut(probe) & (FNAV_STANCE_CUT_WINDOW | FNAV_STANCE_CUT_MIN_ZUPT)) == 0u;
}

/* The rate to advise when the ring cuts the detector's durations at fs_hz:
 * the highest at which both fit, in whole hundreds of Hz from 100 Hz up and
 * whole Hz below, within replay --rate's range (1 Hz up, below fs_hz: it only
 * downsamples); 0 when none does. The ring holds the window W and half
 * window + minimum run + 1 (fnav_stance.c, set_rate), so the rate is at most
 * MAX / window_s and (MAX - 1) / (window_s / 2 + min_zupt_s); the search
 * starts there and steps down to a rate the core accepts. The second bound
 * alone, rounded to the nearest Hz below 100 Hz, would advise "--rate 0"
 * for window_s = 1e30 and "--rate 62" (still cut) for window_s = 2. */
static double stance_fit_rate(const fnav_nav_config_t *cfg, double fs_hz)
{
    const double w_s = (double)cfg->stance.window_s, z_s = (double)cfg->stance.min_zupt_s;
    double r = fs_hz, step;
    int k;
    if (w_s > 0.0 && (double)FNAV_STANCE_MAX_WINDOW / w_s < r) {
        r = (double)FNAV_STANCE_MAX_WINDOW / w_s;
    }
    if (0.5 * w_s + z_s > 0.0 && (double)(FNAV_STANCE_MAX_WINDOW - 1) / (0.5 * w_s + z_s) < r) {
        r = (double)(FNAV_STANCE_MAX_WINDOW - 1) / (0.5 * w_s + z_s);
    }
    for (k = 0; k < 200; k++) {
        step = r >= 100.0 ? 100.0 : 1.0;
        r = step * floor(r / step);
        if (r >= fs_hz) {
            r -= step;
        }
        if (!(r >= 1.0)) {
            return 0.0;
        }
        if (stance_fits(cfg, r)) {
            return r;
        }
        r -= step;
    }
    return 0.0;
}

/* The gait events' searches at fs_hz, samples, as the core sets them
 * (stance_probe): the foot-off's is n_ev (fnav_stance.c, set_rate: at most
 * FNAV_STANCE_EVENT_BUF - 1); the foot-strike's what the jerk history holds
 * before the stance's first n_min_stance samples (foot_strike). Both 0 when
 * the core refuses the configuration. n_ev and n_min_stance come from the
 * core, not from a second copy of set_rate's arithmetic in double. */
static void event_reach(const fnav_nav_config_t *cfg, double fs_hz, long *fo_n, long *fs_n)
{
    const fnav_stance_t *probe = stance_probe(cfg, fs_hz);
    long ev, ms;
    if (probe == NULL) {
        *fo_n = *fs_n = 0;
        return;
    }
    ev = probe->n_ev;
    ms = probe->n_min_stance;
    *fo_n = ev;
    *fs_n = ev < FNAV_STANCE_EVENT_BUF - ms ? ev : FNAV_STANCE_EVENT_BUF - ms;
}

/* The highest rate below fs_hz, in whole hundreds of Hz from 100 Hz up and
 * whole Hz below, at which both event searches span event_window_s; 0 when
 * none does. */
static double event_fit_rate(const fnav_nav_config_t *cfg, double fs_hz)
{
    double r = fs_hz;
    while (r >= 1.0) {
        const double step = r > 100.0 ? 100.0 : 1.0;
        long fo_n, fs_n, want;
        r = step * ceil(r / step) - step;
        if (!(r >= 1.0)) {
            break;
        }
        event_reach(cfg, r, &fo_n, &fs_n);
        want = lround((double)cfg->stance.event_window_s * r);
        if (fo_n >= want && fs_n >= want) {
            return r;
        }
    }
    return 0.0;
}

/* ------------------------------------------------------------ resampler */

/* One output sample at instant t from the kept input samples [a, b) of a
 * segment without time jumps (kernel half length half, cut-off fc in
 * cycles per input sample); *m is the segment's input sample at or before
 * t, advanced as t grows. */
static void resample_at(const hx_log_t *in, const size_t *keep, size_t a, size_t b, size_t *m, int64_t t, int half,
                        double fc, double acc[3], double gyr[3])
{
    double sa[3] = { 0, 0, 0 }, sg[3] = { 0, 0, 0 }, sw = 0.0, u;
    long q, qlo, qhi;
    int c;
    while (*m + 1 < b && in->t_ns[keep[*m + 1]] <= t) {
        (*m)++;
    }
    if (*m + 1 < b) {
        u = (double)(t - in->t_ns[keep[*m]]) / (double)(in->t_ns[keep[*m + 1]] - in->t_ns[keep[*m]]);
        u = (double)*m + (u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u)); /* fractional input index of t */
    } else {
        u = (double)*m; /* the segment's last sample (or its only one) */
    }
    qlo = (long)floor(u) - half;
    qhi = (long)ceil(u) + half;
    for (q = qlo < (long)a ? (long)a : qlo; q <= qhi && q < (long)b; q++) {
        double x = (double)q - u, w;
        if (fabs(x) >= (double)half) {
            continue;
        }
        w = (fabs(x) < 1e-12 ? 2.0 * fc : sin(2.0 * M_PI * fc * x) / (M_PI * x)) *
            (0.42 + 0.5 * cos(M_PI * x / half) + 0.08 * cos(2.0 * M_PI * x / half));
        for (c = 0; c < 3; c++) {
            sa[c] += w * in->acc[keep[q]][c];
            sg[c] += w * in->gyr[keep[q]][c];
        }
        sw += w;
    }
    for (c = 0; c < 3; c++) {
        acc[c] = sa[c] / sw; /* edges: renormalised partial window */
        gyr[c] = sg[c] / sw;
    }
}

int hx_nav_resample(const hx_log_t *in, double rate_hz, double max_gap_s, hx_log_t *out, long *dups,
                    double *in_rate, char *err, size_t err_size)
{
    return hx_nav_resample_progress(in, rate_hz, max_gap_s, out, dups, in_rate, NULL, NULL, err, err_size);
}

int hx_nav_resample_progress(const hx_log_t *in, double rate_hz, double max_gap_s, hx_log_t *out, long *dups,
                             double *in_rate, void (*progress)(void *ctx, double frac), void *ctx, char *err,
                             size_t err_size)
{
    size_t n = 0, i, k, nout, a, b;
    int64_t gap_ns;
    double fs, fc, period_ns;
    int half, pass;
    size_t *keep;
    memset(out, 0, sizeof *out);
    *dups = 0;
    if (in->n < 4) {
        snprintf(err, err_size, "too few samples to resample (%zu)", in->n);
        return -1;
    }
    keep = (size_t *)malloc(in->n * sizeof *keep);
    if (keep == NULL) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    /* exact repeated time stamps carry no new instant: keep the first */
    for (i = 0; i < in->n; i++) {
        if (n > 0 && in->t_ns[i] <= in->t_ns[keep[n - 1]]) {
            (*dups)++;
            continue;
        }
        keep[n++] = i;
    }
    if (n < 4) {
        free(keep);
        snprintf(err, err_size, "too few distinct time stamps to resample (%zu)", n);
        return -1;
    }
    {
        /* The filter takes the input as uniform at its median rate, which
         * needs the median interval to be the sampling period: stamps in
         * bursts break it (hx_stamp_bursts, the test plain replay makes
         * too). Neither kind is resampled: the kernel, 40 times the rate
         * ratio of "200 kHz" samples long, would smear seconds of the walk
         * into each output (0 strides), and shared stamps would keep one
         * sample of four. */
        hx_bursts_t bu;
        char why[640];
        const int kind = hx_stamp_bursts(in->t_ns, in->n, max_gap_s, &bu);
        if (kind < 0) {
            free(keep);
            snprintf(err, err_size, "out of memory");
            return -1;
        }
        fs = bu.median_hz;
        bu.format = in->meta.format;
        if (kind != HX_BURSTS_NONE) {
            free(keep);
            snprintf(err, err_size, "--rate: %s",
                     hx_bursts_text(&bu, "resampling needs each sample's own time", "Resampling (--rate HZ)", why,
                                    sizeof why));
            return -1;
        }
    }
    *in_rate = fs;
    gap_ns = (int64_t)ceil(1e9 * (max_gap_s > 1.5 / fs ? max_gap_s : 1.5 / fs));
    if (!(rate_hz < fs * 0.999)) {
        /* a rate within 0.1 % of the input's leaves nothing to decimate
         * (the vicon trials' 200.080 Hz median would refuse --rate 200 as
         * "not below the input rate 200.1 Hz"); the advised bound
         * is rounded down so that every rate below it is accepted */
        const double below = floor(fs * 0.999 * 1000.0) / 1000.0;
        free(keep);
        if (rate_hz >= fs) {
            snprintf(err, err_size, "--rate %g Hz is not below the input rate %.3f Hz (1 / its median interval; only "
                                    "downsampling): leave --rate out, or give a rate below %.3f Hz (0.999 x the "
                                    "input rate, rounded down)",
                     rate_hz, fs, below);
        } else {
            snprintf(err, err_size, "--rate %g Hz is within 0.1 %% of the input rate %.3f Hz (1 / its median interval): "
                                    "nothing to decimate (only downsampling); leave --rate out, or give a rate below "
                                    "%.3f Hz (0.999 x the input rate, rounded down)",
                     rate_hz, fs, below);
        }
        return -1;
    }
    /* Blackman-windowed sinc low-pass at 0.45 x the new rate, about 41
     * times the rate ratio long (transition ~0.13 x the new rate), unit DC
     * gain; applied as if the input were uniform at its median rate, and
     * evaluated directly at each output instant: its position between two
     * input stamps gives a fractional input index u, and the kernel is
     * taken at j - u (renormalised by its weights at the edges). Filtering
     * the input samples and interpolating the output linearly at the new
     * instants would add a second, phase-dependent low-pass that takes 7 %
     * off a 40 Hz tone at 250 -> 100 Hz and leaves a 9 % error
     * (tests/test_nav.c, test_resampler).
     * A time jump (an interval above max_gap_s and 1.5 input periods, the
     * navigator's own rule) splits the log into segments: the filter does
     * not reach across it and the output grid starts again at the first
     * sample after it, so the jump stays a jump (a grid running through it
     * would make a day's pause 8.6 million made-up samples). Smaller gaps of
     * lost samples are closed up. */
    fc = 0.45 * rate_hz / fs; /* cycles per input sample */
    half = (int)ceil(20.0 * fs / rate_hz);
    period_ns = 1e9 / rate_hz;
    nout = 0;
    for (pass = 0; pass < 2; pass++) {
        k = 0;
        for (a = 0; a < n; a = b) {
            const int64_t t0 = in->t_ns[keep[a]];
            size_t m = a, j, nseg;
            for (b = a + 1; b < n && in->t_ns[keep[b]] - in->t_ns[keep[b - 1]] <= gap_ns; b++) {
            }
            nseg = (size_t)floor((double)(in->t_ns[keep[b - 1]] - t0) / period_ns) + 1;
            if (pass == 0) {
                nout += nseg;
                continue;
            }
            for (j = 0; j < nseg; j++, k++) {
                const int64_t t = t0 + (int64_t)llround((double)j * period_ns);
                if (progress != NULL && (k & 4095u) == 0u) {
                    progress(ctx, (double)k / (double)nout);
                }
                out->t_ns[k] = t;
                out->seq[k] = (uint32_t)k;
                out->temp[k] = (double)NAN;
                resample_at(in, keep, a, b, &m, t, half, fc, out->acc[k], out->gyr[k]);
            }
        }
        if (pass == 0) {
            out->t_ns = (int64_t *)malloc(nout * sizeof *out->t_ns);
            out->seq = (uint32_t *)malloc(nout * sizeof *out->seq);
            out->acc = (double(*)[3])malloc(nout * sizeof *out->acc);
            out->gyr = (double(*)[3])malloc(nout * sizeof *out->gyr);
            out->temp = (double *)malloc(nout * sizeof *out->temp);
            if (!out->t_ns || !out->seq || !out->acc || !out->gyr || !out->temp) {
                hx_log_free(out);
                free(keep);
                snprintf(err, err_size, "out of memory (%zu resampled samples)", nout);
                return -1;
            }
        }
    }
    out->n = nout;
    out->meta = in->meta;
    out->meta.rate_hz = rate_hz;
    out->meta.rate_nominal = 1;
    out->status = FNAV_END;
    free(keep);
    if (progress != NULL) {
        progress(ctx, 1.0);
    }
    return 0;
}

/* ------------------------------------------------------------ replay */

/* 1 when a variance of channel ch (0..2 accelerometer, 3..5 gyroscope)
 * is a foot's at rest, not its motion's (HX_SAT_REST_SD_*): only such a
 * block gives the noise the span is judged against, so that a log that
 * never rests (a run, a walk at 100 Hz whose blocks of 0.64 s all hold a
 * swing) keeps the flat-top rule alone */
static int sat_rest_var(int ch, double var)
{
    const double sd = ch < 3 ? HX_SAT_REST_SD_ACCEL : HX_SAT_REST_SD_GYRO;
    return var <= sd * sd;
}

void hx_sat_push(hx_sat_t *st, const fnav_sample_t *s)
{
    int ch;
    if (st->have && s->t_ns == st->t_last_ns) {
        return; /* an exact duplicate row is not a plateau */
    }
    for (ch = 0; ch < 6; ch++) {
        const double v = ch < 3 ? (double)s->accel_mps2[ch] : (double)s->gyro_rps[ch - 3];
        if (!st->have || v > st->mx[ch]) {
            st->mx[ch] = v;
            st->cmx[ch] = 1;
            st->rmx[ch] = 0;
            st->runx[ch] = 1;
        } else if (v == st->mx[ch]) {
            st->cmx[ch]++;
            if (++st->runx[ch] == 2) {
                st->rmx[ch]++;
            }
        } else {
            st->runx[ch] = 0;
        }
        if (!st->have || v < st->mn[ch]) {
            st->mn[ch] = v;
            st->cmn[ch] = 1;
            st->rmn[ch] = 0;
            st->runn[ch] = 1;
        } else if (v == st->mn[ch]) {
            st->cmn[ch]++;
            if (++st->runn[ch] == 2) {
                st->rmn[ch]++;
            }
        } else {
            st->runn[ch] = 0;
        }
    }
    for (ch = 0; ch < 6; ch++) {
        const double v = ch < 3 ? (double)s->accel_mps2[ch] : (double)s->gyro_rps[ch - 3];
        const double d = st->have ? fabs(v - st->last[ch]) : 0.0;
        if (d > 0.0 && (st->step[ch] == 0.0 || d < st->step[ch])) {
            st->step[ch] = d;
        }
        st->last[ch] = v;
        if (st->bn == 0) {
            st->b0[ch] = v;
            st->bs[ch] = 0.0;
            st->bss[ch] = 0.0;
        }
        st->bs[ch] += v - st->b0[ch];
        st->bss[ch] += (v - st->b0[ch]) * (v - st->b0[ch]);
    }
    if (++st->bn == HX_SAT_BLOCK) {
        for (ch = 0; ch < 6; ch++) {
            const double m = st->bs[ch] / (double)st->bn;
            const double var = st->bss[ch] / (double)st->bn - m * m;
            if (sat_rest_var(ch, var) && (!st->have_rest[ch] || var < st->var_min[ch])) {
                st->var_min[ch] = var;
                st->have_rest[ch] = 1;
            }
        }
        st->bn = 0;
    }
    st->t_last_ns = s->t_ns;
    st->have = 1;
}

/* The noise of channel ch at rest (hx_sat_t); 0 when no block (nor the
 * samples of a log shorter than one) looked like rest: the span is then
 * not judged against it. */
static double sat_noise(const hx_sat_t *st, int ch)
{
    double var;
    double sd;
    if (st->have_rest[ch]) {
        var = st->var_min[ch];
    } else {
        const double m = st->bn > 0 ? st->bs[ch] / (double)st->bn : 0.0;
        var = st->bn > 0 ? st->bss[ch] / (double)st->bn - m * m : 0.0;
        if (st->bn == 0 || !sat_rest_var(ch, var)) {
            return 0.0;
        }
    }
    sd = var > 0.0 ? sqrt(var) : 0.0;
    return sd > st->step[ch] ? sd : st->step[ch];
}

long hx_sat_count(const hx_sat_t *st, int ch)
{
    if (!st->have || ch < 0 || ch >= 6 || st->mx[ch] == st->mn[ch]) {
        return 0; /* a constant channel is no clipping */
    }
    if (st->mx[ch] - st->mn[ch] <= HX_SAT_SPAN_NOISE * sat_noise(st, ch)) {
        return 0; /* extremes within the noise: a still channel's, not a full scale */
    }
    return st->rmx[ch] + st->rmn[ch] >= 2 ? st->cmx[ch] + st->cmn[ch] : 0;
}

void hx_traj_free(hx_traj_t *t)
{
    free(t->f);
    free(t->ev);
    free(t->in_long);
    memset(t, 0, sizeof *t);
}

void hx_traj_set_config(hx_traj_t *t, const hx_nav_opts_t *o, const fnav_nav_config_t *cfg)
{
    fnav_profile_t tmp;
    int i;
    t->have_config = 1;
    t->config = *cfg;
    t->profile_file[0] = '\0';
    if (o->profile != NULL && fnav_profile_by_name(&tmp, o->profile) != FNAV_OK) {
        snprintf(t->profile_file, sizeof t->profile_file, "%s", o->profile);
    }
    t->nparams = 0;
    for (i = 0; i < o->nparams && i < HX_MAX_REPEAT; i++) {
        snprintf(t->params[t->nparams++], sizeof t->params[0], "%s", o->params[i]);
    }
}

/* The names the options take, for the config line, the plot title and the JSON. */
static const char *bias_model_name(const fnav_nav_config_t *c)
{
    return c->bias_model == FNAV_BIAS_OFF ? "off" : "ar1";
}

static const char *detector_name(const fnav_nav_config_t *c)
{
    return c->stance.detector == FNAV_DETECTOR_THRESHOLD ? "threshold" : "shoe";
}

static const char *samples_name(const fnav_nav_config_t *c)
{
    return c->sample_type == FNAV_SAMPLE_MEAN ? "mean" : "instant";
}

void hx_nav_plot_title(const hx_traj_t *t, const char *path, double rate_hz, char *buf, size_t size)
{
    /* the title names the options that change the run, so plots of one log
     * with --rate 100 or --detector threshold do not share the path alone */
    char opt[600];
    size_t used = 0;
    int k;
    opt[0] = '\0';
    if (rate_hz > 0.0) {
        k = snprintf(opt + used, sizeof opt - used, ", --rate %g", rate_hz);
        used += k > 0 ? (size_t)k : 0u;
    }
    if (t->have_config) {
        const fnav_nav_config_t *c = &t->config;
        int i;
        if (used < sizeof opt && (t->profile_file[0] != '\0' ||
                                  strcmp(c->profile.name, fnav_nav_config_default.profile.name) != 0)) {
            k = snprintf(opt + used, sizeof opt - used, ", --profile %s",
                         t->profile_file[0] != '\0' ? t->profile_file : c->profile.name);
            used += k > 0 ? (size_t)k : 0u;
        }
        if (used < sizeof opt && c->bias_model != fnav_nav_config_default.bias_model) {
            k = snprintf(opt + used, sizeof opt - used, ", --bias-model %s", bias_model_name(c));
            used += k > 0 ? (size_t)k : 0u;
        }
        if (used < sizeof opt && c->stance.detector != fnav_nav_config_default.stance.detector) {
            k = snprintf(opt + used, sizeof opt - used, ", --detector %s", detector_name(c));
            used += k > 0 ? (size_t)k : 0u;
        }
        if (used < sizeof opt && c->sample_type != fnav_nav_config_default.sample_type) {
            k = snprintf(opt + used, sizeof opt - used, ", --samples %s", samples_name(c));
            used += k > 0 ? (size_t)k : 0u;
        }
        for (i = 0; i < t->nparams && used < sizeof opt; i++) {
            k = snprintf(opt + used, sizeof opt - used, ", --param %s", t->params[i]);
            used += k > 0 ? (size_t)k : 0u;
        }
    }
    if (opt[0] != '\0') {
        snprintf(buf, size, "%s (%s)", path, opt + 2);
    } else {
        snprintf(buf, size, "%s", path);
    }
}

void hx_nav_detector_label(const fnav_nav_config_t *c, char *buf, size_t size)
{
    if (c->stance.detector == FNAV_DETECTOR_THRESHOLD) {
        /* the threshold detector's own limits (fnav_stance.h), which the
         * adaptive threshold may raise together */
        snprintf(buf, size, " (window RMS |w| < %.4g deg/s and ||f| - g| < %.4g m/s^2, %s limits)",
                 (double)c->stance.gyro_thresh_rps * 180.0 / M_PI,
                 (double)c->stance.accel_thresh_mps2,
                 c->stance.adaptive ? "adaptive" : "fixed");
    } else {
        snprintf(buf, size, "%s", c->stance.adaptive ? " (adaptive threshold)" : " (fixed threshold)");
    }
}

void hx_nav_config_text(const hx_traj_t *t, char *buf, size_t size)
{
    const fnav_nav_config_t *c = &t->config;
    char det[HX_NAV_DETECTOR_LABEL_SIZE];
    size_t used;
    int k, i;
    hx_nav_detector_label(c, det, sizeof det);
    k = snprintf(buf, size, "profile %s%s%s%s, bias model %s, detector %s%s, samples %s, lever %s, settling %s, ZARU %s",
                 c->profile.name, t->profile_file[0] ? " (file " : "", t->profile_file, t->profile_file[0] ? ")" : "",
                 bias_model_name(c), detector_name(c), det,
                 samples_name(c), c->lever ? "on" : "off", c->settle ? "on" : "off",
                 /* the ZARU updates the gyro bias states (fnav_ukf_zaru):
                  * with the bias model off it does nothing */
                 !c->zaru                          ? "off"
                 : c->bias_model == FNAV_BIAS_OFF ? "on (no effect: it updates the gyro bias, which --bias-model off "
                                                    "does not estimate)"
                                                  : "on");
    used = k > 0 ? (size_t)k : 0u;
    for (i = 0; i < t->nparams && used < size; i++) {
        k = snprintf(buf + used, size - used, "%s%s", i == 0 ? "; parameters overridden: " : ", ", t->params[i]);
        used += k > 0 ? (size_t)k : 0u;
    }
}

/* The harness port: the Linux port's CSV sink plus frame collection, and a
 * source that is either the Linux port's reader or a resampled log in
 * memory; progress is updated from the source. */
typedef struct {
    fnav_port_t linux_port;
    fnav_linux_port_ctx_t lctx;
    const hx_log_t *mem;      /* resampled input, or NULL */
    size_t mem_i;
    hx_traj_t *traj;
    hx_progress_t prog;
    int progress;
    double total;
    long n_read;
    int sink_failed;     /* the CSV sink refused a frame */
    int traj_oom;        /* no memory to keep a frame */
    double gyro_max_rps; /* largest |w| on one axis: the units check (a range is per axis) */
    double gyro_max_in_rps; /* the same over the samples within the navigator's range */
    long n_gyro_over;    /* samples past it (FNAV_NAV_GYRO_MAX_RPS on an axis): glitches when few */
    double f_norm_sum;   /* sum of |f| read: the units check when no rest was found */
    hx_walk_t walk;      /* |f| in one-second windows: the units check's gyro mark */
    int64_t q_t0_ns;     /* the open one-second window of the swapped-columns check (q_n > 0) */
    double q_w, q_w2, q_f; /* its sums of |w|, |w|^2 and |f| */
    long q_n;
    double quiet_w, quiet_f; /* the steadiest-|w| window's mean |w| and |f| (quiet_w < 0: none) */
    double quiet_cv;     /* its sd / mean of |w| */
    hx_axes_t *axes;     /* the axes check (with traj), or NULL */
    int64_t t_last_ns;   /* the last sample's stamp (with have_t_last) */
    int64_t t_first_ns;  /* the first sample's stamp (with have_t_last) */
    int have_t_last;
    int64_t stamp_res_ns; /* the stamps' resolution: gcd of the intervals that advance (0: none yet) */
    int64_t *probe;       /* the first HX_STAMPS_PROBE_N stamps read (pairs_warn), or NULL */
    size_t n_probe;
    hx_sat_t sat;         /* flat tops of the input as read (a resampled log's: before resampling) */
    /* HX_REPLAY_EVENTS: a second detector, initialised with the navigator's
     * detector's configuration and fed the samples the navigator accepted
     * (its stats.samples counts them), so that it raises the same outputs
     * in the same order, one per frame: their gait events go to traj->ev */
    fnav_stance_t *ev;
    const fnav_nav_t *nav;
    fnav_sample_t ev_last; /* the sample read last, not yet given to ev */
    int ev_have_last;
    uint32_t ev_pushed;    /* samples given to ev */
    int ev_bad;            /* ev disagreed with a frame, or no memory: no events */
    int ev_fo;             /* the swing's foot-off, waiting for its stride */
    int64_t ev_fo_t_ns;
} hx_port_ctx_t;

/* The swapped-columns check (units_check): one-second windows of the
 * stamps, the one whose |w| is steadiest (smallest sd / mean, 10 samples or
 * more) kept with its mean |w| and |f|. A gyro at rest reads about 0; the
 * steadiest second of columns that hold an accelerometer reads gravity
 * (1 in g, 9.8 in m/s^2) with a spread of a few percent. */
static void quiet_close(hx_port_ctx_t *c)
{
    if (c->q_n >= 10) {
        const double m = c->q_w / (double)c->q_n, var = c->q_w2 / (double)c->q_n - m * m;
        const double cv = m > 0.0 ? sqrt(var > 0.0 ? var : 0.0) / m : 1e300;
        if (c->quiet_w < 0.0 || cv < c->quiet_cv) {
            c->quiet_cv = cv;
            c->quiet_w = m;
            c->quiet_f = c->q_f / (double)c->q_n;
        }
    }
    c->q_n = 0;
}

static void quiet_push(hx_port_ctx_t *c, const fnav_sample_t *s, double f_norm)
{
    const double w = sqrt((double)s->gyro_rps[0] * (double)s->gyro_rps[0] +
                          (double)s->gyro_rps[1] * (double)s->gyro_rps[1] +
                          (double)s->gyro_rps[2] * (double)s->gyro_rps[2]);
    if (c->q_n > 0 && (s->t_ns < c->q_t0_ns || s->t_ns - c->q_t0_ns >= 1000000000)) {
        quiet_close(c);
    }
    if (c->q_n == 0) {
        c->q_t0_ns = s->t_ns;
        c->q_w = c->q_w2 = c->q_f = 0.0;
    }
    c->q_w += w;
    c->q_w2 += w * w;
    c->q_f += f_norm;
    c->q_n++;
}

/* Give ev the last sample read once the navigator has accepted it. */
static void ev_sync(hx_port_ctx_t *c)
{
    if (c->ev != NULL && c->ev_have_last && c->nav->stats.samples != c->ev_pushed) {
        c->ev_have_last = 0;
        c->ev_pushed = c->nav->stats.samples;
        if (fnav_stance_push(c->ev, &c->ev_last) != FNAV_OK) {
            c->ev_bad = 1;
        }
    }
}

/* ev's output for frame f (the navigator's detector raised the same with
 * it): the events into t->ev. */
static void ev_frame(hx_port_ctx_t *c, const fnav_nav_frame_t *f)
{
    hx_traj_t *t = c->traj;
    fnav_stance_out_t o;
    ev_sync(c);
    if (c->nav->stance.finished && !c->ev->finished) {
        fnav_stance_finish(c->ev);
    }
    if (fnav_stance_pop(c->ev, &o) != FNAV_OK || o.sample.t_ns != f->t_ns ||
        ((o.events & FNAV_STANCE_EV_STRIDE) != 0) != ((f->flags & FNAV_FRAME_STRIDE) != 0)) {
        c->ev_bad = 1;
        return;
    }
    if (o.events & FNAV_STANCE_EV_FOOT_OFF) {
        c->ev_fo = 1;
        c->ev_fo_t_ns = o.fo_t_ns;
    }
    if (o.events & FNAV_STANCE_EV_STRIDE) {
        hx_stride_ev_t *e;
        if (t->nev == t->ev_cap) {
            size_t nc = t->ev_cap ? 2 * t->ev_cap : 256;
            hx_stride_ev_t *p = (hx_stride_ev_t *)realloc(t->ev, nc * sizeof *p);
            if (p == NULL) {
                c->ev_bad = 1;
                return;
            }
            t->ev = p;
            t->ev_cap = nc;
        }
        e = &t->ev[t->nev++];
        e->frame = t->n - 1; /* hx_write kept f first */
        e->have_fo = c->ev_fo;
        e->fo_t_ns = c->ev_fo_t_ns;
        e->fs_t_ns = o.fs_t_ns;
        e->swing_t0_ns = o.swing_t0_ns;
        e->swing_t1_ns = o.swing_t1_ns;
        c->ev_fo = 0;
    }
}

static fnav_status_t hx_read(void *ctx, fnav_sample_t *s)
{
    hx_port_ctx_t *c = (hx_port_ctx_t *)ctx;
    fnav_status_t st;
    ev_sync(c); /* the sample before this one, if the navigator took it */
    if (c->mem != NULL) {
        if (c->mem_i >= c->mem->n) {
            return FNAV_END;
        }
        hx_log_sample(c->mem, c->mem_i, s);
        c->mem_i++;
        if (!c->lctx.have_t0) {
            c->lctx.t0_ns = s->t_ns;
            c->lctx.have_t0 = 1;
        }
        st = FNAV_OK;
    } else {
        st = c->linux_port.read_sample(c->linux_port.ctx, s);
        if (st == FNAV_OK) {
            hx_sat_push(&c->sat, s);
        }
    }
    if (st == FNAV_OK) {
        /* the largest single axis, as info's peak line and its units check:
         * a gyro's range is per axis, not the vector's magnitude (454.7
         * against info's 438.8 for one log in deg/s) */
        int k;
        double wmax = 0.0;
        for (k = 0; k < 3; k++) {
            const double w = fabs((double)s->gyro_rps[k]);
            wmax = w > wmax ? w : wmax;
        }
        c->gyro_max_rps = wmax > c->gyro_max_rps ? wmax : c->gyro_max_rps;
        if (wmax > FNAV_NAV_GYRO_MAX_RPS) {
            c->n_gyro_over++;
        } else if (wmax > c->gyro_max_in_rps) {
            c->gyro_max_in_rps = wmax;
        }
        {
            const double fn = sqrt((double)s->accel_mps2[0] * (double)s->accel_mps2[0] +
                                   (double)s->accel_mps2[1] * (double)s->accel_mps2[1] +
                                   (double)s->accel_mps2[2] * (double)s->accel_mps2[2]);
            c->f_norm_sum += fn;
            hx_walk_push(&c->walk, s->t_ns, fn);
            quiet_push(c, s, fn);
        }
        c->n_read++;
        if (c->probe != NULL && c->n_probe < HX_STAMPS_PROBE_N) {
            c->probe[c->n_probe++] = s->t_ns;
        }
        if (c->have_t_last && s->t_ns > c->t_last_ns) {
            c->stamp_res_ns = hx_gcd_i64(s->t_ns - c->t_last_ns, c->stamp_res_ns);
        }
        if (!c->have_t_last) {
            c->t_first_ns = s->t_ns;
        }
        c->t_last_ns = s->t_ns;
        c->have_t_last = 1;
        if (c->ev != NULL) {
            c->ev_last = *s;
            c->ev_have_last = 1;
        }
        if (c->axes != NULL) {
            hx_axes_sample(c->axes, s);
        }
        if (c->progress && (c->n_read & 1023) == 0) {
            /* resampled: samples of a known total; streamed: the fraction of
             * the input file consumed */
            double done = c->mem != NULL ? (double)c->n_read : hx_reader_progress(c->lctx.reader);
            if (done >= 0.0) {
                hx_progress_update(&c->prog, done);
            }
        }
    }
    return st;
}

static fnav_status_t hx_write(void *ctx, const fnav_nav_frame_t *f)
{
    hx_port_ctx_t *c = (hx_port_ctx_t *)ctx;
    hx_traj_t *t = c->traj;
    if (c->linux_port.write_nav(c->linux_port.ctx, f) != FNAV_OK) {
        c->sink_failed = 1;
        return FNAV_E_IO;
    }
    if (t != NULL) {
        if (t->n == t->cap) {
            size_t nc = t->cap ? 2 * t->cap : 16384;
            fnav_nav_frame_t *p = (fnav_nav_frame_t *)realloc(t->f, nc * sizeof *p);
            if (p == NULL) {
                c->traj_oom = 1;
                return FNAV_E_IO;
            }
            t->f = p;
            t->cap = nc;
        }
        t->f[t->n++] = *f;
        if (c->ev != NULL && !c->ev_bad) {
            ev_frame(c, f);
        }
    }
    if (c->axes != NULL) {
        hx_axes_frame(c->axes, f);
    }
    return FNAV_OK;
}

static int64_t hx_now(void *ctx)
{
    hx_port_ctx_t *c = (hx_port_ctx_t *)ctx;
    return c->linux_port.now_ns(c->linux_port.ctx);
}

static void hx_logmsg(void *ctx, fnav_log_level_t level, const char *msg)
{
    hx_port_ctx_t *c = (hx_port_ctx_t *)ctx;
    c->linux_port.log(c->linux_port.ctx, level, msg);
}

/* Input that is not in the SI units of docs/log-format.md navigates into
 * nonsense without any error of the reader: a log in g aligns on |f| = 1,
 * one in deg/s turns 57 times too fast, time in milliseconds makes 100 Hz
 * a 0.1 Hz log. Each leaves a mark no real foot-mounted IMU leaves. */
#define HX_GRAVITY_TOL ((double)FNAV_ALIGN_GRAVITY_TOL) /* |f| at rest within 25 % of gravity (the core's alignment refuses more) */
#define HX_GYRO_MAX_RPS 70.0   /* ~4000 deg/s: the widest range of MEMS gyros */
/* at most this fraction of the samples past FNAV_NAV_GYRO_MAX_RPS are
 * glitches, not a unit (a walk in deg/s read as rad/s has a fifth or more) */
#define HX_GYRO_GLITCH_FRAC 1e-3
/* The swapped-columns check: the gyro's steadiest second (sd / mean of |w|
 * under HX_SWAP_STEADY_CV) reads gravity within HX_SWAP_G_TOL (in g or in
 * m/s^2) while the accelerometer there reads under HX_SWAP_F_MAX_G g: a
 * gyro at rest reads about 0 and never so steady a magnitude */
#define HX_SWAP_STEADY_CV 0.05
#define HX_SWAP_G_TOL 0.2
#define HX_SWAP_F_MAX_G 0.2
#define HX_RATE_MIN_HZ 20.0    /* below this, no stance lasts more than a few samples */
/* A log shorter than this in the finer unit cannot hold a stride (a gait
 * cycle lasts about a second) after the alignment's still period: the
 * slow-rate remedy does not name a finer time unit that would make the
 * log so short (a walk resampled to 5 Hz is no 5 kHz log of 65 ms). A
 * longer slow log is judged by its motion instead (units_problem). */
#define HX_UNIT_MIN_SPAN_S 1.0
#define HX_ACCEL_MEAN_MAX_G 10.0 /* a foot's mean |f| over a log, in g, stays far below (the 66 shared walks and trials 1.0-2.0, the simulator's run 3.3) */
/* A walking foot turns at several rad/s in each swing: the largest |w| on
 * one axis is 6.2-24 rad/s over the shared walks that show a walk (hx_walk_t;
 * square2, which barely walks, 1.8) and 2.6 rad/s for the simulator's walk at
 * 30 steps/min, so 0.75 rad/s (43 deg/s) lies 8 times below the slowest
 * shared walk, 2.4 below square2 and 3.4 below the simulator's slowest. A
 * gyro in rad/s read as deg/s is 57.3 times too small: the shared walks read
 * 0.11-0.42 rad/s so, and any gyro within 43 rad/s stays under the mark */
#define HX_GYRO_WALK_MIN_RPS 0.75
/* The walk the mark needs (a static log's rates are small): one-second
 * windows of |f| whose standard deviation is 2 m/s^2 or more, at least 3 of
 * them; the shared walks have 14-91 (14-92 before HX_WALK_OFF_SHARE; their
 * quietest window of a stride 3.4 m/s^2 and up), the simulator's walk at 30
 * steps/min 5 in 30 s, a static log none (its noise: hundredths) */
#define HX_WALK_F_SD_MPS2 2.0
#define HX_WALK_WINDOWS 3L
#define HX_WALK_WINDOW_MIN_N 10L /* samples a window needs to count */
/* ... and its spread must last: a tenth of its samples or more 2 m/s^2 or
 * more off gravity (a swing's |f| stays off for a good part of it). A tap on
 * a static log (30 ms of 25 m/s^2: 3 % of its second) spreads a window by 4
 * m/s^2 too, and five synchronisation taps on a static log in deg/s, read
 * as such, would make replay exit 1 calling it a walk in rad/s */
#define HX_WALK_OFF_SHARE 0.1

void hx_walk_window(hx_walk_t *w, long n, double s, double s2, long n_off)
{
    if (n >= HX_WALK_WINDOW_MIN_N) {
        const double m = s / (double)n, var = s2 / (double)n - m * m;
        w->windows += var >= HX_WALK_F_SD_MPS2 * HX_WALK_F_SD_MPS2 && (double)n_off >= HX_WALK_OFF_SHARE * (double)n;
    }
}

int hx_walk_off(double f_norm_mps2)
{
    return fabs(f_norm_mps2 - 9.80665) >= HX_WALK_F_SD_MPS2;
}

void hx_walk_push(hx_walk_t *w, int64_t t_ns, double f_norm_mps2)
{
    if (w->open && (t_ns < w->t0_ns || t_ns - w->t0_ns >= 1000000000)) {
        if (t_ns >= w->t0_ns) {
            hx_walk_window(w, w->n, w->s, w->s2, w->n_off);
        }
        w->open = 0;
    }
    if (!w->open) {
        w->open = 1;
        w->t0_ns = t_ns;
        w->s = w->s2 = 0.0;
        w->n = w->n_off = 0;
    }
    w->n_off += hx_walk_off(f_norm_mps2);
    w->s += f_norm_mps2;
    w->s2 += f_norm_mps2 * f_norm_mps2;
    w->n++;
}

int hx_walk_seen(const hx_walk_t *w)
{
    return w != NULL && w->windows >= HX_WALK_WINDOWS;
}

/* The gyro mark: a walk (hx_walk_seen) whose gyro, read as deg/s by
 * --units gyro=deg/s, never reaches HX_GYRO_WALK_MIN_RPS */
static int gyro_rps_as_dps(const hx_csv_layout_t *csv, double gyro_max_rps, int walks)
{
    return walks && csv != NULL && csv->gyr_scale != 1.0 && gyro_max_rps > 0.0 &&
           gyro_max_rps < HX_GYRO_WALK_MIN_RPS;
}
/* A gyro read as mdps whose file values reach a walking foot's rates once
 * read as deg/s (HX_GYRO_WALK_MIN_RPS): a file in deg/s, not rad/s. */
static int gyro_file_dps(const hx_csv_layout_t *csv, double gyro_max_rps)
{
    return csv != NULL && csv->gyr_scale == HX_MDPS_RPS && gyro_max_rps / HX_MDPS_RPS * HX_DPS_RPS >= HX_GYRO_WALK_MIN_RPS;
}

/* The remedies for g and deg/s: want is the layout that reads the log (csv
 * with every unit item the marks found), named whole by hx_units_give when
 * the item was not given; a unit already given, or csv NULL, keeps the
 * arithmetic. */
static const char *fix_g(const hx_csv_layout_t *csv, const hx_csv_layout_t *want, char *buf, size_t size)
{
    if (csv != NULL && csv->acc_scale == 1.0) {
        return hx_units_give(want, buf, size);
    }
    snprintf(buf, size, "multiply by 9.80665");
    return buf;
}

static const char *fix_dps(const hx_csv_layout_t *csv, const hx_csv_layout_t *want, char *buf, size_t size)
{
    if (csv != NULL && csv->gyr_scale == 1.0) {
        return hx_units_give(want, buf, size);
    }
    snprintf(buf, size, "multiply by pi/180");
    return buf;
}

const char *hx_units_fix_dps(const hx_csv_layout_t *csv, char *buf, size_t size)
{
    hx_csv_layout_t want;
    if (csv != NULL) {
        want = *csv;
        want.gyr_scale = M_PI / 180.0;
    }
    return fix_dps(csv, csv != NULL ? &want : NULL, buf, size);
}

/* An accelerometer is judged on the file's values, before --units accel=
 * scaled them: mg read as g are 1000 times too large (the mg mark missed
 * them: "raw counts?" or no unit at all), and their remedy names the unit
 * they are in. */
static double acc_read_scale(const hx_csv_layout_t *csv)
{
    return csv != NULL ? csv->acc_scale : 1.0;
}

/* The unit the file's accelerations are in, by |f| at rest as read: the
 * scale (m/s^2 per unit: 1, HX_G_MPS2, HX_MG_MPS2, HX_UG_MPS2) that makes
 * the file's value gravity within HX_GRAVITY_TOL; 0 when none does. The
 * bands (file values 7.4-12.3, 0.75-1.25, 750-1250, 7.5e5-1.25e6) do not
 * overlap: the units lie 9.8 and 1000 times apart, the band is 1.67 wide.
 * ug has its band, so a file in ug is told its unit, not only "not in
 * m/s^2" */
static double acc_file_scale(const hx_csv_layout_t *csv, double f_rest_mps2, double g)
{
    static const double k_scale[4] = { 1.0, HX_G_MPS2, HX_MG_MPS2, HX_UG_MPS2 };
    size_t i;
    for (i = 0; i < 4u; i++) {
        if (fabs(f_rest_mps2 / acc_read_scale(csv) * k_scale[i] / g - 1.0) < HX_GRAVITY_TOL) {
            return k_scale[i];
        }
    }
    return 0.0;
}

/* The remedy for accelerations whose file unit is file_scale (want: the
 * layout that reads the log, units_want): for the interchange CSV the whole
 * --units value (the unit given named first: "read as g by --units accel=g:
 * give --units accel=mg", not "divide by 1000"), or the item given left out for a file
 * in m/s^2; for another format (csv NULL) the arithmetic. */
static const char *acc_fix(const hx_csv_layout_t *csv, const hx_csv_layout_t *want, double file_scale, char *buf,
                           size_t size)
{
    char give[96];
    const char *given = hx_accel_unit_name(acc_read_scale(csv));
    if (csv == NULL) {
        snprintf(buf, size, "multiply by %s",
                 file_scale == HX_UG_MPS2   ? "9.80665e-6"
                 : file_scale == HX_MG_MPS2 ? "0.00980665"
                                            : "9.80665");
    } else if (file_scale == 1.0) {
        snprintf(buf, size, "read as %s by --units accel=%s: leave accel=%s out", given, given, given);
    } else if (csv->acc_scale == 1.0) {
        hx_units_give(want, buf, size);
    } else {
        snprintf(buf, size, "read as %s by --units accel=%s: %s", given, given, hx_units_give(want, give, sizeof give));
    }
    return buf;
}

/* The layout that reads the log, for the remedies of units_problem: csv
 * with the unit items of every mark found, as units_problem judges them
 * (acc_mean: the file unit the mean |f| of units_check found, HX_G_MPS2,
 * HX_MG_MPS2, HX_UG_MPS2 or 1 for m/s^2 read in another unit; 0 none), so that each remedy
 * names the whole --units value. csv NULL: none (want untouched). */
static void units_want(const hx_csv_layout_t *csv, double f_rest_mps2, double g, double gyro_max_rps,
                       double rate_hz, double acc_mean, int walks, hx_csv_layout_t *want)
{
    hx_time_fix_t tf;
    if (csv == NULL) {
        return;
    }
    *want = *csv;
    if (acc_mean == HX_G_MPS2 && csv->acc_scale == 1.0) {
        want->acc_scale = HX_G_MPS2;
    } else if (acc_mean == HX_MG_MPS2 || acc_mean == HX_UG_MPS2 || acc_mean == 1.0) {
        want->acc_scale = acc_mean;
    } else if (f_rest_mps2 > 0.0 && fabs(f_rest_mps2 / g - 1.0) > HX_GRAVITY_TOL &&
               acc_file_scale(csv, f_rest_mps2, g) > 0.0) {
        /* the unit the file's values are in (g, mg, or m/s^2 read as g or
         * mg: the item left out), whatever was given */
        want->acc_scale = acc_file_scale(csv, f_rest_mps2, g);
    }
    if (gyro_max_rps > HX_GYRO_MAX_RPS && gyro_max_rps * M_PI / 180.0 < HX_GYRO_MAX_RPS && csv->gyr_scale == 1.0) {
        want->gyr_scale = M_PI / 180.0;
    } else if (gyro_max_rps > HX_GYRO_MAX_RPS && gyro_max_rps * HX_MDPS_RPS < HX_GYRO_MAX_RPS &&
               csv->gyr_scale == 1.0) {
        want->gyr_scale = HX_MDPS_RPS;
    }
    if (gyro_rps_as_dps(csv, gyro_max_rps, walks)) {
        /* the remedy leaves gyro=deg/s out, or names deg/s for a file in
         * deg/s read as mdps */
        want->gyr_scale = gyro_file_dps(csv, gyro_max_rps) ? HX_DPS_RPS : 1.0;
    }
    if (((rate_hz > 0.0 && rate_hz < HX_RATE_MIN_HZ) || rate_hz > HX_TIME_RATE_MAX_HZ) &&
        hx_time_unit_fix(rate_hz, csv->time_digits, &tf)) {
        want->time_digits = tf.digits;
    }
}


const hx_csv_layout_t *hx_units_want(const hx_csv_layout_t *csv, double f_rest_mps2, double gravity_mps2,
                                     double gyro_max_rps, hx_csv_layout_t *buf)
{
    if (csv == NULL) {
        return NULL;
    }
    units_want(csv, f_rest_mps2, gravity_mps2, gyro_max_rps, 0.0, 0, 0, buf);
    return buf;
}

static int units_problem(double f_rest_mps2, double gravity_mps2, double gyro_max_rps, double rate_hz,
                         double span_s, const hx_csv_layout_t *csv, double acc_mean, int walks, char *msg,
                         size_t msg_size)
{
    /* every mistake found is named (a log in g and deg/s names both) */
    double g = gravity_mps2;
    size_t len = 0;
    int n = 0;
    hx_csv_layout_t want;
    char give[128]; /* a remedy: "read as mg by --units accel=mg: give --units time=ms,accel=g,gyro=deg/s" */
    units_want(csv, f_rest_mps2, g, gyro_max_rps, rate_hz, acc_mean, walks, &want);
    msg[0] = '\0';
#define HX_UNITS_ADD(...)                                                                                  \
    do {                                                                                                   \
        if (len < msg_size) {                                                                              \
            int w_ = snprintf(msg + len, msg_size - len, "%s", n > 0 ? "; also " : "");                   \
            len += w_ > 0 ? (size_t)w_ : 0u;                                                               \
        }                                                                                                  \
        if (len < msg_size) {                                                                              \
            int w_ = snprintf(msg + len, msg_size - len, __VA_ARGS__);                                     \
            len += w_ > 0 ? (size_t)w_ : 0u;                                                               \
        }                                                                                                  \
        n++;                                                                                               \
    } while (0)
    if (f_rest_mps2 > 0.0 && fabs(f_rest_mps2 / g - 1.0) > HX_GRAVITY_TOL) {
        char fix[192] = "";
        const double file = acc_file_scale(csv, f_rest_mps2, g);
        if (file == 1.0) {
            /* the file in m/s^2 read as g: 9.8 times gravity (named as such,
             * not "not in m/s^2" of a file that is) */
            snprintf(fix, sizeof fix, "in m/s^2 already (%s)", acc_fix(csv, &want, file, give, sizeof give));
        } else if (file > 0.0) {
            snprintf(fix, sizeof fix, "not in m/s^2 but in %s (%s)", hx_accel_unit_name(file),
                     acc_fix(csv, &want, file, give, sizeof give));
        } else if (fabs(f_rest_mps2 * HX_G_MPS2 / g - 1.0) < HX_GRAVITY_TOL) {
            /* in g as read, with a unit given (values in g / 9.80665 read
             * as g): the arithmetic on top of it */
            snprintf(fix, sizeof fix, "not in m/s^2 but in g (%s)", fix_g(csv, &want, give, sizeof give));
        } else if (f_rest_mps2 < HX_NO_GRAVITY_MPS2) {
            /* no unit makes gravity so small: a linear acceleration
             * (Android's linear acceleration sensor, iOS's userAcceleration,
             * which phone apps write beside or instead of the accelerometer) */
            snprintf(fix, sizeof fix, "without gravity: a linear acceleration (gravity removed), not the "
                                      "accelerometer's own reading, the specific force, which the filter needs");
        } else {
            snprintf(fix, sizeof fix, "not in m/s^2");
        }
        HX_UNITS_ADD("the accelerometer reads |f| = %.4g at rest, where gravity is %.4g m/s^2: the log is %s",
                     f_rest_mps2, g, fix);
    }
    if (gyro_max_rps > HX_GYRO_MAX_RPS && csv != NULL && csv->gyr_scale != 1.0) {
        /* read in a unit given or named (deg/s, mdps): beyond any gyro
         * in that unit too, so no other unit of --units explains it (told
         * "not in rad/s but probably in deg/s" with gyro=deg/s given, a
         * user went round in a circle: raw int16 counts, 16.4 a deg/s) */
        const char *u = hx_gyro_unit_name(csv->gyr_scale);
        const double in_unit = gyro_max_rps / csv->gyr_scale;
        if (csv->gyr_scale == HX_DPS_RPS && in_unit > 32768.0 && gyro_max_rps * 1e-3 < HX_GYRO_MAX_RPS) {
            /* beyond any 16-bit count, and within range a thousand times
             * smaller: mdps read as deg/s (int16 counts stop at 32767) */
            HX_UNITS_ADD("the gyroscope reaches %.4g rad/s on one axis read as deg/s (%.4g deg/s), beyond the "
                         "range of any MEMS gyro (about %.0f rad/s = 4000 deg/s per axis): the log is in mdps? "
                         "(read as deg/s by --units gyro=deg/s: give --units gyro=mdps)",
                         gyro_max_rps, in_unit, HX_GYRO_MAX_RPS);
        } else if (csv->gyr_scale != HX_DPS_RPS && csv->gyr_scale != HX_MDPS_RPS) {
            /* a count's size given (gyro=8.75mdps): the size is wrong, not
             * the unit ("(1234 8.75mdps)", "raw counts?" of counts) */
            HX_UNITS_ADD("the gyroscope reaches %.4g rad/s on one axis read with the count's size %s (%.4g counts), "
                         "beyond the range of any MEMS gyro (about %.0f rad/s = 4000 deg/s per axis): is the count's "
                         "size the datasheet's sensitivity for the range the sensor was set to?",
                         gyro_max_rps, u, in_unit, HX_GYRO_MAX_RPS);
        } else {
            HX_UNITS_ADD("the gyroscope reaches %.4g rad/s on one axis read as %s (%.4g %s), beyond the range of "
                         "any MEMS gyro (about %.0f rad/s = 4000 deg/s per axis): raw counts? (give a count's size, "
                         "the datasheet's sensitivity: --units gyro=70mdps for 70 mdps per LSB)",
                         gyro_max_rps, u, in_unit, u, HX_GYRO_MAX_RPS);
        }
    } else if (gyro_max_rps > HX_GYRO_MAX_RPS) {
        char fix[192] = "";
        if (gyro_max_rps * M_PI / 180.0 < HX_GYRO_MAX_RPS) {
            snprintf(fix, sizeof fix, " but probably in deg/s (%s)", fix_dps(csv, &want, give, sizeof give));
        } else if (gyro_max_rps * HX_MDPS_RPS < HX_GYRO_MAX_RPS) {
            /* mdps (ST's SensorTile data log): named, not "not in rad/s"
             * alone */
            if (csv != NULL && csv->gyr_scale == 1.0) {
                hx_units_give(&want, give, sizeof give);
            } else {
                snprintf(give, sizeof give, "multiply by pi/180000");
            }
            snprintf(fix, sizeof fix, ": in mdps? (%s)", give);
        }
        HX_UNITS_ADD("the gyroscope reaches %.4g rad/s on one axis (its largest |w| on a single axis), beyond the "
                     "range of any MEMS gyro (about %.0f rad/s = 4000 deg/s per axis): the log is not in rad/s%s",
                     gyro_max_rps, HX_GYRO_MAX_RPS, fix);
    }
    if (gyro_rps_as_dps(csv, gyro_max_rps, walks)) {
        /* not silent: it would exit 0 with a walk navigated with rates 57.3
         * times too small. Read as mdps, a file in deg/s is too small as
         * well: told gyro=deg/s (gyro_file_dps) */
        const char *given = hx_gyro_unit_name(csv->gyr_scale);
        if (csv->gyr_scale != HX_DPS_RPS && csv->gyr_scale != HX_MDPS_RPS) {
            /* a count's size given: too small a size, not a unit */
            HX_UNITS_ADD("the gyroscope never exceeds %.3g rad/s on one axis while the log walks (|f| spreads by "
                         "%.0f m/s^2 or more within a second), where a walking foot turns at several rad/s in each "
                         "swing, read with the count's size %s: is it the datasheet's sensitivity for the range the "
                         "sensor was set to?",
                         gyro_max_rps, HX_WALK_F_SD_MPS2, given);
        } else if (gyro_file_dps(csv, gyro_max_rps)) {
            HX_UNITS_ADD("the gyroscope never exceeds %.3g rad/s on one axis while the log walks (|f| spreads by "
                         "%.0f m/s^2 or more within a second), where a walking foot turns at several rad/s in each "
                         "swing: the log is in deg/s? (read as %s by --units gyro=%s: %s)",
                         gyro_max_rps, HX_WALK_F_SD_MPS2, given, given, hx_units_give(&want, give, sizeof give));
        } else {
            HX_UNITS_ADD("the gyroscope never exceeds %.3g rad/s on one axis while the log walks (|f| spreads by "
                         "%.0f m/s^2 or more within a second), where a walking foot turns at several rad/s in each "
                         "swing: the log is in rad/s already? (read as %s by --units gyro=%s: leave gyro=%s out)",
                         gyro_max_rps, HX_WALK_F_SD_MPS2, given, given, given);
        }
    }
    if (rate_hz > 0.0 && rate_hz < HX_RATE_MIN_HZ) {
        /* the unit that makes the rate one a foot-mounted IMU has (20 Hz to
         * 100 kHz): 2.5 ms read as 2.5 s (ms), as 2511 s (us), as 2.5e6 s
         * (ns): the remedy names that unit, not always milliseconds. The
         * interchange CSV's remedy is --units time=, counted from the unit
         * it was read in (us read as ms look like ms: time=us;
         * hx_time_unit_fix, as the slow-log hint of info, allan and psd) */
        const int k = csv != NULL ? csv->time_digits : 9; /* the unit the stamps were read in */
        hx_time_fix_t fix;
        if (hx_time_unit_fix(rate_hz, k, &fix) && span_s > 0.0 &&
            (span_s * rate_hz / fix.rate_hz < HX_UNIT_MIN_SPAN_S || walks)) {
            /* in the finer unit the log would be over before a stride, or
             * it walks as read (|f| spreads within its seconds, which a
             * log in ms read as s, one sample to a second, cannot): the
             * stamps are what they say, the log too slow (a walk
             * resampled to 5 Hz was sent to --units time=ms, which read
             * it as 65 ms at 5 kHz and found no still period). The walk
             * test needs 10 samples a second (HX_WALK_WINDOW_MIN_N): a
             * walk under 10 Hz and over 1000 s still gets the ms remedy */
            char why[160];
            if (span_s * rate_hz / fix.rate_hz < HX_UNIT_MIN_SPAN_S) {
                snprintf(why, sizeof why, "in %s the %.4g s log would last %.3g s, too short for a walk", fix.name,
                         span_s, span_s * rate_hz / fix.rate_hz);
            } else {
                snprintf(why, sizeof why, "it walks as read, |f| varying within its seconds, which %s read as %s, "
                                          "a sample to a second, could not",
                         fix.name, fix.read);
            }
            HX_UNITS_ADD("the samples are %.4g s apart (%.3g Hz); a foot-mounted IMU needs %.0f Hz or more, and the "
                         "stamps are in %s (%s): the log is too slow to navigate (record a walking foot at 100 Hz or "
                         "more)",
                         1.0 / rate_hz, rate_hz, HX_RATE_MIN_HZ, fix.read, why);
        } else if (hx_time_unit_fix(rate_hz, k, &fix)) {
            /* 1 s apart: 1 kHz in milliseconds, or a sample number (a
             * logger's counter), which --input-rate serves without the
             * column */
            if (csv != NULL) {
                hx_units_give(&want, give, sizeof give);
            } else {
                snprintf(give, sizeof give, "divide by %s", fix.div);
            }
            HX_UNITS_ADD("the samples are %.4g s apart (%.3g Hz); a foot-mounted IMU needs %.0f Hz or more: are the "
                         "time stamps in %s? (they look like %s: %s%s)",
                         1.0 / rate_hz, rate_hz, HX_RATE_MIN_HZ, fix.read, fix.name, give,
                         fabs(rate_hz - 1.0) < 1e-9 ? "; or, if they count samples, leave the column out and give the "
                                                      "rate with --input-rate HZ"
                                                    : "");
        } else if (k != 9) {
            /* read by --units time= in a finer unit than seconds, and too
             * slow for any unit finer still (5 Hz read as ns): the question
             * and the remedy name the unit given, not seconds and
             * milliseconds */
            HX_UNITS_ADD("the samples are %.4g s apart (%.3g Hz); a foot-mounted IMU needs %.0f Hz or more: are the "
                         "time stamps in %s? (read so by --units time=%s; no finer unit makes the rate 20 Hz to "
                         "100 kHz)",
                         1.0 / rate_hz, rate_hz, HX_RATE_MIN_HZ, fix.read, k == 6 ? "ms" : k == 3 ? "us" : "ns");
        } else {
            HX_UNITS_ADD("the samples are %.4g s apart (%.3g Hz); a foot-mounted IMU needs %.0f Hz or more: are the "
                         "time stamps in seconds? (in milliseconds, %s)",
                         1.0 / rate_hz, rate_hz, HX_RATE_MIN_HZ, csv != NULL ? "give --units time=ms" : "divide by 1000");
        }
    }
    if (rate_hz > HX_TIME_RATE_MAX_HZ) {
        /* stamps read by --units time= in a finer unit than theirs (ms read
         * as ns: 1e6 times too fast), said as such rather than only as a cut
         * detector ring and no still period. Nothing is coarser than
         * seconds: only a unit given can be too fine */
        hx_time_fix_t fix;
        if (hx_time_unit_fix(rate_hz, csv != NULL ? csv->time_digits : 9, &fix)) {
            HX_UNITS_ADD("the samples are %.4g s apart (%.3g Hz); a foot-mounted IMU samples at %.0f kHz at most: "
                         "are the time stamps in %s? (they look like %s: %s)",
                         1.0 / rate_hz, rate_hz, 1e-3 * HX_TIME_RATE_MAX_HZ, fix.read, fix.name,
                         hx_units_give(&want, give, sizeof give));
        }
    }
#undef HX_UNITS_ADD
    if (n > 0 && len < msg_size) {
        snprintf(msg + len, msg_size - len, " (docs/log-format.md)");
    }
    return n > 0;
}

int hx_gyro_glitches(long n_over, long n)
{
    return n_over > 0 && (double)n_over <= HX_GYRO_GLITCH_FRAC * (double)n;
}

int hx_units_problem(double f_rest_mps2, double gravity_mps2, double gyro_max_rps, double rate_hz,
                     const hx_csv_layout_t *csv, int walks, char *msg, size_t msg_size)
{
    return units_problem(f_rest_mps2, gravity_mps2, gyro_max_rps, rate_hz, 0.0, csv, 0, walks, msg, msg_size);
}

/* The remedy for time stamps coarser than the sampling (hx_nav_coarse_stamps),
 * one text for the units error and the summary's note: for the interchange
 * CSV more digits or no time column; for any other format (a .bin, an
 * importer's log: no time column to leave out, --input-rate ignored or
 * only rescaling a counter) the conversion to CSV without it, as for stamps
 * in bursts (hx_bursts_remedy). */
static const char *coarse_stamps_remedy(hx_format_t fmt)
{
    return fmt == HX_FMT_CSV || fmt == HX_FMT_AUTO
               ? "write the stamps with more digits, or leave the time column out and give the rate with "
                 "--input-rate HZ (docs/log-format.md, \"CSV interchange\")"
               : HX_CONVERT_REMEDY("the rate with --input-rate HZ") " (docs/harness.md, \"Time stamps in bursts\")";
}

/* 2 when the replayed log is not in SI units (err says why, without the
 * log's name: the JSON's units_problem), else 0. csv: as hx_units_problem's. */
static int units_check(const fnav_nav_t *nav, double gyro_max_rps, double quiet_w, double quiet_f, double quiet_cv,
                       double f_norm_mean, int walks,
                       double in_rate_hz, size_t n_in, int64_t t_first_ns, int64_t t_last_ns,
                       const hx_csv_layout_t *csv, hx_format_t fmt, char *err, size_t err_size)
{
    char msg[768], acc[420] = "", rep[448] = ""; /* acc + "; also " + msg fit the summary's units_problem */
    const double g = (double)nav->cfg.gravity_mps2;
    double rate;
    /* |f| at rest: the alignment's, or that of a still period it refused
     * for being off gravity (FNAV_ALIGN_GRAVITY_TOL) */
    const double fn = nav->aligned ? (double)fnav_vec3_norm(nav->align.result.accel_mean_mps2)
                                   : (double)nav->align.refused_f_mps2;
    const int acc_in_g = !nav->aligned && fn == 0.0 && f_norm_mean > 0.0 && f_norm_mean < 0.5 * g;
    /* the file's unit the mean |f| found (units_want): g, or, above
     * HX_ACCEL_MEAN_MAX_G, mg, ug or m/s^2 read in another unit (0: none) */
    double acc_mean = acc_in_g ? HX_G_MPS2 : 0.0;
    int bad;
    if (!nav->aligned && !(f_norm_mean > 1e-6 * g)) {
        /* no specific force at all: not a unit but a dead channel */
        snprintf(err, err_size, "the accelerometer reads %s throughout: disconnected, or its columns missing?",
                 f_norm_mean > 0.0 ? "almost 0" : "0");
        return 2;
    }
    rate = in_rate_hz > 0.0 ? in_rate_hz : (double)nav->stance.rate_hz;
    if (hx_nav_coarse_stamps(&nav->stats) && rate > 0.0 && rate < HX_RATE_MIN_HZ) {
        /* a low rate from stamps that repeat is no unit (float32 seconds
         * at 1e6 s step by 62.5 ms: "16 Hz", whose unit remedy would read
         * "divide by 1000") */
        snprintf(rep, sizeof rep,
                 "%.1f %% of the samples repeat the time stamp before them, which advance by %.4g s: %.3g Hz from "
                 "the stamps, too coarse for the sampling (float32 seconds far from 0?): %s",
                 100.0 * (double)nav->stats.duplicates / (double)nav->stats.samples, 1.0 / rate, rate,
                 coarse_stamps_remedy(fmt));
        rate = 0.0;
    }
    /* intervals too short (or too long), but not the log's span for its
     * samples: stamps taken in bursts (a logger stamping a batch of samples
     * as it reads them, microseconds apart), which no unit explains; the
     * time error needs both (else such a log would get a coarser unit
     * that makes it 1000 times too slow). The test of info, allan, psd and simgap too
     * (hx_time_unit_rate); after the repeated stamps' test, whose slow rate
     * the span does not explain either */
    rate = hx_time_unit_rate(rate, n_in, t_first_ns, t_last_ns);
    if (acc_in_g) {
        /* no rest found (a gyro in deg/s hides every still period): the
         * mean |f| of the whole log stands in, but only to reveal a log in
         * g; a walk in m/s^2 averages g or more (its motion adds to |f|).
         * Its remedy names the other items found too (units_want) */
        hx_csv_layout_t want;
        char give[64];
        units_want(csv, fn, g, gyro_max_rps, rate, acc_mean, walks, &want);
        snprintf(acc, sizeof acc,
                 "the accelerometer averages |f| = %.4g over the log, where one in m/s^2 averages %.4g or more: "
                 "the log is probably in g (%s)",
                 f_norm_mean, g, fix_g(csv, &want, give, sizeof give));
    }
    if (!nav->aligned && fn == 0.0 && f_norm_mean > HX_ACCEL_MEAN_MAX_G * g) {
        /* no rest found, and a mean |f| no foot reaches: mg, ug, cm/s^2 or
         * raw counts, whose noise also hides every still period (said so,
         * not only "no still period") */
        const double in_g = f_norm_mean / acc_read_scale(csv) * 0.00980665 / g; /* the file's values in mg */
        const int mg = in_g > 0.75 && in_g < HX_ACCEL_MEAN_MAX_G;
        /* the file's values in ug (the same 0.75-10 g band: 7.5e5-1e7 in
         * the file, above mg's 750-1e4; named, not "raw counts?") */
        const double in_g_ug = f_norm_mean / acc_read_scale(csv) * HX_UG_MPS2 / g;
        const int ug = in_g_ug > 0.75 && in_g_ug < HX_ACCEL_MEAN_MAX_G;
        /* the file's values in m/s^2, read as g (a foot's mean: 0.75-10 g,
         * as the mg mark's; named, not "raw counts?") */
        const double in_mps2 = f_norm_mean / acc_read_scale(csv) / g;
        const int msq = acc_read_scale(csv) != 1.0 && in_mps2 > 0.75 && in_mps2 < HX_ACCEL_MEAN_MAX_G;
        hx_csv_layout_t want;
        char fix[128] = "";
        /* the remedy names the other items found too (units_want), with
         * the accelerometer's unit the file's; so do the others */
        acc_mean = msq ? 1.0 : mg ? HX_MG_MPS2 : ug ? HX_UG_MPS2 : 0.0;
        units_want(csv, fn, g, gyro_max_rps, rate, acc_mean, walks, &want);
        if (msq || mg || ug) {
            acc_fix(csv, &want, acc_mean, fix, sizeof fix);
        }
        snprintf(acc, sizeof acc,
                 "the accelerometer averages |f| = %.4g over the log, where one in m/s^2 on a foot averages a few "
                 "times %.4g at most: the log is %s%s%s",
                 f_norm_mean, g,
                 msq  ? "in m/s^2 already? ("
                 : mg ? "not in m/s^2: in mg? ("
                 : ug ? "not in m/s^2: in ug? ("
                      : "not in m/s^2: raw counts? (give a count's size, the datasheet's sensitivity: --units "
                        "accel=0.061mg for 0.061 mg per LSB)",
                 fix, msq || mg || ug ? ")" : "");
    }
    bad = units_problem(fn, g, gyro_max_rps, rate, n_in > 1 ? 1e-9 * (double)(t_last_ns - t_first_ns) : 0.0, csv,
                        acc_mean, walks, msg, sizeof msg);
    if (rep[0] != '\0') {
        size_t len = strlen(msg);
        if (len < sizeof msg) {
            snprintf(msg + len, sizeof msg - len, "%s%s", bad ? "; also " : "", rep);
        }
        bad = 1;
    }
    if (quiet_w > 0.0 && quiet_cv < HX_SWAP_STEADY_CV && quiet_f < HX_SWAP_F_MAX_G * g &&
        (fabs(quiet_w - 1.0) < HX_SWAP_G_TOL || fabs(quiet_w / g - 1.0) < HX_SWAP_G_TOL)) {
        /* the gyro's steadiest second reads gravity, and the accelerometer
         * there about nothing: the columns are swapped (six bare numbers a
         * line with the gyro first, read as the OpenShoe set's; a header
         * matched wrongly). Said first, the unit findings after it */
        char swp[400];
        snprintf(swp, sizeof swp,
                 "the gyroscope reads a steady |w| = %.3g in the log's steadiest second (spread %.1f %%), as an "
                 "accelerometer at rest reads gravity%s, and the accelerometer %.3g there: the accelerometer and "
                 "gyroscope columns swapped? (read each from the other's: --columns, or for six bare numbers a line "
                 "with the gyro first --from csv --columns gx=1,gy=2,gz=3,ax=4,ay=5,az=6 --input-rate HZ)",
                 quiet_w, 100.0 * quiet_cv, fabs(quiet_w - 1.0) < HX_SWAP_G_TOL ? " in g" : "", quiet_f);
        {
            /* swp, then the unit findings, each after "; also " (pieces
             * appended within err_size: one format of all would be cut) */
            const char *piece[3];
            size_t len, np = 0, i;
            piece[np++] = swp;
            if (acc[0] != '\0') {
                piece[np++] = acc;
            }
            if (bad) {
                piece[np++] = msg;
            }
            err[0] = '\0';
            for (i = 0; i < np; i++) {
                len = strlen(err);
                if (len + 1 < err_size) {
                    snprintf(err + len, err_size - len, "%s%s", i > 0 ? "; also " : "", piece[i]);
                }
            }
            len = strlen(err);
            if (np == 1 && len + 1 < err_size) {
                snprintf(err + len, err_size - len, " (docs/log-format.md)");
            }
        }
        return 2;
    }
    if (acc[0] != '\0') {
        /* in pieces, within err_size (one format of all would be cut) */
        size_t len;
        snprintf(err, err_size, "%s%s", acc, bad ? "; also " : " (docs/log-format.md)");
        len = strlen(err);
        if (bad && len < err_size) {
            snprintf(err + len, err_size - len, "%s", msg);
        }
        return 2;
    }
    if (bad) {
        snprintf(err, err_size, "%s", msg);
        return 2;
    }
    return 0;
}

/* Every sample the navigator took at one time: no interval to integrate or
 * to measure stillness over, so no alignment (the replay's error and the
 * summary's alignment line both name it). */
static int stamps_never_advance(const fnav_nav_stats_t *st)
{
    return st->samples > 1u && st->duplicates + 1u >= st->samples;
}

int hx_nav_bursts_warn(const char *cmd, const char *path, hx_format_t fmt, const int64_t *t_ns, size_t n,
                       int first, const char *reads, double rate_hz, int nominal)
{
    /* info, psd and allan take 1 / the median interval of such stamps
     * (200 kHz for a 400 Hz walk) as the rate; they still run, with this
     * warning, which says which rate they use and where it came from */
    hx_bursts_t bu;
    char msg[640];
    if (hx_stamp_bursts(t_ns, n, (double)fnav_nav_config_default.max_gap_s, &bu) <= 0) {
        return 0;
    }
    bu.first = first;
    bu.format = fmt;
    hx_warn(cmd, "%s: %s", path, hx_bursts_rate_text(&bu, reads, rate_hz, nominal, msg, sizeof msg));
    return 1;
}

int hx_stated_rate_warn(const char *cmd, const char *path, const hx_meta_t *meta, const int64_t *t_ns, size_t n,
                        const char *reads)
{
    /* info's (1000 Hz stated over stamps 5 ms apart would go without a
     * word, and the search for the rest would take windows of 1000 samples,
     * 5 s of that 200 Hz log); psd's and allan's too, which read their
     * frequencies and tau at that rate */
    double hz;
    if (meta == NULL || t_ns == NULL || !meta->rate_nominal || meta->stamps_made || !(meta->rate_hz > 0.0) ||
        n < 2u) {
        return 0;
    }
    hz = hx_stamp_rate_hz(t_ns, n < 4096u ? n : (size_t)4096, NULL);
    if (!(hz > 0.0) || fabs(meta->rate_hz / hz - 1.0) <= HX_STATED_RATE_TOL) {
        return 0;
    }
    hx_warn(cmd,
            "%s: the file states %.6g Hz, but its time stamps give %.6g Hz (%.3f ms apart): %s the stated rate; if "
            "the stamps are right, convert it to CSV (bin/harness convert %s out.csv), whose rate comes from its "
            "stamps (docs/harness.md, \"info\")",
            path, meta->rate_hz, hz, 1e3 / hz, reads, path);
    return 1;
}

/* Replay's warning for distinct time stamps in bursts of the other kind
 * than hx_nav_stamps_check refuses: more samples than the median interval
 * gives over the span, with no stamp repeated to explain them (a logger
 * stamping each pair of 200 Hz samples 0.1 ms apart every 10 ms). The
 * stance detector then takes 1 / the median of its first intervals (101
 * Hz for that log, a 3-sample window where 200 Hz gives 5); info, allan
 * and psd warn too. Samples that share
 * one stamp (the duplicates explain the count) keep the coarse-stamps note
 * of the summary. t_ns: the first n stamps read; first: the log
 * went on past them; det_hz: the detector's rate. 1 when warned. */
static int pairs_warn(const char *cmd, const char *path, hx_format_t fmt, const int64_t *t_ns, size_t n, int first,
                      double max_gap_s, double det_hz)
{
    hx_bursts_t bu;
    char msg[640];
    if (t_ns == NULL || n < 2u || hx_stamp_bursts(t_ns, n, max_gap_s, &bu) != HX_BURSTS_SHARED) {
        return 0;
    }
    /* hx_stamp_bursts's SHARED test over the distinct stamps alone */
    if (!((double)bu.distinct > 1.5 * (bu.span_s * bu.median_hz + (double)bu.segs))) {
        return 0;
    }
    bu.first = first;
    bu.format = fmt;
    hx_warn(cmd, "%s: %s", path, hx_bursts_rate_text(&bu, "the stance detector takes", det_hz, 0, msg, sizeof msg));
    return 1;
}

int hx_nav_stamps_check(const char *path, hx_format_t fmt, double in_rate, double max_gap_s, char *err,
                        size_t err_size)
{
    /* Stamps in bursts make the detector's rate 1 / their median interval
     * (5 us: "200 kHz") and the navigation meaningless: plain replay refuses
     * such a walk as --rate does (it would run with exit 0 and 0 strides).
     * The log's first HX_STAMPS_PROBE_N stamps, read before the run: the
     * detector's rate comes from its first intervals, so the whole log is
     * neither read twice nor its stamps held; a read error stops the
     * collection there, and the replay reports it. */
    hx_reader_t *r = hx_reader_open(path, fmt, in_rate, err, err_size);
    int64_t *t;
    size_t n = 0;
    fnav_sample_t s;
    hx_bursts_t bu;
    hx_format_t read_fmt;
    int kind, rc = 0, more = 0;
    err[0] = '\0';
    if (r == NULL) {
        return 0; /* the replay's own open says why */
    }
    t = (int64_t *)malloc(HX_STAMPS_PROBE_N * sizeof *t);
    if (t == NULL) {
        hx_reader_close(r);
        return 0; /* no check: the replay runs as before */
    }
    memset(&s, 0, sizeof s);
    while ((more = hx_reader_next(r, &s) == FNAV_OK) != 0 && n < HX_STAMPS_PROBE_N) {
        t[n++] = s.t_ns;
    }
    read_fmt = hx_reader_meta(r)->format; /* fmt may be HX_FMT_AUTO */
    hx_reader_close(r);
    kind = hx_stamp_bursts(t, n, max_gap_s, &bu);
    bu.first = more; /* the log goes on past the stamps tested */
    bu.format = read_fmt;
    if (kind == HX_BURSTS_CLOSE) {
        char why[640];
        snprintf(err, err_size, "%s: %s", path,
                 hx_bursts_text(&bu, "navigation needs each sample's own time", "Time stamps in bursts", why,
                                sizeof why));
        rc = -1;
    }
    free(t);
    return rc;
}

/* The gait cycles of the frames kept, s, in order (*k of them; NULL with
 * *k = 0 when there are none to keep or memory runs out; the caller frees):
 * from one onset of the foot's motion to the next (the detector's stance
 * flag, over every frame: a compressed time axis shows before the alignment
 * too), counting a motion that lasts HX_NAV_CYCLE_MOTION_S or more: the
 * strides would not do, since a swing compressed below min_swing_s makes
 * none. A stance shorter than HX_NAV_CYCLE_MOTION_S ends no motion: a slow
 * walk's swing broken by a 15 ms stance would count as two cycles, 0.39 s
 * of 2 s. */
static double *cycle_intervals(const hx_traj_t *t, size_t *k)
{
    double *iv = t->n > 0u ? (double *)malloc((t->n / 2u + 1u) * sizeof *iv) : NULL;
    size_t i, run0 = 0, still0 = 0;
    int64_t onset = 0;
    int have = 0, moving = 0, pause = 0;
    *k = 0;
    for (i = 0; iv != NULL && i <= t->n; i++) {
        const int still = i == t->n || (t->f[i].flags & FNAV_FRAME_STANCE) != 0u;
        if (!still) {
            if (!moving) {
                moving = 1;
                run0 = i;
            }
            pause = 0;
        } else if (moving) {
            if (!pause) {
                pause = 1;
                still0 = i;
            }
            if (i < t->n && 1e-9 * (double)(t->f[i].t_ns - t->f[still0].t_ns) < HX_NAV_CYCLE_MOTION_S) {
                continue; /* perhaps a blip in the swing */
            }
            moving = 0;
            pause = 0;
            if (1e-9 * (double)(t->f[still0 - 1u].t_ns - t->f[run0].t_ns) >= HX_NAV_CYCLE_MOTION_S) {
                if (have && *k < t->n / 2u + 1u) {
                    iv[(*k)++] = 1e-9 * (double)(t->f[run0].t_ns - onset);
                }
                onset = t->f[run0].t_ns;
                have = 1;
            }
        }
    }
    return iv;
}

/* The axes check's remedy for a log read by a command that takes
 * --columns (fmt HX_FMT_AUTO: none), appended to the warning: for a CSV
 * the whole --columns that reads this log's gyro as the map found, since a
 * partial --columns turns the names' matching off; for another format,
 * whose importer has no columns to name, or a CSV with a ',' in a name
 * (which --columns cannot give), the same for the log converted to the
 * interchange CSV, convert given what this run was (--from when given,
 * --input-rate, a CSV's --units) (docs/harness.md, "Axes check"). */
static void axes_columns_remedy(hx_axes_result_t *a, hx_format_t fmt, hx_format_t given_fmt, double in_rate,
                                const char *path)
{
    static const fnav_vec3_t k_axes = { { FNAV_R(1.0), FNAV_R(2.0), FNAV_R(3.0) } };
    hx_csv_layout_t lay, def;
    const hx_csv_layout_t *l;
    fnav_vec3_t m;
    char give[1024], text[2048], word[1100], opts[160] = "", units[96];
    int src[3], neg[3], i, ok;
    size_t len;
    if (!a->problem || fmt == HX_FMT_AUTO) {
        return;
    }
    l = hx_units_layout(fmt, &lay);
    /* the map's source axis and sign, read off the axes (1, 2, 3) mapped */
    m = hx_axes_map(a->best, k_axes);
    for (i = 0; i < 3; i++) {
        neg[i] = m.v[i] < FNAV_R(0.0);
        src[i] = (int)(neg[i] ? -m.v[i] : m.v[i]) - 1;
    }
    if (l != NULL && hx_columns_give(l, src, neg, give, sizeof give) != NULL) {
        ok = snprintf(text, sizeof text, "; this log so read: %s", give) < (int)sizeof text;
    } else {
        hx_csv_layout_default(&def); /* convert writes the interchange names, in SI */
        len = 0;
        if (given_fmt != HX_FMT_AUTO) {
            len += (size_t)snprintf(opts + len, sizeof opts - len, " --from %s", hx_format_name(given_fmt));
        }
        if (in_rate > 0.0 && len < sizeof opts) {
            /* the shortest of %.15g and %.17g that reads back the rate */
            char num[40];
            snprintf(num, sizeof num, "%.15g", in_rate);
            if (strtod(num, NULL) != in_rate) {
                snprintf(num, sizeof num, "%.17g", in_rate);
            }
            len += (size_t)snprintf(opts + len, sizeof opts - len, " --input-rate %s", num);
        }
        if (l != NULL && len < sizeof opts && strncmp(hx_units_give(l, units, sizeof units), "give ", 5) == 0) {
            (void)snprintf(opts + len, sizeof opts - len, " %s", units + 5);
        }
        {
            /* a path that begins with '-' would be read as an option */
            char rel[1100];
            const int dash = path[0] == '-';
            ok = snprintf(rel, sizeof rel, "%s%s", dash ? "./" : "", path) < (int)sizeof rel &&
                 hx_shell_word(rel, 0, word, sizeof word)[0] != '\0';
        }
        ok = ok && hx_columns_give(&def, src, neg, give, sizeof give) != NULL &&
             snprintf(text, sizeof text,
                      "; this log so read: bin/harness convert %s F.csv%s (the %s%s to the interchange CSV), then "
                      "F.csv with %s", word, opts,
                      l != NULL ? "CSV, whose names hold a ',' no --columns can give," : hx_format_name(fmt),
                      l != NULL ? "" : " format", give) < (int)sizeof text;
    }
    len = strlen(a->msg);
    if (ok && strlen(text) < sizeof a->msg - len) {
        memcpy(a->msg + len, text, strlen(text) + 1);
    } else {
        snprintf(a->msg + len, sizeof a->msg - len, "; the options that read this log so are too long for this "
                                                    "message (docs/harness.md, \"Axes check\")");
    }
}

/* --rate: the input's gaps before the resampler closes them up (the
 * navigator sees a uniform grid): those over 1.5 input periods counted,
 * the longest interval, and the ends of those over HX_NAV_LONG_GAP_S kept
 * for the motion-gap summary; a time jump (the resampler's rule) is none,
 * the navigator sees it; exact repeats left out as the resampler drops
 * them. -1: no memory. */
static int in_gaps(const hx_log_t *in, double fs, double max_gap_s, hx_traj_t *t)
{
    const double per = fs > 0.0 ? 1.0 / fs : 0.0;
    const double jump_s = max_gap_s > 1.5 * per ? max_gap_s : 1.5 * per;
    size_t i, prev = 0, cap = 0;
    for (i = 1; i < in->n; i++) {
        double dt;
        if (in->t_ns[i] <= in->t_ns[prev]) {
            continue;
        }
        dt = 1e-9 * (double)(in->t_ns[i] - in->t_ns[prev]);
        if (dt > t->in_longest_s) {
            t->in_longest_s = dt;
        }
        if (dt > 1.5 * per && !(dt > jump_s)) {
            t->in_gaps++;
            if (dt > HX_NAV_LONG_GAP_S) {
                if (t->n_in_long == cap) {
                    const size_t nc = cap ? 2u * cap : 64u;
                    int64_t(*p)[2] = (int64_t(*)[2])realloc(t->in_long, nc * sizeof *p);
                    if (p == NULL) {
                        return -1;
                    }
                    t->in_long = p;
                    cap = nc;
                }
                t->in_long[t->n_in_long][0] = in->t_ns[prev];
                t->in_long[t->n_in_long][1] = in->t_ns[i];
                t->n_in_long++;
            }
        }
        prev = i;
    }
    return 0;
}

static void stage_progress(void *ctx, double frac)
{
    hx_progress_update((hx_progress_t *)ctx, frac);
}

int hx_nav_replay(const char *cmd, const char *path, hx_format_t fmt, double in_rate, const fnav_nav_config_t *cfg,
                  double rate_hz, FILE *csv, hx_traj_t *traj, unsigned flags, char *err, size_t err_size)
{
    static fnav_nav_t nav; /* 11.7 KB in float32 (fnav_nav.h): not on the stack of a deep caller */
    hx_port_ctx_t pc;
    fnav_port_t port;
    hx_reader_t *r = NULL;
    hx_log_t raw, res;
    fnav_status_t st;
    hx_format_t in_fmt; /* the format read: the units check's remedy */
    double remedy_rate = in_rate; /* the axes remedy's --input-rate: not one the reader ignored */
    size_t span_n = 0;  /* the input's samples and their first and last stamps (the units check's span; */
    int64_t span_t0 = 0, span_t1 = 0; /* with --rate the input's, not the resampled grid's) */
    int rc = 0;
    const double t_cmd = hx_now_s(); /* --rate: the progress's "done in" covers the reading and resampling too */
    memset(&pc, 0, sizeof pc);
    pc.quiet_w = -1.0; /* no window yet (quiet_close) */
    memset(&raw, 0, sizeof raw);
    memset(&res, 0, sizeof res);
    err[0] = '\0';
    if (traj != NULL) {
        memset(traj, 0, sizeof *traj);
    }
    if (rate_hz > 0.0) {
        long dups = 0;
        double fs = 0.0;
        const int show = (flags & HX_REPLAY_PROGRESS) != 0;
        hx_progress_t stage;
        char label[64];
        int lrc;
        /* the whole log is read, then resampled, before the first sample is
         * navigated: each stage shows its progress (an hour at 400 Hz took
         * 5.7 s before the first line) */
        snprintf(label, sizeof label, "%s: reading", cmd);
        hx_progress_start(&stage, label, 1.0);
        lrc = hx_log_load_progress(&raw, path, fmt, in_rate, show ? stage_progress : NULL, &stage, err, err_size);
        hx_progress_end(&stage); /* prints only what was shown */
        if (lrc < 0) {
            return -1;
        }
        /* the reader's warnings (assumed rates, cut-off lines, a GX2 timer
         * bridged), as the unresampled replay prints them below; they were
         * dropped here */
        hx_print_warnings(cmd, raw.warnings);
        in_fmt = raw.meta.format;
        remedy_rate = raw.meta.rate_ignored ? 0.0 : in_rate;
        if (traj != NULL) {
            traj->in_format = in_fmt;
            traj->rate_assumed_hz = in_fmt == HX_FMT_OS820 && !(in_rate > 0.0) ? 820.0 : 0.0;
        }
        if (lrc > 0) {
            snprintf(err, err_size, "%s", raw.error);
            rc = 1;
        }
        if (raw.n > 0u) {
            span_n = raw.n;
            span_t0 = raw.t_ns[0];
            span_t1 = raw.t_ns[raw.n - 1u];
        }
        snprintf(label, sizeof label, "%s: resampling", cmd);
        hx_progress_start(&stage, label, 1.0);
        if (hx_nav_resample_progress(&raw, rate_hz, (double)cfg->max_gap_s, &res, &dups, &fs,
                                     show ? stage_progress : NULL, &stage, err, err_size) != 0) {
            hx_line_break(); /* a progress line left open: the error follows */
            if (span_n < 4u && lrc > 0) {
                /* the reader stopped early: its error is the cause (it
                 * said only "too few samples to resample (2)") */
                snprintf(err, err_size, "%s (only %zu sample%s read: too few to resample)", raw.error, span_n,
                         span_n == 1u ? "" : "s");
            } else if (span_n < 4u) {
                /* too few samples: named by the file as convert --rate
                 * names it (the resampler's other errors say the file's
                 * rate or stamps and keep their wording) */
                snprintf(err, err_size, "%s: too few samples to resample (%zu)", path, span_n);
            }
            hx_log_free(&raw);
            return -1;
        }
        hx_progress_end(&stage);
        if (traj != NULL && in_gaps(&raw, fs, (double)cfg->max_gap_s, traj) != 0) {
            hx_log_free(&raw);
            hx_log_free(&res);
            snprintf(err, err_size, "out of memory");
            return -1;
        }
        if (traj != NULL) {
            size_t i;
            traj->cut_lines = raw.stats.cut_lines;
            /* the flat tops of the input: the low-pass rounds them off */
            for (i = 0; i < raw.n; i++) {
                fnav_sample_t smp;
                hx_log_sample(&raw, i, &smp);
                hx_sat_push(&pc.sat, &smp);
            }
        }
        hx_log_free(&raw);
        pc.mem = &res;
        pc.total = (double)res.n;
        if (traj != NULL) {
            traj->in_rate_hz = fs;
            traj->resample_dropped_dups = dups;
        }
    } else {
        if (!(flags & HX_REPLAY_STAMPS_CHECKED) &&
            hx_nav_stamps_check(path, fmt, in_rate, (double)cfg->max_gap_s, err, err_size) != 0) {
            return -1;
        }
        r = hx_reader_open(path, fmt, in_rate, err, err_size);
        if (r == NULL) {
            return -1;
        }
        in_fmt = hx_reader_meta(r)->format;
        remedy_rate = hx_reader_meta(r)->rate_ignored ? 0.0 : in_rate;
        if (traj != NULL) {
            traj->in_format = in_fmt;
            traj->rate_assumed_hz = in_fmt == HX_FMT_OS820 && !(in_rate > 0.0) ? 820.0 : 0.0;
        }
    }
    {
        /* Stamps too coarse for a median interval (a 398 Hz log printed to
         * the millisecond reads 2 and 3 ms): the detector's own estimate
         * from its first intervals would be 20 % off, so it gets the
         * reader's, from the spans of the first 4096 stamps. Other logs keep
         * the detector's estimate, as firmware would. */
        fnav_nav_config_t c = *cfg;
        const hx_meta_t *mt = r != NULL ? hx_reader_meta(r) : NULL;
        if (mt != NULL && !(c.stance.rate_hz > FNAV_R(0.0)) && mt->rate_coarse) {
            c.stance.rate_hz = (fnav_real_t)mt->rate_hz;
        } else if (mt != NULL && !(c.stance.rate_hz > FNAV_R(0.0)) && !mt->rate_nominal && mt->rate_hz > 0.0 &&
                   mt->rate_start_hz > 0.0 && fabs(mt->rate_start_hz / mt->rate_hz - 1.0) > HX_START_RATE_TOL &&
                   mt->rate_span_hz > 0.0 && fabs(mt->rate_span_hz / mt->rate_hz - 1.0) <= HX_START_RATE_TOL) {
            /* The detector's first intervals are not the log's: a burst of
             * stamps at the start (a logger's buffer flushed at power-on:
             * 40 stamps 1 ms apart took a 200 Hz walk for 1000 Hz, a window
             * of 25 samples, 2 strides of 46) would set its window for the
             * whole log. It gets the reader's rate, from the median of the
             * first 4096 intervals, and the warning says so; only where that
             * rate is the stamps' count over their span (stamps in pairs
             * 0.1 ms apart every 10 ms have a median of either: "Time stamps
             * in bursts" warns of those). */
            c.stance.rate_hz = (fnav_real_t)mt->rate_hz;
            hx_warn(cmd, "%s: the first %d intervals give %.6g Hz, the first 4,096 %.6g Hz (a burst of stamps at the "
                         "start, e.g. a logger's buffer flushed at power-on?): the stance detector takes %.6g Hz",
                    path, HX_STANCE_PROBE,
                    mt->rate_start_hz, mt->rate_hz, mt->rate_hz);
        }
        if (fnav_nav_init(&nav, &c) != FNAV_OK) {
            char hint[320];
            hx_csv_layout_t lay;
            hx_nav_init_error(&c,
                              cfg->stance.rate_hz > FNAV_R(0.0)
                                  ? ""
                                  : " (estimated from the log's time stamps, too coarse to give the interval)",
                              "", err, err_size);
            if (!(cfg->stance.rate_hz > FNAV_R(0.0)) && hx_time_unit_hint((double)c.stance.rate_hz,
                                                                            (flags & HX_REPLAY_UNITS_OPT)
                                                                                ? hx_units_layout(in_fmt, &lay)
                                                                                : NULL,
                                                                            hint, sizeof hint) &&
                strlen(err) + strlen(hint) + 3 < err_size) {
                /* stamps in whole ms read as s (5 s apart, jittered by a
                 * ms: coarse) were told only "too low", as info tells the
                 * unit */
                strcat(err, "; ");
                strcat(err, hint);
            }
            hx_reader_close(r);
            hx_log_free(&res);
            return -1;
        }
    }
    fnav_linux_port_init(&pc.linux_port, &pc.lctx, r, csv);
    pc.traj = traj;
    if (r != NULL && !(cfg->stance.rate_hz > FNAV_R(0.0)) && !hx_reader_meta(r)->rate_coarse) {
        /* the stamps the detector's own estimate comes from: pairs_warn
         * (NULL: out of memory, no warning) */
        pc.probe = (int64_t *)malloc(HX_STAMPS_PROBE_N * sizeof *pc.probe);
    }
    if (traj != NULL && (flags & HX_REPLAY_AXES)) {
        pc.axes = hx_axes_new((double)cfg->stance.min_zupt_cycle); /* NULL: out of memory, not checked */
    }
    if (traj != NULL && (flags & HX_REPLAY_EVENTS)) {
        /* the navigator's detector's own configuration (its rate and gravity
         * as the navigator set them), before any sample */
        pc.nav = &nav;
        pc.ev = (fnav_stance_t *)malloc(sizeof *pc.ev);
        if (pc.ev == NULL || fnav_stance_init(pc.ev, &nav.stance.cfg) != FNAV_OK) {
            pc.ev_bad = 1; /* no events: the caller says so */
        }
    }
    pc.progress = (flags & HX_REPLAY_PROGRESS) != 0;
    port.ctx = &pc;
    port.read_sample = hx_read;
    port.now_ns = hx_now;
    port.write_nav = hx_write;
    port.log = hx_logmsg;
    if (pc.progress) {
        hx_progress_start(&pc.prog, cmd, pc.total > 0.0 ? pc.total : 1.0);
        if (pc.mem != NULL) {
            pc.prog.t_origin = t_cmd; /* "done in": the whole command, the reading and resampling with it */
        }
    }
    st = fnav_nav_run(&nav, &port, 0);
    if (pc.progress) {
        if (pc.mem != NULL) {
            /* the samples navigated: updates come every 1,024 (hx_read),
             * so the last line said 90 %, never 100 */
            hx_progress_update(&pc.prog, (double)pc.n_read);
        }
        hx_progress_end(&pc.prog);
    }
    if (pc.sink_failed || pc.traj_oom) {
        if (pc.sink_failed) {
            char why[128];
            snprintf(err, err_size, "cannot write the trajectory%s",
                     hx_errno_note(pc.lctx.write_errno, why, sizeof why));
        } else {
            snprintf(err, err_size, "out of memory keeping the trajectory");
        }
        rc = -3;
    } else if (st != FNAV_OK) {
        /* the input stopped the run (FNAV_E_IO is the reader's too: a NUL
         * block, an over-long line, a truncated .gz): reported as the
         * input's, with its line, not as the sink's failure (exit 3) */
        if (r != NULL && hx_reader_error(r)[0] != '\0') {
            snprintf(err, err_size, "%s", hx_reader_error(r));
        } else {
            snprintf(err, err_size, "%s: the replay stopped (status %d)", path, (int)st);
        }
        rc = 1;
    }
    if (traj != NULL) {
        traj->stats = nav.stats;
        traj->rate_hz = (double)nav.stance.rate_hz;
        /* three rates can be printed for one log (199.44 Hz here, 200.0 Hz
         * by info, 200.1 Hz by --rate's error, for a vicon trial): the line
         * says which this is */
        if (rate_hz > 0.0) {
            snprintf(traj->rate_src, sizeof traj->rate_src, "resampled");
        } else if (cfg->stance.rate_hz > FNAV_R(0.0)) {
            snprintf(traj->rate_src, sizeof traj->rate_src, "configured");
        } else if (r != NULL && hx_reader_meta(r)->rate_coarse) {
            snprintf(traj->rate_src, sizeof traj->rate_src,
                     "from the time stamps of the first 4,096 samples, too coarse for the detector's estimate");
        } else if (nav.stance.cfg.rate_hz > FNAV_R(0.0)) {
            snprintf(traj->rate_src, sizeof traj->rate_src,
                     "from the time stamps of the first 4,096 samples: 1 / their median interval; the detector's "
                     "first intervals give %.4g Hz", r != NULL ? hx_reader_meta(r)->rate_start_hz : 0.0);
        } else if (nav.stats.samples == 0u) {
            /* no sample: the detector never ran, and has no fallback rate
             * nor window to name (info's wording) */
            traj->rate_none = 1;
            snprintf(traj->rate_src, sizeof traj->rate_src, "no sample gives no rate");
        } else if (nav.stats.samples < 2u) {
            /* no interval to take the median of: the figure is the
             * detector's fallback, not the log's rate */
            traj->rate_none = 1;
            snprintf(traj->rate_src, sizeof traj->rate_src,
                     "one sample gives no rate; the stance detector took its fallback of %.1f Hz", traj->rate_hz);
        } else if (stamps_never_advance(&nav.stats)) {
            /* intervals all 0: as one sample, no rate (the figure was the
             * detector's fallback, said to be its estimate) */
            traj->rate_none = 1;
            snprintf(traj->rate_src, sizeof traj->rate_src,
                     "the time stamps never advance; the stance detector took its fallback of %.1f Hz", traj->rate_hz);
        } else {
            snprintf(traj->rate_src, sizeof traj->rate_src,
                     "the stance detector's estimate: 1 / the median of its first %d intervals", HX_STANCE_PROBE);
        }
        traj->max_gap_s = (double)nav.cfg.max_gap_s;
        traj->window = nav.stance.win;
        traj->zupt_min_n = nav.stance.n_min_zupt;
        traj->zupt_max_n = nav.stance.lag + 1;
        traj->align = nav.align.result;
        traj->aligned = nav.aligned;
        {
            int ch;
            for (ch = 0; ch < 6; ch++) {
                traj->saturated[ch] = hx_sat_count(&pc.sat, ch);
            }
        }
        if (r != NULL) {
            traj->cut_lines = hx_reader_stats(r)->cut_lines;
            if (hx_reader_meta(r)->rate_coarse && pc.stamp_res_ns > 0 && traj->rate_hz > 0.0) {
                /* an interval of one period reads up to the next whole
                 * number of stamp steps: above 1.5 periods it counts as a gap */
                const double per = 1e9 / traj->rate_hz, q = (double)pc.stamp_res_ns, k = per / q;
                const double longest = (fabs(k - floor(k + 0.5)) <= 0.05 ? floor(k + 0.5) : ceil(k)) * q;
                traj->stamps_coarse = longest > 1.5 * per;
            }
        }
        traj->t0_ns = pc.lctx.t0_ns;
        traj->output_errno = pc.sink_failed ? pc.lctx.write_errno : 0;
        /* every frame kept has had its detector output (a run stopped by
         * the sink or the memory may have dropped the last frames') */
        traj->events = pc.ev != NULL && !pc.ev_bad;
        if (flags & HX_REPLAY_AXES) {
            hx_axes_finish(pc.axes, &traj->axes);
            if (traj->axes.time_problem && traj->rate_hz > 0.0) {
                /* the input's rate (--rate resamples: its rate is not the one read) */
                const double rd = traj->in_rate_hz > 0.0 ? traj->in_rate_hz : traj->rate_hz;
                const size_t len = strlen(traj->axes.msg);
                snprintf(traj->axes.msg + len, sizeof traj->axes.msg - len, "; read at %.6g Hz, so about %.4g Hz",
                         rd, rd / traj->axes.time_scale);
            }
            axes_columns_remedy(&traj->axes, (flags & HX_REPLAY_UNITS_OPT) ? in_fmt : HX_FMT_AUTO, fmt,
                                remedy_rate, path);
        } else {
            snprintf(traj->axes.msg, sizeof traj->axes.msg, "not checked: not asked for");
        }
    }
    if (r != NULL) {
        /* warnings collected while reading (assumed rates, cut-off lines) */
        hx_print_warnings(cmd, hx_reader_take_warnings(r));
        hx_reader_close(r);
    }
    if (pc.probe != NULL) {
        pairs_warn(cmd, path, in_fmt, pc.probe, pc.n_probe, pc.n_read > (long)pc.n_probe, (double)cfg->max_gap_s,
                   (double)nav.stance.rate_hz);
        free(pc.probe);
    }
    hx_log_free(&res);
    free(pc.ev);
    {
        /* the detector's ring (FNAV_STANCE_MAX_WINDOW samples) cuts its
         * window and minimum ZUPT run at high rates (docs/navigation.md,
         * "Stance detector"): the decisions then differ from the configured
         * durations, silently until said here */
        const unsigned cut = fnav_stance_cut(&nav.stance);
        const int cut_win = (cut & FNAV_STANCE_CUT_WINDOW) != 0u, cut_zupt = (cut & FNAV_STANCE_CUT_MIN_ZUPT) != 0u;
        const double fs = (double)nav.stance.rate_hz;
        if (cut_win || cut_zupt) {
            char what[200], advice[200];
            const double fs_fit = stance_fit_rate(cfg, fs);
            size_t n = 0;
            what[0] = '\0';
            if (cut_win) {
                n += (size_t)snprintf(what, sizeof what, "its window to %.1f ms (of %.1f)",
                                      1e3 * (double)nav.stance.win / fs, 1e3 * (double)cfg->stance.window_s);
            }
            if (cut_zupt && n < sizeof what) {
                snprintf(what + n, sizeof what - n, "%sits minimum ZUPT run to %.1f ms (of %.1f)",
                         cut_win ? " and " : "", 1e3 * (double)nav.stance.n_min_zupt / fs,
                         1e3 * (double)cfg->stance.min_zupt_s);
            }
            if (fs_fit > 0.0) {
                snprintf(advice, sizeof advice, "resample (--rate %.0f)", fs_fit);
            } else {
                snprintf(advice, sizeof advice,
                         "no rate --rate accepts fits them: shorten window_s or min_zupt_s (--param)");
            }
            hx_warn(cmd,
                    "%s: at %.0f Hz the stance detector's ring of %d samples cuts %s: %s or build with a larger "
                    "FNAV_STANCE_MAX_WINDOW (docs/navigation.md, \"Stance detector\")",
                    path, fs, FNAV_STANCE_MAX_WINDOW, what, advice);
        }
        if ((cut & FNAV_STANCE_CUT_ZUPT_CYCLE) != 0u && traj != NULL) {
            /* min_zupt_cycle: the look-ahead is fixed for the longest cycle
             * (FNAV_STANCE_CYCLE_LAG_S); the ring caps it at lag + 1
             * samples, which binds for cycles over run_max / (F fs) only:
             * said when the log has such cycles, not at every rate that
             * cuts whatever the gait (the 820 Hz walk, cycles of 1.0 s, has
             * none) */
            const double run_max = (double)(nav.stance.lag + 1);
            const double cyc_max = run_max / ((double)cfg->stance.min_zupt_cycle * fs);
            size_t k = 0, i, over = 0, gait = 0;
            double *iv = cycle_intervals(traj, &k);
            for (i = 0; i < k; i++) {
                /* an interval over FNAV_STANCE_CYCLE_MAX_S spans a stand,
                 * which clears the detector's cycle (no run is scaled by
                 * it): no gait cycle, not counted (a 30 s stand in the
                 * 820 Hz walk was "1 of the log's 21") */
                if (iv[i] <= (double)FNAV_STANCE_CYCLE_MAX_S) {
                    gait++;
                    over += iv[i] > cyc_max;
                }
            }
            free(iv);
            k = gait;
            if (over > 0u) {
                hx_warn(cmd,
                        "%s: at %.0f Hz the stance detector's ring of %d samples caps the cycle-scaled ZUPT run at "
                        "%.1f ms (min_zupt_cycle %g asks up to %.1f ms): gait cycles over %.2f s get the cap, "
                        "%lu of the log's %lu (docs/navigation.md, \"Stance detector\")",
                        path, fs, FNAV_STANCE_MAX_WINDOW, 1e3 * run_max / fs, (double)cfg->stance.min_zupt_cycle,
                        1e3 * (double)cfg->stance.min_zupt_cycle * (double)FNAV_STANCE_CYCLE_LAG_S, cyc_max,
                        (unsigned long)over, (unsigned long)k);
            }
        }
    }
    if ((flags & HX_REPLAY_EVENTS) && nav.stance.rate_hz > FNAV_R(0.0)) {
        /* the gait events' searches live in the detector's jerk history
         * (FNAV_STANCE_EVENT_BUF samples): above about 450 Hz they are cut,
         * and an event beyond the cut is read late (the 820 Hz OpenShoe
         * walk: 3 of 49 foot-strikes 77-155 ms later than at 200 Hz): said,
         * not silent */
        const double fs = (double)nav.stance.rate_hz;
        const long want = lround((double)cfg->stance.event_window_s * fs);
        long fo_n, fs_n;
        event_reach(cfg, fs, &fo_n, &fs_n);
        if (fo_n < want || fs_n < want) {
            const double fit = event_fit_rate(cfg, fs);
            char advice[96];
            if (fit > 0.0) {
                snprintf(advice, sizeof advice, "resample (--rate %.0f) or", fit);
            } else {
                snprintf(advice, sizeof advice, "shorten min_stance_s (--param) or");
            }
            hx_warn(cmd,
                    "%s: at %.0f Hz the gait events' searches are cut: the foot-off is searched over %.0f ms (of "
                    "%.0f) after the swing begins and the foot-strike over %.0f ms (of %.0f) before the stance "
                    "(FNAV_STANCE_EVENT_BUF, %d samples of jerk history); an event beyond is read late: %s build "
                    "with a larger FNAV_STANCE_EVENT_BUF (docs/navigation.md, \"Strides and gait events\")",
                    path, fs, 1e3 * (double)fo_n / fs, 1e3 * (double)cfg->stance.event_window_s,
                    1e3 * (double)fs_n / fs, 1e3 * (double)cfg->stance.event_window_s, FNAV_STANCE_EVENT_BUF,
                    advice);
        }
    }
    if (rc == 0) {
        /* wrong units are also why a log never looks still */
        char msg[sizeof traj->units_problem];
        hx_csv_layout_t lay;
        int u;
        if (r != NULL && pc.have_t_last) {
            span_n = (size_t)pc.n_read;
            span_t0 = pc.t_first_ns;
            span_t1 = pc.t_last_ns;
        }
        quiet_close(&pc); /* the last window */
        if (hx_gyro_glitches(pc.n_gyro_over, pc.n_read)) {
            /* a few samples past any gyro's range among many within it are
             * glitches (of the sensor or its link), which the navigator
             * rejected: no unit, whose every motion sample reads past it
             * (a walk in deg/s read as rad/s: a fifth or more); the units
             * check reads the others (one spike of 300 rad/s was told
             * "probably in deg/s") */
            hx_warn(cmd, "%s: %ld sample%s read a rate past any MEMS gyro's range (%.0f rad/s on an axis; the largest "
                         "%.4g rad/s) among %ld within it: glitches of the sensor or its link, rejected by the "
                         "navigator (range_rejected; docs/robustness.md)",
                    path, pc.n_gyro_over, pc.n_gyro_over == 1 ? "" : "s", FNAV_NAV_GYRO_MAX_RPS, pc.gyro_max_rps,
                    pc.n_read - pc.n_gyro_over);
            pc.gyro_max_rps = pc.gyro_max_in_rps;
        }
        u = units_check(&nav, pc.gyro_max_rps, pc.quiet_w, pc.quiet_f, pc.quiet_cv,
                        pc.n_read > 0 ? pc.f_norm_sum / (double)pc.n_read : 0.0,
                        hx_walk_seen(&pc.walk),
                        traj != NULL && traj->in_rate_hz > 0.0 ? traj->in_rate_hz : 0.0,
                        span_n, span_t0, span_t1,
                        (flags & HX_REPLAY_UNITS_OPT) ? hx_units_layout(in_fmt, &lay) : NULL, in_fmt, msg,
                        sizeof msg);
        if (traj != NULL) {
            /* the JSON's units_problem ("" when none) */
            traj->units_checked = 1;
            snprintf(traj->units_problem, sizeof traj->units_problem, "%s", u != 0 ? msg : "");
        }
        if (u != 0) {
            snprintf(err, err_size, "%s: %s", path, msg);
            rc = u;
        }
    }
    if (rc == 0 && !nav.aligned) {
        if (stamps_never_advance(&nav.stats)) {
            /* every sample at one time: no interval to integrate or to
             * measure stillness over (said so, not "no still period") */
            snprintf(err, err_size, "%s: the time stamps never advance (all %lu samples at one time): is the time "
                                    "column filled?",
                     path, (unsigned long)nav.stats.samples);
        } else {
            /* what the alignment requires: the first still period of
             * align_min_s, or, when the foot moves before one, the quietest
             * of align_short_s or more (fnav_align.c), not "no still period
             * of 0.50 s" (align_min_s), since 0.3 s still aligns. What was found: the
             * detector's longest still run (the alignment's periods lie in
             * such runs) */
            double longest = 0.0;
            if (traj != NULL) {
                size_t i, run0 = 0;
                int open = 0;
                for (i = 0; i < traj->n; i++) {
                    if (traj->f[i].flags & FNAV_FRAME_STANCE) {
                        const double d = 1e-9 * (double)(traj->f[i].t_ns - traj->f[open ? run0 : i].t_ns);
                        run0 = open ? run0 : i;
                        open = 1;
                        longest = d > longest ? d : longest;
                    } else {
                        open = 0;
                    }
                }
            }
            snprintf(err, err_size,
                     "%s: no still period of %.2f s or more found for the initial alignment (align_short_s; it takes "
                     "the first of %.2f s, align_min_s, else the quietest of %.2f s or more before the foot moves)",
                     path, (double)cfg->align.short_still_s, (double)cfg->align.min_still_s,
                     (double)cfg->align.short_still_s);
            if (traj != NULL) {
                /* a run that long can still give the alignment less: its
                 * noise-floor test or a time jump cuts it (a log that ends
                 * still is not cut: the detector's held-back samples reach
                 * the alignment, fnav_nav_finish) */
                const size_t len = strlen(err);
                const double dur = traj->n > 1u ? 1e-9 * (double)(traj->f[traj->n - 1u].t_ns - traj->f[0].t_ns) : 0.0;
                const size_t len2 = len + (size_t)snprintf(err + len, err_size - len,
                                                           ": the stance detector's longest still run lasted %.2f s%s",
                                                           longest,
                                                           longest >= (double)cfg->align.short_still_s
                                                               ? ", cut shorter for the alignment (its noise-floor test "
                                                                 "or a time jump)"
                                                               : "");
                if (dur < (double)cfg->align.short_still_s && len2 < err_size) {
                    /* the log itself too short (a header and 2 samples said
                     * only "the longest still run lasted 0.00 s", as if the
                     * foot had moved throughout) */
                    snprintf(err + len2, err_size - len2, ", in a log that lasts only %.3g s (%lu frame%s)", dur,
                             (unsigned long)traj->n, traj->n == 1u ? "" : "s");
                }
            }
        }
        /* read to its end: not a run stopped early (returning 1 would make
         * replay say "stopped after N samples, at the input error above",
         * its JSON "complete": false, and eval "input ends early") */
        rc = 3;
    }
    return rc;
}

/* ------------------------------------------------------------ summary */

size_t hx_nav_stance_mids(const hx_traj_t *t, size_t *idx, size_t max)
{
    return hx_nav_stance_phases(t, idx, NULL, max);
}

size_t hx_nav_stance_phases(const hx_traj_t *t, size_t *idx, size_t *start_out, size_t max)
{
    /* A segmented stance phase (FNAV_FRAME_SEG_STANCE) begins min_stance_s
     * after the detector's stance and ends min_swing_s after it (the
     * segmentation's hysteresis), so its middle lies late, and a first phase
     * cut short by the alignment can have its middle in the next swing. The
     * mid-point is therefore the middle of the detector's stance within each
     * segmented phase: from the start of the detector's stance run the phase
     * began in (not before the first aligned frame) to the phase's last
     * detector stance frame. */
    const unsigned aligned = FNAV_FRAME_ALIGNED, det = FNAV_FRAME_STANCE;
    size_t i, n = 0, start = 0;
    int in = 0;
    for (i = 0; i <= t->n; i++) {
        int st = i < t->n && (t->f[i].flags & aligned) && (t->f[i].flags & FNAV_FRAME_SEG_STANCE);
        if (st && !in) {
            start = i;
            in = 1;
        } else if (!st && in) {
            size_t a = start, b = i - 1;
            while (a > 0 && (t->f[a - 1].flags & aligned) && (t->f[a - 1].flags & det)) {
                a--;
            }
            while (b > start && !(t->f[b].flags & det)) {
                b--;
            }
            if (n < max) {
                if (start_out != NULL) {
                    start_out[n] = start;
                }
                idx[n++] = (a + b) / 2;
            }
            in = 0;
        }
    }
    return n;
}

/* The rate along the log against the detector's (hx_rate_changes). */
static void rate_check(const hx_traj_t *t, hx_nav_summary_t *s)
{
    s->rate_off_fraction = hx_rate_changes(t->n > 0 ? &t->f[0].t_ns : NULL, t->n, sizeof t->f[0], t->rate_hz,
                                           &s->rate_change_at_s, &s->rate_change_hz);
}

/* The heading is that of a body-fixed vector level at the first aligned
 * frame: n's x axis seen in b then (row 0 of C_nb). Not the Euler yaw,
 * which is the heading of b's x axis and has none when that axis is
 * vertical: a sensor mounted with x up or down, or tilted so that the swing
 * pitches x through the vertical (the footprint walks' 3DM-GX5 sits at 37
 * deg and passes 89 deg), where yaw flips by up to 180 deg between frames
 * and the unwrapping counted thousands of degrees. Frames in which the
 * vector is steeper than 60 deg (horizontal part below 1/2) have none
 * (heading_of returns 0); the summary unwraps the step across them to
 * (-180, 180], more than a foot turns in one swing. */
static void heading_ref(const hx_traj_t *t, size_t first, double ref_b[3])
{
    double c[3][3];
    int k;
    hx_dcm_from_euler((double)t->f[first].euler_rad[0], (double)t->f[first].euler_rad[1],
                      (double)t->f[first].euler_rad[2], c);
    for (k = 0; k < 3; k++) {
        ref_b[k] = c[0][k];
    }
}

/* d in (-pi, pi]: a heading step of at most half a turn */
static double wrap_step(double d)
{
    while (d > M_PI) {
        d -= 2.0 * M_PI;
    }
    while (d <= -M_PI) {
        d += 2.0 * M_PI;
    }
    return d;
}

static int heading_of(const double ref_b[3], const fnav_nav_frame_t *f, double *yaw)
{
    double c[3][3], hx, hy;
    hx_dcm_from_euler((double)f->euler_rad[0], (double)f->euler_rad[1], (double)f->euler_rad[2], c);
    hx = c[0][0] * ref_b[0] + c[0][1] * ref_b[1] + c[0][2] * ref_b[2];
    hy = c[1][0] * ref_b[0] + c[1][1] * ref_b[1] + c[1][2] * ref_b[2];
    if (hx * hx + hy * hy < 0.25) {
        return 0;
    }
    *yaw = atan2(hy, hx);
    return 1;
}

void hx_nav_summarize(const hx_traj_t *t, hx_nav_summary_t *s)
{
    size_t i, n, *mid;
    size_t first = t->n;
    double yaw_prev = 0.0, yaw_acc = 0.0, zupt = 0.0, ref_b[3];
    memset(s, 0, sizeof *s);
    for (i = 0; i < t->n; i++) {
        if (t->f[i].flags & FNAV_FRAME_ALIGNED) {
            first = i;
            break;
        }
    }
    if (t->n > 0) {
        s->duration_s = 1e-9 * (double)(t->f[t->n - 1].t_ns - t->f[0].t_ns);
    }
    rate_check(t, s);
    s->aligned_at_s = s->before_align_s = (double)NAN;
    if (first < t->n) {
        /* the detector's motion before the first aligned frame: walking
         * that is not navigated (the alignment's result may be a renewal,
         * so its still period does not say where the first one began) */
        s->aligned_at_s = 1e-9 * (double)(t->f[first].t_ns - t->f[0].t_ns);
        s->before_align_s = 0.0;
        for (i = 0; i < first; i++) {
            if (!(t->f[i].flags & FNAV_FRAME_STANCE)) {
                s->before_align_s += 1e-9 * (double)(t->f[i + 1].t_ns - t->f[i].t_ns);
            }
        }
    }
    if (first < t->n && t->rate_hz > 0.0) {
        /* lost samples in motion (HX_NAV_LONG_GAP_S): an interval with an
         * end out of the detector's stance, a time jump (integrated as one
         * period) left out */
        const double per = 1.0 / t->rate_hz;
        for (i = first + 1; i < t->n; i++) {
            const double dt = 1e-9 * (double)(t->f[i].t_ns - t->f[i - 1].t_ns);
            if (!(dt > 0.0) || ((t->f[i].flags & FNAV_FRAME_STANCE) && (t->f[i - 1].flags & FNAV_FRAME_STANCE))) {
                continue;
            }
            if (t->max_gap_s > 0.0 && dt > t->max_gap_s && dt > 1.5 * per) {
                /* a time jump while the foot moved: integrated as one
                 * period, its motion unknown (hx_nav_gappy) */
                s->motion_jumps++;
                s->jump_lost_s += dt - per;
                continue;
            }
            s->motion_s += dt;
            if (t->in_rate_hz <= 0.0 && dt > 1.5 * per && dt > HX_NAV_LONG_GAP_S) {
                s->gap_lost_s += dt - per;
                s->long_gaps++;
                s->longest_motion_gap_s = dt > s->longest_motion_gap_s ? dt : s->longest_motion_gap_s;
            }
        }
        if (t->in_rate_hz > 0.0) {
            /* resampled (--rate): the grid is uniform, its samples made up
             * across the input's gaps, so the long gaps are the input's
             * (hx_traj_t in_long) that overlap a frame interval counted in
             * motion_s above: its motion is no better measured */
            size_t g, j = first + 1;
            const double in_per = 1.0 / t->in_rate_hz;
            for (g = 0; g < t->n_in_long; g++) {
                const int64_t a = t->in_long[g][0], b = t->in_long[g][1];
                const double dt = 1e-9 * (double)(b - a);
                double in_motion = 0.0; /* s of the gap inside frame intervals in motion */
                while (j < t->n && t->f[j].t_ns <= a) {
                    j++;
                }
                for (i = j; i < t->n && t->f[i - 1].t_ns < b; i++) {
                    const double fdt = 1e-9 * (double)(t->f[i].t_ns - t->f[i - 1].t_ns);
                    const int64_t lo = t->f[i - 1].t_ns > a ? t->f[i - 1].t_ns : a;
                    const int64_t hi = t->f[i].t_ns < b ? t->f[i].t_ns : b;
                    if (!(fdt > 0.0) ||
                        ((t->f[i].flags & FNAV_FRAME_STANCE) && (t->f[i - 1].flags & FNAV_FRAME_STANCE)) ||
                        (t->max_gap_s > 0.0 && fdt > t->max_gap_s && fdt > 1.5 * per) || hi <= lo) {
                        continue;
                    }
                    in_motion += 1e-9 * (double)(hi - lo);
                }
                /* the part of the gap in motion, not the whole gap: a
                 * coarse grid's motion interval that reaches into a
                 * stance took a gap lying there whole (ipol 3-3 left: 22
                 * gaps unresampled, 25 at --rate 50, 32 at 10); less than
                 * one input period of it in motion lost no sample there */
                if (in_motion > in_per) {
                    s->gap_lost_s += in_motion * (dt - in_per) / dt;
                    s->long_gaps++;
                    s->longest_motion_gap_s = dt > s->longest_motion_gap_s ? dt : s->longest_motion_gap_s;
                }
            }
        }
    }
    s->longest_stand_at_s = (double)NAN;
    if (first < t->n) {
        /* the longest stance run with motion before and after it, in the
         * navigated frames: a stand in the middle of a walk */
        int moved = 0, open = 0;
        size_t run0 = first;
        for (i = first; i < t->n; i++) {
            const int stance = (t->f[i].flags & FNAV_FRAME_STANCE) != 0u;
            if (stance && !open && moved) {
                open = 1;
                run0 = i;
            } else if (!stance) {
                if (open) {
                    const double d = 1e-9 * (double)(t->f[i].t_ns - t->f[run0].t_ns);
                    if (d > s->longest_stand_s) {
                        s->longest_stand_s = d;
                        s->longest_stand_at_s = 1e-9 * (double)(t->f[run0].t_ns - t->f[0].t_ns);
                    }
                    open = 0;
                }
                moved = 1;
            }
        }
    }
    {
        size_t k = 0;
        double *iv = cycle_intervals(t, &k);
        if (k >= HX_NAV_STRIDE_MIN_N) {
            qsort(iv, k, sizeof *iv, hx_cmp_double);
            s->median_stride_s = k % 2u ? iv[k / 2u] : 0.5 * (iv[k / 2u - 1u] + iv[k / 2u]);
            s->stride_intervals = (long)k;
        }
        free(iv);
    }
    if (first >= t->n) {
        /* never aligned: no position, so no return-to-start figure (null in
         * the JSON, as other figures that cannot be computed) */
        s->end_h_m = s->end_3d_m = s->end_h_pct = s->end_3d_pct = (double)NAN;
        s->vertical_m = s->heading_change_deg = (double)NAN;
        s->end_pos_m[0] = s->end_pos_m[1] = s->end_pos_m[2] = (double)NAN;
        return;
    }
    {
        int have = 0;
        heading_ref(t, first, ref_b);
        for (i = first; i < t->n; i++) {
            const fnav_nav_frame_t *f = &t->f[i];
            double yaw;
            if (i > first) {
                const fnav_nav_frame_t *g = &t->f[i - 1];
                double dx = (double)f->pos_m[0] - (double)g->pos_m[0], dy = (double)f->pos_m[1] - (double)g->pos_m[1],
                       dz = (double)f->pos_m[2] - (double)g->pos_m[2];
                s->integrated_path_m += sqrt(dx * dx + dy * dy + dz * dz);
            }
            if (heading_of(ref_b, f, &yaw)) {
                if (have) {
                    yaw_acc += wrap_step(yaw - yaw_prev);
                }
                yaw_prev = yaw;
                have = 1;
            }
            if (f->flags & FNAV_FRAME_ZUPT) {
                zupt += 1.0;
            }
        }
    }
    s->heading_change_deg = yaw_acc * 180.0 / M_PI;
    s->stance_fraction = zupt / (double)(t->n - first);
    s->strides = (long)t->stats.strides;
    mid = (size_t *)malloc((t->n + 1) * sizeof *mid);
    n = mid != NULL ? hx_nav_stance_mids(t, mid, t->n + 1) : 0;
    s->stance_phases = (long)n;
    {
        const fnav_nav_frame_t *a = n > 0 ? &t->f[mid[0]] : &t->f[first];
        const fnav_nav_frame_t *b = n > 0 ? &t->f[mid[n - 1]] : &t->f[t->n - 1];
        int k;
        for (i = 1; i < n; i++) {
            const fnav_nav_frame_t *p = &t->f[mid[i - 1]], *q = &t->f[mid[i]];
            double dx = (double)q->pos_m[0] - (double)p->pos_m[0], dy = (double)q->pos_m[1] - (double)p->pos_m[1],
                   dz = (double)q->pos_m[2] - (double)p->pos_m[2];
            s->path_m += sqrt(dx * dx + dy * dy + dz * dz);
            s->path_h_m += sqrt(dx * dx + dy * dy);
        }
        for (k = 0; k < 3; k++) {
            s->start_pos_m[k] = (double)a->pos_m[k];
            s->end_pos_m[k] = (double)b->pos_m[k];
        }
    }
    free(mid);
    {
        double dx = s->end_pos_m[0] - s->start_pos_m[0], dy = s->end_pos_m[1] - s->start_pos_m[1],
               dz = s->end_pos_m[2] - s->start_pos_m[2];
        s->end_h_m = sqrt(dx * dx + dy * dy);
        s->end_3d_m = sqrt(dx * dx + dy * dy + dz * dz);
        s->vertical_m = 0.0 - dz; /* n is z down: up positive (0 - dz: never -0) */
        s->end_h_pct = s->path_m > 0.0 ? 100.0 * s->end_h_m / s->path_m : (double)NAN;
        s->end_3d_pct = s->path_m > 0.0 ? 100.0 * s->end_3d_m / s->path_m : (double)NAN;
    }
}

/* ",%.Nf" of v, or "," alone when v is not defined (NaN) */
static void stride_field(FILE *f, int prec, double v)
{
    if (isfinite(v)) {
        fprintf(f, ",%.*f", prec, v);
    } else {
        fputc(',', f);
    }
}

int hx_nav_write_strides(FILE *f, const hx_traj_t *t)
{
    size_t *mid = NULL, *start = NULL, n = 0, p = 0, k, i, first = 0;
    double ref_b[3] = { 1.0, 0.0, 0.0 }, fs_prev = (double)NAN;
    if (!t->events) {
        return -1;
    }
    while (first < t->n && !(t->f[first].flags & FNAV_FRAME_ALIGNED)) {
        first++;
    }
    if (first < t->n) {
        mid = (size_t *)malloc((t->n + 1) * sizeof *mid);
        start = (size_t *)malloc((t->n + 1) * sizeof *start);
        if (mid == NULL || start == NULL) {
            free(mid);
            free(start);
            return -1;
        }
        /* the stance mid-points of the summary's distance */
        n = hx_nav_stance_phases(t, mid, start, t->n + 1);
        heading_ref(t, first, ref_b);
    }
    fprintf(f, "stride,foot_off_s,foot_strike_s,swing_start_s,swing_end_s,swing_s,stance_s,stride_time_s,cadence_spm,"
               "length_m,height_change_m,heading_change_deg,clearance_m\n");
    for (k = 0; k < t->nev; k++) {
        const hx_stride_ev_t *e = &t->ev[k];
        const double fo = e->have_fo ? 1e-9 * (double)(e->fo_t_ns - t->t0_ns) : (double)NAN;
        const double fs = 1e-9 * (double)(e->fs_t_ns - t->t0_ns);
        double len = (double)NAN, dh = (double)NAN, dpsi = (double)NAN, clear = (double)NAN;
        /* the stance phase this swing ended begins at its frame; the one
         * before it began the swing, with every frame between navigated */
        while (p < n && start[p] < e->frame) {
            p++;
        }
        if (p > 0 && p < n && start[p] == e->frame) {
            for (i = start[p - 1]; i <= e->frame && (t->f[i].flags & FNAV_FRAME_ALIGNED); i++) {
            }
            if (i > e->frame) {
                const fnav_nav_frame_t *a = &t->f[mid[p - 1]], *b = &t->f[mid[p]];
                const double dx = (double)b->pos_m[0] - (double)a->pos_m[0];
                const double dy = (double)b->pos_m[1] - (double)a->pos_m[1];
                const double dz = (double)b->pos_m[2] - (double)a->pos_m[2], l2 = dx * dx + dy * dy;
                double ya, yb;
                len = sqrt(l2);
                dh = 0.0 - dz; /* n is z down */
                if (heading_of(ref_b, a, &ya) && heading_of(ref_b, b, &yb)) {
                    dpsi = wrap_step(yb - ya) * 180.0 / M_PI;
                }
                /* the height above the line from a to b, at the point of the
                 * line the frame's horizontal position projects to */
                for (i = mid[p - 1]; i <= mid[p]; i++) {
                    const fnav_nav_frame_t *g = &t->f[i];
                    if (g->t_ns >= e->swing_t0_ns && g->t_ns < e->swing_t1_ns) {
                        double u = l2 > 0.0 ? (((double)g->pos_m[0] - (double)a->pos_m[0]) * dx +
                                               ((double)g->pos_m[1] - (double)a->pos_m[1]) * dy) / l2
                                            : 0.0;
                        double h;
                        u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
                        h = ((double)a->pos_m[2] + u * dz) - (double)g->pos_m[2];
                        clear = isfinite(clear) && clear >= h ? clear : h;
                    }
                }
            }
        }
        fprintf(f, "%lu", (unsigned long)(k + 1));
        stride_field(f, 6, fo);
        stride_field(f, 6, fs);
        stride_field(f, 6, 1e-9 * (double)(e->swing_t0_ns - t->t0_ns));
        stride_field(f, 6, 1e-9 * (double)(e->swing_t1_ns - t->t0_ns));
        /* a swing shorter than the two searches (0.3 s each) can put the
         * foot-off at or after the foot-strike: no swing time then (it read
         * 0 or negative, down to -0.24 s, in 8 of ipol's 515 rows) */
        stride_field(f, 6, fs > fo ? fs - fo : (double)NAN);
        /* the stance of this gait cycle: from the previous foot-strike to
         * this foot-off (stance + swing = stride time); none where the
         * swing has none: from a foot-off not before the foot-strike it
         * would read the whole stride time or more (0.87 s of a 0.68 s stride,
         * ipol 3-4 right) */
        stride_field(f, 6, fo > fs_prev && fs > fo ? fo - fs_prev : (double)NAN);
        stride_field(f, 6, fs - fs_prev);
        stride_field(f, 3, 120.0 / (fs - fs_prev));
        stride_field(f, 4, len);
        stride_field(f, 4, dh);
        stride_field(f, 2, dpsi);
        stride_field(f, 4, clear);
        fputc('\n', f);
        fs_prev = fs;
    }
    free(mid);
    free(start);
    return ferror(f) ? -1 : 0;
}

/* The long gaps in motion lose HX_NAV_GAP_LOST_FRACTION of it (the gap
 * note; with the time-jump note, hx_nav_gappy). */
static int gaps_lose_motion(const hx_nav_summary_t *s)
{
    return s->motion_s > 0.0 && s->gap_lost_s >= HX_NAV_GAP_LOST_FRACTION * s->motion_s;
}

int hx_nav_gappy(const hx_nav_summary_t *s)
{
    return gaps_lose_motion(s) || s->motion_jumps > 0;
}

int hx_nav_strides_too_short(const hx_nav_summary_t *s)
{
    return s->stride_intervals >= HX_NAV_STRIDE_MIN_N && s->median_stride_s < HX_NAV_STRIDE_MIN_S;
}

int hx_nav_gait_slow(const hx_nav_summary_t *s)
{
    /* a log with almost no motion has its own note, and its motions are no
     * gait (openshoe_square2: 13 cycles of 1.76 s, 1 stride) */
    return s->stride_intervals >= HX_NAV_STRIDE_MIN_N && s->median_stride_s > HX_NAV_SLOW_CYCLE_S &&
           !hx_nav_little_motion(s);
}

/* The shortest ZUPT run, samples, the detector takes at cycles of cycle_s
 * with min_zupt_cycle frac (fnav_stance.c cycle_update): the cycle's samples,
 * at least min_zupt_s's (n_fixed), at most n_max (the look-ahead's; none
 * when 0). */
static long slow_cycle_run_n(double frac, double cycle_s, double rate_hz, long n_fixed, long n_max)
{
    long n = lround(frac * cycle_s * rate_hz);
    n = n > n_fixed ? n : n_fixed;
    return n_max > 0 && n > n_max ? n_max : n;
}

hx_slow_note_t hx_nav_slow_note(const hx_traj_t *t, const hx_nav_summary_t *s, double *run_ms)
{
    const fnav_stance_config_t *sc = t->have_config ? &t->config.stance : &fnav_nav_config_default.stance;
    const long n_fixed = t->zupt_min_n > 0 ? (long)t->zupt_min_n : lround((double)sc->min_zupt_s * t->rate_hz);
    long n, n_max;
    if (!hx_nav_gait_slow(s)) {
        return HX_SLOW_NOTE_NONE;
    }
    /* 0.999: --param min_zupt_cycle=0.02 reads 0.0199999996 in float */
    if ((double)sc->min_zupt_cycle >= 0.999 * HX_NAV_SLOW_CYCLE_FRAC) {
        if (run_ms != NULL) {
            n = slow_cycle_run_n((double)sc->min_zupt_cycle, s->median_stride_s, t->rate_hz, n_fixed,
                                 t->zupt_max_n > 0 ? (long)t->zupt_max_n : 0);
            *run_ms = t->rate_hz > 0.0 ? 1e3 * (double)n / t->rate_hz : 0.0;
        }
        return HX_SLOW_NOTE_CYCLE;
    }
    /* the remedy, the default cycle-scaled run (HX_NAV_SLOW_REMEDY_CYCLE),
     * as the detector would take it at this cycle: its look-ahead (a cycle
     * of FNAV_STANCE_CYCLE_LAG_S, fnav_stance.c set_rate) caps it, and the
     * ring caps that. A fixed min_zupt_s guards as well only when its run
     * is as long: a fixed 50 ms does not at 40 steps/min, whose mid-swing
     * dips last about 55 ms */
    n_max = slow_cycle_run_n(HX_NAV_SLOW_REMEDY_CYCLE, (double)FNAV_STANCE_CYCLE_LAG_S, t->rate_hz, n_fixed, 255);
    if (t->window > 0 && n_max > (long)FNAV_STANCE_MAX_WINDOW - 1 - (long)(t->window - 1) / 2) {
        n_max = (long)FNAV_STANCE_MAX_WINDOW - 1 - (long)(t->window - 1) / 2;
    }
    n = slow_cycle_run_n(HX_NAV_SLOW_REMEDY_CYCLE, s->median_stride_s, t->rate_hz, n_fixed, n_max);
    if (run_ms != NULL) {
        *run_ms = t->rate_hz > 0.0 ? 1e3 * (double)n / t->rate_hz : 0.0;
    }
    return n_fixed >= n ? HX_SLOW_NOTE_NONE : HX_SLOW_NOTE_REMEDY;
}

int hx_nav_coarse_stamps(const fnav_nav_stats_t *st)
{
    return st->samples > 1u && (double)st->duplicates >= HX_NAV_DUP_FRACTION * (double)st->samples;
}

int hx_nav_little_motion(const hx_nav_summary_t *s)
{
    return s->duration_s > 10.0 && s->stance_fraction > 0.9 && s->strides < 3;
}

void hx_nav_print_summary(FILE *f, const char *path, const hx_traj_t *t, const hx_nav_summary_t *s)
{
    const fnav_nav_stats_t *st = &t->stats;
    char shown[4096]; /* a file name's control characters as '?' (hx_line_str), as in the messages */
    fprintf(f, "log               %s\n", hx_line_str(shown, sizeof shown, path));
    if (t->have_config) {
        char cfg[1024];
        hx_nav_config_text(t, cfg, sizeof cfg);
        fprintf(f, "config            %s\n", hx_line_str(shown, sizeof shown, cfg)); /* a profile file's name */
    }
    if (t->in_rate_hz > 0.0) {
        fprintf(f, "resampled         %.1f Hz (1 / the median interval) -> %.1f Hz (%ld duplicate time stamps dropped)",
                t->in_rate_hz, t->rate_hz, t->resample_dropped_dups);
        if (t->n_in_long > 0) {
            /* the input lost samples (an interval over HX_NAV_LONG_GAP_S)
             * that the resampler closes up: the timing line below is the
             * grid's, the motion-gap note the input's (without such gaps
             * the line is as it was; the JSON's input_gaps has the count) */
            fprintf(f, "; the input has %ld gap%s, longest interval %.1f ms", t->in_gaps, t->in_gaps == 1 ? "" : "s",
                    1e3 * t->in_longest_s);
        }
        fputc('\n', f);
    }
    if (t->rate_none && st->samples == 0u) {
        fprintf(f, "rate              none (%s)\n", t->rate_src);
    } else if (t->rate_none) {
        fprintf(f, "rate              none (%s), detector window %d samples\n", t->rate_src, t->window);
    } else {
        fprintf(f, "rate              %.1f Hz%s%s%s, detector window %d samples\n", t->rate_hz,
                t->rate_src[0] ? " (" : "", t->rate_src, t->rate_src[0] ? ")" : "", t->window);
    }
    fprintf(f, "duration          %.2f s, %u samples, %u frames\n", s->duration_s, st->samples, st->frames);
    if (t->input_complete == 0) {
        /* the run stopped early: at a bad line of the log, or at the
         * trajectory output (a closed pipe, a full disk); before the
         * first sample (a log of a header alone) there is nothing to
         * align or sum, said as that (until 2026-12-07 "stopped after 0
         * samples" and "NOT ALIGNED (the run stopped before a still
         * period ...)") */
        if (st->samples == 0u) {
            if (t->output_failed) {
                fprintf(f, "stopped           before the first sample: %s (the error above)\n", t->input_error);
            } else {
                fprintf(f, "stopped           before the first sample, at the input error above: no samples to align "
                           "or navigate\n");
            }
            fprintf(f, "alignment         none: no samples\n");
            return;
        }
        if (t->output_failed) {
            fprintf(f, "stopped           after %u samples: %s (the error above); every figure covers those samples\n",
                    st->samples, t->input_error);
        } else {
            fprintf(f, "stopped           after %u samples, at the input error above; every figure covers those "
                       "samples\n",
                    st->samples);
        }
    }
    if (!t->aligned) {
        if (t->input_complete == 0) {
            fprintf(f, "alignment         NOT ALIGNED (the run stopped before a still period long enough was found)\n");
        } else if (stamps_never_advance(st)) {
            /* not "no still period long enough" under an error naming the
             * stamps */
            fprintf(f, "alignment         NOT ALIGNED (the time stamps never advance: the error above)\n");
        } else {
            fprintf(f, "alignment         NOT ALIGNED (no still period long enough: the error above says what was found)\n");
        }
        return;
    }
    fprintf(f, "alignment         %.2f s still: roll %.2f deg, pitch %.2f deg, |f| %.4f m/s^2",
            (double)t->align.duration_s, (double)t->align.euler_rad.v[0] * 180.0 / M_PI,
            (double)t->align.euler_rad.v[1] * 180.0 / M_PI, (double)fnav_vec3_norm(t->align.accel_mean_mps2));
    if (st->realigned > 0u) {
        fprintf(f, " (renewed %u time%s before the first stride)", st->realigned, st->realigned == 1u ? "" : "s");
    }
    fprintf(f, "; aligned %.2f s into the log\n", s->aligned_at_s);
    fprintf(f, "distance          %.2f m step-to-step (%.2f m horizontal), %.2f m integrated\n", s->path_m,
            s->path_h_m, s->integrated_path_m);
    if (isfinite(s->end_h_pct) && isfinite(s->end_3d_pct)) {
        fprintf(f, "return-to-start   horizontal %.3f m (%.2f %%), 3-D %.3f m (%.2f %%)\n", s->end_h_m, s->end_h_pct,
                s->end_3d_m, s->end_3d_pct);
    } else { /* no step-to-step path (fewer than two stance mid-points): no percentage */
        fprintf(f, "return-to-start   horizontal %.3f m, 3-D %.3f m (no step-to-step path for a percentage)\n",
                s->end_h_m, s->end_3d_m);
    }
    fprintf(f, "end position      x %.3f, y %.3f, z %.3f m (n frame, z down)\n", s->end_pos_m[0], s->end_pos_m[1],
            s->end_pos_m[2]);
    fprintf(f, "vertical drift    %+.3f m (height change, up positive)\n", s->vertical_m);
    fprintf(f, "heading change    %+.1f deg\n", s->heading_change_deg);
    /* stance_fraction's share is of the frames from the alignment on, not
     * of the whole log ("of frames" would read as the log's) */
    fprintf(f, "stance            %ld stride%s, %ld stance phase%s, %.1f %% of aligned frames with ZUPT\n", s->strides,
            s->strides == 1 ? "" : "s", s->stance_phases, s->stance_phases == 1 ? "" : "s", 100.0 * s->stance_fraction);
    if (st->zarus > 0u || st->zaru_gated > 0u) {
        fprintf(f, "ZARU              %u applied, %u skipped by the gate (the foot turned)\n", st->zarus, st->zaru_gated);
    }
    if (hx_nav_little_motion(s)) {
        fprintf(f, "note              almost no motion detected (%.0f %% of frames in stance, %ld stride%s in %.0f s): "
                   "a still log, or motion too gentle for the foot-tuned detector (docs/navigation.md, \"Stance "
                   "detector\")\n",
                100.0 * s->stance_fraction, s->strides, s->strides == 1 ? "" : "s", s->duration_s);
    }
    if (s->longest_stand_s > HX_NAV_LONG_STAND_S && st->zarus == 0u && st->zaru_gated == 0u && s->strides >= 2) {
        /* "between strides" needs two of them: with 0 strides and 1 stance
         * phase the note would contradict the stance line (the threshold
         * detector on openshoe_square2) */
        fprintf(f, "note              the foot stood %.0f s between strides (from %.1f s): with ZUPTs only the heading "
                   "drifts with the gyro bias there; --param zaru=1 --param zaru_after_s=1 holds it (docs/navigation.md, "
                   "\"Zero-velocity update\")\n",
                s->longest_stand_s, s->longest_stand_at_s);
    }
    {
        static const char *const k_ch[6] = { "ax", "ay", "az", "gx", "gy", "gz" };
        char list[160];
        size_t used = 0;
        int ch;
        list[0] = '\0';
        for (ch = 0; ch < 6; ch++) {
            if (t->saturated[ch] > 0 && used < sizeof list) {
                int k = snprintf(list + used, sizeof list - used, "%s%s %ld", used > 0 ? ", " : "", k_ch[ch],
                                 t->saturated[ch]);
                used += k > 0 ? (size_t)k : 0u;
            }
        }
        if (list[0] != '\0') {
            fprintf(f, "note              the input is clipped (flat tops at a channel's extreme; samples there: %s): "
                       "the motion beyond the sensor's range is lost, and distance and heading with it; a wider range "
                       "setting fixes it (bin/harness info, \"saturation\")\n",
                    list);
        }
    }
    if (s->rate_off_fraction > 0.0) {
        fprintf(f, "note              the sample rate changes: %.1f Hz from %.1f s, %.0f %% of the log off the "
                   "detector's %.1f Hz (taken once, from the first intervals): its window and durations are wrong in "
                   "seconds there; split the log or resample it (--rate HZ) (docs/navigation.md, \"Timing\")\n",
                s->rate_change_hz, s->rate_change_at_s, 100.0 * s->rate_off_fraction, t->rate_hz);
    }
    if (t->rate_assumed_hz > 0.0 && s->strides < 3 && s->duration_s > 3.0 && s->stance_fraction < 0.9 &&
        !hx_nav_strides_too_short(s)) {
        /* a walk of six bare numbers a line at another rate, read at the
         * OpenShoe set's 820 Hz: a simulated 60 s walk at 100 Hz read so
         * made 0 strides in 7.3 s (too few cycles for the note below) */
        fprintf(f, "note              the rate is assumed, %.0f Hz (the OpenShoe set's: the log has no time stamps), "
                   "and the foot moves in %.0f %% of the aligned frames with %ld stride%s in %.1f s: a log recorded "
                   "at another rate is read too fast or too slow by the ratio of the two, and its strides are lost; "
                   "give its rate with --input-rate HZ\n",
                t->rate_assumed_hz, 100.0 * (1.0 - s->stance_fraction), s->strides, s->strides == 1 ? "" : "s",
                s->duration_s);
    }
    if (hx_nav_strides_too_short(s)) {
        fprintf(f, "note              the gait cycles last %.2f s (median of %ld, from one motion of the foot to the "
                   "next), %.0f steps/min: faster than any foot (a sprint is about 280); the time axis is compressed: "
                   "is the rate right? (%.1f Hz, above; a log without time stamps has an assumed one: give the rate "
                   "with --input-rate HZ)\n",
                s->median_stride_s, s->stride_intervals, 120.0 / s->median_stride_s, t->rate_hz);
    }
    {
        double slow_run_ms = 0.0;
        const hx_slow_note_t slow_note = hx_nav_slow_note(t, s, &slow_run_ms);
        if (slow_note == HX_SLOW_NOTE_CYCLE) {
            /* min_zupt_cycle in effect (--param min_zupt_cycle): the run
             * follows the cycle; naming min_zupt_s=0.05 there was redundant, and
             * that breaks a jogger */
            fprintf(f, "note              the gait cycles last %.2f s (median of %ld), %.0f steps/min: a slow gait, where "
                       "the foot's deceleration before landing can pass for a short stance; the shortest ZUPT run follows "
                       "the cycle (min_zupt_cycle %g: %.0f ms at this cycle) and guards against it, but not in the first "
                       "strides after a start or a stand (docs/harness.md, \"Slow walking, real walks played slower\")\n",
                    s->median_stride_s, s->stride_intervals, 120.0 / s->median_stride_s,
                    (double)(t->have_config ? t->config.stance.min_zupt_cycle
                                            : fnav_nav_config_default.stance.min_zupt_cycle),
                    slow_run_ms);
        } else if (slow_note == HX_SLOW_NOTE_REMEDY) {
            fprintf(f, "note              the gait cycles last %.2f s (median of %ld), %.0f steps/min: a slow gait, where "
                       "the foot's deceleration before landing can pass for a short stance and its ZUPT take speed out of "
                       "the swing (the strides read short; real walks played this slow lost up to a third of their "
                       "length); the default shortest ZUPT run, scaled with the cycle (--param min_zupt_cycle=%g: "
                       "%.0f ms at this cycle), guards against it; a fixed --param min_zupt_s shorter than that (%.0f ms "
                       "here) may not, as the dips grow longer in a slower gait (docs/harness.md, \"Slow walking, real "
                       "walks played slower\")\n",
                    s->median_stride_s, s->stride_intervals, 120.0 / s->median_stride_s, HX_NAV_SLOW_REMEDY_CYCLE,
                    slow_run_ms,
                    t->zupt_min_n > 0 && t->rate_hz > 0.0
                        ? 1e3 * (double)t->zupt_min_n / t->rate_hz
                        : 1e3 * (double)(t->have_config ? t->config.stance.min_zupt_s
                                                        : fnav_nav_config_default.stance.min_zupt_s));
        }
    }
    if (hx_nav_coarse_stamps(st)) {
        fprintf(f, "note              %.1f %% of the samples repeat the time stamp before them (dt = 0; longest "
                   "interval %.1f ms): the stamps are coarser than the sampling (float32 seconds far from 0? a "
                   "millisecond clock above 1 kHz? one stamp for each packet of samples?); a repeated sample is not integrated and the detector's rate "
                   "comes from the stamps, so position and heading are unreliable: %s\n",
                100.0 * (double)st->duplicates / (double)st->samples, 1e3 * (double)st->max_gap_seen_s,
                coarse_stamps_remedy(t->in_format));
    }
    if (s->motion_jumps > 0) {
        fprintf(f, "note              %ld time jump%s while the foot moved (%.3f s lost; a jump is an interval over "
                   "max_gap_s, %.0f ms): the motion inside is not measured, and the walk goes on from the state "
                   "before it, so position and heading after it are unreliable (a logger's dropout? docs/harness.md, "
                   "\"replay\")\n",
                s->motion_jumps, s->motion_jumps == 1 ? "" : "s", s->jump_lost_s, 1e3 * t->max_gap_s);
    }
    if (gaps_lose_motion(s)) {
        fprintf(f, "note              %.1f %% of the time in motion is lost in %ld gap%s longer than %.0f ms (longest "
                   "%.1f ms): the strapdown interpolates across each from the readings at its ends, so the motion "
                   "inside is not measured and position and heading are unreliable (docs/harness.md, \"replay\")\n",
                100.0 * s->gap_lost_s / s->motion_s, s->long_gaps, s->long_gaps == 1 ? "" : "s",
                1e3 * HX_NAV_LONG_GAP_S, 1e3 * s->longest_motion_gap_s);
    }
    if (s->before_align_s > HX_NAV_LATE_ALIGN_S) {
        fprintf(f, "note              the detector saw %.1f s of motion before the alignment (%.2f s into the log): that "
                   "part of the walk is not navigated (the log starts while moving?)\n",
                s->before_align_s, s->aligned_at_s);
    }
    if (t->axes.problem) {
        fprintf(f, "axes              MISMATCH: swings end at %.2f m/s as recorded, %.2f m/s with the gyro read as %s "
                   "(the warning above)\n",
                t->axes.v_recorded_mps, t->axes.v_best_mps, t->axes.best_map);
    } else {
        fprintf(f, "axes              %s\n", t->axes.msg);
    }
    fprintf(f, "timing            %u duplicate%s (dt = 0), %u gap%s, %u time jump%s, longest interval %.1f ms\n",
            st->duplicates, st->duplicates == 1u ? "" : "s", st->gaps, st->gaps == 1u ? "" : "s", st->time_jumps,
            st->time_jumps == 1u ? "" : "s", 1e3 * (double)st->max_gap_seen_s);
    if (t->stamps_coarse && st->gaps > 0u) {
        /* an 820 Hz log stamped to the millisecond reads 1 and 2 ms: the
         * navigator counts every 2 ms interval as a gap (it integrates each
         * sample's own dt, so the sum of the intervals is right) */
        fprintf(f, "                  (the time stamps are coarser than the %.4g Hz sample period, so single "
                   "intervals that read two stamp steps count as gaps although no sample is lost; bin/harness "
                   "info counts the lost ones)\n",
                t->rate_hz);
    }
    fprintf(f, "health            %u NaN/Inf rejected, %u out of range rejected, %u backwards rejected, %u jitter, "
               "%u covariance reset%s, %u undone, %u update%s rejected, %u covariance guard, %u divergence reset%s\n",
            st->nan_inputs, st->range_inputs, st->time_back, st->chol_jitter, st->chol_reset, st->chol_reset == 1u ? "" : "s",
            st->diverged, st->update_reject, st->update_reject == 1u ? "" : "s", st->cov_guard, st->resets,
            st->resets == 1u ? "" : "s");
}

static cJSON *num(double v)
{
    return isfinite(v) ? cJSON_CreateNumber(v) : cJSON_CreateNull();
}

int hx_nav_write_json(const char *json_path, const char *log_path, const char *command, const hx_traj_t *t,
                      const hx_nav_summary_t *s, struct cJSON *extra, char *err, size_t err_size)
{
    cJSON *root = cJSON_CreateObject(), *h = cJSON_CreateObject(), *arr;
    const fnav_nav_stats_t *st = &t->stats;
    int k, rc;
    cJSON_AddStringToObject(root, "log", log_path);
    cJSON_AddStringToObject(root, "command", command);
    /* null for one sample (rate_none), as the text's "none" */
    cJSON_AddItemToObject(root, "rate_hz", num(t->rate_none ? (double)NAN : t->rate_hz));
    cJSON_AddItemToObject(root, "input_rate_hz",
                          num(t->rate_none ? (double)NAN : t->in_rate_hz > 0.0 ? t->in_rate_hz : t->rate_hz));
    cJSON_AddItemToObject(root, "rate_assumed_hz", num(t->rate_assumed_hz > 0.0 ? t->rate_assumed_hz : (double)NAN));
    if (t->in_rate_hz > 0.0) {
        /* --rate: the input's own gaps, closed up by the resampler (health's
         * are the grid's) */
        cJSON_AddNumberToObject(root, "input_gaps", (double)t->in_gaps);
        cJSON_AddItemToObject(root, "input_longest_interval_s", num(t->in_longest_s));
    }
    cJSON_AddNumberToObject(root, "window_samples", t->window);
    if (t->have_config) {
        /* the configuration that ran, as the summary's config line (not
         * only `command` names it) */
        const fnav_nav_config_t *c = &t->config;
        cJSON *pa = cJSON_CreateArray();
        int i;
        cJSON_AddStringToObject(root, "profile", c->profile.name);
        cJSON_AddItemToObject(root, "profile_file", t->profile_file[0] ? cJSON_CreateString(t->profile_file)
                                                                       : cJSON_CreateNull());
        cJSON_AddStringToObject(root, "bias_model", bias_model_name(c));
        cJSON_AddStringToObject(root, "detector", detector_name(c));
        cJSON_AddBoolToObject(root, "adaptive_threshold", c->stance.adaptive);
        cJSON_AddStringToObject(root, "samples", samples_name(c));
        cJSON_AddBoolToObject(root, "lever", c->lever);
        cJSON_AddBoolToObject(root, "settling", c->settle);
        cJSON_AddBoolToObject(root, "zaru", c->zaru);
        for (i = 0; i < t->nparams; i++) {
            cJSON_AddItemToArray(pa, cJSON_CreateString(t->params[i]));
        }
        cJSON_AddItemToObject(root, "params", pa);
    }
    cJSON_AddBoolToObject(root, "aligned", t->aligned);
    if (t->input_complete >= 0) {
        /* as info's and psd's: a log cut short shows in the JSON, not only
         * in the exit status */
        cJSON_AddBoolToObject(root, "complete", t->input_complete);
        if (!t->input_complete) {
            cJSON_AddStringToObject(root, "error", t->input_error);
        }
    }
    cJSON_AddItemToObject(root, "duration_s", num(s->duration_s));
    cJSON_AddItemToObject(root, "distance_m", num(s->path_m));
    cJSON_AddItemToObject(root, "distance_horizontal_m", num(s->path_h_m));
    cJSON_AddItemToObject(root, "integrated_path_m", num(s->integrated_path_m));
    cJSON_AddItemToObject(root, "return_error_h_m", num(s->end_h_m));
    cJSON_AddItemToObject(root, "return_error_3d_m", num(s->end_3d_m));
    cJSON_AddItemToObject(root, "return_error_h_pct", num(s->end_h_pct));
    cJSON_AddItemToObject(root, "return_error_3d_pct", num(s->end_3d_pct));
    cJSON_AddItemToObject(root, "vertical_drift_m", num(s->vertical_m));
    cJSON_AddItemToObject(root, "heading_change_deg", num(s->heading_change_deg));
    arr = cJSON_CreateArray();
    for (k = 0; k < 3; k++) {
        cJSON_AddItemToArray(arr, num(s->end_pos_m[k]));
    }
    cJSON_AddItemToObject(root, "end_position_m", arr);
    cJSON_AddNumberToObject(root, "strides", (double)s->strides);
    cJSON_AddNumberToObject(root, "stance_phases", (double)s->stance_phases);
    cJSON_AddItemToObject(root, "stance_fraction", num(s->stance_fraction));
    cJSON_AddItemToObject(root, "aligned_at_s", num(s->aligned_at_s));
    cJSON_AddItemToObject(root, "before_alignment_s", num(s->before_align_s));
    cJSON_AddItemToObject(root, "longest_stand_s", num(s->longest_stand_s));
    {
        /* the summary's gait-cycle note (hx_nav_strides_too_short) */
        cJSON *gc = cJSON_CreateObject();
        cJSON_AddItemToObject(gc, "median_s", num(s->stride_intervals > 0 ? s->median_stride_s : (double)NAN));
        cJSON_AddNumberToObject(gc, "intervals", (double)s->stride_intervals);
        cJSON_AddBoolToObject(gc, "too_short", hx_nav_strides_too_short(s));
        /* the gait is slow (hx_nav_gait_slow), whatever the settings; the
         * summary's note says what guards against it (hx_nav_slow_note) */
        cJSON_AddBoolToObject(gc, "slow", hx_nav_gait_slow(s));
        cJSON_AddItemToObject(root, "gait_cycles", gc);
    }
    {
        static const char *const k_ch[6] = { "ax", "ay", "az", "gx", "gy", "gz" };
        cJSON *sat = cJSON_AddObjectToObject(root, "saturated_samples");
        int ch;
        for (ch = 0; ch < 6 && sat != NULL; ch++) {
            cJSON_AddNumberToObject(sat, k_ch[ch], (double)t->saturated[ch]);
        }
    }
    {
        /* lost samples in motion (HX_NAV_LONG_GAP_S) */
        cJSON *g = cJSON_CreateObject();
        cJSON_AddItemToObject(g, "motion_s", num(s->motion_s));
        cJSON_AddItemToObject(g, "lost_s", num(s->gap_lost_s));
        cJSON_AddItemToObject(g, "lost_fraction", num(s->motion_s > 0.0 ? s->gap_lost_s / s->motion_s : (double)NAN));
        cJSON_AddNumberToObject(g, "gaps", (double)s->long_gaps);
        cJSON_AddItemToObject(g, "longest_s", num(s->longest_motion_gap_s));
        cJSON_AddNumberToObject(g, "jumps_in_motion", (double)s->motion_jumps);
        cJSON_AddItemToObject(g, "jump_lost_s", num(s->jump_lost_s));
        cJSON_AddBoolToObject(g, "unreliable", hx_nav_gappy(s));
        cJSON_AddItemToObject(root, "motion_gaps", g);
    }
    {
        /* the summary's coarse-stamp note (hx_nav_coarse_stamps); the
         * count is health's duplicates */
        cJSON *sp = cJSON_CreateObject();
        cJSON_AddItemToObject(sp, "duplicate_fraction",
                              num(st->samples > 0u ? (double)st->duplicates / (double)st->samples : (double)NAN));
        cJSON_AddBoolToObject(sp, "coarse", hx_nav_coarse_stamps(st));
        cJSON_AddItemToObject(root, "stamps", sp);
    }
    if (s->rate_off_fraction > 0.0) {
        cJSON *chg = cJSON_CreateObject();
        cJSON_AddItemToObject(chg, "at_s", num(s->rate_change_at_s));
        cJSON_AddItemToObject(chg, "rate_hz", num(s->rate_change_hz));
        cJSON_AddItemToObject(chg, "off_fraction", num(s->rate_off_fraction));
        cJSON_AddItemToObject(root, "rate_change", chg);
    } else {
        cJSON_AddItemToObject(root, "rate_change", cJSON_CreateNull());
    }
    {
        cJSON *ax = cJSON_CreateObject();
        int checked = t->axes.best_map[0] != '\0';
        cJSON_AddNumberToObject(ax, "swings", (double)t->axes.swings);
        cJSON_AddItemToObject(ax, "v_recorded_mps", num(checked ? t->axes.v_recorded_mps : (double)NAN));
        cJSON_AddItemToObject(ax, "v_best_mps", num(checked ? t->axes.v_best_mps : (double)NAN));
        cJSON_AddItemToObject(ax, "v_other_mps", num(checked ? t->axes.v_other_mps : (double)NAN));
        cJSON_AddItemToObject(ax, "best_map", checked ? cJSON_CreateString(t->axes.best_map) : cJSON_CreateNull());
        cJSON_AddItemToObject(ax, "problem", checked ? cJSON_CreateBool(t->axes.problem) : cJSON_CreateNull());
        cJSON_AddItemToObject(ax, "v_scaled_mps", num(checked ? t->axes.v_scaled_mps : (double)NAN));
        cJSON_AddItemToObject(ax, "time_scale", num(checked ? t->axes.time_scale : (double)NAN));
        cJSON_AddItemToObject(ax, "time_problem", checked ? cJSON_CreateBool(t->axes.time_problem) : cJSON_CreateNull());
        cJSON_AddStringToObject(ax, "message", t->axes.msg);
        cJSON_AddItemToObject(root, "axes", ax);
    }
    if (t->units_checked) {
        /* as info's: the units check's message, null when the values look
         * like SI (no key when it did not run: live, a replay stopped early) */
        cJSON_AddItemToObject(root, "units_problem", t->units_problem[0] != '\0'
                                                         ? cJSON_CreateString(t->units_problem)
                                                         : cJSON_CreateNull());
    }
    cJSON_AddNumberToObject(h, "samples", st->samples);
    cJSON_AddNumberToObject(h, "frames", st->frames);
    cJSON_AddNumberToObject(h, "nan_rejected", st->nan_inputs);
    cJSON_AddNumberToObject(h, "range_rejected", st->range_inputs);
    cJSON_AddNumberToObject(h, "backwards_rejected", st->time_back);
    cJSON_AddNumberToObject(h, "duplicates", st->duplicates);
    cJSON_AddNumberToObject(h, "gaps", st->gaps);
    cJSON_AddNumberToObject(h, "time_jumps", st->time_jumps);
    cJSON_AddItemToObject(h, "longest_interval_s", num((double)st->max_gap_seen_s));
    cJSON_AddNumberToObject(h, "zupts", st->zupts);
    cJSON_AddNumberToObject(h, "zarus", st->zarus);
    cJSON_AddNumberToObject(h, "zaru_gated", st->zaru_gated);
    cJSON_AddNumberToObject(h, "realigned", st->realigned);
    cJSON_AddNumberToObject(h, "chol_jitter", st->chol_jitter);
    cJSON_AddNumberToObject(h, "chol_reset", st->chol_reset);
    cJSON_AddNumberToObject(h, "steps_undone", st->diverged);
    cJSON_AddNumberToObject(h, "updates_rejected", st->update_reject);
    cJSON_AddNumberToObject(h, "covariance_guard", st->cov_guard);
    cJSON_AddNumberToObject(h, "divergence_resets", st->resets);
    cJSON_AddNumberToObject(h, "health_bits", t->n > 0 ? (double)t->f[t->n - 1].health : 0.0);
    cJSON_AddItemToObject(root, "health", h);
    if (extra != NULL) {
        while (extra->child != NULL) {
            cJSON *item = cJSON_DetachItemViaPointer(extra, extra->child);
            cJSON_AddItemToObject(root, item->string, item); /* the key string is copied */
        }
        cJSON_Delete(extra);
    }
    rc = hx_write_json(json_path, root, err, err_size);
    cJSON_Delete(root);
    return rc;
}

int hx_nav_plot(const char *cmd, const char *png, const char *title, const hx_traj_t *t)
{
    hx_plot_t p;
    size_t i;
    char q[2048]; /* the title, its quotes doubled */
    if (hx_plot_open(&p, cmd, png, 1200, 600) != 0) {
        return -1;
    }
    size_t naligned = 0;
    for (i = 0; i < t->n; i++) {
        naligned += (t->f[i].flags & FNAV_FRAME_ALIGNED) != 0u;
    }
    fprintf(p.gp, "set multiplot layout 1,2 title '%s'\n", hx_gp_str(q, sizeof q, title));
    if (naligned == 0) {
        /* nothing navigated (a log that never aligned, or an error before
         * it): two empty panels that say so; gnuplot refuses a plot without
         * a valid point, and would leave the png half drawn with exit 3 */
        fprintf(p.gp, "set xlabel '" HX_PLOT_PATH_XLABEL "'\nset ylabel '" HX_PLOT_PATH_YLABEL "'\n"
                      "set xrange [-1:1]\nset yrange [-1:1]\n"
                      "set title 'no aligned frame: nothing navigated'\nplot -2 notitle\n"
                      "set xlabel 'time (s)'\nset ylabel 'height (m, up)'\nset title 'no aligned frame'\n"
                      "plot -2 notitle\nunset multiplot\n");
        return hx_plot_close(&p, cmd);
    }
    /* n's axes (docs/frames.md): no magnetometer, so not north and east */
    fprintf(p.gp, "set size ratio -1\nset xlabel '" HX_PLOT_PATH_XLABEL "'\nset ylabel '" HX_PLOT_PATH_YLABEL "'\n");
    {
        /* one span on both axes, centred on the path (start included): with
         * equal units alone a straight walk became a strip a few pixels wide
         * whose east tick labels ran into each other */
        double lo[2] = { 0.0, 0.0 }, hi[2] = { 0.0, 0.0 }, span;
        int k;
        for (i = 0; i < t->n; i++) {
            if (t->f[i].flags & FNAV_FRAME_ALIGNED) {
                for (k = 0; k < 2; k++) {
                    double v = (double)t->f[i].pos_m[1 - k];
                    lo[k] = v < lo[k] ? v : lo[k];
                    hi[k] = v > hi[k] ? v : hi[k];
                }
            }
        }
        span = hi[0] - lo[0] > hi[1] - lo[1] ? hi[0] - lo[0] : hi[1] - lo[1];
        span = 1.1 * (span > 0.5 ? span : 0.5);
        fprintf(p.gp, "set xrange [%.4f:%.4f]\nset yrange [%.4f:%.4f]\n", 0.5 * (lo[0] + hi[0] - span),
                0.5 * (lo[0] + hi[0] + span), 0.5 * (lo[1] + hi[1] - span), 0.5 * (lo[1] + hi[1] + span));
    }
    fprintf(p.gp, "plot '-' with lines lw 1 title 'path', '-' with points pt 7 ps 1 title 'start', "
                  "'-' with points pt 5 ps 1 title 'end'\n");
    for (i = 0; i < t->n; i++) {
        if (t->f[i].flags & FNAV_FRAME_ALIGNED) {
            fprintf(p.gp, "%.4f %.4f\n", (double)t->f[i].pos_m[1], (double)t->f[i].pos_m[0]);
        }
    }
    fprintf(p.gp, "e\n0 0\ne\n");
    if (t->n > 0) {
        fprintf(p.gp, "%.4f %.4f\n", (double)t->f[t->n - 1].pos_m[1], (double)t->f[t->n - 1].pos_m[0]);
    }
    fprintf(p.gp, "e\n");
    fprintf(p.gp, "set size noratio\nset autoscale xy\nset xlabel 'time (s)'\nset ylabel 'height (m, up)'\n");
    {
        /* a still log's height is one value (a short log's time too): gnuplot
         * printed "Warning: empty y range" on standard error; at least 0.1 m
         * and 1 s are spanned */
        double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
        const double min_span[2] = { 1.0, 0.1 };
        int k;
        for (i = 0; i < t->n; i++) {
            if (t->f[i].flags & FNAV_FRAME_ALIGNED) {
                const double v[2] = { 1e-9 * (double)(t->f[i].t_ns - t->f[0].t_ns), -(double)t->f[i].pos_m[2] };
                for (k = 0; k < 2; k++) {
                    lo[k] = v[k] < lo[k] ? v[k] : lo[k];
                    hi[k] = v[k] > hi[k] ? v[k] : hi[k];
                }
            }
        }
        for (k = 0; k < 2; k++) {
            if (lo[k] <= hi[k] && hi[k] - lo[k] < min_span[k]) {
                fprintf(p.gp, "set %crange [%.4f:%.4f]\n", k == 0 ? 'x' : 'y', 0.5 * (lo[k] + hi[k] - min_span[k]),
                        0.5 * (lo[k] + hi[k] + min_span[k]));
            }
        }
    }
    fprintf(p.gp, "plot '-' with lines lw 1 title 'height'\n");
    for (i = 0; i < t->n; i++) {
        if (t->f[i].flags & FNAV_FRAME_ALIGNED) {
            fprintf(p.gp, "%.4f %.4f\n", 1e-9 * (double)(t->f[i].t_ns - t->f[0].t_ns), -(double)t->f[i].pos_m[2]);
        }
    }
    fprintf(p.gp, "e\nunset multiplot\n");
    return hx_plot_close(&p, cmd);
}
