/* eval's figures (hx_evplot.h). */
#include "hx_evplot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hx_cli.h"

/* A new walk at the end of the set with room for n path points and ns
 * strides; NULL when memory runs out (the figure then lacks the walk). */
static hx_evplot_walk_t *new_walk(hx_evplot_set_t *s, const char *name, size_t n, int ns)
{
    hx_evplot_walk_t *w;
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 8;
        hx_evplot_walk_t *q = (hx_evplot_walk_t *)realloc(s->w, (size_t)cap * sizeof *q);
        if (q == NULL) {
            return NULL;
        }
        s->w = q;
        s->cap = cap;
    }
    w = &s->w[s->n];
    memset(w, 0, sizeof *w);
    w->x = (double *)malloc((4 * (n > 0 ? n : 1) + 4 * (size_t)(ns > 0 ? ns : 1)) * sizeof *w->x);
    if (w->x == NULL) {
        return NULL;
    }
    w->y = w->x + n;
    w->h = w->y + n;
    w->t = w->h + n;
    w->ex = w->t + n;
    w->ey = w->ex + ns;
    w->gx = w->ey + ns;
    w->gy = w->gx + ns;
    snprintf(w->name, sizeof w->name, "%s", name);
    s->n++;
    return w;
}

/* The aligned frames from `from`, every k-th, relative to frame `from`'s
 * position (time from the first aligned frame). */
static void take_path(hx_evplot_walk_t *w, const hx_traj_t *t, size_t from, size_t k, size_t first)
{
    size_t i;
    const double x0 = (double)t->f[from].pos_m[0], y0 = (double)t->f[from].pos_m[1];
    w->n = 0;
    for (i = from; i < t->n; i += k) {
        const fnav_nav_frame_t *f = &t->f[i];
        if (!(f->flags & FNAV_FRAME_ALIGNED)) {
            continue;
        }
        w->x[w->n] = (double)f->pos_m[0] - x0;
        w->y[w->n] = (double)f->pos_m[1] - y0;
        w->h[w->n] = -(double)f->pos_m[2]; /* n is z down */
        w->t[w->n] = 1e-9 * (double)(f->t_ns - t->f[first].t_ns);
        w->n++;
    }
}

static size_t first_aligned(const hx_traj_t *t)
{
    size_t i;
    for (i = 0; i < t->n; i++) {
        if (t->f[i].flags & FNAV_FRAME_ALIGNED) {
            return i;
        }
    }
    return t->n;
}

void hx_evplot_add_path(hx_evplot_set_t *s, const char *name, const hx_traj_t *t)
{
    const size_t first = first_aligned(t);
    size_t k;
    hx_evplot_walk_t *w;
    if (first >= t->n) {
        return;
    }
    k = (t->n - first + HX_EVPLOT_MAX_POINTS - 1) / HX_EVPLOT_MAX_POINTS;
    w = new_walk(s, name, (t->n - first + k - 1) / k, 0);
    if (w != NULL) {
        size_t *mid = (size_t *)malloc((t->n + 1) * sizeof *mid);
        take_path(w, t, first, k, first);
        if (mid != NULL) {
            size_t i, m = hx_nav_stance_mids(t, mid, t->n + 1);
            w->mh = (double *)malloc(2 * (m > 0 ? m : 1) * sizeof *w->mh);
            if (w->mh != NULL) {
                w->mt = w->mh + m;
                for (i = 0; i < m; i++) {
                    w->mh[i] = -(double)t->f[mid[i]].pos_m[2];
                    w->mt[i] = 1e-9 * (double)(t->f[mid[i]].t_ns - t->f[first].t_ns);
                }
                w->nm = m;
            }
            free(mid);
        }
    }
}

void hx_evplot_add_strides(hx_evplot_set_t *s, const char *name, const hx_traj_t *t, const long *idx,
                           const double *gx, const double *gy, int n)
{
    const size_t first = first_aligned(t);
    size_t k;
    int i, j0 = -1;
    hx_evplot_walk_t *w;
    for (i = 0; i < n && j0 < 0; i++) {
        if (idx[i] >= 0 && (size_t)idx[i] < t->n && isfinite(gx[i]) && isfinite(gy[i])) {
            j0 = i;
        }
    }
    if (first >= t->n || j0 < 0) {
        return;
    }
    k = (t->n - (size_t)idx[j0] + HX_EVPLOT_MAX_POINTS - 1) / HX_EVPLOT_MAX_POINTS;
    w = new_walk(s, name, (t->n - (size_t)idx[j0] + k - 1) / k, n);
    if (w == NULL) {
        return;
    }
    take_path(w, t, (size_t)idx[j0], k, first);
    for (i = j0; i < n; i++) {
        const fnav_nav_frame_t *f;
        if (idx[i] < 0 || (size_t)idx[i] >= t->n || !isfinite(gx[i]) || !isfinite(gy[i])) {
            continue;
        }
        f = &t->f[idx[i]];
        w->ex[w->ns] = (double)f->pos_m[0] - (double)t->f[idx[j0]].pos_m[0];
        w->ey[w->ns] = (double)f->pos_m[1] - (double)t->f[idx[j0]].pos_m[1];
        w->gx[w->ns] = gx[i] - gx[j0];
        w->gy[w->ns] = gy[i] - gy[j0];
        w->ns++;
    }
}

