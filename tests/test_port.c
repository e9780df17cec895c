/* The port layer: call helpers, status strings, the Linux replay port and
 * the Cortex-M SPSC ring buffer (compiled for the host). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "footnav/fnav_port.h"
#include "fnav_port_linux.h"
#include "fnav_testdata.h"
#include "fnav_cm_ring.h"

static void test_status_strings(void **state)
{
    int s;
    (void)state;
    for (s = -14; s <= 2; s++) {
        const char *t = fnav_status_str((fnav_status_t)s);
        assert_non_null(t);
        assert_true(strlen(t) > 1);
        assert_string_not_equal(t, "unknown status");
    }
    assert_string_equal(fnav_status_str((fnav_status_t)-99), "unknown status");
    /* each status its own text: a mutant giving FNAV_E_CRC the text of
     * FNAV_E_FORMAT ("malformed input") passed every suite, and a message
     * would have named the wrong failure */
    for (s = -14; s <= 2; s++) {
        int u;
        for (u = s + 1; u <= 2; u++) {
            assert_string_not_equal(fnav_status_str((fnav_status_t)s), fnav_status_str((fnav_status_t)u));
        }
    }
}

static void test_port_helpers_null(void **state)
{
    fnav_port_t p;
    fnav_sample_t s;
    fnav_nav_frame_t f;
    (void)state;
    memset(&p, 0, sizeof p);
    memset(&f, 0, sizeof f);
    assert_int_equal(fnav_port_read(NULL, &s), FNAV_E_ARG);
    assert_int_equal(fnav_port_read(&p, &s), FNAV_E_UNSUPPORTED);
    assert_int_equal(fnav_port_write_nav(&p, &f), FNAV_OK);
    assert_int_equal(fnav_port_write_nav(&p, NULL), FNAV_E_ARG);
    assert_true(fnav_port_now_ns(&p) == 0);
    fnav_port_log(&p, FNAV_LOG_ERROR, "dropped: no hook");
    fnav_port_log(NULL, FNAV_LOG_ERROR, "dropped: no port");
}

/* The Linux port replays a log sample by sample and writes frames as CSV. */
static void test_linux_replay_port(void **state)
{
    char p[512], err[320], line[1024];
    hx_reader_t *r;
    fnav_port_t port;
    fnav_linux_port_ctx_t ctx;
    fnav_sample_t s;
    fnav_nav_frame_t f;
    FILE *out = tmpfile();
    int n = 0;
    int64_t t0, t1;
    (void)state;
    assert_int_equal(fnav_vector_path("logformat/sample_v1.bin", p, sizeof p), 0);
    r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_non_null(r);
    assert_non_null(out);
    fnav_linux_port_init(&port, &ctx, r, out);
    memset(&f, 0, sizeof f);
    while (fnav_port_read(&port, &s) == FNAV_OK) {
        f.t_ns = s.t_ns;
        f.pos_m[0] = (fnav_real_t)n;
        assert_int_equal(fnav_port_write_nav(&port, &f), FNAV_OK);
        n++;
    }
    assert_int_equal(n, 6);
    assert_int_equal(ctx.samples, 6);
    assert_int_equal(ctx.frames, 6);
    assert_int_equal(ctx.last_status, FNAV_END);
    t0 = fnav_port_now_ns(&port);
    t1 = fnav_port_now_ns(&port);
    assert_true(t1 >= t0 && t0 > 0);
    rewind(out);
    assert_non_null(fgets(line, sizeof line, out));
    assert_memory_equal(line, "t,x,y,z,", 8);
    n = 0;
    while (fgets(line, sizeof line, out) != NULL) {
        n++;
    }
    assert_int_equal(n, 6);
    fclose(out);
    {
        /* a level outside the enum is printed as an error (it indexed past
         * the names: a review, 2026-11-28; ASan's global-buffer-overflow) */
        FILE *cap = tmpfile();
        int fd = dup(2);
        assert_non_null(cap);
        assert_true(fd >= 0);
        fflush(stderr);
        assert_true(dup2(fileno(cap), 2) >= 0);
        fnav_port_log(&port, (fnav_log_level_t)7, "level seven");
        fflush(stderr);
        assert_true(dup2(fd, 2) >= 0);
        close(fd);
        rewind(cap);
        assert_non_null(fgets(line, sizeof line, cap));
        assert_string_equal(line, "error: level seven\n");
        fclose(cap);
    }
    hx_reader_close(r);
}

/* SPSC ring: FIFO order, wrap-around of the indices, overrun counting. */
static void test_cm_ring(void **state)
{
    static fnav_cm_ring_t ring;
    fnav_sample_t s, o;
    uint32_t i;
    int k;
    (void)state;
    fnav_cm_ring_init(&ring);
    memset(&s, 0, sizeof s);
    assert_int_equal(fnav_cm_ring_pop(&ring, &o), 0);
    ring.head = ring.tail = 0xfffffff0u; /* exercise index wrap */
    for (k = 0; k < 5; k++) {
        for (i = 0; i < FNAV_CM_RING_SIZE; i++) {
            s.seq = (uint32_t)k * 1000u + i;
            assert_int_equal(fnav_cm_ring_push(&ring, &s), 0);
        }
        s.seq = 999999u;
        assert_int_equal(fnav_cm_ring_push(&ring, &s), -1);
        for (i = 0; i < FNAV_CM_RING_SIZE; i++) {
            assert_int_equal(fnav_cm_ring_pop(&ring, &o), 1);
            assert_int_equal(o.seq, (uint32_t)k * 1000u + i);
        }
        assert_int_equal(fnav_cm_ring_pop(&ring, &o), 0);
    }
    assert_int_equal(ring.overruns, 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_status_strings),
        cmocka_unit_test(test_port_helpers_null),
        cmocka_unit_test(test_linux_replay_port),
        cmocka_unit_test(test_cm_ring),
    };
    return cmocka_run_group_tests_name("port", tests, NULL, NULL);
}
