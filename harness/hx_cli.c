/* Shared command-line plumbing of ./harness (see hx_cli.h). */
#define _XOPEN_SOURCE 700 /* realpath */
#include "hx_cli.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "footnav/fnav_version.h"

static int opt_index(const hx_spec_t *spec, const char *name, size_t len)
{
    int i;
    for (i = 0; spec->opts != NULL && spec->opts[i].name != NULL; i++) {
        if (strlen(spec->opts[i].name) == len && strncmp(spec->opts[i].name, name, len) == 0) {
            return i;
        }
    }
    return -1;
}

void hx_usage(const hx_spec_t *spec, FILE *f)
{
    int i;
    fprintf(f, "usage: harness %s %s\n", spec->name, spec->usage);
    if (spec->summary != NULL) {
        fprintf(f, "\n%s\n", spec->summary);
    }
    fprintf(f, "\noptions:\n");
    for (i = 0; spec->opts != NULL && spec->opts[i].name != NULL; i++) {
        char left[64];
        if (spec->opts[i].help == NULL) {
            continue; /* accepted only to be refused with a reason */
        }
        snprintf(left, sizeof left, "%s%s%s", spec->opts[i].name, spec->opts[i].metavar ? " " : "",
                 spec->opts[i].metavar ? spec->opts[i].metavar : "");
        if (strlen(left) > 22) {
            /* a name and value wider than the column stand on their own
             * line ("--filter-profile NAME|FILE the filter's ..." ran together) */
            fprintf(f, "  %s\n", left);
            left[0] = '\0';
        }
        fprintf(f, "  %-22s %s%s\n", left, spec->opts[i].help, spec->opts[i].repeat ? " (repeatable)" : "");
    }
    fprintf(f, "  %-22s %s\n", "--help", "show this help");
}

/* The name of positional argument `k` (0-based) in a usage such as
 * "LOG PORT [options]": its k-th word of capitals before the options, or "". */
static void missing_name(const char *usage, int k, char *out, size_t size)
{
    const char *p = usage;
    out[0] = '\0';
    while (p != NULL && *p != '\0') {
        size_t n = strspn(p, "ABCDEFGHIJKLMNOPQRSTUVWXYZ_");
        if (n == 0 || (p[n] != ' ' && p[n] != '\0')) {
            return; /* "[options]", "--series", "|": the positional words are over */
        }
        if (k-- == 0) {
            snprintf(out, size, "%.*s", (int)n, p);
            return;
        }
        p += n;
        p += strspn(p, " ");
    }
}

int hx_args_parse(const hx_spec_t *spec, int argc, char **argv, hx_args_t *a)
{
    int i;
    int only_pos = 0;
    memset(a, 0, sizeof *a);
    a->spec = spec;
    for (i = 0; i < argc; i++) {
        const char *s = argv[i];
        if (!only_pos && strcmp(s, "--") == 0) {
            only_pos = 1;
            continue;
        }
        if (!only_pos && (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0)) {
            /* beside `--json -`, standard output is kept in hx_json_stdout
             * (the help went to standard error) */
            FILE *out = hx_json_stdout != NULL ? hx_json_stdout : stdout;
            hx_usage(spec, out);
            fflush(out); /* a write error on stdout is main()'s to report (exit 3) */
            return 1;
        }
        if (!only_pos && s[0] == '-' && s[1] == '-') {
            const char *eq = strchr(s, '=');
            size_t len = eq ? (size_t)(eq - s) : strlen(s);
            int k = opt_index(spec, s, len);
            const char *v = NULL;
            if (k < 0) {
                hx_error(spec->name, "unknown option '%.*s'", (int)len, s);
                hx_usage(spec, stderr);
                return -1;
            }
            if (spec->opts[k].metavar != NULL) {
                if (eq != NULL) {
                    v = eq + 1;
                } else if (i + 1 < argc && !(argv[i + 1][0] == '-' && argv[i + 1][1] == '-' && argv[i + 1][2] != '\0')) {
                    v = argv[++i];
                } else {
                    hx_error(spec->name, "option %s needs a value (%s)", spec->opts[k].name, spec->opts[k].metavar);
                    return -1;
                }
                if (*v == '\0') {
                    /* `--json ""` or `--json=`: an empty file name reached
                     * fopen, "cannot write  (No such file or directory)",
                     * exit 3 */
                    hx_error(spec->name, "option %s needs a value (%s), not an empty one", spec->opts[k].name,
                             spec->opts[k].metavar);
                    return -1;
                }
            } else if (eq != NULL) {
                hx_error(spec->name, "option %s takes no value", spec->opts[k].name);
                return -1;
            }
            if (a->count[k] > 0 && !spec->opts[k].repeat) {
                a->count[k] = 0; /* last one wins */
            }
            if (a->count[k] >= HX_MAX_REPEAT) {
                hx_error(spec->name, "option %s given too often", spec->opts[k].name);
                return -1;
            }
            a->val[k][a->count[k]++] = v ? v : "";
            continue;
        }
        if (s[0] == '-' && s[1] != '\0' && !only_pos && !(s[1] >= '0' && s[1] <= '9')) {
            hx_error(spec->name, "unknown option '%s'", s);
            hx_usage(spec, stderr);
            return -1;
        }
        if (a->npos >= spec->max_pos || a->npos >= HX_MAX_POS) {
            hx_error(spec->name, "unexpected argument '%s'", s);
            hx_usage(spec, stderr);
            return -1;
        }
        if (s[0] == '\0') {
            /* `harness replay "$LOG"` with LOG unset: an empty name is a
             * usage error, as an empty option value is, rather than reaching
             * fopen (": cannot read (No such file or directory)", exit 1,
             * exit 3 for convert's OUT, live's and stream's PORT, naming no
             * file) */
            char what[32];
            missing_name(spec->usage, a->npos, what, sizeof what);
            hx_error(spec->name, "argument%s%s is empty", what[0] != '\0' ? " " : "", what);
            hx_usage(spec, stderr);
            return -1;
        }
        a->pos[a->npos++] = s;
    }
    if (a->npos < spec->min_pos) {
        char what[32];
        missing_name(spec->usage, a->npos, what, sizeof what);
        hx_error(spec->name, "missing argument%s%s", what[0] != '\0' ? " " : "", what);
        hx_usage(spec, stderr);
        return -1;
    }
    return 0;
}

static int find(const hx_args_t *a, const char *name)
{
    int k = opt_index(a->spec, name, strlen(name));
    if (k < 0) {
        fprintf(stderr, "harness: internal: option %s not declared by %s\n", name, a->spec->name);
        abort();
    }
    return k;
}

int hx_refuse_dash(const char *cmd, const hx_args_t *a, const char *const *opts)
{
    /* '-' for an option that takes no stream is refused: otherwise
     * `replay --plot -` would write a PNG named '-', psd's --plot - make a
     * directory '-' and sim's --truth - a file '-' */
    for (; *opts != NULL; opts++) {
        const char *v = hx_arg(a, *opts);
        if (v != NULL && strcmp(v, "-") == 0) {
            const char *mv = a->spec->opts[find(a, *opts)].metavar;
            hx_error(cmd, "%s needs a %s name ('-' is not standard output here)", *opts,
                     mv != NULL && strcmp(mv, "DIR") == 0 ? "directory" : "file");
            return -1;
        }
    }
    return 0;
}

