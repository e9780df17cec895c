/* One sensor's file of a logger that writes accelerometer and gyroscope
 * apart, and the value of one at the other's stamps (hx_merge.h). */
#include "hx_merge.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zlib.h>

#include "hx_cli.h"
#include "hx_names.h"

#define TRI_MAX_COLS 64

static const char *const k_sensor[2] = { "accelerometer", "gyroscope" };

static void say(char *buf, size_t size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* a message, one line of printable text: it quotes the file's own text
 * (a field, a header name), whose control characters are read as '?' as
 * the single-file reader's (a field '0<ESC>]0;...<BEL>' sent an escape
 * sequence to the terminal: tests/cli/test_merge.sh) */
static void say(char *buf, size_t size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    (void)hx_printable(buf);
}

/* The axis of a bare axis name ("x", "X", "x-axis (g)", "x_axis [deg/s]",
 * "axis x"): 0..2, -1 when the name is no bare axis. *unit: the unit in
 * brackets or parentheses after it; *unread: brackets whose unit is not
 * read. */
static int bare_axis(const char *name, hx_name_unit_t *unit, int *unread)
{
    char word[32], inner[48];
    size_t w = 0;
    const char *p = name, *open = strpbrk(name, "([");
    *unit = HX_UNIT_NONE;
    *unread = 0;
    for (; *p != '\0' && p != open; p++) {
        const char c = (char)tolower((unsigned char)*p);
        if (c == ' ' || c == '-' || c == '_' || c == '"' || c == '\t') {
            continue;
        }
        if (w + 1 >= sizeof word) {
            return -1;
        }
        word[w++] = c;
    }
    word[w] = '\0';
    if (open != NULL) {
        const char close = *open == '(' ? ')' : ']';
        const char *e = strrchr(open, close);
        size_t len;
        if (e == NULL || e[1] != '\0') {
            return -1; /* words after the unit: not a bare axis */
        }
        len = (size_t)(e - open - 1);
        if (len >= sizeof inner) {
            return -1;
        }
        memcpy(inner, open + 1, len);
        inner[len] = '\0';
        *unit = hx_name_unit_of_text(inner);
        *unread = *unit == HX_UNIT_NONE && inner[strspn(inner, " \t")] != '\0';
    }
    if (strlen(word) == 1 && word[0] >= 'x' && word[0] <= 'z') {
        return word[0] - 'x';
    }
    if (strlen(word) == 5 && (strncmp(word, "axis", 4) == 0 || strcmp(word + 1, "axis") == 0)) {
        const char c = strncmp(word, "axis", 4) == 0 ? word[4] : word[0];
        return c >= 'x' && c <= 'z' ? c - 'x' : -1;
    }
    return -1;
}

int hx_tri_header_kind(char *const *f, int n)
{
    int i, key[7] = { 0, 0, 0, 0, 0, 0, 0 }, axis[3] = { 0, 0, 0 }, acc, gyr;
    for (i = 0; i < n; i++) {
        hx_name_class_t cl;
        hx_name_unit_t u;
        int unread, a;
        if (hx_name_classify(f[i], &cl) == HX_NAME_MATCH && cl.key >= 0 && cl.key < 7) {
            key[cl.key]++;
        } else if ((a = bare_axis(f[i], &u, &unread)) >= 0) {
            axis[a]++;
        }
    }
    acc = key[1] > 0 && key[2] > 0 && key[3] > 0;
    gyr = key[4] > 0 && key[5] > 0 && key[6] > 0;
    if (key[0] == 0) {
        return -1;
    }
    if (acc && key[4] + key[5] + key[6] == 0) {
        return HX_TRI_ACC;
    }
    if (gyr && key[1] + key[2] + key[3] == 0) {
        return HX_TRI_GYR;
    }
    if (key[1] + key[2] + key[3] + key[4] + key[5] + key[6] == 0 && axis[0] > 0 && axis[1] > 0 && axis[2] > 0) {
        return HX_TRI_BARE;
    }
    return -1;
}

/* 1 for a unit of the sensor's quantity, 0 for another's. */
static int unit_is(hx_tri_kind_t kind, hx_name_unit_t u)
{
    return kind == HX_TRI_ACC ? (u >= HX_UNIT_MPS2 && u <= HX_UNIT_UG) : (u >= HX_UNIT_RPS && u <= HX_UNIT_MDPS);
}

