/* The Cortex-M reference firmware's application and port, compiled for the
 * host: interrupt-to-main-loop path through the ring and the port layer,
 * the frames it emits (decoded with the wire decoder, as a receiver would),
 * ring overruns, a busy output link, configuration errors. The board hooks
 * are the test's own strong definitions of the port's weak functions. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "fnav_cm_app.h"
#include "hx_log.h"

/* ---- the test board ---- */

static uint32_t g_imu_next;           /* sample counter of the fake IMU */
static int g_imu_absent;
static long g_imu_fifo;               /* samples left in the fake IMU's FIFO (-1: endless) */
static int g_imu_still;               /* a sensor lying still (the filter aligns) */
static int64_t g_period_ns;           /* sample interval of the fake IMU's stamps */
static uint8_t g_link[1 << 19];       /* everything sent */
static const hx_log_t *g_walk;        /* the IMU plays this log (NULL: the made-up samples) */
static size_t g_link_n;
static int g_busy_every;              /* refuse every N-th frame (0: never) */
static int g_writes;

static fnav_sample_t make_sample(uint32_t k)
{
    fnav_sample_t s;
    int i;
    memset(&s, 0, sizeof s);
    if (g_walk != NULL) {
        const size_t j = k < g_walk->n ? k : g_walk->n - 1u;
        s.t_ns = g_walk->t_ns[j] - g_walk->t_ns[0];
        s.seq = k;
        s.flags = FNAV_SAMPLE_HAS_SEQ;
        for (i = 0; i < 3; i++) {
            s.accel_mps2[i] = (fnav_real_t)g_walk->acc[j][i];
            s.gyro_rps[i] = (fnav_real_t)g_walk->gyr[j][i];
        }
        return s;
    }
    s.t_ns = (int64_t)k * g_period_ns;
    s.seq = k;
    s.flags = FNAV_SAMPLE_HAS_SEQ;
    if (g_imu_still) {
        /* level and still, z down (docs/frames.md): the specific force is
         * -g along z; a small deterministic wobble, no rotation */
        s.accel_mps2[0] = (fnav_real_t)(0.01 * (double)((k * 7u) % 5u) - 0.02);
        s.accel_mps2[1] = (fnav_real_t)(0.01 * (double)((k * 3u) % 5u) - 0.02);
        s.accel_mps2[2] = (fnav_real_t)(-9.81 + 0.01 * (double)((k * 11u) % 5u) - 0.02);
        return s;
    }
    for (i = 0; i < 3; i++) {
        s.accel_mps2[i] = (fnav_real_t)(0.25 * (double)(i + 1) + (double)k);
        s.gyro_rps[i] = (fnav_real_t)(-0.125 * (double)(i + 1) - (double)k / 1024.0);
    }
    return s;
}

int fnav_cm_imu_read(fnav_sample_t *s)
{
    if (g_imu_absent || g_imu_fifo == 0) {
        return -1;
    }
    if (g_imu_fifo > 0) {
        g_imu_fifo--;
    }
    *s = make_sample(g_imu_next++);
    return 0;
}

int fnav_cm_out_write(const void *bytes, uint32_t n)
{
    g_writes++;
    if (g_busy_every > 0 && g_writes % g_busy_every == 0) {
        return -1;
    }
    assert_true(g_link_n + n <= sizeof g_link);
    memcpy(g_link + g_link_n, bytes, n);
    g_link_n += n;
    return 0;
}

static int g_idles;                   /* calls of the board's idle (the main loop's sleep) */

void fnav_cm_idle(void)
{
    g_idles++;
}

static void reset_board(void)
{
    g_idles = 0;
    g_imu_next = 0;
    g_walk = NULL;
    g_imu_absent = 0;
    g_imu_fifo = -1;
    g_imu_still = 0;
    g_period_ns = 2500000; /* 400 Hz, the app's default rate */
    g_link_n = 0;
    g_busy_every = 0;
    g_writes = 0;
}

/* ---- the receiving end ---- */

typedef struct {
    fnav_wire_decoder_t dec;
    uint32_t by_type[6];
    uint32_t samples_ok;          /* echoed samples equal to what the IMU gave */
    uint32_t seq_breaks;          /* echoed samples whose seq is not the previous one's + 1 */
    uint32_t last_seq;            /* seq of the last echoed sample */
    fnav_wire_status_t last_status;
    fnav_wire_info_t info;
} rx_t;

