/**
 * @file hx_nav.h
 * @brief Harness side of navigation: option handling shared by `replay` and
 *        `eval`, the replay engine (a log through the Linux port into
 *        fnav_nav sample by sample), the anti-alias resampler behind
 *        `--rate`, the trajectory kept in memory, and the summary figures
 *        (docs/harness.md).
 */
#ifndef HX_NAV_H
#define HX_NAV_H

#include <stdio.h>

#include "footnav/fnav_nav.h"
#include "hx_axes.h"
#include "hx_cli.h"
#include "hx_log.h"

/* ------------------------------------------------------------ options */

/** Options of the navigation commands (NULL/0 = default). */
typedef struct {
    const char *profile;     /**< --profile NAME|FILE */
    const char *bias_model;  /**< --bias-model ar1|off */
    const char *detector;    /**< --detector shoe|threshold */
    const char *samples;     /**< --samples instant|mean */
    double rate_hz;          /**< --rate HZ: resample the input (0: no) */
    const char *params[HX_MAX_REPEAT]; /**< --param KEY=VALUE */
    int nparams;
} hx_nav_opts_t;

/** The options every navigation command accepts, for an hx_opt_t table:
 *  HX_NAV_OPTS(HX_NAV_RATE_HELP) where --rate resamples the log,
 *  HX_NAV_OPTS(NULL) where the command refuses it with its own reason (the
 *  option is then left out of the usage). */
#define HX_NAV_RATE_HELP "resample the input to HZ first (anti-alias low-pass, docs/harness.md)"
#define HX_NAV_OPTS(rate_help)                                                                        \
    { "--profile", "NAME|FILE", "sensor profile: generic-mems (default), navchip, mtx, shimmer or a profile file", 0 }, \
    { "--bias-model", "MODEL", "ar1 (default, docs/navigation.md) or off", 0 },                                           \
    { "--detector", "KIND", "stance detector: shoe (default) or threshold", 0 },                      \
    { "--samples", "KIND", "what a sample is: instant (default; rate-output sensors) or mean (delta-angle/velocity over the interval)", 0 }, \
    { "--rate", "HZ", rate_help, 0 },                                                                 \
    { "--param", "KEY=VALUE", "set a navigation parameter (list: --param help)", 1 }

/** Collect the HX_NAV_OPTS values from parsed arguments; -1 on a usage
 *  error (printed). */
int hx_nav_opts_from_args(const char *cmd, const hx_args_t *a, hx_nav_opts_t *o);

/** Why fnav_nav_init refused cfg, in err: a rate too low for max_gap_s
 *  (rate_src says where the rate came from, e.g. " (--rate)"), else the
 *  core's refusal followed by `other`. */
void hx_nav_init_error(const fnav_nav_config_t *cfg, const char *rate_src, const char *other, char *err, size_t err_size);

/** Build a navigation configuration. 0 ok; -1 with err filled. */
int hx_nav_config(const hx_nav_opts_t *o, fnav_nav_config_t *cfg, char *err, size_t err_size);

/** Print the --param keys with their current default values. */
void hx_nav_param_help(FILE *f);
/** 1 (after printing the list on stdout) when the command line asks for
 *  `--param help`, so that it works without the command's required
 *  arguments; 0 otherwise. */
int hx_nav_param_help_requested(int argc, char **argv);

/* ------------------------------------------------------------ trajectory */

/** Samples (distinct stamps) in a block of hx_sat_t's noise at rest. */
#define HX_SAT_BLOCK 64
/** A channel's extremes must lie more than this many times its noise at
 *  rest apart for its flat tops to be clipping (docs/harness.md, "info",
 *  saturation): a channel spans at most 50.1 in the 1-s stretches of
 *  xio_ngimu_gait and openshoe_c_820hz where its flat tops alone call it
 *  clipped (still or slow), the clipped walk of tests/cli/test_replay.sh
 *  at least 1,800 (scripts/sat_span_noise.py). */
#define HX_SAT_SPAN_NOISE 100.0
/** The largest standard deviation of a block at rest: 0.12 m/s^2 and
 *  0.025 rad/s, above the smallest block of every shared walk (at most
 *  0.063 m/s^2 and 0.0103 rad/s, openshoe_c_820hz's quantised channels)
 *  and under every block of a walk at 100 Hz without standing (at least
 *  0.21 m/s^2 and 0.062 rad/s: vectors/walk.bin's moving part at 100 Hz);
 *  scripts/sat_span_noise.py --rest. A log with no block under them (it
 *  never rests: a run, a walk whose blocks all hold a swing) is judged by
 *  the flat tops alone. */
#define HX_SAT_REST_SD_ACCEL 0.12
#define HX_SAT_REST_SD_GYRO 0.025

