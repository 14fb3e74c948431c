#!/usr/bin/env python3
"""glider_plan on every real forecast file the project bundles or installs, each route checked against the file's own
land, read independently of ompl_glider (ncdump text output, numpy; no NetCDF-C binding, no code of the program).

Files: examples/*.nc (every one the repository bundles; a new one must be given trips below, else this fails) and
NCL's POP sample /usr/share/ncarg/data/cdf/pop.nc (Debian's libncarg-data, installed by scripts/setup.sh). A missing
file is a failure, not a skip.

The file's land, per node (the union over every record and depth level, so at least what the program takes):
  - u or v is a fill value (_FillValue, missing_value, NaN, outside valid_min/valid_max/valid_range);
  - a land/sea mask variable (flag_meanings, land_binary_mask/sea_binary_mask, mask/mask_rho/tmask/lsm) says land;
  - on POP's B grid, a velocity point one of whose 4 tracer cells has a missing tracer t (velocity point (j, i) is the
    north-east corner of tracer cell (j, i); the tracer cells are the quadrilaterals of the velocity points, drawn by
    tests/current/pop_route_check.py's Cells).
A sample is in the model's land when the grid cell holding it has a land corner (docs/NETCDF_GEOGRAPHY.md: "inWater()
is false in every cell with a land corner"): the 4 surrounding velocity nodes of a rectilinear lon/lat grid, the
quadrilateral of 4 velocity points on POP's grid (so the 3 x 3 tracer cells around it). A sample on the edge between
a land cell and a water cell is on the water's boundary, which a route may follow: it is in land only when every cell
holding it is a land cell. A sample outside the grid counts as land.

Every leg of the route (path.geojson's line, or path.csv's when it has more points: a heading route's flown track is
the denser) is sampled linearly in lon/lat at most a quarter of the smallest grid cell apart (2 km at most on POP).

Usage: check_bundled_files_land.py GLIDER_PLAN REPO_DIR WORK_DIR
Exit 0 when every trip gives a route (exit 0 of glider_plan, a path) and no sample is in the file's land; prints a
table: file, trip, travel time, samples, samples in land, the closest sample to a land node and to a land cell.
"""
import csv
import glob
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "current"))
from pop_route_check import Cells, samples  # noqa: E402  (the quadrilaterals of POP's velocity points)

KM_PER_DEG = 111.195
POP = "/usr/share/ncarg/data/cdf/pop.nc"
TOL_DEG = 1e-9  # degrees (0.1 mm): a sample on a cell edge, within the rounding of the numbers written

# file (relative to the repository, or absolute), extra glider_plan flags, trips: (name, start, goal, speed m/s)
TRIPS = {
    "examples/labrador_forecast.nc": ([], [
        # the README's trip: its goal lies just east of the island's land cells, the route passes their SE corner
        ("readme_trip", "-52.7,47.9", "-51.5,48.45", 0.3),
        # west to east across the island's latitudes: its land cells reach the grid's north edge, round them south
        ("west_east_round_south", "-52.6,48.62", "-51.35,48.66", 0.3),
        # south-west to north-east round the island's south-east corner and up its east coast
        ("sw_ne_up_east_coast", "-52.45,48.3", "-51.45,48.75", 0.3),
    ]),
    "examples/labrador_nowcast.nc": ([], [
        ("west_east_round_south", "-52.6,48.62", "-51.35,48.66", 0.3),
        # north to south down the island's west coast: a route of held headings (the flown track is path.geojson's)
        ("north_south_west_coast", "-52.35,48.75", "-52.3,47.8", 0.3),
    ]),
    # no land of its own (no fill values, no mask; Jamaica is a GIS coastline, forbidden but not the file's): the
    # check finds no land node, so every sample is in water and the closest land is "none"
    "examples/caribbean_forecast.nc": (["--coastline", "examples/jamaica_coast.geojson"], [
        ("jamaica_coastline", "-78.8,18.2", "-75.8,18.1", 0.4),
        ("windward_to_southwest", "-75.3,19.3", "-79.2,16.8", 0.4),
    ]),
    # NCL's POP sample at 500 m: coasts of the model's 1-degree land
    POP: (["--u-var", "urot", "--v-var", "vrot"], [
        ("yucatan_channel", "-86.5,24.5", "-84.0,19.5", 0.5),          # Gulf of Mexico to the Caribbean
        ("round_tasmania_south", "143.0,-40.8", "149.0,-43.0", 0.5),   # Bass Strait's mouth to the Tasman Sea
        ("cape_of_good_hope", "16.5,-33.0", "26.5,-34.9", 0.5),       # Atlantic to Indian Ocean
    ]),
}


