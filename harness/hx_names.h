/* Column names of an IMU CSV read without --columns (docs/log-format.md,
 * "Names read without --columns"): a header such as
 * "timestamp,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z" or
 * "Time,AccX [g],...,GyrZ [deg/s]" matched to the interchange keys. */
#ifndef HX_NAMES_H
#define HX_NAMES_H

#include <stddef.h>

/** What one header name is (hx_name_classify). */
typedef enum {
    HX_NAME_OTHER = 0, /**< no time, acceleration or rate name */
    HX_NAME_MATCH,     /**< a name of key (0 t, 1..3 ax..az, 4..6 gx..gy) */
    HX_NAME_NEAR       /**< a stem and an axis (or a time word) with another word: FreeAcc_X, acc_x_lin */
} hx_name_kind_t;

/** The unit a name gives (in brackets, parentheses or as its last word). */
typedef enum {
    HX_UNIT_NONE = 0,
    HX_UNIT_S, HX_UNIT_MS, HX_UNIT_US, HX_UNIT_NS, /* time */
    HX_UNIT_MPS2, HX_UNIT_G, HX_UNIT_MG, HX_UNIT_UG, /* acceleration (ug: micro-g) */
    HX_UNIT_RPS, HX_UNIT_DPS, HX_UNIT_MDPS         /* rate */
} hx_name_unit_t;

typedef struct {
    hx_name_kind_t kind;
    int key;              /**< 0 t, 1..6 ax..gz (MATCH and NEAR), -1 none */
    hx_name_unit_t unit;  /**< the unit named, HX_UNIT_NONE when none (or not read) */
    int unit_unread;      /**< 1: a key's name (NEAR) whose unit is none read: "gx [deg/h]", "ax_ug" */
    int clock;            /**< a time name: 1 a clock's (epoch, epoc, unix, unix_time: since 1970), -1 a time
                               from a start (elapsed, elapsed time), 0 neither or not said */
    int gforce;           /**< 1: Physics Toolbox's g-force name (gFx): the specific force in g, read in g
                               unless a unit is given; beside it the app's ax..az are its linear acceleration */
    char unit_text[32];   /**< a key's name's unit as the header spells it ("°/s"), "" when none */
} hx_name_class_t;

/** Classify one header name. The UTF-8 degree sign (U+00B0, and U+00BA,
 *  its common stand-in), micro signs (U+00B5, U+03BC) and superscript two
 *  (U+00B2), or those bytes alone as Latin-1 writes them, are read as
 *  "deg", "u" and "2": "gx [°/s]" is "gx [deg/s]", "acc_x [m/s²]"
 *  "acc_x [m/s2]". Split into lower-case words at blanks, '_',
 *  '-', '.', ':' and at a lower-to-upper case change (AccX: acc, x;
 *  accX_mps2: acc, x, mps2); a unit in brackets or parentheses, or as the
 *  last word, is taken out (a zone in brackets after a time name too). The
 *  words left must be exactly a time name (t, time, timestamp, ts, time
 *  stamp, elapsed, elapsed time, datetime, date time; epoch, epoc, unix
 *  alone or with time, timestamp or ts: a clock's, c->clock 1, which
 *  hx_names_match reads only where no other time name is; time since
 *  start, AndroSensor's, "in" before a last word's unit dropped with it;
 *  sensor timestamp, sensor time, sensor ts: a sensor's own clock, Polar
 *  Sensor Logger's;
 *  millis in ms and
 *  micros in us unless a unit is given), or a stem and an axis x, y, z, the
 *  axis apart or glued (acc_x, accx, ax): acceleration acc, accel,
 *  accelerometer, acceleration, a (glued only: ax); rate gyr, gyro,
 *  gyroscope, w, omega, angvel, angular velocity, angular rate, rotation
 *  rate, g (glued only: gx); or the ASL format's w_RS_S_x (rate) and
 *  a_RS_S_x (acceleration) of EuRoC and TUM-VI; or Physics Toolbox's
 *  g-force gFx (acceleration, in g unless a unit is given: c->gforce,
 *  which hx_names_match reads before the app's ax, its linear
 *  acceleration). Units are also read as a
 *  negative power of the second, "m s^-2", "rad s^-1", "m.s-2". A unit of
 *  another quantity, or any other word (FreeAcc_X's free, acc_x_lin's
 *  lin), makes it no match: a near miss when a stem and an axis (or a time
 *  word) are among the words. A unit in brackets that is none of these, or
 *  a last word that is a unit but none read (ng, lsb, counts, rpm, dph,
 *  or with a '/' or '^': deg/h), makes a key's name a near miss with
 *  unit_unread. Returns kind. */
