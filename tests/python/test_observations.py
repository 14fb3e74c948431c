"""The glider's measurements from Python: plan(observations=...) corrects the forecast with the deployment's DAC and
starts at the last fix, as glider_plan --observations does."""
import os

import pytest

import ompl_glider
from conftest import EXAMPLES, glider_plan

NC = os.path.join(EXAMPLES, "labrador_forecast.nc")
DEPLOYMENT = os.path.join(EXAMPLES, "deployment_ru29")
GOAL = (-51.5, 48.45)


def test_observations_same_as_glider_plan(tmp_path):
    rc, _, err, cli = glider_plan("--currents", NC, "--observations", DEPLOYMENT, f"--goal={GOAL[0]},{GOAL[1]}",
                                  "--speed", "0.3", out_dir=tmp_path / "cli")
    assert rc == 0, err
    obs = cli["observations"]
    assert obs["platform"] == "ru29" and obs["files"] == 8 and obs["used"] >= 1
    assert obs["rms_innovation_after"] < obs["rms_innovation_before"]
    assert obs["last_fix"]["time_iso"] == cli["departure"]["iso"]
    r = ompl_glider.plan(field=ompl_glider.Field.netcdf(NC), goal=GOAL, observations=DEPLOYMENT, speed=0.3)
    assert r.solved
    assert r.travel_time == pytest.approx(cli["travel_time"], rel=1e-12)
    assert r.summary["observations"]["used"] == obs["used"]
    # the route starts at the last fix
    assert abs(r.route.lon[0] - obs["last_fix"]["lon"]) < 1e-9 and abs(r.route.lat[0] - obs["last_fix"]["lat"]) < 1e-9


def test_observations_errors_name_the_keyword(tmp_path):
    with pytest.raises(ompl_glider.Error, match="no such file or folder"):
        ompl_glider.plan(field=ompl_glider.Field.netcdf(NC), goal=GOAL, observations=str(tmp_path / "none"))
