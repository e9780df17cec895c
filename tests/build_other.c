/* One file of a program compiled apart from the library, with options of
 * its own: the Makefile builds it three times into tests/test_build, with
 * BUILD_OTHER_NAME
 *   same: the library's options (FNAV_DEFS);
 *   real: and fnav_real_t flipped (BUILD_OTHER_FLIP_REAL: float <-> double),
 *         as when -DFNAV_USE_DOUBLE=1 reaches one side only;
 *   fw:   and the firmware's options (-DFNAV_CONFIG_FILE='"fnav_cm_fw_config.h"':
 *         smaller stance, Allan and Welch buffers), as an application built
 *         with them against a library built with the defaults;
 *   pack: the library's options, compiled -fpack-struct (the same tag, the
 *         structs with padding smaller);
 *   senum: the library's options, compiled -fshort-enums (the same tag,
 *         a struct with an enum member smaller where no padding hid it).
 * Only FNAV_USE_DOUBLE is changed here: fnav_config.h has defined the
 * options, and fnav_types.h, which reads it, comes after. */
#include "footnav/fnav_config.h"
#if defined(BUILD_OTHER_FLIP_REAL)
#if FNAV_USE_DOUBLE
#undef FNAV_USE_DOUBLE
#define FNAV_USE_DOUBLE 0
#else
#undef FNAV_USE_DOUBLE
#define FNAV_USE_DOUBLE 1
#endif
#endif
#include "footnav/footnav.h"
#include "build_other.h"

#define BO_CAT_(v, f) build_other_##v##_##f
#define BO_CAT(v, f) BO_CAT_(v, f)
#define BO_FN(f) BO_CAT(BUILD_OTHER_NAME, f)

uint64_t BO_FN(tag)(void)
{
    return FNAV_BUILD_TAG;
}

size_t BO_FN(size)(int which)
{
    switch (which) {
    case BO_NAV: return sizeof(fnav_nav_t);
    case BO_UKF: return sizeof(fnav_ukf_t);
    case BO_STANCE: return sizeof(fnav_stance_t);
    case BO_ALIGN: return sizeof(fnav_align_t);
    case BO_ALLAN: return sizeof(fnav_allan_t);
    case BO_WELCH: return sizeof(fnav_welch_t);
    case BO_FFT: return sizeof(fnav_fft_t);
    case BO_IMUERR: return sizeof(fnav_imuerr_t);
    default: return 0;
    }
}

size_t BO_FN(cfg_size)(int which)
{
    switch (which) {
    case BO_NAV: return sizeof(fnav_nav_config_t);
    case BO_UKF: return sizeof(fnav_ukf_config_t);
    case BO_STANCE: return sizeof(fnav_stance_config_t);
    case BO_ALIGN: return sizeof(fnav_align_config_t);
    case BO_ALLAN: return sizeof(fnav_allan_config_t);
    case BO_WELCH: return sizeof(fnav_welch_config_t);
    case BO_IMUERR: return sizeof(fnav_imuerr_config_t);
    default: return 0; /* BO_FFT: no configuration struct */
    }
}

int BO_FN(init)(int which, void *obj)
{
    switch (which) {
    case BO_NAV: return fnav_nav_init((fnav_nav_t *)obj, &fnav_nav_config_default);
    case BO_UKF: return fnav_ukf_init((fnav_ukf_t *)obj, &fnav_ukf_config_default);
    case BO_STANCE: return fnav_stance_init((fnav_stance_t *)obj, &fnav_stance_config_default);
    case BO_ALIGN: return fnav_align_init((fnav_align_t *)obj, &fnav_align_config_default);
    case BO_ALLAN: return fnav_allan_init((fnav_allan_t *)obj, NULL);
    case BO_WELCH: return fnav_welch_init((fnav_welch_t *)obj, NULL);
    case BO_FFT: return fnav_fft_init((fnav_fft_t *)obj, 64u);
    case BO_IMUERR: return fnav_imuerr_init((fnav_imuerr_t *)obj, &fnav_imuerr_config_default);
    default: return FNAV_E_ARG;
    }
}
