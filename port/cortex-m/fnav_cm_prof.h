/**
 * @file fnav_cm_prof.h
 * @brief Profiling marks of the reference firmware's main loop. With
 *        FNAV_CM_PROFILE=1 (the emulator benchmark image) each mark calls
 *        fnav_cm_prof_mark(), which the benchmark implements with the SysTick
 *        counter; otherwise the marks compile to nothing.
 */
#ifndef FNAV_CM_PROF_H
#define FNAV_CM_PROF_H

#include <stdint.h>

#include "fnav_cm_config.h"

/** What a pair of marks encloses. */
typedef enum {
    FNAV_CM_PROF_POP = 0,      /**< taking one sample out of the ring (port read) */
    FNAV_CM_PROF_NAV,          /**< fnav_cm_est_nav(): one navigation (UKF) step */
    FNAV_CM_PROF_ALLAN,        /**< fnav_cm_est_allan(): Allan push, all channels */
    FNAV_CM_PROF_WELCH,        /**< fnav_cm_est_welch(): Welch push, all channels */
    FNAV_CM_PROF_TX_NAV,       /**< encoding and handing out one NAV frame */
    FNAV_CM_PROF_TX_SAMPLE,    /**< encoding and handing out one SAMPLE frame */
    FNAV_CM_PROF_SAMPLE,       /**< everything the main loop does for one sample */
    FNAV_CM_PROF_COUNT
} fnav_cm_prof_id_t;

#if FNAV_CM_PROFILE
/** begin = 1 at the start of the enclosed code, 0 at its end. */
void fnav_cm_prof_mark(fnav_cm_prof_id_t id, int begin);
/** Classify the call measured last under id by what it did (e.g. the
 *  navigation step's output flags), so the benchmark can split its cost. */
void fnav_cm_prof_note(fnav_cm_prof_id_t id, uint32_t tag);
#define FNAV_CM_PROF_BEGIN(id) fnav_cm_prof_mark((id), 1)
#define FNAV_CM_PROF_END(id) fnav_cm_prof_mark((id), 0)
#define FNAV_CM_PROF_NOTE(id, tag) fnav_cm_prof_note((id), (tag))
#else
#define FNAV_CM_PROF_BEGIN(id) ((void)0)
#define FNAV_CM_PROF_END(id) ((void)0)
#define FNAV_CM_PROF_NOTE(id, tag) ((void)0)
#endif

/** Tags of FNAV_CM_PROF_NAV notes. */
#define FNAV_CM_PROF_TAG_NO_OUTPUT 0x10000u /**< no output (aligning, window filling, rejected) */

#endif /* FNAV_CM_PROF_H */
