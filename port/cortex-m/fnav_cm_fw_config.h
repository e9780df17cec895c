/**
 * @file fnav_cm_fw_config.h
 * @brief Library options of the firmware images (`make firmware`,
 *        `make firmware-bench`), passed as FNAV_CONFIG_FILE so that the core
 *        and the port see the same sizes. Everything not set here keeps its
 *        default from fnav_config.h. The harness keeps the defaults (it has
 *        the memory); docs/firmware.md gives the RAM of each choice.
 */
#ifndef FNAV_CM_FW_CONFIG_H
#define FNAV_CM_FW_CONFIG_H

/* Allan (one estimator per channel; FNAV_CM_ALLAN_CHANNELS of them):
 * a full-rate ring of 32 phase values (every tau <= 15 samples fully
 * overlapping, exactly as Stable32), cascade levels with lags up to 4 beyond
 * (overlap stride tau / 4 instead of 1: somewhat wider confidence intervals
 * than the harness's stride tau / 8), one point per octave up to 2^20
 * samples (more than 10 % of a 12-hour record at 200 Hz). 1,396 bytes per
 * channel in float32 instead of the harness's 3,948. */
#define FNAV_ALLAN_RING0_LOG2 5
#define FNAV_ALLAN_CASCADE_LAG_LOG2 2
#define FNAV_ALLAN_MAX_POINTS 21

/* Welch: the paper's 64-sample Hamming segments are all the sensor runs
 * (the harness keeps the default 4096 for its segment-length study): 1,404
 * bytes per channel in float32 instead of 82 KB (docs/firmware.md). */
#define FNAV_WELCH_MAX_NFFT 64

/* Stance detector: windows up to 24 samples, the default 25 ms window up
 * to 960 Hz (the paper's lowest usable rates are 200-350 Hz). The ring also
 * holds the look-ahead of min_zupt_s (half window + min_zupt_s * rate + 1
 * samples must fit): above about 730 Hz the detector shortens min_zupt_s to
 * what fits (fnav_stance.c set_rate). The default cycle-scaled run
 * (min_zupt_cycle 0.025; 0 is off) asks at 400 Hz
 * for runs of up to 30 samples (look-ahead 29): the ring caps the look-ahead
 * at 17, runs of 18 samples, 45 ms, reached for cycles over 1.8 s, and the
 * navigator's latency is h + L = 22 samples, 55 ms (12, 30 ms, with
 * min_zupt_cycle 0; docs/firmware.md). */
#define FNAV_STANCE_MAX_WINDOW 24

/* Foot-strike search history: 128 samples hold the default 0.3 s event
 * window and min_stance_s (0.05 s) up to 366 Hz, 270 ms of it at the
 * image's 400 Hz (docs/firmware.md); 8.5 bytes per sample, 272 bytes less
 * than the default 160 (which the navigation's alignment and detector state needed). */
#define FNAV_STANCE_EVENT_BUF 128

/* Sample ring between the interrupt and the main loop: 16 samples, 40 ms at
 * 400 Hz, far above the main loop's worst case per sample. */
#define FNAV_CM_RING_SIZE 16u

#endif /* FNAV_CM_FW_CONFIG_H */
