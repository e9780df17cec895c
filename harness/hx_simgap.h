/**
 * @file hx_simgap.h
 * @brief Sim-to-real gap diagnosis (docs/simgap.md): a twin of a real log
 *        simulated from a baseline model fitted on a fit segment, the gap
 *        located per domain with z-scores, and attribution of the gap to the
 *        simulator's effect catalogue by forward selection scored on a
 *        held-out segment.
 *
 * Domains: Allan (per channel and tau), spectral (per channel and frequency
 * band), lattice (the value lattice that quantisation leaves, per channel),
 * timing (duplicated and dropped samples, time-stamp jitter) and, for walks,
 * navigation (zero-velocity-update innovations, residual velocity in stance,
 * drift against the twin's Monte Carlo spread).
 *
 * Statistics are compared as z-scores: z = (y_real - mean_s y_twin,s) /
 * sqrt(var_s(y_twin)/S + v_real), v_real the variance of the real estimate
 * from its own confidence interval (equivalent degrees of freedom) or, where
 * no theory exists, the twins' spread. The null distribution of the
 * aggregate gap comes from treating each twin seed as the real log.
 */
#ifndef HX_SIMGAP_H
#define HX_SIMGAP_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "footnav/fnav_allan.h"
#include "footnav/fnav_imuerr.h"
#include "footnav/fnav_welch.h"
#include "hx_log.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define SG_NCH 6            /**< channels: ax ay az gx gy gz */
#define SG_MAX_EFF 8        /**< effects in one channel model */
#define SG_MAX_PAR 4        /**< parameters of one effect */
#define SG_MAX_STEPS 3      /**< forward-selection steps */
#define SG_ZCAP 40.0        /**< |z| counted at most this in aggregates */
#define SG_LAT_MAX 65536L   /**< differences used by the lattice statistic of a segment */
#define SG_ID_FRAC 0.1      /**< the baseline's AR(1) bump must lie within this fraction of a block */
#define SG_TEST_FRAC 0.25   /**< the gap tests use tau up to this fraction (the twins give the statistics) */
#define SG_NFFT_MAX 1024u   /**< longest Welch segment of the gap features (at least 16 segments per block) */
#ifndef SG_FIT_FLOOR
#define SG_FIT_FLOOR 0.003  /**< model-error floor of the Allan fits: sd of ln AVAR added to every point's */
#endif

/** Domains of the gap. */
enum { SG_ALLAN = 0, SG_PSD, SG_LATTICE, SG_TIMING, SG_NAV, SG_TIME, SG_NDOM };
/** Kinds of time-domain points (static logs, one of each per block of a
 *  segment; x_lo, x_hi the block's time span, s). */
enum {
    SG_TIME_TREND = 0, /**< least-squares slope over the block, u/s (Legendre P1) */
    SG_TIME_CURV,      /**< curvature: the Legendre P2 coefficient over the block, u */
    SG_TIME_STEP,      /**< ln(largest |lag-2 difference of SG_TD_K sub-block means| / its robust sd):
                            isolated steps make it large, Gaussian increments do not */
    SG_TIME_NKIND
};
/** The segment's level point (a two-block segment only, one per segment):
 *  the mean of the second block minus the mean of the first, u; x_lo the
 *  first block's start, x_hi the second's end, x_blk each block's length.
 *  A drift's strongest evidence over a sandwich's ends. */
#define SG_TIME_LEVEL SG_TIME_NKIND
#define SG_TD_K 32          /**< sub-blocks of a block for the step statistic */
/** Segments: the whole log, the fit segment, the held-out segment. */
enum { SG_FULL = 0, SG_FIT, SG_HOLD, SG_NSEG };
/** Kinds of navigation-domain points. */
enum {
    SG_NAV_NIS_FIRST = 0, /**< ln mean NIS of each stance's first zero-velocity update */
    SG_NAV_NIS_ALL,       /**< ln mean NIS of every update */
    SG_NAV_AXIS,          /**< ln mean normalised first innovation squared per n axis (x = axis) */
    SG_NAV_WHITE,         /**< lag-1 correlation of the normalised innovations within stances */
    SG_NAV_RESID,         /**< ln RMS residual velocity at mid-stance */
    SG_NAV_WIN,           /**< ln mean first NIS in a time window (x = window centre, s) */
    SG_NAV_DRIFT_H,       /**< ln horizontal drift at the end (closed walks) */
    SG_NAV_DRIFT_V,       /**< ln vertical drift at the end (closed walks) */
    SG_NAV_NKIND
};
/** Kinds of timing points. */
enum { SG_TIM_DUP = 0, SG_TIM_DROP, SG_TIM_JITTER, SG_TIM_NKIND };

/** Domain name ("allan", "psd", "lattice", "timing", "nav"). */
const char *sg_domain_name(int dom);
/** Time-domain kind name ("trend", "curvature", "steps"). */
const char *sg_time_kind_name(int kind);
/** Channel name ("ax" .. "gz"). */
const char *sg_channel_name(int ch);
/** Channel unit ("m/s^2" or "rad/s"). */
const char *sg_channel_unit(int ch);

/* ------------------------------------------------------------ points */

/** One statistic of one segment (e.g. ln AVAR of gz at tau = 0.04 s). */
typedef struct {
    int dom, ch, kind;
    double x, x_lo, x_hi;     /**< tau (s), band centre and edges (Hz), or time window (s) */
    uint32_t m, lag, n_phase; /**< Allan: averaging factor, lag and phase count at its level
                                   (of one block); PSD: first bin, bins, segment length */
    double edf;               /**< degrees of freedom of the estimate (0: no theory; Allan: computed
                                   at comparison time from the noise type) */
    double w;                 /**< weight of the estimate when blocks are pooled (terms, segments) */
    int nblk;                 /**< independent blocks pooled (EDF adds up) */
    double x_blk;             /**< time domain level point: length of each of the two blocks, s */
    int empty;                /**< no data behind it in the real log (a navigation window in
                                   which no stance begins: a long stand): outside G, z 0 */
    double t_peak_lo, t_peak_hi; /**< time domain `steps` of the real: sub-blocks i-1 to i+1 around
                                   its largest lag-2 difference d_i (a step inside sub-block i, a
                                   transient shorter than a sub-block inside i-1 or i+1), s; where
                                   the location reports it (0 elsewhere) */
} sg_point_t;

