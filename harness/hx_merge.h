/**
 * @file hx_merge.h
 * @brief One sensor's file of a logger that writes the accelerometer and
 *        the gyroscope apart (MetaWear's MetaBase, phyphox, Sensor Logger),
 *        and the two merged onto one time line (`harness merge`,
 *        docs/log-format.md "Accelerometer and gyroscope in two files").
 *
 * A file is delimited text (comma, tab, semicolon or blanks; .gz too) with
 * a header naming a time column and the sensor's three axes: as the
 * interchange CSV's names are matched (hx_names.h: "Time (s)",
 * "Acceleration x (m/s^2)", "gyr_x") or bare axes ("x", "x-axis (g)",
 * "X"). Linux only (the harness), not part of the firmware core.
 */
#ifndef HX_MERGE_H
#define HX_MERGE_H

#include <stddef.h>
#include <stdint.h>

#include "hx_log.h"

/** Which sensor a file holds. */
typedef enum {
    HX_TRI_ACC = 0, /**< specific force, m/s^2 once read */
    HX_TRI_GYR = 1  /**< angular rate, rad/s once read */
} hx_tri_kind_t;

/** One sensor's samples, read whole. */
typedef struct {
    hx_tri_kind_t kind;
    size_t n;                 /**< samples kept (stamps increasing) */
    int64_t *t_ns;            /**< stamps, ns, in the file's own unit and epoch */
    double (*v)[3];           /**< m/s^2 or rad/s */
    double rate_hz;           /**< hx_stamp_rate_hz of the stamps (0: fewer than 2) */
    long steps_back;          /**< rows dropped: a stamp not after the last kept one's */
    int hdr_fields;           /**< fields of the header line */
    long rows_checked;        /**< data rows compared with the header's field count */
    long short_rows, short_first; /**< rows with fewer fields than the header (enough for the columns read),
                                       and the first one's line */
    long long_rows, long_first;   /**< rows with data past the header's fields, and the first one's line */
    hx_decimal_mix_t dmix;    /**< numbers with a decimal comma and with a point both (fields not comma-separated:
                                   both read as decimal marks), the first of each; said: the warning due */
    long cut_last;            /**< the line of a last line dropped (no newline, ending in a value read), 0 none */
    char cols[4][64];         /**< the names of the time column and of x, y, z, as the header spells them */
    int t_from_start;         /**< 1: the time column's name is a time from a start ("elapsed (s)"), which
                                   MetaWear counts from each file's own first sample */
    const char *time_unit;    /**< "s", "ms", "us", "ns"; NULL: dates and times (or clock times), read to ns
                                   whatever the unit named */
    const char *time_asked;   /**< the --units time= unit not read because the header names another (the
                                   time_unit read), NULL none */
    const char *unit;         /**< the values' unit: "m/s^2", "g", "mg", "ug", "rad/s", "deg/s", "mdps" */
    const char *unit_from;    /**< where the units came from: "named", "--units", "default" */
    char error[HX_ERR_SIZE];  /**< the error that stopped reading after a first sample ("" none) */
} hx_tri_t;

/** Read a whole file of kind (HX_TRI_ACC or HX_TRI_GYR). units: --units
 *  as parsed (hx_csv_units_parse; its accel and gyro items override a
 *  unit the header names; its time item gives the unit of a time whose
 *  name names none, as one option for two files: a unit named wins, and
 *  f->time_asked says one given was not read), NULL for none. A name of the other sensor with none
 *  of this one's is refused as swapped files; a file with both sensors'
 *  names is refused (read it directly); of several time columns the one
 *  of the clock two files share is read (a clock's name such as "epoch
 *  (ms)", then a date and time, then a name with its unit, then the
 *  first; MetaWear's "elapsed (s)" restarts in each file); a time column that names no unit
 *  whose stamps read in seconds give a rate outside 20 Hz - 100 kHz is
 *  refused with the unit they look like (hx_time_unit_fix). Returns 0
 *  (all read), 1 (read up to an error, f->error; the samples before it
 *  kept, at least one), -1 (nothing usable: err). */
int hx_tri_load(hx_tri_t *f, const char *path, hx_tri_kind_t kind, const hx_csv_layout_t *units, char *err,
                size_t err_size);
/** hx_tri_load with progress(ctx, fraction of the file read) every 65,536
 *  lines (progress NULL: none). Binary data and UTF-16 text are refused as
 *  every reader refuses them (hx_head_not_text). */
int hx_tri_load_progress(hx_tri_t *f, const char *path, hx_tri_kind_t kind, const hx_csv_layout_t *units,
                         void (*progress)(void *ctx, double frac), void *ctx, char *err, size_t err_size);
void hx_tri_free(hx_tri_t *f);

/** What a header of n fields f is, as one sensor's file: HX_TRI_ACC or
 *  HX_TRI_GYR when it names a time and that sensor's three axes and none of
 *  the other's, HX_TRI_BARE for a time and bare axes (x, y, z) alone, -1
 *  otherwise. The readers' refusal of such a header names `merge`. */
#define HX_TRI_BARE 2
int hx_tri_header_kind(char *const *f, int n);

/** hx_tri_at's answers. */
typedef enum {
    HX_TRI_IN = 0,     /**< value interpolated */
    HX_TRI_BEFORE = 1, /**< t before the file's first stamp */
    HX_TRI_AFTER = 2,  /**< t after its last */
    HX_TRI_GAP = 3     /**< t between two stamps more than gap_ns apart */
} hx_tri_where_t;

/** f's value at t_ns: linear between the two stamps around it (its own
 *  value at a stamp of its own). *j is a cursor (0 at first), kept between
 *  calls of increasing t_ns so that a merge walks each file once. */
hx_tri_where_t hx_tri_at(const hx_tri_t *f, int64_t t_ns, size_t *j, int64_t gap_ns, double v[3]);

/** The interval beyond which the other file has a gap and no value is
 *  interpolated: this many of its periods (two samples lost in a row are
 *  bridged, three are not). */
#define HX_MERGE_GAP_PERIODS 3.0

#endif /* HX_MERGE_H */
