/**
 * @file fnav_stance.h
 * @brief Stance (zero-velocity) detection for a foot-mounted IMU: the SHOE
 *        generalised likelihood ratio test (Skog, Handel, Nilsson, Rantakokko
 *        2010) by default, or a simple angular-rate / specific-force
 *        threshold detector; a rate-adaptive window, an optional adaptive
 *        threshold, stride segmentation and gait events (foot-off,
 *        foot-strike).
 *
 * SHOE test statistic over a centred window of W samples (Skog et al. 2010,
 * eq. (13) with the gravity direction taken from the window mean):
 *
 *   T_k = 1/W sum_j ( |f_j - g u|^2 / sigma_a^2 + |w_j|^2 / sigma_g^2 ),
 *   u = mean(f) / |mean(f)|,
 *
 * and the foot is at rest when T_k < gamma. A centred window looks half a
 * window ahead, so the detector delays its decisions by h = (W - 1) / 2
 * samples; a raw stance must also last at least min_zupt_s (a single-sample
 * dip of T in mid-swing, when the foot's rotation reverses, must not zero a
 * velocity of metres per second), which needs L = min_zupt_s * rate - 1 more
 * samples of look-ahead (more with min_zupt_cycle, the default: below).
 * fnav_stance_push() stores each sample in a fixed
 * ring inside the object and fnav_stance_pop() returns it, with its
 * decision, h + L samples later. Call pop until it says FNAV_AGAIN
 * after every push; after the last sample call fnav_stance_finish() and pop
 * until FNAV_END.
 *
 * The window and the durations are set in seconds and converted with the
 * sample rate (configured, or the median of the first FNAV_STANCE_RATE_PROBE
 * intervals, fewer when FNAV_STANCE_MAX_WINDOW is smaller; stamps too coarse
 * for a median interval need the rate configured), so the detector behaves
 * the same at 100 Hz and at 820 Hz. h + L + 2 samples must fit in the
 * ring (FNAV_STANCE_MAX_WINDOW, as set_rate applies it): above about 1.95 kHz with the default 64
 * the window is cut to what fits and min_zupt_s to what is left (at 4 kHz:
 * 63 samples, 15.75 ms, and 32 samples, 8 ms, not 25 and 20 ms;
 * docs/navigation.md, "Stance detector").
 *
 * Adaptive threshold (docs/navigation.md): running or jogging keeps the foot
 * from coming fully to rest, and the statistic's minimum in each stance rises
 * by one to two decades. The detector tracks the floor F of log10 T, its
 * minimum over the last floor_window_s (longer than a stride, so the window
 * always holds the last stance; kept as the minima of
 * FNAV_STANCE_FLOOR_BLOCKS blocks) and uses gamma' = clamp(10^(F + margin),
 * gamma, adapt_max_ratio * gamma) for the next sample: for walking the floor
 * sits decades below the configured gamma and nothing changes; when the
 * stance minima rise, the threshold follows them one window later (so the
 * first running stances after a transition are missed: docs/navigation.md).
 *
 * Cycle-scaled shortest ZUPT run (min_zupt_cycle > 0, 0.025 by default;
 * docs/navigation.md, "Stance detector"): in a slow gait the statistic dips under the threshold
 * for 20-32 ms in late swing, longer than min_zupt_s, and a ZUPT there
 * removes about 1 m/s (docs/harness.md, "Slow walking"). The shortest run
 * then becomes max(n(min_zupt_s), round(min_zupt_cycle * T * rate)) samples,
 * where T is the median of the last three gait cycles (the time between the
 * starts of successive segmented swings; the smaller of two, the one when
 * fewer are known; min_zupt_s alone before the second swing start). A cycle
 * longer than FNAV_STANCE_CYCLE_MAX_S (4 s) spans a stand: it clears the
 * cycles known (as does a step back in time), and the scaling starts again
 * from min_zupt_s. The largest run the scaling can ask for, that of a cycle
 * of FNAV_STANCE_CYCLE_LAG_S (3 s; longer cycles get it),
 * round(min_zupt_cycle * FNAV_STANCE_CYCLE_LAG_S * rate), fixes the
 * look-ahead L when the rate becomes known (capped by the ring as above,
 * FNAV_STANCE_CUT_ZUPT_CYCLE): the latency is fixed, h + L samples, and
 * grows with min_zupt_cycle (the default 0.025 at 200 Hz: L = 14, 70 ms,
 * h + L 80 ms; at 0, the scaling off, L = n(min_zupt_s) - 1,
 * 15 ms, h + L 25 ms, and the decisions without the scaling).
 *
 * Lock-in guard (min_zupt_cycle > 0): a gait whose stances are shorter than
 * the run a long cycle asked for (a jog after a slow start, a pause) would
 * have every stance rejected, so no swing ends, no cycle is measured and
 * the run never comes down (footprint walk 35 at 100 Hz: 16 strides,
 * 100.5 m for 65.4 m). The detector remembers the lengths of the last
 * FNAV_STANCE_RAW_RUNS raw stance runs of at least n(min_zupt_s) samples,
 * accepted or rejected, and caps the scaled run at half the longest of them
 * (never below n(min_zupt_s)). In a slow walk the stance (hundreds of ms) is
 * among them beside the late-swing dips (1-2 per cycle), so the cap does not
 * bind; in a lock-in every recent run is a short stance, and the cap falls
 * under them after at most FNAV_STANCE_RAW_RUNS of them.
 *
 * Not ISR-safe by itself (one object per caller); no allocation.
 */
