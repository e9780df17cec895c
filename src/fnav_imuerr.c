/* Per-sample IMU error model and effect catalogue (see fnav_imuerr.h and
 * docs/simulator.md for every effect's model and signature). */
#include "footnav/fnav_imuerr.h"

#include "footnav/fnav_port.h"

#if FNAV_USE_DOUBLE
static inline fnav_real_t fnav_expm1_(fnav_real_t x) { return expm1(x); }
#else
static inline fnav_real_t fnav_expm1_(fnav_real_t x) { return expm1f(x); }
#endif

#define TWO_PI (FNAV_R(2.0) * FNAV_PI)

/* ================================================================== RNG */

/* splitmix64 (Steele, Lea & Flood 2014), used only to fill the state. */
static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void fnav_rng_seed(fnav_rng_t *r, uint32_t seed, uint32_t stream)
{
    uint64_t x = ((uint64_t)seed << 32) | (uint64_t)stream;
    uint64_t a, b;
    FNAV_ASSERT(r != NULL);
    a = splitmix64(&x);
    b = splitmix64(&x);
    r->s[0] = (uint32_t)a;
    r->s[1] = (uint32_t)(a >> 32);
    r->s[2] = (uint32_t)b;
    r->s[3] = (uint32_t)(b >> 32);
    if ((r->s[0] | r->s[1] | r->s[2] | r->s[3]) == 0u) {
        r->s[0] = 1u; /* the all-zero state is the one fixed point */
    }
    r->spare = FNAV_R(0.0);
    r->has_spare = 0;
}

static inline uint32_t rotl32(uint32_t x, int k)
{
    return (x << k) | (x >> (32 - k));
}

/* xoshiro128+ 1.0 (Blackman & Vigna 2018): the upper bits are used for
 * floating point, where it is the recommended generator of the family. */
uint32_t fnav_rng_u32(fnav_rng_t *r)
{
    const uint32_t result = r->s[0] + r->s[3];
    const uint32_t t = r->s[1] << 9;
    r->s[2] ^= r->s[0];
    r->s[3] ^= r->s[1];
    r->s[1] ^= r->s[2];
    r->s[0] ^= r->s[3];
    r->s[2] ^= t;
    r->s[3] = rotl32(r->s[3], 11);
    return result;
}

fnav_real_t fnav_rng_uniform(fnav_rng_t *r)
{
#if FNAV_USE_DOUBLE
    uint32_t a = fnav_rng_u32(r) >> 5; /* 27 bits */
    uint32_t b = fnav_rng_u32(r) >> 6; /* 26 bits */
    return ((fnav_real_t)a * 67108864.0 + (fnav_real_t)b) * (1.0 / 9007199254740992.0);
#else
    return (fnav_real_t)(fnav_rng_u32(r) >> 8) * FNAV_R(5.9604644775390625e-8); /* 2^-24 */
#endif
}

/* Box-Muller (Box & Muller 1958): bounded work, no rejection loop. */
fnav_real_t fnav_rng_gauss(fnav_rng_t *r)
{
    fnav_real_t u1, u2, rad;
    if (r->has_spare) {
        r->has_spare = 0;
        return r->spare;
    }
    u1 = FNAV_R(1.0) - fnav_rng_uniform(r); /* (0, 1] */
    u2 = fnav_rng_uniform(r);
    rad = fnav_sqrt(-FNAV_R(2.0) * fnav_log(u1));
    r->spare = rad * fnav_sin(TWO_PI * u2);
    r->has_spare = 1;
    return rad * fnav_cos(TWO_PI * u2);
}

/* ============================================================ catalogue */

#define OFF(member) ((uint16_t)offsetof(fnav_imuerr_config_t, member))
#define PC FNAV_PARAM_PER_CHANNEL
#define LG FNAV_PARAM_LOG
#define IN FNAV_PARAM_INTEGER
#define NU FNAV_PARAM_NUISANCE

