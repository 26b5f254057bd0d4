"""The A4 cam figures, the rocker's combined diagram and ``cam --figures``.

The rocker's construction (:mod:`graphmethods.sheets.cam_rocker`) is held against the exact design: the
pressure angle read from the points K at the designed centre equals the pitch frame's, and the zone's
boundary point on the circle of radius a about the pivot gives the designed r₀ to 1e-9 m, for the built-in
problem and for variants where the return binds, the cam turns clockwise, or the follower is a knife.
"""

from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from graphmethods.kinematics.cam import cam_from_dict, design
from graphmethods.problems.builtin import cam_problem
from graphmethods.sheets import cam_rocker
from graphmethods.sheets.cam_figures import cam_combined_diagram, cam_figures, cam_motion_diagrams
from graphmethods.sheets.engine.quality import faults, measure

ROCKER = {
    "kind": "cam",
    "follower": {"type": "oscillating", "contact": "roller", "roller_radius": 0.012, "arm": 0.125, "pivot": 0.15},
    "cam": {"sense": "ccw", "n_rpm": 60},
    "motion": [{"phase": "rise", "angle_deg": 75, "lift_deg": 15, "law": "cycloidal"},
               {"phase": "dwell", "angle_deg": 10},
               {"phase": "return", "angle_deg": 75, "lift_deg": 15, "law": "polynomial_345"},
               {"phase": "dwell", "angle_deg": 200}],
    "pressure_angle_max_deg": 40, "pressure_angle_return_max_deg": 70,
}


def _variant(**change):
    d = copy.deepcopy(ROCKER)
    for key, value in change.items():
        if key == "sense":
            d["cam"]["sense"] = value
        elif key == "contact":
            d["follower"] = {k: v for k, v in d["follower"].items() if k != "roller_radius"} | {"contact": value}
        elif key == "laws":
            d["motion"][0]["law"], d["motion"][2]["law"] = value
        elif key == "angles":
            d["motion"][0]["angle_deg"], d["motion"][2]["angle_deg"] = value
        else:
            d[key] = value
    return design(cam_from_dict(d))


VARIANTS = {
    "built-in": lambda: design(cam_problem("oscillating-cam")),
    "return-binds": lambda: _variant(pressure_angle_return_max_deg=35, laws=("harmonic", "parabolic"),
                                     angles=(100, 50)),
    "clockwise": lambda: _variant(sense="cw"),
    "knife": lambda: _variant(contact="knife", laws=("polynomial_345", "cycloidal")),
    "tight": lambda: _variant(pressure_angle_max_deg=35, pressure_angle_return_max_deg=55),
}


@pytest.mark.parametrize("name", list(VARIANTS))
def test_the_points_K_give_the_exact_pressure_angle_at_the_designed_centre(name):
    cam = VARIANTS[name]()
    rk = cam_rocker.rocker(cam)
    phi = np.linspace(0.0, 360.0, 721)
    s, s1, _, _ = cam.problem.motion(phi)
    alpha = cam_rocker.pressure_angle(rk, np.zeros(2), s, s1)
    assert np.abs(alpha - np.radians(np.abs(cam.state(phi).alpha_deg))).max() < 1e-12


@pytest.mark.parametrize("name", list(VARIANTS))
def test_the_zone_boundary_point_gives_the_designed_base_radius(name):
    cam = VARIANTS[name]()
    assert abs(cam_rocker.zone_boundary_r0(cam) - cam.pitch_base_radius) < 1e-9
    O = cam_rocker.boundary_centre(cam)
    assert abs(math.hypot(*(O - cam_rocker.rocker(cam).A)) - cam.problem.pivot) < 1e-12      # on the circle of a


