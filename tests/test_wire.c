/* Wire protocol: the C encoder and decoder against the independent Python
 * implementation (vectors/wire/gen_wire.py), round trips of every frame
 * type, resynchronisation after damage, sequence accounting, bad arguments. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <float.h>
#include <string.h>
#include <zlib.h>

#include <cmocka.h>

#include "footnav/fnav_wire.h"
#include "fnav_testdata.h"

#define MAXBYTES 4096
#define MAXLINES 64

typedef struct {
    char line[MAXLINES][400];
    int n;
} lines_t;

static size_t read_file(const char *rel, uint8_t *buf, size_t size)
{
    char path[512];
    FILE *f;
    size_t n;
    if (fnav_vector_path(rel, path, sizeof path) != 0) {
        fail_msg("missing vector %s", rel);
    }
    f = fopen(path, "rb");
    assert_non_null(f);
    n = fread(buf, 1, size, f);
    assert_true(feof(f));
    fclose(f);
    /* an empty vector leaves the chunked decode and the re-encoding with
     * nothing to compare (they passed on an empty frames.bin) */
    if (n == 0) {
        fail_msg("vector %s is empty", rel);
    }
    return n;
}

static void read_lines(const char *rel, lines_t *l)
{
    static uint8_t buf[MAXBYTES];
    size_t n = read_file(rel, buf, sizeof buf - 1);
    char *p, *save = NULL;
    buf[n] = 0;
    l->n = 0;
    for (p = strtok_r((char *)buf, "\n", &save); p != NULL; p = strtok_r(NULL, "\n", &save)) {
        assert_true(l->n < MAXLINES);
        snprintf(l->line[l->n++], sizeof l->line[0], "%s", p);
    }
}

static const char *g9(char *b, double v)
{
    snprintf(b, 32, "%.9g", v);
    return b;
}

/* The text line gen_wire.py's describe() writes for a frame. */
static void describe(const fnav_wire_frame_t *f, char *out, size_t size)
{
    char b[9][32];
    switch (f->type) {
    case FNAV_WIRE_SAMPLE: {
        fnav_sample_t s;
        assert_int_equal(fnav_wire_parse_sample(f, &s), FNAV_OK);
        snprintf(out, size, "sample %u %lld %u %u %s %s %s %s %s %s %s", f->seq, (long long)s.t_ns, s.seq,
                 s.flags, g9(b[0], (double)s.accel_mps2[0]), g9(b[1], (double)s.accel_mps2[1]),
                 g9(b[2], (double)s.accel_mps2[2]), g9(b[3], (double)s.gyro_rps[0]),
                 g9(b[4], (double)s.gyro_rps[1]), g9(b[5], (double)s.gyro_rps[2]), g9(b[6], (double)s.temp_c));
        break;
    }
    case FNAV_WIRE_NAV: {
        fnav_wire_nav_t v;
        assert_int_equal(fnav_wire_parse_nav(f, &v), FNAV_OK);
        snprintf(out, size, "nav %u %lld %u %u %u %s %s %s %s %s %s %s %s %s", f->seq, (long long)v.t_ns, v.seq,
                 v.flags, v.health, g9(b[0], (double)v.pos_m[0]), g9(b[1], (double)v.pos_m[1]),
                 g9(b[2], (double)v.pos_m[2]), g9(b[3], (double)v.vel_mps[0]), g9(b[4], (double)v.vel_mps[1]),
                 g9(b[5], (double)v.vel_mps[2]), g9(b[6], (double)v.euler_rad[0]),
                 g9(b[7], (double)v.euler_rad[1]), g9(b[8], (double)v.euler_rad[2]));
        break;
    }
    case FNAV_WIRE_STATUS: {
        fnav_wire_status_t st;
        assert_int_equal(fnav_wire_parse_status(f, &st), FNAV_OK);
        snprintf(out, size, "status %u %u %u %u %u %u", f->seq, st.samples, st.overruns, st.est_errors,
                 st.tx_dropped, st.uptime_ms);
        break;
    }
    case FNAV_WIRE_INFO: {
        fnav_wire_info_t in;
        assert_int_equal(fnav_wire_parse_info(f, &in), FNAV_OK);
        snprintf(out, size, "info %u %.17g %u %s|%s", f->seq, in.rate_hz, in.flags, in.sensor, in.axes);
        break;
    }
    case FNAV_WIRE_END: {
        uint32_t c;
        assert_int_equal(fnav_wire_parse_end(f, &c), FNAV_OK);
        snprintf(out, size, "end %u %u", f->seq, c);
        break;
    }
    default:
        snprintf(out, size, "unknown %u %u %u", f->seq, f->type, f->len);
        break;
    }
}

/* Feed a stream in chunks of `chunk` bytes; collect the frame lines. */
static void decode_stream(const uint8_t *in, size_t n, size_t chunk, lines_t *out, fnav_wire_decoder_t *d)
{
    size_t off = 0;
    fnav_wire_decoder_init(d);
    out->n = 0;
    while (off < n) {
        size_t k = (n - off < chunk) ? n - off : chunk;
        size_t pos = 0;
        for (;;) {
            size_t used;
            fnav_wire_frame_t f;
            fnav_status_t st = fnav_wire_decode(d, in + off + pos, k - pos, &used, &f);
            pos += used;
            if (st == FNAV_AGAIN) {
                break;
            }
            assert_int_equal(st, FNAV_OK);
            assert_true(out->n < MAXLINES);
            describe(&f, out->line[out->n], sizeof out->line[0]);
            out->n++;
        }
        assert_int_equal(pos, k);
        off += k;
    }
}

static void test_crc32(void **state)
{
    static const uint8_t check[] = "123456789";
    uint8_t buf[1000];
    size_t i;
    (void)state;
    assert_int_equal(fnav_crc32(0u, check, 9), 0xCBF43926u);
    assert_int_equal(fnav_crc32(0u, check, 0), 0u);
    srand(7);
    for (i = 0; i < sizeof buf; i++) {
        buf[i] = (uint8_t)(rand() & 0xFF);
    }
    /* against zlib, whole and continued */
    assert_int_equal(fnav_crc32(0u, buf, sizeof buf), (uint32_t)crc32(0L, buf, (uInt)sizeof buf));
    assert_int_equal(fnav_crc32(fnav_crc32(0u, buf, 333), buf + 333, sizeof buf - 333),
                     (uint32_t)crc32(0L, buf, (uInt)sizeof buf));
}

