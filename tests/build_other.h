/* The functions of tests/build_other.c, one set per way the Makefile
 * compiles it (tests/test_build.c): same (the library's options), real
 * (fnav_real_t flipped) and fw (the firmware's options). */
#ifndef BUILD_OTHER_H
#define BUILD_OTHER_H

#include <stddef.h>
#include <stdint.h>

#include "footnav/fnav_types.h"

/** The objects with an _init, in the order the functions below number them. */
enum { BO_NAV, BO_UKF, BO_STANCE, BO_ALIGN, BO_ALLAN, BO_WELCH, BO_FFT, BO_IMUERR, BO_COUNT };

/* build_other_V_tag: FNAV_BUILD_TAG as that file sees it; _size: sizeof
 * its object `which` (BO_*); _init: that object's _init called there on
 * obj with the default configuration (NULL where it takes one) */
#define BUILD_OTHER_DECLARE(v)                             \
    uint64_t build_other_##v##_tag(void);                  \
    size_t build_other_##v##_size(int which);              \
    fnav_status_t build_other_##v##_init(int which, void *obj);

BUILD_OTHER_DECLARE(same)
BUILD_OTHER_DECLARE(real)
BUILD_OTHER_DECLARE(fw)

#endif /* BUILD_OTHER_H */
