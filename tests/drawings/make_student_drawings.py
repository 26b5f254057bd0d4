"""Make the example drawings in graphmethods/problems/data/drawings/ as students make them in CAD (run once;
the files are committed, and tests/test_cad_check.py checks that exactly the planted mistakes are found).

    python tests/drawings/make_student_drawings.py

Made with ezdxf directly (not with graphmethods' renderer), the way a student draws in AutoCAD, KOMPAS or
LibreCAD: LINEs for the vectors, arrowheads as SOLIDs or as a polyline segment of changing width, TEXT
labels placed by hand beside the points (at varying offsets), the scale and the results written as
text (``μv = 0,05 (m/s)/mm``, ``vB = 3.03 m/s``), a frame, construction lines on their own layer.
Lengths are off by up to 0.3 mm and directions by a fraction of a degree (a hand in a CAD program),
so the correct drawings are correct within the drafting tolerances, not exact.

The SVG is drawn as Inkscape writes it: a viewBox in mm, relative path commands, a translated group,
arrowheads by ``marker-end``, font sizes in user units.

Planted mistakes (the same as in the answers files of ../../graphmethods/problems/data/answers):

* press_plan_mistakes.dxf: s₂ put on ab with AS₂/AB measured from b (as₂ = 0.675·ab instead of 0.325·ab;
  no usual mistake: ps₂ is 0.8 mm short and 10° off); v_S2 written from that ps₂ (carried over);
  v_B = pb·μv·μv (the scale applied twice).
* press_wittenbauer_mistakes.dxf: k and l marked on the vertical through the curve's leftmost point instead
  of on the ordinate axis J_e = 0 (J_e not subtracted); J_F from that kl with n (rev/min) used as ω.
* w1_mistakes.dxf, w1_mistakes.svg: the arrow c–d drawn up instead of down (a sign flipped; ΔW_max = 775 J
  follows, carried over); ω_max, ω_min from ω_m(1 ± δ) (δ not halved); n used as ω in J_F.
"""

from __future__ import annotations

import math
import pathlib

import ezdxf
import numpy as np

from graphmethods.kinematics import read_case

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = ROOT / "graphmethods" / "problems" / "data" / "drawings"
MU_V = 0.05
MU_E = 5.0

# small hand errors (mm) for the points, in turn
JITTER = ((0.12, -0.08), (-0.15, 0.1), (0.1, 0.14), (-0.07, -0.13), (0.16, 0.05), (-0.1, 0.09), (0.05, -0.16),
          (0.13, 0.11))
# where students put a letter, relative to the point (mm)
LABEL_AT = ((1.6, 0.8), (-3.4, 1.2), (1.2, -3.6), (1.8, 1.5), (-3.0, -3.2), (2.0, -1.0), (-2.6, 1.9), (1.4, 2.2))


def new_doc():
    doc = ezdxf.new("R2010", setup=True)
    doc.units = ezdxf.units.MM
    doc.layers.add("Frame", color=7)
    doc.layers.add("Plan", color=5)
    doc.layers.add("Construction", color=8, linetype="DASHED")
    doc.layers.add("Text", color=3)
    return doc


def frame(msp):
    msp.add_lwpolyline([(0, 0), (297, 0), (297, 210), (0, 210)], close=True, dxfattribs={"layer": "Frame"})
    msp.add_lwpolyline([(20, 5), (292, 5), (292, 205), (20, 205)], close=True,
                       dxfattribs={"layer": "Frame", "const_width": 0.5})


def arrow(msp, start, tip, *, kind: str):
    """A vector as a student draws it: a LINE and a SOLID head, or one polyline whose last segment narrows."""
    s, t = np.asarray(start, float), np.asarray(tip, float)
    u = (t - s) / np.hypot(*(t - s))
    base = t - 3.0 * u
    n = np.array([-u[1], u[0]]) * 0.5
    if kind == "solid":
        msp.add_line(tuple(s), tuple(base), dxfattribs={"layer": "Plan"})
        msp.add_solid([tuple(t), tuple(base + n), tuple(base - n)], dxfattribs={"layer": "Plan"})
    else:
        msp.add_lwpolyline([(s[0], s[1], 0, 0), (base[0], base[1], 1.0, 0), (t[0], t[1], 0, 0)], format="xyse",
                           dxfattribs={"layer": "Plan"})


