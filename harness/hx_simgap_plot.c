/* Sim-to-real gap diagnosis: plots (gnuplot pngcairo through hx_plot_*):
 * allan.png (real vs the baseline twin and the final model's twin, whole
 * log, with the twins' spread), psd.png (the same for the Welch bands),
 * z.png (z per point with the critical values: Allan, PSD and the time
 * domain's trend, curvature and steps), and the walk domain's
 * innovations plot (hx_simgap_nav.c). */
#include "hx_simgap.h"
#include "hx_simgap_nav.h"

#include <errno.h>
#include <math.h>
#include <string.h>
#include <sys/stat.h>

#include "hx_cli.h"

/* Data block of one channel and domain: x, real, twin mean, twin sd, final
 * twin mean (value transformed: deviation for Allan, PSD as is). */
static void block(FILE *gp, const char *name, const sg_result_t *r, int ch, int dom)
{
    const sg_plist_t *pl = &r->pl[ch][SG_FULL];
    const double *real = r->real[ch][SG_FULL], *tw = r->twin[ch][SG_FULL];
    const double *tf = r->twin_final[ch][SG_FULL] != NULL ? r->twin_final[ch][SG_FULL] : tw;
    const int S = r->S;
    size_t j, n = pl->n;
    fprintf(gp, "$%s << EOD\n", name);
    for (j = 0; j < n; j++) {
        double m = 0.0, v = 0.0, mf = 0.0, f = dom == SG_ALLAN ? 0.5 : 1.0;
        int s;
        if (pl->p[j].dom != dom) {
            continue;
        }
        for (s = 0; s < S; s++) {
            m += tw[(size_t)s * n + j];
            mf += tf[(size_t)s * n + j];
        }
        m /= S;
        mf /= S;
        for (s = 0; s < S; s++) {
            v += (tw[(size_t)s * n + j] - m) * (tw[(size_t)s * n + j] - m);
        }
        v = sqrt(v / (S - 1));
        /* values are ln AVAR / ln PSD: ADEV = exp(ln AVAR / 2); column 7 the
         * given profile's twin (--profile), NaN without */
        fprintf(gp, "%.6g %.6g %.6g %.6g %.6g %.6g %.6g\n", pl->p[j].x, exp(f * real[j]), exp(f * m), exp(f * (m - v)),
                exp(f * (m + v)), exp(f * mf),
                r->ch[ch].have_prof ? exp(f * r->ch[ch].cmp_prof[SG_FULL].twin_mean[j]) : (double)NAN);
    }
    fprintf(gp, "EOD\n");
}

/* Points of domain dom on channel ch's whole log (a short log has no
 * Welch band: at least 16 segments are needed). */
static size_t n_points(const sg_result_t *r, int ch, int dom)
{
    const sg_plist_t *pl = &r->pl[ch][SG_FULL];
    size_t j, n = 0;
    for (j = 0; r->ch[ch].active && j < pl->n; j++) {
        n += pl->p[j].dom == dom;
    }
    return n;
}

/* An empty panel with a title: gnuplot refuses a plot without a valid
 * point (or a logarithmic axis without a range), and the png would not be
 * written. */
static void empty_panel(FILE *gp, const char *title)
{
    fprintf(gp, "set title '%s'\nunset logscale xy\nset xrange [0:1]\nset yrange [0:1]\n"
                "plot -1 notitle\nset autoscale xy\n", title);
}

static int plot_domain(const sg_result_t *r, const char *dir, const char *cmd, int dom)
{
    hx_plot_t p;
    char path[HX_PLOT_PATH_SIZE];
    int ch;
    snprintf(path, sizeof path, "%s/%s.png", dir, dom == SG_ALLAN ? "allan" : "psd");
    if (hx_plot_open(&p, cmd, path, 1200, 800) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 2,3 title '%s: real (points) vs baseline twin (line, +-1 sd band) and the "
                  "final model (dashed), whole log'\n",
            dom == SG_ALLAN ? "Allan deviation" : "Welch PSD (band means)");
    fprintf(p.gp, "set logscale xy\nset format y '%%.0e'\nset key bottom left\n");
    fprintf(p.gp, "set xlabel '%s'\n", dom == SG_ALLAN ? "tau [s]" : "frequency [Hz]");
    for (ch = 0; ch < SG_NCH; ch++) {
        char nm[16];
        snprintf(nm, sizeof nm, "d%d", ch);
        if (!r->ch[ch].active || n_points(r, ch, dom) == 0) {
            char t[160];
            snprintf(t, sizeof t, "%s: %s", sg_channel_name(ch),
                     !r->ch[ch].active ? (r->constant[ch]                 ? "not analysed (one value over the whole log)"
                                          : r->seg_constant[ch] == SG_FIT ? "not analysed (no variation within the fit segment)"
                                          : r->seg_constant[ch] == SG_HOLD
                                              ? "not analysed (no variation within the held-out segment)"
                                              : "not analysed")
                                       : (dom == SG_ALLAN ? "no Allan point" : "no Welch band (the log is too short)"));
            empty_panel(p.gp, t);
            fprintf(p.gp, "set logscale xy\n");
            continue;
        }
        block(p.gp, nm, r, ch, dom);
        fprintf(p.gp, "set title '%s'\nset ylabel '%s'\n", sg_channel_name(ch),
                dom == SG_ALLAN ? (ch < 3 ? "ADEV [m/s^2]" : "ADEV [rad/s]")
                                : (ch < 3 ? "PSD [(m/s^2)^2/Hz]" : "PSD [(rad/s)^2/Hz]"));
        fprintf(p.gp, "plot $%s using 1:4:5 with filledcurves fs transparent solid 0.25 lc rgb '#4060c0' title "
                      "'twin +-1 sd', $%s using 1:3 with lines lw 1.5 lc rgb '#4060c0' title 'baseline twin', "
                      "$%s using 1:6 with lines lw 1.5 dt 2 lc rgb '#20a040' title 'final model', $%s using 1:2 with "
                      "points pt 7 ps 0.6 lc rgb '#c02020' title 'real'",
                nm, nm, nm, nm);
        if (r->ch[ch].have_prof) {
            /* the profile's name is the user's text, quoted for gnuplot
             * ("Bob's MEMS" would end the gnuplot string: no plot) */
            char q[160];
            fprintf(p.gp, ", $%s using 1:7 with lines lw 1.5 dt 4 lc rgb '#e08000' title 'profile %s'", nm,
                    hx_gp_str(q, sizeof q, r->prof_name));
        }
        fprintf(p.gp, "\n");
    }
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, cmd);
}

