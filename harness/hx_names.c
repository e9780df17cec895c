/* Column names of an IMU CSV read without --columns (hx_names.h,
 * docs/log-format.md "Names read without --columns"). */
#include "hx_names.h"
#include "hx_log.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

#define NAME_MAX_TOK 8
#define NAME_TOK_LEN 32

static const char *const k_keys[7] = { "t", "ax", "ay", "az", "gx", "gy", "gz" };

/* the stems of an acceleration and a rate name (one word each) */
static const char *const k_acc_stems[] = { "acc", "accel", "accelerometer", "acceleration", NULL };
static const char *const k_gyr_stems[] = { "gyr", "gyro", "gyroscope", "w", "omega", "angvel", NULL };

static int in_list(const char *w, const char *const *list)
{
    for (; *list != NULL; list++) {
        if (strcmp(w, *list) == 0) {
            return 1;
        }
    }
    return 0;
}

static int axis_of(const char *w)
{
    return (w[0] >= 'x' && w[0] <= 'z' && w[1] == '\0') ? w[0] - 'x' : -1;
}

/* the unit of a unit word or bracket text (lower case, no blanks) when it
 * is one of the spellings read; NONE else */
static hx_name_unit_t unit_listed(const char *u)
{
    static const struct {
        const char *text;
        hx_name_unit_t unit;
    } k_units[] = {
        { "s", HX_UNIT_S },         { "sec", HX_UNIT_S },       { "ms", HX_UNIT_MS },      { "us", HX_UNIT_US },
        { "ns", HX_UNIT_NS },       { "g", HX_UNIT_G },         { "mg", HX_UNIT_MG },      { "ug", HX_UNIT_UG },      { "m/s^2", HX_UNIT_MPS2 },
        { "m/s2", HX_UNIT_MPS2 },   { "mps2", HX_UNIT_MPS2 },   { "ms2", HX_UNIT_MPS2 },   { "rad/s", HX_UNIT_RPS },
        { "rps", HX_UNIT_RPS },     { "rads", HX_UNIT_RPS },    { "radps", HX_UNIT_RPS },  { "deg/s", HX_UNIT_DPS },
        { "dps", HX_UNIT_DPS },     { "degs", HX_UNIT_DPS },    { "mdps", HX_UNIT_MDPS },  { "mdeg/s", HX_UNIT_MDPS },
        { "m/sec^2", HX_UNIT_MPS2 }, { "m/sec2", HX_UNIT_MPS2 }, { "rad/sec", HX_UNIT_RPS }, { "deg/sec", HX_UNIT_DPS },
    };
    size_t i;
    for (i = 0; i < sizeof k_units / sizeof k_units[0]; i++) {
        if (strcmp(u, k_units[i].text) == 0) {
            return k_units[i].unit;
        }
    }
    return HX_UNIT_NONE;
}

/* The unit of u: a spelling read, or one of them written as SI writes a
 * quotient, with a negative power of the second: "m s^-2", "rad s^-1"
 * (EuRoC's, TUM-VI's), "m.s-2", "deg*s^-1" (the blanks are gone here) are
 * m/s^2, rad/s, deg/s. */
static hx_name_unit_t unit_of(const char *u)
{
    const hx_name_unit_t listed = unit_listed(u);
    size_t e = strlen(u);
    char q[32];
    int power;
    if (listed != HX_UNIT_NONE || e < 4 || u[e - 2] != '-' || (u[e - 1] != '1' && u[e - 1] != '2')) {
        return listed;
    }
    power = u[e - 1] - '0';
    e -= 2;
    e -= u[e - 1] == '^';
    if (e == 0 || u[e - 1] != 's') {
        return HX_UNIT_NONE;
    }
    e--;
    e -= e > 0 && (u[e - 1] == '*' || u[e - 1] == '.');
    if (e == 0 || e + 5 >= sizeof q) {
        return HX_UNIT_NONE;
    }
    snprintf(q, sizeof q, "%.*s/s%s", (int)e, u, power == 2 ? "^2" : "");
    return unit_listed(q);
}

const char *hx_name_unit_item(hx_name_unit_t u)
{
    static const char *const items[] = { NULL,      "time=s", "time=ms", "time=us",    "time=ns",  "accel=m/s2",
                                         "accel=g", "accel=mg", "accel=ug", "gyro=rad/s", "gyro=deg/s", "gyro=mdps" };
    return ((int)u > 0 && (size_t)u < sizeof items / sizeof items[0]) ? items[u] : NULL;
}

/* a time zone written after a time column's name, folded to lower case
 * without blanks: utc, gmt, z, local, or an offset (+02:00, -0700, +2) */
static int is_zone(const char *u)
{
    size_t d;
    if (strcmp(u, "utc") == 0 || strcmp(u, "gmt") == 0 || strcmp(u, "z") == 0 || strcmp(u, "local") == 0) {
        return 1;
    }
    if ((u[0] == '+' || u[0] == '-') && (d = strspn(u + 1, "0123456789")) >= 1 && d <= 4) {
        const char *r = u + 1 + d;
        if (*r == ':' && d <= 2 && strspn(r + 1, "0123456789") == 2) {
            r += 3;
        }
        return *r == '\0';
    }
    return 0;
}

/* 0 time, 1 acceleration, 2 rate: the quantity a unit measures */
static int unit_quantity(hx_name_unit_t u)
{
    return u <= HX_UNIT_NS ? 0 : u <= HX_UNIT_UG ? 1 : 2;
}

/* a word that is a stem with its axis glued (accx, gyroz, wx, and the
 * interchange names ax, gx): the quantity (1 accel, 2 rate), axis in *ax */
static int glued(const char *w, int *ax)
{
    char stem[NAME_TOK_LEN];
    size_t n = strlen(w);
    if (n < 2 || n >= sizeof stem || w[n - 1] < 'x' || w[n - 1] > 'z') {
        return 0;
    }
    memcpy(stem, w, n - 1);
    stem[n - 1] = '\0';
    *ax = w[n - 1] - 'x';
    if (strcmp(stem, "a") == 0 || in_list(stem, k_acc_stems)) {
        return 1;
    }
    if (strcmp(stem, "g") == 0 || in_list(stem, k_gyr_stems)) {
        return 2;
    }
    return 0;
}

static int is_sep(char c)
{
    return c == ' ' || c == '\t' || c == '_' || c == '-' || c == '.' || c == ':';
}

/* The number of bytes of the valid UTF-8 sequence at s (up to end), 0 when
 * none starts there (a byte alone, as Latin-1 writes a character). */
