/* Xsens MT Manager's ASCII export (format mtmanager): detection, the
 * preamble, the columns and each row's time (see hx_xsens.h and
 * docs/log-format.md, "MT Manager export"). hx_log.c reads the lines. */
#include "hx_xsens.h"
#include "hx_log.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Whether a name starts with prefix, without regard to case (after leading
 * blanks and quotes). */
static int name_starts(const char *a, const char *prefix)
{
    while (*a == ' ' || *a == '\t' || *a == '"' || *a == '\'') {
        a++;
    }
    for (; *prefix != '\0'; a++, prefix++) {
        if (tolower((unsigned char)*a) != tolower((unsigned char)*prefix)) {
            return 0;
        }
    }
    return 1;
}

/* Whether the len characters at s hold needle, without regard to case. */
static int holds(const char *s, size_t len, const char *needle)
{
    const size_t n = strlen(needle);
    size_t i, k;
    for (i = 0; i + n <= len; i++) {
        for (k = 0; k < n; k++) {
            if (tolower((unsigned char)s[i + k]) != tolower((unsigned char)needle[k])) {
                break;
            }
        }
        if (k == n) {
            return 1;
        }
    }
    return 0;
}

/* The keys of MT Manager's own comment lines (the general, device and
 * settings information it writes before the header). */
static int preamble_key(const char *s, size_t len)
{
    static const char *const keys[] = { "MT Manager", "XDA", "Update Rate", "Filter Profile", "DeviceId",
                                        "ProductCode" };
    size_t i;
    for (i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        if (holds(s, len, keys[i])) {
            return 1;
        }
    }
    return 0;
}

/* Whether one header line (len characters at s) names a counter and the
 * inertial columns: PacketCounter or SampleTimeFine, and Acc_X and Gyr_X or
 * increments (dq_, dv). Fields are separated by tabs, commas, semicolons or
 * blanks. A header naming Euler_X or Quat_W is Movella DOT's CSV, not MT
 * Manager's (which writes Roll, Pitch, Yaw and Quat_q0..q3): DOT counts
 * SampleTimeFine in us and writes Gyr_* in deg/s (DOT user manual, XD0502P,
 * 4.2.5), so it is left to the CSV reader's --columns and --units. */
static int header_line(const char *s, size_t len)
{
    int counter = 0, acc = 0, gyr = 0, inc = 0, dot = 0;
    size_t i = 0;
    while (i < len) {
        char tok[40];
        size_t k = 0;
        while (i < len && (s[i] == '\t' || s[i] == ',' || s[i] == ';' || s[i] == ' ' || s[i] == '\r')) {
            i++;
        }
        while (i < len && s[i] != '\t' && s[i] != ',' && s[i] != ';' && s[i] != ' ' && s[i] != '\r') {
            if (k + 1 < sizeof tok) {
                tok[k++] = s[i];
            }
            i++;
        }
        tok[k] = '\0';
        counter |= hx_name_eq(tok, "PacketCounter") || hx_name_eq(tok, "SampleTimeFine");
        acc |= hx_name_eq(tok, "Acc_X");
        gyr |= hx_name_eq(tok, "Gyr_X");
        inc |= name_starts(tok, "dq_") || name_starts(tok, "dv[") || name_starts(tok, "dv_");
        dot |= hx_name_eq(tok, "Euler_X") || hx_name_eq(tok, "Quat_W");
    }
    return counter && ((acc && gyr) || inc) && !dot;
}

int hx_mtmgr_detect(const char *text)
{
    const char *p = text;
    int keys = 0;
    for (;;) {
        const char *e;
        size_t len;
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') {
            p++;
        }
        if (*p == '\0') {
            return keys; /* the header lies beyond the text seen */
        }
        e = strchr(p, '\n');
        len = e != NULL ? (size_t)(e - p) : strlen(p);
        if (p[0] != '/' || p[1] != '/') {
            return keys || header_line(p, len);
        }
        keys |= preamble_key(p, len);
        if (e == NULL) {
            return keys;
        }
        p = e + 1;
    }
}

