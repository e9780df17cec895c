/**
 * @file fnav_config_check.h
 * @brief Rejects incoherent option sets at compile time (included at the
 *        end of fnav_config.h; included on its own, it includes
 *        fnav_config.h first, which defines the options it checks).
 */
#ifndef FNAV_CONFIG_CHECK_H
#define FNAV_CONFIG_CHECK_H

#include "fnav_config.h"

#if (FNAV_USE_DOUBLE != 0) && (FNAV_USE_DOUBLE != 1)
#error "FNAV_USE_DOUBLE must be 0 or 1"
#endif

#if (FNAV_ENABLE_ASSERT != 0) && (FNAV_ENABLE_ASSERT != 1)
#error "FNAV_ENABLE_ASSERT must be 0 or 1"
#endif

#if (FNAV_STANCE_MAX_WINDOW < 3) || (FNAV_STANCE_MAX_WINDOW > 1024)
#error "FNAV_STANCE_MAX_WINDOW must be in 3..1024"
#endif

#if (FNAV_STANCE_EVENT_BUF < 8) || (FNAV_STANCE_EVENT_BUF > 4096) || (FNAV_STANCE_EVENT_BUF % 8 != 0)
#error "FNAV_STANCE_EVENT_BUF must be a multiple of 8 in 8..4096"
#endif

#if (FNAV_ALLAN_MAX_LEVELS < 2) || (FNAV_ALLAN_MAX_LEVELS > 31)
#error "FNAV_ALLAN_MAX_LEVELS must be in 2..31"
#endif

#if (FNAV_ALLAN_RING0_LOG2 < 3) || (FNAV_ALLAN_RING0_LOG2 > 15)
#error "FNAV_ALLAN_RING0_LOG2 must be in 3..15"
#endif

#if (FNAV_ALLAN_CASCADE_LAG_LOG2 < 0) || (FNAV_ALLAN_CASCADE_LAG_LOG2 > 6) || \
    (FNAV_ALLAN_CASCADE_LAG_LOG2 + 1 >= FNAV_ALLAN_RING0_LOG2)
#error "FNAV_ALLAN_CASCADE_LAG_LOG2 must be in 0..6 and below FNAV_ALLAN_RING0_LOG2 - 1"
#endif

#if (FNAV_ALLAN_MAX_POINTS < 1) || (FNAV_ALLAN_MAX_POINTS > 255)
#error "FNAV_ALLAN_MAX_POINTS must be in 1..255"
#endif

#if (FNAV_WELCH_MAX_NFFT < 8) || (FNAV_WELCH_MAX_NFFT > 65536) || \
    ((FNAV_WELCH_MAX_NFFT & (FNAV_WELCH_MAX_NFFT - 1)) != 0)
#error "FNAV_WELCH_MAX_NFFT must be a power of two in 8..65536"
#endif

#if (FNAV_IMUERR_FLICKER_POLES < 2) || (FNAV_IMUERR_FLICKER_POLES > 64)
#error "FNAV_IMUERR_FLICKER_POLES must be in 2..64"
#endif

#if (FNAV_NAV_TIME_RESYNC < 2) || (FNAV_NAV_TIME_RESYNC > 1000000)
#error "FNAV_NAV_TIME_RESYNC must be in 2..1000000 (1 would accept every stamp going backwards)"
#endif

/* FNAV_INPUT_MAX_ABS is a floating constant, which neither the preprocessor
 * nor a C99 constant expression can compare; keep it in (0, 1e12]
 * (fnav_config.h). */

#endif /* FNAV_CONFIG_CHECK_H */