static void receive(rx_t *rx)
{
    size_t pos = 0;
    fnav_wire_decoder_init(&rx->dec);
    memset(rx->by_type, 0, sizeof rx->by_type);
    rx->samples_ok = 0;
    rx->seq_breaks = 0;
    for (;;) {
        size_t used;
        fnav_wire_frame_t f;
        if (fnav_wire_decode(&rx->dec, g_link + pos, g_link_n - pos, &used, &f) != FNAV_OK) {
            break;
        }
        pos += used;
        assert_true(f.type >= 1 && f.type <= 5);
        rx->by_type[f.type]++;
        if (f.type == FNAV_WIRE_SAMPLE) {
            fnav_sample_t s, want;
            assert_int_equal(fnav_wire_parse_sample(&f, &s), FNAV_OK);
            want = make_sample(s.seq);
            if (s.t_ns == want.t_ns && s.accel_mps2[2] == want.accel_mps2[2] && s.gyro_rps[0] == want.gyro_rps[0]) {
                rx->samples_ok++;
            }
            rx->seq_breaks += rx->by_type[FNAV_WIRE_SAMPLE] > 1 && s.seq != rx->last_seq + 1u;
            rx->last_seq = s.seq;
        } else if (f.type == FNAV_WIRE_STATUS) {
            assert_int_equal(fnav_wire_parse_status(&f, &rx->last_status), FNAV_OK);
        } else if (f.type == FNAV_WIRE_INFO) {
            assert_int_equal(fnav_wire_parse_info(&f, &rx->info), FNAV_OK);
        }
    }
    assert_int_equal(pos, g_link_n);
    assert_int_equal(rx->dec.stats.bad_frames, 0);
}

/* ---- tests ---- */

static void test_config(void **state)
{
    static fnav_cm_app_t app;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    (void)state;
    reset_board();
    assert_int_equal(fnav_cm_app_init(&app, NULL), FNAV_E_ARG);
    cfg.rate_hz = FNAV_R(0.0);
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_E_CONFIG);
    cfg.rate_hz = (fnav_real_t)NAN;
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_E_CONFIG);
    cfg = fnav_cm_app_config_default;
    cfg.nav_rate_hz = -FNAV_R(1.0);
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_E_CONFIG);
    cfg = fnav_cm_app_config_default;
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    assert_int_equal(app.samples, 0);
}

/* Interrupts feed the ring; the main loop drains it through the port
 * layer, echoes every sample and reports its counters. */
static void test_isr_to_frames(void **state)
{
    static fnav_cm_app_t app;
    static rx_t rx;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    uint32_t i, processed = 0;
    (void)state;
    reset_board();
    cfg.sample_every = 1;
    cfg.status_every = 100;
    cfg.sensor = "test-board";
    cfg.sample_flags = FNAV_SAMPLE_HAS_SEQ; /* the test board's samples carry its counter */
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    assert_int_equal(fnav_cm_app_announce(&app), FNAV_OK);
    for (i = 0; i < 1000; i++) {
        fnav_cm_sample_isr(&app.port_ctx);
        if (i % 7 == 6) { /* the main loop runs now and then, several samples waiting */
            processed += fnav_cm_app_poll(&app);
        }
    }
    processed += fnav_cm_app_poll(&app);
    assert_int_equal(processed, 1000);
    assert_int_equal(app.samples, 1000);
    assert_int_equal(app.port_ctx.ring.overruns, 0);
    assert_int_equal(app.est_errors, 0); /* made-up samples: the filter never aligns, and nothing fails */
    receive(&rx);
    assert_int_equal(rx.by_type[FNAV_WIRE_INFO], 1);
    assert_string_equal(rx.info.sensor, "test-board");
    assert_true(rx.info.rate_hz == 400.0);
    assert_int_equal(rx.by_type[FNAV_WIRE_SAMPLE], 1000);
    assert_int_equal(rx.samples_ok, 1000);
    assert_int_equal(rx.by_type[FNAV_WIRE_STATUS], 10);
    assert_int_equal(rx.last_status.samples, 1000);
    /* a NAV frame for every nav_every-th navigation output (none without the filter) */
    assert_int_equal(rx.by_type[FNAV_WIRE_NAV], app.nav_outputs / cfg.nav_every);
    if (!(fnav_cm_est_built() & 1u)) {
        assert_int_equal(app.nav_outputs, 0);
    }
    assert_int_equal(rx.dec.stats.lost, 0);
    assert_int_equal(app.port_ctx.frames, 1 + 1000 + 10 + rx.by_type[FNAV_WIRE_NAV]);
    assert_true((rx.info.flags & FNAV_WIRE_INFO_SEQ) != 0u);
}

