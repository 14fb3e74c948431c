#!/usr/bin/env python3
"""glider_plan's map.html opened in headless Chromium (check_map_html.py), offline, for three runs:

  1. the built-in mission with isochrones (planning frame, no dates);
  2. the Caribbean forecast around Jamaica with a coastline, a keep-off band and isochrones (lon/lat, dates);
  3. an execution run on the built-in mission flown in another jet (two strategies: two flown tracks);
  4. a fleet: the fleet's map.html holds every glider's route, and the other gliders' own starts and goals;
  5. the probability of reach over a 6-member jet ensemble (examples/jet_reachability.yaml at a coarse cell, V = 1): its
     layer is drawn, and its own time slider moves it to another frame whose drawing differs.

For each: no console error, the route layer has the route's vertex count (path.csv, or the flown track of a heading
route), the popups hold the waypoints' arrival dates (waypoints.csv), the isochrones and land are drawn, the time
slider moves the current field, and the screenshot is not blank.

Usage: check_glider_plan_map.py GLIDER_PLAN SOURCE_DIR
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def popup_date(iso):
    """The page shows 2026-06-01T09:58:36Z as '2026-06-01 09:58 UTC'."""
    return iso[:10] + " " + iso[11:16] + " UTC"


def main():
    glider, source = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="ompl_glider_maphtml_")
    failures = 0
    runs = [
        ("builtin", ["--isochrones"], ["--expect-isochrones", "8", "--expect-current-frames", "6"]),
        ("jamaica", ["--currents", os.path.join(source, "examples", "caribbean_forecast.nc"), "--start=-78.8,18.2",
                     "--goal=-75.8,18.1", "--speed", "0.4", "--coastline",
                     os.path.join(source, "examples", "jamaica_coast.geojson"), "--keep-off", "5km", "--isochrones"],
         ["--expect-isochrones", "8", "--expect-land-min", "1", "--expect-current-frames", "6"]),
        ("execution", ["--truth", "B0=1.38,c=0.138", "--strategies", "current_sensitive,greedy"],
         ["--expect-current-frames", "6", "--expect-tracks", "2"]),
    ]
    # the probability of reach: the example's ensemble, fewer members at a coarse cell (a few seconds)
    with open(os.path.join(source, "examples", "jet_reachability.yaml")) as f:
        text = f.read().replace("members: 24", "members: 6").replace("resolution: 0.05", "resolution: 0.2")
        text = text.replace("files: [summary, map, reachability]", "files: [summary, csv, path, map, reachability]")
    reach_yaml = os.path.join(work, "reach.yaml")
    with open(reach_yaml, "w") as f:
        f.write(text)
    # (at V = 1: the robust plan has a route, which the page's checks need; at the example's 0.5 it has none)
    # (a horizon of 10 days at the example's interval of a day: 10 frames)
    runs.append(("reachability", ["--mission", reach_yaml, "--speed", "1.0", "--reach-horizon", "10 d"],
                 ["--expect-current-frames", "6", "--expect-reach-frames", "10"]))
    try:
        for name, args, expect in runs:
            out = os.path.join(work, name)
            p = subprocess.run([glider] + args + ["--out", out], capture_output=True, text=True, timeout=600)
            if p.returncode != 0:
                print("FAIL %s: glider_plan exit %d: %s" % (name, p.returncode, p.stderr[-400:]))
                failures += 1
                continue
            vertices = len(rows(os.path.join(out, "path.csv")))
            waypoints = rows(os.path.join(out, "waypoints.csv"))
            check = [sys.executable, os.path.join(HERE, "check_map_html.py"), os.path.join(out, "map.html"),
                     "--expect-routes", "1", "--expect-route-vertices", str(vertices),
                     "--screenshot", os.path.join(work, name + ".png")] + expect
            dated = [w["time_iso"] for w in waypoints if w.get("time_iso")]
            for iso in (dated[:1] + dated[-1:]) if dated else []:
                check += ["--expect-popup-text", popup_date(iso)]
            c = subprocess.run(check, capture_output=True, text=True, timeout=180)
            print(c.stdout.strip() or c.stderr.strip())
            if c.returncode != 0:
                print("FAIL %s: %s" % (name, c.stderr[-600:]))
                failures += 1
        # a fleet: every glider's route on the fleet's map.html (the example with the map among its outputs)
        with open(os.path.join(source, "examples", "fleet_jet.yaml")) as f:
            text = f.read().replace("files: [csv, geojson, summary, goto]", "files: [csv, geojson, summary, goto, map]")
        fleet_yaml = os.path.join(work, "fleet.yaml")
        with open(fleet_yaml, "w") as f:
            f.write(text)
        out = os.path.join(work, "fleet")
        p = subprocess.run([glider, "--mission", fleet_yaml, "--out", out], capture_output=True, text=True,
                           timeout=600)
        gliders = rows(os.path.join(out, "fleet.csv")) if p.returncode == 0 else []
        c = subprocess.run([sys.executable, os.path.join(HERE, "check_map_html.py"), os.path.join(out, "map.html"),
                            "--expect-routes", str(len(gliders)), "--expect-fleet-ends-min", "2",
                            "--screenshot", os.path.join(work, "fleet.png")],
                           capture_output=True, text=True, timeout=180)
        print(c.stdout.strip() or c.stderr.strip())
        if p.returncode != 0 or len(gliders) < 2 or c.returncode != 0:
            print("FAIL fleet: glider_plan exit %d, %d gliders: %s %s" % (p.returncode, len(gliders),
                                                                         p.stderr[-300:], c.stderr[-300:]))
            failures += 1
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("map.html in Chromium: " + ("every run passed" if failures == 0 else "%d runs failed" % failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