void hx_mtmgr_init(hx_mtmgr_t *x)
{
    int i;
    memset(x, 0, sizeof *x);
    x->col_ctr = -1;
    x->col_stf = -1;
    for (i = 0; i < 3; i++) {
        x->col_acc[i] = -1;
        x->col_gyr[i] = -1;
    }
}

int hx_mtmgr_comment(hx_mtmgr_t *x, const char *line, long lineno)
{
    const char *p = line, *v;
    while (*p == ' ' || *p == '\t') {
        p++;
    }
    if (p[0] != '/' || p[1] != '/') {
        return 0;
    }
    p += 2;
    x->comments++;
    while (*p == ' ' || *p == '\t') {
        p++;
    }
    v = strchr(p, ':');
    if (v == NULL) {
        return 1;
    }
    v++;
    while (*v == ' ' || *v == '\t') {
        v++;
    }
    if (name_starts(p, "Update Rate")) {
        /* "Update Rate: 100.0Hz", "Update Rate: 40 Hz" */
        char *end;
        const double hz = strtod(v, &end);
        while (*end == ' ') {
            end++;
        }
        if (end != v && hz > 0.0 && hz < 1.0e6 && (tolower((unsigned char)end[0]) == 'h') &&
            tolower((unsigned char)end[1]) == 'z') {
            x->stated_hz = hz;
            x->stated_line = lineno;
        }
    } else if (name_starts(p, "ProductCode")) {
        size_t k = 0;
        while (v[k] != '\0' && !isspace((unsigned char)v[k]) && k + 1 < sizeof x->product) {
            x->product[k] = v[k];
            k++;
        }
        x->product[k] = '\0';
    }
    return 1;
}

/* Whether name is one of the n names of list (hx_name_eq: without case,
 * blanks or quotes). */
static int name_in(const char *name, const char *const *list, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (hx_name_eq(name, list[i])) {
            return 1;
        }
    }
    return 0;
}

/* Whether name is stem followed by one of the letters of axes. */
static int name_axis(const char *name, const char *stem, const char *axes)
{
    for (; *axes != '\0'; axes++) {
        char want[32];
        snprintf(want, sizeof want, "%s%c", stem, *axes);
        if (hx_name_eq(name, want)) {
            return 1;
        }
    }
    return 0;
}

/* Whether a header field is a name only MT Manager writes, for what a
 * Movella DOT CSV names otherwise or does not output (the names of the DOT
 * SDK's payloads; DOT user manual, XD0502P, 4.2): Roll, Pitch, Yaw (DOT:
 * Euler_X..Z), Quat_q0..q3 (DOT: Quat_W..Z), StatusWord, SampleTimeCoarse,
 * Mat[..] (the rotation matrix). DOT's own names (Euler_*, Quat_W..Z,
 * ClipCountAcc/Gyr, Cal_FreeAcc_*, FreeAcc_Compared_Result) are not looked
 * for: a DOT CSV without one and with a column of neither (an app's own)
 * would still be read in ticks at 1 to 15 Hz; the stamps tell it
 * (hx_mtmgr_stamps), and the names only what rules a DOT out. */
static int mtmgr_own_name(const char *name)
{
    static const char *const own[] = { "Roll", "Pitch", "Yaw", "StatusWord", "SampleTimeCoarse" };
    return name_in(name, own, sizeof own / sizeof own[0]) || name_axis(name, "Quat_q", "0123") ||
           name_starts(name, "Mat[");
}

