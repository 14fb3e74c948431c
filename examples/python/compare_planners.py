#!/usr/bin/env python3
"""Compare planners on the built-in Gulf Stream mission: travel time and planning time, routes on one map.

Usage: compare_planners.py [OUT_DIR]     (default out/python_planners; writes planners.png)
"""
import os
import sys

import matplotlib

matplotlib.use(os.environ.get("MPLBACKEND", "Agg"))
import matplotlib.pyplot as plt  # noqa: E402

import ompl_glider  # noqa: E402

out_dir = sys.argv[1] if len(sys.argv) > 1 else "out/python_planners"
os.makedirs(out_dir, exist_ok=True)

runs = {}
for name, settings in [("ZA*TVE", {}), ("TVE", {}), ("LevelSet", {}), ("RRTstar", {"time_limit": 5.0})]:
    r = ompl_glider.plan(planner=name, **settings)
    runs[name] = r
    print(f"{name:10s} {r.status:16s} travel time {r.travel_time:8.4f}   planning {r.planning_seconds:6.2f} s")

fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.5))
c = next(iter(runs.values())).current_grid(n=25)
ax.quiver(c["x"], c["y"], c["u"], c["v"], color="0.6")
for name, r in runs.items():
    if not r.solved:
        continue
    ax.plot(r.path["x"], r.path["y"], label=f"{name} ({r.travel_time:.3f})")
ax.set_aspect("equal")
ax.legend(fontsize=8)
ax.set_title("routes across the meandering jet")
solved = {name: r.travel_time for name, r in runs.items() if r.solved}
bx.bar(list(solved), list(solved.values()), color="tab:blue")
bx.set_ylim(min(solved.values()) * 0.95, max(solved.values()) * 1.02)
bx.set_ylabel("travel time")
fig.tight_layout()
png = os.path.join(out_dir, "planners.png")
fig.savefig(png, dpi=100)
print("wrote", png)
