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

from typing import Any

from graphmethods.scene import Line, Page, Scene, Text, notation as get_notation
from graphmethods.scene.elements import Dimension, Region, Table
from graphmethods.scene.primitives import THIN, Style
from graphmethods.sheets.dynamics import SheetFrame, unit
from graphmethods.sheets.layout import TEXT_MM, given_scale

AXIS = Style(width_mm=0.18, dash=(6.0, 1.2, 1.0, 1.2))
OUTLINE = Style(width_mm=0.5)
_LANG = {"en": 0, "ru": 1, "zh": 2}
_W = {
    "title": ("Flywheel design: rim and disc", "Конструкция маховика: обод и диск", "飞轮结构设计: 轮缘式与盘式"),
    "rim": ("rim (spoked) flywheel", "маховик с ободом (спицевый)", "轮缘式飞轮"),
    "disc": ("solid disc", "сплошной диск", "盘式飞轮"),
    "rim_short": ("rim", "обод", "轮缘式"),
    "disc_short": ("disc", "диск", "盘式"),
    "mass": ("mass m", "масса m", "质量 m"),
    "moment": ("flywheel moment mD²", "маховой момент mD²", "飞轮矩 mD²"),
    "speed": ("rim speed", "окружная скорость обода", "轮缘圆周速度"),
    "limit": ("limit", "допускаемая", "许用"),
    "ok": ("within the limit", "в пределах допускаемой", "在许用范围内"),
    "over": ("OVER the limit: a larger D is not allowed; use steel or a smaller n",
             "ПРЕВЫШЕНА: сталь или меньшая частота", "超过许用值: 改用钢或降低转速"),
}


