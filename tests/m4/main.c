/* Cortex-M4F cost of the navigation step, run in qemu-system-arm
 * (mps2-an386, -icount shift=0, semihosting; tests/m4/run.sh). QEMU does not
 * model the DWT cycle counter, but with icount the SysTick (processor clock,
 * 25 MHz) advances deterministically with executed instructions: the
 * calibration loop below gives the instructions per tick (40). Each UKF step
 * is timed on a copy of the filter taken just before the navigator's own
 * step, with the same sample, interval and stance decision. */
#include <stdint.h>
#include <string.h>

#include "footnav/fnav_nav.h"
#include "fnav_cm_semihost.h"
#include "m4_data.h"

/* semihosted output and the assert hook come from port/cortex-m */
#define sh_puts fnav_cm_sh_puts

/* Assert hook: report through semihosting and stop the emulator. */
void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)file;
    (void)line;
    fnav_cm_sh_puts(expr);
    fnav_cm_sh_puts(" ASSERT\n");
    fnav_cm_sh_exit(1);
}

#define SYST_CSR (*(volatile uint32_t *)0xE000E010)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018)

static fnav_nav_t nav;
static fnav_ukf_t u2;

static void putu(const char *label, unsigned long v)
{
    char b[96], t[24];
    int n = 0, i;
    do {
        t[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    for (i = 0; label[i]; i++) {
        b[i] = label[i];
    }
    while (n) {
        b[i++] = t[--n];
    }
    b[i++] = '\n';
    b[i] = 0;
    sh_puts(b);
}

static uint32_t ticks(uint32_t a, uint32_t b)
{
    return (a - b) & 0xFFFFFFu;
}

int main(void)
{
    fnav_nav_config_t c = fnav_nav_config_default;
    fnav_nav_frame_t fr;
    int k;
    uint32_t t0, t1, per_tick, calib;
    unsigned long up_sum = 0, up_n = 0, up_max = 0, uz_sum = 0, uz_n = 0, ust_max = 0, nav_max = 0;
    volatile int x = 0;
#ifdef M4_AR1
    c.bias_model = FNAV_BIAS_AR1; /* the default since the AR(1) model fits the budget */
#endif
#ifdef M4_BIASOFF
    c.bias_model = FNAV_BIAS_OFF;
#endif
#ifdef M4_NOLEVER
    c.lever = 0;
#endif
#ifdef M4_NOSETTLE
    c.settle = 0;
#endif
    SYST_RVR = 0xFFFFFF;
    SYST_CVR = 0;
    SYST_CSR = 5;
    /* calibration: 100000 x (add, subs, bne) = 300000 instructions */
    t0 = SYST_CVR;
    __asm__ volatile("movw r0, #34464\n movt r0, #1\n 1: add %0, %0, #1\n subs r0, r0, #1\n bne 1b"
                     : "+r"(x)::"r0", "cc");
    t1 = SYST_CVR;
    calib = ticks(t0, t1);
    per_tick = (300000u + calib / 2) / calib;
    putu("instructions per SysTick tick: ", per_tick);
    if (fnav_nav_init(&nav, &c) != FNAV_OK) {
        sh_puts("init failed\n");
        fnav_cm_sh_exit(1);
    }
    for (k = 0; k < NS; k++) {
        fnav_sample_t s;
        memset(&s, 0, sizeof s);
        s.t_ns = T_NS[k];
        memcpy(s.accel_mps2, D[k], sizeof s.accel_mps2);
        memcpy(s.gyro_rps, &D[k][3], sizeof s.gyro_rps);
        if (fnav_nav_push(&nav, &s) != FNAV_OK) {
            sh_puts("push rejected\n");
        }
        for (;;) {
            uint32_t pb = nav.ukf.health.predicts;
            int64_t tprev = nav.t_prev_ns;
            fnav_status_t st;
            memcpy(&u2, &nav.ukf, sizeof u2);
            t0 = SYST_CVR;
            st = fnav_nav_pop(&nav, &fr);
            t1 = SYST_CVR;
            if (st != FNAV_OK) {
                break;
            }
            if (ticks(t0, t1) > nav_max) {
                nav_max = ticks(t0, t1);
            }
            if (nav.ukf.health.predicts != pb && u2.started) {
                int j = 0;
                fnav_vec3_t w, a;
                uint32_t a0, a1, b1;
                fnav_status_t s2;
                while (j < NS && T_NS[j] != fr.t_ns) {
                    j++;
                }
                w = fnav_vec3(D[j][3], D[j][4], D[j][5]);
                a = fnav_vec3(D[j][0], D[j][1], D[j][2]);
                a0 = SYST_CVR;
                s2 = fnav_ukf_predict(&u2, w, a, (fnav_real_t)(fr.t_ns - tprev) * 1e-9f);
                a1 = SYST_CVR;
                if (fr.flags & FNAV_FRAME_ZUPT) {
                    s2 = fnav_ukf_zupt(&u2, w);
#ifdef M4_ZARU
                    /* with the zero-angular-rate update after it (--param
                     * zaru=1; docs/navigation.md, "Zero-velocity update") */
                    s2 = fnav_ukf_zaru(&u2, w);
#endif
                }
                b1 = SYST_CVR;
                (void)s2;
                up_sum += ticks(a0, a1);
                up_n++;
                if (ticks(a0, a1) > up_max) {
                    up_max = ticks(a0, a1);
                }
                if (fr.flags & FNAV_FRAME_ZUPT) {
                    uz_sum += ticks(a1, b1);
                    uz_n++;
                    if (ticks(a0, b1) > ust_max) {
                        ust_max = ticks(a0, b1);
                    }
                }
            }
        }
    }
    putu("samples: ", NS);
    putu("UKF predictions timed: ", up_n);
    putu("UKF prediction, instructions (mean): ", up_sum / (up_n ? up_n : 1) * per_tick);
    putu("UKF prediction, instructions (max): ", up_max * per_tick);
    putu("ZUPT update, instructions (mean): ", uz_sum / (uz_n ? uz_n : 1) * per_tick);
    putu("UKF step in stance (prediction + ZUPT), instructions (max): ", ust_max * per_tick);
    putu("whole fnav_nav_pop (detector, filter, frame), instructions (max): ", nav_max * per_tick);
    fnav_cm_sh_exit(0);
}
