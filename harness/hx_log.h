/**
 * @file hx_log.h
 * @brief Harness log I/O: the footnav .bin log (docs/log-format.md), the CSV
 *        interchange format and importers for every format in ../shared/data.
 *
 * Linux only (not part of the firmware core). Readers are incremental: open,
 * then pull one sample at a time, so that a replay feeds the core sample by
 * sample exactly as firmware would. Text inputs may be gzip-compressed.
 *
 * Error policy: a reader delivers every good sample it can. Corrupted .bin
 * records are skipped and counted; the first problem is remembered and
 * returned (instead of FNAV_END) once the input is exhausted, so a caller
 * processes everything before it reports the error and exits non-zero.
 * A malformed text line stops a text reader at that line.
 */
#ifndef HX_LOG_H
#define HX_LOG_H

#include <stdio.h>
#include <zlib.h>
#include "footnav/fnav_types.h"
#include "footnav/fnav_stance.h"
#include "hx_names.h"

/** Input formats. */
typedef enum {
    HX_FMT_AUTO = 0,   /**< detect from content */
    HX_FMT_BIN,        /**< footnav .bin log */
    HX_FMT_CSV,        /**< t,ax,ay,az,gx,gy,gz[,temp] (s, m/s^2, rad/s, degC) */
    HX_FMT_GX2,        /**< OpenShoe MicroStrain 3DM-GX2 text */
    HX_FMT_OS820,      /**< OpenShoe C 820 Hz CSV without header */
    HX_FMT_NGIMU,      /**< x-io NGIMU CSV (deg/s, g) */
    HX_FMT_PYSHOE,     /**< PyShoe / LLIO CSV (t_s, m/s^2, rad/s) */
    HX_FMT_IPOL,       /**< IPOL Xsens MTw text (packet counter, 100 Hz) */
    HX_FMT_ADIS,       /**< ADIS16405 static CSV (deg/s, g, no time) */
    HX_FMT_SQUARE2,    /**< ZUPT-aided-INS square2 CSV (sample index, 100 Hz) */
    HX_FMT_MTMGR,      /**< Xsens MT Manager ASCII export (SampleTimeFine or PacketCounter; hx_xsens.h) */
    HX_FMT_PICOQUAKE,  /**< PLab PicoQuake acquisition CSV (sample count at the '# Config:' data_rate; g, deg/s) */
    HX_FMT_COUNT
} hx_format_t;

/** What is known about a log besides its samples. */
typedef struct {
    hx_format_t format;     /**< format actually read */
    double rate_hz;         /**< nominal sample rate, Hz (0 if unknown) */
    int rate_nominal;       /**< 1: rate from the source; 0: estimated from time stamps */
    int rate_coarse;        /**< estimated from stamps too coarse for their median interval (hx_stamp_rate_hz) */
    double rate_start_hz;   /**< with an estimated rate: 1 / the median of the positive intervals among the
                                 first FNAV_STANCE_RATE_PROBE, the stance detector's own estimate (0: none) */
    double rate_span_hz;    /**< with an estimated rate: the second half of the first 4096 stamps' intervals,
                                 their count over their sum, intervals over 0.2 s left out (0: none) */
    int has_temp;           /**< samples carry temperature */
    int has_seq;            /**< samples carry a sensor record counter */
    int stamps_made;        /**< 1: the format has no time stamps; they are the line index / rate */
    int rate_ignored;       /**< 1: --input-rate was given and ignored (the format has time stamps) */
    char sensor[32];        /**< sensor name, e.g. "x-io NGIMU" */
    char source[60];        /**< where the data came from (file or description) */
    char axes[48];          /**< axis note, e.g. "z up at rest" */
} hx_meta_t;

/** Counters kept while reading. */
typedef struct {
    long records;           /**< samples delivered */
    long bad_records;       /**< .bin records skipped (CRC, type, resync) */
    long skipped_bytes;     /**< .bin bytes skipped while resynchronising */
    long lines;             /**< text lines consumed */
    int clean_end;          /**< .bin: END record seen with matching count */
    long cut_lines;         /**< text: an incomplete last line ignored (cut off mid-write; 0 or 1) */
} hx_read_stats_t;

typedef struct hx_reader hx_reader_t;

/** Name of a format ("bin", "csv", "gx2", ...). */
const char *hx_format_name(hx_format_t fmt);
/** Format from its name; HX_FMT_COUNT if unknown. */
hx_format_t hx_format_from_name(const char *name);
/** Whether two column names are equal but for case, blanks, quotes and
 *  carriage returns ("acc_x" and "Acc_X"), as the readers match headers. */
int hx_name_eq(const char *a, const char *b);
/** Split a text line in place at delim into at most max fields, as the
 *  text readers do: ' ' splits at runs of blanks and tabs (a date and a
 *  clock time after it stay one field), any other delimiter inside double
 *  quotes is the field's, and a field loses the blanks, quotes and line
 *  ends around it. Returns the count. */
int hx_split_fields(char *line, char delim, char **f, int max);
/** A time stamp as text to integer ns, as the readers read it: exactly
 *  for a plain decimal in the unit of 10^digits ns (9 s, 6 ms, 3 us, 0 ns;
 *  the point moves in the text), a date and time as such (its own unit).
 *  0 ok; -1 not a number, -2 NaN or out of range, -3 beyond int64 ns,
 *  -4/-5 a date and time that is none. */
