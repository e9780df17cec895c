/**
 * @file fnav_cm_fw_config.h
 * @brief Library options of the firmware images (`make firmware`,
 *        `make firmware-bench`), passed as FNAV_CONFIG_FILE so that the core
 *        and the port see the same sizes. Everything not set here keeps its
 *        default from fnav_config.h. RAM per object in float32: docs/firmware.md.
 */
#ifndef FNAV_CM_FW_CONFIG_H
#define FNAV_CM_FW_CONFIG_H

/* Welch: the paper's 64-sample Hamming segments are all the sensor runs
 * (the harness keeps 1024 for its segment-length study). */
#define FNAV_WELCH_MAX_NFFT 64

#endif /* FNAV_CM_FW_CONFIG_H */