int hx_mtmgr_header(hx_mtmgr_t *x, char **f, int n, char *msg, size_t msg_size)
{
    static const char *const acc[3] = { "Acc_X", "Acc_Y", "Acc_Z" };
    static const char *const gyr[3] = { "Gyr_X", "Gyr_Y", "Gyr_Z" };
    int i, inc = 0, free_acc = 0;
    x->col_ctr = hx_find_col(f, n, "PacketCounter");
    x->col_stf = hx_find_col(f, n, "SampleTimeFine");
    x->mtmgr_names = 0;
    for (i = 0; i < n; i++) {
        x->mtmgr_names |= mtmgr_own_name(f[i]);
        inc |= name_starts(f[i], "dq_") || name_starts(f[i], "dv[") || name_starts(f[i], "dv_");
        free_acc |= name_starts(f[i], "FreeAcc_");
    }
    for (i = 0; i < 6; i++) {
        const char *name = i < 3 ? acc[i] : gyr[i - 3];
        const int c = hx_find_col(f, n, name);
        if (c < 0) {
            if (inc) {
                /* the strapdown-integrated increments (MTi Family Reference
                 * Manual, 4.3.1: delta_q, delta_v), not a rate and a force */
                snprintf(msg, msg_size,
                         "header has no column '%s': the export holds orientation and velocity increments (dq_*, "
                         "dv*: the SDI output), which footnav does not integrate back; export Acc_X..Z "
                         "(acceleration, m/s^2) and Gyr_X..Z (rate of turn, rad/s) instead",
                         name);
            } else if (free_acc && i < 3) {
                snprintf(msg, msg_size,
                         "header has no column '%s': FreeAcc_* is the acceleration without gravity in the earth "
                         "frame, not the sensor's specific force; export Acc_X..Z (acceleration, m/s^2) and "
                         "Gyr_X..Z (rate of turn, rad/s)",
                         name);
            } else {
                snprintf(msg, msg_size,
                         "header has no column '%s' (an MT Manager export needs Acc_X..Z in m/s^2 and Gyr_X..Z in "
                         "rad/s)",
                         name);
            }
            return -1;
        }
        if (i < 3) {
            x->col_acc[i] = c;
        } else {
            x->col_gyr[i - 3] = c;
        }
    }
    x->ncols_needed = 0;
    for (i = 0; i < 3; i++) {
        if (x->col_acc[i] + 1 > x->ncols_needed) {
            x->ncols_needed = x->col_acc[i] + 1;
        }
        if (x->col_gyr[i] + 1 > x->ncols_needed) {
            x->ncols_needed = x->col_gyr[i] + 1;
        }
    }
    return 0;
}

int hx_mtmgr_missing(const char *field)
{
    const char *p = field;
    if (*p == '+' || *p == '-') {
        p++;
    }
    return *field == '\0' || (tolower((unsigned char)p[0]) == 'n' && tolower((unsigned char)p[1]) == 'a' &&
                              tolower((unsigned char)p[2]) == 'n' && p[3] == '\0');
}

/* the field of column c, NULL when the row has no such column or none is
 * used */
static const char *field(char **f, int n, int c)
{
    return (f != NULL && c >= 0 && c < n) ? f[c] : NULL;
}

int hx_mtmgr_choose_time(hx_mtmgr_t *x, char **f, int n, double input_hz, char *msg, size_t msg_size)
{
    const char *stf = field(f, n, x->col_stf), *ctr = field(f, n, x->col_ctr);
    const int stf_ok = f != NULL ? stf != NULL && !hx_mtmgr_missing(stf) : x->col_stf >= 0;
    const int ctr_ok = f != NULL ? ctr != NULL && !hx_mtmgr_missing(ctr) : x->col_ctr >= 0;
    x->use_ctr = ctr_ok;
    if (stf_ok) {
        x->time_src = HX_MTMGR_TIME_STF;
        x->rate_hz = x->stated_hz;
        if (x->col_stf + 1 > x->ncols_needed) {
            x->ncols_needed = x->col_stf + 1;
        }
    } else {
        x->time_src = ctr_ok ? HX_MTMGR_TIME_COUNTER : HX_MTMGR_TIME_INDEX;
        x->rate_hz = input_hz > 0.0 ? input_hz : x->stated_hz;
        if (!(x->rate_hz > 0.0)) {
            snprintf(msg, msg_size,
                     "no time stamps: SampleTimeFine %s, so the time is the %s at the rate, which no '// Update "
                     "Rate' line states: give it with --input-rate HZ",
                     x->col_stf < 0 ? "is not exported" : "is missing on the first row",
                     ctr_ok ? "PacketCounter" : "row index");
            return -1;
        }
    }
    if (ctr_ok && x->col_ctr + 1 > x->ncols_needed) {
        x->ncols_needed = x->col_ctr + 1;
    }
    return 0;
}