/* A unit as its --units value spells it ("g", "deg/s", "ms"). */
static const char *unit_text(hx_name_unit_t u)
{
    const char *item = hx_name_unit_item(u);
    return item != NULL ? strchr(item, '=') + 1 : "";
}

/* A field into buf with a decimal comma read as a point when the fields
 * are not comma-separated ("0,25" in a phyphox export with semicolons or
 * tabs). 0, -1 empty or too long. */
static int field_text(const char *s, char delim, char *buf, size_t size)
{
    size_t i, len = strlen(s);
    if (len == 0 || len >= size) {
        return -1;
    }
    for (i = 0; i <= len; i++) {
        buf[i] = (delim != ',' && s[i] == ',') ? '.' : s[i];
    }
    return 0;
}

/* A value field as a finite number: 0, -1 none. */
static int field_value(const char *s, char delim, double *v)
{
    char buf[64];
    return field_text(s, delim, buf, sizeof buf) == 0 && hx_parse_number(buf, v) == 0 && isfinite(*v) ? 0 : -1;
}

/* Whether a time field is a date and time, or a clock time alone. */
static int field_dated(const char *s, char delim)
{
    char buf[64];
    return field_text(s, delim, buf, sizeof buf) == 0 && hx_is_datetime(buf);
}

/* A time field as ns in the unit of 10^digits ns (hx_parse_time_ns: exact
 * for plain decimals, dates and times read as such); its return. */
static int field_time(const char *s, char delim, int digits, int64_t *ns)
{
    char buf[64];
    return field_text(s, delim, buf, sizeof buf) == 0 ? hx_parse_time_ns(buf, digits, ns) : -1;
}

typedef struct {
    gzFile gz;
    char line[HX_LINE_MAX];
    long lineno;
    int open; /* the line has no newline: the file's last, perhaps cut off mid-write */
} text_t;

/* The next line: 1, 0 at the end, -1 a line too long or cut by a NUL
 * byte (msg), as the log reader says them (hx_log.c read_line). */
static int next_line(text_t *t, const char *path, char *msg, size_t size)
{
    size_t len;
    int nul;
    if (hx_gzgets(t->gz, t->line, (int)sizeof t->line, &len, &nul) == NULL) {
        return 0;
    }
    t->lineno++;
    if (nul) {
        say(msg, size, "%s:%ld: " HX_NUL_TEXT, path,
            t->lineno);
        return -1;
    }
    if (len == sizeof t->line - 1 && t->line[len - 1] != '\n' && !gzeof(t->gz)) {
        say(msg, size, "%s:%ld: line longer than %d bytes with its line end%s", path, t->lineno, HX_LINE_MAX - 1,
            hx_cr_alone(t->line) ? HX_CR_ALONE_HINT : "");
        return -1;
    }
    if (t->lineno == 1 && hx_cr_alone(t->line)) {
        say(msg, size, "%s:1: a carriage return inside the line%s", path, HX_CR_ALONE_HINT);
        return -1;
    }
    t->open = t->line[len - 1] != '\n';
    return 1;
}

static int blank_line(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') {
        s++;
    }
    return *s == '\0';
}

/* What the header gives: the columns of time and of x, y, z. */
typedef struct {
    int t, ax[3];
    int t_elapsed; /* the time column's name is one from a start (elapsed) */
    int t_dated;   /* the time column's first value is a date and time, or a clock time (hx_is_datetime) */
    hx_name_unit_t t_unit, unit;
} cols_t;

/* The columns of a kind's file from its header fields f[0..n) (on line
 * line) and the first data row d[0..nd) (on row_line). 0, or -1 with msg. */
