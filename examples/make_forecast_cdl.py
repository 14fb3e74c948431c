#!/usr/bin/env python3
"""Writes examples/labrador_forecast.cdl: a small synthetic 5-day current forecast off Newfoundland in CF NetCDF
form (lon, lat, depth, time; u/v in m/s with _FillValue on an island). Build the NetCDF file with
    ncgen -o examples/labrador_forecast.nc examples/labrador_forecast.cdl
With --nowcast it writes examples/labrador_nowcast.cdl instead: "another model" of the same ocean for flying plans
in: the jet 0.1 degree further north and 20 % weaker, the tide 1.5 h later and 25 % stronger, the
drift reversed; its times in minutes since 2026-03-15 06:00 every 3 h (another origin and units).
The field: an eastward shelf-break jet centred at 48.2 N that weakens with depth, a semi-diurnal tide (M2,
12.42 h) and a slow northward drift that grows during the forecast."""
import math
import os
import sys

NOWCAST = "--nowcast" in sys.argv[1:]

lons = [-53.0 + 0.2 * i for i in range(11)]
lats = [47.6 + 0.12 * j for j in range(11)]
depths = [0.0, 50.0, 200.0]
times = [6.0 * k for k in range(21)]  # hours since 2026-03-15 00:00:00
if NOWCAST:
    times = [6.0 + 3.0 * k for k in range(39)]  # hours since 2026-03-15 00:00 (written as minutes since 06:00)
FILL = -999.0
jet = {0.0: 0.45, 50.0: 0.30, 200.0: 0.08}


def land(lon, lat):
    return -52.05 <= lon <= -51.75 and 48.55 <= lat <= 48.80


def uv(t, z, lat, lon):
    if land(lon, lat):
        return FILL, FILL
    centre, strength, lag, tidal, drift = (48.3, 0.8, 1.5, 1.25, -1.0) if NOWCAST else (48.2, 1.0, 0.0, 1.0, 1.0)
    core = strength * jet[z] * math.exp(-((lat - centre) / 0.25) ** 2)
    tide = tidal * 0.12 * (1.0 - z / 400.0)
    w = 2.0 * math.pi * (t - lag) / 12.42
    u = core + tide * math.cos(w)
    v = 0.6 * tide * math.sin(w) + drift * 0.04 * (t / 120.0) * math.cos(math.radians(60.0 * (lon + 53.0)))
    return round(u, 4), round(v, 4)


def block(name, values):
    out = [" %s =" % name]
    line = []
    for i, x in enumerate(values):
        line.append("%g" % x)
        if len(line) == 11:
            out.append("  " + ", ".join(line) + ("," if i + 1 < len(values) else ""))
            line = []
    if line:
        out.append("  " + ", ".join(line))
    out[-1] += " ;"
    return "\n".join(out)


us, vs = [], []
for t in times:
    for z in depths:
        for lat in lats:
            for lon in lons:
                u, v = uv(t, z, lat, lon)
                us.append(u)
                vs.append(v)

name = "labrador_nowcast" if NOWCAST else "labrador_forecast"
time_units = "minutes since 2026-03-15 06:00:00" if NOWCAST else "hours since 2026-03-15 00:00:00"
title = ("Synthetic nowcast for ompl_glider examples (another model of the forecast's ocean)" if NOWCAST
         else "Synthetic 5-day forecast for ompl_glider examples (shelf-break jet, M2 tide, island)")
written_times = [60.0 * (t - 6.0) for t in times] if NOWCAST else times
cdl = f"""netcdf {name} {{
dimensions:
 time = {len(times)} ;
 depth = {len(depths)} ;
 lat = {len(lats)} ;
 lon = {len(lons)} ;
variables:
 double time(time) ;
  time:units = "{time_units}" ;
  time:calendar = "standard" ;
  time:standard_name = "time" ;
 double depth(depth) ;
  depth:units = "m" ;
  depth:positive = "down" ;
  depth:standard_name = "depth" ;
 double lat(lat) ;
  lat:units = "degrees_north" ;
  lat:standard_name = "latitude" ;
 double lon(lon) ;
  lon:units = "degrees_east" ;
  lon:standard_name = "longitude" ;
 float u(time, depth, lat, lon) ;
  u:units = "m/s" ;
  u:standard_name = "eastward_sea_water_velocity" ;
  u:_FillValue = -999.f ;
 float v(time, depth, lat, lon) ;
  v:units = "m/s" ;
  v:standard_name = "northward_sea_water_velocity" ;
  v:_FillValue = -999.f ;

// global attributes:
  :title = "{title}" ;
  :Conventions = "CF-1.8" ;
data:
{block("time", written_times)}
{block("depth", depths)}
{block("lat", [round(x, 4) for x in lats])}
{block("lon", [round(x, 4) for x in lons])}
{block("u", us)}
{block("v", vs)}
}}
"""
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, name + ".cdl"), "w") as f:
    f.write(cdl)
