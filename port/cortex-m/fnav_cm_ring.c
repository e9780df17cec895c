/* Lock-free SPSC sample ring (see fnav_cm_ring.h). */
#include "fnav_cm_ring.h"

/* Data memory barrier: orders the slot write before the index update. On
 * the host it is a compiler barrier only: right for the host tests, where
 * push and pop run in one thread, not for a producer and a consumer on two
 * threads of a weakly ordered CPU (AArch64), which would need a fence. */
#if defined(__arm__)
#define FNAV_CM_DMB() __asm volatile("dmb" ::: "memory")
#else
#define FNAV_CM_DMB() __asm__ volatile("" ::: "memory")
#endif

int fnav_cm_ring_push(fnav_cm_ring_t *ring, const fnav_sample_t *s)
{
    uint32_t head = ring->head;
    if (head - ring->tail >= FNAV_CM_RING_SIZE) {
        ring->overruns++;
        return -1;
    }
    ring->slot[head & (FNAV_CM_RING_SIZE - 1u)] = *s;
    FNAV_CM_DMB();
    ring->head = head + 1u;
    return 0;
}

int fnav_cm_ring_pop(fnav_cm_ring_t *ring, fnav_sample_t *s)
{
    uint32_t tail = ring->tail;
    if (ring->head == tail) {
        return 0;
    }
    FNAV_CM_DMB();
    *s = ring->slot[tail & (FNAV_CM_RING_SIZE - 1u)];
    FNAV_CM_DMB();
    ring->tail = tail + 1u;
    return 1;
}

void fnav_cm_ring_init(fnav_cm_ring_t *ring)
{
    ring->head = 0u;
    ring->tail = 0u;
    ring->overruns = 0u;
}