static int find_cols(char **f, int n, char **d, int nd, char delim, hx_tri_kind_t kind, const char *path,
                     long line, long row_line, cols_t *c, char *msg, size_t size)
{
    int i, k, own[3][3], nown[3] = { 0, 0, 0 }, other = -1, nother = 0, times[8], ntimes = 0, bare_used = 0, best;
    const int k0 = kind == HX_TRI_ACC ? 1 : 4, ko = kind == HX_TRI_ACC ? 4 : 1;
    hx_name_unit_t au[3] = { HX_UNIT_NONE, HX_UNIT_NONE, HX_UNIT_NONE };
    int gforce = 0;
    for (i = 0; i < n && kind == HX_TRI_ACC; i++) {
        hx_name_class_t cl;
        gforce |= hx_name_classify(f[i], &cl) == HX_NAME_MATCH && cl.gforce;
    }
    for (i = 0; i < n; i++) {
        hx_name_class_t cl;
        if (hx_name_classify(f[i], &cl) != HX_NAME_MATCH) {
            continue;
        }
        if (cl.key == 0 && ntimes < 8) {
            times[ntimes++] = i;
        } else if (cl.key >= k0 && cl.key < k0 + 3 && gforce && !cl.gforce) {
            continue; /* Physics Toolbox's ax beside its g-force gFx: the linear acceleration (hx_names_match) */
        } else if (cl.key >= k0 && cl.key < k0 + 3) {
            if (nown[cl.key - k0] < 3) {
                own[cl.key - k0][nown[cl.key - k0]] = i;
            }
            nown[cl.key - k0]++;
        } else if (cl.key >= ko && cl.key < ko + 3) {
            other = other < 0 ? i : other;
            nother++;
        }
    }
    if (nown[0] == 0 && nown[1] == 0 && nown[2] == 0) {
        /* no sensor's name: bare axes, "x", "x-axis (g)" */
        for (i = 0; i < n; i++) {
            hx_name_unit_t u;
            int unread, a = bare_axis(f[i], &u, &unread);
            if (a < 0) {
                continue;
            }
            if (unread) {
                say(msg, size, "%s:%ld: column %d ('%s') names a unit not read (the %s's: %s)", path, line, i + 1,
                    f[i], k_sensor[kind],
                    kind == HX_TRI_ACC ? "m/s^2, g, mg, ug" : "rad/s, deg/s, mdps");
                return -1;
            }
            if (nown[a] < 3) {
                own[a][nown[a]] = i;
            }
            nown[a]++;
            bare_used = 1;
        }
    }
    if (nother >= 3 && (nown[0] > 0 || nown[1] > 0 || nown[2] > 0) && !bare_used) {
        say(msg, size, "%s:%ld: the header names the accelerometer and the gyroscope: a log with both is read "
                       "as it is (bin/harness info %s), not merged", path, line, path);
        return -1;
    }
    if (nown[0] == 0 && nown[1] == 0 && nown[2] == 0) {
        if (nother > 0) {
            say(msg, size, "%s:%ld: the header names the %s's channels ('%s'), not the %s's: the files swapped? "
                           "(merge ACC GYRO OUT: the accelerometer's file first)",
                path, line, k_sensor[1 - kind], f[other], k_sensor[kind]);
        } else {
            say(msg, size, "%s:%ld: the header names no %s axis (as 'x', 'x-axis (%s)', '%s' or '%s'): the "
                           "%s's file has a time column and x, y, z",
                path, line, k_sensor[kind], kind == HX_TRI_ACC ? "g" : "deg/s",
                kind == HX_TRI_ACC ? "acc_x" : "gyr_x", kind == HX_TRI_ACC ? "Acceleration x (m/s^2)" :
                "Gyroscope x (rad/s)", k_sensor[kind]);
        }
        return -1;
    }
    for (k = 0; k < 3; k++) {
        if (nown[k] != 1) {
            if (nown[k] == 0) {
                say(msg, size, "%s:%ld: the header names no %c axis of the %s", path, line, 'x' + k,
                    k_sensor[kind]);
            } else {
                say(msg, size, "%s:%ld: %d columns name the %s's %c axis ('%s', '%s'%s)", path, line, nown[k],
                    k_sensor[kind], 'x' + k, f[own[k][0]], f[own[k][1]], nown[k] > 2 ? ", ..." : "");
            }
            return -1;
        }
        c->ax[k] = own[k][0];
        if (bare_used) {
            int unread;
            (void)bare_axis(f[c->ax[k]], &au[k], &unread);
        } else {
            hx_name_class_t cl;
            (void)hx_name_classify(f[c->ax[k]], &cl);
            au[k] = cl.unit;
        }
        if (au[k] != HX_UNIT_NONE && !unit_is(kind, au[k])) {
            say(msg, size, "%s:%ld: column %d ('%s') names %s, not the %s's unit: the files swapped? (merge ACC "
                           "GYRO OUT: the accelerometer's file first)",
                path, line, c->ax[k] + 1, f[c->ax[k]], unit_text(au[k]), k_sensor[kind]);
            return -1;
        }
    }
    if (au[0] != au[1] || au[1] != au[2]) {
        say(msg, size, "%s:%ld: the axes name different units ('%s', '%s', '%s')", path, line, f[c->ax[0]],
            f[c->ax[1]], f[c->ax[2]]);
        return -1;
    }
    c->unit = au[0];
    /* the time: a time name whose first value reads as a time, the two
     * files' shared clock first. MetaWear's MetaBase writes "epoch (ms)",
     * "time (-13:00)" (a date and time) and "elapsed (s)", and each file's
     * elapsed counts from its own first sample: were the two sensors
     * started apart, merged by it they would be that far out of step. So a
     * clock's name (epoch, unix) first, then a date and time, then a name
     * with its unit, then any; the first of a rank. */
    c->t = -1;
    c->t_unit = HX_UNIT_NONE;
    c->t_elapsed = 0;
    c->t_dated = 0;
    for (i = 0, best = -1; i < ntimes; i++) {
        hx_name_class_t cl;
        int64_t ns;
        int rank, dated;
        const int rc = times[i] < nd ? field_time(d[times[i]], delim, 9, &ns) : -1;
        if (rc != 0 && rc != -3) { /* -3: a number beyond int64 in seconds, as ns since the epoch is */
            continue;
        }
        (void)hx_name_classify(f[times[i]], &cl);
        /* a date and time, or a clock time alone (MetaBase's in dots) */
        dated = field_dated(d[times[i]], delim);
        rank = cl.clock == 1 ? 3 : dated ? 2 : cl.unit != HX_UNIT_NONE ? 1 : 0;
        if (rank > best) {
            best = rank;
            c->t = times[i];
            c->t_unit = cl.unit;
            c->t_elapsed = cl.clock == -1;
            c->t_dated = dated;
        }
    }
    if (c->t < 0) {
        if (ntimes > 0) {
            say(msg, size, "%s:%ld: the time column ('%s') holds no number in the first row ('%s')", path, row_line,
                f[times[0]], times[0] < nd ? d[times[0]] : "");
        } else {
            say(msg, size, "%s:%ld: the header names no time column (t, time, timestamp, elapsed, 'Time (s)', ...)",
                path, line);
        }
        return -1;
    }
    return 0;
}

