/* Sim-to-real gap: static twins of a channel model through the simulator's
 * error model (fnav_imuerr), six independent realisations per run
 * (hx_simgap.h, docs/simgap.md). */
#include "hx_simgap.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sg_segs_split(long n, double frac, sg_segs_t *s)
{
    long nf = (long)floor((double)n * frac);
    if (nf < 1) {
        nf = 1;
    }
    if (nf > n - 1) {
        nf = n - 1;
    }
    s->start[SG_FULL] = 0;
    s->n[SG_FULL] = n;
    s->start[SG_FIT] = 0;
    s->n[SG_FIT] = nf;
    s->start[SG_HOLD] = nf;
    s->n[SG_HOLD] = n - nf;
}

int sg_twin_static(const sg_chmodel_t *m, int ch, const sg_feat_cfg_t *fc, const sg_segs_t *segs, double q, int S,
                   uint32_t seed0, const sg_plist_t pl[SG_NSEG], double *vals[SG_NSEG])
{
    int runs = (S + FNAV_IMUERR_NCH - 1) / FNAV_IMUERR_NCH, r, j, g, rc = 0;
    const long N = segs->n[SG_FULL], nf = segs->n[SG_FIT];
    sg_acc_t *acc = (sg_acc_t *)calloc((size_t)SG_NSEG * FNAV_IMUERR_NCH, sizeof *acc);
    double *tmp = NULL;
    size_t cap = 0;
    if (acc == NULL) {
        return -1;
    }
    for (g = 0; g < SG_NSEG; g++) {
        cap = pl[g].n > cap ? pl[g].n : cap;
    }
    tmp = (double *)malloc((cap + 1) * sizeof *tmp);
    if (tmp == NULL) {
        free(acc);
        return -1;
    }
    for (r = 0; r < runs && rc == 0; r++) {
        fnav_imuerr_config_t cfg;
        fnav_imuerr_t e;
        long k;
        double prev[FNAV_IMUERR_NCH], bc[FNAV_IMUERR_NCH], bs[FNAV_IMUERR_NCH];
        if (sg_model_imuerr(m, fc->rate_hz, seed0 + (uint32_t)r, &cfg) != 0 || fnav_imuerr_init(&e, &cfg) != FNAV_OK) {
            rc = -1;
            break;
        }
        for (g = 0; g < SG_NSEG && rc == 0; g++) {
            for (j = 0; j < FNAV_IMUERR_NCH; j++) {
                if (sg_acc_init(&acc[g * FNAV_IMUERR_NCH + j], fc, segs->n[g], q) != 0) {
                    rc = -1;
                }
                /* the whole log's lattice sums are those of the parts */
                acc[g * FNAV_IMUERR_NCH + j].lat_external = (g == SG_FULL);
            }
        }
        for (k = 0; k < N && rc == 0; k++) {
            fnav_sample_t s;
            int seg = k < nf ? SG_FIT : SG_HOLD;
            memset(&s, 0, sizeof s);
            for (j = 0; j < 3; j++) {
                s.accel_mps2[j] = (fnav_real_t)m->mean;
                s.gyro_rps[j] = (fnav_real_t)m->mean;
            }
            if (fnav_imuerr_apply(&e, &s) != FNAV_OK) {
                rc = -1;
                break;
            }
            for (j = 0; j < FNAV_IMUERR_NCH; j++) {
                double x = (double)(j < 3 ? s.accel_mps2[j] : s.gyro_rps[j - 3]);
                sg_acc_push(&acc[SG_FULL * FNAV_IMUERR_NCH + j], x);
                sg_acc_push(&acc[seg * FNAV_IMUERR_NCH + j], x);
                if (k == nf && q > 0.0) {
                    /* the difference across the boundary */
                    double ph = 2.0 * M_PI * (x - prev[j]) / q;
                    bc[j] = cos(ph);
                    bs[j] = sin(ph);
                }
                prev[j] = x;
            }
        }
        for (j = 0; j < FNAV_IMUERR_NCH && rc == 0; j++) {
            int sidx = r * FNAV_IMUERR_NCH + j;
            sg_acc_t *full = &acc[SG_FULL * FNAV_IMUERR_NCH + j];
            const sg_acc_t *fit = &acc[SG_FIT * FNAV_IMUERR_NCH + j], *hold = &acc[SG_HOLD * FNAV_IMUERR_NCH + j];
            if (q > 0.0) {
                full->lc = fit->lc + hold->lc + bc[j];
                full->ls = fit->ls + hold->ls + bs[j];
                full->lm = fit->lm + hold->lm + 1;
            }
            for (g = 0; g < SG_NSEG; g++) {
                long cnt = sg_acc_finish(&acc[g * FNAV_IMUERR_NCH + j], ch, NULL, tmp, cap + 1);
                if (cnt != (long)pl[g].n) {
                    rc = -1;
                    break;
                }
                if (sidx < S) {
                    memcpy(vals[g] + (size_t)sidx * pl[g].n, tmp, pl[g].n * sizeof *tmp);
                }
            }
        }
        for (g = 0; g < SG_NSEG * FNAV_IMUERR_NCH; g++) {
            sg_acc_free(&acc[g]);
        }
    }
    free(tmp);
    free(acc);
    return rc;
}
