"""The flywheel as a designer sees it: the rim (spoked) flywheel and the solid disc sized from J_F,
their axial sections drawn to one length scale μ_l and dimensioned, with the table of masses,
flywheel moments m·D² and rim speeds against the material's limit (domain.md §6). A4 landscape.

Rim: J ≈ m D²/4, m = ρ π D H B (mean diameter D, radial thickness H, width B, H/B given);
the drawing shows the rim's section at ±D/2 from the axis (spokes and hub, neglected in J, drawn
thin). Disc: J = m D²/8, m = ρ π D² B/4.

>>> from graphmethods.dynamics.flywheel import disc_flywheel, rim_flywheel
>>> s = flywheel_design(rim_flywheel(43.69, n_rpm=600.0, D=0.75), disc_flywheel(43.69, D=0.75, n_rpm=600.0))
>>> s.scales()[0].caption("en")
'μ_l = 0.02 m/mm'
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from graphmethods.scene import Line, Page, Scale, Scene, Text, notation as get_notation
from graphmethods.scene.elements import Dimension, Element, Region, Table
from graphmethods.scene.notation import Notation
from graphmethods.scene.primitives import THIN, Style
from graphmethods.sheets.frame import SheetFrame
from graphmethods.sheets.layout import TEXT_MM, given_scale

AXIS = Style(width_mm=0.18, dash=(6.0, 1.2, 1.0, 1.2))
OUTLINE = Style(width_mm=0.5)



def _rect(x0: float, y0: float, x1: float, y1: float) -> tuple[tuple[float, float], ...]:
    return ((x0, y0), (x1, y0), (x1, y1), (x0, y1))


def flywheel_design(rim: Any, disc: Any = None, *, notation: str = "en", page: Page | None = None,
                    mu_l: float | None = None, title: str | None = None, problem: str = "") -> Scene:
    """The rim flywheel (and the disc, when given) drawn to scale, dimensioned, with the table.

    Parameters
    ----------
    rim : RimFlywheel
        From :func:`graphmethods.dynamics.flywheel.rim_flywheel`.
    disc : DiscFlywheel, optional
        From :func:`graphmethods.dynamics.flywheel.disc_flywheel`.
    mu_l : float, optional
        Length scale, m/mm (picked to fit when not given).
    notation : {"en", "ru", "zh"}
    """
    nt = get_notation(notation)
    if not hasattr(rim, "H") and disc is None:       # a disc alone (flywheel --disc without --rim)
        rim, disc = None, rim
    sheet = SheetFrame(nt=nt, page=page, title=title or nt.word("flywheel.design_title"), problem=problem,
                       title_block=True, default_page=Page("A4", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    lay = LAYOUT
    top = sheet.top + lay.top_mm
    room_h = 0.5 * (sheet.caption_y - lay.bottom_mm - top)  # the drawings above, the table under them
    parts = [p for p in (rim, disc) if p is not None]
    widest = max(p.D + getattr(p, "H", 0.0) for p in parts)
    span_w = sum(p.B for p in parts)
    room_w = (x1 - x0) * lay.drawings_share - lay.dimensions_mm
    s_l = given_scale(mu_l, "μ_l", nt.unit("m"), max(widest, span_w * room_h / max(room_w, 1.0)), room_h,
                      what="the flywheel")
    cy = top + room_h / 2                                     # the axis of rotation (horizontal on paper)
    xr = x0 + lay.rim_left_mm
    els: list[Any] = [sheet.header()]
    if rim is not None:
        els += _rim_section(rim, s_l, nt, xr, cy, top)
    if disc is not None:
        els += _disc_section(disc, s_l, nt, xr + (s_l.to_mm(rim.B) + lay.disc_gap_mm if rim is not None else 0.0),
                             cy, top)
    els.append(Table((x0 + 10.0, cy + room_h / 2 + 14.0), _table_rows(parts, nt), align="lrr", size_mm=2.8,
                     name="table"))
    verdicts = []
    for p, key in zip(parts, ("rim", "disc") if rim is not None else ("disc",)):
        verdict = nt.word("flywheel.ok") if p.rim_speed <= p.speed_limit else nt.word("flywheel.over")
        verdicts.append(f"{nt.word(f'flywheel.{key}')}: {verdict}")
    els.append(Text((x0, sheet.caption_y - 7.0), ";  ".join(verdicts), size_mm=TEXT_MM, name="verdict"))
    els += sheet.captions((s_l,))
    return Scene(sheet.page((s_l,)), tuple(els), title=sheet.title, notation=nt.code, name="flywheel-design")


@dataclass(frozen=True)
class FlywheelDesignLayout:
    """The millimetre constants of the flywheel design sheet."""

    top_mm: float = 12.0             # the headings below the top of the drawing
    bottom_mm: float = 22.0          # kept above the captions
    drawings_share: float = 0.55     # of the width, for the sections
    dimensions_mm: float = 90.0      # of that share, for the dimensions
    rim_left_mm: float = 50.0        # the rim's section from the frame
    disc_gap_mm: float = 95.0        # between the rim's section and the disc's


LAYOUT = FlywheelDesignLayout()


def _length(nt: Notation, v: float) -> str:
    """A length in m written in mm, ``"750 mm"``."""
    return f"{nt.number(v * 1000.0, sig=4)} {nt.unit('mm')}"


def _rim_section(rim: Any, s_l: Scale, nt: Notation, xr: float, cy: float, top: float) -> list[Element]:
    """The rim flywheel's axial section at ``xr`` about the axis ``cy``: rim, spokes, hub, dimensions."""
    els: list[Element] = []
    b = s_l.to_mm(rim.B)
    r_out, r_in = s_l.to_mm(rim.D1) / 2, s_l.to_mm(rim.D2) / 2
    els.append(Text((xr - 30.0, top - 4.0), nt.word("flywheel.rim"), size_mm=TEXT_MM + 0.4, bold=True,
                    name="heading-rim"))
    hub = max(0.12 * r_in, 3.0)
    for sgn, key in ((-1, "upper"), (1, "lower")):
        ya, yb = cy + sgn * r_in, cy + sgn * r_out
        els.append(Region(_rect(xr, min(ya, yb), xr + b, max(ya, yb)), hatch_angle_deg=45.0, hatch_spacing_mm=2.0,
                          name=f"rim-section-{key}"))
        els.append(Line((xr, ya), (xr, yb), style=OUTLINE, name=f"rim-{key}-left"))
        els.append(Line((xr + b, ya), (xr + b, yb), style=OUTLINE, name=f"rim-{key}-right"))
        els.append(Line((xr, ya), (xr + b, ya), style=OUTLINE, name=f"rim-{key}-inner"))
        els.append(Line((xr, yb), (xr + b, yb), style=OUTLINE, name=f"rim-{key}-outer"))
        # a spoke and the hub (thin: neglected in J)
        els.append(Line((xr + b / 2, cy + sgn * hub), (xr + b / 2, ya), style=THIN, name=f"spoke-{key}"))
    els.append(Line((xr + b / 2 - 0.6 * b, cy - hub), (xr + b / 2 + 0.6 * b, cy - hub), style=THIN, name="hub-top"))
    els.append(Line((xr + b / 2 - 0.6 * b, cy + hub), (xr + b / 2 + 0.6 * b, cy + hub), style=THIN, name="hub-bottom"))
    els.append(Line((xr - 10.0, cy), (xr + b + 10.0, cy), style=AXIS, name="rim-axis"))
    els.append(Dimension((xr, cy - r_out), (xr, cy + r_out), f"D_{{1}} = {_length(nt, rim.D1)}", offset_mm=12.0,
                         size_mm=TEXT_MM, name="dim-rim-D1"))
    r_m = s_l.to_mm(rim.D) / 2
    els.append(Dimension((xr + b, cy + r_m), (xr + b, cy - r_m), f"D = {_length(nt, rim.D)}", offset_mm=42.0,
                         size_mm=TEXT_MM, name="dim-rim-D"))
    els.append(Dimension((xr, cy - r_out), (xr + b, cy - r_out), f"B = {_length(nt, rim.B)}", offset_mm=-6.0,
                         size_mm=TEXT_MM, name="dim-rim-B"))
    els.append(Dimension((xr + b, cy - r_in), (xr + b, cy - r_out), f"H = {_length(nt, rim.H)}", offset_mm=6.0,
                         size_mm=TEXT_MM, name="dim-rim-H"))
    return els