/** Flat tops at a channel's extremes, counted sample by sample as `info`
 *  counts them on a whole log (docs/harness.md, "info", saturation): a
 *  channel is saturated when at least two separate runs of two or more
 *  samples with distinct stamps sit exactly at its maximum or minimum and
 *  its extremes lie more than HX_SAT_SPAN_NOISE times its noise at rest
 *  apart. The noise at rest is the smallest standard deviation of a block
 *  of HX_SAT_BLOCK samples at rest (HX_SAT_REST_SD_*; of the first samples
 *  while no block is whole, if they are at rest), at least the smallest
 *  change between consecutive samples (the step of a quantised channel too
 *  still to vary within a block); without a block at rest, the flat tops
 *  alone. */
typedef struct {
    double mx[6], mn[6];     /**< extremes so far (ax..az, gx..gz) */
    long cmx[6], cmn[6];     /**< samples at them */
    long rmx[6], rmn[6];     /**< runs of two or more at them */
    long runx[6], runn[6];   /**< the current run's length at each */
    double last[6];          /**< the last sample's values */
    double step[6];          /**< the smallest non-zero change between consecutive samples (0: none yet) */
    double b0[6], bs[6], bss[6]; /**< the current block: its first value, the sums of the values less it and of their squares */
    long bn;                 /**< samples in the current block */
    double var_min[6];       /**< the smallest variance of a whole block at rest (with have_rest) */
    int have_rest[6];        /**< a whole block of the channel was at rest (HX_SAT_REST_SD_*) */
    int64_t t_last_ns;
    int have;
} hx_sat_t;

/** Takes one sample; an exact duplicate of the last stamp is skipped. */
void hx_sat_push(hx_sat_t *st, const fnav_sample_t *s);

/** Samples at channel ch's extremes when it is saturated, else 0. */
long hx_sat_count(const hx_sat_t *st, int ch);

/** One completed stride of the stance detector (FNAV_STANCE_EV_STRIDE)
 *  with its gait events, as the navigator's own detector raised them
 *  (fnav_stance.h; kept with HX_REPLAY_EVENTS). */
typedef struct {
    size_t frame;        /**< the frame that ended the swing (FNAV_FRAME_STRIDE) */
    int have_fo;         /**< the swing's FNAV_STANCE_EV_FOOT_OFF was raised */
    int64_t fo_t_ns;     /**< foot-off (with have_fo), ns */
    int64_t fs_t_ns;     /**< foot-strike, ns */
    int64_t swing_t0_ns; /**< the detector's first sample of the swing, ns */
    int64_t swing_t1_ns; /**< the first sample of the stance that ended it, ns */
} hx_stride_ev_t;

/** Frames of one replay, kept in memory. */
typedef struct {
    size_t n, cap;
    fnav_nav_frame_t *f;
    int64_t t0_ns;               /**< the first sample's stamp: the trajectory CSV's t = 0 */
    /** with HX_REPLAY_EVENTS: every stride of the frames kept, in order
     *  (events 1; 0: not kept, or the detector that gives them disagreed with
     *  the navigator's frames, which does not happen) */
    hx_stride_ev_t *ev;
    size_t nev, ev_cap;
    int events;
    fnav_nav_stats_t stats;      /**< navigator counters at the end */
    double rate_hz;              /**< detector rate */
    int rate_none;               /**< one sample: no interval gave the rate, the detector took its fallback (rate_hz) */
    int window;                  /**< detector window, samples */
    int zupt_min_n;              /**< the detector's shortest ZUPT run, samples (min_zupt_s at the rate; 0: not known) */
    int zupt_max_n;              /**< the longest shortest ZUPT run the look-ahead allows (lag + 1, samples; 0: not known) */
    double in_rate_hz;           /**< input rate before resampling (0 if not resampled) */
    long resample_dropped_dups;  /**< duplicates dropped by the resampler */
    /** --rate: the input's own gaps, which the resampler closes up (the
     *  navigator sees none of them; hx_nav_summarize's motion gaps are
     *  these). in_gaps: the intervals over 1.5 input periods, time jumps
     *  not counted; in_longest_s: the input's longest interval, s; in_long:
     *  the stamps at the ends of the gaps over HX_NAV_LONG_GAP_S, in order
     *  (n_in_long of them; freed by hx_traj_free) */
    long in_gaps;
    double in_longest_s;
    int64_t (*in_long)[2];
    size_t n_in_long;
    long cut_lines;              /**< the log's incomplete last line ignored (hx_read_stats_t) */
    int stamps_coarse;           /**< the stamps are so coarse that an interval of one period can read over 1.5 periods (a gap) */
    char rate_src[192];          /**< where rate_hz came from, for the summary's rate line ("": not said) */
    hx_format_t in_format;       /**< the format read (replay; HX_FMT_AUTO: not said), which chooses the coarse-stamps note's remedy */
    double rate_assumed_hz;      /**< the rate the reader assumed for a log without stamps or --input-rate (the OpenShoe 820 Hz set's; 0: none) */
    double max_gap_s;            /**< the navigator's time-jump limit (fnav_nav_config_t; 0: not known, no interval is a jump) */
    fnav_align_result_t align;   /**< alignment result */
    int aligned;
    hx_axes_result_t axes;       /**< the axes check (hx_axes.h) */
    long saturated[6];           /**< samples at a clipped channel's extremes, ax..gz (hx_sat_count; the input before any resampling) */
    /** replay: 1 when the input was read to its end, 0 when the run
     *  stopped at an error of the input or of the trajectory output
     *  (input_error); -1 not said (live): no JSON keys */
    int input_complete;
    char input_error[HX_ERR_SIZE];
    /** replay: 1 when the run stopped because the trajectory output could
     *  not be written (input_complete is then 0 and input_error says so) */
    int output_failed;
    /** replay: errno of the trajectory output's failed write (0: not said) */
    int output_errno;
    /** replay: 1 when the units check ran (the log read to its end), with
     *  units_problem its message, "" when the values look like SI (the
     *  JSON's `units_problem`); 0 not checked (live, a run stopped early):
     *  no JSON key */
    int units_checked;
    char units_problem[1152];
    /** the configuration that ran, for the summary's `config` line and the
     *  JSON's keys (hx_traj_set_config; have_config 0: not said, no line) */
    int have_config;
    fnav_nav_config_t config;
    char profile_file[256];      /**< --profile's file ("": a built-in profile) */
    char params[HX_MAX_REPEAT][128]; /**< the --param overrides as given (KEY=VALUE) */
    int nparams;
} hx_traj_t;

