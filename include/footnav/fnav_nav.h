/**
 * @file fnav_nav.h
 * @brief Foot-mounted navigation, one object stepped once per sample: stance
 *        detection, initial alignment, UKF with zero-velocity updates (the
 *        paper's 15 states; 18 with the default lever states). The same
 *        calls run in `harness replay`, in firmware and in the simulator's
 *        Monte Carlo.
 *
 * Use:
 * @code
 *   static fnav_nav_t nav;          // 11.7 KB in float32 (9 KB with the firmware's options), no allocation:
 *                                   // static, not on a small stack
 *   fnav_nav_config_t cfg = fnav_nav_config_default;
 *   if (fnav_nav_init(&nav, &cfg) != FNAV_OK) ...   // FNAV_E_CONFIG: a bad configuration
 *   for each sample s:
 *       st = fnav_nav_push(&nav, &s);       // FNAV_E_NANINF / _RANGE / _TIME: rejected, counted
 *       while (fnav_nav_pop(&nav, &frame) == FNAV_OK) write(frame);
 *   fnav_nav_finish(&nav);
 *   while (fnav_nav_pop(&nav, &frame) == FNAV_OK) write(frame);
 * @endcode
 * or fnav_nav_step(&nav, &s, &frame), which pushes one sample and returns the
 * newest frame (firmware that only wants the latest state). The statuses
 * are FNAV_WARN_UNUSED, which GCC does not let a (void) cast silence: keep
 * them in a variable. A complete program over a port: docs/firmware.md,
 * "Porting to a new board".
 *
 * Ownership and context: the caller owns the navigator (fixed size, no
 * allocation, no pointer kept to anything of the caller's: the
 * configuration is copied by fnav_nav_init, a sample by fnav_nav_push, a
 * port is used only during fnav_nav_run). Not reentrant and not ISR-safe:
 * one navigator per thread of control; a sample-ready interrupt hands its
 * samples over through a queue (port/cortex-m: a lock-free ring) to the
 * loop that pushes and pops. The calls that return a status refuse a NULL
 * pointer with FNAV_E_ARG; fnav_nav_finish and fnav_nav_reset assert it
 * (FNAV_ASSERT, a programmer error). A navigator never initialised (static
 * storage is zeroed) or whose fnav_nav_init failed is refused with
 * FNAV_E_STATE by every call that returns a status (finish and reset do
 * nothing); an automatic one never initialised holds whatever was on the
 * stack, which no check can tell from a navigator: initialise it first.
 *
 * Units are not checked: the core refuses only what no sensor reads
 * (NaN/Inf, FNAV_INPUT_MAX_ABS, a rate or force past the widest MEMS
 * ranges, stamps going back) and navigates the rest as SI. Accelerations
 * in g never align (the alignment refuses a still period off gravity by
 * more than FNAV_ALIGN_GRAVITY_TOL: frames without FNAV_FRAME_ALIGNED, the
 * |f| it refused in nav.align.refused_f_mps2); rates in deg/s align (a
 * foot at rest barely turns), the swings' samples past
 * FNAV_NAV_GYRO_MAX_RPS are refused (stats.range_inputs) and the rest turn
 * the foot 57 times too fast: a nonsense track, usually divergence resets
 * (FNAV_HEALTH_RESET); stamps in ms make the rate estimate
 * (nav.stance.rate_hz) 1000 times too low. Convert in the port's
 * read_sample; `harness replay` checks these marks after a run
 * (docs/firmware.md, "Porting to a new board").
 *
 * Latency: the SHOE window is centred, so a sample's statistic is known h =
 * (W - 1) / 2 samples after it, and the stance decision also waits for the
 * shortest ZUPT run to be confirmed: frames come out h + lag samples after
 * their sample. With the defaults (25 ms window, stance.min_zupt_cycle
 * 0.025) the lag is fixed for the longest cycle-scaled run: at
 * 200 Hz h 2, lag 14, frames 16 samples (80 ms) late; fnav_stance.h. With
 * stance.min_zupt_cycle 0 (the scaling off) lag = n_min_zupt - 1:
 * 5 samples (25 ms) at 200 Hz with the 20 ms run (h 2, lag 3). When the rate
 * is estimated (rate_hz = 0) the first frame waits for 33 samples (the
 * median of 32 intervals; FNAV_STANCE_MAX_WINDOW samples, the window less
 * one, where that is shorter: 24 with the reference firmware's options)
 * or for its latency h + lag, whichever is later:
 * with the defaults the 33rd sample at 200 Hz, the 35th at 400 Hz, the 63rd
 * at 820 Hz (test_nav test_first_frames). Each frame carries its own
 * sample's time.
 *
 * Timing: each sample's own dt is used. A repeated time stamp (dt = 0,
 * e.g. the duplicated rows of the NGIMU logs) is counted and produces a
 * frame without propagation or update (the filter must not count a
 * duplicate as a second measurement; the alignment's still-period means and
 * the stance detector's window do take it, with the weight of one sample,
 * which is what the committed NGIMU replays were made with); an interval longer than 1.5 nominal intervals is
 * counted as a gap and integrated as it is; an interval longer than
 * max_gap_s (and than 1.5 nominal intervals: init refuses a max_gap_s below
 * that with a configured rate) is counted as a time jump and integrated as
 * one nominal interval (the motion inside it is unknown); time going backwards is rejected with
 * FNAV_E_TIME and the sample ignored, unless FNAV_NAV_TIME_RESYNC (16)
 * samples in a row are behind the last accepted one: the last of them is
 * accepted as a new timeline (one corrupted stamp far ahead, a restarted
 * sensor timer), and the interval back to it is a time jump. NaN/Inf samples are rejected with
 * FNAV_E_NANINF. Nothing of the state changes on a rejected sample but
 * the counters (stats, health, the run of samples behind).
 */
