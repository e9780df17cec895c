/**
 * @file fnav_cm_config.h
 * @brief Options of the Cortex-M reference firmware (port/cortex-m), with
 *        their defaults. Override with -DOPTION=value. Library options
 *        (window sizes, Allan levels, FFT length) are in fnav_config.h.
 */
#ifndef FNAV_CM_CONFIG_H
#define FNAV_CM_CONFIG_H

#include "footnav/fnav_config.h"

/** 1 (default): the main loop steps the navigation filter (fnav_nav.h:
 *  stance detection, strapdown, UKF with zero-velocity updates) and emits
 *  NAV frames. */
#ifndef FNAV_CM_WITH_NAV
#define FNAV_CM_WITH_NAV 1
#endif

/** 1 (default): the main loop pushes samples into streaming Allan
 *  estimators (fnav_allan.h), one per channel. */
#ifndef FNAV_CM_WITH_ALLAN
#define FNAV_CM_WITH_ALLAN 1
#endif

/** 1 (default): the main loop pushes samples into streaming Welch
 *  estimators (fnav_welch.h), one per channel. */
#ifndef FNAV_CM_WITH_WELCH
#define FNAV_CM_WITH_WELCH 1
#endif

/** Allan grid density: points per octave of tau (1, 2 or 4; at most
 *  FNAV_ALLAN_MAX_POINTS points in all, fnav_allan_grid()). */
#ifndef FNAV_CM_ALLAN_PER_OCTAVE
#define FNAV_CM_ALLAN_PER_OCTAVE 1u
#endif

/** Channels fed to the Allan estimators: the first N of
 *  (gyro x, y, z, accel x, y, z). */
#ifndef FNAV_CM_ALLAN_CHANNELS
#define FNAV_CM_ALLAN_CHANNELS 6
#endif

/** Channels fed to the Welch estimators: the first N of (accel x, y, z,
 *  gyro x, y, z); the accelerometers set the sampling-frequency answer in
 *  the paper (section II.C). */
#ifndef FNAV_CM_WELCH_CHANNELS
#define FNAV_CM_WELCH_CHANNELS 3
#endif

/** What every sample of the board's fnav_cm_imu_read() carries
 *  (FNAV_SAMPLE_HAS_TEMP 0x1, FNAV_SAMPLE_HAS_SEQ 0x2): the default of
 *  fnav_cm_app_config_t.sample_flags, which the INFO frame announces
 *  (the reference main() uses the default configuration). 0 (default):
 *  neither, as the stub IMU. */
#ifndef FNAV_CM_SAMPLE_FLAGS
#define FNAV_CM_SAMPLE_FLAGS 0u
#endif

/** Exception number offset of the sample-ready interrupt: the handler
 *  FNAV_CM_Sample_IRQHandler sits at external interrupt FNAV_CM_SAMPLE_IRQN
 *  of the vector table (e.g. the EXTI line of the IMU's data-ready pin). */
#ifndef FNAV_CM_SAMPLE_IRQN
#define FNAV_CM_SAMPLE_IRQN 0
#endif

/** External interrupts in the vector table: 32 for a generic Cortex-M4F
 *  part; a multiple of 32 up to 256 that covers every interrupt the board
 *  enables (an STM32F4's EXTI15_10 is 40, USART6 71: 96). */
#ifndef FNAV_CM_IRQ_COUNT
#define FNAV_CM_IRQ_COUNT 32
#endif

#if (FNAV_CM_SAMPLE_IRQN < 0) || (FNAV_CM_SAMPLE_IRQN >= FNAV_CM_IRQ_COUNT)
#error "FNAV_CM_SAMPLE_IRQN must be in 0..FNAV_CM_IRQ_COUNT-1"
#endif
#if (FNAV_CM_ALLAN_CHANNELS < 1) || (FNAV_CM_ALLAN_CHANNELS > 6)
#error "FNAV_CM_ALLAN_CHANNELS must be in 1..6"
#endif
#if (FNAV_CM_WELCH_CHANNELS < 1) || (FNAV_CM_WELCH_CHANNELS > 6)
#error "FNAV_CM_WELCH_CHANNELS must be in 1..6"
#endif

/** Profiling marks in the main loop (FNAV_CM_PROF); on only in the
 *  emulator benchmark image. */
#ifndef FNAV_CM_PROFILE
#define FNAV_CM_PROFILE 0
#endif

/** Functions measured by the benchmark are never inlined, cloned or
 *  analysed across their boundary, so the instructions counted between two
 *  marks belong to them alone. */
#if defined(__GNUC__) && !defined(__clang__) && (__GNUC__ >= 8)
#define FNAV_CM_NOIPA __attribute__((noipa))
#elif defined(__GNUC__)
#define FNAV_CM_NOIPA __attribute__((noinline))
#else
#define FNAV_CM_NOIPA
#endif

/** Weak definition (a board overrides it with a strong one). */
#if defined(__GNUC__)
#define FNAV_CM_WEAK __attribute__((weak))
#else
#define FNAV_CM_WEAK
#endif

#endif /* FNAV_CM_CONFIG_H */
