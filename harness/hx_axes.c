/* The axes check (hx_axes.h; docs/harness.md, "Axes check"). The attitude
 * and velocity of each map use the core's math (fnav_math.h) and its
 * alignment formulas (fnav_align_from_means), in the navigator's frames:
 * n is north-east-down, so at rest C_nb f_b = (0, 0, -g). */
#include "hx_axes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"

#define SWING_MIN_S 0.2   /* shorter: a stance split by the detector */
#define SWING_MAX_S 2.0   /* longer: not one step (a pause, a carried foot) */
#define MIN_SWINGS 8      /* fewer: no verdict */
/* The verdict: the recorded map's median end speed at least RATIO times the
 * best map's and MARGIN_MPS above it. On the 65 real walks of ../shared/data
 * with 8 swings or more the recorded map is the best on every one, and the
 * nearest rival ends 1.11 times slower or more; 1.5 and 0.2 m/s flag 451 of
 * 470 wrong maps on 10 of those walks, each with the right fix
 * (scripts/axes_check_sweep.py). */
#define RATIO 1.5
#define MARGIN_MPS 0.2
#define STILL_S 0.5       /* the start: the stillest stance sample of the stance's last 0.5 s */
#define TILT_S 0.01       /* its tilt: the specific force over the 10 ms up to it */
/* a stance: a ZUPT run of the navigator's default min_zupt_cycle (0.025) gait cycles or more (min_run_s) */
#define CYCLE_FRAC ((double)fnav_nav_config_default.stance.min_zupt_cycle)
#define RUNS 3            /* the lock-in guard: the shortest run at most half the longest of the last 3 */

static const char NOT_CHECKED_OOM[] = "not checked: out of memory";

/* The time scales: a rate 2 or 1.25 times too high or low (a wrong
 * --input-rate, a headerless log at an assumed rate) bends every swing as
 * a wrong axis map does, and some map then fits better than the recorded
 * one: a 250 Hz walk read at 200 Hz ended its swings at 2.0 m/s, and was
 * told to read its gyro axes permuted (a generalisation audit) */
static const double SCALE[HX_AXES_SCALES] = { 0.5, 0.8, 1.25, 2.0 };



static const int PERM[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };

fnav_vec3_t hx_axes_map(int k, fnav_vec3_t w)
{
    const int *p = PERM[k / 8];
    fnav_vec3_t o;
    int i;
    for (i = 0; i < 3; i++) {
        o.v[i] = ((k >> i) & 1) ? -w.v[p[i]] : w.v[p[i]];
    }
    return o;
}

static void map_name(int k, char *buf, size_t size)
{
    const int *p = PERM[k / 8];
    snprintf(buf, size, "(%sg%c, %sg%c, %sg%c)", (k & 1) ? "-" : "", 'x' + p[0], (k & 2) ? "-" : "", 'x' + p[1],
             (k & 4) ? "-" : "", 'x' + p[2]);
}

hx_axes_t *hx_axes_new(double nav_min_zupt_cycle)
{
    hx_axes_t *a = (hx_axes_t *)calloc(1, sizeof(hx_axes_t));
    if (a != NULL) {
        /* the navigator's detector keeps the guard itself (its runs pass it
         * already, decided on its own cycles): the check adds none */
        a->cycle_frac = nav_min_zupt_cycle >= CYCLE_FRAC ? 0.0 : CYCLE_FRAC;
    }
    return a;
}

void hx_axes_sample(hx_axes_t *a, const fnav_sample_t *s)
{
    size_t i = a->n_in % HX_AXES_RING;
    a->t_ns[i] = s->t_ns;
    a->acc[i] = fnav_vec3_from(s->accel_mps2);
    a->gyr[i] = fnav_vec3_from(s->gyro_rps);
    a->n_in++;
    if (a->n_in - a->n_used > HX_AXES_RING) {
        a->n_used = a->n_in - HX_AXES_RING; /* overwritten unmatched: skipped */
    }
}

/* The swing's end speeds at its first ZUPT frame, held until the run
 * proves a stance (hx_axes_frame). */
static void hold_end(hx_axes_t *a, int64_t t_ns)
{
    int k;
    for (k = 0; k < HX_AXES_STATES; k++) {
        a->v_held_mps[k] = (double)fnav_vec3_norm(a->v_mps[k]);
    }
    a->t_held_ns = t_ns;
    a->held = 1;
}

