/* The firmware's estimators (see fnav_cm_est.h). Each block below compiles
 * only when its module is part of the core (FNAV_CM_WITH_*). */
#include "fnav_cm_est.h"

#if FNAV_CM_WITH_NAV || FNAV_CM_WITH_ALLAN || FNAV_CM_WITH_WELCH
#error "fnav_cm_est.c: the calls into fnav_nav / fnav_allan / fnav_welch are wired in when those modules are on main"
#endif

fnav_status_t fnav_cm_est_init(fnav_cm_est_t *e, fnav_real_t rate_hz)
{
    (void)rate_hz;
    e->samples = 0u;
    return FNAV_OK;
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_nav(fnav_cm_est_t *e, const fnav_sample_t *s, fnav_nav_frame_t *out)
{
    e->samples++;
    (void)s;
    (void)out;
    return FNAV_E_UNSUPPORTED;
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_allan(fnav_cm_est_t *e, const fnav_sample_t *s)
{
    (void)e;
    (void)s;
    return FNAV_E_UNSUPPORTED;
}

FNAV_CM_NOIPA fnav_status_t fnav_cm_est_welch(fnav_cm_est_t *e, const fnav_sample_t *s)
{
    (void)e;
    (void)s;
    return FNAV_E_UNSUPPORTED;
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
