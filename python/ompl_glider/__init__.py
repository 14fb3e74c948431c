"""Time-optimal glider routes through time-varying currents, from Python.

A thin layer over the C++ library's one pipeline: every call builds one mission (the library's MissionSpec),
plans it with the same planning function as the command line ``glider_plan`` and reads the same result, so the
travel times are the command line's to the last bit, and :meth:`Result.write` writes the same files.

    >>> import ompl_glider
    >>> r = ompl_glider.plan()                       # the built-in Gulf Stream mission, as glider_plan
    >>> r.travel_time, r.status
    >>> r = ompl_glider.plan("examples/islands_ice.yaml", planner="LevelSet")
    >>> f = ompl_glider.Field.netcdf("examples/labrador_forecast.nc")
    >>> r = ompl_glider.plan(field=f, start=(-52.7, 47.9), goal=(-51.5, 48.45), speed=0.3, isochrones=True)
    >>> r.route.lon, r.route.lat, r.route.t          # numpy arrays
    >>> r.write("out/labrador")                      # summary.json, waypoints.csv, path.geojson, goto list, map

Errors in the input raise :class:`Error` (a ``ValueError``) with glider_plan's message; a well-formed problem
without a path is a result with ``solved`` False and ``reason`` saying why.
"""
from __future__ import annotations

import csv
import io
import json
import math
import numbers
import os
import weakref
from collections.abc import Iterable
from typing import Any, Callable, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Error, set_verbose, set_remote_access as _set_remote_access
from ._core import read_observations as _read_observations

__all__ = ["plan", "plan_fleet", "Field", "Result", "Route", "Error", "planner_names", "analytic_fields", "set_verbose",
           "set_remote_access", "is_gridded_kind", "read_observations"]


def read_observations(source: str, cache: str = "") -> Dict[str, Any]:
    """The fixes and depth-averaged currents (DAC) the planner reads from ``source`` (glider_plan's
    ``--observations``: IOOS profile files, a CSV, an ERDDAP URL, Slocum dba or binary files), by the same reader.

    Returns ``{"fixes": {"time", "lon", "lat"}, "dac": {"time", "lon", "lat", "u", "v", "segment_start",
    "segment_end", "depth_min", "depth_max"}, "rejected": {reason: count}, "notes": {what: count}, "platform",
    "files", "newest_surfacing"}``: numpy arrays of seconds since 1970, degrees, m/s, m (NaN where the source does
    not say). ``cache``: the folder of a Slocum's cache files (``*.cac``), searched before the files' own folder and
    its ``cache/``. Bad input raises :class:`Error` with glider_plan's message.
    """
    return _read_observations(os.fspath(source), os.fspath(cache))

Pair = Tuple[float, float]
ProgressCallback = Callable[[str, bool], None]


def _bad(who: str, value: Any, expected: str) -> Error:
    """The Error of a keyword of the wrong type: who ("plan(): keyword 'speed'"), what it expects, what it got."""
    text = repr(value)
    return Error(f"{who}: expected {expected}, got {type(value).__name__} {text if len(text) <= 60 else text[:57] + '...'}")


def _real(who: str, value: Any) -> float:
    """A finite number (not a bool; NaN would read as "not given"), as a float, or an Error naming who."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise _bad(who, value, "a number")
    if not math.isfinite(value):
        raise _bad(who, value, "a finite number")
    return float(value)


def _integer(who: str, value: Any) -> int:
    """A whole number (not a bool, not a float or text that would be truncated or parsed), or an Error naming who."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise _bad(who, value, "an integer")
    return int(value)


def _pair(who: str, value: Any) -> Pair:
    """Two numbers, as a tuple of floats, or an Error naming who."""
    try:
        a, b = value
        return (_real(who, a), _real(who, b))
    except (TypeError, ValueError, Error):
        raise _bad(who, value, "a pair (x, y) or (lon, lat) of numbers") from None


def set_remote_access(cache: Optional[Union[str, os.PathLike]] = None, request_timeout: float = 60.0,
                      retries: int = 2) -> None:
    """How forecasts given as OPeNDAP URLs (``Field.netcdf("https://...")``) are fetched, as glider_plan's flags.

    cache: a folder that keeps what is fetched (a NetCDF file per URL), so that a later plan over the same window
    reads no network (``--cache``); None: no cache. request_timeout: seconds each request may take (at most 1e6); it
    is fixed by the process's first NetCDF access, so set it before the first plan: another one after it raises Error
    (``--request-timeout``). retries: further attempts
    after a request fails for the network or the server, 0..10 (``--retries``).
    """
    _set_remote_access(os.fspath(cache) if cache is not None else "",
                       _real("set_remote_access(): request_timeout", request_timeout),
                       _integer("set_remote_access(): retries", retries))


