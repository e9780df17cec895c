/* Sim-to-real gap diagnosis: the JSON report, schema footnav-simgap/1
 * (documented in docs/simgap.md). */
#include "hx_simgap.h"
#include "hx_simgap_nav.h"
#include "hx_cli.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const k_seg[SG_NSEG] = { "full", "fit", "held_out" };

/* The refits' 68 % interval of parameter k of e, [ci_lo, ci_hi], and the
 * number of refits it and the se rest on, into *ci and *n (null items
 * where there are none): none where the se is not written (no_se: an
 * AR(1) time without a sigma, a parameter at a bound), not finite, or not
 * from refits; the interval from SG_CI_MIN_REFITS refits (docs/simgap.md,
 * section 3). */
static void ci_items(const sg_effect_t *e, int k, int no_se, cJSON **ci, cJSON **n)
{
    const int c = no_se || !isfinite(e->se[k]) ? 0 : e->nrefit[k];
    *n = c > 0 ? cJSON_CreateNumber((double)c) : cJSON_CreateNull();
    if (c > 0 && sg_has_ci(e, k)) {
        *ci = cJSON_CreateArray();
        cJSON_AddItemToArray(*ci, cJSON_CreateNumber(e->ci_lo[k]));
        cJSON_AddItemToArray(*ci, cJSON_CreateNumber(e->ci_hi[k]));
    } else {
        *ci = cJSON_CreateNull();
    }
}

/* The baseline's KEY_ci68 and KEY_refits of parameter k of e. */
static void add_ci(cJSON *o, const char *key, const sg_effect_t *e, int k, int no_se)
{
    char b[64];
    cJSON *ci, *n;
    ci_items(e, k, no_se, &ci, &n);
    snprintf(b, sizeof b, "%s_ci68", key);
    cJSON_AddItemToObject(o, b, ci);
    snprintf(b, sizeof b, "%s_refits", key);
    cJSON_AddItemToObject(o, b, n);
}

/* One place where the gap is significant. */
static cJSON *loc_json(const sg_loc_t *L)
{
    cJSON *lo = cJSON_CreateObject();
    cJSON_AddStringToObject(lo, "channel", sg_channel_name(L->ch));
    cJSON_AddStringToObject(lo, "domain", sg_domain_name(L->dom));
    cJSON_AddStringToObject(lo, "segment", k_seg[L->seg]);
    hx_json_num(lo, "x_lo", L->x_lo);
    hx_json_num(lo, "x_hi", L->x_hi);
    cJSON_AddStringToObject(lo, "x_unit", (L->dom == SG_ALLAN || L->dom == SG_NAV || L->dom == SG_TIME) ? "s" : (L->dom == SG_PSD ? "Hz" : "u"));
    if (L->dom == SG_TIME) {
        cJSON_AddStringToObject(lo, "kind", sg_time_kind_name(L->kind));
    }
    hx_json_num(lo, "peak_z", L->peak_z);
    hx_json_num(lo, "ratio", L->ratio);
    cJSON_AddNumberToObject(lo, "points", L->npts);
    return lo;
}

/* {"name": value, ...} of an effect's parameters, their standard errors, the
 * refits' 68 % intervals and the number of refits. */
