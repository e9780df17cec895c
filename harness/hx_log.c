/* Harness log I/O: .bin, CSV interchange and importers (see hx_log.h and
 * docs/log-format.md). */
#include "hx_log.h"
#include "hx_cli.h"
#include "hx_bin.h"
#include "hx_merge.h"
#include "hx_names.h"
#include "hx_xsens.h"

#include <ctype.h>
#include <math.h>
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#define HX_MAX_COLS 64
#define HX_BUF_SIZE 65536

static const char *const k_format_names[HX_FMT_COUNT] = {
    "auto", "bin", "csv", "gx2", "openshoe820", "ngimu", "pyshoe", "ipol", "adis", "square2", "mtmanager",
    "picoquake"
};

const char *hx_format_name(hx_format_t fmt)
{
    return ((int)fmt >= 0 && fmt < HX_FMT_COUNT) ? k_format_names[fmt] : "?";
}

hx_format_t hx_format_from_name(const char *name)
{
    int i;
    for (i = 0; i < HX_FMT_COUNT; i++) {
        if (strcmp(name, k_format_names[i]) == 0) {
            return (hx_format_t)i;
        }
    }
    return HX_FMT_COUNT;
}

const char *hx_format_list(void)
{
    return HX_FORMAT_LIST;
}

/* The interchange CSV's column names, and the layout readers take them in
 * (hx_reader_set_layout; option NULL: these names in s, m/s^2, rad/s). */
static const char *const k_csv_names[8] = { "t", "ax", "ay", "az", "gx", "gy", "gz", "temp" };
static hx_csv_layout_t g_layout;
/* the layout the last interchange CSV opened was read with, when its names
 * were matched without --columns (hx_units_layout names its units) */
static hx_csv_layout_t g_read_layout;
static int g_read_matched;

/* How a text format gives time. */
typedef enum {
    TIME_COLUMN_S,   /* a column in seconds */
    TIME_INDEX,      /* uniform: line index / rate */
    TIME_COUNTER,    /* a packet counter column / rate, also the seq */
    TIME_GX2,        /* GX2 sensor timer (19.6608 MHz), see gx2_time() */
    TIME_MTMGR       /* MT Manager export: SampleTimeFine, PacketCounter or index (hx_mtmgr_time) */
} time_mode_t;

struct hx_reader {
    gzFile gz;
    char path[512];
    hx_meta_t meta;
    hx_read_stats_t stats;
    char err[HX_ERR_SIZE];      /* a refusal of names names the candidates (hx_names.h) */
    char warn[HX_WARN_SIZE];    /* the warnings, one a line (HX_WARN_SIZE) */
    size_t warn_taken;          /* bytes of warn already handed out by hx_reader_take_warnings */
    fnav_status_t deferred;     /* error to return at the end (bin) */
    int finished;

    /* text */
    char line[HX_LINE_MAX];
    char delim;                 /* ',' '\t' ';' or ' ' (any whitespace) */
    int col_t, col_a[3], col_g[3], col_temp, col_aux;
    int col_tns;                /* csv: nanoseconds added to t's whole seconds (--columns tns=); -1 none */
    int ncols_needed;
    int missing_col;            /* setup_header: the column not found (0 t ... 6 gz), else -1 */
    int nfields;                /* fields of the line last split */
    int hdr_fields;             /* fields of the header line (at most HX_MAX_COLS); 0: no header */
    int unit_field;             /* blanks: the header's first field that is a unit alone, "(s)" of
                                   "Time (s)" (names that hold blanks), 1-based; 0 none */
    char unit_text[24];         /* ... its text, cut */
    int date_join;              /* blanks: -1 not yet known, 1 a date and its time one field, 0 not (the
                                   header names them apart: "date time ax ..."), by the first row */
    char time_beside[64];       /* adis, square2: a time-named column the format does not read, "" none */
    hx_name_unit_t time_beside_unit; /* its unit as named (HX_UNIT_NONE: none named) */
    int last_line;              /* next_text_fields is parsing a last line without a newline */
    long short_rows;            /* data rows with fewer fields than the header */
    long short_first;           /* the line of the first of them */
    long long_rows;             /* data rows with more non-empty fields than the header */
    long long_first;            /* the line of the first of them */
    long rows_checked;          /* data rows compared with the header */
    double ctr_wrap;            /* ipol: 65536 per wrap of the 16-bit packet counter so far */
    double ctr_prev;            /* ipol: the last raw counter */
    hx_mtmgr_t mt;              /* mtmanager: columns, time source, counters (hx_xsens.h) */
    int row_skipped;            /* the row just read was skipped (mtmanager: a missing value) */
    int consensys;              /* csv: Shimmer's Consensys export (hx_names_consensys), its units row read */
    long dc_first;              /* the first line whose decimal commas were read as points (0: none) */
    hx_decimal_mix_t dmix;      /* decimal commas and points both in the columns read (a mixed log) */
    int ros;                    /* csv: a ROS sensor_msgs/Imu header matched (hx_names_ros) */
    int kalibr;                 /* csv: Kalibr's IMU CSV header matched (hx_names_kalibr) */
    int sensorlog;              /* csv: SensorLog's header matched (hx_names_sensorlog) */
    int gforce;                 /* csv: Physics Toolbox's g-force names matched (hx_names_match) */
    double acc_scale, gyr_scale;
    hx_csv_layout_t layout;     /* the interchange CSV's names and units (--columns, --units) */
    time_mode_t time_mode;
    double rate_hz;
    long index;
    int have_prev;
    int last_line_open;         /* the last line read had no newline (EOF) */
    int64_t prev_t_ns;
    double prev_counter;
    /* GX2 timer state */
    int64_t gx2_ticks;
    long gx2_last_dt;
    double gx2_prev_host;
    double gx2_prev_nr;
    long gx2_bridged;
    long gx2_nr_back;           /* packets whose Nr is not past the last one's (not a duplicate) */
    long gx2_nr_back_line;      /* the line of the first of them */

    /* bin */
    unsigned char buf[HX_BUF_SIZE];
    size_t pos, len;
    long long offset;           /* file offset of buf[pos] */
    int eof;
    int gz_cut;                 /* the gzip data ended early (a truncated .bin.gz) */
    long record_slot;           /* index of the next record slot */
    int temp_unflagged;         /* a record's temperature under a header without the flag was said */
};

/* The reader's messages quote the file's own text (a field, a header
 * name, a path): each is made one line of printable text, a control
 * character read as '?' as in a .bin header's text, so that a field
 * '0<ESC>]0;...<BEL>' cannot send an escape sequence to the terminal
 * (it did: tests/cli/test_bad_input.sh) nor a line break forge a line. */
static void set_err(hx_reader_t *r, const char *fmt, ...)
{
    va_list ap;
    char msg[sizeof r->err], old[sizeof r->err];
    if (r->err[0] != '\0' && r->deferred == FNAV_OK) {
        return; /* keep the first error */
    }
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    (void)hx_printable(msg);
    if (r->err[0] == '\0') {
        memcpy(r->err, msg, sizeof r->err);
        return;
    }
    /* the earlier message was deferred (a skipped record: the reading went
     * on); this one says where it stopped, and keeps the earlier */
    memcpy(old, r->err, sizeof old);
    snprintf(r->err, sizeof r->err, "%.*s; before it: %.*s", (int)sizeof r->err / 2, msg,
             (int)sizeof r->err / 2 - 16, old);
}

/* one line of the reader's messages; a note (routine, nothing to act on)
 * starts with "note: " and hx_print_warnings prints it as one */
static void add_line(hx_reader_t *r, const char *prefix, const char *fmt, va_list ap)
{
    size_t used = strlen(r->warn);
    if (used + 2 + strlen(prefix) >= sizeof r->warn) {
        return;
    }
    if (used > 0) {
        r->warn[used++] = '\n';
        r->warn[used] = '\0';
    }
    used += (size_t)snprintf(r->warn + used, sizeof r->warn - used, "%s", prefix);
    vsnprintf(r->warn + used, sizeof r->warn - used, fmt, ap);
    (void)hx_printable(r->warn + used); /* this line alone: the '\n' between lines stays (set_err) */
}

/* m/s^2 per unit of an acceleration unit a header names (1 for m/s^2 or
 * none), and back: the unit of a scale (HX_UNIT_NONE for m/s^2) */
static double acc_scale_of(hx_name_unit_t u)
{
    return u == HX_UNIT_G ? HX_G_MPS2 : u == HX_UNIT_MG ? HX_MG_MPS2 : u == HX_UNIT_UG ? HX_UG_MPS2 : 1.0;
}

/* A layout read in unit u, set on the field of u's quantity (the time
 * column's digits, the accel or gyro scale); HX_UNIT_NONE sets none. */
static void layout_unit(hx_csv_layout_t *l, hx_name_unit_t u)
{
    if (u == HX_UNIT_NONE) {
        return;
    }
    if (u <= HX_UNIT_NS) {
        l->time_digits = u == HX_UNIT_MS ? 6 : u == HX_UNIT_US ? 3 : u == HX_UNIT_NS ? 0 : 9;
    } else if (u <= HX_UNIT_UG) {
        l->acc_scale = acc_scale_of(u);
    } else {
        l->gyr_scale = u == HX_UNIT_DPS ? HX_DPS_RPS : u == HX_UNIT_MDPS ? HX_MDPS_RPS : 1.0;
    }
}

void hx_csv_layout_unit(hx_csv_layout_t *l, hx_name_unit_t u)
{
    layout_unit(l, u);
}

static hx_name_unit_t acc_unit_of(double scale)
{
    return scale == HX_G_MPS2    ? HX_UNIT_G
           : scale == HX_MG_MPS2 ? HX_UNIT_MG
           : scale == HX_UG_MPS2 ? HX_UNIT_UG
                                 : HX_UNIT_NONE;
}

static void add_warn(hx_reader_t *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    add_line(r, "", fmt, ap);
    va_end(ap);
}

static void add_note(hx_reader_t *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    add_line(r, "note: ", fmt, ap);
    va_end(ap);
}

static void copy_str(char *dst, size_t size, const char *src)
{
    size_t n = strlen(src);
    if (n >= size) {
        n = size - 1;
    }
    memcpy(dst, src, n);
    dst[n] = '\0';
}

int hx_printable(char *s)
{
    int n = 0;
    char *o = s;
    while (*s != '\0') {
        int ctl;
        size_t k = hx_text_char(s, &ctl);
        if (ctl) {
            *o++ = '?'; /* one '?' for the character, of one byte or two */
            s += k;
            n++;
        } else {
            while (k-- > 0u) {
                *o++ = *s++;
            }
        }
    }
    *o = '\0';
    return n;
}

/* ------------------------------------------------------------ parsing */

static char *trim(char *s)
{
    char *e;
    while (*s == ' ' || *s == '\t' || *s == '"') {
        s++;
    }
    e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '\n' || e[-1] == '"')) {
        *--e = '\0';
    }
    return s;
}

/* Whether the len characters at s are a date, YYYY-MM-DD or YYYY/MM/DD
 * (the month and the day in one digit or two: WitMotion's 2023-3-21), and
 * the text at next starts with a clock time, h:mm or hh:mm: a date and
 * time that blanks would split in two. */
static int date_then_time(const char *s, size_t len, const char *next)
{
    const size_t h = next[0] != '\0' && isdigit((unsigned char)next[1]) ? 2 : 1;
    const size_t m = strspn(s + 5, "0123456789");
    const size_t d = 5 + m < len ? strspn(s + 6 + m, "0123456789") : 0;
    if (len < 8 || strspn(s, "0123456789") != 4 || (s[4] != '-' && s[4] != '/') || m < 1 || m > 2 ||
        s[5 + m] != s[4] || d < 1 || d > 2 || 6 + m + d != len) {
        return 0;
    }
    return isdigit((unsigned char)next[0]) && next[h] == ':' && isdigit((unsigned char)next[h + 1]) &&
           isdigit((unsigned char)next[h + 2]);
}

/* Whether the word at s (to a blank, a line end or the end) is a zone's
 * offset, +hh:mm or +hhmm (or '-'), hh 00-19: the offset a date and time
 * may carry after a blank, no value a log writes so. */
static int zone_word(const char *s)
{
    const char *p = s + 3;
    if ((s[0] != '+' && s[0] != '-') || (s[1] != '0' && s[1] != '1') || !isdigit((unsigned char)s[2])) {
        return 0;
    }
    p += *p == ':';
    return p[0] >= '0' && p[0] <= '5' && isdigit((unsigned char)p[1]) &&
           (p[2] == '\0' || p[2] == ' ' || p[2] == '\t' || p[2] == '\r' || p[2] == '\n');
}

/* Split line in place; returns the number of fields. Blank-separated
 * (delim ' '): runs of blanks separate, except between a date and a clock
 * time, and the offset after it, which stay one field with one blank
 * between them ("2024-05-01 12:00:00.5", as a date and time is written,
 * "2024-05-01 12:00:00.5 +0200"). */
static int split_join(char *line, char delim, char **f, int max, int dates)
{
    int n = 0, quoted = 0, joined;
    char *p = line;
    if (delim == ' ') {
        while (*p != '\0' && n < max) {
            while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') {
                p++;
            }
            if (*p == '\0') {
                break;
            }
            f[n++] = p;
            for (joined = 0;; joined++) {
                char *q;
                while (*p != '\0' && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') {
                    p++;
                }
                if (*p == '\0' || !dates || joined > 1 || (joined == 0 && (p - f[n - 1] < 8 || p - f[n - 1] > 10))) {
                    break; /* no date's length: nothing more to look at (every other field of a row) */
                }
                for (q = p; *q == ' ' || *q == '\t'; q++) {
                }
                if (joined == 0 ? !date_then_time(f[n - 1], (size_t)(p - f[n - 1]), q) : !zone_word(q)) {
                    break;
                }
                /* the date's blanks as one: the time follows in the same
                 * field, and an offset after it ("+0100") */
                *p = ' ';
                memmove(p + 1, q, strlen(q) + 1);
                p++;
            }
            if (*p != '\0') {
                *p++ = '\0';
            }
        }
        return n;
    }
    f[n++] = p;
    while (*p != '\0') {
        /* a delimiter between double quotes is the field's ("0,5" in a
         * comma-separated export with a decimal comma); trim drops them */
        quoted ^= *p == '"';
        if (*p == delim && !quoted) {
            *p = '\0';
            if (n < max) {
                f[n++] = p + 1;
            }
        }
        p++;
    }
    {
        int i;
        for (i = 0; i < n; i++) {
            f[i] = trim(f[i]);
        }
    }
    return n;
}

static int split(char *line, char delim, char **f, int max)
{
    return split_join(line, delim, f, max, 1);
}

int hx_split_fields(char *line, char delim, char **f, int max)
{
    return split(line, delim, f, max);
}

/* Strict number: the whole field must be a finite decimal number. -2 for
 * NaN or Inf written as such; -3 for a decimal number beyond 1e300 (1e308,
 * 400 digits: strtod makes the second Inf), *out then +-1e300 so that a
 * caller's range check names it ("beyond 1e+06 in SI units"), not as "NaN
 * or Inf", which it is not */
static int parse_num(const char *s, double *out)
{
    char *end;
    double v;
    if (*s == '\0' || strpbrk(s, "xX") != NULL) {
        return -1; /* C's hexadecimal notation, which strtod reads (0x10 as 16), is no decimal number */
    }
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end != '\0') {
        return -1;
    }
    if (v != v) {
        return -2;
    }
    if (v > 1.0e300 || v < -1.0e300) {
        /* "inf" as written, or a decimal number past 1e300 (the letters
         * looked for here only, off the path of every field in range) */
        if (strpbrk(s, "nNiI") != NULL) {
            return -2;
        }
        *out = v > 0.0 ? 1.0e300 : -1.0e300;
        return -3;
    }
    *out = v;
    return 0;
}

/* Whether a field is a number written with the decimal mark mark and
 * digits on both sides ("-0,5", "9,81e+00" for a comma; "9.81" for a
 * point). */
static int decimal_mark_is(const char *s, char mark)
{
    int lead = 0, frac = 0;
    if (*s == '+' || *s == '-') {
        s++;
    }
    while (isdigit((unsigned char)*s)) {
        s++;
        lead++;
    }
    if (lead == 0 || *s++ != mark) {
        return 0;
    }
    while (isdigit((unsigned char)*s)) {
        s++;
        frac++;
    }
    if (frac > 0 && (*s == 'e' || *s == 'E')) {
        s++;
        if (*s == '+' || *s == '-') {
            s++;
        }
        if (!isdigit((unsigned char)*s)) {
            return 0;
        }
        while (isdigit((unsigned char)*s)) {
            s++;
        }
    }
    return frac > 0 && *s == '\0';
}

/* Whether a field is a number written with a decimal comma, as a
 * European-locale spreadsheet exports it: an error whose message then
 * says so. */
static int decimal_comma(const char *s)
{
    return decimal_mark_is(s, ',');
}

/* A field kept for the decimal-mix warning: whole when it fits, else cut
 * with "..." in the buffer, as the harness's other cut texts end ('%.40s...'):
 * a number of 30 digits quoted as its first 23 read as the field itself. */
static void mix_field(char *dst, size_t size, const char *s)
{
    if (strlen(s) < size) {
        snprintf(dst, size, "%s", s);
    } else {
        snprintf(dst, size, "%.*s...", (int)(size - 4u), s);
    }
}

int hx_decimal_mix_note(hx_decimal_mix_t *m, const char *s, long line)
{
    if (m->said) {
        return 0;
    }
    if (m->comma_line == 0 && decimal_mark_is(s, ',')) {
        m->comma_line = line;
        mix_field(m->comma, sizeof m->comma, s);
    } else if (m->point_line == 0 && decimal_mark_is(s, '.')) {
        m->point_line = line;
        mix_field(m->point, sizeof m->point, s);
    } else {
        return 0;
    }
    m->said = m->comma_line > 0 && m->point_line > 0;
    return m->said;
}

const char *hx_decimal_mix_text(const hx_decimal_mix_t *m, const char *path, char *buf, size_t size)
{
    const int point_later = m->point_line >= m->comma_line;
    snprintf(buf, size, "%s:%ld: a number with a decimal %s ('%s') in a log whose numbers have decimal %s ('%s', "
                        "line %ld): both read as decimal marks (a %s that is a thousands separator, '%s' for "
                        "1002, is misread: export the log with one decimal mark)",
             path, point_later ? m->point_line : m->comma_line, point_later ? "point" : "comma",
             point_later ? m->point : m->comma, point_later ? "commas" : "points", point_later ? m->comma : m->point,
             point_later ? m->comma_line : m->point_line, point_later ? "point" : "comma",
             point_later ? "1.002" : "1,002");
    return buf;
}

#define DECIMAL_COMMA_FIX "footnav reads numbers with a decimal point; export the log without the locale's decimal comma"
#define DECIMAL_COMMA_HINT " (a decimal comma: " DECIMAL_COMMA_FIX ")"
/* a header of names that hold blanks in a blank-separated file: the unit
 * alone ("(s)") and its field (reader's unit_text, unit_field) */
#define UNIT_ALONE_FIX                                                                                       \
    "the fields are separated by blanks and the header's names hold blanks ('%s' is its field %d alone), "   \
    "which cannot be told apart: separate the fields with commas or tabs"

/* "not a number", and why when the field has a decimal comma */
static const char *not_a_number(const char *field)
{
    return decimal_comma(field) ? "not a number" DECIMAL_COMMA_HINT : "not a number";
}

/* The decimal commas of a row whose fields are separated by semicolons or
 * tabs, as a European-locale spreadsheet exports it ("0;-0,5;9,81"):
 * read as points, the columns read only and each a well-formed number
 * (decimal_comma: "1.234,5" stays an error), the first such line said in
 * a warning. A comma-separated row is left as it is: "0,5" there is two
 * fields, ambiguous, and refused (DECIMAL_COMMA_HINT). */
static void decimal_commas_read(hx_reader_t *r, char **f, int n)
{
    int cols[8], k;
    cols[0] = r->col_t;
    cols[7] = r->col_temp;
    for (k = 0; k < 3; k++) {
        cols[1 + k] = r->col_a[k];
        cols[4 + k] = r->col_g[k];
    }
    for (k = 0; k < 8; k++) {
        int mixed;
        if (cols[k] < 0 || cols[k] >= n) {
            continue;
        }
        /* a point among commas, or a comma among points: both read as
         * decimal marks, said once where the second kind first is */
        mixed = hx_decimal_mix_note(&r->dmix, f[cols[k]], r->stats.lines);
        if (decimal_comma(f[cols[k]])) {
            if (r->dc_first == 0) {
                r->dc_first = r->stats.lines;
                add_warn(r, "%s:%ld: numbers with a decimal comma ('%.40s') read as decimals (the fields are "
                            "%s-separated)",
                         r->path, r->stats.lines, f[cols[k]], r->delim == ';' ? "semicolon" : "tab");
            }
            *strchr(f[cols[k]], ',') = '.';
        }
        if (mixed) {
            char wt[HX_ERR_SIZE];
            add_warn(r, "%s", hx_decimal_mix_text(&r->dmix, r->path, wt, sizeof wt));
        }
    }
}

/* Whether a line is numbers separated by semicolons, tabs or blanks, at
 * least one with a decimal comma and the others whole (a headerless
 * European-locale export: "0,19;-0,42;9,86;..."); first: its first field
 * with a decimal comma. */
static int decimal_comma_line(const char *line, char *first, size_t size)
{
    int commas = 0;
    const char *p = line;
    first[0] = '\0';
    for (;;) {
        char tok[64];
        size_t k = 0;
        while (*p == ';' || *p == '\t' || *p == ' ' || *p == '\r' || *p == '\n') {
            p++;
        }
        if (*p == '\0') {
            return commas > 0;
        }
        while (*p != '\0' && *p != ';' && *p != '\t' && *p != ' ' && *p != '\r' && *p != '\n') {
            if (k + 1 >= sizeof tok) {
                return 0;
            }
            tok[k++] = *p++;
        }
        tok[k] = '\0';
        if (decimal_comma(tok)) {
            if (commas++ == 0) {
                copy_str(first, size, tok);
            }
        } else {
            const char *d = tok[0] == '-' || tok[0] == '+' ? tok + 1 : tok;
            if (*d == '\0' || strspn(d, "0123456789") != strlen(d)) {
                return 0; /* neither a decimal comma nor a whole number */
            }
        }
    }
}

/* n digits at *p as a number (-1 if fewer); *p moves past them */
static int take_digits(const char **p, int n)
{
    int v = 0, i;
    for (i = 0; i < n; i++) {
        if (!isdigit((unsigned char)(*p)[i])) {
            return -1;
        }
        v = v * 10 + ((*p)[i] - '0');
    }
    *p += n;
    return v;
}

/* one or two digits at *p as a number (-1 if none); *p moves past them */
static int take_digits12(const char **p)
{
    return take_digits(p, isdigit((unsigned char)(*p)[0]) && isdigit((unsigned char)(*p)[1]) ? 2 : 1);
}

/* Days from 1970-01-01 to a proleptic Gregorian date (the civil-from-days
 * inverse of H. Hinnant's "chrono-compatible low-level date algorithms"). */
static int64_t days_from_civil(int y, int m, int d)
{
    const int64_t yy = (int64_t)y - (m <= 2 ? 1 : 0);
    const int64_t era = (yy >= 0 ? yy : yy - 399) / 400;
    const int64_t yoe = yy - era * 400;                                  /* [0, 399] */
    const int64_t doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1; /* [0, 365] */
    const int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;           /* [0, 146096] */
    return era * 146097 + doe - 719468;
}

/* A date and time as loggers write them (ISO 8601 and its common
 * relatives): "YYYY-MM-DD hh:mm:ss[.f]" with 'T' or a blank between date
 * and time, '/' allowed for '-' (year first only: 05/01/2024 is ambiguous),
 * the month, the day and the hour after a date in one digit or two
 * (WitMotion's "2023-3-21 9:05:23.334"), the time's ':' written '.' after
 * a date and 'T' (MetaWear MetaBase's "2019-12-22T07.33.20.000"), an
 * optional zone ("Z", "+hh:mm", "+hhmm", "+hh"; an offset after a date
 * also after one blank, "... 13:12:49.592 +0100"), or a clock time alone
 * ("hh:mm:ss[.f]", seconds since midnight). To integer ns since
 * 1970-01-01T00:00:00Z (the clock alone: since midnight), the fraction
 * rounded to the ns. 0 ok; 1 not of this shape (a number, say); -4 of
 * this shape but no date and time (month 13, 25:00:00, a trailing word, a
 * date without its time: every stamp of a day would be the same); -5 a
 * year before 1900 or after 2100. */
