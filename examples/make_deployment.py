#!/usr/bin/python3
"""Writes examples/deployment_ru29/: a glider's first day on the Labrador shelf as the IOOS glider DAC writes it
(one profile NetCDF file per dive, the template's scalars time_uv, lat_uv, lon_uv, u, v with their attributes,
profile_time/lat/lon, *_qc flags, the platform variable). The depth-averaged currents are the "truth" of the
examples, labrador_nowcast.nc, averaged over 0-100 m at the middle of each dive, so that planning on the forecast
corrected by them plans in an ocean closer to the one the glider flies in.

Usage: /usr/bin/python3 examples/make_deployment.py   (Debian's python3-netcdf4 and python3-numpy)"""
import os

import netCDF4
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "deployment_ru29")
T0 = 1773554400.0  # 2026-03-15T06:00:00Z


def truth_dac(nc, lon, lat, seconds):
    """The nowcast averaged over its depths at (lon, lat, time), bilinear in space and linear in time."""
    t = nc["time"][:] * 60.0 + T0  # minutes since 2026-03-15 06:00
    lons, lats = nc["lon"][:], nc["lat"][:]
    i = np.clip(np.searchsorted(lons, lon) - 1, 0, len(lons) - 2)
    j = np.clip(np.searchsorted(lats, lat) - 1, 0, len(lats) - 2)
    k = np.clip(np.searchsorted(t, seconds) - 1, 0, len(t) - 2)
    fx = (lon - lons[i]) / (lons[i + 1] - lons[i])
    fy = (lat - lats[j]) / (lats[j + 1] - lats[j])
    ft = (seconds - t[k]) / (t[k + 1] - t[k])
    out = []
    for name in ("u", "v"):
        a = np.asarray(nc[name][k:k + 2, :, j:j + 2, i:i + 2], dtype=float).mean(axis=1)
        s = (1 - fy) * ((1 - fx) * a[:, 0, 0] + fx * a[:, 0, 1]) + fy * ((1 - fx) * a[:, 1, 0] + fx * a[:, 1, 1])
        out.append(float((1 - ft) * s[0] + ft * s[1]))
    return out


def write_profile(path, when, lon, lat, u, v):
    with netCDF4.Dataset(path, "w", format="NETCDF4") as d:
        d.Conventions = "CF-1.6, Unidata Dataset Discovery v1.0"
        d.format_version = "IOOS_Glider_NetCDF_v2.0.nc"
        d.featureType = "trajectoryProfile"
        d.createDimension("traj_strlen", 20)
        traj = d.createVariable("trajectory", "S1", ("traj_strlen",))
        traj.cf_role = "trajectory_id"
        traj[:] = netCDF4.stringtochar(np.array(["ru29-20260315T0600"], dtype="S20"))
        for name, units, std, value in [
                ("profile_time", "seconds since 1970-01-01T00:00:00Z", "time", when),
                ("profile_lat", "degrees_north", "latitude", lat), ("profile_lon", "degrees_east", "longitude", lon),
                ("time_uv", "seconds since 1970-01-01T00:00:00Z", "time", when - 1800.0),
                ("lat_uv", "degrees_north", "latitude", lat - 0.002),
                ("lon_uv", "degrees_east", "longitude", lon - 0.004),
                ("u", "m s-1", "eastward_sea_water_velocity", u), ("v", "m s-1", "northward_sea_water_velocity", v)]:
            var = d.createVariable(name, "f8", (), fill_value=-999.0)
            var.units, var.standard_name = units, std
            var.assignValue(value)
        for name in ("u_qc", "v_qc"):
            q = d.createVariable(name, "i1", ())
            q.flag_values = np.array([0, 1, 2, 3, 4, 9], dtype="i1")
            q.flag_meanings = "no_qc_performed good_data probably_good_data bad_data_that_are_potentially_correctable " \
                              "bad_data missing_value"
            q.assignValue(1)
        p = d.createVariable("platform", "i4", ())
        p.id, p.type, p.wmo_id = "ru29", "platform", "4801234"


def main():
    os.makedirs(OUT, exist_ok=True)
    with netCDF4.Dataset(os.path.join(HERE, "labrador_nowcast.nc")) as nc:
        lon, lat = -52.7, 47.9
        for k in range(8):  # a dive every 3 hours, heading north-east at about 0.3 m/s over ground
            when = T0 + 3 * 3600.0 * (k + 1)
            lon, lat = lon + 0.045, lat + 0.02
            u, v = truth_dac(nc, lon - 0.004, lat - 0.002, when - 1800.0)
            write_profile(os.path.join(OUT, "ru29_%04d.nc" % (k + 1)), when, lon, lat, round(u, 4), round(v, 4))


if __name__ == "__main__":
    main()
