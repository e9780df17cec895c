/* harness sim: simulated foot motion and sensor errors into a log with truth
 * (docs/simulator.md). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_profile.h"
#include "hx_sim.h"

static const hx_opt_t k_opts[] = {
    HX_SIM_OPTS,
    { "--list-effects", NULL, "print the effect catalogue with parameters and defaults, and exit", 0 },
    { "--out", "LOG", "simulated log (.bin, or CSV for any other name; - for CSV on stdout)", 0 },
    { "--truth", "CSV", "truth at every output tick (docs/simulator.md)", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "sim", "--out LOG [options]",
    "Simulate a foot-mounted IMU: exact foot motion (stance, swing, heel-strike\n"
    "impacts; walking, running, stairs, turns, elevator), the sensor's white\n"
    "noise and AR(1) bias from a profile (paper eqs. 1-4) and any effects of the\n"
    "catalogue, through an anti-alias filter and decimation to the output rate.\n"
    "Writes the log and, with --truth, position, velocity, attitude, the ideal\n"
    "signals, the injected bias and the stance truth at every tick.",
    0, 0, k_opts
};

typedef struct {
    hx_writer_t *w;
    FILE *truth;
    const char *truth_path;
    int write_error;     /* bits: 1 the log, 2 the truth CSV (each, once failed, is no longer written) */
    int truth_errno;     /* errno of the truth CSV's failed write */
    size_t written, dropped, dups, ticks, total;
    double peak_f, peak_w;
    hx_progress_t prog;
} sim_ctx_t;

static int sink(void *vctx, const hx_sim_tick_t *tk)
{
    sim_ctx_t *s = (sim_ctx_t *)vctx;
    const hx_truth_t *o = &tk->truth;
    uint32_t k;
    int c;
    /* an output that fails is no longer written, and the other goes on to
     * the end: stopping the run at the first failed write, a truth CSV on a
     * full disk would leave the log cut short, a valid-looking log of a few
     * rows (tests/cli/test_bad_input.sh) */
    for (k = 0; k < tk->count && s->w != NULL && !(s->write_error & 1); k++) {
        if (hx_writer_write(s->w, &tk->meas) != FNAV_OK) {
            s->write_error |= 1;
            break;
        }
        s->written++;
    }
    s->dropped += tk->count == 0u;
    s->dups += tk->count == 2u;
    for (c = 0; c < 3 && tk->count > 0u; c++) {
        /* the peaks of the log: a dropped sample is not in it */
        double f = fabs((double)tk->meas.accel_mps2[c]), w = fabs((double)tk->meas.gyro_rps[c]);
        s->peak_f = f > s->peak_f ? f : s->peak_f;
        s->peak_w = w > s->peak_w ? w : s->peak_w;
    }
    if (s->truth != NULL && !(s->write_error & 2)) {
        int r = fprintf(s->truth,
                        "%.9f,%u,%u,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f,%.12f,%.12f,%.12f,%.12f,%.9f,%.9f,%.9f,"
                        "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d,%d,%d,%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                        tk->t_s, tk->seq, tk->count, o->pos_m[0], o->pos_m[1], o->pos_m[2], o->vel_mps[0],
                        o->vel_mps[1], o->vel_mps[2], o->q_nb[0], o->q_nb[1], o->q_nb[2], o->q_nb[3], o->euler_rad[0],
                        o->euler_rad[1], o->euler_rad[2], o->f_b[0], o->f_b[1], o->f_b[2], o->w_b[0], o->w_b[1],
                        o->w_b[2], o->still, o->zero_vel, o->phase, o->leg, o->odo_m, tk->bias[0], tk->bias[1],
                        tk->bias[2], tk->bias[3], tk->bias[4], tk->bias[5]);
        if (r < 0) {
            s->write_error |= 2;
            s->truth_errno = errno;
        }
    }
    if ((s->write_error & 1) && (s->truth == NULL || (s->write_error & 2))) {
        return 1; /* nothing left to write */
    }
    s->ticks++;
    if ((s->ticks & 1023u) == 0u) {
        hx_progress_update(&s->prog, (double)s->ticks);
    }
    return 0;
}

