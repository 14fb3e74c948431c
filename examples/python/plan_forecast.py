#!/usr/bin/env python3
"""Plan a glider route on a NetCDF forecast and draw the route, the currents and the isochrones.

Usage: plan_forecast.py [OUT_DIR]     (default out/python_forecast; writes forecast_route.png and the pilot's files)
Needs the package on PYTHONPATH (the build tree's python/ folder, or installed with cmake --install).
"""
import os
import sys

import matplotlib

matplotlib.use(os.environ.get("MPLBACKEND", "Agg"))
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ompl_glider  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
out_dir = sys.argv[1] if len(sys.argv) > 1 else "out/python_forecast"
os.makedirs(out_dir, exist_ok=True)

# The forecast, read with the command line's options (here: bicubic in space), and the trip.
forecast = ompl_glider.Field.netcdf(os.path.join(HERE, "..", "labrador_forecast.nc"), xy_interpolation="bicubic")
r = ompl_glider.plan(field=forecast, start=(-52.7, 47.9), goal=(-51.5, 48.45), speed=0.3,
                     departure="2026-03-15T06:00:00Z", grid_size=4000, isochrones=True)
print(f"{r.planner}: {r.status}, {r.travel_time / 3600:.2f} h, {len(r.route.x)} waypoints")

fig, ax = plt.subplots(figsize=(8, 6))
c = r.current_grid(n=30)
speed = np.hypot(c["u"], c["v"])
ax.pcolormesh(c["lon"], c["lat"], speed, shading="auto", cmap="Blues")
ax.quiver(c["lon"], c["lat"], c["u"], c["v"], color="0.3", width=0.002)
for k, iso in enumerate(r.isochrones):
    for line in iso["lonlat"]:
        ax.plot(line[:, 0], line[:, 1], color="tab:orange", lw=0.8, label="isochrones" if k == 0 else None)
ax.plot(r.route.lon, r.route.lat, "o-", color="tab:red", ms=3, label=f"route, {r.travel_time / 3600:.1f} h")
ax.set_xlabel("longitude")
ax.set_ylabel("latitude")
ax.set_title("ZA*TVE on the Labrador forecast, departing 2026-03-15 06:00 UTC")
handles, labels = ax.get_legend_handles_labels()
ax.legend(dict(zip(labels, handles)).values(), dict(zip(labels, handles)).keys(), loc="lower right")
png = os.path.join(out_dir, "forecast_route.png")
fig.savefig(png, dpi=100)
print("wrote", png)
for path in r.write(os.path.join(out_dir, "pilot")):
    print("wrote", path)
assert r.solved and os.path.getsize(png) > 0