/* Every frame the filter releases is an output, also when one sample
 * releases several: with the detector's rate estimated (the default), the
 * first 33 samples' frames come out together, less the detector's delay.
 * An app counting one output per sample would never send the others (21
 * of the walk slice's first frames). Counted against
 * the filter driven directly. At 200 Hz: at the app's 400 Hz the host
 * build's detector delay (its ring of 64 lets min_zupt_cycle's look-ahead
 * reach 29 samples, with the default min_zupt_cycle) is 34 samples, longer
 * than the 33, and no sample releases several; the firmware's ring of 24
 * caps it at 22. */
static void test_every_frame_is_output(void **state)
{
    static fnav_cm_app_t app;
    static fnav_cm_est_t ref;
    static rx_t rx;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    fnav_nav_frame_t fr;
    uint32_t i, n_ref = 0, n_aligned = 0, burst = 0;
    const uint32_t n = 2000; /* 10 s at 200 Hz: aligns after max_still_s (5 s) */
    (void)state;
    if (!(fnav_cm_est_built() & 1u)) {
        skip();
    }
    reset_board();
    g_imu_still = 1;
    g_period_ns = 5000000;
    cfg.rate_hz = FNAV_R(200.0);
    assert_int_equal(fnav_cm_est_init(&ref, cfg.rate_hz, cfg.nav_rate_hz), FNAV_OK);
    for (i = 0; i < n; i++) {
        fnav_sample_t s = make_sample(i);
        uint32_t got = 0;
        assert_int_equal(fnav_nav_push(&ref.nav, &s), FNAV_OK);
        while (fnav_nav_pop(&ref.nav, &fr) == FNAV_OK) {
            got++;
            n_aligned += (fr.flags & FNAV_FRAME_ALIGNED) ? 1u : 0u;
        }
        n_ref += got;
        burst = got > burst ? got : burst;
    }
    assert_true(burst > 1u);       /* the case: one sample, several frames */
    assert_true(n_aligned > 500u); /* and the filter navigates: over half of the 5 s after the alignment */

    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    for (i = 0; i < n; i++) {
        fnav_cm_sample_isr(&app.port_ctx);
        (void)fnav_cm_app_poll(&app);
    }
    assert_int_equal(app.samples, n);
    assert_int_equal(app.est_errors, 0);
    assert_int_equal(app.nav_outputs, n_ref);
    receive(&rx);
    assert_int_equal(rx.by_type[FNAV_WIRE_NAV], n_ref / cfg.nav_every);
}

/* NAV frames every nav_every-th output keep the events of the others: a
 * stride or a ZUPT marks a single output, and the frames between two sent
 * took theirs with them (the bundled walk's 16 strides: 6 received at the
 * default N = 4, 1 at N = 40; the firmware audit). Against the navigator
 * driven directly: every stride is received, and a sent frame carries a
 * ZUPT exactly when one of the outputs since the last sent had one. */