/* The decoder delivers exactly what the independent decoder found, for
 * every chunking of the input. */
static void test_decode_golden_clean(void **state)
{
    static uint8_t bin[MAXBYTES];
    static lines_t want, got;
    fnav_wire_decoder_t d;
    size_t n, chunk;
    int i;
    (void)state;
    n = read_file("wire/frames.bin", bin, sizeof bin);
    read_lines("wire/frames.txt", &want);
    assert_int_equal(want.n, 9);
    for (chunk = 1; chunk <= n; chunk += (chunk < 70) ? 1u : 97u) {
        decode_stream(bin, n, chunk, &got, &d);
        assert_int_equal(got.n, want.n);
        for (i = 0; i < want.n; i++) {
            assert_string_equal(got.line[i], want.line[i]);
        }
        assert_int_equal(d.stats.frames, 9);
        assert_int_equal(d.stats.bad_frames, 0);
        assert_int_equal(d.stats.skipped_bytes, 0);
        assert_int_equal(d.stats.lost, 0);
        assert_int_equal(d.stats.gaps, 0);
        assert_int_equal(d.stats.resets, 0);
        assert_int_equal(d.stats.unknown, 1);
    }
}

static void test_decode_golden_corrupt(void **state)
{
    static uint8_t bin[MAXBYTES];
    static lines_t want, got;
    fnav_wire_decoder_t d;
    size_t n, chunk;
    unsigned fr, bad, skip, lost, gaps, resets, unk;
    int i;
    (void)state;
    n = read_file("wire/corrupt.bin", bin, sizeof bin);
    read_lines("wire/corrupt.txt", &want);
    assert_true(want.n >= 2);
    assert_int_equal(sscanf(want.line[want.n - 1], "stats %u %u %u %u %u %u %u", &fr, &bad, &skip, &lost, &gaps,
                            &resets, &unk),
                     7);
    want.n--; /* the last line holds the counters */
    for (chunk = 1; chunk <= n; chunk += (chunk < 70) ? 1u : 61u) {
        decode_stream(bin, n, chunk, &got, &d);
        assert_int_equal(got.n, want.n);
        for (i = 0; i < want.n; i++) {
            assert_string_equal(got.line[i], want.line[i]);
        }
        assert_int_equal(d.stats.frames, fr);
        assert_int_equal(d.stats.bad_frames, bad);
        assert_int_equal(d.stats.skipped_bytes, skip);
        assert_int_equal(d.stats.lost, lost);
        assert_int_equal(d.stats.gaps, gaps);
        assert_int_equal(d.stats.resets, resets);
        assert_int_equal(d.stats.unknown, unk);
        assert_int_equal(d.fill, 3); /* the trailing partial header waits for more */
    }
}

/* Encoding the decoded content again reproduces the Python bytes exactly. */
static void test_encode_golden(void **state)
{
    static uint8_t bin[MAXBYTES], out[MAXBYTES];
    fnav_wire_decoder_t d;
    size_t n, pos = 0, o = 0;
    (void)state;
    n = read_file("wire/frames.bin", bin, sizeof bin);
    fnav_wire_decoder_init(&d);
    for (;;) {
        size_t used, k = 0;
        fnav_wire_frame_t f;
        fnav_status_t st = fnav_wire_decode(&d, bin + pos, n - pos, &used, &f);
        pos += used;
        if (st == FNAV_AGAIN) {
            break;
        }
        switch (f.type) {
        case FNAV_WIRE_SAMPLE: {
            fnav_sample_t s;
            assert_int_equal(fnav_wire_parse_sample(&f, &s), FNAV_OK);
            k = fnav_wire_encode_sample(out + o, sizeof out - o, f.seq, &s);
            break;
        }
        case FNAV_WIRE_NAV: {
            fnav_wire_nav_t v;
            fnav_nav_frame_t nf;
            int i;
            assert_int_equal(fnav_wire_parse_nav(&f, &v), FNAV_OK);
            memset(&nf, 0, sizeof nf);
            nf.t_ns = v.t_ns;
            nf.seq = v.seq;
            nf.flags = v.flags;
            nf.health = v.health;
            for (i = 0; i < 3; i++) {
                nf.pos_m[i] = (fnav_real_t)v.pos_m[i];
                nf.vel_mps[i] = (fnav_real_t)v.vel_mps[i];
                nf.euler_rad[i] = (fnav_real_t)v.euler_rad[i];
            }
            k = fnav_wire_encode_nav(out + o, sizeof out - o, f.seq, &nf);
            break;
        }
        case FNAV_WIRE_STATUS: {
            fnav_wire_status_t st2;
            assert_int_equal(fnav_wire_parse_status(&f, &st2), FNAV_OK);
            k = fnav_wire_encode_status(out + o, sizeof out - o, f.seq, &st2);
            break;
        }
        case FNAV_WIRE_INFO: {
            fnav_wire_info_t in;
            assert_int_equal(fnav_wire_parse_info(&f, &in), FNAV_OK);
            k = fnav_wire_encode_info(out + o, sizeof out - o, f.seq, &in);
            break;
        }
        case FNAV_WIRE_END: {
            uint32_t c;
            assert_int_equal(fnav_wire_parse_end(&f, &c), FNAV_OK);
            k = fnav_wire_encode_end(out + o, sizeof out - o, f.seq, c);
            break;
        }
        default:
            k = fnav_wire_encode(out + o, sizeof out - o, f.type, f.seq, f.payload, f.len);
            break;
        }
        assert_int_equal(k, FNAV_WIRE_FRAME_SIZE(f.len));
        o += k;
    }
    assert_int_equal(o, n);
    assert_memory_equal(out, bin, n);
}

