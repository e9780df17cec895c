/**
 * @file fnav_wire.h
 * @brief The footnav wire protocol: framed, checksummed messages over a byte
 *        stream (UART, USB CDC, a pseudo-terminal). Specification:
 *        docs/wire-protocol.md.
 *
 * A frame is
 *
 *     A5 5A | type u8 | len u8 | seq u16 | payload[len] | crc u32
 *
 * little-endian; seq counts every frame a sender emits (wraps at 2^16); the
 * CRC-32 (IEEE 802.3 / zlib) covers type, len, seq and the payload.
 *
 * Encoder and decoder are allocation-free and keep no hidden state: the
 * decoder is a caller-owned object holding one frame's worth of bytes
 * (FNAV_WIRE_MAX_FRAME). The same code runs in the firmware (encoder) and in
 * the harness (decoder). Floating-point payload fields are IEEE-754 binary32
 * whatever fnav_real_t is, so a float32 sample crosses the wire unchanged.
 * None of these functions touches shared state: each may run in an interrupt
 * as long as no other context uses the same object at the same time.
 */
#ifndef FNAV_WIRE_H
#define FNAV_WIRE_H

#include "fnav_types.h"
#include "fnav_port.h"

#ifdef __cplusplus
extern "C" {
#endif

/** First and second byte of every frame. */
#define FNAV_WIRE_SYNC0 0xA5u
#define FNAV_WIRE_SYNC1 0x5Au
/** Bytes before the payload: sync (2), type, len, seq (2). */
#define FNAV_WIRE_HEADER_SIZE 6u
/** Bytes after the payload: CRC-32. */
#define FNAV_WIRE_CRC_SIZE 4u
/** Largest payload (len is one byte). */
#define FNAV_WIRE_MAX_PAYLOAD 255u
/** Largest frame: the size of a decoder's buffer. */
#define FNAV_WIRE_MAX_FRAME (FNAV_WIRE_HEADER_SIZE + FNAV_WIRE_MAX_PAYLOAD + FNAV_WIRE_CRC_SIZE)

/** Frame types. A receiver skips (and counts) CRC-valid frames of types it
 *  does not know, so types can be added without breaking old receivers. */
typedef enum {
    FNAV_WIRE_SAMPLE = 0x01, /**< one IMU sample (FNAV_WIRE_SAMPLE_LEN) */
    FNAV_WIRE_NAV = 0x02,    /**< compact navigation output (FNAV_WIRE_NAV_LEN) */
    FNAV_WIRE_STATUS = 0x03, /**< sender counters (FNAV_WIRE_STATUS_LEN) */
    FNAV_WIRE_INFO = 0x04,   /**< stream description: rate, sensor (FNAV_WIRE_INFO_LEN) */
    FNAV_WIRE_END = 0x05     /**< the sender finished cleanly (FNAV_WIRE_END_LEN) */
} fnav_wire_type_t;

/** Payload lengths of the known types (a frame of a known type with any
 *  other length is rejected as corrupt). */
#define FNAV_WIRE_SAMPLE_LEN 41u
#define FNAV_WIRE_NAV_LEN 53u
#define FNAV_WIRE_STATUS_LEN 20u
#define FNAV_WIRE_INFO_LEN 92u
#define FNAV_WIRE_END_LEN 4u

/** Frame size of a payload length. */
#define FNAV_WIRE_FRAME_SIZE(len) (FNAV_WIRE_HEADER_SIZE + (len) + FNAV_WIRE_CRC_SIZE)

/** INFO flags (same bits as the .bin header, docs/log-format.md). */
#define FNAV_WIRE_INFO_RATE_NOMINAL 0x1u
#define FNAV_WIRE_INFO_TEMP 0x2u
#define FNAV_WIRE_INFO_SEQ 0x4u

/** Sizes of the INFO text fields, NUL-padded on the wire. */
#define FNAV_WIRE_SENSOR_SIZE 32u
#define FNAV_WIRE_AXES_SIZE 48u

/** A decoded frame. payload points into the decoder's buffer and is valid
 *  until the next call of fnav_wire_decode() on that decoder. */
typedef struct {
    uint8_t type;            /**< fnav_wire_type_t or an unknown type */
    uint8_t len;             /**< payload length, bytes */
    uint16_t seq;            /**< sender's frame counter */
    const uint8_t *payload;  /**< len bytes */
} fnav_wire_frame_t;

/** Compact navigation output carried by a NAV frame (float32 on the wire). */
typedef struct {
    int64_t t_ns;            /**< time of the sample the output follows, ns */
    uint32_t seq;            /**< sequence number of that sample */
    uint8_t flags;           /**< FNAV_FRAME_* bits (fnav_port.h) */
    uint32_t health;         /**< filter health bits */
    float pos_m[3];          /**< position in n, m */
    float vel_mps[3];        /**< velocity in n, m/s */
    float euler_rad[3];      /**< roll, pitch, yaw (ZYX), rad */
} fnav_wire_nav_t;

/** Sender counters carried by a STATUS frame. */
typedef struct {
    uint32_t samples;        /**< samples the sender processed (taken = these + overruns) */
    uint32_t overruns;       /**< samples lost before processing (ring full) */
    uint32_t est_errors;     /**< estimator calls that returned a failure */
    uint32_t tx_dropped;     /**< frames not sent because the link was busy */
    uint32_t uptime_ms;      /**< sender uptime, ms (wraps) */
} fnav_wire_status_t;

/** Stream description carried by an INFO frame. */
typedef struct {
    double rate_hz;                    /**< nominal sample rate, Hz (0: unknown) */
    uint32_t flags;                    /**< FNAV_WIRE_INFO_* bits */
    char sensor[FNAV_WIRE_SENSOR_SIZE];/**< sensor name, NUL-terminated */
    char axes[FNAV_WIRE_AXES_SIZE];    /**< axis note, NUL-terminated */
} fnav_wire_info_t;

/** Decoder counters (never reset by the decoder). */
typedef struct {
    uint32_t frames;         /**< CRC-valid frames delivered */
    uint32_t bad_frames;     /**< corrupt frames (CRC or length), each counted once */
    uint32_t skipped_bytes;  /**< bytes discarded outside valid frames */
    uint32_t lost;           /**< frames missing according to seq */
    uint32_t gaps;           /**< seq discontinuities (each may lose several frames) */
    uint32_t resets;         /**< seq went backwards: sender restarted or duplicate */
    uint32_t unknown;        /**< CRC-valid frames of an unknown type */
} fnav_wire_stats_t;

/** Streaming decoder. Caller-owned; about 300 bytes (304 on x86-64). */
typedef struct {
    uint8_t buf[FNAV_WIRE_MAX_FRAME]; /**< bytes of the frame being assembled */
    uint16_t fill;           /**< bytes held in buf */
    uint16_t consumed;       /**< size of the frame returned last (dropped on the next call) */
    uint16_t bad_until;      /**< bytes of buf inside an already-counted corrupt frame */
    uint16_t expect_seq;     /**< seq expected next */
    uint8_t have_seq;        /**< 1 once a frame was delivered */
    fnav_wire_stats_t stats; /**< counters */
} fnav_wire_decoder_t;

/**
 * CRC-32 (IEEE 802.3, reflected, as zlib's crc32()): pass 0 to start and the
 * previous result to continue. crc32("123456789") = 0xCBF43926.
 */
uint32_t fnav_crc32(uint32_t crc, const uint8_t *p, size_t n);

/**
 * Encode one frame.
 * @param out       output buffer
 * @param out_size  its size; needs FNAV_WIRE_FRAME_SIZE(len) bytes
 * @param type      frame type
 * @param seq       the sender's frame counter
 * @param payload   len bytes (may be NULL when len is 0)
 * @param len       payload length, at most FNAV_WIRE_MAX_PAYLOAD
 * @return frame size in bytes, or 0 when out is too small, len too large or
 *         an argument is NULL (nothing written)
 */
size_t fnav_wire_encode(uint8_t *out, size_t out_size, uint8_t type, uint16_t seq, const uint8_t *payload,
                        size_t len);

/** SAMPLE frame of @p s (values rounded to float32 in the double build).
 *  @return FNAV_WIRE_FRAME_SIZE(FNAV_WIRE_SAMPLE_LEN), or 0 as fnav_wire_encode(). */
size_t fnav_wire_encode_sample(uint8_t *out, size_t out_size, uint16_t seq, const fnav_sample_t *s);

/** NAV frame of a navigation output (position, velocity, attitude, flags,
 *  health; the biases and covariance stay on the sensor). */
size_t fnav_wire_encode_nav(uint8_t *out, size_t out_size, uint16_t seq, const fnav_nav_frame_t *f);

/** STATUS frame. */
size_t fnav_wire_encode_status(uint8_t *out, size_t out_size, uint16_t seq, const fnav_wire_status_t *st);

/** INFO frame (text fields cut to their size minus one). */
size_t fnav_wire_encode_info(uint8_t *out, size_t out_size, uint16_t seq, const fnav_wire_info_t *info);

/** END frame: the sender stops after @p count SAMPLE frames. */
size_t fnav_wire_encode_end(uint8_t *out, size_t out_size, uint16_t seq, uint32_t count);

/** Empty a decoder and zero its counters. Passes no FNAV_BUILD_TAG or size, unlike the other
 *  _init (no option moves the struct's layout; a flag such as -fpack-struct does, and is not caught:
 *  docs/firmware.md, "A library and a program built with other options"). */
void fnav_wire_decoder_init(fnav_wire_decoder_t *d);

/**
 * Feed received bytes and take out the next valid frame.
 *
 * Consumes input until a CRC-valid frame is complete (FNAV_OK, *frame set,
 * *used = bytes consumed) or the input is exhausted (FNAV_AGAIN, *used = n).
 * Call it again after FNAV_OK, with the remaining input (possibly none),
 * until it returns FNAV_AGAIN: bytes already buffered may hold more frames.
 * Corrupt frames are skipped and counted; the search for the next frame
 * restarts at the byte after the bad frame's sync word, so a frame that
 * follows a truncated one is not lost.
 *
 * @param d      decoder
 * @param in     received bytes (may be NULL when n is 0)
 * @param n      number of bytes
 * @param used   receives the number of bytes consumed
 * @param frame  receives the frame on FNAV_OK
 * @return FNAV_OK (a frame), FNAV_AGAIN (need more bytes), FNAV_E_ARG
 */
FNAV_WARN_UNUSED fnav_status_t fnav_wire_decode(fnav_wire_decoder_t *d, const uint8_t *in, size_t n, size_t *used,
                                                fnav_wire_frame_t *frame);

/**
 * The stream ended, or paused longer than a sender ever pauses inside a
 * frame: the candidate frame being assembled will not be completed. Reject
 * it (a truncated frame: counted once, as by fnav_wire_decode(), a lone first
 * sync byte only skipped) and take out the frames held behind it, which
 * fnav_wire_decode() would deliver only once the candidate's announced extent
 * (up to FNAV_WIRE_MAX_FRAME bytes) had arrived: at the end of a stream,
 * never (an END frame behind a truncated frame was not seen).
 *
 * Call it until it returns FNAV_AGAIN; the decoder is then empty (every
 * byte fed was skipped or delivered; the rejected candidate's extent ends
 * there, so a corrupt frame fed next counts on its own) and goes on with
 * fnav_wire_decode().
 * A frame cut by a pause longer than the receiver waited is lost (counted as
 * corrupt), so a receiver calls this after an idle time far longer than a
 * frame takes on its link, or at the end of a stream.
 *
 * @param d      decoder
 * @param frame  receives the frame on FNAV_OK (valid until the next call
 *               on d, as from fnav_wire_decode())
 * @return FNAV_OK (a frame), FNAV_AGAIN (the decoder is empty), FNAV_E_ARG
 */
FNAV_WARN_UNUSED fnav_status_t fnav_wire_decode_flush(fnav_wire_decoder_t *d, fnav_wire_frame_t *frame);

/** Sample of a SAMPLE frame, as sent (any finite float, any time; what a
 *  consumer accepts is its own policy: fnav_nav_push refuses values beyond
 *  FNAV_INPUT_MAX_ABS and times beyond FNAV_T_NS_MAX). @return FNAV_OK,
 *  FNAV_E_FORMAT (wrong type or length), FNAV_E_NANINF (a non-finite value:
 *  of the temperature only when the flags say it has one, since a sample
 *  without one carries NaN there; *s unchanged), FNAV_E_ARG (f, s or
 *  f->payload NULL; as for every parser below, nothing written). */
FNAV_WARN_UNUSED fnav_status_t fnav_wire_parse_sample(const fnav_wire_frame_t *f, fnav_sample_t *s);

/** Navigation output of a NAV frame. @return FNAV_OK, FNAV_E_FORMAT or FNAV_E_ARG. */
FNAV_WARN_UNUSED fnav_status_t fnav_wire_parse_nav(const fnav_wire_frame_t *f, fnav_wire_nav_t *nav);

/** Counters of a STATUS frame. @return FNAV_OK, FNAV_E_FORMAT or FNAV_E_ARG. */
FNAV_WARN_UNUSED fnav_status_t fnav_wire_parse_status(const fnav_wire_frame_t *f, fnav_wire_status_t *st);

/** Description of an INFO frame (text fields always NUL-terminated).
 *  @return FNAV_OK, FNAV_E_FORMAT, FNAV_E_ARG, or FNAV_E_RANGE when the
 *  rate is not a number in [0, 1e6] Hz (0: unknown; the .bin header's
 *  range; *info unchanged). */
FNAV_WARN_UNUSED fnav_status_t fnav_wire_parse_info(const fnav_wire_frame_t *f, fnav_wire_info_t *info);

/** Sample count of an END frame. @return FNAV_OK, FNAV_E_FORMAT or FNAV_E_ARG. */
FNAV_WARN_UNUSED fnav_status_t fnav_wire_parse_end(const fnav_wire_frame_t *f, uint32_t *count);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_WIRE_H */
