/* harness allan: streaming Allan deviation of every channel of a log (or of
 * one column of numbers), noise types, the paper's and the corrected
 * bias-model identification, the Fig. 7 simulation check, table, JSON,
 * plot and profile (docs/allan.md). */
#include <cjson/cJSON.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include "footnav/fnav_allan.h"
#include "hx_allan_ident.h"
#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_devs.h"
#include "hx_nav.h"
#include "hx_profile.h"

#define CMD "allan"
#define NCH_MAX 6
#define GRID_MAX 160
#define NCHUNK_MAX ((GRID_MAX + FNAV_ALLAN_MAX_POINTS - 1) / FNAV_ALLAN_MAX_POINTS)
#define RAD2DEG 57.29577951308232

static const hx_opt_t k_opts[] = {
    HX_INPUT_OPTS,
    { "--series", "FILE", "analyse one column of numbers (any unit) instead of a log", 0 },
    { "--phase", NULL, "the series is a phase (integral): analyse its differences x rate", 0 },
    { "--rate", "HZ", "sample rate (needed with --series; overrides a log's rate)", 0 },
    { "--unit", "TEXT", "unit of a series, for labels (default 'u'; a log's are m/s^2 and deg/s)", 0 },
    { "--column", "N", "take the N-th number of each line of a series (columns split by blanks or a comma; "
                       "default: one number per line)", 0 },
    { "--fractional", "F0", "the series is a frequency around F0 (e.g. Hz): analyse (f - F0) / F0, the fractional "
                             "frequency", 0 },
    { "--estimator", "NAME", "exact (the whole record, fully overlapping at every tau, in double, as Stable32; "
                             "default for --series) or streaming (the core's fixed-memory estimator, as on the "
                             "sensor; default for a log)", 0 },
    { "--deviation", "LIST", "also these deviations of the whole record (needs --estimator exact): mdev, tdev, hdev, "
                             "ohdev, totdev, pdev (parabolic), mtotdev, ttotdev, htotdev (the total forms of mdev, "
                             "tdev and hdev), or all; each with its interval and term count (adev and oadev are "
                             "always in the table)", 0 },
    { "--max-work", "N", "largest number of window terms (starts x 6m) computed for one tau of mtotdev, ttotdev or "
                         "htotdev, whose cost grows as n m (default 2e8, about a second); larger tau are left out "
                         "and say so", 0 },
    { "--m", "LIST", "averaging factors instead of the log-spaced grid, ascending, e.g. 1,10,100 (needs "
                     "--estimator exact)", 0 },
    { "--channels", "LIST", "channels of a log to analyse, e.g. gx,gy,gz (default ax,ay,az,gx,gy,gz)", 0 },
    { "--per-octave", "N", "tau points per octave: 1, 2 or 4 (default 4)", 0 },
    { "--max-tau-frac", "F", "largest tau identified, printed and plotted, as a fraction of the record "
                             "(default 0.1, the paper's 10 %); --out and --json tabulate every tau with terms, "
                             "beyond it too", 0 },
    { "--fit-extra", NULL, "corrected fit also with quantisation and rate random walk terms", 0 },
    { "--no-sim", NULL, "skip the simulation check (paper Fig. 7)", 0 },
    { "--sim-samples", "N", "samples per simulation (default: as many as the input)", 0 },
    { "--seed", "N", "random seed of the simulations (default 1)", 0 },
    { "--refits", "N", "interval of the corrected fit: simulate the fitted model N times (N >= 2; default 0, "
                       "off) at the record's length (or --sim-samples; also with --no-sim), refit each the same "
                       "way, and print the central --conf share (default 68.3 %) of sigma_v, tau and sigma_bias "
                       "(a parametric bootstrap; channels whose AR(1) part is identified)", 0 },
    { "--conf", "P", "confidence of the intervals (default 0.682689 = erf(1/sqrt(2)), one sigma, Stable32's "
                     "0.683)", 0 },
    { "--name", "TEXT", "profile name (default: from the file name)", 0 },
    { "--out", "FILE", "table of every channel and tau (CSV; '-': standard output, the text then on standard error)", 0 },
    { "--json", "FILE", "parameters, quality and tables (JSON; '-': standard output, the text then on standard "
                        "error; not with --out -)", 0 },
    { "--plot", "FILE", "Allan deviation plot (PNG): measured with confidence bars, simulated", 0 },
    { "--profile", "FILE", "write the corrected identification as a footnav profile", 0 },
    { "--quiet", NULL, "print only the parameter table", 0 },
    { "--paper-tables", NULL, "check the paper's Tables IV-VI against its eqs. (4) and (6) (no input)", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    CMD, "LOG [options]   |   harness allan --series FILE --rate HZ [options]",
    "Streaming Allan deviation (overlapping and non-overlapping, fixed memory per\n"
    "channel as on the sensor) of every channel of a log, with confidence\n"
    "intervals (Greenhall EDF), the noise type per tau region, and the bias model\n"
    "identified twice: as in the paper (III.C: sigma_v = ADEV at 1 s, BS at the\n"
    "minimum, tau = t_BS f_s, sigma_bias = BS / sqrt(tau)) and corrected (weighted\n"
    "least-squares fit of the white + AR(1) Allan variance). Both models are\n"
    "simulated and run through the same estimator (the paper's Fig. 7 check).\n"
    "Parameters are printed in the units of the paper's Tables IV-VI (m/s^2,\n"
    "deg/s; tau in samples at the log's rate). --profile writes the corrected model\n"
    "for `harness replay --profile` (docs/profile-format.md); where its AR(1) part\n"
    "is not identified, the bound printed under the parameter table instead. It\n"
    "needs a log at rest: one that moves, even for a second (handled at its start),\n"
    "gets no profile, exit 1, and the message names the `harness convert` command\n"
    "that cuts it to its still part.",
    0, 1, k_opts
};

typedef struct {
    const char *name, *label, *unit;
    int src;         /* 0..5: ax ay az gx gy gz; -1: series */
    double scale;    /* SI -> display */
    fnav_allan_t *est[NCHUNK_MAX];
    fnav_allan_result_t res[GRID_MAX];
    fnav_real_t slope[GRID_MAX];
    fnav_allan_noise_t noise[GRID_MAX];
    unsigned char periodic[GRID_MAX]; /* the slope's -1 is a periodic term's fall (hx_allan_mark_periodic) */
    int alpha[GRID_MAX];      /* power-law exponent behind the EDF */
    hx_noise_id_t alpha_from[GRID_MAX]; /* how alpha was found: from the data (exact) or the slope */
    double edf[GRID_MAX], lo[GRID_MAX], hi[GRID_MAX];
    double edf_n[GRID_MAX], lo_n[GRID_MAX], hi_n[GRID_MAX];
    fnav_allan_result_t sim_paper[GRID_MAX], sim_fit[GRID_MAX];
    int have_sim_paper, have_sim_fit;
    size_t nres;
    double *x;       /* --estimator exact: the phase record x_0 .. x_n (sample units) */
    size_t nx, capx;
    double y0;       /* first sample, removed from the record (the variance ignores a constant) */
    hx_allan_ident_t id;
    int id_ok;
    int constant;    /* every tau with terms has variance 0: a stuck or disconnected channel */
    double v_first;  /* the first value pushed, and whether a later one differed from it */
    int varied;
    double spread;   /* the largest |value - first value| (exact estimator's underflow check) */
    double avar_least; /* least positive Allan variance (display units; the exact one in double); INFINITY: none */
    double avar_most;  /* the exact estimator's largest Allan variance (display units, double); 0: none */
    int underflow;     /* avar_least is below the float build's normal range: digits lost; 2: the exact
                        * estimator's double range (a spread whose square underflows) */
    /* --deviation: per deviation kind and grid point (display units; TDEV in unit s) */
    double dv[HX_DEV_COUNT][GRID_MAX], dv_lo[HX_DEV_COUNT][GRID_MAX], dv_hi[HX_DEV_COUNT][GRID_MAX];
    double dv_edf[HX_DEV_COUNT][GRID_MAX];
    uint32_t dv_terms[HX_DEV_COUNT][GRID_MAX];
    unsigned char dv_skip[HX_DEV_COUNT][GRID_MAX]; /* not computed: 1 over --max-work, 2 interrupted (a signal) */
    /* --refits: the parametric bootstrap of the corrected fit (refit_channel()) */
    int refitted;        /* 1: its refits ran to the end (0: not eligible, none asked, interrupted, or out of memory) */
    int rf_oom;          /* 1: its refits stopped out of memory (said; exit 1) */
    int rf_ok, rf_fit_failed, rf_unresolved; /* refits fitted with their AR(1) identified; fit failed; AR(1) not */
    double rf_ci[3][2];  /* sigma_v, tau (samples), sigma_bias: the (1 -+ conf) / 2 percentiles (NAN: < 2 ok) */
} chan_t;

typedef struct {
    chan_t ch[NCH_MAX];
    int nch;
    uint32_t grid[GRID_MAX];
    size_t ngrid;
    fnav_allan_config_t cfg[NCHUNK_MAX];
    int nchunk;
    double rate_hz;
    uint32_t n;              /* samples pushed per channel */
    uint32_t nsim;           /* samples per Fig. 7 simulation (0: none run) */
    long refits;             /* --refits: simulations of each channel's corrected fit (0: off) */
    uint32_t nrefit;         /* samples per refit's simulation */
    double tau_max_frac;
    double conf;
    const char *source;
    char sensor[64];
    char sensor_text[80]; /* the text header's: the sensor, or "FORMAT log" when the log names none */
    int is_series;
    int exact;               /* --estimator exact */
    int m_given;             /* --m: its every m is printed, not the octave ones only */
    double f0;               /* --fractional: nominal value, 0 if not given */
    hx_dev_t dev[HX_DEV_COUNT]; /* --deviation, in the order given */
    int ndev;
    double max_work;         /* --max-work: window terms of one tau of an O(n m) deviation */
    double acc_sum[3];       /* a log's specific force summed over the record (units check) */
    double gyro_max;         /* a log's largest |rate| on any axis (units check) */
    int units_bad;           /* the log is not in SI units (hx_units_problem; units_msg says why) */
    char units_msg[768];
    hx_format_t in_fmt;      /* a log's format: the units remedies name --units for the interchange CSV */
    int time_unit_warned;    /* slow_check() warned that the time stamps look like ms, us or ns */
    /* motion check: one-second windows of the log (sums for the spread of
     * the rate and of |f| within each) */
    double win_sum[4], win_sq[4]; /* gx, gy, gz, |f| */
    uint32_t win_fill, win_len;
    long win_off;            /* the open window's samples whose |f| is 2 m/s^2 or more off gravity (hx_walk_off) */
    hx_walk_t walk;          /* the windows that spread as a walk's (hx_walk_window): the units check's walks */
    long win_n, win_moving;
    double win_first_moving_s;
    double *win_spread;      /* every window's rate and |f| spread (RMS), in pairs: the disturbance check */
    size_t win_cap;          /* windows win_spread holds room for */
    int moving;              /* over HX_ALLAN_MOVING_FRAC of the windows move: not a static log */
    char input_error[HX_ERR_SIZE];   /* the error that stopped the input ("": read to its end; input_fail) */
    char interrupted[HX_ERR_SIZE];   /* what a signal left undone ("": not interrupted) */
    hx_progress_t *dev_pr;   /* --deviation: the progress of the deviation tables (NULL: none shown) */
    double dev_done, dev_total; /* their work done and in all (dev_cost units) */
} run_t;

/* R->input_error said: with samples before it, a warning when it is read
 * and an error at the end, as info's, psd's and simgap's (hx_load_input):
 * it was an error here, the analysis then going on under it */
static void say_input_error(const run_t *R)
{
    if (R->n > 0u) {
        hx_warn(CMD, "%s (using the %lu sample%s before it)", R->input_error, (unsigned long)R->n,
                R->n == 1u ? "" : "s");
    } else {
        hx_error(CMD, "%s", R->input_error);
    }
}

/* An error of the input that stops the reading: said, and kept for the
 * JSON's `error` (beside `complete`), so that the JSON tells a record read
 * in part */
static void input_fail(run_t *R, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(R->input_error, sizeof R->input_error, fmt, ap);
    va_end(ap);
    say_input_error(R);
}

/* A window moves when within its second the rate spreads by more than
 * 0.25 rad/s RMS (14 deg/s; a gyro at rest spreads by hundredths) or |f|
 * by more than 0.5 m/s^2 RMS (at rest: hundredths; a foot's swing: metres
 * per second squared). A log with over 10 % of such windows is no static
 * log (a walk: 45-85 %). */
#define HX_ALLAN_MOVING_GYRO_RPS 0.25
#define HX_ALLAN_MOVING_F_MPS2 0.5
#define HX_ALLAN_MOVING_FRAC 0.10

/* A window is disturbed (a touch, a knock on the table: too little to move
 * it by the marks above, enough to raise the Allan curve at short tau and
 * to be fitted as an AR(1) bias) when its rate or |f| spreads by more than
 * this many times the median window's. Judged only with windows of at
 * least HX_ALLAN_DISTURBED_MIN_LEN samples (a spread of a few samples
 * scatters too much) and at least HX_ALLAN_DISTURBED_MIN_WIN windows. */
#define HX_ALLAN_DISTURBED_RATIO 4.0
#define HX_ALLAN_DISTURBED_MIN_LEN 20u
#define HX_ALLAN_DISTURBED_MIN_WIN 10

static const char k_exact_oom[] = "out of memory: --estimator exact keeps the whole record (8 bytes per sample "
                                  "and channel); use --estimator streaming";

static const struct {
    const char *name, *label;
    int gyro;
} k_ch[6] = {
    { "ax", "Acc x", 0 }, { "ay", "Acc y", 0 }, { "az", "Acc z", 0 },
    { "gx", "Gyr x", 1 }, { "gy", "Gyr y", 1 }, { "gz", "Gyr z", 1 },
};

/* ------------------------------------------------------------ setup */

/* Whether the streaming estimator (the simulation check) can track R->grid. */
static int grid_streamable(const run_t *R)
{
    size_t i;
    for (i = 0; i < R->ngrid; i++) {
        if (!fnav_allan_tau_valid(R->grid[i])) {
            return 0;
        }
    }
    return 1;
}

/* A list option (--m, --channels, --deviation): its comma-separated
 * elements as strings in buf, a copy of the list. */
#define LIST_MAX GRID_MAX
typedef struct {
    char buf[2048];
    const char *el[LIST_MAX];
    int n;
} list_t;

/* Split a list option's value into L, refusing an empty element (a comma
 * at either end, or two together) and an element given twice, the option
 * named, for every list option alike: otherwise --m 1,10, and --channels
 * ax, would run as if the comma were not there and --deviation mdev,mdev
 * as mdev. 0, or -1 with the error printed (a usage error). */
static int split_list(const char *opt, const char *list, list_t *L)
{
    const size_t len = strlen(list);
    char *p = L->buf;
    int j;
    L->n = 0;
    if (len >= sizeof L->buf) {
        hx_error(CMD, "%s: list longer than %u characters", opt, (unsigned)(sizeof L->buf - 1u));
        return -1;
    }
    memcpy(L->buf, list, len + 1u);
    for (;;) {
        char *comma = strchr(p, ',');
        if (comma != NULL) {
            *comma = '\0';
        }
        if (*p == '\0') {
            hx_error(CMD, "%s: an empty element in '%s' (a comma at the start or end, or two together)", opt, list);
            return -1;
        }
        for (j = 0; j < L->n; j++) {
            if (strcmp(L->el[j], p) == 0) {
                hx_error(CMD, "%s: '%s' given twice", opt, p);
                return -1;
            }
        }
        if (L->n == LIST_MAX) {
            hx_error(CMD, "%s: more than %d elements", opt, LIST_MAX);
            return -1;
        }
        L->el[L->n++] = p;
        if (comma == NULL) {
            return 0;
        }
        p = comma + 1;
    }
}

/* --m LIST: the averaging factors, strictly ascending, at most GRID_MAX. */
static int parse_m_list(run_t *R, const char *list)
{
    list_t L;
    int i;
    R->ngrid = 0;
    if (split_list("--m", list, &L) != 0) {
        return -1;
    }
    for (i = 0; i < L.n; i++) {
        const char *p = L.el[i];
        char *end;
        unsigned long v;
        if (*p < '0' || *p > '9' || R->ngrid == GRID_MAX) {
            break;
        }
        v = strtoul(p, &end, 10);
        if (*end != '\0' || v == 0ul || v > 4294967295ul || (R->ngrid > 0 && v <= R->grid[R->ngrid - 1u])) {
            break;
        }
        R->grid[R->ngrid++] = (uint32_t)v;
    }
    if (i < L.n || R->ngrid == 0) {
        hx_error(CMD,
                 "--m must be positive whole numbers separated by commas, strictly ascending, at most %d, "
                 "not '%s'",
                 GRID_MAX, list);
        return -1;
    }
    return 0;
}

/* --m: the factors the screen tables leave out, named, not dropped without
 * a word: an m with no Allan term (2 m + 1 phase points needed, the record
 * has n + 1) and one beyond --max-tau-frac (in --out and --json only). */
static double tau_max_samples(const run_t *R);
static void m_dropped(const run_t *R)
{
    char none[512] = "", far[512] = "";
    size_t i, ln = 0u, lf = 0u;
    for (i = 0; i < R->ngrid; i++) {
        const uint32_t m = R->grid[i];
        if (2.0 * (double)m >= (double)R->n + 1.0) {
            if (ln < sizeof none) {
                ln += (size_t)snprintf(none + ln, sizeof none - ln, "%s%lu", ln > 0u ? ", " : "", (unsigned long)m);
            }
        } else if ((double)m > tau_max_samples(R) * (1.0 + 1e-9)) {
            if (lf < sizeof far) {
                lf += (size_t)snprintf(far + lf, sizeof far - lf, "%s%lu", lf > 0u ? ", " : "", (unsigned long)m);
            }
        }
    }
    if (ln > 0u) {
        hx_warn(CMD, "%s: --m %s: too long for the record (an Allan term needs 2 m + 1 phase points, %lu samples "
                     "give %lu): no Allan point, left out of every table",
                R->source, none, (unsigned long)R->n, (unsigned long)R->n + 1ul);
    }
    if (lf > 0u) {
        hx_warn(CMD, "%s: --m %s: beyond --max-tau-frac %g of the record (%.6g samples): not printed nor "
                     "identified, tabulated in --out and --json only",
                R->source, far, R->tau_max_frac, tau_max_samples(R));
    }
}

/* The streaming estimators' configuration chunks over R->grid; with
 * m_list NULL the grid is first filled with the log-spaced one. */
static int setup_grid(run_t *R, long per_octave, const char *m_list)
{
    int c;
    if (m_list == NULL) {
        R->ngrid = fnav_allan_grid(R->grid, GRID_MAX, (uint32_t)FNAV_ALLAN_TAU_MAX, (unsigned)per_octave);
    } else if (parse_m_list(R, m_list) != 0) {
        return -1;
    }
    R->nchunk = 0;
    for (c = 0; (size_t)c * FNAV_ALLAN_MAX_POINTS < R->ngrid; c++) {
        size_t off = (size_t)c * FNAV_ALLAN_MAX_POINTS;
        R->cfg[c].tau = R->grid + off;
        R->cfg[c].n_tau = R->ngrid - off < FNAV_ALLAN_MAX_POINTS ? R->ngrid - off : FNAV_ALLAN_MAX_POINTS;
        R->nchunk++;
    }
    return R->nchunk > 0 ? 0 : -1;
}

static int alloc_channel(run_t *R, chan_t *ch)
{
    int c;
    if (R->exact) {
        return 0; /* the table comes from the record (exact_table), no streaming estimator runs */
    }
    for (c = 0; c < R->nchunk; c++) {
        ch->est[c] = (fnav_allan_t *)malloc(sizeof(fnav_allan_t));
        if (ch->est[c] == NULL || fnav_allan_init(ch->est[c], &R->cfg[c]) != FNAV_OK) {
            return -1;
        }
    }
    return 0;
}

static void free_run(run_t *R)
{
    int i, c;
    for (i = 0; i < R->nch; i++) {
        for (c = 0; c < R->nchunk; c++) {
            free(R->ch[i].est[c]);
            R->ch[i].est[c] = NULL;
        }
        free(R->ch[i].x);
        R->ch[i].x = NULL;
    }
    free(R->win_spread);
    R->win_spread = NULL;
    R->win_cap = 0u;
}

/* Append a sample to the phase record (--estimator exact).
 * @return 0, or -2 when out of memory */
static int record(chan_t *ch, double v)
{
    if (ch->nx + 1u >= ch->capx) {
        const size_t cap = ch->capx == 0u ? 65536u : 2u * ch->capx;
        double *x = (double *)realloc(ch->x, cap * sizeof *x);
        if (x == NULL) {
            return -2;
        }
        ch->x = x;
        ch->capx = cap;
    }
    if (ch->nx == 0u) {
        ch->y0 = v;
        ch->x[ch->nx++] = 0.0;
    }
    ch->x[ch->nx] = ch->x[ch->nx - 1u] + (v - ch->y0);
    ch->nx++;
    return 0;
}

/* The exact estimator's input range, of a value less the first: the
 * streaming estimator's is the core's (FNAV_INPUT_MAX_ABS, 1e6, a float's
 * sums), which the record in double does not need. Its own limit is where
 * the numbers overflow: a spread S gives an Allan variance up to 2 S^2,
 * kept in the result rows' fnav_real_t (the float build's FLT_MAX, 3.4e38:
 * S 1e18, at 1e19 it would be inf), and in the double build sums of
 * squared phase differences that grow with n and m (S 1e100 leaves them
 * 1e100 below DBL_MAX). */
#define HX_ALLAN_EXACT_MAX_ABS (sizeof(fnav_real_t) < sizeof(double) ? 1e18 : 1e100)

/* Push a sample into the channel's streaming estimators, or its record
 * (--estimator exact; within HX_ALLAN_EXACT_MAX_ABS).
 * @return 0; -1 when refused (not finite, or beyond the input range); -2 when out of memory */
static int push_all(run_t *R, chan_t *ch, double v)
{
    int c;
    if (R->n == 0u) {
        ch->v_first = v;
    } else if (v != ch->v_first) {
        ch->varied = 1;
        if (fabs(v - ch->v_first) > ch->spread) {
            ch->spread = fabs(v - ch->v_first);
        }
    }
    if (R->exact) {
        return isfinite(v) && fabs(v) <= HX_ALLAN_EXACT_MAX_ABS ? record(ch, v) : -1;
    }
    for (c = 0; c < R->nchunk; c++) {
        if (fnav_allan_push(ch->est[c], (fnav_real_t)v) != FNAV_OK) {
            return -1;
        }
    }
    return 0;
}

/* Collect the tables (display units) from the estimators of a channel. */
static void collect(run_t *R, chan_t *ch, fnav_allan_t *const *est, fnav_allan_result_t *out)
{
    size_t k = 0, i;
    int c;
    for (c = 0; c < R->nchunk; c++) {
        size_t cnt = fnav_allan_count(est[c]);
        for (i = 0; i < cnt && k < GRID_MAX; i++) {
            if (fnav_allan_get(est[c], i, &out[k]) == FNAV_OK) {
                out[k].avar = (fnav_real_t)((double)out[k].avar * ch->scale * ch->scale);
                out[k].avar_nonoverlap = (fnav_real_t)((double)out[k].avar_nonoverlap * ch->scale * ch->scale);
                k++;
            }
        }
    }
    ch->nres = k;
}

/* ------------------------------------------------------------ input */

static int parse_channels(run_t *R, const char *list)
{
    list_t L;
    int i, j;
    R->nch = 0;
    if (split_list("--channels", list != NULL ? list : "ax,ay,az,gx,gy,gz", &L) != 0) {
        return -1;
    }
    for (j = 0; j < L.n; j++) {
        const char *tok = L.el[j];
        int found = -1;
        for (i = 0; i < 6; i++) {
            if (strcmp(tok, k_ch[i].name) == 0) {
                found = i;
            }
        }
        if (found < 0 || R->nch >= NCH_MAX) {
            hx_error(CMD, "--channels: '%s' is not one of ax, ay, az, gx, gy, gz", tok);
            return -1;
        }
        R->ch[R->nch].src = found;
        R->ch[R->nch].name = k_ch[found].name;
        R->ch[R->nch].label = k_ch[found].label;
        R->ch[R->nch].unit = k_ch[found].gyro ? "deg/s" : "m/s^2";
        R->ch[R->nch].scale = k_ch[found].gyro ? RAD2DEG : 1.0;
        R->nch++;
    }
    return 0;
}

/* --deviation LIST: names separated by commas, or "all". */
static int parse_deviations(run_t *R, const char *list)
{
    list_t L;
    int i;
    if (!R->exact) {
        hx_error(CMD, "--deviation needs --estimator exact (the streaming estimator computes the Allan deviation "
                      "only)");
        return -1;
    }
    if (strcmp(list, "all") == 0) {
        for (i = HX_DEV_MDEV; i < HX_DEV_COUNT; i++) {
            R->dev[R->ndev++] = (hx_dev_t)i;
        }
        return 0;
    }
    if (split_list("--deviation", list, &L) != 0) {
        return -1;
    }
    for (i = 0; i < L.n; i++) {
        hx_dev_t k;
        if (strcmp(L.el[i], "all") == 0) {
            /* it said "unknown 'all' (... or all)": the name is known, its place is not */
            hx_error(CMD, "--deviation: 'all' stands alone, not in a list with other names ('%s')", list);
            return -1;
        }
        if (hx_dev_parse(L.el[i], &k) != 0) {
            hx_error(CMD, "--deviation: unknown '%s' (mdev, tdev, hdev, ohdev, totdev, pdev, mtotdev, ttotdev, "
                          "htotdev or all)", L.el[i]);
            return -1;
        }
        if (k != HX_DEV_ADEV && k != HX_DEV_OADEV) { /* those two are always in the table */
            R->dev[R->ndev++] = k; /* each kind once: split_list refused a name given twice */
        }
    }
    return 0;
}

/* Collect one sample into the motion check's current one-second window. */
static void motion_push(run_t *R, const fnav_sample_t *s)
{
    const double v[4] = { (double)s->gyro_rps[0], (double)s->gyro_rps[1], (double)s->gyro_rps[2],
                          sqrt((double)s->accel_mps2[0] * (double)s->accel_mps2[0] +
                               (double)s->accel_mps2[1] * (double)s->accel_mps2[1] +
                               (double)s->accel_mps2[2] * (double)s->accel_mps2[2]) };
    int i;
    if (R->win_len == 0u) {
        if (!(R->rate_hz > 0.0)) {
            return; /* rate not known yet (the first sample of a log without a nominal rate) */
        }
        R->win_len = R->rate_hz < 2.0 ? 2u : R->rate_hz > 1e6 ? 1000000u : (uint32_t)(R->rate_hz + 0.5);
    }
    for (i = 0; i < 4; i++) {
        R->win_sum[i] += v[i];
        R->win_sq[i] += v[i] * v[i];
    }
    R->win_off += hx_walk_off(v[3]);
    if (++R->win_fill == R->win_len) {
        const double n = (double)R->win_fill;
        double var[4];
        /* the same window tells a walk (replay's and info's test of the
         * stamps' seconds), so that a walk in rad/s read with --units
         * gyro=deg/s is not told "multiply by pi/180" */
        hx_walk_window(&R->walk, (long)R->win_fill, R->win_sum[3], R->win_sq[3], R->win_off);
        R->win_off = 0;
        for (i = 0; i < 4; i++) {
            const double m = R->win_sum[i] / n;
            var[i] = R->win_sq[i] / n - m * m;
            var[i] = var[i] > 0.0 ? var[i] : 0.0;
            R->win_sum[i] = R->win_sq[i] = 0.0;
        }
        if (sqrt(var[0] + var[1] + var[2]) > HX_ALLAN_MOVING_GYRO_RPS || sqrt(var[3]) > HX_ALLAN_MOVING_F_MPS2) {
            if (R->win_moving == 0) {
                R->win_first_moving_s = (double)R->win_n * (double)R->win_len / R->rate_hz;
            }
            R->win_moving++;
        }
        if ((size_t)R->win_n >= R->win_cap) {
            const size_t cap = R->win_cap == 0u ? 4096u : 2u * R->win_cap;
            double *w = (double *)realloc(R->win_spread, 2u * cap * sizeof *w);
            if (w != NULL) {
                R->win_spread = w;
                R->win_cap = cap;
            }
        }
        if ((size_t)R->win_n < R->win_cap) {
            R->win_spread[2 * R->win_n] = sqrt(var[0] + var[1] + var[2]);
            R->win_spread[2 * R->win_n + 1] = sqrt(var[3]);
        }
        R->win_n++;
        R->win_fill = 0u;
    }
}

/* The disturbance check of a static log: warn about the windows whose rate
 * or |f| spreads by more than HX_ALLAN_DISTURBED_RATIO times the median
 * window's, those already counted as moving left out. A touch of 0.1 rad/s
 * and 0.2 m/s^2 for 0.5 s in 30 minutes of ADIS16405 log 1 (noise spread
 * 0.012 rad/s) stays below the moving marks and, without the check, would
 * be fitted without a word as a gz bias of 0.096 deg/s with T = 0.3 s. */
/* The median window's rate and |f| spread (med[0], med[1]) for the
 * disturbance check; -1 when there are too few windows, too short ones, or
 * their spreads were not kept (out of memory). */
static int spread_medians(const run_t *R, double med[2])
{
    double *v;
    long i, n = R->win_n;
    int k;
    if (n < HX_ALLAN_DISTURBED_MIN_WIN || R->win_len < HX_ALLAN_DISTURBED_MIN_LEN || (size_t)n > R->win_cap ||
        R->win_spread == NULL) {
        return -1;
    }
    v = (double *)malloc((size_t)n * sizeof *v);
    if (v == NULL) {
        return -1;
    }
    for (k = 0; k < 2; k++) {
        for (i = 0; i < n; i++) {
            v[i] = R->win_spread[2 * i + k];
        }
        med[k] = hx_median(v, (int)n);
    }
    free(v);
    return 0;
}

/* Window i (0 <= i < win_n, spreads kept) moves (HX_ALLAN_MOVING_*). */
static int window_moving(const run_t *R, long i)
{
    return R->win_spread[2 * i] > HX_ALLAN_MOVING_GYRO_RPS || R->win_spread[2 * i + 1] > HX_ALLAN_MOVING_F_MPS2;
}

/* Window i is disturbed: not moving, but its spread is over
 * HX_ALLAN_DISTURBED_RATIO times the median window's (med). */
static int window_disturbed(const run_t *R, long i, const double med[2])
{
    const double g = R->win_spread[2 * i], f = R->win_spread[2 * i + 1];
    return !window_moving(R, i) && ((med[0] > 0.0 && g > HX_ALLAN_DISTURBED_RATIO * med[0]) ||
                                    (med[1] > 0.0 && f > HX_ALLAN_DISTURBED_RATIO * med[1]));
}

static void disturbed_check(const run_t *R, const char *path)
{
    double med[2], first_s = 0.0;
    long i, n = R->win_n, count = 0;
    if (spread_medians(R, med) != 0) {
        return;
    }
    for (i = 0; i < n; i++) {
        if (window_disturbed(R, i, med)) {
            if (count == 0) {
                first_s = (double)i * (double)R->win_len / R->rate_hz;
            }
            count++;
        }
    }
    if (count > 0) {
        hx_warn(CMD,
                "%s: %ld of %ld one-second windows are disturbed (a touch or a knock?): the rate or |f| spreads by "
                "more than %g times the median window's (%.3g rad/s, %.3g m/s^2 RMS; the first at %.0f s); the "
                "Allan variance includes it: the white noise N and a profile written from it are inflated by "
                "it, and a fit may take it for a bias; cut the log to its still part (harness convert LOG OUT "
                "--start S --end S)",
                path, count, n, HX_ALLAN_DISTURBED_RATIO, med[0], med[1], first_s);
    }
}

/* A static log may be slow, so its rate is no unit error (as replay's is);
 * but one below 1 Hz that a time column in milliseconds, microseconds or
 * nanoseconds explains (20 Hz to 100 kHz once divided) is warned about:
 * 30 minutes of ADIS16405 log 1 with t in ms reads as 0.1 Hz, tau 1000
 * times and sigma_v 31.6 times too large, which would go without a word. */
static int slow_check(const char *path, double rate_hz, const hx_csv_layout_t *want)
{
    char msg[320];
    if (hx_time_unit_hint(rate_hz, want, msg, sizeof msg)) {
        hx_warn(CMD, "%s: %s; tau, sigma_v and the profile are read at %.3g Hz", path, msg, rate_hz);
        return 1;
    }
    return 0;
}

static int read_log(run_t *R, const hx_args_t *a, const char *path, double rate_opt)
{
    hx_reader_t *r = hx_open_input(CMD, a, path);
    fnav_sample_t s;
    fnav_status_t st;
    hx_progress_t pr;
    int64_t t_prev = 0, t_first = 0; /* the last and the first sample's stamps */
    int64_t res_ns = 0; /* the stamps' resolution so far: the gcd of the intervals that advance */
    long irregular = 0, gaps = 0, repeats = 0; /* repeats: intervals of 0, a time stamp written twice */
    size_t checked = 0; /* the intervals checked (against stamp_rate) */
    long run = 0; /* the intervals of 0 right before this one: samples that share a stamp */
    double missing = 0.0, longest_gap_s = 0.0; /* samples the gaps lost (round(dt / T) - 1 each), the longest gap */
    double stamp_rate; /* the rate the stamps are checked against: the log's own, not an overriding --rate */
    /* the first HX_STAMPS_PROBE_N stamps, for the test of stamps in bursts
     * as replay's (none: --rate, or out of memory); a streaming command,
     * it does not hold every stamp */
    int64_t *stamps = rate_opt > 0.0 ? NULL : (int64_t *)malloc(HX_STAMPS_PROBE_N * sizeof *stamps);
    size_t n_stamps = 0;
    int i, rc = 0;
    if (r == NULL) {
        free(stamps);
        return -1;
    }
    snprintf(R->sensor, sizeof R->sensor, "%s", hx_reader_meta(r)->sensor);
    R->in_fmt = hx_reader_meta(r)->format;
    /* a log whose format names no sensor (a CSV's "unknown"): the header
     * names the format, as info does ("(unknown)" before) */
    if (R->sensor[0] == '\0' || strcmp(R->sensor, "unknown") == 0) {
        snprintf(R->sensor_text, sizeof R->sensor_text, "%s log", hx_format_name(hx_reader_meta(r)->format));
    } else {
        snprintf(R->sensor_text, sizeof R->sensor_text, "%s", R->sensor);
    }
    R->rate_hz = rate_opt > 0.0 ? rate_opt : hx_reader_meta(r)->rate_hz;
    stamp_rate = hx_reader_meta(r)->rate_hz;
    hx_progress_start(&pr, "allan: reading", 1.0);
    while ((st = hx_reader_next(r, &s)) == FNAV_OK) {
        if (R->n == UINT32_MAX) {
            hx_warn(CMD, "stopping at 2^32 - 1 samples");
            break;
        }
        if (R->rate_hz <= 0.0) {
            /* rate from the time stamps: first interval, refined below */
            const double rh = hx_reader_meta(r)->rate_hz;
            if (rh > 0.0) {
                R->rate_hz = rh;
            } else if (R->n > 0 && s.t_ns > t_prev) {
                R->rate_hz = 1e9 / (double)(s.t_ns - t_prev);
            }
        }
        if (!(stamp_rate > 0.0) && R->n > 0 && s.t_ns > t_prev) {
            stamp_rate = 1e9 / (double)(s.t_ns - t_prev);
        }
        if (R->n > 0 && s.t_ns > t_prev && hx_reader_meta(r)->rate_coarse) {
            res_ns = hx_gcd_i64(s.t_ns - t_prev, res_ns);
        }
        if (R->n > 0 && stamp_rate > 0.0) {
            /* uniformity of the stamps themselves: against an overriding
             * --rate every interval of a uniform log "differed" (999,999 of
             * the ADIS log at --rate 400, said as non-uniform sampling).
             * Stamps coarser than the period (398 Hz printed to the
             * millisecond reads 2 and 3 ms) may differ by their resolution
             * as well, or every interval of such a uniform log would be
             * counted (as psd's; the gcd so far is never below the final one) */
            /* a stamp written twice (0, 10, 10, 30 ms) is no sample lost: the
             * interval after it spans the two periods of the samples there
             * (it said "about 1 samples missing"); as many periods fewer are
             * missing as samples shared the stamp before */
            const double lost = hx_interval_missing(s.t_ns - t_prev, stamp_rate, res_ns) - (double)run;
            irregular += hx_interval_irregular(s.t_ns - t_prev, stamp_rate, res_ns);
            checked++;
            repeats += s.t_ns == t_prev;
            if (lost > 0.0) {
                const double dt_s = (double)(s.t_ns - t_prev) * 1e-9;
                gaps++;
                missing += lost;
                longest_gap_s = dt_s > longest_gap_s ? dt_s : longest_gap_s;
            }
            run = s.t_ns == t_prev ? run + 1 : 0;
        }
        if (R->n == 0) {
            t_first = s.t_ns;
        }
        t_prev = s.t_ns;
        if (stamps != NULL && n_stamps < HX_STAMPS_PROBE_N) {
            stamps[n_stamps++] = s.t_ns;
        }
        motion_push(R, &s);
        for (i = 0; i < 3; i++) {
            R->acc_sum[i] += (double)s.accel_mps2[i];
            if (fabs((double)s.gyro_rps[i]) > R->gyro_max) {
                R->gyro_max = fabs((double)s.gyro_rps[i]);
            }
        }
        for (i = 0; i < R->nch; i++) {
            const int k = R->ch[i].src;
            const double v = k < 3 ? (double)s.accel_mps2[k] : (double)s.gyro_rps[k - 3];
            const int pr_rc = push_all(R, &R->ch[i], v);
            if (pr_rc == -2) {
                input_fail(R, "%s: sample %lu: %s", path, (unsigned long)R->n + 1u, k_exact_oom);
                rc = 1;
                break;
            }
            if (pr_rc != 0) {
                input_fail(R, "%s: sample %lu: channel %s is not finite (or beyond the float range)", path, (unsigned long)R->n + 1u,
                         R->ch[i].name);
                rc = 1;
                break;
            }
        }
        if (rc != 0) {
            break;
        }
        R->n++;
        if ((R->n & 65535u) == 0u) {
            hx_progress_update(&pr, hx_reader_progress(r));
        }
    }
    hx_progress_end(&pr);
    hx_print_warnings(CMD, hx_reader_take_warnings(r)); /* a cut-off last line is found at the end */
    if (rc == 0 && st != FNAV_OK && st != FNAV_END) {
        input_fail(R, "%s", hx_reader_error(r));
        rc = 1;
    }
    if (irregular > 0) {
        /* the gaps said with what they lost: the series is read as if its
         * samples were consecutive (a 60 s hole in an hour was only "3
         * intervals differ"); a stamp written twice said as such */
        char what[400];
        /* of how many, and the period they were checked against, as psd's
         * ("N intervals differ from 1/rate" named neither) */
        hx_irregular_text(what, sizeof what, irregular, checked, stamp_rate, repeats, gaps, longest_gap_s, missing,
                          (double)R->n);
        hx_warn(CMD, "%s: %s: the Allan variance assumes uniform sampling%s", path, what, hx_gaps_joined(gaps));
    }
    if (stamps != NULL && R->rate_hz > 0.0) {
        /* not with --rate, which sets the rate the analysis takes; the
         * reader's rate is the file's own when nominal */
        const hx_meta_t *m = hx_reader_meta(r);
        if (!hx_nav_bursts_warn(CMD, path, m->format, stamps, n_stamps, (size_t)R->n > n_stamps,
                                "tau, sigma_v and the profile are read at", R->rate_hz,
                                m->rate_nominal && m->rate_hz > 0.0 && R->rate_hz == m->rate_hz)) {
            /* a stated rate the stamps contradict, warned about as info's */
            hx_stated_rate_warn(CMD, path, m, stamps, n_stamps, "tau, sigma_v and the profile are read at");
        }
    }
    free(stamps);
    if (rate_opt > 0.0 && stamp_rate > 0.0 && fabs(rate_opt / stamp_rate - 1.0) > 1e-3) {
        hx_warn(CMD, "%s: analysed at --rate %g Hz; the log's own rate is %g Hz", path, rate_opt, stamp_rate);
    }
    hx_reader_close(r);
    if (R->rate_hz <= 0.0 && rc == 0 && R->n < 2u) {
        return 0; /* one sample has no interval: the caller names the samples needed, not --rate */
    }
    if (rc != 0 && R->n == 0u) {
        /* the reader's error ("no samples") said it; also where the format
         * names a rate (ipol, a data set's nominal rate), not a second error
         * "0 samples are too few for any Allan point" after it */
        return -1;
    }
    if (R->rate_hz <= 0.0) {
        hx_error(CMD, "%s: %s", path,
                 rc != 0       ? "too few samples before the error to know the sample rate"
                 : R->n > 1u && t_prev == t_first
                     ? "sample rate unknown: every time stamp is the same (is the time column filled? --rate HZ "
                       "analyses it at a rate you give)"
                     : "sample rate unknown; give --rate");
        return -1;
    }
    if (R->n > 0u) {
        /* A static log in g or deg/s reads without error and gives a profile
         * 9.8 times too quiet or 57 times too noisy. At rest the mean specific
         * force is gravity: the same marks as replay and info (docs/harness.md,
         * "Units check"; not the rate: a static log may be slow). */
        const double f[3] = { R->acc_sum[0] / (double)R->n, R->acc_sum[1] / (double)R->n,
                              R->acc_sum[2] / (double)R->n };
        /* A log that moves (a walk given as a static log) has no rest: its
         * mean specific force is no gravity, and was named as a unit
         * mistake ("|f| = 13.58 at rest ... not in m/s^2" for a walk in
         * m/s^2). The motion is named instead; the gyro's range still
         * tells deg/s. */
        /* the units error and the time warning each name the items of
         * both, one --units value (a second --units replaces the first) */
        hx_csv_layout_t lay, lay_t, lay_w;
        const hx_csv_layout_t *csv = hx_units_layout(R->in_fmt, &lay);
        /* the rate the time unit is judged at: the log's span too (stamps
         * in bursts are no unit) */
        const double rate_u = hx_time_unit_rate(R->rate_hz, (size_t)R->n, t_first, t_prev);
        double f_rest;
        R->moving = R->win_n > 0 && (double)R->win_moving > HX_ALLAN_MOVING_FRAC * (double)R->win_n;
        f_rest = R->moving ? 0.0 : sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        R->units_bad = hx_units_problem(f_rest, 9.80665, R->gyro_max, 0.0,
                                        rate_opt > 0.0 ? csv : hx_time_unit_layout(rate_u, csv, &lay_t),
                                        hx_walk_seen(&R->walk),
                                        R->units_msg, sizeof R->units_msg);
        if (!(rate_opt > 0.0)) {
            R->time_unit_warned =
                slow_check(path, rate_u, hx_units_want(csv, f_rest, 9.80665, R->gyro_max, &lay_w));
        }
    }
    return rc;
}

/* The shortest of %.15g, %.16g and %.17g that reads back as v: two values
 * that differ print apart (%g printed 1e+300 for both 1e300 and
 * 1.0000001e300), a round one without %.17g's tail (9.9999999999999997e+199) */
static const char *fmt_full(char *b, size_t n, double v)
{
    int p;
    for (p = 15; p <= 17; p++) {
        snprintf(b, n, "%.*g", p, v);
        if (strtod(b, NULL) == v) {
            break;
        }
    }
    return b;
}

/* Push one value of a series. The first value is removed here, in double, so
 * that a large offset (a 10 MHz frequency counted to the mHz) keeps its
 * digits in the float core; the Allan variance ignores a constant. */
static int push_series(run_t *R, const char *path, long lineno, double y, double *first, int *have_first)
{
    int prc;
    if (!*have_first) {
        *first = y;
        *have_first = 1;
    }
    prc = push_all(R, &R->ch[0], y - *first);
    if (prc == -2) {
        input_fail(R, "%s:%ld: %s", path, lineno, k_exact_oom);
    } else if (prc != 0) {
        char by[32], bf[32];
        fmt_full(by, sizeof by, y);
        fmt_full(bf, sizeof bf, *first);
        if (R->exact) {
            input_fail(R, "%s:%ld: %s differs from the first value, %s, by more than the exact estimator's "
                          "range (%g): scale the values down (a power of ten, with --unit)",
                       path, lineno, by, bf, HX_ALLAN_EXACT_MAX_ABS);
        } else {
            input_fail(R, "%s:%ld: %s differs from the first value, %s, by more than the streaming "
                          "estimator's input range (%g, the core's): use --estimator exact (up to %g) or scale the "
                          "values down (a power of ten, with --unit)",
                       path, lineno, by, bf, FNAV_INPUT_MAX_ABS, HX_ALLAN_EXACT_MAX_ABS);
        }
    }
    return prc;
}

/* Skip blanks, then one comma and the blanks after it. */
static char *skip_sep(char *p)
{
    while (*p == ' ' || *p == '\t') {
        p++;
    }
    if (*p == ',') {
        p++;
        while (*p == ' ' || *p == '\t') {
            p++;
        }
    }
    return p;
}

/* A series' read error, or, while no number has been read and the file's
 * first bytes are binary (@p binary, else NULL), the binary data named as
 * the readers name it (not "plot.png:2: not a number" for a PNG given as a
 * series, its first line taken for a header). */
static void series_fail(run_t *R, const char *binary, const char *fmt, ...)
{
    va_list ap;
    if (binary != NULL) {
        input_fail(R, "%s", binary);
        return;
    }
    va_start(ap, fmt);
    vsnprintf(R->input_error, sizeof R->input_error, fmt, ap);
    va_end(ap);
    say_input_error(R);
}

/* A series read through zlib (a .gz transparently, as the logs): its first
 * bytes are read once into head, looked at, and handed out before the rest,
 * so that a pipe (read once, never rewound) is read as a file is. */
#define SERIES_HEAD 600
#define SERIES_LINE_MAX (1u << 20) /* a longer line is refused: no unbounded buffer for a file without newlines */
typedef struct {
    gzFile gz;
    unsigned char head[SERIES_HEAD];
    size_t nhead, ihead;
    char *line;        /* the line read, NUL-terminated, its newline kept */
    size_t cap;
    int eof;           /* the end of the data (or a read error: series_error()) was met */
    int read_errno;    /* errno after a failing read */
} series_in_t;

/* The next byte, or EOF at the end of the data or on an error. */
static int series_getc(series_in_t *in)
{
    if (in->ihead < in->nhead) {
        return in->head[in->ihead++];
    }
    errno = 0;
    {
        const int c = gzgetc(in->gz);
        if (c < 0) {
            in->eof = 1;
            in->read_errno = in->read_errno != 0 ? in->read_errno : errno; /* the first failing read's */
        }
        return c;
    }
}

/* A zlib or read error met (0 if none), its text in msg. */
static int series_error(series_in_t *in, char *msg, size_t n)
{
    int e;
    const char *zm = gzerror(in->gz, &e);
    if (e == Z_OK || e == Z_STREAM_END) {
        return 0;
    }
    if (e == Z_BUF_ERROR) {
        snprintf(msg, n, "the gzip data ends early (a truncated .gz, e.g. an incomplete copy)");
    } else if (e == Z_ERRNO) {
        snprintf(msg, n, "read error (%s)", strerror(in->read_errno != 0 ? in->read_errno : EIO));
    } else {
        snprintf(msg, n, "read error (%s)", zm);
    }
    return 1;
}

/* Read one line of a series into in->line (NUL-terminated, the newline
 * kept, as fgets does): the number of bytes read, 0 at the end of the file.
 * The buffer grows with the line (a CSV of a thousand columns, --column N
 * of them), up to SERIES_LINE_MAX; *cut: 1 the line was longer, and only
 * its start is in the buffer; 2 no memory for it (not the end of the file,
 * nor "longer than" the buffer's size then). *nul: a NUL byte was among
 * them (fgets would hide it: the line would end there). */
static size_t series_line(series_in_t *in, int *nul, int *cut)
{
    size_t n = 0;
    int c = 0;
    *nul = 0;
    *cut = 0;
    if (in->cap == 0u) {
        in->line = (char *)malloc(4096u);
        if (in->line == NULL) {
            *cut = 2;
            return 1u;
        }
        in->cap = 4096u;
    }
    while ((c = series_getc(in)) != EOF) {
        if (n + 2u > in->cap) {
            char *p;
            if (in->cap >= SERIES_LINE_MAX) {
                *cut = 1;
                break;
            }
            if ((p = (char *)realloc(in->line, 2u * in->cap)) == NULL) {
                *cut = 2;
                break;
            }
            in->line = p;
            in->cap *= 2u;
        }
        in->line[n++] = (char)c;
        *nul |= c == 0;
        if (c == '\n') {
            break;
        }
    }
    in->line[n] = '\0';
    return *cut ? n + 1u : n;
}

/* column: 0 for one number per line, else the 1-based column to take */
static int read_series(run_t *R, const char *path, int phase, long column)
{
    series_in_t in;
    char head_msg[HX_ERR_SIZE], rd_msg[HX_ERR_SIZE];
    const char *binary = NULL; /* the binary-data message until a number is read */
    long lineno = 0;
    /* blank lines after the first number: pending until a number follows
     * (those at the file's end stay silent), then counted in blanks */
    long pending = 0, pending_first = 0, blanks = 0, blank_first = 0;
    int data_lines = 0, rc = 0, have_prev = 0, have_first = 0, nul = 0, cut = 0;
    double prev = 0.0, first = 0.0;
    memset(&in, 0, sizeof in);
    errno = 0;
    in.gz = gzopen(path, "rb"); /* a .gz read transparently, as a log is */
    if (in.gz == NULL) {
        const int e = errno;
        hx_error(CMD, "%s: cannot open (%s)%s", path, e != 0 ? strerror(e) : "gzopen failed", hx_stdin_hint(path, e));
        return -1;
    }
    (void)gzbuffer(in.gz, 1u << 16);
    {
        /* its first bytes, as the log readers' (hx_head_not_text): UTF-16
         * refused at once with its iconv remedy, binary data named if no
         * number comes. Kept and handed out before the rest: a pipe is read
         * once, never rewound */
        int got;
        errno = 0;
        got = gzread(in.gz, in.head, (unsigned)sizeof in.head);
        in.read_errno = errno;
        in.nhead = got > 0 ? (size_t)got : 0u;
        if (got > 0) {
            const hx_head_t kind = hx_head_not_text(path, in.head, in.nhead, 1, head_msg, sizeof head_msg);
            if (kind == HX_HEAD_UTF16 || kind == HX_HEAD_CONTAINER) {
                hx_error(CMD, "%s", head_msg);
                gzclose(in.gz);
                return -1;
            }
            binary = kind == HX_HEAD_BINARY ? head_msg : NULL;
        }
    }
    while (series_line(&in, &nul, &cut) > 0) {
        char *p = in.line, *end;
        double v;
        long k;
        lineno++;
        if (cut == 2) {
            series_fail(R, NULL, "%s:%ld: out of memory for the line", path, lineno);
            rc = 1;
            break;
        }
        if (nul) {
            series_fail(R, binary, "%s:%ld: " HX_NUL_TEXT,
                        path, lineno);
            rc = 1;
            break;
        }
        if (cut) {
            /* a longer line would be read in pieces, each taken for a line */
            series_fail(R, binary, "%s:%ld: line longer than %u characters", path, lineno,
                        (unsigned)(in.cap - 2u));
            rc = 1;
            break;
        }
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        if (*p == '\0' || *p == '\n' || *p == '\r' || *p == '#') {
            if (*p != '#' && data_lines == 1 && pending++ == 0) {
                pending_first = lineno;
            }
            continue;
        }
        if (pending > 0) {
            blank_first = blanks == 0 ? pending_first : blank_first;
            blanks += pending;
            pending = 0;
        }
        for (k = 1;; k++) {
            v = strtod(p, &end);
            if (end == p || k >= column) {
                break;
            }
            p = skip_sep(end);
        }
        if (end == p) {
            if (data_lines == 0 && k == 1) {
                data_lines = -1; /* a header line before the numbers */
                continue;
            }
            if (*p == '\0' || *p == '\n' || *p == '\r') {
                series_fail(R, binary, "%s:%ld: no column %ld", path, lineno, column);
            } else {
                series_fail(R, binary, "%s:%ld: not a number", path, lineno);
            }
            rc = 1;
            break;
        }
        while (column == 0 && (*end == ' ' || *end == '\t' || *end == '\r' || *end == '\n')) {
            end++;
        }
        if (column == 0 && *end != '\0') {
            series_fail(R, binary, "%s:%ld: expected one number per line (--column N takes one of several)", path,
                        lineno);
            rc = 1;
            break;
        }
        if (!isfinite(v)) {
            series_fail(R, binary, "%s:%ld: not a finite number", path, lineno);
            rc = 1;
            break;
        }
        data_lines = 1;
        binary = NULL;
        if (phase) {
            if (have_prev) {
                if (push_series(R, path, lineno, (v - prev) * R->rate_hz, &first, &have_first) != 0) {
                    rc = 1;
                    break;
                }
                R->n++;
            }
            prev = v;
            have_prev = 1;
        } else {
            if (push_series(R, path, lineno, R->f0 > 0.0 ? (v - R->f0) / R->f0 : v, &first, &have_first) != 0) {
                rc = 1;
                break;
            }
            R->n++;
        }
    }
    if (rc == 0 && series_error(&in, rd_msg, sizeof rd_msg)) {
        /* not the end of the series: a directory said "no numbers", a
         * failing read mid-file (or a truncated .gz) ended the series
         * there, complete */
        input_fail(R, "%s: %s", path, rd_msg);
        rc = 1;
    }
    gzclose(in.gz);
    free(in.line);
    if (blanks > 0) {
        /* a blank line is no sample: if one stood for a missing value,
         * every later value is one sample early, so the skipped lines are
         * warned about, not skipped without a word */
        hx_warn(CMD, "%s: %ld blank line%s among the numbers (the first at line %ld) %s skipped, not read as "
                     "samples: if one stands for a missing value, every later value is one sample early",
                path, blanks, blanks == 1 ? "" : "s", blank_first, blanks == 1 ? "is" : "are");
    }
    if (R->n == 0 && rc == 0 && data_lines == 1) {
        return 0; /* one phase value, no frequency: the caller names the samples needed */
    }
    if (R->n == 0) {
        if (rc == 0) {
            if (binary != NULL) {
                hx_error(CMD, "%s", binary);
            } else {
                hx_error(CMD, "%s: no numbers", path);
            }
        }
        return -1;
    }
    return rc;
}

/* ------------------------------------------------------------ analysis */

static double tau_max_samples(const run_t *R)
{
    return R->tau_max_frac * (double)R->n;
}

/* The fewest samples whose record has an Allan point in range (in_range()):
 * the grid's shortest tau within --max-tau-frac of the record, with a term
 * (n + 1 phase points >= 2 m + 1). */
static double samples_needed(const run_t *R)
{
    const double m0 = (double)R->grid[0];
    double n = floor(m0 / R->tau_max_frac) - 1.0;
    if (n < 2.0 * m0) {
        n = 2.0 * m0;
    }
    while (!(m0 <= R->tau_max_frac * n * (1.0 + 1e-9))) {
        n += 1.0;
    }
    return n;
}

/* --estimator exact: every tau of the grid from the channel's whole record,
 * in double, in the streaming estimator's result rows (display units). */
static void exact_table(const run_t *R, chan_t *ch)
{
    size_t i;
    ch->nres = R->ngrid;
    for (i = 0; i < ch->nres; i++) {
        fnav_allan_result_t *r = &ch->res[i];
        uint32_t terms, terms_n;
        r->tau = R->grid[i];
        const double ao = hx_allan_avar_record(ch->x, ch->nx, r->tau, 1, &terms);
        const double an = hx_allan_avar_record(ch->x, ch->nx, r->tau, 0, &terms_n);
        r->level = 0u;
        r->stride = 1u;
        r->lag = r->tau;
        r->n_phase = (uint32_t)ch->nx;
        r->terms = terms;
        r->terms_nonoverlap = terms_n;
        r->avar = (fnav_real_t)(ao * ch->scale * ch->scale);
        r->avar_nonoverlap = (fnav_real_t)(an * ch->scale * ch->scale);
        if (terms > 0u && ao > 0.0 && ao * ch->scale * ch->scale < ch->avar_least) {
            ch->avar_least = ao * ch->scale * ch->scale;
        }
        if (terms > 0u && ao * ch->scale * ch->scale > ch->avar_most) {
            ch->avar_most = ao * ch->scale * ch->scale;
        }
    }
}

/* --deviation: each requested deviation at every tau of the grid from the
 * record, with the interval of the tau's noise exponent (hx_devs.h). */
/* The work of one deviation at one tau, for the progress shown: the window
 * terms of a total form (hx_dev_work), at least the record's length. */
static double dev_cost(hx_dev_t k, size_t n, uint32_t m)
{
    const double w = (double)hx_dev_work(k, n, m);
    return w > (double)n ? w : (double)n;
}

static void deviation_tables(run_t *R, chan_t *ch)
{
    int j;
    size_t i;
    for (j = 0; j < R->ndev; j++) {
        const hx_dev_t k = R->dev[j];
        for (i = 0; i < ch->nres; i++) {
            const uint32_t m = ch->res[i].tau;
            double v;
            if (hx_stop_sig) {
                ch->dv_skip[k][i] = 2u; /* interrupted: not computed, said in the table, CSV empty, JSON */
                ch->dv_terms[k][i] = 0u;
                continue;
            }
            if ((double)hx_dev_work(k, ch->nx, m) > R->max_work) {
                ch->dv_skip[k][i] = 1u;
                ch->dv_terms[k][i] = 0u;
                continue;
            }
            v = hx_dev_var_record(k, ch->x, ch->nx, m, &ch->dv_terms[k][i]);
            if (R->dev_pr != NULL) {
                R->dev_done += dev_cost(k, ch->nx, m);
                hx_progress_update(R->dev_pr, R->dev_done / R->dev_total);
            }
            const double dev = sqrt(v) * ch->scale * hx_dev_scale(k, m, R->rate_hz);
            ch->dv[k][i] = dev;
            ch->dv_edf[k][i] = ch->dv_terms[k][i] > 0u ? hx_dev_edf(k, ch->alpha[i], m, ch->nx) : -1.0;
            if (hx_allan_ci(dev, ch->dv_edf[k][i], R->conf, &ch->dv_lo[k][i], &ch->dv_hi[k][i]) != 0) {
                ch->dv_lo[k][i] = ch->dv_hi[k][i] = (double)NAN;
            }
        }
    }
}

/* A time in seconds for the text output: 3 significant digits, but a
 * whole number from 1000 s on ("1200 s", where %.3g would print "1.2e+03
 * s" on a long record). */
static const char *fmt_s(char *b, size_t n, double v)
{
    if (isfinite(v) && fabs(v) >= 999.5 && fabs(v) < 1e15) {
        snprintf(b, n, "%.0f", v);
    } else {
        snprintf(b, n, "%.3g", v);
    }
    return b;
}

static void analyse_channel(run_t *R, chan_t *ch, int fit_extra)
{
    size_t i;
    hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
    ch->avar_least = INFINITY;
    ch->avar_most = 0.0;
    if (R->exact) {
        exact_table(R, ch);
    } else {
        collect(R, ch, ch->est, ch->res);
        for (i = 0; i < ch->nres; i++) {
            if (ch->res[i].terms > 0u && (double)ch->res[i].avar > 0.0 && (double)ch->res[i].avar < ch->avar_least) {
                ch->avar_least = (double)ch->res[i].avar;
            }
        }
    }
    fnav_allan_slopes(ch->res, ch->nres, ch->slope);
    for (i = 0; i < ch->nres; i++) {
        ch->noise[i] = fnav_allan_noise_from_slope(ch->slope[i]);
    }
    hx_allan_mark_periodic(ch->noise, ch->nres, ch->periodic);
    for (i = 0; i < ch->nres; i++) {
        const fnav_allan_result_t *r = &ch->res[i];
        ch->alpha[i] = fnav_allan_noise_alpha(ch->noise[i]);
        ch->alpha_from[i] = HX_NOISE_ID_SLOPE;
        if (ch->periodic[i]) {
            /* no power law: the EDF of the noise beneath, read at the tau before (a periodic
             * term is only marked after one) */
            ch->alpha[i] = ch->alpha[i - 1];
            ch->alpha_from[i] = HX_NOISE_ID_HELD;
        }
        if (R->exact && hx_allan_noise_id_acf(ch->x, ch->nx, r->tau, &ch->alpha[i], &ch->alpha_from[i]) != 0) {
            ch->alpha_from[i] = ch->periodic[i] ? HX_NOISE_ID_HELD : HX_NOISE_ID_SLOPE; /* alpha kept */
        }
        ch->edf[i] = hx_allan_point_edf_alpha(r, ch->alpha[i], 1);
        ch->edf_n[i] = hx_allan_point_edf_alpha(r, ch->alpha[i], 0);
        if (hx_allan_ci(sqrt((double)r->avar), ch->edf[i], R->conf, &ch->lo[i], &ch->hi[i]) != 0) {
            ch->lo[i] = ch->hi[i] = (double)NAN;
        }
        if (hx_allan_ci(sqrt((double)r->avar_nonoverlap), ch->edf_n[i], R->conf, &ch->lo_n[i], &ch->hi_n[i]) != 0) {
            ch->lo_n[i] = ch->hi_n[i] = (double)NAN;
        }
    }
    deviation_tables(R, ch);
    /* a channel that never changes has Allan variance 0 at every tau: nothing
     * to identify, and "too little data" would send the user looking at the
     * record's length instead of the sensor */
    ch->constant = 0;
    for (i = 0; i < ch->nres; i++) {
        if (ch->res[i].terms > 0u) {
            if (!((double)ch->res[i].avar == 0.0)) {
                ch->constant = 0;
                break;
            }
            ch->constant = 1;
        }
    }
    /* (an exact 0 at one tau is no underflow: a few terms of quantised
     * data can cancel; in the float core a varying channel whose every
     * variance is 0 is one) */
    if (sizeof(fnav_real_t) < sizeof(double) && ch->varied &&
        (ch->avar_least < (double)FLT_MIN || (!R->exact && isinf(ch->avar_least)))) {
        /* below the float's normal range a variance keeps fewer digits
         * (white noise of 1e-22 in a series: 4.6 % off at m = 2), and one
         * that underflows to 0 read as a constant channel; the double build
         * has no such limit */
        ch->underflow = 1;
        ch->constant = 0;
    }
    if (R->exact && ch->varied &&
        (isinf(ch->avar_least) ? ch->spread < sqrt(DBL_MIN / DBL_EPSILON) : ch->avar_most < DBL_MIN)) {
        /* the record is in double, but a series that varies by 1e-200
         * squares to 0 there: every variance 0, which read as a constant
         * channel ("stuck channel", exit 0); so is one whose every variance
         * is subnormal (fewer digits than a double's). Not a few subnormal
         * ones at long tau beside normal ones (accurate where normal), nor a
         * variance 0 of values that vary widely (--m at their period) */
        ch->underflow = 2;
        ch->constant = 0;
    }
    if (ch->underflow == 2) {
        hx_error(CMD, "%s: %s: the values vary by at most %.3g %s, and every Allan variance (at most %.3g %s^2) is "
                      "below a double's normal range (%.3g): its digits are lost; scale the values up (a power of "
                      "ten, with --unit)",
                 R->source, ch->name, ch->spread * ch->scale, ch->unit, ch->avar_most, ch->unit, DBL_MIN);
    } else if (ch->underflow) {
        hx_error(CMD, "%s: %s: an Allan variance of %.3g %s^2 is below the float build's range (%.3g): its "
                      "digits are lost; scale the values up (a power of ten, with --unit) or use the double build "
                      "(FNAV_USE_DOUBLE=1)",
                 R->source, ch->name, isinf(ch->avar_least) ? 0.0 : ch->avar_least, ch->unit, (double)FLT_MIN);
    } else if (ch->constant) {
        hx_warn(CMD, "%s: %s is constant over the whole record (Allan deviation 0 at every tau): a stuck, "
                     "saturated or disconnected channel",
                R->source, ch->name);
    }
    o.with_quant = fit_extra;
    o.with_rrw = fit_extra;
    o.tau_max_s = tau_max_samples(R) / R->rate_hz;
    ch->id_ok = hx_allan_identify(ch->res, ch->nres, R->rate_hz, &o, &ch->id) == 0;
    if (ch->id_ok && ch->id.paper_ok) {
        /* the paper's BS is "the minimum" (III.A; t_BS, III.C.2); a curve still falling
         * at the end of the analysed range, or rising from its first tau,
         * has none there, and its end point was printed as a bias stability
         * without a word (white noise: BS at 983 s of a 10^4 s record) */
        size_t first = ch->nres, last = ch->nres;
        for (i = 0; i < ch->nres; i++) {
            const fnav_allan_result_t *r = &ch->res[i];
            if (r->terms > 0u && isfinite((double)r->avar) && (double)r->avar > 0.0 &&
                (double)r->tau <= tau_max_samples(R) * (1.0 + 1e-9)) {
                first = first == ch->nres ? i : first;
                last = i;
            }
        }
        if (first < last && (ch->id.paper.i_min == last || ch->id.paper.i_min == first)) {
            char b1[32], b2[32];
            hx_warn(CMD, "%s: %s: the Allan deviation has no minimum within tau <= %s s (it %s): the paper's BS and "
                         "tau (III.C) are read at the %s tau, %s s, not at a bias stability",
                     R->source, ch->name, fmt_s(b1, sizeof b1, tau_max_samples(R) / R->rate_hz),
                     ch->id.paper.i_min == last ? "still falls at the end" : "rises from the first tau on",
                     ch->id.paper.i_min == last ? "longest" : "shortest",
                     fmt_s(b2, sizeof b2, (double)ch->id.paper.t_bs_s));
        }
    }
}

/* Simulate a model through estimators with the same grid (Fig. 7 check,
 * and --refits' streaming path).
 * @return 0; -1 the model refused; -2 beyond the core's input range;
 * -3 interrupted; -4 out of memory */
static int simulate(run_t *R, chan_t *ch, const hx_noise_model_t *mdl, uint32_t nsim, unsigned long seed,
                    fnav_allan_result_t *out, hx_progress_t *pr, double *done, double total)
{
    fnav_allan_t *est[NCHUNK_MAX];
    hx_noise_sim_t s;
    hx_noise_model_t m = *mdl;
    uint32_t k;
    int c, ok = 1;
    memset(est, 0, sizeof est);
    if (hx_noise_sim_init(&s, &m, R->rate_hz, seed) != 0) {
        return -1;
    }
    for (c = 0; c < R->nchunk && ok == 1; c++) {
        est[c] = (fnav_allan_t *)malloc(sizeof(fnav_allan_t));
        ok = est[c] == NULL ? -4 /* out of memory */ : fnav_allan_init(est[c], &R->cfg[c]) == FNAV_OK;
    }
    for (k = 0; ok == 1 && k < nsim; k++) {
        const fnav_real_t v = (fnav_real_t)hx_noise_sim_next(&s);
        for (c = 0; c < R->nchunk; c++) {
            if (fnav_allan_push(est[c], v) != FNAV_OK) {
                ok = -2; /* beyond the core's input range (a --series of large values, exact estimator) */
            }
        }
        if ((k & 65535u) == 0u) {
            hx_progress_update(pr, (*done + (double)k) / total);
            if (hx_stop_sig) {
                ok = -3; /* interrupted: no curve */
            }
        }
    }
    *done += (double)nsim;
    if (ok == 1) {
        const double keep = ch->scale;
        ch->scale = 1.0; /* already in display units */
        collect(R, ch, est, out);
        ch->scale = keep;
    }
    for (c = 0; c < R->nchunk; c++) {
        free(est[c]);
    }
    hx_noise_sim_free(&s);
    return ok == 1 ? 0 : ok < 0 ? ok : -1;
}

/* ------------------------------------------------------------ --refits */

static int ar1_identified_in(const run_t *R, const fnav_allan_result_t *res, size_t nres, const hx_noise_model_t *f,
                             int fit_ok, double tau_long_s, double tau_max);
static double tau_long_of(const run_t *R, const chan_t *ch);
static int ar1_resolved(const run_t *R, const chan_t *ch);

/* The model simulated at R->nrefit samples through the estimator the
 * measured table came from (the streaming one, or --estimator exact's
 * record), into t's table (display units, t->scale 1).
 * @return 0; -1 failed (the model refused); -2 beyond the streaming
 * estimator's input range; -3 interrupted; -4 out of memory */
static int refit_table(run_t *R, chan_t *t, const hx_noise_model_t *mdl, unsigned long seed, hx_progress_t *pr,
                       double *done, double total)
{
    hx_noise_sim_t s;
    uint32_t k;
    int rc = 0;
    if (!R->exact) {
        return simulate(R, t, mdl, R->nrefit, seed, t->res, pr, done, total);
    }
    if (hx_noise_sim_init(&s, mdl, R->rate_hz, seed) != 0) {
        return -1;
    }
    t->nx = 0u;
    for (k = 0; rc == 0 && k < R->nrefit; k++) {
        if (record(t, hx_noise_sim_next(&s)) != 0) {
            rc = -4; /* out of memory: not a fit that failed */
        }
        if ((k & 65535u) == 0u) {
            hx_progress_update(pr, (*done + (double)k) / total);
            if (hx_stop_sig) {
                rc = -3;
            }
        }
    }
    *done += (double)R->nrefit;
    hx_noise_sim_free(&s);
    if (rc == 0) {
        exact_table(R, t);
    }
    return rc;
}

/* The seed of refit k of the i-th channel: (seed, i, k) mixed by
 * splitmix64's finaliser (Steele, Lea and Flood 2014), so that the refits
 * of --seed 1 and --seed 2 share none (seed + 1,000,000 (i + 1) + k made
 * 19 of 20 the same, shifted by one: the reviewer's finding) and none is
 * a Fig. 7 check's seed (seed + 1000 i and + 1) but by chance; never 0. */
static unsigned long refit_seed(unsigned long seed, int i, long k)
{
    uint64_t z = (uint64_t)seed * UINT64_C(0x9E3779B97F4A7C15) + ((uint64_t)(unsigned)(i + 1) << 40) + (uint64_t)k;
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    z ^= z >> 31;
    return (unsigned long)z != 0ul ? (unsigned long)z : 1ul;
}

/* --refits: a parametric bootstrap of a channel's corrected fit. The
 * fitted model is simulated R->refits times at R->nrefit samples (seeds
 * refit_seed()), each through the same estimator,
 * identified as the measured table was (the same options, tau up to
 * --max-tau-frac of the simulated record) and its AR(1) part tested as
 * the measured one's (ar1_identified_in()); a refit whose fit fails or
 * whose AR(1) part is not identified is counted, not used. The interval
 * is the central --conf share of the refits that are used (the 15.87 and
 * 84.13 percentiles at the default 68.27 %, one sigma), none when fewer
 * than 2.
 * @return 0; -3 interrupted (the channel's refitted stays 0); -1 out of
 *         memory (said; rf_oom set, refitted 0) */
static int refit_channel(run_t *R, chan_t *ch, int i, unsigned long seed, int fit_extra, hx_progress_t *pr,
                         double *done, double total)
{
    chan_t *t = (chan_t *)calloc(1, sizeof *t);
    double *v = (double *)malloc(3u * (size_t)R->refits * sizeof *v);
    hx_allan_fit_opts_t o = hx_allan_fit_opts_default;
    long k;
    int q, rc = 0;
    ch->rf_ok = ch->rf_fit_failed = ch->rf_unresolved = 0;
    ch->rf_oom = 0;
    for (q = 0; q < 3; q++) {
        ch->rf_ci[q][0] = ch->rf_ci[q][1] = (double)NAN;
    }
    if (t == NULL || v == NULL) {
        free(t);
        free(v);
        hx_error(CMD, "%s: %s: out of memory for the refits", R->source, ch->name);
        ch->rf_oom = 1;
        return -1;
    }
    t->scale = 1.0; /* the model is in display units */
    t->name = ch->name;
    o.with_quant = fit_extra;
    o.with_rrw = fit_extra;
    o.tau_max_s = R->tau_max_frac * (double)R->nrefit / R->rate_hz;
    for (k = 0; k < R->refits; k++) {
        hx_allan_ident_t id;
        const int st = refit_table(R, t, &ch->id.fit, refit_seed(seed, i, k), pr, done, total);
        if (st == -3 || hx_stop_sig) {
            rc = -3;
            break;
        }
        if (st == -4) {
            hx_error(CMD, "%s: %s: out of memory for the refits%s", R->source, ch->name,
                     R->exact ? " (--estimator exact keeps each simulated record, 8 to 24 bytes per sample)" : "");
            ch->rf_oom = 1;
            rc = -1;
            break;
        }
        if (st != 0 || hx_allan_identify(t->res, t->nres, R->rate_hz, &o, &id) != 0 || !id.fit_ok) {
            ch->rf_fit_failed++;
        } else if (!ar1_identified_in(R, t->res, t->nres, &id.fit, 1, tau_long_of(R, t),
                                      R->tau_max_frac * (double)R->nrefit)) {
            ch->rf_unresolved++;
        } else {
            v[ch->rf_ok] = id.fit.white;
            v[R->refits + ch->rf_ok] = id.fit.gm_tau_s * R->rate_hz;
            v[2 * R->refits + ch->rf_ok] = id.fit.gm_sigma;
            ch->rf_ok++;
        }
    }
    if (rc == 0) {
        ch->refitted = 1;
        for (q = 0; q < 3 && ch->rf_ok >= 2; q++) {
            double *w = v + (size_t)q * (size_t)R->refits;
            qsort(w, (size_t)ch->rf_ok, sizeof *w, hx_cmp_double);
            /* the central --conf share: the (1 -+ conf) / 2 percentiles
             * (15.87 and 84.13 at the default, one sigma) */
            ch->rf_ci[q][0] = hx_quantile_sorted(w, ch->rf_ok, 0.5 * (1.0 - R->conf));
            ch->rf_ci[q][1] = hx_quantile_sorted(w, ch->rf_ok, 0.5 * (1.0 + R->conf));
        }
    }
    free(t->x);
    free(t);
    free(v);
    return rc;
}

/* Whether a channel's corrected fit is refitted: fitted, its AR(1) part identified */
static int refit_eligible(const run_t *R, const chan_t *ch)
{
    return ch->id_ok && ch->id.fit_ok && !ch->constant && ar1_resolved(R, ch);
}

/* ------------------------------------------------------------ output */

static const char *fmt_g(char *b, size_t n, double v)
{
    return hx_fmt_g(b, n, v);
}

/* the noise type the slope reads at tau i, "periodic" where it is a periodic term's fall */
static const char *noise_name(const chan_t *ch, size_t i)
{
    return ch->periodic[i] ? "periodic" : fnav_allan_noise_name(ch->noise[i]);
}

static int in_range(const run_t *R, const fnav_allan_result_t *r)
{
    return r->terms > 0u && (double)r->tau <= tau_max_samples(R) * (1.0 + 1e-9);
}

/* A Fig. 7 simulation's point within --max-tau-frac of its own record, as
 * the measured curve's within the log's: with --sim-samples below the log's
 * length the log's limit would draw the simulated curves past their own
 * 10 %, down to a term or two. */
static int sim_in_range(const run_t *R, const fnav_allan_result_t *r)
{
    return r->terms > 0u && (double)r->tau <= R->tau_max_frac * (double)R->nsim * (1.0 + 1e-9);
}

static void print_regions(const run_t *R, const chan_t *ch)
{
    size_t i = 0;
    int nreg = 0;
    char b1[32], b2[32];
    printf("  noise types:");
    while (i < ch->nres) {
        size_t j = i;
        if (!in_range(R, &ch->res[i]) || ch->noise[i] == FNAV_ALLAN_NOISE_UNKNOWN) {
            i++;
            continue;
        }
        while (j + 1 < ch->nres && in_range(R, &ch->res[j + 1]) && ch->noise[j + 1] == ch->noise[i] &&
               ch->periodic[j + 1] == ch->periodic[i]) {
            j++;
        }
        /* "; " between the ranges, none after the last (it ended the line);
         * a region of one tau is that tau ("white 0.8 s", not "0.8-0.8 s") */
        printf("%s %s %s", nreg++ > 0 ? ";" : "", noise_name(ch, i),
               fmt_s(b1, sizeof b1, (double)ch->res[i].tau / R->rate_hz));
        if (j > i) {
            printf("-%s", fmt_s(b2, sizeof b2, (double)ch->res[j].tau / R->rate_hz));
        }
        printf(" s");
        i = j + 1;
    }
    printf("%s\n", nreg == 0 ? " none" : "");
}

/* --deviation: one table per deviation at the octave tau, laid out as
 * Stable32's (averaging factor, tau, terms, alpha, min, sigma, max). */
static void print_deviations(const run_t *R, const chan_t *ch)
{
    int j;
    size_t i;
    char b1[32], b2[32], b3[32];
    for (j = 0; j < R->ndev; j++) {
        const hx_dev_t k = R->dev[j];
        printf("\n  %s (%s) [%s%s], CI at %g confidence\n", hx_dev_title(k), hx_dev_name(k), ch->unit,
               k == HX_DEV_TDEV || k == HX_DEV_TTOTDEV ? " s" : "", R->conf);
        printf("  %9s %10s %9s %5s %12s %12s %12s\n", "m", "tau_s", "terms", "alpha", "min", "sigma", "max");
        for (i = 0; i < ch->nres; i++) {
            const uint32_t m = ch->res[i].tau;
            if (!in_range(R, &ch->res[i]) || (!R->m_given && (m & (m - 1u)) != 0u) || ch->dv_terms[k][i] == 0u) {
                continue;
            }
            printf("  %9lu %10.4g %9lu %5d %12s %12s %12s\n", (unsigned long)m, (double)m / R->rate_hz,
                   (unsigned long)ch->dv_terms[k][i], ch->alpha[i], fmt_g(b1, sizeof b1, ch->dv_lo[k][i]),
                   fmt_g(b2, sizeof b2, ch->dv[k][i]), fmt_g(b3, sizeof b3, ch->dv_hi[k][i]));
        }
        for (i = 0; i < ch->nres; i++) {
            if (ch->dv_skip[k][i] == 1u) {
                printf("  m >= %lu not computed: more than %g window terms per tau (the cost is O(n m)); raise "
                       "--max-work\n",
                       (unsigned long)ch->res[i].tau, R->max_work);
                break;
            }
            if (ch->dv_skip[k][i] == 2u) {
                printf("  m >= %lu not computed: the run was interrupted\n", (unsigned long)ch->res[i].tau);
                break;
            }
        }
    }
}

static void print_table(const run_t *R, const chan_t *ch)
{
    size_t i;
    char b1[32], b2[32], b3[32], b4[32];
    printf("\n%s [%s], %lu samples at %g Hz (%s; every tau in --out)\n", ch->label, ch->unit,
           (unsigned long)R->n, R->rate_hz, R->m_given ? "every --m within --max-tau-frac shown" : "octave tau shown");
    printf("  %10s %9s %12s %12s %12s %9s %12s %8s %6s %5s  %s\n", "tau_s", "m", "oadev", "ci_lo", "ci_hi", "terms",
           "adev", "terms_n", "slope", "alpha", "noise");
    for (i = 0; i < ch->nres; i++) {
        const fnav_allan_result_t *r = &ch->res[i];
        if (!in_range(R, r) || (!R->m_given && (r->tau & (r->tau - 1u)) != 0u)) {
            continue;
        }
        printf("  %10.4g %9lu %12s %12s %12s %9lu %12s %8lu %6.2f %4d%s  %s\n", (double)r->tau / R->rate_hz,
               (unsigned long)r->tau, fmt_g(b1, sizeof b1, sqrt((double)r->avar)), fmt_g(b2, sizeof b2, ch->lo[i]),
               fmt_g(b3, sizeof b3, ch->hi[i]), (unsigned long)r->terms,
               fmt_g(b4, sizeof b4, sqrt((double)r->avar_nonoverlap)), (unsigned long)r->terms_nonoverlap,
               (double)ch->slope[i], ch->alpha[i],
               ch->alpha_from[i] == HX_NOISE_ID_SLOPE ? "s" : ch->alpha_from[i] == HX_NOISE_ID_HELD ? "h" : "a",
               noise_name(ch, i));
    }
    print_regions(R, ch);
    print_deviations(R, ch);
}

static int ar1_resolved(const run_t *R, const chan_t *ch);
static int ar1_too_short(const run_t *R, const chan_t *ch);

/* The floor on the AR(1) correlation time, in samples, as the table and
 * the warning name it (HX_ALLAN_AR1_MIN_BUMP_SAMPLES / 1.89, rounded up) */
static double ar1_floor_samples(void)
{
    return ceil(HX_ALLAN_AR1_MIN_BUMP_SAMPLES / 1.89);
}

/* Whether the Gauss-Markov bound's T, t_BS / 1.89, lies under that floor
 * (an Allan minimum under HX_ALLAN_AR1_MIN_BUMP_SAMPLES): a correlation time
 * the identification refuses as the sensor's own filtering, which the bound
 * then does not state either; profile_model() raises it to the floor */
static int bound_at_floor(const run_t *R, const chan_t *ch)
{
    return (double)ch->id.paper.t_bs_s * R->rate_hz / 1.89 < ar1_floor_samples();
}
static int profile_model(const run_t *R, const chan_t *ch, hx_noise_model_t *m);

/* The span of tau about the paper's minimum over which the ADEV stays
 * within the minimum's confidence interval (at --conf): grid points in
 * range (in_range) on both sides of i_min, contiguous, whose overlapping
 * ADEV is at most the minimum's upper bound. Over a flat minimum (a
 * flicker floor) the lowest point is where the noise put it, and the
 * paper's t_BS, and with it tau and sigma_bias (eqs. 5-6), can move
 * anywhere in the span while BS does not (docs/allan.md, "The paper's
 * identification, as written"). 0 with *lo_s, *hi_s set; 1 so set when
 * the minimum is the first or last point in range (no minimum there: the
 * curve still falls or rises, which analyse_channel warns of); -1 when the
 * minimum has no interval. */
static int flat_span(const run_t *R, const chan_t *ch, double *lo_s, double *hi_s)
{
    const size_t im = ch->id.paper.i_min;
    double bound;
    size_t a, b;
    if (!(ch->id_ok && ch->id.paper_ok) || im >= ch->nres || !in_range(R, &ch->res[im]) || !(ch->hi[im] > 0.0) ||
        !isfinite(ch->hi[im])) {
        return -1;
    }
    bound = ch->hi[im];
    for (a = im; a > 0u && in_range(R, &ch->res[a - 1u]) && sqrt((double)ch->res[a - 1u].avar) <= bound; a--) {
    }
    for (b = im; b + 1u < ch->nres && in_range(R, &ch->res[b + 1u]) && sqrt((double)ch->res[b + 1u].avar) <= bound;
         b++) {
    }
    *lo_s = (double)ch->res[a].tau / R->rate_hz;
    *hi_s = (double)ch->res[b].tau / R->rate_hz;
    return im == 0u || !in_range(R, &ch->res[im - 1u]) || im + 1u >= ch->nres || !in_range(R, &ch->res[im + 1u]);
}

/* The channels whose flat span covers an octave or more, below the table:
 * their tau and sigma_bias at the span's ends */
static void print_flat(const run_t *R)
{
    int i, n = 0;
    char b1[32], b2[32], b3[32];
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        double lo, hi;
        if (flat_span(R, ch, &lo, &hi) != 0 || hi < 2.0 * lo) { /* no minimum: warned already */
            continue;
        }
        if (n++ == 0) {
            printf("The paper's t_BS on a flat minimum: the ADEV stays within the minimum's %.1f %% interval over "
                   "an octave or\nmore of tau, where the noise puts the lowest point; the paper's tau and "
                   "sigma_bias (eqs. 5-6) move\nwith t_BS across it, BS does not (docs/allan.md):\n",
                   100.0 * R->conf);
        }
        printf("%-6s %-6s | t_BS %s s, flat from %s to %s s: tau %.0f to %.0f samples, sigma_bias %.3g to %.3g\n",
               ch->label, ch->unit, fmt_s(b1, sizeof b1, (double)ch->id.paper.t_bs_s), fmt_s(b2, sizeof b2, lo),
               fmt_s(b3, sizeof b3, hi), lo * R->rate_hz, hi * R->rate_hz,
               (double)ch->id.paper.bs / sqrt(lo * R->rate_hz), (double)ch->id.paper.bs / sqrt(hi * R->rate_hz));
    }
}