#ifndef FNAV_NAV_H
#define FNAV_NAV_H

#include "fnav_align.h"
#include "fnav_port.h"
#include "fnav_profile.h"
#include "fnav_stance.h"
#include "fnav_ukf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* fnav_nav_frame_t.health bits (sticky: set once the event happened). */
#define FNAV_HEALTH_NANINF 0x001u        /**< a sample with NaN/Inf was rejected */
#define FNAV_HEALTH_TIME_BACK 0x002u     /**< a sample going back in time was rejected */
#define FNAV_HEALTH_DUPLICATE 0x004u     /**< a repeated time stamp (dt = 0) was seen */
#define FNAV_HEALTH_GAP 0x008u           /**< an interval > 1.5 nominal intervals was seen */
#define FNAV_HEALTH_TIME_JUMP 0x010u     /**< an interval > max_gap_s was seen */
#define FNAV_HEALTH_CHOL_JITTER 0x020u   /**< a covariance factorisation needed jitter */
#define FNAV_HEALTH_CHOL_RESET 0x040u    /**< the covariance was reset to its diagonal */
#define FNAV_HEALTH_DIVERGED 0x080u      /**< a filter step was undone (non-finite result) */
#define FNAV_HEALTH_UPDATE_REJECT 0x100u /**< an update was skipped (bad innovation covariance) */
#define FNAV_HEALTH_NOT_ALIGNED 0x200u   /**< the input ended before an alignment */
#define FNAV_HEALTH_COV_GUARD 0x400u     /**< the covariance guard reset or clamped a variance */
#define FNAV_HEALTH_RESET 0x800u         /**< the navigator diverged and was reset (fnav_nav_reset) */
#define FNAV_HEALTH_RANGE 0x1000u        /**< a sample beyond FNAV_INPUT_MAX_ABS or FNAV_T_NS_MAX was rejected */

/* Additional fnav_nav_frame_t.flags bits (fnav_port.h defines 0x1..0x4). */
#define FNAV_FRAME_SEG_STANCE 0x8u  /**< segmented gait phase is stance */
#define FNAV_FRAME_STRIDE 0x10u     /**< a stride (swing) ended at this frame */