static void test_roundtrip_and_sizes(void **state)
{
    uint8_t buf[FNAV_WIRE_MAX_FRAME + 8];
    fnav_sample_t s, r;
    fnav_wire_info_t info, info2;
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t k, used;
    int i;
    (void)state;
    memset(&s, 0, sizeof s);
    s.t_ns = INT64_MIN;
    s.seq = 0xDEADBEEFu;
    s.flags = FNAV_SAMPLE_HAS_TEMP | FNAV_SAMPLE_HAS_SEQ;
    for (i = 0; i < 3; i++) {
        s.accel_mps2[i] = FNAV_R(0.1) * (fnav_real_t)(i + 1);
        s.gyro_rps[i] = -FNAV_R(0.25) * (fnav_real_t)(i + 1);
    }
    s.temp_c = FNAV_R(36.5);
    k = fnav_wire_encode_sample(buf, sizeof buf, 77u, &s);
    assert_int_equal(k, FNAV_WIRE_FRAME_SIZE(FNAV_WIRE_SAMPLE_LEN));
    assert_int_equal(k, 51);
    fnav_wire_decoder_init(&d);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(used, k);
    assert_int_equal(f.seq, 77);
    assert_int_equal(fnav_wire_parse_sample(&f, &r), FNAV_OK);
    assert_true(r.t_ns == INT64_MIN);
    assert_int_equal(r.seq, 0xDEADBEEFu);
    assert_int_equal(r.flags, s.flags);
    for (i = 0; i < 3; i++) {
        /* float32 on the wire: exact in the float build, rounded once in double */
        assert_true((float)r.accel_mps2[i] == (float)s.accel_mps2[i]);
        assert_true((float)r.gyro_rps[i] == (float)s.gyro_rps[i]);
    }
    assert_true(r.temp_c == s.temp_c);
    /* wrong parser for the type */
    {
        fnav_wire_nav_t v;
        uint32_t c;
        assert_int_equal(fnav_wire_parse_nav(&f, &v), FNAV_E_FORMAT);
        assert_int_equal(fnav_wire_parse_end(&f, &c), FNAV_E_FORMAT);
    }
    assert_int_equal(fnav_wire_decode(&d, NULL, 0, &used, &f), FNAV_AGAIN);

    /* INFO: over-long text is cut, always NUL-terminated */
    memset(&info, 'x', sizeof info);
    info.rate_hz = 819.2;
    info.flags = FNAV_WIRE_INFO_RATE_NOMINAL;
    info.sensor[FNAV_WIRE_SENSOR_SIZE - 1] = '\0';
    info.axes[FNAV_WIRE_AXES_SIZE - 1] = '\0';
    k = fnav_wire_encode_info(buf, sizeof buf, 1u, &info);
    assert_int_equal(k, FNAV_WIRE_FRAME_SIZE(FNAV_WIRE_INFO_LEN));
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_info(&f, &info2), FNAV_OK);
    assert_true(info2.rate_hz == 819.2);
    assert_int_equal(strlen(info2.sensor), FNAV_WIRE_SENSOR_SIZE - 1);
    assert_int_equal(strlen(info2.axes), FNAV_WIRE_AXES_SIZE - 1);

    /* sizes: exactly enough works, one byte less writes nothing */
    memset(buf, 0xEE, sizeof buf);
    assert_int_equal(fnav_wire_encode_sample(buf, 50, 0u, &s), 0);
    assert_int_equal(fnav_wire_encode_end(buf, 13, 0u, 1u), 0);
    assert_int_equal(fnav_wire_encode_end(buf, 14, 0u, 1u), 14);
    assert_int_equal(buf[14], 0xEE); /* nothing past the frame */
    assert_int_equal(fnav_wire_encode(buf, sizeof buf, 9u, 0u, buf, 256u), 0);
    assert_int_equal(fnav_wire_encode(buf, sizeof buf, 9u, 0u, NULL, 3u), 0);
    assert_int_equal(fnav_wire_encode(buf, sizeof buf, 9u, 0u, NULL, 0u), 10);
    assert_int_equal(fnav_wire_encode(NULL, 100, 9u, 0u, NULL, 0u), 0);
    {
        uint8_t big[FNAV_WIRE_MAX_PAYLOAD];
        memset(big, 0x42, sizeof big);
        assert_int_equal(fnav_wire_encode(buf, FNAV_WIRE_MAX_FRAME, 9u, 0u, big, sizeof big), FNAV_WIRE_MAX_FRAME);
        assert_int_equal(fnav_wire_decode(&d, buf, FNAV_WIRE_MAX_FRAME, &used, &f), FNAV_OK);
        assert_int_equal(f.len, 255);
        assert_memory_equal(f.payload, big, sizeof big);
    }
    assert_int_equal(fnav_wire_encode_sample(buf, sizeof buf, 0u, NULL), 0);
    /* the other typed encoders refuse a NULL record too, writing nothing
     * (make coverage: not run) */
    {
        uint8_t copy[sizeof buf];
        memset(buf, 0xEE, sizeof buf);
        memcpy(copy, buf, sizeof buf);
        assert_int_equal(fnav_wire_encode_nav(buf, sizeof buf, 0u, NULL), 0);
        assert_int_equal(fnav_wire_encode_status(buf, sizeof buf, 0u, NULL), 0);
        assert_int_equal(fnav_wire_encode_info(buf, sizeof buf, 0u, NULL), 0);
        assert_memory_equal(buf, copy, sizeof buf);
    }
    assert_int_equal(fnav_wire_decode(NULL, buf, 1, &used, &f), FNAV_E_ARG);
    assert_int_equal(fnav_wire_decode(&d, NULL, 1, &used, &f), FNAV_E_ARG);
}

/* A double build's value beyond the float range is sent as the largest
 * float of its sign (the cast itself would be undefined behaviour, C99
 * 6.3.1.5); in range it is the value rounded to
 * float, as in a float build. */