static void test_events_of_unsent_frames(void **state)
{
    static fnav_cm_app_t app;
    static fnav_cm_est_t ref;
    static rx_t rx;
    static uint8_t ref_flags[20000];
    static const uint32_t every[3] = { 4u, 40u, 4u }; /* the third with a busy link */
    hx_log_t log;
    char err[256];
    fnav_nav_frame_t fr;
    uint32_t i, n_ref = 0, strides = 0, e;
    (void)state;
    if (!(fnav_cm_est_built() & 1u)) {
        skip();
    }
    assert_int_equal(hx_log_load(&log, "vectors/walk.bin", HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.n < sizeof ref_flags);
    reset_board();
    g_walk = &log;
    assert_int_equal(fnav_cm_est_init(&ref, FNAV_R(400.0), FNAV_R(0.0)), FNAV_OK);
    for (i = 0; i < (uint32_t)log.n; i++) {
        fnav_sample_t s = make_sample(i);
        assert_int_equal(fnav_nav_push(&ref.nav, &s), FNAV_OK);
        while (fnav_nav_pop(&ref.nav, &fr) == FNAV_OK) {
            ref_flags[n_ref++] = (uint8_t)fr.flags;
            strides += (fr.flags & FNAV_FRAME_STRIDE) ? 1u : 0u;
        }
    }
    assert_true(strides >= 10u); /* the case: a walk's strides */
    for (e = 0; e < 3; e++) {
        fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
        uint32_t want_zupt = 0, got_zupt = 0, got_stride = 0, k;
        size_t pos = 0;
        reset_board();
        g_walk = &log;
        cfg.nav_every = every[e];
        cfg.status_every = 0u;
        g_busy_every = e == 2 ? 3 : 0; /* every third frame refused: its events ride on the next one */
        assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
        for (i = 0; i < (uint32_t)log.n; i++) {
            fnav_cm_sample_isr(&app.port_ctx);
            (void)fnav_cm_app_poll(&app);
        }
        assert_int_equal(app.nav_outputs, n_ref);
        for (k = 0; k + every[e] <= n_ref && e < 2; k += every[e]) {
            uint32_t j, z = 0;
            for (j = k; j < k + every[e]; j++) {
                z |= ref_flags[j] & FNAV_FRAME_ZUPT;
            }
            want_zupt += z != 0u;
        }
        fnav_wire_decoder_init(&rx.dec);
        for (;;) {
            size_t used;
            fnav_wire_frame_t f;
            fnav_wire_nav_t nav;
            if (fnav_wire_decode(&rx.dec, g_link + pos, g_link_n - pos, &used, &f) != FNAV_OK) {
                break;
            }
            pos += used;
            if (f.type != FNAV_WIRE_NAV) {
                continue;
            }
            assert_int_equal(fnav_wire_parse_nav(&f, &nav), FNAV_OK);
            got_zupt += (nav.flags & FNAV_FRAME_ZUPT) ? 1u : 0u;
            got_stride += (nav.flags & FNAV_FRAME_STRIDE) ? 1u : 0u;
        }
        assert_int_equal(pos, g_link_n);
        assert_int_equal(got_stride, strides);
        if (e < 2) {
            assert_int_equal(got_zupt, want_zupt);
        }
    }
    hx_log_free(&log);
}

/* Every second sample echoed: the INFO frame announces the SAMPLE stream's
 * own rate (200 Hz) and no sensor counter, whose steps of 2 a receiver
 * would take for 1,999 lost samples in 4,000. */
static void test_sample_every_info(void **state)
{
    static fnav_cm_app_t app;
    static rx_t rx;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    uint32_t i;
    (void)state;
    reset_board();
    cfg.sample_every = 2;
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    assert_int_equal(fnav_cm_app_announce(&app), FNAV_OK);
    for (i = 0; i < 100; i++) {
        fnav_cm_sample_isr(&app.port_ctx);
        (void)fnav_cm_app_poll(&app);
    }
    receive(&rx);
    assert_int_equal(rx.by_type[FNAV_WIRE_INFO], 1);
    assert_true(rx.info.rate_hz == 200.0);
    assert_true((rx.info.flags & FNAV_WIRE_INFO_SEQ) == 0u);
    assert_int_equal(rx.by_type[FNAV_WIRE_SAMPLE], 50);
}

/* The INFO frame says what the board's samples carry, as the board
 * configured it (sample_flags): `harness live` takes the recording's
 * header from INFO, so a clear temperature bit discarded every temperature
 * the SAMPLE frames carried, and a set counter bit made a board without a
 * sensor counter report 0 counter drops as if it counted them (the
 * firmware audit: INFO flags 0x5 whatever the board). */
static void test_info_sample_flags(void **state)
{
    static const uint32_t flags[4] = { 0u, FNAV_SAMPLE_HAS_TEMP, FNAV_SAMPLE_HAS_SEQ,
                                       FNAV_SAMPLE_HAS_TEMP | FNAV_SAMPLE_HAS_SEQ };
    static fnav_cm_app_t app;
    static rx_t rx;
    int k, every;
    (void)state;
    for (every = 1; every <= 2; every++) {
        for (k = 0; k < 4; k++) {
            fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
            const uint32_t want_seq = (every == 1 && (flags[k] & FNAV_SAMPLE_HAS_SEQ)) ? FNAV_WIRE_INFO_SEQ : 0u;
            const uint32_t want_temp = (flags[k] & FNAV_SAMPLE_HAS_TEMP) ? FNAV_WIRE_INFO_TEMP : 0u;
            reset_board();
            cfg.sample_every = (uint32_t)every;
            cfg.sample_flags = flags[k];
            assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
            assert_int_equal(fnav_cm_app_announce(&app), FNAV_OK);
            receive(&rx);
            assert_int_equal(rx.by_type[FNAV_WIRE_INFO], 1);
            assert_int_equal(rx.info.flags, FNAV_WIRE_INFO_RATE_NOMINAL | want_seq | want_temp);
        }
    }
    /* the default: a board that has said nothing claims neither */
    assert_int_equal(fnav_cm_app_config_default.sample_flags, 0u);
    /* a bit the INFO frame cannot carry is a configuration error */
    {
        fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
        cfg.sample_flags = 0x4u;
        assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_E_CONFIG);
    }
}