static size_t utf8_len(const unsigned char *s, const unsigned char *end)
{
    size_t n, i;
    if (s[0] < 0x80) {
        return 1;
    }
    n = (s[0] & 0xE0) == 0xC0 ? 2 : (s[0] & 0xF0) == 0xE0 ? 3 : (s[0] & 0xF8) == 0xF0 ? 4 : 0;
    if (n == 0 || s[0] == 0xC0 || s[0] == 0xC1 || (size_t)(end - s) < n) {
        return 0;
    }
    for (i = 1; i < n; i++) {
        if ((s[i] & 0xC0) != 0x80) {
            return 0;
        }
    }
    return n;
}

/* text[0, len) into out (NUL-terminated) with the units' signs spelled in
 * ASCII: the degree sign U+00B0 (and U+00BA, the ordinal indicator that
 * keyboards give for it) "deg", the micro sign U+00B5 and the Greek mu
 * U+03BC "u", superscript two U+00B2 "2"; in UTF-8, or as the one byte
 * Latin-1 (Windows-1252) writes them, where it is no UTF-8 sequence's.
 * Any other character is kept. -1 when out is too small. */
static int fold_units(const char *text, size_t len, char *out, size_t size)
{
    const unsigned char *p = (const unsigned char *)text, *end = p + len;
    size_t k = 0;
    while (p < end) {
        const size_t n = utf8_len(p, end);
        unsigned int cp = 0x100; /* none of the signs */
        const char *rep = NULL;
        size_t i, take = n == 0 ? 1 : n;
        if (n == 0) {
            cp = p[0]; /* a Latin-1 byte */
        } else if (n == 2) {
            cp = ((unsigned int)(p[0] & 0x1F) << 6) | (unsigned int)(p[1] & 0x3F);
        }
        rep = cp == 0xB0 || cp == 0xBA ? "deg" : cp == 0xB5 || cp == 0x3BC ? "u" : cp == 0xB2 ? "2" : NULL;
        if (rep == NULL) {
            for (i = 0; i < take; i++) {
                if (k + 1 >= size) {
                    return -1;
                }
                out[k++] = (char)p[i];
            }
        } else {
            for (i = 0; rep[i] != '\0'; i++) {
                if (k + 1 >= size) {
                    return -1;
                }
                out[k++] = rep[i];
            }
        }
        p += take;
    }
    out[k] = '\0';
    return 0;
}

int hx_name_fold_units(const char *text, char *out, size_t size)
{
    return fold_units(text, strlen(text), out, size);
}

/* a last word that is a unit, but none read (ng: a log in nano-g, deg/h):
 * the name is then no other word's near miss, but one for its unit */
static int unit_like(const char *w)
{
    static const char *const k_other[] = { "ng", "lsb", "counts", "rpm", "dph", NULL };
    return strpbrk(w, "/^") != NULL || in_list(w, k_other);
}

/* the words of text[0, len): lower case, split at separators and at a
 * lower-to-upper case change; -1 when there are too many or too long */
static int split_words(const char *text, size_t len, char w[NAME_MAX_TOK][NAME_TOK_LEN])
{
    int n = 0;
    size_t i, k = 0;
    for (i = 0; i <= len; i++) {
        const char c = i < len ? text[i] : ' ';
        const int brk = i > 0 && i < len && islower((unsigned char)text[i - 1]) && isupper((unsigned char)c);
        if ((is_sep(c) || brk) && k > 0) {
            w[n][k] = '\0';
            n++;
            k = 0;
        }
        if (is_sep(c)) {
            continue;
        }
        if (n >= NAME_MAX_TOK || k + 1 >= NAME_TOK_LEN) {
            return -1;
        }
        w[n][k++] = (char)tolower((unsigned char)c);
    }
    return n;
}

/* the unit of a name as its header spells it: the bracket's text between
 * its blanks, or the last word's (after the last separator) */
static void unit_text_of(const char *s, size_t len, char *out, size_t size)
{
    const char *open = NULL, *b, *e = s + len;
    size_t i;
    for (i = 0; i < len && open == NULL; i++) {
        open = s[i] == '(' || s[i] == '[' ? s + i : NULL;
    }
    if (open != NULL) {
        b = open + 1;
        e = (const char *)memchr(b, *open == '(' ? ')' : ']', (size_t)(s + len - b));
        e = e != NULL ? e : s + len;
    } else {
        for (b = e; b > s && !is_sep(b[-1]); b--) {
        }
    }
    while (b < e && (*b == ' ' || *b == '\t')) {
        b++;
    }
    while (e > b && (e[-1] == ' ' || e[-1] == '\t')) {
        e--;
    }
    snprintf(out, size, "%.*s", (int)(e - b), b);
}

