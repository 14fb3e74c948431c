#!/usr/bin/env python3
"""A test bed of forecast runs whose error grows with lead time: a series of CF NetCDF files, one per forecast run,
written from a known truth, and the truth itself as a file.

Usage:
    python3 scripts/make_forecast_runs.py --out DIR [--runs 21] [--interval 24] [--start 2026-06-01T00:00Z]
        [--length 10] [--step 3] [--resolution 0.1] [--naming cmems|hycom|plain] [--reftime variable|attribute|none]
        [--fmrc] [--truth-days D] [--seed 1] [--small] [--stats] [error magnitudes, below]

Pure Python 3 (standard library only): the files are written as CDL text and converted with `ncgen -o F.nc F.cdl`
(netCDF-C's ncgen must be on the PATH), as examples/make_forecast_cdl.py does; the .cdl files are removed.

The truth. The meandering jet of src/current/MeanderingJet.cpp ([EichhornRAS] Sec. 6.1), in planning units of
50 km and 1 day as examples/jet_execution.yaml (whose execution.truth parameters are the defaults here: B0 1.38,
epsilon 0.3, omega 0.4, theta pi/2, k 0.7304, c 0.138; --truth B0=..,k=.. changes them):
    B(t) = B0 + epsilon cos(omega t + theta),  th = k (x - x0 - c t),  D = sqrt(1 + k^2 B^2 sin^2 th),
    s = (y - B cos th) / D,  psi = 1 - tanh s,  u = -dpsi/dy = sech^2(s) / D,  v = dpsi/dx = -sech^2(s) ds/dx,
with t in days since --start, x, y in units of 50 km, x0 = 0 for the truth, and u, v times 50000 / 86400 in m/s.
(x, y) are mapped to lon/lat by a LOCAL EQUIRECTANGULAR mapping about lon0 = -70, lat0 = 36 on a sphere of
R = 6371 km:
    x metres = (lon - lon0) R cos(lat0) pi / 180,   y metres = (lat - lat0) R pi / 180
(not the project's `projection`, an azimuthal equidistant one on WGS84: the two differ by up to a few km at the
region's corners, so a gridded truth is "the jet in this mapping", close to but not the analytic jet flown with a
projection). The velocities are given eastward/northward as they are in x/y (no rotation). The grid covers
examples/jet_execution.yaml's planning region x 0..10, y -4..4 (500 km x 400 km: lon -70..-64.44, lat 34.2..37.8)
with a margin (--margin, degrees) at --resolution degrees.

The runs. Run r has the reference time t_r = start + r * interval. At the valid time t (lead tau = t - t_r, days)
it is the jet with its parameters perturbed by an error that grows with lead time,
    g(tau) = a0 + tau / T           (a0: --analysis-error, 0.1; T: --growth-days, 10)
    B0_r = B0 (1 + eB_r g),  k_r = k (1 + ek_r g),  c_r = c (1 + ec_r g)          (meander amplitude, wavenumber,
                                                                                 phase speed reshaped)
    th_r = k_r (x - d_r g - c t_r - c_r tau)       (the meander displaced by d_r g, and carried at the run's own
                                                    phase speed from its analysis on)
    u_r += bu_r g,  v_r += bv_r g                  (a uniform bias, m/s)
where each run's numbers are drawn by random.Random(--seed) around a systematic part:
    eB_r = --error-b0 + --error-spread N(0,1)     (default -0.12 +- 0.05)
    ek_r = --error-k  + --error-spread N(0,1)     (default +0.14 +- 0.05)
    ec_r = --error-c  + --error-spread N(0,1)     (default -0.12 +- 0.05)
    d_r  = --shift    + --shift-spread N(0,1)     (km; default 0 +- 20 km)
    bu_r = --bias-u   + --bias-spread N(0,1)      (m/s; default 0 +- 0.02)
    bv_r = --bias-v   + --bias-spread N(0,1)      (m/s; default 0 +- 0.02)
(six draws per run in this order, so run r's numbers depend on the seed and r only). At 10 days lead (g = 1.1)
the systematic part is about examples/jet_execution.yaml's forecast against its truth (B0 1.2, k 0.84, c 0.12:
-13 %, +15 %, -13 %); the random part makes two runs valid at the same time differ (what the NMC method of
estimating forecast-error scales from run differences needs). --stats prints the RMS error against the truth by
lead time over the grid and the runs (with the defaults 0.015 m/s at 0 days, 0.083 at 5 and 0.145 at 10; the
example's forecast against its truth: 0.12 m/s over days 0..10).

The files (dims time, lat, lon; time "hours since <the run's reference time>", calendar standard; lat, lon in
degrees_north/east; float uo, vo (time, lat, lon) in m s-1 with CF standard names and _FillValue; global
Conventions CF-1.8, title, source):
  --naming cmems  cmems_mod_glo_phy_anfc_merged-uv_PT3H-i_20260601-20260611_R20260601.nc  (default; the first and
                  last valid dates and the run's reference date R; hours added where a reference time is not 00Z)
  --naming hycom  hycom_glby_930_2026060100_t000_uv3z.nc  (the reference time, and the first lead t000)
  --naming plain  run_20260601T00.nc
  --reftime variable   scalar double forecast_reference_time (standard_name forecast_reference_time, hours since
                       1970-01-01 00:00:00) (default)
  --reftime attribute  a global attribute forecast_reference_time = "2026-06-01T00:00:00Z"
  --reftime none       nothing (a reader then takes the first record)
  truth.nc        the truth from --start over --truth-days (default runs * interval + length), every --step hours,
                  time "hours since <start>", no forecast_reference_time
  fmrc.nc         (with --fmrc) every run in one file as a THREDDS FMRC collection's 2-D time dataset: dims run,
                  time, lat, lon; reftime(run) (forecast_reference_time), time(run, time) the valid times and
                  time_offset(run, time) the leads (forecast_period), uo, vo (run, time, lat, lon)
--small is a preset for tests: 4 runs, 3 days long, 6-hourly, 0.25 degrees (options given explicitly win).

As a module (the tests import it): field(params, t, lon, lat) -> (u, v) m/s of a jet at t days since the start;
TRUTH; configure(argv) -> the options; bed(opts) -> the grid, the truth and each run's numbers; run_params(run, t,
opts) -> the run's jet at valid time t; generate(opts) -> the files written.
"""
import argparse
import datetime
import math
import multiprocessing
import os
import random
import subprocess
import sys
import time as clock

