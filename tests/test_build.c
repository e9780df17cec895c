/* The build tag (fnav_types.h, FNAV_BUILD_TAG) and the sizes each _init
 * passes: a program whose files were compiled with other layout options
 * than the library, or with a flag that changes the size of a struct,
 * gets FNAV_E_BUILD from the first _init, and the library writes nothing
 * into its object; one compiled with the library's options initialises as
 * before. The other files are tests/build_other.c, compiled five ways by
 * the Makefile (build_other.h); this file has the library's options. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "footnav/footnav.h"
#include "build_other.h"

/* an object of either layout: the largest of this build's, twice over
 * (fnav_real_t double where the library's is float), suitably aligned */
#define BIG_OBJ (sizeof(fnav_welch_t) > sizeof(fnav_nav_t) ? sizeof(fnav_welch_t) : sizeof(fnav_nav_t))
static union {
    long double ld;
    int64_t i64;
    void *p;
    unsigned char b[2u * BIG_OBJ + 4096u];
} g_obj;

#define FILL 0xa5

static const char *const k_names[BO_COUNT] = { "nav", "ukf", "stance", "align", "allan", "welch", "fft", "imuerr" };

/* bytes of g_obj not FILL among the first n */
static size_t changed_bytes(size_t n)
{
    size_t i, c = 0;
    for (i = 0; i < n; i++) {
        c += g_obj.b[i] != FILL;
    }
    return c;
}

typedef struct {
    const char *name;
    uint64_t (*tag)(void);
    size_t (*size)(int which);
    size_t (*cfg_size)(int which);
    int (*init)(int which, void *obj);
} other_t;