int hx_parse_time_ns(const char *s, int digits, int64_t *out);
/** 1 when s reads as a date and time, or a clock time alone, as
 *  hx_parse_time_ns reads them ("2024-05-01 12:00:00.5", MetaBase's
 *  "2019-12-22T07.33.20.000", "23:59:59"); 0 otherwise (a number). */
int hx_is_datetime(const char *s);
/** The first of the n header fields f that is name (hx_name_eq); -1 when
 *  none is. */
int hx_find_col(char **f, int n, const char *name);
/** The format names a user gives to --from, comma-separated: the one list
 *  behind --help (HX_INPUT_OPTS) and the error of an unknown name; a new
 *  importer adds its name here and in k_format_names (hx_log.c). */
/** Room for a reader's message: the path (a few hundred bytes) and the
 *  longest remedy (about 400: the Movella DOT CSV's, the other names', a
 *  stamps-in-bursts refusal's "convert it to CSV ..."); 320 bytes would
 *  cut them behind a path of 30-110 bytes. Every buffer a command passes
 *  for an error message is this size (eval's row notes this and room for
 *  its own words, cmd_eval.c's EV_NOTE_SIZE): with 200 to 768 bytes eval
 *  would cut a non-CSV log's bursts remedy (tests/cli/test_eval_data.sh). */
#define HX_ERR_SIZE 1024
/** Room for a reader's warnings, one a line (hx_reader_warnings): a
 *  names-matched header's alone takes up to ~1000 bytes (names_apply's 700
 *  of mapping and 300 of near misses). The reader, hx_log_t.warnings and
 *  hx_print_warnings hold this much. */
#define HX_WARN_SIZE 2048

#define HX_FORMAT_LIST "bin, csv, gx2, openshoe820, ngimu, pyshoe, ipol, adis, square2, mtmanager, picoquake"
/** Comma-separated list of the format names (HX_FORMAT_LIST). */
const char *hx_format_list(void);

/** The interchange CSV under another layout (--columns, --units;
 *  docs/log-format.md, "Another layout"): the file's name of each
 *  interchange column and the units of its time, accelerations and rates. */
typedef struct {
    char names[8][64];  /**< the file's column for t, ax, ay, az, gx, gy, gz, temp; "" keeps the default name */
    char tns[64];       /**< the column of nanoseconds added to t, in whole s (--columns tns=, ROS's
                             header.stamp.nsecs beside header.stamp.secs); "" none */
    int time_digits;    /**< ns per unit of the time column as a power of ten: 9 s, 6 ms, 3 us, 0 ns */
    double acc_scale;   /**< m/s^2 per unit of the accelerations (1, HX_G_MPS2 for g, HX_MG_MPS2 for mg, HX_UG_MPS2 for ug) */
    double gyr_scale;   /**< rad/s per unit of the rates (1, HX_DPS_RPS for deg/s, HX_MDPS_RPS for mdps) */
    const char *option; /**< "--columns", "--units" or "--columns and --units": the options that gave it; NULL: defaults */
    int units_given;    /**< the --units items given: 1 time, 2 accel, 4 gyro (a unit in a matched name gives the others) */
    int names_matched;  /**< the names were matched from the header without --columns (hx_names.h) */
    int negate;         /**< bit k set: key k's column (1..6, ax..gz) read with the other sign, a '-' before
                             its name in --columns ("ax=-acc_x": iOS's accelerations, a flipped axis) */
} hx_csv_layout_t;

/** The scales of --units (hx_csv_layout_t.acc_scale, gyr_scale): m/s^2 per
 *  g and per mg, rad/s per deg/s and per mdps. */
#define HX_G_MPS2 9.80665
#define HX_MG_MPS2 0.00980665
#define HX_UG_MPS2 9.80665e-6 /* micro-g: the standard g of g and mg, 1e-6 of it */
#define HX_DPS_RPS (3.14159265358979323846 / 180.0)
#define HX_MDPS_RPS (3.14159265358979323846 / 180.0 / 1000.0)
/** The --units name of an acceleration scale: "g", "mg", else "m/s2". */
const char *hx_accel_unit_name(double acc_scale);
/** The --units name of a rate scale: "deg/s", "mdps", else "rad/s". */
const char *hx_gyro_unit_name(double gyr_scale);

/** Set on l the field of the quantity of a unit a header names (the time
 *  column's digits, the accel or gyro scale); HX_UNIT_NONE sets none. */
void hx_csv_layout_unit(hx_csv_layout_t *l, hx_name_unit_t u);
/** The interchange names and units (t,ax,...,temp in s, m/s^2, rad/s). */
void hx_csv_layout_default(hx_csv_layout_t *l);
/** Parse a --columns MAP ("t=timestamp_ns,ax=acc_x,..."; keys t, ax, ay, az,
 *  gx, gy, gz, temp, and tns: nanoseconds added to t's whole seconds) into l. 0 ok; -1 with a message in err (an unknown key,
 *  a key given twice, a missing '=', an empty name, one column named for two
 *  keys, counting the default names of the keys not given). */
