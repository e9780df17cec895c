/* Log I/O: the .bin format against the independent Python vectors, CSV
 * interchange, every importer on the shared data, and bad input. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cmocka.h>

#include "fnav_testdata.h"
#include "fuzz/fuzz_log_byte.h"
#include "hx_bin.h"
#include "hx_cli.h"
#include "hx_log.h"
#include "hx_names.h"

#define MAXS 16

typedef struct {
    fnav_sample_t s[MAXS];
    int n;
    fnav_status_t end;
    char err[1024];
    char warn[1024]; /* the reader's warnings */
} readall_t;

static int read_all(const char *path, hx_format_t fmt, double rate, readall_t *out, hx_meta_t *meta)
{
    char err[1024];
    hx_reader_t *r = hx_reader_open(path, fmt, rate, err, sizeof err);
    fnav_sample_t s;
    memset(out, 0, sizeof *out);
    if (r == NULL) {
        snprintf(out->err, sizeof out->err, "%s", err);
        return -1;
    }
    if (meta != NULL) {
        *meta = *hx_reader_meta(r);
    }
    while ((out->end = hx_reader_next(r, &s)) == FNAV_OK) {
        if (out->n < MAXS) {
            out->s[out->n] = s;
        }
        out->n++;
    }
    snprintf(out->err, sizeof out->err, "%s", hx_reader_error(r));
    snprintf(out->warn, sizeof out->warn, "%s", hx_reader_warnings(r));
    hx_reader_close(r);
    return 0;
}

static void tmp_path(char *buf, size_t size, const char *suffix)
{
    static int counter = 0;
    snprintf(buf, size, "/tmp/fnav_test_log_%d_%d%s", (int)getpid(), counter++, suffix);
}

static void write_file(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
}

static size_t read_file(const char *path, unsigned char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    size_t n;
    assert_non_null(f);
    n = fread(buf, 1, cap, f);
    fclose(f);
    return n;
}

static void write_text(const char *path, const char *text)
{
    write_file(path, text, strlen(text));
}

/* ------------------------------------------------------------ golden */

static unsigned char g_golden[4096];
static size_t g_golden_n;

static int setup_golden(void **state)
{
    char p[512];
    (void)state;
    if (fnav_vector_path("logformat/sample_v1.bin", p, sizeof p) != 0) {
        fprintf(stderr, "vectors/logformat/sample_v1.bin missing (run from the repository root)\n");
        return -1;
    }
    g_golden_n = read_file(p, g_golden, sizeof g_golden);
    return 0;
}

/* The C reader decodes the Python-written file to the CSV's values. */
static void test_golden_read(void **state)
{
    char pb[512], pc[512];
    readall_t b, c;
    hx_meta_t mb;
    int i, k;
    (void)state;
    assert_int_equal(fnav_vector_path("logformat/sample_v1.bin", pb, sizeof pb), 0);
    assert_int_equal(fnav_vector_path("logformat/sample_v1.csv", pc, sizeof pc), 0);
    assert_int_equal(read_all(pb, HX_FMT_AUTO, 0.0, &b, &mb), 0);
    assert_int_equal(read_all(pc, HX_FMT_AUTO, 0.0, &c, NULL), 0);
    assert_int_equal(b.end, FNAV_END);
    assert_int_equal(c.end, FNAV_END);
    assert_int_equal(b.n, 6);
    assert_int_equal(c.n, 6);
    assert_int_equal(mb.format, HX_FMT_BIN);
    assert_true(mb.rate_hz == 400.0);
    assert_true(mb.rate_nominal && mb.has_temp && mb.has_seq);
    assert_string_equal(mb.sensor, "golden-vector");
    assert_string_equal(mb.axes, "x fwd, y left, z up");
    for (i = 0; i < 6; i++) {
        assert_true(b.s[i].t_ns == c.s[i].t_ns);
        for (k = 0; k < 3; k++) {
            assert_true((float)b.s[i].accel_mps2[k] == (float)c.s[i].accel_mps2[k]);
            assert_true((float)b.s[i].gyro_rps[k] == (float)c.s[i].gyro_rps[k]);
        }
        assert_true((float)b.s[i].temp_c == (float)c.s[i].temp_c);
        assert_true(b.s[i].flags & FNAV_SAMPLE_HAS_TEMP);
        assert_true(b.s[i].flags & FNAV_SAMPLE_HAS_SEQ);
    }
    /* the counter shows the drop (5 missing) and the duplicate time stamp */
    assert_int_equal(b.s[5].seq, 6);
    assert_true(b.s[3].t_ns == b.s[4].t_ns);
}

/* The C writer reproduces the Python-written file byte for byte. */
static void test_golden_write(void **state)
{
    char pb[512], out[256], err[320];
    readall_t b;
    hx_meta_t m;
    hx_writer_t *w;
    unsigned char buf[4096];
    size_t n;
    int i;
    (void)state;
    assert_int_equal(fnav_vector_path("logformat/sample_v1.bin", pb, sizeof pb), 0);
    assert_int_equal(read_all(pb, HX_FMT_BIN, 0.0, &b, &m), 0);
    snprintf(m.source, sizeof m.source, "vectors/logformat");
    tmp_path(out, sizeof out, ".bin");
    w = hx_writer_open(out, HX_FMT_AUTO, &m, 0, err, sizeof err);
    assert_non_null(w);
    for (i = 0; i < b.n; i++) {
        assert_int_equal(hx_writer_write(w, &b.s[i]), FNAV_OK);
    }
    assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
    n = read_file(out, buf, sizeof buf);
    assert_int_equal(n, g_golden_n);
    assert_memory_equal(buf, g_golden, n);
    unlink(out);
}

/* CSV -> .bin -> CSV reproduces canonical CSV text exactly. */
static void test_csv_bin_csv_text(void **state)
{
    char pc[512], b1[256], c2[256], err[320];
    unsigned char t1[4096], t2[4096];
    size_t n1, n2;
    hx_reader_t *r;
    hx_writer_t *w;
    fnav_sample_t s;
    hx_meta_t m;
    (void)state;
    assert_int_equal(fnav_vector_path("logformat/sample_v1.csv", pc, sizeof pc), 0);
    tmp_path(b1, sizeof b1, ".bin");
    tmp_path(c2, sizeof c2, ".csv");
    r = hx_reader_open(pc, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_non_null(r);
    m = *hx_reader_meta(r);
    assert_true(m.has_temp);
    w = hx_writer_open(b1, HX_FMT_AUTO, &m, 1, err, sizeof err);
    assert_non_null(w);
    while (hx_reader_next(r, &s) == FNAV_OK) {
        assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
    }
    hx_reader_close(r);
    assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
    r = hx_reader_open(b1, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_non_null(r);
    m = *hx_reader_meta(r);
    w = hx_writer_open(c2, HX_FMT_AUTO, &m, 0, err, sizeof err);
    assert_non_null(w);
    while (hx_reader_next(r, &s) == FNAV_OK) {
        assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
    }
    hx_reader_close(r);
    assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
    n1 = read_file(pc, t1, sizeof t1);
    n2 = read_file(c2, t2, sizeof t2);
    assert_int_equal(n1, n2);
    assert_memory_equal(t1, t2, n1);
    unlink(b1);
    unlink(c2);
}

/* ------------------------------------------------------------ bad .bin */

static void expect_bin(const unsigned char *data, size_t n, int open_ok, int n_samples, fnav_status_t end,
                       const char *msg_part)
{
    char p[256];
    readall_t r;
    tmp_path(p, sizeof p, ".bin");
    write_file(p, data, n);
    if (!open_ok) {
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    } else {
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
        assert_int_equal(r.n, n_samples);
        assert_int_equal(r.end, end);
    }
    if (msg_part != NULL && strstr(r.err, msg_part) == NULL) {
        fail_msg("error '%s' does not contain '%s'", r.err, msg_part);
    }
    /* every message names the file */
    if (msg_part != NULL && strstr(r.err, p) == NULL) {
        fail_msg("error '%s' does not name the file", r.err);
    }
    unlink(p);
}

static void test_bin_truncated(void **state)
{
    (void)state;
    /* cut inside the header */
    expect_bin(g_golden, 100, 0, 0, FNAV_END, "too short");
    /* cut inside record #3: the three complete records before the cut survive */
    expect_bin(g_golden, HX_BIN_HEADER_SIZE + 3 * HX_BIN_RECORD_SIZE + 20, 1, 3, FNAV_E_TRUNCATED, "record #3");
    /* cut at a record boundary, before the end record: recording not closed */
    expect_bin(g_golden, HX_BIN_HEADER_SIZE + 6 * HX_BIN_RECORD_SIZE, 1, 6, FNAV_E_TRUNCATED, "did not finish");
    /* header only, nothing else */
    expect_bin(g_golden, HX_BIN_HEADER_SIZE, 1, 0, FNAV_E_TRUNCATED, "truncated");
    /* empty file */
    expect_bin(g_golden, 0, 0, 0, FNAV_END, "empty");
}

static void test_bin_corrupted(void **state)
{
    unsigned char b[4096];
    (void)state;
    /* a flipped byte inside record #2: the other five records survive */
    memcpy(b, g_golden, g_golden_n);
    b[HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE + 20] ^= 0x40;
    expect_bin(b, g_golden_n, 1, 5, FNAV_E_CRC, "record #2");
    /* header corruption */
    memcpy(b, g_golden, g_golden_n);
    b[30] ^= 0x01;
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "header checksum");
    /* wrong magic */
    memcpy(b, g_golden, g_golden_n);
    b[0] = 'X';
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "not a footnav .bin: bad magic (its first 4 bytes are 58 4e 41 56");
    /* wrong version */
    memcpy(b, g_golden, g_golden_n);
    b[4] = 2;
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "unsupported version 2");
    /* huge header size */
    memcpy(b, g_golden, g_golden_n);
    b[6] = 0xff;
    b[7] = 0xff;
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "header size 65535");
    /* seven garbage bytes inserted after record #1: resynchronised, all six kept */
    memcpy(b, g_golden, HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE);
    memcpy(b + HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE, "GARBAGE", 7);
    memcpy(b + HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE + 7, g_golden + HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE,
           g_golden_n - HX_BIN_HEADER_SIZE - 2 * HX_BIN_RECORD_SIZE);
    expect_bin(b, g_golden_n + 7, 1, 6, FNAV_E_CRC, "corrupted");
    /* a record of an unknown type with a right CRC: skipped, and said so
     * (a mutant reading any type checked the CRC alone and called it a
     * checksum mismatch) */
    memcpy(b, g_golden, g_golden_n);
    b[HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE] = 0x02; /* type 0xA502 */
    {
        uLong c = crc32(0L, b + HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE, 44);
        int k;
        for (k = 0; k < 4; k++) {
            b[HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE + 44 + k] = (unsigned char)((c >> (8 * k)) & 0xffu);
        }
    }
    expect_bin(b, g_golden_n, 1, 5, FNAV_E_CRC, "record #2 at byte 288: unknown record type (corrupted); skipped");
    /* trailing garbage after the end record */
    memcpy(b, g_golden, g_golden_n);
    memset(b + g_golden_n, 0x55, 100);
    expect_bin(b, g_golden_n + 100, 1, 6, FNAV_E_CRC, "corrupted");
    /* ... shorter than a record: bytes after the end, every record read,
     * not "truncated: record #7 ... has 25 of 48 bytes" (a cut record
     * of a log that was closed) */
    expect_bin(b, g_golden_n + 25, 1, 6, FNAV_E_FORMAT,
               ": 25 bytes after the end record, at byte 528: too few for a record (junk appended to a closed "
               "log?)");
}

/* A .bin (or .bin.gz) whose magic is off by one byte (a flipped bit): the
 * content is no text, and detection must not read it as CSV and say "a NUL
 * byte in the text": a file so named whose first four bytes hold three of
 * FNAV's is said to be a .bin with a bad magic. The same bytes under
 * another name, or two bytes of the magic, are read as any other file. */
static void test_bin_bad_magic(void **state)
{
    unsigned char b[4096];
    char p[256];
    readall_t r;
    gzFile gz;
    (void)state;
    memcpy(b, g_golden, g_golden_n);
    b[0] ^= 0x01; /* 'G' */
    tmp_path(p, sizeof p, ".bin");
    write_file(p, b, g_golden_n);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    if (strstr(r.err, p) == NULL ||
        strstr(r.err, ": not a footnav .bin: bad magic (its first 4 bytes are 47 4e 41 56, not FNAV's 46 4e 41 56: "
                      "a damaged file?)") == NULL) {
        fail_msg("'%s' names no bad magic", r.err);
    }
    unlink(p);
    tmp_path(p, sizeof p, ".BIN.gz");
    gz = gzopen(p, "wb");
    assert_non_null(gz);
    assert_int_equal(gzwrite(gz, b, (unsigned)g_golden_n), (int)g_golden_n);
    assert_int_equal(gzclose(gz), Z_OK);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    assert_non_null(strstr(r.err, ": not a footnav .bin: bad magic"));
    unlink(p);
    b[3] = 'X'; /* two bytes off: not taken for a damaged magic */
    tmp_path(p, sizeof p, ".bin");
    write_file(p, b, g_golden_n);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    assert_null(strstr(r.err, "bad magic"));
    assert_non_null(strstr(r.err, "a NUL byte in the text"));
    unlink(p);
    b[3] = 'V'; /* another name: the content decides, as before */
    tmp_path(p, sizeof p, ".dat");
    write_file(p, b, g_golden_n);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    assert_null(strstr(r.err, "bad magic"));
    assert_non_null(strstr(r.err, "a NUL byte in the text"));
    unlink(p);
}

/* The golden file with its header's CRC made right again after a change
 * (zlib's crc32, as the specification says). */
static void golden_patched_header(unsigned char *b)
{
    uLong c = crc32(0L, b, 188);
    b[188] = (unsigned char)(c & 0xffu);
    b[189] = (unsigned char)((c >> 8) & 0xffu);
    b[190] = (unsigned char)((c >> 16) & 0xffu);
    b[191] = (unsigned char)((c >> 24) & 0xffu);
}

/* What a reader rejects in a header whose CRC is right (docs/log-format.md,
 * "Header"): a version other than 1, a rate outside [0, 1e6], an
 * unterminated text field, units other than the fixed string. Hand-made
 * mutants dropping each of these checks (or taking version 0 for 1)
 * passed every suite: the corrupted headers above all had a bad CRC, a
 * version of 2 or a huge size. And the header's flags are read as they
 * are: the golden file sets all three, so a reader taking any flag as set
 * passed too. */
static void test_bin_header_fields(void **state)
{
    static const struct {
        unsigned bit;
        size_t off; /* of the hx_meta_t field the bit sets */
    } k_flags[3] = { { 0x1u, offsetof(hx_meta_t, rate_nominal) },
                     { 0x2u, offsetof(hx_meta_t, has_temp) },
                     { 0x4u, offsetof(hx_meta_t, has_seq) } };
    unsigned char b[4096];
    double rate;
    char p[256];
    readall_t r;
    hx_meta_t m;
    int i;
    (void)state;
    memcpy(b, g_golden, g_golden_n);
    b[4] = 0;
    golden_patched_header(b);
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "unsupported version 0");
    memcpy(b, g_golden, g_golden_n);
    rate = 2.0e6;
    memcpy(b + 16, &rate, 8); /* little-endian host, as the format */
    golden_patched_header(b);
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "not in [0, 1e6]");
    memcpy(b, g_golden, g_golden_n);
    rate = 1.0e6; /* the top of the range is in it */
    memcpy(b + 16, &rate, 8);
    golden_patched_header(b);
    expect_bin(b, g_golden_n, 1, 6, FNAV_END, NULL);
    memcpy(b, g_golden, g_golden_n);
    memset(b + 80, 'x', 48); /* the axis note without its NUL */
    golden_patched_header(b);
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "text field not terminated");
    memcpy(b, g_golden, g_golden_n);
    memcpy(b + 56, "m/s^2 rad/s degC us", 20); /* time in microseconds */
    golden_patched_header(b);
    expect_bin(b, g_golden_n, 0, 0, FNAV_END, "units 'm/s^2 rad/s degC us' not supported");
    for (i = 0; i < 3; i++) {
        memcpy(b, g_golden, g_golden_n);
        assert_true((b[12] & k_flags[i].bit) != 0);
        b[12] = (unsigned char)(b[12] & ~k_flags[i].bit);
        golden_patched_header(b);
        tmp_path(p, sizeof p, ".bin");
        write_file(p, b, g_golden_n);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, &m), 0);
        assert_int_equal(r.n, 6);
        assert_int_equal(*(const int *)(const void *)((const char *)&m + k_flags[i].off), 0);
        assert_int_equal(m.rate_nominal + m.has_temp + m.has_seq, 2);
        if (k_flags[i].bit == HX_BIN_FLAG_TEMP) {
            /* the records still flag their temperatures: not read, as the
             * header says (convert writes no column), but said, not
             * dropped silently */
            assert_int_equal(r.s[2].flags & FNAV_SAMPLE_HAS_TEMP, 0);
            if (strstr(r.warn, "record #0 carries a temperature but the header's flags say the log has none") ==
                NULL) {
                fail_msg("no warning for the unflagged temperatures: '%s'", r.warn);
            }
        } else {
            assert_null(strstr(r.warn, "temperature"));
        }
        unlink(p);
    }
}

/* The END record's count against the records read (docs/log-format.md,
 * "Integrity and what a reader does": record count disagrees with END,
 * reported at the end): the golden
 * END says 6; made 5 (its CRC made right), all six samples are delivered,
 * then the mismatch. A mutant ignoring the count passed every suite. */
static void test_bin_end_count(void **state)
{
    unsigned char b[4096], *end = b + HX_BIN_HEADER_SIZE + 6 * HX_BIN_RECORD_SIZE;
    uLong c;
    (void)state;
    memcpy(b, g_golden, g_golden_n);
    assert_int_equal(g_golden_n, HX_BIN_HEADER_SIZE + 7 * HX_BIN_RECORD_SIZE);
    assert_int_equal(end[0] | (end[1] << 8), HX_BIN_REC_END);
    assert_int_equal(end[4], 6);
    end[4] = 5;
    c = crc32(0L, end, 44);
    end[44] = (unsigned char)(c & 0xffu);
    end[45] = (unsigned char)((c >> 8) & 0xffu);
    end[46] = (unsigned char)((c >> 16) & 0xffu);
    end[47] = (unsigned char)((c >> 24) & 0xffu);
    expect_bin(b, g_golden_n, 1, 6, FNAV_E_CRC, "end record counts 5 records but 6 were read");
    /* the END record twice (a writer closing the file twice): all six
     * samples, the end clean, and the second said (it was taken silently) */
    {
        char p[256];
        readall_t r;
        memcpy(b, g_golden, g_golden_n);
        memcpy(b + g_golden_n, b + HX_BIN_HEADER_SIZE + 6 * HX_BIN_RECORD_SIZE, HX_BIN_RECORD_SIZE);
        tmp_path(p, sizeof p, ".bin");
        write_file(p, b, g_golden_n + HX_BIN_RECORD_SIZE);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
        assert_int_equal(r.n, 6);
        assert_int_equal(r.end, FNAV_END);
        if (strstr(r.warn, "record #7 at byte 528: a second end record (the file was closed twice?)") == NULL) {
            fail_msg("no warning for the second end record: '%s'", r.warn);
        }
        unlink(p);
    }
}

/* Resynchronisation (docs/log-format.md, "Integrity and what a reader does": corrupted record): at the next
 * slot when that slot is valid, else byte by byte; the skipped bytes are
 * counted. A record damaged in place skips no byte; seven bytes inserted
 * skip those seven. A mutant always scanning byte by byte (48 bytes
 * skipped for the damaged record) passed every suite. */
static void test_bin_resync_counts(void **state)
{
    unsigned char b[4096];
    const size_t r2 = HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE;
    char p[256], err[320];
    hx_log_t log;
    (void)state;
    memcpy(b, g_golden, g_golden_n);
    b[r2 + 20] ^= 0x40;
    tmp_path(p, sizeof p, ".bin");
    write_file(p, b, g_golden_n);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_int_equal(log.n, 5);
    assert_int_equal(log.stats.bad_records, 1);
    assert_int_equal(log.stats.skipped_bytes, 0);
    hx_log_free(&log);
    memcpy(b, g_golden, r2);
    memcpy(b + r2, "GARBAGE", 7);
    memcpy(b + r2 + 7, g_golden + r2, g_golden_n - r2);
    write_file(p, b, g_golden_n + 7);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_int_equal(log.n, 6);
    assert_int_equal(log.stats.bad_records, 1);
    assert_int_equal(log.stats.skipped_bytes, 7);
    hx_log_free(&log);
    unlink(p);
}

/* The record numbers after a byte-by-byte resynchronisation (record #N
 * counts from 0, the header excluded: docs/log-format.md, "Integrity"):
 * the stretch skipped counts as the records it holds, to the nearest whole
 * one. Ten bytes inserted before record 2 hold none: record 4, with a NaN,
 * is #4 at byte 192 + 4 * 48 + 10 (not #5, the stretch counted as one).
 * Records 1 and 2 damaged, which the next slot cannot skip: 96 bytes, two
 * records, so record 4 is #4 at byte 384 (not #3). */
static void test_bin_resync_numbers(void **state)
{
    unsigned char b[4096];
    const size_t r2 = HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE;
    hx_bin_record_t rec;
    (void)state;
    memcpy(b, g_golden, g_golden_n);
    assert_int_equal(hx_bin_record_decode(b + HX_BIN_HEADER_SIZE + 4 * HX_BIN_RECORD_SIZE, &rec), 0);
    rec.acc[0] = (float)NAN;
    hx_bin_record_encode(&rec, b + HX_BIN_HEADER_SIZE + 4 * HX_BIN_RECORD_SIZE);
    {
        unsigned char c[4096];
        memcpy(c, b, r2);
        memcpy(c + r2, "0123456789", 10);
        memcpy(c + r2 + 10, b + r2, g_golden_n - r2);
        expect_bin(c, g_golden_n + 10, 1, 4, FNAV_E_NANINF, "record #4 at byte 394: NaN or Inf in a sample");
        expect_bin(c, g_golden_n + 10, 1, 4, FNAV_E_NANINF,
                   "record #2 at byte 288: unknown record type (corrupted); skipped");
    }
    b[HX_BIN_HEADER_SIZE + 1 * HX_BIN_RECORD_SIZE + 20] ^= 0x40;
    b[r2 + 20] ^= 0x40;
    expect_bin(b, g_golden_n, 1, 2, FNAV_E_NANINF, "record #4 at byte 384: NaN or Inf in a sample");
}

static void test_bin_nan_record(void **state)
{
    unsigned char b[4096];
    hx_bin_record_t rec;
    float nan = (float)NAN;
    (void)state;
    memcpy(b, g_golden, g_golden_n);
    assert_int_equal(hx_bin_record_decode(b + HX_BIN_HEADER_SIZE + 4 * HX_BIN_RECORD_SIZE, &rec), 0);
    rec.gyr[1] = nan;
    hx_bin_record_encode(&rec, b + HX_BIN_HEADER_SIZE + 4 * HX_BIN_RECORD_SIZE);
    expect_bin(b, g_golden_n, 1, 4, FNAV_E_NANINF, "NaN");
    /* a NaN temperature (flagged valid) likewise: delivered, it would let
     * convert write "nan" into a CSV that the CSV reader refuses */
    memcpy(b, g_golden, g_golden_n);
    assert_int_equal(hx_bin_record_decode(b + HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE, &rec), 0);
    assert_true((rec.flags & HX_BIN_REC_TEMP) != 0);
    rec.temp = nan;
    hx_bin_record_encode(&rec, b + HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE);
    expect_bin(b, g_golden_n, 1, 2, FNAV_E_NANINF, "NaN");    /* under a header without the temperature flag it is not read (warned,
     * test_bin_header_fields), so it does not stop the reading either */
    b[12] = (unsigned char)(b[12] & ~HX_BIN_FLAG_TEMP);
    golden_patched_header(b);
    expect_bin(b, g_golden_n, 1, 6, FNAV_END, NULL);
}

/* A sample record whose values a reader must refuse though its checksum
 * holds (paths only this test runs: make coverage-harness): time going
 * backwards, beyond 2^62 ns, a value beyond FNAV_INPUT_MAX_ABS; and a sample
 * after the end record. Each ends the read there with its status and a
 * message naming the record; the samples before it are delivered. */
static void test_bin_bad_record_values(void **state)
{
    unsigned char b[4096];
    hx_bin_record_t rec, prev;
    const size_t r2 = HX_BIN_HEADER_SIZE + 2 * HX_BIN_RECORD_SIZE;
    const size_t r3 = HX_BIN_HEADER_SIZE + 3 * HX_BIN_RECORD_SIZE;
    const size_t r5 = HX_BIN_HEADER_SIZE + 5 * HX_BIN_RECORD_SIZE;
    (void)state;
    memcpy(b, g_golden, g_golden_n);
    assert_int_equal(hx_bin_record_decode(b + r2, &prev), 0);
    assert_int_equal(hx_bin_record_decode(b + r3, &rec), 0);
    rec.t_ns = prev.t_ns - 1;
    hx_bin_record_encode(&rec, b + r3);
    /* named at its byte as every other record error (it was the one
     * without: "record #3: time goes backwards") */
    expect_bin(b, g_golden_n, 1, 3, FNAV_E_TIME, "record #3 at byte 336: time goes backwards");

    memcpy(b, g_golden, g_golden_n);
    assert_int_equal(hx_bin_record_decode(b + r3, &rec), 0);
    rec.t_ns = INT64_MAX;
    hx_bin_record_encode(&rec, b + r3);
    expect_bin(b, g_golden_n, 1, 3, FNAV_E_RANGE, "beyond 2^62 ns");

    memcpy(b, g_golden, g_golden_n);
    assert_int_equal(hx_bin_record_decode(b + r3, &rec), 0);
    rec.acc[0] = 2.0e6f;
    hx_bin_record_encode(&rec, b + r3);
    expect_bin(b, g_golden_n, 1, 3, FNAV_E_RANGE, "a value beyond");

    /* the last sample and the end record again after the end record (two
     * recordings run together): the sample is delivered, then the read ends
     * in a format error naming it */
    assert_int_equal(g_golden_n, (size_t)HX_BIN_HEADER_SIZE + 7 * HX_BIN_RECORD_SIZE);
    memcpy(b, g_golden, g_golden_n);
    memcpy(b + g_golden_n, g_golden + r5, 2 * HX_BIN_RECORD_SIZE);
    expect_bin(b, g_golden_n + 2 * HX_BIN_RECORD_SIZE, 1, 7, FNAV_E_FORMAT, "data after the end record");
}

/* A .bin whose accelerations were written in ug (1 g reads 1e6, at the
 * limit): the CSV reader asks "in ug?" and names --units accel=ug, but a
 * .bin's units are fixed by its header (m/s^2; docs/log-format.md) and
 * --units does not apply to it, so the .bin reader asks the same question
 * with the remedy that applies: its writer must scale ug to m/s^2 (not
 * only "no sensor reads that"). Not asked of a
 * rate beyond 1e6, nor of an acceleration beyond 400 g once read in ug,
 * nor of a record with a plausible acceleration in ug and a rate both
 * beyond the limit (every value beyond must be a plausible acceleration:
 * stricter than the CSV reader, which asks about the first field beyond
 * alone). */
static void test_bin_value_in_ug(void **state)
{
    static const struct {
        int gyro, axis;
        float v;
        float gz; /* when not 0: gz too */
        int asked;
    } k_case[] = { { 0, 0, 2.0e6f, 0.0f, 1 },  { 0, 2, -9.8e6f, 0.0f, 1 }, { 1, 1, 2.0e6f, 0.0f, 0 },
                   { 0, 0, 1.0e10f, 0.0f, 0 }, { 0, 0, 2.0e6f, 2.0e6f, 0 } };
    unsigned char b[4096];
    hx_bin_record_t rec;
    const size_t r3 = HX_BIN_HEADER_SIZE + 3 * HX_BIN_RECORD_SIZE;
    size_t i;
    char p[256];
    (void)state;
    for (i = 0; i < sizeof k_case / sizeof k_case[0]; i++) {
        readall_t r;
        memcpy(b, g_golden, g_golden_n);
        assert_int_equal(hx_bin_record_decode(b + r3, &rec), 0);
        if (k_case[i].gyro) {
            rec.gyr[k_case[i].axis] = k_case[i].v;
        } else {
            rec.acc[k_case[i].axis] = k_case[i].v;
        }
        if (k_case[i].gz != 0.0f) {
            rec.gyr[2] = k_case[i].gz;
        }
        hx_bin_record_encode(&rec, b + r3);
        tmp_path(p, sizeof p, ".bin");
        write_file(p, b, g_golden_n);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
        unlink(p);
        assert_int_equal(r.n, 3);
        assert_int_equal(r.end, FNAV_E_RANGE);
        assert_non_null(
            strstr(r.err, ": record #3 at byte 336: a value beyond 1e+06 in SI units (no sensor reads that"));
        /* the remedy of a CSV does not apply to a .bin */
        assert_null(strstr(r.err, "--units accel"));
        if (k_case[i].asked) {
            char want[256];
            snprintf(want, sizeof want,
                     "(no sensor reads that; a%c is %g: in ug? 1 g is 1e6 ug, but a .bin holds m/s^2 "
                     "(docs/log-format.md) and --units does not apply to it: the program that wrote it must scale "
                     "ug by 9.80665e-6)",
                     "xyz"[k_case[i].axis], (double)k_case[i].v);
            if (strstr(r.err, want) == NULL) {
                fail_msg("error '%s' does not contain '%s'", r.err, want);
            }
        } else {
            assert_non_null(strstr(r.err, "(no sensor reads that)"));
        }
    }
}

/* ------------------------------------------------------------ bad CSV */

static void expect_csv(const char *text, int open_ok, int n_samples, fnav_status_t end, const char *msg_part)
{
    char p[256];
    readall_t r;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, text);
    if (!open_ok) {
        assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &r, NULL), -1);
    } else {
        assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &r, NULL), 0);
        assert_int_equal(r.n, n_samples);
        assert_int_equal(r.end, end);
    }
    if (msg_part != NULL && strstr(r.err, msg_part) == NULL) {
        fail_msg("error '%s' does not contain '%s'", r.err, msg_part);
    }
    unlink(p);
}

static void test_csv_malformed(void **state)
{
    (void)state;
    expect_csv("", 0, 0, FNAV_END, "empty");
    {
        /* 'gx' in column 65 of 67, past the 64 read: said so, not "no column" */
        char text[1024];
        size_t k, m = 0;
        for (k = 0; k < 60; k++) {
            m += (size_t)snprintf(text + m, sizeof text - m, "c%zu,", k);
        }
        m += (size_t)snprintf(text + m, sizeof text - m, "t,ax,ay,az,gx,gy,gz\n");
        for (k = 0; k < 66; k++) {
            m += (size_t)snprintf(text + m, sizeof text - m, "0,");
        }
        snprintf(text + m, sizeof text - m, "0\n");
        expect_csv(text, 0, 0, FNAV_END, "header has 67 columns; only the first 64 are read, and 'gx' is not among them");
    }
    expect_csv("t,ax,ay,az,gx,gy\n0,1,2,3,4,5\n", 0, 0, FNAV_END, "no column 'gz'");
    expect_csv("t,ax,ay,az,gx,gy,gz\n", 1, 0, FNAV_E_FORMAT, "no samples");
    expect_csv("t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.01,1,2,x3,4,5,6\n", 1, 1, FNAV_E_FORMAT, ":3:");
    expect_csv("t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.01,1,2,3,4,5\n", 1, 1, FNAV_E_FORMAT, "6 columns");
    expect_csv("t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.01,1,2,NaN,4,5,6\n", 1, 1, FNAV_E_NANINF, "NaN or Inf");
    expect_csv("t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.01,1,2,3,inf,5,6\n", 1, 1, FNAV_E_NANINF, ":3:");
    expect_csv("t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.02,1,2,3,4,5,6\n0.01,1,2,3,4,5,6\n", 1, 2, FNAV_E_TIME,
               "backwards");
    expect_csv("t,ax,ay,az,gx,gy,gz\nzero,1,2,3,4,5,6\n", 1, 0, FNAV_E_FORMAT, "time");
    /* C's hexadecimal notation is no decimal number: strtod read 0x10 as 16
     * (a logger's hex field in a wrong column passed as a value) */
    expect_csv("t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.01,0x10,2,3,4,5,6\n", 1, 1, FNAV_E_FORMAT,
               ":3: column 2 ('0x10') is not a number");
    expect_csv("t,ax,ay,az,gx,gy,gz\n0x1,1,2,3,4,5,6\n", 1, 0, FNAV_E_FORMAT, ":2: time");
    /* a decimal number past a double (strtod's Inf) is beyond a sensor's
     * range, not "NaN or Inf" (FNAV_E_NANINF until 2026-12-07) */
    expect_csv("t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,1e999\n", 1, 0, FNAV_E_RANGE,
               ":2: column 7 ('1e999') is beyond 1e+06 in SI units");
    /* a temperature beyond float32 became Inf, which convert wrote as "inf"
     * (a CSV the reader refuses) or into a .bin record the .bin reader
     * refuses: refused at its line, as a value beyond 1e6 */
    expect_csv("t,ax,ay,az,gx,gy,gz,temp\n0,1,2,3,4,5,6,20\n0.01,1,2,3,4,5,6,1e40\n", 1, 1, FNAV_E_RANGE,
               ":3: temperature");
}

static void test_csv_flexible(void **state)
{
    char p[256];
    readall_t r;
    hx_meta_t m;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    /* any column order, extra columns ignored, optional temp kept, spaces,
     * CRLF, blank lines and duplicated time stamps accepted */
    write_text(p, "gx, gy, gz, note, t, ax, ay, az, temp\r\n"
                  "0.1,0.2,0.3,hello,0.000,1,2,3,20.5\r\n"
                  "\r\n"
                  "0.1,0.2,0.3,world,0.000,1,2,3,20.5\r\n"
                  "0.4,0.5,0.6,!,0.0100000005,4,5,6,21\r\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, &m), 0);
    assert_int_equal(m.format, HX_FMT_CSV);
    assert_true(m.has_temp);
    assert_int_equal(r.end, FNAV_END);
    assert_int_equal(r.n, 3);
    assert_true(r.s[2].t_ns == 10000001); /* 1e-2 + 5e-10 to the nearest ns, half up */
    assert_true((float)r.s[2].accel_mps2[0] == 4.0f);
    assert_true((float)r.s[2].gyro_rps[2] == 0.6f);
    assert_true((float)r.s[2].temp_c == 21.0f);
    assert_true(r.s[0].t_ns == r.s[1].t_ns);
    unlink(p);
    /* more than nine decimals round to the nearest ns, as the same number in
     * exponent notation does (they were cut: 1.9999999996 read 1 ns short
     * of 1.9999999996e0) */
    write_text(p, "t,ax,ay,az,gx,gy,gz\n0.0000000014,1,2,3,4,5,6\n0.0000000016,1,2,3,4,5,6\n"
                  "1.9999999996,1,2,3,4,5,6\n1.9999999996e0,1,2,3,4,5,6\n");
    assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &r, NULL), 0);
    assert_int_equal(r.end, FNAV_END);
    assert_int_equal(r.n, 4);
    assert_true(r.s[0].t_ns == 1);
    assert_true(r.s[1].t_ns == 2);
    assert_true(r.s[2].t_ns == 2000000000LL);
    assert_true(r.s[3].t_ns == 2000000000LL);
    unlink(p);
    /* exponent notation is exact to the ns as well, as integers (numpy's
     * %.18e of Unix time: through a double, 1.700000000002500057e+09 read
     * 39 ns off, and the plain 1700000000.0025 after its exponent form
     * went back in time) */
    write_text(p, "t,ax,ay,az,gx,gy,gz\n9.5e-10,1,2,3,4,5,6\n1.23456789015e-1,1,2,3,4,5,6\n"
                  "1.7000000000025e9,1,2,3,4,5,6\n1700000000.0025,1,2,3,4,5,6\n"
                  "1.700000000012500057e+09,1,2,3,4,5,6\n17000000000.15E-1,1,2,3,4,5,6\n"
                  "0.0000017000000000175e15,1,2,3,4,5,6\n");
    assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &r, NULL), 0);
    assert_int_equal(r.end, FNAV_END);
    assert_int_equal(r.n, 7);
    assert_true(r.s[0].t_ns == 1); /* 0.95 ns, half up */
    assert_true(r.s[1].t_ns == 123456789LL);
    assert_true(r.s[2].t_ns == 1700000000002500000LL);
    assert_true(r.s[3].t_ns == r.s[2].t_ns);
    assert_true(r.s[4].t_ns == 1700000000012500057LL);
    assert_true(r.s[5].t_ns == 1700000000015000000LL);
    assert_true(r.s[6].t_ns == 1700000000017500000LL);
    unlink(p);
}

/* A sample without a temperature in a log that has them (a .bin record
 * whose temperature is not valid) is written to CSV as an empty field and
 * read back without one, not written as 0 degC, a temperature it never
 * had. CSV -> .bin -> CSV keeps it. */
