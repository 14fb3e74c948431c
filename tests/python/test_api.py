"""The Python API: ways in (file, dict, keywords, fields), the result's arrays and dicts, errors, progress."""
import json
import math
import os
import threading

import numpy as np
import pytest

import ompl_glider
from conftest import EXAMPLES

SHEAR = {
    "name": "shear",
    "current": {"type": "linear_shear", "parameters": {"a": 0.2}},
    "region": {"x_min": 0, "x_max": 10, "y_min": -2, "y_max": 2},
    "start": {"x": 1, "y": 0},
    "goal": {"x": 8, "y": 1},
    "vehicle": {"speed": 0.5},
    "planner": {"name": "zastartve", "grid_size": 0.25},
}


def test_dict_and_file_give_the_same_plan(tmp_path):
    path = tmp_path / "shear.yaml"
    path.write_text(json.dumps(SHEAR))
    a = ompl_glider.plan(SHEAR)
    b = ompl_glider.plan(str(path))
    assert a.solved and a.travel_time == b.travel_time
    assert a.summary["mission"] == "shear"


def test_result_arrays_and_dicts():
    r = ompl_glider.plan()
    route = r.route
    n = len(route.x)
    assert n >= 2 and all(len(a) == n for a in route)
    assert (route.x[0], route.y[0]) == (1.0, -3.0)
    assert math.hypot(route.x[-1] - 8, route.y[-1] - 3) < 1e-2
    assert np.all(np.diff(route.t) > 0)
    assert route.t[-1] - route.t[0] == pytest.approx(r.travel_time, rel=1e-12)
    assert np.all(np.isnan(route.lon))  # the built-in mission has no projection
    assert r.summary["travel_time"] == r.travel_time
    gj = r.geojson
    assert gj["type"] == "FeatureCollection"
    assert r.isochrones is None and r.arrival_time is None and r.execution is None
    assert "travel time" in r.report().lower()


def test_keywords_change_the_mission():
    slow = ompl_glider.plan(SHEAR)
    fast = ompl_glider.plan(SHEAR, speed=1.0)
    assert fast.travel_time < slow.travel_time
    assert ompl_glider.plan(SHEAR, planner="TVE").planner == "TVE"
    # another planner than the file's drops the file's planner parameters, as glider_plan --planner does
    tuned = dict(SHEAR, planner=dict(SHEAR["planner"], parameters={"delta_phi_max": 0.5}))
    assert ompl_glider.plan(tuned, planner="LevelSet", grid_size=None).planner == "LevelSet"
    with pytest.raises(ompl_glider.Error, match="delta_phi_max"):  # the file's own planner keeps them, checked
        ompl_glider.plan(tuned, planner_params={"delta_phi_max": "not a number"})


def test_global_check_keyword():
    # against the jet the lattice's route is in another route class: the global check finds a faster one
    checked = ompl_glider.plan(start=(5.66, 1.20), goal=(1.58, -2.61))
    plain = ompl_glider.plan(start=(5.66, 1.20), goal=(1.58, -2.61), global_check=False)
    assert checked.solved and plain.solved
    g = checked.summary["global_check"]
    assert g["winner"] != "ZA*TVE" and g["gain"] > 0.05
    assert plain.summary["global_check"] is None
    assert checked.travel_time < 0.95 * plain.travel_time
    assert g["candidates"][0]["travel_time"] == pytest.approx(plain.travel_time, rel=1e-9)


def test_analytic_field_uniform_current_along_the_trip():
    r = ompl_glider.plan(field=ompl_glider.Field.analytic("uniform", u=0.2, v=0.0), start=(1, 0), goal=(9, 0),
                         speed=0.5)
    assert r.solved
    assert r.travel_time == pytest.approx(8 / 0.7, rel=1e-3)


def test_arrays_field_is_read_as_a_forecast():
    lon = np.linspace(-60.0, -59.0, 21)
    lat = np.linspace(40.0, 40.6, 13)
    u = np.full((lat.size, lon.size), 0.1)  # steady, 0.1 m/s east
    v = np.zeros_like(u)
    field = ompl_glider.Field.from_arrays(u, v, lon=lon, lat=lat)
    r = ompl_glider.plan(field=field, start=(-59.8, 40.3), goal=(-59.2, 40.3), speed=0.4)
    assert r.solved and r.geographic
    distance = r.path_length  # metres in the planning frame
    assert r.travel_time == pytest.approx(distance / 0.5, rel=2e-3)
    # the same arrays with a time axis of datetime64 give the same plan
    times = np.array(["2026-03-15T00", "2026-03-18T00"], dtype="datetime64[s]")
    field2 = ompl_glider.Field.from_arrays(np.stack([u, u]), np.stack([v, v]), lon=lon, lat=lat, t=times)
    r2 = ompl_glider.plan(field=field2, start=(-59.8, 40.3), goal=(-59.2, 40.3), speed=0.4)
    assert r2.travel_time == pytest.approx(r.travel_time, rel=1e-9)
    assert r2.waypoints["time_iso"][0].startswith("2026-03-15")


