"""Checking a drawing made in CAD: the student's velocity plan, energy indicator or energy–mass diagram as
DXF (or SVG, read by :mod:`graphmethods.sheets.check.svg_reader`), drawn at their own scales, read, measured
and checked as :func:`graphmethods.sheets.check.check` checks an answers file.

What is read (mm, y up; the DXF through :func:`graphmethods.render.dxf.read_drawing`, an SVG through
:func:`graphmethods.sheets.check.svg_reader.read_svg`):

* **arrows**: a straight segment with an arrowhead at one end (a filled triangle: SOLID, HATCH, a
  polyline segment of changing width, an SVG filled path, or an SVG ``marker-end``/``marker-start``);
* **labels**: short texts (``p``, ``a``, ``b``, ``s2``, ``s₂``; ``a`` … ``h``) placed near the ends of
  the arrows, as students place them; each is given to the nearest arrow end within 10 mm;
* **scales and results** written on the sheet: ``μv = 0.05 (m/s)/mm``, ``μE = 5 J/mm``,
  ``position 2``, ``vB = 3.03 m/s``, ``ΔWmax = 575 J``, ``JF = 43.69 kg·m²`` … (subscripts flat or not,
  ``,`` or ``.`` as the decimal sign).

A **velocity plan** is the set of labelled points: the lengths pa, pb, ab, ps₂ between them and their
directions. An **energy indicator** is the longest staircase of vertical arrows, each starting at the
level where the previous one ended, ordered by their labels (``a`` … ``h``) or else left to right.

From these the same answers dict an answers file would give is built, and the existing checker is called,
so the verdicts, the tolerances (±0.5 mm, propagated to J_F) and the names of the usual mistakes are
those of ``graphmethods check``. A velocity plan adds the direction of each vector, within ±0.5° plus
the angle 0.5 mm subtends at its length.

An **energy–mass (Wittenbauer) diagram** of the press (or of a wittenbauer worksheet): kl between the
letters ``k`` and ``l`` placed at the crossings of the tangent rays with the ordinate axis, the slope of
each ray against ψ_max, ψ_min, and μ_J, μ_T, tg ψ, J_F from the texts; the axes (the longest upright and
level arrows) place the overlay.

An **acceleration plan** (an acceleration-plan worksheet, the slotted lever, or the press when the pole is
lettered ``π``): the pole π and the lettered images (``a``, ``b``, ``s2``, ``a3`` …, the ends of the normal
components ``n2``/``n3`` or ``nBA``, of the Coriolis one ``k``), each vector of the plan measured (length and
direction) between its two letters, μ_a (``μa = 0,04 (m/s²)/mm``) and ε (``ε3 = 3.73 rad/s²``) from the
texts; checked by :mod:`graphmethods.sheets.check.acceleration` (a Coriolis component drawn the wrong way
or a normal one away from its centre shows in the direction of that vector).

When the labels are missing, :func:`check_drawing` says which points it found and asks for a mapping
(``points={"a": (x, y), ...}``, drawing mm).

>>> import pathlib
>>> d = pathlib.Path(__file__).parents[2] / "problems" / "data" / "drawings"
>>> rep = check_drawing("W1", d / "w1_mistakes.dxf")
>>> [i.key for i in rep.wrong if not i.mistakes], [m.code for m in rep.mistakes]
([], ['sign_flipped', 'delta_not_halved', 'n_as_omega'])
"""

from __future__ import annotations

import math
import pathlib
import re
import unicodedata
from dataclasses import dataclass, field, replace

import numpy as np

from graphmethods.errors import InputError
from graphmethods.render.dxf import CadDrawing, CadText
from graphmethods.scene import Page, Scene
from graphmethods.scene.elements import CAP, Element
from graphmethods.scene.primitives import Group, Label, Path, Polygon, Style
from graphmethods.sheets.check.checking import check
from graphmethods.sheets.check.hypotheses import em_data, plan_data
from graphmethods.sheets.check.problems import CycleData, LinkageData, load_problem
from graphmethods.sheets.check.report import Checker, CheckReport, Item
from graphmethods.sheets.check.svg_reader import read_svg
from graphmethods.sheets.check.tolerances import TOL_DEG, TOL_MM
from graphmethods.sheets.check.typed_answers import validate_answers
from graphmethods.sheets.worksheets.elements import RED
from graphmethods.sheets.worksheets.variants import SEGMENTS
from graphmethods.units import input_file

#: how far a label may be from the point it names, mm
LABEL_REACH_MM = 10.0
#: points closer than this are one point, mm
MERGE_MM = 0.6

