/**
 * @file hx_simgap_nav.h
 * @brief Sim-to-real gap diagnosis, walk domain (docs/simgap.md): the
 *        navigation filter on the real walk, the twin's motion from its
 *        estimated trajectory, and the gap in zero-velocity-update
 *        innovations, residual velocity in stance and drift.
 */
#ifndef HX_SIMGAP_NAV_H
#define HX_SIMGAP_NAV_H

#include "hx_simgap.h"
#include "hx_simgap_valid.h"

typedef struct sg_nav sg_nav_t;

/** Walk-domain diagnosis of a loaded log into r (r->nav is set). */
int sg_nav_diagnose(const hx_log_t *log, sg_result_t *r, char *err, size_t err_size);
/** Add the walk domain's gaps, selected effects and open gaps to the counts. */
void sg_nav_verdict_counts(const sg_nav_t *nv, int *gaps, int *sel, int *open);
/** The walk domain's part of the JSON report (cJSON object, caller owns). */
struct cJSON *sg_nav_json(const sg_nav_t *nv, const sg_result_t *r);
/** Plots of the walk domain into dir. 0, -1 (printed). */
int sg_nav_plot(const sg_nav_t *nv, const sg_result_t *r, const char *dir, const char *cmd);

/** The walk domain's selected effects on the verdict line ("; name (...)";
 *  *first: no effect printed yet on the line). */
void sg_nav_verdict_text(const sg_nav_t *nv, FILE *f, int *first);
/** The walk domain's selected effects appended to a JSON array of
 *  {effect, domain, channels, params[]} objects. */
void sg_nav_verdict_json(const sg_nav_t *nv, struct cJSON *arr);
/** Append the walk's gap locations (navigation points and lattices beyond the
 * critical z, whole log) to the JSON array `locations`. */
void sg_nav_locations_json(const sg_nav_t *nv, struct cJSON *arr);
/** Print the walk domain's part of the summary. */
void sg_nav_print(const sg_nav_t *nv, FILE *f, const sg_result_t *r);
void sg_nav_free(sg_nav_t *nv);

/** Validation: add the walk domain's selected effects to the per-effect
 *  scores (indices of sgv_effects()) and its flagged channels. */
void sg_nav_scores(const sg_nav_t *nv, double *score, int neff, uint32_t *flagged);
/** Validation: relative errors of the fitted magnitude and held-out shrink
 *  of effect id on the channels of mask against the true values. */
void sg_nav_truth_errors(const sg_nav_t *nv, int id, uint32_t mask, const double *truth, double *pe, int *np,
                         double *sh, int *ns);
/** Validation: draw a walk case (type: index of sgv_effects() or -1 for a
 *  control): sensor configuration, motion script, truth in cs; the log's
 *  error model is seeded with log_seed (case i's: sgv_case_seeds), which
 *  is recorded in cs->log_seed. On failure (-1) why says what stopped it. */
int sg_nav_draw_case(const sgv_opts_t *o, int type, uint32_t log_seed, fnav_rng_t *rng, sgv_case_t *cs,
                     fnav_imuerr_config_t *cfg, char *script, size_t script_size, char *why, size_t why_size);

/**
 * The sensor's linear error from the one fitted on a twin whose truth is
 * the filter's trajectory (docs/simgap.md, "Walks"): with y = (I + A) x the
 * sensor and x_t = (I + A) x the trajectory's signals, the effect fitted on
 * the trajectory (B x_t = A x) gives A = B (I - B)^-1.
 * @param B  fitted error matrix, rows and columns ax ay az gx gy gz
 * @param A  the sensor's error matrix (out)
 * @return 0, -1 when I - B is singular (A untouched).
 */
int sg_nav_lin_to_sensor(const double B[6][6], double A[6][6]);

/**
 * The sensor's values of npar parameters of the linear motion family id
 * (scale, misalign, gsens) from the error matrix B fitted on the filter's
 * trajectory (sg_nav_lin_to_sensor), each within the catalogue's range
 * [lo, hi] (fnav_imuerr_effect_info), the only values the twins' error
 * model takes: a value beyond it (I - B singular: beyond the bound on the
 * side of its trajectory value) is set to that bound and flagged.
 * @param B      fitted error matrix, every family selected together
 * @param ch, k  channel and parameter index of each parameter
 * @param eq     its trajectory value (B), eq_at its flag (as at; NULL: none)
 * @param val    the sensor's value (out)
 * @param at     0 a fitted value inside the range; -1 (+1): the fit (the
 *               sensor's value, or the trajectory's, eq_at) went past lo
 *               (hi) and val is that bound, only an upper (a lower) limit
 * @return the number of parameters flagged, -1 on a bad id or index.
 */