def test_arrays_field_is_held_in_memory_and_plans_as_the_same_file(tmp_path):
    """from_arrays writes no file (a NetCDF dataset in memory, io/MemoryDataset.h); the same arrays written as a
    file with netCDF4 give the same travel time."""
    import netCDF4  # Debian's python3-netcdf4 (scripts/setup.sh)
    lon = np.linspace(-60.0, -59.0, 21)
    lat = np.linspace(40.0, 40.6, 13)
    X, Y = np.meshgrid(lon, lat)
    u = 0.25 * np.sin(3.0 * (Y - 40.0)) + 0.05
    v = 0.1 * np.cos(2.0 * (X + 60.0))
    u[5:7, 9:11] = np.nan  # a small island
    v[5:7, 9:11] = np.nan
    field = ompl_glider.Field.from_arrays(u, v, lon=lon, lat=lat)
    source = field.settings["files"]
    assert source.startswith("memory:") and not os.path.exists(source)  # a dataset in memory, no file behind it
    r = ompl_glider.plan(field=field, start=(-59.8, 40.3), goal=(-59.2, 40.35), speed=0.4)
    assert r.solved and r.summary["forecast_files"] == [source]
    path = tmp_path / "same.nc"
    with netCDF4.Dataset(path, "w") as d:
        d.createDimension("lat", lat.size)
        d.createDimension("lon", lon.size)
        for name, values, units in (("lat", lat, "degrees_north"), ("lon", lon, "degrees_east")):
            var = d.createVariable(name, "f8", (name,))
            var.units = units
            var[:] = values
        for name, values, std in (("u", u, "eastward_sea_water_velocity"), ("v", v, "northward_sea_water_velocity")):
            var = d.createVariable(name, "f8", ("lat", "lon"), fill_value=1e20)
            var.units = "m s-1"
            var.standard_name = std
            var[:] = np.ma.masked_invalid(values)
    f = ompl_glider.plan(field=ompl_glider.Field.netcdf(str(path)), start=(-59.8, 40.3), goal=(-59.2, 40.35),
                         speed=0.4)
    assert f.solved and abs(f.travel_time - r.travel_time) <= 1e-12 * r.travel_time


def test_arrays_field_rejects_mismatched_axes():
    with pytest.raises(ompl_glider.Error, match="'lon' must be 1-D with 4 values"):
        ompl_glider.Field.from_arrays(np.zeros((3, 4)), np.zeros((3, 4)), lon=np.arange(5.0), lat=np.arange(3.0))


def test_forbidden_keyword_makes_a_detour():
    wall = [(4.0, -1.0), (4.4, -1.0), (4.4, 1.8), (4.0, 1.8)]
    free = ompl_glider.plan(SHEAR)
    blocked = ompl_glider.plan(SHEAR, forbidden=[{"name": "wall", "points": wall}])
    assert blocked.solved and blocked.path_length > free.path_length
    assert [p["name"] for p in blocked.polygons] == ["wall"]
    path = blocked.path
    inside = (path["x"] > 4.0) & (path["x"] < 4.4) & (path["y"] > -1.0) & (path["y"] < 1.8)
    assert not inside.any()


def test_no_path_is_a_result_not_an_error():
    r = ompl_glider.plan(SHEAR, horizon=3.0)  # the goal is 7 units away at speed 0.5
    assert not r.solved and r.reason
    assert math.isinf(r.travel_time)


def test_errors_are_python_exceptions_naming_the_input():
    with pytest.raises(ompl_glider.Error, match="unknown planner 'nope'"):
        ompl_glider.plan(planner="nope")
    with pytest.raises(ompl_glider.Error, match="<mission dict>.*bogus"):
        ompl_glider.plan(dict(SHEAR, bogus=1))
    with pytest.raises(ompl_glider.Error, match="keyword 'speed'"):
        ompl_glider.plan(speed=-1.0)
    with pytest.raises(ompl_glider.Error, match="planner_params"):
        ompl_glider.plan(SHEAR, planner_params={"no_such_parameter": 1})
    with pytest.raises(ompl_glider.Error, match="unknown flow 'nope'"):
        ompl_glider.plan(field=ompl_glider.Field.analytic("nope"))
    assert issubclass(ompl_glider.Error, ValueError)


