#!/usr/bin/env python3
"""A real-data coastal trial of glider_plan, checked independently of the program.

For each route (Florida Straits, Turks Island Passage, St Lucia Channel, round Jamaica, Vanua Levu across 180,
Cape Hatteras): the GSHHG intermediate coastline of the route's box (scripts/make_coastline.sh, GMT), a synthetic
current forecast in a CMEMS layout written with ncgen, then

    glider_plan --currents F --start .. --goal .. --region BOX --coastline COAST --keep-off 2km
                --bathymetry /usr/share/ferret-vis/data/etopo5.cdf --min-depth 50m --out DIR

and, with the standard library and numpy only, on path.csv densified every 100 m:
  (a) every point keeps at least KEEP_OFF - TOL from every coastline edge and is inside no land polygon
      (distances in a local equirectangular projection at each point's latitude);
  (b) the ETOPO5 elevation there (read from the classic NetCDF file by a small reader below, bilinear between the
      four nodes of its cell) is at most -MIN_DEPTH + DEPTH_TOL;
  (c) map.png exists and summary.json's safety section reports a closest approach >= the keep-off.
A refused route (exit 1) passes only when its reason names what closes it (land, the keep-off or shallow water).

Usage: real_coast_trial.py GLIDER_PLAN REPO_DIR WORK_DIR   (exit 0: every check holds; prints a table)
"""
import csv
import json
import math
import os
import re
import struct
import subprocess
import sys
import time

import numpy as np

ETOPO = "/usr/share/ferret-vis/data/etopo5.cdf"
KEEP_OFF = 2000.0   # m
MIN_DEPTH = 50.0    # m
TOL = 20.0          # m: the program's projection against the local equirectangular one here (1 % of 2 km)
DEPTH_TOL = 0.5     # m: the program forbids a cell when any of its four nodes is shallower, so bilinear >= limit
STEP = 100.0        # m between checked points
R_EARTH = 6371008.8

# name, box lon0/lon1/lat0/lat1 (coastline, forecast and planning region), start lon,lat, goal lon,lat,
# current (u, v) in m/s at the box's south edge and at its north edge (linear shear between them)
ROUTES = [
    ("Florida Straits (Key West to Havana)", (-83.0, -81.0, 22.8, 24.9), (-81.80, 24.38), (-82.35, 23.25),
     ((0.35, 0.05), (0.15, 0.0))),
    ("Turks Island Passage", (-71.9, -70.7, 20.9, 22.1), (-71.30, 21.95), (-71.25, 21.05),
     ((0.10, 0.05), (0.20, 0.05))),
    ("St Lucia Channel", (-61.5, -60.4, 13.7, 14.7), (-61.25, 14.25), (-60.65, 14.22),
     ((-0.30, 0.05), (-0.20, 0.10))),
    ("Round Jamaica (south to north coast)", (-79.0, -75.5, 17.0, 19.0), (-77.50, 17.50), (-77.50, 18.75),
     ((-0.20, 0.0), (-0.30, 0.05))),
    ("Vanua Levu across 180", (178.3, 181.2, -17.6, -15.4), (178.80, -16.00), (180.50, -16.90),
     ((0.10, 0.10), (0.20, 0.0))),
    ("Cape Hatteras, Gulf Stream coastal leg", (-76.0, -74.0, 34.5, 36.5), (-75.30, 34.90), (-74.70, 36.10),
     ((0.25, 0.40), (0.35, 0.30))),
    # a control: a 16 km keep-off closes the 31 km St Lucia Channel (and the box's south edge cuts St Lucia off from
    # the sea south of it), so this one must be refused with a reason naming the keep-off
    ("St Lucia Channel, keep-off 16 km (closed)", (-61.5, -60.4, 13.7, 14.7), (-61.45, 14.20), (-60.45, 14.20),
     ((-0.30, 0.05), (-0.20, 0.10)), 16000.0),
]


# ----------------------------------------------------------------------------------------------------------------
# a reader of classic (CDF-1/CDF-2) NetCDF files: enough for etopo5.cdf's coordinates and its 2-D variable