static void test_beyond_float_range(void **state)
{
    uint8_t buf[64];
    fnav_sample_t s, r;
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t used;
    (void)state;
    memset(&s, 0, sizeof s);
    s.accel_mps2[0] = (fnav_real_t)FLT_MAX;
    s.accel_mps2[1] = -(fnav_real_t)FLT_MAX;
    s.gyro_rps[2] = (fnav_real_t)1.5;
#if FNAV_USE_DOUBLE
    s.accel_mps2[0] = (fnav_real_t)1e300;
    s.accel_mps2[1] = (fnav_real_t)-4e38;
#endif
    assert_int_equal(fnav_wire_encode_sample(buf, sizeof buf, 3u, &s), 51);
    fnav_wire_decoder_init(&d);
    assert_int_equal(fnav_wire_decode(&d, buf, 51, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_sample(&f, &r), FNAV_OK);
    assert_true(r.accel_mps2[0] == (fnav_real_t)FLT_MAX);
    assert_true(r.accel_mps2[1] == -(fnav_real_t)FLT_MAX);
    assert_true(r.gyro_rps[2] == (fnav_real_t)1.5);
}

/* A CRC-valid sample with a NaN is reported, not delivered. */
static void test_sample_nan(void **state)
{
    uint8_t buf[64];
    fnav_sample_t s, r;
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t used;
    (void)state;
    memset(&s, 0, sizeof s);
    s.gyro_rps[1] = (fnav_real_t)NAN;
    assert_int_equal(fnav_wire_encode_sample(buf, sizeof buf, 0u, &s), 51);
    fnav_wire_decoder_init(&d);
    assert_int_equal(fnav_wire_decode(&d, buf, 51, &used, &f), FNAV_OK);
    memset(&r, 0x5A, sizeof r);
    assert_int_equal(fnav_wire_parse_sample(&f, &r), FNAV_E_NANINF);
    assert_int_equal(r.seq, 0x5A5A5A5Au); /* unchanged */
    /* the temperature: NaN is "none" without FNAV_SAMPLE_HAS_TEMP, an
     * error with it (as the header says) */
    s.gyro_rps[1] = FNAV_R(0.0);
    s.temp_c = (fnav_real_t)NAN;
    assert_int_equal(fnav_wire_encode_sample(buf, sizeof buf, 1u, &s), 51);
    assert_int_equal(fnav_wire_decode(&d, buf, 51, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_sample(&f, &r), FNAV_OK);
    assert_true(r.temp_c != r.temp_c);
    s.flags = FNAV_SAMPLE_HAS_TEMP;
    assert_int_equal(fnav_wire_encode_sample(buf, sizeof buf, 2u, &s), 51);
    assert_int_equal(fnav_wire_decode(&d, buf, 51, &used, &f), FNAV_OK);
    memset(&r, 0x5A, sizeof r);
    assert_int_equal(fnav_wire_parse_sample(&f, &r), FNAV_E_NANINF);
    assert_int_equal(r.seq, 0x5A5A5A5Au);
}

/* An INFO rate that is not a number in [0, 1e6] Hz (the .bin header's
 * range) is refused and nothing is written; 0 (unknown) is accepted. */
static void test_info_rate(void **state)
{
    uint8_t buf[128];
    fnav_wire_info_t info, got;
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t used, k;
    (void)state;
    fnav_wire_decoder_init(&d);
    memset(&info, 0, sizeof info);
    memset(&got, 0x5A, sizeof got);
    info.rate_hz = (double)NAN;
    k = fnav_wire_encode_info(buf, sizeof buf, 3u, &info);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_info(&f, &got), FNAV_E_RANGE);
    assert_int_equal(got.flags, 0x5A5A5A5Au); /* unchanged */
    info.rate_hz = 1.0e6 * 1.001;
    k = fnav_wire_encode_info(buf, sizeof buf, 4u, &info);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_info(&f, &got), FNAV_E_RANGE);
    info.rate_hz = -1.0;
    k = fnav_wire_encode_info(buf, sizeof buf, 5u, &info);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_info(&f, &got), FNAV_E_RANGE);
    info.rate_hz = 0.0; /* unknown */
    k = fnav_wire_encode_info(buf, sizeof buf, 6u, &info);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_info(&f, &got), FNAV_OK);
    assert_true(got.rate_hz == 0.0);
    /* the top of the range is in it, as in the .bin header ("[0, 1e6]"):
     * a mutant refusing 1e6 itself passed every test */
    info.rate_hz = 1.0e6;
    k = fnav_wire_encode_info(buf, sizeof buf, 7u, &info);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_parse_info(&f, &got), FNAV_OK);
    assert_true(got.rate_hz == 1.0e6);
}

/* Sequence accounting across the 16-bit wrap, gaps and restarts. */
static void test_seq_accounting(void **state)
{
    static const uint16_t seqs[] = { 65534, 65535, 0, 3, 4, 2, 3, 40000 };
    uint8_t buf[32];
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t used, i;
    (void)state;
    fnav_wire_decoder_init(&d);
    for (i = 0; i < sizeof seqs / sizeof seqs[0]; i++) {
        size_t k = fnav_wire_encode_end(buf, sizeof buf, seqs[i], (uint32_t)i);
        assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
        assert_int_equal(f.seq, seqs[i]);
        assert_int_equal(fnav_wire_decode(&d, NULL, 0, &used, &f), FNAV_AGAIN);
    }
    /* 0 -> 3 loses 2; 4 -> 2 is a restart; 3 -> 40000 is a backward jump of
     * more than half the range, which the 16-bit counter cannot tell from a
     * restart (documented) */
    assert_int_equal(d.stats.gaps, 1);
    assert_int_equal(d.stats.lost, 2);
    assert_int_equal(d.stats.resets, 2);
    assert_int_equal(d.stats.frames, 8);
}

/* The five frame types and their payload lengths, in one order (the
 * parser tests below walk them) */
static const uint8_t k_len[5] = { FNAV_WIRE_SAMPLE_LEN, FNAV_WIRE_NAV_LEN, FNAV_WIRE_STATUS_LEN, FNAV_WIRE_INFO_LEN,
                                  FNAV_WIRE_END_LEN };
static const uint8_t k_type[5] = { FNAV_WIRE_SAMPLE, FNAV_WIRE_NAV, FNAV_WIRE_STATUS, FNAV_WIRE_INFO, FNAV_WIRE_END };

/* Each parser refuses a frame of its type with another length (the table's
 * lengths) or of another type, and leaves the output alone: the decoder
 * never delivers such a frame, but a caller may build one. A mutant
 * dropping the NAV parser's length check passed every suite. */
