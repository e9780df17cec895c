/**
 * @file footnav.h
 * @brief Umbrella header of footnav, the foot-mounted IMU navigation library.
 */
#ifndef FOOTNAV_H
#define FOOTNAV_H

#ifdef __cplusplus
extern "C" {
#endif

#include "fnav_version.h"
#include "fnav_config.h"
#include "fnav_types.h"
#include "fnav_math.h"
#include "fnav_port.h"
#include "fnav_profile.h"
#include "fnav_wire.h"
#include "fnav_imuerr.h"
#include "fnav_allan.h"
#include "fnav_fft.h"
#include "fnav_welch.h"
#include "fnav_strapdown.h"
#include "fnav_stance.h"
#include "fnav_align.h"
#include "fnav_ukf.h"
#include "fnav_nav.h"

#ifdef __cplusplus
}
#endif

#endif /* FOOTNAV_H */
