"""A mission resumed at sea from the glider's last fix: the command line and Python give the same plan to the bit
(one library function decides, resumeAtLastFix()), the stations left keep their names, radii, windows and stays; the
via keyword takes a radius and a stay with their units, as a mission file does."""
import os

import pytest

import ompl_glider
from conftest import EXAMPLES, glider_plan

SURVEY = os.path.join(EXAMPLES, "survey_labrador.yaml")
DEPLOYMENT = os.path.join(EXAMPLES, "deployment_ru29")
NC = os.path.join(EXAMPLES, "labrador_forecast.nc")


def test_resumed_survey_same_from_cli_and_python(tmp_path):
    rc, out, err, cli = glider_plan("--mission", SURVEY, "--observations", DEPLOYMENT, out_dir=tmp_path / "cli")
    assert rc == 0, err
    resumed = cli["observations"]["resumed"]
    # the deployment's last profile: eight dives of (0.045, 0.02) degrees from (-52.7, 47.9), 24 h after 06:00
    assert resumed["fix"]["time_iso"] == "2026-03-16T06:00:00Z"
    assert resumed["replaced_start"] == "-52.7, 47.9"
    assert resumed["dropped"] == []
    assert cli["departure"]["iso"] == "2026-03-16T06:00:00Z"
    assert "Resumed:" in out and "the deployment's" in out
    # the stations left, whole: A's stay and C's window are still planned
    legs = cli["legs"]
    assert [leg["to"] for leg in legs] == ["A", "B", "C", "goal"]
    r = ompl_glider.plan(SURVEY, observations=DEPLOYMENT)
    assert r.solved
    assert r.travel_time == cli["travel_time"]  # to the bit
    assert r.summary["observations"]["resumed"] == resumed
    assert r.route.lon[0] == pytest.approx(-52.7 + 8 * 0.045, abs=1e-9)


def test_a_start_given_as_a_keyword_is_kept():
    # (the departure too: the file's is the deployment's, before the DAC; learn=False: the bias of -0.17 m/s the eight
    # DAC show, carried ahead, leaves no arrival in C's window from this start, a right answer but not this test's)
    r = ompl_glider.plan(SURVEY, observations=DEPLOYMENT, start=(-52.6, 47.92), departure="2026-03-16T06:00:00Z",
                         learn=False)
    assert r.solved
    assert r.summary["observations"]["resumed"] is None
    assert r.route.lon[0] == pytest.approx(-52.6, abs=1e-9)


def test_via_radius_and_stay_with_units_as_in_a_mission_file():
    a = ompl_glider.plan(SURVEY, via=[{"at": (-52.2, 48.0), "name": "A", "radius": "500 m", "stay": "6 h"},
                                      {"at": (-51.9, 48.2), "name": "B", "radius": "0.5 km"}])
    b = ompl_glider.plan(SURVEY, via=[{"at": (-52.2, 48.0), "name": "A", "radius": 500, "stay": 21600},
                                      {"at": (-51.9, 48.2), "name": "B", "radius": 500}])
    assert a.solved and b.solved
    assert a.travel_time == b.travel_time
    with pytest.raises(ompl_glider.Error, match=r"via\[0\]\.stay"):
        ompl_glider.plan(SURVEY, via=[{"at": (-52.2, 48.0), "stay": "6 parsecs"}])