#: the symbols written on a sheet (normalised: NFKC, lower case, no spaces, _ { } ) -> answers key
SYMBOLS = {
    "μv": "mu_v", "muv": "mu_v", "µv": "mu_v",
    "μe": "mu_E", "mue": "mu_E", "µe": "mu_E", "μa": "mu_E", "mua": "mu_E",
    "va": "v_A", "vb": "v_B", "vba": "v_BA", "vs2": "v_S2",
    "ω2": "omega_2", "omega2": "omega_2", "w2": "omega_2",
    "jf": "J_F", "jф": "J_F", "jм": "J_F", "iм": "J_F",
    "δwmax": "delta_W_max", "∆wmax": "delta_W_max", "dwmax": "delta_W_max", "deltawmax": "delta_W_max",
    "aизб": "delta_W_max",
    "ωm": "omega_m", "omegam": "omega_m", "ωср": "omega_m",
    "ωmax": "omega_max", "omegamax": "omega_max", "ωmin": "omega_min", "omegamin": "omega_min",
    "md": "M_d", "mд": "M_d",
    "μj": "mu_J", "muj": "mu_J", "µj": "mu_J", "μt": "mu_T", "mut": "mu_T", "µt": "mu_T",
    "tgψmax": "tan_psi_max", "tanψmax": "tan_psi_max", "tgψmin": "tan_psi_min", "tanψmin": "tan_psi_min",
}
_NUMBER = r"([-−+]?\d+(?:[.,]\d+)?(?:[eE][-+]?\d+)?)"
_ASSIGN = re.compile(r"^([^=]+?)=(?:[^=]*=)*\s*" + _NUMBER)      # "ω2 = vBA/lAB = 3.7": the last value
_POSITION = re.compile(r"(?:position|pos\.|положение|поз\.|位置)\s*(?:no\.?|№)?\s*(\d+)", re.IGNORECASE)
_LABEL = re.compile(r"^[a-zπ][a-z0-9′']{0,3}$")
_PAGES = (("A4", "landscape"), ("A4", "portrait"), ("A3", "landscape"), ("A3", "portrait"), ("A2", "landscape"),
          ("A2", "portrait"), ("A1", "landscape"), ("A1", "portrait"))


def normalise(text: str) -> str:
    """Text as compared: NFKC (``s₂`` → ``s2``), lower case, without spaces, ``_``, braces and a trailing colon.

    >>> normalise("v_{BA} "), normalise("s₂"), normalise("ΔW max")
    ('vba', 's2', 'δwmax')
    """
    t = unicodedata.normalize("NFKC", text).lower()
    return re.sub(r"[\s_{}]", "", t).rstrip(":")


def _number(s: str) -> float:
    return float(s.replace("−", "-").replace(",", "."))


def read(source) -> CadDrawing:
    """A DXF or SVG drawing by its file suffix."""
    p = pathlib.Path(source)
    input_file(p, missing="no such drawing")           # a regular file within the size cap, before reading
    if p.suffix.lower() == ".svg":
        return read_svg(p)
    if p.suffix.lower() == ".dxf":
        from graphmethods.render.dxf import read_drawing

        return read_drawing(p)
    raise InputError(f"{p}: give a drawing ending in .dxf or .svg")


# ----------------------------------------------------------------------------- arrows, labels, notes

@dataclass(frozen=True)
class Arrow:
    """A vector of the drawing: from ``start`` to ``tip`` (mm, y up)."""

    start: tuple[float, float]
    tip: tuple[float, float]

    @property
    def length(self) -> float:
        return math.dist(self.start, self.tip)

    @property
    def angle_deg(self) -> float:
        return math.degrees(math.atan2(self.tip[1] - self.start[1], self.tip[0] - self.start[0]))


def _head(poly) -> tuple[np.ndarray, np.ndarray] | None:
    """(tip, unit axis from the base to the tip) of a triangular arrowhead; None for another shape."""
    pts = np.asarray(poly, dtype=float)
    if len(pts) != 3:
        return None
    sides = [float(np.hypot(*(pts[(i + 1) % 3] - pts[(i + 2) % 3]))) for i in range(3)]   # side opposite vertex i
    k = int(np.argmin(sides))
    tip = pts[k]
    base = (pts[(k + 1) % 3] + pts[(k + 2) % 3]) / 2
    axis = tip - base
    L = float(np.hypot(*axis))
    if L < 0.3 or sides[k] > 1.2 * L:
        return None
    return tip, axis / L


def arrows(d: CadDrawing) -> list[Arrow]:
    """The vectors of a drawing: each segment that ends at (or inside) an arrowhead pointing along it.

    The vector runs from the segment's far end to the arrowhead's tip, whether the student ended the
    segment at the head's base or at its tip.
    """
    heads = [h for h in (_head(f) for f in d.fills) if h is not None]
    out = []
    used = set()
    for a, b in d.segments:
        A, B = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        L = float(np.hypot(*(B - A)))
        if L < 1.0:
            continue
        u = (B - A) / L
        best = None
        for k, (tip, axis) in enumerate(heads):
            for end, far, sense in ((B, A, u), (A, B, -u)):
                if float(axis @ sense) < math.cos(math.radians(6.0)):
                    continue
                off = tip - end                                 # the head's tip from the segment's end
                along, across = float(off @ sense), abs(float(off[0] * sense[1] - off[1] * sense[0]))
                if across <= 0.5 and -0.5 <= along <= 6.0:
                    score = abs(along) + across
                    if best is None or score < best[0]:
                        best = (score, k, far, tip)
        if best is not None:
            used.add(best[1])
            out.append(Arrow((float(best[2][0]), float(best[2][1])), (float(best[3][0]), float(best[3][1]))))
    return out