int hx_csv_columns_parse(hx_csv_layout_t *l, const char *map, char *err, size_t err_size);
/** The options that read the log of layout l (the reader's, hx_units_layout)
 *  with its gyro read anew: gyro key i (gx, gy, gz) from the column l reads
 *  as key src[i] (0..2: gx..gz), with the other sign when neg[i]. Every key
 *  l names is named ("--columns t=time,ax=acc_x,...,gy=-gyr_y,...": a
 *  --columns given turns the names' matching off, so a partial one would
 *  lose the others), the three gyro keys always, and the --units of l's
 *  units when they are not all the defaults; the map quoted when a name is
 *  not one shell word (a name's own ' dropped: names match without their
 *  quotes). The axes check's remedy (docs/harness.md, "Axes check").
 *  Returns buf; NULL (buf "") when a name holds a ',', which no --columns
 *  can give (it separates the items), or the text does not fit. */
const char *hx_columns_give(const hx_csv_layout_t *l, const int src[3], const int neg[3], char *buf, size_t size);
/** Parse a --units SPEC ("time=ns,accel=g,gyro=deg/s"; time s|ms|us|ns,
 *  accel m/s2|m/s^2|mps2|g|mg, gyro rad/s|deg/s|dps|mdps|mdeg/s) into l.
 *  0 ok; -1 with a message in err. */
int hx_csv_units_parse(hx_csv_layout_t *l, const char *spec, char *err, size_t err_size);
/** The layout every reader opened afterwards in this process reads the
 *  interchange CSV with (NULL: the defaults); set once from a command's
 *  --columns and --units (hx_cli.c). A layout given by an option makes
 *  opening a log of another format an error that names the option. */
void hx_reader_set_layout(const hx_csv_layout_t *l);
/** The layout hx_reader_set_layout set (the defaults when none was). */
void hx_reader_layout(hx_csv_layout_t *l);
/** The layout a units remedy names --units from (the csv of
 *  hx_units_problem and hx_time_unit_hint): for a log of format fmt read
 *  by a command that takes --units, the reader's layout in *buf when fmt is
 *  the interchange CSV, which --units reads (with the names and units the
 *  last CSV opened was matched to, when its header was read without
 *  --columns: docs/log-format.md, "Names read without --columns"); NULL for
 *  another format, whose remedy is the arithmetic. */
const hx_csv_layout_t *hx_units_layout(hx_format_t fmt, hx_csv_layout_t *buf);
/** The refusal of a layout (opt: its option, hx_csv_layout_t.option) for a
 *  log of another format fmt, one text for the usage error of
 *  hx_check_input_opts and the reader's error: "[PATH: ]OPT applies to the
 *  interchange CSV (format csv), not to the FMT format", and for a format
 *  detected from the content (not given with --from) where it came from
 *  and, but for a .bin (no text), "give --from csv". path NULL: none. */
void hx_layout_refusal(char *msg, size_t msg_size, const char *path, const char *opt, hx_format_t fmt,
                       int detected);
/** Open a log for reading with zlib, as gzopen(path, "rb") but for a pipe:
 *  a FIFO (`harness replay <(ssh host cat log)`, /dev/stdin from a pipe)
 *  is copied once into an unlinked temporary file, which
 *  every later open of the same path reads again (the readers read a log
 *  more than once: detection, the rate's estimate, the loader's count). A
 *  character device but /dev/null (a terminal, a serial port) is refused:
 *  it would be read for ever. NULL with err filled ("PATH: ...") on
 *  failure. */
gzFile hx_gzopen_input(const char *path, char *err, size_t err_size);
/** The format detection gives a file's content (HX_FMT_AUTO: unreadable). */
hx_format_t hx_detect_file(const char *path);

/**
 * Open a log for reading.
 * @param path       file to read (text formats may be .gz)
 * @param fmt        format or HX_FMT_AUTO to detect it
 * @param rate_hz    sample rate to use for formats without time stamps
 *                   (0: the format's documented default)
 * @param err        receives a one-line message on failure
 * @return reader, or NULL on failure with err filled
 */
hx_reader_t *hx_reader_open(const char *path, hx_format_t fmt, double rate_hz,
                            char *err, size_t err_size);

/** What a file's first bytes say when it is no text (hx_head_not_text). */
typedef enum {
    HX_HEAD_TEXT = 0, /**< text, as far as its first bytes tell */
    HX_HEAD_UTF16,    /**< UTF-16 text (Windows' "Unicode text"), with or without a byte-order mark */
    HX_HEAD_BINARY,   /**< a byte no text holds (a control character but tab, LF, VT, FF, CR; DEL) */
    HX_HEAD_CONTAINER /**< a known archive, container or database (zip, HDF5, a ROS bag, ...) by its magic */
} hx_head_t;

/** Whether the file @p path, whose first bytes are head[0..n), is no text:
 *  UTF-16 (msg gets "PATH: UTF-16 text, not UTF-8 (save it as UTF-8, e.g.
 *  iconv -f ENC -t UTF-8 PATH > copy.csv; ...)", ENC as iconv reads it)
 *  or binary data (msg gets "PATH: binary data, not a log: its first bytes
 *  .. hold 0x.. at byte N, ..."), for a log (@p series 0) or a series of
 *  numbers (1: "not a series", copy.txt, docs/allan.md), or a known
 *  archive, container or database by its first bytes (msg gets "PATH: a
 *  ZIP archive (...), not a log: unzip it ..." with what to do); msg is
 *  left alone for text. The readers' open, `merge` and `allan --series`
 *  share it; UTF-16 and a container are refused at once. */
hx_head_t hx_head_not_text(const char *path, const unsigned char *head, size_t n, int series, char *msg,
                           size_t msg_size);

/** Next sample. FNAV_OK with *s, FNAV_END at a clean end, negative status
 *  on an error (message from hx_reader_error()). */
