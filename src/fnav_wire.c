/* The footnav wire protocol (fnav_wire.h, docs/wire-protocol.md). */
#include <float.h>
#include <string.h>

#include "footnav/fnav_wire.h"

/* ------------------------------------------------------------------ CRC */

/* CRC-32, reflected polynomial 0xEDB88320, one 4-bit step at a time: a
 * 16-entry table (64 bytes of flash) instead of the usual 1 KB. Entry i is
 * the CRC register after shifting the nibble i through four bit steps. */
static const uint32_t k_crc_nibble[16] = {
    0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu, 0x76DC4190u, 0x6B6B51F4u, 0x4DB26158u, 0x5005713Cu,
    0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu, 0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu,
};

uint32_t fnav_crc32(uint32_t crc, const uint8_t *p, size_t n)
{
    size_t i;
    crc = ~crc;
    for (i = 0; i < n; i++) {
        crc ^= p[i];
        crc = (crc >> 4) ^ k_crc_nibble[crc & 0xFu];
        crc = (crc >> 4) ^ k_crc_nibble[crc & 0xFu];
    }
    return ~crc;
}

/* ------------------------------------------------------ byte packing (LE) */

static void put_u16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)(v >> 8);
}

static void put_u32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)((v >> 8) & 0xFFu);
    p[2] = (uint8_t)((v >> 16) & 0xFFu);
    p[3] = (uint8_t)(v >> 24);
}

static void put_u64(uint8_t *p, uint64_t v)
{
    put_u32(p, (uint32_t)(v & 0xFFFFFFFFu));
    put_u32(p + 4, (uint32_t)(v >> 32));
}

static void put_f32(uint8_t *p, float v)
{
    uint32_t u;
    memcpy(&u, &v, sizeof u);
    put_u32(p, u);
}

/* An fnav_real_t as float32. In a double build a value beyond the float
 * range is sent as the largest float of its sign (the plain cast is
 * undefined behaviour there, C99 6.3.1.5); NaN and
 * infinities pass as they are. A float build sends the value itself. */
static void put_real32(uint8_t *p, fnav_real_t x)
{
#if FNAV_USE_DOUBLE
    if (x > (fnav_real_t)FLT_MAX && x <= (fnav_real_t)DBL_MAX) {
        x = (fnav_real_t)FLT_MAX;
    } else if (x < -(fnav_real_t)FLT_MAX && x >= -(fnav_real_t)DBL_MAX) {
        x = -(fnav_real_t)FLT_MAX;
    }
#endif
    put_f32(p, (float)x);
}

static void put_f64(uint8_t *p, double v)
{
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    put_u64(p, u);
}