/* --refits: the corrected fit's interval, under the parameter table (and
 * the bound's lines), one line per channel */
static void print_refits(const run_t *R)
{
    int i;
    char b1[32], b2[32];
    if (R->refits <= 0 || R->interrupted[0] != '\0') {
        return; /* off, or cut short by a signal (said in the warning) */
    }
    printf("Corrected fit, %.3g %% interval of %ld refits of the fitted model (parametric bootstrap: the %.4g and "
           "%.4g\npercentiles of the fits of %lu-sample simulations of it; the spread the fitted model gives at "
           "this length,\nnot a check of its form; docs/allan.md):\n",
           100.0 * R->conf, R->refits, 50.0 * (1.0 - R->conf), 50.0 * (1.0 + R->conf), (unsigned long)R->nrefit);
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        const int failed = ch->rf_fit_failed + ch->rf_unresolved;
        printf("%-6s %-6s | ", ch->label, ch->unit);
        if (!ch->refitted) {
            printf("%s\n", ch->rf_oom ? "n/a (out of memory for the refits: the error above)"
                                      : "n/a (no corrected fit with its AR(1) part identified: not refitted)");
            continue;
        }
        if (ch->rf_ok >= 2) {
            /* tau as the table's column: whole samples, %.3g past 1e9 (print_params()) */
            snprintf(b1, sizeof b1, ch->rf_ci[1][0] < 1e9 ? "%.0f" : "%.3g", ch->rf_ci[1][0]);
            snprintf(b2, sizeof b2, ch->rf_ci[1][1] < 1e9 ? "%.0f" : "%.3g", ch->rf_ci[1][1]);
            printf("sigma_v %.3g to %.3g, tau %s to %s samples, sigma_bias %.3g to %.3g", ch->rf_ci[0][0],
                   ch->rf_ci[0][1], b1, b2, ch->rf_ci[2][0], ch->rf_ci[2][1]);
        } else {
            printf("n/a (fewer than 2 refits usable)");
        }
        printf(" (%d of %ld refits", ch->rf_ok, R->refits);
        if (failed > 0) {
            printf("; %d failed: %d fit failed, %d AR(1) not identified", failed, ch->rf_fit_failed,
                   ch->rf_unresolved);
        }
        printf(")\n");
    }
}