/** A list of points. */
typedef struct {
    size_t n, cap;
    sg_point_t *p;
} sg_plist_t;

void sg_plist_free(sg_plist_t *l);
int sg_plist_add(sg_plist_t *l, const sg_point_t *p);

/* ------------------------------------------------------------ features */

/** Settings of the static features (defaults: sg_feat_cfg_default()). */
typedef struct {
    double rate_hz;           /**< sample rate */
    unsigned allan_per_octave;/**< Allan grid density (2) */
    double tau_frac;          /**< largest tau as a fraction of the segment (SG_TEST_FRAC) */
    unsigned nfft_max;        /**< longest Welch segment (1024) */
    unsigned bands_per_octave;/**< spectral bands per octave (3) */
} sg_feat_cfg_t;

sg_feat_cfg_t sg_feat_cfg_default(double rate_hz);

/** Streaming features of one channel over one segment: Allan deviation,
 *  Welch PSD bands, the value lattice at a given step. */
typedef struct {
    fnav_allan_t *allan;
    fnav_welch_t *welch;
    uint32_t tau[FNAV_ALLAN_MAX_POINTS];
    size_t ntau;
    long n_expect, n;
    double q;                 /**< lattice step (0: none) */
    double lc, ls, prev;      /**< lattice sums, previous value */
    long lm;
    int have_prev;
    int lat_external;         /**< lattice sums set by the caller (lc, ls, lm), not pushed */
    /* time domain: Legendre sums over the block and the sub-block sums */
    int td;                   /**< time-domain points on (blocks of at least 16 SG_TD_K samples) */
    double t0_s;              /**< block start, s (set by sg_segacc_init) */
    double x0;                /**< first value (the sums are of x - x0) */
    double s1, s1q, s2, s2q;  /**< sum (x - x0) u, sum u^2, sum (x - x0) c, sum c^2 (u in [-1, 1], c = P2(u) centred) */
    double sub[SG_TD_K];      /**< sums of x - x0 per sub-block */
    long subn[SG_TD_K];
    sg_feat_cfg_t cfg;
} sg_acc_t;

/** Prepare features of a segment of n samples; q the lattice step (0: none).
 *  0, or -1 on memory / configuration failure. */
int sg_acc_init(sg_acc_t *a, const sg_feat_cfg_t *cfg, long n, double q);
void sg_acc_push(sg_acc_t *a, double x);
void sg_acc_free(sg_acc_t *a);
/**
 * Finish: append the points of channel ch (when pl is not NULL) and write
 * their values to vals (capacity cap; the count is returned, -1 on error).
 * Values: Allan ln AVAR, spectral ln(mean PSD of the band), lattice the
 * normal score of the Rayleigh statistic, time domain the trend, curvature
 * and step statistic of the block (SG_TIME_*; signed, so that twins of a
 * deterministic drift reproduce them and twins of a random one do not). Points are a function of the
 * segment length and settings only, so a twin of the same length yields the
 * same list.
 */
long sg_acc_finish(sg_acc_t *a, int ch, sg_plist_t *pl, double *vals, size_t cap);

/** Lattice step of a series: the smallest difference between consecutive
 *  values above 10 ulp, refined; 0 when there is none. Also the normal score
 *  of the lattice statistic at that step (*z). */
double sg_lattice_step(const double *x, size_t n, double *z);

/** Normal score of the lattice (Rayleigh) statistic of the differences of x
 *  at step q: exactly N(0, 1) for a continuous signal, large on a lattice. */
double sg_lattice_z(const double *x, size_t n, double q);

/** Normal score of a Rayleigh statistic R (exponential under the null):
 *  Phi^-1(1 - exp(-R)), asymptotic for large R; -8 for R <= 0. */
double sg_rayleigh_z(double R);

/* ------------------------------------------------------------ gap */

/** Comparison of one segment's real values with S twins. */
typedef struct {
    size_t n;                 /**< points */
    double *z;                /**< z-score per point */
    double *twin_mean, *twin_sd; /**< mean and spread of the twins per point */
    double *sd_tot;           /**< denominator of z */
    double *dev;              /**< deviation behind z: real - twin mean - the part the fitted
                               *   parameters' uncertainty explains (the Woodbury correction);
                               *   real - twin mean without refit shifts. Of z's sign */
    double G;                 /**< aggregate gap: mean over domains of mean min(z^2, SG_ZCAP^2) */
    double G_dom[SG_NDOM];    /**< per domain (NaN when the domain has no point) */
    double maxz;              /**< largest |z| */
    int imax;                 /**< its point */
    int S;                    /**< twins */
    double *G_null;           /**< G of each twin treated as the real (leave one out), S values */
    double null_mean, null_sd;  /**< null distribution of G */
    double G_crit;            /**< (1 - alpha) quantile of the null G (scaled chi-square); NaN when undefined */
    double z_crit;            /**< point threshold (Bonferroni over the points, alpha) */
    int significant;          /**< G > G_crit or maxz > z_crit; 0 when undefined */
    int undefined;            /**< the null of G has no distribution to test against (no critical
                               *   value, nothing significant): SG_CMP_EMPTY no point to compare
                               *   (a segment too short: G 0), SG_CMP_FLAT the twins do not vary
                               *   (every null G is 0: a noise-free model), SG_CMP_NONFINITE a
                               *   twin statistic is not finite; 0 otherwise */
} sg_cmp_t;

enum { SG_CMP_EMPTY = 1, SG_CMP_FLAT = 2, SG_CMP_NONFINITE = 3 };

/** Why a comparison is undefined, as a phrase ("" when it is defined). */
const char *sg_cmp_why(const sg_cmp_t *c);

void sg_cmp_free(sg_cmp_t *c);