int hx_evplot_paths(const hx_evplot_set_t *s, const char *cmd, const char *png, const char *title)
{
    hx_plot_t p;
    char q[256];
    int i;
    size_t j;
    if (s->n == 0 || hx_plot_open(&p, cmd, png, 1400, 650) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 1,2 title '%s'\n", hx_gp_str(q, sizeof q, title));
    fprintf(p.gp, "set key outside bottom center horizontal noautotitle\n");
    /* n's y to the right, x up: x is the heading at the alignment, not
     * north (no magnetometer, docs/frames.md), as in replay's plot */
    fprintf(p.gp, "set size ratio -1\nset xlabel '" HX_PLOT_PATH_XLABEL "'\nset ylabel '" HX_PLOT_PATH_YLABEL
                  "'\nplot ");
    for (i = 0; i < s->n; i++) {
        fprintf(p.gp, "'-' with lines lw 1 title '%s', ", hx_gp_str(q, sizeof q, s->w[i].name));
    }
    fprintf(p.gp, "'-' with points pt 7 ps 1.2 lc 'black' title 'start'\n");
    for (i = 0; i < s->n; i++) {
        for (j = 0; j < s->w[i].n; j++) {
            fprintf(p.gp, "%.4f %.4f\n", s->w[i].y[j], s->w[i].x[j]);
        }
        fprintf(p.gp, "e\n");
    }
    fprintf(p.gp, "0 0\ne\n");
    fprintf(p.gp, "unset key\nset size noratio\nset xlabel 'time (s)'\nset ylabel 'height at the stance mid-points (m, up)'\nplot ");
    for (i = 0; i < s->n; i++) {
        fprintf(p.gp, "'-' with linespoints lw 1 pt 7 ps 0.4%s", i + 1 < s->n ? ", " : "\n");
    }
    for (i = 0; i < s->n; i++) {
        for (j = 0; j < s->w[i].nm; j++) {
            fprintf(p.gp, "%.4f %.4f\n", s->w[i].mt[j], s->w[i].mh[j]);
        }
        fprintf(p.gp, "e\n");
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, cmd);
}

/* What the strides' panels show (the second line of their title). */
static const char k_strides_key[] = "(grey: estimated path; red dots: the estimate at each stride; circles: the truth "
                                    "there)";

/* Widen the ranges lo..hi (n's y, x) to a point. */
static void widen(double lo[2], double hi[2], double e, double n)
{
    lo[0] = fmin(lo[0], e);
    hi[0] = fmax(hi[0], e);
    lo[1] = fmin(lo[1], n);
    hi[1] = fmax(hi[1], n);
}

int hx_evplot_strides(const hx_evplot_set_t *s, const char *cmd, const char *png, const char *title)
{
    hx_plot_t p;
    char q[256];
    int i, k, cols, rows;
    size_t j;
    if (s->n == 0) {
        return -1;
    }
    cols = (int)ceil(sqrt((double)s->n));
    rows = (s->n + cols - 1) / cols;
    /* the title and the key on two lines, the picture at least as wide as
     * the longer (about 6 px a character): on one line, 3 panels wide, the
     * footprints' figure would cut both ends off, the key's "circles: the
     * truth" among them */
    {
        const size_t len = strlen(title) > strlen(k_strides_key) ? strlen(title) : strlen(k_strides_key);
        const int w = 320 * cols > 7 * (int)len + 40 ? 320 * cols : 7 * (int)len + 40;
        if (hx_plot_open(&p, cmd, png, w, 320 * rows + 60) != 0) {
            return -1;
        }
    }
    fprintf(p.gp, "set multiplot layout %d,%d title '%s'.\"\\n\".'%s'\n", rows, cols, hx_gp_str(q, sizeof q, title),
            k_strides_key);
    fprintf(p.gp, "set size ratio -1\nunset key\nset xlabel '" HX_PLOT_PATH_XLABEL "' font ',8'\n"
                  "set ylabel '" HX_PLOT_PATH_YLABEL "' font ',8'\nset tics font ',8'\n");
    for (i = 0; i < s->n; i++) {
        const hx_evplot_walk_t *w = &s->w[i];
        /* the panel's ranges: every point, the narrower side widened to
         * half the wider (a straight walk stays readable) */
        double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL }, span, c;
        int a;
        for (j = 0; j < w->n; j++) {
            widen(lo, hi, w->y[j], w->x[j]);
        }
        for (k = 0; k < w->ns; k++) {
            widen(lo, hi, w->gy[k], w->gx[k]);
            widen(lo, hi, w->ey[k], w->ex[k]);
        }
        span = 1.05 * fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), 1.0);
        for (a = 0; a < 2; a++) {
            c = 0.5 * (lo[a] + hi[a]);
            if (hi[a] - lo[a] < 0.5 * span) {
                lo[a] = c - 0.25 * span;
                hi[a] = c + 0.25 * span;
            } else {
                lo[a] = c - 0.525 * (hi[a] - lo[a]);
                hi[a] = c + 0.525 * (hi[a] - lo[a]);
            }
        }
        fprintf(p.gp, "set xrange [%.3f:%.3f]\nset yrange [%.3f:%.3f]\n", lo[0], hi[0], lo[1], hi[1]);
        fprintf(p.gp, "set title '%s' font ',9'\n", hx_gp_str(q, sizeof q, w->name));
        fprintf(p.gp, "plot '-' with lines lw 1 lc 'gray60' title 'path', "
                      "'-' with points pt 6 ps 0.9 lc 'black' title 'truth', "
                      "'-' with points pt 7 ps 0.5 lc 'red' title 'estimate'\n");
        for (j = 0; j < w->n; j++) {
            fprintf(p.gp, "%.4f %.4f\n", w->y[j], w->x[j]);
        }
        fprintf(p.gp, "e\n");
        for (k = 0; k < w->ns; k++) {
            fprintf(p.gp, "%.4f %.4f\n", w->gy[k], w->gx[k]);
        }
        fprintf(p.gp, "e\n");
        for (k = 0; k < w->ns; k++) {
            fprintf(p.gp, "%.4f %.4f\n", w->ey[k], w->ex[k]);
        }
        fprintf(p.gp, "e\n");
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, cmd);
}