/* A header's delimiter: a comma, else a tab, else a semicolon, else
 * blanks (as the log reader takes the first it finds). */
static char header_delim(const char *h)
{
    return strchr(h, ',') != NULL ? ',' : strchr(h, '\t') != NULL ? '\t' : strchr(h, ';') != NULL ? ';' : ' ';
}

/* Whether a comment's text, a note to the log reader, names one sensor's
 * columns (hx_tri_header_kind): "# t acc_x acc_y acc_z", numpy's savetxt
 * header with blanks between the names (the log reader's needs all seven
 * interchange names, so that "# t is in s" is no header). */
static int comment_names_sensor(const char *text)
{
    char copy[HX_LINE_MAX], *f[TRI_MAX_COLS];
    snprintf(copy, sizeof copy, "%s", text);
    return hx_tri_header_kind(f, hx_split_fields(copy, header_delim(text), f, TRI_MAX_COLS)) >= 0;
}

/* Grow the arrays to hold n + 1 samples. 0, -1 out of memory. */
static int grow(hx_tri_t *f, size_t *cap)
{
    size_t c;
    void *p;
    if (f->n < *cap) {
        return 0;
    }
    c = *cap == 0 ? 4096 : *cap * 2;
    if ((p = realloc(f->t_ns, c * sizeof *f->t_ns)) == NULL) {
        return -1;
    }
    f->t_ns = (int64_t *)p;
    if ((p = realloc(f->v, c * sizeof *f->v)) == NULL) {
        return -1;
    }
    f->v = (double(*)[3])p;
    *cap = c;
    return 0;
}

