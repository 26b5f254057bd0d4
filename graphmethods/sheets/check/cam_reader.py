"""Reading a student's cam drawing (DXF or SVG) as curves: every line, polyline, spline, arc, circle, ellipse or
path kept whole and flattened to a polyline in mm (y up), then sorted into what a cam construction has.

* **circles**: a closed curve whose points lie on one circle (a DXF CIRCLE, a closed spline or an SVG
  ``<circle>``, any of them) — the base circles about the cam centre O, the offset circle, the rollers;
* **the cam centre O**: the centre shared by the most circles (a letter ``O`` written within 10 mm of a
  circle's centre picks that one);
* **closed curves around O** that are not circles: the profile and, for a roller, the pitch curve (the one
  further out);
* **the follower's positions**: straight segments (a LINE, a two-point polyline) whose line passes at the
  offset e from O (within 1.5 mm), turned back by −φ: the angle φ of each is read from its direction.

The texts are read as :func:`graphmethods.sheets.check.cad.read` reads them (DXF through
:func:`graphmethods.render.dxf.read_drawing`, SVG through :func:`graphmethods.sheets.check.svg_reader.read_svg`,
both of which refuse an unreadable or oversized file in one line first).

>>> import numpy as np
>>> fit_circle(np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]))
(0.0, 0.0, 1.0, 0.0)
"""

from __future__ import annotations

import io
import math
import pathlib
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmethods.errors import InputError
from graphmethods.render.dxf import CadDrawing, CadText

#: the chord height a curve is flattened to, mm
FLATTEN_MM = 0.01
#: centres closer than this are one centre, mm
SAME_CENTRE_MM = 0.6


@dataclass(frozen=True, eq=False)
class Curves:
    """A drawing as whole curves (mm, y up), with its texts and the flat drawing an overlay redraws."""

    curves: tuple[np.ndarray, ...]
    closed: tuple[bool, ...]
    texts: tuple[CadText, ...]
    drawing: CadDrawing


def fit_circle(pts: np.ndarray) -> tuple[float, float, float, float]:
    """(x, y, r, largest |distance − r|) of the least-squares circle through points (mm)."""
    x, y = pts[:, 0], pts[:, 1]
    A = np.column_stack((x, y, np.ones_like(x)))
    b = -(x * x + y * y)
    (D, E, F), *_ = np.linalg.lstsq(A, b, rcond=None)
    cx, cy = -D / 2.0, -E / 2.0
    r = math.sqrt(max(cx * cx + cy * cy - F, 0.0))
    dev = float(np.max(np.abs(np.hypot(x - cx, y - cy) - r)))
    return (round(float(cx), 9) + 0.0, round(float(cy), 9) + 0.0, round(r, 9), round(dev, 9) + 0.0)


def read_curves(source: Any) -> Curves:
    """The curves and texts of a DXF or SVG drawing (see the module docstring)."""
    from graphmethods.sheets.check.cad import read

    p = pathlib.Path(source)
    flat = read(p)                        # checks the file (size, syntax) and reads its texts
    with warnings.catch_warnings(), np.errstate(all="ignore"):      # a non-finite number is refused below
        warnings.simplefilter("ignore")
        curves = _dxf_curves(p) if p.suffix.lower() == ".dxf" else _svg_curves(p)
    if not curves:
        raise InputError(f"{p}: no lines or curves in the drawing")
    curves = joined(curves)
    segs = tuple((tuple(map(float, a)), tuple(map(float, b))) for c, _ in curves for a, b in zip(c, c[1:]))
    drawing = CadDrawing(segs, flat.fills, (), flat.texts, source=flat.source)   # type: ignore[arg-type]
    return Curves(tuple(c for c, _ in curves), tuple(k for _, k in curves), flat.texts, drawing)


#: open pieces whose ends are closer than this are one curve, mm
JOIN_MM = 0.05


def joined(curves: list[tuple[np.ndarray, bool]]) -> list[tuple[np.ndarray, bool]]:
    """Open pieces joined end to end into chains (a profile drawn as many arcs or lines, or a spline a program
    wrote as separate short paths); a chain whose ends meet is closed. Pieces at a branch (three ends at one
    point) are left as they are.

    >>> tri = [np.array([[0.0, 0.0], [1.0, 0.0]]), np.array([[1.0, 0.0], [1.0, 1.0]]),
    ...        np.array([[0.0, 0.0], [1.0, 1.0]])]
    >>> [(len(c), k) for c, k in joined([(q, False) for q in tri])]
    [(4, True)]
    """
    done = [c for c in curves if c[1]]
    pieces = [c for c, k in curves if not k]
    ends: dict[tuple[int, int], list[tuple[int, int]]] = {}

    def cell(q: np.ndarray) -> tuple[int, int]:
        return (round(float(q[0]) / JOIN_MM), round(float(q[1]) / JOIN_MM))

    def near(q: np.ndarray) -> list[tuple[int, int]]:
        cx, cy = cell(q)
        return [e for dx in (-1, 0, 1) for dy in (-1, 0, 1) for e in ends.get((cx + dx, cy + dy), ())
                if float(np.hypot(*(pieces[e[0]][0 if e[1] == 0 else -1] - q))) <= JOIN_MM]
    for i, c in enumerate(pieces):
        for side in (0, 1):
            ends.setdefault(cell(c[0] if side == 0 else c[-1]), []).append((i, side))
    used = [False] * len(pieces)
    out = list(done)
    for i in range(len(pieces)):
        if used[i]:
            continue
        used[i] = True
        chain = [pieces[i]]
        for grow_end in (True, False):            # extend at the end, then at the start
            while True:
                tip = chain[-1][-1] if grow_end else chain[0][0]
                cand = [e for e in near(tip) if not used[e[0]]]
                if len(cand) != 1:
                    break
                j, side = cand[0]
                used[j] = True
                q = pieces[j] if (side == 0) == grow_end else pieces[j][::-1]
                if grow_end:
                    chain.append(q[1:])
                else:
                    chain.insert(0, q[:-1])
        pts = np.vstack(chain)
        out.append(_closed(pts, False))
    return out


