/* Sensor profile files (docs/profile-format.md). */
#include "hx_profile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hx_cli.h"

#define PROFILE_MAGIC "footnav-profile 1"

typedef struct {
    const char *key;
    size_t offset; /* of a fnav_real_t[3] in fnav_profile_t */
    double lo, hi; /* its limits (hx_profile.h) */
    const char *why;
} key3_t;

static const key3_t k_keys[6] = {
    { "accel_noise_mps2_rthz", offsetof(fnav_profile_t, accel_noise_mps2_rthz), HX_PROFILE_NOISE_MIN,
      HX_PROFILE_NOISE_MAX, "positive in float; sim's white density at most 1e3" },
    { "accel_tau_s", offsetof(fnav_profile_t, accel_tau_s), HX_PROFILE_TAU_MIN_S, HX_PROFILE_TAU_MAX_S,
      "sim's ar1 tau_s range" },
    { "accel_bias_sigma_mps2", offsetof(fnav_profile_t, accel_bias_sigma_mps2), HX_PROFILE_SIGMA_MIN,
      HX_PROFILE_SIGMA_MAX, "the filter's square positive in float; sim's ar1 sigma at most 1e3" },
    { "gyro_noise_rps_rthz", offsetof(fnav_profile_t, gyro_noise_rps_rthz), HX_PROFILE_NOISE_MIN,
      HX_PROFILE_NOISE_MAX, "positive in float; sim's white density at most 1e3" },
    { "gyro_tau_s", offsetof(fnav_profile_t, gyro_tau_s), HX_PROFILE_TAU_MIN_S, HX_PROFILE_TAU_MAX_S,
      "sim's ar1 tau_s range" },
    { "gyro_bias_sigma_rps", offsetof(fnav_profile_t, gyro_bias_sigma_rps), HX_PROFILE_SIGMA_MIN,
      HX_PROFILE_SIGMA_MAX, "the filter's square positive in float; sim's ar1 sigma at most 1e3" },
};

#define RATE_WHY "an IMU's output rate"

/* The keys a misspelling is matched against: those read (format, name,
 * rate_hz, then k_keys' order), then the optional ones `allan --profile`
 * writes (cmd_allan.c, write_profile). */
enum { KEY_FORMAT, KEY_NAME, KEY_RATE, KEY_VEC0, KEY_NREAD = KEY_VEC0 + 6 };
static const char *const k_known[] = {
    "format", "name", "rate_hz", "accel_noise_mps2_rthz", "accel_tau_s", "accel_bias_sigma_mps2",
    "gyro_noise_rps_rthz", "gyro_tau_s", "gyro_bias_sigma_rps", "ident_method", "ident_samples",
    "accel_quant_mps", "gyro_quant_rad", "accel_rrw_mps2_rts", "gyro_rrw_rps_rts", "ident_bound_accel",
    "ident_bound_gyro", "allan_fit_rms_log10_accel", "allan_fit_rms_log10_gyro", "paper_accel_noise_mps2_rthz",
    "paper_accel_tau_s", "paper_accel_bias_sigma_mps2", "paper_gyro_noise_rps_rthz", "paper_gyro_tau_s",
    "paper_gyro_bias_sigma_rps",
};
#define NKNOWN (sizeof k_known / sizeof k_known[0])

/* 1 for a key of the documented optional families, never warned about:
 * what allan writes and may write later (profile-format.md), and x_*, the
 * user's own */
static int key_optional(const char *key)
{
    return strncmp(key, "x_", 2) == 0 || strncmp(key, "ident_", 6) == 0 || strncmp(key, "paper_", 6) == 0 ||
           strncmp(key, "allan_fit_rms_log10_", 20) == 0 || strstr(key, "_quant_") != NULL ||
           strstr(key, "_rrw_") != NULL;
}

/* How far the unknown key u is from the known key k: the Levenshtein
 * distance to k, or 1 more than that to a part of k ending at an '_'
 * (gyro_nosie is 2 from gyro_noise, so 3 from gyro_noise_rps_rthz, not
 * the 11 of the whole key). Two rows over k, iterative. */