@pytest.mark.parametrize("keywords, phrase", [
    (dict(speed="fast"), "plan(): keyword 'speed': expected a number, got str 'fast'"),
    (dict(speed=True), "keyword 'speed': expected a number, got bool True"),
    (dict(time_limit=2e6), "keyword 'time_limit': at most 1e6 s"),  # as --time-limit and planner.time_limit
    (dict(sectors=2.5), "keyword 'sectors': expected an integer 1..5, got float 2.5"),
    (dict(smoothing="no"), "keyword 'smoothing': expected True or False, got str 'no'"),
    (dict(refinement=1), "keyword 'refinement': expected True or False, got int 1"),
    (dict(start=(1, 2, 3)), "keyword 'start': expected a pair (x, y) or (lon, lat) of numbers, got tuple (1, 2, 3)"),
    (dict(goal="8,3"), "keyword 'goal': expected a pair"),
    (dict(region=(0, 1)), "keyword 'region': expected four numbers"),
    (dict(grid_size=[1]), "keyword 'grid_size': expected a number, got list [1]"),
    (dict(forbidden=[{"points": "abc"}]), "keyword 'forbidden[0].points': expected a list of (x, y)"),
    (dict(forbidden=[{"points": [(4, -1), (6, -1), (6, 1)], "windows": 5}]),
     "keyword 'forbidden[0].windows': expected a list of (begin, end) pairs, got int 5"),
    (dict(speeds=[0.3, "x"]), "keyword 'speeds': expected a number, got str 'x'"),
    # a bool is no number, also inside a pair or a list; NaN is no "not given"; an empty text no "none"
    (dict(via=[(True, False)]), "keyword 'via[0]': expected a pair (x, y) or (lon, lat) of numbers, or a dict, got tuple "
                                "(True, False) (item [0] is a bool)"),
    (dict(via=[{"at": (4, 1), "radius": float("nan")}]), "keyword 'via[0].radius': expected a number"),
    (dict(via=[(4, float("inf"))]), "(item [1] is not finite)"),
    (dict(start=(1, True)), "keyword 'start': expected a pair (x, y) or (lon, lat) of numbers, got tuple (1, True) "
                            "(item [1] is a bool)"),
    (dict(region=(0, -4, float("nan"), 4)), "keyword 'region': expected four numbers"),
    (dict(radius=float("nan")), "keyword 'radius': expected a number, got float nan (it is not finite)"),
    (dict(goal_tolerance=float("inf")), "keyword 'goal_tolerance': expected a number, got float inf"),
    (dict(keep_off=float("nan")), "keyword 'keep_off': expected a number or a length"),
    (dict(departure=True), "keyword 'departure': expected a number or an ISO 8601 date, got bool True"),
    (dict(departure=float("nan")), "keyword 'departure': expected a number or an ISO 8601 date, got float nan"),
    (dict(arrive_between=(False, 5)), "keyword 'arrive_between': expected a pair (begin, end) of times"),
    (dict(forbidden=[{"points": [(4, -1), (6, -1), (6, True)]}]), "(item [2][1] is a bool)"),
    (dict(observations=""), "keyword 'observations': expected a file name, not an empty one, got str ''"),
    (dict(coastline=""), "keyword 'coastline': expected a file name, not an empty one, got str ''"),
    (dict(truth=""), "keyword 'truth': expected 'forecast', forecast files or a dict of the flow's parameters, got "
                     "an empty text"),
    (dict(truth={"velocity": float("nan")}), "keyword 'truth': expected a dict of numbers"),
    (dict(bathymetry_variable=""), "keyword 'bathymetry_variable': expected a text, got an empty text"),
])
def test_wrong_types_are_errors_naming_the_keyword(keywords, phrase):
    with pytest.raises(ompl_glider.Error) as e:
        ompl_glider.plan(**keywords)
    assert phrase in str(e.value)