@dataclass(frozen=True)
class Notes:
    """What is written on the sheet: values by answers key, the position number, and the point labels."""

    values: dict
    position: int | None
    labels: tuple[CadText, ...]


def _label_text(text: str) -> str:
    """A point's letter as compared: NFKC (``s₂`` → ``s2``), no spaces, ``_`` or braces; case kept (plan
    points are lower case, the mechanism's upper case)."""
    return re.sub(r"[\s_{}]", "", unicodedata.normalize("NFKC", text))


_ONLY_NUMBER = re.compile(r"^\s*" + _NUMBER + r"\s*$")


def _table_values(d: CadDrawing) -> dict:
    """Values typed into a table under a column heading (``vB, m/s`` above ``3.03``)."""
    heads = []
    for t in d.texts:
        if "=" in t.text:
            continue
        key = SYMBOLS.get(normalise(unicodedata.normalize("NFKC", t.text).split(",")[0]))
        if key is not None:
            heads.append((key, t))
    out: dict = {}
    for t in d.texts:
        m = _ONLY_NUMBER.match(unicodedata.normalize("NFKC", t.text))
        if not m:
            continue
        below = [(h.y - t.y, key) for key, h in heads
                 if abs(h.x - t.x) <= max(8.0, 0.4 * h.height * len(h.text)) and 0.0 < h.y - t.y <= 15.0]
        if below:
            out.setdefault(min(below)[1], _number(m.group(1)))
    return out


def notes(d: CadDrawing) -> Notes:
    """Read the scales, results (``vB = 3.03 m/s``, or typed under a table's heading), the position number
    and the point labels written on a drawing."""
    values: dict = {}
    labels = []
    position = None
    for t in d.texts:
        raw = unicodedata.normalize("NFKC", t.text).strip()
        for part in re.split(r";|\n", raw):
            m = _ASSIGN.match(part.strip())
            if m:
                key = SYMBOLS.get(normalise(m.group(1)))
                if key is not None and key not in values:
                    values[key] = _number(m.group(2))
                continue
            pm = _POSITION.search(part)
            if pm and position is None:
                position = int(pm.group(1))
                continue
            names = [_label_text(x) for x in part.split(",")]
            if names and all(_LABEL.match(x) for x in names) and part.strip():
                for x in names:
                    labels.append(CadText(x, t.x, t.y, t.height))
    for key, v in _table_values(d).items():
        values.setdefault(key, v)
    return Notes(values, position, tuple(labels))


def _points(arrs: list[Arrow]) -> list[np.ndarray]:
    """The ends of the arrows, coincident ends (within MERGE_MM) merged."""
    pts: list[np.ndarray] = []
    for a in arrs:
        for p in (a.start, a.tip):
            P = np.asarray(p, dtype=float)
            if not any(float(np.hypot(*(P - q))) <= MERGE_MM for q in pts):
                pts.append(P)
    return pts


def name_points(arrs: list[Arrow], labels, wanted: tuple[str, ...], *, points: dict | None = None) -> dict:
    """Label -> point (mm): each wanted label given to the nearest arrow end within :data:`LABEL_REACH_MM`
    (the nearest label first), or taken from ``points`` (drawing mm) when given.

    Raises
    ------
    InputError
        When a wanted label is on no arrow end: the message lists the ends found, for a mapping.
    """
    pts = _points(arrs)
    named: dict = {}
    if points:
        for k, v in points.items():
            named[normalise(k)] = np.asarray(v, dtype=float)
    pairs = []
    for lab in labels:
        if lab.text not in wanted or lab.text in named:
            continue
        for j, P in enumerate(pts):
            dist = math.hypot(lab.x - P[0], lab.y - P[1])
            if dist <= LABEL_REACH_MM:
                pairs.append((dist, lab.text, j))
    taken: set = set()
    for _dist, text, j in sorted(pairs):
        if text in named or j in taken:
            continue
        named[text] = pts[j]
        taken.add(j)
    missing = [w for w in wanted if w not in named]
    if missing:
        found = "; ".join(f"({P[0]:.1f}, {P[1]:.1f})" for P in pts) or "none"
        raise InputError(f"no label {', '.join(missing)} near an arrow end (within {LABEL_REACH_MM:g} mm); arrow ends "
                         f"found at {found} mm: write the letters beside the points, or give the mapping "
                         f"(--point {missing[0]}=X,Y)")
    return named