static void end_swing(hx_axes_t *a)
{
    double d = 1e-9 * (double)(a->t_held_ns - a->t_swing_ns);
    int k;
    a->in_swing = 0;
    a->held = 0;
    if (d < SWING_MIN_S || d > SWING_MAX_S || a->failed) {
        return;
    }
    if (a->nswing == a->cap) {
        size_t nc = a->cap ? 2 * a->cap : 256;
        double *p = (double *)realloc(a->vend, nc * HX_AXES_STATES * sizeof *p);
        if (p == NULL) {
            a->failed = 1;
            return;
        }
        a->vend = p;
        a->cap = nc;
    }
    for (k = 0; k < HX_AXES_STATES; k++) {
        a->vend[a->nswing * HX_AXES_STATES + (size_t)k] = a->v_held_mps[k];
    }
    a->nswing++;
}

/* One sample of ring slot `slot`, every map and time scale: the
 * strapdown's first-order step, q <- q exp(P w dt), v <- v + (C_nb f + (0,
 * 0, g)) dt. */
static void integrate(hx_axes_t *a, size_t slot, double dt)
{
    fnav_vec3_t g_n = fnav_vec3(FNAV_R(0.0), FNAV_R(0.0), a->g_mps2);
    int k;
    for (k = 0; k < HX_AXES_STATES; k++) {
        const fnav_real_t h = (fnav_real_t)(k < HX_AXES_MAPS ? dt : dt * SCALE[k - HX_AXES_MAPS]);
        fnav_vec3_t th = fnav_vec3_scale(hx_axes_map(k < HX_AXES_MAPS ? k : 0, a->gyr[slot]), h);
        a->q_nb[k] = fnav_quat_normalize(fnav_quat_mul(a->q_nb[k], fnav_quat_from_rotvec(th)));
        a->v_mps[k] = fnav_vec3_add(
            a->v_mps[k], fnav_vec3_scale(fnav_vec3_add(fnav_quat_rotate(a->q_nb[k], a->acc[slot]), g_n), h));
    }
}

/* The swing begins at ring sample n (its first frame without a ZUPT): start
 * every map at the stillest of the stance samples before it (least |w| within
 * STILL_S), tilted along the mean f of TILT_S up to that sample, and integrate
 * from there up to n. */
static void start_swing(hx_axes_t *a, size_t n)
{
    size_t ahead = a->n_in - n, back = a->stance_run, lo, j, best = n - 1u, m = 0;
    int64_t t_end = a->t_ns[(n - 1u) % HX_AXES_RING];
    fnav_real_t wmin = fnav_vec3_norm(a->gyr[best % HX_AXES_RING]);
    fnav_vec3_t f = fnav_vec3_zero();
    fnav_align_result_t al;
    int k;
    if (back > HX_AXES_RING - ahead) {
        back = HX_AXES_RING - ahead; /* older samples are overwritten (frames far behind the samples) */
    }
    if (back == 0u) {
        return;
    }
    lo = n - back; /* the oldest stance sample held */
    for (j = n - 1u; j > lo; j--) {
        size_t q = (j - 1u) % HX_AXES_RING;
        if (1e-9 * (double)(t_end - a->t_ns[q]) > STILL_S) {
            break;
        }
        if (fnav_vec3_norm(a->gyr[q]) < wmin) {
            wmin = fnav_vec3_norm(a->gyr[q]);
            best = j - 1u;
        }
    }
    for (j = best;; j--) {
        size_t q = j % HX_AXES_RING;
        if (m > 0 && 1e-9 * (double)(a->t_ns[best % HX_AXES_RING] - a->t_ns[q]) > TILT_S) {
            break;
        }
        f = fnav_vec3_add(f, a->acc[q]);
        m++;
        if (j == lo) {
            break;
        }
    }
    f = fnav_vec3_scale(f, FNAV_R(1.0) / (fnav_real_t)m);
    a->g_mps2 = fnav_vec3_norm(f);
    if (fnav_align_from_means(f, fnav_vec3_zero(), a->g_mps2, &al) != FNAV_OK) {
        return;
    }
    for (k = 0; k < HX_AXES_STATES; k++) {
        a->q_nb[k] = al.q_nb;
        a->v_mps[k] = fnav_vec3_zero();
    }
    a->in_swing = 1;
    a->t_swing_ns = a->t_ns[n % HX_AXES_RING];
    for (j = best + 1u; j <= n; j++) {
        integrate(a, j % HX_AXES_RING, 1e-9 * (double)(a->t_ns[j % HX_AXES_RING] - a->t_ns[(j - 1u) % HX_AXES_RING]));
    }
}

/* The shortest ZUPT run taken for a stance, s: CYCLE_FRAC of the gait
 * cycle (the median of the last three, as the detector's cycle-scaled run,
 * docs/navigation.md, "Stance detector"), at most half the longest of the
 * last RUNS runs (the detector's lock-in guard); 0 before a cycle is
 * known. */
