#!/usr/bin/env python3
"""glider_plan --currents on a Zarr store and a GRIB2 file, read through GDAL's multidimensional API.

Usage: check_gdal_sources.py GLIDER_PLAN

One forecast (a CMEMS-like layout: uo/vo in m s-1 on time, depth, latitude, longitude, float32, an island of NaN) is
written by xarray (Debian's python3-xarray, python3-zarr) as NetCDF and as two Zarr v2 stores with consolidated
metadata, as Copernicus Marine publishes them: time-chunked (1, 1, ny, nx), blosc/zstd, and geo-chunked
(nt, 1, 8, 8), blosc/lz4. Checked:
  1. each store plans with the NetCDF file's travel time (1e-12) and the same waypoints;
  2. the geo-chunked store served by a loopback HTTP server plans the same, and the trip's chunks only are requested
     (fewer than half of the store's velocity chunks); a store whose chunk keys nest in folders plans the same;
     With --cache: a second run asks the server nothing and plans to the bit (the report says so); a store
     republished at the URL (its metadata changed) is refused for a trip that needs chunks the cache lacks, naming
     the URL and the cache folder; a folder of another URL at the cache's place is replaced;
     With --cache: a second run asks the server nothing and plans to the bit (the report says so); a store
     republished at the URL (its metadata changed) is refused for a trip that needs chunks the cache lacks, naming
     the URL and the cache folder; a folder of another URL at the cache's place is replaced;
  3. garbage: a store whose metadata is not JSON (served), a chunk that is not blosc (on disk): exit 2 naming the
     URL, or the store and the variable;
  4. a server too slow (2 s limit, one retry) or down: exit 2 naming the URL, soon; nothing written;
  5. a GRIB2 file written by GDAL's GRIB driver (UOGRD/VOGRD, discipline 10, complex packing with a missing value,
     the records of a parameter in a row) plans with the travel time of the same decoded values in NetCDF (1e-12),
     found by the GRIB parameters' standard names and by --u-var UOGRD --v-var VOGRD alike;
  6. the same as one GRIB2 file per forecast time (RTOFS's layout), given by a pattern: the same travel time;
     the single GRIB2 file served over HTTP: fetched whole in one request, the same travel time; with --cache the
     second run asks nothing;
  7. the same in one file whose fields of each time are interleaved (U, V, U, V): the same travel time;
  8. such a file with one field missing at one time: exit 2 naming the file.
"""
import functools
import http.server
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

if __name__ == "__main__" and os.environ.get("OMPL_GLIDER_REEXEC") is None:
    try:
        import xarray  # noqa: F401
        import zarr  # noqa: F401
    except ImportError:  # pyenv's python3 first on PATH: Debian's has python3-xarray and python3-zarr
        if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != "/usr/bin/python3":
            os.environ["OMPL_GLIDER_REEXEC"] = "1"
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        raise

import numcodecs
import numpy as np
import pandas as pd
import xarray as xr

failures = []
TRIP = ["--start=-74.2,30.4", "--goal=-72.1,32.3", "--speed", "0.5", "--departure", "2026-06-01T03:00:00Z",
        "--beyond", "hold"]


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what, flush=True)
    if not cond:
        failures.append(what)


def forecast(nt=6, ny=81, nx=97):
    """A meandering jet over 6 days on a 1/8 degree grid of 12 x 10 degrees, two levels, an island of NaN."""
    lon = -76.0 + 0.125 * np.arange(nx)
    lat = 29.0 + 0.125 * np.arange(ny)
    X, Y = np.meshgrid(lon, lat)
    u = np.empty((nt, 2, ny, nx), "f4")
    v = np.empty((nt, 2, ny, nx), "f4")
    for k in range(nt):
        jet = 0.8 * np.exp(-((Y - 31.0 - 0.8 * np.sin(0.9 * X + 0.3 * k)) / 0.9) ** 2)
        for m in range(2):
            u[k, m] = (jet + 0.05) * (1.0 - 0.3 * m)
            v[k, m] = 0.3 * np.cos(0.9 * X + 0.3 * k) * jet * (1.0 - 0.3 * m)
    island = np.hypot(X + 73.0, (Y - 31.6) * 1.2) < 0.35
    u[:, :, island] = np.nan
    v[:, :, island] = np.nan
    return xr.Dataset(
        {"uo": (("time", "depth", "latitude", "longitude"), u,
                {"units": "m s-1", "standard_name": "eastward_sea_water_velocity"}),
         "vo": (("time", "depth", "latitude", "longitude"), v,
                {"units": "m s-1", "standard_name": "northward_sea_water_velocity"})},
        coords={"time": pd.date_range("2026-06-01", periods=nt, freq="D"),
                "depth": ("depth", np.array([0.494, 1.541]), {"units": "m", "positive": "down"}),
                "latitude": ("latitude", lat, {"units": "degrees_north", "standard_name": "latitude"}),
                "longitude": ("longitude", lon, {"units": "degrees_east", "standard_name": "longitude"})})


