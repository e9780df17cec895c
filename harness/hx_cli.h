/**
 * @file hx_cli.h
 * @brief Shared command-line plumbing of ./harness: option parsing, exit
 *        codes, messages, progress indicator, input opening, plotting.
 */
#ifndef HX_CLI_H
#define HX_CLI_H

#include <signal.h>
#include <stdio.h>
#include "hx_log.h"

/** Exit codes of every harness command (docs/harness.md). */
enum {
    HX_EXIT_OK = 0,      /**< success */
    HX_EXIT_DATA = 1,    /**< bad or incomplete input data; outputs valid up to the error */
    HX_EXIT_USAGE = 2,   /**< bad command line */
    HX_EXIT_IO = 3,      /**< cannot write an output, or a tool is missing */
    HX_EXIT_UNAVAIL = 4  /**< command not available in this build */
};

#define HX_MAX_REPEAT 32
#define HX_MAX_POS 8

/** One option of a command. */
typedef struct {
    const char *name;     /**< "--out" */
    const char *metavar;  /**< "FILE"; NULL for a flag */
    const char *help;     /**< one line; NULL: accepted but left out of the
                           *   usage (a command that refuses it with a reason) */
    int repeat;           /**< may be given several times */
} hx_opt_t;

/** A command's command-line specification. */
typedef struct {
    const char *name;        /**< "replay" */
    const char *usage;       /**< "LOG [options]" */
    const char *summary;     /**< one paragraph */
    int min_pos, max_pos;    /**< positional arguments */
    const hx_opt_t *opts;    /**< options, terminated by {NULL} */
} hx_spec_t;

/** Parsed arguments. */
typedef struct {
    const hx_spec_t *spec;
    const char *pos[HX_MAX_POS];
    int npos;
    int count[64];                         /**< per option: times given */
    const char *val[64][HX_MAX_REPEAT];    /**< per option: values */
} hx_args_t;

/** Parse; returns 0 ok, 1 when --help was printed (exit 0), -1 on a usage
 *  error (message and usage printed on stderr; exit HX_EXIT_USAGE). */
int hx_args_parse(const hx_spec_t *spec, int argc, char **argv, hx_args_t *a);

/** Value of an option (last given) or NULL. */
const char *hx_arg(const hx_args_t *a, const char *name);
/** Number of times an option was given. */
int hx_arg_count(const hx_args_t *a, const char *name);
/** The i-th value of a repeatable option. */
const char *hx_arg_at(const hx_args_t *a, const char *name, int i);
/** Flag given? */
int hx_flag(const hx_args_t *a, const char *name);
/** Read a number as the command line takes it at the start of `s`: decimal
 *  (optional sign, digits with an optional point, optional exponent), finite;
 *  no leading blank, no hexadecimal, no nan or inf, as the log readers.
 *  0 with *v and *end (just after it) set, -1 when no such number starts
 *  there. Every option and option list that holds numbers reads them so. */
int hx_scan_number(const char *s, const char **end, double *v);
/** The whole of `s` is such a number: 0 with *v set, else -1. */
int hx_parse_number(const char *s, double *v);
/** Numeric option: 0 ok (default kept when absent), -1 on a bad number
 *  (message printed). Range checked against [lo, hi]. */
int hx_arg_double(const hx_args_t *a, const char *name, double lo, double hi, double *out);
int hx_arg_long(const hx_args_t *a, const char *name, long lo, long hi, long *out);
/** A count or seed beyond long's range: a whole number (1e3 is one) in
 *  [lo, hi], as a double; 0 ok (default kept when absent), -1 with the
 *  error printed. */
int hx_arg_whole(const hx_args_t *a, const char *name, double lo, double hi, double *out);

/** Print the usage of a command to a stream. */
void hx_usage(const hx_spec_t *spec, FILE *f);

