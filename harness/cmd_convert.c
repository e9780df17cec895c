/* harness convert: any readable format -> .bin or CSV, sample by sample
 * (with --rate: the whole log resampled as replay --rate does). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_nav.h"

static const hx_opt_t k_opts[] = {
    HX_INPUT_OPTS,
    { "--to", "FORMAT", "output format: bin or csv (default: from OUT's extension, .bin in any case -> bin)", 0 },
    { "--rate", "HZ", "resample to HZ (1 to 100000, below the input's rate) first, as replay --rate (anti-alias "
                      "low-pass; docs/harness.md)", 0 },
    { "--start", "S", "keep only the samples from S seconds after the input's first (default 0)", 0 },
    { "--end", "S", "keep only the samples up to S seconds after the input's first (default: to the end)", 0 },
    { NULL, NULL, NULL, 0 }
};

/* --start / --end: a window in seconds after the input's first sample, as
 * the commands report times (the tool for allan's "cut the log to its
 * still part"). */
typedef struct {
    int64_t start_ns, end_ns; /* end_ns < 0: to the end */
    int64_t t0_ns;
    int have_t0;
    long kept;
    int64_t before_ns; /* the latest sample before the window, after the first (its span when none is past it) */
    int64_t after_ns;  /* the first sample past the window's end (-1: none seen) */
    int64_t span_ns;   /* --rate: the input's span (the resampled grid stops short of it); -1 otherwise */
} window_t;

static int in_window(window_t *wd, int64_t t_ns)
{
    int64_t dt;
    if (!wd->have_t0) {
        wd->t0_ns = t_ns;
        wd->have_t0 = 1;
    }
    dt = t_ns - wd->t0_ns;
    if (dt < wd->start_ns) {
        if (dt > wd->before_ns) {
            wd->before_ns = dt;
        }
        return 0;
    }
    if (wd->end_ns >= 0 && dt > wd->end_ns) {
        if (wd->after_ns < 0 || dt < wd->after_ns) {
            wd->after_ns = dt;
        }
        return 0;
    }
    wd->kept++;
    return 1;
}

/* The window has no sample: said, exit 1 (the output is valid and empty). */
static int window_empty(const window_t *wd, const hx_args_t *a)
{
    if (wd->kept > 0 || !wd->have_t0) {
        return 0;
    }
    /* with the log's span, or the gap the window fell in, not only "no
     * sample between 100 and the end s after the first" */
    {
        char to[96];
        const char *start = hx_arg(a, "--start") != NULL ? hx_arg(a, "--start") : "0";
        if (hx_arg(a, "--end") != NULL) {
            snprintf(to, sizeof to, "%s s", hx_arg(a, "--end"));
        } else {
            snprintf(to, sizeof to, "the end");
        }
        if (wd->after_ns >= 0) {
            hx_error("convert",
                     "%s: no sample from %s s to %s: the log has none from %.6g s to %.6g s after its first sample",
                     a->pos[0], start, to, (double)wd->before_ns * 1e-9, (double)wd->after_ns * 1e-9);
        } else {
            hx_error("convert", "%s: no sample from %s s to %s: the log spans 0-%.6g s after its first sample",
                     a->pos[0], start, to, (double)(wd->span_ns >= 0 ? wd->span_ns : wd->before_ns) * 1e-9);
        }
    }
    return 1;
}

/* What the CSV cannot carry of the input's (docs/log-format.md, "CSV
 * interchange": t,ax,...,gz[,temp]): the sensor's own counter, and a .bin
 * header's sensor name (not the 'unknown' of a log that named none), axis
 * note and nominal-rate flag, said in one line (they were dropped without a
 * word: a .bin to CSV and back read 'sensor unknown', its drops no longer
 * counted, its rate an estimate). Not the header's source: no command
 * shows it (info does not), and every .bin has one, so the warning would
 * fire on every .bin to CSV, a CSV made into a .bin and back too. */
