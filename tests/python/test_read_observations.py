"""read_observations() and glider_plan --show-observations give the fixes and DAC the planner reads: checked against
the files read independently (netCDF4 for the IOOS profile files, the CSV's own rows), and the command line's table
against the Python arrays to the table's printed digits."""
import glob
import math
import os

import numpy as np
import pytest

import ompl_glider
from conftest import EXAMPLES, glider_plan

netCDF4 = pytest.importorskip("netCDF4")
DEPLOYMENT = os.path.join(EXAMPLES, "deployment_ru29")


def _ioos_dac():
    """(time_uv, lon_uv, lat_uv, u, v) of every profile file, read with netCDF4, in time order."""
    rows = []
    for path in sorted(glob.glob(os.path.join(DEPLOYMENT, "*.nc"))):
        with netCDF4.Dataset(path) as f:
            f.set_auto_mask(False)
            rows.append(tuple(float(f.variables[k][...]) for k in ("time_uv", "lon_uv", "lat_uv", "u", "v")))
    return sorted(rows)


def test_read_observations_gives_the_ioos_files_dac_and_fixes():
    o = ompl_glider.read_observations(DEPLOYMENT)
    assert set(o) >= {"fixes", "dac", "rejected"}
    for key in ("time", "lon", "lat", "u", "v", "segment_start", "segment_end"):
        assert isinstance(o["dac"][key], np.ndarray) and o["dac"][key].dtype == np.float64
    expected = _ioos_dac()
    assert len(o["dac"]["time"]) == len(expected) == 8
    for k, (t, lon, lat, u, v) in enumerate(expected):
        assert o["dac"]["time"][k] == t and o["dac"]["lon"][k] == lon and o["dac"]["lat"][k] == lat
        assert o["dac"]["u"][k] == u and o["dac"]["v"][k] == v
    # the IOOS files give the segment's mean only: its ends are unknown
    assert np.all(np.isnan(o["dac"]["segment_start"])) and np.all(np.isnan(o["dac"]["segment_end"]))
    # every profile's fix is among the fixes, in time order
    times = o["fixes"]["time"]
    assert np.all(np.diff(times) > 0)
    for path in glob.glob(os.path.join(DEPLOYMENT, "*.nc")):
        with netCDF4.Dataset(path) as f:
            f.set_auto_mask(False)
            t = float(f.variables["profile_time"][...])
            k = int(np.searchsorted(times, t))
            assert times[k] == t
            assert o["fixes"]["lon"][k] == float(f.variables["profile_lon"][...])
            assert o["fixes"]["lat"][k] == float(f.variables["profile_lat"][...])


def test_read_observations_of_a_csv_gives_its_rows(tmp_path):
    csv = tmp_path / "dac.csv"
    csv.write_text("time,lon,lat,u,v\n"
                   "2026-03-15T06:00:00Z,-52.5,47.9,0.10,-0.05\n"
                   "2026-03-15T09:00:00Z,-52.4,47.95,,\n"
                   "2026-03-15T12:00:00Z,-52.3,48.0,9.0,0.0\n")  # faster than any DAC: rejected
    o = ompl_glider.read_observations(str(csv))
    assert list(o["dac"]["u"]) == [0.10] and list(o["dac"]["v"]) == [-0.05]
    assert list(o["dac"]["time"]) == [1773554400.0]
    assert list(o["fixes"]["lon"]) == [-52.5, -52.4, -52.3]
    assert sum(o["rejected"].values()) == 1


def test_show_observations_prints_the_same_arrays(tmp_path):
    rc, out, err, _ = glider_plan("--observations", DEPLOYMENT, "--show-observations")
    assert rc == 0, err
    o = ompl_glider.read_observations(DEPLOYMENT)
    lines = out.splitlines()
    fixes_at = next(i for i, l in enumerate(lines) if l.startswith("fixes: "))
    dac_at = next(i for i, l in enumerate(lines) if l.startswith("dac: "))
    assert int(lines[fixes_at].split()[1]) == len(o["fixes"]["time"])
    assert int(lines[dac_at].split()[1]) == len(o["dac"]["time"])
    fix_rows = [l.split() for l in lines[fixes_at + 2:dac_at] if l.strip()]
    assert len(fix_rows) == len(o["fixes"]["time"])
    for k, row in enumerate(fix_rows):
        assert float(row[0]) == pytest.approx(o["fixes"]["time"][k], abs=0.051)
        assert float(row[2]) == pytest.approx(o["fixes"]["lon"][k], abs=6e-8)
        assert float(row[3]) == pytest.approx(o["fixes"]["lat"][k], abs=6e-8)
    dac_rows = [l.split() for l in lines[dac_at + 2:] if l.strip()]
    assert len(dac_rows) == len(o["dac"]["time"])
    for k, row in enumerate(dac_rows):
        assert float(row[0]) == pytest.approx(o["dac"]["time"][k], abs=0.051)
        assert float(row[2]) == pytest.approx(o["dac"]["lon"][k], abs=6e-8)
        assert float(row[4]) == pytest.approx(o["dac"]["u"][k], abs=6e-6)
        assert float(row[5]) == pytest.approx(o["dac"]["v"][k], abs=6e-6)
        assert math.isnan(float(row[6])) == math.isnan(o["dac"]["segment_start"][k])


def test_show_observations_of_a_bad_source_exits_2(tmp_path):
    rc, _, err, _ = glider_plan("--observations", str(tmp_path / "none"), "--show-observations")
    assert rc == 2 and "none" in err