# ---------------------------------------------------------------------------------------------------------- reading
def ncdump_header(path):
    return subprocess.run(["ncdump", "-h", path], capture_output=True, text=True, check=True).stdout


def parse_header(text):
    """dims {name: size}, variables {name: {"dims": [...], "attrs": {name: text}}}."""
    dims, variables = {}, {}
    section = None
    for raw in text.splitlines():
        line = raw.strip()
        if line.startswith("dimensions:"):
            section = "dims"
            continue
        if line.startswith("variables:"):
            section = "vars"
            continue
        if line.startswith("// global attributes") or line.startswith("data:"):
            section = None
            continue
        if section == "dims" and "=" in line:
            name, value = line.split("=", 1)
            value = value.strip()  # "11 ;" or "UNLIMITED ; // (21 currently)"
            size = value.split("(")[1].split()[0] if value.startswith("UNLIMITED") else value.split()[0]
            dims[name.strip()] = int(size)
        elif section == "vars" and line.endswith(";"):
            body = line.rstrip(" ;")
            if ":" in body.split("=")[0] and "=" in body:  # an attribute: var:name = value
                left, value = body.split("=", 1)
                var, att = left.strip().split(":", 1)
                if var in variables:
                    variables[var]["attrs"][att.strip()] = value.strip()
            elif "(" in body or len(body.split()) == 2:  # a declaration: type name(dims)
                decl = body.split(None, 1)[1]
                name = decl.split("(")[0].strip()
                vdims = [d.strip() for d in decl.split("(")[1].rstrip(")").split(",")] if "(" in decl else []
                variables[name] = {"dims": vdims, "attrs": {}}
    return dims, variables


def number(text):
    """An attribute's first number ("9.96921e+36f", "-999.f", "1s")."""
    t = text.split(",")[0].strip().strip('"')
    while t and t[-1] in "fFdDsSbBlLuU":
        t = t[:-1]
    return float(t)


def read_variables(path, names):
    """The variables as float arrays of their shapes; ncdump's "_" (the fill value) and NaN become NaN, as do values
    equal to missing_value or outside valid_min/valid_max/valid_range."""
    dims, variables = parse_header(ncdump_header(path))
    out = subprocess.run(["ncdump", "-v", ",".join(names), "-p", "9,17", path], capture_output=True, text=True,
                         check=True).stdout
    data = out.split("\ndata:\n", 1)[1]
    arrays = {}
    for block in data.split(";"):
        if "=" not in block:
            continue
        name, values = block.split("=", 1)
        name = name.strip()
        if name not in names:
            continue
        vals = []
        for v in values.replace("\n", " ").split(","):
            v = v.strip()
            if not v:
                continue
            vals.append(math.nan if v == "_" or v.lower().startswith("nan") else number(v))
        a = np.array(vals, dtype=float)
        shape = tuple(dims[d] for d in variables[name]["dims"])
        a = a.reshape(shape) if shape else a
        attrs = variables[name]["attrs"]
        bad = np.zeros(a.shape, dtype=bool)
        for key in ("_FillValue", "missing_value"):
            if key in attrs:
                fill = number(attrs[key])
                bad |= np.isclose(a, fill, rtol=1e-6, atol=0.0) if fill != 0.0 else (a == 0.0)
        if "valid_min" in attrs:
            bad |= a < number(attrs["valid_min"])
        if "valid_max" in attrs:
            bad |= a > number(attrs["valid_max"])
        if "valid_range" in attrs:
            lo, hi = (number(x) for x in attrs["valid_range"].split(","))
            bad |= (a < lo) | (a > hi)
        a[bad] = math.nan
        arrays[name] = a
    missing = [n for n in names if n not in arrays]
    if missing:
        raise SystemExit("FAIL: %s: variables %s not read" % (path, missing))
    return arrays, variables