/**
 * Compare real values with S twin rows (twin[s * n + j]).
 * @param vx    extra variance per point (the fitted model's parameter
 *              uncertainty), or NULL
 * @param shift S rows: how much the model refitted to twin s moves each
 *              point's expectation (the null's twin-as-real carries it), or NULL
 * @param alpha family-wise level of the point test (0.05 / channels)
 * @return 0 (out->undefined says whether the test is defined), -1 on
 *         memory failure.
 */
int sg_compare(const sg_plist_t *pl, const double *real, const double *twin, int S, const double *vx,
               const double *shift, double alpha, sg_cmp_t *out);

/** G of the real against a subset of twin seeds (bootstrap helper):
 *  idx[k], k < S2, are seed indices (with repeats). */
double sg_gap_resampled(const sg_plist_t *pl, const double *real, const double *twin, int S, const int *idx, int S2,
                        const double *vx, const double *shift);

/**
 * Explained fraction of the excess gap (G_a - null mean) by going from twins
 * a to twins b (paired seeds), with a 68 % bootstrap interval f +- se that
 * carries the twins' seeds and the real's own noise (each resample's real
 * perturbed by one of b's twins as a real; docs/simgap.md, section 4); NaN
 * when G_a is within two null standard deviations (no excess).
 */
void sg_explained(const sg_plist_t *pl, const double *real, const double *ta, const double *va, const double *sa,
                  const double *tb, const double *vb, const double *sb, int S, double null_mean, double null_sd,
                  double *f, double *lo, double *hi, uint32_t seed);

/**
 * Score test of going from model a to model b on one segment: the real's
 * deviation from a's twins projected on the signature b - a (each point
 * weighted by its noise variance from ca), against the same projection of
 * each twin of a taken as the real. Returns z; the statistic and its null
 * mean and sd through the pointers.
 */
double sg_score_test(const sg_plist_t *pl, const double *real, const sg_cmp_t *ca, const double *ta, const double *sa,
                     const double *tb, int S, double *t_real, double *t_mean, double *t_sd);

/**
 * Likelihood-ratio test of going from model a to model b on one segment:
 * the drop of the Gaussian deviance (G plus the mean ln of the points'
 * variances, with G's weights) from a's twins to b's, for the real, against
 * the same drop for each twin of a taken as the real (against the other
 * twins of a and of b: b's paired seed shares its noise). A parametric
 * bootstrap of the likelihood ratio: it sees effects that change the
 * spread or the shape of a statistic (sparse steps) as well as those that
 * shift its mean, which sg_score_test projects on, and the ln-variance term
 * charges a model for the spread it adds, so a wider twin does not win by
 * being wide. Returns z; the real's deviance drop through drop (or NULL).
 */
double sg_lr_test(const sg_plist_t *pl, const double *real, const double *ta, const double *va, const double *sa,
                  const double *tb, const double *vb, const double *sb, int S, double *drop);

/* ------------------------------------------------------------ models */

/** One effect of a channel model: catalogue id and parameter values in the
 *  catalogue's parameter order (per-channel ones hold this channel's value). */
typedef struct {
    int id;                   /**< fnav_effect_id_t */
    double p[SG_MAX_PAR];
    double se[SG_MAX_PAR];    /**< standard errors (NaN: unknown) */
    int se_allan[SG_MAX_PAR]; /**< se[k] is the Allan fit's Gauss-Newton value, which treats the
                                   overlapping Allan points as independent (too small); the twins'
                                   refits replace it (sg_se_from_refits) */
    int nrefit[SG_MAX_PAR];   /**< the number of twins' refits se[k] is the standard deviation of
                                   (sg_se_from_refits); 0: se[k] is not from refits */
    double ci_lo[SG_MAX_PAR], ci_hi[SG_MAX_PAR]; /**< the 16th and 84th percentiles of those refits
                                   (hx_quantile_sorted), the 68 % of them in between; NaN with fewer
                                   than SG_CI_MIN_REFITS. Reporting only, as se */
    double lo[SG_MAX_PAR], hi[SG_MAX_PAR]; /**< the interval the fit searched the parameter in (its
                                   unit; lo = hi = 0: not searched within bounds): the thermal tau_s,
                                   an rrw's or a flicker's magnitude refined by likelihood */
    int at_bound[SG_MAX_PAR]; /**< the fit left it at a bound of that interval (sg_param_at_bound):
                                   -1 the lower (the value is only an upper limit), +1 the upper
                                   (only a lower limit), 0 inside or not searched. Reporting only:
                                   the summary says so, the JSON's `bounds` too, with no se */
} sg_effect_t;

/** Relative distance within which a searched parameter counts as at a
 *  bound of its search (0.1 %, as the AR(1) time's sg_ar1_at_min and
 *  sg_ar1_at_max): the golden sections stop within 0.05 % (ln 5e-4) of a
 *  bound the optimum lies at or beyond, a grid point on it. */
#define SG_BOUND_REL 1e-3

/** Side of the search interval [lo, hi] (lo > 0) a fitted value v lies at:
 *  -1 when v <= lo (1 + SG_BOUND_REL), +1 when v >= hi (1 - SG_BOUND_REL),
 *  0 inside, or when the interval is not set (lo, hi not positive). */
int sg_param_at_bound(double v, double lo, double hi);

/** Model of one channel of a static log: the value at rest plus effects
 *  (white and ar1 are the baseline). */
typedef struct {
    double mean;
    int n;
    sg_effect_t e[SG_MAX_EFF];
} sg_chmodel_t;

/** The fewest refits a 68 % percentile interval is given from: the 16th
 *  percentile of n values lies at order statistic 1 + 0.16 (n - 1) (the
 *  84th symmetrically), so from n = 8 (1 + 0.16 x 7 = 2.12) an end
 *  interpolates between the 2nd and 3rd smallest (largest) refits and owes
 *  nothing to the single most extreme one; below 8 the extreme refit
 *  enters with weight 1 - 0.16 (n - 1) (0.04 at n = 7, 0.20 at 6, 0.36 at
 *  5, 0.52 at 4). */
#define SG_CI_MIN_REFITS 8

/** The most twins per model (`--seeds` of simgap and simgap-validate);
 *  sg_se_from_refits counts at most this many refits. */
#define SG_MAX_TWINS 60

