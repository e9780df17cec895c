/* Sim-to-real gap diagnosis: the human summary (hx_simgap.h). JSON in
 * hx_simgap_json.c, plots in hx_simgap_plot.c. */
#include "hx_simgap.h"
#include "hx_simgap_nav.h"
#include "hx_cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *dom_title(int dom)
{
    switch (dom) {
    case SG_ALLAN: return "Allan";
    case SG_PSD: return "PSD";
    case SG_LATTICE: return "value lattice";
    case SG_TIMING: return "timing";
    case SG_TIME: return "time domain";
    default: return "navigation";
    }
}

static const char *ch_title(int ch)
{
    static const char *const t[SG_NCH] = { "accel x", "accel y", "accel z", "gyro x", "gyro y", "gyro z" };
    return (ch >= 0 && ch < SG_NCH) ? t[ch] : "all";
}

/* A value in the channel's unit, with deg for gyro quantities. */
static void fmt_u(char *b, size_t n, int ch, double v, const char *suffix)
{
    if (ch >= 3) {
        snprintf(b, n, "%.3g rad/s%s (%.3g deg/s%s)", v, suffix, v * 180.0 / M_PI, suffix);
    } else {
        snprintf(b, n, "%.3g m/s^2%s", v, suffix);
    }
}

/* A fraction in percent for "%.0f": within half a percent of zero it is 0,
 * where printf would write "-0". */
static double pct(double f)
{
    const double v = 100.0 * f;
    return fabs(v) <= 0.5 ? 0.0 : v;
}

/* What a parameter the fit left at a bound of its search is (at_bound):
 * at the lower, at most that; at the upper, at least that. */
static const char *limit_text(const sg_effect_t *e, int k)
{
    return e->at_bound[k] < 0 ? "only an upper limit" : "only a lower limit";
}

/* Whether parameter k of e has the refits' 68 % interval (as the JSON's
 * ci68: an se from SG_CI_MIN_REFITS refits or more). */
/* The line under a channel's baseline: where the middle 68 % of the twins'
 * refits of each baseline parameter lie (docs/simgap.md, section 3), with
 * how many refits; nothing when no parameter has an interval. no_tau: the
 * time has none (no AR(1), or at a bound of its search). */
static void print_ci(FILE *f, int ch, const sg_effect_t *w, const sg_effect_t *a, int no_tau)
{
    const char *u = sg_channel_unit(ch);
    const int hw = sg_has_ci(w, 0), hs = sg_has_ci(a, 1), ht = !no_tau && sg_has_ci(a, 0);
    int n = 0;
    if (!hw && !hs && !ht) {
        return;
    }
    n = hw ? w->nrefit[0] : (hs ? a->nrefit[1] : a->nrefit[0]);
    fprintf(f, "      68 %% of the twins' %d refits:", n);
    if (hw) {
        fprintf(f, " white %.3g to %.3g %s/sqrt(Hz)", w->ci_lo[0], w->ci_hi[0], u);
    }
    if (hs) {
        fprintf(f, "%s sigma %.3g to %.3g %s", hw ? "," : "", a->ci_lo[1], a->ci_hi[1], u);
        if (a->nrefit[1] != n) {
            fprintf(f, " (of %d)", a->nrefit[1]);
        }
    }
    if (ht) {
        fprintf(f, "%s tau %.3g to %.3g s", hw || hs ? "," : "", a->ci_lo[0], a->ci_hi[0]);
        if (a->nrefit[0] != n) {
            fprintf(f, " (of %d with an AR(1))", a->nrefit[0]);
        }
    }
    fprintf(f, "\n");
}

