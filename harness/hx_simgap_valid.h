/**
 * @file hx_simgap_valid.h
 * @brief Validation of the sim-to-real gap diagnosis on cases whose effect
 *        is withheld (docs/simgap.md, docs/simgap-validation.md): each case
 *        is a log simulated with one effect of the catalogue drawn at random
 *        (or none: a control) at a magnitude drawn from the range the
 *        catalogue documents as detectable; the diagnosis sees only the log;
 *        the answer is scored afterwards.
 */
#ifndef HX_SIMGAP_VALID_H
#define HX_SIMGAP_VALID_H

#include <signal.h>
#include <stdio.h>

#include "footnav/fnav_profile.h"
#include "hx_simgap.h"

/** Effect classes of the validation. */
enum { SGV_STATIC = 0, SGV_TIMING, SGV_MOTION, SGV_NCLASS };

/** One effect the validation draws. */
typedef struct {
    const char *name;   /**< catalogue name; "quant_shaped" is quant with shaped = 1 */
    int id;             /**< fnav_effect_id_t */
    int cls;            /**< SGV_* */
    int magp;           /**< index of the magnitude parameter */
} sgv_effect_t;

/** The table of validated effects; *n receives its length. */
const sgv_effect_t *sgv_effects(int *n);

/**
 * Smallest detectable magnitude of an effect on one channel by the
 * catalogue's rule (docs/simulator.md, vectors/sim/gen_detectable.py): a
 * static log of `duration_s` at `rate_hz` whose baseline is white noise
 * (density N) + AR(1) (sigma, tau_s); detectable when the effect's Allan
 * variance exceeds the baseline's by more than 5 standard deviations of the
 * overlapping estimate (white-FM EDF, NIST SP 1065) at some octave tau with
 * at least 10 averages in the log (at least 20 for the octave's pairs).
 * @param e  the effect with every non-magnitude parameter set (frequency,
 *           band, warm-up, step rate); its magnitude is ignored
 * @return the magnitude, or NAN when the effect has no Allan signature.
 */
double sgv_detect_threshold(const sg_effect_t *e, int magp, double N, double sigma, double tau_s, double rate_hz,
                            double duration_s);

/** Simulate a log in memory through the simulator's chain (hx_sim_run):
 *  motion script, sensor configuration; point = 1 samples the truth at the
 *  output instants (static logs). 0, -1 with err filled. */
int sgv_simulate(const char *script, const fnav_imuerr_config_t *cfg, int point, hx_log_t *log, char *err,
                 size_t err_size);

/** Bounds of --mag-range (multiples of the detectable threshold): beyond
 *  1000 (a million times the threshold's excess Allan variance) an effect
 *  no longer tests detection, and a ramp at 1e6 x gave a static log whose
 *  accelerometer read 5921 m/s^2; below 0.001 no effect shows at all. */
#define SGV_MAG_MIN 1e-3
#define SGV_MAG_MAX 1e3

/** Most samples of a static case (--duration x --rate): 2e7 is 27.8 h at
 *  200 Hz, 20 times the ADIS16405 logs' million; a case holds its log,
 *  the twins and the Allan tables in memory, and 1e11 (the options' own
 *  ends) ran for ever instead of failing. */
#define SGV_MAX_STATIC_SAMPLES 2e7

/** Options of a validation run. */
typedef struct {
    int cases;
    uint32_t seed;
    double duration_s;      /**< static cases (default 3600 s: the catalogue's reference) */
    double rate_hz;         /**< static cases (default 200 Hz) */
    double walk_duration_s; /**< walk cases (default 60 s) */
    double walk_rate_hz;    /**< walk cases (default 200 Hz) */
    int walks;              /**< 1: include motion-domain cases */
    int statics;            /**< 1: include static-domain cases */
    int seeds;              /**< twins per model in the diagnosis */
    double mag_lo, mag_hi;  /**< magnitude multiplier range over the threshold (1, 10) */
    int quiet;
    int verbose;            /**< print the diagnosis of every case */
    int only;               /**< run only this case index (-1: all) */
    const char *effects;    /**< comma-separated effect names to draw (NULL: all), "control" for controls */
    /** Non-zero: stop before the next case (a signal handler sets it; NULL:
     *  never). The cases already run keep their scores. */
    const volatile sig_atomic_t *stop;
} sgv_opts_t;

