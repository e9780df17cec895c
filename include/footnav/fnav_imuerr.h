/**
 * @file fnav_imuerr.h
 * @brief Per-sample IMU error model: white noise plus an AR(1) / Gauss-Markov
 *        bias per axis (paper eqs. (1)-(4)) and a catalogue of named sensor
 *        effects, each toggled and parameterised independently.
 *
 * Allocation-free, float by default, deterministic for a seed: the model has
 * its own small random number generator (xoshiro128+, seeded by splitmix64)
 * and one independent stream per effect, so switching one effect on or off
 * never changes the random draws of another (paired comparisons stay paired).
 *
 * Channels: 0..2 accelerometer x, y, z (m/s^2, specific force), 3..5
 * gyroscope x, y, z (rad/s), all in the body (sensor) frame b. A parameter
 * "in u" is in the channel's own unit (m/s^2 or rad/s).
 *
 * The measurement is built in three stages (docs/simulator.md):
 * - signal stage, fnav_imuerr_signal(), at the sensor's internal rate:
 *   scale factor, misalignment / cross-coupling, gyro g-sensitivity,
 *   vibration tone, saturation of the sensing element;
 * - sensor stage, fnav_imuerr_sensor(), at the output rate, after the
 *   (harness-side) decimation: offset, AR(1) bias (eq. 3, 4), flicker,
 *   rate random walk, ramp, thermal drift, bias jumps, white noise (eq. 2),
 *   output clipping, quantisation;
 * - timing, fnav_imuerr_tick(), once per nominal output tick: sampling
 *   instant and time-stamp jitter, dropped and duplicated samples.
 * fnav_imuerr_apply() runs the signal and sensor stages on one sample for
 * users that have no separate internal rate (firmware tests).
 *
 * The `alias` effect (sampling without an anti-alias filter) is multi-rate:
 * the harness (harness/hx_sim.c) simulates the signal stage at
 * factor x rate and picks every factor-th sample instead of filtering; the
 * core folds the sensor's white noise accordingly (density x sqrt(factor)).
 *
 * Nothing here may be called from an interrupt while another context uses
 * the same object; distinct objects are independent.
 */
#ifndef FNAV_IMUERR_H
#define FNAV_IMUERR_H

#include "fnav_types.h"
#include "fnav_profile.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Number of channels: accel x, y, z then gyro x, y, z. */
#define FNAV_IMUERR_NCH 6

/** Channel masks (bit i = channel i). */
#define FNAV_CH_AX 0x01u
#define FNAV_CH_AY 0x02u
#define FNAV_CH_AZ 0x04u
#define FNAV_CH_GX 0x08u
#define FNAV_CH_GY 0x10u
#define FNAV_CH_GZ 0x20u
#define FNAV_CH_ACC 0x07u
#define FNAV_CH_GYRO 0x38u
#define FNAV_CH_ALL 0x3Fu

/* ------------------------------------------------------------------ RNG */

/** xoshiro128+ state (Blackman & Vigna 2018) with a cached Gaussian. */
typedef struct {
    uint32_t s[4];
    fnav_real_t spare;  /**< second Box-Muller deviate */
    int has_spare;
} fnav_rng_t;

/** Seed a stream: the state is filled by splitmix64 of (seed, stream), so
 *  streams of one seed are independent for practical purposes. */
void fnav_rng_seed(fnav_rng_t *r, uint32_t seed, uint32_t stream);
/** Next 32 random bits. */
uint32_t fnav_rng_u32(fnav_rng_t *r);
/** Uniform deviate in [0, 1) with 24 random bits (float build) or 53 (double). */
fnav_real_t fnav_rng_uniform(fnav_rng_t *r);
/** Standard normal deviate (Box-Muller, pairs cached). The float build's
 *  24-bit uniforms bound |x| < 5.8; the double build's 53-bit ones < 8.6. */
fnav_real_t fnav_rng_gauss(fnav_rng_t *r);

/* ------------------------------------------------------------ catalogue */

