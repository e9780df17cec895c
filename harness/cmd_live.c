/* harness live: navigate live from a serial port (docs/wire-protocol.md,
 * docs/harness.md). Reads wire frames through libserialport, records every
 * received sample to a .bin that stays valid if the process is killed, runs
 * the navigation filter on every sample exactly as `harness replay` does
 * (fnav_nav_push / pop, then finish at the end), and prints the position and
 * the stance state. */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fnav_port_linux.h"
#include <cjson/cJSON.h>

#include "footnav/fnav_wire.h"
#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_nav.h"
#include "hx_serial.h"
#include "hx_profile.h"

#define CMD "live"
#define READ_TIMEOUT_MS 100u
/* A line quiet this long has no frame in flight: the decoder gives out the
 * frames it holds behind an incomplete candidate (fnav_wire_decode_flush;
 * a frame takes 1 ms at 460800 baud). */
#define IDLE_FLUSH_S 1.0
#define RECENT_N 64 /* accepted samples remembered to recognise a late copy (0.16 s at 400 Hz) */
/* Samples in a row stamped behind the last one while the frame sequence
 * goes on: then not a stamp out of order but the sender's clock gone back */
#define BACK_RUN_MAX 8
#define MAX_WARNINGS 20
/* A status line says how long no frame has come once it is this long: a
 * sender that stopped with the port still open (a pty whose writer went, a
 * sensor that hung) would otherwise look like a steady one */
#define QUIET_NOTE_S 1.0
#define PLOT_SECONDS 10.0

static const hx_opt_t k_opts[] = {
    { "--baud", "N", "baud rate, 8N1 (default 460800)", 0 },
    { "--record", "FILE", "record every received sample to FILE (.bin; valid even if killed)", 0 },
    { "--plot-every", "S", "redraw the plot every S seconds", 0 },
    { "--plot", "FILE", "PNG redrawn every --plot-every seconds (default live.png; given alone: every 1 s)", 0 },
    { "--timeout", "S", "give up when no valid frame arrives for S seconds (default: wait forever)", 0 },
    { "--print-every", "S", "status line period, s (default 1; 0: only the summary)", 0 },
    { "--out", "FILE", "trajectory CSV, the columns of `harness replay --out` ('-': standard output)", 0 },
    { "--json", "FILE", "summary as JSON, the keys of `harness replay --json` and the link's counters", 0 },
    HX_NAV_OPTS(NULL),
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    CMD, "PORT [options]",
    "Read the footnav wire protocol (docs/wire-protocol.md) from the serial port\n"
    "PORT, record every received sample, run the navigation filter on it as\n"
    "`harness replay` does, and print the position and stance state. Corrupt\n"
    "frames are skipped and counted; a gap in the frame sequence numbers is\n"
    "reported as a drop. The run ends at the sender's END frame, on Ctrl-C, or\n"
    "when the port disappears (the recording stays intact in every case).\n"
    "Exit status: 0 complete (END and every sample, or Ctrl-C with no frame\n"
    "lost), 1 samples were lost or refused (drops, bad frames, bad samples, a\n"
    "bad INFO frame), none arrived, the sender restarted, the port went away or\n"
    "--timeout ran out, 2 usage, 3 the port, the recording or an output could\n"
    "not be opened or written.",
    1, 1, k_opts
};

static volatile sig_atomic_t g_stop;
/* The handler after the first signal: without SA_RESTART. The first is
 * installed with SA_RESTART, so that a write it lands in (the trajectory
 * to a slow reader of --out -, whose pipe is full) goes on: interrupted,
 * the write would fail, and the run would exit 3 with the rows not yet
 * written lost. A second signal interrupts such a
 * write, for a reader that never reads. The receive loop stops on either:
 * libserialport's read waits in slices of READ_TIMEOUT_MS. */
static struct sigaction g_sa_second;

static void on_signal(int sig)
{
    if (!g_stop) {
        sigaction(SIGINT, &g_sa_second, NULL);
        sigaction(SIGTERM, &g_sa_second, NULL);
        sigaction(SIGHUP, &g_sa_second, NULL);
    }
    g_stop = sig; /* named in the summary */
}

/* Recent signal magnitudes for the plot (a ring of PLOT_SECONDS). */
typedef struct {
    double *t, *a, *w;
    size_t cap, head, n;
} hist_t;

typedef struct {
    /* link */
    fnav_wire_decoder_t dec;
    fnav_wire_stats_t last_stats; /* to report what changed */
    uint32_t by_type[6];
    uint32_t bad_samples;         /* CRC-valid SAMPLE frames with NaN/Inf or out of range */
    uint32_t noise;               /* corrupt candidates between two valid frames whose sequence numbers
                                   * follow on: line noise, no frame lost */
    uint32_t cut;                 /* the candidate the stop (a signal) cut short: a frame on its way */
    uint32_t idle_cut;            /* the candidate a quiet line's flush ended, no frame after it yet: cut
                                     if the run stops so (a sensor switched off mid-frame), else corrupt */
    uint32_t repeated;            /* SAMPLE frames received twice (same frame seq and sample), skipped */
    uint32_t seq_repeats;         /* frames whose seq repeats the previous one's (the decoder counts a restart) */
    /* the last RECENT_N accepted samples' frame seq, time and counter: a
     * copy of one of them arriving late (a link's stale repetition) is
     * skipped, not taken for the sender's restart that ends the run */
    struct {
        unsigned frame_seq;
        int64_t t_ns;
        uint32_t seq;
        uint32_t crc;             /* of the payload: a copy is the same bytes */
    } recent[RECENT_N];
    unsigned n_recent;
    unsigned prev_frame_seq;      /* seq of the last valid frame */
    int have_prev_frame;
    unsigned last_frame_seq;      /* frame seq of the last recorded sample */
    uint32_t last_crc;            /* its payload's CRC */
    uint32_t last_sample_seq;     /* its sample counter */
    uint32_t bad_info;            /* INFO frames with an impossible rate */
    long baud;                    /* --baud */
    int told_baud;                /* the INFO rate's need of baud was said */
    /* samples the sender lost (its ring overran): gaps in the sensor's own
     * counter that the link's losses do not explain (a lower bound) */
    uint32_t sensor_missing, sensor_gaps;
    uint32_t lost_at_last, bad_at_last; /* link counters at the last accepted sample */
    int have_sensor_seq;          /* the last accepted sample carried the sensor's counter */
    int have_info, have_end, have_status;
    int restarted;                /* a sample went back in time: the sender restarted */
    int clock_back;               /* ... with the frame sequence going on (BACK_RUN_MAX stamps behind) */
    double restart_from_s, restart_to_s;
    unsigned restart_seq;
    /* the last sample accepted is held back by one sample before it is
     * navigated and recorded: a stamp far ahead of the samples on both sides
     * is known only at the next sample, and is dropped then (recorded, it
     * made every later sample "time goes back") */
    fnav_sample_t held;
    int have_held;
    /* the last three samples accepted, newest first (the held one, P
     * before it, and the one before P), for which of two is out of order */
    struct {
        int64_t t_ns;
        unsigned fseq;
        uint32_t epoch;           /* the sequence restarts before it */
    } acc[3];
    unsigned n_acc;
    /* samples stamped behind the held one, set aside: BACK_RUN_MAX of them
     * rising after P mean the held one was ahead (taken back then) */
    struct {
        fnav_sample_t s;
        unsigned fseq;
        uint32_t crc;
        uint32_t lost;            /* the link's lost frames when it came */
    } run[BACK_RUN_MAX];
    uint32_t restarts_at_last;    /* the decoder's true sequence restarts when the last sample was accepted */
    uint32_t bad_stamps;          /* samples dropped for a time stamp out of order (in bad_samples too) */
    uint32_t back_run;            /* samples in a row stamped behind the last, frame sequence going on */
    uint32_t samples_at_restart;  /* samples accepted before the last sequence restart */
    int have_seq_restart;
    /* the INFO frame the recording's header was written with */
    fnav_wire_info_t hdr_info;
    int hdr_has_info;
    int rate_changed;             /* an INFO frame changed the rate during the session */
    int told_name;                /* control characters in the INFO's text were said */
    int told_temp;                /* a temperature the INFO in force denies was said (and discarded) */
    int told_unknown;             /* a frame of a type this receiver does not know was said */
    /* what the recorded samples carried, for the header's bits 1 and 2 at
     * the end: a temperature (under an INFO that announced it, or before
     * any INFO), and a sample without the sensor counter the INFO announces */
    int temp_recorded, seq_undeclared;
    int hdr_has_temp, hdr_has_seq; /* the header's bits 1 and 2 as written at the first sample */
    int traj_partial;             /* out of memory: the summary covers the first outputs */
    fnav_wire_info_t info;
    fnav_wire_status_t status;
    uint32_t end_count;
    int warnings;
    /* samples */
    uint32_t samples;
    uint32_t recorded;            /* samples the recording took (it stops at a write error) */
    int64_t t_first_ns, t_last_ns;
    double acc_norm, gyr_norm;
    /* recording */
    const char *record_path;
    hx_writer_t *rec;
    int rec_failed;
    /* navigation: the filter and the trajectory so far */
    fnav_nav_t *nav;
    fnav_linux_port_ctx_t lctx;   /* the replay's CSV writer */
    fnav_port_t lport;
    FILE *csv;
    int csv_failed;
    hx_traj_t traj;
    hx_axes_t *axes;              /* the axes check, as replay's (NULL: out of memory, not checked) */
    hx_sat_t sat;                 /* flat tops at the channels' extremes, as replay's */
    fnav_nav_frame_t last;
    int have_frame;
    /* standard error */
    int tty;                      /* a terminal: the status line is redrawn in place */
    int status_len;               /* its length, to blank what a shorter one leaves */
    /* plot */
    hist_t hist;
    pid_t plot_pid;
    int plot_failed;              /* the last picture, drawn at the end, was not written */
} live_t;

