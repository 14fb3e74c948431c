"""Checks a glider_plan route on NCL's POP file (pop.nc) against the model's own land, read independently of
ompl_glider: the tracer t (potential temperature at 500 m) is missing on land, and a B grid's tracer cell (j, i) is
the quadrilateral of the velocity points lat2d/lon2d at its corners (j-1, i-1), (j-1, i), (j, i), (j, i-1) (POP's
velocity point (j, i) is the north-east corner of tracer cell (j, i); the grid's columns wrap round the globe).

Usage: pop_route_check.py POP.nc CACHE.npz ROUTE_DIR [--south-of LAT]
Every leg of ROUTE_DIR/path.csv is sampled every 2 km or less (linear in lon/lat); each sample must lie in a tracer
cell that is not masked. Prints the samples, those on land, the clearance (km from the samples to the nearest masked
cell) and the southernmost latitude; exits 1 when a sample is on land or the route is not south of LAT.
"""
import csv
import math
import os
import subprocess
import sys

import numpy as np

KM_PER_DEG = 111.195


def read_pop(path, cache):
    """lat2d, lon2d (degrees east in -180..180) and the tracer's land (t missing) as arrays (nlat, nlon)."""
    if os.path.exists(cache):
        d = np.load(cache)
        return d["lat"], d["lon"], d["land"]
    out = subprocess.run(["ncdump", "-v", "t,lat2d,lon2d", "-p", "9,17", path], capture_output=True, text=True,
                         check=True).stdout
    head, data = out.split("\ndata:\n", 1)
    dims = {}
    for line in head.split("dimensions:")[1].split("variables:")[0].splitlines():
        if "=" in line:
            name, value = line.split("=")
            dims[name.strip()] = int(value.strip(" ;"))
    shape = (dims["nlat"], dims["nlon"])
    arrays = {}
    for block in data.split(";"):
        if "=" not in block:
            continue
        name, values = block.split("=", 1)
        vals = [math.nan if v.strip() == "_" else float(v) for v in values.replace("\n", " ").split(",")]
        arrays[name.strip()] = np.array(vals).reshape(shape)
    lat, lon = arrays["lat2d"], arrays["lon2d"]
    lon = np.where(lon > 180.0, lon - 360.0, lon)
    land = np.isnan(arrays["t"]) | (np.abs(arrays["t"]) > 1e30)
    np.savez(cache, lat=lat, lon=lon, land=land)
    return lat, lon, land


def route(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [(float(r["lon"]), float(r["lat"])) for r in rows]


def samples(points, step_km=2.0):
    out = []
    for (a, b), (c, d) in zip(points, points[1:]):
        dlon = (c - a + 180.0) % 360.0 - 180.0
        km = math.hypot(dlon * math.cos(math.radians(0.5 * (b + d))), d - b) * KM_PER_DEG
        n = max(1, int(math.ceil(km / step_km)))
        out += [(a + dlon * k / n, b + (d - b) * k / n) for k in range(n)]
    out.append(points[-1])
    return out


class Cells:
    """The tracer cells as quadrilaterals of the velocity points."""

    def __init__(self, lat, lon, land):
        self.lat, self.lon, self.land = lat, lon, land
        self.ny, self.nx = lat.shape

    def corners(self, j, i):
        """SW, SE, NE, NW corners (lon, lat) of tracer cell (j, i) (j >= 1)."""
        w = (i - 1) % self.nx
        return [(self.lon[j - 1, w], self.lat[j - 1, w]), (self.lon[j - 1, i], self.lat[j - 1, i]),
                (self.lon[j, i], self.lat[j, i]), (self.lon[j, w], self.lat[j, w])]

    @staticmethod
    def local(p, q):
        """q in km in the tangent plane at p."""
        dlon = (q[0] - p[0] + 180.0) % 360.0 - 180.0
        return dlon * math.cos(math.radians(p[1])) * KM_PER_DEG, (q[1] - p[1]) * KM_PER_DEG

    def distance(self, p, j, i):
        """km from p to tracer cell (j, i) (0 inside)."""
        v = [self.local(p, c) for c in self.corners(j, i)]
        inside = True
        sign = 0.0
        best = math.inf
        for k in range(4):
            (x0, y0), (x1, y1) = v[k], v[(k + 1) % 4]
            cross = (x1 - x0) * (-y0) - (y1 - y0) * (-x0)
            if sign == 0.0:
                sign = cross
            elif cross * sign < 0.0:
                inside = False
            ex, ey = x1 - x0, y1 - y0
            s = max(0.0, min(1.0, -(x0 * ex + y0 * ey) / (ex * ex + ey * ey)))
            best = min(best, math.hypot(x0 + s * ex, y0 + s * ey))
        return 0.0 if inside else best

    def nearest_node(self, p):
        dlon = (self.lon - p[0] + 180.0) % 360.0 - 180.0
        d = (dlon * math.cos(math.radians(p[1]))) ** 2 + (self.lat - p[1]) ** 2
        return np.unravel_index(np.argmin(d), d.shape)

    def check(self, p):
        """(the cell holding p, its land, the km to the nearest land cell within 4 cells)."""
        j0, i0 = self.nearest_node(p)
        cell, clearance = None, math.inf
        for j in range(max(1, j0 - 4), min(self.ny - 1, j0 + 5) + 1):
            for di in range(-4, 6):
                i = (i0 + di) % self.nx
                dist = self.distance(p, j, i)
                if dist == 0.0 and cell is None:
                    cell = (j, i)
                if self.land[j, i]:
                    clearance = min(clearance, dist)
        if cell is None:
            raise SystemExit("no tracer cell holds %.5f, %.5f" % p)
        return cell, bool(self.land[cell]), clearance


def main():
    pop, cache, out = sys.argv[1:4]
    south_of = float(sys.argv[sys.argv.index("--south-of") + 1]) if "--south-of" in sys.argv else None
    cells = Cells(*read_pop(pop, cache))
    pts = samples(route(os.path.join(out, "path.csv")))
    # the nearest node is searched over the trip's neighbourhood only
    lons = [p[0] for p in pts]
    lats = [p[1] for p in pts]
    on_land = []
    clearance = math.inf
    for p in pts:
        cell, land, c = cells.check(p)
        clearance = min(clearance, c)
        if land:
            on_land.append((p, cell))
    south = min(lats)
    print("%s: %d samples, %d on the model's land, clearance %.3f km, lon %.2f..%.2f, southernmost lat %.3f" %
          (os.path.basename(out), len(pts), len(on_land), clearance, min(lons), max(lons), south))
    for p, cell in on_land[:10]:
        print("  on land: %.5f, %.5f in tracer cell (j, i) = %s" % (p[0], p[1], cell))
    ok = not on_land
    if south_of is not None and not south < south_of:
        print("  the route does not pass south of %.2f N" % south_of)
        ok = False
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
