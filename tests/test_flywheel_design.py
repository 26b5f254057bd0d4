"""The flywheel as a designer sees it (issue 18 item 6): rim and disc sized from J_F, drawn to scale."""

import json
import math

import numpy as np
import pytest
import shapely

from graphmethods.cli import main
from graphmethods.dynamics.flywheel import DENSITY, RIM_SPEED_LIMIT, disc_flywheel, rim_flywheel
from graphmethods.render.recording import record
from graphmethods.scene.elements import label_bbox
from graphmethods.sheets.flywheel_design import DRAWING_SCALES, flywheel_design

J_F = 900 * 575 / (math.pi**2 * 600**2 / 300)        # W1's flywheel, kg·m²


def test_rim_and_disc_keep_their_textbook_relations():
    r = rim_flywheel(J_F, n_rpm=600.0, D=0.75)
    assert r.m * r.D**2 / 4 == pytest.approx(J_F, rel=1e-12)                      # J ≈ m D²/4
    assert DENSITY["cast iron"] * math.pi * r.D * r.H * r.B == pytest.approx(r.m, rel=1e-12)
    assert r.H / r.B == pytest.approx(1.5)
    assert r.J_rim == pytest.approx(r.m * (r.D1**2 + r.D2**2) / 8, rel=1e-12) and r.J_rim > J_F
    assert r.rim_speed == pytest.approx(math.pi * 0.75 * 600 / 60)
    top = rim_flywheel(J_F, n_rpm=600.0)                # D from the rim-speed limit
    assert top.rim_speed == pytest.approx(RIM_SPEED_LIMIT["cast iron"]) and top.speed_ok
    d = disc_flywheel(J_F, D=0.75, n_rpm=600.0)
    assert d.m * d.D**2 / 8 == pytest.approx(J_F, rel=1e-12)
    assert DENSITY["steel"] * math.pi * d.D**2 * d.B / 4 == pytest.approx(d.m, rel=1e-12)
    assert not disc_flywheel(J_F, D=0.75, n_rpm=1200.0, speed_limit=40.0).speed_ok   # 47 m/s


def test_the_drawing_is_to_scale():
    r, d = rim_flywheel(J_F, n_rpm=600.0, D=0.75), disc_flywheel(J_F, D=0.75, n_rpm=600.0)
    s = flywheel_design(r, d)
    (mu,) = s.scales()
    assert mu.per_mm * 1000 in DRAWING_SCALES and mu.per_mm == pytest.approx(0.01)        # 1 : 10 fills A4
    assert s.element("scale-note").text == "Scale 1 : 10"
    dim = s.element("dim-rim-D1")
    assert dim.length_mm * mu.per_mm == pytest.approx(r.D1, abs=mu.per_mm * 1e-3)
    assert dim.text == f"⌀{r.D1 * 1000:.4g}" == "⌀915.8"                  # not "D = …"; as the table and the report
    pts = np.array(s.element("rim-section-upper").outline)
    assert np.ptp(pts[:, 0]) * mu.per_mm == pytest.approx(r.B, abs=mu.per_mm * 1e-3)
    assert np.ptp(pts[:, 1]) * mu.per_mm == pytest.approx(r.H, abs=mu.per_mm * 1e-3)
    assert s.element("dim-disc-D1").length_mm * mu.per_mm == pytest.approx(d.D, abs=mu.per_mm * 1e-3)
    for part in ("rim", "disc"):                          # a hub and a bore on each
        assert s.element(f"{part}-hub-upper") and s.element(f"dim-{part}-bore").text.startswith("⌀")
    fast = flywheel_design(rim_flywheel(J_F, n_rpm=900.0, D=0.75), notation="en")
    assert "OVER" in fast.element("verdict").text


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_dimension_values_stand_clear_of_every_line(lang):
    s = flywheel_design(rim_flywheel(J_F, n_rpm=600.0, D=0.75), disc_flywheel(J_F, D=0.75, n_rpm=600.0),
                        notation=lang)
    rec = record(s)
    segments = [(a, b) for c in rec.calls if c.kind == "path" for a, b in zip(c.data[0], c.data[0][1:])]
    dims = [c.data for c in rec.calls if c.kind == "text" and any(g.startswith("dim-") for g in c.groups)]
    assert len(dims) == 11                                # rim: ⌀D1 ⌀D2 ⌀hub ⌀bore B L; disc: no ⌀D2
    for lab in dims:
        x0, y0, x1, y1 = label_bbox(lab)
        box = shapely.box(x0 - 0.3, y0 - 0.3, x1 + 0.3, y1 + 0.3)
        crossing = [seg for seg in segments if box.intersects(shapely.LineString(seg))]
        assert not crossing, (lab.text, crossing[:3])


def test_flywheel_command_sizes_and_draws(capsys, tmp_path):
    fig = tmp_path / "fw.svg"
    args = ["flywheel", "--areas=-50,550,-100,125,-500,25,-50", "--n", "600", "--delta", "1/300"]
    code = main(args + ["--rim", "0.75", "--disc", "0.75", "--figure", str(fig), "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    d = json.loads(out)
    assert d["rim"]["m"] == pytest.approx(4 * d["J_F"] / 0.75**2, rel=1e-12)
    assert d["disc"]["m"] == pytest.approx(8 * d["J_F"] / 0.75**2, rel=1e-12)
    assert fig.exists() and "dim-rim-D1" in fig.read_text(encoding="utf-8")
    code = main(args + ["--figure", str(tmp_path / "other.svg")])
    out, err = capsys.readouterr()
    assert code == 2 and "--rim" in err and not (tmp_path / "other.svg").exists()
    code = main(args + ["--J-e", "100", "--rim"])
    out, err = capsys.readouterr()
    assert code == 2 and "nothing to size" in err