static int parse_datetime_ns(const char *s, int64_t *out)
{
    static const int mdays[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
    const char *p = s;
    int64_t days = 0, sec, ns = 0;
    int y, mo, d, hh, mi, ss, n = 0, up = 0, dated = 0;
    char tsep = ':'; /* the time's separator: '.' after a date and 'T' (MetaBase) */
    if (isdigit((unsigned char)s[0]) && isdigit((unsigned char)s[1]) && s[2] == ':') {
        /* a clock time alone */
    } else if (strspn(s, "0123456789") == 4 && (s[4] == '-' || s[4] == '/')) {
        const char sep = s[4];
        y = take_digits(&p, 4);
        p++;
        mo = take_digits12(&p);
        if (mo < 0 || *p++ != sep) {
            return -4;
        }
        d = take_digits12(&p);
        if (y < 1900 || y > 2100) {
            return -5; /* the reader's 2^62 ns (146 years) about 1970 */
        }
        if (mo < 1 || mo > 12 || d < 1 ||
            d > mdays[mo - 1] + (mo == 2 && y % 4 == 0 && (y % 100 != 0 || y % 400 == 0))) {
            return -4;
        }
        days = days_from_civil(y, mo, d);
        dated = 1;
        if (*p != 'T' && *p != 't' && *p != ' ') {
            return -4;
        }
        tsep = *p++ != ' ' && p[strspn(p, "0123456789")] == '.' ? '.' : ':';
        hh = take_digits12(&p);
    } else {
        return 1;
    }
    if (!dated) {
        hh = take_digits(&p, 2);
    }
    if (hh < 0 || *p++ != tsep) {
        return -4;
    }
    mi = take_digits(&p, 2);
    if (mi < 0 || *p++ != tsep) {
        return -4;
    }
    ss = take_digits(&p, 2);
    if (hh > 23 || mi > 59 || ss < 0 || ss > 59) {
        return -4;
    }
    if (*p == '.' || *p == ',') { /* ISO 8601 allows a decimal comma here */
        p++;
        if (!isdigit((unsigned char)*p)) {
            return -4;
        }
        for (; isdigit((unsigned char)*p); p++) {
            if (n < 9) {
                ns = ns * 10 + (*p - '0');
                n++;
            } else if (n++ == 9) {
                up = *p >= '5'; /* the tenth digit rounds to the nearest ns */
            }
        }
        for (; n < 9; n++) {
            ns *= 10;
        }
    }
    sec = days * 86400 + hh * 3600 + mi * 60 + ss;
    if (*p == ' ' && (p[1] == '+' || p[1] == '-') && dated) {
        p++; /* one blank before an offset: "13:12:49.592 +0100" (SensorLog's, Java's "Z" pattern) */
    }
    if (*p == 'Z' || *p == 'z') {
        p++;
    } else if ((*p == '+' || *p == '-') && dated) {
        const int sign = *p++ == '-' ? -1 : 1;
        const int oh = take_digits(&p, 2);
        int om = 0;
        if (oh < 0 || oh > 23) {
            return -4;
        }
        if (*p == ':' && p[1] == '\0') {
            return -4; /* "+02:": the minutes left out after their colon */
        }
        if (*p == ':') {
            p++;
        }
        if (*p != '\0') {
            om = take_digits(&p, 2);
            if (om < 0 || om > 59) {
                return -4;
            }
        }
        sec -= sign * (oh * 3600 + om * 60); /* local time minus its offset is UTC */
    }
    if (*p != '\0') {
        return -4;
    }
    *out = sec * 1000000000LL + ns + up;
    return 0;
}

#define DATETIME_FORM                                                                                          \
    "YYYY-MM-DD hh:mm:ss[.f] with an optional T, Z or +hh:mm (month, day and hour in one digit or two; "       \
    "hh.mm.ss after T); or hh:mm:ss[.f]"

const char *hx_field_count_text(const char *path, long first, long rows, long checked, int hdr_fields, int more,
                                char *buf, size_t size)
{
    if (!more) {
        snprintf(buf, size, "%s:%ld: %ld row%s with fewer fields than the header's %d (the first here): where a "
                            "field was lost inside a row, the values after it were read from the wrong columns",
                 path, first, rows, rows == 1 ? "" : "s", hdr_fields);
    } else if (rows > 1 && rows == checked) {
        /* the same on every row: more likely a name the header lacks than
         * a stray delimiter, and then the columns after it are all wrong */
        snprintf(buf, size, "%s:%ld: every row (%ld) has more fields than the header's %d (the first here): the "
                            "header may lack a column's name, and where it lacks one before a column the reader "
                            "uses, every value after it was read from the wrong column (name each column in the "
                            "header)",
                 path, first, rows, hdr_fields);
    } else {
        snprintf(buf, size, "%s:%ld: %ld row%s with more fields than the header's %d (the first here): where a "
                            "stray delimiter split a field, the values after it were read from the wrong columns",
                 path, first, rows, rows == 1 ? "" : "s", hdr_fields);
    }
    return buf;
}

/* A stamp in seconds to the ns, as the CSV writer writes it (a double's
 * %.9f is 300 ns off at Unix time: two stamps 1 ns apart read alike). */
static const char *ns_text(int64_t t_ns, char *buf, size_t size)
{
    const int64_t a = t_ns < 0 ? -t_ns : t_ns;
    snprintf(buf, size, "%s%lld.%09lld", t_ns < 0 ? "-" : "", (long long)(a / 1000000000LL),
             (long long)(a % 1000000000LL));
    return buf;
}

/* A number in exponent notation, [+-]d[.d]e[+-]d, as integer ns in the
 * unit of 10^k ns: the significant digits shifted by the exponent, the
 * first digit dropped rounding half up, as parse_time_ns's plain decimals.
 * 0, -3 beyond 9e18 ns, 1 not of this form (the caller's strtod decides). */
static int exp_time_ns(const char *s, int k, int64_t *out)
{
    char d[40];
    int m = 0, point = 0, seen_point = 0, neg = 0, eneg = 0, e = 0, i, keep;
    int64_t v = 0;
    if (*s == '+' || *s == '-') {
        neg = *s++ == '-';
    }
    for (; isdigit((unsigned char)*s) || (*s == '.' && !seen_point); s++) {
        if (*s == '.') {
            seen_point = 1;
        } else if (m == 0 && *s == '0') {
            point -= seen_point; /* a leading zero: after the point it moves the digits right */
        } else if (m < (int)sizeof d) {
            d[m++] = *s;
            point += !seen_point;
        } else if (!seen_point) {
            return 1; /* more significant digits than kept before the point: strtod's */
        }
    }
    if (*s != 'e' && *s != 'E') {
        return 1;
    }
    s++;
    if (*s == '+' || *s == '-') {
        eneg = *s++ == '-';
    }
    if (!isdigit((unsigned char)*s)) {
        return 1;
    }
    for (; isdigit((unsigned char)*s); s++) {
        e = e < 1000 ? e * 10 + (*s - '0') : e;
    }
    if (*s != '\0') {
        return 1;
    }
    /* the value is 0.d[0]d[1]... x 10^(point + exponent + k) in ns: the
     * integer part keeps the first `keep` digits */
    keep = point + (eneg ? -e : e) + k;
    if (m == 0 || keep < 0) {
        *out = 0;
        return 0;
    }
    if (keep > 19) {
        return -3;
    }
    for (i = 0; i < keep; i++) {
        const int64_t dig = i < m ? d[i] - '0' : 0;
        if (v > (INT64_C(9000000000000000000) - dig) / 10) {
            return -3;
        }
        v = v * 10 + dig;
    }
    v += keep < m && d[keep] >= '5';
    *out = neg ? -v : v;
    return 0;
}

/* Time as text to integer ns, exactly for plain decimals: in seconds
 * (k = 9), ms (6), us (3) or ns (0), 10^k ns to the unit; the point moves
 * in the text, no float (--units time=ns: Unix time in ns to the ns). */
static int parse_time_ns(const char *s, int k, int64_t *out)
{
    static const int64_t p10[10] = { 1LL, 10LL, 100LL, 1000LL, 10000LL, 100000LL, 1000000LL, 10000000LL,
                                     100000000LL, 1000000000LL };
    const int64_t lim = 9000000000LL * p10[9 - k]; /* 9e9 s in the unit */
    const char *p = s;
    int neg = 0, digits = 0, frac = 0, extra = 0, up = 0, over = 0;
    int64_t ip = 0, fp = 0;
    const int dt = parse_datetime_ns(s, out); /* carries its own unit */
    if (dt <= 0) {
        return dt;
    }
    if (*p == '+' || *p == '-') {
        neg = (*p == '-');
        p++;
    }
    while (isdigit((unsigned char)*p)) {
        /* beyond 9e9 s, where int64 ns would overflow: said below unless an
         * exponent follows ("100000000000000000000e-15" is 1e5 s, not
         * refused here before the exponent is seen) */
        if (over || ip > (lim - (*p - '0')) / 10) {
            over = 1;
        } else {
            ip = ip * 10 + (*p - '0');
        }
        p++;
        digits++;
    }
    if (*p == '.') {
        p++;
        while (isdigit((unsigned char)*p)) {
            if (frac < k) {
                fp = fp * 10 + (*p - '0');
                frac++;
            } else if (extra++ == 0) {
                /* the tenth decimal rounds to the nearest ns, as strtod's
                 * path below does (cut off, 1.9999999996 would read 1 ns
                 * short of 1.9999999996e0) */
                up = *p >= '5';
            }
            p++;
            digits++;
        }
    }
    if (*p != '\0' && digits > 0 && (*p == 'e' || *p == 'E')) {
        /* exponent notation (numpy's %.18e, 1.7000000000025e9): the digits
         * shifted by the exponent, as integers, exact to the ns as a plain
         * decimal is (a double has 16 digits: Unix time in ns has 19) */
        const int rc = exp_time_ns(s, k, out);
        if (rc != 1) {
            return rc;
        }
    }
    if (*p != '\0' || digits == 0) {
        double v;
        int rc = parse_num(s, &v);
        if (rc != 0) {
            return rc;
        }
        v *= (double)p10[k]; /* ns */
        if (v > 9.0e18 || v < -9.0e18) {
            return -3;
        }
        *out = (int64_t)(v + (v >= 0.0 ? 0.5 : -0.5));
        return 0;
    }
    if (over) {
        return -3;
    }
    while (frac < k) {
        fp *= 10;
        frac++;
    }
    *out = (ip * p10[k] + fp + up) * (neg ? -1 : 1);
    return 0;
}

int hx_parse_time_ns(const char *s, int digits, int64_t *out)
{
    return parse_time_ns(s, digits, out);
}

int hx_is_datetime(const char *s)
{
    int64_t ns;
    return parse_datetime_ns(s, &ns) == 0;
}

/* Seconds to ns with a range check (|t| < 9.2e9 s keeps int64 ns exact enough). */
static int secs_to_ns(double t_s, int64_t *out)
{
    if (!(t_s > -9.0e9 && t_s < 9.0e9)) {
        return -1;
    }
    *out = (int64_t)floor(t_s * 1.0e9 + 0.5);
    return 0;
}

/* A zlib error after reading (0 if none), said with its line: a gzip stream
 * that ends early is a truncated .gz (an incomplete copy), not a recording
 * cut off mid-write. */
static int gz_failed(hx_reader_t *r, long line)
{
    int e;
    const char *msg = gzerror(r->gz, &e);
    if (e == Z_OK || e == Z_STREAM_END) {
        return 0;
    }
    if (e == Z_BUF_ERROR) {
        set_err(r, "%s:%ld: the gzip data ends early (a truncated .gz, e.g. an incomplete copy)", r->path, line);
    } else {
        set_err(r, "%s:%ld: read error (%s)", r->path, line, msg);
    }
    return 1;
}

int hx_cr_alone(const char *line)
{
    /* every CR; a run of them before a newline is a line end written twice
     * (CR CR LF: '\r\n' written in a Windows text-mode file, unix2dos run
     * twice), not a line end of its own */
    const char *cr = line;
    while ((cr = strchr(cr, '\r')) != NULL) {
        cr += strspn(cr, "\r");
        if (*cr != '\n' && *cr != '\0') {
            return 1;
        }
    }
    return 0;
}

char *hx_gzgets(gzFile gz, char *buf, int size, size_t *len, int *nul)
{
    const z_off_t before = gztell(gz);
    z_off_t after;
    *len = 0;
    *nul = 0;
    if (gzgets(gz, buf, size) == NULL) {
        return NULL;
    }
    *len = strlen(buf);
    after = gztell(gz);
    /* gzgets stops only at a newline, a full buffer or the end of the
     * file, and copies a NUL byte like any other: the string then ends
     * before the bytes read do */
    *nul = before >= 0 && after >= 0 && (size_t)(after - before) != *len;
    return buf;
}

/* Read one line; 1 ok, 0 EOF, -1 error (err set). */
static int read_line(hx_reader_t *r)
{
    size_t n;
    int nul;
    if (hx_gzgets(r->gz, r->line, (int)sizeof r->line, &n, &nul) == NULL) {
        return gz_failed(r, r->stats.lines + 1) ? -1 : 0;
    }
    r->stats.lines++;
    if (n > 0 && r->line[n - 1] != '\n' && gzeof(r->gz) && gz_failed(r, r->stats.lines)) {
        return -1; /* the last text before a truncated gzip stream's end */
    }
    if (nul) {
        set_err(r, "%s:%ld: " HX_NUL_TEXT, r->path,
                r->stats.lines);
        return -1;
    }
    if (r->stats.lines == 1 && n >= 3 && memcmp(r->line, "\xef\xbb\xbf", 3) == 0) {
        /* a UTF-8 byte-order mark, as Windows tools write it: not data */
        memmove(r->line, r->line + 3, n - 2);
        n -= 3;
    }
    r->last_line_open = (n == 0 || r->line[n - 1] != '\n');
    if (n == sizeof r->line - 1 && r->line[n - 1] != '\n' && !gzeof(r->gz)) {
        set_err(r, "%s:%ld: line longer than %d bytes with its line end%s", r->path, r->stats.lines, HX_LINE_MAX - 1,
                hx_cr_alone(r->line) ? HX_CR_ALONE_HINT : "");
        return -1;
    }
    if (r->stats.lines == 1 && hx_cr_alone(r->line)) {
        /* a short file of such lines is one line: said, not read as a
         * header whose last name runs into the data ("gz\r0.01") */
        set_err(r, "%s:1: a carriage return inside the line%s", r->path, HX_CR_ALONE_HINT);
        return -1;
    }
    return 1;
}

static int blank(const char *s)
{
    while (*s != '\0') {
        if (!isspace((unsigned char)*s)) {
            return 0;
        }
        s++;
    }
    return 1;
}

/* A comment line of the plain CSV format: '#' first (after blanks), as
 * numpy's savetxt writes its header ("# t,ax,...") and other tools their
 * notes. */
static int comment(const char *s)
{
    while (*s == ' ' || *s == '\t') {
        s++;
    }
    return *s == '#';
}

/* ------------------------------------------------------------ detection */

/* The first line of text in out: lower case, without spaces, tabs kept as
 * separators, quotes and carriage returns dropped. */
static void squeeze_line(const char *text, char *out, size_t size)
{
    size_t k = 0;
    for (; *text != '\0' && *text != '\n' && k + 1 < size; text++) {
        if (*text == ' ' || *text == '"' || *text == '\'' || *text == '\r') {
            continue;
        }
        out[k++] = (char)tolower((unsigned char)*text);
    }
    out[k] = '\0';
}

/* The first line of text in out as squeeze_line makes it, but for a line
 * without commas, tabs or semicolons, whose runs of blanks separate its
 * names (numpy's savetxt with its default delimiter, "t ax ay ..."): each
 * run becomes a tab. */
static int blank_separated(const char *text)
{
    while (*text != '\0' && *text != '\n' && *text != ',' && *text != '\t' && *text != ';') {
        text++;
    }
    return *text == '\0' || *text == '\n';
}

static void squeeze_header(const char *text, char *out, size_t size)
{
    size_t k = 0;
    if (!blank_separated(text)) {
        squeeze_line(text, out, size);
        return;
    }
    for (; *text != '\0' && *text != '\n' && k + 1 < size; text++) {
        if (*text == ' ') {
            if (k > 0 && out[k - 1] != '\t') {
                out[k++] = '\t';
            }
            continue;
        }
        if (*text == '"' || *text == '\'' || *text == '\r') {
            continue;
        }
        out[k++] = (char)tolower((unsigned char)*text);
    }
    while (k > 0 && out[k - 1] == '\t') {
        k--;
    }
    out[k] = '\0';
}

/* Whether the squeezed header line holds the field name (separated by
 * commas, tabs or semicolons). */
static int has_field(const char *head, const char *name)
{
    const size_t n = strlen(name);
    const char *p = head;
    while (*p != '\0') {
        const char *e = p;
        while (*e != '\0' && *e != ',' && *e != '\t' && *e != ';') {
            e++;
        }
        if ((size_t)(e - p) == n && strncmp(p, name, n) == 0) {
            return 1;
        }
        p = *e != '\0' ? e + 1 : e;
    }
    return 0;
}

/* Whether a field of the squeezed header is a time name as the names
 * reader takes one (hx_name_classify: t, time, timestamp_ms, "Time (s)"). */
static int has_time_field(const char *head)
{
    const char *p = head;
    while (*p != '\0') {
        char name[64];
        hx_name_class_t c;
        const char *e = p;
        while (*e != '\0' && *e != ',' && *e != '\t' && *e != ';') {
            e++;
        }
        if ((size_t)(e - p) < sizeof name) {
            memcpy(name, p, (size_t)(e - p));
            name[e - p] = '\0';
            if (hx_name_classify(name, &c) == HX_NAME_MATCH && c.key == 0) {
                return 1;
            }
        }
        p = *e != '\0' ? e + 1 : e;
    }
    return 0;
}

/* The OpenShoe GX2 logger's preamble: a line that begins with "Inertial
 * data", or the "Header:" line naming a_x [g]. A mention of either inside
 * another line (a CSV's comment "# from a GX2 log, a_x [g] x 9.80665") is
 * not one. */
static int gx2_preamble(const char *text)
{
    const char *p = text;
    while (*p != '\0') {
        const char *e = strchr(p, '\n');
        size_t len = e != NULL ? (size_t)(e - p) : strlen(p);
        while (len > 0 && (*p == ' ' || *p == '\t' || *p == '\r')) {
            p++;
            len--;
        }
        if (len >= 13 && strncmp(p, "Inertial data", 13) == 0) {
            return 1;
        }
        if (len >= 7 && strncmp(p, "Header:", 7) == 0) {
            char line[600];
            memcpy(line, p, len < sizeof line ? len : sizeof line - 1);
            line[len < sizeof line ? len : sizeof line - 1] = '\0';
            if (strstr(line, "a_x [g]") != NULL) {
                return 1;
            }
        }
        if (e == NULL) {
            break;
        }
        p = e + 1;
    }
    return 0;
}

/* Whether the first line of text is n numbers (n in 1..HX_MAX_COLS) and
 * nothing else, separated by commas, tabs, semicolons or blanks, a trailing
 * separator allowed: the headerless OpenShoe 820 Hz file, also as a
 * spreadsheet or MATLAB (save -ascii) writes it. */
static int count_numbers(const char *text)
{
    int n = 0;
    const char *p = text;
    for (;;) {
        char tok[64];
        size_t k = 0;
        double v;
        while (*p == ',' || *p == ';' || *p == '\t' || *p == ' ' || *p == '\r') {
            p++;
        }
        if (*p == '\0' || *p == '\n') {
            return n;
        }
        while (*p != '\0' && *p != '\n' && *p != ',' && *p != ';' && *p != '\t' && *p != ' ' && *p != '\r') {
            if (k + 1 >= sizeof tok) {
                return -1;
            }
            tok[k++] = *p++;
        }
        tok[k] = '\0';
        if (parse_num(tok, &v) != 0 || ++n > HX_MAX_COLS) {
            return -1;
        }
    }
}

static int full_interchange_header(const char *head)
{
    static const char *const names[7] = { "t", "ax", "ay", "az", "gx", "gy", "gz" };
    int i;
    for (i = 0; i < 7; i++) {
        if (!has_field(head, names[i])) {
            return 0;
        }
    }
    return 1;
}

/* Whether a comment line (text after its '#') is the interchange header,
 * as numpy's savetxt writes it: "# t,ax,..." (the name t is enough), or
 * blank-separated "# t ax ay az gx gy gz" (all seven, so that a note such
 * as "# t is in seconds" is not taken for one): 1; or names read without
 * --columns, a time and the six channels (EuRoC's "#timestamp [ns],..."):
 * 2, a header only when data follows it (data_follows); else 0. */
static int comment_header(const char *text)
{
    char head[600], copy[2048], *f[HX_MAX_COLS];
    hx_names_match_t m;
    int n;
    squeeze_header(text, head, sizeof head);
    if (blank_separated(text)) {
        return full_interchange_header(head);
    }
    if (has_field(head, "t")) {
        return 1;
    }
    /* a header of names read without --columns, time and all six
     * channels, behind the comment sign: EuRoC's and TUM-VI's
     * "#timestamp [ns],w_RS_S_x [rad s^-1],..." */
    copy_str(copy, sizeof copy, text);
    copy[strcspn(copy, "\n")] = '\0';
    n = split(copy, strchr(copy, ',') != NULL ? ',' : strchr(copy, '\t') != NULL ? '\t' : ';', f, HX_MAX_COLS);
    return n >= 7 && hx_names_match(f, n, &m) && m.col[0] >= 0 ? 2 : 0;
}

int hx_sep_line(const char *s, char *d)
{
    if (*s == '"') {
        s++;
    }
    if (tolower((unsigned char)s[0]) != 's' || tolower((unsigned char)s[1]) != 'e' ||
        tolower((unsigned char)s[2]) != 'p' || s[3] != '=' || s[4] == '\0' || s[4] == '\r' || s[4] == '\n') {
        return 0;
    }
    *d = s[4];
    s += 5;
    if (*s == '"') {
        s++;
    }
    while (*s == '\r' || *s == '\n') {
        s++;
    }
    return *s == '\0' && (*d == ',' || *d == ';' || *d == '\t' || *d == '|');
}

hx_comment_t hx_comment_line(const char *line, const char **text)
{
    int ch;
    if (!comment(line)) {
        return HX_COMMENT_NONE;
    }
    line = strchr(line, '#') + 1;
    ch = comment_header(line);
    while (*line == ' ' || *line == '\t') {
        line++;
    }
    *text = line;
    return ch == 1 ? HX_COMMENT_HEADER : ch == 2 ? HX_COMMENT_HEADER_IF_DATA : HX_COMMENT_NOTE;
}

/* The PLab PicoQuake acquisition CSV's first line. */
#define PQ_SIGNATURE "# PLab PicoQuake Data"

static hx_format_t detect(const unsigned char *b, size_t n)
{
    char text[600], head[600];
    size_t m;
    if (n >= 4 && memcmp(b, HX_BIN_MAGIC, 4) == 0) {
        return HX_FMT_BIN;
    }
    if (n >= 3 && memcmp(b, "\xef\xbb\xbf", 3) == 0) {
        b += 3; /* UTF-8 byte-order mark (read_line drops it too) */
        n -= 3;
    }
    m = n < sizeof text - 1 ? n : sizeof text - 1;
    memcpy(text, b, m);
    text[m] = '\0';
    if (gx2_preamble(text)) {
        return HX_FMT_GX2;
    }
    if (strncmp(text, PQ_SIGNATURE, sizeof PQ_SIGNATURE - 1) == 0) {
        return HX_FMT_PICOQUAKE; /* the first line its writer puts (PicoQuake's AcquisitionData.to_csv) */
    }
    {
        /* The first non-blank line, lower case, without spaces and quotes:
         * a header is known by the names it holds, in any order, with a
         * leading index column, ", " or tabs between them */
        char *h = text;
        for (;;) {
            char first[16], d;
            while (*h == '\n' || *h == '\r' || *h == ' ' || *h == '\t') {
                h++;
            }
            copy_str(first, sizeof first, h);
            first[strcspn(first, "\n")] = '\0';
            if (hx_sep_line(first, &d) && strchr(h, '\n') != NULL) {
                h = strchr(h, '\n') + 1; /* Excel's separator line: the header is the next */
                continue;
            }
            if (*h != '#') {
                break;
            }
            /* a commented header ("# t,ax,...", numpy's savetxt) is the
             * plain format's; other comment lines are skipped */
            if (comment_header(h + 1)) {
                return HX_FMT_CSV;
            }
            h = strchr(h, '\n');
            if (h == NULL) {
                return HX_FMT_CSV;
            }
        }
        memmove(text, h, strlen(h) + 1);
        squeeze_line(text, head, sizeof head);
        if (strncmp(head, "acquisitionfrequency", 20) == 0) {
            return HX_FMT_IPOL;
        }
        squeeze_header(text, head, sizeof head);
        if (full_interchange_header(head)) {
            /* every column of the interchange format: ours, even if it
             * also carries a foreign format's names (a converted log that
             * kept its source's columns) */
            return HX_FMT_CSV;
        }
        if (has_field(head, "time(s)") && has_field(head, "gyroscopex(deg/s)") && has_field(head, "accelerometerx(g)")) {
            return HX_FMT_NGIMU;
        }
        if (has_field(head, "t_s") && has_field(head, "ax_mps2") && has_field(head, "gx_radps")) {
            return HX_FMT_PYSHOE;
        }
        if (has_field(head, "gyro_x_dps") && has_field(head, "acc_x_g")) {
            /* the data set's names, but with a time column beside them
             * ("timestamp_ms,acc_x_g,...,gyro_z_dps"): another logger's, read
             * by its stamps with the names matched (the adis reader has no
             * time and would read it at 100 Hz; test_bad_input.sh) */
            return has_time_field(head) ? HX_FMT_CSV : HX_FMT_ADIS;
        }
        if (has_field(head, "sample") && has_field(head, "f_x_mps2") && has_field(head, "w_x_radps")) {
            return HX_FMT_SQUARE2;
        }
        if (has_field(head, "count") && has_field(head, "a_x") && has_field(head, "g_x") && !has_time_field(head)) {
            return HX_FMT_PICOQUAKE; /* PicoQuake's header without its preamble: the rate is asked for */
        }
        if (has_field(head, "t")) {
            return HX_FMT_CSV;
        }
        if (hx_mtmgr_detect(text)) {
            /* Xsens MT Manager's export, by its '//' preamble or its header
             * (none of the names above is in it) */
            return HX_FMT_MTMGR;
        }
    }
    if (count_numbers(text) == 6) {
        /* headerless: six numbers -> OpenShoe 820 Hz */
        return HX_FMT_OS820;
    }
    return HX_FMT_CSV;
}

/* ------------------------------------------------------------ text setup */

/* Equal but for case, blanks (spaces, tabs), quotes and carriage returns
 * ("Time(s)" is "Time (s)", "acc_x" is "Acc_X"), as detection compares
 * names (squeeze_line); also the MT Manager reader's (hx_xsens.c). */
int hx_name_eq(const char *a, const char *b)
{
    for (;;) {
        while (*a == ' ' || *a == '\t' || *a == '"' || *a == '\'' || *a == '\r') {
            a++;
        }
        while (*b == ' ' || *b == '\t' || *b == '"' || *b == '\'' || *b == '\r') {
            b++;
        }
        if (*a == '\0' || *b == '\0') {
            return *a == *b;
        }
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) {
            return 0;
        }
        a++;
        b++;
    }
}

/* The fields a header names, of its `total`: a delimiter at its end names
 * none (a spreadsheet's export), so rows without one have every field and
 * are not warned "fewer fields than the header's". The names split kept
 * (n) are enough to tell, unless it kept fewer than total. */
int hx_named_fields(char **f, int n, int total)
{
    while (n == total && n > 1 && f[n - 1][0] == '\0') {
        n--;
        total--;
    }
    return total;
}

int hx_fields_total(const char *line, char delim)
{
    const char *q;
    int quoted = 0, total = 1;
    for (q = line; delim != ' ' && *q != '\0'; q++) {
        quoted ^= *q == '"';
        total += *q == delim && !quoted;
    }
    return total;
}

int hx_find_col(char **f, int n, const char *name)
{
    int i;
    for (i = 0; i < n; i++) {
        if (hx_name_eq(f[i], name)) {
            return i;
        }
    }
    return -1;
}

/* every field a number or a date and time: the line is data, not a header */
static int all_numeric(char **f, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        char *end;
        const char *s = f[i];
        int64_t t_ns;
        while (*s == ' ' || *s == '\t') {
            s++;
        }
        if (parse_datetime_ns(s, &t_ns) == 0) {
            continue;
        }
        (void)strtod(s, &end);
        if (end == s) {
            return 0;
        }
        while (*end == ' ' || *end == '\t' || *end == '\r' || *end == '\n') {
            end++;
        }
        if (*end != '\0') {
            return 0;
        }
    }
    return n > 0;
}

/* The header's names matched without --columns (hx_names.h; docs/log-format.md,
 * "Names read without --columns"): the names and the units they name into
 * r->layout (a --units item given keeps its unit), and the warning that says
 * it as the options that make it explicit. */
static void names_apply(hx_reader_t *r, hx_names_match_t *m, char *const *f, int n)
{
    hx_csv_layout_t *l = &r->layout;
    char give[700];
    int k;
    for (k = 0; k < 7; k++) {
        if (m->col[k] >= 0) {
            hx_name_bare(f[m->col[k]], l->names[k], sizeof l->names[k]);
        }
    }
    if (m->col_tns >= 0) {
        hx_name_bare(f[m->col_tns], l->tns, sizeof l->tns);
    }
    for (k = 0; k < 3; k++) {
        if (!(l->units_given & (1 << k))) {
            layout_unit(l, m->unit[k]);
        }
    }
    l->names_matched = 1;
    r->ros = m->ros;
    r->kalibr = m->kalibr;
    r->sensorlog = m->sensorlog;
    l->negate |= m->negate; /* SensorLog's ax..az: iOS's sign */
    r->gforce = m->gforce;
    /* the warning names the units the log is read in (not the defaults) */
    m->unit[0] = l->time_digits == 6 ? HX_UNIT_MS : l->time_digits == 3 ? HX_UNIT_US
                 : l->time_digits == 0 ? HX_UNIT_NS : HX_UNIT_NONE;
    m->unit[1] = acc_unit_of(l->acc_scale);
    m->unit[2] = l->gyr_scale == HX_DPS_RPS ? HX_UNIT_DPS : l->gyr_scale == HX_MDPS_RPS ? HX_UNIT_MDPS : HX_UNIT_NONE;
    {
        char near[300];
        (void)hx_names_near(m, f, near, sizeof near);
        /* ROS: the names' family, and a receive time read for want of the
         * message's own stamp (%time, bagpy's Time) */
        hx_name_unit_t ru;
        const int receive = m->ros && m->col[0] >= 0 && m->col[0] == hx_names_ros_receive(f, n, &ru);
        char times[160] = "";
        if (m->times > 1) {
            snprintf(times, sizeof times, "; of %d time names, the first that names its unit read%s", m->times,
                     m->times_clock ? " (a clock's since 1970 only where no other is)" : "");
        }
        add_warn(r, "%s: header read as %s (%s%s%s%s%s; give --columns to choose otherwise)", r->path,
                 hx_names_give(m, f, give, sizeof give),
                 m->ros      ? "a ROS sensor_msgs/Imu's names matched, in SI units as REP 103 sets them"
                 : m->sensorlog
                     ? "SensorLog's names matched: the accelerometer with iOS's sign (z -1 g face up), read negated "
                       "as the specific force"
                 : m->kalibr ? "Kalibr's IMU CSV names matched: the stamp in ns, omega in rad/s, alpha the "
                               "specific force in m/s^2, as Kalibr's bag format sets them"
                 : m->gforce ? "names matched; gFx..gFz, Physics Toolbox's g-force, are the specific force"
                               " in g"
                             : "names matched",
                 receive ? "; the time is the bag's receive time, the message's stamp not found" : "", times,
                 near[0] != '\0' ? "; not read: " : "", near);
    }
}

/* The columns of names[0..7] (t, ax..gz, temp; NULL: not read) among the
 * n header fields f, set in r in that order, r->ncols_needed with them,
 * up to the first name that is required and missing: its index, kept in
 * r->missing_col; -1 when none is. A name --columns gave is required, also
 * temp's and t's with a rate given (not dropped without a word); t is
 * required when time_required. */
static int find_columns(hx_reader_t *r, const char *const names[8], char **f, int n, int time_required)
{
    int i;
    r->ncols_needed = 0;
    r->missing_col = -1;
    for (i = 0; i < 8; i++) {
        int c = (names[i] != NULL) ? hx_find_col(f, n, names[i]) : -1;
        const int given = r->meta.format == HX_FMT_CSV && r->layout.names[i][0] != '\0';
        if (c < 0 && names[i] != NULL && (given || ((i < 7) && (i > 0 || time_required)))) {
            r->missing_col = i;
            return i;
        }
        if (i == 0) {
            r->col_t = c;
        } else if (i <= 3) {
            r->col_a[i - 1] = c;
        } else if (i <= 6) {
            r->col_g[i - 4] = c;
        } else {
            r->col_temp = c;
        }
        if (c + 1 > r->ncols_needed) {
            r->ncols_needed = c + 1;
        }
    }
    return -1;
}

/* A column read whose name the header gives twice: the first is read, and
 * the warning says so, rather than reading it without a word. The first
 * such name is named. */
static void dup_names_warn(hx_reader_t *r, const char *const names[8], char **f, int n)
{
    int i, k;
    for (i = 0; i < 8; i++) {
        const int c = names[i] != NULL ? hx_find_col(f, n, names[i]) : -1;
        for (k = c + 1; c >= 0 && k < n; k++) {
            if (hx_name_eq(f[k], names[i])) {
                add_warn(r, "%s:%ld: the header names '%s' twice (columns %d and %d): column %d is read (--columns "
                            "cannot choose between them: rename the other to read it)",
                         r->path, r->stats.lines, names[i], c + 1, k + 1, c + 1);
                return;
            }
        }
    }
}