/** The effects. The first two are the paper's baseline model (eqs. 1-4). */
typedef enum {
    FNAV_EFFECT_WHITE = 0,   /**< white noise v_k (eq. 2): density */
    FNAV_EFFECT_AR1,         /**< AR(1) bias b_k (eqs. 3, 4): tau_s, sigma */
    FNAV_EFFECT_OFFSET,      /**< constant bias: value */
    FNAV_EFFECT_QUANT,       /**< quantisation: lsb, shaped */
    FNAV_EFFECT_FLICKER,     /**< 1/f bias instability: b, tau_lo_s, tau_hi_s */
    FNAV_EFFECT_RRW,         /**< rate random walk: k */
    FNAV_EFFECT_RAMP,        /**< drift ramp in time: rate */
    FNAV_EFFECT_THERMAL,     /**< drift with a warm-up temperature: coef, rise_c, tau_s, t0_c */
    FNAV_EFFECT_VIBRATION,   /**< sinusoidal tone: amp, freq_hz, phase_rad */
    FNAV_EFFECT_JUMPS,       /**< random bias steps: rate_hz, amp */
    FNAV_EFFECT_SATURATION,  /**< clipping at full scale: range */
    FNAV_EFFECT_SCALE,       /**< scale-factor error: sf */
    FNAV_EFFECT_MISALIGN,    /**< misalignment / cross-coupling: from_x, from_y, from_z */
    FNAV_EFFECT_GSENS,       /**< gyro g-sensitivity: from_x, from_y, from_z */
    FNAV_EFFECT_JITTER,      /**< timing jitter: stamp_s, sample_s */
    FNAV_EFFECT_DROPOUT,     /**< dropped samples: prob */
    FNAV_EFFECT_DUPLICATE,   /**< duplicated samples: prob */
    FNAV_EFFECT_ALIAS,       /**< sampling without anti-alias filter: factor */
    FNAV_EFFECT_COUNT
} fnav_effect_id_t;

/**
 * Configuration. `mask[e]` is the set of channels effect e applies to
 * (0 = off; effects without per-channel parameters are on for any non-zero
 * mask). Parameters are SI; per-channel arrays are indexed by channel.
 * Start from fnav_imuerr_config_default (every effect off, parameters at
 * their documented defaults) or fnav_imuerr_config_from_profile().
 */
typedef struct {
    uint32_t seed;        /**< random seed; equal seeds give equal outputs */
    fnav_real_t rate_hz;  /**< output rate, Hz (sensor stage and ticks) */
    uint32_t oversample;  /**< internal rate / output rate of the signal stage
                               when `alias` is off (the harness filters before
                               decimating); 1 = same rate */
    uint8_t mask[FNAV_EFFECT_COUNT]; /**< channels per effect, FNAV_CH_* bits */

    struct { fnav_real_t density[6]; } white;  /**< u/sqrt(Hz): sample std = density sqrt(rate) */
    struct {
        fnav_real_t tau_s[6];  /**< correlation time, s: c = exp(-dt/tau_s) (eq. 3) */
        fnav_real_t sigma[6];  /**< stationary std, u (the paper's sigma_bias, eq. 4) */
    } ar1;
    struct { fnav_real_t value[6]; } offset;   /**< constant bias, u */
    struct {
        fnav_real_t lsb[6];    /**< quantisation step, u */
        fnav_real_t shaped[6]; /**< 1: first-order noise shaping (integrating sensor, the
                                    sum of outputs tracks the sum of inputs); 0: plain rounding */
    } quant;
    struct {
        fnav_real_t b[6];      /**< bias instability coefficient B, u: one-sided PSD B^2/(pi f),
                                    Allan floor sqrt(2 ln2 / pi) B = 0.664 B */
        fnav_real_t tau_lo_s;  /**< shortest correlation time of the 1/f band, s */
        fnav_real_t tau_hi_s;  /**< longest correlation time of the 1/f band, s */
    } flicker;
    struct { fnav_real_t k[6]; } rrw;          /**< rate random walk K, u/sqrt(s): Allan K sqrt(tau/3) */
    struct { fnav_real_t rate[6]; } ramp;      /**< drift rate R, u/s: Allan R tau / sqrt(2) */
    struct {
        fnav_real_t coef[6];   /**< bias per degree, u/degC */
        fnav_real_t rise_c;    /**< warm-up temperature rise, degC */
        fnav_real_t tau_s;     /**< warm-up time constant, s */
        fnav_real_t t0_c;      /**< temperature at start, degC */
    } thermal;
    struct {
        fnav_real_t amp[6];       /**< amplitude, u */
        fnav_real_t freq_hz[6];   /**< frequency, Hz */
        fnav_real_t phase_rad[6]; /**< phase at t = 0, rad */
    } vibration;
    struct {
        fnav_real_t rate_hz[6];   /**< mean number of steps per second (Poisson) */
        fnav_real_t amp[6];       /**< std of a step (Gaussian), u */
    } jumps;
    struct { fnav_real_t range[6]; } saturation; /**< full scale, u: output in [-range, range] */
    struct { fnav_real_t sf[6]; } scale;         /**< y = (1 + sf) x */
    struct {
        fnav_real_t from_x[6]; /**< coupling of the same sensor's x axis into this channel */
        fnav_real_t from_y[6]; /**< ... y axis (own axis must be 0) */
        fnav_real_t from_z[6]; /**< ... z axis */
    } misalign;
    struct {
        fnav_real_t from_x[6]; /**< gyro error per specific force x, rad/s per m/s^2 (gyro channels only) */
        fnav_real_t from_y[6];
        fnav_real_t from_z[6];
    } gsens;
    struct {
        fnav_real_t stamp_s;   /**< std of the time-stamp error, s (stamps kept non-decreasing) */
        fnav_real_t sample_s;  /**< std of the sampling-instant error, s (stamps nominal) */
    } jitter;
    struct { fnav_real_t prob; } dropout;   /**< probability that a sample is lost */
    struct { fnav_real_t prob; } duplicate; /**< probability that a sample is delivered twice */
    struct { fnav_real_t factor; } alias;   /**< internal rate / output rate (integer >= 2) */
} fnav_imuerr_config_t;

