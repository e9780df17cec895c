/**
 * @file fnav_cm_ring.h
 * @brief Lock-free single-producer / single-consumer sample ring for the
 *        Cortex-M port: the sample-ready interrupt pushes, the main loop pops.
 *        Portable C (testable on the host); indices are free-running uint32.
 */
#ifndef FNAV_CM_RING_H
#define FNAV_CM_RING_H

#include "footnav/fnav_types.h"

/** Ring capacity in samples; a power of two. 32 samples are 160 ms at 200 Hz. */
#ifndef FNAV_CM_RING_SIZE
#define FNAV_CM_RING_SIZE 32u
#endif

#if (FNAV_CM_RING_SIZE & (FNAV_CM_RING_SIZE - 1u)) != 0u
#error "FNAV_CM_RING_SIZE must be a power of two"
#endif

/** Lock-free SPSC ring: the ISR only writes head, the main loop only tail. */
typedef struct {
    fnav_sample_t slot[FNAV_CM_RING_SIZE];
    volatile uint32_t head;      /**< written by the producer (ISR) */
    volatile uint32_t tail;      /**< written by the consumer (main loop) */
    volatile uint32_t overruns;  /**< samples dropped because the ring was full */
} fnav_cm_ring_t;

/** Empty the ring (not concurrently with push/pop). */
void fnav_cm_ring_init(fnav_cm_ring_t *ring);
/** Producer side; call from the sample-ready interrupt. Returns 0, or -1
 *  (counted in overruns) when the ring is full. ISR-safe. */
int fnav_cm_ring_push(fnav_cm_ring_t *ring, const fnav_sample_t *s);
/** Consumer side; 1 with *s filled, 0 when empty. Main loop only. */
int fnav_cm_ring_pop(fnav_cm_ring_t *ring, fnav_sample_t *s);

#endif /* FNAV_CM_RING_H */