/* The formats without time stamps (adis; square2, whose counter is read at
 * a rate): the first column the names reader would take for time
 * (hx_name_classify: t, timestamp_ms, "Time (s)"), which the format does
 * not read, kept to be named in a warning with how to read it. */
static void time_beside(hx_reader_t *r, char **f, int n)
{
    int k;
    r->time_beside[0] = '\0';
    for (k = 0; k < n; k++) {
        hx_name_class_t c;
        char bare[64];
        hx_name_bare(f[k], bare, sizeof bare);
        if (k != r->col_t && hx_name_classify(bare, &c) == HX_NAME_MATCH && c.key == 0) {
            copy_str(r->time_beside, sizeof r->time_beside, bare);
            r->time_beside_unit = c.unit;
            return;
        }
    }
}

/* The warning of a time column left unread (time_beside): what is read
 * instead, and the --from csv that reads the stamps; cols: the format's
 * channels as --columns gives them, units: theirs as --units gives them
 * ("" SI). */
static void time_beside_warn(hx_reader_t *r, const char *fmt, const char *instead, const char *cols, const char *units)
{
    const hx_name_unit_t u = r->time_beside_unit;
    const char *tu = u == HX_UNIT_MS ? "time=ms" : u == HX_UNIT_US ? "time=us" : u == HX_UNIT_NS ? "time=ns" : "";
    char give[96];
    if (tu[0] != '\0' || units[0] != '\0') {
        snprintf(give, sizeof give, " --units %s%s%s", tu, tu[0] != '\0' && units[0] != '\0' ? "," : "", units);
    } else {
        give[0] = '\0';
    }
    add_warn(r, "%s: the column '%s' is not read: the %s format has no time stamps (%s); to read them, give --from "
                "csv --columns t=%s,%s%s%s",
             r->path, r->time_beside, fmt, instead, r->time_beside, cols, give,
             u != HX_UNIT_NONE ? ""
             : give[0] != '\0' ? " (and time=ms, us or ns if it is not in s)"
                               : " (and --units time=ms, us or ns if it is not in s)");
}

/* A column of the interchange CSV whose name states a unit other than the
 * one it is read in (--columns named it, and --units or the default sets
 * the unit): warned, the first such, with the --units that reads what the
 * names state; the values are read as asked ('acc_x [g]' given with
 * --columns alone is read as m/s^2, which would otherwise go without a
 * word). The names matched without --columns set their units themselves. */
static void units_named_warn(hx_reader_t *r, char **f, int n)
{
    static const char *const what[3] = { "the time", "the accelerations", "the rates" };
    static const char *const tu[4] = { "s", "ms", "us", "ns" };
    const hx_csv_layout_t *l = &r->layout;
    hx_csv_layout_t want = *l;
    int k, col_first = -1, q_first = 0;
    hx_name_unit_t u_first = HX_UNIT_NONE;
    if (r->meta.format != HX_FMT_CSV || l->names_matched) {
        return;
    }
    for (k = 0; k < 7; k++) {
        const int col = k == 0 ? r->col_t : k <= 3 ? r->col_a[k - 1] : r->col_g[k - 4];
        const int q = k == 0 ? 0 : k <= 3 ? 1 : 2;
        hx_name_class_t c;
        int differs;
        if (col < 0 || col >= n || hx_name_classify(f[col], &c) != HX_NAME_MATCH || c.unit == HX_UNIT_NONE) {
            continue;
        }
        layout_unit(&want, c.unit);
        differs = q == 0 ? want.time_digits != l->time_digits
                  : q == 1 ? want.acc_scale != l->acc_scale
                           : want.gyr_scale != l->gyr_scale;
        if (differs && col_first < 0) {
            col_first = col;
            q_first = q;
            u_first = c.unit;
        }
    }
    if (col_first >= 0) {
        char name[128], give[160];
        const char *item = hx_name_unit_item(u_first), *in;
        in = q_first == 0   ? tu[(9 - l->time_digits) / 3]
             : q_first == 1 ? hx_accel_unit_name(l->acc_scale)
                            : hx_gyro_unit_name(l->gyr_scale);
        hx_name_bare(f[col_first], name, sizeof name);
        (void)hx_units_give(&want, give, sizeof give);
        add_warn(r, "%s:%ld: column %d ('%s') names %s, but %s %s read in %s (%s %s the column's unit)", r->path,
                 r->stats.lines, col_first + 1, name, item != NULL ? strchr(item, '=') + 1 : "?", what[q_first],
                 q_first == 0 ? "is" : "are", in, strncmp(give, "give ", 5) == 0 ? give + 5 : give,
                 strncmp(give, "give ", 5) == 0 ? "reads" : "to read");
    }
}

/* Back to pos, where the reader was before looking ahead (the line
 * count lines then): the lines read since are read again. 0, or -1 with
 * the error (a stream that cannot seek back). */
static int read_again_from(hx_reader_t *r, z_off_t pos, long lines)
{
    if (pos < 0 || gzseek(r->gz, pos, SEEK_SET) != pos) {
        set_err(r, "%s:%ld: cannot read the first row again (seek failed)", r->path, r->stats.lines);
        return -1;
    }
    r->stats.lines = lines;
    r->last_line_open = 0;
    return 0;
}

/* PicoQuake's preamble, the '#' lines before its header: the rate of the
 * sample count from "# Config: data_rate = 2000.0 Hz, filter = ..." (the
 * writer's Config, with "Hz" or without as PLab's versions differ) into
 * *fs_hz (0: no such line) and its line; the reader then stands before the
 * header. A data_rate of 2 without "Hz" is no rate of the device: a
 * version of PLab's library writes 2 for its 12.5 Hz setting
 * (DataRate.hz_12_5 = 1, 2), whose index 1 is also its 25 Hz's; refused,
 * or with --input-rate warned about. A second Config line is
 * not read (a warning). A data_rate that is no rate in Hz is refused, or
 * with --input-rate (rate_hz > 0) warned about. 0 ok, -1 error (err set). */
static int pq_preamble(hx_reader_t *r, double rate_hz, double *fs_hz, long *line)
{
    for (;;) {
        const z_off_t pos = gztell(r->gz);
        const long lines = r->stats.lines;
        const char *p;
        char *end;
        double fs = 0.0;
        int hz = 0;
        const int rc = read_line(r);
        if (rc <= 0) {
            if (rc == 0) {
                set_err(r, "%s: no header line after the PicoQuake preamble", r->path);
            }
            return -1;
        }
        if (!comment(r->line) && !blank(r->line)) {
            return read_again_from(r, pos, lines);
        }
        p = strstr(r->line, "data_rate");
        if (strncmp(r->line, "# Config:", 9) != 0 || p == NULL) {
            continue;
        }
        if (*line > 0) {
            add_warn(r, "%s:%ld: a second '# Config:' line, not read (the first, line %ld, is the file's)", r->path,
                     r->stats.lines, *line);
            continue;
        }
        p += 9;
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        end = NULL;
        if (*p == '=') {
            p++;
            fs = strtod(p, &end);
            while (end != p && (*end == ' ' || *end == '\t')) {
                end++;
            }
            if (end != p && (end[0] == 'H' || end[0] == 'h') && (end[1] == 'z' || end[1] == 'Z')) {
                end += 2;
                hz = 1;
            }
        }
        if (end == NULL || end == p || !(*end == ',' || *end == '\r' || *end == '\n' || *end == '\0') ||
            !(fs >= 1.0e-3 && fs < 1.0e6)) {
            if (rate_hz > 0.0) {
                add_warn(r, "%s:%ld: the data_rate of '# Config:' is no rate in Hz; --input-rate %g Hz is read",
                         r->path, r->stats.lines, rate_hz);
                *line = r->stats.lines;
                continue;
            }
            set_err(r, "%s:%ld: expected '# Config: data_rate = N Hz, ...', a rate in Hz in [0.001, 1e+06) (or "
                       "give the rate with --input-rate)", r->path, r->stats.lines);
            return -1;
        }
        if (fs == 2.0 && !hz) {
            /* no rate of the device: not guessed */
            if (rate_hz > 0.0) {
                add_warn(r, "%s:%ld: data_rate = 2 is no PicoQuake rate; --input-rate %g Hz is read", r->path,
                         r->stats.lines, rate_hz);
                *line = r->stats.lines;
                continue;
            }
            set_err(r, "%s:%ld: data_rate = 2 is no PicoQuake rate: a version of PLab's library writes 2 for its "
                       "12.5 Hz setting, whose index its firmware reads as 25 Hz; give the rate with --input-rate",
                    r->path, r->stats.lines);
            return -1;
        }
        *fs_hz = fs;
        *line = r->stats.lines;
    }
}

/* The row of units under a header: Shimmer's Consensys export writes one
 * (hx_names_consensys), and so do loggers and hand-made spreadsheets
 * (`s,g,g,g,deg/s,...` under `time,acc_x,...`). The units of the time,
 * accel and gyro columns read, for those --units does not give, said in a
 * warning. A row of data there instead (an export without its units row)
 * is left to be read, and so, under another header, is a row whose first
 * column read (the time's, else the accelerometer's) is no unit: its
 * error is the data's. 0 ok, -1 error (err set). */
static int units_row(hx_reader_t *r, int consensys)
{
    static const char *const what[3] = { "time", "accel", "gyro" };
    hx_csv_layout_t *l = &r->layout;
    char *f[HX_MAX_COLS], said[160] = "";
    const long lines = r->stats.lines;
    const z_off_t pos = gztell(r->gz);
    hx_name_unit_t unit[3] = { HX_UNIT_NONE, HX_UNIT_NONE, HX_UNIT_NONE };
    int n, rc, q;
    double v;
    int64_t t_ns;
    rc = read_line(r);
    if (rc <= 0) {
        return rc < 0 ? -1 : 0;
    }
    n = split(r->line, r->delim, f, HX_MAX_COLS);
    if (r->col_t >= 0 && r->col_t < n &&
        (parse_num(f[r->col_t], &v) == 0 || parse_datetime_ns(f[r->col_t], &t_ns) == 0)) {
        return read_again_from(r, pos, lines); /* data: read again as the first row */
    }
    if (!consensys) {
        const int c0 = r->col_t >= 0 ? r->col_t : r->col_a[0];
        if (c0 < 0 || c0 >= n || hx_name_unit_of_text(f[c0]) == HX_UNIT_NONE) {
            return read_again_from(r, pos, lines);
        }
    }
    for (q = 0; q < 3; q++) {
        const int *cols = q == 0 ? &r->col_t : q == 1 ? r->col_a : r->col_g;
        const int ncol = q == 0 ? 1 : 3;
        int a;
        if (l->units_given & (1 << q) || cols[0] < 0) {
            continue; /* --units rules; no time column */
        }
        for (a = 0; a < ncol; a++) {
            const char *text = cols[a] < n ? f[cols[a]] : "";
            const hx_name_unit_t u = hx_name_unit_of_text(text);
            const int want = u == HX_UNIT_NONE ? -1 : u <= HX_UNIT_NS ? 0 : u <= HX_UNIT_UG ? 1 : 2;
            if (q == 0 && u == HX_UNIT_NONE && (strstr(text, "yyyy") != NULL || strstr(text, "YYYY") != NULL)) {
                break; /* stamps written as dates and times: they carry their unit */
            }
            if (want != q || (a > 0 && u != unit[q])) {
                set_err(r, "%s:%ld: the row of units under the header gives '%.40s' for the %s column%s; "
                        "give its unit with --units %s=...", r->path, r->stats.lines, text, what[q],
                        want != q ? ", not a unit of it read" : ", another than its first axis's", what[q]);
                return -1;
            }
            unit[q] = u;
        }
    }
    for (q = 0; q < 3; q++) {
        const char *item = hx_name_unit_item(unit[q]);
        layout_unit(l, unit[q]);
        if (item != NULL) {
            const size_t len = strlen(said);
            snprintf(said + len, sizeof said - len, "%s%s", len > 0 ? "," : "", item);
        }
    }
    add_warn(r, "%s:%ld: a row of units under the header%s: read as --units %s", r->path, r->stats.lines,
             consensys ? " (Shimmer's Consensys export)" : "", said[0] != '\0' ? said : "(none: the units given)");
    return 0;
}

/* The column of nanoseconds added to t (layout.tns: --columns tns=, or
 * a ROS stamp split in two columns): found, or an error naming it; it
 * adds to whole seconds, so t must be read in s. 0 ok, -1 error. */
static int tns_column(hx_reader_t *r, char **f, int n)
{
    const char *why = g_layout.tns[0] != '\0' ? "the name --columns gives tns" : "the split stamp's nanoseconds";
    r->col_tns = hx_find_col(f, n, r->layout.tns);
    if (r->col_tns < 0) {
        set_err(r, "%s:%ld: header has no column '%s' (%s)", r->path, r->stats.lines, r->layout.tns, why);
        return -1;
    }
    if (r->col_t < 0 || r->layout.time_digits != 9) {
        set_err(r, "%s:%ld: --columns tns=%s adds nanoseconds to the whole seconds of a time column: %s", r->path,
                r->stats.lines, r->layout.tns,
                r->col_t < 0 ? "give the seconds' column with t=NAME" : "its unit must be s (--units time=s)");
        return -1;
    }
    if (r->col_tns + 1 > r->ncols_needed) {
        r->ncols_needed = r->col_tns + 1;
    }
    return 0;
}

/* A ROS topic read by the message's stamp (names matched, hx_names_ros)
 * whose first row has it 0, as a driver that never sets the stamp writes
 * it (an unset header.stamp is 0): the bag's receive
 * time beside it (%time in ns, bagpy's Time in s) is read instead, with a
 * warning; the row is read again as data. 0 ok, -1 error. */
static int ros_stamp_unset(hx_reader_t *r, char **f, int n)
{
    char name[64], stamp[64];
    const long lines = r->stats.lines;
    const z_off_t pos = gztell(r->gz);
    hx_name_unit_t unit = HX_UNIT_NONE;
    const int recv = hx_names_ros_receive(f, n, &unit), digits = unit == HX_UNIT_NS ? 0 : 9;
    int m, rc;
    double v, vns = 0.0;
    if (recv < 0 || recv == r->col_t || r->col_t < 0) {
        return 0;
    }
    hx_name_bare(f[recv], name, sizeof name);
    hx_name_bare(f[r->col_t], stamp, sizeof stamp);
    rc = read_line(r);
    if (rc <= 0) {
        return rc < 0 ? -1 : 0;
    }
    m = split(r->line, r->delim, f, HX_MAX_COLS);
    rc = m > r->col_t && m > r->col_tns && parse_num(f[r->col_t], &v) == 0 && v == 0.0 &&
         (r->col_tns < 0 || (parse_num(f[r->col_tns], &vns) == 0 && vns == 0.0));
    if (read_again_from(r, pos, lines) != 0) {
        return -1;
    }
    if (rc) {
        add_warn(r, "%s:%ld: the message's stamp (%s) is 0: the driver left it unset; the bag's receive time, "
                    "'%s', is read instead",
                 r->path, lines + 1, stamp, name);
        r->col_t = recv;
        r->col_tns = -1;
        r->layout.tns[0] = '\0';
        copy_str(r->layout.names[0], sizeof r->layout.names[0], name);
        r->layout.time_digits = digits;
        if (recv + 1 > r->ncols_needed) {
            r->ncols_needed = recv + 1;
        }
    }
    return 0;
}

int hx_data_row(const char *line)
{
    const char *b = line + strspn(line, " \t\"");
    char first[64];
    double v;
    int64_t t_ns;
    snprintf(first, sizeof first, "%.*s", (int)strcspn(b, ",;\t \"\r\n"), b);
    return parse_num(first, &v) == 0 || parse_datetime_ns(first, &t_ns) == 0 ||
           (strlen(first) == 10 && isdigit((unsigned char)first[0]) && (first[4] == '-' || first[4] == '/'));
}

/* Whether the next line that is not blank is a row of data, its first
 * field a number or a date: a comment of names before it is the header
 * (comment_header 2); before another header line, or none, it is a note.
 * The reader is left as it was, r->line too. 1 data, 0 not, -1 error. */
static int data_follows(hx_reader_t *r)
{
    char keep[HX_LINE_MAX];
    const long lines = r->stats.lines;
    const z_off_t pos = gztell(r->gz);
    int rc, data = 0;
    memcpy(keep, r->line, sizeof keep);
    while ((rc = read_line(r)) > 0 && blank(r->line)) {
    }
    if (rc > 0) {
        data = hx_data_row(r->line);
    }
    if (read_again_from(r, pos, lines) != 0) {
        return -1;
    }
    memcpy(r->line, keep, sizeof keep);
    return data;
}

/* A log without a header, its columns given by number (--columns t=1,
 * ax=2,...: 1 the first field): when the first line is data and every
 * column --columns names is a number, the columns read are those, the
 * time's too where a time is required (else --input-rate's). 1 applied
 * (a warning says so; the caller reads the line again as data), 0 not
 * numbers (the first line's error as before), -1 error (err set). */
/* A line of whole numbers counting its columns, 0,1,2,... or 1,2,3,...
 * (pandas' header of an array): its first number, else -1. */
static long index_row_base(char **f, int n)
{
    char *end;
    const long base = strtol(f[0], &end, 10);
    int k, ok = n > 1 && (base == 0 || base == 1);
    for (k = 0; k < n && ok; k++) {
        ok = strtol(f[k], &end, 10) == base + k && *end == '\0' && end != f[k];
    }
    return ok ? base : -1;
}

static int numbered_columns(hx_reader_t *r, char **f, int n, int time_required)
{
    int k, given = 0, col[8], all_named = 1, index_row, col_tns = -1;
    for (k = 0; k <= 8; k++) { /* 8: tns */
        const char *v = k < 8 ? r->layout.names[k] : r->layout.tns;
        if (v[0] != '\0' && (!isdigit((unsigned char)v[0]) || strspn(v, "0123456789") != strlen(v))) {
            return 0; /* a name: a header is expected */
        }
        all_named &= v[0] == '\0' || hx_find_col(f, n, v) >= 0;
    }
    index_row = index_row_base(f, n) >= 0;
    if (all_named || index_row) {
        /* every number given is a field of the line (a header of numbers:
         * read by name, as before), or the line counts its columns from 0
         * or 1 (pandas' header of an array): a header */
        return 0;
    }
    for (k = 0; k <= 8; k++) {
        const char *v = k < 8 ? r->layout.names[k] : r->layout.tns;
        long c;
        if (k < 8) {
            col[k] = -1;
        }
        if (v[0] == '\0') {
            continue;
        }
        c = strtol(v, NULL, 10);
        if (c < 1 || c > n) {
            set_err(r, "%s:%ld: --columns %s=%s: the line has %d fields, numbered 1 to %d", r->path,
                    r->stats.lines, k < 8 ? k_csv_names[k] : "tns", v, n, n);
            return -1;
        }
        if (k == 8) {
            col_tns = (int)c - 1;
        } else {
            col[k] = (int)c - 1;
            given |= 1 << k;
        }
    }
    if (given == 0) {
        return 0;
    }
    for (k = 0; k < 7; k++) {
        if (!(given & (1 << k)) && (k > 0 || time_required)) {
            set_err(r, "%s:%ld: the log has no header and --columns numbers some columns but not %s: give each "
                       "of t,ax,ay,az,gx,gy,gz by number (t=1,ax=2,...)%s",
                    r->path, r->stats.lines, k_csv_names[k], k == 0 ? ", or the rate with --input-rate HZ" : "");
            return -1;
        }
    }
    r->col_t = col[0];
    r->col_temp = col[7];
    r->ncols_needed = 0;
    r->missing_col = -1;
    for (k = 0; k < 3; k++) {
        r->col_a[k] = col[1 + k];
        r->col_g[k] = col[4 + k];
    }
    for (k = 0; k < 8; k++) {
        r->ncols_needed = col[k] + 1 > r->ncols_needed ? col[k] + 1 : r->ncols_needed;
    }
    if (col_tns >= 0) {
        if (r->col_t < 0 || r->layout.time_digits != 9) {
            set_err(r, "%s:%ld: --columns tns=%s adds nanoseconds to the whole seconds of a time column: %s",
                    r->path, r->stats.lines, r->layout.tns,
                    r->col_t < 0 ? "give the seconds' column with t=N" : "its unit must be s (--units time=s)");
            return -1;
        }
        r->col_tns = col_tns;
        r->ncols_needed = col_tns + 1 > r->ncols_needed ? col_tns + 1 : r->ncols_needed;
    }
    r->hdr_fields = n;
    add_warn(r, "%s:%ld: no header: the columns read by the numbers --columns gives", r->path, r->stats.lines);
    return 1;
}

static int setup_header(hx_reader_t *r, const char *const names_in[8], int time_required)
{
    char *f[HX_MAX_COLS], dc_first[64], matched[1000] = "";
    const char *names[8];
    int n, i, rc, total, dc_line, tried = 0, sep_given = 0, consensys, units;
    hx_comment_t ch;
    const char *text;
    static const char *const what[8] = { "t", "ax", "ay", "az", "gx", "gy", "gz", "temp" };
    z_off_t hpos = 0;
    long hlines = 0;
    for (i = 0; i < 8; i++) {
        names[i] = names_in[i];
    }
    for (;;) {
        hpos = gztell(r->gz); /* the header line's start: a log without one reads it again */
        hlines = r->stats.lines;
        rc = read_line(r);
        if (rc <= 0) {
            if (rc == 0) {
                set_err(r, "%s: empty file (no header line)", r->path);
            }
            return -1;
        }
        if (blank(r->line)) {
            continue;
        }
        if (!sep_given && hx_sep_line(r->line, &r->delim)) {
            sep_given = 1; /* the separator the line names, the header's next */
            continue;
        }
        if (r->meta.format == HX_FMT_CSV && (ch = hx_comment_line(r->line, &text)) != HX_COMMENT_NONE) {
            /* "# t,ax,...": the header behind the comment sign; any other
             * comment line before the header is skipped */
            if (ch == HX_COMMENT_NOTE) {
                continue;
            }
            if (ch == HX_COMMENT_HEADER_IF_DATA) {
                const int data = data_follows(r);
                if (data < 0) {
                    return -1;
                }
                if (!data) {
                    continue; /* a note naming the columns before the header itself */
                }
            }
            memmove(r->line, text, strlen(text) + 1);
        }
        break;
    }
    if (strchr(r->line, r->delim) == NULL) {
        /* the interchange format and the comma-separated foreign ones: a
         * spreadsheet's tab- or semicolon-separated export is read the same
         * way (detection accepts those separators too); the tab-separated
         * ipol file also with commas, semicolons or blanks; and any of them
         * with blanks alone, whose runs then separate the names (numpy's
         * savetxt with its default delimiter; a name with a blank in it,
         * as the ngimu's "Time (s)", is then not found) */
        if (strchr(r->line, ',') != NULL) {
            r->delim = ',';
        } else if (strchr(r->line, '\t') != NULL) {
            r->delim = '\t';
        } else if (strchr(r->line, ';') != NULL) {
            r->delim = ';';
        } else {
            r->delim = ' ';
        }
    }
    total = hx_fields_total(r->line, r->delim); /* the header's own count of fields: split keeps HX_MAX_COLS */
    dc_line = decimal_comma_line(r->line, dc_first, sizeof dc_first);
    n = split(r->line, r->delim, f, HX_MAX_COLS);
    r->hdr_fields = r->delim == ' ' || total > HX_MAX_COLS ? n : hx_named_fields(f, n, total);
    /* a unit alone between blanks ("Time (s) Gyroscope X (deg/s)", x-io's
     * names with the commas made blanks): names that hold blanks, which a
     * blank-separated file cannot tell from fields; named where the
     * columns do not fit */
    r->unit_field = 0;
    units = 0;
    for (i = 0; r->delim == ' ' && i < n; i++) {
        if (f[i][0] == '(' || f[i][0] == '[') {
            units++;
            if (r->unit_field == 0) {
                /* cut to fit, and marked so */
                const int cut = strlen(f[i]) >= sizeof r->unit_text;
                r->unit_field = i + 1;
                copy_str(r->unit_text, sizeof r->unit_text - (cut ? 3 : 0), f[i]);
                if (cut) {
                    strcat(r->unit_text, "...");
                }
            }
        }
    }
    if (r->meta.format == HX_FMT_CSV && !dc_line && all_numeric(f, n)) {
        const int h = numbered_columns(r, f, n, time_required);
        if (h != 0) {
            return h < 0 ? -1 : read_again_from(r, hpos, hlines);
        }
    }
    consensys = r->meta.format == HX_FMT_CSV && hx_names_consensys(f, n);
    for (;;) {
        i = find_columns(r, names, f, n, time_required);
        if (i < 0) {
            dup_names_warn(r, names, f, n);
            units_named_warn(r, f, n);
            if (r->meta.format == HX_FMT_ADIS || r->meta.format == HX_FMT_SQUARE2) {
                time_beside(r, f, n);
            }
            r->consensys = consensys;
            if (r->meta.format == HX_FMT_CSV && r->layout.tns[0] != '\0' && tns_column(r, f, n) != 0) {
                return -1;
            }
            if (r->ros && ros_stamp_unset(r, f, n) != 0) {
                return -1;
            }
            return r->meta.format == HX_FMT_CSV ? units_row(r, consensys) : 0;
        }
        if (r->meta.format == HX_FMT_CSV && !tried && total <= HX_MAX_COLS && !dc_line && !all_numeric(f, n)) {
            /* no --columns and the interchange names not all there: the
             * names of the six channels matched (a log refused before,
             * never one read before: docs/log-format.md, "Names read
             * without --columns") */
            int k, named = 0;
            for (k = 0; k < 8; k++) {
                named |= r->layout.names[k][0] != '\0';
            }
            if (!named) {
                hx_names_match_t m;
                tried = 1;
                if (hx_names_match(f, n, &m) && (m.col[0] >= 0 || !time_required)) {
                    names_apply(r, &m, f, n);
                    for (k = 0; k < 7; k++) {
                        if (r->layout.names[k][0] != '\0') {
                            names[k] = r->layout.names[k];
                        }
                    }
                    continue; /* the columns again, under the names matched */
                }
                /* something to say: a channel's name matched, and more
                 * than the interchange names the header has (t,ax,ay,az
                 * keeps its message, a stride table with a timestamp
                 * and a file of no IMU names theirs) */
                int six = 0, news = m.units_differ != 0;
                for (k = 0; k < 7; k++) {
                    six |= k > 0 && m.ncand[k] > 0;
                    news |= m.ncand[k] > 1 || m.nnear[k] > 0 ||
                            (m.ncand[k] == 1 && !hx_name_eq(f[m.cand[k][0]], k_csv_names[k]));
                }
                if (!m.excluded && (six || m.unit_col >= 0) && news) {
                    char give[700], miss[400], unit[300];
                    size_t ul;
                    (void)hx_names_give(&m, f, give, sizeof give);
                    (void)hx_names_unmatched(&m, f, time_required, miss, sizeof miss);
                    /* a name matched but for its unit says which (a unit
                     * not read, "gx [deg/h]", or another quantity's), so
                     * that such a name is mentioned */
                    snprintf(unit, sizeof unit, "; ");
                    ul = strlen(unit);
                    if (hx_names_unit_problem(&m, f, unit + ul, sizeof unit - ul)[0] == '\0') {
                        unit[0] = '\0';
                    }
                    if (m.ok) {
                        /* all but the time: the no-time path's rate */
                        snprintf(matched, sizeof matched,
                                 "%.290s; names matched: %.400s; no time column%.150s: give the log's rate with "
                                 "--input-rate HZ, or its time column with --columns t=NAME too",
                                 unit, give, strncmp(miss, "t: none", 7) == 0 ? miss + 7 : "");
                    } else if (give[0] != '\0' || miss[0] != '\0') {
                        if (strlen(miss) > 250) {
                            /* more than the message holds (two devices'
                             * candidates for every channel): cut after a
                             * whole item and marked, not in a name */
                            char *cut;
                            miss[244] = '\0';
                            cut = strrchr(miss, ';');
                            snprintf(cut != NULL ? cut : miss + 244, 6, "; ...");
                        }
                        snprintf(matched, sizeof matched, "%.290s; names matched: %.400s; not matched: %.250s", unit,
                                 give[0] != '\0' ? give : "none", miss[0] != '\0' ? miss : "none");
                    }
                }
            }
        }
        break;
    }
    if (total > HX_MAX_COLS) {
        /* the column may be there, past the ones read (not "header has
         * no column 'gx'" of a header that has it) */
        set_err(r, "%s:%ld: header has %d columns; only the first %d are read, and '%s' is not among them",
                r->path, r->stats.lines, total, HX_MAX_COLS, names[i]);
    } else if (dc_line) {
        /* no header problem: no hint about the format's detection */
        r->missing_col = -1;
        set_err(r, "%s:%ld: the first line is numbers with a decimal comma ('%s'): " DECIMAL_COMMA_FIX,
                r->path, r->stats.lines, dc_first);
    } else if (r->meta.format == HX_FMT_CSV && r->layout.names[i][0] != '\0' && index_row_base(f, n) >= 0) {
        /* pandas' header of an array, read by its names: --columns t=1,...
         * counted from 1 where it counts from 0 (not told to give what it
         * gave) */
        const long base = index_row_base(f, n);
        set_err(r, "%s:%ld: the header counts the columns from %ld%s, and --columns names them as it does: %s=%s is "
                   "not one of its names, %ld to %ld (the first column is %ld)",
                r->path, r->stats.lines, base, base == 0 ? " (pandas' header of an array)" : "", what[i], names[i],
                base, base + n - 1, base);
    } else if (all_numeric(f, n)) {
        /* "the first line" only where it is line 1 (not ipol's line 2,
         * after its "Acquisition frequency", nor a line after comments) */
        set_err(r, "%s:%ld: the %s is data, not a header: a log of format %s starts with its header (%s)%s",
                r->path, r->stats.lines, r->stats.lines > 1 ? "line where the header belongs" : "first line",
                hx_format_name(r->meta.format),
                r->meta.format == HX_FMT_CSV ? "t,ax,ay,az,gx,gy,gz[,temp]" : "see docs/log-format.md",
                r->meta.format == HX_FMT_CSV && n >= 7 /* fields enough for a time and the six channels */
                    ? "; a log without one: give its columns by number, --columns t=1,ax=2,ay=3,az=4,gx=5,gy=6,"
                      "gz=7 in the interchange order (and --units for other units)"
                : r->meta.format == HX_FMT_CSV && n == 6
                    ? "; a log without one: give its columns by number and its rate, --columns ax=1,ay=2,az=3,"
                      "gx=4,gy=5,gz=6 --input-rate HZ in the interchange order (and --units for other units)"
                    : "");
    } else if (r->meta.format == HX_FMT_CSV && r->layout.names[i][0] != '\0') {
        /* a name the user gave: say where it came from */
        set_err(r, "%s:%ld: header has no column '%s' (the name --columns gives %s)", r->path,
                r->stats.lines, names[i], what[i]);
    } else if (r->meta.format == HX_FMT_CSV) {
        /* a header with the six others lacks only its time: say how
         * to give the rate (not to a file that is no IMU log) */
        int k, six = i == 0;
        for (k = 1; k < 7 && six; k++) {
            six = hx_find_col(f, n, names[k]) >= 0;
        }
        /* one sensor's file (a logger that writes the other to another
         * file): say how to make one log of the two */
        const int one = hx_tri_header_kind(f, n);
        /* one unit alone as the last field is a note ("gz (SI)"), not a
         * name cut apart: the name missing is said as it was */
        if (r->unit_field > 0 && (r->unit_field < n || units > 1)) {
            r->missing_col = -1; /* no detection hint: --columns cannot split such a header */
            set_err(r, "%s:%ld: header has no column '%s'; expected t,ax,ay,az,gx,gy,gz[,temp]; " UNIT_ALONE_FIX,
                    r->path, r->stats.lines, names[i], r->unit_text, r->unit_field);
            return -1;
        }
        set_err(r, "%s:%ld: header has no column '%s'; expected t,ax,ay,az,gx,gy,gz[,temp]%s%s%s%s", r->path,
                r->stats.lines, names[i],
                six ? " (t in s: name the time column t; a log without time stamps: give its rate with "
                      "--input-rate HZ)"
                    : "",
                one < 0 ? "" : one == HX_TRI_ACC ? "; the accelerometer's alone" :
                one == HX_TRI_GYR ? "; the gyroscope's alone" : "; a time and x, y, z alone",
                one < 0 ? "" : " (one sensor's file? bin/harness merge ACC GYRO OUT makes one log of a logger's two: "
                               "docs/log-format.md, \"Accelerometer and gyroscope in two files\")",
                matched);
    } else {
        set_err(r, "%s:%ld: header has no column '%s' (the %s column of the %s format)", r->path,
                r->stats.lines, names[i], what[i], hx_format_name(r->meta.format));
    }
    return -1;
}

