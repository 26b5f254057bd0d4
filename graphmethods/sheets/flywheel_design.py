"""The flywheel as an engineering drawing: the rim (spoked) flywheel and the solid disc sized from J_F,
each in axial section at one standard scale of the drawing series (1 : 2, 1 : 2.5, 1 : 4, 1 : 5,
1 : 10, 1 : 15, 1 : 20, ...; the largest that fits the page), with rim, spokes or web, hub and bore,
⌀ dimensions in mm written clear of every line, and the table of masses, flywheel moments m·D² and
rim speeds against the material's limit (domain.md §6). A4 landscape.

Rim: J ≈ m D²/4, m = ρ π D H B (mean diameter D, radial thickness H, width B, H/B given); the spokes
and the hub are neglected in J. Disc: J = m D²/8, m = ρ π D² B/4. The hub and the bore follow the
usual proportions (bore d ≈ 0.15 D on the normal series of sizes, hub ⌀ 1.8 d, hub length 1.5 d):
the shaft's own design fixes d. Spokes cut along their length are drawn unhatched, as the drafting
standards draw them.

>>> from graphmethods.dynamics.flywheel import disc_flywheel, rim_flywheel
>>> s = flywheel_design(rim_flywheel(43.69, n_rpm=600.0, D=0.75), disc_flywheel(43.69, D=0.75, n_rpm=600.0))
>>> s.scales()[0].caption("en"), s.element("scale-note").text
('μ_l = 0.01 m/mm', 'Scale 1 : 10')
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from graphmethods.errors import InputError
from graphmethods.scene import Line, Page, Scale, Scene, Text, notation as get_notation
from graphmethods.scene.elements import CAP, Dimension, Element, Region, Table
from graphmethods.scene.markup import text_width_mm
from graphmethods.scene.notation import Notation
from graphmethods.scene.numbers import FLYWHEEL_DIGITS
from graphmethods.scene.primitives import Label, Style
from graphmethods.sheets.frame import SheetFrame
from graphmethods.sheets.layout import TEXT_MM
from graphmethods.sheets.styles import CENTRE_LINE

AXIS = CENTRE_LINE
OUTLINE = Style(width_mm=0.5)
#: the reduction scales of a machine drawing (ГОСТ 2.302, GB/T 14690), 1 : k
DRAWING_SCALES = (1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 15.0, 20.0, 25.0, 40.0, 50.0, 75.0, 100.0)
#: significant digits of each kind of quantity (:data:`graphmethods.scene.numbers.FLYWHEEL_DIGITS`), one rule
#: for this drawing's table, the hyperbola and the text of ``graphmethods flywheel``
DIGITS = FLYWHEEL_DIGITS
#: the normal linear sizes (ГОСТ 6636 Ra 20), mm: the bore is rounded up to one
NORMAL_MM = (20, 22, 25, 28, 32, 36, 40, 45, 50, 56, 63, 71, 80, 90, 100, 110, 125, 140, 160, 180, 200, 220, 250,
             280, 320, 360, 400)


@dataclass(frozen=True)
class FlywheelDesignLayout:
    """The millimetre constants of the flywheel drawing."""

    top_mm: float = 12.0             # the headings below the top of the drawing
    bottom_mm: float = 10.0          # kept above the captions
    dim_step_mm: float = 12.0        # between parallel dimension lines (≥ 7, and a value's width)
    dim_first_mm: float = 8.0        # the first dimension line from the contour
    value_mm: float = 10.5           # a ⌀ value's width and its gap
    width_dims_mm: float = 12.0      # above and below a section: its width dimensions
    table_mm: float = 80.0           # the table's column at the right
    gap_mm: float = 8.0              # between the drawings


LAYOUT = FlywheelDesignLayout()


@dataclass(frozen=True)
class Hub:
    """The hub and the bore of a flywheel of mean diameter D (m), by the usual proportions."""

    d: float          # bore, m
    d_hub: float      # hub's outer diameter, m
    L: float          # hub's length, m

    @classmethod
    def of(cls, D: float, B: float) -> Hub:
        d_mm = next((v for v in NORMAL_MM if v >= 150.0 * D), NORMAL_MM[-1])
        d = d_mm / 1000.0
        return cls(d=d, d_hub=1.8 * d, L=max(1.5 * d, 1.2 * B))


def _rect(x0: float, y0: float, x1: float, y1: float) -> tuple[tuple[float, float], ...]:
    return ((x0, y0), (x1, y0), (x1, y1), (x0, y1))


def _outer_D(p: Any) -> float:
    return float(getattr(p, "D1", p.D))


def _width(p: Any) -> float:
    return max(p.B, Hub.of(p.D, p.B).L)


def side_layouts(p: Any, lay: FlywheelDesignLayout = LAYOUT) -> tuple[FlywheelDesignLayout, FlywheelDesignLayout]:
    """The layouts of a section's left (outer ⌀) and right (hub, bore) dimensions, each with its dimension lines
    spaced for its widest ⌀ value (a ⌀915.8 is wider than the 12 mm step: the next line out struck it through),
    measured as English writes it, so every language draws at one scale.

    >>> from graphmethods.dynamics.flywheel import rim_flywheel
    >>> left, right = side_layouts(rim_flywheel(60.69, n_rpm=120.0, D=1.2))
    >>> left.dim_step_mm > right.dim_step_mm == LAYOUT.dim_step_mm
    True
    """
    hub = Hub.of(p.D, p.B)
    en = get_notation("en")
    sides = ([_outer_D(p)] + ([p.D2] if hasattr(p, "D2") else []), [hub.d_hub, hub.d])
    out = []
    for values in sides:
        widest = max(text_width_mm(f"⌀{size_text(v, en)}", TEXT_MM) for v in values)
        out.append(replace(lay, dim_step_mm=max(lay.dim_step_mm, widest + 3.0),
                           value_mm=max(lay.value_mm, widest + 1.5)))
    return out[0], out[1]


def _side_width(lay: FlywheelDesignLayout) -> float:
    """The width two ⌀ dimensions take on one side of a section, mm."""
    return lay.dim_first_mm + lay.dim_step_mm + lay.value_mm


def _dims_width(p: Any, lay: FlywheelDesignLayout) -> float:
    """The width the ⌀ dimensions take on both sides of a section, mm."""
    return sum(_side_width(side) for side in side_layouts(p, lay))


def _span(p: Any, k: float) -> float:
    """The width of a section on paper at 1 : k, mm: the rim's or the web's, or the hub's when it is wider."""
    return max(_width(p), Hub.of(p.D, p.B).L) * 1000.0 / k


