/**
 * @file hx_evplot.h
 * @brief eval's figures: the walks of a data set drawn together (paths
 *        and heights), and walks with stride truth drawn panel by panel
 *        (estimate against the footprints or the motion capture).
 *
 * The walks are collected while eval runs (each trajectory is freed after
 * its figures are taken) and drawn at the end of each section with
 * gnuplot (docs/harness.md, "eval").
 */
#ifndef HX_EVPLOT_H
#define HX_EVPLOT_H

#include <stddef.h>

#include "hx_nav.h"

/** Most points kept of a walk's path (every k-th aligned frame). */
#define HX_EVPLOT_MAX_POINTS 3000

/** One walk of a figure. */
typedef struct {
    char name[64];
    size_t n;        /**< path points */
    double *x, *y;   /**< n frame north, east, m, from the first stride (or the first aligned frame) */
    double *h, *t;   /**< height, up, m, and time, s, from the first aligned frame */
    size_t nm;       /**< stance mid-points (closed walks) */
    double *mh, *mt; /**< height and time at the stance mid-points (hx_nav_stance_mids) */
    int ns;          /**< strides with truth (0: a closed walk) */
    double *ex, *ey; /**< estimate at the strides, from the first stride's, m */
    double *gx, *gy; /**< truth at the strides, from the first stride's, m */
} hx_evplot_walk_t;

/** The walks of one figure. */
typedef struct {
    int n, cap;
    hx_evplot_walk_t *w;
} hx_evplot_set_t;

/** Add a closed walk: its path and height. */
void hx_evplot_add_path(hx_evplot_set_t *s, const char *name, const hx_traj_t *t);

/** Add a walk with stride truth: the path from the first stride, and the
 *  estimate and truth at the n strides idx[] (frame indices) whose truth
 *  gx[], gy[] is finite and whose frame is inside the trajectory; the first
 *  stride is the origin of both (eval's stride errors, docs/harness.md). */
void hx_evplot_add_strides(hx_evplot_set_t *s, const char *name, const hx_traj_t *t, const long *idx,
                           const double *gx, const double *gy, int n);

/** Draw the set's paths overlaid (left) and the height at the stance
 *  mid-points over time (right: the footsteps' height, what the closure's
 *  vertical part measures, without the swings).
 *  0, or -1 with the error printed (no gnuplot, a PNG not written). */
int hx_evplot_paths(const hx_evplot_set_t *s, const char *cmd, const char *png, const char *title);

/** Draw one panel per walk: the estimated path, the estimate at each
 *  stride and the truth. 0, or -1 with the error printed. */
int hx_evplot_strides(const hx_evplot_set_t *s, const char *cmd, const char *png, const char *title);

/** Draw two histograms of integer errors side by side (counts per value,
 *  values beyond +-clip gathered at the ends): e.g. the gait events'
 *  timing errors in samples. 0, or -1 with the error printed. */
int hx_evplot_hist2(const char *cmd, const char *png, const char *title, const char *xlabel, const double *a,
                    int na, const char *la, const double *b, int nb, const char *lb, int clip);

/** Free the set (it can be filled again). */
void hx_evplot_free(hx_evplot_set_t *s);

#endif /* HX_EVPLOT_H */