void hx_traj_free(hx_traj_t *t);

/** Record the configuration that ran in t (after hx_nav_replay, which
 *  clears t): the profile, bias model, detector and switches of cfg, and
 *  from o the profile file and the --param overrides. */
void hx_traj_set_config(hx_traj_t *t, const hx_nav_opts_t *o, const fnav_nav_config_t *cfg);

/** The replay PNG's title: the log's path, then in brackets the options
 *  that differ from the defaults as they would be typed (`--rate HZ`,
 *  `--profile`, `--bias-model`, `--detector`, `--samples`, each `--param`),
 *  from t's configuration (hx_traj_set_config) and rate_hz (--rate, 0:
 *  none); the path alone when every option is the default. */
void hx_nav_plot_title(const hx_traj_t *t, const char *path, double rate_hz, char *buf, size_t size);

/** The stance detector's label after its name, as the `config` line and
 *  eval's results.md print it: " (adaptive threshold)" or " (fixed
 *  threshold)" for SHOE; the threshold detector's limits, " (window RMS |w|
 *  < 34.38 deg/s and ||f| - g| < 0.6 m/s^2, adaptive limits)". */
#define HX_NAV_DETECTOR_LABEL_SIZE 160
void hx_nav_detector_label(const fnav_nav_config_t *c, char *buf, size_t size);

/** The configuration's description as the summary's `config` line prints
 *  it, without the label ("profile generic-mems, bias model ar1, ..."). */
void hx_nav_config_text(const hx_traj_t *t, char *buf, size_t size);

/* ------------------------------------------------------------ resampler */

/**
 * Resample a whole log to rate_hz (downsampling only): exact duplicate time
 * stamps are dropped, a Blackman-windowed sinc low-pass with cut-off 0.45 x
 * rate_hz (length about 41 x the rate ratio, unit DC gain, zero phase) is
 * evaluated directly at each output instant t0 + k / rate_hz, placed between
 * the input's own time stamps as a fractional input index (the input taken
 * as uniform at its median rate; renormalised at the edges). An interval
 * above max_gap_s (and 1.5 input periods) is a time jump: the filter does
 * not reach across it and the grid starts again after it.
 * @param max_gap_s the navigator's time-jump limit (fnav_nav_config_t)
 * @param dups     receives the number of dropped duplicates
 * @param in_rate  receives the input's median rate, Hz
 * @return 0, or -1 with err filled (too few samples, rate not below 0.999 x
 *         the input rate, memory). out is freed with hx_log_free().
 */
int hx_nav_resample(const hx_log_t *in, double rate_hz, double max_gap_s, hx_log_t *out, long *dups,
                    double *in_rate, char *err, size_t err_size);
/** hx_nav_resample that reports progress(ctx, fraction of the output made,
 *  0..1) every 4,096 output samples and 1 at the end (progress NULL:
 *  none), for a progress indicator on long logs. */
int hx_nav_resample_progress(const hx_log_t *in, double rate_hz, double max_gap_s, hx_log_t *out, long *dups,
                             double *in_rate, void (*progress)(void *ctx, double frac), void *ctx, char *err,
                             size_t err_size);