def label(msp, text, at, k):
    dx, dy = LABEL_AT[k % len(LABEL_AT)]
    msp.add_text(text, height=3.5, dxfattribs={"layer": "Text"}).set_placement((at[0] + dx, at[1] + dy))


def note(msp, text, x, y):
    msp.add_text(text, height=3.0, dxfattribs={"layer": "Text"}).set_placement((x, y))


def press_plan(mistakes: bool) -> bytes:
    case = read_case(ROOT / "graphmethods" / "problems" / "data" / "slider_crank_press.json")
    mech = case.mechanism
    plan = mech.velocity_plans(mech.positions(m=12), omega_1=case.omega_m)
    k = 2
    v = {plan.label(n): np.asarray(plan.v(n)[k], float) for n in plan.order}
    pole = np.array([170.0, 105.0])
    pts = {"p": pole}
    for j, name in enumerate(("a", "b", "s2")):
        pts[name] = pole + v[name] / MU_V + np.array(JITTER[j + 1])
    if mistakes:          # s2 on ab with AS2/AB = 0.325 measured from b
        pts["s2"] = pts["b"] + 0.325 * (pts["a"] - pts["b"])
    doc = new_doc()
    msp = doc.modelspace()
    frame(msp)
    # construction lines: ⟂ AB through a, ∥ guide through p, each past b
    a, b = pts["a"], pts["b"]
    d = (b - a) / np.hypot(*(b - a))
    msp.add_line(tuple(a - 8 * d), tuple(b + 12 * d), dxfattribs={"layer": "Construction"})
    msp.add_line(tuple(pole + np.array([12.0, 0.0])), tuple(b - np.array([14.0, 0.0])),
                 dxfattribs={"layer": "Construction"})
    arrow(msp, pole, a, kind="solid")
    arrow(msp, pole, b, kind="width")
    arrow(msp, a, b, kind="solid")
    arrow(msp, pole, pts["s2"], kind="width")
    msp.add_circle(tuple(pole), 0.6, dxfattribs={"layer": "Plan"})
    for j, name in enumerate(("p", "a", "b", "s2")):
        label(msp, name, pts[name], j)
    L = {s: float(np.hypot(*(pts[t] - pts[f]))) for s, (f, t) in
         {"pa": ("p", "a"), "pb": ("p", "b"), "ab": ("a", "b"), "ps2": ("p", "s2")}.items()}
    v_B = L["pb"] * MU_V * (MU_V if mistakes else 1.0)
    v_BA = L["ab"] * MU_V
    note(msp, "Velocity plan, position 2", 30, 190)
    note(msp, "μv = 0,05 (m/s)/mm", 30, 183)
    note(msp, f"vA = {L['pa'] * MU_V:.3f} m/s", 30, 60)
    note(msp, f"vB = {v_B:.4g} m/s", 30, 54)
    note(msp, f"vBA = {v_BA:.3f} m/s", 30, 48)
    note(msp, f"vS2 = {L['ps2'] * MU_V:.3f} m/s", 30, 42)
    note(msp, f"ω2 = vBA/lAB = {v_BA / 0.4:.3f} rad/s", 30, 36)
    return doc


W1_WORKS = (-50.0, 550.0, -100.0, 125.0, -500.0, 25.0, -50.0)
W1_LABELS = "abcdefgh"


def w1_arrows(mistakes: bool):
    """Start and tip (mm) of each arrow of the staircase, with hand errors; c–d flipped when mistakes."""
    works = list(W1_WORKS)
    if mistakes:
        works[2] = -works[2]
    x0, y = 60.0, 50.0
    out = []
    for k, w in enumerate(works):
        x = x0 + 16.0 * k
        L = w / MU_E + JITTER[k][1] * 1.5
        out.append(((x, y), (x + JITTER[k][0] * 0.1, y + L)))
        y = y + L
    return out


def w1_results(mistakes: bool) -> list[str]:
    if mistakes:
        return ["ΔWmax = 775 J", "ωm = 62,83 rad/s", "ωmax = 63,04 rad/s", "ωmin = 62,62 rad/s", "JF = 0,6458 kg·m²"]
    return ["ΔWmax = 575 J", "ωm = 62,83 rad/s", "ωmax = 62,94 rad/s", "ωmin = 62,73 rad/s", "JF = 43,69 kg·m²"]


