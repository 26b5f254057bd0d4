"""The kinematic scheme and the velocity plans of any linkage file, read from its structure."""

import json
import pathlib

import numpy as np
import pytest
from figure_checks import assert_fits_and_labels_apart
from test_sheets_kinematics import _check_plan

from graphmethods.errors import InputError
from graphmethods.kinematics import read_case
from graphmethods.render.recording import record
from graphmethods.sheets import kinematics as ks

DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
FILES = sorted(p.name for p in DATA.glob("*.json") if json.loads(p.read_text()).get("kind") == "linkage")


_TRIAD_TABLE = pytest.mark.xfail(strict=True, raises=InputError, reason=(
    "triad_six_bar.json: the velocity table of a class III six-bar (9 points, 5 links) is 357 mm wide, "
    "the A4 sheet leaves 267 mm (as in test_every_sheet_layout's KNOWN)"))


@pytest.mark.parametrize("name", [pytest.param(n, marks=_TRIAD_TABLE) if n == "triad_six_bar.json" else n
                                  for n in FILES])
@pytest.mark.parametrize("lang", ["en", "zh"])
def test_figures_of_linkage_files_fit_and_plans_are_to_scale(name, lang):
    case = read_case(DATA / name)
    plans = case.mechanism.velocity_plans(12, omega_1=case.omega_m)
    for fid, scene in (("grid", ks.velocity_plan_grid(case, notation=lang)),
                       ("plan", ks.velocity_plan(case, position=3, notation=lang)),
                       ("table", ks.velocity_table(case, notation=lang))):
        assert_fits_and_labels_apart(scene, f"{name}-{fid}-{lang}")
    grid = ks.velocity_plan_grid(case)
    (mu_v,) = grid.scales()
    rec = record(grid)
    assert sum(_check_plan(rec, plans, k, mu_v.per_mm, f"plan-{k}-") for k in range(12)) > 12
    # the plans are the core's velocities, and the fixed joints come from the file, not from names
    mo = case.linkage.motion(m=12, omega_1=case.omega_m)
    for p in plans.vectors:
        assert np.abs(plans.v(p) - mo.v(p)).max() <= 1e-12 * max(1.0, np.abs(mo.v(p)).max())
    assert case.mechanism.fixed_joints == tuple(json.loads((DATA / name).read_text())["fixed"])


@pytest.mark.parametrize("name", FILES)
def test_schemes_of_linkage_files_fit(name):
    """Every scheme fits and its labels keep apart, the slotting machine's vertical ram included."""
    case = read_case(DATA / name)
    assert_fits_and_labels_apart(ks.kinematic_scheme(case, notation="en"), f"{name}-scheme")


@pytest.mark.parametrize("angle_deg", [90.0, 60.0, -30.0])
def test_stroke_of_a_guide_at_an_angle_is_dimensioned_along_it(angle_deg):
    """A ram on a guide at any angle: its stroke H is dimensioned parallel to the guide, to scale
    (drawn length × μ_l = H), beyond the position numbers, which sit on the free side of the guide."""
    import math

    from graphmethods.kinematics import LinkageMechanism
    from graphmethods.kinematics.presets import six_bar_press

    a = math.radians(angle_deg)
    lk = six_bar_press(guide_angle=a, guide_through=(0.25 + 0.3 * math.cos(a + 0.6), 0.1 + 0.3 * math.sin(a + 0.6)),
                       l_CD=0.2)
    mech = LinkageMechanism(lk)
    pos = mech.positions(12)
    scene = ks.kinematic_scheme(mech)
    assert_fits_and_labels_apart(scene, f"ram-{angle_deg}")
    dim = next(e for e in scene.elements if getattr(e, "name", "") == "dimension-H")
    (mu_l,) = scene.scales()
    d = np.subtract(dim.end, dim.start)
    assert abs(float(np.hypot(*d)) * mu_l.per_mm - pos.H) <= 1e-9 * pos.H
    g = np.array(lk.guides["D"])
    assert abs(abs(float(d @ np.array([g[0], -g[1]]))) / float(np.hypot(*d)) - 1.0) <= 1e-9   # parallel on paper
    rec = record(scene)
    assert [i for i in rec.group_ids() if i.startswith("number-out-")]
