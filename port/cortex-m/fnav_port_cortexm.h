/**
 * @file fnav_port_cortexm.h
 * @brief Cortex-M4F port: a sample-ready interrupt pushes samples into a
 *        lock-free single-producer / single-consumer ring buffer that the
 *        main loop drains through fnav_port_t.read_sample; navigation frames
 *        leave through fnav_port_t.write_nav as wire-protocol NAV frames
 *        (fnav_wire.h, docs/wire-protocol.md).
 *
 * Hardware specifics are weak functions with default stubs, so the port
 * links for a generic Cortex-M4F; a board overrides them with strong ones:
 *   - fnav_cm_board_init(): clocks, pins, IMU set-up, starting the time
 *     base (fnav_cm_systick_start(core_hz), unless the board has its own
 *     fnav_cm_ticks_ns()), enabling the sample-ready interrupt (default:
 *     nothing),
 *   - fnav_cm_imu_read(): read one sample from the IMU, e.g. over SPI
 *     (default: no IMU, returns -1),
 *   - fnav_cm_ticks_ns(): a monotonic time base (default: the SysTick time
 *     base of fnav_cm_systick_start(), 0 until it is started),
 *   - fnav_cm_out_write(): send the bytes of one frame, e.g. by UART DMA
 *     from a copy (the port reuses its buffer: see below)
 *     (default: discard),
 *   - fnav_cm_idle(): wait for the next interrupt (default: WFI).
 * The code is portable C apart from the ARM-only parts guarded by
 * __arm__, so the host tests exercise it too.
 */
#ifndef FNAV_PORT_CORTEXM_H
#define FNAV_PORT_CORTEXM_H

#include "footnav/fnav_port.h"
#include "footnav/fnav_wire.h"
#include "fnav_cm_config.h"
#include "fnav_cm_ring.h"

/** Largest frame the port sends (INFO). */
#define FNAV_CM_TX_SIZE FNAV_WIRE_FRAME_SIZE(FNAV_WIRE_INFO_LEN)

/** Port context (caller-owned; 1,664 bytes on a Cortex-M4F with the default 32-sample ring, 896 with the firmware's 16). */
typedef struct {
    fnav_cm_ring_t ring;         /**< samples from the ISR to the main loop */
    uint32_t frames;             /**< frames handed to fnav_cm_out_write() */
    uint32_t tx_dropped;         /**< frames the output refused (link busy) */
    uint16_t tx_seq;             /**< wire frame counter */
    uint8_t tx[FNAV_CM_TX_SIZE]; /**< frame being sent */
} fnav_cm_port_ctx_t;

/** Set up @p port over @p ctx (empties the ring, zeroes the counters). */
void fnav_cm_port_init(fnav_port_t *port, fnav_cm_port_ctx_t *ctx);

/** Sample-ready interrupt body: reads the IMU once (fnav_cm_imu_read) and
 *  pushes that one sample (a full ring counts an overrun). ISR only. An IMU
 *  that interrupts once per FIFO batch needs one call per sample of the
 *  batch, or fnav_cm_sample_isr_fifo below: docs/firmware.md, "FIFO
 *  batches and the ring". */
void fnav_cm_sample_isr(fnav_cm_port_ctx_t *ctx);

/** FIFO-watermark interrupt body: calls fnav_cm_imu_read until it returns
 *  -1 (the IMU's FIFO is empty) or @p max samples were read, and pushes each
 *  (a full ring counts each sample past it as an overrun; the ring keeps
 *  what it holds). @return the number of samples read. ISR only. @p max
 *  bounds the time spent in the interrupt: the watermark, or
 *  FNAV_CM_RING_SIZE. Stamps: fnav_cm_batch_stamp (fnav_cm_time.h).
 *  Nothing of it is in an image that does not call it (the reference image
 *  calls fnav_cm_sample_isr). */
uint32_t fnav_cm_sample_isr_fifo(fnav_cm_port_ctx_t *ctx, uint32_t max);