def w1_dxf(mistakes: bool):
    doc = new_doc()
    msp = doc.modelspace()
    frame(msp)
    arrows = w1_arrows(mistakes)
    arrow(msp, (40.0, 20.0), (40.0, 200.0), kind="solid")          # the E axis, an arrow too
    note(msp, "E, J", 42, 196)
    msp.add_line((36, 50), (170, 50), dxfattribs={"layer": "Construction"})
    for k, (s, t) in enumerate(arrows):
        arrow(msp, s, t, kind="solid" if k % 2 else "width")
        if k + 1 < len(arrows):
            msp.add_line(t, arrows[k + 1][0], dxfattribs={"layer": "Construction"})
        label(msp, W1_LABELS[k], s, k)
    label(msp, W1_LABELS[len(arrows)], arrows[-1][1], len(arrows))
    note(msp, "Energy indicator diagram, W1", 180, 190)
    note(msp, "μE = 5 J/mm", 180, 183)
    for i, text in enumerate(w1_results(mistakes)):
        note(msp, text, 200, 60 - 6 * i)
    return doc


def w1_svg(mistakes: bool) -> str:
    """The same staircase as Inkscape writes it (y down, a translated group, relative paths, markers)."""
    H = 210.0
    arrows = w1_arrows(mistakes)
    lines = ['<?xml version="1.0" encoding="UTF-8" standalone="no"?>',
             '<svg xmlns="http://www.w3.org/2000/svg" width="297mm" height="210mm" viewBox="0 0 297 210" '
             'version="1.1">',
             '<defs><marker id="Arrow2" orient="auto" style="overflow:visible"><path d="M 0,0 L -3,1 L -3,-1 z" '
             'style="fill:#000000"/></marker></defs>',
             '<g id="layer1" transform="translate(5,-2)">',
             '<path style="fill:none;stroke:#000000;stroke-width:0.25" d="m 15,7 h 272 v 196 h -272 z"/>']
    for k, (s, t) in enumerate(arrows):
        sx, sy = s[0] - 5, H - s[1] + 2
        dy = -(t[1] - s[1])
        lines.append(f'<path style="fill:none;stroke:#000000;stroke-width:0.35;marker-end:url(#Arrow2)" '
                     f'd="m {sx:.3f},{sy:.3f} {t[0] - s[0]:.3f},{dy:.3f}"/>')
        if k + 1 < len(arrows):
            nx = arrows[k + 1][0][0] - t[0]
            lines.append(f'<path style="fill:none;stroke:#000000;stroke-width:0.18;stroke-dasharray:1,1" '
                         f'd="M {t[0] - 5:.3f},{H - t[1] + 2:.3f} h {nx:.3f}"/>')
    for k in range(len(arrows) + 1):
        p = arrows[k][0] if k < len(arrows) else arrows[-1][1]
        dx, dy = LABEL_AT[k % len(LABEL_AT)]
        lines.append(f'<text xml:space="preserve" style="font-size:4.9px;font-family:Arial" x="{p[0] + dx - 5:.3f}" '
                     f'y="{H - (p[1] + dy) + 2:.3f}"><tspan x="{p[0] + dx - 5:.3f}" y="{H - (p[1] + dy) + 2:.3f}">'
                     f'{W1_LABELS[k]}</tspan></text>')
    lines.append('<text style="font-size:4.2px" x="175" y="29">μE = 5 J/mm</text>')
    for i, text in enumerate(w1_results(mistakes)):
        lines.append(f'<text style="font-size:4.2px" x="195" y="{H - (60 - 6 * i) + 2:.3f}">{text}</text>')
    lines += ["</g>", "</svg>"]
    return "\n".join(lines) + "\n"