/* Before a message on standard error: a status line redrawn in place has no
 * newline yet, and a warning written after it would share its line
 * (tests/cli/live_tty.py) */
static void end_status_line(live_t *L)
{
    hx_line_break(); /* the flag hx_error and hx_warn test too */
    L->status_len = 0;
}

/* One navigation output: to the CSV (through the Linux port's writer, as
 * replay) and into the trajectory kept for the summary and the plot. */
static void on_nav_frame(live_t *L, const fnav_nav_frame_t *f)
{
    if (L->csv != NULL && !L->csv_failed && fnav_port_write_nav(&L->lport, f) != FNAV_OK) {
        end_status_line(L);
        /* with the reason the port kept where the write failed; --out -
         * named standard output, as the end's error (it said "the
         * trajectory CSV (Broken pipe)" of a reader gone) */
        char why[128];
        hx_error(CMD, "cannot write the trajectory %s%s; it stops here",
                 L->csv == stdout ? "to standard output" : "CSV",
                 hx_errno_note(L->lctx.write_errno, why, sizeof why));
        L->csv_failed = 1;
        if (L->csv == stdout) {
            /* what stdio still holds for a reader that never reads (a write
             * a second signal cut) would go to it again at the final flush
             * and at exit, which would then wait for ever: the rest goes
             * nowhere, the reader gets its end */
            int null_fd = open("/dev/null", O_WRONLY);
            if (null_fd >= 0) {
                (void)dup2(null_fd, STDOUT_FILENO);
                (void)close(null_fd);
            }
        }
    }
    if (L->traj.n == L->traj.cap && !L->traj_partial) {
        size_t nc = L->traj.cap ? 2 * L->traj.cap : 16384;
        fnav_nav_frame_t *p = (fnav_nav_frame_t *)realloc(L->traj.f, nc * sizeof *p);
        if (p != NULL) {
            L->traj.f = p;
            L->traj.cap = nc;
        } else {
            /* the summary covers what fitted, and says so: a run "until
             * switched off" keeps sizeof(fnav_nav_frame_t) bytes an output */
            end_status_line(L);
            hx_warn(CMD, "out of memory keeping the trajectory (%zu outputs, %.0f MB): the summary, --json and "
                    "--plot cover those; the trajectory CSV and the recording go on with every sample",
                    L->traj.n, (double)(L->traj.n * sizeof *p) / 1e6);
            L->traj_partial = 1;
        }
    }
    if (L->traj.n < L->traj.cap) {
        L->traj.f[L->traj.n++] = *f;
    }
    if (L->axes != NULL) {
        hx_axes_frame(L->axes, f);
    }
    L->last = *f;
    L->have_frame = 1;
}

static void nav_push(live_t *L, const fnav_sample_t *s)
{
    fnav_nav_frame_t fr;
    if (!L->lctx.have_t0) {
        L->lctx.t0_ns = s->t_ns; /* CSV time is relative to the first sample, as in replay */
        L->lctx.have_t0 = 1;
    }
    if (L->axes != NULL) {
        hx_axes_sample(L->axes, s);
    }
    hx_sat_push(&L->sat, s);
    if (fnav_nav_push(L->nav, s) != FNAV_OK) {
        /* rejected (NaN, time backwards): counted in the filter's stats, as in replay */
    }
    while (fnav_nav_pop(L->nav, &fr) == FNAV_OK) {
        on_nav_frame(L, &fr);
    }
}

static void nav_finish(live_t *L)
{
    fnav_nav_frame_t fr;
    fnav_nav_finish(L->nav);
    while (fnav_nav_pop(L->nav, &fr) == FNAV_OK) {
        on_nav_frame(L, &fr);
    }
    L->traj.stats = L->nav->stats;
    L->traj.rate_hz = (double)L->nav->stance.rate_hz;
    L->traj.max_gap_s = (double)L->nav->cfg.max_gap_s;
    L->traj.window = L->nav->stance.win;
    L->traj.zupt_min_n = L->nav->stance.n_min_zupt;
    L->traj.zupt_max_n = L->nav->stance.lag + 1;
    L->traj.align = L->nav->align.result;
    L->traj.aligned = L->nav->aligned;
    {
        int ch;
        for (ch = 0; ch < 6; ch++) {
            L->traj.saturated[ch] = hx_sat_count(&L->sat, ch);
        }
    }
    hx_axes_finish(L->axes, &L->traj.axes);
    L->axes = NULL;
}

static void warn_limited(live_t *L, const char *msg)
{
    if (L->warnings <= MAX_WARNINGS) {
        end_status_line(L);
    }
    if (L->warnings < MAX_WARNINGS) {
        hx_warn(CMD, "%s", msg);
    } else if (L->warnings == MAX_WARNINGS) {
        hx_warn(CMD, "more link problems: only counted from now on (see the summary)");
    }
    L->warnings++;
}

static uint32_t payload_crc(const fnav_wire_frame_t *f)
{
    return fnav_crc32(0u, f->payload, f->len);
}

/* 1 when the SAMPLE frame f is a copy of one of the recent accepted ones
 * (its frame seq, time and counter, and the same bytes: a sender restarted
 * within RECENT_N samples, stamping from its sample counter, sends the same
 * keys with other values, which are no copy), received again. */
static int recent_has(const live_t *L, unsigned fseq, const fnav_sample_t *s, uint32_t crc)
{
    unsigned k, n = L->n_recent < RECENT_N ? L->n_recent : RECENT_N;
    for (k = 0; k < n; k++) {
        if (L->recent[k].frame_seq == fseq && L->recent[k].t_ns == s->t_ns && L->recent[k].seq == s->seq &&
            L->recent[k].crc == crc) {
            return 1;
        }
    }
    return 0;
}

/* recent_has for a frame of any type (the decoder's sequence restarts) */
static int recent_copy(const live_t *L, const fnav_wire_frame_t *f)
{
    fnav_sample_t s;
    return f->type == FNAV_WIRE_SAMPLE && fnav_wire_parse_sample(f, &s) == FNAV_OK &&
           recent_has(L, (unsigned)f->seq, &s, payload_crc(f));
}

/* Report what the decoder's counters say happened since the last frame. */

static void report_link(live_t *L, const fnav_wire_frame_t *f)
{
    const fnav_wire_stats_t *s = &L->dec.stats;
    char msg[160];
    if (s->bad_frames != L->last_stats.bad_frames) {
        /* this frame's sequence number follows the previous valid frame's:
         * no frame was lost, the corrupt candidates were bytes between two
         * frames (noise on the line, a false sync word), not data: they do
         * not make the run exit 1, "incomplete" with nothing missing. A
         * damaged frame always leaves a gap. */
        const uint32_t bad = s->bad_frames - L->last_stats.bad_frames;
        const int noise = L->have_prev_frame && s->lost == L->last_stats.lost && s->resets == L->last_stats.resets;
        if (noise) {
            L->noise += bad;
        }
        snprintf(msg, sizeof msg, "bad frame: %lu corrupt frame(s) skipped before frame seq %u%s", (unsigned long)bad,
                 (unsigned)f->seq, noise ? "; no frame lost (noise on the line)" : "");
        warn_limited(L, msg);
    }
    if (s->lost != L->last_stats.lost) {
        snprintf(msg, sizeof msg, "drop: %lu frame(s) lost before frame seq %u",
                 (unsigned long)(s->lost - L->last_stats.lost), (unsigned)f->seq);
        warn_limited(L, msg);
    }
    if (s->resets != L->last_stats.resets) {
        if (L->have_prev_frame && ((unsigned)f->seq == L->prev_frame_seq || recent_copy(L, f))) {
            /* the previous frame again (a link's repetition), not a restart:
             * a SAMPLE frame's copy is reported where it is skipped, and
             * only there, not also as "restart ... (sender reset?)" */
            L->seq_repeats++;
            if (f->type != FNAV_WIRE_SAMPLE) {
                snprintf(msg, sizeof msg, "repeated frame: frame seq %u received twice", (unsigned)f->seq);
                warn_limited(L, msg);
            }
            /* the decoder now expects the frame after the copy: it expects
             * the one after the last frame again (a late copy moved it
             * back, and the next frame was counted lost; the frame counter
             * covers every type, so the last frame, not the last sample's),
             * and the copy is not the previous frame */
            L->dec.expect_seq = (uint16_t)(L->prev_frame_seq + 1u);
            L->last_stats = *s;
            return;
        } else {
            snprintf(msg, sizeof msg, "restart: the frame sequence went back to %u (sender reset?)", (unsigned)f->seq);
            warn_limited(L, msg);
            /* a sender's END counts its samples since its own start: with
             * its clock going on, the session goes on too, and END is
             * compared with the samples since this restart as well */
            L->samples_at_restart = L->samples;
            L->have_seq_restart = 1;
        }
    }
    L->last_stats = *s;
    L->prev_frame_seq = (unsigned)f->seq;
    L->have_prev_frame = 1;
}

/* The recording's header from the last good INFO frame: the sensor, the
 * axes, the flags and the rate, unless the rate changed in the session (0,
 * unknown: the samples keep their stamps). */