static cJSON *effect_json(const sg_effect_t *e, int ch)
{
    const fnav_effect_info_t *info = fnav_imuerr_effect_info((fnav_effect_id_t)e->id);
    cJSON *o = cJSON_CreateObject(), *p = cJSON_CreateObject(), *se = cJSON_CreateObject(), *u = cJSON_CreateObject();
    cJSON *bd = cJSON_CreateObject(), *ci = cJSON_CreateObject(), *nr = cJSON_CreateObject();
    int k;
    cJSON_AddStringToObject(o, "effect", info != NULL ? info->name : "?");
    for (k = 0; info != NULL && k < info->nparams && k < SG_MAX_PAR; k++) {
        const char *unit = info->params[k].unit;
        /* an AR(1) of sigma 0 is no bias process: its tau means nothing
         * (null, as the baseline's ar1_tau_s) */
        const int void_tau = e->id == FNAV_EFFECT_AR1 && k == 0 && !(e->p[1] > 0.0);
        hx_json_num(p, info->params[k].name, void_tau ? (double)NAN : e->p[k]);
        /* a parameter at a bound of its search has no standard error (the
         * curvature at a constraint is none), as the AR(1) time at its
         * bounds */
        hx_json_num(se, info->params[k].name, void_tau || e->at_bound[k] != 0 ? (double)NAN : e->se[k]);
        {
            cJSON *c, *n;
            ci_items(e, k, void_tau || e->at_bound[k] != 0, &c, &n);
            cJSON_AddItemToObject(ci, info->params[k].name, c);
            cJSON_AddItemToObject(nr, info->params[k].name, n);
        }
        if (e->lo[k] > 0.0 && e->hi[k] > e->lo[k]) {
            cJSON *b = cJSON_AddObjectToObject(bd, info->params[k].name);
            hx_json_num(b, "lo", e->lo[k]);
            hx_json_num(b, "hi", e->hi[k]);
            if (e->at_bound[k] != 0) {
                cJSON_AddStringToObject(b, "at_bound", e->at_bound[k] < 0 ? "lower" : "upper");
            } else {
                cJSON_AddNullToObject(b, "at_bound");
            }
        }
        if (strncmp(unit, "u", 1) == 0) {
            char b[48];
            snprintf(b, sizeof b, "%s%s", sg_channel_unit(ch), unit + 1);
            cJSON_AddStringToObject(u, info->params[k].name, b);
        } else {
            cJSON_AddStringToObject(u, info->params[k].name, unit);
        }
    }
    cJSON_AddItemToObject(o, "params", p);
    cJSON_AddItemToObject(o, "se", se);
    cJSON_AddItemToObject(o, "units", u);
    cJSON_AddItemToObject(o, "bounds", bd);
    cJSON_AddItemToObject(o, "ci68", ci);
    cJSON_AddItemToObject(o, "refits", nr);
    return o;
}

static cJSON *cmp_json(const sg_cmp_t *c)
{
    cJSON *o = cJSON_CreateObject(), *d = cJSON_CreateObject();
    int k;
    hx_json_num(o, "G", c->G);
    hx_json_num(o, "G_null_mean", c->null_mean);
    hx_json_num(o, "G_null_sd", c->null_sd);
    hx_json_num(o, "G_crit", c->G_crit);
    hx_json_num(o, "max_abs_z", c->maxz);
    hx_json_num(o, "z_crit", c->z_crit);
    cJSON_AddBoolToObject(o, "significant", c->significant);
    /* the static domains, each present (null: no point of it) */
    for (k = 0; k < SG_NDOM; k++) {
        if (k == SG_ALLAN || k == SG_PSD || k == SG_LATTICE || k == SG_TIME || c->G_dom[k] == c->G_dom[k]) {
            hx_json_num(d, sg_domain_name(k), c->G_dom[k]);
        }
    }
    cJSON_AddItemToObject(o, "G_per_domain", d);
    return o;
}

static cJSON *points_json(const sg_plist_t *pl, const double *real, const sg_cmp_t *c)
{
    cJSON *a = cJSON_CreateArray();
    size_t j;
    for (j = 0; j < pl->n && c->z != NULL; j++) {
        const sg_point_t *p = &pl->p[j];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "domain", sg_domain_name(p->dom));
        if (p->dom == SG_TIME) {
            cJSON_AddStringToObject(o, "kind", sg_time_kind_name(p->kind));
        }
        hx_json_num(o, "x", p->x);
        hx_json_num(o, "x_lo", p->x_lo);
        hx_json_num(o, "x_hi", p->x_hi);
        hx_json_num(o, "real", real[j]);
        hx_json_num(o, "twin", c->twin_mean[j]);
        hx_json_num(o, "twin_sd", c->twin_sd[j]);
        hx_json_num(o, "sd", c->sd_tot[j]);
        hx_json_num(o, "z", c->z[j]);
        cJSON_AddItemToArray(a, o);
    }
    return a;
}

