"""Motion from the dense solution: extremes of ω on roots of ε, --J-F as given, --until-steady explained."""

import json
import math

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.dynamics.motion import ReducedModel
from graphmethods.dynamics.regimes import run


def _json(capsys, *argv):
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


def test_W4_omega_max_is_the_true_maximum_at_a_quarter_turn(capsys):
    s = _json(capsys, "motion", "W4-exact", "--omega0", "10", "--turns", "1", "--json")["summary"]
    # issue 28: the true maximum is 11.80127 at φ = π/2; the step values gave 11.79948
    assert s["omega_max_run"] == pytest.approx(11.80127, abs=1e-5)
    assert s["phi_omega_max_run_deg"] == pytest.approx(90.0, abs=1e-6)
    assert s["error_extremes_omega"] < 1e-6
    # the dense maximum is never below the largest step value
    r = _json(capsys, "motion", "W4-exact", "--omega0", "10", "--turns", "1", "--json")
    assert s["omega_max_run"] >= max(r["omega"]) - 1e-12


def test_dense_extremes_against_a_closed_form():
    # J = 1, M = cos φ from ω0 = 1: ½ω² = ½ + sin φ, so ω_max = √3 at π/2 and ω_min = 1 at 0 and 2π
    r = run(ReducedModel(J_e=1.0, M_e=lambda p: np.cos(p)), omega_0=1.0, turns=1)
    ex = r.extremes()
    assert ex["omega_max_run"] == pytest.approx(math.sqrt(3.0), abs=1e-9)
    assert ex["phi_omega_max_run_deg"] == pytest.approx(90.0, abs=1e-5)
    # ε = cos φ: its extremes are +1 at the ends and −1 at π, found between the steps
    assert ex["epsilon_min_run"] == pytest.approx(-1.0, abs=1e-9)
    assert ex["epsilon_max_run"] == pytest.approx(1.0, abs=1e-9)
    assert abs(ex["omega_max_run"] - math.sqrt(3.0)) <= ex["error_extremes_omega"] + 1e-12


def test_J_F_given_is_used_as_given(capsys):
    s = _json(capsys, "motion", "four-bar", "--J-F", "0.5", "--turns", "1", "--json")["summary"]
    assert s["J_F"] == 0.5


def test_J_F_negative_is_refused(capsys):
    assert main(["motion", "press", "--J-F", "-1", "--turns", "1"]) == 2
    assert "--J-F" in capsys.readouterr().err


def test_until_steady_from_rest_without_a_motor_says_what_it_needs(capsys):
    assert main(["motion", "press", "--until-steady"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--motor" in err and "from rest" in err


def test_until_steady_that_stops_says_why(capsys):
    assert main(["motion", "press", "--omega0", "5", "--until-steady"]) == 2
    err = capsys.readouterr().err
    assert "stopped" in err and "--motor" in err