/** One more than the largest offset a diagnosis adds to its --seed S
 *  (docs/simgap.md "What `--seed` seeds"): S + 7000 + 1000 c + r, c <= 5,
 *  r < ceil(SG_MAX_TWINS / 6), is 12,009 (the profile's static twins);
 *  the bootstrap's S + 1000 c + 17 is 5,017, a walk's S + 7777 + k,
 *  k < SG_MAX_TWINS, 7,836. A diagnosis draws from the seeds S ...
 *  S + SG_SEED_SPAN - 1 (mod 2^32) only. */
#define SG_SEED_SPAN 12010u

/** Standard errors of the Allan fit's parameters from the twins' refits
 *  (a parametric bootstrap: docs/simgap.md, section 3): every parameter of
 *  m whose se the Allan fit gave (se_allan) gets the sample standard
 *  deviation of the same parameter over fits[s] with ok[s] (S refits of
 *  the same model on twins simulated from m), and its se_allan cleared; an
 *  effect's other parameters (the AR(1) time) count only the refits whose
 *  magnitude is not zero; fewer than 3 values leave se NaN. Beside
 *  each such se: the number of refits (nrefit) and their 16th and 84th
 *  percentiles (ci_lo, ci_hi; from SG_CI_MIN_REFITS values, else NaN); at
 *  most SG_MAX_TWINS refits are counted. Other
 *  standard errors (a drift's, a likelihood's) and NaN ones stay as they
 *  are. Reporting only: no decision reads se. */
void sg_se_from_refits(sg_chmodel_t *m, const sg_chmodel_t *fits, const int *ok, int S);
/** 1 when parameter k of e has the refits' 68 % interval beside its se
 *  (a finite se from at least SG_CI_MIN_REFITS refits), else 0. */
int sg_has_ci(const sg_effect_t *e, int k);

/** Find an effect in a model (index or -1). */
int sg_model_find(const sg_chmodel_t *m, int id);
/** Add or replace an effect. 0, -1 when full. */
int sg_model_set(sg_chmodel_t *m, const sg_effect_t *e);

/**
 * Build a simulator configuration that applies channel model m to all six
 * simulator channels (six independent realisations of the same channel).
 */
int sg_model_imuerr(const sg_chmodel_t *m, double rate_hz, uint32_t seed, fnav_imuerr_config_t *cfg);

/* ------------------------------------------------------------ twin */

#define SG_MAX_BLK 2 /**< blocks of one segment */

/** Segments of a log: each one or two blocks [start, start + n). */
typedef struct {
    int nb[SG_NSEG];
    long start[SG_NSEG][SG_MAX_BLK], n[SG_NSEG][SG_MAX_BLK];
    long total[SG_NSEG];      /**< samples of the segment */
    int sandwich;             /**< 1: fit = both ends, held out = the middle */
} sg_segs_t;

/**
 * Split n samples, frac of them to the fit segment: contiguous (fit = the
 * first frac, held out = the rest) or sandwich (fit = the first and the
 * last frac/2, held out = the middle; a transient at the start and the late
 * behaviour are then in both). The whole log is SG_FULL.
 */
void sg_segs_split(long n, double frac, int sandwich, sg_segs_t *s);
/** Block of segment g holding sample k, or -1. */
int sg_segs_block(const sg_segs_t *s, int g, long k);
/** Shortest block of a segment, samples. */
long sg_segs_minblock(const sg_segs_t *s, int g);

/** Features of a segment of one or two blocks (pooled: Allan variances
 *  weighted by their terms, Welch spectra by their segments, lattice sums
 *  added; degrees of freedom add up). */
typedef struct {
    int nb;
    sg_acc_t b[SG_MAX_BLK];
} sg_segacc_t;

int sg_segacc_init(sg_segacc_t *a, const sg_feat_cfg_t *cfg, const sg_segs_t *s, int g, double q);
void sg_segacc_push(sg_segacc_t *a, int blk, double x);
long sg_segacc_finish(sg_segacc_t *a, int ch, sg_plist_t *pl, double *vals, size_t cap);
void sg_segacc_free(sg_segacc_t *a);

/**
 * Simulate S static twins of one channel model over the segments and
 * return their features: vals[seg][s * npts[seg] + j] with the point lists
 * pl[seg] (the real's lists, checked). seed0 + run is the simulator seed of
 * each run of six twins.
 * @return 0, -1 on failure.
 */
int sg_twin_static(const sg_chmodel_t *m, int ch, const sg_feat_cfg_t *fc, const sg_segs_t *segs, double q, int S,
                   uint32_t seed0, const sg_plist_t pl[SG_NSEG], double *vals[SG_NSEG]);

/* ------------------------------------------------------------ fitting */

/** Evidence of the special estimators on a channel's fit segment. */
typedef struct {
    double q, q_z;            /**< lattice step and its normal score */
    double tone_hz, tone_amp, tone_phase, tone_score; /**< strongest line, amplitude, phase at sample 0,
                                                           -log10 of its false-alarm probability */
    int nsteps;               /**< bias steps detected */
    double step_rms;          /**< their RMS size */
    double step_min;          /**< smallest step size the detector finds (its threshold at the best scale), u */
    double span_s;            /**< time the detector searched (the fit segment), s */
    double slope;             /**< least-squares slope of the fit segment, u/s */
} sg_evidence_t;

/** Fit result of one model on the fit segment's Allan table. */
typedef struct {
    sg_chmodel_t model;
    double Q;                 /**< weighted sum of squared log residuals (Allan) */
    double Q_time;            /**< the time points' Gaussian deviance: squared residuals over the
                                   baseline twins' variances widened by the model's slow random parts
                                   beyond the baseline's, plus the log of the widening (0 without
                                   twins): what a drift or a random drift explains */
    double Q_time_drift;      /**< the same residuals over the baseline twins' variances alone: what a
                                   drift explains, whatever random parts the model holds */
    int npts;
    int ok;
} sg_fit_t;

/** Time points of a fit table: trend and curvature per block, one level. */
#define SG_TAB_NT (2 * SG_MAX_BLK + 1)

