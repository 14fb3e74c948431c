#!/usr/bin/env python3
"""Bad and edge inputs for glider_plan, one table row each: mission YAML, NetCDF files, flags, output directories.

Every row runs glider_plan in a fresh directory that holds an output directory with an earlier run's files, and
asserts the exit status (2: bad input, 1: a well-formed problem without a path), a phrase of the message
(case-insensitive), that no signal ended the process, that no NaN was printed, and that the output directory is
unchanged, byte for byte. Usage: bad_inputs.py GLIDER_PLAN [-k SUBSTRING] [-v]
"""
import base64
import hashlib
import json
import os
import shutil
import subprocess
import struct
import sys
import tempfile

# ---------------------------------------------------------------------------------------------------------------
# Inputs the rows are built from

MISSION = """name: base
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
"""

# A forecast as ocean models write it: CF attributes, float u/v with a fill value, hours since a date.
FORECAST = """netcdf forecast {
dimensions: time = UNLIMITED ; lat = 6 ; lon = 6 ;
variables:
  double time(time) ; time:units = "hours since 2026-03-15 00:00:00" ; time:standard_name = "time" ;
  double lat(lat) ; lat:units = "degrees_north" ; lat:standard_name = "latitude" ;
  double lon(lon) ; lon:units = "degrees_east" ; lon:standard_name = "longitude" ;
  float u(time, lat, lon) ; u:units = "m s-1" ; u:standard_name = "eastward_sea_water_velocity" ;
    u:_FillValue = -999.f ;
  float v(time, lat, lon) ; v:units = "m s-1" ; v:standard_name = "northward_sea_water_velocity" ;
    v:_FillValue = -999.f ;
data:
  time = 0, 24, 48 ;
  lat = LAT ;
  lon = LON ;
  u = UDATA ;
  v = VDATA ;
}
"""
LAT = "47.0, 47.2, 47.4, 47.6, 47.8, 48.0"
LON = "-53.0, -52.8, -52.6, -52.4, -52.2, -52.0"
START, GOAL = "--start=-52.9,47.1", "--goal=-52.1,47.9"


def forecast(lat=LAT, lon=LON, u="0.1", replace=()):
    text = FORECAST.replace("LAT", lat).replace("LON", lon)
    text = text.replace("UDATA", u if "," in u else ", ".join([u] * 108)).replace("VDATA", ", ".join(["0"] * 108))
    for a, b in replace:
        assert a in text, a
        text = text.replace(a, b)
    return text


def mission(*edits, append=""):
    """The base mission with lines replaced (key prefix -> new line) and lines appended."""
    lines = MISSION.splitlines()
    for new in edits:
        key = new.split(":")[0] + ":"
        hit = [i for i, l in enumerate(lines) if l.startswith(key)]
        if hit:
            lines[hit[0]] = new
        else:
            lines.append(new)
    return "\n".join(lines) + "\n" + append


def nested(depth):
    return "name: deep\nx: " + "[" * depth + "]" * depth + "\n"


# ---------------------------------------------------------------------------------------------------------------
# The table: (name, files, arguments, exit status, phrase). Files: name -> text (".cdl" files are also turned into
# ".nc" with ncgen; a value ("truncate", cdl text) writes the classic file cut in half). "{out}" in the arguments
# is the output directory holding the earlier run; "{dir}" the case's directory.
CASES = []


def case(name, args, status, phrase, files=None, env=None):
    CASES.append((name, files or {}, args, status, phrase, env or {}))


def yaml_case(name, text, phrase, status=2):
    case(name, ["--mission", "m.yaml", "--out", "{out}"], status, phrase, {"m.yaml": text})


def nc_case(name, cdl, phrase, args=(START, GOAL), status=2, extra=()):
    files = {"f.cdl": cdl}
    case(name, ["--currents", "f.nc", *args, "--out", "{out}", *extra], status, phrase, files)


# --- mission files: structure ----------------------------------------------------------------------------------
yaml_case("yaml-empty", "", "m.yaml: the mission file is empty")
yaml_case("yaml-only-comment", "# nothing\n", "empty")
yaml_case("yaml-syntax", MISSION + "planner: {name: [\n", "m.yaml:9: YAML syntax error")
yaml_case("yaml-tab-indent", MISSION.replace("current:", "current:\n\t- x"), "m.yaml")
yaml_case("yaml-deep-nesting", nested(100000), "nest")
yaml_case("yaml-not-a-map", "- a\n- b\n", "expected a mapping")
yaml_case("yaml-unknown-top-field", MISSION + "colour: red\n", "m.yaml:8: unknown field 'colour'")
yaml_case("yaml-duplicate-key", MISSION + "vehicle: {speed: 0.4}\n", "given twice")
yaml_case("yaml-two-documents", MISSION + "---\nname: second\n",
          "m.yaml:8: a second YAML document: a mission file holds one document")
yaml_case("yaml-fleet-entry-missing-goal", mission(append="fleet:\n  - {name: a, start: {x: 1, y: 0}}\n"),
          "m.yaml:9: field 'fleet[0].goal': missing")
yaml_case("yaml-fleet-start-on-island",
          mission(append="forbidden:\n  obstacles:\n    - {name: rock, kind: island, points: [[4, 1], [6, 1], [6, 3], "
                         "[4, 3]]}\nfleet:\n  - {name: a, start: {x: 1, y: 0}, goal: {x: 9, y: 0}}\n"
                         "  - {name: b, start: {x: 5, y: 2}, goal: {x: 9, y: 2}}\n"),
          "glider 'b': m.yaml:13: field 'start'")
yaml_case("yaml-epoch-arrival-after-9999", mission("epoch: 9999-12-31T00:00:00Z", "units: {time_s: 86400}"),
          "field 'epoch': t = 13.33333333 falls outside the years 0000-9999")
case("cli-truth-overflows", ["--truth", "B0=1e300", "--out", "{out}"], 2,
     "--truth: the current is not a finite number at (0, -4) at t = 0: its parameters overflow")
yaml_case("yaml-current-overflows",
          mission("current: {type: meandering_jet, parameters: {B0: 1e300}}"),
          "m.yaml:2: field 'current.parameters': the current is not a finite number")
yaml_case("yaml-mapping-as-key", "name: x\n? {a: 1}\n: 2\n" + MISSION.split("\n", 1)[1],
          "m.yaml:2: a key is a mapping: keys are plain names (allowed here: current")
yaml_case("yaml-mapping-as-key-nested", mission("vehicle: {? [1, 2] : 3, speed: 0.5}"),
          "m.yaml:6: a key in 'vehicle' is a list: keys are plain names")
yaml_case("yaml-start-without-value", MISSION.replace("start: {x: 1, y: 0}", "start:\n\n"),
          "m.yaml:4: field 'start': has no value; expected a mapping")
yaml_case("yaml-last-key-without-value", MISSION + "outputs:\n",
          "m.yaml:8: field 'outputs': has no value")
yaml_case("yaml-binary-garbage", "\x00\x01\x02\xff\xfe", "m.yaml")
case("mission-is-a-directory", ["--mission", "sub", "--out", "{out}"], 2, "is a directory", {"sub/x": "x"})
case("mission-missing", ["--mission", "nope.yaml", "--out", "{out}"], 2, "cannot read mission file 'nope.yaml'")

# --- mission files: values --------------------------------------------------------------------------------------
yaml_case("current-type-unknown", mission("current: {type: tidal}"), "current.type")
yaml_case("current-param-unknown", mission("current: {type: uniform, parameters: {w: 1}}"),
          "unknown field 'current.parameters.w'")
yaml_case("current-param-nan", mission("current: {type: uniform, parameters: {u: .nan}}"), "NaN")
yaml_case("double-gyre-length-0", mission("current: {type: double_gyre, parameters: {length: 0}}"),
          "current.parameters.length")
yaml_case("netcdf-file-missing", mission("current: {type: netcdf, file: none.nc}"), "cannot open")
yaml_case("region-reversed", mission("region: {x_min: 10, x_max: 0, y_min: -4, y_max: 4}"), "region")
yaml_case("region-inf", mission("region: {x_min: 0, x_max: .inf, y_min: -4, y_max: 4}"), "finite")
yaml_case("region-1e308", mission("region: {x_min: 0, x_max: 1e308, y_min: -4, y_max: 4}"),
          "m.yaml:3: field 'region': the region spans 1e+308 units")
yaml_case("region-mixed", mission("region: {x_min: 0, x_max: 10, lat_min: 1, lat_max: 2}"), "either")
yaml_case("start-outside-region", mission("start: {x: 11, y: 0}"), "m.yaml:4: field 'start': lies outside")
yaml_case("start-missing", MISSION.replace("start: {x: 1, y: 0}\n", ""), "'start': missing")
yaml_case("start-text", mission("start: {x: one, y: 0}"), "start.x")
yaml_case("speed-zero", mission("vehicle: {speed: 0}"), "vehicle.speed")
yaml_case("speed-negative", mission("vehicle: {speed: -0.5}"), "vehicle.speed")
yaml_case("speed-inf", mission("vehicle: {speed: .inf}"), "vehicle.speed")
yaml_case("speed-1e308", mission("vehicle: {speed: 1e308}"), "m.yaml:6: field 'vehicle.speed': 1e+308 crosses")
yaml_case("depth-negative", mission("vehicle: {speed: 0.5, depth: -3}"), "vehicle.depth")
yaml_case("units-zero", mission("units: {length_m: 0, time_s: 1}"), "units.length_m")
yaml_case("projection-pole", mission("projection: {lon0: 0, lat0: 95}"), "projection.lat0")
yaml_case("epoch-bad", mission("epoch: 2026-13-45T00:00:00Z"), "epoch")
yaml_case("iso-without-epoch", mission("departure: {time: 2026-03-15T00:00:00Z}"), "epoch")
yaml_case("departure-huge", mission("departure: {time: 1e17}"), "departure")
yaml_case("departure-window-spacing-tiny",
          mission("departure: {window: {begin: 0, end: 20, spacing: 1e-9}}"), "departure.window.spacing")
yaml_case("departure-window-reversed", mission("departure: {window: {begin: 20, end: 0}}"), "departure.window")
yaml_case("travel-eps-zero", mission("travel_time: {eps: 0}"), "travel_time.eps")
yaml_case("travel-hmax-2", mission("travel_time: {h_max: 2}"), "travel_time")
yaml_case("planner-unknown", mission("planner: {name: dijkstra}"), "unknown planner 'dijkstra'")
yaml_case("planner-sectors-9", mission("planner: {name: zastartve, sectors: 9}"), "planner.sectors")
yaml_case("planner-grid-tiny", mission("planner: {name: zastartve, grid_size: 1e-6}"), "planner.grid_size")
yaml_case("planner-time-limit-huge", mission("planner: {name: zastartve, time_limit: 1e10}"), "planner.time_limit")
yaml_case("planner-zermelo-steps-huge", mission("planner: {name: zastartve, parameters: {zermelo_steps: 1e12}}"),
          "planner.parameters.zermelo_steps")
yaml_case("planner-coarse-factor-huge", mission("planner: {name: zastartve, parameters: {coarse_factor: 100}}"),
          "coarse_factor must be an integer in 0..64")
yaml_case("planner-corridor-blocks-zero", mission("planner: {name: zastartve, parameters: {corridor_blocks: 0}}"),
          "corridor_blocks must be an integer in 1..1000")
yaml_case("wavefront-time-step-negative",
          mission("planner: {name: Wavefront, grid_size: 0.5, parameters: {time_step: -1}}"),
          "planner.parameters.time_step")
yaml_case("wavefront-time-step-tiny", mission("planner: {name: Wavefront, grid_size: 0.5, parameters: {time_step: 1e-9}}"),
          "m.yaml:7: field 'planner.parameters.time_step': 2.081e+12 time intervals")
# constant-bearing stints
yaml_case("stints-planner-without-section", mission("planner: {name: init_optim}"), "m.yaml:7: field 'planner.name'")
yaml_case("stints-duration-zero", mission("stints: {duration: 0, mission_duration: 10}"),
          "m.yaml:8: field 'stints.duration'")
yaml_case("stints-duration-text", mission("stints: {duration: one, mission_duration: 10}"), "stints.duration")
yaml_case("stints-mission-missing", mission("stints: {duration: 1}"), "m.yaml:8: field 'stints.mission_duration'")
yaml_case("stints-mission-negative", mission("stints: {duration: 1, mission_duration: -4}"),
          "stints.mission_duration")
yaml_case("stints-too-many", mission("stints: {duration: 1e-9, mission_duration: 10}"), "stints.mission_duration")
yaml_case("stints-bearing-step-270", mission("stints: {duration: 1, mission_duration: 10, bearing_step: 270}"),
          "m.yaml:8: field 'stints.bearing_step'")
yaml_case("stints-bearing-step-zero", mission("stints: {duration: 1, mission_duration: 10, bearing_step: 0}"),
          "stints.bearing_step")
yaml_case("stints-objective-bad", mission("stints: {duration: 1, mission_duration: 10, objective: fastest}"),
          "stints.objective")
yaml_case("stints-earliest-without-radius",
          mission("stints: {duration: 1, mission_duration: 10, objective: earliest_arrival}"), "stints.radius")
yaml_case("stints-radius-negative", mission("stints: {duration: 1, mission_duration: 10, radius: -1}"),
          "stints.radius")
yaml_case("stints-step-tiny", mission("stints: {duration: 1, mission_duration: 10, step: 1e-9}"), "stints.step")
yaml_case("stints-unknown-field", mission("stints: {duration: 1, mission_duration: 10, heading: 4}"),
          "stints.heading")