def read_classic(path, want):
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    if head[:3] != b"CDF" or head[3] not in (1, 2):
        raise SystemExit("%s: not a classic NetCDF file" % path)
    pos = [8]  # magic + numrecs

    def i4():
        v = struct.unpack(">i", head[pos[0]:pos[0] + 4])[0]
        pos[0] += 4
        return v

    def name():
        n = i4()
        s = head[pos[0]:pos[0] + n].decode()
        pos[0] += (n + 3) // 4 * 4
        return s

    size = {1: 1, 2: 1, 3: 2, 4: 4, 5: 4, 6: 8}

    def skip_atts():
        tag, n = i4(), i4()
        for _ in range(n):
            name()
            t, m = i4(), i4()
            pos[0] += (m * size[t] + 3) // 4 * 4

    tag, n = i4(), i4()
    dims = []
    for _ in range(n):
        dname = name()
        dims.append((dname, i4()))
    skip_atts()
    tag, n = i4(), i4()
    out = {}
    for _ in range(n):
        vname = name()
        dimids = [i4() for _ in range(i4())]
        skip_atts()
        t, vsize = i4(), i4()
        begin = struct.unpack(">q" if head[3] == 2 else ">i", head[pos[0]:pos[0] + (8 if head[3] == 2 else 4)])[0]
        pos[0] += 8 if head[3] == 2 else 4
        if vname in want:
            dtype = {5: ">f4", 6: ">f8", 4: ">i4", 3: ">i2"}[t]
            shape = tuple(dims[d][1] for d in dimids)
            out[vname] = np.memmap(path, dtype=dtype, mode="r", offset=begin, shape=shape)
    return out


class Etopo:
    def __init__(self, path):
        v = read_classic(path, {"ETOPO05_X", "ETOPO05_Y", "ROSE"})
        self.x, self.y, self.z = np.array(v["ETOPO05_X"]), np.array(v["ETOPO05_Y"]), v["ROSE"]

    def elevation(self, lon, lat):
        """Bilinear elevation (m, positive up) between the four nodes round (lon, lat), and the shallowest node."""
        lon = lon % 360.0
        i = int(np.searchsorted(self.x, lon, side="right")) - 1
        j = int(np.searchsorted(self.y, lat, side="right")) - 1
        i, j = min(max(i, 0), len(self.x) - 2), min(max(j, 0), len(self.y) - 2)
        tx = (lon - self.x[i]) / (self.x[i + 1] - self.x[i])
        ty = (lat - self.y[j]) / (self.y[j + 1] - self.y[j])
        z = self.z[j:j + 2, i:i + 2].astype(float)
        bil = (z[0, 0] * (1 - tx) * (1 - ty) + z[0, 1] * tx * (1 - ty) + z[1, 0] * (1 - tx) * ty
               + z[1, 1] * tx * ty)
        return bil, float(z.max())


# ----------------------------------------------------------------------------------------------------------------
# geometry in a local equirectangular projection

def unwrap(points, box):
    """Longitudes within 180 degrees of the box's centre (path.csv writes -179.9 for 180.1 across 180)."""
    c = 0.5 * (box[0] + box[1])
    return [(c + (x - c + 180.0) % 360.0 - 180.0, y) for x, y in points]


def densify(points):
    """Points every STEP metres along the polyline of (lon, lat)."""
    out = [points[0]]
    for (a, b), (c, d) in zip(points, points[1:]):
        k = math.cos(math.radians(0.5 * (b + d)))
        length = R_EARTH * math.radians(math.hypot((c - a) * k, d - b))
        n = max(1, int(math.ceil(length / STEP)))
        out.extend((a + (c - a) * s / n, b + (d - b) * s / n) for s in range(1, n + 1))
    return out


