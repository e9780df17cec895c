/* Fuzz target: the reader of one sensor's file that `harness merge` takes
 * (hx_merge.h). The first input byte selects the sensor (bit 0), --units
 * (bits 1-2: none, time=ns, accel=g,gyro=deg/s, time=ms) and the .gz name
 * (bit 6); the rest is the file. A file read is then sampled by hx_tri_at
 * at stamps inside, between and around its own, and every value it gives
 * must lie between the two samples around the stamp. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "fuzz_support.h"
#include "hx_merge.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const units[4] = { NULL, "time=ns", "accel=g,gyro=deg/s", "time=ms" };
    char err[HX_ERR_SIZE];
    const char *path;
    hx_csv_layout_t l;
    hx_tri_t f;
    size_t i, j = 0;
    unsigned sel;
    if (size < 1) {
        return 0;
    }
    sel = data[0];
    path = fuzz_write_input(data + 1, size - 1, (sel & 0x40) ? ".gz" : ".csv");
    if (path == NULL) {
        return 0;
    }
    hx_csv_layout_default(&l);
    if (units[(sel >> 1) & 3u] != NULL && hx_csv_units_parse(&l, units[(sel >> 1) & 3u], err, sizeof err) != 0) {
        __builtin_trap(); /* a valid --units refused */
    }
    if (hx_tri_load(&f, path, (sel & 1u) ? HX_TRI_GYR : HX_TRI_ACC, &l, err, sizeof err) < 0) {
        return 0;
    }
    for (i = 0; i < f.n; i++) {
        const int64_t t = f.t_ns[i];
        int64_t probe[3];
        int p, k;
        if (i > 0 && t <= f.t_ns[i - 1]) {
            __builtin_trap(); /* stamps kept must increase */
        }
        probe[0] = t;
        probe[1] = i + 1 < f.n ? t + (f.t_ns[i + 1] - t) / 2 : t + 1;
        probe[2] = t == INT64_MIN ? t : t - 1;
        for (p = 0; p < 3; p++) {
            double v[3];
            const hx_tri_where_t w = hx_tri_at(&f, probe[p], &j, INT64_MAX, v);
            if (w != HX_TRI_IN) {
                continue;
            }
            for (k = 0; k < 3; k++) {
                /* between the samples around the stamp (the cursor j is the one at or before it) */
                const double a = f.v[j][k], b = j + 1 < f.n ? f.v[j + 1][k] : a;
                const double lo = a < b ? a : b, hi = a < b ? b : a;
                if (!(v[k] >= lo - 1e-9 * fabs(lo) && v[k] <= hi + 1e-9 * fabs(hi))) {
                    __builtin_trap();
                }
            }
        }
    }
    hx_tri_free(&f);
    return 0;
}