LENGTH_M = 50000.0  # planning length unit
TIME_S = 86400.0  # planning time unit
SPEED = LENGTH_M / TIME_S  # one planning speed unit in m/s
EARTH_M = 6371000.0
LON0, LAT0 = -70.0, 36.0
REGION = (0.0, 10.0, -4.0, 4.0)  # x_min x_max y_min y_max in planning units
TRUTH = {"B0": 1.38, "epsilon": 0.3, "omega": 0.4, "theta": math.pi / 2, "k": 0.7304, "c": 0.138}
FILL = -999.0
EPOCH = datetime.datetime(1970, 1, 1, tzinfo=datetime.timezone.utc)
SMALL = {"runs": 4, "length": 3.0, "step": 6.0, "resolution": 0.25}
DEFAULTS = {"runs": 21, "length": 10.0, "step": 3.0, "resolution": 0.1}


def x_of_lon(lon):
    return (lon - LON0) * EARTH_M * math.cos(math.radians(LAT0)) * math.pi / 180.0 / LENGTH_M


def y_of_lat(lat):
    return (lat - LAT0) * EARTH_M * math.pi / 180.0 / LENGTH_M


def lon_of_x(x):
    return LON0 + x * LENGTH_M * 180.0 / (math.pi * EARTH_M * math.cos(math.radians(LAT0)))


def lat_of_y(y):
    return LAT0 + y * LENGTH_M * 180.0 / (math.pi * EARTH_M)


def _jet_rows(p, t, lons, lats):
    """u, v (m/s) of the jet with parameters p at t (days) on the grid lats x lons, row by row (lat major)."""
    B = p["B0"] + p["epsilon"] * math.cos(p["omega"] * t + p["theta"])
    k, c, x0 = p["k"], p["c"], p.get("x0", 0.0)
    bu, bv = p.get("bu", 0.0), p.get("bv", 0.0)
    cols = []
    for lon in lons:
        th = k * (x_of_lon(lon) - x0 - c * t)
        sn, cs = math.sin(th), math.cos(th)
        D = math.sqrt(1.0 + (k * B * sn) ** 2)
        Dx = k ** 3 * B * B * sn * cs / D
        cols.append((B * cs, 1.0 / D, B * k * sn / D, Dx / (D * D)))
    us, vs = [], []
    for lat in lats:
        y = y_of_lat(lat)
        for bcs, inv_d, nx_d, dx_d2 in cols:
            n = y - bcs
            a = math.exp(-2.0 * abs(n * inv_d))
            g = 4.0 * a / ((1.0 + a) * (1.0 + a))  # sech^2(s), no overflow
            us.append(g * inv_d * SPEED + bu)
            vs.append(-g * (nx_d - n * dx_d2) * SPEED + bv)
    return us, vs


