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


def _cli_fields(*args):
    rc, out, err, _ = glider_plan(*args, "--show-mission")
    assert rc == 0, err
    fields = dict(line.split(" = ", 1) for line in out.splitlines() if " = " in line)
    assert "planner.name" in fields and "given" in fields
    return fields


@pytest.mark.parametrize("mission", [None, "islands_ice.yaml", "shear_goal_window.yaml"])
def test_the_same_overrides_give_the_same_mission_field_by_field(mission, tmp_path):
    """The flags and the keywords are one override set (Overrides.h): every field it can change, and which fields
    are marked as given, agree between glider_plan and Python."""
    coast = os.path.join(EXAMPLES, "jamaica_coast.geojson")
    flags = ["--planner", "LevelSet", "--grid-size", "0.3", "--sectors", "4", "--time-limit", "12", "--speed",
             "0.45", "--departure", "1.5", "--start", "1.25,-2", "--goal", "8.5,2.75", "--region=0,-4,10,4",
             "--no-smooth", "--no-refine", "--no-global-check", "--arrive-between", "20,30",
             "--coastline", coast, "--isochrone-interval", "2.5", "--goto-turn", "15"]
    keywords = dict(planner="LevelSet", grid_size=0.3, sectors=4, time_limit=12, speed=0.45, departure=1.5,
                    start=(1.25, -2), goal=(8.5, 2.75), region=(0, -4, 10, 4), smoothing=False, refinement=False,
                    global_check=False, arrive_between=(20, 30), coastline=coast, isochrone_interval=2.5,
                    goto_turn=15)
    if mission is None:
        # the built-in mission's region is fixed (--region belongs to --currents and --mission)
        flags.remove("--region=0,-4,10,4")
        del keywords["region"]
        cli = _cli_fields(*flags)
        spec = ompl_glider._core.builtin_mission()
    else:
        path = os.path.join(EXAMPLES, mission)
        cli = _cli_fields("--mission", path, *flags)
        spec = ompl_glider._core.load_mission(path)
    before = dict(spec.fields())
    py = dict(spec.with_keywords(**keywords).fields())
    if mission is None:
        py["outputs.directory"] = cli["outputs.directory"]  # the built-in mode writes where --out says ("" here)
    assert py == cli
    # the overrides did change the mission: the two front ends do not merely agree on leaving it alone
    changed = {k for k in py if py[k] != before[k]}
    assert {"planner.name", "planner.grid_size", "planner.sectors", "vehicle.speed", "start", "goal",
            "goal.window", "forbidden.coastline", "outputs.isochrone_interval"} <= changed


def test_planner_keyword_drops_the_files_planner_parameters_like_the_flag():
    path = os.path.join(EXAMPLES, "campaign_islands.yaml")  # LevelSet with resolution: 0.05
    cli = _cli_fields("--mission", path, "--planner", "ZA*TVE")
    py = dict(ompl_glider._core.load_mission(path).with_keywords(planner="ZA*TVE").fields())
    assert cli["planner.parameters"] == py["planner.parameters"] == ""
    same = dict(ompl_glider._core.load_mission(path).with_keywords(planner="LevelSet").fields())
    assert same["planner.parameters"] == "resolution=0.05"


@pytest.mark.parametrize("flag, keyword, value, says", [
    ("--sectors", "sectors", "7", "1..5"),
    ("--arrive-between", "arrive_between", "30,20", "must not be before the begin"),
    ("--goto-turn", "goto_turn", "200", "0..180"),
])
def test_a_bad_override_is_refused_alike(flag, keyword, value, says):
    rc, _, err, _ = glider_plan(flag, value, "--show-mission")
    assert rc == 2 and says in err, err
    py_value = tuple(float(v) for v in value.split(",")) if "," in value else float(value)
    if keyword == "sectors":
        py_value = int(py_value)
    with pytest.raises(ompl_glider.Error) as e:
        ompl_glider._core.builtin_mission().with_keywords(**{keyword: py_value})
    assert says in str(e.value) and f"keyword '{keyword}'" in str(e.value)