def planner_names() -> List[str]:
    """The planners by their registry names (ZA*TVE, LevelSet, RRTstar, ...), as ``glider_plan --planner``."""
    return list(_core.planner_names())


def analytic_fields() -> Dict[str, Dict[str, float]]:
    """The analytic flows by name, each with its parameters and their defaults."""
    return dict(_core.analytic_fields())


def is_gridded_kind(kind: str) -> bool:
    """True when the library's registry reads the current kind ``kind`` from files through a gridded source: the
    built-in ``gridded`` (NetCDF, OPeNDAP, Zarr, GRIB) and its alias ``netcdf``, and the kinds an application
    registered as gridded (registerCurrentFieldKind()); False for analytic flows and unknown names."""
    return _core.is_gridded_kind(kind)


def _is_gridded(field: "Field") -> bool:
    """A Field planned as a forecast (forecast_mission()): one of a gridded kind of the registry."""
    return field.kind != "analytic" and isinstance(field.kind, str) and _core.is_gridded_kind(field.kind)


class Field:
    """A current field for :func:`plan`: a gridded forecast (NetCDF, OPeNDAP, Zarr, GRIB, or another gridded source
    of the registry), numpy arrays, or an analytic flow by name.

    Build one with :meth:`gridded` (or its alias :meth:`netcdf`), :meth:`from_arrays` or :meth:`analytic`. ``kind``
    is the registry's name of a gridded source (:func:`is_gridded_kind`) or "analytic".
    """

    def __init__(self, kind: str, **settings: Any) -> None:
        self.kind = kind
        self.settings = settings

    def __repr__(self) -> str:
        return f"Field({self.kind!r}, {self.settings!r})"

    @staticmethod
    def gridded(path: Union[str, os.PathLike, Sequence[str]], *, kind: str = "gridded",
                variables: Optional[Dict[str, str]] = None, depth: float = 0.0, xy_interpolation: str = "bilinear",
                depth_interpolation: str = "linear", time_interpolation: str = "linear", horizon: str = "refuse",
                velocity_units: str = "", time_units: str = "", steady_record: Optional[int] = None,
                zero_velocity_land: bool = True, depth_average: Optional[Pair] = None,
                max_speed: Union[None, float, str] = None, runs: bool = False,
                run_delay: Optional[str] = None) -> "Field":
        """A gridded forecast with the command line's options (``glider_plan --currents``): NetCDF files, OPeNDAP
        URLs, Zarr stores or GRIB files (kind ``gridded``, alias ``netcdf``), or the files of another gridded source
        the library's registry knows by ``kind`` (:func:`is_gridded_kind`).

        path: a file, a list of files read as one forecast, or a comma-separated list of files and glob patterns.
        variables: names by role (u, v, lon, lat, depth, time, mask, angle), found automatically when not given.
        The other options are those of the mission format's ``current`` section (examples/MISSION_FORMAT.md).
        """
        return Field._forecast("Field.gridded()", kind, path, variables, depth, xy_interpolation,
                               depth_interpolation, time_interpolation, horizon, velocity_units, time_units,
                               steady_record, zero_velocity_land, depth_average, max_speed, runs, run_delay)

    @staticmethod
    def netcdf(path: Union[str, os.PathLike, Sequence[str]], *, variables: Optional[Dict[str, str]] = None,
               depth: float = 0.0, xy_interpolation: str = "bilinear", depth_interpolation: str = "linear",
               time_interpolation: str = "linear", horizon: str = "refuse", velocity_units: str = "",
               time_units: str = "", steady_record: Optional[int] = None, zero_velocity_land: bool = True,
               depth_average: Optional[Pair] = None, max_speed: Union[None, float, str] = None,
               runs: bool = False, run_delay: Optional[str] = None) -> "Field":
        """A NetCDF forecast with the command line's options (``glider_plan --currents``): :meth:`gridded` by the
        kind's alias ``netcdf`` (its results say ``netcdf``, as glider_plan's do). Reads whatever :meth:`gridded`
        reads (NetCDF files, OPeNDAP URLs, Zarr stores, GRIB files).

        path: a file, a list of files read as one forecast, or a comma-separated list of files and glob patterns.
        variables: names by role (u, v, lon, lat, depth, time, mask, angle), found automatically when not given.
        The other options are those of the mission format's ``current`` section (examples/MISSION_FORMAT.md);
        max_speed is its ``max_speed``: the fastest current believed (m/s, or a text with a unit: "600 m/s").
        runs: the files are a forecast's runs, each file one run, a file or OPeNDAP URL of several runs (a THREDDS
        FMRC: a run dimension, a 2-D time) each of its runs (``--runs``; the mission format's ``current.runs``): the
        plan is made on the newest run available at the departure; run_delay (``"12 h"``, the default) is how
        long after its reference time a run becomes available.
        """
        return Field._forecast("Field.netcdf()", "netcdf", path, variables, depth, xy_interpolation,
                               depth_interpolation, time_interpolation, horizon, velocity_units, time_units,
                               steady_record, zero_velocity_land, depth_average, max_speed, runs, run_delay)

    @staticmethod
    def _forecast(who: str, kind: str, path: Union[str, os.PathLike, Sequence[str]],
                  variables: Optional[Dict[str, str]], depth: float, xy_interpolation: str, depth_interpolation: str,
                  time_interpolation: str, horizon: str, velocity_units: str, time_units: str,
                  steady_record: Optional[int], zero_velocity_land: bool, depth_average: Optional[Pair],
                  max_speed: Union[None, float, str] = None, runs: bool = False,
                  run_delay: Optional[str] = None) -> "Field":
        """The Field of :meth:`gridded` and :meth:`netcdf` (who names the method in messages)."""
        if not isinstance(runs, (bool, np.bool_)):
            raise _bad(f"{who}: runs", runs, "True (the files are forecast runs, each one run) or False")
        if run_delay is not None and (not isinstance(run_delay, str) or not run_delay):
            raise _bad(f"{who}: run_delay", run_delay, "a duration such as '12 h'")
        if run_delay is not None and not runs:
            raise _bad(f"{who}: run_delay", run_delay, "no run_delay without runs=True")
        if not isinstance(kind, str) or not _core.is_gridded_kind(kind):
            raise _bad(f"{who}: kind", kind, "the name of a gridded source (gridded, netcdf, or one registered as "
                       "gridded)")
        files = path if isinstance(path, (str, os.PathLike)) else ",".join(os.fspath(p) for p in path)
        if steady_record is not None and (isinstance(steady_record, (bool, np.bool_)) or
                                          not isinstance(steady_record, numbers.Integral) or steady_record < 0):
            raise _bad(f"{who}: steady_record", steady_record,
                       "the index of the record to hold as a steady field, an integer >= 0 (0: the first record)")
        if depth_average is not None:
            depth_average = _pair(f"{who}: depth_average", depth_average)
        return Field(kind, files=os.fspath(files), variables=dict(variables or {}),
                     depth=_real(f"{who}: depth", depth),
                     xy_interpolation=xy_interpolation, depth_interpolation=depth_interpolation,
                     time_interpolation=time_interpolation, horizon=horizon, velocity_units=velocity_units,
                     time_units=time_units, steady_record=steady_record, zero_velocity_land=zero_velocity_land,
                     depth_average=depth_average, max_speed="" if max_speed is None else str(max_speed),
                     runs=bool(runs), run_delay="" if run_delay is None else run_delay)

    @staticmethod
    def from_arrays(u: Any, v: Any, *, lon: Any = None, lat: Any = None, x: Any = None, y: Any = None,
                    t: Any = None, time_units: str = "", velocity_units: str = "m s-1", **options: Any) -> "Field":
        """Currents from numpy arrays (what an ``xarray.Dataset`` gives with ``.values``).

        u, v: (time, lat, lon) or, for a steady field, (lat, lon) arrays in m/s; NaN marks land.
        lon, lat: 1-D axes in degrees (a geographic field), or x, y: 1-D axes in metres (a Cartesian one).
        t: the times, numbers in ``time_units`` (e.g. "seconds since 2026-03-15 00:00:00") or numpy datetime64.
        The arrays become a CF NetCDF dataset in memory (no file; released with the Field) read by the forecast
        reader, so they get the same checks, interpolation and land handling as any forecast.
        ``options`` are those of :meth:`netcdf`.
        """
        geographic = lon is not None or lat is not None
        if geographic == (x is not None or y is not None):
            raise TypeError("Field.from_arrays: give the axes either as lon and lat or as x and y")
        ax, ay = (lon, lat) if geographic else (x, y)
        if ax is None or ay is None:
            raise TypeError("Field.from_arrays: both axes are needed (lon and lat, or x and y)")
        times = None
        if t is not None:
            times = np.asarray(t)
            if np.issubdtype(times.dtype, np.datetime64):
                times = (times - np.datetime64("1970-01-01T00:00:00")) / np.timedelta64(1, "s")
                time_units = "seconds since 1970-01-01 00:00:00"
            times = np.asarray(times, dtype=float)
        name = _core.memory_forecast(np.asarray(u, dtype=float), np.asarray(v, dtype=float),
                                     np.asarray(ax, dtype=float), np.asarray(ay, dtype=float), times, geographic,
                                     time_units, velocity_units)
        field = Field.netcdf(name, variables={"u": "u", "v": "v"}, **options)
        weakref.finalize(field, _core.release_memory_dataset, name)
        return field

    @staticmethod
    def analytic(name: str, **parameters: float) -> "Field":
        """An analytic flow by its registry name (meandering_jet, uniform, linear_shear, double_gyre, ...) and
        parameters (missing ones take their defaults; :func:`analytic_fields` lists them). Dimensionless units;
        the region is the built-in mission's (x in [0, 10], y in [-4, 4]) unless ``region=`` is given."""
        return Field("analytic", name=name,
                     parameters={k: _real(f"Field.analytic(): parameter '{k}'", p) for k, p in parameters.items()})


