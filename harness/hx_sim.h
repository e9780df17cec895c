/**
 * @file hx_sim.h
 * @brief The simulator's sampling chain (docs/simulator.md): exact foot
 *        motion (hx_motion.h) -> signal-stage effects at the internal rate
 *        -> anti-alias FIR and decimation (or picking, with the `alias`
 *        effect) -> sensor-stage errors at the output rate -> timing
 *        (jitter, drops, duplicates). Plus the text form of effects
 *        ("quant:ch=gyro:lsb=1e-3") shared by every command that names them.
 */
#ifndef HX_SIM_H
#define HX_SIM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "footnav/fnav_imuerr.h"
#include "hx_cli.h"
#include "hx_motion.h"

/** Half length of the anti-alias FIR in output periods: L = 2 K M + 1 taps
 *  (Kaiser, 60 dB, pass band to 0.41 f_s, stop band from 0.59 f_s). */
#define HX_SIM_FIR_HALF 10

/** How the internal samples become output samples (without `alias`). */
typedef enum {
    HX_DECIM_FIR = 0,  /**< linear-phase anti-alias FIR centred on the stamp: the band-limited
                            instantaneous value (a rate-output MEMS sensor, delay compensated) */
    HX_DECIM_MEAN = 1  /**< the mean over the output interval that ends at the stamp (an
                            integrating sensor delivering delta-angles and delta-velocities; the
                            convention of footnav's strapdown, fnav_strapdown.h) */
} hx_decim_t;

/** What to simulate. */
typedef struct {
    const hx_motion_t *motion;  /**< truth */
    fnav_imuerr_config_t err;   /**< sensor model; err.rate_hz is the output rate, err.seed the seed */
    double duration_s;          /**< output covers [0, duration_s]; <= 0: the motion's duration */
    hx_decim_t decim;           /**< decimation (ignored with the alias effect: picking) */
} hx_sim_config_t;

/** One nominal output tick. */
typedef struct {
    uint32_t seq;              /**< tick index (the sensor's counter) */
    double t_s;                /**< nominal time seq / rate, s */
    hx_truth_t truth;          /**< exact truth at t_s */
    fnav_sample_t meas;        /**< the measurement (t_ns with stamp jitter, seq, flags) */
    uint32_t count;            /**< deliveries: 0 dropped, 1, 2 duplicated */
    double bias[6];            /**< injected additive bias (fnav_imuerr_bias), SI */
} hx_sim_tick_t;

/** Receives every tick in order; return non-zero to stop the run. */
typedef int (*hx_sim_sink_fn)(void *ctx, const hx_sim_tick_t *tick);

/** Number of output ticks of a configuration. */
size_t hx_sim_ticks(const hx_sim_config_t *cfg);

/**
 * Run the chain. Returns 0 when every tick was delivered, 1 when the sink
 * stopped it, -1 on a configuration error (message in err: an invalid
 * error-model configuration, or sampling-instant jitter combined with the
 * anti-alias filter, which needs --oversample 1 or the alias effect).
 */
int hx_sim_run(const hx_sim_config_t *cfg, hx_sim_sink_fn sink, void *ctx, char *err, size_t err_size);

/**
 * Apply one effect specification to a configuration:
 *   NAME                    switch on (all allowed channels, current parameters)
 *   NAME:off                switch off
 *   NAME[:ch=CH][:P=V]...   switch on for channels CH with parameters P = V (SI)
 * CH is all, acc, gyro or a '+'-separated list of ax ay az gx gy gz; an effect on whole
 * samples (no per-channel parameter: jitter, dropout, duplicate, alias)
 * takes no ch=.
 * Parameters given apply to the channels of this specification only.
 * @return 0, or -1 with a one-line message in err.
 */
int hx_effect_parse(fnav_imuerr_config_t *cfg, const char *spec, char *err, size_t err_size);

/** The specification of an enabled effect as text that hx_effect_parse
 *  reads back to the same configuration: one space-separated
 *  "NAME:ch=..:P=V..." per group of channels with identical parameters
 *  (each value the shortest decimal that reads back to it). Empty for an
 *  effect that is off. Returns the length needed. */
size_t hx_effect_format(const fnav_imuerr_config_t *cfg, fnav_effect_id_t id, char *buf, size_t size);

/* ------------------------------------------------------------ options */

/** Command-line options that describe a simulation (motion, sensor,
 *  sampling), shared by `sim` and `montecarlo`; for an hx_opt_t table. */
