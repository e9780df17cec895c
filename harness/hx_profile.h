/**
 * @file hx_profile.h
 * @brief Sensor profile files (docs/profile-format.md): written by
 *        `harness allan --profile`, read by `--profile FILE` everywhere.
 */
#ifndef HX_PROFILE_H
#define HX_PROFILE_H

#include <float.h>
#include <stddef.h>
#include "footnav/fnav_profile.h"
#include "hx_cli.h"

/* The limits of a profile's values (docs/profile-format.md, "Limits"): the
 * strictest of the consumers', so that a file every command reads is one
 * every command can use (the filter took gyro_tau_s = 0.0005, which sim
 * refused after the load, simgap after reading the log, neither naming the
 * key). The same in either build: a file valid for the double build is
 * valid for the float one. */
/** rate_hz: an IMU's output rate (no sensor identified for navigation runs
 *  below 1 Hz; sim --bias-sigma eq6 scales the bias sd by sqrt(tau rate),
 *  which 1e-40 Hz made 0); at most the log formats' 1e6 Hz. */
#define HX_PROFILE_RATE_MIN_HZ 1.0
#define HX_PROFILE_RATE_MAX_HZ 1e6
/** Noise densities: positive in the float build (fnav_profile_validate; a
 *  normal float), at most the simulator's white density (1e3, the effect
 *  catalogue of src/fnav_imuerr.c; the filter's noise_ok takes up to 1.8e19). */
#define HX_PROFILE_NOISE_MIN ((double)FLT_MIN)
#define HX_PROFILE_NOISE_MAX 1e3
/** Correlation times: the simulator's ar1 tau_s range (src/fnav_imuerr.c;
 *  the filter takes any positive one). */
#define HX_PROFILE_TAU_MIN_S 1e-3
#define HX_PROFILE_TAU_MAX_S 1e9
/** Bias sds: the filter's sd_ok wants the square a positive float
 *  (src/fnav_ukf.c, which takes a subnormal one, from about 2.6e-23); kept
 *  to a normal square, from sqrt(FLT_MIN) = 2^-63 = 1.08e-19; at most the
 *  simulator's ar1 sigma (1e3). */
#define HX_PROFILE_SIGMA_MIN 1.0842021724855044e-19
#define HX_PROFILE_SIGMA_MAX 1e3

/** Read a profile file. 0 on success; -1 with a one-line "FILE:LINE: ..."
 *  message in err (a missing key: "FILE: no line gives KEY ..."). A key
 *  neither read nor documented (docs/profile-format.md) is ignored; see
 *  hx_profile_read_warn() for the warning about it. */
int hx_profile_read(const char *path, fnav_profile_t *p, char *err, size_t err_size);

/** As hx_profile_read(), with the warnings about the file in @p warn (may
 *  be NULL): one line each, "FILE:LINE: unknown key 'K' ignored ...", for a
 *  key that is neither read nor an optional one (ident_*, paper_*,
 *  allan_fit_rms_log10_*, *_quant_*, *_rrw_*) nor an extension of the
 *  user's (x_*); "" when there is none. */
int hx_profile_read_warn(const char *path, fnav_profile_t *p, char *warn, size_t warn_size, char *err,
                         size_t err_size);

/** 0 when every value of @p p is within the limits above (HX_PROFILE_*)
 *  and its name is printable; else -1 with "KEY value K V outside [LO, HI]
 *  (why)" in err. For a profile made in memory: sim --bias-sigma eq6's
 *  rescaled bias sd, or one `allan --profile` is about to write. */
int hx_profile_check(const fnav_profile_t *p, char *err, size_t err_size);

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
 *  with a value hx_profile_implausible() flags or an unknown key
 *  (hx_profile_read_warn()) gets its warnings (once per
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