static void print_params(const run_t *R)
{
    int i, nbound = 0, nother = 0;
    char b1[32];
    printf("\nBias model, units of the paper's Tables IV-VI (sigma_v in unit/sqrt(Hz), tau in samples at %g Hz,\n"
           "sigma_bias in unit; quality: RMS of log10 ADEV model/measured over tau <= %s s, and model/measured\n"
           "at the measured minimum):\n",
           R->rate_hz, fmt_s(b1, sizeof b1, tau_max_samples(R) / R->rate_hz));
    /* tau is in samples, as in the paper's tables, and the column says so:
     * right after tables whose tau_s is in seconds, "tau 1" would read as
     * 1 s */
    printf("%-6s %-6s | %-57s | %-57s\n", "", "", "paper III.C as written (eqs. 5-6, sigma_bias per eq. 4)",
           "corrected: LSQ fit of white + AR(1) Allan variance");
    printf("%-6s %-6s | %10s %12s %10s %10s %5s %6s | %10s %12s %10s %10s %5s %6s\n", "chan", "unit", "sigma_v",
           "tau[samples]", "sigma_bias", "BS", "rms", "@min", "sigma_v", "tau[samples]", "sigma_bias", "peak", "rms",
           "@min");
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        const hx_allan_ident_t *id = &ch->id;
        printf("%-6s %-6s |", ch->label, ch->unit);
        if (ch->id_ok && id->paper_ok) {
            printf(" %10.3g %12.0f %10.3g %10.3g %5.2f %6.3f |", (double)id->paper.sigma_v,
                   (double)id->paper.tau_samples, (double)id->paper.sigma_bias, (double)id->paper.bs,
                   id->paper_quality.rms_log10, id->paper_quality.ratio_at_min);
        } else {
            printf(" %-57s |", ch->constant ? "n/a (constant channel)" : "n/a (1 s or the minimum not covered)");
        }
        if (ch->id_ok && id->fit_ok) {
            const double tau_samples = id->fit.gm_tau_s * R->rate_hz;
            /* ADEV peak of the AR(1) alone (hx_allan_ident.h); a tau of a
             * fit the curve does not resolve can be any size (1.2e8 samples
             * on 10 s of white noise), %.0f would push the columns aside */
            printf(tau_samples < 1e9 ? " %10.3g %12.0f" : " %10.3g %12.3g", id->fit.white, tau_samples);
            printf(" %10.3g %10.3g %5.2f %6.3f", id->fit.gm_sigma, HX_GM_PEAK_RATIO * id->fit.gm_sigma,
                   id->fit_quality.rms_log10, id->fit_quality.ratio_at_min);
            if (id->fit.quant > 0.0 || id->fit.rrw > 0.0) {
                printf("  Q %.3g K %.3g", id->fit.quant, id->fit.rrw);
            }
            if (!ar1_resolved(R, ch)) {
                /* the JSON's ar1_identified = false: not the bias a profile takes */
                if (ar1_too_short(R, ch)) {
                    printf("  AR(1) not resolved by the curve (T below the %.0f-sample floor): see below",
                           ar1_floor_samples());
                } else {
                    printf("  AR(1) not resolved by the curve: see below");
                }
            }
            printf("\n");
        } else {
            printf(" n/a (%s)\n", ch->constant ? "constant channel" : "fit failed");
        }
    }
    /* Where the fit's AR(1) is not identified its numbers are no noise model
     * of the sensor (30 minutes of ADIS16405 log 1: gx sigma_v 0.0039
     * deg/s/sqrt(Hz) against the 0.0408 the profile holds), yet they read as
     * one: say so under the table, with the numbers a profile takes. */
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        hx_noise_model_t m;
        if (profile_model(R, ch, &m) != 1) {
            continue;
        }
        if (nbound++ == 0) {
            printf("AR(1) not identified (the JSON's ar1_identified false): the corrected sigma_v, tau and sigma_bias "
                   "of these\nchannels are no model of the sensor. %s instead the paper's sigma_v (the ADEV at 1 "
                   "s) and the\nGauss-Markov bound from the Allan minimum (T = t_BS / 1.89, sigma_bias = BS / "
                   "0.6174: the true T may be longer; docs/allan.md):\n",
                   R->is_series ? "A log's --profile would hold"
                   /* refused at the end for a log that moves or is not
                    * in SI units: no "holds" of a file not written */
                   : (R->units_bad || R->moving || R->win_moving > 0) ? "Of a static log in SI units, --profile "
                                                                        "would hold"
                                                                      : "--profile holds");
        }
        printf("%-6s %-6s | %s: sigma_v %.3g, tau %.0f samples (%s s), sigma_bias %.3g", ch->label, ch->unit,
               R->is_series ? "bound" : "profile", m.white, m.gm_tau_s * R->rate_hz, fmt_s(b1, sizeof b1, m.gm_tau_s),
               m.gm_sigma);
        if (bound_at_floor(R, ch)) {
            printf(" (T raised to the %.0f-sample floor from t_BS / 1.89 = %s s)", ar1_floor_samples(),
                   fmt_s(b1, sizeof b1, (double)ch->id.paper.t_bs_s / 1.89));
        }
        printf("\n");
    }
    print_refits(R);
    print_flat(R);
    for (i = 0; i < R->nch; i++) {
        nother += R->ch[i].id_ok && R->ch[i].id.paper_ok;
    }
    if (nother == 0) {
        /* the header and no row, on a record too short or a constant series */
        printf("\nOther readings of the paper's parameters: none (no channel has the paper's reading, above)\n");
        return;
    }
    printf("\nOther readings of the paper's parameters (RMS log10 ADEV model/measured; model/measured at the minimum):\n"
           "  drive:  sigma_bias taken as the std of the driving noise n_k (the Fig. 7 text), stationary std\n"
           "          sigma_bias / sqrt(1 - c^2)\n"
           "  sample: eq. (4) as above, but sigma_v drawn as the per-sample std (density sigma_v / sqrt(f_s))\n");
    printf("%-6s | %12s %8s | %12s %8s\n", "chan", "drive rms", "@min", "sample rms", "@min");
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        if (ch->id_ok && ch->id.paper_ok) {
            printf("%-6s | %12.2f %8.3f | %12.2f %8.3f\n", ch->label, ch->id.paper_drive_quality.rms_log10,
                   ch->id.paper_drive_quality.ratio_at_min, ch->id.paper_sample_quality.rms_log10,
                   ch->id.paper_sample_quality.ratio_at_min);
        }
    }
}