void sg_effect_text(char *b, size_t n, int ch, const sg_effect_t *e)
{
    char u[96], u2[96];
    switch (e->id) {
    case FNAV_EFFECT_QUANT:
        fmt_u(u, sizeof u, ch, e->p[0], "");
        snprintf(b, n, "quant (lsb %s, %s)", u, e->p[1] != 0.0 ? "noise-shaped" : "plain rounding");
        break;
    case FNAV_EFFECT_FLICKER:
        fmt_u(u, sizeof u, ch, e->p[0], "");
        snprintf(b, n, "flicker (B %s%s%s)", u, e->at_bound[0] != 0 ? " at the search bound: " : "",
                 e->at_bound[0] != 0 ? limit_text(e, 0) : "");
        break;
    case FNAV_EFFECT_RRW:
        fmt_u(u, sizeof u, ch, e->p[0], "/sqrt(s)");
        snprintf(b, n, "rrw (K %s%s%s)", u, e->at_bound[0] != 0 ? " at the search bound: " : "",
                 e->at_bound[0] != 0 ? limit_text(e, 0) : "");
        break;
    case FNAV_EFFECT_RAMP:
        fmt_u(u, sizeof u, ch, e->p[0], "/s");
        snprintf(b, n, "ramp (rate %s)", u);
        break;
    case FNAV_EFFECT_THERMAL:
        fmt_u(u, sizeof u, ch, e->p[0], "/degC");
        if (e->at_bound[2] != 0) {
            /* the time constant a bound of its search */
            snprintf(b, n, "thermal (coef %s over a %.3g degC rise, tau at the search bound %.5g s: %s)", u, e->p[1],
                     e->at_bound[2] < 0 ? e->lo[2] : e->hi[2], limit_text(e, 2));
        } else {
            snprintf(b, n, "thermal (coef %s over a %.3g degC rise, tau %.3g s)", u, e->p[1], e->p[2]);
        }
        break;
    case FNAV_EFFECT_VIBRATION:
        fmt_u(u, sizeof u, ch, e->p[0], "");
        snprintf(b, n, "vibration (amp %s at %.4g Hz)", u, e->p[1]);
        break;
    case FNAV_EFFECT_JUMPS:
        fmt_u(u, sizeof u, ch, e->p[1], "");
        snprintf(b, n, "jumps (%.3g per hour, rms step %s)", e->p[0] * 3600.0, u);
        break;
    case FNAV_EFFECT_WHITE:
        fmt_u(u, sizeof u, ch, e->p[0], "/sqrt(Hz)");
        snprintf(b, n, "white (%s)", u);
        break;
    case FNAV_EFFECT_AR1:
        if (!(e->p[1] > 0.0)) {
            snprintf(b, n, "ar1 (none: sigma 0)"); /* no bias process: its tau means nothing (null in the JSON) */
            break;
        }
        fmt_u(u2, sizeof u2, ch, e->p[1], "");
        snprintf(b, n, "ar1 (sigma %s, tau %.3g s)", u2, e->p[0]);
        break;
    default: {
        const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)e->id);
        int k;
        size_t o = 0;
        o += (size_t)snprintf(b + o, n - o, "%s (", info != NULL ? info->name : "?");
        for (k = 0; info != NULL && k < info->nparams && k < SG_MAX_PAR && o < n; k++) {
            o += (size_t)snprintf(b + o, n - o, "%s%s %.3g", k ? ", " : "", info->params[k].name, e->p[k]);
        }
        if (o < n) {
            snprintf(b + o, n - o, ")");
        }
        break;
    }
    }
}

static void range_text(char *b, size_t n, const sg_loc_t *L)
{
    const char *u = L->dom == SG_ALLAN ? "s" : (L->dom == SG_PSD ? "Hz" : "");
    if (L->dom == SG_ALLAN) {
        snprintf(b, n, "tau %.3g-%.3g %s", L->x_lo, L->x_hi, u);
    } else if (L->dom == SG_PSD) {
        snprintf(b, n, "%.3g-%.3g %s", L->x_lo, L->x_hi, u);
    } else if (L->dom == SG_LATTICE) {
        snprintf(b, n, "values on a lattice of step %.4g", L->x_lo);
    } else if (L->dom == SG_TIME) {
        snprintf(b, n, "%s, t %.0f-%.0f s", sg_time_kind_name(L->kind), L->x_lo, L->x_hi);
    } else {
        snprintf(b, n, "t %.1f-%.1f s", L->x_lo, L->x_hi);
    }
}