#define KEY_DIST_FAR 1000u
static unsigned key_distance(const char *u, const char *k)
{
    unsigned row[2][40];
    const size_t lk = strlen(k), lu = strlen(u);
    size_t i, j;
    unsigned best;
    if (lk + 1u > sizeof row[0] / sizeof row[0][0] || lu > 64u) {
        return KEY_DIST_FAR;
    }
    for (j = 0; j <= lk; j++) {
        row[0][j] = (unsigned)j;
    }
    for (i = 1; i <= lu; i++) {
        unsigned *prev = row[(i - 1u) & 1u], *cur = row[i & 1u];
        cur[0] = (unsigned)i;
        for (j = 1; j <= lk; j++) {
            unsigned d = prev[j - 1] + (u[i - 1] != k[j - 1]);
            d = prev[j] + 1u < d ? prev[j] + 1u : d;
            d = cur[j - 1] + 1u < d ? cur[j - 1] + 1u : d;
            cur[j] = d;
        }
    }
    best = row[lu & 1u][lk];
    for (j = 1; j < lk; j++) {
        if (k[j] == '_' && row[lu & 1u][j] + 1u < best) {
            best = row[lu & 1u][j] + 1u;
        }
    }
    return best;
}

/* The known key an unknown one most likely meant (index in k_known), or
 * -1: within 3 edits, fewer for a short key (within 1 for 3 letters) */
static int key_suggest(const char *u)
{
    const size_t lu = strlen(u);
    const unsigned limit = lu >= 6u ? 3u : lu >= 4u ? 2u : 1u;
    unsigned best = KEY_DIST_FAR;
    int at = -1;
    size_t i;
    for (i = 0; i < NKNOWN; i++) {
        const unsigned d = key_distance(u, k_known[i]);
        if (d < best) {
            best = d;
            at = (int)i;
        }
    }
    return best <= limit ? at : -1;
}

/* Index of the first character of a name shown as '?' (hx_text_char: a
 * control character, or a byte that is not UTF-8 text), or
 * -1; a name goes to stdout (sim's effect lines, replay's summary) */
static long name_control(const char *s)
{
    long i = 0;
    while (s[i] != '\0') {
        int ctl;
        const size_t k = hx_text_char(s + i, &ctl);
        if (ctl) {
            return i;
        }
        i += (long)k;
    }
    return -1;
}

/* What the character name_control() found at s is, for its message */
static const char *name_bad_what(const char *s)
{
    int ctl;
    /* hx_text_char's '?' of two bytes is a C1 control; of one, an ASCII control or a byte of no character */
    return hx_text_char(s, &ctl) == 2u || (unsigned char)s[0] < 0x80u ? "a control character"
                                                                       : "a byte that is not UTF-8 text";
}

static char *trim(char *s)
{
    char *e;
    while (*s == ' ' || *s == '\t') {
        s++;
    }
    e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '\n')) {
        *--e = '\0';
    }
    return s;
}

/* The number at s (after blanks) into *v, its text [*num, *end): 0, -1
 * when the text up to the next blank is no number, -2 when it has an x or
 * a p: strtod reads 0x10 as 16 and 0x1p-3 as 0.125, and a profile's
 * numbers are decimal as the options' are (docs/harness.md) */
static int read_decimal(const char *s, double *v, const char **num, const char **end)
{
    const char *t = s + strspn(s, " \t");
    const size_t n = strcspn(t, " \t");
    char *stop;
    *num = t;
    *end = t + n;
    if (n == 0u) {
        return -1;
    }
    if (strcspn(t, "xXpP") < n) {
        return -2;
    }
    *v = strtod(t, &stop);
    return stop == t + n ? 0 : -1;
}

/* One line of f into line[size] without its newline. Returns its length,
 * or READ_EOF at the end of the file, READ_LONG when it does not fit,
 * READ_NUL on a NUL byte (not a text file: with fgets it would show as "line
 * too long"), READ_ERROR when reading failed (a directory read as a file
 * would otherwise be "not a footnav profile"). */
