/* Fuzz target: the navigator stepped with arbitrary samples.
 *
 * Input: byte 0 selects options (bias model, lever, ZARU, threshold
 * detector, a still lead-in so that alignment happens, sample rate class;
 * bit 7 turns the cycle-scaled shortest ZUPT run, with its lock-in guard,
 * off: it is on by default);
 * then records of 13 bytes: a time code and six int16 values. Values map to
 * +-16 g and +-2000 deg/s except for special codes that inject NaN, +-Inf,
 * denormals, 1e30 and values just beyond a sensor's range; time codes give
 * regular steps, duplicates (dt = 0), gaps, time going backwards and huge
 * jumps. Property checked after every frame: every output is finite and the
 * covariance diagonal is non-negative (abort otherwise, which the fuzzer
 * reports). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "footnav/fnav_nav.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static fnav_real_t value(int16_t raw, int gyro)
{
    switch (raw) {
    case 32767: return (fnav_real_t)NAN;
    case -32768: return (fnav_real_t)-INFINITY;
    case 32766: return (fnav_real_t)INFINITY;
    case 32765: return (fnav_real_t)1.0e-40f; /* denormal in float */
    case 32764: return FNAV_R(1.0e30);
    case 32763: return gyro ? FNAV_R(40.0) : FNAV_R(400.0); /* beyond any sensor */
    default: break;
    }
    return gyro ? (fnav_real_t)raw * FNAV_R(2000.0) * FNAV_DEG2RAD / FNAV_R(32768.0)
                : (fnav_real_t)raw * FNAV_R(16.0) * FNAV_G0_MPS2 / FNAV_R(32768.0);
}

static void check_frame(const fnav_nav_frame_t *f)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (!fnav_isfinite(f->pos_m[i]) || !fnav_isfinite(f->vel_mps[i]) || !fnav_isfinite(f->euler_rad[i]) ||
            !fnav_isfinite(f->gyro_bias_rps[i]) || !fnav_isfinite(f->accel_bias_mps2[i]) ||
            !fnav_isfinite(f->lever_m[i])) {
            abort();
        }
    }
    for (i = 0; i < 15; i++) {
        if (!fnav_isfinite(f->p_diag[i]) || f->p_diag[i] < FNAV_R(0.0)) {
            abort();
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fnav_nav_t nav;
    fnav_nav_config_t cfg = fnav_nav_config_default;
    fnav_sample_t s;
    fnav_nav_frame_t f;
    int64_t t = 1000000000LL, step_ns;
    size_t i;
    uint8_t opt;
    static const int64_t steps[4] = { 10000000LL, 5000000LL, 2500000LL, 1219512LL }; /* 100..820 Hz */
    if (size < 1) {
        return 0;
    }
    opt = data[0];
    cfg.bias_model = (opt & 1u) ? FNAV_BIAS_AR1 : FNAV_BIAS_OFF;
    cfg.lever = (opt & 2u) ? 1 : 0;
    cfg.zaru = (opt & 4u) ? 1 : 0;
    if (opt & 8u) {
        cfg.stance.detector = FNAV_DETECTOR_THRESHOLD;
    }
    step_ns = steps[(opt >> 5) & 3u];
    if (opt & 128u) {
        cfg.stance.min_zupt_cycle = FNAV_R(0.0); /* --param min_zupt_cycle=0 (0.025 by default) */
    }
    if (fnav_nav_init(&nav, &cfg) != FNAV_OK) {
        abort(); /* the default configuration must be valid */
    }
    memset(&s, 0, sizeof s);
    if (opt & 16u) { /* 2 s still lead-in: the filter aligns and navigates */
        for (i = 0; i < (size_t)(2000000000LL / step_ns); i++) {
            s.t_ns = t;
            s.accel_mps2[2] = -FNAV_G0_MPS2;
            t += step_ns;
            if (fnav_nav_push(&nav, &s) == FNAV_OK) {
                while (fnav_nav_pop(&nav, &f) == FNAV_OK) {
                    check_frame(&f);
                }
            }
        }
    }
    for (i = 1; i + 13 <= size; i += 13) {
        const uint8_t *r = data + i;
        int k;
        switch (r[0]) {
        case 0: break;                                  /* duplicate, dt = 0 */
        case 1: t -= step_ns; break;                    /* backwards */
        case 2: t += 3600LL * 1000000000LL; break;      /* an hour's jump */
        case 3: t += 25 * step_ns; break;               /* gap */
        default: t += step_ns + (int64_t)(r[0] - 128) * step_ns / 512; break; /* jitter */
        }
        s.t_ns = t;
        for (k = 0; k < 6; k++) {
            int16_t raw = (int16_t)((uint16_t)r[1 + 2 * k] | ((uint16_t)r[2 + 2 * k] << 8));
            if (k < 3) {
                s.accel_mps2[k] = value(raw, 0);
            } else {
                s.gyro_rps[k - 3] = value(raw, 1);
            }
        }
        if (fnav_nav_push(&nav, &s) == FNAV_OK) {
            while (fnav_nav_pop(&nav, &f) == FNAV_OK) {
                check_frame(&f);
            }
        }
    }
    fnav_nav_finish(&nav);
    while (fnav_nav_pop(&nav, &f) == FNAV_OK) {
        check_frame(&f);
    }
    return 0;
}