/** Configuration of the navigator. */
typedef struct {
    fnav_profile_t profile;            /**< sensor error model (white noise, AR(1) biases) */
    fnav_bias_model_t bias_model;      /**< AR1 (default) or OFF (paper IV.A) */
    fnav_stance_config_t stance;       /**< detector (its gravity is overwritten with gravity_mps2) */
    fnav_align_config_t align;         /**< alignment (gravity overwritten) */
    fnav_real_t gravity_mps2;          /**< local gravity, m/s^2 (default 9.80665) */
    fnav_sample_type_t sample_type;    /**< what a sample is (fnav_strapdown.h): instantaneous (default) or interval mean */
    fnav_real_t accel_motion_noise_mps2_rthz; /**< extra accel process noise in motion, m/s^2/sqrt(Hz) */
    fnav_real_t gyro_motion_noise_rps_rthz;   /**< extra gyro process noise, rad/s/sqrt(Hz) */
    fnav_real_t zupt_sigma_mps;        /**< ZUPT noise, m/s */
    int lever;                         /**< 1: estimate the rolling-foot lever (fnav_ukf.h) */
    fnav_real_t lever_sd_m;            /**< initial lever sd, m */
    fnav_real_t lever_rw_m_rts;        /**< lever random walk, m/sqrt(s) */
    int settle;                        /**< 1: the landing settling state (fnav_ukf.h) */
    fnav_real_t settle_sd_mps;         /**< settling sd at each stance onset, m/s */
    fnav_real_t settle_tau_s;          /**< settling time constant, s */
    int zaru;                          /**< 1: zero-angular-rate updates in stance; 0: none (other values refused) */
    fnav_real_t zaru_sigma_rps;        /**< ZARU noise, rad/s */
    fnav_real_t zaru_gate;             /**< ZARU validation gate, chi-square 3 dof (fnav_ukf.h); 0: none */
    fnav_real_t zaru_after_s;          /**< ZARU only once a stance has lasted this long, s (0: from its start) */
    fnav_real_t realign_min_s;         /**< until the first stride, every clean still period of at
                                            least this long renews the alignment; 0: off;
                                            at most align.max_still_s, where a period ends
                                            (docs/navigation.md, "Initial alignment") */
    fnav_real_t tilt_sd_rad;           /**< initial roll/pitch standard deviation, rad */
    fnav_real_t yaw_sd_rad;            /**< initial yaw standard deviation, rad (yaw is defined 0) */
    fnav_real_t gyro_bias_sd_rps;      /**< initial sd of the AR(1) gyro bias states, rad/s */
    fnav_real_t accel_bias_sd_mps2;    /**< initial sd of the AR(1) accel bias states, m/s^2 */
    fnav_real_t max_gap_s;             /**< intervals above this (and above 1.5 nominal intervals)
                                            are time jumps, s (default 0.2, docs/navigation.md
                                            "Timing"); with stance.rate_hz set, init
                                            refuses max_gap_s <= 1.5 / rate_hz */
    int closed_form;                   /**< UKF closed-form linear sigma points (1) or not (0) */
    fnav_real_t diverge_speed_mps;     /**< |velocity| above this is divergence, m/s (default 30:
                                            beyond any foot, sprinting swing included) */
    uint32_t diverge_undone;           /**< this many consecutive undone predictions is divergence (default 20;
                                            an update undone, FNAV_E_DIVERGED of a ZUPT, is counted in the
                                            health, not here: the prediction after it decides) */
} fnav_nav_config_t;

/** Defaults: profile "generic-mems" (fnav_profile.h) with the AR(1) bias
 *  model, lever on (18 states), SHOE with the adaptive threshold, the
 *  detector's rate estimated (stance.rate_hz 0). Every field's default,
 *  unit and reason: docs/navigation.md, "Configuration" (the fields above
 *  name their unit; the alignment's and the detector's defaults are in
 *  fnav_align.h and fnav_stance.h). */
extern const fnav_nav_config_t fnav_nav_config_default;

/** Counters (also summarised in fnav_nav_frame_t.health). */
typedef struct {
    uint32_t samples;        /**< samples accepted */
    uint32_t frames;         /**< frames produced */
    uint32_t nan_inputs;     /**< samples rejected: NaN/Inf */
    uint32_t range_inputs;   /**< samples rejected: |value| > FNAV_INPUT_MAX_ABS, a rate or force past the widest
                                  MEMS ranges (FNAV_NAV_GYRO_MAX_RPS, FNAV_NAV_ACCEL_MAX_MPS2), or
                                  |t_ns| > FNAV_T_NS_MAX */
    uint32_t time_back;      /**< samples rejected: time going backwards */
    uint32_t duplicates;     /**< dt = 0 */
    uint32_t gaps;           /**< dt > 1.5 nominal */
    uint32_t time_jumps;     /**< dt > max_gap_s */
    uint32_t stance_samples; /**< samples decided as stance */
    uint32_t zupts;          /**< ZUPT updates applied */
    uint32_t zarus;          /**< ZARU updates applied */
    uint32_t zaru_gated;     /**< ZARU updates skipped by the gate (the foot turns) */
    uint32_t realigned;      /**< alignments renewed before the first stride */
    uint32_t strides;        /**< completed swings */
    uint32_t chol_jitter, chol_reset, diverged, update_reject; /**< UKF health */
    uint32_t cov_guard;      /**< covariance guard interventions (fnav_ukf.h) */
    uint32_t resets;         /**< divergence resets (automatic or fnav_nav_reset) */
    fnav_real_t max_gap_seen_s; /**< longest interval seen, s */
} fnav_nav_stats_t;

