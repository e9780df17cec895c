/* harness psd: streaming Welch PSD of every channel of a log and the paper's
 * lowest usable sampling frequency (section II.B), with the sensitivity to
 * segment length and DC handling, and the plots of the paper's Figs. 3, 4
 * and 6 (docs/psd.md). */
#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "footnav/fnav_welch.h"
#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_nav.h"

#define CMD "psd"
#define NSENS_NFFT 5
/* Fewer Welch segments than this are warned: each bin then scatters by
 * 1/sqrt(K) of its value at least, over 35 % (100 % for one segment, but
 * 141 % at DC and Nyquist, whose periodogram is chi2 with 1 degree of
 * freedom, not 2). The paper's
 * 64-sample segments give hundreds on any walk; so few come of an --nfft
 * near the log's length. */
#define PSD_FEW_SEGMENTS 8
#define NDC 5

static const hx_opt_t k_opts[] = {
    HX_INPUT_OPTS,
    { "--nfft", "N", "Welch segment length, a power of two (default 64, the paper's)", 0 },
    { "--overlap", "N", "samples shared by consecutive segments (default nfft/2, the paper's 50 %)", 0 },
    { "--window", "NAME", "hamming (default, the paper's), hann or rect", 0 },
    { "--symmetric", NULL, "symmetric window (MATLAB's hamming(N)) instead of the periodic one (scipy's)", 0 },
    { "--dc", "MODE", "DC / gravity handling: segment (default: each segment's mean, scipy's default), "
                      "linear, global (the record's mean), none, exclude (none, and the DC bin left out "
                      "of the total)", 0 },
    { "--threshold", "F", "fraction of the total power the band must hold (default 0.95)", 0 },
    { "--round", "HZ", "round the sampling frequency up to a multiple of this (default 50; 0: not rounded)", 0 },
    { "--sensitivity", NULL, "also tabulate the answer for segments of 64..1024 samples x every DC mode", 0 },
    { "--spec-nfft", "N", "spectrogram segment length (default 256)", 0 },
    { "--spec-axis", "CH", "spectrogram channel: ax..gz (default: the accelerometer axis along gravity)", 0 },
    { "--out", "FILE", "PSD and CCDF of every axis (CSV; '-': standard output, the text then on standard error)", 0 },
    { "--json", "FILE", "settings, per-axis and overall answers, sensitivity (JSON; '-': standard output, the "
                        "text then on standard error; not with --out -)", 0 },
    { "--plot", "DIR", "psd.png (Fig. 3), ccdf.png (Fig. 4), spectrogram.png (Fig. 6), and sensitivity.png with "
                       "--sensitivity", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    CMD, "LOG [options]",
    "Welch power spectral density of the six channels (streaming, as on the sensor:\n"
    "Hamming window of 64 samples, 50 % overlap, one-sided density), the cumulative\n"
    "power and its complement (CCDF), the bandwidth holding 95 % of the power per\n"
    "axis and the lowest usable sampling frequency = 2 x bandwidth rounded up to a\n"
    "multiple of 50 Hz, per axis, per sensor group and overall (paper II.B). How the\n"
    "DC component (gravity, biases) is treated decides the answer: see --dc and\n"
    "--sensitivity, and docs/psd.md for the recommended setting (--dc global).",
    1, 1, k_opts
};

static const char *const k_ch[6] = { "ax", "ay", "az", "gx", "gy", "gz" };
static const char *const k_dc_names[NDC] = { "segment", "linear", "global", "none", "exclude" };
static const uint32_t k_sens_nfft[NSENS_NFFT] = { 64, 128, 256, 512, 1024 };

typedef struct {
    fnav_welch_config_t wc;
    int exclude_dc;
} setting_t;

typedef struct {
    uint32_t nbins;
    double df;
    fnav_real_t psd[6][FNAV_WELCH_MAX_BINS];
    fnav_real_t ccdf[6][FNAV_WELCH_MAX_BINS];
    fnav_bandwidth_t bw[6];
    int ok[6];
    double group_bw[2], group_fs[2], overall_fs;
    uint32_t nseg;
} result_t;

/* What each DC mode removes, for the output's statement of its assumptions;
 * %s is the segment high-pass's corner (about f_s / nfft). */
static void dc_text(int mode, double df, char *buf, size_t n)
{
    switch (mode) {
    case 0:
        snprintf(buf, n, "each segment's mean removed (a high-pass near f_s/nfft = %.3g Hz: gravity, biases and the "
                         "motion below it do not count)", df);
        break;
    case 1:
        snprintf(buf, n, "each segment's least-squares line removed (a high-pass near f_s/nfft = %.3g Hz: gravity, "
                         "biases and the motion below it do not count)", df);
        break;
    case 2:
        snprintf(buf, n, "the record's mean removed (its constant part only: the mean gravity and bias; everything "
                         "that varies counts)");
        break;
    case 3:
        snprintf(buf, n, "nothing removed (gravity and the biases count as power at 0 Hz)");
        break;
    default:
        snprintf(buf, n, "nothing removed, and the 0 Hz bin left out of the total");
        break;
    }
}

/* The band is flagged as reaching the Nyquist frequency when it ends in the
 * top tenth of the log's band: there the power has not fallen off (white
 * noise puts the threshold at threshold x Nyquist, 0.95 of it), so the log
 * cannot show where the band ends. */
#define NYQ_FRAC 0.9

/* The smallest --round step (0 aside, not rounded), Hz. The step goes to
 * the core as fnav_real_t (float): 1e-40 became a subnormal, 1e-50 zero,
 * and 2 x bandwidth / step has whole-number precision in float only below
 * 2^24, which a millihertz keeps up to 16.7 kHz; the answers are printed
 * with the step's decimals (fs_decimals), three at 0.001 Hz. */
#define ROUND_MIN_HZ 0.001

/* Decimals that print a sampling frequency as the rule gives it: those of
 * the rounding step (50 Hz: 0; 2.5 Hz: 1; up to 6), 1 when not rounded.
 * A rounded answer printed to the hertz read 232 Hz for 232.5 Hz with
 * --round 2.5: no multiple of the step, and below the answer. */
static int fs_decimals(const fnav_bandwidth_config_t *bc)
{
    double step = (double)bc->round_hz;
    int d;
    if (!(step > 0.0)) {
        return 1;
    }
    for (d = 0; d < 6; d++) {
        if (fabs(step - nearbyint(step)) <= 1e-6 * step) {
            return d;
        }
        step *= 10.0;
    }
    return 6;
}

static int parse_dc(const char *s, setting_t *st)
{
    int i;
    for (i = 0; i < NDC; i++) {
        if (strcmp(s, k_dc_names[i]) == 0) {
            static const fnav_detrend_t map[NDC] = { FNAV_DETREND_CONSTANT, FNAV_DETREND_LINEAR, FNAV_DETREND_GLOBAL,
                                                     FNAV_DETREND_NONE, FNAV_DETREND_NONE };
            st->wc.detrend = map[i];
            st->exclude_dc = i == 4;
            return i;
        }
    }
    return -1;
}

static double chan(const hx_log_t *log, size_t i, int c)
{
    return c < 3 ? log->acc[i][c] : log->gyr[i][c - 3];
}

/* Run the six channels through streaming Welch estimators. A sample the
 * estimator rejects (not finite, or so large that its power overflows the
 * core's float) stops the analysis: its index and channel go to bad_i /
 * bad_c (else both stay -1). */
static int analyse(const hx_log_t *log, const setting_t *st, const fnav_bandwidth_config_t *bc, result_t *r,
                   long *bad_i, int *bad_c)
{
    static fnav_welch_t w[6];
    size_t i;
    int c, g;
    hx_progress_t pr;
    memset(r, 0, sizeof *r);
    *bad_i = -1;
    *bad_c = -1;
    for (c = 0; c < 6; c++) {
        if (fnav_welch_init(&w[c], &st->wc) != FNAV_OK) {
            return -1;
        }
    }
    /* a transform every nfft - overlap samples: with --overlap nfft - 1 a
     * long log is minutes of work, so it shows progress; silent under a
     * second as every progress line */
    hx_progress_start(&pr, "psd: Welch", (double)log->n);
    for (i = 0; i < log->n; i++) {
        for (c = 0; c < 6; c++) {
            if (fnav_welch_push(&w[c], (fnav_real_t)chan(log, i, c)) != FNAV_OK) {
                *bad_i = (long)i;
                *bad_c = c;
                hx_progress_end(&pr);
                return -1;
            }
        }
        if ((i & 1023u) == 0u) {
            hx_progress_update(&pr, (double)i);
        }
    }
    hx_progress_end(&pr);
    r->nbins = fnav_welch_bins(&w[0]);
    r->df = (double)st->wc.rate_hz / (double)st->wc.nfft;
    r->nseg = fnav_welch_segments(&w[0]);
    for (c = 0; c < 6; c++) {
        fnav_bandwidth_config_t b = *bc;
        b.exclude_dc = st->exclude_dc;
        if (fnav_welch_get(&w[c], r->psd[c], FNAV_WELCH_MAX_BINS) != FNAV_OK) {
            return -1;
        }
        r->ok[c] = fnav_welch_bandwidth(r->psd[c], r->nbins, (fnav_real_t)r->df, &b, &r->bw[c], r->ccdf[c]) ==
                   FNAV_OK;
    }
    /* a group needs the widest band of its axes; the answer is the larger group */
    for (g = 0; g < 2; g++) {
        r->group_bw[g] = 0.0;
        for (c = 3 * g; c < 3 * g + 3; c++) {
            if (r->ok[c] && (double)r->bw[c].bandwidth_hz > r->group_bw[g]) {
                r->group_bw[g] = (double)r->bw[c].bandwidth_hz;
            }
        }
        r->group_fs[g] = bc->round_hz > FNAV_R(0.0)
                             ? ceil(2.0 * r->group_bw[g] / (double)bc->round_hz) * (double)bc->round_hz
                             : 2.0 * r->group_bw[g];
    }
    r->overall_fs = r->group_fs[0] > r->group_fs[1] ? r->group_fs[0] : r->group_fs[1];
    return 0;
}

/* The widest group's band, Hz */
static double widest_band(const result_t *r)
{
    return r->group_bw[0] > r->group_bw[1] ? r->group_bw[0] : r->group_bw[1];
}

/* Whether the answer is only a lower bound: the widest band ends in the top
 * tenth of the log's band (at NYQ_FRAC of the Nyquist frequency or above),
 * where the power has not fallen off and the log cannot show where the band
 * ends (white sensor noise: a static log). The bound is then the answer, or
 * the log's rate where the rounding lifts the answer above it. Not so where
 * the rounding alone lifts it above the rate: the band ends well inside. */
static int fs_lower_bound(const result_t *r, double rate, double *bound_hz)
{
    const int lower = widest_band(r) >= NYQ_FRAC * 0.5 * rate;
    *bound_hz = lower ? (r->overall_fs < rate ? r->overall_fs : rate) : (double)NAN;
    return lower;
}

/* paper_dc: the DC mode is segment, the paper's setting and the default,
 * which docs/psd.md does not recommend: the answer line says so (450 Hz on
 * the 820 Hz walk would read as the answer where --dc global gives 300 Hz).
 * A lower bound (fs_lower_bound()) is said there too, not only in a
 * warning, so the line does not read as a measurement. */
static void print_result(const char *title, const result_t *r, const fnav_bandwidth_config_t *bc, double rate,
                         int paper_dc)
{
    const int rounded = bc->round_hz > FNAV_R(0.0), dec = fs_decimals(bc);
    char lower[256] = "";
    double bound_hz;
    char rnd[64];
    int c, g, none = 0;
    /* --round 0 said "multiples of 0 Hz" */
    if (rounded) {
        snprintf(rnd, sizeof rnd, "multiples of %g Hz", (double)bc->round_hz);
    } else {
        snprintf(rnd, sizeof rnd, "not rounded");
    }
    printf("%s\n", title);
    printf("  %-5s %14s %12s %10s %10s\n", "axis", "total_power", "bandwidth_Hz", "2xBW_Hz", "fs_Hz");
    for (c = 0; c < 6; c++) {
        if (!r->ok[c]) {
            printf("  %-5s %14s\n", k_ch[c], "no power");
            continue;
        }
        printf("  %-5s %14.6g %12.1f %10.1f %10.*f\n", k_ch[c], (double)r->bw[c].total, (double)r->bw[c].bandwidth_hz,
               (double)r->bw[c].fs_hz, dec, (double)r->bw[c].fs_rounded_hz);
    }
    /* a group without power on any axis has no band: it said "bandwidth 0.0 Hz -> 0 Hz" */
    for (g = 0; g < 2; g++) {
        if (!r->ok[3 * g] && !r->ok[3 * g + 1] && !r->ok[3 * g + 2]) {
            printf("  %-15s no power on any axis (left out)\n", g == 0 ? "accelerometers:" : "gyroscopes:");
            none++;
        } else {
            printf("  %-15s bandwidth %.1f Hz -> %.*f Hz\n", g == 0 ? "accelerometers:" : "gyroscopes:",
                   r->group_bw[g], dec, r->group_fs[g]);
        }
    }
    if (none == 2) {
        printf("  lowest usable sampling frequency: none (no channel has power)\n");
        return;
    }
    if (fs_lower_bound(r, rate, &bound_hz)) {
        char of[64] = "";
        if (r->overall_fs > rate * (1.0 + 1e-9)) {
            snprintf(of, sizeof of, " of %.4g Hz, the log's rate", bound_hz);
        }
        snprintf(lower, sizeof lower,
                 ", only a lower bound%s (%g %% of the power reaches %.1f Hz, %.0f %% of the Nyquist frequency: "
                 "the log cannot show where the band ends)",
                 of, 100.0 * (double)bc->threshold, widest_band(r), 100.0 * widest_band(r) / (0.5 * rate));
    }
    /* a tie is said as one: on a static log both groups reach the Nyquist frequency alike */
    printf("  lowest usable sampling frequency: %.*f Hz (%s; %g %% of the power, %s)%s%s\n", dec,
           r->overall_fs,
           r->group_fs[0] > r->group_fs[1]   ? "the accelerometers limit it"
           : r->group_fs[0] < r->group_fs[1] ? "the gyroscopes limit it"
                                             : "accelerometers and gyroscopes alike",
           100.0 * (double)bc->threshold, rnd, lower,
           paper_dc ? " (--dc segment, the paper's setting; --dc global is recommended: docs/psd.md)" : "");
}

/* ------------------------------------------------------------ outputs */

static int write_csv(const char *path, const result_t *r, const char *src)
{
    FILE *f = hx_out_open(path); /* "-": standard output (hx_json_stdout_claim) */
    uint32_t k;
    int c;
    char line[4096];
    if (f == NULL) {
        hx_error(CMD, "%s: cannot create (%s)", path, strerror(errno));
        return -1;
    }
    fprintf(f, "# harness psd: %s; one-sided Welch PSD (accel (m/s^2)^2/Hz, gyro (rad/s)^2/Hz) and CCDF "
               "(1 - cumulative power fraction at the bin's upper edge)\n",
            hx_line_str(line, sizeof line, src));
    fprintf(f, "freq_hz");
    for (c = 0; c < 6; c++) {
        fprintf(f, ",psd_%s", k_ch[c]);
    }
    for (c = 0; c < 6; c++) {
        fprintf(f, ",ccdf_%s", k_ch[c]);
    }
    fprintf(f, "\n");
    for (k = 0; k < r->nbins; k++) {
        fprintf(f, "%.6g", (double)k * r->df);
        for (c = 0; c < 6; c++) {
            fprintf(f, ",%.6g", (double)r->psd[c][k]);
        }
        for (c = 0; c < 6; c++) {
            fprintf(f, ",%.6g", (double)r->ccdf[c][k]);
        }
        fprintf(f, "\n");
    }
    return hx_out_finish(CMD, path, f);
}

static cJSON *json_result(const result_t *r)
{
    cJSON *o = cJSON_CreateObject(), *ax = cJSON_AddObjectToObject(o, "axes");
    int c;
    for (c = 0; c < 6; c++) {
        cJSON *a = cJSON_AddObjectToObject(ax, k_ch[c]);
        if (r->ok[c]) {
            cJSON_AddNumberToObject(a, "total_power", (double)r->bw[c].total);
            cJSON_AddNumberToObject(a, "bandwidth_hz", (double)r->bw[c].bandwidth_hz);
            cJSON_AddNumberToObject(a, "fs_hz", (double)r->bw[c].fs_hz);
            cJSON_AddNumberToObject(a, "fs_rounded_hz", (double)r->bw[c].fs_rounded_hz);
        }
    }
    {
        /* a group with no power on any axis has no band: null, not 0 */
        static const char *const bw_key[2] = { "accel_bandwidth_hz", "gyro_bandwidth_hz" };
        static const char *const fs_key[2] = { "accel_fs_hz", "gyro_fs_hz" };
        int g, any = 0;
        for (g = 0; g < 2; g++) {
            if (r->ok[3 * g] || r->ok[3 * g + 1] || r->ok[3 * g + 2]) {
                cJSON_AddNumberToObject(o, bw_key[g], r->group_bw[g]);
                cJSON_AddNumberToObject(o, fs_key[g], r->group_fs[g]);
                any = 1;
            } else {
                cJSON_AddNullToObject(o, bw_key[g]);
                cJSON_AddNullToObject(o, fs_key[g]);
            }
        }
        if (any) {
            cJSON_AddNumberToObject(o, "fs_hz", r->overall_fs);
        } else {
            cJSON_AddNullToObject(o, "fs_hz");
        }
    }
    cJSON_AddNumberToObject(o, "segments", (double)r->nseg);
    cJSON_AddNumberToObject(o, "resolution_hz", r->df);
    return o;
}

/* One channel's data block; returns the number of points written (a PSD
 * point only where it is positive: the axis is logarithmic; a CCDF point
 * under ybot, 0 past the last power, at ybot, the bottom of its
 * logarithmic axis, so the curve is seen to fall off it). */
static int block(FILE *gp, const char *name, const result_t *r, int c, int ccdf, double ybot)
{
    uint32_t k;
    int npts = 0;
    fprintf(gp, "$%s << EOD\n", name);
    for (k = 0; k < r->nbins; k++) {
        const double v = ccdf ? fmax((double)r->ccdf[c][k], ybot) : (double)r->psd[c][k];
        /* CCDF at the bin's upper edge; PSD at the bin centre */
        const double f = ccdf ? ((k + 1u == r->nbins) ? (double)k * r->df : ((double)k + 0.5) * r->df)
                              : (double)k * r->df;
        if (!ccdf && !(v > 0.0)) {
            continue;
        }
        fprintf(gp, "%.6g %.6g\n", f, v);
        npts++;
    }
    fprintf(gp, "EOD\n");
    return npts;
}

static int plot_psd(const char *dir, const result_t *r, const char *src, const setting_t *st)
{
    hx_plot_t p;
    char path[HX_PLOT_PATH_SIZE];
    int g, c;
    snprintf(path, sizeof path, "%s/psd.png", dir);
    if (hx_plot_open(&p, CMD, path, 900, 700) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 2,1 title 'Welch PSD (%s %u, %u overlap, dc %s): %s'\n",
            st->wc.window == FNAV_WINDOW_HAMMING ? "Hamming" : (st->wc.window == FNAV_WINDOW_HANN ? "Hann" : "rect"),
            (unsigned)st->wc.nfft, (unsigned)st->wc.overlap,
            k_dc_names[st->exclude_dc ? 4 : (st->wc.detrend == FNAV_DETREND_CONSTANT ? 0 : st->wc.detrend == FNAV_DETREND_LINEAR ? 1 : st->wc.detrend == FNAV_DETREND_GLOBAL ? 2 : 3)],
            src);
    fprintf(p.gp, "set logscale y\nset format y '%%.0e'\nset xlabel 'frequency [Hz]'\n");
    for (g = 0; g < 2; g++) {
        int npts[3], n = 0;
        for (c = 3 * g; c < 3 * g + 3; c++) {
            char nm[16];
            snprintf(nm, sizeof nm, "d%d", c);
            npts[c - 3 * g] = block(p.gp, nm, r, c, 0, 0.0);
        }
        fprintf(p.gp, "set title '%s'\nset ylabel '%s'\n", g == 0 ? "accelerometers (Fig. 3)" : "gyroscopes",
                g == 0 ? "PSD [(m/s^2)^2/Hz]" : "PSD [(rad/s)^2/Hz]");
        /* only the axes with points: a group without power on any axis (a
         * constant channel, e.g. gyroscopes logged as zeros) gave gnuplot
         * nothing to plot, and psd.png failed with exit 3 */
        for (c = 3 * g; c < 3 * g + 3; c++) {
            if (npts[c - 3 * g] > 0) {
                fprintf(p.gp, "%s$d%d using 1:2 with lines lw 1.5 title '%s'", n++ ? ", " : "plot ", c, k_ch[c]);
            }
        }
        if (n > 0) {
            fprintf(p.gp, "\n");
        } else {
            fprintf(p.gp, "set xrange [0:%.6g]\nset yrange [1e-6:1]\nset label 1 'no power on any axis' at graph 0.5,0.5 "
                          "center\nplot 1/0 notitle\nunset label 1\nset autoscale\n",
                    (double)(r->nbins - 1u) * r->df);
        }
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, CMD);
}

static int plot_ccdf(const char *dir, const result_t *r, const char *src, const fnav_bandwidth_config_t *bc)
{
    hx_plot_t p;
    char path[HX_PLOT_PATH_SIZE];
    int g, c;
    /* a logarithmic y axis: on 0..1 the threshold's crossing (1 - 0.95 =
     * 0.05) would sit in the bottom 5 % of the panel; its floor is 1e-3, or a decade under the
     * threshold line where that is lower (--threshold 0.9999: 1e-5;
     * --threshold 1: no line, the floor 1e-3) */
    const double line = 1.0 - (double)bc->threshold;
    const double ybot = line > 0.0 && line / 10.0 < 1e-3 ? line / 10.0 : 1e-3;
    snprintf(path, sizeof path, "%s/ccdf.png", dir);
    if (hx_plot_open(&p, CMD, path, 900, 700) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 2,1 title 'CCDF of the power (threshold %g %%): %s'\n",
            100.0 * (double)bc->threshold, src);
    fprintf(p.gp, "set xlabel 'frequency [Hz]'\nset ylabel '1 - cumulative power fraction'\nset logscale y\n"
                  "set format y '%%g'\nset yrange [%.6g:1]\n",
            ybot);
    for (g = 0; g < 2; g++) {
        const int any = r->ok[3 * g] || r->ok[3 * g + 1] || r->ok[3 * g + 2];
        fprintf(p.gp, "unset arrow\n");
        for (c = 3 * g; c < 3 * g + 3; c++) {
            char nm[16];
            snprintf(nm, sizeof nm, "c%d", c);
            block(p.gp, nm, r, c, 1, ybot);
            if (r->ok[c]) {
                /* the panel's bottom to its top: y = 0 is off a log axis */
                fprintf(p.gp, "set arrow from first %.4g, graph 0 to first %.4g, graph 1 nohead dt 3 lc %d\n",
                        (double)r->bw[c].bandwidth_hz, (double)r->bw[c].bandwidth_hz, c - 3 * g + 1);
            }
        }
        /* an axis without power has no band and no CCDF: it was titled 0 Hz
         * and drawn as a flat line at 0 */
        fprintf(p.gp, "set title '%s (Fig. 4): bandwidths", g == 0 ? "accelerometers" : "gyroscopes");
        for (c = 3 * g; c < 3 * g + 3; c++) {
            if (r->ok[c]) {
                fprintf(p.gp, "%s %.0f", c > 3 * g ? "," : "", (double)r->bw[c].bandwidth_hz);
            } else {
                fprintf(p.gp, "%s no power", c > 3 * g ? "," : "");
            }
        }
        fprintf(p.gp, "%s'\n", any ? " Hz" : "");
        if (!any) {
            /* no curve: the x axis was gnuplot's -10..10; the log's band
             * instead, and the panel says why it is empty, as psd.png's */
            fprintf(p.gp, "set xrange [0:%.6g]\nset label 1 'no power on any axis' at graph 0.5,0.5 center\n",
                    (double)(r->nbins - 1u) * r->df);
        }
        fprintf(p.gp, "plot ");
        for (c = 3 * g; c < 3 * g + 3; c++) {
            if (r->ok[c]) {
                fprintf(p.gp, "$c%d using 1:2 with lines lw 1.5 lc %d title '%s', ", c, c - 3 * g + 1, k_ch[c]);
            }
        }
        if (line > 0.0) {
            fprintf(p.gp, "%.4g with lines dt 2 lc rgb 'black' title 'threshold'\n", line);
        } else {
            fprintf(p.gp, "1/0 notitle\n"); /* --threshold 1: the line would be at 0 */
        }
        if (!any) {
            fprintf(p.gp, "unset label 1\nset autoscale x\n");
        }
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, CMD);
}

/* The most time columns spectrogram.png is drawn with: a longer log's
 * consecutive periodograms are averaged in power, SPEC_COLS_MAX or fewer
 * columns (1,000 px wide). Every segment of every bin was sent to gnuplot
 * as text: 1 M samples took 90 s (3 s without --plot), 3 M 366 MB. */
#define SPEC_COLS_MAX 2000u

/* Spectrogram (Fig. 6): the per-segment spectra of one channel in dB, or
 * on a long log the mean of each `group` consecutive ones (in power). */
static int plot_spectrogram(const char *dir, const hx_log_t *log, int c, uint32_t nfft, double rate, const char *src)
{
    static fnav_welch_t w;
    static fnav_real_t col[FNAV_WELCH_MAX_BINS];
    static double acc[FNAV_WELCH_MAX_BINS];
    fnav_welch_config_t cfg = fnav_welch_config_default;
    hx_plot_t p;
    char path[HX_PLOT_PATH_SIZE];
    size_t i, nseg, group, ingroup = 0;
    double t_first = 0.0;
    uint32_t seen = 0, k, nb;
    cfg.nfft = nfft;
    cfg.overlap = nfft / 2u;
    cfg.window = FNAV_WINDOW_HANN;
    cfg.rate_hz = (fnav_real_t)rate;
    if (fnav_welch_init(&w, &cfg) != FNAV_OK) {
        hx_error(CMD, "--spec-nfft %u: not a power of two in 8..%u", (unsigned)nfft, (unsigned)FNAV_WELCH_MAX_NFFT);
        return -1;
    }
    snprintf(path, sizeof path, "%s/spectrogram.png", dir);
    if (hx_plot_open(&p, CMD, path, 1000, 500) != 0) {
        return -1;
    }
    nb = fnav_welch_bins(&w);
    /* segments of nfft at a hop of nfft / 2, and how many go in a column */
    nseg = log->n >= (size_t)nfft ? (log->n - (size_t)nfft) / ((size_t)nfft / 2u) + 1u : 0u;
    group = nseg > SPEC_COLS_MAX ? (nseg + SPEC_COLS_MAX - 1u) / SPEC_COLS_MAX : 1u;
    memset(acc, 0, sizeof acc);
    fprintf(p.gp, "$s << EOD\n");
    for (i = 0; i < log->n; i++) {
        if (fnav_welch_push(&w, (fnav_real_t)chan(log, i, c)) != FNAV_OK) {
            break;
        }
        if (fnav_welch_segments(&w) > seen) {
            /* the segment's centre: samples i - nfft + 1 .. i under a
             * periodic Hann window, which is 0 at the first and symmetric
             * about the first + nfft / 2, scipy.signal.spectrogram's t
             * (i - nfft / 2 would be a sample early; tests/cli/test_psd.sh) */
            double t = ((double)i + 1.0 - 0.5 * (double)nfft) / rate;
            seen = fnav_welch_segments(&w);
            if (fnav_welch_last(&w, col, FNAV_WELCH_MAX_BINS) != FNAV_OK) {
                continue;
            }
            for (k = 0; k < nb; k++) {
                acc[k] += (double)col[k];
            }
            t_first = ingroup == 0u ? t : t_first;
            if (++ingroup < group) {
                continue;
            }
            /* a column: the group's mean power, at the middle of its
             * segments' centres (one segment: its centre, as before). A last
             * group of fewer segments is left out: its column would break
             * the even time grid `with image` draws */
            t = 0.5 * (t_first + t);
            for (k = 0; k < nb; k++) {
                const double pw = acc[k] / (double)group;
                const double v = pw > 1e-30 ? 10.0 * log10(pw) : -300.0;
                fprintf(p.gp, "%.5g %.5g %.4g\n", t, (double)k * rate / (double)nfft, v);
                acc[k] = 0.0;
            }
            ingroup = 0u;
            fprintf(p.gp, "\n");
        }
    }
    fprintf(p.gp, "EOD\n");
    fprintf(p.gp, "set title 'Spectrogram of %s (Hann %u, 50 %% overlap; Fig. 6): %s'\n", k_ch[c], (unsigned)nfft,
            src);
    /* the averaging on the time axis, not in the title (which a long log's
     * source name then clipped) */
    if (group > 1u) {
        fprintf(p.gp, "set xlabel 'time [s] (%lu segments averaged in power per column)'\n", (unsigned long)group);
    } else {
        fprintf(p.gp, "set xlabel 'time [s]'\n");
    }
    fprintf(p.gp, "set ylabel 'frequency [Hz]'\nset cblabel 'PSD [dB re 1 %s^2/Hz]' offset 2.5,0\n",
            c < 3 ? "(m/s^2)" : "(rad/s)");
    /* stats first: with one column it reads the values as y and drops those
     * outside the y range, which is the frequency axis [0, f_s/2] (every dB
     * value of a static log is negative: no point left, STATS_max undefined,
     * gnuplot failed and the command exited 3) */
    fprintf(p.gp, "stats $s using 3 nooutput\n");
    fprintf(p.gp, "set view map\nset palette rgbformulae 33,13,10\nunset grid\n");
    fprintf(p.gp, "set xrange [0:%.6g]\nset yrange [0:%.6g]\n", (double)log->n / rate, 0.5 * rate);
    fprintf(p.gp, "set cbrange [STATS_max-80:STATS_max]\n");
    fprintf(p.gp, "plot $s using 1:2:3 with image notitle\n");
    return hx_plot_close(&p, CMD);
}

static int plot_sensitivity(const char *dir, double fs_tab[NDC][NSENS_NFFT], const int have[NSENS_NFFT], double rate,
                            const char *src)
{
    hx_plot_t p;
    char path[HX_PLOT_PATH_SIZE];
    int d, k;
    snprintf(path, sizeof path, "%s/sensitivity.png", dir);
    /* 900 wide as psd.png and ccdf.png: at 800 the title runs past the
     * right edge on the shared data's paths */
    if (hx_plot_open(&p, CMD, path, 900, 500) != 0) {
        return -1;
    }
    fprintf(p.gp, "$t << EOD\n");
    for (k = 0; k < NSENS_NFFT; k++) {
        if (!have[k]) {
            continue;
        }
        fprintf(p.gp, "%u", (unsigned)k_sens_nfft[k]);
        for (d = 0; d < NDC; d++) {
            fprintf(p.gp, " %.6g", fs_tab[d][k]);
        }
        fprintf(p.gp, "\n");
    }
    fprintf(p.gp, "EOD\n");
    fprintf(p.gp, "set title 'Lowest usable sampling frequency vs Welch segment (%g Hz log): %s'\n", rate, src);
    fprintf(p.gp, "set logscale x 2\nset xlabel 'segment length [samples]'\nset ylabel 'sampling frequency [Hz]'\n");
    {
        /* only the DC treatments with an answer; none at all (a log of
         * zeros) would fail the plot, exit 3, and one value everywhere (a
         * constant log: 50 Hz) would make gnuplot warn "empty y range" */
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        int n = 0, nd[NDC];
        for (d = 0; d < NDC; d++) {
            nd[d] = 0;
            for (k = 0; k < NSENS_NFFT; k++) {
                if (have[k] && isfinite(fs_tab[d][k])) {
                    nd[d]++;
                    lo = fmin(lo, fs_tab[d][k]);
                    hi = fmax(hi, fs_tab[d][k]);
                }
            }
        }
        if (hi < lo) {
            fprintf(p.gp, "set yrange [0:1]\nset label 1 'no answer: no channel has power under any DC treatment' at "
                          "graph 0.5,0.5 center\nplot $t using 1:(-1) notitle\n");
            return hx_plot_close(&p, CMD);
        }
        if (hi - lo <= 1e-9 * hi) {
            fprintf(p.gp, "set yrange [0:%.6g]\n", 2.0 * hi);
        } else {
            /* a margin above and below: the lines at the lowest and highest
             * answer ran along the frame, where they could not be seen */
            fprintf(p.gp, "set offsets 0, 0, graph 0.05, graph 0.05\n");
        }
        fprintf(p.gp, "set key outside right top\nplot "); /* beside the axes: inside, it sits on the lines */
        for (d = 0; d < NDC; d++) {
            if (nd[d] > 0) {
                fprintf(p.gp, "%s$t using 1:%d with linespoints lw 2 title 'dc %s'", n++ ? ", " : "", d + 2,
                        k_dc_names[d]);
            }
        }
    }
    fprintf(p.gp, "\n");
    return hx_plot_close(&p, CMD);
}

/* ------------------------------------------------------------ main */

int hx_cmd_psd(int argc, char **argv)
{
    hx_args_t a;
    hx_log_t log;
    setting_t st;
    fnav_bandwidth_config_t bc = fnav_bandwidth_config_default;
    static result_t res, sres;
    long nfft = 64, overlap = -1, spec_nfft = 256, bad_i = -1;
    double thr = 0.95, rnd = 50.0, rate, bw_max;
    int above_rate, at_nyquist;
    int rc, exit_code = HX_EXIT_OK, dc_mode = 0, c, spec_axis = -1, bad_c = -1;
    const char *s;
    double fs_tab[NDC][NSENS_NFFT];
    int have[NSENS_NFFT];
    cJSON *root = NULL;

    rc = hx_args_parse(&k_spec, argc, argv, &a);
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--plot", NULL };
        if (hx_refuse_dash(CMD, &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_check_input_opts(CMD, &a) != 0) {
        return HX_EXIT_USAGE;
    }
    st.wc = fnav_welch_config_default;
    st.exclude_dc = 0;
    if (hx_arg_long(&a, "--nfft", 8, FNAV_WELCH_MAX_NFFT, &nfft) != 0 || (nfft & (nfft - 1)) != 0) {
        if ((nfft & (nfft - 1)) != 0) {
            hx_error(CMD, "--nfft must be a power of two in 8..%d, not '%s'", FNAV_WELCH_MAX_NFFT,
                     hx_arg(&a, "--nfft"));
        }
        return HX_EXIT_USAGE;
    }
    if (hx_arg_long(&a, "--overlap", 0, nfft - 1, &overlap) != 0 ||
        hx_arg_double(&a, "--threshold", 0.01, 1.0, &thr) != 0 || hx_arg_double(&a, "--round", 0.0, 1e6, &rnd) != 0 ||
        hx_arg_long(&a, "--spec-nfft", 8, FNAV_WELCH_MAX_NFFT, &spec_nfft) != 0) {
        return HX_EXIT_USAGE;
    }
    if (rnd != 0.0 && rnd < ROUND_MIN_HZ) {
        /* 1e-40 ran as "multiples of 9.99995e-41 Hz" (a float subnormal),
         * 1e-50 as "not rounded" with round_hz 1e-50 in the JSON, exit 0 */
        hx_error(CMD, "--round '%s' is neither 0 (not rounded) nor a step in [%g, %g] Hz", hx_arg(&a, "--round"),
                 ROUND_MIN_HZ, 1e6);
        return HX_EXIT_USAGE;
    }
    if ((spec_nfft & (spec_nfft - 1)) != 0) {
        hx_error(CMD, "--spec-nfft must be a power of two in 8..%d, not '%s'", FNAV_WELCH_MAX_NFFT,
                 hx_arg(&a, "--spec-nfft"));
        return HX_EXIT_USAGE;
    }
    st.wc.nfft = (uint32_t)nfft;
    st.wc.overlap = overlap >= 0 ? (uint32_t)overlap : (uint32_t)nfft / 2u;
    if ((s = hx_arg(&a, "--window")) != NULL) {
        if (strcmp(s, "hamming") == 0) {
            st.wc.window = FNAV_WINDOW_HAMMING;
        } else if (strcmp(s, "hann") == 0) {
            st.wc.window = FNAV_WINDOW_HANN;
        } else if (strcmp(s, "rect") == 0) {
            st.wc.window = FNAV_WINDOW_RECT;
        } else {
            hx_error(CMD, "--window must be hamming, hann or rect, not '%s'", s);
            return HX_EXIT_USAGE;
        }
    }
    st.wc.symmetric = hx_flag(&a, "--symmetric");
    if ((s = hx_arg(&a, "--dc")) != NULL && (dc_mode = parse_dc(s, &st)) < 0) {
        hx_error(CMD, "--dc must be segment, linear, global, none or exclude, not '%s'", s);
        return HX_EXIT_USAGE;
    }
    if (st.wc.symmetric && st.wc.detrend == FNAV_DETREND_GLOBAL) {
        hx_error(CMD, "--dc global needs a periodic window (drop --symmetric)");
        return HX_EXIT_USAGE;
    }
    if ((s = hx_arg(&a, "--spec-axis")) != NULL) {
        for (c = 0; c < 6; c++) {
            if (strcmp(s, k_ch[c]) == 0) {
                spec_axis = c;
            }
        }
        if (spec_axis < 0) {
            hx_error(CMD, "--spec-axis must be one of ax, ay, az, gx, gy, gz, not '%s'", s);
            return HX_EXIT_USAGE;
        }
    }
    if (hx_arg(&a, "--plot") == NULL && (hx_arg(&a, "--spec-axis") != NULL || hx_arg(&a, "--spec-nfft") != NULL)) {
        /* they shape spectrogram.png only: without --plot they are refused,
         * not ignored with exit 0 */
        hx_error(CMD, "%s sets the spectrogram of --plot DIR (spectrogram.png): give --plot DIR",
                 hx_arg(&a, "--spec-axis") != NULL ? "--spec-axis" : "--spec-nfft");
        return HX_EXIT_USAGE;
    }
    bc.threshold = (fnav_real_t)thr;
    bc.round_hz = (fnav_real_t)rnd;

    {
        static const char *const outs[] = { "--out", "--json", "--plot", NULL };
        static const char *const files[] = { "--out", "--json", NULL };
        const char *dir = hx_arg(&a, "--plot");
        struct stat sb;
        char png[HX_PLOT_PATH_SIZE];
        if (hx_output_is_input(CMD, a.pos[0], &a, outs)) {
            return HX_EXIT_USAGE;
        }
        /* written after the Welch work: checked now, the plots' directory
         * made (not found unwritable at the end) */
        if (hx_check_outputs(CMD, &a, files, NULL) != 0) {
            return HX_EXIT_IO;
        }
        if (dir != NULL) {
            /* gnuplot first: a run refused for want of it must not leave
             * the directory made, empty; one made here is removed when the
             * picture cannot be written */
            int made = 0;
            snprintf(png, sizeof png, "%s/psd.png", dir);
            if (hx_plot_have_gnuplot(CMD, png) != 0) {
                return HX_EXIT_IO;
            }
            if (stat(dir, &sb) != 0) {
                if (mkdir(dir, 0777) != 0) {
                    hx_error(CMD, "%s: cannot create directory (%s)", dir, strerror(errno));
                    return HX_EXIT_IO;
                }
                made = 1;
            }
            if (hx_plot_check(CMD, png) != 0) {
                if (made) {
                    (void)remove(dir); /* an empty directory: rmdir */
                }
                return HX_EXIT_IO;
            }
            if (made) {
                /* made again when the plots are written: a run that ends
                 * before them (an input error, Ctrl-C) left it made and
                 * empty */
                (void)remove(dir);
            }
        }
    }
    rc = hx_load_input(CMD, &a, a.pos[0], &log);
    if (rc < 0) {
        return HX_EXIT_DATA;
    }
    if (rc > 0) {
        exit_code = HX_EXIT_DATA;
    }
    rate = log.meta.rate_hz;
    if (!(rate > 0.0) && log.n > 1 && log.t_ns[log.n - 1] > log.t_ns[0]) {
        rate = 1e9 * (double)(log.n - 1) / (double)(log.t_ns[log.n - 1] - log.t_ns[0]);
    }
    /* too short first: one stamped sample has no rate either, and no
     * --input-rate gives it one (a stamped format ignores the option) */
    if (log.n < (size_t)nfft) {
        /* what to do: the segment length that fits; --nfft's least is 8 */
        char fix[96];
        unsigned fit = 8u;
        while ((size_t)fit * 2u <= log.n) {
            fit *= 2u;
        }
        /* not "--nfft 8 or less" (--nfft 4 is refused), nor "(--nfft 8)"
         * to a log of fewer samples, which that option does not help */
        if (log.n >= 16u) {
            snprintf(fix, sizeof fix, "give --nfft %u or less (a power of two)", fit);
        } else if (log.n >= 8u) {
            snprintf(fix, sizeof fix, "give --nfft 8 (the least)");
        } else {
            snprintf(fix, sizeof fix, "a Welch segment needs at least 8 samples: the log is too short for a spectrum");
        }
        if (rc > 0) {
            /* the input's error is the cause, not a missing option; its
             * line was warned when it was read (hx_load_input): the log
             * named, not the line again, as simgap's and info's closing
             * error */
            hx_error(CMD, "%s: incomplete input (warned above): the %zu sample%s before the error %s fewer than one "
                          "%u-sample segment",
                     a.pos[0], log.n, log.n == 1u ? "" : "s", log.n == 1u ? "is" : "are", (unsigned)nfft);
        } else {
            hx_error(CMD, "%s: %zu sample%s, fewer than one %u-sample segment; %s", a.pos[0], log.n,
                     log.n == 1u ? "" : "s", (unsigned)nfft, fix);
        }
        hx_log_free(&log);
        return HX_EXIT_DATA;
    }
    if (!(rate > 0.0)) {
        /* a bad line after these samples was warned when it was read */
        if (log.n > 1 && log.t_ns[log.n - 1] == log.t_ns[0]) {
            /* the count and the question simgap and allan ask (--input-rate
             * is ignored for a stamped log: not offered) */
            hx_error(CMD, "%s: sample rate unknown: every time stamp is the same (all %zu samples at one time): is the "
                          "time column filled?",
                     a.pos[0], log.n);
        } else {
            hx_error(CMD, "%s: sample rate unknown; give --input-rate", a.pos[0]);
        }
        hx_log_free(&log);
        return HX_EXIT_DATA;
    }
    {
        /* Welch assumes uniform sampling: say how far the time stamps are
         * from it. Stamps coarser than the period (a 398 Hz log printed to
         * the millisecond reads 2 and 3 ms) may differ by their resolution,
         * the intervals' gcd: every interval of such a uniform log was
         * counted as irregular. */
        size_t i;
        long irregular = 0, gaps = 0, repeats = 0, run = 0; /* run: the intervals of 0 right before */
        double missing = 0.0, longest_gap_s = 0.0;
        int64_t res_ns = 0;
        if (log.meta.rate_coarse) {
            for (i = 1; i < log.n; i++) {
                if (log.t_ns[i] > log.t_ns[i - 1]) {
                    res_ns = hx_gcd_i64(log.t_ns[i] - log.t_ns[i - 1], res_ns);
                }
            }
        }
        for (i = 1; i < log.n; i++) {
            const int64_t dt = log.t_ns[i] - log.t_ns[i - 1];
            /* the gaps with what they lost, as allan's warning (a 5 s hole
             * was only "1 of 4999 intervals differ"); a stamp written twice
             * (0, 10, 10, 30 ms) is no sample lost: as many periods fewer
             * after it as samples shared the stamp */
            const double lost = hx_interval_missing(dt, rate, res_ns) - (double)run;
            irregular += hx_interval_irregular(dt, rate, res_ns);
            repeats += dt == 0;
            run = dt == 0 ? run + 1 : 0;
            if (lost > 0.0) {
                gaps++;
                missing += lost;
                longest_gap_s = 1e-9 * (double)dt > longest_gap_s ? 1e-9 * (double)dt : longest_gap_s;
            }
        }
        if (irregular > 0) {
            char what[400];
            hx_irregular_text(what, sizeof what, irregular, log.n - 1, rate, repeats, gaps, longest_gap_s, missing,
                              (double)log.n);
            hx_warn(CMD, "%s: %s: Welch assumes uniform sampling%s", a.pos[0], what, hx_gaps_joined(gaps));
        }
    }
    if (!hx_nav_bursts_warn(CMD, a.pos[0], log.meta.format, log.t_ns, log.n, 0, "the frequencies are read at", rate,
                            log.meta.rate_nominal && log.meta.rate_hz > 0.0)) {
        /* a stated rate the stamps contradict, warned as info's */
        hx_stated_rate_warn(CMD, a.pos[0], &log.meta, log.t_ns, log.n, "the frequencies are read at");
    }
    if (hx_arg(&a, "--input-rate") == NULL) {
        /* a time column in milliseconds (100 Hz read as 0.1 Hz) is said as
         * such, not only as an answer above the log's rate */
        char msg[320];
        hx_csv_layout_t lay;
        /* judged by the log's span too: stamps in bursts are no unit */
        if (hx_time_unit_hint(hx_log_time_unit_rate(&log, rate), hx_units_layout(log.meta.format, &lay), msg,
                              sizeof msg)) {
            hx_warn(CMD, "%s: %s; the frequencies are read at %.3g Hz", a.pos[0], msg, rate);
        }
    }
    st.wc.rate_hz = (fnav_real_t)rate;
    if (analyse(&log, &st, &bc, &res, &bad_i, &bad_c) != 0) {
        if (bad_i >= 0) {
            hx_error(CMD, "%s: sample %ld: channel %s (%g) is not finite or its power overflows the core's float",
                     a.pos[0], bad_i + 1, k_ch[bad_c], chan(&log, (size_t)bad_i, bad_c));
        } else {
            hx_error(CMD, "Welch rejected the configuration (nfft %d at %.4g Hz)", (int)st.wc.nfft, rate);
        }
        hx_log_free(&log);
        return HX_EXIT_DATA;
    }
    if (res.nseg < PSD_FEW_SEGMENTS) {
        /* Welch's average of K periodograms has nu <= 2K degrees of
         * freedom (2K without overlap; the overlap's correlation lowers
         * it), so each bin's relative sd is at least 1/sqrt(K): 100 % for
         * one segment, a single periodogram (Percival & Walden 1993,
         * 6.17) */
        hx_warn(CMD, "%s: %u segment%s of %u samples: each PSD bin scatters by %s%.0f %% of its value (Welch averages "
                     "its segments' periodograms); the 95 %% band, from the cumulative power, is steadier; a "
                     "shorter --nfft or a longer log gives %d segments or more",
                a.pos[0], (unsigned)res.nseg, res.nseg == 1 ? "" : "s", (unsigned)st.wc.nfft,
                res.nseg == 1 ? "" : "at least ", 100.0 / sqrt((double)res.nseg), PSD_FEW_SEGMENTS);
    }
    {
        /* a log whose format names no sensor (a CSV's "unknown"): the line
         * names the format, as allan's and info's do */
        char sensor_text[64];
        if (log.meta.sensor[0] == '\0' || strcmp(log.meta.sensor, "unknown") == 0) {
            snprintf(sensor_text, sizeof sensor_text, "%s log", hx_format_name(log.meta.format));
        } else {
            snprintf(sensor_text, sizeof sensor_text, "%s", log.meta.sensor);
        }
        char shown[4096]; /* a file name's control characters as '?' (hx_line_str), as in the messages */
        printf("harness psd: %s (%s), %zu samples at %.4g Hz, %.2f s\n", hx_line_str(shown, sizeof shown, a.pos[0]),
               sensor_text, log.n, rate, (double)log.n / rate);
    }
    {
        char title[1024], dct[256], rndt[64];
        dc_text(dc_mode, res.df, dct, sizeof dct);
        if (bc.round_hz > FNAV_R(0.0)) {
            snprintf(rndt, sizeof rndt, "rounded up to a multiple of %g Hz", (double)bc.round_hz);
        } else {
            snprintf(rndt, sizeof rndt, "not rounded (--round 0)");
        }
        snprintf(title, sizeof title,
                 "Welch: %s window of %u samples%s, overlap %u, dc %s, %u segment%s, resolution %.3g Hz\n"
                 "Criterion (paper II.B): per axis, the band from 0 Hz holding %g %% of the total power of the "
                 "one-sided PSD of the channel as logged (sensor axes);\n"
                 "  DC: %s;\n"
                 "  sampling frequency = 2 x band, %s; a group needs its widest axis",
                 st.wc.window == FNAV_WINDOW_HAMMING ? "Hamming" : (st.wc.window == FNAV_WINDOW_HANN ? "Hann" : "rect"),
                 (unsigned)st.wc.nfft, st.wc.symmetric ? " (symmetric)" : "", (unsigned)st.wc.overlap,
                 k_dc_names[dc_mode], (unsigned)res.nseg, res.nseg == 1 ? "" : "s", res.df, 100.0 * thr, dct, rndt);
        print_result(title, &res, &bc, rate, dc_mode == 0);
    }
    {
        /* a group whose every axis is constant after the DC treatment has no
         * band: its 0 Hz is no answer, and with both groups so there is none */
        int g, none[2];
        for (g = 0; g < 2; g++) {
            none[g] = !res.ok[3 * g] && !res.ok[3 * g + 1] && !res.ok[3 * g + 2];
        }
        if (none[0] && none[1]) {
            hx_error(CMD, "%s: no channel has power once the DC is treated (dc %s): every channel is constant%s, so "
                          "no sampling frequency can be read",
                     a.pos[0], k_dc_names[dc_mode],
                     sizeof(fnav_real_t) < sizeof(double)
                         ? ", or varies by less than the float build's range holds as a power (about 1e-19 of the "
                           "values' unit: scale them, or use the double build, FNAV_USE_DOUBLE=1)"
                         : "");
            exit_code = HX_EXIT_DATA;
        } else if (none[0] || none[1]) {
            hx_warn(CMD, "%s: no %s axis has power once the DC is treated: the answer comes from the %s alone",
                    a.pos[0], none[0] ? "accelerometer" : "gyroscope", none[0] ? "gyroscopes" : "accelerometers");
        }
    }
    bw_max = widest_band(&res);
    above_rate = res.overall_fs > rate * (1.0 + 1e-9);
    at_nyquist = above_rate || bw_max >= NYQ_FRAC * 0.5 * rate;
    if (at_nyquist && !above_rate) {
        /* the rounded answer is within the log's rate, but the band still ends
         * at the top of what the log can show (a static log: white sensor
         * noise to the Nyquist frequency; the answer is then the log's rate by
         * construction, not a property of the motion) */
        hx_warn(CMD, "%s: %g %% of the power reaches %.1f Hz, %.0f %% of the Nyquist frequency %.4g Hz: the power does "
                     "not fall off inside this log's band (white sensor noise does this, e.g. a static log, which "
                     "measures the sensor, not motion), so the log cannot show where the band ends; read %.*f Hz as "
                     "a lower bound set by the log's rate, not a measured requirement",
                a.pos[0], 100.0 * thr, bw_max, 100.0 * bw_max / (0.5 * rate), 0.5 * rate, fs_decimals(&bc),
                res.overall_fs);
    }
    if (above_rate && bw_max < NYQ_FRAC * 0.5 * rate) {
        /* the rounding step alone (--round above the rate, or a low-rate
         * log): the band itself ends well inside the log's (this said it was
         * "near the Nyquist frequency" for a 115 Hz band of a 1000 Hz log) */
        hx_warn(CMD, "%s: the answer (%.*f Hz) is above the log's own rate (%.4g Hz) only through the rounding to "
                     "multiples of %g Hz: %g %% of the power lies below %.1f Hz, %.0f %% of the Nyquist frequency, "
                     "and 2 x that is %.1f Hz (--round 0 gives it)",
                a.pos[0], fs_decimals(&bc), res.overall_fs, rate, (double)bc.round_hz, 100.0 * thr, bw_max, 100.0 * bw_max / (0.5 * rate),
                2.0 * bw_max);
    } else if (above_rate) {
        /* 2 x bandwidth never exceeds the rate; the rounding up did. The band
         * reaches the Nyquist frequency (a static log's noise is white up to
         * it), so the log cannot show where the signal ends. */
        hx_warn(CMD, "%s: the answer (%.*f Hz) is above the log's own rate (%.4g Hz): %g %% of the power reaches "
                     "%.1f Hz, near the Nyquist frequency %.4g Hz, so this log cannot show where the band ends; "
                     "read it as 'at least %.4g Hz' (or give --round 0)",
                a.pos[0], fs_decimals(&bc), res.overall_fs, rate, 100.0 * thr, bw_max, 0.5 * rate, rate);
    }

    memset(have, 0, sizeof have);
    if (hx_flag(&a, "--sensitivity")) {
        int d, k;
        printf("\nSensitivity: bandwidth per axis (Hz) and the sampling frequency, Hamming, 50 %% overlap\n");
        printf("  %-8s %5s %7s %7s %7s %7s %7s %7s %7s %7s %7s %7s\n", "dc", "nfft", "df_Hz", "ax", "ay", "az", "gx",
               "gy", "gz", "fs_acc", "fs_gyr", "fs");
        for (d = 0; d < NDC; d++) {
            for (k = 0; k < NSENS_NFFT; k++) {
                setting_t ss;
                ss.wc = fnav_welch_config_default;
                ss.wc.rate_hz = (fnav_real_t)rate;
                ss.wc.nfft = k_sens_nfft[k];
                ss.wc.overlap = k_sens_nfft[k] / 2u;
                ss.exclude_dc = 0;
                parse_dc(k_dc_names[d], &ss);
                fs_tab[d][k] = (double)NAN;
                if (ss.wc.nfft > FNAV_WELCH_MAX_NFFT || (size_t)ss.wc.nfft > log.n || analyse(&log, &ss, &bc, &sres, &bad_i, &bad_c) != 0) {
                    continue;
                }
                {
                    /* an axis or group without power has no band: '-' (it
                     * printed 0.0 and 0 Hz; with no power anywhere the row's
                     * answer was 0 Hz, also in the JSON) */
                    int g, gok[2];
                    have[k] = 1;
                    printf("  %-8s %5u %7.3g", k_dc_names[d], (unsigned)ss.wc.nfft, sres.df);
                    for (c = 0; c < 6; c++) {
                        if (sres.ok[c]) {
                            printf(" %7.1f", (double)sres.bw[c].bandwidth_hz);
                        } else {
                            printf(" %7s", "-");
                        }
                    }
                    for (g = 0; g < 2; g++) {
                        gok[g] = sres.ok[3 * g] || sres.ok[3 * g + 1] || sres.ok[3 * g + 2];
                        if (gok[g]) {
                            printf(" %7.*f", fs_decimals(&bc), sres.group_fs[g]);
                        } else {
                            printf(" %7s", "-");
                        }
                    }
                    if (gok[0] || gok[1]) {
                        fs_tab[d][k] = sres.overall_fs;
                        printf(" %7.*f\n", fs_decimals(&bc), sres.overall_fs);
                    } else {
                        printf(" %7s\n", "-");
                    }
                }
            }
        }
    }

    if (hx_arg(&a, "--out") != NULL && write_csv(hx_arg(&a, "--out"), &res, a.pos[0]) != 0) {
        exit_code = HX_EXIT_IO;
    }
    if (hx_arg(&a, "--json") != NULL) {
        char err[HX_ERR_SIZE];
        cJSON *set;
        root = cJSON_CreateObject();
        cJSON_AddStringToObject(root, "source", a.pos[0]);
        /* the name replay's JSON gives the input file; source kept as its
         * alias for readers of older psd JSON, where it was the only key
         * (docs/psd.md, "JSON") */
        cJSON_AddStringToObject(root, "log", a.pos[0]);
        cJSON_AddStringToObject(root, "sensor", log.meta.sensor);
        cJSON_AddNumberToObject(root, "rate_hz", rate);
        cJSON_AddNumberToObject(root, "samples", (double)log.n);
        set = cJSON_AddObjectToObject(root, "settings");
        cJSON_AddNumberToObject(set, "nfft", st.wc.nfft);
        cJSON_AddNumberToObject(set, "overlap", st.wc.overlap);
        cJSON_AddStringToObject(set, "window", st.wc.window == FNAV_WINDOW_HAMMING ? "hamming"
                                               : st.wc.window == FNAV_WINDOW_HANN  ? "hann"
                                                                                   : "rect");
        cJSON_AddBoolToObject(set, "symmetric", st.wc.symmetric);
        cJSON_AddStringToObject(set, "dc", k_dc_names[dc_mode]);
        cJSON_AddNumberToObject(set, "threshold", thr);
        cJSON_AddNumberToObject(set, "round_hz", rnd);
        cJSON_AddItemToObject(root, "result", json_result(&res));
        cJSON_AddBoolToObject(root, "fs_above_log_rate", above_rate);
        cJSON_AddBoolToObject(root, "band_at_nyquist", at_nyquist);
        {
            /* the answer as a lower bound, and that bound (null where the
             * answer is a measurement): band_at_nyquist is true also where
             * the rounding alone lifts the answer above the rate */
            double bound_hz;
            cJSON_AddBoolToObject(root, "fs_is_lower_bound", fs_lower_bound(&res, rate, &bound_hz));
            hx_json_num(root, "fs_lower_bound_hz", bound_hz);
        }
        if (hx_flag(&a, "--sensitivity")) {
            cJSON *arr = cJSON_AddArrayToObject(root, "sensitivity");
            int d, k;
            for (d = 0; d < NDC; d++) {
                for (k = 0; k < NSENS_NFFT; k++) {
                    cJSON *e;
                    if (!isfinite(fs_tab[d][k])) {
                        continue;
                    }
                    e = cJSON_CreateObject();
                    cJSON_AddStringToObject(e, "dc", k_dc_names[d]);
                    cJSON_AddNumberToObject(e, "nfft", k_sens_nfft[k]);
                    cJSON_AddNumberToObject(e, "fs_hz", fs_tab[d][k]);
                    cJSON_AddItemToArray(arr, e);
                }
            }
        }
        cJSON_AddBoolToObject(root, "complete", log.status == FNAV_END);
        if (log.status != FNAV_END) {
            /* the reader's message, as info's, replay's, allan's and
             * simgap's `error`, beside `complete` */
            cJSON_AddStringToObject(root, "error", log.error);
        }
        if (hx_write_json(hx_arg(&a, "--json"), root, err, sizeof err) != 0) {
            hx_error(CMD, "%s", err);
            exit_code = HX_EXIT_IO;
        }
        cJSON_Delete(root);
    }
    if ((s = hx_arg(&a, "--plot")) != NULL) {
        struct stat sb;
        if (stat(s, &sb) != 0 && mkdir(s, 0777) != 0) {
            hx_error(CMD, "%s: cannot create directory (%s)", s, strerror(errno));
            exit_code = HX_EXIT_IO;
        } else {
            if (spec_axis < 0) {
                /* the accelerometer axis along gravity: largest |mean| */
                double best = -1.0;
                int k;
                for (k = 0; k < 3; k++) {
                    double m = 0.0;
                    size_t i;
                    for (i = 0; i < log.n; i++) {
                        m += log.acc[i][k];
                    }
                    m = fabs(m / (double)log.n);
                    if (m > best) {
                        best = m;
                        spec_axis = k;
                    }
                }
            }
            /* a spectrogram needs two segments (50 % overlap): gnuplot has
             * nothing to draw with none, and draws nothing of an image one
             * column wide (a blank spectrogram.png) */
            const size_t two = (size_t)spec_nfft + (size_t)spec_nfft / 2u;
            const int spec = log.n >= two;
            if (log.n < (size_t)spec_nfft) {
                hx_warn(CMD, "%s: fewer samples (%zu) than one spectrogram segment (--spec-nfft %ld): spectrogram.png "
                             "not drawn",
                        a.pos[0], log.n, spec_nfft);
            } else if (!spec) {
                hx_warn(CMD, "%s: one spectrogram segment (%zu samples, --spec-nfft %ld needs %zu for two): "
                             "spectrogram.png not drawn",
                        a.pos[0], log.n, spec_nfft, two);
            }
            /* the input's name goes into the titles as a gnuplot string (a
             * bare quote in it would end the string: no plot) */
            char src[1024];
            hx_gp_str(src, sizeof src, a.pos[0]);
            if (plot_psd(s, &res, src, &st) != 0 || plot_ccdf(s, &res, src, &bc) != 0 ||
                (spec && plot_spectrogram(s, &log, spec_axis, (uint32_t)spec_nfft, rate, src) != 0) ||
                (hx_flag(&a, "--sensitivity") && plot_sensitivity(s, fs_tab, have, rate, src) != 0)) {
                exit_code = HX_EXIT_IO;
            }
        }
    }
    if (log.status != FNAV_END) {
        /* the reader's message was warned when the input was read
         * (hx_load_input()); the log named, as in that warning */
        hx_error(CMD, "%s: incomplete input (warned above): the results cover the %zu sample%s before the error",
                 a.pos[0], log.n, log.n == 1 ? "" : "s");
    }
    hx_log_free(&log);
    return exit_code;
}
