"""Every setting of the command line is one of Python's: each flag is a plan() keyword or has the equivalent
docs/PYTHON.md names; safety and execution settings given as keywords give the flags' answers; a bad value of each
keyword is refused naming the keyword."""
import csv
import inspect
import io
import math
import os
import re
import subprocess

import pytest

import ompl_glider
from conftest import EXAMPLES, SOURCE_DIR, glider_plan

CARIBBEAN = os.path.join(EXAMPLES, "caribbean_forecast.nc")
COAST = os.path.join(EXAMPLES, "jamaica_coast.geojson")
# along Jamaica's north coast; the global check off on both sides (the same answers, a quicker test)
START, GOAL = (-78.6, 18.7), (-76.6, 18.6)
TRIP = ["--currents", CARIBBEAN, "--start=-78.6,18.7", "--goal=-76.6,18.6", "--grid-size", "6000", "--no-global-check"]
KEYWORDS = dict(start=START, goal=GOAL, grid_size=6000, global_check=False)


def _flags():
    exe = os.environ.get("GLIDER_PLAN")
    if not exe:
        pytest.skip("GLIDER_PLAN (the glider_plan binary) is not set")
    text = subprocess.run([exe, "--help"], capture_output=True, text=True, timeout=60).stdout
    flags = set(re.findall(r"^\s+(?:-\w, )?(--[a-z][a-z0-9-]*)", text, re.M))
    assert "--keep-off" in flags and "--truth" in flags and "--u-var" in flags  # the parse found the flags
    return flags - {"--help"}


def _documented():
    """docs/PYTHON.md's table of flags and their Python equivalents: flag -> (callable, keyword) or None."""
    with open(os.path.join(SOURCE_DIR, "docs", "PYTHON.md")) as f:
        text = f.read()
    section = text.split("### Every flag in Python", 1)[1].split("\n#", 1)[0]
    table = {}
    for flag, python in re.findall(r"^\| `(--[a-z0-9-]+)` \| (.+?) \|$", section, re.M):
        m = re.fullmatch(r"`([\w.]+)\((\w+)=\)`", python)
        table[flag] = (m.group(1), m.group(2)) if m else None
        assert m or python.startswith("none: "), f"{flag}: an equivalent `f(keyword=)` or 'none: reason'"
    return table


def _parameters(name):
    """The keyword names of ompl_glider's callable @p name ("plan", "Field.netcdf", "Result.write", ...)."""
    obj = ompl_glider
    for part in name.split("."):
        obj = getattr(obj, part)
    try:
        return set(inspect.signature(obj).parameters)
    except (TypeError, ValueError):  # a function of the compiled module: its signature is its docstring's first line
        return set(re.findall(r"(\w+):", obj.__doc__.split("\n", 1)[0]))


def test_every_flag_has_a_python_keyword_or_a_documented_equivalent():
    keywords = _parameters("plan")
    table = _documented()
    for flag in sorted(_flags()):
        same = flag[2:].replace("-", "_")
        if same in keywords:
            assert flag not in table, f"{flag} is plan({same}=) and needs no row in docs/PYTHON.md"
            continue
        assert flag in table, f"{flag} has no plan() keyword '{same}' and no row in docs/PYTHON.md's table"
        if table[flag]:
            where, keyword = table[flag]
            assert keyword in _parameters(where), f"{flag}: {where}() has no keyword '{keyword}'"
    stale = set(table) - _flags()
    assert not stale, f"docs/PYTHON.md names flags glider_plan does not have: {sorted(stale)}"