fnav_status_t hx_reader_next(hx_reader_t *r, fnav_sample_t *s);

/** One-line description of the last error: "FILE:LINE: text" or
 *  "FILE: record N: text". Empty string when there was none. */
const char *hx_reader_error(const hx_reader_t *r);

/** Warnings collected so far (e.g. "assuming 820 Hz"), newline-separated;
 *  a line that starts with "note: " is a note (routine, e.g. a GX2 timer
 *  restart bridged), which hx_print_warnings prints as one. */
const char *hx_reader_warnings(const hx_reader_t *r);
/** The warnings added since the last call (all of them the first time),
 *  newline-separated; for printing each warning once, as it appears. */
const char *hx_reader_take_warnings(hx_reader_t *r);

const hx_meta_t *hx_reader_meta(const hx_reader_t *r);
const hx_read_stats_t *hx_reader_stats(const hx_reader_t *r);
/** Fraction of the input file consumed so far (0..1, compressed bytes for
 *  .gz), for progress indicators; -1 when unknown. */
double hx_reader_progress(const hx_reader_t *r);
void hx_reader_close(hx_reader_t *r);

/* ------------------------------------------------------------------ */

typedef struct hx_writer hx_writer_t;

/**
 * Open a log for writing; the format is HX_FMT_BIN or HX_FMT_CSV (AUTO:
 * from the extension, ".bin" -> BIN, anything else CSV).
 * @param sync_each  1: every record reaches the OS before the call returns,
 *                   so a killed process leaves every written record intact
 */
hx_writer_t *hx_writer_open(const char *path, hx_format_t fmt, const hx_meta_t *meta,
                            int sync_each, char *err, size_t err_size);
fnav_status_t hx_writer_write(hx_writer_t *w, const fnav_sample_t *s);
/** .bin: write the header again for meta (the file's records stay);
 *  FNAV_E_IO when the file cannot seek (a pipe: the header stays) or the
 *  write fails. */
fnav_status_t hx_writer_rewrite_header(hx_writer_t *w, const hx_meta_t *meta);
/** Finish the file (.bin: END record) and close it. */
fnav_status_t hx_writer_close(hx_writer_t *w, char *err, size_t err_size);
/** Close a file whose input stopped at an error: a .bin gets no END
 *  record, so every reader says it is incomplete (a CSV closes as above). */
fnav_status_t hx_writer_close_cut(hx_writer_t *w, char *err, size_t err_size);

/* ------------------------------------------------------------------ */

/** A whole log in memory (for analyses that need random access). */
typedef struct {
    hx_meta_t meta;
    hx_read_stats_t stats;
    size_t n;               /**< number of samples */
    int64_t *t_ns;
    uint32_t *seq;
    double (*acc)[3];       /**< m/s^2 (float32 values held exactly) */
    double (*gyr)[3];       /**< rad/s */
    double *temp;           /**< degC, NaN when unknown */
    fnav_status_t status;   /**< FNAV_END when read completely, else the error */
    char error[HX_ERR_SIZE]; /**< the error, if any */
    char warnings[HX_WARN_SIZE]; /**< the reader's warnings, one a line */
} hx_log_t;

/** 1 when the end characters of s before index end (strlen(s) for the
 *  whole string) are suffix (given in lower case), in any case. */
int hx_ends_in(const char *s, size_t end, const char *suffix);
/** Sampling rate (Hz) of n time stamps (ns), on the strictly increasing
 *  stamps (duplicates and steps back dropped). When the stamps resolve the
 *  period (their resolution, the intervals' greatest common divisor, is at
 *  most 1/1000 of the median interval): 1 / the median interval. Coarser
 *  stamps (a 398 Hz log printed to the millisecond reads 2 and 3 ms, whose
 *  median gives 333 or 500 Hz): a first period T1 from the median of spans
 *  of 16 intervals / 16, then the mean of the intervals up to 1.5 T1 (+ the
 *  resolution unless T1 is a whole number of resolutions, as with stamps
 *  from a sample counter): lost samples left out. 0 when no two stamps
 *  increase. *coarse (may be NULL) is set to 1 when the stamps were coarse. */
double hx_stamp_rate_hz(const int64_t *t_ns, size_t n, int *coarse);
/** What the irregular intervals of a log were, for allan's and psd's
 *  warning, one form for both: "N of M intervals differ from 1/R s by more
 *  than 10 %, N of them time stamps repeated, M of them gaps (longest L s;
 *  about K samples missing in all, P % of the log)" (either part left out
 *  when 0) into buf; of one irregular interval ("1 of M intervals
 *  differs ..."), what it is: " (a gap of L s; about K samples missing, P %
 *  of the log)", " (a time stamp repeated)" or nothing. total the
 *  intervals checked, rate_hz the rate they were checked against (%.4g), n
 *  the samples read. */
void hx_irregular_text(char *buf, size_t size, long irregular, size_t total, double rate_hz, long repeats, long gaps,
                       double longest_gap_s, double missing, double n);
/** ", and the samples are joined across the gap(s) as if consecutive"
 *  for gaps > 0, else "". */
const char *hx_gaps_joined(long gaps);

/** Greatest common divisor of a >= 0 and b >= 0 (Euclid); gcd(a, 0) = a.
 *  Folded over the positive intervals of time stamps it gives their
 *  resolution. */
int64_t hx_gcd_i64(int64_t a, int64_t b);