class Land:
    def __init__(self, geojson):
        self.rings = [np.array(f["geometry"]["coordinates"][0], dtype=float) for f in geojson["features"]]
        self.edges = np.concatenate([np.hstack([r[:-1], r[1:]]) for r in self.rings]) if self.rings else None
        self.ring_of = np.concatenate([np.full(len(r) - 1, k) for k, r in enumerate(self.rings)]) if self.rings \
            else None

    def distance(self, lon, lat):
        """Metres from each point (arrays lon, lat) to the nearest coastline edge (equirectangular at the point's
        latitude), and whether the point is inside a land polygon (even-odd rule, ring by ring)."""
        lon, lat = np.asarray(lon, float), np.asarray(lat, float)
        if self.edges is None:
            return np.full(lon.shape, np.inf), np.zeros(lon.shape, bool)
        m = R_EARTH * math.pi / 180.0
        dist = np.empty(lon.shape)
        inside = np.zeros(lon.shape, bool)
        e = self.edges
        for c in range(0, len(lon), 256):
            x, y = lon[c:c + 256, None], lat[c:c + 256, None]
            k = np.cos(np.radians(y))
            ax, ay = (e[None, :, 0] - x) * k * m, (e[None, :, 1] - y) * m
            bx, by = (e[None, :, 2] - x) * k * m, (e[None, :, 3] - y) * m
            dx, dy = bx - ax, by - ay
            dd = dx * dx + dy * dy
            t = np.clip(-(ax * dx + ay * dy) / np.where(dd > 0, dd, 1.0), 0.0, 1.0)
            dist[c:c + 256] = np.sqrt(np.min((ax + t * dx) ** 2 + (ay + t * dy) ** 2, axis=1))
            cross = (e[None, :, 1] > y) != (e[None, :, 3] > y)
            with np.errstate(divide="ignore", invalid="ignore"):
                xs = e[None, :, 0] + (y - e[None, :, 1]) * (e[None, :, 2] - e[None, :, 0]) / (e[None, :, 3] - e[None, :, 1])
            hits = cross & (x < xs)
            per_ring = np.zeros((hits.shape[0], len(self.rings)), int)
            for r in range(len(self.rings)):
                per_ring[:, r] = np.count_nonzero(hits[:, self.ring_of == r], axis=1)
            inside[c:c + 256] = np.any(per_ring % 2 == 1, axis=1)
        return dist, inside


# ----------------------------------------------------------------------------------------------------------------
# the forecast: CMEMS layout (time, depth, latitude, longitude; uo/vo in m s-1), 0.02 degree, 10 days daily

def forecast_cdl(box, shear):
    lon0, lon1, lat0, lat1 = box
    pad = 0.1
    nx = int(round((lon1 - lon0 + 2 * pad) / 0.02)) + 1
    ny = int(round((lat1 - lat0 + 2 * pad) / 0.02)) + 1
    lons = [lon0 - pad + 0.02 * i for i in range(nx)]
    lats = [lat0 - pad + 0.02 * j for j in range(ny)]
    (us, vs), (un, vn) = shear
    nt = 11
    u, v = [], []
    for t in range(nt):
        for lat in lats:
            s = min(1.0, max(0.0, (lat - lat0) / (lat1 - lat0)))
            uu, vv = us + (un - us) * s, vs + (vn - vs) * s
            g = 1.0 + 0.1 * math.sin(2 * math.pi * t / 4.0)  # a slow pulse in time
            u.extend(["%.4f" % (uu * g)] * nx)
            v.extend(["%.4f" % (vv * g)] * nx)

    def data(vals):
        return ",\n  ".join(", ".join(vals[k:k + 12]) for k in range(0, len(vals), 12))
    return """netcdf forecast {
dimensions:
  time = UNLIMITED ; depth = 1 ; latitude = %d ; longitude = %d ;
variables:
  float time(time) ; time:units = "hours since 1950-01-01 00:00:00" ; time:standard_name = "time" ;
    time:calendar = "gregorian" ;
  float depth(depth) ; depth:units = "m" ; depth:positive = "down" ; depth:standard_name = "depth" ;
  float latitude(latitude) ; latitude:units = "degrees_north" ; latitude:standard_name = "latitude" ;
  float longitude(longitude) ; longitude:units = "degrees_east" ; longitude:standard_name = "longitude" ;
  short uo(time, depth, latitude, longitude) ; uo:units = "m s-1" ; uo:scale_factor = 0.0001 ;
    uo:add_offset = 0. ; uo:_FillValue = -32767s ; uo:standard_name = "eastward_sea_water_velocity" ;
  short vo(time, depth, latitude, longitude) ; vo:units = "m s-1" ; vo:scale_factor = 0.0001 ;
    vo:add_offset = 0. ; vo:_FillValue = -32767s ; vo:standard_name = "northward_sea_water_velocity" ;
// global attributes:
  :Conventions = "CF-1.6" ; :source = "synthetic sheared current for the real-coast trial" ;
data:
 time = %s ;
 depth = 0.494 ;
 latitude = %s ;
 longitude = %s ;
 uo = %s ;
 vo = %s ;
}
""" % (ny, nx, ", ".join("%d" % (665832 + 24 * t) for t in range(nt)),  # 2025-12-16 + t days
       data(["%.4f" % y for y in lats]), data(["%.4f" % x for x in lons]),
       data(["%d" % round(float(x) / 0.0001) for x in u]), data(["%d" % round(float(x) / 0.0001) for x in v]))