static const fnav_effect_param_t k_white[] = {
    { "density", "u/sqrt(Hz)", OFF(white.density), PC | LG, 0.0, 1e3 },
};
static const fnav_effect_param_t k_ar1[] = {
    { "tau_s", "s", OFF(ar1.tau_s), PC | LG, 1e-3, 1e9 },
    { "sigma", "u", OFF(ar1.sigma), PC | LG, 0.0, 1e3 },
};
static const fnav_effect_param_t k_offset[] = {
    { "value", "u", OFF(offset.value), PC, -1e3, 1e3 },
};
static const fnav_effect_param_t k_quant[] = {
    { "lsb", "u", OFF(quant.lsb), PC | LG, 1e-12, 1e3 },
    { "shaped", "0/1", OFF(quant.shaped), PC | IN | NU, 0.0, 1.0 },
};
static const fnav_effect_param_t k_flicker[] = {
    { "b", "u", OFF(flicker.b), PC | LG, 0.0, 1e3 },
    { "tau_lo_s", "s", OFF(flicker.tau_lo_s), LG | NU, 1e-3, 1e8 },
    { "tau_hi_s", "s", OFF(flicker.tau_hi_s), LG | NU, 1e-3, 1e8 },
};
static const fnav_effect_param_t k_rrw[] = {
    { "k", "u/sqrt(s)", OFF(rrw.k), PC | LG, 0.0, 1e3 },
};
static const fnav_effect_param_t k_ramp[] = {
    { "rate", "u/s", OFF(ramp.rate), PC, -1e3, 1e3 },
};
static const fnav_effect_param_t k_thermal[] = {
    { "coef", "u/degC", OFF(thermal.coef), PC, -1e3, 1e3 },
    { "rise_c", "degC", OFF(thermal.rise_c), NU, -200.0, 200.0 },
    { "tau_s", "s", OFF(thermal.tau_s), LG, 1e-3, 1e9 },
    { "t0_c", "degC", OFF(thermal.t0_c), NU, -100.0, 200.0 },
};
static const fnav_effect_param_t k_vibration[] = {
    { "amp", "u", OFF(vibration.amp), PC | LG, 0.0, 1e4 },
    { "freq_hz", "Hz", OFF(vibration.freq_hz), PC, 0.0, 1e6 },
    { "phase_rad", "rad", OFF(vibration.phase_rad), PC | NU, -1e3, 1e3 },
};
static const fnav_effect_param_t k_jumps[] = {
    { "rate_hz", "1/s", OFF(jumps.rate_hz), PC | LG, 0.0, 1e6 },
    { "amp", "u", OFF(jumps.amp), PC | LG, 0.0, 1e3 },
};
static const fnav_effect_param_t k_saturation[] = {
    { "range", "u", OFF(saturation.range), PC | LG, 1e-9, 1e6 },
};
static const fnav_effect_param_t k_scale[] = {
    { "sf", "1", OFF(scale.sf), PC, -0.9, 10.0 },
};
static const fnav_effect_param_t k_misalign[] = {
    { "from_x", "1", OFF(misalign.from_x), PC, -1.0, 1.0 },
    { "from_y", "1", OFF(misalign.from_y), PC, -1.0, 1.0 },
    { "from_z", "1", OFF(misalign.from_z), PC, -1.0, 1.0 },
};
static const fnav_effect_param_t k_gsens[] = {
    { "from_x", "rad/s per m/s^2", OFF(gsens.from_x), PC, -1.0, 1.0 },
    { "from_y", "rad/s per m/s^2", OFF(gsens.from_y), PC, -1.0, 1.0 },
    { "from_z", "rad/s per m/s^2", OFF(gsens.from_z), PC, -1.0, 1.0 },
};
static const fnav_effect_param_t k_jitter[] = {
    { "stamp_s", "s", OFF(jitter.stamp_s), LG, 0.0, 10.0 },
    { "sample_s", "s", OFF(jitter.sample_s), LG, 0.0, 10.0 },
};
static const fnav_effect_param_t k_dropout[] = {
    { "prob", "1", OFF(dropout.prob), LG, 0.0, 1.0 },
};
static const fnav_effect_param_t k_duplicate[] = {
    { "prob", "1", OFF(duplicate.prob), LG, 0.0, 1.0 },
};
static const fnav_effect_param_t k_alias[] = {
    { "factor", "1", OFF(alias.factor), IN, 2.0, 1024.0 },
};

#define NP(a) ((uint8_t)(sizeof(a) / sizeof((a)[0])))

static const fnav_effect_info_t k_effects[FNAV_EFFECT_COUNT] = {
    { "white", "white noise (paper eq. 2)", FNAV_CH_ALL, NP(k_white), k_white },
    { "ar1", "AR(1) / Gauss-Markov bias (paper eqs. 3, 4)", FNAV_CH_ALL, NP(k_ar1), k_ar1 },
    { "offset", "constant bias", FNAV_CH_ALL, NP(k_offset), k_offset },
    { "quant", "quantisation of the output", FNAV_CH_ALL, NP(k_quant), k_quant },
    { "flicker", "1/f bias instability", FNAV_CH_ALL, NP(k_flicker), k_flicker },
    { "rrw", "rate random walk", FNAV_CH_ALL, NP(k_rrw), k_rrw },
    { "ramp", "bias drift ramp in time", FNAV_CH_ALL, NP(k_ramp), k_ramp },
    { "thermal", "bias drift with a warm-up temperature", FNAV_CH_ALL, NP(k_thermal), k_thermal },
    { "vibration", "sinusoidal vibration (motor tone)", FNAV_CH_ALL, NP(k_vibration), k_vibration },
    { "jumps", "random bias steps", FNAV_CH_ALL, NP(k_jumps), k_jumps },
    { "saturation", "clipping at full scale", FNAV_CH_ALL, NP(k_saturation), k_saturation },
    { "scale", "scale-factor error", FNAV_CH_ALL, NP(k_scale), k_scale },
    { "misalign", "axis misalignment / cross-coupling", FNAV_CH_ALL, NP(k_misalign), k_misalign },
    { "gsens", "gyro g-sensitivity", FNAV_CH_GYRO, NP(k_gsens), k_gsens },
    { "jitter", "timing jitter (time stamps, sampling instants)", FNAV_CH_ALL, NP(k_jitter), k_jitter },
    { "dropout", "dropped samples", FNAV_CH_ALL, NP(k_dropout), k_dropout },
    { "duplicate", "duplicated samples", FNAV_CH_ALL, NP(k_duplicate), k_duplicate },
    { "alias", "sampling without an anti-alias filter", FNAV_CH_ALL, NP(k_alias), k_alias },
};

/* Default parameters (docs/simulator.md): magnitudes typical of a consumer
 * MEMS IMU, each well above what a one-hour static log can detect. White
 * and AR(1) are the NavChip x rows of paper Table IV. */
