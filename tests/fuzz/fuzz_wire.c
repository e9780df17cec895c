/* Fuzz target: the wire-protocol decoder (src/fnav_wire.c) and every frame
 * parser. The first input byte sets the chunk size the stream is fed in
 * (1..256 bytes), so resynchronisation across chunk boundaries is covered;
 * the rest is the received byte stream. Checks the decoder's invariants:
 * every byte fed is consumed, skipped, delivered or still buffered; after
 * fnav_wire_decode_flush() (the end of the stream) nothing is buffered. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "footnav/fnav_wire.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fnav_wire_decoder_t d;
    size_t chunk, off, delivered = 0;
    if (size < 1) {
        return 0;
    }
    chunk = (size_t)data[0] + 1u;
    data++;
    size--;
    fnav_wire_decoder_init(&d);
    for (off = 0; off < size || off == 0;) {
        size_t k = (size - off < chunk) ? size - off : chunk, pos = 0;
        for (;;) {
            size_t used;
            fnav_wire_frame_t f;
            fnav_sample_t s;
            fnav_wire_nav_t nav;
            fnav_wire_status_t st;
            fnav_wire_info_t info;
            uint32_t count;
            if (fnav_wire_decode(&d, data + off + pos, k - pos, &used, &f) != FNAV_OK) {
                pos += used;
                break;
            }
            pos += used;
            delivered += FNAV_WIRE_FRAME_SIZE((size_t)f.len);
            (void)fnav_wire_parse_sample(&f, &s);
            (void)fnav_wire_parse_nav(&f, &nav);
            (void)fnav_wire_parse_status(&f, &st);
            if (fnav_wire_parse_info(&f, &info) == FNAV_OK &&
                (memchr(info.sensor, 0, sizeof info.sensor) == NULL || memchr(info.axes, 0, sizeof info.axes) == NULL)) {
                abort(); /* text fields must come out NUL-terminated */
            }
            (void)fnav_wire_parse_end(&f, &count);
        }
        if (pos != k) {
            abort(); /* FNAV_AGAIN must mean all input was consumed */
        }
        off += k;
        if (size == 0) {
            break;
        }
    }
    if (d.fill > FNAV_WIRE_MAX_FRAME || (size_t)d.stats.skipped_bytes + delivered + d.fill != size) {
        abort();
    }
    {
        fnav_wire_frame_t f;
        fnav_status_t st;
        while ((st = fnav_wire_decode_flush(&d, &f)) == FNAV_OK) {
            delivered += FNAV_WIRE_FRAME_SIZE((size_t)f.len);
        }
        if (st != FNAV_AGAIN || d.fill != 0u || (size_t)d.stats.skipped_bytes + delivered != size) {
            abort();
        }
    }
    return 0;
}