/** 1 when an interval of dt_ns is irregular at rate_hz: more than 10 % of a
 *  period off it, or, with stamps of resolution res_ns coarser than the
 *  period (0 for fine stamps), more than that plus the resolution (398 Hz
 *  printed to the millisecond reads 2 and 3 ms) unless the period is a
 *  whole number of resolutions (100 Hz printed to 10 ms: exact intervals,
 *  as hx_stamp_rate_hz reads them). The uniform-sampling
 *  check of psd and allan. */
int hx_interval_irregular(int64_t dt_ns, double rate_hz, int64_t res_ns);
/** The samples an interval of dt_ns lost at rate_hz: 0 unless it is a gap
 *  (over 1.5 periods, plus the resolution's slack of hx_interval_irregular),
 *  else the periods it spans less one. allan's and simgap's gap count. */
double hx_interval_missing(int64_t dt_ns, double rate_hz, int64_t res_ns);

/** The highest rate a foot-mounted IMU's time stamps give, Hz: above it
 *  (as below 20 Hz) the stamps' unit is questioned. */
#define HX_TIME_RATE_MAX_HZ 1e5
/** The unit of time stamps that read rate_hz in the unit of 10^digits ns
 *  (9 s, 6 ms, 3 us, 0 ns): the first of 1000, 1e6 and 1e9 times slower
 *  stamps that makes the rate 20 Hz to 100 kHz; above 100 kHz, the first of
 *  1000, 1e6 and 1e9 times faster ones, at most seconds (fast). */
typedef struct {
    const char *read; /**< the unit read ("seconds") */
    const char *name; /**< the unit the stamps look like ("milliseconds"); NULL: none (0 returned) */
    const char *opt;  /**< its --units item ("ms") */
    const char *div;  /**< the divisor of the values as read ("1000"); fast: their factor */
    int fast;         /**< 1: the stamps were read too fast (multiply by div), 0: too slow */
    double rate_hz;   /**< the rate in that unit */
    int digits;       /**< that unit as hx_csv_layout_t.time_digits */
} hx_time_fix_t;
/** Fill fix for rate_hz read in 10^digits ns: 1 when a unit (at most ns)
 *  makes the rate 20 Hz to 100 kHz, else 0 (fix->read still set). The
 *  remedy of hx_units_problem and hx_time_unit_hint. */
int hx_time_unit_fix(double rate_hz, int digits, hx_time_fix_t *fix);
/** Excel's separator line before a header ("sep=;", "\"sep=\t\"", as
 *  Shimmer's Consensys writes it): 1 and the separator in *d, else 0. The
 *  log reader's and merge's. */
int hx_sep_line(const char *s, char *d);
/** What a line of a text log whose first character but blanks is '#' is
 *  before the header (hx_comment_line). */
typedef enum {
    HX_COMMENT_NONE = 0,          /**< no comment line */
    HX_COMMENT_NOTE = 1,          /**< a comment, skipped */
    HX_COMMENT_HEADER = 2,        /**< a commented header: numpy's savetxt "# t,ax,..." (the name t is enough;
                                       blank-separated, all seven interchange names) */
    HX_COMMENT_HEADER_IF_DATA = 3 /**< a time and the six channels by name (EuRoC's "#timestamp [ns],..."): the
                                       header when a row of data follows it (hx_data_row), else a note */
} hx_comment_t;
/** Classify line as the log reader does before the header; *text: the
 *  comment's text after the '#' and blanks (unless HX_COMMENT_NONE). */
hx_comment_t hx_comment_line(const char *line, const char **text);
/** Whether line is a row of data: its first field (after blanks and a
 *  quote) a number, a date and time, or a date. */
int hx_data_row(const char *line);
/** The text readers' line buffer, bytes (the log reader's and merge's): a
 *  line of more than HX_LINE_MAX - 1 bytes with its line end (4094
 *  characters and a newline fit, not 4095) stops the read, "PATH:LINE:
 *  line longer than 4095 bytes with its line end" (docs/log-format.md, "CSV
 *  interchange"). */
#define HX_LINE_MAX 4096
/** A line cut by a NUL byte (gzgets stops at none: the text after it is
 *  lost), as every text reader says it after "PATH:LINE: ". */
#define HX_NUL_TEXT "a NUL byte in the text (binary data, e.g. a logger's unwritten blocks)"
/** A last line without a newline that ends in a value read, dropped, as
 *  the interchange CSV's reader and merge say it after "PATH:LINE: ". */
#define HX_CUT_LAST_TEXT                                                                                      \
    "last line has no newline and ends in a value the reader uses, which may be cut (file cut off mid-write?); " \
    "ignored"
/** The stance detector's rate probe: the intervals among its first samples
 *  it takes the median of (fnav_stance.c PROBE; fewer with a shorter ring). */
#define HX_STANCE_PROBE                                                                                       \
    (FNAV_STANCE_MAX_WINDOW - 1 < FNAV_STANCE_RATE_PROBE ? FNAV_STANCE_MAX_WINDOW - 1 : FNAV_STANCE_RATE_PROBE)

/** The fields of a header line as written, its delimiters counted outside
 *  double quotes (1 for a blank-separated line: not counted). */
int hx_fields_total(const char *line, char delim);
/** The header's named fields: n split of total, trailing empty names (a
 *  trailing delimiter) not counted when the split kept them all. */
int hx_named_fields(char **f, int n, int total);

/** 1 when a line holds a carriage return before more text: lines ending in
 *  a CR alone (classic Mac OS), read as one; HX_CR_ALONE_HINT says so. */