enum { READ_EOF = -1, READ_LONG = -2, READ_NUL = -3, READ_ERROR = -4 };
static long read_line(FILE *f, char *line, size_t size)
{
    size_t n = 0;
    int c;
    while ((c = getc(f)) != EOF && c != '\n') {
        if (c == '\0') {
            return READ_NUL;
        }
        if (n + 1u >= size) {
            return READ_LONG;
        }
        line[n++] = (char)c;
    }
    if (ferror(f)) {
        return READ_ERROR;
    }
    if (c == EOF && n == 0u) {
        return READ_EOF;
    }
    line[n] = '\0';
    return (long)n;
}

/* An unknown key kept for the error about a missing one it may spell */
#define UNKNOWN_KEPT 16
typedef struct {
    int line, meant; /* meant: index in k_known, or -1 */
    char text[48];
} unknown_t;

/* "; line N has 'TEXT', unknown: misspelt?" when an unknown key kept in
 * u[n] most likely meant k_known[key], else "" */
static const char *misspelt(char *buf, size_t size, const unknown_t *u, int n, int key)
{
    int i;
    buf[0] = '\0';
    for (i = 0; i < n; i++) {
        if (u[i].meant == key) {
            snprintf(buf, size, "; line %d has '%s', unknown: misspelt?", u[i].line, u[i].text);
            break;
        }
    }
    return buf;
}

int hx_profile_read(const char *path, fnav_profile_t *p, char *err, size_t err_size)
{
    return hx_profile_read_warn(path, p, NULL, 0, err, err_size);
}

/* The unknown-key warnings kept in a warn buffer; the rest are counted,
 * and so is a line the buffer has no room for (a long path): room is kept
 * for the count's line, so an unknown key is never ignored without a word */
#define WARN_LINES_MAX 8
#define WARN_COUNT_ROOM 64 /* the count's line but the path */

