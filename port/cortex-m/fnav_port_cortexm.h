/**
 * @file fnav_port_cortexm.h
 * @brief Cortex-M4F port skeleton: a sample-ready interrupt pushes samples
 *        into a lock-free single-producer / single-consumer ring buffer that
 *        the main loop drains through fnav_port_t.read_sample.
 *
 * Hardware specifics are weak functions with default stubs, so the port
 * links for a generic Cortex-M4F; a board overrides them:
 *   - fnav_cm_imu_read(): read one sample from the IMU (e.g. over SPI),
 *   - fnav_cm_ticks_ns(): a monotonic time base (default: SysTick counter),
 *   - fnav_cm_out_write(): send bytes of an output frame (e.g. UART DMA).
 */
#ifndef FNAV_PORT_CORTEXM_H
#define FNAV_PORT_CORTEXM_H

#include "footnav/fnav_port.h"
#include "fnav_cm_ring.h"

/** Port context. */
typedef struct {
    fnav_cm_ring_t ring;
    uint32_t frames;             /**< frames sent to the sink */
} fnav_cm_port_ctx_t;

void fnav_cm_port_init(fnav_port_t *port, fnav_cm_port_ctx_t *ctx);

/** Sample-ready interrupt body: reads the IMU and pushes the sample. */
void fnav_cm_sample_isr(fnav_cm_port_ctx_t *ctx);

/* Weak hardware hooks (override in the board support code). */
int fnav_cm_imu_read(fnav_sample_t *s);
int64_t fnav_cm_ticks_ns(void);
int fnav_cm_out_write(const void *bytes, uint32_t n);

#endif /* FNAV_PORT_CORTEXM_H */