def _w(nt: Any, key: str) -> str:
    return _W[key][_LANG.get(nt.code, 0)]


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
    sheet = SheetFrame(nt=nt, page=page, title=title or _w(nt, "title"), problem=problem, title_block=True,
                       default_page=Page("A4", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    top = sheet.top + 12.0
    room_h = 0.5 * (sheet.caption_y - 22.0 - top)          # the drawings above, the table under them
    parts = [rim] + ([disc] if disc is not None else [])
    widest = max(rim.D + rim.H, disc.D if disc is not None else 0.0)
    span_w = rim.B + (disc.B if disc is not None else 0.0)
    room_w = (x1 - x0) * 0.55 - 90.0
    s_l = given_scale(mu_l, "μ_l", unit(nt, "m"), max(widest, span_w * room_h / max(room_w, 1.0)), room_h,
                      what="the flywheel")
    num = nt.number
    mm = unit(nt, "mm")

    def L(v: float) -> str:
        return f"{num(v * 1000.0, sig=4)} {mm}"

    els: list[Any] = [sheet.header()]
    cy = top + room_h / 2                                     # the axis of rotation (horizontal on paper)
    # --- the rim flywheel: its axial section
    xr = x0 + 50.0
    b = s_l.to_mm(rim.B)
    r_out, r_in = s_l.to_mm(rim.D1) / 2, s_l.to_mm(rim.D2) / 2
    els.append(Text((xr - 30.0, top - 4.0), _w(nt, "rim"), size_mm=TEXT_MM + 0.4, bold=True, name="heading-rim"))
    for sgn, key in ((-1, "upper"), (1, "lower")):
        ya, yb = cy + sgn * r_in, cy + sgn * r_out
        els.append(Region(_rect(xr, min(ya, yb), xr + b, max(ya, yb)), hatch_angle_deg=45.0, hatch_spacing_mm=2.0,
                          name=f"rim-section-{key}"))
        els.append(Line((xr, ya), (xr, yb), style=OUTLINE, name=f"rim-{key}-left"))
        els.append(Line((xr + b, ya), (xr + b, yb), style=OUTLINE, name=f"rim-{key}-right"))
        els.append(Line((xr, ya), (xr + b, ya), style=OUTLINE, name=f"rim-{key}-inner"))
        els.append(Line((xr, yb), (xr + b, yb), style=OUTLINE, name=f"rim-{key}-outer"))
        # a spoke and the hub (thin: neglected in J)
        hub = max(0.12 * r_in, 3.0)
        els.append(Line((xr + b / 2, cy + sgn * hub), (xr + b / 2, ya), style=THIN, name=f"spoke-{key}"))
    hub = max(0.12 * r_in, 3.0)
    els.append(Line((xr + b / 2 - 0.6 * b, cy - hub), (xr + b / 2 + 0.6 * b, cy - hub), style=THIN, name="hub-top"))
    els.append(Line((xr + b / 2 - 0.6 * b, cy + hub), (xr + b / 2 + 0.6 * b, cy + hub), style=THIN, name="hub-bottom"))
    els.append(Line((xr - 10.0, cy), (xr + b + 10.0, cy), style=AXIS, name="rim-axis"))
    els.append(Dimension((xr, cy - r_out), (xr, cy + r_out), f"D_{{1}} = {L(rim.D1)}", offset_mm=12.0,
                         size_mm=TEXT_MM, name="dim-rim-D1"))
    r_m = s_l.to_mm(rim.D) / 2
    els.append(Dimension((xr + b, cy + r_m), (xr + b, cy - r_m), f"D = {L(rim.D)}", offset_mm=42.0,
                         size_mm=TEXT_MM, name="dim-rim-D"))
    els.append(Dimension((xr, cy - r_out), (xr + b, cy - r_out), f"B = {L(rim.B)}", offset_mm=-6.0,
                         size_mm=TEXT_MM, name="dim-rim-B"))
    els.append(Dimension((xr + b, cy - r_in), (xr + b, cy - r_out), f"H = {L(rim.H)}", offset_mm=6.0,
                         size_mm=TEXT_MM, name="dim-rim-H"))
    # --- the disc
    if disc is not None:
        xd = xr + b + 95.0
        bd = s_l.to_mm(disc.B)
        rd = s_l.to_mm(disc.D) / 2
        els.append(Text((xd - 10.0, top - 4.0), _w(nt, "disc"), size_mm=TEXT_MM + 0.4, bold=True,
                        name="heading-disc"))
        els.append(Region(_rect(xd, cy - rd, xd + bd, cy + rd), hatch_angle_deg=45.0, hatch_spacing_mm=2.0,
                          name="disc-section"))
        for i, (p, q) in enumerate(((( xd, cy - rd), (xd + bd, cy - rd)), ((xd + bd, cy - rd), (xd + bd, cy + rd)),
                                    ((xd + bd, cy + rd), (xd, cy + rd)), ((xd, cy + rd), (xd, cy - rd)))):
            els.append(Line(p, q, style=OUTLINE, name=f"disc-edge-{i}"))
        els.append(Line((xd - 10.0, cy), (xd + bd + 10.0, cy), style=AXIS, name="disc-axis"))
        els.append(Dimension((xd + bd, cy + rd), (xd + bd, cy - rd), f"D = {L(disc.D)}", offset_mm=10.0,
                             size_mm=TEXT_MM, name="dim-disc-D"))
        els.append(Dimension((xd, cy - rd), (xd + bd, cy - rd), f"B = {L(disc.B)}", offset_mm=-6.0,
                             size_mm=TEXT_MM, name="dim-disc-B"))
    # --- the table
    kg, kgm2, ms = unit(nt, "kg"), unit(nt, "kg·m²"), unit(nt, "m/s")
    head = ("", _w(nt, "rim_short")) + ((_w(nt, "disc_short"),) if disc is not None else ())
    rows: list[tuple[str, ...]] = [head]

    def row(label: str, f: Any) -> None:
        rows.append((label,) + tuple(f(p) for p in parts))

    row(f"J, {kgm2}", lambda p: num(p.J, sig=5))
    row(f"{_w(nt, 'mass')}, {kg}", lambda p: num(p.m, sig=4))
    row(f"{_w(nt, 'moment')}, {kgm2}", lambda p: num(p.m * p.D**2, sig=4))
    row(f"D, B, {mm}", lambda p: f"{num(p.D * 1000, sig=4)}, {num(p.B * 1000, sig=3)}")
    row(f"ρ, {unit(nt, 'kg/m³')}", lambda p: num(p.rho, sig=4))
    row(f"{_w(nt, 'speed')}, {ms}", lambda p: f"{num(p.rim_speed, sig=3)} ({_w(nt, 'limit')} {num(p.speed_limit, sig=3)})")
    els.append(Table((x0 + 10.0, cy + room_h / 2 + 14.0), tuple(rows), align="lrr", size_mm=2.8, name="table"))
    verdicts = []
    for p, key in zip(parts, ("rim", "disc")):
        verdicts.append(f"{_w(nt, key)}: {_w(nt, 'ok') if p.rim_speed <= p.speed_limit else _w(nt, 'over')}")
    els.append(Text((x0, sheet.caption_y - 7.0), ";  ".join(verdicts), size_mm=TEXT_MM, name="verdict"))
    els += sheet.captions((s_l,))
    return Scene(sheet.page((s_l,)), tuple(els), title=sheet.title, notation=nt.code, name="flywheel-design")