/** "harness CMD: error: ..." on stderr. */
void hx_error(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/** "harness CMD: warning: ..." on stderr. */
/** The running command's name, for messages of shared code that is not
 *  given one (set by main.c; "harness" before). */
extern const char *hx_cmd_name;
void hx_warn(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/** Once-per-process mode for hx_warn and hx_print_warnings' notes (on:
 *  1): a message identical to one printed already (the same command and
 *  text) is counted, not printed again. For a command that runs the same
 *  logs several times (eval: a walk's table run and its experiments'
 *  repeats would print each reader warning up to 11 times);
 *  off by default, so a command that warns of repeated events (live's
 *  hangups) says each. */
void hx_warn_once(int on);
/** Messages not printed again in once mode so far. */
long hx_warn_repeats(void);

/** FNV-1a of s continuing the hash h (start with HX_FNV1A_INIT), then a
 *  separator, so that ("ab", "c") and ("a", "bc") hash apart: the key of
 *  the harness's remembered-once tables. */
#define HX_FNV1A_INIT 14695981039346656037ULL
unsigned long long hx_fnv1a(unsigned long long h, const char *s);

/** A warning when an output log's name ends in .gz (any case): footnav
 *  writes no gzip, so the file is plain (and CSV unless fmt, the format
 *  asked for, is HX_FMT_BIN or the name ends in .bin before the .gz). */
void hx_warn_gz_output(const char *cmd, const char *path, hx_format_t fmt);

/** Options every command that reads a log understands. */
#define HX_INPUT_OPTS                                                                         \
    { "--from", "NAME", "input format (default: detected): " HX_FORMAT_LIST, 0 },            \
    { "--input-rate", "HZ", "sample rate of an input without time stamps", 0 },                \
    { "--columns", "MAP", "the CSV's names of the columns, e.g. t=timestamp_ns,ax=acc_x,...", 0 }, \
    { "--units", "SPEC", "the CSV's units: time=s|ms|us|ns,accel=m/s2|g|mg|ug,gyro=rad/s|deg/s|mdps; raw counts: a count's size first (accel=0.061mg)", 0 }

/** The format of an output log from --to (bin or csv; another is a usage
 *  error, printed: -1) or, without it, HX_FMT_CSV for out "-" (standard
 *  output) and HX_FMT_AUTO otherwise (the writer goes by the extension).
 *  0 ok. */
int hx_arg_to(const char *cmd, const hx_args_t *a, const char *out, hx_format_t *to);

/** Check --from, --input-rate, --columns and --units (a log of another
 *  format than csv with either of the last two, given or detected, is a
 *  usage error) and set the readers' CSV layout (hx_reader_set_layout);
 *  call right after parsing so that a bad
 *  value is a usage error (exit HX_EXIT_USAGE). 0 ok, -1 error printed. */
int hx_check_input_opts(const char *cmd, const hx_args_t *a);

/** Open the input of a command using --from and --input-rate (and the CSV
 *  layout of --columns and --units, hx_check_input_opts). Prints the
 *  error and returns NULL on failure; prints reader warnings. */
hx_reader_t *hx_open_input(const char *cmd, const hx_args_t *a, const char *path);
/** Print newline-separated warnings, one "warning:" line each; a line
 *  that starts with "note: " is printed as a "note:" line. */
void hx_print_warnings(const char *cmd, const char *w);
/** Load a whole input using --from and --input-rate. Returns 0 complete,
 *  1 partial (error printed as a warning now; caller exits HX_EXIT_DATA
 *  after writing its outputs), -1 nothing read (error printed). */
int hx_load_input(const char *cmd, const hx_args_t *a, const char *path, hx_log_t *log);

/* ------------------------------------------------------------ progress */

/** Progress on stderr for long work: redrawn in place on a terminal (at most
 *  5 times a second), a line every 10 % otherwise; silent for work that
 *  ends within 1 s. */
typedef struct {
    const char *label;
    double total;
    double t_start;
    double t_last;
    int last_decile;
    int shown;
    int tty;
    double t_origin; /**< "done in" counts from here: t_start (hx_progress_start), or earlier work's start */
} hx_progress_t;

void hx_progress_start(hx_progress_t *p, const char *label, double total);
/** The progress line for a fraction done after elapsed_s: "LABEL:  42 % (3.1 s, about 4 s left)", the
 *  percentage floored, the time left (at the rate so far) from 5 % and 2 s on; snprintf's return. */
int hx_progress_text(char *buf, size_t size, const char *label, double frac, double elapsed_s);
void hx_progress_update(hx_progress_t *p, double done);
void hx_progress_end(hx_progress_t *p);
/** A line drawn in place on standard error (a progress or status line on a
 *  terminal, no newline yet): hx_line_break() ends it. */
void hx_line_open(void);
/** End with a newline a line hx_line_open() left open (nothing when none
 *  is): before other output, or when work stops without "done in".
 *  hx_error and hx_warn call it first. */
void hx_line_break(void);
/** Seconds since an arbitrary origin (monotonic). */
double hx_now_s(void);

/** qsort comparator of doubles, ascending. */
int hx_cmp_double(const void *a, const void *b);

/** Median of v[0..n-1] (sorts v in place); NaN when n <= 0. */
double hx_median(double *v, int n);
/** The q quantile (0 <= q <= 1) of n values sorted ascending, numpy's
 *  default definition (numpy.percentile's "linear", Hyndman and Fan's
 *  type 7): h = (n - 1) q, x[floor h] + (h - floor h)(x[floor h + 1] -
 *  x[floor h]). NaN when n < 1. Shared by simgap's and allan's refits. */
double hx_quantile_sorted(const double *x, int n, double q);

/* ------------------------------------------------------------ plots */

/** Room for a plot's path: any path the system can open (PATH_MAX 4096)
 *  and a file name added to a directory of that length. */
#define HX_PLOT_PATH_SIZE 4400

/** A gnuplot session writing one PNG. */
typedef struct {
    FILE *gp;
    char path[HX_PLOT_PATH_SIZE];
    int existed;            /**< the file was there before gnuplot started */
    long long before[7];    /**< and its device, inode, size, mtime and ctime then */
} hx_plot_t;

/** Start gnuplot for a PNG of w x h pixels. Returns 0, or -1 with a
 *  message printed when gnuplot is not installed or the PNG cannot be
 *  written (a path of HX_PLOT_PATH_SIZE bytes or more included). */
int hx_plot_open(hx_plot_t *p, const char *cmd, const char *png_path, int w, int h);
/** 0 when gnuplot is installed and `png_path` can be written (a file, or
 *  none yet: a device or a directory is refused); -1 with the error
 *  printed. For plots drawn only after long work. */
int hx_plot_check(const char *cmd, const char *png_path);
/** The file a picture drawn beside it and renamed onto it replaces, in
 *  `buf` (`size` bytes): `path`, or the regular file a symlink `path`
 *  names (realpath: the link stays, its target is updated). 0, or -1 with
 *  the error printed when `path` is there and is not a regular file (a
 *  device, a directory, a symlink to none): a rename would replace it. */
int hx_plot_rename_target(const char *cmd, const char *path, char *buf, size_t size);
/** 0 when gnuplot is installed; -1 with the error printed (naming
 *  png_path). For a command that makes the picture's directory: asked
 *  first, so that a refused run leaves none behind. */
int hx_plot_have_gnuplot(const char *cmd, const char *png_path);
/** Finish; returns 0 when the PNG was written: gnuplot's exit status 0
 *  and a whole PNG, its IEND chunk last (pngcairo exits 0 on a full disk).
 *  When gnuplot failed, the file it started in this session (one that was
 *  not there, or one that was and has changed since hx_plot_open) is
 *  removed, and the error says so. */
int hx_plot_close(hx_plot_t *p, const char *cmd);
/** on: a picture gnuplot fails to draw (hx_plot_close, or gnuplot not
 *  starting in hx_plot_open) is printed as a warning, for a command that
 *  goes on without it (eval); off (the default): as an error. */
void hx_plot_failure_warns(int on);
/** The axis labels of a path plot: the navigation frame's y and x
 *  (docs/frames.md), x along the sensor's heading at the alignment; no
 *  magnetometer, so not east and north (replay's, live's and eval's
 *  plots). */
#define HX_PLOT_PATH_XLABEL "y (m, right of the start heading)"
#define HX_PLOT_PATH_YLABEL "x (m, along the start heading)"
/** 1 when the two paths name one file: one that exists, or, when neither
 *  exists yet, one name in one directory (an output about to overwrite the
 *  input, or two outputs written into one file), else 0. */
int hx_same_file(const char *a, const char *b);
/** 1, after an error naming it, when one of the output options `outputs`
 *  (NULL-terminated, e.g. "--json") given in `a` names the input file
 *  itself (it would be overwritten, after the input was read; `input` may
 *  be NULL), or two of them name one file; else 0. The caller exits
 *  HX_EXIT_USAGE before opening anything. */
int hx_output_is_input(const char *cmd, const char *input, const hx_args_t *a, const char *const *outputs);
/** 0 when `path` can be opened for writing (an existing file is left as
 *  it is, none is left behind); -1 with the error printed. For outputs
 *  written only after long work, or by a child process. */
int hx_check_writable(const char *cmd, const char *path);
/** -1, after a usage error naming it, when one of the output options
 *  `opts` (NULL-ended) given in `a` is "-": options that write only to a
 *  file or directory (a PNG, a profile), where '-' would make a file named
 *  '-'; else 0. The caller exits HX_EXIT_USAGE before anything is read. */
int hx_refuse_dash(const char *cmd, const hx_args_t *a, const char *const *opts);
/** " (REASON)", strerror(e) in brackets, in buf (size bytes) for a message
 *  about a failed call; "" when e is 0 (no reason known). Returns buf. */
const char *hx_errno_note(int e, char *buf, size_t size);
/** hx_check_writable for each option of `files` (NULL-ended) given in `a`
 *  with a file name ("-", standard output, is not checked), and
 *  hx_plot_check for each of `pngs`: the outputs a command writes after its
 *  work, checked before it. 0, or -1 with the error printed (exit
 *  HX_EXIT_IO). */
int hx_check_outputs(const char *cmd, const hx_args_t *a, const char *const *files, const char *const *pngs);

/** The signal that asked a long command to stop (SIGINT, SIGTERM), 0 while
 *  none came: set by the handler hx_stop_on_signals installs. */
extern volatile sig_atomic_t hx_stop_sig;
/** Ctrl-C and SIGTERM stop the work at its next step instead of ending the
 *  process: the handler sets hx_stop_sig and says "CMD: stopping HOW (a
 *  second signal quits at once)" on standard error; the first signal puts
 *  both back to their default, so a second one, of either kind, ends the
 *  command at once. The command reports and writes what it did, marked
 *  incomplete, and exits 128 + hx_stop_sig (docs/harness.md, "Stopping a
 *  command"). */
void hx_stop_on_signals(const char *cmd, const char *how);
/** Both signals back to their default (end the process) once nothing is
 *  left to stop: a signal while the outputs are written is not taken for
 *  one that stopped the work. */
void hx_stop_off(void);

/** Where `--json -` (and allan's and psd's `--out -`) writes: the
 *  process's standard output, kept aside by hx_json_stdout_claim (main.c)
 *  before a command runs; NULL when no option asked for it. */
extern FILE *hx_json_stdout;
/** When argv has `--json -` (or `--json=-`), standard output is kept for
 *  the JSON alone (hx_json_stdout) and what a command prints there goes to
 *  standard error instead, so that the JSON can be piped. 0, or -1 with the
 *  error printed when another option (`--out -`, `--csv -`, `--strides -`) wants standard
 *  output as well. `allan` and `psd` claim it the same way for `--out -`
 *  alone (their CSV, written with hx_out_open). */
int hx_json_stdout_claim(const char *cmd, int argc, char **argv);
/** `path` opened for writing, or hx_json_stdout when it is "-" (claimed
 *  by hx_json_stdout_claim); NULL on failure. Close with hx_out_close. */
FILE *hx_out_open(const char *path);
/** Closes what hx_out_open returned (standard output is only flushed);
 *  0, or EOF on a write error. */
int hx_out_close(FILE *f);
/** hx_out_close, and on a write error "PATH: write failed (REASON)"
 *  printed for `cmd` (PATH "standard output" for "-", REASON the errno of
 *  the failed write or close); 0, or -1 with the error printed. */
int hx_out_finish(const char *cmd, const char *path, FILE *f);
struct cJSON;
/** Write `root` as text (one trailing newline) to `path`, or to
 *  hx_json_stdout when `path` is "-". An object first gets the key
 *  `footnav_version` (FNAV_VERSION_STRING), at the front, once: every
 *  command's JSON document carries the version that wrote it
 *  (docs/harness.md, "Conventions shared by every command"). 0, or -1 with
 *  the reason in err. */
int hx_write_json(const char *path, struct cJSON *root, char *err, size_t err_size);
/** Add `v` to the object `o` under the key `k`: a number when finite, else
 *  null (JSON has no NaN or infinity). */
void hx_json_num(struct cJSON *o, const char *k, double v);

/** `s` as the inside of a gnuplot single-quoted string (a quote doubled),
 *  cut to fit `buf`; returns buf. Every text from outside the program (a
 *  path, a file name, a unit) goes through it, so that it stays text. */
const char *hx_gp_str(char *buf, size_t size, const char *s);

/** printf to standard error with each control character of the text
 *  (or byte that is not UTF-8; hx_text_char) written as '?' but a line
 *  end that ends it, as
 *  hx_error and hx_warn write theirs: for a line that quotes a path or a
 *  file's text outside those (merge's account of a file). */
void hx_eprintf(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/** The character of text s starts with: its length in bytes (0 at the
 *  end), and in *control whether it is shown as '?': an ASCII control
 *  (below 0x20, and DEL; 1 byte), a C1 one in UTF-8 (U+0080-U+009F, C2
 *  80-9F: U+009B is a terminal's CSI, as ESC [ is; 2 bytes), or a byte of
 *  no well-formed UTF-8 character (1 byte: a raw 0x9B is CSI to a
 *  terminal of 8-bit controls). Any other character, of 1 to 4 bytes, is
 *  text. The one rule by which the text of a file or of a sender is made
 *  safe to print (hx_printable, hx_line_str, the messages, a profile's
 *  keys and name); a loop over text steps by the length it returns. */
size_t hx_text_char(const char *s, int *control);


/** `s` as one line of text, each character hx_text_char shows as '?' (a
 *  line break, a tab, a byte that is not UTF-8) a '?', cut to fit `buf`
 *  at a character's start (never inside a UTF-8 letter); returns buf. For a path in a comment line of a
 *  CSV (`# harness psd: PATH; ...`), which a line break split in two. */
const char *hx_line_str(char *buf, size_t size, const char *s);

/** Format a double for JSON/text (finite or "null"). */
const char *hx_fmt_g(char *buf, size_t size, double v);
/** After a command that failed on its input (exit HX_EXIT_DATA) before it
 *  wrote its JSON: `--json FILE` gets {command, complete: false, error: the
 *  first error printed}, so that a pipeline reading FILE finds why rather
 *  than no file or the previous run's. 0 when nothing was due or it was
 *  written, -1 (error printed) when it could not be. */
int hx_json_failure(const char *cmd, int argc, char **argv);
/** The command line as run, for a JSON's `command` or a results page:
 *  prefix ("harness replay"), then each of argv[0..argc) after a space,
 *  single-quoted as a POSIX shell reads it back when it holds anything but
 *  letters, digits and _./:=,+@%^- (or is empty); cut at size. */
void hx_command_line(char *buf, size_t size, const char *prefix, int argc, char **argv);

#endif /* HX_CLI_H */
