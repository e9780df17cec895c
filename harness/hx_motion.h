/**
 * @file hx_motion.h
 * @brief Foot motion generator with exact truth (docs/simulator.md).
 *
 * The sensor's trajectory is a sequence of legs (stand, walk, run, stairs,
 * in-place turns, elevator rides) built from strides of one foot: foot flat
 * and still, heel rise to toe-off, swing, landing (the heel-strike impact),
 * foot slap, still again. Position (navigation frame n: x along the initial
 * heading, z down) and the foot's ZYX Euler angles are piecewise quintic
 * Hermite splines (value, first and second derivative continuous at every
 * knot), and each landing adds a compactly supported ringing of the shoe.
 * Velocity, acceleration and the Euler rates are exact derivatives, so the
 * ideal specific force f_b = C_bn (a_n - g_n) and angular rate w_b are exact
 * and integrate back to the trajectory. The Earth is flat and does not
 * rotate; gravity g_n = (0, 0, g).
 *
 * Impact sharpness is the landing deceleration time `impact_s`: the foot
 * goes from `land_speed_mps` to rest in that time (the speed follows a cubic
 * smooth step: peak deceleration 1.5 v / impact_s), which sets the
 * high-frequency content of section II
 * of the paper; the ringing adds a damped tone at `ring_hz`.
 */
#ifndef HX_MOTION_H
#define HX_MOTION_H

#include <stddef.h>

/** Gait of one kind of leg. */
typedef struct {
    double cadence_spm;      /**< steps per minute (both feet); the sensor foot makes one stride per 2 steps */
    double stride_m;         /**< nominal horizontal displacement of the sensor foot per stride, m */
    double still_frac;       /**< fraction of the cycle with the foot flat and still */
    double heeloff_frac;     /**< fraction from heel rise to toe-off */
    double slap_frac;        /**< fraction from heel strike to foot flat */
    double lift_m;           /**< swing clearance above the higher of start and landing, m */
    double pitch_off_deg;    /**< pitch at toe-off (negative: toe down) */
    double pitch_strike_deg; /**< pitch at contact (positive: heel first, negative: toe first) */
    double pitch_mid_deg;    /**< pitch in mid-swing (toe raised to clear a step on stairs) */
    double roll_deg;         /**< roll in mid-swing */
    double land_speed_mps;   /**< downward speed just before contact, m/s */
    double impact_s;         /**< landing deceleration time (impact sharpness), s */
    double ring_hz;          /**< ringing frequency after contact, Hz */
    double ring_mps2;        /**< ringing peak acceleration, m/s^2 (0: none) */
    double ring_s;           /**< ringing duration, s */
} hx_gait_t;

/** Motion configuration (hx_motion_config_default() gives the defaults). */
typedef struct {
    hx_gait_t walk, run, stairs_up, stairs_down, turn;
    double stair_rise_m;      /**< height of one stair step, m */
    double stair_run_m;       /**< depth of one stair step, m */
    double elev_speed_mps;    /**< elevator cruise speed, m/s */
    double elev_accel_mps2;   /**< elevator peak acceleration, m/s^2 */
    double elev_vib_hz;       /**< elevator motor vibration frequency (truth motion), Hz */
    double elev_vib_mps2;     /**< its peak acceleration, m/s^2 (0: none) */
    double foot_toe_m;        /**< sensor behind the toe, m (toe pivot at heel rise) */
    double foot_heel_m;       /**< sensor in front of the heel, m (heel pivot at contact) */
    double foot_height_m;     /**< sensor above the sole, m */
    double mount_deg[3];      /**< sensor mounting on the foot: roll, pitch, yaw (ZYX), deg */
    double g_mps2;            /**< gravity, m/s^2 */
} hx_motion_config_t;

/** Defaults: walking 1.28 m/s at 110 steps/min, running 3.4 m/s at 170,
 *  stairs 0.17 m x 0.28 m, elevator 1.5 m/s, g = 9.80665 m/s^2. */
hx_motion_config_t hx_motion_config_default(void);

/** The longest landing a gait's stride takes, s: 30 % of its swing time;
 *  a longer impact_s is capped there. */
double hx_gait_max_impact_s(const hx_gait_t *g);

