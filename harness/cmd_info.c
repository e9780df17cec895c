/* harness info: what a log contains and how healthy its timing is. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_nav.h"

static const hx_opt_t k_opts[] = {
    HX_INPUT_OPTS,
    { "--json", "FILE", "also write the figures as JSON", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "info", "LOG [options]",
    "Print the format, sensor, sample rate, duration, timing health (median\n"
    "interval, gaps > 1.5 intervals, duplicated time stamps, counter drops),\n"
    "saturation (flat-topped channel extremes), the peak rates and forces, and\n"
    "the gravity vector in the stillest second (its axis and magnitude).",
    1, 1, k_opts
};

static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

typedef struct {
    double rate_hz, dt_med_s, dt_min_s, dt_max_s, duration_s;
    double rate_chg_at_s, rate_chg_hz, rate_off; /* hx_rate_changes */
    long gaps, dups, drops;
    long backwards;        /* steps back of the sensor counter (seq), which the drops leave out */
    size_t back_first;     /* the first of them: the sample whose seq is below its predecessor's */
    double max_gap_s;
    long sat[6];
    double peak[6];
    double g_vec[3], g_mag, still_t_s, gyro_rest[3];
    double still_spread; /* the stillest second's spread of f over its mean |f| (INFO_STILL_SPREAD) */
    double still_sd_mps2; /* that spread in m/s^2 */
    int no_axis;          /* |f| there under HX_NO_GRAVITY_MPS2: no gravity axis to name */
    int no_gravity;       /* not still, |f| and its spread there both under HX_NO_GRAVITY_MPS2 */
    int still;           /* that second is still: its |f| is the rest value the units check reads */
    int g_axis;
    int units_bad;     /* not SI units (hx_units_problem) */
    char units[768];   /* why, and the remedy */
    double gyro_max;   /* the largest |w| on one axis (the units check's) */
    long gyro_glitches; /* samples past the navigator's gyro range taken for glitches (hx_gyro_glitches) */
    double gyro_glitch_max; /* the largest |w| among them */
    int empty;         /* no sample (report_empty): every figure but rate_hz is null in the JSON */
} info_t;

/* Clipping at full scale leaves flat tops at the channel's extreme value,
 * again at every impact; a natural maximum is one event. The rule (two
 * separate runs of two or more samples with distinct stamps exactly at a
 * channel's maximum or minimum, the extremes more than HX_SAT_SPAN_NOISE
 * times the channel's noise at rest apart) is replay's hx_sat_t, fed the
 * samples as replay reads them, so that the two commands give the same
 * counts; the peaks are the log's own values. */
static void saturation(const hx_log_t *log, long sat[6], double peak[6])
{
    hx_sat_t st;
    size_t i;
    int c;
    memset(&st, 0, sizeof st);
    for (c = 0; c < 6; c++) {
        peak[c] = 0.0;
    }
    for (i = 0; i < log->n; i++) {
        fnav_sample_t s;
        hx_log_sample(log, i, &s);
        hx_sat_push(&st, &s);
        for (c = 0; c < 6; c++) {
            const double v = fabs(c < 3 ? log->acc[i][c] : log->gyr[i][c - 3]);
            peak[c] = v > peak[c] ? v : peak[c];
        }
    }
    for (c = 0; c < 6; c++) {
        sat[c] = hx_sat_count(&st, c);
    }
}

/* The stillest second is a rest when its specific force spreads (the
 * root of the summed per-axis variances) by less than this fraction of its
 * mean |f|: at most 0.017 over the 69 logs of ../shared/data (0.0044 on
 * vectors/walk.bin), 0.34 to 2.6 where a simulated walk or run has no rest
 * (bin/harness sim --motion walk:20, run:20, walk:20 --cadence 60;
 * scripts/info_still_spread.py, docs/harness.md "info"). A
 * ratio, so that a log in g or mg is judged as one in m/s^2; the gyro is
 * left out, since its unit is what the check may find wrong (a still gyro
 * in deg/s spreads by tenths of a "rad/s"). Taking any stillest second for
 * a rest, a walk without one would be told its accelerometer was not in
 * m/s^2 (|f| = 13.8 mid-stride). */
#define INFO_STILL_SPREAD 0.1

