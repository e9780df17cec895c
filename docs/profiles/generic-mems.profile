# footnav sensor profile (docs/profile-format.md)
# Generic industrial MEMS IMU (3DM-GX5 / MTi class), literature reading of the
# AR(1) model (docs/navigation.md, "Bias model"): the bias stationary sd is the
# bias instability itself (gyro 10 deg/h = 4.8e-5 rad/s, accelerometer 50 ug =
# 4.9e-4 m/s^2), correlation time 100 s; white noise as the NavChip (Table IV).
# Datasheet-class values, not identified from a static log of the sensors in
# ../shared/data (none exists); used by `harness eval` for the bias-model
# experiment.
format = footnav-profile 1
name = generic-mems
rate_hz = 200
accel_noise_mps2_rthz = 7.4e-4 6.4e-4 5.0e-4
accel_tau_s = 100 100 100
accel_bias_sigma_mps2 = 4.9e-4 4.9e-4 4.9e-4
gyro_noise_rps_rthz = 5.8e-5 6.5e-5 7.3e-5
gyro_tau_s = 100 100 100
gyro_bias_sigma_rps = 4.8e-5 4.8e-5 4.8e-5