hx_name_kind_t hx_name_classify(const char *name, hx_name_class_t *c)
{
    char buf[128], w[NAME_MAX_TOK][NAME_TOK_LEN];
    const char *s = name, *open;
    size_t len, len0;
    int n, i, q = -1, ax = -1, key = -1, time_word = 0, unread = 0, zone = 0;
    hx_name_unit_t unit = HX_UNIT_NONE;
    c->kind = HX_NAME_OTHER;
    c->key = -1;
    c->unit = HX_UNIT_NONE;
    c->unit_unread = 0;
    c->clock = 0;
    c->gforce = 0;
    c->unit_text[0] = '\0';
    while (*s == ' ' || *s == '\t' || *s == '"' || *s == '\'') {
        s++;
    }
    len = strlen(s);
    while (len > 0 && (s[len - 1] == ' ' || s[len - 1] == '\t' || s[len - 1] == '"' || s[len - 1] == '\'' ||
                       s[len - 1] == '\r' || s[len - 1] == '\n')) {
        len--;
    }
    len0 = len;
    /* the units' signs in ASCII: "gx [°/s]" is "gx [deg/s]" (left as they
     * are, they would make the name no match) */
    if (len == 0 || len >= sizeof buf || fold_units(s, len, buf, sizeof buf) != 0) {
        return c->kind;
    }
    len = strlen(buf);
    open = strpbrk(buf, "([");
    if (open != NULL) {
        /* "Gyro Z (deg/s)", "AccX [g]": the unit in brackets, nothing after */
        const char *close = strchr(open, *open == '(' ? ')' : ']');
        char u[32];
        size_t k = 0;
        const char *p;
        if (close == NULL || close[1 + strspn(close + 1, " \t")] != '\0') {
            return c->kind;
        }
        for (p = open + 1; p < close; p++) {
            if (*p != ' ' && *p != '\t') {
                if (k + 1 >= sizeof u) {
                    break; /* longer than any unit read */
                }
                u[k++] = (char)tolower((unsigned char)*p);
            }
        }
        u[k] = '\0';
        unit = p == close ? unit_of(u) : HX_UNIT_NONE;
        /* "(raw)", "[counts]", "[deg/h]": no unit we read (a key's name so
         * is a near miss that says so, rather than no name at all); a zone,
         * "Time (UTC)", MetaWear's "time (-07:00)", is none of a unit */
        zone = unit == HX_UNIT_NONE && p == close && is_zone(u);
        unread = unit == HX_UNIT_NONE && !zone;
        len = (size_t)(open - buf);
    }
    n = split_words(buf, len, w);
    if (n <= 0) {
        return c->kind;
    }
    if (open == NULL && n >= 2 && unit_of(w[n - 1]) != HX_UNIT_NONE) {
        /* the last word a unit: time_s, accX_mps2, gyro_x_dps; "in" before
         * it is the unit's too (AndroSensor's "Time since start in ms") */
        unit = unit_of(w[n - 1]);
        n--;
        if (n >= 2 && strcmp(w[n - 1], "in") == 0) {
            n--;
        }
    } else if (open == NULL && n >= 2 && unit_like(w[n - 1])) {
        unread = 1; /* ax_ug, gyro_z_deg/h */
        n--;
    }
    /* what the words are */
    if (n == 1 && (strcmp(w[0], "t") == 0 || strcmp(w[0], "time") == 0 || strcmp(w[0], "timestamp") == 0 ||
                   strcmp(w[0], "ts") == 0 || strcmp(w[0], "datetime") == 0)) {
        key = 0;
    } else if (n == 2 && ((strcmp(w[0], "time") == 0 && strcmp(w[1], "stamp") == 0) ||
                          (strcmp(w[0], "date") == 0 && strcmp(w[1], "time") == 0) ||
                          (strcmp(w[0], "elapsed") == 0 && strcmp(w[1], "time") == 0))) {
        key = 0; /* "Time Stamp"; "DateTime", "Date Time", date_time: dates and times (docs/log-format.md) */
        c->clock = strcmp(w[0], "elapsed") == 0 ? -1 : 0;
    } else if (n == 1 && strcmp(w[0], "elapsed") == 0) {
        key = 0;
        c->clock = -1; /* from a start: MetaWear's "elapsed (s)" from each file's first sample */
    } else if (n == 2 && strcmp(w[0], "sensor") == 0 &&
               (strcmp(w[1], "timestamp") == 0 || strcmp(w[1], "time") == 0 || strcmp(w[1], "ts") == 0)) {
        /* the sensor's own clock: Polar Sensor Logger's "sensor timestamp
         * [ns]" (ns since 2000-01-01, the device's, which its ACC and GYRO
         * files share), beside its "Phone timestamp" (the phone's, per
         * packet: not a time name, named as not read) */
        key = 0;
    } else if (n == 3 && strcmp(w[0], "time") == 0 && strcmp(w[1], "since") == 0 && strcmp(w[2], "start") == 0) {
        key = 0; /* AndroSensor's "Time since start in ms" */
        c->clock = -1;
    } else if ((n == 1 || (n == 2 && (strcmp(w[1], "time") == 0 || strcmp(w[1], "timestamp") == 0 ||
                                      strcmp(w[1], "ts") == 0))) &&
               (strcmp(w[0], "epoch") == 0 || strcmp(w[0], "epoc") == 0 || strcmp(w[0], "unix") == 0)) {
        /* a clock's: "epoch (ms)", MetaWear's "epoc (ms)", unix_time, the
         * time since 1970 that two files of one logger share */
        key = 0;
        c->clock = 1;
    } else if (n == 1 && (strcmp(w[0], "millis") == 0 || strcmp(w[0], "micros") == 0)) {
        /* Arduino's clocks, named by their unit: millis() ms, micros() us */
        key = 0;
        if (unit == HX_UNIT_NONE && !unread) {
            unit = w[0][1] == 'i' && w[0][2] == 'l' ? HX_UNIT_MS : HX_UNIT_US;
        }
    } else if ((n == 2 && strcmp(w[0], "g") == 0 && w[1][0] == 'f' && axis_of(w[1] + 1) >= 0) ||
               (n == 1 && w[0][0] == 'g' && w[0][1] == 'f' && axis_of(w[0] + 2) >= 0)) {
        /* Physics Toolbox Sensor Suite's g-force, gFx: the accelerometer's
         * reading over g, the specific force in g (1 up when the phone lies
         * flat); its ax..az beside it are the linear acceleration */
        key = 1 + (n == 2 ? axis_of(w[1] + 1) : axis_of(w[0] + 2));
        c->gforce = 1;
        if (unit == HX_UNIT_NONE && !unread) {
            unit = HX_UNIT_G;
        }
    } else if (n == 1 && (q = glued(w[0], &ax)) != 0) {
        key = 1 + 3 * (q - 1) + ax;
    } else if (n == 2 && axis_of(w[1]) >= 0 && (in_list(w[0], k_acc_stems) || in_list(w[0], k_gyr_stems))) {
        key = (in_list(w[0], k_acc_stems) ? 1 : 4) + axis_of(w[1]);
    } else if (n == 3 && axis_of(w[2]) >= 0 &&
               ((strcmp(w[0], "angular") == 0 && (strcmp(w[1], "velocity") == 0 || strcmp(w[1], "rate") == 0)) ||
                (strcmp(w[0], "rotation") == 0 && strcmp(w[1], "rate") == 0))) {
        key = 4 + axis_of(w[2]);
    } else if (n == 4 && axis_of(w[3]) >= 0 && strcmp(w[1], "rs") == 0 && strcmp(w[2], "s") == 0 &&
               (strcmp(w[0], "w") == 0 || strcmp(w[0], "a") == 0)) {
        /* the ASL format of EuRoC and TUM-VI: w_RS_S_x, a_RS_S_x, the rate
         * and specific force of the sensor S against the frame R, in S */
        key = (w[0][0] == 'a' ? 1 : 4) + axis_of(w[3]);
    }
    if (key > 0 && zone) {
        unread = 1; /* "ax (UTC)": a zone is a time's */
    }
    if (key >= 0) {
        const int want = key == 0 ? 0 : key <= 3 ? 1 : 2;
        c->key = key;
        c->unit = unit;
        c->unit_unread = unread;
        c->kind = !unread && (unit == HX_UNIT_NONE || unit_quantity(unit) == want) ? HX_NAME_MATCH : HX_NAME_NEAR;
        if (unit != HX_UNIT_NONE || unread) {
            unit_text_of(s, len0, c->unit_text, sizeof c->unit_text);
        }
        return c->kind;
    }
    /* a near miss: a stem and an axis, or a time word, among other words
     * (FreeAcc_X, acc_x_lin, SampleTimeFine) */
    for (i = 0; i < n; i++) {
        int a;
        if ((q = glued(w[i], &a)) != 0) {
            c->key = 1 + 3 * (q - 1) + a;
            break;
        }
        if (in_list(w[i], k_acc_stems) || in_list(w[i], k_gyr_stems)) {
            int j;
            for (j = i + 1; j < n && axis_of(w[j]) < 0; j++) {
            }
            if (j < n) {
                c->key = (in_list(w[i], k_acc_stems) ? 1 : 4) + axis_of(w[j]);
                break;
            }
        }
        time_word |= strcmp(w[i], "time") == 0 || strcmp(w[i], "timestamp") == 0;
    }
    if (c->key < 0 && time_word) {
        c->key = 0;
    }
    if (c->key >= 0) {
        c->kind = HX_NAME_NEAR;
        c->unit = unit;
        c->unit_unread = unread;
        if (unit != HX_UNIT_NONE || unread) {
            unit_text_of(s, len0, c->unit_text, sizeof c->unit_text);
        }
    }
    return c->kind;
}

