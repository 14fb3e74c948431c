#!/usr/bin/env python3
"""glider_plan --currents URL through NetCDF-C's own DAP client against tests/opendap/dap2_server.py on 127.0.0.1.

Usage: check_opendap.py GLIDER_PLAN

A HYCOM-like forecast (time, depth, lat, lon; water_u/water_v packed as shorts with scale_factor and _FillValue; an
island of fill values) is written with NetCDF-C (python3-netcdf4) and served. Checked:
  1. the plan from the URL has the travel time of the plan from the file (1e-12), and the same waypoints;
  2. a trip over a fifth of the domain fetches less than a fifth of the whole velocity variables' bytes (the server's
     own count of the XDR data it sent, and the report's count of the values);
  3. with --cache, a second plan reads no network (no request reaches the server) and has the same travel time;
     the cache is an ordinary NetCDF file that names the URL and the constraints it answers;
  4. a stopped server: exit 2 naming the URL, within the request time limit;
  5. a server that does not answer in time: exit 2 naming the URL and the time limit, bounded by the retries;
  6. a server that answers an error (HTTP 500): exit 2 naming the URL;
  7. a mission file whose current.file is the URL plans like --currents URL;
  8. two daily files served as two URLs plan as the two files do (one forecast);
  9. a real model file (NCL's POP sample: curvilinear, global, cm/s, tracer land) from its URL plans as the file;
 10. a URL with a user and a password: the password reaches no output, message or cache name;
 11. another URL's cache file copied into place is not used (the URL's own travel time, the file replaced);
 12. a forecast republished at the URL with other dates is refused when a plan needs more than the cache holds;
 13. data answers cut short (the length header says so, or promises more) are refused, never planned on.
"""
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

if __name__ == "__main__" and os.environ.get("OMPL_GLIDER_REEXEC") is None:
    try:
        import netCDF4  # noqa: F401
        import numpy  # noqa: F401
    except ImportError:  # pyenv's python3 first on PATH: Debian's has python3-netcdf4
        if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != "/usr/bin/python3":
            os.environ["OMPL_GLIDER_REEXEC"] = "1"
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        raise

import netCDF4
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SERVER = os.path.join(HERE, "dap2_server.py")
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what, flush=True)
    if not cond:
        failures.append(what)


def write_forecast(path):
    """A regional HYCOM-like forecast: 121 x 101 nodes, 2 levels, 12 daily records, an island of fill values."""
    nt, nz, ny, nx = 12, 2, 101, 121
    lon = np.linspace(-80.0, -60.0, nx)
    lat = np.linspace(25.0, 45.0, ny)
    with netCDF4.Dataset(path, "w", format="NETCDF4_CLASSIC") as d:
        d.createDimension("time", None)
        d.createDimension("depth", nz)
        d.createDimension("lat", ny)
        d.createDimension("lon", nx)
        d.Conventions = "CF-1.6"
        d.title = "loopback test forecast (HYCOM-like layout)"
        t = d.createVariable("time", "f8", ("time",))
        t.units = "hours since 2000-01-01 00:00:00"
        t.calendar = "gregorian"
        t.axis = "T"
        t[:] = 230000.0 + 24.0 * np.arange(nt)
        z = d.createVariable("depth", "f8", ("depth",))
        z.units = "m"
        z.positive = "down"
        z.axis = "Z"
        z[:] = [0.0, 10.0]
        y = d.createVariable("lat", "f8", ("lat",))
        y.units = "degrees_north"
        y.standard_name = "latitude"
        y[:] = lat
        x = d.createVariable("lon", "f8", ("lon",))
        x.units = "degrees_east"
        x.standard_name = "longitude"
        x[:] = lon
        X, Y = np.meshgrid(lon, lat)
        island = (np.hypot(X + 72.5, (Y - 32.0) * 1.2) < 0.8)
        for name, std in (("water_u", "eastward_sea_water_velocity"), ("water_v", "northward_sea_water_velocity")):
            v = d.createVariable(name, "i2", ("time", "depth", "lat", "lon"), fill_value=np.int16(-30000))
            v.units = "m/s"
            v.standard_name = std
            v.scale_factor = np.float32(0.001)
            v.add_offset = np.float32(0.0)
            v.set_auto_maskandscale(False)
            data = np.empty((nt, nz, ny, nx), dtype=np.int16)
            for k in range(nt):
                phase = 0.15 * k
                jet = 0.9 * np.exp(-((Y - 32.0 - 1.5 * np.sin(0.5 * X + phase)) / 1.2) ** 2)
                u = jet + 0.05 * np.cos(0.3 * Y)
                vv = 0.75 * np.cos(0.5 * X + phase) * jet * 0.5 + 0.04 * np.sin(0.2 * X)
                field = u if name == "water_u" else vv
                for m in range(nz):
                    packed = np.round(field * (1.0 - 0.2 * m) / 0.001).astype(np.int16)
                    packed[island] = -30000
                    data[k, m] = packed
            v[:] = data
    return nt * nz * ny * nx


