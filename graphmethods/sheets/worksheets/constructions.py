"""The constructions a worksheet's key draws (and the checker's overlay draws again at the student's
scales): the staircase of excess works, the energy-mass diagram and its rays, a velocity plan, the
regions between moment curves, the slider-crank scheme.
"""

from __future__ import annotations

import math

import numpy as np

from graphmethods.scene import Scale, Text, Vector, notation as get_notation
from graphmethods.scene.elements import Axis, Element, Line, Point, Region, make_label
from graphmethods.scene.primitives import DASHED, MAIN, THIN, Style
from graphmethods.sheets.worksheets.elements import RED, SMALL_MM, TEXT_MM, THICK, ColorText, arc, ground, pin, slider
from graphmethods.sheets.worksheets.variants import SEGMENTS

# ----------------------------------------------------------------------------- constructions
# (drawn on the key pages, and by graphmethods.sheets.check on an overlay at a student's scales)

def staircase(first_x: float, y0: float, works, *, mu_E: float, step_mm: float, labels, nt, occ=None,
              wrong: dict | None = None, name: str = "staircase") -> list[Element]:
    """The energy indicator: arrows A_i/μ_E (up for a gain), ``step_mm`` apart, from (first_x, y0).

    ``wrong`` maps an interval index to a student's (wrong) arrow length in mm: that arrow is drawn
    red with the student's value beside it. Returns the elements (vectors named ``vector-ab`` …).
    """
    from graphmethods.sheets.layout import Occupancy

    nt = get_notation(nt)
    occ = occ or Occupancy()
    wrong = wrong or {}
    work = np.asarray(works, dtype=float)
    E = np.concatenate(([0.0], np.cumsum(work)))
    s_E = Scale(nt.sym("mu_E"), nt.unit("J"), mu_E)
    n = work.size
    xs = [first_x + k * step_mm for k in range(n)]

    def y(v):
        return y0 - s_E.to_mm(float(v))

    els: list[Element] = [Line((first_x - 6.0, y0), (xs[-1] + 6.0, y0), style=DASHED, name=f"{name}-start")]
    for k in range(n - 1):
        els.append(Line((xs[k], y(E[k + 1])), (xs[k + 1], y(E[k + 1])), style=DASHED,
                        name=f"{name}-level-{labels[k + 1]}"))
    vecs = []
    for k in range(n):
        bad = k in wrong
        style = Style(stroke=RED, width_mm=0.45) if bad else Style(width_mm=0.35)
        vec = Vector.of((xs[k], y(E[k])), value=float(work[k]), scale=s_E, angle_deg=90.0, style=style,
                        name=f"vector-{labels[k]}{labels[k + 1]}")
        vecs.append(vec)
    for e in els + vecs:
        occ.add_primitives(e.primitives())
    texts: list[Element] = []
    for k in range(n + 1):
        at = (xs[0], y0) if k == 0 else (xs[k - 1], y(E[k]))
        dirs = ("w", "nw", "sw") if k == 0 else ("e", "ne", "se", "w", "nw", "sw", "n", "s")
        lab = occ.place_label(at, labels[k], dirs, size_mm=TEXT_MM, gap_mm=1.0)
        texts.append(Text((lab.x, lab.y), labels[k], size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-name-{k}"))
    for k, vec in enumerate(vecs):
        text = nt.number(work[k], plus=True)
        lab = occ.place_label(vec.mid, text, ("w", "e", "nw", "sw", "ne", "se"), size_mm=SMALL_MM, gap_mm=1.2)
        texts.append(Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=f"{name}-value-{k + 1}"))
        if k in wrong:
            t = f"{nt.number(wrong[k])} {nt.unit('mm')}?"
            lab, leader = occ.place_label_with_leader(vec.mid, t, ("e", "w", "ne", "se", "nw", "sw"), size_mm=SMALL_MM,
                                                      gap_mm=3.0)
            if leader is not None:                  # where the staircase is dense: further off, with a leader
                texts.append(Line(leader[0], leader[1], style=Style(stroke=RED, width_mm=0.18),
                                  name=f"{name}-student-{k + 1}-leader"))
            texts.append(ColorText((lab.x, lab.y), t, size_mm=SMALL_MM, anchor=lab.anchor, color=RED,
                                   name=f"{name}-student-{k + 1}"))
    return els + vecs + texts


def extremes(first_x: float, y0: float, works, *, mu_E: float, step_mm: float, nt, unit_J: str = "J",
             occ=None, name: str = "extremes") -> list[Element]:
    """E_max and E_min of a staircase marked, their levels carried right, ΔW_max dimensioned."""
    from graphmethods.scene import Dimension

    nt = get_notation(nt)
    work = np.asarray(works, dtype=float)
    E = np.concatenate(([0.0], np.cumsum(work)))
    s_E = Scale("μ", "J", mu_E)
    n = work.size
    i_max, i_min = int(np.argmax(E)), int(np.argmin(E))
    x_end = first_x + (n - 1) * step_mm
    x_dim = x_end + 12.0

    def at(k):
        return (first_x + max(k - 1, 0) * step_mm, y0 - s_E.to_mm(float(E[k])))

    els: list[Element] = []
    for k, key in ((i_max, "max"), (i_min, "min")):
        p = at(k)
        els.append(Line(p, (x_dim + 2.0, p[1]), style=DASHED, name=f"{name}-level-{key}"))
        els.append(Point(p, radius_mm=1.1, filled=False, name=f"{name}-mark-{key}"))
    dW = float(E[i_max] - E[i_min])
    els.append(Dimension((x_dim, at(i_min)[1]), (x_dim, at(i_max)[1]),
                         f"{nt.sym('delta_W_max')} = {nt.number(dW)} {nt.unit(unit_J)}", size_mm=TEXT_MM,
                         name=f"{name}-dimension"))
    if occ is not None:
        for e in els:
            occ.add_primitives(e.primitives())
    return els


def energy_mass_construction(res, *, origin, box, axes=(), nt="en", prefix: str = "key-") -> list[Element]:
    """The energy–mass diagram of a construction ``res`` (its curve, rays, k, l, kl, ψ, position numbers)
    at ``origin`` (page point of J_e = 0, ΔT = 0), inside ``box``, drawn by
    :func:`graphmethods.sheets.wittenbauer.diagram_elements` over the page's ``axes`` (J_e, ΔT: it keeps its
    labels off them and out of the J_e axis's row of values, and breaks its rays behind their values)."""
    from graphmethods.scene.elements import label_bbox
    from graphmethods.scene.primitives import Label
    from graphmethods.sheets.dynamics import FastOccupancy
    from graphmethods.sheets.linkage_figures import broken_behind
    from graphmethods.sheets.wittenbauer import diagram_elements

    occ = FastOccupancy()
    J_axis = next((a for a in axes if isinstance(a, Axis) and a.direction == "x"), None)
    T_axis = next((a for a in axes if isinstance(a, Axis) and a.direction == "y"), None)
    page_axes = (T_axis, J_axis) if J_axis is not None and T_axis is not None else None
    for a in axes:
        if page_axes is None or not isinstance(a, Axis):     # plain lines (an overlay's): kept clear of
            occ.add_primitives(a.primitives())
    J = np.asarray(res.x_mm) * res.mu_J
    T = np.asarray(res.y_mm) * res.mu_T
    ox, oy = origin
    T_hi = min(max(float(T.max()), res.k_mm * res.mu_T, 0.0), (oy - box[1] - 6.0) * res.mu_T)
    T_lo = max(min(float(T.min()), res.l_mm * res.mu_T, 0.0), -(box[3] - oy - 2.0) * res.mu_T)
    # the rays stop at the ordinate axis (k and l are on it): left of it they would cross its tick values
    els = diagram_elements(res, origin=origin, nt=nt, occ=occ, clip=(ox, *box[1:]), J_to=float(J.max()), T_hi=T_hi,
                           T_lo=T_lo, within=box, prefix=prefix, page_axes=page_axes)
    # a ray is broken for the axes' values it passes (ГОСТ 2.303): the axis keeps every value under the key's rays
    values = [label_bbox(p) for a in axes for p in a.primitives() if isinstance(p, Label)]
    rays = [e for e in els if e.name.startswith(f"{prefix}ray-")]
    kept = [e for e in els if e.name not in (f"{prefix}axis-J", f"{prefix}axis-T") and e not in rays
            and all(e is not a for a in page_axes or ())]
    return kept + broken_behind(rays, values)


def velocity_plan(pole, vectors: dict, *, mu_v: float, link_dir, nt="en", wrong: dict | None = None, occ=None,
                  name: str = "plan") -> list[Element]:
    """A slider-crank's velocity plan from ``pole``: pa, pb, ab, ps2 with the construction lines.

    ``vectors`` maps plan labels (p, a, b, s2) to velocities (m/s); ``link_dir`` is the unit vector A→B
    (the line through a is ⊥ AB, the one through p ∥ the guide). ``wrong`` maps a segment (``"pb"``) to
    a student's length in mm: drawn red with the value beside it.
    """
    nt = get_notation(nt)
    from graphmethods.sheets.layout import Occupancy

    occ = occ or Occupancy()
    wrong = wrong or {}
    px, py = pole

    def P(v):
        return (px + float(v[0]) / mu_v, py - float(v[1]) / mu_v)

    pts = {k: P(v) for k, v in vectors.items()}
    a, b = np.array(pts["a"]), np.array(pts["b"])
    u = np.array([float(link_dir[0]), -float(link_dir[1])])       # A→B on paper
    n = np.array([-u[1], u[0]])                                   # ⊥ AB on paper
    t = [float((p - a) @ n) for p in (a, b)]
    t0, t1 = min(t) - 12.0, max(t) + 12.0
    els: list[Element] = [
        Line(tuple(a + t0 * n), tuple(a + t1 * n), style=THIN, name=f"{name}-line-perp-AB"),
        Line((min(px, b[0]) - 12.0, py), (max(px, b[0]) + 12.0, py), style=THIN, name=f"{name}-line-guide")]
    for seg, (f, to) in SEGMENTS.items():
        style = Style(stroke=RED, width_mm=0.45) if seg in wrong else Style(width_mm=0.35)
        els.append(Vector(pts[f], pts[to], style=style, name=f"{name}-{seg}"))
    for e in els:
        occ.add_primitives(e.primitives())
    occ.add_box((px - 1.0, py - 1.0, px + 1.0, py + 1.0))
    for lab_text in ("p", "a", "b", "s2"):
        text = "s_{2}" if lab_text == "s2" else lab_text
        lab = occ.place_label(pts[lab_text], text, ("nw", "ne", "sw", "se", "n", "s", "w", "e"), size_mm=TEXT_MM,
                              gap_mm=1.0)
        els.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-name-{lab_text}"))
    for seg in SEGMENTS:
        if seg in wrong:
            f, to = SEGMENTS[seg]
            mid = ((pts[f][0] + pts[to][0]) / 2, (pts[f][1] + pts[to][1]) / 2)
            txt = f"{seg} = {nt.number(wrong[seg])} {nt.unit('mm')}?"
            lab = occ.place_label(mid, txt, ("e", "w", "ne", "nw", "se", "sw"), size_mm=SMALL_MM, gap_mm=2.0)
            els.append(ColorText((lab.x, lab.y), txt, size_mm=SMALL_MM, anchor=lab.anchor, color=RED,
                                 name=f"{name}-student-{seg}"))
    return els


def moment_regions(frame, cycle, *, wrong: dict | None = None, nt="en", occ=None,
                   name: str = "moments") -> list[Element]:
    """M_d and M_r drawn through ``frame`` (φ from the period start, rad → mm), the intervals hatched,
    the boundary points a, b, … labelled. ``wrong`` maps an interval index to a student's area (mm²):
    that region is outlined red with the value written in it."""
    nt = get_notation(nt)
    from graphmethods.sheets.layout import Occupancy

    occ = occ or Occupancy()
    wrong = wrong or {}
    M_d, M_r = cycle.M_d, cycle.M_r
    phi0 = float(M_d.start)
    els: list[Element] = []
    regions = []
    for i in range(cycle.work.size):
        a, b = float(cycle.phi[i]), float(cycle.phi[i + 1])
        pd, md = _piece(M_d, a, b)
        pr, mr = _piece(M_r, a, b)
        outline = frame.pts(np.concatenate((pd, pr[::-1])) - phi0, np.concatenate((md, mr[::-1])))
        gain = cycle.work[i] > 0
        bad = i in wrong
        regions.append(Region(outline, hatch_angle_deg=45.0 if gain else 135.0, hatch_spacing_mm=2.5,
                              style=Style(stroke=RED, width_mm=0.18) if bad else THIN,
                              outline_style=Style(stroke=RED, width_mm=0.45) if bad else None,
                              name=f"{name}-region-{i + 1}"))
    cd = frame.curve(M_d.phi - phi0, M_d.M, style=MAIN, name=f"{name}-M_d")
    cr = frame.curve(M_r.phi - phi0, M_r.M, style=MAIN, name=f"{name}-M_r")
    els += regions + [cd, cr]
    for e in (cd, cr):
        occ.add_primitives(e.primitives())
    for i in range(cycle.work.size):
        occ.add_primitives(regions[i].primitives())
    for k, ph in enumerate(cycle.phi):
        at = frame.pt(float(ph) - phi0, float(M_d(float(ph))) if k < len(cycle.phi) - 1 else float(M_d.M[-1]))
        lab = occ.place_label(at, cycle.labels[k], ("n", "nw", "ne", "s", "sw", "se"), size_mm=TEXT_MM, gap_mm=1.0)
        els.append(Point(at, radius_mm=0.6, name=f"{name}-dot-{k}"))
        els.append(Text((lab.x, lab.y), cycle.labels[k], size_mm=TEXT_MM, anchor=lab.anchor,
                        name=f"{name}-name-{k}"))
    for i, val in sorted(wrong.items()):
        shape = regions[i].shape()
        c = shape.representative_point()
        txt = f"{nt.number(val)} {nt.unit('mm²')}?"
        lab = occ.place_label((c.x, c.y), txt, ("n", "s", "e", "w", "ne", "se"), size_mm=SMALL_MM, gap_mm=0.5)
        els.append(ColorText((lab.x, lab.y), txt, size_mm=SMALL_MM, anchor=lab.anchor, color=RED,
                             name=f"{name}-student-{i + 1}"))
    for key, _curve, el in (("M_d", M_d, cd), ("M_r", M_r, cr)):
        lab = occ.place_label(el.end, nt.sym(key), ("e", "ne", "se"), size_mm=TEXT_MM, gap_mm=1.5)
        els.append(Text((lab.x, lab.y), nt.sym(key), size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-{key}-name"))
    return els


def _piece(curve, a: float, b: float):
    inner = (curve.phi > a) & (curve.phi < b)
    left_b = curve.limits(np.array([b]))[0][0]
    right_a = curve.limits(np.array([a]))[1][0]
    return (np.concatenate(([a], curve.phi[inner], [b])), np.concatenate(([right_a], curve.M[inner], [left_b])))


def region_perimeters_mm(cycle, *, mu_M: float, mu_phi: float) -> np.ndarray:
    """Perimeter (mm) of each interval's region between M_d and M_r, drawn at μ_M (N·m/mm), μ_φ (rad/mm)."""
    out = []
    for i in range(cycle.work.size):
        a, b = float(cycle.phi[i]), float(cycle.phi[i + 1])
        pd, md = _piece(cycle.M_d, a, b)
        pr, mr = _piece(cycle.M_r, a, b)
        x = np.concatenate((pd, pr[::-1], pd[:1])) / mu_phi
        y = np.concatenate((md, mr[::-1], md[:1])) / mu_M
        out.append(float(np.hypot(np.diff(x), np.diff(y)).sum()))
    return np.asarray(out)


def slider_crank_scheme(O, *, r: float, l: float, e: float, l_AS2: float, phi_deg: float, mu_l: float,
                        nt="en", guide_mm: float = 40.0, name: str = "scheme") -> list[Element]:
    """A slider-crank drawn at μ_l (m/mm) in the position φ: ground at O, crank, rod, slider on its
    guide (the line y = e), S2, the angle φ and the crank's sense."""
    ox, oy = O
    ph = math.radians(phi_deg)
    A = (r * math.cos(ph), r * math.sin(ph))
    xB = A[0] + math.sqrt(l * l - (e - A[1]) ** 2)
    B = (xB, e)
    S = (A[0] + (B[0] - A[0]) * l_AS2 / l, A[1] + (B[1] - A[1]) * l_AS2 / l)

    def P(p):
        return (ox + p[0] / mu_l, oy - p[1] / mu_l)

    pO, pA, pB, pS = P((0.0, 0.0)), P(A), P(B), P(S)
    els: list[Element] = [
        Line((ox - 6.0, oy), (ox + r / mu_l + 14.0, oy), style=Style(width_mm=0.18, dash=(6.0, 1.5, 1.0, 1.5)),
             name=f"{name}-x-axis"),
        arc(pO, 9.0, 0.0, phi_deg, name=f"{name}-phi-arc"),
        arc(pO, 13.0, phi_deg + 18.0, phi_deg + 58.0, arrow=True, name=f"{name}-omega"),
        slider(pB, guide_mm=guide_mm, name=f"{name}-slider"),
        Line(pO, pA, style=THICK, name=f"{name}-crank"),
        Line(pA, pB, style=THICK, name=f"{name}-rod"),
        ground(pO, name=f"{name}-ground"), pin(pA, name=f"{name}-pin-A"),
        Point(pS, radius_mm=0.9, name=f"{name}-S2"),
    ]
    from graphmethods.sheets.layout import Occupancy

    occ = Occupancy()
    for el in els:
        occ.add_primitives(el.primitives())
    phi_lab = None
    for frac in (0.5, 0.35, 0.65, 0.2, 0.8):
        mid = math.radians(phi_deg * frac)
        at = (pO[0] + 9.0 * math.cos(mid), pO[1] - 9.0 * math.sin(mid))
        d = ("e" if math.cos(mid) > 0.4 else "w" if math.cos(mid) < -0.4 else "") + ""
        d = ("n" if math.sin(mid) > 0.4 else "s" if math.sin(mid) < -0.4 else "") + d
        phi_lab = occ.first_free(at, "φ", (d or "n",), (0.8, 2.0), TEXT_MM, None)
        if phi_lab is not None:
            break
    if phi_lab is None:
        phi_lab = make_label((pO[0] + 11.5, pO[1] - 2.0), "φ", size_mm=TEXT_MM, valign="middle")
    occ.add_label(phi_lab)
    om_lab = None
    for turn in (60.0, 38.0, 75.0, 25.0, 90.0):     # beside the arc of ω₁, clear of its arrowhead
        w = math.radians(phi_deg + turn)
        at = (pO[0] + 14.0 * math.cos(w), pO[1] - 14.0 * math.sin(w))
        d = ("n" if math.sin(w) > 0.4 else "s" if math.sin(w) < -0.4 else "") + (
            "e" if math.cos(w) > 0.4 else "w" if math.cos(w) < -0.4 else "")
        om_lab = occ.first_free(at, "ω_{1}", (d or "n",), (1.0, 2.5), TEXT_MM, None)
        if om_lab is not None:
            break
    if om_lab is None:
        w = math.radians(phi_deg + 60.0)
        om_lab = make_label((pO[0] + 15.0 * math.cos(w), pO[1] - 15.0 * math.sin(w)), "ω_{1}", size_mm=TEXT_MM,
                            anchor="start" if math.cos(w) >= 0 else "end", valign="middle")
    texts = [Text((phi_lab.x, phi_lab.y), "φ", size_mm=TEXT_MM, anchor=phi_lab.anchor, name=f"{name}-phi"),
             Text((om_lab.x, om_lab.y), "ω_{1}", size_mm=TEXT_MM, anchor=om_lab.anchor, name=f"{name}-omega-name")]
    for t in texts:
        occ.add_primitives(t.primitives())
    for txt, at, dirs in (("O", pO, ("w", "nw", "sw", "e", "ne")), ("A", pA, ("n", "nw", "ne", "w", "e", "s")),
                          ("B", pB, ("ne", "n", "nw")), ("S_{2}", pS, ("s", "n", "se", "sw", "ne", "nw"))):
        lab = occ.place_label(at, txt, dirs, size_mm=TEXT_MM, gap_mm=2.6 if txt == "O" else 1.8)
        texts.append(Text((lab.x, lab.y), txt, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-name-{txt[0]}"))
    return els + texts


