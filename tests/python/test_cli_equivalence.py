"""ompl_glider.plan() is the command line's pipeline: the same problem gives the same travel time, status, files
and error messages as glider_plan."""
import os

import pytest

import ompl_glider
from conftest import EXAMPLES, glider_plan


def test_builtin_mission_same_travel_time_as_glider_plan(tmp_path):
    rc, _, _, summary = glider_plan(out_dir=tmp_path / "cli")
    assert rc == 0
    r = ompl_glider.plan()
    assert r.solved and r.status == summary["status"]
    assert r.travel_time == summary["travel_time"]  # bit-identical: one pipeline
    assert r.planner == "ZA*TVE"


def test_keywords_same_as_flags(tmp_path):
    rc, _, _, summary = glider_plan("--speed", "0.7", "--start", "1,-2", "--goal", "9,2", "--grid-size", "0.5",
                                    out_dir=tmp_path / "cli")
    assert rc == 0
    r = ompl_glider.plan(speed=0.7, start=(1, -2), goal=(9, 2), grid_size=0.5)
    assert r.travel_time == summary["travel_time"]
    assert r.route.x[0] == 1 and r.route.y[-1] == 2


def test_forecast_same_travel_time_as_glider_plan_currents(tmp_path):
    nc = os.path.join(EXAMPLES, "labrador_forecast.nc")
    args = ["--currents", nc, "--start=-52.7,47.9", "--goal=-51.5,48.45", "--departure", "2026-03-15T06:00:00Z",
            "--grid-size", "5000"]
    rc, _, _, summary = glider_plan(*args, out_dir=tmp_path / "cli")
    assert rc == 0
    r = ompl_glider.plan(field=ompl_glider.Field.netcdf(nc), start=(-52.7, 47.9), goal=(-51.5, 48.45),
                         departure="2026-03-15T06:00:00Z", grid_size=5000)
    assert r.travel_time == summary["travel_time"]
    assert r.geographic
    assert abs(r.route.lon[0] + 52.7) < 1e-9 and abs(r.route.lat[-1] - 48.45) < 1e-9


def test_write_gives_the_command_lines_files(tmp_path):
    glider_plan(out_dir=tmp_path / "cli")
    written = ompl_glider.plan().write(tmp_path / "py")
    assert sorted(os.listdir(tmp_path / "py")) == sorted(os.listdir(tmp_path / "cli"))
    assert sorted(os.path.basename(p) for p in written) == sorted(os.listdir(tmp_path / "py"))
    with open(tmp_path / "py" / "waypoints.csv") as a, open(tmp_path / "cli" / "waypoints.csv") as b:
        assert a.read() == b.read()


def test_bad_mission_file_same_message_as_glider_plan(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: bad\ncurrent: {type: meandering_jet}\nregion: {x_min: 0, x_max: 10, y_min: -4, "
                   "y_max: 4}\nstart: {x: 1, y: -3}\ngoal: {x: 8, y: 3}\nvehicle: {speed: -0.5}\n")
    rc, _, err, _ = glider_plan("--mission", str(bad))
    assert rc == 2
    with pytest.raises(ompl_glider.Error) as e:
        ompl_glider.plan(str(bad))
    assert err.strip() == "glider_plan: " + str(e.value)
    assert "bad.yaml:6" in str(e.value) and "vehicle.speed" in str(e.value)


def test_bad_start_same_message_as_glider_plan_but_naming_the_keyword():
    rc, _, err, _ = glider_plan("--start", "20,0")
    assert rc == 2
    with pytest.raises(ompl_glider.Error) as e:
        ompl_glider.plan(start=(20, 0))
    message = str(e.value)
    assert message.startswith("plan(): keyword 'start'")
    # the same words after the place (the command line names its flag there)
    assert err.strip().split("--start", 1)[1] == message.split("plan(): keyword 'start'", 1)[1]