def attr(variables, name, key):
    return variables[name]["attrs"].get(key, "").strip('"').lower()


def velocity_names(variables, flags):
    """u and v: the flags' --u-var/--v-var, else by standard_name, else usual names."""
    if "--u-var" in flags:
        return flags[flags.index("--u-var") + 1], flags[flags.index("--v-var") + 1]
    found = {}
    for name in variables:
        sn = attr(variables, name, "standard_name")
        if sn.startswith("eastward_sea_water_velocity") or sn == "sea_water_x_velocity":
            found.setdefault("u", name)
        if sn.startswith("northward_sea_water_velocity") or sn == "sea_water_y_velocity":
            found.setdefault("v", name)
    for u, v in (("u", "v"), ("uo", "vo"), ("water_u", "water_v"), ("UVEL", "VVEL")):
        if "u" not in found and u in variables and v in variables:
            found.update(u=u, v=v)
    if "u" not in found or "v" not in found:
        raise SystemExit("FAIL: no velocity variables found among %s" % sorted(variables))
    return found["u"], found["v"]


def mask_names(variables, uname):
    """Land/sea mask variables on the velocities' horizontal grid."""
    hdims = variables[uname]["dims"][-2:]
    out = []
    for name, v in variables.items():
        if v["dims"][-2:] != hdims or name == uname:
            continue
        sn = attr(variables, name, "standard_name")
        fm = attr(variables, name, "flag_meanings")
        if (sn in ("land_binary_mask", "sea_binary_mask") or "land" in fm or "sea" in fm
                or name.lower() in ("mask", "mask_rho", "tmask", "lsm", "land_mask", "landmask", "sea_mask")):
            out.append(name)
    return out


def mask_land(variables, name, a):
    """Land of a mask variable: 1 = land for land_binary_mask/lsm/flag 'land', else 0 = land (sea masks)."""
    sn = attr(variables, name, "standard_name")
    fm = attr(variables, name, "flag_meanings").split()
    if sn == "land_binary_mask" or name.lower() in ("lsm", "land_mask", "landmask"):
        return np.nan_to_num(a, nan=1.0) > 0.5
    if fm and "flag_values" in variables[name]["attrs"]:
        values = [number(x) for x in variables[name]["attrs"]["flag_values"].split(",")]
        land_values = [val for val, meaning in zip(values, fm) if "land" in meaning]
        if land_values:
            return np.isnan(a) | np.isin(a, land_values)
    return np.nan_to_num(a, nan=0.0) < 0.5  # a sea mask (mask_rho, tmask, sea_binary_mask): 0 is land


def collapse(a):
    """Any over every leading (record, depth) dimension: (..., ny, nx) -> (ny, nx)."""
    while a.ndim > 2:
        a = a.any(axis=0)
    return a


# ------------------------------------------------------------------------------------------------------ the models
def local_km(p, q):
    dlon = (q[0] - p[0] + 180.0) % 360.0 - 180.0
    return dlon * math.cos(math.radians(p[1])) * KM_PER_DEG, (q[1] - p[1]) * KM_PER_DEG


