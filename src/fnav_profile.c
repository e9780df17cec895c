/* Sensor error profiles and the paper's Tables IV-VI (see fnav_profile.h). */
#include "footnav/fnav_profile.h"

/* The paper's tables, each written once as six rows ROW(kind, axis, noise,
 * tau in samples at PAPER_RATE_HZ, sigma_bias) in the paper's units (acc x,
 * y, z, gyr x, y, z; fnav_profile.h): expanded into the rows
 * fnav_profile_paper_table returns and into the built-in profiles. */
#define PAPER_RATE_HZ 200.0
#define DEG2RAD (3.14159265358979323846 / 180.0)

/* Paper Table IV, "Model parameters for the InterSense IMU NavChip at 200 Hz".
 * (The text says Tables IV, V, VI hold Figs. 9, 8, 10, i.e. MTx first; the
 * captions and the noise levels - NavChip gyro ~0.004 deg/s/sqrt(Hz), MTx
 * ~0.03 - say Table IV is the NavChip. We follow the captions.) */
#define TABLE_NAVCHIP(ROW)                                                                                   \
    ROW(ACC, 0, 7.4e-4, 2000.0, 1.3e-5) ROW(ACC, 1, 6.4e-4, 2000.0, 9.7e-6) ROW(ACC, 2, 5.0e-4, 2000.0, 7.3e-6) \
    ROW(GYR, 0, 3.3e-3, 1000.0, 8.5e-5) ROW(GYR, 1, 3.7e-3, 1000.0, 6.4e-5) ROW(GYR, 2, 4.2e-3, 10000.0, 3.4e-5)

/* Paper Table V, Xsens MTx at 200 Hz. */
#define TABLE_MTX(ROW)                                                                                       \
    ROW(ACC, 0, 8.9e-4, 2600.0, 7.9e-6) ROW(ACC, 1, 8.4e-4, 2600.0, 8.1e-6) ROW(ACC, 2, 8.4e-4, 11000.0, 2.5e-6) \
    ROW(GYR, 0, 2.6e-2, 42000.0, 1.8e-5) ROW(GYR, 1, 2.5e-2, 56000.0, 1.6e-5)                                 \
    ROW(GYR, 2, 2.9e-2, 144000.0, 8.4e-6)

/* Paper Table VI, Shimmer at 200 Hz. */
#define TABLE_SHIMMER(ROW)                                                                                     \
    ROW(ACC, 0, 6.0e-3, 14600.0, 8.7e-6) ROW(ACC, 1, 5.9e-3, 36000.0, 5.3e-6) ROW(ACC, 2, 6.5e-3, 9400.0, 1.4e-5) \
    ROW(GYR, 0, 1.9e-2, 4200.0, 1.0e-4) ROW(GYR, 1, 1.7e-2, 800.0, 5.3e-4) ROW(GYR, 2, 1.9e-2, 2800.0, 2.2e-4)

/* A row as printed. */
#define PAPER_ROW(kind, axis, noise, tau, sigma) { noise, tau, sigma },

static const fnav_profile_paper_row_t k_navchip[6] = { TABLE_NAVCHIP(PAPER_ROW) };
static const fnav_profile_paper_row_t k_mtx[6] = { TABLE_MTX(PAPER_ROW) };
static const fnav_profile_paper_row_t k_shimmer[6] = { TABLE_SHIMMER(PAPER_ROW) };

/* A row in SI units, the arithmetic of fnav_profile_from_paper (in double,
 * each value rounded once to fnav_real_t) done by the compiler: the
 * built-ins link no double arithmetic, which on a single-precision FPU
 * (Cortex-M4F) is soft-float code (docs/firmware.md, "Another sensor
 * model"); the same bits as fnav_profile_from_paper's (test_profile
 * test_builtin_exact). */
#define SI_ROW(kind, axis, noise, tau, sigma) SI_##kind(axis, noise, tau, sigma)
#define SI_ACC(axis, noise, tau, sigma)                                                                      \
    .accel_noise_mps2_rthz[axis] = (fnav_real_t)(noise),                                                     \
    .accel_tau_s[axis] = (fnav_real_t)((tau) / PAPER_RATE_HZ), /* eq. (5) inverted */                         \
    .accel_bias_sigma_mps2[axis] = (fnav_real_t)(sigma),
#define SI_GYR(axis, noise, tau, sigma)                                                                      \
    .gyro_noise_rps_rthz[axis] = (fnav_real_t)((noise) * DEG2RAD),                                           \
    .gyro_tau_s[axis] = (fnav_real_t)((tau) / PAPER_RATE_HZ),                                                \
    .gyro_bias_sigma_rps[axis] = (fnav_real_t)((sigma) * DEG2RAD),

