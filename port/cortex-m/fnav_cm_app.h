/**
 * @file fnav_cm_app.h
 * @brief The reference firmware application: the main loop's work, as one
 *        caller-owned object. The sample-ready interrupt pushes samples into
 *        the port's ring (fnav_cm_sample_isr); fnav_cm_app_poll() drains it
 *        through the port layer, steps the estimators (fnav_cm_est.h) and
 *        emits wire frames: NAV (decimated), optionally the raw SAMPLEs, and
 *        STATUS counters. Portable C: the host tests run it as is.
 */
#ifndef FNAV_CM_APP_H
#define FNAV_CM_APP_H

#include "fnav_cm_est.h"
#include "fnav_port_cortexm.h"

/** Application settings. */
typedef struct {
    fnav_real_t rate_hz;     /**< nominal IMU sample rate, Hz (default 400): INFO frame, Welch */
    fnav_real_t nav_rate_hz; /**< rate given to the navigation filter's stance detector: 0 (default)
                                  estimates it from the first intervals, as `harness replay` does for a
                                  log, so the sensor computes what a replay of its recording computes */
    uint32_t nav_every;      /**< send a NAV frame every N navigation outputs (0: none; default 4); the
                                  navigator has no output while it aligns, so the count starts at its
                                  first output, not at the first sample. A sent frame's event bits
                                  (FNAV_FRAME_ZUPT, FNAV_FRAME_STRIDE) tell the events of the outputs
                                  since the last frame the link took, its own included */
    uint32_t sample_every;   /**< send every N-th raw sample as a SAMPLE frame (0: none; default 0) */
    uint32_t status_every;   /**< send a STATUS frame every N samples (0: none; default 400) */
    const char *sensor;      /**< sensor name for the INFO frame (default "footnav-fw") */
    uint32_t sample_flags;   /**< what every sample of the board's fnav_cm_imu_read carries, for the INFO
                                  frame: FNAV_SAMPLE_HAS_TEMP (a temperature: INFO bit
                                  FNAV_WIRE_INFO_TEMP) and FNAV_SAMPLE_HAS_SEQ (the sensor's own sample
                                  counter: FNAV_WIRE_INFO_SEQ, sent only with sample_every 1). Default
                                  FNAV_CM_SAMPLE_FLAGS (fnav_cm_config.h), 0: neither, as the stub IMU.
                                  A receiver records what INFO says (`harness live` takes its recording's
                                  header from it): a clear TEMP bit discards every temperature, a set SEQ
                                  bit counts "drops" of a counter the board does not have. Other bits:
                                  FNAV_E_CONFIG */
} fnav_cm_app_config_t;

/** Defaults (above). */
extern const fnav_cm_app_config_t fnav_cm_app_config_default;

/** The application (caller-owned, usually one static object). */
typedef struct {
    fnav_cm_app_config_t cfg;   /**< settings */
    fnav_port_t port;           /**< the port layer over port_ctx */
    fnav_cm_port_ctx_t port_ctx;/**< ring buffer and frame output */
    fnav_cm_est_t est;          /**< the estimators */
    fnav_nav_frame_t frame;     /**< last navigation output (when sent, with the event bits of the outputs
                                     since the last frame the link took) */
    uint32_t samples;           /**< samples processed */
    uint32_t nav_outputs;       /**< navigation outputs produced */
    uint32_t events;            /**< event bits of the outputs not sent yet (nav_every) */
    uint32_t est_errors;        /**< estimator failures (data errors; the state stays usable) */
    fnav_status_t last_error;   /**< status of the last failure */
} fnav_cm_app_t;

/** Validate @p cfg and set up the port and the estimators.
 *  @return FNAV_OK, FNAV_E_CONFIG on a bad setting, or an estimator's status. */
FNAV_WARN_UNUSED fnav_status_t fnav_cm_app_init(fnav_cm_app_t *app, const fnav_cm_app_config_t *cfg);

/** Send the INFO frame that describes the stream (call once at start). */
fnav_status_t fnav_cm_app_announce(fnav_cm_app_t *app);

/** Process every sample waiting in the ring. Main loop only.
 *  @return number of samples processed */
uint32_t fnav_cm_app_poll(fnav_cm_app_t *app);

/** Process one sample (what fnav_cm_app_poll() does per sample). */
void fnav_cm_app_process(fnav_cm_app_t *app, const fnav_sample_t *s);

#endif /* FNAV_CM_APP_H */