static void print_static(FILE *f, const sg_result_t *r)
{
    int ch, i, at_max = 0;
    size_t k;
    char b[256];
    fprintf(f, "baseline (white + AR(1) per channel, fitted on the fit segment):\n");
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_chres_t *c = &r->ch[ch];
        char w[128], a[128];
        int iw, ia;
        if (!c->active) {
            if (r->seg_constant[ch]) {
                fprintf(f, "  %s  not analysed: does not vary within the %s segment\n", sg_channel_name(ch),
                        r->seg_constant[ch] == SG_FIT ? "fit" : "held-out");
            } else if (!r->constant[ch]) {
                fprintf(f, "  %s  not analysed: fewer than 4 Allan points on the fit segment\n", sg_channel_name(ch));
            }
            continue;
        }
        iw = sg_model_find(&c->baseline, FNAV_EFFECT_WHITE);
        ia = sg_model_find(&c->baseline, FNAV_EFFECT_AR1);
        sg_effect_text(w, sizeof w, ch, &c->baseline.e[iw]);
        sg_effect_text(a, sizeof a, ch, &c->baseline.e[ia]);
        at_max += sg_ar1_at_max(c);
        /* the shortest bound too, where the optimum lies at or below one
         * sample */
        fprintf(f, "  %s  %s, %s%s\n", sg_channel_name(ch), w, a,
                sg_ar1_at_max(c) ? ", tau at the longest this log resolves"
                                 : (sg_ar1_at_min(c, r->rate_hz) ? ", tau at the shortest the fit may take" : ""));
        print_ci(f, ch, &c->baseline.e[iw], &c->baseline.e[ia],
                 sg_ar1_at_max(c) || sg_ar1_at_min(c, r->rate_hz) || !(c->baseline.e[ia].p[1] > 0.0));
    }
    if (at_max > 0) {
        /* a bias correlated longer than the record can show looks like a
         * random walk over it: the catalogue's rrw, flicker or ramp stand
         * in for it below (docs/simgap.md, section 1) */
        fprintf(f, "  (tau at the longest this log resolves: a quarter of the longest Allan tau analysed; a longer\n"
                   "   correlation looks like a random walk over the record, and rrw, flicker or ramp stand in for it)\n");
    }
    /* G as computed (section 3), not "mean z^2", which a reader of the
     * JSON's points would get otherwise */
    fprintf(f, "gap of the baseline twin (%d seeds; G = mean over the domains of their mean z^2 (|z| capped at %g), "
               "about 1 when the twin explains the data):\n",
            r->S, SG_ZCAP);
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_chres_t *c = &r->ch[ch];
        if (!c->active) {
            continue;
        }
        /* the held-out max |z| and its critical value too: a held-out gap
         * can be significant by one point while G is below its critical
         * value, which the line would otherwise seem to contradict */
        fprintf(f,
                "  %s  whole log G %.3g (null %.2g, crit %.2g, max |z| %.1f)%s; held out G %.3g (crit %.2g, max |z| "
                "%.1f of %.2f)%s\n",
                sg_channel_name(ch), c->cmp[SG_FULL].G, c->cmp[SG_FULL].null_mean, c->cmp[SG_FULL].G_crit,
                c->cmp[SG_FULL].maxz, c->gap_full ? " SIGNIFICANT" : "", c->cmp[SG_HOLD].G, c->cmp[SG_HOLD].G_crit,
                c->cmp[SG_HOLD].maxz, c->cmp[SG_HOLD].z_crit, c->gap_hold ? " SIGNIFICANT" : "");
    }
    if (r->nloc > 0) {
        fprintf(f, "where (whole log, |z| beyond the critical %.2f):\n", r->ch[r->loc[0].ch].cmp[SG_FULL].z_crit);
    }
    if (r->nloc_dropped > 0) {
        fprintf(f, "  (%lu more locations beyond the %lu listed: not kept)\n", (unsigned long)r->nloc_dropped,
                (unsigned long)(sizeof r->loc / sizeof r->loc[0]));
    }
    for (k = 0; k < r->nloc; k++) {
        const sg_loc_t *L = &r->loc[k];
        range_text(b, sizeof b, L);
        if (L->dom == SG_LATTICE) {
            fprintf(f, "  %s, %s: %.0f sigma above the twin\n", ch_title(L->ch), b, L->peak_z);
        } else if (L->dom == SG_TIME) {
            fprintf(f, "  %s, %s %s, %.1f sigma %s the twin (real - twin %.3g)\n", ch_title(L->ch), dom_title(L->dom),
                    b, fabs(L->peak_z), L->peak_z > 0 ? "above" : "below", L->ratio);
        } else {
            fprintf(f, "  %s, %s %s, %.1f sigma %s the twin (%s x%.3g)\n", ch_title(L->ch), dom_title(L->dom), b,
                    fabs(L->peak_z), L->peak_z > 0 ? "above" : "below", L->dom == SG_ALLAN ? "ADEV" : "amplitude",
                    L->ratio);
        }
    }
    if (r->prof_name[0] != '\0') {
        fprintf(f, "given model: profile %s (white + AR(1) as given, not fitted; %d seeds):\n", r->prof_name, r->S);
        for (ch = 0; ch < SG_NCH; ch++) {
            const sg_chres_t *c = &r->ch[ch];
            char w[128], a[128];
            if (!c->have_prof) {
                continue;
            }
            sg_effect_text(w, sizeof w, ch, &c->prof.e[0]);
            sg_effect_text(a, sizeof a, ch, &c->prof.e[1]);
            fprintf(f, "  %s  %s, %s\n      whole log G %.3g (null %.2g, crit %.2g, max |z| %.1f)%s; held out G %.3g "
                       "(crit %.2g)%s; the fitted baseline: whole log G %.3g\n",
                    sg_channel_name(ch), w, a, c->cmp_prof[SG_FULL].G, c->cmp_prof[SG_FULL].null_mean,
                    c->cmp_prof[SG_FULL].G_crit, c->cmp_prof[SG_FULL].maxz,
                    c->cmp_prof[SG_FULL].significant ? " SIGNIFICANT" : "", c->cmp_prof[SG_HOLD].G,
                    c->cmp_prof[SG_HOLD].G_crit, c->cmp_prof[SG_HOLD].significant ? " SIGNIFICANT" : "",
                    c->cmp[SG_FULL].G);
        }
        if (r->nploc > 0) {
            fprintf(f, "where the given model misses (whole log):\n");
        }
        for (k = 0; k < r->nploc; k++) {
            const sg_loc_t *L = &r->ploc[k];
            range_text(b, sizeof b, L);
            if (L->dom == SG_LATTICE) {
                fprintf(f, "  %s, %s: %.0f sigma above the profile's twin\n", ch_title(L->ch), b, L->peak_z);
            } else if (L->dom == SG_TIME) {
                fprintf(f, "  %s, %s %s, %.1f sigma %s the profile's twin (real - twin %.3g)\n", ch_title(L->ch),
                        dom_title(L->dom), b, fabs(L->peak_z), L->peak_z > 0 ? "above" : "below", L->ratio);
            } else {
                fprintf(f, "  %s, %s %s, %.1f sigma %s the profile's twin (%s x%.3g)\n", ch_title(L->ch),
                        dom_title(L->dom), b, fabs(L->peak_z), L->peak_z > 0 ? "above" : "below",
                        L->dom == SG_ALLAN ? "ADEV" : "amplitude", L->ratio);
            }
        }
    }
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_chres_t *c = &r->ch[ch];
        if (!c->active || !(c->gap || (c->nsteps > 0 && c->step[0].ncand > 0))) {
            continue;
        }
        fprintf(f, "attribution %s (held-out segment):\n", sg_channel_name(ch));
        if (c->nsteps == 0) {
            /* --max-effects 0 (a channel with a gap reaches this line: the
             * test above passes it) */
            /* and a log too short for a confident answer, said so, not a
             * bare "not attempted" */
            fprintf(f, "  not attempted%s\n", r->opts.max_steps == 0 ? " (--max-effects 0)"
                                               : (!r->confident ? " (too short for a confident answer)" : ""));
        }
        for (i = 0; i < c->nsteps; i++) {
            const sg_step_t *st = &c->step[i];
            int j;
            for (j = 0; j < st->ncand; j++) {
                const sg_cand_t *cd = &st->cand[j];
                sg_effect_text(b, sizeof b, ch, &cd->eff);
                if (cd->simulated) {
                    char ex[96];
                    if (cd->expl_hold == cd->expl_hold) {
                        snprintf(ex, sizeof ex, "explains %.0f %% of the excess (68 %%: %.0f..%.0f %%)",
                                 pct(cd->expl_hold), pct(cd->expl_lo), pct(cd->expl_hi));
                    } else {
                        snprintf(ex, sizeof ex, "no held-out excess to explain");
                    }
                    char zf[96] = "", zl[96] = "", dl[64] = "";
                    /* without a second fold (--contiguous, or fold 2
                     * failed) there is no ends' drop: left out, not
                     * "(ends nan)" */
                    if (cd->dL_ends == cd->dL_ends) {
                        snprintf(dl, sizeof dl, " (ends %.3g)", cd->dL_ends);
                    }
                    if (cd->z_ends == cd->z_ends) {
                        snprintf(zf, sizeof zf, " (middle %+.1f, ends %+.1f)", cd->z_mid, cd->z_ends);
                    }
                    if (cd->zg_ends == cd->zg_ends) {
                        snprintf(zl, sizeof zl, " (middle %+.1f, ends %+.1f)", cd->zg_mid, cd->zg_ends);
                    }
                    fprintf(f,
                            "  step %d %c %-58s fit dQ %.1f; held out: G %.3g -> %.3g, score %+.1f sigma%s, "
                            "likelihood ratio %+.1f sigma%s, deviance drop %.3g%s, %s\n",
                            i + 1, j == st->selected ? '*' : ' ', b, cd->dQ_fit, st->G_hold_before, cd->G_hold,
                            cd->z_delta, zf, cd->z_gap, zl, cd->dL_rank, dl, ex);
                } else {
                    fprintf(f, "  step %d   %-58s fit dQ %.1f; not simulated%s\n", i + 1, b, cd->dQ_fit,
                            cd->nested ? " (nested: a ramp fits the blocks' trends, curvatures and level as well)" : "");
                }
            }
        }
        for (i = 0; i < c->nzero; i++) {
            fprintf(f, "  %s: accepted at its step, then refitted to zero once the later effects joined: left out "
                       "of the answer\n",
                    fnav_imuerr_effect_info((fnav_effect_id_t)c->zero_id[i])->name);
        }
        if (c->within_noise) {
            fprintf(f, "  -> remaining held-out gap within noise\n");
        } else {
            /* which test: with G below its critical value the gap is one
             * point's |z|, shown too (else "G 2.38 -> 1.57" then "a
             * significant held-out gap remains" would seem to contradict) */
            const sg_cmp_t *h = &c->cmp_final[SG_HOLD];
            fprintf(f, "  -> a significant held-out gap remains (G %.3g, critical %.3g; max |z| %.2f, critical %.2f)\n",
                    h->G, h->G_crit, h->maxz, h->z_crit);
        }
    }
}