def split_forecast(path, first, second, at):
    """The records of @p path before @p at into @p first, the rest into @p second (daily files of one forecast)."""
    with netCDF4.Dataset(path) as src:
        for out, sl in ((first, slice(0, at)), (second, slice(at, None))):
            with netCDF4.Dataset(out, "w", format="NETCDF4_CLASSIC") as d:
                for name, dim in src.dimensions.items():
                    d.createDimension(name, None if dim.isunlimited() else len(dim))
                d.setncatts({k: src.getncattr(k) for k in src.ncattrs()})
                for name, var in src.variables.items():
                    fill = var.getncattr("_FillValue") if "_FillValue" in var.ncattrs() else None
                    v = d.createVariable(name, var.dtype, var.dimensions, fill_value=fill)
                    v.setncatts({k: var.getncattr(k) for k in var.ncattrs() if k != "_FillValue"})
                    var.set_auto_maskandscale(False)
                    v.set_auto_maskandscale(False)
                    v[:] = var[sl] if "time" in var.dimensions else var[:]


def start_server(root, log, *extra):
    pf = os.path.join(root, "..", "port_%d" % time.monotonic_ns())
    proc = subprocess.Popen([sys.executable, SERVER, "--root", root, "--port", "0", "--port-file", pf, "--log", log,
                             "--lifetime", "300"] + list(extra), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)
    deadline = time.monotonic() + 30
    while not os.path.exists(pf):
        if proc.poll() is not None or time.monotonic() > deadline:
            raise SystemExit("the DAP2 server did not start")
        time.sleep(0.05)
    with open(pf) as f:
        return proc, int(f.read().strip())


def stop(proc):
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGTERM)
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()


def log_lines(log):
    if not os.path.exists(log):
        return []
    with open(log) as f:
        return [json.loads(line) for line in f if line.strip()]


