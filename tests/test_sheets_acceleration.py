"""The acceleration figures: drawn vectors × μ_a are the core's accelerations, words, scales, refusals."""

import itertools
import math

import numpy as np
import pytest
from figure_checks import assert_fits_and_labels_apart

from graphmethods.errors import InputError
from graphmethods.kinematics.acceleration_plan import acceleration_plan as construct
from graphmethods.kinematics.presets import slider_crank
from graphmethods.problems import builtin
from graphmethods.render import svg
from graphmethods.render.recording import record
from graphmethods.scene import markup
from graphmethods.sheets import acceleration as A

PROFILES = ("en", "ru", "zh")


def _drawn_vector(rec, name: str) -> complex:
    """The drawn vector start → tip, in paper mm, as x + iy with y up."""
    paths, heads = rec.in_group(name, "path"), rec.in_group(name, "polygon")
    (sx, sy), (tx, ty) = paths[0].data[0][0], heads[0].data[0]
    return complex(tx - sx, -(ty - sy))


def _special_point_a(lk, mo, point, k):
    """a of Assur's special point K of a triad from the core, a point of its basic link t.

    a_K = a_B + (iε_t − ω_t²)(K − B).
    """
    g = next(g for g in lk.groups if g.kind == "triad" and g.special == point)
    K = complex(g.special_point(mo._state)[0][k])
    B, t = g.inner[0], str(g.links[0])
    return complex(mo.a_[B][k] + (1j * mo.epsilon[t][k] - mo.omega[t][k] ** 2) * (K - mo.z[B][k]))


@pytest.mark.parametrize("name", list(builtin.LINKAGES))
def test_drawn_vectors_times_mu_a_are_the_cores_accelerations(name):
    case = builtin.case(name)
    lk = case.linkage
    mo = lk.motion(m=12, omega_1=case.omega_m, level=2)
    for k in (1, 4, 9):
        scene = A.acceleration_plan(case, k)
        mu = scene.scales()[0].per_mm
        rec = record(scene)
        ids = set(rec.group_ids())
        plan = construct(lk, k, omega_1=case.omega_m)
        checked = 0
        for point, label in plan.labels.items():
            vid = f"vector-pi-{A._id(label)}"
            if vid not in ids:                     # at π (a fixed point) or coincident with another image
                at_another = any(abs(plan.a(point) - plan.a(q)) < 1e-12 for q in plan.labels if q != point)
                assert point in lk.ground or at_another or abs(plan.a(point)) < 1e-9
                continue
            drawn = _drawn_vector(rec, vid) * mu
            ref = complex(mo.a_[point][k]) if point in mo.a_ else _special_point_a(lk, mo, point, k)
            assert abs(drawn - ref) <= 1e-12 * max(abs(ref), 1.0), (name, k, point, drawn, ref)
            checked += 1
        distinct = {complex(round(plan.a(q).real, 9), round(plan.a(q).imag, 9)) for q in plan.labels
                    if q not in lk.ground and abs(plan.a(q)) >= 1e-9}
        assert checked >= min(2, len(distinct))        # a Scotch yoke has one image besides π


def test_every_component_is_drawn_to_scale_and_the_table_says_so():
    case = builtin.case("shaper")
    scene = A.acceleration_plan(case, 3)
    mu = scene.scales()[0].per_mm
    rec = record(scene)
    plan = construct(case.linkage, 3, omega_1=case.omega_m)
    for c in plan.components:
        vid = A._elname(c)
        if c.magnitude == 0 or vid not in rec.group_ids():
            continue
        assert abs(_drawn_vector(rec, vid) * mu - c.vector) <= 1e-12 * max(c.magnitude, 1.0)
    table = " ".join(rec.texts("table"))
    a_k = next(c for c in plan.components if c.kind == "coriolis")
    assert f"{a_k.magnitude:.3f}" in table
    # solid known components, dashed found ones
    for c in plan.components:
        vid = A._elname(c)
        if vid in rec.group_ids():
            shaft = rec.in_group(vid, "path")[0]
            assert (shaft.style.dash is None) == c.known, vid


def test_construction_lines_pass_through_their_point_and_the_image_found():
    case = builtin.case("four-bar")
    scene = A.acceleration_plan(case, 5)
    rec = record(scene)
    names = [g for g in rec.group_ids() if g.startswith("line-")]
    assert names == ["line-B-n_BA", "line-B-n_BO2"]
    b = rec.in_group("vector-pi-b", "polygon")[0].data[0]
    for nm in names:
        (p, q), _ = rec.in_group(nm, "path")[0].data
        cross = (q[0] - p[0]) * (b[1] - p[1]) - (q[1] - p[1]) * (b[0] - p[0])
        assert abs(cross) / math.dist(p, q) < 1e-9
        assert rec.in_group(nm, "path")[0].style.dash is not None           # unknown directions dashed