const char *hx_errno_note(int e, char *buf, size_t size)
{
    if (e != 0) {
        snprintf(buf, size, " (%s)", strerror(e));
    } else if (size > 0) {
        buf[0] = '\0';
    }
    return buf;
}

const char *hx_arg(const hx_args_t *a, const char *name)
{
    int k = find(a, name);
    return a->count[k] > 0 ? a->val[k][a->count[k] - 1] : NULL;
}

int hx_arg_count(const hx_args_t *a, const char *name)
{
    return a->count[find(a, name)];
}

const char *hx_arg_at(const hx_args_t *a, const char *name, int i)
{
    int k = find(a, name);
    return (i >= 0 && i < a->count[k]) ? a->val[k][i] : NULL;
}

int hx_flag(const hx_args_t *a, const char *name)
{
    return a->count[find(a, name)] > 0;
}

/* strtod alone took '0x10' as 16, ' 5' as 5 (but not '5 '), 'nan' and
 * 'inf'; the log readers refuse all of them */
int hx_scan_number(const char *s, const char **end, double *v)
{
    const char *p = s;
    char *e;
    double x;
    if (*p == '+' || *p == '-') {
        p++;
    }
    if (!((*p >= '0' && *p <= '9') || (*p == '.' && p[1] >= '0' && p[1] <= '9')) ||
        (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))) {
        return -1;
    }
    x = strtod(s, &e);
    if (e == s || !isfinite(x)) {
        return -1;
    }
    *v = x;
    *end = e;
    return 0;
}

int hx_parse_number(const char *s, double *v)
{
    const char *end;
    double x;
    if (hx_scan_number(s, &end, &x) != 0 || *end != '\0') {
        return -1;
    }
    *v = x;
    return 0;
}

/* hx_arg_double, and hx_arg_whole when `whole`: that also refuses a
 * fraction, and its message says "a whole number" */
