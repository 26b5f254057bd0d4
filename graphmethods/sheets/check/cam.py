"""Checking a student's cam profile: drawn in CAD (DXF or SVG) at μ_l, or typed into an answers file, against
the exact design of the problem (a built-in cam, a ``"kind": "cam"`` file, or a ``cam`` worksheet variant).

What is read off a drawing (:mod:`graphmethods.sheets.check.cam_reader`; the drawing in mm at 1:1, the
follower in position 0 above the cam centre O as the worksheet draws it): the circles about O (the base
circle r_b, for a roller the pitch base circle r₀, the offset circle), the profile and the pitch curve (closed
curves around O), the follower's positions (segments at the offset e from O; φ from each one's direction,
taken as the nearest marked position within 1.5°), the roller centres on them, and the texts
``μl = 0,001 m/mm`` (or ``--mu-l``; a worksheet's own μ_l otherwise), ``αmax = 29.5°`` (rise) and
``αmax2 = 41°`` or ``αret = 41°`` (return).

Checked items, each against the exact value at the student's μ_l (:data:`TOL_MM` = ±0.5 mm on the drawing):

* the base radius r_b and, for a roller, r₀ (m): ±0.5 mm·μ_l + 0.1 %;
* s at each marked position (mm on the drawing, from the pitch base circle to the pitch point along the
  follower's axis): ±0.5 mm;
* the largest pressure angles of the rise and of the return (degrees, written on the drawing or typed):
  ±(0.5° + how much α_max changes when r₀ moves 0.5 mm·μ_l); computed at the student's own r₀, a value that
  follows from a wrong base radius is ``carried``;
* the profile (and a roller's pitch curve): the largest distance from the exact curve, expected 0, within
  1 mm (±0.5 mm of drafting and 0.5 mm between the points a smooth curve is drawn through); a profile that
  fits the design at the student's own base radius is ``carried``.

The usual mistakes named: the roller radius not subtracted (r₀ given as r_b), the offset on the wrong side,
s laid off from the foot of the follower's axis instead of the base circle, the follower turned with the
cam (+φ) instead of against it (the profile mirrored).

>>> from graphmethods.sheets import worksheets as ws
>>> v = ws.variant("cam", seed=3, number=2)
>>> a = v.answers()
>>> rep = check_cam(v.id, {"cam": {"mu_l": v.mu_l, "base_radius": a["base_radius"], "s_mm": a["s_mm"]}})
>>> rep.ok, len(rep.items) == 1 + len(a["s_mm"])
(True, True)
"""

from __future__ import annotations

import json
import math
import pathlib
import re
import unicodedata
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.kinematics.cam import CamDesign, design
from graphmethods.kinematics.cam.geometry import to_cam_frame
from graphmethods.scene import Page, Scene
from graphmethods.sheets.check.cad import DrawingReport, _page_for, _page_xy, normalise
from graphmethods.sheets.check.cam_reader import SAME_CENTRE_MM, Curves, fit_circle, read_curves
from graphmethods.sheets.check.report import MISTAKES, Checker, Item, rel
from graphmethods.sheets.check.tolerances import TOL_MM
from graphmethods.titles import Title

#: the usual mistakes of a cam profile (their names in en/ru/zh: the vocabulary's check family)
CAM_MISTAKES = {
    "pitch_for_profile": "the roller radius not subtracted: the pitch base radius r_0 given as r_b",
    "offset_wrong_side": "the offset e laid off on the wrong side of the cam centre",
    "s_from_centre": "s laid off from the foot of the follower's axis instead of from the base circle",
    "inversion_same_sense": "the follower turned with the cam (+φ) instead of against it (−φ): the profile mirrored",
}

#: the tolerance of a drawn curve against the exact one, mm (drafting plus the sag between the points)
TOL_CURVE_MM = 1.0
#: how far a follower's direction may be from a marked position, degrees
SNAP_DEG = 1.5