yaml_case("stints-not-a-map", mission("stints: 8"), "stints")
yaml_case("stints-window-remaining-distance",
          mission("planner: {name: optim}", "departure: {window: {begin: 0, end: 5}}",
                  "stints: {duration: 1, mission_duration: 10}"), "departure.window")
# level set and isochrones
yaml_case("levelset-resolution-negative", mission("planner: {name: LevelSet, parameters: {resolution: -1}}"),
          "resolution")
yaml_case("levelset-cfl-huge", mission("planner: {name: LevelSet, parameters: {cfl: 9}}"), "cfl")
yaml_case("isochrone-interval-zero", mission(append="outputs: {files: [summary, isochrones], isochrone_interval: 0}\n"),
          "outputs.isochrone_interval")
yaml_case("isochrone-interval-hours-without-unit",
          mission(append="outputs: {files: [summary, isochrones], isochrone_interval: 2 h}\n"),
          "needs the mission's time unit")
yaml_case("levelset-walled-in",
          mission("planner: {name: LevelSet, horizon: 60, parameters: {resolution: 0.1}}",
                  append="forbidden:\n  obstacles:\n    - {name: pocket, points: [[0, -1], [3, -1], [3, 1], [0, 1], "
                  "[0, 0.6], [2.5, 0.6], [2.5, -0.6], [0, -0.6]]}\n"),
          "never reaches the goal", status=1)
# the goto list thinned to the turns
yaml_case("goto-turn-deg-out-of-range", mission(append="outputs: {goto_turn_deg: 200}\n"), "outputs.goto_turn_deg")
yaml_case("goto-wpt-dist-zero", mission(append="outputs: {goto_wpt_dist: 0}\n"), "outputs.goto_wpt_dist")
yaml_case("hold-tolerance-negative", mission(append="outputs: {hold_tolerance: -5}\n"), "outputs.hold_tolerance")
case("cli-hold-tolerance-negative", ["--hold-tolerance=-5", "--out", "{out}"], 2, "--hold-tolerance")
case("cli-hold-tolerance-no-length", ["--hold-tolerance", "3 h", "--out", "{out}"], 2, "--hold-tolerance")
case("cli-goto-turn-negative", ["--goto-turn=-5", "--out", "{out}"], 2, "--goto-turn")
case("cli-isochrone-interval-zero", ["--isochrone-interval", "0", "--out", "{out}"], 2, "--isochrone-interval")
case("cli-isochrone-interval-fortnight", ["--isochrone-interval", "1 fortnight", "--out", "{out}"], 2,
     "--isochrone-interval")
# the probability of reach over an ensemble's members
yaml_case("reachability-unknown-field", mission("reachability: {steps: 3}"),
          "m.yaml:8: unknown field 'reachability.steps'")
yaml_case("reachability-horizon-zero", mission("reachability: {horizon: 0}"),
          "m.yaml:8: field 'reachability.horizon': expected a duration > 0")
yaml_case("reachability-level-one", mission("reachability: {levels: [0.5, 1]}"),
          "m.yaml:8: field 'reachability.levels[1]': expected a number in (0, 1)")
yaml_case("reachability-quantiles-not-a-list", mission("reachability: {quantiles: 0.5}"),
          "m.yaml:8: field 'reachability.quantiles'")
yaml_case("reachability-resolution-negative", mission("reachability: {resolution: -0.1}"),
          "m.yaml:8: field 'reachability.resolution'")
yaml_case("reachability-interval-tiny",
          mission("reachability: {horizon: 10, interval: 0.001, resolution: 0.5}",
                  append="outputs: {files: [summary, reachability]}\n"),
          "field 'reachability.interval': an interval of 0.001 gives")
case("reachability-beyond-memory", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:8: field 'reachability.resolution': the probability of reach over 1 member on",
     {"m.yaml": mission("reachability: {resolution: 0.002}", append="outputs: {files: [summary, reachability]}\n")},
     {"OMPL_GLIDER_MEMORY_LIMIT": "64M"})
# refused before the plan: a sampling planner running for 1000 s first would hit the table's time limit
case("reachability-beyond-memory-before-the-plan", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:8: field 'reachability.resolution': the probability of reach over 1 member on",
     {"m.yaml": mission("reachability: {resolution: 0.002}", "planner: {name: RRTstar, time_limit: 1000}",
                        append="outputs: {files: [summary, reachability]}\n")},
     {"OMPL_GLIDER_MEMORY_LIMIT": "64M"})
# a horizon past the mission's dates: the horizon named, not the epoch
case("reachability-horizon-past-the-dates", ["--mission", "m.yaml", "--reach-horizon", "1e9 h", "--out", "{out}"], 2,
     "--reach-horizon: from the departure, it reaches past the years 0000-9999",
     {"m.yaml": mission("epoch: \"2026-01-01T00:00:00Z\"", append="units: {length_m: 1000, time_s: 3600}\n")})
yaml_case("stay-past-the-dates",
          mission("epoch: \"2026-01-01T00:00:00Z\"",
                  append="units: {length_m: 1000, time_s: 3600}\nwaypoints:\n  - {name: A, x: 5, y: 1, stay: 1e9}\n"),
          "m.yaml:11: field 'waypoints[0].stay': from the departure, it reaches past the years 0000-9999 that the "
          "mission's dates are written in (ISO 8601, from its epoch 2026-01-01T00:00:00Z): 114077.1161 years")
yaml_case("reachability-horizon-beyond-the-limits",
          mission("reachability: {horizon: 1e9}", append="outputs: {files: [summary, reachability]}\n"),
          "m.yaml:8: field 'reachability.horizon': the fronts of 1 member(s)")
case("cli-reach-horizon-zero", ["--reach-horizon", "0", "--out", "{out}"], 2, "--reach-horizon")
case("cli-reach-interval-fortnight", ["--reach-interval", "1 fortnight", "--out", "{out}"], 2, "--reach-interval")
# execution in another ocean, ensembles
yaml_case("execution-unknown-field", mission("execution: {surfacing: 1}"), "m.yaml:8: unknown field 'execution.surfacing'")
yaml_case("execution-strategy-unknown", mission("execution: {strategies: [current_sensitive, zigzag]}"),
          "m.yaml:8: field 'execution.strategies[1]'")
yaml_case("execution-strategy-twice", mission("execution: {strategies: [greedy, greedy]}"), "listed twice")
yaml_case("execution-interval-negative", mission("execution: {surfacing_interval: -1}"),
          "m.yaml:8: field 'execution.surfacing_interval'")
yaml_case("execution-interval-hours-without-unit", mission("execution: {surfacing_interval: 1 h}"),
          "needs the mission's time unit")
yaml_case("execution-interval-fortnight", mission("units: {length_m: 1000, time_s: 3600}",
                                                   "execution: {surfacing_interval: 1 fortnight}"),
          "execution.surfacing_interval")
yaml_case("execution-radius-zero", mission("execution: {radius: 0}"), "execution.radius")
# a radius with its unit needs the mission's length unit (a dimensionless mission has none)
yaml_case("execution-radius-metres-without-units", mission("execution: {radius: 50 m}"),
          "m.yaml:8: field 'execution.radius': '50 m' needs the mission's length unit")
# the mission's strategies measure DAC, the flag's do not: the noise would change nothing, said naming both
case("execution-dac-noise-strategies-flag", ["--mission", "m.yaml", "--strategies", "greedy,replan", "--out", "{out}"],
     2, "--strategies: no strategy listed measures a DAC, yet m.yaml:8: field 'execution.dac_noise' adds noise to them",
     {"m.yaml": mission("execution: {strategies: [dac, greedy], dac_noise: 0.01}")})
yaml_case("execution-dac-noise-without-dac", mission("execution: {strategies: [replan, greedy], dac_noise: 0.01}"),
          "m.yaml:8: field 'execution.dac_noise': no strategy measures a DAC")
# runs that once never ended (the last dive a rounding short of the run's end: fixes without end): each ends at its
# end with the reason, the goal not reached
RUNAWAY = """units: {length_m: 1000, time_s: 3600}
current: {type: uniform, parameters: {u: 0.1, v: 0}}
region: {x_min: 0, x_max: 14, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 12, y: 0}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
outputs: {files: [summary]}
"""
yaml_case("execution-truth-against-ends", RUNAWAY + "execution: {truth: {type: uniform, parameters: {u: -0.3, v: 0}}, "
          "surfacing_interval: 15 min, strategies: [greedy, current_blind], radius: 0.2}\n",
          "greedy: the goal not reached: not within 200 m of it by t = 36.6667, when the run ended (twice the planned "
          "trip)", status=0)
yaml_case("execution-duration-shorter-than-trip-ends", RUNAWAY + "execution: {surfacing_interval: 15 min, strategies: "
          "[current_sensitive, current_blind, greedy, dac, replan, replan_observed], radius: 0.2, duration: 5 h}\n",
          "replan_observed: the goal not reached: not within 200 m of it by t = 5, when the run ended "
          "(execution.duration)", status=0)
yaml_case("via-empty-list", mission(append="waypoints: []\n"),
          "m.yaml:8: field 'waypoints': the list is empty: give at least one via point, or leave 'waypoints' out")
yaml_case("via-named-goal-upper", mission(append="waypoints:\n  - {name: GOAL, x: 5, y: 1}\n"),
          "field 'waypoints[0].name': 'GOAL' names the mission's goal too")
yaml_case("via-names-differ-in-case", mission(append="waypoints:\n  - {name: A, x: 5, y: 1}\n  - {name: a, x: 6, y: 1}\n"),
          "field 'waypoints[1].name': 'a' names another via point too")
yaml_case("execution-replan-every-zero", mission("execution: {replan_every: 0}"), "execution.replan_every")
yaml_case("execution-truth-netcdf-for-analytic", mission("execution: {truth: {type: netcdf, file: f.nc}}"),
          "execution.truth")
yaml_case("execution-truth-word", mission("execution: {truth: nowcast}"), "field 'execution.truth'")
yaml_case("execution-truth-parameter", mission("execution: {truth: {type: uniform, parameters: {w: 1}}}"),
          "execution.truth.parameters.w")
yaml_case("execution-batch-negative", mission("execution: {batch: {pairs: -3}}"), "execution.batch.pairs")
yaml_case("execution-batch-min-distance-huge",
          mission("execution: {batch: {pairs: 3, min_distance: 100}}"), "execution.batch")
