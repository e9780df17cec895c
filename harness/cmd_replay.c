/* harness replay: a log through the navigation core, sample by sample via
 * the port layer, as firmware would run it (docs/harness.md). */
#include <stdlib.h>
#include <errno.h>
#include <string.h>
#include <unistd.h>

#include "fnav_port_linux.h"
#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_nav.h"
#include "hx_profile.h"

static const hx_opt_t k_opts[] = {
    HX_INPUT_OPTS,
    HX_NAV_OPTS(HX_NAV_RATE_HELP),
    { "--out", "FILE", "trajectory CSV (time, position, velocity, attitude, biases, flags, covariance)", 0 },
    { "--json", "FILE", "summary as JSON (keys in docs/harness.md)", 0 },
    { "--plot", "FILE", "PNG of the 2-D path and of the height over time", 0 },
    { "--strides", "FILE",
      "stride CSV: gait events, swing, stance and stride time, cadence, length, height and heading change, "
      "clearance per stride",
      0 },
    { "--quiet", NULL, "no summary on standard output", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "replay", "LOG [options]",
    "Replay a log through footnav's navigation (stance detector, alignment, UKF\n"
    "with zero-velocity updates: the paper's 15 states and, by default, 3 for\n"
    "the lever of the rolling foot; --param lever=0 leaves them out) sample by\n"
    "sample through the port layer, write the trajectory, print a summary:\n"
    "duration, distance (step-to-step through stance mid-points),\n"
    "return-to-start error, vertical drift, heading change, strides, timing and\n"
    "health counters. On bad input every frame before the error is written and\n"
    "the exit status is 1.",
    1, 1, k_opts
};

int hx_cmd_replay(int argc, char **argv)
{
    hx_args_t a;
    hx_nav_opts_t o;
    fnav_nav_config_t cfg;
    hx_traj_t traj;
    hx_nav_summary_t sum;
    hx_format_t fmt = HX_FMT_AUTO;
    double in_rate = 0.0;
    const char *out_path, *json_path, *plot_path, *strides_path, *from;
    FILE *csv = NULL, *summary_to;
    /* err holds the units check's message (as long as the JSON's
     * units_problem) after the log's name: at 400 characters it was cut in
     * the third of three unit mistakes */
    char err[sizeof traj.units_problem + 512], cmdline[1024];
    int rc, exit_code = HX_EXIT_OK;
    if (hx_nav_param_help_requested(argc, argv)) {
        return HX_EXIT_OK;
    }
    rc = hx_args_parse(&k_spec, argc, argv, &a);
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--plot", NULL };
        if (hx_refuse_dash("replay", &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    rc = hx_nav_opts_from_args("replay", &a, &o);
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    /* the checks of every command that reads a log (replay took --from
     * auto, which they refuse) */
    if (hx_check_input_opts("replay", &a) != 0 || hx_arg_double(&a, "--input-rate", 1e-3, 1e6, &in_rate) != 0) {
        return HX_EXIT_USAGE;
    }
    from = hx_arg(&a, "--from");
    if (from != NULL) {
        fmt = hx_format_from_name(from);
    }
    if (hx_nav_config(&o, &cfg, err, sizeof err) != 0) {
        hx_error("replay", "%s", err);
        return HX_EXIT_USAGE;
    }
    out_path = hx_arg(&a, "--out");
    json_path = hx_arg(&a, "--json");
    plot_path = hx_arg(&a, "--plot");
    strides_path = hx_arg(&a, "--strides");
    if (access(a.pos[0], R_OK) != 0) {
        /* before any output is opened (and an existing one emptied) */
        const int e = errno;
        hx_error("replay", "%s: cannot read (%s)%s", a.pos[0], strerror(e), hx_stdin_hint(a.pos[0], e));
        return HX_EXIT_DATA;
    }
    {
        static const char *const outs[] = { "--out", "--json", "--plot", "--strides", NULL };
        /* both on standard output (--json - with either is refused before
         * the command runs, hx_json_stdout_claim): said before the check of
         * one file named twice, which takes two '-' for one file */
        if (out_path != NULL && strides_path != NULL && strcmp(out_path, "-") == 0 && strcmp(strides_path, "-") == 0) {
            hx_error("replay", "--out - and --strides - cannot both write to standard output");
            return HX_EXIT_USAGE;
        }
        if (hx_output_is_input("replay", a.pos[0], &a, outs) || hx_profile_is_output("replay", o.profile, &a, outs)) {
            return HX_EXIT_USAGE;
        }
    }
    {
        /* the header is checked before any output is opened: a log that
         * cannot be read at all empties no earlier trajectory (nor leaves an
         * earlier --json beside an emptied one) */
        hx_reader_t *probe = hx_reader_open(a.pos[0], fmt, in_rate, err, sizeof err);
        if (probe == NULL) {
            hx_error("replay", "%s", err);
            return HX_EXIT_DATA;
        }
        hx_reader_close(probe);
        /* stamps in bursts are refused before any output is opened too */
        if (!(o.rate_hz > 0.0) && hx_nav_stamps_check(a.pos[0], fmt, in_rate, (double)cfg.max_gap_s, err, sizeof err) != 0) {
            hx_error("replay", "%s", err);
            return HX_EXIT_DATA;
        }
    }
    /* the JSON and the PNG are written after the whole log: find out now,
     * before running the log, that they can be */
    {
        static const char *const files[] = { "--json", "--strides", NULL }, *const pngs[] = { "--plot", NULL };
        if (hx_check_outputs("replay", &a, files, pngs) != 0) {
            return HX_EXIT_IO;
        }
    }
    if (out_path != NULL) {
        csv = strcmp(out_path, "-") == 0 ? stdout : fopen(out_path, "w");
        if (csv == NULL) {
            /* with the reason (a directory, a missing one), as --json's */
            hx_error("replay", "cannot write %s (%s)", out_path, strerror(errno));
            return HX_EXIT_IO;
        }
    }
    hx_command_line(cmdline, sizeof cmdline, "harness replay", argc, argv);
    rc = hx_nav_replay("replay", a.pos[0], fmt, in_rate, &cfg, o.rate_hz, csv, &traj,
                       HX_REPLAY_PROGRESS | HX_REPLAY_AXES | HX_REPLAY_UNITS_OPT | HX_REPLAY_STAMPS_CHECKED |
                           (strides_path != NULL ? HX_REPLAY_EVENTS : 0u), err,
                       sizeof err);
    traj.input_complete = 1;
    hx_traj_set_config(&traj, &o, &cfg);
    if (rc == -3) {
        /* the sink (or the memory for the frames) failed during the run,
         * which stopped there: the figures cover the samples before it, as
         * a log cut at a bad line (not "NOT ALIGNED (no still period long
         * enough ...)" and "complete": true for `--out - | head -2`) */
        if (csv != NULL && ferror(csv)) { /* the sink's write failed, not the memory */
            /* with the reason the port kept where the write failed (errno
             * is not it here) */
            char why[128];
            snprintf(err, sizeof err, "cannot write the trajectory to %s%s",
                     strcmp(out_path, "-") == 0 ? "standard output" : out_path,
                     hx_errno_note(traj.output_errno, why, sizeof why));
        }
        traj.input_complete = 0;
        traj.output_failed = 1;
        snprintf(traj.input_error, sizeof traj.input_error, "%.*s", (int)sizeof traj.input_error - 1, err);
    }
    if (csv != NULL && rc != -3 && traj.stats.frames == 0u) {
        /* the port writes the header with the first frame: an input with
         * no sample (a CSV header alone, a .bin without records) gets it
         * here, a valid empty CSV, the header alone, not a 0-byte file
         * (docs/harness.md, "replay") */
        fprintf(csv, "%s\n", FNAV_LINUX_NAV_CSV_HEADER);
    }
    if (csv != NULL) {
        errno = 0; /* set only by a failed call: the reason of this one */
        if ((csv == stdout ? fflush(csv) != 0 || ferror(csv) : fclose(csv) != 0) && rc >= 0) {
            char why[128];
            snprintf(err, sizeof err, "cannot write %s%s", strcmp(out_path, "-") == 0 ? "standard output" : out_path,
                     hx_errno_note(errno, why, sizeof why));
            rc = -3;
        }
    }
    if (rc == -1) {
        hx_error("replay", "%s", err);
        hx_traj_free(&traj);
        return HX_EXIT_DATA;
    }
    if (rc == -3) {
        hx_error("replay", "%s", err);
        exit_code = HX_EXIT_IO;
    } else if (rc == 1) {
        /* not "frames before it were written" with none before it (a header
         * without samples) */
        hx_error("replay", "%s (%s)", err,
                 traj.stats.frames > 0u ? "frames before it were written" : "no frame before it: the outputs hold none");
        exit_code = HX_EXIT_DATA;
        traj.input_complete = 0;
        snprintf(traj.input_error, sizeof traj.input_error, "%.*s", (int)sizeof traj.input_error - 1, err);
    } else if (rc == 2) {
        hx_error("replay", "%s; outputs were still written, computed from the values as given", err);
        exit_code = HX_EXIT_DATA;
    } else if (rc == 3) {
        /* read to its end, never aligned: every frame was written and the
         * input is complete (docs/harness.md, "replay") */
        hx_error("replay", "%s", err);
        exit_code = HX_EXIT_DATA;
    }
    if (rc != 2 && traj.axes.problem) {
        /* a statistical verdict, not a physical impossibility like the
         * units check: a warning, the exit status is the replay's */
        hx_warn("replay", "%s: %s; outputs were computed from the axes as recorded", a.pos[0], traj.axes.msg);
    }
    if (rc != 2 && traj.axes.time_problem) {
        hx_warn("replay", "%s: %s; outputs were computed at the rate read", a.pos[0], traj.axes.msg);
    }
    hx_nav_summarize(&traj, &sum);
    /* standard output holds the rows of `--out -` or `--strides -` alone */
    summary_to = csv == stdout || (strides_path != NULL && strcmp(strides_path, "-") == 0) ? stderr : stdout;
    if (!hx_flag(&a, "--quiet")) {
        hx_nav_print_summary(summary_to, a.pos[0], &traj, &sum);
    }
    if (strides_path != NULL) {
        /* after the run: a stride's length needs the stance after it */
        const int to_stdout = strcmp(strides_path, "-") == 0;
        FILE *sf;
        int bad, e;
        char why[160];
        errno = 0;
        sf = to_stdout ? stdout : fopen(strides_path, "w");
        bad = sf == NULL || hx_nav_write_strides(sf, &traj) != 0;
        e = bad ? errno : 0; /* the reason of the first failure: a full disk is more than "cannot write" */
        if (sf != NULL && (to_stdout ? fflush(sf) != 0 || ferror(sf) : fclose(sf) != 0)) {
            e = bad ? e : errno;
            bad = 1;
        }
        if (bad) {
            hx_error("replay", "cannot write the strides to %s%s%s", to_stdout ? "standard output" : strides_path,
                     hx_errno_note(traj.events ? e : 0, why, sizeof why),
                     traj.events ? ""
                                 : " (the detector's events were not kept: out of memory, or its outputs "
                                   "disagreed with the navigator's frames)");
            exit_code = HX_EXIT_IO;
        }
    }
    if (json_path != NULL && hx_nav_write_json(json_path, a.pos[0], cmdline, &traj, &sum, NULL, err, sizeof err) != 0) {
        hx_error("replay", "%s", err);
        exit_code = HX_EXIT_IO;
    }
    if (plot_path != NULL) {
        char title[1024];
        hx_nav_plot_title(&traj, a.pos[0], o.rate_hz, title, sizeof title);
        if (hx_nav_plot("replay", plot_path, title, &traj) != 0) {
            exit_code = HX_EXIT_IO;
        }
    }
    hx_traj_free(&traj);
    return exit_code;
}