def test_a_given_mu_a_is_honoured_or_refused():
    case = builtin.case("press")
    assert A.acceleration_plan(case, 2, mu_a=2.0).scales()[0].per_mm == 2.0
    with pytest.raises(InputError, match="does not fit"):
        A.acceleration_plan(case, 2, mu_a=0.01)
    with pytest.raises(InputError, match="mu_a"):
        A.acceleration_plan(case, 2, mu_a=-1.0)
    with pytest.raises(InputError, match="position 12"):
        A.acceleration_plan(case, 12)
    with pytest.raises(InputError, match="epsilon_1"):
        A.acceleration_plan(case, 2, epsilon_1=float("nan"))


def test_the_crank_speeding_up_draws_its_own_tangential_component():
    lk = slider_crank(r=0.1, l=0.4, points={"S2": ("AB", 0.2)})
    scene = A.acceleration_plan(lk, 2, omega_1=10.0, epsilon_1=50.0, mu_a=0.2)
    rec = record(scene)
    tau = _drawn_vector(rec, "vector-n_A-a") * 0.2
    phi = construct(lk, 2, omega_1=10.0).phi
    assert abs(tau - 1j * 50.0 * 0.1 * complex(math.cos(phi), math.sin(phi))) < 1e-12
    assert any("ε_1 = 50" in markup.plain(t) or "ε1 = 50" in markup.plain(t) for t in rec.texts())


def test_equations_and_epsilon_with_its_sense_in_three_languages():
    case = builtin.case("slotted-lever")
    words = {"en": ("Acceleration plan", "clockwise"), "ru": ("План ускорений", "часовой"),
             "zh": ("加速度多边形", "时针")}
    for nt, (title, sense) in words.items():
        rec = record(A.acceleration_plan(case, 2, notation=nt))
        texts = [markup.plain(t) for t in rec.texts()]
        assert any(title in t for t in texts)
        eq = " ".join(texts)
        assert "aA3 = aA2 + akA3A2 + arA3A2 = aO3 + anA3O3 + aτA3O3" in eq
        assert "akA3A2 = 2·ω3·vA3A2" in eq
        eps = [t for t in texts if t.startswith("ε3 = aτA3O3/lO3A3")]
        assert len(eps) == 1 and sense in eps[0]
    plan = construct(case.linkage, 2, omega_1=case.omega_m)
    en = [markup.plain(t) for t in record(A.acceleration_plan(case, 2)).texts()]
    e3 = plan.epsilon["3"]
    line = next(t for t in en if t.startswith("ε3"))
    assert ("counterclockwise" in line) == (e3 > 0)


FIGS = [("plan", lambda c, nt: A.acceleration_plan(c, notation=nt)),
        ("grid", lambda c, nt: A.acceleration_plan_grid(c, notation=nt)),
        ("table", lambda c, nt: A.acceleration_table(c, notation=nt))]


@pytest.mark.parametrize("case, fig, nt", list(itertools.product(("press", "shaper", "four-bar", "slotted-lever"),
                                                                 [f[0] for f in FIGS], PROFILES)))
def test_every_figure_fits_its_frame_and_labels_keep_apart(case, fig, nt):
    scene = dict(FIGS)[fig](builtin.case(case), nt)
    assert_fits_and_labels_apart(scene, f"{case}-{fig}-{nt}")
    if fig != "table":
        assert [s.symbol for s in scene.scales()] == ["μ_a"]


def test_same_input_gives_byte_identical_svg():
    for fn in (A.acceleration_plan, A.acceleration_plan_grid, A.acceleration_table):
        assert svg.to_bytes(fn(builtin.case("shaper"), notation="ru")) == svg.to_bytes(fn(builtin.case("shaper"),
                                                                                          notation="ru"))


def test_table_rows_are_the_plans():
    case = builtin.case("six-bar-press")
    cols, rows = A.acceleration_rows(case)
    plans = [construct(case.linkage, k, omega_1=case.omega_m) for k in (0, 5)]
    i_d, i_c = cols.index("a_{D}"), cols.index("a_{C}")
    for k, p in zip((0, 5), plans):
        assert rows[k][i_d] == pytest.approx(p.a("D").real, abs=1e-12)          # the ram, signed along +x
        assert rows[k][i_c] == pytest.approx(abs(p.a("C")), abs=1e-12)
        assert rows[k][cols.index("ε_{4}")] == pytest.approx(p.epsilon["4"], abs=1e-12)
    assert len(rows) == 12 and np.all(np.diff([r[1] for r in rows]) > 0)