/** Allan table of a segment for fitting: ln AVAR, m, EDF of each point. */
typedef struct {
    size_t n;
    double lnav[FNAV_ALLAN_MAX_POINTS];
    double m[FNAV_ALLAN_MAX_POINTS];
    double w[FNAV_ALLAN_MAX_POINTS]; /**< 1 / var(ln AVAR) */
    double rate_hz;
    int nb;                   /**< blocks of the segment */
    double t0_s[SG_MAX_BLK], t1_s[SG_MAX_BLK]; /**< their time spans (for thermal) */
    /* time domain: the blocks' trends and curvatures and the ends' level,
     * which fix the deterministic drifts (ramp, thermal) with their signs */
    int nt;
    int tkind[SG_TAB_NT];               /**< SG_TIME_TREND, SG_TIME_CURV or SG_TIME_LEVEL */
    size_t tidx[SG_TAB_NT];             /**< index of the point in the list */
    double ty[SG_TAB_NT];               /**< value (u/s or u) */
    double tw[SG_TAB_NT];               /**< 1 / variance (white-noise shape unless set from twins) */
    double tlo[SG_TAB_NT], thi[SG_TAB_NT], tblk[SG_TAB_NT]; /**< span and (level) block length, s */
    int tw_twins;                       /**< tw are 1 / the twins' variances (absolute) */
    double tvb[SG_TAB_NT];              /**< variance of each time point from the baseline model's slow
                                             random parts (AR(1), flicker, rrw, jumps), u^2 (or (u/s)^2) */
    int tvb_set;                        /**< tvb holds the baseline's variances */
} sg_table_t;

/** Allan table of the Allan points of channel ch in a point list / values,
 *  every tau of the tests (SG_TEST_FRAC of the shortest block of segment g:
 *  the long-tau points weigh little, by their EDF, but carry the slow
 *  effects' signatures; the AR(1) time bound still follows SG_ID_FRAC). */
void sg_table_from(const sg_plist_t *pl, const double *vals, int ch, double rate_hz, const sg_segs_t *segs, int g,
                   sg_table_t *t);

/** Weighted residual of the time-domain fit of a ramp alone (thermal 0)
 *  or a warm-up alone (thermal 1) to a table's time points, in the
 *  twins' variances (chi-square-like); NAN without twin weights. */
double sg_time_fit_q(const sg_table_t *t, int thermal);

/** Weights of a table's time-domain points from the twins' spread of each
 *  point of the same list (sd[j], a comparison's twin_sd): 1 / sd^2. */
void sg_table_time_weights(sg_table_t *t, const double *sd);

/** Variances of a table's time points under the baseline model's slow
 *  random parts (sg_table_t.tvb): what the prescreen's time-point deviance
 *  of a candidate model is measured against (a random drift candidate
 *  explains a trend by widening its spread, at the price of the log of the
 *  widening). */
void sg_table_time_base(sg_table_t *t, const sg_chmodel_t *base);

/**
 * Fit white + AR(1) (correlation time at most tmax_s) plus the effects
 * listed in `with` (ids; their non-Allan parameters taken from ev) to a
 * table. The fitted model keeps `mean`.
 */
int sg_fit_model(const sg_table_t *t, double mean, const int *with, int nwith, const sg_evidence_t *ev, double tmax_s,
                 sg_fit_t *out);

/**
 * Refine the rate random walk's K of a model by the exact likelihood of
 * segment g of the samples x (white + AR(1) + walk as a Kalman filter, the
 * deterministic drifts removed, the other parameters held). Returns 0 when
 * K was refined, 1 when the model has no walk or parts without a
 * state-space form (the Allan fit's K stands).
 */
int sg_rrw_ml(const double *x, const sg_segs_t *segs, int g, double rate_hz, sg_chmodel_t *m);

/**
 * -2 ln L (without the constant n ln 2 pi) of nblk independent series dd[b]
 * of lengths nd[b] <= 400, each stationary Gaussian with autocovariance
 * acv[0 .. max nd - 1], by the Durbin-Levinson recursion (O(n^2)): the sum of
 * ln v_k + e_k^2 / v_k over the one-step prediction errors e_k and their
 * variances v_k. INFINITY when acv is not positive definite; NaN when a
 * series is too long.
 */
double sg_toeplitz_nll2(const double *acv, int nblk, const int *nd, const double *const *dd);

/**
 * Fit the magnitude of a flicker's B or a walk's K (id) in m by the exact
 * Gaussian likelihood of the first differences of the block means of
 * segment g of x (the deterministic drifts removed, every other parameter
 * held; at most 401 block means per block), by golden section in
 * ln magnitude within a factor 30 of the starting value; its se from the
 * curvature of -2 ln L. Returns 0 with *nll2 = -2 ln L at the fit, 1 when
 * the model has no such effect or a part without a closed-form
 * autocovariance here (vibration and other deterministic tones).
 */
int sg_bm_fit(const double *x, const sg_segs_t *segs, int g, double rate_hz, sg_chmodel_t *m, int id, double *nll2);

/** Allan variance of an effect per unit magnitude squared (its other
 *  parameters from e) at averaging factor m over [t0_s, t1_s]; 0 for
 *  effects without a static Allan signature. */
double sg_effect_avar_unit(const sg_effect_t *e, double rate_hz, double m, double t0_s, double t1_s);

/** Exact Allan variance of a channel model at averaging factor m over a
 *  segment spanning [t0_s, t1_s] (thermal depends on it). */
double sg_model_avar(const sg_chmodel_t *mdl, double rate_hz, double m, double t0_s, double t1_s);
/** The same pooled over nb blocks (weights: their terms). */
double sg_model_avar_blocks(const sg_chmodel_t *mdl, double rate_hz, double m, int nb, const double *t0_s,
                            const double *t1_s);

/** Expected statistic of a point under a model: ln AVAR (Allan), ln of
 *  the band's mean one-sided PSD (spectral, continuous-time shapes), or the
 *  trend and curvature of the model's deterministic drift over the block
 *  (time domain); NaN for other points. Used for the spread of refitted models. */
double sg_model_lnstat(const sg_chmodel_t *mdl, const sg_point_t *p, double rate_hz, int nb, const double *t0_s,
                       const double *t1_s);

