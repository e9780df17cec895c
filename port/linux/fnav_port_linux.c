/* Linux port: file replay source, CSV sink, monotonic clock, stderr log. */
#include "fnav_port_linux.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static fnav_status_t linux_read(void *ctx, fnav_sample_t *sample)
{
    fnav_linux_port_ctx_t *c = (fnav_linux_port_ctx_t *)ctx;
    fnav_status_t st;
    if (c->reader == NULL) {
        return FNAV_END;
    }
    st = hx_reader_next(c->reader, sample);
    c->last_status = st;
    if (st == FNAV_OK) {
        if (!c->have_t0) {
            c->t0_ns = sample->t_ns;
            c->have_t0 = 1;
        }
        c->samples++;
    }
    return st;
}

static int64_t linux_now_ns(void *ctx)
{
    struct timespec ts;
    (void)ctx;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

static fnav_status_t linux_write_nav(void *ctx, const fnav_nav_frame_t *f)
{
    fnav_linux_port_ctx_t *c = (fnav_linux_port_ctx_t *)ctx;
    int i;
    if (c->nav_csv == NULL) {
        c->frames++;
        return FNAV_OK;
    }
    /* errno is set only by a failed call: cleared here, it is the reason of
     * this frame's failed write, kept before anything else can change it
     * (so the message gives the reason, not only "cannot write the
     * trajectory to /dev/full") */
    errno = 0;
    if (!c->header_written) {
        fprintf(c->nav_csv, "%s\n", FNAV_LINUX_NAV_CSV_HEADER);
        c->header_written = 1;
    }
    fprintf(c->nav_csv, "%.6f", (double)(f->t_ns - c->t0_ns) * 1e-9);
    for (i = 0; i < 3; i++) {
        fprintf(c->nav_csv, ",%.6f", (double)f->pos_m[i]);
    }
    for (i = 0; i < 3; i++) {
        fprintf(c->nav_csv, ",%.6f", (double)f->vel_mps[i]);
    }
    for (i = 0; i < 3; i++) {
        fprintf(c->nav_csv, ",%.6f", (double)f->euler_rad[i]);
    }
    for (i = 0; i < 3; i++) {
        fprintf(c->nav_csv, ",%.4e", (double)f->gyro_bias_rps[i]);
    }
    for (i = 0; i < 3; i++) {
        fprintf(c->nav_csv, ",%.4e", (double)f->accel_bias_mps2[i]);
    }
    fprintf(c->nav_csv, ",%u,%u,%lu", (f->flags & FNAV_FRAME_STANCE) ? 1u : 0u, (f->flags & FNAV_FRAME_ZUPT) ? 1u : 0u,
            (unsigned long)f->health);
    for (i = 0; i < 15; i++) {
        fprintf(c->nav_csv, ",%.4e", (double)f->p_diag[i]);
    }
    for (i = 0; i < 3; i++) {
        fprintf(c->nav_csv, ",%.4f", (double)f->lever_m[i]);
    }
    /* last, so that the columns before it keep their places: 0 before the
     * alignment and while re-aligning after a reset (the state columns
     * then hold 0 or the held position and heading) */
    fprintf(c->nav_csv, ",%u", (f->flags & FNAV_FRAME_ALIGNED) ? 1u : 0u);
    /* a full disk shows when the buffer is flushed: ferror is sticky */
    if (fputc('\n', c->nav_csv) == EOF || ferror(c->nav_csv)) {
        if (c->write_errno == 0) {
            c->write_errno = errno;
        }
        return FNAV_E_IO;
    }
    c->frames++;
    return FNAV_OK;
}

static void linux_log(void *ctx, fnav_log_level_t level, const char *msg)
{
    fnav_linux_port_ctx_t *c = (fnav_linux_port_ctx_t *)ctx;
    static const char *const names[] = { "debug", "info", "warning", "error" };
    if (level < c->min_level) {
        return;
    }
    /* a level outside the enum (a caller's cast) is printed as an error */
    fprintf(stderr, "%s: %s\n", (unsigned)level < 4u ? names[level] : "error", msg);
}

void fnav_linux_port_init(fnav_port_t *port, fnav_linux_port_ctx_t *ctx, hx_reader_t *reader, FILE *nav_csv)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->reader = reader;
    ctx->nav_csv = nav_csv;
    ctx->min_level = FNAV_LOG_INFO;
    ctx->last_status = FNAV_OK;
    port->ctx = ctx;
    port->read_sample = linux_read;
    port->now_ns = linux_now_ns;
    port->write_nav = linux_write_nav;
    port->log = linux_log;
}

FNAV_NORETURN void fnav_port_assert_failed(const char *file, int line, const char *expr)
{
    fprintf(stderr, "footnav: assertion failed at %s:%d: %s\n", file, line, expr);
    abort();
}
