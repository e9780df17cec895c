/* Sim-to-real gap: JSON report (WORK IN PROGRESS). */
#include "hx_simgap.h"
int sg_write_json(const sg_result_t *r, const char *path, char *err, size_t err_size)
{
    (void)r;
    snprintf(err, err_size, "%s: JSON not written yet", path);
    return -1;
}
int sg_write_plots(const sg_result_t *r, const char *dir, const char *cmd)
{
    (void)r;
    (void)dir;
    (void)cmd;
    return -1;
}