def field(params, t, lon, lat):
    """(u, v) in m/s of the jet with params (B0 epsilon omega theta k c, and x0 the meander's displacement in
    planning units, bu bv a uniform bias in m/s) at t days after the start, at (lon, lat)."""
    us, vs = _jet_rows(params, t, [lon], [lat])
    return us[0], vs[0]


def parse_time(text):
    text = text.strip().replace(" ", "T")
    if text.endswith("Z"):
        text = text[:-1]
    for fmt in ("%Y-%m-%dT%H:%M:%S", "%Y-%m-%dT%H:%M", "%Y-%m-%dT%H", "%Y-%m-%d"):
        try:
            return datetime.datetime.strptime(text, fmt).replace(tzinfo=datetime.timezone.utc)
        except ValueError:
            pass
    raise argparse.ArgumentTypeError("expected an ISO 8601 UTC date such as 2026-06-01T00:00Z, got '%s'" % text)


def parse_truth(text):
    params = dict(TRUTH)
    for item in filter(None, text.split(",")):
        name, _, value = item.partition("=")
        if name.strip() not in TRUTH:
            raise argparse.ArgumentTypeError("--truth: unknown parameter '%s' (%s)" % (name, " ".join(TRUTH)))
        params[name.strip()] = float(value)
    return params


def iso(when):
    return when.strftime("%Y-%m-%dT%H:%M:%SZ")


def hours_since_epoch(when):
    return (when - EPOCH).total_seconds() / 3600.0


def parser():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", help="folder the .nc files are written to (made if missing)")
    p.add_argument("--runs", type=int, help="number of runs (default 21; --small 4)")
    p.add_argument("--interval", type=float, default=24.0, help="hours between two runs' reference times (24)")
    p.add_argument("--start", type=parse_time, default=parse_time("2026-06-01T00:00Z"),
                   help="the first run's reference time and the truth's first time (2026-06-01T00:00Z)")
    p.add_argument("--length", type=float, help="days each run covers (default 10; --small 3)")
    p.add_argument("--step", type=float, help="hours between records (default 3; --small 6)")
    p.add_argument("--resolution", type=float, help="grid spacing in degrees (default 0.1; --small 0.25)")
    p.add_argument("--margin", type=float, default=0.2, help="degrees of grid beyond the planning region (0.2)")
    p.add_argument("--truth-days", type=float, help="days the truth covers (default runs * interval + length)")
    p.add_argument("--truth", type=parse_truth, default=dict(TRUTH),
                   help="the truth's jet parameters changed, e.g. B0=1.3,c=0.14 (default those of TRUTH)")
    p.add_argument("--naming", choices=["cmems", "hycom", "plain"], default="cmems", help="run file names")
    p.add_argument("--reftime", choices=["variable", "attribute", "none"], default="variable",
                   help="how a run file gives its reference time (default a forecast_reference_time variable)")
    p.add_argument("--fmrc", action="store_true", help="also write fmrc.nc, every run in one FMRC 2-D file")
    p.add_argument("--seed", type=int, default=1, help="seed of the runs' random errors (1)")
    p.add_argument("--analysis-error", type=float, default=0.1, help="a0: the error's growth factor at lead 0")
    p.add_argument("--growth-days", type=float, default=10.0, help="T: the factor grows by 1 in T days (10)")
    p.add_argument("--error-b0", type=float, default=-0.12, help="systematic relative error of B0 (-0.12)")
    p.add_argument("--error-k", type=float, default=0.14, help="systematic relative error of k (0.14)")
    p.add_argument("--error-c", type=float, default=-0.12, help="systematic relative error of c (-0.12)")
    p.add_argument("--error-spread", type=float, default=0.05,
                   help="standard deviation of each run's relative errors about the systematic ones (0.05)")
    p.add_argument("--shift", type=float, default=0.0, help="systematic displacement of the meander, km (0)")
    p.add_argument("--shift-spread", type=float, default=20.0, help="its standard deviation over runs, km (20)")
    p.add_argument("--bias-u", type=float, default=0.0, help="systematic uniform eastward bias, m/s (0)")
    p.add_argument("--bias-v", type=float, default=0.0, help="systematic uniform northward bias, m/s (0)")
    p.add_argument("--bias-spread", type=float, default=0.02, help="the biases' standard deviation, m/s (0.02)")
    p.add_argument("--small", action="store_true", help="preset for tests: 4 runs, 3 days, 6-hourly, 0.25 deg")
    p.add_argument("--stats", action="store_true", help="print the RMS error against the truth by lead time")
    p.add_argument("--jobs", type=int, default=0, help="processes writing files (default: the cores)")
    return p


