"""The probability of reach in Python (plan(reachability=True), docs/REACHABILITY.md): the arrays and what they must
satisfy, the quantiles against the members' own goal times, the keywords as glider_plan's flags."""
import math

import numpy as np
import pytest

import ompl_glider
from conftest import glider_plan

# the jet of examples/jet_reachability.yaml: 4 drawn members at a coarse cell (41 x 33 nodes)
JET = {
    "name": "reach",
    "current": {"type": "meandering_jet",
                "parameters": {"B0": 1.2, "epsilon": 0.3, "omega": 0.4, "theta": 1.5707963267948966, "k": 0.84,
                               "c": 0.12},
                "members": 4, "spread": {"B0": 0.25, "k": 0.25, "c": 0.25}, "seed": 7},
    "region": {"x_min": 0, "x_max": 10, "y_min": -4, "y_max": 4},
    "start": {"x": 1.0, "y": -3.0},
    "goal": {"x": 8.0, "y": 3.0},
    "vehicle": {"speed": 1.0},
    "planner": {"name": "zastartve", "grid_size": 0.8, "sectors": 2, "global_check": False},
}


def test_arrays_of_the_probability_of_reach():
    r = ompl_glider.plan(JET, reachability=True, reach_horizon=15, reach_interval=3, reach_resolution=0.25)
    p = r.reachability
    assert p is not None and p["members"] == 4
    nf, ny, nx = p["probability"].shape
    assert (nf, ny, nx) == (5, len(p["y"]), len(p["x"])) and (ny, nx) == (33, 41)
    assert p["member_arrival"].shape == (4, ny, nx)
    assert p["lon"] is None and p["lat"] is None  # no projection: the planning frame only
    np.testing.assert_allclose(p["times"], [3, 6, 9, 12, 15])
    np.testing.assert_allclose(p["weights"], [0.25] * 4)
    prob = p["probability"]
    assert prob.min() >= 0 and prob.max() <= 1
    assert np.all(np.diff(prob, axis=0) >= 0)  # reach is monotone in time
    # p is the share of the members whose own front came by the frame's time, node by node
    share = (p["member_arrival"][None, :, :, :] <= p["times"][:, None, None, None]).mean(axis=1)
    np.testing.assert_allclose(prob, share, atol=1e-6)
    assert 0 < prob[1].mean() < 1 and np.any((prob > 0) & (prob < 1))  # the members disagree somewhere
    # the quantiles are the members' goal times' ceil(q M)-th smallest (all four arrive within 15)
    goal = np.sort(p["goal_travel_times"])
    assert np.all(np.isfinite(goal)) and p["goal_probability"] == 1.0
    for q, t in p["quantiles"].items():
        assert t == goal[math.ceil(q * 4 - 1e-9) - 1]
    assert set(p["quantiles"]) == {0.1, 0.5, 0.9}
    g = r.reachability_geojson
    assert len(g["features"]) == 5 * 2 and {f["properties"]["level"] for f in g["features"]} == {0.5, 0.9}
    assert r.summary["reachability"]["goal"]["probability"] == 1.0


def test_a_quantile_not_reached_by_the_horizon_is_none():
    r = ompl_glider.plan(JET, reachability=True, reach_resolution=0.25, reach_horizon=15)
    goal = np.sort(r.reachability["goal_travel_times"])
    horizon = 0.5 * (goal[1] + goal[2])  # two of the four members arrive by then
    p = ompl_glider.plan(JET, reach_horizon=horizon, reach_resolution=0.25).reachability
    assert p["goal_probability"] == pytest.approx(0.5)
    assert p["quantiles"][0.5] == goal[1]
    assert p["quantiles"][0.9] is None and p["quantile_arrivals"][0.9] is None


def test_bad_keywords_name_themselves():
    with pytest.raises(ompl_glider.Error, match="reach_horizon"):
        ompl_glider.plan(JET, reach_horizon=0)
    with pytest.raises(ompl_glider.Error, match="reach_interval"):
        ompl_glider.plan(JET, reach_interval="1 fortnight")


def test_keywords_and_flags_give_the_same_mission():
    status, out, err, _ = glider_plan("--reach-horizon", "12", "--reach-interval", "2", "--show-mission")
    assert status == 0, err
    cli = dict(line.split(" = ", 1) for line in out.splitlines() if " = " in line)
    py = dict(ompl_glider._core.builtin_mission().with_keywords(reach_horizon=12, reach_interval=2).fields())
    for key in ("reachability.horizon", "reachability.interval", "outputs.files"):
        assert cli[key] == py[key], key
    assert cli["reachability.horizon"] == "12" and "reachability" in cli["outputs.files"]
