/**
 * @file fnav_version.h
 * @brief footnav's version, MAJOR.MINOR.PATCH: the one place it is written.
 *
 * The Makefile reads the three numbers for footnav.pc's Version (a packager
 * may still set VERSION=), `harness --version` prints FNAV_VERSION_STRING
 * and every JSON output of the harness carries it as `footnav_version`.
 * Macros only: nothing of it is compiled into the library or the firmware.
 * It starts at 0.1.0, before a first release; CHANGELOG.md says what bumps
 * which number.
 */
#ifndef FNAV_VERSION_H
#define FNAV_VERSION_H

#define FNAV_VERSION_MAJOR 0
#define FNAV_VERSION_MINOR 1
#define FNAV_VERSION_PATCH 0

#define FNAV_VERSION_STR_(x) #x
#define FNAV_VERSION_STR(x) FNAV_VERSION_STR_(x)
/** "MAJOR.MINOR.PATCH", made from the three numbers above: "0.1.0". */
#define FNAV_VERSION_STRING \
    FNAV_VERSION_STR(FNAV_VERSION_MAJOR) "." FNAV_VERSION_STR(FNAV_VERSION_MINOR) "." FNAV_VERSION_STR(FNAV_VERSION_PATCH)

#endif /* FNAV_VERSION_H */