def write_nested_store(ds, path, chunks):
    """@p ds as a Zarr v2 store whose chunk keys nest in folders (dimension_separator "/": uo/0/0/1/2)."""
    import zarr
    encoding = {v: {"chunks": chunks, "compressor": numcodecs.Blosc(cname="zstd")} for v in ("uo", "vo")}
    ds.to_zarr(zarr.storage.NestedDirectoryStore(path), encoding=encoding, consolidated=True)


def write_store(ds, path, chunks, cname):
    comp = numcodecs.Blosc(cname=cname, clevel=5, shuffle=numcodecs.Blosc.SHUFFLE)
    enc = {n: {"chunks": chunks, "compressor": comp} for n in ("uo", "vo")}
    enc["time"] = {"units": "hours since 1950-01-01", "dtype": "f8"}
    ds.to_zarr(path, encoding=enc, consolidated=True, mode="w")


# Every plan here, of a NetCDF file and of a store or GRIB file alike, is the lattice search alone: the readers are
# what this checks, and two readers of the same values must give the same route under any one pipeline (the global
# check and the refinement, seconds per plan, run on forecasts in the tests of mission/).
PIPELINE = ["--no-global-check", "--no-refine"]


def plan(glider, args, timeout=120):
    return subprocess.run([glider] + args + PIPELINE, capture_output=True, text=True, timeout=timeout)


def travel_time(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["travel_time"]


def read(path):
    with open(path) as f:
        return f.read()


class Logged(http.server.SimpleHTTPRequestHandler):
    """Serves a folder and keeps the paths asked for."""

    def log_message(self, *args):
        pass

    def do_GET(self):
        self.server.asked.append(self.path)
        super().do_GET()


class Slow(Logged):
    """Answers every request after 30 s."""

    def do_GET(self):
        time.sleep(30)
        super().do_GET()

    def do_HEAD(self):
        time.sleep(30)
        super().do_HEAD()


def serve(root, handler=Logged):
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(handler, directory=root))
    server.daemon_threads = True
    server.asked = []
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def write_grib_hours(ds, folder):
    """The surface level of @p ds as RTOFS lays it out: one GRIB2 file per forecast time (f000.grib2, f024.grib2,
    ...), each holding UOGRD then VOGRD of that time; returns the file names."""
    names = []
    for k in range(ds.sizes["time"]):
        hours = int((ds.time.values[k] - ds.time.values[0]) / np.timedelta64(1, "h"))
        name = os.path.join(folder, "f%03d.grib2" % hours)
        write_grib(ds.isel(time=[k]), name, first_hour=hours)
        names.append(name)
    return names


def write_grib(ds, path, first_hour=0, interleaved=False):
    """The surface level of @p ds as GRIB2 through GDAL's GRIB driver: UOGRD for each time, then VOGRD (interleaved:
    UOGRD and VOGRD of each time in turn, as an ERA5-like download orders its fields) (discipline 10,
    category 1, parameters 2 and 3), complex packing with a missing value for the island (1 mm/s steps), latitude
    rows north first, as RTOFS writes them."""
    from osgeo import gdal, osr
    gdal.UseExceptions()
    nt, ny, nx = ds.sizes["time"], ds.sizes["latitude"], ds.sizes["longitude"]
    lon, lat = ds.longitude.values, ds.latitude.values
    mem = gdal.GetDriverByName("MEM").Create("", nx, ny, 2 * nt, gdal.GDT_Float32)
    mem.SetGeoTransform((lon[0] - 0.0625, 0.125, 0.0, lat[-1] + 0.0625, 0.0, -0.125))
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(4326)
    mem.SetProjection(srs.ExportToWkt())
    options = ["DATA_ENCODING=COMPLEX_PACKING", "DECIMAL_SCALE_FACTOR=3"]
    hours = first_hour + (ds.time.values - ds.time.values[0]) / np.timedelta64(1, "h")
    for j, (name, parameter) in enumerate((("uo", 2), ("vo", 3))):
        for k in range(nt):
            band = 1 + (2 * k + j if interleaved else j * nt + k)
            values = ds[name].values[k, 0][::-1]  # north first
            mem.GetRasterBand(band).WriteArray(np.where(np.isnan(values), 9999.0, values).astype("f4"))
            mem.GetRasterBand(band).SetNoDataValue(9999.0)
            options += ["BAND_%d_DISCIPLINE=10" % band,
                        "BAND_%d_IDS=CENTER=7 SUBCENTER=0 MASTER_TABLE=2 LOCAL_TABLE=0 SIGNF_REF_TIME=1 "
                        "REF_TIME=2026-06-01T00:00:00Z PROD_STATUS=0 TYPE=1" % band,
                        "BAND_%d_PDS_PDTN=0" % band,
                        "BAND_%d_PDS_TEMPLATE_ASSEMBLED_VALUES=1 %d 2 0 0 0 0 1 %d 160 0 0 255 0 0"
                        % (band, parameter, int(hours[k]))]
    gdal.GetDriverByName("GRIB").CreateCopy(path, mem, options=options)


