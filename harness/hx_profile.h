/**
 * @file hx_profile.h
 * @brief Sensor profile files (docs/profile-format.md): written by
 *        `harness allan --profile`, read by `--profile FILE` everywhere.
 */
#ifndef HX_PROFILE_H
#define HX_PROFILE_H

#include <stddef.h>
#include "footnav/fnav_profile.h"
#include "hx_cli.h"

/** Read a profile file. 0 on success; -1 with a one-line "FILE:LINE: ..."
 *  message in err. Unknown keys are ignored (room for extra information). */
int hx_profile_read(const char *path, fnav_profile_t *p, char *err, size_t err_size);

/** Write a profile file; @p comment (may be NULL) becomes '# ' lines at
 *  the top. 0 on success, -1 with err filled. */
int hx_profile_write(const char *path, const fnav_profile_t *p, const char *comment, char *err, size_t err_size);

/** As hx_profile_write(), then @p extra (may be NULL) verbatim after the
 *  standard keys: further "key = value" lines (docs/profile-format.md lists
 *  the optional keys), which hx_profile_read() ignores. */
int hx_profile_write_extra(const char *path, const fnav_profile_t *p, const char *comment, const char *extra,
                           char *err, size_t err_size);

/** 1 with @p msg filled (the key, its value, the units it most likely is
 *  in, with the value converted from each: deg/s/sqrt(Hz) or deg/sqrt(h),
 *  mg/sqrt(Hz) or ug/sqrt(Hz), deg/s or deg/h, mg or ug, each named when
 *  its conversion is within the bound) when a value lies beyond any IMU's
 *  in its key's unit: a gyro noise
 *  above 1 deg/s/sqrt(Hz), an accelerometer noise above 10 mg/sqrt(Hz), a
 *  gyro bias sd above 10 deg/s, an accelerometer bias sd above 0.1 g
 *  (docs/profile-format.md); else 0. */
int hx_profile_implausible(const fnav_profile_t *p, char *msg, size_t n);

/** Files hx_profile_load() remembers having warned about in a run. */
#define HX_PROFILE_WARNED_MAX 64

/** A built-in name ("navchip", "mtx", "shimmer") or a file path; a file
 *  with a value hx_profile_implausible() flags gets a warning (once per
 *  file in a run, the file known by its name as given; past
 *  HX_PROFILE_WARNED_MAX files warned about, a further one is warned about
 *  at each load), and is loaded. */
int hx_profile_load(const char *name_or_path, fnav_profile_t *p, char *err, size_t err_size);

/** A profile given as a file is an input: 1 (with the error printed) when
 *  one of the output options @p outs (NULL-terminated) names that file,
 *  which would replace the profile after it was read; 0 otherwise, and for
 *  a built-in name or NULL. */
int hx_profile_is_output(const char *cmd, const char *name_or_path, const hx_args_t *a, const char *const *outs);

#endif /* HX_PROFILE_H */
