"""The gridded current kind from Python: Field.gridded() (kind ``gridded``) and Field.netcdf() (its alias
``netcdf``) plan the same route to the bit, and plan() takes any kind the registry reads as gridded
(is_gridded_kind()), not one spelling."""
import os

import numpy as np
import pytest

import ompl_glider
from ompl_glider import _core
from conftest import EXAMPLES

NC = os.path.join(EXAMPLES, "labrador_forecast.nc")
TRIP = dict(start=(-52.7, 47.9), goal=(-51.5, 48.45), departure="2026-03-15T06:00:00Z", grid_size=5000)


def test_the_registry_says_which_kinds_are_gridded():
    assert ompl_glider.is_gridded_kind("gridded")
    assert ompl_glider.is_gridded_kind("netcdf")  # the alias
    assert _core.is_gridded_kind("gridded")
    for name in ("meandering_jet", "uniform", "analytic", "zarr", ""):
        assert not ompl_glider.is_gridded_kind(name)


def test_gridded_and_netcdf_plan_the_same_route():
    named = ompl_glider.Field.gridded(NC)
    alias = ompl_glider.Field.netcdf(NC)
    assert named.kind == "gridded" and alias.kind == "netcdf"
    assert named.settings == alias.settings
    a = ompl_glider.plan(field=named, **TRIP)
    b = ompl_glider.plan(field=alias, **TRIP)
    assert a.solved and b.solved
    assert a.travel_time == b.travel_time
    assert np.array_equal(a.path["x"], b.path["x"]) and np.array_equal(a.path["y"], b.path["y"])
    # each result says the kind it was given (Field.netcdf() as glider_plan --currents: netcdf)
    assert a.summary["current"] == "gridded"
    assert b.summary["current"] == "netcdf"


def test_a_field_of_any_gridded_spelling_takes_the_forecast_path():
    # a Field made by hand with the alias or the name, as a registered gridded kind would be
    settings = ompl_glider.Field.netcdf(NC).settings
    for kind in ("netcdf", "gridded"):
        r = ompl_glider.plan(field=ompl_glider.Field(kind, **settings), **TRIP)
        assert r.solved and r.geographic
        assert r.summary["current"] == kind


def test_kinds_that_are_not_gridded_are_refused():
    with pytest.raises(ompl_glider.Error, match="Field.gridded\\(\\): kind: expected the name of a gridded source"):
        ompl_glider.Field.gridded(NC, kind="uniform")
    with pytest.raises(ompl_glider.Error, match="plan\\(\\): keyword 'field'"):
        ompl_glider.plan(field=ompl_glider.Field("no_such_kind", files=NC), **TRIP)