static void analyse(const hx_log_t *log, info_t *in)
{
    size_t i, n = log->n, nd = 0;
    int64_t *dt = NULL;
    int c;
    memset(in, 0, sizeof *in);
    in->rate_hz = log->meta.rate_hz;
    if (n >= 2) {
        dt = (int64_t *)malloc((n - 1) * sizeof *dt);
    }
    if (dt != NULL) {
        size_t nz = 0;
        int64_t res = 0; /* the stamps' resolution: gcd of the intervals that advance */
        double gap_s;
        for (i = 1; i < n; i++) {
            int64_t d = log->t_ns[i] - log->t_ns[i - 1];
            dt[nd++] = d;
            nz += d <= 0;
            if (d > 0) {
                res = hx_gcd_i64(d, res);
            }
        }
        qsort(dt, nd, sizeof *dt, cmp_i64);
        /* the median of the intervals that advance (duplicated stamps are
         * counted apart: a log of mostly duplicates had a median of 0, and
         * every real interval was a gap) */
        in->dt_med_s = 1e-9 * (double)dt[nz < nd ? nz + (nd - nz) / 2 : nd / 2];
        in->dt_min_s = 1e-9 * (double)dt[0];
        in->dt_max_s = 1e-9 * (double)dt[nd - 1];
        free(dt);
        /* a gap: an interval over 1.5 periods. Stamps that resolve the
         * period (1/1000 of the median interval or finer) give it as the
         * median interval. Coarser ones show only a few values (an 820 Hz
         * log stamped to the millisecond reads 1 and 2 ms, median 1 ms, and
         * a fifth of its intervals, with no sample lost, would be gaps by
         * the median): the period is that of the rate estimated from them
         * (hx_stamp_rate_hz) and, unless it is a whole number of
         * resolutions, an interval of one period reads up to a resolution
         * longer (the same threshold as hx_stamp_rate_hz's) */
        gap_s = 1.5 * in->dt_med_s;
        if (res > 0 && 1000.0 * (double)res > 1e9 * in->dt_med_s && in->rate_hz > 0.0) {
            const double per = 1e9 / in->rate_hz, q = (double)res;
            gap_s = 1.5 * per;
            if (fabs(per / q - floor(per / q + 0.5)) > 0.05) {
                gap_s += q;
            }
            gap_s *= 1e-9;
        }
        for (i = 1; i < n; i++) {
            double d = 1e-9 * (double)(log->t_ns[i] - log->t_ns[i - 1]);
            if (d == 0.0) {
                in->dups++;
            } else if (d > gap_s) {
                in->gaps++;
                in->max_gap_s = d > in->max_gap_s ? d : in->max_gap_s;
            }
            if (log->meta.has_seq) {
                uint32_t ds = log->seq[i] - log->seq[i - 1];
                if (ds > 1u && ds < 0x80000000u) {
                    in->drops += (long)(ds - 1u);
                } else if (ds >= 0x80000000u) {
                    /* below the last by up to half the range (a wrap of a
                     * counter reads as a small step forward): out of order,
                     * or the counter restarted */
                    if (in->backwards++ == 0) {
                        in->back_first = i;
                    }
                }
            }
        }
        if (in->rate_hz <= 0.0 && in->dt_med_s > 0.0) {
            in->rate_hz = 1.0 / in->dt_med_s;
        }
    }
    in->duration_s = n > 0 ? 1e-9 * (double)(log->t_ns[n - 1] - log->t_ns[0]) : 0.0;
    in->rate_off = hx_rate_changes(log->t_ns, n, sizeof log->t_ns[0], in->rate_hz, &in->rate_chg_at_s,
                                   &in->rate_chg_hz);
    saturation(log, in->sat, in->peak);
    /* stillest window of about one second: least gyro energy + accel variance */
    {
        size_t w = (size_t)(in->rate_hz > 0.0 ? in->rate_hz : 100.0);
        size_t best = 0, start;
        double best_cost = INFINITY;
        if (w < 2) {
            w = 2;
        }
        if (w > n) {
            w = n;
        }
        for (start = 0; start + w <= n && w > 0; start += w / 2 > 0 ? w / 2 : 1) {
            double sa[3] = { 0, 0, 0 }, sa2 = 0.0, sg = 0.0, cost;
            size_t k;
            for (k = start; k < start + w; k++) {
                for (c = 0; c < 3; c++) {
                    sa[c] += log->acc[k][c];
                    sa2 += log->acc[k][c] * log->acc[k][c];
                    sg += log->gyr[k][c] * log->gyr[k][c];
                }
            }
            cost = sg / (double)w + (sa2 - (sa[0] * sa[0] + sa[1] * sa[1] + sa[2] * sa[2]) / (double)w) / (double)w;
            if (cost < best_cost) {
                best_cost = cost;
                best = start;
            }
        }
        if (w > 0) {
            size_t k;
            for (k = best; k < best + w; k++) {
                for (c = 0; c < 3; c++) {
                    in->g_vec[c] += log->acc[k][c] / (double)w;
                    in->gyro_rest[c] += log->gyr[k][c] / (double)w;
                }
            }
            in->g_mag = sqrt(in->g_vec[0] * in->g_vec[0] + in->g_vec[1] * in->g_vec[1] + in->g_vec[2] * in->g_vec[2]);
            in->g_axis = 0;
            for (c = 1; c < 3; c++) {
                if (fabs(in->g_vec[c]) > fabs(in->g_vec[in->g_axis])) {
                    in->g_axis = c;
                }
            }
            in->still_t_s = 1e-9 * (double)(log->t_ns[best] - log->t_ns[0]);
            {
                double var = 0.0;
                for (k = best; k < best + w; k++) {
                    for (c = 0; c < 3; c++) {
                        const double d = log->acc[k][c] - in->g_vec[c];
                        var += d * d / (double)w;
                    }
                }
                in->still_sd_mps2 = sqrt(var);
                in->still_spread = in->g_mag > 0.0 ? in->still_sd_mps2 / in->g_mag : HUGE_VAL;
                in->still = in->still_spread < INFO_STILL_SPREAD;
                /* an accelerometer that reads about 0 (gravity removed, or a
                 * dead one writing zeros): no gravity axis to name (it said
                 * "gravity along -x" and, at exactly 0, a spread of "inf %"
                 * without the no-gravity line) */
                in->no_axis = in->g_mag < HX_NO_GRAVITY_MPS2;
                in->no_gravity = !in->still && in->no_axis && in->still_sd_mps2 < HX_NO_GRAVITY_MPS2;
            }
        }
    }
    {
        double wmax = in->peak[3] > in->peak[4] ? in->peak[3] : in->peak[4];
        hx_csv_layout_t lay, lay_t; /* the remedies name --units for the interchange CSV, as replay's */
        const hx_csv_layout_t *csv = hx_units_layout(log->meta.format, &lay);
        wmax = wmax > in->peak[5] ? wmax : in->peak[5];
        {
            /* a few samples past any gyro's range are glitches, which the
             * navigator refuses: the units are judged on the others, as
             * replay judges them (one spike of 300 rad/s was told "probably
             * in deg/s" here while replay named it a glitch) */
            long n_over = 0;
            double w_in = 0.0;
            for (i = 0; i < n; i++) {
                double m = 0.0;
                for (c = 0; c < 3; c++) {
                    m = fabs(log->gyr[i][c]) > m ? fabs(log->gyr[i][c]) : m;
                }
                if (m > FNAV_NAV_GYRO_MAX_RPS) {
                    n_over++;
                } else if (m > w_in) {
                    w_in = m;
                }
            }
            if (hx_gyro_glitches(n_over, (long)n)) {
                in->gyro_glitches = n_over; /* warned by the caller */
                in->gyro_glitch_max = wmax;
                wmax = w_in;
            }
        }
        in->gyro_max = wmax;
        /* the rate is not judged here: a static log for the Allan variance
         * may be slow; but the remedy names the time item of the warning
         * on a slow log too (one --units value: a second replaces the first) */
        hx_walk_t walk; /* the walk a gyro read as deg/s below a foot's rates needs, as replay's */
        memset(&walk, 0, sizeof walk);
        for (i = 0; i < n; i++) {
            hx_walk_push(&walk, log->t_ns[i],
                         sqrt(log->acc[i][0] * log->acc[i][0] + log->acc[i][1] * log->acc[i][1] +
                              log->acc[i][2] * log->acc[i][2]));
        }
        /* no rest, no |f| at rest to judge (0: not known); the gyro's marks need none */
        in->units_bad = hx_units_problem(in->still ? in->g_mag : 0.0, 9.80665, wmax, 0.0,
                                         log->meta.rate_nominal
                                             ? csv
                                             : hx_time_unit_layout(hx_log_time_unit_rate(log, in->rate_hz), csv, &lay_t),
                                         hx_walk_seen(&walk), in->units, sizeof in->units);
    }
}

