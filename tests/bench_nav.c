/* Navigation benchmark (make bench): object sizes, host replay throughput
 * of the core and of the whole `harness replay` path, host instructions per
 * UKF step counted by valgrind/callgrind (when installed), and the
 * worst-case stack of a step from the Cortex-M4F call graph (when
 * `make firmware` has produced it). Figures in docs/navigation.md come from
 * here. The emulated Cortex-M4F instruction count is measured by the
 * firmware issue's qemu image (issue #7). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "footnav/fnav_nav.h"
#include "fnav_testdata.h"
#include "hx_log.h"
#include "hx_nav.h"

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define HAVE_CALLGRIND 1
#endif
#endif
#ifndef HAVE_CALLGRIND
#define HAVE_CALLGRIND 0
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static fnav_sample_t sample_of(const hx_log_t *log, size_t i)
{
    fnav_sample_t s;
    int k;
    memset(&s, 0, sizeof s);
    s.t_ns = log->t_ns[i];
    s.seq = log->seq[i];
    for (k = 0; k < 3; k++) {
        s.accel_mps2[k] = (fnav_real_t)log->acc[i][k];
        s.gyro_rps[k] = (fnav_real_t)log->gyr[i][k];
    }
    return s;
}

/* One pass of a whole log through the navigator; returns frames. */
static long run_core(fnav_nav_t *nav, const fnav_nav_config_t *c, const hx_log_t *log, long *stance)
{
    fnav_nav_frame_t fr;
    size_t i;
    long frames = 0;
    fnav_status_t st;
    if (fnav_nav_init(nav, c) != FNAV_OK) {
        return -1;
    }
    *stance = 0;
    for (i = 0; i < log->n; i++) {
        fnav_sample_t s = sample_of(log, i);
        st = fnav_nav_push(nav, &s);
        (void)st;
        while (fnav_nav_pop(nav, &fr) == FNAV_OK) {
            frames++;
            *stance += (fr.flags & FNAV_FRAME_ZUPT) ? 1 : 0;
        }
    }
    fnav_nav_finish(nav);
    while (fnav_nav_pop(nav, &fr) == FNAV_OK) {
        frames++;
    }
    return frames;
}

