/* harness eval: every data set with ground truth in the shared data
 * directory through the navigation, figures written to docs/results.md
 * (docs/harness.md). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <cjson/cJSON.h>
#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_nav.h"
#include "hx_profile.h"
#include "hx_evplot.h"

/* Room for a row's note: a reader's or replay's message whole (HX_ERR_SIZE:
 * the path and the longest remedy, a stamps-in-bursts refusal's "convert it
 * to CSV ...") with eval's words around it ("input ends early (...): the
 * walk was read only in part"), so that a non-CSV log's bursts refusal
 * keeps its remedy (200 bytes for a note and 400 for a replay's message
 * would cut it). */
#define EV_NOTE_SIZE (HX_ERR_SIZE + 128)

static const hx_opt_t k_opts[] = {
    HX_NAV_OPTS(NULL),
    { "--data", "DIR", "shared data directory (default: $FNAV_DATA_DIR, ../shared/data)", 0 },
    { "--out", "FILE", "results in Markdown (default docs/results.md; '-' for standard output)", 0 },
    { "--json", "FILE", "also write the headline figures as JSON", 0 },
    { "--no-experiments", NULL, "skip the paper's experiments (bias model, 100 vs 200 Hz)", 0 },
    { "--plots", "DIR", "write the figures (PNG) here (default: img/ beside the --out file; none with --out -)", 0 },
    { "--no-plots", NULL, "no figures", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "eval", "[options]",
    "Run every data set with ground truth in the shared data directory through\n"
    "the navigation and write docs/results.md: closure on openshoe_gx2 and\n"
    "xio_ngimu_gait, per-stride error against the measured footprints and the\n"
    "motion capture of pyshoe_vicon_llio, stance detection and gait-event\n"
    "timing against the expert events of ipol_gait_xsens, and the paper's two\n"
    "experiments (AR(1) bias model on/off; 100 vs 200 Hz by resampling).",
    0, 0, k_opts
};

/* A file name in a data set folder (NAME_MAX is 255 on Linux). */
typedef char ev_name_t[256];

/* Room for the data directory's path, and for a path built on it: the
 * directory, a set's folder (pyshoe_vicon_llio/own_3dmgx5_footprints, 39
 * bytes), a file name (255) and the longest suffix eval adds
 * (_strides_gcp.csv), with room to spare. With 512 bytes for the directory
 * one of 561 would be cut and reported missing ("no shared data in" the
 * cut name, exit 4). */
#define EV_DATA_SIZE 1024
#define EV_DIR_SIZE (EV_DATA_SIZE + 64)  /* the directory and a set's folder */
#define EV_PATH_SIZE (EV_DIR_SIZE + 320) /* that, a file name and a suffix */

typedef struct {
    char data[EV_DATA_SIZE];
    fnav_nav_config_t cfg;
    FILE *md;
    int runs, failures;
    int main_failures; /* failures of the main runs, before the experiments (each failed walk once) */
    hx_progress_t prog;
    double total_runs;
    cJSON *json;
    int plots;            /* draw the figures (a directory and gnuplot are there) */
    char plot_dir[HX_PLOT_PATH_SIZE - 32]; /* where they go (room for "/eval-NAME.png" after it) */
    char plot_link[3 * HX_PLOT_PATH_SIZE]; /* the same as results.md links it (percent-encoded, md_link()) */
    hx_evplot_set_t fig;  /* the walks of the section being written */
    int ipol_fig;         /* eval-ipol.png was drawn (linked after the section's summary) */
    const char *unreadable[8]; /* data set folders there but not readable (their errno in unreadable_err) */
    int unreadable_err[8], n_unreadable;
} ev_t;

/* calloc that ends eval on exhaustion (the lists grow with the data). */
static void *ev_calloc(size_t n, size_t size)
{
    void *p = calloc(n > 0 ? n : 1, size);
    if (p == NULL) {
        hx_error("eval", "out of memory");
        exit(HX_EXIT_DATA);
    }
    return p;
}

static void *ev_realloc(void *p, size_t n, size_t size)
{
    void *q = n <= (size_t)-1 / size ? realloc(p, n * size) : NULL;
    if (q == NULL) {
        hx_error("eval", "out of memory");
        exit(HX_EXIT_DATA);
    }
    return q;
}

/* A growable list of numbers (the ipol event errors of every trial). */
typedef struct {
    double *v;
    int n, cap;
} ev_dvec_t;

static void dvec_push(ev_dvec_t *d, double x)
{
    if (d->n == d->cap) {
        d->cap = d->cap > 0 ? 2 * d->cap : 1024;
        d->v = (double *)ev_realloc(d->v, (size_t)d->cap, sizeof *d->v);
    }
    d->v[d->n++] = x;
}

static double maxv(const double *v, int n)
{
    double m = -INFINITY;
    int i;
    for (i = 0; i < n; i++) {
        m = v[i] > m ? v[i] : m;
    }
    return n > 0 ? m : (double)NAN;
}

static double pct_rank(double *v, int n, double p)
{
    int k;
    if (n <= 0) {
        return (double)NAN;
    }
    qsort(v, (size_t)n, sizeof *v, hx_cmp_double);
    k = (int)ceil(p / 100.0 * n) - 1;
    return v[k < 0 ? 0 : (k >= n ? n - 1 : k)];
}

/* A licence, source or readme file of a folder, not data: its name holds
 * "licen" (LICENSE.md, ISC_license.txt, LICENCE) or "readme", or starts
 * with "source", "copying" or "notice", in any case. */
static int doc_file(const char *name)
{
    char low[sizeof(ev_name_t)];
    size_t i;
    for (i = 0; name[i] != '\0' && i + 1 < sizeof low; i++) {
        low[i] = (char)(name[i] >= 'A' && name[i] <= 'Z' ? name[i] - 'A' + 'a' : name[i]);
    }
    low[i] = '\0';
    return strstr(low, "licen") != NULL || strstr(low, "readme") != NULL || strncmp(low, "source", 6) == 0 ||
           strncmp(low, "copying", 7) == 0 || strncmp(low, "notice", 6) == 0;
}

static int cmp_name(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

/* The suffix of nsuf in suf that name ends in (and is longer than), or -1. */
static int suffix_of(const char *name, const char *const *suf, int nsuf)
{
    size_t l = strlen(name);
    int k;
    for (k = 0; k < nsuf; k++) {
        size_t ls = strlen(suf[k]);
        if (l > ls && strcmp(name + l - ls, suf[k]) == 0) {
            return k;
        }
    }
    return -1;
}

/* The data files of a data set folder, sorted, however many (in *names, to
 * free()): names ending in one of the nsuf suffixes suf, without the
 * folder's licence, source and readme files. With stem, each name without
 * its suffix, once (a walk's IMU log and truth files, found from any of
 * them: a truth file without its log is a walk that failed, not one to
 * pass over). The count; 0 when dir does not exist, -1 with errno when
 * it cannot be read (no permission, not a directory: not taken for a set
 * that is absent). */
static int list_data(const char *dir, const char *const *suf, int nsuf, int stem, ev_name_t **names)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    size_t n = 0, cap = 0, i, k;
    *names = NULL;
    if (d == NULL) {
        return errno == ENOENT ? 0 : -1;
    }
    while ((e = readdir(d)) != NULL) {
        size_t l = strlen(e->d_name);
        int j = suffix_of(e->d_name, suf, nsuf);
        if (j >= 0 && l < sizeof **names && !doc_file(e->d_name)) {
            if (n == cap) {
                cap = cap > 0 ? 2 * cap : 64;
                *names = (ev_name_t *)ev_realloc(*names, cap, sizeof **names);
            }
            memcpy((*names)[n], e->d_name, l + 1); /* l < 256 checked above */
            if (stem) {
                (*names)[n][l - strlen(suf[j])] = '\0';
            }
            n++;
        }
    }
    closedir(d);
    if (n > 1) {
        qsort(*names, n, sizeof **names, cmp_name);
    }
    for (i = k = 0; i < n; i++) {
        if (k == 0 || strcmp((*names)[k - 1], (*names)[i]) != 0) {
            memmove((*names)[k++], (*names)[i], sizeof **names);
        }
    }
    return (int)k;
}

/* The walk files of a data set folder: names ending in suffix (list_data). */
static int list_walks(const char *dir, const char *suffix, ev_name_t **names)
{
    return list_data(dir, &suffix, 1, 0, names);
}

/* The data files of the data set folder sub (list_data), listed before
 * the run: one that cannot be read is warned about with the reason, kept
 * for its section ("cannot read", folder_unreadable()) and counted as a
 * failed run; it counts 0 files. */
static int list_set(ev_t *ev, const char *sub, const char *const *suf, int nsuf, int stem, ev_name_t **names)
{
    char dir[EV_DIR_SIZE];
    int n;
    snprintf(dir, sizeof dir, "%s/%s", ev->data, sub);
    n = list_data(dir, suf, nsuf, stem, names);
    if (n < 0) {
        const int err = errno;
        hx_warn("eval", "cannot read %s (%s): its walks are not evaluated", dir, strerror(err));
        if (ev->n_unreadable < (int)(sizeof ev->unreadable / sizeof ev->unreadable[0])) {
            ev->unreadable[ev->n_unreadable] = sub;
            ev->unreadable_err[ev->n_unreadable++] = err;
        }
        ev->failures++;
        n = 0;
    }
    return n;
}

/* A section's data set folder that could not be read (list_set): said in
 * results.md ("Cannot read DIR (reason)."), after lead; 1 when it was, 0
 * when the folder is one to say "No walks found" of. */
static int set_unreadable(const ev_t *ev, const char *sub)
{
    int i;
    for (i = 0; i < ev->n_unreadable; i++) {
        if (strcmp(ev->unreadable[i], sub) == 0) {
            return 1;
        }
    }
    return 0;
}

/* a followed by b (NULL: nothing) as a Markdown code span: delimited by
 * one backtick more than the longest run of backticks inside, and padded
 * with a space where the text starts or ends with one (CommonMark), so a
 * path or a command holding a backtick is one span, as it reads. */
static void md_code(FILE *f, const char *a, const char *b)
{
    const char *part[2];
    size_t run = 0, longest = 0, k;
    int i, pad;
    char first, last = '\0';
    part[0] = a;
    part[1] = b != NULL ? b : "";
    first = a[0] != '\0' ? a[0] : part[1][0];
    for (i = 0; i < 2; i++) {
        const char *c;
        for (c = part[i]; *c != '\0'; c++) {
            run = *c == '`' ? run + 1 : 0;
            longest = run > longest ? run : longest;
            last = *c;
        }
    }
    pad = first == '`' || last == '`' || (first == ' ' && last == ' '); /* CommonMark strips one space each side */
    for (k = 0; k <= longest; k++) {
        fputc('`', f);
    }
    fprintf(f, "%s%s%s%s", pad ? " " : "", part[0], part[1], pad ? " " : "");
    for (k = 0; k <= longest; k++) {
        fputc('`', f);
    }
}

static int folder_unreadable(ev_t *ev, const char *sub, const char *lead)
{
    int i;
    for (i = 0; i < ev->n_unreadable; i++) {
        if (strcmp(ev->unreadable[i], sub) == 0) {
            char sub_path[EV_PATH_SIZE];
            snprintf(sub_path, sizeof sub_path, "/%s", sub);
            fprintf(ev->md, "%sCannot read ", lead);
            md_code(ev->md, ev->data, sub_path);
            fprintf(ev->md, " (%s): its walks are not evaluated.\n\n", strerror(ev->unreadable_err[i]));
            return 1;
        }
    }
    return 0;
}

/* The files of a data set folder that eval does not read (no data file's
 * suffix, not a licence, source or readme file, not hidden): each warned
 * about and named under the section, so that a walk under an unexpected
 * name is not passed over in silence. They do not fail the run. */
static void unread_files(ev_t *ev, const char *sub, const char *const *suf, int nsuf)
{
    ev_name_t *names = NULL;
    char dir[EV_DIR_SIZE];
    DIR *d;
    struct dirent *e;
    size_t n = 0, cap = 0, i;
    int k;
    snprintf(dir, sizeof dir, "%s/%s", ev->data, sub);
    d = opendir(dir);
    if (d == NULL) {
        return;
    }
    while ((e = readdir(d)) != NULL) {
        char path[EV_PATH_SIZE];
        struct stat sb;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (e->d_name[0] == '.' || doc_file(e->d_name) || suffix_of(e->d_name, suf, nsuf) >= 0 ||
            stat(path, &sb) != 0 || !S_ISREG(sb.st_mode) || strlen(e->d_name) >= sizeof *names) {
            continue;
        }
        if (n == cap) {
            cap = cap > 0 ? 2 * cap : 16;
            names = (ev_name_t *)ev_realloc(names, cap, sizeof *names);
        }
        snprintf(names[n++], sizeof *names, "%s", e->d_name);
    }
    closedir(d);
    if (n == 0) {
        return;
    }
    qsort(names, n, sizeof *names, cmp_name);
    fprintf(ev->md, "Not read (no name of this set's data files, `*");
    for (k = 0; k < nsuf; k++) {
        fprintf(ev->md, "%s%s", k > 0 ? "`, `*" : "", suf[k]);
    }
    fprintf(ev->md, "`):");
    for (i = 0; i < n; i++) {
        hx_warn("eval", "%s/%s: not read: no name of this set's data files", dir, names[i]);
        fprintf(ev->md, "%s `%s`", i > 0 ? "," : "", names[i]);
    }
    fprintf(ev->md, ".\n\n");
    free(names);
}

/* 1 when path names a regular file (or a link to one). */
static int is_file(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0 && S_ISREG(sb.st_mode);
}

/* A reader's or replay's message without the file's path in front of it
 * (the table names the file): "PATH:LINE: what" becomes "line LINE: what". */
static const char *after_path(const char *msg, const char *path, char *buf, size_t size)
{
    size_t lp = strlen(path);
    if (strncmp(msg, path, lp) != 0 || msg[lp] != ':') {
        return msg;
    }
    msg += lp + 1;
    if (*msg >= '0' && *msg <= '9') {
        snprintf(buf, size, "line %s", msg);
        return buf;
    }
    return *msg == ' ' ? msg + 1 : msg;
}

/* A walk's name as a Markdown table cell: '|' escaped, a control character
 * (a line break in a file name) as '?'. Written as it is, a name holding
 * '|' would make its row one cell wider than its
 * table. out needs 2 * strlen(name) + 1 bytes (EV_CELL_SIZE for a file
 * name). */
#define EV_CELL_SIZE (2 * sizeof(ev_name_t) + 64)
static const char *md_cell(const char *name, char *out, size_t size)
{
    size_t o = 0;
    while (*name != '\0') {
        int ctl;
        const size_t k = hx_text_char(name, &ctl);
        if (*name == '|' && o + 2 < size) {
            out[o++] = '\\';
            out[o++] = '|';
        } else if (ctl && o + 1 < size) {
            out[o++] = '?';
        } else if (!ctl && *name != '|' && o + k < size) {
            memcpy(out + o, name, k); /* a character whole, not cut */
            o += k;
        } else {
            break;
        }
        name += k;
    }
    out[o] = '\0';
    return out;
}

/* A failed run: warned with its path, counted (eval's exit status and the
 * targets' note) and its reason kept for the row of its table. A fault
 * warned about already (the same file, the same reason) is not warned
 * again, by eval's once-per-process warnings (hx_warn_once): an events
 * file's fault that both feet's rows give (one foot's events missing or not
 * pairs: that foot's and the other foot's run fail on it), a walk that fails
 * each experiment's repeat as its main run (a warning per failed run would
 * be twice per events file, up to eleven times per walk). */
static void fail(ev_t *ev, const char *path, char *why, size_t why_size, const char *msg)
{
    char buf[HX_ERR_SIZE];
    const char *reason = after_path(msg, path, buf, sizeof buf);
    size_t i, o;
    hx_warn("eval", "%s: %s", path, reason);
    ev->failures++;
    if (why == NULL) {
        return;
    }
    /* for the row's cell: '|' escaped, as a name (md_cell(); not '/',
     * which would name another file: "cannot open 1/1.json" for
     * 1|1.json), a line break '/' */
    for (i = o = 0; reason[i] != '\0' && o + 2 < why_size; i++) {
        if (reason[i] == '|') {
            why[o++] = '\\';
            why[o++] = '|';
        } else {
            why[o++] = reason[i] == '\n' ? '/' : reason[i];
        }
    }
    why[o] = '\0';
}

/* The row of a walk that gave no figures, when its table is written: a
 * dash in each of its ncol figure columns and the reason in the last. name
 * is its first cell(s), written as given (md_cell()). */
static void not_run_row(const ev_t *ev, int write, const char *name, int ncol, const char *why)
{
    int i;
    if (!write) {
        return;
    }
    fprintf(ev->md, "| %s |", name);
    for (i = 0; i < ncol; i++) {
        fputs(" - |", ev->md);
    }
    fprintf(ev->md, " not run: %s |\n", why);
}

/* Append "; what" (or "what" to an empty note). */
static void note_add(char *note, size_t size, const char *what)
{
    size_t len = strlen(note);
    snprintf(note + len, size - len, "%s%s", len > 0 ? "; " : "", what);
}

/* One replay; 0 ok (a cut-off last line accepted with a note), -1 failure
 * (its reason in note). axes: run the axes check (the tables' replays; the
 * experiments' repeat the same walks and would spend half of eval's time on
 * it). */
static int replay(ev_t *ev, const char *path, const fnav_nav_config_t *cfg, double rate_hz, int axes, hx_traj_t *t,
                  hx_nav_summary_t *s, char *note, size_t note_size)
{
    char err[HX_ERR_SIZE], buf[HX_ERR_SIZE];
    int rc = hx_nav_replay("eval", path, HX_FMT_AUTO, 0.0, cfg, rate_hz, NULL, t, axes ? HX_REPLAY_AXES : 0u, err,
                           sizeof err);
    ev->runs++;
    hx_progress_update(&ev->prog, (double)ev->runs);
    note[0] = '\0';
    if (rc < 0 || rc == 2 || t->n == 0) { /* 2: not in SI units */
        fail(ev, path, note, note_size, err);
        hx_traj_free(t);
        return -1;
    }
    if (rc == 1) {
        /* a line the reader could not take (malformed, NaN, ...) stopped
         * the walk: only the part before it was navigated, and its figures
         * (a closure of a walk read to a third, a final-stride error of a
         * stride in the middle) are not the walk's. A failed run, as a log
         * that cannot be read at all (warned and counted in the exit
         * status, the part not judged against the targets), not a note in
         * the row only */
        char why[EV_NOTE_SIZE];
        snprintf(why, sizeof why, "input ends early (%s): the walk was read only in part",
                 after_path(err, path, buf, sizeof buf));
        fail(ev, path, note, note_size, why);
        hx_traj_free(t);
        return -1;
    }
    if (rc == 3) {
        /* read to its end, never aligned: replay's reason (no still period,
         * or time stamps that never advance), not "no still period at the
         * start" for both */
        char why[EV_NOTE_SIZE];
        snprintf(why, sizeof why, "the filter never aligned: %s", after_path(err, path, buf, sizeof buf));
        fail(ev, path, note, note_size, why);
        hx_traj_free(t);
        return -1;
    }
    if (t->cut_lines > 0) {
        /* the reader's warning, in the row: the recording was cut off
         * mid-write (a walk cut short is no closed loop) */
        note_add(note, note_size, "last line cut off mid-write: not read");
    }
    if (!t->aligned) {
        /* no still period: no navigation to evaluate (its figures are NaN) */
        fail(ev, path, note, note_size, "the filter never aligned (no still period at the start)");
        hx_traj_free(t);
        return -1;
    }
    if (t->axes.problem) {
        /* a statistical verdict (hx_axes.h): noted in the walk's row, not a failure */
        snprintf(buf, sizeof buf, "gyro axes do not match the accelerometer's (fits as %s)", t->axes.best_map);
        note_add(note, note_size, buf);
    }
    if (t->axes.time_problem) {
        snprintf(buf, sizeof buf, "the sample rate looks wrong (swings fit with intervals x%g)", t->axes.time_scale);
        note_add(note, note_size, buf);
    }
    hx_nav_summarize(t, s);
    if (s->before_align_s > HX_NAV_LATE_ALIGN_S) {
        /* replay's note: a log that starts moving; its start is not in the
         * figures (said in the row) */
        snprintf(buf, sizeof buf, "%.1f s of motion before the alignment: not navigated", s->before_align_s);
        note_add(note, note_size, buf);
    }
    if (s->rate_off_fraction > 0.0) {
        /* replay's note: the detector keeps the first rate (docs/navigation.md, "Timing") */
        snprintf(buf, sizeof buf, "sample rate changes to %.1f Hz from %.1f s (%.0f %% of the log off the detector's "
                 "%.1f Hz)", s->rate_change_hz, s->rate_change_at_s, 100.0 * s->rate_off_fraction, t->rate_hz);
        note_add(note, note_size, buf);
    }
    return 0;
}

/* A judged walk must give a closure: with no stride (no motion the
 * detector took for a step) its "return to the start" is zero by
 * construction, not a result. Counted as a failed run; 1 (after freeing t)
 * when it is one. (A walk that never aligned has failed in replay().) */
static int no_closure(ev_t *ev, const char *path, const hx_nav_summary_t *s, hx_traj_t *t, char *note,
                      size_t note_size)
{
    if (s->strides > 0 && s->path_m > 0.0) {
        return 0;
    }
    fail(ev, path, note, note_size, "no stride detected: no closure to judge");
    hx_traj_free(t);
    return 1;
}

static void fmt_name(char *out, size_t size, const char *name, const char *strip)
{
    const char *p = strstr(name, strip);
    snprintf(out, size, "%.*s", p ? (int)(p - name) : (int)strlen(name), name);
}

/* The data files of the sets whose walks have more than one: the IMU log
 * first. */
static const char *const k_fp_files[3] = { "_imu.csv", "_strides_gcp.csv", "_gcp_wcf_measured.csv" };
static const char *const k_vicon_files[2] = { "_imu.csv", "_strides_gcp.csv" };
static const char *const k_ipol_files[3] = { ".json", "_lf.txt", "_rf.txt" };
static const char *const k_gx2_files[1] = { "_data_inert.txt" };
static const char *const k_csv_files[1] = { ".csv" };
static const char *const k_txt_files[1] = { ".txt" };

/* ------------------------------------------------------------ closure */

typedef struct {
    double h_pct_med, d3_pct_med, d3_pct_max, vert_med, h_m_med, path_med;
    int n, files; /* walks with a result, walk files found */
} closure_t;

/* A per-walk figure for the paired comparisons (walk: NULL, or set to a
 * calloc'd array of one value per walk file, in the list's order, NaN
 * where the walk gave no result; the caller frees it). */
static double *walk_values(double **walk, int n)
{
    int i;
    if (walk == NULL) {
        return NULL;
    }
    *walk = (double *)ev_calloc(n > 0 ? (size_t)n : 1u, sizeof **walk);
    for (i = 0; i < n; i++) {
        (*walk)[i] = (double)NAN;
    }
    return *walk;
}

static void closure_set(ev_t *ev, const char *sub, const char *suffix, const fnav_nav_config_t *cfg, double rate_hz,
                        int write, closure_t *out, double **walk)
{
    char dir[EV_DIR_SIZE], path[EV_PATH_SIZE], note[EV_NOTE_SIZE], nm[256], cell[EV_CELL_SIZE];
    ev_name_t *names;
    double *h, *d3, *vz, *hm, *pm, *wv;
    int n, i, k = 0;
    snprintf(dir, sizeof dir, "%s/%s", ev->data, sub);
    n = list_walks(dir, suffix, &names);
    n = n < 0 ? 0 : n; /* cannot be read: warned before the run (list_set) */
    wv = walk_values(walk, n);
    h = (double *)ev_calloc(5 * (size_t)n, sizeof *h);
    d3 = h + n;
    vz = d3 + n;
    hm = vz + n;
    pm = hm + n;
    if (write) {
        fprintf(ev->md, "| walk | path (m) | horizontal (m) | horizontal (%%) | 3-D (m) | 3-D (%%) | "
                        "vertical (m) | heading change (deg) | strides | note |\n");
        fprintf(ev->md, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    }
    for (i = 0; i < n; i++) {
        hx_traj_t t;
        hx_nav_summary_t s;
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        fmt_name(nm, sizeof nm, names[i], suffix);
        md_cell(nm, cell, sizeof cell);
        if (replay(ev, path, cfg, rate_hz, write, &t, &s, note, sizeof note) != 0 ||
            no_closure(ev, path, &s, &t, note, sizeof note)) {
            not_run_row(ev, write, cell, 8, note);
            continue;
        }
        if (write) {
            fprintf(ev->md, "| %s | %.2f | %.3f | %.2f | %.3f | %.2f | %+.3f | %+.1f | %ld | %s |\n", cell, s.path_m,
                    s.end_h_m, s.end_h_pct, s.end_3d_m, s.end_3d_pct, s.vertical_m, s.heading_change_deg, s.strides,
                    note);
            if (ev->plots) {
                hx_evplot_add_path(&ev->fig, nm, &t);
            }
        }
        if (wv != NULL) {
            wv[i] = s.end_h_pct;
        }
        h[k] = s.end_h_pct;
        d3[k] = s.end_3d_pct;
        vz[k] = s.vertical_m;
        hm[k] = s.end_h_m;
        pm[k] = s.path_m;
        k++;
        hx_traj_free(&t);
    }
    out->n = k;
    out->files = n;
    out->d3_pct_max = maxv(d3, k);
    out->h_pct_med = hx_median(h, k);
    out->d3_pct_med = hx_median(d3, k);
    out->vert_med = hx_median(vz, k);
    out->h_m_med = hx_median(hm, k);
    out->path_med = hx_median(pm, k);
    free(h);
    free(names);
}

/* ------------------------------------------------------------ xio and other closed walks */

/* The vendor's published 3-D closure of its two walks (x-io Gait-Tracking
 * README), m; NaN for a walk without one. */
static double xio_vendor_m(const char *name)
{
    if (strcmp(name, "short_walk.csv") == 0) {
        return 0.082;
    }
    if (strcmp(name, "long_walk.csv") == 0) {
        return 0.421;
    }
    return (double)NAN;
}

/* Closure of one walk (last stance mid-point from the first), m; NaN when
 * the replay failed, or, for a judged walk (openshoe_gx2's and xio's
 * sections), when it has no stride (no_closure). The other closed walks
 * are reported, not judged, in their table and in the rate experiment
 * alike (judged in the experiment, a walk without a stride would be two
 * failed runs, exit 1). */
static double closure_3d_m(ev_t *ev, const char *path, const fnav_nav_config_t *cfg, double rate_hz, int judged)
{
    hx_traj_t t;
    hx_nav_summary_t s;
    char note[EV_NOTE_SIZE];
    if (replay(ev, path, cfg, rate_hz, 0, &t, &s, note, sizeof note) != 0 ||
        (judged && no_closure(ev, path, &s, &t, note, sizeof note))) {
        return (double)NAN;
    }
    hx_traj_free(&t);
    return s.end_3d_m;
}

/* ------------------------------------------------------------ strides */

#define GCP_MAX 1024

typedef struct {
    int n;
    long idx[GCP_MAX];
    double x[GCP_MAX], y[GCP_MAX];
    int bad; /* rows that are not strideIndex, _, x, y with finite numbers */
    long bad_line; /* the first such row's line number (1 = the file's first line) */
    char bad_text[160]; /* and its text, printable (hx_line_str), cut (a row is about 100 characters) */
    long idx_lo, idx_hi; /* the lowest and highest stride index read, as in the file (before any resampling) */
    int cut; /* a last line without its newline (cut off), not read */
    long cut_line; /* its line number */
    char cut_text[160]; /* and its text, printable (hx_line_str), cut */
} gcp_t;

/* The n numbers of a truth row, separated by commas, blanks around them
 * allowed: 0, or -1 for anything else. sscanf's "%lf,%lf,%lf,%lf" took the
 * number before junk in a field (a y of 6"x"02e-01 as 6, a stride index of
 * 2.685e as 3) and read a row of five fields shifted (its timestamp as x):
 * a mutated truth file scored a walk against a footprint 2e16 m away that
 * way, exit 0. */
static int truth_row(const char *line, double *v, int n)
{
    const char *p = line;
    int i;
    for (i = 0; i < n; i++) {
        p += strspn(p, " \t");
        if (hx_scan_number(p, &p, &v[i]) != 0) {
            return -1;
        }
        p += strspn(p, " \t");
        if (i + 1 < n && *p++ != ',') {
            return -1;
        }
    }
    return p[strspn(p, " \t\r\n")] == '\0' ? 0 : -1;
}

/* 1 when fgets filled line (size bytes) without reaching the end of the
 * line, whose rest is then skipped: a long line is one row. Not the missing
 * newline alone, which a NUL byte in the line also gives: the next line would
 * go with it. */
static int skip_long_line(FILE *f, const char *line, size_t size)
{
    const size_t len = strlen(line);
    int c;
    if (len + 1u < size || line[len - 1u] == '\n') {
        return 0;
    }
    while ((c = getc(f)) != EOF && c != '\n') {
    }
    return 1;
}

/* The strides of a _strides_gcp.csv truth file (strideIndex, ..., x, y);
 * 0, or -1 with the reason in why. */
static int read_gcp(const char *path, gcp_t *g, char *why, size_t why_size)
{
    FILE *f = fopen(path, "r");
    char line[512];
    long row = 0;
    g->n = g->bad = g->cut = 0;
    g->idx_lo = g->idx_hi = 0;
    g->bad_line = g->cut_line = 0;
    g->bad_text[0] = g->cut_text[0] = '\0';
    if (f == NULL) {
        snprintf(why, why_size, "no truth file %.160s", strrchr(path, '/') ? strrchr(path, '/') + 1 : path);
        return -1;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        double v[4];
        /* a position beyond FNAV_INPUT_MAX_ABS (1e6 m, the log readers'
         * bound on any value in SI units) is no footprint: x of -7e42 would
         * make a path of 1.4e43 m and a final error of 0.00 % */
        int ok = truth_row(line, v, 4) == 0 && fabs(v[2]) <= FNAV_INPUT_MAX_ABS && fabs(v[3]) <= FNAV_INPUT_MAX_ABS;
        size_t k = strspn(line, " \t\r\n");
        if (skip_long_line(f, line, sizeof line)) {
            /* a line longer than the buffer (no truth row is) is one
             * unreadable row: each 511 characters of it were a row, and the
             * tail of 1.1e+03x000...0,5.7,-4.0,-0.2 a stride at sample 0 */
            ok = 0;
        }
        if (row++ == 0 && !ok) {
            continue; /* the header (a file without one starts with its first stride) */
        }
        if (strchr(line, '\n') == NULL && feof(f)) {
            /* the last line without its newline: the file was cut off, and
             * the cut may have shortened the y it ends in (-0.5529 read as
             * -5.529): not read, as the log reader's last line */
            g->cut = line[k] != '\0';
            if (g->cut) {
                /* its line and text, for the warning below */
                line[strcspn(line, "\r")] = '\0';
                g->cut_line = row;
                (void)hx_line_str(g->cut_text, sizeof g->cut_text, line);
            }
            break;
        }
        if (!ok) {
            if (line[k] != '\0' && g->bad++ == 0) {
                /* the first one's line and text, for the warning below */
                line[strcspn(line, "\r\n")] = '\0';
                g->bad_line = row;
                (void)hx_line_str(g->bad_text, sizeof g->bad_text, line);
            }
            continue; /* blank lines are no rows */
        }
        if (g->n == GCP_MAX) {
            fclose(f);
            snprintf(why, why_size, "truth file has more than %d strides", GCP_MAX);
            return -1;
        }
        g->idx[g->n] = (long)llround(v[0]);
        if (g->n == 0 || g->idx[g->n] < g->idx_lo) {
            g->idx_lo = g->idx[g->n];
        }
        if (g->n == 0 || g->idx[g->n] > g->idx_hi) {
            g->idx_hi = g->idx[g->n];
        }
        g->x[g->n] = v[2];
        g->y[g->n] = v[3];
        g->n++;
    }
    fclose(f);
    if (g->bad > 0) {
        /* said on standard error as well as in the walk's row (a user of
         * eval reads its warnings, not each row's note); printed once in
         * eval's once-per-process mode, however many runs read the file */
        hx_warn("eval",
                "%s:%ld: %d unreadable truth row%s ignored (the first here: '%s'): a row is strideIndex, _, x, y, "
                "four finite numbers with x and y within 1e6 m; the strides of those rows are not scored",
                path, g->bad_line, g->bad, g->bad == 1 ? "" : "s", g->bad_text);
    }
    if (g->cut) {
        /* the same for the cut last line (only the walk's note said so),
         * once per file as above */
        hx_warn("eval",
                "%s:%ld: truth's last line cut off (no newline): not read ('%s': the cut may have shortened "
                "the y it ends in); the stride of that row is not scored",
                path, g->cut_line, g->cut_text);
    }
    if (g->n < 2) {
        /* "1 readable stride rows" read wrongly */
        snprintf(why, why_size, "truth file has %d readable stride row%s (strideIndex, _, x, y), 2 needed", g->n,
                 g->n == 1 ? "" : "s");
        return -1;
    }
    return 0;
}

typedef struct {
    double stride_err_med, final_err, path, final_pct, rms;
    int strides;
    int skipped;  /* strides whose sample lies outside the trajectory */
    int no_truth; /* strides without a truth position (motion capture lost) */
    double truth_end_gap_s; /* log time after the truth's last stride (0 when beyond the log) */
    int pre_align; /* truth strides (the reference included) before the alignment with a step between */
} stride_res_t;

/* A truth that ends this long before the log leaves the walk's end unscored:
 * said in the row's note (the shared footprint truths end on the log's last
 * sample) */
#define TRUTH_END_GAP_NOTE_S 5.0

/* Per-stride horizontal error in the truth's frame, which is the initial
 * heading frame of the IMU (as footnav's n frame: x along the initial
 * heading): both start at the first stride position, so the first stride
 * is the reference, its error zero by construction, and the statistics
 * count the strides after it. The path runs up to the last stride with an
 * estimate. */
/* Whether the frame at sample k was navigated: aligned, or before the
 * alignment but in the still period it ended (no frame out of stance between
 * k and the first aligned frame, so the foot stood where the navigation
 * starts). A truth stride before that, with a step between (a log that
 * starts walking: the filter aligns in a later stance), has no estimate: its
 * frames hold position 0, and it is scored against the aligned start. */
static int navigated(const hx_traj_t *t, size_t k)
{
    size_t j;
    for (j = k; j < t->n; j++) {
        if (t->f[j].flags & FNAV_FRAME_ALIGNED) {
            return 1;
        }
        if (!(t->f[j].flags & FNAV_FRAME_STANCE)) {
            return 0;
        }
    }
    return 0;
}

static int stride_errors(const hx_traj_t *t, const gcp_t *g, stride_res_t *r)
{
    double e[GCP_MAX], se2 = 0.0, path = 0.0;
    double x0, y0;
    int i, n = 0, prev = 0;
    long i0 = g->idx[0];
    r->path = 0.0;
    r->skipped = r->no_truth = r->pre_align = 0;
    if (i0 < 0 || (size_t)i0 >= t->n || !isfinite(g->x[0]) || !isfinite(g->y[0])) {
        return -1;
    }
    for (i = 0; i < g->n; i++) {
        /* the truth strides (with a sample in the log) the filter did not
         * navigate, for the row's note; scored as before */
        if (g->idx[i] >= 0 && (size_t)g->idx[i] < t->n && !navigated(t, (size_t)g->idx[i])) {
            r->pre_align++;
        }
    }
    x0 = (double)t->f[i0].pos_m[0];
    y0 = (double)t->f[i0].pos_m[1];
    for (i = 1; i < g->n; i++) {
        long k = g->idx[i];
        double dx, dy;
        if (!isfinite(g->x[i]) || !isfinite(g->y[i])) {
            /* the path runs from the stride before to the next with a position */
            if (k < 0 || (size_t)k >= t->n) {
                r->skipped++;
            } else {
                r->no_truth++;
            }
            continue;
        }
        path += hypot(g->x[i] - g->x[prev], g->y[i] - g->y[prev]);
        prev = i;
        if (k < 0 || (size_t)k >= t->n) {
            r->skipped++;
            continue;
        }
        dx = ((double)t->f[k].pos_m[0] - x0) - (g->x[i] - g->x[0]);
        dy = ((double)t->f[k].pos_m[1] - y0) - (g->y[i] - g->y[0]);
        e[n] = sqrt(dx * dx + dy * dy);
        se2 += e[n] * e[n];
        r->final_err = e[n];
        r->path = path;
        n++;
    }
    r->strides = n;
    r->truth_end_gap_s = 0.0;
    if (g->n > 0 && t->n > 0 && g->idx[g->n - 1] >= 0 && (size_t)g->idx[g->n - 1] < t->n) {
        r->truth_end_gap_s = 1e-9 * (double)(t->f[t->n - 1].t_ns - t->f[g->idx[g->n - 1]].t_ns);
    }
    r->rms = n > 0 ? sqrt(se2 / n) : (double)NAN;
    r->stride_err_med = hx_median(e, n);
    r->final_pct = r->path > 0.0 ? 100.0 * r->final_err / r->path : (double)NAN;
    return n > 0 ? 0 : -1;
}

typedef struct {
    double final_pct_med, final_pct_mean, stride_med, final_m_med;
    int n, files; /* walks with a result, IMU files found */
} fp_t;

/* stride_errors' failure as a reason, with the spans that tell why: the
 * log's replayed and its truth's strides (in the file's sample indices and
 * in s at the log's rate, the same in a resampled run, whose repeat of the
 * warning is then not printed again), and how many strides lie inside with
 * a position, the first (the reference) among them or not. The bare phrase
 * gave no number to check a truth of another walk or a log cut short by. */
static void no_strides(ev_t *ev, const char *path, const hx_traj_t *t, const gcp_t *g, char *why, size_t why_size)
{
    char msg[HX_ERR_SIZE];
    const double rate = t->in_rate_hz > 0.0 ? t->in_rate_hz : t->rate_hz; /* the log's own */
    const double span_s = t->n > 1 ? 1e-9 * (double)(t->f[t->n - 1].t_ns - t->f[0].t_ns) : 0.0;
    int i, in = 0, first_in = 0;
    for (i = 0; i < g->n; i++) {
        if (g->idx[i] >= 0 && (size_t)g->idx[i] < t->n && isfinite(g->x[i]) && isfinite(g->y[i])) {
            in++;
            first_in |= i == 0;
        }
    }
    snprintf(msg, sizeof msg,
             "fewer than 2 truth strides with a position fall inside the replayed samples: the log replayed spans "
             "%.1f s, its truth's %d strides samples %ld to %ld (%.1f to %.1f s at the log's %.4g Hz), %d of them "
             "inside it with a position, the first (the reference) %s: is the truth file another walk's, or the log "
             "cut short?",
             span_s, g->n, g->idx_lo, g->idx_hi, rate > 0.0 ? (double)g->idx_lo / rate : 0.0,
             rate > 0.0 ? (double)g->idx_hi / rate : 0.0, rate, in, first_in ? "among them" : "not among them");
    fail(ev, path, why, why_size, msg);
}

/* The strides a walk's figures leave out, and the truth rows not read, in
 * its row's note. */
static void stride_notes(char *note, size_t size, const gcp_t *g, const stride_res_t *r)
{
    char buf[120];
    if (r->skipped > 0) {
        snprintf(buf, sizeof buf, "%d stride%s outside the log not scored", r->skipped, r->skipped == 1 ? "" : "s");
        note_add(note, size, buf);
    }
    if (r->no_truth > 0) {
        snprintf(buf, sizeof buf, "%d stride%s without a truth position not scored", r->no_truth,
                 r->no_truth == 1 ? "" : "s");
        note_add(note, size, buf);
    }
    if (g->bad > 0) {
        snprintf(buf, sizeof buf, "%d unreadable truth row%s ignored", g->bad, g->bad == 1 ? "" : "s");
        note_add(note, size, buf);
    }
    if (g->cut) {
        note_add(note, size, "truth's last line cut off (no newline): not read");
    }
    if (r->pre_align > 0) {
        snprintf(buf, sizeof buf,
                 "%d truth stride%s before the alignment, a step between (log starts walking): not navigated",
                 r->pre_align, r->pre_align == 1 ? "" : "s");
        note_add(note, size, buf);
    }
    if (r->truth_end_gap_s > TRUTH_END_GAP_NOTE_S) {
        snprintf(buf, sizeof buf, "truth ends %.0f s before the log: its end not scored", r->truth_end_gap_s);
        note_add(note, size, buf);
    }
}

static void footprints(ev_t *ev, const fnav_nav_config_t *cfg, double rate_hz, int write, fp_t *out,
                       double **walk)
{
    char dir[EV_DIR_SIZE], path[EV_PATH_SIZE], gpath[EV_PATH_SIZE], note[EV_NOTE_SIZE], msg[HX_ERR_SIZE], nm[256],
        cell[EV_CELL_SIZE];
    ev_name_t *names;
    double *fpct, *smed, *fm, *wv, sum = 0.0;
    int n, i, k = 0;
    snprintf(dir, sizeof dir, "%s/pyshoe_vicon_llio/own_3dmgx5_footprints", ev->data);
    n = list_data(dir, k_fp_files, 3, 1, &names);
    n = n < 0 ? 0 : n; /* cannot be read: warned before the run (list_set) */
    wv = walk_values(walk, n);
    fpct = (double *)ev_calloc(3 * (size_t)n, sizeof *fpct);
    smed = fpct + n;
    fm = smed + n;
    if (write) {
        fprintf(ev->md, "| walk | strides | measured path (m) | median stride error (m) | RMS (m) | "
                        "final-stride error (m) | final (%% of path) | note |\n");
        fprintf(ev->md, "|---|---:|---:|---:|---:|---:|---:|---|\n");
    }
    for (i = 0; i < n; i++) {
        hx_traj_t t;
        hx_nav_summary_t s;
        static gcp_t g;
        stride_res_t r;
        size_t l;
        snprintf(path, sizeof path, "%s/%s_imu.csv", dir, names[i]);
        snprintf(gpath, sizeof gpath, "%s/%s_strides_gcp.csv", dir, names[i]);
        snprintf(nm, sizeof nm, "%s", names[i]);
        md_cell(nm, cell, sizeof cell);
        if (!is_file(path)) {
            snprintf(msg, sizeof msg, "no IMU log %.160s_imu.csv", names[i]);
        }
        if (!is_file(path) || read_gcp(gpath, &g, msg, sizeof msg) != 0) {
            /* a truth file that is there but refused is named, not the
             * walk's IMU log */
            fail(ev, is_file(path) && is_file(gpath) ? gpath : path, note, sizeof note, msg);
            not_run_row(ev, write, cell, 6, note);
            continue;
        }
        if (rate_hz > 0.0) {
            /* resampled: the stride indices refer to the original samples */
            double in = 0.0;
            if (replay(ev, path, cfg, rate_hz, write, &t, &s, note, sizeof note) != 0) {
                not_run_row(ev, write, cell, 6, note);
                continue;
            }
            in = t.in_rate_hz;
            for (l = 0; l < (size_t)g.n; l++) {
                g.idx[l] = (long)llround((double)g.idx[l] * rate_hz / in);
                if (g.idx[l] == (long)t.n && t.n > 0) {
                    /* the walk's last sample (where every truth file puts
                     * its last stride) rounds one past the last resampled
                     * frame: it is that frame, not a stride to drop */
                    g.idx[l] = (long)t.n - 1;
                }
            }
        } else if (replay(ev, path, cfg, 0.0, write, &t, &s, note, sizeof note) != 0) {
            not_run_row(ev, write, cell, 6, note);
            continue;
        }
        if (stride_errors(&t, &g, &r) != 0) {
            no_strides(ev, path, &t, &g, note, sizeof note);
            not_run_row(ev, write, cell, 6, note);
        } else if (!(r.path > 0.0)) {
            /* the truth's scored strides all at the first one's position:
             * no measured path, so no final % to judge (a "nan" would make
             * the section's median and mean nan, exit 0), as a judged closed
             * walk without a stride (no_closure) */
            fail(ev, gpath, note, sizeof note,
                 "the truth's strides span no path (all at the first stride's position): no final-stride error "
                 "as a share of it");
            not_run_row(ev, write, cell, 6, note);
        } else {
            stride_notes(note, sizeof note, &g, &r);
            if (write) {
                fprintf(ev->md, "| %s | %d | %.1f | %.3f | %.3f | %.3f | %.2f | %s |\n", cell, r.strides, r.path,
                        r.stride_err_med, r.rms, r.final_err, r.final_pct, note);
                if (ev->plots) {
                    hx_evplot_add_strides(&ev->fig, nm, &t, g.idx, g.x, g.y, g.n);
                }
            }
            if (wv != NULL) {
                wv[i] = r.final_pct;
            }
            fpct[k] = r.final_pct;
            smed[k] = r.stride_err_med;
            fm[k] = r.final_err;
            sum += r.final_pct;
            k++;
        }
        hx_traj_free(&t);
    }
    out->n = k;
    out->files = n;
    out->final_pct_mean = k > 0 ? sum / k : (double)NAN;
    out->final_pct_med = hx_median(fpct, k);
    out->stride_med = hx_median(smed, k);
    out->final_m_med = hx_median(fm, k);
    free(fpct);
    free(names);
}

/* Vicon: every stride of the trials against the motion-capture position at
 * the same sample (its frame is also the IMU's initial heading frame). The
 * position of every sample (columns 8 and 9), one entry per data row as the
 * log reader counts them (blank and '#' lines are none), so that stride
 * indices stay sample indices: NaN where a row has none (a lost marker) or
 * is a last line without its newline (the cut may have shortened it). 0, or
 * -1 when the file cannot be read or no row has a position. */
static int read_vicon(const char *path, double **vx, double **vy, size_t *n)
{
    FILE *f = fopen(path, "r");
    char line[512];
    size_t cap = 0, have = 0;
    int header = 1;
    *vx = *vy = NULL;
    *n = 0;
    if (f == NULL) {
        return -1;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        double v[9];
        const char *q = line + strspn(line, " \t");
        /* a line longer than the buffer is one row, without a position, not
         * a row per 511 characters of it, which would give every stride
         * after it the position of the sample before */
        const int long_line = skip_long_line(f, line, sizeof line);
        int ok;
        if (line[strspn(line, " \t\r\n\v\f")] == '\0' || *q == '#') {
            continue;
        }
        if (header) {
            header = 0;
            continue;
        }
        /* nine numbers, as read_gcp's rows (sscanf took 1.04 of a y of
         * 1.04xyz) */
        ok = !long_line && truth_row(line, v, 9) == 0 && fabs(v[7]) <= FNAV_INPUT_MAX_ABS &&
             fabs(v[8]) <= FNAV_INPUT_MAX_ABS && !(strchr(line, '\n') == NULL && feof(f));
        if (*n == cap) {
            cap = cap ? cap * 2 : 4096;
            *vx = (double *)ev_realloc(*vx, cap, sizeof **vx);
            *vy = (double *)ev_realloc(*vy, cap, sizeof **vy);
        }
        (*vx)[*n] = ok ? v[7] : (double)NAN;
        (*vy)[*n] = ok ? v[8] : (double)NAN;
        (*n)++;
        have += ok;
    }
    fclose(f);
    if (have == 0) {
        free(*vx);
        free(*vy);
        *vx = *vy = NULL;
        return -1;
    }
    return 0;
}

typedef struct {
    double stride_med, rms_med, final_med;
    int n, strides, files; /* trials with a result, strides, IMU files found */
} vicon_t;

static void vicon(ev_t *ev, const fnav_nav_config_t *cfg, int write, vicon_t *out, double **walk)
{
    char dir[EV_DIR_SIZE], path[EV_PATH_SIZE], gpath[EV_PATH_SIZE], note[EV_NOTE_SIZE], msg[HX_ERR_SIZE], nm[256],
        cell[EV_CELL_SIZE];
    ev_name_t *names;
    double *med, *rms, *fin, *wv;
    int n, i, k = 0, rc;
    snprintf(dir, sizeof dir, "%s/pyshoe_vicon_llio/vicon_3dmgx3", ev->data);
    n = list_data(dir, k_vicon_files, 2, 1, &names);
    n = n < 0 ? 0 : n; /* cannot be read: warned before the run (list_set) */
    wv = walk_values(walk, n);
    med = (double *)ev_calloc(3 * (size_t)n, sizeof *med);
    rms = med + n;
    fin = rms + n;
    out->strides = 0;
    if (write) {
        fprintf(ev->md, "| trial | strides | median stride error (m) | RMS (m) | final (m) | note |\n");
        fprintf(ev->md, "|---|---:|---:|---:|---:|---|\n");
    }
    for (i = 0; i < n; i++) {
        hx_traj_t t;
        hx_nav_summary_t s;
        static gcp_t g;
        stride_res_t r;
        double *vx, *vy;
        size_t nv;
        int j;
        snprintf(path, sizeof path, "%s/%s_imu.csv", dir, names[i]);
        snprintf(gpath, sizeof gpath, "%s/%s_strides_gcp.csv", dir, names[i]);
        snprintf(nm, sizeof nm, "%s", names[i]);
        md_cell(nm, cell, sizeof cell);
        const char *bad = path; /* the file the failure is about */
        if (!is_file(path)) {
            snprintf(msg, sizeof msg, "no IMU log %.160s_imu.csv", names[i]);
            rc = -1;
        } else {
            rc = read_gcp(gpath, &g, msg, sizeof msg);
            if (rc != 0 && is_file(gpath)) {
                bad = gpath; /* a truth file there but refused */
            }
        }
        if (rc == 0 && read_vicon(path, &vx, &vy, &nv) != 0) {
            snprintf(msg, sizeof msg, "no motion-capture position columns");
            rc = -1;
        }
        if (rc != 0) {
            fail(ev, bad, note, sizeof note, msg);
            not_run_row(ev, write, cell, 4, note);
            continue;
        }
        /* truth = the motion capture at the stride samples */
        for (j = 0; j < g.n; j++) {
            const int in = g.idx[j] >= 0 && (size_t)g.idx[j] < nv;
            g.x[j] = in ? vx[g.idx[j]] : (double)NAN;
            g.y[j] = in ? vy[g.idx[j]] : (double)NAN;
        }
        free(vx);
        free(vy);
        if (replay(ev, path, cfg, 0.0, write, &t, &s, note, sizeof note) != 0) {
            not_run_row(ev, write, cell, 4, note);
            continue;
        }
        if (stride_errors(&t, &g, &r) != 0) {
            no_strides(ev, path, &t, &g, note, sizeof note);
            not_run_row(ev, write, cell, 4, note);
        } else {
            stride_notes(note, sizeof note, &g, &r);
            if (write) {
                fprintf(ev->md, "| %s | %d | %.3f | %.3f | %.3f | %s |\n", cell, r.strides, r.stride_err_med, r.rms,
                        r.final_err, note);
                if (ev->plots) {
                    hx_evplot_add_strides(&ev->fig, nm, &t, g.idx, g.x, g.y, g.n);
                }
            }
            if (wv != NULL) {
                wv[i] = r.stride_err_med;
            }
            med[k] = r.stride_err_med;
            rms[k] = r.rms;
            fin[k] = r.final_err;
            out->strides += r.strides;
            k++;
        }
        hx_traj_free(&t);
    }
    out->n = k;
    out->files = n;
    out->stride_med = hx_median(med, k);
    out->rms_med = hx_median(rms, k);
    out->final_med = hx_median(fin, k);
    free(med);
    free(names);
}

/* ------------------------------------------------------------ stance (IPOL) */

typedef struct {
    int expected, detected, missed, spurious, trials, files; /* files: events files found */
    int both_feet; /* expert swings left out: the other foot's expert swing overlaps them */
    int strict_missed, strict_spurious; /* with those swings kept */
    int off_time;  /* missed although a detected swing overlaps: its events IPOL_TOL or more away */
    double fo_med, fs_med, fo_p90, fs_p90, fo_bias, fs_bias;
    int n_fo, n_fs;
} ipol_t;

/* A JSON pair of sample indices [x, y] (whole numbers, 0 <= x <= y) into
 * v; 0, or -1 when p is not one (an unknown value, NaN in the file, is
 * null here: read as 0, [NaN, 574] would be a swing from the file's first
 * packet and [527, NaN] one that ends before it starts, a missed stride). */
static int json_pair(const cJSON *p, long v[2])
{
    const cJSON *x = cJSON_GetArrayItem(p, 0), *y = cJSON_GetArrayItem(p, 1);
    if (!cJSON_IsArray(p) || cJSON_GetArraySize(p) != 2 || !cJSON_IsNumber(x) || !cJSON_IsNumber(y) ||
        !(x->valuedouble >= 0.0 && x->valuedouble <= y->valuedouble && y->valuedouble <= 1e9) ||
        x->valuedouble != floor(x->valuedouble) || y->valuedouble != floor(y->valuedouble)) {
        return -1;
    }
    v[0] = (long)x->valuedouble;
    v[1] = (long)y->valuedouble;
    return 0;
}

/* The expert events of one foot (key) and the trial and U-turn boundaries
 * of an ipol_gait_xsens N-M.json; the number of events, or -1 with the
 * reason in why. */
static int read_events(const char *path, long ev[][2], int max, const char *key, long tb[2], long ub[2], char *why,
                       size_t why_size)
{
    FILE *f = fopen(path, "rb");
    char *buf, *q, *js;
    long size;
    size_t i0, o;
    cJSON *root, *a, *u;
    int k = 0, i, n;
    if (f == NULL) {
        /* with the reason: "cannot open 1-1.json" alone did not say that
         * the trial's events file is missing */
        snprintf(why, why_size, "cannot open %.160s (%s)", strrchr(path, '/') ? strrchr(path, '/') + 1 : path,
                 strerror(errno));
        return -1;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || size > (16L << 20) || fseek(f, 0, SEEK_SET) != 0 ||
        (buf = (char *)malloc((size_t)size + 1)) == NULL) {
        fclose(f);
        snprintf(why, why_size, "cannot read the events file (larger than 16 MB or unreadable)");
        return -1;
    }
    buf[fread(buf, 1, (size_t)size, f)] = '\0';
    fclose(f);
    /* the data set writes NaN for unknown values (the subjects' weight),
     * which JSON does not have: null, an unknown, which no pair of sample
     * indices is */
    js = (char *)malloc(2 * (size_t)size + 1);
    if (js == NULL) {
        free(buf);
        snprintf(why, why_size, "out of memory reading the events file");
        return -1;
    }
    for (i0 = o = 0, q = buf; (q = strstr(q, "NaN")) != NULL; q += 3) {
        const size_t at = (size_t)(q - buf);
        memcpy(js + o, buf + i0, at - i0);
        o += at - i0;
        memcpy(js + o, "null", 4);
        o += 4;
        i0 = at + 3;
    }
    snprintf(js + o, 2 * (size_t)size + 1 - o, "%s", buf + i0);
    free(buf);
    {
        /* where the parser stopped: the line (the NaN -> null edit keeps
         * the lines), or the end of a file cut short */
        const char *stop = NULL;
        root = cJSON_ParseWithOpts(js, &stop, 0);
        if (root == NULL) {
            long line = 1;
            const char *c;
            for (c = js; stop != NULL && c < stop && *c != '\0'; c++) {
                line += *c == '\n';
            }
            if (stop == NULL) {
                snprintf(why, why_size, "the events file is not valid JSON");
            } else if (strspn(stop, " \t\r\n") == strlen(stop)) {
                snprintf(why, why_size, "the events file is not valid JSON (it ends early)");
            } else {
                /* the text there, up to 16 bytes of its line (a file of
                 * one line, as the data set's, gives no other clue) */
                const int len = (int)strcspn(stop, "\r\n");
                snprintf(why, why_size, "the events file is not valid JSON (line %ld, at '%.*s')", line,
                         len < 16 ? len : 16, stop);
            }
            free(js);
            return -1;
        }
    }
    free(js);
    if (json_pair(cJSON_GetObjectItem(root, "TrialBoundaries"), tb) != 0) {
        cJSON_Delete(root);
        snprintf(why, why_size, "the events file has no TrialBoundaries pair");
        return -1;
    }
    u = cJSON_GetObjectItem(root, "UTurnBoundaries");
    if (u == NULL) {
        ub[0] = ub[1] = 0; /* a trial without a U-turn: an empty range */
    } else if (json_pair(u, ub) != 0) {
        /* unknown (NaN) or not a pair: the turn's strides, which the
         * experts annotate only partly, would be judged as walking */
        cJSON_Delete(root);
        snprintf(why, why_size, "the events file's UTurnBoundaries is not a pair of sample indices");
        return -1;
    }
    a = cJSON_GetObjectItem(root, key);
    if (!cJSON_IsArray(a)) {
        cJSON_Delete(root);
        snprintf(why, why_size, "the events file has no %s", key);
        return -1;
    }
    n = cJSON_GetArraySize(a);
    if (n > max) {
        cJSON_Delete(root);
        snprintf(why, why_size, "%s holds %d events, more than %d", key, n, max);
        return -1;
    }
    for (i = 0; i < n; i++) {
        if (json_pair(cJSON_GetArrayItem(a, i), ev[k]) != 0) {
            cJSON_Delete(root);
            snprintf(why, why_size, "%s[%d] is not a pair of sample indices", key, i);
            return -1;
        }
        k++;
    }
    cJSON_Delete(root);
    return k;
}

/* Packet index (the experts' unit: the PacketCounter, 16-bit wraps counted
 * on) of a time from the log: the reader stamps a sample counter / rate, so
 * a time after dropped packets still counts them. The counter itself, not
 * packets since the file's first: it is the time base the Awinda station
 * gives every sensor of a recording, and one TrialBoundaries pair serves
 * both feet, whose files start at different counters when their first
 * packets were lost (1-2: left 0, right 1; 3-3: left 2, right 0).
 * Subtracting each file's first counter would move the events of the six
 * files not starting at 0 earlier by one or two packets: their foot-off
 * errors would have a median of -3 packets against -1 for the other 22
 * (subject 1's three such files at -3 each, its nine others between -2 and
 * -1), their foot-strike errors 0 against +1; with the counter both groups
 * agree (-1 and +1). */
static long pkt_of_time(const hx_log_t *log, int64_t t_ns)
{
    return (long)llround((double)t_ns * log->meta.rate_hz * 1e-9);
}

/* Largest |event error| for an expert swing to count as detected, samples. */
#define IPOL_TOL 50

static int overlaps(long a0, long a1, long b0, long b1)
{
    return a0 < b1 && a1 > b0;
}

/* v with one decimal, or "-" when there is none (no event to time). */
/* v in the printf format fmt (one double), or "-" when there is none (a
 * failed run, not "nan" in a table). */
static const char *fmt_v(char *buf, size_t size, const char *fmt, double v)
{
    if (isfinite(v)) {
        snprintf(buf, size, fmt, v);
    } else {
        snprintf(buf, size, "-");
    }
    return buf;
}

static const char *fmt_1f(char *buf, size_t size, double v)
{
    return fmt_v(buf, size, "%.1f", v);
}

/* Counts of one trial and foot's matching. */
typedef struct {
    int exp_n, det_n, miss, spur, both, off_time;
    int beyond; /* expert swings past the log's last packet (a log cut short): not evaluated */
} ipol_match_t;

/* Everything in packets (the experts' unit, the PacketCounter; the log's
 * rows skip dropped packets). Evaluated: the expert swings evs inside
 * the trial tb and clear of the U-turn ub (the experts annotate the turn
 * only partly), and, unless keep_both, not overlapping an expert swing of
 * the other foot oevs (both feet in the air: no walking stride has that, so
 * the annotation is not reliable there). An evaluated expert swing is
 * detected when a detected swing sw overlaps it and the nearest reported
 * foot-off fo and foot-strike fs both lie within IPOL_TOL samples of its
 * ends; otherwise it is missed. A detected swing that detects none counts
 * as spurious when its middle is inside the trial, outside the U-turn, and
 * it overlaps no excluded expert swing. An expert swing that would be
 * evaluated but ends after the log's last packet `last` (a log cut short:
 * no detector could find it) is left out too and counted in m->beyond.
 * found[j] gets expert swing j's reported foot-off and foot-strike when it
 * was detected, else -1. */
static void ipol_match(const long (*evs)[2], int ne, const long (*oevs)[2], int noe, const long (*sw)[2], int nsw,
                       const long *fo, int nfo, const long *fs, int nfs, const long tb[2], const long ub[2],
                       long last, int keep_both, int *used, long (*found)[2], ipol_match_t *m)
{
    int j, k, q;
    memset(m, 0, sizeof *m);
    for (k = 0; k < nsw; k++) {
        used[k] = 0;
    }
    for (j = 0; j < ne; j++) {
        long s0 = evs[j][0], s1 = evs[j][1], bfo = -1, bfs = -1;
        int hit = -1, both = 0;
        const int outside = overlaps(s0, s1, ub[0], ub[1]) || s0 < tb[0] - 5 || s1 > tb[1] + 5;
        found[j][0] = found[j][1] = -1;
        for (q = 0; q < noe && !keep_both; q++) {
            both = both || overlaps(oevs[q][0], oevs[q][1], s0, s1);
        }
        if (outside || both || s1 > last) {
            for (k = 0; k < nsw; k++) {
                if (used[k] == 0 && overlaps(sw[k][0], sw[k][1], s0, s1)) {
                    /* belongs to an excluded expert swing (not spurious);
                     * one that already detected an evaluated swing keeps
                     * that mark, else a later evaluated swing would take it
                     * again: one detected swing over three expert swings,
                     * the middle one left out, would count as two
                     * detections */
                    used[k] = 2;
                }
            }
            m->both += !outside && both;
            m->beyond += !outside && !both;
            continue;
        }
        m->exp_n++;
        for (k = 0; k < nsw; k++) {
            if (used[k] != 1 && overlaps(sw[k][0], sw[k][1], s0, s1)) {
                hit = k;
                break;
            }
        }
        /* nearest reported events to the expert's foot-off / strike */
        for (q = 0; q < nfo; q++) {
            if (bfo < 0 || labs(fo[q] - s0) < labs(bfo - s0)) {
                bfo = fo[q];
            }
        }
        for (q = 0; q < nfs; q++) {
            if (bfs < 0 || labs(fs[q] - s1) < labs(bfs - s1)) {
                bfs = fs[q];
            }
        }
        if (hit < 0 || bfo < 0 || bfs < 0 || labs(bfo - s0) >= IPOL_TOL || labs(bfs - s1) >= IPOL_TOL) {
            m->off_time += hit >= 0;
            m->miss++;
            continue;
        }
        used[hit] = 1;
        m->det_n++;
        found[j][0] = bfo;
        found[j][1] = bfs;
    }
    for (k = 0; k < nsw; k++) {
        long mid = (sw[k][0] + sw[k][1]) / 2;
        if (used[k] == 0 && !(mid >= ub[0] && mid < ub[1]) && mid > tb[0] - 5 && mid < tb[1] + 5) {
            m->det_n++;
            m->spur++;
        }
    }
}

static void ipol(ev_t *ev, const fnav_nav_config_t *cfg, int write, ipol_t *out)
{
    char dir[EV_DIR_SIZE], path[EV_PATH_SIZE], jpath[EV_PATH_SIZE], note[EV_NOTE_SIZE], nm[EV_CELL_SIZE + 16];
    ev_name_t *names;
    ev_dvec_t fo_e = { NULL, 0, 0 }, fs_e = { NULL, 0, 0 }, fo_a = { NULL, 0, 0 }, fs_a = { NULL, 0, 0 };
    long (*sw)[2] = NULL, *fo = NULL, *fs = NULL;
    int *used = NULL, swcap = 0, focap = 0, fscap = 0;
    int n, i, foot;
    memset(out, 0, sizeof *out);
    snprintf(dir, sizeof dir, "%s/ipol_gait_xsens", ev->data);
    n = list_data(dir, k_ipol_files, 3, 1, &names);
    n = n < 0 ? 0 : n; /* cannot be read: warned before the run (list_set) */
    out->files = n;
    if (write) {
        fprintf(ev->md, "| trial | foot | expert strides | detected | missed | spurious | median \\|FO error\\| | "
                        "median \\|FS error\\| (samples) | note |\n");
        fprintf(ev->md, "|---|---|---:|---:|---:|---:|---:|---:|---|\n");
    }
    for (i = 0; i < n; i++) {
        for (foot = 0; foot < 2; foot++) {
            static long evs[256][2], oevs[256][2];
            long tb[2], ub[2], otb[2], oub[2];
            int ne, noe, nsw = 0, nfo = 0, nfs = 0, j, exp_n = 0, det_n = 0, miss = 0, spur_n = 0, lrc = 0;
            long last;
            hx_log_t log;
            char err[HX_ERR_SIZE], oerr[HX_ERR_SIZE];
            fnav_stance_t st;
            fnav_stance_config_t sc = cfg->stance;
            fnav_stance_out_t o;
            size_t r;
            int trial_fo = 0, trial_fs = 0;
            double tfo[256], tfs[256];
            snprintf(jpath, sizeof jpath, "%s/%s.json", dir, names[i]);
            snprintf(path, sizeof path, "%s/%s_%s.txt", dir, names[i], foot ? "rf" : "lf");
            {
                char cell[EV_CELL_SIZE];
                /* escaped here: not_run_row's escape would take the separator's '|' too */
                snprintf(nm, sizeof nm, "%s | %s", md_cell(names[i], cell, sizeof cell), foot ? "right" : "left");
            }
            ne = read_events(jpath, evs, 256, foot ? "RightFootEvents" : "LeftFootEvents", tb, ub, err, sizeof err);
            /* the other foot's swings, to find annotations with both feet in the air */
            noe = ne < 0 ? 0 : read_events(jpath, oevs, 256, foot ? "LeftFootEvents" : "RightFootEvents", otb, oub,
                                            oerr, sizeof oerr);
            /* an events file's fault (it serves both feet) is warned once:
             * fail() */
            if (ne < 0) {
                fail(ev, jpath, note, sizeof note, err);
            } else if (noe < 0) {
                /* the other foot's swings decide which of this foot's are
                 * evaluated (both feet in the air): without them the
                 * evaluation is not the one described (it would go on as if
                 * the other foot never left the ground) */
                fail(ev, jpath, note, sizeof note, oerr);
                ne = -1;
            } else if (!is_file(path)) {
                snprintf(err, sizeof err, "no IMU log %.160s_%s.txt", names[i], foot ? "rf" : "lf");
                fail(ev, path, note, sizeof note, err);
                ne = -1;
            } else if ((lrc = hx_log_load(&log, path, HX_FMT_AUTO, 0.0, err, sizeof err)) < 0) {
                fail(ev, path, note, sizeof note, err);
                ne = -1;
            } else if (lrc > 0 || log.n == 0) {
                /* a line the reader could not take stopped the log: the
                 * expert swings after it would read as missed strides, the
                 * detector blamed for the data (so it is said, not passed
                 * with exit 0) */
                char buf[HX_ERR_SIZE], why[EV_NOTE_SIZE];
                snprintf(why, sizeof why, "input ends early (%s): the foot's log was read only in part",
                         log.n == 0 ? "no sample" : after_path(log.error, path, buf, sizeof buf));
                fail(ev, path, note, sizeof note, why);
                hx_log_free(&log);
                ne = -1;
            }
            if (ne < 0) {
                not_run_row(ev, write, nm, 6, note);
                continue;
            }
            ev->runs++;
            hx_progress_update(&ev->prog, (double)ev->runs);
            hx_print_warnings("eval", log.warnings); /* a cut-off last line (noted in the row) */
            note[0] = '\0';
            if (log.stats.cut_lines > 0) {
                note_add(note, sizeof note, "last line cut off mid-write: not read");
            }
            last = pkt_of_time(&log, log.t_ns[log.n - 1]);
            sc.gravity_mps2 = cfg->gravity_mps2;
            if (fnav_stance_init(&st, &sc) != FNAV_OK) {
                fail(ev, path, note, sizeof note, "the stance detector refused its configuration");
                not_run_row(ev, write, nm, 6, note);
                hx_log_free(&log);
                continue;
            }
            /* run the detector sample by sample */
            for (r = 0; r <= log.n; r++) {
                fnav_status_t ps;
                if (r < log.n) {
                    fnav_sample_t s;
                    hx_log_sample(&log, r, &s);
                    if (fnav_stance_push(&st, &s) != FNAV_OK) {
                        break;
                    }
                } else {
                    fnav_stance_finish(&st);
                }
                while ((ps = fnav_stance_pop(&st, &o)) == FNAV_OK) {
                    if (o.events & FNAV_STANCE_EV_STRIDE) {
                        if (nsw == swcap) {
                            swcap = swcap > 0 ? 2 * swcap : 256;
                            sw = (long (*)[2])ev_realloc(sw, (size_t)swcap, sizeof *sw);
                            used = (int *)ev_realloc(used, (size_t)swcap, sizeof *used);
                        }
                        sw[nsw][0] = pkt_of_time(&log, o.swing_t0_ns);
                        sw[nsw][1] = pkt_of_time(&log, o.swing_t1_ns);
                        nsw++;
                    }
                    if (o.events & FNAV_STANCE_EV_FOOT_OFF) {
                        if (nfo == focap) {
                            focap = focap > 0 ? 2 * focap : 256;
                            fo = (long *)ev_realloc(fo, (size_t)focap, sizeof *fo);
                        }
                        fo[nfo++] = pkt_of_time(&log, o.fo_t_ns);
                    }
                    if (o.events & FNAV_STANCE_EV_FOOT_STRIKE) {
                        if (nfs == fscap) {
                            fscap = fscap > 0 ? 2 * fscap : 256;
                            fs = (long *)ev_realloc(fs, (size_t)fscap, sizeof *fs);
                        }
                        fs[nfs++] = pkt_of_time(&log, o.fs_t_ns);
                    }
                }
                (void)ps;
            }
            {
                static long found[256][2];
                ipol_match_t m, ms;
                ipol_match((const long (*)[2])evs, ne, (const long (*)[2])oevs, noe, (const long (*)[2])sw, nsw, fo,
                           nfo, fs, nfs, tb, ub, last, 1, used, found, &ms);
                out->strict_missed += ms.miss;
                out->strict_spurious += ms.spur;
                ipol_match((const long (*)[2])evs, ne, (const long (*)[2])oevs, noe, (const long (*)[2])sw, nsw, fo,
                           nfo, fs, nfs, tb, ub, last, 0, used, found, &m);
                exp_n = m.exp_n;
                det_n = m.det_n;
                miss = m.miss;
                spur_n = m.spur;
                out->both_feet += m.both;
                out->off_time += m.off_time;
                if (m.beyond > 0) {
                    char buf[120];
                    snprintf(buf, sizeof buf, "%d expert swing%s after the log's end not evaluated", m.beyond,
                             m.beyond == 1 ? "" : "s");
                    note_add(note, sizeof note, buf);
                }
                for (j = 0; j < ne; j++) {
                    const long bfo = found[j][0], bfs = found[j][1];
                    if (bfo < 0) {
                        continue;
                    }
                    /* ne <= 256 (read_events): tfo and tfs hold them all */
                    dvec_push(&fo_e, (double)(bfo - evs[j][0]));
                    dvec_push(&fo_a, fabs((double)(bfo - evs[j][0])));
                    tfo[trial_fo++] = fabs((double)(bfo - evs[j][0]));
                    dvec_push(&fs_e, (double)(bfs - evs[j][1]));
                    dvec_push(&fs_a, fabs((double)(bfs - evs[j][1])));
                    tfs[trial_fs++] = fabs((double)(bfs - evs[j][1]));
                }
            }
            if (write) {
                char m1[32], m2[32];
                fprintf(ev->md, "| %s | %d | %d | %d | %d | %s | %s | %s |\n", nm, exp_n, det_n, miss, spur_n,
                        fmt_1f(m1, sizeof m1, hx_median(tfo, trial_fo)),
                        fmt_1f(m2, sizeof m2, hx_median(tfs, trial_fs)), note);
            }
            out->expected += exp_n;
            out->detected += det_n;
            out->missed += miss;
            out->spurious += spur_n;
            out->trials++;
            hx_log_free(&log);
        }
    }
    if (write && ev->plots && (fo_e.n > 0 || fs_e.n > 0)) {
        char png[HX_PLOT_PATH_SIZE];
        snprintf(png, sizeof png, "%s/eval-ipol.png", ev->plot_dir);
        if (hx_evplot_hist2("eval", png, "ipol_gait_xsens: gait-event timing error, detector - experts",
                            "error (samples at 100 Hz; the ends gather beyond +-10)", fo_e.v, fo_e.n,
                            "foot-off (FO)", fs_e.v, fs_e.n, "foot-strike (FS)", 10) == 0) {
            ev->ipol_fig = 1;
        } else {
            hx_warn("eval", "figure %s not drawn (see above); results.md goes on without it", png);
        }
    }
    out->n_fo = fo_a.n;
    out->n_fs = fs_a.n;
    out->fo_bias = hx_median(fo_e.v, fo_e.n);
    out->fs_bias = hx_median(fs_e.v, fs_e.n);
    out->fo_p90 = pct_rank(fo_a.v, fo_a.n, 90.0);
    out->fs_p90 = pct_rank(fs_a.v, fs_a.n, 90.0);
    out->fo_med = hx_median(fo_a.v, fo_a.n);
    out->fs_med = hx_median(fs_a.v, fs_a.n);
    free(fo_e.v);
    free(fs_e.v);
    free(fo_a.v);
    free(fs_a.v);
    free(sw);
    free(used);
    free(fo);
    free(fs);
    free(names);
}

/* ------------------------------------------------------------ main */

static const char *met(int ok)
{
    return ok ? "met" : "**not met**";
}

/* The command that wrote results.md, as a shell reads it back (in a
 * malloc'd buffer, to free()): `./bin/harness eval` and argv, whole, after
 * `FNAV_DATA_DIR=DIR` when that variable named the data (env_data, or
 * NULL), so that the line rerun reads the same data. */
static char *eval_command(int argc, char **argv, char *env_data)
{
    static const char k_cmd[] = "./bin/harness eval";
    size_t size = sizeof k_cmd + 32, i;
    char *buf, *prefix;
    /* an argument's worst case: every character a ' written '\'', quoted,
     * after a space */
    for (i = 0; i < (size_t)argc; i++) {
        size += 4 * strlen(argv[i]) + 3;
    }
    if (env_data != NULL) {
        size += 4 * strlen(env_data) + 3 + sizeof "FNAV_DATA_DIR=";
    }
    buf = (char *)ev_calloc(size, 1);
    prefix = (char *)ev_calloc(size, 1);
    if (env_data != NULL) {
        hx_command_line(prefix, size, "", 1, &env_data); /* " DIR", quoted as an argument */
        memmove(prefix + sizeof "FNAV_DATA_DIR=" - 1, prefix + 1, strlen(prefix + 1) + 1);
        memcpy(prefix, "FNAV_DATA_DIR=", sizeof "FNAV_DATA_DIR=" - 1);
        strcat(prefix, " ");
    }
    strcat(prefix, k_cmd);
    hx_command_line(buf, size, prefix, argc, argv);
    free(prefix);
    return buf;
}

/* A target's status: judged only when its data set gave a result; "not
 * run (failed)" when its files were found but every run failed (not "no
 * data", as if absent), "no data" when none was found. */
/* found: 0 the data set is absent, 1 there, 2 its folder could not be
 * read (set_unreadable: it read "no data", as an absent one) */
static const char *target(int found, int have_data, int ok)
{
    return have_data ? met(ok) : found == 2 ? "not run (cannot read)" : found ? "not run (failed)" : "no data";
}

/* target()'s found for the data set folder sub with files found */
static int set_found(const ev_t *ev, const char *sub, int files)
{
    return files > 0 ? 1 : set_unreadable(ev, sub) ? 2 : 0;
}

/* The ipol detection target's status: "nothing evaluated" when no expert
 * swing was evaluated and no swing was spurious (never "met" on nothing);
 * a spurious swing fails it even then. */
static const char *ipol_judged(const ipol_t *ip, int ok)
{
    return ip->expected == 0 && ip->spurious == 0 ? "nothing evaluated" : met(ok);
}

static const char *fmt_pct(char *buf, size_t size, double v)
{
    return fmt_v(buf, size, "%.2f %%", v);
}

/* A row of the rate experiment: label (its first two cells) and three
 * figures, native, 200 and 100 Hz, in fmt ("-" for none). */
static void row3(FILE *md, const char *label, const char *fmt, double a, double b, double c)
{
    char s1[40], s2[40], s3[40];
    fprintf(md, "| %s | %s | %s | %s |\n", label, fmt_v(s1, sizeof s1, fmt, a), fmt_v(s2, sizeof s2, fmt, b),
            fmt_v(s3, sizeof s3, fmt, c));
}

static const char *fmt_mm(char *buf, size_t size, double v_m)
{
    snprintf(buf, size, isfinite(v_m) ? "%.0f mm" : "-", 1e3 * v_m);
    return buf;
}

/* Two-sided sign test: the probability, under "either way equally
 * likely", of a split at least as uneven as k of n. */
static double sign_test_p(int k, int n)
{
    double c = 1.0, sum = 0.0, p;
    int i, lo = k < n - k ? k : n - k;
    if (n <= 0) {
        return (double)NAN;
    }
    for (i = 0; i <= lo; i++) {
        sum += c; /* C(n, i) */
        c = c * (double)(n - i) / (double)(i + 1);
    }
    p = 2.0 * sum / pow(2.0, (double)n);
    return p < 1.0 ? p : 1.0;
}

/* One row of the bias-model experiment's paired table: per walk off - on
 * (walks with a result in both runs), median [min, max], the count the
 * model improves and the sign test. */
static void paired_row(ev_t *ev, const char *profile, const char *figure, const char *fmt, const double *off,
                       const double *on, int n)
{
    double *d = (double *)ev_calloc(n > 0 ? (size_t)n : 1u, sizeof *d), lo = (double)INFINITY, hi = -(double)INFINITY;
    int i, k = 0, better = 0, ties = 0;
    char a[40], b[40], c[40], pv[40];
    for (i = 0; off != NULL && on != NULL && i < n; i++) {
        if (isfinite(off[i]) && isfinite(on[i])) {
            d[k] = off[i] - on[i];
            better += d[k] > 0.0;
            ties += d[k] == 0.0;
            lo = d[k] < lo ? d[k] : lo;
            hi = d[k] > hi ? d[k] : hi;
            k++;
        }
    }
    if (k == 0) {
        fprintf(ev->md, "| %s | %s | 0 | - | - | - |\n", profile, figure);
        free(d);
        return;
    }
    snprintf(a, sizeof a, fmt, hx_median(d, k));
    snprintf(b, sizeof b, fmt, lo);
    snprintf(c, sizeof c, fmt, hi);
    /* every walk a tie: no sign test ("-", not "nan") */
    fprintf(ev->md, "| %s | %s | %d | %d of %d | %s [%s, %s] | %s |\n", profile, figure, k, better, k - ties, a, b,
            c, fmt_v(pv, sizeof pv, "%.3f", sign_test_p(better, k - ties)));
    free(d);
}

/* ------------------------------------------------------------ figures */

/* The directory of a file path ("." for a bare name). */
static void dir_of(const char *path, char *out, size_t size)
{
    const char *sl = strrchr(path, '/');
    if (sl == NULL) {
        snprintf(out, size, ".");
    } else if (sl == path) {
        snprintf(out, size, "/");
    } else {
        snprintf(out, size, "%.*s", (int)(sl - path), path);
    }
}

/* `to` relative to the directory `from` (both existing): by their real
 * paths, with "../" for each of from's components below the common part.
 * 0, or -1 (then `to` as given). */
static int rel_path(const char *from, const char *to, char *out, size_t size)
{
    char rf[PATH_MAX], rt[PATH_MAX];
    size_t common = 0, i, len = 0;
    if (realpath(from, rf) == NULL || realpath(to, rt) == NULL) {
        snprintf(out, size, "%s", to);
        return -1;
    }
    /* the common part ends at a '/' (or at the end of one of them) */
    for (i = 0; rf[i] != '\0' && rf[i] == rt[i]; i++) {
        if (rf[i] == '/') {
            common = i;
        }
    }
    if (rf[i] == '\0' && (rt[i] == '/' || rt[i] == '\0')) {
        common = i;
    } else if (rt[i] == '\0' && rf[i] == '/') {
        common = i;
    }
    out[0] = '\0';
    for (i = common; rf[i] != '\0'; i++) {
        if (rf[i] == '/' && rf[i + 1] != '\0') {
            len += (size_t)snprintf(out + len, len < size ? size - len : 0, "../");
        }
    }
    if (strcmp(rf, "/") == 0 || rf[common] == '\0') {
        /* from is a prefix of to: nothing to climb */
        len = 0;
        out[0] = '\0';
    }
    if (rt[common] == '/') {
        common++;
    }
    snprintf(out + len, len < size ? size - len : 0, "%s", rt[common] != '\0' ? rt + common : ".");
    if (len > 0 && rt[common] == '\0') {
        out[len - 1] = '\0'; /* "../" alone: "..", the directory itself */
    }
    return 0;
}

/* A relative path as a Markdown link destination: the bytes that end one
 * or are not allowed in it (space and control characters, parentheses,
 * angle brackets, backslash) and '%' itself percent-encoded ("my figs"
 * was linked as written, which is no link: the figure was not shown). */
static void md_link(const char *path, char *out, size_t size)
{
    static const char hex[] = "0123456789ABCDEF";
    size_t o = 0;
    for (; *path != '\0' && o + 1 < size; path++) {
        const unsigned char c = (unsigned char)*path;
        if (c <= 0x20u || c == 0x7fu || strchr("%()<>\\", (int)c) != NULL) {
            if (o + 4 > size) {
                break;
            }
            out[o++] = '%';
            out[o++] = hex[c >> 4];
            out[o++] = hex[c & 15u];
        } else {
            out[o++] = (char)c;
        }
    }
    out[o] = '\0';
}

/* Draw the walks collected for a section into PLOTS/eval-NAME.png (closed
 * walks: paths and heights; strides: a panel per walk against the truth)
 * and link it from results.md under its caption; the set is emptied. */
static void figure(ev_t *ev, const char *name, int strides, const char *title, const char *caption)
{
    char png[HX_PLOT_PATH_SIZE];
    if (ev->plots && ev->fig.n > 0) {
        snprintf(png, sizeof png, "%s/eval-%s.png", ev->plot_dir, name);
        if ((strides ? hx_evplot_strides(&ev->fig, "eval", png, title)
                     : hx_evplot_paths(&ev->fig, "eval", png, title)) == 0) {
            fprintf(ev->md, "![%s](%s/eval-%s.png)\n\n%s\n\n", title, ev->plot_link, name, caption);
        } else {
            hx_warn("eval", "figure %s not drawn (see above); results.md goes on without it", png);
        }
    }
    hx_evplot_free(&ev->fig);
}

/* The report is written into OUT.part beside OUT and renamed onto it at
 * a clean end: an eval stopped by Ctrl-C or a full disk emptied the
 * tracked docs/results.md (fopen "w" before the runs). A signal removes
 * the part written (the handler: unlink, then the signal's own action) */
static char g_md_part[PATH_MAX + 8];
static const int k_md_sigs[3] = { SIGINT, SIGTERM, SIGHUP };
static struct sigaction g_md_old[3]; /* their actions before (ignored under nohup: left so) */

static void md_part_signal(int sig)
{
    int k;
    if (g_md_part[0] != '\0') {
        (void)unlink(g_md_part);
    }
    for (k = 0; k < 3; k++) {
        if (k_md_sigs[k] == sig) {
            (void)sigaction(sig, &g_md_old[k], NULL);
        }
    }
    (void)raise(sig);
}

/* the handler on (on) or the actions before back (off) */
static void md_signals(int on)
{
    int k;
    for (k = 0; k < 3; k++) {
        if (on) {
            struct sigaction sa;
            (void)sigaction(k_md_sigs[k], NULL, &g_md_old[k]);
            if (g_md_old[k].sa_handler == SIG_IGN) {
                continue;
            }
            memset(&sa, 0, sizeof sa);
            sa.sa_handler = md_part_signal;
            sigemptyset(&sa.sa_mask);
            (void)sigaction(k_md_sigs[k], &sa, NULL);
        } else {
            (void)sigaction(k_md_sigs[k], &g_md_old[k], NULL);
        }
    }
}

/* the file to write the report into (OUT itself when it is no regular file
 * or name too long for the part's: /dev/null, a terminal); path the name
 * of the one renamed onto at the end (a symlink's target) */
static FILE *md_open(const char *out_path, char *path, size_t path_size)
{
    struct stat st, lst;
    FILE *f;
    const int exists = stat(out_path, &st) == 0;
    if ((exists && !S_ISREG(st.st_mode)) || strlen(out_path) >= path_size ||
        (!exists && lstat(out_path, &lst) == 0 && S_ISLNK(lst.st_mode))) {
        /* written in place: no regular file (/dev/null), or a symlink to
         * none, whose target the write creates (a part renamed onto it
         * replaced the link by a file) */
        return fopen(out_path, "w");
    }
    if (exists && realpath(out_path, path) != NULL && strlen(path) + 5 < sizeof g_md_part) {
        /* a symlink: its target replaced, not the link by a file */
    } else {
        snprintf(path, path_size, "%s", out_path);
    }
    snprintf(g_md_part, sizeof g_md_part, "%s.part", path);
    md_signals(1);
    f = fopen(g_md_part, "w");
    if (f == NULL) {
        md_signals(0);
        g_md_part[0] = '\0';
        return NULL;
    }
    if (exists) {
        /* the report keeps the file's mode (a 0600 one came back 0644) */
        (void)fchmod(fileno(f), st.st_mode & 07777);
    }
    return f;
}

/* the part written renamed onto path (ok), or removed; 0 or the errno */
static int md_finish(const char *path, int ok)
{
    int e = 0;
    if (g_md_part[0] == '\0') {
        return 0;
    }
    if (ok && rename(g_md_part, path) != 0) {
        e = errno;
    }
    if (!ok || e != 0) {
        (void)unlink(g_md_part);
    }
    g_md_part[0] = '\0';
    md_signals(0); /* after the rename: a signal before it removes the part */
    return e;
}

int hx_cmd_eval(int argc, char **argv)
{
    hx_args_t a;
    hx_nav_opts_t o;
    ev_t ev;
    char err[HX_ERR_SIZE], *cmdline, *env_data = NULL, zupt_run[96], det_label[HX_NAV_DETECTOR_LABEL_SIZE];
    int manifest;
    const char *out_path, *json_path, *data;
    char md_path[PATH_MAX + 1];
    closure_t gx2, gx2_200, gx2_100;
    double xs = (double)NAN, xl = (double)NAN; /* the vendor-figure walks' 3-D closure, m */
    int xs_found = 0, xl_found = 0;            /* those walks were found (their run may have failed) */
    ev_name_t *xio;
    char (*other)[300]; /* "set/name" */
    double *xio3, *other3, *other_hz;
    int nxio, nother = 0, nother_set[2];
    fp_t fp, fp_100;
    double *fp_walk = NULL, *gx2_200_walk = NULL, *gx2_100_walk = NULL, *fp_100_walk = NULL;
    vicon_t vi;
    ipol_t ip;
    int rc, i, exp = 1, md_failed = 0;
    fnav_nav_config_t off, ar1;
    rc = hx_args_parse(&k_spec, argc, argv, &a);
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--plots", NULL };
        if (hx_refuse_dash("eval", &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    rc = hx_nav_opts_from_args("eval", &a, &o);
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    if (o.rate_hz > 0.0) {
        hx_error("eval", "--rate is not used by eval (it runs the rate experiment itself)");
        return HX_EXIT_USAGE;
    }
    {
        static const char *const outs[] = { "--out", "--json", NULL };
        if (hx_output_is_input("eval", NULL, &a, outs) || hx_profile_is_output("eval", o.profile, &a, outs)) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_arg(&a, "--plots") != NULL && hx_flag(&a, "--no-plots")) {
        /* a command-line error, said before the data are looked for (exit
         * 2, not 4 without them) */
        hx_error("eval", "--plots and --no-plots together");
        return HX_EXIT_USAGE;
    }
    memset(&ev, 0, sizeof ev);
    if (hx_nav_config(&o, &ev.cfg, err, sizeof err) != 0) {
        hx_error("eval", "%s", err);
        return HX_EXIT_USAGE;
    }
    exp = !hx_flag(&a, "--no-experiments");
    data = hx_arg(&a, "--data");
    if (data == NULL) {
        data = env_data = getenv("FNAV_DATA_DIR");
    }
    if (data == NULL || *data == '\0') {
        data = "../shared/data";
    }
    if (strlen(data) >= sizeof ev.data) {
        /* cut, it would name another directory (the figures' directory's
         * check, below) */
        hx_error("eval", "the data directory %.80s... is longer than %d bytes", data, (int)sizeof ev.data - 1);
        return HX_EXIT_USAGE;
    }
    snprintf(ev.data, sizeof ev.data, "%s", data);
    {
        /* the shared data: its MANIFEST.md, or at least one data set folder
         * (a copy holding only some of the sets is evaluated on those) */
        static const char *const sets[] = { "MANIFEST.md",     "openshoe_gx2",     "xio_ngimu_gait",
                                             "pyshoe_vicon_llio", "ipol_gait_xsens", "openshoe_c_820hz",
                                             "openshoe_square2" };
        char probe[EV_DIR_SIZE];
        FILE *f = NULL;
        DIR *d = NULL;
        size_t k;
        for (k = 0; k < sizeof sets / sizeof sets[0] && f == NULL && d == NULL; k++) {
            snprintf(probe, sizeof probe, "%s/%s", ev.data, sets[k]);
            if (k == 0) {
                f = fopen(probe, "r");
            } else {
                d = opendir(probe);
            }
        }
        if (f == NULL && d == NULL) {
            /* a --data that does not exist, or is a file, is told so, not
             * "no shared data in DIR (give --data DIR ...)" as a directory
             * without the data is */
            const char *hint = hx_arg(&a, "--data") == NULL ? "; give --data DIR or set FNAV_DATA_DIR" : "";
            struct stat st;
            if (stat(ev.data, &st) != 0) {
                hx_error("eval", "no shared data in %s: it does not exist (%s)%s", ev.data, strerror(errno), hint);
            } else if (!S_ISDIR(st.st_mode)) {
                hx_error("eval", "no shared data in %s: it is not a directory%s", ev.data, hint);
            } else {
                hx_error("eval",
                         "no shared data in %s (neither MANIFEST.md nor a data set folder such as "
                         "openshoe_gx2)%s",
                         ev.data, hint);
            }
            return HX_EXIT_UNAVAIL;
        }
        if (f != NULL) {
            fclose(f);
        }
        if (d != NULL) {
            closedir(d);
        }
    }
    out_path = hx_arg(&a, "--out");
    if (out_path == NULL) {
        out_path = "docs/results.md";
    }
    json_path = hx_arg(&a, "--json");
    if (json_path != NULL && strcmp(json_path, "-") != 0 && hx_check_writable("eval", json_path) != 0) {
        return HX_EXIT_IO; /* found out before the run, as for --out */
    }
    {
        /* the figures: --plots DIR, else img/ beside the Markdown file */
        const char *pd = hx_arg(&a, "--plots");
        char md_dir[HX_PLOT_PATH_SIZE];
        int dlen = 0;
        dir_of(strcmp(out_path, "-") == 0 ? "./-" : out_path, md_dir, sizeof md_dir);
        if (pd != NULL) {
            dlen = snprintf(ev.plot_dir, sizeof ev.plot_dir, "%s", pd);
        } else if (strcmp(out_path, "-") != 0 && !hx_flag(&a, "--no-plots")) {
            dlen = snprintf(ev.plot_dir, sizeof ev.plot_dir, "%s/img", md_dir);
        }
        if (dlen < 0 || (size_t)dlen >= sizeof ev.plot_dir) {
            /* a cut name is another directory */
            hx_error("eval", "the figures' directory %.80s... is longer than %d bytes", ev.plot_dir,
                     (int)sizeof ev.plot_dir - 1);
            return HX_EXIT_IO;
        }
        if (ev.plot_dir[0] != '\0') {
            struct stat sb;
            if (mkdir(ev.plot_dir, 0777) != 0 && errno != EEXIST) {
                hx_error("eval", "cannot create the figures' directory %s (%s)", ev.plot_dir, strerror(errno));
                return HX_EXIT_IO;
            }
            if (stat(ev.plot_dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
                /* there, but a file (mkdir's EEXIST): refused here, or each
                 * figure would fail in the middle of the run, which would
                 * end with exit 0 */
                hx_error("eval", "the figures' directory %s is not a directory", ev.plot_dir);
                return HX_EXIT_IO;
            }
            if (access(ev.plot_dir, W_OK | X_OK) != 0) {
                /* there, but no picture can be made in it (each is drawn
                 * beside its name and renamed onto it): refused here, not
                 * an error per figure in a run that ended with exit 0 */
                hx_error("eval", "cannot write in the figures' directory %s (%s)", ev.plot_dir, strerror(errno));
                return HX_EXIT_IO;
            }
            if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
                hx_warn("eval", "no figures: gnuplot is not installed (apt-get install gnuplot-nox)");
            } else {
                char rel[HX_PLOT_PATH_SIZE];
                ev.plots = 1;
                hx_plot_failure_warns(1); /* eval goes on without a figure (see figure()) */
                rel_path(md_dir, ev.plot_dir, rel, sizeof rel);
                md_link(rel, ev.plot_link, sizeof ev.plot_link);
            }
        }
    }
    {
        /* the closed walks without a file-name convention of their own */
        static const char *const osets[2][2] = { { "openshoe_c_820hz", ".txt" }, { "openshoe_square2", ".csv" } };
        ev_name_t *names[2];
        int k, j, n[2];
        nxio = list_set(&ev, "xio_ngimu_gait", k_csv_files, 1, 0, &xio);
        for (k = 0; k < 2; k++) {
            n[k] = list_set(&ev, osets[k][0], &osets[k][1], 1, 0, &names[k]);
            nother_set[k] = n[k];
        }
        other = (char (*)[300])ev_calloc((size_t)(n[0] + n[1]), sizeof *other);
        for (k = 0; k < 2; k++) {
            for (j = 0; j < n[k]; j++) {
                snprintf(other[nother++], sizeof other[0], "%.40s/%s", osets[k][0], names[k][j]);
            }
            free(names[k]);
        }
        xio3 = (double *)ev_calloc((size_t)nxio, sizeof *xio3);
        other3 = (double *)ev_calloc(2 * (size_t)nother, sizeof *other3);
        other_hz = other3 + nother;
    }
    {
        /* progress: one run per walk or trial and configuration */
        ev_name_t *names;
        int ngx2, nfp, nvi, nip;
        ngx2 = list_set(&ev, "openshoe_gx2", k_gx2_files, 1, 0, &names);
        free(names);
        nfp = list_set(&ev, "pyshoe_vicon_llio/own_3dmgx5_footprints", k_fp_files, 3, 1, &names);
        free(names);
        nvi = list_set(&ev, "pyshoe_vicon_llio/vicon_3dmgx3", k_vicon_files, 2, 1, &names);
        free(names);
        nip = 2 * list_set(&ev, "ipol_gait_xsens", k_ipol_files, 3, 1, &names);
        free(names);
        ev.total_runs = ngx2 + nxio + nother + nfp + nvi + nip;
        if (ev.total_runs == 0 && ev.n_unreadable == 0) {
            /* a MANIFEST.md or data set folders, but not one walk in them
             * (a copy not synced, a wrong directory): nothing to run on,
             * said before results.md is touched (not overwritten with "no
             * data" in every section, exit 0) */
            hx_error("eval", "no walk or trial in any data set folder of %s: nothing to evaluate", ev.data);
            free(xio);
            free(other);
            free(xio3);
            free(other3);
            return HX_EXIT_UNAVAIL;
        }
        if (exp) {
            ev.total_runs += 8 * (ngx2 + nfp + nvi + nxio) + 2 * (ngx2 + nxio + nother) + nfp;
        }
    }
    ev.md = strcmp(out_path, "-") == 0 ? stdout : md_open(out_path, md_path, sizeof md_path);
    if (ev.md == NULL) {
        hx_error("eval", "cannot write %s (%s)", out_path, strerror(errno));
        free(xio);
        free(other);
        free(xio3);
        free(other3);
        return HX_EXIT_IO;
    }
    hx_progress_start(&ev.prog, "eval", ev.total_runs);
    /* each walk is replayed up to 11 times (its table's run and the
     * experiments' repeats): the reader's warnings and notes about it are
     * printed by its first run only, the repeats counted below */
    hx_warn_once(1);
    off = ev.cfg;
    off.bias_model = FNAV_BIAS_OFF;
    ar1 = ev.cfg;
    ar1.bias_model = FNAV_BIAS_AR1;

    /* the shortest ZUPT run: fixed, or scaled with the gait cycle (the
     * default; docs/navigation.md, "Cycle-scaled shortest
     * run"), which moves every walk's figures */
    if (ev.cfg.stance.min_zupt_cycle > FNAV_R(0.0)) {
        snprintf(zupt_run, sizeof zupt_run, "%g ms or `min_zupt_cycle` %g of the gait cycle if longer",
                 1e3 * (double)ev.cfg.stance.min_zupt_s, (double)ev.cfg.stance.min_zupt_cycle);
    } else {
        snprintf(zupt_run, sizeof zupt_run, "%g ms (`min_zupt_cycle` 0)", 1e3 * (double)ev.cfg.stance.min_zupt_s);
    }
    cmdline = eval_command(argc, argv, env_data != NULL && *env_data != '\0' ? env_data : NULL);
    hx_nav_detector_label(&ev.cfg, det_label, sizeof det_label); /* as replay's config line */
    {
        char mpath[EV_PATH_SIZE];
        snprintf(mpath, sizeof mpath, "%s/MANIFEST.md", ev.data);
        manifest = is_file(mpath); /* the data's description, said absent when it is */
    }
    fprintf(ev.md, "# footnav results\n\n");
    fputs("Written by ", ev.md);
    md_code(ev.md, cmdline, NULL);
    fprintf(ev.md, " (float%s build). Every number below comes from that command;\nrerun it to reproduce them. Data: ",
            FNAV_USE_DOUBLE ? "64" : "32");
    md_code(ev.md, ev.data, NULL);
    fprintf(ev.md, " (%s). Configuration: profile `%s`, "
                   "bias model `%s`, detector `%s`%s, lever states %s, landing settling state %s, "
                   "shortest ZUPT run %s (docs/navigation.md).\n\n",
            manifest ? "MANIFEST.md" : "no MANIFEST.md",
            ev.cfg.profile.name,
            ev.cfg.bias_model == FNAV_BIAS_AR1 ? "ar1" : "off",
            ev.cfg.stance.detector == FNAV_DETECTOR_SHOE ? "shoe" : "threshold", det_label,
            ev.cfg.lever ? "on" : "off",
            ev.cfg.settle ? "on" : "off", zupt_run);
    free(cmdline);

    fprintf(ev.md, "## openshoe_gx2: return to start (closed loops, 250 Hz)\n\n"
                   "Error of the last stance mid-point from the first, as a fraction of the step-to-step path "
                   "through the stance mid-points. Vertical: height change, up positive.\n\n");
    closure_set(&ev, "openshoe_gx2", "_data_inert.txt", &ev.cfg, 0.0, 1, &gx2, NULL);
    if (gx2.n == 0) {
        if (!folder_unreadable(&ev, "openshoe_gx2", "\n")) {
            fputs(gx2.files > 0 ? "\nNo walk in " : "\nNo walks found in ", ev.md);
            md_code(ev.md, ev.data, "/openshoe_gx2");
            fputs(gx2.files > 0 ? " gave a result (table).\n\n" : ".\n\n", ev.md);
        }
    } else {
        fprintf(ev.md, "\nMedian horizontal %.2f %% (target <= 0.35 %%: %s), median 3-D %.2f %% (target <= 0.6 %%: %s), "
                       "worst 3-D %.2f %% (target <= 1.2 %%: %s); median vertical %+.3f m, median path %.1f m.\n\n",
                gx2.h_pct_med, met(gx2.h_pct_med <= 0.35), gx2.d3_pct_med, met(gx2.d3_pct_med <= 0.6), gx2.d3_pct_max,
                met(gx2.d3_pct_max <= 1.2), gx2.vert_med, gx2.path_med);
    }
    figure(&ev, "gx2", 0, "openshoe_gx2: paths and heights",
           "Each walk in its own navigation frame (x along the heading at the alignment), from the first aligned "
           "frame; the height up, over time. A closed loop ends where it began.");
    unread_files(&ev, "openshoe_gx2", k_gx2_files, 1);

    fprintf(ev.md, "## xio_ngimu_gait: return to start (closed loops, ~400 Hz, irregular timing)\n\n");
    if (nxio == 0) {
        if (!folder_unreadable(&ev, "xio_ngimu_gait", "")) {
            fputs("No walks found in ", ev.md);
            md_code(ev.md, ev.data, "/xio_ngimu_gait");
            fputs(".\n\n", ev.md);
        }
    } else {
        char p[EV_PATH_SIZE], note[EV_NOTE_SIZE];
        fprintf(ev.md, "| walk | path (m) | horizontal (m) | 3-D (m) | 3-D (%%) | vertical (m) | vendor 3-D (m) | "
                       "duplicates | gaps | longest interval (ms) | result |\n");
        fprintf(ev.md, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
        for (i = 0; i < nxio; i++) {
            hx_traj_t t;
            hx_nav_summary_t s;
            double vendor = xio_vendor_m(xio[i]);
            char vs[32], cell[EV_CELL_SIZE];
            xio3[i] = (double)NAN;
            snprintf(p, sizeof p, "%s/xio_ngimu_gait/%s", ev.data, xio[i]);
            xs_found |= strcmp(xio[i], "short_walk.csv") == 0;
            xl_found |= strcmp(xio[i], "long_walk.csv") == 0;
            if (replay(&ev, p, &ev.cfg, 0.0, 1, &t, &s, note, sizeof note) != 0 ||
                no_closure(&ev, p, &s, &t, note, sizeof note)) {
                not_run_row(&ev, 1, md_cell(xio[i], cell, sizeof cell), 9, note);
                continue;
            }
            xio3[i] = s.end_3d_m;
            if (strcmp(xio[i], "short_walk.csv") == 0) {
                xs = s.end_3d_m;
            } else if (strcmp(xio[i], "long_walk.csv") == 0) {
                xl = s.end_3d_m;
            }
            snprintf(vs, sizeof vs, isfinite(vendor) ? "%.3f" : "-", vendor);
            fprintf(ev.md, "| %s | %.2f | %.3f | %.3f | %.2f | %+.3f | %s | %u | %u | %.1f | %s%s%s |\n",
                    md_cell(xio[i], cell, sizeof cell),
                    s.path_m, s.end_h_m, s.end_3d_m, s.end_3d_pct, s.vertical_m, vs, t.stats.duplicates,
                    t.stats.gaps, 1e3 * (double)t.stats.max_gap_seen_s,
                    !isfinite(vendor) ? "no vendor figure"
                                      : (s.end_3d_m < vendor ? "better than vendor" : "**worse than vendor**"),
                    note[0] ? "; " : "", note);
            if (ev.plots) {
                hx_evplot_add_path(&ev.fig, xio[i], &t);
            }
            hx_traj_free(&t);
        }
        fprintf(ev.md, "\nThe vendor's figures come from an offline method that uses future samples; footnav is "
                       "causal.\n\n");
        figure(&ev, "xio", 0, "xio_ngimu_gait: paths and heights",
               "As above. The climb of the height is the unmet xio target (docs/xio-climb.md, \"The xio walks\").");
    }
    unread_files(&ev, "xio_ngimu_gait", k_csv_files, 1);

    fprintf(ev.md, "## Other closed walks (no measured truth)\n\n"
                   "Walks that the MANIFEST describes as returning to the start (from the sources' plots, not "
                   "measured): the closure is reported, not judged. A walk with almost every frame in stance and "
                   "a path of centimetres moved too gently for the foot-tuned detector (docs/navigation.md, "
                   "\"Stance detector\").\n\n");
    if (nother == 0) {
        const int u0 = folder_unreadable(&ev, "openshoe_c_820hz", ""), u1 = folder_unreadable(&ev, "openshoe_square2", "");
        if (!u0 && !u1) {
            fputs("No walks found in ", ev.md);
            md_code(ev.md, ev.data, "/openshoe_c_820hz");
            fputs(" or ", ev.md);
            md_code(ev.md, ev.data, "/openshoe_square2");
            fputs(".\n\n", ev.md);
        } else if (!u0 || !u1) {
            fputs("No walks found in ", ev.md);
            md_code(ev.md, ev.data, u0 ? "/openshoe_square2" : "/openshoe_c_820hz");
            fputs(".\n\n", ev.md);
        }
    } else {
        /* one of the two sets absent: said, as every other absent set */
        for (i = 0; i < 2; i++) {
            const char *sub = i == 0 ? "openshoe_c_820hz" : "openshoe_square2";
            if (nother_set[i] == 0 && !folder_unreadable(&ev, sub, "")) {
                fputs("No walks found in ", ev.md);
                md_code(ev.md, ev.data, i == 0 ? "/openshoe_c_820hz" : "/openshoe_square2");
                fputs(".\n\n", ev.md);
            }
        }
        char p[EV_PATH_SIZE], note[EV_NOTE_SIZE];
        fprintf(ev.md, "| walk | rate (Hz) | path (m) | horizontal (m) | 3-D (m) | 3-D (%%) | vertical (m) | "
                       "frames in stance (%%) | strides | note |\n");
        fprintf(ev.md, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
        for (i = 0; i < nother; i++) {
            hx_traj_t t;
            hx_nav_summary_t s;
            char pct[32], cell[EV_CELL_SIZE];
            other3[i] = other_hz[i] = (double)NAN;
            snprintf(p, sizeof p, "%s/%.300s", ev.data, other[i]);
            if (replay(&ev, p, &ev.cfg, 0.0, 1, &t, &s, note, sizeof note) != 0) {
                not_run_row(&ev, 1, md_cell(other[i], cell, sizeof cell), 8, note);
                continue;
            }
            other3[i] = s.end_3d_m;
            if (hx_nav_little_motion(&s)) {
                snprintf(note + strlen(note), sizeof note - strlen(note), "%s%.0f %% of frames in stance: motion "
                         "below the detector's threshold", note[0] ? "; " : "", 100.0 * s.stance_fraction);
            }
            other_hz[i] = t.rate_hz;
            /* a walk without a stride has no path: its 3-D % is none ("-",
             * not "nan") */
            fprintf(ev.md, "| %s | %.0f | %.2f | %.3f | %.3f | %s | %+.3f | %.1f | %ld | %s |\n",
                    md_cell(other[i], cell, sizeof cell),
                    t.rate_hz, s.path_m, s.end_h_m, s.end_3d_m, fmt_v(pct, sizeof pct, "%.2f", s.end_3d_pct),
                    s.vertical_m, 100.0 * s.stance_fraction, s.strides, note);
            if (ev.plots) {
                hx_evplot_add_path(&ev.fig, other[i], &t);
            }
            hx_traj_free(&t);
        }
        fprintf(ev.md, "\n");
        figure(&ev, "other", 0, "other closed walks: paths and heights", "As above.");
    }
    unread_files(&ev, "openshoe_c_820hz", k_txt_files, 1);
    unread_files(&ev, "openshoe_square2", k_csv_files, 1);

    fprintf(ev.md, "## pyshoe_vicon_llio / own_3dmgx5_footprints: per-stride error against measured footprints\n\n"
                   "Estimated position at each stride sample against the footprint measured with a ruler, both "
                   "in the initial-heading frame (the `_strides_gcp.csv` truth), starting at the first stride.\n\n");
    footprints(&ev, &ev.cfg, 0.0, 1, &fp, &fp_walk);
    if (fp.n == 0) {
        if (!folder_unreadable(&ev, "pyshoe_vicon_llio/own_3dmgx5_footprints", "\n")) {
            fputs(fp.files > 0 ? "\nNo walk in " : "\nNo walks found in ", ev.md);
            md_code(ev.md, ev.data, "/pyshoe_vicon_llio/own_3dmgx5_footprints");
            fputs(fp.files > 0 ? " gave a result (table).\n\n" : ".\n\n", ev.md);
        }
    } else {
        fprintf(ev.md, "\nMedian final-stride error %.2f %% of the measured path (target <= 2 %%: %s), mean %.2f %%, "
                       "median %.2f m; median of the per-walk median stride errors %.3f m. Reference: pyshoe with its "
                       "SHOE detector, 1.43 m median final error, 4.3 %% mean.\n\n",
                fp.final_pct_med, met(fp.final_pct_med <= 2.0), fp.final_pct_mean, fp.final_m_med, fp.stride_med);
    }
    figure(&ev, "footprints", 1, "own_3dmgx5_footprints: estimate at each stride against the measured footprints",
           "Per walk, in the initial-heading frame, both from the first stride: the estimated path (grey), the "
           "estimate at each stride sample (red) and the footprint measured there (circles).");
    unread_files(&ev, "pyshoe_vicon_llio/own_3dmgx5_footprints", k_fp_files, 3);

    fprintf(ev.md, "## pyshoe_vicon_llio / vicon_3dmgx3: per-stride error against motion capture\n\n");
    vicon(&ev, &ev.cfg, 1, &vi, NULL);
    if (vi.n == 0) {
        if (!folder_unreadable(&ev, "pyshoe_vicon_llio/vicon_3dmgx3", "\n")) {
            fputs(vi.files > 0 ? "\nNo trial in " : "\nNo trials found in ", ev.md);
            md_code(ev.md, ev.data, "/pyshoe_vicon_llio/vicon_3dmgx3");
            fputs(vi.files > 0 ? " gave a result (table).\n\n" : ".\n\n", ev.md);
        }
    } else {
        fprintf(ev.md, "\n%d trials, %d strides: median of the per-trial median stride errors %.3f m, median RMS %.3f m, "
                       "median final error %.3f m.\n\n",
                vi.n, vi.strides, vi.stride_med, vi.rms_med, vi.final_med);
    }
    figure(&ev, "vicon", 1, "vicon_3dmgx3: estimate at each stride against the motion capture",
           "As the footprints, against the motion capture's position at each stride sample.");
    unread_files(&ev, "pyshoe_vicon_llio/vicon_3dmgx3", k_vicon_files, 2);

    fprintf(ev.md, "## ipol_gait_xsens: stance detection and gait events against the experts\n\n"
                   "Strides of the straight walking phases (inside the trial, clear of the U-turn, which the "
                   "experts annotate only partly), leaving out expert swings that overlap an expert swing of the "
                   "other foot (both feet in the air, which no walking stride has). An expert swing is detected "
                   "when a detected swing overlaps it and the nearest foot-off and foot-strike lie within %d "
                   "samples of its ends. Event errors in samples at 100 Hz (packets, dropped ones counted): "
                   "foot-off (FO) against the start, foot-strike (FS) against the end of the expert swing.\n\n",
            IPOL_TOL);
    ipol(&ev, &ev.cfg, 1, &ip);
    if (ip.trials == 0) {
        if (!folder_unreadable(&ev, "ipol_gait_xsens", "\n")) {
            fputs(ip.files > 0 ? "\nNo trial in " : "\nNo trials found in ", ev.md);
            md_code(ev.md, ev.data, "/ipol_gait_xsens");
            fputs(ip.files > 0 ? " gave a result (table).\n\n" : ".\n\n", ev.md);
        }
    } else {
        fprintf(ev.md, "\n%d trials and feet: %d expert strides, %d detected, %d missed (%d of them overlapped by a "
                       "detected swing whose events are %d samples or more away), %d spurious (target: none "
                       "missed or spurious: %s); %d expert swings left out for overlapping the other foot's "
                       "(with them kept: %d missed, %d spurious). ",
                ip.trials, ip.expected, ip.detected, ip.missed, ip.off_time, IPOL_TOL, ip.spurious,
                ipol_judged(&ip, ip.missed == 0 && ip.spurious == 0), ip.both_feet, ip.strict_missed,
                ip.strict_spurious);
        if (ip.expected == 0) {
            /* no expert swing to evaluate (logs cut before the first one):
             * nothing judged, not "met" on nothing */
            fprintf(ev.md, "Event timing: no expert swing to evaluate, no event to time (target <= 2: nothing "
                           "evaluated).\n\n");
        } else if (ip.n_fo > 0) {
            fprintf(ev.md, "Event timing: median |FO error| %.1f samples (bias %+.1f, 90th percentile %.1f), median "
                           "|FS error| %.1f samples (bias %+.1f, 90th percentile %.1f) (target <= 2: %s).\n\n",
                    ip.fo_med, ip.fo_bias, ip.fo_p90, ip.fs_med, ip.fs_bias, ip.fs_p90,
                    met(ip.fo_med <= 2.0 && ip.fs_med <= 2.0));
        } else {
            /* every expert swing missed: no event was timed (said so, not
             * "nan samples") */
            fprintf(ev.md, "Event timing: no expert swing detected, no event to time (target <= 2: %s).\n\n",
                    met(0));
        }
    }
    if (ev.ipol_fig) {
        fprintf(ev.md, "![ipol_gait_xsens: gait-event timing error](%s/eval-ipol.png)\n\nEvery matched event's "
                       "signed error (detector minus experts), foot-off and foot-strike, in samples at 100 Hz.\n\n",
                ev.plot_link);
    }
    unread_files(&ev, "ipol_gait_xsens", k_ipol_files, 3);
    ev.main_failures = ev.failures;

    if (exp) {
        fnav_nav_config_t c2 = ev.cfg;
        {
            /* the bias model off and on (AR(1)) with each built-in table
             * and with the generic MEMS profile of docs/profiles (literature
             * reading of sigma_bias): a pair per profile, so that within a
             * pair only the model differs (the profile also sets the white
             * noise; one "off" column, with the generic profile's white
             * noise, would not stand for every table) */
#define EV_NP 4
#define EV_NC (2 * EV_NP)
            /* the built-in generic-mems is docs/profiles/generic-mems.profile
             * value for value (tests/test_profile.c); by its name, so that
             * eval run outside the repository root keeps the default's pair
             * (the file's path is relative: outside the root the column pair
             * would be dropped with a warning, exit 0, the text still
             * calling the last columns the default's) */
            static const char *const prof[EV_NP] = { "navchip", "mtx", "shimmer", "generic-mems" };
            static const char *const pname[EV_NP] = { "navchip", "mtx", "shimmer", "generic MEMS" };
            closure_t g[EV_NC];
            fp_t fpv[EV_NC];
            vicon_t vv[EV_NC];
            double *wg[EV_NC], *wf[EV_NC], *wv[EV_NC];
            double *x3 = (double *)ev_calloc(EV_NC * (size_t)(nxio > 0 ? nxio : 1), sizeof *x3);
            int b, pi, ok[EV_NP], ngf = 0, nff = 0, nvf = 0;
            fprintf(ev.md, "## Paper experiment 1: AR(1) bias model on vs off\n\n"
                           "Same walks and configuration; for each profile (the paper's Tables IV-VI, and "
                           "`docs/profiles/generic-mems.profile`: bias instability as the stationary sd, 100 s; the "
                           "built-in `generic-mems`; docs/navigation.md, \"Bias model\") the walks run with "
                           "`--bias-model off` and `ar1`, so that within a profile's pair only the bias model "
                           "differs (the profile also sets the white noise). The navigation's default profile "
                           "and bias model are the last column's.\n\n");
            for (b = 0; b < EV_NC; b++) {
                wg[b] = wf[b] = wv[b] = NULL;
            }
            for (pi = 0; pi < EV_NP; pi++) {
                char perr[HX_ERR_SIZE];
                fnav_profile_t pr;
                ok[pi] = 1;
                if (hx_profile_load(prof[pi], &pr, perr, sizeof perr) != 0) {
                    hx_warn("eval", "bias-model experiment: %s", perr);
                    ok[pi] = 0;
                    continue;
                }
                for (b = 2 * pi; b < 2 * pi + 2; b++) {
                    fnav_nav_config_t cv = b == 2 * pi ? off : ar1;
                    cv.profile = pr;
                    closure_set(&ev, "openshoe_gx2", "_data_inert.txt", &cv, 0.0, 0, &g[b], &wg[b]);
                    ngf = g[b].files;
                    footprints(&ev, &cv, 0.0, 0, &fpv[b], &wf[b]);
                    nff = fpv[b].files;
                    vicon(&ev, &cv, 0, &vv[b], &wv[b]);
                    nvf = vv[b].files;
                    for (i = 0; i < nxio; i++) {
                        char p[EV_PATH_SIZE];
                        snprintf(p, sizeof p, "%s/xio_ngimu_gait/%s", ev.data, xio[i]);
                        x3[b * nxio + i] = closure_3d_m(&ev, p, &cv, 0.0, 1);
                    }
                }
            }
            fprintf(ev.md, "| data set | figure |");
            for (b = 0; b < EV_NC; b++) {
                if (ok[b / 2]) {
                    fprintf(ev.md, " %s %s |", pname[b / 2], b % 2 ? "ar1" : "off");
                }
            }
            fprintf(ev.md, "\n|---|---|");
            for (b = 0; b < EV_NC; b++) {
                if (ok[b / 2]) {
                    fprintf(ev.md, "---:|");
                }
            }
            fprintf(ev.md, "\n");
#define EV_ROW(label, fmt, expr)                                                                                     \
    do {                                                                                                             \
        fprintf(ev.md, "| %s |", label);                                                                             \
        for (b = 0; b < EV_NC; b++) {                                                                                \
            if (ok[b / 2] && isfinite(expr)) {                                                                       \
                fprintf(ev.md, " " fmt " |", (expr));                                                                \
            } else if (ok[b / 2]) {                                                                                  \
                fprintf(ev.md, " - |");                                                                              \
            }                                                                                                        \
        }                                                                                                            \
        fprintf(ev.md, "\n");                                                                                        \
    } while (0)
            EV_ROW("openshoe_gx2 | median horizontal closure (%)", "%.2f", g[b].h_pct_med);
            EV_ROW("openshoe_gx2 | median 3-D closure (%)", "%.2f", g[b].d3_pct_med);
            EV_ROW("openshoe_gx2 | worst 3-D closure (%)", "%.2f", g[b].d3_pct_max);
            EV_ROW("openshoe_gx2 | median vertical (m)", "%+.3f", g[b].vert_med);
            EV_ROW("footprints | median final-stride error (% of path)", "%.2f", fpv[b].final_pct_med);
            EV_ROW("footprints | mean final-stride error (% of path)", "%.2f", fpv[b].final_pct_mean);
            EV_ROW("vicon | median of the per-trial median stride errors (m)", "%.3f", vv[b].stride_med);
            for (i = 0; i < nxio; i++) {
                char label[EV_CELL_SIZE + 64], cell[EV_CELL_SIZE];
                snprintf(label, sizeof label, "xio %s | 3-D closure (m)", md_cell(xio[i], cell, sizeof cell));
                EV_ROW(label, "%.3f", x3[b * nxio + i]);
            }
#undef EV_ROW
            /* the spread: the paired differences walk by walk */
            fprintf(ev.md, "\nThe same comparison walk by walk: the difference off - ar1 of each walk's figure "
                           "(positive: the AR(1) model's is smaller, better), its median and range over the walks, "
                           "how many walks the model improves, and the two-sided sign test's p on that count (ties "
                           "left out). With 6 walks only 6 of 6 reaches p < 0.05 (0.031), with 7 only 7 of 7 "
                           "(0.016), with the 2 xio walks nothing can.\n\n"
                           "| profile | figure (per walk) | walks | ar1 better | off - ar1: median [min, max] | "
                           "sign test p |\n|---|---|---:|---:|---|---:|\n");
            for (pi = 0; pi < EV_NP; pi++) {
                const int bo = 2 * pi, ba = 2 * pi + 1;
                if (!ok[pi]) {
                    continue;
                }
                paired_row(&ev, pname[pi], "openshoe_gx2 horizontal closure (%)", "%+.2f", wg[bo], wg[ba], ngf);
                paired_row(&ev, pname[pi], "footprints final-stride error (%)", "%+.2f", wf[bo], wf[ba], nff);
                paired_row(&ev, pname[pi], "vicon median stride error (m)", "%+.3f", wv[bo], wv[ba], nvf);
                paired_row(&ev, pname[pi], "xio 3-D closure (m)", "%+.3f", x3 + bo * nxio, x3 + ba * nxio, nxio);
            }
            for (b = 0; b < EV_NC; b++) {
                free(wg[b]);
                free(wf[b]);
                free(wv[b]);
            }
            free(x3);
#undef EV_NC
#undef EV_NP
        }
        fprintf(ev.md, "\n## Paper experiment 2: 100 Hz vs 200 Hz\n\n"
                       "The higher-rate walks resampled (anti-alias low-pass, docs/harness.md) to 200 and 100 Hz, "
                       "configuration as above (bias model `%s`; the detector's window and durations are set in "
                       "seconds, so they scale with the rate). The footprint walks are recorded at 200 Hz: their "
                       "200 Hz column is the native run, not resampled.\n\n",
                ev.cfg.bias_model == FNAV_BIAS_AR1 ? "ar1" : "off");
        closure_set(&ev, "openshoe_gx2", "_data_inert.txt", &c2, 200.0, 0, &gx2_200, &gx2_200_walk);
        closure_set(&ev, "openshoe_gx2", "_data_inert.txt", &c2, 100.0, 0, &gx2_100, &gx2_100_walk);
        footprints(&ev, &c2, 100.0, 0, &fp_100, &fp_100_walk);
        fprintf(ev.md, "| data set | figure | native | 200 Hz | 100 Hz |\n|---|---|---:|---:|---:|\n");
        if (gx2.n > 0) {
            row3(ev.md, "openshoe_gx2 (250 Hz) | median horizontal closure (%)", "%.2f", gx2.h_pct_med,
                 gx2_200.h_pct_med, gx2_100.h_pct_med);
            row3(ev.md, "openshoe_gx2 (250 Hz) | median 3-D closure (%)", "%.2f", gx2.d3_pct_med,
                 gx2_200.d3_pct_med, gx2_100.d3_pct_med);
            row3(ev.md, "openshoe_gx2 (250 Hz) | median vertical (m)", "%+.3f", gx2.vert_med, gx2_200.vert_med,
                 gx2_100.vert_med);
        }
        if (fp.n > 0) {
            row3(ev.md, "footprints (200 Hz) | median final-stride error (%)", "%.2f", fp.final_pct_med,
                 fp.final_pct_med, fp_100.final_pct_med);
        }
        {
            const double rates[2] = { 200.0, 100.0 };
            char label[2 * EV_CELL_SIZE], cell[EV_CELL_SIZE];
            int k;
            for (i = 0; i < nxio + nother; i++) {
                char p[EV_PATH_SIZE];
                double r3[3];
                if (i < nxio) {
                    snprintf(p, sizeof p, "%s/xio_ngimu_gait/%s", ev.data, xio[i]);
                    r3[0] = xio3[i];
                } else {
                    snprintf(p, sizeof p, "%s/%.300s", ev.data, other[i - nxio]);
                    r3[0] = other3[i - nxio];
                    if (!(other_hz[i - nxio] > 200.0)) {
                        continue; /* not above the experiment's rates */
                    }
                }
                for (k = 0; k < 2; k++) {
                    r3[k + 1] = closure_3d_m(&ev, p, &c2, rates[k], i < nxio);
                }
                if (i < nxio) {
                    snprintf(label, sizeof label, "xio %s (~400 Hz) | 3-D closure (m)", md_cell(xio[i], cell, sizeof cell));
                } else {
                    snprintf(label, sizeof label, "%s (%.0f Hz) | 3-D closure (m)", md_cell(other[i - nxio], cell, sizeof cell),
                             other_hz[i - nxio]);
                }
                row3(ev.md, label, "%.3f", r3[0], r3[1], r3[2]);
            }
        }
        fprintf(ev.md, "\nWalk by walk: the difference 100 Hz - 200 Hz of each walk's figure (positive: 200 Hz is "
                       "better), its median and range, and the two-sided sign test on the count (as in experiment "
                       "1).\n\n| rates | figure (per walk) | walks | 200 Hz better | 100 Hz - 200 Hz: median [min, max] "
                       "| sign test p |\n|---|---|---:|---:|---|---:|\n");
        paired_row(&ev, "100 vs 200 Hz", "openshoe_gx2 horizontal closure (%)", "%+.2f", gx2_100_walk, gx2_200_walk,
                   gx2_200.files);
        paired_row(&ev, "100 vs 200 Hz", "footprints final-stride error (%)", "%+.2f", fp_100_walk, fp_walk,
                   fp_100.files);
        fprintf(ev.md, "\n");
    }
    free(fp_walk);
    free(gx2_200_walk);
    free(gx2_100_walk);
    free(fp_100_walk);
    free(xio);
    free(other);
    free(xio3);
    free(other3);
    fprintf(ev.md, "## Targets\n\n| target | measured | status |\n|---|---|---|\n");
    {
        char v[96];
        fprintf(ev.md, "| openshoe_gx2 horizontal median <= 0.35 %% | %s | %s |\n", fmt_pct(v, sizeof v, gx2.h_pct_med),
                target(set_found(&ev, "openshoe_gx2", gx2.files), gx2.n, gx2.h_pct_med <= 0.35));
        fprintf(ev.md, "| openshoe_gx2 3-D median <= 0.6 %% | %s | %s |\n", fmt_pct(v, sizeof v, gx2.d3_pct_med),
                target(set_found(&ev, "openshoe_gx2", gx2.files), gx2.n, gx2.d3_pct_med <= 0.6));
        fprintf(ev.md, "| openshoe_gx2 3-D worst <= 1.2 %% | %s | %s |\n", fmt_pct(v, sizeof v, gx2.d3_pct_max),
                target(set_found(&ev, "openshoe_gx2", gx2.files), gx2.n, gx2.d3_pct_max <= 1.2));
        fprintf(ev.md, "| footprints median final-stride error <= 2 %% | %s | %s |\n",
                fmt_pct(v, sizeof v, fp.final_pct_med), target(set_found(&ev, "pyshoe_vicon_llio/own_3dmgx5_footprints", fp.files), fp.n, fp.final_pct_med <= 2.0));
        fprintf(ev.md, "| xio short 3-D < 82 mm | %s | %s |\n", fmt_mm(v, sizeof v, xs),
                target(set_found(&ev, "xio_ngimu_gait", xs_found), isfinite(xs), xs < 0.082));
        fprintf(ev.md, "| xio long 3-D < 421 mm | %s | %s |\n", fmt_mm(v, sizeof v, xl),
                target(set_found(&ev, "xio_ngimu_gait", xl_found), isfinite(xl), xl < 0.421));
        if (ip.trials > 0 && ip.expected == 0) {
            snprintf(v, sizeof v, "no expert swing to evaluate, %d spurious", ip.spurious);
        } else if (ip.trials > 0) {
            snprintf(v, sizeof v, "%d missed, %d spurious (%d and %d with the %d both-feet swings kept)", ip.missed,
                     ip.spurious, ip.strict_missed, ip.strict_spurious, ip.both_feet);
        } else {
            snprintf(v, sizeof v, "-");
        }
        fprintf(ev.md, "| ipol: no missed or spurious strides | %s | %s |\n", v,
                ip.trials > 0 ? ipol_judged(&ip, ip.missed == 0 && ip.spurious == 0) : target(set_found(&ev, "ipol_gait_xsens", ip.files), 0, 0));
        if (ip.trials > 0 && ip.expected == 0) {
            snprintf(v, sizeof v, "no expert swing to evaluate");
        } else if (ip.trials > 0 && ip.n_fo > 0) {
            snprintf(v, sizeof v, "FO %.1f, FS %.1f", ip.fo_med, ip.fs_med);
        } else if (ip.trials > 0) {
            snprintf(v, sizeof v, "no event timed"); /* not "FO nan, FS nan" */
        } else {
            snprintf(v, sizeof v, "-");
        }
        fprintf(ev.md, "| ipol: median event timing error <= 2 samples | %s | %s |\n", v,
                ip.trials == 0         ? target(set_found(&ev, "ipol_gait_xsens", ip.files), 0, 0)
                : ip.expected == 0     ? "nothing evaluated"
                                       : met(ip.fo_med <= 2.0 && ip.fs_med <= 2.0));
    }
    if (ev.main_failures > 0) {
        fprintf(ev.md, "\n**%d run(s) failed** (\"not run\" in the tables above, with the reason). The figures and "
                       "targets leave them out: they are judged on incomplete data.\n",
                ev.main_failures);
    }
    if (ev.failures > ev.main_failures) {
        fprintf(ev.md, "\n%d of the experiments' runs failed (the same walks repeated with other settings; named in "
                       "the warnings, each fault once).\n",
                ev.failures - ev.main_failures);
    }
    hx_progress_end(&ev.prog);
    hx_warn_once(0);
    if (hx_warn_repeats() > 0) {
        fprintf(stderr, "harness eval: note: %ld %s repeated by the walks' later runs, printed once\n",
                hx_warn_repeats(), hx_warn_repeats() == 1 ? "warning or note" : "warnings and notes");
    }
    if (ev.failures > 0) {
        /* the experiments' count only when some of their runs failed (with
         * --no-experiments it read "1 run(s) failed, and 0 of the
         * experiments' runs"); said before the outputs are closed, so that
         * an output that cannot be written (exit 3, below) does not hide it
         * (`--json -` into a closed pipe left only "cannot write -") */
        const int exp_failed = ev.failures - ev.main_failures;
        char runs[40] = "", also[80] = "";
        if (ev.main_failures > 0) {
            snprintf(runs, sizeof runs, "%d run%s", ev.main_failures, ev.main_failures == 1 ? "" : "s");
        }
        if (exp_failed > 0) {
            snprintf(also, sizeof also, "%s%d of the experiments' runs", ev.main_failures > 0 ? ", and " : "",
                     exp_failed);
        }
        hx_error("eval", "%s%s failed (see the warnings); the results are incomplete", runs, also);
    }
    if (ev.md != stdout) {
        /* a write that failed on the way (ferror) or at the close: said
         * with the reason, and the JSON still written (not returned before
         * it without a reason) */
        const int werr = ferror(ev.md);
        const int cerr = fclose(ev.md) != 0 ? errno : 0;
        const int rerr = md_finish(md_path, !werr && cerr == 0);
        if (werr || cerr != 0 || rerr != 0) {
            /* the previous report left as it was */
            hx_error("eval", "cannot write %s (%s)", out_path,
                     strerror(cerr != 0 ? cerr : rerr != 0 ? rerr : EIO));
            md_failed = 1;
        }
    }
    if (json_path != NULL) {
        cJSON *j = cJSON_CreateObject();
        hx_json_num(j, "gx2_h_pct_median", gx2.h_pct_med);
        hx_json_num(j, "gx2_3d_pct_median", gx2.d3_pct_med);
        hx_json_num(j, "gx2_3d_pct_worst", gx2.d3_pct_max);
        hx_json_num(j, "gx2_vertical_m_median", gx2.vert_med);
        hx_json_num(j, "xio_short_3d_m", xs);
        hx_json_num(j, "xio_long_3d_m", xl);
        hx_json_num(j, "footprints_final_pct_median", fp.final_pct_med);
        hx_json_num(j, "footprints_final_pct_mean", fp.final_pct_mean);
        hx_json_num(j, "vicon_stride_err_m_median", vi.stride_med);
        /* the counts are 0 on no trials: null, as every absent figure */
        /* missed counts of no expert swing evaluated: null, not 0 (as
         * "nothing evaluated" in the Targets) */
        hx_json_num(j, "ipol_missed", ip.trials > 0 && ip.expected > 0 ? (double)ip.missed : (double)NAN);
        hx_json_num(j, "ipol_spurious", ip.trials > 0 ? (double)ip.spurious : (double)NAN);
        hx_json_num(j, "ipol_missed_strict",
                    ip.trials > 0 && ip.expected + ip.both_feet > 0 ? (double)ip.strict_missed : (double)NAN);
        hx_json_num(j, "ipol_spurious_strict", ip.trials > 0 ? (double)ip.strict_spurious : (double)NAN);
        hx_json_num(j, "ipol_fo_err_median", ip.trials > 0 ? ip.fo_med : (double)NAN);
        hx_json_num(j, "ipol_fs_err_median", ip.trials > 0 ? ip.fs_med : (double)NAN);
        hx_json_num(j, "failed_runs", (double)ev.main_failures);
        hx_json_num(j, "failed_experiment_runs", exp ? (double)(ev.failures - ev.main_failures) : (double)NAN);
        rc = hx_write_json(json_path, j, err, sizeof err);
        cJSON_Delete(j);
        if (rc != 0) {
            hx_error("eval", "%s", err);
            return HX_EXIT_IO;
        }
    }
    if (md_failed) {
        return HX_EXIT_IO;
    }
    return ev.failures > 0 ? HX_EXIT_DATA : HX_EXIT_OK;
}