#ifndef FNAV_STANCE_H
#define FNAV_STANCE_H

#include "fnav_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/* FNAV_STANCE_EVENT_BUF (fnav_config.h): jerk history of the foot-strike
 * search, samples. */

/** Jerk samples per block of the foot-strike search's block maxima
 *  (FNAV_STANCE_EVENT_BUF is a multiple of it). */
#define FNAV_STANCE_JERK_BLOCK 8

/** Number of intervals used to estimate the rate when none is configured. */
#define FNAV_STANCE_RATE_PROBE 32

/** Detector kind. */
typedef enum {
    FNAV_DETECTOR_SHOE = 0,     /**< SHOE / GLRT (default) */
    FNAV_DETECTOR_THRESHOLD = 1 /**< |w| and ||f| - g| below thresholds */
} fnav_detector_t;

/** Configuration; every value in SI units. */
typedef struct {
    fnav_detector_t detector;   /**< SHOE (default) or THRESHOLD */
    fnav_real_t rate_hz;        /**< nominal sample rate, Hz; 0: estimate from the first 32 intervals
                                     (100 Hz when no interval is positive: stamps that never advance) */
    fnav_real_t window_s;       /**< detector window, s (default 0.025: 5 samples at 200 Hz) */
    fnav_real_t sigma_a_mps2;   /**< SHOE accelerometer noise weight, m/s^2 (default 0.01) */
    fnav_real_t sigma_g_rps;    /**< SHOE gyroscope noise weight, rad/s (default 0.1 deg/s) */
    fnav_real_t gamma;          /**< SHOE threshold on T, dimensionless (default 1e5) */
    fnav_real_t gyro_thresh_rps;   /**< THRESHOLD: window RMS |w| limit, rad/s (default 0.6) */
    fnav_real_t accel_thresh_mps2; /**< THRESHOLD: window RMS ||f| - g| limit, m/s^2 (default 0.6) */
    fnav_real_t gravity_mps2;   /**< local gravity, m/s^2 (default 9.80665) */
    int adaptive;               /**< 1 (default): adaptive threshold (see file comment) */
    fnav_real_t floor_window_s; /**< adaptive floor: minimum of log10 T over this window, s (default 2) */
    fnav_real_t margin_dec;     /**< threshold above the floor, decades (default 0.4) */
    fnav_real_t adapt_max_ratio; /**< adaptive threshold at most this times gamma (default 10) */
    fnav_real_t min_zupt_s;     /**< a stance shorter than this is ignored, s (default 0.02) */
    fnav_real_t min_stance_s;   /**< segmentation: shortest stance ending a swing, s (default 0.05) */
    fnav_real_t min_swing_s;    /**< segmentation: shortest swing, s (default 0.25) */
    fnav_real_t event_window_s; /**< gait-event search window, s (default 0.3) */
    fnav_real_t min_zupt_cycle; /**< shortest ZUPT run as a fraction of the recent gait cycle,
                                     dimensionless (default 0.025; 0: off; see
                                     "Cycle-scaled shortest ZUPT run" above) */
} fnav_stance_config_t;

/** Cycle-scaled ZUPT run: the look-ahead covers the run of a gait cycle this
 *  long, s (a stride of two steps at 40 steps/min, slower than the slowest
 *  walks measured, 49 steps/min; docs/harness.md, "Slow walking"); a longer
 *  cycle gets that run. */