def test_field_and_write_arguments_are_checked():
    f = os.path.join(EXAMPLES, "labrador_forecast.nc")
    with pytest.raises(ompl_glider.Error, match=r"steady_record: expected the index of the record .* integer >= 0 .* "
                                                r"got int -1"):
        ompl_glider.Field.netcdf(f, steady_record=-1)
    with pytest.raises(ompl_glider.Error, match="steady_record: .* got float 1.5"):
        ompl_glider.Field.netcdf(f, steady_record=1.5)
    with pytest.raises(ompl_glider.Error, match="Field.netcdf\\(\\): depth: expected a number, got str 'deep'"):
        ompl_glider.Field.netcdf(f, depth="deep")
    with pytest.raises(ompl_glider.Error, match="Field.netcdf\\(\\): depth: expected a finite number, got float nan"):
        ompl_glider.Field.netcdf(f, depth=float("nan"))
    field = ompl_glider.Field.netcdf(f)
    with pytest.raises(ompl_glider.Error, match="keyword 'start': expected a pair .* got str 'ab'"):
        ompl_glider.plan(field=field, start="ab", goal=(-51.5, 48.45))
    with pytest.raises(ompl_glider.Error, match="keyword 'speed': expected a number, got str 'x'"):
        ompl_glider.plan(field=field, start=(-52.7, 47.9), goal=(-51.5, 48.45), speed="x")
    r = ompl_glider.plan(grid_size=0.8, refinement=False)
    with pytest.raises(ompl_glider.Error, match="Result.write\\(\\): out_dir: expected the path of an output "
                                                "directory, got str ''"):
        r.write("")


def test_writes_from_threads_into_sibling_directories(tmp_path):
    r = ompl_glider.plan(grid_size=0.8, refinement=False)
    errors, written = [], {}

    def write(k):
        try:
            written[k] = r.write(tmp_path / f"out{k}")
        except Exception as e:  # noqa: BLE001 (collected and asserted below)
            errors.append(str(e))

    threads = [threading.Thread(target=write, args=(k,)) for k in range(6)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    for k in range(6):
        assert (tmp_path / f"out{k}" / "summary.json").read_bytes() == (tmp_path / "out0" / "summary.json").read_bytes()
    # no staging directory left (the lock files .outK.lock stay by design: removing one would race a waiting run)
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.endswith(".lock")) == [f"out{k}" for k in range(6)]


def test_isochrones_and_arrival_time_field():
    r = ompl_glider.plan(SHEAR, isochrones=True)
    contours = r.isochrones
    assert len(contours) == 8
    assert contours[-1]["time"] == pytest.approx(r.departure + r.travel_time)
    assert all(line.shape[1] == 2 for c in contours for line in c["lines"])
    field = r.arrival_time
    t = field["arrival"]
    assert t.shape == (field["y"].size, field["x"].size)
    i = np.argmin(np.abs(field["x"] - 1.0))
    j = np.argmin(np.abs(field["y"] - 0.0))
    assert t[j, i] < 0.1  # the start is reached at once
    # the goal is first reached about when the plan arrives (level-set cell of 0.1)
    i, j = np.argmin(np.abs(field["x"] - 8.0)), np.argmin(np.abs(field["y"] - 1.0))
    assert t[j, i] == pytest.approx(r.travel_time, rel=0.05)


def test_progress_callback_and_other_threads_run_while_planning():
    mission = dict(SHEAR, departure={"window": {"begin": 0, "end": 4, "spacing": 1}})
    lines = []
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.001)

    t = threading.Thread(target=tick)
    t.start()
    try:
        r = ompl_glider.plan(mission, progress=lambda line, done: lines.append((line, done)))
    finally:
        stop.set()
        t.join()
    assert r.solved
    assert lines and lines[-1][1] is True
    assert len(ticks) > 1  # the thread ran during the plan (the GIL is released)


def test_progress_callback_exception_is_raised_after_the_run():
    mission = dict(SHEAR, departure={"window": {"begin": 0, "end": 2, "spacing": 1}})

    def fail(line, done):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        ompl_glider.plan(mission, progress=fail)


def test_execution_table():
    mission = dict(SHEAR, execution={"truth": {"type": "linear_shear", "parameters": {"a": 0.3}},
                                     "surfacing_interval": 2.0, "strategies": ["current_sensitive", "greedy"]})
    r = ompl_glider.plan(mission)
    table = r.execution
    assert table is not None
    assert table["strategy"] == ["current_sensitive", "greedy"]


def test_planner_names_and_fields():
    names = ompl_glider.planner_names()
    assert "ZA*TVE" in names and "LevelSet" in names and "RRTstar" in names
    assert "meandering_jet" in ompl_glider.analytic_fields()


def test_ctrl_c_stops_a_long_plan_at_once():
    # a level set at 1/100 of the region: about a minute of planning; SIGINT after a second raises KeyboardInterrupt
    # while the plan runs (its searches stop at their next check), not when it would have finished
    import signal
    import time

    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        ompl_glider.plan(planner="LevelSet", planner_params={"resolution": "0.01"})
    assert time.monotonic() - start < 15.0
    timer.join()
    r = ompl_glider.plan(grid_size=0.8, refinement=False)  # the next plan runs to its end
    assert r.solved
