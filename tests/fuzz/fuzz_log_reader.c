/* Fuzz target: every log reader (.bin, CSV and the importers). The first
 * input byte selects the format (0: detect, 1..: forced) and whether the
 * whole-log loader or the streaming reader is used (a CSV also under
 * --units, and under --columns with --units); the rest is the file. */
#include <stdint.h>
#include <string.h>

#include "fuzz_log_byte.h"
#include "fuzz_support.h"
#include "hx_log.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[320];
    const char *path;
    hx_format_t fmt;
    int whole;
    if (size < 1) {
        return 0;
    }
    fmt = fuzz_log_format(data[0]);
    whole = (data[0] & 0x80) != 0;
    path = fuzz_write_input(data + 1, size - 1, (data[0] & 0x40) ? ".gz" : ".log");
    if (path == NULL) {
        return 0;
    }
    if (whole) {
        hx_log_t log;
        if (hx_log_load(&log, path, fmt, (data[0] & 0x20) ? 123.0 : 0.0, err, sizeof err) >= 0) {
            hx_log_free(&log);
        }
    } else {
        /* the streaming reader as the file's format reads it, then, for a
         * CSV (given or detected), again under --units (the time unit by the
         * input's size: s, ms, us, ns; g, deg/s), whose time parsing moves
         * the decimal point in the text, and under --columns (the map by the
         * input's size, size / 4 % 4: swapped names the interchange seeds
         * read, the phone export of seed csv_columns, a map refused for
         * naming one column twice, names with blanks) with the same --units;
         * another detected format is refused */
        int pass;
        for (pass = 0; pass < (fmt == HX_FMT_AUTO || fmt == HX_FMT_CSV ? 3 : 1); pass++) {
            hx_reader_t *r;
            if (pass >= 1) {
                static const char *const units[4] = { "time=s,accel=g,gyro=deg/s", "time=ms,accel=g,gyro=deg/s",
                                                      "time=us,accel=g,gyro=deg/s", "time=ns,accel=g,gyro=deg/s" };
                static const char *const columns[4] = {
                    "ax=ay,ay=ax,gx=gz,gz=gx", "t=timestamp_ns,ax=acc_x,ay=acc_y,az=acc_z,gx=gyro_x,gy=gyro_y,gz=gyro_z",
                    "ax=ay", " t = time , temp = \"temperature\" "
                };
                const size_t c = (size >> 2) & 3u;
                hx_csv_layout_t l;
                hx_csv_layout_default(&l);
                if (pass == 2 && (hx_csv_columns_parse(&l, columns[c], err, sizeof err) != 0) != (c == 2u)) {
                    __builtin_trap(); /* a valid map refused, or ax=ay (ay keeps its own name) taken */
                }
                if (pass == 2 && c == 2u) {
                    continue;
                }
                if (hx_csv_units_parse(&l, units[size & 3u], err, sizeof err) != 0) {
                    __builtin_trap();
                }
                hx_reader_set_layout(&l);
            }
            r = hx_reader_open(path, fmt, 0.0, err, sizeof err);
            if (r != NULL) {
                fnav_sample_t s;
                long n = 0;
                while (hx_reader_next(r, &s) == FNAV_OK && n < 1000000) {
                    n++;
                }
                (void)hx_reader_error(r);
                (void)hx_reader_warnings(r);
                hx_reader_close(r);
            }
        }
        hx_reader_set_layout(NULL);
    }
    unlink(path);
    return 0;
}