# ----------------------------------------------------------------------------------------------------------------

def run_route(k, route, glider_plan, repo, work, etopo):
    name, box, start, goal, shear = route[:5]
    keep_off = route[5] if len(route) > 5 else KEEP_OFF
    d = os.path.join(work, "route%d" % k)
    os.makedirs(d, exist_ok=True)
    coast = os.path.join(d, "coast.geojson")
    region = "%g/%g/%g/%g" % box
    subprocess.run(["bash", os.path.join(repo, "scripts", "make_coastline.sh"), region, coast, "i"], check=True,
                   capture_output=True, text=True)
    cdl, nc = os.path.join(d, "forecast.cdl"), os.path.join(d, "forecast.nc")
    with open(cdl, "w") as f:
        f.write(forecast_cdl(box, shear))
    subprocess.run(["ncgen", "-o", nc, cdl], check=True)
    out = os.path.join(d, "out")
    cmd = [glider_plan, "--currents", nc, "--start=%g,%g" % start, "--goal=%g,%g" % goal,
           "--region=%g,%g,%g,%g" % (box[0], box[2], box[1], box[3]), "--speed", "0.5", "--coastline", coast,
           "--keep-off", "%gm" % keep_off, "--bathymetry", ETOPO, "--min-depth", "50m", "--out", out]
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    row = {"name": name, "exit": p.returncode, "seconds": time.time() - t0, "hours": None, "closest_km": None,
           "min_depth_m": None, "reported_km": None, "failures": [], "cmd": " ".join(cmd)}
    fail = row["failures"]
    with open(os.path.join(d, "log.txt"), "w") as f:
        f.write(" ".join(cmd) + "\n" + p.stdout + p.stderr)
    note = re.search(r"Coastline: +(\d+) land polygons from (\d+) of (\d+) features", p.stdout)
    if p.returncode == 0 and not note:
        fail.append("no 'Coastline: N land polygons from U of K features' line")
    elif note and int(note.group(2)) > int(note.group(3)):
        fail.append("the coastline note counts more features used than the file has: " + note.group(0))
    land = Land(json.load(open(coast)))
    straight = densify(unwrap([start, goal], box))
    sd, sin = land.distance([q[0] for q in straight], [q[1] for q in straight])
    row["straight"] = "%s, %.0f m" % ("crosses land" if sin.any() else "%.1f km" % (sd.min() / 1000.0),
                                     -max(etopo.elevation(a, b)[0] for a, b in straight))
    if len(route) > 5 and p.returncode != 1:
        fail.append("expected a refusal (exit 1) naming the keep-off, got exit %d" % p.returncode)
    if p.returncode == 1:
        reason = [l for l in (p.stdout + p.stderr).splitlines() if l.startswith("Reason:")]
        text = " ".join(reason).lower()
        needed = ("keep-off",) if len(route) > 5 else ("keep-off", "shallow", "depth", "land", "coastline")
        if not any(w in text for w in needed):
            fail.append("refused without naming what closes the route (%s): %s" % ("/".join(needed),
                                                                                   (p.stdout + p.stderr)[-400:]))
        row["reason"] = reason[:1]
        return row
    if p.returncode != 0:
        fail.append("exit %d: %s" % (p.returncode, (p.stdout + p.stderr)[-600:]))
        return row
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "path.csv")) as f:
        rows = list(csv.DictReader(f))
    path = [(float(r["lon"]), float(r["lat"])) for r in rows]
    row["hours"] = summary_travel_hours(summary)
    points = densify(unwrap(path, box))
    lons, lats = np.array([p[0] for p in points]), np.array([p[1] for p in points])
    dist, inside = land.distance(lons, lats)
    for q in np.nonzero(inside)[0][:5]:
        fail.append("(%.5f, %.5f) is inside a land polygon" % (lons[q], lats[q]))
    closest = float(dist.min())
    elev = [etopo.elevation(a, b) for a, b in points]
    shallowest = max(e[0] for e in elev)
    row["closest_km"], row["min_depth_m"] = closest / 1000.0, -shallowest
    if closest < keep_off - TOL:
        fail.append("closest approach to the coastline %.0f m < keep-off %.0f m - %.0f m" % (closest, keep_off, TOL))
    if shallowest > -MIN_DEPTH + DEPTH_TOL:
        fail.append("ETOPO5 elevation %.1f m on the route: shallower than %.0f m" % (shallowest, MIN_DEPTH))
    ends = unwrap([path[0], path[-1], start, goal], box)
    if max(abs(ends[0][0] - ends[2][0]), abs(ends[0][1] - ends[2][1]),
           abs(ends[1][0] - ends[3][0]), abs(ends[1][1] - ends[3][1])) > 1e-3:
        fail.append("path.csv runs from %s to %s, not from the start to the goal" % (path[0], path[-1]))
    if not os.path.getsize(os.path.join(out, "map.png")) > 1000:
        fail.append("map.png missing or empty")
    reported = find_closest(summary)
    row["reported_km"] = reported
    if reported is None:
        fail.append("summary.json has no closest_land_m (safety: %s)" % summary.get("safety"))
    elif reported < keep_off / 1000.0 - 1e-6:
        fail.append("summary.json: closest approach %.3f km < keep-off" % reported)
    return row