int hx_cmd_sim(int argc, char **argv)
{
    hx_args_t a;
    hx_sim_setup_t su;
    hx_sim_config_t sc;
    hx_motion_t *motion = NULL;
    sim_ctx_t ctx;
    hx_meta_t meta;
    char err[HX_ERR_SIZE];
    const char *motion_name, *profile, *out, *truth;
    double rate, dur;
    int rc, status = HX_EXIT_OK;
    int pr = hx_args_parse(&k_spec, argc, argv, &a);
    if (pr != 0) {
        return pr > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    if (hx_flag(&a, "--list-effects")) {
        hx_effect_list(stdout);
        return HX_EXIT_OK;
    }
    out = hx_arg(&a, "--out");
    truth = hx_arg(&a, "--truth");
    if (out == NULL) {
        hx_error("sim", "--out LOG is required");
        hx_usage(&k_spec, stderr);
        return HX_EXIT_USAGE;
    }
    if (truth != NULL && strcmp(truth, "-") == 0) {
        /* refused: it would create a file named '-' */
        hx_error("sim", "--truth needs a file name ('-' is not standard output here: the summary goes there)");
        return HX_EXIT_USAGE;
    }
    if (truth != NULL && (strcmp(truth, out) == 0 || hx_same_file(truth, out))) {
        hx_error("sim", "--truth and --out name the same file");
        return HX_EXIT_USAGE;
    }
    if (hx_sim_setup_from_args("sim", &a, &su) != 0) {
        return HX_EXIT_USAGE;
    }
    {
        /* a profile file is an input (--out onto it would replace it, exit
         * 0) */
        static const char *const outs[] = { "--out", "--truth", NULL };
        if (hx_profile_is_output("sim", su.profile_name, &a, outs)) {
            return HX_EXIT_USAGE;
        }
    }
    sc.err = su.err;
    sc.decim = su.decim;
    rate = (double)su.err.rate_hz;
    dur = su.duration_s;
    profile = su.profile_name;
    motion_name = su.motion_name;
    motion = hx_motion_create(&su.motion_cfg, motion_name, dur, err, sizeof err);
    if (motion == NULL) {
        hx_error("sim", "%s", err);
        return HX_EXIT_USAGE;
    }
    sc.motion = motion;
    sc.duration_s = dur > 0.0 ? dur : hx_motion_duration(motion);
    if (sc.duration_s * rate >= 4294967295.0) {
        /* the record counter and the error model's step count are 32-bit
         * (--duration 1e6 --rate 1e5 asked for 1e11 ticks, a log of
         * terabytes, and would have wrapped them) */
        hx_error("sim", "%.6g s at %.6g Hz is %.3g samples; at most 2^32 - 1 (shorten --duration or lower --rate)",
                 sc.duration_s, rate, sc.duration_s * rate);
        hx_motion_free(motion);
        return HX_EXIT_USAGE;
    }

    hx_sim_warn_cut("sim", motion, motion_name, dur);
    hx_sim_warn_unused("sim", &a, motion, motion_name);
    if (rate < HX_TIME_RATE_MIN_HZ && hx_motion_strides(motion) > 0) {
        /* a walk too slow to replay (a static log at any rate serves
         * allan and psd): said before the samples, not by replay later */
        hx_warn("sim", "at %g Hz the walk is below the %.0f Hz that replay navigates as recorded (a foot-mounted "
                       "IMU needs %.0f Hz or more); allan, psd and info read it",
                rate, HX_TIME_RATE_MIN_HZ, HX_TIME_RATE_MIN_HZ);
    }

    memset(&meta, 0, sizeof meta);
    meta.format = HX_FMT_AUTO;
    meta.rate_hz = rate;
    meta.rate_nominal = 1;
    meta.has_seq = 1;
    meta.has_temp = sc.err.mask[FNAV_EFFECT_THERMAL] != 0u;
    snprintf(meta.sensor, sizeof meta.sensor, "sim:%.27s", profile);
    snprintf(meta.source, sizeof meta.source, "harness sim --motion %.20s --seed %u", motion_name, sc.err.seed);
    snprintf(meta.axes, sizeof meta.axes, "sensor frame; foot flat: z down");

    memset(&ctx, 0, sizeof ctx);
    ctx.w = hx_writer_open(out, HX_FMT_AUTO, &meta, 0, err, sizeof err);
    if (ctx.w == NULL) {
        hx_error("sim", "%s", err);
        hx_motion_free(motion);
        return HX_EXIT_IO;
    }
    hx_warn_gz_output("sim", out, HX_FMT_AUTO);
    if (truth != NULL && hx_same_file(truth, out)) {
        /* the same file under another name (--out x.bin --truth ./x.bin):
         * only now that the log exists can stat tell (the truth CSV would
         * be written into the .bin, exit 0) */
        hx_error("sim", "--truth and --out name the same file");
        hx_writer_close(ctx.w, err, sizeof err);
        hx_motion_free(motion);
        return HX_EXIT_USAGE;
    }
    if (truth != NULL) {
        ctx.truth_path = truth;
        ctx.truth = fopen(truth, "w");
        if (ctx.truth == NULL) {
            hx_error("sim", "%s: cannot create (%s)", truth, strerror(errno));
            hx_writer_close(ctx.w, err, sizeof err);
            hx_motion_free(motion);
            return HX_EXIT_IO;
        }
        fprintf(ctx.truth, "t,seq,count,px,py,pz,vx,vy,vz,qw,qx,qy,qz,roll,pitch,yaw,fx,fy,fz,wx,wy,wz,"
                           "still,zero_vel,phase,leg,odo,bax,bay,baz,bgx,bgy,bgz\n");
    }
    ctx.total = hx_sim_ticks(&sc);
    hx_progress_start(&ctx.prog, "sim", (double)ctx.total);
    rc = hx_sim_run(&sc, sink, &ctx, err, sizeof err);
    hx_progress_end(&ctx.prog);
    if (rc < 0) {
        hx_error("sim", "%s", err);
        status = HX_EXIT_USAGE;
    } else {
        if (ctx.write_error & 1) {
            status = HX_EXIT_IO; /* hx_writer_close below names the error, with its reason */
        }
        if (ctx.write_error & 2) {
            /* one line with the reason, as convert's, for either output
             * (the log's failure not said twice, the truth CSV's not
             * without a reason) */
            hx_error("sim", "%s: write failed (%s)", truth, strerror(ctx.truth_errno));
            status = HX_EXIT_IO;
        }
    }
    if (hx_writer_close(ctx.w, err, sizeof err) != FNAV_OK) {
        hx_error("sim", "%s", err);
        status = HX_EXIT_IO;
    }
    if (ctx.truth != NULL && fclose(ctx.truth) != 0 && !(ctx.write_error & 2)) {
        hx_error("sim", "%s: write failed (%s)", truth, strerror(errno));
        status = HX_EXIT_IO;
    }
    if (status == HX_EXIT_OK) {
        /* with the log on standard output (--out -) the summary goes to
         * standard error, as replay's, not dropped */
        FILE *so = strcmp(out, "-") == 0 ? stderr : stdout;
        hx_truth_t end;
        char spec[1024], shown[4096]; /* a file name's control characters as '?' (hx_line_str), as in the messages */
        int id;
        /* the output's span: its last tick, (ticks - 1) / rate; a
         * --duration between two ticks (7.0049 s at 100 Hz) prints the last
         * tick's time and truth, not 7.005 s and the truth there, past the
         * log's last sample (test_sim.sh) */
        const double t_end = (double)(ctx.total - 1u) / rate;
        hx_motion_eval(motion, t_end, &end);
        fprintf(so, "motion      %s\n", motion_name);
        fprintf(so, "duration    %.3f s, %d strides, %.2f m between footfalls, ends at (%.3f, %.3f, %.3f) m\n",
                    t_end, hx_motion_strides_until(motion, t_end), end.odo_m, end.pos_m[0], end.pos_m[1], end.pos_m[2]);
        fprintf(so, "sampling    %g Hz, internal x%u (%s), seed %u\n", rate, fnav_imuerr_internal_factor(&sc.err),
                    sc.err.mask[FNAV_EFFECT_ALIAS]              ? "picked, no anti-alias filter"
                    : sc.decim == HX_DECIM_MEAN                 ? "interval means"
                    : fnav_imuerr_internal_factor(&sc.err) > 1u ? "anti-alias FIR"
                                                                  : "point samples",
                    sc.err.seed);
        fprintf(so, "profile     %s\n", hx_line_str(shown, sizeof shown, profile));
        for (id = 0; id < (int)FNAV_EFFECT_COUNT; id++) {
            if (hx_effect_format(&sc.err, (fnav_effect_id_t)id, spec, sizeof spec) > 0) {
                fprintf(so, "effect      %s\n", spec);
            }
        }
        fprintf(so, "samples     %zu written (%zu ticks, %zu dropped, %zu duplicated)\n", ctx.written, ctx.ticks,
                    ctx.dropped, ctx.dups);
        /* the largest |reading| of any one axis, what a sensor's range must
         * hold; '|f|' would read as the norm */
        fprintf(so, "peaks       largest on one axis: f %.1f m/s^2 (%.1f g), w %.2f rad/s (%.0f deg/s)\n", ctx.peak_f,
                    ctx.peak_f / 9.80665, ctx.peak_w, ctx.peak_w * 180.0 / 3.14159265358979323846);
        fprintf(so, "log         %s\n", hx_line_str(shown, sizeof shown, out));
        if (truth != NULL) {
            fprintf(so, "truth       %s\n", hx_line_str(shown, sizeof shown, truth));
        }
        if (ctx.written == 0u) {
            /* as convert's empty window: said, exit 1, the log valid and
             * empty (dropout:prob=1 exited 0 with a log info refuses) */
            hx_error("sim", "%s: no sample written: the dropout effect (prob %g) dropped every one of the %zu ticks "
                            "(the log is valid and empty)",
                     out, (double)sc.err.dropout.prob, ctx.ticks);
            status = HX_EXIT_DATA;
        }
    }
    hx_motion_free(motion);
    return status;
}