static void recording_meta(const live_t *L, hx_meta_t *meta)
{
    memset(meta, 0, sizeof *meta);
    meta->format = HX_FMT_BIN;
    if (L->have_info) {
        meta->rate_hz = L->rate_changed ? 0.0 : L->info.rate_hz;
        meta->rate_nominal = (L->info.flags & FNAV_WIRE_INFO_RATE_NOMINAL) != 0u && !L->rate_changed;
        /* the bits cover the session's records, not the last INFO alone:
         * a temperature recorded under an INFO that announced it stays
         * readable after an INFO without (the reader reads none under a
         * header whose bit 1 is clear), and a counter is the sensor's only
         * when every sample recorded carried it under an INFO saying so */
        meta->has_temp = (L->info.flags & FNAV_WIRE_INFO_TEMP) != 0u || L->temp_recorded;
        meta->has_seq = (L->info.flags & FNAV_WIRE_INFO_SEQ) != 0u && !L->seq_undeclared;
        snprintf(meta->sensor, sizeof meta->sensor, "%s", L->info.sensor);
        snprintf(meta->axes, sizeof meta->axes, "%s", L->info.axes);
    } else {
        meta->has_temp = L->temp_recorded; /* the samples' own word, with no INFO to deny it */
        snprintf(meta->sensor, sizeof meta->sensor, "unknown (no INFO frame)");
    }
    snprintf(meta->source, sizeof meta->source, "harness live");
}

static int open_recording(live_t *L)
{
    hx_meta_t meta;
    char err[HX_ERR_SIZE];
    L->hdr_info = L->info;
    L->hdr_has_info = L->have_info;
    recording_meta(L, &meta);
    L->hdr_has_temp = meta.has_temp;
    L->hdr_has_seq = meta.has_seq;
    L->rec = hx_writer_open(L->record_path, HX_FMT_BIN, &meta, 1, err, sizeof err);
    if (L->rec == NULL) {
        hx_error(CMD, "%s", err);
        L->rec_failed = 1;
        return -1;
    }
    return 0;
}

/* the INFO flag bits a header holds: a bit of a newer sender's, which this
 * receiver ignores (docs/wire-protocol.md), changes nothing recorded, and an
 * INFO that differed only there rewrote the header, "it changed during the
 * session" */
#define LIVE_INFO_FLAGS_KNOWN (FNAV_WIRE_INFO_RATE_NOMINAL | FNAV_WIRE_INFO_TEMP | FNAV_WIRE_INFO_SEQ)
static int info_flags_differ(const fnav_wire_info_t *a, const fnav_wire_info_t *b)
{
    return ((a->flags ^ b->flags) & LIVE_INFO_FLAGS_KNOWN) != 0u;
}

/* At the end: an INFO frame that came after the first sample (live joined
 * a sender already running: the reference firmware sends INFO once), or
 * that changed, is written into the recording's header, which was written
 * at the first sample; 1 when it was. */
static int update_recording_header(live_t *L)
{
    hx_meta_t meta;
    recording_meta(L, &meta);
    if (L->rec == NULL || (!L->have_info && L->hdr_has_temp == meta.has_temp) ||
        (L->have_info && L->hdr_has_info && L->hdr_info.rate_hz == L->info.rate_hz && !info_flags_differ(&L->hdr_info, &L->info) &&
         strcmp(L->hdr_info.sensor, L->info.sensor) == 0 && strcmp(L->hdr_info.axes, L->info.axes) == 0 &&
         !L->rate_changed && L->hdr_has_temp == meta.has_temp && L->hdr_has_seq == meta.has_seq)) {
        return 0;
    }
    if (hx_writer_rewrite_header(L->rec, &meta) != FNAV_OK) {
        end_status_line(L);
        hx_warn(CMD, "%s: the header could not be rewritten with the INFO frame that came later (%s); it says what "
                "was known at the first sample", L->record_path, strerror(errno));
        return 0;
    }
    return 1;
}

static void hist_push(hist_t *h, double t, double a, double w)
{
    if (h->cap == 0u) {
        return;
    }
    h->t[h->head] = t;
    h->a[h->head] = a;
    h->w[h->head] = w;
    h->head = (h->head + 1u) % h->cap;
    if (h->n < h->cap) {
        h->n++;
    }
}

/* A sample released from the hold: navigated, recorded, plotted. */
static void on_sample(live_t *L, const fnav_sample_t *s)
{
    double a2 = 0.0, w2 = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        a2 += (double)s->accel_mps2[i] * (double)s->accel_mps2[i];
        w2 += (double)s->gyro_rps[i] * (double)s->gyro_rps[i];
    }
    L->acc_norm = sqrt(a2);
    L->gyr_norm = sqrt(w2);
    hist_push(&L->hist, (double)(s->t_ns - L->t_first_ns) * 1e-9, L->acc_norm, L->gyr_norm);
    nav_push(L, s);
    if (L->record_path != NULL && !L->rec_failed) {
        /* before the header is written at the first sample, which takes them */
        L->temp_recorded |= (s->flags & FNAV_SAMPLE_HAS_TEMP) != 0u;
        L->seq_undeclared |= (s->flags & FNAV_SAMPLE_HAS_SEQ) == 0u;
        if (L->rec == NULL) {
            end_status_line(L);
        }
        if (L->rec == NULL && open_recording(L) != 0) {
            return;
        }
        if (hx_writer_write(L->rec, s) != FNAV_OK) {
            end_status_line(L);
            hx_error(CMD, "%s: write failed (%s); recording stopped", L->record_path, strerror(errno));
            L->rec_failed = 1;
        } else {
            L->recorded++;
        }
    }
}

/* A jump of the sensor's own counter (INFO bit 2 and the sample's
 * FNAV_SAMPLE_HAS_SEQ) beyond what the link lost since the last sample
 * (frames lost, samples refused) is a loss on the sender: reported and
 * counted, not passed in silence. Frames of other
 * types lost on the link are counted as samples, so this is a lower bound. */
static void sensor_counter(live_t *L, const fnav_sample_t *s, uint32_t lost_now, uint32_t bad_now)
{
    const int counted = L->have_info && (L->info.flags & FNAV_WIRE_INFO_SEQ) != 0u &&
                        (s->flags & FNAV_SAMPLE_HAS_SEQ) != 0u;
    if (counted && L->have_sensor_seq) {
        const uint32_t step = s->seq - L->last_sample_seq;
        const uint32_t link = (lost_now - L->lost_at_last) + (bad_now - L->bad_at_last);
        if (step > 1u && step < 0x80000000u && step - 1u > link) {
            char msg[160];
            L->sensor_missing += step - 1u - link;
            L->sensor_gaps++;
            snprintf(msg, sizeof msg,
                     "sensor drop: %lu sample(s) missing by the sensor's counter before sample seq %lu (lost on "
                     "the sender, not on the link)",
                     (unsigned long)(step - 1u - link), (unsigned long)s->seq);
            warn_limited(L, msg);
        }
    }
    L->have_sensor_seq = counted;
    L->lost_at_last = lost_now;
    L->bad_at_last = bad_now;
}

/* A SAMPLE frame kept among the recent ones (a later copy of it is
 * skipped): the samples taken and those dropped for their stamps. */
static void remember(live_t *L, unsigned fseq, uint32_t crc, const fnav_sample_t *s)
{
    L->recent[L->n_recent % RECENT_N].frame_seq = fseq;
    L->recent[L->n_recent % RECENT_N].t_ns = s->t_ns;
    L->recent[L->n_recent % RECENT_N].seq = s->seq;
    L->recent[L->n_recent % RECENT_N].crc = crc;
    L->n_recent++;
}

/* A sample taken: counted, and held back by one sample (live_t.held) while
 * the one held before is navigated and recorded. */
static void accept_sample_at(live_t *L, unsigned fseq, uint32_t crc, const fnav_sample_t *s, uint32_t lost_now,
                             uint32_t bad_now)
{
    sensor_counter(L, s, lost_now, bad_now);
    if (L->samples == 0u) {
        L->t_first_ns = s->t_ns;
    }
    L->acc[2] = L->acc[1];
    L->acc[1] = L->acc[0];
    L->acc[0].t_ns = s->t_ns;
    L->acc[0].fseq = fseq;
    L->acc[0].epoch = L->dec.stats.resets - L->seq_repeats;
    L->n_acc += L->n_acc < 3u;
    L->samples++;
    L->t_last_ns = s->t_ns;
    L->last_frame_seq = fseq;
    L->last_sample_seq = s->seq;
    L->last_crc = crc;
    remember(L, fseq, crc, s);
    L->restarts_at_last = L->dec.stats.resets - L->seq_repeats;
    L->back_run = 0u;
    if (L->have_held) {
        on_sample(L, &L->held);
    }
    L->held = *s;
    L->have_held = 1;
}

static void accept_sample(live_t *L, unsigned fseq, uint32_t crc, const fnav_sample_t *s)
{
    accept_sample_at(L, fseq, crc, s, L->dec.stats.lost, L->bad_samples);
}

/* The held sample dropped (stamped ahead): P becomes the last taken. */
static void drop_held(live_t *L)
{
    L->have_held = 0;
    L->samples--;
    L->acc[0] = L->acc[1];
    L->acc[1] = L->acc[2];
    L->n_acc--;
    if (L->n_acc > 0u) {
        L->t_last_ns = L->acc[0].t_ns;
        L->last_frame_seq = L->acc[0].fseq;
    }
}

/* The held sample, navigated and recorded: at the end of the run. */
static void release_held(live_t *L)
{
    if (L->have_held) {
        L->have_held = 0;
        on_sample(L, &L->held);
    }
}

/* Did the sender go on from the last sample accepted to s: no restart of
 * the frame sequence since (copies aside), and the sensor's counter, when
 * both carry it, one or more ahead? */
static int in_sequence(const live_t *L, const fnav_sample_t *s)
{
    const int counted = L->have_info && (L->info.flags & FNAV_WIRE_INFO_SEQ) != 0u &&
                        (s->flags & FNAV_SAMPLE_HAS_SEQ) != 0u && L->have_sensor_seq;
    const uint32_t step = s->seq - L->last_sample_seq;
    return L->dec.stats.resets - L->seq_repeats == L->restarts_at_last && (!counted || (step >= 1u && step < 0x80000000u));
}

/* The interval per frame before P (ns): from P and the sample before it
 * when no sequence restart lies between them, else the INFO's period; 0
 * unknown. */