static void add_col(int *count, int list[3], int col)
{
    if (*count < 3) {
        list[*count] = col;
    }
    (*count)++;
}

/* Shimmer's Consensys columns (its CSV export: "sep=," line, a header of
 * <device>_<signal>_CAL names, a row of units): the suffix of each name
 * read, its key and its rank. The highest rank of a key is read, the
 * others are near misses (named as not read): the Unix time before the
 * synchronised one, the wide-range accelerometer (up to +-16 g) before the
 * low-noise one (+-2 g, which a foot's impacts clip). */
typedef struct {
    const char *text; /* the name (k_ros) or the end of it (k_consensys), lower case */
    int key, rank;    /* rank 0: never read, only named as not read */
    hx_name_unit_t unit;
} name_row_t;

static const name_row_t k_consensys[] = {
    { "_timestamp_unix_cal", 0, 2, HX_UNIT_NONE }, { "_timestampsync_unix_cal", 0, 1, HX_UNIT_NONE },
    { "_accel_wr_x_cal", 1, 2, HX_UNIT_NONE },     { "_accel_wr_y_cal", 2, 2, HX_UNIT_NONE },
    { "_accel_wr_z_cal", 3, 2, HX_UNIT_NONE },     { "_accel_ln_x_cal", 1, 1, HX_UNIT_NONE },
    { "_accel_ln_y_cal", 2, 1, HX_UNIT_NONE },     { "_accel_ln_z_cal", 3, 1, HX_UNIT_NONE },
    { "_gyro_x_cal", 4, 1, HX_UNIT_NONE },         { "_gyro_y_cal", 5, 1, HX_UNIT_NONE },
    { "_gyro_z_cal", 6, 1, HX_UNIT_NONE },
};

/* name without the blanks, quotes and CR around it, in lower case, into
 * bare (cut to size); its length */
static size_t lower_bare(const char *name, char *bare, size_t size)
{
    size_t i;
    hx_name_bare(name, bare, size);
    for (i = 0; bare[i] != '\0'; i++) {
        bare[i] = (char)tolower((unsigned char)bare[i]);
    }
    return i;
}

/* the row of tab[0..n) whose text is b; -1 none */
static int row_exact(const char *b, const name_row_t *tab, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++) {
        if (strcmp(b, tab[k].text) == 0) {
            return (int)k;
        }
    }
    return -1;
}

/* the k_consensys row a name ends with (case, quotes and blanks around
 * ignored); -1 none */
static int consensys_row(const char *name)
{
    char bare[128];
    const size_t len = lower_bare(name, bare, sizeof bare);
    size_t k;
    for (k = 0; k < sizeof k_consensys / sizeof k_consensys[0]; k++) {
        const size_t sl = strlen(k_consensys[k].text);
        if (len > sl && strcmp(bare + len - sl, k_consensys[k].text) == 0) {
            return (int)k;
        }
    }
    return -1;
}

int hx_names_consensys(char *const *f, int n)
{
    int i, time = 0;
    for (i = 0; i < n; i++) {
        const int k = consensys_row(f[i]);
        time |= k >= 0 && k_consensys[k].key == 0;
    }
    return time;
}

/* A family's columns (the rows of tab that row_of finds) into m's
 * candidates and near misses by rank: the highest rank of a key is read,
 * a lower one or rank 0 named as not read; the time read's unit into
 * m->unit[0]. */
static void rank_match(char *const *f, int n, const name_row_t *tab, int (*row_of)(const char *),
                       hx_names_match_t *m)
{
    int best[7] = { 0, 0, 0, 0, 0, 0, 0 }, i;
    for (i = 0; i < n; i++) {
        const int k = row_of(f[i]);
        if (k >= 0 && tab[k].rank > best[tab[k].key]) {
            best[tab[k].key] = tab[k].rank;
        }
    }
    for (i = 0; i < n; i++) {
        const int k = row_of(f[i]);
        if (k >= 0) {
            const int key = tab[k].key;
            if (tab[k].rank > 0 && tab[k].rank == best[key]) {
                add_col(&m->ncand[key], m->cand[key], i);
                m->unit[0] = key == 0 ? tab[k].unit : m->unit[0];
            } else {
                add_col(&m->nnear[key], m->near[key], i);
            }
        }
    }
}

/* ROS sensor_msgs/Imu messages written as CSV: by `rostopic echo -p`
 * (each name after "field.", the stamps in ns: %time the bag's receive
 * time, field.header.stamp the driver's) or by bagpy (no prefix; Time the
 * receive time in s, the header stamp split in secs and nsecs; ROS 2's
 * tools: sec and nanosec). The names after an optional "field.", in lower
 * case; the highest rank of a key is read; the split stamp's rows, rank 0,
 * are read as a pair by ros_split_stamp, before the receive time.
 * REP 103 fixes the units (m/s^2, rad/s); REP 145 has a driver publish
 * what the device reports, gravity not removed: linear_acceleration is
 * the specific force an IMU measures. */