#define FNAV_STANCE_CYCLE_LAG_S FNAV_R(3.0)
/** Cycle-scaled ZUPT run: a "cycle" longer than this, s, spans a stand and
 *  clears the cycles known (the slowed walks' turning strides last up to
 *  3.5 s at 49 steps/min). */
#define FNAV_STANCE_CYCLE_MAX_S FNAV_R(4.0)

/** Cycle-scaled ZUPT run's guard: the raw stance runs remembered; the
 *  scaled run is at most half the longest of them (at least n(min_zupt_s);
 *  see "Lock-in guard" above). 3: a slow walk's stance stays among them
 *  while up to three late-swing dips of a swing are decided (a fourth
 *  would pass), and a lock-in ends after three short
 *  stances (with 4, footprint walk 35 at 100 Hz kept 77.6 m for 65.4 m;
 *  docs/navigation.md). At most 4 fit the padding the bytes sit in. */
#define FNAV_STANCE_RAW_RUNS 3

/** Blocks of the sliding-window minimum of the adaptive floor. */
#define FNAV_STANCE_FLOOR_BLOCKS 8

/** The defaults' initializer, shared by fnav_stance_config_default and the
 *  navigator's default (fnav_nav_config_default.stance), so the two cannot
 *  differ. */
#define FNAV_STANCE_CONFIG_DEFAULT_INIT                                                                            \
    {                                                                                                              \
        FNAV_DETECTOR_SHOE,          /* detector */                                                                \
        FNAV_R(0.0),                 /* rate_hz: estimate */                                                       \
        FNAV_R(0.025),               /* window_s, s */                                                             \
        FNAV_R(0.01),                /* sigma_a_mps2, m/s^2 (OpenShoe default) */                                  \
        FNAV_R(0.1) * FNAV_DEG2RAD,  /* sigma_g_rps, rad/s (OpenShoe default) */                                   \
        FNAV_R(1.0e5),               /* gamma */                                                                   \
        FNAV_R(0.6),                 /* gyro_thresh_rps, rad/s */                                                  \
        FNAV_R(0.6),                 /* accel_thresh_mps2, m/s^2 */                                                \
        FNAV_R(9.80665),             /* gravity_mps2, m/s^2 */                                                     \
        1,                           /* adaptive */                                                                \
        FNAV_R(2.0),                 /* floor_window_s, s */                                                       \
        FNAV_R(0.4),                 /* margin_dec, decades */                                                     \
        FNAV_R(10.0),                /* adapt_max_ratio */                                                         \
        FNAV_R(0.02),                /* min_zupt_s, s */                                                           \
        FNAV_R(0.05),                /* min_stance_s, s */                                                         \
        FNAV_R(0.25),                /* min_swing_s, s */                                                          \
        FNAV_R(0.3),                 /* event_window_s, s */                                                       \
        FNAV_R(0.025)                /* min_zupt_cycle (docs/navigation.md, "Cycle-scaled shortest run") */    \
    }

/** Defaults (see each field). */
extern const fnav_stance_config_t fnav_stance_config_default;

/** fnav_stance_out_t.events: a swing ended (a stride was completed). */
#define FNAV_STANCE_EV_STRIDE 0x1u
/** fnav_stance_out_t.events: foot-off time fo_t_ns was determined. */
#define FNAV_STANCE_EV_FOOT_OFF 0x2u
/** fnav_stance_out_t.events: foot-strike time fs_t_ns was determined. */
#define FNAV_STANCE_EV_FOOT_STRIKE 0x4u

/** One decision, for the sample it carries (h + L samples behind the input). */
typedef struct {
    fnav_sample_t sample; /**< the sample this decision is for */
    fnav_real_t stat;     /**< test statistic T (SHOE); THRESHOLD: the larger of (RMS |w| /
                               gyro_thresh)^2 and (RMS ||f| - g| / accel_thresh)^2, a mean
                               square like T, stance below 1 */
    fnav_real_t gamma;    /**< threshold used for this sample */
    int raw_stance;       /**< 1: statistic below the threshold */
    int stance;           /**< 1: foot at rest (apply a zero-velocity update): raw stance in a
                               run of at least min_zupt_s (or the cycle-scaled run) */
    int segment_stance;   /**< segmented gait phase: 1 stance, 0 swing */
    uint32_t events;      /**< FNAV_STANCE_EV_* bits raised at this sample */
    int64_t fo_t_ns;      /**< foot-off time, ns (with EV_FOOT_OFF) */
    int64_t fs_t_ns;      /**< foot-strike time, ns (with EV_FOOT_STRIKE) */
    int64_t swing_t0_ns;  /**< with EV_STRIDE: first sample of the swing, ns */
    int64_t swing_t1_ns;  /**< with EV_STRIDE: first sample of the stance that ended it, ns */
} fnav_stance_out_t;