def grib_as_netcdf(grib, like, path):
    """The values GDAL decodes from @p grib (NaN where missing) on the grid and times of @p like, as NetCDF: the same
    data as the GRIB file, whatever its packing rounded."""
    from osgeo import gdal
    gdal.UseExceptions()
    g = gdal.OpenEx(grib, gdal.OF_MULTIDIM_RASTER).GetRootGroup()
    out = like.isel(depth=[0]).copy(deep=True)
    for name, array in (("uo", "UOGRD_0-DBSL"), ("vo", "VOGRD_0-DBSL")):
        a = g.OpenMDArray(array)
        values = a.ReadAsArray().astype("f8")
        nodata = a.GetNoDataValueAsDouble()
        if nodata is not None:
            values[values == nodata] = np.nan
        out[name] = (("time", "depth", "latitude", "longitude"), values[:, None], out[name].attrs)  # Y south first
    out.to_netcdf(path, encoding={n: {"dtype": "f8"} for n in ("uo", "vo")})


WIDE = ["--start=-75.5,29.5", "--goal=-66.5,37.5", "--speed", "0.5", "--departure", "2026-06-01T03:00:00Z",
        "--beyond", "hold"]


def rewrite_values(store, ds):
    """Writes the velocities of @p ds into @p store in place: its .zarray/.zattrs/.zmetadata and coordinates kept
    to the byte (checked)."""
    import zarr
    names = [os.path.join(d, f) for d in (store, os.path.join(store, "uo"), os.path.join(store, "time"))
             for f in (".zmetadata", ".zarray", ".zattrs") if os.path.exists(os.path.join(d, f))]
    names += [os.path.join(store, "time", f) for f in os.listdir(os.path.join(store, "time")) if f[0] != "."]
    before = {n: open(n, "rb").read() for n in names}
    group = zarr.open_group(store, mode="r+")
    for name in ("uo", "vo"):
        group[name][...] = ds[name].values
    return all(open(n, "rb").read() == b for n, b in before.items())