int hx_mtmgr_row(hx_mtmgr_t *x, char **f, int n, long line)
{
    int i, miss = 0;
    x->rows++;
    for (i = 0; i < 3 && !miss; i++) {
        miss = hx_mtmgr_missing(f[x->col_acc[i]]) || hx_mtmgr_missing(f[x->col_gyr[i]]);
    }
    if (x->time_src == HX_MTMGR_TIME_STF && x->col_stf < n) {
        miss |= hx_mtmgr_missing(f[x->col_stf]);
    }
    if (x->use_ctr && x->col_ctr < n) {
        miss |= hx_mtmgr_missing(f[x->col_ctr]);
    }
    if (miss && x->skipped++ == 0) {
        x->skipped_first = line;
    }
    return miss;
}

/* A counter field: a whole number from 0 to max (an IPOL-style "12.0"
 * too). 0, or -1. */
static int count_of(const char *s, double max, double *out)
{
    char *end;
    double v;
    if (*s == '\0' || strpbrk(s, "xX") != NULL) {
        return -1;
    }
    v = strtod(s, &end);
    if (end == s || *end != '\0' || !(v >= 0.0 && v <= max) || v != floor(v)) {
        return -1;
    }
    *out = v;
    return 0;
}

/* value + the wraps so far, a new wrap counted when the value drops by more
 * than half the range (XDA's packet stamper rule) */
static double unwrap(double v, double range, int *have, double *prev, double *wrap)
{
    if (*have && v < *prev - range / 2.0) {
        *wrap += range;
    }
    *have = 1;
    *prev = v;
    return v + *wrap;
}

int hx_mtmgr_time(hx_mtmgr_t *x, char **f, int64_t *t_ns, uint32_t *seq, int *has_seq, char *msg, size_t msg_size)
{
    double count = 0.0;
    *has_seq = 0;
    *seq = (uint32_t)(x->rows - 1);
    if (x->use_ctr) {
        double v;
        if (count_of(f[x->col_ctr], 4294967295.0, &v) != 0) {
            snprintf(msg, msg_size, "PacketCounter ('%.20s') is not a whole number from 0 to 4294967295",
                     f[x->col_ctr]);
            return -1;
        }
        /* 16 bits (a counter past them is another device's, taken as it is) */
        count = v < HX_MTMGR_CTR_WRAP ? unwrap(v, HX_MTMGR_CTR_WRAP, &x->have_ctr, &x->ctr_prev, &x->ctr_wrap) : v;
        *seq = (uint32_t)fmod(count, 4294967296.0);
        *has_seq = 1;
    }
    switch (x->time_src) {
    case HX_MTMGR_TIME_STF: {
        double v, ticks;
        if (count_of(f[x->col_stf], HX_MTMGR_STF_WRAP - 1.0, &v) != 0) {
            snprintf(msg, msg_size, "SampleTimeFine ('%.20s') is not a whole number from 0 to 4294967295",
                     f[x->col_stf]);
            return -1;
        }
        if (x->have_stf && x->stf_prev < HX_MTMGR_STF_DAY && v < x->stf_prev - HX_MTMGR_STF_DAY / 2.0) {
            /* ticks of the day past midnight (XDA's packet stamper wraps
             * the sample time at one day of 10 kHz ticks) */
            x->stf_wrap += HX_MTMGR_STF_DAY;
            x->stf_prev = v;
            ticks = v + x->stf_wrap;
        } else {
            /* ticks since power-up, a uint32 */
            ticks = unwrap(v, HX_MTMGR_STF_WRAP, &x->have_stf, &x->stf_prev, &x->stf_wrap);
        }
        /* ticks of 100 us: exact in int64 ns for 29,000 years */
        *t_ns = (int64_t)ticks * (1000000000LL / HX_MTMGR_STF_HZ);
        break;
    }
    case HX_MTMGR_TIME_COUNTER:
    case HX_MTMGR_TIME_INDEX: {
        const double k = x->time_src == HX_MTMGR_TIME_COUNTER ? count : (double)(x->rows - 1);
        const double t_s = k / x->rate_hz;
        if (!(t_s < 9.0e9)) {
            snprintf(msg, msg_size, "time of count %.0f at %g Hz is out of range", k, x->rate_hz);
            return -1;
        }
        *t_ns = (int64_t)floor(t_s * 1.0e9 + 0.5);
        break;
    }
    }
    return 0;
}