static void test_csv_missing_temp(void **state)
{
    char pc[256], pb[256], pc2[256], err[320];
    unsigned char t1[1024], t2[1024];
    size_t n1, n2;
    readall_t r;
    hx_meta_t m;
    hx_writer_t *w;
    int i;
    (void)state;
    tmp_path(pc, sizeof pc, ".csv");
    tmp_path(pb, sizeof pb, ".bin");
    tmp_path(pc2, sizeof pc2, ".csv");
    write_text(pc, "t,ax,ay,az,gx,gy,gz,temp\n"
                   "0.000000000,1,2,3,4,5,6,20.5\n"
                   "0.010000000,1,2,3,4,5,6,\n"
                   "0.020000000,1,2,3,4,5,6,21\n");
    assert_int_equal(read_all(pc, HX_FMT_CSV, 0.0, &r, &m), 0);
    assert_int_equal(r.end, FNAV_END);
    assert_int_equal(r.n, 3);
    assert_true(m.has_temp);
    assert_true(r.s[0].flags & FNAV_SAMPLE_HAS_TEMP);
    assert_false(r.s[1].flags & FNAV_SAMPLE_HAS_TEMP);
    assert_true(r.s[2].flags & FNAV_SAMPLE_HAS_TEMP);
    assert_true((float)r.s[2].temp_c == 21.0f);
    /* to .bin: the record's temperature flag is clear */
    w = hx_writer_open(pb, HX_FMT_AUTO, &m, 0, err, sizeof err);
    assert_non_null(w);
    for (i = 0; i < r.n; i++) {
        assert_int_equal(hx_writer_write(w, &r.s[i]), FNAV_OK);
    }
    assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
    assert_int_equal(read_all(pb, HX_FMT_AUTO, 0.0, &r, &m), 0);
    assert_int_equal(r.n, 3);
    assert_false(r.s[1].flags & FNAV_SAMPLE_HAS_TEMP);
    assert_true(r.s[0].flags & FNAV_SAMPLE_HAS_TEMP);
    /* and back to CSV: the same text, the missing temperature an empty field */
    w = hx_writer_open(pc2, HX_FMT_AUTO, &m, 0, err, sizeof err);
    assert_non_null(w);
    for (i = 0; i < r.n; i++) {
        assert_int_equal(hx_writer_write(w, &r.s[i]), FNAV_OK);
    }
    assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
    n1 = read_file(pc, t1, sizeof t1);
    n2 = read_file(pc2, t2, sizeof t2);
    assert_int_equal(n1, n2);
    assert_memory_equal(t1, t2, n1);
    /* a blank temperature among spaces is missing too; text still is an error */
    write_text(pc, "t,ax,ay,az,gx,gy,gz,temp\n0,1,2,3,4,5,6, \n0.01,1,2,3,4,5,6,warm\n");
    assert_int_equal(read_all(pc, HX_FMT_CSV, 0.0, &r, NULL), 0);
    assert_int_equal(r.n, 1);
    assert_false(r.s[0].flags & FNAV_SAMPLE_HAS_TEMP);
    assert_int_equal(r.end, FNAV_E_FORMAT);
    unlink(pc);
    unlink(pb);
    unlink(pc2);
}

static void test_csv_gzip(void **state)
{
    char p[256];
    readall_t r;
    gzFile gz;
    const char *text = "t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.005,1,2,3,4,5,6\n";
    (void)state;
    tmp_path(p, sizeof p, ".csv.gz");
    gz = gzopen(p, "wb");
    assert_non_null(gz);
    assert_int_equal(gzwrite(gz, text, (unsigned)strlen(text)), (int)strlen(text));
    assert_int_equal(gzclose(gz), Z_OK);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.n, 2);
    assert_int_equal(r.end, FNAV_END);
    assert_true(r.s[1].t_ns == 5000000);
    unlink(p);
}

/* A .csv.gz cut short (an incomplete copy): every sample before the cut is
 * kept and the reading ends in an error that says so: a cut inside a line
 * must not pass as "last line is incomplete (recording cut off
 * mid-write)", a warning with exit status 0, while a cut at a line's end
 * is a "read error". */
static void test_gz_truncated(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    gzFile gz;
    struct stat sb;
    int k, rc;
    (void)state;
    tmp_path(p, sizeof p, ".csv.gz");
    gz = gzopen(p, "wb");
    assert_non_null(gz);
    gzprintf(gz, "gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n");
    for (k = 0; k < 20000; k++) {
        gzprintf(gz, "%.2f,%.2f,%.2f,%.5f,%.5f,%.5f\n", 0.05 * (k % 7), -0.3 + 0.05 * (k % 11), 0.45 + 0.05 * (k % 5),
                 -0.00333 * (k % 3), 0.00333 * (k % 13), -1.01565 + 0.00333 * (k % 4));
    }
    assert_int_equal(gzclose(gz), Z_OK);
    assert_int_equal(stat(p, &sb), 0);
    assert_int_equal(truncate(p, sb.st_size / 2), 0);
    rc = hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_int_equal(rc, 1);
    assert_int_equal(log.meta.format, HX_FMT_ADIS);
    assert_true(log.n > 1000 && log.n < 20000);
    assert_non_null(strstr(log.error, "the gzip data ends early (a truncated .gz"));
    assert_null(strstr(log.warnings, "cut off mid-write"));
    hx_log_free(&log);
    /* cut inside the first block: nothing decompresses; said as a
     * truncated .gz, not as an empty file */
    assert_int_equal(truncate(p, 25), 0);
    rc = hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_true(rc < 0);
    assert_non_null(strstr(err, "the gzip data ends before any of it inflates (a truncated .gz"));
    unlink(p);
    /* a .bin.gz cut short: said as a truncated .gz, not as a recording cut
     * off mid-record or never closed (bytes of the uncompressed data) */
    {
        hx_writer_t *w;
        hx_meta_t m;
        fnav_sample_t s;
        tmp_path(p, sizeof p, ".bin");
        memset(&m, 0, sizeof m);
        m.rate_hz = 100.0;
        memset(&s, 0, sizeof s);
        w = hx_writer_open(p, HX_FMT_BIN, &m, 0, err, sizeof err);
        assert_non_null(w);
        for (k = 0; k < 20000; k++) {
            s.t_ns = (int64_t)k * 10000000;
            s.accel_mps2[0] = (fnav_real_t)(0.01 * (k % 17));
            s.accel_mps2[2] = (fnav_real_t)(9.81 + 0.001 * (k % 29));
            s.gyro_rps[1] = (fnav_real_t)(0.001 * (k % 13));
            assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
        }
        assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
        {
            unsigned char *buf = (unsigned char *)malloc(2000000);
            size_t n;
            char pz[256];
            assert_non_null(buf);
            n = read_file(p, buf, 2000000);
            unlink(p);
            tmp_path(pz, sizeof pz, ".bin.gz");
            gz = gzopen(pz, "wb");
            assert_non_null(gz);
            assert_int_equal(gzwrite(gz, buf, (unsigned)n), (int)n);
            assert_int_equal(gzclose(gz), Z_OK);
            free(buf);
            assert_int_equal(stat(pz, &sb), 0);
            assert_int_equal(truncate(pz, sb.st_size / 2), 0);
            rc = hx_log_load(&log, pz, HX_FMT_AUTO, 0.0, err, sizeof err);
            assert_int_equal(rc, 1);
            assert_int_equal(log.meta.format, HX_FMT_BIN);
            assert_true(log.n > 1000 && log.n < 20000);
            if (strstr(log.error, "the gzip data ends early (a truncated .gz") == NULL) {
                fail_msg("'%s' does not name the truncated .gz", log.error);
            }
            hx_log_free(&log);
            unlink(pz);
        }
    }
}

/* A .bin.gz cut inside its 192-byte header: said as a truncated .gz, as
 * docs/log-format.md ("A truncated .gz") promises, with the bytes of the
 * header it holds, not "too short for a footnav log header (130 of 192
 * bytes)", the message of a plain .bin cut short, which stays. The golden
 * file is stored uncompressed (level 0: a 10-byte gzip
 * header, a 5-byte block header, then the bytes), so that a cut at
 * 15 + 100 bytes leaves exactly 100 bytes of the header. */
static void test_bin_gz_header_cut(void **state)
{
    char p[256], pz[256];
    readall_t r;
    gzFile gz;
    (void)state;
    tmp_path(pz, sizeof pz, ".bin.gz");
    gz = gzopen(pz, "wb0");
    assert_non_null(gz);
    assert_int_equal(gzwrite(gz, g_golden, (unsigned)g_golden_n), (int)g_golden_n);
    assert_int_equal(gzclose(gz), Z_OK);
    assert_int_equal(truncate(pz, 15 + 100), 0);
    assert_int_equal(read_all(pz, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    if (strstr(r.err, pz) == NULL ||
        strstr(r.err, ": the gzip data ends early (a truncated .gz, e.g. an incomplete copy) inside the header "
                      "(100 of 192 bytes)") == NULL) {
        fail_msg("'%s' does not name the truncated .gz", r.err);
    }
    assert_int_equal(read_all(pz, HX_FMT_BIN, 0.0, &r, NULL), -1); /* --from bin: the same */
    assert_non_null(strstr(r.err, "the gzip data ends early"));
    unlink(pz);
    /* a plain .bin cut in its header: unchanged */
    tmp_path(p, sizeof p, ".bin");
    write_file(p, g_golden, 100);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    assert_non_null(strstr(r.err, ": too short for a footnav log header (100 of 192 bytes)"));
    assert_null(strstr(r.err, "gzip"));
    unlink(p);
    /* a whole .bin.gz ending inside the header (a header written, the
     * compressed stream complete): no truncated .gz, the header is short */
    gz = gzopen(pz, "wb");
    assert_non_null(gz);
    assert_int_equal(gzwrite(gz, g_golden, 100), 100);
    assert_int_equal(gzclose(gz), Z_OK);
    assert_int_equal(read_all(pz, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    assert_non_null(strstr(r.err, ": too short for a footnav log header (100 of 192 bytes)"));
    assert_null(strstr(r.err, "gzip"));
    unlink(pz);
}

/* Reads the foreign recording at p to its end: it must be of format fmt,
 * give n samples and end normally with a warning containing warn. */
static void expect_cut(const char *p, hx_format_t fmt, int n, const char *warn)
{
    char err[320];
    hx_reader_t *r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    fnav_sample_t s;
    fnav_status_t st;
    int k = 0;
    assert_non_null(r);
    assert_int_equal(hx_reader_meta(r)->format, fmt);
    while ((st = hx_reader_next(r, &s)) == FNAV_OK) {
        k++;
    }
    assert_int_equal(st, FNAV_END);
    assert_int_equal(k, n);
    assert_non_null(strstr(hx_reader_warnings(r), warn));
    hx_reader_close(r);
}

/* A foreign recording whose last line was cut off mid-write keeps every
 * complete line and warns; our own CSV treats the same as an error. */
static void test_cut_last_line(void **state)
{
    char p[256];
    readall_t ra;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "sample,f_x_mps2,f_y_mps2,f_z_mps2,w_x_radps,w_y_radps,w_z_radps,q0,q1,q2,q3\n"
                  "0,0.1,0.2,-9.8,0.01,0.02,0.03,1,0,0,0\n"
                  "1,0.1,0.2,-9.8,0.01,0.02,0.03,1,0,0,0\n"
                  "2,0.1,0.2,-9.");
    expect_cut(p, HX_FMT_SQUARE2, 2, ":4: last line is incomplete");
    /* an NGIMU line cut inside its last value, which the reader uses: it
     * parses (8.448539 cut to 8), but may be wrong, so it is dropped; with
     * unused columns after the last used one (the square2 quaternion) a
     * line without a newline is whole where it matters and is read */
    write_text(p, "Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s),Accelerometer X (g),"
                  "Accelerometer Y (g),Accelerometer Z (g)\n"
                  "0,0.1,0.2,0.3,-0.49,0.24,0.83\n"
                  "0.0025,0.1,0.2,0.3,-0.49,0.24,0.83\n"
                  "0.005,0.1,0.2,0.3,-0.49,0.24,8");
    expect_cut(p, HX_FMT_NGIMU, 2, ":4: last line has no newline and ends in a value the reader uses");
    /* an MT Manager export cut inside a row */
    write_text(p, "// Update Rate: 100.0Hz\nPacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "1\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n2\t200\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n3\t300\t0.1\t0.");
    expect_cut(p, HX_FMT_MTMGR, 2, ":5: last line is incomplete");
    write_text(p, "sample,f_x_mps2,f_y_mps2,f_z_mps2,w_x_radps,w_y_radps,w_z_radps,q0,q1,q2,q3\n"
                  "0,0.1,0.2,-9.8,0.01,0.02,0.03,1,0,0,0\n"
                  "1,0.1,0.2,-9.8,0.01,0.02,0.03,1,0,0");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 2);
    write_text(p, "t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.01,1,2,3");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 1);
    assert_int_equal(ra.end, FNAV_E_FORMAT);
    /* our CSV with every column but no newline after its last used value:
     * the value may be cut (-0.00245940452 read as -0.0024590001), so the
     * line is dropped with the warning; an unused
     * column after it leaves the used values whole, and the line is read */
    write_text(p, "t,ax,ay,az,gx,gy,gz\n0,1,2,3,4,5,6\n0.01,1,2,3,4,5,6\n0.02,1,2,3,4,5,-0.002459");
    expect_cut(p, HX_FMT_CSV, 2, ":4: last line has no newline and ends in a value the reader uses");
    write_text(p, "t,ax,ay,az,gx,gy,gz,note\n0,1,2,3,4,5,6,a\n0.01,1,2,3,4,5,6,b");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 2);
    assert_int_equal(ra.end, FNAV_END);
    unlink(p);
}

/* Found by fuzzing: counters beyond 32 bits or time beyond int64 ns are
 * format errors, never undefined conversions. */
static void test_counter_ranges(void **state)
{
    char p[256];
    readall_t r;
    (void)state;
    tmp_path(p, sizeof p, ".txt");
    write_text(p, "Inertial data.\nHeader: a_x [g]:\n"
                  "   0xcb   -0.1   +0.15   +0.99   +0.005   -0.012   +0.001     130516848    0x15fd       87782700000 "
                  "1274434048.503018 1274434048.503018 1274434048.507018  250.0   -0.12   -0.01   -0.46\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.n, 0);
    assert_int_equal(r.end, FNAV_E_FORMAT);
    assert_non_null(strstr(r.err, "32-bit"));
    write_text(p, "sample,f_x_mps2,f_y_mps2,f_z_mps2,w_x_radps,w_y_radps,w_z_radps\n"
                  "0,0.1,0.2,-9.8,0.01,0.02,0.03\n1.5,0.1,0.2,-9.8,0.01,0.02,0.03\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.n, 1);
    assert_int_equal(r.end, FNAV_E_FORMAT);
    write_text(p, "t,ax,ay,az,gx,gy,gz\n99999999999.5,1,2,3,4,5,6\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.n, 0);
    assert_int_not_equal(r.end, FNAV_END);
    unlink(p);
}

static void test_bad_rate(void **state)
{
    char err[320];
    (void)state;
    assert_null(hx_reader_open("vectors/logformat/sample_v1.csv", HX_FMT_AUTO, -5.0, err, sizeof err));
    assert_non_null(strstr(err, "sample rate"));
    assert_null(hx_reader_open("/nonexistent/file.csv", HX_FMT_AUTO, 0.0, err, sizeof err));
    assert_non_null(strstr(err, "cannot open"));
}

/* ------------------------------------------------------------ importers */

typedef struct {
    const char *rel;
    hx_format_t fmt;
    long samples;          /* expected count, or -1 */
    double rate_hz;        /* expected rate (nominal or estimated), 1e-3 rel */
    double g_sign_z;       /* +1: z up at rest, -1: z down */
} importer_case_t;

static const importer_case_t k_importers[] = {
    { "openshoe_gx2/Measurement_100521_2_data_inert.txt", HX_FMT_GX2, 16420, 249.756, 1.0 },
    { "openshoe_c_820hz/OpenShoeDataSet.txt", HX_FMT_OS820, 51055, 820.0, 1.0 },
    { "xio_ngimu_gait/short_walk.csv", HX_FMT_NGIMU, 16539, 398.32, 1.0 },
    { "xio_ngimu_gait/long_walk.csv", HX_FMT_NGIMU, -1, 0.0, 1.0 },
    { "pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-22-03_imu.csv", HX_FMT_PYSHOE, 6490, 200.0, -1.0 },
    { "pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_31_imu.csv", HX_FMT_PYSHOE, 8549, 200.04, -1.0 },
    { "ipol_gait_xsens/1-1_lf.txt", HX_FMT_IPOL, 2913, 100.0, 1.0 },
    { "openshoe_square2/square2_u.csv", HX_FMT_SQUARE2, 8687, 100.0, -1.0 },
};

/* Detection, counts, rates and at-rest gravity (first 0.5 s) of every format. */
static void test_importers(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof k_importers / sizeof k_importers[0]; i++) {
        const importer_case_t *c = &k_importers[i];
        char p[512], err[320];
        hx_log_t log;
        double f[3] = { 0, 0, 0 }, g;
        size_t k, m;
        if (fnav_testdata_path(c->rel, p, sizeof p) != 0) {
            fnav_test_skip_notice(c->rel);
            continue;
        }
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        if (log.meta.format != c->fmt) {
            fail_msg("%s detected as %s", c->rel, hx_format_name(log.meta.format));
        }
        if (c->samples >= 0) {
            assert_int_equal((long)log.n, c->samples);
        }
        if (c->rate_hz > 0.0) {
            FNAV_ASSERT_CLOSE(log.meta.rate_hz, c->rate_hz, 0.0, 1e-3);
        }
        m = (size_t)(0.5 * log.meta.rate_hz);
        for (k = 0; k < m; k++) {
            f[0] += log.acc[k][0] / (double)m;
            f[1] += log.acc[k][1] / (double)m;
            f[2] += log.acc[k][2] / (double)m;
        }
        g = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        /* units: the specific force at rest is one g (loose: sensors are
         * tilted, biased and some move slightly in the first half second) */
        FNAV_ASSERT_CLOSE(g, 9.81, 0.6, 0.0);
        assert_true(f[2] * c->g_sign_z > 4.0);
        for (k = 1; k < log.n; k++) {
            assert_true(log.t_ns[k] >= log.t_ns[k - 1]);
        }
        hx_log_free(&log);
    }
}

/* Unit conversions of the first rows, checked against the raw text. */
static void test_importer_units(void **state)
{
    char p[512], err[320];
    hx_log_t log;
    const double d2r = 3.14159265358979323846 / 180.0;
    (void)state;
    if (fnav_testdata_path("xio_ngimu_gait/short_walk.csv", p, sizeof p) == 0) {
        /* 0,-0.1428319,-0.7708032,-0.2320606,-0.4937814,0.2420433,0.8312204 */
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        FNAV_ASSERT_CLOSE(log.gyr[0][0], -0.1428319 * d2r, 0.0, 1e-7);
        FNAV_ASSERT_CLOSE(log.gyr[0][2], -0.2320606 * d2r, 0.0, 1e-7);
        FNAV_ASSERT_CLOSE(log.acc[0][0], -0.4937814 * 9.80665, 0.0, 1e-7);
        FNAV_ASSERT_CLOSE(log.acc[0][2], 0.8312204 * 9.80665, 0.0, 1e-7);
        assert_true(log.t_ns[1] == 7531643);
        {
            /* MANIFEST: 205 exact duplicates (dt = 0) in the short walk */
            size_t k;
            long dups = 0;
            for (k = 1; k < log.n; k++) {
                dups += log.t_ns[k] == log.t_ns[k - 1];
            }
            assert_int_equal(dups, 205);
        }
        hx_log_free(&log);
    } else {
        fnav_test_skip_notice("xio_ngimu_gait/short_walk.csv");
    }
    if (fnav_testdata_path("openshoe_gx2/Measurement_100521_2_data_inert.txt", p, sizeof p) == 0) {
        /* first data row: a = (-0.10581776, +0.15830289, +0.99007481) g,
         * w = (+0.00535047, -0.01242570, +0.00101861) rad/s, Nr 1 */
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        FNAV_ASSERT_CLOSE(log.acc[0][0], -0.10581776 * 9.80665, 0.0, 1e-7);
        FNAV_ASSERT_CLOSE(log.acc[0][2], 0.99007481 * 9.80665, 0.0, 1e-7);
        FNAV_ASSERT_CLOSE(log.gyr[0][1], -0.01242570, 0.0, 1e-7);
        assert_int_equal(log.seq[0], 1);
        assert_int_equal(log.seq[log.n - 1], log.n);
        /* the sensor timer's period: 78720 ticks of 19.6608 MHz */
        FNAV_ASSERT_CLOSE(1e-9 * (double)(log.t_ns[100] - log.t_ns[99]), 78720.0 / 19660800.0, 2e-6, 0.0);
        hx_log_free(&log);
    } else {
        fnav_test_skip_notice("openshoe_gx2");
    }
    if (fnav_testdata_path("ipol_gait_xsens/1-1_lf.txt", p, sizeof p) == 0) {
        size_t k;
        long drops = 0;
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        FNAV_ASSERT_CLOSE(log.acc[0][0], 5.090554, 0.0, 1e-7);
        FNAV_ASSERT_CLOSE(log.gyr[0][2], -0.017776, 0.0, 1e-6);
        for (k = 1; k < log.n; k++) {
            drops += (long)(log.seq[k] - log.seq[k - 1]) - 1;
            assert_true(log.t_ns[k] - log.t_ns[k - 1] == 10000000LL * (int64_t)(log.seq[k] - log.seq[k - 1]));
        }
        assert_true(drops > 0); /* the MANIFEST: packet counter jumps */
        hx_log_free(&log);
    } else {
        fnav_test_skip_notice("ipol_gait_xsens");
    }
    if (fnav_testdata_path("adis16405_static/adis16405_imu1_100Hz.csv.gz", p, sizeof p) == 0) {
        /* gzip, deg/s and g, no time stamps: first row -0.05,-0.3,0.7,-0.00666,0,-1.01565 */
        hx_reader_t *r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
        fnav_sample_t s;
        assert_non_null(r);
        assert_int_equal(hx_reader_meta(r)->format, HX_FMT_ADIS);
        assert_int_equal(hx_reader_next(r, &s), FNAV_OK);
        FNAV_ASSERT_CLOSE(s.gyro_rps[0], -0.05 * d2r, 0.0, 1e-6);
        FNAV_ASSERT_CLOSE(s.accel_mps2[2], -1.01565 * 9.80665, 0.0, 1e-6);
        assert_int_equal(hx_reader_next(r, &s), FNAV_OK);
        assert_true(s.t_ns == 10000000);
        hx_reader_close(r);
    } else {
        fnav_test_skip_notice("adis16405_static");
    }
}

/* Every axis of the first sample of each walk, against its first data row
 * as the file has it (columns found by name with Python's csv module;
 * units and scale factors from ../shared/data/MANIFEST.md: g x 9.80665,
 * deg/s x pi/180, the SI sets as they are). test_importer_units checks two
 * axes of some formats and test_importers only gravity's size and z sign:
 * hand-made mutants swapping the gyro's x and y columns of the pyshoe,
 * ipol and OpenShoe 820 Hz importers passed every suite. */
static void test_importer_first_rows(void **state)
{
    static const double g0 = 9.80665, d2r = 3.14159265358979323846 / 180.0;
    static const struct {
        const char *rel;
        hx_format_t fmt;
        double acc[3], acc_scale, gyr[3], gyr_scale;
    } k_rows[] = {
        /* t_s 0.000000: ax_mps2..gz_radps */
        { "pyshoe_vicon_llio/own_3dmgx5_footprints/SensorConnectData_31_imu.csv", HX_FMT_PYSHOE,
          { 5.689716, 1.564783, -7.854842 }, 1.0, { 0.003722398, -0.002670883, 0.0052455 }, 1.0 },
        /* sample 0: f_x_mps2..w_z_radps (the quaternion after them unused) */
        { "openshoe_square2/square2_u.csv", HX_FMT_SQUARE2, { -0.073840446, -0.000314401199, -9.81912955 }, 1.0,
          { 0.00148909, -0.00189885, -0.00106122 }, 1.0 },
        /* PacketCounter 0.0: Acc_X..Gyr_Z (the magnetometer after them unused) */
        { "ipol_gait_xsens/1-1_lf.txt", HX_FMT_IPOL, { 5.090554, 0.409101, 8.923938 }, 1.0,
          { -0.002503, 0.008869, -0.017776 }, 1.0 },
        /* line 1, no header: f_x f_y f_z [m/s^2], w_x w_y w_z [rad/s] */
        { "openshoe_c_820hz/OpenShoeDataSet.txt", HX_FMT_OS820, { 0.19594386, -0.42454505, 9.86250782 }, 1.0,
          { -0.00349064, -0.01745320, -0.02443448 }, 1.0 },
        /* Time (s) 0: the gyroscope (deg/s) first, then the accelerometer (g) */
        { "xio_ngimu_gait/short_walk.csv", HX_FMT_NGIMU, { -0.4937814, 0.2420433, 0.8312204 }, g0,
          { -0.1428319, -0.7708032, -0.2320606 }, d2r },
        /* Nr 1: a_x a_y a_z [g], ar_x ar_y ar_z [rad/s] */
        { "openshoe_gx2/Measurement_100521_2_data_inert.txt", HX_FMT_GX2, { -0.10581776, 0.15830289, 0.99007481 },
          g0, { 0.00535047, -0.01242570, 0.00101861 }, 1.0 },
    };
    size_t i;
    int k;
    (void)state;
    for (i = 0; i < sizeof k_rows / sizeof k_rows[0]; i++) {
        char p[512], err[320];
        hx_log_t log;
        if (fnav_testdata_path(k_rows[i].rel, p, sizeof p) != 0) {
            fnav_test_skip_notice(k_rows[i].rel);
            continue;
        }
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.meta.format, k_rows[i].fmt);
        for (k = 0; k < 3; k++) {
            /* float32 samples: 1e-7 relative */
            FNAV_ASSERT_CLOSE(log.acc[0][k], k_rows[i].acc[k] * k_rows[i].acc_scale, 1e-12, 1e-7);
            FNAV_ASSERT_CLOSE(log.gyr[0][k], k_rows[i].gyr[k] * k_rows[i].gyr_scale, 1e-12, 1e-7);
        }
        hx_log_free(&log);
    }
}

/* The OpenShoe GX2 logger's preamble and header line, as its files have them. */
static void write_gx2_header(FILE *f)
{
    fprintf(f, "\r\nInertial data.\r\n\r\nHeader:      a_x [g]:      a_y [g]:      a_z [g]: ar_x [rad/s]: ar_y [rad/s]: "
               "ar_z [rad/s]:      Counter: Checksum:     Nr:   Filtered ts[s]: Unfiltered ts[s]:      Pred. ts[s]: "
               "Freq. [Hz]:      m_x [G]:      m_y [G]:      m_z [G]:\r\n");
}

/* A new GX2 file (its name ends as the data set's do) with the header written. */
static FILE *open_gx2(char *p, size_t size)
{
    FILE *f;
    tmp_path(p, size, "_data_inert.txt");
    f = fopen(p, "w");
    assert_non_null(f);
    write_gx2_header(f);
    return f;
}

/* One GX2 record: sensor timer, packet number, host stamps (filtered and
 * unfiltered host, predicted), the logger's rate estimate. */
static void write_gx2_record(FILE *f, unsigned long counter, long nr, double host, double pred, const char *freq)
{
    fprintf(f, "   0xcb   -0.10581776   +0.15830289   +0.99007481   +0.00535047   -0.01242570   +0.00101861     %lu    0x15fd       %ld %.6f %.6f %.6f  %s   -0.12299968   -0.01066045   -0.46057537 \r\n",
            counter, nr, host, host, pred, freq);
}

/* GX2 time across lost packets: Nr jumps by k, the sensor timer by k
 * periods, and the interval must be k periods, also when the timer restarts
 * across the loss (bridged with k periods, not one). A written file in the
 * format of openshoe_gx2: Nr 1-10, 14-20 (11-13 lost, timer running), 21,
 * 23-25 (22 lost and the timer restarted between 21 and 23). */
static void test_gx2_lost_packets(void **state)
{
    const long period = 78720;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr, counter = 130516848;
    size_t k;
    (void)state;
    f = open_gx2(p, sizeof p);
    for (nr = 1; nr <= 25; nr++) {
        if (nr > 1) {
            counter += period;
        }
        if (nr == 23) {
            counter = 1000; /* the logger restarted the sensor timer */
        }
        if ((nr >= 11 && nr <= 13) || nr == 22) {
            continue; /* lost */
        }
        write_gx2_record(f, (unsigned long)counter, nr, 1274434048.5 + 0.004 * (double)nr,
                         1274434048.504 + 0.004 * (double)nr, "250.000001");
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_GX2);
    assert_int_equal(log.n, 21);
    for (k = 1; k < log.n; k++) {
        const int64_t want = (int64_t)(log.seq[k] - log.seq[k - 1]) * period * 1000000000LL / 19660800LL;
        assert_true(llabs(log.t_ns[k] - log.t_ns[k - 1] - want) <= 1);
    }
    hx_log_free(&log);
    remove(p);
}

/* GX2 rows against the header's count: the packet id and the 16 fields the
 * Header: line names, 17. A row that lost a field (a stamp: the rate
 * estimate then read from m_x) or gained one (a stray blank splitting a
 * number) shifts the values after it (one in the columns the samples are
 * read from mostly stops the reader: a counter read as a_z); such rows
 * must not be read without a word. Counted and warned as in the other
 * formats; a clean file and a cut last line have none. */
static void test_gx2_field_count(void **state)
{
    const long period = 78720;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr, counter = 130516848;
    int pass;
    (void)state;
    for (pass = 0; pass < 3; pass++) {
        f = open_gx2(p, sizeof p);
        for (nr = 1; nr <= 30; nr++, counter += period) {
            const double host = 1274434048.5 + 0.004 * (double)nr;
            if (pass == 1 && (nr == 7 || nr == 9)) {
                fprintf(f, "   0xcb   -0.10581776   +0.15830289   +0.99007481   +0.00535047   -0.01242570   +0.00101861     %ld    0x15fd       %ld %.6f %.6f  250.000001   -0.12299968   -0.01066045   -0.46057537 \r\n",
                        counter, nr, host, host + 0.004); /* a stamp lost: Freq. read from m_x */
            } else if (pass == 2 && nr == 12) {
                fprintf(f, "   0xcb   -0.10581776   +0.15830289   +0.99007481   +0.00535047   -0.01242570   +0.00101861     %ld    0x15fd       %ld %.6f %.6f %.6f  250.000001   -0.12 299968   -0.01066045   -0.46057537 \r\n",
                        counter, nr, host, host, host + 0.004); /* a stray blank */
            } else {
                write_gx2_record(f, (unsigned long)counter, nr, host, host + 0.004, "250.000001");
            }
        }
        fprintf(f, "   0xcb   -0.10581776   +0.15830289   +0.99007481   +0.00535047   -0.01242570   +0.00101861     %ld    0x15fd       31 1274434048.624000", counter); /* cut */
        assert_int_equal(fclose(f), 0);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.meta.format, HX_FMT_GX2);
        if (pass == 1) {
            assert_non_null(strstr(log.warnings, "_data_inert.txt:11: 2 rows with fewer fields than the header's 17"));
        } else {
            assert_null(strstr(log.warnings, "fewer fields"));
        }
        if (pass == 2) {
            assert_non_null(strstr(log.warnings, "_data_inert.txt:16: 1 row with more fields than the header's 17"));
        } else {
            assert_null(strstr(log.warnings, "more fields"));
        }
        hx_log_free(&log);
        remove(p);
    }
}

/* GX2: the timer-restart note is kept when the log then stops at a bad
 * line (the samples before it were bridged all the same); added only at a
 * clean end, it would be lost from a log cut by an error. */
static void test_gx2_restart_then_error(void **state)
{
    const long period = 78720;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr, counter = 130516848;
    (void)state;
    f = open_gx2(p, sizeof p);
    for (nr = 1; nr <= 10; nr++) {
        counter = nr == 6 ? 1000 : counter + period; /* restarted at 6 */
        write_gx2_record(f, (unsigned long)counter, nr, 1274434048.5 + 0.004 * (double)nr,
                         1274434048.504 + 0.004 * (double)nr, "250.000001");
    }
    fputs("   0xcb   garbage\r\n", f);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1); /* samples, then an error */
    assert_int_equal(log.n, 10);
    assert_true(log.status != FNAV_END);
    /* a note, not a warning (routine for the GX2), and the
     * count in words: "once", not "1 time" */
    {
        char want[512];
        snprintf(want, sizeof want,
                 "note: %s: the sensor's timer restarted once (normal for the 3DM-GX2, about once a second); each "
                 "restart bridged with the measured period (docs/log-format.md, GX2 time)",
                 p);
        assert_string_equal(log.warnings, want);
    }
    hx_log_free(&log);
    remove(p);
}

/* GX2: a timer restart on the file's first interval, before any period was
 * measured, is bridged with the logger's own rate (Freq. [Hz], here 249.8)
 * instead of the host stamps, which jitter to 25 ms (here 31.5 ms: bridged
 * with that, the interval would be a false 31.5 ms gap). */
static void test_gx2_first_restart(void **state)
{
    const long period = 78720;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr, counter = 130831728;
    (void)state;
    f = open_gx2(p, sizeof p);
    for (nr = 1; nr <= 10; nr++) {
        const double host = 1274434048.5 + (nr == 1 ? 0.0 : 0.0315 + 0.004 * (double)(nr - 2));
        if (nr == 2) {
            counter = 6068; /* restarted */
        } else if (nr > 2) {
            counter += period;
        }
        write_gx2_record(f, (unsigned long)counter, nr, host, host + 0.004, "249.800000");
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_GX2);
    assert_int_equal(log.n, 10);
    assert_true(llabs(log.t_ns[1] - log.t_ns[0] - (int64_t)llround(1e9 / 249.8)) <= 60); /* a tick: 51 ns */
    assert_true(llabs(log.t_ns[2] - log.t_ns[1] - period * 1000000000LL / 19660800LL) <= 1);
    hx_log_free(&log);
    remove(p);
}

/* GX2: a packet written twice (same Nr, same timer value) is a duplicate,
 * dt = 0, as in every other format; bridged as a timer restart, one period
 * later, it would be hidden and every later sample shifted by a period. */
static void test_gx2_repeated_packet(void **state)
{
    const long period = 78720;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr, counter = 130516848;
    size_t k;
    (void)state;
    f = open_gx2(p, sizeof p);
    for (nr = 1; nr <= 10; nr++) {
        int rep;
        for (rep = 0; rep < (nr == 5 ? 2 : 1); rep++) {
            write_gx2_record(f, (unsigned long)counter, nr, 1274434048.5 + 0.004 * (double)nr,
                             1274434048.504 + 0.004 * (double)nr, "250.000001");
        }
        counter += period;
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_GX2);
    assert_int_equal(log.n, 11);
    assert_true(log.t_ns[5] == log.t_ns[4]); /* the repeat */
    for (k = 0; k < log.n; k++) {
        const int64_t want = (int64_t)(log.seq[k] - 1u) * period * 1000000000LL / 19660800LL;
        assert_true(log.t_ns[k] == want);
    }
    assert_null(strstr(log.warnings, "restarted"));
    assert_null(strstr(log.warnings, "does not advance"));
    hx_log_free(&log);
    remove(p);
    /* Nr going back (rows out of order, a restarted count) with new timer
     * values: read as one period on each, as before, and said (it went
     * unsaid) */
    f = open_gx2(p, sizeof p);
    counter = 130516848;
    for (k = 0; k < 10; k++) {
        nr = (k == 6) ? 3 : (long)k + 1;
        write_gx2_record(f, (unsigned long)counter, nr, 1274434048.5 + 0.004 * (double)k,
                         1274434048.504 + 0.004 * (double)k, "250.000001");
        counter += period;
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.n, 10);
    if (strstr(log.warnings, "the packet number Nr does not advance at 1 packet (the first here), not a repeat") ==
        NULL) {
        fail_msg("Nr going back not said: '%s'", log.warnings);
    }
    hx_log_free(&log);
    remove(p);
    /* two rows swapped (Nr 1-4, 6, 5, 7-10, each with its own timer value):
     * 6 looks like a jump of two (one period inserted, unknowable until 5
     * comes), 5 is read one period on, and 7 is counted from 6, the
     * highest, one period on; counted from 5 it was a second jump of two,
     * a second inserted period (two gaps where the log has none). The
     * swapped row is no timer restart. */
    f = open_gx2(p, sizeof p);
    for (k = 0; k < 10; k++) {
        nr = (k == 4) ? 6 : (k == 5) ? 5 : (long)k + 1;
        write_gx2_record(f, (unsigned long)(130516848 + (nr - 1) * period), nr, 1274434048.5 + 0.004 * (double)k,
                         1274434048.504 + 0.004 * (double)k, "250.000001");
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.n, 10);
    for (k = 1; k < log.n; k++) {
        const int64_t dt = log.t_ns[k] - log.t_ns[k - 1], one = period * 1000000000LL / 19660800LL;
        assert_true(llabs(dt - (k == 4 ? 2 : 1) * one) <= 1);
    }
    assert_non_null(strstr(log.warnings, "does not advance at 1 packet"));
    if (strstr(log.warnings, "timer restarted") != NULL) {
        fail_msg("a swapped row taken for a timer restart: '%s'", log.warnings);
    }
    hx_log_free(&log);
    remove(p);
}