int hx_cr_alone(const char *line);
/** gzgets into buf (size bytes), its length in *len; *nul 1 when the bytes
 *  read (gztell) outrun the string: a NUL byte cut it, wherever it is (a
 *  last line without a newline too, which gzgets ends at the file's end).
 *  NULL at the end or on an error, as gzgets. */
char *hx_gzgets(gzFile gz, char *buf, int size, size_t *len, int *nul);
#define HX_CR_ALONE_HINT                                                                                      \
    " (its lines end in a carriage return alone, the old Mac OS convention: convert them, e.g. tr '\\r' '\\n')"

/** Replaces the characters of s that hx_text_char shows as '?' (ASCII's
 *  controls, C1's in UTF-8, and each byte of no well-formed UTF-8
 *  character) with '?' in place, one '?' for each (the text may get
 *  shorter); returns how many there were. The text of a file that a
 *  message or a report shows (a .bin header's, a quoted field) goes
 *  through it, so that it cannot reach the terminal as an escape
 *  sequence or forge a line. Shared by the readers and merge. */
int hx_printable(char *s);

/** The warning for data rows whose field count is not the header's
 *  hdr_fields: more = 0, rows with fewer (enough for the columns read);
 *  more = 1, rows with data past the header's fields, of checked rows
 *  compared (every one: the header lacks a name). first: the first such
 *  row's line. Written to buf; returns buf. Shared by the readers and merge. */
const char *hx_field_count_text(const char *path, long first, long rows, long checked, int hdr_fields, int more,
                                char *buf, size_t size);

/** Numbers written with a decimal comma and with a decimal point in the
 *  columns one log's reader reads where a comma can be one (fields not
 *  comma-separated): the first of each, and whether said. Zeroed to start. */
typedef struct {
    long comma_line, point_line; /**< their lines, 0 none yet */
    char comma[24], point[24];   /**< their fields; one longer than 23 bytes cut to 20 and "..." */
    int said;                    /**< the warning was due once */
} hx_decimal_mix_t;
/** Note field s of line: 1 when it makes the log's numbers hold both
 *  marks for the first time (the warning due, hx_decimal_mix_text), else
 *  0. Only a well-formed number counts ("-0,5", "9.81e+00"; not a date). */
int hx_decimal_mix_note(hx_decimal_mix_t *m, const char *s, long line);
/** The warning of a log whose numbers have both decimal marks, at the
 *  line of the later one's first: both read as decimal marks, a point
 *  there perhaps a thousands separator. Written to buf; returns buf.
 *  Shared by the readers and merge. */
const char *hx_decimal_mix_text(const hx_decimal_mix_t *m, const char *path, char *buf, size_t size);

/** The remedy "give --units ITEMS" naming every unit item of want, the
 *  layout that reads the log (time=, accel=g, gyro=deg/s, in the
 *  synopsis's order): one --units value, since a second --units replaces
 *  the first; "leave --units out" when every item is the default (s,
 *  m/s^2, rad/s). Returns buf. */
const char *hx_units_give(const hx_csv_layout_t *want, char *buf, size_t size);
/** Whether a value v read in a unit of scale SI units each is beyond what
 *  any sensor reads (|v scale| > FNAV_INPUT_MAX_ABS, or not finite): 1 and
 *  the text that follows "PATH:LINE: column N " in text ("('TEXT') is
 *  beyond 1e+06 in SI units (no sensor reads that)"; read in another unit
 *  than SI, the unit and the value in SI units follow TEXT: "('-105307.65'
 *  g, -1.03e+06 m/s^2)"), else 0. field: the field's text (TEXT, its first
 *  20 characters); gyro: 1 for a rate (rad/s), 0 for an acceleration.
 *  ug_ask: the layout of an accelerometer's column whose remedy is --units,
 *  NULL else: a value that read in ug is within 400 g asks "in ug?" with
 *  the --units value. The text log readers' check and merge's. */
int hx_value_beyond(double v, double scale, int gyro, const char *field, const hx_csv_layout_t *ug_ask, char *text,
                    size_t size);

/** ": for standard input give /dev/stdin (a pipe is read)" when @p path
 *  is "-" and no file of that name could be opened (@p err, the errno of
 *  the failed open, is ENOENT), else "": the remedy after a "cannot open"
 *  of a log. */
const char *hx_stdin_hint(const char *path, int err);
/** The lowest rate of a foot-mounted IMU the time-unit remedies aim at,
 *  Hz (hx_time_unit_fix's band is 20 Hz to HX_TIME_RATE_MAX_HZ). */
#define HX_TIME_RATE_MIN_HZ 20.0
/** The rate the time-unit checks judge (hx_time_unit_hint,
 *  hx_time_unit_layout and replay's units check) for a log whose stamps'
 *  intervals give rate_hz (1 / their median interval, hx_stamp_rate_hz)
 *  and whose n samples run from the stamp t_first_ns to t_last_ns, its
 *  span rate (n - 1) / span: rate_hz when it lies in the band of
 *  HX_TIME_RATE_MIN_HZ to HX_TIME_RATE_MAX_HZ (a log with a pause keeps
 *  it), when there is no span (n < 2, or the last stamp not after the
 *  first), or when the span rate is out of the band on the same side (a
 *  wrong unit moves both alike); else 0, no unit to question. Stamps taken
 *  in bursts, a batch of samples stamped microseconds apart as a logger
 *  reads them (5 us apart every 16 ms: 200 kHz from the median interval,
 *  250 Hz over the log), or one stamp shared by a batch of samples (one
 *  stamp every 2 s for 100 samples: 0.5 Hz from the distinct stamps, 50 Hz
 *  over the log), are in the right unit: naming one would make the log
 *  1000 times too slow or too fast. */