#define OTHER(v)                                                                                    \
    { #v, build_other_##v##_tag, build_other_##v##_size, build_other_##v##_cfg_size, build_other_##v##_init }
static const other_t k_real = OTHER(real);
static const other_t k_fw = OTHER(fw);
static const other_t k_pack = OTHER(pack);
static const other_t k_senum = OTHER(senum);

/* Every _init called from a file with other layout options: FNAV_E_BUILD,
 * and not a byte of the object written (of the caller's size or the
 * library's, the larger: before the check, the library's init wrote its own
 * layout, past the end of the caller's smaller object). */
static void check_mismatch(const other_t *o)
{
    int k;
    printf("library tag 0x%016llx, %s file's 0x%016llx; fnav_nav_t: the library's %zu bytes, the file's %zu\n",
           (unsigned long long)fnav_build_tag(), o->name, (unsigned long long)o->tag(), sizeof(fnav_nav_t),
           o->size(BO_NAV));
    assert_true(o->tag() != fnav_build_tag());
    /* the layouts do differ: the navigator holds the stance detector (fw)
     * and reals everywhere (real) */
    assert_true(o->size(BO_NAV) != sizeof(fnav_nav_t));
    for (k = 0; k < BO_COUNT; k++) {
        /* the library's size: build_other.c compiled with its options (same) */
        size_t n = o->size(k) > build_other_same_size(k) ? o->size(k) : build_other_same_size(k);
        fnav_status_t st;
        assert_true(n > 0u && n <= sizeof g_obj.b);
        memset(g_obj.b, FILL, n);
        st = (fnav_status_t)o->init(k, g_obj.b);
        if (st != FNAV_E_BUILD || changed_bytes(n) != 0u) {
            printf("%s file, fnav_%s_init: %s, %zu of %zu bytes written\n", o->name, k_names[k], fnav_status_str(st),
                   changed_bytes(n), n);
        }
        assert_int_equal(st, FNAV_E_BUILD);
        assert_int_equal(changed_bytes(n), 0);
    }
}

static void test_float_double_mismatch(void **state)
{
    (void)state;
    check_mismatch(&k_real);
}

static void test_firmware_options_mismatch(void **state)
{
    (void)state;
    if (build_other_fw_tag() == fnav_build_tag()) {
        printf("SKIP: the library was built with the firmware's options (fnav_cm_fw_config.h)\n");
        skip();
    }
    check_mismatch(&k_fw);
}

/* A file compiled with the library's options: the same tag, and
 * every _init does its work (FNAV_OK, the object written). */
static void test_same_options_match(void **state)
{
    int k;
    (void)state;
    assert_true(build_other_same_tag() == fnav_build_tag());
    assert_true(FNAV_BUILD_TAG == fnav_build_tag());
    for (k = 0; k < BO_COUNT; k++) {
        size_t n = build_other_same_size(k);
        memset(g_obj.b, FILL, n);
        assert_int_equal(build_other_same_init(k, g_obj.b), FNAV_OK);
        assert_true(changed_bytes(n) > 0u);
    }
}

/* Every public init through its _tagged function, with the library's tag
 * and the given sizes of the object and of the configuration struct it
 * reads (the FFT's takes none: cfg_size is not passed). */
static fnav_status_t init_sized(int which, void *obj, size_t obj_size, size_t cfg_size)
{
    switch (which) {
    case BO_NAV:
        return fnav_nav_init_tagged((fnav_nav_t *)obj, &fnav_nav_config_default, FNAV_BUILD_TAG, obj_size, cfg_size);
    case BO_UKF:
        return fnav_ukf_init_tagged((fnav_ukf_t *)obj, &fnav_ukf_config_default, FNAV_BUILD_TAG, obj_size, cfg_size);
    case BO_STANCE:
        return fnav_stance_init_tagged((fnav_stance_t *)obj, &fnav_stance_config_default, FNAV_BUILD_TAG, obj_size,
                                       cfg_size);
    case BO_ALIGN:
        return fnav_align_init_tagged((fnav_align_t *)obj, &fnav_align_config_default, FNAV_BUILD_TAG, obj_size,
                                      cfg_size);
    case BO_ALLAN:
        return fnav_allan_init_tagged((fnav_allan_t *)obj, &fnav_allan_config_default, FNAV_BUILD_TAG, obj_size,
                                      cfg_size);
    case BO_WELCH:
        return fnav_welch_init_tagged((fnav_welch_t *)obj, &fnav_welch_config_default, FNAV_BUILD_TAG, obj_size,
                                      cfg_size);
    case BO_FFT: return fnav_fft_init_tagged((fnav_fft_t *)obj, 64u, FNAV_BUILD_TAG, obj_size);
    case BO_IMUERR:
        return fnav_imuerr_init_tagged((fnav_imuerr_t *)obj, &fnav_imuerr_config_default, FNAV_BUILD_TAG, obj_size,
                                       cfg_size);
    default: return FNAV_E_ARG;
    }
}

/* The right tag with a wrong size, 4 bytes short or 4 over, of the object
 * or of its configuration (the layout of another version of the library,
 * or of a flag, with the same options): FNAV_E_BUILD and not a byte of the
 * object written; the right sizes: FNAV_OK, the object written. The
 * library's sizes are this file's (it has the library's options). */
static void test_wrong_size(void **state)
{
    static const int k_delta[] = { -4, 4 };
    int k, d;
    (void)state;
    for (k = 0; k < BO_COUNT; k++) {
        const size_t obj = build_other_same_size(k), cfg = build_other_same_cfg_size(k);
        const size_t n = obj + 4u; /* the larger of the two object sizes tried */
        fnav_status_t st;
        assert_true(n <= sizeof g_obj.b);
        for (d = 0; d < 2; d++) {
            const size_t bad = (size_t)((long)obj + k_delta[d]);
            memset(g_obj.b, FILL, n);
            st = init_sized(k, g_obj.b, bad, cfg);
            if (st != FNAV_E_BUILD || changed_bytes(n) != 0u) {
                printf("fnav_%s_init_tagged, object size %zu for %zu: %s, %zu bytes written\n", k_names[k], bad, obj,
                       fnav_status_str(st), changed_bytes(n));
            }
            assert_int_equal(st, FNAV_E_BUILD);
            assert_int_equal(changed_bytes(n), 0);
            if (k == BO_FFT) {
                continue; /* no configuration struct */
            }
            memset(g_obj.b, FILL, n);
            st = init_sized(k, g_obj.b, obj, (size_t)((long)cfg + k_delta[d]));
            if (st != FNAV_E_BUILD || changed_bytes(n) != 0u) {
                printf("fnav_%s_init_tagged, config size %ld for %zu: %s, %zu bytes written\n", k_names[k],
                       (long)cfg + k_delta[d], cfg, fnav_status_str(st), changed_bytes(n));
            }
            assert_int_equal(st, FNAV_E_BUILD);
            assert_int_equal(changed_bytes(n), 0);
        }
        /* the right ones: initialised as by fnav_X_init */
        memset(g_obj.b, FILL, n);
        assert_int_equal(init_sized(k, g_obj.b, obj, cfg), FNAV_OK);
        assert_true(changed_bytes(obj) > 0u);
        assert_int_equal(g_obj.b[obj], FILL); /* nothing past the object */
    }
    /* the NULL configuration that fnav_allan_init and fnav_welch_init take
     * (the defaults): its size is checked all the same */
    memset(g_obj.b, FILL, sizeof(fnav_allan_t));
    assert_int_equal(fnav_allan_init_tagged((fnav_allan_t *)g_obj.b, NULL, FNAV_BUILD_TAG, sizeof(fnav_allan_t),
                                            sizeof(fnav_allan_config_t) + 4u),
                     FNAV_E_BUILD);
    assert_int_equal(changed_bytes(sizeof(fnav_allan_t)), 0);
    memset(g_obj.b, FILL, sizeof(fnav_welch_t));
    assert_int_equal(fnav_welch_init_tagged((fnav_welch_t *)g_obj.b, NULL, FNAV_BUILD_TAG, sizeof(fnav_welch_t),
                                            sizeof(fnav_welch_config_t) - 4u),
                     FNAV_E_BUILD);
    assert_int_equal(changed_bytes(sizeof(fnav_welch_t)), 0);
}

/* A file with the library's options, so its tag, compiled with a flag that
 * changes a layout: each _init says FNAV_E_BUILD, writing nothing, when the
 * file's size of its object or configuration is not the library's, and
 * initialises as before when both are (the flag left that struct alone).
 * Returns how many inits were refused. */
static int check_layout_flag(const other_t *o)
{
    int k, refused = 0;
    assert_true(o->tag() == fnav_build_tag());
    for (k = 0; k < BO_COUNT; k++) {
        const size_t lib = build_other_same_size(k), mine = o->size(k);
        const size_t n = lib > mine ? lib : mine;
        const int differs = mine != lib || o->cfg_size(k) != build_other_same_cfg_size(k);
        fnav_status_t st;
        printf("%s file, fnav_%s_t %zu bytes (library %zu), its configuration %zu (library %zu)\n", o->name,
               k_names[k], mine, lib, o->cfg_size(k), build_other_same_cfg_size(k));
        memset(g_obj.b, FILL, n);
        st = (fnav_status_t)o->init(k, g_obj.b);
        if (differs) {
            refused++;
            assert_int_equal(st, FNAV_E_BUILD);
            assert_int_equal(changed_bytes(n), 0);
        } else {
            assert_int_equal(st, FNAV_OK);
            assert_true(changed_bytes(n) > 0u);
        }
    }
    return refused;
}

/* -fpack-struct drops the padding: the navigator's object (it holds the
 * stance detector's, whose flags sit between reals) is smaller under host
 * gcc, 11,696 -> 11,416 bytes in float, 20,608 -> 20,504 in double; before
 * the sizes were passed, fnav_nav_init said FNAV_OK and wrote past it. */
static void test_pack_struct(void **state)
{
    (void)state;
    assert_true(k_pack.size(BO_NAV) != sizeof(fnav_nav_t));
    assert_true(check_layout_flag(&k_pack) > 0);
}

/* -fshort-enums: an enum member takes a byte where no padding hides it,
 * fnav_welch_config_t's in float under host gcc (32 -> 28 bytes); in double
 * the padding hides every one (no struct changes size, and every _init
 * says FNAV_OK: nothing to catch). */
static void test_short_enums(void **state)
{
    int refused;
    (void)state;
    refused = check_layout_flag(&k_senum);
    if (refused == 0) {
        printf("-fshort-enums changes no public struct's size in this build\n");
    }
    if (sizeof(fnav_real_t) == 4u) {
        assert_true(k_senum.cfg_size(BO_WELCH) != sizeof(fnav_welch_config_t));
        assert_true(refused > 0);
    }
}

/* The tag's fields as fnav_types.h documents them: shift and width. */
typedef struct {
    const char *name;
    unsigned shift, width;
} field_t;
enum { F_REAL, F_WINDOW, F_EVENT, F_LEVELS, F_RING0, F_LAG, F_POINTS, F_NFFT, F_POLES, F_FORMAT, F_COUNT };
static const field_t k_fields[F_COUNT] = {
    { "sizeof(fnav_real_t)", 0, 4 },          { "FNAV_STANCE_MAX_WINDOW", 4, 11 },
    { "FNAV_STANCE_EVENT_BUF", 15, 13 },       { "FNAV_ALLAN_MAX_LEVELS", 28, 5 },
    { "FNAV_ALLAN_RING0_LOG2", 33, 4 },        { "FNAV_ALLAN_CASCADE_LAG_LOG2", 37, 3 },
    { "FNAV_ALLAN_MAX_POINTS", 40, 8 },        { "log2 FNAV_WELCH_MAX_NFFT", 48, 5 },
    { "FNAV_IMUERR_FLICKER_POLES", 53, 7 },    { "tag layout", 60, 4 },
};

/* The value fnav_cm_fw_config.h gives the option of field f (log2 for the
 * FFT size), -1 for one it leaves alone; at the end of the file, where it
 * reads the firmware's configuration. */
static int64_t fw_config_value(int f);

static uint64_t field(uint64_t tag, int f)
{
    return (tag >> k_fields[f].shift) & ((1ULL << k_fields[f].width) - 1u);
}

/* the fields tile the 64 bits, none overlapping */
static void test_fields_tile(void **state)
{
    unsigned next = 0;
    int f;
    (void)state;
    for (f = 0; f < F_COUNT; f++) {
        assert_int_equal(k_fields[f].shift, next);
        next += k_fields[f].width;
    }
    assert_int_equal(next, 64);
}

/* This build's tag holds this build's options; the other files' tags
 * differ from it in the fields of the options they changed, only. */
static void test_tag_fields(void **state)
{
    const uint64_t lib = fnav_build_tag(), real = build_other_real_tag(), fw = build_other_fw_tag();
    int f;
    (void)state;
    assert_int_equal(field(lib, F_REAL), sizeof(fnav_real_t));
    assert_int_equal(field(lib, F_WINDOW), FNAV_STANCE_MAX_WINDOW);
    assert_int_equal(field(lib, F_EVENT), FNAV_STANCE_EVENT_BUF);
    assert_int_equal(field(lib, F_LEVELS), FNAV_ALLAN_MAX_LEVELS);
    assert_int_equal(field(lib, F_RING0), FNAV_ALLAN_RING0_LOG2);
    assert_int_equal(field(lib, F_LAG), FNAV_ALLAN_CASCADE_LAG_LOG2);
    assert_int_equal(field(lib, F_POINTS), FNAV_ALLAN_MAX_POINTS);
    assert_int_equal(1ULL << field(lib, F_NFFT), FNAV_WELCH_MAX_NFFT);
    assert_int_equal(field(lib, F_POLES), FNAV_IMUERR_FLICKER_POLES);
    assert_int_equal(field(lib, F_FORMAT), 1);
    /* real: only the size of fnav_real_t, 4 <-> 8 */
    assert_int_equal(field(real, F_REAL), sizeof(fnav_real_t) == 4u ? 8u : 4u);
    assert_true((real ^ lib) >> 4 == 0u);
    /* fw: fnav_cm_fw_config.h sets the stance, Allan ring and Welch sizes,
     * not the real type, the Allan levels or the flicker poles */
    for (f = 0; f < F_COUNT; f++) {
        int set_by_fw = f == F_WINDOW || f == F_EVENT || f == F_RING0 || f == F_LAG || f == F_POINTS || f == F_NFFT;
        assert_int_equal(set_by_fw, fw_config_value(f) >= 0);
        if (!set_by_fw) {
            if (field(fw, f) != field(lib, f)) {
                printf("fw file: %s differs\n", k_fields[f].name);
            }
            assert_true(field(fw, f) == field(lib, f));
        } else {
            /* the firmware's value, and not the library's (the defaults) */
            assert_true(field(fw, f) == (uint64_t)fw_config_value(f));
            assert_true(field(fw, f) != field(lib, f));
        }
    }
    assert_true(fw != lib);
}

/* Each option alone, at both ends of the range fnav_config_check.h allows,
 * moves its own field, to its value, and no other (each is then put back
 * to the library's value, read from the tag). */
static void test_each_option_alone(void **state);

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_float_double_mismatch), cmocka_unit_test(test_firmware_options_mismatch),
        cmocka_unit_test(test_same_options_match),    cmocka_unit_test(test_wrong_size),
        cmocka_unit_test(test_pack_struct),           cmocka_unit_test(test_short_enums),
        cmocka_unit_test(test_fields_tile),           cmocka_unit_test(test_tag_fields),
        cmocka_unit_test(test_each_option_alone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* Last in the file: it redefines the options for the rest of it. */
static void check_alone(uint64_t base, uint64_t t, int f, uint64_t value)
{
    const uint64_t mask = ((1ULL << k_fields[f].width) - 1u) << k_fields[f].shift;
    if (field(t, f) != value || ((t ^ base) & ~mask) != 0u) {
        printf("%s = %llu: tag 0x%016llx (base 0x%016llx)\n", k_fields[f].name, (unsigned long long)value,
               (unsigned long long)t, (unsigned long long)base);
    }
    assert_true(field(t, f) == value);
    assert_true(((t ^ base) & ~mask) == 0u);
}

static void test_each_option_alone(void **state)
{
    const uint64_t base = FNAV_BUILD_TAG;
    (void)state;
#undef FNAV_STANCE_MAX_WINDOW
#define FNAV_STANCE_MAX_WINDOW 3
    check_alone(base, FNAV_BUILD_TAG, F_WINDOW, 3);
#undef FNAV_STANCE_MAX_WINDOW
#define FNAV_STANCE_MAX_WINDOW 1024
    check_alone(base, FNAV_BUILD_TAG, F_WINDOW, 1024);
#undef FNAV_STANCE_MAX_WINDOW
#define FNAV_STANCE_MAX_WINDOW field(base, F_WINDOW)
#undef FNAV_STANCE_EVENT_BUF
#define FNAV_STANCE_EVENT_BUF 8
    check_alone(base, FNAV_BUILD_TAG, F_EVENT, 8);
#undef FNAV_STANCE_EVENT_BUF
#define FNAV_STANCE_EVENT_BUF 4096
    check_alone(base, FNAV_BUILD_TAG, F_EVENT, 4096);
#undef FNAV_STANCE_EVENT_BUF
#define FNAV_STANCE_EVENT_BUF field(base, F_EVENT)
#undef FNAV_ALLAN_MAX_LEVELS
#define FNAV_ALLAN_MAX_LEVELS 2
    check_alone(base, FNAV_BUILD_TAG, F_LEVELS, 2);
#undef FNAV_ALLAN_MAX_LEVELS
#define FNAV_ALLAN_MAX_LEVELS 31
    check_alone(base, FNAV_BUILD_TAG, F_LEVELS, 31);
#undef FNAV_ALLAN_MAX_LEVELS
#define FNAV_ALLAN_MAX_LEVELS field(base, F_LEVELS)
#undef FNAV_ALLAN_RING0_LOG2
#define FNAV_ALLAN_RING0_LOG2 3
    check_alone(base, FNAV_BUILD_TAG, F_RING0, 3);
#undef FNAV_ALLAN_RING0_LOG2
#define FNAV_ALLAN_RING0_LOG2 15
    check_alone(base, FNAV_BUILD_TAG, F_RING0, 15);
#undef FNAV_ALLAN_RING0_LOG2
#define FNAV_ALLAN_RING0_LOG2 field(base, F_RING0)
#undef FNAV_ALLAN_CASCADE_LAG_LOG2
#define FNAV_ALLAN_CASCADE_LAG_LOG2 0
    check_alone(base, FNAV_BUILD_TAG, F_LAG, 0);
#undef FNAV_ALLAN_CASCADE_LAG_LOG2
#define FNAV_ALLAN_CASCADE_LAG_LOG2 6
    check_alone(base, FNAV_BUILD_TAG, F_LAG, 6);
#undef FNAV_ALLAN_CASCADE_LAG_LOG2
#define FNAV_ALLAN_CASCADE_LAG_LOG2 field(base, F_LAG)
#undef FNAV_ALLAN_MAX_POINTS
#define FNAV_ALLAN_MAX_POINTS 1
    check_alone(base, FNAV_BUILD_TAG, F_POINTS, 1);
#undef FNAV_ALLAN_MAX_POINTS
#define FNAV_ALLAN_MAX_POINTS 255
    check_alone(base, FNAV_BUILD_TAG, F_POINTS, 255);
#undef FNAV_ALLAN_MAX_POINTS
#define FNAV_ALLAN_MAX_POINTS field(base, F_POINTS)
#undef FNAV_WELCH_MAX_NFFT
#define FNAV_WELCH_MAX_NFFT 8
    check_alone(base, FNAV_BUILD_TAG, F_NFFT, 3);
#undef FNAV_WELCH_MAX_NFFT
#define FNAV_WELCH_MAX_NFFT 65536
    check_alone(base, FNAV_BUILD_TAG, F_NFFT, 16);
#undef FNAV_WELCH_MAX_NFFT
#define FNAV_WELCH_MAX_NFFT (1ULL << field(base, F_NFFT))
#undef FNAV_IMUERR_FLICKER_POLES
#define FNAV_IMUERR_FLICKER_POLES 2
    check_alone(base, FNAV_BUILD_TAG, F_POLES, 2);
#undef FNAV_IMUERR_FLICKER_POLES
#define FNAV_IMUERR_FLICKER_POLES 64
    check_alone(base, FNAV_BUILD_TAG, F_POLES, 64);
#undef FNAV_IMUERR_FLICKER_POLES
#define FNAV_IMUERR_FLICKER_POLES field(base, F_POLES)
    /* every option back at the library's value: the library's tag */
    assert_true(FNAV_BUILD_TAG == base);
}

/* Last in the file: the firmware's configuration in place of the options. */
#undef FNAV_STANCE_MAX_WINDOW
#undef FNAV_STANCE_EVENT_BUF
#undef FNAV_ALLAN_RING0_LOG2
#undef FNAV_ALLAN_CASCADE_LAG_LOG2
#undef FNAV_ALLAN_MAX_POINTS
#undef FNAV_WELCH_MAX_NFFT
#undef FNAV_CM_RING_SIZE
#include "fnav_cm_fw_config.h"

static int64_t fw_config_value(int f)
{
    switch (f) {
    case F_WINDOW: return FNAV_STANCE_MAX_WINDOW;
    case F_EVENT: return FNAV_STANCE_EVENT_BUF;
    case F_RING0: return FNAV_ALLAN_RING0_LOG2;
    case F_LAG: return FNAV_ALLAN_CASCADE_LAG_LOG2;
    case F_POINTS: return FNAV_ALLAN_MAX_POINTS;
    case F_NFFT: return FNAV_BUILD_NFFT_LOG2;
    default: return -1;
    }
}