static void set_cols(hx_reader_t *r, int t, int a0, int g0)
{
    int i;
    r->col_t = t;
    for (i = 0; i < 3; i++) {
        r->col_a[i] = a0 + i;
        r->col_g[i] = g0 + i;
    }
    r->col_temp = -1;
    r->ncols_needed = (a0 > g0 ? a0 : g0) + 3;
    if (t + 1 > r->ncols_needed) {
        r->ncols_needed = t + 1;
    }
}

/* The first rows of an MT Manager export after its header, read ahead for
 * their SampleTimeFine (hx_mtmgr_peek) on the reader's own handle, which
 * the caller then puts back at the first row (gzclearerr, gzseek): a fault
 * there (a NUL byte, a line too long, a read error) ends the look ahead
 * and is left for the reading to meet at its line. The file is not
 * opened a second time for this. */
static void mtmgr_peek(hx_reader_t *r)
{
    char *f[HX_MAX_COLS];
    size_t len;
    int nul;
    while (hx_gzgets(r->gz, r->line, (int)sizeof r->line, &len, &nul) != NULL) {
        int n;
        if (nul || len == 0 || (r->line[len - 1] != '\n' && !gzeof(r->gz))) {
            break;
        }
        if (blank(r->line)) {
            continue;
        }
        n = split(r->line, r->delim, f, HX_MAX_COLS);
        if (!hx_mtmgr_peek(&r->mt, f, n)) {
            break;
        }
    }
}

/* A format whose time is a counter at a rate the file states (fs Hz on
 * line; 0: none), its header of names with delimiter delim next: a
 * different --input-rate (rate_hz > 0) replaces the rate with a warning
 * (--input-rate 200 on a 100 Hz file halves every stride time); it still
 * rules, since the file may state the wrong one. The counter is the seq.
 * 0 ok, -1 error (setup_header's). */
static int counter_format(hx_reader_t *r, double rate_hz, double fs, long line, char delim,
                          const char *const names[8], const char *sensor, const char *axes)
{
    r->time_mode = TIME_COUNTER;
    r->rate_hz = rate_hz > 0.0 ? rate_hz : fs;
    if (rate_hz > 0.0 && fs > 0.0 && fabs(rate_hz - fs) > 1.0e-9 * fs) {
        add_warn(r, "%s: --input-rate %g Hz replaces the rate the file states (%g Hz on line %ld)", r->path, rate_hz,
                 fs, line);
    }
    r->delim = delim;
    if (setup_header(r, names, 1) != 0) {
        return -1;
    }
    r->meta.has_seq = 1;
    copy_str(r->meta.sensor, sizeof r->meta.sensor, sensor);
    copy_str(r->meta.axes, sizeof r->meta.axes, axes);
    return 0;
}

/* Xsens MT Manager's export (hx_xsens.h): the '//' lines, the header and
 * a look at the first data row, whose SampleTimeFine (a number or NaN)
 * chooses the time source; the row is read again as the first sample. With
 * SampleTimeFine, the steps of the first rows' stamps check the stated rate
 * and their unit (hx_mtmgr_stamps; the unit's refusal is open_raw's). */
static int setup_mtmgr(hx_reader_t *r, double rate_hz)
{
    hx_meta_t *m = &r->meta;
    char *f[HX_MAX_COLS], msg[256];
    int n, rc;
    long lines;
    z_off_t pos;
    hx_mtmgr_init(&r->mt);
    do {
        rc = read_line(r);
        if (rc <= 0) {
            if (rc == 0) {
                set_err(r, "%s: no header line (PacketCounter, SampleTimeFine, Acc_X, ...)", r->path);
            }
            return -1;
        }
    } while (blank(r->line) || hx_mtmgr_comment(&r->mt, r->line, r->stats.lines));
    /* tabs as MT Manager writes them, else commas, semicolons or blanks */
    r->delim = strchr(r->line, '\t') != NULL ? '\t'
               : strchr(r->line, ',') != NULL ? ','
               : strchr(r->line, ';') != NULL ? ';'
                                              : ' ';
    n = split(r->line, r->delim, f, HX_MAX_COLS);
    r->hdr_fields = hx_named_fields(f, n, n);
    if (hx_mtmgr_header(&r->mt, f, n, msg, sizeof msg) != 0) {
        set_err(r, "%s:%ld: %s", r->path, r->stats.lines, msg);
        return -1;
    }
    lines = r->stats.lines;
    pos = gztell(r->gz);
    do {
        rc = read_line(r);
    } while (rc > 0 && blank(r->line));
    if (rc < 0) {
        return -1;
    }
    n = rc > 0 ? split(r->line, r->delim, f, HX_MAX_COLS) : 0;
    if (hx_mtmgr_choose_time(&r->mt, rc > 0 ? f : NULL, n, rate_hz, msg, sizeof msg) != 0) {
        set_err(r, "%s:%ld: %s", r->path, r->stats.lines, msg);
        return -1;
    }
    if (pos < 0 || gzseek(r->gz, pos, SEEK_SET) != pos) {
        set_err(r, "%s:%ld: cannot read the first row again (seek failed)", r->path, r->stats.lines);
        return -1;
    }
    if (r->mt.time_src == HX_MTMGR_TIME_STF) {
        mtmgr_peek(r);
        gzclearerr(r->gz); /* a read error of the look ahead is met again at its line */
        if (gzseek(r->gz, pos, SEEK_SET) != pos) {
            set_err(r, "%s:%ld: cannot read the first row again (seek failed)", r->path, r->stats.lines);
            return -1;
        }
        if (hx_mtmgr_stamps(&r->mt, msg, sizeof msg)) {
            add_warn(r, "%s:%ld: %s", r->path, r->mt.stated_line, msg);
        }
    }
    r->stats.lines = lines;
    r->last_line_open = 0;
    for (n = 0; n < 3; n++) {
        r->col_a[n] = r->mt.col_acc[n];
        r->col_g[n] = r->mt.col_gyr[n];
    }
    r->ncols_needed = r->mt.ncols_needed;
    r->time_mode = TIME_MTMGR;
    r->rate_hz = r->mt.rate_hz;
    m->has_seq = r->mt.use_ctr;
    m->stamps_made = r->mt.time_src == HX_MTMGR_TIME_INDEX;
    if (r->mt.rate_hz > 0.0) {
        m->rate_hz = r->mt.rate_hz;
        m->rate_nominal = 1;
    }
    if (r->mt.time_src != HX_MTMGR_TIME_STF && rate_hz > 0.0 && r->mt.stated_hz > 0.0 &&
        fabs(rate_hz - r->mt.stated_hz) > 1.0e-9 * r->mt.stated_hz) {
        /* as for ipol: the user's rate rules, said */
        add_warn(r, "%s: --input-rate %g Hz replaces the rate the file states (%g Hz on line %ld)", r->path, rate_hz,
                 r->mt.stated_hz, r->mt.stated_line);
    }
    snprintf(m->sensor, sizeof m->sensor, "Xsens %s", r->mt.product[0] != '\0' ? r->mt.product : "(MT Manager)");
    if (hx_printable(m->sensor) > 0) { /* an escape in the ProductCode reached the terminal, as a .bin's text */
        add_warn(r, "%s: the ProductCode holds control characters or bytes that are not UTF-8 (read as '?')", r->path);
    }
    copy_str(m->axes, sizeof m->axes, "sensor axes");
    return 0;
}

static int setup_text(hx_reader_t *r, double rate_hz)
{
    hx_meta_t *m = &r->meta;
    r->acc_scale = 1.0;
    r->gyr_scale = 1.0;
    r->col_temp = -1;
    r->col_aux = -1;
    r->col_tns = -1;
    r->missing_col = -1;
    r->delim = ',';
    switch (m->format) {
    case HX_FMT_CSV: {
        const char *names[8];
        int i;
        for (i = 0; i < 8; i++) {
            names[i] = r->layout.names[i][0] != '\0' ? r->layout.names[i] : k_csv_names[i];
        }
        r->time_mode = TIME_COLUMN_S;
        if (setup_header(r, names, !(rate_hz > 0.0)) != 0) {
            return -1;
        }
        /* after the header: names matched there may name units */
        r->acc_scale = r->layout.acc_scale;
        r->gyr_scale = r->layout.gyr_scale;
        if (r->col_t < 0) {
            /* no time column: --input-rate gives the rate, t = index / rate,
             * as for the importers without time stamps (not an error with
             * no way to give the rate) */
            r->time_mode = TIME_INDEX;
            m->stamps_made = 1;
            r->rate_hz = rate_hz;
        }
        m->has_temp = r->col_temp >= 0;
        copy_str(m->sensor, sizeof m->sensor,
                 r->consensys ? "Shimmer (Consensys export)" : r->ros ? "ROS sensor_msgs/Imu"
                 : r->kalibr  ? "Kalibr IMU CSV" : r->sensorlog ? "SensorLog (iOS)"
                 : r->gforce  ? "Physics Toolbox (g-force)" : "unknown");
        break;
    }
    case HX_FMT_NGIMU: {
        static const char *const names[8] = { "Time (s)", "Accelerometer X (g)", "Accelerometer Y (g)",
                                              "Accelerometer Z (g)", "Gyroscope X (deg/s)",
                                              "Gyroscope Y (deg/s)", "Gyroscope Z (deg/s)", NULL };
        r->time_mode = TIME_COLUMN_S;
        r->acc_scale = 9.80665;
        r->gyr_scale = 3.14159265358979323846 / 180.0;
        if (setup_header(r, names, 1) != 0) {
            return -1;
        }
        copy_str(m->sensor, sizeof m->sensor, "x-io NGIMU");
        copy_str(m->axes, sizeof m->axes, "sensor axes; tilted at rest, +z mostly up");
        break;
    }
    case HX_FMT_PYSHOE: {
        static const char *const names[8] = { "t_s", "ax_mps2", "ay_mps2", "az_mps2",
                                              "gx_radps", "gy_radps", "gz_radps", NULL };
        r->time_mode = TIME_COLUMN_S;
        if (setup_header(r, names, 1) != 0) {
            return -1;
        }
        copy_str(m->sensor, sizeof m->sensor, "MicroStrain 3DM-GX3/GX5");
        copy_str(m->axes, sizeof m->axes, "sensor axes; z down at rest");
        break;
    }
    case HX_FMT_ADIS: {
        /* a time column beside the names: not read (the format has none),
         * named below (time_beside) */
        static const char *const names[8] = { NULL, "acc_x_g", "acc_y_g", "acc_z_g",
                                              "gyro_x_dps", "gyro_y_dps", "gyro_z_dps", NULL };
        r->time_mode = TIME_INDEX;
        m->stamps_made = 1;
        r->rate_hz = rate_hz > 0.0 ? rate_hz : 100.0;
        r->acc_scale = 9.80665;
        r->gyr_scale = 3.14159265358979323846 / 180.0;
        if (setup_header(r, names, 0) != 0) {
            return -1;
        }
        copy_str(m->sensor, sizeof m->sensor, "ADIS16405");
        copy_str(m->axes, sizeof m->axes, "sensor axes; z down at rest");
        if (r->time_beside[0] != '\0') {
            /* said to be left unread, not ignored under "no time stamps;
             * assuming ... 100 Hz" (a log stamped at 200 Hz would read at
             * 100 without a word); detection reads such a header as the
             * interchange CSV, so only --from adis comes here */
            time_beside_warn(r, "adis",
                             rate_hz > 0.0 ? "the --input-rate given is used"
                                           : "read at 100 Hz, the ADIS16405 data set's rate",
                             "ax=acc_x_g,ay=acc_y_g,az=acc_z_g,gx=gyro_x_dps,gy=gyro_y_dps,gz=gyro_z_dps",
                             "accel=g,gyro=deg/s");
        } else if (!(rate_hz > 0.0)) {
            /* no time stamps: a log of another rate would be read at 100 Hz
             * without a word (warned as the OpenShoe 820 Hz reader warns) */
            add_warn(r, "%s: no time stamps; assuming the ADIS16405 data set rate of 100 Hz (give --input-rate)",
                     r->path);
        }
        break;
    }
    case HX_FMT_SQUARE2: {
        static const char *const names[8] = { "sample", "f_x_mps2", "f_y_mps2", "f_z_mps2",
                                              "w_x_radps", "w_y_radps", "w_z_radps", NULL };
        r->time_mode = TIME_COUNTER;
        r->rate_hz = rate_hz > 0.0 ? rate_hz : 100.0;
        if (setup_header(r, names, 1) != 0) {
            return -1;
        }
        m->has_seq = 1;
        copy_str(m->sensor, sizeof m->sensor, "ZUPT-aided-INS square2");
        copy_str(m->axes, sizeof m->axes, "sensor axes; z down at rest");
        if (r->time_beside[0] != '\0') {
            /* a time column beside the counter: not read, said (as adis) */
            time_beside_warn(r, "square2",
                             rate_hz > 0.0 ? "its counter 'sample' is read at the --input-rate given"
                                           : "its counter 'sample' is read at 100 Hz, the data set's rate",
                             "ax=f_x_mps2,ay=f_y_mps2,az=f_z_mps2,gx=w_x_radps,gy=w_y_radps,gz=w_z_radps", "");
        } else if (!(rate_hz > 0.0)) {
            /* a sample counter, no time: a log of another rate would be
             * read at 100 Hz without a word (warned as for ADIS16405 logs) */
            add_warn(r, "%s: no time stamps; assuming the ZUPT-aided-INS square2 data set rate of 100 Hz (give --input-rate)",
                     r->path);
        }
        break;
    }
    case HX_FMT_IPOL: {
        static const char *const names[8] = { "PacketCounter", "Acc_X", "Acc_Y", "Acc_Z",
                                              "Gyr_X", "Gyr_Y", "Gyr_Z", NULL };
        double fs = 0.0;
        do {
            /* blank lines before the first are skipped, as detection does */
            if (read_line(r) <= 0) {
                set_err(r, "%s: empty file", r->path);
                return -1;
            }
        } while (blank(r->line));
        {
            /* "Acquisition frequency: 100 Hz", in any case, spaces around:
             * a decimal number and the unit Hz, nothing else. sscanf's %lf
             * stops where it cannot go on: "100 kHz" and "100,5 Hz" would
             * read as 100 Hz, exit 0, every time off; and a rate of 1e-300
             * Hz would fail at the second row as a counter out of range */
            char head[64];
            const char *num;
            char *end = NULL;
            squeeze_line(r->line, head, sizeof head);
            num = head + 21;
            if (strncmp(head, "acquisitionfrequency:", 21) == 0 && strpbrk(num, "xX") == NULL) {
                fs = strtod(num, &end);
            }
            if (end == NULL || end == num || strcmp(end, "hz") != 0) {
                const int comma = end != NULL && end != num && end[0] == ',' && isdigit((unsigned char)end[1]);
                set_err(r, "%s:%ld: expected 'Acquisition frequency: N Hz', a number in Hz%s", r->path,
                        r->stats.lines, comma ? DECIMAL_COMMA_HINT : "");
                return -1;
            }
            if (!(fs >= 1.0e-3 && fs < 1.0e6)) {
                set_err(r, "%s:%ld: expected 'Acquisition frequency: N Hz': %g Hz is outside [0.001, 1e+06)", r->path,
                        r->stats.lines, fs);
                return -1;
            }
        }
        if (counter_format(r, rate_hz, fs, r->stats.lines, '\t', names, "Xsens MTw Awinda",
                           "sensor axes; tilted at rest, +z mostly up") != 0) {
            return -1;
        }
        break;
    }
    case HX_FMT_PICOQUAKE: {
        static const char *const names[8] = { "count", "a_x", "a_y", "a_z", "g_x", "g_y", "g_z", NULL };
        long config_line = 0;
        double fs = 0.0;
        if (pq_preamble(r, rate_hz, &fs, &config_line) != 0) {
            return -1;
        }
        if (!(fs > 0.0) && !(rate_hz > 0.0)) {
            set_err(r, "%s: no '# Config: data_rate = N' line before the header: the sample count's rate is not "
                       "known (give --input-rate; the header count,a_x,...,g_z is read as PLab PicoQuake's, in g and "
                       "deg/s: for another layout give --from csv with --columns, --units and --input-rate)",
                    r->path);
            return -1;
        }
        /* the device's units (its docs, "Acquisition CSV File"): g and deg/s */
        r->acc_scale = HX_G_MPS2;
        r->gyr_scale = HX_DPS_RPS;
        if (counter_format(r, rate_hz, fs, config_line, ',', names, "PLab PicoQuake (ICM-42688-P)",
                           "sensor axes, as marked on the device") != 0) {
            return -1;
        }
        break;
    }
    case HX_FMT_MTMGR:
        if (setup_mtmgr(r, rate_hz) != 0) {
            return -1;
        }
        break;
    case HX_FMT_OS820:
        r->time_mode = TIME_INDEX;
        m->stamps_made = 1;
        r->delim = '\0'; /* chosen on the first line (next_text_fields) */
        r->rate_hz = rate_hz > 0.0 ? rate_hz : 820.0;
        set_cols(r, -1, 0, 3);
        copy_str(m->sensor, sizeof m->sensor, "OpenShoe (820 Hz)");
        copy_str(m->axes, sizeof m->axes, "sensor axes; z up at rest");
        if (!(rate_hz > 0.0)) {
            add_warn(r, "%s: no time stamps; assuming the OpenShoe C data set rate of 820 Hz (give --input-rate)",
                     r->path);
        }
        break;
    case HX_FMT_GX2: {
        int rc;
        r->time_mode = TIME_GX2;
        r->delim = ' ';
        r->acc_scale = 9.80665;
        do {
            rc = read_line(r);
            if (rc <= 0) {
                if (rc == 0) {
                    set_err(r, "%s: no 'Header:' line found", r->path);
                }
                return -1;
            }
        } while (strncmp(trim(r->line), "Header:", 7) != 0);
        {
            /* a row's fields: the packet id, which the header leaves
             * unnamed, and one for each name the header ends with a colon
             * (16), as many as the colons with "Header:"'s; the rows are
             * compared with it */
            const char *q;
            r->hdr_fields = 0;
            for (q = r->line; *q != '\0'; q++) {
                r->hdr_fields += *q == ':' && r->hdr_fields < HX_MAX_COLS; /* as many as split keeps */
            }
        }
        /* fields 0-10 are taken (the Freq. column 13 only when there, see
         * TIME_GX2): a last line cut inside field 11 or later is read, as
         * docs/log-format.md says (requiring 12 fields would drop it) */
        set_cols(r, 10, 1, 4);
        r->col_aux = 9; /* Nr */
        m->has_seq = 1;
        copy_str(m->sensor, sizeof m->sensor, "MicroStrain 3DM-GX2");
        copy_str(m->axes, sizeof m->axes, "sensor axes; z up at rest");
        break;
    }
    default:
        set_err(r, "%s: internal: not a text format", r->path);
        return -1;
    }
    if (r->time_mode != TIME_COLUMN_S && r->time_mode != TIME_GX2 && r->time_mode != TIME_MTMGR) {
        m->rate_hz = r->rate_hz;
        m->rate_nominal = 1;
    }
    return 0;
}

/* GX2: the sensor's timer counts at 19.6608 MHz but the logger restarts it
 * about once a second; inside a run the tick difference is the true period.
 * A difference that is not positive or differs from the last good one by
 * more than half bridges with the last good period (docs/log-format.md).
 * The packet number Nr says how many periods the difference spans: a jump
 * of k (k - 1 packets lost) expects k periods, and a restart across it is
 * bridged with k of them. A restart before any period was measured (the
 * file's first interval) is bridged with k periods of the logger's own rate
 * estimate (the Freq. column, within 4 % of the true rate from the first
 * line), or without it with the host interval (the filtered stamps, index
 * 10: the unfiltered ones, index 11, jitter ten times more), which jitters
 * 1-25 ms. */
#define GX2_TICK_HZ 19660800L
#define GX2_MAX_LOST 1000 /* a larger jump of Nr is taken for a restart of the count, one period */
#define GX2_SWAP_MAX 8    /* Nr and timer back by at most this many packets: a row out of order */
static int64_t gx2_time(hx_reader_t *r, double counter, double host_s, double nr, double freq_hz)
{
    int held = 0; /* a row out of order: the last row stays the reference */
    if (!r->have_prev) {
        r->gx2_ticks = 0;
    } else if (counter == r->prev_counter && nr == r->gx2_prev_nr) {
        /* the same packet written again: a duplicate (dt = 0), as in every
         * other format; bridged as a restart, one period on, it would be
         * hidden and shift the rest of the log */
    } else {
        double d = counter - r->prev_counter, dn = nr - r->gx2_prev_nr;
        const long k = (dn >= 1.0 && dn <= (double)GX2_MAX_LOST) ? (long)dn : 1;
        if (!(dn >= 1.0)) {
            /* Nr back, or repeated with another timer value: rows out of
             * order or the count restarted; taken as one period on, said at
             * the end (it went unsaid) */
            if (r->gx2_nr_back++ == 0) {
                r->gx2_nr_back_line = r->stats.lines;
            }
            /* Nr and timer both a few packets back: a row out of order
             * (5, 7, 6, 8). The next row is then counted from the highest
             * (7), not from this one: from 6, 8's jump of two would insert
             * a second period (two gaps where the log has none) */
            held = dn <= -1.0 && dn >= -(double)GX2_SWAP_MAX && d < 0.0;
        }
        if (d > 0.0 && d < (double)(GX2_TICK_HZ / 10) * (double)k &&
            (r->gx2_last_dt == 0 || labs((long)d - k * r->gx2_last_dt) < r->gx2_last_dt / 2)) {
            r->gx2_last_dt = (long)d / k;
            r->gx2_ticks += (long)d;
        } else if (r->gx2_last_dt > 0) {
            r->gx2_ticks += k * r->gx2_last_dt;
            r->gx2_bridged += !held; /* a row out of order is no timer restart */
        } else {
            double dh = host_s - r->gx2_prev_host;
            if (freq_hz > 10.0 && freq_hz < 10000.0) {
                dh = (double)k / freq_hz;
            } else if (!(dh > 0.0 && dh < 0.1)) {
                dh = 1.0 / 250.0;
            }
            r->gx2_ticks += (int64_t)(dh * (double)GX2_TICK_HZ + 0.5);
            r->gx2_bridged++;
        }
    }
    if (!held) {
        r->prev_counter = counter;
        r->gx2_prev_host = host_s;
        r->gx2_prev_nr = nr;
    }
    /* whole seconds apart: ticks x 1e9 leaves int64 after 469 s (a longer
     * log would read "time goes backwards" there) */
    return (r->gx2_ticks / GX2_TICK_HZ) * 1000000000LL + ((r->gx2_ticks % GX2_TICK_HZ) * 1000000000LL) / GX2_TICK_HZ;
}

static fnav_status_t next_text_fields(hx_reader_t *r, fnav_sample_t *s);
static fnav_status_t next_text_line(hx_reader_t *r, fnav_sample_t *s);

/* The next sample of a text log: the next line's, past the rows skipped
 * (an MT Manager export's rows with a missing value, counted). */
static fnav_status_t next_text(hx_reader_t *r, fnav_sample_t *s)
{
    for (;;) {
        const fnav_status_t st = next_text_line(r, s);
        if (st != FNAV_OK || !r->row_skipped) {
            return st;
        }
        r->row_skipped = 0;
        s->flags = 0;
    }
}

static fnav_status_t next_text_line(hx_reader_t *r, fnav_sample_t *s)
{
    int rc;
    for (;;) {
        rc = read_line(r);
        if (rc < 0) {
            return FNAV_E_IO;
        }
        if (rc == 0) {
            return FNAV_END;
        }
        if (!blank(r->line) && !(r->meta.format == HX_FMT_CSV && comment(r->line))) {
            break;
        }
    }
    if (r->last_line_open && r->meta.format == HX_FMT_CSV && gzeof(r->gz)) {
        /* Our own CSV: a last line without a newline is read (many tools
         * write none), and an incomplete one is an error like any malformed
         * line; but one that ends in a used value may have been cut inside
         * it (-0.00245940452 read as -0.0024590001): dropped with a
         * warning, as for the foreign formats below, not read silently */
        fnav_status_t st;
        r->last_line_open = 0;
        r->last_line = 1;
        st = next_text_fields(r, s);
        if (st == FNAV_OK && r->nfields <= r->ncols_needed) {
            r->stats.cut_lines++;
            add_warn(r, "%s:%ld: " HX_CUT_LAST_TEXT, r->path, r->stats.lines);
            return FNAV_END;
        }
        return st;
    }
    if (r->last_line_open && r->meta.format != HX_FMT_CSV && gzeof(r->gz)) {
        /* The final line of a foreign recording has no newline: the file was
         * cut off mid-write. Parse it on a copy; if it is incomplete, ignore
         * it with a warning (docs/log-format.md) instead of failing. */
        fnav_status_t st;
        r->last_line_open = 0;
        r->last_line = 1;
        st = next_text_fields(r, s);
        if (st != FNAV_OK) {
            r->err[0] = '\0';
            r->stats.cut_lines++;
            add_warn(r, "%s:%ld: last line is incomplete (recording cut off mid-write); ignored", r->path,
                     r->stats.lines);
            return FNAV_END;
        }
        if (r->nfields <= r->ncols_needed) {
            /* it parsed, but it ends in a value the reader uses, which the
             * cut may have shortened (8.448539 read as 8): one sample is
             * dropped rather than a wrong one read */
            r->stats.cut_lines++;
            add_warn(r, "%s:%ld: last line has no newline and ends in a value the reader uses, which may be cut "
                        "(recording cut off mid-write); ignored", r->path, r->stats.lines);
            return FNAV_END;
        }
        return st;
    }
    return next_text_fields(r, s);
}