static int arg_real(const hx_args_t *a, const char *name, double lo, double hi, int whole, double *out)
{
    const char *s = hx_arg(a, name);
    double v = 0.0;
    if (s == NULL) {
        return 0;
    }
    /* the three faults said apart: "--hangup-after '0' is not a whole
     * number in [1, ...]" read as if 0 were not a whole number */
    if (hx_parse_number(s, &v) != 0) {
        hx_error(a->spec->name, "%s '%s' is not a number (give a %snumber in [%.10g, %.10g])", name, s,
                 whole ? "whole " : "", lo, hi);
        return -1;
    }
    if (whole && v != floor(v)) {
        hx_error(a->spec->name, "%s '%s' is not a whole number (give one in [%.10g, %.10g])", name, s, lo, hi);
        return -1;
    }
    if (v < lo || v > hi) {
        hx_error(a->spec->name, "%s '%s' is out of range (give a %snumber in [%.10g, %.10g])", name, s,
                 whole ? "whole " : "", lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

int hx_arg_double(const hx_args_t *a, const char *name, double lo, double hi, double *out)
{
    return arg_real(a, name, lo, hi, 0, out);
}

int hx_arg_long(const hx_args_t *a, const char *name, long lo, long hi, long *out)
{
    /* a whole number as hx_arg_whole reads it (hx_parse_number: strtol
     * refused psd --nfft 1.28e2 and simgap --seeds 1e1, which
     * docs/harness.md, "Numbers", and montecarlo's --seeds take); absent,
     * *out keeps its default (exact in a double for these ranges) */
    double v = (double)*out;
    if (arg_real(a, name, (double)lo, (double)hi, 1, &v) != 0) {
        return -1;
    }
    *out = (long)v;
    return 0;
}

int hx_arg_whole(const hx_args_t *a, const char *name, double lo, double hi, double *out)
{
    return arg_real(a, name, lo, hi, 1, out);
}

/* A progress or status line redrawn in place on a terminal ends without a
 * newline: an error or a warning that comes while one is drawn starts a
 * line of its own, not the rest of that line (stream's "write failed"
 * after "harness stream:  41 % (1.6 s)", live's warnings after its status
 * line). One flag for both. */
static int g_line_open;

void hx_line_open(void)
{
    g_line_open = 1;
}

void hx_line_break(void)
{
    if (g_line_open) {
        fputc('\n', stderr);
        g_line_open = 0;
    }
}

/* A message's text to standard error with each control character
 * (or byte that is not UTF-8; hx_text_char) as '?': a path or a field that a message quotes is the
 * text of a file name or a file, and an escape sequence in it (ESC ]0;...
 * sets the terminal's title, CSI clears it) must not reach the terminal
 * as one; no message of the harness holds a control character of its
 * own (its line ends are written here). */
static void put_msg(const char *fmt, va_list ap)
{
    char buf[4096], *p = buf, *o;
    const char *s;
    va_list aq;
    int n;
    va_copy(aq, ap);
    n = vsnprintf(buf, sizeof buf, fmt, aq);
    va_end(aq);
    if (n < 0) {
        return;
    }
    if ((size_t)n >= sizeof buf) {
        char *big = malloc((size_t)n + 1u);
        if (big != NULL) {
            (void)vsnprintf(big, (size_t)n + 1u, fmt, ap);
            p = big;
        } else {
            /* out of memory: the message cut at a character's start, and
             * said to be ("...") */
            size_t e = sizeof buf - 4u;
            while (e > 0u && ((unsigned char)buf[e] & 0xc0u) == 0x80u) {
                e--;
            }
            memcpy(buf + e, "...", 4u);
        }
    }
    /* in place (a control character's one or two bytes become one '?'),
     * then one write: stderr is unbuffered, and a character at a time was
     * a write(2) per byte, which a concurrent writer's line (a parallel
     * job's, into the same log) could split */
    for (s = p, o = p; *s != '\0';) {
        int ctl;
        size_t k = hx_text_char(s, &ctl);
        if (ctl && !(s[0] == '\n' && s[1] == '\0')) { /* the line's own end stays */
            *o++ = '?';
            s += k;
        } else {
            while (k-- > 0u) {
                *o++ = *s++;
            }
        }
    }
    *o = '\0';
    (void)fputs(p, stderr);
    if (p != buf) {
        free(p);
    }
}

void hx_eprintf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    put_msg(fmt, ap);
    va_end(ap);
}

/* The process's first error message (hx_json_failure) and whether a JSON
 * was written (hx_write_json). */
static char g_first_error[1024];
static int g_json_written;

void hx_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    if (g_first_error[0] == '\0') {
        va_start(ap, fmt);
        (void)vsnprintf(g_first_error, sizeof g_first_error, fmt, ap);
        va_end(ap);
    }
    hx_line_break();
    fprintf(stderr, "harness %s: error: ", cmd);
    va_start(ap, fmt);
    put_msg(fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

const char *hx_cmd_name = "harness";

/* Once-per-process mode (hx_warn_once): the 64-bit FNV-1a hash of each
 * warning and note printed, "cmd\nkind\ntext"; a repeat is counted, not
 * printed. A full table prints every new message (nothing is lost but the
 * dedup). */
#define HX_WARN_SEEN_MAX 4096
static int g_warn_once;
static unsigned long long g_warn_seen[HX_WARN_SEEN_MAX];
static size_t g_warn_seen_n;
static long g_warn_repeats;

void hx_warn_once(int on)
{
    g_warn_once = on;
}

long hx_warn_repeats(void)
{
    return g_warn_repeats;
}

unsigned long long hx_fnv1a(unsigned long long h, const char *s)
{
    for (; *s != '\0'; s++) {
        h ^= (unsigned char)*s;
        h *= 1099511628211ULL;
    }
    return h ^ 0x0aULL; /* a separator, so that ("ab", "c") and ("a", "bc") differ */
}

/* 1 when the message was printed already in once mode (counted), else 0
 * (remembered). */
static int warn_repeat(const char *cmd, const char *kind, const char *text)
{
    unsigned long long h = hx_fnv1a(hx_fnv1a(hx_fnv1a(HX_FNV1A_INIT, cmd), kind), text);
    size_t i;
    if (!g_warn_once) {
        return 0;
    }
    for (i = 0; i < g_warn_seen_n; i++) {
        if (g_warn_seen[i] == h) {
            g_warn_repeats++;
            return 1;
        }
    }
    if (g_warn_seen_n < HX_WARN_SEEN_MAX) {
        g_warn_seen[g_warn_seen_n++] = h;
    }
    return 0;
}

void hx_warn(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    if (g_warn_once) {
        char text[4096];
        va_start(ap, fmt);
        (void)vsnprintf(text, sizeof text, fmt, ap);
        va_end(ap);
        if (warn_repeat(cmd, "warning", text)) {
            return;
        }
    }
    hx_line_break();
    fprintf(stderr, "harness %s: warning: ", cmd);
    va_start(ap, fmt);
    put_msg(fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

void hx_warn_gz_output(const char *cmd, const char *path, hx_format_t fmt)
{
    /* convert and sim must not write OUT.csv.gz plain, nor OUT.bin.gz as
     * plain CSV (its name does not end in .bin) without a word: gzip -d
     * would refuse it */
    const size_t n = strlen(path);
    if (!hx_ends_in(path, n, ".gz")) {
        return;
    }
    if (fmt == HX_FMT_BIN || fmt == HX_FMT_CSV || !hx_ends_in(path, n - 3, ".bin")) {
        hx_warn(cmd, "%s: written uncompressed (footnav writes no gzip; every command reads the file by its "
                     "content); for a gzip file write it without .gz and compress it with gzip",
                path);
    } else {
        hx_warn(cmd, "%s: written uncompressed, as CSV (a name ending in .bin is a .bin, or with --to bin; footnav "
                     "writes no gzip): for a compressed .bin write %.*s and compress it with gzip",
                path, (int)(n - 3), path);
    }
}

static int input_options(const char *cmd, const hx_args_t *a, hx_format_t *fmt, double *rate)
{
    const char *from = hx_arg(a, "--from");
    *fmt = HX_FMT_AUTO;
    *rate = 0.0;
    if (from != NULL) {
        *fmt = hx_format_from_name(from);
        if (*fmt == HX_FMT_COUNT || *fmt == HX_FMT_AUTO) {
            hx_error(cmd, "unknown input format '%s' (known: %s)", from, hx_format_list());
            return -1;
        }
    }
    if (hx_arg_double(a, "--input-rate", 1e-3, 1e6, rate) != 0) {
        return -1;
    }
    {
        /* --columns and --units: the interchange CSV under another layout,
         * for every reader this command opens (docs/log-format.md,
         * "Another layout") */
        const char *map = hx_arg(a, "--columns"), *units = hx_arg(a, "--units");
        hx_csv_layout_t l;
        char err[HX_ERR_SIZE];
        hx_csv_layout_default(&l);
        if ((map != NULL && hx_csv_columns_parse(&l, map, err, sizeof err) != 0) ||
            (units != NULL && hx_csv_units_parse(&l, units, err, sizeof err) != 0)) {
            hx_error(cmd, "%s", err);
            return -1;
        }
        if (l.option != NULL && *fmt != HX_FMT_CSV && *fmt != HX_FMT_AUTO) {
            hx_layout_refusal(err, sizeof err, NULL, l.option, *fmt, 0);
            hx_error(cmd, "%s", err);
            return -1;
        }
        hx_reader_set_layout(&l);
    }
    return 0;
}

int hx_check_input_opts(const char *cmd, const hx_args_t *a)
{
    hx_format_t fmt;
    double rate;
    hx_csv_layout_t l;
    if (input_options(cmd, a, &fmt, &rate) != 0) {
        return -1;
    }
    hx_reader_layout(&l); /* input_options set it: l.option names the options given, NULL none */
    if (fmt == HX_FMT_AUTO && l.option != NULL && a->npos > 0) {
        /* a log detected as another format is a usage error too, as with
         * --from (the reader would refuse it as unreadable data) */
        const hx_format_t got = hx_detect_file(a->pos[0]);
        if (got != HX_FMT_AUTO && got != HX_FMT_CSV) {
            char msg[1024];
            hx_layout_refusal(msg, sizeof msg, a->pos[0], l.option, got, 1);
            hx_error(cmd, "%s", msg);
            return -1;
        }
    }
    return 0;
}

int hx_arg_to(const char *cmd, const hx_args_t *a, const char *out, hx_format_t *to)
{
    const char *name = hx_arg(a, "--to");
    *to = HX_FMT_AUTO;
    if (name != NULL) {
        *to = hx_format_from_name(name);
        if (*to != HX_FMT_BIN && *to != HX_FMT_CSV) {
            hx_error(cmd, "--to must be bin or csv, not '%s'", name);
            return -1;
        }
    } else if (strcmp(out, "-") == 0) {
        *to = HX_FMT_CSV;
    }
    return 0;
}

void hx_print_warnings(const char *cmd, const char *w)
{
    char buf[HX_WARN_SIZE]; /* a reader's warnings whole (512 bytes cut a ROS header's second warning) */
    char *line, *save = NULL;
    if (w == NULL || *w == '\0') {
        return;
    }
    snprintf(buf, sizeof buf, "%s", w);
    for (line = strtok_r(buf, "\n", &save); line != NULL; line = strtok_r(NULL, "\n", &save)) {
        if (strncmp(line, "note: ", 6) == 0) {
            if (!warn_repeat(cmd, "note", line + 6)) {
                hx_line_break();
                fprintf(stderr, "harness %s: note: ", cmd); /* routine: nothing to act on */
                hx_eprintf("%s", line + 6);
                fputc('\n', stderr);
            }
        } else {
            hx_warn(cmd, "%s", line);
        }
    }
}

hx_reader_t *hx_open_input(const char *cmd, const hx_args_t *a, const char *path)
{
    hx_format_t fmt;
    double rate;
    char err[HX_ERR_SIZE];
    hx_reader_t *r;
    if (input_options(cmd, a, &fmt, &rate) != 0) {
        return NULL;
    }
    r = hx_reader_open(path, fmt, rate, err, sizeof err);
    if (r == NULL) {
        hx_error(cmd, "%s", err);
        return NULL;
    }
    hx_print_warnings(cmd, hx_reader_take_warnings(r));
    return r;
}

static void load_progress(void *ctx, double frac)
{
    hx_progress_update((hx_progress_t *)ctx, frac);
}

int hx_load_input(const char *cmd, const hx_args_t *a, const char *path, hx_log_t *log)
{
    hx_format_t fmt;
    double rate;
    char err[HX_ERR_SIZE], label[48];
    hx_progress_t pr;
    int rc;
    if (input_options(cmd, a, &fmt, &rate) != 0) {
        return -1;
    }
    /* the reading of a long log shows progress (a day at 100 Hz takes
     * `info` 2.3 s) */
    snprintf(label, sizeof label, "%s: reading", cmd);
    {
        /* a command's --quiet ("no progress indicator": simgap's) holds for
         * the reading too (no "simgap: reading: 10 %" under --quiet) */
        const int k = opt_index(a->spec, "--quiet", strlen("--quiet"));
        const int quiet = k >= 0 && a->count[k] > 0;
        hx_progress_start(&pr, label, 1.0);
        rc = hx_log_load_progress(log, path, fmt, rate, quiet ? NULL : load_progress, &pr, err, sizeof err);
        hx_progress_end(&pr); /* prints only what was shown */
    }
    if (rc < 0) {
        hx_error(cmd, "%s", err);
        return -1;
    }
    hx_print_warnings(cmd, log->warnings);
    if (rc > 0) {
        hx_warn(cmd, "%s (using the %zu sample%s before it)", log->error, log->n, log->n == 1 ? "" : "s");
    }
    return rc;
}

/* ------------------------------------------------------------ progress */

double hx_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void hx_progress_start(hx_progress_t *p, const char *label, double total)
{
    memset(p, 0, sizeof *p);
    p->label = label;
    p->total = total > 0.0 ? total : 1.0;
    p->t_start = hx_now_s();
    p->t_last = p->t_start;
    p->t_origin = p->t_start;
    p->tty = isatty(fileno(stderr));
    p->last_decile = 0;
}

int hx_progress_text(char *buf, size_t size, const char *label, double frac, double elapsed_s)
{
    char left[48] = "";
    /* floored, so that a line never says more than is done: rounded, 9.6 %
     * would print "10 %" and the decile's line after it "10 %" again, and
     * 99.6 % "100 %" before the end */
    const int pct = frac >= 1.0 ? 100 : frac > 0.0 ? (int)(100.0 * frac + 1e-9) : 0; /* 0.29: 28.999... */
    /* the time left at the rate so far, once 5 % and 2 s of it give a rate to go by */
    if (frac >= 0.05 && frac < 1.0 && elapsed_s >= 2.0) {
        (void)snprintf(left, sizeof left, ", about %.0f s left", elapsed_s * (1.0 - frac) / frac);
    }
    return snprintf(buf, size, "%s: %3d %% (%.1f s%s)", label, pct, elapsed_s, left);
}

void hx_progress_update(hx_progress_t *p, double done)
{
    double now, frac;
    int decile;
    char line[256];
    now = hx_now_s();
    if (now - p->t_start < 1.0) {
        return;
    }
    frac = done / p->total;
    if (frac > 1.0) {
        frac = 1.0;
    }
    if (p->tty) {
        if (now - p->t_last < 0.2 && p->shown) {
            return;
        }
        (void)hx_progress_text(line, sizeof line, p->label, frac, now - p->t_start);
        /* the trailing blanks clear a longer line drawn before */
        fprintf(stderr, "\r%s   ", line);
        fflush(stderr);
        hx_line_open();
    } else {
        decile = (int)(frac * 10.0);
        if (decile <= p->last_decile && p->shown) {
            return;
        }
        p->last_decile = decile;
        (void)hx_progress_text(line, sizeof line, p->label, frac, now - p->t_start);
        fprintf(stderr, "%s\n", line);
    }
    p->shown = 1;
    p->t_last = now;
}

void hx_progress_end(hx_progress_t *p)
{
    g_line_open = 0; /* the line below ends it */
    if (p->shown) {
        /* on a terminal the blanks clear the rest of the longer progress line */
        fprintf(stderr, "%s%s: done in %.1f s%s\n", p->tty ? "\r" : "", p->label, hx_now_s() - p->t_origin,
                p->tty ? "                        " : "");
    }
}

/* ------------------------------------------------------------ output files */

/* a path's directory (".", when it has none) into dir and its last
 * component into *base; 0 when it has no usable last component */
static int split_dir(const char *path, char *dir, size_t size, const char **base)
{
    const char *slash = strrchr(path, '/');
    size_t dn = slash == NULL ? 0 : slash == path ? 1 : (size_t)(slash - path);
    *base = slash != NULL ? slash + 1 : path;
    if (dn >= size || **base == '\0' || strcmp(*base, ".") == 0 || strcmp(*base, "..") == 0) {
        return 0;
    }
    if (dn == 0) {
        dir[0] = '.';
        dn = 1;
    } else {
        memcpy(dir, path, dn);
    }
    dir[dn] = '\0';
    return 1;
}

int hx_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    int ha, hb;
    char da[4096], db[4096];
    const char *ba, *bb;
    if (a == NULL || b == NULL) {
        return 0;
    }
    ha = stat(a, &sa) == 0;
    hb = stat(b, &sb) == 0;
    if (ha && hb) {
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    }
    if (ha || hb) {
        return 0; /* one is there, the other is not */
    }
    /* neither is there yet: one name in one directory (`--strides s.csv
     * --json ./s.csv` would write both into one file, exit 0) */
    return split_dir(a, da, sizeof da, &ba) && split_dir(b, db, sizeof db, &bb) && strcmp(ba, bb) == 0 &&
           stat(da, &sa) == 0 && stat(db, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int hx_output_is_input(const char *cmd, const char *input, const hx_args_t *a, const char *const *outputs)
{
    int i, j;
    for (i = 0; outputs[i] != NULL; i++) {
        const char *out = hx_arg(a, outputs[i]);
        if (hx_same_file(input, out)) {
            hx_error(cmd, "%s: %s %s is the input itself (it would be overwritten)", input, outputs[i], out);
            return 1;
        }
    }
    /* two outputs on one file: the later one replaced the earlier without
     * a word (`replay LOG --out r.txt --json r.txt` left only the JSON,
     * exit 0) */
    for (i = 0; outputs[i] != NULL; i++) {
        const char *oi = hx_arg(a, outputs[i]);
        struct stat st;
        if (oi == NULL || (stat(oi, &st) == 0 && !S_ISREG(st.st_mode))) {
            continue; /* /dev/null twice discards both; a directory fails on its own */
        }
        for (j = i + 1; outputs[j] != NULL; j++) {
            const char *oj = hx_arg(a, outputs[j]);
            if (oj != NULL && (strcmp(oi, oj) == 0 || hx_same_file(oi, oj))) {
                hx_error(cmd, "%s %s and %s %s name the same file (one would overwrite the other)", outputs[i], oi,
                         outputs[j], oj);
                return 1;
            }
        }
    }
    return 0;
}

volatile sig_atomic_t hx_stop_sig = 0;
static char g_stop_msg[200];
static size_t g_stop_len;
/* the two signals' actions before hx_stop_on_signals (the default, or
 * ignored: nohup, a script's background job), set up before the handler
 * can run */
static struct sigaction g_stop_old_int, g_stop_old_term;

static void stop_handler(int sig)
{
    ssize_t w;
    hx_stop_sig = sig;
    /* a second signal of either kind ends the command at once (SA_RESETHAND
     * reset only the one delivered: SIGTERM then SIGINT went on) */
    (void)sigaction(SIGINT, &g_stop_old_int, NULL);
    (void)sigaction(SIGTERM, &g_stop_old_term, NULL);
    w = write(STDERR_FILENO, g_stop_msg, g_stop_len); /* async-signal-safe; nothing to do if stderr is gone */
    (void)w;
}

void hx_stop_off(void)
{
    (void)sigaction(SIGINT, &g_stop_old_int, NULL);
    (void)sigaction(SIGTERM, &g_stop_old_term, NULL);
}

void hx_stop_on_signals(const char *cmd, const char *how)
{
    struct sigaction sa;
    const int n = snprintf(g_stop_msg, sizeof g_stop_msg, "\n%s: stopping %s (a second signal quits at once)\n", cmd,
                           how);
    g_stop_len = n < 0 ? 0u : (size_t)n < sizeof g_stop_msg ? (size_t)n : sizeof g_stop_msg - 1u;
    (void)sigaction(SIGINT, NULL, &g_stop_old_int);
    (void)sigaction(SIGTERM, NULL, &g_stop_old_term);
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = stop_handler;
    /* SA_RESTART: the handler only sets hx_stop_sig, which the long loops
     * look at between runs and cases, so a write it lands in goes on (a
     * case's line to a terminal stopped by Ctrl-S or slow to take it: the
     * kernel's tty write waits for room). Interrupted, the write failed
     * with EINTR and stdio dropped what it held: the line of a case the
     * summary counts was lost (tests/cli/stop_tty.py). Nothing these
     * commands do under the handler waits for the signal to cut it short:
     * no read of a terminal or pipe, and pclose retries its wait. A second
     * signal still quits at once: the handler puts the actions before back. */
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    (void)sigaddset(&sa.sa_mask, SIGINT);
    (void)sigaddset(&sa.sa_mask, SIGTERM);
    /* a signal ignored when the command started stays ignored (it was
     * caught: `nohup`'s and a script's background job's) */
    if (g_stop_old_int.sa_handler != SIG_IGN) {
        (void)sigaction(SIGINT, &sa, NULL);
    }
    if (g_stop_old_term.sa_handler != SIG_IGN) {
        (void)sigaction(SIGTERM, &sa, NULL);
    }
}

FILE *hx_json_stdout = NULL;

/* argv[*i] is option `name`, as `name VALUE` or `name=VALUE` (hx_args_parse
 * reads both): 1 with *val set (NULL when a separate value is missing) and
 * *i on the last word used; else 0. */
static int opt_value(char **argv, int argc, int *i, const char *name, const char **val)
{
    const size_t len = strlen(name);
    if (strncmp(argv[*i], name, len) != 0) {
        return 0;
    }
    if (argv[*i][len] == '=') {
        *val = argv[*i] + len + 1;
        return 1;
    }
    if (argv[*i][len] != '\0') {
        return 0;
    }
    *val = *i + 1 < argc ? argv[++*i] : NULL;
    return 1;
}

int hx_json_stdout_claim(const char *cmd, int argc, char **argv)
{
    static const char *const k_other[] = { "--out", "--csv", "--strides" }; /* options whose '-' is standard output too */
    const char *json = NULL, *other[3] = { NULL, NULL, NULL }, *v;
    int i, k, fd;
    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--") == 0) {
            break; /* positional arguments only from here */
        }
        /* the last value of each counts, as for hx_arg(): `--json - --json F`
         * sent the command's text to standard error and the JSON to F */
        if (opt_value(argv, argc, &i, "--json", &v)) {
            json = v;
            continue;
        }
        for (k = 0; k < 3; k++) {
            if (opt_value(argv, argc, &i, k_other[k], &v)) {
                other[k] = v;
                break;
            }
        }
    }
    if (json == NULL || strcmp(json, "-") != 0) {
        /* allan's and psd's --out - is standard output as well, the CSV
         * alone there and their text on standard error, as with --json -,
         * not a file named '-'. replay, live and eval send their own text
         * aside for their --out -. */
        if (other[0] == NULL || strcmp(other[0], "-") != 0 ||
            (strcmp(cmd, "allan") != 0 && strcmp(cmd, "psd") != 0)) {
            return 0;
        }
    }
    for (k = 0; json != NULL && strcmp(json, "-") == 0 && k < 3; k++) {
        if (other[k] != NULL && strcmp(other[k], "-") == 0) {
            hx_error(cmd, "--json - and %s - cannot both write to standard output", k_other[k]);
            return -1;
        }
    }
    fflush(stdout);
    fd = dup(STDOUT_FILENO);
    hx_json_stdout = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (hx_json_stdout == NULL || dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
        hx_error(cmd, "%s -: cannot set up standard output (%s)", json != NULL && strcmp(json, "-") == 0 ? "--json" : "--out",
                 strerror(errno));
        return -1;
    }
    /* the text now goes to standard error beside the messages: a line at
     * a time (block-buffered, an error landed inside a table's line, and
     * the text of a run a signal stopped was lost) */
    (void)setvbuf(stdout, NULL, _IOLBF, 0);
    return 0;
}

int hx_json_failure(const char *cmd, int argc, char **argv)
{
    const char *json = NULL, *v;
    char line[2048], prefix[64], err[1024];
    cJSON *root;
    struct stat sj, sa;
    int i, rc, json_i = -1;
    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--") == 0) {
            break;
        }
        if (opt_value(argv, argc, &i, "--json", &v)) {
            json = v;
            json_i = i;
        }
    }
    if (json == NULL || json[0] == '\0' || g_json_written) {
        return 0;
    }
    if (strcmp(json, "-") == 0) {
        if (hx_json_stdout == NULL) {
            return 0; /* standard output never claimed (a usage error came first) */
        }
    } else if (stat(json, &sj) == 0) {
        /* never over a file the command line names otherwise (the input
         * given as --json too, when the input error came before that check) */
        for (i = 0; i < argc; i++) {
            if (i != json_i && stat(argv[i], &sa) == 0 && sa.st_dev == sj.st_dev && sa.st_ino == sj.st_ino) {
                return 0;
            }
        }
    }
    root = cJSON_CreateObject();
    if (root == NULL) {
        return -1;
    }
    (void)snprintf(prefix, sizeof prefix, "harness %s", cmd);
    hx_command_line(line, sizeof line, prefix, argc, argv);
    cJSON_AddStringToObject(root, "command", line);
    /* the key every command's JSON has for a run stopped by its input */
    cJSON_AddBoolToObject(root, "complete", 0);
    cJSON_AddStringToObject(root, "error", g_first_error[0] != '\0' ? g_first_error : "failed (see standard error)");
    rc = hx_write_json(json, root, err, sizeof err);
    cJSON_Delete(root);
    if (rc != 0) {
        hx_line_break();
        hx_eprintf("harness %s: error: %s\n", cmd, err);
    }
    return rc;
}

/* The length of the well-formed UTF-8 sequence at s (Unicode 3-7: no
 * overlong form, no surrogate, nothing above U+10FFFF), 0 when it is none. */
static size_t utf8_len(const unsigned char *s)
{
    const unsigned c = s[0];
    unsigned lo = 0x80u, hi = 0xBFu;
    size_t n, i;
    if (c < 0x80u) {
        return 1;
    }
    if (c >= 0xC2u && c <= 0xDFu) {
        n = 2;
    } else if (c >= 0xE0u && c <= 0xEFu) {
        n = 3;
        lo = c == 0xE0u ? 0xA0u : 0x80u;
        hi = c == 0xEDu ? 0x9Fu : 0xBFu;
    } else if (c >= 0xF0u && c <= 0xF4u) {
        n = 4;
        lo = c == 0xF0u ? 0x90u : 0x80u;
        hi = c == 0xF4u ? 0x8Fu : 0xBFu;
    } else {
        return 0;
    }
    for (i = 1; i < n; i++) {
        if (s[i] < (i == 1 ? lo : 0x80u) || s[i] > (i == 1 ? hi : 0xBFu)) {
            return 0;
        }
    }
    return n;
}

/* JSON text is UTF-8 (RFC 8259), but cJSON copies a string's bytes as they
 * are: a file name in Latin-1 would make the whole file unreadable to a
 * strict reader. Each byte outside a well-formed
 * sequence, which can only be inside a string, becomes \ufffd, the
 * replacement character. txt itself when it is clean; NULL: out of memory. */
static char *json_utf8(char *txt)
{
    const unsigned char *s = (const unsigned char *)txt;
    size_t i = 0, bad = 0, len = strlen(txt), o = 0, k;
    char *out;
    while (i < len) {
        k = utf8_len(s + i);
        bad += k == 0;
        i += k == 0 ? 1 : k;
    }
    if (bad == 0) {
        return txt;
    }
    out = malloc(len + 5 * bad + 1);
    if (out == NULL) {
        return NULL;
    }
    for (i = 0; i < len;) {
        k = utf8_len(s + i);
        if (k == 0) {
            memcpy(out + o, "\\ufffd", 6);
            o += 6;
            i++;
        } else {
            memcpy(out + o, txt + i, k);
            o += k;
            i += k;
        }
    }
    out[o] = '\0';
    return out;
}

FILE *hx_out_open(const char *path)
{
    if (strcmp(path, "-") == 0) {
        if (hx_json_stdout == NULL) {
            errno = EBADF;
        }
        return hx_json_stdout;
    }
    return fopen(path, "w");
}

int hx_out_close(FILE *f)
{
    const int failed = ferror(f);
    const int r = f == hx_json_stdout ? fflush(f) : fclose(f);
    return r != 0 || failed ? EOF : 0;
}

int hx_out_finish(const char *cmd, const char *path, FILE *f)
{
    if (hx_out_close(f) != 0) {
        /* the reason, as every other output's error gives it, not "write
         * failed" alone: errno of the failed write or close */
        char why[128];
        hx_error(cmd, "%s: write failed%s", strcmp(path, "-") == 0 ? "standard output" : path,
                 hx_errno_note(errno, why, sizeof why));
        return -1;
    }
    return 0;
}

/* `footnav_version` as the first key of the object `root` (not again when
 * it has one): added as cJSON adds, last, then moved to the front, with its
 * name. 0, or -1 out of memory. */
static int json_add_version(cJSON *root)
{
    cJSON *v;
    if (!cJSON_IsObject(root) || cJSON_HasObjectItem(root, "footnav_version")) {
        return 0;
    }
    if ((v = cJSON_AddStringToObject(root, "footnav_version", FNAV_VERSION_STRING)) == NULL) {
        return -1;
    }
    /* moved to the front: called as a statement, since cJSON < 1.7.13
     * returns void here and later versions a bool; it inserts at 0 or not
     * at all, so a version item not first is not in root: freed */
    v = cJSON_DetachItemViaPointer(root, v);
    cJSON_InsertItemInArray(root, 0, v);
    if (root->child != v) {
        cJSON_Delete(v);
        return -1;
    }
    return 0;
}

int hx_write_json(const char *path, struct cJSON *root, char *err, size_t err_size)
{
    const int to_stdout = strcmp(path, "-") == 0;
    char *txt = json_add_version(root) == 0 ? cJSON_Print(root) : NULL, *clean;
    FILE *f;
    int ok, e;
    if (txt != NULL && (clean = json_utf8(txt)) != txt) {
        free(txt);
        txt = clean;
    }
    if (txt == NULL) {
        snprintf(err, err_size, "%s: out of memory", path);
        return -1;
    }
    f = to_stdout ? hx_json_stdout : fopen(path, "w");
    if (f == NULL) {
        snprintf(err, err_size, "cannot write %s (%s)", path, to_stdout ? "standard output not claimed" : strerror(errno));
        free(txt);
        return -1;
    }
    /* the reason of the first failure said, as convert's (a full disk is
     * more than "cannot write FILE") */
    ok = fputs(txt, f) >= 0 && fputc('\n', f) != EOF;
    e = ok ? 0 : errno;
    if ((to_stdout ? fflush(f) : fclose(f)) != 0) {
        e = ok ? errno : e;
        ok = 0;
    }
    free(txt);
    g_json_written = 1; /* written or attempted: hx_json_failure adds nothing */
    if (!ok) {
        if (e != 0) {
            snprintf(err, err_size, "cannot write %s (%s)", path, strerror(e));
        } else {
            snprintf(err, err_size, "cannot write %s", path);
        }
        return -1;
    }
    return 0;
}

void hx_json_num(cJSON *o, const char *k, double v)
{
    if (isfinite(v)) {
        cJSON_AddNumberToObject(o, k, v);
    } else {
        cJSON_AddNullToObject(o, k);
    }
}

/* 0 when `path` can be opened for writing, else the errno the open would
 * give. Nothing is created or removed: a file made and removed again left
 * the target of a dangling symlink made and the link itself removed. */
static int writable_errno(const char *path)
{
    char cur[HX_PLOT_PATH_SIZE], link[HX_PLOT_PATH_SIZE];
    const char *slash;
    struct stat st;
    ssize_t n;
    size_t len;
    int fd, hops;
    if (*path == '\0') {
        return ENOENT;
    }
    if (strlen(path) >= sizeof cur) {
        return ENAMETOOLONG;
    }
    strcpy(cur, path);
    for (hops = 0;; hops++) {
        if (stat(cur, &st) == 0) {
            /* there: opened as the write opens it, without creating; a FIFO
             * only asked (an open and close hands its reader an end of file,
             * and the real write then waits for ever) */
            if (S_ISFIFO(st.st_mode)) {
                return access(cur, W_OK) == 0 ? 0 : errno;
            }
            if ((fd = open(cur, O_WRONLY | O_APPEND)) < 0) {
                return errno;
            }
            close(fd);
            return 0;
        }
        if (errno != ENOENT) {
            return errno;
        }
        /* a dangling symlink: the write creates its target */
        if ((n = readlink(cur, link, sizeof link - 1)) < 0) {
            break;
        }
        if (hops == 40) {
            return ELOOP;
        }
        link[n] = '\0';
        slash = strrchr(cur, '/');
        len = link[0] != '/' && slash != NULL ? (size_t)(slash - cur) + 1u : 0u;
        if (len + (size_t)n >= sizeof cur) {
            return ENAMETOOLONG;
        }
        memcpy(cur + len, link, (size_t)n + 1u);
    }
    /* not there: created in its directory */
    len = strlen(cur);
    if (cur[len - 1u] == '/') {
        return EISDIR;
    }
    slash = strrchr(cur, '/');
    if (slash == NULL) {
        strcpy(cur, ".");
    } else {
        cur[slash == cur ? 1 : slash - cur] = '\0';
    }
    return access(cur, W_OK | X_OK) == 0 ? 0 : errno;
}

int hx_check_writable(const char *cmd, const char *path)
{
    const int e = writable_errno(path);
    if (e != 0) {
        hx_error(cmd, "cannot write %s (%s)", path, strerror(e));
        return -1;
    }
    return 0;
}

int hx_check_outputs(const char *cmd, const hx_args_t *a, const char *const *files, const char *const *pngs)
{
    const char *v;
    for (; files != NULL && *files != NULL; files++) {
        if ((v = hx_arg(a, *files)) != NULL && strcmp(v, "-") != 0 && hx_check_writable(cmd, v) != 0) {
            return -1;
        }
    }
    for (; pngs != NULL && *pngs != NULL; pngs++) {
        if ((v = hx_arg(a, *pngs)) != NULL && hx_plot_check(cmd, v) != 0) {
            return -1;
        }
    }
    return 0;
}

/* ------------------------------------------------------------ plots */

const char *hx_gp_str(char *buf, size_t size, const char *s)
{
    size_t o = 0;
    if (size == 0) {
        return buf;
    }
    for (; *s != '\0' && o + 1 < size; s++) {
        if (*s == '\'') {
            if (o + 2 >= size) {
                break;
            }
            buf[o++] = '\'';
        }
        buf[o++] = (*s == '\n' || *s == '\r') ? ' ' : *s;
    }
    buf[o] = '\0';
    return buf;
}

size_t hx_text_char(const char *s, int *control)
{
    const unsigned char *u = (const unsigned char *)s;
    size_t n;
    *control = 0;
    if (u[0] == 0u) {
        return 0u; /* the terminating NUL is not a character */
    }
    if (u[0] < 0x20u || u[0] == 0x7fu) {
        *control = 1;
        return 1u;
    }
    n = utf8_len(u);
    if (n == 0u) {
        /* a byte of no well-formed character (Latin-1 text, a cut or
         * corrupted one): a raw 0x9B is CSI to a terminal of 8-bit
         * controls (the Linux console out of UTF-8 mode), and the bytes
         * after it may not be the text they seem */
        *control = 1;
        return 1u;
    }
    *control = n == 2u && u[0] == 0xc2u && u[1] <= 0x9fu; /* C1 in UTF-8, U+0080-U+009F */
    return n;
}

const char *hx_line_str(char *buf, size_t size, const char *s)
{
    size_t o = 0;
    if (size == 0) {
        return buf;
    }
    while (*s != '\0') {
        int ctl;
        const size_t k = hx_text_char(s, &ctl);
        if (o + (ctl ? 1u : k) >= size) {
            break; /* cut at a character's start */
        }
        if (ctl) {
            buf[o++] = '?';
        } else {
            memcpy(buf + o, s, k);
            o += k;
        }
        s += k;
    }
    buf[o] = '\0';
    return buf;
}

int hx_plot_have_gnuplot(const char *cmd, const char *png_path)
{
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        hx_error(cmd, "cannot draw %s: gnuplot is not installed (apt-get install gnuplot-nox)", png_path);
        return -1;
    }
    return 0;
}

/* 1 when `path` is there and is not a regular file: gnuplot writes into
 * whatever is there, and a device takes the picture (/dev/full: lost,
 * exit 0) */
static int not_a_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && !S_ISREG(st.st_mode);
}
#define NOT_A_FILE_MSG "cannot write %s: not a regular file (a picture is written to a file)"