static void warn_csv_drops(const char *path, const hx_meta_t *m, const char *out, hx_format_t to)
{
    char what[512] = "";
    size_t len;
    if (to == HX_FMT_BIN || (to == HX_FMT_AUTO && hx_ends_in(out, strlen(out), ".bin"))) {
        return; /* hx_writer_open's choice: a .bin keeps them all */
    }
    /* the counter, unless the time stamps are made of it (ipol's, square2's
     * and PicoQuake's: count / rate, so the CSV's stamps keep its gaps) */
    if (m->has_seq && m->format != HX_FMT_IPOL && m->format != HX_FMT_SQUARE2 && m->format != HX_FMT_PICOQUAKE) {
        snprintf(what, sizeof what, ", the sensor's counter (seq, by which info counts drops)");
    }
    /* the sensor's name and the axis note, a .bin header's or an
     * importer's (info on the CSV reads 'sensor unknown') */
    len = strlen(what);
    if (m->sensor[0] != '\0' && strcmp(m->sensor, "unknown") != 0) {
        snprintf(what + len, sizeof what - len, ", the sensor name '%s'", m->sensor);
    }
    len = strlen(what);
    if (m->axes[0] != '\0') {
        snprintf(what + len, sizeof what - len, ", the axis note '%s'", m->axes);
    }
    /* a .bin header's flag that its rate is the sensor's (with --rate too,
     * the grid's): a CSV's rate is always estimated from its stamps
     * (hx_reader_open), the same figure where they keep the rate, but read
     * as the stamps' (info: not "nominal"; simgap, allan and psd take the
     * estimate, the stated-rate check is gone). Not an importer's, whose
     * stamps are made of its rate (count / rate) or checked against it (MT
     * Manager's SampleTimeFine): the input had no flag a user set. */
    len = strlen(what);
    if (m->format == HX_FMT_BIN && m->rate_nominal && m->rate_hz > 0.0) {
        snprintf(what + len, sizeof what - len, ", the flag that %.6g Hz is the sensor's nominal rate (a CSV's is "
                 "estimated from its stamps)", m->rate_hz);
    }
    if (what[0] != '\0') {
        hx_warn("convert", "%s: the CSV has no place for %s: not written (a .bin keeps them: --to bin)", path,
                what + 2);
    }
}

static const hx_spec_t k_spec = {
    "convert", "IN OUT [options]",
    "Convert a log between the footnav .bin format, the CSV interchange format\n"
    "(t,ax,ay,az,gx,gy,gz[,temp] in s, m/s^2, rad/s, degC) and every importable\n"
    "format; OUT '-' writes CSV to standard output. On bad input, every sample\n"
    "before the error is written and the exit status is 1 (a .bin is left\n"
    "without its END record: every reader says it is incomplete).",
    2, 2, k_opts
};

/* convert --rate: the whole log loaded, resampled by the replay's resampler
 * (hx_nav_resample) and written; a partial input is resampled and written,
 * exit 1. */
