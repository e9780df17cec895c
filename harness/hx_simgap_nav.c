/* Sim-to-real gap diagnosis, walk domain (hx_simgap_nav.h). */
#include "hx_simgap_nav.h"

#include <stdio.h>
#include <stdlib.h>

struct sg_nav {
    int dummy;
};

int sg_nav_diagnose(const hx_log_t *log, sg_result_t *r, char *err, size_t err_size)
{
    (void)log;
    (void)r;
    snprintf(err, err_size, "the walk domain is not built yet");
    return -1;
}

void sg_nav_verdict_counts(const sg_nav_t *nv, int *gaps, int *sel, int *open)
{
    (void)nv;
    (void)gaps;
    (void)sel;
    (void)open;
}

void sg_nav_free(sg_nav_t *nv)
{
    (void)nv;
}

void sg_nav_print(const sg_nav_t *nv, FILE *f, const sg_result_t *r)
{
    (void)nv;
    (void)f;
    (void)r;
}
