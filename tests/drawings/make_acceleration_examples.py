"""Make the acceleration-plan examples (run once; the files are committed and tests check that exactly the
planted mistakes are found):

    python tests/drawings/make_acceleration_examples.py

* graphmethods/problems/data/answers/*_acc_*.toml: typed answers (lengths measured to 0.1 mm, as a student
  reads a ruler; ε to 3 significant figures), a correct one per linkage and one per usual mistake;
* graphmethods/problems/data/drawings/*_acc_*.dxf (and the slotted lever's mistakes as Inkscape SVG too):
  acceleration plans drawn as a student draws them in CAD
  (LINEs with SOLID or polyline-width heads, TEXT letters beside the points at varying offsets, hand errors of
  up to 0.2 mm), correct and with the Coriolis sense reversed (slotted lever) and a normal component drawn
  away from its centre (press).

A mistaken plan is the construction with that mistake made (graphmethods.sheets.check.acceleration.Problem):
the student draws it through to the end, so every later vector follows from the mistake.
"""

from __future__ import annotations

import pathlib

import numpy as np

from graphmethods.kinematics import read_case
from graphmethods.sheets.acceleration import _Problem
from graphmethods.sheets.check import acceleration as ca

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "graphmethods" / "problems" / "data"
MU_A = {"press": 1.0, "slotted-lever": 0.04}
POSITION = {"press": 2, "slotted-lever": 2}
FILE = {"press": "slider_crank_press.json", "slotted-lever": "slotted_lever.json"}


def problem(name: str) -> ca.Problem:
    pr = _Problem(read_case(DATA / FILE[name]), m=12, omega_1=None, epsilon_1=0.0)
    return ca.Problem(pr.linkage, POSITION[name], 12, pr.omega_1, 0.0)


def answers_text(name: str, stem: str, comment: str, plan, mu_a: float, crank: str, *, problem_id: str,
                 position: bool = True) -> str:
    lines = [f"# {comment}", f'problem = "{problem_id}"', f'student = "Example student ({stem})"', "",
             "[page]", 'size = "A4"', 'orientation = "landscape"', "", "[acceleration_plan]"]
    if position:
        lines += ["positions = 12", f"position = {plan.position}"]
    lines.append(f"mu_a = {mu_a:g}")
    for c in ca.vectors(plan):
        lines.append(f"{ca.key_of(c.symbol)}_mm = {c.magnitude / mu_a:.1f}")
    for link in ca.turning_links(plan, crank):
        e = plan.epsilon[link]
        lines.append(f"epsilon_{link} = {float(f'{abs(e):.3g}'):g}")
        lines.append(f'epsilon_{link}_sense = "{"ccw" if e > 0 else "cw"}"')
    return "\n".join(lines) + "\n"


TYPED = {
    # file stem: (problem, mistake kw for Problem.plan, comment)
    "press_acc_correct": ("press", {}, "The press's acceleration plan in position 2, correct."),
    "press_acc_mistakes": ("press", {"reversed_link": "2"},
                           "Planted: a^n_BA drawn from a away from the centre A (normal_reversed); a^τ_BA, a_B, "
                           "a_S2 and ε_2 follow from it."),
    "slotted_lever_acc_correct": ("slotted-lever", {}, "The slotted lever's acceleration plan in position 2, correct."),
    "slotted_lever_acc_mistakes": ("slotted-lever", {"coriolis_factor": -2j},
                                   "Planted: the Coriolis component turned the wrong way (coriolis_reversed); "
                                   "the rest of the plan follows from it."),
    "slotted_lever_acc_factor": ("slotted-lever", {"coriolis_factor": 1j},
                                 "Planted: a^k = ω3·v_rel, the factor 2 missing (coriolis_factor_2)."),
    "slotted_lever_acc_no_coriolis": ("slotted-lever", {"coriolis_factor": 0j},
                                    "Planted: the Coriolis component forgotten (coriolis_forgotten): no a^k, "
                                    "a^r drawn from a."),
    "slotted_lever_acc_length": ("slotted-lever", {"length_link": "3", "length": 0.5},
                                 "Planted: a^n_A3O3 = ω3²·O3B (the lever's whole length) instead of ω3²·O3A3 "
                                 "(normal_wrong_length)."),
}


LETTER = {"n_BA": "n2", "n_A3O3": "n3", "k_A3A2": "k", "n_A": "n1"}
DRAWN = {
    # file: (problem, mistake kw, μ_a of the student's drawing)
    "press_acc_correct.dxf": ("press", {}, 1.0),
    "press_acc_mistakes.dxf": ("press", {"reversed_link": "2"}, 1.0),
    "slotted_lever_acc_correct.dxf": ("slotted-lever", {}, 0.04),
    "slotted_lever_acc_mistakes.dxf": ("slotted-lever", {"coriolis_factor": -2j}, 0.04),
}