/* GX2: a tick difference within half of the last good period is taken as
 * it is, a larger one is a restart bridged with that period
 * (docs/log-format.md, "GX2 time"). Intervals of 1.45 and 1.55 periods,
 * Nr stepping by one: the first is kept (and becomes the period the next
 * one, of one period, is compared with), the second bridged. A mutant
 * allowing an eighth instead of a half passed every suite (the six real
 * files vary by 0.3 %). */
static void test_gx2_restart_tolerance(void **state)
{
    const long p = 78720;
    static const double k_step[9] = { 1, 1, 1, 1, 1.45, 1, 1, 1.55, 1 };
    hx_log_t log;
    char err[320], path[256];
    FILE *f;
    long nr, counter = 130516848, ticks = 0;
    (void)state;
    f = open_gx2(path, sizeof path);
    for (nr = 1; nr <= 10; nr++) {
        if (nr > 1) {
            counter += (long)(k_step[nr - 2] * (double)p + 0.5);
        }
        write_gx2_record(f, (unsigned long)counter, nr, 1274434048.5 + 0.004 * (double)nr,
                         1274434048.504 + 0.004 * (double)nr, "250.000001");
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, path, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.n, 10);
    for (nr = 2; nr <= 10; nr++) {
        /* 114144 ticks kept; 122016 bridged with 78720 */
        ticks += nr == 9 ? p : (long)(k_step[nr - 2] * (double)p + 0.5);
        assert_true(log.t_ns[nr - 1] == (int64_t)ticks * 1000000000LL / 19660800LL);
    }
    assert_non_null(strstr(log.warnings, ": the sensor's timer restarted once (normal for the 3DM-GX2"));
    assert_true(strncmp(log.warnings, "note: ", 6) == 0);
    hx_log_free(&log);
    remove(path);
}

/* GX2: a timer restart on the first interval across lost packets (Nr 1 to
 * 4, two lost) is bridged with three periods of the logger's rate
 * (Freq. [Hz] 250: 12 ms), as a restart across a loss later on is bridged
 * with k measured periods. A mutant bridging one period (4 ms) passed every
 * suite. */
static void test_gx2_first_restart_lost(void **state)
{
    const long period = 78720;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr, counter = 130831728;
    (void)state;
    f = open_gx2(p, sizeof p);
    for (nr = 1; nr <= 10; nr++) {
        const double host = 1274434048.5 + 0.004 * (double)nr;
        if (nr == 2 || nr == 3) {
            continue; /* lost */
        }
        if (nr == 4) {
            counter = 6068; /* restarted */
        } else if (nr > 4) {
            counter += period;
        }
        write_gx2_record(f, (unsigned long)counter, nr, host, host + 0.004, "250.000000");
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.n, 8);
    assert_int_equal(log.seq[1], 4);
    assert_true(llabs(log.t_ns[1] - log.t_ns[0] - 12000000LL) <= 60); /* a tick: 51 ns */
    assert_true(llabs(log.t_ns[2] - log.t_ns[1] - period * 1000000000LL / 19660800LL) <= 1);
    hx_log_free(&log);
    remove(p);
}

/* GX2: without a Freq. value (lines that end after the Pred. ts column), a
 * timer restart on the first interval is bridged with the interval of the
 * filtered host stamps (column 10, 6 ms here), not the unfiltered ones
 * (column 11, 9 ms) nor the predicted ones (column 12, 5 ms): the logger's
 * filter takes out most of the USB jitter (docs/log-format.md, "GX2 time"). */
static void test_gx2_first_restart_host_column(void **state)
{
    const long period = 78720;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr, counter = 130831728;
    (void)state;
    f = open_gx2(p, sizeof p);
    for (nr = 1; nr <= 6; nr++) {
        const double k = (double)(nr - 1);
        if (nr == 2) {
            counter = 6068; /* restarted */
        } else if (nr > 2) {
            counter += period;
        }
        fprintf(f, "   0xcb   -0.10581776   +0.15830289   +0.99007481   +0.00535047   -0.01242570   +0.00101861     %lu    0x15fd       %ld %.6f %.6f %.6f\r\n",
                (unsigned long)counter, nr, 1274434048.5 + 0.006 * k, 1274434048.5 + 0.009 * k,
                1274434048.504 + 0.005 * k);
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_GX2);
    assert_int_equal(log.n, 6);
    /* the stamps are written to 1 us, and a double holds them to 0.24 us */
    assert_true(llabs(log.t_ns[1] - log.t_ns[0] - 6000000LL) <= 1000);
    assert_true(llabs(log.t_ns[2] - log.t_ns[1] - period * 1000000000LL / 19660800LL) <= 1);
    hx_log_free(&log);
    remove(p);
}

/* GX2: a last line without a newline, cut inside field 12 (the unfiltered
 * host stamp, which the reader does not use), leaves every value the reader
 * takes whole and is read, as docs/log-format.md ("Recordings cut off
 * mid-write") says; one cut inside field 11 (the filtered host stamp, which
 * it takes) is dropped with the warning. A reader requiring twelve fields
 * would drop the first kind too, as "ends in a value the reader uses" (a
 * hand-made mutant of that count passes every other suite: no other test
 * has a 12-field last line; none of the six files has one, walks 31 and 32
 * end inside fields 10 and 7). */
static void test_gx2_cut_last_line(void **state)
{
    const long period = 78720;
    static const char *const k_cut[2] = { "1274434048.54", "1274434048.54 127443" };
    char p[256];
    int c;
    (void)state;
    for (c = 0; c < 2; c++) {
        FILE *f = open_gx2(p, sizeof p);
        long nr, counter = 130516848;
        for (nr = 1; nr <= 3; nr++) {
            write_gx2_record(f, (unsigned long)counter, nr, 1274434048.5 + 0.004 * (double)nr,
                             1274434048.504 + 0.004 * (double)nr, "250.000001");
            counter += period;
        }
        fprintf(f, "   0xcb   -0.10581776   +0.15830289   +0.99007481   +0.00535047   -0.01242570   +0.00101861     "
                   "%ld    0x15fd       4 %s", counter, k_cut[c]);
        assert_int_equal(fclose(f), 0);
        if (c == 0) {
            expect_cut(p, HX_FMT_GX2, 3, ":8: last line"); /* 4 preamble lines, 3 records */
        } else {
            char err[320];
            hx_log_t log;
            assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
            assert_int_equal(log.n, 4);
            assert_int_equal(log.seq[3], 4);
            assert_true(log.t_ns[3] == 3LL * period * 1000000000LL / 19660800LL);
            assert_int_equal(log.stats.cut_lines, 0);
            assert_null(strstr(log.warnings, "last line"));
            hx_log_free(&log);
        }
        remove(p);
    }
}

/* GX2 timer cases of docs/log-format.md ("GX2 time") that no test had; a
 * hand-made mutant of each passed every suite:
 * - the first interval's timer jumps 1e8 ticks (5 s) on, "an unrelated
 *   base": bridged with the logger's rate (Freq. 250 Hz, 4 ms), not taken
 *   (a mutant without the 0.1 s bound took it);
 * - Nr jumps from 5 to 5000 with the timer one period on: a jump beyond
 *   1000 is a restart of the count, one period (a mutant without the bound
 *   bridged 4995 periods, 19.5 s);
 * - the timer repeats with Nr one on: not the same packet written twice,
 *   so a restart bridged with a period, not a duplicate (a mutant comparing
 *   the timer alone made it dt = 0);
 * - --input-rate on this time-stamped format is ignored with a warning (a
 *   mutant left GX2 out of the warning). */
static void test_gx2_timer_cases(void **state)
{
    const long p = 78720;
    static const long k_nr[8] = { 1, 2, 3, 4, 5, 5000, 5001, 5002 };
    /* ticks after the previous record; -1: the timer repeats */
    static const long k_step[8] = { 0, 100000000, 78720, 78720, 78720, 78720, -1, 78720 };
    /* the interval the reader must give, in ticks: 4 ms at 250 Hz is
     * (int64)(0.004 x 19660800 + 0.5) = 78643 */
    static const long k_dt[8] = { 0, 78643, 78720, 78720, 78720, 78720, 78720, 78720 };
    hx_log_t log;
    char err[320], path[256];
    FILE *f;
    long counter = 1000, ticks = 0;
    int i;
    (void)state;
    f = open_gx2(path, sizeof path);
    for (i = 0; i < 8; i++) {
        counter += k_step[i] < 0 ? 0 : k_step[i];
        write_gx2_record(f, (unsigned long)counter, k_nr[i], 1274434048.5 + 0.004 * (double)i,
                         1274434048.504 + 0.004 * (double)i, "250.000000");
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, path, HX_FMT_AUTO, 100.0, err, sizeof err), 0);
    assert_int_equal(log.n, 8);
    for (i = 1; i < 8; i++) {
        ticks += k_dt[i];
        assert_true(log.t_ns[i] == (int64_t)ticks * 1000000000LL / 19660800LL);
        assert_int_equal(log.seq[i], k_nr[i]);
    }
    assert_true(p == k_dt[2]);
    assert_non_null(strstr(log.warnings, ": the sensor's timer restarted 2 times (normal for the 3DM-GX2"));
    assert_non_null(strstr(log.warnings, "--input-rate ignored: the gx2 format has time stamps"));
    hx_log_free(&log);
    remove(path);
}

/* GX2 time past 469 s: ticks x 1e9 overflowed int64 there (19.6608 MHz), and
 * a longer log stopped with "time goes backwards". 9,600 samples 50 ms
 * apart (983,040 ticks; the 32-bit timer wraps twice, bridged with the
 * period) end at 479.95 s exactly. */
static void test_gx2_long(void **state)
{
    const long period = 983040;
    hx_log_t log;
    char err[320], p[256];
    FILE *f;
    long nr;
    unsigned long counter = 1000;
    (void)state;
    f = open_gx2(p, sizeof p);
    for (nr = 1; nr <= 9600; nr++) {
        const double host = 1274434048.5 + 0.05 * (double)nr;
        write_gx2_record(f, counter, nr, host, host + 0.05, "20.000000");
        counter = (counter + (unsigned long)period) & 0xFFFFFFFFUL;
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_GX2);
    assert_int_equal(log.n, 9600);
    assert_true(log.t_ns[log.n - 1] == 9599LL * 50000000LL);
    hx_log_free(&log);
    remove(p);
}

/* Format detection by the names a header holds, not its first bytes: the
 * shared data sets' headers with ", " between names, quotes, another
 * column order, a leading index column, a blank first line, and the ipol
 * first line in another case all read as their format, with the same
 * first sample. */
static void test_detect_variants(void **state)
{
    static const struct {
        const char *text;
        hx_format_t fmt;
        double ax, gz; /* first sample, SI */
    } cases[] = {
        { "Time (s), Gyroscope X (deg/s), Gyroscope Y (deg/s), Gyroscope Z (deg/s), Accelerometer X (g), "
          "Accelerometer Y (g), Accelerometer Z (g)\n0,1,2,3,0.5,0.25,1\n0.0025,1,2,3,0.5,0.25,1\n",
          HX_FMT_NGIMU, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
        { "\"Time (s)\",\"Accelerometer X (g)\",\"Accelerometer Y (g)\",\"Accelerometer Z (g)\",\"Gyroscope X (deg/s)\","
          "\"Gyroscope Y (deg/s)\",\"Gyroscope Z (deg/s)\"\n0,0.5,0.25,1,1,2,3\n0.0025,0.5,0.25,1,1,2,3\n",
          HX_FMT_NGIMU, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
        { ",t_s,ax_mps2,ay_mps2,az_mps2,gx_radps,gy_radps,gz_radps\n0,0,0.5,0.2,-9.8,0.1,0.2,0.3\n"
          "1,0.005,0.5,0.2,-9.8,0.1,0.2,0.3\n",
          HX_FMT_PYSHOE, 0.5, 0.3 },
        /* Excel's separator line before an importer's header (a re-save) */
        { "\"sep=,\"\r\nTime (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s),Accelerometer X (g),"
          "Accelerometer Y (g),Accelerometer Z (g)\r\n0,1,2,3,0.5,0.25,1\r\n0.0025,1,2,3,0.5,0.25,1\r\n",
          HX_FMT_NGIMU, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
        { "sep=;\nt_s;ax_mps2;ay_mps2;az_mps2;gx_radps;gy_radps;gz_radps\n0;0.5;0.2;-9.8;0.1;0.2;0.3\n"
          "0.005;0.5;0.2;-9.8;0.1;0.2;0.3\n",
          HX_FMT_PYSHOE, 0.5, 0.3 },
        { "\n\nsample,w_x_radps,w_y_radps,w_z_radps,f_x_mps2,f_y_mps2,f_z_mps2\n0,0.1,0.2,0.3,0.5,0.2,-9.8\n"
          "1,0.1,0.2,0.3,0.5,0.2,-9.8\n",
          HX_FMT_SQUARE2, 0.5, 0.3 },
        { "acc_x_g, acc_y_g, acc_z_g, gyro_x_dps, gyro_y_dps, gyro_z_dps\n0.5,0,-1,1,2,3\n0.5,0,-1,1,2,3\n",
          HX_FMT_ADIS, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
        { " ACQUISITION FREQUENCY : 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
          "0.0\t0.5\t0.2\t9.8\t0.1\t0.2\t0.3\n1.0\t0.5\t0.2\t9.8\t0.1\t0.2\t0.3\n",
          HX_FMT_IPOL, 0.5, 0.3 },
        { ",t,ax,ay,az,gx,gy,gz\n0,0,0.5,0.2,9.8,0.1,0.2,0.3\n1,0.01,0.5,0.2,9.8,0.1,0.2,0.3\n", HX_FMT_CSV, 0.5, 0.3 },
        /* a tab-separated export, a name without its space: found as detection finds them */
        { "Time(s)\tGyroscope X (deg/s)\tGyroscope Y (deg/s)\tGyroscope Z (deg/s)\tAccelerometer X (g)\t"
          "Accelerometer Y (g)\tAccelerometer Z (g)\n0\t1\t2\t3\t0.5\t0.25\t1\n0.0025\t1\t2\t3\t0.5\t0.25\t1\n",
          HX_FMT_NGIMU, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
        /* numpy's savetxt: the header behind "# " */
        { "# t,ax,ay,az,gx,gy,gz\n0,0.5,0.2,9.8,0.1,0.2,0.3\n0.01,0.5,0.2,9.8,0.1,0.2,0.3\n", HX_FMT_CSV, 0.5, 0.3 },
        /* comment lines before the header and between samples are skipped */
        { "# made by a script\n#\nt,ax,ay,az,gx,gy,gz\n0,0.5,0.2,9.8,0.1,0.2,0.3\n  # a note\n"
          "0.01,0.5,0.2,9.8,0.1,0.2,0.3\n",
          HX_FMT_CSV, 0.5, 0.3 },
        /* the headerless OpenShoe 820 Hz file with a trailing comma, tabs,
         * semicolons, or blanks and exponents (MATLAB's save -ascii): not
         * only exactly five commas, the others failing with "header has no
         * column 't'" */
        { "0.5,-0.4,9.8,0.1,0.2,0.3,\r\n0.5,-0.4,9.8,0.1,0.2,0.3,\r\n", HX_FMT_OS820, 0.5, 0.3 },
        { "0.5\t-0.4\t9.8\t0.1\t0.2\t0.3\n0.5\t-0.4\t9.8\t0.1\t0.2\t0.3\n", HX_FMT_OS820, 0.5, 0.3 },
        { "0.5;-0.4;9.8;0.1;0.2;0.3\n0.5;-0.4;9.8;0.1;0.2;0.3\n", HX_FMT_OS820, 0.5, 0.3 },
        { "   5.0000000e-01  -4.0000000e-01   9.8000000e+00   1.0000000e-01   2.0000000e-01   3.0000000e-01\n"
          "   5.0000000e-01  -4.0000000e-01   9.8000000e+00   1.0000000e-01   2.0000000e-01   3.0000000e-01\n",
          HX_FMT_OS820, 0.5, 0.3 },
        /* ipol: a blank line before the first, and a comma-separated export
         * (not "FILE:1: expected 'Acquisition frequency'", "header has no
         * column 'PacketCounter'") */
        { "\nAcquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
          "0.0\t0.5\t0.2\t9.8\t0.1\t0.2\t0.3\n1.0\t0.5\t0.2\t9.8\t0.1\t0.2\t0.3\n",
          HX_FMT_IPOL, 0.5, 0.3 },
        { "Acquisition frequency: 100 Hz\nPacketCounter,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z\n"
          "0.0,0.5,0.2,9.8,0.1,0.2,0.3\n1.0,0.5,0.2,9.8,0.1,0.2,0.3\n",
          HX_FMT_IPOL, 0.5, 0.3 },
        /* the interchange format that mentions a GX2 in a comment, or keeps a
         * foreign format's columns beside its own: ours (not read as gx2,
         * "no 'Header:' line found", and adis, "header has no column
         * 'acc_y_g'") */
        { "# converted from an OpenShoe GX2 log (a_x [g] x 9.80665)\nt,ax,ay,az,gx,gy,gz\n"
          "0,0.5,0.2,9.8,0.1,0.2,0.3\n0.01,0.5,0.2,9.8,0.1,0.2,0.3\n",
          HX_FMT_CSV, 0.5, 0.3 },
        { "t,ax,ay,az,gx,gy,gz,acc_x_g,gyro_x_dps\n0,0.5,0.2,9.8,0.1,0.2,0.3,9,9\n0.01,0.5,0.2,9.8,0.1,0.2,0.3,9,9\n",
          HX_FMT_CSV, 0.5, 0.3 },
        /* blank-separated: numpy's savetxt with its default delimiter
         * (header "# t ax ..."), a header padded with runs of blanks, and a
         * foreign format whose names hold no blank (not "FILE:2: header has
         * no column 't'" and "FILE:1: ...") */
        { "# t ax ay az gx gy gz\n0.000000000000000000e+00 5.000000000000000000e-01 2.0e-01 9.8e+00 1.0e-01 2.0e-01 "
          "3.000000000000000000e-01\n1.0e-02 5.0e-01 2.0e-01 9.8e+00 1.0e-01 2.0e-01 3.0e-01\n",
          HX_FMT_CSV, 0.5, 0.3 },
        { "t    ax    ay    az    gx    gy    gz\r\n0    0.5   0.2   9.8   0.1   0.2   0.3\r\n"
          "0.01 0.5   0.2   9.8   0.1   0.2   0.3\r\n",
          HX_FMT_CSV, 0.5, 0.3 },
        { "gyro_x_dps  gyro_y_dps  gyro_z_dps  acc_x_g  acc_y_g  acc_z_g\n1 2 3 0.5 0 -1\n1 2 3 0.5 0 -1\n",
          HX_FMT_ADIS, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
        /* the adis names with a time column beside them: another logger's
         * CSV, read by its stamps with the names matched (the adis reader,
         * which has no time, read them at 100 Hz) */
        { "timestamp_ms,acc_x_g,acc_y_g,acc_z_g,gyro_x_dps,gyro_y_dps,gyro_z_dps\n0,0.5,0,-1,1,2,3\n5,0.5,0,-1,1,2,3\n",
          HX_FMT_CSV, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
        { "Time (s)\tgyro_x_dps\tgyro_y_dps\tgyro_z_dps\tacc_x_g\tacc_y_g\tacc_z_g\n0\t1\t2\t3\t0.5\t0\t-1\n"
          "0.005\t1\t2\t3\t0.5\t0\t-1\n",
          HX_FMT_CSV, 0.5 * 9.80665, 3.0 * 0.017453292519943295 },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char p[256], err[320];
        hx_log_t log;
        tmp_path(p, sizeof p, ".csv");
        write_text(p, cases[i].text);
        if (hx_log_load(&log, p, HX_FMT_AUTO, 100.0, err, sizeof err) != 0) {
            fail_msg("case %zu: %s", i, err);
        }
        assert_int_equal(log.meta.format, cases[i].fmt);
        assert_int_equal(log.n, 2);
        FNAV_ASSERT_CLOSE(log.acc[0][0], cases[i].ax, 1e-6, 1e-6);
        FNAV_ASSERT_CLOSE(log.gyr[0][2], cases[i].gz, 1e-7, 1e-6);
        hx_log_free(&log);
        unlink(p);
    }
}

/* Numbers with a decimal comma (a European-locale export). Where the
 * fields are separated by semicolons or tabs they are read as decimals,
 * the first such line named in a warning (refused before 2026-12-06, when
 * merge already read them); where the separator is the comma itself (or a
 * headerless file, taken for the OpenShoe set), or the number is no
 * well-formed decimal, an error that says so, at the line (not "column 2
 * ('0,5') is not a number", and of the headerless OpenShoe file "header
 * has no column 't'"). */
static void test_decimal_comma(void **state)
{
    static const struct {
        const char *text, *where;
    } cases[] = {
        { "0,19594386;-0,42454505;9,86250782;-0,00349064;-0,01745320;-0,02443448\n"
          "0,19594386;-0,42454505;9,86250782;-0,00349064;-0,01745320;-0,02443448\n",
          ":1: the first line is numbers with a decimal comma ('0,19594386')" },
        /* comma-separated, each number quoted (a spreadsheet quotes a field
         * that holds the separator): the quoted commas split the fields, and
         * "0,00","0,5",... loaded as t 0, ax 0, ay 5, ... without a word */
        { "t,ax,ay,az,gx,gy,gz\n\"0,00\",\"0,5\",\"0,2\",\"9,8\",\"0,1\",\"0,2\",\"0,3\"\n"
          "\"0,01\",\"0,5\",\"0,2\",\"9,8\",\"0,1\",\"0,2\",\"0,3\"\n",
          ":2: column 2 ('0,5')" },
    };
    static const struct {
        const char *text, *warn;
        int64_t t1_ns;
    } read[] = {
        { "t;ax;ay;az;gx;gy;gz\n0;0,5;0,2;9,8;0,1;0,2;0,3\n0,01;0.5;0.2;9.8;0.1;0.2;-0,3\n",
          ":2: numbers with a decimal comma ('0,5') read as decimals (the fields are semicolon-separated)", 10000000 },
        { "Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
          "0\t0,5\t0,2\t9,8\t0,1\t0,2\t0,3\n1\t0,5\t0,2\t9,8\t0,1\t0,2\t-0,3\n",
          ":3: numbers with a decimal comma ('0,5') read as decimals (the fields are tab-separated)", 10000000 },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char p[256], err[320];
        hx_log_t log;
        tmp_path(p, sizeof p, ".csv");
        write_text(p, cases[i].text);
        assert_int_not_equal(hx_log_load(&log, p, HX_FMT_AUTO, 100.0, err, sizeof err), 0);
        if (strstr(err, cases[i].where) == NULL || strstr(err, "decimal point") == NULL ||
            strstr(err, "--from") != NULL) {
            fail_msg("case %zu: %s", i, err);
        }
        hx_log_free(&log);
        unlink(p);
    }
    for (i = 0; i < sizeof read / sizeof read[0]; i++) {
        char p[256];
        readall_t ra;
        tmp_path(p, sizeof p, i == 0 ? ".csv" : "_lf.txt");
        write_text(p, read[i].text);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
        assert_int_equal(ra.end, FNAV_END);
        assert_int_equal(ra.n, 2);
        assert_true(ra.s[1].t_ns - ra.s[0].t_ns == read[i].t1_ns);
        assert_true((float)ra.s[0].accel_mps2[0] == 0.5f && (float)ra.s[0].accel_mps2[2] == 9.8f);
        assert_true((float)ra.s[1].gyro_rps[2] == -0.3f);
        if (strstr(ra.warn, read[i].warn) == NULL) {
            fail_msg("read %zu: %s", i, ra.warn);
        }
        unlink(p);
    }
    {
        /* a thousands separator is no decimal comma: refused at its line */
        char p[256];
        readall_t ra;
        tmp_path(p, sizeof p, ".csv");
        write_text(p, "t;ax;ay;az;gx;gy;gz\n0;1.234,5;0;9,8;0;0;0\n");
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
        assert_int_equal(ra.n, 0);
        if (strstr(ra.err, ":2: column 2 ('1.234,5') is not a number") == NULL) {
            fail_msg("thousands: %s", ra.err);
        }
        unlink(p);
    }
}

/* Time stamps written as a date and time (ISO 8601 and its relatives) read
 * to Unix ns: each expected value is Python's
 * int(datetime(..., tzinfo=timezone.utc).timestamp()) in ns, an independent
 * calendar (2024-05-01T12:00Z 1714564800 s, 2024-03-01T00:00Z 1709251200,
 * 2000-02-29T06:30:15Z 951805815, 2100-03-01T00:00Z 4107542400,
 * 1969-12-31T23:59:59Z -1, 1900-01-01T00:00Z -2208988800, 2100-12-31T23:59:59Z
 * 4133980799). A shape that is no date and time stops with
 * the form the reader takes. */
static void test_datetime_stamps(void **state)
{
    static const struct {
        const char *stamp;
        int64_t t_ns;
    } ok[] = {
        { "2024-05-01 12:00:00.000000", 1714564800000000000LL },
        { "2024-05-01T12:00:00.0025Z", 1714564800002500000LL },
        { "2024-05-01t12:00:00.0025z", 1714564800002500000LL },
        { "2024-05-01T14:00:00.005+02:00", 1714564800005000000LL },
        { "2024/05/01 14:00:00.0075+0200", 1714564800007500000LL },
        { "2024-05-01T09:30:00-02:30", 1714564800000000000LL },
        { "2024-05-01T14:00:00+02", 1714564800000000000LL },
        /* the tenth decimal rounds to the nearest ns, over the leap day */
        { "2024-02-29T23:59:59.9999999996Z", 1709251200000000000LL },
        { "2024-02-29T23:59:59.9999999994Z", 1709251199999999999LL },
        { "2000-02-29 06:30:15", 951805815000000000LL },
        { "2100-03-01T00:00:00Z", 4107542400000000000LL }, /* 2100 is no leap year */
        { "1969-12-31T23:59:59Z", -1000000000LL },
        { "1900-01-01T00:00:00Z", -2208988800000000000LL },
        { "2100-12-31T23:59:59.999999999Z", 4133980799999999999LL },
        { "23:59:59.5", 86399500000000LL },
        { "00:00:00,25", 250000000LL }, /* ISO's decimal comma, in a ;-separated log */
        /* WitMotion's month, day and hour in one digit; MetaWear
         * MetaBase's time in dots after a date and T */
        { "2023-3-21 9:05:23.334", 1679389523334000000LL },
        { "2023/12/1 15:05:23", 1701443123000000000LL },
        { "2019-12-22T07.33.20.005", 1577000000005000000LL },
        { "2024-05-01T12.00.00Z", 1714564800000000000LL },
        /* an offset after one blank (SensorLog's loggingTime) */
        { "2024-05-01 14:00:00.005 +0200", 1714564800005000000LL },
    };
    /* years outside 1900-2100: the reader's 2^62 ns about 1970 span 1824-2116 */
    static const char *const far = "outside the years 1900 to 2100";
    static const char *const form = "no date and time (read as YYYY-MM-DD hh:mm:ss";
    static const struct {
        const char *stamp, *why;
    } bad[] = {
        { "2024-13-01 00:00:00", form },  { "2023-02-29 00:00:00", form }, { "2100-02-29 00:00:00", form },
        { "2024-05-01", form },           { "2024-05-01 24:00:00", form }, { "2024-05-01 12:60:00", form },
        { "12:00:00 UTC", form },         { "2024-05-01 12:00", form },    { "2024-05-01 12:00:00.", form },
        { "2024-05-01 12:00:00+25:00", form }, { "1899-12-31T23:59:59Z", far }, { "2101-01-01 00:00:00", far },
        { "9999-12-31 23:59:59", far },
        /* dots only after a date and T, and in all three places; no
         * month or day of three digits or none */
        { "2024-05-01 12.00.00", form },  { "2024-05-01T12.00:00", form }, { "2024-05-01T12:00.00", form },
        { "2024-123-01 00:00:00", form }, { "2024--01 00:00:00", form },   { "2024-05-011 00:00:00", form },
        { "2024-05-01 12:00:00  +0200", form }, { "12:00:00 +0200", form }, { "2024-05-01 12:00:00 Z", form },
        { "2024-05-01T12:00:00+02:", form },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        char p[256], text[256];
        readall_t r;
        const char *stamp = ok[i].stamp;
        const int64_t want = ok[i].t_ns;
        tmp_path(p, sizeof p, ".csv");
        snprintf(text, sizeof text, "t;ax;ay;az;gx;gy;gz\n%s;0.5;0.2;9.8;0.1;0.2;0.3\n", stamp);
        write_text(p, text);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
        if (r.end != FNAV_END || r.n != 1 || r.s[0].t_ns != want) {
            fail_msg("case %zu (%s): end %d, n %ld, t_ns %lld: %s", i, stamp, (int)r.end, (long)r.n,
                     r.n > 0 ? (long long)r.s[0].t_ns : 0LL, r.err);
        }
        if (strchr(stamp, ',') == NULL) {
            /* blank-separated columns, runs of blanks and tabs: the date
             * and its time stay one field, whatever blanks part them */
            char spaced[64];
            const char *sp = strchr(stamp, ' ');
            if (sp != NULL) {
                snprintf(spaced, sizeof spaced, "%.*s \t  %s", (int)(sp - stamp), stamp, sp + 1);
            } else {
                snprintf(spaced, sizeof spaced, "%s", stamp);
            }
            snprintf(text, sizeof text, "t  ax ay  az gx gy gz\n%s   0.5 0.2\t9.8 0.1 0.2 0.3\n", spaced);
            write_text(p, text);
            assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
            if (r.end != FNAV_END || r.n != 1 || r.s[0].t_ns != want || (float)r.s[0].accel_mps2[0] != 0.5f ||
                (float)r.s[0].gyro_rps[2] != 0.3f) {
                fail_msg("blank-separated case %zu (%s): end %d, n %ld, t_ns %lld: %s", i, spaced, (int)r.end,
                         (long)r.n, r.n > 0 ? (long long)r.s[0].t_ns : 0LL, r.err);
            }
        }
        unlink(p);
    }
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char p[256], text[256];
        readall_t r;
        tmp_path(p, sizeof p, ".csv");
        snprintf(text, sizeof text, "t,ax,ay,az,gx,gy,gz\n%s,0.5,0.2,9.8,0.1,0.2,0.3\n", bad[i].stamp);
        write_text(p, text);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
        if (r.end == FNAV_END || r.n != 0 || strstr(r.err, ":2: time ('") == NULL ||
            strstr(r.err, bad[i].why) == NULL) {
            fail_msg("case %zu (%s): end %d, n %ld: %s", i, bad[i].stamp, (int)r.end, (long)r.n, r.err);
        }
        unlink(p);
    }
    {
        /* blank-separated: a value after a date and time that is no
         * offset (a sign, then not hh and mm) stays its own column */
        static const char *const after[] = { "-12", "-0.25", "+5", "-0130.5", "-2060", "+12:3" };
        static const double want[] = { -12.0, -0.25, 5.0, -130.5, -2060.0, 0.0 };
        char p[256], text[256];
        readall_t r;
        for (i = 0; i < sizeof after / sizeof after[0]; i++) {
            tmp_path(p, sizeof p, ".csv");
            snprintf(text, sizeof text, "t ax ay az gx gy gz\n2024-05-01 12:00:00.5 %s 0.2 9.8 0.1 0.2 0.3\n",
                     after[i]);
            write_text(p, text);
            assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
            if (want[i] != 0.0 && (r.n != 1 || r.s[0].t_ns != 1714564800500000000LL ||
                                   (float)r.s[0].accel_mps2[0] != (float)want[i])) {
                fail_msg("after %s: n %ld: %s", after[i], (long)r.n, r.err);
            }
            if (want[i] == 0.0 && r.n != 0) { /* "+12:3": no number, no offset: the row refused */
                fail_msg("after %s: read, n %ld", after[i], (long)r.n);
            }
            unlink(p);
        }
    }
    {
        /* blank-separated with the date and the time named apart ("date
         * time ax ..."): not joined (the first row's split that gives the
         * header's count decides), the time of day read as the time */
        static const char *const dates[] = { "2023-3-21", "2023-03-21" };
        char p[256], text[256];
        readall_t r;
        for (i = 0; i < sizeof dates / sizeof dates[0]; i++) {
            tmp_path(p, sizeof p, ".csv");
            snprintf(text, sizeof text,
                     "date time ax ay az gx gy gz\n%s 09:05:23.25 0.5 0.2 9.8 0.1 0.2 0.3\n"
                     "%s 09:05:23.26 0.5 0.2 9.8 0.1 0.2 0.3\n",
                     dates[i], dates[i]);
            write_text(p, text);
            assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
            if (r.end != FNAV_END || r.n != 2 || r.s[0].t_ns != 32723250000000LL ||
                r.s[1].t_ns != 32723260000000LL || (float)r.s[0].accel_mps2[0] != 0.5f) {
                fail_msg("date and time apart (%s): end %d, n %ld: %s", dates[i], (int)r.end, (long)r.n, r.err);
            }
            unlink(p);
        }
    }
    {
        /* a log without its header whose stamps are dates and times is
         * data, not a header without a column 't' */
        char p[256];
        readall_t r;
        tmp_path(p, sizeof p, ".csv");
        write_text(p, "2024-05-01 12:00:00.000,0.5,0.2,9.8,0.1,0.2,0.3\n");
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
        if (strstr(r.err, ":1: the first line is data, not a header") == NULL) {
            fail_msg("headerless: %s", r.err);
        }
        unlink(p);
    }
}

/* A ROS sensor_msgs/Imu topic written as CSV and EuRoC's ASL format, read
 * without options: rostopic echo -p's header stamp in ns (not %time, the
 * receive time), bagpy's stamp split in secs and nsecs (not Time, the
 * receive time), ROS 2's split in sec and nanosec, bagpy's Time when no
 * stamp is there (said to be the receive time); Android's gravity-free
 * linear_acceleration_x not taken for ROS's; EuRoC's commented header
 * "#timestamp [ns],w_RS_S_x [rad s^-1],..." with the rates first. Expected
 * values are the file's numbers. */
static void test_ros_euroc(void **state)
{
    static const char *const ros1 =
        "%time,field.header.seq,field.header.stamp,field.header.frame_id,field.orientation.x,field.orientation.y,"
        "field.orientation.z,field.orientation.w,field.angular_velocity.x,field.angular_velocity.y,"
        "field.angular_velocity.z,field.linear_acceleration.x,field.linear_acceleration.y,"
        "field.linear_acceleration.z\n"
        "1700000000001234567,0,1700000000000000000,imu,0,0,0,1,0.5,-0.25,0.125,1.5,-2.5,9.75\n"
        "1700000000006234567,1,1700000000002500000,imu,0,0,0,1,0.5,-0.25,0.125,1.5,-2.5,9.75\n";
    static const char *const bagpy =
        "Time,header.seq,header.stamp.secs,header.stamp.nsecs,header.frame_id,angular_velocity.x,"
        "angular_velocity.y,angular_velocity.z,linear_acceleration.x,linear_acceleration.y,linear_acceleration.z\n"
        "1700000000.0012,0,1700000000,999000000,imu,0.5,-0.25,0.125,1.5,-2.5,9.75\n"
        "1700000000.0062,1,1700000001,1500000,imu,0.5,-0.25,0.125,1.5,-2.5,9.75\n";
    static const char *const ros2 =
        "header.stamp.sec,header.stamp.nanosec,angular_velocity.x,angular_velocity.y,angular_velocity.z,"
        "linear_acceleration.x,linear_acceleration.y,linear_acceleration.z\n"
        "1700000000,0,0.5,-0.25,0.125,1.5,-2.5,9.75\n1700000000,2500000,0.5,-0.25,0.125,1.5,-2.5,9.75\n";
    static const char *const bagpy_time =
        "Time,angular_velocity.x,angular_velocity.y,angular_velocity.z,linear_acceleration.x,"
        "linear_acceleration.y,linear_acceleration.z\n1700000000.0012,0.5,-0.25,0.125,1.5,-2.5,9.75\n";
    static const char *const android =
        "time,linear_acceleration_x,linear_acceleration_y,linear_acceleration_z,angular_velocity_x,"
        "angular_velocity_y,angular_velocity_z\n0,1.5,-2.5,0.5,0.5,-0.25,0.125\n";
    static const char *const euroc =
        "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],"
        "a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\r\n"
        "1403636579758555392,-0.0991,0.1424,0.0628,8.1334,-0.6456,-2.7136\r\n"
        "1403636579763555584,-0.0991,0.1431,0.0628,8.1334,-0.6456,-2.7136\r\n";
    char p[256];
    readall_t ra;
    hx_meta_t m;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, ros1);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &m), 0);
    assert_int_equal(ra.n, 2);
    assert_true(ra.s[0].t_ns == 1700000000000000000LL && ra.s[1].t_ns == 1700000000002500000LL);
    assert_true((float)ra.s[0].accel_mps2[0] == 1.5f && (float)ra.s[0].accel_mps2[2] == 9.75f);
    assert_true((float)ra.s[0].gyro_rps[0] == 0.5f && (float)ra.s[0].gyro_rps[2] == 0.125f);
    assert_string_equal(m.sensor, "ROS sensor_msgs/Imu");
    if (strstr(ra.warn, "--columns t=field.header.stamp,ax=field.linear_acceleration.x") == NULL ||
        strstr(ra.warn, "--units time=ns (a ROS sensor_msgs/Imu's names matched") == NULL ||
        strstr(ra.warn, "not read: %time") == NULL || strstr(ra.warn, "receive time") != NULL) {
        fail_msg("rostopic: %s", ra.warn);
    }
    {
        /* the stamp left 0 by a driver that never sets it: %time read */
        char text[1024];
        snprintf(text, sizeof text, "%.*s1700000000001234567,0,0,imu,0,0,0,1,0.5,-0.25,0.125,1.5,-2.5,9.75\n"
                                    "1700000000006234567,1,0,imu,0,0,0,1,0.5,-0.25,0.125,1.5,-2.5,9.75\n",
                 (int)(strchr(ros1, '\n') - ros1 + 1), ros1);
        write_text(p, text);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
        assert_int_equal(ra.n, 2);
        assert_true(ra.s[0].t_ns == 1700000000001234567LL && ra.s[1].t_ns == 1700000000006234567LL);
        if (strstr(ra.warn, ":2: the message's stamp (field.header.stamp) is 0: the driver left it unset; the "
                            "bag's receive time, '%time', is read instead") == NULL) {
            fail_msg("stamp unset: %s", ra.warn);
        }
    }
    write_text(p, bagpy);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &m), 0);
    assert_int_equal(ra.n, 2);
    assert_true(ra.s[0].t_ns == 1700000000999000000LL && ra.s[1].t_ns == 1700000001001500000LL);
    if (strstr(ra.warn, "--columns t=header.stamp.secs,tns=header.stamp.nsecs,ax=") == NULL ||
        strstr(ra.warn, "not read: Time") == NULL || strstr(ra.warn, "--units") != NULL) {
        fail_msg("bagpy: %s", ra.warn);
    }
    write_text(p, ros2);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 2);
    assert_true(ra.s[0].t_ns == 1700000000000000000LL && ra.s[1].t_ns == 1700000000002500000LL);
    if (strstr(ra.warn, "--columns t=header.stamp.sec,tns=header.stamp.nanosec,") == NULL) {
        fail_msg("ros 2: %s", ra.warn);
    }
    write_text(p, bagpy_time);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 1);
    assert_true(ra.s[0].t_ns == 1700000000001200000LL);
    if (strstr(ra.warn, "--columns t=Time,") == NULL ||
        strstr(ra.warn, "the time is the bag's receive time, the message's stamp not found") == NULL) {
        fail_msg("bagpy's Time: %s", ra.warn);
    }
    write_text(p, android);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    if (strstr(ra.err, "near misses: linear_acceleration_x") == NULL) {
        fail_msg("android: %s", ra.err);
    }
    write_text(p, euroc);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &m), 0);
    assert_int_equal(ra.n, 2);
    assert_true(ra.s[0].t_ns == 1403636579758555392LL && ra.s[1].t_ns == 1403636579763555584LL);
    assert_true((float)ra.s[0].accel_mps2[0] == 8.1334f && (float)ra.s[0].gyro_rps[0] == -0.0991f);
    assert_true((float)ra.s[1].gyro_rps[1] == 0.1431f);
    if (strstr(ra.warn, "ax=a_RS_S_x [m s^-2]") == NULL || strstr(ra.warn, "gx=w_RS_S_x [rad s^-1]") == NULL ||
        strstr(ra.warn, "--units time=ns") == NULL) {
        fail_msg("euroc: %s", ra.warn);
    }
    /* a comment naming the columns before the header itself is a note: the
     * header under it is read (the comment is the header only before data) */
    write_text(p, "# timestamp,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n\nt,ax,ay,az,gx,gy,gz\n"
                  "0.5,1,2,3,4,5,6\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 1);
    assert_true(ra.s[0].t_ns == 500000000LL && (float)ra.s[0].gyro_rps[2] == 6.0f);
    unlink(p);
}