#define D2R(x) ((x) * FNAV_R(0.017453292519943295))
const fnav_imuerr_config_t fnav_imuerr_config_default = {
    1u,             /* seed */
    FNAV_R(100.0),  /* rate_hz */
    1u,             /* oversample */
    { 0u },         /* mask: every effect off */
    { { FNAV_R(7.4e-4), FNAV_R(7.4e-4), FNAV_R(7.4e-4), D2R(FNAV_R(3.3e-3)), D2R(FNAV_R(3.3e-3)),
        D2R(FNAV_R(3.3e-3)) } },
    { { FNAV_R(10.0), FNAV_R(10.0), FNAV_R(10.0), FNAV_R(5.0), FNAV_R(5.0), FNAV_R(5.0) },
      { FNAV_R(1.3e-5), FNAV_R(1.3e-5), FNAV_R(1.3e-5), D2R(FNAV_R(8.5e-5)), D2R(FNAV_R(8.5e-5)),
        D2R(FNAV_R(8.5e-5)) } },
    { { FNAV_R(0.05), FNAV_R(0.05), FNAV_R(0.05), FNAV_R(0.005), FNAV_R(0.005), FNAV_R(0.005) } },
    /* quant: 16 bits over +-16 g and +-2000 deg/s */
    { { FNAV_R(4.788e-3), FNAV_R(4.788e-3), FNAV_R(4.788e-3), FNAV_R(1.0653e-3), FNAV_R(1.0653e-3),
        FNAV_R(1.0653e-3) },
      { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0) } },
    { { FNAV_R(2.0e-4), FNAV_R(2.0e-4), FNAV_R(2.0e-4), FNAV_R(5.0e-5), FNAV_R(5.0e-5), FNAV_R(5.0e-5) },
      FNAV_R(0.5), FNAV_R(5000.0) },
    { { FNAV_R(1.0e-4), FNAV_R(1.0e-4), FNAV_R(1.0e-4), FNAV_R(1.0e-5), FNAV_R(1.0e-5), FNAV_R(1.0e-5) } },
    { { FNAV_R(1.0e-5), FNAV_R(1.0e-5), FNAV_R(1.0e-5), FNAV_R(1.0e-6), FNAV_R(1.0e-6), FNAV_R(1.0e-6) } },
    { { FNAV_R(2.0e-3), FNAV_R(2.0e-3), FNAV_R(2.0e-3), FNAV_R(2.0e-4), FNAV_R(2.0e-4), FNAV_R(2.0e-4) },
      FNAV_R(10.0), FNAV_R(600.0), FNAV_R(25.0) },
    { { FNAV_R(0.2), FNAV_R(0.2), FNAV_R(0.2), FNAV_R(0.02), FNAV_R(0.02), FNAV_R(0.02) },
      { FNAV_R(37.0), FNAV_R(37.0), FNAV_R(37.0), FNAV_R(37.0), FNAV_R(37.0), FNAV_R(37.0) },
      { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0) } },
    { { FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01) },
      { FNAV_R(0.02), FNAV_R(0.02), FNAV_R(0.02), FNAV_R(0.002), FNAV_R(0.002), FNAV_R(0.002) } },
    /* saturation: +-16 g, +-2000 deg/s */
    { { FNAV_R(156.9064), FNAV_R(156.9064), FNAV_R(156.9064), FNAV_R(34.906585), FNAV_R(34.906585),
        FNAV_R(34.906585) } },
    { { FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01), FNAV_R(0.01) } },
    { { FNAV_R(0.0), FNAV_R(0.005), FNAV_R(0.005), FNAV_R(0.0), FNAV_R(0.005), FNAV_R(0.005) },
      { FNAV_R(0.005), FNAV_R(0.0), FNAV_R(0.005), FNAV_R(0.005), FNAV_R(0.0), FNAV_R(0.005) },
      { FNAV_R(0.005), FNAV_R(0.005), FNAV_R(0.0), FNAV_R(0.005), FNAV_R(0.005), FNAV_R(0.0) } },
    /* gsens: 0.1 deg/s per g on every gyro axis */
    { { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(1.78e-4), FNAV_R(1.78e-4), FNAV_R(1.78e-4) },
      { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(1.78e-4), FNAV_R(1.78e-4), FNAV_R(1.78e-4) },
      { FNAV_R(0.0), FNAV_R(0.0), FNAV_R(0.0), FNAV_R(1.78e-4), FNAV_R(1.78e-4), FNAV_R(1.78e-4) } },
    { FNAV_R(5.0e-4), FNAV_R(0.0) },
    { FNAV_R(0.01) },
    { FNAV_R(0.01) },
    { FNAV_R(4.0) },
};

static int str_eq(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

const fnav_effect_info_t *fnav_imuerr_effect_info(fnav_effect_id_t id)
{
    if ((unsigned)id >= (unsigned)FNAV_EFFECT_COUNT) {
        return NULL;
    }
    return &k_effects[id];
}

fnav_effect_id_t fnav_imuerr_effect_find(const char *name)
{
    int i;
    if (name == NULL) {
        return FNAV_EFFECT_COUNT;
    }
    for (i = 0; i < (int)FNAV_EFFECT_COUNT; i++) {
        if (str_eq(name, k_effects[i].name)) {
            return (fnav_effect_id_t)i;
        }
    }
    return FNAV_EFFECT_COUNT;
}

int fnav_imuerr_param_find(fnav_effect_id_t id, const char *name)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info(id);
    int i;
    if (info == NULL || name == NULL) {
        return -1;
    }
    for (i = 0; i < info->nparams; i++) {
        if (str_eq(name, info->params[i].name)) {
            return i;
        }
    }
    return -1;
}

static int is_scalar_effect(const fnav_effect_info_t *info)
{
    int i;
    for (i = 0; i < info->nparams; i++) {
        if ((info->params[i].flags & FNAV_PARAM_PER_CHANNEL) != 0u) {
            return 0;
        }
    }
    return 1;
}

