/**
 * @file hx_simgap_nav.h
 * @brief Sim-to-real gap diagnosis, walk domain (docs/simgap.md): the
 *        navigation filter on the real walk, the twin's motion from its
 *        estimated trajectory, and the gap in zero-velocity-update
 *        innovations, residual velocity in stance and drift.
 */
#ifndef HX_SIMGAP_NAV_H
#define HX_SIMGAP_NAV_H

#include "hx_simgap.h"

typedef struct sg_nav sg_nav_t;

/** Walk-domain diagnosis of a loaded log into r (r->nav is set). */
int sg_nav_diagnose(const hx_log_t *log, sg_result_t *r, char *err, size_t err_size);
/** Add the walk domain's gaps, selected effects and open gaps to the counts. */
void sg_nav_verdict_counts(const sg_nav_t *nv, int *gaps, int *sel, int *open);
/** Print the walk domain's part of the summary. */
void sg_nav_print(const sg_nav_t *nv, FILE *f, const sg_result_t *r);
void sg_nav_free(sg_nav_t *nv);

#endif /* HX_SIMGAP_NAV_H */
