"""Forecast runs from Python: Field.netcdf(files, runs=True) plans on the newest run available at the departure,
to the bit as on that run's file alone (as glider_plan --currents FILES --runs), names it in the summary, and
refuses a run_delay without runs; a THREDDS FMRC of the runs is each of its runs. The runs are the project's test
bed (scripts/make_forecast_runs.py --small)."""
import os
import subprocess
import sys

import pytest

import ompl_glider
from conftest import EXAMPLES

SCRIPT = os.path.join(os.path.dirname(EXAMPLES), "scripts", "make_forecast_runs.py")


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    out = tmp_path_factory.mktemp("runs")
    subprocess.run([sys.executable, SCRIPT, "--small", "--naming", "plain", "--out", str(out)], check=True,
                   capture_output=True)
    files = sorted(str(out / f) for f in os.listdir(out) if f.startswith("run_"))
    assert len(files) >= 3
    return files


def test_runs_plan_on_the_newest_run_as_on_its_file_alone(runs):
    trip = dict(start=(-66.0, 35.0), goal=(-67.0, 35.8), departure="2026-06-02T13:00:00Z", speed=0.4,
                grid_size=10000, global_check=False)
    a = ompl_glider.plan(field=ompl_glider.Field.netcdf(runs, runs=True, horizon="hold_last"), **trip)
    b = ompl_glider.plan(field=ompl_glider.Field.netcdf(runs[1], horizon="hold_last"), **trip)
    assert a.solved and b.solved
    assert a.travel_time == b.travel_time
    run = a.summary["forecast_run"]
    assert run["run"] == 2 and run["runs"] == len(runs)
    assert run["reference_time"] == "2026-06-02T00:00:00Z"
    assert run["available_since"] == "2026-06-02T12:00:00Z"
    assert run["lead_time_at_arrival_hours"] > 13.0
    assert b.summary["forecast_run"] is None


def test_a_run_delay_needs_runs(runs):
    with pytest.raises(ValueError, match="run_delay"):
        ompl_glider.Field.netcdf(runs, run_delay="6 h")
    with pytest.raises(ValueError, match="runs"):
        ompl_glider.Field.netcdf(runs, runs="yes")


def test_a_thredds_fmrc_is_its_runs(tmp_path_factory):
    """One file of every run as a THREDDS FMRC serves it (run dimension, reftime(run), 2-D time(run, time)): the
    same plan as on the run files, the run named by its reference time; given as one forecast, an error."""
    out = tmp_path_factory.mktemp("fmrc")
    subprocess.run([sys.executable, SCRIPT, "--small", "--naming", "plain", "--fmrc", "--out", str(out)], check=True,
                   capture_output=True)
    files = sorted(str(out / f) for f in os.listdir(out) if f.startswith("run_"))
    fmrc = str(out / "fmrc.nc")
    trip = dict(start=(-66.0, 35.0), goal=(-67.0, 35.8), departure="2026-06-02T13:00:00Z", speed=0.4,
                grid_size=10000, global_check=False)
    a = ompl_glider.plan(field=ompl_glider.Field.netcdf(fmrc, runs=True, horizon="hold_last"), **trip)
    b = ompl_glider.plan(field=ompl_glider.Field.netcdf(files, runs=True, horizon="hold_last"), **trip)
    assert a.solved and b.solved
    assert a.travel_time == pytest.approx(b.travel_time, abs=1e-9)
    ra, rb = a.summary["forecast_run"], b.summary["forecast_run"]
    assert ra["run"] == rb["run"] == 2 and ra["runs"] == rb["runs"] == len(files)
    assert ra["reference_time"] == rb["reference_time"] == "2026-06-02T00:00:00Z"
    assert "reftime" in ra["reference_from"]
    with pytest.raises(Exception, match="forecast runs"):
        ompl_glider.plan(field=ompl_glider.Field.netcdf(fmrc, horizon="hold_last"), **trip)