def configure(argv):
    """The options of a command line, the --small preset and the defaults filled in."""
    p = parser()
    opts = p.parse_args(argv)
    if not opts.out:
        p.error("--out DIR is required")
    for name, value in DEFAULTS.items():
        if getattr(opts, name) is None:
            setattr(opts, name, SMALL[name] if opts.small else value)
    if opts.runs < 1 or opts.length <= 0 or opts.step <= 0 or opts.interval <= 0 or opts.resolution <= 0:
        p.error("--runs, --length, --step, --interval and --resolution must be positive")
    if opts.truth_days is None:
        opts.truth_days = opts.runs * opts.interval / 24.0 + opts.length
    return opts


def grid(opts):
    """Longitudes and latitudes of the grid: the planning region and the margin, on multiples of the spacing."""
    res = opts.resolution
    lo = [lon_of_x(REGION[0]) - opts.margin, lat_of_y(REGION[2]) - opts.margin]
    hi = [lon_of_x(REGION[1]) + opts.margin, lat_of_y(REGION[3]) + opts.margin]
    axes = []
    for a, b in zip(lo, hi):
        first, last = math.floor(a / res + 1e-9), math.ceil(b / res - 1e-9)
        axes.append([round(i * res, 6) for i in range(first, last + 1)])
    return axes[0], axes[1]


def record_hours(days, step):
    n = int(math.floor(days * 24.0 / step + 1e-9))
    return [i * step for i in range(n + 1)]


def bed(opts):
    """The test bed's numbers: {"lons", "lats", "truth", "truth_hours", "runs"}; each run a dict with its index,
    reference time (datetime, and "t_ref" days since the start), valid "hours" since its reference time and the
    drawn errors eB ek ec (relative), d (planning units), bu bv (m/s)."""
    lons, lats = grid(opts)
    rng = random.Random(opts.seed)
    runs = []
    for r in range(opts.runs):
        draws = [rng.gauss(0.0, 1.0) for _ in range(6)]
        ref = opts.start + datetime.timedelta(hours=r * opts.interval)
        runs.append({
            "index": r, "reftime": ref, "t_ref": r * opts.interval / 24.0,
            "hours": record_hours(opts.length, opts.step),
            "eB": opts.error_b0 + opts.error_spread * draws[0],
            "ek": opts.error_k + opts.error_spread * draws[1],
            "ec": opts.error_c + opts.error_spread * draws[2],
            "d": (opts.shift + opts.shift_spread * draws[3]) * 1000.0 / LENGTH_M,
            "bu": opts.bias_u + opts.bias_spread * draws[4],
            "bv": opts.bias_v + opts.bias_spread * draws[5]})
    return {"lons": lons, "lats": lats, "truth": dict(opts.truth),
            "truth_hours": record_hours(opts.truth_days, opts.step), "runs": runs}


def growth(tau, opts):
    return opts.analysis_error + tau / opts.growth_days


def run_params(run, t, opts):
    """The jet parameters of a run at the valid time t (days since the start; lead t - t_ref)."""
    truth = opts.truth
    tau = t - run["t_ref"]
    g = growth(tau, opts)
    p = dict(truth)
    p["B0"] = truth["B0"] * (1.0 + run["eB"] * g)
    p["k"] = truth["k"] * (1.0 + run["ek"] * g)
    p["c"] = truth["c"] * (1.0 + run["ec"] * g)
    # th = k_r (x - d g - c t_ref - c_r tau) = k_r (x - x0 - c_r t)
    p["x0"] = run["d"] * g - (p["c"] - truth["c"]) * run["t_ref"]
    p["bu"], p["bv"] = run["bu"] * g, run["bv"] * g
    return p