def _disc_section(disc: Any, s_l: Scale, nt: Notation, xd: float, cy: float, top: float) -> list[Element]:
    """The solid disc's axial section at ``xd`` about the axis ``cy``, dimensioned."""
    els: list[Element] = []
    bd = s_l.to_mm(disc.B)
    rd = s_l.to_mm(disc.D) / 2
    els.append(Text((xd - 10.0, top - 4.0), nt.word("flywheel.disc"), size_mm=TEXT_MM + 0.4, bold=True,
                    name="heading-disc"))
    els.append(Region(_rect(xd, cy - rd, xd + bd, cy + rd), hatch_angle_deg=45.0, hatch_spacing_mm=2.0,
                      name="disc-section"))
    for i, (p, q) in enumerate((((xd, cy - rd), (xd + bd, cy - rd)), ((xd + bd, cy - rd), (xd + bd, cy + rd)),
                                ((xd + bd, cy + rd), (xd, cy + rd)), ((xd, cy + rd), (xd, cy - rd)))):
        els.append(Line(p, q, style=OUTLINE, name=f"disc-edge-{i}"))
    els.append(Line((xd - 10.0, cy), (xd + bd + 10.0, cy), style=AXIS, name="disc-axis"))
    els.append(Dimension((xd + bd, cy + rd), (xd + bd, cy - rd), f"D = {_length(nt, disc.D)}", offset_mm=10.0,
                         size_mm=TEXT_MM, name="dim-disc-D"))
    els.append(Dimension((xd, cy - rd), (xd + bd, cy - rd), f"B = {_length(nt, disc.B)}", offset_mm=-6.0,
                         size_mm=TEXT_MM, name="dim-disc-B"))
    return els


