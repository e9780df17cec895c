/* Foot motion generator with exact truth (see hx_motion.h, docs/simulator.md). */
#include "hx_motion.h"
#include "hx_cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define D2R (PI / 180.0)
#define NCOORD 6 /* x, y, z (n frame), roll, pitch, yaw (foot) */

typedef struct {
    double t;
    double v[NCOORD][3]; /* value, first and second derivative */
    int phase;           /* phase of the segment that starts here */
    int leg;
    double still_from;   /* STILL segment: at rest from here (ringing over) */
    /* rolling segment (heel-off over the toe, slap over the heel): the
     * position is the flat-foot position plus Ry(pitch) r - r turned by the
     * heading, r the sensor relative to the contact point in the foot's
     * x-z plane; the contact point does not move */
    int roll;            /* 1: position from the pitch by the pivot formula */
    double flat[3];      /* sensor position with the foot flat, n */
    double rx, rz;       /* sensor relative to the pivot, foot frame, m */
    double psi;          /* heading of the segment, rad */
} knot_t;

typedef struct {
    double t0, dur, w;   /* start, duration, angular frequency rad/s */
    double amp[4];       /* x, y, z displacement (m) and pitch (rad) amplitudes */
    int sym;             /* 0: impact envelope u^2 (1-u)^4; 1: ride envelope u^3 (1-u)^3 */
} ring_t;

typedef struct {
    double t;
    double odo;
} land_t;

struct hx_motion {
    hx_motion_config_t cfg;
    knot_t *k;
    size_t nk, capk;
    double (*coef)[NCOORD][6];
    ring_t *r;
    size_t nr, capr;
    double ring_maxdur;
    land_t *land;
    size_t nland, capl;
    double C_fs[3][3]; /* sensor mounting: v_f = C_fs v_s */
    double q_fs[4];
    int strides;
    int walk_strides; /* of them, those of the walking gait (--speed, --cadence, --stride) */
    /* builder state */
    double odo;
    int leg;
    char *err;
    size_t err_size;
};

/* ------------------------------------------------------------ defaults */

hx_motion_config_t hx_motion_config_default(void)
{
    hx_motion_config_t c;
    memset(&c, 0, sizeof c);
    /* walking: 110 steps/min, 1.4 m stride -> 1.28 m/s; heel strike at
     * 0.5 m/s stopped in 7 ms (peak 1.5 v / T = 107 m/s^2, like the 820 Hz
     * OpenShoe walk) plus a 25 m/s^2 ringing. The impact times of every gait
     * are set so that `harness psd --dc global` finds the paper's Table III
     * lowest usable sampling frequency on a simulated minute at 1 kHz:
     * walking 200 Hz, running 300 Hz, stairs 300 Hz (docs/simulator.md). */
    c.walk.cadence_spm = 110.0;
    c.walk.stride_m = 1.4;
    c.walk.still_frac = 0.35;
    c.walk.heeloff_frac = 0.15;
    c.walk.slap_frac = 0.08;
    c.walk.lift_m = 0.10;
    c.walk.pitch_off_deg = -50.0;
    c.walk.pitch_strike_deg = 25.0;
    c.walk.pitch_mid_deg = -12.5;
    c.walk.roll_deg = 4.0;
    c.walk.land_speed_mps = 0.5;
    c.walk.impact_s = 0.007;
    c.walk.ring_hz = 60.0;
    c.walk.ring_mps2 = 25.0;
    c.walk.ring_s = 0.06;
    /* running: 170 steps/min, 2.4 m stride -> 3.4 m/s; contact at 1 m/s
     * stopped in 5 ms (peak 300 m/s^2) */
    c.run = c.walk;
    c.run.cadence_spm = 170.0;
    c.run.stride_m = 2.4;
    c.run.still_frac = 0.12;
    c.run.heeloff_frac = 0.10;
    c.run.slap_frac = 0.06;
    c.run.lift_m = 0.25;
    c.run.pitch_off_deg = -60.0;
    c.run.pitch_strike_deg = 15.0;
    c.run.pitch_mid_deg = -22.5;
    c.run.roll_deg = 6.0;
    c.run.land_speed_mps = 1.0;
    c.run.impact_s = 0.005;
    c.run.ring_hz = 80.0;
    c.run.ring_mps2 = 60.0;
    c.run.ring_s = 0.05;
    /* stairs: two steps per stride */
    c.stairs_up = c.walk;
    c.stairs_up.cadence_spm = 90.0;
    c.stairs_up.still_frac = 0.35;
    c.stairs_up.heeloff_frac = 0.10;
    c.stairs_up.slap_frac = 0.06;
    c.stairs_up.lift_m = 0.06;
    c.stairs_up.pitch_off_deg = -35.0;
    c.stairs_up.pitch_strike_deg = -8.0; /* forefoot first on the step */
    c.stairs_up.pitch_mid_deg = 15.0; /* toe up over the step's edge */
    c.stairs_up.roll_deg = 3.0;
    c.stairs_up.land_speed_mps = 0.35;
    c.stairs_up.impact_s = 0.005;
    c.stairs_up.ring_mps2 = 15.0;
    c.stairs_down = c.stairs_up;
    c.stairs_down.cadence_spm = 100.0;
    c.stairs_down.pitch_off_deg = -30.0;
    c.stairs_down.pitch_strike_deg = -15.0;
    c.stairs_down.pitch_mid_deg = 10.0;
    c.stairs_down.land_speed_mps = 0.45;
    c.stairs_down.impact_s = 0.005;
    c.stairs_down.ring_hz = 70.0;
    c.stairs_down.ring_mps2 = 30.0;
    /* turning on the spot: the foot lifts, rotates and lands in place */
    c.turn = c.walk;
    c.turn.cadence_spm = 100.0;
    c.turn.still_frac = 0.30;
    c.turn.lift_m = 0.06;
    c.turn.pitch_off_deg = -25.0;
    c.turn.pitch_strike_deg = 10.0;
    c.turn.pitch_mid_deg = -5.0;
    c.turn.roll_deg = 2.0;
    c.turn.land_speed_mps = 0.2;
    c.turn.impact_s = 0.008;
    c.turn.ring_mps2 = 8.0;
    c.stair_rise_m = 0.17;
    c.stair_run_m = 0.28;
    c.elev_speed_mps = 1.5;
    c.elev_accel_mps2 = 1.0;
    c.elev_vib_hz = 150.0; /* paper Fig. 6 */
    c.elev_vib_mps2 = 0.05;
    c.foot_toe_m = 0.12;
    c.foot_heel_m = 0.14;
    c.foot_height_m = 0.05;
    c.g_mps2 = 9.80665;
    return c;
}