int hx_profile_read_warn(const char *path, fnav_profile_t *p, char *warn, size_t warn_size, char *err,
                         size_t err_size)
{
    FILE *f = fopen(path, "r");
    char line[513]; /* 511 characters (profile-format.md), a CR and the terminator */
    char hint[128];
    long len;
    int lineno = 0, have_magic = 0, have_rate = 0, have_name = 0, have[6] = { 0, 0, 0, 0, 0, 0 };
    int i, nunknown = 0, nwarned = 0, nshown = 0;
    size_t wlen = 0, keep = strlen(path) + WARN_COUNT_ROOM;
    unknown_t unknown[UNKNOWN_KEPT];
    if (warn_size == 0u) {
        warn = NULL;
    }
    if (warn != NULL) {
        warn[0] = '\0';
    }
    if (f == NULL) {
        snprintf(err, err_size, "%s: cannot open profile (%s)", path, strerror(errno));
        return -1;
    }
    memset(p, 0, sizeof *p);
    while ((len = read_line(f, line, sizeof line)) != READ_EOF) {
        char *eq, *key, *val;
        lineno++;
        if (len == READ_ERROR) {
            snprintf(err, err_size, "%s: cannot read profile (%s)", path, strerror(errno));
            fclose(f);
            return -1;
        }
        if (len == READ_NUL) {
            snprintf(err, err_size, "%s:%d: NUL byte: not a text file (a profile is 'key = value' lines)", path,
                     lineno);
            fclose(f);
            return -1;
        }
        if (len == READ_LONG || (len > 511 && line[len - 1] != '\r')) {
            snprintf(err, err_size, "%s:%d: line too long (at most 511 characters)", path, lineno);
            fclose(f);
            return -1;
        }
        key = line;
        if (lineno == 1 && len >= 3 && memcmp(key, "\xef\xbb\xbf", 3) == 0) {
            /* a UTF-8 byte order mark (an editor's), skipped as the CSV
             * reader does: the file read as "not a footnav profile" */
            key += 3;
        }
        key = trim(key);
        if (*key == '\0' || *key == '#') {
            continue;
        }
        eq = strchr(key, '=');
        if (eq == NULL) {
            snprintf(err, err_size, "%s:%d: expected 'key = value'", path, lineno);
            fclose(f);
            return -1;
        }
        *eq = '\0';
        key = trim(key);
        val = trim(eq + 1);
        if ((strcmp(key, "format") == 0 && have_magic) || (strcmp(key, "rate_hz") == 0 && have_rate) ||
            (strcmp(key, "name") == 0 && have_name)) {
            /* a key given twice (name too): which one was meant is not
             * known, so the last one is not taken silently */
            snprintf(err, err_size, "%s:%d: %s given twice", path, lineno, key);
            fclose(f);
            return -1;
        }
        if (strcmp(key, "format") == 0) {
            if (strcmp(val, PROFILE_MAGIC) != 0) {
                snprintf(err, err_size, "%s:%d: format '%s' not supported (expected '%s')", path, lineno, val,
                         PROFILE_MAGIC);
                fclose(f);
                return -1;
            }
            have_magic = 1;
        } else if (strcmp(key, "name") == 0) {
            const long bad = name_control(val);
            if (bad >= 0) {
                /* an ESC in the name went to the terminal as is */
                snprintf(err, err_size, "%s:%d: name has %s (byte %ld, 0x%02x): a name is printable text", path,
                         lineno, name_bad_what(val + bad), bad + 1, (unsigned)(unsigned char)val[bad]);
                fclose(f);
                return -1;
            }
            (void)hx_line_str(p->name, sizeof p->name, val); /* cut before a UTF-8 letter, not inside one */
            have_name = 1;
        } else if (strcmp(key, "rate_hz") == 0) {
            const char *num, *end;
            double v = 0.0;
            const int rc = read_decimal(val, &v, &num, &end);
            if (rc == -2) {
                snprintf(err, err_size, "%s:%d: rate_hz '%s' is not a decimal number (no hexadecimal)", path, lineno,
                         val);
                fclose(f);
                return -1;
            }
            if (rc != 0 || *end != '\0' || !isfinite(v) || !(v > 0.0)) {
                snprintf(err, err_size, "%s:%d: rate_hz '%s' is not a positive number", path, lineno, val);
                fclose(f);
                return -1;
            }
            p->rate_hz = (fnav_real_t)v;
            if (!(p->rate_hz > FNAV_R(0.0)) || !isfinite(p->rate_hz)) {
                /* 1e-50 is 0 in float: said at its line, with its key (not
                 * "a value is zero ... in the float build", no line, no
                 * key) */
                snprintf(err, err_size, "%s:%d: rate_hz '%s' is %s in the %s build (out of its range)", path, lineno,
                         val, isfinite(p->rate_hz) ? "0" : "infinite", FNAV_USE_DOUBLE ? "double" : "float");
                fclose(f);
                return -1;
            }
            if (!(v >= HX_PROFILE_RATE_MIN_HZ && v <= HX_PROFILE_RATE_MAX_HZ)) {
                snprintf(err, err_size, "%s:%d: rate_hz '%s' outside [%g, %g] (%s)", path, lineno, val,
                         HX_PROFILE_RATE_MIN_HZ, HX_PROFILE_RATE_MAX_HZ, RATE_WHY);
                fclose(f);
                return -1;
            }
            have_rate = 1;
        } else {
            int found = 0;
            for (i = 0; i < 6; i++) {
                if (strcmp(key, k_keys[i].key) == 0) {
                    fnav_real_t *dst = (fnav_real_t *)((char *)p + k_keys[i].offset);
                    const char *s = val, *num, *end = val;
                    int k;
                    found = 1;
                    if (have[i]) {
                        snprintf(err, err_size, "%s:%d: %s given twice", path, lineno, key);
                        fclose(f);
                        return -1;
                    }
                    for (k = 0; k < 3; k++) {
                        double v = 0.0;
                        const int rc = read_decimal(s, &v, &num, &end);
                        if (rc == -2) {
                            snprintf(err, err_size, "%s:%d: %s value %d '%.*s' is not a decimal number (no "
                                                    "hexadecimal)",
                                     path, lineno, key, k + 1, (int)(end - num), num);
                            fclose(f);
                            return -1;
                        }
                        if (rc != 0 || !isfinite(v) || !(v > 0.0)) {
                            snprintf(err, err_size, "%s:%d: %s needs three positive numbers (x y z)", path, lineno,
                                     key);
                            fclose(f);
                            return -1;
                        }
                        dst[k] = (fnav_real_t)v;
                        if (!isfinite(dst[k]) || !(dst[k] > FNAV_R(0.0))) {
                            /* positive in double, not in the working
                             * precision (1e39, 1e-50 in float): at its line */
                            snprintf(err, err_size, "%s:%d: %s value %d '%.*s' is %s in the %s build (out of its range)",
                                     path, lineno, key, k + 1, (int)(end - num), num,
                                     isfinite(dst[k]) ? "0" : "infinite", FNAV_USE_DOUBLE ? "double" : "float");
                            fclose(f);
                            return -1;
                        }
                        if (!(v >= k_keys[i].lo && v <= k_keys[i].hi)) {
                            /* refused here for every command: the filter
                             * took what the simulator refused later */
                            snprintf(err, err_size, "%s:%d: %s value %d '%.*s' outside [%g, %g] (%s)", path, lineno,
                                     key, k + 1, (int)(end - num), num, k_keys[i].lo, k_keys[i].hi, k_keys[i].why);
                            fclose(f);
                            return -1;
                        }
                        s = end;
                    }
                    if (*trim(val + (end - val)) != '\0') {
                        snprintf(err, err_size, "%s:%d: %s: unexpected text after three values", path, lineno, key);
                        fclose(f);
                        return -1;
                    }
                    have[i] = 1;
                    break;
                }
            }
            if (!found && !key_optional(key)) {
                /* ignored (a later version's key reads in this one), not
                 * without a word: gyro_nosie left the default unseen */
                const int meant = key_suggest(key);
                char q[48];
                (void)hx_line_str(q, sizeof q, key); /* the file's text, a control character as '?' */
                if (nunknown < UNKNOWN_KEPT) {
                    unknown[nunknown].line = lineno;
                    unknown[nunknown].meant = meant;
                    snprintf(unknown[nunknown].text, sizeof unknown[nunknown].text, "%s", q);
                    nunknown++;
                }
                if (warn != NULL && nwarned < WARN_LINES_MAX) {
                    int m;
                    if (meant >= 0) {
                        m = snprintf(warn + wlen, warn_size - wlen, "%s:%d: unknown key '%s' ignored (did you mean %s?)\n",
                                     path, lineno, q, k_known[meant]);
                    } else {
                        m = snprintf(warn + wlen, warn_size - wlen,
                                     "%s:%d: unknown key '%s' ignored (a key of your own starts with x_)\n", path, lineno,
                                     q);
                    }
                    if (m > 0 && (size_t)m + keep < warn_size - wlen) {
                        wlen += (size_t)m;
                        nshown++;
                    } else {
                        warn[wlen] = '\0'; /* a line that does not fit is left out whole, and counted */
                    }
                }
                nwarned++;
            }
        }
    }
    fclose(f);
    if (warn != NULL && nwarned > nshown) {
        int m = snprintf(warn + wlen, warn_size - wlen, "%s: %d %sunknown key%s ignored\n", path, nwarned - nshown,
                         nshown > 0 ? "more " : "", nwarned - nshown > 1 ? "s" : "");
        if (!(m > 0 && (size_t)m < warn_size - wlen)) {
            /* a path too long for the buffer: the count without it (the
             * caller's buffer holds one of PATH_MAX) */
            snprintf(warn, warn_size, "%d unknown key%s ignored in the profile file\n", nwarned,
                     nwarned > 1 ? "s" : "");
        }
    }
    /* no line to name: the file's name alone, and the line of an unknown
     * key that may spell the missing one */
    if (!have_magic) {
        snprintf(err, err_size, "%s: not a footnav profile (no 'format = %s' line%s)", path, PROFILE_MAGIC,
                 misspelt(hint, sizeof hint, unknown, nunknown, KEY_FORMAT));
        return -1;
    }
    if (!have_rate) {
        snprintf(err, err_size, "%s: no line gives rate_hz (a required key%s)", path,
                 misspelt(hint, sizeof hint, unknown, nunknown, KEY_RATE));
        return -1;
    }
    for (i = 0; i < 6; i++) {
        if (!have[i]) {
            snprintf(err, err_size, "%s: no line gives %s (a required key%s)", path, k_keys[i].key,
                     misspelt(hint, sizeof hint, unknown, nunknown, KEY_VEC0 + i));
            return -1;
        }
    }
    if (p->name[0] == '\0') {
        snprintf(p->name, sizeof p->name, "file");
    }
    /* every value is within the limits, each positive and finite in
     * either precision: fnav_profile_validate holds (the check it had here,
     * "a value is zero, negative or not finite", could not be reached) */
    return 0;
}

