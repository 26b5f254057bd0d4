"""The force-plans figure: every drawn side is its force over μ_F, every polygon closes on paper,
three languages, bad positions and scales refused."""

import numpy as np
import pytest

from graphmethods.dynamics.forces import case_forces
from graphmethods.errors import InputError
from graphmethods.problems import builtin
from graphmethods.scene import Vector
from graphmethods.sheets.forces import force_plans


@pytest.mark.parametrize("name, k", [("press", 3), ("shaper", 2), ("four-bar", 2), ("six-bar-press", 7)])
def test_sides_are_the_forces_to_scale_and_the_polygons_close(name, k):
    case = builtin.case(name)
    scene = force_plans(case, position=k)
    mu = scene.scales()[0].per_mm
    fa = case_forces(case, m=12)
    vecs = {e.name: e for e in scene.elements if isinstance(e, Vector)}
    for j, plan in enumerate(fa.plans):
        poly = plan.polygons[0]
        sides = [("known", s, F) for s, (_, F) in enumerate(poly.known)] + \
                [("closing", s, F) for s, (_, _, F) in enumerate(poly.closing)]
        origin = None
        walked = 0j                             # Σ of the sides so far, N
        for kind, s, F in sides:
            v = vecs.get(f"{kind}-{j}-{s}")
            if v is None:                       # too short to draw (under 0.3 mm)
                assert abs(F[k]) / mu < 0.3
            else:
                assert v.length_mm * mu == pytest.approx(abs(F[k]), rel=1e-9)
                if origin is None:
                    origin = complex(v.start[0], -v.start[1]) - walked / mu
                # head to tail: each side starts where the sides before it end
                assert complex(v.start[0], -v.start[1]) == pytest.approx(origin + walked / mu, abs=1e-9)
                assert complex(v.end[0], -v.end[1]) == pytest.approx(origin + (walked + F[k]) / mu, abs=1e-9)
            walked += complex(F[k])
        assert abs(walked) / mu <= 1e-9                  # the polygon closes


def test_three_languages_and_the_scale_is_reported():
    titles = {lang: force_plans(builtin.case("press"), position=3, notation=lang).title for lang in ("en", "ru", "zh")}
    assert titles == {"en": "Force plans, position 3", "ru": "Планы сил, положение 3", "zh": "力多边形，位置 3"}
    s = force_plans(builtin.case("press"), position=3, mu_F=100.0)
    assert s.scales()[0].per_mm == 100.0


def test_a_given_mu_F_that_does_not_fit_and_a_bad_position_are_refused():
    with pytest.raises(InputError, match="force plans"):
        force_plans(builtin.case("press"), position=3, mu_F=0.5)
    with pytest.raises(InputError, match="position 13"):
        force_plans(builtin.case("press"), position=13)
    s = force_plans(builtin.case("press"), phi_deg=100.0)
    assert "100" in s.title and np.isfinite(s.scales()[0].per_mm)


@pytest.mark.parametrize("name, k", [("press", 3), ("shaper", 2), ("four-bar", 2), ("whitworth", 5)])
def test_the_drawn_lever_is_in_equilibrium_about_the_pole(name, k):
    """Measured on paper: every force's drawn length × μ_F is its value, and Σ (image × F) about p,
    with the images measured in mm × μ_l, is zero with F_b included."""
    from graphmethods.sheets.forces import zhukovsky_forces

    case = builtin.case(name)
    scene = zhukovsky_forces(case, position=k)
    mu_l, mu_F = (s.per_mm for s in scene.scales())
    pole = next(e for e in scene.elements if e.name == "pole").at
    fa = case_forces(case, m=12)
    vecs = [e for e in scene.elements if isinstance(e, Vector)]
    assert len(vecs) == sum(1 for f in fa.lever.forces if abs(f.F[k]) > 0) + 1
    total, scale = 0.0, 0.0
    for v in vecs:
        img = complex(v.start[0] - pole[0], -(v.start[1] - pole[1])) * mu_l
        F = complex(v.end[0] - v.start[0], -(v.end[1] - v.start[1])) * mu_F
        total += (img.conjugate() * F).imag
        scale += abs(img) * abs(F)
    assert abs(total) <= 1e-9 * scale
    fb = next(v for v in vecs if v.name == "F_b")
    assert fb.length_mm * mu_F == pytest.approx(abs(fa.lever.F_balance[k]), rel=1e-9)