case("ensemble-members-without-common-time", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:1: field 'current.ensemble': the members hold currents at no common time ([0] 'e1.nc' from "
     "2026-03-15T00:00:00Z to 2026-03-17T00:00:00Z, [1] 'e2.nc' from 2026-03-20T00:00:00Z to 2026-03-22T00:00:00Z)",
     {"e1.cdl": forecast(), "e2.cdl": forecast(replace=[("2026-03-15 00:00:00", "2026-03-20 00:00:00")]),
      "m.yaml": "current: {ensemble: [{type: netcdf, file: e1.nc}, {type: netcdf, file: e2.nc}]}\n"
                "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
yaml_case("ensemble-one-member", mission("current: {ensemble: [{type: uniform}]}"), "field 'current.ensemble'")
yaml_case("ensemble-mixed", mission("current: {ensemble: [{type: uniform}, {type: netcdf, file: f.nc}]}"),
          "current.ensemble[1]")
yaml_case("ensemble-with-type", mission("current: {type: uniform, ensemble: [{type: uniform}, {type: uniform}]}"),
          "current")
yaml_case("objective-without-ensemble", mission("planner: {name: zastartve, objective: worst}"),
          "needs an ensemble current")
yaml_case("objective-quantile-range",
          mission("current: {ensemble: [{type: uniform, parameters: {u: 0.1}}, {type: uniform}]}",
                  "planner: {objective: quantile, quantile: 1.5}"), "planner.quantile")
NC_MISSION = """name: nc
current: {type: netcdf, file: f.nc}
start: {lon: -52.9, lat: 47.1}
goal: {lon: -52.1, lat: 47.9}
vehicle: {speed: 0.5}
"""
case("execution-truth-file-missing", ["--mission", "m.yaml", "--out", "{out}"], 2, "execution.truth.file",
     {"f.cdl": forecast(), "m.yaml": NC_MISSION + "execution: {truth: {type: netcdf, file: missing.nc}}\n"})
case("execution-truth-other-calendar", ["--mission", "m.yaml", "--out", "{out}"], 2, "calendar",
     {"f.cdl": forecast(), "t.cdl": forecast(replace=[('time:standard_name = "time" ;',
                                                       'time:standard_name = "time" ; time:calendar = "noleap" ;')]),
      "m.yaml": NC_MISSION + "execution: {truth: {type: netcdf, file: t.nc}}\n"})
case("execution-truth-undated", ["--mission", "m.yaml", "--out", "{out}"], 2, "execution.truth.time_units",
     {"f.cdl": forecast(), "t.cdl": forecast(replace=[('"hours since 2026-03-15 00:00:00"', '"hours"')]),
      "m.yaml": NC_MISSION + "execution: {truth: {type: netcdf, file: t.nc}}\n"})
case("cli-truth-parameter", ["--truth", "Q=1", "--out", "{out}"], 2, "--truth")
case("cli-truth-not-a-number", ["--truth", "B0=big", "--out", "{out}"], 2, "--truth")
case("cli-strategies-unknown", ["--strategies", "current_sensitive,zigzag", "--out", "{out}"], 2, "--strategies")
case("cli-surfacing-fortnight", ["--surfacing-interval", "1 fortnight", "--out", "{out}"], 2,
     "--surfacing-interval")
nc_case("cli-truth-file-missing", forecast(), "--truth: NetCDF file 'nothere.nc'", extra=("--truth", "nothere.nc"))
case("cli-radius-zero", ["--radius", "0", "--out", "{out}"], 2, "--radius")
case("cli-truth-with-mission-unknown-parameter", ["--mission", "m.yaml", "--truth", "w=1", "--out", "{out}"], 2,
     "--truth: expected 'forecast' or NAME=VALUE,... with the uniform's parameters (u, v), got 'w=1'",
     {"m.yaml": MISSION})
case("cli-start-over-mission-one-number", ["--mission", "m.yaml", "--start", "1", "--out", "{out}"], 2,
     "--start expects two numbers", {"m.yaml": MISSION})
case("cli-departure-over-mission-text", ["--mission", "m.yaml", "--departure", "noon", "--out", "{out}"], 2,
     "--departure: ", {"m.yaml": MISSION})
case("cli-start-over-mission-outside", ["--mission", "m.yaml", "--start", "20,0", "--out", "{out}"], 2,
     "--start", {"m.yaml": MISSION})
# work estimates before work: refused with the estimate and the limit (no hang)
yaml_case("levelset-cfl-tiny", mission("planner: {name: LevelSet, parameters: {cfl: 1e-6}}"),
          "m.yaml:7: field 'planner.parameters.cfl': planner LevelSet accepts cfl in 0.1 .. 8")
yaml_case("levelset-threads-huge", mission("planner: {name: LevelSet, parameters: {threads: 100000}}"),
          "field 'planner.parameters.threads': planner LevelSet accepts threads in 0 .. 64")
yaml_case("levelset-resolution-fine", mission("planner: {name: LevelSet, parameters: {resolution: 0.001}}"),
          "m.yaml:7: field 'planner.parameters.resolution': the level set would take up to 8.32e+05 time steps")
yaml_case("levelset-walled-in-long-horizon",
          mission("planner: {name: LevelSet, horizon: 1000000}",
                  append="forbidden:\n  obstacles:\n    - {name: pocket, points: [[0, -1], [3, -1], [3, 1], [0, 1], "
                  "[0, 0.6], [2.5, 0.6], [2.5, -0.6], [0, -0.6]]}\n"),
          "field 'planner.horizon': the level set would take up to 8e+06 time steps")
yaml_case("stints-bearing-step-tenth",
          mission("planner: {name: CTS-A*}", "stints: {duration: 1, mission_duration: 30, bearing_step: 0.1}"),
          "m.yaml:8: field 'stints.bearing_step': a bearing step of 0.1 degrees flies 3600 stints")
yaml_case("stints-bearing-step-micro",
          mission("planner: {name: init_optim}", "stints: {duration: 1, mission_duration: 30, bearing_step: 1e-6}"),
          "more than the limit of 360 bearings")
yaml_case("wavefront-fine-grid", mission("planner: {name: Wavefront, grid_size: 0.01, sectors: 5}"),
          "m.yaml:7: field 'planner.grid_size': the Wavefront search settles 8.02e+05 lattice vertices")
yaml_case("execution-surfacing-tiny", mission("execution: {surfacing_interval: 1e-7}"),
          "m.yaml:8: field 'execution.surfacing_interval': a surfacing interval of 1e-07 gives up to")
case("cli-surfacing-tiny", ["--surfacing-interval", "1e-7", "--out", "{out}"], 2,
     "--surfacing-interval: a surfacing interval of 1e-07 gives up to 2.28e+08 surfacings per flight")
case("cli-isochrone-interval-tiny", ["--isochrone-interval", "0.01", "--out", "{out}"], 2,
     "--isochrone-interval: an interval of 0.01 gives 1139 isochrones over the 11.4 the plan takes")
# an ensemble member that no candidate can cross: not robust, exit 1 with the member named
# a member impassable, the other not: the route most likely to arrive, with its share (never "no path" while a
# member arrives); none passable: no path, that reason first
yaml_case("ensemble-worst-member-impassable",
          mission("current: {ensemble: [{type: uniform, parameters: {u: 0.1}}, {type: uniform, parameters: {u: -0.6}}]}",
                  "planner: {name: zastartve, grid_size: 0.5, objective: worst}"),
          "Ensemble:           arrives in 1 of 2 members, p = 0.50", status=0)
yaml_case("ensemble-no-member-reached",
          mission("current: {ensemble: [{type: uniform, parameters: {u: -0.7}}, {type: uniform, parameters: {u: -0.6}}]}",
                  "planner: {name: zastartve, grid_size: 0.5, objective: worst}"),
          "Reason:             no member of the ensemble is reached", status=1)
# a truth that ends before the plan arrives: refused, never extrapolated
case("execution-truth-ends-early", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "field 'execution.truth': the truth ends at t = 7200",
     {"f.cdl": forecast(), "t.cdl": forecast(replace=[("time = 0, 24, 48 ;", "time = 0, 1, 2 ;")]),
      "m.yaml": NC_MISSION.replace("speed: 0.5", "speed: 1.0") + "execution: {truth: {type: netcdf, file: t.nc}}\n"})
yaml_case("planner-refiner-evals-huge",
          mission("planner: {name: zastartve, parameters: {refiner_max_evaluations: 5e9}}"),
          "planner.parameters.refiner_max_evaluations")
yaml_case("planner-bool-maybe", mission("planner: {name: zastartve, parameters: {heuristic: maybe}}"),
          "true or false")
yaml_case("planner-horizon-negative", mission("planner: {name: zastartve, horizon: -1}"), "planner.horizon")
yaml_case("outputs-prefix-escapes", mission("outputs: {prefix: ../../x}"), "outputs.prefix")
yaml_case("outputs-unknown-format", mission("outputs: {files: [pdf]}"), "outputs.files")
case("outputs-dir-is-file", ["--mission", "m.yaml"], 2, "afile", {"m.yaml": mission("outputs: {directory: afile}")})
case("outputs-dir-dangling-link", ["--mission", "m.yaml", "--out", "gone"], 2,
     "output directory 'gone' is a symbolic link to 'no/such/place', which does not exist",
     {"m.yaml": MISSION, "gone": ("symlink", "no/such/place")})
case("outputs-directory-where-a-file-goes", ["--mission", "m.yaml", "--out", "o2"], 2,
     "output directory 'o2' holds a directory 'summary.json' where glider_plan writes a file; nothing was replaced",
     {"m.yaml": MISSION, "o2/summary.json/keep": "a pilot's file\n"})
yaml_case("speeds-empty", mission("speeds: []"), "speeds")
yaml_case("speeds-text", mission("speeds: [0.3, abc]"), "speeds[1]")
yaml_case("forbidden-bowtie",
          mission(append="forbidden:\n  obstacles:\n    - {name: bow, points: [[4, -1], [6, 1], [6, -1], [4, 1]]}\n"),
          "forbidden region 'bow': an invalid polygon: Self-intersection at or near point 5 0 (x y as given)")
yaml_case("forbidden-two-points",
          mission(append="forbidden:\n  obstacles:\n    - {name: line, points: [[4, -1], [6, 1]]}\n"),
          "at least 3 points")
yaml_case("start-in-polygon",
          mission(append="forbidden:\n  obstacles:\n    - {name: rock, points: [[0.5, -0.5], [1.5, -0.5], [1.5, 0.5], "
                         "[0.5, 0.5]]}\n"), "rock")
yaml_case("goal-in-polygon",
          mission(append="forbidden:\n  obstacles:\n    - {name: reef, points: [[8.5, -0.5], [9.5, -0.5], [9.5, 0.5], "
                         "[8.5, 0.5]]}\n"), "reef")
yaml_case("geojson-missing", mission(append="forbidden: {geojson: nope.geojson}\n"), "nope.geojson")
case("geojson-not-collection", ["--mission", "m.yaml", "--out", "{out}"], 2, "FeatureCollection",
     {"m.yaml": mission(append="forbidden: {geojson: r.geojson}\n"), "r.geojson": '{"type": "Feature"}'})

# --- NetCDF forecasts -------------------------------------------------------------------------------------------
nc_case("nc-zero-length-lat", ("nc4", forecast(replace=[("lat = 6 ;", "lat = UNLIMITED ;"),
                                                        ("lat = " + LAT + " ;", ""),
                                                        ("u = " + ", ".join(["0.1"] * 108) + " ;", ""),
                                                        ("v = " + ", ".join(["0"] * 108) + " ;", "")])), "lat")
nc_case("nc-no-time-records", forecast(replace=[("time = 0, 24, 48 ;", ""),
                                                ("u = " + ", ".join(["0.1"] * 108) + " ;", ""),
                                                ("v = " + ", ".join(["0"] * 108) + " ;", "")]), "time")
nc_case("nc-lon-not-monotonic", forecast(lon="-53.0, -52.8, -52.2, -52.4, -52.6, -52.0"), "lon")
nc_case("nc-lat-not-monotonic", forecast(lat="47.0, 47.2, 47.4, 47.4, 47.8, 48.0"), "lat")
nc_case("nc-lat-nan", forecast(lat="47.0, 47.2, NaN, 47.6, 47.8, 48.0"), "lat")
# (furlongs per fortnight would be a velocity: UDUNITS-2 converts it)
nc_case("nc-units-unknown", forecast(replace=[('u:units = "m s-1"', 'u:units = "furlongs per blink"')]),
        "furlongs per blink")
nc_case("nc-units-not-velocity", forecast(replace=[('u:units = "m s-1"', 'u:units = "degC"')]),
        "variable 'u': units 'degC' are not a velocity")
nc_case("nc-time-units-bad", forecast(replace=[('"hours since 2026-03-15 00:00:00"', '"hours since whenever"')]),
        "time")
nc_case("nc-time-not-monotonic", forecast(replace=[("time = 0, 24, 48 ;", "time = 0, 48, 24 ;")]), "time")
nc_case("nc-u-v-shapes", forecast(replace=[("float v(time, lat, lon)", "float v(time, lon)"),
                                           ("v = " + ", ".join(["0"] * 108) + " ;", "")]), "v")
nc_case("nc-truncated", ("truncate", forecast()), "truncated")
nc_case("nc-u-var-missing", forecast(), "speed_u", extra=("--u-var", "speed_u"))
nc_case("nc-start-on-land", forecast(u=", ".join(["-999"] * 2 + ["0.1"] * 106)), "land",
        args=("--start=-53.0,47.0", GOAL))
nc_case("nc-start-on-land-nearest-water", forecast(u=", ".join(["-999"] * 2 + ["0.1"] * 106)),
        "the nearest water is -52.", args=("--start=-53.0,47.0", GOAL))
nc_case("nc-start-outside", forecast(), "outside", args=("--start=-60,47.1", GOAL))
nc_case("nc-goal-outside-extent", forecast(), "--goal -40,47.9 (lon,lat) lies outside the grid of 'f.nc' (lon -53..-52, lat 47..48)",
        args=(START, "--goal=-40,47.9"))
# a rotated curvilinear grid, left-handed (eta clockwise of xi), u/v without angle or standard_name: ambiguous
nc_case("nc-grid-angle-ambiguous", """netcdf roms {
dimensions: ocean_time = 1 ; eta_rho = 3 ; xi_rho = 3 ;
variables:
  double ocean_time(ocean_time) ; ocean_time:units = "seconds since 2026-04-01" ;
  double lon_rho(eta_rho, xi_rho) ; lon_rho:units = "degree_east" ;
  double lat_rho(eta_rho, xi_rho) ; lat_rho:units = "degree_north" ;
  float u(ocean_time, eta_rho, xi_rho) ; u:units = "m s-1" ;
  float v(ocean_time, eta_rho, xi_rho) ; v:units = "m s-1" ;
data:
  ocean_time = 0 ;
  lon_rho = LONS ;
  lat_rho = LATS ;
  u = 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1 ;
  v = 0, 0, 0, 0, 0, 0, 0, 0, 0 ;
}
""".replace("LONS", "-52.5000, -52.3718, -52.2436, -52.4260, -52.2978, -52.1696, -52.3520, -52.2238, -52.0956").replace("LATS", "47.5000, 47.5500, 47.6000, 47.4134, 47.4634, 47.5134, 47.3268, 47.3768, 47.4268"),
        "gives no clear angle", args=("--start=-52.4,47.5", "--goal=-52.3,47.45"))
nc_case("nc-departure-after-forecast", forecast(), "departure", extra=("--departure", "2026-04-01T00:00:00Z"))
nc_case("nc-departure-garbage", forecast(), "departure", extra=("--departure", "yesterday"))
nc_case("nc-lat-all-fill", ("nc4", """netcdf huge {
dimensions: lat = 1000 ; lon = 1000 ; time = 1 ;
variables:
  double time(time) ; time:units = "hours since 2026-03-15" ;
  double lat(lat) ; lat:units = "degrees_north" ;
  double lon(lon) ; lon:units = "degrees_east" ;
  float u(time, lat, lon) ; u:units = "m s-1" ; u:standard_name = "eastward_sea_water_velocity" ;
  float v(time, lat, lon) ; v:units = "m s-1" ; v:standard_name = "northward_sea_water_velocity" ;
data: time = 0 ;
}
"""), "lat")
# 100000 x 100000 nodes 1e-5 degrees apart: the trip's subset alone would need about 100 GB
AXIS = 100000
nc_case("nc-huge-grid", ("nc4", """netcdf huge {
dimensions: lat = %d ; lon = %d ; time = 1 ;
variables:
  double time(time) ; time:units = "hours since 2026-03-15" ;
  double lat(lat) ; lat:units = "degrees_north" ;
  double lon(lon) ; lon:units = "degrees_east" ;
  float u(time, lat, lon) ; u:units = "m s-1" ; u:standard_name = "eastward_sea_water_velocity" ;
  float v(time, lat, lon) ; v:units = "m s-1" ; v:standard_name = "northward_sea_water_velocity" ;
data: time = 0 ;
  lat = %s ;
  lon = %s ;
}
""" % (AXIS, AXIS, ", ".join("%.5f" % (47 + 1e-5 * i) for i in range(AXIS)),
       ", ".join("%.5f" % (-53 + 1e-5 * i) for i in range(AXIS)))), "memory")
CARTESIAN = """netcdf cart {
dimensions: time = UNLIMITED ; y = 4 ; x = 5 ;
variables:
  double time(time) ; time:units = "seconds" ;
  double y(y) ; y:units = "m" ; double x(x) ; x:units = "m" ;
  float u(time, y, x) ; u:units = "m s-1" ; float v(time, y, x) ; v:units = "m s-1" ;
data: y = 0, 10000, 20000, 30000 ; x = 0, 10000, 20000, 30000, 40000 ;
}
"""
# the NetCDF flags : units (checked with UDUNITS-2 before the file is read), the time record, the time units
nc_case("flag-velocity-units-unparseable", forecast(), "--velocity-units: units 'parsecs per thingy' not understood",
        extra=("--velocity-units", "parsecs per thingy"))
nc_case("flag-velocity-units-not-velocity", forecast(), "--velocity-units: units 'degC' are not a velocity",
        extra=("--velocity-units", "degC"))
nc_case("flag-velocity-units-length", forecast(), "are not a velocity", extra=("--velocity-units", "m"))
nc_case("flag-steady-record-out-of-range", forecast(), "--steady-record 3 is out of range: time variable 'time' has 3",
        extra=("--steady-record", "3"))
nc_case("flag-steady-record-negative", forecast(), "--steady-record", extra=("--steady-record", "-1"))
nc_case("flag-steady-record-text", forecast(), "--steady-record", extra=("--steady-record", "first"))
nc_case("flag-angle-var-missing", forecast(), "no grid angle variable 'theta'", extra=("--angle-var", "theta"))
nc_case("flag-angle-var-not-on-grid", forecast(), "grid angle variable 'time' (--angle-var) is not on the grid",
        extra=("--angle-var", "time"))
nc_case("flag-time-units-without-since", forecast(), "--time-units", extra=("--time-units", "hours"))
nc_case("flag-time-units-bad-date", forecast(), "--time-units 'days since the flood'",
        extra=("--time-units", "days since the flood"))
nc_case("nc-time-units-month", forecast(replace=[('"hours since 2026-03-15 00:00:00"', '"month"')]), "--time-units")
nc_case("nc-time-units-month-names-steady-record", forecast(replace=[('"hours since 2026-03-15 00:00:00"', '"month"')]),
        "--steady-record")
nc_case("nc-no-velocity-candidates", forecast(replace=[("float u(", "float speed_east("), ("u:", "speed_east:"),
                                                       ("  u = ", "  speed_east = "),
                                                       ('"eastward_sea_water_velocity"', '"sea_water_speed"')]),
        "candidates: speed_east(time,lat,lon) [m s-1], v(time,lat,lon) [m s-1]; name them with --u-var/--v-var")
case("yaml-velocity-units-not-velocity", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:1: field 'current.velocity_units': units 'degC' are not a velocity",
     {"f.cdl": forecast(), "m.yaml": "current: {type: netcdf, file: f.nc, velocity_units: degC}\n"
                                     "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
case("yaml-steady-record-out-of-range", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:1: field 'current.steady_record'",
     {"f.cdl": forecast(), "m.yaml": "current: {type: netcdf, file: f.nc, steady_record: 7}\n"
                                     "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
case("yaml-time-units-without-since", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:1: field 'current.time_units'",
     {"f.cdl": forecast(), "m.yaml": "current: {type: netcdf, file: f.nc, time_units: days}\n"
                                     "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
case("yaml-velocity-units-analytic", ["--mission", "m.yaml", "--out", "{out}"], 2, "only for type gridded",
     {"m.yaml": mission("current: {type: uniform, velocity_units: knots}")})
nc_case("nc-cartesian-no-time-records", CARTESIAN, "time", args=("--start", "5000,5000", "--goal", "35000,25000"))
case("mission-netcdf-departure-after-end", ["--mission", "m.yaml", "--out", "{out}"], 2, "departure",
     {"f.cdl": forecast(), "m.yaml": "current: {type: netcdf, file: f.nc}\nstart: {lon: -52.9, lat: 47.1}\n"
                                     "goal: {lon: -52.1, lat: 47.9}\nvehicle: {speed: 0.3}\n"
                                     "departure: {time: 2026-04-01T00:00:00Z}\n"})
# a forecast in several files (--currents LIST or glob, current.file list or glob): the files must be dated, on one
# grid and calendar, without a gap in the trip; a pattern must match
LATER = '"hours since 2026-03-17 00:00:00"'
case("currents-glob-no-match", ["--currents", "f.nc,hycom_*.nc", START, GOAL, "--out", "{out}"], 2,
     "no file matches the pattern 'hycom_*.nc'", {"f.cdl": forecast()})
case("currents-glob-in-directory", ["--currents", "*/f.nc", START, GOAL, "--out", "{out}"], 2,
     "the pattern '*/f.nc' has wildcards in its directory", {"f.cdl": forecast()})
case("currents-list-empty-item", ["--currents", "f.nc,,f.nc", START, GOAL, "--out", "{out}"], 2,
     "forecast files: an empty name in the list", {"f.cdl": forecast()})
case("currents-list-same-file-twice", ["--currents", "f.nc,f.nc", START, GOAL, "--out", "{out}"], 2,
     "'f.nc' and 'f.nc' cannot be joined as one forecast: both begin at 2026-03-15T00:00:00Z", {"f.cdl": forecast()})
case("currents-list-grids-differ", ["--currents", "f.nc,g.nc", START, GOAL, "--out", "{out}"], 2,
     "NetCDF files 'f.nc' and 'g.nc' cannot be joined as one forecast: their grids in the trip's region differ",
     {"f.cdl": forecast(), "g.cdl": forecast(lat="47.0, 47.25, 47.4, 47.6, 47.8, 48.0",
                                             replace=[('"hours since 2026-03-15 00:00:00"', LATER)])})
case("currents-list-undated", ["--currents", "f.nc,g.nc", START, GOAL, "--out", "{out}"], 2,
     "NetCDF file 'g.nc': time variable 'time': units 'hours' have no date",
     {"f.cdl": forecast(), "g.cdl": forecast(replace=[('"hours since 2026-03-15 00:00:00"', '"hours"')])})
case("currents-list-calendars-differ", ["--currents", "g.nc,f.nc", START, GOAL, "--out", "{out}"], 2,
     "NetCDF files 'g.nc' and 'f.nc' cannot be joined as one forecast: their calendars differ ('360_day' and 'standard'",
     {"f.cdl": forecast(), "g.cdl": forecast(replace=[('"hours since 2026-03-15 00:00:00"',
                                                       LATER + ' ; time:calendar = "360_day"')])})
case("currents-list-gap", ["--currents", "f.nc,g.nc", START, GOAL, "--out", "{out}"], 2,
     "NetCDF files 'f.nc' and 'g.nc': a gap of 72 h in the forecast within the trip's time window",
     {"f.cdl": forecast(),
      "g.cdl": forecast(replace=[('"hours since 2026-03-15 00:00:00"', '"hours since 2026-03-20 00:00:00"')])})
case("yaml-file-glob-no-match", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:1: field 'current.file': forecast files: no file matches the pattern",
     {"f.cdl": forecast(), "m.yaml": "current: {type: netcdf, file: \"x_*.nc\"}\n"
                                     "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
case("yaml-file-list-empty", ["--mission", "m.yaml", "--out", "{out}"], 2, "m.yaml:1: field 'current.file'",
     {"f.cdl": forecast(), "m.yaml": "current: {type: netcdf, file: []}\n"
                                     "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
# A corrupt classic header found by fuzz_netcdf: an attribute declaring more values than the file holds made
# NetCDF-C allocate gigabytes inside nc_open; the header is now checked before NetCDF-C opens the file.
CORRUPT_HEADER = base64.b64decode(
    "Q0RGAQAAAAIAAAAKAAAAAwAAAAR0aW1lAAAAAAAAAANsYXQAAAAABAAAAANsb24AAAAABAAAAAAAAAAAAAAACwAAAAUAAAAEdGlt"
    "ZQAAAAEAAAAAAAAADAAAAAIAAAAFdW5pdHMAAAAAAAACAAAAH2hvdXJzIHNpbmNlIDIwMjYtMDMtMTUgMDA6MDA6MDAAAAAADXN0"
    "YW5kYXJkX25hbWUAAAAAAAACAAAABHRpbWUAAAAGAAAACAAAAwwAAAADbGF0AAAAAAEAAAABAAAADAAAAAIAAAAFdW5pdHMAAAAA"
    "AAACAAAADWRlZ3JlZXNfbm9ydGgAAAAAAAANc3RhbmRhcmRfbmFtZQAAAAAAAAIAAAAIbGF0aXR1ZGUAAAAGAAAAIAAAAswAAAAD"
    "bG9uAAAAAAEAAAACAAAADAAAANcAAAAFdW5pdHMAAAAAAAACAAAADGRlZ3JlZXNfZWFzdAAAAA1zdGFuZGFyZF9uYW1lAAAAAAAA"
    "AgAAAAlsb25naXR1ZGUAAAAAAAAGAAAAIAAAAuwAAAABdQAAAAAAAAMAAAAAAAAAAQAAAAIAAAAMAAAAAwAAAAV1bml0cwAAAAAA"
    "AAIAAAAFbSBzLTEAAAAAAAANc3RhbmRhcmRfbmFtZQAAAAAAAAIAAAAbZWFzdHdhcmRfc2VhX3dhdGVyX3ZlbG9jaXR5AAAAAApf"
    "RmlsbFZhbHVlAAAAAAAFAAAAAcR5wAAAAAAFAAAAQAAAAxQAAAABdgAAAAAAAAMAAAAAAAAAAQAAAAIAAAAMAAAAAwAAAAV1bml0"
    "cwAAAAAAAAIAAAAFbSBzLTEAAAAAAAANc3RhbmRhcmRfbmFtZQAAAAAAAAIAAAAcbm9ydGh3YXJkX3NlYV93YXRlcl92ZWxvY2l0"
    "eQAAAApfRmlsbFZhbHVlAAAAAAAFAAAAAcR5wAAAAAAFAAAAQAAAA1RAR4AAAAAAAEBHwAAAAAAAQEgAAAAAAABASEAAAAAAAMBK"
    "gAAAAAAAwEpAAAAAAADASgAAAAAAAMBJwAAAAAAAAAAAAAAAAADEecAAPczMzT3MzM09zMzNPczMzT5MzM0+TMzNPczMzT3MzM0+"
    "TMzNPkzMzT3MzM09zMzNPczMzT3MzM09zMzNxHnAAAAAAAAAAAAAAAAAAAAAAAA9TMzNPUzMzQAAAAAAAAAAPUzMzT1MzM0AAAAA"
    "AAAAAAAAAAAAAAAAAAAAAEA4AAAAAAAAxHnAAD3MzM09zMzNPczMzT3MzM0+mZmaPpmZmj3MzM09zMy6PpmZmj6ZmZo9zMzNPczM"
    "zT3MzM09zMzNPczMzcR5wAAAAAAAAAAAAAAAAAAAAAAAvUzMzb1MzM0AAAAAAAAAAL1MzM29TMzNAAAAAAAAAAAAAAAAAAAAAAAA"
    "AAA=")
case("nc-corrupt-header-oom", ["--currents", "f.nc", START, GOAL, "--out", "{out}"], 2, "truncated or corrupt",
     {"f.nc": ("bytes", CORRUPT_HEADER)})
# found by fuzz_netcdf: a classic header whose attribute-list tag is broken made NetCDF-C divide by zero (SIGFPE)
BROKEN_TAG_HEADER = base64.b64decode(
    "Q0RGAQAAAAIAAAAKAAAAAwAAAAR0aW1lAAAAAAAAAANsYXQAAAAABAAAAANsb24AAAAABAAAAAAAAAAAAAAACwAAAAUAAAAEdGlt"
    "ZQAAAAEAAAAAAAAADAAAAAIAAAAFdW5pdHMAAAAAAAACAAAAH2hvdXJzIHNpbmNlIDIwMjYtMDMtMTUgMDA6MDA6MDAAAAAADXN0"
    "YW5kYXJkX25hbWUAAAAAAAACAAAABHRpbWUAAAAGAAAACAAAAwwAAAADbGF0AAAAAAEAAAABAAAADAAAAAIAAAAFdW5pdHMAAAAA"
    "AAACAAAADWRlZ3JlZXNfbm9ydGgAAAAAAAANc3RhbmRhcmRfbmFtZQAAAAAAAAIAAAAIbGF0aXR1ZGUAAAAGAAAAIAAAAswAAAAD"
    "bG9uAAAAAAEAAAACAAAADAAAAAIAAAAFdW5pdHMAAAAAAAACAAAADGRlZ3JlZXNfZWFzdAAAAA1zdGFuZGFyZF9uYW1lAAAAAAAA"
    "AgAAAAlsb25naXR1ZGUAAAAAAAAGAAAAIAAAAuwAAAABdQAAAAAAAAMAAAAAAAAAAQAAAAIAAAAMAAAAAwAAAAV1bml0cwAAAAAA"
    "AAIAAAAFbSBzLTEAAAAAAAANc3RhbmRhcmRfbmFtZQAAAAAAAAIAAAAbZWFzdHdhcmRfc2VhX3dhdGVyX3ZlbG9jaXR5AAAAAApf"
    "RmlsbFZhbHVlAAAAAAAFAAAAAcR5wAAAAAAFAAAAQAAAAxQAAAABdgAAAAAAAAMAAAAAAAAAAQAAAAIAAAoAAAAAAAAAAAwAAAAD"
    "AAAABXVuaXRzAAAAAAAAAgAAAAVtIHMtMQAAAAAAAA1zdGFuZGFyZF9uYW1lAAAAAAAAAgAAABxub3J0aHdhcmRfc2VhX3dhdGVy"
    "X3ZlbG9jaXR5AAAACl9GaWxsVmFsdWUAAAAAAAUAAAABxHnAAAAAAAUAAABAAAADVEBHgAAAAAAAQEfAAAAAAABASAAAAAAAAEBI"
    "QAAAAAAAwEqAAAAAAADASkAAAAAAAMBKAAAAAAAAwEnAAAAAAAAAAAAAAAAAAMR5wAA9zMzNPczMzT3MzM09zMzNPkzMzT5MzM09"
    "zMzNPczMzT5MzM0+TMzNPczMzT3MzM09zMzNPczMzT3MzM3EecAAAAAAAAAAAAAAAAAAAAAAAD1MzM09TMzNAAAAAAAAAAA9TMzN"
    "PUzMzQAAAAAAAAAAAAAAAAAAAAAAAAAAQDgAAAAAAADEecAAPczMzT3MzM09zMzNPczMzT6ZmZo+mZmaPczMzT3MzM0+mZmaPpmZ"
    "mj3MzM09zMzNPczMzT3MzM09zMzNxHnAAAAAAAAAAAAAAAAAAAAAAAC9TMzNvUzMzQAAAAAAAAAAvUzMzb1MzM0AAAAAAAAAAAAA"
    "AAAAAAAAAAAAAA==")
case("nc-broken-header-sigfpe", ["--currents", "f.nc", START, GOAL, "--out", "{out}"], 2, "is corrupt",
     {"f.nc": ("bytes", BROKEN_TAG_HEADER)})
# found by fuzz_netcdf: NC_STRING as a variable type in a CDF-1 header makes NetCDF-C divide by zero in nc_open
STRING_IN_CDF1_HEADER = base64.b64decode(
    "Q0RGAQAAAAAAAAAKAAAABAAAAAR0aW0lAAAAAgAAAAF6AAAAAAAAAgAAAAF5AAAAAAAAAwAAAAF4AAAAAAAABAAAAAAAAAAAAAAA"
    "CwAAAAYAAAAEdGltZQAAAAEAAAAAAAAADAAAAAEAAAAFdW5pdHMAAAAAAAACAAAAB3NlY29uZHMAAAAABgAAABAAAAH0AAAAAXoA"
    "AAAAAAABAAAAAQAAAAwAAAACAAAABXVuaXRzAAAAAAAAAgAAAAFtAAAAAAAACHBvc2l0aXZlAAAAAgAAAAJ1cAAAAAAADAAAABAA"
    "AAIEAAAAAXkAAAAAAAABAAAAAgAAAAwAAAABAAAABXVuaXRzAAAAAAAAAgAAAAJrbQAAAAAABgAAABgAAAIUAAAAAXgAAAAAAAAB"
    "AAAAAwAAAAwAAAABAAAABXVuaXRzAAAAAAAAAgAAAAJrbQAAAAAABgAAACAAAAIsAAAAAXUAAAAAAAAEAAAAAAAAAAEAAAACAAAA"
    "AAAAAAwAAAABAAAABXVuaXRzAAAAAAAAAgAAAAZjbSBzLTIAAAAAAAUAAADAAAACTAAAAAF2AAAAAAAABAAAAAAAAAABAAAAAgAA"
    "AAMAAAAMAAAAAQAAAAV1bml0cwAAAAAAAAIAAAAGY20gcy0xAAAAAAAFAAAAwAAAAwwAAAAAAAAAAECsIAAAAAAAwCQAAAAAAAAA"
    "AAAAAAAAAAAAAAAAAAAAQBQAAAAAAABAJAAAAAAAAAAAAAAAAAAAQBQAAAAAAABAJAAAAAAAAEAuAAAAAAAAQSAAAEEgAAD/////"
    "//////////////////////////////////////////////////////////////////9BIAAAQSAAAEEgAABBIAAAQSAAAEEgAABB"
    "IAAAQSAAAEEgAABBIAAAQaAAAEGgAABBoAAAQaAAAEGgAABBoAAAQaAAAEGgAABBoAAAQaAAAEGgAABBoAAAQSAAAEEgAABBIAAA"
    "QSAAAEEgAABBIAAAQSAAAEEgAABBIAAAQSAAAEEgAABBIAAAQaAAAEGgAABBoAAAQaAAAEGgAABBoAAAQaAAAEGgAABBoAAAQaAA"
    "AEGgAABBoAAAAAAAAD+AAABAAAAAQEAAAAAAAAA/gAAAQAAAAEBAAAAAAAAAP4AAAEAAAABAQAAAAAAAAD+AAABAAAAAQEAAAAAA"
    "AAA/gAAAQAAAAEBAAAAAAAAAP4AAAEAAAABAQAAAAAAAAD+AAABAAAAAQEAAAAAAAAA/gAAAQAAAAEBAAAAAAAAAP4AAAEAAAABA"
    "QAAAAAAAAD+AAABAAAAAQEAAAAAAAAA/gAAAQAAAAEBAAAAAAAAAP4AAAEAAAABAQAAA")
case("nc-string-type-in-cdf1-sigfpe", ["--currents", "f.nc", START, GOAL, "--out", "{out}"], 2, "unknown type 12",
     {"f.nc": ("bytes", STRING_IN_CDF1_HEADER)})
case("nc-not-netcdf", ["--currents", "f.nc", START, GOAL, "--out", "{out}"], 2, "f.nc", {"f.nc": "hello\n"})

# --- geography: --region, longitudes in either convention, poles ------------------------------------------------
for name, region, phrase in [
        ("region-lat-above-90", "--region=-53,47,-52,95", "--region -53,47,-52,95: lat_max 95 is not a latitude"),
        ("region-lat-inverted", "--region=-53,48,-52,47", "lat_max 47 must be > lat_min 48"),
        ("region-360-wide", "--region=-180,47,180,48", "less than 360"),
        ("region-no-width", "--region=-53,47,-53,48", "no width"),
        ("region-lon-beyond-360", "--region=-53,47,400,48", "lon_max 400 is not a longitude"),
        ("region-lon-below-180", "--region=-200,47,-52,48", "lon_min -200 is not a longitude"),
        ("region-three-numbers", "--region=-53,47,-52", "--region expects four numbers"),
        ("region-text", "--region=-53,47,-52,north", "--region"),
        ("region-nan", "--region=-53,nan,-52,48", "--region"),
        ("region-start-outside", "--region=-52.5,47,-52,48", "--start -52.9,47.1 (lon,lat) lies outside --region"),
]:
    nc_case(name, forecast(), phrase, extra=(region,))
nc_case("start-lon-beyond-360", forecast(), "--start 400,47.1: longitude 400", args=("--start=400,47.1", GOAL))
nc_case("start-lat-beyond-90", forecast(), "latitude 91", args=("--start=-52.9,91", GOAL))
nc_case("start-at-pole", forecast(), "--start: latitude 89.95 is within 0.1 degrees of a pole",
        args=("--start=-52.9,89.95", GOAL))
case("region-without-currents", ["--region", "1,2,3,4", "--out", "{out}"], 2, "--region needs --currents")
case("region-over-mission-inverted", ["--mission", "m.yaml", "--region=5,3,1,-3", "--out", "{out}"], 2,
     "--region expects x_min,y_min,x_max,y_max with x_max > x_min", {"m.yaml": MISSION})
case("u-var-with-mission", ["--mission", "m.yaml", "--u-var", "u", "--out", "{out}"], 2,
     "--u-var cannot be combined with --mission", {"m.yaml": MISSION})
NC_MISSION = "current: {type: netcdf, file: f.nc}\nstart: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"
for name, region, phrase in [
        ("mission-region-lat-above-90", "{lon_min: -53, lon_max: -52, lat_min: 47, lat_max: 95}",
         "m.yaml:4: field 'region.lat_max'"),
        ("mission-region-360-wide", "{lon_min: 0, lon_max: 360, lat_min: 47, lat_max: 48}",
         "field 'region.lon_max'"),
        ("mission-region-start-outside", "{lon_min: 307.5, lon_max: 308, lat_min: 47, lat_max: 48}",
         "field 'start': lon,lat -52.9,47.1 lies outside the region"),
]:
    case(name, ["--mission", "m.yaml", "--out", "{out}"], 2, phrase,
         {"f.cdl": forecast(), "m.yaml": NC_MISSION + "region: " + region + "\n"})

# --- flags ------------------------------------------------------------------------------------------------------
for name, args, phrase in [
        ("flag-unknown", ["--colour", "red"], "colour"),
        ("flag-speed-zero", ["--speed", "0"], "--speed"),
        ("flag-speed-nan", ["--speed", "nan"], "--speed"),
        ("flag-speed-text", ["--speed", "fast"], "--speed"),
        ("flag-speed-1e308", ["--speed", "1e308"], "--speed: 1e+308 crosses the planning region"),
        ("flag-start-one-number", ["--start", "1"], "--start"),
        ("flag-start-three-numbers", ["--start", "1,2,3"], "--start"),
        ("flag-start-text", ["--start", "a,b"], "--start"),
        ("flag-start-inf", ["--start", "inf,0"], "--start"),
        ("flag-start-outside", ["--start", "20,0"], "start"),
        ("flag-grid-zero", ["--grid-size", "0"], "--grid-size"),
        ("flag-grid-tiny", ["--grid-size", "1e-4"], "--grid-size"),
        ("flag-sectors-0", ["--sectors", "0"], "--sectors"),
        ("flag-time-limit-huge", ["--time-limit", "1e10"], "--time-limit: at most 1e6 s (11.6 days), got 1e+10"),
        ("flag-time-limit-negative", ["--time-limit", "-1"], "--time-limit: expected a number in 0..1e6 s"),
        ("flag-request-timeout-huge", ["--request-timeout", "9.3e18"], "at most 1e6"),
        ("flag-departure-huge", ["--departure", "1e16"], "departure"),
        ("flag-departure-text", ["--departure", "noon"], "--departure"),
        ("flag-planner-unknown", ["--planner", "Dijkstra"], "Dijkstra"),
        ("flag-mission-and-currents", ["--mission", "m.yaml", "--currents", "f.nc"], "cannot be combined"),
        ("flag-u-var-without-currents", ["--u-var", "u"], "--currents"),
        ("flag-velocity-units-without-currents", ["--velocity-units", "knots"], "--velocity-units needs --currents"),
        ("flag-steady-record-without-currents", ["--steady-record", "0"], "--steady-record needs --currents"),
        ("flag-speeds-empty", ["--speeds", ""], "--speeds"),
        ("flag-speeds-negative", ["--speeds", "0.3,-1"], "--speeds"),
        ("flag-depth-average-reversed", ["--depth-average", "100,50"], "0 <= top <= bottom"),
        ("flag-depth-average-one-number", ["--depth-average", "200"], "two numbers"),
]:
    case(name, args + ["--out", "{out}"], 2, phrase, {"m.yaml": MISSION})
case("flag-grid-fine-memory-limit", ["--grid-size", "1e-3", "--out", "{out}"], 2, "--grid-size: a lattice spacing",
     env={"OMPL_GLIDER_MEMORY_LIMIT": "500M"})
# an automatic spacing the memory limit refuses: named as the automatic one, not as a planner.grid_size never given
case("automatic-grid-memory-limit", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml: the automatic lattice spacing (chosen from the leg's length; give one: planner.grid_size, --grid-size): "
     "a lattice spacing of 0.32 gives", {"m.yaml": mission("planner: {name: zastartve}")}, env={"OMPL_GLIDER_MEMORY_LIMIT": "4000"})
case("tmpdir-missing-fleet", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "the folder for temporary files '/nonexistent/tmp' (the environment variable TMPDIR) does not exist",
     {"m.yaml": mission(append="fleet:\n  - {name: a, start: {x: 1, y: 0}, goal: {x: 9, y: 0}}\n")},
     env={"TMPDIR": "/nonexistent/tmp"})
case("memory-limit-env-bad", ["--out", "{out}"], 2, "OMPL_GLIDER_MEMORY_LIMIT", env={"OMPL_GLIDER_MEMORY_LIMIT": "lots"})
case("out-is-a-file", ["--out", "afile"], 2, "afile")
case("out-unwritable", ["--out", "/proc/glider_out"], 2, "/proc/glider_out")

# --- goals in time: goal.window and --arrive-between ---------------------------------------------------
yaml_case("goal-window-reversed", mission("goal: {x: 9, y: 0, window: {begin: 20, end: 10}}"),
          "m.yaml:5: field 'goal.window.end': must not be before begin")
yaml_case("goal-window-missing-end", mission("goal: {x: 9, y: 0, window: {begin: 20}}"),
          "field 'goal.window': begin and end are required (missing end)")
yaml_case("goal-window-missing-begin", mission("goal: {x: 9, y: 0, window: {end: 20}}"), "(missing begin)")
yaml_case("goal-window-unknown-key", mission("goal: {x: 9, y: 0, window: {begin: 1, end: 2, slack: 3}}"),
          "goal.window.slack")
yaml_case("goal-window-not-a-time", mission("goal: {x: 9, y: 0, window: {begin: soon, end: 30}}"),
          "field 'goal.window.begin'")
yaml_case("goal-window-date-without-epoch",
          mission("goal: {x: 9, y: 0, window: {begin: 2026-03-15T00:00:00Z, end: 30}}"), "epoch")
yaml_case("goal-window-before-departure",
          mission("goal: {x: 9, y: 0, window: {begin: 10, end: 20}}", "departure: {time: 50}"),
          "field 'goal.window.end': the arrival window ends at t = 20, before the departure")
yaml_case("goal-window-beyond-horizon",
          mission("goal: {x: 9, y: 0, window: {begin: 100, end: 200}}",
                  "planner: {name: zastartve, grid_size: 0.5, horizon: 30}"),
          "field 'goal.window.begin': the arrival window opens at t = 100, after the planning horizon ends")
yaml_case("goal-window-stint-planner",
          mission("goal: {x: 9, y: 0, window: {begin: 10, end: 20}}", "planner: {name: direct}",
                  "stints: {duration: 1, mission_duration: 30}"), "goal.window")
nc_case("goal-window-after-forecast", forecast(), "--arrive-between: the arrival window opens",
        extra=("--arrive-between", "2026-03-20T00:00:00Z,2026-03-21T00:00:00Z"))
nc_case("cli-arrive-between-not-a-date", forecast(), "--arrive-between: begin",
        extra=("--arrive-between", "tomorrow,2026-03-16T00:00:00Z"))
case("cli-arrive-between-one-time", ["--arrive-between", "5", "--out", "{out}"], 2,
     "--arrive-between expects two times separated by a comma")
case("cli-arrive-between-three-times", ["--arrive-between", "5,6,7", "--out", "{out}"], 2,
     "--arrive-between expects two times")
case("cli-arrive-between-empty-item", ["--arrive-between", "5,", "--out", "{out}"], 2,
     "--arrive-between expects two times")
case("cli-arrive-between-reversed", ["--arrive-between", "20,10", "--out", "{out}"], 2,
     "--arrive-between: the end (10) must not be before the begin (20)")
case("cli-arrive-between-nan", ["--arrive-between", "nan,10", "--out", "{out}"], 2, "--arrive-between: begin")
case("cli-arrive-between-date-built-in", ["--arrive-between", "2026-03-15,2026-03-16", "--out", "{out}"], 2,
     "--arrive-between: begin")
case("goal-window-missed", ["--arrive-between", "1,2", "--out", "{out}"], 1,
     "after the end of the goal's arrival window")
# --- safety margins: keep-off distance, depth limit --------------------------------------------------------------
BATHY = """netcdf b {
dimensions: lat = 3 ; lon = 3 ;
variables:
  double lat(lat) ; lat:units = "degrees_north" ;
  double lon(lon) ; lon:units = "degrees_east" ;
  float VAR(lat, lon) ; ATTRS
data:
  lat = 46.9, 47.5, 48.1 ;
  lon = -53.1, -52.5, -51.9 ;
  VAR = -100, -100, -100, -100, -100, -100, -100, -100, -100 ;
}
"""
for name, args, phrase in [
        ("flag-keep-off-negative", ["--keep-off=-2"], "--keep-off: expected a length >= 0"),
        ("flag-keep-off-unknown-unit", ["--keep-off", "2 fortnights"], "--keep-off: expected a length"),
        ("flag-keep-off-km-without-units", ["--keep-off", "2km"], "needs the mission's length unit"),
        ("flag-min-depth-without-bathymetry", ["--min-depth", "50m"],
         "--min-depth: a depth limit needs a bathymetry file, a NetCDF file of seafloor depth or elevation "
         "(safety.bathymetry, --bathymetry)"),
]:
    case(name, args + ["--out", "{out}"], 2, phrase, {"m.yaml": MISSION})
yaml_case("safety-keep-off-negative", mission(append="safety: {keep_off: -1}\n"), "m.yaml:8: field 'safety.keep_off'")
yaml_case("safety-unknown-key", mission(append="safety: {keepoff: 1}\n"), "safety.keepoff")
yaml_case("safety-min-depth-without-bathymetry", mission(append="safety: {min_depth: 50m}\n"),
          "field 'safety.min_depth': needs safety.bathymetry")
yaml_case("safety-start-within-keep-off",
          mission(append="forbidden: {obstacles: [{name: Rock, points: [[1.5, -1], [2.5, -1], [2.5, 1], [1.5, 1]]}]}\n"
                         "safety: {keep_off: 1}\n"), "keep-off")
case("bathymetry-without-depth-variable", ["--currents", "f.nc", START, GOAL, "--bathymetry", "b.nc", "--min-depth",
                                           "50m", "--out", "{out}"], 2,
     "no seafloor depth or elevation variable",
     {"f.cdl": forecast(), "b.cdl": BATHY.replace("VAR", "foo").replace("ATTRS", "foo:units = \"m\" ;")})
case("bathymetry-sign-ambiguous", ["--currents", "f.nc", START, GOAL, "--bathymetry", "b.nc", "--bathymetry-variable",
                                   "foo", "--out", "{out}"], 2,
     "variable 'foo': cannot tell a depth (positive down) from an elevation",
     {"f.cdl": forecast(), "b.cdl": BATHY.replace("VAR", "foo").replace("ATTRS", "foo:units = \"m\" ;")})
case("bathymetry-variable-missing", ["--currents", "f.nc", START, GOAL, "--bathymetry", "b.nc", "--bathymetry-variable",
                                     "depth", "--out", "{out}"], 2, "--bathymetry: NetCDF file",
     {"f.cdl": forecast(), "b.cdl": BATHY.replace("VAR", "elevation").replace("ATTRS", "elevation:positive = \"up\" ;")})
BATHY_100 = BATHY.replace("-100", "100")
for name, var, attrs, data, phrase in [
        ("bathymetry-elevation-holding-depths", "elevation", 'elevation:units = "m" ;', "100",
         "variable 'elevation' read as elevation, positive up (by its name) makes every node over the mission's "
         "region land (values 100..100 m in the file); expected a seafloor below the trip: if its values are "
         "depths, positive down, mark the variable positive = \"down\""),
        ("bathymetry-depth-marked-positive-up", "depth", 'depth:units = "m" ; depth:positive = "up" ;', "100",
         "variable 'depth' read as elevation, positive up (attribute positive) makes every node"),
        ("bathymetry-fill-values-only", "depth", 'depth:units = "m" ; depth:_FillValue = -999.f ;', "-999",
         "variable 'depth' holds only fill values over the mission's region"),
        ("bathymetry-land-everywhere", "depth", 'depth:units = "m" ; depth:positive = "down" ;', "-5",
         "read as depth, positive down (attribute positive) makes every node over the mission's region land (values "
         "-5..-5 m in the file); expected a seafloor below the trip: if its values are elevations, positive up")]:
    case(name, ["--currents", "f.nc", START, GOAL, "--bathymetry", "b.nc", "--min-depth", "50m", "--out", "{out}"], 2,
         phrase, {"f.cdl": forecast(), "b.cdl": BATHY.replace("VAR", var).replace("ATTRS", attrs).replace("-100", data)})
# (lon, lat) dimensions, axes over the same numbers, nothing that says which is which: refused, never guessed
ANON_BATHY = """netcdf b {
dimensions: p = 3 ; q = 3 ;
variables:
  double p(p) ; double q(q) ;
  float depth(p, q) ; depth:positive = "down" ;
data:
  p = 47, 47.5, 48 ; q = 47, 47.5, 48 ;
  depth = 100, 100, 100, 100, 100, 100, 100, 100, 100 ;
}
"""
case("bathymetry-axis-order-unknown", ["--currents", "f.nc", START, GOAL, "--bathymetry", "b.nc", "--min-depth", "50m",
                                       "--out", "{out}"], 2,
     "variable 'depth' on dimensions (p, q): cannot tell which is longitude/x and which latitude/y",
     {"f.cdl": forecast(), "b.cdl": ANON_BATHY})
# --depth on a forecast without a depth dimension (a scalar 'depth' variable, or none): refused, never planned at the
# surface in silence
for name, cdl in [("depth-on-a-scalar-depth-variable",
                   forecast(replace=[("variables:", 'variables:\n  double depth ; depth:units = "m" ; depth:positive = "down" ;'),
                                     ("data:", "data:\n  depth = 10 ;")])),
                  ("depth-on-a-forecast-without-depth", forecast())]:
    nc_case(name, cdl, "--depth: the glider's depth of 50 m: the forecast's 'u' has no depth dimension",
            extra=("--depth", "50"))
nc_case("depth-average-single-level", forecast(), "needs several depth levels", extra=("--depth-average", "0,200"))

# --- coastline and forbidden-region files: their CRS, coordinates that are not lon/lat, files nowhere near -------
def mercator(lon, lat):
    import math
    r = 6378137.0
    return r * math.radians(lon), r * math.log(math.tan(math.pi / 4 + math.radians(lat) / 2))


ISLAND = [(-52.55, 47.45), (-52.45, 47.45), (-52.45, 47.55), (-52.55, 47.55), (-52.55, 47.45)]


def island_geojson(points, crs=None):
    ring = ", ".join("[%.3f, %.3f]" % p for p in points)
    head = '"crs": {"type": "name", "properties": {"name": "%s"}}, ' % crs if crs else ""
    return ('{"type": "FeatureCollection", %s"features": [{"type": "Feature", "properties": {"name": "Isle"}, '
            '"geometry": {"type": "Polygon", "coordinates": [[%s]]}}]}\n' % (head, ring))


MERC = [mercator(*p) for p in ISLAND]
SWAPPED = [(b, a) for a, b in ISLAND]
case("coastline-crs-3857-transformed", ["--currents", "f.nc", START, GOAL, "--coastline", "c.geojson", "--speed", "1",
                                        "--no-refine", "--out", "{out}"],
     0, "1 land polygons from 1 of 1 features of 'c.geojson'",
     {"f.cdl": forecast(), "c.geojson": island_geojson(MERC, "urn:ogc:def:crs:EPSG::3857")})
case("coastline-mercator-without-crs", ["--currents", "f.nc", START, GOAL, "--coastline", "c.geojson", "--out", "{out}"],
     2, "coastline file 'c.geojson', layer 'c', feature 'Isle': coordinates up to lon",
     {"f.cdl": forecast(), "c.geojson": island_geojson(MERC)})
case("coastline-lon-lat-swapped", ["--currents", "f.nc", START, GOAL, "--coastline", "c.geojson", "--out", "{out}"],
     2, "coastline file 'c.geojson': none of its 1 features lies in or near the trip's box",
     {"f.cdl": forecast(), "c.geojson": island_geojson(SWAPPED)})
GJ_MISSION = NC_MISSION + "forbidden: {geojson: r.geojson}\n"
case("forbidden-geojson-crs-3857", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "r.geojson:1: field 'crs': the GeoJSON names the coordinate reference system 'urn:ogc:def:crs:EPSG::3857'",
     {"f.cdl": forecast(), "m.yaml": GJ_MISSION, "r.geojson": island_geojson(MERC, "urn:ogc:def:crs:EPSG::3857")})
case("forbidden-geojson-mercator-without-crs", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "feature 'Isle': [-5849839.241, 6015837.354] is not lon/lat",
     {"f.cdl": forecast(), "m.yaml": GJ_MISSION, "r.geojson": island_geojson(MERC)})
case("forbidden-geojson-lon-lat-swapped", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "none of its 1 forbidden regions lies in or near the planning region; they lie within lon 47.45..47.55",
     {"f.cdl": forecast(), "m.yaml": GJ_MISSION, "r.geojson": island_geojson(SWAPPED)})


def zone_geojson(properties):
    return ('{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {%s}, "geometry": '
            '{"type": "Polygon", "coordinates": [[[4, -1], [6, -1], [6, 1], [4, 1], [4, -1]]]}}]}\n' % properties)


XY_GJ = mission(append="forbidden: {geojson: r.geojson, geojson_coordinates: local}\n")
for name, props, phrase in [
        ("forbidden-geojson-windows-on-an-island", '"kind": "island", "windows": [[0, 5]]',
         "r.geojson:1: field 'features[0].properties.windows': belongs to a zone of kind 'closure', but this "
         "feature's kind is 'island'"),
        ("forbidden-geojson-windows-without-kind", '"windows": [[0, 5]]', "'island' (the default): give kind: closure"),
        ("forbidden-geojson-drift-on-a-closure", '"kind": "closure", "windows": [[0, 5]], "drift": [1, 0]',
         "field 'features[0].properties.drift': belongs to a zone of kind 'ice'"),
        ("forbidden-geojson-windows-flat-list", '"kind": "closure", "windows": [0, 5]',
         "field 'features[0].properties.windows[0]': expected a pair [a, b]"),
        ("forbidden-geojson-windows-a-number", '"kind": "closure", "windows": 3',
         "field 'features[0].properties.windows': a closure needs windows: [[from, to], ...]")]:
    case(name, ["--mission", "m.yaml", "--out", "{out}"], 2, phrase, {"m.yaml": XY_GJ, "r.geojson": zone_geojson(props)})
# a coastline collection: a closed shoreline is land (the route goes around it), an open one is refused
SHORE = ", ".join("[%.3f, %.3f]" % p for p in ISLAND)
OPEN_SHORE = ", ".join("[%.3f, %.3f]" % p for p in ISLAND[:-1])


def collection_geojson(ring):
    return ('{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"name": "Shores"}, '
            '"geometry": {"type": "GeometryCollection", "geometries": [{"type": "LineString", "coordinates": [%s]}]}}]}'
            '\n' % ring)


case("coastline-collection-closed-shoreline-is-land",
     ["--currents", "f.nc", "--start=-52.6,47.5", "--goal=-52.4,47.5", "--coastline", "c.geojson", "--speed", "1",
      "--out", "{out}"], 0, "Straight line:      impassable", {"f.cdl": forecast(), "c.geojson": collection_geojson(SHORE)})
case("coastline-collection-open-shoreline",
     ["--currents", "f.nc", START, GOAL, "--coastline", "c.geojson", "--out", "{out}"], 2,
     "feature 'Shores', member 1 of its collection: an open line from lon -52.55, lat 47.45 to lon -52.55, lat 47.55",
     {"f.cdl": forecast(), "c.geojson": collection_geojson(OPEN_SHORE)})
# --- NetCDF: attributes and axes that were taken in silence, packed coordinates, groups ---------------------------
NOT_EASTWARD = [('u:standard_name = "eastward_sea_water_velocity" ;', ""),
                ('v:standard_name = "northward_sea_water_velocity" ;', "")]
nc_case("nc-angle-1d-on-2d-grid", forecast(replace=NOT_EASTWARD + [
    ('  float u(', '  double angle(lon) ; angle:units = "radians" ;\n  float u('),
    ("  u = ", "  angle = 0, 0, 0, 0, 0, 0 ;\n  u = ")]),
    "grid angle variable 'angle' is not on the grid of the velocities")
nc_case("nc-scale-factor-text", forecast(replace=[('u:_FillValue = -999.f ;', 'u:_FillValue = -999.f ; u:scale_factor = "0.01" ;')]),
        "variable 'u': attribute 'scale_factor' is text ('0.01'); it must be numeric")
DEPTH_NO_AXIS = forecast(replace=[("lat = 6 ;", "k = 2 ; lat = 6 ;"), ("float u(time, lat", "float u(time, k, lat"),
                                  ("float v(time, lat", "float v(time, k, lat")]).replace(
    ", ".join(["0.1"] * 108), ", ".join(["0.1"] * 216)).replace(", ".join(["0"] * 108), ", ".join(["0"] * 216))
nc_case("nc-depth-without-depth-axis", DEPTH_NO_AXIS, "has dimension 'k' (length 2) that is neither time, depth")
# a THREDDS FMRC (two runs: a run dimension, its reference times, a 2-D time) given as one forecast: read it as runs
FMRC = forecast(replace=[("time = UNLIMITED ;", "run = 2 ; time = 3 ;"),
                         ("double time(time) ;", 'double run(run) ; run:units = "hours since 2026-03-15 00:00:00" ; '
                          'run:standard_name = "forecast_reference_time" ;\n  double time(run, time) ;'),
                         ("float u(time", "float u(run, time"), ("float v(time", "float v(run, time"),
                         ("time = 0, 24, 48 ;", "run = 0, 24 ;\n  time = 0, 24, 48, 24, 48, 72 ;")]).replace(
    ", ".join(["0.1"] * 108), ", ".join(["0.1"] * 216)).replace(", ".join(["0"] * 108), ", ".join(["0"] * 216))
nc_case("nc-fmrc-without-runs", FMRC, "is on dimension 'run' of 2 forecast runs (a forecast model run collection, "
        "a THREDDS FMRC, with a 2-D time): read it as forecast runs, each run one forecast, with --currents ... --runs")
case("yaml-fmrc-as-file", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "field 'current.file': '", {"f.cdl": FMRC, "m.yaml": "name: fmrc\ncurrent: {type: netcdf, file: f.nc}\n"
                                "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
PACKED = forecast(replace=[("double lat(lat) ;", "short lat(lat) ; lat:scale_factor = 0.01 ; lat:add_offset = 47. ;"),
                           ("double lon(lon) ;", "short lon(lon) ; lon:scale_factor = 0.01 ; lon:add_offset = -53. ;")],
                  lat="0, 20, 40, 60, 80, 100", lon="0, 20, 40, 60, 80, 100")
nc_case("nc-lon-lat-int16-packed-extent", PACKED,
        "--goal -40,47.9 (lon,lat) lies outside the grid of 'f.nc' (lon -53..-52, lat 47..48)", args=(START, "--goal=-40,47.9"))
# the same travel time as the unpacked forecast() (102067.2 s at 1 m/s): the nodes are where the doubles put them
nc_case("nc-lon-lat-int16-packed-plans", PACKED, "Travel time:        1 d 4.4 h (102067.2 s)", status=0,
        extra=("--speed", "1"))
GROUPED = "netcdf grouped {\ngroup: ocean {\n" + forecast().split("{", 1)[1] + "}\n"
nc_case("nc4-variables-in-a-group", ("nc4", GROUPED), "NetCDF-4 groups ('ocean'): only the root group is read")
case("currents-file-name-with-brackets", ["--currents", "a[1].nc", START, "--goal=-40,47.9", "--out", "{out}"], 2,
     "lies outside the grid of 'a[1].nc'", {"a[1].cdl": forecast()})
# --- a truth over a corner of the trip: refused where the plan leaves it (its grid's edge is not land) -------------
case("execution-truth-covers-a-corner", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "field 'execution.truth': the truth's grid covers lon -53, lat 46.9989 to lon -52.6, lat 47.401; the plan leaves it at",
     {"f.cdl": forecast(), "t.cdl": forecast(lat="47.0, 47.08, 47.16, 47.24, 47.32, 47.4",
                                             lon="-53.0, -52.92, -52.84, -52.76, -52.68, -52.6"),
      "m.yaml": NC_MISSION + "vehicle: {speed: 1.0}\nexecution: {truth: {type: netcdf, file: t.nc}}\n"})
# --- a goal walled in, with a long window: proven at once, not stepped for minutes ----------------------------------
yaml_case("levelset-walled-in-horizon-1e5",
          mission("planner: {name: LevelSet, horizon: 100000}",
                  append="forbidden:\n  obstacles:\n    - {name: pocket, points: [[0, -1], [3, -1], [3, 1], [0, 1], "
                  "[0, 0.6], [2.5, 0.6], [2.5, -0.6], [0, -0.6]]}\n"),
          "no water links it to the start", status=1)
# --- mission files that are no files, nulls, tiny speeds, bad UTF-8 ------------------------------------------------
case("mission-is-dev-zero", ["--mission", "/dev/zero", "--out", "{out}"], 2,
     "cannot read mission file '/dev/zero': it is not a regular file")
case("mission-is-a-fifo", ["--mission", "pipe", "--out", "{out}"], 2,
     "cannot read mission file 'pipe': it is not a regular file", {"pipe": ("fifo", "")})
case("mission-huge-file", ["--mission", "big.yaml", "--out", "{out}"], 2,
     "cannot read mission file 'big.yaml': it holds 17825792 bytes", {"big.yaml": ("bytes", b"#" * (17 << 20))})
yaml_case("start-null", mission("start: ~"), "m.yaml:4: field 'start'")
yaml_case("speed-denormal", mission("vehicle: {speed: 1e-310}"), "m.yaml:6: field 'vehicle.speed'")
case("flag-speed-denormal", ["--speed", "1e-310", "--out", "{out}"], 2, "--speed")
case("name-bad-utf8", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:1: the text is not UTF-8 (byte 0xff at column 7)",
     {"m.yaml": ("bytes", b"name: \xff\xfe glider\n" + mission().split("\n", 1)[1].encode())})

# --- the glider's observations in real time: Slocum dba files, an ERDDAP URL ----------------------------------------
DBA = ("dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\nencoding_ver: 2\nnum_ascii_tags: 5\n"
       "filename: ru29-2026-074-0-0\nsensors_per_cycle: 5\n"
       "m_present_time m_gps_lat m_gps_lon m_water_vx m_water_vy\ntimestamp lat lon m/s m/s\n8 8 8 4 4\n")


def observations_case(name, observations, phrase, files=None, extra=()):
    case(name, ["--currents", "f.nc", "--observations", observations, GOAL, *extra, "--out", "{out}"], 2, phrase,
         {"f.cdl": forecast(), **(files or {})})


observations_case("observations-dba-not-a-number", "g.dba", "g.dba:9: sensor 'm_gps_lat': '47x0.0' is not a number",
                  {"g.dba": DBA + "1773554400 47x0.0 -5230.0 NaN NaN\n"})
observations_case("observations-dba-row-too-short", "g.dba", "g.dba:10: 3 values, the label line (6) names 5 sensors",
                  {"g.dba": DBA + "1773554400 4730.0 -5230.0 NaN NaN\n1773554430 NaN NaN\n"})
observations_case("observations-dba-no-water-velocity", "g.dba", "g.dba:6: no sensor 'm_water_vy'",
                  {"g.dba": DBA.replace(" m_water_vy", " m_depth")})
observations_case("observations-dba-degc", "g.dba", "g.dba:7: 'm_water_vx' is in 'degC': units 'degC' are not a velocity",
                  {"g.dba": DBA.replace("lon m/s m/s", "lon degC degC")})
observations_case("observations-fix-after-forecast", "d.csv", "the last fix's time (--observations) 2030-01-01",
                  {"d.csv": "time,lon,lat,u,v\n2030-01-01T00:00:00Z,-52.5,47.5,0.1,0\n"})
# a mission resumed at a last fix after the forecast's end (2026-03-17T00:00:00Z): the forecast's end is named, not the
# window of a station the glider could then never reach
case("observations-last-fix-after-forecast-end", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "the glider's last fix (2026-03-17T06:00:00Z) is after the forecast's end (2026-03-17T00:00:00Z)",
     {"f.cdl": forecast(),
      "d.csv": "time,lon,lat,u,v\n2026-03-15T06:00:00Z,-52.8,47.2,0.1,0\n2026-03-17T06:00:00Z,-52.7,47.3,0.1,0\n",
      "m.yaml": "name: late\ncurrent: {type: netcdf, file: f.nc}\nstart: {lon: -52.9, lat: 47.1}\n"
                "waypoints:\n  - {name: A, lon: -52.5, lat: 47.5, radius: 500 m, "
                "arrive: {begin: \"2026-03-15T12:00:00Z\", end: \"2026-03-16T12:00:00Z\"}}\n"
                "goal: {lon: -52.1, lat: 47.9}\ndeparture: {time: \"2026-03-15T00:00:00Z\"}\n"
                "vehicle: {speed: 0.3}\nobservations: {file: d.csv}\n"})
observations_case("observations-csv-degc", "d.csv", "d.csv:1: 'u' is in 'degC': units 'degC' are not a velocity",
                  {"d.csv": "time,lon,lat,u (degC),v (degC)\n2026-03-15T06:00:00Z,-52.5,47.5,12,11\n"})
# a CSV row whose u and v are NaN is a fix without a DAC's value: rejected as such, never counted as a DAC
observations_case("observations-csv-nan-dac", "d.csv", "u or v not a number",
                  {"d.csv": "time,lon,lat,u,v\n2026-03-15T06:00:00Z,-52.5,47.5,NaN,NaN\n"})
observations_case("observations-dba-no-dac", "g.dba", "no usable depth-averaged current (sensors m_water_vx, m_water_vy",
                  {"g.dba": DBA + "1773554400 4730.0 -5230.0 NaN NaN\n"})
# a Slocum's own binary files: cut short, their sensor list in a cache file that is not there, an encoding unknown
def slocum_binary(version=5, factored=False, end=b"X"):
    """A Slocum sbd file (big-endian) of the five sensors, one data cycle, its end tag @p end."""
    sensors = [("m_present_time", "timestamp", 8), ("m_gps_lat", "lat", 8), ("m_gps_lon", "lon", 8),
               ("m_water_vx", "m/s", 4), ("m_water_vy", "m/s", 4)]
    head = ("dbd_label: DBD(dinkum_binary_data)file\nencoding_ver: %d\nnum_ascii_tags: 9\n"
            "full_filename: ru29-2026-074-0-0\ntotal_num_sensors: 5\nsensors_per_cycle: 5\n"
            "state_bytes_per_cycle: 2\nsensor_list_crc: 1a2b3c4d\nsensor_list_factored: %d\n" % (version, factored))
    if not factored:
        head += "".join("s: T %d %d %d %s %s\n" % (k, k, b, n, u) for k, (n, u, b) in enumerate(sensors))
    known = b"sa" + struct.pack(">hfd", 0x1234, 123.456, 123456789.12345)
    # one cycle: a new time and fix (state 2), no DAC (state 0)
    cycle = b"d" + bytes([0b10101000, 0]) + struct.pack(">ddd", 1773554400.0, 4730.0, -5230.0)
    return ("bytes", head.encode() + known + cycle + end)


# (byte 404: the 361 bytes of the header and sensor list, the 16 known bytes, the cycle's 27: where the end tag is due)
observations_case("observations-sbd-cut-short", "ru29-2026-074-0-0.sbd",
                  "ru29-2026-074-0-0.sbd: byte 404: the file ends without its end tag 'X'",
                  {"ru29-2026-074-0-0.sbd": slocum_binary(end=b"")})
observations_case("observations-sbd-no-cache-file", "ru29-2026-074-0-0.sbd",
                  "the sensor list is in the cache file '1a2b3c4d.cac' (sensor_list_factored: 1), found in none of the "
                  "folders", {"ru29-2026-074-0-0.sbd": slocum_binary(factored=True)})
observations_case("observations-sbd-encoding-unknown", "ru29-2026-074-0-0.sbd",
                  "ru29-2026-074-0-0.sbd: unknown encoding version 9 (encoding_ver",
                  {"ru29-2026-074-0-0.sbd": slocum_binary(version=9)})
observations_case("observations-erddap-server-down", "http://127.0.0.1:1/erddap/tabledap/ru29.csvp?time,u",
                  "ERDDAP: cannot fetch 'http://127.0.0.1:1/erddap/tabledap/ru29.csvp?time,u'", extra=("--retries", "0"))
observations_case("observations-erddap-file-type", "http://127.0.0.1:1/erddap/tabledap/ru29.htmlTable?time",
                  "not an ERDDAP tabledap answer this reader knows (the file type '.htmlTable'")

# --- well-formed problems without a path: exit 1 with the reason ------------------------------------------------
case("no-path-slow-in-jet", ["--speed", "0.05", "--out", "{out}"], 1, "Status:             No path")
case("no-path-horizon-named", ["--speed", "0.05", "--out", "{out}"], 1, "within the planning horizon")
# a start in a Rankine vortex three times the glider's speed: the heading planners after the lattice run under a time
# limit (here the mission's 2 s) and say so, never for hours
yaml_case("no-path-vortex-fallback-time-limit",
          mission("current: {type: rankine_vortex, parameters: {x0: 5, y0: 0, radius: 4, vmax: 1.5}}",
                  "start: {x: 4, y: 0}", "goal: {x: 9.5, y: -3.5}",
                  "planner: {name: zastartve, grid_size: 0.5, time_limit: 2}"),
          "no path found: the level set, after Isochrone, each with the time limit: the time limit (2 s) ended the "
          "search before a path was found: raise it (planner.time_limit, --time-limit)", status=1)


# --- forecast values and sources that are not what they seem: the message names the source, not a planner field --
# velocities no current reaches, not fill values (a fill value not declared): the file, the variable, the value, where
nc_case("nc-velocity-1e30", forecast(u="1e30"), "NetCDF file 'f.nc': variable 'u' holds 1e+30 m/s at (j, i) = (0, 0)")
nc_case("nc-velocity-1e38-one-node", forecast(u=", ".join(["0.1"] * 50 + ["1e38"] + ["0.1"] * 57)),
        "variable 'u' holds 1e+38 m/s at (j, i) = (2, 2), lon -52.6, lat 47.4, record 1 of 'time'")
# a lone spike far faster than the flow around it: refused, naming the bound and how to raise it
nc_case("nc-velocity-473-one-node", forecast(u=", ".join(["0.1"] * 50 + ["-473.867"] + ["0.1"] * 57)),
        "variable 'u' holds -473.867 m/s at (j, i) = (2, 2), lon -52.6, lat 47.4, record 1 of 'time': faster than any "
        "current or wind (more than 300 m/s)")
nc_case("nc-velocity-473-names-the-flag", forecast(u=", ".join(["0.1"] * 50 + ["-473.867"] + ["0.1"] * 57)),
        "if the speeds are real, raise the bound with --max-current-speed")
# the bound given lower than the flow: the flag named
nc_case("nc-velocity-above-the-bound-given", forecast(u="0.5"), "faster than the bound given (more than 0.2 m/s)",
        extra=("--max-current-speed", "0.2"))
nc_case("flag-max-current-speed-not-a-speed", forecast(), "--max-current-speed: expected a speed > 0",
        extra=("--max-current-speed", "3 km"))
case("yaml-max-speed-not-a-speed", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:1: field 'current.max_speed': expected a speed > 0",
     {"f.cdl": forecast(), "m.yaml": "current: {type: netcdf, file: f.nc, max_speed: -3}\n"
                                     "start: {lon: -52.9, lat: 47.1}\ngoal: {lon: -52.1, lat: 47.9}\n"})
case("yaml-max-speed-analytic", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:3: field 'current.max_speed': only for type",
     {"m.yaml": MISSION.replace("current: {type: uniform, parameters: {u: 0.1, v: 0.0}}",
                                "current: {type: uniform, parameters: {u: 0.1, v: 0.0},\n  max_speed: 5}")})
case("yaml-velocity-1e30", ["--mission", "m.yaml", "--out", "{out}"], 2, "variable 'u' holds 1e+30 m/s",
     {"f.cdl": forecast(u="1e30"), "m.yaml": "current: {type: netcdf, file: f.nc}\nstart: {lon: -52.9, lat: 47.1}\n"
                                             "goal: {lon: -52.1, lat: 47.9}\n"})
# a flow within that bound yet far faster than the glider: the level set's step count blames the current
case("levelset-current-far-faster", ["--mission", "m.yaml", "--out", "{out}"], 2,
     "m.yaml:2: field 'current': the currents reach 200 (400 times the vehicle's speed of 0.5): the level set would "
     "take up to 5.56e+06 time steps",
     {"m.yaml": mission("current: {type: uniform, parameters: {u: 200, v: 0.0}}", "planner: {name: LevelSet}")})
nc_case("nc-currents-far-faster-levelset", forecast(u="250"),
        "f.nc: field 'current': the currents reach 250 (833 times the vehicle's speed of 0.3)",
        extra=("--planner", "LevelSet", "--beyond", "hold"))


def zarr_store(name, u_zarray=None, u_compressor=None):
    """A Zarr v2 store (no consolidated metadata, no compressor) of forecast()'s grid: u = 0.1, v = 0 m s-1."""
    files = {name + "/.zgroup": json.dumps({"zarr_format": 2})}

    def array(var, dims, dtype, values, attrs, compressor=None):
        shape = [len(values)] if len(dims) == 1 else [3, 6, 6]
        zarray = {"zarr_format": 2, "shape": shape, "chunks": shape, "dtype": dtype, "compressor": compressor,
                  "fill_value": "NaN", "order": "C", "filters": None}
        files["%s/%s/.zarray" % (name, var)] = zarray if var != "u" or u_zarray is None else u_zarray
        files["%s/%s/.zattrs" % (name, var)] = json.dumps(dict(attrs, _ARRAY_DIMENSIONS=dims))
        fmt = "<%d%s" % (len(values), "d" if dtype == "<f8" else "f")
        files["%s/%s/%s" % (name, var, ".".join(["0"] * len(dims)))] = ("bytes", struct.pack(fmt, *values))

    array("time", ["time"], "<f8", [0, 24, 48], {"units": "hours since 2026-03-15 00:00:00", "standard_name": "time"})
    array("lat", ["lat"], "<f8", [47.0 + 0.2 * k for k in range(6)], {"units": "degrees_north"})
    array("lon", ["lon"], "<f8", [-53.0 + 0.2 * k for k in range(6)], {"units": "degrees_east"})
    array("u", ["time", "lat", "lon"], "<f4", [0.1] * 108, {"units": "m s-1"}, u_compressor)
    array("v", ["time", "lat", "lon"], "<f4", [0.0] * 108, {"units": "m s-1"})
    for key, value in list(files.items()):
        if isinstance(value, dict):
            files[key] = json.dumps(value)
    return files


def store_case(name, files, phrase, store="s.zarr"):
    case(name, ["--currents", store, START, GOAL, "--out", "{out}"], 2, phrase, files)
    case(name + "-yaml", ["--mission", "m.yaml", "--out", "{out}"], 2, phrase,
         dict(files, **{"m.yaml": "current: {type: netcdf, file: %s}\nstart: {lon: -52.9, lat: 47.1}\n"
                                  "goal: {lon: -52.1, lat: 47.9}\n" % store}))


case("zarr-store-plans", ["--currents", "s.zarr", START, GOAL, "--beyond", "hold", "--out", "o2"], 0,
     "current gridded (Zarr store)", zarr_store("s.zarr"))  # (the store of the rows below, whole: it plans)
store_case("zarr-codec-unknown", zarr_store("s.zarr", u_compressor={"id": "foo"}),
           "Zarr store 's.zarr': no eastward (u) velocity among the arrays that can be read, and array 'u' cannot be "
           "opened: Decompressor foo not handled")
store_case("zarr-zarray-not-json", zarr_store("s.zarr", u_zarray="{not json"),
           "array 'u' cannot be opened: JSON parsing error")
store_case("zarr-zarray-no-shape", zarr_store("s.zarr", u_zarray={"zarr_format": 2, "chunks": [3, 6, 6],
                                                                   "dtype": "<f4", "compressor": None,
                                                                   "fill_value": "NaN", "order": "C",
                                                                   "filters": None}),
           "array 'u' cannot be opened: shape missing or not an array")
# a folder of NetCDF files is no Zarr store: say so, and how to give its files
store_case("currents-folder-of-netcdf", {"d/a.cdl": forecast(), "d/b.cdl": forecast()},
           "'d' is a folder, not a forecast file nor a Zarr v2 store (it holds no .zgroup, .zarray or .zmetadata); "
           "it holds 2 NetCDF file(s): give them as one forecast by a pattern ('d/*.nc', quoted)", store="d")
store_case("currents-empty-folder", {"e/.keep": ""}, "'e' is a folder, not a forecast file nor a Zarr v2 store",
           store="e")


# ---------------------------------------------------------------------------------------------------------------
def snapshot(root):
    """Every file below root with its content hash (the output directory must not change)."""
    out = {}
    for base, _, names in os.walk(root):
        for n in names:
            p = os.path.join(base, n)
            out[os.path.relpath(p, root)] = hashlib.sha256(open(p, "rb").read()).hexdigest()
    return out


def prepare(workdir, files):
    for name, text in files.items():
        path = os.path.join(workdir, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        how = text[0] if isinstance(text, tuple) else ""
        truncate = how == "truncate"
        if how:
            text = text[1]
        if name.endswith(".cdl"):
            nc = path[:-4] + ".nc"
            kind = "nc4" if how == "nc4" else "nc3"
            subprocess.run(["ncgen", "-k", kind, "-o", nc, "-"], input=text.encode(), check=True)
            if truncate:
                size = os.path.getsize(nc)
                with open(nc, "r+b") as f:
                    f.truncate(size // 2 + 8)
        elif how == "symlink":
            os.symlink(text, path)
        elif how == "fifo":
            os.mkfifo(path)
        elif how == "bytes":
            with open(path, "wb") as f:
                f.write(text)
        else:
            with open(path, "w", encoding="utf-8", errors="surrogateescape") as f:
                f.write(text)
    with open(os.path.join(workdir, "afile"), "w") as f:
        f.write("a file, not a directory\n")


def main():
    exe = os.path.abspath(sys.argv[1])
    only = sys.argv[sys.argv.index("-k") + 1] if "-k" in sys.argv else ""
    verbose = "-v" in sys.argv
    earlier = tempfile.mkdtemp()
    try:  # an earlier run's outputs, copied into every case's output directory
        r = subprocess.run([exe, "--grid-size", "0.8", "--no-refine", "--out", os.path.join(earlier, "out")],
                           capture_output=True, timeout=120)
        assert r.returncode == 0, r.stderr.decode()
        failures, ran = [], 0
        for name, files, args, status, phrase, env in CASES:
            if only not in name:
                continue
            ran += 1
            work = tempfile.mkdtemp()
            try:
                prepare(work, files)
                out = os.path.join(work, "out")
                shutil.copytree(os.path.join(earlier, "out"), out)
                before = snapshot(out)
                argv = [exe] + [a.replace("{out}", out).replace("{dir}", work) for a in args]
                try:
                    r = subprocess.run(argv, cwd=work, capture_output=True, timeout=120,
                                       env=dict(os.environ, **env))
                    text = (r.stdout + r.stderr).decode(errors="replace")
                    rc = r.returncode
                except subprocess.TimeoutExpired:
                    rc, text = "timeout", ""
                problems = []
                if rc != status:
                    problems.append("exit %s, expected %d" % (rc, status))
                if phrase.lower() not in text.lower():
                    problems.append("message lacks '%s'" % phrase)
                if "nan" in text.lower().replace("nanos", "").split("error")[-1] and "NaN" not in phrase:
                    if any(w in ("nan", "-nan") for w in text.lower().replace(",", " ").split()):
                        problems.append("NaN printed")
                if status == 2 and snapshot(out) != before:
                    problems.append("output directory changed")
                if len(text.strip().splitlines()) > 3 and status == 2:
                    problems.append("message longer than 3 lines")
                if problems or verbose:
                    first = text.strip().splitlines()[-1] if text.strip() else ""
                    print("%-32s %s\n    %s" % (name, "; ".join(problems) or "ok", first[:300]))
                if problems:
                    failures.append(name)
            finally:
                shutil.rmtree(work, ignore_errors=True)
        print("%d of %d bad-input cases pass" % (ran - len(failures), ran))
        if failures:
            print("failing: " + ", ".join(failures))
            return 1
        return 0
    finally:
        shutil.rmtree(earlier, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