/* ------------------------------------------------------------ replay */

/** Whether a log's values look like SI units (docs/harness.md, "Units
 *  check"): |f| at rest within 25 % of gravity (0: not known), no rate above
 *  70 rad/s, samples at least 20 per second (0: not known). 1 with the
 *  mistake and its remedy in msg, else 0. csv: the layout an interchange
 *  CSV was read with, by a command that takes --units: a remedy it can give
 *  names the option (accel=g, gyro=deg/s, time=ms|us|ns from the unit given),
 *  each remedy the whole --units value: the items given and every item
 *  found ("give --units time=ms,accel=g"; hx_units_give); NULL: the
 *  arithmetic (multiply by 9.80665, divide by 1000). walks: the log walks
 *  (hx_walk_seen), so that a gyro read as deg/s (csv) that stays below
 *  0.75 rad/s is named as rad/s read as deg/s; 0: not known. */
/** 1 when n_over samples past the navigator's gyro range
 *  (FNAV_NAV_GYRO_MAX_RPS) among n are glitches, not a unit: at most 1 in
 *  1000 (a walk in deg/s read as rad/s has a fifth or more past it). The
 *  units check then reads the largest |w| of the others (replay, info). */
int hx_gyro_glitches(long n_over, long n);
int hx_units_problem(double f_rest_mps2, double gravity_mps2, double gyro_max_rps, double rate_hz,
                     const hx_csv_layout_t *csv, int walks, char *msg, size_t msg_size);
/** The walk evidence of the units check's gyro mark: |f| (m/s^2) in
 *  one-second windows of the stamps, pushed sample by sample (zeroed
 *  first). hx_walk_seen: 1 when 3 windows or more spread by 2 m/s^2 (sd) or
 *  more, a tenth of their samples or more 2 m/s^2 or more off gravity, as a
 *  walking foot's do and a static log's never (nor its taps); given as walks to
 *  hx_units_problem, which then names a gyro read as deg/s by --units
 *  gyro=deg/s that never exceeds 0.75 rad/s (a rad/s log read as deg/s). */
typedef struct {
    int64_t t0_ns; /**< the open window's first stamp */
    double s, s2;  /**< its sum of |f| and of |f|^2 */
    long n;        /**< its samples */
    long n_off;    /**< its samples 2 m/s^2 or more off gravity */
    long windows;  /**< closed windows that spread */
    int open;
} hx_walk_t;
void hx_walk_push(hx_walk_t *w, int64_t t_ns, double f_norm_mps2);
/** A window closed by its owner (allan's one-second windows of samples,
 *  the same idea as hx_walk_push's of stamps): n samples whose |f| (m/s^2)
 *  sums to s and its square to s2, n_off of them 2 m/s^2 or more off
 *  gravity (hx_walk_off). Counted in w->windows when it spreads as a
 *  walking foot's: the one test of hx_walk_push's windows too. */
void hx_walk_window(hx_walk_t *w, long n, double s, double s2, long n_off);
/** 1 when a sample's |f| (m/s^2) is 2 m/s^2 or more off gravity: the
 *  n_off of hx_walk_window. */
int hx_walk_off(double f_norm_mps2);
int hx_walk_seen(const hx_walk_t *w);
/** csv with the unit items hx_units_problem finds for these arguments (no
 *  rate) in *buf, NULL for csv NULL: the layout given to
 *  hx_time_unit_hint so that its remedy names them too, for a command that
 *  says both in two messages (a second --units replaces the first). */
const hx_csv_layout_t *hx_units_want(const hx_csv_layout_t *csv, double f_rest_mps2, double gravity_mps2,
                                     double gyro_max_rps, hx_csv_layout_t *buf);
/** The remedy for a gyro in deg/s, csv as hx_units_problem's, in buf
 *  (returned): "give --units gyro=deg/s" for the interchange CSV read
 *  without it, with the unit items given ("give --units
 *  time=ms,gyro=deg/s": a second --units replaces the first;
 *  hx_units_give), else "multiply by pi/180". */
const char *hx_units_fix_dps(const hx_csv_layout_t *csv, char *buf, size_t size);

#define HX_REPLAY_PROGRESS 0x1u /**< hx_nav_replay: progress indicator */
#define HX_REPLAY_AXES 0x2u     /**< hx_nav_replay: the axes check (48 integrations per swing sample) */
#define HX_REPLAY_EVENTS 0x4u   /**< hx_nav_replay: keep the strides' gait events in traj->ev (a second
                                     fnav_stance_t fed the samples the navigator accepted, whose outputs
                                     are checked against its frames: fnav_nav_frame_t has no event times) */
#define HX_REPLAY_UNITS_OPT 0x8u /**< hx_nav_replay: the command takes --units: the units check's remedy for
                                      the interchange CSV names it (hx_units_problem) */