static int convert_resampled(const hx_args_t *a, hx_format_t to, double rate, window_t *wd)
{
    hx_log_t raw, res;
    hx_writer_t *w;
    char err[HX_ERR_SIZE]; /* a reader's or the resampler's refusal: the path and a remedy (hx_log.h) */
    long dups = 0, k;
    size_t n_read; /* the input's samples read, before its error if any */
    double fs = 0.0;
    int exit_code, lrc;
    fnav_sample_t s;
    lrc = hx_load_input("convert", a, a->pos[0], &raw);
    if (lrc < 0) {
        return HX_EXIT_DATA;
    }
    exit_code = lrc > 0 ? HX_EXIT_DATA : HX_EXIT_OK;
    if (hx_nav_resample(&raw, rate, (double)fnav_nav_config_default.max_gap_s, &res, &dups, &fs, err, sizeof err) != 0) {
        hx_error("convert", "%s: %s", a->pos[0], err);
        hx_log_free(&raw);
        return HX_EXIT_DATA;
    }
    res.meta = raw.meta;
    res.meta.rate_hz = rate;
    res.meta.rate_nominal = 1;
    res.meta.has_temp = 0; /* the resampler carries no temperature */
    res.meta.has_seq = 0;  /* nor the sensor's counter: its seq is a running index (marked as "the
                              sensor's own counter", info would count no drops) */
    if (lrc > 0 && wd->end_ns >= 0 && raw.n > 0 && fs > 0.0) {
        /* an --end before the error: the window is whole, as without
         * --rate, when the samples read reach past it by the resampler's
         * kernel (half length ceil(20 fs / rate) input samples,
         * hx_nav_resample): exit 0, the .bin closed (it was cut, exit 1) */
        const double reach_s = (ceil(20.0 * fs / rate) + 1.0) / fs;
        if (1e-9 * (double)(raw.t_ns[raw.n - 1] - raw.t_ns[0]) > 1e-9 * (double)wd->end_ns + reach_s) {
            exit_code = HX_EXIT_OK;
        }
    }
    n_read = raw.n;
    if (raw.n > 0) {
        wd->t0_ns = raw.t_ns[0]; /* the window counts from the input's first sample */
        wd->have_t0 = 1;
        wd->span_ns = raw.t_ns[raw.n - 1] - raw.t_ns[0]; /* as without --rate: 41.618 s, not the grid's 41.61 */
    }
    hx_log_free(&raw);
    w = hx_writer_open(a->pos[1], to, &res.meta, 0, err, sizeof err);
    if (w == NULL) {
        hx_error("convert", "%s", err);
        hx_log_free(&res);
        return HX_EXIT_IO;
    }
    hx_warn_gz_output("convert", a->pos[1], to);
    warn_csv_drops(a->pos[0], &res.meta, a->pos[1], to);
    for (k = 0; k < (long)res.n; k++) {
        hx_log_sample(&res, (size_t)k, &s);
        if (!in_window(wd, s.t_ns)) {
            continue;
        }
        if (hx_writer_write(w, &s) != FNAV_OK) {
            exit_code = HX_EXIT_IO; /* hx_writer_close below names the error, with its reason */
            break;
        }
    }
    hx_log_free(&res);
    /* an input read up to an error: a .bin without END, as convert's below */
    if ((exit_code == HX_EXIT_DATA ? hx_writer_close_cut(w, err, sizeof err) : hx_writer_close(w, err, sizeof err)) !=
        FNAV_OK) {
        hx_error("convert", "%s", err);
        exit_code = HX_EXIT_IO;
    }
    if (dups > 0) {
        hx_warn("convert", "%s: %ld duplicated time stamp%s dropped before resampling", a->pos[0], dups,
                dups == 1 ? "" : "s");
    }
    if (exit_code == HX_EXIT_DATA) {
        /* the reader's warning named the line; exit 1 says an error too, as
         * without --rate and as info's and psd's closing message (it exited
         * 1 after a warning alone) */
        hx_error("convert",
                 "%s: incomplete input (warned above): the output covers the %zu sample%s before the error",
                 a->pos[0], n_read, n_read == 1 ? "" : "s");
    }
    if (exit_code == HX_EXIT_OK && window_empty(wd, a)) {
        exit_code = HX_EXIT_DATA;
    }
    return exit_code;
}