/** The navigator (caller-owned, fixed size). */
typedef struct {
    fnav_nav_config_t cfg;
    fnav_stance_t stance;
    fnav_align_t align;
    fnav_ukf_t ukf;
    int aligned;
    int have_prev;          /**< a sample was processed */
    int64_t t_prev_ns;      /**< time of the last processed sample */
    uint32_t back_run;      /**< consecutive samples rejected for a stamp behind t_in_ns (FNAV_NAV_TIME_RESYNC;
                                 in the place of a flag "a sample was accepted", which t_in_ns now says) */
    uint32_t undone_run;    /**< consecutive undone predictions (here: no padding before t_in_ns) */
    int64_t t_in_ns;        /**< time of the last accepted sample; INT64_MIN before the first (no stamp is behind it) */
    uint32_t health;        /**< FNAV_HEALTH_* bits */
    fnav_nav_stats_t stats;
    fnav_nav_frame_t last;  /**< newest frame */
    int prev_stance;        /**< the previous frame was decided stance */
    int settle_pending;     /**< a stance began: start the settling state at its first ZUPT */
    fnav_real_t stance_s;   /**< time the current stance has lasted, s */
    int renewing;           /**< aligned, no stride yet: still periods renew the alignment */
    int have_hold;          /**< a reset holds the last good position and heading */
    fnav_vec3_t hold_pos_m; /**< position carried over a reset, n frame, m */
    fnav_quat_t hold_q_nb;  /**< attitude of the newest aligned frame, carried over a reset or a
                                 renewal (its heading is kept; the frame's Euler angles lose it
                                 near pitch +-90 deg) */
    fnav_real_t hold_pos_var_m2[3]; /**< position variance carried over a reset, m^2 */
    fnav_real_t hold_yaw_var_rad2;  /**< heading variance carried over a reset (attitude error
                                         about n's z), rad^2; -1 after a renewal with no reset
                                         before it (none held) */
} fnav_nav_t;

/** fnav_nav_init() with the caller's FNAV_BUILD_TAG, sizeof(fnav_nav_t) and sizeof(fnav_nav_config_t)
 *  (call fnav_nav_init(), which passes them): FNAV_E_BUILD, *nav not written, when one is not
 *  the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_nav_init_tagged(fnav_nav_t *nav, const fnav_nav_config_t *cfg,
                                                    uint64_t build_tag, size_t obj_size, size_t cfg_size);

/** Initialise, or start over: every earlier state and counter is
 *  dropped, so a second call resets the navigator. *cfg is copied (it need
 *  not outlive the call); it may be the navigator's own, &nav->cfg, to
 *  start over with the same configuration.
 *  @return FNAV_OK, FNAV_E_ARG (NULL; *nav untouched), FNAV_E_CONFIG
 *          (profile or any module's configuration invalid, or an initial
 *          tilt or yaw sd above fnav_nav_att_sd_max_rad(); *nav is left
 *          zeroed, not initialised: the other calls say FNAV_E_STATE).
 *  FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *  than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *  them): nothing written. */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_nav_init(fnav_nav_t *nav, const fnav_nav_config_t *cfg)
{
    return fnav_nav_init_tagged(nav, cfg, FNAV_BUILD_TAG, sizeof(fnav_nav_t), sizeof(fnav_nav_config_t));
}

/** The largest tilt_sd_rad and yaw_sd_rad fnav_nav_init takes with cfg's
 *  filter, rad (fnav_ukf_att_sd_max): 0.707 rad = 40.5 deg with the
 *  default 18 states, the lever's included; 0.775 rad = 44.4 deg without
 *  the lever. Above it fnav_nav_init says FNAV_E_CONFIG (to the rounding
 *  of its test). 0 for NULL. */
fnav_real_t fnav_nav_att_sd_max_rad(const fnav_nav_config_t *cfg);