/** Defaults: seed 1, 100 Hz, oversample 1, every effect off, parameters
 *  at the values listed in docs/simulator.md. */
extern const fnav_imuerr_config_t fnav_imuerr_config_default;

/** Parameter flags. */
#define FNAV_PARAM_PER_CHANNEL 0x01u /**< an array of 6, one value per channel */
#define FNAV_PARAM_LOG 0x02u         /**< positive scale parameter: fit in log space */
#define FNAV_PARAM_INTEGER 0x04u     /**< integer valued (or a 0/1 switch) */
#define FNAV_PARAM_NUISANCE 0x08u    /**< not worth fitting by itself (phase, band edges) */

/** Description of one parameter (for parsing, fitting and documentation). */
typedef struct {
    const char *name;   /**< "lsb" */
    const char *unit;   /**< "u" = the channel's unit (m/s^2 or rad/s), or "s", "Hz", ... */
    uint16_t offset;    /**< byte offset of the value (or array) in fnav_imuerr_config_t */
    uint8_t flags;      /**< FNAV_PARAM_* */
    double lo, hi;      /**< valid range, inclusive (checked by init for enabled effects) */
} fnav_effect_param_t;

/** Description of one effect. */
typedef struct {
    const char *name;    /**< "quant" */
    const char *brief;   /**< one line */
    uint8_t allowed;     /**< channels it may apply to */
    uint8_t nparams;
    const fnav_effect_param_t *params;
} fnav_effect_info_t;

/** Description of an effect, or NULL for an invalid id. */
const fnav_effect_info_t *fnav_imuerr_effect_info(fnav_effect_id_t id);
/** Effect by name ("quant"); FNAV_EFFECT_COUNT when unknown. */
fnav_effect_id_t fnav_imuerr_effect_find(const char *name);
/** Index of a parameter of an effect by name, or -1. */
int fnav_imuerr_param_find(fnav_effect_id_t id, const char *name);

/** Switch an effect on for the channels in ch_mask (limited to the
 *  channels it allows; scalar-only effects become FNAV_CH_ALL).
 *  @return FNAV_OK, FNAV_E_ARG for a bad id or an empty resulting mask. */
FNAV_WARN_UNUSED fnav_status_t fnav_imuerr_enable(fnav_imuerr_config_t *cfg, fnav_effect_id_t id, uint32_t ch_mask);
/** Switch an effect off (its parameters are kept). */
void fnav_imuerr_disable(fnav_imuerr_config_t *cfg, fnav_effect_id_t id);
/** Put every parameter of an effect back to its default (mask unchanged). */
void fnav_imuerr_effect_reset(fnav_imuerr_config_t *cfg, fnav_effect_id_t id);

