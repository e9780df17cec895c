/**
 * @file hx_bin.h
 * @brief Byte layout of the footnav .bin log, version 1 (docs/log-format.md).
 *
 * All fields little-endian; CRC-32 is the IEEE 802.3 / zlib polynomial.
 */
#ifndef HX_BIN_H
#define HX_BIN_H

#include <stddef.h>
#include <stdint.h>

#define HX_BIN_MAGIC "FNAV"
#define HX_BIN_VERSION 1
#define HX_BIN_HEADER_SIZE 192
#define HX_BIN_RECORD_SIZE 48

#define HX_BIN_FLAG_RATE_NOMINAL 0x1u /* rate_hz is the sensor's nominal rate */
#define HX_BIN_FLAG_TEMP 0x2u         /* records may carry temperature */
#define HX_BIN_FLAG_SEQ 0x4u          /* seq is the sensor's own counter */

#define HX_BIN_REC_SAMPLE 0xA501u
#define HX_BIN_REC_END 0xA5E0u
#define HX_BIN_REC_TEMP 0x1u          /* record flag: temp is valid */

typedef struct {
    uint32_t flags;
    double rate_hz;
    char sensor[32];
    char units[24];
    char axes[48];
    char source[60];
} hx_bin_header_t;

typedef struct {
    uint16_t type;
    uint16_t flags;
    uint32_t seq;
    int64_t t_ns;
    float acc[3];
    float gyr[3];
    float temp;
} hx_bin_record_t;

/** Units string written into every header. */
#define HX_BIN_UNITS "m/s^2 rad/s degC ns"

void hx_bin_header_encode(const hx_bin_header_t *h, unsigned char out[HX_BIN_HEADER_SIZE]);
/** 0 on success; -1 with msg filled when the header is not a valid v1 header. */
int hx_bin_header_decode(const unsigned char *in, size_t n, hx_bin_header_t *h, char *msg, size_t msg_size);
void hx_bin_record_encode(const hx_bin_record_t *r, unsigned char out[HX_BIN_RECORD_SIZE]);
/** 0: valid record; -1: unknown type; -2: checksum mismatch. */
int hx_bin_record_decode(const unsigned char *in, hx_bin_record_t *r);
uint32_t hx_crc32(const unsigned char *p, size_t n);

#endif /* HX_BIN_H */