static void test_parse_wrong_length(void **state)
{
    static uint8_t pay[255];
    fnav_wire_frame_t f;
    fnav_sample_t s;
    fnav_wire_nav_t nav;
    fnav_wire_status_t st;
    fnav_wire_info_t info;
    uint32_t count = 77u;
    int i, d;
    (void)state;
    assert_int_equal(k_len[0], 41); /* docs/wire-protocol.md's table */
    assert_int_equal(k_len[1], 53);
    assert_int_equal(k_len[2], 20);
    assert_int_equal(k_len[3], 92);
    assert_int_equal(k_len[4], 4);
    memset(pay, 0, sizeof pay);
    f.seq = 1u;
    f.payload = pay;
    for (i = 0; i < 5; i++) {
        for (d = -1; d <= 1; d += 2) {
            fnav_status_t r[5];
            f.type = k_type[i];
            f.len = (uint8_t)(k_len[i] + d);
            memset(&nav, 0x5A, sizeof nav);
            r[0] = fnav_wire_parse_sample(&f, &s);
            r[1] = fnav_wire_parse_nav(&f, &nav);
            r[2] = fnav_wire_parse_status(&f, &st);
            r[3] = fnav_wire_parse_info(&f, &info);
            r[4] = fnav_wire_parse_end(&f, &count);
            assert_int_equal(r[0], FNAV_E_FORMAT);
            assert_int_equal(r[1], FNAV_E_FORMAT);
            assert_int_equal(r[2], FNAV_E_FORMAT);
            assert_int_equal(r[3], FNAV_E_FORMAT);
            assert_int_equal(r[4], FNAV_E_FORMAT);
            assert_int_equal(nav.seq, 0x5A5A5A5Au);
            assert_int_equal(count, 77u);
        }
    }
}

/* A NULL frame, output or payload is an invalid argument, FNAV_E_ARG, as
 * for every other function of the core that returns a status (the
 * decoder, the port helpers): the parsers said FNAV_E_FORMAT, which their
 * comment gives for a frame of the wrong type or length, and a frame of the
 * right type and length with a NULL payload was read through it. Nothing
 * is written. */
static void test_parse_null_args(void **state)
{
    fnav_wire_frame_t f;
    fnav_sample_t s;
    fnav_wire_nav_t nav;
    fnav_wire_status_t st;
    fnav_wire_info_t info;
    uint32_t count = 77u;
    int i;
    (void)state;
    assert_int_equal(fnav_wire_parse_sample(NULL, &s), FNAV_E_ARG);
    assert_int_equal(fnav_wire_parse_nav(NULL, &nav), FNAV_E_ARG);
    assert_int_equal(fnav_wire_parse_status(NULL, &st), FNAV_E_ARG);
    assert_int_equal(fnav_wire_parse_info(NULL, &info), FNAV_E_ARG);
    assert_int_equal(fnav_wire_parse_end(NULL, &count), FNAV_E_ARG);
    f.seq = 1u;
    for (i = 0; i < 5; i++) {
        fnav_status_t r[5];
        static uint8_t pay[255];
        f.type = k_type[i];
        f.len = k_len[i];
        f.payload = pay;
        r[0] = i == 0 ? fnav_wire_parse_sample(&f, NULL) : FNAV_E_ARG;
        r[1] = i == 1 ? fnav_wire_parse_nav(&f, NULL) : FNAV_E_ARG;
        r[2] = i == 2 ? fnav_wire_parse_status(&f, NULL) : FNAV_E_ARG;
        r[3] = i == 3 ? fnav_wire_parse_info(&f, NULL) : FNAV_E_ARG;
        r[4] = i == 4 ? fnav_wire_parse_end(&f, NULL) : FNAV_E_ARG;
        assert_int_equal(r[i], FNAV_E_ARG);
        /* the right type and length, no payload */
        f.payload = NULL;
        {
            /* nothing written: each output poisoned, and compared byte for
             * byte with a copy poisoned alike */
            fnav_sample_t s0;
            fnav_wire_nav_t nav0;
            fnav_wire_status_t st0;
            fnav_wire_info_t info0;
            memset(&s, 0x5A, sizeof s);
            memset(&nav, 0x5A, sizeof nav);
            memset(&st, 0x5A, sizeof st);
            memset(&info, 0x5A, sizeof info);
            s0 = s;
            nav0 = nav;
            st0 = st;
            info0 = info;
            count = 77u;
            r[0] = fnav_wire_parse_sample(&f, &s);
            r[1] = fnav_wire_parse_nav(&f, &nav);
            r[2] = fnav_wire_parse_status(&f, &st);
            r[3] = fnav_wire_parse_info(&f, &info);
            r[4] = fnav_wire_parse_end(&f, &count);
            assert_int_equal(r[i], FNAV_E_ARG);
            assert_memory_equal(&s, &s0, sizeof s);
            assert_memory_equal(&nav, &nav0, sizeof nav);
            assert_memory_equal(&st, &st0, sizeof st);
            assert_memory_equal(&info, &info0, sizeof info);
            assert_int_equal(count, 77u);
        }
    }
}

/* The boundary of a drop (docs/wire-protocol.md, step 5): a forward jump
 * of k < 32768 frames is a gap of k lost frames, one of 32768 is a restart
 * ("a drop of 32768 frames or more in one gap is indistinguishable from a
 * restart"). A mutant taking 32768 for a drop passed every test. */
static void test_seq_gap_boundary(void **state)
{
    /* after 0, 32768 skips 32767 frames; after it, 1 (65537 mod 65536)
     * skips 32768 */
    static const uint16_t seqs[] = { 0, 32768, 1 };
    uint8_t buf[32];
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t used, i;
    (void)state;
    fnav_wire_decoder_init(&d);
    for (i = 0; i < sizeof seqs / sizeof seqs[0]; i++) {
        size_t k = fnav_wire_encode_end(buf, sizeof buf, seqs[i], (uint32_t)i);
        assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
        assert_int_equal(f.seq, seqs[i]);
    }
    assert_int_equal(d.stats.gaps, 1);
    assert_int_equal(d.stats.lost, 32767);
    assert_int_equal(d.stats.resets, 1);
}

/* A known type announced with another length is corrupt (step 2), also
 * when its CRC is right: a SAMPLE header saying 10 bytes, framed with a
 * valid CRC by the generic encoder, then an END frame. The decoder must
 * count one corrupt frame, skip its 20 bytes and deliver only END. Without
 * the length check the SAMPLE frame would be delivered as valid and every
 * other test pass (vectors/wire/corrupt.bin's wrong-length frame has a bad
 * CRC too, which fails either way). */