static cJSON *channel_json(const sg_result_t *r, int ch)
{
    const sg_chres_t *c = &r->ch[ch];
    cJSON *o = cJSON_CreateObject(), *b, *g, *gf, *pts, *att, *steps, *sel, *fm;
    int i, k, iw, ia;
    const int tau_bound = sg_ar1_at_min(c, r->rate_hz) || sg_ar1_at_max(c);
    cJSON_AddStringToObject(o, "channel", sg_channel_name(ch));
    cJSON_AddStringToObject(o, "unit", sg_channel_unit(ch));
    cJSON_AddBoolToObject(o, "analysed", c->active);
    if (!c->active) {
        return o;
    }
    b = cJSON_AddObjectToObject(o, "baseline");
    hx_json_num(b, "mean", c->baseline.mean);
    iw = sg_model_find(&c->baseline, FNAV_EFFECT_WHITE);
    ia = sg_model_find(&c->baseline, FNAV_EFFECT_AR1);
    if (iw >= 0) {
        hx_json_num(b, "white_density", c->baseline.e[iw].p[0]);
        hx_json_num(b, "white_density_se", c->baseline.e[iw].se[0]);
        add_ci(b, "white_density", &c->baseline.e[iw], 0, 0);
    }
    if (ia >= 0) {
        hx_json_num(b, "ar1_sigma", c->baseline.e[ia].p[1]);
        hx_json_num(b, "ar1_sigma_se", c->baseline.e[ia].se[1]);
        add_ci(b, "ar1_sigma", &c->baseline.e[ia], 1, 0);
        hx_json_num(b, "ar1_tau_s", c->baseline.e[ia].p[1] > 0.0 ? c->baseline.e[ia].p[0] : (double)NAN);
        /* a time at either bound of its search is no fit and has no
         * standard error (the curvature at a constraint is none): the
         * shortest bound as well as the longest */
        hx_json_num(b, "ar1_tau_s_se", tau_bound ? (double)NAN : c->baseline.e[ia].se[0]);
        add_ci(b, "ar1_tau_s", &c->baseline.e[ia], 0, tau_bound || !(c->baseline.e[ia].p[1] > 0.0));
        hx_json_num(b, "ar1_tau_min_s", sg_ar1_tau_min(r->rate_hz));
        cJSON_AddBoolToObject(b, "ar1_tau_at_min", sg_ar1_at_min(c, r->rate_hz));
        hx_json_num(b, "ar1_tau_max_s", c->ar1_tau_max_s);
        cJSON_AddBoolToObject(b, "ar1_tau_at_max", sg_ar1_at_max(c));
    }
    if (c->q_full > 0.0) {
        cJSON *l = cJSON_AddObjectToObject(o, "lattice");
        hx_json_num(l, "step", c->q_full);
        hx_json_num(l, "z", c->q_full_z);
    } else {
        cJSON_AddNullToObject(o, "lattice");
    }
    g = cJSON_AddObjectToObject(o, "gap");
    gf = cJSON_AddObjectToObject(o, "gap_final");
    pts = cJSON_AddObjectToObject(o, "points");
    for (k = 0; k < SG_NSEG; k++) {
        cJSON_AddItemToObject(g, k_seg[k], cmp_json(&c->cmp[k]));
        /* without an attribution (a log too short for one) the final model
         * is the baseline */
        cJSON_AddItemToObject(gf, k_seg[k], cmp_json(c->cmp_final[k].z != NULL ? &c->cmp_final[k] : &c->cmp[k]));
        if (k != SG_FIT) {
            cJSON_AddItemToObject(pts, k_seg[k], points_json(&r->pl[ch][k], r->real[ch][k], &c->cmp[k]));
        }
    }
    cJSON_AddBoolToObject(o, "gap_significant", c->gap);
    att = cJSON_AddObjectToObject(o, "attribution");
    steps = cJSON_AddArrayToObject(att, "steps");
    for (i = 0; i < c->nsteps; i++) {
        const sg_step_t *st = &c->step[i];
        cJSON *so = cJSON_CreateObject(), *ca = cJSON_AddArrayToObject(so, "candidates");
        cJSON_AddNumberToObject(so, "step", i + 1);
        hx_json_num(so, "G_held_out_before", st->G_hold_before);
        hx_json_num(so, "G_fit_before", st->G_fit_before);
        for (k = 0; k < st->ncand; k++) {
            const sg_cand_t *cd = &st->cand[k];
            cJSON *co = effect_json(&cd->eff, ch);
            hx_json_num(co, "fit_dQ", cd->dQ_fit);
            cJSON_AddBoolToObject(co, "simulated", cd->simulated);
            cJSON_AddBoolToObject(co, "nested_in_ramp", cd->nested != 0);
            if (cd->simulated) {
                hx_json_num(co, "G_fit", cd->G_fit);
                hx_json_num(co, "G_held_out", cd->G_hold);
                hx_json_num(co, "dG_held_out", cd->dG_hold);
                hx_json_num(co, "score", cd->t_hold);
                hx_json_num(co, "score_null_mean", cd->t_null_mean);
                hx_json_num(co, "score_null_sd", cd->t_null_sd);
                hx_json_num(co, "z", cd->z_delta);
                hx_json_num(co, "z_held_out_middle", cd->z_mid);
                hx_json_num(co, "z_held_out_ends", cd->z_ends);
                hx_json_num(co, "dG_held_out_ends", cd->dG_ends);
                hx_json_num(co, "z_lr", cd->z_gap);
                hx_json_num(co, "z_lr_held_out_middle", cd->zg_mid);
                hx_json_num(co, "z_lr_held_out_ends", cd->zg_ends);
                hx_json_num(co, "explained", cd->expl_hold);
                hx_json_num(co, "explained_lo", cd->expl_lo);
                hx_json_num(co, "explained_hi", cd->expl_hi);
                hx_json_num(co, "explained_fit", cd->expl_fit);
            }
            cJSON_AddBoolToObject(co, "selected", k == st->selected);
            cJSON_AddItemToArray(ca, co);
        }
        cJSON_AddItemToArray(steps, so);
    }
    sel = cJSON_AddArrayToObject(att, "selected");
    for (i = 0; i < c->nsel; i++) {
        int m = sg_model_find(&c->final, c->sel_id[i]);
        if (m >= 0) {
            cJSON *so = effect_json(&c->final.e[m], ch);
            hx_json_num(so, "explained", c->sel_expl[i]);
            hx_json_num(so, "explained_lo", c->sel_lo[i]);
            hx_json_num(so, "explained_hi", c->sel_hi[i]);
            cJSON_AddItemToArray(sel, so);
        }
    }
    {
        cJSON *zr = cJSON_AddArrayToObject(att, "refitted_to_zero");
        for (i = 0; i < c->nzero; i++) {
            cJSON_AddItemToArray(zr, cJSON_CreateString(fnav_imuerr_effect_info((fnav_effect_id_t)c->zero_id[i])->name));
        }
    }
    fm = cJSON_AddArrayToObject(att, "final_model");
    for (i = 0; i < c->final.n; i++) {
        sg_effect_t e = c->final.e[i];
        /* the final refit keeps the baseline's AR(1) time (the grid from
         * the same bounds): at a bound, no standard error as above */
        if (e.id == FNAV_EFFECT_AR1 && e.p[1] > 0.0 &&
            (e.p[0] <= 1.001 * sg_ar1_tau_min(r->rate_hz) ||
             (c->ar1_tau_max_s > 0.0 && e.p[0] >= 0.999 * c->ar1_tau_max_s))) {
            e.se[0] = (double)NAN;
        }
        cJSON_AddItemToArray(fm, effect_json(&e, ch));
    }
    cJSON_AddBoolToObject(att, "within_noise", c->within_noise);
    if (c->have_prof) {
        cJSON *pr = cJSON_AddObjectToObject(o, "profile"), *pg = cJSON_AddObjectToObject(pr, "gap"), *pm;
        hx_json_num(pr, "white_density", c->prof.e[0].p[0]);
        hx_json_num(pr, "ar1_sigma", c->prof.e[1].p[1]);
        hx_json_num(pr, "ar1_tau_s", c->prof.e[1].p[0]);
        for (k = 0; k < SG_NSEG; k++) {
            cJSON_AddItemToObject(pg, k_seg[k], cmp_json(&c->cmp_prof[k]));
        }
        pm = cJSON_AddArrayToObject(pr, "twin");
        for (k = 0; k < (int)r->pl[ch][SG_FULL].n && c->cmp_prof[SG_FULL].z != NULL; k++) {
            cJSON *po = cJSON_CreateObject();
            hx_json_num(po, "twin", c->cmp_prof[SG_FULL].twin_mean[k]);
            hx_json_num(po, "sd", c->cmp_prof[SG_FULL].sd_tot[k]);
            hx_json_num(po, "z", c->cmp_prof[SG_FULL].z[k]);
            cJSON_AddItemToArray(pm, po);
        }
    }
    return o;
}