/** The samples hx_nav_stamps_check reads at most: a walk of minutes whole,
 *  and the rate over a longer log's first 65,536 to 1 part in 10^4 for
 *  packets of 4 samples (512 KiB of stamps). */
#define HX_STAMPS_PROBE_N 65536

#define HX_REPLAY_STAMPS_CHECKED 0x10u /**< hx_nav_replay: the caller ran hx_nav_stamps_check on the log
                                            already (before opening its outputs) */

/**
 * Refuse a log whose time stamps come in bursts (HX_BURSTS_CLOSE of
 * hx_stamp_bursts over its first HX_STAMPS_PROBE_N stamps: samples stamped
 * microseconds apart as a logger reads them, whose median interval the
 * stance detector takes for the period from its first intervals,
 * FNAV_STANCE_RATE_PROBE): -1 with the cause and the
 * --input-rate remedy in err, else 0 (a log that cannot be opened too: the
 * replay's own open says why). Samples that share one stamp are left to
 * the coarse-stamps note (docs/harness.md, "Time stamps in bursts").
 * hx_nav_replay runs it without --rate unless HX_REPLAY_STAMPS_CHECKED.
 */
int hx_nav_stamps_check(const char *path, hx_format_t fmt, double in_rate, double max_gap_s, char *err,
                        size_t err_size);
/**
 * The warning of info, psd and allan for n time stamps in bursts (either
 * kind of hx_stamp_bursts, with the navigator's default time jump): "cmd:
 * warning: PATH: the time stamps come in bursts (...): ...; READS R Hz,
 * ..." with hx_bursts_rate_text's account of the rate: the stamps' rate,
 * not the sampling rate, and the remedy (nominal 0); the rate the file
 * states, which the samples' span keeps or not (nominal 1). reads: what of
 * the command's output the rate rate_hz makes ("the frequencies are read
 * at"). first: the n are the log's first stamps, not all (the message says
 * so). fmt: the format read, which chooses the remedy (hx_bursts_remedy).
 * 1 when warned, else 0.
 */
int hx_nav_bursts_warn(const char *cmd, const char *path, hx_format_t fmt, const int64_t *t_ns, size_t n,
                       int first, const char *reads, double rate_hz, int nominal);

/** |f| at rest under which no unit reads gravity (a log in g read as m/s^2
 *  gives 1.0, the least of the units read): a linear acceleration, gravity
 *  removed (replay's and info's message). */
#define HX_NO_GRAVITY_MPS2 0.5

/** Largest relative difference between the stance detector's own rate
 *  estimate (the first FNAV_STANCE_RATE_PROBE intervals) and the reader's
 *  (the first 4096) under which replay leaves the detector its own. */
#define HX_START_RATE_TOL 0.05

/** Largest relative difference between a stated rate and its stamps' that
 *  hx_stated_rate_warn lets pass. */
#define HX_STATED_RATE_TOL 0.10
/**
 * The warning of info, psd and allan for a stated rate (meta->rate_nominal:
 * a .bin header's) that the log's own time stamps contradict by more than
 * HX_STATED_RATE_TOL: "cmd: warning: PATH: the file states S Hz, but its
 * time stamps give R Hz (D ms apart): READS the stated rate; if the stamps
 * are right, convert it to CSV (...)". The stamps' rate is every command's
 * estimate from the first 4,096 (hx_stamp_rate_hz) of the n stamps t_ns.
 * reads: what of the command's output takes the stated rate ("the
 * frequencies are read at"). Stamps made from the stated rate
 * (meta->stamps_made) cannot contradict it; stamps in bursts have their
 * own warning (hx_nav_bursts_warn: call this when that one did not warn).
 * 1 when warned, else 0.
 */
int hx_stated_rate_warn(const char *cmd, const char *path, const hx_meta_t *meta, const int64_t *t_ns, size_t n,
                        const char *reads);

/**
 * Replay one log through the Linux port into a navigator, sample by sample.
 * @param cmd       command name for messages
 * @param path      log file
 * @param fmt       input format (HX_FMT_AUTO)
 * @param in_rate   --input-rate (0: default)
 * @param cfg       navigation configuration
 * @param rate_hz   resample to this rate first (0: no)
 * @param csv       trajectory CSV sink (may be NULL)
 * @param traj      frames kept (may be NULL)
 * @param flags     HX_REPLAY_PROGRESS: show a progress indicator;
 *                  HX_REPLAY_AXES: run the axes check into traj->axes
 *                  (hx_axes.h; without it traj->axes says "not checked")
 * @param err       message on failure
 * @return 0 complete; 1 the input had an error after some samples (frames up
 *         to it are valid, err says why); 2 complete, but the input is
 *         not in SI units (|f| at rest far from gravity, a rate beyond any
 *         MEMS gyro, samples more than 1/20 s apart; err says which); 3
 *         complete, but the filter never aligned (no still period, or time
 *         stamps that never advance; err says which); -1 nothing could be
 *         replayed; -3 the CSV sink failed.
 */