class Route(NamedTuple):
    """The route's waypoints as numpy arrays (start first): planning frame x, y; lon, lat (NaN without a
    projection); arrival time t (the mission's time unit); the heading held from each waypoint in degrees clockwise
    from north for a route of held headings (NaN for straight legs and at the last waypoint)."""
    x: np.ndarray
    y: np.ndarray
    lon: np.ndarray
    lat: np.ndarray
    t: np.ndarray
    headings: np.ndarray


class Result:
    """One planned mission: travel time, status, route, summary, GeoJSON, isochrones, execution table.

    Everything comes from the library's one result type; :meth:`write` writes the command line's files.
    """

    def __init__(self, core: "_core.Result") -> None:
        self._core = core

    def __repr__(self) -> str:
        return (f"<ompl_glider.Result planner={self.planner!r} status={self.status!r} "
                f"travel_time={self.travel_time!r}>")

    def map_html(self) -> str:
        """The interactive map of the plan (the command line's map.html): one HTML page that works offline."""
        return self._core.map_html()

    def _repr_html_(self) -> str:
        """Jupyter shows the interactive map inline (map.html in a sandboxed iframe)."""
        import html
        return ('<iframe style="width:100%;height:560px;border:0" sandbox="allow-scripts allow-popups" '
                f'srcdoc="{html.escape(self.map_html(), quote=True)}"></iframe>')

    @property
    def travel_time(self) -> float:
        """Arrival minus departure of the final path (the mission's time unit; inf without a path)."""
        return self._core.travel_time

    @property
    def status(self) -> str:
        """OMPL's planner status ("Exact solution", "Timeout", ...)."""
        return self._core.status

    @property
    def solved(self) -> bool:
        """True when a path to the goal was found."""
        return self._core.solved

    @property
    def reason(self) -> str:
        """Why there is no path (empty when solved)."""
        return self._core.reason

    @property
    def planner(self) -> str:
        """The planner that made the path (its registry name)."""
        return self._core.planner

    @property
    def departure(self) -> float:
        """The departure time (the mission's time unit)."""
        return self._core.departure

    @property
    def route(self) -> Route:
        """The waypoints for the pilot as numpy arrays (:class:`Route`)."""
        w = self._core.waypoints()
        return Route(w["x"], w["y"], w["lon"], w["lat"], w["t"], w["heading"])

    @property
    def waypoints(self) -> Dict[str, Any]:
        """The waypoints with every column of waypoints.csv: x, y, lon, lat, t, time_iso, leg_time, heading,
        heading_duration as the result holds them, leg (the leg of a mission of several legs, 0 for one leg) and
        stop (the via point a waypoint is: "start", a via point's name, the goal's; "" between them, and in a
        mission of one leg), and the file's other columns (index, time, time_s, profile, climb_to, dive_to,
        heading_true_deg, segment_duration: NaN where the file has no value) as the output layer writes them; heading
        and heading_true_deg are bearings from true north where the mission has lon/lat."""
        w = self._core.waypoints()
        rows = list(csv.DictReader(io.StringIO(self._core.waypoints_csv())))
        for key in (rows[0].keys() if rows else []):
            if key not in w:
                w[key] = np.array([_number(row[key]) for row in rows])
        return w

    @property
    def path(self) -> Dict[str, np.ndarray]:
        """The final path (x, y, t, lon, lat)."""
        return self._core.path()

    @property
    def track(self) -> Dict[str, np.ndarray]:
        """The flown track of a route of held headings (empty arrays for straight legs)."""
        return self._core.track()

    @property
    def summary(self) -> Dict[str, Any]:
        """summary.json as a dict."""
        return json.loads(self._core.summary_json())

    @property
    def geojson(self) -> Dict[str, Any]:
        """path.geojson as a dict (a FeatureCollection)."""
        return json.loads(self._core.route_geojson())

    @property
    def isochrones(self) -> Optional[List[Dict[str, Any]]]:
        """Where the glider can be by a few times after the departure (``plan(isochrones=True)``): a list of
        {time, time_iso, lines, lonlat}, each line an (n, 2) array; None when not computed."""
        return self._core.isochrones()

    @property
    def arrival_time(self) -> Optional[Dict[str, np.ndarray]]:
        """The level set's first-arrival time field behind the isochrones: {x, y, arrival} with arrival[j, i] the
        time at (x[i], y[j]) (inf where the front never came); None when isochrones were not computed."""
        return self._core.arrival_field()

    @property
    def reachability(self) -> Optional[Dict[str, Any]]:
        """The probability of reach over the ensemble's members (``plan(reachability=True)``, the mission's
        ``reachability`` section): x, y (the grid's nodes, planning frame) and lon, lat ((ny, nx) arrays where the
        mission is geographic, else None); times (absolute, the frames) and time_iso; probability, an array
        [frame, y, x] of p in [0, 1]; member_arrival [member, y, x], each member's first arrival (inf: not by the
        horizon); weights; goal_times and goal_travel_times per member (inf: not by the horizon); goal_probability;
        quantiles {q: travel time or None when not reached by the horizon} (quantile_arrivals, quantile_iso the same
        as absolute times and dates); levels and contours [{time, time_iso, level, lines}]; horizon, resolution,
        members, stopped, seconds. None when not computed."""
        return self._core.reachability()

    @property
    def reachability_geojson(self) -> Optional[Dict[str, Any]]:
        """reachability.geojson as a dict (one Feature per frame and level); None when not computed."""
        return json.loads(self._core.reachability_geojson()) if self._core.reachability() is not None else None

    @property
    def execution(self) -> Optional[Dict[str, List[Any]]]:
        """execution.csv (the plan flown in the truth ocean, one row per run and strategy) as columns; None
        without an execution section."""
        text = self._core.execution_csv()
        if not text:
            return None
        rows = list(csv.DictReader(io.StringIO(text)))
        return {key: [_number(row[key]) for row in rows] for key in (rows[0].keys() if rows else [])}

    @property
    def ensemble(self) -> Optional[Dict[str, Any]]:
        """How the robust plan fares over an ensemble's members; None for a single current."""
        return self._core.ensemble()

    @property
    def speed_sweep(self) -> Dict[str, np.ndarray]:
        """The speed sweep (``plan(speeds=[...])``): speed, travel_time, path_length."""
        return self._core.speed_sweep()

    @property
    def polygons(self) -> List[Dict[str, Any]]:
        """The forbidden regions in the planning frame: {name, kind, points}."""
        return self._core.polygons()

    def current_grid(self, n: int = 25, t: Optional[float] = None) -> Dict[str, Any]:
        """The current on an n x n grid over the planning box at time t (default: the departure), for maps:
        x, y, u, v, lon, lat as (n, n) arrays."""
        return self._core.current_grid(n, float("nan") if t is None else float(t))

    def report(self) -> str:
        """The command line's report (what glider_plan prints)."""
        return self._core.report()

    def write(self, out_dir: Union[str, os.PathLike]) -> List[str]:
        """Writes the command line's files (summary.json and the mission's output formats) into out_dir, all or
        nothing; returns the paths written."""
        if not isinstance(out_dir, (str, os.PathLike)) or os.fspath(out_dir) == "":
            raise _bad("Result.write(): out_dir", out_dir, "the path of an output directory")
        return list(self._core.write(os.fspath(out_dir)))

    def __getattr__(self, name: str) -> Any:  # the rest of the C++ result: path_length, box, start, goal, ...
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self._core, name)


