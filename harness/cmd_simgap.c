/* harness simgap: where a real log and its simulated twin disagree, which
 * effect of the simulator's catalogue explains it and how far the gap
 * shrinks on held-out data (docs/simgap.md). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_profile.h"
#include "hx_simgap.h"

static const hx_opt_t k_opts[] = {
    HX_INPUT_OPTS,
    { "--static", NULL, "treat the log as static (default: detected)", 0 },
    { "--walk", NULL, "treat the log as a walk (default: detected)", 0 },
    { "--json", "FILE", "JSON report (schema in docs/simgap.md)", 0 },
    { "--plot", "DIR", "plots: static logs Allan, PSD and z, real vs twin before and after; walks the innovations", 0 },
    { "--seeds", "N", "twins per model (default 16)", 0 },
    { "--seed", "S", "first simulator seed (default 1); seeds less than 12010 apart may share twins: take seeds "
                     "20000 apart for independent repeats (docs/simgap.md, \"What --seed seeds\")", 0 },
    { "--fit-frac", "F", "fraction of the log in the fit segment (default 0.6; the rest is held out)", 0 },
    { "--contiguous", NULL, "static logs: fit on the first part (default: on both ends, held out the middle)", 0 },
    { "--alpha", "A", "false-alarm level of each family of tests: the gap tests, an effect's acceptance, the timing "
                      "domain (default 0.05)", 0 },
    { "--max-effects", "K", "forward-selection steps per channel (default 3)", 0 },
    { "--prescreen", "K", "candidates simulated per step besides lattice and line (default 3)", 0 },
    { "--profile", "NAME|FILE", "walks: baseline noise from a profile instead of the stances; static logs: also "
                                "test the profile's white + AR(1) model as given (a parameterisation check)", 0 },
    { "--closed", NULL, "walks: the walk ends where it started (drift check against the twins)", 0 },
    { "--quiet", NULL, "no progress indicator", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "simgap", "LOG [options]",
    "Sim-to-real gap: fit the baseline model (white noise + AR(1) bias per axis)\n"
    "on the first part of a real log, simulate its twin with several seeds, locate\n"
    "where real and twin disagree (Allan per tau, PSD per band, value lattice,\n"
    "timing; for walks the navigation filter's innovations and drift) with\n"
    "z-scores, and rank the simulator's catalogue effects by how much of the gap\n"
    "they explain on the held-out part of the log (forward selection, stopping\n"
    "when the rest is within noise). Input: any log format, e.g. CSV with header\n"
    "t,ax,ay,az,gx,gy,gz in SI units.",
    1, 1, k_opts
};

int hx_cmd_simgap(int argc, char **argv)
{
    hx_args_t a;
    hx_log_t log;
    sg_opts_t o = sg_opts_default();
    sg_result_t *r;
    char err[HX_ERR_SIZE]; /* a reader's refusal: the path and a remedy (hx_log.h) */
    long seeds = o.seeds, steps = o.max_steps, pre = o.prescreen;
    double frac = o.fit_frac, alpha = o.alpha, seed = (double)o.seed;
    const char *json, *plot, *path;
    int lr, status = HX_EXIT_OK;
    int pr = hx_args_parse(&k_spec, argc, argv, &a);
    if (pr != 0) {
        return pr > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--plot", NULL };
        if (hx_refuse_dash("simgap", &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_check_input_opts("simgap", &a) != 0 || hx_arg_long(&a, "--seeds", 3, SG_MAX_TWINS, &seeds) != 0 ||
        hx_arg_whole(&a, "--seed", 0.0, 4294967295.0, &seed) != 0 ||
        hx_arg_double(&a, "--fit-frac", 0.2, 0.9, &frac) != 0 ||
        hx_arg_double(&a, "--alpha", 1e-6, 0.5, &alpha) != 0 || hx_arg_long(&a, "--max-effects", 0, SG_MAX_STEPS, &steps) != 0 ||
        hx_arg_long(&a, "--prescreen", 0, 16, &pre) != 0) {
        return HX_EXIT_USAGE;
    }
    if (hx_flag(&a, "--static") && hx_flag(&a, "--walk")) {
        hx_error("simgap", "--static and --walk exclude each other");
        return HX_EXIT_USAGE;
    }
    o.domain = hx_flag(&a, "--static") ? 1 : (hx_flag(&a, "--walk") ? 2 : 0);
    o.seeds = (int)seeds;
    o.seeds_cand = (int)seeds;
    /* sim's and montecarlo's range, the whole uint32_t: every seed derived
     * from it (+ 1000 x channel, + 7000, + 7777, + a twin's index) is
     * uint32_t arithmetic, which wraps, defined */
    o.seed = (uint32_t)seed;
    o.fit_frac = frac;
    o.alpha = alpha;
    o.max_steps = (int)steps;
    o.prescreen = (int)pre;
    o.quiet = hx_flag(&a, "--quiet");
    o.contiguous = hx_flag(&a, "--contiguous");
    o.profile = hx_arg(&a, "--profile");
    if (o.profile != NULL) {
        fnav_profile_t probe; /* refused up front, as by the other commands */
        if (hx_profile_load(o.profile, &probe, err, sizeof err) != 0) {
            hx_error("simgap", "%s", err);
            return HX_EXIT_USAGE;
        }
    }
    o.closed = hx_flag(&a, "--closed");
    json = hx_arg(&a, "--json");
    plot = hx_arg(&a, "--plot");
    path = a.pos[0];
    {
        static const char *const outs[] = { "--json", "--plot", NULL };
        if (hx_output_is_input("simgap", path, &a, outs) || hx_profile_is_output("simgap", o.profile, &a, outs)) {
            return HX_EXIT_USAGE;
        }
    }
    /* the outputs are written after the diagnosis (minutes on a long log):
     * find out now that they can be */
    if (json != NULL && strcmp(json, "-") != 0 && hx_check_writable("simgap", json) != 0) {
        return HX_EXIT_IO;
    }
    if (plot != NULL) {
        /* gnuplot first: a run refused for want of it would leave the
         * directory made, empty; one made here is removed when the pictures
         * cannot be written */
        char png[4200];
        int made = 1;
        snprintf(png, sizeof png, "%s/z.png", plot);
        if (hx_plot_have_gnuplot("simgap", png) != 0) {
            return HX_EXIT_IO;
        }
        if (mkdir(plot, 0777) != 0) {
            if (errno != EEXIST) {
                hx_error("simgap", "cannot create %s: %s", plot, strerror(errno));
                return HX_EXIT_IO;
            }
            made = 0;
        }
        if (hx_plot_check("simgap", png) != 0) {
            if (made) {
                (void)remove(plot); /* an empty directory: rmdir */
            }
            return HX_EXIT_IO;
        }
        if (made) {
            /* sg_write_plots makes it again: a run that ends before the
             * plots (an input error, a log without noise, Ctrl-C) left it
             * made and empty */
            (void)remove(plot);
        }
    }
    lr = hx_load_input("simgap", &a, path, &log);
    if (lr < 0) {
        return HX_EXIT_DATA;
    }
    /* stamps in bursts: a walk refused as replay refuses it, before the
     * domain (which the wrong rate breaks) decides anything else */
    if (sg_stamps_check(&log, path, o.domain, err, sizeof err) != 0) {
        hx_error("simgap", "%s: %s", path, err);
        hx_log_free(&log);
        return HX_EXIT_DATA;
    }
    /* a static log's held-out score and likelihood-ratio tests leave one
     * twin out of each null and need 4 twins: with 3 every effect would
     * score 0 sigma and a plain tone be answered "unexplained", exit 0;
     * walks, and static logs without an attribution, work with 3 */
    if (o.seeds < 4 && o.max_steps > 0 && log.n >= 16 &&
        (o.domain == 1 || (o.domain == 0 && sg_detect_domain(&log, sg_log_rate(&log)) == 1))) {
        hx_error("simgap", "--seeds %d is too few for a static log: the held-out tests of an effect need at least 4 "
                           "twins (or --max-effects 0)", o.seeds);
        hx_log_free(&log);
        return HX_EXIT_USAGE;
    }
    r = (sg_result_t *)calloc(1, sizeof *r);
    if (r == NULL) {
        hx_log_free(&log);
        hx_error("simgap", "out of memory");
        return HX_EXIT_IO;
    }
    if (sg_diagnose(&log, path, &o, r, err, sizeof err) != 0) {
        hx_error("simgap", "%s: %s", path, err);
        hx_log_free(&log);
        sg_result_free(r);
        free(r);
        return HX_EXIT_DATA;
    }
    if (r->domain == 1 && log.t_ns != NULL && !log.meta.stamps_made && log.n > 1) {
        /* a static log's gaps, said as allan says them: its Allan
         * variances and lines join the samples across them (five 2 s gaps
         * in ten minutes moved a 0.566 Hz line and took another channel's
         * rrw; the simgap audit), which the dropout effect, if named,
         * does not undo */
        /* against the stamps' own period and resolution, as allan counts
         * them (a stated rate the stamps contradict, or stamps rounded to
         * the ms at 800 Hz, made every interval a "gap") */
        const double rate = hx_stamp_rate_hz(log.t_ns, log.n, NULL);
        double missing = 0.0, longest = 0.0;
        int64_t res_ns = 0;
        long gaps = 0;
        size_t k;
        for (k = 1; k < log.n; k++) {
            if (log.t_ns[k] > log.t_ns[k - 1]) {
                res_ns = hx_gcd_i64(log.t_ns[k] - log.t_ns[k - 1], res_ns);
            }
        }
        for (k = 1; k < log.n && rate > 0.0; k++) {
            const double lost = hx_interval_missing(log.t_ns[k] - log.t_ns[k - 1], rate, res_ns);
            if (lost > 0.0) {
                const double dt_s = (double)(log.t_ns[k] - log.t_ns[k - 1]) * 1e-9;
                gaps++;
                missing += lost;
                longest = dt_s > longest ? dt_s : longest;
            }
        }
        if (gaps > 0) {
            hx_warn("simgap", "%s: %ld gap%s (longest %.3g s; about %.0f samples missing in all, %.2g %% of the log): "
                              "the static analysis (Allan variances, lines) joins the samples across %s as if "
                              "consecutive",
                    path, gaps, gaps == 1 ? "" : "s", longest, missing,
                    100.0 * missing / ((double)log.n + missing), gaps == 1 ? "it" : "them");
        }
    }
    sg_print_summary(stdout, r);
    if (json != NULL && sg_write_json(r, json, err, sizeof err) != 0) {
        hx_error("simgap", "%s", err);
        status = HX_EXIT_IO;
    }
    if (plot != NULL && sg_write_plots(r, plot, "simgap") != 0) {
        status = HX_EXIT_IO;
    }
    /* exit 1 says why in one error line (the summary, JSON and plots are
     * written): an incomplete input (its error, FILE:LINE or record, was
     * warned when it was read, hx_load_input(): the log named, not the
     * line again, as info's and psd's closing error), else why the log is
     * too short for a confident answer */
    if (lr == 1) {
        if (!r->confident) {
            hx_error("simgap",
                     "%s: incomplete input (warned above): the %zu sample%s before the error %s too short for a "
                     "confident answer: %s",
                     path, log.n, log.n == 1 ? "" : "s", log.n == 1 ? "is" : "are", r->why);
        } else {
            hx_error("simgap", "%s: incomplete input (warned above): the results cover the %zu sample%s before the error",
                     path, log.n, log.n == 1 ? "" : "s");
        }
    } else if (!r->confident) {
        hx_error("simgap", "%s: too short for a confident answer: %s", path, r->why);
    }
    if (status == HX_EXIT_OK && (lr == 1 || !r->confident)) {
        status = HX_EXIT_DATA;
    }
    hx_log_free(&log);
    sg_result_free(r);
    free(r);
    return status;
}