int hx_nav_replay(const char *cmd, const char *path, hx_format_t fmt, double in_rate, const fnav_nav_config_t *cfg,
                  double rate_hz, FILE *csv, hx_traj_t *traj, unsigned flags, char *err, size_t err_size);

/* ------------------------------------------------------------ summary */


/** Summary figures of a trajectory (docs/harness.md lists the JSON keys). */
typedef struct {
    double duration_s;        /**< first to last frame, s */
    double path_m;            /**< step-to-step path through stance mid-points, 3-D, m */
    double path_h_m;          /**< the same, horizontal, m */
    double integrated_path_m; /**< sum of |dp| over all frames, m */
    double end_pos_m[3];      /**< last stance mid-point (or last frame), n frame, m */
    double start_pos_m[3];    /**< first stance mid-point, m */
    double end_h_m, end_3d_m; /**< return-to-start error, m */
    double end_h_pct, end_3d_pct; /**< the same in % of path_m */
    double vertical_m;        /**< height change start -> end (up positive), m */
    double heading_change_deg; /**< unwrapped heading change of a body vector level at the alignment, deg */
    long strides;             /**< completed swings */
    long stance_phases;       /**< stance phases (segmented) */
    double stance_fraction;   /**< share of the frames from the first aligned one on with the ZUPT flag (the aligned frames, unless a divergence reset left some unaligned) */
    double aligned_at_s;      /**< first aligned frame after the first frame, s (NaN: never aligned) */
    double before_align_s;    /**< frames before it the detector called motion (not navigated), s */
    double longest_stand_s;   /**< longest stance between two motions after the alignment, s (0: none) */
    double longest_stand_at_s; /**< its start, s after the first frame (NaN: none) */
    double median_stride_s;   /**< median gait cycle, one motion onset of the foot to the next, s (0: fewer than HX_NAV_STRIDE_MIN_N cycles) */
    long stride_intervals;    /**< the cycles that median is of */
    double rate_change_at_s;  /**< first block of intervals whose rate is off the detector's (hx_rate_changes), s after the first frame (NaN: none) */
    double rate_change_hz;    /**< that block's rate, Hz (NaN: none) */
    double rate_off_fraction; /**< share of the log's duration in such blocks (0: none) */
    double motion_s;          /**< navigated time in motion: intervals after the alignment with an end out of the detector's stance, time jumps left out, s */
    double gap_lost_s;        /**< the time lost in those intervals that are long gaps (HX_NAV_LONG_GAP_S): each one's excess over the detector's period, s */
    long long_gaps;           /**< their number */
    double longest_motion_gap_s; /**< the longest of them, s (0: none) */
    long motion_jumps;        /**< time jumps (over max_gap_s) after the alignment with an end out of the stance */
    double jump_lost_s;       /**< the time they span less one period each, s: the motion inside is not measured */
} hx_nav_summary_t;

/** Lost samples in motion: the strapdown integrates a gap by interpolating
 *  between the readings at its ends, so the motion inside is not measured.
 *  A gap longer than HX_NAV_LONG_GAP_S during motion is a "long gap" (one of
 *  exactly 20 ms is none: test_nav test_long_gap_edge); when
 *  the time they lose reaches HX_NAV_GAP_LOST_FRACTION of the motion time,
 *  the summary notes that position and heading are unreliable. Found on
 *  openshoe_gx2 walk 2 with samples deleted (five phases of each pattern,
 *  closure of the intact walk 0.53 m): holes of 12 ms (3 samples) losing 4 % of the time left the
 *  median closure at 0.53 m, holes of 24 ms losing 0.6 % at 0.59 m, but
 *  holes of 50 ms losing 1.2 % moved it to 0.88 m (up to 1.36) and every
 *  300 ms (17 %) to 2.4 m (up to 3.7). The xio walks lose 1.1 and 1.5 %
 *  in gaps of at most 17.6 ms: no note (docs/harness.md, "replay"). */
#define HX_NAV_LONG_GAP_S 0.020
#define HX_NAV_GAP_LOST_FRACTION 0.01

/** True when the long gaps in motion lose HX_NAV_GAP_LOST_FRACTION of the
 *  motion time or more, or a time jump came while the foot moved (the
 *  summary's notes, the JSON's `motion_gaps.unreliable`). A jump is
 *  integrated as one period: the motion inside is unknown, and one of
 *  0.5 s mid-stride took openshoe_gx2 walk 2 from 0.50 to 3.70 m of
 *  closure, xio's long walk from 0.60 to 7.40 m (a generalisation audit). */