int hx_mtmgr_peek(hx_mtmgr_t *x, char **f, int n)
{
    const char *s = field(f, n, x->col_stf);
    double v;
    if (x->npeek >= HX_MTMGR_PEEK_ROWS) {
        return 0;
    }
    x->peek[x->npeek++] = s != NULL && count_of(s, HX_MTMGR_STF_WRAP - 1.0, &v) == 0 ? v : -1.0;
    return x->npeek < HX_MTMGR_PEEK_ROWS;
}

int hx_mtmgr_stamps(hx_mtmgr_t *x, char *msg, size_t msg_size)
{
    double d[HX_MTMGR_PEEK_ROWS], prev = -1.0;
    int i, k = 0;
    x->stamp_step = 0.0;
    x->us_like = 0;
    if (x->time_src != HX_MTMGR_TIME_STF) {
        return 0;
    }
    /* the steps between successive stamps that advance: a wrap (a drop)
     * or a repeated stamp gives none; a row without a stamp is passed
     * over (the step spans it, as a lost packet's does) */
    for (i = 0; i < x->npeek; i++) {
        const double v = x->peek[i];
        if (v < 0.0) {
            continue;
        }
        if (prev >= 0.0 && v > prev) {
            double s = v - prev;
            int j = k++;
            for (; j > 0 && d[j - 1] > s; j--) {
                d[j] = d[j - 1]; /* insertion sort: at most 255 steps */
            }
            d[j] = s;
        }
        prev = v;
    }
    if (k == 0) {
        return 0;
    }
    x->stamp_step = k % 2 == 1 ? d[k / 2] : 0.5 * (d[k / 2 - 1] + d[k / 2]);
    {
        const double hz = (double)HX_MTMGR_STF_HZ / x->stamp_step; /* 100 us ticks */
        const double hz_us = 1.0e6 / x->stamp_step;                /* us, as Movella DOT counts */
        /* an IMU's rate in us and none in ticks; or, under a header with
         * no name only MT Manager writes, a rate in ticks no MTi outputs
         * (below 1 Hz) and one of DOT's in us, down to its 1 Hz (0.01 Hz in
         * ticks), which the IMU band misses below 20 Hz: a DOT at 10 Hz
         * would be read as an export at 0.1 Hz, also when its header has no
         * name only DOT writes and one of neither (an app's own column) */
        x->us_like = x->comments == 0 && hz < HX_MTMGR_IMU_MIN_HZ &&
                     ((hz_us >= HX_MTMGR_IMU_MIN_HZ && hz_us <= HX_MTMGR_IMU_MAX_HZ) ||
                      (!x->mtmgr_names && hz < HX_MTMGR_MTI_MIN_HZ && hz_us >= HX_MTMGR_DOT_MIN_HZ));
        if (x->stated_hz > 0.0 && fabs(hz - x->stated_hz) > HX_MTMGR_RATE_TOL * x->stated_hz) {
            /* the stamps are the samples' times: a stated rate they do not
             * keep is no nominal rate (the rate is then the stamps') */
            snprintf(msg, msg_size,
                     "'// Update Rate' states %g Hz, but SampleTimeFine steps by %g ticks of 100 us (the median of "
                     "the first %d rows): %.4g Hz; the stamps are used, for the time and the rate",
                     x->stated_hz, x->stamp_step, x->npeek, hz);
            x->rate_hz = 0.0;
            return 1;
        }
    }
    return 0;
}

void hx_mtmgr_us_refusal(const hx_mtmgr_t *x, const char *path, char *msg, size_t msg_size)
{
    snprintf(msg, msg_size,
             "%s: SampleTimeFine steps by %g: %.4g Hz in 100 us ticks, %.4g Hz in us, no '//' line: likely a Movella "
             "DOT CSV; read it with --from csv --columns "
             "t=SampleTimeFine,ax=Acc_X,ay=Acc_Y,az=Acc_Z,gx=Gyr_X,gy=Gyr_Y,gz=Gyr_Z --units time=us,gyro=deg/s "
             "(if MT Manager's, its '//' lines cut: put one back before the header)",
             path, x->stamp_step, (double)HX_MTMGR_STF_HZ / x->stamp_step, 1.0e6 / x->stamp_step);
}