int hx_plot_check(const char *cmd, const char *png_path)
{
    if (hx_plot_have_gnuplot(cmd, png_path) != 0) {
        return -1;
    }
    if (not_a_file(png_path)) {
        hx_error(cmd, NOT_A_FILE_MSG, png_path);
        return -1;
    }
    return hx_check_writable(cmd, png_path);
}

int hx_plot_rename_target(const char *cmd, const char *path, char *buf, size_t size)
{
    char real[PATH_MAX];
    struct stat st;
    const char *to = path;
    if (lstat(path, &st) == 0) {
        /* a rename replaces what is there: the file a symlink names is the
         * one to replace, and anything but a file is refused */
        if (S_ISLNK(st.st_mode) && realpath(path, real) != NULL && stat(real, &st) == 0) {
            to = real;
        }
        if (!S_ISREG(st.st_mode)) {
            hx_error(cmd, "cannot write %s: not a regular file%s (the picture is drawn beside it and renamed onto it)",
                     path, S_ISLNK(st.st_mode) ? " (a symbolic link to no file)" : "");
            return -1;
        }
    }
    if (strlen(to) >= size) {
        hx_error(cmd, "cannot write %.80s...: the path is longer than %d bytes", to, (int)size - 1);
        return -1;
    }
    strcpy(buf, to);
    return 0;
}