int hx_profile_check(const fnav_profile_t *p, char *err, size_t err_size)
{
    const double rate = (double)p->rate_hz;
    const long bad = name_control(p->name);
    int i, k;
    if (!(rate >= HX_PROFILE_RATE_MIN_HZ && rate <= HX_PROFILE_RATE_MAX_HZ)) {
        snprintf(err, err_size, "rate_hz %g outside [%g, %g] (%s)", rate, HX_PROFILE_RATE_MIN_HZ,
                 HX_PROFILE_RATE_MAX_HZ, RATE_WHY);
        return -1;
    }
    for (i = 0; i < 6; i++) {
        const fnav_real_t *v = (const fnav_real_t *)((const char *)p + k_keys[i].offset);
        for (k = 0; k < 3; k++) {
            if (!((double)v[k] >= k_keys[i].lo && (double)v[k] <= k_keys[i].hi)) {
                snprintf(err, err_size, "%s value %d %g outside [%g, %g] (%s)", k_keys[i].key, k + 1, (double)v[k],
                         k_keys[i].lo, k_keys[i].hi, k_keys[i].why);
                return -1;
            }
        }
    }
    if (bad >= 0) {
        snprintf(err, err_size, "name has %s (byte %ld, 0x%02x): a name is printable text", name_bad_what(p->name + bad),
                 bad + 1, (unsigned)(unsigned char)p->name[bad]);
        return -1;
    }
    return 0;
}