fnav_status_t fnav_imuerr_enable(fnav_imuerr_config_t *cfg, fnav_effect_id_t id, uint32_t ch_mask)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info(id);
    uint32_t m;
    if (cfg == NULL || info == NULL) {
        return FNAV_E_ARG;
    }
    m = is_scalar_effect(info) ? ((ch_mask != 0u) ? FNAV_CH_ALL : 0u) : (ch_mask & info->allowed);
    if (m == 0u) {
        return FNAV_E_ARG;
    }
    cfg->mask[id] = (uint8_t)(cfg->mask[id] | m);
    return FNAV_OK;
}

void fnav_imuerr_disable(fnav_imuerr_config_t *cfg, fnav_effect_id_t id)
{
    if (cfg != NULL && (unsigned)id < (unsigned)FNAV_EFFECT_COUNT) {
        cfg->mask[id] = 0u;
    }
}

static fnav_real_t *param_ptr(fnav_imuerr_config_t *cfg, const fnav_effect_param_t *p)
{
    return (fnav_real_t *)(void *)((char *)cfg + p->offset);
}

static const fnav_real_t *param_cptr(const fnav_imuerr_config_t *cfg, const fnav_effect_param_t *p)
{
    return (const fnav_real_t *)(const void *)((const char *)cfg + p->offset);
}

void fnav_imuerr_effect_reset(fnav_imuerr_config_t *cfg, fnav_effect_id_t id)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info(id);
    int i, c;
    if (cfg == NULL || info == NULL) {
        return;
    }
    for (i = 0; i < info->nparams; i++) {
        const fnav_effect_param_t *p = &info->params[i];
        int n = (p->flags & FNAV_PARAM_PER_CHANNEL) ? FNAV_IMUERR_NCH : 1;
        fnav_real_t *dst = param_ptr(cfg, p);
        const fnav_real_t *src = param_cptr(&fnav_imuerr_config_default, p);
        for (c = 0; c < n; c++) {
            dst[c] = src[c];
        }
    }
}

static int in_range(const fnav_effect_param_t *p, fnav_real_t v)
{
    /* against the bounds in the value's own precision: in float, 1e-9 and
     * 1e-12 round below the double bounds of the same name, and the
     * documented inclusive ends would be refused) */
    return fnav_isfinite(v) && v >= (fnav_real_t)p->lo && v <= (fnav_real_t)p->hi;
}

fnav_status_t fnav_imuerr_param_set(fnav_imuerr_config_t *cfg, fnav_effect_id_t id, int param, uint32_t ch_mask,
                                    fnav_real_t value)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info(id);
    const fnav_effect_param_t *p;
    fnav_real_t *dst;
    int c;
    if (cfg == NULL || info == NULL || param < 0 || param >= info->nparams) {
        return FNAV_E_ARG;
    }
    p = &info->params[param];
    if (!in_range(p, value)) {
        return FNAV_E_RANGE;
    }
    if ((p->flags & FNAV_PARAM_INTEGER) != 0u && value != fnav_floor(value)) {
        /* init's refusal of the same value (validate), given here at once
         * rather than only when init sees the configuration */
        return FNAV_E_CONFIG;
    }
    dst = param_ptr(cfg, p);
    if ((p->flags & FNAV_PARAM_PER_CHANNEL) == 0u) {
        dst[0] = value;
        return FNAV_OK;
    }
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        if ((ch_mask & (1u << c)) != 0u) {
            dst[c] = value;
        }
    }
    return FNAV_OK;
}

fnav_real_t fnav_imuerr_param_get(const fnav_imuerr_config_t *cfg, fnav_effect_id_t id, int param, int ch)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info(id);
    const fnav_effect_param_t *p;
    if (cfg == NULL || info == NULL || param < 0 || param >= info->nparams) {
        return FNAV_R(0.0);
    }
    p = &info->params[param];
    if ((p->flags & FNAV_PARAM_PER_CHANNEL) == 0u) {
        return param_cptr(cfg, p)[0];
    }
    if (ch < 0 || ch >= FNAV_IMUERR_NCH) {
        return FNAV_R(0.0);
    }
    return param_cptr(cfg, p)[ch];
}

fnav_status_t fnav_imuerr_config_from_profile(fnav_imuerr_config_t *cfg, const fnav_profile_t *p)
{
    int i;
    if (cfg == NULL || p == NULL) {
        return FNAV_E_ARG;
    }
    if (fnav_profile_validate(p) != FNAV_OK) {
        return FNAV_E_CONFIG;
    }
    {
        /* the catalogue's ranges of white and ar1 (a correlation time under
         * 1 ms passing here would be refused only by init, and the harness
         * would blame --effect options never given) */
        fnav_imuerr_config_t t = *cfg;
        int id, k, c;
        for (i = 0; i < 3; i++) {
            t.white.density[i] = p->accel_noise_mps2_rthz[i];
            t.white.density[3 + i] = p->gyro_noise_rps_rthz[i];
            t.ar1.tau_s[i] = p->accel_tau_s[i];
            t.ar1.tau_s[3 + i] = p->gyro_tau_s[i];
            t.ar1.sigma[i] = p->accel_bias_sigma_mps2[i];
            t.ar1.sigma[3 + i] = p->gyro_bias_sigma_rps[i];
        }
        for (id = FNAV_EFFECT_WHITE; id <= FNAV_EFFECT_AR1; id++) {
            const fnav_effect_info_t *info = &k_effects[id];
            for (k = 0; k < info->nparams; k++) {
                const fnav_real_t *v = param_cptr(&t, &info->params[k]);
                for (c = 0; c < FNAV_IMUERR_NCH; c++) {
                    if (!in_range(&info->params[k], v[c])) {
                        return FNAV_E_CONFIG;
                    }
                }
            }
        }
    }
    for (i = 0; i < 3; i++) {
        cfg->white.density[i] = p->accel_noise_mps2_rthz[i];
        cfg->white.density[3 + i] = p->gyro_noise_rps_rthz[i];
        cfg->ar1.tau_s[i] = p->accel_tau_s[i];
        cfg->ar1.tau_s[3 + i] = p->gyro_tau_s[i];
        cfg->ar1.sigma[i] = p->accel_bias_sigma_mps2[i];
        cfg->ar1.sigma[3 + i] = p->gyro_bias_sigma_rps[i];
    }
    cfg->mask[FNAV_EFFECT_WHITE] = (uint8_t)FNAV_CH_ALL;
    cfg->mask[FNAV_EFFECT_AR1] = (uint8_t)FNAV_CH_ALL;
    return FNAV_OK;
}