hx_name_kind_t hx_name_classify(const char *name, hx_name_class_t *c);

/** Whether a header is Shimmer's Consensys export (its columns named
 *  <device>_<signal>_CAL or _RAW, a row of units under it): one of its n
 *  names ends in _Timestamp_Unix_CAL or _TimestampSync_Unix_CAL (case
 *  ignored). */
int hx_names_consensys(char *const *f, int n);

/** Whether a header is a ROS sensor_msgs/Imu message written as CSV
 *  (rostopic echo -p's field.linear_acceleration.x, bagpy's
 *  linear_acceleration.x): it names one of linear_acceleration.x/y/z and
 *  one of angular_velocity.x/y/z, after an optional "field." (case
 *  ignored). Matched from those names (SI units) and the message's stamp:
 *  field.header.stamp in ns, else split in header.stamp.secs and .nsecs
 *  (ROS 2: .sec and .nanosec; col_tns), else the receive time, %time in ns
 *  or bagpy's Time in s. */
int hx_names_ros(char *const *f, int n);

/** Whether a header is Kalibr's IMU CSV (its bag format's imu0.csv,
 *  "timestamp,omega_x,omega_y,omega_z,alpha_x,alpha_y,alpha_z"): it names
 *  all six of omega_x..z and alpha_x..z (case ignored). Matched from those
 *  names: omega the rate in rad/s, alpha the specific force in m/s^2 (not
 *  the angular acceleration the word names elsewhere, so read only beside
 *  omega), and timestamp (or timestamp_ns) in ns, as Kalibr writes them. */
int hx_names_kalibr(char *const *f, int n);

/** Whether a header is SensorLog's (the iOS app's CSV): it names
 *  accelerometerAccelerationX..Z and gyroRotationX..Z or
 *  motionRotationRateX..Z (case ignored, a unit in parentheses after
 *  each). Matched from those names: the accelerometer in g with iOS's
 *  sign, read negated (the specific force), the raw gyroRotation before
 *  motionRotationRate in rad/s, accelerometerTimestamp_sinceReboot in s
 *  the time; CoreMotion's user acceleration, gravity, the logging time
 *  and the other stamps named as not read. */
int hx_names_sensorlog(char *const *f, int n);

/** The column of a ROS topic's receive time among the n header fields f
 *  (%time, in ns, before bagpy's Time, in s), its unit in *unit; -1 when
 *  there is none. */
int hx_names_ros_receive(char *const *f, int n, hx_name_unit_t *unit);

/** The unit of a units row's field (Consensys: "ms", "m/(s^2)", "deg/s"),
 *  spelled as a bracketed unit of a name is (brackets inside, blanks and
 *  case ignored; "mSecs" is ms); HX_UNIT_NONE when none read. */
hx_name_unit_t hx_name_unit_of_text(const char *text);

/** text with the units' signs spelled in ASCII, as hx_name_classify reads
 *  them (° "deg", µ and μ "u", ² "2"; UTF-8 or the Latin-1 byte), into out:
 *  "m/s²" is "m/s2", "°/s" "deg/s" (--units reads its values so). 0, or -1
 *  when out is too small. */
int hx_name_fold_units(const char *text, char *out, size_t size);

/** A name as the header spells it, without the blanks, tabs, quotes and
 *  CR around it, into out (cut to size). */
void hx_name_bare(const char *name, char *out, size_t size);

