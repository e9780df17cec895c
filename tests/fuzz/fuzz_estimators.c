/* Fuzz target: the streaming Allan and Welch estimators with arbitrary
 * configurations and samples (NaN, Inf, denormals and huge values included).
 * Property: every result either has a failure status or is finite and
 * non-negative (abort otherwise). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "footnav/fnav_allan.h"
#include "footnav/fnav_welch.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fnav_allan_t allan;
    static fnav_welch_t welch;
    static fnav_real_t psd[FNAV_WELCH_MAX_NFFT / 2 + 1];
    static uint32_t tau[64];
    fnav_allan_config_t ac;
    fnav_welch_config_t wc = fnav_welch_config_default;
    size_t i, ntau;
    if (size < 4) {
        return 0;
    }
    /* Allan: a grid from the first byte (1, 2 or 4 points per octave, capped) */
    ntau = fnav_allan_grid(tau, FNAV_ALLAN_MAX_POINTS < 64 ? FNAV_ALLAN_MAX_POINTS : 64,
                           (uint32_t)1u << (data[0] % 21u), 1u + (data[0] >> 6));
    ac.tau = tau;
    ac.n_tau = ntau;
    if (fnav_allan_init(&allan, &ac) != FNAV_OK) {
        abort(); /* a grid from fnav_allan_grid is always valid */
    }
    /* Welch: nfft 8..MAX, overlap below it, window, detrend, scaling */
    wc.nfft = 8u << (data[1] % 8u);
    if (wc.nfft > FNAV_WELCH_MAX_NFFT) {
        wc.nfft = FNAV_WELCH_MAX_NFFT;
    }
    wc.overlap = (uint32_t)data[2] % wc.nfft;
    wc.window = (fnav_window_t)(data[3] % 3u);
    wc.symmetric = (data[3] >> 2) & 1;
    wc.detrend = (fnav_detrend_t)((data[3] >> 3) % 4u);
    wc.scaling = (fnav_scaling_t)((data[3] >> 5) & 1u);
    wc.rate_hz = FNAV_R(100.0);
    if (fnav_welch_init(&welch, &wc) != FNAV_OK) {
        return 0; /* some combinations are invalid by design (e.g. global + symmetric) */
    }
    for (i = 4; i + 4 <= size; i += 4) {
        float f;
        memcpy(&f, data + i, 4);
        (void)fnav_allan_push(&allan, (fnav_real_t)f);
        (void)fnav_welch_push(&welch, (fnav_real_t)f);
    }
    for (i = 0; i < fnav_allan_count(&allan); i++) {
        fnav_allan_result_t r;
        if (fnav_allan_get(&allan, i, &r) != FNAV_OK) {
            abort();
        }
        if (r.terms > 0 && !(r.avar >= FNAV_R(0.0))) {
            abort(); /* NaN or negative variance with data behind it */
        }
    }
    if (fnav_welch_get(&welch, psd, FNAV_WELCH_MAX_NFFT / 2 + 1) == FNAV_OK) {
        for (i = 0; i < fnav_welch_bins(&welch); i++) {
            if (!(psd[i] >= FNAV_R(0.0))) {
                abort();
            }
        }
    }
    return 0;
}