/* A main loop that falls behind: the ring keeps the oldest samples, counts
 * the rest as overruns, and STATUS tells the receiver. */
static void test_ring_overrun(void **state)
{
    static fnav_cm_app_t app;
    static rx_t rx;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    uint32_t i;
    (void)state;
    reset_board();
    cfg.sample_every = 1;
    cfg.nav_every = 0; /* only the raw stream: this test is about the ring */
    cfg.status_every = FNAV_CM_RING_SIZE;
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    for (i = 0; i < FNAV_CM_RING_SIZE + 9u; i++) {
        fnav_cm_sample_isr(&app.port_ctx);
    }
    assert_int_equal(app.port_ctx.ring.overruns, 9);
    assert_int_equal(fnav_cm_app_poll(&app), FNAV_CM_RING_SIZE);
    receive(&rx);
    assert_int_equal(rx.by_type[FNAV_WIRE_SAMPLE], FNAV_CM_RING_SIZE);
    assert_int_equal(rx.samples_ok, FNAV_CM_RING_SIZE);
    assert_int_equal(rx.by_type[FNAV_WIRE_STATUS], 1);
    assert_int_equal(rx.last_status.overruns, 9);
    /* no IMU: the interrupt pushes nothing */
    g_imu_absent = 1;
    fnav_cm_sample_isr(&app.port_ctx);
    assert_int_equal(fnav_cm_app_poll(&app), 0);
}

/* A FIFO-watermark interrupt: fnav_cm_sample_isr_fifo reads the IMU until it
 * has no sample left or max were read, and pushes each; the main loop sees
 * them in order. fnav_cm_sample_isr reads one per interrupt, so such a board
 * would lose all but one sample of each batch with it. */
