/**
 * @file hx_mc.h
 * @brief Monte Carlo engine of `harness montecarlo` (docs/results-sim.md):
 *        N seeds of one simulated motion, each fed to one or more
 *        navigators (variants, e.g. the filter with and without the bias
 *        model, on exactly the same samples), errors against the truth,
 *        error growth with time and distance, and the filter's consistency
 *        (average normalised estimation error squared, NEES, against its
 *        chi-square band).
 *
 * A navigator is seen through hx_mc_nav_t (callbacks plus a context), so the
 * engine does not depend on one filter: the footnav filter is one adapter;
 * the tests use oracle navigators with a known covariance.
 */
#ifndef HX_MC_H
#define HX_MC_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "hx_sim.h"

#define HX_MC_MAX_VARIANTS 4

/** NEES groups. */
enum { HX_NEES_POS = 0, HX_NEES_VEL, HX_NEES_ATT, HX_NEES_BIAS, HX_NEES_ALL, HX_NEES_COUNT };

/** Dimensions of the NEES groups (3, 3, 3, 6, 15). */
extern const int hx_nees_dim[HX_NEES_COUNT];
/** Names of the NEES groups ("pos", "vel", "att", "bias", "all"). */
extern const char *const hx_nees_name[HX_NEES_COUNT];

/** One estimate of a navigator, for the sample with counter `seq`. */
typedef struct {
    uint32_t seq;        /**< counter of the sample it belongs to */
    int valid;           /**< 0 before alignment: ignored */
    double pos_m[3];     /**< navigation frame of the filter (origin where the sensor was at the first
                              valid estimate, x along its heading then, z down) */
    double vel_mps[3];
    double q_nb[4];
    double gyro_bias_rps[3];
    double accel_bias_mps2[3];
    /** Error covariance, order: attitude error about the n axes (rad),
     *  velocity, position, gyro bias, accel bias; of the error truth minus
     *  estimate (truth = exp(a) (x) q_nb, v + dv, ...) or, the same matrix,
     *  estimate minus truth with q_nb = exp(a) (x) truth: one sign for every
     *  state, as the filter's sigma points. */
    double P[15][15];
} hx_mc_est_t;

/** A navigator under test. */
typedef struct {
    const char *name;    /**< variant name, e.g. "ar1" */
    void *ctx;
    /** Start a run (output rate, run index). 0 ok. */
    int (*start)(void *ctx, double rate_hz, int run);
    /** Accept one delivered sample. 0 ok (a rejected sample is not an error). */
    int (*push)(void *ctx, const fnav_sample_t *s);
    /** Next estimate: 1 with *est filled, 0 when none is due. */
    int (*pop)(void *ctx, hx_mc_est_t *est);
    /** End of the run's input (estimates held back become due). */
    void (*finish)(void *ctx);
} hx_mc_nav_t;

/** Statistics of one time bin (the last estimate of each run in the bin). */
typedef struct {
    double t_s;            /**< end of the bin, s (the run's end for a last bin that would outlast it) */
    double odo_m;          /**< distance walked by then, m */
    int n;                 /**< runs with an estimate in the bin */
    double rms_h_m;        /**< RMS horizontal position error */
    double rms_v_m;        /**< RMS vertical position error */
    double rms_yaw_rad;    /**< RMS heading error (attitude error about n z) */
    double pred_h_m;       /**< RMS of the predicted horizontal sd sqrt(Pxx + Pyy) */
    double pred_v_m;       /**< RMS of the predicted vertical sd */
    double nees[HX_NEES_COUNT]; /**< average NEES over the runs (NaN: no positive definite covariance) */
    int n_nees[HX_NEES_COUNT];  /**< runs in each average (the band depends on it) */
} hx_mc_bin_t;

/** Results of one variant. */
typedef struct {
    const char *name;
    int nbins;
    hx_mc_bin_t *bins;
    double *final_h_m;     /**< per run: horizontal error at the end */
    double *final_v_m;     /**< per run: vertical error at the end */
    double *final_pred_h_m;/**< per run: predicted horizontal sd at the end */
    double *final_nees_pos;/**< per run: position NEES at the end */
    double *rms_h_m;       /**< per run: RMS horizontal error over the whole run */
    long estimates;        /**< estimates compared */
    int nonfinite;         /**< estimates with a non-finite value or covariance (skipped) */
} hx_mc_var_t;

/** Results of a Monte Carlo. */
typedef struct {
    int runs;
    int nvar;
    double duration_s;
    double distance_m;     /**< odometer at the end */
    double bin_s;
    hx_mc_var_t var[HX_MC_MAX_VARIANTS];
} hx_mc_result_t;

/** Configuration. */
typedef struct {
    hx_sim_config_t sim;   /**< motion and sensor model; sim.err.seed is the seed of run 0 */
    int runs;              /**< number of seeds (run r uses seed + r) */
    double bin_s;          /**< bin width of the growth curves, s (default 1) */
    double out_bytes_per_bin; /**< memory the caller's outputs take per bin and variant (a JSON tree and its
                                   text), bytes: counted with the engine's own in the memory check (0: none) */
    const volatile sig_atomic_t *stop; /**< nonzero (a signal's handler): no run started after it, the result holds
                                   the runs done (NULL: run them all) */
} hx_mc_config_t;

/** Progress callback: runs done, with the fraction of the run under way
 *  (its simulation, then each variant's replay, reported every 4,096
 *  samples: a single long run shows progress too), and the total. */
typedef void (*hx_mc_progress_fn)(void *ctx, double done, int total);

/**
 * Run the Monte Carlo.
 * @return 0 (res->runs the runs done: fewer than cfg->runs when cfg->stop
 *         was set), or -1 with a one-line message in err (configuration,
 *         memory, a navigator failing to start or to accept input, stopped
 *         before a run was done).
 */
int hx_mc_run(const hx_mc_config_t *cfg, hx_mc_nav_t *navs, int nvar, hx_mc_result_t *res,
              hx_mc_progress_fn progress, void *progress_ctx, char *err, size_t err_size);

void hx_mc_result_free(hx_mc_result_t *res);

/** Two-sided (1 - alpha) band of the average NEES of n runs of dimension d:
 *  [chi2_{alpha/2}(n d) / n, chi2_{1-alpha/2}(n d) / n] (Bar-Shalom,
 *  Li & Kirubarajan 2001, sec. 5.4). */
void hx_nees_band(int n, int d, double alpha, double *lo, double *hi);

#endif /* HX_MC_H */