/** Set parameter `param` of effect `id` on the channels of ch_mask (a
 *  scalar parameter ignores the mask). @return FNAV_OK, FNAV_E_ARG for a
 *  bad id / index, FNAV_E_RANGE for a value outside [lo, hi] or non-finite,
 *  FNAV_E_CONFIG (fnav_imuerr_init's status for it) for a value that is not
 *  whole for a FNAV_PARAM_INTEGER parameter; nothing is set on an error. */
FNAV_WARN_UNUSED fnav_status_t fnav_imuerr_param_set(fnav_imuerr_config_t *cfg, fnav_effect_id_t id, int param,
                                                     uint32_t ch_mask, fnav_real_t value);
/** Value of a parameter on channel ch (ignored for scalars); 0 for bad ids. */
fnav_real_t fnav_imuerr_param_get(const fnav_imuerr_config_t *cfg, fnav_effect_id_t id, int param, int ch);

/** Fill the baseline (white + AR(1), both enabled on every channel) from a
 *  sensor profile; other fields are left as they are.
 *  @return FNAV_OK, FNAV_E_ARG on NULL, FNAV_E_CONFIG on an invalid profile. */
FNAV_WARN_UNUSED fnav_status_t fnav_imuerr_config_from_profile(fnav_imuerr_config_t *cfg, const fnav_profile_t *p);

/** Internal rate factor of the signal stage: alias.factor when `alias` is on,
 *  else oversample. 1 for NULL, an alias.factor outside [2, 1024] or not
 *  finite, and an oversample outside 1 .. 1024 (fnav_imuerr_init refuses
 *  those; a non-whole factor in range, refused too, is rounded). */
uint32_t fnav_imuerr_internal_factor(const fnav_imuerr_config_t *cfg);

/* ---------------------------------------------------------------- model */

/** The error model (caller-owned, about 2.3 kB in float). */
typedef struct {
    fnav_imuerr_config_t cfg;
    fnav_rng_t rng[FNAV_EFFECT_COUNT];     /**< one stream per effect */
    fnav_real_t dt_s;                      /**< output period, s */
    fnav_real_t dt_int_s;                  /**< signal-stage period, s */
    uint32_t factor;                       /**< internal rate factor */
    uint32_t k;                            /**< sensor steps so far */
    /* derived coefficients */
    fnav_real_t white_std[6];              /**< per-sample std, u */
    fnav_real_t ar1_omc[6], ar1_drive[6];  /**< 1 - c and sqrt of eq. (4) */
    fnav_real_t flk_omc[FNAV_IMUERR_FLICKER_POLES];
    fnav_real_t flk_drive[6][FNAV_IMUERR_FLICKER_POLES];
    fnav_real_t rrw_step[6];               /**< K sqrt(dt) */
    fnav_real_t jump_p[6];                 /**< step probability per sample */
    fnav_real_t vib_dphi[6];               /**< phase increment per signal step, rad */
    /* state (value + compensation of a Kahan sum where small increments matter) */
    fnav_real_t ar1_b[6], ar1_c[6];
    fnav_real_t flk_b[6][FNAV_IMUERR_FLICKER_POLES], flk_c[6][FNAV_IMUERR_FLICKER_POLES];
    fnav_real_t rrw_b[6], rrw_c[6];
    fnav_real_t jump_b[6];
    fnav_real_t vib_phase[6];
    fnav_real_t quant_res[6];
    fnav_real_t temp_c;                    /**< temperature of the last sensor step */
    fnav_real_t bias[6];                   /**< additive bias of the last sensor step, u */
    fnav_real_t last_stamp_off_s;          /**< time-stamp offset of the last emitted tick */
    uint32_t ticks_since_emit;             /**< ticks since the last emitted sample */
    uint32_t emitted;                      /**< a sample was emitted already */
} fnav_imuerr_t;

/** What happens at one nominal output tick (fnav_imuerr_tick). */
typedef struct {
    uint32_t count;              /**< samples delivered: 0 dropped, 1, or 2 duplicated */
    fnav_real_t sample_off_s;    /**< sampling-instant offset from the nominal tick, s */
    fnav_real_t stamp_off_s;     /**< time-stamp offset from the nominal tick, s */
} fnav_imuerr_tick_t;