/** Detector object (caller-owned; fixed size, about 5.3 KB in float, see
 *  docs/navigation.md for the measured sizeof). */
typedef struct {
    fnav_stance_config_t cfg;
    fnav_sample_t ring[FNAV_STANCE_MAX_WINDOW]; /**< newest samples */
    long n_in;          /**< samples pushed (the three counters move back together by a
                             multiple of both rings from 2^30 on: a long run never overflows) */
    long n_raw;         /**< raw decisions made */
    long n_out;         /**< decisions returned */
    fnav_real_t dq_stat[FNAV_STANCE_MAX_WINDOW];  /**< raw decisions waiting for confirmation */
    fnav_real_t dq_gamma[FNAV_STANCE_MAX_WINDOW];
    unsigned char dq_raw[FNAV_STANCE_MAX_WINDOW];
    int lag;            /**< confirmation look-ahead, samples (n_min_zupt - 1; with min_zupt_cycle,
                             the largest run the scaling can ask for - 1) */
    int n_min_zupt;     /**< shortest stance run from min_zupt_s, samples */
    long back;          /**< raw stance run length ending at the last output (saturates) */
    int win;            /**< window W, samples (odd), 0 until the rate is known */
    int half;           /**< h = (W - 1) / 2 */
    fnav_real_t rate_hz; /**< rate in use, Hz */
    int floor_valid;       /**< a statistic entered the floor window */
    fnav_real_t fw_blk[FNAV_STANCE_FLOOR_BLOCKS]; /**< minima of T in the completed blocks */
    int fw_nblk, fw_head;  /**< completed blocks kept, next slot */
    fnav_real_t fw_cur;    /**< minimum of the block being filled */
    long fw_fill, fw_len;  /**< samples in it, samples per block */
    fnav_real_t margin_ratio; /**< 10^margin_dec */
    /* segmentation */
    unsigned char seg;  /**< 1 stance, 0 swing */
    signed char run_raw; /**< raw decision of the current run (-1 before the first) */
    unsigned char cyc_n;      /**< min_zupt_cycle: cycles in cyc_run (bits 0-1: 0-3); bit 2: a
                                   swing start is known */
    unsigned char raw_cap;    /**< min_zupt_cycle's lock-in guard: half the longest of raw_runs,
                                   the cycle-scaled run's cap, samples */
    long run;           /**< length of the current run of raw decisions, samples (saturates) */
    unsigned char cyc_run[3]; /**< min_zupt_cycle: the last gait cycles' shortest runs, samples
                                   (newest first) */
    unsigned char raw_runs[FNAV_STANCE_RAW_RUNS]; /**< the guard: the last raw stance runs of at
                                   least n_min_zupt samples, accepted or not, samples (newest
                                   first, saturated at 255; 0: none yet). These bytes sit
                                   in the padding around run (before run_t0_ns): the struct's
                                   size is as without them. */
    int64_t run_t0_ns;  /**< time of the first sample of the run */
    int64_t swing_t0_ns; /**< start of the current swing */
    int64_t prev_t_ns;  /**< time of the last decision */
    fnav_real_t prev_acc[3]; /**< specific force of the last decision (for the jerk) */
    int have_prev;
    /* foot-off search: largest |f| in the first event_window_s of a swing run */
    fnav_real_t fo_max;
    int n_zupt_req;     /**< shortest stance run in use, samples: n_min_zupt, or more from the
                             gait cycle (min_zupt_cycle) */
    int64_t fo_t_ns;
    int fo_open;
    int fo_pending;     /**< report foot-off once the swing is confirmed */
    /* foot-strike search: jerk history of the newest decisions */
    fnav_real_t jerk[FNAV_STANCE_EVENT_BUF];     /**< |f_k - f_k-1|, m/s^2 */
    uint32_t jerk_t_us[FNAV_STANCE_EVENT_BUF];   /**< sample time, us modulo 2^32 */
    int jerk_long_left; /**< decisions for which the history still holds an interval of
                             2^31 us / FNAV_STANCE_EVENT_BUF or more (0: none) */
    fnav_real_t jerk_bmax[FNAV_STANCE_EVENT_BUF / FNAV_STANCE_JERK_BLOCK]; /**< largest jerk per block */
    int n_ev;           /**< event window, samples */
    int n_min_stance;   /**< shortest stance, samples */
    int n_min_swing;    /**< shortest swing, samples */
    long strides;       /**< completed swings */
    int finished;       /**< fnav_stance_finish() was called */
} fnav_stance_t;