/* What tells a file apart from the same path rewritten: device, inode,
 * size, modification and status change times; 0 when it exists. */
static int file_sig(const char *path, long long sig[7])
{
    struct stat st;
    if (stat(path, &st) != 0) {
        return -1;
    }
    sig[0] = (long long)st.st_dev;
    sig[1] = (long long)st.st_ino;
    sig[2] = (long long)st.st_size;
    sig[3] = (long long)st.st_mtim.tv_sec;
    sig[4] = (long long)st.st_mtim.tv_nsec;
    sig[5] = (long long)st.st_ctim.tv_sec;
    sig[6] = (long long)st.st_ctim.tv_nsec;
    return 0;
}

/* a failed picture is a warning (hx_plot_failure_warns) */
static int g_plot_warns;

void hx_plot_failure_warns(int on)
{
    g_plot_warns = on;
}

/* a failed picture said: an error, or a warning for a command that goes
 * on (not "error: gnuplot failed ..." with exit 0, as eval would) */
static void plot_failed(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    char msg[HX_PLOT_PATH_SIZE + 200];
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (g_plot_warns) {
        hx_warn(cmd, "%s", msg);
    } else {
        hx_error(cmd, "%s", msg);
    }
}

int hx_plot_open(hx_plot_t *p, const char *cmd, const char *png_path, int w, int h)
{
    /* the path as a gnuplot string: a quote doubles (the path is not cut,
     * where a cut to 511 bytes here or to 1023 in the string would have
     * gnuplot write another file, or this one while the check below looks
     * for the cut name) */
    char q[2 * HX_PLOT_PATH_SIZE];
    memset(p, 0, sizeof *p);
    if (strlen(png_path) >= sizeof p->path) {
        hx_error(cmd, "cannot write %.80s...: the path is longer than %d bytes", png_path, HX_PLOT_PATH_SIZE - 1);
        return -1;
    }
    /* gnuplot writes the image to its standard output when it cannot open
     * the file: find out first, and keep its output away from ours (a
     * device there: eval's warning, as a picture gnuplot fails to draw) */
    if (not_a_file(png_path)) {
        plot_failed(cmd, NOT_A_FILE_MSG, png_path);
        return -1;
    }
    if (hx_plot_check(cmd, png_path) != 0) {
        return -1;
    }
    /* a file already there is gnuplot's to overwrite, not to remove when
     * gnuplot fails before it opens it (hx_plot_close) */
    p->existed = file_sig(png_path, p->before) == 0;
    p->gp = popen("gnuplot >/dev/null", "w");
    if (p->gp == NULL) {
        plot_failed(cmd, "cannot start gnuplot (%s)", strerror(errno));
        return -1;
    }
    snprintf(p->path, sizeof p->path, "%s", png_path);
    fprintf(p->gp, "set terminal pngcairo size %d,%d noenhanced font 'sans,10'\n", w, h);
    if (strpbrk(png_path, "\001\002\003\004\005\006\007\010\011\012\013\014\015\016\017\020\021\022\023\024\025\026"
                          "\027\030\031\032\033\034\035\036\037\177") != NULL) {
        /* a control character (a line break) has no place in a quoted
         * string, which takes it for a space: another file would be written,
         * and the check below would fail; a double-quoted one
         * with octal escapes names the file exactly */
        const char *c;
        fprintf(p->gp, "set output \"");
        for (c = png_path; *c != '\0'; c++) {
            const unsigned char u = (unsigned char)*c;
            if (u < 0x20u || u == 0x7fu) {
                fprintf(p->gp, "\\%03o", (unsigned)u);
            } else if (u == '\\' || u == '"') {
                fprintf(p->gp, "\\%c", (int)u);
            } else {
                fputc((int)u, p->gp);
            }
        }
        fprintf(p->gp, "\"\n");
    } else {
        fprintf(p->gp, "set output '%s'\n", hx_gp_str(q, sizeof q, png_path));
    }
    fprintf(p->gp, "set grid\n");
    return 0;
}

