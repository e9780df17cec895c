/* footnav .bin log v1 codec (docs/log-format.md). */
#include "hx_bin.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <zlib.h>

uint32_t hx_crc32(const unsigned char *p, size_t n)
{
    return (uint32_t)crc32(crc32(0L, Z_NULL, 0), p, (uInt)n);
}

static void put_u16(unsigned char *p, uint16_t v)
{
    p[0] = (unsigned char)(v & 0xffu);
    p[1] = (unsigned char)(v >> 8);
}

static void put_u32(unsigned char *p, uint32_t v)
{
    int i;
    for (i = 0; i < 4; i++) {
        p[i] = (unsigned char)((v >> (8 * i)) & 0xffu);
    }
}

static void put_u64(unsigned char *p, uint64_t v)
{
    int i;
    for (i = 0; i < 8; i++) {
        p[i] = (unsigned char)((v >> (8 * i)) & 0xffu);
    }
}

static uint16_t get_u16(const unsigned char *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static uint32_t get_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

static uint64_t get_u64(const unsigned char *p)
{
    return (uint64_t)get_u32(p) | ((uint64_t)get_u32(p + 4) << 32);
}

static void put_f32(unsigned char *p, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    put_u32(p, u);
}

static float get_f32(const unsigned char *p)
{
    uint32_t u = get_u32(p);
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static void put_str(unsigned char *p, size_t size, const char *s)
{
    size_t n = strlen(s);
    memset(p, 0, size);
    if (n > size - 1) {
        n = size - 1;
    }
    memcpy(p, s, n);
}

static int get_str(const unsigned char *p, size_t size, char *out)
{
    if (memchr(p, '\0', size) == NULL) {
        return -1;
    }
    memcpy(out, p, size);
    return 0;
}

void hx_bin_header_encode(const hx_bin_header_t *h, unsigned char out[HX_BIN_HEADER_SIZE])
{
    uint64_t r;
    memset(out, 0, HX_BIN_HEADER_SIZE);
    memcpy(out, HX_BIN_MAGIC, 4);
    put_u16(out + 4, HX_BIN_VERSION);
    put_u16(out + 6, HX_BIN_HEADER_SIZE);
    put_u16(out + 8, HX_BIN_RECORD_SIZE);
    put_u16(out + 10, 0);
    put_u32(out + 12, h->flags);
    memcpy(&r, &h->rate_hz, 8);
    put_u64(out + 16, r);
    put_str(out + 24, 32, h->sensor);
    put_str(out + 56, 24, HX_BIN_UNITS);
    put_str(out + 80, 48, h->axes);
    put_str(out + 128, 60, h->source);
    put_u32(out + 188, hx_crc32(out, 188));
}

int hx_bin_header_decode(const unsigned char *in, size_t n, hx_bin_header_t *h, char *msg, size_t msg_size)
{
    uint64_t r;
    unsigned version, hsize, rsize;
    if (n < 12 || memcmp(in, HX_BIN_MAGIC, 4) != 0) {
        snprintf(msg, msg_size, "not a footnav log (bad magic)");
        return -1;
    }
    version = get_u16(in + 4);
    hsize = get_u16(in + 6);
    rsize = get_u16(in + 8);
    if (version != HX_BIN_VERSION) {
        snprintf(msg, msg_size, "unsupported version %u (this reader knows version %d)", version, HX_BIN_VERSION);
        return -1;
    }
    if (hsize != HX_BIN_HEADER_SIZE || rsize != HX_BIN_RECORD_SIZE) {
        snprintf(msg, msg_size, "header size %u / record size %u, expected %d / %d", hsize, rsize,
                 HX_BIN_HEADER_SIZE, HX_BIN_RECORD_SIZE);
        return -1;
    }
    if (n < HX_BIN_HEADER_SIZE) {
        snprintf(msg, msg_size, "header cut short (%zu of %d bytes)", n, HX_BIN_HEADER_SIZE);
        return -1;
    }
    if (get_u32(in + 188) != hx_crc32(in, 188)) {
        snprintf(msg, msg_size, "header checksum mismatch (corrupted)");
        return -1;
    }
    memset(h, 0, sizeof *h);
    h->flags = get_u32(in + 12);
    r = get_u64(in + 16);
    memcpy(&h->rate_hz, &r, 8);
    if (!(h->rate_hz >= 0.0 && h->rate_hz <= 1.0e6)) {
        snprintf(msg, msg_size, "sample rate %g Hz is not in [0, 1e6]", h->rate_hz);
        return -1;
    }
    if (get_str(in + 24, 32, h->sensor) || get_str(in + 56, 24, h->units) || get_str(in + 80, 48, h->axes) ||
        get_str(in + 128, 60, h->source)) {
        snprintf(msg, msg_size, "text field not terminated");
        return -1;
    }
    if (strcmp(h->units, HX_BIN_UNITS) != 0) {
        snprintf(msg, msg_size, "units '%s' not supported (expected '%s')", h->units, HX_BIN_UNITS);
        return -1;
    }
    return 0;
}

void hx_bin_record_encode(const hx_bin_record_t *r, unsigned char out[HX_BIN_RECORD_SIZE])
{
    put_u16(out, r->type);
    put_u16(out + 2, r->flags);
    put_u32(out + 4, r->seq);
    put_u64(out + 8, (uint64_t)r->t_ns);
    put_f32(out + 16, r->acc[0]);
    put_f32(out + 20, r->acc[1]);
    put_f32(out + 24, r->acc[2]);
    put_f32(out + 28, r->gyr[0]);
    put_f32(out + 32, r->gyr[1]);
    put_f32(out + 36, r->gyr[2]);
    put_f32(out + 40, r->temp);
    put_u32(out + 44, hx_crc32(out, 44));
}

int hx_bin_record_decode(const unsigned char *in, hx_bin_record_t *r)
{
    r->type = get_u16(in);
    if (r->type != HX_BIN_REC_SAMPLE && r->type != HX_BIN_REC_END) {
        return -1;
    }
    if (get_u32(in + 44) != hx_crc32(in, 44)) {
        return -2;
    }
    r->flags = get_u16(in + 2);
    r->seq = get_u32(in + 4);
    r->t_ns = (int64_t)get_u64(in + 8);
    r->acc[0] = get_f32(in + 16);
    r->acc[1] = get_f32(in + 20);
    r->acc[2] = get_f32(in + 24);
    r->gyr[0] = get_f32(in + 28);
    r->gyr[1] = get_f32(in + 32);
    r->gyr[2] = get_f32(in + 36);
    r->temp = get_f32(in + 40);
    return 0;
}