sgv_opts_t sgv_opts_default(void);

/** Seeds one case owns (docs/simgap.md "What `--seed` seeds"): case i of
 *  --seed S owns S + i SGV_SEED_STRIDE ... S + (i + 1) SGV_SEED_STRIDE - 1
 *  (mod 2^32): its diagnosis draws from the first SG_SEED_SPAN, its log is
 *  the error model's run of the next. 100,000 cases (--cases' limit) own
 *  2e9 seeds, fewer than 2^32: no two cases meet, whatever S. */
#define SGV_SEED_STRIDE 20000u

/** The seeds of case i: *log_seed the error model's seed of its log,
 *  *diag_seed the --seed S of its diagnosis (which draws from S ...
 *  S + SG_SEED_SPAN - 1): S + i SGV_SEED_STRIDE + SG_SEED_SPAN and
 *  S + i SGV_SEED_STRIDE (mod 2^32). Either pointer may be NULL (that seed
 *  is not wanted). */
void sgv_case_seeds(const sgv_opts_t *o, int i, uint32_t *log_seed, uint32_t *diag_seed);

/** truth of a case that was not run (--only, a stop, a failure). */
#define SGV_NOT_RUN (-1000)

/** One scored case. */
typedef struct {
    int truth;              /**< index into sgv_effects(), -1 control */
    uint32_t log_seed;      /**< the error model's seed of the log (sgv_case_seeds) */
    int cls;                /**< class of the truth (controls: the domain's) */
    int walk;               /**< walk case */
    int profile;            /**< fnav_profile_id_t */
    uint32_t mask;          /**< channels of the effect */
    double mult;            /**< magnitude / threshold */
    double value[SG_NCH];   /**< true magnitude per channel */
    int pred;               /**< top-ranked effect, index into sgv_effects(); -1 none; -2 other */
    int detected;           /**< verdict is not "none" */
    uint32_t flagged;       /**< channels with a significant gap */
    int timing_flagged;
    double jaccard;         /**< |flagged & mask| / |flagged | mask| (timing: 1 when the timing test flags
                             *   the log and no channel, else 0) */
    double perr;            /**< median relative error of the magnitude over the channels (NaN) */
    double shrink;          /**< median held-out excess explained by the right effect (NaN) */
    char verdict[32];
    double elapsed_s;
    double n_events[SG_NSEG]; /**< jumps: steps in the fit and held-out parts */
} sgv_case_t;

/** Check the options a command line gives (every --effects name known, some
 *  case kind selected, --only below --cases): 0, or -1 with err filled (a
 *  usage error). */
int sgv_check_opts(const sgv_opts_t *o, char *err, size_t err_size);

/** Run the validation; prints progress lines to `f` (NULL: silent). cases
 *  receives o->cases entries (caller allocated); a case not run (--only, a
 *  stop, a failure) has truth SGV_NOT_RUN and is left out of the report.
 *  0 every case run; 1 stopped by *o->stop; -1 a case failed, err filled
 *  (the cases before it keep their scores: report them). */
int sgv_run(const sgv_opts_t *o, sgv_case_t *cases, FILE *f, char *err, size_t err_size);

/** The summary: confusion matrix, rates, errors, targets (text, or
 *  Markdown when md != 0). */
void sgv_report(FILE *f, const sgv_opts_t *o, const sgv_case_t *cases, int n, int md, double elapsed_s);

/** JSON of the run; `error` why it stopped early (NULL: it did not). 0, -1
 *  on failure. */
int sgv_write_json(const char *path, const sgv_opts_t *o, const sgv_case_t *cases, int n, double elapsed_s,
                   const char *error);

#endif /* HX_SIMGAP_VALID_H */