static void test_known_type_wrong_length(void **state)
{
    uint8_t buf[64], pay[10];
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t k, used;
    (void)state;
    memset(pay, 0x11, sizeof pay);
    k = fnav_wire_encode(buf, sizeof buf, FNAV_WIRE_SAMPLE, 7u, pay, sizeof pay);
    assert_int_equal(k, 20); /* CRC 0x593e9860 (zlib.crc32 of 01 0a 07 00 and ten 0x11): no sync word inside */
    k += fnav_wire_encode_end(buf + k, sizeof buf - k, 8u, 3u);
    fnav_wire_decoder_init(&d);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(f.type, FNAV_WIRE_END);
    assert_int_equal(f.seq, 8);
    assert_int_equal(used, k);
    assert_int_equal(d.stats.frames, 1);
    assert_int_equal(d.stats.bad_frames, 1);
    assert_int_equal(d.stats.skipped_bytes, 20);
    assert_int_equal(d.stats.unknown, 0);
}

/* A known type announced with the wrong length is one damaged frame over
 * the extent of the frame it can be. A SAMPLE whose length byte was hit
 * (41 -> 40) holds a sync word and a false END header (payload zeros, CRC
 * broken) 26 bytes in, then comes a valid END: the candidate was rejected
 * with the 6 bytes of its header as extent, so the false header counted
 * as a second corrupt frame (the firmware audit's one.bin: bad 2). A NAV
 * frame (53 bytes of payload) whose type byte was hit reads as a SAMPLE
 * announcing 53: its false header 52 bytes in lies past a SAMPLE's 51
 * bytes, so the extent is the longer of the two frames it can be. */
static void test_wrong_length_extent(void **state)
{
    uint8_t buf[256], pay[FNAV_WIRE_NAV_LEN];
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t k, used, chunk;
    int c;
    (void)state;
    for (c = 0; c < 2; c++) {
        const size_t len = c == 0 ? FNAV_WIRE_SAMPLE_LEN : FNAV_WIRE_NAV_LEN;
        const size_t at = c == 0 ? 20u : 46u; /* the false header's first byte in the payload */
        memset(pay, 0, sizeof pay);
        pay[at] = FNAV_WIRE_SYNC0;
        pay[at + 1u] = FNAV_WIRE_SYNC1;
        pay[at + 2u] = FNAV_WIRE_END;
        pay[at + 3u] = (uint8_t)FNAV_WIRE_END_LEN;
        k = fnav_wire_encode(buf, sizeof buf, c == 0 ? FNAV_WIRE_SAMPLE : FNAV_WIRE_NAV, 11u, pay, len);
        assert_int_equal(k, FNAV_WIRE_FRAME_SIZE(len));
        if (c == 0) {
            buf[3] = (uint8_t)(FNAV_WIRE_SAMPLE_LEN - 1u); /* the length byte hit */
        } else {
            buf[2] = FNAV_WIRE_SAMPLE; /* the type byte hit */
        }
        k += fnav_wire_encode_end(buf + k, sizeof buf - k, 12u, 0u);
        for (chunk = 1; chunk <= k; chunk++) {
            size_t pos = 0;
            int got = 0;
            fnav_wire_decoder_init(&d);
            while (pos < k) {
                const size_t n = (k - pos < chunk) ? k - pos : chunk;
                size_t off = 0;
                for (;;) {
                    const fnav_status_t st = fnav_wire_decode(&d, buf + pos + off, n - off, &used, &f);
                    off += used;
                    if (st != FNAV_OK) {
                        break;
                    }
                    assert_int_equal(f.type, FNAV_WIRE_END);
                    got++;
                }
                pos += n;
            }
            assert_int_equal(got, 1);
            assert_int_equal(d.stats.frames, 1);
            assert_int_equal(d.stats.bad_frames, 1);
            assert_int_equal(d.stats.skipped_bytes, FNAV_WIRE_FRAME_SIZE(len));
        }
    }
}

/* One damaged frame counts once (step 4): a frame of an unknown type whose
 * payload holds a sync word and a false header (a NAV type announcing 0
 * bytes), its CRC broken, then an END frame. The false header starts
 * inside the extent of the frame already counted, so it is not counted
 * again: one corrupt frame, not two. A mutant forgetting the extent at
 * each skipped byte counted both and passed every test. */
static void test_nested_candidate_counts_once(void **state)
{
    static const uint8_t pay[8] = { 0x00, 0xA5, 0x5A, 0x02, 0x00, 0x00, 0x00, 0x00 };
    uint8_t buf[64];
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    size_t k, used;
    (void)state;
    k = fnav_wire_encode(buf, sizeof buf, 0x40, 1u, pay, sizeof pay);
    assert_int_equal(k, 18);
    buf[k - 1] ^= 0xFFu; /* the CRC's last byte */
    k += fnav_wire_encode_end(buf + k, sizeof buf - k, 2u, 0u);
    fnav_wire_decoder_init(&d);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(f.type, FNAV_WIRE_END);
    assert_int_equal(d.stats.frames, 1);
    assert_int_equal(d.stats.bad_frames, 1);
    assert_int_equal(d.stats.skipped_bytes, 18);
}

/* Random garbage between frames: every frame is recovered, nothing is
 * read or written out of bounds (ASan run), counters add up. */
