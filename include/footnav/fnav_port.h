/**
 * @file fnav_port.h
 * @brief The port layer: everything that touches hardware or the OS.
 *
 * Data flows one way: a port's sample source feeds the core estimators,
 * whose results go to the port's output sink. The core itself never calls
 * an OS or libc I/O function; it only calls through an fnav_port_t (a
 * struct of function pointers plus a context pointer) and, for programmer
 * errors, the link-time hook fnav_port_assert_failed().
 *
 * Implementations: port/linux/ (file replay, stdout/CSV sink, CLOCK_MONOTONIC)
 * and port/cortex-m/ (interrupt-fed ring buffer, SysTick clock, frame sink).
 */
#ifndef FNAV_PORT_H
#define FNAV_PORT_H

#include "fnav_types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Severity of a log message. */
typedef enum {
    FNAV_LOG_DEBUG = 0,
    FNAV_LOG_INFO = 1,
    FNAV_LOG_WARN = 2,
    FNAV_LOG_ERROR = 3
} fnav_log_level_t;

/** fnav_nav_frame_t.flags: the stance detector reports the foot at rest. */
#define FNAV_FRAME_STANCE 0x1u
/** fnav_nav_frame_t.flags: a zero-velocity update was applied this step. */
#define FNAV_FRAME_ZUPT 0x2u
/** fnav_nav_frame_t.flags: the filter is aligned and navigating. */
#define FNAV_FRAME_ALIGNED 0x4u

/** One navigation output, as written to a port's sink. Navigation frame n
 *  is local-level, x along the initial heading, z down (docs/frames.md).
 *  Without FNAV_FRAME_ALIGNED (before the alignment, or re-aligning after a
 *  divergence reset) there is no estimate: every real field is 0, except
 *  after a reset the held position, its variance, the yaw and its variance
 *  (fnav_nav_reset in fnav_nav.h). */
typedef struct {
    int64_t t_ns;                    /**< time of the sample this output follows, ns */
    uint32_t seq;                    /**< sequence number of that sample */
    uint32_t flags;                  /**< FNAV_FRAME_* bits */
    uint32_t health;                 /**< health bits of the filter (fnav_nav.h) */
    fnav_real_t pos_m[3];            /**< position in n, m */
    fnav_real_t vel_mps[3];          /**< velocity in n, m/s */
    fnav_real_t euler_rad[3];        /**< roll, pitch, yaw (ZYX), rad */
    fnav_real_t gyro_bias_rps[3];    /**< gyroscope bias estimate, rad/s */
    fnav_real_t accel_bias_mps2[3];  /**< accelerometer bias estimate, m/s^2 */
    fnav_real_t p_diag[15];          /**< covariance diagonal, the output order of fnav_ukf.h: attitude
                                          error about n's x, y, z (rad^2), velocity ((m/s)^2), position
                                          (m^2), gyro bias ((rad/s)^2), accel bias ((m/s^2)^2) */
    fnav_real_t lever_m[3];          /**< estimated pivot-to-IMU lever in b, m (0 when not estimated) */
} fnav_nav_frame_t;

/** A port: callbacks plus the context pointer passed to each of them.
 *  Any callback may be NULL when the port has no such facility. The core
 *  calls them only from inside fnav_nav_run (and the fnav_port_* helpers),
 *  in the caller's thread, one at a time: none needs to be reentrant, and
 *  any may block (fnav_nav_run has no timeout). A sample or frame passed to a callback is the caller's
 *  and valid only during the call. docs/firmware.md, "The callbacks'
 *  contract", "Time stamps from a board". */
typedef struct {
    void *ctx; /**< passed unchanged to every callback */

    /** Sample source: fills every field of *sample (t_ns in ns, never going
     *  back: a board's wrapping counter or one stamp per FIFO batch must be
     *  converted first, port/cortex-m/fnav_cm_time.h). Returns FNAV_OK with *sample filled, FNAV_END when the
     *  source is exhausted, FNAV_AGAIN when no sample is ready yet
     *  (non-blocking sources), or a negative status on an error. */
    fnav_status_t (*read_sample)(void *ctx, fnav_sample_t *sample);

    /** Monotonic clock, ns, for the application (fnav_port_now_ns; the
     *  reference firmware's STATUS uptime), never for the samples' own
     *  time (that comes with each sample). The core itself does not call
     *  it: it has no timeouts. */
    int64_t (*now_ns)(void *ctx);

    /** Output sink for navigation frames. */
    fnav_status_t (*write_nav)(void *ctx, const fnav_nav_frame_t *frame);

    /** Log hook for the application (fnav_port_log): one line of text
     *  without a trailing newline. The core itself logs nothing: its
     *  outcomes are status codes and counters. */
    void (*log)(void *ctx, fnav_log_level_t level, const char *msg);
} fnav_port_t;

/** Link-time assert hook: every port provides exactly one definition
 *  (port/linux prints and aborts; port/cortex-m breaks into the debugger
 *  and halts). Called only for programmer errors, never for bad data.
 *  Declared FNAV_NORETURN: it must not return. The code after an
 *  FNAV_ASSERT relies on the condition (e.g. dereferences the pointer it
 *  checked) and the compiler may leave out any code for a return; a
 *  definition that can return does not compile with -Werror under GCC or
 *  clang, and one that returns anyway is undefined behaviour. End the
 *  program (abort, exit), reset the part, spin, or longjmp out; never
 *  record and return. A test harness's mock_assert longjmps but is not
 *  declared noreturn, so a hook calling it ends in a call the compiler
 *  knows does not return: mock_assert(0, expr, file, line); abort();
 *  (not reached).
 *  docs/firmware.md, "The callbacks' contract". */
FNAV_NORETURN void fnav_port_assert_failed(const char *file, int line, const char *expr);

#if FNAV_ENABLE_ASSERT
/** Programmer-error check; compiled out with FNAV_ENABLE_ASSERT=0. */
#define FNAV_ASSERT(cond) \
    ((cond) ? (void)0 : fnav_port_assert_failed(__FILE__, __LINE__, #cond))
#else
#define FNAV_ASSERT(cond) ((void)0)
#endif

/** Read one sample through a port (FNAV_E_UNSUPPORTED without a source,
 *  FNAV_E_ARG for a NULL port or sample). */
FNAV_WARN_UNUSED fnav_status_t fnav_port_read(const fnav_port_t *port, fnav_sample_t *sample);

/** Write one navigation frame through a port (FNAV_OK without a sink,
 *  FNAV_E_ARG for a NULL port or frame). */
FNAV_WARN_UNUSED fnav_status_t fnav_port_write_nav(const fnav_port_t *port, const fnav_nav_frame_t *frame);

/** Log one message through a port (does nothing without a log hook). */
void fnav_port_log(const fnav_port_t *port, fnav_log_level_t level, const char *msg);

/** Monotonic time through a port (0 without a clock). */
int64_t fnav_port_now_ns(const fnav_port_t *port);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_PORT_H */