def goal_in_keep_off(glider_plan, work):
    """A goal inside the keep-off band (Turks Island Passage, 15 km): refused with exit 2, in lon/lat and km."""
    d = os.path.join(work, "route1")
    cmd = [glider_plan, "--currents", os.path.join(d, "forecast.nc"), "--start=-71.30,21.95", "--goal=-71.25,21.05",
           "--region=-71.9,20.9,-70.7,22.1", "--speed", "0.5", "--coastline", os.path.join(d, "coast.geojson"),
           "--keep-off", "15km", "--out", os.path.join(work, "goal_keep_off")]
    p = subprocess.run(cmd, capture_output=True, text=True)
    text = p.stdout + p.stderr
    want = re.compile(r"the goal \(lon -71\.25000, lat 21\.05000\) is within the keep-off distance 15 km of land "
                      r"\((\d+\.\d+) km away\)")
    m = want.search(text)
    if p.returncode != 2 or not m or not float(m.group(1)) < 15.0:
        return ["a goal within the keep-off: expected exit 2 naming it in lon/lat and km, got exit %d: %s" %
                (p.returncode, text[-400:])]
    if "Error:" in text or os.path.exists(os.path.join(work, "goal_keep_off")):
        return ["a goal within the keep-off: an OMPL error line or an output directory: " + text[-400:]]
    return []


def summary_travel_hours(summary):
    for key in ("travel_time_s", "travel_time"):
        v = summary.get(key)
        if isinstance(v, (int, float)):
            return v / 3600.0
        if isinstance(v, dict):
            for kk in ("s", "seconds", "value"):
                if isinstance(v.get(kk), (int, float)):
                    return v[kk] / 3600.0
    return None


def find_closest(summary):
    """summary.json's closest approach to land in km (closest_land_m, beside the safety section)."""
    v = summary.get("closest_land_m")
    return v / 1000.0 if isinstance(v, (int, float)) else None


def main():
    glider_plan, repo, work = sys.argv[1:4]
    only = sys.argv[4:]
    etopo = Etopo(ETOPO)
    rows = []
    for k, route in enumerate(ROUTES):
        if only and str(k) not in only:
            continue
        rows.append(run_route(k, route, glider_plan, repo, work, etopo))
    print("%-42s %4s %8s %9s %10s %9s  %s" % ("route", "exit", "time (h)", "land (km)", "summary km",
                                                "depth (m)", "straight line: land, depth"))
    for r in rows:
        f = lambda v, fmt: (fmt % v) if v is not None else "-"
        print("%-42s %4d %8s %9s %10s %9s  %s" % (r["name"], r["exit"], f(r["hours"], "%.1f"),
                                                 f(r["closest_km"], "%.2f"), f(r["reported_km"], "%.2f"),
                                                 f(r["min_depth_m"], "%.0f"), r.get("straight", "-")))
        if r.get("reason"):
            print("    " + r["reason"][0][:160])
    print("(land: closest approach of path.csv densified every %g m to the GSHHG 'i' coastline; depth: the "
          "shallowest ETOPO5 depth along it, bilinear)" % STEP)
    bad = [(r["name"], x, r["cmd"]) for r in rows for x in r["failures"]]
    if not only or "1" in only:
        bad += [("goal in the keep-off band", x, "") for x in goal_in_keep_off(glider_plan, work)]
    for name, x, cmd in bad:
        print("FAIL %s: %s\n    (%s)" % (name, x, cmd))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