@dataclass(frozen=True, eq=False)
class CamData:
    """What a cam check needs: the exact design, and a worksheet's stated μ_l and marked positions."""

    id: str
    title: Title | str
    cam: CamDesign
    mu_l: float | None = None
    positions_deg: tuple[float, ...] | None = None


def is_cam_problem(spec: Any) -> bool:
    """True when ``spec`` names a cam problem: a built-in cam, a ``cam:SEED:N`` worksheet id, a ``"kind": "cam"``
    file or a cam worksheet's problem file."""
    from graphmethods.problems.builtin import CAMS

    text = str(spec).strip()
    if text.lower() in CAMS or re.fullmatch(r"cam:\d+:\d+", text):
        return True
    p = pathlib.Path(text)
    if p.suffix.lower() != ".json" or not p.is_file():
        return False
    try:
        d = json.loads(p.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return False
    return isinstance(d, dict) and d.get("kind") == "cam"


def load_cam(spec: Any) -> CamData:
    """The cam problem ``spec`` names (see :func:`is_cam_problem`), designed."""
    from graphmethods.problems.builtin import cam_problem
    from graphmethods.sheets.worksheets.variants import PROBLEM_FORMAT, parse_id, variant_from_dict

    if isinstance(spec, CamData):
        return spec
    text = str(spec).strip()
    v = parse_id(text)
    if v is None and pathlib.Path(text).is_file():
        try:
            d = json.loads(pathlib.Path(text).read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, ValueError) as exc:
            raise InputError(f"{text}: not a readable JSON problem file ({exc})") from None
        if isinstance(d, dict) and d.get("format") == PROBLEM_FORMAT:
            v = variant_from_dict(d, source=text)
    if v is not None:
        if v.kind != "cam":
            raise InputError(f"{text}: a {v.kind} worksheet, not a cam problem")
        return CamData(v.id, v.title, v.cam, v.mu_l, v.positions_deg)       # type: ignore[attr-defined]
    p = cam_problem(text)
    return CamData(pathlib.Path(text).name if pathlib.Path(text).is_file() else text.lower(), p.title, design(p))


# ----------------------------------------------------------------------------- the exact construction

def _variant(cam: CamDesign, **change: Any) -> CamDesign:
    """The design of the same problem with fields changed (base_radius given, offset negated)."""
    return design(replace(cam.problem, **change))


def _s_exact(cam: CamDesign, phi_deg: Any) -> np.ndarray:
    return cam.problem.motion(np.asarray(phi_deg, dtype=float))[0]


def _alpha_spread(cam: CamDesign, r0: float, d: float) -> tuple[float, float]:
    """How much the largest pressure angles of rise and return change when r₀ moves by ±d (m)."""
    p = cam.problem
    out = []
    for sign in (-1.0, 1.0):
        r = r0 + sign * d
        out.append(_variant(cam, base_radius=max(r - p.roller_radius, 1e-6), alpha_max_deg=None))
    return (abs(out[1].alpha_max_rise_deg - out[0].alpha_max_rise_deg) / 2,
            abs(out[1].alpha_max_return_deg - out[0].alpha_max_return_deg) / 2)


def _own(cam: CamDesign, base_radius: float | None, tol: float) -> CamDesign | None:
    """The design at the student's own base radius (what follows from it), or None when that is within the
    tolerance ``tol`` (m) of the exact one (nothing then follows from it)."""
    if base_radius is None or not base_radius > 0 or abs(base_radius - cam.base_radius) <= tol:
        return None
    try:
        return _variant(cam, base_radius=float(base_radius))
    except InputError:
        return None


# ----------------------------------------------------------------------------- the items

def _radius_items(ck: Checker, cam: CamDesign, sec: dict, mu: float) -> None:
    p = cam.problem
    tol_b, tol_0 = rel(TOL_MM * mu, cam.base_radius), rel(TOL_MM * mu, cam.pitch_base_radius)
    wrong = (abs(float(sec.get("base_radius", cam.base_radius)) - cam.base_radius) > tol_b
             or abs(float(sec.get("pitch_base_radius", cam.pitch_base_radius)) - cam.pitch_base_radius) > tol_0)
    other = _other_side(cam) if wrong else None
    if "base_radius" in sec:
        hyp = [("pitch_for_profile", cam.pitch_base_radius if p.contact == "roller" else None)]
        hyp.append(("offset_wrong_side", other.base_radius if other is not None else None))
        ck.value("cam.base_radius", "base radius r_b", "m", cam.base_radius, float(sec["base_radius"]), tol_b,
                 hypotheses=hyp, note="±0.5 mm·μ_l + 0.1 %")
    if "pitch_base_radius" in sec and p.contact == "roller":
        ck.value("cam.pitch_base_radius", "pitch base radius r_0", "m", cam.pitch_base_radius,
                 float(sec["pitch_base_radius"]), tol_0,
                 hypotheses=[("offset_wrong_side", other.pitch_base_radius if other is not None else None)],
                 note="±0.5 mm·μ_l + 0.1 %")


def _other_side(cam: CamDesign) -> CamDesign | None:
    """The design with the offset on the other side (a usual mistake), or None (in-line, or not designable)."""
    if not cam.problem.offset:
        return None
    try:
        return _variant(cam, offset=-cam.problem.offset)
    except InputError:
        return None


def _s_items(ck: Checker, cam: CamDesign, sec: dict, mu: float) -> None:
    phis = [float(x) for x in sec.get("phi_deg", ())]
    s_stu = [float(x) for x in sec.get("s_mm", ())]
    if len(phis) != len(s_stu):
        raise InputError(f"[cam] s_mm has {len(s_stu)} values for {len(phis)} positions; give one per position of "
                         f"the table (0, 1, …), or phi_deg with them")
    p = cam.problem
    s0 = math.sqrt(max(cam.pitch_base_radius ** 2 - p.offset ** 2, 0.0))
    exact = _s_exact(cam, phis)
    mirror = _s_exact(cam, [(360.0 - f) % 360.0 for f in phis])
    for k, (phi, s, e, m) in enumerate(zip(phis, s_stu, exact, mirror)):
        ck.value(f"cam.s_mm[{k}]", f"s at φ = {_deg(phi)}°", "mm", float(e) / mu, s, TOL_MM,
                 hypotheses=[("s_from_centre", (s0 + float(e)) / mu),
                             ("inversion_same_sense", float(m) / mu)],
                 note="±0.5 mm")


def _alpha_items(ck: Checker, cam: CamDesign, sec: dict, mu: float, own: CamDesign | None) -> None:
    keys = [k for k in ("alpha_max_rise_deg", "alpha_max_return_deg") if k in sec]
    if not keys:
        return
    spread = _alpha_spread(cam, cam.pitch_base_radius, TOL_MM * mu)
    for key, label, sp in (("alpha_max_rise_deg", "largest pressure angle, rise", spread[0]),
                           ("alpha_max_return_deg", "largest pressure angle, return", spread[1])):
        if key not in sec:
            continue
        exp = getattr(cam, key)
        ck.value(f"cam.{key}", label, "°", exp, float(sec[key]), 0.5 + sp, own=getattr(own, key, None),
                 own_from="the student's base radius", note="±(0.5° + the change of α_max with r₀ ± 0.5 mm·μ_l)")


def _curve_items(ck: Checker, cam: CamDesign, sec: dict, extra: dict, own: CamDesign | None) -> None:
    """The drawn profile (and pitch curve) against the exact ones (see :func:`_curve_item`)."""
    for which, label in (("profile", "profile: largest distance from the exact one"),
                         ("pitch", "pitch curve: largest distance from the exact one")):
        pts = extra.get(which)
        if pts is None:
            continue
        _curve_item(ck, cam, sec, pts, which, label, own)


def _dense(cam: CamDesign, which: str, *, mirrored: bool = False) -> np.ndarray:
    st = cam.state(np.linspace(0.0, 360.0, 3601))
    xy = st.profile if which == "profile" else st.pitch
    if mirrored:                      # turned with the cam: R(+φ)·B instead of R(−φ)·B
        p = cam.problem
        B = cam.frame(*p.motion(st.phi_deg)[:3]).B if p.contact != "flat" else None
        if B is None:
            return xy
        pitch = to_cam_frame(B, -np.radians(st.phi_deg), p.sense)
        if which == "pitch" or p.contact != "roller":
            return pitch
        from shapely.geometry import Polygon

        ring = Polygon(pitch).buffer(-p.roller_radius, quad_segs=32).exterior
        return np.asarray(ring.coords, dtype=float)
    return xy


def _distance(points_m: np.ndarray, curve_m: np.ndarray) -> float:
    """The largest distance from the points to the closed polyline (m)."""
    import shapely

    ring = shapely.linearrings(curve_m)
    return float(np.max(shapely.distance(shapely.points(points_m), ring)))


def _curve_item(ck: Checker, cam: CamDesign, sec: dict, pts_m: np.ndarray, which: str, label: str,
                own: CamDesign | None) -> None:
    mu = float(sec["mu_l"])
    dev = _distance(pts_m, _dense(cam, which)) / mu
    codes: list[str] = []
    verdict, note = ("ok" if dev <= TOL_CURVE_MM else "wrong"), "±0.5 mm drafting + 0.5 mm between the points"
    if verdict == "wrong":
        other = _other_side(cam)
        if own is not None and _distance(pts_m, _dense(own, which)) / mu <= TOL_CURVE_MM:
            verdict, note = "carried", "follows from the student's base radius"
        elif _distance(pts_m, _dense(cam, which, mirrored=True)) / mu <= TOL_CURVE_MM:
            codes.append("inversion_same_sense")
        elif other is not None and _distance(pts_m, _dense(other, which)) / mu <= TOL_CURVE_MM:
            codes.append("offset_wrong_side")
    ck.items.append(Item(f"cam.{which}_dev_mm", label, "mm", 0.0, round(dev, 3), round(dev, 3), TOL_CURVE_MM, verdict,
                         tuple(codes), note))


def _deg(x: float) -> str:
    return f"{x:.6g}"


# ----------------------------------------------------------------------------- the report

@dataclass(frozen=True, eq=False)
class CamReport(DrawingReport):
    """A cam check's report: its overlay is the exact construction at the student's μ_l about their O."""

    cam_data: CamData | None = field(default=None, repr=False)

    def mistake_names(self) -> dict[str, str]:
        """The names of the mistakes a cam check diagnoses: :data:`CAM_MISTAKES` besides the others."""
        return {**MISTAKES, **CAM_MISTAKES}

    def overlay(self, *, notation: Any = "en") -> Scene:
        """The exact profile by inversion at the student's μ_l, with O where the student's is (or the page's
        centre), the follower at each position the student drew, and the wrong items listed."""
        from graphmethods.scene import notation as get_notation
        from graphmethods.sheets.check.overlay import _overlay_head
        from graphmethods.sheets.worksheets.cam import inversion_elements

        nt = get_notation(notation)
        title, els, _y = _overlay_head(self, nt)
        sec = self.answers.get("cam", {})
        assert self.cam_data is not None
        W, H = self.page.width_mm, self.page.height_mm
        o = sec.get("origin_mm", (W / 2.0, H / 2.0 + 10.0))
        phis = tuple(sec.get("phi_deg", ())) or (0.0,)
        els += inversion_elements(self.cam_data.cam, (float(o[0]), float(o[1])), float(sec["mu_l"]), nt,
                                  phi_deg=phis, full=True, name="check")
        return Scene(self.page, tuple(els), title=title, notation=nt.code, name="overlay")


def item_label(it: Item, nt: Any) -> str:
    """The label of a cam item in the notation's language (markup)."""
    name = it.key.split(".", 1)[1]
    m = re.fullmatch(r"s_mm\[(\d+)\]", name)
    if m:
        phi = re.search(r"φ = (\S+)°", it.label)
        return str(nt.word("camcheck.s_at", phi=phi.group(1) if phi else m.group(1)))
    words = {"base_radius": "base_radius", "pitch_base_radius": "pitch_base_radius", "mu_l": "mu_l",
             "alpha_max_rise_deg": "alpha_rise", "alpha_max_return_deg": "alpha_return",
             "profile_dev_mm": "profile_dev", "pitch_dev_mm": "pitch_dev"}
    return str(nt.word("camcheck." + words[name])) if name in words else it.label


def _section(answers: dict) -> dict:
    sec = answers.get("cam")
    if not isinstance(sec, dict):
        raise InputError("the answers have no [cam] section (the cam's scale mu_l, base_radius, s_mm, …)")
    known = {"mu_l", "base_radius", "pitch_base_radius", "s_mm", "phi_deg", "alpha_max_rise_deg",
             "alpha_max_return_deg", "origin_mm"}
    for k, v in sec.items():
        if k not in known:
            raise InputError(f"[cam] {k}: unknown key; the keys are {', '.join(sorted(known))}")
        vals = v if isinstance(v, (list, tuple)) else [v]
        if any(isinstance(x, (bool, str)) or not isinstance(x, (int, float)) or not math.isfinite(x) for x in vals):
            raise InputError(f"[cam] {k} = {v!r}: give a number (a list of numbers for s_mm, phi_deg)")
    return {k: v for k, v in sec.items() if not (isinstance(v, (list, tuple)) and k not in ("s_mm", "phi_deg",
                                                                                           "origin_mm"))}


def check_cam(problem: Any, answers: dict, *, extra: dict | None = None, student: str = "",
              page: Page | None = None) -> CamReport:
    """Check a cam's answers (the ``[cam]`` section of an answers file, or what a drawing gave) against the
    problem's exact design; ``extra`` holds curves read off a drawing (cam frame, m: ``profile``, ``pitch``).

    Returns
    -------
    CamReport
    """
    data = load_cam(problem)
    sec = dict(_section(answers))
    mu = sec.get("mu_l", data.mu_l)
    if mu is None or not mu > 0:
        raise InputError("no scale: give mu_l (m per mm) in [cam], or write μl = … m/mm on the drawing (--mu-l)")
    sec["mu_l"] = float(mu)
    if "s_mm" in sec and "phi_deg" not in sec:
        if data.positions_deg is None:
            raise InputError("[cam] s_mm needs phi_deg (the cam angles of the positions, degrees) for this problem")
        sec["phi_deg"] = data.positions_deg[:len(sec["s_mm"])]
    ck = Checker({"cam": sec})
    notes: list[str] = []
    if data.mu_l is not None and abs(sec["mu_l"] - data.mu_l) > 1e-12 * data.mu_l:
        notes.append(f"drawn at μ_l = {sec['mu_l']:g} m/mm; the worksheet asks for {data.mu_l:g} m/mm")
    cam = data.cam
    _radius_items(ck, cam, sec, sec["mu_l"])
    if "s_mm" in sec:
        _s_items(ck, cam, sec, sec["mu_l"])
    own = _own(cam, sec.get("base_radius"), rel(TOL_MM * sec["mu_l"], cam.base_radius))
    _alpha_items(ck, cam, sec, sec["mu_l"], own)
    _curve_items(ck, cam, sec, extra or {}, own)
    if not ck.items:
        raise InputError("the answers hold nothing to check: give base_radius, s_mm, the largest pressure angles, "
                         "or a drawing with the base circle and the profile")
    named = str(answers.get("problem", "") or "")
    if named and named.strip().lower() != str(data.id).lower():
        notes.append(f"the answers file names problem {named!r}; checked against {data.id}")
    pg = page or Page("A4", "portrait", frame=False)
    return CamReport(str(data.id), data.title, student or str(answers.get("student", "") or ""), tuple(ck.items), pg,
                     tuple(ck.notes + notes), data=None, answers={"cam": sec}, cam_data=data)


def check_cam_answers(problem: Any, path: Any) -> CamReport:
    """Check a cam answers file (TOML, the ``[cam]`` section of ``cam-answers.toml``)."""
    from graphmethods.sheets.check.typed_answers import load_toml
    from graphmethods.units import read_text

    p = pathlib.Path(path)
    raw = load_toml(read_text(p, missing="no such answers file"), source=str(p))
    sec = raw.get("cam", {})
    if isinstance(sec, dict):        # blanks ("" and []) are not answered
        raw["cam"] = {k: v for k, v in sec.items() if v not in ("", [])}
    page = raw.get("page", {}) if isinstance(raw.get("page"), dict) else {}
    try:
        pg = Page(str(page.get("size", "A4")), str(page.get("orientation", "portrait")), frame=False)
    except InputError as exc:
        raise InputError(f"{p}: [page]: {exc}") from None
    try:
        return check_cam(problem, raw, page=pg)
    except InputError as exc:
        raise InputError(f"{p}: {exc}") from None


# ----------------------------------------------------------------------------- a drawing

_TEXT = re.compile(r"^([^=]+?)=(?:[^=]*=)*\s*([-−+]?\d+(?:[.,]\d+)?(?:[eE][-+]?\d+)?)\s*(\S*)")
_SYMBOLS = {"μl": "mu_l", "mul": "mu_l", "µl": "mu_l",
            "αmax": "alpha_max_rise_deg", "αmax1": "alpha_max_rise_deg", "αrise": "alpha_max_rise_deg",
            "αmax,rise": "alpha_max_rise_deg", "ϑmax": "alpha_max_rise_deg", "ϑmax1": "alpha_max_rise_deg",
            "αmax2": "alpha_max_return_deg", "αret": "alpha_max_return_deg", "αmax,return": "alpha_max_return_deg",
            "α'max": "alpha_max_return_deg", "ϑmax2": "alpha_max_return_deg", "αreturn": "alpha_max_return_deg"}


def drawing_texts(texts: Any) -> dict[str, float]:
    """The scale and the largest pressure angles written on a drawing (``μl = 0,001 m/mm``, ``αmax = 30°``)."""
    out: dict[str, float] = {}
    for t in texts:
        m = _TEXT.match(unicodedata.normalize("NFKC", t.text).strip())
        if not m:
            continue
        key = _SYMBOLS.get(normalise(m.group(1)))
        if key is not None and key not in out:
            out[key] = float(m.group(2).replace("−", "-").replace(",", "."))
    return out


def _centre(c: Curves, circles: list[tuple[float, float, float]]) -> tuple[float, float]:
    """The cam centre O (mm): the circle centre nearest a letter O (within 10 mm), else the centre most circles
    share (then the one of the largest circle)."""
    if not circles:
        raise InputError(f"{c.drawing.source}: no circle about the cam centre: draw the base circle (a circle about O)")
    for t in c.texts:
        if t.text.strip() in ("O", "О"):
            near = min(circles, key=lambda q: math.hypot(q[0] - t.x, q[1] - t.y))
            if math.hypot(near[0] - t.x, near[1] - t.y) <= 10.0:
                return near[0], near[1]
    best = max(circles, key=lambda q: (sum(1 for o in circles if math.hypot(o[0] - q[0], o[1] - q[1])
                                           <= SAME_CENTRE_MM), q[2]))
    return best[0], best[1]


def _read_geometry(c: Curves, cam: CamDesign, mu: float) -> dict[str, Any]:
    """O, the circles about it, the rollers, the closed curves around O and the follower segments (mm, O at 0)."""
    circles, others, segments = [], [], []
    for pts, closed in zip(c.curves, c.closed):
        if closed and len(pts) >= 4:
            x, y, r, dev = fit_circle(pts[:-1])
            if dev <= max(0.05, 0.003 * r) and len(pts) >= 9:        # a square's four corners are no circle
                circles.append((x, y, r))
                continue
            others.append(pts)
        elif len(pts) >= 2:
            d = pts[-1] - pts[0]
            L = float(np.hypot(*d))
            q = pts - pts[0]
            if L >= 5.0 and np.max(np.abs(q[:, 0] * d[1] - q[:, 1] * d[0])) / L <= 0.05:
                segments.append((pts[0], pts[-1]))
    ox, oy = _centre(c, circles)
    O = np.array([ox, oy])
    about = sorted(r for x, y, r in circles if math.hypot(x - ox, y - oy) <= SAME_CENTRE_MM)
    rollers = [np.array([x, y]) - O for x, y, r in circles if math.hypot(x - ox, y - oy) > SAME_CENTRE_MM]
    around = []
    for pts in others:
        q = pts - O
        ang = np.unwrap(np.arctan2(q[:, 1], q[:, 0]))
        if abs(ang[-1] - ang[0]) > 1.5 * math.pi and float(np.min(np.hypot(*q.T))) > 0.5:
            around.append(q)
    around.sort(key=lambda q: float(np.mean(np.hypot(*q.T))))
    return {"O": O, "about": about, "rollers": rollers, "around": around,
            "segments": [(a - O, b - O) for a, b in segments]}


def _radii(geo: dict, cam: CamDesign, mu: float) -> dict[str, float]:
    """The base radii among the circles about O: each circle given to the nearest of r_b, r₀ (roller) and e."""
    p = cam.problem
    targets = {"base_radius": cam.base_radius / mu, "offset": abs(p.offset) / mu}
    if p.contact == "roller":
        targets["pitch_base_radius"] = cam.pitch_base_radius / mu
    out: dict[str, float] = {}
    for r in geo["about"]:
        key = min(targets, key=lambda k: abs(targets[k] - r))
        if key != "offset" and key not in out:
            out[key] = round(r * mu, 9)
    return out


def _positions(data: CamData) -> np.ndarray:
    """The angles a follower's direction is snapped to: the worksheet's marked positions, or the division points
    of 4, 6, 8 or 12 parts per rise and return."""
    from graphmethods.sheets.worksheets.cam import positions_of

    if data.positions_deg is not None:
        return np.asarray(data.positions_deg, dtype=float)
    return np.unique(np.concatenate([positions_of(data.cam.problem, n) for n in (4, 6, 8, 12)]))


def _phi_of(u: np.ndarray, cam: CamDesign, marks: np.ndarray) -> float:
    """The cam angle φ (degrees) whose turned-back follower axis points along ``u``: the nearest marked position
    within :data:`SNAP_DEG`, else the angle itself to 0.1°."""
    grid = np.arange(0.0, 360.0, 0.05)
    dirs = to_cam_frame(np.tile([0.0, 1.0], (grid.size, 1)), np.radians(grid), cam.problem.sense)
    phi = float(grid[int(np.argmax(dirs @ u))])
    gap = np.abs((marks - phi + 180.0) % 360.0 - 180.0)
    return float(marks[int(np.argmin(gap))]) if gap.size and gap.min() <= SNAP_DEG else round(phi, 1)


def _ray_hit(F: np.ndarray, u: np.ndarray, curve: np.ndarray) -> float | None:
    """The largest t at which the ray F + t·u (t > 0) crosses the closed curve (mm)."""
    import shapely

    ray = shapely.linestrings([F, F + u * 1e4])
    hit = shapely.intersection(ray, shapely.linearrings(curve))
    pts = np.asarray(shapely.get_coordinates(hit), dtype=float)
    if pts.size == 0:
        return None
    return float(np.max((pts - F) @ u))


def _follower_s(geo: dict, radii: dict, cam: CamDesign, mu: float, marks: np.ndarray,
                pitch: np.ndarray | None) -> list[tuple[float, float]]:
    """(φ, s mm) of each follower position drawn: s from the pitch base circle to the roller centre (or the
    pitch curve, or a knife's profile) along the axis."""
    p = cam.problem
    R0 = radii.get("pitch_base_radius", radii.get("base_radius", 0.0) + p.roller_radius
                   if "base_radius" in radii else None)
    if R0 is None:
        return []
    R0 /= mu
    out: dict[float, float] = {}
    for a, b in geo["segments"]:
        near, far = (a, b) if np.hypot(*a) <= np.hypot(*b) else (b, a)
        u = (far - near) / float(np.hypot(*(far - near)))
        e_line = -float(u[0] * near[1] - u[1] * near[0])
        if abs(abs(e_line) - abs(p.offset) / mu) > 1.5 or float(np.hypot(*far)) < R0:
            continue
        F = near - float(near @ u) * u
        t_base = math.sqrt(max(R0 * R0 - e_line * e_line, 0.0))
        centres = [float((c - F) @ u) for c in geo["rollers"]
                   if abs(float(u[0] * (c - F)[1] - u[1] * (c - F)[0])) <= TOL_MM and float((c - F) @ u) > 0]
        t = min(centres, key=lambda x: abs(x - t_base)) if centres else (
            _ray_hit(F, u, pitch) if pitch is not None else None)
        if t is None:
            continue
        phi = _phi_of(u, cam, marks)
        out.setdefault(phi, round(t - t_base, 3))
    return sorted(out.items())


def _assign_curves(geo: dict, cam: CamDesign, mu: float) -> dict[str, np.ndarray]:
    """The closed curves around O as the profile and (roller) the pitch curve, by their mean radius."""
    dense = cam.state(np.linspace(0.0, 360.0, 721))
    want = {"profile": float(np.mean(np.hypot(*dense.profile.T))) / mu}
    if cam.problem.contact == "roller":
        want["pitch"] = float(np.mean(np.hypot(*dense.pitch.T))) / mu
    out: dict[str, np.ndarray] = {}
    for q in geo["around"]:
        r = float(np.mean(np.hypot(*q.T)))
        free = [k for k in want if k not in out]
        if free:
            out[min(free, key=lambda k: abs(want[k] - r))] = q
    return out


def check_drawing(problem: Any, source: Any, *, mu_l: float | None = None, student: str | None = None) -> CamReport:
    """Check a cam profile drawn in CAD (DXF or SVG, mm at 1:1) against ``problem`` (see the module docstring).

    Raises
    ------
    InputError
        An unreadable drawing, no circle about the cam centre, no scale, nothing to check.
    """
    data = load_cam(problem)
    c = read_curves(source)
    written = drawing_texts(c.texts)
    mu = mu_l if mu_l is not None else written.get("mu_l", data.mu_l)
    if mu is None or not mu > 0:
        raise InputError(f"{source}: no scale: write μl = … m/mm on the drawing, or give --mu-l")
    cam = data.cam
    geo = _read_geometry(c, cam, float(mu))
    radii = _radii(geo, cam, float(mu))
    curves = _assign_curves(geo, cam, float(mu))
    pitch = curves.get("pitch", curves.get("profile") if cam.problem.contact != "roller" else None)
    s = _follower_s(geo, radii, cam, float(mu), _positions(data), pitch)
    page, shift = _page_for(c.drawing)
    sec: dict[str, Any] = {"mu_l": float(mu), **radii, "origin_mm": _page_xy(geo["O"], page, shift)}
    if s:
        sec["phi_deg"], sec["s_mm"] = [f for f, _ in s], [x for _, x in s]
    sec.update({k: v for k, v in written.items() if k != "mu_l"})
    extra = {k: v * float(mu) for k, v in curves.items()}
    rep = check_cam(data, {"cam": sec, "problem": data.id}, extra=extra, page=page,
                    student=student or pathlib.Path(source).stem.split("__")[0])
    read_note = (f"read from {pathlib.Path(source).name}: mu_l = {float(mu):g}, radii_mm = "
                 f"{'/'.join(f'{r:.2f}' for r in geo['about'])}, positions = {len(s)}, curves = {len(curves)}")
    return replace(rep, notes=rep.notes + (read_note,), drawing=c.drawing, shift=shift)
