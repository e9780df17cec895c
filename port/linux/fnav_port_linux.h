/**
 * @file fnav_port_linux.h
 * @brief Linux port: replays a log file (any format hx_log reads) as the
 *        sample source, writes navigation frames as CSV rows, uses
 *        CLOCK_MONOTONIC and logs to stderr.
 */
#ifndef FNAV_PORT_LINUX_H
#define FNAV_PORT_LINUX_H

#include <stdio.h>
#include "footnav/fnav_port.h"
#include "hx_log.h"

/** Context of the Linux port; owned by the caller. */
typedef struct {
    hx_reader_t *reader;        /**< sample source (NULL: none) */
    FILE *nav_csv;              /**< sink for navigation frames (NULL: none) */
    int header_written;         /**< CSV header already written */
    int64_t t0_ns;              /**< time of the first sample, for relative time */
    int have_t0;
    long samples;               /**< samples delivered */
    long frames;                /**< frames written */
    fnav_log_level_t min_level; /**< messages below this level are dropped */
    fnav_status_t last_status;  /**< last status of the reader */
    int write_errno;            /**< errno of the sink's first failed write (0: none or not said) */
} fnav_linux_port_ctx_t;

/** Set up @p port with the Linux callbacks over @p ctx. */
void fnav_linux_port_init(fnav_port_t *port, fnav_linux_port_ctx_t *ctx, hx_reader_t *reader, FILE *nav_csv);

/** Columns of the trajectory CSV written by the sink (docs/harness.md). */
#define FNAV_LINUX_NAV_CSV_HEADER                                                              \
    "t,x,y,z,vx,vy,vz,roll,pitch,yaw,bgx,bgy,bgz,bax,bay,baz,stance,zupt,health,"             \
    "P_att_x,P_att_y,P_att_z,P_vel_x,P_vel_y,P_vel_z,P_pos_x,P_pos_y,P_pos_z,"                \
    "P_bg_x,P_bg_y,P_bg_z,P_ba_x,P_ba_y,P_ba_z,lever_x,lever_y,lever_z,aligned"

#endif /* FNAV_PORT_LINUX_H */
