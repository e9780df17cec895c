/* The firmware's estimators (see fnav_cm_est.h). Each block below compiles
 * only when its module is built in (FNAV_CM_WITH_*); a missing estimator
 * answers FNAV_E_UNSUPPORTED. */
#include "fnav_cm_est.h"

fnav_status_t fnav_cm_est_init(fnav_cm_est_t *e, fnav_real_t rate_hz, fnav_real_t nav_rate_hz)
{
    fnav_status_t st = FNAV_OK;
    e->samples = 0u;
#if FNAV_CM_WITH_NAV
    {
        fnav_nav_config_t cfg = fnav_nav_config_default;
        /* the detector's rate: the nominal rate, or 0 to estimate it from
         * the first intervals as `harness replay` does for a log */
        cfg.stance.rate_hz = nav_rate_hz;
        st = fnav_nav_init(&e->nav, &cfg);
        if (st != FNAV_OK) {
            return st;
        }
    }
#endif
#if FNAV_CM_WITH_ALLAN
    {
        uint32_t grid[FNAV_ALLAN_MAX_POINTS];
        fnav_allan_config_t ac;
        unsigned ch;
        /* octaves tau = 1, 2, 4, ... up to the largest the options allow */
        ac.tau = grid;
        ac.n_tau = fnav_allan_grid(grid, FNAV_ALLAN_MAX_POINTS, (uint32_t)FNAV_ALLAN_TAU_MAX, FNAV_CM_ALLAN_PER_OCTAVE);
        for (ch = 0; ch < FNAV_CM_ALLAN_CHANNELS; ch++) {
            st = fnav_allan_init(&e->allan[ch], &ac);
            if (st != FNAV_OK) {
                return st;
            }
        }
    }
#endif
#if FNAV_CM_WITH_WELCH
    {
        fnav_welch_config_t wc = fnav_welch_config_default; /* the paper's Hamming 64, 50 % */
        unsigned ch;
        wc.rate_hz = rate_hz;
        for (ch = 0; ch < FNAV_CM_WELCH_CHANNELS; ch++) {
            st = fnav_welch_init(&e->welch[ch], &wc);
            if (st != FNAV_OK) {
                return st;
            }
        }
    }
#endif
#if !FNAV_CM_WITH_NAV
    (void)nav_rate_hz;
#endif
#if !FNAV_CM_WITH_WELCH
    (void)rate_hz;
#endif
    return st;
}

#if FNAV_CM_WITH_ALLAN || FNAV_CM_WITH_WELCH
/* Channel k of a sample: 0..2 gyro x, y, z, 3..5 accel x, y, z
 * (accel_first swaps the two triples). */
static fnav_real_t channel(const fnav_sample_t *s, unsigned k, int accel_first)
{
    int gyro = (k < 3u) != (accel_first != 0);
    return gyro ? s->gyro_rps[k % 3u] : s->accel_mps2[k % 3u];
}
#endif

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_nav(fnav_cm_est_t *e, const fnav_sample_t *s, fnav_nav_frame_t *out)
{
    e->samples++;
#if FNAV_CM_WITH_NAV
    {
        fnav_status_t st = fnav_nav_push(&e->nav, s);
        if (st != FNAV_OK) {
            return st;
        }
        /* the first frame this sample released; fnav_cm_est_nav_next pops
         * the others (fnav_nav_step kept only the newest of them) */
        return (fnav_nav_pop(&e->nav, out) == FNAV_OK) ? FNAV_OK : FNAV_AGAIN;
    }
#else
    (void)s;
    (void)out;
    return FNAV_E_UNSUPPORTED;
#endif
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_nav_next(fnav_cm_est_t *e, fnav_nav_frame_t *out)
{
#if FNAV_CM_WITH_NAV
    return (fnav_nav_pop(&e->nav, out) == FNAV_OK) ? FNAV_OK : FNAV_AGAIN;
#else
    (void)e;
    (void)out;
    return FNAV_E_UNSUPPORTED;
#endif
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_allan(fnav_cm_est_t *e, const fnav_sample_t *s)
{
#if FNAV_CM_WITH_ALLAN
    fnav_status_t st = FNAV_OK;
    unsigned ch;
    for (ch = 0; ch < FNAV_CM_ALLAN_CHANNELS; ch++) {
        fnav_status_t r = fnav_allan_push(&e->allan[ch], channel(s, ch, 0));
        st = (r != FNAV_OK) ? r : st;
    }
    return st;
#else
    (void)e;
    (void)s;
    return FNAV_E_UNSUPPORTED;
#endif
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_welch(fnav_cm_est_t *e, const fnav_sample_t *s)
{
#if FNAV_CM_WITH_WELCH
    fnav_status_t st = FNAV_OK;
    unsigned ch;
    for (ch = 0; ch < FNAV_CM_WELCH_CHANNELS; ch++) {
        fnav_status_t r = fnav_welch_push(&e->welch[ch], channel(s, ch, 1));
        st = (r != FNAV_OK) ? r : st;
    }
    return st;
#else
    (void)e;
    (void)s;
    return FNAV_E_UNSUPPORTED;
#endif
}

unsigned fnav_cm_est_built(void)
{
    unsigned built = 0u;
#if FNAV_CM_WITH_NAV
    built += 1u;
#endif
#if FNAV_CM_WITH_ALLAN
    built += 2u;
#endif
#if FNAV_CM_WITH_WELCH
    built += 4u;
#endif
    return built;
}