/* The z of every whole-log point of domain dom, one data block per channel
 * ($<tag><ch>; x the point's x, or for the time domain its kind with the
 * channels side by side), and the panel's plot line (style per channel;
 * dashed lines at the largest critical |z| of the channels). */
static void z_panel(FILE *gp, const sg_result_t *r, int dom, char tag, const char *style)
{
    double zc = 0.0;
    int ch;
    for (ch = 0; ch < SG_NCH; ch++) {
        const sg_plist_t *pl = &r->pl[ch][SG_FULL];
        const sg_cmp_t *c = &r->ch[ch].cmp[SG_FULL];
        size_t j;
        fprintf(gp, "$%c%d << EOD\n", tag, ch);
        for (j = 0; r->ch[ch].active && c->z != NULL && j < pl->n; j++) {
            if (pl->p[j].dom == dom) {
                double zz = c->z[j] > SG_ZCAP ? SG_ZCAP : (c->z[j] < -SG_ZCAP ? -SG_ZCAP : c->z[j]);
                double x = dom == SG_TIME ? 1.0 + (double)pl->p[j].kind + 0.08 * ((double)ch - 2.5) : pl->p[j].x;
                fprintf(gp, "%.6g %.4g\n", x, zz);
            }
        }
        fprintf(gp, "EOD\n");
        if (r->ch[ch].active && c->z_crit > zc) {
            zc = c->z_crit;
        }
    }
    {
        int any = 0;
        for (ch = 0; ch < SG_NCH; ch++) {
            any |= n_points(r, ch, dom) > 0;
        }
        if (!any) {
            /* no point on any channel (no Welch band in a short log) */
            empty_panel(gp, dom == SG_PSD    ? "PSD bands: none (the log is too short)"
                            : dom == SG_TIME ? "time domain: none (the log is too short)"
                                             : "Allan: none (the log is too short)");
            return;
        }
    }
    fprintf(gp, "plot ");
    for (ch = 0; ch < SG_NCH; ch++) {
        if (n_points(r, ch, dom) > 0) { /* a channel not analysed has no point (a warning from gnuplot) */
            fprintf(gp, "$%c%d using 1:2 with %s lc %d title '%s', ", tag, ch, style, ch + 1, sg_channel_name(ch));
        }
    }
    fprintf(gp, "%.3f with lines dt 2 lc rgb 'black' notitle, %.3f with lines dt 2 lc rgb 'black' notitle\n", zc, -zc);
}

static int plot_z(const sg_result_t *r, const char *dir, const char *cmd)
{
    hx_plot_t p;
    char path[HX_PLOT_PATH_SIZE];
    snprintf(path, sizeof path, "%s/z.png", dir);
    if (hx_plot_open(&p, cmd, path, 1200, 1000) != 0) {
        return -1;
    }
    fprintf(p.gp, "set multiplot layout 3,1 title 'z of the real against the baseline twin, whole log (lines: the "
                  "critical |z|)'\nset logscale x\nset key outside right\nset ylabel 'z'\n");
    fprintf(p.gp, "set xlabel 'tau [s]'\nset title 'Allan'\n");
    z_panel(p.gp, r, SG_ALLAN, 'a', "linespoints pt 7 ps 0.5");
    fprintf(p.gp, "set logscale x\nset xlabel 'frequency [Hz]'\nset title 'PSD bands'\n");
    z_panel(p.gp, r, SG_PSD, 'p', "linespoints pt 7 ps 0.5");
    /* the time domain: per channel, the trend, curvature and steps points
     * of the whole log (one block), side by side */
    fprintf(p.gp, "unset logscale x\nset xrange [0.5:3.5]\nset xtics ('trend' 1, 'curvature' 2, 'steps' 3)\n"
                  "set xlabel 'time-domain statistic'\nset title 'time domain'\n");
    z_panel(p.gp, r, SG_TIME, 't', "impulses lw 3");
    fprintf(p.gp, "unset multiplot\n");
    return hx_plot_close(&p, cmd);
}

int sg_write_plots(const sg_result_t *r, const char *dir, const char *cmd)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        hx_error(cmd, "cannot create %s: %s", dir, strerror(errno));
        return -1;
    }
    if (r->domain == 2) {
        return r->nav != NULL ? sg_nav_plot((const sg_nav_t *)r->nav, r, dir, cmd) : -1;
    }
    if (plot_domain(r, dir, cmd, SG_ALLAN) != 0 || plot_domain(r, dir, cmd, SG_PSD) != 0 || plot_z(r, dir, cmd) != 0) {
        return -1;
    }
    return 0;
}