/** fnav_stance_init() with the caller's FNAV_BUILD_TAG, sizeof(fnav_stance_t) and sizeof(fnav_stance_config_t)
 *  (call fnav_stance_init(), which passes them): FNAV_E_BUILD, *st not written, when one is not
 *  the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_stance_init_tagged(fnav_stance_t *st, const fnav_stance_config_t *cfg,
                                                       uint64_t build_tag, size_t obj_size, size_t cfg_size);

/**
 * Initialise a detector.
 * @return FNAV_OK, FNAV_E_ARG on NULL, FNAV_E_CONFIG on a bad config
 *         (non-positive or non-finite weights, window, threshold; negative rate;
 *         a noise weight sigma_a_mps2, sigma_g_rps or a threshold
 *         gyro_thresh_rps, accel_thresh_mps2 whose square is 0 or not
 *         finite: in float32 below about 2.6e-23 or above 1.8e19).
 *         FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *         than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *         them): nothing written.
 */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_stance_init(fnav_stance_t *st, const fnav_stance_config_t *cfg)
{
    return fnav_stance_init_tagged(st, cfg, FNAV_BUILD_TAG, sizeof(fnav_stance_t), sizeof(fnav_stance_config_t));
}

/**
 * Store one sample. The caller checks it first (finite values, time not going
 * backwards but at a new timeline, such as fnav_nav_push accepts after
 * FNAV_NAV_TIME_RESYNC samples behind: the gait-event search does not look
 * back across that step); the sample is copied.
 * @return FNAV_OK; FNAV_E_ARG on NULL; FNAV_E_STATE after fnav_stance_finish()
 *         or when the caller did not pop the due decisions: the ring is
 *         full, or the sample would overwrite the start of the window of a
 *         decision not yet made (a window longer than the look-ahead); pop
 *         until FNAV_AGAIN and push it again (nothing was stored); also
 *         FNAV_E_STATE, taking nothing, for a detector never initialised
 *         (zeroed, as static storage is, or whose only init failed).
 */
FNAV_WARN_UNUSED fnav_status_t fnav_stance_push(fnav_stance_t *st, const fnav_sample_t *sample);

/**
 * Next due decision.
 * @param st   detector
 * @param out  decision for the oldest undecided sample (valid with FNAV_OK)
 * @return FNAV_OK with *out; FNAV_AGAIN when no decision is due yet (the
 *         window still fills, or the rate is being estimated); after
 *         fnav_stance_finish(), FNAV_END once every sample was returned;
 *         FNAV_E_STATE for a detector never initialised; FNAV_E_ARG on NULL.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_stance_pop(fnav_stance_t *st, fnav_stance_out_t *out);

/** Mark the end of the input: the samples still held back become due and
 *  are decided on the part of their window that exists. */
void fnav_stance_finish(fnav_stance_t *st);

/** Samples the detector currently holds back (its delay), samples. */
long fnav_stance_pending(const fnav_stance_t *st);

#define FNAV_STANCE_CUT_WINDOW 0x1u   /**< the window is shorter than window_s */
#define FNAV_STANCE_CUT_MIN_ZUPT 0x2u /**< the shortest ZUPT run is shorter than min_zupt_s */
#define FNAV_STANCE_CUT_ZUPT_CYCLE 0x4u /**< the cycle-scaled run is capped below what
                                             min_zupt_cycle asks for at FNAV_STANCE_CYCLE_LAG_S */

/** Which configured durations the ring (FNAV_STANCE_MAX_WINDOW samples) cut
 *  at the rate in use (high rates: the comment at the top): FNAV_STANCE_CUT_*
 *  bits, 0 while the rate is not known. */
unsigned fnav_stance_cut(const fnav_stance_t *st);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_STANCE_H */