/** The result of matching a header (hx_names_match). */
typedef struct {
    int ok;             /**< 1: each of ax..gz one column, t at most one, one unit per quantity */
    int col[7];         /**< the column of t, ax..gz; -1 none (or ambiguous: ncand > 1) */
    int col_tns;        /**< the nanoseconds added to t, a stamp split in two columns (ROS); -1 none */
    int ncand[7];       /**< the columns that match each key */
    int cand[7][3];     /**< the first three of them */
    int nnear[7];       /**< near misses of each key (and Physics Toolbox's ax..az beside its g-force) */
    int near[7][3];     /**< the first three of them */
    int times;          /**< the time names, when more than one and one names its unit: the first that
                             does is read, the others counted with t's near misses; else 0 */
    int times_clock;    /**< 1: a clock's name (epoch, unix) among those times, not read beside the others */
    int units_differ;   /**< 1 accel, 2 gyro: the three axes name different units */
    int excluded;       /**< 1: an Xsens export's name (SampleTimeFine, PacketCounter): not matched */
    int consensys;      /**< 1: Shimmer's Consensys names (hx_names_consensys): their units are the row's */
    int ros;            /**< 1: a ROS sensor_msgs/Imu header (hx_names_ros): SI units, the stamp in ns or s */
    int kalibr;         /**< 1: Kalibr's IMU CSV header (hx_names_kalibr): SI units, the stamp in ns */
    int sensorlog;      /**< 1: SensorLog's header (hx_names_sensorlog): g and rad/s, the stamp in s */
    int negate;         /**< bit k: key k (1..6, ax..gz) read with the other sign (SensorLog's ax..az) */
    int gforce;         /**< 1: the accelerations are Physics Toolbox's g-force names (gFx..gFz); the app's
                             other acceleration names (ax..az, its linear acceleration, gravity removed)
                             are then not read, and listed with the near misses */
    hx_name_unit_t unit[3]; /**< the unit of time, accel, gyro the names give (NONE: not named) */
    int unit_col;       /**< the first column named for a key with no candidate whose unit is not read or is
                             another quantity's ("gx [deg/h]", "acc_x [s]"); -1 none (hx_names_unit_problem) */
} hx_names_match_t;

/** Match the n header fields f to the interchange keys. A header with
 *  SampleTimeFine or PacketCounter (Xsens exports, whose Gyr_X is deg/s in
 *  one product and rad/s in another) is not matched (excluded set).
 *  Returns m->ok. */
int hx_names_match(char *const *f, int n, hx_names_match_t *m);

/** The --units item of a unit ("time=ms", "accel=g", "gyro=deg/s"), NULL
 *  for HX_UNIT_NONE. */
const char *hx_name_unit_item(hx_name_unit_t u);

/** The text "--columns t=NAME,ax=NAME,..." of the keys matched uniquely
 *  (the names as the header spells them), then " --units ITEMS" of the units
 *  named; "" when nothing matched. Returns buf. */
const char *hx_names_give(const hx_names_match_t *m, char *const *f, char *buf, size_t size);
/** 1 when s is one shell word only quoted (a name with a blank, a bracket
 *  or another character outside [A-Za-z0-9_.,=/+-], or a '~' or '=' first). */
int hx_names_need_quotes(const char *s);
/** s as one shell word into buf: as it is when nothing in it needs quoting,
 *  else in single quotes, a ' in s dropped when names (a --columns map: a
 *  column's name is matched without its quotes, hx_name_eq), else written
 *  '\''. Returns buf; "" when it does not fit. */
const char *hx_shell_word(const char *s, int names, char *buf, size_t size);

/** What did not match, for a refusal: "gx: 2 candidates (gyro_x,
 *  gyro_x_filt); gy: none (near misses: gyr_y_lin)", "" when every key
 *  matched. time_required: say of a missing t too. Returns buf. */
const char *hx_names_unmatched(const hx_names_match_t *m, char *const *f, int time_required, char *buf,
                               size_t size);

/** What is wrong with the unit of m->unit_col, for a refusal: "column 5
 *  ('gx [deg/h]') names a unit not read, 'deg/h' (a rate's: rad/s, ...)"
 *  or "column 2 ('acc_x [s]') names a time unit, 's', not an
 *  acceleration's (...)"; "" when unit_col < 0. Returns buf. */
const char *hx_names_unit_problem(const hx_names_match_t *m, char *const *f, char *buf, size_t size);

/** The near misses of every key, comma-separated (the first four, then
 *  "..."): the names a warning says were not read. "" when none. */
const char *hx_names_near(const hx_names_match_t *m, char *const *f, char *buf, size_t size);

#endif