uint32_t fnav_imuerr_internal_factor(const fnav_imuerr_config_t *cfg)
{
    if (cfg == NULL) {
        return 1u;
    }
    if (cfg->mask[FNAV_EFFECT_ALIAS] != 0u) {
        /* inside the catalogue's range before the conversion: NaN, a
         * negative factor or one above 2^32 make it undefined behaviour
         * (test_imuerr test_catalogue_names_and_params) */
        const fnav_effect_param_t *p = &k_alias[0];
        if (!(cfg->alias.factor >= (fnav_real_t)p->lo && cfg->alias.factor <= (fnav_real_t)p->hi)) {
            return 1u;
        }
        return (uint32_t)(cfg->alias.factor + FNAV_R(0.5));
    }
    return (cfg->oversample >= 1u && cfg->oversample <= 1024u) ? cfg->oversample : 1u;
}

/* ================================================================ model */

static int on(const fnav_imuerr_t *e, fnav_effect_id_t id, int ch)
{
    return (e->cfg.mask[id] & (1u << ch)) != 0u;
}

/* Every parameter of every enabled effect in range, plus the cross-field
 * rules that a range cannot express. */
static fnav_status_t validate(const fnav_imuerr_config_t *cfg)
{
    int id, i, c;
    /* the period 1 / rate_hz finite too: a subnormal float rate made it
     * Inf, the first step's time 0 * Inf NaN (test_imuerr
     * test_config_validation) */
    if (!fnav_isfinite(cfg->rate_hz) || !(cfg->rate_hz > FNAV_R(0.0)) ||
        !fnav_isfinite(FNAV_R(1.0) / cfg->rate_hz) || cfg->oversample < 1u || cfg->oversample > 1024u) {
        return FNAV_E_CONFIG;
    }
    for (id = 0; id < (int)FNAV_EFFECT_COUNT; id++) {
        const fnav_effect_info_t *info = &k_effects[id];
        if (cfg->mask[id] == 0u) {
            continue;
        }
        if ((cfg->mask[id] & ~info->allowed) != 0u) {
            return FNAV_E_CONFIG;
        }
        for (i = 0; i < info->nparams; i++) {
            const fnav_effect_param_t *p = &info->params[i];
            const fnav_real_t *v = param_cptr(cfg, p);
            if ((p->flags & FNAV_PARAM_PER_CHANNEL) == 0u) {
                if (!in_range(p, v[0])) {
                    return FNAV_E_CONFIG;
                }
                if ((p->flags & FNAV_PARAM_INTEGER) && v[0] != fnav_floor(v[0])) {
                    return FNAV_E_CONFIG;
                }
                continue;
            }
            for (c = 0; c < FNAV_IMUERR_NCH; c++) {
                if ((cfg->mask[id] & (1u << c)) == 0u) {
                    continue;
                }
                if (!in_range(p, v[c]) || ((p->flags & FNAV_PARAM_INTEGER) && v[c] != fnav_floor(v[c]))) {
                    return FNAV_E_CONFIG;
                }
            }
        }
    }
    /* misalignment: a channel's own axis is the scale factor's job */
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        const fnav_real_t *own[3];
        own[0] = cfg->misalign.from_x;
        own[1] = cfg->misalign.from_y;
        own[2] = cfg->misalign.from_z;
        if ((cfg->mask[FNAV_EFFECT_MISALIGN] & (1u << c)) && own[c % 3][c] != FNAV_R(0.0)) {
            return FNAV_E_CONFIG;
        }
    }
    if (cfg->mask[FNAV_EFFECT_FLICKER] != 0u && !(cfg->flicker.tau_lo_s < cfg->flicker.tau_hi_s)) {
        return FNAV_E_CONFIG;
    }
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        if ((cfg->mask[FNAV_EFFECT_JUMPS] & (1u << c)) && cfg->jumps.rate_hz[c] > cfg->rate_hz) {
            return FNAV_E_CONFIG; /* at most one step per sample */
        }
    }
    return FNAV_OK;
}

/* Kahan-compensated sum s += x: AR(1) and random-walk states take
 * increments far below one ulp of the state in float. */
static inline void kahan_add(fnav_real_t *s, fnav_real_t *comp, fnav_real_t x)
{
    fnav_real_t y = x - *comp;
    fnav_real_t t = *s + y;
    *comp = (t - *s) - y;
    *s = t;
}

