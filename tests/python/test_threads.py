"""Plans in several Python threads at once (concurrent.futures), each on its own forecast: currents from arrays
(NetCDF datasets built and read in memory) and a NetCDF file. NetCDF-C is not thread-safe; the library holds one
lock around every NetCDF-C call (src/io/DatasetLock.h), so each answer is the one the same plan gives alone, to the
bit, and no thread crashes or reads another's dataset."""
import concurrent.futures
import os

import numpy as np

import ompl_glider

SOURCE = os.environ.get("OMPL_GLIDER_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
FILE = os.path.join(SOURCE, "examples", "labrador_forecast.nc")


def _arrays(k):
    """A small steady field, a little different for each k, with an island."""
    lon = np.linspace(-60.0, -59.0, 21)
    lat = np.linspace(40.0, 40.6, 13)
    X, Y = np.meshgrid(lon, lat)
    u = (0.2 + 0.03 * k) * np.sin(3.0 * (Y - 40.0)) + 0.05
    v = 0.1 * np.cos(2.0 * (X + 60.0)) - 0.02 * k
    u[5:7, 9:11] = np.nan
    v[5:7, 9:11] = np.nan
    return u, v, lon, lat


def _task(job):
    """One plan: the field built in this thread (arrays: a new in-memory dataset each time), planned."""
    kind, k = job
    if kind == "arrays":
        u, v, lon, lat = _arrays(k)
        field = ompl_glider.Field.from_arrays(u, v, lon=lon, lat=lat)
        r = ompl_glider.plan(field=field, start=(-59.8, 40.3), goal=(-59.2, 40.35), speed=0.4, global_check=False)
    else:
        field = ompl_glider.Field.netcdf(FILE)
        r = ompl_glider.plan(field=field, start=(-52.7, 47.9), goal=(-52.3, 48.05), speed=0.3,
                             departure="2026-03-15T06:00:00Z", global_check=False)
    assert r.solved, (job, r.reason)
    return r.travel_time, float(r.route.x[-1]), float(r.route.y[-1])


JOBS = [("arrays", k) for k in range(6)] + [("file", 0), ("file", 1)]


def test_eight_threads_plan_as_each_plan_alone():
    alone = {job: _task(job) for job in JOBS}
    for _ in range(5):  # a few rounds: a race shows within them (a crash, or "Not a valid ID") before the lock
        with concurrent.futures.ThreadPoolExecutor(max_workers=8) as pool:
            together = dict(zip(JOBS, pool.map(_task, JOBS)))
        for job in JOBS:
            assert together[job] == alone[job], job  # bit-identical: the same travel time and end point