def _closed(pts: np.ndarray, flag: bool) -> tuple[np.ndarray, bool]:
    if len(pts) > 2 and math.dist(pts[0], pts[-1]) <= 0.05:
        return pts, True
    if flag and len(pts) > 2:
        return np.vstack((pts, pts[:1])), True
    return pts, False


def _dxf_curves(p: pathlib.Path) -> list[tuple[np.ndarray, bool]]:
    """Every curve entity of the model space (blocks exploded) flattened, in mm."""
    from ezdxf import path as ezpath

    from graphmethods.render.dxf import _read_document, _to_mm

    doc, _name = _read_document(p)
    f = _to_mm(doc)
    out: list[tuple[np.ndarray, bool]] = []

    def visit(e: Any, depth: int) -> None:
        t = e.dxftype()
        if t == "INSERT" and depth < 8:
            for v in e.virtual_entities():
                visit(v, depth + 1)
            return
        if t not in ("LINE", "LWPOLYLINE", "POLYLINE", "SPLINE", "ARC", "CIRCLE", "ELLIPSE"):
            return
        try:
            pts = np.array([(v.x, v.y) for v in ezpath.make_path(e).flattening(FLATTEN_MM / max(f, 1e-12))],
                           dtype=float) * f
        except (ValueError, TypeError, AttributeError, IndexError, ZeroDivisionError) as exc:
            raise InputError(f"{p}: a {t} cannot be read ({exc.__class__.__name__}: {str(exc)[:80]})") from None
        if len(pts) >= 2 and np.all(np.isfinite(pts)):
            closed = t in ("CIRCLE",) or bool(getattr(e, "closed", False)) or bool(getattr(e, "is_closed", False))
            out.append(_closed(pts, closed))
    try:
        for e in doc.modelspace():
            visit(e, 0)
    except InputError:
        raise
    except (ValueError, TypeError, AttributeError, IndexError, KeyError) as exc:
        raise InputError(f"{p}: not a readable DXF drawing ({exc.__class__.__name__}: {str(exc)[:80]})") from None
    return out


def _svg_curves(p: pathlib.Path) -> list[tuple[np.ndarray, bool]]:
    """Every shape of the SVG, each subpath a curve, its curved segments sampled, in mm (y up)."""
    import svgelements as se

    from graphmethods.sheets.check.svg_reader import MM_PER_PX
    from graphmethods.units import read_bytes

    data = read_bytes(p, missing="no such drawing")
    try:
        svg = se.SVG.parse(io.BytesIO(data), reify=True, ppi=se.DEFAULT_PPI)
        H = float(svg.height) if svg.height else 0.0
        out: list[tuple[np.ndarray, bool]] = []
        for el in svg.elements():
            if isinstance(el, se.Shape) and not isinstance(el, se.Use):
                out += _svg_shape(el if isinstance(el, se.Path) else se.Path(el), se, H, MM_PER_PX)
    except InputError as exc:
        raise InputError(f"{p}: {exc}") from None
    except (ValueError, TypeError, ZeroDivisionError, IndexError, KeyError, AttributeError, OverflowError) as exc:
        raise InputError(f"{p}: not a readable SVG drawing ({exc.__class__.__name__}: {str(exc)[:80]})") from None
    return out


def _svg_shape(path: Any, se: Any, H: float, k: float) -> list[tuple[np.ndarray, bool]]:
    subs: list[list[tuple[float, float]]] = []
    closed: list[bool] = []
    for seg in path:
        if isinstance(seg, se.Move):
            subs.append([(seg.end.x, seg.end.y)])
            closed.append(False)
        elif subs and seg.end is not None:
            if isinstance(seg, (se.Line, se.Close)):
                subs[-1].append((seg.end.x, seg.end.y))
                closed[-1] = closed[-1] or isinstance(seg, se.Close)
            else:
                coarse = np.array([(q.x, q.y) for q in (seg.point(t) for t in np.linspace(0.0, 1.0, 9))], dtype=float)
                L = float(np.sum(np.hypot(*np.diff(coarse, axis=0).T))) * k          # mm, from 8 chords
                if not math.isfinite(L):
                    raise InputError("a curve of the drawing has a coordinate that is not finite")
                n = max(8, min(256, int(L / 0.5) + 1))
                subs[-1] += [(q.x, q.y) for q in (seg.point(t) for t in np.linspace(0.0, 1.0, n + 1)[1:])]
    out = []
    for pts, c in zip(subs, closed):
        a = np.array([(x * k, (H - y) * k) for x, y in pts], dtype=float)
        if len(a) >= 2 and np.all(np.isfinite(a)):
            out.append(_closed(a, c))
    return out