double hx_time_unit_rate(double rate_hz, size_t n, int64_t t_first_ns, int64_t t_last_ns);
/** Stamps in bursts, the verdict of hx_stamp_bursts. */
typedef enum {
    HX_BURSTS_NONE = 0, /**< the median interval is the sampling period, give or take lost (a third of the
                             samples) and repeated (a quarter of the stamps) samples */
    HX_BURSTS_CLOSE,    /**< fewer than half the samples the median interval gives over the span: samples
                             stamped close together as a logger reads them (5 us apart every 10 ms) */
    HX_BURSTS_SHARED    /**< more than 1.5 times as many: samples that share one stamp (4 to a stamp every
                             10 ms), as stamps coarser than the sampling also give */
} hx_bursts_kind_t;
typedef struct {
    hx_bursts_kind_t kind;
    size_t n;         /**< the samples */
    size_t distinct;  /**< the distinct stamps among them (the cause of HX_BURSTS_SHARED: stamps that
                           repeat, or distinct stamps close together in pairs, 0.1 ms and 9.9 ms apart) */
    int first;        /**< 1: n are a log's first samples, not all of them (the message says so) */
    size_t segs;      /**< the segments between time jumps */
    double median_hz; /**< 1 / the median interval of the strictly increasing stamps (0: fewer than 2) */
    double span_s;    /**< the segments' spans, summed */
    double rate_hz;   /**< the rate to give: per segment, the samples from the start of its second burst to
                           the start of its last over the time between them (whole packets, whatever the
                           first and last hold); with no segment of 3 bursts the samples over the span,
                           (n - segs) / span_s (0: no span) */
    hx_format_t format; /**< the format read, which chooses the remedy (hx_bursts_text): the interchange CSV
                             (and HX_FMT_AUTO, hx_stamp_bursts's 0) leaves its time column out, any other
                             (a .bin, an importer's log) is converted to CSV first; the caller sets it */
} hx_bursts_t;
/** Whether n time stamps (ns) come in bursts: the samples between the time
 *  jumps (an interval above max_gap_s and 1.5 median intervals, the
 *  navigator's rule) against the count the median interval of the strictly
 *  increasing stamps predicts over their span (span x rate + one per
 *  segment): below half of it HX_BURSTS_CLOSE, above 1.5 times
 *  HX_BURSTS_SHARED. The one test of replay (before navigating), of
 *  --rate's resampler, and of the warning of info, psd and allan. Fewer
 *  than 4 distinct stamps: HX_BURSTS_NONE. Returns the kind, -1 out of
 *  memory. */
int hx_stamp_bursts(const int64_t *t_ns, size_t n, double max_gap_s, hx_bursts_t *b);
/** The cause and the remedy for stamps in bursts (b->kind not
 *  HX_BURSTS_NONE) in msg (returned): "the time stamps come in bursts
 *  (samples stamped close together as a logger reads them?): 1 / their
 *  median interval gives 200000 Hz, but the 16539 samples span 41.34 s,
 *  400 Hz; NEEDS: leave the time column out and give --input-rate 400
 *  (docs/harness.md, \"SECTION\")". needs: what the wrong rate breaks.
 *  The remedy is the interchange CSV's (b->format HX_FMT_CSV or
 *  HX_FMT_AUTO); for any other format, whose time cannot be left out and
 *  which ignores --input-rate or takes it for its counter's rate,
 *  hx_bursts_remedy's conversion to CSV without the time column. */
const char *hx_bursts_text(const hx_bursts_t *b, const char *needs, const char *section, char *msg, size_t size);
/** The remedy for stamps in bursts of a log in format fmt, with the rate
 *  to give, in msg (returned): for the interchange CSV (or HX_FMT_AUTO)
 *  "leave the time column out and give --input-rate 400", with "(drop
 *  t=NAME from --columns)" after "out" when --columns names the time
 *  column (hx_reader_set_layout's; a DOT CSV's t=SampleTimeFine); for any other
 *  format "convert it to CSV without the time column (bin/harness convert
 *  LOG out.csv; cut -d, -f2- out.csv > in.csv) and give in.csv
 *  --input-rate 400": a .bin has no column to leave out, and a time-stamped
 *  importer (ngimu, pyshoe, gx2, an MT Manager export by SampleTimeFine)
 *  ignores --input-rate as the .bin does, while a counter's (ipol,
 *  square2, an export by PacketCounter) only rescales its stamps
 *  (docs/harness.md, "Time stamps in bursts"). */
const char *hx_bursts_remedy(hx_format_t fmt, double rate_hz, char *msg, size_t size);
/** The remedy for a log of a format other than the interchange CSV whose
 *  time stamps navigation cannot use, "convert it to CSV without the time
 *  column (bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv)
 *  and give in.csv " followed by rate, a string literal naming the rate to
 *  give: hx_bursts_remedy's "--input-rate %.4g" (a format for the rate it
 *  found) and the coarse-stamps note's "the rate with --input-rate HZ"
 *  (hx_nav.c). One text, so that the two cannot drift apart. */