/* Whether a value beyond FNAV_INPUT_MAX_ABS could be an acceleration in ug
 * written as m/s^2: within the widest range of MEMS accelerometers (400 g,
 * ST's H3LIS331DL) once read in ug. The CSV and .bin readers ask "in ug?"
 * on it. */
static int ug_plausible(double v)
{
    return fabs(v) * HX_UG_MPS2 <= 400.0 * HX_G_MPS2;
}

const char *hx_stdin_hint(const char *path, int err)
{
    return strcmp(path, "-") == 0 && err == ENOENT ? ": for standard input give /dev/stdin (a pipe is read)" : "";
}

int hx_value_beyond(double v, double scale, int gyro, const char *field, const hx_csv_layout_t *ug_ask, char *text,
                    size_t size)
{
    /* an accelerometer in ug read as m/s^2 reads 1e6 at 1 g, at this
     * limit: before the units check can name ug, a log in ug meets this
     * error, so it asks about ug rather than saying only "no sensor reads
     * that"; read as g (--units accel=g) it meets it at once. Asked when
     * the value in ug is within the widest range of MEMS accelerometers
     * (ug_plausible), as a question: raw counts of a 24-bit converter
     * reach it too */
    char give[96] = "", quote[96];
    const double si = v * scale;
    if (fabs(si) <= FNAV_INPUT_MAX_ABS) {
        return 0;
    }
    /* read in another unit, the value quoted is not the one compared
     * with the limit: both are given ('-105307.65' g, -1.03e+06 m/s^2),
     * lest 1e5 look within 1e6; not for a number beyond 1e300, which
     * parse_num keeps as 1e300 */
    if (scale == 1.0) {
        snprintf(quote, sizeof quote, "('%.20s')", field);
    } else if (isfinite(si) && fabs(v) < 1.0e300) {
        snprintf(quote, sizeof quote, "('%.20s' %s, %.3g %s)", field,
                 gyro ? hx_gyro_unit_name(scale) : hx_accel_unit_name(scale), si, gyro ? "rad/s" : "m/s^2");
    } else {
        snprintf(quote, sizeof quote, "('%.20s' %s)", field, gyro ? hx_gyro_unit_name(scale) : hx_accel_unit_name(scale));
    }
    if (ug_ask != NULL && ug_ask->acc_scale != HX_UG_MPS2 && ug_plausible(v)) {
        /* the whole --units value, as the units check names it */
        hx_csv_layout_t want = *ug_ask;
        char items[80];
        want.acc_scale = HX_UG_MPS2;
        snprintf(give, sizeof give, "; in ug? 1 g is 1e6 ug: %s", hx_units_give(&want, items, sizeof items));
    }
    snprintf(text, size, "%s is beyond %g in SI units (no sensor reads that%s)", quote, FNAV_INPUT_MAX_ABS, give);
    return 1;
}

static fnav_status_t next_text_fields(hx_reader_t *r, fnav_sample_t *s)
{
    char *f[HX_MAX_COLS], what[320];
    int n, i, neg;
    double v[6], tv = 0.0, aux = 0.0;
    int64_t t_ns = 0;
    if (r->delim == '\0') {
        /* headerless OpenShoe 820 Hz: commas as in the data set, or tabs,
         * semicolons or blanks (a spreadsheet's export, MATLAB's save
         * -ascii), as detection accepts them */
        r->delim = strchr(r->line, ',') != NULL    ? ','
                   : strchr(r->line, '\t') != NULL ? '\t'
                   : strchr(r->line, ';') != NULL  ? ';'
                                                   : ' ';
    }
    if (r->delim == ' ' && r->hdr_fields > 0 && r->date_join < 0) {
        /* the first row: a date and its time are one field unless the
         * header names them apart ("date time ax ...", two columns that
         * read a time of day): the split that gives the header's count
         * decides, for every row after */
        char copy[HX_LINE_MAX];
        const size_t len = strlen(r->line) + 1;
        memcpy(copy, r->line, len);
        r->date_join = split_join(r->line, r->delim, f, HX_MAX_COLS, 1) == r->hdr_fields;
        memcpy(r->line, copy, len);
        if (!r->date_join) {
            /* joined, the count is not the header's: apart, it may be */
            r->date_join = split_join(r->line, r->delim, f, HX_MAX_COLS, 0) != r->hdr_fields;
            memcpy(r->line, copy, len);
        }
    }
    n = split_join(r->line, r->delim, f, HX_MAX_COLS, r->date_join != 0);
    r->nfields = n;
    if (r->delim == ';' || r->delim == '\t') {
        decimal_commas_read(r, f, n);
    }
    if (r->meta.format == HX_FMT_GX2) {
        if (n == 0 || strncmp(f[0], "0x", 2) != 0) {
            /* what a data line starts with, and what this one does (not
             * the bare "not a GX2 data line" of a row that lost its first
             * field) */
            set_err(r, "%s:%ld: not a GX2 data line: its first field ('%.20s') is not the command byte in hex "
                       "(0x..., 0xcb in the OpenShoe logs) that a 3DM-GX2 data line starts with",
                    r->path, r->stats.lines, n == 0 ? "" : f[0]);
            return FNAV_E_FORMAT;
        }
    }
    if (n < r->ncols_needed) {
        /* the unit alone among the columns read shifted them (past them, it
         * does not: a row cut short under a header read by its names) */
        if (r->unit_field > 0 && r->unit_field <= r->ncols_needed) {
            set_err(r, "%s:%ld: %d column%s, expected at least %d; " UNIT_ALONE_FIX, r->path, r->stats.lines, n,
                    n == 1 ? "" : "s", r->ncols_needed, r->unit_text, r->unit_field);
            return FNAV_E_FORMAT;
        }
        set_err(r, "%s:%ld: %d column%s, expected at least %d", r->path, r->stats.lines, n,
                n == 1 ? "" : "s", r->ncols_needed);
        return FNAV_E_FORMAT;
    }
    if (n < r->hdr_fields && !r->last_line) {
        /* enough fields for the columns used, fewer than the header names:
         * a field lost inside the row shifts the values after it (az read
         * from gx), which nothing can tell from trailing fields left off;
         * counted and warned at the end, not read silently. A cut last
         * line is the cut's. */
        if (r->short_rows++ == 0) {
            r->short_first = r->stats.lines;
        }
    }
    if (r->hdr_fields > 0) {
        /* more fields than the header names: a stray delimiter inside the
         * row shifts the values after it (0.01,5,0.01,... read as ax = 5),
         * or the header lacks a column's name; counted and warned at the
         * end, not read silently. Empty
         * fields past the header's are no data: a trailing delimiter, as
         * spreadsheets and MT Manager write one on every row. The
         * headerless OpenShoe 820 Hz file has no count to compare with. */
        int k, data = 0;
        for (k = r->hdr_fields; k < n && !data; k++) {
            data = f[k][0] != '\0';
        }
        if (data && r->long_rows++ == 0) {
            r->long_first = r->stats.lines;
        }
        r->rows_checked++;
    }
    if (r->meta.format == HX_FMT_MTMGR && hx_mtmgr_row(&r->mt, f, n, r->stats.lines)) {
        /* NaN or empty where the reader needs a value: the packet lacks
         * it; skipped and counted, warned at the end (hx_reader_next) */
        r->row_skipped = 1;
        return FNAV_OK;
    }
    for (i = 0; i < 3; i++) {
        int c;
        for (c = 0; c < 2; c++) {
            int col = c == 0 ? r->col_a[i] : r->col_g[i];
            int prc = parse_num(f[col], &v[c * 3 + i]);
            if (prc != 0 && prc != -3) { /* -3 (1e308) is beyond the range below */
                set_err(r, "%s:%ld: column %d ('%.20s') is %s", r->path, r->stats.lines, col + 1, f[col],
                        prc == -2 ? "NaN or Inf" : not_a_number(f[col]));
                return prc == -2 ? FNAV_E_NANINF : FNAV_E_FORMAT;
            }
            /* what the core would refuse (and float would make Inf) is a
             * reader error here, with its line (hx_value_beyond, merge's
             * check too) */
            if (hx_value_beyond(v[c * 3 + i], c == 0 ? r->acc_scale : r->gyr_scale, c == 1, f[col],
                                c == 0 && r->meta.format == HX_FMT_CSV ? &r->layout : NULL, what, sizeof what)) {
                set_err(r, "%s:%ld: column %d %s", r->path, r->stats.lines, col + 1, what);
                return FNAV_E_RANGE;
            }
        }
    }
    if (r->col_temp >= 0 && f[r->col_temp][0] != '\0') {
        /* an empty field is a sample without a temperature (convert writes
         * one for a .bin record whose temperature is not valid) */
        double tc;
        int prc = parse_num(f[r->col_temp], &tc);
        if (prc != 0 && prc != -3) {
            set_err(r, "%s:%ld: temperature ('%.20s') is %s", r->path, r->stats.lines, f[r->col_temp],
                    prc == -2 ? "NaN or Inf" : not_a_number(f[r->col_temp]));
            return prc == -2 ? FNAV_E_NANINF : FNAV_E_FORMAT;
        }
        if (fabs(tc) > FNAV_INPUT_MAX_ABS) {
            /* 1e40 would become an Inf float, written by convert as "inf"
             * or into a .bin record that its reader refuses */
            set_err(r, "%s:%ld: temperature ('%.20s') is beyond %g degC (no sensor reads that)", r->path,
                    r->stats.lines, f[r->col_temp], FNAV_INPUT_MAX_ABS);
            return FNAV_E_RANGE;
        }
        s->temp_c = (fnav_real_t)tc;
        s->flags |= FNAV_SAMPLE_HAS_TEMP;
    }
    switch (r->time_mode) {
    case TIME_COLUMN_S: {
        int prc = parse_time_ns(f[r->col_t], r->layout.time_digits, &t_ns);
        if (prc != 0) {
            set_err(r, "%s:%ld: time ('%.40s') is %s", r->path, r->stats.lines, f[r->col_t],
                    prc == -2   ? "NaN or Inf"
                    : prc == -4 ? "no date and time (read as " DATETIME_FORM ")"
                    : prc == -5 ? "a date outside the years 1900 to 2100 (the ones read)"
                    : prc == -3 && r->layout.time_digits != 9
                        ? "beyond 9e9 s"
                    : prc == -3 && r->meta.format != HX_FMT_CSV
                        ? "beyond 9e9 s (the time column is in seconds; Unix time in milliseconds or "
                          "nanoseconds must be divided by 1e3 or 1e9)"
                    : prc == -3 ? "beyond 9e9 s (the time column is in seconds; Unix time in milliseconds or "
                                  "nanoseconds: --units time=ms or time=ns)"
                                : not_a_number(f[r->col_t]));
            return prc == -2 ? FNAV_E_NANINF : FNAV_E_FORMAT;
        }
        if (r->col_tns >= 0) {
            /* a stamp split in whole seconds and nanoseconds (ROS) */
            int64_t ns;
            if (parse_time_ns(f[r->col_tns], 0, &ns) != 0 || ns < 0 || ns > 999999999 ||
                strpbrk(f[r->col_tns], ".eE") != NULL) {
                set_err(r, "%s:%ld: nanoseconds ('%.20s', column '%s') are not a whole number from 0 to 999999999",
                        r->path, r->stats.lines, f[r->col_tns], r->layout.tns);
                return FNAV_E_FORMAT;
            }
            t_ns += ns;
        }
        s->seq = (uint32_t)r->index;
        break;
    }
    case TIME_INDEX:
        if (secs_to_ns((double)r->index / r->rate_hz, &t_ns) != 0) {
            set_err(r, "%s:%ld: time of sample %ld at %g Hz is out of range", r->path, r->stats.lines, r->index,
                    r->rate_hz);
            return FNAV_E_RANGE;
        }
        s->seq = (uint32_t)r->index;
        break;
    case TIME_COUNTER: {
        /* what is wrong, said: a counter beyond 32 bits, or above 4e9 and
         * within them, is out of range, not "not a non-negative number";
         * the range is the 32 bits of seq */
        const int prc = parse_num(f[r->col_t], &tv);
        if ((prc != 0 && prc != -3) || tv < 0.0 || tv > 4294967295.0) {
            set_err(r, "%s:%ld: counter ('%.20s') is %s", r->path, r->stats.lines, f[r->col_t],
                    prc == -2                 ? "NaN or Inf"
                    : prc != 0 && prc != -3   ? not_a_number(f[r->col_t])
                    : tv < 0.0                ? "negative"
                                              : "beyond 32 bits (4294967295)");
            return FNAV_E_FORMAT;
        }
        if (r->meta.format == HX_FMT_IPOL && tv < 65536.0) {
            /* the Xsens packet counter has 16 bits: a drop by more than half
             * its range is a wrap, counted on (a counter already past 16 bits
             * is taken as it is) */
            if (r->have_prev && tv < r->ctr_prev - 32768.0) {
                r->ctr_wrap += 65536.0;
            }
            r->ctr_prev = tv;
            tv += r->ctr_wrap;
        }
        if (tv != floor(tv) || secs_to_ns(tv / r->rate_hz, &t_ns) != 0) {
            set_err(r, "%s:%ld: counter ('%.20s') is not a whole number in range", r->path, r->stats.lines,
                    f[r->col_t]);
            return FNAV_E_FORMAT;
        }
        s->seq = (uint32_t)tv;
        s->flags |= FNAV_SAMPLE_HAS_SEQ;
        break;
    }
    case TIME_MTMGR: {
        char msg[160];
        int has_seq;
        if (hx_mtmgr_time(&r->mt, f, &t_ns, &s->seq, &has_seq, msg, sizeof msg) != 0) {
            set_err(r, "%s:%ld: %s", r->path, r->stats.lines, msg);
            return FNAV_E_FORMAT;
        }
        if (has_seq) {
            s->flags |= FNAV_SAMPLE_HAS_SEQ;
        }
        break;
    }
    case TIME_GX2: {
        double host = 0.0, freq = 0.0;
        /* the field and its text named, as the other readers do (not
         * "counter, Nr or time stamp is not a number") */
        static const char *const gx2_names[3] = { "Counter", "Nr", "time stamp Filtered ts" };
        const int cols[3] = { 7, r->col_aux, r->col_t };
        double *vals[3];
        int k;
        vals[0] = &tv;
        vals[1] = &aux;
        vals[2] = &host;
        for (k = 0; k < 3; k++) {
            const int prc = parse_num(f[cols[k]], vals[k]);
            if (prc != 0 && !(prc == -3 && k < 2)) { /* a count beyond 1e300 is no 32-bit count, said below */
                set_err(r, "%s:%ld: %s ('%.20s') is %s", r->path, r->stats.lines, gx2_names[k], f[cols[k]],
                        prc == -2   ? "NaN or Inf"
                        : prc == -3 ? "beyond 1e+300 s"
                                    : not_a_number(f[cols[k]]));
                return FNAV_E_FORMAT;
            }
        }
        for (k = 0; k < 2; k++) {
            const double cv = *vals[k];
            if (!(cv >= 0.0 && cv <= 4294967295.0 && (k == 0 || cv == floor(cv)))) {
                set_err(r, "%s:%ld: %s ('%.20s') is not a 32-bit count", r->path, r->stats.lines, gx2_names[k],
                        f[cols[k]]);
                return FNAV_E_FORMAT;
            }
        }
        if (n <= 13 || parse_num(f[13], &freq) != 0) {
            freq = 0.0; /* Freq. [Hz], used only before a period is measured */
        }
        t_ns = gx2_time(r, tv, host, aux, freq);
        s->seq = (uint32_t)aux;
        s->flags |= FNAV_SAMPLE_HAS_SEQ;
        break;
    }
    }
    if (t_ns > FNAV_T_NS_MAX || t_ns < -FNAV_T_NS_MAX) {
        /* time in ms, us or ns read as seconds: Unix time in ms is 1.7e12 "s"
         * (the message names the likely cause) */
        set_err(r, "%s:%ld: time %.6g s is beyond 2^62 ns (146 years)%s", r->path, r->stats.lines,
                (double)t_ns * 1e-9,
                r->meta.format != HX_FMT_CSV ? ": is the time column in seconds? (in milliseconds, microseconds or "
                                               "nanoseconds, divide by 1000, 1e6 or 1e9)"
                : r->time_mode == TIME_COLUMN_S && r->layout.time_digits == 9
                    ? ": is the time column in seconds? (in milliseconds, microseconds or nanoseconds: --units "
                      "time=ms, us or ns)"
                    : "");
        return FNAV_E_RANGE;
    }
    if (r->have_prev && t_ns < r->prev_t_ns) {
        char a[32], b[32];
        set_err(r, "%s:%ld: time goes backwards (%s s after %s s)", r->path, r->stats.lines,
                ns_text(t_ns, a, sizeof a), ns_text(r->prev_t_ns, b, sizeof b));
        return FNAV_E_TIME;
    }
    r->have_prev = 1;
    r->prev_t_ns = t_ns;
    s->t_ns = t_ns;
    neg = r->meta.format == HX_FMT_CSV ? r->layout.negate : 0; /* --columns ax=-NAME: the other sign */
    for (i = 0; i < 3; i++) {
        s->accel_mps2[i] = (fnav_real_t)(v[i] * r->acc_scale * ((neg & (1 << (1 + i))) ? -1.0 : 1.0));
        s->gyro_rps[i] = (fnav_real_t)(v[3 + i] * r->gyr_scale * ((neg & (1 << (4 + i))) ? -1.0 : 1.0));
    }
    r->index++;
    return FNAV_OK;
}

/* ------------------------------------------------------------ bin */

static int bin_fill(hx_reader_t *r, size_t need)
{
    while (r->len - r->pos < need && !r->eof) {
        int got;
        if (r->pos > 0) {
            memmove(r->buf, r->buf + r->pos, r->len - r->pos);
            r->len -= r->pos;
            r->pos = 0;
        }
        got = gzread(r->gz, r->buf + r->len, (unsigned)(sizeof r->buf - r->len));
        if (got <= 0) {
            int e;
            const char *msg = gzerror(r->gz, &e);
            if (e == Z_BUF_ERROR) {
                /* a .bin.gz cut short: the records before the cut are
                 * delivered, then said as a truncated .gz, not as a
                 * recording cut off mid-record */
                r->gz_cut = 1;
                got = 0;
            } else if (got < 0) {
                set_err(r, "%s: read error (%s)", r->path, msg);
                return -1;
            }
        }
        if (got == 0) {
            r->eof = 1;
        }
        r->len += (size_t)got;
    }
    return (r->len - r->pos >= need) ? 1 : 0;
}

static int setup_bin(hx_reader_t *r)
{
    hx_bin_header_t h;
    char msg[160];
    int rc = bin_fill(r, HX_BIN_HEADER_SIZE);
    if (rc < 0) {
        return -1;
    }
    if (rc == 0) {
        /* a .bin.gz cut inside the header is a truncated .gz, as after it
         * (next_bin), not a .bin too short for its header
         * (test_bin_gz_header_cut) */
        set_err(r, "%s: %s (%zu of %d bytes)", r->path,
                r->gz_cut ? "the gzip data ends early (a truncated .gz, e.g. an incomplete copy) inside the header"
                          : "too short for a footnav log header",
                r->len - r->pos, HX_BIN_HEADER_SIZE);
        return -1;
    }
    if (hx_bin_header_decode(r->buf + r->pos, r->len - r->pos, &h, msg, sizeof msg) != 0) {
        set_err(r, "%s: header: %s", r->path, msg);
        return -1;
    }
    r->pos += HX_BIN_HEADER_SIZE;
    r->offset = HX_BIN_HEADER_SIZE;
    r->meta.rate_hz = h.rate_hz;
    r->meta.rate_nominal = (h.flags & HX_BIN_FLAG_RATE_NOMINAL) != 0;
    r->meta.has_temp = (h.flags & HX_BIN_FLAG_TEMP) != 0;
    r->meta.has_seq = (h.flags & HX_BIN_FLAG_SEQ) != 0;
    copy_str(r->meta.sensor, sizeof r->meta.sensor, h.sensor);
    copy_str(r->meta.source, sizeof r->meta.source, h.source);
    copy_str(r->meta.axes, sizeof r->meta.axes, h.axes);
    {
        /* text that reaches the reports, read as printable: a sensor name
         * "x<LF>samples 1" would forge a line of info's report, and an
         * escape sequence reach the terminal */
        const int ctl = hx_printable(r->meta.sensor) + hx_printable(r->meta.source) + hx_printable(r->meta.axes);
        if (ctl > 0) {
            add_warn(r, "%s: the header's text holds %d control character%s or byte%s that %s not UTF-8 (read as '?')",
                     r->path, ctl, ctl == 1 ? "" : "s", ctl == 1 ? "" : "s", ctl == 1 ? "is" : "are");
        }
    }
    return 0;
}

static fnav_status_t next_bin(hx_reader_t *r, fnav_sample_t *s)
{
    for (;;) {
        hx_bin_record_t rec;
        int rc = bin_fill(r, HX_BIN_RECORD_SIZE);
        int dec;
        if (rc < 0) {
            return FNAV_E_IO;
        }
        if (rc == 0) {
            size_t left = r->len - r->pos;
            if (r->gz_cut) {
                set_err(r, "%s: the gzip data ends early (a truncated .gz, e.g. an incomplete copy) after %ld "
                           "complete records", r->path, r->stats.records);
                r->pos = r->len;
                return FNAV_E_TRUNCATED;
            }
            if (left > 0 && r->stats.clean_end) {
                /* after the end record: the log was closed, every record
                 * read; not a cut record */
                set_err(r, "%s: %zu byte%s after the end record, at byte %lld: too few for a record (junk appended to "
                           "a closed log?)",
                        r->path, left, left == 1 ? "" : "s", r->offset);
                r->pos = r->len;
                return FNAV_E_FORMAT;
            }
            if (left > 0) {
                set_err(r, "%s: truncated: record #%ld at byte %lld has %zu of %d bytes (%ld complete records read)",
                        r->path, r->record_slot, r->offset, left, HX_BIN_RECORD_SIZE, r->stats.records);
                r->pos = r->len;
                return FNAV_E_TRUNCATED;
            }
            if (!r->stats.clean_end) {
                set_err(r, "%s: truncated: no end record after %ld records (its writer did not finish it: killed, or stopped "
                        "at an error in its input)",
                        r->path, r->stats.records);
                return FNAV_E_TRUNCATED;
            }
            if (r->deferred != FNAV_OK) {
                return r->deferred;
            }
            return FNAV_END;
        }
        dec = hx_bin_record_decode(r->buf + r->pos, &rec);
        if (dec == 0 && rec.type == HX_BIN_REC_SAMPLE) {
            if (r->stats.clean_end) {
                set_err(r, "%s: record #%ld at byte %lld: data after the end record", r->path, r->record_slot,
                        r->offset);
                r->deferred = FNAV_E_FORMAT;
                r->stats.clean_end = 0;
            }
            if (rec.t_ns > FNAV_T_NS_MAX || rec.t_ns < -FNAV_T_NS_MAX) {
                set_err(r, "%s: record #%ld at byte %lld: time %.6g s is beyond 2^62 ns (146 years)", r->path,
                        r->record_slot, r->offset, (double)rec.t_ns * 1e-9);
                return FNAV_E_RANGE;
            }
            if (r->have_prev && rec.t_ns < r->prev_t_ns) {
                char a[32], b[32];
                set_err(r, "%s: record #%ld at byte %lld: time goes backwards (%s s after %s s)", r->path,
                        r->record_slot, r->offset, ns_text(rec.t_ns, a, sizeof a), ns_text(r->prev_t_ns, b, sizeof b));
                return FNAV_E_TIME;
            }
            {
                int k, finite = 1, in_range = 1, ug = -1;
                for (k = 0; k < 3; k++) {
                    finite &= isfinite(rec.acc[k]) && isfinite(rec.gyr[k]);
                    in_range &= fabs((double)rec.acc[k]) <= FNAV_INPUT_MAX_ABS &&
                                fabs((double)rec.gyr[k]) <= FNAV_INPUT_MAX_ABS;
                }
                /* an accelerometer in ug written as m/s^2 reads 1e6 at 1 g:
                 * the CSV reader asks "in ug?" with --units accel=ug, which
                 * does not apply here (a .bin's units are fixed by its
                 * header). Asked, with the remedy that does apply, only
                 * when every value beyond the limit is an acceleration
                 * within 400 g once read in ug (ug_plausible): stricter than
                 * the CSV reader, which asks about the first field beyond
                 * the limit alone, so a record with a gyro beyond it too is
                 * not asked about here */
                for (k = 0; k < 3 && !in_range; k++) {
                    const double a = fabs((double)rec.acc[k]);
                    if (fabs((double)rec.gyr[k]) > FNAV_INPUT_MAX_ABS ||
                        (a > FNAV_INPUT_MAX_ABS && !ug_plausible(a))) {
                        ug = 3; /* not asked */
                    } else if (a > FNAV_INPUT_MAX_ABS && ug < 0) {
                        ug = k;
                    }
                }
                /* a valid temperature too, as the CSV reader checks it (a
                 * NaN one would be delivered and written into a CSV that
                 * the CSV reader refuses) */
                finite &= !(rec.flags & HX_BIN_REC_TEMP) || !r->meta.has_temp || isfinite(rec.temp);
                if (!finite) {
                    set_err(r, "%s: record #%ld at byte %lld: NaN or Inf in a sample", r->path, r->record_slot,
                            r->offset);
                    return FNAV_E_NANINF;
                }
                if (!in_range) {
                    char give[200] = "";
                    if (ug >= 0 && ug < 3) {
                        snprintf(give, sizeof give,
                                 "; a%c is %g: in ug? 1 g is 1e6 ug, but a .bin holds m/s^2 (docs/log-format.md) and "
                                 "--units does not apply to it: the program that wrote it must scale ug by 9.80665e-6",
                                 "xyz"[ug], (double)rec.acc[ug]);
                    }
                    set_err(r, "%s: record #%ld at byte %lld: a value beyond %g in SI units (no sensor reads that%s)",
                            r->path, r->record_slot, r->offset, FNAV_INPUT_MAX_ABS, give);
                    return FNAV_E_RANGE;
                }
            }
            r->pos += HX_BIN_RECORD_SIZE;
            r->offset += HX_BIN_RECORD_SIZE;
            r->record_slot++;
            r->have_prev = 1;
            r->prev_t_ns = rec.t_ns;
            s->t_ns = rec.t_ns;
            s->seq = rec.seq;
            if ((rec.flags & HX_BIN_REC_TEMP) && !r->meta.has_temp && !r->temp_unflagged) {
                /* the header decides the columns (convert writes none):
                 * said once, not dropped silently */
                r->temp_unflagged = 1;
                add_warn(r, "%s: record #%ld carries a temperature but the header's flags say the log has none "
                            "(a writer's fault?): the temperatures are not read",
                         r->path, r->record_slot - 1);
            }
            s->flags = (r->meta.has_seq ? FNAV_SAMPLE_HAS_SEQ : 0u) |
                       ((rec.flags & HX_BIN_REC_TEMP) && r->meta.has_temp ? FNAV_SAMPLE_HAS_TEMP : 0u);
            s->accel_mps2[0] = (fnav_real_t)rec.acc[0];
            s->accel_mps2[1] = (fnav_real_t)rec.acc[1];
            s->accel_mps2[2] = (fnav_real_t)rec.acc[2];
            s->gyro_rps[0] = (fnav_real_t)rec.gyr[0];
            s->gyro_rps[1] = (fnav_real_t)rec.gyr[1];
            s->gyro_rps[2] = (fnav_real_t)rec.gyr[2];
            s->temp_c = (fnav_real_t)rec.temp;
            return FNAV_OK;
        }
        if (dec == 0 && rec.type == HX_BIN_REC_END) {
            if (r->stats.clean_end) {
                /* a writer's fault, harmless once its count is checked
                 * like the first's: said, not taken silently */
                add_warn(r, "%s: record #%ld at byte %lld: a second end record (the file was closed twice?)", r->path,
                         r->record_slot, r->offset);
            }
            r->pos += HX_BIN_RECORD_SIZE;
            r->offset += HX_BIN_RECORD_SIZE;
            r->record_slot++;
            if ((long)rec.seq != r->stats.records) {
                set_err(r, "%s: end record counts %lu records but %ld were read", r->path,
                        (unsigned long)rec.seq, r->stats.records);
                if (r->deferred == FNAV_OK) {
                    r->deferred = FNAV_E_CRC;
                }
            }
            r->stats.clean_end = 1;
            continue;
        }
        /* Bad record: remember, then resynchronise on the next valid record. */
        {
            char what[64];
            long long at = r->offset;
            snprintf(what, sizeof what, "%s", dec == -1 ? "unknown record type" : "checksum mismatch");
            if (r->err[0] == '\0') {
                set_err(r, "%s: record #%ld at byte %lld: %s (corrupted); skipped", r->path, r->record_slot, at,
                        what);
            }
            if (r->deferred == FNAV_OK) {
                r->deferred = FNAV_E_CRC;
            }
            r->stats.bad_records++;
            /* Prefer the next slot (a corrupted record in place); else scan. */
            if (bin_fill(r, 2 * HX_BIN_RECORD_SIZE) > 0 &&
                hx_bin_record_decode(r->buf + r->pos + HX_BIN_RECORD_SIZE, &rec) == 0) {
                r->pos += HX_BIN_RECORD_SIZE;
                r->offset += HX_BIN_RECORD_SIZE;
                r->record_slot++;
                continue;
            }
            for (;;) {
                int frc = bin_fill(r, HX_BIN_RECORD_SIZE + 1);
                if (frc <= 0) {
                    /* nothing valid until the end: drop the rest */
                    r->stats.skipped_bytes += (long)(r->len - r->pos);
                    r->offset += (long long)(r->len - r->pos);
                    r->pos = r->len;
                    r->eof = 1;
                    r->stats.clean_end = 1; /* error already deferred */
                    break;
                }
                r->pos++;
                r->offset++;
                r->stats.skipped_bytes++;
                if (hx_bin_record_decode(r->buf + r->pos, &rec) == 0) {
                    break;
                }
            }
            /* the stretch skipped (from the bad record to the next valid
             * one) counts as the records it holds, to the nearest whole
             * one: the fewest bytes inserted or lost. Ten bytes inserted
             * hold none, two damaged records two; counted as one whatever
             * its length, the records after ten bytes inserted would be
             * numbered one too high (test_bin_resync_numbers) */
            r->record_slot += (long)((r->offset - at + HX_BIN_RECORD_SIZE / 2) / HX_BIN_RECORD_SIZE);
        }
    }
}