int sg_write_json(const sg_result_t *r, const char *path, char *err, size_t err_size)
{
    cJSON *root = cJSON_CreateObject(), *o, *a;
    int ch, k, rc;
    size_t i;
    if (root == NULL) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    cJSON_AddStringToObject(root, "schema", "footnav-simgap/1");
    cJSON_AddBoolToObject(root, "complete", r->complete);
    if (!r->complete) {
        cJSON_AddStringToObject(root, "error", r->input_error);
    }
    o = cJSON_AddObjectToObject(root, "log");
    cJSON_AddStringToObject(o, "path", r->path);
    cJSON_AddNumberToObject(o, "samples", (double)r->n);
    hx_json_num(o, "rate_hz", r->rate_hz);
    hx_json_num(o, "duration_s", r->duration_s);
    cJSON_AddStringToObject(o, "domain", r->domain == 1 ? "static" : "walk");
    cJSON_AddStringToObject(o, "domain_detected", r->domain_detected == 1 ? "static" : "walk");
    cJSON_AddStringToObject(o, "domain_from", r->opts.domain != 0 ? "option" : "detected");
    o = cJSON_AddObjectToObject(root, "split");
    cJSON_AddStringToObject(o, "method", r->segs.sandwich ? "sandwich: fit on both ends, held out the middle"
                                                          : "contiguous: fit on the first part, held out the rest");
    for (k = SG_FIT; k <= SG_HOLD; k++) {
        cJSON *s = cJSON_AddArrayToObject(o, k_seg[k]);
        int b;
        for (b = 0; b < r->segs.nb[k]; b++) {
            cJSON *bo = cJSON_CreateObject();
            hx_json_num(bo, "start_s", r->seg_start_s[k][b]);
            hx_json_num(bo, "end_s", r->seg_end_s[k][b]);
            cJSON_AddNumberToObject(bo, "samples", (double)r->segs.n[k][b]);
            cJSON_AddItemToArray(s, bo);
        }
    }
    o = cJSON_AddObjectToObject(root, "settings");
    cJSON_AddNumberToObject(o, "seeds", r->S);
    cJSON_AddNumberToObject(o, "seed", r->opts.seed);
    hx_json_num(o, "alpha", r->opts.alpha);
    hx_json_num(o, "fit_frac", r->opts.fit_frac);
    cJSON_AddNumberToObject(o, "max_effects", r->opts.max_steps);
    cJSON_AddNumberToObject(o, "prescreen", r->opts.prescreen);
    hx_json_num(o, "tau_identification_frac", SG_ID_FRAC);
    hx_json_num(o, "tau_test_frac", SG_TEST_FRAC);
    hx_json_num(o, "z_cap", SG_ZCAP);
    cJSON_AddBoolToObject(root, "confident", r->confident);
    if (r->confident) {
        cJSON_AddNullToObject(root, "too_short");
    } else {
        cJSON_AddStringToObject(root, "too_short", r->why);
    }
    if (r->domain == 1) {
        a = cJSON_AddArrayToObject(root, "channels");
        for (ch = 0; ch < SG_NCH; ch++) {
            cJSON_AddItemToArray(a, channel_json(r, ch));
        }
    }
    if (r->prof_name[0] != '\0') {
        cJSON_AddStringToObject(root, "profile", r->prof_name);
        a = cJSON_AddArrayToObject(root, "profile_locations");
        for (i = 0; i < r->nploc; i++) {
            cJSON_AddItemToArray(a, loc_json(&r->ploc[i]));
        }
    }
    a = cJSON_AddArrayToObject(root, "constant_channels");
    for (ch = 0; ch < SG_NCH; ch++) {
        if (r->constant[ch]) {
            cJSON *co = cJSON_CreateObject();
            cJSON_AddStringToObject(co, "channel", sg_channel_name(ch));
            hx_json_num(co, "value", r->constant_value[ch]);
            cJSON_AddItemToArray(a, co);
        }
    }
    a = cJSON_AddArrayToObject(root, "constant_segments");
    for (ch = 0; ch < SG_NCH; ch++) {
        if (r->seg_constant[ch]) {
            cJSON *co = cJSON_CreateObject();
            cJSON_AddStringToObject(co, "channel", sg_channel_name(ch));
            cJSON_AddStringToObject(co, "segment", r->seg_constant[ch] == SG_FIT ? "fit" : "held_out");
            hx_json_num(co, "value", r->seg_constant_value[ch]);
            cJSON_AddItemToArray(a, co);
        }
    }
    cJSON_AddNumberToObject(root, "locations_dropped", (double)r->nloc_dropped);
    a = cJSON_AddArrayToObject(root, "locations");
    for (i = 0; i < r->nloc; i++) {
        cJSON_AddItemToArray(a, loc_json(&r->loc[i]));
    }
    if (r->nav != NULL) {
        sg_nav_locations_json((const sg_nav_t *)r->nav, a);
    }
    o = cJSON_AddObjectToObject(root, "timing");
    cJSON_AddBoolToObject(o, "has_stamps", r->tim.have);
    cJSON_AddBoolToObject(o, "stamps_made_from_rate", r->stamps_made);
    if (r->tim.have) {
        static const char *const nm[SG_TIM_NKIND] = { "duplicate", "dropout", "jitter" };
        cJSON *cnt = cJSON_AddObjectToObject(o, "counts");
        hx_json_num(o, "stamp_resolution_s", r->tim.res_s);
        for (k = 0; k < SG_NSEG; k++) {
            cJSON *s = cJSON_AddObjectToObject(cnt, k_seg[k]);
            int d;
            cJSON *z = cJSON_AddObjectToObject(s, "z");
            cJSON_AddNumberToObject(s, "duplicated", (double)r->tim.n_dup[k]);
            cJSON_AddNumberToObject(s, "dropped", (double)r->tim.n_drop[k]);
            cJSON_AddNumberToObject(s, "intervals", (double)r->tim.n_int[k]);
            hx_json_num(s, "dropped_jitter_expected", r->tim.tail_drop[k]);
            hx_json_num(s, "duplicated_jitter_expected", r->tim.tail_dup[k]);
            hx_json_num(s, "interval_sd_s", r->tim.jit_sd[k]);
            for (d = 0; d < SG_TIM_NKIND; d++) {
                hx_json_num(z, nm[d], r->tim.z[k][d]);
            }
        }
        cJSON_AddBoolToObject(o, "significant", r->tim.significant);
        a = cJSON_AddArrayToObject(o, "selected");
        for (k = 0; k < SG_TIM_NKIND; k++) {
            if (r->tim.sel[k]) {
                cJSON *e = cJSON_CreateObject(), *p = cJSON_AddObjectToObject(e, "params");
                cJSON_AddStringToObject(e, "effect", nm[k]);
                if (k == SG_TIM_JITTER) {
                    hx_json_num(p, "stamp_s", r->tim.stamp_s);
                } else {
                    hx_json_num(p, "prob", k == SG_TIM_DUP ? r->tim.dup_prob : r->tim.drop_prob);
                }
                /* false: the whole log shows it, the fit segment none
                 * of it (its parameter 0 reproduces nothing) */
                cJSON_AddBoolToObject(e, "rate_from_fit", (k == SG_TIM_JITTER  ? r->tim.stamp_s
                                                           : k == SG_TIM_DUP ? r->tim.dup_prob
                                                                             : r->tim.drop_prob) > 0.0);
                hx_json_num(e, "z_whole_log", r->tim.z[SG_FULL][k]);
                hx_json_num(e, "z_held_out_before", r->tim.z[SG_HOLD][k]);
                hx_json_num(e, "z_held_out_after", r->tim.z_after[k]);
                cJSON_AddBoolToObject(e, "held_out_within_noise", !r->tim.open[k]);
                /* a jitter has no first event: null (its field, zeroed,
                 * would read 0) */
                hx_json_num(e, "first_event_s", k == SG_TIM_JITTER ? (double)NAN : r->tim.first_t[k]);
                cJSON_AddItemToArray(a, e);
            }
        }
    }
    if (r->nav != NULL) {
        cJSON_AddItemToObject(root, "navigation", sg_nav_json((const sg_nav_t *)r->nav, r));
    }
    /* ranked effects over the channels: held-out gap reduction summed */
    a = cJSON_AddArrayToObject(root, "effects");
    {
        int ids[FNAV_EFFECT_COUNT], ne = 0, e2;
        double score[FNAV_EFFECT_COUNT];
        memset(score, 0, sizeof score);
        for (ch = 0; ch < SG_NCH; ch++) {
            const sg_chres_t *c = &r->ch[ch];
            for (k = 0; k < c->nsteps; k++) {
                if (c->step[k].selected >= 0) {
                    const sg_cand_t *cd = &c->step[k].cand[c->step[k].selected];
                    int found = 0, kept = 0;
                    /* an effect refitted to zero (sg_prune_zero) is no
                     * answer here either: ranked, it would have no
                     * channel */
                    for (e2 = 0; e2 < c->nsel; e2++) {
                        kept |= c->sel_id[e2] == cd->id;
                    }
                    if (!kept) {
                        continue;
                    }
                    for (e2 = 0; e2 < ne; e2++) {
                        found |= ids[e2] == cd->id;
                    }
                    if (!found) {
                        ids[ne++] = cd->id;
                    }
                    score[cd->id] += cd->dG_rank;
                }
            }
        }
        /* order by score */
        for (e2 = 1; e2 < ne; e2++) {
            int v = ids[e2], m = e2 - 1;
            while (m >= 0 && score[ids[m]] < score[v]) {
                ids[m + 1] = ids[m];
                m--;
            }
            ids[m + 1] = v;
        }
        for (e2 = 0; e2 < ne; e2++) {
            cJSON *eo = cJSON_CreateObject(), *chs = cJSON_AddArrayToObject(eo, "channels");
            cJSON_AddStringToObject(eo, "effect", fnav_imuerr_effect_info((fnav_effect_id_t)ids[e2])->name);
            cJSON_AddNumberToObject(eo, "rank", e2 + 1);
            hx_json_num(eo, "held_out_gap_reduction", score[ids[e2]]);
            for (ch = 0; ch < SG_NCH; ch++) {
                const sg_chres_t *c = &r->ch[ch];
                for (k = 0; k < c->nsel; k++) {
                    int m = sg_model_find(&c->final, c->sel_id[k]);
                    if (c->sel_id[k] == ids[e2] && m >= 0) {
                        cJSON *co = effect_json(&c->final.e[m], ch);
                        cJSON_AddStringToObject(co, "channel", sg_channel_name(ch));
                        hx_json_num(co, "explained", c->sel_expl[k]);
                        hx_json_num(co, "explained_lo", c->sel_lo[k]);
                        hx_json_num(co, "explained_hi", c->sel_hi[k]);
                        cJSON_AddItemToArray(chs, co);
                    }
                }
            }
            cJSON_AddItemToArray(a, eo);
        }
    }
    o = cJSON_AddObjectToObject(root, "verdict");
    cJSON_AddStringToObject(o, "answer", r->verdict);
    /* every accepted effect of every domain, in the summary's order */
    a = cJSON_AddArrayToObject(o, "effects");
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_chres_t *c = &r->ch[ch];
        for (k = 0; k < c->nsel; k++) {
            int m = sg_model_find(&c->final, c->sel_id[k]);
            if (m >= 0) {
                cJSON *eo = effect_json(&c->final.e[m], ch), *cl = cJSON_CreateArray();
                cJSON_AddStringToObject(eo, "domain", "static");
                cJSON_AddItemToArray(cl, cJSON_CreateString(sg_channel_name(ch)));
                cJSON_AddItemToObject(eo, "channels", cl);
                hx_json_num(eo, "explained", c->sel_expl[k]);
                cJSON_AddItemToArray(a, eo);
            }
        }
    }
    if (r->nav != NULL) {
        sg_nav_verdict_json((const sg_nav_t *)r->nav, a);
    }
    /* static channels with a gap and no accepted effect, and why */
    {
        cJSON *u = cJSON_AddArrayToObject(o, "unconfirmed");
        for (ch = 0; ch < SG_NCH; ch++) {
            const sg_cand_t *lead;
            const int why = sg_unconfirmed(r, ch, &lead);
            cJSON *uo;
            if (why == SG_UNCONF_NONE) {
                continue;
            }
            uo = cJSON_CreateObject();
            cJSON_AddStringToObject(uo, "channel", sg_channel_name(ch));
            /* not-tried: no effect of the catalogue was tried (--max-effects
             * 0), as the summary says; not no-effect, "a held-out gap no
             * candidate reduces", which would say some were */
            cJSON_AddStringToObject(uo, "reason", why == SG_UNCONF_NOT_HELD_OUT
                                                      ? "not-held-out"
                                                      : (r->ch[ch].nsteps == 0 ? "not-tried" : "no-effect"));
            if (why == SG_UNCONF_NOT_HELD_OUT && lead != NULL) {
                cJSON *lo = effect_json(&lead->eff, ch);
                /* fit_dQ as in every other effect object; fit_dq, the
                 * name the lead was first written with, kept for
                 * footnav-simgap/1 readers */
                hx_json_num(lo, "fit_dQ", lead->dQ_fit);
                hx_json_num(lo, "fit_dq", lead->dQ_fit);
                cJSON_AddItemToObject(uo, "lead", lo);
            } else {
                cJSON_AddNullToObject(uo, "lead");
            }
            cJSON_AddItemToArray(u, uo);
        }
    }
    if (r->tim.have && r->tim.significant) {
        static const char *const tn[SG_TIM_NKIND] = { "duplicate", "dropout", "jitter" };
        for (k = 0; k < SG_TIM_NKIND; k++) {
            if (r->tim.sel[k]) {
                cJSON *eo = cJSON_CreateObject(), *p = cJSON_AddObjectToObject(eo, "params");
                cJSON_AddStringToObject(eo, "effect", tn[k]);
                cJSON_AddStringToObject(eo, "domain", "timing");
                cJSON_AddItemToObject(eo, "channels", cJSON_CreateArray());
                if (k == SG_TIM_JITTER) {
                    hx_json_num(p, "stamp_s", r->tim.stamp_s);
                } else {
                    hx_json_num(p, "prob", k == SG_TIM_DUP ? r->tim.dup_prob : r->tim.drop_prob);
                }
                cJSON_AddItemToArray(a, eo);
            }
        }
    }
    hx_json_num(root, "elapsed_s", r->elapsed_s);
    rc = hx_write_json(path, root, err, err_size);
    cJSON_Delete(root);
    return rc;
}