def _number(text: str) -> Any:
    try:
        return float(text) if text != "" else float("nan")
    except ValueError:
        return text


def _json_default(value: Any) -> Any:
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"mission dict: {type(value).__name__} is not a mission value")


def _forbidden(items: Optional[Sequence[Any]]) -> Optional[List[Dict[str, Any]]]:
    if items is None:
        return None
    try:
        return [dict(item) if isinstance(item, dict) else {"points": [tuple(p) for p in item]} for item in items]
    except TypeError:
        raise _bad("plan(): keyword 'forbidden'", items, "a list of polygons (point lists or dicts with points)")


def _path_keyword(name: str, value: Any) -> Optional[str]:
    """A file name of keyword @p name, or an Error naming the keyword."""
    if value is None:
        return None
    if not isinstance(value, (str, os.PathLike)):
        raise _bad(f"plan(): keyword '{name}'", value, "a file name")
    if os.fspath(value) == "":  # not "none": None is
        raise _bad(f"plan(): keyword '{name}'", value, "a file name, not an empty one")
    return os.fspath(value)


def _list_keyword(name: str, value: Any, expected: str) -> Optional[List[Any]]:
    """The items of keyword @p name as a list, or an Error naming the keyword."""
    if value is None:
        return None
    if isinstance(value, (str, bytes, dict)) or not isinstance(value, Iterable):
        raise _bad(f"plan(): keyword '{name}'", value, expected)
    return list(value)


