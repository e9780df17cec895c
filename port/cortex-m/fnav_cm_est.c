/* The firmware's estimators (see fnav_cm_est.h). Each block below compiles
 * only when its module is built in (FNAV_CM_WITH_*); a missing estimator
 * answers FNAV_E_UNSUPPORTED. */
#include "fnav_cm_est.h"

fnav_status_t fnav_cm_est_init(fnav_cm_est_t *e, fnav_real_t rate_hz)
{
    fnav_status_t st = FNAV_OK;
    e->samples = 0u;
#if FNAV_CM_WITH_NAV
    {
        fnav_nav_config_t cfg = fnav_nav_config_default;
        /* the detector's rate: the nominal rate, or 0 to estimate it from
         * the first intervals as `harness replay` does for a log */
        cfg.stance.rate_hz = rate_hz;
        st = fnav_nav_init(&e->nav, &cfg);
        if (st != FNAV_OK) {
            return st;
        }
    }
#else
    (void)rate_hz;
#endif
    return st;
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_nav(fnav_cm_est_t *e, const fnav_sample_t *s, fnav_nav_frame_t *out)
{
    e->samples++;
#if FNAV_CM_WITH_NAV
    return fnav_nav_step(&e->nav, s, out);
#else
    (void)s;
    (void)out;
    return FNAV_E_UNSUPPORTED;
#endif
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_allan(fnav_cm_est_t *e, const fnav_sample_t *s)
{
#if FNAV_CM_WITH_ALLAN
#error "fnav_cm_est_allan: wired in when fnav_allan is on main"
#else
    (void)e;
    (void)s;
    return FNAV_E_UNSUPPORTED;
#endif
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_welch(fnav_cm_est_t *e, const fnav_sample_t *s)
{
#if FNAV_CM_WITH_WELCH
#error "fnav_cm_est_welch: wired in when fnav_welch is on main"
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
