"""The A1 cam sheet measured like every sheet: lettering, texts apart and off the lines, values on every axis,
empty 20 mm cells, the numbers of the CLI, byte-identical output; the construction's own accuracy."""

from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from graphmethods.kinematics.cam import EXAMPLE, cam_from_dict, design
from graphmethods.problems.builtin import CAMS, cam_problem
from graphmethods.render.recording import record
from graphmethods.scene.elements import label_bbox
from graphmethods.sheets.cam_sheet import cam_sheet
from graphmethods.sheets.engine.quality import faults, measure
from graphmethods.sheets.layout import segments_hit_boxes
from tests.test_every_sheet_layout import bare_axes, text_faults

LANGS = ("en", "ru", "zh")
CELL_MM = 20.0


def _flat():
    d = copy.deepcopy(EXAMPLE)
    d["follower"] = {"type": "translating", "contact": "flat"}
    d["rho_min_allowed"] = 0.003
    return cam_from_dict(d)


def _knife():
    d = copy.deepcopy(EXAMPLE)
    d["follower"] = {"type": "translating", "contact": "knife", "offset": 0.0}
    d["motion"][0]["law"], d["motion"][2]["law"] = "polynomial_345", "parabolic"
    d["cam"]["sense"] = "cw"
    return cam_from_dict(d)


PROBLEMS = {**{name: (lambda n=name: cam_problem(n)) for name in CAMS}, "example": lambda: cam_from_dict(EXAMPLE),
            "flat": _flat, "knife-cw": _knife}


@pytest.fixture(scope="module")
def sheets():
    cache = {}

    def get(name, lang):
        if (name, lang) not in cache:
            cam = design(PROBLEMS[name]())
            cache[name, lang] = (cam, cam_sheet(cam, notation=lang))
        return cache[name, lang]
    return get