def _load(mission: Union[str, os.PathLike, Dict[str, Any]]) -> Any:
    """A mission file or a mission dict as the library's mission."""
    if isinstance(mission, dict):
        text = json.dumps(mission, indent=1, default=_json_default)
        return _core.parse_mission(text, "<mission dict>", os.getcwd())
    return _core.load_mission(os.fspath(mission))


def plan_fleet(mission: Union[str, os.PathLike, Dict[str, Any]], progress: Optional[ProgressCallback] = None,
               out_dir: Union[None, str, os.PathLike] = None) -> Dict[str, "Result"]:
    """Plans every glider of a mission's ``fleet`` (examples/MISSION_FORMAT.md, Fleets) and returns their results by
    name, in the fleet's order.

    The library's fleet runner plans them, as ``glider_plan --mission`` does: each glider's mission is the mission
    with its start, goal, speed and departure, planned by the same pipeline as :func:`plan`, the gliders in
    parallel; a glider without a path has ``solved`` False. With ``out_dir``, the command line's fleet files are
    written there (a folder per glider, ``fleet.csv``, ``summary.json``; all or nothing). Raises :class:`Error` for a
    mission without a fleet, and for bad input (naming the glider's fleet entry).
    """
    spec = _load(mission)
    if spec.fleet_size == 0:
        raise Error("plan_fleet(): the mission has no fleet (a 'fleet:' list of gliders); use plan()")
    if out_dir is not None and (not isinstance(out_dir, (str, os.PathLike)) or os.fspath(out_dir) == ""):
        raise _bad("plan_fleet(): out_dir", out_dir, "the path of an output directory")
    gliders, _ = _core.run_fleet(spec, progress, "" if out_dir is None else os.fspath(out_dir))
    return {name: Result(core) for name, core in gliders}


