/* harness stream: play a log out over a serial port in the wire protocol
 * (docs/wire-protocol.md), at the pace of its time stamps, so a desk test of
 * `harness live` (or of any receiver) needs no sensor. */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "footnav/fnav_wire.h"
#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_serial.h"

#define CMD "stream"
#define WRITE_TIMEOUT_MS 10000u

static const hx_opt_t k_opts[] = {
    HX_INPUT_OPTS,
    { "--baud", "N", "baud rate, 8N1 (default 460800)", 0 },
    { "--rate", "HZ", "send HZ samples per second instead of following the time stamps", 0 },
    { "--speed", "X", "play X times faster than real time (default 1; 0: as fast as the port takes it)", 0 },
    { "--inject-corrupt", "N", "test: flip one payload bit of every N-th sample frame", 0 },
    { "--inject-drop", "N", "test: leave out every N-th sample frame (its sequence number is used up)", 0 },
    { "--hangup-after", "N", "test: close the port after N samples without an END frame", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    CMD, "LOG PORT [options]",
    "Play LOG out over the serial port PORT in the footnav wire protocol\n"
    "(docs/wire-protocol.md): an INFO frame (rate, sensor), one SAMPLE frame per\n"
    "sample at the pace of the log's time stamps (or --rate), and an END frame.\n"
    "The other end is `harness live PORT`. The --inject-* and --hangup-after\n"
    "options damage the stream on purpose to test a receiver.\n"
    "Exit status: 0 sent, 1 the log was bad (every sample before the error was\n"
    "sent), 2 usage, 3 the port could not be opened or stopped accepting data,\n"
    "130 (143, 129) interrupted by Ctrl-C (SIGTERM, SIGHUP) before the END frame.",
    2, 2, k_opts
};

static volatile sig_atomic_t g_stop, g_abort;

static void on_signal(int sig)
{
    if (g_stop) {
        g_abort = 1; /* a second signal: stop writing what is already queued */
    }
    g_stop = sig; /* the signal, for the exit status */
}

/* Sleep until t (hx_now_s's clock), in slices of at most 1 s: a wait of
 * any length (a slow --speed on a long gap) never casts a huge double to
 * time_t, and a signal ends it */
static void sleep_until(double t)
{
    double now;
    while (!g_stop && (now = hx_now_s()) < t) {
        const double d = (t - now < 1.0) ? t - now : 1.0;
        struct timespec ts;
        ts.tv_sec = (time_t)d;
        ts.tv_nsec = (long)((d - (double)ts.tv_sec) * 1e9);
        (void)nanosleep(&ts, NULL); /* EINTR: the loop looks at g_stop */
    }
}

/* Frames wait in a buffer until the next sample is due later, so a fast
 * pace costs one write per batch instead of one per sample. */
typedef struct {
    hx_serial_t *port;
    uint8_t buf[8192];
    size_t n;
    uint16_t seq;
    int failed;
    int cut;                 /* a write was stopped by a signal: that batch was not all sent */
} tx_t;

/* Write the batch. *stop ends a write that the port does not take (a
 * receiver that does not read): g_stop while samples are being sent, g_abort
 * (a second signal) for the last batch, which a first signal does not cut. */
static int tx_flush(tx_t *tx, const volatile sig_atomic_t *stop)
{
    if (tx->n > 0u && !tx->failed && !tx->cut) {
        int r = hx_serial_write(tx->port, tx->buf, tx->n, WRITE_TIMEOUT_MS, stop);
        if (r < 0) {
            hx_error(CMD, "%s", hx_serial_error(tx->port));
            tx->failed = 1;
        } else if (r > 0) {
            tx->cut = 1;
        }
    }
    tx->n = 0u;
    return (tx->failed || tx->cut) ? -1 : 0;
}

/* Room for one more frame of the largest size (stop: as tx_flush's). */
static uint8_t *tx_room(tx_t *tx, const volatile sig_atomic_t *stop)
{
    if (sizeof tx->buf - tx->n < FNAV_WIRE_MAX_FRAME) {
        (void)tx_flush(tx, stop);
    }
    return tx->buf + tx->n;
}

/* 1 when the number text has a non-zero digit before its exponent (a
 * value that strtod read as 0 by underflow, not a zero) */
static int nonzero_mantissa(const char *t)
{
    for (; *t != '\0' && *t != 'e' && *t != 'E'; t++) {
        if (*t >= '1' && *t <= '9') {
            return 1;
        }
    }
    return 0;
}

int hx_cmd_stream(int argc, char **argv)
{
    hx_args_t a;
    hx_log_t log;
    tx_t tx;
    long baud = 460800, corrupt = 0, drop = 0, hangup = 0;
    double rate = 0.0, speed = 1.0, t_start, need_bps;
    char err[HX_ERR_SIZE];
    int rc = hx_args_parse(&k_spec, argc, argv, &a), loaded;
    int exit_code = HX_EXIT_OK;
    size_t i;
    uint32_t sent = 0, left_out = 0; /* samples encoded (END's count); of them never written (--inject-drop) */
    int end_queued = 0;
    hx_progress_t prog;
    struct sigaction sa;

    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    if (hx_check_input_opts(CMD, &a) != 0 || hx_arg_long(&a, "--baud", 50, 20000000, &baud) != 0 ||
        hx_arg_double(&a, "--rate", 1e-3, 1e6, &rate) != 0 || hx_arg_double(&a, "--speed", 0.0, 1e6, &speed) != 0 ||
        hx_arg_long(&a, "--inject-corrupt", 1, 1000000000L, &corrupt) != 0 ||
        hx_arg_long(&a, "--inject-drop", 1, 1000000000L, &drop) != 0 ||
        hx_arg_long(&a, "--hangup-after", 1, 2000000000L, &hangup) != 0) {
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--rate") != NULL && hx_arg(&a, "--speed") != NULL) {
        hx_error(CMD, "--rate and --speed exclude each other");
        return HX_EXIT_USAGE;
    }
    if (hx_arg(&a, "--speed") != NULL && (speed > 0.0 ? speed < 1e-3 : nonzero_mantissa(hx_arg(&a, "--speed")))) {
        /* a speed so small that the wait overflowed played at full speed;
         * one below the smallest double (1e-400) read as 0, full speed */
        hx_error(CMD, "--speed %s: give 0 (as fast as the port takes it) or at least 0.001", hx_arg(&a, "--speed"));
        return HX_EXIT_USAGE;
    }
    {
        /* a serial port or terminal given as the log (the arguments swapped:
         * live takes PORT first) would be read as a log for ever */
        struct stat st;
        if (stat(a.pos[0], &st) == 0 && S_ISCHR(st.st_mode)) {
            hx_error(CMD, "%s is a character device (a terminal, a serial port), not a log: the order is `harness stream LOG PORT`",
                     a.pos[0]);
            return HX_EXIT_USAGE;
        }
    }

    loaded = hx_load_input(CMD, &a, a.pos[0], &log);
    if (loaded < 0) {
        return HX_EXIT_DATA;
    }
    if (log.n == 0) {
        hx_error(CMD, "%s: no samples to send", a.pos[0]);
        hx_log_free(&log);
        return HX_EXIT_DATA;
    }
    if (hangup > 0 && (size_t)hangup > log.n) {
        hx_warn(CMD, "--hangup-after %ld: %s has %zu samples, which end first, with the END frame", hangup, a.pos[0],
                log.n);
    }

    memset(&tx, 0, sizeof tx);
    tx.port = hx_serial_open(a.pos[1], (int)baud, HX_SERIAL_WRITE, err, sizeof err);
    if (tx.port == NULL) {
        hx_error(CMD, "%s", err);
        hx_log_free(&log);
        return HX_EXIT_IO;
    }
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    /* SA_RESTART: a signal that lands inside the kernel's write to the tty
     * (before any byte went) restarts that write instead of failing it with
     * EINTR, which libserialport reports as "write() failed" (exit 3, as if
     * the port had gone; a CI run hit it by chance, tests/cli/eintr_seam.c
     * puts it there). The handler only sets g_stop: the writes go in slices
     * of at most 100 ms (hx_serial_write), nanosleep is never restarted, so
     * the signal is seen as soon as without the flag. */
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL); /* as live: its terminal closed (it died without a summary) */
    signal(SIGPIPE, SIG_IGN);

    /* 10 bits per byte on an 8N1 line */
    {
        double dur = (double)(log.t_ns[log.n - 1] - log.t_ns[0]) * 1e-9;
        double sps = (rate > 0.0) ? rate : ((dur > 0.0) ? (double)(log.n - 1) / dur * speed : 0.0);
        need_bps = sps * (double)FNAV_WIRE_FRAME_SIZE(FNAV_WIRE_SAMPLE_LEN) * 10.0;
        if (speed > 0.0 && need_bps > (double)baud) {
            hx_warn(CMD, "%.0f samples/s need %.0f baud; at %ld baud a real UART falls behind (a pty does not care)",
                    sps, need_bps, baud);
        }
    }

    {
        fnav_wire_info_t info;
        memset(&info, 0, sizeof info);
        info.rate_hz = log.meta.rate_hz;
        if (!(info.rate_hz >= 0.0 && info.rate_hz <= 1.0e6)) {
            /* a rate the protocol refuses (stamps so dense they imply MHz):
             * sent as 0, unknown, as the .bin writer stores it; a receiver
             * refused the INFO frame and called the stream incomplete */
            hx_warn(CMD, "%s: the log's rate %g Hz is beyond the wire protocol's 1e6 Hz; the INFO frame gives it as 0 "
                    "(unknown), the samples keep their stamps", a.pos[0], info.rate_hz);
            info.rate_hz = 0.0;
        }
        info.flags = (log.meta.rate_nominal && info.rate_hz > 0.0 ? FNAV_WIRE_INFO_RATE_NOMINAL : 0u) |
                     (log.meta.has_temp ? FNAV_WIRE_INFO_TEMP : 0u) | (log.meta.has_seq ? FNAV_WIRE_INFO_SEQ : 0u);
        snprintf(info.sensor, sizeof info.sensor, "%s", log.meta.sensor);
        snprintf(info.axes, sizeof info.axes, "%s", log.meta.axes);
        tx.n += fnav_wire_encode_info(tx_room(&tx, &g_stop), FNAV_WIRE_MAX_FRAME, tx.seq++, &info); /* empty: no flush */
    }

    hx_progress_start(&prog, "harness stream", (double)log.n);
    t_start = hx_now_s();
    for (i = 0; i < log.n && !g_stop && !tx.failed && !tx.cut; i++) {
        fnav_sample_t s;
        double due;
        uint8_t *f;
        size_t k;
        int j;
        if (hangup > 0 && (long)i == hangup) {
            break;
        }
        if (rate > 0.0) {
            due = t_start + (double)i / rate;
        } else if (speed > 0.0) {
            due = t_start + (double)(log.t_ns[i] - log.t_ns[0]) * 1e-9 / speed;
        } else {
            due = 0.0;
        }
        if (due > hx_now_s() + 5e-4) {
            if (tx_flush(&tx, &g_stop) != 0) {
                break;
            }
            sleep_until(due);
            if (g_stop) {
                break; /* a signal in the wait: this sample was not due yet */
            }
        }
        memset(&s, 0, sizeof s);
        s.t_ns = log.t_ns[i];
        s.seq = log.seq[i];
        s.flags = log.meta.has_seq ? FNAV_SAMPLE_HAS_SEQ : 0u;
        for (j = 0; j < 3; j++) {
            s.accel_mps2[j] = (fnav_real_t)log.acc[i][j];
            s.gyro_rps[j] = (fnav_real_t)log.gyr[i][j];
        }
        if (log.temp != NULL && log.temp[i] == log.temp[i]) {
            s.temp_c = (fnav_real_t)log.temp[i];
            s.flags |= FNAV_SAMPLE_HAS_TEMP;
        }
        f = tx_room(&tx, &g_stop);
        k = fnav_wire_encode_sample(f, FNAV_WIRE_MAX_FRAME, tx.seq++, &s);
        sent++;
        if (drop > 0 && sent % (uint32_t)drop == 0u) {
            left_out++;
            continue; /* never sent: the receiver sees the seq gap */
        }
        if (corrupt > 0 && sent % (uint32_t)corrupt == 0u) {
            f[FNAV_WIRE_HEADER_SIZE + 20u] ^= 0x08u; /* a bit inside acc y */
        }
        tx.n += k;
        hx_progress_update(&prog, (double)(i + 1));
    }
    if (!tx.failed && !tx.cut && !g_stop && !(hangup > 0 && (long)i == hangup)) {
        /* tx_room() may flush the batch and reset tx.n: called in a statement
         * of its own, since in `tx.n += encode(tx_room(&tx), ...)` C99 leaves
         * open whether tx.n is read before the call (then the END frame went
         * out with the batch already sent; gcc and clang read it after) */
        uint8_t *end_at = tx_room(&tx, &g_abort); /* every sample is encoded: the last batches */
        tx.n += fnav_wire_encode_end(end_at, FNAV_WIRE_MAX_FRAME, tx.seq++, sent);
        end_queued = 1;
    }
    if (tx_flush(&tx, &g_abort) == 0 && hx_serial_drain(tx.port) != 0) {
        hx_error(CMD, "%s", hx_serial_error(tx.port));
        tx.failed = 1;
    }
    if (end_queued && !tx.failed && !tx.cut) {
        /* every sample and the END frame went out: a signal that came while
         * the last batch drained interrupted nothing (no exit 130 while the
         * receiver has the END frame and every sample) */
        g_stop = 0;
    }
    if (tx.failed || tx.cut || g_stop) {
        /* not "done in 1.6 s" after the port's error, as if the log had
         * gone out: the line redrawn in place is ended, and the summary
         * below says what was sent */
        hx_line_break();
    } else {
        hx_progress_end(&prog);
    }
    hx_serial_close(tx.port);

    {
        /* the samples left out on purpose are counted in END (the receiver
         * sees them missing) but never written: said so (not "N samples
         * sent" with all N left out) */
        char dropped[96] = "";
        if (left_out > 0u) {
            snprintf(dropped, sizeof dropped, " (%u of them left out by --inject-drop, %u written)",
                     (unsigned)left_out, (unsigned)(sent - left_out));
        }
        printf("stream: %u samples %s %s%s in %.1f s%s%s\n", (unsigned)sent,
               tx.failed ? "encoded (the port failed before all were written) for"
                         : (tx.cut ? "encoded (the interrupt cut the write of the last batch) for" : "sent to"),
               a.pos[1], dropped, hx_now_s() - t_start,
               (hangup > 0 && (long)i == hangup) ? " (hung up on purpose, no END frame)" : "",
               g_stop ? " (interrupted)" : "");
    }
    if (tx.failed) {
        exit_code = HX_EXIT_IO;
    } else if (g_stop) {
        exit_code = 128 + (int)g_stop; /* as the shell reports a command a signal ended: not all was sent */
    } else if (loaded == 1) {
        exit_code = HX_EXIT_DATA; /* the reader's error was printed by hx_load_input */
    }
    hx_log_free(&log);
    return exit_code;
}