static const name_row_t k_ros[] = {
    { "header.stamp", 0, 3, HX_UNIT_NS },          { "%time", 0, 2, HX_UNIT_NS },
    { "time", 0, 1, HX_UNIT_S },                   { "header.stamp.secs", 0, 0, HX_UNIT_NONE },
    { "header.stamp.nsecs", 0, 0, HX_UNIT_NONE },  { "header.stamp.sec", 0, 0, HX_UNIT_NONE },
    { "header.stamp.nanosec", 0, 0, HX_UNIT_NONE }, { "linear_acceleration.x", 1, 1, HX_UNIT_NONE },
    { "linear_acceleration.y", 2, 1, HX_UNIT_NONE }, { "linear_acceleration.z", 3, 1, HX_UNIT_NONE },
    { "angular_velocity.x", 4, 1, HX_UNIT_NONE },  { "angular_velocity.y", 5, 1, HX_UNIT_NONE },
    { "angular_velocity.z", 6, 1, HX_UNIT_NONE },
};

/* the k_ros row of a name (an optional "field." before it; case, quotes
 * and blanks around ignored); -1 none */
static int ros_row(const char *name)
{
    char bare[128];
    (void)lower_bare(name, bare, sizeof bare);
    return row_exact(bare + (strncmp(bare, "field.", 6) == 0 ? 6 : 0), k_ros, sizeof k_ros / sizeof k_ros[0]);
}

/* A stamp split in whole seconds and nanoseconds (bagpy's
 * header.stamp.secs and .nsecs, ROS 2's .sec and .nanosec), both there,
 * read as the time when no field.header.stamp is: the seconds as t (in s),
 * the nanoseconds as m->col_tns; the receive time and any other time name
 * become near misses. */
static void ros_split_stamp(char *const *f, int n, hx_names_match_t *m)
{
    static const char *const pairs[2][2] = { { "header.stamp.secs", "header.stamp.nsecs" },
                                             { "header.stamp.sec", "header.stamp.nanosec" } };
    int p, i;
    for (i = 0; i < m->ncand[0] && i < 3; i++) {
        const int k = ros_row(f[m->cand[0][i]]);
        if (k >= 0 && strcmp(k_ros[k].text, "header.stamp") == 0) {
            return; /* the message's stamp in one column */
        }
    }
    for (p = 0; p < 2; p++) {
        int secs = -1, nsecs = -1;
        for (i = 0; i < n; i++) {
            const int k = ros_row(f[i]);
            if (k >= 0 && secs < 0 && strcmp(k_ros[k].text, pairs[p][0]) == 0) {
                secs = i;
            } else if (k >= 0 && nsecs < 0 && strcmp(k_ros[k].text, pairs[p][1]) == 0) {
                nsecs = i;
            }
        }
        if (secs < 0 || nsecs < 0) {
            continue;
        }
        m->ncand[0] = 0;
        m->nnear[0] = 0;
        add_col(&m->ncand[0], m->cand[0], secs);
        for (i = 0; i < n; i++) {
            const int k = ros_row(f[i]);
            if (k >= 0 && k_ros[k].key == 0 && i != secs && i != nsecs) {
                add_col(&m->nnear[0], m->near[0], i);
            }
        }
        m->col_tns = nsecs;
        m->unit[0] = HX_UNIT_S;
        return;
    }
}

int hx_names_ros_receive(char *const *f, int n, hx_name_unit_t *unit)
{
    int i, col = -1, rank = 0;
    for (i = 0; i < n; i++) {
        const int k = ros_row(f[i]);
        /* the receive times: the time rows below the message's stamp (rank
         * 3) and above the split stamp's halves (rank 0) */
        if (k >= 0 && k_ros[k].key == 0 && k_ros[k].rank > rank && k_ros[k].rank < 3) {
            col = i;
            rank = k_ros[k].rank;
            *unit = k_ros[k].unit;
        }
    }
    return col;
}

int hx_names_ros(char *const *f, int n)
{
    int i, acc = 0, gyr = 0;
    for (i = 0; i < n; i++) {
        const int k = ros_row(f[i]);
        acc |= k >= 0 && k_ros[k].key >= 1 && k_ros[k].key <= 3;
        gyr |= k >= 0 && k_ros[k].key >= 4;
    }
    return acc && gyr;
}

/* Kalibr's IMU CSV (the bag format kalibr_bagcreater reads, imu0.csv):
 * the stamp in ns, omega in rad/s, alpha the specific force in m/s^2; a
 * leading '#' of the header's first name is not part of it. */
static const name_row_t k_kalibr[] = {
    { "timestamp", 0, 1, HX_UNIT_NS }, { "timestamp_ns", 0, 1, HX_UNIT_NS }, { "alpha_x", 1, 1, HX_UNIT_NONE },
    { "alpha_y", 2, 1, HX_UNIT_NONE }, { "alpha_z", 3, 1, HX_UNIT_NONE },    { "omega_x", 4, 1, HX_UNIT_NONE },
    { "omega_y", 5, 1, HX_UNIT_NONE }, { "omega_z", 6, 1, HX_UNIT_NONE },
};

/* the k_kalibr row of a name (case, quotes, blanks and a leading '#'
 * ignored); -1 none */
static int kalibr_row(const char *name)
{
    char bare[64];
    (void)lower_bare(name, bare, sizeof bare);
    return row_exact(bare + (bare[0] == '#'), k_kalibr, sizeof k_kalibr / sizeof k_kalibr[0]);
}

int hx_names_kalibr(char *const *f, int n)
{
    int i, seen = 0;
    for (i = 0; i < n; i++) {
        const int k = kalibr_row(f[i]);
        if (k >= 0 && k_kalibr[k].key > 0) {
            seen |= 1 << k_kalibr[k].key;
        }
    }
    return seen == 0x7e; /* ax..gz: alpha_x..z and omega_x..z all named */
}

/* SensorLog (iOS, B. Thomas): one row per logging sample of CoreMotion's
 * readings, each sensor with its own stamp in s since the phone's boot.
 * accelerometerAcceleration is CMAccelerometerData's, in g with iOS's
 * sign: the acceleration, the specific force's negative (z -1 g face up,
 * Apple's CMAcceleration docs), so it is read with the other sign on all
 * three axes (m->negate); gyroRotation is CMGyroData's raw rate in rad/s,
 * right-handed as the specific force's axes, before motionRotationRate
 * (CoreMotion's fused, bias-corrected rate). The accelerometer's stamp
 * is the row's time (the gyroscope's, then CoreMotion's, without it).
 * CoreMotion's user acceleration and gravity (gravity apart), the logging
 * time (a local date with " +0100") and the other sensors' stamps are
 * named as not read. The names without their unit in parentheses, lower
 * case; a unit in the parentheses that is read (hx_name_unit_of_text) and
 * its quantity's is the one read, else the row's. */