/* ------------------------------------------------------------ small math */

void hx_dcm_from_euler(double roll, double pitch, double yaw, double C[3][3])
{
    /* C_nb = Rz(yaw) Ry(pitch) Rx(roll) (Titterton & Weston eq. 3.47) */
    double cr = cos(roll), sr = sin(roll), cp = cos(pitch), sp = sin(pitch), cy = cos(yaw), sy = sin(yaw);
    C[0][0] = cp * cy;
    C[0][1] = -cr * sy + sr * sp * cy;
    C[0][2] = sr * sy + cr * sp * cy;
    C[1][0] = cp * sy;
    C[1][1] = cr * cy + sr * sp * sy;
    C[1][2] = -sr * cy + cr * sp * sy;
    C[2][0] = -sp;
    C[2][1] = sr * cp;
    C[2][2] = cr * cp;
}

static void quat_from_euler(double roll, double pitch, double yaw, double q[4])
{
    double cr = cos(0.5 * roll), sr = sin(0.5 * roll), cp = cos(0.5 * pitch), sp = sin(0.5 * pitch);
    double cy = cos(0.5 * yaw), sy = sin(0.5 * yaw);
    q[0] = cr * cp * cy + sr * sp * sy;
    q[1] = sr * cp * cy - cr * sp * sy;
    q[2] = cr * sp * cy + sr * cp * sy;
    q[3] = cr * cp * sy - sr * sp * cy;
}

