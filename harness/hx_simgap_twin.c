/* Sim-to-real gap: static twins of a channel model through the simulator's
 * error model (fnav_imuerr), six independent realisations per run
 * (hx_simgap.h, docs/simgap.md). */
#include "hx_simgap.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sg_segs_split(long n, double frac, int sandwich, sg_segs_t *s)
{
    long nf = (long)floor((double)n * frac);
    memset(s, 0, sizeof *s);
    if (nf < 2) {
        nf = 2;
    }
    if (nf > n - 1) {
        nf = n - 1;
    }
    s->sandwich = sandwich;
    s->nb[SG_FULL] = 1;
    s->start[SG_FULL][0] = 0;
    s->n[SG_FULL][0] = n;
    if (sandwich) {
        long a = nf / 2, b = n - (nf - a);
        s->nb[SG_FIT] = 2;
        s->start[SG_FIT][0] = 0;
        s->n[SG_FIT][0] = a;
        s->start[SG_FIT][1] = b;
        s->n[SG_FIT][1] = n - b;
        s->nb[SG_HOLD] = 1;
        s->start[SG_HOLD][0] = a;
        s->n[SG_HOLD][0] = b - a;
    } else {
        s->nb[SG_FIT] = 1;
        s->start[SG_FIT][0] = 0;
        s->n[SG_FIT][0] = nf;
        s->nb[SG_HOLD] = 1;
        s->start[SG_HOLD][0] = nf;
        s->n[SG_HOLD][0] = n - nf;
    }
    {
        int g, b;
        for (g = 0; g < SG_NSEG; g++) {
            for (b = 0; b < s->nb[g]; b++) {
                s->total[g] += s->n[g][b];
            }
        }
    }
}

int sg_segs_block(const sg_segs_t *s, int g, long k)
{
    int b;
    for (b = 0; b < s->nb[g]; b++) {
        if (k >= s->start[g][b] && k < s->start[g][b] + s->n[g][b]) {
            return b;
        }
    }
    return -1;
}

long sg_segs_minblock(const sg_segs_t *s, int g)
{
    long m = s->n[g][0];
    int b;
    for (b = 1; b < s->nb[g]; b++) {
        m = s->n[g][b] < m ? s->n[g][b] : m;
    }
    return m;
}

int sg_twin_static(const sg_chmodel_t *m, int ch, const sg_feat_cfg_t *fc, const sg_segs_t *segs, double q, int S,
                   uint32_t seed0, const sg_plist_t pl[SG_NSEG], double *vals[SG_NSEG])
{
    int runs = (S + FNAV_IMUERR_NCH - 1) / FNAV_IMUERR_NCH, r, j, g, rc = 0;
    const long N = segs->n[SG_FULL][0];
    sg_segacc_t *acc = (sg_segacc_t *)calloc((size_t)SG_NSEG * FNAV_IMUERR_NCH, sizeof *acc);
    double *tmp = NULL;
    size_t cap = 0;
    if (acc == NULL) {
        return -1;
    }
    for (g = 0; g < SG_NSEG; g++) {
        cap = pl[g].n > cap ? pl[g].n : cap;
    }
    tmp = (double *)malloc((cap + 16) * sizeof *tmp);
    if (tmp == NULL) {
        free(acc);
        return -1;
    }
    for (r = 0; r < runs && rc == 0; r++) {
        fnav_imuerr_config_t cfg;
        fnav_imuerr_t e;
        long k;
        int blk[SG_NSEG];
        if (sg_model_imuerr(m, fc->rate_hz, seed0 + (uint32_t)r, &cfg) != 0 || fnav_imuerr_init(&e, &cfg) != FNAV_OK) {
            rc = -1;
            break;
        }
        for (g = 0; g < SG_NSEG && rc == 0; g++) {
            for (j = 0; j < FNAV_IMUERR_NCH; j++) {
                if (sg_segacc_init(&acc[g * FNAV_IMUERR_NCH + j], fc, segs, g, q) != 0) {
                    rc = -1;
                }
            }
        }
        for (k = 0; k < N && rc == 0; k++) {
            fnav_sample_t s;
            memset(&s, 0, sizeof s);
            for (j = 0; j < 3; j++) {
                s.accel_mps2[j] = (fnav_real_t)m->mean;
                s.gyro_rps[j] = (fnav_real_t)m->mean;
            }
            if (fnav_imuerr_apply(&e, &s) != FNAV_OK) {
                rc = -1;
                break;
            }
            for (g = 0; g < SG_NSEG; g++) {
                blk[g] = sg_segs_block(segs, g, k);
            }
            for (j = 0; j < FNAV_IMUERR_NCH; j++) {
                double x = (double)(j < 3 ? s.accel_mps2[j] : s.gyro_rps[j - 3]);
                for (g = 0; g < SG_NSEG; g++) {
                    if (blk[g] >= 0) {
                        sg_segacc_push(&acc[g * FNAV_IMUERR_NCH + j], blk[g], x);
                    }
                }
            }
        }
        for (j = 0; j < FNAV_IMUERR_NCH && rc == 0; j++) {
            int sidx = r * FNAV_IMUERR_NCH + j;
            for (g = 0; g < SG_NSEG; g++) {
                long cnt = sg_segacc_finish(&acc[g * FNAV_IMUERR_NCH + j], ch, NULL, tmp, cap + 16);
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
            sg_segacc_free(&acc[g]);
        }
    }
    free(tmp);
    free(acc);
    return rc;
}