def rms_difference(p, q, t, lons, lats):
    """RMS over the grid of the vector difference (m/s) of the jets p and q at t."""
    pu, pv = _jet_rows(p, t, lons, lats)
    qu, qv = _jet_rows(q, t, lons, lats)
    total = sum((a - b) ** 2 + (c - d) ** 2 for a, b, c, d in zip(pu, qu, pv, qv))
    return math.sqrt(total / len(pu))


# ----------------------------------------------------------------------------------------------------------- files

def run_file_name(opts, run):
    ref = run["reftime"]
    hourly = any((opts.start + datetime.timedelta(hours=r * opts.interval)).hour for r in range(opts.runs))
    stamp = ref.strftime("%Y%m%d%H" if hourly else "%Y%m%d")
    if opts.naming == "hycom":
        return "hycom_glby_930_%s_t000_uv3z.nc" % ref.strftime("%Y%m%d%H")
    if opts.naming == "plain":
        return "run_%s.nc" % ref.strftime("%Y%m%dT%H")
    last = ref + datetime.timedelta(hours=run["hours"][-1])
    return "cmems_mod_glo_phy_anfc_merged-uv_PT%gH-i_%s-%s_R%s.nc" % (
        opts.step, ref.strftime("%Y%m%d"), last.strftime("%Y%m%d"), stamp)


def numbers(values, fmt="%.10g"):
    return ", ".join(fmt % v for v in values)


def velocity_rows(rows, last):
    """CDL data lines: one line per grid row of velocities."""
    return ",\n".join(numbers(row, "%.5f") for row in rows) + (" ;" if last else ",")


def header(name, dims, time_var, extra_vars):
    dim_text = "\n".join(" %s = %d ;" % d for d in dims)
    lead = ", ".join(d[0] for d in dims[:-2])
    return "\n".join([
        "netcdf %s {" % name, "dimensions:", dim_text, "variables:", time_var,
        " double lat(lat) ;", "  lat:units = \"degrees_north\" ;", "  lat:standard_name = \"latitude\" ;",
        "  lat:long_name = \"latitude\" ;", "  lat:axis = \"Y\" ;",
        " double lon(lon) ;", "  lon:units = \"degrees_east\" ;", "  lon:standard_name = \"longitude\" ;",
        "  lon:long_name = \"longitude\" ;", "  lon:axis = \"X\" ;",
        " float uo(%s, lat, lon) ;" % lead, "  uo:units = \"m s-1\" ;",
        "  uo:standard_name = \"eastward_sea_water_velocity\" ;", "  uo:long_name = \"eastward velocity\" ;",
        "  uo:_FillValue = %.1ff ;" % FILL,
        " float vo(%s, lat, lon) ;" % lead, "  vo:units = \"m s-1\" ;",
        "  vo:standard_name = \"northward_sea_water_velocity\" ;", "  vo:long_name = \"northward velocity\" ;",
        "  vo:_FillValue = %.1ff ;" % FILL] + extra_vars)


def globals_text(title, extra=()):
    lines = ["", "// global attributes:", "  :Conventions = \"CF-1.8\" ;", "  :title = \"%s\" ;" % title,
             "  :source = \"synthetic test bed of ompl_glider (scripts/make_forecast_runs.py): the meandering jet "
             "in a local equirectangular mapping about 70W 36N, runs with an error growing with lead time; "
             "not a model's output\" ;"]
    return "\n".join(lines + list(extra))


def write_nc(path, cdl):
    """Writes the CDL beside the target, converts it with ncgen and removes it."""
    cdl_path = path[:-3] + ".cdl"
    with open(cdl_path, "w") as f:
        f.write(cdl)
    try:
        subprocess.run(["ncgen", "-o", path, cdl_path], check=True)
    finally:
        os.remove(cdl_path)


def grid_data(lons, lats):
    return ["lat = %s ;" % numbers(lats), "lon = %s ;" % numbers(lons)]


def series_rows(params_at, days, lons, lats):
    """The uo and vo grid rows of records at the given days (params_at(t): the jet at t)."""
    us, vs = [], []
    n = len(lons)
    for t in days:
        u, v = _jet_rows(params_at(t), t, lons, lats)
        us.extend(u[i:i + n] for i in range(0, len(u), n))
        vs.extend(v[i:i + n] for i in range(0, len(v), n))
    return us, vs


def series_text(params_at, days, lons, lats):
    """The uo and vo data blocks of records at the given days."""
    us, vs = series_rows(params_at, days, lons, lats)
    return "uo =\n" + velocity_rows(us, True) + "\nvo =\n" + velocity_rows(vs, True)


