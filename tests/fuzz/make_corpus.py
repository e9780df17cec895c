#!/usr/bin/env python3
"""Build the committed seed corpora of the fuzz targets (tests/fuzz/corpus/).

Log reader seeds are the first lines of each data set in ../shared/data whose
licence allows copying (MIT, ISC, BSD, CC BY; sources and licences in
corpus/README.md), synthetic stand-ins for the others (ADIS: CC BY-NC-SA;
IPOL: AGPL; the pyshoe vicon trials, whose UofT PyShoe licence the MIT
repository does not restate: their header line with made-up rows), and the
golden .bin vector. The first byte of a log seed selects the format (see
fuzz_log_reader.c).

  /usr/bin/python3 tests/fuzz/make_corpus.py [DATA_DIR]
"""
import gzip
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, '..', 'shared', 'data')
FMT = {'auto': 0, 'bin': 1, 'csv': 2, 'gx2': 3, 'openshoe820': 4, 'ngimu': 5, 'pyshoe': 6,
       'ipol': 7, 'adis': 8, 'square2': 9, 'mtmanager': 10, 'picoquake': 11}

def head(rel, lines):
    with open(os.path.join(DATA, rel), 'rb') as f:
        return b''.join(f.readline() for _ in range(lines))

def put(target, name, data):
    d = os.path.join(HERE, 'corpus', target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), 'wb') as f:
        f.write(data)

def nav_slow_gait():
    """A navigator seed (fuzz_nav.c) that reaches the cycle-scaled shortest
    ZUPT run and its lock-in guard: option byte AR(1) bias model, lever,
    still lead-in, 100 Hz, min_zupt_cycle 0.025 (the default: bit 7 clear);
    then seven 2 s gait cycles of 13-byte records (regular time code 128, accel at 2048 LSB/g,
    gyro at 16.384 LSB/(deg/s)): 0.6 s still, 1.4 s of swing with a 50 ms
    still dip in late swing (a raw run of 3 samples: rejected with the 5 of
    the 2 s cycle, a ZUPT without), then four 0.6 s cycles whose stances are
    60 ms (raw runs of 4, under the 5 the 2 s cycles ask for: the lock-in
    case, which the guard ends); a constant yaw rate keeps the swing from
    passing for a stance. Replayed as a CSV (t,ax..gz in SI, after a 2 s
    still lead-in): 7 strides of 2 s either way, 444 ZUPT samples with
    min_zupt_cycle 0, 418 with 0.025 (the dips rejected)."""
    import math
    import struct
    out = bytearray([1 | 2 | 16])
    def rec(a, g):
        out.extend(struct.pack('<B6h', 128, *[max(-32000, min(32000, int(round(v)))) for v in a + g]))
    still = ([0.0, 0.0, -2048.0], [0.0, 0.0, 0.0])
    def swing(n, dip_at=None):
        for k in range(n):
            if dip_at is not None and dip_at <= k < dip_at + 5:
                rec(*still)
                continue
            ph = 2.0 * math.pi * k / n
            rec([2048.0 * math.sin(ph), 200.0 * math.sin(2 * ph), -2048.0 + 1500.0 * math.sin(ph)],
                [300.0 * math.sin(3 * ph), 16.384 * 300.0 * math.sin(ph), 16.384 * 150.0])
    for _ in range(7):
        for _ in range(60):
            rec(*still)
        swing(140, dip_at=110)
    for _ in range(4):
        for _ in range(6):
            rec(*still)
        swing(54)
    for _ in range(60):
        rec(*still)
    return bytes(out)