int hx_profile_write(const char *path, const fnav_profile_t *p, const char *comment, char *err, size_t err_size)
{
    return hx_profile_write_extra(path, p, comment, NULL, err, err_size);
}

int hx_profile_write_extra(const char *path, const fnav_profile_t *p, const char *comment, const char *extra,
                           char *err, size_t err_size)
{
    FILE *f = fopen(path, "w");
    int i;
    if (f == NULL) {
        snprintf(err, err_size, "%s: cannot create (%s)", path, strerror(errno));
        return -1;
    }
    fprintf(f, "# footnav sensor profile (docs/profile-format.md)\n");
    if (comment != NULL) {
        const char *c = comment;
        while (*c != '\0') {
            const char *nl = strchr(c, '\n');
            size_t n = nl ? (size_t)(nl - c) : strlen(c);
            fprintf(f, "# %.*s\n", (int)n, c);
            c += n + (nl ? 1 : 0);
        }
    }
    fprintf(f, "format = %s\nname = %s\nrate_hz = %.9g\n", PROFILE_MAGIC, p->name, (double)p->rate_hz);
    for (i = 0; i < 6; i++) {
        const fnav_real_t *v = (const fnav_real_t *)((const char *)p + k_keys[i].offset);
        fprintf(f, "%s = %.9g %.9g %.9g\n", k_keys[i].key, (double)v[0], (double)v[1], (double)v[2]);
    }
    if (extra != NULL) {
        fputs(extra, f);
    }
    if (fclose(f) != 0) {
        snprintf(err, err_size, "%s: write failed (%s)", path, strerror(errno));
        return -1;
    }
    return 0;
}

