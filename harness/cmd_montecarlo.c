/* harness montecarlo: N seeds of a simulated motion through the navigation
 * filter; error growth with time and distance and the filter's consistency
 * (NEES against its chi-square band). docs/simulator.md, "Monte Carlo"; docs/results-sim.md. */
#include <cjson/cJSON.h>
#include <errno.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_mc.h"
#include "hx_profile.h"
#include "hx_sim.h"

#include "footnav/fnav_nav.h"
#include "hx_nav.h"

static const hx_opt_t k_opts[] = {
    HX_SIM_OPTS,
    { "--seeds", "N", "number of runs, 1 to 100000 (seeds seed .. seed+N-1; default 50)", 0 },
    { "--filter-profile", "NAME|FILE", "the filter's sensor profile, taken as given (default: --profile, read with --bias-sigma; navchip, as given, for --profile none)", 0 },
    { "--bias-model", "MODEL", "filter bias model: ar1 (default), off, or both (paired, on the same samples)", 0 },
    { "--detector", "KIND", "stance detector: shoe (default) or threshold", 0 },
    { "--samples", "KIND", "what the filter takes a sample for: instant or mean (default: what --decimation makes)", 0 },
    { "--param", "KEY=VALUE", "set a navigation parameter (list: --param help)", 1 },
    { "--bin", "S", "time bin of the growth curves, s (default 1; at least the sample interval)", 0 },
    { "--json", "FILE", "results as JSON (keys: docs/simulator.md, \"Monte Carlo\"; '-' for standard output)", 0 },
    { "--csv", "FILE", "growth curves and NEES per bin and variant ('-' for standard output)", 0 },
    { "--plot", "PNG", "error growth with the predicted sd, and position NEES with its band", 0 },
    { "--quiet", NULL, "no summary on standard output (none either when --json or --csv is '-')", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "montecarlo", "[options]",
    "Run N seeds of one simulated motion (options as for `harness sim`) through\n"
    "the navigation filter and report the error growth with time and distance,\n"
    "the final errors, and the filter's consistency: the average normalised\n"
    "estimation error squared (NEES) of position, velocity, attitude, biases and\n"
    "all 15 states against its 95 % chi-square band. With --bias-model both,\n"
    "the filter runs with and without the AR(1) bias model on exactly the same\n"
    "samples and the paired differences are reported.",
    0, 0, k_opts
};

/* ------------------------------------------------------------ statistics */


/* Statistics of the finite values of x; NaN where undefined (no value;
 * the sd and the interval of one value). */
typedef struct {
    int n;
    double mean, sd, ci95, rms, median, p95, max;
} stats_t;

static stats_t stats_of(const double *x, int n)
{
    stats_t s;
    double *v = (double *)malloc((size_t)(n > 0 ? n : 1) * sizeof *v);
    int i, k = 0;
    memset(&s, 0, sizeof s);
    s.mean = s.sd = s.ci95 = s.rms = s.median = s.p95 = s.max = (double)NAN;
    if (v == NULL) {
        return s;
    }
    for (i = 0; i < n; i++) {
        if (isfinite(x[i])) {
            v[k++] = x[i];
        }
    }
    s.n = k;
    if (k > 0) {
        double sum = 0.0, sq = 0.0;
        qsort(v, (size_t)k, sizeof *v, hx_cmp_double);
        for (i = 0; i < k; i++) {
            sum += v[i];
            sq += v[i] * v[i];
        }
        s.mean = sum / k;
        s.rms = sqrt(sq / k);
        if (k > 1) {
            /* two passes: the one-pass sum of squares less k mean^2 came
             * out a rounding below 0 for runs that agree, and its root NaN */
            double ss = 0.0;
            for (i = 0; i < k; i++) {
                ss += (v[i] - s.mean) * (v[i] - s.mean);
            }
            s.sd = sqrt(ss / (k - 1));
            /* half-width of the mean's 95 % interval: Student's t with
             * k - 1 degrees of freedom (1.96, the normal's, made 3 runs'
             * interval less than half as wide as it is) */
            s.ci95 = gsl_cdf_tdist_Pinv(0.975, (double)(k - 1)) * s.sd / sqrt((double)k);
        }
        s.median = (k % 2) ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
        s.p95 = v[(int)ceil(0.95 * k) - 1];
        s.max = v[k - 1];
    }
    free(v);
    return s;
}

typedef struct {
    double time_avg;   /* average over bins of the average NEES */
    double frac_in;    /* fraction of bins inside their 95 % band */
    int above, below;  /* bins above / below their band */
    double above_t[2], below_t[2]; /* the first and last of those bins' times, s */
    double lo, hi;     /* band for the full number of runs */
    int bins;
} cons_t;

static cons_t consistency(const hx_mc_var_t *v, int g, int runs)
{
    cons_t c;
    int b, in = 0, k = 0;
    double sum = 0.0;
    memset(&c, 0, sizeof c);
    hx_nees_band(runs, hx_nees_dim[g], 0.05, &c.lo, &c.hi);
    for (b = 0; b < v->nbins; b++) {
        const hx_mc_bin_t *x = &v->bins[b];
        double lo, hi;
        if (x->n_nees[g] < 1 || !isfinite(x->nees[g])) {
            continue;
        }
        hx_nees_band(x->n_nees[g], hx_nees_dim[g], 0.05, &lo, &hi);
        in += x->nees[g] >= lo && x->nees[g] <= hi;
        if (x->nees[g] > hi) {
            if (c.above == 0) {
                c.above_t[0] = x->t_s;
            }
            c.above_t[1] = x->t_s;
            c.above++;
        } else if (x->nees[g] < lo) {
            if (c.below == 0) {
                c.below_t[0] = x->t_s;
            }
            c.below_t[1] = x->t_s;
            c.below++;
        }
        sum += x->nees[g];
        k++;
    }
    c.bins = k;
    c.time_avg = k > 0 ? sum / k : (double)NAN;
    c.frac_in = k > 0 ? (double)in / k : (double)NAN;
    return c;
}

/* The verdict is the per-bin test: a consistent filter's bin averages lie
 * in their band 95 % of the time, so at least MC_CONSISTENT_FRAC of them
 * (bins close in time are correlated, hence the margin; the oracle of
 * tests/test_mc.c scores 85 % or more). The time average alone is not a
 * test against the single bin's band (it needs a narrower one), and a time
 * average inside the band can hide bins far outside on both sides. */
#define MC_CONSISTENT_FRAC 0.8

/* Once that rule has failed, the direction: a consistent filter leaves
 * 2.5 % of its bins above the band and 2.5 % below, and the rule above
 * lets 20 % out in all; half of that, MC_TAIL_FRAC, is each side's share
 * (this names the direction only: 15 % above and 2 % below is still
 * consistent by the rule above). A side with more has failed:
 * one side alone names the direction (over-confident: NEES above, the
 * errors larger than P says; pessimistic: below); both sides is
 * inconsistent, the filter over-confident in some bins and pessimistic in
 * others (a pessimistic prior while the foot stands, an over-confident
 * bias covariance once it walks). Before, the side with more bins won,
 * which called a bias NEES four times the band's top over the walk
 * pessimistic for the one bin more below it during the opening stand. */
#define MC_TAIL_FRAC 0.1

static const char *verdict(const cons_t *c)
{
    int over, pess;
    if (c->frac_in >= MC_CONSISTENT_FRAC) {
        return "consistent";
    }
    over = c->above > MC_TAIL_FRAC * c->bins;
    pess = c->below > MC_TAIL_FRAC * c->bins;
    /* one of the two holds: above + below > (1 - 0.8) bins */
    return over && pess ? "inconsistent" : (over ? "over-confident" : "pessimistic");
}

/* ------------------------------------------------------------ outputs */

/* A figure of the summary right-aligned in `width` columns, or "-" where it
 * is undefined (a bin before the alignment, a ratio of zeros). */
static const char *col(char *buf, size_t size, int width, int prec, double v)
{
    if (isfinite(v)) {
        snprintf(buf, size, "%*.*f", width, prec, v);
    } else {
        snprintf(buf, size, "%*s", width, "-");
    }
    return buf;
}

/* When the bins outside a band lie: " at 5.0 s", " from 5.0 to 30.0 s",
 * or nothing for none (the bins' times are their ends). */
static const char *span(char *buf, size_t size, int n, const double t[2])
{
    if (n == 0) {
        buf[0] = '\0';
    } else if (n == 1) {
        snprintf(buf, size, " at %.1f s", t[0]);
    } else {
        snprintf(buf, size, " from %.1f to %.1f s", t[0], t[1]);
    }
    return buf;
}

/* The 95 % interval of a mean: "+- 0.012", or why there is none. */
static const char *ci_text(char *buf, size_t size, const stats_t *s)
{
    if (isfinite(s->ci95)) {
        snprintf(buf, size, "+- %.3f", s->ci95);
    } else {
        snprintf(buf, size, "no interval: %s", s->n == 1 ? "one run" : "no run");
    }
    return buf;
}

/* the reading of a profile's bias sd that is applied: sensor and filter
 * apart (--bias-sigma eq6 is ignored for --profile none and for a
 * --filter-profile); NULL for the ideal sensor, which has no bias model */
typedef struct {
    const char *sensor;
    const char *filter;
} bias_reading_t;

static const char *reading_text(const char *reading)
{
    return strcmp(reading, "eq6") == 0 ? "eq. 6 reading" : "as given";
}

/* --bias-sigma eq6 with a --filter-profile: eq. 6 rereads the sensor's
 * profile alone, the filter's is taken as given, so the filter's bias sd
 * is another than the simulated sensor's, said with how far (--profile
 * mtx --bias-sigma eq6 --filter-profile mtx: the filter's 0.0016 to 0.012
 * times the sensor's, bias NEES time average 6.0 consistent -> 8.5
 * over-confident, 4 runs of 60 s of 'paper' at 100 Hz; only the summary's
 * filter line said 'as given'). */
static void warn_filter_reading(const char *sensor, const fnav_profile_t *ps, const char *filter,
                                const fnav_profile_t *pf)
{
    double lo = HUGE_VAL, hi = 0.0;
    char how[96];
    int i;
    for (i = 0; i < 6; i++) {
        const double s_sd = i < 3 ? (double)ps->accel_bias_sigma_mps2[i] : (double)ps->gyro_bias_sigma_rps[i - 3];
        const double f_sd = i < 3 ? (double)pf->accel_bias_sigma_mps2[i] : (double)pf->gyro_bias_sigma_rps[i - 3];
        if (s_sd > 0.0) {
            lo = f_sd / s_sd < lo ? f_sd / s_sd : lo;
            hi = f_sd / s_sd > hi ? f_sd / s_sd : hi;
        }
    }
    if (lo > hi) {
        snprintf(how, sizeof how, "(the sensor's bias sd is 0)");
    } else if (hi - lo <= 1e-3 * hi) {
        snprintf(how, sizeof how, "%.2g times the simulated sensor's", lo);
    } else {
        snprintf(how, sizeof how, "%.2g to %.2g times the simulated sensor's", lo, hi);
    }
    hx_warn("montecarlo", "--bias-sigma eq6 rereads the sensor's profile %s alone: --filter-profile %s is taken as "
                          "given, its bias sd %s (leave --filter-profile out for eq. 6 on both)",
            sensor, filter, how);
}

static void print_summary(const hx_mc_result_t *r, const char *motion, double rate, const char *profile,
                          const char *fprofile, const bias_reading_t *br)
{
    int v, g, i;
    char c1[32], c2[32], c3[32], c4[32], s1[40], s2[40];
    printf("montecarlo  %d seeds of '%s': %.1f s, %.1f m between footfalls, %g Hz\n", r->runs, motion, r->duration_s,
           r->distance_m, rate);
    char shown[2][4096]; /* a profile file's name: its control characters as '?' (hx_line_str), as in the messages */
    printf("sensor      %s (%s%s), filter %s (bias sigma: %s)\n", hx_line_str(shown[0], sizeof shown[0], profile),
           br->sensor != NULL ? "bias sigma: " : "", br->sensor != NULL ? reading_text(br->sensor) : "no bias model",
           hx_line_str(shown[1], sizeof shown[1], fprofile), reading_text(br->filter));
    for (v = 0; v < r->nvar; v++) {
        const hx_mc_var_t *x = &r->var[v];
        stats_t h = stats_of(x->final_h_m, r->runs), z = stats_of(x->final_v_m, r->runs);
        stats_t p = stats_of(x->final_pred_h_m, r->runs), rm = stats_of(x->rms_h_m, r->runs);
        printf("\nvariant %s (%ld estimates compared, %d skipped as non-finite)\n", x->name, x->estimates, x->nonfinite);
        if (h.n == 0) {
            printf("  final errors             none: no run has an aligned estimate at the end\n");
        } else {
            printf("  final horizontal error   mean %.3f m (%s), median %.3f, 95%% %.3f, RMS %.3f", h.mean,
                   ci_text(c1, sizeof c1, &h), h.median, h.p95, h.rms);
            if (r->distance_m > 0.0) {
                printf(" = %.2f %% of distance\n", 100.0 * h.rms / r->distance_m);
            } else {
                printf(" (no distance walked)\n");
            }
            printf("  final vertical error     mean %.3f m, median %.3f, 95%% %.3f, RMS %.3f\n", z.mean, z.median,
                   z.p95, z.rms);
            printf("  predicted horizontal sd  RMS over runs %.3f m (error RMS / predicted %s)\n", p.rms,
                   col(c1, sizeof c1, 0, 2, p.rms > 0.0 ? h.rms / p.rms : (double)NAN));
            printf("  RMS horizontal error over each run: mean %.3f m\n", rm.mean);
        }
        printf("  growth     t [s]   dist [m]  RMS horiz [m]  pred sd [m]  RMS vert [m]  RMS yaw [deg]\n");
        /* six bins spread over the run (every bin when there are fewer) */
        for (i = 0; i < 6 && i < x->nbins; i++) {
            int b = x->nbins <= 6 ? i : (int)((double)(i + 1) / 6.0 * x->nbins) - 1;
            const hx_mc_bin_t *o = &x->bins[b];
            printf("           %7.1f  %8.1f  %s  %s  %s  %s\n", o->t_s, o->odo_m, col(c1, sizeof c1, 13, 3, o->rms_h_m),
                   col(c2, sizeof c2, 11, 3, o->pred_h_m), col(c3, sizeof c3, 12, 3, o->rms_v_m),
                   col(c4, sizeof c4, 13, 2, o->rms_yaw_rad * 180.0 / 3.14159265358979323846));
        }
        printf("  consistency (NEES averaged over runs; 95 %% band for %d runs)\n", r->runs);
        for (g = 0; g < HX_NEES_COUNT; g++) {
            cons_t c = consistency(x, g, r->runs);
            if (c.bins == 0) {
                printf("    %-5s d=%-2d  no NEES: %s\n", hx_nees_name[g], hx_nees_dim[g],
                       x->estimates > 0 ? "no positive definite covariance (states off)" : "no aligned estimate");
                continue;
            }
            printf("    %-5s d=%-2d  time-average %7.2f  band [%.2f, %.2f]  %3.0f %% of bins inside (%d above%s, %d "
                   "below%s) -> %s\n",
                   hx_nees_name[g], hx_nees_dim[g], c.time_avg, c.lo, c.hi, 100.0 * c.frac_in, c.above,
                   span(s1, sizeof s1, c.above, c.above_t), c.below, span(s2, sizeof s2, c.below, c.below_t),
                   verdict(&c));
        }
    }
    if (r->nvar == 2) {
        double *d = (double *)malloc((size_t)r->runs * sizeof *d), *dv = (double *)malloc((size_t)r->runs * sizeof *dv);
        int better = 0, k;
        if (d != NULL && dv != NULL) {
            stats_t s, sv;
            for (k = 0; k < r->runs; k++) {
                d[k] = r->var[1].final_h_m[k] - r->var[0].final_h_m[k];
                dv[k] = r->var[1].final_v_m[k] - r->var[0].final_v_m[k];
                better += d[k] > 0.0;
            }
            s = stats_of(d, r->runs);
            sv = stats_of(dv, r->runs);
            if (s.n == 0) {
                printf("\npaired (%s - %s, same samples): none, no run has a final estimate in both\n", r->var[1].name,
                       r->var[0].name);
            } else {
                /* over the runs with a final estimate in both */
                printf("\npaired (%s - %s, same samples, 95 %% intervals): final horizontal error %+.3f m (%s), "
                       "vertical %+.3f m (%s); %s better in %d of %d runs\n",
                       r->var[1].name, r->var[0].name, s.mean, ci_text(c1, sizeof c1, &s), sv.mean,
                       ci_text(c2, sizeof c2, &sv), r->var[0].name, better, s.n);
            }
        }
        free(d);
        free(dv);
    }
}

static cJSON *num_array(const double *x, int n)
{
    cJSON *a = cJSON_CreateArray();
    int i;
    for (i = 0; i < n; i++) {
        cJSON_AddItemToArray(a, isfinite(x[i]) ? cJSON_CreateNumber(x[i]) : cJSON_CreateNull());
    }
    return a;
}

static int write_json(const char *path, const hx_mc_result_t *r, int runs_asked, const char *motion, double rate,
                      const char *profile, const char *fprofile, int eq6, const bias_reading_t *br, unsigned seed)
{
    cJSON *root = cJSON_CreateObject(), *vars = cJSON_CreateArray();
    char err[HX_ERR_SIZE];
    int v, g, b, rc;
    cJSON_AddStringToObject(root, "motion", motion);
    cJSON_AddNumberToObject(root, "rate_hz", rate);
    cJSON_AddStringToObject(root, "profile", profile);
    cJSON_AddStringToObject(root, "filter_profile", fprofile);
    cJSON_AddStringToObject(root, "bias_sigma", eq6 ? "eq6" : "given");
    if (br->sensor != NULL) {
        cJSON_AddStringToObject(root, "sensor_bias_sigma", br->sensor);
    } else {
        cJSON_AddNullToObject(root, "sensor_bias_sigma");
    }
    cJSON_AddStringToObject(root, "filter_bias_sigma", br->filter);
    cJSON_AddBoolToObject(root, "complete", r->runs == runs_asked);
    cJSON_AddNumberToObject(root, "runs", r->runs);
    cJSON_AddNumberToObject(root, "runs_asked", runs_asked);
    cJSON_AddNumberToObject(root, "first_seed", seed);
    cJSON_AddNumberToObject(root, "duration_s", r->duration_s);
    cJSON_AddNumberToObject(root, "distance_m", r->distance_m);
    cJSON_AddNumberToObject(root, "bin_s", r->bin_s);
    for (v = 0; v < r->nvar; v++) {
        const hx_mc_var_t *x = &r->var[v];
        cJSON *o = cJSON_CreateObject(), *cons = cJSON_CreateObject(), *bins = cJSON_CreateArray();
        stats_t h = stats_of(x->final_h_m, r->runs), z = stats_of(x->final_v_m, r->runs);
        cJSON_AddStringToObject(o, "name", x->name);
        cJSON_AddNumberToObject(o, "estimates", (double)x->estimates);
        cJSON_AddNumberToObject(o, "nonfinite", x->nonfinite);
        hx_json_num(o, "final_h_mean_m", h.mean);
        hx_json_num(o, "final_h_rms_m", h.rms);
        hx_json_num(o, "final_h_median_m", h.median);
        hx_json_num(o, "final_h_p95_m", h.p95);
        hx_json_num(o, "final_v_rms_m", z.rms);
        hx_json_num(o, "final_v_median_m", z.median);
        cJSON_AddItemToObject(o, "final_h_m", num_array(x->final_h_m, r->runs));
        cJSON_AddItemToObject(o, "final_v_m", num_array(x->final_v_m, r->runs));
        cJSON_AddItemToObject(o, "final_pred_h_m", num_array(x->final_pred_h_m, r->runs));
        cJSON_AddItemToObject(o, "final_nees_pos", num_array(x->final_nees_pos, r->runs));
        cJSON_AddItemToObject(o, "rms_h_m", num_array(x->rms_h_m, r->runs));
        for (g = 0; g < HX_NEES_COUNT; g++) {
            cons_t c = consistency(x, g, r->runs);
            cJSON *cg = cJSON_CreateObject();
            cJSON_AddNumberToObject(cg, "dim", hx_nees_dim[g]);
            hx_json_num(cg, "time_average", c.time_avg);
            hx_json_num(cg, "fraction_in_band", c.frac_in);
            cJSON_AddNumberToObject(cg, "bins", c.bins);
            cJSON_AddNumberToObject(cg, "bins_above", c.above);
            cJSON_AddNumberToObject(cg, "bins_below", c.below);
            if (c.bins > 0) {
                cJSON_AddStringToObject(cg, "verdict", verdict(&c));
            } else {
                cJSON_AddNullToObject(cg, "verdict"); /* no NEES: no verdict (it said over-confident) */
            }
            hx_json_num(cg, "band_lo", c.lo);
            hx_json_num(cg, "band_hi", c.hi);
            cJSON_AddItemToObject(cons, hx_nees_name[g], cg);
        }
        cJSON_AddItemToObject(o, "nees", cons);
        for (b = 0; b < x->nbins; b++) {
            const hx_mc_bin_t *q = &x->bins[b];
            cJSON *ob = cJSON_CreateObject();
            hx_json_num(ob, "t_s", q->t_s);
            hx_json_num(ob, "odo_m", q->odo_m);
            cJSON_AddNumberToObject(ob, "n", q->n);
            hx_json_num(ob, "rms_h_m", q->rms_h_m);
            hx_json_num(ob, "rms_v_m", q->rms_v_m);
            hx_json_num(ob, "rms_yaw_rad", q->rms_yaw_rad);
            hx_json_num(ob, "pred_h_m", q->pred_h_m);
            hx_json_num(ob, "pred_v_m", q->pred_v_m);
            for (g = 0; g < HX_NEES_COUNT; g++) {
                char key[16];
                snprintf(key, sizeof key, "nees_%s", hx_nees_name[g]);
                hx_json_num(ob, key, q->nees[g]);
            }
            cJSON_AddItemToArray(bins, ob);
        }
        cJSON_AddItemToObject(o, "bins", bins);
        cJSON_AddItemToArray(vars, o);
    }
    cJSON_AddItemToObject(root, "variants", vars);
    rc = hx_write_json(path, root, err, sizeof err);
    cJSON_Delete(root);
    if (rc != 0) {
        hx_error("montecarlo", "%s", err);
    }
    return rc;
}

/* ",value", or "," alone where it is undefined (the JSON's null; allan's
 * CSV leaves such fields empty too) */
static void csv_num(FILE *f, double v)
{
    if (isfinite(v)) {
        fprintf(f, ",%.6g", v);
    } else {
        fputc(',', f);
    }
}

static int write_csv(const char *path, const hx_mc_result_t *r)
{
    const int to_stdout = strcmp(path, "-") == 0; /* '-': standard output, as --json */
    FILE *f = to_stdout ? stdout : fopen(path, "w");
    int v, b, g, ok = 1;
    if (f == NULL) {
        return -1;
    }
    fprintf(f, "variant,t_s,odo_m,n,rms_h_m,pred_h_m,rms_v_m,pred_v_m,rms_yaw_rad");
    for (g = 0; g < HX_NEES_COUNT; g++) {
        fprintf(f, ",nees_%s,lo_%s,hi_%s", hx_nees_name[g], hx_nees_name[g], hx_nees_name[g]);
    }
    fprintf(f, "\n");
    for (v = 0; v < r->nvar; v++) {
        for (b = 0; b < r->var[v].nbins; b++) {
            const hx_mc_bin_t *q = &r->var[v].bins[b];
            /* t_s as exact as the bin (three decimals printed --bin 0.0125's 0.0125 as 0.013) */
            fprintf(f, "%s,%.6f,%.3f,%d", r->var[v].name, q->t_s, q->odo_m, q->n);
            csv_num(f, q->rms_h_m);
            csv_num(f, q->pred_h_m);
            csv_num(f, q->rms_v_m);
            csv_num(f, q->pred_v_m);
            csv_num(f, q->rms_yaw_rad);
            for (g = 0; g < HX_NEES_COUNT; g++) {
                double lo = (double)NAN, hi = (double)NAN;
                if (q->n_nees[g] > 0) {
                    hx_nees_band(q->n_nees[g], hx_nees_dim[g], 0.05, &lo, &hi);
                }
                csv_num(f, q->nees[g]);
                csv_num(f, lo);
                csv_num(f, hi);
            }
            if (fprintf(f, "\n") < 0) {
                ok = 0;
            }
        }
    }
    if (to_stdout ? fflush(f) != 0 : fclose(f) != 0) {
        ok = 0;
    }
    return ok ? 0 : -1;
}

/* Points of a variant's curve: what (0 RMS error, 1 predicted sd, 2
 * average position NEES, positive only: a log axis). */
static double curve_value(const hx_mc_result_t *r, int v, int b, int what)
{
    const double x = what == 0 ? r->var[v].bins[b].rms_h_m
                     : what == 1 ? r->var[v].bins[b].pred_h_m
                                 : r->var[v].bins[b].nees[HX_NEES_POS];
    return isfinite(x) && (what < 2 || x > 0.0) ? x : (double)NAN;
}

static int curve_points(const hx_mc_result_t *r, int v, int what)
{
    int b, n = 0;
    for (b = 0; b < r->var[v].nbins; b++) {
        n += isfinite(curve_value(r, v, b, what));
    }
    return n;
}

/* The '-' data of the curves with points, in the order of their plot
 * entries. */
static void curve_data(FILE *gp, const hx_mc_result_t *r, int what0, int what1)
{
    int v, w, b;
    for (v = 0; v < r->nvar; v++) {
        for (w = what0; w <= what1; w++) {
            if (curve_points(r, v, w) == 0) {
                continue;
            }
            for (b = 0; b < r->var[v].nbins; b++) {
                const double x = curve_value(r, v, b, w);
                if (isfinite(x)) {
                    fprintf(gp, "%g %g\n", r->var[v].bins[b].t_s, x);
                }
            }
            fprintf(gp, "e\n");
        }
    }
}

static int write_plot(const char *png, const hx_mc_result_t *r, const char *motion, const char *profile)
{
    hx_plot_t p;
    int v, b, w, n;
    double t0 = HUGE_VAL, t1 = -HUGE_VAL;
    char q1[128], q2[256];
    if (hx_plot_open(&p, "montecarlo", png, 1100, 800) != 0) {
        return -1;
    }
    /* the time span of every point: runs too short to align have none
     * (gnuplot would refuse the plot, leave the picture half drawn and the
     * run exit 3), one growth bin is one time (gnuplot would warn "empty x
     * range" on standard error) */
    for (v = 0; v < r->nvar; v++) {
        for (b = 0; b < r->var[v].nbins; b++) {
            for (w = 0; w < 3; w++) {
                if (isfinite(curve_value(r, v, b, w))) {
                    t0 = fmin(t0, r->var[v].bins[b].t_s);
                    t1 = fmax(t1, r->var[v].bins[b].t_s);
                }
            }
        }
    }
    fprintf(p.gp, "set multiplot layout 2,1 title 'montecarlo: motion %s, profile %s, %d runs'\n",
            hx_gp_str(q1, sizeof q1, motion), hx_gp_str(q2, sizeof q2, profile), r->runs);
    fprintf(p.gp, "set grid\nset key left top\n");
    if (t0 > t1) {
        fprintf(p.gp, "set xrange [0:1]\n");
    } else if (t1 - t0 < 1e-9) {
        fprintf(p.gp, "set xrange [%g:%g]\n", t0 - 0.5, t1 + 0.5);
    }
    fprintf(p.gp, "set xlabel 'time [s]'\nset ylabel 'horizontal error [m]'\n");
    for (v = 0, n = 0; v < r->nvar; v++) {
        n += curve_points(r, v, 0) + curve_points(r, v, 1);
    }
    if (n == 0) {
        fprintf(p.gp, "set yrange [0:1]\nset label 1 'no aligned estimate in any run' at graph 0.5,0.5 center\n"
                      "plot -1 notitle\nunset label 1\nset autoscale y\n");
    } else {
        fprintf(p.gp, "plot ");
        for (v = 0, n = 0; v < r->nvar; v++) {
            /* a variant's error and predicted sd in one colour */
            if (curve_points(r, v, 0) > 0) {
                fprintf(p.gp, "%s'-' w l lw 2 lc %d t 'RMS error, %s'", n++ ? ", " : "", v + 1, r->var[v].name);
            }
            if (curve_points(r, v, 1) > 0) {
                fprintf(p.gp, "%s'-' w l dt 2 lc %d t 'predicted sd, %s'", n++ ? ", " : "", v + 1, r->var[v].name);
            }
        }
        fprintf(p.gp, "\n");
        curve_data(p.gp, r, 0, 1);
    }
    {
        double lo, hi;
        hx_nees_band(r->runs, 3, 0.05, &lo, &hi);
        fprintf(p.gp, "set ylabel 'position NEES (d = 3)'\nset logscale y\nset format y '%%g'\n");
        for (v = 0, n = 0; v < r->nvar; v++) {
            n += curve_points(r, v, 2);
        }
        if (n == 0) {
            fprintf(p.gp, "set label 1 'no NEES: no aligned estimate' at graph 0.5,0.5 center\n");
        }
        fprintf(p.gp, "plot %g w l lc rgb 'gray' t '95%% band, %d runs', %g w l lc rgb 'gray' notitle", lo, r->runs, hi);
        for (v = 0; v < r->nvar; v++) {
            if (curve_points(r, v, 2) > 0) {
                fprintf(p.gp, ", '-' w l lw 2 lc %d t 'average NEES, %s'", v + 1, r->var[v].name);
            }
        }
        fprintf(p.gp, "\n");
        curve_data(p.gp, r, 2, 2);
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, "montecarlo");
}

/* ------------------------------------------------------------ filter */

typedef struct {
    fnav_nav_config_t cfg;
    fnav_nav_t nav;
} fnav_adapter_t;

static int ad_start(void *ctx, double rate_hz, int run)
{
    fnav_adapter_t *a = (fnav_adapter_t *)ctx;
    (void)rate_hz;
    (void)run;
    return fnav_nav_init(&a->nav, &a->cfg) == FNAV_OK ? 0 : -1;
}

static int ad_push(void *ctx, const fnav_sample_t *s)
{
    fnav_adapter_t *a = (fnav_adapter_t *)ctx;
    fnav_status_t st = fnav_nav_push(&a->nav, s);
    return st == FNAV_E_STATE ? -1 : 0; /* rejected samples are counted by the filter */
}

static int ad_pop(void *ctx, hx_mc_est_t *e)
{
    /* 15-state output order <- the filter's internal covariance order */
    static const int k_map[15] = { FNAV_UKF_A,      FNAV_UKF_A + 1,  FNAV_UKF_A + 2,  FNAV_UKF_V,     FNAV_UKF_V + 1,
                                   FNAV_UKF_V + 2,  FNAV_UKF_P,      FNAV_UKF_P + 1,  FNAV_UKF_P + 2, FNAV_UKF_BG,
                                   FNAV_UKF_BG + 1, FNAV_UKF_BG + 2, FNAV_UKF_BA,     FNAV_UKF_BA + 1, FNAV_UKF_BA + 2 };
    fnav_adapter_t *a = (fnav_adapter_t *)ctx;
    fnav_nav_frame_t fr;
    int i, j;
    if (fnav_nav_pop(&a->nav, &fr) != FNAV_OK) {
        return 0;
    }
    memset(e, 0, sizeof *e);
    e->seq = fr.seq;
    e->valid = (fr.flags & FNAV_FRAME_ALIGNED) != 0u;
    for (i = 0; i < 3; i++) {
        e->pos_m[i] = (double)fr.pos_m[i];
        e->vel_mps[i] = (double)fr.vel_mps[i];
        e->gyro_bias_rps[i] = (double)fr.gyro_bias_rps[i];
        e->accel_bias_mps2[i] = (double)fr.accel_bias_mps2[i];
    }
    /* the filter has just processed this frame: its state is the frame's */
    for (i = 0; i < 4; i++) {
        e->q_nb[i] = (double)a->nav.ukf.q_nb.q[i];
    }
    for (i = 0; i < 15; i++) {
        for (j = 0; j < 15; j++) {
            e->P[i][j] = (double)fnav_ukf_cov(&a->nav.ukf, k_map[i], k_map[j]);
        }
    }
    return 1;
}

static void ad_finish(void *ctx)
{
    fnav_adapter_t *a = (fnav_adapter_t *)ctx;
    fnav_nav_finish(&a->nav);
}

typedef struct {
    hx_progress_t prog;
} prog_ctx_t;

static void on_progress(void *ctx, double done, int total)
{
    (void)total;
    hx_progress_update(&((prog_ctx_t *)ctx)->prog, done);
}

int hx_cmd_montecarlo(int argc, char **argv)
{
    hx_args_t a;
    hx_sim_setup_t su;
    int pr;
    /* as replay and live (the unknown-key error points at it) */
    if (hx_nav_param_help_requested(argc, argv)) {
        return HX_EXIT_OK;
    }
    pr = hx_args_parse(&k_spec, argc, argv, &a);
    if (pr != 0) {
        return pr > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--plot", NULL };
        if (hx_refuse_dash("montecarlo", &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_sim_setup_from_args("montecarlo", &a, &su) != 0) {
        return HX_EXIT_USAGE;
    }
    if ((double)su.err.rate_hz < HX_TIME_RATE_MIN_HZ) {
        /* replay refuses a log this slow (a foot-mounted IMU needs 20 Hz
         * or more, docs/harness.md): error growth at 2 Hz (71 % of the
         * distance, reported as any other run) describes no log footnav
         * navigates */
        hx_error("montecarlo", "--rate %g Hz: the navigation needs %.0f Hz or more (replay refuses a log recorded "
                               "slower: no stance lasts more than a few samples)",
                 (double)su.err.rate_hz, HX_TIME_RATE_MIN_HZ);
        return HX_EXIT_USAGE;
    }
    if (su.err.mask[FNAV_EFFECT_DROPOUT] != 0u && su.err.dropout.prob >= FNAV_R(1.0)) {
        /* no run would have a sample to navigate (it reported "no aligned
         * estimate" for every run, exit 0) */
        hx_error("montecarlo", "--effect dropout:prob=1 drops every sample: no run has one to navigate");
        return HX_EXIT_USAGE;
    }
    {
        static fnav_adapter_t ad[2];
        hx_mc_nav_t navs[2];
        hx_mc_config_t mc;
        hx_mc_result_t res;
        hx_motion_t *motion;
        hx_nav_opts_t no;
        prog_ctx_t pc;
        bias_reading_t br;
        char err[HX_ERR_SIZE];
        const char *bm = hx_arg(&a, "--bias-model"), *fprof = hx_arg(&a, "--filter-profile");
        const char *json = hx_arg(&a, "--json"), *csv = hx_arg(&a, "--csv"), *png = hx_arg(&a, "--plot");
        double seeds = 50.0, bin = 1.0;
        int nvar, v, i, status = HX_EXIT_OK;
        if (hx_arg_whole(&a, "--seeds", 1.0, 100000.0, &seeds) != 0 ||
            hx_arg_double(&a, "--bin", 0.01, 1e5, &bin) != 0) {
            return HX_EXIT_USAGE;
        }
        if (bin < 1.0 / (double)su.err.rate_hz * (1.0 - 1e-9)) {
            /* a bin narrower than the sample interval holds no sample at
             * times: its summary row was '-' without a word */
            hx_error("montecarlo", "--bin %g s is shorter than the sample interval (%g s at %g Hz): bins without a "
                                   "sample; --bin %g or more",
                     bin, 1.0 / (double)su.err.rate_hz, (double)su.err.rate_hz, 1.0 / (double)su.err.rate_hz);
            return HX_EXIT_USAGE;
        }
        if (bm == NULL) {
            bm = "ar1";
        }
        if (strcmp(bm, "ar1") != 0 && strcmp(bm, "off") != 0 && strcmp(bm, "both") != 0) {
            hx_error("montecarlo", "--bias-model is ar1, off or both, not '%s'", bm);
            return HX_EXIT_USAGE;
        }
        {
            static const char *const outs[] = { "--json", "--csv", "--plot", NULL };
            /* a profile file is an input: an output onto it would replace
             * it after it was read, exit 0 */
            if (hx_output_is_input("montecarlo", NULL, &a, outs) ||
                hx_profile_is_output("montecarlo", hx_arg(&a, "--profile"), &a, outs) ||
                hx_profile_is_output("montecarlo", fprof, &a, outs)) {
                return HX_EXIT_USAGE;
            }
        }
        /* the outputs are written after every run: find out now that they can be */
        if ((json != NULL && strcmp(json, "-") != 0 && hx_check_writable("montecarlo", json) != 0) ||
            (csv != NULL && strcmp(csv, "-") != 0 && hx_check_writable("montecarlo", csv) != 0) ||
            (png != NULL && hx_plot_check("montecarlo", png) != 0)) {
            return HX_EXIT_IO;
        }
        br.sensor = !su.has_profile ? NULL : su.bias_eq6 ? "eq6" : "given";
        br.filter = fprof == NULL && su.has_profile && su.bias_eq6 ? "eq6" : "given";
        if (fprof == NULL) {
            fprof = su.has_profile ? su.profile_name : "navchip";
        }
        nvar = strcmp(bm, "both") == 0 ? 2 : 1;
        for (v = 0; v < nvar; v++) {
            memset(&no, 0, sizeof no);
            no.profile = fprof;
            no.bias_model = nvar == 2 ? (v == 0 ? "ar1" : "off") : bm;
            no.detector = hx_arg(&a, "--detector");
            /* the filter integrates the samples as what they are: interval
             * means with --decimation mean, instantaneous values otherwise */
            no.samples = hx_arg(&a, "--samples");
            if (no.samples == NULL) {
                no.samples = su.decim == HX_DECIM_MEAN ? "mean" : "instant";
            }
            for (i = 0; i < hx_arg_count(&a, "--param") && i < HX_MAX_REPEAT; i++) {
                no.params[no.nparams++] = hx_arg_at(&a, "--param", i);
            }
            if (hx_nav_config(&no, &ad[v].cfg, err, sizeof err) != 0) {
                hx_error("montecarlo", "%s", err);
                return HX_EXIT_USAGE;
            }
            if (strcmp(br.filter, "eq6") == 0) {
                /* the sensor's profile read by eq. 6 for the filter too; a
                 * --filter-profile is taken as given (read by eq. 6 as well,
                 * generic-mems would be inflated 229 times), and so is the
                 * navchip of --profile none, whose sensor ignores eq6 (the
                 * filter's bias sd went 0.0138 -> 0.0094 in bias NEES
                 * while the warning said "ignored") */
                hx_profile_bias_eq6(&ad[v].cfg.profile);
            }
            navs[v].name = no.bias_model;
            navs[v].ctx = &ad[v];
            navs[v].start = ad_start;
            navs[v].push = ad_push;
            navs[v].pop = ad_pop;
            navs[v].finish = ad_finish;
        }
        if (su.bias_eq6 && su.has_profile && hx_arg(&a, "--filter-profile") != NULL) {
            warn_filter_reading(su.profile_name, &su.profile, fprof, &ad[0].cfg.profile);
        }
        if ((double)su.err.seed + seeds - 1.0 > 4294967295.0) {
            /* the seeds seed .. seed + N - 1 wrapped past 2^32 - 1 to 0 */
            hx_error("montecarlo", "--seed %lu with --seeds %.0f runs past the last seed, 4294967295",
                     (unsigned long)su.err.seed, seeds);
            return HX_EXIT_USAGE;
        }
        motion = hx_motion_create(&su.motion_cfg, su.motion_name, su.duration_s, err, sizeof err);
        if (motion == NULL) {
            hx_error("montecarlo", "%s", err);
            return HX_EXIT_USAGE;
        }
        hx_sim_warn_cut("montecarlo", motion, su.motion_name, su.duration_s);
        hx_sim_warn_unused("montecarlo", &a, motion, su.motion_name);
        mc.sim.motion = motion;
        mc.sim.err = su.err;
        mc.sim.decim = su.decim;
        mc.sim.duration_s = su.duration_s > 0.0 ? su.duration_s : hx_motion_duration(motion);
        mc.runs = (int)seeds;
        mc.bin_s = bin;
        /* the JSON holds each bin of each variant as a tree (14 cJSON
         * nodes) and then as text: 1.7 KB a bin measured (a 300 s stand at
         * --bin 0.01, 30,000 bins: 49 MB more peak memory with --json) */
        mc.out_bytes_per_bin = json != NULL ? 1800.0 : 0.0;
        /* Ctrl-C or SIGTERM: no run is started after it, and the runs done
         * are reported and written, marked incomplete (200 runs stopped at
         * 80 lost all 80) */
        hx_stop_on_signals("montecarlo", "after the current run");
        mc.stop = &hx_stop_sig;
        hx_progress_start(&pc.prog, "montecarlo", seeds);
        if (hx_mc_run(&mc, navs, nvar, &res, on_progress, &pc, err, sizeof err) != 0) {
            hx_progress_end(&pc.prog);
            hx_error("montecarlo", "%s", err);
            hx_motion_free(motion);
            return hx_stop_sig != 0 ? 128 + (int)hx_stop_sig : HX_EXIT_USAGE;
        }
        hx_progress_end(&pc.prog);
        if (res.runs < mc.runs) {
            hx_warn("montecarlo", "stopped by a signal after %d of %d runs: the results and outputs cover those runs "
                                  "(JSON \"complete\": false)", res.runs, mc.runs);
            status = 128 + (int)hx_stop_sig; /* as the shell reports a command a signal ended */
        }
        /* an output to standard output ('-') takes it alone */
        if (!hx_flag(&a, "--quiet") && !(json != NULL && strcmp(json, "-") == 0) &&
            !(csv != NULL && strcmp(csv, "-") == 0)) {
            print_summary(&res, su.motion_name, (double)su.err.rate_hz, su.profile_name, fprof, &br);
        }
        if (json != NULL && write_json(json, &res, mc.runs, su.motion_name, (double)su.err.rate_hz, su.profile_name,
                                       fprof, su.bias_eq6, &br, su.err.seed) != 0) {
            status = HX_EXIT_IO;
        }
        if (csv != NULL && write_csv(csv, &res) != 0) {
            hx_error("montecarlo", "%s: cannot write (%s)", strcmp(csv, "-") == 0 ? "standard output" : csv,
                     strerror(errno));
            status = HX_EXIT_IO;
        }
        if (png != NULL && write_plot(png, &res, su.motion_name, su.profile_name) != 0) {
            status = HX_EXIT_IO;
        }
        hx_mc_result_free(&res);
        hx_motion_free(motion);
        return status;
    }
}