static double min_run_s(const hx_axes_t *a)
{
    double c0 = a->cyc_s[0], c1 = a->cyc_s[1], c2 = a->cyc_s[2], t, longest = 0.0;
    int j;
    if (a->n_cyc == 0 || a->cycle_frac <= 0.0) {
        return 0.0;
    }
    if (a->n_cyc == 1) {
        t = c0;
    } else if (a->n_cyc == 2) {
        t = c0 < c1 ? c0 : c1;
    } else {
        t = c0 < c1 ? (c1 < c2 ? c1 : (c0 < c2 ? c2 : c0)) : (c0 < c2 ? c0 : (c1 < c2 ? c2 : c1));
    }
    t = a->cycle_frac * (t < (double)FNAV_STANCE_CYCLE_LAG_S ? t : (double)FNAV_STANCE_CYCLE_LAG_S);
    for (j = 0; j < RUNS; j++) {
        longest = a->runs_s[j] > longest ? a->runs_s[j] : longest;
    }
    return t < 0.5 * longest ? t : 0.5 * longest;
}

/* A swing begins: the cycle since the last one (one over
 * FNAV_STANCE_CYCLE_MAX_S spans a stand and clears those known). */
static void cycle_update(hx_axes_t *a, int64_t t_ns)
{
    if (a->have_start) {
        double c = 1e-9 * (double)(t_ns - a->t_start_ns);
        if (c <= 0.0 || c > (double)FNAV_STANCE_CYCLE_MAX_S) {
            a->n_cyc = 0;
        } else {
            a->cyc_s[2] = a->cyc_s[1];
            a->cyc_s[1] = a->cyc_s[0];
            a->cyc_s[0] = c;
            a->n_cyc = a->n_cyc < 3 ? a->n_cyc + 1 : 3;
        }
    }
    a->have_start = 1;
    a->t_start_ns = t_ns;
}

/* A ZUPT run ended (its frames and their span, s): the lock-in guard's
 * memory. */
static void run_end(hx_axes_t *a, double run_s)
{
    int j;
    for (j = RUNS - 1; j > 0; j--) {
        a->runs_s[j] = a->runs_s[j - 1];
    }
    a->runs_s[0] = run_s;
}

/* A swing runs from a stance to the next, a stance being a run of ZUPT
 * frames at least min_run_s long: the check needs stances it can take for
 * rest, not the navigator's latency, so when the navigator runs with a
 * smaller min_zupt_cycle than the default 0.025 (0 for the shortest
 * latency) the check applies the detector's cycle-scaled shortest run at
 * 0.025 itself (with the default or more, the navigator's runs have passed
 * it already, and every run is taken as before). A shorter run inside a swing (with --param
 * min_zupt_cycle=0, the detector's dip where the gyro passes through zero
 * mid-swing in a slow gait: 25 ms at 60 steps/min, 55 ms at 40) neither
 * ends the swing nor starts one: the swing is integrated through it, its
 * end speeds held at the run's first frame until the run is long enough.
 * Split there, each second half began "at rest" where the foot moved at
 * 0.4 m/s, and the walks were told "the sample rate looks wrong"
 * (docs/harness.md, "Axes check"). */
void hx_axes_frame(hx_axes_t *a, const fnav_nav_frame_t *f)
{
    size_t n;
    int stance = (f->flags & FNAV_FRAME_ZUPT) != 0;
    double dt;
    /* its sample: the oldest unmatched one with its time stamp */
    while (a->n_used < a->n_in && a->t_ns[a->n_used % HX_AXES_RING] < f->t_ns) {
        a->n_used++;
        if (a->stance_run > 0) {
            run_end(a, a->run_s);
        }
        a->stance_run = 0; /* a sample without a frame breaks the run */
        a->run_ok = 0;
        a->held = 0; /* ... and its held end: the next run holds its own */
    }
    if (a->n_used == a->n_in || a->t_ns[a->n_used % HX_AXES_RING] != f->t_ns) {
        a->in_swing = 0; /* no sample for this frame (not expected): drop the swing */
        a->held = 0;
        a->stance_run = 0;
        a->run_ok = 0;
        return;
    }
    n = a->n_used++;
    dt = 1e-9 * (double)(f->t_ns - a->t_last_ns);
    if (!stance && !a->in_swing && a->stance_run > 0 && a->run_ok) {
        cycle_update(a, f->t_ns);
        start_swing(a, n);
    } else if (a->in_swing) {
        integrate(a, n % HX_AXES_RING, dt);
    }
    a->t_last_ns = f->t_ns;
    if (stance) {
        if (a->stance_run == 0) {
            a->t_run_ns = f->t_ns;
        }
        if (a->in_swing && !a->held) {
            hold_end(a, f->t_ns);
        }
        /* the run's span: its frames times the interval */
        a->run_s = 1e-9 * (double)(f->t_ns - a->t_run_ns) + dt;
        if (!a->run_ok && a->run_s >= min_run_s(a)) {
            a->run_ok = 1;
        }
        if (a->in_swing && a->run_ok) {
            end_swing(a);
        }
        a->stance_run++;
    } else {
        if (a->stance_run > 0) {
            run_end(a, a->run_s);
        }
        a->held = 0; /* the run was no stance: the swing goes on */
        a->stance_run = 0;
        a->run_ok = 0;
    }
}