/** Gather the special-estimator evidence of the fit segment of x (lines in
 *  its first block, which starts at sample 0; steps in every block; the
 *  slope over all of it). */
void sg_evidence(const double *x, const sg_segs_t *segs, double rate_hz, double q_hint, sg_evidence_t *ev);
/** The same on segment g (SG_FIT or SG_HOLD): the second fold, fitted on
 *  the middle, takes its evidence from the middle (a line's phase is
 *  referred back to sample 0 of the log). */
void sg_evidence_seg(const double *x, const sg_segs_t *segs, int g, double rate_hz, double q_hint, sg_evidence_t *ev);

/* ------------------------------------------------------------ diagnosis */

/** Options of a diagnosis. */
typedef struct {
    int domain;               /**< 0 detect, 1 static, 2 walk */
    int seeds;                /**< baseline twins (12) */
    int seeds_cand;           /**< twins per candidate (12) */
    int prescreen;            /**< candidates simulated per step (3) */
    double fit_frac;          /**< fit segment fraction (0.6) */
    int contiguous;           /**< static logs: fit on the first part instead of both ends */
    double alpha;             /**< family-wise false-alarm level (0.05) */
    uint32_t seed;            /**< first simulator seed */
    int max_steps;            /**< forward-selection steps (3) */
    int quiet;                /**< no progress */
    const char *cmd;          /**< command name for messages */
    const char *profile;      /**< walk: baseline noise profile (NULL: from the stances); static: a given
                                   white + AR(1) model compared with the log besides the fitted
                                   baseline (a parameterisation check, e.g. the paper's Fig. 7) */
    int closed;               /**< walk: the walk ends where it started (drift check) */
} sg_opts_t;

sg_opts_t sg_opts_default(void);

/** One location of a gap. */
typedef struct {
    int dom, ch, kind, seg;
    double x_lo, x_hi;        /**< tau (s), frequency (Hz) or time (s) range */
    double peak_z;            /**< signed z at the peak */
    double ratio;             /**< at the peak: real / twin of the deviation (Allan) or amplitude (PSD);
                                   real - twin for the time domain and the lattice score */
    int npts;
} sg_loc_t;

/** Locations (docs/simgap.md, section 3, "Locations"): runs of consecutive
 *  points of list pl (channel ch, segment seg) and one domain (and, in the
 *  time domain, one kind) with |z| > 2.5 of one sign that hold a point
 *  beyond the critical z of the comparison c, appended to loc (count
 *  *nloc, capacity cap; those beyond it counted in *dropped). */
void sg_locate_into(const sg_plist_t *pl, int ch, int seg, const sg_cmp_t *c, sg_loc_t *loc, size_t *nloc,
                    size_t cap, size_t *dropped);

/** One candidate tried in a step. */
typedef struct {
    int id;
    sg_effect_t eff;          /**< fitted parameters */
    double Q_fit;             /**< fit-segment objective with it */
    double dQ_fit;            /**< improvement of the fit-segment objective over the current model */
    int simulated;
    double G_fit, G_hold;     /**< gaps with it */
    double expl_hold, expl_lo, expl_hi; /**< explained fraction of the held-out excess gap, 68 % interval */
    double expl_fit;
    double dG_hold;           /**< held-out gap reduction of the real */
    double t_hold;            /**< score statistic: the held-out deviation projected on the effect's signature */
    double t_null_mean, t_null_sd; /**< ... of the twins taken as real (no effect): its null distribution */
    double z_delta;           /**< significance of the effect on held-out data: z_mid, or with a sandwich
                                   split (z_mid + z_ends) / sqrt 2 (both folds, Stouffer) */
    double z_mid;             /**< (t_hold - null mean) / null sd: fitted on the ends, held out the middle */
    double z_ends;            /**< the same, fitted on the middle, held out the ends (NaN: no second fold) */
    double dG_ends;           /**< the ends' gap reduction in the second fold (NaN: none) */
    double dG_rank;           /**< held-out gap reduction that ranks effects: dG_hold, plus dG_ends with a
                                   second fold */
    double zg_mid, zg_ends;   /**< likelihood-ratio test (sg_lr_test) per fold (NaN: no second fold) */
    double z_gap;             /**< the two folds' likelihood-ratio z combined (Stouffer) */
    double dL_mid, dL_ends;   /**< the real's deviance drop per fold (NaN: no second fold) */
    double dL_rank;           /**< their sum: what ranks the accepted candidates */
    int nested;               /**< thermal only: its warm-up fits the fit segment's time points no
                                   better than a ramp (chi-square_1 at 1 %); not simulated, the ramp stands for it */
} sg_cand_t;

/** Critical z of a candidate's acceptance tests (docs/simgap.md, section 4,
 *  step 5): Student's t^-1(1 - alpha / (6 * 5 * 2), seeds - 1), Bonferroni
 *  over the six channels, about five candidates and the two tests (score
 *  and likelihood ratio), the null's spread from `seeds` twins. */
double sg_accept_zcrit(double alpha, int seeds);

/** Whether candidate cd passes the acceptance test at the critical z zacc
 *  (sg_accept_zcrit): its score test's z (z_delta) or its likelihood-ratio
 *  test's (z_gap) beyond zacc, and the lower end of the 68 % interval of
 *  its explained fraction (expl_lo) above 0 where the fraction is defined
 *  (NaN, no held-out excess: accepted on its z alone). 1 or 0. */
int sg_cand_accepted(const sg_cand_t *cd, double zacc);

/** Stopping rule (a) of the forward selection (docs/simgap.md, section 4,
 *  "Stopping rule"): 1 when a step has been taken (step > 0) and the
 *  current model's held-out gap is no longer significant
 *  (held_significant 0), else 0. The first step (step 0) is always tried:
 *  a candidate's held-out tests over both folds may confirm an effect
 *  whose middle shows no excess (accepted on its z alone). */
int sg_selection_stops(int step, int held_significant);

/** Parsimony between nested drifts (docs/simgap.md, section 4): 1 when the
 *  warm-up's time fit (q_thermal, sg_time_fit_q(tab, 1)) beats the ramp's
 *  (q_ramp, sg_time_fit_q(tab, 0)) by less than chi-square_1 at 1 %
 *  (6.63): thermal is not simulated, the ramp stands for it. 0 when either
 *  q is NaN. */