/**
 * Accept one sample (b frame, SI units: m/s^2, rad/s, ns; not checked,
 * see the file comment).
 * @return FNAV_OK; FNAV_E_ARG for NULL; FNAV_E_STATE for a navigator not
 *         initialised (nothing counted); FNAV_E_NANINF, FNAV_E_RANGE (a
 *         value beyond FNAV_INPUT_MAX_ABS, a rate or force past the widest
 *         MEMS ranges, FNAV_NAV_GYRO_MAX_RPS and FNAV_NAV_ACCEL_MAX_MPS2:
 *         a glitch no sensor reads, or a stamp beyond
 *         FNAV_T_NS_MAX) or FNAV_E_TIME (a stamp behind the last accepted
 *         one, but the FNAV_NAV_TIME_RESYNC-th in a row, which is
 *         accepted): sample rejected (counted, state
 *         unchanged); FNAV_E_STATE after fnav_nav_finish(), checked before
 *         the sample, whatever it holds: nothing counted, the navigator
 *         unchanged; FNAV_E_STATE also for a good sample when frames were
 *         not popped (a bad one is rejected and counted as above).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_nav_push(fnav_nav_t *nav, const fnav_sample_t *sample);

/** The input check of fnav_nav_push, for a receiver that must refuse what
 *  the navigator would (harness live, before recording). @return FNAV_OK,
 *  FNAV_E_NANINF (a non-finite value), FNAV_E_RANGE (a value beyond
 *  FNAV_INPUT_MAX_ABS or a time beyond FNAV_T_NS_MAX), FNAV_E_ARG. */
FNAV_WARN_UNUSED fnav_status_t fnav_sample_check(const fnav_sample_t *s);

/**
 * Next navigation frame.
 * @return FNAV_OK with *frame; FNAV_AGAIN when none is due; FNAV_END after
 *         fnav_nav_finish() when all frames were returned; FNAV_E_ARG for
 *         NULL; FNAV_E_STATE for a navigator not initialised. A filter
 *         problem in this step (covariance reset, undone step) is reported in
 *         frame->health and the counters, not as a status.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_nav_pop(fnav_nav_t *nav, fnav_nav_frame_t *frame);

/**
 * Divergence reset: the filter stops and re-aligns at the next still period,
 * keeping the last good position and heading (with their variances) so the
 * trajectory stays continuous; until then frames hold that position with the
 * ALIGNED flag clear. The navigator calls it itself when |velocity| exceeds
 * cfg.diverge_speed_mps or cfg.diverge_undone consecutive predictions were undone;
 * a caller may call it on its own evidence (e.g. an external position fix
 * disagreeing). Counted in stats.resets, FNAV_HEALTH_RESET in the frames.
 * Does nothing to a navigator not initialised.
 */
void fnav_nav_reset(fnav_nav_t *nav);

/** End of input (does nothing to a navigator not initialised): the frames
 *  held back by the detector become due. If the input ended before an
 *  alignment, aligns on what was still, if enough
 *  (fnav_align_finish): at once on the samples popped so far when they
 *  qualify, and the held-back frames are navigated; else the held-back
 *  samples go on to the alignment as their frames are popped, and it
 *  completes on the first with which the still period qualifies (that frame
 *  aligned, neither predicted nor updated; the later ones navigated, as
 *  after an alignment at max_still_s). Still not aligned when
 *  fnav_nav_pop returns FNAV_END: FNAV_HEALTH_NOT_ALIGNED in nav->health. */
void fnav_nav_finish(fnav_nav_t *nav);

/**
 * Push one sample and process every due frame; *frame receives the newest.
 * When one sample releases several frames (with the rate estimated,
 * stance.rate_hz = 0, the 33rd sample releases the first 33 - (h + lag)
 * when the latency is shorter: 17 at 200 Hz with the defaults, 28 at 200
 * Hz and 21 at 400 Hz with stance.min_zupt_cycle 0; at 400 Hz and above
 * the defaults' latency is longer and frames come one a sample; test_nav
 * test_first_frames) the earlier ones are processed and counted
 * (stats.frames) but not returned: push and pop to see every frame.
 * @return FNAV_OK with *frame; FNAV_AGAIN when no frame is due yet; the
 *         statuses of fnav_nav_push() (FNAV_E_ARG also for a NULL frame,
 *         checked before the sample, which is then not taken).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_nav_step(fnav_nav_t *nav, const fnav_sample_t *sample, fnav_nav_frame_t *frame);

/**
 * Replay a whole source through a port, as firmware does: read_sample ->
 * fnav_nav_push -> fnav_nav_pop -> write_nav, until the source ends.
 * @param max_samples  stop after this many samples (0: no limit)
 * @return FNAV_OK at the end of the source; the source's negative status
 *         (after flushing every frame) on a read error; FNAV_E_IO when the
 *         sink fails; FNAV_E_ARG for NULL; FNAV_E_STATE, before reading
 *         anything, for a navigator not initialised or already finished (a
 *         second run needs fnav_nav_init first). Rejected samples are
 *         counted, not fatal.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_nav_run(fnav_nav_t *nav, const fnav_port_t *port, long max_samples);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_NAV_H */