# ----------------------------------------------------------------------------- the drawing as answers

@dataclass(frozen=True, eq=False)
class DrawingReport(CheckReport):
    """A :class:`CheckReport` of a drawing, with the drawing and where the construction was found on it."""

    drawing: CadDrawing | None = field(default=None, repr=False)
    shift: tuple[float, float] = (0.0, 0.0)            # drawing mm = page mm (y up) + shift


def _page_for(d: CadDrawing) -> tuple[Page, tuple[float, float]]:
    """The smallest ISO page that holds the drawing at 1:1, and the shift from page to drawing mm."""
    xs = [p[0] for s in d.segments for p in s] + [p[0] for f in d.fills for p in f] + [t.x for t in d.texts]
    ys = [p[1] for s in d.segments for p in s] + [p[1] for f in d.fills for p in f] + [t.y for t in d.texts]
    if not xs:
        raise InputError(f"{d.source}: the drawing is empty (no lines, arrows or texts in model space)")
    x0, y0, x1, y1 = min(xs), min(ys), max(xs), max(ys)
    shift = (0.0, 0.0) if x0 >= -0.5 and y0 >= -0.5 else (x0 - 10.0, y0 - 10.0)
    need_w, need_h = x1 - shift[0] - 0.5, y1 - shift[1] - 0.5        # a frame on the sheet's edge fits
    for size, orient in _PAGES:
        page = Page(size, orient, frame=False)
        if page.width_mm >= need_w and page.height_mm >= need_h:
            return page, shift
    raise InputError(f"{d.source}: the drawing is {x1 - x0:.0f} × {y1 - y0:.0f} mm, larger than A1: is it drawn in mm "
                     f"at 1:1?")


def _page_xy(P, page: Page, shift) -> tuple[float, float]:
    return (round(float(P[0]) - shift[0], 3), round(page.height_mm - (float(P[1]) - shift[1]), 3))


def _results(values: dict, keys) -> dict:
    return {k: values[k] for k in keys if k in values}


def plan_answers(d: CadDrawing, data: LinkageData, *, position: int | None = None, mu_v: float | None = None,
                 points: dict | None = None) -> tuple[dict, dict]:
    """(answers, measured) of a velocity plan drawing: the answers dict ``check`` takes, and the arrows'
    points by label (drawing mm)."""
    nts = notes(d)
    arrs = arrows(d)
    if len(arrs) < 2 and not points:
        raise InputError(f"{d.source}: found {len(arrs)} arrow(s); a velocity plan needs its vectors drawn as lines "
                         f"with arrowheads (filled triangles, SOLIDs or polyline width)")
    mu = mu_v if mu_v is not None else nts.values.get("mu_v")
    if mu is None:
        raise InputError(f"{d.source}: no scale: write μv = … (m/s)/mm on the drawing, or give --mu-v")
    present = ("p", "a", "b") + (("s2",) if any(lb.text == "s2" for lb in nts.labels) else ())
    if points:
        present = tuple(dict.fromkeys(present + tuple(normalise(k) for k in points)))
    named = name_points(arrs, nts.labels, present, points=points)
    if "p" not in named:
        raise InputError(f"{d.source}: no pole p found; write p beside the pole")
    page, shift = _page_for(d)
    sec: dict = {"mu_v": float(mu), "origin_mm": _page_xy(named["p"], page, shift)}
    if data.plan_variant is None:
        k = position if position is not None else nts.position
        if k is None:
            raise InputError(f"{d.source}: which position is drawn? write 'position K' on the drawing, or give "
                             f"--position")
        sec["position"] = int(k)
        sec["positions"] = 12
    for seg, (f, t) in SEGMENTS.items():
        if f in named and t in named:
            sec[f"{seg}_mm"] = round(float(np.hypot(*(named[t] - named[f]))), 3)
    answers = {"page": {"size": page.size, "orientation": page.orientation}, "velocity_plan": sec}
    res = _results(nts.values, ("v_A", "v_B", "v_BA", "v_S2", "omega_2"))
    if res:
        answers["results"] = res
    return answers, named