static double frame_interval(const live_t *L)
{
    if (L->n_acc >= 3u && L->acc[1].epoch == L->acc[2].epoch) {
        const unsigned d = (uint16_t)(L->acc[1].fseq - L->acc[2].fseq);
        if (d > 0u && d < 0x8000u && L->acc[1].t_ns > L->acc[2].t_ns) {
            return (double)(L->acc[1].t_ns - L->acc[2].t_ns) / (double)d;
        }
    }
    return (L->have_info && L->info.rate_hz > 0.0) ? 1e9 / L->info.rate_hz : 0.0;
}

/* A sample s (frame seq fseq) stamped behind the held one H while the
 * sender went on. When it lies after P, the sample before H, either H is
 * stamped late or s early: with T the interval per frame before P (or the
 * INFO's period), H is the one out of order when s fits its frame distance
 * from P in intervals better than H fits its own (a stamp far ahead: 1000
 * s against 2.5 ms; the distances count the frames a link lost). */
static int held_is_ahead(const live_t *L, const fnav_sample_t *s, unsigned fseq)
{
    const double T = frame_interval(L);
    double n_s, n_h;
    if (!(L->have_held && L->n_acc >= 2u && s->t_ns >= L->acc[1].t_ns)) {
        return 0;
    }
    n_s = (double)(uint16_t)(fseq - L->acc[1].fseq);
    n_h = (double)(uint16_t)(L->acc[0].fseq - L->acc[1].fseq);
    return T > 0.0 && fabs((double)(s->t_ns - L->acc[1].t_ns) - n_s * T) <
                          fabs((double)(L->acc[0].t_ns - L->acc[1].t_ns) - n_h * T);
}

/* Samples set aside for a stamp behind the held one that rise, each at or
 * after the one before, and start after P (or there is no P). */
static int run_after_p(const live_t *L)
{
    unsigned i;
    for (i = 1; i < L->back_run; i++) {
        if (L->run[i].s.t_ns < L->run[i - 1].s.t_ns) {
            return 0;
        }
    }
    return L->have_held && (L->n_acc < 2u || L->run[0].s.t_ns >= L->acc[1].t_ns);
}

/* The held sample was stamped ahead of the back_run samples set aside
 * after it: it is dropped and they are taken, each with the link's losses
 * when it came (a frame lost among them is not the sender's). */
static void take_back(live_t *L)
{
    char msg[240];
    const uint32_t n = L->back_run;
    uint32_t i, bad;
    snprintf(msg, sizeof msg,
             "bad time stamp: sample frame seq %u stamped %.6f s, ahead of the %u samples after it (from %.6f s), "
             "which are taken back; it is skipped",
             L->last_frame_seq, (double)L->t_last_ns * 1e-9, (unsigned)n, (double)L->run[0].s.t_ns * 1e-9);
    warn_limited(L, msg);
    L->bad_samples -= n - 1u; /* the run taken, the held one dropped */
    L->bad_stamps -= n - 1u;
    bad = L->bad_at_last;
    drop_held(L);
    for (i = 0; i < n; i++) {
        accept_sample_at(L, L->run[i].fseq, L->run[i].crc, &L->run[i].s, L->run[i].lost, bad);
    }
}

/* s stamped behind the held one H while the sender went on: H dropped (s
 * taken) when H is the one out of order (held_is_ahead), else s set aside.
 * BACK_RUN_MAX set aside in a row: when they rise after P, H was ahead of
 * them all (the first sample stamped ahead, no P to judge by; a link's
 * loss before it): H is dropped and they are taken back; otherwise the
 * sender's clock went back, which ends the session as a restart does. */
static void out_of_order(live_t *L, const fnav_wire_frame_t *f, const fnav_sample_t *s, uint32_t crc)
{
    char msg[240];
    L->bad_samples++;
    L->bad_stamps++;
    if (held_is_ahead(L, s, (unsigned)f->seq)) {
        snprintf(msg, sizeof msg,
                 "bad time stamp: sample frame seq %u stamped %.6f s, ahead of the samples on both sides (%.6f and "
                 "%.6f s); it is skipped",
                 L->last_frame_seq, (double)L->t_last_ns * 1e-9, (double)L->acc[1].t_ns * 1e-9,
                 (double)s->t_ns * 1e-9);
        warn_limited(L, msg);
        drop_held(L);
        accept_sample(L, (unsigned)f->seq, crc, s);
        return;
    }
    snprintf(msg, sizeof msg,
             "bad time stamp: sample frame seq %u stamped %.6f s, behind the last sample's %.6f s while the frame "
             "sequence goes on; skipped (a stamp out of order, not a restart)",
             (unsigned)f->seq, (double)s->t_ns * 1e-9, (double)L->t_last_ns * 1e-9);
    warn_limited(L, msg);
    remember(L, (unsigned)f->seq, crc, s);
    if (L->back_run == 0u) { /* where the run began, for the message */
        L->restart_from_s = (double)L->t_last_ns * 1e-9;
        L->restart_to_s = (double)s->t_ns * 1e-9;
        L->restart_seq = (unsigned)f->seq;
    }
    L->run[L->back_run].s = *s;
    L->run[L->back_run].fseq = (unsigned)f->seq;
    L->run[L->back_run].crc = crc;
    L->run[L->back_run].lost = L->dec.stats.lost;
    if (++L->back_run < BACK_RUN_MAX) {
        return;
    }
    if (!run_after_p(L)) {
        L->restarted = 1;
        L->clock_back = 1;
        return;
    }
    take_back(L);
}

static void on_frame(live_t *L, const fnav_wire_frame_t *f)
{
    report_link(L, f);
    L->by_type[f->type <= 5u ? f->type : 0u]++;
    switch (f->type) {
    case FNAV_WIRE_SAMPLE: {
        fnav_sample_t s;
        fnav_status_t st = fnav_wire_parse_sample(f, &s);
        uint32_t crc = 0u;
        if (st == FNAV_OK) {
            /* what the navigator and the .bin reader refuse, refused on
             * arrival so that the recording stays readable to its end */
            st = fnav_sample_check(&s);
            crc = payload_crc(f); /* a copy is the same bytes */
        }
        if (st == FNAV_OK && L->have_info) {
            /* the INFO in force says what the samples carry (its bits 1
             * and 2): a temperature or a counter it does not announce is
             * not kept (a temperature recorded under a header without bit
             * 1 is unread, "a writer's fault?") */
            if ((s.flags & FNAV_SAMPLE_HAS_TEMP) != 0u && (L->info.flags & FNAV_WIRE_INFO_TEMP) == 0u) {
                s.flags &= ~(uint32_t)FNAV_SAMPLE_HAS_TEMP;
                if (!L->told_temp) {
                    char msg[200];
                    L->told_temp = 1;
                    snprintf(msg, sizeof msg, "sample frame seq %u carries a temperature, but the sender's INFO "
                             "frame says its samples have none (flags bit 1): the temperatures are not recorded",
                             (unsigned)f->seq);
                    warn_limited(L, msg);
                }
            }
            if ((L->info.flags & FNAV_WIRE_INFO_SEQ) == 0u) {
                s.flags &= ~(uint32_t)FNAV_SAMPLE_HAS_SEQ;
            }
        }
        if (st == FNAV_OK && L->samples > 0u && (unsigned)f->seq == L->last_frame_seq && s.t_ns == L->t_last_ns &&
            s.seq == L->last_sample_seq && crc == L->last_crc) {
            /* the same frame again (a sender's or a link's repetition): one
             * sample, not two with dt = 0 (a sensor's own duplicate comes in
             * a frame of its own, with the next frame seq) */
            char msg[120];
            L->repeated++;
            snprintf(msg, sizeof msg, "repeated frame: sample frame seq %u received twice; the copy skipped",
                     (unsigned)f->seq);
            warn_limited(L, msg);
        } else if (st == FNAV_OK && L->samples > 0u && recent_has(L, (unsigned)f->seq, &s, crc)) {
            /* a copy of an earlier frame arriving late (a link's stale
             * repetition): its time goes back, but it is no restart, which
             * would end the run with the rest of the session lost (the live
             * audit: one stale copy kept 3,002 of 16,539 samples); also a
             * copy of one dropped for a stamp ahead, which is not behind.
             * The decoder's sequence is set back by report_link. */
            char msg[160];
            L->repeated++;
            snprintf(msg, sizeof msg,
                     "repeated frame: sample frame seq %u received again after seq %u (a late copy); skipped",
                     (unsigned)f->seq, L->prev_frame_seq);
            warn_limited(L, msg);
        } else if (st == FNAV_OK && L->samples > 0u && s.t_ns < L->t_last_ns && in_sequence(L, &s)) {
            /* time back with the frame sequence (and the sensor's counter)
             * going on: a stamp out of order, not a restart (one stamp 0.5
             * ms early ended the session: the live audit of 2026-12-06) */
            out_of_order(L, f, &s, crc);
        } else if (st == FNAV_OK && L->samples > 0u && s.t_ns < L->t_last_ns) {
            /* what the .bin reader and the navigator refuse: the session
             * ends here, with the recording readable to this point */
            L->restarted = 1;
            L->restart_from_s = (double)L->t_last_ns * 1e-9;
            L->restart_to_s = (double)s.t_ns * 1e-9;
            L->restart_seq = (unsigned)f->seq;
        } else if (st == FNAV_OK) {
            accept_sample(L, (unsigned)f->seq, crc, &s);
        } else {
            char msg[160];
            L->bad_samples++;
            snprintf(msg, sizeof msg, "bad sample: sample frame seq %u holds %s; skipped", (unsigned)f->seq,
                     st == FNAV_E_RANGE ? "a value beyond 1e6 SI or a time beyond 2^62 ns" : "NaN or Inf");
            warn_limited(L, msg);
        }
        break;
    }
    case FNAV_WIRE_INFO: {
        fnav_wire_info_t info;
        if (fnav_wire_parse_info(f, &info) == FNAV_OK) {
            /* 10 bits per byte on an 8N1 line, as stream's check: a real
             * UART at a lower rate falls behind, losing frames (warned, as
             * stream warns) */
            const double need_bps = (double)info.rate_hz * (double)FNAV_WIRE_FRAME_SIZE(FNAV_WIRE_SAMPLE_LEN) * 10.0;
            char clean[sizeof info.axes];
            int ctl;
            /* the sender's text, shown and recorded as one line of text: a
             * control character (a line break, an escape that clears the
             * terminal) becomes '?', as the .bin reader reads it */
            ctl = strcmp(hx_line_str(clean, sizeof info.sensor, info.sensor), info.sensor) != 0;
            memcpy(info.sensor, clean, sizeof info.sensor); /* a string of at most as many bytes */
            ctl |= strcmp(hx_line_str(clean, sizeof info.axes, info.axes), info.axes) != 0;
            memcpy(info.axes, clean, sizeof info.axes);
            if (ctl && !L->told_name) {
                L->told_name = 1;
                warn_limited(L, "the INFO frame's sensor name or axis note holds control characters or bytes that are "
                                "not UTF-8 (shown and recorded as '?')");
            }
            if (L->have_info && L->samples > 0u && info.rate_hz != L->info.rate_hz && !L->rate_changed) {
                char msg[200];
                L->rate_changed = 1;
                snprintf(msg, sizeof msg, "the sender's INFO frame seq %u changes its rate from %.6g to %.6g Hz: the "
                         "recording's header gives no rate (0), the samples keep their own stamps",
                         (unsigned)f->seq, L->info.rate_hz, info.rate_hz);
                warn_limited(L, msg);
            }
            L->info = info;
            L->have_info = 1;
            if (need_bps > (double)L->baud && !L->told_baud) {
                char msg[200];
                L->told_baud = 1;
                snprintf(msg, sizeof msg, "the sender's %.0f samples/s need %.0f baud; at %ld baud a real UART falls "
                         "behind and frames are lost (a pty does not care; --baud)", (double)info.rate_hz, need_bps,
                         L->baud);
                warn_limited(L, msg);
            }
        } else {
            char msg[120];
            L->bad_info++;
            snprintf(msg, sizeof msg, "bad INFO frame seq %u: its rate is not in [0, 1e6] Hz; ignored", (unsigned)f->seq);
            warn_limited(L, msg);
        }
        break;
    }
    case FNAV_WIRE_STATUS:
        if (fnav_wire_parse_status(f, &L->status) == FNAV_OK) {
            L->have_status = 1;
        }
        break;
    case FNAV_WIRE_END:
        if (fnav_wire_parse_end(f, &L->end_count) == FNAV_OK) {
            L->have_end = 1;
        }
        break;
    case FNAV_WIRE_NAV:
        break; /* from an on-sensor filter: live navigates the samples itself */
    default:
        /* a type this receiver does not know: skipped and counted (the
         * protocol's versioning rule), said once, so that a sender whose
         * samples come in a newer type is not only "samples missing" */
        if (!L->told_unknown) {
            char msg[200];
            L->told_unknown = 1;
            snprintf(msg, sizeof msg, "frame seq %u is of type 0x%02x, which this receiver does not know (a newer "
                     "sender?): such frames are skipped and counted (frames: unknown)", (unsigned)f->seq,
                     (unsigned)f->type);
            warn_limited(L, msg);
        }
        break;
    }
}