#define HX_CONVERT_REMEDY(rate)                                                                                      \
    "convert it to CSV without the time column (bin/harness convert LOG out.csv; cut -d, -f2- out.csv > in.csv) "  \
    "and give in.csv " rate
/** How far a rate the file states (nominal) may be from the rate of the
 *  samples' span (hx_bursts_t.rate_hz) and still be called kept, a
 *  fraction (the tolerance of an MT Manager export's '// Update Rate'). */
#define HX_BURSTS_RATE_TOL 0.05
/** The warning of info, psd, allan and simgap for stamps in bursts (b->kind
 *  not HX_BURSTS_NONE) in msg (returned), saying which rate the command
 *  uses and where it came from: hx_bursts_text's cause, then "READS R Hz,"
 *  and, for a rate from the stamps (nominal 0), "the stamps' rate, not the
 *  sampling rate: leave the time column out and give --input-rate N
 *  (docs/harness.md, "Time stamps in bursts")"; for the rate the file
 *  states (nominal 1) that the samples' span keeps (within
 *  HX_BURSTS_RATE_TOL), "the rate the file states, which the samples' span
 *  keeps, not the stamps' 200000 Hz (docs/harness.md, ...)"; for one it
 *  does not keep, "the rate the file states, which the samples' span does
 *  not keep: leave the time column out ...". reads: what of the output
 *  the rate makes, e.g. "the frequencies are read at". */
const char *hx_bursts_rate_text(const hx_bursts_t *b, const char *reads, double rate_hz, int nominal, char *msg,
                                size_t size);
/** csv with the time unit hx_time_unit_hint finds for rate_hz (in *buf),
 *  else csv itself (NULL stays NULL): the layout whose other remedies
 *  (hx_units_problem's, given with no rate) name the time item too, for a
 *  command that says both in two messages. */
const hx_csv_layout_t *hx_time_unit_layout(double rate_hz, const hx_csv_layout_t *csv, hx_csv_layout_t *buf);
/** The time unit a slow log's stamps look like: 1 when rate_hz is below
 *  1 Hz and milliseconds, microseconds or nanoseconds make it 20 Hz to
 *  100 kHz (or above 100 kHz and a coarser unit than the one read, at most
 *  seconds, does: ms read as ns), with the question and the remedy in msg ("the samples are 10 s
 *  apart (0.1 Hz): are the time stamps in seconds? (they look like
 *  milliseconds, a 100 Hz log: divide by 1000)"), else 0. csv: as
 *  hx_units_layout gives it; the remedy is then the --units item counted
 *  from the time unit given, with the unit items given ("give --units
 *  time=ms,accel=g"; hx_units_give). A static log may be
 *  slow, so this is a warning of info, allan, psd and simgap, not a unit
 *  error. */
int hx_time_unit_hint(double rate_hz, const hx_csv_layout_t *csv, char *msg, size_t msg_size);

/** The rate along a log is judged in blocks of this many positive
 *  intervals; a block whose rate is off the expected one by more than
 *  HX_RATE_TOL is a rate change (docs/navigation.md, "Timing"). */
#define HX_RATE_BLOCK 200
#define HX_RATE_TOL 0.2

/**
 * Where the sample rate of a log leaves rate_hz: each block of
 * HX_RATE_BLOCK positive intervals (a shorter last block when it holds at
 * least half as many) gives a rate from its median interval (jitter, time
 * jumps and lost samples up to half of the block leave it alone; more is
 * a lower rate in effect); a block is off when its rate is off by more than
 * HX_RATE_TOL and its median interval by a resolution of the stamps or
 * more (the gcd of the log's intervals: a 398 Hz log stamped to the
 * millisecond reads 2 and 3 ms). The stamps are read at t_ns, t_ns + stride bytes, ...
 * (n of them).
 * @param at_s      the first block off by more than HX_RATE_TOL: its start,
 *                  s after the first stamp (NaN: none)
 * @param rate_off  that block's rate, Hz (NaN: none)
 * @return the share of the duration in such blocks (0: the rate holds)
 */
double hx_rate_changes(const int64_t *t_ns, size_t n, size_t stride, double rate_hz, double *at_s, double *rate_off);

/** Read a whole log. Returns 0 when every sample was read, 1 when an
 *  error stopped reading after some samples (log->n of them are valid and
 *  log->error says why), -1 when nothing could be read (err filled). */
int hx_log_load(hx_log_t *log, const char *path, hx_format_t fmt, double rate_hz,
                char *err, size_t err_size);
/** hx_log_load that reports progress(ctx, fraction of the input read, 0..1;
 *  hx_reader_progress) every 65,536 samples and 1 at the end of a
 *  complete read (a log that stops at an error ends where it stopped;
 *  progress NULL: none), for a progress indicator on long logs. */
int hx_log_load_progress(hx_log_t *log, const char *path, hx_format_t fmt, double rate_hz,
                         void (*progress)(void *ctx, double frac), void *ctx, char *err, size_t err_size);
void hx_log_free(hx_log_t *log);

/** hx_time_unit_rate for a loaded log: its stamps' rate_hz judged by the
 *  span of its samples (rate_hz itself for an empty log). */
double hx_log_time_unit_rate(const hx_log_t *log, double rate_hz);

/** Sample i of a loaded log as the core takes it (time, sequence, specific
 *  force and rate; no temperature). */
void hx_log_sample(const hx_log_t *log, size_t i, fnav_sample_t *s);

#endif /* HX_LOG_H */
