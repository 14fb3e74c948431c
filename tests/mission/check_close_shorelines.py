#!/usr/bin/env python3
"""scripts/close_shorelines.py on a small synthetic Florida Straits: shorelines cut by the box are closed along its
edges (Florida from the north edge, Cuba from the west to the east edge with the box's southern corners), an island
stays as it is, and a shoreline running outside the box is clipped to it. Exit 0 when every check holds."""
import json
import subprocess
import sys

script = sys.argv[1]
BOX = "-84/-78/22/27"
# Florida: enters beyond the north edge (lat 28, clipped), down to the Keys and back up; written west to east
florida = [(-82.5, 28.0), (-82.5, 26.0), (-81.0, 25.0), (-80.0, 26.0), (-80.0, 28.0)]
# Cuba's north coast: written east to west (land to its left, south); the box's southern corners are land
cuba = [(-78.0, 22.4), (-80.0, 23.1), (-82.0, 23.1), (-84.0, 22.8)]
# an island (closed ring) in the Bahamas
island = [(-78.6, 24.0), (-78.2, 24.0), (-78.2, 24.5), (-78.6, 24.5), (-78.6, 24.0)]


def run(segments, corner_land):
    text = "".join("> segment\n" + "".join("%g %g\n" % p for p in s) for s in segments)
    out = subprocess.run([sys.executable, script, "--corner-land", corner_land, "--", BOX], input=text,
                         capture_output=True, text=True, check=True)
    return [f["geometry"]["coordinates"][0] for f in json.loads(out.stdout)["features"]], out.stderr


def contains(ring, x, y):
    inside = False
    for (ax, ay), (bx, by) in zip(ring, ring[1:] + ring[:1]):
        if (ay > y) != (by > y) and x < (bx - ax) * (y - ay) / (by - ay) + ax:
            inside = not inside
    return inside


failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def land(rings, x, y):
    return sum(contains(r, x, y) for r in rings)


rings, log = run([florida, cuba, island], "yes")
check(len(rings) == 3, "three land polygons, got %d (%s)" % (len(rings), log))
check(land(rings, -81.3, 26.5) == 1, "central Florida is land")
check(land(rings, -81.0, 22.3) == 1, "Cuba is land")
check(land(rings, -83.9, 22.05) == 1, "Cuba reaches the box's south-west corner")
check(land(rings, -78.4, 24.2) == 1, "the island is land")
for x, y in [(-81.0, 24.0), (-83.0, 26.0), (-79.0, 26.5), (-78.5, 23.5)]:
    check(land(rings, x, y) == 0, "(%g, %g) in the Straits is water" % (x, y))
for r in rings:
    check(r[0] == r[-1], "rings are closed")
    for x, y in r:
        check(-84 - 1e-9 <= x <= -78 + 1e-9 and 22 - 1e-9 <= y <= 27 + 1e-9, "(%g, %g) within the box" % (x, y))
# the same shorelines written the other way round give the same land
rings2, _ = run([florida[::-1], cuba[::-1], island], "yes")
check(len(rings2) == 3 and land(rings2, -81.3, 26.5) == 1 and land(rings2, -81.0, 22.3) == 1
      and land(rings2, -81.0, 24.0) == 0, "the shorelines' direction does not matter")
# Florida alone, the south-west corner in water
rings3, _ = run([florida], "no")
check(len(rings3) == 1 and land(rings3, -81.3, 26.5) == 1 and land(rings3, -83.0, 23.0) == 0,
      "Florida alone: one polygon, the south of the box water")
# no shoreline: all land or all water
check(len(run([], "yes")[0]) == 1 and len(run([], "no")[0]) == 0, "an empty box is all land or all water")
# GMT writes a shoreline cut into pieces at its bins' edges (lat 24 and lon -80 here), some of them reversed: the
# pieces are joined before clipping, so Cuba is still one polygon and the Straits water
cuba_pieces = [cuba[:2] + [(-80.0, 23.1)], [(-82.0, 23.1), (-80.0, 23.1)], cuba[2:]]
florida_pieces = [florida[:2] + [(-81.5, 25.4)], [(-81.5, 25.4), (-81.0, 25.0), (-80.0, 26.0)], florida[3:]]
rings4, log4 = run(cuba_pieces + florida_pieces + [island], "yes")
check(len(rings4) == 3 and land(rings4, -81.0, 22.3) == 1 and land(rings4, -81.3, 26.5) == 1
      and land(rings4, -81.0, 24.0) == 0 and "ends inside" not in log4,
      "shorelines in bin pieces are joined (%d polygons, %s)" % (len(rings4), log4))
# a box across 180: GMT writes lon 181 as -179; an island from 179.8 to 180.2 stays one ring
fiji = [(179.8, -16.2), (-179.8, -16.2), (-179.8, -16.0), (179.8, -16.0), (179.8, -16.2)]
out = subprocess.run([sys.executable, script, "--corner-land", "no", "--", "179/181/-17/-15"],
                     input="> s\n" + "".join("%g %g\n" % p for p in fiji), capture_output=True, text=True, check=True)
rings5 = [f["geometry"]["coordinates"][0] for f in json.loads(out.stdout)["features"]]
check(len(rings5) == 1 and land(rings5, 180.1, -16.1) == 1 and land(rings5, 179.5, -16.1) == 0,
      "an island across 180 is one ring (%s)" % rings5)
# GMT closes some shorelines along the box's edges itself, through the south-west corner: the corner's land is
# that ring's and the rest of the box stays water
corner_ring = [(-83.0, 22.0), (-84.0, 22.5), (-84.0, 22.0), (-83.0, 22.0)]
rings6, _ = run([corner_ring, island], "yes")
check(len(rings6) == 2 and land(rings6, -81.0, 24.0) == 0 and land(rings6, -83.8, 22.1) == 1,
      "a ring closed along the edges through the corner does not make the whole box land (%d)" % len(rings6))
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
