/* Benchmark of the streaming Welch PSD (make bench).
 *
 * Side by side on the same 1,000,000-sample channel (ADIS16405 log 1 gyro x
 * when ../shared/data is there, else synthetic): samples/s of the streaming
 * estimator with the paper's settings (Hamming 64, 50 % overlap, per-segment
 * mean removal, density) against scipy.signal.welch with the same settings
 * (tests/bench_welch_ref.py, /usr/bin/python3, same run), memory per channel,
 * and host instructions per push (callgrind) when valgrind is installed.
 * Target (issue #4): faster than scipy. */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "footnav/fnav_welch.h"
#include "hx_log.h"
#include "support/fnav_testdata.h"

#define N_SAMPLES 1000000u
#define RUNS 5
#define FS 100.0

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void synthetic(double *y, size_t n)
{
    uint64_t s = 3;
    size_t k;
    for (k = 0; k < n; k++) {
        s = 6364136223846793005u * s + 1442695040888963407u;
        y[k] = (double)(s >> 11) / 9007199254740992.0 - 0.5 + sin(0.1 * (double)k);
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
            y[k] = log.gyr[k][0] * 57.29577951308232;
        }
        hx_log_free(&log);
        return "ADIS16405 log 1, gyro x (deg/s)";
    }
    synthetic(y, n);
    return "synthetic (shared data not found)";
}

static fnav_welch_config_t config(uint32_t nfft)
{
    fnav_welch_config_t c = fnav_welch_config_default;
    c.nfft = nfft;
    c.overlap = nfft / 2u;
    c.rate_hz = (fnav_real_t)FS;
    return c;
}

static double time_stream(const double *y, size_t n, uint32_t nfft, fnav_welch_t *w, fnav_real_t *psd)
{
    const fnav_welch_config_t c = config(nfft);
    double best = 1e30;
    int r;
    size_t k;
    for (r = 0; r < RUNS; r++) {
        double t0 = now_s(), dt;
        if (fnav_welch_init(w, &c) != FNAV_OK) {
            return -1.0;
        }
        for (k = 0; k < n; k++) {
            if (fnav_welch_push(w, (fnav_real_t)y[k]) != FNAV_OK) {
                return -1.0;
            }
        }
        if (fnav_welch_get(w, psd, FNAV_WELCH_MAX_BINS) != FNAV_OK) {
            return -1.0;
        }
        dt = now_s() - t0;
        best = dt < best ? dt : best;
    }
    return best;
}

static int pushes_only(long n)
{
    static fnav_welch_t w;
    static double y[100000];
    const fnav_welch_config_t c = config(64);
    long k;
    synthetic(y, 100000);
    if (fnav_welch_init(&w, &c) != FNAV_OK) {
        return 1;
    }
    for (k = 0; k < n; k++) {
        if (fnav_welch_push(&w, (fnav_real_t)y[k % 100000]) != FNAV_OK) {
            return 1;
        }
    }
    return 0;
}

static double callgrind_per_push(const char *self)
{
    char cmd[1024], out[256], line[512];
    const long n = 400000;
    FILE *f;
    double ir = -1.0;
    if (system("command -v valgrind >/dev/null 2>&1") != 0) {
        return -1.0;
    }
    snprintf(out, sizeof out, "/tmp/fnav_bench_welch_%ld.cg", (long)getpid());
    snprintf(cmd, sizeof cmd,
             "valgrind --tool=callgrind --callgrind-out-file=%s --toggle-collect=fnav_welch_push %s --pushes %ld "
             ">/dev/null 2>&1",
             out, self, n);
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
    static fnav_welch_t w;
    static fnav_real_t psd[FNAV_WELCH_MAX_BINS];
    static const uint32_t sizes[3] = { 64, 256, 1024 };
    char tmp[] = "/tmp/fnav_bench_welch_XXXXXX", cmd[1024], line[256];
    const char *py = getenv("PYTHON") != NULL ? getenv("PYTHON") : "/usr/bin/python3";
    const char *src;
    double t_c[3], t_py[3] = { -1.0, -1.0, -1.0 }, maxrel = 0.0;
    int fd, s, wrote = 0;
    FILE *f;

    if (argc == 3 && strcmp(argv[1], "--pushes") == 0) {
        return pushes_only(atol(argv[2]));
    }
    src = load(y, N_SAMPLES);
    fd = mkstemp(tmp);
    if (fd >= 0) {
        f = fdopen(fd, "wb");
        wrote = f != NULL && fwrite(y, sizeof y[0], N_SAMPLES, f) == N_SAMPLES && fclose(f) == 0;
    }
    printf("welch: %u samples of %s at %g Hz; Hamming, 50 %% overlap, per-segment mean, density; best of %d runs; "
           "%s build\n",
           N_SAMPLES, src, FS, RUNS, FNAV_USE_DOUBLE ? "double" : "float");
    printf("  memory per channel: %zu bytes (fnav_welch_t with FNAV_WELCH_MAX_NFFT %d)\n", sizeof(fnav_welch_t),
           FNAV_WELCH_MAX_NFFT);
    for (s = 0; s < 3; s++) {
        if (sizes[s] > FNAV_WELCH_MAX_NFFT) {
            continue;
        }
        t_c[s] = time_stream(y, N_SAMPLES, sizes[s], &w, psd);
        if (wrote) {
            snprintf(cmd, sizeof cmd, "%s tests/bench_welch_ref.py %s %g %u %d", py, tmp, FS, (unsigned)sizes[s], RUNS);
            f = popen(cmd, "r");
            while (f != NULL && fgets(line, sizeof line, f) != NULL) {
                unsigned k;
                double v;
                if (strncmp(line, "seconds ", 8) == 0) {
                    t_py[s] = strtod(line + 8, NULL);
                } else if (sscanf(line, "bin %u %lf", &k, &v) == 2 && k < fnav_welch_bins(&w)) {
                    const double rel = fabs((double)psd[k] / v - 1.0);
                    maxrel = rel > maxrel ? rel : maxrel;
                }
            }
            if (f != NULL) {
                pclose(f);
            }
        }
        printf("  nfft %4u: streaming %.4f s = %.1f M samples/s", (unsigned)sizes[s], t_c[s],
               1e-6 * N_SAMPLES / t_c[s]);
        if (t_py[s] > 0.0) {
            printf("; scipy.signal.welch %.4f s = %.1f M samples/s; speed-up %.1fx (%s)\n", t_py[s],
                   1e-6 * N_SAMPLES / t_py[s], t_py[s] / t_c[s], t_py[s] > t_c[s] ? "faster" : "NOT faster");
        } else {
            printf("; scipy reference could not run\n");
        }
    }
    if (wrote) {
        remove(tmp);
        printf("  cross-check with scipy (3 bins per size): max relative difference %.2g\n", maxrel);
    }
    {
        const double ir = callgrind_per_push(argv[0]);
        if (ir > 0.0) {
            printf("  host instructions per push (callgrind, x86-64, nfft 64): %.0f\n", ir);
        } else {
            printf("  host instructions per push: valgrind not available\n");
        }
    }
    return 0;
}