/* The line went quiet or the session ends: no byte will complete the
 * candidate frame the decoder holds, so the frames behind it (a truncated
 * frame followed by END, the sender then silent) are taken now, not left to
 * wait for bytes that never come (live would miss the END frame and run on
 * until --timeout or for ever). */
static void flush_link(live_t *L, int at_stop)
{
    fnav_wire_frame_t f;
    uint32_t bad = L->dec.stats.bad_frames;
    while (!L->have_end && !L->restarted && !L->rec_failed && fnav_wire_decode_flush(&L->dec, &f) == FNAV_OK) {
        on_frame(L, &f);
        bad = L->dec.stats.bad_frames;
        L->idle_cut = 0u; /* a frame came after it: that one was corrupt */
    }
    if (at_stop) {
        /* the candidate after the last frame, cut by a Ctrl-C: a frame on
         * its way when the user stopped (on a UART a frame arrives in
         * pieces, so about half the stops land in one at 400 Hz), not a
         * corrupt one that makes the run exit 1; also when the line went
         * quiet first and its flush ended that candidate (the sensor
         * switched off mid-frame, Ctrl-C a second or more later: it was
         * counted corrupt, exit 1, by how fast the user pressed it) */
        L->cut = L->dec.stats.bad_frames - bad + L->idle_cut;
    } else {
        /* only the last candidate can be the frame the switch-off cut:
         * one before bytes that came later was not */
        L->idle_cut = L->dec.stats.bad_frames - bad;
    }
}

static double span_s(const live_t *L)
{
    return L->samples > 1u ? (double)(L->t_last_ns - L->t_first_ns) * 1e-9 : 0.0;
}

/* What came in while no sample did: for the status line and the end of a
 * run without samples (not "aligning (keep the foot still)" with nothing
 * received, or with bytes at a wrong baud rate). */
static void describe_nothing(const live_t *L, char *out, size_t size)
{
    const fnav_wire_stats_t *s = &L->dec.stats;
    unsigned long bytes = (unsigned long)s->skipped_bytes + (unsigned long)L->dec.fill;
    if (L->by_type[FNAV_WIRE_SAMPLE] > 0u) {
        snprintf(out, size, "the %u SAMPLE frames were all refused", (unsigned)L->by_type[FNAV_WIRE_SAMPLE]);
    } else if (s->frames > 0u) {
        snprintf(out, size, "no SAMPLE frame among %u valid frames", (unsigned)s->frames);
    } else if (bytes > 0u) {
        snprintf(out, size, "%lu bytes received, no valid frame (wrong --baud, or not a footnav sender?)", bytes);
    } else {
        snprintf(out, size, "nothing received");
    }
}

static void print_status(live_t *L, double quiet_s)
{
    const fnav_wire_stats_t *s = &L->dec.stats;
    double span = span_s(L);
    char nav[160], line[400];
    int n;
    if (L->samples == 0u) {
        char what[120];
        describe_nothing(L, what, sizeof what);
        snprintf(nav, sizeof nav, "waiting: %s", what);
    } else if (L->have_frame && (L->last.flags & FNAV_FRAME_ALIGNED)) {
        snprintf(nav, sizeof nav, "x %.2f y %.2f z %.2f m, yaw %.0f deg, %s, %u strides",
                 (double)L->last.pos_m[0], (double)L->last.pos_m[1], (double)L->last.pos_m[2],
                 (double)L->last.euler_rad[2] * 57.29577951308232,
                 (L->last.flags & FNAV_FRAME_STANCE) ? "stance" : "swing", (unsigned)L->nav->stats.strides);
    } else {
        snprintf(nav, sizeof nav, "aligning (keep the foot still)");
    }
    /* what each number is: the time is the sensor's, not the wall's, and
     * "bad 0 lost 0" alone would name no unit */
    n = snprintf(line, sizeof line, "live: sensor time %.1f s, %u samples | %s | bad frames %u, lost frames %u", span,
                 (unsigned)L->samples, nav, (unsigned)(s->bad_frames + L->bad_samples), (unsigned)s->lost);
    if (quiet_s >= QUIET_NOTE_S && n > 0 && (size_t)n < sizeof line) {
        n += snprintf(line + n, sizeof line - (size_t)n, " | no frame for %.0f s", quiet_s);
    }
    if (n < 0) {
        return;
    }
    if ((size_t)n >= sizeof line) {
        n = (int)sizeof line - 1;
    }
    if (L->tty) {
        /* redrawn in place: spaces over what a longer line before left */
        fprintf(stderr, "\r%s%*s", line, L->status_len > n ? L->status_len - n : 0, "");
        L->status_len = n;
        hx_line_open();
    } else {
        fprintf(stderr, "%s\n", line);
    }
    fflush(stderr);
}

/* Has the aligned trajectory left its start (a path worth drawing)? */
static int moved(const hx_traj_t *t)
{
    size_t i;
    for (i = 0; i < t->n; i++) {
        const fnav_nav_frame_t *f = &t->f[i];
        if ((f->flags & FNAV_FRAME_ALIGNED) &&
            (fabs((double)f->pos_m[0]) > 0.01 || fabs((double)f->pos_m[1]) > 0.01 || fabs((double)f->pos_m[2]) > 0.01)) {
            return 1;
        }
    }
    return 0;
}

/* Draw the plot in a child process so that the receive loop never waits for
 * gnuplot; the PNG is written to a temporary name and renamed (onto a
 * regular file or none: hx_plot_rename_target). */