class RectilinearLand:
    """A 1-D lon/lat grid: land nodes, cells with a land corner."""

    def __init__(self, path, flags):
        dims, variables = parse_header(ncdump_header(path))
        self.u, self.v = velocity_names(variables, flags)
        ydim, xdim = variables[self.u]["dims"][-2:]
        masks = mask_names(variables, self.u)
        arrays, _ = read_variables(path, [self.u, self.v, xdim, ydim] + masks)
        self.lon, self.lat = arrays[xdim], arrays[ydim]
        if self.lat[0] > self.lat[-1]:
            raise SystemExit("FAIL: %s: descending latitudes not handled by this check" % path)
        land = collapse(np.isnan(arrays[self.u]) | np.isnan(arrays[self.v]))
        self.signals = ["fill values of %s/%s: %d nodes" % (self.u, self.v, land.sum())]
        for m in masks:
            ml = collapse(mask_land(variables, m, arrays[m]))
            self.signals.append("mask %s: %d nodes" % (m, ml.sum()))
            land |= ml
        self.node_land = land
        self.cell_land = land[:-1, :-1] | land[1:, :-1] | land[:-1, 1:] | land[1:, 1:]
        dx = np.min(np.diff(self.lon)) * math.cos(math.radians(max(abs(self.lat[0]), abs(self.lat[-1]))))
        self.cell_km = min(dx, np.min(np.diff(self.lat))) * KM_PER_DEG
        jj, ii = np.nonzero(land)
        self.land_nodes = [(self.lon[i], self.lat[j]) for j, i in zip(jj, ii)]
        jj, ii = np.nonzero(self.cell_land)
        self.land_cells = [(self.lon[i], self.lon[i + 1], self.lat[j], self.lat[j + 1]) for j, i in zip(jj, ii)]

    def describe(self):
        return "%d x %d nodes, %s" % (len(self.lon), len(self.lat), "; ".join(self.signals))

    def step_km(self, pts):
        return 0.25 * self.cell_km

    def x_of(self, lon):
        return self.lon[0] + (lon - self.lon[0]) % 360.0 if lon < self.lon[0] - TOL_DEG else lon

    @staticmethod
    def spans(axis, x):
        """Indices of the intervals [axis[k], axis[k + 1]] holding x (two on a node)."""
        k = int(np.searchsorted(axis, x))
        return [c for c in (k - 1, k) if 0 <= c < len(axis) - 1 and axis[c] - TOL_DEG <= x <= axis[c + 1] + TOL_DEG]

    def sample(self, p):
        """(in land, the cells holding p, km to the nearest land node, km to the nearest land cell, km to the nearest
        water cell when in land, False: no tracer)."""
        x = self.x_of(p[0])
        cells = [(j, i) for j in self.spans(self.lat, p[1]) for i in self.spans(self.lon, x)]
        in_land = not cells or all(self.cell_land[c] for c in cells)
        q = (x, p[1])
        node = min((math.hypot(*local_km(q, n)) for n in self.land_nodes), default=math.inf)
        cell = math.inf
        for x0, x1, y0, y1 in self.land_cells:
            cx, cy = min(max(x, x0), x1), min(max(p[1], y0), y1)
            cell = min(cell, math.hypot(*local_km(q, (cx, cy))))
        water = 0.0 if not in_land else self.water_km(q)
        return in_land, cells, node, cell, water, False

    def water_km(self, q):
        """km from q to the nearest water cell."""
        best = math.inf
        for j, i in zip(*np.nonzero(~self.cell_land)):
            cx = min(max(q[0], self.lon[i]), self.lon[i + 1])
            cy = min(max(q[1], self.lat[j]), self.lat[j + 1])
            best = min(best, math.hypot(*local_km(q, (cx, cy))))
        return best