/* --deviation columns of one CSV row, ending the line. */
static void csv_deviations(const run_t *R, const chan_t *ch, size_t k, FILE *f)
{
    int j;
    char b[4][32];
    for (j = 0; j < R->ndev; j++) {
        const hx_dev_t d = R->dev[j];
        if (ch->dv_terms[d][k] == 0u) {
            fprintf(f, ",,,,,0");
            continue;
        }
        fprintf(f, ",%s,%s,%s,%s,%lu", fmt_g(b[0], 32, ch->dv[d][k]), fmt_g(b[1], 32, ch->dv_lo[d][k]),
                fmt_g(b[2], 32, ch->dv_hi[d][k]), fmt_g(b[3], 32, ch->dv_edf[d][k]),
                (unsigned long)ch->dv_terms[d][k]);
    }
    fprintf(f, "\n");
}

static int write_csv(const run_t *R, const char *path)
{
    FILE *f = hx_out_open(path); /* "-": standard output (hx_json_stdout_claim) */
    int i;
    size_t k;
    char b[16][32], line[4096];
    if (f == NULL) {
        hx_error(CMD, "%s: cannot create (%s)", path, strerror(errno));
        return -1;
    }
    fprintf(f, "# harness allan: %s, %lu samples at %g Hz; %s estimator; ADEV in the channel's unit; CI at %g "
               "confidence (Greenhall EDF)\n",
            hx_line_str(line, sizeof line, R->source), (unsigned long)R->n, R->rate_hz, R->exact ? "exact" : "streaming", R->conf);
    fprintf(f, "channel,unit,tau_s,m,level,stride,oadev,oadev_lo,oadev_hi,edf,terms,adev,adev_lo,adev_hi,edf_n,"
               "terms_n,slope,noise,sim_paper,sim_fit,model_paper,model_fit,alpha,alpha_from");
    for (i = 0; i < R->ndev; i++) {
        const char *n = hx_dev_name(R->dev[i]);
        fprintf(f, ",%s,%s_lo,%s_hi,%s_edf,%s_terms", n, n, n, n, n);
    }
    fprintf(f, "\n");
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        for (k = 0; k < ch->nres; k++) {
            const fnav_allan_result_t *r = &ch->res[k];
            double mp = (double)NAN, mf = (double)NAN;
            if (r->terms == 0u) {
                continue;
            }
            if (ch->id_ok && ch->id.paper_ok) {
                mp = sqrt(hx_noise_model_avar(&ch->id.paper_model, R->rate_hz, (double)r->tau));
            }
            if (ch->id_ok && ch->id.fit_ok) {
                mf = sqrt(hx_noise_model_avar(&ch->id.fit, R->rate_hz, (double)r->tau));
            }
            fprintf(f, "%s,%s,%s,%lu,%lu,%lu,%s,%s,%s,%s,%lu,%s,%s,%s,%s,%lu,%s,%s,%s,%s,%s,%s,%d,%s", ch->name, ch->unit,
                    fmt_g(b[0], 32, (double)r->tau / R->rate_hz), (unsigned long)r->tau, (unsigned long)r->level,
                    (unsigned long)r->stride, fmt_g(b[1], 32, sqrt((double)r->avar)), fmt_g(b[2], 32, ch->lo[k]),
                    fmt_g(b[3], 32, ch->hi[k]), fmt_g(b[4], 32, ch->edf[k]), (unsigned long)r->terms,
                    fmt_g(b[5], 32, sqrt((double)r->avar_nonoverlap)), fmt_g(b[6], 32, ch->lo_n[k]),
                    fmt_g(b[7], 32, ch->hi_n[k]), fmt_g(b[8], 32, ch->edf_n[k]), (unsigned long)r->terms_nonoverlap,
                    fmt_g(b[9], 32, (double)ch->slope[k]), noise_name(ch, k),
                    fmt_g(b[10], 32, ch->have_sim_paper ? sqrt((double)ch->sim_paper[k].avar) : (double)NAN),
                    fmt_g(b[11], 32, ch->have_sim_fit ? sqrt((double)ch->sim_fit[k].avar) : (double)NAN),
                    fmt_g(b[12], 32, mp), fmt_g(b[13], 32, mf), ch->alpha[k], hx_noise_id_name(ch->alpha_from[k]));
            csv_deviations(R, ch, k, f);
        }
    }
    return hx_out_finish(CMD, path, f);
}