/* A figure, or null for a log with no sample to make it (in->empty) */
static void add_num(cJSON *j, const char *name, double v, const info_t *in)
{
    if (in->empty) {
        cJSON_AddNullToObject(j, name);
    } else {
        cJSON_AddNumberToObject(j, name, v);
    }
}

/* A .bin header's source (docs/log-format.md): the command that wrote
 * the file (`harness sim --motion walk --seed 1`, `harness live`, ...) or
 * the file a conversion read; NULL for another format (whose reader puts
 * the path there) or an empty field. Control characters were read as '?'. */
static const char *bin_source(const hx_meta_t *meta)
{
    return meta->format == HX_FMT_BIN && meta->source[0] != '\0' ? meta->source : NULL;
}

static void print_source(const hx_meta_t *meta)
{
    if (bin_source(meta) != NULL) {
        printf("source      %s\n", meta->source);
    }
}

/* info's JSON, for a log and for one that holds no sample (in->empty:
 * report_empty's, the same keys with the figures null, from this one
 * function rather than a list of its keys kept by hand) */
static int write_json(const char *path, const hx_log_t *log, const info_t *in)
{
    cJSON *j = cJSON_CreateObject();
    cJSON *arr;
    char err[HX_ERR_SIZE];
    int c, rc;
    static const char *const ch[6] = { "ax", "ay", "az", "gx", "gy", "gz" };
    cJSON_AddStringToObject(j, "format", hx_format_name(log->meta.format));
    cJSON_AddStringToObject(j, "sensor", log->meta.sensor);
    if (bin_source(&log->meta) != NULL) {
        cJSON_AddStringToObject(j, "source", log->meta.source);
    } else {
        cJSON_AddNullToObject(j, "source");
    }
    cJSON_AddNumberToObject(j, "samples", (double)log->n);
    cJSON_AddNumberToObject(j, "rate_hz", in->rate_hz);
    cJSON_AddBoolToObject(j, "rate_nominal", log->meta.rate_nominal);
    add_num(j, "duration_s", in->duration_s, in);
    add_num(j, "dt_median_s", in->dt_med_s, in);
    add_num(j, "dt_min_s", in->dt_min_s, in);
    add_num(j, "dt_max_s", in->dt_max_s, in);
    add_num(j, "gaps", (double)in->gaps, in);
    add_num(j, "max_gap_s", in->max_gap_s, in);
    add_num(j, "duplicates", (double)in->dups, in);
    /* null, as the text leaves its drops line out, when the format has no
     * sensor counter: a 0 would read "no drops" where none can be counted */
    if (log->meta.has_seq && !in->empty) {
        cJSON_AddNumberToObject(j, "counter_drops", (double)in->drops);
    } else {
        cJSON_AddNullToObject(j, "counter_drops");
    }
    if (log->meta.has_seq && !in->empty) {
        cJSON_AddNumberToObject(j, "counter_backwards", (double)in->backwards);
    } else {
        cJSON_AddNullToObject(j, "counter_backwards");
    }
    if (in->rate_off > 0.0 && !in->empty) {
        cJSON *chg = cJSON_AddObjectToObject(j, "rate_change");
        cJSON_AddNumberToObject(chg, "at_s", in->rate_chg_at_s);
        cJSON_AddNumberToObject(chg, "rate_hz", in->rate_chg_hz);
        cJSON_AddNumberToObject(chg, "off_fraction", in->rate_off);
    } else {
        cJSON_AddNullToObject(j, "rate_change");
    }
    if (in->empty) {
        cJSON_AddNullToObject(j, "saturated_samples");
        cJSON_AddNullToObject(j, "peak_abs");
        cJSON_AddNullToObject(j, "gravity_at_rest_mps2");
    } else {
        arr = cJSON_AddObjectToObject(j, "saturated_samples");
        for (c = 0; c < 6; c++) {
            cJSON_AddNumberToObject(arr, ch[c], (double)in->sat[c]);
        }
        arr = cJSON_AddObjectToObject(j, "peak_abs");
        for (c = 0; c < 6; c++) {
            cJSON_AddNumberToObject(arr, ch[c], in->peak[c]);
        }
        cJSON_AddItemToObject(j, "gravity_at_rest_mps2", cJSON_CreateDoubleArray(in->g_vec, 3));
    }
    add_num(j, "gravity_magnitude_mps2", in->g_mag, in);
    if (in->empty || in->no_axis) {
        cJSON_AddNullToObject(j, "gravity_axis");
        cJSON_AddNullToObject(j, "up_axis");
    }
    if (in->empty) {
        cJSON_AddNullToObject(j, "gyro_at_rest_rps");
    } else {
        /* the accelerometer reads the specific force, which points up at
         * rest: gravity lies along the other sign (frames.md) */
        char up[3] = { in->g_vec[in->g_axis] >= 0.0 ? '+' : '-', (char)('x' + in->g_axis), '\0' };
        char down[3] = { in->g_vec[in->g_axis] >= 0.0 ? '-' : '+', (char)('x' + in->g_axis), '\0' };
        if (!in->no_axis) {
            cJSON_AddStringToObject(j, "gravity_axis", down);
            cJSON_AddStringToObject(j, "up_axis", up);
        }
        cJSON_AddItemToObject(j, "gyro_at_rest_rps", cJSON_CreateDoubleArray(in->gyro_rest, 3));
    }
    if (in->units_bad && !in->empty) {
        cJSON_AddStringToObject(j, "units_problem", in->units);
    } else {
        cJSON_AddNullToObject(j, "units_problem");
    }
    add_num(j, "still_window_start_s", in->still_t_s, in);
    /* whether that window is a rest (INFO_STILL_SPREAD): without one the
     * accelerometer's units are not checked, and units_problem's null
     * says only that the gyro's look SI */
    if (in->empty) {
        cJSON_AddNullToObject(j, "still_found");
    } else {
        cJSON_AddBoolToObject(j, "still_found", in->still);
    }
    cJSON_AddBoolToObject(j, "complete", log->status == FNAV_END);
    if (log->status != FNAV_END) {
        cJSON_AddStringToObject(j, "error", log->error);
    }
    rc = hx_write_json(path, j, err, sizeof err);
    cJSON_Delete(j);
    if (rc != 0) {
        hx_error("info", "%s", err);
    }
    return rc;
}