class PopLand:
    """NCL's POP sample: velocity points lat2d/lon2d, tracer t, B grid."""

    def __init__(self, path, flags):
        dims, variables = parse_header(ncdump_header(path))
        self.u, self.v = velocity_names(variables, flags)
        a, _ = read_variables(path, [self.u, self.v, "t", "lat2d", "lon2d"])
        lat, lon = a["lat2d"], a["lon2d"]
        lon = np.where(lon > 180.0, lon - 360.0, lon)
        fill = collapse(np.isnan(a[self.u]) | np.isnan(a[self.v]))
        tracer = collapse(np.isnan(a["t"]))
        # velocity point (j, i) is a corner of tracer cells (j, i), (j, i + 1), (j + 1, i), (j + 1, i + 1)
        t_up = np.vstack([tracer[1:], tracer[-1:]])  # row j + 1 (the last row repeated)
        around = tracer | np.roll(tracer, -1, axis=1) | t_up | np.roll(t_up, -1, axis=1)
        node = fill | around
        # the quadrilateral of velocity points (j-1, i-1), (j-1, i), (j, i), (j, i-1): pop_route_check's cell (j, i)
        n_dn = np.vstack([node[:1], node[:-1]])
        cell = node | np.roll(node, 1, axis=1) | n_dn | np.roll(n_dn, 1, axis=1)
        self.lat, self.lon = lat, lon
        self.node_land, self.tracer_land = node, tracer
        self.cells = Cells(lat, lon, cell)
        self.signals = ["fill values of %s/%s: %d velocity points" % (self.u, self.v, fill.sum()),
                        "missing tracer t: %d cells" % tracer.sum(),
                        "velocity points in land: %d" % node.sum()]

    def describe(self):
        return "%d x %d velocity points (B grid), %s" % (self.lat.shape[1], self.lat.shape[0], "; ".join(self.signals))

    def step_km(self, pts):
        """A quarter of the smallest cell edge near the route, 2 km at most."""
        lo0, lo1 = min(p[0] for p in pts) - 3, max(p[0] for p in pts) + 3
        la0, la1 = min(p[1] for p in pts) - 3, max(p[1] for p in pts) + 3
        lat, lon = self.lat, self.lon
        near = ((lon >= lo0) & (lon <= lo1) & (lat >= la0) & (lat <= la1))[:-1, :-1]
        e = math.inf
        for b_lat, b_lon in ((lat[:-1, 1:], lon[:-1, 1:]), (lat[1:, :-1], lon[1:, :-1])):  # east and north edges
            dlon = (b_lon - lon[:-1, :-1] + 180.0) % 360.0 - 180.0
            km = np.hypot(dlon * np.cos(np.radians(lat[:-1, :-1])), b_lat - lat[:-1, :-1]) * KM_PER_DEG
            if near.any():
                e = min(e, float(km[near].min()))
        return min(2.0, 0.25 * e)

    def sample(self, p):
        """(in land, the cells holding p, km to the nearest land velocity point, km to the nearest land cell, km to the
        nearest water cell, the tracer cells holding p all masked)."""
        c = self.cells
        j0, i0 = c.nearest_node(p)
        holding, clearance, water = [], math.inf, math.inf
        for j in range(max(1, j0 - 4), min(c.ny - 1, j0 + 5) + 1):
            for di in range(-4, 6):
                i = (i0 + di) % c.nx
                d = c.distance(p, j, i)
                if d <= 1e-6:  # km: inside or on the edge
                    holding.append((j, i))
                if c.land[j, i]:
                    clearance = min(clearance, d)
                else:
                    water = min(water, d)
        if not holding:
            raise SystemExit("FAIL: no POP cell holds %.5f, %.5f" % p)
        in_land = all(c.land[h] for h in holding)
        tracer = all(self.tracer_land[h] for h in holding)
        js, ii = slice(max(0, j0 - 6), j0 + 7), [(i0 + k) % c.nx for k in range(-6, 7)]
        lat, lon, land = self.lat[js][:, ii], self.lon[js][:, ii], self.node_land[js][:, ii]
        dlon = (lon - p[0] + 180.0) % 360.0 - 180.0
        d = np.hypot(dlon * math.cos(math.radians(p[1])), lat - p[1]) * KM_PER_DEG
        node = float(d[land].min()) if land.any() else math.inf
        return in_land, holding, node, clearance, water, tracer


# ----------------------------------------------------------------------------------------------------------- route
def route_points(out):
    """The densest line of the route: path.geojson's path feature or path.csv (lon, lat)."""
    with open(os.path.join(out, "path.csv")) as f:
        csv_pts = [(float(r["lon"]), float(r["lat"])) for r in csv.DictReader(f)]
    geo_pts = []
    gj = os.path.join(out, "path.geojson")
    if os.path.exists(gj):
        with open(gj) as f:
            doc = json.load(f)
        for feat in doc.get("features", []):
            g = feat.get("geometry") or {}
            if g.get("type") == "LineString":
                geo_pts = [tuple(c[:2]) for c in g["coordinates"]]
                break
            if g.get("type") == "MultiLineString":
                geo_pts = [tuple(c[:2]) for part in g["coordinates"] for c in part]
                break
    return (geo_pts, "path.geojson") if len(geo_pts) >= len(csv_pts) else (csv_pts, "path.csv")


def densify(points, step_km):
    """pop_route_check.samples(), longitudes wrapped to -180..180."""
    return [((lon + 180.0) % 360.0 - 180.0, lat) for lon, lat in samples(points, step_km)]


