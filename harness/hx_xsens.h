/**
 * @file hx_xsens.h
 * @brief Xsens MT Manager's ASCII export (format `mtmanager`,
 *        docs/log-format.md, "MT Manager export"): what the reader knows of
 *        the format, apart from reading lines.
 *
 * The export of an MTi, MTw or MTw2 recording: `//` comment lines (MT
 * Manager's and XDA's versions, the device, its settings, sometimes
 * `// Update Rate: 100.0Hz`), then a header naming the columns the user
 * chose to export (tab-separated, or ',' or ';'), then one row per packet,
 * `NaN` where a packet lacks a value. hx_log.c reads the lines and splits
 * them; these functions detect the format, take the rate from the comments,
 * find the columns, choose the time source and turn each row's counters
 * into a time and a sequence number. Linux harness only; no I/O here.
 */
#ifndef HX_XSENS_H
#define HX_XSENS_H

#include <stddef.h>
#include <stdint.h>

/** SampleTimeFine ticks per second: 0.1 ms resolution (MTi User Manual,
 *  MT0605P.E, 4.12.3). */
#define HX_MTMGR_STF_HZ 10000
/** SampleTimeFine is a uint32 and wraps at 2^32 ticks (119.3 h). */
#define HX_MTMGR_STF_WRAP 4294967296.0
/** ... or, as time of day (an MTi-G with a GNSS fix), at 864,000,000 ticks:
 *  XDA's packet stamper unwraps the sample time at "1 day @ 10kHz". */
#define HX_MTMGR_STF_DAY 864000000.0
/** PacketCounter is a uint16 and wraps at 65536 (XDA's packet stamper:
 *  a drop by more than half the range is a wrap). */
#define HX_MTMGR_CTR_WRAP 65536.0
/** The rows after the header whose SampleTimeFine steps hx_mtmgr_stamps
 *  compares with the stated rate and the unit. */
#define HX_MTMGR_PEEK_ROWS 256
/** How far the stated '// Update Rate' may be from the stamps' rate before
 *  it is warned and left out (a fraction of the stated rate). */
#define HX_MTMGR_RATE_TOL 0.05
/** The rates an IMU can have, Hz: SampleTimeFine steps slower than the
 *  lowest in 100 us ticks that are in this range in us are a Movella DOT
 *  CSV's (hx_mtmgr_stamps). */
#define HX_MTMGR_IMU_MIN_HZ 20.0
#define HX_MTMGR_IMU_MAX_HZ 5000.0
/** Half the slowest rate of a Movella DOT (1 Hz; it logs at 1, 4, 10, 12,
 *  15, 20, 30, 60 or 120 Hz), Hz in us: steps this fast or faster in us
 *  that make no MTi's rate in ticks (HX_MTMGR_MTI_MIN_HZ), under a header
 *  with no name only MT Manager writes, are a DOT CSV's at any of its rates
 *  (hx_mtmgr_stamps). */
#define HX_MTMGR_DOT_MIN_HZ 0.5
/** The slowest rate an MTi outputs, Hz: its output configuration sets
 *  each data's rate in whole Hz (XDA's XsOutputConfiguration::m_frequency,
 *  a uint16; 0xFFFF the maximum), so SampleTimeFine steps slower than this
 *  in 100 us ticks are no MTi export's (hx_mtmgr_stamps). Any bound from
 *  0.2 Hz (20 Hz in us, where the IMU band takes over) to 20 Hz decides
 *  the same. */
#define HX_MTMGR_MTI_MIN_HZ 1.0

/** Where a row's time comes from. */
typedef enum {
    HX_MTMGR_TIME_STF = 1,   /**< SampleTimeFine, unwrapped, x 100 us */
    HX_MTMGR_TIME_COUNTER,   /**< PacketCounter, unwrapped, / rate */
    HX_MTMGR_TIME_INDEX      /**< neither: the row's index / rate */
} hx_mtmgr_time_t;

/** The reader's state for one export. */
typedef struct {
    int col_ctr, col_stf;    /**< PacketCounter, SampleTimeFine columns; -1: none */
    int col_acc[3], col_gyr[3];
    int ncols_needed;        /**< columns a row must have (the last used one + 1) */
    double stated_hz;        /**< "// Update Rate: 100.0Hz"; 0: not stated */
    long stated_line;        /**< its line */
    char product[24];        /**< "// ProductCode: MTW2-3A7G6"; "" when not given */
    long comments;           /**< '//' lines before the header */
    hx_mtmgr_time_t time_src;
    int use_ctr;             /**< PacketCounter gives each sample's seq */
    double rate_hz;          /**< rate of the counter or index time */
    long rows;               /**< data rows seen, skipped ones included */
    long skipped;            /**< rows skipped for a missing value */
    long skipped_first;      /**< the line of the first of them */
    int have_ctr, have_stf;
    double ctr_prev, stf_prev;     /**< the last raw values */
    double ctr_wrap, stf_wrap;     /**< counts added by the wraps so far */
    double peek[HX_MTMGR_PEEK_ROWS]; /**< SampleTimeFine of the first rows (hx_mtmgr_peek); -1: none */
    int npeek;               /**< rows in peek */
    double stamp_step;       /**< their median step that advances, ticks; 0: none (hx_mtmgr_stamps) */
    int us_like;             /**< the steps read as a Movella DOT CSV's us (hx_mtmgr_stamps) */
    int mtmgr_names;         /**< the header holds a name only MT Manager writes, for what a
                                  Movella DOT CSV names otherwise (Roll, Quat_q0, StatusWord, ...;
                                  hx_mtmgr_header): no DOT CSV */
} hx_mtmgr_t;