/* SG_DEBUG=CH:SEG prints every point of a channel and segment (development aid). */
static void debug_points(FILE *f, const sg_result_t *r)
{
    const char *e = getenv("SG_DEBUG");
    int ch, g;
    size_t j;
    if (e == NULL || sscanf(e, "%d:%d", &ch, &g) != 2 || ch < 0 || ch >= SG_NCH || g < 0 || g >= SG_NSEG ||
        !r->ch[ch].active) {
        return;
    }
    for (j = 0; j < r->pl[ch][g].n; j++) {
        const sg_point_t *p = &r->pl[ch][g].p[j];
        const sg_cmp_t *c = &r->ch[ch].cmp[g];
        fprintf(f, "  %-7s x %-10.4g real %-10.5g twin %-10.5g sd %-9.3g sdtot %-9.3g vx %-9.3g z %+.2f\n",
                sg_domain_name(p->dom), p->x, r->real[ch][g][j], c->twin_mean[j], c->twin_sd[j], c->sd_tot[j],
                r->vx[ch][g] != NULL ? sqrt(r->vx[ch][g][j]) : 0.0, c->z[j]);
    }
}

int sg_unconfirmed(const sg_result_t *r, int ch, const sg_cand_t **lead)
{
    const sg_chres_t *c = &r->ch[ch];
    int j;
    *lead = NULL;
    if (r->domain != 1 || !r->confident || !c->active || c->nsel > 0 || !c->gap) {
        return SG_UNCONF_NONE;
    }
    for (j = 0; c->nsteps > 0 && j < c->step[0].ncand; j++) {
        const sg_cand_t *cd = &c->step[0].cand[j];
        if (cd->simulated && (*lead == NULL || cd->dQ_fit > (*lead)->dQ_fit)) {
            *lead = cd;
        }
    }
    return c->gap_hold ? SG_UNCONF_NO_EFFECT : SG_UNCONF_NOT_HELD_OUT;
}