/* Shimmer's Consensys CSV export: Excel's "sep=" line, a header of
 * <device>_<signal>_CAL names, a row of units, a separator at each line's
 * end (the layout as Shimmer's users' loaders describe it). Read without
 * options: the Unix time in ms, the wide-range accelerometer before the
 * low-noise one (named as not read), deg/s from the units row. */
static void test_consensys(void **state)
{
    static const char *const head =
        "P_Timestamp_Unix_CAL\tP_Accel_LN_X_CAL\tP_Accel_LN_Y_CAL\tP_Accel_LN_Z_CAL\tP_Battery_CAL\t"
        "P_Accel_WR_X_CAL\tP_Accel_WR_Y_CAL\tP_Accel_WR_Z_CAL\tP_Gyro_X_CAL\tP_Gyro_Y_CAL\tP_Gyro_Z_CAL\t\r\n";
    static const char *const rows = "1595933810034.18\t1.5\t0.2\t-9.8\t3700\t2.5\t0.3\t-9.7\t10\t20\t30\t\r\n"
                                    "1595933810036.68\t1.5\t0.2\t-9.8\t3700\t2.5\t0.3\t-9.7\t10\t20\t30\t\r\n";
    static const char *const units = "ms\tm/(s^2)\tm/(s^2)\tm/(s^2)\tmV\tm/(s^2)\tm/(s^2)\tm/(s^2)\tdeg/s\tdeg/s\tdeg/s\t\r\n";
    const double d2r = 0.017453292519943295;
    char p[256], text[1024], err[512];
    hx_reader_t *r;
    fnav_sample_t s0, s1, end;
    readall_t ra;
    hx_meta_t m;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    snprintf(text, sizeof text, "\"sep=\t\"\r\n%s%s%s", head, units, rows);
    write_text(p, text);
    r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    if (r == NULL) {
        fail_msg("%s", err);
    }
    assert_int_equal(hx_reader_next(r, &s0), FNAV_OK);
    assert_int_equal(hx_reader_next(r, &s1), FNAV_OK);
    assert_int_equal(hx_reader_next(r, &end), FNAV_END);
    assert_true(s0.t_ns == 1595933810034180000LL && s1.t_ns - s0.t_ns == 2500000);
    assert_true((float)s0.accel_mps2[0] == 2.5f && (float)s0.accel_mps2[2] == -9.7f); /* wide range */
    assert_true((float)s0.gyro_rps[2] == (float)(30.0 * d2r));
    if (strstr(hx_reader_warnings(r), "not read: P_Accel_LN_X_CAL, P_Accel_LN_Y_CAL, P_Accel_LN_Z_CAL") == NULL ||
        strstr(hx_reader_warnings(r), ":3: a row of units under the header (Shimmer's Consensys export): read "
                                      "as --units time=ms,accel=m/s2,gyro=deg/s") == NULL) {
        fail_msg("warnings: %s", hx_reader_warnings(r));
    }
    assert_string_equal(hx_reader_meta(r)->sensor, "Shimmer (Consensys export)");
    hx_reader_close(r);
    unlink(p);
    /* comma-separated, no sep line, no units row: line 2 read as data,
     * its stamp in ms then out of range in s, with the remedy */
    snprintf(text, sizeof text, "%s%s", head, rows);
    for (char *c = text; *c != '\0'; c++) {
        *c = *c == '\t' ? ',' : *c;
    }
    write_text(p, text);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &m), 0);
    assert_int_equal(ra.n, 0);
    if (strstr(ra.err, ":2: time ('1595933810034.18') is beyond 9e9 s") == NULL || strstr(ra.err, "time=ms") == NULL) {
        fail_msg("no units row: %s", ra.err);
    }
    unlink(p);
    /* two devices: each key twice, refused with both named */
    write_text(p, "A_Timestamp_Unix_CAL,A_Accel_WR_X_CAL,A_Accel_WR_Y_CAL,A_Accel_WR_Z_CAL,A_Gyro_X_CAL,A_Gyro_Y_CAL,"
                  "A_Gyro_Z_CAL,B_Timestamp_Unix_CAL,B_Accel_WR_X_CAL,B_Accel_WR_Y_CAL,B_Accel_WR_Z_CAL,B_Gyro_X_CAL,"
                  "B_Gyro_Y_CAL,B_Gyro_Z_CAL\nms,m/(s^2),m/(s^2),m/(s^2),deg/s,deg/s,deg/s,ms,m/(s^2),m/(s^2),"
                  "m/(s^2),deg/s,deg/s,deg/s\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    if (strstr(ra.err, "t: 2 candidates (A_Timestamp_Unix_CAL, B_Timestamp_Unix_CAL)") == NULL ||
        strstr(ra.err, "ax: 2 candidates (A_Accel_WR_X_CAL, B_Accel_WR_X_CAL)") == NULL) {
        fail_msg("two devices: %s", ra.err);
    }
    unlink(p);
    /* a unit not read for a column read: refused, with the option */
    write_text(p, "P_Timestamp_Unix_CAL,P_Accel_WR_X_CAL,P_Accel_WR_Y_CAL,P_Accel_WR_Z_CAL,P_Gyro_X_CAL,P_Gyro_Y_CAL,"
                  "P_Gyro_Z_CAL\nms,m/(s^2),m/(s^2),m/(s^2),no units,no units,no units\n0,1,2,3,4,5,6\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    if (strstr(ra.err, ":2: the row of units under the header gives 'no units' for the gyro column, not a unit of "
                       "it read; give its unit with --units gyro=...") == NULL) {
        fail_msg("no units: %s", ra.err);
    }
    unlink(p);
    /* stamps written as dates and times, as Consensys can export them */
    write_text(p, "\"sep=,\"\nP_Timestamp_Unix_CAL,P_Accel_WR_X_CAL,P_Accel_WR_Y_CAL,P_Accel_WR_Z_CAL,P_Gyro_X_CAL,"
                  "P_Gyro_Y_CAL,P_Gyro_Z_CAL,\nyyyy/mm/dd hh:mm:ss.000,m/(s^2),m/(s^2),m/(s^2),deg/s,deg/s,deg/s,\n"
                  "2020/07/28 10:56:50.034,1,2,3,4,5,6,\n2020/07/28 10:56:50.039,1,2,3,4,5,6,\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.end, FNAV_END);
    assert_int_equal(ra.n, 2);
    /* Python: datetime(2020, 7, 28, 10, 56, 50, tzinfo=timezone.utc).timestamp() = 1595933810 */
    assert_true(ra.s[0].t_ns == 1595933810034000000LL && ra.s[1].t_ns - ra.s[0].t_ns == 5000000);
    assert_true((float)ra.s[0].gyro_rps[0] == (float)(4.0 * d2r));
    unlink(p);
}

/* A row of units under any CSV header, as loggers and spreadsheets write
 * it: read as --units, said in a warning; --units given rules its column;
 * a second row that is neither data nor units keeps the data's error. */
static void test_units_row(void **state)
{
    const double d2r = 0.017453292519943295;
    char p[256];
    readall_t ra;
    hx_reader_t *r;
    fnav_sample_t s0;
    char err[512];
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "time,acc_x,acc_y,acc_z,gyro_x,gyro_y,gyro_z\ns,g,g,g,deg/s,deg/s,[deg/s]\n"
                  "0,0,0,1,10,20,30\n0.01,0,0,1,10,20,30\n");
    r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    if (r == NULL) {
        fail_msg("%s", err);
    }
    assert_int_equal(hx_reader_next(r, &s0), FNAV_OK);
    assert_true((float)s0.accel_mps2[2] == (float)9.80665);
    assert_true((float)s0.gyro_rps[1] == (float)(20.0 * d2r));
    if (strstr(hx_reader_warnings(r), ":2: a row of units under the header: read as --units "
                                      "time=s,accel=g,gyro=deg/s") == NULL ||
        strstr(hx_reader_warnings(r), "Consensys") != NULL) {
        fail_msg("warnings: %s", hx_reader_warnings(r));
    }
    hx_reader_close(r);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 2);
    assert_true(ra.s[1].t_ns - ra.s[0].t_ns == 10000000);
    unlink(p);
    /* semicolons, ms, no unit for the gyro: refused with the option */
    write_text(p, "t;ax;ay;az;gx;gy;gz\nms;m/s^2;m/s^2;m/s^2;;;\n0;0;0;9.8;0;0;0\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    if (strstr(ra.err, ":2: the row of units under the header gives '' for the gyro column, not a unit of it read; "
                       "give its unit with --units gyro=...") == NULL) {
        fail_msg("no gyro unit: %s", ra.err);
    }
    unlink(p);
    /* a second row that is no units (a label): the data's error as before */
    write_text(p, "t,ax,ay,az,gx,gy,gz\nstart,0,0,9.8,0,0,0\n0,0,0,9.8,0,0,0\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 0);
    if (strstr(ra.err, ":2: time ('start') is not a number") == NULL) {
        fail_msg("label row: %s", ra.err);
    }
    unlink(p);
}

/* A log without a header, its columns given by number: read from the
 * first line (a warning); a column not numbered, a number past the line's
 * fields and names mixed in are refused, and without --columns the
 * first line's error names the remedy. */
/* read_all under --columns map (NULL: none) */
static int read_mapped(const char *path, const char *map, double rate, readall_t *ra)
{
    static hx_csv_layout_t l;
    char err[512];
    int rc;
    hx_csv_layout_default(&l);
    if (map != NULL) {
        assert_int_equal(hx_csv_columns_parse(&l, map, err, sizeof err), 0);
        l.option = "--columns";
    }
    hx_reader_set_layout(map != NULL ? &l : NULL);
    rc = read_all(path, HX_FMT_AUTO, rate, ra, NULL);
    hx_reader_set_layout(NULL);
    return rc;
}

static void test_numbered_columns(void **state)
{
    char p[256];
    readall_t ra;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "0,1,2,9.8,0.1,0.2,0.3\n0.01,1,2,9.8,0.1,0.2,0.3\n0.02,1,2,9.8,0.1,0.2,0.3\n");
    assert_int_equal(read_mapped(p, NULL, 0.0, &ra), -1);
    if (strstr(ra.err, ":1: the first line is data, not a header") == NULL ||
        strstr(ra.err, "give its columns by number, --columns t=1,ax=2,ay=3,az=4,gx=5,gy=6,gz=7") == NULL) {
        fail_msg("no header: %s", ra.err);
    }
    /* the gyro first: the columns as numbered, not as the line's order */
    assert_int_equal(read_mapped(p, "t=1,gx=2,gy=3,gz=4,ax=5,ay=6,az=-7", 0.0, &ra), 0);
    assert_int_equal(ra.end, FNAV_END);
    assert_int_equal(ra.n, 3); /* the first line is data */
    assert_true(ra.s[0].t_ns == 0 && ra.s[2].t_ns == 20000000);
    assert_true((float)ra.s[0].gyro_rps[0] == 1.0f && (float)ra.s[0].gyro_rps[2] == 9.8f);
    assert_true((float)ra.s[0].accel_mps2[0] == 0.1f && (float)ra.s[0].accel_mps2[2] == -0.3f);
    if (strstr(ra.warn, ":1: no header: the columns read by the numbers --columns gives") == NULL) {
        fail_msg("warnings: %s", ra.warn);
    }
    /* no time: refused, naming t and --input-rate; with the rate read */
    assert_int_equal(read_mapped(p, "ax=2,ay=3,az=4,gx=5,gy=6,gz=7", 0.0, &ra), -1);
    if (strstr(ra.err, "numbers some columns but not t: give each of t,ax,ay,az,gx,gy,gz by number") == NULL ||
        strstr(ra.err, "--input-rate HZ") == NULL) {
        fail_msg("no t: %s", ra.err);
    }
    assert_int_equal(read_mapped(p, "ax=2,ay=3,az=4,gx=5,gy=6,gz=7", 50.0, &ra), 0);
    assert_int_equal(ra.n, 3);
    assert_true(ra.s[1].t_ns == 20000000); /* sample 1 at 1 / 50 s */
    /* a number past the fields */
    assert_int_equal(read_mapped(p, "t=1,ax=2,ay=3,az=4,gx=5,gy=6,gz=8", 0.0, &ra), -1);
    if (strstr(ra.err, "--columns gz=8: the line has 7 fields, numbered 1 to 7") == NULL) {
        fail_msg("past the fields: %s", ra.err);
    }
    /* names mixed in: a header is expected, the first line's error */
    assert_int_equal(read_mapped(p, "t=time,ax=2", 0.0, &ra), -1);
    if (strstr(ra.err, ":1: the first line is data, not a header") == NULL) {
        fail_msg("names mixed: %s", ra.err);
    }
    /* a header whose names are numbers is still a header */
    write_text(p, "t,1,2,3,4,5,6\n0,0,0,9.8,0,0,0\n0.01,0,0,9.8,0,0,0\n");
    assert_int_equal(read_mapped(p, "ax=1,ay=2,az=3,gx=4,gy=5,gz=6", 0.0, &ra), 0);
    assert_int_equal(ra.n, 2);
    assert_true((float)ra.s[0].accel_mps2[2] == 9.8f);
    /* ... also all numbers, when it names every column given, or counts
     * the columns from 0 (pandas' header of an array): not a sample */
    write_text(p, "0,1,2,3,4,5,6\n0,0,0,9.8,0,0,0\n0.01,0,0,9.8,0,0,0\n");
    assert_int_equal(read_mapped(p, "t=0,ax=1,ay=2,az=3,gx=4,gy=5,gz=6", 0.0, &ra), 0);
    assert_int_equal(ra.n, 2);
    assert_true(ra.s[0].t_ns == 0 && (float)ra.s[0].accel_mps2[2] == 9.8f);
    /* 1..7 over that header: a header still (it counts its columns), whose
     * names lack 7: refused as before, not read with the header as a sample */
    assert_int_equal(read_mapped(p, "t=1,ax=2,ay=3,az=4,gx=5,gy=6,gz=7", 0.0, &ra), -1);
    assert_true(strstr(ra.warn, "no header") == NULL && strstr(ra.err, ":1: ") != NULL);
    /* ... saying how it counts (not "the first line is data ... give its
     * columns by number, --columns t=1,...", what was given) */
    if (strstr(ra.err, ":1: the header counts the columns from 0 (pandas' header of an array), and --columns names "
                       "them as it does: gz=7 is not one of its names, 0 to 6 (the first column is 0)") == NULL) {
        fail_msg("1..7 over a 0-based header: %s", ra.err);
    }
    /* the nanoseconds by number too */
    write_text(p, "100,0,0,9.8,0,0,0,0\n100,0,0,9.8,0,0,0,10000000\n100,0,0,9.8,0,0,0,20000000\n");
    assert_int_equal(read_mapped(p, "t=1,tns=8,ax=2,ay=3,az=4,gx=5,gy=6,gz=7", 0.0, &ra), 0);
    assert_int_equal(ra.n, 3);
    assert_true(ra.s[0].t_ns == 100000000000LL && ra.s[2].t_ns - ra.s[0].t_ns == 20000000);
    assert_int_equal(read_mapped(p, "t=1,tns=9,ax=2,ay=3,az=4,gx=5,gy=6,gz=7", 0.0, &ra), -1);
    if (strstr(ra.err, "--columns tns=9: the line has 8 fields") == NULL) {
        fail_msg("tns past the fields: %s", ra.err);
    }
    unlink(p);
}

/* The names of --help and of the unknown-format error (HX_FORMAT_LIST) are
 * exactly the formats --from takes, in order: a new importer that misses
 * one of the two lists fails here (CONTRIBUTING.md, "Extending footnav"). */
static void test_format_list(void **state)
{
    char want[256] = "";
    size_t len = 0;
    int f;
    (void)state;
    for (f = HX_FMT_AUTO + 1; f < HX_FMT_COUNT; f++) {
        assert_int_equal(hx_format_from_name(hx_format_name((hx_format_t)f)), f);
        /* appended in place (a copy through a second buffer of the same
         * size is a truncation warning at -O1, make sanitize) */
        assert_true(len < sizeof want);
        len += (size_t)snprintf(want + len, sizeof want - len, "%s%s", len > 0 ? ", " : "",
                                hx_format_name((hx_format_t)f));
    }
    assert_true(len < sizeof want);
    assert_string_equal(hx_format_list(), want);
    assert_int_equal(hx_format_from_name("nope"), HX_FMT_COUNT);
}

/* The seeds of the log-reader fuzz target run the format their names say:
 * a target taking the format as the whole first byte modulo HX_FMT_COUNT,
 * flag bits included, would run gx2_forced (0x83) as bin, square2_forced
 * (0x89) as ipol and adis_synthetic_gz (0x40) as openshoe820, and a new
 * format would move them again. */
static void test_fuzz_seed_formats(void **state)
{
    static const struct {
        const char *seed, *format;
    } k[] = {
        { "gx2_forced", "gx2" },           { "ngimu_forced", "ngimu" },   { "openshoe820_forced", "openshoe820" },
        { "pyshoe_forced", "pyshoe" },     { "square2_forced", "square2" }, { "bin_golden_whole", "bin" },
        { "adis_synthetic_gz", "auto" },   { "openshoe820_tabs", "auto" }, { "openshoe820_blanks", "openshoe820" },
        { "csv_temp", "csv" },             { "regress_gx2_huge_nr", "gx2" }, { "csv_columns", "csv" },
        { "mtmanager_synthetic", "auto" }, { "mtmanager_forced", "mtmanager" },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof k / sizeof k[0]; i++) {
        char path[128];
        FILE *f;
        int b;
        snprintf(path, sizeof path, "tests/fuzz/corpus/log_reader/%s", k[i].seed);
        f = fopen(path, "rb");
        assert_non_null(f);
        b = fgetc(f);
        fclose(f);
        assert_true(b != EOF);
        if (fuzz_log_format((uint8_t)b) != hx_format_from_name(k[i].format)) {
            fail_msg("%s (first byte 0x%02x) runs as %s, not %s", k[i].seed, b,
                     hx_format_name(fuzz_log_format((uint8_t)b)), k[i].format);
        }
    }
}

/* A header that detection takes for one format but that lacks a column:
 * the error names the detected format and --from; with --from given it
 * does not. */
static void test_detect_wrong_hint(void **state)
{
    char p[256], err[1024];
    hx_log_t log;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Accelerometer X (g),Accelerometer Y (g),"
                  "Accelerometer Z (g)\n0,1,2,3,4,5\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: header has no column 'Gyroscope Z (deg/s)'"));
    assert_non_null(strstr(err, "format ngimu detected from the content; give --from FORMAT"));
    assert_int_equal(hx_log_load(&log, p, HX_FMT_NGIMU, 0.0, err, sizeof err), -1);
    assert_null(strstr(err, "--from"));
    /* (names with a word besides stem and axis: "acc x" alone is read,
     * test_csv_names) */
    write_text(p, "time,acc x raw,acc y raw,acc z raw,gyr x raw,gyr y raw,gyr z raw\n0,1,2,3,4,5,6\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: header has no column 't'"));
    assert_non_null(strstr(err, "no importer's header recognised, read as footnav CSV; give --from FORMAT"));
    /* a layout no importer reads (a phone app's export): the error names
     * the way without C, not only --from: the options (not "rename the
     * columns and convert the units") */
    write_text(p, "timestamp_ns,acc_x_uncal,acc_y_uncal,acc_z_uncal,gyro_x_uncal,gyro_y_uncal,gyro_z_uncal\n"
                  "1764500000000000000,1,2,3,4,5,6\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, "or give its names and units with --columns and --units: docs/log-format.md, "
                                "\"Another layout\")"));
    write_text(p, "t,ax,ay,az,gx,gy\n0,1,2,3,4,5\n"); /* ours, known by its 't': no hint */
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: header has no column 'gz'; expected t,ax,ay,az,gx,gy,gz[,temp]"));
    assert_null(strstr(err, "--from"));
    /* no header at all: the first line is data (not "header has no column 't'") */
    write_text(p, "0.0025,0.1,-0.2,9.81,0.01,0.02,-0.03\n0.005,0.1,-0.2,9.81,0.01,0.02,-0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: the first line is data, not a header"));
    assert_non_null(strstr(err, "t,ax,ay,az,gx,gy,gz[,temp]"));
    unlink(p);
}

/* The rate of time-stamped logs (hx_stamp_rate_hz), at 398.3 and 820 Hz:
 * - exact stamps with 20 us of jitter, 1 % lost and 1 % duplicated samples:
 *   1 / the median interval, within 0.2 %;
 * - the same printed to the millisecond without lost or duplicated samples
 *   (a duplicate hides a sample's own stamp, an interval of two periods):
 *   within 0.2 %,
 *   where the median interval reads 2 or 3 ms (333 or 500 Hz), 1 ms at
 *   820 Hz (1000 Hz);
 * - printed to the millisecond with 1 % lost and 1 % duplicated samples:
 *   within 1 %. A lost
 *   sample whose interval rounds to one a normal interval can also read
 *   (2.44 ms read as 2 ms at 820 Hz) cannot be told from it, so the bias can
 *   reach the lost fraction; 0.7 % at 820 Hz here. */
static void stamps(int64_t *t, size_t n, double rate, double lost, int ms)
{
    uint64_t s = 7u;
    double tk = 0.0;
    size_t k;
    for (k = 0; k < n; k++) {
        double u;
        s = 6364136223846793005u * s + 1442695040888963407u;
        u = (double)(s >> 40) / 16777216.0;
        tk += (u < lost) ? 2.0 / rate : 1.0 / rate;
        t[k] = (lost > 0.0 && k % 100u == 99u) ? t[k - 1u] : (int64_t)llround((tk + 20e-6 * (u - 0.5)) * 1e9);
        if (ms) {
            t[k] = (t[k] + 500000) / 1000000 * 1000000;
        }
    }
}

static void test_stamp_rate(void **state)
{
    enum { N = 4000 };
    static int64_t t[N];
    static const double rates[2] = { 398.3, 820.0 };
    int64_t same[3] = { 5, 5, 5 };
    size_t j;
    (void)state;
    for (j = 0; j < 2; j++) {
        stamps(t, N, rates[j], 0.01, 0);
        FNAV_ASSERT_CLOSE(hx_stamp_rate_hz(t, N, NULL), rates[j], 0.0, 2e-3);
        stamps(t, N, rates[j], 0.0, 1);
        FNAV_ASSERT_CLOSE(hx_stamp_rate_hz(t, N, NULL), rates[j], 0.0, 2e-3);
        stamps(t, N, rates[j], 0.01, 1);
        FNAV_ASSERT_CLOSE(hx_stamp_rate_hz(t, N, NULL), rates[j], 0.0, 1e-2);
    }
    {
        /* stamps from a sample counter (k / 100 Hz) with 1 % lost samples:
         * exactly 100 Hz (the lost ones are gaps, not rounding), and not
         * coarse: every interval is a whole number of the median one, which
         * the detector's own median estimate reads exactly (replay must not
         * say such a grid is "too coarse for the detector's estimate": the
         * stamps' resolution, the intervals' gcd, is the period itself) */
        uint64_t r = 3u;
        int64_t c = 0;
        int coarse = 1;
        size_t k;
        for (k = 0; k < N; k++) {
            r = 6364136223846793005u * r + 1442695040888963407u;
            c += ((r >> 40) < 167772u) ? 2 : 1;
            t[k] = c * 10000000;
        }
        assert_true(hx_stamp_rate_hz(t, N, &coarse) == 100.0);
        assert_int_equal(coarse, 0);
        /* 5 % and 10 % lost: exactly 100 Hz still. A first period from the
         * median of spans of 16 intervals, which above 4.2 % lost holds a
         * lost sample (17 periods over 16, 10.625 ms), would make the gap
         * threshold take 20 ms intervals for periods, 95.3 and 91.6 Hz
         * (`sim --rate 100 --effect dropout:prob=0.05` as a CSV, `info`) */
        {
            static const uint64_t lost[2] = { 838861u, 1677722u }; /* 5 %, 10 % of 2^24 */
            size_t e;
            for (e = 0; e < 2; e++) {
                r = 5u;
                c = 0;
                for (k = 0; k < N; k++) {
                    do {
                        r = 6364136223846793005u * r + 1442695040888963407u;
                        c++;
                    } while ((r >> 40) < lost[e]);
                    t[k] = c * 10000000;
                }
                assert_true(hx_stamp_rate_hz(t, N, &coarse) == 100.0);
                assert_int_equal(coarse, 0);
            }
            r = 3u;
            c = 0;
            for (k = 0; k < N; k++) {
                r = 6364136223846793005u * r + 1442695040888963407u;
                c += ((r >> 40) < 167772u) ? 2 : 1;
                t[k] = c * 10000000;
            }
        }
        /* one interval that is no whole number of periods (10 ms read as
         * 11): coarse, as a 100 Hz log stamped to the millisecond whose
         * clock runs slow */
        t[N / 2] += 1000000;
        (void)hx_stamp_rate_hz(t, N, &coarse);
        assert_int_equal(coarse, 1);
        /* a repeated stamp on the grid: the stamps hide a sample's own
         * time (10 s stamps on a 100 Hz log repeat): coarse */
        t[N / 2] -= 1000000;
        t[N / 2] = t[N / 2 - 1];
        (void)hx_stamp_rate_hz(t, N, &coarse);
        assert_int_equal(coarse, 1);
    }
    {
        /* a 100.4 Hz log stamped to 0.1 ms (four decimals): the intervals
         * read 9.9 or 10.0 ms, a resolution of a hundredth of the period.
         * Their median is one of those two (101.0 or 100.0 Hz, 0.4 % off);
         * stamps that coarse take the mean of the intervals, 100.4 Hz. A
         * mutant taking the median down to a hundredth (not a thousandth)
         * of the period passed every suite */
        int coarse = 0;
        size_t k;
        for (k = 0; k < N; k++) {
            t[k] = (int64_t)floor((double)k / 100.4 * 1e4 + 0.5) * 100000;
        }
        FNAV_ASSERT_CLOSE(hx_stamp_rate_hz(t, N, &coarse), 100.4, 0.0, 1e-4);
        assert_int_equal(coarse, 1);
    }
    assert_true(hx_stamp_rate_hz(same, 3, NULL) == 0.0);
    assert_true(hx_stamp_rate_hz(same, 1, NULL) == 0.0);
}

/* Stamps in bursts (hx_stamp_bursts), the test of replay, --rate and the
 * warning of info, psd and allan; expected values worked out by hand from
 * the stamps built here:
 * - packets of 4 samples stamped 5 us apart every 10 ms (400 Hz): median
 *   interval 5 us, 200 kHz; the 4000 samples span 10,000 us to
 *   10,000,015 us: 9.990015 s; the rate to give 400 Hz, from packets 2 to
 *   1000 (3992 samples over 9.98 s); CLOSE (4000 samples,
 *   where 200 kHz gives about 2 million);
 * - one stamp shared by each packet: 100 Hz, 9.99 s, SHARED;
 * - the same bursts with a 5 s pause after 2000 samples: two segments, the
 *   pause left out of the span;
 * - 400 Hz with every third sample lost, or every fourth stamp a repeat of
 *   the one before (coarse stamps, not bursts): NONE;
 * - fewer than 4 distinct stamps: NONE. */
static void test_stamp_bursts(void **state)
{
    enum { N = 4000 };
    static int64_t t[N];
    hx_bursts_t b;
    char msg[512];
    size_t k, m;
    (void)state;
    for (k = 0; k < N; k++) {
        t[k] = ((int64_t)(k / 4u) + 1) * 10000000 + 5000 * (int64_t)(k % 4u);
    }
    assert_int_equal(hx_stamp_bursts(t, N, 0.2, &b), HX_BURSTS_CLOSE);
    assert_int_equal(b.kind, HX_BURSTS_CLOSE);
    assert_true(b.median_hz == 200000.0);
    assert_int_equal(b.segs, 1);
    assert_int_equal(b.n, N);
    FNAV_ASSERT_CLOSE(b.span_s, 9.990015, 1e-12, 0.0);
    /* the samples of packets 2 to 1000, 3992, over their stamps' 9.98 s */
    FNAV_ASSERT_CLOSE(b.rate_hz, 400.0, 0.0, 1e-12);
    assert_string_equal(hx_bursts_text(&b, "WHAT", "SECTION", msg, sizeof msg),
                        "the time stamps come in bursts (samples stamped close together as a logger reads them?): 1 "
                        "/ their median interval gives 200000 Hz, but the 4000 samples span 9.99 s, 400 Hz; WHAT: "
                        "leave the time column out and give --input-rate 400 (docs/harness.md, \"SECTION\")");
    /* a pause of 5 s after 2000 samples: a time jump, not in the span */
    for (k = N / 2u; k < N; k++) {
        t[k] += 5000000000;
    }
    assert_int_equal(hx_stamp_bursts(t, N, 0.2, &b), HX_BURSTS_CLOSE);
    assert_int_equal(b.segs, 2);
    FNAV_ASSERT_CLOSE(b.span_s, 2.0 * 4.990015, 1e-12, 0.0); /* 10,000 us to 5,000,015 us, and as long after the pause */
    FNAV_ASSERT_CLOSE(b.rate_hz, 400.0, 0.0, 1e-12); /* packets 2 to 500 of each segment: 2 x 1992 samples over 2 x 4.98 s */
    assert_non_null(strstr(hx_bursts_text(&b, "W", "S", msg, sizeof msg), "span 9.98 s between the time jumps"));
    /* one stamp per packet */
    for (k = 0; k < N; k++) {
        t[k] = ((int64_t)(k / 4u) + 1) * 10000000;
    }
    assert_int_equal(hx_stamp_bursts(t, N, 0.2, &b), HX_BURSTS_SHARED);
    assert_true(b.median_hz == 100.0);
    FNAV_ASSERT_CLOSE(b.span_s, 9.99, 1e-12, 0.0);
    assert_non_null(strstr(hx_bursts_text(&b, "W", "S", msg, sizeof msg), "(samples that share one stamp: one per packet, or stamps coarser than the sampling?)"));
    /* 400 Hz, a third of the samples lost in gaps of 27.5 ms (10 of every
     * 30): the median interval stays 2.5 ms, and 2/3 of its count is no
     * burst */
    for (k = 0, m = 0; k < N; k++) {
        if (k % 30u < 20u) {
            t[m++] = (int64_t)k * 2500000;
        }
    }
    assert_int_equal(hx_stamp_bursts(t, m, 0.2, &b), HX_BURSTS_NONE);
    assert_true(b.median_hz == 400.0);
    FNAV_ASSERT_CLOSE((double)m / (b.span_s * b.median_hz + 1.0), 2.0 / 3.0, 2e-3, 0.0);
    /* every third sample lost: intervals of 2.5 and 5 ms alike, whose
     * median (5 ms) halves the rate; 4/3 of its count, no burst either */
    for (k = 0, m = 0; k < N; k++) {
        if (k % 3u != 2u) {
            t[m++] = (int64_t)k * 2500000;
        }
    }
    assert_int_equal(hx_stamp_bursts(t, m, 0.2, &b), HX_BURSTS_NONE);
    assert_true(b.median_hz == 200.0);
    /* 400 Hz, every fourth stamp the one before it */
    for (k = 0; k < N; k++) {
        t[k] = (int64_t)(k % 4u == 3u ? k - 1u : k) * 2500000;
    }
    assert_int_equal(hx_stamp_bursts(t, N, 0.2, &b), HX_BURSTS_NONE);
    /* too few distinct stamps */
    for (k = 0; k < 8; k++) {
        t[k] = (int64_t)(k / 3u) * 1000;
    }
    assert_int_equal(hx_stamp_bursts(t, 8, 0.2, &b), HX_BURSTS_NONE);
    assert_int_equal(hx_stamp_bursts(NULL, 0, 0.2, &b), HX_BURSTS_NONE);
}

/* The rate hx_bursts_text gives for --input-rate: exact for whole packets
 * whatever the log's first and last packets hold. It was (n - segs) / span
 * over the stamps, which counts the samples of a cut last packet and of the
 * first one against a span that ends at the last stamp: a 250 Hz log gave
 * 250.1, a walk's 4000 whole packets 400.3. Expected rates worked out by
 * hand: 4 samples every 7 ms, 571.43 Hz (%.4g: 571.4); 4 every 16 ms,
 * 250 Hz; 3 to a stamp every 10 ms, 300 Hz; the 400 Hz bursts with a 5 s
 * pause in the middle of a packet, 400 Hz. */
