#!/usr/bin/env python3
"""ctest demo.benchmark_ice: runs demo_benchmark with tiny runs, converts its logs with OMPL's
ompl_benchmark_statistics into the database Planner Arena reads, and checks that every planner is in it.
Usage: check_benchmark_demo.py DEMO OUTDIR [ompl_benchmark_statistics]"""
import os
import shutil
import sqlite3
import subprocess
import sys

demo, out = sys.argv[1], sys.argv[2]
stats = sys.argv[3] if len(sys.argv) > 3 and sys.argv[3] else shutil.which("ompl_benchmark_statistics")
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
subprocess.run([demo, out, "2", "1"], check=True)  # 2 s per run: ZA*TVE needs about 0.4 s, more on a loaded machine
logs = [os.path.join(out, f) for f in ("ice_geometric.log", "ice_control.log")]
for log in logs:
    assert os.path.getsize(log) > 0, log
    text = open(log).read()
    assert "ice_" in text, log
if not stats or not os.path.exists(stats):
    print("ompl_benchmark_statistics not found: the logs are checked, the database is not made")
    sys.exit(0)
db = os.path.join(out, "ice.db")
subprocess.run([sys.executable, stats, *logs, "-d", db], check=True)
con = sqlite3.connect(db)
planners = {name for (name,) in con.execute("SELECT name FROM plannerConfigs")}
experiments = con.execute("SELECT COUNT(*) FROM experiments").fetchone()[0]
runs = con.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
print("planners:", sorted(planners), "experiments:", experiments, "runs:", runs)
expected = ["ZA*TVE", "RRTstar", "PRM", "RRT", "SST", "KPIECE1"]
missing = [p for p in expected if not any(p in name for name in planners)]
assert not missing, f"planners missing from the database: {missing}"
assert experiments == 2 and runs == 6, (experiments, runs)
solved = con.execute("SELECT solved FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                     "WHERE plannerConfigs.name LIKE '%ZA*TVE%'").fetchone()[0]
assert solved == 1, "ZA*TVE did not solve the ice crossing"