def write_run(task):
    opts, b, run, path = task
    ref = run["reftime"]
    units = "hours since %s" % ref.strftime("%Y-%m-%d %H:%M:%S")
    time_var = "\n".join([" double time(time) ;", "  time:units = \"%s\" ;" % units,
                          "  time:calendar = \"standard\" ;", "  time:standard_name = \"time\" ;",
                          "  time:long_name = \"valid time\" ;", "  time:axis = \"T\" ;"])
    extra, attrs, data = [], [], []
    if opts.reftime == "variable":
        extra = [" double forecast_reference_time ;",
                 "  forecast_reference_time:units = \"hours since 1970-01-01 00:00:00\" ;",
                 "  forecast_reference_time:calendar = \"standard\" ;",
                 "  forecast_reference_time:standard_name = \"forecast_reference_time\" ;",
                 "  forecast_reference_time:long_name = \"the run's reference (analysis) time\" ;"]
        data = ["forecast_reference_time = %.10g ;" % hours_since_epoch(ref)]
    elif opts.reftime == "attribute":
        attrs = ["  :forecast_reference_time = \"%s\" ;" % iso(ref)]
    dims = [("time", len(run["hours"])), ("lat", len(b["lats"])), ("lon", len(b["lons"]))]
    days = [run["t_ref"] + h / 24.0 for h in run["hours"]]
    title = "Synthetic forecast run of %s (run %d of the test bed)" % (iso(ref), run["index"])
    cdl = "\n".join([header("run", dims, time_var, extra), globals_text(title, attrs), "data:",
                     "time = %s ;" % numbers(run["hours"])] + grid_data(b["lons"], b["lats"]) + data +
                    [series_text(lambda t: run_params(run, t, opts), days, b["lons"], b["lats"]), "}", ""])
    write_nc(path, cdl)
    return path


def write_truth(task):
    opts, b, path = task
    units = "hours since %s" % opts.start.strftime("%Y-%m-%d %H:%M:%S")
    time_var = "\n".join([" double time(time) ;", "  time:units = \"%s\" ;" % units,
                          "  time:calendar = \"standard\" ;", "  time:standard_name = \"time\" ;",
                          "  time:axis = \"T\" ;"])
    dims = [("time", len(b["truth_hours"])), ("lat", len(b["lats"])), ("lon", len(b["lons"]))]
    days = [h / 24.0 for h in b["truth_hours"]]
    cdl = "\n".join([header("truth", dims, time_var, []),
                     globals_text("Synthetic truth of the forecast-run test bed (meandering jet)"), "data:",
                     "time = %s ;" % numbers(b["truth_hours"])] + grid_data(b["lons"], b["lats"]) +
                    [series_text(lambda t: b["truth"], days, b["lons"], b["lats"]), "}", ""])
    write_nc(path, cdl)
    return path


def write_fmrc(task):
    opts, b, path = task
    runs = b["runs"]
    time_var = "\n".join([
        " double reftime(run) ;", "  reftime:units = \"hours since 1970-01-01 00:00:00\" ;",
        "  reftime:calendar = \"standard\" ;", "  reftime:standard_name = \"forecast_reference_time\" ;",
        "  reftime:long_name = \"reference time of the run\" ;", "  reftime:_CoordinateAxisType = \"RunTime\" ;",
        " double time(run, time) ;", "  time:units = \"hours since 1970-01-01 00:00:00\" ;",
        "  time:calendar = \"standard\" ;", "  time:standard_name = \"time\" ;",
        "  time:long_name = \"valid time of each run's records\" ;", "  time:_CoordinateAxisType = \"Time\" ;",
        " double time_offset(run, time) ;", "  time_offset:units = \"hours\" ;",
        "  time_offset:standard_name = \"forecast_period\" ;",
        "  time_offset:long_name = \"lead time: valid time - reference time\" ;"])
    dims = [("run", len(runs)), ("time", len(runs[0]["hours"])), ("lat", len(b["lats"])), ("lon", len(b["lons"]))]
    refs = [hours_since_epoch(r["reftime"]) for r in runs]
    valid = [ref + h for ref, r in zip(refs, runs) for h in r["hours"]]
    offsets = [h for r in runs for h in r["hours"]]
    us, vs = [], []  # each run's rows as text at once (the floats of every run would take a GB)
    for r in runs:
        u, v = series_rows(lambda t, r=r: run_params(r, t, opts), [r["t_ref"] + h / 24.0 for h in r["hours"]],
                           b["lons"], b["lats"])
        us.append(velocity_rows(u, False)[:-1])
        vs.append(velocity_rows(v, False)[:-1])
    cdl = "\n".join([header("fmrc", dims, time_var, []),
                     globals_text("Synthetic forecast model run collection (FMRC 2-D time) of the test bed",
                                  ["  :featureType = \"grid\" ;"]), "data:",
                     "reftime = %s ;" % numbers(refs), "time = %s ;" % numbers(valid),
                     "time_offset = %s ;" % numbers(offsets)] + grid_data(b["lons"], b["lats"]) +
                    ["uo =\n" + ",\n".join(us) + " ;", "vo =\n" + ",\n".join(vs) + " ;", "}", ""])
    write_nc(path, cdl)
    return path