/* Correlation times of the flicker poles, log-spaced over [lo, hi]. */
static fnav_real_t flicker_tau(const fnav_imuerr_config_t *cfg, int i)
{
    fnav_real_t r = fnav_log(cfg->flicker.tau_hi_s / cfg->flicker.tau_lo_s) /
                    (fnav_real_t)(FNAV_IMUERR_FLICKER_POLES - 1);
    return cfg->flicker.tau_lo_s * fnav_exp(r * (fnav_real_t)i);
}

fnav_status_t fnav_imuerr_init_tagged(fnav_imuerr_t *e, const fnav_imuerr_config_t *cfg, uint64_t build_tag,
                                      size_t obj_size, size_t cfg_size)
{
    fnav_status_t st;
    fnav_rng_t init_rng;
    int c, i;
    if (build_tag != FNAV_BUILD_TAG || obj_size != sizeof(fnav_imuerr_t) || cfg_size != sizeof(fnav_imuerr_config_t)) {
        return FNAV_E_BUILD; /* the caller's objects have another layout: write nothing */
    }
    if (e == NULL || cfg == NULL) {
        return FNAV_E_ARG;
    }
    st = validate(cfg);
    if (st != FNAV_OK) {
        return st;
    }
    e->cfg = *cfg;
    for (i = 0; i < (int)FNAV_EFFECT_COUNT; i++) {
        fnav_rng_seed(&e->rng[i], cfg->seed, (uint32_t)i + 1u);
    }
    e->factor = fnav_imuerr_internal_factor(cfg);
    e->dt_s = FNAV_R(1.0) / cfg->rate_hz;
    e->dt_int_s = e->dt_s / (fnav_real_t)e->factor;
    e->k = 0u;
    e->temp_c = cfg->thermal.t0_c;
    e->last_stamp_off_s = FNAV_R(0.0);
    e->ticks_since_emit = 0u;
    e->emitted = 0u;
    /* initial states come from streams of their own, so that the driving
     * noise sequences do not depend on whether a state was drawn */
    fnav_rng_seed(&init_rng, cfg->seed, 0x1000u);
    {
        /* white noise folded by sampling without anti-alias filter:
         * picking 1 in M samples of density N at M f_s gives N sqrt(M) */
        fnav_real_t fold = (cfg->mask[FNAV_EFFECT_ALIAS] != 0u) ? fnav_sqrt((fnav_real_t)e->factor) : FNAV_R(1.0);
        for (c = 0; c < FNAV_IMUERR_NCH; c++) {
            e->white_std[c] = cfg->white.density[c] * fnav_sqrt(cfg->rate_hz) * fold;
        }
    }
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        fnav_real_t tau = cfg->ar1.tau_s[c] > FNAV_R(0.0) ? cfg->ar1.tau_s[c] : FNAV_R(1.0);
        /* eq. (3): c = exp(-dt/tau); eq. (4): var(n) = sigma^2 (1 - exp(-2 dt/tau)) */
        e->ar1_omc[c] = -fnav_expm1_(-e->dt_s / tau);
        e->ar1_drive[c] = cfg->ar1.sigma[c] * fnav_sqrt(-fnav_expm1_(FNAV_R(-2.0) * e->dt_s / tau));
        /* stationary start: b_0 ~ N(0, sigma^2) */
        e->ar1_b[c] = cfg->ar1.sigma[c] * fnav_rng_gauss(&init_rng);
        e->ar1_c[c] = FNAV_R(0.0);
        e->rrw_step[c] = cfg->rrw.k[c] * fnav_sqrt(e->dt_s);
        e->rrw_b[c] = FNAV_R(0.0);
        e->rrw_c[c] = FNAV_R(0.0);
        e->jump_p[c] = -fnav_expm1_(-cfg->jumps.rate_hz[c] * e->dt_s);
        e->jump_b[c] = FNAV_R(0.0);
        e->vib_dphi[c] = TWO_PI * cfg->vibration.freq_hz[c] * e->dt_int_s;
        e->vib_phase[c] = cfg->vibration.phase_rad[c] - TWO_PI * fnav_floor(cfg->vibration.phase_rad[c] / TWO_PI);
        e->quant_res[c] = FNAV_R(0.0);
        e->bias[c] = FNAV_R(0.0);
    }
    /* flicker: 1/f from equal-variance AR(1) poles, one-sided PSD of the sum
     * ~ v / (f ln r) for pole ratio r, so v = B^2 ln r / pi gives B^2/(pi f),
     * i.e. IEEE Std 952's two-sided B^2/(2 pi f) (docs/simulator.md) */
    if (cfg->mask[FNAV_EFFECT_FLICKER] != 0u) {
        fnav_real_t lnr = fnav_log(cfg->flicker.tau_hi_s / cfg->flicker.tau_lo_s) /
                          (fnav_real_t)(FNAV_IMUERR_FLICKER_POLES - 1);
        for (i = 0; i < FNAV_IMUERR_FLICKER_POLES; i++) {
            fnav_real_t tau = flicker_tau(cfg, i);
            fnav_real_t omc2 = -fnav_expm1_(FNAV_R(-2.0) * e->dt_s / tau);
            e->flk_omc[i] = -fnav_expm1_(-e->dt_s / tau);
            for (c = 0; c < FNAV_IMUERR_NCH; c++) {
                fnav_real_t sd = cfg->flicker.b[c] * fnav_sqrt(lnr / FNAV_PI);
                e->flk_drive[c][i] = sd * fnav_sqrt(omc2);
                e->flk_b[c][i] = sd * fnav_rng_gauss(&init_rng);
                e->flk_c[c][i] = FNAV_R(0.0);
            }
        }
    } else {
        for (i = 0; i < FNAV_IMUERR_FLICKER_POLES; i++) {
            e->flk_omc[i] = FNAV_R(0.0);
            for (c = 0; c < FNAV_IMUERR_NCH; c++) {
                e->flk_drive[c][i] = FNAV_R(0.0);
                e->flk_b[c][i] = FNAV_R(0.0);
                e->flk_c[c][i] = FNAV_R(0.0);
            }
        }
    }
    return FNAV_OK;
}

