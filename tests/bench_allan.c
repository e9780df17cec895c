/* Benchmark of the streaming Allan estimator (make bench).
 *
 * Side by side on the same 1,000,000-sample channel (ADIS16405 log 1 gyro x
 * when ../shared/data is there, else a synthetic white + random-walk
 * series): samples/s of the streaming estimator (octave grid, and the
 * default grid of 2 points per octave) against a vectorised numpy octave
 * OADEV (tests/bench_allan_ref.py, run with /usr/bin/python3 in the same
 * run), memory per channel, and - when valgrind is installed - host
 * instructions per push (callgrind, inclusive, --toggle-collect).
 * Target (issue #4): >= 5x numpy, <= 4 KB per channel. */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "footnav/fnav_allan.h"
#include "hx_log.h"
#include "support/fnav_testdata.h"

#define N_SAMPLES 1000000u
#define RUNS 5

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void synthetic(double *y, size_t n)
{
    uint64_t s = 1;
    double rw = 0.0;
    size_t k;
    for (k = 0; k < n; k++) {
        double u1, u2;
        s = 6364136223846793005u * s + 1442695040888963407u;
        u1 = (double)(s >> 11) / 9007199254740992.0;
        s = 6364136223846793005u * s + 1442695040888963407u;
        u2 = (double)(s >> 11) / 9007199254740992.0;
        rw += 1e-4 * (u2 - 0.5);
        y[k] = 0.3 * (u1 - 0.5) + rw;
    }
}

static const char *load(double *y, size_t n)
{
    char path[512], err[320];
    hx_log_t log;
    size_t k;
    if (fnav_testdata_path("adis16405_static/adis16405_imu1_100Hz.csv.gz", path, sizeof path) == 0 &&
        hx_log_load(&log, path, HX_FMT_AUTO, 0.0, err, sizeof err) == 0 && log.n >= n) {
        for (k = 0; k < n; k++) {
            y[k] = log.gyr[k][0] * 57.29577951308232; /* deg/s, as allantools was given */
        }
        hx_log_free(&log);
        return "ADIS16405 log 1, gyro x (deg/s)";
    }
    synthetic(y, n);
    return "synthetic white + random walk (shared data not found)";
}

/* Best-of-RUNS time of init + n pushes. */
static double time_stream(const double *y, size_t n, const fnav_allan_config_t *cfg, fnav_allan_t *a)
{
    double best = 1e30;
    int r;
    size_t k;
    for (r = 0; r < RUNS; r++) {
        double t0 = now_s(), dt;
        if (fnav_allan_init(a, cfg) != FNAV_OK) {
            return -1.0;
        }
        for (k = 0; k < n; k++) {
            if (fnav_allan_push(a, (fnav_real_t)y[k]) != FNAV_OK) {
                return -1.0;
            }
        }
        dt = now_s() - t0;
        best = dt < best ? dt : best;
    }
    return best;
}

static int pushes_only(long n, int octave)
{
    static fnav_allan_t a;
    static double y[100000];
    uint32_t grid[64];
    fnav_allan_config_t cfg;
    long k;
    cfg.tau = grid;
    cfg.n_tau = fnav_allan_grid(grid, 64, (uint32_t)FNAV_ALLAN_TAU_MAX, octave ? 1u : 2u);
    synthetic(y, 100000);
    if (fnav_allan_init(&a, &cfg) != FNAV_OK) {
        return 1;
    }
    for (k = 0; k < n; k++) {
        if (fnav_allan_push(&a, (fnav_real_t)y[k % 100000]) != FNAV_OK) {
            return 1;
        }
    }
    return 0;
}

/* Host instructions per push with callgrind (inclusive of callees). */
static double callgrind_per_push(const char *self, int octave)
{
    char cmd[1024], out[256], line[512];
    const long n = 400000;
    FILE *f;
    double ir = -1.0;
    if (system("command -v valgrind >/dev/null 2>&1") != 0) {
        return -1.0;
    }
    snprintf(out, sizeof out, "/tmp/fnav_bench_allan_%ld.cg", (long)getpid());
    snprintf(cmd, sizeof cmd,
             "valgrind --tool=callgrind --callgrind-out-file=%s --toggle-collect=fnav_allan_push %s --pushes %ld %s "
             ">/dev/null 2>&1",
             out, self, n, octave ? "octave" : "default");
    if (system(cmd) != 0 || (f = fopen(out, "r")) == NULL) {
        return -1.0;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        if (strncmp(line, "summary:", 8) == 0 || strncmp(line, "totals:", 7) == 0) {
            ir = strtod(line + (line[0] == 's' ? 8 : 7), NULL);
        }
    }
    fclose(f);
    remove(out);
    return ir > 0.0 ? ir / (double)n : -1.0;
}

