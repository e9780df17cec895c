/* harness merge: an accelerometer's file and a gyroscope's, written apart
 * by one logger, into one log on the stamps of the faster (hx_merge.h). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_merge.h"

/* A stamp at or after it reads as a date: 1e8 s since 1970 (March 1973),
 * beyond any recording's seconds from its start (three years) */
#define MERGE_DATE_NS 100000000000000000LL

static const hx_opt_t k_opts[] = {
    { "--to", "FORMAT", "output format: bin or csv (default: from OUT's extension, .bin -> bin)", 0 },
    { "--units", "SPEC", "units the headers do not name (accel, gyro: or override; a time's unit named wins): "
                         "time=s|ms|us|ns,accel=m/s2|g|mg|ug,gyro=rad/s|deg/s|mdps; raw counts: a count's size first "
                         "(accel=0.061mg)", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "merge", "ACC GYRO OUT [options]",
    "Merge an accelerometer's file ACC and a gyroscope's file GYRO, written\n"
    "apart by one logger (MetaWear's MetaBase, phyphox, Sensor Logger), into one\n"
    "log OUT (the CSV interchange format, or .bin): the samples of the file with\n"
    "the higher rate, the other's interpolated linearly at their stamps, where\n"
    "both files have samples. Each file is delimited text (.gz too) with a time\n"
    "column and the sensor's x, y, z (docs/log-format.md, \"Accelerometer and\n"
    "gyroscope in two files\"); OUT '-' writes CSV to standard output.",
    3, 3, k_opts
};

/* The progress of one stage, a share of the whole. */
typedef struct {
    hx_progress_t *p;
    double base, span;
} stage_t;

static void stage_update(void *ctx, double frac)
{
    const stage_t *st = (const stage_t *)ctx;
    hx_progress_update(st->p, st->base + st->span * frac);
}

/* A file's one-line account. */
static void describe(const char *path, const hx_tri_t *f)
{
    const double span = f->n > 1 ? (double)(f->t_ns[f->n - 1] - f->t_ns[0]) * 1e-9 : 0.0;
    hx_line_break();
    hx_eprintf("harness merge: %s: %zu samples, %.6g Hz, %.6g s; time '%s' %s%s, x, y, z '%s', '%s', '%s' in %s%s\n",
            path, f->n, f->rate_hz, span, f->cols[0], f->time_unit != NULL ? "in " : "as dates and times",
            f->time_unit != NULL ? f->time_unit : "", f->cols[1], f->cols[2], f->cols[3], f->unit,
            strcmp(f->unit_from, "named") == 0 ? "" : strcmp(f->unit_from, "--units") == 0 ? " (--units)"
                                                                                            : " (no unit named)");
}

int hx_cmd_merge(int argc, char **argv)
{
    hx_args_t a;
    hx_csv_layout_t units;
    hx_tri_t f[2];
    hx_format_t to;
    hx_writer_t *w;
    hx_meta_t meta;
    char err[HX_ERR_SIZE];
    int rc = hx_args_parse(&k_spec, argc, argv, &a), part[2], base, other, k, exit_code = HX_EXIT_OK;
    long written = 0, before = 0, after = 0, gaps = 0;
    size_t i, j = 0;
    int64_t gap_ns, lo, hi;
    hx_progress_t pr;
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    hx_csv_layout_default(&units);
    if (hx_arg(&a, "--units") != NULL && hx_csv_units_parse(&units, hx_arg(&a, "--units"), err, sizeof err) != 0) {
        hx_error("merge", "%s", err);
        hx_usage(&k_spec, stderr);
        return HX_EXIT_USAGE;
    }
    if (hx_arg_to("merge", &a, a.pos[2], &to) != 0) {
        return HX_EXIT_USAGE;
    }
    for (k = 0; k < 2; k++) {
        if (hx_same_file(a.pos[k], a.pos[2])) {
            hx_error("merge", "%s: the output is an input (it would be overwritten while read)", a.pos[2]);
            return HX_EXIT_USAGE;
        }
    }
    if (hx_same_file(a.pos[0], a.pos[1])) {
        hx_error("merge", "%s: ACC and GYRO are one file (a log with both sensors is read as it is: bin/harness "
                          "info %s)", a.pos[0], a.pos[0]);
        return HX_EXIT_USAGE;
    }
    /* an output that cannot be written is found before the reading */
    if (strcmp(a.pos[2], "-") != 0 && hx_check_writable("merge", a.pos[2]) != 0) {
        return HX_EXIT_IO;
    }
    /* an hour at 400 Hz on each side takes 4-5 s to a CSV (2 s to a .bin:
     * docs/harness.md, "merge"), each file's reading about 30 % of it, the
     * writing of the CSV 40 % */
    hx_progress_start(&pr, "merge", 1.0);
    for (k = 0; k < 2; k++) {
        stage_t st;
        st.p = &pr;
        st.base = 0.3 * k;
        st.span = 0.3;
        part[k] = hx_tri_load_progress(&f[k], a.pos[k], k == 0 ? HX_TRI_ACC : HX_TRI_GYR, &units, stage_update, &st,
                                       err, sizeof err);
        if (part[k] < 0) {
            hx_error("merge", "%s", err);
            if (k == 1) {
                hx_tri_free(&f[0]);
            }
            return HX_EXIT_DATA;
        }
        if (part[k] > 0) {
            hx_warn("merge", "%s (the %zu sample%s before it %s merged)", f[k].error, f[k].n, f[k].n == 1 ? "" : "s",
                    f[k].n == 1 ? "is" : "are");
        }
        if (f[k].short_rows > 0 || f[k].long_rows > 0) {
            char wt[HX_ERR_SIZE];
            if (f[k].short_rows > 0) {
                hx_warn("merge", "%s", hx_field_count_text(a.pos[k], f[k].short_first, f[k].short_rows, 0,
                                                           f[k].hdr_fields, 0, wt, sizeof wt));
            }
            if (f[k].long_rows > 0) {
                hx_warn("merge", "%s", hx_field_count_text(a.pos[k], f[k].long_first, f[k].long_rows,
                                                           f[k].rows_checked, f[k].hdr_fields, 1, wt, sizeof wt));
            }
        }
        if (f[k].dmix.said) {
            char wt[HX_ERR_SIZE];
            hx_warn("merge", "%s", hx_decimal_mix_text(&f[k].dmix, a.pos[k], wt, sizeof wt));
        }
        if (f[k].cut_last > 0) {
            hx_warn("merge", "%s:%ld: " HX_CUT_LAST_TEXT, a.pos[k], f[k].cut_last);
        }
        if (f[k].time_asked != NULL) {
            hx_warn("merge", "%s: time '%s' names its unit: read in %s, not in the %s of --units time=%s (the unit "
                             "of a time whose name gives none; a name that gives the wrong unit is mended in the "
                             "header)", a.pos[k], f[k].cols[0], f[k].time_unit, f[k].time_asked, f[k].time_asked);
        }
        if (f[k].steps_back > 0) {
            hx_warn("merge", "%s: %ld row%s whose stamp is not after the one before dropped", a.pos[k],
                    f[k].steps_back, f[k].steps_back == 1 ? "" : "s");
        }
        if (f[k].n < 2) {
            /* no interval: neither a rate to merge at nor a gap to judge */
            hx_error("merge", "%s: only one sample%s: merging needs two or more from each file", a.pos[k],
                     part[k] > 0 ? " before the error above" : "");
            hx_tri_free(&f[k]);
            if (k == 1) {
                hx_tri_free(&f[0]);
            }
            return HX_EXIT_DATA;
        }
        describe(a.pos[k], &f[k]);
    }
    if (f[0].t_from_start && f[1].t_from_start && f[0].t_ns[0] == 0 && f[1].t_ns[0] == 0) {
        /* MetaWear's "elapsed (s)" counts from each file's own first
         * sample: the two line up only if both sensors began together */
        hx_warn("merge", "both files' time ('%s', '%s') starts at 0: if each counts from its own first sample "
                         "(as MetaWear's elapsed does), the two are aligned only if both sensors began at once; "
                         "a column of the logger's clock (epoch, a date and time) would align them",
                f[0].cols[0], f[1].cols[0]);
    }
    /* the faster file's stamps; the accelerometer's at a rate within 1 % */
    base = f[1].rate_hz > 1.01 * f[0].rate_hz ? 1 : 0;
    other = 1 - base;
    lo = f[0].t_ns[0] > f[1].t_ns[0] ? f[0].t_ns[0] : f[1].t_ns[0];
    hi = f[0].t_ns[f[0].n - 1] < f[1].t_ns[f[1].n - 1] ? f[0].t_ns[f[0].n - 1] : f[1].t_ns[f[1].n - 1];
    if (lo > hi) {
        /* one file on a clock since 1970 (after 1973 in s), the other from
         * a start: two loggers' files, or a time column of each kind */
        const int d0 = f[0].t_ns[0] >= MERGE_DATE_NS, d1 = f[1].t_ns[0] >= MERGE_DATE_NS;
        char why[512];
        if (d0 != d1) {
            const int kd = d0 ? 0 : 1;
            snprintf(why, sizeof why, "%s's time ('%s') reads as a date (since 1970), %s's ('%s') as seconds from a "
                                      "start or a time of day: not one clock (one recording's two files share one)",
                     a.pos[kd], f[kd].cols[0], a.pos[1 - kd], f[1 - kd].cols[0]);
        } else {
            snprintf(why, sizeof why, "one recording's two files share a clock");
        }
        hx_error("merge", "the files do not overlap in time: %s spans %.9g to %.9g s, %s %.9g to %.9g s; %s",
                 a.pos[0], (double)f[0].t_ns[0] * 1e-9, (double)f[0].t_ns[f[0].n - 1] * 1e-9, a.pos[1],
                 (double)f[1].t_ns[0] * 1e-9, (double)f[1].t_ns[f[1].n - 1] * 1e-9, why);
        hx_tri_free(&f[0]);
        hx_tri_free(&f[1]);
        return HX_EXIT_DATA;
    }
    gap_ns = f[other].rate_hz > 0.0 ? (int64_t)llround(HX_MERGE_GAP_PERIODS * 1e9 / f[other].rate_hz) : INT64_MAX;
    memset(&meta, 0, sizeof meta);
    meta.format = HX_FMT_CSV;
    meta.rate_hz = f[base].rate_hz;
    snprintf(meta.sensor, sizeof meta.sensor, "merged accelerometer + gyro");
    snprintf(meta.source, sizeof meta.source, "harness merge of two files");
    w = hx_writer_open(a.pos[2], to, &meta, 0, err, sizeof err);
    if (w == NULL) {
        hx_error("merge", "%s", err);
        hx_tri_free(&f[0]);
        hx_tri_free(&f[1]);
        return HX_EXIT_IO;
    }
    hx_warn_gz_output("merge", a.pos[2], to);
    for (i = 0; i < f[base].n; i++) {
        fnav_sample_t s;
        double v[3];
        if ((i & 65535) == 0) {
            hx_progress_update(&pr, 0.6 + 0.4 * (double)i / (double)f[base].n);
        }
        const hx_tri_where_t where = hx_tri_at(&f[other], f[base].t_ns[i], &j, gap_ns, v);
        if (where != HX_TRI_IN) {
            before += where == HX_TRI_BEFORE;
            after += where == HX_TRI_AFTER;
            gaps += where == HX_TRI_GAP;
            continue;
        }
        memset(&s, 0, sizeof s);
        s.t_ns = f[base].t_ns[i];
        s.seq = (uint32_t)written;
        for (k = 0; k < 3; k++) {
            s.accel_mps2[k] = (fnav_real_t)(base == 0 ? f[0].v[i][k] : v[k]);
            s.gyro_rps[k] = (fnav_real_t)(base == 1 ? f[1].v[i][k] : v[k]);
        }
        if (hx_writer_write(w, &s) != FNAV_OK) {
            exit_code = HX_EXIT_IO; /* hx_writer_close names the error */
            break;
        }
        written++;
    }
    hx_progress_end(&pr);
    /* a file read up to an error: a .bin without END (convert's rule) */
    if ((part[0] > 0 || part[1] > 0 ? hx_writer_close_cut(w, err, sizeof err) : hx_writer_close(w, err, sizeof err)) !=
        FNAV_OK) {
        hx_error("merge", "%s", err);
        exit_code = HX_EXIT_IO;
    }
    if (exit_code == HX_EXIT_OK) {
        hx_eprintf(
                "harness merge: wrote %ld samples at the %s's stamps (%s), the %s's interpolated linearly; left out: "
                "%ld before and %ld after the %s's span, %ld in its gaps (over %.3g ms, %g of its periods)\n",
                written, base == 0 ? "accelerometer" : "gyroscope", a.pos[base],
                other == 0 ? "accelerometer" : "gyroscope", before, after,
                other == 0 ? "accelerometer" : "gyroscope", gaps, (double)gap_ns * 1e-6, HX_MERGE_GAP_PERIODS);
        if (written == 0) {
            hx_error("merge", "no sample of %s falls where %s has samples", a.pos[base], a.pos[other]);
            exit_code = HX_EXIT_DATA;
        } else if (part[0] > 0 || part[1] > 0) {
            /* the warning above named the row; exit 1 says an error too, as
             * convert's and info's (it exited 1 after warnings alone) */
            k = part[0] > 0 ? 0 : 1;
            hx_error("merge",
                     "%s: incomplete input (warned above): the %ld sample%s written cover its %zu before the error",
                     a.pos[k], written, written == 1 ? "" : "s", f[k].n);
            exit_code = HX_EXIT_DATA;
        }
    }
    hx_tri_free(&f[0]);
    hx_tri_free(&f[1]);
    return exit_code;
}