/* The rows of a time column that names no unit whose intervals judge it
 * (a rate no IMU has in seconds: hx_time_unit_fix). */
#define TRI_PROBE_ROWS 4096

static const char *digits_unit(int digits)
{
    return digits == 6 ? "ms" : digits == 3 ? "us" : digits == 0 ? "ns" : "s";
}

int hx_tri_load(hx_tri_t *f, const char *path, hx_tri_kind_t kind, const hx_csv_layout_t *units, char *err,
                size_t err_size)
{
    return hx_tri_load_progress(f, path, kind, units, NULL, NULL, err, err_size);
}

/* The fraction of the file read (compressed bytes for a .gz), -1 unknown. */
static double read_fraction(gzFile gz, const char *path)
{
    struct stat st;
    const z_off_t off = gzoffset(gz);
    if (off < 0 || stat(path, &st) != 0 || st.st_size <= 0) {
        return -1.0;
    }
    return (double)off >= (double)st.st_size ? 1.0 : (double)off / (double)st.st_size;
}

int hx_tri_load_progress(hx_tri_t *f, const char *path, hx_tri_kind_t kind, const hx_csv_layout_t *units,
                         void (*progress)(void *ctx, double frac), void *ctx, char *err, size_t err_size)
{
    text_t *t;
    char *hf[TRI_MAX_COLS], *df[TRI_MAX_COLS], hdr[HX_LINE_MAX], delim = ',';
    int nh = 0, nd, rc, k, need, unitless, overflow = 0, nprobe = 0, total, sep_given = 0;
    long hline;
    hx_comment_t ch;
    cols_t c;
    size_t cap = 0;
    double scale, *probe = NULL;
    hx_csv_layout_t l, ask; /* ask: the --units given, for a remedy that names one --units for both files */
    memset(f, 0, sizeof *f);
    f->kind = kind;
    t = (text_t *)calloc(1, sizeof *t);
    if (t == NULL) {
        say(err, err_size, "%s: out of memory", path);
        return -1;
    }
    t->gz = hx_gzopen_input(path, err, err_size);
    if (t->gz == NULL) {
        free(t);
        return -1;
    }
    {
        /* binary data (a .bin given here) or UTF-16 text: the readers' words */
        unsigned char head[512];
        const int got = gzread(t->gz, head, sizeof head);
        if (got > 0 && hx_head_not_text(path, head, (size_t)got, 0, err, err_size) != HX_HEAD_TEXT) {
            gzclose(t->gz);
            free(t);
            return -1;
        }
        if (gzrewind(t->gz) != 0) {
            say(err, err_size, "%s: cannot read its start again", path);
            gzclose(t->gz);
            free(t);
            return -1;
        }
    }
    /* the header: the first line that is neither blank nor a comment, after
     * Excel's separator line, or a commented header, as the log reader
     * finds it (hx_sep_line, hx_comment_line) */
    for (;;) {
        const char *text;
        rc = next_line(t, path, err, err_size);
        if (rc <= 0) {
            if (rc == 0) {
                say(err, err_size, "%s: no header line (the file is empty or blank)", path);
            }
            goto fail;
        }
        if (t->lineno == 1 && (unsigned char)t->line[0] == 0xEF && (unsigned char)t->line[1] == 0xBB &&
            (unsigned char)t->line[2] == 0xBF) {
            memmove(t->line, t->line + 3, strlen(t->line + 3) + 1); /* a UTF-8 byte-order mark */
        }
        if (blank_line(t->line)) {
            continue;
        }
        if (!sep_given && hx_sep_line(t->line, &delim)) {
            sep_given = 1; /* the separator the line names, the header's next */
            continue;
        }
        ch = hx_comment_line(t->line, &text);
        if (ch == HX_COMMENT_NOTE && comment_names_sensor(text)) {
            ch = HX_COMMENT_HEADER_IF_DATA; /* "# t acc_x acc_y acc_z": one sensor's names */
        }
        if (ch == HX_COMMENT_NOTE) {
            continue;
        }
        if (ch != HX_COMMENT_NONE) {
            memmove(t->line, text, strlen(text) + 1);
        }
        break;
    }
    for (;;) {
        memcpy(hdr, t->line, sizeof hdr);
        hline = t->lineno;
        /* the first data row, for the time column's choice */
        do {
            rc = next_line(t, path, err, err_size);
            if (rc <= 0) {
                if (rc == 0) {
                    say(err, err_size, "%s: no data after the header (line %ld)", path, t->lineno);
                }
                goto fail;
            }
        } while (blank_line(t->line) || t->line[0] == '#');
        if (ch != HX_COMMENT_HEADER_IF_DATA || hx_data_row(t->line)) {
            break;
        }
        ch = HX_COMMENT_NONE; /* a note naming the columns before the header itself: this line */
    }
    if (!sep_given || strchr(hdr, delim) == NULL) {
        delim = header_delim(hdr);
    }
    total = hx_fields_total(hdr, delim);
    nh = hx_split_fields(hdr, delim, hf, TRI_MAX_COLS);
    /* a trailing delimiter names no field (as the log reader counts them) */
    f->hdr_fields = delim == ' ' || total > TRI_MAX_COLS ? nh : hx_named_fields(hf, nh, total);
    nd = hx_split_fields(t->line, delim, df, TRI_MAX_COLS);
    if (find_cols(hf, nh, df, nd, delim, kind, path, hline, t->lineno, &c, err, err_size) != 0) {
        if (total > TRI_MAX_COLS && strlen(err) + 80 < err_size) {
            /* names past the columns read may be the ones looked for */
            say(err + strlen(err), err_size - strlen(err), " (merge reads the first %d columns of a header; this "
                                                           "one has more)", TRI_MAX_COLS);
        }
        goto fail;
    }
    snprintf(f->cols[0], sizeof f->cols[0], "%s", hf[c.t]);
    f->t_from_start = c.t_elapsed;
    for (k = 0; k < 3; k++) {
        snprintf(f->cols[k + 1], sizeof f->cols[k + 1], "%s", hf[c.ax[k]]);
    }
    /* units: --units first (a time named aside, below), then the names, then the interchange's */
    if (units != NULL) {
        l = *units;
    } else {
        hx_csv_layout_default(&l);
    }
    /* the ug question's remedy names --units as given, not this file's
     * header units: one --units applies to both files (a 'time (ms)'
     * header made it 'give --units time=ms,accel=ug', which read the
     * other file's seconds as ms) */
    ask = l;
    /* the time: a unit the header names wins over --units time=, which is
     * one option for two files: the unit of a time whose name gives none
     * (a 'time (ms)' file beside a bare 'time' one was read in the s that
     * --units time=s gave the other, a 0.1 Hz log, merged, exit 0) */
    if (!(l.units_given & 1) || c.t_unit != HX_UNIT_NONE) {
        const int asked = l.time_digits;
        hx_csv_layout_unit(&l, c.t_unit);
        if ((l.units_given & 1) && !c.t_dated && l.time_digits != asked) {
            f->time_asked = digits_unit(asked);
        }
    }
    if (!(l.units_given & (kind == HX_TRI_ACC ? 2 : 4))) {
        hx_csv_layout_unit(&l, c.unit);
    }
    unitless = !(l.units_given & 1) && c.t_unit == HX_UNIT_NONE;
    /* a date and time carries its own unit, whatever the name or --units say */
    f->time_unit = c.t_dated ? NULL : digits_unit(l.time_digits);
    scale = kind == HX_TRI_ACC ? l.acc_scale : l.gyr_scale;
    f->unit = kind == HX_TRI_ACC ? hx_accel_unit_name(scale) : hx_gyro_unit_name(scale);
    f->unit_from = (l.units_given & (kind == HX_TRI_ACC ? 2 : 4)) ? "--units"
                   : c.unit != HX_UNIT_NONE ? "named" : "default";
    if (unitless && (probe = (double *)malloc(TRI_PROBE_ROWS * sizeof *probe)) == NULL) {
        say(err, err_size, "%s: out of memory", path);
        goto fail;
    }
    need = c.t;
    for (k = 0; k < 3; k++) {
        need = c.ax[k] > need ? c.ax[k] : need;
    }
    /* the rows (the first is in t->line already); a row whose stamp is not
     * after the last kept one's (a repeated stamp, a step back) dropped */
    for (;;) {
        if (!blank_line(t->line) && t->line[0] != '#') {
            int64_t ns = 0;
            double v[3];
            int bad = -1, trc;
            if (nd <= need) {
                say(f->error, sizeof f->error, "%s:%ld: %d field%s, the %s's columns need %d", path, t->lineno,
                    nd, nd == 1 ? "" : "s", k_sensor[kind], need + 1);
                break;
            }
            if (t->open && nd <= need + 1) {
                /* the last line, no newline, ending in a value read: the
                 * cut may have shortened it (9.8 read as 9); dropped */
                f->cut_last = t->lineno;
                break;
            }
            if (nd < f->hdr_fields && !t->open && f->short_rows++ == 0) {
                f->short_first = t->lineno; /* a field lost inside the row shifts the ones after it */
            }
            for (k = f->hdr_fields; k < nd; k++) {
                if (df[k][0] != '\0') {
                    /* data past the header's fields (not a trailing
                     * delimiter): a stray delimiter split a field */
                    if (f->long_rows++ == 0) {
                        f->long_first = t->lineno;
                    }
                    break;
                }
            }
            f->rows_checked++;
            if (delim != ',' && !f->dmix.said) {
                /* decimal commas and points both: read alike, said once */
                (void)hx_decimal_mix_note(&f->dmix, df[c.t], t->lineno);
                for (k = 0; k < 3; k++) {
                    (void)hx_decimal_mix_note(&f->dmix, df[c.ax[k]], t->lineno);
                }
            }
            trc = field_time(df[c.t], delim, l.time_digits, &ns);
            if (unitless && nprobe < TRI_PROBE_ROWS && field_value(df[c.t], delim, &probe[nprobe]) == 0) {
                nprobe++;
            }
            if (trc == -3 && unitless) {
                /* beyond int64 ns in seconds: judged by the probe below */
                overflow = 1;
                if (nprobe >= TRI_PROBE_ROWS) {
                    break;
                }
            } else if (trc != 0) {
                bad = c.t;
            }
            for (k = 0; k < 3 && bad < 0; k++) {
                if (field_value(df[c.ax[k]], delim, &v[k]) != 0) {
                    bad = c.ax[k];
                }
            }
            if (bad >= 0) {
                say(f->error, sizeof f->error, "%s:%ld: column %d ('%s') is not a number: '%.40s'", path, t->lineno,
                    bad + 1, hf[bad], df[bad]);
                break;
            }
            for (k = 0; k < 3; k++) {
                /* what the log reader refuses in the merged log: the file
                 * stops here, as at a row of text */
                char what[320]; /* the value quoted in its unit and in SI units, the --units remedy */
                if (hx_value_beyond(v[k], scale, kind != HX_TRI_ACC, df[c.ax[k]], kind == HX_TRI_ACC ? &ask : NULL, what,
                                    sizeof what)) {
                    say(f->error, sizeof f->error, "%s:%ld: column %d %s", path, t->lineno, c.ax[k] + 1, what);
                    bad = c.ax[k];
                    break;
                }
            }
            if (bad >= 0) {
                break;
            }
            if (overflow) {
                /* no sample kept: the probe decides */
            } else if (f->n > 0 && ns <= f->t_ns[f->n - 1]) {
                f->steps_back++;
            } else {
                if (grow(f, &cap) != 0) {
                    say(f->error, sizeof f->error, "%s:%ld: out of memory", path, t->lineno);
                    break;
                }
                f->t_ns[f->n] = ns;
                for (k = 0; k < 3; k++) {
                    f->v[f->n][k] = v[k] * scale;
                }
                f->n++;
            }
        }
        rc = next_line(t, path, f->error, sizeof f->error);
        if (rc <= 0) {
            break;
        }
        if (progress != NULL && (t->lineno & 65535) == 0) {
            const double fr = read_fraction(t->gz, path);
            if (fr >= 0.0) {
                progress(ctx, fr);
            }
        }
        nd = hx_split_fields(t->line, delim, df, TRI_MAX_COLS);
    }
    if (unitless) {
        /* seconds, unless the stamps so read give a rate no IMU has: the
         * median of the first rows' positive intervals */
        double rate = 0.0;
        int m = 0, i;
        hx_time_fix_t fix;
        for (i = 1; i < nprobe; i++) {
            if (probe[i] > probe[i - 1]) {
                probe[m++] = probe[i] - probe[i - 1];
            }
        }
        if (m > 0) {
            const double med = hx_median(probe, m);
            rate = med > 0.0 ? 1.0 / med : 0.0;
        }
        if (rate > 0.0 && (rate < HX_TIME_RATE_MIN_HZ || rate > HX_TIME_RATE_MAX_HZ) &&
            hx_time_unit_fix(rate, 9, &fix)) {
            /* 1 to 20 Hz may be a slow logger's seconds as well (12.5 Hz read
             * as ms is 12.5 kHz): both named, merge has no floor of its own */
            char slow[96] = "";
            if (rate >= 1.0 && rate < HX_TIME_RATE_MIN_HZ) {
                say(slow, sizeof slow, "; if they are seconds, a %.4g Hz log: --units time=s", rate);
            }
            say(err, err_size, "%s: the time column '%s' names no unit, and in seconds its stamps give %.3g Hz: "
                               "they look like %s, a %.4g Hz log (give --units time=%s)%s",
                path, f->cols[0], rate, fix.name, fix.rate_hz, fix.opt, slow);
            goto fail;
        }
    }
    if (overflow) {
        say(err, err_size, "%s: the stamps of column '%s' are beyond 292 years in nanoseconds read in %s (give "
                           "their unit with --units time=...)", path, f->cols[0],
                f->time_unit != NULL ? f->time_unit : "dates");
        goto fail;
    }
    if (f->n == 0) {
        if (f->error[0] != '\0') {
            say(err, err_size, "%s", f->error);
        } else if (f->cut_last > 0) {
            say(err, err_size, "%s:%ld: no sample: its one row is a last line without a newline, ending in a value "
                               "that may be cut (file cut off mid-write?)", path, f->cut_last);
        } else {
            say(err, err_size, "%s: no sample", path);
        }
        goto fail;
    }
    f->rate_hz = hx_stamp_rate_hz(f->t_ns, f->n, NULL);
    free(probe);
    gzclose(t->gz);
    free(t);
    return f->error[0] != '\0' ? 1 : 0;
fail:
    free(probe);
    gzclose(t->gz);
    free(t);
    hx_tri_free(f);
    return -1;
}