static void test_garbage_fuzz(void **state)
{
    static uint8_t stream[200000];
    fnav_wire_decoder_t d;
    fnav_sample_t s;
    size_t n = 0, pos = 0;
    uint32_t sent = 0, got = 0, next_seq = 0, i;
    uint32_t frame_bytes = 0;
    (void)state;
    srand(12345);
    memset(&s, 0, sizeof s);
    while (n + 400 < sizeof stream) {
        uint32_t g = (uint32_t)(rand() % 40), j;
        for (j = 0; j < g; j++) {
            /* garbage rich in sync bytes */
            int r = rand() % 4;
            stream[n++] = (uint8_t)(r == 0 ? 0xA5 : (r == 1 ? 0x5A : rand() & 0xFF));
        }
        s.seq = sent;
        s.t_ns = (int64_t)sent * 2500000;
        s.accel_mps2[0] = (fnav_real_t)sent;
        n += fnav_wire_encode_sample(stream + n, sizeof stream - n, (uint16_t)sent, &s);
        frame_bytes += 51u;
        sent++;
    }
    fnav_wire_decoder_init(&d);
    while (pos < n) {
        size_t k = (size_t)(1 + rand() % 300), used;
        size_t p2 = 0;
        if (k > n - pos) {
            k = n - pos;
        }
        for (;;) {
            fnav_wire_frame_t f;
            fnav_sample_t r;
            fnav_status_t st = fnav_wire_decode(&d, stream + pos + p2, k - p2, &used, &f);
            p2 += used;
            if (st == FNAV_AGAIN) {
                break;
            }
            if (f.type == FNAV_WIRE_SAMPLE) {
                assert_int_equal(fnav_wire_parse_sample(&f, &r), FNAV_OK);
                assert_int_equal(r.seq, next_seq);
                assert_true(r.accel_mps2[0] == (fnav_real_t)next_seq);
                next_seq++;
                got++;
            }
        }
        pos += k;
    }
    /* a false frame announced near the end may still hold the last frames */
    for (i = 0; i < 400;) {
        size_t used;
        fnav_wire_frame_t f;
        uint8_t z = 0;
        fnav_status_t st = fnav_wire_decode(&d, &z, 1, &used, &f);
        i += (uint32_t)used;
        if (st == FNAV_OK && f.type == FNAV_WIRE_SAMPLE) {
            got++;
            next_seq++;
        }
    }
    assert_int_equal(got, sent);
    assert_int_equal(d.stats.lost, 0);
    assert_int_equal(d.stats.unknown, 0);
    assert_int_equal(d.stats.frames, sent);
    assert_int_equal(frame_bytes, 51u * sent);
    /* every byte fed was skipped, delivered in a frame, or is still buffered */
    assert_int_equal(d.stats.skipped_bytes + frame_bytes + d.fill, n + 400u);
}

/* Take every frame fnav_wire_decode_flush() gives out; returns their number
 * and the type of the last one. */
static int flush_all(fnav_wire_decoder_t *d, uint8_t *last_type)
{
    int n = 0;
    fnav_wire_frame_t f;
    fnav_status_t st;
    while ((st = fnav_wire_decode_flush(d, &f)) == FNAV_OK) {
        *last_type = f.type;
        n++;
    }
    assert_int_equal(st, FNAV_AGAIN);
    assert_int_equal(d->fill, 0);
    return n;
}

/* The end of a stream: the frames behind a candidate no byte will complete
 * (a truncated frame, a partial header, a false sync word announcing a long
 * frame) come out of fnav_wire_decode_flush(); fnav_wire_decode() held them
 * until the candidate's extent had arrived, that is for ever when the sender
 * had stopped (harness live waited for an END frame it had received). */
static void test_flush_end_of_stream(void **state)
{
    uint8_t buf[1024], t = 0;
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    fnav_sample_t s;
    size_t n, k, used;
    (void)state;
    memset(&s, 0, sizeof s);

    /* a SAMPLE frame cut after 20 bytes, then the END frame (14 bytes): the
     * cut frame announces 51 bytes and holds the END frame */
    n = fnav_wire_encode_sample(buf, sizeof buf, 7, &s);
    assert_int_equal(n, 51);
    n = 20;
    n += fnav_wire_encode_end(buf + n, sizeof buf - n, 8, 1);
    fnav_wire_decoder_init(&d);
    assert_int_equal(fnav_wire_decode(&d, buf, n, &used, &f), FNAV_AGAIN);
    assert_int_equal(used, n);
    assert_int_equal(d.fill, n);
    assert_int_equal(flush_all(&d, &t), 1);
    assert_int_equal(t, FNAV_WIRE_END);
    assert_int_equal(d.stats.bad_frames, 1);
    assert_int_equal(d.stats.skipped_bytes, 20);
    assert_int_equal(d.stats.frames, 1);
    assert_int_equal(fnav_wire_decode_flush(&d, &f), FNAV_AGAIN); /* empty: nothing more */
    assert_int_equal(d.stats.bad_frames, 1);
    /* the decoder goes on: the next frame is delivered, the cut one is a drop */
    k = fnav_wire_encode_end(buf, sizeof buf, 10, 2);
    assert_int_equal(fnav_wire_decode(&d, buf, k, &used, &f), FNAV_OK);
    assert_int_equal(f.seq, 10);
    assert_int_equal(d.stats.lost, 1);
    assert_int_equal(d.stats.gaps, 1);

    /* a sync word with a partial header: a truncated frame */
    fnav_wire_decoder_init(&d);
    buf[0] = FNAV_WIRE_SYNC0;
    buf[1] = FNAV_WIRE_SYNC1;
    buf[2] = FNAV_WIRE_SAMPLE;
    assert_int_equal(fnav_wire_decode(&d, buf, 3, &used, &f), FNAV_AGAIN);
    assert_int_equal(flush_all(&d, &t), 0);
    assert_int_equal(d.stats.bad_frames, 1);
    assert_int_equal(d.stats.skipped_bytes, 3);

    /* a lone first sync byte is a skipped byte, not a frame */
    fnav_wire_decoder_init(&d);
    assert_int_equal(fnav_wire_decode(&d, buf, 1, &used, &f), FNAV_AGAIN);
    assert_int_equal(flush_all(&d, &t), 0);
    assert_int_equal(d.stats.bad_frames, 0);
    assert_int_equal(d.stats.skipped_bytes, 1);

    /* a false sync word announcing a 255-byte frame of an unknown type, then
     * three whole frames (93 bytes < 265): all three come out, the false
     * candidate counts once */
    fnav_wire_decoder_init(&d);
    buf[0] = FNAV_WIRE_SYNC0;
    buf[1] = FNAV_WIRE_SYNC1;
    buf[2] = 0x80u;
    buf[3] = 0xFFu;
    buf[4] = 0u;
    buf[5] = 0u;
    n = 6;
    n += fnav_wire_encode_sample(buf + n, sizeof buf - n, 1, &s);
    n += fnav_wire_encode_end(buf + n, sizeof buf - n, 2, 1);
    n += fnav_wire_encode_end(buf + n, sizeof buf - n, 3, 1);
    assert_int_equal(fnav_wire_decode(&d, buf, n, &used, &f), FNAV_AGAIN);
    assert_int_equal(d.stats.frames, 0);
    assert_int_equal(flush_all(&d, &t), 3);
    assert_int_equal(d.stats.frames, 3);
    assert_int_equal(d.stats.bad_frames, 1);
    assert_int_equal(d.stats.skipped_bytes, 6);
    assert_int_equal(d.stats.lost, 0);

    /* a frame left undelivered by the caller comes out of the flush first */
    fnav_wire_decoder_init(&d);
    n = fnav_wire_encode_end(buf, sizeof buf, 1, 0);
    n += fnav_wire_encode_end(buf + n, sizeof buf - n, 2, 0);
    assert_int_equal(fnav_wire_decode(&d, buf, n, &used, &f), FNAV_OK);
    assert_int_equal(fnav_wire_decode(&d, buf + used, n - used, &used, &f), FNAV_OK);
    assert_int_equal(flush_all(&d, &t), 0); /* the second was taken; nothing else */
    assert_int_equal(d.stats.frames, 2);

    assert_int_equal(fnav_wire_decode_flush(NULL, &f), FNAV_E_ARG);
    assert_int_equal(fnav_wire_decode_flush(&d, NULL), FNAV_E_ARG);
}