static void test_isr_fifo(void **state)
{
    static fnav_cm_app_t app;
    static rx_t rx;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    (void)state;
    reset_board();
    cfg.sample_every = 1;
    cfg.nav_every = 0;
    cfg.status_every = 0;
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    /* a batch of 12, all read at one interrupt */
    g_imu_fifo = 12;
    assert_int_equal(fnav_cm_sample_isr_fifo(&app.port_ctx, FNAV_CM_RING_SIZE), 12);
    assert_int_equal(g_imu_fifo, 0);
    assert_int_equal(fnav_cm_app_poll(&app), 12);
    /* more waiting than max: max read, the rest left in the FIFO */
    g_imu_fifo = 20;
    assert_int_equal(fnav_cm_sample_isr_fifo(&app.port_ctx, 8), 8);
    assert_int_equal(g_imu_fifo, 12);
    assert_int_equal(fnav_cm_sample_isr_fifo(&app.port_ctx, 0), 0);
    assert_int_equal(fnav_cm_sample_isr_fifo(&app.port_ctx, FNAV_CM_RING_SIZE), 12);
    assert_int_equal(fnav_cm_app_poll(&app), 20);
    /* more than the ring holds: each read sample past it is an overrun */
    g_imu_fifo = (long)FNAV_CM_RING_SIZE + 3;
    assert_int_equal(fnav_cm_sample_isr_fifo(&app.port_ctx, FNAV_CM_RING_SIZE + 3u), FNAV_CM_RING_SIZE + 3u);
    assert_int_equal(app.port_ctx.ring.overruns, 3);
    assert_int_equal(fnav_cm_app_poll(&app), FNAV_CM_RING_SIZE);
    /* no IMU: nothing read */
    g_imu_absent = 1;
    assert_int_equal(fnav_cm_sample_isr_fifo(&app.port_ctx, FNAV_CM_RING_SIZE), 0);
    receive(&rx);
    /* every sample the ring kept, in the IMU's order: the three dropped are
     * the newest (the ring keeps what it holds), so no break in seq */
    assert_int_equal(app.samples, 12 + 20 + FNAV_CM_RING_SIZE);
    assert_int_equal(rx.by_type[FNAV_WIRE_SAMPLE], 12 + 20 + FNAV_CM_RING_SIZE);
    assert_int_equal(rx.samples_ok, 12 + 20 + FNAV_CM_RING_SIZE);
    assert_int_equal(rx.seq_breaks, 0);
    assert_int_equal(rx.last_seq, 12 + 20 + FNAV_CM_RING_SIZE - 1);
}

/* The main loop's sleep (fnav_cm_port_wait, after fnav_cm_app_poll): a
 * sample that the interrupt pushed after the loop's last empty pop keeps
 * it awake. It slept until the next interrupt (fnav_cm_main.c polled, then
 * WFI: the firmware audit), one sample period late, or for ever without
 * another interrupt. On the M4 the check runs with interrupts masked
 * (PRIMASK), whose pending interrupt still ends WFI, so no push slips
 * between the check and the sleep; the host has no interrupt to mask. */
static void test_wait_after_late_sample(void **state)
{
    static fnav_cm_app_t app;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    (void)state;
    reset_board();
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    assert_int_equal(fnav_cm_app_poll(&app), 0);
    fnav_cm_sample_isr(&app.port_ctx); /* the interrupt, after the last empty pop */
    fnav_cm_port_wait(&app.port_ctx);
    assert_int_equal(g_idles, 0);
    assert_int_equal(fnav_cm_app_poll(&app), 1);
    fnav_cm_port_wait(&app.port_ctx); /* nothing waiting: sleep */
    assert_int_equal(g_idles, 1);
}

/* A busy link: the refused frames are counted by the sender and show up
 * as sequence gaps (drops) at the receiver. */
static void test_busy_link(void **state)
{
    static fnav_cm_app_t app;
    static rx_t rx;
    fnav_cm_app_config_t cfg = fnav_cm_app_config_default;
    uint32_t i;
    (void)state;
    reset_board();
    g_busy_every = 10;
    cfg.sample_every = 1;
    cfg.nav_every = 0; /* only the raw stream: this test is about the link */
    cfg.status_every = 0;
    assert_int_equal(fnav_cm_app_init(&app, &cfg), FNAV_OK);
    for (i = 0; i < 200; i++) {
        fnav_cm_sample_isr(&app.port_ctx);
        (void)fnav_cm_app_poll(&app);
    }
    assert_int_equal(app.port_ctx.tx_dropped, 20);
    receive(&rx);
    assert_int_equal(rx.by_type[FNAV_WIRE_SAMPLE], 180);
    /* frames 10, 20, ..., 200 were refused; the last one is the last frame
     * sent, so no later frame reveals it: 19 gaps of one frame */
    assert_int_equal(rx.dec.stats.lost, 19);
    assert_int_equal(rx.dec.stats.gaps, 19);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_config),
        cmocka_unit_test(test_isr_to_frames),
        cmocka_unit_test(test_sample_every_info),
        cmocka_unit_test(test_info_sample_flags),
        cmocka_unit_test(test_every_frame_is_output),
        cmocka_unit_test(test_events_of_unsent_frames),
        cmocka_unit_test(test_ring_overrun),
        cmocka_unit_test(test_isr_fifo),
        cmocka_unit_test(test_busy_link),
        cmocka_unit_test(test_wait_after_late_sample),
    };
    return cmocka_run_group_tests_name("cm_app", tests, NULL, NULL);
}
