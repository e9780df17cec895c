/* The axes check: do the gyroscope's axes match the accelerometer's?
 * (docs/harness.md, "Axes check")
 *
 * A log whose gyro axis is sign-flipped or swapped against the accelerometer
 * (a left-handed triad, a wrong axis map in a logger) reads without any error
 * and navigates into nonsense. Each swing between two stances is integrated
 * from the accelerometer's tilt at the end of the stance, once for every
 * signed permutation of the gyro axes (48: the recorded map, 23 other
 * rotations and 24 reflections); the true map brings the foot back to rest,
 * v = 0, at the next stance, a wrong one leaves metres per second. The check
 * compares the median end speed of the recorded map with the best one.
 * Streaming: samples in (hx_axes_sample, as read), the navigator's frames in
 * (hx_axes_frame, in order, each after its sample), a verdict at the end. */
#ifndef HX_AXES_H
#define HX_AXES_H

#include <stddef.h>
#include <stdint.h>

#include "footnav/footnav.h"

#define HX_AXES_MAPS 48          /**< signed permutations of three axes */
#define HX_AXES_SCALES 4         /**< time scales tried with the recorded map: the interval read times 0.5, 0.8,
                                      1.25, 2 (a rate read 0.5, 0.8, 1.25, 2 times the true one) */
#define HX_AXES_STATES (HX_AXES_MAPS + HX_AXES_SCALES)
#define HX_AXES_RING 4096        /**< samples held until their frame arrives (the navigator's delay is far less) */

typedef struct {
    /* samples between read and frame */
    int64_t t_ns[HX_AXES_RING];
    fnav_vec3_t acc[HX_AXES_RING], gyr[HX_AXES_RING];
    size_t n_in, n_used;         /* samples pushed / matched or passed */
    size_t stance_run;           /* matched stance samples in a row, up to the newest */
    double cycle_frac;           /* a stance: a ZUPT run of this many gait cycles (0: any run) */
    int64_t t_run_ns;            /* that run's first frame */
    double run_s;                /* its span so far, s */
    int run_ok;                  /* 1: it is long enough to be a stance (hx_axes.c, min_run_s) */
    double runs_s[3];            /* the spans of the last ZUPT runs, newest first */
    double cyc_s[3];             /* the last gait cycles (swing start to swing start), newest first */
    int n_cyc;                   /* cycles known (0-3) */
    int have_start;              /* a swing began: */
    int64_t t_start_ns;          /* its first frame */
    /* the swing being integrated, one state per gyro map (the core's math) */
    int in_swing;
    int64_t t_swing_ns, t_last_ns; /* the swing's first frame; the last matched frame */
    fnav_real_t g_mps2;          /* |f| of this swing's start tilt */
    fnav_quat_t q_nb[HX_AXES_STATES];
    fnav_vec3_t v_mps[HX_AXES_STATES];
    int held;                    /* the swing met a ZUPT run not yet proven a stance: */
    int64_t t_held_ns;           /* its first frame, */
    double v_held_mps[HX_AXES_STATES]; /* the end speeds there */
    /* end speeds, swings x states (the maps, then the time scales), m/s */
    double *vend;
    size_t nswing, cap;
    int failed;                  /* out of memory: no verdict */
} hx_axes_t;

typedef struct {
    size_t swings;               /**< swings of 0.2-2 s judged */
    double v_recorded_mps;       /**< median end speed with the axes as recorded */
    double v_best_mps;           /**< the smallest median end speed over the 48 maps */
    double v_other_mps;          /**< the smallest over the 47 other maps than the recorded one: how far
                                      the walk tells the recorded map from its nearest rival */
    int best;                    /**< that map (0: as recorded) */
    char best_map[40];           /**< e.g. "(gx, -gy, gz)" */
    int problem;                 /**< 1: the recorded map is clearly not the gyro's */
    double v_scaled_mps;         /**< the smallest median end speed over its scale with the recorded map and the
                                      time between samples scaled (HX_AXES_SCALES) */
    double time_scale;           /**< that scale: the true interval over the one read */
    int time_problem;            /**< 1: a time scale fits clearly better than the time read and than every
                                      map (the sample rate is wrong; problem is then 0: no map is offered) */
    char msg[2048];              /**< the verdict, with the remedy when problem (for a CSV the whole --columns:
                                      hx_nav_replay) */
} hx_axes_result_t;

/** A new check (about 100 KB, so on the heap); NULL when out of memory.
 *  nav_min_zupt_cycle: the navigator's (fnav_stance_config_t); below the
 *  default 0.025 the check takes only ZUPT runs of 0.025 gait cycles or more
 *  for stances (hx_axes.c, hx_axes_frame). */
hx_axes_t *hx_axes_new(double nav_min_zupt_cycle);
/** A sample as it is read. */
void hx_axes_sample(hx_axes_t *a, const fnav_sample_t *s);
/** A frame of the navigator, in order, after its sample was pushed. */
void hx_axes_frame(hx_axes_t *a, const fnav_nav_frame_t *f);
/** The verdict over the swings seen ("not checked: out of memory" for a
 *  NULL check); frees the check. */
void hx_axes_finish(hx_axes_t *a, hx_axes_result_t *r);

/** Signed permutation k (0..47; 0 the identity) applied to w: out_i = s_i w_p(i). */
fnav_vec3_t hx_axes_map(int k, fnav_vec3_t w);

#endif