int sg_thermal_nested(double q_ramp, double q_thermal);

/** Enters the second fold's results into candidate cd (docs/simgap.md,
 *  section 4, steps 4-5): z_ends, dG_ends, zg_ends, dL_ends; dL_rank gains
 *  dLb; z_delta and z_gap become the Stouffer combinations
 *  (z_mid + zb) / sqrt(2) and (zg_mid + zgb) / sqrt(2). cd's z_mid, zg_mid
 *  and dL_rank hold fold 1's values on entry. */
void sg_cand_fold2(sg_cand_t *cd, double zb, double dGb, double zgb, double dLb);

/** One forward-selection step of a channel. */
typedef struct {
    int ncand;
    sg_cand_t cand[FNAV_EFFECT_COUNT];
    int selected;             /**< index into cand, -1 none */
    double G_hold_before, G_fit_before;
} sg_step_t;

/** Diagnosis of one channel. */
typedef struct {
    int active;               /**< channel present and analysed */
    sg_chmodel_t baseline;    /**< fitted baseline */
    sg_chmodel_t final;       /**< baseline + selected effects, refitted */
    double ar1_tau_max_s;     /**< longest AR(1) time the baseline may take: a quarter of the longest Allan
                               *   tau analysed on both segments (section 1 of docs/simgap.md) */
    sg_evidence_t ev;         /**< evidence of the fit segment */
    sg_evidence_t ev_mid;     /**< of the held-out segment (sandwich split: the second fold's fit) */
    double q_full, q_full_z;  /**< lattice on the whole log */
    sg_cmp_t cmp[SG_NSEG];    /**< baseline vs real */
    sg_cmp_t cmp_final[SG_NSEG]; /**< final model vs real */
    int nsteps;
    sg_step_t step[SG_MAX_STEPS];
    int nsel;
    int sel_id[SG_MAX_STEPS];
    double sel_expl[SG_MAX_STEPS], sel_lo[SG_MAX_STEPS], sel_hi[SG_MAX_STEPS];
    int nzero;                /**< effects accepted at a step whose magnitude the later refits set to 0 */
    int zero_id[SG_MAX_STEPS]; /**< their ids (left out of the selection: the final model gives them nothing) */
    int within_noise;         /**< held-out gap of the final model within the null band */
    int gap_full;             /**< significant gap on the whole log with the baseline */
    int gap_hold;             /**< ... on the held-out segment */
    int gap;                  /**< a gap: either of the above, or an effect selected on held-out evidence */
    int have_prof;            /**< static logs with --profile: the profile's model compared too */
    sg_chmodel_t prof;        /**< the profile's white + AR(1) model of this channel (not fitted) */
    sg_cmp_t cmp_prof[SG_NSEG]; /**< profile model twins vs real (no parameter uncertainty: given) */
} sg_chres_t;

/** Fraction of the fit segment's excess gap (G_before - null_mean) that a
 *  candidate removes (G_before - G_after) / (G_before - null_mean); NaN
 *  where the fit segment has no excess (G_before <= null_mean): undefined,
 *  as the held-out fraction is (null in the JSON). */
double sg_fit_explained(double G_before, double null_mean, double G_after);

/** 1 when the channel's baseline has an AR(1) bias whose correlation time
 *  is at its bound ar1_tau_max_s (within 0.1 %): the log cannot tell a
 *  longer one, which looks like a random walk over the record. */
int sg_ar1_at_max(const sg_chres_t *c);

/** Shortest AR(1) correlation time the baseline fit may take at rate_hz:
 *  one sample or the catalogue's shortest (1 ms), whichever is longer (the
 *  twin must be one the simulator runs; section 1 of docs/simgap.md). */
double sg_ar1_tau_min(double rate_hz);

/** 1 when the channel's baseline has an AR(1) bias whose correlation time
 *  is at the shortest the fit may take (within 0.1 %): the optimum lies at
 *  or below it, so the time is a bound, not a fit, as at ar1_tau_max_s. */
int sg_ar1_at_min(const sg_chres_t *c, double rate_hz);

/** Leave out of a channel's selection the effects its final (refitted)
 *  model gives a magnitude of exactly zero (into zero_id). */
void sg_prune_zero(sg_chres_t *c);

/** Timing-domain result. */
typedef struct {
    int have;                 /**< the log has time stamps */
    double res_s;             /**< time-stamp resolution found */
    long n_dup[SG_NSEG], n_drop[SG_NSEG], n_int[SG_NSEG];
    double jit_sd[SG_NSEG];   /**< sd of interval - nominal over regular intervals, s */
    double jit_kurt[SG_NSEG]; /**< their kurtosis (3 when too few): the log-variance tests' spread */
    /** the drops and duplicates the jitter's own Gaussian tails make
     *  expected (intervals beyond 1.5 or under 0.1 nominal periods, from
     *  the regular intervals' quartiles corrected for the cut): the
     *  counts' null; 0 where the jitter is not significant or not resolved */
    double tail_drop[SG_NSEG], tail_dup[SG_NSEG];
    double tail_drop_var[SG_NSEG], tail_dup_var[SG_NSEG]; /**< their variances as estimates */
    double z[SG_NSEG][SG_TIM_NKIND];
    int significant;
    double dup_prob, drop_prob, stamp_s;   /**< fitted on the fit segment */
    double z_after[SG_TIM_NKIND];          /**< held-out z with the fitted effects */
    int sel[SG_TIM_NKIND];
    double z_crit;                         /**< the held-out check's critical |z| (alpha / 3, two-sided) */
    int open[SG_TIM_NKIND];                /**< selected, but |z_after| > z_crit: the held-out segment's
                                                rate differs from the fit's (not stationary) */
    double first_t[SG_TIM_NKIND];          /**< time of the first event */
} sg_timing_t;