int hx_nav_gappy(const hx_nav_summary_t *s);

/** Time stamps coarser than the sampling: float32 seconds far from 0 (at
 *  1e5 s they step by 2^-7 s = 7.8 ms) or a millisecond clock above 1 kHz
 *  repeat a stamp for many samples. The navigator integrates no repeated
 *  sample (dt = 0) and its detector reads the rate from the stamps, so the
 *  walk is navigated on a fraction of its samples: openshoe_gx2 walk 2 with
 *  float32 stamps at 1e5 s (49 % repeated) halves its ZUPT share, the 820 Hz
 *  walk (84 %) cuts it from 39 % to 7 % and doubles its closure, with exit
 *  0 and no other word. When the
 *  repeated samples reach this share of the log, the summary notes it and
 *  names the remedy; the xio logger repeats 1.2 % (205 and 252 samples). */
#define HX_NAV_DUP_FRACTION 0.10

/** Gait cycles no foot makes: a median cycle (from one onset of the foot's
 *  motion, the detector's stance flag, to the next, counting a motion of
 *  HX_NAV_CYCLE_MOTION_S or more, which no shorter stance ends) below
 *  HX_NAV_STRIDE_MIN_S, a cadence
 *  above 300 steps/min (a sprinter reaches about 280), says the time axis
 *  is compressed: most often a rate assumed for a log without time stamps
 *  (the OpenShoe 820 Hz reader takes six bare numbers a line at 820 Hz: a
 *  250 Hz walk in that form navigates 5 m of 77, a 200 Hz one makes no
 *  stride at all, with exit 0 and no other word). Judged on HX_NAV_STRIDE_MIN_N
 *  cycles or more. */
#define HX_NAV_STRIDE_MIN_S 0.40
#define HX_NAV_STRIDE_MIN_N 8
#define HX_NAV_CYCLE_MOTION_S 0.05

/** True when the gait cycles are too short for a foot (the summary's note). */
int hx_nav_strides_too_short(const hx_nav_summary_t *s);

/** A slow gait: a median gait cycle (as HX_NAV_STRIDE_MIN_S's, of
 *  HX_NAV_STRIDE_MIN_N cycles or more) above HX_NAV_SLOW_CYCLE_S, a cadence
 *  below 70 steps/min. Real walks played slower (scripts/probe_slow.py)
 *  lost 2-33 % of their length at 53-68 steps/min and kept it from 71-75
 *  up, with min_zupt_cycle 0 (the scaling off): in late swing
 *  the foot's slowed deceleration brings |f| near g, the statistic dips
 *  under the threshold for 20-32 ms, longer than the shortest ZUPT run, and
 *  the ZUPT zeroes a swing's velocity. A fixed shortest run of 50 ms
 *  (--param min_zupt_s=0.05) cured those copies but breaks a jogger, whose
 *  stances are shorter (footprint walk 35: 2.67 -> 80.74 %), and does not
 *  guard a slower gait (HX_NAV_SLOW_REMEDY_CYCLE); a shortest run scaled with
 *  the gait cycle, min_zupt_cycle 0.025, the default (with
 *  the lock-in guard that keeps walk 35 at 100 Hz from locking in,
 *  docs/navigation.md), cures them too (2.5 % or less) and keeps walk 35.
 *  docs/harness.md, "Slow walking, real walks played slower". */
#define HX_NAV_SLOW_CYCLE_S (120.0 / 70.0)
/** The min_zupt_cycle from which the slow-gait note says the shortest ZUPT
 *  run follows the cycle instead of naming HX_NAV_SLOW_REMEDY_CYCLE: the
 *  slowed copies lost up to 23 % at 0.015, up to 10 % at 0.02 and 2.5 % at
 *  0.025 (docs/harness.md, "Slow walking, real walks played slower"). */
#define HX_NAV_SLOW_CYCLE_FRAC 0.02
/** The slow-gait note's remedy below HX_NAV_SLOW_CYCLE_FRAC: the default
 *  min_zupt_cycle, whose run (the run_ms of hx_nav_slow_note) the note gives
 *  at the median cycle. A fixed min_zupt_s guards only when it is as long:
 *  a fixed 50 ms does not at 40 steps/min (the simulator's walk, mid-swing
 *  dips of about 55 ms: 34 strides for 17 walked, 19 by default, with
 *  --param min_zupt_cycle=0 --param min_zupt_s=0.05; docs/harness.md, the
 *  summary's note "a slow gait", has the commands). */
#define HX_NAV_SLOW_REMEDY_CYCLE ((double)fnav_nav_config_default.stance.min_zupt_cycle) /* 0.025, the default's */

/** True when the gait is slow (HX_NAV_SLOW_CYCLE_S; not for a log with
 *  almost no motion, which has its own note): the JSON's gait_cycles.slow,
 *  a statement about the gait whatever the settings. */