static void verdict(const hx_axes_t *a, hx_axes_result_t *r)
{
    double med[HX_AXES_STATES], *col;
    int ts = 0;
    size_t i;
    int k;
    r->swings = a->nswing;
    if (a->nswing < MIN_SWINGS) {
        snprintf(r->msg, sizeof r->msg, "not checked: fewer than %d swings", MIN_SWINGS);
        return;
    }
    col = a->failed ? NULL : (double *)malloc(a->nswing * sizeof *col);
    if (col == NULL) {
        snprintf(r->msg, sizeof r->msg, "%s", NOT_CHECKED_OOM);
        return;
    }
    r->v_other_mps = (double)INFINITY;
    for (k = 0; k < HX_AXES_STATES; k++) {
        for (i = 0; i < a->nswing; i++) {
            col[i] = a->vend[i * HX_AXES_STATES + (size_t)k];
        }
        med[k] = hx_median(col, (int)a->nswing);
        if (k >= HX_AXES_MAPS) {
            /* divided by the scale: shrinking every interval by s shrinks
             * a swing's whole velocity integral by about s, so a foot not
             * yet at rest when the detector calls stance would favour the
             * short scales alone (a looser detector flagged 18 of the 65
             * walks "rate wrong" at x0.5, their ratios 0.44-0.50: a review) */
            if (med[k] / SCALE[k - HX_AXES_MAPS] < med[HX_AXES_MAPS + ts] / SCALE[ts]) {
                ts = k - HX_AXES_MAPS;
            }
            continue;
        }
        if (med[k] < med[r->best]) {
            r->best = k;
        }
        if (k > 0 && med[k] < r->v_other_mps) {
            r->v_other_mps = med[k];
        }
    }
    free(col);
    r->v_scaled_mps = med[HX_AXES_MAPS + ts] / SCALE[ts];
    r->time_scale = SCALE[ts];
    /* a time scale that fits as a map must (RATIO, MARGIN_MPS) and better
     * than every map: the rate, not the axes */
    r->time_problem = med[0] >= RATIO * r->v_scaled_mps && med[0] - r->v_scaled_mps >= MARGIN_MPS &&
                      r->v_scaled_mps < med[r->best];
    r->v_recorded_mps = med[0];
    r->v_best_mps = med[r->best];
    map_name(r->best, r->best_map, sizeof r->best_map);
    r->problem = !r->time_problem && r->best != 0 && med[0] >= RATIO * med[r->best] &&
                 med[0] - med[r->best] >= MARGIN_MPS;
    if (r->time_problem) {
        snprintf(r->msg, sizeof r->msg,
                 "the sample rate looks wrong: integrated through each of %zu swings, the foot ends at %.2f m/s "
                 "(median) with the time as read but at %.2f m/s (over the scale) with every interval %g times as "
                 "long, a rate %g times the one read (no axis map comes as close: %.2f m/s); check the rate the log "
                 "is read at, its time stamps or the rate given (docs/harness.md, \"Axes check\")",
                 a->nswing, med[0], r->v_scaled_mps, r->time_scale, 1.0 / r->time_scale, med[r->best]);
    } else if (r->problem) {
        snprintf(r->msg, sizeof r->msg,
                 "the gyroscope's axes do not match the accelerometer's: integrated through each of %zu swings, the "
                 "foot ends at %.2f m/s (median) as recorded but at %.2f m/s with the gyro read as %s; check the "
                 "gyro's axis order and signs against the accelerometer's (docs/harness.md, \"Axes check\"; a "
                 "CSV's columns are reordered by --columns, and read with the other sign by a '-' before the "
                 "name: gy=-NAME)",
                 a->nswing, med[0], med[r->best], r->best_map);
    } else {
        snprintf(r->msg, sizeof r->msg, "gyro and accelerometer axes agree (%zu swings end at %.2f m/s, median)",
                 a->nswing, med[0]);
    }
}

void hx_axes_finish(hx_axes_t *a, hx_axes_result_t *r)
{
    memset(r, 0, sizeof *r);
    if (a == NULL) {
        snprintf(r->msg, sizeof r->msg, "%s", NOT_CHECKED_OOM);
        return;
    }
    verdict(a, r);
    free(a->vend);
    free(a);
}