def check_route(model, out):
    """(line source, its points, samples, [(p, cells, km into land)] in land, closest km to a land node, to a land
    cell, notes)."""
    pts, source = route_points(out)
    samples = densify(pts, model.step_km(pts))
    in_land, node_km, cell_km = [], math.inf, math.inf
    tracer_hits = 0
    for p in samples:
        land, cells, node, cell, water, tracer = model.sample(p)
        node_km, cell_km = min(node_km, node), min(cell_km, cell)
        if land:
            in_land.append((p, cells, water))
        tracer_hits += tracer
    notes = []
    if isinstance(model, PopLand):
        notes.append("%d samples in a masked tracer cell" % tracer_hits)
    return source, len(pts), samples, in_land, node_km, cell_km, notes


def days_hours(seconds):
    return "%.2f d (%.1f h)" % (seconds / 86400.0, seconds / 3600.0)


def main():
    glider_plan, repo, work = sys.argv[1:4]
    glider_plan = os.path.abspath(glider_plan)
    bundled = sorted(os.path.relpath(p, repo) for p in glob.glob(os.path.join(repo, "examples", "*.nc")))
    failures = []
    for f in bundled:
        if f not in TRIPS:
            failures.append("%s is bundled but has no trips in this check" % f)
    rows = []
    t_start = time.time()
    for f, (flags, trips) in TRIPS.items():
        path = f if os.path.isabs(f) else os.path.join(repo, f)
        if not os.path.isfile(path):
            hint = " (scripts/setup.sh installs it: Debian package libncarg-data)" if f == POP else ""
            failures.append("%s is missing%s" % (path, hint))
            continue
        model = PopLand(path, flags) if f == POP else RectilinearLand(path, flags)
        print("%s: %s" % (f, model.describe()))
        flags = [os.path.join(repo, x) if x.startswith("examples/") else x for x in flags]
        for name, start, goal, speed in trips:
            out = os.path.join(work, os.path.basename(f).replace(".nc", "") + "_" + name)
            cmd = [glider_plan, "--currents", path, "--start=" + start, "--goal=" + goal, "--speed", str(speed),
                   "--out", out] + flags
            t0 = time.time()
            r = subprocess.run(cmd, capture_output=True, text=True)
            wall = time.time() - t0
            label = "%s %s (%s -> %s)" % (os.path.basename(f), name, start, goal)
            if r.returncode != 0 or not os.path.exists(os.path.join(out, "path.csv")):
                failures.append("%s: expected a route, glider_plan exit %d" % (label, r.returncode))
                print(r.stdout[-2000:] + r.stderr[-2000:])
                continue
            with open(os.path.join(out, "summary.json")) as fh:
                summary = json.load(fh)
            if summary.get("solved") is not True:
                failures.append("%s: summary.json says solved = %s" % (label, summary.get("solved")))
            t1 = time.time()
            source, n_pts, samples, in_land, node_km, cell_km, notes = check_route(model, out)
            notes.append("checked in %.1f s" % (time.time() - t1))
            rows.append((os.path.basename(f), name, days_hours(summary["travel_time"]), len(samples), len(in_land),
                         node_km, cell_km, summary.get("route_model"), wall))
            print("  %s: %d points of %s (%s), %d samples, %d in land%s; %.1f s" %
                  (name, n_pts, source, summary.get("route_model"), len(samples), len(in_land),
                   "".join("; " + n for n in notes), wall))
            for p, cells, water in in_land[:10]:
                print("    in land: %.6f, %.6f, %.3f km from the water (cells (j, i) %s)" % (p[0], p[1], water, cells))
            if in_land:
                failures.append("%s: %d of %d samples in the file's land, the first at %.6f, %.6f" %
                                (label, len(in_land), len(samples), in_land[0][0][0], in_land[0][0][1]))
    print()
    print("| file | trip | travel time | samples | in land | closest land node | closest land cell | route | run |")
    print("|---|---|---|---:|---:|---:|---:|---|---:|")
    for f, name, tt, ns, nl, node_km, cell_km, model, wall in rows:
        km = lambda v: "none" if not math.isfinite(v) else "%.2f km" % v  # noqa: E731
        print("| %s | %s | %s | %d | %d | %s | %s | %s | %.1f s |" % (f, name, tt, ns, nl, km(node_km), km(cell_km),
                                                                       model, wall))
    print("\n%d routes in %.1f s" % (len(rows), time.time() - t_start))
    if failures:
        for msg in failures:
            print("FAIL: " + msg, file=sys.stderr)
        sys.exit(1)
    print("PASS")


if __name__ == "__main__":
    main()