/* The advice of a flagged value v of a key in unit `key_unit`: the units
 * it was most likely written in, a (factor fa, spelt fa_txt) and b, each
 * named when v converted from it is itself within `limit` (the key's
 * bound, in the key's unit), both when neither or both are. */
static void units_advice(char *buf, size_t n, double v, double limit, const char *key_unit, const char *ua, double fa,
                         const char *fa_txt, const char *ub, double fb, const char *fb_txt)
{
    const int ok_a = v * fa <= limit, ok_b = v * fb <= limit;
    if (ok_a != ok_b) {
        snprintf(buf, n, "in %s? the key is in %s (x %s = %.3g)", ok_a ? ua : ub, key_unit, ok_a ? fa_txt : fb_txt,
                 v * (ok_a ? fa : fb));
    } else {
        snprintf(buf, n, "in %s or %s? the key is in %s (x %s = %.3g from %s, x %s = %.3g from %s)", ua, ub, key_unit,
                 fa_txt, v * fa, ua, fb_txt, v * fb, ub);
    }
}

int hx_profile_implausible(const fnav_profile_t *p, char *msg, size_t n)
{
    /* the bounds in the keys' units; the advice names the datasheet units
     * too: a gyro's angle random walk in deg/sqrt(h) and bias instability
     * in deg/h, an accelerometer's noise and bias in ug. Naming only deg/s
     * and mg would be followed (10 deg/h written as 10 -> 0.175 rad/s) with
     * a value still thousands of times too large, no longer flagged */
    const double pi = 3.14159265358979323846, g = 9.80665;
    const double wn_max = pi / 180.0, an_max = 0.01 * g, wb_max = 10.0 * pi / 180.0, ab_max = 0.1 * g;
    char adv[224];
    int i;
    for (i = 0; i < 3; i++) {
        const double wn = (double)p->gyro_noise_rps_rthz[i], an = (double)p->accel_noise_mps2_rthz[i];
        const double wb = (double)p->gyro_bias_sigma_rps[i], ab = (double)p->accel_bias_sigma_mps2[i];
        if (wn > wn_max) {
            units_advice(adv, sizeof adv, wn, wn_max, "rad/s/sqrt(Hz)", "deg/s/sqrt(Hz)", pi / 180.0, "pi/180",
                         "deg/sqrt(h)", pi / 10800.0, "pi/10800");
            snprintf(msg, n, "gyro_noise_rps_rthz %g is %.3g deg/s/sqrt(Hz), above any IMU's (1 deg/s/sqrt(Hz)): %s", wn,
                     wn * 180.0 / pi, adv);
            return 1;
        }
        if (an > an_max) {
            units_advice(adv, sizeof adv, an, an_max, "m/s^2/sqrt(Hz)", "mg/sqrt(Hz)", g / 1e3, "0.00980665",
                         "ug/sqrt(Hz)", g / 1e6, "9.80665e-6");
            snprintf(msg, n, "accel_noise_mps2_rthz %g is %.3g mg/sqrt(Hz), above any IMU's (10 mg/sqrt(Hz)): %s", an,
                     1e3 * an / g, adv);
            return 1;
        }
        if (wb > wb_max) {
            units_advice(adv, sizeof adv, wb, wb_max, "rad/s", "deg/s", pi / 180.0, "pi/180", "deg/h", pi / 648000.0,
                         "pi/648000");
            snprintf(msg, n, "gyro_bias_sigma_rps %g is %.3g deg/s, above any IMU's in-run bias (10 deg/s): %s", wb,
                     wb * 180.0 / pi, adv);
            return 1;
        }
        if (ab > ab_max) {
            units_advice(adv, sizeof adv, ab, ab_max, "m/s^2", "mg", g / 1e3, "0.00980665", "ug", g / 1e6,
                         "9.80665e-6");
            snprintf(msg, n, "accel_bias_sigma_mps2 %g is %.3g g, above any IMU's in-run bias (0.1 g): %s", ab, ab / g,
                     adv);
            return 1;
        }
    }
    return 0;
}