@pytest.mark.parametrize("name, k", [("press", 3), ("shaper", 2), ("four-bar", 2), ("two-slider", 5)])
def test_the_scheme_draws_every_force_from_its_point_to_scale(name, k):
    from graphmethods.sheets.forces import force_scheme

    case = builtin.case(name)
    scene = force_scheme(case, position=k, gravity=True)
    mu_l, mu_F = (s.per_mm for s in scene.scales())
    fa = case_forces(case, m=12, gravity=True)
    # the paper frame from two joints: the crank's centre and pin
    cr = fa.motion.linkage.crank
    pO = next(e for e in scene.elements if e.name == f"pivot-{cr.centre}").at
    zO = complex(fa.motion.z[cr.centre][k])
    drawn = [e for e in scene.elements if isinstance(e, Vector) and e.name.startswith("force-")]
    want = [f for fs in fa.applied.values() for f in fs if abs(f.F[k]) / mu_F >= 0.3]
    assert len(drawn) == len(want)
    for v, f in zip(drawn, want):
        start = zO + complex(v.start[0] - pO[0], -(v.start[1] - pO[1])) * mu_l
        assert start == pytest.approx(complex(f.at[k]), abs=1e-9)
        F = complex(v.end[0] - v.start[0], -(v.end[1] - v.start[1])) * mu_F
        assert F == pytest.approx(complex(f.F[k]), rel=1e-9, abs=1e-9 * abs(f.F[k]))
    moments = [e.name for e in scene.elements if e.name.startswith("moment-")]
    assert len(moments) == sum(1 for fs in fa.applied.values() for f in fs if f.M[k] != 0)


# ----------------------------------------------------------------------------- layouts on every problem

EVERY = list(dict.fromkeys(builtin.LINKAGES))


def _faults(fig):
    """Text over text, or anything out of the page's inner box (the lecture slides' check)."""
    from graphmethods.scene.steps import BuildUp, Step
    from graphmethods.sheets.steps import layout_faults

    x0, _, x1, y1 = fig.page.inner_box()
    return layout_faults(BuildUp(fig, (Step("", tuple(range(len(fig.elements)))),), (x0, y1, x1, y1)))


_TRIAD_FORCES = pytest.mark.xfail(strict=True, reason=(
    "triad-six-bar: force_plans draws the class III triad's inner reaction R_32 out of the page's inner box "
    "(k = 0, 3, 7; at k = 0 its label covers result-3), and at k = 0 the Zhukovsky lever's force labels "
    "near the pole overlap"))


@pytest.mark.parametrize("name", [pytest.param(n, marks=_TRIAD_FORCES) if n == "triad-six-bar" else n
                                  for n in EVERY])
def test_no_text_covers_another_and_nothing_leaves_the_frame_on_every_problem(name):
    from graphmethods.sheets.forces import force_scheme, zhukovsky_forces

    case = builtin.case(name)
    for k in (0, 3, 7):
        for figure in (force_plans, zhukovsky_forces, force_scheme):
            assert _faults(figure(case, position=k)) == [], (name, k, figure.__name__)


@pytest.mark.parametrize("name", EVERY)
def test_moment_arcs_keep_off_the_links_through_their_centre(name):
    """Each moment's arc (and M_b's) is drawn on the side of its point where no link passes: it crosses
    none of the drawn links through its centre (shapely, on the drawn coordinates)."""
    from shapely.geometry import LineString, Point

    from graphmethods.sheets.forces import force_scheme
    from graphmethods.sheets.kinematic_symbols import RotationArrow

    for k in (1, 4, 9):
        scene = force_scheme(builtin.case(name), position=k)
        links = [LineString([e.start, e.end]) for e in scene.elements if e.name.startswith("link-")]
        arcs = [e for e in scene.elements if isinstance(e, RotationArrow)]
        assert any(a.name == "M_b" for a in arcs)
        for arc in arcs:
            centre = Point(arc.centre)
            drawn = LineString(arc.arc_points())
            through = [ln for ln in links if ln.distance(centre) < 1e-6]
            assert through, (name, k, arc.name)
            assert not any(drawn.intersects(ln) for ln in through), (name, k, arc.name)


def test_long_flat_force_plans_go_one_under_the_other_and_are_drawn_larger():
    """The press's polygons are long and flat: stacked one under the other, the widest drawn wider than
    half the page's inner width, which two plans side by side could not be."""
    case = builtin.case("press")
    scene = force_plans(case, position=3)
    boxes = {}
    for e in scene.elements:
        if isinstance(e, Vector) and e.name.split("-")[0] in ("known", "closing", "inner"):
            j = int(e.name.split("-")[1])
            xs, ys = (e.start[0], e.end[0]), (e.start[1], e.end[1])
            b = boxes.get(j, (1e9, 1e9, -1e9, -1e9))
            boxes[j] = (min(b[0], *xs), min(b[1], *ys), max(b[2], *xs), max(b[3], *ys))
    assert sorted(boxes) == [0, 1]
    assert boxes[0][3] < boxes[1][1]                           # group 0 above the crank's plan
    mu = scene.scales()[0].per_mm
    fa = case_forces(case, m=12)
    widths = []
    for pl in fa.plans:
        poly = pl.polygons[0]
        pts = np.cumsum([0j] + [complex(F[3]) for _, F in poly.known] + [complex(F[3]) for _, _, F in poly.closing])
        widths.append(float(np.ptp(pts.real)))
    drawn_w = max(b[2] - b[0] for b in boxes.values())
    assert max(widths) / mu == pytest.approx(drawn_w, rel=1e-6)
    # side by side, two cells share the page's inner width: neither could be half as wide
    x0, _, x1, _ = scene.page.inner_box()
    assert drawn_w > (x1 - x0) / 2