/** Whether the start of a file (text, NUL-terminated, a UTF-8 byte-order
 *  mark removed) is an MT Manager export: `//` comment lines that name MT
 *  Manager's keys (`MT Manager`, `XDA`, `Update Rate`, `Filter Profile`,
 *  `DeviceId`, `ProductCode`), or a header (after such lines, or first)
 *  with PacketCounter or SampleTimeFine and Acc_X and Gyr_X (or dq_/dv
 *  increments). */
int hx_mtmgr_detect(const char *text);

/** Reset x before the first line. */
void hx_mtmgr_init(hx_mtmgr_t *x);

/** Whether line (leading blanks allowed) is a `//` comment line; the rate
 *  of `Update Rate: N Hz` and the ProductCode are kept from it. */
int hx_mtmgr_comment(hx_mtmgr_t *x, const char *line, long lineno);

/** Find the columns among the n header fields f, and whether one is a name
 *  only MT Manager writes, for what a Movella DOT CSV names otherwise
 *  (mtmgr_names: Roll, Pitch, Yaw, Quat_q0..q3, StatusWord,
 *  SampleTimeCoarse, Mat[..]). 0, or -1 with
 *  the reason in msg: an Acc_ or Gyr_ column missing (an export of
 *  increments dq_, dv_ or of FreeAcc_ alone is named as such, with the
 *  export setting that gives Acc_ and Gyr_). */
int hx_mtmgr_header(hx_mtmgr_t *x, char **f, int n, char *msg, size_t msg_size);

/** Whether a field is a missing value: empty, or NaN in any case or sign. */
int hx_mtmgr_missing(const char *field);

/** Choose the time source from the first data row (f, n; f NULL: none):
 *  SampleTimeFine when it holds a number there, else PacketCounter, else
 *  the row index, the last two at input_hz (--input-rate; 0: none) or else
 *  the stated rate. 0, or -1 with the reason in msg (a counter or index
 *  time without a rate). */
int hx_mtmgr_choose_time(hx_mtmgr_t *x, char **f, int n, double input_hz, char *msg, size_t msg_size);

/** One of the first data rows (n fields f; the first one included), read
 *  ahead before the samples: its SampleTimeFine is kept (-1 when it has
 *  none) for hx_mtmgr_stamps. 1 while more rows are wanted. */
int hx_mtmgr_peek(hx_mtmgr_t *x, char **f, int n);

/** After hx_mtmgr_peek, with SampleTimeFine the time source: the median of
 *  the steps between the rows' stamps that advance (stamp_step), and
 *  - when the '// Update Rate' differs from the stamps' rate by more than
 *    HX_MTMGR_RATE_TOL of it: the stamps rule, the stated rate is dropped
 *    (rate_hz 0, the rate is then estimated from the stamps), and 1 with
 *    the warning in msg;
 *  - when there is no '//' line and the steps are slower than
 *    HX_MTMGR_IMU_MIN_HZ in 100 us ticks but in HX_MTMGR_IMU_MIN_HZ ..
 *    HX_MTMGR_IMU_MAX_HZ in us, or, under a header with no name only MT
 *    Manager writes (mtmgr_names), slower than HX_MTMGR_MTI_MIN_HZ in ticks
 *    (no MTi's rate) and HX_MTMGR_DOT_MIN_HZ or faster in us (a DOT at 1 to
 *    15 Hz, which make no IMU's rate in us): us_like (a Movella DOT CSV, whose
 *    SampleTimeFine counts us; hx_mtmgr_us_refusal).
 *  Else 0. */
int hx_mtmgr_stamps(hx_mtmgr_t *x, char *msg, size_t msg_size);

/** The refusal of a file read as an export (detected, or --from mtmanager)
 *  whose stamps are us_like: "PATH: SampleTimeFine steps by N: R Hz in 100
 *  us ticks, R' Hz in us, no '//' line: likely a Movella DOT CSV; read it
 *  with --from csv --columns ... --units time=us,gyro=deg/s (if MT
 *  Manager's, its '//' lines cut: put one back before the header)". */
void hx_mtmgr_us_refusal(const hx_mtmgr_t *x, const char *path, char *msg, size_t msg_size);

/** A data row (n fields f): 1 when a value the reader uses (Acc_, Gyr_,
 *  the time source, the counter when it gives seq) is missing, and the row
 *  is skipped and counted (line: its line); 0 to read it. Either way the
 *  row takes its place in the index. */
int hx_mtmgr_row(hx_mtmgr_t *x, char **f, int n, long line);

/** The time and sequence number of a row hx_mtmgr_row let through.
 *  *has_seq: 1 when seq is the sensor's counter. 0, or -1 with the reason in
 *  msg (a counter that is not a whole number in its range). */
int hx_mtmgr_time(hx_mtmgr_t *x, char **f, int64_t *t_ns, uint32_t *seq, int *has_seq, char *msg, size_t msg_size);

#endif /* HX_XSENS_H */