def _ink_cells(rec, box) -> np.ndarray:
    """Which 20 mm cells of the frame's inside hold ink: paths and circles sampled every 0.5 mm, texts' boxes."""
    x0, y0, x1, y1 = box
    nx, ny = int((x1 - x0) // CELL_MM), int((y1 - y0) // CELL_MM)
    ink = np.zeros((ny, nx), dtype=bool)

    def mark(xs, ys):
        i = ((np.asarray(ys) - y0) // CELL_MM).astype(int)
        j = ((np.asarray(xs) - x0) // CELL_MM).astype(int)
        ok = (i >= 0) & (i < ny) & (j >= 0) & (j < nx)
        ink[i[ok], j[ok]] = True

    for c in rec.calls:
        if c.kind in ("path", "polygon"):
            pts = np.asarray(c.data[0] if c.kind == "path" else c.data, dtype=float)
            if (c.kind == "path" and c.data[1]) or c.kind == "polygon":
                pts = np.vstack((pts, pts[:1]))
            for a, b in zip(pts[:-1], pts[1:]):
                n = max(2, int(math.dist(a, b) / 0.5) + 1)
                t = np.linspace(0.0, 1.0, n)
                mark(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
        elif c.kind == "circle":
            cx, cy, r = c.data
            t = np.linspace(0.0, 2 * math.pi, max(8, int(2 * math.pi * r / 0.5)))
            mark(cx + r * np.cos(t), cy + r * np.sin(t))
        elif c.kind == "text":
            bx0, by0, bx1, by1 = label_bbox(c.data)
            xs, ys = np.meshgrid(np.arange(bx0, bx1, 1.0), np.arange(by0, by1, 1.0))
            mark(xs.ravel(), ys.ravel())
    return ink


def _labels_on_lines(rec) -> list[str]:
    """Texts whose box (less 0.3 mm all round) a drawn line crosses, other than the frame and the tables' rules."""
    seg = []
    for c in rec.calls:
        if c.kind == "path" and not any(g.startswith(("results", "positions-table", "title-block")) for g in c.groups):
            pts = list(c.data[0]) + ([c.data[0][0]] if c.data[1] else [])
            seg += [(a[0], a[1], b[0], b[1]) for a, b in zip(pts[:-1], pts[1:])]
    texts = [c for c in rec.calls if c.kind == "text"
             and not any(g.startswith(("results", "positions-table", "title-block")) for g in c.groups)]
    boxes = np.array([label_bbox(c.data) for c in texts]) + np.array([0.3, 0.3, -0.3, -0.3])
    hits = segments_hit_boxes(np.array(seg), boxes).any(axis=1) if len(texts) else []
    return [texts[k].data.text for k in np.flatnonzero(hits)]


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", list(PROBLEMS))
def test_the_cam_sheet_keeps_the_standard(name, lang, sheets):
    cam, scene = sheets(name, lang)
    rec = record(scene)
    texts = [c.data for c in rec.calls if c.kind == "text"]
    assert scene.page.size == "A1"
    assert min(t.size_mm for t in texts) >= 3.5 - 1e-9
    assert text_faults(scene, texts) == []
    assert bare_axes(scene, texts) == []
    assert _labels_on_lines(rec) == []
    ink = _ink_cells(rec, scene.page.inner_box())
    assert 1.0 - ink.mean() <= 0.5, f"{1.0 - ink.mean():.1%} of the 20 mm cells are empty"
    assert faults(measure(scene)) == []                  # the engine's measure of every sheet


def test_the_sheet_prints_the_numbers_of_the_command_line(capsys, sheets):
    from graphmethods.cli import main
    from graphmethods.scene.notation import get

    cam, scene = sheets("shaper-cam", "en")
    assert main(["cam", "shaper-cam", "--json", "--positions", "4"]) == 0
    res = json.loads(capsys.readouterr().out)
    table = scene.element("results")
    cells = " | ".join(" | ".join(r) for r in table.rows)
    nt = get("en")
    for key in ("base_radius", "pitch_base_radius", "rho_pitch_min"):
        assert nt.number(res[key], sig=4) in cells, key
    assert f"{nt.number(res['pressure_angle_max_rise_deg'])}° / {nt.number(res['pressure_angle_max_return_deg'])}°" \
        in cells


def test_the_sheet_is_byte_identical_from_the_same_input():
    from graphmethods.render import formats

    cam = design(cam_problem("oscillating-cam"))
    assert formats.to_bytes(cam_sheet(cam, notation="ru"), ".svg") == formats.to_bytes(cam_sheet(cam, notation="ru"),
                                                                                        ".svg")


@pytest.mark.parametrize("n_div", [4, 8, 16])
def test_the_chord_integration_error_against_the_exact_displacement(n_div):
    """The first integration (exact mean ordinates of d²s/dφ²) is exact at the nodes; the second (trapezoids of
    the chords) errs by O(Δφ²): the error printed on the sheet, measured here."""
    from graphmethods.sheets.cam_diagrams import construction

    cam = design(cam_problem("shaper-cam"))
    con = construction(cam, n_div, mu_phi=math.radians(1.5), mu_a=4e-4, room_mm=1e9, fit_v=60.0, fit_s=120.0)
    p = cam.problem
    v_exact = p.motion(np.degrees(con.nodes))[1]
    assert np.abs(con.first.values + v_exact[0] - v_exact).max() < 1e-12
    h = p.stroke
    bound = {4: 0.08, 8: 0.02, 16: 0.005}[n_div]
    assert con.error_s < bound * h


def _uniform(both: bool = False):
    d = copy.deepcopy(EXAMPLE)
    d["motion"][0]["law"] = "uniform"
    if both:
        d["motion"][2]["law"] = "uniform"
    d["base_radius"] = 0.03
    return design(cam_from_dict(d))


@pytest.mark.parametrize("both", [False, True], ids=["uniform-rise", "uniform-rise-and-return"])
def test_a_uniform_phase_is_drawn_with_impulses_to_infinity_at_its_hard_impacts(both):
    cam = _uniform(both)
    hard = [i for i in cam.impacts if i.kind == "hard"]
    assert len(hard) == (4 if both else 2)
    sheet = cam_sheet(cam, notation="ru")
    names = [e.name for g in sheet.elements if hasattr(g, "elements") for e in g.elements]
    arrows = [n for n in names if n.startswith("m0-impulse-")]
    assert len(arrows) == len(hard) and sum(n.startswith("m0-infinity-") for n in names) == len(hard)
    assert not any(n.startswith("m0-ray-") or n == "m0-pole" for n in names)      # d²s/dφ² is not integrated
    assert any(n == "m1-pole" for n in names)                                     # ds/dφ is, once
    texts = [e.text for g in sheet.elements if hasattr(g, "elements") for e in g.elements if hasattr(e, "text")]
    assert any("жёсткие удары" in x for x in texts)
    motion = next(g for g in sheet.elements if g.name == "motion")
    for imp, arrow in zip(hard, [e for e in motion.elements if e.name.startswith("m0-impulse-")]):
        assert (arrow.end[1] < arrow.start[1]) == (imp.jump > 0)       # up (smaller y on paper) where v jumps up
    q = measure(sheet)
    assert q.min_text_mm >= 3.5 and q.noise == ()


def test_the_uniform_law_s_is_exact_at_the_nodes_by_one_chord_integration():
    from graphmethods.sheets.cam_diagrams import construction

    cam = _uniform(both=True)
    con = construction(cam, 8, mu_phi=math.radians(1.5), mu_a=4e-4, room_mm=1e9, fit_v=60.0, fit_s=120.0)
    assert con.impulses and con.first is None
    assert con.error_s < 1e-15 * cam.problem.stroke * 1e3


@pytest.mark.parametrize("name", list(CAMS))
def test_the_inversion_step_by_step_takes_every_element_once(name):
    from graphmethods.sheets.steps import build

    bu = build(name, "inversion", notation="ru", page="A4")
    assert len(bu) == 7
    taken = [i for st in bu.steps for i in st.elements]
    assert sorted(taken) == list(range(len(bu.figure.elements)))
    assert bu.scene_at(len(bu)) == bu.figure
    assert faults(measure(bu.figure)) == [] or all("empty" in f for f in faults(measure(bu.figure)))


def test_a_cam_problem_has_only_the_inversion_steps():
    from graphmethods.errors import InputError
    from graphmethods.sheets.steps import build

    with pytest.raises(InputError, match="inversion"):
        build("shaper-cam", "velocity-plan")
    with pytest.raises(InputError, match="inversion"):
        build("press", "inversion")