/** The timing domain of a log with stamps of its own (docs/simgap.md,
 *  section 4, "Timing domain"), its segments segs, at the family-wise
 *  level alpha: counts and z-scores per segment, the effects selected
 *  (whole-log z beyond the one-sided critical value of the family of
 *  three, Phi^-1(1 - alpha / 3)), their rates fitted on the fit segment and
 *  the held-out check (|z| beyond Phi^-1(1 - alpha / 6)). A log without
 *  stamps of its own or with fewer than 16 samples: t->have 0. */
void sg_timing_analyse(const hx_log_t *lg, double rate, const sg_segs_t *segs, double alpha, sg_timing_t *t);

/** Whole result. */
typedef struct {
    char path[512];
    int complete;             /**< the log was read to its end (else input_error says where it stopped) */
    char input_error[HX_ERR_SIZE];    /**< the reader's error when not complete: the diagnosis covers the samples before it */
    int domain;               /**< 1 static, 2 walk */
    int domain_detected;
    double rate_hz;
    long n;
    double duration_s;
    sg_segs_t segs;
    double seg_start_s[SG_NSEG][SG_MAX_BLK]; /**< each block's first sample, s from the log's first (its stamps) */
    double seg_end_s[SG_NSEG][SG_MAX_BLK];   /**< ... the sample after its last (the last's + 1/rate at the log's end) */
    sg_opts_t opts;
    int confident;
    char why[512];            /**< too short: why */
    double tau_span_dec[SG_NCH]; /**< decades of tau with a tight interval on the held-out segment */
    int constant[SG_NCH];     /**< the channel holds one value over the whole log (stuck, or its noise
                                   below the output's step): nothing to test; static logs: not analysed */
    double constant_value[SG_NCH]; /**< ... that value, u */
    int seg_constant[SG_NCH]; /**< static logs: SG_FIT or SG_HOLD when the channel, not constant over the
                                   whole log, holds one value over that segment (nothing to fit or to
                                   test there): not analysed, the other channels are; 0 otherwise */
    double seg_constant_value[SG_NCH]; /**< ... that value, u */
    sg_chres_t ch[SG_NCH];
    sg_plist_t pl[SG_NCH][SG_NSEG];      /**< points per channel and segment */
    double *real[SG_NCH][SG_NSEG];       /**< real values */
    double *twin[SG_NCH][SG_NSEG];       /**< baseline twins, S rows */
    double *twin_final[SG_NCH][SG_NSEG]; /**< final-model twins (NULL: the baseline's) */
    double *vx[SG_NCH][SG_NSEG];         /**< parameter-uncertainty variance per point, baseline */
    double *vx_final[SG_NCH][SG_NSEG];   /**< ... final model */
    double *sh[SG_NCH][SG_NSEG];         /**< refit shifts of the baseline twins (S rows) */
    double *sh_final[SG_NCH][SG_NSEG];   /**< ... final model */
    int S;
    sg_timing_t tim;
    int stamps_made;           /**< the log's format has no time stamps (hx_meta_t.stamps_made): timing not analysed */
    size_t nloc;
    sg_loc_t loc[512];        /**< whole log and held out, every channel (room for all: with 64
                                   the last channels' would be dropped) */
    size_t nloc_dropped;      /**< locations beyond the capacity: counted, said */
    char verdict[32];         /**< none, explained, partly-explained, unexplained, too-short */
    char prof_name[64];       /**< static logs with --profile: its name */
    size_t nploc;
    sg_loc_t ploc[512];       /**< where the profile's model misses the log (whole log) */
    double elapsed_s;
    void *nav;                /**< walk-domain result (hx_simgap_nav.h) */
} sg_result_t;

/** Run the whole diagnosis on a loaded log. 0, or -1 with err filled. */
int sg_diagnose(const hx_log_t *log, const char *path, const sg_opts_t *o, sg_result_t *r, char *err, size_t err_size);
void sg_result_free(sg_result_t *r);

/** Static or walk: stillness over the whole log (1 static, 2 walk). */
int sg_detect_domain(const hx_log_t *log, double rate_hz);

/** Time stamps in bursts (either kind of hx_stamp_bursts over the log's
 *  first HX_STAMPS_PROBE_N stamps, with the navigator's default time jump,
 *  as replay's test and allan's): the log's rate, 1 / the median interval
 *  of the distinct stamps, is then no sampling rate. A walk (domain 2, or
 *  0 and detected as one at the rate of the whole packets, which the wrong
 *  rate's one-second windows hide) cannot be navigated or twinned: -1 with
 *  the cause and the --input-rate remedy in err (replay's message). A
 *  static log is warned as allan and psd warn (the taus and frequencies at
 *  the wrong rate): 0, as for stamps without bursts. */
int sg_stamps_check(const hx_log_t *log, const char *path, int domain, char *err, size_t err_size);

/** Nominal rate of a log (meta, else hx_stamp_rate_hz of its stamps). */
double sg_log_rate(const hx_log_t *log);

/** One effect with its parameters as text ("quant (lsb ..., plain rounding)"). */
void sg_effect_text(char *b, size_t n, int ch, const sg_effect_t *e);

/** Text summary. */
void sg_print_summary(FILE *f, const sg_result_t *r);

/** Why a static channel with a gap has no accepted effect (logs with a
 *  confident answer): SG_UNCONF_NOT_HELD_OUT, the whole log's gap does not
 *  show on the held-out segment, so no effect can be confirmed there;
 *  SG_UNCONF_NO_EFFECT, a held-out gap that no candidate reduces;
 *  SG_UNCONF_NONE otherwise. *lead: the simulated candidate of the first
 *  step the fit segment supports most (largest fit dQ), or NULL. */
enum { SG_UNCONF_NONE = 0, SG_UNCONF_NOT_HELD_OUT = 1, SG_UNCONF_NO_EFFECT = 2 };
int sg_unconfirmed(const sg_result_t *r, int ch, const sg_cand_t **lead);
/** JSON report (schema in docs/simgap.md). 0, -1 on failure (err). */
int sg_write_json(const sg_result_t *r, const char *path, char *err, size_t err_size);
/** Plots into a directory. 0, -1 on failure (printed). */
int sg_write_plots(const sg_result_t *r, const char *dir, const char *cmd);

#endif /* HX_SIMGAP_H */