int main(int argc, char **argv)
{
    static double y[N_SAMPLES];
    static fnav_allan_t a;
    uint32_t oct[64];
    fnav_allan_config_t cfg_oct;
    char tmp[] = "/tmp/fnav_bench_allan_XXXXXX", cmd[1024], line[256];
    const char *py = getenv("PYTHON") != NULL ? getenv("PYTHON") : "/usr/bin/python3";
    const char *src;
    double t_oct, t_def, t_py = -1.0, maxrel = 0.0;
    FILE *f;
    int fd, ncmp = 0;

    if (argc == 4 && strcmp(argv[1], "--pushes") == 0) {
        return pushes_only(atol(argv[2]), strcmp(argv[3], "octave") == 0);
    }
    src = load(y, N_SAMPLES);
    cfg_oct.tau = oct;
    cfg_oct.n_tau = fnav_allan_grid(oct, 64, (uint32_t)FNAV_ALLAN_TAU_MAX, 1u);
    t_oct = time_stream(y, N_SAMPLES, &cfg_oct, &a);
    /* keep the octave results for the cross-check below */
    t_def = time_stream(y, N_SAMPLES, NULL, &a);
    (void)time_stream(y, N_SAMPLES, &cfg_oct, &a);

    fd = mkstemp(tmp);
    if (fd >= 0) {
        f = fdopen(fd, "wb");
        if (f != NULL && fwrite(y, sizeof y[0], N_SAMPLES, f) == N_SAMPLES && fclose(f) == 0) {
            snprintf(cmd, sizeof cmd, "%s tests/bench_allan_ref.py %s %d", py, tmp, RUNS);
            f = popen(cmd, "r");
            while (f != NULL && fgets(line, sizeof line, f) != NULL) {
                unsigned m, terms;
                double dev;
                if (strncmp(line, "seconds ", 8) == 0) {
                    t_py = strtod(line + 8, NULL);
                } else if (sscanf(line, "tau %u %lf %u", &m, &dev, &terms) == 3) {
                    size_t i;
                    for (i = 0; i < fnav_allan_count(&a); i++) {
                        fnav_allan_result_t r;
                        if (fnav_allan_get(&a, i, &r) == FNAV_OK && r.tau == m && r.level == 0) {
                            const double rel = fabs(sqrt((double)r.avar) / dev - 1.0);
                            maxrel = rel > maxrel ? rel : maxrel;
                            ncmp++;
                        }
                    }
                }
            }
            if (f != NULL) {
                pclose(f);
            }
        }
        remove(tmp);
    }

    printf("allan: %u samples of %s; best of %d runs; %s build\n", N_SAMPLES, src, RUNS,
           FNAV_USE_DOUBLE ? "double" : "float");
    printf("  memory per channel: %zu bytes (fnav_allan_t; target <= 4096)\n", sizeof(fnav_allan_t));
    printf("  streaming, octave grid (%zu tau, 1..2^%d): %.4f s = %.1f M samples/s\n", cfg_oct.n_tau,
           FNAV_ALLAN_MAX_LEVELS - 1, t_oct, 1e-6 * N_SAMPLES / t_oct);
    printf("  streaming, default grid (%zu tau, 2 per octave): %.4f s = %.1f M samples/s\n",
           fnav_allan_count(&a) > 0 ? (size_t)40 : (size_t)0, t_def, 1e-6 * N_SAMPLES / t_def);
    if (t_py > 0.0) {
        printf("  numpy vectorised octave OADEV (%s tests/bench_allan_ref.py): %.4f s = %.1f M samples/s\n", py, t_py,
               1e-6 * N_SAMPLES / t_py);
        printf("  speed-up, octave grid: %.1fx (target >= 5x: %s); default grid: %.1fx\n", t_py / t_oct,
               t_py / t_oct >= 5.0 ? "met" : "NOT met", t_py / t_def);
        printf("  cross-check with numpy at %d fully overlapping tau: max relative difference %.2g\n", ncmp, maxrel);
    } else {
        printf("  numpy reference could not run (%s with numpy needed)\n", py);
    }
    {
        const double ir_oct = callgrind_per_push(argv[0], 1), ir_def = callgrind_per_push(argv[0], 0);
        if (ir_oct > 0.0) {
            printf("  host instructions per push (callgrind, x86-64): %.0f octave grid, %.0f default grid\n", ir_oct,
                   ir_def);
        } else {
            printf("  host instructions per push: valgrind not available\n");
        }
    }
    return 0;
}