def drawing_scale(parts: list[Any], room_w: float, room_h: float, lay: FlywheelDesignLayout = LAYOUT) -> float:
    """The largest standard drawing scale 1 : k at which every section and its dimensions fit, k.

    >>> from graphmethods.dynamics.flywheel import rim_flywheel
    >>> drawing_scale([rim_flywheel(43.69, n_rpm=600.0, D=0.75)], 160.0, 130.0)
    10.0
    """
    for k in DRAWING_SCALES:
        w = sum(_span(p, k) + _dims_width(p, lay) for p in parts) + lay.gap_mm * (len(parts) - 1)
        h = max(_outer_D(p) for p in parts) * 1000.0 / k + 2 * lay.width_dims_mm
        if w <= room_w and h <= room_h:
            return k
    raise InputError(f"the flywheel (⌀{max(_outer_D(p) for p in parts) * 1000:.0f} mm) does not fit the page "
                     f"even at 1 : {DRAWING_SCALES[-1]:g}; give a larger page")


def flywheel_design(rim: Any, disc: Any = None, *, notation: str = "en", page: Page | None = None,
                    mu_l: float | None = None, title: str | None = None, problem: str = "") -> Scene:
    """The rim flywheel (and the disc, when given) as a drawing: sections at a standard scale, ⌀ dimensions, table.

    Parameters
    ----------
    rim : RimFlywheel or DiscFlywheel
        From :func:`graphmethods.dynamics.flywheel.rim_flywheel` (or a disc drawn alone).
    disc : DiscFlywheel, optional
        From :func:`graphmethods.dynamics.flywheel.disc_flywheel`.
    mu_l : float, optional
        Length scale, m/mm (default: the largest standard drawing scale that fits, 1 : k is k/1000 m/mm).
    notation : {"en", "ru", "zh"}
    """
    nt = get_notation(notation)
    if not hasattr(rim, "H") and disc is None:       # a disc alone (flywheel --disc without --rim)
        rim, disc = None, rim
    default_title = (nt.word("flywheel.design_title") if rim is not None and disc is not None
                     else nt.word("flywheel.design_title_rim") if rim is not None
                     else nt.word("flywheel.design_title_disc"))
    sheet = SheetFrame(nt=nt, page=page, title=title or default_title, problem=problem,
                       title_block=True, default_page=Page("A4", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    parts = [p for p in (rim, disc) if p is not None]
    lay = LAYOUT
    top = sheet.top + lay.top_mm
    bottom = sheet.caption_y - lay.bottom_mm
    room_w = x1 - x0 - lay.table_mm - lay.gap_mm
    k = 1000.0 * float(mu_l) if mu_l is not None else drawing_scale(parts, room_w, bottom - top, lay)
    s_l = Scale("μ_l", nt.unit("m"), k / 1000.0, note=f"1 : {k:g}, the largest drawing scale that fits")
    cy = (top + bottom) / 2                                    # the axis of rotation (horizontal on paper)
    els: list[Any] = [sheet.header()]
    widths = [_span(p, k) + _dims_width(p, lay) for p in parts]
    spare = (room_w - sum(widths) - lay.gap_mm * (len(parts) - 1)) / (len(parts) + 1)
    x = x0 + max(spare, 0.0)
    for p, w in zip(parts, widths):
        centre = x + _side_width(side_layouts(p, lay)[0]) + _span(p, k) / 2
        kind = "rim" if hasattr(p, "H") else "disc"
        els += _section(p, kind, s_l, nt, centre, cy, top, name=kind, lay=lay)
        x += w + lay.gap_mm + max(spare, 0.0)
    els.append(Text((x0 + 2.0, sheet.top + 4.0), nt.word("flywheel.scale", k=f"{k:g}"), size_mm=TEXT_MM,
                    name="scale-note"))
    tx = x1 - lay.table_mm
    table = Table((tx, top), _table_rows(parts, nt), align="lrr", size_mm=2.8, name="table")
    els.append(table)
    for i, key in enumerate(("hub_note", "hub_rule")):
        els.append(Text((tx, top + table.height_mm + 6.0 + 4.5 * i), nt.word(f"flywheel.{key}"), size_mm=2.8,
                        name=f"hub-note-{i}"))
    verdicts = []
    for p, key in zip(parts, ("rim", "disc") if rim is not None else ("disc",)):
        verdict = nt.word("flywheel.ok") if p.rim_speed <= p.speed_limit else nt.word("flywheel.over")
        verdicts.append(f"{nt.word(f'flywheel.{key}')}{nt.colon}{verdict}")
    els.append(Text((x0, sheet.caption_y - 7.0), nt.semicolon.join(verdicts), size_mm=TEXT_MM, name="verdict"))
    els += sheet.captions((s_l,))
    return Scene(sheet.page((s_l,)), tuple(els), title=sheet.title, notation=nt.code, name="flywheel-design")


def size_text(value_m: float, nt: Notation) -> str:
    """A size of the drawing in mm as the table writes it (one number on the drawing and in its table:
    the table's mass and J_F are of these sizes, so the dimension is not rounded further).

    >>> from graphmethods.scene import notation
    >>> size_text(0.1105, notation("ru")), size_text(0.75, notation("en"))
    ('110,5', '750')
    """
    return nt.number(value_m * 1000, sig=DIGITS["mm"])


def _diameter(name: str, x: float, cy: float, r: float, side: int, level: int, lay: FlywheelDesignLayout,
              value_m: float, nt: Notation) -> Dimension:
    """A ⌀ dimension of radius ``r`` (mm on paper) on the ``side`` (−1 left, +1 right) of the contour at
    ``x``, on the ``level``-th dimension line out: its value between its line and the next one out."""
    off = lay.dim_first_mm + level * lay.dim_step_mm
    a, b = (x, cy + r), (x, cy - r)                            # measured upwards: the line to the right
    if side < 0:
        a, b = b, a                                            # measured downwards: the line to the left
    return Dimension(a, b, f"⌀{size_text(value_m, nt)}", offset_mm=off, size_mm=TEXT_MM, name=name)


def _bore(name: str, x: float, cy: float, r: float, r_hub: float, lay: FlywheelDesignLayout,
          value_m: float, nt: Notation) -> list[Element]:
    """The bore's ⌀ on the first line right of the hub. Its value goes between the extension lines; where they
    are closer than the value is high (⌀80 in a ⌀144 hub at 1 : 40: 2 and 3.6 mm) it is written under the
    hub's lower one, beside its own line (the extension lines, 1.5 mm past the line, struck it through)."""
    dim = _diameter(name, x, cy, r, 1, 0, lay, value_m, nt)
    value = next(p for p in dim.primitives() if isinstance(p, Label))
    band = (value.y - CAP * value.size_mm - 0.5, value.y + 0.5)         # the capitals' band, with a margin
    if not any(band[0] <= y <= band[1] for y in (cy - r_hub, cy + r_hub, cy - r, cy + r)):
        return [dim]
    line_x = dim.line_start[0]
    return [replace(dim, text=""), Text((line_x + 1.2, cy + r_hub + 1.0 + CAP * TEXT_MM), dim.text, size_mm=TEXT_MM,
                                        name=f"{name}-value")]


def _section(p: Any, kind: str, s_l: Scale, nt: Notation, xc: float, cy: float, top: float, *,
             name: str, lay: FlywheelDesignLayout = LAYOUT) -> list[Element]:
    """One flywheel's axial section centred at ``xc`` on the axis ``cy``: the rim or the web, the hub, the
    bore (empty), spokes unhatched; ⌀ dimensions left (outer) and right (hub, bore), widths above and below."""
    hub = Hub.of(p.D, p.B)
    mm = s_l.to_mm
    b, L = mm(p.B), mm(hub.L)
    r_bore, r_hub = mm(hub.d) / 2, mm(hub.d_hub) / 2
    r_out = mm(_outer_D(p)) / 2
    r_in = mm(p.D2) / 2 if kind == "rim" else r_hub
    xl, xr = xc - b / 2, xc + b / 2                            # the rim's or the web's faces
    hl, hr = xc - L / 2, xc + L / 2                            # the hub's faces
    els: list[Element] = [Text((xc, top - 4.0), nt.word(f"flywheel.{kind}"), size_mm=TEXT_MM + 0.5, bold=True,
                               anchor="middle", name=f"heading-{name}")]
    for sgn, half in ((-1, "upper"), (1, "lower")):
        y_in, y_out = cy + sgn * r_in, cy + sgn * r_out
        y_bore, y_hub = cy + sgn * r_bore, cy + sgn * r_hub
        outer = _rect(xl, min(y_in, y_out), xr, max(y_in, y_out))
        els.append(Region(outer, hatch_angle_deg=45.0, hatch_spacing_mm=2.0,
                          name=f"{'rim' if kind == 'rim' else 'disc'}-section-{half}"))
        els.append(Region(_rect(hl, min(y_bore, y_hub), hr, max(y_bore, y_hub)), hatch_angle_deg=45.0,
                          hatch_spacing_mm=2.0, name=f"{name}-hub-{half}"))
        els += [Line(a, c, style=OUTLINE, name=f"{name}-{half}-{i}") for i, (a, c) in enumerate((
            (outer[0], outer[1]), (outer[1], outer[2]), (outer[2], outer[3]), (outer[3], outer[0]),
            ((hl, y_bore), (hr, y_bore)), ((hl, y_hub), (hr, y_hub)), ((hl, y_bore), (hl, y_hub)),
            ((hr, y_bore), (hr, y_hub))))]
        if kind == "rim":                                      # a spoke cut along its length: not hatched
            w = 0.45 * b
            els += [Line((xc - w / 2, y_hub), (xc - w / 2, y_in), style=OUTLINE, name=f"{name}-spoke-{half}-a"),
                    Line((xc + w / 2, y_hub), (xc + w / 2, y_in), style=OUTLINE, name=f"{name}-spoke-{half}-b")]
    reach = max(b, L) / 2 + 4.0
    els.append(Line((xc - reach, cy), (xc + reach, cy), style=AXIS, name=f"{name}-axis"))
    right = max(xr, hr)
    left = min(xl, hl)                     # a hub wider than the rim: the ⌀ lines start left of it (and of the axis)
    lay_l, lay_r = side_layouts(p, lay)
    els += [_diameter(f"dim-{name}-D1", left, cy, r_out, -1, 1, lay_l, _outer_D(p), nt)]
    if kind == "rim":
        els.append(_diameter(f"dim-{name}-D2", left, cy, r_in, -1, 0, lay_l, p.D2, nt))
    els += [_diameter(f"dim-{name}-hub", right, cy, r_hub, 1, 1, lay_r, hub.d_hub, nt),
            *_bore(f"dim-{name}-bore", right, cy, r_bore, r_hub, lay_r, hub.d, nt)]
    els += _width_dimension((xl, cy - r_out), (xr, cy - r_out), size_text(p.B, nt), -7.0, f"dim-{name}-B")
    els += _width_dimension((hl, cy + r_hub), (hr, cy + r_hub), size_text(hub.L, nt), (r_out - r_hub) + 7.0,
                            f"dim-{name}-L")
    return els


def _width_dimension(a: tuple[float, float], b: tuple[float, float], value: str, offset_mm: float,
                     name: str) -> list[Element]:
    """A width dimension; a value wider than the width between its extension lines (a 38 mm disc at 1 : 15 is
    2.5 mm) is written beside the line, right of the right extension line, as drawings do."""
    if text_width_mm(value, TEXT_MM) + 1.0 <= abs(b[0] - a[0]):
        return [Dimension(a, b, value, offset_mm=offset_mm, size_mm=TEXT_MM, name=name)]
    dim = Dimension(a, b, "", offset_mm=offset_mm, size_mm=TEXT_MM, name=name)
    y0 = dim.line_start[1]
    return [dim, Text((max(a[0], b[0]) + 2.0, y0 - 1.0), value, size_mm=TEXT_MM, name=f"{name}-value")]


def _table_rows(parts: list[Any], nt: Notation) -> tuple[tuple[str, ...], ...]:
    """The table: J_F, m, mD², D, B, ρ and the rim speed of each flywheel."""
    num = nt.number
    head = ("",) + tuple(nt.word("flywheel.rim_short" if hasattr(p, "H") else "flywheel.disc_short") for p in parts)
    rows: list[tuple[str, ...]] = [head]

    def row(label: str, f: Any) -> None:
        rows.append((label,) + tuple(f(p) for p in parts))

    row(nt.quantity(nt.sym("dynamics.J_F"), "kg·m²"), lambda p: num(p.J, sig=DIGITS["J"]))   # as the hyperbola
    row(nt.quantity(nt.word("flywheel.mass"), "kg"), lambda p: num(p.m, sig=DIGITS["mass"]))
    row(nt.quantity(nt.word("flywheel.moment"), "kg·m²"), lambda p: num(p.m * p.D**2, sig=DIGITS["J"]))
    # D and B each on its row: "750, 111" reads as one number with a decimal comma in Russian
    row(nt.quantity("D", "mm"), lambda p: size_text(p.D, nt))
    row(nt.quantity("B", "mm"), lambda p: size_text(p.B, nt))
    row(nt.quantity("ρ", "kg/m³"), lambda p: num(p.rho, sig=DIGITS["density"]))
    row(nt.quantity(nt.word("flywheel.speed"), "m/s"), lambda p: num(p.rim_speed, sig=DIGITS["speed"]))
    row(nt.quantity(nt.word("flywheel.limit"), "m/s"), lambda p: num(p.speed_limit, sig=DIGITS["speed"]))
    return tuple(rows)