static void test_stamp_bursts_rate(void **state)
{
    enum { N = 3000 };
    static int64_t t[N];
    hx_bursts_t b;
    char msg[512];
    size_t k, skip, n;
    (void)state;
    /* close bursts, 4 samples 5 us apart every 7 ms: a last packet of 1,
     * 2, 3 or 4 samples, and a first packet cut to 3, 2 or 1 */
    for (skip = 0; skip < 4u; skip++) {
        for (n = N - 3u; n <= N; n++) {
            for (k = 0; k < n; k++) {
                const size_t j = k + skip;
                t[k] = ((int64_t)(j / 4u) + 1) * 7000000 + 5000 * (int64_t)(j % 4u);
            }
            assert_int_equal(hx_stamp_bursts(t, n, 0.2, &b), HX_BURSTS_CLOSE);
            assert_non_null(strstr(hx_bursts_text(&b, "W", "S", msg, sizeof msg), "give --input-rate 571.4 ("));
            FNAV_ASSERT_CLOSE(b.rate_hz, 4.0 / 0.007, 0.0, 1e-12);
        }
    }
    /* 250 Hz in packets of 4 every 16 ms, 2998 samples (a last packet of 2):
     * the log of tests/cli/test_replay.sh that said 250.1 */
    for (k = 0; k < 2998u; k++) {
        t[k] = ((int64_t)(k / 4u) + 1) * 16000000 + 5000 * (int64_t)(k % 4u);
    }
    assert_int_equal(hx_stamp_bursts(t, 2998u, 0.2, &b), HX_BURSTS_CLOSE);
    assert_non_null(strstr(hx_bursts_text(&b, "W", "S", msg, sizeof msg), "span 11.98 s, 250 Hz; W: leave the time column out and give --input-rate 250 ("));
    /* 3 samples to a stamp every 10 ms (300 Hz): a last packet of 1 and a
     * first one cut to 2 */
    for (k = 0; k < 2998u; k++) {
        t[k] = ((int64_t)((k + 1u) / 3u) + 1) * 10000000;
    }
    assert_int_equal(hx_stamp_bursts(t, 2998u, 0.2, &b), HX_BURSTS_SHARED);
    assert_non_null(strstr(hx_bursts_text(&b, "W", "S", msg, sizeof msg), "give --input-rate 300 ("));
    FNAV_ASSERT_CLOSE(b.rate_hz, 300.0, 0.0, 1e-12);
    /* the 400 Hz bursts (4 every 10 ms) with a pause of 5 s after 2002
     * samples, in the middle of a packet: two segments, each with a cut
     * packet at its end or its start */
    for (k = 0; k < N; k++) {
        t[k] = ((int64_t)(k / 4u) + 1) * 10000000 + 5000 * (int64_t)(k % 4u) + (k >= 2002u ? 5000000000 : 0);
    }
    assert_int_equal(hx_stamp_bursts(t, N, 0.2, &b), HX_BURSTS_CLOSE);
    assert_int_equal(b.segs, 2);
    assert_non_null(strstr(hx_bursts_text(&b, "W", "S", msg, sizeof msg), "between the time jumps, 400 Hz; W: leave the time column out and give --input-rate 400 ("));
    FNAV_ASSERT_CLOSE(b.rate_hz, 400.0, 0.0, 1e-12);
}

/* The remedy for stamps in bursts is the format's (hx_bursts_remedy): the
 * interchange CSV leaves its time column out; every other format, whose
 * time cannot be left out (a .bin) or which ignores --input-rate (a
 * time-stamped importer) or takes it for its counter's rate (ipol), is
 * converted to CSV first, not told to leave its time column out
 * (tests/cli/test_bursts.sh follows each remedy). */
static void test_bursts_remedy(void **state)
{
    static const hx_format_t convert[] = { HX_FMT_BIN, HX_FMT_GX2, HX_FMT_NGIMU, HX_FMT_PYSHOE,
                                           HX_FMT_IPOL, HX_FMT_SQUARE2, HX_FMT_MTMGR };
    hx_bursts_t b;
    char msg[640];
    int64_t t[400];
    size_t k;
    (void)state;
    hx_reader_set_layout(NULL);
    assert_string_equal(hx_bursts_remedy(HX_FMT_CSV, 400.0, msg, sizeof msg),
                        "leave the time column out and give --input-rate 400");
    assert_string_equal(hx_bursts_remedy(HX_FMT_AUTO, 250.0, msg, sizeof msg),
                        "leave the time column out and give --input-rate 250");
    {
        /* a time column --columns names: its item goes too */
        hx_csv_layout_t l;
        hx_csv_layout_default(&l);
        strcpy(l.names[0], "SampleTimeFine");
        l.option = "--columns";
        hx_reader_set_layout(&l);
        assert_string_equal(hx_bursts_remedy(HX_FMT_CSV, 398.0, msg, sizeof msg),
                            "leave the time column out (drop t=SampleTimeFine from --columns) and give --input-rate 398");
        hx_reader_set_layout(NULL);
    }
    for (k = 0; k < sizeof convert / sizeof convert[0]; k++) {
        assert_string_equal(hx_bursts_remedy(convert[k], 400.0, msg, sizeof msg),
                            "convert it to CSV without the time column (bin/harness convert LOG out.csv; cut -d, -f2- "
                            "out.csv > in.csv) and give in.csv --input-rate 400");
    }
    /* the format set in hx_bursts_t chooses the text of both messages */
    for (k = 0; k < 400u; k++) {
        t[k] = ((int64_t)(k / 4u) + 1) * 10000000 + 5000 * (int64_t)(k % 4u);
    }
    assert_int_equal(hx_stamp_bursts(t, 400u, 0.2, &b), HX_BURSTS_CLOSE);
    assert_int_equal(b.format, HX_FMT_AUTO);
    b.format = HX_FMT_BIN;
    assert_non_null(strstr(hx_bursts_text(&b, "W", "S", msg, sizeof msg),
                           "400 Hz; W: convert it to CSV without the time column (bin/harness convert LOG out.csv; cut "
                           "-d, -f2- out.csv > in.csv) and give in.csv --input-rate 400 (docs/harness.md, \"S\")"));
    assert_non_null(strstr(hx_bursts_rate_text(&b, "R", 50.0, 1, msg, sizeof msg),
                           "R 50 Hz, the rate the file states, which the samples' span does not keep: convert it to CSV "
                           "without the time column"));
    b.format = HX_FMT_CSV;
    assert_non_null(strstr(hx_bursts_rate_text(&b, "R", 2e5, 0, msg, sizeof msg),
                           "the stamps' rate, not the sampling rate: leave the time column out and give --input-rate 400 ("));
}

/* The Xsens packet counter of ipol_gait_xsens has 16 bits: past 65535 it
 * wraps to 0 (and a packet may be lost across the wrap), which must read as
 * time going on, not backwards. */
static void test_ipol_counter_wrap(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    FILE *f;
    long c;
    size_t k;
    (void)state;
    tmp_path(p, sizeof p, "_lf.txt");
    f = fopen(p, "w");
    assert_non_null(f);
    fprintf(f, "Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n");
    for (c = 65530; c < 65536 + 6; c++) {
        if (c == 65536 + 1) {
            continue; /* lost, just after the wrap */
        }
        fprintf(f, "%ld.0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\t-0.58\t-0.15\t-0.4\n", c % 65536);
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_IPOL);
    assert_int_equal(log.n, 11);
    for (k = 1; k < log.n; k++) {
        const uint32_t d = log.seq[k] - log.seq[k - 1];
        assert_true(d == (k == 7 ? 2u : 1u));
        assert_true(log.t_ns[k] - log.t_ns[k - 1] == 10000000LL * (int64_t)d);
    }
    hx_log_free(&log);
    unlink(p);
}

/* PicoQuake's acquisition CSV (its writer, AcquisitionData.to_csv): the
 * first line names it; the count's rate is the '# Config:' line's
 * data_rate (with "Hz" or without, as PLab's versions differ); g and deg/s
 * to SI; a count skipped is a drop; --input-rate replaces the rate with a
 * warning; the header alone (the preamble cut off) is known but needs
 * --input-rate; a data_rate that is no rate is refused at its line, or
 * with --input-rate warned about; "data_rate = 2" (PLab's library's
 * 12.5 Hz setting, sampled at 25 Hz by its firmware) is refused, or with
 * --input-rate warned about, "2 Hz" is 2 Hz; a second Config line is not
 * read, with a warning. */
static void test_picoquake(void **state)
{
    static const char *const pre = "# PLab PicoQuake Data\n"
                                   "# Time: 2024-04-21 15:54:46.333682, Device: D4E9 (E6632891E36F2029), FW: 1.0\n"
                                   "# Num. samples: 4, Duration: 0.008 s\n";
    static const char *const rows = "count,a_x,a_y,a_z,g_x,g_y,g_z\n"
                                    "1,0.5,-0.25,1,90,-45,0\n2,0.5,-0.25,1,90,-45,0\n"
                                    "4,0.5,-0.25,1,90,-45,0\n5,0.5,-0.25,1,90,-45,0\n";
    static const struct {
        const char *config; /* the '# Config:' line ("" none) */
        double rate_opt, rate_hz;
        int ok;
        const char *err;  /* NULL: no error */
        const char *warn; /* a warning said (NULL: none of the preamble's) */
    } k[] = {
        { "# Config: data_rate = 500.0 Hz, filter = 42 Hz, acc_range = 4 g, gyro_range = 250.0 dps\n", 0.0, 500.0, 1,
          NULL, NULL },
        { "# Config: data_rate = 500.0, filter = 42, acc_range = 4, gyro_range = 250.0\n", 0.0, 500.0, 1, NULL, NULL },
        { "# Config: data_rate = 500.0 Hz, filter = 42 Hz, acc_range = 4 g, gyro_range = 250.0 dps\n", 250.0, 250.0,
          1, NULL, "--input-rate 250 Hz replaces the rate the file states (500 Hz on line 4)" },
        { "", 0.0, 0.0, 0, "no '# Config: data_rate = N' line before the header", NULL },
        { "", 200.0, 200.0, 1, NULL, NULL },
        { "# Config: data_rate = fast, filter = 42\n", 0.0, 0.0, 0,
          ":4: expected '# Config: data_rate = N Hz, ...', a rate in Hz", NULL },
        { "# Config: data_rate = 500 kHz, filter = 42\n", 0.0, 0.0, 0, ":4: expected '# Config: data_rate", NULL },
        { "# Config: data_rate = fast, filter = 42\n", 250.0, 250.0, 1, NULL,
          ":4: the data_rate of '# Config:' is no rate in Hz; --input-rate 250 Hz is read" },
        { "# Config: data_rate = 2, filter = 42, acc_range = 4, gyro_range = 250.0\n", 0.0, 0.0, 0,
          ":4: data_rate = 2 is no PicoQuake rate: a version of PLab's library writes 2 for its 12.5 Hz setting, "
          "whose index its firmware reads as 25 Hz; give the rate with --input-rate", NULL },
        { "# Config: data_rate = 2 Hz, filter = 42 Hz\n", 0.0, 2.0, 1, NULL, NULL },
        { "# Config: data_rate = 2, filter = 42\n", 25.0, 25.0, 1, NULL,
          ":4: data_rate = 2 is no PicoQuake rate; --input-rate 25 Hz is read" },
        { "# Config: data_rate = 500.0 Hz, filter = 42 Hz\n# Config: data_rate = 100.0 Hz, filter = 42 Hz\n", 0.0,
          500.0, 1, NULL, ":5: a second '# Config:' line, not read (the first, line 4, is the file's)" },
    };
    char p[256], err[320], text[1024];
    hx_log_t log;
    size_t i;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    for (i = 0; i < sizeof k / sizeof k[0]; i++) {
        snprintf(text, sizeof text, "%s%s%s", pre, k[i].config, rows);
        write_text(p, text);
        assert_int_equal(hx_detect_file(p), HX_FMT_PICOQUAKE);
        if (!k[i].ok) {
            assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, k[i].rate_opt, err, sizeof err), -1);
            assert_non_null(strstr(err, k[i].err));
            continue;
        }
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, k[i].rate_opt, err, sizeof err), 0);
        assert_int_equal(log.meta.format, HX_FMT_PICOQUAKE);
        assert_true(log.meta.rate_hz == k[i].rate_hz);
        assert_int_equal(log.n, 4);
        assert_true(log.t_ns[0] == (int64_t)(1e9 / k[i].rate_hz + 0.5)); /* count 1 */
        assert_true(log.t_ns[2] - log.t_ns[1] == (int64_t)(2e9 / k[i].rate_hz + 0.5)); /* 3 skipped */
        assert_true(log.seq[0] == 1u && log.seq[2] - log.seq[1] == 2u);
        /* the values read in double, scaled, held as fnav_real_t: within
         * float32's rounding (2^-24 relative) of the SI value */
        assert_true(fabs(log.acc[0][0] - 0.5 * HX_G_MPS2) <= 6e-8 * 0.5 * HX_G_MPS2);
        assert_true(fabs(log.acc[0][1] + 0.25 * HX_G_MPS2) <= 6e-8 * 0.25 * HX_G_MPS2);
        assert_true(fabs(log.acc[0][2] - HX_G_MPS2) <= 6e-8 * HX_G_MPS2);
        assert_true(fabs(log.gyr[0][0] - 90.0 * HX_DPS_RPS) <= 6e-8 * 90.0 * HX_DPS_RPS);
        assert_true(fabs(log.gyr[0][1] + 45.0 * HX_DPS_RPS) <= 6e-8 * 45.0 * HX_DPS_RPS);
        if (k[i].warn != NULL) {
            /* that warning, and no other of the rate's */
            assert_non_null(strstr(log.warnings, k[i].warn));
            assert_true(strstr(k[i].warn, "replaces") != NULL || strstr(log.warnings, "replaces") == NULL);
            assert_true(strstr(k[i].warn, "is read") != NULL || strstr(log.warnings, "is read") == NULL);
            assert_true(strstr(k[i].warn, "second") != NULL || strstr(log.warnings, "second") == NULL);
        } else {
            assert_null(strstr(log.warnings, "replaces"));
            assert_null(strstr(log.warnings, "Config"));
            assert_null(strstr(log.warnings, "data_rate"));
        }
        assert_string_equal(log.meta.sensor, "PLab PicoQuake (ICM-42688-P)");
        hx_log_free(&log);
    }
    /* the header alone: known by its names, the rate asked for */
    write_text(p, rows);
    assert_int_equal(hx_detect_file(p), HX_FMT_PICOQUAKE);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, "(give --input-rate; the header count,a_x,...,g_z is read as PLab PicoQuake's, in g "
                                "and deg/s: for another layout give --from csv with --columns, --units and --input-rate)"));
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 500.0, err, sizeof err), 0);
    assert_int_equal(log.n, 4);
    hx_log_free(&log);
    unlink(p);
}

/* ipol: the rate of line 1 gives the time of each packet count, and
 * --input-rate overrides it (the file has a counter, no time stamps; the
 * reader warns "ignored" only for time-stamped formats); a counter that
 * drops by less than half its 16-bit range is no wrap but a step back in
 * time, an error at its line. Hand-made mutants ignoring --input-rate for
 * ipol and taking any drop for a wrap (65536 counts on, 655 s at 100 Hz)
 * passed every suite. */
static void test_ipol_rate_and_step_back(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    FILE *f;
    long c;
    (void)state;
    tmp_path(p, sizeof p, "_lf.txt");
    f = fopen(p, "w");
    assert_non_null(f);
    fprintf(f, "Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n");
    for (c = 10; c < 14; c++) {
        fprintf(f, "%ld.0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\t-0.58\t-0.15\t-0.4\n", c);
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 50.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_IPOL);
    assert_true(log.meta.rate_hz == 50.0);
    assert_int_equal(log.n, 4);
    assert_true(log.t_ns[0] == 200000000LL); /* count 10 at 50 Hz */
    assert_true(log.t_ns[1] - log.t_ns[0] == 20000000LL);
    assert_null(strstr(log.warnings, "ignored"));
    hx_log_free(&log);
    /* without it, 100 Hz from line 1; then 13 -> 11: back in time */
    f = fopen(p, "a");
    assert_non_null(f);
    fprintf(f, "11.0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\t-0.58\t-0.15\t-0.4\n");
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_true(log.meta.rate_hz == 100.0);
    assert_int_equal(log.n, 4);
    assert_true(log.t_ns[1] - log.t_ns[0] == 10000000LL);
    assert_int_equal(log.status, FNAV_E_TIME);
    assert_non_null(strstr(log.error, ":7: time goes backwards"));
    hx_log_free(&log);
    unlink(p);
}

/* A row with the columns the reader uses but fewer fields than the header
 * names: a field lost inside it shifts the values after it (Acc_Y lost: az
 * read from Gyr_X), which nothing can tell from trailing fields left off.
 * Read, but counted and warned with the first such line (not read
 * silently); a file without one,
 * and a cut last line that lost its trailing fields, have no warning. */
static void test_short_rows_warned(void **state)
{
    static const char row[] = "%ld.0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\t-0.58\t-0.15\t-0.4\n";
    char p[256], err[320];
    hx_log_t log;
    FILE *f;
    long c;
    int pass;
    (void)state;
    tmp_path(p, sizeof p, "_lf.txt");
    for (pass = 0; pass < 3; pass++) {
        f = fopen(p, "w");
        assert_non_null(f);
        fprintf(f, "Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n");
        for (c = 0; c < 20; c++) {
            if (pass == 0 && (c == 5 || c == 9)) {
                fprintf(f, "%ld.0\t5.09\t8.92\t-0.0025\t0.0089\t-0.0178\t-0.58\t-0.15\t-0.4\n", c); /* Acc_Y lost */
            } else {
                fprintf(f, row, c);
            }
        }
        if (pass == 2) {
            fprintf(f, "20.0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\t-0.58"); /* cut: no newline */
        }
        assert_int_equal(fclose(f), 0);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.meta.format, HX_FMT_IPOL);
        assert_int_equal(log.n, pass == 2 ? 21 : 20);
        if (pass == 0) {
            assert_true(fabs(log.acc[5][2] + 0.0025) < 1e-7); /* the shift the warning is about */
            assert_non_null(strstr(log.warnings, "_lf.txt:8: 2 rows with fewer fields than the header's 10"));
        } else {
            assert_null(strstr(log.warnings, "fewer fields"));
        }
        hx_log_free(&log);
    }
    unlink(p);
    /* a header that ends in a delimiter names no column there (a
     * spreadsheet's export): rows without it have every field the header
     * names (none is warned "fewer fields than the header's 9"); a row that
     * lost a field still is, against 8 */
    tmp_path(p, sizeof p, ".csv");
    for (pass = 0; pass < 2; pass++) {
        f = fopen(p, "w");
        assert_non_null(f);
        fprintf(f, "t,ax,ay,az,gx,gy,gz,mx,\n");
        for (c = 0; c < 20; c++) {
            if (pass == 1 && c == 6) {
                fprintf(f, "%ld.01,0.01,9.81,0.001,0.002,0.003,0.4\n", c); /* ay lost */
            } else {
                fprintf(f, "%ld.01,0.01,0.02,9.81,0.001,0.002,0.003,0.4\n", c);
            }
        }
        assert_int_equal(fclose(f), 0);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.meta.format, HX_FMT_CSV);
        assert_int_equal(log.n, 20);
        if (pass == 0) {
            assert_null(strstr(log.warnings, "fewer fields"));
        } else {
            assert_non_null(strstr(log.warnings, ".csv:8: 1 row with fewer fields than the header's 8"));
        }
        assert_null(strstr(log.warnings, "more fields"));
        hx_log_free(&log);
    }
    unlink(p);
}

/* A row with more fields than the header names: a stray delimiter inside
 * it shifts the values after it (0.01,5,0.01,... read as ax = 5, az =
 * 0.02, gx = 9.81), which must not go without a word. Read, as a row with
 * fewer fields is, but counted and warned
 * with the first such line; when every row has more, the message says the
 * header may lack a column's name. What exporters write is no extra field:
 * an empty field after a trailing delimiter on every row (also with an
 * MT Manager export's tabs, and a stray comma among such rows is still
 * counted); a file without either has no warning. */
static void test_long_rows_warned(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    FILE *f;
    long c;
    int pass;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    for (pass = 0; pass < 5; pass++) {
        f = fopen(p, "w");
        assert_non_null(f);
        fprintf(f, "t,ax,ay,az,gx,gy,gz\n");
        for (c = 0; c < 20; c++) {
            const char *tail = pass == 1 || pass == 2 ? "," : pass == 3 ? ",7.5" : "";
            if ((pass == 0 || pass == 2) && (c == 4 || c == 11)) {
                fprintf(f, "%ld.01,5,0.01,0.02,9.81,0.001,0.002,0.003%s\n", c, tail); /* a stray comma */
            } else {
                fprintf(f, "%ld.01,0.01,0.02,9.81,0.001,0.002,0.003%s\n", c, tail);
            }
        }
        assert_int_equal(fclose(f), 0);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.meta.format, HX_FMT_CSV);
        assert_int_equal(log.n, 20);
        if (pass == 0 || pass == 2) {
            assert_true(log.acc[4][0] == (double)(fnav_real_t)5.0); /* the shift the warning is about */
            assert_true(log.gyr[4][0] == (double)(fnav_real_t)9.81);
            assert_non_null(strstr(log.warnings, ".csv:6: 2 rows with more fields than the header's 7 (the first "
                                                 "here): where a stray delimiter split a field, the values after it "
                                                 "were read from the wrong columns"));
            assert_null(strstr(log.warnings, "every row"));
        } else if (pass == 3) {
            assert_true(log.acc[4][0] == (double)(fnav_real_t)0.01);
            assert_non_null(strstr(log.warnings, ".csv:2: every row (20) has more fields than the header's 7"));
            assert_non_null(strstr(log.warnings, "the header may lack a column's name"));
        } else {
            assert_true(log.acc[4][0] == (double)(fnav_real_t)0.01);
            assert_null(strstr(log.warnings, "more fields"));
        }
        hx_log_free(&log);
    }
    /* an MT Manager export whose rows end in a tab: no warning; with a
     * stray tab in one, a warning */
    for (pass = 0; pass < 2; pass++) {
        f = fopen(p, "w");
        assert_non_null(f);
        fprintf(f, "// Update Rate: 100.0Hz\nPacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n");
        for (c = 0; c < 10; c++) {
            fprintf(f, "%ld\t%ld\t0.1\t%s0.2\t9.8\t0.01\t0.02\t0.03\t\n", c, 1000 + 100 * c,
                    pass == 1 && c == 3 ? "\t" : "");
        }
        assert_int_equal(fclose(f), 0);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.meta.format, HX_FMT_MTMGR);
        if (pass == 0) {
            assert_int_equal(log.n, 10);
            assert_null(strstr(log.warnings, "more fields"));
        } else {
            /* the shifted row has an empty Acc_Y: skipped as a lost packet, and its fields counted */
            assert_non_null(strstr(log.warnings, ".csv:6: 1 row with more fields than the header's 8 (the first here)"));
        }
        hx_log_free(&log);
    }
    unlink(p);
}

/* The reader's limit of 1e6 applies in SI units, after the importer's scale
 * (docs/log-format.md: "a value ... beyond 1e6 in SI units"): in an NGIMU
 * log 1.5e6 deg/s is 26,180 rad/s, read; 2e5 g is 1.96e6 m/s^2, refused at
 * its line. A mutant comparing the raw value passed every suite. */
static void test_range_in_si_units(void **state)
{
    static const char head[] = "Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s),"
                               "Accelerometer X (g),Accelerometer Y (g),Accelerometer Z (g)\n";
    char p[256], text[512];
    readall_t r;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    snprintf(text, sizeof text, "%s0,1.5e6,0,0,0,0,1\n0.0025,0,0,0,0,0,1\n", head);
    write_text(p, text);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.end, FNAV_END);
    assert_int_equal(r.n, 2);
    FNAV_ASSERT_CLOSE(r.s[0].gyro_rps[0], 1.5e6 * 3.14159265358979323846 / 180.0, 0.0, 1e-6);
    snprintf(text, sizeof text, "%s0,0,0,0,0,0,1\n0.0025,0,0,0,2e5,0,1\n", head);
    write_text(p, text);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.n, 1);
    assert_int_equal(r.end, FNAV_E_RANGE);
    assert_non_null(strstr(r.err, ":3: column 5 ('2e5' g, 1.96e+06 m/s^2) is beyond 1e+06 in SI units"));
    unlink(p);
}

/* Quotes around values are ignored as around names (docs/log-format.md,
 * "CSV interchange"; spreadsheets quote every field), and an ipol rate
 * beyond 1e6 Hz is refused at line 1 as one that is no number. Hand-made
 * mutants keeping a leading quote and dropping the rate's bound passed
 * every suite. */
static void test_quoted_values_and_ipol_rate(void **state)
{
    char p[256];
    readall_t r;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "\"t\",\"ax\",\"ay\",\"az\",\"gx\",\"gy\",\"gz\"\n\"0.5\",\"1\",\"2\",\"3\",\"4\",\"5\",\"-6.25\"\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.end, FNAV_END);
    assert_int_equal(r.n, 1);
    assert_true(r.s[0].t_ns == 500000000LL);
    assert_true((float)r.s[0].accel_mps2[0] == 1.0f);
    assert_true((float)r.s[0].gyro_rps[2] == -6.25f);
    unlink(p);
    tmp_path(p, sizeof p, "_lf.txt");
    write_text(p, "Acquisition frequency: 2000000 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), -1);
    assert_non_null(strstr(r.err, ":1: expected 'Acquisition frequency: N Hz'"));
    unlink(p);
}

/* Negative time stamps (a log timed from an event) are read exactly, as
 * the writer writes them ("-%lld.%09lld"): -1.5 s, -1 ns, 0. A mutant
 * dropping the sign of the exact decimal path passed every suite; it read
 * the first two as positive and stopped with "time goes backwards". */
static void test_csv_negative_time(void **state)
{
    char p[256];
    readall_t r;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "t,ax,ay,az,gx,gy,gz\n-1.5,0,0,9.8,0,0,0\n-0.000000001,0,0,9.8,0,0,0\n0,0,0,9.8,0,0,0\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.end, FNAV_END);
    assert_int_equal(r.n, 3);
    assert_true(r.s[0].t_ns == -1500000000LL);
    assert_true(r.s[1].t_ns == -1LL);
    assert_true(r.s[2].t_ns == 0);
    unlink(p);
}

/* Importer -> .bin -> CSV -> read: every value equals the importer's value
 * rounded to float32, every time stamp is exact. */
static void test_roundtrip_all_formats(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof k_importers / sizeof k_importers[0]; i++) {
        char p[512], b[256], c[256], err[320];
        hx_log_t orig, back;
        hx_reader_t *r;
        hx_writer_t *w;
        fnav_sample_t s;
        hx_meta_t m;
        size_t k;
        int ax;
        if (fnav_testdata_path(k_importers[i].rel, p, sizeof p) != 0) {
            fnav_test_skip_notice(k_importers[i].rel);
            continue;
        }
        tmp_path(b, sizeof b, ".bin");
        tmp_path(c, sizeof c, ".csv");
        /* importer -> bin */
        r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
        assert_non_null(r);
        m = *hx_reader_meta(r);
        w = hx_writer_open(b, HX_FMT_BIN, &m, 0, err, sizeof err);
        assert_non_null(w);
        while (hx_reader_next(r, &s) == FNAV_OK) {
            assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
        }
        hx_reader_close(r);
        assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
        /* bin -> csv */
        r = hx_reader_open(b, HX_FMT_AUTO, 0.0, err, sizeof err);
        assert_non_null(r);
        m = *hx_reader_meta(r);
        w = hx_writer_open(c, HX_FMT_CSV, &m, 0, err, sizeof err);
        assert_non_null(w);
        while (hx_reader_next(r, &s) == FNAV_OK) {
            assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
        }
        hx_reader_close(r);
        assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
        assert_int_equal(hx_log_load(&orig, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(hx_log_load(&back, c, HX_FMT_CSV, 0.0, err, sizeof err), 0);
        assert_int_equal(orig.n, back.n);
        for (k = 0; k < orig.n; k++) {
            assert_true(orig.t_ns[k] == back.t_ns[k]);
            for (ax = 0; ax < 3; ax++) {
                if ((float)orig.acc[k][ax] != (float)back.acc[k][ax] ||
                    (float)orig.gyr[k][ax] != (float)back.gyr[k][ax]) {
                    fail_msg("%s sample %zu axis %d changed beyond float32 rounding", k_importers[i].rel, k, ax);
                }
            }
        }
        hx_log_free(&orig);
        hx_log_free(&back);
        unlink(b);
        unlink(c);
    }
}

/* A .bin whose header gives no rate (0, "unknown", as live records when the
 * device names none) gets the rate of its time stamps, as a time-stamped
 * text log does: the estimate read the .bin as text and gave nothing, and
 * allan, for one, fell back on the first interval alone. 1,000 samples
 * at 5 ms with a 1 ms jitter on every fourth interval: median 5 ms. */
static void test_bin_rate_unknown(void **state)
{
    char p[256], err[320];
    hx_writer_t *w;
    hx_reader_t *r;
    hx_meta_t m;
    fnav_sample_t s;
    int i;
    (void)state;
    tmp_path(p, sizeof p, ".bin");
    memset(&m, 0, sizeof m);
    memset(&s, 0, sizeof s);
    w = hx_writer_open(p, HX_FMT_BIN, &m, 0, err, sizeof err);
    assert_non_null(w);
    for (i = 0; i < 1000; i++) {
        s.t_ns = (int64_t)i * 5000000 + (i % 4 == 1 ? 1000000 : 0);
        s.accel_mps2[2] = FNAV_R(9.81);
        assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
    }
    assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
    r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_non_null(r);
    assert_int_equal(hx_reader_meta(r)->format, HX_FMT_BIN);
    assert_true(fabs(hx_reader_meta(r)->rate_hz - 200.0) < 1e-9);
    assert_int_equal(hx_reader_meta(r)->rate_nominal, 0);
    hx_reader_close(r);
    unlink(p);
}

/* A recording killed mid-write (no end record, partial last record) still
 * yields every complete record. */
static void test_killed_writer(void **state)
{
    char p[256], err[320];
    hx_writer_t *w;
    hx_meta_t m;
    fnav_sample_t s;
    readall_t r;
    FILE *f;
    int i;
    (void)state;
    memset(&m, 0, sizeof m);
    m.rate_hz = 200.0;
    snprintf(m.sensor, sizeof m.sensor, "test");
    tmp_path(p, sizeof p, ".bin");
    w = hx_writer_open(p, HX_FMT_BIN, &m, 1, err, sizeof err);
    assert_non_null(w);
    memset(&s, 0, sizeof s);
    for (i = 0; i < 10; i++) {
        s.t_ns = (int64_t)i * 5000000;
        s.seq = (uint32_t)i;
        s.accel_mps2[2] = FNAV_R(-9.81);
        assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
    }
    /* simulate the kill: the file is complete up to here (sync_each), the
     * writer is never closed; append half a record as a torn write */
    f = fopen(p, "ab");
    assert_non_null(f);
    assert_int_equal(fwrite("\x01\xa5\x00\x00\x0a\x00\x00\x00", 1, 8, f), 8);
    fclose(f);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &r, NULL), 0);
    assert_int_equal(r.n, 10);
    assert_int_equal(r.end, FNAV_E_TRUNCATED);
    assert_non_null(strstr(r.err, "10 complete records"));
    (void)hx_writer_close(w, err, sizeof err); /* release; rewrites nothing already read */
    unlink(p);
}

static void test_format_names(void **state)
{
    int i;
    (void)state;
    for (i = 1; i < HX_FMT_COUNT; i++) {
        assert_int_equal(hx_format_from_name(hx_format_name((hx_format_t)i)), i);
    }
    assert_int_equal(hx_format_from_name("nonsense"), HX_FMT_COUNT);
}

/* --columns and --units: the interchange CSV under another layout (a phone
 * app's export: ns stamps, g, deg/s) read without an awk conversion
 * (docs/log-format.md, "Another layout"), without rewriting the file
 * first. */
/* The rate the time-unit checks judge (hx_time_unit_rate): the span of the
 * samples has the last word on a rate out of 20 Hz - 100 kHz. Judging the
 * median interval alone, info, allan, psd and simgap would tell stamps in
 * bursts time=ms (tests/cli/test_foundation.sh). */
static void test_time_unit_rate(void **state)
{
    (void)state;
    /* 4 samples 5 us apart every 10 ms: 200 kHz from the median interval,
     * 16539 samples over 41.34 s (400 Hz): no unit to question */
    assert_true(hx_time_unit_rate(2e5, 16539u, 10000000, 41350015000) == 0.0);
    /* one stamp per 100 samples, 2 s apart: 0.5 Hz from the distinct
     * stamps, 50 Hz over the log */
    assert_true(hx_time_unit_rate(0.5, 16539u, 0, 330000000000) == 0.0);
    /* a wrong unit moves the span alike: ms read as ns (100 MHz, 300
     * samples 10 ns apart), ms read as s (0.1 Hz, 300 samples 10 s apart) */
    assert_true(hx_time_unit_rate(1e8, 300u, 0, 2990) == 1e8);
    assert_true(hx_time_unit_rate(0.1, 300u, 0, 2990000000000) == 0.1);
    /* the span on the other side of the band still disagrees: no unit */
    assert_true(hx_time_unit_rate(2e5, 5u, 0, 4000000000) == 0.0);
    /* a rate in the band stays, whatever the span (a log with a day's
     * pause is no unit mistake); 0 (no rate) stays 0 */
    assert_true(hx_time_unit_rate(400.0, 1000u, 0, 86400000000000) == 400.0);
    assert_true(hx_time_unit_rate(400.0, 1000u, 0, 2497500) == 400.0);
    assert_true(hx_time_unit_rate(0.0, 1000u, 0, 2497500000) == 0.0);
    /* no span (one sample, the last stamp not after the first): the
     * intervals alone */
    assert_true(hx_time_unit_rate(2e5, 1u, 5, 5) == 2e5);
    assert_true(hx_time_unit_rate(2e5, 100u, 7000, 7000) == 2e5);
    assert_true(hx_time_unit_rate(0.1, 100u, 9000, 1000) == 0.1);
    /* the band's edges are in it: 20 Hz and 100 kHz over the span */
    assert_true(hx_time_unit_rate(0.5, 21u, 0, 1000000000) == 0.0);
    assert_true(hx_time_unit_rate(2e5, 100001u, 0, 1000000000) == 0.0);
    assert_true(hx_time_unit_rate(2e5, 100002u, 0, 1000000000) == 2e5);
}

/* The names of a header matched without --columns (hx_names.h;
 * docs/log-format.md, "Names read without --columns"): one name */