void hx_tri_free(hx_tri_t *f)
{
    free(f->t_ns);
    free(f->v);
    f->t_ns = NULL;
    f->v = NULL;
    f->n = 0;
}

hx_tri_where_t hx_tri_at(const hx_tri_t *f, int64_t t_ns, size_t *j, int64_t gap_ns, double v[3])
{
    size_t a;
    int k;
    if (f->n == 0 || t_ns < f->t_ns[0]) {
        return HX_TRI_BEFORE;
    }
    if (t_ns > f->t_ns[f->n - 1]) {
        return HX_TRI_AFTER;
    }
    a = *j < f->n ? *j : 0;
    if (f->t_ns[a] > t_ns) {
        a = 0; /* a cursor past t: from the start again */
    }
    while (a + 1 < f->n && f->t_ns[a + 1] <= t_ns) {
        a++;
    }
    *j = a;
    if (f->t_ns[a] == t_ns) {
        for (k = 0; k < 3; k++) {
            v[k] = f->v[a][k];
        }
        return HX_TRI_IN;
    }
    /* t_ns lies strictly between the stamps a and a + 1 */
    {
        const int64_t span = f->t_ns[a + 1] - f->t_ns[a];
        const double w = (double)(t_ns - f->t_ns[a]) / (double)span;
        if (span > gap_ns) {
            return HX_TRI_GAP;
        }
        for (k = 0; k < 3; k++) {
            /* between the two values even when rounding says otherwise (a
             * sample of 1e18 beside one of 9) */
            const double x0 = f->v[a][k], x1 = f->v[a + 1][k], x = (1.0 - w) * x0 + w * x1;
            v[k] = x < (x0 < x1 ? x0 : x1) ? (x0 < x1 ? x0 : x1) : x > (x0 < x1 ? x1 : x0) ? (x0 < x1 ? x1 : x0) : x;
        }
    }
    return HX_TRI_IN;
}
