"""The correction of the forecast by the glider's DAC from Python: the keywords set what a mission file's
observations section sets, a scale given is kept and the others are learned from the DAC, Result.correction() says
where each came from and agrees with summary.json; bad values are refused naming the keyword."""
import os

import pytest

import ompl_glider
from conftest import EXAMPLES

SURVEY = os.path.join(EXAMPLES, "survey_labrador.yaml")
DEPLOYMENT = os.path.join(EXAMPLES, "deployment_ru29")


def test_learned_by_default_and_reported_as_in_summary_json():
    r = ompl_glider.plan(SURVEY, observations=DEPLOYMENT)
    assert r.solved
    c = r.correction()
    learned = r.summary["observations"]["learned"]
    assert c["used"] == r.summary["observations"]["used"] >= 6
    assert c["dac_estimated_from"] == learned["dac_estimated_from"] == c["used"]
    for key in ("length_scale", "time_scale", "error_ratio"):
        assert c[key + "_source"] == learned[key + "_source"] == "estimated from %d DAC" % c["used"]
        assert c[key] == r.summary["observations"][key]
    assert c["log_likelihood_gain"] >= 0.0
    assert c["bias"] is not None and learned["bias"]["u"] == c["bias"][0]
    assert len(c["member_weights"]) == 0  # one forecast, no ensemble


def test_a_scale_given_as_a_keyword_is_kept_and_learn_false_keeps_the_defaults():
    r = ompl_glider.plan(SURVEY, observations=DEPLOYMENT, correction_length="30 km", error_ratio=0.4)
    c = r.correction()
    assert c["length_scale"] == 30000.0 and c["length_scale_source"] == "given"
    assert c["error_ratio"] == 0.4 and c["error_ratio_source"] == "given"
    assert c["time_scale_source"].startswith("estimated from")
    fixed = ompl_glider.plan(SURVEY, observations=DEPLOYMENT, correction_time="3 h", learn=False).correction()
    assert fixed["time_scale"] == 10800.0 and fixed["time_scale_source"] == "given"
    assert fixed["length_scale"] == 20000.0 and fixed["length_scale_source"] == "default"
    assert fixed["dac_estimated_from"] == 0 and fixed["bias"] is None


def test_no_observations_no_correction():
    assert ompl_glider.plan(SURVEY).correction() is None


@pytest.mark.parametrize("keywords, name", [({"error_ratio": 0}, "error_ratio"),
                                            ({"correction_time": "3 parsecs"}, "correction_time"),
                                            ({"correction_length": -5}, "correction_length"),
                                            ({"learn": "yes"}, "learn")])
def test_bad_correction_keywords_name_the_keyword(keywords, name):
    with pytest.raises(ompl_glider.Error, match=name):
        ompl_glider.plan(SURVEY, observations=DEPLOYMENT, **keywords)