def _bathymetry(path):
    """A GEBCO-like elevation grid over the Caribbean forecast: 2000 m deep, with a 20 m bank across the route
    (lon -78.3..-77.9, south of lat 18.55)."""
    lon = [-79.5 + 0.1 * i for i in range(46)]
    lat = [16.5 + 0.1 * j for j in range(31)]
    values = []
    for y in lat:
        for x in lon:
            values.append("-20" if -78.3 <= x <= -77.9 and y <= 18.55 else "-2000")
    cdl = ("netcdf bathy {\ndimensions:\n lat = 31 ;\n lon = 46 ;\nvariables:\n double lat(lat) ;\n"
           "  lat:units = \"degrees_north\" ;\n double lon(lon) ;\n  lon:units = \"degrees_east\" ;\n"
           " float elevation(lat, lon) ;\n  elevation:units = \"m\" ;\n  elevation:positive = \"up\" ;\n"
           "  elevation:standard_name = \"height_above_reference_ellipsoid\" ;\ndata:\n"
           f" lat = {', '.join(f'{v:.1f}' for v in lat)} ;\n lon = {', '.join(f'{v:.1f}' for v in lon)} ;\n"
           f" elevation = {', '.join(values)} ;\n}}\n")
    (path.parent / "bathy.cdl").write_text(cdl)
    subprocess.run(["ncgen", "-o", str(path), str(path.parent / "bathy.cdl")], check=True)
    return str(path)


def _close(a, b):
    return a == b or abs(a - b) <= 1e-9 * max(abs(a), abs(b))


def test_safety_keywords_give_the_flags_answers(tmp_path):
    bathy = _bathymetry(tmp_path / "bathy.nc")
    field = ompl_glider.Field.netcdf(CARIBBEAN)
    for flags, keywords in [
        (["--coastline", COAST, "--keep-off", "15km"], dict(coastline=COAST, keep_off="15km")),
        (["--bathymetry", bathy, "--min-depth", "50m"], dict(bathymetry=bathy, min_depth=50)),
        (["--bathymetry", bathy, "--bathymetry-variable", "elevation", "--min-depth", "50 m", "--snap-to-water"],
         dict(bathymetry=bathy, bathymetry_variable="elevation", min_depth="50 m", snap_to_water=True)),
    ]:
        rc, out, err, summary = glider_plan(*TRIP, *flags, out_dir=tmp_path / f"cli{len(flags)}")
        assert rc == 0, out + err
        r = ompl_glider.plan(field=field, **KEYWORDS, **keywords)
        assert r.solved
        assert _close(r.travel_time, summary["travel_time"]), (flags, r.travel_time, summary["travel_time"])
        assert r.summary["safety"] == summary["safety"]
    # the limits change the route: keep-off and the bank each cost time over the plain trip
    plain = ompl_glider.plan(field=field, **KEYWORDS)
    banked = ompl_glider.plan(field=field, **KEYWORDS, bathymetry=bathy, min_depth=50)
    assert banked.summary["safety"]["min_depth_m"] == 50 and plain.summary["safety"]["min_depth_m"] == 0
    assert banked.travel_time > plain.travel_time


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_execution_keywords_give_the_flags_answers(tmp_path):
    flags = ["--truth", "B0=1.3,c=0.14", "--strategies", "current_sensitive,greedy", "--surfacing-interval", "0.5",
             "--radius", "0.1", "--execution-pairs", "1", "--execution-seed", "3"]
    rc, out, err, summary = glider_plan(*flags, out_dir=tmp_path / "cli")
    assert rc == 0, out + err
    r = ompl_glider.plan(truth={"B0": 1.3, "c": 0.14}, strategies=["current_sensitive", "greedy"],
                         surfacing_interval=0.5, radius=0.1, execution_pairs=1, execution_seed=3)
    with open(tmp_path / "cli" / "execution.csv") as f:
        cli = _rows(f.read())
    py = r.execution
    assert py is not None and len(cli) == len(py["strategy"]) >= 4  # two strategies on the mission and one pair
    assert [row["strategy"] for row in cli] == list(py["strategy"])
    for k, row in enumerate(cli):
        for key, text in row.items():
            try:
                a = float(text)
            except ValueError:
                continue
            b = float(py[key][k])
            assert (math.isnan(a) and math.isnan(b)) or _close(a, b), (key, k, a, b)
    # the truth is another ocean than the plan's: "forecast" flies in the planning field itself
    same = ompl_glider.plan(truth="forecast", strategies=["current_sensitive"], surfacing_interval=0.5)
    assert set(same.execution["strategy"]) == {"current_sensitive"}


