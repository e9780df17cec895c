/* Benchmarks of the simulator (run by `make bench`; figures in
 * docs/simulator.md come from here): cost of one error-model sample in the
 * core (the firmware-test injection path), of the full catalogue, and the
 * throughput of the whole chain (motion + filter + sensor) of `harness sim`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "footnav/fnav_imuerr.h"
#include "hx_sim.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double bench_apply(const fnav_imuerr_config_t *c, long n)
{
    fnav_imuerr_t e;
    fnav_sample_t s;
    double t0, sink = 0.0;
    long i;
    if (fnav_imuerr_init(&e, c) != FNAV_OK) {
        fprintf(stderr, "bench: bad config\n");
        exit(1);
    }
    memset(&s, 0, sizeof s);
    t0 = now_s();
    for (i = 0; i < n; i++) {
        s.accel_mps2[2] = (fnav_real_t)-9.80665;
        s.gyro_rps[0] = s.gyro_rps[1] = s.gyro_rps[2] = (fnav_real_t)0.0;
        s.accel_mps2[0] = s.accel_mps2[1] = (fnav_real_t)0.0;
        if (fnav_imuerr_apply(&e, &s) != FNAV_OK) {
            exit(1);
        }
        sink += (double)s.accel_mps2[0];
    }
    if (sink == 12345.678) {
        printf("(unlikely)\n");
    }
    return (now_s() - t0) / (double)n;
}

static int count_sink(void *ctx, const hx_sim_tick_t *tk)
{
    (void)tk;
    (*(long *)ctx)++;
    return 0;
}

int main(void)
{
    fnav_imuerr_config_t c = fnav_imuerr_config_default;
    fnav_profile_t p;
    long n = 2000000;
    int id;
    double t;
    if (fnav_profile_by_name(&p, "navchip") != FNAV_OK || fnav_imuerr_config_from_profile(&c, &p) != FNAV_OK) {
        return 1;
    }
    c.rate_hz = (fnav_real_t)200.0;
    printf("sizeof(fnav_imuerr_t) = %zu bytes (%s)\n", sizeof(fnav_imuerr_t),
           sizeof(fnav_real_t) == 4 ? "float" : "double");
    t = bench_apply(&c, n);
    printf("fnav_imuerr_apply, white + AR(1):           %7.1f ns/sample (6 channels)\n", t * 1e9);
    for (id = 0; id < (int)FNAV_EFFECT_COUNT; id++) {
        if (id != FNAV_EFFECT_ALIAS && fnav_imuerr_enable(&c, (fnav_effect_id_t)id, FNAV_CH_ALL) != FNAV_OK) {
            return 1;
        }
    }
    t = bench_apply(&c, n / 4);
    printf("fnav_imuerr_apply, every per-sample effect: %7.1f ns/sample (flicker: 12 poles x 6)\n", t * 1e9);
    {
        char err[256];
        hx_motion_config_t mc = hx_motion_config_default();
        hx_motion_t *m = hx_motion_create(&mc, "walk", 600.0, err, sizeof err);
        hx_sim_config_t sc;
        long ticks = 0;
        double t0;
        if (m == NULL) {
            fprintf(stderr, "%s\n", err);
            return 1;
        }
        sc.motion = m;
        sc.err = fnav_imuerr_config_default;
        if (fnav_imuerr_config_from_profile(&sc.err, &p) != FNAV_OK) {
            return 1;
        }
        sc.err.rate_hz = (fnav_real_t)200.0;
        sc.err.oversample = 10u;
        sc.duration_s = 0.0;
        sc.decim = HX_DECIM_FIR;
        t0 = now_s();
        if (hx_sim_run(&sc, count_sink, &ticks, err, sizeof err) != 0) {
            return 1;
        }
        t = now_s() - t0;
        printf("harness sim chain, 600 s walk at 200 Hz (2 kHz internal, FIR): %.2f s, %.0f x real time\n", t,
               600.0 / t);
        hx_motion_free(m);
    }
    return 0;
}