static const fnav_profile_t k_builtin[FNAV_PROFILE_COUNT] = {
    { .name = "navchip", .rate_hz = (fnav_real_t)PAPER_RATE_HZ, TABLE_NAVCHIP(SI_ROW) },
    { .name = "mtx", .rate_hz = (fnav_real_t)PAPER_RATE_HZ, TABLE_MTX(SI_ROW) },
    { .name = "shimmer", .rate_hz = (fnav_real_t)PAPER_RATE_HZ, TABLE_SHIMMER(SI_ROW) },
};

/* Not a paper table: SI units directly (fnav_profile.h). */
static const fnav_profile_t k_generic_mems = FNAV_PROFILE_GENERIC_MEMS_INIT;

const fnav_profile_paper_row_t *fnav_profile_paper_table(fnav_profile_id_t id)
{
    switch (id) {
    case FNAV_PROFILE_NAVCHIP: return k_navchip;
    case FNAV_PROFILE_MTX: return k_mtx;
    case FNAV_PROFILE_SHIMMER: return k_shimmer;
    default: return NULL;
    }
}

static int str_eq(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

static void copy_name(char *dst, const char *src)
{
    int i;
    for (i = 0; i < FNAV_PROFILE_NAME_MAX - 1 && src[i] != '\0'; i++) {
        dst[i] = src[i];
    }
    for (; i < FNAV_PROFILE_NAME_MAX; i++) {
        dst[i] = '\0';
    }
}

fnav_status_t fnav_profile_from_paper(fnav_profile_t *p, const char *name, double rate_hz,
                                      const fnav_profile_paper_row_t rows[6])
{
    const double deg2rad = DEG2RAD;
    fnav_profile_t t;
    int i;
    if (p == NULL || name == NULL || rows == NULL || !(rate_hz > 0.0)) {
        return FNAV_E_ARG;
    }
    for (i = 0; i < 6; i++) {
        if (!(rows[i].noise > 0.0) || !(rows[i].tau_samples > 0.0) || !(rows[i].sigma_bias > 0.0)) {
            return FNAV_E_ARG;
        }
    }
    copy_name(t.name, name);
    t.rate_hz = (fnav_real_t)rate_hz;
    for (i = 0; i < 3; i++) {
        t.accel_noise_mps2_rthz[i] = (fnav_real_t)rows[i].noise;
        t.accel_tau_s[i] = (fnav_real_t)(rows[i].tau_samples / rate_hz); /* eq. (5) inverted */
        t.accel_bias_sigma_mps2[i] = (fnav_real_t)rows[i].sigma_bias;
        t.gyro_noise_rps_rthz[i] = (fnav_real_t)(rows[3 + i].noise * deg2rad);
        t.gyro_tau_s[i] = (fnav_real_t)(rows[3 + i].tau_samples / rate_hz);
        t.gyro_bias_sigma_rps[i] = (fnav_real_t)(rows[3 + i].sigma_bias * deg2rad);
    }
    /* the conversions can leave float's range (an infinite rate gives tau
     * 0): the result must pass the same check as a profile file, and *p is
     * written only then (bad data leaves it as it was) */
    if (fnav_profile_validate(&t) != FNAV_OK) {
        return FNAV_E_ARG;
    }
    *p = t;
    return FNAV_OK;
}

fnav_status_t fnav_profile_builtin(fnav_profile_t *p, fnav_profile_id_t id)
{
    if (p == NULL || (unsigned)id >= (unsigned)FNAV_PROFILE_COUNT) {
        return FNAV_E_ARG;
    }
    *p = k_builtin[id];
    return FNAV_OK;
}

fnav_status_t fnav_profile_by_name(fnav_profile_t *p, const char *name)
{
    int i;
    if (p == NULL || name == NULL) {
        return FNAV_E_ARG;
    }
    for (i = 0; i < FNAV_PROFILE_COUNT; i++) {
        if (str_eq(name, k_builtin[i].name)) {
            return fnav_profile_builtin(p, (fnav_profile_id_t)i);
        }
    }
    if (str_eq(name, k_generic_mems.name)) {
        *p = k_generic_mems;
        return FNAV_OK;
    }
    return FNAV_E_ARG;
}

static int positive_finite(fnav_real_t x)
{
    return fnav_isfinite(x) && x > FNAV_R(0.0);
}

fnav_status_t fnav_profile_validate(const fnav_profile_t *p)
{
    int i;
    if (p == NULL) {
        return FNAV_E_ARG;
    }
    if (!positive_finite(p->rate_hz)) {
        return FNAV_E_CONFIG;
    }
    for (i = 0; i < 3; i++) {
        if (!positive_finite(p->accel_noise_mps2_rthz[i]) || !positive_finite(p->accel_tau_s[i]) ||
            !positive_finite(p->accel_bias_sigma_mps2[i]) || !positive_finite(p->gyro_noise_rps_rthz[i]) ||
            !positive_finite(p->gyro_tau_s[i]) || !positive_finite(p->gyro_bias_sigma_rps[i])) {
            return FNAV_E_CONFIG;
        }
    }
    return FNAV_OK;
}