@pytest.mark.parametrize("keyword,value,says", [
    ("keep_off", "2 fortnights", "expected a length"),
    ("keep_off", -1.0, "expected a length >= 0"),
    ("min_depth", "-5 m", "expected a length >= 0"),
    ("min_depth", "deep", "expected a length"),
    ("bathymetry", 42, "expected a text"),
    ("bathymetry_variable", "elevation", "needs a bathymetry file (safety.bathymetry, bathymetry=)"),
    ("snap_to_water", "yes", "expected True or False"),
    ("truth", {"nope": 1.0}, "expected 'forecast' or NAME=VALUE"),
    ("truth", 3, "expected 'forecast', forecast files"),
    ("surfacing_interval", "soon", ""),
    ("strategies", ["fly"], "unknown strategy 'fly'"),
    ("strategies", ["greedy", "greedy"], "listed twice"),
    ("radius", -1.0, "expected a length > 0"),
    ("execution_pairs", -1, "expected an integer in 0..100000"),
    ("execution_seed", 1.5, "expected an integer"),
    ("coastline", "/nonexistent/coast.geojson", "the coastline is in lon/lat"),
])
def test_a_bad_value_of_each_keyword_names_the_keyword(keyword, value, says):
    with pytest.raises(ompl_glider.Error) as e:
        ompl_glider.plan(**{keyword: value})
    message = str(e.value)
    assert message.startswith(f"plan(): keyword '{keyword}'"), message
    assert says in message, message


@pytest.mark.parametrize("keywords,flags,names", [
    (dict(goal=(-70.0, 18.0)), ["--goal=-70,18"], ("plan(): keyword 'goal'", "--goal")),
    (dict(departure="2027-01-01T00:00:00Z"), ["--departure", "2027-01-01T00:00:00Z"],
     ("plan(): keyword 'departure'", "--departure")),
    (dict(region=(-79.0, 19.0, -77.0, 18.0)), ["--region=-79,19,-77,18"], ("plan(): keyword 'region'", "--region")),
])
def test_forecast_errors_name_the_keyword_in_python_and_the_flag_on_the_command_line(keywords, flags, names):
    """forecastMission() words its refusals in the caller's terms (ForecastInput::words): no flag reaches Python."""
    trip = dict(start=START, goal=GOAL) | keywords
    with pytest.raises(ompl_glider.Error) as e:
        ompl_glider.plan(field=ompl_glider.Field.netcdf(CARIBBEAN), **trip)
    message = str(e.value)
    assert message.startswith(names[0]) and "--" not in message, message
    args = [a for a in TRIP if not any(a.startswith(f.split("=")[0]) for f in flags)]
    rc, out, err, _ = glider_plan(*args, *flags)
    assert rc == 2 and err.startswith("glider_plan: " + names[1]), err
    # the same words after the name
    assert err.split(names[1], 1)[1].splitlines()[0] == message.split(names[0], 1)[1]


def test_a_forecast_variable_missing_names_its_keyword():
    with pytest.raises(ompl_glider.Error) as e:
        ompl_glider.plan(field=ompl_glider.Field.netcdf(CARIBBEAN, variables={"u": "nope"}), start=START, goal=GOAL)
    message = str(e.value)
    assert "no variable 'nope'" in message and "Field.netcdf(): keyword 'variables' (u)" in message, message
    assert "--" not in message, message


def test_every_plan_keyword_refuses_a_value_of_the_wrong_type_naming_itself():
    """Whatever the keyword, a value of no type it takes is an Error that names that keyword."""
    for name in inspect.signature(ompl_glider.plan).parameters:
        if name in ("mission", "field", "progress"):
            continue  # the mission itself, the field (its own checks: Field.netcdf()...), and a callback
        with pytest.raises(ompl_glider.Error) as e:
            ompl_glider.plan(**{name: object()})
        assert str(e.value).startswith(f"plan(): keyword '{name}': expected "), str(e.value)
