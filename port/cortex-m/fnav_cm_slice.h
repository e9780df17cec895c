/**
 * @file fnav_cm_slice.h
 * @brief A piece of a recorded walk compiled into the emulator benchmark
 *        image. The data source file is generated at build time from a log
 *        (tools/fw_slice.c, e.g. from vectors/walk.bin) into build/, never
 *        committed. Values are the log's float32 samples, exactly (C99
 *        hexadecimal floating constants).
 */
#ifndef FNAV_CM_SLICE_H
#define FNAV_CM_SLICE_H

#include <stdint.h>

/** One recorded sample. */
typedef struct {
    int64_t t_ns;     /**< sample time, ns */
    uint32_t seq;     /**< sample counter of the log */
    uint32_t flags;   /**< FNAV_SAMPLE_* bits */
    float acc[3];     /**< specific force, m/s^2 (sensor axes) */
    float gyr[3];     /**< angular rate, rad/s (sensor axes) */
} fnav_cm_slice_sample_t;

extern const fnav_cm_slice_sample_t fnav_cm_slice[];
/** Number of samples in fnav_cm_slice. */
extern const uint32_t fnav_cm_slice_n;
/** Nominal rate of the log, Hz (0 if unknown). */
extern const double fnav_cm_slice_rate_hz;
/** Where the slice came from (file, first sample, count). */
extern const char fnav_cm_slice_source[];

#endif /* FNAV_CM_SLICE_H */
