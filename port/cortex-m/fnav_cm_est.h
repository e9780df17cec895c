/**
 * @file fnav_cm_est.h
 * @brief The estimators the reference firmware runs on every sample, behind
 *        one small interface: the navigation filter (strapdown, stance
 *        detection, UKF with zero-velocity updates) and the streaming Allan
 *        and Welch estimators. Which ones are built is chosen by
 *        FNAV_CM_WITH_NAV / _ALLAN / _WELCH (fnav_cm_config.h); an estimator
 *        that is not built answers FNAV_E_UNSUPPORTED and costs nothing.
 *
 * Each call is a separate, never-inlined function (FNAV_CM_NOIPA) so that
 * the emulator benchmark can count the instructions of each on its own.
 */
#ifndef FNAV_CM_EST_H
#define FNAV_CM_EST_H

#include "footnav/fnav_port.h"
#include "fnav_cm_config.h"

#if FNAV_CM_WITH_NAV
#include "footnav/fnav_nav.h"
#endif
#if FNAV_CM_WITH_ALLAN
#include "footnav/fnav_allan.h"
#endif
#if FNAV_CM_WITH_WELCH
#include "footnav/fnav_welch.h"
#endif

/** The firmware's estimators (caller-owned; no other state). */
typedef struct {
#if FNAV_CM_WITH_NAV
    fnav_nav_t nav;                                /**< navigation filter */
#endif
#if FNAV_CM_WITH_ALLAN
    fnav_allan_t allan[FNAV_CM_ALLAN_CHANNELS];    /**< one per channel */
#endif
#if FNAV_CM_WITH_WELCH
    fnav_welch_t welch[FNAV_CM_WELCH_CHANNELS];    /**< one per channel */
#endif
    uint32_t samples;                              /**< samples seen */
} fnav_cm_est_t;

/** Initialise every built estimator.
 *  @param rate_hz      nominal sample rate, Hz (Welch frequency axis)
 *  @param nav_rate_hz  rate for the stance detector, Hz; 0: estimated from the first intervals
 *  @return FNAV_OK or the first failing init's status. */
FNAV_WARN_UNUSED fnav_status_t fnav_cm_est_init(fnav_cm_est_t *e, fnav_real_t rate_hz, fnav_real_t nav_rate_hz);

/** One navigation step: stance detection, strapdown prediction and, in
 *  stance, the zero-velocity update. Pushes the sample and pops the first
 *  frame it released. @return FNAV_OK with *out filled, FNAV_AGAIN when no
 *  frame is due yet (the detector's window filling, its rate being
 *  estimated), FNAV_E_UNSUPPORTED when not built, or the sample's rejection
 *  status (fnav_nav_push). */
fnav_status_t fnav_cm_est_nav(fnav_cm_est_t *e, const fnav_sample_t *s, fnav_nav_frame_t *out);

/** The next frame released by the same sample: one sample can release
 *  several (with the detector's rate estimated, the 33rd sample releases
 *  the frames due by then, fnav_nav_step). Call until it answers FNAV_AGAIN.
 *  @return FNAV_OK with *out filled, FNAV_AGAIN when none is left,
 *  FNAV_E_UNSUPPORTED when not built. */
fnav_status_t fnav_cm_est_nav_next(fnav_cm_est_t *e, fnav_nav_frame_t *out);

/** Push a sample into the Allan estimators. */
fnav_status_t fnav_cm_est_allan(fnav_cm_est_t *e, const fnav_sample_t *s);

/** Push a sample into the Welch estimators. */
fnav_status_t fnav_cm_est_welch(fnav_cm_est_t *e, const fnav_sample_t *s);

/** Which estimators are built: bit 0 nav, bit 1 Allan, bit 2 Welch. */
unsigned fnav_cm_est_built(void);

#endif /* FNAV_CM_EST_H */