static const name_row_t k_sensorlog[] = {
    { "accelerometertimestamp_sincereboot", 0, 3, HX_UNIT_S },
    { "gyrotimestamp_sincereboot", 0, 2, HX_UNIT_S },
    { "motiontimestamp_sincereboot", 0, 1, HX_UNIT_S },
    { "loggingtime", 0, 0, HX_UNIT_NONE },
    { "accelerometeraccelerationx", 1, 1, HX_UNIT_G },
    { "accelerometeraccelerationy", 2, 1, HX_UNIT_G },
    { "accelerometeraccelerationz", 3, 1, HX_UNIT_G },
    { "motionuseraccelerationx", 1, 0, HX_UNIT_G },
    { "motionuseraccelerationy", 2, 0, HX_UNIT_G },
    { "motionuseraccelerationz", 3, 0, HX_UNIT_G },
    { "motiongravityx", 1, 0, HX_UNIT_G },
    { "motiongravityy", 2, 0, HX_UNIT_G },
    { "motiongravityz", 3, 0, HX_UNIT_G },
    { "gyrorotationx", 4, 2, HX_UNIT_RPS },
    { "gyrorotationy", 5, 2, HX_UNIT_RPS },
    { "gyrorotationz", 6, 2, HX_UNIT_RPS },
    { "motionrotationratex", 4, 1, HX_UNIT_RPS },
    { "motionrotationratey", 5, 1, HX_UNIT_RPS },
    { "motionrotationratez", 6, 1, HX_UNIT_RPS },
};

/* the k_sensorlog row of a name (case, quotes and blanks ignored; a unit
 * in parentheses at its end, "(G)", "(rad/s)", "(s)", "(txt)", dropped);
 * -1 none */
static int sensorlog_row(const char *name)
{
    char bare[64];
    size_t len = lower_bare(name, bare, sizeof bare);
    char *open = strchr(bare, '(');
    if (open != NULL && len > 0 && bare[len - 1] == ')') {
        *open = '\0';
        len = (size_t)(open - bare);
        while (len > 0 && (bare[len - 1] == ' ' || bare[len - 1] == '\t')) {
            bare[--len] = '\0'; /* "accelerometerAccelerationX (G)" */
        }
    }
    return row_exact(bare, k_sensorlog, sizeof k_sensorlog / sizeof k_sensorlog[0]);
}

/* The unit of key's column (the first candidate; 1 ax, 4 gx) as its
 * parentheses name it, when read and of the key's quantity; else def. */
static hx_name_unit_t sensorlog_unit(char *const *f, const hx_names_match_t *m, int key, hx_name_unit_t def)
{
    const char *open = m->ncand[key] > 0 ? strchr(f[m->cand[key][0]], '(') : NULL;
    char text[32];
    const char *close;
    hx_name_unit_t u;
    if (open == NULL || (close = strchr(open, ')')) == NULL || (size_t)(close - open - 1) >= sizeof text) {
        return def;
    }
    snprintf(text, sizeof text, "%.*s", (int)(close - open - 1), open + 1);
    u = hx_name_unit_of_text(text);
    return u != HX_UNIT_NONE && unit_quantity(u) == (key <= 3 ? 1 : 2) ? u : def;
}

int hx_names_sensorlog(char *const *f, int n)
{
    int i, seen = 0;
    for (i = 0; i < n; i++) {
        const int k = sensorlog_row(f[i]);
        if (k >= 0 && k_sensorlog[k].rank > 0 && k_sensorlog[k].key > 0) {
            seen |= 1 << k_sensorlog[k].key;
        }
    }
    return seen == 0x7e; /* accelerometerAcceleration x..z and a rate's x..z */
}

hx_name_unit_t hx_name_unit_of_text(const char *text)
{
    char folded[64], u[32];
    size_t k = 0, i;
    if (hx_name_fold_units(text, folded, sizeof folded) != 0) {
        return HX_UNIT_NONE;
    }
    for (i = 0; folded[i] != '\0'; i++) {
        const char ch = folded[i];
        if (ch == ' ' || ch == '\t' || ch == '"' || ch == '\'' || ch == '(' || ch == ')' || ch == '[' || ch == ']' ||
            ch == '\r' || ch == '\n') {
            continue;
        }
        if (k + 1 >= sizeof u) {
            return HX_UNIT_NONE;
        }
        u[k++] = (char)tolower((unsigned char)ch);
    }
    u[k] = '\0';
    if (strcmp(u, "msecs") == 0 || strcmp(u, "msec") == 0) {
        return HX_UNIT_MS;
    }
    return unit_of(u);
}