static uint16_t get_u16(const uint8_t *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static uint32_t get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

static uint64_t get_u64(const uint8_t *p)
{
    return (uint64_t)get_u32(p) | ((uint64_t)get_u32(p + 4) << 32);
}

static float get_f32(const uint8_t *p)
{
    uint32_t u = get_u32(p);
    float v;
    memcpy(&v, &u, sizeof v);
    return v;
}

static double get_f64(const uint8_t *p)
{
    uint64_t u = get_u64(p);
    double v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* Two's complement int64 <-> uint64 without implementation-defined casts
 * of out-of-range values. */
static uint64_t i64_to_u64(int64_t v)
{
    return (uint64_t)v;
}

static int64_t u64_to_i64(uint64_t u)
{
    if (u <= (uint64_t)INT64_MAX) {
        return (int64_t)u;
    }
    return -(int64_t)(~u) - 1;
}

/* Copy a string into a NUL-padded field of n bytes, keeping a NUL at the end. */
static void put_text(uint8_t *p, const char *s, size_t n)
{
    memset(p, 0, n);
    if (s != NULL) {
        size_t i;
        for (i = 0; i + 1 < n && s[i] != '\0'; i++) {
            p[i] = (uint8_t)s[i];
        }
    }
}

static void get_text(char *s, const uint8_t *p, size_t n)
{
    size_t i;
    for (i = 0; i + 1 < n && p[i] != 0; i++) {
        s[i] = (char)p[i];
    }
    memset(s + i, 0, n - i);
}

/* ------------------------------------------------------------- encoding */

size_t fnav_wire_encode(uint8_t *out, size_t out_size, uint8_t type, uint16_t seq, const uint8_t *payload,
                        size_t len)
{
    size_t total = FNAV_WIRE_FRAME_SIZE(len);
    uint32_t crc;
    if (out == NULL || len > FNAV_WIRE_MAX_PAYLOAD || out_size < total || (payload == NULL && len > 0u)) {
        return 0;
    }
    out[0] = FNAV_WIRE_SYNC0;
    out[1] = FNAV_WIRE_SYNC1;
    out[2] = type;
    out[3] = (uint8_t)len;
    put_u16(out + 4, seq);
    if (len > 0u && payload != out + FNAV_WIRE_HEADER_SIZE) {
        memmove(out + FNAV_WIRE_HEADER_SIZE, payload, len);
    }
    crc = fnav_crc32(0u, out + 2, 4u + len);
    put_u32(out + FNAV_WIRE_HEADER_SIZE + len, crc);
    return total;
}

/* The typed encoders build the payload in place (out + header) and then
 * frame it, so no payload copy lives on the stack. */
static uint8_t *payload_area(uint8_t *out, size_t out_size, size_t len)
{
    if (out == NULL || out_size < FNAV_WIRE_FRAME_SIZE(len)) {
        return NULL;
    }
    return out + FNAV_WIRE_HEADER_SIZE;
}

size_t fnav_wire_encode_sample(uint8_t *out, size_t out_size, uint16_t seq, const fnav_sample_t *s)
{
    uint8_t *p = payload_area(out, out_size, FNAV_WIRE_SAMPLE_LEN);
    size_t i;
    if (p == NULL || s == NULL) {
        return 0;
    }
    put_u64(p, i64_to_u64(s->t_ns));
    put_u32(p + 8, s->seq);
    p[12] = (uint8_t)(s->flags & 0xFFu);
    for (i = 0; i < 3; i++) {
        put_real32(p + 13 + 4 * i, s->accel_mps2[i]);
        put_real32(p + 25 + 4 * i, s->gyro_rps[i]);
    }
    put_real32(p + 37, s->temp_c);
    return fnav_wire_encode(out, out_size, FNAV_WIRE_SAMPLE, seq, p, FNAV_WIRE_SAMPLE_LEN);
}

size_t fnav_wire_encode_nav(uint8_t *out, size_t out_size, uint16_t seq, const fnav_nav_frame_t *f)
{
    uint8_t *p = payload_area(out, out_size, FNAV_WIRE_NAV_LEN);
    size_t i;
    if (p == NULL || f == NULL) {
        return 0;
    }
    put_u64(p, i64_to_u64(f->t_ns));
    put_u32(p + 8, f->seq);
    p[12] = (uint8_t)(f->flags & 0xFFu);
    put_u32(p + 13, f->health);
    for (i = 0; i < 3; i++) {
        put_real32(p + 17 + 4 * i, f->pos_m[i]);
        put_real32(p + 29 + 4 * i, f->vel_mps[i]);
        put_real32(p + 41 + 4 * i, f->euler_rad[i]);
    }
    return fnav_wire_encode(out, out_size, FNAV_WIRE_NAV, seq, p, FNAV_WIRE_NAV_LEN);
}

size_t fnav_wire_encode_status(uint8_t *out, size_t out_size, uint16_t seq, const fnav_wire_status_t *st)
{
    uint8_t *p = payload_area(out, out_size, FNAV_WIRE_STATUS_LEN);
    if (p == NULL || st == NULL) {
        return 0;
    }
    put_u32(p, st->samples);
    put_u32(p + 4, st->overruns);
    put_u32(p + 8, st->est_errors);
    put_u32(p + 12, st->tx_dropped);
    put_u32(p + 16, st->uptime_ms);
    return fnav_wire_encode(out, out_size, FNAV_WIRE_STATUS, seq, p, FNAV_WIRE_STATUS_LEN);
}

size_t fnav_wire_encode_info(uint8_t *out, size_t out_size, uint16_t seq, const fnav_wire_info_t *info)
{
    uint8_t *p = payload_area(out, out_size, FNAV_WIRE_INFO_LEN);
    if (p == NULL || info == NULL) {
        return 0;
    }
    put_f64(p, info->rate_hz);
    put_u32(p + 8, info->flags);
    put_text(p + 12, info->sensor, FNAV_WIRE_SENSOR_SIZE);
    put_text(p + 12 + FNAV_WIRE_SENSOR_SIZE, info->axes, FNAV_WIRE_AXES_SIZE);
    return fnav_wire_encode(out, out_size, FNAV_WIRE_INFO, seq, p, FNAV_WIRE_INFO_LEN);
}

size_t fnav_wire_encode_end(uint8_t *out, size_t out_size, uint16_t seq, uint32_t count)
{
    uint8_t *p = payload_area(out, out_size, FNAV_WIRE_END_LEN);
    if (p == NULL) {
        return 0;
    }
    put_u32(p, count);
    return fnav_wire_encode(out, out_size, FNAV_WIRE_END, seq, p, FNAV_WIRE_END_LEN);
}

/* ------------------------------------------------------------- decoding */

void fnav_wire_decoder_init(fnav_wire_decoder_t *d)
{
    memset(d, 0, sizeof *d);
}

/* Payload length a known type must have; -1 for an unknown type. */
static int known_len(uint8_t type)
{
    switch (type) {
    case FNAV_WIRE_SAMPLE: return (int)FNAV_WIRE_SAMPLE_LEN;
    case FNAV_WIRE_NAV: return (int)FNAV_WIRE_NAV_LEN;
    case FNAV_WIRE_STATUS: return (int)FNAV_WIRE_STATUS_LEN;
    case FNAV_WIRE_INFO: return (int)FNAV_WIRE_INFO_LEN;
    case FNAV_WIRE_END: return (int)FNAV_WIRE_END_LEN;
    default: return -1;
    }
}

/* Discard the first k buffered bytes. */
static void drop(fnav_wire_decoder_t *d, uint16_t k)
{
    if (k >= d->fill) {
        d->fill = 0;
    } else {
        memmove(d->buf, d->buf + k, (size_t)(d->fill - k));
        d->fill = (uint16_t)(d->fill - k);
    }
    d->bad_until = (d->bad_until > k) ? (uint16_t)(d->bad_until - k) : 0u;
}

/* Skip one byte that does not start a valid frame. */
static void skip_byte(fnav_wire_decoder_t *d)
{
    d->stats.skipped_bytes++;
    drop(d, 1u);
}

/* A corrupt frame of extent bytes starts at buf[0]: count it unless it lies
 * inside one already counted (and no valid frame came since), then resume
 * the search one byte further. */
static void reject(fnav_wire_decoder_t *d, uint16_t extent)
{
    if (d->bad_until == 0u) {
        d->stats.bad_frames++;
        d->bad_until = extent;
    }
    skip_byte(d);
}

static void track_seq(fnav_wire_decoder_t *d, uint16_t seq)
{
    if (d->have_seq && seq != d->expect_seq) {
        uint16_t gap = (uint16_t)(seq - d->expect_seq);
        if (gap < 0x8000u) {
            d->stats.gaps++;
            d->stats.lost += gap;
        } else {
            d->stats.resets++; /* seq went backwards: restart or duplicate */
        }
    }
    d->have_seq = 1u;
    d->expect_seq = (uint16_t)(seq + 1u);
}

fnav_status_t fnav_wire_decode(fnav_wire_decoder_t *d, const uint8_t *in, size_t n, size_t *used,
                               fnav_wire_frame_t *frame)
{
    size_t pos = 0;
    if (d == NULL || used == NULL || frame == NULL || (in == NULL && n > 0u)) {
        return FNAV_E_ARG;
    }
    *used = 0;
    if (d->consumed > 0u) {
        drop(d, d->consumed);
        d->consumed = 0u;
    }
    for (;;) {
        size_t want;
        /* 1. sync word at buf[0..1] */
        if (d->fill >= 1u && d->buf[0] != FNAV_WIRE_SYNC0) {
            skip_byte(d);
            continue;
        }
        if (d->fill >= 2u && d->buf[1] != FNAV_WIRE_SYNC1) {
            skip_byte(d);
            continue;
        }
        /* 2. header: a known type must have its own length */
        want = FNAV_WIRE_HEADER_SIZE;
        if (d->fill >= FNAV_WIRE_HEADER_SIZE) {
            int klen = known_len(d->buf[2]);
            size_t total = FNAV_WIRE_FRAME_SIZE((size_t)d->buf[3]);
            if (klen >= 0 && klen != (int)d->buf[3]) {
                /* the frame its type or its length byte says, whichever was
                 * hit: a false sync word inside either is part of this one
                 * damaged frame, not a second (the header alone as extent
                 * counted one inside the payload again) */
                const size_t known = FNAV_WIRE_FRAME_SIZE((size_t)klen);
                reject(d, (uint16_t)(known > total ? known : total));
                continue;
            }
            want = total;
            /* 3. whole frame: check the CRC */
            if (d->fill >= total) {
                uint32_t crc = fnav_crc32(0u, d->buf + 2, 4u + (size_t)d->buf[3]);
                if (crc != get_u32(d->buf + FNAV_WIRE_HEADER_SIZE + d->buf[3])) {
                    reject(d, (uint16_t)total);
                    continue;
                }
                frame->type = d->buf[2];
                frame->len = d->buf[3];
                frame->seq = get_u16(d->buf + 4);
                frame->payload = d->buf + FNAV_WIRE_HEADER_SIZE;
                d->consumed = (uint16_t)total;
                d->bad_until = 0u; /* a valid frame ends a counted extent: that candidate was false */
                d->stats.frames++;
                if (klen < 0) {
                    d->stats.unknown++;
                }
                track_seq(d, frame->seq);
                *used = pos;
                return FNAV_OK;
            }
        } else if (d->fill < 2u) {
            want = (d->fill == 0u) ? 1u : 2u;
        }
        /* 4. need more bytes: take what completes the current stage */
        if (pos >= n) {
            *used = pos;
            return FNAV_AGAIN;
        }
        {
            size_t k = want - d->fill;
            if (k > n - pos) {
                k = n - pos;
            }
            memcpy(d->buf + d->fill, in + pos, k);
            d->fill = (uint16_t)(d->fill + k);
            pos += k;
        }
    }
}

fnav_status_t fnav_wire_decode_flush(fnav_wire_decoder_t *d, fnav_wire_frame_t *frame)
{
    if (d == NULL || frame == NULL) {
        return FNAV_E_ARG;
    }
    for (;;) {
        size_t used;
        fnav_status_t st = fnav_wire_decode(d, NULL, 0u, &used, frame);
        if (st != FNAV_AGAIN) {
            return st; /* a whole frame held behind the rejected candidate */
        }
        if (d->fill == 0u) {
            /* no byte of a counted candidate's extent will come: a corrupt
             * frame after the pause counts on its own (the rest of the
             * extent, if carried over, would hide it) */
            d->bad_until = 0u;
            return FNAV_AGAIN;
        }
        /* buf[0] starts a candidate no byte will complete: a lone first
         * sync byte is skipped as any other; a sync word with a partial
         * header or frame is a truncated frame, corrupt over the extent it
         * announced (or what arrived of it), then the search goes on one
         * byte further, as after a failed CRC */
        if (d->fill < 2u) {
            skip_byte(d);
        } else if (d->fill < FNAV_WIRE_HEADER_SIZE) {
            reject(d, d->fill);
        } else {
            reject(d, (uint16_t)FNAV_WIRE_FRAME_SIZE((size_t)d->buf[3]));
        }
    }
}

/* ------------------------------------------------------------- parsing */

fnav_status_t fnav_wire_parse_sample(const fnav_wire_frame_t *f, fnav_sample_t *s)
{
    const uint8_t *p;
    float a[3], g[3], temp;
    size_t i;
    /* NULL is an invalid argument, as everywhere in the core (every parser
     * said FNAV_E_FORMAT, and read a NULL payload; test_wire
     * test_parse_null_args) */
    if (f == NULL || s == NULL || f->payload == NULL) {
        return FNAV_E_ARG;
    }
    if (f->type != FNAV_WIRE_SAMPLE || f->len != FNAV_WIRE_SAMPLE_LEN) {
        return FNAV_E_FORMAT;
    }
    p = f->payload;
    for (i = 0; i < 3; i++) {
        a[i] = get_f32(p + 13 + 4 * i);
        g[i] = get_f32(p + 25 + 4 * i);
        if (!fnav_isfinite((fnav_real_t)a[i]) || !fnav_isfinite((fnav_real_t)g[i])) {
            return FNAV_E_NANINF;
        }
    }
    temp = get_f32(p + 37);
    if ((p[12] & FNAV_SAMPLE_HAS_TEMP) != 0u && !fnav_isfinite((fnav_real_t)temp)) {
        return FNAV_E_NANINF; /* a temperature the sample claims to have */
    }
    s->t_ns = u64_to_i64(get_u64(p));
    s->seq = get_u32(p + 8);
    s->flags = p[12];
    for (i = 0; i < 3; i++) {
        s->accel_mps2[i] = (fnav_real_t)a[i];
        s->gyro_rps[i] = (fnav_real_t)g[i];
    }
    s->temp_c = (fnav_real_t)temp;
    return FNAV_OK;
}

fnav_status_t fnav_wire_parse_nav(const fnav_wire_frame_t *f, fnav_wire_nav_t *nav)
{
    const uint8_t *p;
    size_t i;
    if (f == NULL || nav == NULL || f->payload == NULL) {
        return FNAV_E_ARG;
    }
    if (f->type != FNAV_WIRE_NAV || f->len != FNAV_WIRE_NAV_LEN) {
        return FNAV_E_FORMAT;
    }
    p = f->payload;
    nav->t_ns = u64_to_i64(get_u64(p));
    nav->seq = get_u32(p + 8);
    nav->flags = p[12];
    nav->health = get_u32(p + 13);
    for (i = 0; i < 3; i++) {
        nav->pos_m[i] = get_f32(p + 17 + 4 * i);
        nav->vel_mps[i] = get_f32(p + 29 + 4 * i);
        nav->euler_rad[i] = get_f32(p + 41 + 4 * i);
    }
    return FNAV_OK;
}

fnav_status_t fnav_wire_parse_status(const fnav_wire_frame_t *f, fnav_wire_status_t *st)
{
    const uint8_t *p;
    if (f == NULL || st == NULL || f->payload == NULL) {
        return FNAV_E_ARG;
    }
    if (f->type != FNAV_WIRE_STATUS || f->len != FNAV_WIRE_STATUS_LEN) {
        return FNAV_E_FORMAT;
    }
    p = f->payload;
    st->samples = get_u32(p);
    st->overruns = get_u32(p + 4);
    st->est_errors = get_u32(p + 8);
    st->tx_dropped = get_u32(p + 12);
    st->uptime_ms = get_u32(p + 16);
    return FNAV_OK;
}

fnav_status_t fnav_wire_parse_info(const fnav_wire_frame_t *f, fnav_wire_info_t *info)
{
    const uint8_t *p;
    double rate;
    if (f == NULL || info == NULL || f->payload == NULL) {
        return FNAV_E_ARG;
    }
    if (f->type != FNAV_WIRE_INFO || f->len != FNAV_WIRE_INFO_LEN) {
        return FNAV_E_FORMAT;
    }
    p = f->payload;
    rate = get_f64(p);
    if (!(rate >= 0.0 && rate <= 1.0e6)) {
        return FNAV_E_RANGE; /* NaN fails both; *info unchanged */
    }
    info->rate_hz = rate;
    info->flags = get_u32(p + 8);
    get_text(info->sensor, p + 12, FNAV_WIRE_SENSOR_SIZE);
    get_text(info->axes, p + 12 + FNAV_WIRE_SENSOR_SIZE, FNAV_WIRE_AXES_SIZE);
    return FNAV_OK;
}

fnav_status_t fnav_wire_parse_end(const fnav_wire_frame_t *f, uint32_t *count)
{
    if (f == NULL || count == NULL || f->payload == NULL) {
        return FNAV_E_ARG;
    }
    if (f->type != FNAV_WIRE_END || f->len != FNAV_WIRE_END_LEN) {
        return FNAV_E_FORMAT;
    }
    *count = get_u32(f->payload);
    return FNAV_OK;
}