int sg_nav_sensor_values(const double B[6][6], int id, int npar, const int *ch, const int *k, const double *eq,
                         const int *eq_at, double *val, int *at);

/**
 * One parameter of a walk-domain effect as the summary prints it,
 * "gz.sf=0.3", and for a value at a bound of the catalogue's range (at as
 * sg_nav_sensor_values) "gz.sf=10 at the catalogue's bound: only a lower
 * limit".
 * @return the length snprintf reports.
 */
int sg_nav_param_text(char *b, size_t n, int id, int ch, int k, double v, int at);

/**
 * Add `bounds` to a walk-domain parameter's JSON object p: for a linear
 * family {`lo`, `hi` (the catalogue's range), `at_bound` (`"lower"`,
 * `"upper"` or null: at as sg_nav_sensor_values)}, null for the others.
 */
void sg_nav_bounds_json(struct cJSON *p, int id, int k, int at);

/**
 * The stance of run b that observes the same swing as stance i of run a:
 * the nearest first update in time (within 0.15 s), each other's nearest
 * (one to one), after a swing of the same duration to 10 %.
 * @param ta, swa  run a: first-update times and preceding swing durations (s), na stances
 * @param tb, swb  run b, nb stances
 * @return index into b, or -1.
 */
int sg_nav_match_swing(const double *ta, const double *swa, int na, int i, const double *tb, const double *swb,
                       int nb);

/**
 * The navigation points of one segment (docs/simgap.md, section 3, `nav`)
 * from a filter run given per sample, in their order: NIS of the first
 * updates, of all updates, per axis (3), whiteness, residual velocity,
 * nwin windows, and with drift the horizontal and vertical drift between
 * the first and the last stance (a closed walk: truth zero). A stance is a
 * run of updates with gaps of at most 2 samples.
 * @param zupt  per sample: nonzero where the zero-velocity update ran
 * @param y, S  its innovation and covariance (xx xy xz yy yz zz); nis its NIS
 * @param v, p  posterior velocity and position
 * @param vals  the points' values (out, at least 7 + nwin + 2)
 * @param pl    the points (appended; NULL: values only)
 * @return the number of points, -1 on bad arguments or memory failure.
 */
long sg_nav_stance_points(long n, const int64_t *t_ns, const unsigned char *zupt, const double (*y)[3],
                          const double (*S)[6], const double *nis, const double (*v)[3], const double (*p)[3],
                          int nwin, int drift, double *vals, sg_plist_t *pl);

/**
 * The start times (s after t_ns[0]) of the stances of a filter run given by
 * its update flags, as the fit of the motion effects takes them (one per
 * stance, at its first update; a stance as in sg_nav_stance_points).
 * @param t    receives the first min(count, max) times
 * @return the number of stances, -1 on bad arguments or memory failure.
 */
long sg_nav_stance_starts(long n, const int64_t *t_ns, const unsigned char *zupt, double *t, long max);

/**
 * The held-out stances of a walk split at sample split (docs/simgap.md,
 * section 2): stances counted as the core's stride segmentation counts
 * them (runs of updates with gaps of at most 2 samples, runs less than
 * min_swing_s apart one stance), held out those that begin at or after
 * split. A stance in progress at split began in the fit segment: it is the
 * fit's, not held out.
 * @param from  the first update of the first held-out stance (out; n when
 *              there is none)
 * @return the number of held-out stances, -1 on bad arguments.
 */
int sg_nav_held_out_stances(long n, const int64_t *t_ns, const unsigned char *zupt, long split, double min_swing_s,
                            long *from);

/**
 * The navigation points of the held-out segment [split, n) of a walk as
 * the diagnosis computes them: those of sg_nav_stance_points (no drift)
 * over the stances from the first held-out one (sg_nav_held_out_stances)
 * on, the windows spanning the segment from split.
 * @return the number of points, -1 on bad arguments or memory failure.
 */
long sg_nav_held_out_points(long n, const int64_t *t_ns, const unsigned char *zupt, const double (*y)[3],
                            const double (*S)[6], const double *nis, const double (*v)[3], const double (*p)[3],
                            long split, double min_swing_s, int nwin, double *vals, sg_plist_t *pl);

#endif /* HX_SIMGAP_NAV_H */