def layout(name: str, kw: dict, mu_a: float):
    """(plan, its vectors, the points drawn (mm, y up, hand errors added), each letter's corner, the notes)."""
    import make_student_drawings as sd

    pr = problem(name)
    plan = pr.plan(**kw)
    comps = ca.vectors(plan)
    labels = sorted({lb for c in comps for lb in (c.start, c.end)} - {"π"})
    z = {lb: plan.images[lb] / mu_a for lb in ["π", *labels]}
    xs, ys = [v.real for v in z.values()], [v.imag for v in z.values()]
    pole = np.array([160.0 - (min(xs) + max(xs)) / 2, 110.0 - (min(ys) + max(ys)) / 2])
    pts = {"π": pole}
    for j, lb in enumerate(labels):
        pts[lb] = pole + np.array([z[lb].real, z[lb].imag]) + np.array(sd.JITTER[j % len(sd.JITTER)])
    letters = {}
    for j, lb in enumerate(["π", *labels]):
        P = pts[lb]
        q = min((Q for k, Q in pts.items() if k != lb and float(np.hypot(*(Q - P))) > 0.5),
                key=lambda Q: float(np.hypot(*(Q - P))))
        away = (P - q) / float(np.hypot(*(P - q)))
        letters[LETTER.get(lb, lb)] = P + away * (2.6 + 0.3 * (j % 3)) + np.array([-1.0, -1.7])
    notes = [f"Acceleration plan, position {plan.position}", f"μa = {mu_a:g} (m/s²)/mm".replace(".", ",")]
    for link in ca.turning_links(plan, pr.linkage.crank.link):
        tau = next(c for c in comps if c.kind == "tangential" and c.link == link)
        L = float(np.hypot(*(pts[tau.end] - pts[tau.start])))
        notes.append(f"ε{link} = aτ/l = {L * mu_a / plan.lengths[link]:.3f} rad/s²")
    return plan, comps, pts, letters, notes


def svg_drawing(name: str, kw: dict, mu_a: float) -> str:
    """The same plan as Inkscape writes it: y down, a translated group, relative paths, marker-end heads."""
    plan, comps, pts, letters, notes = layout(name, kw, mu_a)
    H = 210.0

    def P(q):
        return q[0] - 5.0, H - q[1] + 2.0

    out = ['<?xml version="1.0" encoding="UTF-8" standalone="no"?>',
           '<svg xmlns="http://www.w3.org/2000/svg" width="297mm" height="210mm" viewBox="0 0 297 210" version="1.1">',
           '<defs><marker id="Arrow2" orient="auto" style="overflow:visible"><path d="M 0,0 L -3,1 L -3,-1 z" '
           'style="fill:#000000"/></marker></defs>',
           '<g id="layer1" transform="translate(5,-2)">',
           '<path style="fill:none;stroke:#000000;stroke-width:0.25" d="m 15,7 h 272 v 196 h -272 z"/>']
    for st in plan.steps:
        for ln in st.lines:
            d = np.array([ln.direction.real, ln.direction.imag])
            t = float((pts[st.label] - pts[ln.through]) @ d)
            a, b = pts[ln.through] + d * (min(0.0, t) - 10.0), pts[ln.through] + d * (max(0.0, t) + 10.0)
            (ax, ay), (bx, by) = P(a), P(b)
            out.append('<path style="fill:none;stroke:#808080;stroke-width:0.18" '
                       f'd="M {ax:.3f},{ay:.3f} L {bx:.3f},{by:.3f}"/>')
    for c in comps:
        (sx, sy), (tx, ty) = P(pts[c.start]), P(pts[c.end])
        out.append(f'<path style="fill:none;stroke:#000000;stroke-width:0.35;marker-end:url(#Arrow2)" '
                   f'd="m {sx:.3f},{sy:.3f} {tx - sx:.3f},{ty - sy:.3f}"/>')
    for text, at in letters.items():
        x, y = P(at)
        out.append(f'<text xml:space="preserve" style="font-size:4.9px;font-family:Arial" x="{x:.3f}" y="{y:.3f}">'
                   f'<tspan x="{x:.3f}" y="{y:.3f}">{text}</tspan></text>')
    for i, text in enumerate(notes):
        out.append(f'<text style="font-size:4.2px" x="20" y="{15 + 6 * i if i < 2 else 190:.3f}">{text}</text>')
    out += ["</g>", "</svg>"]
    return "\n".join(out) + "\n"