static void plot_async(live_t *L, const char *png)
{
    pid_t pid;
    if (L->hist.n == 0u) {
        /* nothing received yet: gnuplot would get empty data, and its
         * errors would run down standard error at every redraw */
        return;
    }
    if (L->plot_pid > 0) {
        if (waitpid(L->plot_pid, NULL, WNOHANG) == 0) {
            return; /* the previous plot is still being drawn */
        }
        L->plot_pid = 0;
    }
    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid < 0) {
        return;
    }
    if (pid == 0) {
        hx_plot_t p;
        char tmp[HX_PLOT_PATH_SIZE]; /* room for any png (hx_plot_rename_target): not cut to another name */
        size_t i;
        const hist_t *h = &L->hist;
        snprintf(tmp, sizeof tmp, "%s.tmp.png", png);
        /* a FILE.tmp.png there is a stale one, or a link placed there: it
         * goes, so that gnuplot writes a file of its own, not through a
         * link, and the rename moves that file, not the link */
        (void)unlink(tmp);
        if (moved(&L->traj)) {
            char title[160];
            snprintf(title, sizeof title, "harness live: %u samples, bad %u lost %u", (unsigned)L->samples,
                     (unsigned)L->dec.stats.bad_frames, (unsigned)L->dec.stats.lost);
            if (hx_nav_plot(CMD, tmp, title, &L->traj) == 0 && rename(tmp, png) == 0) {
                _exit(0);
            }
            remove(tmp); /* a picture gnuplot failed to finish, if any */
            _exit(3);
        }
        if (hx_plot_open(&p, CMD, tmp, 900, 500) != 0) {
            _exit(3);
        }
        fprintf(p.gp, "set title 'harness live: last %.0f s, %u samples, bad %u lost %u'\n", PLOT_SECONDS,
                (unsigned)L->samples, (unsigned)L->dec.stats.bad_frames, (unsigned)L->dec.stats.lost);
        fprintf(p.gp, "set xlabel 't (s)'\nset ylabel '|a| (m/s^2)'\nset y2label '|w| (rad/s)'\n"
                      "set y2tics\nset ytics nomirror\n");
        fprintf(p.gp, "plot '-' using 1:2 with lines title '|a|', '-' using 1:2 axes x1y2 with lines title '|w|'\n");
        {
            /* the last PLOT_SECONDS of the history, as the title says (the
             * history holds 20,000 samples: 50 s at 400 Hz) */
            const double t_from = h->n > 0 ? h->t[(h->head + h->cap - 1u) % h->cap] - PLOT_SECONDS : 0.0;
            int col;
            for (col = 0; col < 2; col++) {
                for (i = 0; i < h->n; i++) {
                    size_t k = (h->head + h->cap - h->n + i) % h->cap;
                    if (h->t[k] >= t_from) {
                        fprintf(p.gp, "%.4f %.5g\n", h->t[k], col == 0 ? h->a[k] : h->w[k]);
                    }
                }
                fprintf(p.gp, "e\n");
            }
        }
        if (hx_plot_close(&p, CMD) != 0 || rename(tmp, png) != 0) {
            remove(tmp);
            _exit(3);
        }
        _exit(0);
    }
    L->plot_pid = pid;
}

static void live_free(live_t *L)
{
    free(L->hist.t);
    free(L->hist.a);
    free(L->hist.w);
    free(L->traj.f);
    L->traj.f = NULL;
    if (L->axes != NULL) { /* an exit before nav_finish: free the check, its verdict unused */
        hx_axes_result_t unused;
        hx_axes_finish(L->axes, &unused);
        L->axes = NULL;
    }
}