/** The main loop's sleep, after fnav_cm_app_poll() found the ring empty:
 *  calls fnav_cm_idle() unless a sample is waiting, and on ARM checks the
 *  ring with interrupts masked (CPSID i ... CPSIE i, ISB), so that a sample
 *  pushed after the loop's last pop cannot be left in the ring while the
 *  core sleeps until the next interrupt. fnav_cm_idle() is then called with
 *  PRIMASK set: WFI wakes on an interrupt made pending under it (ARMv7-M
 *  ARM B1.5.19), which runs once the mask is cleared here. Main loop only. */
void fnav_cm_port_wait(fnav_cm_port_ctx_t *ctx);

/** Send a SAMPLE frame (raw stream). Main loop only. @return FNAV_OK or FNAV_E_IO. */
fnav_status_t fnav_cm_port_send_sample(fnav_cm_port_ctx_t *ctx, const fnav_sample_t *s);
/** Send a STATUS frame. Main loop only. */
fnav_status_t fnav_cm_port_send_status(fnav_cm_port_ctx_t *ctx, const fnav_wire_status_t *st);
/** Send an INFO frame. Main loop only. */
fnav_status_t fnav_cm_port_send_info(fnav_cm_port_ctx_t *ctx, const fnav_wire_info_t *info);

/** Start a SysTick time base: an interrupt every floor(@p core_hz / 1000)
 *  core clocks, about 1 ms (ARM only; does nothing on the host). The port
 *  defines SysTick_Handler; a board that needs SysTick for itself builds
 *  the port with -DFNAV_CM_OWN_SYSTICK, keeps this reload (an RTOS that
 *  reprograms SYST_RVR gets wrong stamps) and calls fnav_cm_systick_tick()
 *  from its own handler at each SysTick interrupt. SysTick's priority must
 *  be at least that of every interrupt that reads the time (a reader above
 *  it can preempt the handler mid-update). The stamps count core clocks,
 *  so they are exact over any run at any clock (a period is not taken for
 *  1 ms: fnav_cm_time.h). fnav_cm_ticks_ns() is right in any context of
 *  SysTick's priority or below, the sample-ready interrupt included (a wrap whose interrupt is still pending
 *  is counted), and its 64-bit ns do not wrap. */
void fnav_cm_systick_start(uint32_t core_hz);
/** One SysTick period more on the time base (called by SysTick_Handler). */
void fnav_cm_systick_tick(void);

/* Weak hardware hooks (override in the board support code). */
/** Board set-up; called once by the reference main() before the loop.
 *  Starts the time base: the reference main() does not, as only the board
 *  knows the core clock (fnav_cm_ticks_ns() reads 0 until then). */
void fnav_cm_board_init(void);
/** Read one sample (fill every field, t_ns included: int64 ns, never going
 *  back; fnav_cm_time.h converts a wrapping timer or a FIFO batch's one
 *  stamp). 0 ok, -1 none. ISR context: must not block; acknowledges the
 *  sample-ready interrupt (its pending flag), or the handler runs again. Called once per
 *  sample-ready interrupt by fnav_cm_sample_isr, or until it returns -1 by
 *  fnav_cm_sample_isr_fifo. */
int fnav_cm_imu_read(fnav_sample_t *s);
/** Monotonic time, ns. */
int64_t fnav_cm_ticks_ns(void);
/** Send n bytes (one whole frame). 0 ok, -1 busy (the frame is dropped and
 *  counted). The bytes are in the port's single transmit buffer, which the
 *  next frame's encoding overwrites: the hook must copy them (into its DMA
 *  buffer or a FIFO) or finish sending before it returns. A DMA reading
 *  these bytes after the return would send a mix of two frames. */
int fnav_cm_out_write(const void *bytes, uint32_t n);
/** Sleep until the next interrupt. Called by fnav_cm_port_wait() with
 *  interrupts masked (PRIMASK): it must return once an interrupt is
 *  pending without waiting for its handler to run (WFI does; a wait on a
 *  flag the handler sets would never end). */
void fnav_cm_idle(void);

#endif /* FNAV_PORT_CORTEXM_H */