int hx_nav_gait_slow(const hx_nav_summary_t *s);

/** The summary's slow-gait note, for the configuration that ran (t's; the
 *  default when not said). */
typedef enum {
    HX_SLOW_NOTE_NONE = 0, /**< no slow gait, or min_zupt_cycle below HX_NAV_SLOW_CYCLE_FRAC with a min_zupt_s
                                whose run is as long as HX_NAV_SLOW_REMEDY_CYCLE's at the median cycle (as
                                long as the remedy): nothing said */
    HX_SLOW_NOTE_CYCLE,    /**< min_zupt_cycle of HX_NAV_SLOW_CYCLE_FRAC or more: the run follows the cycle */
    HX_SLOW_NOTE_REMEDY    /**< neither: the note names --param min_zupt_cycle=HX_NAV_SLOW_REMEDY_CYCLE and
                                its run at the median cycle */
} hx_slow_note_t;

/** Which slow-gait note the summary prints; *run_ms (when not NULL)
 *  receives the shortest ZUPT run the detector takes at the median gait
 *  cycle, ms: max(min_zupt_s's run, round(min_zupt_cycle x cycle x rate))
 *  samples, capped at the look-ahead's (fnav_stance.c cycle_update); with
 *  HX_SLOW_NOTE_CYCLE for the min_zupt_cycle that ran, otherwise for
 *  HX_NAV_SLOW_REMEDY_CYCLE (with its own look-ahead, that of a cycle of
 *  FNAV_STANCE_CYCLE_LAG_S, capped by the ring). */
hx_slow_note_t hx_nav_slow_note(const hx_traj_t *t, const hx_nav_summary_t *s, double *run_ms);

/** True when the samples that repeat the time stamp before them reach
 *  HX_NAV_DUP_FRACTION of the samples (the summary's note). */
int hx_nav_coarse_stamps(const fnav_nav_stats_t *st);

/** A stand between strides longer than this is noted in the summary when
 *  the ZARU is off and there are two strides or more: with ZUPTs only the heading drifts with the gyro bias
 *  while the foot stands (docs/navigation.md, "Zero-velocity update"). */
#define HX_NAV_LONG_STAND_S 10.0

/** A log that starts moving: more motion than this before the alignment is
 *  noted in the summary and in eval's row (that part of the walk is not
 *  navigated). A confirmed swing's worth (min_swing_s's default): a log that
 *  starts in a swing aligns on the next stance, after less than a second of
 *  motion (0.40 s for openshoe_gx2 walk 2 cut 0.5 s into its first swing, the JSON's before_alignment_s 0.404),
 *  which a limit of 1 s would let pass without a word; every shared log
 *  has none. */
#define HX_NAV_LATE_ALIGN_S 0.25

/** True when a log of more than 10 s shows almost no motion: over 90 % of
 *  its frames in stance and fewer than three strides (a still log, or
 *  motion too gentle for the foot-tuned detector). */
int hx_nav_little_motion(const hx_nav_summary_t *s);

/** Compute the summary of a trajectory. */
void hx_nav_summarize(const hx_traj_t *t, hx_nav_summary_t *s);

/** Stance mid-points of a trajectory (frame indices): one per segmented
 *  stance phase, the middle of the detector's stance in it (aligned frames
 *  only); returns their number (at most max). */
size_t hx_nav_stance_mids(const hx_traj_t *t, size_t *idx, size_t max);

/** The same with start[i] (may be NULL): the first frame of the segmented
 *  stance phase of idx[i]. */
size_t hx_nav_stance_phases(const hx_traj_t *t, size_t *idx, size_t *start, size_t max);

/** Write the stride CSV (docs/harness.md, "replay", "Stride CSV") of a
 *  trajectory replayed with HX_REPLAY_EVENTS: one row per stride. 0 ok, -1
 *  when t has no events or a write failed. */
int hx_nav_write_strides(FILE *f, const hx_traj_t *t);

/** Print the summary as text. */
void hx_nav_print_summary(FILE *f, const char *path, const hx_traj_t *t, const hx_nav_summary_t *s);

struct cJSON;

/** Write the summary as JSON (keys in docs/harness.md). extra: an object
 *  whose items are added at the end (live's "link"), taken over and freed
 *  in every case; NULL for none. 0 ok, -1 failure. */
int hx_nav_write_json(const char *json_path, const char *log_path, const char *command, const hx_traj_t *t,
                      const hx_nav_summary_t *s, struct cJSON *extra, char *err, size_t err_size);

/** Plot the 2-D path and the height over time. 0 ok, -1 failure (printed). */
int hx_nav_plot(const char *cmd, const char *png, const char *title, const hx_traj_t *t);

#endif /* HX_NAV_H */