def indicator_answers(d: CadDrawing, data: CycleData, *, mu_E: float | None = None) -> tuple[dict, list]:
    """(answers, arrows) of an energy indicator drawing: the staircase's arrows in order."""
    nts = notes(d)
    mu = mu_E if mu_E is not None else nts.values.get("mu_E")
    if mu is None:
        raise InputError(f"{d.source}: no scale: write μE = … J/mm on the drawing, or give --mu-E")
    vertical = [a for a in arrows(d) if a.length >= 0.5 and abs(abs(a.angle_deg) - 90.0) <= 3.0]
    if not vertical:
        raise InputError(f"{d.source}: no vertical arrows: an energy indicator is a staircase of vertical arrows")
    vertical.sort(key=lambda a: (a.start[0], a.start[1]))
    n = len(vertical)
    best = [1] * n
    prev = [-1] * n
    for j in range(n):                              # the longest chain: each arrow starts where the last ended
        for i in range(j):
            a, b = vertical[i], vertical[j]
            if b.start[0] > a.start[0] + 1.0 and abs(b.start[1] - a.tip[1]) <= 1.0 and best[i] + 1 > best[j]:
                best[j], prev[j] = best[i] + 1, i
    j = int(np.argmax(best))
    chain = []
    while j >= 0:
        chain.append(vertical[j])
        j = prev[j]
    chain.reverse()
    labels = list(data.cycle.labels)
    by_label = {}
    named = [lab for lab in nts.labels if lab.text in labels]
    for k, a in enumerate(chain):                  # the label nearest each arrow's start names it
        if named:
            lab = min(named, key=lambda t: math.hypot(t.x - a.start[0], t.y - a.start[1]))
            if math.hypot(lab.x - a.start[0], lab.y - a.start[1]) <= LABEL_REACH_MM:
                by_label[k] = labels.index(lab.text)
    if len(by_label) == len(chain) and len(set(by_label.values())) == len(chain):
        chain = [chain[k] for k in sorted(range(len(chain)), key=lambda k: by_label[k])]
    arrows_mm = [round(a.tip[1] - a.start[1], 3) for a in chain]
    steps = [b.start[0] - a.start[0] for a, b in zip(chain, chain[1:])]
    page, shift = _page_for(d)
    sec = {"mu_E": float(mu), "arrows_mm": tuple(arrows_mm), "origin_mm": _page_xy(chain[0].start, page, shift)}
    if steps:
        sec["step_mm"] = round(float(np.median(steps)), 3)
    answers = {"page": {"size": page.size, "orientation": page.orientation}, "energy_indicator": sec}
    res = _results(nts.values, ("delta_W_max", "J_F", "omega_m", "omega_max", "omega_min", "M_d"))
    if res:
        answers["results"] = res
    return answers, chain


def _crossings_near(d: CadDrawing, x: float, y: float, reach: float) -> list[np.ndarray]:
    """Points where two of the drawing's segments cross, within ``reach`` mm of (x, y)."""
    near = []
    for a, b in d.segments:
        A, B = np.asarray(a, float), np.asarray(b, float)
        AB = B - A
        L2 = float(AB @ AB)
        if L2 < 1e-12:
            continue
        t = min(1.0, max(0.0, float((np.array([x, y]) - A) @ AB) / L2))
        if float(np.hypot(*(A + t * AB - np.array([x, y])))) <= reach:
            near.append((A, AB))
    out = []
    for i in range(len(near)):
        for j in range(i + 1, len(near)):
            (A, u), (C, v) = near[i], near[j]
            den = u[0] * v[1] - u[1] * v[0]
            if abs(den) < 1e-9 * math.sqrt(float(u @ u) * float(v @ v)):
                continue
            w = C - A
            t, s_ = (w[0] * v[1] - w[1] * v[0]) / den, (w[0] * u[1] - w[1] * u[0]) / den
            if -1e-6 <= t <= 1 + 1e-6 and -1e-6 <= s_ <= 1 + 1e-6:
                P = A + t * u
                if math.hypot(P[0] - x, P[1] - y) <= reach:
                    out.append(P)
    return out


def _ray_items(d: CadDrawing, named: dict, answers: dict, data: LinkageData) -> list[Item]:
    """The direction of the ray drawn through k (ψ_max) and through l (ψ_min) against the exact tangent
    (±0.5° + atan(0.5 mm / the ray's length)); the ray is the longest sloping segment through the point."""
    J, T, n_rpm, delta = em_data(Checker(validate_answers(answers)), data)
    sec = answers["energy_mass"]
    w = 2.0 * math.pi * n_rpm / 60.0
    c = sec["mu_J"] / (2.0 * sec["mu_T"]) * w * w
    items = []
    for letter, which, tan in (("k", "max", c * (1 + delta / 2) ** 2), ("l", "min", c * (1 - delta / 2) ** 2)):
        P = named[letter]
        best = None
        for a, b in d.segments:
            A, B = np.asarray(a, float), np.asarray(b, float)
            u = B - A
            L = float(np.hypot(*u))
            if L < 5.0 or abs(u[0]) < 1e-6 * L:
                continue
            dist = abs(float(u[0] * (P[1] - A[1]) - u[1] * (P[0] - A[0]))) / L
            if dist <= TOL_MM and (best is None or L > best[0]):
                best = (L, math.degrees(math.atan(u[1] / u[0])))
        if best is None:
            continue
        exp = math.degrees(math.atan(tan))
        dev = best[1] - exp
        tol = TOL_DEG + math.degrees(math.atan2(TOL_MM, best[0]))
        items.append(Item(f"drawing.ray_{which}_deg", f"ray ψ_{which}", "°", round(exp, 3), round(best[1], 3),
                          round(dev, 3), round(tol, 3), "ok" if abs(dev) <= tol else "wrong",
                          note="±0.5° + atan(0.5 mm / length)"))
    return items


