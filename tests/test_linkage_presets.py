"""The four classic kinds as presets on the core: every result equal to the classes' within 1e-12."""

import json
import pathlib

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from test_kinematics import four_bars, shapers, slider_cranks, slotted_levers

from graphmethods.kinematics import presets, read_case

PRESS = pathlib.Path(__file__).parents[2] / "shared" / "cases" / "slider_crank_press.json"
if not PRESS.exists():
    PRESS = pathlib.Path("/work/shared/cases/slider_crank_press.json")

#: old canonical link name -> core link number, per class
NUMBERS = {"SliderCrank": {"OA": "1", "AB": "2"}, "FourBar": {"O1A": "1", "AB": "2", "O2B": "3"},
           "SlottedLever": {"O1A": "1", "block": "2", "O3B": "3"},
           "Shaper": {"O1A": "1", "block": "2", "O3B": "3", "BC": "4"}}


def assert_same(mech, m=None, phi=None, omega_1=2.5, rel=1e-12):
    lk = presets.from_mechanism(mech)
    old_st, new_st = mech.strokes(), lk.strokes()
    if old_st is not None and abs(old_st.K - 1.0) > 1e-9:
        assert abs(old_st.phi_start - new_st.phi_start) <= 1e-12
        assert abs(old_st.phi_end - new_st.phi_end) <= 1e-12
        assert abs(old_st.K - new_st.K) <= 1e-12 * old_st.K
    if m is not None and old_st is not None and abs(old_st.K - 1.0) <= 1e-9:
        m, phi = None, np.linspace(0, 2 * np.pi, 13)     # equal strokes: compare at angles, not numbering
    pos = mech.positions(m=m) if m is not None else mech.positions(phi=phi)
    plan = mech.velocity_plans(pos, omega_1=omega_1, sin_threshold=0.0)
    mo = lk.motion(m=m, omega_1=omega_1) if m is not None else lk.motion(phi=phi, omega_1=omega_1)
    assert np.abs(pos.phi - mo.phi).max() <= 1e-12
    L = max(np.abs(pos.coords[k]).max() for k in pos.coords)
    V = max(np.abs(plan.vectors[k]).max() for k in plan.vectors)
    for name in pos.coords:
        assert np.abs(pos.xy(name) - mo.xy(name)).max() <= rel * L, name
        assert np.abs(plan.v(name) - mo.v(name)).max() <= rel * V, name
    W = max(np.abs(w).max() for w in plan.omegas.values())
    for canon, num in NUMBERS[type(mech).__name__].items():
        assert np.abs(plan.omegas[canon] - mo.omega[num]).max() <= rel * W, canon
    if m is not None and pos.s is not None and mo.s is not None:
        assert np.abs(pos.s - mo.s).max() <= rel * L
        assert abs(pos.H - lk.stroke_H()) <= rel * L
    if m is not None and pos.psi is not None and mo.psi is not None:
        assert np.abs(pos.psi - mo.psi).max() <= 1e-12
        assert abs(pos.psi_max - lk.psi_max()) <= 1e-12


@settings(deadline=None, max_examples=30)
@given(mech=st.one_of(slider_cranks(), four_bars(), slotted_levers(), shapers()), m=st.integers(3, 48))
def test_presets_equal_the_classes(mech, m):
    assert_same(mech, m=m)


@pytest.mark.parametrize("kind", ["slider_crank", "four_bar", "slotted_lever", "shaper"])
def test_built_in_problem_files_equal_on_the_core(kind):
    from graphmethods.problems import reference_cases  # noqa: F401 - the data folder
    data = pathlib.Path(__file__).parents[1] / "graphmethods" / "problems" / "data"
    files = {"slider_crank": "slider_crank_press.json"}
    path = data / files.get(kind, f"{kind}.json")
    if not path.exists():
        cands = [p for p in data.glob("*.json") if json.loads(p.read_text()).get("kind", "slider_crank") == kind]
        assert cands, f"no built-in problem of kind {kind}"
        path = cands[0]
    case = read_case(path)
    assert_same(case.mechanism, m=12, omega_1=case.omega_m)
    assert_same(case.mechanism, m=360, omega_1=case.omega_m)


def test_the_shared_press_file_is_read_as_it_is():
    case = read_case(PRESS)
    lk = presets.from_mechanism(case.mechanism)
    mo = lk.motion(m=12, omega_1=case.omega_m)
    r, l = case.r, case.l
    assert abs(float(np.hypot(*mo.xy("B")[0])) - (r + l)) <= 1e-12     # position 0: the far dead centre
    assert_same(case.mechanism, m=12, omega_1=case.omega_m)