/* The rate line's figure: three decimals, and below 0.1 Hz as many more as
 * keep three significant digits, where three decimals would print a log of
 * one sample per 83 min (0.0002 Hz) as "0.000 Hz"
 * (tests/cli/test_foundation.sh); from 0.1 Hz three decimals */
static const char *rate_str(double hz, char *buf, size_t size)
{
    int dec = 3;
    double x;
    for (x = hz; x > 0.0 && x < 0.1 && dec < 15; x *= 10.0) {
        dec++;
    }
    snprintf(buf, size, "%.*f", dec, hz);
    return buf;
}

/* A log that opens (a valid .bin header, a CSV header) but holds no sample:
 * hx_load_input has said why (the reader's error) and kept nothing; a
 * report and the JSON still follow. The file is
 * opened again, quietly, for what its header says (format, sensor, a
 * stated rate), and the report and the JSON say that it holds no sample;
 * exit 1 (bad or incomplete input). -1 when it does not open (a bad
 * header, a missing file: the error said so). */
static int report_empty(const hx_args_t *a, const char *path)
{
    const char *from = hx_arg(a, "--from");
    const char *json = hx_arg(a, "--json");
    hx_format_t fmt = from != NULL ? hx_format_from_name(from) : HX_FMT_AUTO;
    double in_rate = 0.0;
    char err[HX_ERR_SIZE], why[HX_ERR_SIZE];
    hx_reader_t *r;
    hx_meta_t meta;
    fnav_sample_t s;
    char hz[32];
    int rc = HX_EXIT_DATA;
    /* the options were checked by hx_check_input_opts: no message here */
    if (hx_arg(a, "--input-rate") != NULL && hx_arg_double(a, "--input-rate", 1e-3, 1e6, &in_rate) != 0) {
        return -1;
    }
    r = hx_reader_open(path, fmt, in_rate, err, sizeof err);
    if (r == NULL) {
        return -1;
    }
    meta = *hx_reader_meta(r);
    if (hx_reader_next(r, &s) == FNAV_OK) {
        hx_reader_close(r); /* a sample after all: the file changed; the error stands */
        return -1;
    }
    snprintf(why, sizeof why, "%s", hx_reader_error(r));
    hx_reader_close(r);
    {
        char shown[4096]; /* a file name's control characters as '?' (hx_line_str), as in the messages */
        printf("file        %s\n", hx_line_str(shown, sizeof shown, path));
    }
    printf("format      %s\n", hx_format_name(meta.format));
    printf("sensor      %s\n", meta.sensor);
    print_source(&meta);
    if (meta.axes[0]) {
        printf("axes        %s\n", meta.axes);
    }
    printf("samples     0 (the file holds no sample: nothing to analyse)\n");
    if (meta.rate_nominal && meta.rate_hz > 0.0) {
        printf("rate        %s Hz (nominal)\n", rate_str(meta.rate_hz, hz, sizeof hz));
    } else {
        printf("rate        none (no sample gives no rate)\n");
    }
    printf("incomplete  %s\n", why);
    if (json != NULL) {
        /* info's JSON with no sample: the figures null, the stated rate or 0 */
        static hx_log_t log; /* static: a few kB, zeroed */
        info_t in;
        memset(&log, 0, sizeof log);
        memset(&in, 0, sizeof in);
        log.meta = meta;
        log.status = FNAV_E_FORMAT; /* not FNAV_END: "complete" false, the error given */
        snprintf(log.error, sizeof log.error, "%s", why);
        in.empty = 1;
        in.rate_hz = meta.rate_nominal && meta.rate_hz > 0.0 ? meta.rate_hz : 0.0;
        if (write_json(json, &log, &in) != 0) {
            rc = HX_EXIT_IO;
        }
    }
    return rc;
}