def em_answers(d: CadDrawing, data: LinkageData, *, points: dict | None = None) -> tuple[dict, dict]:
    """(answers, points) of an energy–mass (Wittenbauer) diagram drawing: k and l are the crossings of the
    tangent rays with the ordinate axis nearest the letters ``k`` and ``l``; μ_J, μ_T, tan ψ and J_F are read
    from the texts."""
    nts = notes(d)
    for key, what in (("mu_J", "μJ = … kg·m²/mm"), ("mu_T", "μT = … J/mm")):
        if key not in nts.values:
            raise InputError(f"{d.source}: no scale {key}: write {what} on the drawing")
    named: dict = {normalise(k): np.asarray(v, float) for k, v in (points or {}).items()}
    for letter in ("k", "l"):
        if letter in named:
            continue
        labs = [t for t in nts.labels if t.text == letter]
        cands = [(math.hypot(P[0] - t.x, P[1] - t.y), tuple(P)) for t in labs
                 for P in _crossings_near(d, t.x, t.y, LABEL_REACH_MM)]
        if not cands:
            raise InputError(f"{d.source}: no letter {letter} beside a crossing of a ray with the ordinate axis; write "
                             f"it there, or give the mapping (--point {letter}=X,Y)")
        named[letter] = np.asarray(min(cands)[1])
    page, shift = _page_for(d)
    sec: dict = {"positions": int(nts.values.get("positions", 12)), "mu_J": float(nts.values["mu_J"]),
                 "mu_T": float(nts.values["mu_T"]), "kl_mm": round(float(np.hypot(*(named["k"] - named["l"]))), 3)}
    for key in ("tan_psi_max", "tan_psi_min"):
        if key in nts.values:
            sec[key] = nts.values[key]
    # the origin (J_e = 0, ΔT = 0): where the axes cross, the longest upright and level arrows
    arrs = arrows(d)
    ups = [a for a in arrs if abs(a.tip[0] - a.start[0]) <= 0.02 * a.length and a.tip[1] > a.start[1]]
    levels = [a for a in arrs if abs(a.tip[1] - a.start[1]) <= 0.02 * a.length and a.tip[0] > a.start[0]]
    if ups and levels:
        up, level = max(ups, key=lambda a: a.length), max(levels, key=lambda a: a.length)
        sec["origin_mm"] = _page_xy((up.start[0], level.start[1]), page, shift)
    answers = {"page": {"size": page.size, "orientation": page.orientation}, "energy_mass": sec}
    res = _results(nts.values, ("J_F",))
    if res:
        answers["results"] = res
    return answers, named


_EPS_TEXT = re.compile(r"^(?:ε|eps|epsilon)_?\{?(\d+)\}?\s*=(?:[^=]*=)*\s*" + _NUMBER)
_PI = ("π", "pi", "Π")


def _aliases(plan) -> dict[str, str]:
    """How a student may letter each image of the plan -> the image's label: ``a3``, ``s3``; an end of a
    normal component ``n_BA`` as ``nBA`` or ``n`` + its link (``n2``); of a Coriolis one as ``k`` too."""
    from graphmethods.sheets.check import acceleration as ca

    out: dict[str, str] = dict.fromkeys(_PI, "π")
    comps = ca.vectors(plan)
    for c in comps:
        for lb in (c.start, c.end):
            if lb == "π":
                continue
            out.setdefault(_label_text(lb), lb)
    n_k = sum(1 for c in comps if c.kind == "coriolis")
    for c in comps:
        if c.kind == "normal" and c.end.startswith("n_"):
            out.setdefault(f"n{c.link}", c.end)
        if c.kind == "coriolis" and n_k == 1:
            out.setdefault("k", c.end)
    return out