/* ------------------------------------------------------------ public */

/* The index of the first byte among b[0..n) that no text log holds (a
 * control character but tab, line feed, vertical tab, form feed and
 * carriage return; DEL), or -1. */
static long binary_at(const unsigned char *b, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++) {
        if ((b[k] < 0x20 && (b[k] < 0x09 || b[k] > 0x0d)) || b[k] == 0x7f) {
            return (long)k;
        }
    }
    return -1;
}

/* The UTF-16 encoding of a text that starts with b[0..n) ("UTF-16" with a
 * byte-order mark, which iconv reads; "UTF-16LE" / "UTF-16BE" without one,
 * known by its first characters being ASCII: a NUL beside every printable
 * byte), or NULL. */
static const char *utf16_of(const unsigned char *b, size_t n)
{
    size_t k, m = n < 64 ? n & ~(size_t)1 : 64;
    int le = 1, be = 1;
    if (n >= 2 && ((b[0] == 0xff && b[1] == 0xfe) || (b[0] == 0xfe && b[1] == 0xff))) {
        return "UTF-16";
    }
    if (m < 4) {
        return NULL;
    }
    for (k = 0; k < m; k += 2) {
        le = le && b[k] >= 0x09 && b[k] < 0x7f && b[k + 1] == 0;
        be = be && b[k] == 0 && b[k + 1] >= 0x09 && b[k + 1] < 0x7f;
    }
    return le ? "UTF-16LE" : (be ? "UTF-16BE" : NULL);
}

/* Archives, containers and databases a log may come in, by their first
 * bytes (each format's published magic): what the file is and what to do
 * with it, for hx_head_not_text. */
static const struct {
    const char *magic;
    size_t len;
    const char *what;
} k_containers[] = {
    { "PK\x03\x04", 4, "a ZIP archive (an app's export of several files, or an .xlsx or .ods workbook): unzip it "
                        "(unzip FILE) and give the log inside; a workbook: save its sheet as CSV" },
    { "PK\x05\x06", 4, "an empty ZIP archive: no log inside" },
    { "\x89HDF\r\n\x1a\n", 8, "an HDF5 file (APDM's .h5, a MATLAB v7.3 .mat): write the IMU's data as CSV, e.g. "
                                "with h5dump or Python's h5py" },
    { "MATLAB 5.0 MAT-file", 19, "a MATLAB .mat file: write the IMU's data as CSV (writematrix or writetable)" },
    { "#ROSBAG V", 9, "a ROS bag: write its IMU topic as CSV (rostopic echo -b FILE -p /TOPIC > imu.csv) and give "
                      "that (docs/log-format.md, \"ROS, EuRoC and Kalibr\")" },
    { "SQLite format 3", 16, "an SQLite database: write the IMU's table as CSV (sqlite3 -header -csv FILE "
                             "'select * from TABLE' > imu.csv)" },
    { "BZh", 3, "bzip2-compressed data: decompress it (bunzip2 -k FILE) and give the result" },
    { "\xfd" "7zXZ", 5, "xz-compressed data: decompress it (unxz -k FILE) and give the result" },
    { "\x28\xb5\x2f\xfd", 4, "zstd-compressed data: decompress it (unzstd FILE) and give the result" },
    { "7z\xbc\xaf\x27\x1c", 6, "a 7-Zip archive: extract it (7z x FILE) and give the log inside" },
    { "\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1", 8, "an Excel .xls workbook (or another OLE file): save its sheet as CSV" },
    { "PAR1", 4, "an Apache Parquet file: write it as CSV (e.g. pandas' read_parquet, then to_csv)" },
};

/* "PATH: not a log but WHAT", FILE in what (its remedy's command) given
 * as the path, one shell word */
static void container_msg(char *msg, size_t size, const char *path, const char *what, int series)
{
    const char *file = strstr(what, "FILE");
    char word[1100];
    if (file != NULL && hx_shell_word(path, 0, word, sizeof word)[0] != '\0' && path[0] != '-') {
        snprintf(msg, size, "%s: not a %s but %.*s%s%s", path, series ? "series" : "log", (int)(file - what), what,
                 word, file + 4);
    } else {
        snprintf(msg, size, "%s: not a %s but %s", path, series ? "series" : "log", what);
    }
}

hx_head_t hx_head_not_text(const char *path, const unsigned char *head, size_t n, int series, char *msg,
                           size_t msg_size)
{
    const char *utf16 = utf16_of(head, n);
    long bin_at;
    size_t c;
    for (c = 0; c < sizeof k_containers / sizeof k_containers[0]; c++) {
        const size_t len = k_containers[c].len;
        /* BZh is text's too ("BZh" a name?): bzip2's block size digit and
         * its block magic 1AY&SY after it */
        const int bz = len == 3 && !(n >= 10 && head[3] >= '1' && head[3] <= '9' && memcmp(head + 4, "1AY&SY", 6) == 0);
        if (n >= len && memcmp(head, k_containers[c].magic, len) == 0 && !bz) {
            container_msg(msg, msg_size, path, k_containers[c].what, series);
            return HX_HEAD_CONTAINER;
        }
    }
    if (n >= 262 && memcmp(head + 257, "ustar", 5) == 0) { /* POSIX tar: "ustar" at byte 257 (a .tar.gz unpacked) */
        container_msg(msg, msg_size, path, "a tar archive: extract it (tar xf FILE) and give the log inside", series);
        return HX_HEAD_CONTAINER;
    }
    if (utf16 != NULL) {
        snprintf(msg, msg_size, "%s: UTF-16 text, not UTF-8 (save it as UTF-8, e.g. iconv -f %s -t UTF-8 %s > %s; %s)",
                 path, utf16, path, series ? "copy.txt" : "copy.csv",
                 series ? "a series: docs/allan.md, \"Input\"" : "the formats read: docs/log-format.md");
        return HX_HEAD_UTF16;
    }
    bin_at = binary_at(head, n);
    if (bin_at >= 0) {
        size_t k, m = n < 8 ? n : 8;
        char hex[3 * 8 + 1];
        hex[0] = '\0';
        for (k = 0; k < m; k++) {
            snprintf(hex + strlen(hex), sizeof hex - strlen(hex), "%s%02x", k > 0 ? " " : "", head[k]);
        }
        snprintf(msg, msg_size, "%s: binary data, not a %s: its first bytes %s hold 0x%02x at byte %lu, which no text %s",
                 path, series ? "series" : "log", hex, head[bin_at], (unsigned long)bin_at + 1,
                 series ? "holds (a series is text, numbers one per line: docs/allan.md, \"Input\")"
                        : "log holds, and a footnav .bin starts with FNAV (the formats read: docs/log-format.md)");
        return HX_HEAD_BINARY;
    }
    return HX_HEAD_TEXT;
}

/* A pipe's copy (hx_gzopen_input): the path it was read from and the
 * unlinked temporary file that holds its bytes, open until the end */
enum { SPOOL_MAX = 4 };
static struct {
    char path[4096];
    int fd;            /* -1: the copy failed (err), said again at every open */
    char err[HX_ERR_SIZE];
} g_spool[SPOOL_MAX];
static int g_spool_n = 0;

/* the bytes of the pipe at path into an unlinked temporary file: its fd, or
 * -1 with err filled (kept for the path: a later open would read the rest
 * of the pipe as the log) */
static int spool_pipe_once(const char *path, char *err, size_t err_size);

static int spool_pipe(const char *path, char *err, size_t err_size)
{
    const int fd = spool_pipe_once(path, err, err_size);
    if (fd < 0 && g_spool_n < SPOOL_MAX && strlen(path) < sizeof g_spool[0].path) {
        copy_str(g_spool[g_spool_n].path, sizeof g_spool[0].path, path);
        g_spool[g_spool_n].fd = -1;
        copy_str(g_spool[g_spool_n].err, sizeof g_spool[0].err, err);
        g_spool_n++;
    }
    return fd;
}

static int spool_pipe_once(const char *path, char *err, size_t err_size)
{
    static char buf[1 << 16];
    FILE *tmp;
    int in, fd;
    if (g_spool_n == SPOOL_MAX || strlen(path) >= sizeof g_spool[0].path) {
        snprintf(err, err_size, "%s: a pipe, and no room left to copy it (give a file)", path);
        return -1;
    }
    in = open(path, O_RDONLY);
    if (in < 0) {
        const int e = errno;
        snprintf(err, err_size, "%s: cannot open (%s)%s", path, strerror(e), hx_stdin_hint(path, e));
        return -1;
    }
    tmp = tmpfile();
    if (tmp == NULL) {
        snprintf(err, err_size, "%s: a pipe, read through a temporary file, which cannot be made (%s)", path,
                 strerror(errno));
        close(in);
        return -1;
    }
    fd = fileno(tmp);
    for (;;) {
        const ssize_t got = read(in, buf, sizeof buf);
        ssize_t off = 0;
        if (got == 0) {
            break;
        }
        if (got < 0) {
            if (errno == EINTR) {
                continue;
            }
            snprintf(err, err_size, "%s: read error (%s)", path, strerror(errno));
            close(in);
            fclose(tmp);
            return -1;
        }
        while (off < got) {
            const ssize_t put = write(fd, buf + off, (size_t)(got - off));
            if (put < 0 && errno == EINTR) {
                continue;
            }
            if (put <= 0) {
                snprintf(err, err_size, "%s: a pipe, read through a temporary file, which cannot be written (%s)",
                         path, put < 0 ? strerror(errno) : "no space");
                close(in);
                fclose(tmp);
                return -1;
            }
            off += put;
        }
    }
    close(in);
    /* tmp stays open (its FILE with it) until the process ends: the
     * readers open the path again */
    copy_str(g_spool[g_spool_n].path, sizeof g_spool[0].path, path);
    g_spool[g_spool_n].fd = fd;
    g_spool_n++;
    return fd;
}

gzFile hx_gzopen_input(const char *path, char *err, size_t err_size)
{
    struct stat st, null_st;
    gzFile gz;
    int k, fd = -1;
    for (k = 0; k < g_spool_n; k++) {
        if (strcmp(g_spool[k].path, path) == 0) {
            if (g_spool[k].fd < 0) {
                snprintf(err, err_size, "%s", g_spool[k].err);
                return NULL;
            }
            fd = g_spool[k].fd;
        }
    }
    if (fd < 0 && stat(path, &st) == 0) {
        if (S_ISCHR(st.st_mode) &&
            !(stat("/dev/null", &null_st) == 0 && S_ISCHR(null_st.st_mode) && null_st.st_rdev == st.st_rdev)) {
            snprintf(err, err_size, "%s: a character device (a terminal, a serial port), not a log file (a serial "
                                    "port is read by `harness live`)", path);
            return NULL;
        }
        if (S_ISFIFO(st.st_mode)) {
            fd = spool_pipe(path, err, err_size);
            if (fd < 0) {
                return NULL;
            }
        }
    }
    if (fd >= 0) {
        /* a reader of its own with its own offset (a dup() would share
         * one: the rate's estimate reads the start while the reader is
         * open) */
        char self[64];
        int own;
        snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
        own = open(self, O_RDONLY);
        if (own < 0) {
            snprintf(err, err_size, "%s: a pipe, whose copy cannot be read again (%s: %s)", path, self,
                     strerror(errno));
            return NULL;
        }
        gz = gzdopen(own, "rb");
        if (gz == NULL) {
            close(own);
        }
    } else {
        errno = 0;
        gz = gzopen(path, "rb");
    }
    if (gz == NULL) {
        const int e = errno;
        snprintf(err, err_size, "%s: cannot open (%s)%s", path, e ? strerror(e) : "gzopen failed", hx_stdin_hint(path, e));
    }
    return gz;
}

/* fopen(path, "rb") of a log's raw bytes (the .gz trailer checks), its
 * copy for a pipe hx_gzopen_input has read (a second open of the pipe
 * would wait for a writer for ever) */
static FILE *fopen_input(const char *path)
{
    int k;
    for (k = 0; k < g_spool_n; k++) {
        if (strcmp(g_spool[k].path, path) == 0) {
            char self[64];
            if (g_spool[k].fd < 0) {
                return NULL;
            }
            snprintf(self, sizeof self, "/proc/self/fd/%d", g_spool[k].fd);
            return fopen(self, "rb");
        }
    }
    return fopen(path, "rb");
}

static hx_reader_t *open_raw(const char *path, hx_format_t fmt, double rate_hz, char *err, size_t err_size)
{
    hx_reader_t *r;
    unsigned char head[600];
    int got, guessed = 0;
    hx_head_t head_kind = HX_HEAD_TEXT;
    char head_msg[HX_ERR_SIZE];
    if (rate_hz < 0.0 || rate_hz > 1.0e6 || rate_hz != rate_hz) {
        snprintf(err, err_size, "%s: sample rate %g Hz is not in (0, 1e6]", path, rate_hz);
        return NULL;
    }
    r = (hx_reader_t *)calloc(1, sizeof *r);
    if (r == NULL) {
        snprintf(err, err_size, "%s: out of memory", path);
        return NULL;
    }
    r->date_join = -1;
    copy_str(r->path, sizeof r->path, path);
    r->gz = hx_gzopen_input(path, err, err_size);
    if (r->gz == NULL) {
        free(r);
        return NULL;
    }
    (void)gzbuffer(r->gz, 1 << 16);
    got = gzread(r->gz, head, sizeof head);
    if (got < 0) {
        int e;
        snprintf(err, err_size, "%s: read error (%s)", path, gzerror(r->gz, &e));
        gzclose(r->gz);
        free(r);
        return NULL;
    }
    if (got == 0) {
        /* nothing decompressed: an empty file, or a .gz cut inside its
         * first block, told apart (not "empty file" for both) */
        int e;
        (void)gzerror(r->gz, &e);
        snprintf(err, err_size, "%s: %s", path,
                 e == Z_BUF_ERROR ? "the gzip data ends before any of it inflates (a truncated .gz, e.g. an incomplete copy)"
                                  : "empty file");
        gzclose(r->gz);
        free(r);
        return NULL;
    }
    if (fmt != HX_FMT_BIN &&
        ((head_kind = hx_head_not_text(path, head, (size_t)got, 0, head_msg, sizeof head_msg)) == HX_HEAD_UTF16 ||
         head_kind == HX_HEAD_CONTAINER)) {
        /* Windows' "Unicode text" export: "FILE:1: a NUL byte in the text
         * (binary data ...)" with its byte-order mark, the hint of
         * --columns without it would be wrong: it only needs saving as
         * UTF-8. An archive or a database (a zip, a ROS bag): named, with
         * what to do, not "a NUL byte" at some line */
        snprintf(err, err_size, "%s", head_msg);
        gzclose(r->gz);
        free(r);
        return NULL;
    }
    if (fmt == HX_FMT_AUTO) {
        fmt = detect(head, (size_t)got);
        guessed = 1;
        if (fmt != HX_FMT_BIN && got >= 4 && (hx_ends_in(path, strlen(path), ".bin") ||
                                              hx_ends_in(path, strlen(path), ".bin.gz"))) {
            /* a .bin whose magic is one byte off (a flipped bit) is no
             * text: read as CSV it would give "a NUL byte in the text"
             * (test_bin_bad_magic). Three of the four bytes of FNAV, and
             * the name: no text file is so taken */
            int k, same = 0;
            for (k = 0; k < 4; k++) {
                same += head[k] == (unsigned char)HX_BIN_MAGIC[k];
            }
            if (same == 3) {
                snprintf(err, err_size, "%s: not a footnav .bin: bad magic (its first 4 bytes are %02x %02x %02x "
                                        "%02x, not FNAV's %02x %02x %02x %02x: a damaged file?)",
                         path, head[0], head[1], head[2], head[3], (unsigned char)HX_BIN_MAGIC[0],
                         (unsigned char)HX_BIN_MAGIC[1], (unsigned char)HX_BIN_MAGIC[2],
                         (unsigned char)HX_BIN_MAGIC[3]);
                gzclose(r->gz);
                free(r);
                return NULL;
            }
        }
    }
    if (gzrewind(r->gz) != 0) {
        snprintf(err, err_size, "%s: cannot rewind", path);
        gzclose(r->gz);
        free(r);
        return NULL;
    }
    r->meta.format = fmt;
    copy_str(r->meta.source, sizeof r->meta.source, path);
    if (g_layout.option == NULL) {
        hx_csv_layout_default(&r->layout);
    } else if (fmt != HX_FMT_CSV) {
        /* for a caller that skipped hx_check_input_opts, which refuses it
         * as a usage error before reading */
        hx_layout_refusal(err, err_size, path, g_layout.option, fmt, guessed);
        gzclose(r->gz);
        free(r);
        return NULL;
    } else {
        r->layout = g_layout;
    }
    if (((fmt == HX_FMT_BIN) ? setup_bin(r) : setup_text(r, rate_hz)) != 0) {
        if (!guessed || (fmt == HX_FMT_CSV && (r->missing_col != 0 || r->layout.option != NULL))) {
            /* given with --from, or our CSV known by its 't' column */
            snprintf(err, err_size, "%s", r->err);
        } else if (fmt == HX_FMT_CSV && head_kind == HX_HEAD_BINARY) {
            /* a PNG, a zip given as a log: named as binary data, not told
             * "header has no column 't' ... give its names and units with
             * --columns", which no such file can follow */
            snprintf(err, err_size, "%s", head_msg);
        } else if (fmt == HX_FMT_CSV) {
            /* --from alone would leave a layout no importer reads (a phone
             * app's export) without a way: --columns and --units named */
            snprintf(err, err_size, "%s (no importer's header recognised, read as footnav CSV; give --from FORMAT "
                                    "for another format, or give its names and units with --columns and --units: "
                                    "docs/log-format.md, \"Another layout\")", r->err);
        } else {
            snprintf(err, err_size, "%s (format %s detected from the content; give --from FORMAT if it is another)",
                     r->err, hx_format_name(fmt));
        }
        gzclose(r->gz);
        free(r);
        return NULL;
    }
    if (fmt == HX_FMT_MTMGR && r->mt.us_like) {
        /* read as an MT Manager export, with no '//' line, with stamps
         * that make an IMU's rate in us and none in 100 us ticks (or one
         * of DOT's rates under a header of DOT's): Movella DOT's CSV
         * (hx_mtmgr_stamps), refused with the CSV reader's remedy (read as
         * an export it would be 100 times too slow). Given with --from
         * mtmanager too: read in ticks, as asked, it would take DOT's deg/s
         * as rad/s; an export whose '//' lines were cut is read with one
         * put back */
        hx_mtmgr_us_refusal(&r->mt, path, err, err_size);
        gzclose(r->gz);
        free(r);
        return NULL;
    }
    if (fmt == HX_FMT_CSV) {
        g_read_layout = r->layout;
        g_read_matched = r->layout.names_matched;
    }
    if (rate_hz > 0.0 && (fmt == HX_FMT_BIN || r->time_mode == TIME_COLUMN_S || r->time_mode == TIME_GX2 ||
                          (r->time_mode == TIME_MTMGR && r->mt.time_src == HX_MTMGR_TIME_STF))) {
        /* --input-rate gives the rate of an input without time stamps
         * (docs/harness.md): ignored here with a warning. Replacing a
         * .bin's header rate, every analysis would use it against the
         * stamps (`psd walk.bin --input-rate 100` would analyse the 398 Hz
         * walk as 100 Hz); ignored without a word, a time-stamped text log
         * would not say so */
        add_warn(r, "%s: --input-rate ignored: the %s format has time stamps", path, hx_format_name(fmt));
        r->meta.rate_ignored = 1;
    }
    return r;
}

static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

double hx_rate_changes(const int64_t *t_ns, size_t n, size_t stride, double rate_hz, double *at_s, double *rate_off)
{
#define STAMP(i) (*(const int64_t *)(const void *)((const char *)t_ns + (i) * stride))
    int64_t d[HX_RATE_BLOCK], q = 0;
    size_t i, m = 0, b0 = 0;
    double off_s = 0.0, dur;
    *at_s = *rate_off = (double)NAN;
    if (!(rate_hz > 0.0) || n < 2) {
        return 0.0;
    }
    dur = 1e-9 * (double)(STAMP(n - 1) - STAMP(0));
    if (!(dur > 0.0)) {
        return 0.0;
    }
    /* the stamps' resolution: the gcd of the whole log's intervals. A
     * block's own gcd is no resolution when its stamps are exact (from a
     * sample counter): 200 intervals of 20 ms have a gcd of 20 ms, so a log
     * whose exact stamps went from 10 to 20 ms was never "off by a
     * resolution" and its rate change went unreported */
    for (i = 1; i < n; i++) {
        const int64_t dt = STAMP(i) - STAMP(i - 1);
        if (dt > 0) {
            q = hx_gcd_i64(dt, q);
        }
    }
    for (i = 1; i <= n; i++) {
        if (i < n) {
            const int64_t dt = STAMP(i) - STAMP(i - 1);
            if (dt > 0) {
                d[m++] = dt;
            }
        }
        if (m == HX_RATE_BLOCK || (i == n && 2 * m >= HX_RATE_BLOCK)) {
            double med, rate;
            qsort(d, m, sizeof d[0], cmp_i64);
            med = (double)d[m / 2];
            rate = 1e9 / med;
            /* off by more than the tolerance, and by a resolution of the
             * stamps or more (a 398 Hz log stamped to the millisecond reads
             * 2 and 3 ms) */
            if (fabs(rate / rate_hz - 1.0) > HX_RATE_TOL && fabs(med - 1e9 / rate_hz) >= (double)q) {
                const size_t b1 = i < n ? i : n - 1;
                if (!isfinite(*at_s)) {
                    *at_s = 1e-9 * (double)(STAMP(b0) - STAMP(0));
                    *rate_off = rate;
                }
                off_s += 1e-9 * (double)(STAMP(b1) - STAMP(b0));
            }
            m = 0;
            b0 = i < n ? i : b0;
        }
    }
    return off_s / dur;
#undef STAMP
}

int64_t hx_gcd_i64(int64_t a, int64_t b)
{
    while (b != 0) {
        const int64_t r = a % b;
        a = b;
        b = r;
    }
    return a;
}

/* The resolution's slack of an interval at rate_hz (hx_interval_irregular). */
static double res_slack_s(double rate_hz, int64_t res_ns)
{
    if (res_ns > 0) {
        /* a period that is a whole number of resolutions (100 Hz printed to
         * 10 ms) reads exact intervals, as hx_stamp_rate_hz takes them: no
         * slack. With it a lost sample (20 ms) was within 10 % + 10 ms of
         * 10 ms, and a log that lost single samples was called uniform */
        const double k = 1e9 / rate_hz / (double)res_ns;
        if (fabs(k - floor(k + 0.5)) > 0.05) {
            return 1e-9 * (double)res_ns;
        }
    }
    return 0.0;
}

int hx_interval_irregular(int64_t dt_ns, double rate_hz, int64_t res_ns)
{
    const double dt = 1e-9 * (double)dt_ns;
    return fabs(dt - 1.0 / rate_hz) > 0.1 / rate_hz + res_slack_s(rate_hz, res_ns);
}

double hx_interval_missing(int64_t dt_ns, double rate_hz, int64_t res_ns)
{
    const double dt = 1e-9 * (double)dt_ns;
    return dt > 1.5 / rate_hz + res_slack_s(rate_hz, res_ns) ? floor(dt * rate_hz + 0.5) - 1.0 : 0.0;
}

int hx_time_unit_fix(double rate_hz, int digits, hx_time_fix_t *fix)
{
    static const struct {
        double scale;
        const char *div;
    } k_units[] = { { 1e3, "1000" }, { 1e6, "1e6" }, { 1e9, "1e9" } };
    /* by (9 - digits) / 3 */
    static const char *const k_name[4] = { "seconds", "milliseconds", "microseconds", "nanoseconds" };
    static const char *const k_opt[4] = { "s", "ms", "us", "ns" };
    size_t u;
    memset(fix, 0, sizeof *fix);
    fix->read = k_name[(9 - digits) / 3];
    if (rate_hz > HX_TIME_RATE_MAX_HZ) {
        /* too fast: read in a finer unit than theirs (ms read as ns look
         * 1e6 times too fast); nothing is coarser than seconds. As on the
         * slow side, the unit that gives the lowest rate of 20 Hz or more
         * (100 MHz read as ns: ms, 100 Hz, not us, 100 kHz) */
        for (u = sizeof k_units / sizeof k_units[0]; u-- > 0;) {
            const double r_u = rate_hz / k_units[u].scale;
            const int true_digits = digits + 3 * (int)(u + 1u);
            if (true_digits > 9) {
                continue;
            }
            if (r_u >= HX_TIME_RATE_MIN_HZ && r_u <= HX_TIME_RATE_MAX_HZ) {
                fix->name = k_name[(9 - true_digits) / 3];
                fix->opt = k_opt[(9 - true_digits) / 3];
                fix->digits = true_digits;
                fix->div = k_units[u].div;
                fix->fast = 1;
                fix->rate_hz = r_u;
                return 1;
            }
        }
        return 0;
    }
    for (u = 0; u < sizeof k_units / sizeof k_units[0]; u++) {
        const double r_u = rate_hz * k_units[u].scale;
        if (r_u >= HX_TIME_RATE_MIN_HZ && r_u <= HX_TIME_RATE_MAX_HZ) {
            /* us read as ms look like us; nothing is finer than ns */
            const int true_digits = digits - 3 * (int)(u + 1u);
            if (true_digits < 0) {
                return 0;
            }
            fix->name = k_name[(9 - true_digits) / 3];
            fix->opt = k_opt[(9 - true_digits) / 3];
            fix->digits = true_digits;
            fix->div = k_units[u].div;
            fix->rate_hz = r_u;
            return 1;
        }
    }
    return 0;
}

/* A rate the time hint questions: below 1 Hz (a static log may be slow, but
 * not so slow), or above HX_TIME_RATE_MAX_HZ (stamps read in a finer unit
 * than theirs): both sides are questioned */
static int time_rate_odd(double rate_hz)
{
    return (rate_hz > 0.0 && rate_hz < 1.0) || rate_hz > HX_TIME_RATE_MAX_HZ;
}

int hx_time_unit_hint(double rate_hz, const hx_csv_layout_t *csv, char *msg, size_t msg_size)
{
    hx_time_fix_t fix;
    char fix_text[64];
    if (msg_size > 0u) {
        msg[0] = '\0';
    }
    if (!time_rate_odd(rate_hz) || !hx_time_unit_fix(rate_hz, csv != NULL ? csv->time_digits : 9, &fix)) {
        return 0;
    }
    if (csv != NULL) {
        hx_csv_layout_t want = *csv;
        want.time_digits = fix.digits;
        hx_units_give(&want, fix_text, sizeof fix_text);
    } else {
        snprintf(fix_text, sizeof fix_text, "%s by %s", fix.fast ? "multiply" : "divide", fix.div);
    }
    snprintf(msg, msg_size,
             "the samples are %.4g s apart (%.3g Hz): are the time stamps in %s? (they look like %s, a %.4g Hz log: "
             "%s)",
             1.0 / rate_hz, rate_hz, fix.read, fix.name, fix.rate_hz, fix_text);
    return 1;
}

double hx_time_unit_rate(double rate_hz, size_t n, int64_t t_first_ns, int64_t t_last_ns)
{
    /* one test for every command, so that none of info, allan, psd and
     * simgap tells stamps in bursts time=ms where replay does not */
    const int fast = rate_hz > HX_TIME_RATE_MAX_HZ, slow = rate_hz > 0.0 && rate_hz < HX_TIME_RATE_MIN_HZ;
    double span_hz;
    if (!fast && !slow) {
        return rate_hz; /* a foot-mounted IMU's rate: no unit to question, whatever the span */
    }
    if (n < 2u || t_last_ns <= t_first_ns) {
        return rate_hz; /* no span: the intervals alone */
    }
    span_hz = 1e9 * (double)(n - 1u) / (double)(t_last_ns - t_first_ns);
    /* a wrong unit makes the span as fast (or as slow) as the intervals;
     * stamps in bursts leave it at the sampling rate */
    return (fast && span_hz > HX_TIME_RATE_MAX_HZ) || (slow && span_hz < HX_TIME_RATE_MIN_HZ) ? rate_hz : 0.0;
}