static void json_model(cJSON *o, const hx_noise_model_t *m, double fs)
{
    hx_json_num(o, "sigma_v", m->white);
    hx_json_num(o, "tau_samples", m->gm_tau_s * fs);
    hx_json_num(o, "tau_s", m->gm_tau_s);
    hx_json_num(o, "sigma_bias", m->gm_sigma);
    hx_json_num(o, "quant", m->quant);
    hx_json_num(o, "rrw", m->rrw);
}

static void json_quality(cJSON *o, const hx_allan_quality_t *q)
{
    cJSON *j = cJSON_AddObjectToObject(o, "quality");
    hx_json_num(j, "rms_log10", q->rms_log10);
    hx_json_num(j, "max_ratio", q->max_ratio);
    hx_json_num(j, "ratio_at_min", q->ratio_at_min);
    cJSON_AddNumberToObject(j, "points", q->npoints);
}

/* --deviation keys of one table entry: an object per deviation. */
static void json_deviations(const run_t *R, const chan_t *ch, size_t k, cJSON *e)
{
    int j;
    for (j = 0; j < R->ndev; j++) {
        const hx_dev_t d = R->dev[j];
        cJSON *o = cJSON_AddObjectToObject(e, hx_dev_name(d));
        cJSON_AddNumberToObject(o, "terms", (double)ch->dv_terms[d][k]);
        if (ch->dv_skip[d][k]) {
            cJSON_AddStringToObject(o, "not_computed", ch->dv_skip[d][k] == 2u ? "interrupted" : "max_work");
        }
        if (ch->dv_terms[d][k] > 0u) {
            hx_json_num(o, "dev", ch->dv[d][k]);
            hx_json_num(o, "lo", ch->dv_lo[d][k]);
            hx_json_num(o, "hi", ch->dv_hi[d][k]);
            hx_json_num(o, "edf", ch->dv_edf[d][k]);
        }
    }
}


static int write_json(const run_t *R, const char *path)
{
    cJSON *root = cJSON_CreateObject(), *arr;
    char err[HX_ERR_SIZE];
    int i, rc;
    size_t k;
    cJSON_AddStringToObject(root, "source", R->source);
    /* the name replay's JSON gives the input file; source, the older key,
     * kept as its alias (docs/allan.md, "JSON") */
    cJSON_AddStringToObject(root, "log", R->source);
    cJSON_AddStringToObject(root, "sensor", R->sensor);
    cJSON_AddNumberToObject(root, "rate_hz", R->rate_hz);
    cJSON_AddNumberToObject(root, "samples", (double)R->n);
    cJSON_AddNumberToObject(root, "tau_max_s", tau_max_samples(R) / R->rate_hz);
    cJSON_AddNumberToObject(root, "confidence", R->conf);
    cJSON_AddStringToObject(root, "estimator", R->exact ? "exact" : "streaming");
    if (R->exact) {
        /* no streaming estimator runs: the channel's record instead (8 bytes per phase value) */
        cJSON_AddNullToObject(root, "estimator_bytes_per_channel");
    } else {
        /* every estimator of the channel, as the screen's header says (two at 4 tau per octave) */
        cJSON_AddNumberToObject(root, "estimator_bytes_per_channel", (double)(sizeof(fnav_allan_t) * (size_t)R->nchunk));
    }
    if (R->f0 > 0.0) {
        cJSON_AddNumberToObject(root, "fractional_f0", R->f0);
    }
    /* as info's, replay's, psd's and simgap's: false when the input
     * stopped at an error, the tables covering the samples before it */
    cJSON_AddBoolToObject(root, "complete", R->input_error[0] == '\0' && R->interrupted[0] == '\0');
    if (R->input_error[0] != '\0' || R->interrupted[0] != '\0') {
        /* a signal (Ctrl-C) as simgap-validate's: "interrupted by SIGINT: ..." */
        cJSON_AddStringToObject(root, "error", R->input_error[0] != '\0' ? R->input_error : R->interrupted);
    }
    if (R->interrupted[0] != '\0') {
        cJSON_AddStringToObject(root, "interrupted", R->interrupted);
    }
    arr = cJSON_AddArrayToObject(root, "channels");
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        cJSON *c = cJSON_CreateObject(), *t, *p;
        cJSON_AddStringToObject(c, "name", ch->name);
        cJSON_AddStringToObject(c, "unit", ch->unit);
        p = cJSON_AddObjectToObject(c, "paper");
        if (ch->id_ok && ch->id.paper_ok) {
            hx_json_num(p, "sigma_v", (double)ch->id.paper.sigma_v);
            hx_json_num(p, "bs", (double)ch->id.paper.bs);
            hx_json_num(p, "t_bs_s", (double)ch->id.paper.t_bs_s);
            hx_json_num(p, "tau_samples", (double)ch->id.paper.tau_samples);
            hx_json_num(p, "sigma_bias", (double)ch->id.paper.sigma_bias);
            {
                double lo, hi;
                if (flat_span(R, ch, &lo, &hi) >= 0) {
                    cJSON *fl = cJSON_AddArrayToObject(p, "t_bs_flat_s");
                    cJSON_AddItemToArray(fl, cJSON_CreateNumber(lo));
                    cJSON_AddItemToArray(fl, cJSON_CreateNumber(hi));
                } else {
                    cJSON_AddNullToObject(p, "t_bs_flat_s");
                }
            }
            json_quality(p, &ch->id.paper_quality);
            {
                cJSON *rd = cJSON_AddObjectToObject(p, "reading_drive");
                json_model(rd, &ch->id.paper_drive_model, R->rate_hz);
                json_quality(rd, &ch->id.paper_drive_quality);
                rd = cJSON_AddObjectToObject(p, "reading_sample");
                json_quality(rd, &ch->id.paper_sample_quality);
            }
        }
        p = cJSON_AddObjectToObject(c, "corrected");
        if (ch->id_ok && ch->id.fit_ok) {
            json_model(p, &ch->id.fit, R->rate_hz);
            hx_json_num(p, "gm_adev_peak", HX_GM_PEAK_RATIO * ch->id.fit.gm_sigma);
            json_quality(p, &ch->id.fit_quality);
        }
        /* false: no fit, or the curve does not resolve its AR(1) part; a
         * --profile then holds the bound from the Allan minimum */
        cJSON_AddBoolToObject(p, "ar1_identified", ch->id_ok && ar1_resolved(R, ch));
        if (ch->rf_oom) {
            /* the refits stopped out of memory (said, exit 1): no interval */
            cJSON *rf = cJSON_AddObjectToObject(p, "refits");
            hx_json_num(rf, "requested", (double)R->refits);
            cJSON_AddStringToObject(rf, "error", "out of memory");
        }
        if (ch->refitted) {
            /* --refits: the parametric bootstrap's counts and intervals at
             * --conf (the root's "confidence"; null: fewer than 2 refits
             * usable) */
            static const char *const keys[3] = { "sigma_v_ci", "tau_samples_ci", "sigma_bias_ci" };
            cJSON *rf = cJSON_AddObjectToObject(p, "refits");
            int q;
            hx_json_num(rf, "requested", (double)R->refits);
            hx_json_num(rf, "samples", (double)R->nrefit);
            hx_json_num(rf, "ok", (double)ch->rf_ok);
            hx_json_num(rf, "failed", (double)(ch->rf_fit_failed + ch->rf_unresolved));
            hx_json_num(rf, "fit_failed", (double)ch->rf_fit_failed);
            hx_json_num(rf, "ar1_not_identified", (double)ch->rf_unresolved);
            for (q = 0; q < 3; q++) {
                if (ch->rf_ok >= 2) {
                    cJSON *ci = cJSON_AddArrayToObject(p, keys[q]);
                    cJSON_AddItemToArray(ci, cJSON_CreateNumber(ch->rf_ci[q][0]));
                    cJSON_AddItemToArray(ci, cJSON_CreateNumber(ch->rf_ci[q][1]));
                } else {
                    cJSON_AddNullToObject(p, keys[q]);
                }
            }
        }
        /* the model a --profile takes: the fit, or where its AR(1) is not
         * identified the bound from the Allan minimum (whose numbers the
         * corrected object above does not hold); empty when there is none */
        p = cJSON_AddObjectToObject(c, "profile");
        {
            hx_noise_model_t m;
            const int bound = profile_model(R, ch, &m);
            if (bound >= 0) {
                cJSON_AddStringToObject(p, "basis", bound ? "bound" : "fit");
                json_model(p, &m, R->rate_hz);
                /* the bound's T raised to the floor (t_BS / 1.89 under it) */
                cJSON_AddBoolToObject(p, "tau_at_floor", bound == 1 && bound_at_floor(R, ch));
            }
        }
        t = cJSON_AddArrayToObject(c, "table");
        for (k = 0; k < ch->nres; k++) {
            const fnav_allan_result_t *r = &ch->res[k];
            cJSON *e;
            if (r->terms == 0u) {
                continue;
            }
            e = cJSON_CreateObject();
            hx_json_num(e, "tau_s", (double)r->tau / R->rate_hz);
            cJSON_AddNumberToObject(e, "m", (double)r->tau);
            cJSON_AddNumberToObject(e, "stride", (double)r->stride);
            hx_json_num(e, "oadev", sqrt((double)r->avar));
            hx_json_num(e, "lo", ch->lo[k]);
            hx_json_num(e, "hi", ch->hi[k]);
            hx_json_num(e, "edf", ch->edf[k]);
            cJSON_AddNumberToObject(e, "terms", (double)r->terms);
            hx_json_num(e, "adev", sqrt((double)r->avar_nonoverlap));
            cJSON_AddNumberToObject(e, "terms_n", (double)r->terms_nonoverlap);
            hx_json_num(e, "slope", (double)ch->slope[k]);
            cJSON_AddStringToObject(e, "noise", noise_name(ch, k));
            cJSON_AddNumberToObject(e, "alpha", (double)ch->alpha[k]);
            cJSON_AddStringToObject(e, "alpha_from", hx_noise_id_name(ch->alpha_from[k]));
            if (ch->have_sim_paper) {
                hx_json_num(e, "sim_paper", sqrt((double)ch->sim_paper[k].avar));
            }
            if (ch->have_sim_fit) {
                hx_json_num(e, "sim_fit", sqrt((double)ch->sim_fit[k].avar));
            }
            json_deviations(R, ch, k, e);
            cJSON_AddItemToArray(t, e);
        }
        cJSON_AddItemToArray(arr, c);
    }
    rc = hx_write_json(path, root, err, sizeof err);
    cJSON_Delete(root);
    if (rc != 0) {
        hx_error(CMD, "%s", err);
    }
    return rc;
}

