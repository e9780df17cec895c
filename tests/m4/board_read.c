/* A board's fnav_cm_imu_read as tests/m4/stack.sh links it into the
 * reference image (make firmware FW_BOARD_SRC=tests/m4/board_read.c): an SPI
 * burst of FNAV_TEST_READ_BYTES bytes into a local buffer, scaled to SI in
 * float (the firmware audit's board read, without its timer state: 56 bytes
 * of stack at 14 bytes). No hardware behind the registers: built, never run. */
#include "fnav_port_cortexm.h"

#ifndef FNAV_TEST_READ_BYTES
#define FNAV_TEST_READ_BYTES 14
#endif

#define SPI_DR (*(volatile uint32_t *)0x4001300Cu)
#define TIM_CNT (*(volatile uint32_t *)0x40000024u)

static void spi_burst(uint8_t *b, unsigned n)
{
    unsigned i;
    for (i = 0; i < n; i++) {
        SPI_DR = 0u;
        b[i] = (uint8_t)SPI_DR;
    }
}

int fnav_cm_imu_read(fnav_sample_t *s)
{
    uint8_t raw[FNAV_TEST_READ_BYTES];
    int16_t v[FNAV_TEST_READ_BYTES / 2];
    int i;
    spi_burst(raw, sizeof raw);
    for (i = 0; i < FNAV_TEST_READ_BYTES / 2; i++) {
        v[i] = (int16_t)((raw[2 * i] << 8) | raw[2 * i + 1]);
    }
    s->t_ns = (int64_t)TIM_CNT * 1000;
    s->seq++;
    s->flags = FNAV_SAMPLE_HAS_TEMP;
    for (i = 0; i < 3; i++) {
        s->accel_mps2[i] = (float)v[i] * (9.80665f / 2048.0f);
        s->gyro_rps[i] = (float)v[4 + i] * 1.0652e-3f;
    }
    s->temp_c = (float)v[3] / 340.0f + 36.53f;
    for (i = 7; i < FNAV_TEST_READ_BYTES / 2; i++) {
        s->temp_c += (float)v[i]; /* the longer burst's words used: its buffer stays */
    }
    return 0;
}