/* The strictly increasing stamps of t_ns[0..n) into v (duplicates and steps
 * back dropped); their count. hx_stamp_rate_hz's and hx_stamp_bursts's. */
static size_t distinct_stamps(const int64_t *t_ns, size_t n, int64_t *v)
{
    size_t i, m = 0;
    for (i = 0; i < n; i++) {
        if (m == 0u || t_ns[i] > v[m - 1u]) {
            v[m++] = t_ns[i];
        }
    }
    return m;
}

/* The rate the bursts of t_ns[0..n) give, into b->rate_hz (left as it is,
 * the samples over the span, when no segment has 3 bursts): a burst starts
 * at a stamp more than half a period (b->rate_hz's, the samples over the
 * span) after the latest one before it; a time jump (over gap_ns) starts a
 * segment. Per segment the samples from the start of its second burst to
 * the start of its last, over the time between those two stamps, summed
 * over the segments: whole packets only, whatever the first (cut by the
 * log's start or a time jump) and the last (cut by its end) hold. Either
 * kind: a burst of samples stamped close together (5 us apart), or of
 * samples that share one stamp (every distinct stamp starts one). The
 * samples over the span would count a cut last packet's and the first
 * packet's samples against a span that ends at the last stamp: 250.1 Hz
 * for 250 Hz. */
static void bursts_rate(const int64_t *t_ns, size_t n, int64_t gap_ns, hx_bursts_t *b)
{
    const double half_ns = b->rate_hz > 0.0 ? 0.5e9 / b->rate_hz : 0.0;
    int64_t last = t_ns[0], t2 = 0, tl = 0, time_ns = 0;
    size_t i, i2 = 0, il = 0, bursts = 1, count = 0;
    for (i = 1; i <= n; i++) {
        const int64_t dt = i < n ? t_ns[i] - last : 0;
        if (i < n && dt <= 0) {
            continue; /* a repeated stamp or a step back: the burst goes on */
        }
        if (i == n || dt > gap_ns) {
            if (bursts >= 3u) { /* the segment's end: its whole packets */
                count += il - i2;
                time_ns += tl - t2;
            }
            bursts = 1;
        } else if ((double)dt > half_ns) {
            if (++bursts == 2u) {
                i2 = i;
                t2 = t_ns[i];
            }
            il = i;
            tl = t_ns[i];
        }
        if (i < n) {
            last = t_ns[i];
        }
    }
    if (time_ns > 0) {
        b->rate_hz = 1e9 * (double)count / (double)time_ns;
    }
}

int hx_stamp_bursts(const int64_t *t_ns, size_t n, double max_gap_s, hx_bursts_t *b)
{
    /* the test of every command, not of --rate's resampler alone
     * (hx_nav.c): plain replay would navigate such logs at "200 kHz" (0
     * strides, exit 0) */
    int64_t *v, *d, gap_ns;
    size_t i, m = 0, a, e;
    memset(b, 0, sizeof *b);
    b->n = n;
    if (t_ns == NULL || n < 2u) {
        return HX_BURSTS_NONE;
    }
    v = (int64_t *)malloc(2u * n * sizeof *v);
    if (v == NULL) {
        return -1;
    }
    d = v + n;
    m = distinct_stamps(t_ns, n, v); /* exact repeated stamps carry no new instant */
    b->distinct = m;
    if (m < 2u) {
        free(v);
        return HX_BURSTS_NONE;
    }
    for (i = 1; i < m; i++) {
        d[i - 1u] = v[i] - v[i - 1u];
    }
    qsort(d, m - 1u, sizeof *d, cmp_i64);
    b->median_hz = 1e9 / (double)d[(m - 1u) / 2u];
    if (m < 4u) {
        free(v);
        return HX_BURSTS_NONE;
    }
    gap_ns = (int64_t)ceil(1e9 * (max_gap_s > 1.5 / b->median_hz ? max_gap_s : 1.5 / b->median_hz));
    for (a = 0; a < m; a = e) {
        for (e = a + 1u; e < m && v[e] - v[e - 1u] <= gap_ns; e++) {
        }
        b->span_s += 1e-9 * (double)(v[e - 1u] - v[a]);
        b->segs++;
    }
    free(v);
    b->rate_hz = b->span_s > 0.0 ? (double)(n - b->segs) / b->span_s : 0.0;
    bursts_rate(t_ns, n, gap_ns, b);
    {
        /* the samples the median interval gives: one per segment and one
         * per interval over the span */
        const double expect = b->span_s * b->median_hz + (double)b->segs;
        b->kind = (double)n < 0.5 * expect   ? HX_BURSTS_CLOSE
                  : (double)n > 1.5 * expect ? HX_BURSTS_SHARED
                                             : HX_BURSTS_NONE;
    }
    return (int)b->kind;
}

/* hx_bursts_text's cause, up to the rate of the samples' span: "the time
 * stamps come in bursts (...): 1 / their median interval gives 200000 Hz,
 * but the 16539 samples span 41.34 s, 400 Hz" */
static void bursts_cause(const hx_bursts_t *b, char *msg, size_t size)
{
    /* more samples than the median interval gives, with (nearly) every
     * stamp distinct: samples stamped close together in pairs (0.1 ms and
     * 9.9 ms apart), whose median interval is the long one; not samples
     * sharing one stamp (tests/cli/test_bad_input.sh) */
    const int close = b->kind == HX_BURSTS_CLOSE || (double)b->distinct >= 0.9 * (double)b->n;
    snprintf(msg, size,
             "the time stamps come in bursts (%s): 1 / their median interval gives %.6g Hz, but the %s%zu samples "
             "span %.4g s%s, %.4g Hz",
             close ? "samples stamped close together as a logger reads them?"
                   : "samples that share one stamp: one per packet, or stamps coarser than the sampling?",
             b->median_hz, b->first ? "first " : "", b->n, b->span_s, b->segs > 1u ? " between the time jumps" : "",
             b->rate_hz);
}

const char *hx_bursts_remedy(hx_format_t fmt, double rate_hz, char *msg, size_t size)
{
    /* not every format is told to leave its time column out: a .bin has
     * none, and the importers' logs with their time column cut
     * are no longer their format; --input-rate is ignored (with a warning)
     * on a .bin and a time-stamped importer's log, and a counter's only
     * rescales the stamps. The converted CSV's t is its first column
     * (cmd_convert), which cut takes out */
    if ((fmt == HX_FMT_CSV || fmt == HX_FMT_AUTO) && g_layout.option != NULL && g_layout.names[0][0] != '\0') {
        /* a time column --columns names (a DOT CSV's t=SampleTimeFine):
         * the item goes too, since --columns t= with --input-rate is an
         * error, and t= naming a column cut from the file is one */
        snprintf(msg, size, "leave the time column out (drop t=%s from --columns) and give --input-rate %.4g",
                 g_layout.names[0], rate_hz);
    } else if (fmt == HX_FMT_CSV || fmt == HX_FMT_AUTO) {
        snprintf(msg, size, "leave the time column out and give --input-rate %.4g", rate_hz);
    } else {
        snprintf(msg, size, HX_CONVERT_REMEDY("--input-rate %.4g"), rate_hz);
    }
    return msg;
}

const char *hx_bursts_text(const hx_bursts_t *b, const char *needs, const char *section, char *msg, size_t size)
{
    size_t len;
    char fix[192];
    bursts_cause(b, msg, size);
    len = strlen(msg);
    if (len < size) {
        snprintf(msg + len, size - len, "; %s: %s (docs/harness.md, \"%s\")", needs,
                 hx_bursts_remedy(b->format, b->rate_hz, fix, sizeof fix), section);
    }
    return msg;
}

const char *hx_bursts_rate_text(const hx_bursts_t *b, const char *reads, double rate_hz, int nominal, char *msg,
                                size_t size)
{
    /* not "read at R Hz, not the sampling rate" in every case: where R is
     * the rate the file states and the span keeps (a .bin's nominal rate),
     * it is the sampling rate */
    const int kept = nominal && b->rate_hz > 0.0 && fabs(rate_hz / b->rate_hz - 1.0) <= HX_BURSTS_RATE_TOL;
    size_t len;
    char fix[192];
    bursts_cause(b, msg, size);
    len = strlen(msg);
    if (len >= size) {
        return msg;
    }
    if (kept) {
        snprintf(msg + len, size - len,
                 "; %s %.4g Hz, the rate the file states, which the samples' span keeps, not the stamps' %.6g Hz "
                 "(docs/harness.md, \"Time stamps in bursts\")",
                 reads, rate_hz, b->median_hz);
    } else {
        snprintf(msg + len, size - len,
                 "; %s %.4g Hz, %s: %s (docs/harness.md, \"Time stamps in bursts\")", reads, rate_hz,
                 nominal ? "the rate the file states, which the samples' span does not keep"
                         : "the stamps' rate, not the sampling rate",
                 hx_bursts_remedy(b->format, b->rate_hz, fix, sizeof fix));
    }
    return msg;
}

double hx_log_time_unit_rate(const hx_log_t *log, double rate_hz)
{
    return log->n > 0u ? hx_time_unit_rate(rate_hz, log->n, log->t_ns[0], log->t_ns[log->n - 1u]) : rate_hz;
}

const hx_csv_layout_t *hx_time_unit_layout(double rate_hz, const hx_csv_layout_t *csv, hx_csv_layout_t *buf)
{
    hx_time_fix_t fix;
    if (csv == NULL || !time_rate_odd(rate_hz) || !hx_time_unit_fix(rate_hz, csv->time_digits, &fix)) {
        return csv;
    }
    *buf = *csv;
    buf->time_digits = fix.digits;
    return buf;
}

/* A count's size as --units reads it back to the same scale: 9 digits
 * in the first unit that gives it exactly (0.0609756dps, not the mdps
 * number that rounds otherwise), else 17 digits in the first unit. */
static const char *count_name(char *buf, size_t size, double scale, const double *unit, const char *const *name,
                              int n)
{
    int i;
    for (i = 0; i < n; i++) {
        snprintf(buf, size, "%.9g%s", scale / unit[i], name[i]);
        if (strtod(buf, NULL) * unit[i] == scale) {
            return buf;
        }
    }
    snprintf(buf, size, "%.17g%s", scale / unit[0], name[0]);
    return buf;
}

const char *hx_accel_unit_name(double acc_scale)
{
    static char buf[40];
    if (acc_scale == HX_G_MPS2 || acc_scale == HX_MG_MPS2 || acc_scale == HX_UG_MPS2 || acc_scale == 1.0) {
        return acc_scale == HX_G_MPS2 ? "g" : acc_scale == HX_MG_MPS2 ? "mg" : acc_scale == HX_UG_MPS2 ? "ug" : "m/s2";
    }
    /* a count's size (--units accel=0.061mg), as --units reads it back */
    {
        static const double k_scale[4] = { HX_MG_MPS2, HX_G_MPS2, HX_UG_MPS2, 1.0 };
        static const char *const k_name[4] = { "mg", "g", "ug", "m/s2" };
        return count_name(buf, sizeof buf, acc_scale, k_scale, k_name, 4);
    }
}

const char *hx_gyro_unit_name(double gyr_scale)
{
    static char buf[40];
    if (gyr_scale == HX_DPS_RPS || gyr_scale == HX_MDPS_RPS || gyr_scale == 1.0) {
        return gyr_scale == HX_DPS_RPS ? "deg/s" : gyr_scale == HX_MDPS_RPS ? "mdps" : "rad/s";
    }
    {
        static const double k_scale[3] = { HX_MDPS_RPS, HX_DPS_RPS, 1.0 }; /* --units gyro=8.75mdps */
        static const char *const k_name[3] = { "mdps", "deg/s", "rad/s" };
        return count_name(buf, sizeof buf, gyr_scale, k_scale, k_name, 3);
    }
}

const char *hx_units_give(const hx_csv_layout_t *want, char *buf, size_t size)
{
    /* one --units value: a second --units replaces the first (a
     * non-repeatable option given twice takes the last value), so each
     * remedy names every item, in the order of the synopsis */
    static const char *const k_opt[4] = { "s", "ms", "us", "ns" };
    size_t len;
    snprintf(buf, size, "give --units ");
    len = strlen(buf);
    if (want->time_digits != 9 && len < size) {
        snprintf(buf + len, size - len, "time=%s,", k_opt[(9 - want->time_digits) / 3]);
        len = strlen(buf);
    }
    if (want->acc_scale != 1.0 && len < size) {
        snprintf(buf + len, size - len, "accel=%s,", hx_accel_unit_name(want->acc_scale));
        len = strlen(buf);
    }
    if (want->gyr_scale != 1.0 && len < size) {
        snprintf(buf + len, size - len, "gyro=%s,", hx_gyro_unit_name(want->gyr_scale)); /* a count's size kept */
        len = strlen(buf);
    }
    if (len > 0u && buf[len - 1u] == ',') {
        buf[len - 1u] = '\0';
    } else if (len > 0u && buf[len - 1u] == ' ') {
        /* no item: the file is in s, m/s^2 and rad/s, the defaults, so the
         * --units given is what is wrong (seconds read as time=ms) */
        snprintf(buf, size, "leave --units out");
    }
    return buf;
}

double hx_stamp_rate_hz(const int64_t *t_ns, size_t n, int *coarse)
{
    enum { K = 16 };
    int64_t *v, *d, *srt, q = 0;
    size_t i, m = 0, w, used = 0;
    double t1, thr, sum = 0.0, rate;
    if (coarse != NULL) {
        *coarse = 0;
    }
    if (t_ns == NULL || n < 2u) {
        return 0.0;
    }
    v = (int64_t *)malloc(3u * n * sizeof *v);
    if (v == NULL) {
        return 0.0;
    }
    d = v + n;
    srt = d + n;
    /* the strictly increasing stamps, their intervals, and the intervals'
     * greatest common divisor: the stamps' resolution (1 ms for stamps
     * printed to three decimals) */
    m = distinct_stamps(t_ns, n, v);
    if (m < 2u) {
        free(v);
        return 0.0;
    }
    for (i = 0; i + 1u < m; i++) {
        d[i] = v[i + 1u] - v[i];
        q = hx_gcd_i64(d[i], q);
    }
    memcpy(srt, d, (m - 1u) * sizeof *srt);
    qsort(srt, m - 1u, sizeof srt[0], cmp_i64);
    t1 = (double)srt[(m - 1u) / 2u];
    if (1000.0 * (double)q <= t1) {
        /* the stamps resolve the period: the median interval, which no
         * jitter outlier or gap moves */
        free(v);
        return 1.0e9 / t1;
    }
    if (coarse != NULL) {
        *coarse = 1;
    }
    /* Coarse stamps: the median interval is one of the few values they can
     * show. A first period from the spans of K intervals (a span carries
     * the stamps' rounding once, not K times), then the mean of the
     * intervals that are not gaps: rounding errors cancel in the sum, and a
     * lost sample (two periods, give or take the resolution) is left out.
     * The span is their 10th percentile: a lost sample only lengthens a
     * span, so it is one without one while more than a tenth of the spans
     * hold none (up to 13 % of the samples lost; rounding moves it by at
     * most a resolution over K). Not the median: above 4.2 % lost the
     * median span would hold one, 17 periods over 16, and the gap threshold
     * let one lost sample's interval in (95.3 Hz for 100 Hz at 5 %;
     * test_log test_stamp_rate) */
    if (m >= 3u * K + 1u) {
        for (w = 0; (w + 1u) * K < m; w++) {
            srt[w] = v[(w + 1u) * K] - v[w * K];
        }
        qsort(srt, w, sizeof srt[0], cmp_i64);
        t1 = (double)srt[w / 10u] / (double)K;
    }
    /* a period that is a whole number of resolutions (stamps from a sample
     * counter, k / rate, or exact ones rounded at a multiple of the period)
     * has exact intervals: a gap is anything over 1.5 periods. Otherwise an
     * interval of one period reads up to a resolution longer. */
    thr = 1.5 * t1;
    if (fabs(t1 / (double)q - floor(t1 / (double)q + 0.5)) > 0.05) {
        thr += (double)q;
    }
    {
        int64_t lo = INT64_MAX, hi = 0;
        for (i = 0; i + 1u < m; i++) {
            if ((double)d[i] <= thr) {
                sum += (double)d[i];
                used++;
                lo = d[i] < lo ? d[i] : lo;
                hi = d[i] > hi ? d[i] : hi;
            }
        }
        if (used > 0u && lo == hi && m == n && coarse != NULL) {
            /* every interval that is no gap the same and no stamp repeated
             * (a sample counter's k / rate, lost samples as gaps): the
             * stamps show no rounding and the median interval, the
             * detector's own estimate, is exact, and replay does not call
             * such a grid "too coarse for the detector's estimate"
             * (test_stamp_rate). Repeated stamps (10 s stamps on
             * a 100 Hz log) hide the samples' own times: coarse. */
            *coarse = 0;
        }
    }
    rate = used > 0u ? 1.0e9 * (double)used / sum : 1.0e9 / t1;
    free(v);
    return rate;
}

/* 1 / the median of the positive intervals among the first
 * FNAV_STANCE_RATE_PROBE + 1 stamps (fewer with a shorter window ring), as
 * the stance detector estimates its rate (fnav_stance.c estimate_rate: the
 * upper median of an even count);
 * 0 without one. */
static double start_rate_hz(const int64_t *t, size_t n)
{
    enum { PROBE = HX_STANCE_PROBE };
    int64_t d[PROBE];
    size_t i;
    int k = 0, j;
    for (i = 1; i < n && i <= PROBE; i++) {
        const int64_t v = t[i] - t[i - 1];
        if (v > 0) {
            for (j = k; j > 0 && d[j - 1] > v; j--) {
                d[j] = d[j - 1];
            }
            d[j] = v;
            k++;
        }
    }
    return k > 0 ? 1e9 / (double)d[k / 2] : 0.0;
}

/* The count over the span of the second half of the first n stamps, time
 * jumps (intervals over HX_SPAN_JUMP_S) left out: past a burst of stamps at
 * the start (a buffer of 400 flushed at power-on moved the whole span's
 * rate 6 %), and past an early dropout, but not past stamps in pairs, whose
 * every other interval is the sampling's (0.1 and 9.9 ms: 200 Hz, where
 * their median reads either). 0 without an interval. */
#define HX_SPAN_JUMP_S 0.2
static double span_rate_hz(const int64_t *t, size_t n)
{
    double sum = 0.0;
    size_t i, k = 0;
    for (i = n / 2u + 1u; i < n; i++) {
        const double d = 1e-9 * (double)(t[i] - t[i - 1u]);
        if (d > 0.0 && d <= HX_SPAN_JUMP_S) {
            sum += d;
            k++;
        }
    }
    return k > 0u && sum > 0.0 ? (double)k / sum : 0.0;
}

hx_reader_t *hx_reader_open(const char *path, hx_format_t fmt, double rate_hz, char *err, size_t err_size)
{
    hx_reader_t *r = open_raw(path, fmt, rate_hz, err, err_size);
    if (r == NULL) {
        return NULL;
    }
    if (r->meta.rate_hz <= 0.0 || (r->meta.format == HX_FMT_BIN && !r->meta.rate_nominal)) {
        /* time stamps without a nominal rate (text, or a .bin whose header
         * gives 0, "unknown", or a rate not flagged nominal: the writer's
         * estimate from the stamps, made again here so that what info
         * says of it is true of this file's stamps): estimate from the
         * stamps of the first samples
         * (a separate pass over the start, in the log's own format: a .bin
         * read as text here would give nothing) */
        char e2[64];
        hx_reader_t *p = open_raw(path, r->meta.format, rate_hz, e2, sizeof e2);
        if (p != NULL) {
            enum { N = 4096 };
            static int64_t ts[N];
            size_t n = 0;
            fnav_sample_t s;
            memset(&s, 0, sizeof s);
            while (n < N && (p->meta.format == HX_FMT_BIN ? next_bin(p, &s) : next_text(p, &s)) == FNAV_OK) {
                ts[n++] = s.t_ns;
            }
            {
                int coarse;
                const double est = hx_stamp_rate_hz(ts, n, &coarse);
                if (est > 0.0) {
                    r->meta.rate_hz = est;
                    r->meta.rate_nominal = 0;
                    r->meta.rate_coarse = coarse;
                }
                r->meta.rate_start_hz = start_rate_hz(ts, n);
                r->meta.rate_span_hz = span_rate_hz(ts, n);
            }
            hx_reader_close(p);
        }
    }
    return r;
}

/* 1 when path's last four bytes are the gzip trailer's ISIZE of a file
 * whose data, read whole, were size bytes (RFC 1952: the length mod 2^32,
 * little-endian): the last member then ends the file, as in every
 * single-member .gz, and gz_trailing_bytes need not inflate it all again
 * (it cost 0.1 s, a tenth of `info` on a 5 MB log of ADIS16405). 0
 * otherwise (several members, bytes after the data, a read error). */
static int gz_isize_ends(const char *path, unsigned long size)
{
    unsigned char t[4];
    FILE *f = fopen_input(path);
    int ok;
    if (f == NULL) {
        return 0;
    }
    ok = fseek(f, -4L, SEEK_END) == 0 && fread(t, 1, 4, f) == 4u &&
         ((unsigned long)t[0] | (unsigned long)t[1] << 8 | (unsigned long)t[2] << 16 | (unsigned long)t[3] << 24) ==
             (size & 0xffffffffUL);
    fclose(f);
    return ok;
}

/* The bytes after the last gzip member of path, as gunzip reads the file:
 * members one after another (concatenated .gz files are one valid .gz),
 * each inflated to its end; *zeros set when they are all zero bytes (a
 * block's padding). 0 when none, -1 when the file cannot be read again or
 * a member is damaged (the reader said so). zlib's gzread ignores such
 * bytes without a word; gunzip says "trailing garbage ignored". */
static long gz_trailing_bytes(const char *path, int *zeros)
{
    enum { IN_SIZE = 1 << 14, OUT_SIZE = 1 << 15 };
    unsigned char *const in = (unsigned char *)malloc(IN_SIZE + OUT_SIZE), *const out = in + IN_SIZE;
    FILE *f = in != NULL ? fopen_input(path) : NULL;
    z_stream zs;
    long member_end = 0, size, left = -1;
    if (f == NULL) {
        free(in);
        return -1;
    }
    memset(&zs, 0, sizeof zs);
    if (fseek(f, 0L, SEEK_END) != 0 || (size = ftell(f)) < 0 || inflateInit2(&zs, 15 + 16) != Z_OK) {
        fclose(f);
        free(in);
        return -1;
    }
    for (;;) {
        size_t n;
        int rc = Z_OK;
        if (fseek(f, member_end, SEEK_SET) != 0) {
            break;
        }
        n = fread(in, 1, 2, f);
        if (n == 0) {
            left = 0; /* the last member ends the file */
            break;
        }
        if (n < 2 || in[0] != 0x1f || in[1] != 0x8b) {
            /* no gzip member: the rest is junk (counted with its zero bytes) */
            long k, nonzero = (long)(n == 2 ? (in[0] != 0) + (in[1] != 0) : in[0] != 0);
            if (fseek(f, member_end + (long)n, SEEK_SET) == 0) {
                while ((n = fread(in, 1, IN_SIZE, f)) > 0) {
                    for (k = 0; k < (long)n; k++) {
                        nonzero += in[k] != 0;
                    }
                }
                left = size - member_end;
                *zeros = nonzero == 0;
            }
            break;
        }
        if (fseek(f, member_end, SEEK_SET) != 0 || inflateReset(&zs) != Z_OK) {
            break;
        }
        zs.avail_in = 0;
        while (rc == Z_OK) {
            if (zs.avail_in == 0) {
                zs.avail_in = (uInt)fread(in, 1, IN_SIZE, f);
                zs.next_in = in;
                if (zs.avail_in == 0) {
                    break; /* cut inside the member */
                }
            }
            zs.next_out = out;
            zs.avail_out = OUT_SIZE;
            rc = inflate(&zs, Z_NO_FLUSH);
        }
        if (rc != Z_STREAM_END) {
            break;
        }
        member_end += (long)zs.total_in;
    }
    inflateEnd(&zs);
    fclose(f);
    free(in);
    return left;
}

fnav_status_t hx_reader_next(hx_reader_t *r, fnav_sample_t *s)
{
    fnav_status_t st;
    if (r == NULL || s == NULL) {
        return FNAV_E_ARG;
    }
    if (r->finished) {
        return r->deferred != FNAV_OK ? r->deferred : FNAV_END;
    }
    memset(s, 0, sizeof *s);
    s->temp_c = (fnav_real_t)NAN;
    st = (r->meta.format == HX_FMT_BIN) ? next_bin(r, s) : next_text(r, s);
    if (st == FNAV_OK) {
        r->stats.records++;
        return FNAV_OK;
    }
    r->finished = 1;
    if (r->meta.format == HX_FMT_GX2 && r->gx2_bridged > 0) {
        /* also when the log stops at an error: the samples before it were
         * bridged all the same, so the note is given then too. A note, not a
         * warning: the logger restarts the timer about once a second and
         * the bridge is exact to a tick (docs/log-format.md, "GX2 time"), so
         * as a warning every GX2 log would warn of it */
        char count[32] = "once"; /* "restarted 1 time" read awkwardly; "2 times" on */
        if (r->gx2_bridged != 1) {
            snprintf(count, sizeof count, "%ld times", r->gx2_bridged);
        }
        add_note(r,
                 "%s: the sensor's timer restarted %s (normal for the 3DM-GX2, about once a second); each "
                 "restart bridged with the measured period (docs/log-format.md, GX2 time)",
                 r->path, count);
    }
    if (r->meta.format == HX_FMT_GX2 && r->gx2_nr_back > 0) {
        add_warn(r,
                 "%s:%ld: the packet number Nr does not advance at %ld packet%s (the first here), %s: rows out "
                 "of order, or the logger's count restarted; each read as one period on",
                 r->path, r->gx2_nr_back_line, r->gx2_nr_back, r->gx2_nr_back == 1 ? "" : "s",
                 r->gx2_nr_back == 1 ? "not a repeat of the packet before" : "none a repeat of the packet before");
    }
    if (r->meta.format == HX_FMT_MTMGR && r->mt.skipped > 0) {
        /* MT Manager writes NaN where a packet lacks a value (a packet the
         * radio lost, a quantity not yet available): such rows are left
         * out, so the stamps around them show a gap */
        add_warn(r, "%s:%ld: %ld row%s with NaN or an empty field in Acc_*, Gyr_* or the time or counter column (the "
                    "first here) skipped: a gap in the samples there",
                 r->path, r->mt.skipped_first, r->mt.skipped, r->mt.skipped == 1 ? "" : "s");
    }
    if (r->short_rows > 0 || r->long_rows > 0) {
        char w[HX_ERR_SIZE];
        if (r->short_rows > 0) {
            add_warn(r, "%s", hx_field_count_text(r->path, r->short_first, r->short_rows, 0, r->hdr_fields, 0, w,
                                                  sizeof w));
        }
        if (r->long_rows > 0) {
            add_warn(r, "%s", hx_field_count_text(r->path, r->long_first, r->long_rows, r->rows_checked,
                                                  r->hdr_fields, 1, w, sizeof w));
        }
    }
    if (st == FNAV_END && !gzdirect(r->gz) && gztell(r->gz) >= 0 &&
        !gz_isize_ends(r->path, (unsigned long)gztell(r->gz))) {
        /* bytes after the gzip data (a second member is read whole) */
        int zeros = 0;
        const long junk = gz_trailing_bytes(r->path, &zeros);
        if (junk > 0) {
            add_warn(r, "%s: %ld byte%s after the end of the gzip data %s no gzip member (%s): ignored, as gunzip "
                        "does; the samples are the gzip data's",
                     r->path, junk, junk == 1 ? "" : "s", junk == 1 ? "is" : "are",
                     zeros ? "zero bytes, padding" : "trailing junk");
        }
    }
    if (st == FNAV_END && r->stats.records == 0) {
        if (r->meta.format == HX_FMT_MTMGR && r->mt.skipped > 0) {
            set_err(r, "%s: no samples: each of the %ld rows has NaN or an empty field in Acc_*, Gyr_* or the time or "
                       "counter column", r->path, r->mt.skipped);
        } else {
            set_err(r, "%s: no samples", r->path);
        }
        st = FNAV_E_FORMAT;
    }
    r->deferred = st == FNAV_END ? FNAV_OK : st;
    return st;
}

const char *hx_reader_error(const hx_reader_t *r)
{
    return r->err;
}

const char *hx_reader_warnings(const hx_reader_t *r)
{
    return r->warn;
}

const char *hx_reader_take_warnings(hx_reader_t *r)
{
    const char *w = r->warn + r->warn_taken;
    r->warn_taken = strlen(r->warn);
    return *w == '\n' ? w + 1 : w;
}

const hx_meta_t *hx_reader_meta(const hx_reader_t *r)
{
    return &r->meta;
}

const hx_read_stats_t *hx_reader_stats(const hx_reader_t *r)
{
    return &r->stats;
}