def plan(mission: Union[None, str, os.PathLike, Dict[str, Any]] = None, *, field: Optional[Field] = None,
         start: Optional[Pair] = None, goal: Optional[Pair] = None, speed: Optional[float] = None,
         departure: Union[None, float, str] = None, region: Optional[Tuple[float, float, float, float]] = None,
         forbidden: Optional[Sequence[Any]] = None, planner: Optional[str] = None,
         planner_params: Optional[Dict[str, Any]] = None, grid_size: Optional[float] = None,
         sectors: Optional[int] = None, time_limit: Optional[float] = None, smoothing: Optional[bool] = None,
         refinement: Optional[bool] = None, global_check: Optional[bool] = None, horizon: Optional[float] = None,
         goal_tolerance: Optional[float] = None, isochrones: bool = False,
         isochrone_interval: Union[None, float, str] = None, arrive_between: Optional[Tuple[Any, Any]] = None,
         coastline: Union[None, str, os.PathLike] = None, goto_turn: Optional[float] = None,
         hold_tolerance: Union[None, float, str] = None, via: Optional[Sequence[Any]] = None, order: Optional[str] = None,
         observations: Union[None, str, os.PathLike] = None,
         observations_cache: Union[None, str, os.PathLike] = None,
         correction_length: Union[None, float, str] = None, correction_time: Union[None, float, str] = None,
         error_ratio: Optional[float] = None, learn: Optional[bool] = None,
         keep_off: Union[None, float, str] = None, min_depth: Union[None, float, str] = None,
         bathymetry: Union[None, str, os.PathLike] = None, bathymetry_variable: Optional[str] = None,
         snap_to_water: Optional[bool] = None,
         truth: Union[None, str, Sequence[str], Dict[str, float]] = None,
         surfacing_interval: Union[None, float, str] = None, strategies: Optional[Sequence[str]] = None,
         radius: Optional[float] = None, execution_pairs: Optional[int] = None, execution_seed: Optional[int] = None,
         across_runs: Optional[str] = None,
         reachability: bool = False, reach_horizon: Union[None, float, str] = None,
         reach_interval: Union[None, float, str] = None, reach_resolution: Union[None, float, str] = None,
         speeds: Optional[Sequence[float]] = None,
         optimum: bool = False, progress: Optional[ProgressCallback] = None) -> Result:
    """Plans a mission with the library's one pipeline and returns its :class:`Result`.

    mission: a YAML mission file, a mission as a dict (the keys of the mission format, examples/MISSION_FORMAT.md;
    relative paths are resolved against the working directory), or None: the built-in Gulf Stream mission (as
    ``glider_plan`` without arguments), or the mission of ``field``.
    field: a :class:`Field` instead of a mission: a gridded forecast of any gridded source (NetCDF, OPeNDAP, Zarr,
    GRIB, a registered one; needs start and goal as lon, lat) or arrays (as ``glider_plan --currents``), or an
    analytic flow (the built-in mission on that flow).
    The keywords change the mission as glider_plan's flags do: start, goal ((x, y) or (lon, lat) as the mission
    gives them), speed, departure (a number in the mission's time unit or an ISO 8601 date), region ((x_min, y_min,
    x_max, y_max), or lon/lat in that order), forbidden (polygons, each a list of points or a dict with points,
    name, kind, and windows for a time-windowed zone or max_submerged_time, t_ref, drift for an ice zone),
    planner (a registry name, :func:`planner_names`) and planner_params (its OMPL parameters by name), grid_size,
    sectors, time_limit (s), smoothing, refinement, global_check (False: no global check of the route class,
    docs/TRUST.md), horizon, goal_tolerance, arrive_between ((begin, end): the goal's arrival window, times as
    departure), coastline (a GIS file of land), goto_turn (the goto list's turn threshold, degrees), hold_tolerance (the uploads' merged holds:
    metres or "0.5 km"), via (via points
    between start and goal, a mission of several legs: each a pair (x, y) / (lon, lat), or a dict with ``at`` (the
    pair), ``name``, ``radius``, ``stay`` (the mission's units) and ``arrive`` ((begin, end), times as departure)),
    order ("given" or "free": the fastest order of up to 8 via points), observations_cache (the folder of a Slocum's
    cache files for binary observations), observations (the glider's depth-averaged
    currents: IOOS glider profile files or Slocum dba files, a folder or glob of them, a CSV time,lon,lat,u,v, or an
    ERDDAP tabledap URL (.csvp, .csv, .ncCF): the forecast is corrected by them and, without start, the plan starts at the last fix, at its time without departure); correction_length ("20 km"), correction_time
    ("1 d"), error_ratio and learn (False: the values and defaults as they are) set the correction by the DAC
    (observations.length_scale, time_scale, error_ratio, learn; a scale not given is learned from the DAC, and an
    ensemble's members are weighed by them: :meth:`Result.correction`); isochrones /
    isochrone_interval (a number in the mission's time unit, or a duration such as "6 h") add the reachable-set
    contours (:attr:`Result.isochrones`); speeds a speed sweep; optimum the optimal-control reference.
    Safety: keep_off (the distance kept from land: a number in the mission's length unit, or "2 km"), min_depth (the
    shallowest water allowed: metres, or "50 m"; needs bathymetry or a forecast with the seafloor depth), bathymetry (a
    NetCDF file of seafloor depth or elevation) and bathymetry_variable (its variable), snap_to_water (a start or
    goal on the forecast's land moved to the nearest water). Execution in another ocean (docs/EXECUTION.md; any of
    these flies the plan): truth ("forecast", another forecast's files, or {parameter: value} of the analytic flow),
    surfacing_interval (a number in the mission's time unit, or "1 h"), strategies (names), radius (the goal radius),
    execution_pairs and execution_seed (random start/goal pairs, :attr:`Result.execution`), across_runs ('carry' or
    'reset': with forecast runs, the DAC replan_observed learned before a new run kept or dropped). The probability of
    reach over the ensemble's members (:attr:`Result.reachability`, docs/REACHABILITY.md): reachability, and
    reach_horizon, reach_interval (durations: a number in the mission's time unit, or "10 d") and reach_resolution (the
    level set's cell: a number in the length unit, or "2 km"), each of which also asks for it. These
    keywords and glider_plan's flags are one set of overrides in the library (Overrides.h): the same values give
    the same mission (``Mission.fields()``, ``glider_plan --show-mission``). progress(line, done) receives the progress lines of long runs (the GIL is released while planning).

    Raises :class:`Error` with glider_plan's message for bad input (exit status 2 there); a problem without a
    path returns a result with ``solved`` False (exit status 1 there).
    """
    keywords = dict(start=start, goal=goal, speed=speed, departure=departure, region=region,
                    forbidden=_forbidden(forbidden), planner=planner, grid_size=grid_size, sectors=sectors,
                    time_limit=time_limit, smoothing=smoothing, refinement=refinement,
                    global_check=global_check, horizon=horizon, goal_tolerance=goal_tolerance, isochrones=isochrones,
                    isochrone_interval=isochrone_interval, arrive_between=arrive_between,
                    coastline=_path_keyword("coastline", coastline), goto_turn=goto_turn,
                    hold_tolerance=hold_tolerance, via=_list_keyword("via", via, "a list of via points"), order=order,
                    observations=_path_keyword("observations", observations),
                    observations_cache=_path_keyword("observations_cache", observations_cache),
                    correction_length=correction_length, correction_time=correction_time, error_ratio=error_ratio,
                    learn=learn,
                    keep_off=keep_off, min_depth=min_depth,
                    bathymetry=os.fspath(bathymetry) if isinstance(bathymetry, os.PathLike) else bathymetry,
                    bathymetry_variable=bathymetry_variable, snap_to_water=snap_to_water,
                    truth=[os.fspath(t) for t in truth] if isinstance(truth, (list, tuple)) else truth,
                    surfacing_interval=surfacing_interval,
                    strategies=_list_keyword("strategies", strategies, "a list of strategy names"), radius=radius,
                    execution_pairs=execution_pairs, execution_seed=execution_seed, across_runs=across_runs,
                    reachability=reachability, reach_horizon=reach_horizon, reach_interval=reach_interval,
                    reach_resolution=reach_resolution)
    if planner_params is not None and not isinstance(planner_params, dict):
        raise _bad("plan(): keyword 'planner_params'", planner_params, "a dict of parameter names to values")
    if not isinstance(optimum, (bool, np.bool_)):
        raise _bad("plan(): keyword 'optimum'", optimum, "True or False")
    if planner_params is not None:
        keywords["planner_params"] = {k: (str(v).lower() if isinstance(v, bool) else str(v))
                                      for k, v in planner_params.items()}
    if field is not None and mission is not None:
        raise TypeError("plan(): give a mission or a field, not both")
    gridded = field is not None and _is_gridded(field)
    if field is not None and not gridded and field.kind != "analytic":
        raise _bad("plan(): keyword 'field'", field, "a Field of a gridded source (Field.gridded(), Field.netcdf(), "
                   "Field.from_arrays()) or an analytic flow (Field.analytic())")
    if gridded:
        # without a start: the glider's last fix (and its time), read by the library (forecastMission())
        if (start is None and observations is None) or goal is None:
            raise TypeError("plan(): a gridded field needs start and goal (lon, lat, or x, y on a Cartesian grid)")
        s = field.settings
        if region is not None:
            try:
                region = tuple(_real("plan(): keyword 'region'", c) for c in region)
            except TypeError:
                raise _bad("plan(): keyword 'region'", region, "four numbers (lon_min, lat_min, lon_max, lat_max)")
            if len(region) != 4:
                raise _bad("plan(): keyword 'region'", region, "four numbers (lon_min, lat_min, lon_max, lat_max)")
        spec = _core.forecast_mission(s["files"], None if start is None else _pair("plan(): keyword 'start'", start),
                                      _pair("plan(): keyword 'goal'", goal),
                                      "" if departure is None else str(departure),
                                      None if speed is None else _real("plan(): keyword 'speed'", speed), s["depth"],
                                      region, s["variables"],
                                      s["xy_interpolation"], s["depth_interpolation"], s["time_interpolation"],
                                      s["horizon"], s["velocity_units"], s["time_units"], s["steady_record"],
                                      s["zero_velocity_land"], s["depth_average"], bool(snap_to_water),
                                      "" if observations is None else os.fspath(observations), field.kind,
                                      "" if observations_cache is None else os.fspath(observations_cache),
                                      s.get("max_speed", ""), s.get("runs", False), s.get("run_delay", ""))
        for used in ("start", "goal", "departure", "speed", "region"):
            keywords.pop(used)
    elif field is not None:
        spec = _core.builtin_mission()
        keywords["analytic"] = (field.settings["name"], field.settings["parameters"])
    elif mission is None:
        spec = _core.builtin_mission()
    else:
        spec = _load(mission)
    spec = spec.with_keywords(**keywords)
    if speeds is not None:
        try:
            speeds = [_real("plan(): keyword 'speeds'", v) for v in speeds]
        except TypeError:
            raise _bad("plan(): keyword 'speeds'", speeds, "a list of numbers") from None
    core = _core.run(spec, progress, speeds, optimum)
    return Result(core)