static void test_name_classify(void **state)
{
    hx_name_class_t c0;
    static const struct {
        const char *name;
        hx_name_kind_t kind;
        int key;
        hx_name_unit_t unit;
    } k[] = {
        /* time */
        { "t", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "Time", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "timestamp", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "TimeStamp", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "time stamp", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "ts", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "time_s", HX_NAME_MATCH, 0, HX_UNIT_S },
        { "timestamp_ns", HX_NAME_MATCH, 0, HX_UNIT_NS },
        { "Time [ms]", HX_NAME_MATCH, 0, HX_UNIT_MS },
        { "t (us)", HX_NAME_MATCH, 0, HX_UNIT_US },
        { "time_sec", HX_NAME_MATCH, 0, HX_UNIT_S },
        { "SampleTimeFine", HX_NAME_NEAR, 0, HX_UNIT_NONE },
        { "time_utc", HX_NAME_NEAR, 0, HX_UNIT_NONE },
        /* a date and time's column (test_datetime_stamps), a zone in brackets */
        { "DateTime", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "Date Time", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "date_time", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "datetime", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "Time (UTC)", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "time (-07:00)", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "Timestamp [+0200]", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "time (local)", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "time (abc)", HX_NAME_NEAR, 0, HX_UNIT_NONE },
        { "time (+2:0)", HX_NAME_NEAR, 0, HX_UNIT_NONE },
        { "ax (UTC)", HX_NAME_NEAR, 1, HX_UNIT_NONE }, /* a zone is a time's */
        /* Arduino's clocks, named by their unit; an elapsed time */
        { "millis", HX_NAME_MATCH, 0, HX_UNIT_MS },
        { "micros", HX_NAME_MATCH, 0, HX_UNIT_US },
        { "millis [s]", HX_NAME_MATCH, 0, HX_UNIT_S },
        { "Elapsed", HX_NAME_MATCH, 0, HX_UNIT_NONE },
        { "elapsed (s)", HX_NAME_MATCH, 0, HX_UNIT_S },
        { "Elapsed Time [ms]", HX_NAME_MATCH, 0, HX_UNIT_MS },
        { "Gyro X (deg/sec)", HX_NAME_MATCH, 4, HX_UNIT_DPS },
        { "acc_z [m/sec^2]", HX_NAME_MATCH, 3, HX_UNIT_MPS2 },
        { "time [g]", HX_NAME_NEAR, 0, HX_UNIT_G }, /* a unit of another quantity */
        /* EuRoC's and TUM-VI's ASL names; a negative power of the second */
        { "w_RS_S_x [rad s^-1]", HX_NAME_MATCH, 4, HX_UNIT_RPS },
        { "a_RS_S_z [m s^-2]", HX_NAME_MATCH, 3, HX_UNIT_MPS2 },
        { "acc_x [m.s-2]", HX_NAME_MATCH, 1, HX_UNIT_MPS2 },
        { "gyro_y (deg*s^-1)", HX_NAME_MATCH, 5, HX_UNIT_DPS },
        { "acc_x [m s^-1]", HX_NAME_NEAR, 1, HX_UNIT_NONE },   /* m/s: none read */
        { "w_RS_S_x [m s^-2]", HX_NAME_NEAR, 4, HX_UNIT_MPS2 }, /* an acceleration's unit */
        { "a_RS_x", HX_NAME_OTHER, -1, HX_UNIT_NONE }, /* "a" a stem only glued (ax) */
        { "w_RS_B_x", HX_NAME_NEAR, 4, HX_UNIT_NONE },
        { "timestamp [ns]", HX_NAME_MATCH, 0, HX_UNIT_NS },
        /* accelerations */
        { "acc_x", HX_NAME_MATCH, 1, HX_UNIT_NONE },
        { "AccX", HX_NAME_MATCH, 1, HX_UNIT_NONE },
        { "accY", HX_NAME_MATCH, 2, HX_UNIT_NONE },
        { "ACC_Z", HX_NAME_MATCH, 3, HX_UNIT_NONE },
        { "accel_x", HX_NAME_MATCH, 1, HX_UNIT_NONE },
        { "Accelerometer Y (g)", HX_NAME_MATCH, 2, HX_UNIT_G },
        { "acceleration-z", HX_NAME_MATCH, 3, HX_UNIT_NONE },
        { "accx", HX_NAME_MATCH, 1, HX_UNIT_NONE },
        { "ax", HX_NAME_MATCH, 1, HX_UNIT_NONE },
        { "accX_mps2", HX_NAME_MATCH, 1, HX_UNIT_MPS2 },
        { "acc_x [m/s^2]", HX_NAME_MATCH, 1, HX_UNIT_MPS2 },
        /* Physics Toolbox's g-force: the specific force in g unless a
         * unit is given; its total and other words are no match */
        { "gFx", HX_NAME_MATCH, 1, HX_UNIT_G },
        { "gFz", HX_NAME_MATCH, 3, HX_UNIT_G },
        { "gfy", HX_NAME_MATCH, 2, HX_UNIT_G },
        { "GFY", HX_NAME_MATCH, 2, HX_UNIT_G },
        { "gFx (m/s^2)", HX_NAME_MATCH, 1, HX_UNIT_MPS2 },
        { "gFTotal", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "TgF", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "gFw", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "acc_x (m/s2)", HX_NAME_MATCH, 1, HX_UNIT_MPS2 },
        { "acc_z_ms2", HX_NAME_MATCH, 3, HX_UNIT_MPS2 },
        { "AccX [mg]", HX_NAME_MATCH, 1, HX_UNIT_MG },
        { "ax_g", HX_NAME_MATCH, 1, HX_UNIT_G },
        { "\"acc_y\"", HX_NAME_MATCH, 2, HX_UNIT_NONE },
        /* rates */
        { "gyr_x", HX_NAME_MATCH, 4, HX_UNIT_NONE },
        { "GyrZ", HX_NAME_MATCH, 6, HX_UNIT_NONE },
        { "gyro_y", HX_NAME_MATCH, 5, HX_UNIT_NONE },
        { "Gyro Z (deg/s)", HX_NAME_MATCH, 6, HX_UNIT_DPS },
        { "gyroscope_x", HX_NAME_MATCH, 4, HX_UNIT_NONE },
        { "gyroz", HX_NAME_MATCH, 6, HX_UNIT_NONE },
        { "wx", HX_NAME_MATCH, 4, HX_UNIT_NONE },
        { "w_y", HX_NAME_MATCH, 5, HX_UNIT_NONE },
        { "omega_z", HX_NAME_MATCH, 6, HX_UNIT_NONE },
        { "angvel_x", HX_NAME_MATCH, 4, HX_UNIT_NONE },
        { "Angular Velocity Y", HX_NAME_MATCH, 5, HX_UNIT_NONE },
        { "angular rate z [rad/s]", HX_NAME_MATCH, 6, HX_UNIT_RPS },
        { "rotation rate x", HX_NAME_MATCH, 4, HX_UNIT_NONE },
        { "gyrZ_rps", HX_NAME_MATCH, 6, HX_UNIT_RPS },
        { "gyro_x_dps", HX_NAME_MATCH, 4, HX_UNIT_DPS },
        { "GyroX [mdps]", HX_NAME_MATCH, 4, HX_UNIT_MDPS },
        { "gx", HX_NAME_MATCH, 4, HX_UNIT_NONE },
        { "gyr_x_degs", HX_NAME_MATCH, 4, HX_UNIT_DPS },
        /* near misses: a word besides stem, axis and unit */
        { "FreeAcc_X", HX_NAME_NEAR, 1, HX_UNIT_NONE },
        { "acc_x_lin", HX_NAME_NEAR, 1, HX_UNIT_NONE },
        { "linear_acceleration_y", HX_NAME_NEAR, 2, HX_UNIT_NONE },
        { "acc_x_filtered", HX_NAME_NEAR, 1, HX_UNIT_NONE },
        { "gravity acc z", HX_NAME_NEAR, 3, HX_UNIT_NONE },
        { "acc_world_x", HX_NAME_NEAR, 1, HX_UNIT_NONE },
        { "gyr_x_bias", HX_NAME_NEAR, 4, HX_UNIT_NONE },
        { "gyro_x_uncal", HX_NAME_NEAR, 4, HX_UNIT_NONE },
        { "acc_x [s]", HX_NAME_NEAR, 1, HX_UNIT_S }, /* a time unit on an acceleration */
        { "gyro_x_g", HX_NAME_NEAR, 4, HX_UNIT_G },
        { "acc1_x", HX_NAME_OTHER, -1, HX_UNIT_NONE }, /* a numbered sensor: not a stem */
        /* no stem, no axis, or no unit we read */
        { "mag_x", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "quat_w", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "Euler_X", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "acc", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "x", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "g", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "temp", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "acc_x (g) 2", HX_NAME_OTHER, -1, HX_UNIT_NONE },
        { "", HX_NAME_OTHER, -1, HX_UNIT_NONE },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof k / sizeof k[0]; i++) {
        hx_name_class_t c;
        const hx_name_kind_t kind = hx_name_classify(k[i].name, &c);
        if (kind != k[i].kind || c.key != k[i].key || c.unit != k[i].unit) {
            print_error("%s: kind %d key %d unit %d, expected %d %d %d\n", k[i].name, (int)kind, c.key, (int)c.unit,
                        (int)k[i].kind, k[i].key, (int)k[i].unit);
        }
        assert_int_equal(kind, k[i].kind);
        assert_int_equal(c.kind, k[i].kind);
        assert_int_equal(c.key, k[i].key);
        assert_int_equal(c.unit, k[i].unit);
    }
    {
        /* a clock's time (since 1970), one from a start, and neither */
        static const struct {
            const char *name;
            hx_name_unit_t unit;
            int clock;
        } t[] = {
            { "epoch (ms)", HX_UNIT_MS, 1 }, { "epoc (ms)", HX_UNIT_MS, 1 }, { "unix_time", HX_UNIT_NONE, 1 },
            { "Epoch Time [s]", HX_UNIT_S, 1 }, { "unix_timestamp_ns", HX_UNIT_NS, 1 }, { "epoch", HX_UNIT_NONE, 1 },
            { "elapsed (s)", HX_UNIT_S, -1 }, { "Elapsed Time", HX_UNIT_NONE, -1 }, { "Time (s)", HX_UNIT_S, 0 },
            { "time (-13:00)", HX_UNIT_NONE, 0 }, { "timestamp", HX_UNIT_NONE, 0 },
            /* AndroSensor's; "in" before a last word's unit */
            { "Time since start in ms ", HX_UNIT_MS, -1 }, { "time since start", HX_UNIT_NONE, -1 },
            { "time in us", HX_UNIT_US, 0 }, { "Timestamp in s", HX_UNIT_S, 0 },
            /* the sensor's own clock (Polar Sensor Logger's) */
            { "sensor timestamp [ns]", HX_UNIT_NS, 0 }, { "Sensor Time (ms)", HX_UNIT_MS, 0 },
        };
        for (i = 0; i < sizeof t / sizeof t[0]; i++) {
            hx_name_class_t c;
            assert_int_equal(hx_name_classify(t[i].name, &c), HX_NAME_MATCH);
            assert_int_equal(c.key, 0);
            assert_int_equal(c.unit, t[i].unit);
            assert_int_equal(c.clock, t[i].clock);
        }
        /* a word more is not a clock's name; an axis name is none; "in"
         * goes only with a unit after it */
        assert_int_equal(hx_name_classify("epoch count", &c0), HX_NAME_OTHER);
        /* the phone's time beside Polar's sensor clock: not a time name */
        assert_int_equal(hx_name_classify("Phone timestamp", &c0), HX_NAME_NEAR);
        assert_int_equal(hx_name_classify("time since boot in ms", &c0), HX_NAME_NEAR);
        assert_int_equal(hx_name_classify("time in", &c0), HX_NAME_NEAR);
        assert_int_equal(hx_name_classify("ACCELEROMETER X in g", &c0), HX_NAME_MATCH);
        assert_int_equal(c0.key, 1);
        assert_int_equal(c0.unit, HX_UNIT_G);
        assert_int_equal(hx_name_classify("acc_x", &c0), HX_NAME_MATCH);
        assert_int_equal(c0.clock, 0);
    }
}

/* Units spelled in UTF-8 (the degree, micro and superscript-two signs) are
 * their ASCII spellings; a unit not read makes the name a near miss that
 * says so (unit_unread, unit_text as the header spells it). "gx [°/s]" and
 * "acc_x [m/s²]" must be names, and a bracketed unit not read must make a
 * name a near miss. */
static void test_name_units_utf8(void **state)
{
    static const struct {
        const char *name;
        hx_name_kind_t kind;
        int key;
        hx_name_unit_t unit;
        int unread;
        const char *text; /* unit_text */
    } k[] = {
        /* U+00B0 DEGREE SIGN, U+00B5 MICRO SIGN, U+03BC GREEK SMALL MU, U+00B2 SUPERSCRIPT TWO */
        { "gx [\xc2\xb0/s]", HX_NAME_MATCH, 4, HX_UNIT_DPS, 0, "\xc2\xb0/s" },
        { "gyr_x(\xc2\xb0/s)", HX_NAME_MATCH, 4, HX_UNIT_DPS, 0, "\xc2\xb0/s" },
        { "Gyro Z (\xc2\xb0 / s)", HX_NAME_MATCH, 6, HX_UNIT_DPS, 0, "\xc2\xb0 / s" },
        { "gyro_y_\xc2\xb0/s", HX_NAME_MATCH, 5, HX_UNIT_DPS, 0, "\xc2\xb0/s" },
        { "GyroX [m\xc2\xb0/s]", HX_NAME_MATCH, 4, HX_UNIT_MDPS, 0, "m\xc2\xb0/s" },
        { "acc_x [m/s\xc2\xb2]", HX_NAME_MATCH, 1, HX_UNIT_MPS2, 0, "m/s\xc2\xb2" },
        { "AccZ (m/s\xc2\xb2)", HX_NAME_MATCH, 3, HX_UNIT_MPS2, 0, "m/s\xc2\xb2" },
        { "t [\xc2\xb5s]", HX_NAME_MATCH, 0, HX_UNIT_US, 0, "\xc2\xb5s" },
        { "t [\xce\xbcs]", HX_NAME_MATCH, 0, HX_UNIT_US, 0, "\xce\xbcs" },
        { "time_\xc2\xb5s", HX_NAME_MATCH, 0, HX_UNIT_US, 0, "\xc2\xb5s" },
        /* Latin-1 / Windows-1252 bytes (a spreadsheet's export), not UTF-8 */
        { "gx [\xb0/s]", HX_NAME_MATCH, 4, HX_UNIT_DPS, 0, "\xb0/s" },
        { "acc_y [m/s\xb2]", HX_NAME_MATCH, 2, HX_UNIT_MPS2, 0, "m/s\xb2" },
        /* the ASCII spellings keep their meaning, with their text */
        { "gx [deg/s]", HX_NAME_MATCH, 4, HX_UNIT_DPS, 0, "deg/s" },
        { "acc_x", HX_NAME_MATCH, 1, HX_UNIT_NONE, 0, "" },
        /* a unit not read: a near miss that says so */
        { "gx [\xc2\xb0/h]", HX_NAME_NEAR, 4, HX_UNIT_NONE, 1, "\xc2\xb0/h" },
        { "ax_ng", HX_NAME_NEAR, 1, HX_UNIT_NONE, 1, "ng" },
        /* micro-g, read (not a near miss "not read") */
        { "ax_\xc2\xb5g", HX_NAME_MATCH, 1, HX_UNIT_UG, 0, "\xc2\xb5g" },
        { "ax_ug", HX_NAME_MATCH, 1, HX_UNIT_UG, 0, "ug" },
        { "AccY [\xce\xbcg]", HX_NAME_MATCH, 2, HX_UNIT_UG, 0, "\xce\xbcg" },
        { "acc_x [counts]", HX_NAME_NEAR, 1, HX_UNIT_NONE, 1, "counts" },
        { "gyro_z_rad/h", HX_NAME_NEAR, 6, HX_UNIT_NONE, 1, "rad/h" },
        { "time [\xc2\xb5h]", HX_NAME_NEAR, 0, HX_UNIT_NONE, 1, "\xc2\xb5h" },
        /* another word than a unit: a near miss as before, no unit named */
        { "acc_x_lin", HX_NAME_NEAR, 1, HX_UNIT_NONE, 0, "" },
        /* no IMU name: nothing to say of its unit */
        { "mag_x [\xc2\xb5T]", HX_NAME_OTHER, -1, HX_UNIT_NONE, 0, "" },
        { "temp [\xc2\xb0" "C]", HX_NAME_OTHER, -1, HX_UNIT_NONE, 0, "" },
        /* a UTF-8 character that is none of these stays itself */
        { "acc_x [m/s\xe2\x81\xbb\xc2\xb2]", HX_NAME_NEAR, 1, HX_UNIT_NONE, 1, "m/s\xe2\x81\xbb\xc2\xb2" },
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof k / sizeof k[0]; i++) {
        hx_name_class_t c;
        const hx_name_kind_t kind = hx_name_classify(k[i].name, &c);
        if (kind != k[i].kind || c.key != k[i].key || c.unit != k[i].unit || c.unit_unread != k[i].unread ||
            strcmp(c.unit_text, k[i].text) != 0) {
            print_error("%s: kind %d key %d unit %d unread %d '%s', expected %d %d %d %d '%s'\n", k[i].name,
                        (int)kind, c.key, (int)c.unit, c.unit_unread, c.unit_text, (int)k[i].kind, k[i].key,
                        (int)k[i].unit, k[i].unread, k[i].text);
        }
        assert_int_equal(kind, k[i].kind);
        assert_int_equal(c.key, k[i].key);
        assert_int_equal(c.unit, k[i].unit);
        assert_int_equal(c.unit_unread, k[i].unread);
        assert_string_equal(c.unit_text, k[i].text);
    }
}

/* --units takes the UTF-8 spellings the names do: time=µs (U+00B5) or μs
 * (U+03BC), accel=m/s² (U+00B2), gyro=°/s (U+00B0) or m°/s, none an unknown
 * unit with exit 2. The error quotes the value as given. */
static void test_units_option_utf8(void **state)
{
    static const struct {
        const char *spec;
        int time_digits;
        double acc, gyr;
    } k[] = {
        { "time=\xc2\xb5s", 3, 1.0, 1.0 },
        { "time=\xce\xbcs,accel=m/s\xc2\xb2", 3, 1.0, 1.0 },
        { "gyro=\xc2\xb0/s", 9, 1.0, HX_DPS_RPS },
        { "gyro=m\xc2\xb0/s,accel=g", 9, HX_G_MPS2, HX_MDPS_RPS },
        { "accel=\xc2\xb5g", 9, 9.80665e-6, 1.0 },
        { "accel=\xce\xbcg", 9, 9.80665e-6, 1.0 },
        { "accel=ug", 9, 9.80665e-6, 1.0 },
        { "gyro=deg/s", 9, 1.0, HX_DPS_RPS },
    };
    size_t i;
    char err[256];
    (void)state;
    for (i = 0; i < sizeof k / sizeof k[0]; i++) {
        hx_csv_layout_t l;
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, k[i].spec, err, sizeof err), 0);
        assert_int_equal(l.time_digits, k[i].time_digits);
        assert_true(l.acc_scale == k[i].acc);
        assert_true(l.gyr_scale == k[i].gyr);
    }
    {
        hx_csv_layout_t l;
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, "gyro=\xc2\xb0/h", err, sizeof err), -1);
        assert_non_null(strstr(err, "gyro=\xc2\xb0/h: the rate unit is"));
    }
    {
        /* a count's size before the unit: raw counts at the datasheet's
         * sensitivity (0.061 mg and 8.75 mdps per LSB, an LSM6DS at 2 g
         * and 250 deg/s); the scale is the number times the unit's */
        hx_csv_layout_t l;
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, "accel=0.061mg,gyro=8.75m\xc2\xb0/s", err, sizeof err), 0);
        assert_true(l.acc_scale == 0.061 * HX_MG_MPS2);
        assert_true(l.gyr_scale == 8.75 * HX_MDPS_RPS);
        assert_string_equal(hx_accel_unit_name(l.acc_scale), "0.061mg");
        assert_string_equal(hx_gyro_unit_name(l.gyr_scale), "8.75mdps");
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, "gyro=1e-3rad/s", err, sizeof err), 0);
        assert_true(l.gyr_scale == 1e-3);
    }
    {
        /* a count's name reads back to the same scale (9 digits when
         * they do, else 17): 1/16.4 deg/s and 1e-3 rad/s did not at 9 */
        static const char *const spec[] = { "gyro=0.06097560975609756dps", "gyro=1e-3rad/s", "accel=0.48828125mg",
                                            "accel=0.1234567891234mg" };
        for (i = 0; i < sizeof spec / sizeof spec[0]; i++) {
            hx_csv_layout_t l, back;
            char again[80];
            hx_csv_layout_default(&l);
            hx_csv_layout_default(&back);
            assert_int_equal(hx_csv_units_parse(&l, spec[i], err, sizeof err), 0);
            if (spec[i][0] == 'g') {
                snprintf(again, sizeof again, "gyro=%s", hx_gyro_unit_name(l.gyr_scale));
                assert_int_equal(hx_csv_units_parse(&back, again, err, sizeof err), 0);
                assert_true(back.gyr_scale == l.gyr_scale);
            } else {
                snprintf(again, sizeof again, "accel=%s", hx_accel_unit_name(l.acc_scale));
                assert_int_equal(hx_csv_units_parse(&back, again, err, sizeof err), 0);
                assert_true(back.acc_scale == l.acc_scale);
            }
        }
    }
    {
        static const char *const bad[] = { "accel=0.061", "gyro=-1dps", "accel=0g", "gyro=1e7dps", "accel=.mg",
                                           "time=10us", "accel=2xg" };
        for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            hx_csv_layout_t l;
            hx_csv_layout_default(&l);
            assert_int_equal(hx_csv_units_parse(&l, bad[i], err, sizeof err), -1);
        }
    }
}

/* --columns names a column whose name states a unit other than the one
 * --units (or its default) reads it in: warned, naming the column, the two
 * units and the --units item that reads it so; the values are read as
 * asked: 'acc_x [g]' given with --columns alone must not be read as m/s^2
 * without a word. */
static void test_columns_unit_warned(void **state)
{
    char p[512], err[1024];
    hx_csv_layout_t l;
    hx_reader_t *r;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "time [ms],acc_x [g],acc_y [g],acc_z [g],gx [\xc2\xb0/s],gy [\xc2\xb0/s],gz [\xc2\xb0/s]\n"
                  "0,0,0,1,0,0,0\n"
                  "10,0,0,1,0,0,0\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l,
                                          "t=time [ms],ax=acc_x [g],ay=acc_y [g],az=acc_z [g],gx=gx [\xc2\xb0/s],"
                                          "gy=gy [\xc2\xb0/s],gz=gz [\xc2\xb0/s]",
                                          err, sizeof err),
                     0);
    assert_int_equal(hx_csv_units_parse(&l, "time=ms,gyro=deg/s", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_non_null(r);
    {
        char want[1024];
        snprintf(want, sizeof want,
                 "%s:1: column 2 ('acc_x [g]') names g, but the accelerations are read in m/s2 (--units "
                 "time=ms,accel=g,gyro=deg/s reads the column's unit)",
                 p);
        assert_non_null(strstr(hx_reader_warnings(r), want));
        assert_null(strstr(hx_reader_warnings(r), "column 1 ("));   /* time in ms as named */
        assert_null(strstr(hx_reader_warnings(r), "column 5 ("));   /* deg/s as named */
        assert_null(strstr(hx_reader_warnings(r), "column 3 ("));   /* the first only */
    }
    hx_reader_close(r);
    /* the units that agree: no warning */
    assert_int_equal(hx_csv_units_parse(&l, "time=ms,accel=g,gyro=deg/s", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_non_null(r);
    assert_null(strstr(hx_reader_warnings(r), "names"));
    hx_reader_close(r);
    hx_reader_set_layout(NULL);
}

/* split a header at commas into f (the text is changed) */
static int split_header(char *text, char **f, int max)
{
    int n = 0;
    char *p = text;
    for (;;) {
        char *e = strchr(p, ',');
        if (n == max) {
            return n;
        }
        f[n++] = p;
        if (e == NULL) {
            return n;
        }
        *e = '\0';
        p = e + 1;
    }
}

/* A whole header: each key one column, t at most one, one unit per quantity */
static void test_names_match(void **state)
{
    static const struct {
        const char *header;
        int ok;
        int col[7];
        hx_name_unit_t unit[3];
        const char *give; /* hx_names_give */
    } k[] = {
        { "timestamp,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1, { 0, 1, 2, 3, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=timestamp,ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        { "Time,AccX,AccY,AccZ,GyrX,GyrY,GyrZ", 1, { 0, 1, 2, 3, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=Time,ax=AccX,ay=AccY,az=AccZ,gx=GyrX,gy=GyrY,gz=GyrZ" },
        { "time,ax,ay,az,wx,wy,wz", 1, { 0, 1, 2, 3, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=time,ax=ax,ay=ay,az=az,gx=wx,gy=wy,gz=wz" },
        { "t,accel_x,accel_y,accel_z,gyro_x,gyro_y,gyro_z", 1, { 0, 1, 2, 3, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=t,ax=accel_x,ay=accel_y,az=accel_z,gx=gyro_x,gy=gyro_y,gz=gyro_z" },
        { "time_s,accX_mps2,accY_mps2,accZ_mps2,gyrX_rps,gyrY_rps,gyrZ_rps", 1, { 0, 1, 2, 3, 4, 5, 6 },
          { HX_UNIT_S, HX_UNIT_MPS2, HX_UNIT_RPS },
          "--columns t=time_s,ax=accX_mps2,ay=accY_mps2,az=accZ_mps2,gx=gyrX_rps,gy=gyrY_rps,gz=gyrZ_rps "
          "--units time=s,accel=m/s2,gyro=rad/s" },
        /* units in brackets; another order; extra columns not read */
        { "Time [ms],GyroX [deg/s],GyroY [deg/s],GyroZ [deg/s],AccX [g],AccY [g],AccZ [g],mag_x,quat_w", 1,
          { 0, 4, 5, 6, 1, 2, 3 }, { HX_UNIT_MS, HX_UNIT_G, HX_UNIT_DPS },
          "--columns 't=Time [ms],ax=AccX [g],ay=AccY [g],az=AccZ [g],gx=GyroX [deg/s],gy=GyroY [deg/s],"
          "gz=GyroZ [deg/s]' --units time=ms,accel=g,gyro=deg/s" },
        /* no time column: the six matched (the no-time path reads it) */
        { "acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,temp", 1, { -1, 0, 1, 2, 3, 4, 5 }, { 0, 0, 0 },
          "--columns ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        /* near misses are not candidates: acc_x read beside acc_x_lin */
        { "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,acc_x_lin,FreeAcc_Y", 1, { 0, 1, 2, 3, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=t,ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        /* a near miss for a channel: no match */
        { "t,FreeAcc_X,FreeAcc_Y,FreeAcc_Z,gyr_x,gyr_y,gyr_z", 0, { 0, -1, -1, -1, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=t,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        { "t,acc_x_lin,acc_y_lin,acc_z_lin,gyr_x,gyr_y,gyr_z", 0, { 0, -1, -1, -1, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=t,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        { "t,mag_x,mag_y,mag_z,quat_w,quat_x,quat_y", 0, { 0, -1, -1, -1, -1, -1, -1 }, { 0, 0, 0 },
          "--columns t=t" },
        /* duplicates: two candidates for ax, two time columns */
        { "t,acc_x,accel_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 0, { 0, -1, 3, 4, 5, 6, 7 }, { 0, 0, 0 },
          "--columns t=t,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        { "time,timestamp,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 0, { -1, 2, 3, 4, 5, 6, 7 }, { 0, 0, 0 },
          "--columns ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        /* time names that name their units: the first that does is read
         * (one clock of the samples is as good as another), the others
         * are near misses; none naming its unit (above): refused */
        { "Timestamp (ms),Time since start in ms,ax,ay,az,gx,gy,gz", 1, { 0, 2, 3, 4, 5, 6, 7 },
          { HX_UNIT_MS, 0, 0 }, "--columns 't=Timestamp (ms),ax=ax,ay=ay,az=az,gx=gx,gy=gy,gz=gz' --units time=ms" },
        { "time,Time (s),acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1, { 1, 2, 3, 4, 5, 6, 7 }, { HX_UNIT_S, 0, 0 },
          "--columns 't=Time (s),ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z' --units time=s" },
        { "acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,time_us,elapsed (s)", 1, { 6, 0, 1, 2, 3, 4, 5 }, { HX_UNIT_US, 0, 0 },
          "--columns t=time_us,ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z --units time=us" },
        /* a clock's name is the time where no other time name is; beside
         * one, the other is read (as before the clock's names were read) */
        { "epoch (ms),acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1, { 0, 1, 2, 3, 4, 5, 6 }, { HX_UNIT_MS, 0, 0 },
          "--columns 't=epoch (ms),ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z' --units time=ms" },
        { "epoch (ms),elapsed (s),acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 1, { 1, 2, 3, 4, 5, 6, 7 },
          { HX_UNIT_S, 0, 0 },
          "--columns 't=elapsed (s),ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z' --units time=s" },
        { "unix_time,epoch,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z", 0, { -1, 2, 3, 4, 5, 6, 7 }, { 0, 0, 0 },
          "--columns ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        /* AndroSensor: gravity and linear acceleration are near misses */
        { "ACCELEROMETER X (m/s\xc2\xb2),GRAVITY X (m/s\xc2\xb2),LINEAR ACCELERATION X (m/s\xc2\xb2),"
          "ACCELEROMETER Y (m/s\xc2\xb2),ACCELEROMETER Z (m/s\xc2\xb2),GYROSCOPE X (rad/s),GYROSCOPE Y (rad/s),"
          "GYROSCOPE Z (rad/s),Time since start in ms ,YYYY-MO-DD HH-MI-SS_SSS",
          1, { 8, 0, 3, 4, 5, 6, 7 }, { HX_UNIT_MS, HX_UNIT_MPS2, HX_UNIT_RPS },
          "--columns 't=Time since start in ms,ax=ACCELEROMETER X (m/s\xc2\xb2),ay=ACCELEROMETER Y (m/s\xc2\xb2),"
          "az=ACCELEROMETER Z (m/s\xc2\xb2),gx=GYROSCOPE X (rad/s),gy=GYROSCOPE Y (rad/s),gz=GYROSCOPE Z (rad/s)' "
          "--units time=ms,accel=m/s2,gyro=rad/s" },
        /* Physics Toolbox: the g-force is the specific force, in g; the
         * app's ax..az beside it (its linear acceleration, gravity
         * removed) are not read */
        { "time,gFx,gFy,gFz,ax,ay,az,wx,wy,wz,p,Bx,By,Bz", 1, { 0, 1, 2, 3, 7, 8, 9 }, { 0, HX_UNIT_G, 0 },
          "--columns t=time,ax=gFx,ay=gFy,az=gFz,gx=wx,gy=wy,gz=wz --units accel=g" },
        { "time,gFx,gFy,gFz,wx,wy,wz,p,Bx,By,Bz,Azimuth,Pitch,Roll,Latitude,Longitude,Speed (m/s)", 1,
          { 0, 1, 2, 3, 4, 5, 6 }, { 0, HX_UNIT_G, 0 },
          "--columns t=time,ax=gFx,ay=gFy,az=gFz,gx=wx,gy=wy,gz=wz --units accel=g" },
        { "time,gFx,gFy,gFz,gFTotal", 0, { 0, 1, 2, 3, -1, -1, -1 }, { 0, HX_UNIT_G, 0 },
          "--columns t=time,ax=gFx,ay=gFy,az=gFz --units accel=g" },
        /* Kalibr's IMU CSV: the stamp in ns, alpha the specific force
         * beside omega; alpha without omega is no name read (elsewhere the
         * angular acceleration) */
        { "timestamp,omega_x,omega_y,omega_z,alpha_x,alpha_y,alpha_z", 1, { 0, 4, 5, 6, 1, 2, 3 },
          { HX_UNIT_NS, 0, 0 },
          "--columns t=timestamp,ax=alpha_x,ay=alpha_y,az=alpha_z,gx=omega_x,gy=omega_y,gz=omega_z --units time=ns" },
        { "timestamp_ns,omega_x,omega_y,omega_z,alpha_x,alpha_y,alpha_z,frame_idx,t_us", 1, { 0, 4, 5, 6, 1, 2, 3 },
          { HX_UNIT_NS, 0, 0 },
          "--columns t=timestamp_ns,ax=alpha_x,ay=alpha_y,az=alpha_z,gx=omega_x,gy=omega_y,gz=omega_z --units "
          "time=ns" },
        { "t,alpha_x,alpha_y,alpha_z,gyr_x,gyr_y,gyr_z", 0, { 0, -1, -1, -1, 4, 5, 6 }, { 0, 0, 0 },
          "--columns t=t,gx=gyr_x,gy=gyr_y,gz=gyr_z" },
        /* SensorLog (iOS): the accelerometer in g read negated (iOS's
         * sign), the raw gyroRotation before CoreMotion's fused rate, the
         * accelerometer's stamp; without a rate's names no SensorLog */
        { "loggingTime(txt),loggingSample(N),accelerometerTimestamp_sinceReboot(s),accelerometerAccelerationX(G),"
          "accelerometerAccelerationY(G),accelerometerAccelerationZ(G),gyroTimestamp_sinceReboot(s),"
          "gyroRotationX(rad/s),gyroRotationY(rad/s),gyroRotationZ(rad/s),motionRotationRateX(rad/s),"
          "motionRotationRateY(rad/s),motionRotationRateZ(rad/s)",
          1, { 2, 3, 4, 5, 7, 8, 9 }, { HX_UNIT_S, HX_UNIT_G, HX_UNIT_RPS },
          "--columns 't=accelerometerTimestamp_sinceReboot(s),ax=-accelerometerAccelerationX(G),"
          "ay=-accelerometerAccelerationY(G),az=-accelerometerAccelerationZ(G),gx=gyroRotationX(rad/s),"
          "gy=gyroRotationY(rad/s),gz=gyroRotationZ(rad/s)' --units time=s,accel=g,gyro=rad/s" },
        { "accelerometerTimestamp_sinceReboot,accelerometerAccelerationX,accelerometerAccelerationY,"
          "accelerometerAccelerationZ,motionRotationRateX,motionRotationRateY,motionRotationRateZ",
          1, { 0, 1, 2, 3, 4, 5, 6 }, { HX_UNIT_S, HX_UNIT_G, HX_UNIT_RPS },
          "--columns t=accelerometerTimestamp_sinceReboot,ax=-accelerometerAccelerationX,"
          "ay=-accelerometerAccelerationY,az=-accelerometerAccelerationZ,gx=motionRotationRateX,"
          "gy=motionRotationRateY,gz=motionRotationRateZ --units time=s,accel=g,gyro=rad/s" },
        /* a blank before the unit; a unit given that is read; without the
         * accelerometer's stamp, the gyroscope's */
        { "gyroTimestamp_sinceReboot (s),accelerometerAccelerationX (m/s^2),accelerometerAccelerationY (m/s^2),"
          "accelerometerAccelerationZ (m/s^2),gyroRotationX (deg/s),gyroRotationY (deg/s),gyroRotationZ (deg/s)",
          1, { 0, 1, 2, 3, 4, 5, 6 }, { HX_UNIT_S, HX_UNIT_MPS2, HX_UNIT_DPS },
          "--columns 't=gyroTimestamp_sinceReboot (s),ax=-accelerometerAccelerationX (m/s^2),"
          "ay=-accelerometerAccelerationY (m/s^2),az=-accelerometerAccelerationZ (m/s^2),gx=gyroRotationX (deg/s),"
          "gy=gyroRotationY (deg/s),gz=gyroRotationZ (deg/s)' --units time=s,accel=m/s2,gyro=deg/s" },
        { "accelerometerTimestamp_sinceReboot(s),accelerometerAccelerationX(G),accelerometerAccelerationY(G),"
          "accelerometerAccelerationZ(G),gyro_x,gyro_y,gyro_z",
          0, { -1, -1, -1, -1, 4, 5, 6 }, { 0, 0, 0 }, "--columns gx=gyro_x,gy=gyro_y,gz=gyro_z" },
        /* one quantity in two units: no one --units item reads it */
        { "t,acc_x [g],acc_y [g],acc_z,gyr_x,gyr_y,gyr_z", 0, { 0, 1, 2, 3, 4, 5, 6 }, { 0, 0, 0 },
          "--columns 't=t,ax=acc_x [g],ay=acc_y [g],az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z'" },
        /* an Xsens export (Movella DOT: Gyr_X in deg/s): not matched */
        { "PacketCounter,SampleTimeFine,Euler_X,Euler_Y,Euler_Z,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z", 0,
          { -1, -1, -1, -1, -1, -1, -1 }, { 0, 0, 0 }, "" },
    };
    size_t i;
    int j;
    (void)state;
    for (i = 0; i < sizeof k / sizeof k[0]; i++) {
        char text[512], give[512];
        char *f[32];
        hx_names_match_t m;
        int n;
        snprintf(text, sizeof text, "%s", k[i].header);
        n = split_header(text, f, 32);
        assert_int_equal(hx_names_match(f, n, &m), k[i].ok);
        assert_int_equal(m.ok, k[i].ok);
        for (j = 0; j < 7; j++) {
            if (m.col[j] != k[i].col[j]) {
                print_error("%s: key %d column %d, expected %d\n", k[i].header, j, m.col[j], k[i].col[j]);
            }
            assert_int_equal(m.col[j], k[i].col[j]);
        }
        for (j = 0; j < 3; j++) {
            assert_int_equal(m.unit[j], k[i].unit[j]);
        }
        assert_string_equal(hx_names_give(&m, f, give, sizeof give), k[i].give);
    }
    {
        /* what a refusal says: the candidates and the near misses */
        char text[256], miss[256];
        char *f[16];
        hx_names_match_t m;
        int n;
        snprintf(text, sizeof text, "t,acc_x,accel_x,acc_y,FreeAcc_Z,gyr_x,gyr_y,gyr_z");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 0);
        assert_string_equal(hx_names_unmatched(&m, f, 1, miss, sizeof miss),
                            "ax: 2 candidates (acc_x, accel_x); az: none (near misses: FreeAcc_Z)");
        /* the time names not read beside the one read: counted, named */
        snprintf(text, sizeof text, "Timestamp (ms),Time since start in ms,ax,ay,az,gx,gy,gz");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 1);
        assert_int_equal(m.times, 2);
        assert_string_equal(hx_names_near(&m, f, miss, sizeof miss), "Time since start in ms");
        snprintf(text, sizeof text, "t,time (ms),timestamp (us),elapsed (s),time_ns,ax,ay,az,gx,gy,gz");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 1);
        assert_int_equal(m.times, 5);
        assert_int_equal(m.col[0], 1);
        assert_string_equal(hx_names_near(&m, f, miss, sizeof miss), "t, timestamp (us), elapsed (s), ...");
        /* a clock's name beside them: not read, counted and named */
        snprintf(text, sizeof text, "epoch (ms),time (-13:00),elapsed (s),ax,ay,az,gx,gy,gz");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 1);
        assert_int_equal(m.col[0], 2);
        assert_int_equal(m.times, 3);
        assert_int_equal(m.times_clock, 1);
        assert_string_equal(hx_names_near(&m, f, miss, sizeof miss), "time (-13:00), epoch (ms)");
        snprintf(text, sizeof text, "time,timestamp,ax,ay,az,gx,gy,gz");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 0);
        assert_int_equal(m.times, 0);
        assert_string_equal(hx_names_unmatched(&m, f, 1, miss, sizeof miss), "t: 2 candidates (time, timestamp)");
        /* Physics Toolbox's ax..az beside its g-force: named as not read */
        snprintf(text, sizeof text, "time,gFx,gFy,gFz,ax,ay,az,wx,wy,wz");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 1);
        assert_int_equal(m.gforce, 1);
        assert_string_equal(hx_names_near(&m, f, miss, sizeof miss), "ax, ay, az");
        snprintf(text, sizeof text, "time,ax,ay,az,wx,wy,wz");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 1);
        assert_int_equal(m.gforce, 0);
        assert_string_equal(hx_names_near(&m, f, miss, sizeof miss), "");
        snprintf(text, sizeof text, "acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z [deg/s]");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 0);
        assert_int_equal(m.units_differ, 2);
        assert_string_equal(hx_names_unmatched(&m, f, 0, miss, sizeof miss), "the rates name different units");
        assert_string_equal(hx_names_unmatched(&m, f, 1, miss, sizeof miss),
                            "t: none; the rates name different units");
        assert_true(m.excluded == 0);
        /* a unit not read, and one of another quantity: the column, its
         * name as spelled and the unit named (hx_names_unit_problem) */
        snprintf(text, sizeof text, "t,ax,ay,az,gx [\xc2\xb0/h],gy [\xc2\xb0/h],gz [\xc2\xb0/h]");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 0);
        assert_int_equal(m.unit_col, 4);
        assert_string_equal(hx_names_unit_problem(&m, f, miss, sizeof miss),
                            "column 5 ('gx [\xc2\xb0/h]') names a unit not read, '\xc2\xb0/h' (a rate's: rad/s, "
                            "deg/s or dps or \xc2\xb0/s, mdps or mdeg/s)");
        snprintf(text, sizeof text, "t,acc_x [s],acc_y [s],acc_z [s],gx,gy,gz");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 0);
        assert_int_equal(m.unit_col, 1);
        assert_string_equal(hx_names_unit_problem(&m, f, miss, sizeof miss),
                            "column 2 ('acc_x [s]') names a time unit, 's', not an acceleration's (m/s^2 or m/s2 or "
                            "m/s\xc2\xb2 or mps2, g, mg, ug or \xc2\xb5g)");
        /* a key with a candidate: its near misses' units are no problem */
        snprintf(text, sizeof text, "t,ax,ay,az,gx,gy,gz,gx [counts]");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 1);
        assert_int_equal(m.unit_col, -1);
        assert_string_equal(hx_names_unit_problem(&m, f, miss, sizeof miss), "");
        /* an Xsens export is not matched: no unit named either */
        snprintf(text, sizeof text, "PacketCounter,acc_x [counts],Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z");
        n = split_header(text, f, 16);
        assert_int_equal(hx_names_match(f, n, &m), 0);
        assert_int_equal(m.excluded, 1);
        assert_int_equal(m.unit_col, -1);
        assert_string_equal(hx_names_unit_problem(&m, f, miss, sizeof miss), "");
    }
}

/* --columns ax=-NAME: the column read with the other sign (iOS's
 * accelerations, a flipped gyro axis); refused for t and temp */
static void test_columns_negate(void **state)
{
    char p[256], err[320];
    readall_t ra;
    hx_csv_layout_t l;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,1.5,-2,9.75,0.25,-0.5,0.125\n0.01,1.5,-2,9.75,0.25,-0.5,0.125\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "ax=-acc_x,ay=acc_y,az=-acc_z,gx=gyr_x,gy=-gyr_y,gz=gyr_z", err,
                                          sizeof err), 0);
    assert_int_equal(l.negate, (1 << 1) | (1 << 3) | (1 << 5));
    assert_string_equal(l.names[1], "acc_x");
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 2);
    assert_float_equal(ra.s[1].accel_mps2[0], -1.5f, 0.0f);
    assert_float_equal(ra.s[1].accel_mps2[1], -2.0f, 0.0f);
    assert_float_equal(ra.s[1].accel_mps2[2], -9.75f, 0.0f);
    assert_float_equal(ra.s[1].gyro_rps[0], 0.25f, 0.0f);
    assert_float_equal(ra.s[1].gyro_rps[1], 0.5f, 0.0f);
    assert_float_equal(ra.s[1].gyro_rps[2], 0.125f, 0.0f);
    /* with a unit: the sign and the scale both */
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "ax=-acc_x,ay=acc_y,az=acc_z,gx=-gyr_x,gy=gyr_y,gz=gyr_z", err,
                                          sizeof err), 0);
    assert_int_equal(hx_csv_units_parse(&l, "accel=g", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_float_equal(ra.s[0].accel_mps2[0], (float)(-1.5 * 9.80665), 1e-5f);
    assert_float_equal(ra.s[0].gyro_rps[0], -0.25f, 0.0f);
    /* refused: t and temp, a '-' alone, one column twice however signed */
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=-time", err, sizeof err), -1);
    assert_non_null(strstr(err, "t=-time: a '-' before a name reads the column with the other sign, which only "
                                "ax..gz take"));
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "temp=-T", err, sizeof err), -1);
    assert_non_null(strstr(err, "which only ax..gz take"));
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=sec,tns=-nsec", err, sizeof err), -1);
    assert_non_null(strstr(err, "tns=-nsec: a '-' before a name reads the column with the other sign"));
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "ax=-", err, sizeof err), -1);
    assert_non_null(strstr(err, "ax= has an empty name"));
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "ax=-x,ay=x", err, sizeof err), -1);
    assert_non_null(strstr(err, "column 'x' is named for both ax and ay"));
    hx_reader_set_layout(NULL);
    unlink(p);
}