/** Phase of the sensor foot. */
typedef enum {
    HX_PHASE_STILL = 0,  /**< foot flat and at rest on its support */
    HX_PHASE_HEELOFF,    /**< heel rising, rolling over the toe */
    HX_PHASE_SWING,      /**< in the air */
    HX_PHASE_LANDING,    /**< decelerating into contact (the impact) */
    HX_PHASE_SLAP,       /**< from contact to foot flat */
    HX_PHASE_RIDE        /**< standing in a moving elevator */
} hx_phase_t;

/** Truth at one instant. */
typedef struct {
    double t_s;
    double pos_m[3];     /**< sensor position in n, m */
    double vel_mps[3];   /**< velocity in n, m/s */
    double acc_mps2[3];  /**< acceleration in n, m/s^2 */
    double q_nb[4];      /**< attitude of the sensor frame, [w x y z] */
    double euler_rad[3]; /**< roll, pitch, yaw (ZYX) of the sensor frame, yaw wrapped to (-pi, pi] */
    double f_b[3];       /**< specific force C_bn (a_n - g_n), m/s^2 */
    double w_b[3];       /**< angular rate of b relative to n, in b, rad/s */
    int still;           /**< 1: foot flat and at rest on its support (shoe ringing over) */
    int zero_vel;        /**< 1: velocity exactly zero (still and not riding) */
    int phase;           /**< hx_phase_t */
    int leg;             /**< index of the leg (script item) */
    double odo_m;        /**< horizontal distance between completed footfalls so far, m */
} hx_truth_t;

typedef struct hx_motion hx_motion_t;

/**
 * Build a motion from a script: comma-separated legs
 *   stand:SECONDS | walk:METRES[:TURN_DEG] | run:METRES[:TURN_DEG] |
 *   stairs-up:STEPS[:TURN_DEG] | stairs-down:STEPS[:TURN_DEG] |
 *   turn:DEG | elevator:METRES (positive up) | home
 * (`home` turns to face the start and walks there in a straight line), or
 * a built-in scenario name (hx_motion_scenario). `duration_s` > 0 makes the
 * built-ins `walk`, `run`, `stand` and `loop` last about that
 * long; scripts keep their own length.
 * @return the motion, or NULL with a one-line message in err.
 */
hx_motion_t *hx_motion_create(const hx_motion_config_t *cfg, const char *script, double duration_s, char *err,
                              size_t err_size);
void hx_motion_free(hx_motion_t *m);

/** Expand a built-in scenario name into a script for about duration_s
 *  seconds (0: its default length). Returns 0, or -1 for an unknown name. */
int hx_motion_scenario(const char *name, const hx_motion_config_t *cfg, double duration_s, char *script,
                       size_t size);
/** Comma-separated names of the built-in scenarios (for --help). */
const char *hx_motion_scenario_list(void);

/** Time at which the last leg ends, s (the motion is still before 0 and
 *  after this). */
double hx_motion_duration(const hx_motion_t *m);
/** Number of footfalls (completed strides). */
int hx_motion_strides(const hx_motion_t *m);
/** Of them, the strides of the walking gait (cfg->walk: walk legs and
 *  home); 0 when the options that set it have no effect. */
int hx_motion_walk_strides(const hx_motion_t *m);
/** Number of footfalls at or before time t, s (the strides of an output cut
 *  by --duration). */
int hx_motion_strides_until(const hx_motion_t *m, double t);

/** Number of spline knots, and the time of knot i: between consecutive
 *  knots the truth is analytic (polynomial plus smooth ringing); at a knot
 *  the third derivative of position may jump (for integration tests). */
size_t hx_motion_nknots(const hx_motion_t *m);
double hx_motion_knot_time(const hx_motion_t *m, size_t i);

/** Exact truth at time t (any t; still outside [0, duration]). */
void hx_motion_eval(const hx_motion_t *m, double t_s, hx_truth_t *out);

/** C_nb = Rz(yaw) Ry(pitch) Rx(roll) of ZYX Euler angles, rad (Titterton &
 *  Weston eq. 3.47; the simulator's mounting and truth, the replay's heading). */
void hx_dcm_from_euler(double roll, double pitch, double yaw, double C[3][3]);
/** r = a b, the Hamilton product of quaternions [w x y z] (r may be a or b;
 *  the simulator's truth attitude, montecarlo's attitude error). */
void hx_quat_mul(const double a[4], const double b[4], double r[4]);

#endif /* HX_MOTION_H */
