"""Missions of several legs: a three-station survey on the Labrador forecast plans the same from the command line,
a mission file and Python, and its files hold every leg."""
import csv
import json
import os
import re

import pytest

import ompl_glider
from conftest import EXAMPLES, glider_plan

NC = os.path.join(EXAMPLES, "labrador_forecast.nc")
STATIONS = [(-52.2, 48.0), (-51.9, 48.2), (-51.65, 48.3)]
START, GOAL = (-52.7, 47.9), (-51.5, 48.45)
DEPARTURE = "2026-03-15T06:00:00Z"


def mission_yaml(path):
    path.write_text(
        "name: survey\n"
        f"current: {{type: netcdf, file: '{NC}'}}\n"
        f"start: {{lon: {START[0]}, lat: {START[1]}}}\n"
        f"goal: {{lon: {GOAL[0]}, lat: {GOAL[1]}}}\n"
        "waypoints:\n" + "".join(f"  - {{name: WP{i + 1}, lon: {lo}, lat: {la}}}\n" for i, (lo, la) in enumerate(STATIONS)) +
        f"departure: {{time: '{DEPARTURE}'}}\nvehicle: {{speed: 0.3}}\n"
        "outputs: {files: [summary, csv, path, geojson, goto, map]}\n")
    return str(path)


def degmin(text):
    """[-]DDDMM.MMMM -> degrees (an independent reader)."""
    neg = text.startswith("-")
    body = text.lstrip("-")
    whole, frac = body.split(".")
    value = int(whole[:-2]) + float(whole[-2:] + "." + frac) / 60.0
    return -value if neg else value