/* 1 when `path` is a regular file holding a whole PNG: its signature, and
 * the IEND chunk last. pngcairo exits 0 when its write fails (a full
 * disk): the picture is cut short and gnuplot's status says nothing. */
static int png_complete(const char *path)
{
    static const unsigned char k_sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
    static const unsigned char k_iend[12] = { 0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82 };
    unsigned char head[8], tail[12];
    struct stat st;
    FILE *f;
    int ok;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size < 20 || (f = fopen(path, "rb")) == NULL) {
        return 0;
    }
    ok = fread(head, 1, sizeof head, f) == sizeof head && memcmp(head, k_sig, sizeof head) == 0 &&
         fseek(f, -12L, SEEK_END) == 0 && fread(tail, 1, sizeof tail, f) == sizeof tail &&
         memcmp(tail, k_iend, sizeof tail) == 0;
    fclose(f);
    return ok;
}

int hx_plot_close(hx_plot_t *p, const char *cmd)
{
    int rc;
    if (p->gp == NULL) {
        return -1;
    }
    fprintf(p->gp, "unset output\n");
    rc = pclose(p->gp);
    p->gp = NULL;
    if (rc != 0 || !png_complete(p->path)) {
        /* gnuplot failed partway: a half-drawn picture is no result, not
         * to be left behind. Removed when this session
         * started it: new, or changed since hx_plot_open (gnuplot's set
         * output truncates the file in place); a file gnuplot never opened
         * (it failed before its set output) stays as it was. Only a
         * regular file is removed: through a symlink, the file it names. */
        long long now[7];
        int i, changed = 0;
        char real[PATH_MAX];
        const char *file = p->path;
        const char *why = rc == 0 && access(p->path, F_OK) == 0 ? " (the PNG is cut short: a full disk?)" : "";
        struct stat st;
        if (lstat(p->path, &st) == 0 && S_ISLNK(st.st_mode) && realpath(p->path, real) != NULL) {
            file = real;
        }
        if (stat(file, &st) == 0 && S_ISREG(st.st_mode) && file_sig(file, now) == 0) {
            for (i = 0; i < 7; i++) {
                changed |= !p->existed || now[i] != p->before[i];
            }
        }
        if (changed && remove(file) == 0) {
            plot_failed(cmd, "gnuplot failed to write %s%s; the partial file was removed", p->path, why);
        } else if (changed) {
            plot_failed(cmd, "gnuplot failed to write %s%s; the partial file could not be removed (%s)", p->path, why,
                        strerror(errno));
        } else {
            plot_failed(cmd, "gnuplot failed to write %s%s", p->path, why);
        }
        return -1;
    }
    return 0;
}