/* Writes a datablock; returns the number of points (log axes: positive only). */
static int plot_block(FILE *gp, const char *name, const run_t *R, const chan_t *ch, int what)
{
    size_t k;
    int np = 0;
    hx_noise_model_t bound;
    /* what 4: the Gauss-Markov bound a profile holds where the fit's AR(1)
     * is not resolved (profile_model() 1) */
    const int bound_ok = what == 4 && profile_model(R, ch, &bound) == 1;
    fprintf(gp, "$%s << EOD\n", name);
    for (k = 0; k < ch->nres; k++) {
        const fnav_allan_result_t *r = &ch->res[k];
        const double t = (double)r->tau / R->rate_hz;
        if (!in_range(R, r)) {
            continue;
        }
        if (what == 0) {
            if (isfinite(ch->lo[k]) && ch->lo[k] > 0.0 && (double)r->avar > 0.0) {
                fprintf(gp, "%.6g %.6g %.6g %.6g\n", t, sqrt((double)r->avar), ch->lo[k], ch->hi[k]);
                np++;
            }
        } else if (what == 1 && ch->have_sim_paper && sim_in_range(R, &ch->sim_paper[k]) &&
                   (double)ch->sim_paper[k].avar > 0.0) {
            fprintf(gp, "%.6g %.6g\n", t, sqrt((double)ch->sim_paper[k].avar));
            np++;
        } else if (what == 2 && ch->have_sim_fit && sim_in_range(R, &ch->sim_fit[k]) &&
                   (double)ch->sim_fit[k].avar > 0.0) {
            fprintf(gp, "%.6g %.6g\n", t, sqrt((double)ch->sim_fit[k].avar));
            np++;
        } else if (what == 3 && ch->id_ok && ch->id.fit_ok) {
            fprintf(gp, "%.6g %.6g\n", t, sqrt(hx_noise_model_avar(&ch->id.fit, R->rate_hz, (double)r->tau)));
            np++;
        } else if (what == 4 && bound_ok) {
            fprintf(gp, "%.6g %.6g\n", t, sqrt(hx_noise_model_avar(&bound, R->rate_hz, (double)r->tau)));
            np++;
        }
    }
    fprintf(gp, "EOD\n");
    return np;
}

static int write_plot(const run_t *R, const char *path)
{
    hx_plot_t p;
    char q[512];
    int i, cols = R->nch > 3 ? 3 : R->nch, rows = (R->nch + 2) / 3;
    if (hx_plot_open(&p, CMD, path, 520 * cols, 420 * rows) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout %d,%d title 'Allan deviation: %s (%g Hz, %lu samples)'\n", rows, cols,
            hx_gp_str(q, sizeof q, R->source), R->rate_hz, (unsigned long)R->n);
    fprintf(p.gp, "set logscale xy\nset format y '%%.0e'\nset key bottom left font ',8'\nset xlabel 'tau [s]'\n");
    for (i = 0; i < R->nch; i++) {
        const chan_t *ch = &R->ch[i];
        const int nm = plot_block(p.gp, "m", R, ch, 0);
        const int nsp = plot_block(p.gp, "sp", R, ch, 1);
        const int nsf = plot_block(p.gp, "sf", R, ch, 2);
        const int naf = plot_block(p.gp, "af", R, ch, 3);
        const int npb = plot_block(p.gp, "pb", R, ch, 4);
        /* an unresolved fit is no model of the sensor: the legend says so,
         * and the bound the profile holds instead is drawn, not such a fit
         * as the corrected model without the bound */
        const char *unres = npb > 0 ? " (unresolved)" : "";
        fprintf(p.gp, "set title '%s'\n", hx_gp_str(q, sizeof q, ch->label));
        fprintf(p.gp, "set ylabel 'ADEV [%s]'\n", hx_gp_str(q, sizeof q, ch->unit));
        if (nm == 0) {
            /* nothing positive to draw on log axes: an empty panel that says so */
            fprintf(p.gp, "set label 1 '%s' at graph 0.5,0.5 center\nset xrange [0.01:1]\n"
                          "set yrange [0.01:1]\nplot 10 notitle\nunset label 1\nset autoscale\n",
                    ch->constant ? "constant channel (ADEV 0)" : "not enough data");
            continue;
        }
        fprintf(p.gp, "plot $m using 1:2:3:4 with yerrorbars pt 7 ps 0.5 lc rgb '#c00000' title 'measured (OADEV, "
                      "%.3g CI)'",
                R->conf);
        if (nsp > 0) {
            fprintf(p.gp, ", $sp using 1:2 with linespoints lw 1.5 pt 6 ps 0.5 lc rgb '#0050c0' title 'simulated, "
                          "paper id.'");
        }
        if (nsf > 0) {
            fprintf(p.gp, ", $sf using 1:2 with linespoints lw 1.5 pt 4 ps 0.5 lc rgb '#008000' title 'simulated, "
                          "corrected id.%s'",
                    unres);
        }
        if (naf > 0) {
            fprintf(p.gp, ", $af using 1:2 with lines dt 2 lc rgb '#404040' title 'corrected model (analytic%s)'",
                    npb > 0 ? ", unresolved" : "");
        }
        if (npb > 0) {
            /* a series has no profile: the table's line says "bound" */
            fprintf(p.gp, ", $pb using 1:2 with lines lw 2 lc rgb '#e08000' title '%sGM bound (analytic)'",
                    R->is_series ? "" : "profile: ");
        }
        fprintf(p.gp, "\n");
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, CMD);
}

/* Whether a profile name is one line of printable UTF-8 text (nothing
 * hx_text_char shows as '?': the profile reader refuses such a name). */
static int name_printable(const char *s)
{
    while (*s != '\0') {
        int ctl;
        s += hx_text_char(s, &ctl);
        if (ctl) {
            return 0;
        }
    }
    return 1;
}

/* The file name of path up to its first '.', as one line of the
 * profile: a control character (or a byte that is not UTF-8) one '_',
 * cut to fit out at a character's start (never inside a UTF-8 letter) */
static void base_name(const char *path, char *out, size_t n)
{
    const char *c = strrchr(path, '/');
    size_t o = 0;
    for (c = c != NULL ? c + 1 : path; *c != '\0' && *c != '.';) {
        int ctl;
        const size_t k = hx_text_char(c, &ctl);
        if (o + (ctl ? 1u : k) >= n) {
            break;
        }
        if (ctl) {
            out[o++] = '_'; /* one '_' for the character, of one byte or two */
        } else {
            memcpy(out + o, c, k); /* a UTF-8 letter whole ('\001' U+00E9 keeps its U+00E9) */
            o += k;
        }
        c += k;
    }
    out[o] = '\0';
}

/* The still part of a static log that moves in places (a few windows: it
 * was handled at its start or end, or knocked): the longest run of windows
 * that do not move, its ends moved inward past the disturbed windows next to
 * a moving one (the tail of the handling), in whole seconds from the first
 * sample, rounded inward: *start_s (0: from the first sample) and *end_s (0:
 * to the last). *from_s and *to_s span the moving windows, the first's
 * start to the last's end. -1 when the windows' spreads were not kept (out
 * of memory) or no window is still. */
static int still_part(const run_t *R, double *from_s, double *to_s, double *start_s, double *end_s)
{
    const double win_s = (double)R->win_len / R->rate_hz;
    double med[2];
    long i, run_a = 0, a = 0, b = 0, first = -1, last = -1;
    int have_med;
    if (R->win_spread == NULL || (size_t)R->win_n > R->win_cap || !(win_s > 0.0)) {
        return -1;
    }
    have_med = spread_medians(R, med) == 0;
    for (i = 0; i <= R->win_n; i++) {
        if (i == R->win_n || window_moving(R, i)) {
            if (i - run_a > b - a) {
                a = run_a;
                b = i;
            }
            run_a = i + 1;
            if (i < R->win_n) {
                first = first < 0 ? i : first;
                last = i;
            }
        }
    }
    while (have_med && a > 0 && a < b && window_disturbed(R, a, med)) {
        a++;
    }
    while (have_med && b < R->win_n && b > a && window_disturbed(R, b - 1, med)) {
        b--;
    }
    if (first < 0 || b <= a) {
        return -1;
    }
    *from_s = (double)first * win_s;
    *to_s = (double)(last + 1) * win_s;
    *start_s = a > 0 ? ceil((double)a * win_s - 1e-9) : 0.0;
    *end_s = b < R->win_n ? floor((double)b * win_s + 1e-9) : 0.0;
    return *end_s > 0.0 && !(*end_s > *start_s) ? -1 : 0;
}

/* path as one shell word (n >= 8): as it is when it holds only characters
 * no shell reads, else in single quotes (a quote inside as '\''). */