static fnav_real_t clip(fnav_real_t x, fnav_real_t r)
{
    return fnav_clamp(x, -r, r);
}

void fnav_imuerr_signal_index(fnav_imuerr_t *e, int32_t n)
{
    int c;
    FNAV_ASSERT(e != NULL);
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        fnav_real_t ph = e->cfg.vibration.phase_rad[c] + e->vib_dphi[c] * (fnav_real_t)n;
        e->vib_phase[c] = ph - TWO_PI * fnav_floor(ph / TWO_PI);
    }
}

void fnav_imuerr_signal(fnav_imuerr_t *e, const fnav_real_t f_b[3], const fnav_real_t w_b[3],
                        fnav_real_t y[FNAV_IMUERR_NCH])
{
    fnav_real_t x[FNAV_IMUERR_NCH];
    int c;
    FNAV_ASSERT(e != NULL && f_b != NULL && w_b != NULL && y != NULL);
    for (c = 0; c < 3; c++) {
        x[c] = f_b[c];
        x[3 + c] = w_b[c];
    }
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        int s0 = (c < 3) ? 0 : 3; /* first channel of the same sensor */
        fnav_real_t v = x[c];
        if (on(e, FNAV_EFFECT_SCALE, c)) {
            v += e->cfg.scale.sf[c] * x[c];
        }
        if (on(e, FNAV_EFFECT_MISALIGN, c)) {
            v += e->cfg.misalign.from_x[c] * x[s0] + e->cfg.misalign.from_y[c] * x[s0 + 1] +
                 e->cfg.misalign.from_z[c] * x[s0 + 2];
        }
        if (on(e, FNAV_EFFECT_GSENS, c)) {
            v += e->cfg.gsens.from_x[c] * x[0] + e->cfg.gsens.from_y[c] * x[1] + e->cfg.gsens.from_z[c] * x[2];
        }
        if (on(e, FNAV_EFFECT_VIBRATION, c)) {
            v += e->cfg.vibration.amp[c] * fnav_sin(e->vib_phase[c]);
            e->vib_phase[c] += e->vib_dphi[c];
            if (e->vib_phase[c] >= TWO_PI) {
                e->vib_phase[c] -= TWO_PI * fnav_floor(e->vib_phase[c] / TWO_PI);
            }
        }
        if (on(e, FNAV_EFFECT_SATURATION, c)) {
            v = clip(v, e->cfg.saturation.range[c]);
        }
        y[c] = v;
    }
}

void fnav_imuerr_sensor(fnav_imuerr_t *e, fnav_real_t y[FNAV_IMUERR_NCH])
{
    fnav_real_t t_s, g;
    int c, i;
    FNAV_ASSERT(e != NULL && y != NULL);
    /* the k-th output sample (from 0) is the log's sample at t = k dt */
    t_s = (fnav_real_t)e->k * e->dt_s;
    e->k++;
    if (e->cfg.mask[FNAV_EFFECT_THERMAL] != 0u) {
        /* first-order warm-up T(t) = t0 + rise (1 - exp(-t/tau)) */
        e->temp_c = e->cfg.thermal.t0_c - e->cfg.thermal.rise_c * fnav_expm1_(-t_s / e->cfg.thermal.tau_s);
    }
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        fnav_real_t b = FNAV_R(0.0);
        /* Random draws are made for every channel of an enabled effect,
         * masked or not, so that a channel's sequence never depends on the
         * mask of another. */
        if (e->cfg.mask[FNAV_EFFECT_AR1] != 0u) {
            /* eq. (3): b_k = c b_(k-1) + n_k, written b += -(1-c) b + n */
            g = fnav_rng_gauss(&e->rng[FNAV_EFFECT_AR1]);
            kahan_add(&e->ar1_b[c], &e->ar1_c[c], -e->ar1_omc[c] * e->ar1_b[c] + e->ar1_drive[c] * g);
            if (on(e, FNAV_EFFECT_AR1, c)) {
                b += e->ar1_b[c];
            }
        }
        if (on(e, FNAV_EFFECT_OFFSET, c)) {
            b += e->cfg.offset.value[c];
        }
        if (e->cfg.mask[FNAV_EFFECT_FLICKER] != 0u) {
            fnav_real_t sum = FNAV_R(0.0);
            for (i = 0; i < FNAV_IMUERR_FLICKER_POLES; i++) {
                g = fnav_rng_gauss(&e->rng[FNAV_EFFECT_FLICKER]);
                kahan_add(&e->flk_b[c][i], &e->flk_c[c][i],
                          -e->flk_omc[i] * e->flk_b[c][i] + e->flk_drive[c][i] * g);
                sum += e->flk_b[c][i];
            }
            if (on(e, FNAV_EFFECT_FLICKER, c)) {
                b += sum;
            }
        }
        if (e->cfg.mask[FNAV_EFFECT_RRW] != 0u) {
            g = fnav_rng_gauss(&e->rng[FNAV_EFFECT_RRW]);
            kahan_add(&e->rrw_b[c], &e->rrw_c[c], e->rrw_step[c] * g);
            if (on(e, FNAV_EFFECT_RRW, c)) {
                b += e->rrw_b[c];
            }
        }
        if (on(e, FNAV_EFFECT_RAMP, c)) {
            b += e->cfg.ramp.rate[c] * t_s;
        }
        if (on(e, FNAV_EFFECT_THERMAL, c)) {
            b += e->cfg.thermal.coef[c] * (e->temp_c - e->cfg.thermal.t0_c);
        }
        if (e->cfg.mask[FNAV_EFFECT_JUMPS] != 0u) {
            fnav_real_t u = fnav_rng_uniform(&e->rng[FNAV_EFFECT_JUMPS]);
            g = fnav_rng_gauss(&e->rng[FNAV_EFFECT_JUMPS]);
            if (on(e, FNAV_EFFECT_JUMPS, c)) {
                if (u < e->jump_p[c]) {
                    e->jump_b[c] += e->cfg.jumps.amp[c] * g;
                }
                b += e->jump_b[c];
            }
        }
        e->bias[c] = b;
        if (e->cfg.mask[FNAV_EFFECT_WHITE] != 0u) {
            g = fnav_rng_gauss(&e->rng[FNAV_EFFECT_WHITE]);
            if (on(e, FNAV_EFFECT_WHITE, c)) {
                b += e->white_std[c] * g; /* eq. (2): e_k = b_k + v_k */
            }
        }
        y[c] += b; /* eq. (1): x_k = x_k,real + e_k */
        if (on(e, FNAV_EFFECT_SATURATION, c)) {
            y[c] = clip(y[c], e->cfg.saturation.range[c]);
        }
        if (on(e, FNAV_EFFECT_QUANT, c)) {
            fnav_real_t q = e->cfg.quant.lsb[c];
            fnav_real_t v = y[c];
            if (e->cfg.quant.shaped[c] != FNAV_R(0.0)) {
                v += e->quant_res[c];
            }
            y[c] = q * fnav_floor(v / q + FNAV_R(0.5));
            e->quant_res[c] = v - y[c];
            if (on(e, FNAV_EFFECT_SATURATION, c) && fnav_fabs(y[c]) > e->cfg.saturation.range[c]) {
                fnav_real_t top = q * fnav_floor(e->cfg.saturation.range[c] / q);
                y[c] = y[c] > FNAV_R(0.0) ? top : -top;
            }
        }
    }
}