def drawing(name: str, kw: dict, mu_a: float):
    """The plan (with the mistake made) as a student draws it in CAD at ``mu_a``."""
    import make_student_drawings as sd

    pr = problem(name)
    plan = pr.plan(**kw)
    comps = ca.vectors(plan)
    labels = sorted({lb for c in comps for lb in (c.start, c.end)} - {"π"})
    z = {lb: plan.images[lb] / mu_a for lb in ["π", *labels]}
    xs, ys = [v.real for v in z.values()], [v.imag for v in z.values()]
    pole = np.array([160.0 - (min(xs) + max(xs)) / 2, 110.0 - (min(ys) + max(ys)) / 2])
    pts = {"π": pole}
    for j, lb in enumerate(labels):
        pts[lb] = pole + np.array([z[lb].real, z[lb].imag]) + np.array(sd.JITTER[j % len(sd.JITTER)])
    doc = sd.new_doc()
    msp = doc.modelspace()
    sd.frame(msp)
    for st in plan.steps:                         # the construction lines, each past the point found
        for ln in st.lines:
            P0 = pts[ln.through]
            d = np.array([ln.direction.real, ln.direction.imag])
            t = float((pts[st.label] - P0) @ d)
            msp.add_line(tuple(P0 + d * (min(0.0, t) - 10.0)), tuple(P0 + d * (max(0.0, t) + 10.0)),
                         dxfattribs={"layer": "Construction"})
    for j, c in enumerate(comps):
        sd.arrow(msp, pts[c.start], pts[c.end], kind="solid" if j % 2 == 0 else "width")
    msp.add_circle(tuple(pole), 0.6, dxfattribs={"layer": "Plan"})
    for j, lb in enumerate(["π", *labels]):       # each letter beside its point, away from the nearest other one
        P = pts[lb]
        q = min((Q for k, Q in pts.items() if k != lb and float(np.hypot(*(Q - P))) > 0.5),
                key=lambda Q: float(np.hypot(*(Q - P))))
        away = (P - q) / float(np.hypot(*(P - q)))
        at = P + away * (2.6 + 0.3 * (j % 3)) + np.array([-1.0, -1.7])      # the text's corner, its middle there
        msp.add_text(LETTER.get(lb, lb), height=3.5, dxfattribs={"layer": "Text"}).set_placement(tuple(at))
    sd.note(msp, f"Acceleration plan, position {plan.position}", 25, 195)
    sd.note(msp, f"μa = {mu_a:g} (m/s²)/mm".replace(".", ","), 25, 189)
    crank = pr.linkage.crank.link
    for i, link in enumerate(ca.turning_links(plan, crank)):
        tau = next(c for c in comps if c.kind == "tangential" and c.link == link)
        L = float(np.hypot(*(pts[tau.end] - pts[tau.start])))
        sd.note(msp, f"ε{link} = aτ/l = {L * mu_a / plan.lengths[link]:.3f} rad/s²", 25, 20 - 6 * i)
    return doc


def main() -> None:
    import sys

    import ezdxf

    sys.path.insert(0, str(pathlib.Path(__file__).parent))
    ezdxf.options.write_fixed_meta_data_for_testing = True      # no dates: the same files every run
    for fname, (name, kw, mu_a) in DRAWN.items():
        drawing(name, kw, mu_a).saveas(DATA / "drawings" / fname)
    (DATA / "drawings" / "slotted_lever_acc_mistakes.svg").write_text(
        svg_drawing("slotted-lever", {"coriolis_factor": -2j}, 0.04), encoding="utf-8")
    out = DATA / "answers"
    for stem, (name, kw, comment) in TYPED.items():
        pr = problem(name)
        plan = pr.plan(**kw)
        text = answers_text(name, stem, comment, plan, MU_A[name], pr.linkage.crank.link, problem_id=name)
        (out / f"{stem}.toml").write_text(text, encoding="utf-8")
    # a worksheet variant whose crank speeds up (ε₁ ≠ 0): its a^τ_A forgotten
    from graphmethods.sheets import worksheets as ws

    v = ws.variant("acceleration-plan", seed=1, number=4)
    assert v.epsilon_1 != 0.0
    pr = ca.Problem(v.linkage, v.position, 12, v.omega_1, 0.0, v.mu_a)
    text = answers_text("", "crank", "Planted: the crank's a^τ_A = ε1·OA forgotten (crank_tangential_forgotten); "
                        "the plan is drawn from a^n_A alone.", pr.plan(), v.mu_a, v.linkage.crank.link,
                        problem_id=v.id, position=False)
    (out / "worksheet_acc_crank.toml").write_text(text, encoding="utf-8")


if __name__ == "__main__":
    main()