int hx_cmd_live(int argc, char **argv)
{
    static fnav_nav_t nav; /* 11.7 KB in float32 (fnav_nav.h): not on the stack */
    hx_args_t a;
    live_t L;
    hx_serial_t *port;
    hx_nav_opts_t nopt;
    fnav_nav_config_t ncfg;
    long baud = 460800;
    double plot_every = 0.0, timeout = 0.0, print_every = 1.0;
    double t_last_frame, t_last_byte, t_next_print, t_next_plot, t0;
    /* quiet time before held frames are flushed: shorter than --timeout */
    double idle_flush_s;
    const char *plot_png = "live.png", *out_path, *json_path;
    char plot_file[HX_PLOT_PATH_SIZE - 8]; /* room for ".tmp.png" after it */
    char err[HX_ERR_SIZE], gone_msg[600] = "";
    int rc, exit_code = HX_EXIT_OK, gone = 0, timed_out = 0;
    int stop_sig;
    char cmdline[1024], why[700] = "", port_path[4096];
    struct sigaction sa;

    if (hx_nav_param_help_requested(argc, argv)) {
        return HX_EXIT_OK;
    }
    rc = hx_args_parse(&k_spec, argc, argv, &a);

    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--plot", "--record", NULL };
        if (hx_refuse_dash(CMD, &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_arg_long(&a, "--baud", 50, 20000000, &baud) != 0 ||
        hx_arg_double(&a, "--plot-every", 0.1, 3600.0, &plot_every) != 0 ||
        hx_arg_double(&a, "--timeout", 0.1, 1e6, &timeout) != 0 ||
        hx_arg_double(&a, "--print-every", 0.0, 3600.0, &print_every) != 0) {
        return HX_EXIT_USAGE;
    }
    rc = hx_nav_opts_from_args(CMD, &a, &nopt);
    if (rc != 0) {
        return rc > 0 ? HX_EXIT_OK : HX_EXIT_USAGE; /* --param help printed */
    }
    if (nopt.rate_hz > 0.0) {
        hx_error(CMD, "--rate resamples a whole log (a zero-phase filter looks ahead); run "
                      "`harness replay --rate` on the recording instead");
        return HX_EXIT_USAGE;
    }
    if (hx_nav_config(&nopt, &ncfg, err, sizeof err) != 0) {
        hx_error(CMD, "%s", err);
        return HX_EXIT_USAGE;
    }
    if (fnav_nav_init(&nav, &ncfg) != FNAV_OK) {
        hx_nav_init_error(&ncfg, "", nopt.nparams > 0 ? " (check the --param values)" : "", err, sizeof err);
        hx_error(CMD, "%s", err);
        return HX_EXIT_USAGE;
    }
    {
        static const char *const outs[] = { "--record", "--out", "--json", "--plot", NULL };
        if (hx_output_is_input(CMD, NULL, &a, outs) || hx_profile_is_output(CMD, nopt.profile, &a, outs)) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_arg(&a, "--plot") != NULL) {
        plot_png = hx_arg(&a, "--plot");
        if (plot_every <= 0.0) {
            plot_every = 1.0;
        }
    }
    if (plot_every > 0.0) {
        /* each picture is renamed onto the path: a device there was
         * replaced by a PNG, a symlink by a file (its target never updated) */
        if (hx_plot_rename_target(CMD, plot_png, plot_file, sizeof plot_file) != 0) {
            return HX_EXIT_IO; /* an output that cannot be written, as every command's plot */
        }
        plot_png = plot_file;
        /* the plots are drawn in a child, whose failure nobody would see:
         * find out now that gnuplot is there and the picture can be written */
        if (hx_plot_check(CMD, plot_png) != 0) {
            return HX_EXIT_IO;
        }
    }
    out_path = hx_arg(&a, "--out");
    json_path = hx_arg(&a, "--json");
    /* the recording is opened at the first sample (its header takes the
     * INFO frame), the JSON written at the end: find out now, before the
     * session, that both can be written */
    /* --out too: it is created once the port is open, so that a port that
     * cannot be opened leaves an earlier run's trajectory as it was */
    if ((hx_arg(&a, "--record") != NULL && hx_check_writable(CMD, hx_arg(&a, "--record")) != 0) ||
        (json_path != NULL && strcmp(json_path, "-") != 0 && hx_check_writable(CMD, json_path) != 0) ||
        (out_path != NULL && strcmp(out_path, "-") != 0 && hx_check_writable(CMD, out_path) != 0)) {
        return HX_EXIT_IO;
    }

    memset(&L, 0, sizeof L);
    L.tty = isatty(fileno(stderr));
    hx_command_line(cmdline, sizeof cmdline, "harness live", argc, argv);
    hx_traj_set_config(&L.traj, &nopt, &ncfg); /* the summary's config line, as replay's */
    fnav_wire_decoder_init(&L.dec);
    L.nav = &nav;
    L.axes = hx_axes_new((double)ncfg.stance.min_zupt_cycle); /* NULL: out of memory, not checked */
    L.record_path = hx_arg(&a, "--record");
    L.baud = baud;
    if (plot_every > 0.0) {
        L.hist.cap = 20000u;
        L.hist.t = calloc(L.hist.cap, sizeof(double));
        L.hist.a = calloc(L.hist.cap, sizeof(double));
        L.hist.w = calloc(L.hist.cap, sizeof(double));
        if (L.hist.t == NULL || L.hist.a == NULL || L.hist.w == NULL) {
            hx_error(CMD, "out of memory");
            live_free(&L);
            return HX_EXIT_IO;
        }
    }
    port = hx_serial_open(a.pos[0], (int)baud, HX_SERIAL_READ, err, sizeof err);
    if (port == NULL) {
        hx_error(CMD, "%s", err);
        live_free(&L);
        return HX_EXIT_IO;
    }
    if (out_path != NULL) {
        L.csv = (strcmp(out_path, "-") == 0) ? stdout : fopen(out_path, "w");
        if (L.csv == NULL) {
            hx_error(CMD, "cannot write %s: %s", out_path, strerror(errno));
            hx_serial_close(port);
            live_free(&L);
            return HX_EXIT_IO;
        }
    }
    fnav_linux_port_init(&L.lport, &L.lctx, NULL, L.csv);
    memset(&g_sa_second, 0, sizeof g_sa_second);
    g_sa_second.sa_handler = on_signal;
    sigemptyset(&g_sa_second.sa_mask);
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sa.sa_flags = SA_RESTART; /* on_signal, above */
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    /* a closed reader of --out - (live ... | head) is a write error with a
     * summary and a closed recording, not a silent death by SIGPIPE */
    signal(SIGPIPE, SIG_IGN);
    hx_eprintf("harness live: reading %s at %ld baud\n", hx_serial_path(port), baud);

    idle_flush_s = (timeout > 0.0 && timeout < 2.0 * IDLE_FLUSH_S) ? 0.5 * timeout : IDLE_FLUSH_S;
    t0 = hx_now_s();
    t_last_frame = t0;
    t_last_byte = t0;
    t_next_print = t0 + print_every;
    t_next_plot = t0 + plot_every;
    while (!g_stop && !L.have_end && !L.rec_failed && !L.restarted) {
        uint8_t buf[4096];
        long n = hx_serial_read(port, buf, sizeof buf, READ_TIMEOUT_MS);
        double now;
        size_t pos = 0;
        if (n == HX_SERIAL_GONE) {
            if (!g_stop) {
                gone = 1;
                snprintf(gone_msg, sizeof gone_msg, "%s", hx_serial_error(port));
            }
            break;
        }
        for (;;) {
            size_t used;
            fnav_wire_frame_t f;
            if (fnav_wire_decode(&L.dec, buf + pos, (size_t)n - pos, &used, &f) != FNAV_OK) {
                break;
            }
            pos += used;
            on_frame(&L, &f);
            t_last_frame = hx_now_s();
            if (L.have_end || L.restarted) {
                break; /* anything after END belongs to the next run */
            }
        }
        now = hx_now_s();
        if (n > 0) {
            t_last_byte = now;
            L.idle_cut = 0u; /* bytes after it: not the last thing on the line */
        } else if (L.dec.fill > 0u && now - t_last_byte >= idle_flush_s) {
            uint32_t frames_before = L.dec.stats.frames;
            flush_link(&L, 0);
            if (L.dec.stats.frames != frames_before) {
                t_last_frame = now;
            }
        }
        if (timeout > 0.0 && now - t_last_frame > timeout) {
            timed_out = 1;
            break;
        }
        if (print_every > 0.0 && now >= t_next_print) {
            print_status(&L, now - t_last_frame);
            t_next_print = now + print_every;
        }
        if (plot_every > 0.0 && now >= t_next_plot) {
            plot_async(&L, plot_png);
            t_next_plot = now + plot_every;
        }
    }
    /* the frames still held behind an incomplete one (Ctrl-C, a hang-up or
     * --timeout came before the line was quiet for idle_flush_s) */
    flush_link(&L, g_stop && !gone && !timed_out);
    if (L.back_run > 0u && run_after_p(&L) && (L.n_acc < 2u || !(frame_interval(&L) > 0.0))) {
        /* the run ended (END, a signal) before BACK_RUN_MAX samples came
         * behind a held sample that nothing before it could judge (the
         * first, or no interval known): they rising after it, it was the
         * one ahead */
        take_back(&L);
    }
    release_held(&L); /* the last sample taken, held back by one */
    /* how the run ended: a signal that comes later (while the last picture
     * is drawn) ends nothing, so the summary does not say "stopped by
     * SIGINT" after a --timeout, a hang-up or a restart */
    stop_sig = (gone || timed_out || L.restarted) ? 0 : (int)g_stop;
    end_status_line(&L);
    snprintf(port_path, sizeof port_path, "%s", hx_serial_path(port));
    hx_serial_close(port);

    /* the recording first: it must be complete whatever happens below */
    const int rewritten = update_recording_header(&L);
    if (rewritten && !L.have_info) {
        /* no INFO: the samples' own temperatures, the first ones without */
        hx_eprintf("harness live: %s: the header was written again at the end: samples after the first carried "
                        "a temperature (no INFO frame came)\n", L.record_path);
    } else if (rewritten) {
        const int info_changed = !L.hdr_has_info || L.hdr_info.rate_hz != L.info.rate_hz ||
                                 info_flags_differ(&L.hdr_info, &L.info) || strcmp(L.hdr_info.sensor, L.info.sensor) != 0 ||
                                 strcmp(L.hdr_info.axes, L.info.axes) != 0;
        const int no_seq = (L.info.flags & FNAV_WIRE_INFO_SEQ) != 0u && L.seq_undeclared;
        hx_eprintf("harness live: %s: the header was written again at the end with the sender's last INFO "
                        "frame (%s%s%s)\n",
                L.record_path, !L.hdr_has_info ? "none had come by the first sample"
                               : L.rate_changed ? "it changed during the session; the rate given as unknown"
                               : info_changed   ? "it changed during the session"
                                                : "",
                info_changed && no_seq ? "; " : "",
                no_seq ? "samples came without the sensor counter it announces: the header gives none" : "");
    }
    if (L.rec != NULL) {
        char werr[HX_ERR_SIZE];
        if (hx_writer_close(L.rec, werr, sizeof werr) != FNAV_OK) {
            hx_error(CMD, "%s", werr);
            L.rec_failed = 1;
        }
    }
    /* the frames the detector still holds, as replay does at the end */
    nav_finish(&L);
    {
        int csv_errno = L.lctx.write_errno; /* a frame's failed write: its reason */
        errno = 0;                          /* set only by a failed call: the reason of this one */
        if (L.csv != NULL && (L.csv == stdout ? fflush(L.csv) != 0 || ferror(L.csv) : fclose(L.csv) != 0)) {
            if (!L.csv_failed) {
                csv_errno = errno;
            }
            L.csv_failed = 1;
        }
        if (L.csv_failed && out_path != NULL) {
            char note[128];
            /* --out -: said as replay says it, not "cannot write - (Broken pipe)" */
            if (strcmp(out_path, "-") == 0) {
                hx_error(CMD, "cannot write the trajectory to standard output%s",
                         hx_errno_note(csv_errno, note, sizeof note));
            } else {
                hx_error(CMD, "cannot write %s%s", out_path, hx_errno_note(csv_errno, note, sizeof note));
            }
        }
    }
    if (L.plot_pid > 0) {
        while (waitpid(L.plot_pid, NULL, 0) < 0 && errno == EINTR) {
        }
        L.plot_pid = 0;
    }
    if (plot_every > 0.0 && L.hist.n > 0u) {
        /* the final picture is an output like the others: its child's exit
         * status is looked at, so that a picture gnuplot failed to draw
         * does not exit 0 */
        int st = 0;
        pid_t w = -1;
        plot_async(&L, plot_png);
        /* a signal after the one that ended the run interrupts the wait
         * (that handler has no SA_RESTART), not the picture: wait on */
        while (L.plot_pid > 0 && (w = waitpid(L.plot_pid, &st, 0)) < 0 && errno == EINTR) {
        }
        if (L.plot_pid <= 0 || w < 0 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
            hx_error(CMD, "the last picture %s was not drawn (the error above)", plot_png);
            L.plot_failed = 1;
        }
        L.plot_pid = 0;
    }

    {
        const fnav_wire_stats_t *s = &L.dec.stats;
        FILE *sum_out = (L.csv == stdout) ? stderr : stdout;
        double span = span_s(&L);
        /* END counts the sender's samples since its own start: after a
         * restart of the frame sequence with the clock going on (the
         * session went on), those since the restart (which said so) */
        /* (a sender counts since its own start: after a restart of the
         * frame sequence those since, unless END counts them all exactly) */
        const uint32_t since = L.samples - L.samples_at_restart;
        const int end_since = L.have_end && L.have_seq_restart && since != L.samples && L.end_count != L.samples;
        const uint32_t got = end_since ? since : L.samples;
        uint32_t missing = L.have_end && L.end_count > got ? L.end_count - got : 0u;
        uint32_t extra = L.have_end && got > L.end_count ? got - L.end_count : 0u;
        /* corrupt frames that may have held data: not the noise between two
         * frames in sequence, nor the frame a Ctrl-C cut */
        uint32_t bad_frames = s->bad_frames - L.noise - L.cut;
        const char *end_how = L.have_end ? "END frame"
                              : stop_sig ? (stop_sig == SIGINT ? "SIGINT" : (stop_sig == SIGTERM ? "SIGTERM" : "SIGHUP"))
                              : timed_out ? "timeout"
                              : gone      ? "port gone"
                              : L.restarted ? (L.clock_back ? "clock went back" : "sender restarted")
                              : L.rec_failed ? "recording failed"
                                             : "unknown";
        char what[120] = "";
        if (L.samples == 0u) {
            describe_nothing(&L, what, sizeof what);
        }
        /* the verdict on the data, before the JSON that states it
         * ("complete" and the link counters, so that a run with lost frames
         * does not write the JSON of a clean one) */
        if (gone) {
            snprintf(why, sizeof why, "%s", gone_msg);
        } else if (timed_out) {
            snprintf(why, sizeof why, "no valid frame for %.1f s (--timeout)%s%s", timeout, what[0] ? ": " : "", what);
        } else if (L.restarted && L.clock_back) {
            snprintf(why, sizeof why,
                     "the sender's clock went back from %.6f s to %.6f s at sample frame seq %u and stayed behind for "
                     "%d samples while the frame sequence went on (its clock reset, or a stamp before was far ahead)",
                     L.restart_from_s, L.restart_to_s, L.restart_seq, BACK_RUN_MAX);
        } else if (L.restarted) {
            snprintf(why, sizeof why, "the sender restarted: time went back from %.6f s to %.6f s at sample frame seq %u",
                     L.restart_from_s, L.restart_to_s, L.restart_seq);
        } else if (L.rec_failed && !L.have_end && !stop_sig) {
            snprintf(why, sizeof why, "the recording failed; the run stopped there");
        } else if (s->lost > 0u || bad_frames > 0u || L.bad_samples > 0u || L.bad_info > 0u || missing > 0u ||
                   extra > 0u) {
            snprintf(why, sizeof why,
                     "incomplete: %u frames lost, %u corrupt frames, %u bad samples, %u bad INFO frames, "
                     "%u samples missing, %u more than the sender sent",
                     (unsigned)s->lost, (unsigned)bad_frames, (unsigned)L.bad_samples, (unsigned)L.bad_info,
                     (unsigned)missing, (unsigned)extra);
        } else if (L.samples == 0u) {
            snprintf(why, sizeof why, "no sample received from %s: %s", a.pos[0], what);
        }
        /* not said in the text summary (-1): its replay-style "stopped after N
         * samples, at the input error above" is not live's case (a run that
         * lost frames went on to its END frame, and the error comes below);
         * live's own "live: end:" line says how the run ended */
        L.traj.input_complete = -1;
        if (L.traj.aligned || json_path != NULL) {
            /* --json is always written, as replay's, also without a frame:
             * an earlier run's file must not stay beside the emptied --out */
            hx_nav_summary_t sum;
            hx_nav_summarize(&L.traj, &sum);
            if (L.traj.aligned) {
                if (L.traj.axes.problem || L.traj.axes.time_problem) {
                    hx_warn(CMD, "%s: %s", a.pos[0], L.traj.axes.msg);
                }
                hx_nav_print_summary(sum_out, a.pos[0], &L.traj, &sum);
            }
            /* as replay's: written unaligned too ("aligned": false) */
            if (json_path != NULL) {
                cJSON *x = cJSON_CreateObject(), *link = cJSON_CreateObject();
                L.traj.input_complete = why[0] == '\0';
                snprintf(L.traj.input_error, sizeof L.traj.input_error, "%.500s", why);
                cJSON_AddStringToObject(link, "port", port_path);
                cJSON_AddStringToObject(link, "end", end_how);
                cJSON_AddNumberToObject(link, "samples", (double)L.samples);
                cJSON_AddItemToObject(link, "recorded", L.record_path != NULL ? cJSON_CreateNumber((double)L.recorded)
                                                                               : cJSON_CreateNull());
                cJSON_AddItemToObject(link, "end_count", L.have_end ? cJSON_CreateNumber((double)L.end_count)
                                                                     : cJSON_CreateNull());
                cJSON_AddNumberToObject(link, "frames", (double)s->frames);
                cJSON_AddNumberToObject(link, "bad_frames", (double)(s->bad_frames - L.cut));
                cJSON_AddNumberToObject(link, "unknown_frames", (double)L.by_type[0]);
                cJSON_AddNumberToObject(link, "noise_frames", (double)L.noise);
                cJSON_AddNumberToObject(link, "cut_frames", (double)L.cut);
                cJSON_AddNumberToObject(link, "lost_frames", (double)s->lost);
                cJSON_AddNumberToObject(link, "drops", (double)s->gaps);
                cJSON_AddNumberToObject(link, "bad_samples", (double)L.bad_samples);
                cJSON_AddNumberToObject(link, "bad_stamps", (double)L.bad_stamps);
                cJSON_AddNumberToObject(link, "bad_info", (double)L.bad_info);
                cJSON_AddNumberToObject(link, "skipped_bytes", (double)s->skipped_bytes);
                cJSON_AddNumberToObject(link, "sequence_restarts", (double)(s->resets - L.seq_repeats));
                cJSON_AddNumberToObject(link, "repeated_samples", (double)L.repeated);
                cJSON_AddNumberToObject(link, "sensor_missing", (double)L.sensor_missing);
                cJSON_AddNumberToObject(link, "wall_s", hx_now_s() - t0);
                cJSON_AddBoolToObject(link, "summary_partial", L.traj_partial);
                cJSON_AddItemToObject(x, "link", link);
                if (hx_nav_write_json(json_path, a.pos[0], cmdline, &L.traj, &sum, x, err, sizeof err) != 0) {
                    hx_error(CMD, "%s", err);
                    L.csv_failed = 1;
                }
            }
        }
        if (!L.traj.aligned && L.samples > 0u) {
            fprintf(sum_out, "live: no navigation: the filter never aligned (the foot must be still at the start)\n");
        }
        char shown[4096]; /* a file name's control characters as '?' (hx_line_str), as in the messages */
        fprintf(sum_out, "live: %s: %u samples over %.3f s of sensor time (%.1f Hz), %.1f s of wall time\n",
               hx_line_str(shown, sizeof shown, a.pos[0]),
               (unsigned)L.samples, span, span > 0.0 ? (double)(L.samples - 1u) / span : 0.0, hx_now_s() - t0);
        fprintf(sum_out, "live: frames: %u valid (info %u, sample %u, nav %u, status %u, end %u, unknown %u)\n",
               (unsigned)s->frames, (unsigned)L.by_type[FNAV_WIRE_INFO], (unsigned)L.by_type[FNAV_WIRE_SAMPLE],
               (unsigned)L.by_type[FNAV_WIRE_NAV], (unsigned)L.by_type[FNAV_WIRE_STATUS],
               (unsigned)L.by_type[FNAV_WIRE_END], (unsigned)L.by_type[0]);
        {
            char noise[80] = "";
            char stamps[80] = "";
            if (L.noise > 0u) {
                snprintf(noise, sizeof noise, " (%u of them noise between intact frames)", (unsigned)L.noise);
            }
            if (L.bad_stamps > 0u) {
                snprintf(stamps, sizeof stamps, " (%u of them time stamps out of order)", (unsigned)L.bad_stamps);
            }
            fprintf(sum_out, "live: link: %u bad frames%s, %u lost frames in %u drops, %u bad samples%s, %u bytes "
                   "skipped, %u sequence restarts, %u repeated sample frames skipped\n",
                   (unsigned)(s->bad_frames - L.cut), noise, (unsigned)s->lost, (unsigned)s->gaps,
                   (unsigned)L.bad_samples, stamps, (unsigned)s->skipped_bytes, (unsigned)(s->resets - L.seq_repeats),
                   (unsigned)L.repeated);
        }
        if (L.sensor_missing > 0u) {
            fprintf(sum_out, "live: sensor: %u samples missing by the sensor's counter in %u gaps (lost on the "
                             "sender, not on the link)\n",
                    (unsigned)L.sensor_missing, (unsigned)L.sensor_gaps);
        }
        if (L.have_info) {
            fprintf(sum_out, "live: sender: %s, %.6g Hz%s\n", L.info.sensor[0] ? L.info.sensor : "(unnamed)",
                    L.info.rate_hz, (L.info.flags & FNAV_WIRE_INFO_RATE_NOMINAL) ? " nominal" : "");
        }
        if (L.have_status) {
            fprintf(sum_out,
                    "live: sender status: %u samples processed, %u overruns, %u estimator errors, %u frames not sent\n",
                    (unsigned)L.status.samples, (unsigned)L.status.overruns, (unsigned)L.status.est_errors,
                    (unsigned)L.status.tx_dropped);
        }
        if (L.record_path != NULL && L.rec != NULL) {
            /* what the file holds, not what was received (after a write
             * error the rest of the read is not counted) */
            fprintf(sum_out, "live: recorded %u samples to %s%s\n", (unsigned)L.recorded,
                    hx_line_str(shown, sizeof shown, L.record_path),
                   L.rec_failed ? " (recording failed, see above)" : "");
        } else if (L.record_path != NULL) {
            fprintf(sum_out, "live: nothing recorded: no sample was received (%s not written)\n",
                    hx_line_str(shown, sizeof shown, L.record_path));
        }
        if (L.samples == 0u && L.by_type[FNAV_WIRE_NAV] > 0u) {
            fprintf(sum_out, "live: the sender sends NAV frames but no SAMPLE frames: live navigates and records "
                             "raw samples (the reference firmware sends them with sample_every = 1, "
                             "docs/firmware.md)\n");
        }
        if (L.have_end && end_since) {
            fprintf(sum_out, "live: end: END frame, the sender sent %u samples since it restarted, %u received "
                             "since (%u in all)\n",
                    (unsigned)L.end_count, (unsigned)since, (unsigned)L.samples);
        } else if (L.have_end) {
            fprintf(sum_out, "live: end: END frame, the sender sent %u samples, %u received\n", (unsigned)L.end_count,
                   (unsigned)L.samples);
        } else if (L.restarted) {
            fprintf(sum_out, "live: end: %s\n",
                    L.clock_back ? "the sender's clock went back" : "the sender restarted");
        } else if (L.rec_failed && !stop_sig) {
            fprintf(sum_out, "live: end: the recording failed\n");
        } else if (stop_sig) {
            /* how the run ended, said as for END and a vanished port */
            fprintf(sum_out, "live: end: stopped by %s%s\n",
                    stop_sig == SIGINT ? "SIGINT (Ctrl-C)" : (stop_sig == SIGTERM ? "SIGTERM" : "SIGHUP"),
                    L.cut > 0u ? "; the frame arriving then was cut (not counted as corrupt)" : "");
        } else if (timed_out) {
            fprintf(sum_out, "live: end: no valid frame for %.1f s (--timeout)\n", timeout);
        } else if (gone) {
            fprintf(sum_out, "live: end: the port went away\n");
            if (L.record_path != NULL) {
                hx_error(CMD, "%s; %u samples were received before it, %u recorded", gone_msg, (unsigned)L.samples,
                         (unsigned)L.recorded);
            } else {
                hx_error(CMD, "%s; the %u samples received before it are navigated", gone_msg, (unsigned)L.samples);
            }
        }
        if (L.restarted) {
            hx_error(CMD, "%s; stopped there (the %u samples before it are recorded and navigated; run live again "
                          "for the new session)",
                     why, (unsigned)L.samples);
        }
        if (L.rec_failed || L.csv_failed || L.plot_failed) {
            exit_code = HX_EXIT_IO;
        } else if (gone || timed_out || L.restarted) {
            exit_code = HX_EXIT_DATA;
        } else if (why[0] != '\0') {
            hx_error(CMD, "%s", why); /* incomplete: ..., or no sample received */
            exit_code = HX_EXIT_DATA;
        }
        if (timed_out) {
            hx_error(CMD, "no valid frame for %.1f s (--timeout); giving up%s%s", timeout, what[0] ? ": " : "",
                     what);
        } else if (L.samples == 0u && exit_code == HX_EXIT_OK) {
            /* nothing to navigate or record is not a complete stream, as
             * replay of an empty log exits 1 (also after Ctrl-C) */
            hx_error(CMD, "no sample received from %s: %s", a.pos[0], what);
            exit_code = HX_EXIT_DATA;
        }
    }
    live_free(&L);
    return exit_code;
}