fnav_status_t fnav_imuerr_apply(fnav_imuerr_t *e, fnav_sample_t *s)
{
    fnav_real_t y[FNAV_IMUERR_NCH];
    int c;
    if (e == NULL || s == NULL) {
        return FNAV_E_ARG;
    }
    for (c = 0; c < 3; c++) {
        if (!fnav_isfinite(s->accel_mps2[c]) || !fnav_isfinite(s->gyro_rps[c])) {
            return FNAV_E_NANINF;
        }
    }
    fnav_imuerr_signal(e, s->accel_mps2, s->gyro_rps, y);
    fnav_imuerr_sensor(e, y);
    for (c = 0; c < 3; c++) {
        s->accel_mps2[c] = y[c];
        s->gyro_rps[c] = y[3 + c];
    }
    if (e->cfg.mask[FNAV_EFFECT_THERMAL] != 0u) {
        s->temp_c = e->temp_c;
        s->flags |= FNAV_SAMPLE_HAS_TEMP;
    }
    return FNAV_OK;
}

void fnav_imuerr_tick(fnav_imuerr_t *e, fnav_imuerr_tick_t *tick)
{
    FNAV_ASSERT(e != NULL && tick != NULL);
    tick->count = 1u;
    tick->sample_off_s = FNAV_R(0.0);
    tick->stamp_off_s = FNAV_R(0.0);
    if (e->cfg.mask[FNAV_EFFECT_DROPOUT] != 0u) {
        if (fnav_rng_uniform(&e->rng[FNAV_EFFECT_DROPOUT]) < e->cfg.dropout.prob) {
            tick->count = 0u;
        }
    }
    if (e->cfg.mask[FNAV_EFFECT_DUPLICATE] != 0u) {
        if (fnav_rng_uniform(&e->rng[FNAV_EFFECT_DUPLICATE]) < e->cfg.duplicate.prob && tick->count == 1u) {
            tick->count = 2u;
        }
    }
    if (e->cfg.mask[FNAV_EFFECT_JITTER] != 0u) {
        fnav_real_t g1 = fnav_rng_gauss(&e->rng[FNAV_EFFECT_JITTER]);
        fnav_real_t g2 = fnav_rng_gauss(&e->rng[FNAV_EFFECT_JITTER]);
        tick->sample_off_s = e->cfg.jitter.sample_s * g1;
        tick->stamp_off_s = e->cfg.jitter.stamp_s * g2;
    }
    e->ticks_since_emit++;
    if (tick->count > 0u) {
        /* time stamps never go backwards: not before the previous one */
        if (e->emitted) {
            fnav_real_t prev = e->last_stamp_off_s - (fnav_real_t)e->ticks_since_emit * e->dt_s;
            if (tick->stamp_off_s < prev) {
                tick->stamp_off_s = prev;
            }
        }
        e->last_stamp_off_s = tick->stamp_off_s;
        e->ticks_since_emit = 0u;
        e->emitted = 1u;
    }
}

void fnav_imuerr_bias(const fnav_imuerr_t *e, fnav_real_t bias[FNAV_IMUERR_NCH])
{
    int c;
    FNAV_ASSERT(e != NULL && bias != NULL);
    for (c = 0; c < FNAV_IMUERR_NCH; c++) {
        bias[c] = e->bias[c];
    }
}