/* The summary's line for each channel sg_unconfirmed names. */
static void print_unconfirmed(FILE *f, const sg_result_t *r)
{
    int ch;
    char b[256];
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_chres_t *c = &r->ch[ch];
        const sg_cand_t *lead;
        const int why = sg_unconfirmed(r, ch, &lead);
        if (why == SG_UNCONF_NO_EFFECT && c->nsteps == 0) {
            fprintf(f, "  %s: a held-out gap (G %.3g, critical %.2g; max |z| %.1f, critical %.2f); no effect of the "
                       "catalogue was tried\n",
                    sg_channel_name(ch), c->cmp[SG_HOLD].G, c->cmp[SG_HOLD].G_crit, c->cmp[SG_HOLD].maxz,
                    c->cmp[SG_HOLD].z_crit);
        } else if (why == SG_UNCONF_NO_EFFECT) {
            fprintf(f, "  %s: a held-out gap (G %.3g, critical %.2g; max |z| %.1f, critical %.2f) that no effect of "
                       "the catalogue reduces on held-out data\n",
                    sg_channel_name(ch), c->cmp[SG_HOLD].G, c->cmp[SG_HOLD].G_crit, c->cmp[SG_HOLD].maxz,
                    c->cmp[SG_HOLD].z_crit);
        } else if (why == SG_UNCONF_NOT_HELD_OUT) {
            fprintf(f, "  %s: the whole log's gap (G %.3g, critical %.2g) does not show on the held-out %s (G %.3g, "
                       "critical %.2g), so no effect can be confirmed",
                    sg_channel_name(ch), c->cmp[SG_FULL].G, c->cmp[SG_FULL].G_crit,
                    r->segs.sandwich ? "middle" : "segment", c->cmp[SG_HOLD].G, c->cmp[SG_HOLD].G_crit);
            if (lead != NULL) {
                sg_effect_text(b, sizeof b, ch, &lead->eff);
                fprintf(f, "; the fit segment's best candidate is %s, fit dQ %.1f, unconfirmed", b, lead->dQ_fit);
            }
            fprintf(f, "; a longer log may tell\n");
        }
    }
}