/* --inner LOG: the steps of one pass under callgrind instrumentation only. */
static int inner(const char *path)
{
    static fnav_nav_t nav;
    hx_log_t log;
    char err[320];
    long stance;
    fnav_nav_config_t c = fnav_nav_config_default;
    if (hx_log_load(&log, path, HX_FMT_AUTO, 0.0, err, sizeof err) < 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    CALLGRIND_START_INSTRUMENTATION;
    run_core(&nav, &c, &log, &stance);
    CALLGRIND_STOP_INSTRUMENTATION;
    printf("predicts %u zupts %u\n", nav.ukf.health.predicts, nav.ukf.health.zupts);
    hx_log_free(&log);
    return 0;
}

/* Ir of the functions collected with --toggle-collect, from callgrind's
 * "totals:" line. */
static double callgrind_ir(const char *self, const char *path, const char *fn, char *out_line, size_t size)
{
    char cmd[1200], file[] = "/tmp/fnav_cg_XXXXXX", line[512];
    double ir = -1.0;
    FILE *f;
    int fd = mkstemp(file);
    if (fd < 0) {
        return -1.0;
    }
    close(fd);
    snprintf(cmd, sizeof cmd,
             "valgrind --tool=callgrind --callgrind-out-file=%s --collect-atstart=no --toggle-collect=%s "
             "%s --inner %s 2>/dev/null",
             file, fn, self, path);
    f = popen(cmd, "r");
    if (f == NULL) {
        remove(file);
        return -1.0;
    }
    out_line[0] = '\0';
    while (fgets(line, sizeof line, f) != NULL) {
        snprintf(out_line, size, "%.200s", line);
    }
    if (pclose(f) != 0) {
        remove(file);
        return -1.0;
    }
    f = fopen(file, "r");
    while (f != NULL && fgets(line, sizeof line, f) != NULL) {
        if (strncmp(line, "totals:", 7) == 0 || strncmp(line, "summary:", 8) == 0) {
            ir = atof(line + (line[0] == 't' ? 7 : 8));
        }
    }
    if (f != NULL) {
        fclose(f);
    }
    remove(file);
    return ir;
}

int main(int argc, char **argv)
{
    static fnav_nav_t nav;
    hx_log_t log;
    char path[512], err[400];
    fnav_nav_config_t c = fnav_nav_config_default;
    double best = 1e30;
    long frames = 0, stance = 0;
    int rep;
    if (argc == 3 && strcmp(argv[1], "--inner") == 0) {
        return inner(argv[2]);
    }
    printf("bench_nav (%s build)\n", FNAV_USE_DOUBLE ? "float64" : "float32");
    printf("  sizeof fnav_nav_t %zu B (fnav_ukf_t %zu, fnav_stance_t %zu, fnav_align_t %zu)\n", sizeof(fnav_nav_t),
           sizeof(fnav_ukf_t), sizeof(fnav_stance_t), sizeof(fnav_align_t));
    if (fnav_testdata_path("openshoe_gx2/Measurement_100521_2_data_inert.txt", path, sizeof path) != 0) {
        printf("  replay figures skipped: shared data not found (set FNAV_DATA_DIR)\n");
        return 0;
    }
    if (hx_log_load(&log, path, HX_FMT_AUTO, 0.0, err, sizeof err) < 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    /* core only: samples already in memory, best of 5 passes */
    for (rep = 0; rep < 5; rep++) {
        double t0 = now_s(), dt;
        frames = run_core(&nav, &c, &log, &stance);
        dt = now_s() - t0;
        best = dt < best ? dt : best;
    }
    printf("  core replay, openshoe_gx2 walk 2 (%zu samples, %ld with ZUPT): %.0f samples/s (best of 5, %.1f us "
           "per sample)\n",
           log.n, stance, (double)log.n / best, 1e6 * best / (double)log.n);
    /* the whole harness path: text parsing, port, CSV to /dev/null */
    {
        FILE *null = fopen("/dev/null", "w");
        double b2 = 1e30;
        for (rep = 0; rep < 3; rep++) {
            double t0 = now_s(), dt;
            int rc = hx_nav_replay("bench", path, HX_FMT_AUTO, 0.0, &c, 0.0, null, NULL, 0, err, sizeof err);
            dt = now_s() - t0;
            if (rc < 0) {
                fprintf(stderr, "%s\n", err);
                break;
            }
            b2 = dt < b2 ? dt : b2;
        }
        if (null != NULL) {
            fclose(null);
        }
        printf("  harness replay path (parse text, port, CSV to /dev/null): %.0f samples/s (best of 3)\n",
               (double)log.n / b2);
    }
    hx_log_free(&log);
    (void)frames;
    /* host instructions per step under callgrind */
    if (HAVE_CALLGRIND && system("command -v valgrind >/dev/null 2>&1") == 0) {
        char line[256];
        double ir_p = callgrind_ir(argv[0], path, "fnav_ukf_predict", line, sizeof line);
        double ir_z = callgrind_ir(argv[0], path, "fnav_ukf_zupt", line, sizeof line);
        double ir_all = callgrind_ir(argv[0], path, "fnav_nav_pop", line, sizeof line);
        unsigned np = 0, nz = 0;
        if (sscanf(line, "predicts %u zupts %u", &np, &nz) == 2 && np > 0 && nz > 0 && ir_p > 0.0 && ir_z > 0.0) {
            printf("  host x86-64 instructions (callgrind Ir, -O2): UKF predict %.0f per call, ZUPT update %.0f per "
                   "call, stance step %.0f; whole fnav_nav_pop %.0f per frame\n",
                   ir_p / np, ir_z / nz, ir_p / np + ir_z / nz, ir_all / (double)(np + 1));
        } else {
            printf("  callgrind figures unavailable\n");
        }
    } else {
        printf("  callgrind not available: instruction counts skipped\n");
    }
    /* emulated Cortex-M4F instruction counts (tests/m4): the default
     * configuration (18 states and the landing settling), without the
     * settling, the paper's 15 (no lever) and the bias model off (12) */
    fflush(stdout);
    if (system("sh tests/m4/run.sh") != 0 || system("sh tests/m4/run.sh -DM4_NOSETTLE") != 0 ||
        system("sh tests/m4/run.sh -DM4_NOLEVER") != 0 || system("sh tests/m4/run.sh -DM4_BIASOFF") != 0) {
        printf("  m4 benchmark failed\n");
    }
    fflush(stdout);
    /* worst-case stack from the Cortex-M4F call graph */
    if (system("ls build/arm/obj/src/fnav_nav.ci >/dev/null 2>&1") == 0) {
        fflush(stdout);
        if (system("/usr/bin/python3 tests/support/stack_usage.py build/arm/obj/src fnav_nav_step | sed 's/^/  /'") !=
            0) {
            printf("  stack analysis failed\n");
        }
    } else {
        printf("  stack: run `make firmware` first (needs build/arm/obj/src/*.ci)\n");
    }
    return 0;
}
