/* The first input byte of the log-reader fuzz target: its low five bits
 * select the format (0: detect, 1..: forced, as hx_format_t), bit 0x20
 * gives --input-rate 123 Hz to the whole-log loader, 0x40 names the file
 * .gz, 0x80 picks the whole-log loader over the streaming reader
 * (tests/fuzz/make_corpus.py writes the seeds so). */
#ifndef FUZZ_LOG_BYTE_H
#define FUZZ_LOG_BYTE_H

#include <stdint.h>

#include "hx_log.h"

static inline hx_format_t fuzz_log_format(uint8_t b)
{
    /* the flag bits left out: with them a forced format ran as another */
    return (hx_format_t)((b & 0x1F) % HX_FMT_COUNT);
}

#endif