int hx_names_match(char *const *f, int n, hx_names_match_t *m)
{
    int i, k, nclock = 0, clocks = 0, clock[3], ngf[4] = { 0, 0, 0, 0 }, gf[4][3] = { { 0 } };
    memset(m, 0, sizeof *m);
    m->unit_col = -1;
    m->col_tns = -1;
    for (k = 0; k < 7; k++) {
        m->col[k] = -1;
    }
    for (i = 0; i < n; i++) {
        /* Xsens's exports: Gyr_X is deg/s in a Movella DOT CSV and rad/s
         * in MT Manager's, which has its own importer */
        if (hx_name_eq(f[i], "SampleTimeFine") || hx_name_eq(f[i], "PacketCounter")) {
            m->excluded = 1;
            return 0;
        }
    }
    if (hx_names_consensys(f, n)) {
        m->consensys = 1;
        rank_match(f, n, k_consensys, consensys_row, m);
    } else if (hx_names_ros(f, n)) {
        m->ros = 1;
        rank_match(f, n, k_ros, ros_row, m);
        ros_split_stamp(f, n, m);
    } else if (hx_names_kalibr(f, n)) {
        m->kalibr = 1;
        rank_match(f, n, k_kalibr, kalibr_row, m);
    } else if (hx_names_sensorlog(f, n)) {
        m->sensorlog = 1;
        rank_match(f, n, k_sensorlog, sensorlog_row, m);
        m->unit[1] = sensorlog_unit(f, m, 1, HX_UNIT_G);
        m->unit[2] = sensorlog_unit(f, m, 4, HX_UNIT_RPS);
        m->negate = 0x0e; /* ax..az: iOS's acceleration is the specific force's negative */
    }
    for (i = 0; i < n && !m->consensys && !m->ros && !m->kalibr && !m->sensorlog; i++) {
        hx_name_class_t c;
        const hx_name_kind_t kind = hx_name_classify(f[i], &c);
        if (kind == HX_NAME_MATCH && c.key == 0 && c.clock == 1) {
            add_col(&nclock, clock, i);
        } else if (kind == HX_NAME_MATCH && c.gforce) {
            add_col(&ngf[c.key], gf[c.key], i);
        } else if (kind == HX_NAME_MATCH) {
            add_col(&m->ncand[c.key], m->cand[c.key], i);
        } else if (kind == HX_NAME_NEAR) {
            add_col(&m->nnear[c.key], m->near[c.key], i);
        }
    }
    if (m->ncand[0] == 0) {
        /* a clock's name ("epoch (ms)") is the time where no other time
         * name is: beside "elapsed (s)" or "time" the header read as before */
        for (k = 0; k < nclock && k < 3; k++) {
            add_col(&m->ncand[0], m->cand[0], clock[k]);
        }
        m->ncand[0] = nclock;
        clocks = nclock > 0;
    }
    if (m->ncand[0] > 1 && !m->consensys && !m->ros && !m->kalibr && !m->sensorlog) {
        /* several time names ("Timestamp (ms)" and AndroSensor's "Time
         * since start in ms"): each is a clock of the samples, and one
         * is as good as another for their intervals, so the first that
         * names its unit is read rather than the header refused; the
         * others are named in the warning as not read. Where none names
         * its unit ("time,timestamp": s, ms or ns, a date and time?), the
         * header is refused with the candidates, as before
         * (docs/log-format.md, "Names read without --columns"). The
         * candidates are the clocks' names only where no other is. */
        int best = -1, pass;
        for (pass = 0; pass < 2; pass++) {
            for (i = 0; i < n; i++) {
                hx_name_class_t c;
                if (hx_name_classify(f[i], &c) != HX_NAME_MATCH || c.key != 0 || (c.clock == 1) != clocks) {
                    continue;
                }
                if (pass == 0 && best < 0 && c.unit != HX_UNIT_NONE) {
                    best = i;
                } else if (pass == 1 && i != best) {
                    add_col(&m->nnear[0], m->near[0], i);
                }
            }
            if (best < 0) {
                break;
            }
        }
        if (best >= 0) {
            /* a clock's name beside them ("epoch (ms)"): a time name not
             * read too, counted and named */
            m->times = m->ncand[0] + (clocks ? 0 : nclock);
            m->times_clock = !clocks && nclock > 0;
            for (k = 0; !clocks && k < nclock && k < 3; k++) {
                add_col(&m->nnear[0], m->near[0], clock[k]);
            }
            m->cand[0][0] = best;
            m->ncand[0] = 1;
        }
    }
    if (ngf[1] + ngf[2] + ngf[3] > 0) {
        /* Physics Toolbox's g-force is the specific force; the app's
         * ax..az beside it its linear acceleration (gravity removed): not
         * read, and named with the near misses in the warning (for the
         * whole file, as merge's find_cols) */
        m->gforce = 1;
        for (k = 1; k <= 3; k++) {
            int j;
            for (j = 0; j < m->ncand[k] && j < 3; j++) {
                add_col(&m->nnear[k], m->near[k], m->cand[k][j]);
            }
            memcpy(m->cand[k], gf[k], sizeof gf[k]);
            m->ncand[k] = ngf[k];
        }
    }
    for (i = 0; i < n && m->unit_col < 0 && !m->consensys && !m->ros && !m->kalibr && !m->sensorlog; i++) {
        /* a key without a candidate that one name has but for its unit:
         * the refusal names the unit (hx_names_unit_problem) */
        hx_name_class_t c;
        if (hx_name_classify(f[i], &c) == HX_NAME_NEAR && m->ncand[c.key] == 0 &&
            (c.unit_unread ||
             (c.unit != HX_UNIT_NONE && unit_quantity(c.unit) != (c.key == 0 ? 0 : c.key <= 3 ? 1 : 2)))) {
            m->unit_col = i;
        }
    }
    m->ok = m->ncand[0] <= 1;
    for (k = 0; k < 7; k++) {
        if (m->ncand[k] == 1) {
            m->col[k] = m->cand[k][0];
        } else if (k > 0) {
            m->ok = 0;
        }
    }
    if (m->consensys || m->ros || m->kalibr || m->sensorlog) {
        /* Consensys: the units are the row's under the header (hx_log.c);
         * ROS and Kalibr: SI, the time's set by rank_match; SensorLog: g
         * and rad/s, set above */
        return m->ok;
    }
    if (m->col[0] >= 0) {
        hx_name_class_t c;
        (void)hx_name_classify(f[m->col[0]], &c);
        m->unit[0] = c.unit;
    }
    for (k = 1; k < 3; k++) {
        /* one unit for the three axes of a quantity (one --units item) */
        int a, seen = 0;
        for (a = 0; a < 3; a++) {
            const int col = m->col[1 + 3 * (k - 1) + a];
            hx_name_class_t c;
            if (col < 0) {
                continue;
            }
            (void)hx_name_classify(f[col], &c);
            if (!seen) {
                m->unit[k] = c.unit;
                seen = 1;
            } else if (c.unit != m->unit[k]) {
                m->units_differ |= k;
            }
        }
        if (m->units_differ & k) {
            m->unit[k] = HX_UNIT_NONE;
            m->ok = 0;
        }
    }
    return m->ok;
}

void hx_name_bare(const char *name, char *out, size_t size)
{
    size_t len;
    while (*name == ' ' || *name == '\t' || *name == '"' || *name == '\'') {
        name++;
    }
    len = strlen(name);
    while (len > 0 && (name[len - 1] == ' ' || name[len - 1] == '\t' || name[len - 1] == '"' ||
                       name[len - 1] == '\'' || name[len - 1] == '\r')) {
        len--;
    }
    snprintf(out, size, "%.*s", (int)len, name);
}

static void cat(char *buf, size_t size, const char *text)
{
    const size_t n = strlen(buf);
    if (n + 1 < size) {
        snprintf(buf + n, size - n, "%s", text);
    }
}