def _write(task):
    kind = task[0]
    return {"run": write_run, "truth": write_truth, "fmrc": write_fmrc}[kind](task[1:])


def generate(opts, quiet=False):
    """Writes the files; returns their paths (runs first, then truth.nc, then fmrc.nc)."""
    os.makedirs(opts.out, exist_ok=True)
    b = bed(opts)
    tasks = []
    if opts.fmrc:
        tasks.append(("fmrc", opts, b, os.path.join(opts.out, "fmrc.nc")))
    tasks.append(("truth", opts, b, os.path.join(opts.out, "truth.nc")))  # the longest first
    tasks += [("run", opts, b, run, os.path.join(opts.out, run_file_name(opts, run))) for run in b["runs"]]
    jobs = opts.jobs if opts.jobs > 0 else (os.cpu_count() or 1)
    descriptions = {t[-1]: describe(t, b) for t in tasks}
    written = []
    if jobs > 1 and len(tasks) > 1:
        with multiprocessing.Pool(min(jobs, len(tasks))) as pool:
            for path in pool.imap_unordered(_write, tasks):
                written.append(path)
                if not quiet:
                    print("%s  %s" % (path, descriptions[path]), flush=True)
    else:
        for task in tasks:
            written.append(_write(task))
            if not quiet:
                print("%s  %s" % (written[-1], descriptions[written[-1]]), flush=True)
    order = {t[-1]: i for i, t in enumerate(tasks)}
    return sorted(written, key=lambda p: (p.endswith("truth.nc") + 2 * p.endswith("fmrc.nc"), order[p]))


def describe(task, b):
    n = "%d x %d grid" % (len(b["lons"]), len(b["lats"]))
    if task[0] == "run":
        run = task[3]
        return "run %d, reference time %s, %d records, %s" % (run["index"], iso(run["reftime"]), len(run["hours"]), n)
    if task[0] == "truth":
        return "truth from %s, %d records, %s" % (iso(task[1].start), len(b["truth_hours"]), n)
    return "FMRC of %d runs x %d records, %s" % (len(b["runs"]), len(b["runs"][0]["hours"]), n)


def stats(opts, b):
    """RMS (m/s) over the grid and the runs of each run against the truth at leads 0, 1, ..., length days; the
    jet_execution example's forecast against its truth for comparison."""
    lines = ["lead_days rms_m_s (mean over %d runs, every grid node)" % len(b["runs"])]
    for lead in range(int(opts.length) + 1):
        values = [rms_difference(run_params(r, r["t_ref"] + lead, opts), b["truth"], r["t_ref"] + lead,
                                 b["lons"], b["lats"]) for r in b["runs"]]
        lines.append("%9d %.4f" % (lead, math.sqrt(sum(v * v for v in values) / len(values))))
    example = dict(TRUTH, B0=1.2, k=0.84, c=0.12)
    ex = [rms_difference(example, TRUTH, t, b["lons"], b["lats"]) for t in range(0, 11)]
    lines.append("examples/jet_execution.yaml forecast vs truth over days 0..10: %.4f m/s"
                 % math.sqrt(sum(v * v for v in ex) / len(ex)))
    return "\n".join(lines)


def main(argv):
    opts = configure(argv)
    begin = clock.time()
    paths = generate(opts)
    total = sum(os.path.getsize(p) for p in paths)
    print("%d files, %.1f MB, %.1f s" % (len(paths), total / 1e6, clock.time() - begin))
    if opts.stats:
        print(stats(opts, bed(opts)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