/** fnav_imuerr_init() with the caller's FNAV_BUILD_TAG, sizeof(fnav_imuerr_t) and sizeof(fnav_imuerr_config_t)
 *  (call fnav_imuerr_init(), which passes them): FNAV_E_BUILD, *e not written, when one is not
 *  the library's. */
FNAV_WARN_UNUSED fnav_status_t fnav_imuerr_init_tagged(fnav_imuerr_t *e, const fnav_imuerr_config_t *cfg,
                                                       uint64_t build_tag, size_t obj_size, size_t cfg_size);

/**
 * Validate a configuration and initialise the model: seed every stream,
 * draw the stationary initial AR(1) and flicker states.
 * @return FNAV_OK, FNAV_E_ARG on NULL, FNAV_E_CONFIG when an enabled
 *         effect has a parameter outside its range, or rate_hz is not
 *         positive and finite with a finite period 1 / rate_hz, or
 *         oversample is outside 1 .. 1024 (object untouched).
 *         FNAV_E_BUILD when this file was compiled with other layout options or layout-changing flags
 *         than the library (FNAV_BUILD_TAG and the struct sizes, fnav_types.h; an inline function passes
 *         them): nothing written.
 */
static inline FNAV_WARN_UNUSED fnav_status_t fnav_imuerr_init(fnav_imuerr_t *e, const fnav_imuerr_config_t *cfg)
{
    return fnav_imuerr_init_tagged(e, cfg, FNAV_BUILD_TAG, sizeof(fnav_imuerr_t), sizeof(fnav_imuerr_config_t));
}

/**
 * Signal stage, once per internal sample (period dt_int_s): y = the true
 * signal with scale factor, misalignment, g-sensitivity, vibration and
 * sensing-element saturation.
 * @param f_b  true specific force, body frame, m/s^2
 * @param w_b  true angular rate, body frame, rad/s
 * @param y    out: 6 channels
 */
void fnav_imuerr_signal(fnav_imuerr_t *e, const fnav_real_t f_b[3], const fnav_real_t w_b[3],
                        fnav_real_t y[FNAV_IMUERR_NCH]);

/**
 * Index of the internal sample the next fnav_imuerr_signal() call is for,
 * counted from the output's t = 0 (negative for the past an anti-alias
 * filter needs; fnav_imuerr_init() sets 0). Only the vibration tone
 * depends on it: its phase is phase_rad at index 0, whatever the
 * oversampling and the filter.
 */
void fnav_imuerr_signal_index(fnav_imuerr_t *e, int32_t n);

/**
 * Sensor stage, once per output sample (period dt_s), in place: advances
 * every bias process one step, adds the bias and the white noise, clips at
 * full scale and quantises.
 */
void fnav_imuerr_sensor(fnav_imuerr_t *e, fnav_real_t y[FNAV_IMUERR_NCH]);

/**
 * Both stages on one sample in place (internal rate = output rate): the
 * sample holds the truth on entry and the measurement on return; with the
 * thermal effect on, temp_c is set and FNAV_SAMPLE_HAS_TEMP raised.
 * Timing effects are not applied (see fnav_imuerr_tick).
 * @return FNAV_OK, FNAV_E_NANINF for a non-finite input (sample unchanged,
 *         model not advanced), FNAV_E_ARG for a NULL model or sample.
 */
FNAV_WARN_UNUSED fnav_status_t fnav_imuerr_apply(fnav_imuerr_t *e, fnav_sample_t *s);

/** Timing of the next nominal output tick: dropout / duplicate / jitter.
 *  Time stamps of delivered samples never go backwards. */
void fnav_imuerr_tick(fnav_imuerr_t *e, fnav_imuerr_tick_t *tick);

/** Additive bias of the last sensor step per channel (offset, AR(1),
 *  flicker, rrw, ramp, thermal, jumps; without white noise), u. */
void fnav_imuerr_bias(const fnav_imuerr_t *e, fnav_real_t bias[FNAV_IMUERR_NCH]);

#ifdef __cplusplus
}
#endif

#endif /* FNAV_IMUERR_H */
