"""The force sheet's panels: μ_l and μ_F chosen together (convenient, the drawing and its arrows inside the
box), forces too short to draw at μ_F drawn at the least arrow, the lever's arms, and what each panel holds
for the composer (force_panels.panel_content)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from graphmethods.errors import InputError
from graphmethods.problems import builtin
from graphmethods.scene import Page, Scale, Vector, notation
from graphmethods.scene.scale import SERIES
from graphmethods.sheets.composition import region_page
from graphmethods.sheets.engine.lettering import lettered
from graphmethods.sheets.force_fit import LEAST_ARROW_MM, TOO_SHORT_MM, arm_lines, drawn_tip, fit_forces
from graphmethods.sheets.force_panels import KINDS, panel_content
from graphmethods.sheets.force_sheet_plans import group_panel
from graphmethods.sheets.forces import analysed, force_scheme, zhukovsky_forces

EN = notation("en")


def _convenient(v: float) -> bool:
    k = math.floor(math.log10(v) + 1e-12)
    return any(math.isclose(v, m * 10.0 ** k, rel_tol=1e-9) for m in SERIES)


def _walk(elements):
    for e in elements:
        yield e
        yield from _walk(getattr(e, "elements", ()) or ())


points = st.lists(st.complex_numbers(max_magnitude=2.0, allow_nan=False, allow_infinity=False), min_size=2,
                  max_size=6).filter(lambda z: max(np.ptp(np.real(z)), np.ptp(np.imag(z))) > 1e-3)


@settings(max_examples=40, deadline=None)
@given(points, st.lists(st.complex_numbers(min_magnitude=1.0, max_magnitude=1e4, allow_nan=False,
                                           allow_infinity=False), min_size=1, max_size=4),
       st.floats(80.0, 400.0), st.floats(80.0, 400.0))
def test_both_scales_are_convenient_and_the_drawing_with_its_arrows_lies_in_the_area(z, forces, w, h):
    area = (10.0, 20.0, 10.0 + w, 20.0 + h)
    arrows = [(z[k % len(z)], F) for k, F in enumerate(forces)]
    s_l, s_F, at = fit_forces(z, arrows, area, EN, pad_mm=10.0)
    assert _convenient(s_l.per_mm) and _convenient(s_F.per_mm)
    ends = [at(p) for p in z] + [drawn_tip(at(p), F, s_F)[0] for p, F in arrows]
    for x, y in ends:
        assert area[0] + 10.0 - 1e-6 <= x <= area[2] - 10.0 + 1e-6
        assert area[1] + 10.0 - 1e-6 <= y <= area[3] - 10.0 + 1e-6
    assert max(abs(F) for F in forces) / s_F.per_mm <= max(w, h)          # the largest force fits the area


def test_the_largest_force_is_drawn_long_beside_the_drawing():
    s_l, s_F, _ = fit_forces([0j, 0.3j, 0.2 + 0.3j], [(0.2 + 0.3j, 7000 + 0j), (0.1j, 12 + 0j)],
                             (0.0, 0.0, 300.0, 400.0), EN)
    length = 7000 / s_F.per_mm
    assert length >= 20.0 and length <= 0.6 * 0.3 / s_l.per_mm + 1e-9


def test_no_force_is_an_input_error():
    with pytest.raises(InputError, match="no force"):
        fit_forces([0j, 1j], [(0j, 0j)], (0.0, 0.0, 100.0, 100.0), EN)


def test_a_force_too_short_for_its_scale_is_drawn_at_the_least_arrow_along_its_direction():
    s = Scale("μ_F", "N", 100.0)
    (tip, to_scale) = drawn_tip((5.0, 5.0), 50.0 - 50.0j, s)         # 0.7 mm at 100 N/mm
    assert not to_scale and math.isclose(math.dist((5.0, 5.0), tip), LEAST_ARROW_MM)
    assert tip[0] > 5.0 and tip[1] > 5.0                                # right and down the page (F_y < 0)
    tip, to_scale = drawn_tip((0.0, 0.0), 1000.0 + 0j, s)
    assert to_scale and tip == (10.0, 0.0) and 10.0 >= TOO_SHORT_MM


@settings(max_examples=60, deadline=None)
@given(*(st.tuples(st.floats(-100, 100), st.floats(-100, 100)) for _ in range(3)))
def test_an_arm_is_perpendicular_to_the_force_and_ends_on_its_line(pole, a, b):
    lines = arm_lines(pole, a, b)
    if not lines:
        return
    (p, foot) = lines[0]
    d = np.subtract(b, a)
    assert p == pole
    assert abs(np.dot(np.subtract(foot, pole), d)) <= 1e-6 * (1 + np.hypot(*d) * np.hypot(*np.subtract(foot, pole)))
    u = np.subtract(foot, a)
    assert abs(u[0] * d[1] - u[1] * d[0]) <= 1e-6 * (1 + np.hypot(*d) * np.hypot(*u))


@pytest.mark.parametrize("name", ["shaper", "press", "six-bar-press", "scotch-yoke"])
def test_on_a1_every_force_of_the_scheme_and_the_lever_is_an_arrow_none_too_short_to_see(name):
    case = builtin.case(name)
    pg = region_page(Page("A1", "landscape", frame=True), (30.0, 30.0, 330.0, 450.0))
    with lettered("A1"):
        scheme = force_scheme(case, 3, page=pg, title_block=False)
        lever = zhukovsky_forces(case, 3, page=pg, title_block=False)
    fa, i = analysed(case, position=3, phi_deg=None, m=12)
    n_forces = sum(1 for fs in fa.applied.values() for f in fs if abs(f.F[i]) > 0)
    arrows = [e for e in _walk(scheme.elements) if isinstance(e, Vector) and e.name.startswith("force-")]
    assert len(arrows) == n_forces
    assert all(math.dist(v.start, v.end) >= TOO_SHORT_MM - 1e-9 for v in arrows)
    assert all(math.dist(v.start, v.end) >= TOO_SHORT_MM - 1e-9
               for v in _walk(lever.elements) if isinstance(v, Vector))


def test_the_group_s_drawing_and_forces_fill_its_box():
    case = builtin.case("shaper")
    fa, i = analysed(case, position=3, phi_deg=None, m=12)
    box = (100.0, 100.0, 300.0, 260.0)
    with lettered("A1"):
        s = group_panel(case, fa, i, 0, page=region_page(Page("A1", "landscape", frame=True), box))
    ink = np.asarray([e.bbox() for e in s.elements if e.bbox() is not None and e.name.startswith(("link", "force",
                                                                                                   "reaction"))])
    w, h = ink[:, 2].max() - ink[:, 0].min(), ink[:, 3].max() - ink[:, 1].min()
    assert max(w / (box[2] - box[0]), h / (box[3] - box[1])) > 0.45    # not a small drawing in a big box
    assert ink[:, 0].min() >= box[0] - 1e-6 and ink[:, 2].max() <= box[2] + 1e-6


@pytest.mark.parametrize("kind", KINDS)
def test_panel_content_states_points_and_text_without_drawing(kind):
    fa, i = analysed(builtin.case("shaper"), position=3, phi_deg=None, m=12)
    c = panel_content(fa, i, kind, 1, nt="ru", page="A1")
    assert c.unit == ("Н" if kind == "plan" else "м")
    assert len(c.points) >= 2 and all(np.isfinite(complex(p)) for p in c.points)
    x0, y0, x1, y1 = c.extent
    w1, h1 = c.size_mm(max(x1 - x0, y1 - y0) / 100.0)                    # the drawing 100 mm at its largest
    assert 100.0 <= max(w1, h1) and c.text_mm[1] > 0.0
    w2, h2 = c.size_mm(max(x1 - x0, y1 - y0) / 50.0)
    assert w2 <= w1 and h2 <= h1


def test_panel_content_refuses_an_unknown_kind_or_plan():
    fa, i = analysed(builtin.case("press"), position=3, phi_deg=None, m=12)
    with pytest.raises(InputError, match="kind"):
        panel_content(fa, i, "table", 0)
    with pytest.raises(InputError, match="plan 5"):
        panel_content(fa, i, "plan", 5)
