/* The functions of tests/build_other.c, one set per way the Makefile
 * compiles it (tests/test_build.c): same (the library's options), real
 * (fnav_real_t flipped), fw (the firmware's options), and with the
 * library's options but a compiler flag that changes a layout: pack
 * (-fpack-struct) and senum (-fshort-enums). */
#ifndef BUILD_OTHER_H
#define BUILD_OTHER_H

#include <stddef.h>
#include <stdint.h>

#include "footnav/fnav_types.h"

/** The objects with an _init, in the order the functions below number them. */
enum { BO_NAV, BO_UKF, BO_STANCE, BO_ALIGN, BO_ALLAN, BO_WELCH, BO_FFT, BO_IMUERR, BO_COUNT };

/* build_other_V_tag: FNAV_BUILD_TAG as that file sees it; _size: sizeof
 * its object `which` (BO_*); _cfg_size: sizeof the configuration struct
 * that object's _init reads (0 for the FFT's, which takes none); _init:
 * that object's _init called there on obj with the default configuration
 * (NULL where it takes one), its status as an int (an enum has another
 * size under -fshort-enums) */
#define BUILD_OTHER_DECLARE(v)                             \
    uint64_t build_other_##v##_tag(void);                  \
    size_t build_other_##v##_size(int which);              \
    size_t build_other_##v##_cfg_size(int which);          \
    int build_other_##v##_init(int which, void *obj);

BUILD_OTHER_DECLARE(same)
BUILD_OTHER_DECLARE(real)
BUILD_OTHER_DECLARE(fw)
BUILD_OTHER_DECLARE(pack)
BUILD_OTHER_DECLARE(senum)

#endif /* BUILD_OTHER_H */
