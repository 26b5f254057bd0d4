"""Make the example cam drawings in graphmethods/problems/data/drawings/ as a student makes them in CAD (run
once; the files are committed, and tests/test_cam_check.py checks that exactly the planted mistakes are found).

    python tests/drawings/make_cam_drawings.py

The shaper's table-feed cam (``shaper-cam``: an offset roller follower) drawn by inversion at μ_l = 0.0005
m/mm (2:1) on an A4 sheet: the base circle, the pitch base circle and the offset circle about O (CIRCLEs), the
follower's axis turned back at each division point (LINEs, 8 parts per rise and return), the roller circles
at the pitch points, the pitch curve and the profile as SPLINEs through fit points (the way AutoCAD's and
LibreCAD's SPLINE command draws a smooth curve through points), the letter O, the scale and the largest
pressure angles written as text. Points are off by up to 0.15 mm (a hand in a CAD program). The SVG is the
same drawing as Inkscape writes it: ``<circle>``s, the curves as cubic Bézier ``<path>``s, ``<line>``s.

Planted mistakes:

* shaper_cam_mistakes.dxf: the follower turned with the cam (+φ) instead of against it: the positions, the
  pitch curve and the profile mirrored (each s is then at the mirrored angle; the profile and the pitch
  curve lie off the exact ones: the mistake named); the largest pressure angle of the return written as
  20° (wrong, no usual mistake).
* shaper_cam_small.svg: the base radius read 3 mm (on the drawing) short off the combined diagram and the
  whole construction drawn on it (r_b wrong; the profile and the α written, computed at that radius,
  carried over).
"""

from __future__ import annotations

import math
import pathlib
from dataclasses import replace

import ezdxf
import numpy as np

from graphmethods.kinematics.cam import CamDesign, design
from graphmethods.kinematics.cam.geometry import to_cam_frame
from graphmethods.problems.builtin import cam_problem
from graphmethods.sheets.worksheets.cam import positions_of

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = ROOT / "graphmethods" / "problems" / "data" / "drawings"
MU = 0.0005
O = np.array([105.0, 150.0])             # the cam centre on the A4 portrait sheet, mm (y up)
JITTER = ((0.12, -0.08), (-0.15, 0.1), (0.1, 0.14), (-0.07, -0.13), (0.14, 0.05), (-0.1, 0.09), (0.05, -0.14))


def geometry(cam: CamDesign, *, mirrored: bool = False, n_div: int = 8) -> dict:
    """What the student draws, mm on the sheet (y up): circles, follower lines, pitch points, the curves."""
    p = cam.problem
    phi = np.asarray(positions_of(p, n_div))
    dense = np.linspace(0.0, 360.0, 73)[:-1]

    def turned(B: np.ndarray, ang: np.ndarray) -> np.ndarray:
        rad = np.radians(ang)
        return to_cam_frame(B, -rad if mirrored else rad, p.sense)

    def B(ang: np.ndarray) -> np.ndarray:
        return cam.frame(*p.motion(ang)[:3]).B

    s0 = math.sqrt(cam.pitch_base_radius ** 2 - p.offset ** 2)
    feet = turned(np.column_stack((np.full(phi.shape, p.offset), np.zeros(phi.shape))), phi)
    tops = turned(np.column_stack((np.full(phi.shape, p.offset), s0 + p.motion(phi)[0] + 0.009)), phi)
    pitch_k = turned(B(phi), phi)
    pitch = turned(B(dense), dense)
    if mirrored:
        from shapely.geometry import Polygon

        ring = Polygon(pitch).buffer(-p.roller_radius, quad_segs=16).exterior
        profile = np.asarray(ring.coords, dtype=float)[:-1][::4]
    else:
        profile = cam.state(dense).profile

    def mm(xy: np.ndarray) -> np.ndarray:
        xy = O + np.atleast_2d(xy) / MU
        jit = np.array([JITTER[k % len(JITTER)] for k in range(len(xy))])
        return xy + jit
    return {"circles": [r / MU for r in (cam.base_radius, cam.pitch_base_radius, abs(p.offset)) if r > 0],
            "lines": list(zip(mm(feet), mm(tops))), "rollers": mm(pitch_k), "r_r": p.roller_radius / MU,
            "pitch": mm(pitch), "profile": mm(profile)}


