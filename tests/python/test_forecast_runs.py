"""The forecast-run test bed (scripts/make_forecast_runs.py): its files as netCDF-C's ncdump reads them back (how
many, each run's reference time, the CF layout, the values against the script's own field()), an error against the
truth that grows with lead time, and runs that differ where they overlap. Pure Python: ncgen and ncdump only."""
import datetime
import importlib.util
import math
import os
import re
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

SCRIPT = os.path.join(SOURCE_DIR, "scripts", "make_forecast_runs.py")
pytestmark = pytest.mark.skipif(not (shutil.which("ncgen") and shutil.which("ncdump")),
                                reason="netCDF-C's ncgen and ncdump are needed")


def load_script():
    spec = importlib.util.spec_from_file_location("make_forecast_runs", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


runs_bed = load_script()


def generate(out, *args):
    p = subprocess.run([sys.executable, SCRIPT, "--out", str(out), *args], capture_output=True, text=True,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    return p.stdout


def header(path):
    return subprocess.run(["ncdump", "-h", str(path)], capture_output=True, text=True, check=True).stdout


def values(path, name):
    """The values of a variable as ncdump -v prints them (floats; a scalar as a list of one)."""
    text = subprocess.run(["ncdump", "-v", name, str(path)], capture_output=True, text=True, check=True).stdout
    data = text.split("\ndata:\n", 1)[1]
    m = re.search(r"^\s*%s =(.*?);" % re.escape(name), data, re.S | re.M)
    return [float(x) for x in m.group(1).replace("\n", " ").split(",") if x.strip()]


def dims(path):
    block = header(path).split("dimensions:", 1)[1].split("variables:", 1)[0]
    return {m.group(1): int(m.group(2)) for m in re.finditer(r"(\w+) = (\d+) ;", block)}


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    out = tmp_path_factory.mktemp("runs")
    printed = generate(out, "--small", "--fmrc")
    opts = runs_bed.configure(["--small", "--fmrc", "--out", str(out)])
    return out, printed, opts, runs_bed.bed(opts)


def run_path(out, opts, run):
    return os.path.join(str(out), runs_bed.run_file_name(opts, run))


def test_the_small_preset_writes_its_runs_the_truth_and_the_fmrc(small):
    out, printed, opts, bed = small
    assert (opts.runs, opts.length, opts.step, opts.resolution) == (4, 3.0, 6.0, 0.25)
    names = sorted(os.listdir(str(out)))
    assert len(names) == 4 + 2 and "truth.nc" in names and "fmrc.nc" in names
    assert not [n for n in names if n.endswith(".cdl")]
    runs = [n for n in names if n.startswith("cmems_mod_glo_phy_anfc_merged-uv_PT6H-i_")]
    assert runs == ["cmems_mod_glo_phy_anfc_merged-uv_PT6H-i_2026060%d-2026060%d_R2026060%d.nc" % (d, d + 3, d)
                    for d in range(1, 5)]
    # one line per file, and the total
    assert sum(1 for line in printed.splitlines() if line.split()[0].endswith(".nc")) == 6


def test_each_run_gives_its_reference_time_and_its_own_time_origin(small):
    out, _, opts, bed = small
    for r, run in enumerate(bed["runs"]):
        path = run_path(out, opts, run)
        ref = datetime.datetime(2026, 6, 1 + r, tzinfo=datetime.timezone.utc)
        hours = (ref - datetime.datetime(1970, 1, 1, tzinfo=datetime.timezone.utc)).total_seconds() / 3600
        assert values(path, "forecast_reference_time") == [hours]
        h = header(path)
        assert 'forecast_reference_time:standard_name = "forecast_reference_time"' in h
        assert 'forecast_reference_time:units = "hours since 1970-01-01 00:00:00"' in h
        assert 'time:units = "hours since %s"' % ref.strftime("%Y-%m-%d %H:%M:%S") in h
        assert 'time:calendar = "standard"' in h
        assert values(path, "time") == [6.0 * i for i in range(13)]
        assert dims(path) == {"time": 13, "lat": len(bed["lats"]), "lon": len(bed["lons"])}
        for text in ('uo:standard_name = "eastward_sea_water_velocity"',
                     'vo:standard_name = "northward_sea_water_velocity"', 'uo:units = "m s-1"', "uo:_FillValue",
                     'lat:units = "degrees_north"', 'lon:units = "degrees_east"', ':Conventions = "CF-1.8"',
                     "float uo(time, lat, lon)", "float vo(time, lat, lon)"):
            assert text in h
    truth = os.path.join(str(out), "truth.nc")
    assert "forecast_reference_time" not in header(truth)
    assert 'time:units = "hours since 2026-06-01 00:00:00"' in header(truth)
    assert values(truth, "time")[-1] == (4 + 3) * 24.0  # runs * interval + length


def test_the_grid_covers_the_jet_missions_region(small):
    _, _, opts, bed = small
    lons, lats = bed["lons"], bed["lats"]
    assert lons[0] <= -70.0 and lons[-1] >= runs_bed.lon_of_x(10.0)
    assert lats[0] <= runs_bed.lat_of_y(-4.0) and lats[-1] >= runs_bed.lat_of_y(4.0)
    # the mapping: 500 km east and 400 km north of 70W 36N on the equirectangular sphere
    assert abs(runs_bed.lon_of_x(10.0) - (-70.0 + 500.0 / (6371.0 * math.cos(math.radians(36.0)) * math.pi / 180))) \
        < 1e-9
    assert abs(runs_bed.lat_of_y(4.0) - (36.0 + 200.0 / (6371.0 * math.pi / 180))) < 1e-9


def test_the_files_hold_the_field_of_the_scripts_function(small):
    out, _, opts, bed = small
    lons, lats = bed["lons"], bed["lats"]
    assert values(run_path(out, opts, bed["runs"][0]), "lon") == pytest.approx(lons, abs=1e-9)
    run = bed["runs"][1]
    path = run_path(out, opts, run)
    uo, vo = values(path, "uo"), values(path, "vo")
    n = len(lons) * len(lats)
    assert len(uo) == 13 * n
    worst = 0.0
    for rec in (0, 6, 12):
        t = run["t_ref"] + rec * 6.0 / 24.0
        p = runs_bed.run_params(run, t, opts)
        for j, lat in enumerate(lats):
            for i, lon in enumerate(lons):
                u, v = runs_bed.field(p, t, lon, lat)
                k = rec * n + j * len(lons) + i
                worst = max(worst, abs(uo[k] - u), abs(vo[k] - v))
    assert worst < 2e-5
    # the truth file: the truth's parameters, and a jet of about 0.58 m/s at its core
    truth = os.path.join(str(out), "truth.nc")
    tu = values(truth, "uo")
    rec = 10
    t = rec * 6.0 / 24.0
    for j in range(0, len(lats), 4):
        for i in range(0, len(lons), 5):
            u, _ = runs_bed.field(runs_bed.TRUTH, t, lons[i], lats[j])
            assert abs(tu[rec * n + j * len(lons) + i] - u) < 2e-5
    assert 0.5 < max(tu) < 0.6


def test_the_error_against_the_truth_grows_with_lead_time(small):
    _, _, opts, bed = small
    lons, lats, truth = bed["lons"], bed["lats"], bed["truth"]
    for run in bed["runs"]:
        errors = []
        for lead in (0.0, 1.0, 2.0, 3.0):
            t = run["t_ref"] + lead
            errors.append(runs_bed.rms_difference(runs_bed.run_params(run, t, opts), truth, t, lons, lats))
        assert all(a < b for a, b in zip(errors, errors[1:])), errors
        assert errors[0] < 0.03 and errors[-1] > 2 * errors[0]
    # with the defaults (10 days): of the order of jet_execution.yaml's forecast against its truth at 10 days
    full = runs_bed.configure(["--out", "unused", "--resolution", "0.25"])
    fb = runs_bed.bed(full)
    run = fb["runs"][3]
    t = run["t_ref"] + 10.0
    at10 = runs_bed.rms_difference(runs_bed.run_params(run, t, full), fb["truth"], t, fb["lons"], fb["lats"])
    example = dict(runs_bed.TRUTH, B0=1.2, k=0.84, c=0.12)
    ex = runs_bed.rms_difference(example, runs_bed.TRUTH, 10.0, fb["lons"], fb["lats"])
    assert 0.4 * ex < at10 < 2.5 * ex


def test_two_runs_valid_at_the_same_time_differ(small):
    out, _, opts, bed = small
    n = len(bed["lons"]) * len(bed["lats"])
    first = values(run_path(out, opts, bed["runs"][0]), "uo")
    second = values(run_path(out, opts, bed["runs"][1]), "uo")
    # 2026-06-02T00: record 4 of the run of June 1 (lead 1 day), record 0 of the run of June 2 (lead 0)
    a, b = first[4 * n:5 * n], second[0:n]
    rms = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / n)
    assert rms > 0.005
    # and by the function: every pair of runs at a valid time they share
    t = 3.0
    params = [runs_bed.run_params(r, t, opts) for r in bed["runs"] if r["t_ref"] <= t]
    for i in range(len(params)):
        for j in range(i + 1, len(params)):
            assert runs_bed.rms_difference(params[i], params[j], t, bed["lons"], bed["lats"]) > 0.005


def test_the_fmrc_file_has_two_dimensional_time(small):
    out, _, opts, bed = small
    path = os.path.join(str(out), "fmrc.nc")
    assert dims(path) == {"run": 4, "time": 13, "lat": len(bed["lats"]), "lon": len(bed["lons"])}
    h = header(path)
    assert "double reftime(run)" in h and "double time(run, time)" in h and "float uo(run, time, lat, lon)" in h
    assert 'reftime:standard_name = "forecast_reference_time"' in h
    refs = values(path, "reftime")
    assert [b - a for a, b in zip(refs, refs[1:])] == [24.0, 24.0, 24.0]
    valid = values(path, "time")
    assert valid[13] == refs[1] and valid[13 + 4] == refs[1] + 24.0
    # run 1 in the collection is run 1's file
    n = len(bed["lons"]) * len(bed["lats"])
    assert values(path, "vo")[13 * n:26 * n] == values(run_path(out, opts, bed["runs"][1]), "vo")


def test_reference_time_as_attribute_or_left_out_and_other_names(tmp_path):
    generate(tmp_path / "a", "--small", "--runs", "2", "--length", "1", "--reftime", "attribute", "--naming",
             "hycom", "--interval", "12", "--truth-days", "1")
    names = sorted(os.listdir(str(tmp_path / "a")))
    assert names == ["hycom_glby_930_2026060100_t000_uv3z.nc", "hycom_glby_930_2026060112_t000_uv3z.nc",
                     "truth.nc"]
    h = header(tmp_path / "a" / names[1])
    assert ':forecast_reference_time = "2026-06-01T12:00:00Z"' in h
    assert "double forecast_reference_time" not in h
    assert 'time:units = "hours since 2026-06-01 12:00:00"' in h
    generate(tmp_path / "b", "--small", "--runs", "1", "--length", "1", "--reftime", "none", "--naming", "plain")
    assert sorted(os.listdir(str(tmp_path / "b"))) == ["run_20260601T00.nc", "truth.nc"]
    assert "forecast_reference_time" not in header(tmp_path / "b" / "run_20260601T00.nc")


def test_the_defaults_and_the_seed():
    opts = runs_bed.configure(["--out", "unused"])
    assert (opts.runs, opts.interval, opts.length, opts.step, opts.resolution) == (21, 24.0, 10.0, 3.0, 0.1)
    assert opts.truth_days == 31.0
    b = runs_bed.bed(opts)
    assert len(b["runs"][0]["hours"]) == 81 and len(b["truth_hours"]) == 249
    # a seed draws the same runs; another seed others; run r's numbers do not depend on how many runs follow
    again = runs_bed.bed(runs_bed.configure(["--out", "unused", "--runs", "3"]))
    assert again["runs"] == b["runs"][:3]
    other = runs_bed.bed(runs_bed.configure(["--out", "unused", "--seed", "2"]))
    assert other["runs"][0]["eB"] != b["runs"][0]["eB"]