def acc_answers(d: CadDrawing, data: LinkageData, *, position: int | None = None, mu_a: float | None = None,
                points: dict | None = None) -> tuple[dict, dict]:
    """(answers, measured points) of an acceleration plan drawing: the ``[acceleration_plan]`` section with
    every vector's length (mm) and direction (degrees from +x, counterclockwise) between its letters."""
    from graphmethods.sheets.check import acceleration as ca

    nts = notes(d)
    arrs = arrows(d)
    if len(arrs) < 2 and not points:
        raise InputError(f"{d.source}: found {len(arrs)} arrow(s); an acceleration plan needs its vectors drawn as "
                         f"lines with arrowheads (filled triangles, SOLIDs or polyline width)")
    mu = mu_a if mu_a is not None else nts.values.get("mu_E")           # μa is read as the key of μ_E
    if mu is None:
        raise InputError(f"{d.source}: no scale: write μa = … (m/s²)/mm on the drawing, or give --mu-a")
    sec: dict = {"mu_a": float(mu)}
    if data.accel_variant is None:
        k = position if position is not None else nts.position
        if k is None:
            raise InputError(f"{d.source}: which position is drawn? write 'position K' on the drawing, or give "
                             f"--position")
        sec["position"], sec["positions"] = int(k), 12
    plan = ca.problem_of(Checker({"acceleration_plan": sec}), data).plan()
    alias = _aliases(plan)
    labels = [replace(t, text=alias[t.text]) for t in nts.labels if t.text in alias]
    given = {alias.get(_label_text(k), k): v for k, v in (points or {}).items()}
    wanted = tuple(dict.fromkeys(lb for c in ca.vectors(plan) for lb in (c.start, c.end)
                                 if lb == "π" or any(t.text == lb for t in labels) or lb in given))
    named = name_points(arrs, labels, wanted, points=given or None)
    if "π" not in named:
        raise InputError(f"{d.source}: no pole π found; write π beside the pole")
    page, shift = _page_for(d)
    sec["origin_mm"] = _page_xy(named["π"], page, shift)
    for c in ca.vectors(plan):
        if c.start in named and c.end in named:
            v = named[c.end] - named[c.start]
            key = ca.key_of(c.symbol)
            sec[f"{key}_mm"] = round(float(np.hypot(*v)), 3)
            sec[f"{key}_deg"] = round(math.degrees(math.atan2(v[1], v[0])), 3)
    for t in d.texts:
        m = _EPS_TEXT.match(unicodedata.normalize("NFKC", t.text).strip())
        if m:
            sec.setdefault(f"epsilon_{m.group(1)}", _number(m.group(2)))
    answers = {"page": {"size": page.size, "orientation": page.orientation}, "acceleration_plan": sec}
    return answers, named


def _direction_items(named: dict, answers: dict, data: LinkageData) -> list[Item]:
    """The direction of each vector of the plan against the expected one (±0.5° + atan(0.5 mm / length))."""
    ck = Checker(validate_answers(answers))
    vec, *_ = plan_data(ck, data)
    items = []
    for seg, (f, t) in SEGMENTS.items():
        if f not in named or t not in named:
            continue
        exp_v = np.asarray(vec[t], dtype=float) - np.asarray(vec[f], dtype=float)
        got = named[t] - named[f]
        L = float(np.hypot(*got))
        if L < 1e-6 or float(np.hypot(*exp_v)) < 1e-12:
            continue
        exp = math.degrees(math.atan2(exp_v[1], exp_v[0]))
        stu = math.degrees(math.atan2(got[1], got[0]))
        dev = (stu - exp + 180.0) % 360.0 - 180.0
        tol = TOL_DEG + math.degrees(math.atan2(TOL_MM, L))
        items.append(Item(f"drawing.{seg}_deg", f"direction of {seg}", "°", round(exp, 3), round(exp + dev, 3),
                          round(dev, 3), round(tol, 3), "ok" if abs(dev) <= tol else "wrong",
                          note="±0.5° + atan(0.5 mm / length)"))
    return items


def check_drawing(problem, source, *, student: str | None = None, position: int | None = None,
                  mu_v: float | None = None, mu_E: float | None = None, points: dict | None = None,
                  mu_a: float | None = None) -> DrawingReport:
    """Check a velocity plan, energy indicator or energy–mass diagram drawn in CAD (DXF or SVG) against ``problem``.

    Parameters
    ----------
    problem : str or CycleData or LinkageData
        As for :func:`graphmethods.sheets.check.check` (W1…W4 and indicator worksheets: an energy
        indicator; velocity-plan worksheets: a velocity plan; wittenbauer worksheets: an energy–mass
        diagram; the press: a velocity plan, or an energy–mass diagram when the letters are k and l).
    source : path
        The drawing (``.dxf`` or ``.svg``), in mm at 1:1.
    student : str, optional
        The student's name (default: the file's name).
    position, mu_v, mu_E, mu_a : optional
        The position drawn and the scales, when not written on the drawing.
    points : dict, optional
        Label -> (x, y) drawing mm, for points whose labels are missing.

    Returns
    -------
    DrawingReport
    """
    data = problem if isinstance(problem, (CycleData, LinkageData)) else load_problem(problem)
    d = read(source)
    if isinstance(data, CycleData):
        answers, _ = indicator_answers(d, data, mu_E=mu_E)
        extra: list[Item] = []
    else:
        kind = "em" if data.em_variant is not None else ("plan" if data.plan_variant is not None else None)
        if data.accel_variant is not None or (data.case is not None and data.case.kind != "slider_crank"):
            kind = "acc"
        if kind is None:                 # the press: a plan if there are p, a, b, an energy–mass diagram if k, l
            letters = {t.text for t in notes(d).labels}
            kind = ("acc" if letters & set(_PI) else
                    "em" if {"k", "l"} <= letters and not {"p", "a", "b"} <= letters else "plan")
        if kind == "acc":
            answers, named = acc_answers(d, data, position=position, mu_a=mu_a, points=points)
            extra = []
        elif kind == "em":
            answers, named = em_answers(d, data, points=points)
            extra = _ray_items(d, named, answers, data)
        else:
            answers, named = plan_answers(d, data, position=position, mu_v=mu_v, points=points)
            extra = _direction_items(named, answers, data)
    answers["student"] = student or pathlib.Path(source).stem.split("__")[0]
    answers["problem"] = str(data.id)
    rep = check(data, answers)
    page, shift = _page_for(d)
    note = f"read from {pathlib.Path(source).name}: " + ", ".join(
        f"{k} = {v}" for sec in ("velocity_plan", "energy_indicator", "energy_mass", "acceleration_plan")
        for k, v in answers.get(sec, {}).items() if k != "origin_mm")
    return DrawingReport(rep.problem, rep.title, rep.student, rep.items + tuple(extra), rep.page,
                         rep.notes + (note,), data=rep.data, answers=rep.answers, drawing=d, shift=shift)