const char *hx_fmt_g(char *buf, size_t size, double v)
{
    if (isfinite(v)) {
        snprintf(buf, size, "%.6g", v);
    } else {
        snprintf(buf, size, "null");
    }
    return buf;
}

void hx_command_line(char *buf, size_t size, const char *prefix, int argc, char **argv)
{
    /* characters a POSIX shell takes as they are; an argument with any
     * other (a space, a quote, $, *) or none is single-quoted, a ' in it
     * written '\'' (joined bare, "--out a b.csv" would read back as two
     * arguments) */
    static const char k_plain[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./:=,+@%^-";
    size_t len = (size_t)snprintf(buf, size, "%s", prefix);
    int i;
    for (i = 0; i < argc && len < size; i++) {
        const char *s = argv[i];
        if (*s != '\0' && strspn(s, k_plain) == strlen(s)) {
            len += (size_t)snprintf(buf + len, size - len, " %s", s);
            continue;
        }
        len += (size_t)snprintf(buf + len, size - len, " '");
        for (; *s != '\0' && len < size; s++) {
            if (*s == '\'') {
                len += (size_t)snprintf(buf + len, size - len, "'\\''");
            } else {
                len += (size_t)snprintf(buf + len, size - len, "%c", *s);
            }
        }
        if (len < size) {
            len += (size_t)snprintf(buf + len, size - len, "'");
        }
    }
}

int hx_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double hx_quantile_sorted(const double *x, int n, double q)
{
    double h;
    int j;
    if (n < 1) {
        return (double)NAN;
    }
    h = (double)(n - 1) * (q < 0.0 ? 0.0 : (q > 1.0 ? 1.0 : q));
    j = (int)floor(h);
    if (j >= n - 1) {
        return x[n - 1];
    }
    return x[j] + (h - (double)j) * (x[j + 1] - x[j]);
}

double hx_median(double *v, int n)
{
    if (n <= 0) {
        return (double)NAN;
    }
    qsort(v, (size_t)n, sizeof *v, hx_cmp_double);
    return (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