/* hx_columns_give, the axes check's remedy: every key the layout names,
 * the three gyro keys always (from the source key, the sign the XOR of the
 * layout's and the map's), --units when not all defaults, the map quoted
 * when a name is not one shell word; the map it gives parses back to the
 * layout with the gyro so read. */
static void test_columns_give(void **state)
{
    static const int k_swap[3] = { 1, 0, 2 }, k_same[3] = { 0, 1, 2 }, k_none[3] = { 0, 0, 0 };
    static const int k_flip_y[3] = { 0, 1, 0 }, k_rot[3] = { 1, 2, 0 }, k_neg_z[3] = { 0, 0, 1 };
    char buf[700], err[320], map[700];
    hx_csv_layout_t l, back;
    const char *q, *e;
    (void)state;
    hx_csv_layout_default(&l);
    assert_string_equal(hx_columns_give(&l, k_swap, k_none, buf, sizeof buf), "--columns gx=gy,gy=gx,gz=gz");
    assert_string_equal(hx_columns_give(&l, k_rot, k_neg_z, buf, sizeof buf), "--columns gx=gy,gy=gz,gz=-gx");
    /* tns given, t under its default name: tns kept (it was lost with t) */
    assert_int_equal(hx_csv_columns_parse(&l, "tns=nsec", err, sizeof err), 0);
    assert_string_equal(hx_columns_give(&l, k_same, k_flip_y, buf, sizeof buf), "--columns tns=nsec,gx=gx,gy=-gy,gz=gz");
    hx_csv_layout_default(&l);
    /* a layout given whole, with a sign already on gy: the flip undoes it */
    assert_int_equal(hx_csv_columns_parse(&l, "t=sec,tns=nsec,ax=-a x,ay=ay1,az=az1,gx=w1,gy=-w2,gz=w3,temp=T", err,
                                          sizeof err), 0);
    assert_int_equal(hx_csv_units_parse(&l, "accel=g,gyro=deg/s", err, sizeof err), 0);
    assert_string_equal(hx_columns_give(&l, k_same, k_flip_y, buf, sizeof buf),
                        "--columns 't=sec,tns=nsec,ax=-a x,ay=ay1,az=az1,gx=w1,gy=w2,gz=w3,temp=T' --units "
                        "accel=g,gyro=deg/s");
    /* its map parses back: the same names, gy's sign gone */
    q = strchr(buf, '\'');
    assert_non_null(q);
    e = strchr(q + 1, '\'');
    assert_non_null(e);
    snprintf(map, sizeof map, "%.*s", (int)(e - q - 1), q + 1);
    hx_csv_layout_default(&back);
    assert_int_equal(hx_csv_columns_parse(&back, map, err, sizeof err), 0);
    assert_memory_equal(back.names, l.names, sizeof l.names);
    assert_string_equal(back.tns, "nsec");
    assert_int_equal(back.negate, l.negate & ~(1 << 5));
    /* rotated: each gyro key takes its source's name and sign */
    assert_string_equal(hx_columns_give(&l, k_rot, k_neg_z, buf, sizeof buf),
                        "--columns 't=sec,tns=nsec,ax=-a x,ay=ay1,az=az1,gx=-w2,gy=w3,gz=-w1,temp=T' --units "
                        "accel=g,gyro=deg/s");
    /* names matched in ms, no blank: unquoted, the time's unit given */
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=time_ms,ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z", err,
                                          sizeof err), 0);
    assert_int_equal(hx_csv_units_parse(&l, "time=ms", err, sizeof err), 0);
    assert_string_equal(hx_columns_give(&l, k_swap, k_none, buf, sizeof buf),
                        "--columns t=time_ms,ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_y,gy=gyr_x,gz=gyr_z --units time=ms");
    /* a ' in a name is dropped inside the quotes: names match without
     * their quotes (hx_name_eq), so the map read back finds the column */
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=Time [s],ax=Acc'X,ay=ay,az=az,gx=Gyr'X,gy=gy,gz=gz", err, sizeof err),
                     0);
    assert_string_equal(hx_columns_give(&l, k_same, k_flip_y, buf, sizeof buf),
                        "--columns 't=Time [s],ax=AccX,ay=ay,az=az,gx=GyrX,gy=-gy,gz=gz'");
    snprintf(map, sizeof map, "%.*s", (int)(strlen(buf) - strlen("--columns ''")), buf + strlen("--columns '"));
    hx_csv_layout_default(&back);
    assert_int_equal(hx_csv_columns_parse(&back, map, err, sizeof err), 0);
    assert_true(hx_name_eq(back.names[1], l.names[1]));
    assert_true(hx_name_eq(back.names[4], l.names[4]));
    /* a ',' in a name: no --columns can give it (it separates the items) */
    snprintf(l.names[4], sizeof l.names[4], "%s", "w,x");
    assert_null(hx_columns_give(&l, k_same, k_flip_y, buf, sizeof buf));
    assert_string_equal(buf, "");
    /* a buffer too small: NULL, nothing cut short */
    hx_csv_layout_default(&l);
    assert_null(hx_columns_give(&l, k_swap, k_none, buf, 20));
    assert_string_equal(buf, "");
}

/* hx_shell_word: a word as it is, else single-quoted, a ' written '\'' (or
 * dropped for a --columns map); "" when it does not fit */
static void test_shell_word(void **state)
{
    char buf[64];
    (void)state;
    assert_string_equal(hx_shell_word("/tmp/walk-1.bin", 0, buf, sizeof buf), "/tmp/walk-1.bin");
    assert_string_equal(hx_shell_word("my walk's.bin", 0, buf, sizeof buf), "'my walk'\\''s.bin'");
    assert_string_equal(hx_shell_word("t=Time [s],ax=Acc'X", 1, buf, sizeof buf), "'t=Time [s],ax=AccX'");
    assert_string_equal(hx_shell_word("", 0, buf, sizeof buf), "''");
    assert_string_equal(hx_shell_word("a*b", 0, buf, sizeof buf), "'a*b'");
    assert_string_equal(hx_shell_word("~x.bin", 0, buf, sizeof buf), "'~x.bin'");
    assert_string_equal(hx_shell_word("=x.bin", 0, buf, sizeof buf), "'=x.bin'");
    assert_string_equal(hx_shell_word("x=~y", 0, buf, sizeof buf), "'x=~y'");
    /* fits exactly: 'a b' is 5 characters and the NUL */
    assert_string_equal(hx_shell_word("a b", 0, buf, 6), "'a b'");
    assert_string_equal(hx_shell_word("a b", 0, buf, 5), "");
    assert_string_equal(hx_shell_word("ab", 0, buf, 2), "");
    assert_string_equal(hx_shell_word("x'y", 0, buf, 9), "'x'\\''y'");
    assert_string_equal(hx_shell_word("x'y", 0, buf, 8), "");
}

/* --columns tns=NAME: nanoseconds added to t's whole seconds (a stamp split
 * in two columns, as ROS writes it); the sum exact to the ns; each wrong
 * use refused with its reason: a nanoseconds value out of 0..999999999 or
 * not whole, a column not in the header, t in ms, tns given twice or named
 * for another key too. */
static void test_columns_tns(void **state)
{
    static const char *const head = "sec,nsec,ax,ay,az,gx,gy,gz\n";
    static const struct {
        const char *row, *err;
    } bad[] = {
        { "5,1000000000,0,0,1,0,0,0\n", "nanoseconds ('1000000000', column 'nsec') are not a whole number" },
        { "5,-1,0,0,1,0,0,0\n", "nanoseconds ('-1', column 'nsec')" },
        { "5,2.5,0,0,1,0,0,0\n", "nanoseconds ('2.5', column 'nsec')" },
        { "5,x,0,0,1,0,0,0\n", "nanoseconds ('x', column 'nsec')" },
    };
    char p[256], err[320], text[256];
    readall_t ra;
    hx_csv_layout_t l;
    size_t k;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "sec,nsec,ax,ay,az,gx,gy,gz\n1764460800,999999999,0,0,1,0,0,0\n1764460801,2500000,0,0,1,0,0,0\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=sec,tns=nsec", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 2);
    assert_true(ra.s[0].t_ns == 1764460800999999999LL && ra.s[1].t_ns == 1764460801002500000LL);
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        snprintf(text, sizeof text, "%s%s", head, bad[k].row);
        write_text(p, text);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
        assert_int_equal(ra.n, 0);
        if (strstr(ra.err, bad[k].err) == NULL) {
            fail_msg("%s: %s", bad[k].row, ra.err);
        }
    }
    /* no such column; t in ms */
    assert_int_equal(hx_csv_columns_parse(&l, "tns=nanos", err, sizeof err), -1); /* given twice */
    assert_non_null(strstr(err, "tns= given twice"));
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=sec,tns=nanos", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    if (strstr(ra.err, "header has no column 'nanos' (the name --columns gives tns)") == NULL) {
        fail_msg("no column: %s", ra.err);
    }
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=sec,tns=nsec", err, sizeof err), 0);
    assert_int_equal(hx_csv_units_parse(&l, "time=ms", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    if (strstr(ra.err, "--columns tns=nsec adds nanoseconds to the whole seconds of a time column: its unit must "
                       "be s") == NULL) {
        fail_msg("ms: %s", ra.err);
    }
    /* tns alone, beside a header whose other names are matched */
    write_text(p, "timestamp,nsec,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n17,5,0,0,1,0,0,0\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "tns=nsec", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), 0);
    assert_int_equal(ra.n, 1);
    assert_true(ra.s[0].t_ns == 17000000005LL);
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "tns=nanos", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    if (strstr(ra.err, "header has no column 'nanos' (the name --columns gives tns)") == NULL) {
        fail_msg("tns alone: %s", ra.err);
    }
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=sec,tns=sec", err, sizeof err), -1);
    assert_non_null(strstr(err, "column 'sec' is named for both t and tns"));
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "tns=", err, sizeof err), -1);
    assert_non_null(strstr(err, "tns= has an empty name"));
    hx_reader_set_layout(NULL);
    unlink(p);
}

/* The reader: a header refused before is read with the names matched and
 * the units they name, said once as the options; one refused still is
 * refused with the candidates */
static void test_csv_names(void **state)
{
    char p[512], err[1024];
    readall_t ra;
    hx_meta_t meta;
    hx_csv_layout_t lay;
    hx_reader_t *r;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "Time [ms],AccX [g],AccY [g],AccZ [g],GyroX [deg/s],GyroY [deg/s],GyroZ [deg/s],acc_x_lin\n"
                  "1500,0.5,-0.25,1,90,-45,180,7\n"
                  "1502.5,0,0,1,0,0,0,7\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), 0);
    assert_int_equal(meta.format, HX_FMT_CSV);
    assert_int_equal(ra.n, 2);
    assert_int_equal(ra.end, FNAV_END);
    assert_true(ra.s[0].t_ns == 1500000000LL);
    assert_true(ra.s[1].t_ns == 1502500000LL);
    assert_true((float)ra.s[0].accel_mps2[0] == (float)(0.5 * 9.80665));
    assert_true((float)ra.s[0].accel_mps2[1] == (float)(-0.25 * 9.80665));
    assert_true((float)ra.s[0].accel_mps2[2] == (float)9.80665);
    assert_true((float)ra.s[0].gyro_rps[0] == (float)(90.0 * (3.14159265358979323846 / 180.0)));
    assert_true((float)ra.s[0].gyro_rps[2] == (float)(180.0 * (3.14159265358979323846 / 180.0)));
    r = hx_reader_open(p, HX_FMT_AUTO, 0.0, err, sizeof err);
    assert_non_null(r);
    {
        char want[1024];
        const char *w = hx_reader_warnings(r), *at;
        snprintf(want, sizeof want,
                 "%s: header read as --columns 't=Time [ms],ax=AccX [g],ay=AccY [g],az=AccZ [g],gx=GyroX [deg/s],"
                 "gy=GyroY [deg/s],gz=GyroZ [deg/s]' --units time=ms,accel=g,gyro=deg/s (names matched; not read: "
                 "acc_x_lin; give --columns to choose otherwise)",
                 p);
        at = strstr(w, want);
        assert_non_null(at);
        assert_null(strstr(at + strlen(want), "header read as")); /* once */
    }
    hx_reader_close(r);
    /* the units remedies name the layout it was read with */
    assert_non_null(hx_units_layout(HX_FMT_CSV, &lay));
    assert_int_equal(lay.names_matched, 1);
    assert_int_equal(lay.time_digits, 6);
    assert_true(lay.acc_scale == HX_G_MPS2);
    assert_true(lay.gyr_scale == HX_DPS_RPS);
    assert_string_equal(lay.names[1], "AccX [g]");
    /* a --units item given keeps its unit; the others come from the names */
    {
        hx_csv_layout_t l;
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, "gyro=rad/s", err, sizeof err), 0);
        hx_reader_set_layout(&l);
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), 0);
        assert_true((float)ra.s[0].accel_mps2[0] == (float)(0.5 * 9.80665));
        assert_true((float)ra.s[0].gyro_rps[0] == 90.0f);
        assert_true(ra.s[1].t_ns == 1502500000LL);
        hx_reader_set_layout(NULL);
    }
    /* an interchange CSV opened next: the defaults again */
    write_text(p, "t,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), 0);
    assert_non_null(hx_units_layout(HX_FMT_CSV, &lay));
    assert_int_equal(lay.names_matched, 0);
    assert_true(lay.acc_scale == 1.0);
    /* ambiguous: refused, the candidates and what matched named */
    write_text(p, "timestamp,acc_x,accel_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,1,1,2,3,4,5,6\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), -1);
    assert_non_null(strstr(ra.err, ":1: header has no column 't'; expected t,ax,ay,az,gx,gy,gz[,temp]; names "
                                   "matched: --columns t=timestamp,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z; "
                                   "not matched: ax: 2 candidates (acc_x, accel_x)"));
    /* no time column and no rate: the six named, and --input-rate */
    write_text(p, "acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n1,2,3,4,5,6\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), -1);
    assert_non_null(strstr(ra.err, "names matched: --columns ax=acc_x,ay=acc_y,az=acc_z,gx=gyr_x,gy=gyr_y,gz=gyr_z; "
                                   "no time column: give the log's rate with --input-rate HZ"));
    assert_int_equal(read_all(p, HX_FMT_AUTO, 100.0, &ra, &meta), 0);
    assert_int_equal(ra.n, 1);
    assert_true((float)ra.s[0].gyro_rps[2] == 6.0f);
    /* the interchange names with one missing: the message as before */
    write_text(p, "t,ax,ay,az\n0,0,0,-9.8\n");
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), -1);
    assert_null(strstr(ra.err, "names matched"));
    /* --columns given: no matching (the name it gives is required) */
    {
        hx_csv_layout_t l;
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_columns_parse(&l, "t=time_ns", err, sizeof err), 0);
        hx_reader_set_layout(&l);
        write_text(p, "timestamp,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n0,1,2,3,4,5,6\n");
        assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), -1);
        assert_non_null(strstr(ra.err, "header has no column 'time_ns' (the name --columns gives t)"));
        assert_null(strstr(ra.err, "names matched"));
        hx_reader_set_layout(NULL);
    }
    unlink(p);
}

static void test_csv_layout(void **state)
{
    char p[512], err[320];
    readall_t ra;
    hx_meta_t meta;
    hx_csv_layout_t l;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    /* the mapping and every unit: Unix time in ns to the ns, g, deg/s */
    write_text(p, "timestamp_ns, \"Acc_X\",acc_y,acc_z,gyro_x,gyro_y,gyro_z,temperature\n"
                  "1764460800123456789,0.5,-0.25,1,90,-45,180,21.5\n"
                  "1764460800126969349,0,0,1,0,0,0,\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=timestamp_ns,ax=acc_x,ay=acc_y,az=acc_z,gx=gyro_x,gy=gyro_y,"
                                              "gz=gyro_z,temp=temperature",
                                          err, sizeof err),
                     0);
    assert_int_equal(hx_csv_units_parse(&l, "time=ns,accel=g,gyro=deg/s", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), 0);
    assert_int_equal(meta.format, HX_FMT_CSV);
    assert_int_equal(ra.n, 2);
    assert_int_equal(ra.end, FNAV_END);
    assert_true(ra.s[0].t_ns == 1764460800123456789LL);
    assert_true(ra.s[1].t_ns == 1764460800126969349LL);
    assert_true((float)ra.s[0].accel_mps2[0] == (float)(0.5 * 9.80665));
    assert_true((float)ra.s[0].accel_mps2[1] == (float)(-0.25 * 9.80665));
    assert_true((float)ra.s[0].accel_mps2[2] == (float)9.80665);
    assert_true((float)ra.s[0].gyro_rps[0] == (float)(90.0 * (3.14159265358979323846 / 180.0)));
    assert_true((float)ra.s[0].gyro_rps[1] == (float)(-45.0 * (3.14159265358979323846 / 180.0)));
    assert_true((float)ra.s[0].gyro_rps[2] == (float)(180.0 * (3.14159265358979323846 / 180.0)));
    assert_true((float)ra.s[0].temp_c == 21.5f);
    /* the other spellings: m/s^2, mps2, rad/s, dps, and ms and us stamps,
     * exact in the decimal text (1.0000005 ms is 1000000.5 ns: rounds up) */
    {
        static const struct {
            const char *units, *t0;
            long long ns;
            double acc, gyr;
        } k[] = {
            { "time=s,accel=m/s2,gyro=rad/s", "12.000000001", 12000000001LL, 1.0, 1.0 },
            { "time=ms,accel=m/s^2,gyro=dps", "1500.25", 1500250000LL, 1.0, 3.14159265358979323846 / 180.0 },
            { "time=ms", "1.0000005", 1000001LL, 1.0, 1.0 },
            { "time=us,accel=mps2", "1500.2504", 1500250LL, 1.0, 1.0 },
            { "time=ns", "42", 42LL, 1.0, 1.0 },
            /* mg and mdps (ST's SensorTile data log writes AccX [mg] and
             * GyroX [mdps]) */
            { "accel=mg,gyro=mdps", "1", 1000000000LL, 0.00980665, 3.14159265358979323846 / 180.0 / 1000.0 },
            { "gyro=mdeg/s", "1", 1000000000LL, 1.0, 3.14159265358979323846 / 180.0 / 1000.0 },
            { "time=ns", "1.5e3", 1500LL, 1.0, 1.0 },
            /* more integer digits than 9e9 s holds, scaled down by an
             * exponent: a number, not "beyond 9e9 s" */
            { "time=s", "100000000000000000000e-15", 100000000000000LL, 1.0, 1.0 },
            { "time=ns", "90000000000000000000e-2", 900000000000000000LL, 1.0, 1.0 },
        };
        size_t i;
        tmp_path(p, sizeof p, ".csv");
        for (i = 0; i < sizeof k / sizeof k[0]; i++) {
            char text[256];
            snprintf(text, sizeof text, "t,ax,ay,az,gx,gy,gz\n%s,0,0,9.5,2,0,0\n", k[i].t0);
            write_text(p, text);
            hx_csv_layout_default(&l);
            assert_int_equal(hx_csv_units_parse(&l, k[i].units, err, sizeof err), 0);
            hx_reader_set_layout(&l);
            assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &ra, NULL), 0);
            assert_int_equal(ra.n, 1);
            assert_true(ra.s[0].t_ns == k[i].ns);
            assert_true((float)ra.s[0].accel_mps2[2] == (float)(9.5 * k[i].acc));
            assert_true((float)ra.s[0].gyro_rps[0] == (float)(2.0 * k[i].gyr));
        }
    }
    /* 1000 mg is g and 90000 mdps 90 deg/s, to the float32 the core takes:
     * the same sample as 1 g and 90 deg/s read with accel=g,gyro=deg/s */
    {
        float a_g, w_dps;
        tmp_path(p, sizeof p, ".csv");
        write_text(p, "t,ax,ay,az,gx,gy,gz\n0,0,0,1,90,0,0\n");
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, "accel=g,gyro=deg/s", err, sizeof err), 0);
        hx_reader_set_layout(&l);
        assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &ra, NULL), 0);
        a_g = (float)ra.s[0].accel_mps2[2];
        w_dps = (float)ra.s[0].gyro_rps[0];
        assert_true(a_g == 9.80665f);
        write_text(p, "t,ax,ay,az,gx,gy,gz\n0,0,0,1000,90000,0,0\n");
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, "accel=mg,gyro=mdps", err, sizeof err), 0);
        hx_reader_set_layout(&l);
        assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &ra, NULL), 0);
        assert_true((float)ra.s[0].accel_mps2[2] == a_g);
        assert_true((float)ra.s[0].gyro_rps[0] == w_dps);
        assert_true((float)ra.s[0].gyro_rps[0] == (float)(3.14159265358979323846 / 2.0));
    }
    /* the remedy's --units value names every item in its unit, the
     * synopsis's order (hx_units_give): mg and mdps as well as g and deg/s */
    {
        char give[96];
        hx_csv_layout_default(&l);
        assert_int_equal(hx_csv_units_parse(&l, "gyro=mdps,accel=mg,time=us", err, sizeof err), 0);
        assert_string_equal(hx_units_give(&l, give, sizeof give), "give --units time=us,accel=mg,gyro=mdps");
        assert_int_equal(hx_csv_units_parse(&l, "accel=g,gyro=deg/s,time=s", err, sizeof err), 0);
        assert_string_equal(hx_units_give(&l, give, sizeof give), "give --units accel=g,gyro=deg/s");
        /* every item in SI (seconds read with --units time=ms, say): no
         * item to give, so the remedy is to leave --units out, not
         * "give --units " */
        hx_csv_layout_default(&l);
        assert_string_equal(hx_units_give(&l, give, sizeof give), "leave --units out");
    }
    /* a mapped column the header lacks: the error names it and --columns */
    tmp_path(p, sizeof p, ".csv");
    write_text(p, "time_ns,ax,ay,az,gx,gy,gz\n1,0,0,1,0,0,0\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=timestamp_ns", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    assert_non_null(strstr(ra.err, "header has no column 'timestamp_ns'"));
    assert_non_null(strstr(ra.err, "--columns"));
    /* so is a mapped temp, an optional column, and a mapped t with the rate
     * given: a name the user gave is there (neither ignored: the
     * temperature not left out, the time not taken from the rate) */
    write_text(p, "t,ax,ay,az,gx,gy,gz\n0,0,0,1,0,0,0\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "temp=temperature", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_CSV, 0.0, &ra, NULL), -1);
    assert_non_null(strstr(ra.err, "header has no column 'temperature' (the name --columns gives temp)"));
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_columns_parse(&l, "t=timestamp_ns", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    write_text(p, "time_ns,ax,ay,az,gx,gy,gz\n1,0,0,1,0,0,0\n");
    assert_int_equal(read_all(p, HX_FMT_CSV, 100.0, &ra, NULL), -1);
    assert_non_null(strstr(ra.err, "header has no column 'timestamp_ns' (the name --columns gives t)"));
    /* another format: the options are the interchange CSV's; the error names
     * the option and the format */
    write_text(p, "Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s),Accelerometer X (g),"
                  "Accelerometer Y (g),Accelerometer Z (g)\n0,0,0,0,0,0,1\n");
    hx_csv_layout_default(&l);
    assert_int_equal(hx_csv_units_parse(&l, "accel=g", err, sizeof err), 0);
    hx_reader_set_layout(&l);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
    assert_non_null(strstr(ra.err, "--units"));
    assert_non_null(strstr(ra.err, "ngimu"));
    assert_non_null(strstr(ra.err, "give --from csv"));
    /* a .bin is no text: not told to give --from csv, which reads "a NUL
     * byte in the text" */
    {
        hx_meta_t bm;
        hx_writer_t *w;
        fnav_sample_t s;
        char pb[512];
        memset(&bm, 0, sizeof bm);
        bm.rate_hz = 100.0;
        bm.rate_nominal = 1;
        memset(&s, 0, sizeof s);
        s.accel_mps2[2] = -9.81f;
        tmp_path(pb, sizeof pb, ".bin");
        w = hx_writer_open(pb, HX_FMT_AUTO, &bm, 0, err, sizeof err);
        assert_non_null(w);
        assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
        assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
        assert_int_equal(read_all(pb, HX_FMT_AUTO, 0.0, &ra, NULL), -1);
        assert_non_null(strstr(ra.err, "not to the bin format"));
        assert_null(strstr(ra.err, "--from csv"));
    }
    hx_reader_set_layout(NULL);
    assert_int_equal(read_all(p, HX_FMT_AUTO, 0.0, &ra, &meta), 0); /* the defaults again */
    assert_int_equal(meta.format, HX_FMT_NGIMU);
    /* bad maps and specs: each refused with a message that says why */
    {
        static const struct {
            int units;
            const char *spec, *says;
        } bad[] = {
            { 0, "tx=a", "unknown" },         { 0, "t=a,t=b", "twice" },
            { 0, "ax=x,ay=x", "'x'" },        { 0, "ax=ay", "'ay'" },
            { 0, "t", "'='" },                { 0, "t=", "empty" },
            { 1, "time", "'='" },             { 1, "time=min", "s, ms, us or ns" },
            { 1, "accel=G2", "m/s2" },        { 1, "gyro=rpm", "rad/s" },
            { 1, "accel=ng", "ug" },          { 1, "gyro=udps", "mdps" },
            { 1, "speed=1", "unknown" },      { 1, "time=ms,time=ns", "twice" },
        };
        size_t i;
        for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            int rc;
            err[0] = '\0';
            hx_csv_layout_default(&l);
            rc = bad[i].units ? hx_csv_units_parse(&l, bad[i].spec, err, sizeof err)
                              : hx_csv_columns_parse(&l, bad[i].spec, err, sizeof err);
            if (rc == 0 || strstr(err, bad[i].says) == NULL) {
                fail_msg("'%s': rc %d, '%s' (expected an error saying %s)", bad[i].spec, rc, err, bad[i].says);
            }
        }
    }
}

/* test_csv_layout's teardown: the process-wide layout back to the
 * defaults also when an assertion left the test midway (the tests after it
 * read the interchange CSV) */
/* ------------------------------------------------------------ mtmanager */

/* Xsens MT Manager's ASCII export (docs/log-format.md, "MT Manager
 * export"). A preamble as MT Manager writes it (the public example of an
 * MTw2 export; trailing blanks on some lines), then the header. */
static const char k_mtmgr_preamble[] =
    "// General information: \n"
    "//  MT Manager version: 2022.2.0 \n"
    "//  XDA version: 2022.2.0 build 7381 rev 124627 built on 2023-07-19\n"
    "// Device information: \n"
    "//  DeviceId: 00B42D4F\n"
    "//  ProductCode: MTW2-3A7G6\n"
    "//  Firmware Version: 4.4.0\n"
    "//  Hardware Version: 1.1.0\n"
    "// Device settings: \n"
    "//  Filter Profile: human(46.1)\n"
    "//  Option Flags: Orientation Smoother Disabled, Position/Velocity Smoother Disabled, Continuous Zero "
    "Rotation Update Disabled, AHS Disabled, ICC Disabled\n"
    "// Coordinate system: ENU\n";

/* Both counters wrap (PacketCounter at 2^16, SampleTimeFine at 2^32 ticks
 * of 100 us) and one packet is lost after the wraps: the time is the
 * unwrapped SampleTimeFine (10 ms a packet at 100 Hz, 20 ms over the lost
 * one), seq the unwrapped counter (a step of 2 there: a drop), the rate
 * the one the '// Update Rate' line states; the unused Roll/Pitch/Yaw and
 * the NaN date columns are ignored. A mutant without the
 * SampleTimeFine unwrap reads "time goes backwards" at the wrap; one
 * without the counter unwrap a seq step of -65535. */
static void test_mtmgr_wraps_and_gap(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    FILE *f;
    long i;
    size_t k;
    const double stf0 = 4294967296.0 - 300.0; /* 3 packets before the wrap */
    (void)state;
    tmp_path(p, sizeof p, ".txt");
    f = fopen(p, "w");
    assert_non_null(f);
    fprintf(f, "%s//  Update Rate: 100.0Hz\n", k_mtmgr_preamble);
    fprintf(f, "PacketCounter\tSampleTimeFine\tYear\tMonth\tDay\tSecond\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\t"
               "Roll\tPitch\tYaw\n");
    for (i = 0; i < 8; i++) {
        if (i == 5) {
            continue; /* lost: 2 packets after both wraps */
        }
        fprintf(f, "%ld\t%.0f\tNaN\tNaN\tNaN\tNaN\t0.069663\t-0.012828\t9.978389\t0.001960\t-0.000371\t%.6f\t"
                   "-0.254385\t0.210872\t-137.2\n",
                (65533L + i) % 65536L, fmod(stf0 + 100.0 * (double)i, 4294967296.0), 0.005926 + 0.001 * (double)i);
    }
    assert_int_equal(fclose(f), 0);
    assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_MTMGR);
    assert_string_equal(log.meta.sensor, "Xsens MTW2-3A7G6");
    assert_true(log.meta.rate_hz == 100.0);
    assert_int_equal(log.meta.rate_nominal, 1);
    assert_int_equal(log.meta.has_seq, 1);
    assert_int_equal(log.meta.stamps_made, 0);
    assert_int_equal(log.n, 7);
    assert_true(log.t_ns[0] == (int64_t)stf0 * 100000LL);
    assert_true(log.seq[0] == 65533u);
    for (k = 1; k < log.n; k++) {
        const int lost = k == 5;
        assert_true(log.t_ns[k] - log.t_ns[k - 1] == (lost ? 20000000LL : 10000000LL));
        assert_true(log.seq[k] - log.seq[k - 1] == (lost ? 2u : 1u));
    }
    assert_true(log.acc[6][2] == (double)(fnav_real_t)9.978389);
    assert_true(log.gyr[6][2] == (double)(fnav_real_t)0.012926); /* "%.6f" of 0.005926 + 0.007 (row 7) */
    assert_string_equal(log.warnings, "");
    hx_log_free(&log);
    /* SampleTimeFine as time of day (an MTi-G with a GNSS fix) wraps at
     * midnight, 864,000,000 ticks (XDA's packet stamper): 10 ms on, not
     * "time goes backwards"; a drop of less than half a day is no wrap */
    write_text(p, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "1\t863999800\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "2\t863999900\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "3\t0\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "4\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "5\t50\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_int_equal(log.n, 4);
    for (k = 1; k < log.n; k++) {
        assert_true(log.t_ns[k] - log.t_ns[k - 1] == 10000000LL);
    }
    assert_int_equal(log.status, FNAV_E_TIME);
    assert_non_null(strstr(log.error, ":6: time goes backwards"));
    hx_log_free(&log);
    unlink(p);
}

/* Rows with NaN or an empty field where the reader needs a value (Acc_,
 * Gyr_, SampleTimeFine, the PacketCounter that gives seq) are lost packets:
 * skipped, counted and warned with the first one's line, as MT Manager
 * writes them; NaN in a column the reader does not use is no loss. The
 * other readers stop at a NaN (their files have none); a mutant that does
 * so here reads 2 samples. */
static void test_mtmgr_nan_rows(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    (void)state;
    tmp_path(p, sizeof p, ".txt");
    write_text(p, "// Update Rate: 100.0Hz\n"
                  "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\n"
                  "10\t1000\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\tNaN\n"
                  "11\t1100\t0.1\tNaN\t9.8\t0.01\t0.02\t0.03\t0.5\n" /* line 4 */
                  "12\t1200\t0.1\t0.2\t9.8\t0.01\t0.02\t\t0.5\n"
                  "13\tnan\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\t0.5\n"
                  "NaN\t1400\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\t0.5\n"
                  "15\t1500\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\t0.5\n"
                  "16\t1600\t-0.1\t0.2\t9.8\t0.01\t0.02\t0.03\t0.5\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_int_equal(log.meta.format, HX_FMT_MTMGR);
    assert_int_equal(log.n, 3);
    assert_true(log.seq[1] == 15u && log.t_ns[1] == 150000000LL);
    assert_true(log.t_ns[2] - log.t_ns[1] == 10000000LL);
    assert_true(log.acc[2][0] == (double)(fnav_real_t)-0.1);
    assert_non_null(strstr(log.warnings, ":4: 4 rows with NaN or an empty field in Acc_*, Gyr_* or the time or "
                                         "counter column (the first here) skipped"));
    hx_log_free(&log);
    /* every row lost: no samples, an error that says why */
    write_text(p, "// Update Rate: 100.0Hz\n"
                  "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "10\t1000\tNaN\tNaN\tNaN\tNaN\tNaN\tNaN\n11\t1100\tNaN\tNaN\tNaN\tNaN\tNaN\tNaN\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ": no samples: each of the 2 rows has NaN or an empty field in Acc_*, Gyr_* or the "
                                "time or counter column"));
    /* Inf is no missing value but a fault: an error at its line, as in
     * every reader */
    write_text(p, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "10\t1000\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "11\t1100\t0.1\tinf\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_int_equal(log.n, 1);
    assert_int_equal(log.status, FNAV_E_NANINF);
    assert_non_null(strstr(log.error, ":3: column 4 ('inf') is NaN or Inf"));
    hx_log_free(&log);
    unlink(p);
}

/* Columns in another order, extra columns, comma or semicolon delimiter,
 * CRLF, no preamble (the header alone is recognised): the values land in
 * the right axes. Without SampleTimeFine the time is the PacketCounter at
 * the stated rate, or --input-rate (warned when it differs from the stated
 * one); with neither a rate is asked for. A SampleTimeFine of NaN on the
 * first row (the public example's) leaves the time to the counter. */
static void test_mtmgr_columns_and_rate(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    static const char *const delims[2] = { ",", ";" };
    int d;
    (void)state;
    tmp_path(p, sizeof p, ".txt");
    for (d = 0; d < 2; d++) {
        char text[512];
        const char *c = delims[d];
        snprintf(text, sizeof text,
                 "Gyr_Z%sGyr_Y%sGyr_X%sQuat_q0%sAcc_Z%sAcc_Y%sAcc_X%sSampleTimeFine%sPacketCounter\r\n"
                 "0.3%s0.2%s0.1%s1%s9.7%s-0.5%s0.25%s20000%s7\r\n"
                 "0.3%s0.2%s0.1%s1%s9.7%s-0.5%s0.25%s20050%s8\r\n",
                 c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c, c);
        write_text(p, text);
        assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.n, 2);
        assert_true(log.acc[0][0] == (double)(fnav_real_t)0.25 && log.acc[0][1] == (double)(fnav_real_t)-0.5 &&
                    log.acc[0][2] == (double)(fnav_real_t)9.7);
        assert_true(log.gyr[0][0] == (double)(fnav_real_t)0.1 && log.gyr[0][1] == (double)(fnav_real_t)0.2 &&
                    log.gyr[0][2] == (double)(fnav_real_t)0.3);
        assert_true(log.t_ns[0] == 2000000000LL && log.t_ns[1] == 2005000000LL); /* 200 Hz */
        assert_true(log.seq[1] == 8u);
        assert_int_equal(log.meta.rate_nominal, 0); /* estimated from the stamps */
        assert_true(fabs(log.meta.rate_hz - 200.0) < 1e-9);
        hx_log_free(&log);
    }
    /* the counter at the stated 40 Hz */
    write_text(p, "// Start Time: Unknown\n// Update Rate: 40.0Hz\n// Filter Profile: human (46.1)\n"
                  "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "4\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n5\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.meta.rate_hz == 40.0 && log.meta.rate_nominal == 1);
    assert_true(log.t_ns[0] == 100000000LL && log.t_ns[1] == 125000000LL);
    assert_string_equal(log.warnings, "");
    hx_log_free(&log);
    /* --input-rate replaces it, said */
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 50.0, err, sizeof err), 0);
    assert_true(log.meta.rate_hz == 50.0);
    assert_true(log.t_ns[1] == 100000000LL);
    assert_non_null(strstr(log.warnings, ": --input-rate 50 Hz replaces the rate the file states (40 Hz on line 2)"));
    hx_log_free(&log);
    /* no rate at all: an error naming --input-rate; with it, read */
    write_text(p, "// ProductCode: MTI-3-8A7G6\n"
                  "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "4\tNaN\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n5\tNaN\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":3: no time stamps: SampleTimeFine is missing on the first row, so the time is "
                                "the PacketCounter at the rate, which no '// Update Rate' line states: give it "
                                "with --input-rate HZ"));
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 100.0, err, sizeof err), 0);
    assert_int_equal(log.n, 2);
    assert_true(log.t_ns[0] == 40000000LL && log.t_ns[1] == 50000000LL);
    assert_null(strstr(log.warnings, "ignored")); /* the counter needs it */
    hx_log_free(&log);
    /* --input-rate with SampleTimeFine: ignored, said */
    write_text(p, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "4\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n5\t200\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 50.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 10000000LL);
    assert_non_null(strstr(log.warnings, "--input-rate ignored: the mtmanager format has time stamps"));
    hx_log_free(&log);
    unlink(p);
}