def check_rewritten_values(glider, work, root, geo_chunked, time_chunked, server, ds):
    """A store whose values are rewritten (same metadata, same coordinates): over HTTP with --cache, a trip beyond
    the cache is refused naming the chunk that changed and the folder to remove (the plan would mix the cached
    chunks with the new ones), then, the folder removed, plans as the new values in NetCDF; on disk (no cache) the
    new values are read at once."""
    new = ds.copy(deep=True)
    # another flow: the jet and the island moved 10 rows north, v reversed
    new["uo"].values[...] = np.roll(ds["uo"].values, 10, axis=2)
    new["vo"].values[...] = -np.roll(ds["vo"].values, 10, axis=2)
    new_nc = os.path.join(work, "rewritten.nc")
    new.to_netcdf(new_nc)
    p = plan(glider, ["--currents", new_nc, "--out", os.path.join(work, "o_rw_nc")] + WIDE)
    check(p.returncode == 0, "rewritten values in NetCDF plan (exit %d: %s)" % (p.returncode, p.stderr[-300:]))
    if p.returncode:
        return
    t_new = travel_time(os.path.join(work, "o_rw_nc"))
    store = os.path.join(root, "rewritten.zarr")
    shutil.copytree(geo_chunked, store)
    url = "http://127.0.0.1:%d/rewritten.zarr" % server.server_address[1]
    cache = os.path.join(work, "cache_rw")
    p = plan(glider, ["--currents", url, "--cache", cache, "--out", os.path.join(work, "o_rw_first")] + TRIP)
    check(p.returncode == 0, "rewritten: the first run fills the cache (exit %d: %s)" % (p.returncode,
                                                                                       p.stderr[-300:]))
    time.sleep(1.1)  # a Last-Modified of another second (the loopback server gives no ETag)
    check(rewrite_values(store, new), "rewritten: the store's metadata and coordinates unchanged to the byte")
    out = os.path.join(work, "o_rw_mixed")
    p = plan(glider, ["--currents", url, "--cache", cache, "--out", out] + WIDE)
    check(p.returncode == 2 and "differs from the cache's" in p.stderr and "would be mixed" in p.stderr and
          url in p.stderr and cache in p.stderr, "rewritten values over HTTP, a trip beyond the cache: exit 2 naming "
          "the chunk, the URL and the cache folder (exit %d: %s)" % (p.returncode, p.stderr[-400:]))
    check(not os.path.exists(out), "rewritten values over HTTP: no output directory")
    # the same trip within the cache: the cached forecast as a whole (a snapshot), no request
    before = len(server.asked)
    p = plan(glider, ["--currents", url, "--cache", cache, "--out", os.path.join(work, "o_rw_snapshot")] + TRIP)
    check(p.returncode == 0 and server.asked[before:] == [] and
          travel_time(os.path.join(work, "o_rw_snapshot")) == travel_time(os.path.join(work, "o_rw_first")),
          "rewritten values, a trip within the cache: the cached snapshot, no request (exit %d)" % p.returncode)
    shutil.rmtree(cache)
    p = plan(glider, ["--currents", url, "--cache", cache, "--out", os.path.join(work, "o_rw_fresh")] + WIDE)
    check(p.returncode == 0 and abs(travel_time(os.path.join(work, "o_rw_fresh")) - t_new) <= 1e-12 * t_new,
          "rewritten values over HTTP, the cache removed: the new values' travel time (exit %d: %s)" %
          (p.returncode, p.stderr[-300:]))
    # on disk: no cache, the values as they are now
    local = os.path.join(work, "local_rw.zarr")
    shutil.copytree(time_chunked, local)
    p = plan(glider, ["--currents", local, "--out", os.path.join(work, "o_rw_local0")] + WIDE)
    check(rewrite_values(local, new), "rewritten on disk: metadata and coordinates unchanged to the byte")
    p = plan(glider, ["--currents", local, "--out", os.path.join(work, "o_rw_local")] + WIDE)
    check(p.returncode == 0 and abs(travel_time(os.path.join(work, "o_rw_local")) - t_new) <= 1e-12 * t_new,
          "rewritten values on disk: the new values' travel time (exit %d: %s)" % (p.returncode, p.stderr[-300:]))