static void shell_word(const char *path, char *out, size_t n)
{
    size_t len = 0;
    const char *c;
    if (path[0] != '\0' &&
        strspn(path, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./+,:=@%-") == strlen(path)) {
        snprintf(out, n, "%s", path);
        return;
    }
    out[len++] = '\'';
    for (c = path; *c != '\0' && len + 6 < n; c++) {
        if (*c == '\'') {
            memcpy(out + len, "'\\''", 4);
            len += 4;
        } else {
            out[len++] = *c;
        }
    }
    out[len++] = '\'';
    out[len] = '\0';
}

/* A static log that moves in some of its windows, fewer than
 * HX_ALLAN_MOVING_FRAC of them (a log that starts with handling: the sensor
 * picked up and put down). The Allan variance includes that motion, and a
 * profile from it is no sensor's: 5 s of handling (1-2 m/s^2, 1 rad/s) at
 * the start of 30 minutes of ADIS16405 log 1 raised the gx noise the
 * profile held 14 times (0.555 against 0.0408 deg/s/sqrt(Hz)), with a
 * warning that named only the first moving second and exit 0. The message
 * names the span that moves and the command that cuts the log to its
 * longest still part; with --profile (profile != 0) it is an error: no
 * profile is written (the caller), the tables still are. */
static void motion_report(const run_t *R, const char *path, int profile)
{
    double from_s = R->win_first_moving_s, to_s = 0.0, start_s = 0.0, end_s = 0.0;
    char log[1100], out[300], base[256], cut[1500], span[96];
    const int have = still_part(R, &from_s, &to_s, &start_s, &end_s) == 0;
    if (have) {
        size_t len;
        shell_word(path, log, sizeof log);
        base_name(path, base, sizeof base);
        snprintf(cut, sizeof cut, "%s_still.csv", base);
        shell_word(cut, out, sizeof out);
        len = (size_t)snprintf(cut, sizeof cut, "bin/harness convert %s %s", log, out);
        if (start_s > 0.0 && len < sizeof cut) {
            len += (size_t)snprintf(cut + len, sizeof cut - len, " --start %.0f", start_s);
        }
        if (end_s > 0.0 && len < sizeof cut) {
            snprintf(cut + len, sizeof cut - len, " --end %.0f", end_s);
        }
        snprintf(span, sizeof span, "from %.0f s to %.0f s", from_s, to_s);
    } else {
        snprintf(cut, sizeof cut, "bin/harness convert LOG OUT --start S --end S");
        snprintf(span, sizeof span, "the first at %.0f s", from_s);
    }
    if (profile) {
        hx_error(CMD,
                 "%s: %ld of %ld one-second windows move (the rate spreads by more than %g rad/s RMS or |f| by more "
                 "than %g m/s^2; %s): the Allan variance includes that motion, and a profile from it would hold a "
                 "noise far above the sensor's, so none is written; cut the log to its still part (`%s`) and run "
                 "allan on that (docs/allan.md, \"Command\")",
                 path, R->win_moving, R->win_n, HX_ALLAN_MOVING_GYRO_RPS, HX_ALLAN_MOVING_F_MPS2, span, cut);
    } else {
        hx_warn(CMD,
                "%s: %ld of %ld one-second windows move (the rate spreads by more than %g rad/s RMS or |f| by more "
                "than %g m/s^2; %s): the Allan variance and the parameters below include that motion (a --profile "
                "would be refused); cut the log to its still part (`%s`)",
                path, R->win_moving, R->win_n, HX_ALLAN_MOVING_GYRO_RPS, HX_ALLAN_MOVING_F_MPS2, span, cut);
    }
}

/* Whether the model (AVAR all at table entry r) exceeds the model without
 * one of its parts (null) by more than the measured point can tell: two
 * standard errors of its log ADEV, sqrt(1/(2 EDF) + floor^2) as in the fit's
 * weights, with the EDF of the noise type the null model has there (its
 * local slope: the uncertainty if the part were absent; the measured slope
 * reads white noise as white phase noise often enough at long tau, EDF 20x
 * too high). The fit's 5 % floor alone was no test: at EDF 10-50 the
 * measured ADEV is uncertain by 10-22 %, and a fit of pure white noise raises
 * its AR(1) above the white part by 5 % in 26 of 100 records of
 * 10-1000 s. */
static int part_resolved(const run_t *R, const fnav_allan_result_t *r, double all, const hx_noise_model_t *null)
{
    const double m = (double)r->tau, fl = hx_allan_fit_opts_default.model_floor;
    const double v0 = hx_noise_model_avar(null, R->rate_hz, m);
    const double lo = m / 1.1 > 1.0 ? m / 1.1 : 1.0, hi = m * 1.1;
    const double slope =
        0.5 * log(hx_noise_model_avar(null, R->rate_hz, hi) / hx_noise_model_avar(null, R->rate_hz, lo)) / log(hi / lo);
    double edf = hx_allan_point_edf(r, fnav_allan_noise_from_slope((fnav_real_t)slope), 1), sd;
    if (!(edf > 0.0)) {
        edf = r->terms_nonoverlap > 0u ? (double)r->terms_nonoverlap : 1.0;
    }
    sd = sqrt(1.0 / (2.0 * edf) + fl * fl);
    return v0 > 0.0 ? 0.5 * log(all / v0) > 2.0 * sd : all > 0.0;
}

/* Whether the fitted AR(1) part is identified by the measured curve: its
 * bump (near 1.89 T) lies within the measured averaging times (a bump beyond
 * the longest is a random walk in disguise, one below a sample is white
 * noise in disguise), and somewhere in the fitted range it raises the
 * model's ADEV above the rest of the model by more than the measurement can
 * tell (part_resolved(); else the curve is white throughout and T and
 * sigma are whatever the optimiser stopped at: a 1-minute log gave
 * T = 8e-6 s, sigma = 1.3e-6 m/s^2, a bias the filter would then never
 * estimate). */
static int ar1_identified_in(const run_t *R, const fnav_allan_result_t *res, size_t nres, const hx_noise_model_t *f,
                             int fit_ok, double tau_long_s, double tau_max)
{
    hx_noise_model_t w = *f, nw = *f;
    const double bump_s = 1.89 * f->gm_tau_s;
    int ar1_seen = 0, white_seen = 0;
    size_t j;
    /* a bump within two decades of one sample is the sensor's own filtering,
     * not a bias (HX_ALLAN_AR1_MIN_BUMP_SAMPLES): 10 minutes of ADIS16405
     * log 1 fit gx with T = 1 sample and a white noise of 0.0279
     * deg/s/sqrt(Hz) for the log's 0.040 */
    if (!fit_ok || !(bump_s <= tau_long_s) || !(bump_s * R->rate_hz >= HX_ALLAN_AR1_MIN_BUMP_SAMPLES)) {
        return 0;
    }
    w.gm_sigma = 0.0; /* the model without its AR(1) part */
    nw.white = 0.0;   /* the model without its white part */
    for (j = 0; j < nres; j++) {
        const fnav_allan_result_t *r = &res[j];
        const double m = (double)r->tau;
        double all;
        if (r->terms < 2u || m > tau_max * (1.0 + 1e-9)) {
            continue;
        }
        all = hx_noise_model_avar(f, R->rate_hz, m);
        ar1_seen |= part_resolved(R, r, all, &w);
        /* the white part too must show somewhere: a fit that traded it for
         * an AR(1) of about a sample (10 s of ADIS16405 log 1: ay white
         * 5.2e-9 m/s^2/sqrt(Hz), T = 0.0078 s) is white noise in disguise,
         * not an identified bias */
        white_seen |= part_resolved(R, r, all, &nw);
    }
    return ar1_seen && white_seen;
}

/* ar1_identified_in() of the channel's measured table and fit, over the
 * tau the identification keeps to */
static int ar1_identified(const run_t *R, const chan_t *ch, double tau_long_s)
{
    return ar1_identified_in(R, ch->res, ch->nres, &ch->id.fit, ch->id.fit_ok, tau_long_s, tau_max_samples(R));
}

/* The channel's longest averaging time with data, s: it bounds what can be
 * identified (an AR(1) whose bump, near 1.89 T, lies beyond it is a random
 * walk in disguise, with an arbitrary sigma). */
static double tau_long_of(const run_t *R, const chan_t *ch)
{
    double tau_long_s = 0.0;
    size_t j;
    for (j = 0; j < ch->nres; j++) {
        if (ch->res[j].terms > 0) {
            tau_long_s = (double)ch->res[j].tau / R->rate_hz;
        }
    }
    return tau_long_s;
}

/* ar1_identified with the channel's longest averaging time with data */
static int ar1_resolved(const run_t *R, const chan_t *ch)
{
    return ar1_identified(R, ch, tau_long_of(R, ch));
}

/* Whether the fit's AR(1) is refused for its correlation time: its bump
 * lies from one sample up to HX_ALLAN_AR1_MIN_BUMP_SAMPLES, where the
 * sensor's own filtering shapes the curve (a bump under one sample is
 * white noise in disguise, refused as unresolved). */
static int ar1_too_short(const run_t *R, const chan_t *ch)
{
    const double bump = 1.89 * ch->id.fit.gm_tau_s * R->rate_hz; /* as ar1_identified() */
    return ch->id.fit_ok && ch->id.fit.gm_sigma > 0.0 && bump >= 1.0 && bump < HX_ALLAN_AR1_MIN_BUMP_SAMPLES;
}

/* The noise model a --profile takes for one channel (docs/allan.md, "When
 * the AR(1) part is not identifiable"), in the channel's display unit:
 * returns 0 with the fit where its AR(1) part is identified, 1 with the
 * bound from the Allan minimum where it is not (the fit's numbers are then
 * no model of the sensor: 30 minutes of ADIS16405 log 1 fitted gx with
 * sigma_v 0.0039 deg/s/sqrt(Hz), ten times below the 0.0408 the profile
 * holds), -1 when there is neither (no fit or no paper identification).
 * The table, the JSON and write_profile() all take it from here. */
static int profile_model(const run_t *R, const chan_t *ch, hx_noise_model_t *m)
{
    memset(m, 0, sizeof *m);
    if (ch->constant || !ch->id_ok || (!ch->id.fit_ok && !ch->id.paper_ok)) {
        return -1;
    }
    if (ar1_resolved(R, ch)) {
        *m = ch->id.fit;
        return 0;
    }
    if (!ch->id.paper_ok) {
        return -1;
    }
    /* The AR(1) part is not identifiable: white noise dominates the
     * whole curve (typically a bias correlation time longer than a
     * tenth of the record, or a record too short to leave the white
     * part). Take the conservative first-order
     * Gauss-Markov bound from the curve's minimum: the AR(1) Allan
     * deviation peaks at 0.6174 sigma at tau = 1.893 T (docs/allan.md),
     * so T = t_min / 1.89 and sigma = ADEV_min / 0.6174 put the model's bump
     * on the lowest measured point. No upper bound for the bias in
     * general: a pure Gauss-Markov channel (T = 1 s, sigma 0.004, no
     * white noise, 10^4 s) gets T = 520 s, sigma 2.4e-4 (docs/allan.md).
     * A minimum under HX_ALLAN_AR1_MIN_BUMP_SAMPLES would give a T under the
     * floor the fit is refused for (21-26 samples from a minimum near 0.45 s
     * at 100 Hz): T is then the floor, the shortest correlation time the
     * curve can tell from the sensor's filtering, its bump at the minimum's
     * height where the curve lies at or above it. */
    m->white = (double)ch->id.paper.sigma_v;
    m->gm_tau_s = bound_at_floor(R, ch) ? ar1_floor_samples() / R->rate_hz : (double)ch->id.paper.t_bs_s / 1.89;
    m->gm_sigma = (double)ch->id.paper.bs / 0.6174;
    return 1;
}

/* The error for a channel with no identification at all. After the
 * time-unit warning (stamps in ms read as 0.1 Hz) that is the likely cause:
 * below 1 Hz the shortest tau is past the 1 s the white noise is read at,
 * and "too little data?" would send the user to the record's length. */
/* The samples the paper's white noise, the ADEV at 1 s, needs: twice the
 * first grid tau at or above 1 s (a level-0 term needs 2 m + 1 phase
 * values); 0 when the grid ends below 1 s. */
static double one_s_needs(const run_t *R)
{
    size_t i;
    for (i = 0; i < R->ngrid; i++) {
        if ((double)R->grid[i] >= R->rate_hz) {
            return 2.0 * (double)R->grid[i];
        }
    }
    return 0.0;
}

static void no_identification(const run_t *R, const char *path, const chan_t *ch)
{
    if (R->time_unit_warned) {
        hx_error(CMD, "%s: no identification for %s, most likely because of the time stamps' unit (the warning "
                      "above): read at %.3g Hz, the shortest tau, %.3g s, lies past the 1 s the white noise is read "
                      "at; convert the time column to seconds (or give --rate) and run allan again; profile not "
                      "written",
                 path, ch->name, R->rate_hz, 1.0 / R->rate_hz);
    } else if (one_s_needs(R) > (double)R->n) {
        /* how much is enough, said ("(too little data?)" would leave the
         * user to guess) */
        const double m1 = one_s_needs(R) / 2.0;
        hx_error(CMD, "%s: no identification for %s: the record, %.3g s (%lu samples), is too short: the white noise "
                      "is read at tau = 1 s, whose Allan point (%.3g s, m = %.0f) needs %.0f samples (%.3g s); record "
                      "%.3g s or more, far longer for the bias (docs/workflow.md); profile not written",
                 path, ch->name, (double)R->n / R->rate_hz, (unsigned long)R->n, m1 / R->rate_hz, m1, 2.0 * m1,
                 2.0 * m1 / R->rate_hz, 1.0 / R->tau_max_frac);
    } else {
        hx_error(CMD, "%s: no identification for %s (too little data?); profile not written", path, ch->name);
    }
}

/* Why the fit's AR(1) is not what the profile takes (ar1_resolved() false),
 * naming the test that failed and the limit it used: "longest tau 287 s"
 * beside a table that says "tau <= 60 s" would leave the reader to guess
 * which limit the identification keeps to. */
static void ar1_refusal(const run_t *R, const chan_t *ch, double tau_long_s, char *why, size_t n)
{
    const double fit_s = tau_max_samples(R) / R->rate_hz, bump_s = 1.89 * ch->id.fit.gm_tau_s;
    char b1[32], b2[32], b3[32];
    if (ar1_too_short(R, ch)) {
        snprintf(why, n, "the fit's AR(1) of %s has T = %.3g s (%.3g samples), under the floor of %.0f samples "
                         "(%.3g s), the taus where the sensor's own filtering shapes the Allan curve: not a bias the "
                         "profile takes (docs/allan.md)",
                 ch->name, ch->id.fit.gm_tau_s, ch->id.fit.gm_tau_s * R->rate_hz,
                 ar1_floor_samples(), ar1_floor_samples() / R->rate_hz);
    } else if (!ch->id.fit_ok) {
        snprintf(why, n, "the AR(1) bias of %s is not identifiable within the record (no fit within the fitted "
                         "range, tau <= %s s, --max-tau-frac)",
                 ch->name, fmt_s(b1, sizeof b1, fit_s));
    } else if (bump_s > tau_long_s) {
        snprintf(why, n, "the AR(1) bias of %s is not identifiable within the record (the fit's bump, 1.89 T = "
                         "%s s, lies beyond the longest tau with data, %s s; the fit itself uses tau <= %s s, "
                         "--max-tau-frac)",
                 ch->name, fmt_s(b1, sizeof b1, bump_s), fmt_s(b2, sizeof b2, tau_long_s),
                 fmt_s(b3, sizeof b3, fit_s));
    } else if (bump_s * R->rate_hz < 1.0) {
        snprintf(why, n, "the AR(1) bias of %s is not identifiable within the record (the fit's T, %.3g s, is "
                         "under a sample)",
                 ch->name, ch->id.fit.gm_tau_s);
    } else {
        snprintf(why, n, "the AR(1) bias of %s is not identifiable within the record (the fit's AR(1) part, or "
                         "its white part, rises above the rest of the model by no more than the measurement's "
                         "spread at every tau <= %s s, the fitted range of --max-tau-frac)",
                 ch->name, fmt_s(b1, sizeof b1, fit_s));
    }
}

static int write_profile(const run_t *R, const char *path, const char *name)
{
    fnav_profile_t p;
    char err[HX_ERR_SIZE], comment[1024], extra[2048];
    size_t len = 0;
    int i, have_q = 0, have_k = 0, nfallback = 0, bound;
    double tau_long_s;
    double q[6], kk[6], pv[6], pt[6], ps[6], rms[6], fallback[6];
    memset(&p, 0, sizeof p);
    (void)hx_line_str(p.name, sizeof p.name, name); /* cut at a character's start, not inside a UTF-8 letter */
    p.rate_hz = (fnav_real_t)R->rate_hz;
    for (i = 0; i < 6; i++) {
        const chan_t *ch = &R->ch[i];
        const double si = 1.0 / ch->scale; /* display -> SI */
        const int k = ch->src;
        hx_noise_model_t m;
        if (ch->constant) {
            hx_error(CMD, "%s: %s is constant over the whole record (Allan deviation 0): no noise to identify; "
                          "profile not written",
                     path, ch->name);
            return -2;
        }
        if (!ch->id_ok || (!ch->id.fit_ok && !ch->id.paper_ok)) {
            no_identification(R, path, ch);
            return -2;
        }
        tau_long_s = tau_long_of(R, ch);
        bound = profile_model(R, ch, &m);
        if (bound < 0) {
            no_identification(R, path, ch);
            return -2;
        }
        fallback[k] = bound;
        if (bound) {
            char fitw[48] = "no fit", why[400], tb[32], mb[32];
            nfallback++;
            if (ch->id.fit_ok) {
                snprintf(fitw, sizeof fitw, "not the fit's %.3g", ch->id.fit.white);
            }
            ar1_refusal(R, ch, tau_long_s, why, sizeof why);
            /* which way it bounds: "bound T = 173 s" on a channel whose T is
             * 720 s would read as an upper bound; it is the AR(1) whose bump
             * sits on the minimum, no bound on sigma */
            if (bound_at_floor(R, ch)) {
                /* t_BS / 1.89 under the floor: the raised T is stated, not
                 * T = 0.24 s for a fit refused for its T under 0.53 s */
                char t0[32], bb[32];
                hx_warn(CMD, "%s: %s; the profile holds the white noise %.3g %s/sqrt(Hz) (the ADEV at 1 s; %s) and the "
                             "Gauss-Markov bound T = %s s (raised to the floor of %.0f samples from t_BS / 1.89 = %s "
                             "s: a shorter T is not told from the sensor's filtering), sigma = %.3g %s, whose Allan "
                             "bump at %s s has the height of the minimum at %s s (the true T may be longer; no upper "
                             "bound on the bias, docs/allan.md)",
                        path, why, m.white, ch->unit, fitw, fmt_s(tb, sizeof tb, m.gm_tau_s), ar1_floor_samples(),
                        fmt_s(t0, sizeof t0, (double)ch->id.paper.t_bs_s / 1.89), m.gm_sigma, ch->unit,
                        fmt_s(bb, sizeof bb, 1.89 * m.gm_tau_s), fmt_s(mb, sizeof mb, (double)ch->id.paper.t_bs_s));
            } else {
                hx_warn(CMD, "%s: %s; the profile holds the white noise %.3g %s/sqrt(Hz) (the ADEV at 1 s; %s) and the "
                             "Gauss-Markov bound T = %s s, sigma = %.3g %s, whose Allan bump sits on the minimum at "
                             "%s s (T from the minimum's position: the true T may be longer; no upper bound on the "
                             "bias, docs/allan.md)",
                        path, why, m.white, ch->unit, fitw, fmt_s(tb, sizeof tb, m.gm_tau_s), m.gm_sigma, ch->unit,
                        fmt_s(mb, sizeof mb, (double)ch->id.paper.t_bs_s));
            }
        }
        if (k < 3) {
            p.accel_noise_mps2_rthz[k] = (fnav_real_t)(m.white * si);
            p.accel_tau_s[k] = (fnav_real_t)m.gm_tau_s;
            p.accel_bias_sigma_mps2[k] = (fnav_real_t)(m.gm_sigma * si);
        } else {
            p.gyro_noise_rps_rthz[k - 3] = (fnav_real_t)(m.white * si);
            p.gyro_tau_s[k - 3] = (fnav_real_t)m.gm_tau_s;
            p.gyro_bias_sigma_rps[k - 3] = (fnav_real_t)(m.gm_sigma * si);
        }
        q[k] = m.quant * si;
        kk[k] = m.rrw * si;
        have_q |= m.quant > 0.0;
        have_k |= m.rrw > 0.0;
        pv[k] = ch->id.paper_ok ? (double)ch->id.paper.sigma_v * si : (double)NAN;
        pt[k] = ch->id.paper_ok ? (double)ch->id.paper.tau_samples / R->rate_hz : (double)NAN;
        ps[k] = ch->id.paper_ok ? (double)ch->id.paper.sigma_bias * si : (double)NAN;
        rms[k] = fallback[k] ? (double)NAN : ch->id.fit_quality.rms_log10;
    }
    if (fnav_profile_validate(&p) != FNAV_OK) {
        hx_error(CMD, "%s: identified parameters not all positive and finite; profile not written", path);
        return -2;
    }
    snprintf(comment, sizeof comment,
             "identified by `harness allan` from %s (%lu samples at %g Hz)\n"
             "method: weighted least-squares fit of the white + AR(1) Allan variance (docs/allan.md);\n"
             "the paper's own identification (eqs. 5-6) is kept below as paper_* keys for reference",
             R->source, (unsigned long)R->n, R->rate_hz);
#define ADD3(key, v, o)                                                                                   \
    len += (size_t)snprintf(extra + len, sizeof extra - len, "%s = %.6g %.6g %.6g\n", key, (v)[(o) + 0], \
                            (v)[(o) + 1], (v)[(o) + 2])
    len += (size_t)snprintf(extra + len, sizeof extra - len, "ident_method = allan-lsq-white-ar1%s\n",
                            (have_q || have_k) ? "-quant-rrw" : "");
    len += (size_t)snprintf(extra + len, sizeof extra - len, "ident_samples = %lu\n", (unsigned long)R->n);
    if (have_q) {
        ADD3("accel_quant_mps", q, 0);
        ADD3("gyro_quant_rad", q, 3);
    }
    if (have_k) {
        ADD3("accel_rrw_mps2_rts", kk, 0);
        ADD3("gyro_rrw_rps_rts", kk, 3);
    }
    if (nfallback > 0 && R->rate_hz > tau_max_samples(R) * (1.0 + 1e-9)) {
        /* the bound's white noise, the ADEV at 1 s, lies beyond the tenth
         * of the record the identification keeps to: a 5 s log writes a
         * profile from an Allan point of EDF 4, which would otherwise go
         * without a word, exit 0 */
        hx_warn(CMD, "%s: the white noise of %d channel%s (the bound's, above) is the ADEV at 1 s, beyond the longest "
                     "tau the identification keeps to, %.3g s (--max-tau-frac of the %.3g-s record): it rests on a "
                     "few averages; record %.3g s or more, far longer for the bias (docs/workflow.md)",
                path, nfallback, nfallback == 1 ? "" : "s", tau_max_samples(R) / R->rate_hz,
                (double)R->n / R->rate_hz, 1.0 / R->tau_max_frac);
    }
    if (nfallback > 0) {
        /* 1 where the AR(1) part is the Allan-minimum bound, not a fit */
        ADD3("ident_bound_accel", fallback, 0);
        ADD3("ident_bound_gyro", fallback, 3);
    }
    ADD3("allan_fit_rms_log10_accel", rms, 0);
    ADD3("allan_fit_rms_log10_gyro", rms, 3);
    ADD3("paper_accel_noise_mps2_rthz", pv, 0);
    ADD3("paper_accel_tau_s", pt, 0);
    ADD3("paper_accel_bias_sigma_mps2", ps, 0);
    ADD3("paper_gyro_noise_rps_rthz", pv, 3);
    ADD3("paper_gyro_tau_s", pt, 3);
    ADD3("paper_gyro_bias_sigma_rps", ps, 3);
#undef ADD3
    if (hx_profile_write_extra(path, &p, comment, extra, err, sizeof err) != 0) {
        hx_error(CMD, "%s", err);
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------ paper tables */

/* The paper's Tables IV-VI read back through eqs. (4)-(6): the bias
 * stability each row implies (BS = sigma_bias sqrt(tau), eq. 6), and where
 * the model's Allan deviation puts it (docs/allan.md). */
static int paper_tables(void)
{
    static const char *const names[3] = { "NavChip (IV)", "MTx (V)", "Shimmer (VI)" };
    static const char *const rows[6] = { "Acc x", "Acc y", "Acc z", "Gyr x", "Gyr y", "Gyr z" };
    const double fs = 200.0;
    int t, k;
    printf("The paper's Tables IV-VI (200 Hz) read through its own equations. BS = sigma_bias sqrt(tau) (eq. 6\n"
           "inverted) is the measured bias stability each row encodes, at t_BS = tau / f_s (eq. 5).\n"
           "  white@t_BS  ADEV of the white part alone at t_BS, sigma_v / sqrt(t_BS)\n"
           "  model/BS    ADEV of the paper's model (white + AR(1) with stationary std sigma_bias, eq. 4) at t_BS\n"
           "  peak/BS     ADEV peak of that AR(1) (%.4f sigma_bias at %.2f t_BS) over BS = %.4f / sqrt(tau)\n"
           "  drive/BS    the same peak if sigma_bias were the std of the driving noise n_k\n"
           "  (if sigma_v were drawn as the per-sample std, the white ADEV at 1 s would be sigma_v / sqrt(200) =\n"
           "   %.4f sigma_v instead of sigma_v)\n\n",
           HX_GM_PEAK_RATIO, HX_GM_PEAK_TAU, HX_GM_PEAK_RATIO, 1.0 / sqrt(fs));
    printf("%-13s %-6s %9s %7s %10s %10s %7s %10s %8s %8s %8s\n", "table", "row", "sigma_v", "tau", "sigma_bias", "BS",
           "t_BS_s", "white@tBS", "model/BS", "peak/BS", "drive/BS");
    for (t = 0; t < FNAV_PROFILE_COUNT; t++) {
        const fnav_profile_paper_row_t *row = fnav_profile_paper_table((fnav_profile_id_t)t);
        for (k = 0; k < 6; k++) {
            const double tau = row[k].tau_samples, sb = row[k].sigma_bias, sv = row[k].noise;
            const double bs = sb * sqrt(tau), tbs = tau / fs;
            fnav_allan_paper_id_t id;
            hx_noise_model_t m4, md;
            double model_at;
            memset(&id, 0, sizeof id);
            id.sigma_v = (fnav_real_t)sv;
            id.sigma_bias = (fnav_real_t)sb;
            id.tau_samples = (fnav_real_t)tau;
            hx_noise_model_paper_reading(&id, fs, HX_PAPER_EQ4, &m4);
            hx_noise_model_paper_reading(&id, fs, HX_PAPER_DRIVE, &md);
            model_at = sqrt(hx_noise_model_avar(&m4, fs, tau));
            printf("%-13s %-6s %9.2g %7.0f %10.2g %10.3g %7.1f %10.3g %8.3f %8.4f %8.3f\n", k == 0 ? names[t] : "",
                   rows[k], sv, tau, sb, bs, tbs, sv / sqrt(tbs), model_at / bs, HX_GM_PEAK_RATIO * sb / bs,
                   HX_GM_PEAK_RATIO * md.gm_sigma / bs);
        }
    }
    return HX_EXIT_OK;
}

/* ------------------------------------------------------------ main */

/* The exit status after one more failure: an output that could not be
 * written (HX_EXIT_IO) decides over bad input or a refused profile
 * (HX_EXIT_DATA), which says that every output was written; the outputs
 * after a failure are still written (docs/allan.md, "Command"), so the
 * status does not depend on which failure came last. */
static int worse_exit(int exit_code, int failure)
{
    if (exit_code == HX_EXIT_IO || (exit_code == HX_EXIT_DATA && failure != HX_EXIT_IO)) {
        return exit_code;
    }
    return failure;
}

int hx_cmd_allan(int argc, char **argv)
{
    hx_args_t a;
    run_t *R;
    int rc, i, exit_code = HX_EXIT_OK, input_rc, npaper = 0;
    double rate_opt = 0.0, seed_d = 1.0, nsim_d = 0.0, refits_d = 0.0;
    long per_octave = 4, column = 0;
    const char *series, *path, *s_est;
    char name[FNAV_PROFILE_NAME_MAX];

    rc = hx_args_parse(&k_spec, argc, argv, &a);
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--plot", "--profile", NULL };
        if (hx_refuse_dash(CMD, &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_check_input_opts(CMD, &a) != 0) {
        return HX_EXIT_USAGE;
    }
    series = hx_arg(&a, "--series");
    if (hx_flag(&a, "--paper-tables")) {
        int k;
        if (series != NULL || a.npos > 0) {
            hx_error(CMD, "--paper-tables takes no input");
            return HX_EXIT_USAGE;
        }
        /* it prints one table to standard output and reads no option: an
         * option given with it (--json FILE, --out FILE) is refused, not
         * ignored with exit 0 and no file written */
        for (k = 0; k_opts[k].name != NULL; k++) {
            if (a.count[k] > 0 && strcmp(k_opts[k].name, "--paper-tables") != 0) {
                hx_error(CMD, "--paper-tables prints its table to standard output and takes no other option (%s)",
                         k_opts[k].name);
                return HX_EXIT_USAGE;
            }
        }
        return paper_tables();
    }
    if ((series == NULL) == (a.npos == 0)) {
        hx_error(CMD, series == NULL ? "give a LOG or --series FILE" : "give either a LOG or --series, not both");
        hx_usage(&k_spec, stderr);
        return HX_EXIT_USAGE;
    }
    {
        static const char *const outs[] = { "--out", "--json", "--plot", "--profile", NULL };
        static const char *const files[] = { "--out", "--json", "--profile", NULL }, *const pngs[] = { "--plot", NULL };
        if (hx_output_is_input(CMD, series != NULL ? series : a.pos[0], &a, outs)) {
            return HX_EXIT_USAGE;
        }
        /* written after the whole record: checked now, not found
         * unwritable at the end, after minutes on a long log */
        if (hx_check_outputs(CMD, &a, files, pngs) != 0) {
            return HX_EXIT_IO;
        }
    }
    if (hx_arg(&a, "--name") != NULL && !name_printable(hx_arg(&a, "--name"))) {
        /* the profile's "name = ..." line: a line break in it wrote keys of
         * its own (a second rate_hz), and the profile could not be read */
        hx_error(CMD, "--name must be printable text on one line (no control characters; UTF-8)");
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--unit") != NULL &&
        (!name_printable(hx_arg(&a, "--unit")) || strpbrk(hx_arg(&a, "--unit"), ",\"") != NULL)) {
        /* a field of every row of the --out CSV: a comma would split it
         * (rows one column wider than the header) */
        hx_error(CMD, "--unit must be printable text on one line without a comma or a double quote (it is a field "
                      "of the --out CSV)");
        return HX_EXIT_USAGE;
    }
    {
        /* one message for every value but 1, 2 and 4: the range check's
         * "not a whole number in [1, 4]" for 5 or 0 implied that 3 was
         * taken, and 3 then got this message */
        const char *po = hx_arg(&a, "--per-octave");
        double pv = 0.0;
        if (po != NULL && (hx_parse_number(po, &pv) != 0 || !(pv == 1.0 || pv == 2.0 || pv == 4.0))) {
            hx_error(CMD, "--per-octave must be 1, 2 or 4, not '%s'", po);
            return HX_EXIT_USAGE;
        }
    }
    R = (run_t *)calloc(1, sizeof *R);
    if (R == NULL) {
        hx_error(CMD, "out of memory");
        return HX_EXIT_IO;
    }
    R->tau_max_frac = 0.1;
    R->max_work = 2e8;
    R->conf = 0.682689492137086; /* one sigma, erf(1 / sqrt(2)): Stable32's "0.683" (docs/allan.md) */
    if (hx_arg_double(&a, "--rate", 1e-9, 1e9, &rate_opt) != 0 || hx_arg_long(&a, "--per-octave", 1, 4, &per_octave) != 0 ||
        hx_arg_double(&a, "--max-tau-frac", 1e-6, 0.5, &R->tau_max_frac) != 0 ||
        hx_arg_whole(&a, "--seed", 0.0, 4294967295.0, &seed_d) != 0 ||
        hx_arg_whole(&a, "--sim-samples", 16.0, 4294967295.0, &nsim_d) != 0 ||
        hx_arg_whole(&a, "--refits", 0.0, 999999.0, &refits_d) != 0 ||
        hx_arg_double(&a, "--conf", 0.01, 0.999, &R->conf) != 0 ||
        hx_arg_double(&a, "--max-work", 1.0, 1e18, &R->max_work) != 0 || hx_arg_long(&a, "--column", 1, 1000, &column) != 0) {
        free(R);
        return HX_EXIT_USAGE;
    }
    if (refits_d == 1.0) {
        /* one refit has no spread: refused, not printed as an interval of width 0 */
        hx_error(CMD, "--refits must be 0 (off) or at least 2, not '%s' (the interval is the spread of the refits)",
                 hx_arg(&a, "--refits"));
        free(R);
        return HX_EXIT_USAGE;
    }
    R->refits = (long)refits_d;
    if (series != NULL && hx_arg(&a, "--profile") != NULL) {
        hx_error(CMD, "--profile needs a six-channel log, not a --series");
        free(R);
        return HX_EXIT_USAGE;
    }
    if (series != NULL && !(rate_opt > 0.0)) {
        hx_error(CMD, "--series needs --rate HZ");
        free(R);
        return HX_EXIT_USAGE;
    }
    if (series == NULL && (hx_flag(&a, "--phase") || hx_arg(&a, "--column") != NULL)) {
        /* named as given, as --unit with a log and the log's options with
         * a series are (it named both for either) */
        if (hx_flag(&a, "--phase")) {
            hx_error(CMD, "--phase applies to --series only (a log holds rates and specific forces, not a phase)");
        } else {
            hx_error(CMD, "--column applies to --series only (a log's columns are named with --columns MAP)");
        }
        free(R);
        return HX_EXIT_USAGE;
    }
    if (series != NULL) {
        /* the log's options are refused with a series, not ignored without
         * a word, exit 0 (`--series F --channels gx`), as --unit with a log
         * is */
        static const char *const log_only[] = { "--channels", "--from", "--input-rate", "--columns", "--units", "--name", NULL };
        int k;
        for (k = 0; log_only[k] != NULL; k++) {
            if (hx_arg(&a, log_only[k]) != NULL) {
                hx_error(CMD, "%s applies to a log, not a --series (%s)", log_only[k],
                         strcmp(log_only[k], "--name") == 0 ? "it names a profile, which a series does not give"
                                                             : "one column of numbers at --rate HZ");
                free(R);
                return HX_EXIT_USAGE;
            }
        }
    }
    if (series == NULL && hx_arg(&a, "--unit") != NULL) {
        /* a log's channels are in m/s^2 and deg/s: the unit is refused, not
         * ignored without a word, exit 0 */
        hx_error(CMD, "--unit applies to --series only (a log's channels are in m/s^2 and deg/s)");
        free(R);
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--fractional") != NULL &&
        (series == NULL || hx_flag(&a, "--phase") || hx_arg_double(&a, "--fractional", 1e-300, 1e300, &R->f0) != 0)) {
        if (series == NULL || hx_flag(&a, "--phase")) {
            hx_error(CMD, "--fractional applies to a --series of frequencies (not a log, not --phase)");
        }
        free(R);
        return HX_EXIT_USAGE;
    }
    R->exact = series != NULL;
    if ((s_est = hx_arg(&a, "--estimator")) != NULL) {
        if (strcmp(s_est, "exact") != 0 && strcmp(s_est, "streaming") != 0) {
            hx_error(CMD, "--estimator must be exact or streaming, not '%s'", s_est);
            free(R);
            return HX_EXIT_USAGE;
        }
        R->exact = strcmp(s_est, "exact") == 0;
    }
    if (hx_arg(&a, "--deviation") != NULL && parse_deviations(R, hx_arg(&a, "--deviation")) != 0) {
        free(R);
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--m") != NULL && !R->exact) {
        hx_error(CMD, "--m needs --estimator exact (the streaming estimator has its own grid)");
        free(R);
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--m") != NULL && hx_arg(&a, "--per-octave") != NULL) {
        /* --per-octave spaces the log grid that --m replaces: refused, not
         * ignored without a word, exit 0 */
        hx_error(CMD, "--per-octave spaces the log-spaced grid, which --m replaces: give one of them");
        free(R);
        return HX_EXIT_USAGE;
    }
    R->m_given = hx_arg(&a, "--m") != NULL;
    if (setup_grid(R, per_octave, hx_arg(&a, "--m")) != 0) {
        free(R);
        return HX_EXIT_USAGE;
    }
    if (series != NULL) {
        R->nch = 1;
        R->ch[0].src = -1;
        R->ch[0].name = "series";
        R->ch[0].label = "series";
        R->ch[0].unit = hx_arg(&a, "--unit") != NULL ? hx_arg(&a, "--unit") : "u";
        R->ch[0].scale = 1.0;
        R->is_series = 1;
        R->rate_hz = rate_opt;
        path = series;
        snprintf(R->sensor, sizeof R->sensor, "series");
        snprintf(R->sensor_text, sizeof R->sensor_text, "series");
    } else {
        path = a.pos[0];
        if (parse_channels(R, hx_arg(&a, "--channels")) != 0) {
            free(R);
            return HX_EXIT_USAGE;
        }
        if (hx_arg(&a, "--profile") != NULL && R->nch != 6) {
            hx_error(CMD, "--profile needs all six channels");
            free(R);
            return HX_EXIT_USAGE;
        }
    }
    R->source = path;
    for (i = 0; i < R->nch; i++) {
        if (alloc_channel(R, &R->ch[i]) != 0) {
            hx_error(CMD, "out of memory");
            free_run(R);
            free(R);
            return HX_EXIT_IO;
        }
    }
    input_rc = series != NULL ? read_series(R, path, hx_flag(&a, "--phase"), column)
                              : read_log(R, &a, path, rate_opt);
    if (input_rc < 0) {
        free_run(R);
        free(R);
        return HX_EXIT_DATA;
    }
    if (R->n < 2u || (double)R->n < samples_needed(R)) {
        /* no tau in range: every table would be empty and every value n/a,
         * exit 0 (2 samples). After a reader's error the samples are those
         * before it, and said so: "bad.txt: 2 samples are too few" under
         * "bad.txt:3: not a number" read as the file's length */
        hx_error(CMD, "%s: %s%lu %s%s%s too few for any Allan point: the shortest tau (%lu sample%s) needs at "
                      "least %.0f samples (tau up to %g of the record, --max-tau-frac)",
                 path, input_rc > 0 ? "the " : "", (unsigned long)R->n, R->n == 1u ? "sample" : "samples",
                 input_rc > 0 ? " before the error" : "", R->n == 1u ? " is" : " are", (unsigned long)R->grid[0],
                 R->grid[0] == 1u ? "" : "s",
                 samples_needed(R), R->tau_max_frac);
        free_run(R);
        free(R);
        return HX_EXIT_DATA;
    }
    if (R->m_given) {
        m_dropped(R);
    }
    if (input_rc > 0) {
        /* said at the end, FILE: incomplete input (below) */
        exit_code = worse_exit(exit_code, HX_EXIT_DATA);
    }

    if (hx_arg(&a, "--m") == NULL && R->ngrid > 0u && tau_max_samples(R) > (double)R->grid[R->ngrid - 1u] * 1.01) {
        /* a long fast log (12 h at 1 kHz: 10 % is 4,320 s) outgrows the core's
         * grid (2^20 samples, 1,049 s at 1 kHz): say where the curve ends, and
         * the option that moves it (FNAV_ALLAN_TAU_MAX, which it named, is
         * derived from FNAV_ALLAN_MAX_LEVELS, not set) */
        hx_warn(CMD, "%s: %g %% of the record is %.4g s, beyond the longest tau of the grid (%lu samples = %.4g s; "
                     "FNAV_ALLAN_MAX_LEVELS in fnav_config.h raises it): longer tau are not computed, and an AR(1) "
                     "bias whose bump lies beyond is not identified",
                path, 100.0 * R->tau_max_frac, tau_max_samples(R) / R->rate_hz, (unsigned long)R->grid[R->ngrid - 1u],
                (double)R->grid[R->ngrid - 1u] / R->rate_hz);
    }
    if (R->moving) {
        hx_csv_layout_t lay, lay_t;
        char give[64], dps[128] = "";
        const hx_csv_layout_t *csv = hx_units_layout(R->in_fmt, &lay);
        if (csv == NULL || csv->gyr_scale == 1.0) {
            /* a gyro read as deg/s already (--units gyro=) is not told to
             * multiply by pi/180 again (a walk in rad/s read so is named by
             * the units check instead) */
            snprintf(dps, sizeof dps, " (a gyro in deg/s at rest also reads so: %s)",
                     hx_units_fix_dps(hx_time_unit_layout(R->time_unit_warned ? R->rate_hz : 0.0, csv, &lay_t),
                                      give, sizeof give));
        }
        hx_error(CMD,
                 "%s: the log moves: in %ld of its %ld one-second windows the rate spreads by more than %g rad/s "
                 "RMS or |f| by more than %g m/s^2 (the first at %.0f s): not a static log (a walk?); the Allan "
                 "variance and its bias model describe a sensor at rest%s (docs/allan.md, \"Command\")",
                 path, R->win_moving, R->win_n, HX_ALLAN_MOVING_GYRO_RPS, HX_ALLAN_MOVING_F_MPS2,
                 R->win_first_moving_s, dps);
        exit_code = worse_exit(exit_code, HX_EXIT_DATA);
    } else if (R->win_moving > 0) {
        motion_report(R, path, hx_arg(&a, "--profile") != NULL);
    }
    if (!R->moving) {
        disturbed_check(R, path);
    }
    if (R->units_bad) {
        hx_error(CMD, "%s: %s", path, R->units_msg);
        exit_code = worse_exit(exit_code, HX_EXIT_DATA);
    }
    {
        /* Ctrl-C or SIGTERM after the record is read: the slow stages (the
         * deviation tables, the Fig. 7 simulation) stop, and what is done
         * is printed and written, marked incomplete, exit 128 + the signal
         * (as simgap-validate) */
        hx_stop_on_signals(CMD, "the slow stages: what is done is printed and written");
    }
    {
        hx_progress_t dpr;
        if (R->ndev > 0) {
            /* the total forms on a long record take minutes: their progress
             * (the reading's went on to "done" and then nothing was said) */
            int j;
            size_t g;
            R->dev_total = 0.0;
            for (i = 0; i < R->nch; i++) {
                for (j = 0; j < R->ndev; j++) {
                    for (g = 0; g < R->ngrid; g++) {
                        if (!((double)hx_dev_work(R->dev[j], R->ch[i].nx, R->grid[g]) > R->max_work)) {
                            R->dev_total += dev_cost(R->dev[j], R->ch[i].nx, R->grid[g]);
                        }
                    }
                }
            }
            if (R->dev_total > 0.0) {
                hx_progress_start(&dpr, "allan: deviations", 1.0);
                R->dev_pr = &dpr;
            }
        }
        for (i = 0; i < R->nch; i++) {
            analyse_channel(R, &R->ch[i], hx_flag(&a, "--fit-extra"));
            if (R->ch[i].underflow) {
                exit_code = worse_exit(exit_code, HX_EXIT_DATA);
            }
            npaper += R->ch[i].id_ok && R->ch[i].id.paper_ok;
        }
        if (R->dev_pr != NULL) {
            if (!hx_stop_sig) {
                hx_progress_end(&dpr); /* "done": not said of a stage cut short (the warning below ends the line) */
            }
            R->dev_pr = NULL;
        }
        if (hx_stop_sig && R->ndev > 0) {
            /* said of the stages the run has (no deviation tables or no
             * simulation check named that was not asked for) */
            snprintf(R->interrupted, sizeof R->interrupted, "interrupted by %s in the deviation tables: those from "
                                                            "there on not computed%s%s",
                     hx_stop_sig == SIGTERM ? "SIGTERM" : "SIGINT",
                     hx_flag(&a, "--no-sim") ? "" : ", the simulation check not run",
                     R->refits > 0 ? ", the refits not run" : "");
        } else if (hx_stop_sig && !hx_flag(&a, "--no-sim")) {
            snprintf(R->interrupted, sizeof R->interrupted, "interrupted by %s before the simulation check: not "
                                                            "run%s (the tables and the identification are complete)",
                     hx_stop_sig == SIGTERM ? "SIGTERM" : "SIGINT", R->refits > 0 ? ", nor the refits" : "");
        } else if (hx_stop_sig && R->refits > 0) {
            snprintf(R->interrupted, sizeof R->interrupted, "interrupted by %s before the refits: not run (the "
                                                            "tables and the identification are complete)",
                     hx_stop_sig == SIGTERM ? "SIGTERM" : "SIGINT");
        }
    }
    if (npaper > 0 && R->rate_hz > tau_max_samples(R) * (1.0 + 1e-9)) {
        /* the paper's sigma_v, the ADEV at 1 s, lies beyond the tenth of the
         * record the identification keeps to: said for the paper's column of
         * a 5 s log as for the profile's bound (write_profile()), in words
         * a user knows (until 2026-12-07 "the paper's sigma_v of 6 channels
         * (its column of the parameter table: the ADEV at 1 s)") */
        hx_warn(CMD, "%s: the white-noise density sigma_v of %d channel%s (the bias model's \"paper III.C as "
                     "written\" columns, which take it as the Allan deviation at tau = 1 s) is read beyond the "
                     "longest tau the identification keeps to, %.3g s (--max-tau-frac of the %.3g-s record): it "
                     "rests on a few averages; record %.3g s or more (docs/allan.md, \"Command\")",
                R->source, npaper, npaper == 1 ? "" : "s", tau_max_samples(R) / R->rate_hz,
                (double)R->n / R->rate_hz, 1.0 / R->tau_max_frac);
    }
    if (hx_stop_sig) {
        /* interrupted above: no simulation */
    } else if (!hx_flag(&a, "--no-sim") && !grid_streamable(R)) {
        hx_warn(CMD, "simulation check skipped: it runs the streaming estimator, which cannot track every --m");
    } else if (!hx_flag(&a, "--no-sim")) {
        const uint32_t nsim = nsim_d > 0.0 ? (uint32_t)nsim_d : R->n;
        hx_progress_t pr;
        R->nsim = nsim;
        double done = 0.0, total = 2.0 * (double)nsim * (double)R->nch;
        hx_progress_start(&pr, "allan: simulating (Fig. 7 check)", 1.0);
        for (i = 0; i < R->nch; i++) {
            chan_t *ch = &R->ch[i];
            const unsigned long seed = (unsigned long)seed_d + 1000ul * (unsigned long)i;
            int src = 0, srf = 0;
            if (ch->id_ok && ch->id.paper_ok) {
                src = simulate(R, ch, &ch->id.paper_model, nsim, seed, ch->sim_paper, &pr, &done, total);
                ch->have_sim_paper = src == 0;
            }
            if (ch->id_ok && ch->id.fit_ok) {
                srf = simulate(R, ch, &ch->id.fit, nsim, seed + 1u, ch->sim_fit, &pr, &done, total);
                ch->have_sim_fit = srf == 0;
            }
            if (src == -3 || srf == -3 || hx_stop_sig) {
                ch->have_sim_paper = ch->have_sim_fit = 0;
                snprintf(R->interrupted, sizeof R->interrupted,
                         "interrupted by %s in the simulation check: no simulated curve%s (the tables and the "
                         "identification are complete)",
                         hx_stop_sig == SIGTERM ? "SIGTERM" : "SIGINT", R->refits > 0 ? ", the refits not run" : "");
                for (; i < R->nch; i++) {
                    R->ch[i].have_sim_paper = R->ch[i].have_sim_fit = 0;
                }
                break;
            }
            if (src == -2 || srf == -2) {
                /* a series beyond the core's range, which the exact estimator reads: no curve, said */
                hx_warn(CMD, "%s: %s: simulation check skipped: the model's samples are beyond the streaming "
                             "estimator's input range (%g) it runs through",
                        R->source, ch->name, FNAV_INPUT_MAX_ABS);
            }
        }
        if (!hx_stop_sig) {
            hx_progress_end(&pr);
        }
    }
    if (R->refits > 0 && !hx_stop_sig) {
        /* --refits: the parametric bootstrap of each corrected fit whose
         * AR(1) part is identified (refit_channel()), at --sim-samples or
         * the record's length */
        hx_progress_t pr;
        double done = 0.0, total = 0.0;
        R->nrefit = nsim_d > 0.0 ? (uint32_t)nsim_d : R->n;
        for (i = 0; i < R->nch; i++) {
            total += refit_eligible(R, &R->ch[i]) ? (double)R->refits * (double)R->nrefit : 0.0;
        }
        if (total > 0.0) {
            hx_progress_start(&pr, "allan: refits (parametric bootstrap)", 1.0);
        }
        for (i = 0; i < R->nch && total > 0.0; i++) {
            const int rf = refit_eligible(R, &R->ch[i]) ? refit_channel(R, &R->ch[i], i, (unsigned long)seed_d,
                                                                        hx_flag(&a, "--fit-extra"), &pr, &done, total)
                                                        : 0;
            if (rf == -1) {
                exit_code = worse_exit(exit_code, HX_EXIT_DATA); /* said; the other channels go on */
            }
            if (rf == -3) {
                int j;
                for (j = 0; j < R->nch; j++) {
                    R->ch[j].refitted = 0;
                }
                snprintf(R->interrupted, sizeof R->interrupted,
                         "interrupted by %s in the refits: no interval (the tables%s the identification%s are "
                         "complete)",
                         hx_stop_sig == SIGTERM ? "SIGTERM" : "SIGINT", hx_flag(&a, "--no-sim") ? " and" : ",",
                         hx_flag(&a, "--no-sim") ? "" : " and the simulation check");
                break;
            }
        }
        if (total > 0.0 && !hx_stop_sig) {
            hx_progress_end(&pr);
        }
    }

    /* nothing left to stop: a signal from here on ends the command (it gave
     * exit 143 with a JSON saying complete) */
    hx_stop_off();
    if (R->interrupted[0] != '\0') {
        hx_warn(CMD, "%s; what is done is printed and written (JSON complete false)", R->interrupted);
        exit_code = 128 + (int)hx_stop_sig; /* as the shell reports a command a signal ended */
    } else if (hx_stop_sig) {
        hx_warn(CMD, "%s came after the slow stages: the results are complete",
                hx_stop_sig == SIGTERM ? "SIGTERM" : "SIGINT");
    }
    if (!hx_flag(&a, "--quiet")) {
        char shown[4096]; /* a file name's control characters as '?' (hx_line_str), as in the messages */
        printf("harness allan: %s (%s), %lu samples at %g Hz, %d tau points, ",
               hx_line_str(shown, sizeof shown, R->source), R->sensor_text,
               (unsigned long)R->n, R->rate_hz, (int)R->ngrid);
        if (R->exact) {
            printf("exact estimator (the whole record in double, fully overlapping at every tau)\n");
        } else {
            printf("streaming estimator, %lu bytes per channel\n",
                   (unsigned long)(sizeof(fnav_allan_t) * (size_t)R->nchunk));
        }
        for (i = 0; i < R->nch; i++) {
            print_table(R, &R->ch[i]);
        }
    }
    print_params(R);

    if (hx_arg(&a, "--out") != NULL && write_csv(R, hx_arg(&a, "--out")) != 0) {
        exit_code = worse_exit(exit_code, HX_EXIT_IO);
    }
    if (hx_arg(&a, "--json") != NULL && write_json(R, hx_arg(&a, "--json")) != 0) {
        exit_code = worse_exit(exit_code, HX_EXIT_IO);
    }
    if (hx_arg(&a, "--plot") != NULL && write_plot(R, hx_arg(&a, "--plot")) != 0) {
        exit_code = worse_exit(exit_code, HX_EXIT_IO);
    }
    if (hx_arg(&a, "--profile") != NULL && (R->units_bad || R->moving || R->win_moving > 0)) {
        hx_error(CMD, "%s: the log %s (above); profile not written", hx_arg(&a, "--profile"),
                 R->moving ? "is not static" : R->units_bad ? "is not in SI units" : "moves in places");
        exit_code = worse_exit(exit_code, HX_EXIT_DATA);
    } else if (hx_arg(&a, "--profile") != NULL) {
        if (hx_arg(&a, "--name") != NULL) {
            snprintf(name, sizeof name, "%s", hx_arg(&a, "--name"));
        } else {
            base_name(path, name, sizeof name);
        }
        rc = write_profile(R, hx_arg(&a, "--profile"), name);
        if (rc != 0) {
            exit_code = worse_exit(exit_code, rc == -2 ? HX_EXIT_DATA : HX_EXIT_IO);
        }
    }
    if (input_rc > 0) {
        /* the bad line was warned when it was read (input_fail): the log
         * named, not the line again, as info's, psd's and simgap's closing
         * error (it was "warning: FILE: analysing the N samples before the
         * error" under an error printed before the analysis) */
        hx_error(CMD, "%s: incomplete input (warned above): the results cover the %lu sample%s before the error", path,
                 (unsigned long)R->n, R->n == 1u ? "" : "s");
    }
    if (R->interrupted[0] != '\0' && exit_code != HX_EXIT_IO) {
        exit_code = 128 + (int)hx_stop_sig; /* not a data error found after it (the profile's refusal) */
    }
    free_run(R);
    free(R);
    return exit_code;
}