def test_the_designed_centre_sits_on_the_drawn_zone_and_the_tangent_through_it():
    from shapely.geometry import Point, Polygon

    cam = VARIANTS["built-in"]()
    rk = cam_rocker.rocker(cam)
    zone = Polygon(cam_rocker.zone_polygon(cam, rk, (-0.2, -0.2, 0.2, 0.2)))
    assert zone.exterior.distance(Point(0.0, 0.0)) < 2e-4 * cam.pitch_base_radius       # 121 samples a phase
    d = cam_rocker.rocker_diagram_data(cam, np.arange(0.0, 160.0, 10.0))
    dist = [abs(float(e[0] * (d.O - K)[1] - e[1] * (d.O - K)[0])) for _, K, e in d.tangents]
    assert min(dist) < 1e-6 * cam.pitch_base_radius


def test_the_rocker_diagram_prints_the_designed_radius():
    cam = VARIANTS["built-in"]()
    scene = cam_combined_diagram(cam, notation="en")
    texts = [e.text for e in scene.elements if hasattr(e, "text")]
    assert any(t.startswith("O: r_0 = ") and t.endswith(f"{cam.pitch_base_radius:.4g} m") for t in texts)


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_the_a4_figures_meet_the_standard_for_a_uniform_law_too(lang):
    d = copy.deepcopy(ROCKER)
    d["follower"] = {"type": "translating", "contact": "roller", "roller_radius": 0.01, "offset": 0.005}
    d["motion"] = [{"phase": "rise", "angle_deg": 120, "lift": 0.02, "law": "uniform"},
                   {"phase": "dwell", "angle_deg": 60},
                   {"phase": "return", "angle_deg": 120, "lift": 0.02, "law": "harmonic"},
                   {"phase": "dwell", "angle_deg": 60}]
    d["base_radius"] = 0.03
    scene = cam_motion_diagrams(cam_from_dict(d), notation=lang)
    assert scene.page.size == "A4" and faults(measure(scene)) == []
    assert sum(e.name.startswith("m0-impulse-") for e in scene.elements) == 2


def test_every_figure_is_a4_with_every_scale_it_draws_in_its_title_block():
    figs = cam_figures(cam_problem("shaper-cam"), notation="ru")
    assert sorted(figs) == ["combined_diagram", "motion_diagrams", "pressure_angle", "profile"]
    for scene in figs.values():
        tb = scene.page.title_block
        rows = " ".join(t for _, t in tb.rows())
        assert scene.page.size == "A4"
        for s in scene.scales():
            assert s.caption(scene.notation) in rows


def test_a_flat_face_has_no_combined_diagram():
    from graphmethods.errors import InputError
    from graphmethods.kinematics.cam import EXAMPLE

    d = copy.deepcopy(EXAMPLE)
    d["follower"] = {"type": "translating", "contact": "flat"}
    d["rho_min_allowed"] = 0.003
    cam = cam_from_dict(d)
    assert sorted(cam_figures(cam)) == ["motion_diagrams", "pressure_angle", "profile"]
    with pytest.raises(InputError, match="flat"):
        cam_combined_diagram(cam)


def test_cli_figures_writes_the_set_and_keeps_it_unless_forced(tmp_path, capsys):
    from graphmethods.cli import main

    out = tmp_path / "figs"
    assert main(["cam", "oscillating-cam", "--figures", str(out), "--lang", "zh", "--json", "--positions", "2"]) == 0
    res = json.loads(capsys.readouterr().out)
    names = sorted(p.name for p in out.iterdir())
    assert names == [f"oscillating-cam_{k}.svg" for k in ("combined_diagram", "motion_diagrams", "pressure_angle",
                                                           "profile")]
    assert sorted(res["figures"]) == sorted(str(out / n) for n in names)
    before = (out / names[0]).read_bytes()
    assert main(["cam", "oscillating-cam", "--figures", str(out), "--format", "svg"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--force" in err
    assert (out / names[0]).read_bytes() == before
    assert main(["cam", "oscillating-cam", "--figures", str(out), "--force", "--positions", "2"]) == 0


def test_cli_lang_without_an_output_is_refused(capsys):
    from graphmethods.cli import main

    assert main(["cam", "shaper-cam", "--lang", "ru"]) == 2
    assert "--figures" in capsys.readouterr().err
