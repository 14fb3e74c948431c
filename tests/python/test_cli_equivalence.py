"""ompl_glider.plan() is the command line's pipeline: the same problem gives the same travel time, status, files
and error messages as glider_plan."""
import csv
import json
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


def test_fleet_same_travel_times_as_glider_plan(tmp_path):
    # a fleet of two on the built-in jet with an island, one flying slower; then a third whose goal is in the island
    mission = {
        "name": "py_fleet",
        "current": {"type": "meandering_jet"},
        "region": {"x_min": 0, "x_max": 10, "y_min": -4, "y_max": 4},
        "vehicle": {"speed": 0.5},
        "planner": {"name": "zastartve", "grid_size": 0.4, "sectors": 3},
        "forbidden": {"obstacles": [{"name": "isle", "kind": "island",
                                     "points": [[6.5, -1.5], [7.5, -1.5], [7.5, -0.5], [6.5, -0.5]]}]},
        "fleet": [{"name": "alpha", "start": {"x": 1, "y": -3}, "goal": {"x": 8, "y": 3}},
                  {"name": "bravo", "start": {"x": 1, "y": 3}, "goal": {"x": 8, "y": -3}, "speed": 0.4}],
    }
    path = tmp_path / "fleet.json"  # JSON is YAML: the same mission for glider_plan
    path.write_text(json.dumps(mission))
    rc, out, err, summary = glider_plan("--mission", str(path), out_dir=tmp_path / "cli")
    assert rc == 0, out + err
    assert summary is not None and "fleet" in summary
    results = ompl_glider.plan_fleet(mission)
    assert list(results) == ["alpha", "bravo"]
    with open(tmp_path / "cli" / "fleet.csv") as f:
        rows = {r["name"]: r for r in csv.DictReader(f)}
    for name in ("alpha", "bravo"):
        assert results[name].solved
        with open(tmp_path / "cli" / name / "summary.json") as f:
            assert results[name].travel_time == json.load(f)["travel_time"]  # bit-identical: one pipeline
        assert abs(results[name].travel_time - float(rows[name]["travel_time"])) <= 1e-6 * results[name].travel_time
    assert results["alpha"].route.x[0] == 1 and results["bravo"].route.y[0] == 3
    assert results["bravo"].travel_time != results["alpha"].travel_time
    # with out_dir: the command line's fleet files, by the library's fleet runner (the same names, the same fleet.csv)
    again = ompl_glider.plan_fleet(mission, out_dir=tmp_path / "py")
    assert [r.travel_time for r in again.values()] == [r.travel_time for r in results.values()]

    def names(root):
        return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs)

    assert names(tmp_path / "py") == names(tmp_path / "cli")
    assert (tmp_path / "py" / "fleet.csv").read_bytes() == (tmp_path / "cli" / "fleet.csv").read_bytes()

    # a glider whose goal is in the island: bad input for both, the island named
    mission["fleet"].append({"name": "charlie", "start": {"x": 2, "y": 0}, "goal": {"x": 7, "y": -1}})
    path.write_text(json.dumps(mission))
    rc, out, err, _ = glider_plan("--mission", str(path), out_dir=tmp_path / "cli2")
    assert rc == 2 and "isle" in err, out + err
    with pytest.raises(ompl_glider.Error, match="isle"):
        ompl_glider.plan_fleet(mission)

    with pytest.raises(ompl_glider.Error, match="no fleet"):
        ompl_glider.plan_fleet({k: v for k, v in mission.items() if k != "fleet"} | {"start": {"x": 1, "y": -3},
                                                                                   "goal": {"x": 8, "y": 3}})