def plan(glider, args, timeout=300):
    t0 = time.monotonic()
    p = subprocess.run([glider] + args, capture_output=True, text=True, timeout=timeout)
    return p, time.monotonic() - t0


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    glider = sys.argv[1]
    work = tempfile.mkdtemp(prefix="ompl_glider_opendap_")
    servers = []
    try:
        root = os.path.join(work, "srv")
        os.makedirs(root)
        nc = os.path.join(root, "forecast.nc")
        values = write_forecast(nc)
        whole_xdr = 2 * (values * 4 + 8)  # two short variables as XDR Int16 (4 bytes a value) + length words
        whole_values = 2 * values * 2     # the same as the file's shorts
        log = os.path.join(work, "dap.jsonl")
        server, port = start_server(root, log)
        servers.append(server)
        url = "http://127.0.0.1:%d/forecast.nc" % port
        depart = netCDF4.num2date(230003.0, "hours since 2000-01-01 00:00:00").strftime("%Y-%m-%dT%H:%M:%SZ")
        # (the lattice search alone, no global check and no refinement: the reader is what is checked here, and the
        # case runs sanitized in CI too)
        trip = ["--start=-74.2,30.4", "--goal=-71.6,31.2", "--speed", "0.5", "--departure", depart,
                "--no-global-check", "--no-refine"]

        # 1. the file and the URL give the same plan
        p_file, _ = plan(glider, ["--currents", nc, "--out", os.path.join(work, "o_file")] + trip)
        check(p_file.returncode == 0, "plan from the file (exit %d: %s)" % (p_file.returncode, p_file.stderr[-300:]))
        cache = os.path.join(work, "cache")
        p_url, _ = plan(glider, ["--currents", url, "--cache", cache, "--out", os.path.join(work, "o_url")] + trip)
        check(p_url.returncode == 0, "plan from the URL (exit %d: %s)" % (p_url.returncode, p_url.stderr[-300:]))
        if p_file.returncode or p_url.returncode:
            return
        a, b = summary(os.path.join(work, "o_file")), summary(os.path.join(work, "o_url"))
        ta, tb = a["travel_time"], b["travel_time"]
        check(math.isfinite(ta) and abs(ta - tb) <= 1e-12 * abs(ta),
              "same travel time from the URL as from the file (%r, %r)" % (ta, tb))
        with open(os.path.join(work, "o_file", "waypoints.csv")) as f1, \
                open(os.path.join(work, "o_url", "waypoints.csv")) as f2:
            check(f1.read() == f2.read(), "the same waypoints.csv")

        # 2. a subset, not the whole variables
        lines = log_lines(log)
        dods = [e for e in lines if e["path"].endswith(".dods")]
        velocity_bytes = sum(e.get("data_bytes", 0) for e in dods
                             if set(e.get("variables", {})) & {"water_u", "water_v"})
        all_bytes = sum(e.get("data_bytes", 0) for e in dods)
        check(0 < velocity_bytes < whole_xdr / 5,
              "velocity bytes the server sent %d < a fifth of the whole variables' %d" % (velocity_bytes, whole_xdr))
        check(all_bytes < whole_xdr / 5, "all data bytes the server sent %d < a fifth of %d" % (all_bytes, whole_xdr))
        src = b.get("forecast_sources", [])
        check(len(src) == 1 and src[0]["source"] == url and src[0]["network"],
              "summary.json names the source and that it came from the network")
        fetched = src[0]["bytes_fetched"] if src else -1
        check(0 < fetched < whole_values / 5,
              "the report's bytes fetched %d < a fifth of the whole variables' %d" % (fetched, whole_values))
        check("OPeNDAP" in p_url.stdout and url in p_url.stdout, "the report says what came from where")

        # 3. the cache: a second plan reads no network
        files = [f for f in os.listdir(cache) if f.endswith(".nc")]
        check(len(files) == 1, "one cache file (%s)" % files)
        if files:
            with netCDF4.Dataset(os.path.join(cache, files[0])) as d:
                check(d.getncattr("ompl_glider_source") == url, "the cache file names its URL")
                check("water_u[" in d.getncattr("ompl_glider_fetched"), "the cache file lists the constraints")
                check(d.variables["water_u"].shape == (12, 2, 101, 121), "the cache file has the dataset's shape")
        before = len(log_lines(log))
        p_again, _ = plan(glider, ["--currents", url, "--cache", cache, "--out", os.path.join(work, "o_again")] + trip)
        check(p_again.returncode == 0, "second plan through the cache (exit %d: %s)" %
              (p_again.returncode, p_again.stderr[-300:]))
        if p_again.returncode == 0:
            c = summary(os.path.join(work, "o_again"))
            check(c["travel_time"] == tb, "same travel time from the cache (%r, %r)" % (c["travel_time"], tb))
            s = c.get("forecast_sources", [{}])[0]
            check(s.get("network") is False and s.get("bytes_fetched") == 0 and s.get("bytes_from_cache", 0) > 0,
                  "the report says all came from the cache: %s" % s)
        check(len(log_lines(log)) == before, "no request reached the server on the second plan (%d new)" %
              (len(log_lines(log)) - before))

        # 11. another URL's cache file copied into place: not used, the URL's own forecast fetched and the file replaced
        other_nc = os.path.join(root, "other.nc")
        shutil.copy(nc, other_nc)
        with netCDF4.Dataset(other_nc, "a") as d:
            for name in ("water_u", "water_v"):
                v = d.variables[name]
                v.set_auto_maskandscale(False)
                data = v[:]
                v[:] = np.where(data == -30000, data, (data * 0.7).astype(np.int16))
        other_url = "http://127.0.0.1:%d/other.nc" % port
        p_of, _ = plan(glider, ["--currents", other_nc, "--out", os.path.join(work, "o_other_file")] + trip)
        other_cache = os.path.join(work, "cache_other")
        p_o1, _ = plan(glider, ["--currents", other_url, "--cache", other_cache, "--out",
                                os.path.join(work, "o_other_1")] + trip)
        other_files = os.listdir(other_cache) if os.path.isdir(other_cache) else []
        check(p_of.returncode == 0 and p_o1.returncode == 0 and len(other_files) == 1 and files,
              "the second dataset plans from its file and its URL (exit %d, %d: %s)" %
              (p_of.returncode, p_o1.returncode, p_o1.stderr[-300:]))
        if p_of.returncode == 0 and p_o1.returncode == 0 and len(other_files) == 1 and files:
            shutil.copy(os.path.join(cache, files[0]), os.path.join(other_cache, other_files[0]))
            p_o2, _ = plan(glider, ["--currents", other_url, "--cache", other_cache, "--out",
                                    os.path.join(work, "o_other_2")] + trip)
            check(p_o2.returncode == 0, "a copied-in cache file of another URL (exit %d: %s)" %
                  (p_o2.returncode, p_o2.stderr[-300:]))
            if p_o2.returncode == 0:
                t_file = summary(os.path.join(work, "o_other_file"))["travel_time"]
                o2 = summary(os.path.join(work, "o_other_2"))
                check(o2["travel_time"] == t_file and t_file != tb,
                      "another URL's cache file is not used: the URL's own travel time (%r, file %r, other %r)" %
                      (o2["travel_time"], t_file, tb))
                src = o2["forecast_sources"][0]
                check(src["network"] is True and url in (src.get("cache_ignored") or ""),
                      "the report says the file found was another URL's: %s" % src.get("cache_ignored"))
                with netCDF4.Dataset(os.path.join(other_cache, other_files[0])) as d:
                    check(d.getncattr("ompl_glider_source") == other_url, "the cache file was replaced by the URL's")

        # 12. a forecast republished at the same URL with its dates 5 days later: a plan that needs more than the
        # cache holds is refused naming the URL and the cache file (never the new values on the cached dates)
        repub_nc = os.path.join(root, "repub.nc")
        shutil.copy(nc, repub_nc)
        repub_url = "http://127.0.0.1:%d/repub.nc" % port
        repub_cache = os.path.join(work, "cache_repub")
        p_r1, _ = plan(glider, ["--currents", repub_url, "--cache", repub_cache, "--out",
                                os.path.join(work, "o_repub_1")] + trip)
        check(p_r1.returncode == 0, "republished: the first plan (exit %d: %s)" % (p_r1.returncode, p_r1.stderr[-300:]))
        with netCDF4.Dataset(repub_nc, "a") as d:
            d.variables["time"][:] = d.variables["time"][:] + 120.0
        # another trip (a region the cache does not hold), the same departure
        east_trip = ["--start=-66.2,30.4", "--goal=-63.6,31.2"] + trip[2:]
        p_r2, _ = plan(glider, ["--currents", repub_url, "--cache", repub_cache, "--out",
                                os.path.join(work, "o_repub_2")] + east_trip)
        check(p_r2.returncode == 2 and repub_url in p_r2.stderr and "cache file" in p_r2.stderr and
              "time[" in p_r2.stderr, "republished with other dates: exit 2 naming the URL, the cache file and the "
              "date (exit %d: %s)" % (p_r2.returncode, p_r2.stderr[-400:]))
        check(not os.path.exists(os.path.join(work, "o_repub_2")), "republished: no output directory")

        # 13. data answers cut short (NetCDF-C fills the missing values with zeros and returns success): refused,
        # naming the URL, after the retries; whether the length header gives the cut length or promises the whole
        for mode in ("short", "cut"):
            cut_srv, cut_port = start_server(root, os.path.join(work, "cut_%s.jsonl" % mode), "--truncate", "0.3",
                                             "--truncate-mode", mode)
            servers.append(cut_srv)
            cut_url = "http://127.0.0.1:%d/forecast.nc" % cut_port
            p_cut, _ = plan(glider, ["--currents", cut_url, "--retries", "1", "--out",
                                     os.path.join(work, "o_cut_" + mode)] + trip)
            check(p_cut.returncode == 2 and cut_url in p_cut.stderr and "cut short" in p_cut.stderr and
                  "2 attempts" in p_cut.stderr, "answers cut short (%s): exit 2 naming the URL after 2 attempts "
                  "(exit %d: %s)" % (mode, p_cut.returncode, p_cut.stderr[-300:]))
            check(not os.path.exists(os.path.join(work, "o_cut_" + mode)), "answers cut short: no output directory")
            stop(cut_srv)

        # 7. a mission file whose current.file is the URL (its region: the whole grid; no cache)
        mission = os.path.join(work, "m.yaml")
        with open(mission, "w") as f:
            f.write("name: url mission\n"
                    "current: {type: netcdf, file: '%s'}\n"
                    "start: {lon: -74.2, lat: 30.4}\n"
                    "goal: {lon: -71.6, lat: 31.2}\n"
                    "vehicle: {speed: 0.5}\n"
                    "departure: {time: '%s'}\n"
                    "outputs: {directory: %s}\n" % (url, depart, os.path.join(work, "o_mission")))
        p_m, _ = plan(glider, ["--mission", mission])
        check(p_m.returncode == 0, "mission file with the URL (exit %d: %s)" % (p_m.returncode, p_m.stderr[-400:]))
        if p_m.returncode == 0:
            src = summary(os.path.join(work, "o_mission")).get("forecast_sources", [])
            check(len(src) == 1 and src[0]["source"] == url and src[0]["network"], "the mission's source is the URL")

        # 8. several URLs form one forecast as several files do
        split_forecast(nc, os.path.join(root, "day1.nc"), os.path.join(root, "day2.nc"), 6)
        files = ",".join(os.path.join(root, n) for n in ("day1.nc", "day2.nc"))
        urls = ",".join("http://127.0.0.1:%d/%s" % (port, n) for n in ("day1.nc", "day2.nc"))
        p_files, _ = plan(glider, ["--currents", files, "--out", os.path.join(work, "o_files")] + trip)
        p_urls, _ = plan(glider, ["--currents", urls, "--out", os.path.join(work, "o_urls")] + trip)
        check(p_files.returncode == 0 and p_urls.returncode == 0,
              "two daily files and their two URLs plan (exit %d, %d: %s)" %
              (p_files.returncode, p_urls.returncode, p_urls.stderr[-300:]))
        if p_files.returncode == 0 and p_urls.returncode == 0:
            tf = summary(os.path.join(work, "o_files"))["travel_time"]
            tu = summary(os.path.join(work, "o_urls"))
            check(tf == tu["travel_time"], "two URLs give the two files' travel time (%r, %r)" % (tf, tu["travel_time"]))
            check(len(tu["forecast_sources"]) == 2, "the report names both URLs")

        # 10. a URL with a user and a password: planned, and the password reaches no output, message or cache name
        secret_url = "http://pilot:s3cretPW@127.0.0.1:%d/forecast.nc" % port
        secret_cache = os.path.join(work, "cache_secret")
        p_s, _ = plan(glider, ["--currents", secret_url, "--cache", secret_cache, "--out",
                               os.path.join(work, "o_secret")] + trip)
        check(p_s.returncode == 0, "a URL with credentials plans (exit %d: %s)" % (p_s.returncode, p_s.stderr[-300:]))
        if p_s.returncode == 0:
            seen = {"stdout": p_s.stdout, "stderr": p_s.stderr, "cache names": "".join(os.listdir(secret_cache))}
            for name in os.listdir(os.path.join(work, "o_secret")):
                with open(os.path.join(work, "o_secret", name), "rb") as f:
                    seen[name] = f.read().decode("utf-8", "replace")
            for name in os.listdir(secret_cache):
                with netCDF4.Dataset(os.path.join(secret_cache, name)) as d:
                    seen["cache attribute"] = d.getncattr("ompl_glider_source")
            leaks = [k for k, v in seen.items() if "s3cretPW" in v]
            check(not leaks, "the password is in no output, message, cache name or cache attribute (in %s)" % leaks)
            src = summary(os.path.join(work, "o_secret")).get("forecast_sources", [])
            check(len(src) == 1 and src[0]["source"] == url, "the source is shown without its credentials: %s" % src)

        # 9. a real model file served: NCL's POP sample (Debian's libncarg-data; curvilinear B grid, global, velocities
        # in cm/s, land from a tracer): the route past Jamaica from the URL is the file's
        pop = "/usr/share/ncarg/data/cdf/pop.nc"
        shutil.copy(pop, os.path.join(root, "pop.nc"))
        pop_trip = ["--u-var", "urot", "--v-var", "vrot", "--start=-79.5,18.6", "--goal=-74.5,17.6", "--speed", "0.5",
                    "--no-global-check", "--no-refine"]
        p_pf, _ = plan(glider, ["--currents", pop, "--out", os.path.join(work, "o_pop_file")] + pop_trip)
        pop_url = "http://127.0.0.1:%d/pop.nc" % port
        p_pu, _ = plan(glider, ["--currents", pop_url, "--out", os.path.join(work, "o_pop_url")] + pop_trip)
        check(p_pf.returncode == 0 and p_pu.returncode == 0, "POP: the file and its URL plan (exit %d, %d: %s)" %
              (p_pf.returncode, p_pu.returncode, p_pu.stderr[-300:]))
        if p_pf.returncode == 0 and p_pu.returncode == 0:
            sf, su = summary(os.path.join(work, "o_pop_file")), summary(os.path.join(work, "o_pop_url"))
            check(sf["travel_time"] == su["travel_time"], "POP: the URL's travel time is the file's (%r, %r)" %
                  (sf["travel_time"], su["travel_time"]))
            with netCDF4.Dataset(pop) as d:
                whole = sum(d.variables[n].size * 4 + 8 for n in ("urot", "vrot"))  # XDR Float32 + length words
            sent = sum(e.get("data_bytes", 0) for e in log_lines(log) if e["path"] == "/pop.nc.dods"
                       and set(e.get("variables", {})) & {"urot", "vrot"})
            check(0 < sent < whole / 5, "POP: velocity bytes the server sent %d < a fifth of the whole variables' %d "
                  "(a regional trip on a global grid)" % (sent, whole))

        # 4. a stopped server
        stop(server)
        p_down, dt = plan(glider, ["--currents", url, "--request-timeout", "8", "--out",
                                   os.path.join(work, "o_down")] + trip, timeout=120)
        check(p_down.returncode == 2 and url in p_down.stderr,
              "stopped server: exit 2 naming the URL (exit %d: %s)" % (p_down.returncode, p_down.stderr[-300:]))
        check(dt < 8, "stopped server: answered within the request time limit (%.1f s < 8 s)" % dt)
        check(not os.path.exists(os.path.join(work, "o_down")), "stopped server: no output directory")

        # 5. a server too slow: every .dods answer waits 30 s
        slow, port2 = start_server(root, os.path.join(work, "slow.jsonl"), "--delay", "30")
        servers.append(slow)
        slow_url = "http://127.0.0.1:%d/forecast.nc" % port2
        p_slow, dt = plan(glider, ["--currents", slow_url, "--request-timeout", "2", "--retries", "1", "--out",
                                   os.path.join(work, "o_slow")] + trip, timeout=120)
        check(p_slow.returncode == 2 and slow_url in p_slow.stderr and "time limit" in p_slow.stderr,
              "slow server: exit 2 naming the URL and the time limit (exit %d: %s)" %
              (p_slow.returncode, p_slow.stderr[-300:]))
        check(dt < 20, "slow server: gave up after 2 attempts of 2 s and a pause (%.1f s)" % dt)
        stop(slow)

        # 6. a server that answers an error
        bad, port3 = start_server(root, os.path.join(work, "bad.jsonl"), "--fail-status", "500")
        servers.append(bad)
        bad_url = "http://127.0.0.1:%d/forecast.nc" % port3
        p_bad, dt = plan(glider, ["--currents", bad_url, "--retries", "0", "--out", os.path.join(work, "o_bad")] + trip)
        check(p_bad.returncode == 2 and bad_url in p_bad.stderr,
              "server error: exit 2 naming the URL (exit %d: %s)" % (p_bad.returncode, p_bad.stderr[-300:]))
        stop(bad)

    finally:
        for s in servers:
            stop(s)
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
    print("opendap: " + ("every check passed" if not failures else "%d checks failed" % len(failures)))
    sys.exit(1 if failures else 0)
