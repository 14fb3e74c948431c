"""Python's Field.netcdf() on an OPeNDAP URL (tests/opendap/dap2_server.py on 127.0.0.1): the plan of the file's
travel time, the source in the summary, a cache that serves a second plan, and the inline map of a Result."""
import importlib.util
import json
import os
import signal
import subprocess
import sys
import time

import pytest

import ompl_glider

SOURCE = os.environ.get("OMPL_GLIDER_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SERVER = os.path.join(SOURCE, "tests", "opendap", "dap2_server.py")


def _checker():
    spec = importlib.util.spec_from_file_location("check_opendap", os.path.join(SOURCE, "tests", "opendap",
                                                                               "check_opendap.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture()
def served(tmp_path):
    import netCDF4  # Debian's python3-netcdf4, installed by scripts/setup.sh
    root = tmp_path / "srv"
    root.mkdir()
    _checker().write_forecast(str(root / "f.nc"))
    port_file, log = tmp_path / "port", tmp_path / "log.jsonl"
    proc = subprocess.Popen([sys.executable, SERVER, "--root", str(root), "--port", "0", "--port-file",
                             str(port_file), "--log", str(log), "--lifetime", "200"], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 30
    while not port_file.exists():
        assert proc.poll() is None and time.monotonic() < deadline, "the DAP2 server did not start"
        time.sleep(0.05)
    depart = netCDF4.num2date(230003.0, "hours since 2000-01-01 00:00:00").strftime("%Y-%m-%dT%H:%M:%SZ")
    yield str(root / "f.nc"), "http://127.0.0.1:%s/f.nc" % port_file.read_text().strip(), log, depart
    os.killpg(proc.pid, signal.SIGTERM)
    proc.wait(10)


def test_url_plans_as_the_file_and_the_cache_serves_a_second_plan(served, tmp_path):
    path, url, log, depart = served
    trip = dict(start=(-74.2, 30.4), goal=(-71.6, 31.2), speed=0.5, departure=depart)
    a = ompl_glider.plan(field=ompl_glider.Field.netcdf(path), **trip)
    ompl_glider.set_remote_access(cache=tmp_path / "cache")
    try:
        b = ompl_glider.plan(field=ompl_glider.Field.netcdf(url), **trip)
        assert a.solved and abs(a.travel_time - b.travel_time) <= 1e-12 * a.travel_time
        src = b.summary["forecast_sources"]
        assert len(src) == 1 and src[0]["source"] == url and src[0]["bytes_fetched"] > 0
        requests = len(log.read_text().splitlines())
        c = ompl_glider.plan(field=ompl_glider.Field.netcdf(url), **trip)
        assert c.travel_time == b.travel_time
        assert len(log.read_text().splitlines()) == requests  # all from the process's memory and the cache
    finally:
        ompl_glider.set_remote_access()
    with pytest.raises(ompl_glider.Error, match="request time limit"):
        ompl_glider.set_remote_access(request_timeout=0)
    # a limit NetCDF-C cannot take, or one set after the process's first NetCDF access (which fixed it), is refused
    with pytest.raises(ompl_glider.Error, match="at most 1e6"):
        ompl_glider.set_remote_access(request_timeout=9.3e18)
    with pytest.raises(ompl_glider.Error, match="fixed at .* s by the process's first NetCDF access"):
        ompl_glider.set_remote_access(request_timeout=7777)
    # retries is a count: a float, a text or a bool is refused, not truncated or converted
    for bad in (2.9, "3", True):
        with pytest.raises(ompl_glider.Error, match=r"set_remote_access\(\): retries: expected an integer"):
            ompl_glider.set_remote_access(retries=bad)


def test_result_shows_its_map_inline():
    r = ompl_glider.plan()
    page = r.map_html()
    assert page.startswith("<!DOCTYPE html>") and "window.GLIDER_MAP = {" in page
    data = json.loads(page.split("window.GLIDER_MAP = ", 1)[1].split(";\n", 1)[0])
    assert len(data["routes"][0]["points"]) == len(r.route.x)
    frame = r._repr_html_()
    assert frame.startswith("<iframe") and "srcdoc=" in frame and "&lt;!DOCTYPE html&gt;" in frame


def test_ctrl_c_stops_a_fetch_between_its_retries(tmp_path):
    # a server that answers every request with HTTP 500 and 8 retries (pauses of 1 + 2 + ... + 8 s): Ctrl-C a second
    # in raises KeyboardInterrupt within a few seconds, not after the retries
    import threading

    root = tmp_path / "srv"
    root.mkdir()
    port_file = tmp_path / "port"
    proc = subprocess.Popen([sys.executable, SERVER, "--root", str(root), "--port", "0", "--port-file", str(port_file),
                             "--fail-status", "500", "--lifetime", "100"], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 30
        while not port_file.exists():
            assert proc.poll() is None and time.monotonic() < deadline, "the DAP2 server did not start"
            time.sleep(0.05)
        url = "http://127.0.0.1:%s/f.nc" % port_file.read_text().strip()
        ompl_glider.set_remote_access(retries=8)
        timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            ompl_glider.plan(field=ompl_glider.Field.netcdf(url), start=(-74.2, 30.4), goal=(-71.6, 31.2))
        assert time.monotonic() - start < 6.0
        timer.join()
    finally:
        ompl_glider.set_remote_access()
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(10)


def test_ctrl_c_stops_a_fetch_the_server_stalls(tmp_path):
    # a server that holds every data answer for 100 s (longer than the request time limit, 60 s): Ctrl-C a second
    # and a half in raises KeyboardInterrupt within a few seconds, not when the request's time limit ends
    import threading
    import netCDF4  # noqa: F401  (the server's)

    root = tmp_path / "srv"
    root.mkdir()
    _checker().write_forecast(str(root / "f.nc"))
    port_file = tmp_path / "port"
    proc = subprocess.Popen([sys.executable, SERVER, "--root", str(root), "--port", "0", "--port-file", str(port_file),
                             "--delay", "100", "--lifetime", "150"], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 30
        while not port_file.exists():
            assert proc.poll() is None and time.monotonic() < deadline, "the DAP2 server did not start"
            time.sleep(0.05)
        url = "http://127.0.0.1:%s/f.nc" % port_file.read_text().strip()
        timer = threading.Timer(1.5, lambda: os.kill(os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            ompl_glider.plan(field=ompl_glider.Field.netcdf(url), start=(-74.2, 30.4), goal=(-71.6, 31.2))
        elapsed = time.monotonic() - start
        timer.join()
        assert elapsed < 5.0, elapsed
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(10)


def test_ctrl_c_during_a_fleet_writes_no_folder(tmp_path):
    # a fleet of fine level sets (about a minute): Ctrl-C a second in raises KeyboardInterrupt at once, and out_dir
    # is not written
    import threading

    mission = {"current": {"type": "meandering_jet"}, "region": {"x_min": 0, "x_max": 10, "y_min": -4, "y_max": 4},
               "vehicle": {"speed": 0.5}, "planner": {"name": "LevelSet", "parameters": {"resolution": 0.01}},
               "fleet": [{"name": "alpha", "start": {"x": 1, "y": -3}, "goal": {"x": 8, "y": 3}},
                         {"name": "bravo", "start": {"x": 1, "y": 3}, "goal": {"x": 8, "y": -3}}]}
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        ompl_glider.plan_fleet(mission, out_dir=tmp_path / "fleet")
    assert time.monotonic() - start < 15.0
    timer.join()
    assert not (tmp_path / "fleet").exists()


def test_zarr_store_plans_as_its_netcdf(tmp_path):
    # Field.netcdf() takes a Zarr store (read through GDAL): a Copernicus-like store written by xarray plans with the
    # travel time of the same data in NetCDF, to the bit
    spec = importlib.util.spec_from_file_location("check_gdal_sources", os.path.join(SOURCE, "tests", "gdal",
                                                                                   "check_gdal_sources.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    ds = mod.forecast(nt=3, ny=41, nx=49)
    mod.write_store(ds, str(tmp_path / "f.zarr"), (1, 1, 16, 16), "zstd")
    ds.to_netcdf(str(tmp_path / "f.nc"))
    trip = dict(start=(-74.2, 30.4), goal=(-72.1, 32.3), speed=0.5, departure="2026-06-01T03:00:00Z")
    a = ompl_glider.plan(field=ompl_glider.Field.netcdf(tmp_path / "f.zarr", horizon="hold"), **trip)
    b = ompl_glider.plan(field=ompl_glider.Field.netcdf(tmp_path / "f.nc", horizon="hold"), **trip)
    assert a.solved and b.solved, (a.reason, b.reason)
    assert a.travel_time == b.travel_time
