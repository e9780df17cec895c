/**
 * @file fnav_config.h
 * @brief Every compile-time option of footnav, with its default.
 *
 * Replace this whole file with your own by compiling with
 * `-DFNAV_CONFIG_FILE='"my_config.h"'` (Mbed TLS style), or override single
 * options with `-DOPTION=value`. Incoherent option sets are rejected by
 * fnav_config_check.h with an `#error`.
 */
#ifndef FNAV_CONFIG_H
#define FNAV_CONFIG_H

#if defined(FNAV_CONFIG_FILE)
#include FNAV_CONFIG_FILE
#endif

/** 1: fnav_real_t is double; 0 (default): float. The one switch between
 *  the float32 firmware build and the double reference build. */
#ifndef FNAV_USE_DOUBLE
#define FNAV_USE_DOUBLE 0
#endif

/** 1 (default): FNAV_ASSERT checks programmer errors and calls
 *  fnav_port_assert_failed(); 0 compiles every assertion out. */
#ifndef FNAV_ENABLE_ASSERT
#define FNAV_ENABLE_ASSERT 1
#endif

/** Largest stance-detector window in samples (SHOE/GLRT). 64 samples are
 *  about 80 ms at 820 Hz; the window adapts to the rate below this cap. */
#ifndef FNAV_STANCE_MAX_WINDOW
#define FNAV_STANCE_MAX_WINDOW 64
#endif

/** Jerk history of the stance detector's foot-strike search, samples. The
 *  search runs when a stance is confirmed, min_stance_s after it began, and
 *  covers what the history still holds before the stance: min(event_window_s,
 *  this many samples less the min_stance_s ones), i.e. the full 0.3 s up to
 *  457 Hz with the default 0.05 s (fnav_stance.h); beyond, a shorter window.
 *  8.5 bytes per sample (13 in the double build). */
#ifndef FNAV_STANCE_EVENT_BUF
#define FNAV_STANCE_EVENT_BUF 160
#endif

/** Octaves of averaging time covered by the streaming Allan estimator:
 *  tau = 2^0 .. 2^(N-1) samples. 21 reaches 2^20 = 1,048,576 samples, more
 *  than 10 % of a 12-hour log at 200 Hz (864,000 samples). Each octave above
 *  the full-rate ring costs one cascade level of 2 * 2^LAG_LOG2 + 1 reals
 *  (docs/allan.md). */
#ifndef FNAV_ALLAN_MAX_LEVELS
#define FNAV_ALLAN_MAX_LEVELS 21
#endif

/** log2 of the full-rate phase ring of the Allan estimator. Every averaging
 *  time tau <= 2^(N-1) - 1 samples is estimated fully overlapping (exactly
 *  as Stable32 / NIST SP 1065); 9 (512 reals) covers tau <= 255 samples. */
#ifndef FNAV_ALLAN_RING0_LOG2
#define FNAV_ALLAN_RING0_LOG2 9
#endif

/** log2 of the largest lag kept by each cascade level of the Allan
 *  estimator: level j stores 2 * 2^N + 1 phase values 2^j samples apart and
 *  serves tau = m * 2^j for m <= 2^N (overlap stride tau / m). */
#ifndef FNAV_ALLAN_CASCADE_LAG_LOG2
#define FNAV_ALLAN_CASCADE_LAG_LOG2 3
#endif

/** Largest number of averaging times (tau points) one Allan estimator
 *  tracks; each costs 4 reals + 6 bytes. The default grid (two points per
 *  octave up to 2^20) uses 40. */
#ifndef FNAV_ALLAN_MAX_POINTS
#define FNAV_ALLAN_MAX_POINTS 40
#endif

/** Largest Welch segment (FFT) length; a power of two. It sizes
 *  fnav_welch_t at about 5 * N reals: 4096 (the host default: the
 *  harness's segment-length study, and segments as long as common reference
 *  spectra use, e.g. scipy's nperseg 4096) costs 82 KB per channel in float;
 *  a sensor that only runs the paper's 64-sample segments sets 64 (1.4 KB
 *  per channel; port/cortex-m/fnav_cm_fw_config.h). */
#ifndef FNAV_WELCH_MAX_NFFT
#define FNAV_WELCH_MAX_NFFT 4096
#endif

/** Number of AR(1) poles (log-spaced correlation times) whose sum makes
 *  the 1/f "flicker" bias of the error model (fnav_imuerr.h). 12 poles over
 *  four decades keep the Allan floor within a few per cent of 0.664 B. */
#ifndef FNAV_IMUERR_FLICKER_POLES
#define FNAV_IMUERR_FLICKER_POLES 12
#endif

/** Consecutive samples stamped before the last accepted one after which the
 *  navigator takes the timeline as restarted (fnav_nav_push): the first
 *  FNAV_NAV_TIME_RESYNC - 1 are rejected (FNAV_E_TIME), the next is
 *  accepted and the interval back to it is a time jump. Without it one
 *  corrupted stamp far ahead made every later sample "backwards" for the
 *  rest of the run. 16: 80 ms at 200 Hz, far longer than a glitch. */
#ifndef FNAV_NAV_TIME_RESYNC
#define FNAV_NAV_TIME_RESYNC 16
#endif

/** Largest sample magnitude the streaming Allan and Welch estimators accept
 *  (beyond it a push returns FNAV_E_RANGE and the sample is ignored). 1e6
 *  covers every inertial sensor in SI units with room to spare, and keeps
 *  sums of squared differences over 2^32 samples finite in float32. */
#ifndef FNAV_INPUT_MAX_ABS
#define FNAV_INPUT_MAX_ABS 1.0e6
#endif

/** Largest rate and specific force the navigator integrates, per axis:
 *  beyond the widest MEMS ranges (gyros +-4000 deg/s = 69.8 rad/s,
 *  accelerometers +-400 g = 3923 m/s^2) with their scale tolerance, so a
 *  sample past them is a glitch of the sensor or its link, not motion. One
 *  gyro sample of 300 rad/s at 200 Hz turned the heading by 86 deg without
 *  a word (a 60 s simulated walk; tests/test_nav_robust.c,
 *  test_implausible_rate). fnav_nav_push rejects it (FNAV_E_RANGE,
 *  counted in stats.range_inputs, FNAV_HEALTH_RANGE); fnav_sample_check
 *  does not, so a recorder still keeps it. Raise them for a sensor beyond
 *  these ranges. */
#ifndef FNAV_NAV_GYRO_MAX_RPS
#define FNAV_NAV_GYRO_MAX_RPS 75.0
#endif
#ifndef FNAV_NAV_ACCEL_MAX_MPS2
#define FNAV_NAV_ACCEL_MAX_MPS2 4000.0
#endif

#include "fnav_config_check.h"

#endif /* FNAV_CONFIG_H */