def check_cut_grib(glider, work, grib):
    """A GRIB2 file cut inside a message, and at the end of a message (the VOGRD messages after it lost): exit 2
    naming the file and what is wrong with it, never "no northward (v) velocity"."""
    import struct
    data = open(grib, "rb").read()
    ends, at = [], 0
    while at < len(data):
        at += struct.unpack(">Q", data[at + 8:at + 16])[0]
        ends.append(at)
    cut = os.path.join(work, "cut.grib2")
    for label, size, phrase in (("inside a message", len(data) // 2 + 7, "the file is truncated"),
                                ("at a message's end", ends[len(ends) // 2 - 1], "holds UOGRD but no VOGRD")):
        with open(cut, "wb") as f:
            f.write(data[:size])
        p = plan(glider, ["--currents", cut, "--out", os.path.join(work, "o_cut")] + TRIP)
        check(p.returncode == 2 and "GRIB file '%s'" % cut in p.stderr and phrase in p.stderr and
              "velocity found" not in p.stderr, "GRIB2 cut %s: exit 2 naming the file, '%s' (exit %d: %s)" %
              (label, phrase, p.returncode, p.stderr[-300:]))
        check(not os.path.exists(os.path.join(work, "o_cut")), "GRIB2 cut %s: no output directory" % label)


def check_not_dap(glider, work, root, server, t_nc):
    """A Zarr store served at a URL without .zarr (taken for OPeNDAP) and a web page: exit 2 saying what the server
    holds and what was expected, the page never printed; the store given as ZARR:URL plans as the NetCDF file."""
    port = server.server_address[1]
    os.symlink("geo.zarr", os.path.join(root, "geostore"))
    bare = "http://127.0.0.1:%d/geostore" % port
    page = "http://127.0.0.1:%d/page" % port
    with open(os.path.join(root, "page"), "w") as f:
        f.write("<html><body>a landing page</body></html>")
    mission = os.path.join(work, "bare.yaml")
    with open(mission, "w") as f:
        f.write("current: {type: netcdf, file: '%s'}\nstart: {lon: -74.2, lat: 30.4}\ngoal: {lon: -72.1, lat: 32.3}\n"
                "vehicle: {speed: 0.5}\ndeparture: {time: 2026-06-01T03:00:00Z}\n" % bare)
    for label, args, phrases in (
            ("a store's URL without .zarr", ["--currents", bare] + TRIP, [bare, "ZARR:" + bare, "Zarr store"]),
            ("the same in a mission file", ["--mission", mission], ["bare.yaml", "ZARR:" + bare]),
            ("a web page", ["--currents", page] + TRIP, [page, "HTML page", "ending in .zarr"])):
        out = os.path.join(work, "o_notdap")
        p = plan(glider, args + ["--out", out])
        lines = p.stderr.strip().splitlines()
        check(p.returncode == 2 and all(x in p.stderr for x in phrases) and "<html" not in p.stderr.lower() and
              "<!doctype" not in p.stderr.lower() and len(lines) <= 3 and not os.path.exists(out),
              "%s: exit 2 saying what the server holds, no HTML, no output (exit %d: %s)" %
              (label, p.returncode, p.stderr[-400:]))
    out = os.path.join(work, "o_zarr_prefix")
    p = plan(glider, ["--currents", "ZARR:" + bare, "--out", out] + TRIP)
    check(p.returncode == 0 and travel_time(out) == t_nc, "the store as ZARR:URL plans as the NetCDF file (exit %d: "
          "%s)" % (p.returncode, p.stderr[-300:]))


def main():
    glider = sys.argv[1]
    work = tempfile.mkdtemp(prefix="ompl_glider_gdal_")
    server = None
    try:
        ds = forecast()
        nc = os.path.join(work, "cmems.nc")
        ds.to_netcdf(nc)
        root = os.path.join(work, "srv")
        os.makedirs(root)
        time_chunked, geo_chunked = os.path.join(root, "time.zarr"), os.path.join(root, "geo.zarr")
        write_store(ds, time_chunked, (1, 1, ds.sizes["latitude"], ds.sizes["longitude"]), "zstd")
        write_store(ds, geo_chunked, (ds.sizes["time"], 1, 8, 8), "lz4")

        # 1. each store plans as the NetCDF file
        p_nc = plan(glider, ["--currents", nc, "--out", os.path.join(work, "o_nc")] + TRIP)
        check(p_nc.returncode == 0, "the NetCDF file plans (exit %d: %s)" % (p_nc.returncode, p_nc.stderr[-300:]))
        if p_nc.returncode:
            return
        t_nc = travel_time(os.path.join(work, "o_nc"))
        for name, store in (("time-chunked", time_chunked), ("geo-chunked", geo_chunked)):
            out = os.path.join(work, "o_" + name)
            p = plan(glider, ["--currents", store, "--out", out] + TRIP)
            check(p.returncode == 0, "%s store plans (exit %d: %s)" % (name, p.returncode, p.stderr[-300:]))
            if p.returncode == 0:
                t = travel_time(out)
                check(abs(t - t_nc) <= 1e-12 * t_nc, "%s store: the NetCDF file's travel time (%r, %r)" %
                      (name, t, t_nc))
                check(read(os.path.join(out, "waypoints.csv")) == read(os.path.join(work, "o_nc", "waypoints.csv")),
                      "%s store: the same waypoints.csv" % name)
                # named as what it is, in the report and summary.json
                check("current gridded (Zarr store)" in p.stdout, "%s store: the report says Zarr store" % name)
                check(json.load(open(os.path.join(out, "summary.json")))["current_source"] == "Zarr store",
                      "%s store: summary.json current_source" % name)

        # 2. the geo-chunked store over HTTP: the same plan, only the trip's chunks asked for
        server = serve(root)
        url = "http://127.0.0.1:%d/geo.zarr" % server.server_address[1]
        out = os.path.join(work, "o_url")
        p = plan(glider, ["--currents", url, "--out", out] + TRIP)
        check(p.returncode == 0, "the store over HTTP plans (exit %d: %s)" % (p.returncode, p.stderr[-300:]))
        if p.returncode == 0:
            t = travel_time(out)
            check(abs(t - t_nc) <= 1e-12 * t_nc, "over HTTP: the NetCDF file's travel time (%r, %r)" % (t, t_nc))
            chunks = [a for a in server.asked if a.startswith("/geo.zarr/uo/") or a.startswith("/geo.zarr/vo/")]
            chunks = [a for a in chunks if not a.rsplit("/", 1)[-1].startswith(".")]
            total = sum(len([f for f in os.listdir(os.path.join(geo_chunked, v)) if not f.startswith(".")])
                        for v in ("uo", "vo"))
            check(0 < len(chunks) < total / 2, "over HTTP: %d velocity chunks asked for of the store's %d" %
                  (len(chunks), total))
            check(len(set(chunks)) == len(chunks), "over HTTP: no chunk asked for twice (%d, %d distinct)" %
                  (len(chunks), len(set(chunks))))

        # 2a. a store whose chunk keys nest in folders (dimension_separator "/"), over HTTP: the same plan
        nested = os.path.join(root, "nested.zarr")
        write_nested_store(ds, nested, (ds.sizes["time"], 1, 8, 8))
        out = os.path.join(work, "o_nested")
        nested_url = "http://127.0.0.1:%d/nested.zarr" % server.server_address[1]
        p = plan(glider, ["--currents", nested_url, "--out", out] + TRIP)
        check(p.returncode == 0 and travel_time(out) == t_nc, "a nested store over HTTP: the NetCDF file's travel "
              "time (exit %d: %s)" % (p.returncode, p.stderr[-300:]))

        # 2a'. a store's URL without .zarr, and a web page, where NetCDF-C expects OPeNDAP
        check_not_dap(glider, work, root, server, t_nc)

        # 2b. the cache: the first run fills it, the second asks the server nothing; a republished store is refused
        cache = os.path.join(work, "cache")
        cached_times = []
        for run in ("first", "second"):
            out = os.path.join(work, "o_cache_" + run)
            before = len(server.asked)
            p = plan(glider, ["--currents", url, "--cache", cache, "--out", out] + TRIP)
            check(p.returncode == 0 and "ERROR" not in p.stderr, "cache, %s run plans, no stray message (exit %d: %s)" %
                  (run, p.returncode, p.stderr[-300:]))
            if p.returncode:
                continue
            cached_times.append(travel_time(out))
            asked = server.asked[before:]
            if run == "first":
                check(len(asked) > 0, "cache, first run: the store fetched (%d requests)" % len(asked))
            else:
                check(asked == [], "cache, second run: no request to the server (%d: %s)" % (len(asked), asked[:3]))
                notes = json.dumps(json.load(open(os.path.join(out, "summary.json"))))
                check("read from the cache, no network" in notes, "cache, second run: the report says so")
        check(len(cached_times) == 2 and cached_times[0] == cached_times[1] and abs(cached_times[0] - t_nc) <= 1e-12
              * t_nc, "cache: both runs plan the NetCDF file's travel time (%r, %r)" % (cached_times, t_nc))
        folders = os.listdir(cache)
        check(len(folders) == 1 and folders[0].endswith(".zarr"), "cache: one folder for the store (%s)" % folders)
        meta = os.path.join(geo_chunked, ".zmetadata")
        kept = read(meta)
        doc = json.loads(kept)
        doc["metadata"][".zattrs"]["history"] = "republished with new values"
        with open(meta, "w") as f:
            json.dump(doc, f)
        out = os.path.join(work, "o_republished")
        p = plan(glider, ["--currents", url, "--cache", cache, "--out", out, "--start=-75.5,29.5", "--goal=-66.5,37.5",
                          "--speed", "0.5", "--departure", "2026-06-01T03:00:00Z", "--beyond", "hold"])
        check(p.returncode == 2 and "republished" in p.stderr and url in p.stderr and cache in p.stderr,
              "cache: a republished store is refused for a trip beyond the cache (exit %d: %s)" %
              (p.returncode, p.stderr[-300:]))
        check(not os.path.exists(out), "cache: republished, no output directory")
        with open(meta, "w") as f:
            f.write(kept)
        with open(os.path.join(cache, folders[0], ".ompl_glider_source"), "w") as f:
            f.write("http://elsewhere.example/other.zarr")
        out = os.path.join(work, "o_cache_other")
        p = plan(glider, ["--currents", url, "--cache", cache, "--out", out] + TRIP)
        check(p.returncode == 0 and travel_time(out) == t_nc, "cache: another URL's folder is replaced, the plan "
              "the same (exit %d: %s)" % (p.returncode, p.stderr[-300:]))
        if p.returncode == 0:
            notes = json.dumps(json.load(open(os.path.join(out, "summary.json"))))
            check("elsewhere.example" in notes, "cache: the report names the folder's other source")

        # 2c. values rewritten under the same metadata and coordinates: never old chunks beside new ones
        check_rewritten_values(glider, work, root, geo_chunked, time_chunked, server, ds)

        # 3. garbage: a store whose metadata is not JSON, served; a chunk that is not blosc, on disk
        bad = os.path.join(root, "bad.zarr")
        os.makedirs(bad)
        for name in (".zmetadata", ".zgroup"):
            with open(os.path.join(bad, name), "w") as f:
                f.write("<html>502 Bad Gateway</html>")
        bad_url = "http://127.0.0.1:%d/bad.zarr" % server.server_address[1]
        p = plan(glider, ["--currents", bad_url, "--out", os.path.join(work, "o_bad")] + TRIP)
        check(p.returncode == 2 and bad_url in p.stderr, "garbage metadata over HTTP: exit 2 naming the URL (exit %d: "
              "%s)" % (p.returncode, p.stderr[-300:]))
        broken = os.path.join(work, "broken.zarr")
        shutil.copytree(time_chunked, broken)
        for k in range(ds.sizes["time"]):
            with open(os.path.join(broken, "uo", "%d.0.0.0" % k), "wb") as f:
                f.write(b"not a blosc chunk")
        p = plan(glider, ["--currents", broken, "--out", os.path.join(work, "o_broken")] + TRIP)
        check(p.returncode == 2 and broken in p.stderr and "uo" in p.stderr,
              "a corrupt chunk: exit 2 naming the store and the variable (exit %d: %s)" % (p.returncode,
                                                                                         p.stderr[-300:]))
        check(not os.path.exists(os.path.join(work, "o_broken")), "a corrupt chunk: no output directory")

        # 3b. a server too slow: every answer after 30 s, a request time limit of 2 s and one retry
        slow = serve(root, Slow)
        slow_url = "http://127.0.0.1:%d/geo.zarr" % slow.server_address[1]
        started = time.monotonic()
        p = plan(glider, ["--currents", slow_url, "--request-timeout", "2", "--retries", "1", "--out",
                          os.path.join(work, "o_slow")] + TRIP)
        waited = time.monotonic() - started
        check(p.returncode == 2 and slow_url in p.stderr, "slow server: exit 2 naming the URL (exit %d: %s)" %
              (p.returncode, p.stderr[-300:]))
        check(waited < 20, "slow server: gave up within the time limit and its retry (%.1f s)" % waited)
        slow.shutdown()
        slow.server_close()

        # 4. a server that is down
        server.shutdown()
        server.server_close()
        server = None
        down = os.path.join(work, "o_down")
        p = plan(glider, ["--currents", url, "--request-timeout", "5", "--retries", "1", "--out", down] + TRIP,
                 timeout=120)
        check(p.returncode == 2 and url in p.stderr, "server down: exit 2 naming the URL (exit %d: %s)" %
              (p.returncode, p.stderr[-300:]))
        check(not os.path.exists(down), "server down: no output directory")

        # 5. GRIB2: the surface level of the same forecast, against the same values in NetCDF
        grib = os.path.join(work, "rtofs.grib2")
        write_grib(ds, grib)
        grib_nc = os.path.join(work, "surface.nc")
        grib_as_netcdf(grib, ds, grib_nc)
        p_gnc = plan(glider, ["--currents", grib_nc, "--out", os.path.join(work, "o_gnc")] + TRIP)
        check(p_gnc.returncode == 0, "the surface NetCDF plans (exit %d: %s)" % (p_gnc.returncode,
                                                                                p_gnc.stderr[-300:]))
        for label, extra in (("by standard names", []), ("by --u-var UOGRD", ["--u-var", "UOGRD", "--v-var",
                                                                              "VOGRD"])):
            out = os.path.join(work, "o_grib_" + str(len(extra)))
            p = plan(glider, ["--currents", grib, "--out", out] + extra + TRIP)
            check(p.returncode == 0, "GRIB2 %s plans (exit %d: %s)" % (label, p.returncode, p.stderr[-300:]))
            if p.returncode == 0 and p_gnc.returncode == 0:
                t, tg = travel_time(out), travel_time(os.path.join(work, "o_gnc"))
                check(abs(t - tg) <= 1e-12 * tg, "GRIB2 %s: the NetCDF file's travel time (%r, %r)" % (label, t, tg))
                check("current gridded (GRIB file)" in p.stdout, "GRIB2 %s: the report says GRIB file" % label)
                check(json.load(open(os.path.join(out, "summary.json")))["current_source"] == "GRIB file",
                      "GRIB2 %s: summary.json current_source" % label)
        # 5b. a GRIB2 file cut short: inside a message (GDAL reads none), at a message's end (VOGRD lost)
        check_cut_grib(glider, work, grib)
        # 6. RTOFS's layout: one GRIB2 file per forecast time, given as one forecast by a pattern
        hourly = os.path.join(work, "hourly")
        os.makedirs(hourly)
        write_grib_hours(ds, hourly)
        out = os.path.join(work, "o_hourly")
        p = plan(glider, ["--currents", os.path.join(hourly, "f*.grib2"), "--out", out] + TRIP)
        check(p.returncode == 0, "GRIB2 one file per forecast time plans (exit %d: %s)" % (p.returncode,
                                                                                         p.stderr[-300:]))
        if p.returncode == 0 and p_gnc.returncode == 0:
            t, tg = travel_time(out), travel_time(os.path.join(work, "o_gnc"))
            check(abs(t - tg) <= 1e-12 * tg, "GRIB2 one file per time: the single file's travel time (%r, %r)" %
                  (t, tg))
        # 6b. a GRIB2 file over HTTP: fetched whole once; with --cache a second run asks nothing
        grib_server = serve(work)
        grib_url = "http://127.0.0.1:%d/rtofs.grib2" % grib_server.server_address[1]
        grib_cache = os.path.join(work, "grib_cache")
        for run, extra in (("no cache", []), ("cache, first", ["--cache", grib_cache]),
                           ("cache, second", ["--cache", grib_cache])):
            out = os.path.join(work, "o_grib_url_" + str(len(grib_server.asked)))
            before = len(grib_server.asked)
            p = plan(glider, ["--currents", grib_url, "--out", out] + extra + TRIP)
            asked = grib_server.asked[before:]
            check(p.returncode == 0, "GRIB2 over HTTP, %s: plans (exit %d: %s)" % (run, p.returncode,
                                                                                  p.stderr[-300:]))
            if p.returncode == 0 and p_gnc.returncode == 0:
                t, tg = travel_time(out), travel_time(os.path.join(work, "o_gnc"))
                check(t == tg, "GRIB2 over HTTP, %s: the file's travel time (%r, %r)" % (run, t, tg))
            expected = 0 if run == "cache, second" else 1
            check(len(asked) == expected, "GRIB2 over HTTP, %s: %d request(s) (%s)" % (run, expected, asked))
        grib_server.shutdown()
        grib_server.server_close()
        # 7. the fields of several times interleaved in one file (U, V of each time in turn)
        mixed = os.path.join(work, "interleaved.grib2")
        write_grib(ds, mixed, interleaved=True)
        out = os.path.join(work, "o_interleaved")
        p = plan(glider, ["--currents", mixed, "--out", out] + TRIP)
        check(p.returncode == 0, "GRIB2 with interleaved times plans (exit %d: %s)" % (p.returncode, p.stderr[-300:]))
        if p.returncode == 0 and p_gnc.returncode == 0:
            t, tg = travel_time(out), travel_time(os.path.join(work, "o_gnc"))
            check(abs(t - tg) <= 1e-12 * tg, "GRIB2 interleaved: the single file's travel time (%r, %r)" % (t, tg))
        # 8. a parameter missing at one time: GDAL's arrays as they are, refused with a message naming the file
        gappy = os.path.join(work, "gappy.grib2")
        write_grib(ds.isel(time=[0, 1, 2]), gappy, interleaved=True)
        from osgeo import gdal
        src = gdal.Open(gappy)
        keep = [b for b in range(1, src.RasterCount + 1) if b != 4]  # VOGRD of the second time left out
        gdal.Translate(os.path.join(work, "gappy_cut.grib2"), src, bandList=keep, format="GRIB")
        src = None
        p = plan(glider, ["--currents", os.path.join(work, "gappy_cut.grib2"), "--out", os.path.join(work, "o_gap")] +
                 TRIP)
        check(p.returncode == 2 and "gappy_cut.grib2" in p.stderr, "GRIB2 with a field missing at one time: exit 2 "
              "naming the file (exit %d: %s)" % (p.returncode, p.stderr[-300:]))
    finally:
        if server:
            server.shutdown()
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