/* After a flush the decoder starts afresh: the extent of the truncated
 * candidate it rejected ends there (no byte of it will come), so a corrupt
 * frame arriving after the quiet time counts on its own. Were the rejected
 * candidate's remaining extent (here 50 - 19 = 31 bytes) kept, the corrupt
 * frame after it would not be counted: harness live would call a damaged
 * frame after a sender's pause a plain drop. */
static void test_flush_ends_extent(void **state)
{
    uint8_t buf[128];
    fnav_wire_decoder_t d;
    fnav_wire_frame_t f;
    fnav_sample_t s;
    size_t n, used;
    uint8_t t = 0;
    (void)state;
    memset(&s, 0, sizeof s);
    fnav_wire_decoder_init(&d);
    /* a SAMPLE frame cut after 20 bytes, then the line goes quiet */
    n = fnav_wire_encode_sample(buf, sizeof buf, 1, &s);
    assert_int_equal(n, 51);
    assert_int_equal(fnav_wire_decode(&d, buf, 20, &used, &f), FNAV_AGAIN);
    assert_int_equal(flush_all(&d, &t), 0);
    assert_int_equal(d.stats.bad_frames, 1);
    assert_int_equal(d.stats.skipped_bytes, 20);
    /* then a whole SAMPLE frame with a flipped payload bit, then a good one */
    n = fnav_wire_encode_sample(buf, sizeof buf, 2, &s);
    buf[FNAV_WIRE_HEADER_SIZE + 20u] ^= 0x08u;
    n += fnav_wire_encode_end(buf + n, sizeof buf - n, 3, 1);
    assert_int_equal(fnav_wire_decode(&d, buf, n, &used, &f), FNAV_OK);
    assert_int_equal(f.type, FNAV_WIRE_END);
    assert_int_equal(d.stats.bad_frames, 2);
    assert_int_equal(d.stats.skipped_bytes, 20 + 51);
    assert_int_equal(d.stats.frames, 1);
}

/* Flushes at random points of a damaged stream (a receiver's idle timer
 * firing at any byte): every frame whole before the flush point is
 * delivered, the decoder is empty after each flush, and every byte fed is
 * skipped or delivered. */
static void test_flush_random(void **state)
{
    static uint8_t stream[60000];
    fnav_wire_decoder_t d;
    fnav_sample_t s;
    size_t n = 0, pos = 0;
    uint32_t sent = 0, got = 0, delivered_bytes = 0, flushes = 0;
    (void)state;
    srand(4711);
    memset(&s, 0, sizeof s);
    while (n + 400 < sizeof stream) {
        uint32_t g = (uint32_t)(rand() % 8), j;
        size_t k;
        for (j = 0; j < g; j++) {
            int r = rand() % 4;
            stream[n++] = (uint8_t)(r == 0 ? 0xA5 : (r == 1 ? 0x5A : rand() & 0xFF));
        }
        s.seq = sent;
        k = fnav_wire_encode_sample(stream + n, sizeof stream - n, (uint16_t)sent, &s);
        if (rand() % 10 == 0) {
            k = (size_t)(1 + rand() % 50); /* cut short */
        }
        n += k;
        sent++;
    }
    fnav_wire_decoder_init(&d);
    while (pos < n) {
        size_t k = (size_t)(1 + rand() % 200), p2 = 0, used;
        fnav_wire_frame_t f;
        if (k > n - pos) {
            k = n - pos;
        }
        for (;;) {
            fnav_status_t st = fnav_wire_decode(&d, stream + pos + p2, k - p2, &used, &f);
            p2 += used;
            if (st == FNAV_AGAIN) {
                break;
            }
            got++;
            delivered_bytes += FNAV_WIRE_FRAME_SIZE((uint32_t)f.len);
        }
        pos += k;
        if (rand() % 4 == 0 || pos == n) {
            fnav_status_t st;
            while ((st = fnav_wire_decode_flush(&d, &f)) == FNAV_OK) {
                got++;
                delivered_bytes += FNAV_WIRE_FRAME_SIZE((uint32_t)f.len);
            }
            assert_int_equal(st, FNAV_AGAIN);
            assert_int_equal(d.fill, 0);
            flushes++;
        }
    }
    assert_true(flushes > 10);
    assert_true(got > 0);
    assert_int_equal(d.stats.frames, got);
    assert_int_equal(d.stats.skipped_bytes + delivered_bytes, n);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crc32),
        cmocka_unit_test(test_decode_golden_clean),
        cmocka_unit_test(test_decode_golden_corrupt),
        cmocka_unit_test(test_encode_golden),
        cmocka_unit_test(test_roundtrip_and_sizes),
        cmocka_unit_test(test_sample_nan),
        cmocka_unit_test(test_beyond_float_range),
        cmocka_unit_test(test_info_rate),
        cmocka_unit_test(test_seq_accounting),
        cmocka_unit_test(test_seq_gap_boundary),
        cmocka_unit_test(test_parse_wrong_length),
        cmocka_unit_test(test_parse_null_args),
        cmocka_unit_test(test_known_type_wrong_length),
        cmocka_unit_test(test_wrong_length_extent),
        cmocka_unit_test(test_nested_candidate_counts_once),
        cmocka_unit_test(test_garbage_fuzz),
        cmocka_unit_test(test_flush_end_of_stream),
        cmocka_unit_test(test_flush_ends_extent),
        cmocka_unit_test(test_flush_random),
    };
    return cmocka_run_group_tests_name("wire", tests, NULL, NULL);
}