def main():
    seeds = [
        ('gx2', 'openshoe_gx2/Measurement_100521_2_data_inert.txt', 12),   # ISC
        ('openshoe820', 'openshoe_c_820hz/OpenShoeDataSet.txt', 12),        # CC BY 4.0
        ('ngimu', 'xio_ngimu_gait/short_walk.csv', 12),                     # MIT
        ('square2', 'openshoe_square2/square2_u.csv', 12),                  # BSD-2
    ]
    for fmt, rel, n in seeds:
        text = head(rel, n)
        put('log_reader', fmt + '_auto', bytes([FMT['auto']]) + text)
        put('log_reader', fmt + '_forced', bytes([FMT[fmt] | 0x80]) + text)
    # the vicon trials' column names with made-up rows (their data's own
    # licence is not restated by the MIT repository that carries them)
    pyshoe = head('pyshoe_vicon_llio/vicon_3dmgx3/2017-11-22-11-22-03_imu.csv', 1)
    for k in range(11):
        t = 0.005 * (k + 1)
        pyshoe += ('%.6f,%.6f,%.6f,%.6f,%.7f,%.7f,%.7f,%.7f,%.7f\n' % (
            t, -2.78 + 0.01 * k, 0.30 - 0.002 * k, -9.35 + 0.003 * k, 0.004 - 0.0003 * k,
            0.012 - 0.001 * k, -0.008 + 0.0007 * k, -0.0006 - 1e-6 * k, -0.0005 + 2e-6 * k)).encode()
    put('log_reader', 'pyshoe_auto', bytes([FMT['auto']]) + pyshoe)
    put('log_reader', 'pyshoe_forced', bytes([FMT['pyshoe'] | 0x80]) + pyshoe)
    put('log_reader', 'ipol_synthetic', bytes([FMT['auto']]) +
        b'Acquisition frequency: 100 Hz\n'
        b'PacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n'
        b'0.0\t5.0\t0.4\t8.9\t-0.002\t0.008\t-0.017\t-0.6\t0.0\t-0.4\n'
        b'1.0\t5.1\t0.4\t8.9\t-0.010\t0.008\t-0.015\t-0.6\t0.0\t-0.4\n'
        b'4.0\t5.0\t0.5\t8.8\t-0.011\t0.009\t-0.016\t-0.6\t0.0\t-0.4\n')
    # Xsens MT Manager exports (synthetic): a preamble, both counters about
    # to wrap, a NaN row; and a comma-separated one with NaN SampleTimeFine,
    # whose counter then needs the stated rate
    put('log_reader', 'mtmanager_synthetic', bytes([FMT['auto']]) +
        b'// General information:\n//  MT Manager version: 2022.2.0\n// Device information:\n'
        b'//  ProductCode: MTW2-3A7G6\n// Coordinate system: ENU\n'
        b'PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tRoll\tPitch\tYaw\n'
        b'65534\t4294967096\t0.07\t-0.01\t9.98\t0.002\t-0.0004\t0.006\t-0.25\t0.21\t-137.2\n'
        b'65535\t4294967196\tNaN\tNaN\tNaN\tNaN\tNaN\tNaN\t-0.25\t0.21\t-137.2\n'
        b'0\t0\t0.07\t-0.01\t9.98\t0.002\t-0.0004\t0.006\t-0.25\t0.21\t-137.2\n')
    put('log_reader', 'mtmanager_forced', bytes([FMT['mtmanager'] | 0x80]) +
        b'// Update Rate: 100.0Hz\r\nGyr_Z,Gyr_Y,Gyr_X,Acc_Z,Acc_Y,Acc_X,SampleTimeFine,PacketCounter\r\n'
        b'0.3,0.2,0.1,9.7,-0.5,0.25,NaN,7\r\n0.3,0.2,0.1,9.7,-0.5,0.25,NaN,8\r\n')
    adis = (b'gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n'
            b'-0.05,-0.3,0.7,-0.006,0,-1.015\n0.35,-0.3,0.45,-0.01,0,-1.018\n')
    put('log_reader', 'adis_synthetic', bytes([FMT['auto']]) + adis)
    put('log_reader', 'adis_synthetic_gz', bytes([FMT['auto'] | 0x40]) + gzip.compress(adis, mtime=0))
    # separators of the headerless 820 Hz file and of the ipol file that
    # detection and the readers accept (docs/log-format.md, Importers)
    os820 = head('openshoe_c_820hz/OpenShoeDataSet.txt', 6)
    put('log_reader', 'openshoe820_trailing_comma', bytes([FMT['auto']]) + os820.replace(b'\r\n', b',\r\n'))
    put('log_reader', 'openshoe820_tabs', bytes([FMT['auto'] | 0x80]) + os820.replace(b',', b'\t'))
    put('log_reader', 'openshoe820_blanks', bytes([FMT['openshoe820']]) + os820.replace(b',', b'  '))
    put('log_reader', 'ipol_comma_blank_first', bytes([FMT['auto']]) +
        b'\nAcquisition frequency: 100 Hz\n'
        b'PacketCounter,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z\n'
        b'0.0,5.0,0.4,8.9,-0.002,0.008,-0.017\n1.0,5.1,0.4,8.9,-0.010,0.008,-0.015\n')
    # GX2 whose timer restarts on the first interval (bridged with Freq.)
    gx2 = head('openshoe_gx2/Measurement_100521_2_data_inert.txt', 12).split(b'\r\n')
    put('log_reader', 'gx2_first_restart', bytes([FMT['auto']]) + b'\r\n'.join(gx2[:5] + gx2[9:]))
    put('log_reader', 'csv_temp', bytes([FMT['csv']]) +
        b't,ax,ay,az,gx,gy,gz,temp\n0,0.1,0.2,-9.8,0.01,0.02,0.03,21.5\n0.005,0.1,0.2,-9.8,0.01,0.02,0.03,21.5\n')
    # stamps written as dates and times, a zone in the time column's name
    put('log_reader', 'csv_datetime', bytes([FMT['auto']]) +
        b'Timestamp (UTC),ax,ay,az,gx,gy,gz\n2024-05-01T14:00:00.0025+02:00,0.1,0.2,-9.8,0.01,0.02,0.03\n'
        b'2024/05/01 12:00:00.0075Z,0.1,0.2,-9.8,0.01,0.02,0.03\n23:59:59,0.1,0.2,-9.8,0.01,0.02,0.03\n')
    # blank-separated columns, a date and its time parted by blanks
    put('log_reader', 'blank_datetime', bytes([FMT['auto']]) +
        b't ax ay az gx gy gz\n2024-05-01 12:00:00.0025 0.1 0.2 -9.8 0.01 0.02 0.03\n'
        b'2024/05/01  \t 12:00:00.0075Z  0.1 0.2 -9.8 0.01 0.02 0.03\n')
    # Shimmer's Consensys export: separator line, <device>_<signal>_CAL, units row
    put('log_reader', 'csv_consensys', bytes([FMT['auto']]) +
        b'"sep=\t"\r\nP_Timestamp_Unix_CAL\tP_Accel_LN_X_CAL\tP_Accel_LN_Y_CAL\tP_Accel_LN_Z_CAL\t'
        b'P_Accel_WR_X_CAL\tP_Accel_WR_Y_CAL\tP_Accel_WR_Z_CAL\tP_Gyro_X_CAL\tP_Gyro_Y_CAL\tP_Gyro_Z_CAL\t\r\n'
        b'ms\tm/(s^2)\tm/(s^2)\tm/(s^2)\tm/(s^2)\tm/(s^2)\tm/(s^2)\tdeg/s\tdeg/s\tdeg/s\t\r\n'
        b'1595933810034.18\t1.5\t0.2\t-9.8\t2.5\t0.3\t-9.7\t10\t20\t30\t\r\n'
        b'1595933810039.18\t1.5\t0.2\t-9.8\t2.5\t0.3\t-9.7\t10\t20\t30\t\r\n')
    # AndroSensor's CSV (semicolons, "Time since start in ms ", near
    # misses beside the axes) and a clock's name, "epoch (ms)"
    put('log_reader', 'csv_androsensor', bytes([FMT['auto']]) +
        'ACCELEROMETER X (m/s\u00b2);ACCELEROMETER Y (m/s\u00b2);ACCELEROMETER Z (m/s\u00b2);'
        'LINEAR ACCELERATION X (m/s\u00b2);GYROSCOPE X (rad/s);GYROSCOPE Y (rad/s);GYROSCOPE Z (rad/s);'
        'Time since start in ms ;YYYY-MO-DD HH-MI-SS_SSS\n'
        '0.1;0.2;9.8;0;0.01;0.02;0.03;10;2024-05-01 12-00-00_010\n'
        '0.1;0.2;9.8;0;0.01;0.02;0.03;15;2024-05-01 12-00-00_015\n'.encode('utf-8'))
    put('log_reader', 'csv_epoch_ms', bytes([FMT['auto']]) +
        b'epoch (ms),elapsed (s),acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n1700000000000,0.000,0.1,0.2,-9.8,0.01,0.02,0.03\n'
        b'1700000000005,0.005,0.1,0.2,-9.8,0.01,0.02,0.03\n')
    # PLab PicoQuake's acquisition CSV (synthetic, as its to_csv writes
    # it): the preamble with the rate, a skipped count
    pq = (b'# PLab PicoQuake Data\n# Time: 2024-04-21 15:54:46.333682, Device: D4E9 (E6632891E36F2029), FW: 1.0\n'
          b'# Num. samples: 3, Duration: 0.0015 s\n'
          b'# Config: data_rate = 2000.0 Hz, filter = 488 Hz, acc_range = 4 g, gyro_range = 250.0 dps\n'
          b'# Integrity: False, Skipped samples: 1\ncount,a_x,a_y,a_z,g_x,g_y,g_z\n'
          b'1,0.96,0.41,0.53,19.71,123.73,93.19\n2,0.72,0.51,0.53,14.6,105.12,77.13\n4,0.77,0.5,0.52,13.9,99.1,70.2\n')
    put('log_reader', 'picoquake_auto', bytes([FMT['auto']]) + pq)
    put('log_reader', 'picoquake_forced', bytes([FMT['picoquake'] | 0x80]) + pq)
    # data_rate = 2 (PLab's library's 12.5 Hz setting: refused) and a second Config line
    # (not read); a data_rate that is no rate, read whole with an
    # --input-rate (0x20: 123 Hz) that replaces it
    put('log_reader', 'picoquake_rate2_twice', bytes([FMT['auto']]) +
        pq.replace(b'data_rate = 2000.0 Hz', b'data_rate = 2').replace(
            b'# Integrity', b'# Config: data_rate = 100.0 Hz, filter = 42 Hz\n# Integrity'))
    put('log_reader', 'picoquake_bad_rate_given', bytes([FMT['picoquake'] | 0x80 | 0x20]) +
        pq.replace(b'data_rate = 2000.0 Hz', b'data_rate = fast'))
    # Physics Toolbox Sensor Suite: the g-force in g beside the app's
    # linear acceleration (not read)
    put('log_reader', 'csv_physics_toolbox', bytes([FMT['auto']]) +
        b'time,gFx,gFy,gFz,ax,ay,az,wx,wy,wz,p,Bx,By,Bz\n0.078756,-0.0488,0.3217,1.0039,0.01,-0.02,0.03,0.1,0.2,0.3,'
        b'1013.2,10,20,30\n0.083827,-0.0490,0.3215,1.0041,0.01,-0.02,0.03,0.1,0.2,0.3,1013.2,10,20,30\n')
    # a ROS sensor_msgs/Imu topic as rostopic echo -p writes it; EuRoC's
    # ASL format (a commented header, units as negative powers)
    put('log_reader', 'csv_ros', bytes([FMT['auto']]) +
        b'%time,field.header.seq,field.header.stamp,field.header.frame_id,field.angular_velocity.x,'
        b'field.angular_velocity.y,field.angular_velocity.z,field.linear_acceleration.x,field.linear_acceleration.y,'
        b'field.linear_acceleration.z\n1700000000001234567,0,1700000000000000000,imu,0.5,-0.25,0.125,1.5,-2.5,9.75\n'
        b'1700000000006234567,1,1700000000002500000,imu,0.5,-0.25,0.125,1.5,-2.5,9.75\n')
    put('log_reader', 'csv_ros_split', bytes([FMT['auto']]) +
        b'Time,header.stamp.secs,header.stamp.nsecs,angular_velocity.x,angular_velocity.y,angular_velocity.z,'
        b'linear_acceleration.x,linear_acceleration.y,linear_acceleration.z\n'
        b'1700000000.0012,1700000000,999000000,0.5,-0.25,0.125,1.5,-2.5,9.75\n'
        b'1700000000.0062,1700000001,1500000,0.5,-0.25,0.125,1.5,-2.5,9.75\n')
    put('log_reader', 'csv_euroc', bytes([FMT['auto']]) +
        b'#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],'
        b'a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\r\n1403636579758555392,-0.0991,0.1424,0.0628,8.1334,-0.6456,-2.7136\r\n'
        b'1403636579763555584,-0.0991,0.1431,0.0628,8.1334,-0.6456,-2.7136\r\n')
    # Kalibr's IMU CSV: the stamp in ns, omega (rad/s) then alpha (m/s^2)
    put('log_reader', 'csv_kalibr', bytes([FMT['auto']]) +
        b'timestamp,omega_x,omega_y,omega_z,alpha_x,alpha_y,alpha_z\n1385030208736607488,0.5,-0.2,-0.1,8.1,-1.9,-3.3\n'
        b'1385030208741607488,0.5,-0.1,-0.1,8.1,-1.9,-3.3\n')
    # WitMotion's export: tabs, a date with one-digit month, day and hour
    put('log_reader', 'csv_witmotion', bytes([FMT['auto']]) +
        'Time\tDevice name\tAcceleration X(g)\tAcceleration Y(g)\tAcceleration Z(g)\tAngular velocity X(\u00b0/s)\t'
        'Angular velocity Y(\u00b0/s)\tAngular velocity Z(\u00b0/s)\tAngle X(\u00b0)\n'.encode() +
        b'2023-3-21 9:05:23.334\tWT901BLE68(E4:5A)\t0.01\t-0.02\t1.0\t0.0\t0.06\t0.0\t0.1\n'
        b'2023-3-21 9:05:23.344\tWT901BLE68(E4:5A)\t0.01\t-0.02\t1.0\t0.0\t0.06\t0.0\t0.1\n')
    # SensorLog (iOS): the accelerometer read negated, g and rad/s
    put('log_reader', 'csv_sensorlog', bytes([FMT['auto']]) +
        b'loggingTime(txt),loggingSample(N),accelerometerTimestamp_sinceReboot(s),accelerometerAccelerationX(G),'
        b'accelerometerAccelerationY(G),accelerometerAccelerationZ(G),gyroTimestamp_sinceReboot(s),'
        b'gyroRotationX(rad/s),gyroRotationY(rad/s),gyroRotationZ(rad/s),motionUserAccelerationX(G)\n'
        b'2019-03-19 13:12:49.592 +0100,0,266943.391,0.01,-0.02,-1.0,266943.392,0.001,0.002,0.003,0.0\n'
        b'2019-03-19 13:12:49.602 +0100,1,266943.401,0.01,-0.02,-1.0,266943.402,0.001,0.002,0.003,0.0\n')
    # semicolons and decimal commas, read as decimals (decimal_commas_read)
    put('log_reader', 'csv_semicolon_decimal_comma', bytes([FMT['auto']]) +
        b't;ax;ay;az;gx;gy;gz\n0;0,5;-0,2;9,8;0,1;0,2;0,3\n0,01;1.234,5;0;9,8e+00;0;0;0\n')
    # a row of units under a plain header (units_row)
    put('log_reader', 'csv_units_row', bytes([FMT['auto']]) +
        b'time,acc_x,acc_y,acc_z,gyro_x,gyro_y,gyro_z\ns,g,g,g,deg/s,deg/s,deg/s\n'
        b'0,0.01,-0.02,1.0,0.1,0.2,0.3\n0.01,0.01,-0.02,1.0,0.1,0.2,0.3\n')
    # several time names, the first naming its unit read (hx_names_match)
    put('log_reader', 'csv_two_times', bytes([FMT['auto']]) +
        b'Timestamp (ms),Time since start in ms,ax,ay,az,gx,gy,gz\n1700000000000.5,0,0.1,0.2,9.8,0,0,0\n'
        b'1700000000010.5,10,0.1,0.2,9.8,0,0,0\n')
    # a phone export for --columns (fuzz_log_reader.c: the map and the units
    # by the input's size): zeros after the last value make the size 7 mod
    # 16, the phone map (size / 4 % 4 == 1) and time=ns (size % 4 == 3)
    phone = (b'timestamp_ns,acc_x,acc_y,acc_z,gyro_x,gyro_y,gyro_z\n'
             b'1764500000000000000,0.01,0.02,-1.0,0.5,1.0,1.5\n'
             b'1764500000005000000,0.01,0.02,-1.0,0.5,1.0,1.5')
    pad = 0
    while (1 + len(phone) + pad + 1) % 16 != 7:
        pad += 1
    put('log_reader', 'csv_columns', bytes([FMT['csv']]) + phone + b'0' * pad + b'\n')
    with open(os.path.join(ROOT, 'vectors', 'logformat', 'sample_v1.bin'), 'rb') as f:
        b = f.read()
    put('log_reader', 'bin_golden', bytes([FMT['auto']]) + b)
    put('log_reader', 'bin_golden_whole', bytes([FMT['bin'] | 0x80]) + b)
    put('profile', 'navchip', b'''# footnav sensor profile
format = footnav-profile 1
name = navchip
rate_hz = 200
accel_noise_mps2_rthz = 0.00074 0.00064 0.0005
accel_tau_s = 10 10 10
accel_bias_sigma_mps2 = 1.3e-05 9.7e-06 7.3e-06
gyro_noise_rps_rthz = 5.7e-05 6.4e-05 7.3e-05
gyro_tau_s = 5 5 50
gyro_bias_sigma_rps = 1.5e-06 1.1e-06 5.9e-07
''')
    put('nav', 'slow_gait_cycle', nav_slow_gait())
    # merge (fuzz_merge.c): the first byte's bit 0 the sensor (1 gyro), bits
    # 1-2 --units (1 time=ns, 2 accel=g,gyro=deg/s, 3 time=ms); a MetaWear
    # accelerometer file, a MetaWear gyroscope file with ISO dates and no
    # epoch, a phyphox gyroscope file with semicolons and
    # decimal commas, Sensor Logger's ns since the epoch with bare z,y,x,
    # and tabs with a comment, a repeated stamp, a blank line and a bad row
    put('merge', 'metawear_acc', b'\x00epoch (ms),time (-13:00),elapsed (s),x-axis (g),y-axis (g),z-axis (g)\n'
        b'1700000000000,2023-11-14T22.13.20.000,0.000,-0.49,0.24,0.83\n'
        b'1700000000010,2023-11-14T22.13.20.010,0.010,-0.48,0.25,0.82\n'
        b'1700000000020,2023-11-14T22.13.20.020,0.020,-0.47,0.26,0.81\n')
    put('merge', 'metawear_iso_gyr', b'\x05time (-13:00),elapsed (s),x-axis (deg/s),y-axis (deg/s),z-axis (deg/s)\n'
        b'2023-11-14T09:13:20.025,0.000,0.10,-0.41,0.01\n2023-11-14T09:13:20.027,0.002,0.22,-0.59,0.07\n'
        b'2023-11-14T09:13:20.030,0.005,0.31,-0.66,0.09\n')
    put('merge', 'metabase_dotted_gyr', b'\x01time (-13:00),elapsed (s),x-axis (deg/s),y-axis (deg/s),z-axis (deg/s)\n'
        b'2023-11-14T9.13.20.025,0.000,0.10,-0.41,0.01\n2023-11-14T9.13.20.027,0.002,0.22,-0.59,0.07\n')
    put('merge', 'polar_acc', b'\x00Phone timestamp;sensor timestamp [ns];X [mg];Y [mg];Z [mg]\n'
        b'2023-01-12T14:41:33.466;726849693410011776;-12;25;1001\n2023-01-12T14:41:33.476;726849693420011776;-11;24;1002\n')
    put('merge', 'phyphox_semi_gyr', b'\x01"Time (s)";"Gyroscope x (rad/s)";"Gyroscope y (rad/s)";"Gyroscope z (rad/s)"\n'
        b'0,000;0,5;-0,25;0,125\n0,010;0,6;-0,35;0,225\n0,020;0,7;-0,45;0,325\n')
    put('merge', 'slog_acc_ns', b'\x03time,seconds_elapsed,z,y,x\n1733300000000000000,0.0,9.8,0.1,0.2\n'
        b'1733300000010000000,0.01,9.7,0.2,0.3\n1733300000020000000,0.02,9.6,0.3,0.4\n')
    put('merge', 'tab_dup_bad', b'\x01t\tgyr_x\tgyr_y\tgyr_z\n# a comment\n0.0\t1\t2\t3\n0.0\t1\t2\t3\n0.01\t2\t3\t4\n\n'
        b'0.02\toops\t4\t5\n')
    # Physics Toolbox's iOS g-force file: a date and time, the g-force in g
    put('merge', 'ptb_ios_acc', b'\x00time,gFx,gFy,gFz,gFTotal\n2018-10-03 17:23:55.4640,0.035,-0.517,-0.821,0.971\n'
        b'2018-10-03 17:23:55.4690,0.035,-0.517,-0.821,0.971\n2018-10-03 17:23:55.4740,0.036,-0.516,-0.820,0.970\n')
    print('corpus written under', os.path.join(HERE, 'corpus'))

if __name__ == '__main__':
    main()