double hx_reader_progress(const hx_reader_t *r)
{
    struct stat st;
    z_off_t off;
    if (r == NULL || r->gz == NULL || stat(r->path, &st) != 0 || st.st_size <= 0) {
        return -1.0;
    }
    off = gzoffset(r->gz); /* compressed bytes consumed (raw bytes for plain files) */
    if (off < 0) {
        return -1.0;
    }
    return (double)off >= (double)st.st_size ? 1.0 : (double)off / (double)st.st_size;
}

void hx_reader_close(hx_reader_t *r)
{
    if (r != NULL) {
        gzclose(r->gz);
        free(r);
    }
}

/* ------------------------------------------------------------ writer */

struct hx_writer {
    FILE *f;
    char path[512];
    hx_format_t fmt;
    int sync_each;
    int has_temp;
    uint32_t count;
    int64_t last_t_ns;
    int failed;
};

int hx_ends_in(const char *s, size_t end, const char *suffix)
{
    const size_t m = strlen(suffix);
    size_t i;
    if (end < m) {
        return 0;
    }
    for (i = 0; i < m; i++) {
        if (tolower((unsigned char)s[end - m + i]) != suffix[i]) {
            return 0;
        }
    }
    return 1;
}

/* 1 when s ends with suffix (lower case), in any case: OUT.BIN is a .bin,
 * not written as CSV */
static int ends_with(const char *s, const char *suffix)
{
    return hx_ends_in(s, strlen(s), suffix);
}

/* The .bin header's bytes for meta (NULL: none known). */
static void bin_header_of(const hx_meta_t *meta, unsigned char hb[HX_BIN_HEADER_SIZE])
{
    hx_bin_header_t h;
    memset(&h, 0, sizeof h);
    h.rate_hz = (meta != NULL) ? meta->rate_hz : 0.0;
    if (!(h.rate_hz >= 0.0 && h.rate_hz <= 1.0e6)) {
        /* a rate the reader refuses (stamps a thousand times too dense
         * imply MHz) is stored as 0, "not known": the samples carry
         * their own stamps, and the file stays readable (written as it
         * is, it would be refused by every command) */
        h.rate_hz = 0.0;
    }
    h.flags = 0;
    if (meta != NULL && h.rate_hz > 0.0) {
        h.flags |= meta->rate_nominal ? HX_BIN_FLAG_RATE_NOMINAL : 0u;
    }
    if (meta != NULL) {
        h.flags |= meta->has_temp ? HX_BIN_FLAG_TEMP : 0u;
        h.flags |= meta->has_seq ? HX_BIN_FLAG_SEQ : 0u;
        copy_str(h.sensor, sizeof h.sensor, meta->sensor);
        copy_str(h.source, sizeof h.source, meta->source);
        copy_str(h.axes, sizeof h.axes, meta->axes);
    }
    hx_bin_header_encode(&h, hb);
}

hx_writer_t *hx_writer_open(const char *path, hx_format_t fmt, const hx_meta_t *meta, int sync_each, char *err,
                            size_t err_size)
{
    hx_writer_t *w;
    if (fmt == HX_FMT_AUTO) {
        fmt = ends_with(path, ".bin") ? HX_FMT_BIN : HX_FMT_CSV;
    }
    if (fmt != HX_FMT_BIN && fmt != HX_FMT_CSV) {
        snprintf(err, err_size, "%s: can only write bin or csv, not %s", path, hx_format_name(fmt));
        return NULL;
    }
    w = (hx_writer_t *)calloc(1, sizeof *w);
    if (w == NULL) {
        snprintf(err, err_size, "%s: out of memory", path);
        return NULL;
    }
    w->f = (strcmp(path, "-") == 0) ? stdout : fopen(path, "wb");
    if (w->f == NULL) {
        snprintf(err, err_size, "%s: cannot create (%s)", path, strerror(errno));
        free(w);
        return NULL;
    }
    copy_str(w->path, sizeof w->path, path);
    w->fmt = fmt;
    w->sync_each = sync_each;
    w->has_temp = meta != NULL && meta->has_temp;
    if (fmt == HX_FMT_BIN) {
        unsigned char hb[HX_BIN_HEADER_SIZE];
        bin_header_of(meta, hb);
        if (fwrite(hb, 1, sizeof hb, w->f) != sizeof hb) {
            snprintf(err, err_size, "%s: write failed (%s)", path, strerror(errno));
            if (w->f != stdout) {
                fclose(w->f);
            }
            free(w);
            return NULL;
        }
    } else {
        fprintf(w->f, "t,ax,ay,az,gx,gy,gz%s\n", w->has_temp ? ",temp" : "");
    }
    if (sync_each) {
        fflush(w->f);
    }
    return w;
}

/* float32 printed with 9 significant digits reads back bit-exactly. */
static void put_f32(FILE *f, float v)
{
    fprintf(f, ",%.9g", (double)v);
}

fnav_status_t hx_writer_write(hx_writer_t *w, const fnav_sample_t *s)
{
    if (w == NULL || s == NULL) {
        return FNAV_E_ARG;
    }
    if (w->fmt == HX_FMT_BIN) {
        unsigned char rb[HX_BIN_RECORD_SIZE];
        hx_bin_record_t rec;
        int i;
        rec.type = HX_BIN_REC_SAMPLE;
        rec.flags = (s->flags & FNAV_SAMPLE_HAS_TEMP) ? HX_BIN_REC_TEMP : 0u;
        rec.seq = s->seq;
        rec.t_ns = s->t_ns;
        for (i = 0; i < 3; i++) {
            rec.acc[i] = (float)s->accel_mps2[i];
            rec.gyr[i] = (float)s->gyro_rps[i];
        }
        rec.temp = (s->flags & FNAV_SAMPLE_HAS_TEMP) ? (float)s->temp_c : 0.0f;
        hx_bin_record_encode(&rec, rb);
        if (fwrite(rb, 1, sizeof rb, w->f) != sizeof rb) {
            w->failed = 1;
            return FNAV_E_IO;
        }
    } else {
        char tb[32];
        fputs(ns_text(s->t_ns, tb, sizeof tb), w->f);
        put_f32(w->f, (float)s->accel_mps2[0]);
        put_f32(w->f, (float)s->accel_mps2[1]);
        put_f32(w->f, (float)s->accel_mps2[2]);
        put_f32(w->f, (float)s->gyro_rps[0]);
        put_f32(w->f, (float)s->gyro_rps[1]);
        put_f32(w->f, (float)s->gyro_rps[2]);
        if (w->has_temp) {
            if (s->flags & FNAV_SAMPLE_HAS_TEMP) {
                put_f32(w->f, (float)s->temp_c);
            } else {
                fputc(',', w->f); /* no temperature: an empty field, not 0 degC */
            }
        }
        if (fputc('\n', w->f) == EOF) {
            w->failed = 1;
            return FNAV_E_IO;
        }
    }
    w->count++;
    w->last_t_ns = s->t_ns;
    if (w->sync_each && fflush(w->f) != 0) {
        w->failed = 1;
        return FNAV_E_IO;
    }
    return FNAV_OK;
}

fnav_status_t hx_writer_rewrite_header(hx_writer_t *w, const hx_meta_t *meta)
{
    unsigned char hb[HX_BIN_HEADER_SIZE];
    long at;
    if (w == NULL || w->fmt != HX_FMT_BIN || w->failed) {
        return FNAV_E_ARG;
    }
    bin_header_of(meta, hb);
    if (fflush(w->f) != 0 || (at = ftell(w->f)) < 0 || fseek(w->f, 0L, SEEK_SET) != 0) {
        return FNAV_E_IO; /* a pipe: the header stays */
    }
    if (fwrite(hb, 1, sizeof hb, w->f) != sizeof hb || fseek(w->f, at, SEEK_SET) != 0) {
        w->failed = 1;
        return FNAV_E_IO;
    }
    if (w->sync_each && fflush(w->f) != 0) {
        w->failed = 1;
        return FNAV_E_IO;
    }
    return FNAV_OK;
}

/* end_record 0: a .bin is left without its END record, as a killed
 * writer leaves it, so that every later reader says it is incomplete */
static fnav_status_t writer_finish(hx_writer_t *w, int end_record, char *err, size_t err_size)
{
    fnav_status_t st = FNAV_OK;
    if (w == NULL) {
        return FNAV_E_ARG;
    }
    if (w->fmt == HX_FMT_BIN && end_record) {
        unsigned char rb[HX_BIN_RECORD_SIZE];
        hx_bin_record_t rec;
        memset(&rec, 0, sizeof rec);
        rec.type = HX_BIN_REC_END;
        rec.seq = w->count;
        rec.t_ns = w->last_t_ns;
        hx_bin_record_encode(&rec, rb);
        if (fwrite(rb, 1, sizeof rb, w->f) != sizeof rb) {
            w->failed = 1;
        }
    }
    if (fflush(w->f) != 0) {
        w->failed = 1;
    }
    if (w->f != stdout && fclose(w->f) != 0) {
        w->failed = 1;
    }
    if (w->failed) {
        snprintf(err, err_size, "%s: write failed (%s)", w->path, strerror(errno));
        st = FNAV_E_IO;
    }
    free(w);
    return st;
}

fnav_status_t hx_writer_close(hx_writer_t *w, char *err, size_t err_size)
{
    return writer_finish(w, 1, err, err_size);
}

fnav_status_t hx_writer_close_cut(hx_writer_t *w, char *err, size_t err_size)
{
    return writer_finish(w, 0, err, err_size);
}

/* ------------------------------------------------------------ whole log */

int hx_log_load(hx_log_t *log, const char *path, hx_format_t fmt, double rate_hz, char *err, size_t err_size)
{
    return hx_log_load_progress(log, path, fmt, rate_hz, NULL, NULL, err, err_size);
}

int hx_log_load_progress(hx_log_t *log, const char *path, hx_format_t fmt, double rate_hz,
                         void (*progress)(void *ctx, double frac), void *ctx, char *err, size_t err_size)
{
    hx_reader_t *r;
    size_t cap = 0;
    fnav_sample_t s;
    fnav_status_t st;
    memset(log, 0, sizeof *log);
    r = hx_reader_open(path, fmt, rate_hz, err, err_size);
    if (r == NULL) {
        return -1;
    }
    log->meta = *hx_reader_meta(r);
    while ((st = hx_reader_next(r, &s)) == FNAV_OK) {
        if (log->n == cap) {
            size_t nc = cap ? 2 * cap : 65536;
            int64_t *t = (int64_t *)realloc(log->t_ns, nc * sizeof *t);
            uint32_t *q = (uint32_t *)realloc(log->seq, nc * sizeof *q);
            double(*a)[3] = (double(*)[3])realloc(log->acc, nc * sizeof *a);
            double(*g)[3] = (double(*)[3])realloc(log->gyr, nc * sizeof *g);
            double *tc = (double *)realloc(log->temp, nc * sizeof *tc);
            if (t) log->t_ns = t;
            if (q) log->seq = q;
            if (a) log->acc = a;
            if (g) log->gyr = g;
            if (tc) log->temp = tc;
            if (!t || !q || !a || !g || !tc) {
                snprintf(log->error, sizeof log->error, "%s: out of memory after %zu samples", path, log->n);
                st = FNAV_E_SIZE;
                break;
            }
            cap = nc;
        }
        log->t_ns[log->n] = s.t_ns;
        log->seq[log->n] = s.seq;
        log->acc[log->n][0] = (double)s.accel_mps2[0];
        log->acc[log->n][1] = (double)s.accel_mps2[1];
        log->acc[log->n][2] = (double)s.accel_mps2[2];
        log->gyr[log->n][0] = (double)s.gyro_rps[0];
        log->gyr[log->n][1] = (double)s.gyro_rps[1];
        log->gyr[log->n][2] = (double)s.gyro_rps[2];
        log->temp[log->n] = (s.flags & FNAV_SAMPLE_HAS_TEMP) ? (double)s.temp_c : (double)NAN;
        log->n++;
        if (progress != NULL && (log->n & 65535u) == 0u) {
            const double f = hx_reader_progress(r);
            if (f >= 0.0) {
                progress(ctx, f);
            }
        }
    }
    if (progress != NULL && st == FNAV_END) {
        progress(ctx, 1.0); /* a log that stops at an error ends where it stopped */
    }
    log->status = st;
    log->stats = *hx_reader_stats(r);
    if (st != FNAV_END && log->error[0] == '\0') {
        copy_str(log->error, sizeof log->error, hx_reader_error(r));
    }
    snprintf(log->warnings, sizeof log->warnings, "%s", hx_reader_warnings(r));
    hx_reader_close(r);
    if (st != FNAV_END && log->n == 0) {
        snprintf(err, err_size, "%s", log->error);
        hx_log_free(log);
        return -1;
    }
    return st == FNAV_END ? 0 : 1;
}

void hx_log_sample(const hx_log_t *log, size_t i, fnav_sample_t *s)
{
    int c;
    memset(s, 0, sizeof *s);
    s->t_ns = log->t_ns[i];
    s->seq = log->seq[i];
    for (c = 0; c < 3; c++) {
        s->accel_mps2[c] = (fnav_real_t)log->acc[i][c];
        s->gyro_rps[c] = (fnav_real_t)log->gyr[i][c];
    }
}

void hx_log_free(hx_log_t *log)
{
    free(log->t_ns);
    free(log->seq);
    free(log->acc);
    free(log->gyr);
    free(log->temp);
    log->t_ns = NULL;
    log->seq = NULL;
    log->acc = NULL;
    log->gyr = NULL;
    log->temp = NULL;
    log->n = 0;
}

/* ------------------------------------------------------------ layout */


void hx_csv_layout_default(hx_csv_layout_t *l)
{
    memset(l, 0, sizeof *l);
    l->time_digits = 9;
    l->acc_scale = 1.0;
    l->gyr_scale = 1.0;
}

void hx_reader_set_layout(const hx_csv_layout_t *l)
{
    if (l == NULL) {
        hx_csv_layout_default(&g_layout);
    } else {
        g_layout = *l;
    }
}

void hx_reader_layout(hx_csv_layout_t *l)
{
    if (g_layout.option == NULL) {
        hx_csv_layout_default(l);
    } else {
        *l = g_layout;
    }
}

const hx_csv_layout_t *hx_units_layout(hx_format_t fmt, hx_csv_layout_t *buf)
{
    if (fmt != HX_FMT_CSV) {
        return NULL;
    }
    hx_reader_layout(buf);
    if (g_read_matched) {
        g_read_layout.option = buf->option;
        *buf = g_read_layout;
    }
    return buf;
}

void hx_layout_refusal(char *msg, size_t msg_size, const char *path, const char *opt, hx_format_t fmt,
                       int detected)
{
    /* the names and units are the interchange CSV's: an importer has its own */
    snprintf(msg, msg_size, "%s%s%s appl%s to the interchange CSV (format csv), not to the %s format%s",
             path != NULL ? path : "", path != NULL ? ": " : "", opt, strchr(opt, ' ') != NULL ? "y" : "ies",
             hx_format_name(fmt),
             !detected              ? ""
             : fmt == HX_FMT_BIN ? " (detected from the content)" /* no text: --from csv reads a NUL byte */
                                 : " (detected from the content; give --from csv to read the file as CSV)");
}

/* One "key=value" item of a comma-separated list, blanks around each part
 * dropped: 1 an item, 0 the end, -1 no '=' (err filled). */
static int next_item(const char **p, const char *opt, char *key, size_t ksize, char *val, size_t vsize, char *err,
                     size_t err_size)
{
    const char *s = *p, *e, *eq;
    size_t n;
    while (*s == ' ' || *s == '\t') {
        s++;
    }
    if (*s == '\0') {
        return 0;
    }
    e = strchr(s, ',');
    if (e == NULL) {
        e = s + strlen(s);
    }
    eq = memchr(s, '=', (size_t)(e - s));
    if (eq == NULL) {
        snprintf(err, err_size, "%s: '%.*s' has no '=' (KEY=VALUE, items separated by commas)", opt, (int)(e - s), s);
        return -1;
    }
    n = (size_t)(eq - s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) {
        n--;
    }
    snprintf(key, ksize, "%.*s", (int)n, s);
    s = eq + 1;
    while (s < e && (*s == ' ' || *s == '\t')) {
        s++;
    }
    n = (size_t)(e - s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) {
        n--;
    }
    snprintf(val, vsize, "%.*s", (int)n, s);
    *p = *e == ',' ? e + 1 : e;
    return 1;
}

static void layout_given(hx_csv_layout_t *l, const char *opt)
{
    if (l->option == NULL || strcmp(l->option, opt) == 0) {
        l->option = opt;
    } else {
        l->option = "--columns and --units";
    }
}

const char *hx_columns_give(const hx_csv_layout_t *l, const int src[3], const int neg[3], char *buf, size_t size)
{
    char map[8 * 72 + 72], word[8 * 72 + 80], units[96];
    size_t len = 0;
    int k, given;
    map[0] = '\0';
    buf[0] = '\0';
    for (k = 0; k < 8; k++) {
        /* the key's column as l reads it: the gyro's from key src[] */
        const int from = (k >= 4 && k <= 6) ? 4 + src[k - 4] : k;
        const int minus = ((l->negate >> from) & 1) ^ ((k >= 4 && k <= 6) ? (neg[k - 4] != 0) : 0);
        const char *name = l->names[from][0] != '\0' ? l->names[from] : k_csv_names[from];
        if (strchr(name, ',') != NULL || (k == 0 && strchr(l->tns, ',') != NULL)) {
            return NULL;
        }
        /* a default name read as it is needs no word, but the gyro's are
         * always given; tns, after t, whatever t's name */
        if (l->names[from][0] != '\0' || (k >= 4 && k <= 6) || minus) {
            len += (size_t)snprintf(map + len, sizeof map - len, "%s%s=%s%s", len > 0u ? "," : "", k_csv_names[k],
                                    minus ? "-" : "", name);
        }
        if (k == 0 && l->tns[0] != '\0' && len < sizeof map) {
            len += (size_t)snprintf(map + len, sizeof map - len, "%stns=%s", len > 0u ? "," : "", l->tns);
        }
        if (len >= sizeof map) {
            return NULL;
        }
    }
    given = strncmp(hx_units_give(l, units, sizeof units), "give ", 5) == 0;
    if (hx_shell_word(map, 1, word, sizeof word)[0] == '\0' ||
        (size_t)snprintf(buf, size, "--columns %s%s%s", word, given ? " " : "", given ? units + 5 : "") >= size) {
        buf[0] = '\0';
        return NULL;
    }
    return buf;
}

int hx_csv_columns_parse(hx_csv_layout_t *l, const char *map, char *err, size_t err_size)
{
    const char *p = map;
    char key[16], val[256];
    int seen = 0, i, j, rc;
    while ((rc = next_item(&p, "--columns", key, sizeof key, val, sizeof val, err, err_size)) > 0) {
        for (i = 0; i < 8 && strcmp(key, k_csv_names[i]) != 0; i++) {
        }
        if (i == 8 && strcmp(key, "tns") == 0) {
            /* the nanoseconds of a stamp split in two columns */
            if (val[0] == '-') {
                snprintf(err, err_size, "--columns: tns=%s: a '-' before a name reads the column with the other "
                                        "sign, which only ax..gz take", val);
                return -1;
            }
            if (l->tns[0] != '\0' || val[0] == '\0' || strspn(val, " \t\"'") == strlen(val) ||
                strlen(val) >= sizeof l->tns) {
                snprintf(err, err_size, "--columns: tns=%s", l->tns[0] != '\0' ? " given twice"
                                                              : val[0] == '\0' ? " has an empty name"
                                                                               : ": a name too long");
                return -1;
            }
            memcpy(l->tns, val, strlen(val) + 1);
            continue;
        }
        if (i == 8) {
            snprintf(err, err_size, "--columns: unknown column '%s' (the interchange names: t, ax, ay, az, gx, gy, "
                                    "gz, temp; and tns, nanoseconds added to t)", key);
            return -1;
        }
        if (seen & (1 << i)) {
            snprintf(err, err_size, "--columns: '%s' given twice", key);
            return -1;
        }
        if (val[0] == '-') {
            /* "ax=-acc_x": the column read with the other sign (iOS's
             * accelerations, an axis the axes check finds flipped) */
            if (i == 0 || i == 7) {
                snprintf(err, err_size, "--columns: %s=%s: a '-' before a name reads the column with the other "
                                        "sign, which only ax..gz take", key, val);
                return -1;
            }
            memmove(val, val + 1, strlen(val));
            l->negate |= 1 << i;
        }
        if (val[0] == '\0' || strspn(val, " \t\"'") == strlen(val)) {
            snprintf(err, err_size, "--columns: %s= has an empty name (the file's name of the column)", key);
            return -1;
        }
        if (strlen(val) >= sizeof l->names[i]) {
            snprintf(err, err_size, "--columns: %s=: a name of more than %d characters", key,
                     (int)sizeof l->names[i] - 1);
            return -1;
        }
        seen |= 1 << i;
        memcpy(l->names[i], val, strlen(val) + 1);
    }
    if (rc < 0) {
        return -1;
    }
    if (seen == 0 && l->tns[0] == '\0') {
        snprintf(err, err_size, "--columns: no KEY=NAME given (e.g. t=timestamp_ns,ax=acc_x)");
        return -1;
    }
    for (i = 0; i < 8 && l->tns[0] != '\0'; i++) {
        const char *a = l->names[i][0] != '\0' ? l->names[i] : k_csv_names[i];
        if (hx_name_eq(a, l->tns)) {
            snprintf(err, err_size, "--columns: column '%s' is named for both %s and tns", a, k_csv_names[i]);
            return -1;
        }
    }
    /* one column of the file for two quantities (named twice, or named
     * for one key while another keeps it as its default) */
    for (i = 0; i < 8; i++) {
        for (j = i + 1; j < 8; j++) {
            const char *a = l->names[i][0] != '\0' ? l->names[i] : k_csv_names[i];
            const char *b = l->names[j][0] != '\0' ? l->names[j] : k_csv_names[j];
            if (hx_name_eq(a, b)) {
                snprintf(err, err_size, "--columns: column '%s' is named for both %s and %s%s", a, k_csv_names[i],
                         k_csv_names[j],
                         l->names[i][0] == '\0' || l->names[j][0] == '\0' ? " (a key not given keeps its own name)"
                                                                           : "");
                return -1;
            }
        }
    }
    layout_given(l, "--columns");
    return 0;
}

int hx_csv_units_parse(hx_csv_layout_t *l, const char *spec, char *err, size_t err_size)
{
    const char *p = spec;
    char key[16], given[32], val[64];
    int seen = 0, rc;
    while ((rc = next_item(&p, "--units", key, sizeof key, given, sizeof given, err, err_size)) > 0) {
        int k = strcmp(key, "time") == 0 ? 0 : strcmp(key, "accel") == 0 ? 1 : strcmp(key, "gyro") == 0 ? 2 : -1;
        double count = 1.0; /* a count's size: accel=0.061mg, gyro=8.75mdps (raw integer counts) */
        /* the units' signs as the names read them: time=µs, accel=m/s²,
         * gyro=°/s are known units, not unknown ones; the errors quote
         * the value as given */
        if (hx_name_fold_units(given, val, sizeof val) != 0) {
            snprintf(val, sizeof val, "?");
        }
        if (k > 0 && ((val[0] >= '0' && val[0] <= '9') || val[0] == '.')) {
            /* raw counts, scaled by the datasheet's sensitivity: the
             * number, then the unit it is in */
            char *end;
            errno = 0;
            count = strtod(val, &end);
            if (end == val || errno != 0 || !(count > 0.0) || !(count < 1e6) || *end == '\0') {
                snprintf(err, err_size,
                         "--units: %s=%s: a count's size is a positive number then its unit (accel=0.061mg, "
                         "gyro=8.75mdps: the datasheet's sensitivity, per LSB)",
                         key, given);
                return -1;
            }
            memmove(val, end, strlen(end) + 1);
        }
        if (k < 0) {
            snprintf(err, err_size, "--units: unknown quantity '%s' (time, accel or gyro)", key);
            return -1;
        }
        if (seen & (1 << k)) {
            snprintf(err, err_size, "--units: '%s' given twice", key);
            return -1;
        }
        seen |= 1 << k;
        l->units_given |= 1 << k;
        if (k == 0) {
            static const char *const tu[4] = { "s", "ms", "us", "ns" };
            int i;
            for (i = 0; i < 4 && strcmp(val, tu[i]) != 0; i++) {
            }
            if (i == 4) {
                snprintf(err, err_size, "--units: time=%s: the time unit is s, ms, us or ns (\xc2\xb5s: us)", given);
                return -1;
            }
            l->time_digits = 9 - 3 * i;
        } else if (k == 1) {
            if (strcmp(val, "m/s2") == 0 || strcmp(val, "m/s^2") == 0 || strcmp(val, "mps2") == 0) {
                l->acc_scale = 1.0;
            } else if (strcmp(val, "g") == 0) {
                l->acc_scale = HX_G_MPS2;
            } else if (strcmp(val, "mg") == 0) {
                l->acc_scale = HX_MG_MPS2; /* ST's SensorTile data log, AccX [mg] */
            } else if (strcmp(val, "ug") == 0) {
                l->acc_scale = HX_UG_MPS2; /* micro-g, \xc2\xb5g and \xce\xbcg folded to ug */
            } else {
                snprintf(err, err_size,
                         "--units: accel=%s: the acceleration unit is m/s2 (m/s^2, m/s\xc2\xb2, mps2), g, mg or ug "
                         "(\xc2\xb5g), after a count's size for raw counts (0.061mg)",
                         given);
                return -1;
            }
            l->acc_scale *= count;
        } else {
            if (strcmp(val, "rad/s") == 0) {
                l->gyr_scale = 1.0;
            } else if (strcmp(val, "deg/s") == 0 || strcmp(val, "dps") == 0) {
                l->gyr_scale = HX_DPS_RPS;
            } else if (strcmp(val, "mdps") == 0 || strcmp(val, "mdeg/s") == 0) {
                l->gyr_scale = HX_MDPS_RPS; /* ST's SensorTile data log, GyroX [mdps] */
            } else {
                snprintf(err, err_size,
                         "--units: gyro=%s: the rate unit is rad/s, deg/s (dps, \xc2\xb0/s) or mdps (mdeg/s), after a "
                         "count's size for raw counts (8.75mdps)",
                         given);
                return -1;
            }
            l->gyr_scale *= count;
        }
    }
    if (rc < 0) {
        return -1;
    }
    if (seen == 0) {
        snprintf(err, err_size, "--units: no KEY=UNIT given (e.g. time=ns,accel=g,gyro=deg/s)");
        return -1;
    }
    layout_given(l, "--units");
    return 0;
}

hx_format_t hx_detect_file(const char *path)
{
    unsigned char head[600];
    int got;
    char err[HX_ERR_SIZE];
    gzFile gz = hx_gzopen_input(path, err, sizeof err);
    if (gz == NULL) {
        return HX_FMT_AUTO;
    }
    got = gzread(gz, head, sizeof head);
    gzclose(gz);
    return got > 0 ? detect(head, (size_t)got) : HX_FMT_AUTO;
}

void hx_irregular_text(char *buf, size_t size, long irregular, size_t total, double rate_hz, long repeats, long gaps,
                       double longest_gap_s, double missing, double n)
{
    char head[96], rep[96] = "", gap[192] = "";
    const double pct = 100.0 * missing / (n + missing > 0.0 ? n + missing : 1.0);
    const char *ms = missing == 1.0 ? "" : "s";
    snprintf(head, sizeof head, "%ld of %zu intervals %s from 1/%.4g s by more than 10 %%", irregular, total,
             irregular == 1 ? "differs" : "differ", rate_hz);
    if (irregular == 1 && repeats + gaps <= 1) {
        /* one interval: what it is, in brackets ("1 interval differs ...,
         * 1 of them a gap (longest ...)" read awkwardly) */
        if (gaps == 1) {
            snprintf(buf, size, "%s (a gap of %.3g s; about %.0f sample%s missing, %.2g %% of the log)", head,
                     longest_gap_s, missing, ms, pct);
        } else {
            snprintf(buf, size, "%s%s", head, repeats == 1 ? " (a time stamp repeated)" : "");
        }
        return;
    }
    if (repeats > 0) {
        snprintf(rep, sizeof rep, ", %ld of them %s", repeats,
                 repeats == 1 ? "a time stamp repeated" : "time stamps repeated");
    }
    if (gaps > 1) {
        snprintf(gap, sizeof gap, ", %ld of them gaps (longest %.3g s; about %.0f sample%s missing in all, %.2g %% "
                                  "of the log)",
                 gaps, longest_gap_s, missing, ms, pct);
    } else if (gaps == 1) {
        /* one gap has no "longest" and no "in all" */
        snprintf(gap, sizeof gap, ", 1 of them a gap of %.3g s (about %.0f sample%s missing, %.2g %% of the log)",
                 longest_gap_s, missing, ms, pct);
    }
    snprintf(buf, size, "%s%s%s", head, rep, gap);
}

const char *hx_gaps_joined(long gaps)
{
    return gaps > 1 ? ", and the samples are joined across the gaps as if consecutive"
           : gaps == 1 ? ", and the samples are joined across the gap as if consecutive" : "";
}