/* 1 when the file named @p path was warned about already, else 0 (then
 * remembered). Each file warned about is kept as the 64-bit FNV-1a hash of
 * its name as given (hx_fnv1a), so that loading A, B, A warns about A once (the last
 * one alone would warn about A twice). A full table remembers no
 * more: a file warned about after the first HX_PROFILE_WARNED_MAX is
 * warned about at each load (repeated). Two names with the same hash would
 * drop the second one's warning: with n names the odds are about
 * n^2 / 2^65 (1e-16 for the table's 64). */
static int profile_warned(const char *path)
{
    static unsigned long long seen[HX_PROFILE_WARNED_MAX];
    static size_t nseen;
    const unsigned long long h = hx_fnv1a(HX_FNV1A_INIT, path);
    size_t i;
    for (i = 0; i < nseen; i++) {
        if (seen[i] == h) {
            return 1;
        }
    }
    if (nseen < HX_PROFILE_WARNED_MAX) {
        seen[nseen++] = h;
    }
    return 0;
}

int hx_profile_load(const char *name_or_path, fnav_profile_t *p, char *err, size_t err_size)
{
    char msg[320], warn[8192]; /* WARN_LINES_MAX lines and the count's, of a path of PATH_MAX */
    int implausible;
    if (fnav_profile_by_name(p, name_or_path) == FNAV_OK) {
        return 0;
    }
    if (strchr(name_or_path, '/') == NULL && strchr(name_or_path, '.') == NULL) {
        /* a file named `mysensor` is a built-in's name by this rule: the
         * error says so beside "unknown profile", and how to give the file */
        struct stat st;
        int found = stat(name_or_path, &st) == 0;
        int is_file = found && S_ISREG(st.st_mode);
        int is_dir = found && S_ISDIR(st.st_mode); /* named, not "unknown profile" alone */
        snprintf(err, err_size,
                 "unknown profile '%s' (built-in: navchip, mtx, shimmer, generic-mems; or a profile file)%s%s%s",
                 name_or_path,
                 is_file  ? "; a file of that name exists: give it as ./"
                 : is_dir ? "; '"
                          : "",
                 is_file || is_dir ? name_or_path : "", is_dir ? "' is a directory, not a profile file" : "");
        return -1;
    }
    if (hx_profile_read_warn(name_or_path, p, warn, sizeof warn, err, err_size) != 0) {
        return -1;
    }
    /* a file edited by hand in the wrong unit (a gyro noise in
     * deg/s/sqrt(Hz)) is valid but not plausible: replay on the bundled
     * walk ends 0.33 m from its start instead of 0.04 m with it. Valid, so
     * a warning; the run goes on. */
    implausible = hx_profile_implausible(p, msg, sizeof msg);
    if ((implausible || warn[0] != '\0') && !profile_warned(name_or_path)) {
        /* once per file in a run: a command that loads its profiles once
         * per seed (montecarlo, the sensor's and the filter's) says each
         * once */
        const char *w = warn;
        while (*w != '\0') {
            const char *nl = strchr(w, '\n');
            const size_t n = nl != NULL ? (size_t)(nl - w) : strlen(w);
            hx_warn(hx_cmd_name, "%.*s", (int)n, w);
            w += n + (nl != NULL ? 1u : 0u);
        }
        if (implausible) {
            hx_warn(hx_cmd_name, "%s: %s", name_or_path, msg);
        }
    }
    return 0;
}

int hx_profile_is_output(const char *cmd, const char *name_or_path, const hx_args_t *a, const char *const *outs)
{
    fnav_profile_t tmp;
    if (name_or_path == NULL || fnav_profile_by_name(&tmp, name_or_path) == FNAV_OK) {
        return 0;
    }
    return hx_output_is_input(cmd, name_or_path, a, outs);
}