#define HX_SIM_OPTS                                                                                             \
    { "--motion", "NAME|SCRIPT", "walk (default), run, stairs, elevator, stand, loop, paper, mixed, or a "     \
                                 "script such as stand:5,walk:20:90,stairs-up:12,home", 0 },                   \
    { "--duration", "S", "length of the output in seconds (stand, walk, run and loop are sized to it; other "   \
                         "motions are cut short or end standing; default: the motion's own length, stand, walk " \
                         "and run sized to 60 s and loop to 90 s, in whole strides)", 0 },                      \
    { "--rate", "HZ", "output sample rate (default 200)", 0 },                                                  \
    { "--profile", "NAME|FILE", "sensor noise: navchip (default), mtx, shimmer, generic-mems, a profile file, or none", 0 },  \
    { "--bias-sigma", "READING", "paper Tables' sigma_bias: given (default, eq. 4: stationary sd) or eq6 "     \
                                 "(sd = sigma_bias sqrt(tau) / 0.617, docs/simulator.md)", 0 },                \
    { "--effect", "SPEC", "add an effect: NAME[:ch=CH][:PARAM=VALUE]... or NAME:off (see sim --list-effects)", 1 }, \
    { "--seed", "N", "random seed (default 1)", 0 },                                                            \
    { "--oversample", "M", "internal rate / output rate before the anti-alias filter (default: >= 2 kHz "     \
                           "internally; 1 = point sampling)", 0 },                                              \
    { "--speed", "MPS", "walking speed (with --cadence or --stride; the third follows)", 0 },                  \
    { "--cadence", "SPM", "walking steps per minute (both feet)", 0 },                                          \
    { "--stride", "M", "walking stride of the sensor foot", 0 },                                                \
    { "--impact-ms", "MS", "landing deceleration time of every gait (impact sharpness)", 0 },                   \
    { "--ring-scale", "X", "multiply the shoe ringing after each contact (0: none)", 0 },                       \
    { "--mount", "R,P,Y", "sensor mounting on the foot, ZYX Euler degrees", 0 },                            \
    { "--decimation", "KIND", "fir (default: band-limited instantaneous samples) or mean (the mean over "     \
                              "each interval, as delta-angle/velocity sensors; docs/simulator.md)", 0 }

/** A simulation described by the HX_SIM_OPTS options. */
typedef struct {
    hx_motion_config_t motion_cfg;
    fnav_imuerr_config_t err;      /**< with rate, seed, oversample, profile baseline, effects */
    fnav_profile_t profile;        /**< the profile (after --bias-sigma), valid when has_profile */
    int has_profile;
    const char *profile_name;      /**< "navchip", a path, or "none" */
    const char *motion_name;       /**< --motion (default "walk") */
    double duration_s;             /**< --duration (0: the motion's) */
    int bias_eq6;                  /**< --bias-sigma eq6 */
    hx_decim_t decim;              /**< --decimation */
} hx_sim_setup_t;

/** Read the HX_SIM_OPTS options. 0 ok; -1 on a usage error (message
 *  printed as "harness CMD: error: ..."). */
int hx_sim_setup_from_args(const char *cmd, const hx_args_t *a, hx_sim_setup_t *s);

/** Warn of the gait options the motion m (built from --motion `name`)
 *  leaves without effect: --speed, --cadence, --stride without a walking
 *  stride, --impact-ms without any stride. */
void hx_sim_warn_unused(const char *cmd, const hx_args_t *a, const hx_motion_t *m, const char *name);

/** The paper's eq. (6) reading of a profile's bias sigmas: the Allan floor
 *  is BS = sigma_bias sqrt(tau / T_s) and a Gauss-Markov process with that
 *  floor has a stationary sd of BS / 0.617 (docs/simulator.md). */
void hx_profile_bias_eq6(fnav_profile_t *p);

/** Warn (as @p cmd) when @p duration_s (> 0) ends the output before the
 *  motion @p m (named @p name) is done: a stride, a turn or a ride still to
 *  come. Cutting the final standing short is no cut. */
void hx_sim_warn_cut(const char *cmd, const hx_motion_t *m, const char *name, double duration_s);

/** Channel mask of a channel list ("gyro", "ax+gz"); 0 when invalid. */
uint32_t hx_channels_parse(const char *s);

/** Print the catalogue (names, parameters, units, defaults) to a stream. */
void hx_effect_list(FILE *f);

#endif /* HX_SIM_H */