/* The forward-selection step (0-based) at which effect id was accepted on
 * channel c, or -1. */
static int sel_step(const sg_chres_t *c, int id)
{
    int k;
    for (k = 0; k < c->nsteps; k++) {
        if (c->step[k].selected >= 0 && c->step[k].cand[c->step[k].selected].id == id) {
            return k;
        }
    }
    return -1;
}

void sg_print_summary(FILE *f, const sg_result_t *r)
{
    debug_points(f, r);
    int ch, i, d;
    char b[256], shown[sizeof r->path]; /* the path's control characters as '?' (hx_line_str), as in the messages */
    (void)hx_line_str(shown, sizeof shown, r->path);
    /* %.3g: with %.0f, --fit-frac 0.25 would read "the first and last 12 %,
     * held out the middle 75 %" */
    if (r->segs.sandwich) {
        fprintf(f, "simgap %s: %s, %ld samples at %.4g Hz (%.1f s); fit on the first and last %.3g %%, held out the "
                   "middle %.3g %%\n",
                shown, r->domain == 1 ? "static" : "walk", r->n, r->rate_hz, r->duration_s,
                50.0 * r->opts.fit_frac, 100.0 * (1.0 - r->opts.fit_frac));
    } else {
        fprintf(f, "simgap %s: %s, %ld samples at %.4g Hz (%.1f s); fit on the first %.3g %%, held out the last %.3g %%\n",
                shown, r->domain == 1 ? "static" : "walk", r->n, r->rate_hz, r->duration_s, 100.0 * r->opts.fit_frac,
                100.0 * (1.0 - r->opts.fit_frac));
    }
    if (r->opts.domain != 0 && r->domain != r->domain_detected) {
        fprintf(f, "domain: %s as given (%s); the log looks like a %s (stillness test, docs/simgap.md \"Usage\")\n",
                r->domain == 1 ? "static" : "walk", r->domain == 1 ? "--static" : "--walk",
                r->domain_detected == 1 ? "static log" : "walk");
    }
    for (ch = 0; ch < SG_NCH; ch++) {
        if (r->constant[ch]) {
            fprintf(f, "%s holds one value (%.6g %s) over the whole log: stuck, or its noise below the output's step; "
                       "%s\n",
                    sg_channel_name(ch), r->constant_value[ch], sg_channel_unit(ch),
                    r->domain == 1 ? "not analysed" : "navigated as it is, but its noise not tested");
        }
        if (r->seg_constant[ch]) {
            fprintf(f, "%s does not vary within the %s segment (%.6g %s at its start): stuck there, or its "
                       "noise below the output's step; not analysed\n",
                    sg_channel_name(ch), r->seg_constant[ch] == SG_FIT ? "fit" : "held-out",
                    r->seg_constant_value[ch], sg_channel_unit(ch));
        }
    }
    if (!r->confident) {
        fprintf(f, "TOO SHORT for a confident answer: %s\n", r->why);
    }
    if (r->domain == 1) {
        print_static(f, r);
    } else if (r->nav != NULL) {
        sg_nav_print((const sg_nav_t *)r->nav, f, r);
    }
    if (!r->tim.have && r->stamps_made) {
        fprintf(f, "timing: the log has no time stamps (the format's are the line index / rate): not analysed\n");
    }
    if (r->tim.have) {
        static const char *const nm[SG_TIM_NKIND] = { "duplicated samples", "dropped samples", "time-stamp jitter" };
        fprintf(f, "timing: %ld duplicated, %ld dropped, interval sd %.3g s (stamp resolution %.3g s)\n",
                r->tim.n_dup[SG_FULL], r->tim.n_drop[SG_FULL], r->tim.jit_sd[SG_FULL], r->tim.res_s);
        if (r->tim.tail_drop[SG_FULL] >= 0.5 || r->tim.tail_dup[SG_FULL] >= 0.5) {
            /* a jitter wide against the period: its tails pass the counts'
             * thresholds, and the counts are judged against them */
            fprintf(f, "  the jitter alone would give about %.0f drops and %.0f duplicates (intervals over 1.5 or "
                       "under 0.1 periods; counted %ld and %ld): the counts are judged against them\n",
                    r->tim.tail_drop[SG_FULL], r->tim.tail_dup[SG_FULL], r->tim.n_drop[SG_FULL],
                    r->tim.n_dup[SG_FULL]);
        }
        for (d = 0; d < SG_TIM_NKIND; d++) {
            if (r->tim.sel[d]) {
                fprintf(f, "  %s: %.1f sigma above an ideal clock; held out after fitting: %+.1f sigma%s\n", nm[d],
                        r->tim.z[SG_FULL][d], r->tim.z_after[d],
                        r->tim.open[d] ? " (beyond noise: the held-out segment's rate differs from the fit's, "
                                         "not stationary)"
                                       : "");
            }
        }
    }
    fprintf(f, "verdict: %s", r->verdict);
    {
        int first = 1, nfinal = 0;
        /* the channels' parameters below are their final refit (the
         * accepted effects together, on the fit segment), not the steps'
         * fits printed above them, and are labelled so (unlabelled, a jumps
         * step of rms 0.00875 would stand beside a verdict of rms 0) */
        for (ch = 0; ch < SG_NCH; ch++) {
            for (i = 0; i < r->ch[ch].nsel; i++) {
                nfinal += sg_model_find(&r->ch[ch].final, r->ch[ch].sel_id[i]) >= 0;
            }
        }
        if (nfinal > 0 && r->segs.sandwich) {
            fprintf(f, " (parameters of the final refit on the fit segment, the first and last %.3g %%)",
                    50.0 * r->opts.fit_frac);
        } else if (nfinal > 0) {
            fprintf(f, " (parameters of the final refit on the fit segment, the first %.3g %%)",
                    100.0 * r->opts.fit_frac);
        }
        for (ch = 0; ch < SG_NCH; ch++) {
            for (i = 0; i < r->ch[ch].nsel; i++) {
                const sg_chmodel_t *m = &r->ch[ch].final;
                int k = sg_model_find(m, r->ch[ch].sel_id[i]);
                if (k >= 0) {
                    sg_effect_text(b, sizeof b, ch, &m->e[k]);
                    if (r->ch[ch].sel_expl[i] == r->ch[ch].sel_expl[i]) {
                        /* an effect accepted after others explains a share
                         * of the excess they left, not of the baseline's:
                         * "99 %" then "68 % of the held-out excess" on one
                         * channel would otherwise read as 167 % */
                        fprintf(f, "%s %s on %s (%.0f %% of the held-out excess%s)", first ? ":" : ";", b,
                                sg_channel_name(ch), pct(r->ch[ch].sel_expl[i]),
                                sel_step(&r->ch[ch], r->ch[ch].sel_id[i]) > 0
                                    ? " left by the effects accepted before it" : "");
                    } else {
                        fprintf(f, "%s %s on %s (no excess in the held-out %s to explain)", first ? ":" : ";", b,
                                sg_channel_name(ch), r->segs.sandwich ? "middle" : "segment");
                    }
                    first = 0;
                }
            }
        }
        if (r->nav != NULL) {
            sg_nav_verdict_text((const sg_nav_t *)r->nav, f, &first);
        }
        if (r->tim.significant) {
            /* an effect the whole log shows but the fit segment holds
             * none of (every drop held out) has no rate to give: "prob 0"
             * named an effect whose twin reproduces nothing */
            static const char *const k_none = "held-out segment only: no rate from the fit segment";
            if (r->tim.sel[SG_TIM_DUP]) {
                if (r->tim.dup_prob > 0.0) {
                    fprintf(f, "%s duplicate (prob %.3g)", first ? ":" : ";", r->tim.dup_prob);
                } else {
                    fprintf(f, "%s duplicate (%s)", first ? ":" : ";", k_none);
                }
                first = 0;
            }
            if (r->tim.sel[SG_TIM_DROP]) {
                if (r->tim.drop_prob > 0.0) {
                    fprintf(f, "%s dropout (prob %.3g)", first ? ":" : ";", r->tim.drop_prob);
                } else {
                    fprintf(f, "%s dropout (%s)", first ? ":" : ";", k_none);
                }
                first = 0;
            }
            if (r->tim.sel[SG_TIM_JITTER]) {
                if (r->tim.stamp_s > 0.0) {
                    fprintf(f, "%s jitter (stamp_s %.3g s)", first ? ":" : ";", r->tim.stamp_s);
                } else {
                    fprintf(f, "%s jitter (%s)", first ? ":" : ";", k_none);
                }
                first = 0;
            }
        }
    }
    fprintf(f, "\n");
    print_unconfirmed(f, r);
    fprintf(f, "(%.1f s)\n", r->elapsed_s);
}