int hx_cmd_info(int argc, char **argv)
{
    hx_args_t a;
    hx_log_t log;
    info_t in;
    int rc = hx_args_parse(&k_spec, argc, argv, &a);
    int c, exit_code = HX_EXIT_OK;
    char hz[32];
    static const char *const ch[6] = { "ax", "ay", "az", "gx", "gy", "gz" };
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    if (hx_check_input_opts("info", &a) != 0) {
        return HX_EXIT_USAGE;
    }
    {
        static const char *const outs[] = { "--json", NULL };
        if (hx_output_is_input("info", a.pos[0], &a, outs)) {
            return HX_EXIT_USAGE;
        }
    }
    rc = hx_load_input("info", &a, a.pos[0], &log);
    if (rc < 0) {
        const int e = report_empty(&a, a.pos[0]);
        return e < 0 ? HX_EXIT_DATA : e;
    }
    analyse(&log, &in);
    if (in.backwards > 0) {
        /* a timing fault as a gap or a drop is, but one the drops do not
         * count: said on standard error as well, where a script sees it */
        hx_warn("info", "%s: the sensor counter steps back %ld time%s (first at sample %zu, t = %.3f s: %lu after "
                        "%lu): samples out of order, or the counter restarted; the drops count only its steps forward",
                a.pos[0], in.backwards, in.backwards == 1 ? "" : "s", in.back_first + 1u,
                1e-9 * (double)(log.t_ns[in.back_first] - log.t_ns[0]), (unsigned long)log.seq[in.back_first],
                (unsigned long)log.seq[in.back_first - 1u]);
    }
    if (in.gyro_glitches > 0) {
        hx_warn("info", "%s: %ld sample%s read a rate past any MEMS gyro's range (%.0f rad/s on an axis; the largest "
                        "%.4g rad/s) among %ld within it: glitches of the sensor or its link, which the navigator "
                        "rejects; the units line judges the others (docs/robustness.md)",
                a.pos[0], in.gyro_glitches, in.gyro_glitches == 1 ? "" : "s", FNAV_NAV_GYRO_MAX_RPS,
                in.gyro_glitch_max, (long)log.n - in.gyro_glitches);
    }
    {
        /* time stamps in milliseconds make a 100 Hz log 0.1 Hz: said as
         * allan and psd say it (a warning: a static log may be slow), not
         * the rate without a word */
        char hint[256];
        hx_csv_layout_t lay, lay_w; /* with the unit items of the units line (one --units value) */
        if (!log.meta.rate_nominal &&
            hx_time_unit_hint(hx_log_time_unit_rate(&log, in.rate_hz), /* no hint for stamps in bursts */
                              hx_units_want(hx_units_layout(log.meta.format, &lay), in.still ? in.g_mag : 0.0, 9.80665,
                                            in.gyro_max,
                                            &lay_w),
                              hint, sizeof hint)) {
            hx_warn("info", "%s: %s", a.pos[0], hint);
        }
    }
    if (!hx_nav_bursts_warn("info", a.pos[0], log.meta.format, log.t_ns, log.n, 0, "the rate line gives", in.rate_hz,
                            log.meta.rate_nominal && log.meta.rate_hz > 0.0)) {
        /* a stated rate the stamps contradict (the rate line prints it) */
        hx_stated_rate_warn("info", a.pos[0], &log.meta, log.t_ns, log.n,
                            "the rate line and the one-second windows of the search for the rest take");
    }
    {
        char shown[4096]; /* a file name's control characters as '?' (hx_line_str), as in the messages */
        printf("file        %s\n", hx_line_str(shown, sizeof shown, a.pos[0]));
    }
    printf("format      %s\n", hx_format_name(log.meta.format));
    printf("sensor      %s\n", log.meta.sensor);
    print_source(&log.meta);
    if (log.meta.axes[0]) {
        printf("axes        %s\n", log.meta.axes);
    }
    {
        /* the column or flag alone is no temperature: one read, or none */
        size_t i, nt = 0;
        for (i = 0; i < log.n && log.meta.has_temp && log.temp != NULL && nt == 0; i++) {
            nt += log.temp[i] == log.temp[i]; /* NaN: none read */
        }
        printf("samples     %zu%s\n", log.n,
               !log.meta.has_temp ? "" : nt > 0 ? " (with temperature)" : " (no temperature: every value empty)");
    }
    if (log.meta.rate_nominal || in.rate_hz > 0.0) {
        /* which stamps, and how: replay's detector and --rate take other
         * estimates (199.44 and 200.1 Hz for a vicon trial that reads 200.000
         * here) */
        printf("rate        %s Hz (%s)\n", rate_str(in.rate_hz, hz, sizeof hz),
               log.meta.rate_nominal ? "nominal"
               : log.meta.rate_hz <= 0.0 ? "from the time stamps: 1 / the median interval"
               : log.meta.rate_coarse ? "from the time stamps of the first 4,096 samples: their mean interval without gaps"
                                      : "from the time stamps of the first 4,096 samples: 1 / their median interval");
    } else {
        /* no interval that advances, no rate, not "0.000 Hz (from the time
         * stamps)" */
        printf("rate        none (%s)\n", log.n < 2 ? "one sample gives no rate" : "every time stamp is the same");
    }
    printf("duration    %.3f s\n", in.duration_s);
    if (log.n < 2) {
        printf("interval    none (one sample)\n");
    } else {
        printf("interval    median %.3f ms, min %.3f ms, max %.3f ms\n", 1e3 * in.dt_med_s, 1e3 * in.dt_min_s,
               1e3 * in.dt_max_s);
    }
    printf("gaps        %ld (> 1.5 intervals; longest %.1f ms)\n", in.gaps, 1e3 * in.max_gap_s);
    printf("duplicates  %ld (time stamp repeated, dt = 0)\n", in.dups);
    if (in.rate_off > 0.0) {
        printf("rate change %.1f Hz from %.1f s, %.0f %% of the log off %.1f Hz (replay's detector keeps the first "
               "rate: docs/navigation.md, \"Timing\")\n",
               in.rate_chg_hz, in.rate_chg_at_s, 100.0 * in.rate_off, in.rate_hz);
    }
    if (log.meta.has_seq) {
        printf("drops       %ld (missing sensor counter values)\n", in.drops);
    }
    if (in.backwards > 0) {
        printf("counter     steps back %ld time%s, first at sample %zu (t = %.3f s: %lu after %lu)\n", in.backwards,
               in.backwards == 1 ? "" : "s", in.back_first + 1u,
               1e-9 * (double)(log.t_ns[in.back_first] - log.t_ns[0]), (unsigned long)log.seq[in.back_first],
               (unsigned long)log.seq[in.back_first - 1u]);
    }
    printf("saturation ");
    for (c = 0; c < 6; c++) {
        printf(" %s %ld", ch[c], in.sat[c]);
    }
    printf("\npeak        |a| %.2f %.2f %.2f g, |w| %.1f %.1f %.1f deg/s\n", in.peak[0] / 9.80665,
           in.peak[1] / 9.80665, in.peak[2] / 9.80665, in.peak[3] * 57.29577951308232, in.peak[4] * 57.29577951308232,
           in.peak[5] * 57.29577951308232);
    /* f at rest is the specific force, -g: it points up, gravity down */
    if (in.no_axis) {
        printf("at rest     no gravity axis: |f| = %.4f m/s^2 (%.4f g), f = (%.4f, %.4f, %.4f) m/s^2 at t = %.1f s\n",
               in.g_mag, in.g_mag / 9.80665, in.g_vec[0], in.g_vec[1], in.g_vec[2], in.still_t_s);
    } else {
        printf("at rest     gravity along %c%c (%c%c up), |f| = %.4f m/s^2 (%.4f g), f = (%.4f, %.4f, %.4f) m/s^2 at "
               "t = %.1f s\n",
               in.g_vec[in.g_axis] >= 0.0 ? '-' : '+', 'x' + in.g_axis, in.g_vec[in.g_axis] >= 0.0 ? '+' : '-',
               'x' + in.g_axis, in.g_mag, in.g_mag / 9.80665, in.g_vec[0], in.g_vec[1], in.g_vec[2], in.still_t_s);
    }
    /* in deg/s as well, the unit of the peak line and of a data sheet's bias */
    printf("            gyro (%.5f, %.5f, %.5f) rad/s = (%.3f, %.3f, %.3f) deg/s\n", in.gyro_rest[0], in.gyro_rest[1],
           in.gyro_rest[2], in.gyro_rest[0] * 57.29577951308232, in.gyro_rest[1] * 57.29577951308232,
           in.gyro_rest[2] * 57.29577951308232);
    if (!in.still && in.g_mag > 0.0) { /* at |f| = 0 no ratio: the no-gravity line says the spread */
        printf("            not still: f spreads by %.0f %% of its mean |f| in that second (a rest: below %.0f %%)\n",
               100.0 * in.still_spread, 100.0 * INFO_STILL_SPREAD);
    }
    if (in.no_gravity && in.g_mag == 0.0 && in.still_sd_mps2 == 0.0) {
        /* every axis exactly 0 for a second: no sensor reads that */
        printf("            no gravity: f is exactly 0 on every axis in the quietest second: an accelerometer "
               "disabled, or not written by the logger? replay needs its reading, the specific force\n");
    } else if (in.no_gravity) {
        /* the quietest second near 0 m/s^2 and quiet in m/s^2: no gravity,
         * not a rest that moved (replay names it too: hx_nav.c) */
        printf("            no gravity: |f| %.4f m/s^2 and its spread %.4f m/s^2 in the quietest second: a linear "
               "acceleration (gravity removed)? replay needs the accelerometer's own reading, the specific force\n",
               in.g_mag, in.still_sd_mps2);
    }
    if (in.units_bad) {
        printf("units       NOT SI: %s%s\n", in.units,
               in.still ? "" : " (no still second found: the accelerometer's units not checked)");
    } else if (!in.still) {
        printf("units       no still second found: units not checked (the accelerometer's is read at rest; the "
               "gyro's range found nothing wrong)\n");
    }
    if (log.status != FNAV_END) {
        printf("incomplete  %s\n", log.error);
        exit_code = HX_EXIT_DATA;
    }
    if (hx_arg(&a, "--json") != NULL && write_json(hx_arg(&a, "--json"), &log, &in) != 0) {
        exit_code = HX_EXIT_IO;
    }
    if (log.status != FNAV_END) {
        /* the reader's message was warned when the input was read
         * (hx_load_input()); the log named, as in that warning */
        hx_error("info", "%s: incomplete input (warned above): the results cover the %zu sample%s before the error",
                 a.pos[0], log.n, log.n == 1 ? "" : "s");
    }
    hx_log_free(&log);
    return exit_code;
}
