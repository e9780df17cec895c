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
} key3_t;

static const key3_t k_keys[6] = {
    { "accel_noise_mps2_rthz", offsetof(fnav_profile_t, accel_noise_mps2_rthz) },
    { "accel_tau_s", offsetof(fnav_profile_t, accel_tau_s) },
    { "accel_bias_sigma_mps2", offsetof(fnav_profile_t, accel_bias_sigma_mps2) },
    { "gyro_noise_rps_rthz", offsetof(fnav_profile_t, gyro_noise_rps_rthz) },
    { "gyro_tau_s", offsetof(fnav_profile_t, gyro_tau_s) },
    { "gyro_bias_sigma_rps", offsetof(fnav_profile_t, gyro_bias_sigma_rps) },
};

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

int hx_profile_read(const char *path, fnav_profile_t *p, char *err, size_t err_size)
{
    FILE *f = fopen(path, "r");
    char line[513]; /* 511 characters (profile-format.md), a CR and the terminator */
    long len;
    int lineno = 0, have_magic = 0, have_rate = 0, have_name = 0, have[6] = { 0, 0, 0, 0, 0, 0 };
    int i;
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
            snprintf(p->name, sizeof p->name, "%s", val);
            have_name = 1;
        } else if (strcmp(key, "rate_hz") == 0) {
            char *end;
            double v = strtod(val, &end);
            if (end == val || *trim(end) != '\0' || !(v > 0.0 && v <= 1e6)) {
                snprintf(err, err_size, "%s:%d: rate_hz '%s' is not a rate in (0, 1e6]", path, lineno, val);
                fclose(f);
                return -1;
            }
            p->rate_hz = (fnav_real_t)v;
            if (!(p->rate_hz > FNAV_R(0.0))) {
                /* 1e-50 is 0 in float: said at its line, with its key (not
                 * "a value is zero ... in the float build", no line, no
                 * key) */
                snprintf(err, err_size, "%s:%d: rate_hz '%s' is 0 in the %s build (out of its range)", path, lineno,
                         val, FNAV_USE_DOUBLE ? "double" : "float");
                fclose(f);
                return -1;
            }
            have_rate = 1;
        } else {
            for (i = 0; i < 6; i++) {
                if (strcmp(key, k_keys[i].key) == 0) {
                    fnav_real_t *dst = (fnav_real_t *)((char *)p + k_keys[i].offset);
                    char *s = val, *end;
                    int k;
                    if (have[i]) {
                        snprintf(err, err_size, "%s:%d: %s given twice", path, lineno, key);
                        fclose(f);
                        return -1;
                    }
                    for (k = 0; k < 3; k++) {
                        double v = strtod(s, &end);
                        if (end == s || !isfinite(v) || !(v > 0.0)) {
                            snprintf(err, err_size, "%s:%d: %s needs three positive numbers (x y z)", path, lineno,
                                     key);
                            fclose(f);
                            return -1;
                        }
                        dst[k] = (fnav_real_t)v;
                        if (!isfinite(dst[k]) || !(dst[k] > FNAV_R(0.0))) {
                            /* positive in double, not in the working
                             * precision (1e39, 1e-50 in float): at its line */
                            const char *num = s + strspn(s, " \t");
                            snprintf(err, err_size, "%s:%d: %s value %d '%.*s' is %s in the %s build (out of its range)",
                                     path, lineno, key, k + 1, (int)(end - num), num,
                                     isfinite(dst[k]) ? "0" : "infinite", FNAV_USE_DOUBLE ? "double" : "float");
                            fclose(f);
                            return -1;
                        }
                        s = end;
                    }
                    if (*trim(s) != '\0') {
                        snprintf(err, err_size, "%s:%d: %s: unexpected text after three values", path, lineno, key);
                        fclose(f);
                        return -1;
                    }
                    have[i] = 1;
                    break;
                }
            }
            /* unknown keys are ignored on purpose */
        }
    }
    fclose(f);
    if (!have_magic) {
        snprintf(err, err_size, "%s: not a footnav profile (no 'format = %s' line)", path, PROFILE_MAGIC);
        return -1;
    }
    if (!have_rate) {
        snprintf(err, err_size, "%s: rate_hz missing", path);
        return -1;
    }
    for (i = 0; i < 6; i++) {
        if (!have[i]) {
            snprintf(err, err_size, "%s: %s missing", path, k_keys[i].key);
            return -1;
        }
    }
    if (p->name[0] == '\0') {
        snprintf(p->name, sizeof p->name, "file");
    }
    if (fnav_profile_validate(p) != FNAV_OK) {
        /* each value was positive in double; in the working precision one
         * may not be (1e-60 is 0 in float): said here, not later as a
         * rejected --param */
        snprintf(err, err_size, "%s: a value is zero, negative or not finite in the %s build (out of its range)",
                 path, FNAV_USE_DOUBLE ? "double" : "float");
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
    char msg[320];
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
    if (hx_profile_read(name_or_path, p, err, err_size) != 0) {
        return -1;
    }
    /* a file edited by hand in the wrong unit (a gyro noise in
     * deg/s/sqrt(Hz)) is valid but not plausible: replay on the bundled
     * walk ends 0.33 m from its start instead of 0.04 m with it. Valid, so
     * a warning; the run goes on. */
    if (hx_profile_implausible(p, msg, sizeof msg) && !profile_warned(name_or_path)) {
        /* once per file in a run: a command that loads its profiles once
         * per seed (montecarlo, the sensor's and the filter's) says each
         * once */
        hx_warn(hx_cmd_name, "%s: %s", name_or_path, msg);
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