int hx_cmd_convert(int argc, char **argv)
{
    hx_args_t a;
    hx_reader_t *r;
    hx_writer_t *w;
    hx_format_t to;
    fnav_sample_t s;
    fnav_status_t st;
    char err[HX_ERR_SIZE];
    int rc = hx_args_parse(&k_spec, argc, argv, &a);
    int exit_code = HX_EXIT_OK;
    hx_meta_t meta;
    double rate = 0.0, start_s = 0.0, end_s = -1.0;
    window_t wd;
    hx_progress_t pr;
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    /* 1e9 s (32 years) keeps the window in int64 nanoseconds */
    if (hx_arg_double(&a, "--start", 0.0, 1e9, &start_s) != 0 || hx_arg_double(&a, "--end", 0.0, 1e9, &end_s) != 0) {
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--end") != NULL && end_s < start_s) {
        hx_error("convert", "--end %g is before --start %g", end_s, start_s);
        return HX_EXIT_USAGE;
    }
    memset(&wd, 0, sizeof wd);
    wd.start_ns = (int64_t)llround(start_s * 1e9);
    wd.end_ns = hx_arg(&a, "--end") != NULL ? (int64_t)llround(end_s * 1e9) : -1;
    wd.after_ns = -1;
    wd.span_ns = -1;
    /* --rate: the range of replay --rate (hx_nav_opts_from_args); far below
     * 1 Hz the resampler's filter half-length, 20 x input rate / rate, no
     * longer fits an int (--rate 1e-9 wrote one NaN row and exit 0) */
    if (hx_check_input_opts("convert", &a) != 0 || hx_arg_double(&a, "--rate", 1.0, 100000.0, &rate) != 0) {
        return HX_EXIT_USAGE;
    }
    if (hx_arg_to("convert", &a, a.pos[1], &to) != 0) {
        return HX_EXIT_USAGE;
    }
    if (hx_same_file(a.pos[0], a.pos[1])) {
        hx_error("convert", "%s: the output is the input (it would be overwritten while read)", a.pos[1]);
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--rate") != NULL) {
        return convert_resampled(&a, to, rate, &wd);
    }
    r = hx_open_input("convert", &a, a.pos[0]);
    if (r == NULL) {
        return HX_EXIT_DATA;
    }
    meta = *hx_reader_meta(r);
    w = hx_writer_open(a.pos[1], to, &meta, 0, err, sizeof err);
    if (w == NULL) {
        hx_error("convert", "%s", err);
        hx_reader_close(r);
        return HX_EXIT_IO;
    }
    hx_warn_gz_output("convert", a.pos[1], to);
    warn_csv_drops(a.pos[0], &meta, a.pos[1], to);
    /* a long log shows progress (a day at 100 Hz takes 11 s to CSV) */
    hx_progress_start(&pr, "convert", 1.0);
    while ((st = hx_reader_next(r, &s)) == FNAV_OK) {
        if ((hx_reader_stats(r)->records & 65535) == 0) {
            const double f = hx_reader_progress(r);
            if (f >= 0.0) {
                hx_progress_update(&pr, f);
            }
        }
        if (!in_window(&wd, s.t_ns)) {
            if (wd.end_ns >= 0 && s.t_ns - wd.t0_ns > wd.end_ns) {
                st = FNAV_END; /* past the window: the rest is not read */
                break;
            }
            continue;
        }
        if (hx_writer_write(w, &s) != FNAV_OK) {
            exit_code = HX_EXIT_IO; /* hx_writer_close below names the error, with its reason */
            break;
        }
    }
    hx_progress_end(&pr);
    if (st != FNAV_END && exit_code == HX_EXIT_OK) {
        /* the samples written: with --start/--end those of the window, not
         * the samples read ("the 200 samples before it were written" when
         * --start kept none) */
        const long n = hx_reader_stats(r)->records, kept = wd.kept;
        if (hx_arg(&a, "--start") != NULL || hx_arg(&a, "--end") != NULL) {
            hx_error("convert", "%s (the %ld sample%s of the window before it %s written, of %ld read)",
                     hx_reader_error(r), kept, kept == 1 ? "" : "s", kept == 1 ? "was" : "were", n);
        } else if (n == 0) {
            /* not "no samples (the 0 samples before it were written)" */
            hx_error("convert", "%s (the output holds no sample)", hx_reader_error(r));
        } else {
            hx_error("convert", "%s (the %ld sample%s before it %s written)", hx_reader_error(r), n,
                     n == 1 ? "" : "s", n == 1 ? "was" : "were");
        }
        exit_code = HX_EXIT_DATA;
    }
    /* a .bin of an input read up to an error gets no END record: every
     * later reader says it is incomplete (with END it read as whole) */
    if ((exit_code == HX_EXIT_DATA ? hx_writer_close_cut(w, err, sizeof err) : hx_writer_close(w, err, sizeof err)) !=
        FNAV_OK) {
        hx_error("convert", "%s", err);
        exit_code = HX_EXIT_IO;
    }
    hx_print_warnings("convert", hx_reader_take_warnings(r)); /* a cut-off last line is found at the end */
    hx_reader_close(r);
    if (exit_code == HX_EXIT_OK && window_empty(&wd, &a)) {
        exit_code = HX_EXIT_DATA;
    }
    return exit_code;
}