void hx_quat_mul(const double a[4], const double b[4], double r[4])
{
    double t[4];
    t[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    t[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    t[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    t[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    memcpy(r, t, sizeof t);
}

static double wrap_pi(double a)
{
    a = fmod(a + PI, 2.0 * PI);
    if (a <= 0.0) {
        a += 2.0 * PI;
    }
    return a - PI;
}

/* ------------------------------------------------------------ builder */

static int fail(hx_motion_t *m, const char *msg, const char *arg)
{
    snprintf(m->err, m->err_size, "%s%s%s", msg, arg ? ": " : "", arg ? arg : "");
    return -1;
}

static knot_t *last_knot(hx_motion_t *m)
{
    return &m->k[m->nk - 1];
}

/* Append a knot; the segment that ends here gets `phase`. */
static int push(hx_motion_t *m, double t, double v[NCOORD][3], int phase)
{
    knot_t *k;
    if (m->nk > 0 && !(t > last_knot(m)->t)) {
        return fail(m, "internal: knot times must increase", NULL);
    }
    if (m->nk == m->capk) {
        size_t cap = m->capk ? 2 * m->capk : 256;
        knot_t *nk = (knot_t *)realloc(m->k, cap * sizeof *nk);
        if (nk == NULL) {
            return fail(m, "out of memory", NULL);
        }
        m->k = nk;
        m->capk = cap;
    }
    if (m->nk > 0) {
        last_knot(m)->phase = phase;
        last_knot(m)->leg = m->leg;
        last_knot(m)->still_from = last_knot(m)->t;
    }
    k = &m->k[m->nk++];
    memset(k, 0, sizeof *k);
    k->t = t;
    memcpy(k->v, v, sizeof k->v);
    k->phase = HX_PHASE_STILL;
    k->leg = m->leg;
    k->still_from = t;
    return 0;
}

static int push_ring(hx_motion_t *m, const ring_t *r)
{
    if (m->nr == m->capr) {
        size_t cap = m->capr ? 2 * m->capr : 64;
        ring_t *nr = (ring_t *)realloc(m->r, cap * sizeof *nr);
        if (nr == NULL) {
            return fail(m, "out of memory", NULL);
        }
        m->r = nr;
        m->capr = cap;
    }
    m->r[m->nr++] = *r;
    if (r->dur > m->ring_maxdur) {
        m->ring_maxdur = r->dur;
    }
    return 0;
}

static int push_land(hx_motion_t *m, double t, double dist)
{
    if (m->nland == m->capl) {
        size_t cap = m->capl ? 2 * m->capl : 64;
        land_t *nl = (land_t *)realloc(m->land, cap * sizeof *nl);
        if (nl == NULL) {
            return fail(m, "out of memory", NULL);
        }
        m->land = nl;
        m->capl = cap;
    }
    m->odo += dist;
    m->land[m->nland].t = t;
    m->land[m->nland].odo = m->odo;
    m->nland++;
    return 0;
}

/* A still state at position p with heading yaw. */
static void still_state(double v[NCOORD][3], const double p[3], double yaw)
{
    int c;
    memset(v, 0, sizeof(double) * NCOORD * 3);
    for (c = 0; c < 3; c++) {
        v[c][0] = p[c];
    }
    v[5][0] = yaw;
}

static int add_still(hx_motion_t *m, double dur, int phase)
{
    double v[NCOORD][3];
    knot_t *k = last_knot(m);
    memcpy(v, k->v, sizeof v);
    return push(m, k->t + dur, v, phase);
}

/* Displacement of the sensor when the foot pitches by th about a contact
 * point, sensor at (rx, rz) from that point in the foot's x-z plane:
 * Ry(th) r - r and its first two derivatives with respect to th. */
static void pivot(double th, double rx, double rz, double d0[2], double d1[2], double d2[2])
{
    double c = cos(th), s = sin(th);
    d0[0] = rx * c + rz * s - rx;
    d0[1] = -rx * s + rz * c - rz;
    d1[0] = -rx * s + rz * c;
    d1[1] = -rx * c - rz * s;
    d2[0] = -rx * c - rz * s;
    d2[1] = rx * s - rz * c;
}

double hx_gait_max_impact_s(const hx_gait_t *g)
{
    const double T = 120.0 / g->cadence_spm;
    /* as stride() computes the swing, to the last bit */
    return 0.3 * (T - g->heeloff_frac * T - g->slap_frac * T - g->still_frac * T);
}

/* One stride of the sensor foot from the current still state: horizontal
 * displacement (dx, dy) in n, height change dz (n, down positive), heading
 * change dpsi; ps scales the pitch angles (turning on the spot). */
static int stride(hx_motion_t *m, const hx_gait_t *g, double dx, double dy, double dz, double dpsi, double ps)
{
    const hx_motion_config_t *cf = &m->cfg;
    knot_t k0 = *last_knot(m);
    double T = 120.0 / g->cadence_spm;
    double T_ho = g->heeloff_frac * T, T_sl = g->slap_frac * T, T_st = g->still_frac * T;
    double T_sw = T - T_ho - T_sl - T_st, T_imp;
    double psi0 = k0.v[5][0], psi1 = psi0 + dpsi, L = hypot(dx, dy);
    double chi = (L > 1e-9) ? atan2(dy, dx) : psi0 + 0.5 * dpsi;
    double cchi = cos(chi), schi = sin(chi);
    double P0[3], P1[3], Pb[3], Pd[3], Ps[3];
    double th_b = g->pitch_off_deg * D2R * ps, th_s = g->pitch_strike_deg * D2R * ps;
    double d0[2], d1[2], d2[2], w_roll;
    double t0 = k0.t, tb, tc, td, ts, tf, tg;
    double v[NCOORD][3];
    ring_t ring;
    int c, rings = 0;
    if (!(T_sw > 0.05)) {
        return fail(m, "gait fractions leave no time to swing", NULL);
    }
    T_imp = hx_gait_max_impact_s(g);
    T_imp = g->impact_s < T_imp ? g->impact_s : T_imp;
    tb = t0 + T_ho;
    ts = tb + T_sw;
    td = ts - T_imp;
    tc = 0.5 * (tb + td);
    tf = ts + T_sl;
    tg = t0 + T;
    for (c = 0; c < 3; c++) {
        P0[c] = k0.v[c][0];
    }
    P1[0] = P0[0] + dx;
    P1[1] = P0[1] + dy;
    P1[2] = P0[2] + dz;

    /* heel-off: the foot rolls over the toe (a rigid rotation about the
     * toe's contact point) until toe-off. The foot is still rotating
     * toe-down at toe-off (the pitch minimum comes early in the swing), as
     * in real gaits: a zero rate there, with |f| near g, would look like a
     * stance to a detector. */
    {
        double wb = th_b / T_ho, rx = -cf->foot_toe_m, rz = -cf->foot_height_m;
        knot_t *ka = last_knot(m);
        ka->roll = 1;
        memcpy(ka->flat, P0, sizeof ka->flat);
        ka->rx = rx;
        ka->rz = rz;
        ka->psi = psi0;
        pivot(th_b, rx, rz, d0, d1, d2);
        memset(v, 0, sizeof v);
        Pb[0] = P0[0] + d0[0] * cos(psi0);
        Pb[1] = P0[1] + d0[0] * sin(psi0);
        Pb[2] = P0[2] + d0[1];
        for (c = 0; c < 3; c++) {
            v[c][0] = Pb[c];
        }
        /* v = dp/dth th', a = d2p/dth2 th'^2 + dp/dth th'' (th'' = 0 here) */
        v[0][1] = d1[0] * wb * cos(psi0);
        v[1][1] = d1[0] * wb * sin(psi0);
        v[2][1] = d1[1] * wb;
        v[0][2] = d2[0] * wb * wb * cos(psi0);
        v[1][2] = d2[0] * wb * wb * sin(psi0);
        v[2][2] = d2[1] * wb * wb;
        v[4][0] = th_b;
        v[4][1] = wb;
        v[5][0] = psi0;
        if (push(m, tb, v, HX_PHASE_HEELOFF) != 0) {
            return -1;
        }
    }

    /* contact: heel first (th_s >= 0, pivot at the heel) or toe first */
    {
        double rx = th_s >= 0.0 ? cf->foot_heel_m : -cf->foot_toe_m;
        pivot(th_s, rx, -cf->foot_height_m, d0, d1, d2);
    }
    Ps[0] = P1[0] + d0[0] * cos(psi1);
    Ps[1] = P1[1] + d0[0] * sin(psi1);
    Ps[2] = P1[2] + d0[1];
    /* just before contact: descending at land_speed, forward at half of it */
    {
        double vf = 0.5 * g->land_speed_mps, vz = g->land_speed_mps;
        Pd[0] = Ps[0] - 0.5 * T_imp * vf * cchi;
        Pd[1] = Ps[1] - 0.5 * T_imp * vf * schi;
        Pd[2] = Ps[2] - 0.5 * T_imp * vz;

        /* mid-swing: peak forward speed, top of the clearance */
        {
            double Tm = td - tb;
            double hx = hypot(Pd[0] - Pb[0], Pd[1] - Pb[1]);
            double top = (P0[2] < P1[2] ? P0[2] : P1[2]) - g->lift_m;
            double vpk = 1.75 * hx / Tm;
            memset(v, 0, sizeof v);
            v[0][0] = 0.5 * (Pb[0] + Pd[0]);
            v[1][0] = 0.5 * (Pb[1] + Pd[1]);
            v[2][0] = top;
            v[0][1] = vpk * cchi;
            v[1][1] = vpk * schi;
            v[2][1] = (Pd[2] - Pb[2]) / Tm;
            v[2][2] = 2.0 * PI * PI * (0.5 * (Pb[2] + Pd[2]) - top) / (Tm * Tm);
            w_roll = g->roll_deg * D2R * ps;
            v[3][0] = w_roll;
            /* pitch rate in mid-swing: the harmonic mean of the two chord
             * slopes (Fritsch-Carlson), zero at a peak of toe clearance */
            {
                double s1 = (g->pitch_mid_deg * D2R * ps - th_b) / (0.5 * Tm);
                double s2 = (th_s - g->pitch_mid_deg * D2R * ps) / (0.5 * Tm);
                v[4][0] = g->pitch_mid_deg * D2R * ps;
                v[4][1] = (s1 * s2 > 0.0) ? 2.0 / (1.0 / s1 + 1.0 / s2) : 0.0;
            }
            v[5][0] = psi0 + 0.5 * dpsi;
            v[5][1] = 1.875 * dpsi / Tm;
            if (push(m, tc, v, HX_PHASE_SWING) != 0) {
                return -1;
            }
        }
        memset(v, 0, sizeof v);
        for (c = 0; c < 3; c++) {
            v[c][0] = Pd[c];
        }
        v[0][1] = vf * cchi;
        v[1][1] = vf * schi;
        v[2][1] = vz;
        v[4][0] = th_s;
        /* still rotating towards the contact attitude; the contact stops it
         * (an angular impact, as the gyros of real walks show) */
        v[4][1] = (th_s - g->pitch_mid_deg * D2R * ps) / (td - tb);
        v[5][0] = psi1;
        if (push(m, td, v, HX_PHASE_SWING) != 0) {
            return -1;
        }
    }
    /* contact: foot at rest on its contact point, about to slap down by
     * rolling over it (pitch rate and acceleration zero at contact, so the
     * pivot formula gives zero velocity and acceleration here too) */
    memset(v, 0, sizeof v);
    for (c = 0; c < 3; c++) {
        v[c][0] = Ps[c];
    }
    v[4][0] = th_s;
    v[5][0] = psi1;
    if (push(m, ts, v, HX_PHASE_LANDING) != 0) {
        return -1;
    }
    {
        knot_t *ke = last_knot(m);
        ke->roll = 1;
        memcpy(ke->flat, P1, sizeof ke->flat);
        ke->rx = th_s >= 0.0 ? cf->foot_heel_m : -cf->foot_toe_m;
        ke->rz = -cf->foot_height_m;
        ke->psi = psi1;
    }
    /* foot flat */
    still_state(v, P1, psi1);
    if (push(m, tf, v, HX_PHASE_SLAP) != 0) {
        return -1;
    }
    /* still until the next stride; at rest once the ringing is over */
    if (push(m, tg, v, HX_PHASE_STILL) != 0) {
        return -1;
    }
    if (g->ring_mps2 > 0.0 && g->ring_s > 0.0 && g->ring_hz > 0.0) {
        double w = 2.0 * PI * g->ring_hz, a = g->ring_mps2 / (w * w);
        memset(&ring, 0, sizeof ring);
        ring.t0 = ts;
        ring.dur = g->ring_s;
        ring.w = w;
        ring.amp[0] = 0.4 * a * cchi;
        ring.amp[1] = 0.4 * a * schi;
        ring.amp[2] = -a;
        ring.amp[3] = a / 0.03; /* the shoe rocks about a point ~3 cm away */
        ring.sym = 0;
        if (push_ring(m, &ring) != 0) {
            return -1;
        }
        rings = 1;
    }
    /* at rest from foot flat, or from the ringing's end if it rings longer
     * (without a ringing ring_s is no time at all: the running slap, 42 ms,
     * was not still for another 8 ms with ring_mps2 0) */
    m->k[m->nk - 2].still_from = (rings && ts + g->ring_s > tf) ? ts + g->ring_s : tf;
    if (m->k[m->nk - 2].still_from >= tg) {
        return fail(m, "the shoe ringing outlasts the stance; shorten ring_s", NULL);
    }
    m->strides++;
    if (g == &cf->walk) {
        m->walk_strides++;
    }
    return push_land(m, tf, L);
}

static int turn_in_place(hx_motion_t *m, double deg)
{
    int n = (int)ceil(fabs(deg) / 45.0 - 1e-9), i;
    for (i = 0; i < n; i++) {
        if (stride(m, &m->cfg.turn, 0.0, 0.0, 0.0, deg * D2R / n, 1.0) != 0) {
            return -1;
        }
    }
    return 0;
}

static int walk_leg(hx_motion_t *m, const hx_gait_t *g, double dist, double turn_deg)
{
    int n = (int)floor(dist / g->stride_m + 0.5), i;
    double L, dpsi;
    if (n < 1) {
        n = 1;
    }
    L = dist / n;
    dpsi = turn_deg * D2R / n;
    for (i = 0; i < n; i++) {
        double psi = last_knot(m)->v[5][0] + 0.5 * dpsi;
        if (stride(m, g, L * cos(psi), L * sin(psi), 0.0, dpsi, 1.0) != 0) {
            return -1;
        }
    }
    return 0;
}

static int stairs_leg(hx_motion_t *m, int up, int steps, double turn_deg)
{
    const hx_gait_t *g = up ? &m->cfg.stairs_up : &m->cfg.stairs_down;
    int n = (steps + 1) / 2, i, left = steps;
    double dpsi = turn_deg * D2R / n;
    for (i = 0; i < n; i++) {
        int k = left >= 2 ? 2 : 1;
        double psi = last_knot(m)->v[5][0] + 0.5 * dpsi;
        double L = k * m->cfg.stair_run_m, dz = (up ? -1.0 : 1.0) * k * m->cfg.stair_rise_m;
        if (stride(m, g, L * cos(psi), L * sin(psi), dz, dpsi, 1.0) != 0) {
            return -1;
        }
        left -= k;
    }
    return 0;
}

/* Elevator ride of height h (positive up): smooth trapezoidal speed. */
static int elevator_leg(hx_motion_t *m, double h)
{
    const hx_motion_config_t *cf = &m->cfg;
    double H = fabs(h), s = h > 0.0 ? -1.0 : 1.0; /* n frame: up is -z */
    double vc = cf->elev_speed_mps, Ta, Tc, z0, t0;
    double v[NCOORD][3];
    ring_t ring;
    if (H < 1e-6) {
        return 0;
    }
    if (add_still(m, 2.0, HX_PHASE_STILL) != 0) { /* doors */
        return -1;
    }
    /* ramps: the speed follows a cubic smooth step (zero acceleration at
     * both ends), peak acceleration 1.5 vc / Ta */
    Ta = 1.5 * vc / cf->elev_accel_mps2;
    if (vc * Ta > H) { /* short ride: never reaches cruise speed */
        vc = sqrt(H * cf->elev_accel_mps2 / 1.5);
        Ta = 1.5 * vc / cf->elev_accel_mps2;
    }
    Tc = (H - vc * Ta) / vc;
    memcpy(v, last_knot(m)->v, sizeof v);
    z0 = v[2][0];
    t0 = last_knot(m)->t;
    v[2][0] = z0 + s * 0.5 * vc * Ta;
    v[2][1] = s * vc;
    if (push(m, t0 + Ta, v, HX_PHASE_RIDE) != 0) {
        return -1;
    }
    if (Tc > 1e-6) {
        v[2][0] = z0 + s * (0.5 * vc * Ta + vc * Tc);
        if (push(m, t0 + Ta + Tc, v, HX_PHASE_RIDE) != 0) {
            return -1;
        }
    }
    v[2][0] = z0 + s * H;
    v[2][1] = 0.0;
    if (push(m, t0 + 2.0 * Ta + Tc, v, HX_PHASE_RIDE) != 0) {
        return -1;
    }
    if (cf->elev_vib_mps2 > 0.0 && cf->elev_vib_hz > 0.0) {
        double w = 2.0 * PI * cf->elev_vib_hz;
        memset(&ring, 0, sizeof ring);
        ring.t0 = t0;
        ring.dur = 2.0 * Ta + Tc;
        ring.w = w;
        ring.amp[2] = cf->elev_vib_mps2 / (w * w);
        ring.sym = 1;
        if (push_ring(m, &ring) != 0) {
            return -1;
        }
    }
    return add_still(m, 2.0, HX_PHASE_STILL);
}

static int home_leg(hx_motion_t *m)
{
    knot_t *k = last_knot(m);
    double dx = -k->v[0][0], dy = -k->v[1][0], D = hypot(dx, dy);
    if (D < 0.05) {
        return 0;
    }
    if (turn_in_place(m, wrap_pi(atan2(dy, dx) - k->v[5][0]) / D2R) != 0) {
        return -1;
    }
    k = last_knot(m); /* the turn strides land in place: recompute anyway */
    dx = -k->v[0][0];
    dy = -k->v[1][0];
    D = hypot(dx, dy);
    {
        int n = (int)floor(D / m->cfg.walk.stride_m + 0.5), i;
        double chi = atan2(dy, dx);
        if (n < 1) {
            n = 1;
        }
        for (i = 0; i < n; i++) {
            double psi = last_knot(m)->v[5][0];
            if (stride(m, &m->cfg.walk, D / n * cos(chi), D / n * sin(chi), 0.0, wrap_pi(chi - psi), 1.0) != 0) {
                return -1;
            }
        }
    }
    /* land exactly on the start (the stride arithmetic is exact up to rounding) */
    k = last_knot(m);
    k->v[0][0] = 0.0;
    k->v[1][0] = 0.0;
    m->k[m->nk - 2].v[0][0] = 0.0;
    m->k[m->nk - 2].v[1][0] = 0.0;
    m->k[m->nk - 3].flat[0] = 0.0; /* the slap rolls down onto it */
    m->k[m->nk - 3].flat[1] = 0.0;
    return 0;
}

/* ------------------------------------------------------------ scripts */

const char *hx_motion_scenario_list(void)
{
    return "stand, walk, run, stairs, elevator, loop, paper, mixed";
}

int hx_motion_scenario(const char *name, const hx_motion_config_t *cfg, double duration_s, char *script,
                       size_t size)
{
    const double still = 5.0;
    double D = duration_s;
    double walk_v = cfg->walk.stride_m * cfg->walk.cadence_spm / 120.0;
    double run_v = cfg->run.stride_m * cfg->run.cadence_spm / 120.0;
    if (strcmp(name, "stand") == 0) {
        snprintf(script, size, "stand:%g", D > 0.0 ? D : 60.0);
    } else if (strcmp(name, "walk") == 0) {
        double T = (D > 0.0 ? D : 60.0) - 2.0 * still;
        snprintf(script, size, "stand:%g,walk:%.3f,stand:%g", still, (T > 2.0 ? T : 2.0) * walk_v, still);
    } else if (strcmp(name, "run") == 0) {
        double T = (D > 0.0 ? D : 60.0) - 2.0 * still;
        snprintf(script, size, "stand:%g,run:%.3f,stand:%g", still, (T > 2.0 ? T : 2.0) * run_v, still);
    } else if (strcmp(name, "stairs") == 0) {
        snprintf(script, size,
                 "stand:%g,walk:3,stairs-up:12,turn:180,stairs-up:12,walk:4,turn:180,walk:4,"
                 "stairs-down:12,turn:180,stairs-down:12,walk:3,stand:%g",
                 still, still);
    } else if (strcmp(name, "elevator") == 0) {
        snprintf(script, size, "stand:%g,walk:5,elevator:8,walk:5,turn:180,walk:5,elevator:-8,walk:5,stand:%g",
                 still, still);
    } else if (strcmp(name, "loop") == 0) {
        /* a square walked clockwise seen from above (right turns: positive
         * yaw, NED), back to the start */
        double T = (D > 0.0 ? D : 90.0) - 2.0 * still - 12.0;
        double side = (T > 8.0 ? T : 8.0) * walk_v / 4.0;
        snprintf(script, size, "stand:%g,walk:%.3f,turn:90,walk:%.3f,turn:90,walk:%.3f,turn:90,home,stand:%g", still,
                 side, side, side, still);
    } else if (strcmp(name, "paper") == 0) {
        /* like the paper's Fig. 11: corridors, two flights up and down
         * (about one floor each way; the paper's walk went two floors up
         * and down), back to the start room */
        snprintf(script, size,
                 "stand:%g,walk:8,turn:90,walk:30,turn:180,walk:40,turn:-90,walk:6,stairs-up:12,turn:180,"
                 "stairs-up:12,walk:6,turn:90,walk:25,turn:90,walk:6,stairs-down:12,turn:180,stairs-down:12,"
                 "walk:10,home,stand:%g",
                 still, still);
    } else if (strcmp(name, "mixed") == 0) {
        snprintf(script, size,
                 "stand:%g,walk:20,run:%.1f,walk:10,turn:90,stairs-up:12,turn:180,stairs-up:12,walk:5,"
                 "elevator:-4.08,walk:5,home,stand:%g",
                 still, 10.0 * run_v, still);
    } else {
        return -1;
    }
    return 0;
}

static int parse_leg(hx_motion_t *m, char *item)
{
    char *name = item, *a1 = NULL, *a2 = NULL;
    double x1 = 0.0, x2 = 0.0;
    a1 = strchr(item, ':');
    if (a1 != NULL) {
        *a1++ = '\0';
        a2 = strchr(a1, ':');
        if (a2 != NULL) {
            *a2++ = '\0';
        }
        if (hx_parse_number(a1, &x1) != 0) {
            return fail(m, "bad number in motion script", a1);
        }
        if (a2 != NULL) {
            if (hx_parse_number(a2, &x2) != 0) {
                return fail(m, "bad number in motion script", a2);
            }
        }
    }
    if (strcmp(name, "home") == 0) {
        if (a1 != NULL) {
            return fail(m, "home takes no value", a1);
        }
        return home_leg(m);
    }
    if (a1 == NULL) {
        return fail(m, "motion script item needs a value (NAME:VALUE)", name);
    }
    if (a2 != NULL && (strcmp(name, "stand") == 0 || strcmp(name, "turn") == 0 || strcmp(name, "elevator") == 0)) {
        /* only walk, run and the stairs take a second value: an extra one
         * is refused, not ignored without a word */
        return fail(m, "stand, turn and elevator take one value (NAME:VALUE)", a2);
    }
    if (a2 != NULL && fabs(x2) > 3600.0) {
        /* the turn of a walk, run or stairs leg, bounded as a turn item's:
         * 1e300 deg would write infinite and NaN gyro samples */
        return fail(m, "the turn of a leg must be within +-3600 deg", a2);
    }
    if (strcmp(name, "stand") == 0) {
        if (!(x1 > 0.0) || x1 > 1e6) {
            return fail(m, "stand needs a duration in (0, 1e6] s", a1);
        }
        return add_still(m, x1, HX_PHASE_STILL);
    }
    if (strcmp(name, "walk") == 0 || strcmp(name, "run") == 0) {
        if (!(x1 > 0.0) || x1 > 1e5) {
            return fail(m, "walk/run needs a distance in (0, 1e5] m", a1);
        }
        return walk_leg(m, name[0] == 'w' ? &m->cfg.walk : &m->cfg.run, x1, x2);
    }
    if (strcmp(name, "stairs-up") == 0 || strcmp(name, "stairs-down") == 0) {
        if (!(x1 >= 1.0) || x1 > 1e4 || x1 != floor(x1)) {
            return fail(m, "stairs needs a whole number of steps (1..10000)", a1);
        }
        return stairs_leg(m, name[7] == 'u', (int)x1, x2);
    }
    if (strcmp(name, "turn") == 0) {
        if (fabs(x1) > 3600.0) {
            return fail(m, "turn needs an angle within +-3600 deg", a1);
        }
        return turn_in_place(m, x1);
    }
    if (strcmp(name, "elevator") == 0) {
        if (fabs(x1) > 1000.0) {
            return fail(m, "elevator needs a height within +-1000 m", a1);
        }
        return elevator_leg(m, x1);
    }
    return fail(m, "unknown motion (scenarios: stand, walk, run, stairs, elevator, loop, paper, mixed; "
                   "script items: stand, walk, run, stairs-up, stairs-down, turn, elevator, home)",
                name);
}

static void build_coefficients(hx_motion_t *m)
{
    size_t i;
    int c;
    for (i = 0; i + 1 < m->nk; i++) {
        const knot_t *a = &m->k[i], *b = &m->k[i + 1];
        double h = b->t - a->t;
        for (c = 0; c < NCOORD; c++) {
            double p0 = a->v[c][0], V0 = a->v[c][1] * h, A0 = a->v[c][2] * h * h;
            double p1 = b->v[c][0], V1 = b->v[c][1] * h, A1 = b->v[c][2] * h * h;
            double dp = p1 - p0;
            double *k = m->coef[i][c];
            /* quintic Hermite: value, slope and curvature at both ends */
            k[0] = p0;
            k[1] = V0;
            k[2] = 0.5 * A0;
            k[3] = 10.0 * dp - 6.0 * V0 - 4.0 * V1 - 1.5 * A0 + 0.5 * A1;
            k[4] = -15.0 * dp + 8.0 * V0 + 7.0 * V1 + 1.5 * A0 - A1;
            k[5] = 6.0 * dp - 3.0 * V0 - 3.0 * V1 - 0.5 * A0 + 0.5 * A1;
        }
    }
}

hx_motion_t *hx_motion_create(const hx_motion_config_t *cfg, const char *script, double duration_s, char *err,
                              size_t err_size)
{
    hx_motion_t *m;
    char buf[2048], *save = NULL, *item;
    double v[NCOORD][3], zero[3] = { 0.0, 0.0, 0.0 };
    size_t i;
    int scenario = 0, items = 0;
    if (cfg == NULL || script == NULL) {
        snprintf(err, err_size, "internal: no motion configuration");
        return NULL;
    }
    if (strchr(script, ':') == NULL && strchr(script, ',') == NULL && strcmp(script, "home") != 0) {
        if (hx_motion_scenario(script, cfg, duration_s, buf, sizeof buf) != 0) {
            snprintf(err, err_size, "unknown motion '%s' (scenarios: %s; or a script such as stand:5,walk:20)",
                     script, hx_motion_scenario_list());
            return NULL;
        }
        scenario = 1;
    } else if (strlen(script) >= sizeof buf) {
        snprintf(err, err_size, "motion script too long (max %zu characters)", sizeof buf - 1);
        return NULL;
    } else {
        strcpy(buf, script);
    }
    if (!(cfg->g_mps2 > 0.0) || !(cfg->walk.cadence_spm > 0.0) || !(cfg->run.cadence_spm > 0.0) ||
        !(cfg->walk.stride_m > 0.0) || !(cfg->run.stride_m > 0.0)) {
        snprintf(err, err_size, "motion: cadence, stride and gravity must be positive");
        return NULL;
    }
    m = (hx_motion_t *)calloc(1, sizeof *m);
    if (m == NULL) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    m->cfg = *cfg;
    m->err = err;
    m->err_size = err_size;
    hx_dcm_from_euler(cfg->mount_deg[0] * D2R, cfg->mount_deg[1] * D2R, cfg->mount_deg[2] * D2R, m->C_fs);
    quat_from_euler(cfg->mount_deg[0] * D2R, cfg->mount_deg[1] * D2R, cfg->mount_deg[2] * D2R, m->q_fs);
    still_state(v, zero, 0.0);
    if (push(m, 0.0, v, HX_PHASE_STILL) != 0) {
        hx_motion_free(m);
        return NULL;
    }
    for (item = strtok_r(buf, ",", &save); item != NULL; item = strtok_r(NULL, ",", &save)) {
        while (*item == ' ') {
            item++;
        }
        if (parse_leg(m, item) != 0) {
            if (scenario) {
                /* the item is the scenario's, sized to the duration: say so
                 * (not "walk/run needs a distance in (0, 1e5] m: 128320.500"
                 * for --duration 1e5, a distance never given) */
                char why[256];
                snprintf(why, sizeof why, "%s", err);
                if (duration_s > 0.0) {
                    snprintf(err, err_size, "motion '%s' sized to %g s: %s", script, duration_s, why);
                } else {
                    snprintf(err, err_size, "motion '%s': %s", script, why);
                }
            }
            hx_motion_free(m);
            return NULL;
        }
        m->leg++;
        items++;
    }
    if (items == 0) {
        /* "," or ",," is refused, not one second of standing with exit 0 */
        snprintf(err, err_size, "empty motion script '%s' (items such as stand:5,walk:20)", script);
        hx_motion_free(m);
        return NULL;
    }
    if (m->nk < 2 && add_still(m, 1.0, HX_PHASE_STILL) != 0) {
        hx_motion_free(m);
        return NULL;
    }
    m->coef = (double(*)[NCOORD][6])malloc((m->nk - 1) * sizeof *m->coef);
    if (m->coef == NULL) {
        snprintf(err, err_size, "out of memory");
        hx_motion_free(m);
        return NULL;
    }
    build_coefficients(m);
    for (i = 0; i < m->nk; i++) {
        if (m->k[i].phase != HX_PHASE_STILL) {
            m->k[i].still_from = HUGE_VAL;
        }
    }
    m->err = NULL;
    return m;
}

void hx_motion_free(hx_motion_t *m)
{
    if (m != NULL) {
        free(m->k);
        free(m->coef);
        free(m->r);
        free(m->land);
        free(m);
    }
}

double hx_motion_duration(const hx_motion_t *m)
{
    return m->k[m->nk - 1].t;
}

int hx_motion_strides(const hx_motion_t *m)
{
    return m->strides;
}

int hx_motion_walk_strides(const hx_motion_t *m)
{
    return m->walk_strides;
}

int hx_motion_strides_until(const hx_motion_t *m, double t)
{
    size_t i, n = 0;
    for (i = 0; i < m->nland; i++) { /* one landing per stride, in time order */
        n += m->land[i].t <= t;
    }
    return (int)n;
}

size_t hx_motion_nknots(const hx_motion_t *m)
{
    return m->nk;
}

double hx_motion_knot_time(const hx_motion_t *m, size_t i)
{
    return i < m->nk ? m->k[i].t : m->k[m->nk - 1].t;
}

/* ------------------------------------------------------------ evaluation */

/* Envelopes on u in [0, 1] with value and derivatives (per u): zero with
 * first and second derivative at both ends, except the impact one, which
 * starts with zero value and slope (so the ringing is C2 at contact). */
static void envelope(int sym, double u, double e[3])
{
    double a = 1.0 - u;
    if (sym) {
        /* 64 u^3 (1-u)^3 */
        e[0] = 64.0 * u * u * u * a * a * a;
        e[1] = 64.0 * (3.0 * u * u * a * a * a - 3.0 * u * u * u * a * a);
        e[2] = 64.0 * (6.0 * u * a * a * a - 18.0 * u * u * a * a + 6.0 * u * u * u * a);
    } else {
        /* (729/16) u^2 (1-u)^4, peak 1 at u = 1/3 */
        const double k = 729.0 / 16.0;
        e[0] = k * u * u * a * a * a * a;
        e[1] = k * (2.0 * u * a * a * a * a - 4.0 * u * u * a * a * a);
        e[2] = k * (2.0 * a * a * a * a - 16.0 * u * a * a * a + 12.0 * u * u * a * a);
    }
}

static size_t find_segment(const hx_motion_t *m, double t)
{
    size_t lo = 0, hi = m->nk - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (m->k[mid].t <= t) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

void hx_motion_eval(const hx_motion_t *m, double t, hx_truth_t *o)
{
    double p[NCOORD][3], tc = t;
    double C_nf[3][3], C_ns[3][3], w_f[3], q_nf[4], fn[3];
    double sr, cr, sp, cp;
    size_t i;
    int c, r;
    memset(o, 0, sizeof *o);
    o->t_s = t;
    if (tc < m->k[0].t) {
        tc = m->k[0].t;
    }
    if (tc > m->k[m->nk - 1].t) {
        tc = m->k[m->nk - 1].t;
    }
    i = find_segment(m, tc);
    if (i + 1 >= m->nk) {
        i = m->nk - 2;
    }
    {
        double h = m->k[i + 1].t - m->k[i].t, s = (tc - m->k[i].t) / h;
        for (c = 0; c < NCOORD; c++) {
            const double *k = m->coef[i][c];
            p[c][0] = k[0] + s * (k[1] + s * (k[2] + s * (k[3] + s * (k[4] + s * k[5]))));
            p[c][1] = (k[1] + s * (2.0 * k[2] + s * (3.0 * k[3] + s * (4.0 * k[4] + s * 5.0 * k[5])))) / h;
            p[c][2] = (2.0 * k[2] + s * (6.0 * k[3] + s * (12.0 * k[4] + s * 20.0 * k[5]))) / (h * h);
        }
    }
    if (m->k[i].roll && tc > m->k[0].t && tc < m->k[m->nk - 1].t) {
        /* rolling over a contact point: position from the pitch exactly */
        const knot_t *kk = &m->k[i];
        double d0[2], d1[2], d2[2], th = p[4][0], w1 = p[4][1], w2 = p[4][2];
        double cps = cos(kk->psi), sps = sin(kk->psi), hx, hv, ha;
        pivot(th, kk->rx, kk->rz, d0, d1, d2);
        hx = d0[0];
        hv = d1[0] * w1;
        ha = d2[0] * w1 * w1 + d1[0] * w2;
        p[0][0] = kk->flat[0] + hx * cps;
        p[1][0] = kk->flat[1] + hx * sps;
        p[2][0] = kk->flat[2] + d0[1];
        p[0][1] = hv * cps;
        p[1][1] = hv * sps;
        p[2][1] = d1[1] * w1;
        p[0][2] = ha * cps;
        p[1][2] = ha * sps;
        p[2][2] = d2[1] * w1 * w1 + d1[1] * w2;
    }
    o->phase = m->k[i].phase;
    o->leg = m->k[i].leg;
    if (t < m->k[0].t || t > m->k[m->nk - 1].t) {
        o->phase = HX_PHASE_STILL;
    }
    /* ringing: rings are sorted by start; look back over the longest one */
    if (m->nr > 0) {
        size_t lo = 0, hi = m->nr;
        while (lo < hi) { /* first ring starting after t */
            size_t mid = (lo + hi) / 2;
            if (m->r[mid].t0 <= t) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        while (lo > 0) {
            const ring_t *g = &m->r[--lo];
            double tau = t - g->t0, e[3], sn, cs, d0, d1, d2;
            if (tau > m->ring_maxdur) {
                break;
            }
            if (tau < 0.0 || tau >= g->dur) {
                continue;
            }
            envelope(g->sym, tau / g->dur, e);
            e[1] /= g->dur;
            e[2] /= g->dur * g->dur;
            sn = sin(g->w * tau);
            cs = cos(g->w * tau);
            d0 = e[0] * sn;
            d1 = e[1] * sn + e[0] * g->w * cs;
            d2 = e[2] * sn + 2.0 * e[1] * g->w * cs - e[0] * g->w * g->w * sn;
            for (c = 0; c < 3; c++) {
                p[c][0] += g->amp[c] * d0;
                p[c][1] += g->amp[c] * d1;
                p[c][2] += g->amp[c] * d2;
            }
            p[4][0] += g->amp[3] * d0;
            p[4][1] += g->amp[3] * d1;
            p[4][2] += g->amp[3] * d2;
        }
    }
    for (c = 0; c < 3; c++) {
        o->pos_m[c] = p[c][0];
        o->vel_mps[c] = p[c][1];
        o->acc_mps2[c] = p[c][2];
    }
    /* attitude of the foot and its body rates from the ZYX Euler rates
     * (Titterton & Weston eq. 3.52 inverted) */
    hx_dcm_from_euler(p[3][0], p[4][0], p[5][0], C_nf);
    sr = sin(p[3][0]);
    cr = cos(p[3][0]);
    sp = sin(p[4][0]);
    cp = cos(p[4][0]);
    w_f[0] = p[3][1] - p[5][1] * sp;
    w_f[1] = p[4][1] * cr + p[5][1] * sr * cp;
    w_f[2] = -p[4][1] * sr + p[5][1] * cr * cp;
    /* sensor frame: C_ns = C_nf C_fs, w_s = C_sf w_f */
    for (r = 0; r < 3; r++) {
        for (c = 0; c < 3; c++) {
            C_ns[r][c] = C_nf[r][0] * m->C_fs[0][c] + C_nf[r][1] * m->C_fs[1][c] + C_nf[r][2] * m->C_fs[2][c];
        }
    }
    for (c = 0; c < 3; c++) {
        o->w_b[c] = m->C_fs[0][c] * w_f[0] + m->C_fs[1][c] * w_f[1] + m->C_fs[2][c] * w_f[2];
    }
    quat_from_euler(p[3][0], p[4][0], p[5][0], q_nf);
    hx_quat_mul(q_nf, m->q_fs, o->q_nb);
    if (o->q_nb[0] < 0.0) {
        for (c = 0; c < 4; c++) {
            o->q_nb[c] = -o->q_nb[c];
        }
    }
    {
        double w = o->q_nb[0], x = o->q_nb[1], y = o->q_nb[2], z = o->q_nb[3];
        double s = 2.0 * (w * y - x * z);
        s = s > 1.0 ? 1.0 : (s < -1.0 ? -1.0 : s);
        o->euler_rad[0] = atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y));
        o->euler_rad[1] = asin(s);
        o->euler_rad[2] = atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
    }
    /* specific force f_b = C_bn (a_n - g_n), g_n = (0, 0, g) */
    fn[0] = p[0][2];
    fn[1] = p[1][2];
    fn[2] = p[2][2] - m->cfg.g_mps2;
    for (c = 0; c < 3; c++) {
        o->f_b[c] = C_ns[0][c] * fn[0] + C_ns[1][c] * fn[1] + C_ns[2][c] * fn[2];
    }
    o->still = (o->phase == HX_PHASE_RIDE) ||
               (o->phase == HX_PHASE_STILL && (t >= m->k[i].still_from || t < m->k[0].t || t > m->k[m->nk - 1].t));
    o->zero_vel = o->still && o->phase != HX_PHASE_RIDE;
    /* odometer: distance between footfalls completed by t */
    if (m->nland > 0 && t >= m->land[0].t) {
        size_t lo = 0, hi = m->nland;
        while (hi - lo > 1) {
            size_t mid = (lo + hi) / 2;
            if (m->land[mid].t <= t) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        o->odo_m = m->land[lo].odo;
    }
}