def texts(alpha_rise: float, alpha_return: float) -> list[tuple[str, tuple[float, float]]]:
    return [("O", (O[0] - 5.0, O[1] - 4.0)), ("μl = 0,0005 m/mm", (20.0, 40.0)),
            (f"αmax = {alpha_rise:.1f}°", (20.0, 32.0)), (f"αret = {alpha_return:.1f}°", (20.0, 24.0))]


def write_dxf(g: dict, words: list, path: pathlib.Path) -> None:
    doc = ezdxf.new("R2010", setup=True)
    doc.units = ezdxf.units.MM
    for name, colour in (("Frame", 7), ("Cam", 5), ("Construction", 8), ("Text", 3)):
        doc.layers.add(name, color=colour)
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (210, 0), (210, 297), (0, 297)], close=True, dxfattribs={"layer": "Frame"})
    for r in g["circles"]:
        msp.add_circle(tuple(O), r, dxfattribs={"layer": "Construction"})
    for a, b in g["lines"]:
        msp.add_line(tuple(a), tuple(b), dxfattribs={"layer": "Construction"})
    for c in g["rollers"]:
        msp.add_circle(tuple(c), g["r_r"], dxfattribs={"layer": "Construction"})
    for key in ("pitch", "profile"):
        pts = [tuple(q) for q in g[key]]
        msp.add_spline(fit_points=pts + [pts[0]], dxfattribs={"layer": "Cam"})
    for text, at in words:
        msp.add_text(text, height=3.5, dxfattribs={"layer": "Text"}).set_placement(at)
    doc.saveas(path)


def _bezier(pts: np.ndarray) -> str:
    """A closed Catmull–Rom curve through the points as cubic Bézier commands (the page's y down)."""
    n = len(pts)
    d = [f"M{pts[0][0]:.3f} {pts[0][1]:.3f}"]
    for i in range(n):
        p0, p1, p2, p3 = pts[i - 1], pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
        c1, c2 = p1 + (p2 - p0) / 6.0, p2 - (p3 - p1) / 6.0
        d.append(f"C{c1[0]:.3f} {c1[1]:.3f} {c2[0]:.3f} {c2[1]:.3f} {p2[0]:.3f} {p2[1]:.3f}")
    return " ".join(d) + " Z"


def write_svg(g: dict, words: list, path: pathlib.Path) -> None:
    H = 297.0

    def f(q) -> tuple[float, float]:
        return (round(float(q[0]), 3), round(H - float(q[1]), 3))
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="297mm" viewBox="0 0 210 297">',
           '<style>.c{fill:none;stroke:#000;stroke-width:0.25}.t{font-family:sans-serif;font-size:4.9px}</style>']
    ox, oy = f(O)
    out += [f'<circle class="c" cx="{ox}" cy="{oy}" r="{r:.3f}"/>' for r in g["circles"]]
    out += [f'<line class="c" x1="{f(a)[0]}" y1="{f(a)[1]}" x2="{f(b)[0]}" y2="{f(b)[1]}"/>' for a, b in g["lines"]]
    out += [f'<circle class="c" cx="{f(c)[0]}" cy="{f(c)[1]}" r="{g["r_r"]:.3f}"/>' for c in g["rollers"]]
    for key in ("pitch", "profile"):
        pts = np.array([f(q) for q in g[key]])
        out.append(f'<path class="c" d="{_bezier(pts)}"/>')
    out += [f'<text class="t" x="{f(at)[0]}" y="{f(at)[1]}">{t}</text>' for t, at in words]
    path.write_text("\n".join(out + ["</svg>"]) + "\n", encoding="utf-8")


def main() -> None:
    cam = design(cam_problem("shaper-cam"))
    OUT.mkdir(parents=True, exist_ok=True)
    good = geometry(cam)
    words = texts(cam.alpha_max_rise_deg, cam.alpha_max_return_deg)
    write_dxf(good, words, OUT / "shaper_cam_correct.dxf")
    write_svg(good, words, OUT / "shaper_cam_correct.svg")
    write_dxf(geometry(cam, mirrored=True), texts(cam.alpha_max_rise_deg, 20.0), OUT / "shaper_cam_mistakes.dxf")
    small = design(replace(cam.problem, base_radius=cam.base_radius - 3.0 * MU, alpha_max_deg=None))
    write_svg(geometry(small), texts(small.alpha_max_rise_deg, small.alpha_max_return_deg),
              OUT / "shaper_cam_small.svg")


if __name__ == "__main__":
    main()
