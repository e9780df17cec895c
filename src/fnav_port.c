/* Port-layer call helpers, status strings and the build tag (no OS calls here). */
#include "footnav/fnav_port.h"

const char *fnav_status_str(fnav_status_t status)
{
    switch (status) {
    case FNAV_OK: return "ok";
    case FNAV_END: return "end of input";
    case FNAV_AGAIN: return "no data yet";
    case FNAV_E_ARG: return "invalid argument";
    case FNAV_E_CONFIG: return "invalid configuration";
    case FNAV_E_NANINF: return "NaN or Inf in input";
    case FNAV_E_RANGE: return "value out of range";
    case FNAV_E_DECOMP: return "matrix factorisation failed";
    case FNAV_E_STATE: return "invalid call in this state";
    case FNAV_E_TIME: return "timestamp out of order";
    case FNAV_E_SIZE: return "size mismatch";
    case FNAV_E_IO: return "I/O error";
    case FNAV_E_FORMAT: return "malformed input";
    case FNAV_E_CRC: return "integrity check failed";
    case FNAV_E_TRUNCATED: return "input truncated";
    case FNAV_E_UNSUPPORTED: return "unsupported";
    case FNAV_E_DIVERGED: return "estimator diverged";
    case FNAV_E_BUILD: return "built with other layout options or flags than the library";
    }
    return "unknown status";
}

uint64_t fnav_build_tag(void)
{
    return FNAV_BUILD_TAG;
}

fnav_status_t fnav_port_read(const fnav_port_t *port, fnav_sample_t *sample)
{
    if (port == NULL || sample == NULL) {
        return FNAV_E_ARG;
    }
    if (port->read_sample == NULL) {
        return FNAV_E_UNSUPPORTED;
    }
    return port->read_sample(port->ctx, sample);
}

fnav_status_t fnav_port_write_nav(const fnav_port_t *port, const fnav_nav_frame_t *frame)
{
    if (port == NULL || frame == NULL) {
        return FNAV_E_ARG;
    }
    if (port->write_nav == NULL) {
        return FNAV_OK;
    }
    return port->write_nav(port->ctx, frame);
}

void fnav_port_log(const fnav_port_t *port, fnav_log_level_t level, const char *msg)
{
    if (port != NULL && port->log != NULL && msg != NULL) {
        port->log(port->ctx, level, msg);
    }
}

int64_t fnav_port_now_ns(const fnav_port_t *port)
{
    if (port == NULL || port->now_ns == NULL) {
        return 0;
    }
    return port->now_ns(port->ctx);
}