def _table_rows(parts: list[Any], nt: Notation) -> tuple[tuple[str, ...], ...]:
    """The table: J, m, mD², D and B, ρ and the rim speed of each flywheel."""
    num = nt.number
    kg, kgm2, ms, mm = nt.unit("kg"), nt.unit("kg·m²"), nt.unit("m/s"), nt.unit("mm")
    head = ("",) + tuple(nt.word("flywheel.rim_short" if hasattr(p, "H") else "flywheel.disc_short") for p in parts)
    rows: list[tuple[str, ...]] = [head]

    def row(label: str, f: Any) -> None:
        rows.append((label,) + tuple(f(p) for p in parts))

    row(f"J, {kgm2}", lambda p: num(p.J, sig=5))
    row(f"{nt.word('flywheel.mass')}, {kg}", lambda p: num(p.m, sig=4))
    row(f"{nt.word('flywheel.moment')}, {kgm2}", lambda p: num(p.m * p.D**2, sig=4))
    row(f"D, B, {mm}", lambda p: f"{num(p.D * 1000, sig=4)}, {num(p.B * 1000, sig=3)}")
    row(f"ρ, {nt.unit('kg/m³')}", lambda p: num(p.rho, sig=4))
    limit = nt.word("flywheel.limit")
    row(f"{nt.word('flywheel.speed')}, {ms}",
        lambda p: f"{num(p.rim_speed, sig=3)} ({limit} {num(p.speed_limit, sig=3)})")
    return tuple(rows)