def test_survey_same_from_cli_mission_file_and_python(tmp_path):
    via = ";".join(f"{lo},{la}" for lo, la in STATIONS)
    rc, out, err, cli = glider_plan("--currents", NC, f"--start={START[0]},{START[1]}", f"--goal={GOAL[0]},{GOAL[1]}",
                                    "--via", via, "--speed", "0.3", "--departure", DEPARTURE,
                                    out_dir=tmp_path / "cli")
    assert rc == 0, err
    assert len(cli["legs"]) == 4 and all(l["solved"] for l in cli["legs"])
    rc, _, err, fil = glider_plan("--mission", mission_yaml(tmp_path / "survey.yaml"), out_dir=tmp_path / "file")
    assert rc == 0, err
    py = ompl_glider.plan(field=ompl_glider.Field.netcdf(NC), start=START, goal=GOAL, via=STATIONS,
                          departure=DEPARTURE, speed=0.3)
    assert py.solved
    for s in (fil, py.summary):
        assert s["travel_time"] == pytest.approx(cli["travel_time"], rel=1e-9, abs=0)
        assert [l["to"] for l in s["legs"]] == ["WP1", "WP2", "WP3", "goal"]
    # each leg departs at the previous one's arrival
    legs = cli["legs"]
    for a, b in zip(legs, legs[1:]):
        assert b["departure"] == pytest.approx(a["arrival"] + a["stay"], rel=1e-12)

    # Result.waypoints: the leg and stop of each waypoint, as the result's own waypoints.csv has them
    py.write(tmp_path / "py")
    with open(tmp_path / "py" / "waypoints.csv") as f:
        written = list(csv.DictReader(f))
    w = py.waypoints
    assert list(w["leg"]) == [int(r["leg"]) for r in written] and sorted(set(w["leg"])) == [1, 2, 3, 4]
    assert list(w["stop"]) == [r["stop"] for r in written]
    assert [s for s in w["stop"] if s] == ["start", "WP1", "WP2", "WP3", "goal"]
    assert list(w["index"]) == list(range(len(written)))  # the file's other columns too
    single = ompl_glider.plan(field=ompl_glider.Field.netcdf(NC), start=START, goal=GOAL, departure=DEPARTURE,
                              speed=0.3).waypoints
    assert set(single["leg"]) == {0} and set(single["stop"]) == {""}

    d = tmp_path / "file"
    # waypoints.csv and path.csv: a leg column, every leg, the stops by name
    with open(d / "waypoints.csv") as f:
        rows = list(csv.DictReader(f))
    assert sorted({int(r["leg"]) for r in rows}) == [1, 2, 3, 4]
    assert [r["stop"] for r in rows if r["stop"]] == ["start", "WP1", "WP2", "WP3", "goal"]
    with open(d / "path.csv") as f:
        assert {int(r["leg"]) for r in csv.DictReader(f)} == {1, 2, 3, 4}
    # the goto list and the targets file pass every station, within 1e-4 minutes
    goto = open(d / "goto_l10.ma").read()
    # (the comment lines of a leg of held headings left out: "# to here: hold heading ...")
    body = " ".join(line for line in goto.split("<start:waypoints>")[1].split("<end:waypoints>")[0].splitlines()
                    if not line.lstrip().startswith("#")).split()
    points = [(degmin(body[i]), degmin(body[i + 1])) for i in range(0, len(body), 2)]
    targets = [l.split() for l in open(d / "targets") if l.strip() and not l.startswith("/")]
    named = {t[0]: (degmin(t[2].split("=")[1]), degmin(t[1].split("=")[1])) for t in targets}
    for i, (lo, la) in enumerate(STATIONS):
        assert any(abs(p[0] - lo) < 2e-6 and abs(p[1] - la) < 2e-6 for p in points), f"WP{i + 1} not in the goto list"
        assert abs(named[f"WP{i + 1}"][0] - lo) < 2e-6 and abs(named[f"WP{i + 1}"][1] - la) < 2e-6
    assert targets[-1][0] == "GOAL" and targets[-1][-1] == "goto=GOAL"
    for a, b in zip(targets, targets[1:]):
        assert a[-1] == "goto=" + b[0]
    # KML: a folder per leg; GeoJSON: the whole route; map.html: the stations
    kml = open(d / "route.kml").read()
    assert [m for m in re.findall(r"<name>(leg \d+: [^<]+)</name>", kml)] == [
        "leg 1: start to WP1", "leg 2: WP1 to WP2", "leg 3: WP2 to WP3", "leg 4: WP3 to goal"]
    gj = json.load(open(d / "path.geojson"))
    line = [f for f in gj["features"] if f["geometry"]["type"] == "LineString"][0]["geometry"]["coordinates"]
    for lo, la in STATIONS:
        assert min(abs(c[0] - lo) + abs(c[1] - la) for c in line) < 1e-6
    html = open(d / "map.html").read()
    for name in ("WP1", "WP2", "WP3"):
        assert f'"name":"{name}"' in html.replace(" ", "")


def test_via_keyword_errors_name_the_keyword():
    with pytest.raises(ompl_glider.Error, match="keyword 'via'.*radius"):
        ompl_glider.plan(via=[{"at": (4, 0), "radius": -1}])
    with pytest.raises(ompl_glider.Error, match="keyword 'via'"):
        ompl_glider.plan(via=[{"at": (4, 0), "colour": "red"}])
    with pytest.raises(ompl_glider.Error, match="keyword 'order'"):
        ompl_glider.plan(via=[(4, 0)], order="sideways")


def test_stay_and_free_order_from_python():
    r = ompl_glider.plan(via=[{"at": (6, -2), "name": "far"}, {"at": (2, -2), "name": "near", "stay": 1.0}],
                         order="free", grid_size=0.8)
    assert r.solved
    assert sorted(r.summary["order"]["visited"]) == ["far", "near"]
    s = r.summary["order"]["search"]
    assert s["chosen_travel_time"] == pytest.approx(r.travel_time, rel=1e-12)
    assert s["orders_total"] == 2 and 1 <= s["orders_evaluated"] <= 2
    assert s["chosen_travel_time"] <= s["given_travel_time"]
    near = [l for l in r.summary["legs"] if l["to"] == "near"][0]
    assert near["stay"] == 1.0