def press_wittenbauer(mistakes: bool):
    """The press's energy–mass diagram at μ_J = 0.005 kg·m²/mm, μ_T = 4 J/mm on an A3 sheet: the curve through
    the 12 positions (numbered), the axes, the two tangent rays drawn past the ordinate axis, k and l."""
    from graphmethods.dynamics.study import Study
    from graphmethods.dynamics.wittenbauer import wittenbauer

    case = read_case(ROOT / "graphmethods" / "problems" / "data" / "slider_crank_press.json")
    study = Study(case, positions=12, estimate=False)
    J, T = np.asarray(study.J_e, float), np.asarray(study.delta_T, float)
    mu_J, mu_T = 0.005, 4.0
    res = wittenbauer(J_e=J, delta_T=T, omega_m=case.omega_m, delta=case.delta, mu_J=mu_J, mu_T=mu_T)
    doc = ezdxf.new("R2010", setup=True)
    doc.units = ezdxf.units.MM
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (420, 0), (420, 297), (0, 297)], close=True)
    o = np.array([60.0, 255.0])                                   # the origin: J_e = 0, ΔT = 0
    arrow(msp, (o[0], 12.0), (o[0], 290.0), kind="solid")          # ΔT axis
    arrow(msp, (40.0, o[1]), (190.0, o[1]), kind="solid")          # J_e axis
    pts = [o + np.array([J[i] / mu_J, T[i] / mu_T]) + np.array(JITTER[i % 8]) * 0.5 for i in range(12)]
    msp.add_lwpolyline([tuple(q) for q in pts], close=True)
    for i, q in enumerate(pts):
        msp.add_text(str(i), height=2.5).set_placement((q[0] + 1.2, q[1] + 1.0))
    k = o + np.array([0.0, res.k_mm + 0.15])
    l_ = o + np.array([0.0, res.l_mm - 0.2])
    reach = (12.0, 170.0)                                         # the rays' lengths behind and past k, l
    kl = res.kl_mm + 0.35
    if mistakes:                 # k and l on the vertical through the curve's leftmost point (J_e not subtracted)
        x_min = o[0] + float(J.min()) / mu_J
        msp.add_line((x_min, 12.0), (x_min, 280.0))
        # the student marks k and l on that vertical and draws the rays through them (the hand's slip
        # turns each ray about its mark, so the marks stay within the drafting tolerance)
        k = k + (x_min - o[0]) * np.array([1.0, res.tan_psi_max])
        l_ = l_ + (x_min - o[0]) * np.array([1.0, res.tan_psi_min])
        reach = (12.0 + x_min - o[0], 170.0 - (x_min - o[0]))
        kl = float(k[1] - l_[1])
    for start, tan in ((k, res.tan_psi_max), (l_, res.tan_psi_min)):
        tan = math.tan(math.atan(tan) + math.radians(0.15 if tan > res.tan_psi_min else -0.1))   # a hand's slip
        d = np.array([1.0, tan]) / math.hypot(1.0, tan)
        msp.add_line(tuple(start - reach[0] * d), tuple(start + reach[1] * d))
    msp.add_text("k", height=3.5).set_placement((k[0] - 4.5, k[1] + 1.2))
    msp.add_text("l", height=3.5).set_placement((l_[0] - 3.8, l_[1] - 4.0))
    omega = case.n_rpm if mistakes else case.omega_m             # n (rev/min) used as ω in J_F
    J_F = mu_T * kl / (omega ** 2 * case.delta)
    for i, text in enumerate(("Energy–mass diagram (Wittenbauer), press, m = 12", "μJ = 0,005 kg·m²/mm", "μT = 4 J/mm",
                              f"tg ψmax = {res.tan_psi_max:.4f}", f"tg ψmin = {res.tan_psi_min:.4f}",
                              f"JF = {J_F:.4g} kg·m²")):
        msp.add_text(text, height=3.5).set_placement((250.0, 60.0 - 7.0 * i))
    return doc


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    ezdxf.options.write_fixed_meta_data_for_testing = True      # no dates: the same files every run
    for mistakes in (False, True):
        tag = "mistakes" if mistakes else "correct"
        press_plan(mistakes).saveas(OUT / f"press_plan_{tag}.dxf")
        w1_dxf(mistakes).saveas(OUT / f"w1_{tag}.dxf")
        (OUT / f"w1_{tag}.svg").write_text(w1_svg(mistakes), encoding="utf-8")
        press_wittenbauer(mistakes).saveas(OUT / f"press_wittenbauer_{tag}.dxf")
    print(f"wrote {', '.join(sorted(p.name for p in OUT.iterdir()))} in {OUT}")


if __name__ == "__main__":
    main()