int hx_names_need_quotes(const char *s)
{
    if (*s == '~' || *s == '=') {
        return 1; /* expanded at a word's start (a home; zsh's =command) */
    }
    for (; *s != '\0'; s++) {
        /* a name with a blank or a bracket is one shell word only quoted */
        if (!(isalnum((unsigned char)*s) || strchr("_.,=/-+", *s) != NULL)) {
            return 1;
        }
    }
    return 0;
}

const char *hx_shell_word(const char *s, int names, char *buf, size_t size)
{
    size_t n = 0;
    if (size == 0u) {
        return buf;
    }
    if (!hx_names_need_quotes(s) && *s != '\0') {
        snprintf(buf, size, "%s", s);
        return strlen(s) < size ? buf : (buf[0] = '\0', buf);
    }
    buf[n++] = '\'';
    for (; *s != '\0'; s++) {
        /* room for what is written, the closing quote and the NUL */
        const size_t w = *s != '\'' ? 1u : names ? 0u : 4u;
        if (n + w + 2u > size) {
            buf[0] = '\0';
            return buf;
        }
        if (w == 1u) {
            buf[n] = *s;
        } else if (w == 4u) {
            memcpy(buf + n, "'\\''", 4);
        }
        n += w;
    }
    if (n + 2u > size) {
        buf[0] = '\0';
        return buf;
    }
    buf[n++] = '\'';
    buf[n] = '\0';
    return buf;
}

const char *hx_names_give(const hx_names_match_t *m, char *const *f, char *buf, size_t size)
{
    char map[512], name[128], word[520];
    int k;
    map[0] = '\0';
    for (k = 0; k < 7; k++) {
        if (m->ncand[k] == 1) {
            hx_name_bare(f[m->cand[k][0]], name, sizeof name);
            cat(map, sizeof map, map[0] != '\0' ? "," : "");
            cat(map, sizeof map, k_keys[k]);
            cat(map, sizeof map, (m->negate >> k) & 1 ? "=-" : "=");
            cat(map, sizeof map, name);
            if (k == 0 && m->col_tns >= 0) {
                hx_name_bare(f[m->col_tns], name, sizeof name);
                cat(map, sizeof map, ",tns=");
                cat(map, sizeof map, name);
            }
        }
    }
    buf[0] = '\0';
    if (map[0] == '\0') {
        return buf;
    }
    snprintf(buf, size, "--columns %s", hx_shell_word(map, 1, word, sizeof word));
    {
        char units[64] = "";
        for (k = 0; k < 3; k++) {
            const char *item = hx_name_unit_item(m->unit[k]);
            if (item != NULL && unit_quantity(m->unit[k]) == k) {
                cat(units, sizeof units, units[0] != '\0' ? "," : "");
                cat(units, sizeof units, item);
            }
        }
        if (units[0] != '\0') {
            cat(buf, size, " --units ");
            cat(buf, size, units);
        }
    }
    return buf;
}

const char *hx_names_unmatched(const hx_names_match_t *m, char *const *f, int time_required, char *buf,
                               size_t size)
{
    int k, j;
    char name[128], item[64];
    buf[0] = '\0';
    for (k = time_required ? 0 : 1; k < 7; k++) {
        const int count = m->ncand[k] == 0 ? m->nnear[k] : m->ncand[k];
        const int *list = m->ncand[k] == 0 ? m->near[k] : m->cand[k];
        if (m->ncand[k] == 1) {
            continue;
        }
        cat(buf, size, buf[0] != '\0' ? "; " : "");
        if (m->ncand[k] > 1) {
            snprintf(item, sizeof item, "%s: %d candidates (", k_keys[k], m->ncand[k]);
        } else if (count > 0) {
            snprintf(item, sizeof item, "%s: none (near misses: ", k_keys[k]);
        } else {
            snprintf(item, sizeof item, "%s: none", k_keys[k]);
        }
        cat(buf, size, item);
        for (j = 0; j < count && j < 3; j++) {
            hx_name_bare(f[list[j]], name, sizeof name);
            cat(buf, size, j > 0 ? ", " : "");
            cat(buf, size, name);
        }
        cat(buf, size, count > 3 ? ", ...)" : count > 0 ? ")" : "");
    }
    for (k = 1; k < 3; k++) {
        if (m->units_differ & k) {
            cat(buf, size, buf[0] != '\0' ? "; " : "");
            cat(buf, size, k == 1 ? "the accelerations name different units" : "the rates name different units");
        }
    }
    return buf;
}

const char *hx_names_unit_problem(const hx_names_match_t *m, char *const *f, char *buf, size_t size)
{
    /* the units read, as docs/log-format.md lists them */
    static const char *const k_read[3] = { "s, ms, us or \xc2\xb5s, ns",
                                           "m/s^2 or m/s2 or m/s\xc2\xb2 or mps2, g, mg, ug or \xc2\xb5g",
                                           "rad/s, deg/s or dps or \xc2\xb0/s, mdps or mdeg/s" };
    static const char *const k_what[3] = { "a time", "an acceleration", "a rate" };
    static const char *const k_unit_of[3] = { "a time unit", "an acceleration unit", "a rate unit" };
    hx_name_class_t c;
    char name[128];
    int want;
    buf[0] = '\0';
    if (m->unit_col < 0 || hx_name_classify(f[m->unit_col], &c) != HX_NAME_NEAR || c.key < 0) {
        return buf;
    }
    want = c.key == 0 ? 0 : c.key <= 3 ? 1 : 2;
    hx_name_bare(f[m->unit_col], name, sizeof name);
    if (c.unit_unread) {
        snprintf(buf, size, "column %d ('%s') names a unit not read, '%s' (%s's: %s)", m->unit_col + 1, name,
                 c.unit_text, k_what[want], k_read[want]);
    } else {
        snprintf(buf, size, "column %d ('%s') names %s, '%s', not %s's (%s)", m->unit_col + 1, name,
                 k_unit_of[unit_quantity(c.unit)], c.unit_text, k_what[want], k_read[want]);
    }
    return buf;
}

const char *hx_names_near(const hx_names_match_t *m, char *const *f, char *buf, size_t size)
{
    int k, j, shown = 0, total = 0;
    char name[128];
    buf[0] = '\0';
    for (k = 0; k < 7; k++) {
        total += m->nnear[k];
        for (j = 0; j < m->nnear[k] && j < 3; j++) {
            if (shown < 4) {
                hx_name_bare(f[m->near[k][j]], name, sizeof name);
                cat(buf, size, shown > 0 ? ", " : "");
                cat(buf, size, name);
                shown++;
            }
        }
    }
    cat(buf, size, total > shown ? ", ..." : "");
    return buf;
}