/* Counts of the rounded values of v in -clip..clip (the ends gather the
 * values beyond). */
static void counts(const double *v, int n, int clip, int *c)
{
    int i;
    for (i = 0; i <= 2 * clip; i++) {
        c[i] = 0;
    }
    for (i = 0; i < n; i++) {
        double x = v[i] < -clip ? -clip : (v[i] > clip ? clip : v[i]);
        c[(int)lround(x) + clip]++;
    }
}

int hx_evplot_hist2(const char *cmd, const char *png, const char *title, const char *xlabel, const double *a,
                    int na, const char *la, const double *b, int nb, const char *lb, int clip)
{
    hx_plot_t p;
    char q[256];
    int c[2 * 64 + 1], k, h;
    const double *v[2] = { a, b };
    const int nv[2] = { na, nb };
    const char *lab[2] = { la, lb };
    if (clip < 1 || clip > 64 || hx_plot_open(&p, cmd, png, 1100, 420) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 1,2 title '%s'\n", hx_gp_str(q, sizeof q, title));
    fprintf(p.gp, "set style fill solid 0.6\nset boxwidth 0.8\nunset key\nset ylabel 'count'\n");
    fprintf(p.gp, "set xrange [%d:%d]\n", -clip - 1, clip + 1);
    for (h = 0; h < 2; h++) {
        fprintf(p.gp, "set title '%s (%d)'\nset xlabel '%s'\n", hx_gp_str(q, sizeof q, lab[h]), nv[h], xlabel);
        fprintf(p.gp, "plot '-' with boxes lc rgb 'steelblue'\n");
        counts(v[h], nv[h], clip, c);
        for (k = 0; k <= 2 * clip; k++) {
            fprintf(p.gp, "%d %d\n", k - clip, c[k]);
        }
        fprintf(p.gp, "e\n");
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, cmd);
}

void hx_evplot_free(hx_evplot_set_t *s)
{
    int i;
    for (i = 0; i < s->n; i++) {
        free(s->w[i].x);
        free(s->w[i].mh);
    }
    free(s->w);
    memset(s, 0, sizeof *s);
}
