/* The reference firmware application (see fnav_cm_app.h). */
#include "fnav_cm_app.h"
#include "fnav_cm_prof.h"
#include "footnav/fnav_math.h"
#include "footnav/fnav_nav.h" /* FNAV_FRAME_STRIDE (the frame bits, whatever estimators are built) */

const fnav_cm_app_config_t fnav_cm_app_config_default = {
    FNAV_R(400.0), /* rate_hz */
    FNAV_R(0.0),   /* nav_rate_hz: estimated, as replay */
    4u,            /* nav_every: 100 Hz of NAV frames at 400 Hz */
    0u,            /* sample_every */
    400u,          /* status_every: about once a second */
    "footnav-fw",  /* sensor */
    FNAV_CM_SAMPLE_FLAGS, /* sample_flags: what the board's samples carry (0 by default) */
};

fnav_status_t fnav_cm_app_init(fnav_cm_app_t *app, const fnav_cm_app_config_t *cfg)
{
    fnav_status_t st;
    if (app == NULL || cfg == NULL) {
        return FNAV_E_ARG;
    }
    if (!(cfg->rate_hz > FNAV_R(0.0)) || !fnav_isfinite(cfg->rate_hz) || !(cfg->nav_rate_hz >= FNAV_R(0.0)) ||
        !fnav_isfinite(cfg->nav_rate_hz) || (cfg->sample_flags & ~(FNAV_SAMPLE_HAS_TEMP | FNAV_SAMPLE_HAS_SEQ)) != 0u) {
        return FNAV_E_CONFIG;
    }
    app->cfg = *cfg;
    fnav_cm_port_init(&app->port, &app->port_ctx);
    st = fnav_cm_est_init(&app->est, cfg->rate_hz, cfg->nav_rate_hz);
    if (st != FNAV_OK) {
        return st;
    }
    app->samples = 0u;
    app->nav_outputs = 0u;
    app->events = 0u;
    app->est_errors = 0u;
    app->last_error = FNAV_OK;
    return FNAV_OK;
}

fnav_status_t fnav_cm_app_announce(fnav_cm_app_t *app)
{
    fnav_wire_info_t info;
    const char *name = (app->cfg.sensor != NULL) ? app->cfg.sensor : "";
    size_t i;
    /* the SAMPLE stream's own rate and counter: every N-th sample runs at
     * rate / N and its seq steps by N, which a receiver must not take for
     * N - 1 lost samples each time (1,999 "drops" in 4,000 at N = 2); the
     * temperature and the counter only when the board's samples carry them
     * (sample_flags) */
    const uint32_t every = app->cfg.sample_every > 1u ? app->cfg.sample_every : 1u;
    const uint32_t has = app->cfg.sample_flags;
    info.rate_hz = (double)(app->cfg.rate_hz / (fnav_real_t)every);
    info.flags = FNAV_WIRE_INFO_RATE_NOMINAL | ((has & FNAV_SAMPLE_HAS_TEMP) ? FNAV_WIRE_INFO_TEMP : 0u) |
                 ((every == 1u && (has & FNAV_SAMPLE_HAS_SEQ)) ? FNAV_WIRE_INFO_SEQ : 0u);
    for (i = 0; i + 1u < sizeof info.sensor && name[i] != '\0'; i++) {
        info.sensor[i] = name[i];
    }
    info.sensor[i] = '\0';
    info.axes[0] = '\0';
    return fnav_cm_port_send_info(&app->port_ctx, &info);
}

static void count_error(fnav_cm_app_t *app, fnav_status_t st)
{
    if (st < 0 && st != FNAV_E_UNSUPPORTED) {
        app->est_errors++;
        app->last_error = st;
    }
}

void fnav_cm_app_process(fnav_cm_app_t *app, const fnav_sample_t *s)
{
    fnav_status_t st;
    app->samples++;
    if (app->cfg.sample_every != 0u && app->samples % app->cfg.sample_every == 0u) {
        FNAV_CM_PROF_BEGIN(FNAV_CM_PROF_TX_SAMPLE);
        (void)fnav_cm_port_send_sample(&app->port_ctx, s);
        FNAV_CM_PROF_END(FNAV_CM_PROF_TX_SAMPLE);
    }

    FNAV_CM_PROF_BEGIN(FNAV_CM_PROF_NAV);
    st = fnav_cm_est_nav(&app->est, s, &app->frame);
    FNAV_CM_PROF_END(FNAV_CM_PROF_NAV);
    FNAV_CM_PROF_NOTE(FNAV_CM_PROF_NAV, (st == FNAV_OK) ? app->frame.flags : FNAV_CM_PROF_TAG_NO_OUTPUT);
    /* every frame the sample released is an output, not only the first
     * (a sample can release several together) */
    while (st == FNAV_OK) {
        app->nav_outputs++;
        /* the events of the frames not sent ride on the next one sent: a
         * stride or a ZUPT marks one frame, and every nav_every-th frame
         * alone carried 6 of the bundled walk's 16 strides at N = 4 */
        app->events |= app->frame.flags & (FNAV_FRAME_ZUPT | FNAV_FRAME_STRIDE);
        if (app->cfg.nav_every != 0u && app->nav_outputs % app->cfg.nav_every == 0u) {
            app->frame.flags |= app->events;
            FNAV_CM_PROF_BEGIN(FNAV_CM_PROF_TX_NAV);
            if (fnav_port_write_nav(&app->port, &app->frame) == FNAV_OK) {
                app->events = 0u;
            } /* else link busy: counted in port_ctx.tx_dropped, the receiver sees the seq gap, and the
               * events ride on the next frame sent */
            FNAV_CM_PROF_END(FNAV_CM_PROF_TX_NAV);
        }
        st = fnav_cm_est_nav_next(&app->est, &app->frame);
    }
    count_error(app, st);

    FNAV_CM_PROF_BEGIN(FNAV_CM_PROF_ALLAN);
    st = fnav_cm_est_allan(&app->est, s);
    FNAV_CM_PROF_END(FNAV_CM_PROF_ALLAN);
    count_error(app, st);

    FNAV_CM_PROF_BEGIN(FNAV_CM_PROF_WELCH);
    st = fnav_cm_est_welch(&app->est, s);
    FNAV_CM_PROF_END(FNAV_CM_PROF_WELCH);
    count_error(app, st);

    if (app->cfg.status_every != 0u && app->samples % app->cfg.status_every == 0u) {
        fnav_wire_status_t ws;
        ws.samples = app->samples;
        ws.overruns = app->port_ctx.ring.overruns;
        ws.est_errors = app->est_errors;
        ws.tx_dropped = app->port_ctx.tx_dropped;
        ws.uptime_ms = fnav_ns_to_ms_u32(fnav_port_now_ns(&app->port)); /* wraps */
        (void)fnav_cm_port_send_status(&app->port_ctx, &ws);
    }
}

uint32_t fnav_cm_app_poll(fnav_cm_app_t *app)
{
    uint32_t n = 0u;
    for (;;) {
        fnav_sample_t s;
        fnav_status_t st;
        FNAV_CM_PROF_BEGIN(FNAV_CM_PROF_POP);
        st = fnav_port_read(&app->port, &s);
        FNAV_CM_PROF_END(FNAV_CM_PROF_POP);
        if (st != FNAV_OK) {
            return n;
        }
        FNAV_CM_PROF_BEGIN(FNAV_CM_PROF_SAMPLE);
        fnav_cm_app_process(app, &s);
        FNAV_CM_PROF_END(FNAV_CM_PROF_SAMPLE);
        n++;
    }
}