# ----------------------------------------------------------------------------- the overlay over the drawing

def _recolour(prim, color: str):
    if isinstance(prim, Group):
        return Group(prim.name, tuple(_recolour(c, color) for c in prim.children))
    if isinstance(prim, Label):
        return replace(prim, color=color)
    if isinstance(prim, (Path, Polygon)) or hasattr(prim, "style"):
        st = prim.style
        new = st.with_(stroke=color if st.stroke and st.stroke != "none" else st.stroke,
                       fill=color if st.fill and st.fill not in ("none", "#ffffff") else st.fill)
        return replace(prim, style=new)
    return prim


@dataclass(frozen=True)
class InRed(Element):
    """An element drawn in red (every stroke, fill but white, and text)."""

    inner: Element | None = None
    color: str = RED
    name: str = "check"

    def primitives(self):
        return (_recolour(self.inner.draw(), self.color),) if self.inner is not None else ()


@dataclass(frozen=True)
class StudentDrawing(Element):
    """The student's own drawing, as read, on the page (thin black lines, filled heads, plain texts)."""

    drawing: CadDrawing | None = None
    page_height_mm: float = 210.0
    shift: tuple[float, float] = (0.0, 0.0)
    name: str = "student-drawing"

    def primitives(self):
        d = self.drawing
        H, (sx, sy) = self.page_height_mm, self.shift

        def P(p):
            return (round(p[0] - sx, 4), round(H - (p[1] - sy), 4))
        style = Style(stroke="#000000", width_mm=0.25)
        out: list = [Path((P(a), P(b)), style) for a, b in d.segments]
        out += [Polygon(tuple(P(p) for p in f), Style(stroke=None, width_mm=0.0, fill="#000000")) for f in d.fills]
        for t in d.texts:
            size = t.height / CAP
            x, y = P((t.x, t.y - t.height / 2))
            out.append(Label(x, y, ((t.text, 0),), size_mm=round(size, 3), anchor="middle"))
        return tuple(out)


def overlay_on_drawing(report: CheckReport, *, notation="en") -> Scene:
    """The check's overlay (the correct construction at the student's scales, where the student drew it,
    and the list of wrong items) in red over the student's own drawing."""
    if not isinstance(report, DrawingReport) or report.drawing is None:
        raise InputError("an overlay over a drawing needs the report of check_drawing")
    from graphmethods.sheets.check.overlay_placement import heading_clear_of

    over = report.overlay(notation=notation)
    student = StudentDrawing(report.drawing, report.page.height_mm, report.shift)
    els: list[Element] = [student]
    els += [InRed(e, name=f"check-{e.name}") for e in heading_clear_of(student, over.elements, report.page)]
    return Scene(report.page, tuple(els), title=over.title, notation=over.notation, name="overlay-on-drawing")


def overlay_dxf(report: CheckReport, *, notation="en") -> bytes:
    """The student's DXF with the check's overlay added in red on a layer ``CHECK``."""
    from graphmethods.render.dxf import overlay_onto

    if not isinstance(report, DrawingReport) or report.drawing is None:
        raise InputError("an overlay over a drawing needs the report of check_drawing")
    src = pathlib.Path(report.drawing.source)
    if src is None or src.suffix.lower() != ".dxf":
        raise InputError("an overlay in DXF needs a DXF drawing")
    over = report.overlay(notation=notation)
    scene = Scene(report.page, tuple(InRed(e, name=f"check-{e.name}") for e in over.elements), title=over.title,
                  notation=over.notation, name="check")
    return overlay_onto(src, scene, shift=report.shift)