/* What is refused, with its line: an export of increments (dq_, dv: the SDI
 * output) or of FreeAcc_ alone, named with what to export instead; a column
 * missing (the detection hint); a counter that is no whole number; a
 * SampleTimeFine that steps back by less than half its range (no wrap). */
static void test_mtmgr_refused(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    (void)state;
    tmp_path(p, sizeof p, ".txt");
    write_text(p, "// General information:\n//  MT Manager version: 2022.2.0\n"
                  "PacketCounter\tSampleTimeFine\tdq_W\tdq_X\tdq_Y\tdq_Z\tdv[1]\tdv[2]\tdv[3]\n"
                  "1\t100\t1\t0\t0\t0\t0\t0\t0.098\n");
    assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":3: header has no column 'Acc_X': the export holds orientation and velocity "
                                "increments (dq_*, dv*: the SDI output), which footnav does not integrate back; "
                                "export Acc_X..Z (acceleration, m/s^2) and Gyr_X..Z (rate of turn, rad/s) instead"));
    write_text(p, "PacketCounter\tSampleTimeFine\tFreeAcc_X\tFreeAcc_Y\tFreeAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "1\t100\t0\t0\t0\t0\t0\t0\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_MTMGR, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":1: header has no column 'Acc_X': FreeAcc_* is the acceleration without gravity"));
    write_text(p, "// Update Rate: 100.0Hz\nPacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\n"
                  "1\t100\t0\t0\t0\t0\t0\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ":2: header has no column 'Gyr_Z' (an MT Manager export needs Acc_X..Z in m/s^2 "
                                "and Gyr_X..Z in rad/s) (format mtmanager detected from the content; give --from"));
    write_text(p, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "1\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "2\t200.5\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_int_equal(log.n, 1);
    assert_non_null(strstr(log.error, ":3: SampleTimeFine ('200.5') is not a whole number from 0 to 4294967295"));
    hx_log_free(&log);
    write_text(p, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "1\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "x2\t200\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_non_null(strstr(log.error, ":3: PacketCounter ('x2') is not a whole number"));
    hx_log_free(&log);
    write_text(p, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "1\t3000000000\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n"
                  "2\t2000000000\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 1);
    assert_int_equal(log.status, FNAV_E_TIME);
    assert_non_null(strstr(log.error, ":3: time goes backwards"));
    hx_log_free(&log);
    /* the preamble alone, no header */
    write_text(p, "// General information:\n//  MT Manager version: 2022.2.0\n\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ": no header line (PacketCounter, SampleTimeFine, Acc_X, ...) (format mtmanager detected"));
    /* a header alone, no rows */
    write_text(p, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ": no samples"));
    unlink(p);
}

/* Detection reads the first 600 bytes: a preamble longer than that (more
 * comment lines than the example's) is known by MT Manager's keys in its
 * '//' lines; '//' lines without them are an export only when the header
 * shows (PacketCounter or SampleTimeFine with Acc_X and Gyr_X); other
 * '//' text and the formats detected before stay as they were. */
static void test_mtmgr_detect(void **state)
{
    char p[256], text[2048];
    int i;
    size_t len;
    static const char hdr[] = "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                              "1\t100\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n";
    (void)state;
    tmp_path(p, sizeof p, ".txt");
    len = (size_t)snprintf(text, sizeof text, "%s", k_mtmgr_preamble);
    for (i = 0; i < 6; i++) {
        len += (size_t)snprintf(text + len, sizeof text - len, "// Coordinate system: ENU\n");
    }
    assert_true(len > 600);
    snprintf(text + len, sizeof text - len, "%s", hdr);
    write_text(p, text);
    assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
    /* no keys, the header past 600 bytes: not recognised */
    for (len = 0, i = 0; i < 40; i++) {
        len += (size_t)snprintf(text + len, sizeof text - len, "// recorded by hand\n");
    }
    snprintf(text + len, sizeof text - len, "%s", hdr);
    write_text(p, text);
    assert_int_equal(hx_detect_file(p), HX_FMT_CSV);
    /* no keys, the header in sight */
    snprintf(text, sizeof text, "// recorded by hand\n%s", hdr);
    write_text(p, text);
    assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
    /* '//' before another header, and the ipol file's counter header under
     * its first line: as before */
    write_text(p, "// a note\nt,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n");
    assert_int_equal(hx_detect_file(p), HX_FMT_CSV);
    write_text(p, "Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n"
                  "0.0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\n");
    assert_int_equal(hx_detect_file(p), HX_FMT_IPOL);
    /* the same header without that line: the export's */
    write_text(p, "PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n0\t5.09\t0.41\t8.92\t-0.0025\t0.0089\t-0.0178\n");
    assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
    /* a CSV that also carries Xsens names but has t: ours */
    write_text(p, "t,PacketCounter,Acc_X,Gyr_X,ax,ay,az,gx,gy,gz\n0,1,0,0,0,0,9.8,0,0,0\n");
    assert_int_equal(hx_detect_file(p), HX_FMT_CSV);
    unlink(p);
}

/* An export of rows whose SampleTimeFine steps by step from 1000 (one
 * step of gap instead after row gap_at, when > 0), after pre ("" for a
 * header alone) and an optional '// Update Rate' of stated Hz (0: none). */
/* An export of rows rows whose SampleTimeFine steps by step (40 steps
 * after row gap_at) under the header hdr of 11 columns, after pre and a
 * '// Update Rate' line when stated > 0. */
static void write_mtmgr_steps_hdr(const char *p, const char *pre, const char *hdr, double stated, int rows, long step,
                                  int gap_at)
{
    FILE *f = fopen(p, "w");
    long stf = 1000;
    int i;
    assert_non_null(f);
    fprintf(f, "%s", pre);
    if (stated > 0.0) {
        fprintf(f, "// Update Rate: %.1fHz\n", stated);
    }
    fprintf(f, "%s\n", hdr);
    for (i = 0; i < rows; i++) {
        fprintf(f, "%d,%ld,0.1,0.2,9.8,0.01,0.02,0.03,0.4,-0.1,0.8\n", i, stf);
        stf += i + 1 == gap_at ? 40 * step : step;
    }
    assert_int_equal(fclose(f), 0);
}

/* The columns of a Movella DOT CSV of Acc_*, Gyr_* and Mag_* (DOT's
 * "rate quantities with mag" payload), which MT Manager may export too. */
#define DOT_ACC_GYR_MAG "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Mag_X,Mag_Y,Mag_Z"

static void write_mtmgr_steps(const char *p, const char *pre, double stated, int rows, long step, int gap_at)
{
    write_mtmgr_steps_hdr(p, pre, DOT_ACC_GYR_MAG, stated, rows, step, gap_at);
}

/* A header alone whose SampleTimeFine steps are slower than 20 Hz in MT
 * Manager's 100 us ticks but 20 Hz .. 5 kHz in us is Movella DOT's CSV
 * (DOT user manual, XD0502P, 4.2.5: SampleTimeFine in us), refused with the
 * CSV reader's remedy, not read 100 times too slow. At the bound of 500
 * ticks (20 Hz) or with a '//' line it is read as an export; with a column
 * DOT does not write (Roll) too at 50,001 (19.9996 Hz in us), which DOT's
 * own columns refuse (test_mtmgr_dot_rates). With --from mtmanager it is
 * refused the same (not read in ticks). The median
 * step (a gap, a wrap in the first rows) decides. A mutant that drops the
 * '//' condition refuses the preamble case; one without the us range
 * refuses 50,001 under Roll. */
static void test_mtmgr_us_stamps(void **state)
{
    char p[256], err[HX_ERR_SIZE];
    hx_log_t log;
    static const struct {
        long step;
        int refused;
    } cases[] = { { 150, 0 }, { 500, 0 }, { 501, 1 }, { 2511, 1 }, { 50000, 1 }, { 50001, 1 } };
    size_t c;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        write_mtmgr_steps(p, "", 0.0, 12, cases[c].step, 0);
        assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
        if (cases[c].refused) {
            assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
            assert_non_null(strstr(err, "no '//' line: likely a Movella DOT CSV; read it with --from csv --columns "
                                        "t=SampleTimeFine,ax=Acc_X,ay=Acc_Y,az=Acc_Z,gx=Gyr_X,gy=Gyr_Y,gz=Gyr_Z "
                                        "--units time=us,gyro=deg/s (if MT Manager's, its '//' lines cut: put one "
                                        "back before the header)"));
        } else {
            assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
            assert_int_equal(log.n, 12);
            assert_true(log.t_ns[1] - log.t_ns[0] == cases[c].step * 100000LL);
            hx_log_free(&log);
        }
    }
    write_mtmgr_steps(p, "", 0.0, 12, 501, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ".csv: SampleTimeFine steps by 501: 19.96 Hz in 100 us ticks, 1996 Hz in us, no "
                                "'//' line: likely a Movella DOT CSV"));
    /* the median step: a gap of 40 steps and a 2^32 wrap in the first rows */
    write_mtmgr_steps(p, "", 0.0, 12, 2511, 4);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ": SampleTimeFine steps by 2511: 3.982 Hz in 100 us ticks, 398.2 Hz in us"));
    write_text(p, "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z\n"
                  "0,4294962000,0.1,0.2,9.8,0.01,0.02,0.03\n1,4294964500,0.1,0.2,9.8,0.01,0.02,0.03\n"
                  "2,4294967000,0.1,0.2,9.8,0.01,0.02,0.03\n3,2204,0.1,0.2,9.8,0.01,0.02,0.03\n"
                  "4,4704,0.1,0.2,9.8,0.01,0.02,0.03\n");
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ": SampleTimeFine steps by 2500: 4 Hz in 100 us ticks, 400 Hz in us"));
    /* a '//' line before the header: MT Manager's, read in ticks */
    write_mtmgr_steps(p, "// Coordinate system: ENU\n", 0.0, 12, 2511, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 251100000LL);
    hx_log_free(&log);
    /* a column MT Manager writes and DOT does not (Roll, Pitch, Yaw): the
     * rate rule alone, whose bound 50,001 (19.9996 Hz in us) is read */
    write_mtmgr_steps_hdr(p, "", "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Roll,Pitch,Yaw", 0.0,
                          12, 50001, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 5000100000LL);
    hx_log_free(&log);
    write_mtmgr_steps_hdr(p, "", "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Roll,Pitch,Yaw", 0.0,
                          12, 2511, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, "likely a Movella DOT CSV"));
    /* given with --from mtmanager: the same refusal (read in ticks, a DOT
     * CSV would be 100 times too slow with its deg/s read as rad/s, and only
     * replay's units check would say something, naming --units) */
    write_mtmgr_steps(p, "", 0.0, 12, 2511, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_MTMGR, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ".csv: SampleTimeFine steps by 2511: 3.982 Hz in 100 us ticks, 398.2 Hz in us, no "
                                "'//' line: likely a Movella DOT CSV; read it with --from csv"));
    unlink(p);
}

/* A Movella DOT CSV at any of DOT's rates (1, 4, 10, 12, 15, 20, 30, 60 and
 * 120 Hz: DOT SDK's output rates): with no '//' line and a header of DOT's
 * own columns, SampleTimeFine steps of 0.5 Hz or faster in us are DOT's.
 * Below 20 Hz in us (0.2 Hz in ticks) they must not be read as an export,
 * 100 times too slow: the rate rule alone needs an IMU's rate in us. Half DOT's
 * slowest rate is the bound (2,000,000 us refused, 2,000,001 read); a
 * column only MT Manager writes, a '//' line, leave the export as it was;
 * a column of neither (an app's own) does not. */
static void test_mtmgr_dot_rates(void **state)
{
    static const int rates[] = { 1, 4, 10, 12, 15, 20, 30, 60, 120 };
    char p[256], err[HX_ERR_SIZE];
    hx_log_t log;
    size_t c;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    for (c = 0; c < sizeof rates / sizeof rates[0]; c++) {
        const long step = (1000000L + rates[c] / 2) / rates[c];
        write_mtmgr_steps(p, "", 0.0, 12, step, 0);
        err[0] = '\0';
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
        assert_non_null(strstr(err, "likely a Movella DOT CSV; read it with --from csv --columns"));
        /* --from mtmanager: the same */
        assert_int_equal(hx_log_load(&log, p, HX_FMT_MTMGR, 0.0, err, sizeof err), -1);
        assert_non_null(strstr(err, "likely a Movella DOT CSV; read it with --from csv --columns"));
    }
    write_mtmgr_steps(p, "", 0.0, 12, 100000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ".csv: SampleTimeFine steps by 100000: 0.1 Hz in 100 us ticks, 10 Hz in us, no '//' "
                                "line: likely a Movella DOT CSV"));
    write_mtmgr_steps(p, "", 0.0, 12, 1000000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, ": SampleTimeFine steps by 1e+06: 0.01 Hz in 100 us ticks, 1 Hz in us"));
    /* DOT's other columns (Status, ClipCountAcc/Gyr) and a trailing comma */
    write_mtmgr_steps_hdr(p, "", "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Status,ClipCountAcc,"
                          "ClipCountGyr,", 0.0, 12, 100000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    assert_non_null(strstr(err, "likely a Movella DOT CSV"));
    /* half DOT's slowest rate */
    write_mtmgr_steps(p, "", 0.0, 12, 2000000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    write_mtmgr_steps(p, "", 0.0, 12, 2000001, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 200000100000LL);
    hx_log_free(&log);
    /* a DOT CSV with one column neither DOT's nor MT Manager's (an app's own) and no DOT-only name, at each of
     * DOT's rates below 20 Hz: its steps make no MTi's rate in 100 us ticks (an MTi outputs at whole Hz, 1 or
     * more) and one of DOT's in us, so it is refused as the DOT header is, not read in ticks, 100 times too
     * slow. The same bound (2,000,000 us refused, 2,000,001 read) */
    for (c = 0; c < 5; c++) {
        const long step = (1000000L + rates[c] / 2) / rates[c];
        write_mtmgr_steps_hdr(p, "", "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Mag_X,Mag_Y,"
                              "AppTime", 0.0, 12, step, 0);
        err[0] = '\0';
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
        assert_non_null(strstr(err, "likely a Movella DOT CSV; read it with --from csv --columns"));
    }
    write_mtmgr_steps_hdr(p, "", "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Mag_X,Mag_Y,AppTime",
                          0.0, 12, 2000000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), -1);
    write_mtmgr_steps_hdr(p, "", "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Mag_X,Mag_Y,AppTime",
                          0.0, 12, 2000001, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 200000100000LL);
    hx_log_free(&log);
    /* a column only MT Manager writes: its export with the '//' lines cut, read in ticks, 0.1 Hz */
    write_mtmgr_steps_hdr(p, "", "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,StatusWord,Roll,Yaw",
                          0.0, 12, 100000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 10000000000LL);
    hx_log_free(&log);
    /* a '//' line: MT Manager's, read in ticks */
    write_mtmgr_steps(p, "// MT Manager\n", 0.0, 12, 100000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 10000000000LL);
    hx_log_free(&log);
    unlink(p);
}

/* A DOT CSV is known by a name only DOT writes (ClipCountAcc, ClipCountGyr,
 * Cal_FreeAcc_*, FreeAcc_Compared_Result, Quat_W..Z, Euler_X..Z), whatever
 * else its header holds, not only when every column is on DOT's list: a
 * column on no list (an app's own, here "UtcTime") would leave a DOT at
 * 10 Hz read at 0.1 Hz, exit 0. Given with --from mtmanager a
 * header with Euler_X (which detection leaves to the CSV reader) is refused
 * the same. A name only MT Manager writes (Roll, StatusWord, Quat_q0,
 * SampleTimeCoarse) beside DOT's mark leaves the file read in ticks. An
 * unknown column without the mark must not make it read in ticks, at 0.1
 * Hz: no MTi outputs below 1 Hz, so a header without a
 * name only MT Manager writes is DOT's at such steps, mark or none. */
static void test_mtmgr_dot_marks(void **state)
{
    static const struct {
        const char *hdr; /* 11 columns, SampleTimeFine second */
        hx_format_t from; /* HX_FMT_AUTO or HX_FMT_MTMGR */
        int refused;
    } cases[] = {
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,ClipCountAcc,ClipCountGyr,UtcTime",
          HX_FMT_AUTO, 1 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,UtcTime,Cal_FreeAcc_X,Temp", HX_FMT_AUTO,
          1 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,FreeAcc_Compared_Result,Foo,Bar",
          HX_FMT_AUTO, 1 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Euler_X,Euler_Y,UtcTime", HX_FMT_MTMGR,
          1 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Quat_W,Quat_X,Quat_Y", HX_FMT_MTMGR, 1 },
        /* MT Manager's own names beside DOT's mark: not DOT's */
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,ClipCountAcc,ClipCountGyr,Roll",
          HX_FMT_AUTO, 0 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,ClipCountAcc,StatusWord,UtcTime",
          HX_FMT_AUTO, 0 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Quat_W,Quat_q0,Quat_q1", HX_FMT_MTMGR,
          0 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Cal_FreeAcc_X,SampleTimeCoarse,Foo",
          HX_FMT_AUTO, 0 },
        /* no mark, an unknown column: 0.1 Hz in ticks is no MTi's output rate (whole Hz, 1 or more), 10 Hz in us
         * one of DOT's: refused (not read at 0.1 Hz, exit 0) */
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,Mag_X,Mag_Y,UtcTime", HX_FMT_AUTO, 1 },
        { "PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z,UtcTime,Foo,Bar", HX_FMT_MTMGR, 1 },
    };
    char p[256], err[HX_ERR_SIZE];
    hx_log_t log;
    size_t c;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        int rc;
        write_mtmgr_steps_hdr(p, "", cases[c].hdr, 0.0, 12, 100000, 0); /* 10 Hz in us, 0.1 Hz in ticks */
        if (cases[c].from == HX_FMT_AUTO) {
            assert_int_equal(hx_detect_file(p), HX_FMT_MTMGR);
        }
        err[0] = '\0';
        rc = hx_log_load(&log, p, cases[c].from, 0.0, err, sizeof err);
        if (cases[c].refused) {
            assert_int_equal(rc, -1);
            assert_non_null(strstr(err, ".csv: SampleTimeFine steps by 100000: 0.1 Hz in 100 us ticks, 10 Hz in us, "
                                        "no '//' line: likely a Movella DOT CSV; read it with --from csv"));
        } else {
            assert_int_equal(rc, 0);
            assert_int_equal(log.n, 12);
            assert_true(log.t_ns[1] - log.t_ns[0] == 10000000000LL);
            hx_log_free(&log);
        }
    }
    /* a '//' line before the marked header: MT Manager's, read in ticks */
    write_mtmgr_steps_hdr(p, "// MT Manager\n", cases[0].hdr, 0.0, 12, 100000, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_true(log.t_ns[1] - log.t_ns[0] == 10000000000LL);
    hx_log_free(&log);
    unlink(p);
}

/* The '// Update Rate' is checked against the SampleTimeFine steps (their
 * median over the first 256 rows): more than 5 % apart, a warning names
 * both and the stamps rule (the rate is theirs, not nominal); within 5 %
 * the stated rate stays the nominal one. It was taken without a check: an
 * export stating 100 Hz with stamps at 400 Hz was "100 Hz (nominal)". */
static void test_mtmgr_stated_rate(void **state)
{
    char p[256], err[320];
    hx_log_t log;
    static const struct {
        long step;
        int warned;
    } cases[] = { { 100, 0 }, { 96, 0 }, { 105, 0 }, { 94, 1 }, { 106, 1 }, { 25, 1 } };
    size_t c;
    (void)state;
    tmp_path(p, sizeof p, ".csv");
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        write_mtmgr_steps(p, "", 100.0, 12, cases[c].step, 0);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_int_equal(log.n, 12);
        assert_true(log.t_ns[1] - log.t_ns[0] == cases[c].step * 100000LL);
        if (cases[c].warned) {
            assert_non_null(strstr(log.warnings, ".csv:1: '// Update Rate' states 100 Hz, but SampleTimeFine steps by"));
            assert_non_null(strstr(log.warnings, "the stamps are used, for the time and the rate"));
            assert_int_equal(log.meta.rate_nominal, 0);
            assert_true(fabs(log.meta.rate_hz - 1.0e4 / (double)cases[c].step) < 1e-6);
        } else {
            assert_string_equal(log.warnings, "");
            assert_int_equal(log.meta.rate_nominal, 1);
            assert_true(log.meta.rate_hz == 100.0);
        }
        hx_log_free(&log);
    }
    write_mtmgr_steps(p, "", 100.0, 12, 25, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_non_null(strstr(log.warnings, ".csv:1: '// Update Rate' states 100 Hz, but SampleTimeFine steps by 25 ticks "
                                         "of 100 us (the median of the first 12 rows): 400 Hz; the stamps are used, "
                                         "for the time and the rate"));
    hx_log_free(&log);
    /* the median of the first 256 rows, whatever follows */
    write_mtmgr_steps(p, "", 100.0, 300, 25, 0);
    assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
    assert_non_null(strstr(log.warnings, "steps by 25 ticks of 100 us (the median of the first 256 rows): 400 Hz"));
    hx_log_free(&log);
    unlink(p);
    /* the same compressed: the look ahead reads the first 256 rows on the
     * reader's own handle (not a second open of the file),
     * which is put back at the first row: every row read once, in order */
    {
        gzFile gz;
        int i;
        tmp_path(p, sizeof p, ".csv.gz");
        gz = gzopen(p, "wb");
        assert_non_null(gz);
        gzprintf(gz, "// Update Rate: 100.0Hz\n" DOT_ACC_GYR_MAG "\n\n");
        for (i = 0; i < 300; i++) {
            gzprintf(gz, "%d,%ld,0.1,0.2,9.8,0.01,0.02,%d,0.4,-0.1,0.8\n", i, 1000L + 25L * i, i);
        }
        assert_int_equal(gzclose(gz), Z_OK);
        assert_int_equal(hx_log_load(&log, p, HX_FMT_AUTO, 0.0, err, sizeof err), 0);
        assert_non_null(strstr(log.warnings, "steps by 25 ticks of 100 us (the median of the first 256 rows): 400 Hz"));
        assert_int_equal(log.n, 300);
        for (i = 0; i < 300; i++) {
            assert_true(log.t_ns[i] == (1000LL + 25LL * i) * 100000LL);
            assert_true(log.gyr[i][2] == (double)i);
        }
        hx_log_free(&log);
        unlink(p);
    }
}

static int layout_reset(void **state)
{
    (void)state;
    hx_reader_set_layout(NULL);
    return 0;
}

typedef struct {
    int calls;
    double last;
    int backwards;
} prog_seen_t;

static void prog_seen(void *ctx, double frac)
{
    prog_seen_t *p = (prog_seen_t *)ctx;
    p->backwards |= frac < p->last;
    p->last = frac;
    p->calls++;
}

/* hx_log_load_progress reports the fraction of the input read while it
 * reads (every 65,536 samples) and 1 at the end, so that info and psd can
 * show progress on a long log: without it `info` on a day at 100 Hz reads
 * for 2.3 s, `convert` for 11 s, without a word. */
static void test_load_progress(void **state)
{
    enum { N = 200000 };
    char p[256], err[320];
    hx_meta_t m;
    hx_writer_t *w;
    hx_log_t log;
    fnav_sample_t s;
    prog_seen_t seen;
    long i;
    (void)state;
    memset(&m, 0, sizeof m);
    m.rate_hz = 100.0;
    m.rate_nominal = 1;
    tmp_path(p, sizeof p, ".bin");
    w = hx_writer_open(p, HX_FMT_AUTO, &m, 0, err, sizeof err);
    assert_non_null(w);
    memset(&s, 0, sizeof s);
    for (i = 0; i < N; i++) {
        s.t_ns = (int64_t)i * 10000000;
        s.seq = (uint32_t)i;
        s.accel_mps2[2] = -9.81f;
        assert_int_equal(hx_writer_write(w, &s), FNAV_OK);
    }
    assert_int_equal(hx_writer_close(w, err, sizeof err), FNAV_OK);
    memset(&seen, 0, sizeof seen);
    assert_int_equal(hx_log_load_progress(&log, p, HX_FMT_AUTO, 0.0, prog_seen, &seen, err, sizeof err), 0);
    assert_int_equal((long)log.n, N);
    assert_true(seen.calls >= 3);
    assert_int_equal(seen.backwards, 0);
    FNAV_ASSERT_CLOSE(seen.last, 1.0, 0.0, 0.0);
    hx_log_free(&log);
    /* a log that stops early (cut inside a record) does not end at 100 %:
     * `info` must not print "100 %" before the error */
    assert_int_equal(truncate(p, (off_t)(192 + 48 * (N - 10) + 20)), 0);
    memset(&seen, 0, sizeof seen);
    assert_int_equal(hx_log_load_progress(&log, p, HX_FMT_AUTO, 0.0, prog_seen, &seen, err, sizeof err), 1);
    assert_int_equal((long)log.n, N - 10);
    assert_true(seen.calls >= 2);
    assert_true(seen.last < 1.0);
    hx_log_free(&log);
    unlink(p);
}

/* The one rule for text shown from a file (hx_text_char): an ASCII
 * control, a C1 control in UTF-8 and a byte of no well-formed UTF-8
 * character are one '?' each; a UTF-8 letter of 2 to 4 bytes is kept
 * whole. Before, a raw 0x9B (CSI to a terminal of 8-bit controls) or a
 * Latin-1 byte passed as it was (a CLI mutation sweep's messages). */
static void test_printable_utf8(void **state)
{
    static const struct {
        const char *in, *out;
        int n;
    } k_case[] = {
        { "a\x1b]0;X\x07" "b", "a?]0;X?b", 2 },      /* ASCII controls */
        { "0\xc2\x9b" "2J", "0?2J", 1 },              /* U+009B in UTF-8 */
        { "0\x9b" "2J", "0?2J", 1 },                  /* a raw 0x9B */
        { "caf\xe9", "caf?", 1 },                    /* Latin-1 */
        { "caf\xc3\xa9", "caf\xc3\xa9", 0 },          /* UTF-8 e acute */
        { "\xf0\x9f\x98\x80!", "\xf0\x9f\x98\x80!", 0 }, /* 4 bytes, U+1F600 */
        { "\xc0\xaf", "??", 2 },                     /* an overlong '/' */
        { "\xed\xa0\x80", "???", 3 },                /* a surrogate */
        { "\xe2\x82", "??", 2 },                     /* a letter cut at the end */
        { "\xe2\x82x", "??x", 2 },                   /* ... and before an ASCII one */
    };
    char buf[64], small[6];
    size_t i;
    (void)state;
    for (i = 0; i < sizeof k_case / sizeof k_case[0]; i++) {
        snprintf(buf, sizeof buf, "%s", k_case[i].in);
        assert_int_equal(hx_printable(buf), k_case[i].n);
        assert_string_equal(buf, k_case[i].out);
        assert_string_equal(hx_line_str(buf, sizeof buf, k_case[i].in), k_case[i].out);
    }
    /* cut to fit at a character's start, never inside a letter: 5 bytes
     * of room hold "ab" and one two-byte letter, not half of the next */
    assert_string_equal(hx_line_str(small, sizeof small, "ab\xc3\xa9\xc3\xa9"), "ab\xc3\xa9");
    assert_string_equal(hx_line_str(small, sizeof small, "abcd\x1b"), "abcd?");
    assert_string_equal(hx_line_str(small, sizeof small, "abcd\xc3\xa9"), "abcd");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_golden_read),
        cmocka_unit_test(test_golden_write),
        cmocka_unit_test(test_csv_bin_csv_text),
        cmocka_unit_test(test_bin_truncated),
        cmocka_unit_test(test_bin_corrupted),
        cmocka_unit_test(test_bin_bad_magic),
        cmocka_unit_test(test_bin_nan_record),
        cmocka_unit_test(test_bin_bad_record_values),
        cmocka_unit_test(test_bin_value_in_ug),
        cmocka_unit_test(test_bin_header_fields),
        cmocka_unit_test(test_bin_end_count),
        cmocka_unit_test(test_bin_resync_counts),
        cmocka_unit_test(test_bin_resync_numbers),
        cmocka_unit_test(test_csv_malformed),
        cmocka_unit_test(test_csv_flexible),
        cmocka_unit_test(test_csv_missing_temp),
        cmocka_unit_test(test_csv_gzip),
        cmocka_unit_test(test_cut_last_line),
        cmocka_unit_test(test_counter_ranges),
        cmocka_unit_test(test_bad_rate),
        cmocka_unit_test(test_importers),
        cmocka_unit_test(test_importer_units),
        cmocka_unit_test(test_importer_first_rows),
        cmocka_unit_test(test_gx2_lost_packets),
        cmocka_unit_test(test_gx2_field_count),
        cmocka_unit_test(test_gx2_restart_then_error),
        cmocka_unit_test(test_gx2_first_restart),
        cmocka_unit_test(test_gx2_long),
        cmocka_unit_test(test_gx2_repeated_packet),
        cmocka_unit_test(test_gx2_restart_tolerance),
        cmocka_unit_test(test_gx2_first_restart_lost),
        cmocka_unit_test(test_gx2_first_restart_host_column),
        cmocka_unit_test(test_gx2_cut_last_line),
        cmocka_unit_test(test_gx2_timer_cases),
        cmocka_unit_test(test_quoted_values_and_ipol_rate),
        cmocka_unit_test(test_csv_negative_time),
        cmocka_unit_test(test_ipol_counter_wrap),
        cmocka_unit_test(test_ipol_rate_and_step_back),
        cmocka_unit_test(test_short_rows_warned),
        cmocka_unit_test(test_long_rows_warned),
        cmocka_unit_test(test_range_in_si_units),
        cmocka_unit_test(test_detect_variants),
        cmocka_unit_test(test_decimal_comma),
        cmocka_unit_test(test_datetime_stamps),
        cmocka_unit_test(test_consensys),
        cmocka_unit_test(test_units_row),
        cmocka_unit_test(test_numbered_columns),
        cmocka_unit_test(test_ros_euroc),
        cmocka_unit_test(test_format_list),
        cmocka_unit_test(test_fuzz_seed_formats),
        cmocka_unit_test(test_detect_wrong_hint),
        cmocka_unit_test(test_gz_truncated),
        cmocka_unit_test(test_bin_gz_header_cut),
        cmocka_unit_test(test_stamp_rate),
        cmocka_unit_test(test_stamp_bursts),
        cmocka_unit_test(test_stamp_bursts_rate),
        cmocka_unit_test(test_bursts_remedy),
        cmocka_unit_test(test_roundtrip_all_formats),
        cmocka_unit_test(test_killed_writer),
        cmocka_unit_test(test_bin_rate_unknown),
        cmocka_unit_test(test_format_names),
        cmocka_unit_test(test_load_progress),
        cmocka_unit_test(test_mtmgr_wraps_and_gap),
        cmocka_unit_test(test_mtmgr_nan_rows),
        cmocka_unit_test(test_mtmgr_columns_and_rate),
        cmocka_unit_test(test_mtmgr_refused),
        cmocka_unit_test(test_mtmgr_detect),
        cmocka_unit_test(test_mtmgr_us_stamps),
        cmocka_unit_test(test_mtmgr_dot_rates),
        cmocka_unit_test(test_mtmgr_dot_marks),
        cmocka_unit_test(test_mtmgr_stated_rate),
        cmocka_unit_test_teardown(test_csv_layout, layout_reset),
        cmocka_unit_test_teardown(test_columns_tns, layout_reset),
        cmocka_unit_test_teardown(test_columns_negate, layout_reset),
        cmocka_unit_test(test_columns_give),
        cmocka_unit_test(test_shell_word),
        cmocka_unit_test(test_picoquake),
        cmocka_unit_test(test_name_classify),
        cmocka_unit_test(test_names_match),
        cmocka_unit_test(test_name_units_utf8),
        cmocka_unit_test(test_units_option_utf8),
        cmocka_unit_test_teardown(test_csv_names, layout_reset),
        cmocka_unit_test_teardown(test_columns_unit_warned, layout_reset),
        cmocka_unit_test(test_time_unit_rate),
        cmocka_unit_test(test_printable_utf8),
    };
    return cmocka_run_group_tests_name("log", tests, setup_golden, NULL);
}
