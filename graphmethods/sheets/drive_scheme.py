"""The reduced scheme of a drive of several masses (two-, three-, n-mass torsional models).

Top: the drive as given, each mass a disc on its shaft with its speed ratio u_i = ω_i/ω; bottom:
the same chain reduced to one shaft, J_i' = J_i·u_i² and c_j' = c_j·u_j² written at the discs and
the shafts. A scheme, not a drawing to scale: disc heights only grow with J' (its fourth root, so
that a 100 times larger inertia is about three times taller); the numbers are in the table beside
it with the natural frequencies. A4 landscape, en/ru/zh.

>>> from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain
>>> d = reduce_chain([Mass("1", 0.05, 4.0), Mass("2", 2.0, 1.0)], [Shaft("1", 800.0, 4.0)])
>>> s = drive_scheme(d)
>>> s.name, s.element("reduced-disc-2").name
('drive-scheme', 'reduced-disc-2')
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from graphmethods.scene import Line, Page, Polyline, Scene, Text, notation as get_notation
from graphmethods.scene.elements import Table, label_bbox
from graphmethods.scene.primitives import MAIN, THIN, Style
from graphmethods.sheets.frame import SheetFrame

THICK = Style(width_mm=0.5)
#: the scheme's lettering: A4's value size (ГОСТ 2.304 series), read at arm's length
LABEL_MM = 3.5



def _disc(x: float, y: float, h: float, name: str, style: Style) -> Polyline:
    return Polyline(((x - 2.5, y - h / 2), (x + 2.5, y - h / 2), (x + 2.5, y + h / 2), (x - 2.5, y + h / 2)),
                    closed=True, style=style, name=name)


def _spring(x0: float, x1: float, y: float, name: str) -> Polyline:
    """A shaft with a zigzag in its middle third (the elastic element)."""
    a, b = x0 + (x1 - x0) / 3, x1 - (x1 - x0) / 3
    zig = [(x0, y), (a, y)]
    k = 6
    for i in range(1, k):
        zig.append((a + (b - a) * i / k, y + (2.0 if i % 2 else -2.0)))
    zig += [(b, y), (x1, y)]
    return Polyline(tuple(zig), style=MAIN, name=name)


def _width(t: Text) -> float:
    x0, _, x1, _ = label_bbox(t.primitives()[0])  # type: ignore[arg-type]
    return x1 - x0


def _levels(widths: list[tuple[float, float]], gap_mm: float = 1.5) -> list[int]:
    """The level of each label of a row (0 the nearest the chain), given its extent ``(x0, x1)`` in order: the
    first level where it clears the labels already set there by ``gap_mm``: a long chain or long values
    staggered over two or more levels, as a draftsman staggers close dimensions."""
    ends: list[float] = []                  # the right end of the last label set on each level
    out = []
    for x0, x1 in widths:
        k = next((i for i, e in enumerate(ends) if x0 >= e + gap_mm), len(ends))
        ends[k:k + 1] = [x1]
        out.append(k)
    return out


def _extent(t: Text) -> tuple[float, float]:
    w = _width(t)
    return (t.at[0] - w / 2, t.at[0] + w / 2)


def _shaft_labels(labels: list[Text], xs: list[float], tops: list[float], size: float) -> list[Text]:
    """The shafts' labels over the shafts; when one is wider than the room between its two discs, all of them
    above the tallest disc (one was set across the discs' sides), staggered upward where they would touch."""
    if all(_width(t) <= xs[j + 1] - xs[j] - 7.0 for j, t in enumerate(labels)):
        return _stagger(labels, -1.4 * size)
    y = min(tops) - 3.0
    return _stagger([replace(t, at=(t.at[0], y)) for t in labels], -1.4 * size)


def _stagger(labels: list[Text], step_mm: float, *, by: list[Text] | None = None) -> list[Text]:
    """The labels, each moved ``step_mm`` per level (:func:`_levels`; ``by``: the levels of those labels)."""
    levels = _levels([_extent(t) for t in (by if by is not None else labels)])
    return [replace(t, at=(t.at[0], t.at[1] + k * step_mm)) for t, k in zip(labels, levels)]


def _row_texts(chain: Any, nt: Any, key: str) -> tuple[list[str], list[str], list[str]]:
    """The texts of a scheme's shafts, discs and (the given drive) the masses' names."""
    num, sep = nt.number, nt.list_separator
    n = len(chain.names)
    cu, kgm2 = nt.unit("N·m/rad"), nt.unit("kg·m²")
    if key == "reduced":
        return ([f"c'_{{{j + 1}}} = {num(float(chain.c[j]), sig=4)} {cu}" for j in range(n - 1)],
                [f"J'_{{{i + 1}}} = {num(float(chain.J[i]), sig=4)} {kgm2}" for i in range(n)], [])
    return ([f"c_{{{j + 1}}} = {num(float(chain.c_given[j]), sig=4)} {cu}{sep}"
             f"u = {num(float(chain.u_shafts[j]), sig=4)}" for j in range(n - 1)],
            [f"J_{{{i + 1}}} = {num(float(chain.J_given[i]), sig=4)} {kgm2}{sep}u = {num(float(chain.u[i]), sig=4)}"
             for i in range(n)],
            [name if name != str(i + 1) else "" for i, name in enumerate(chain.names)])   # unnamed: no name


def _count(texts: list[list[str]], xs: list[float], size: float) -> int:
    """How many levels above the first the labels centred at ``xs`` need (:func:`_levels`); ``texts``: the
    lines set one under another at each (the widest counts)."""
    labels = [max((Text((x, 0.0), t, size_mm=size, anchor="middle") for t in col), key=_width)
              for x, *col in zip(xs, *(t for t in texts if t))]
    return max(_levels([_extent(t) for t in labels]), default=0)


def _row(chain: Any, nt: Any, key: str, texts: tuple[list[str], list[str], list[str]], xs: list[float], y: float, *,
         h_max: float, up: float, size: float) -> list[Any]:
    """One scheme (the drive as given, or reduced) on the line ``y``: its heading, shafts, discs and labels."""
    reduced = key == "reduced"
    values = np.asarray(chain.J if reduced else chain.J_given, dtype=float)
    hh = h_max * (0.35 + 0.65 * (values / values.max()) ** 0.25)
    n = len(xs)
    els: list[Any] = [Text((xs[0] - 24.0, y - h_max / 2 - 9.0 - up), nt.word(f"drive.{key}"), size_mm=size + 0.5,
                           bold=True, name=f"heading-{key}")]
    c_labels = []
    for j in range(n - 1):
        els.append(_spring(xs[j] + 2.5, xs[j + 1] - 2.5, y, f"{key}-shaft-{j + 1}"))
        c_labels.append(Text(((xs[j] + xs[j + 1]) / 2, y - 6.0), texts[0][j], size_mm=size, anchor="middle",
                             name=f"{key}-label-c-{j + 1}"))
    J_labels, name_labels = [], []
    for i in range(n):
        els.append(_disc(xs[i], y, float(hh[i]), f"{key}-disc-{i + 1}", THICK))
        J_labels.append(Text((xs[i], y + float(hh[i]) / 2 + 6.0), texts[1][i], size_mm=size, anchor="middle",
                             name=f"{key}-label-J-{i + 1}"))
        if not reduced and any(texts[2]):
            name_labels.append(Text((xs[i], y + float(hh[i]) / 2 + 6.0 + 1.5 * size), texts[2][i] or " ",
                                    size_mm=size - 0.4, anchor="middle", name=f"label-name-{i + 1}"))
    els += _shaft_labels(c_labels, xs, [y - float(h) / 2 for h in hh], size)
    step = (2.6 if name_labels else 1.4) * size
    widest = [max((a, b), key=_width) for a, b in zip(J_labels, name_labels)] if name_labels else J_labels
    if max(_levels([_extent(t) for t in widest]), default=0):        # staggered: from one line under the discs
        base = y + float(max(hh)) / 2 + 6.0
        J_labels = [replace(t, at=(t.at[0], base)) for t in J_labels]
        name_labels = [replace(t, at=(t.at[0], base + 1.5 * size)) for t in name_labels]
    els += _stagger(J_labels, step, by=widest) + _stagger(name_labels, step, by=widest)
    els.append(Line((xs[0] - 12.0, y), (xs[0] - 2.5, y), style=THIN, name=f"{key}-axis-in"))
    return els


def _table(chain: Any, nt: Any, size: float) -> Table:
    """The table beside the schemes: per mass J and J', per shaft c and c'."""
    num = nt.number
    rows: list[tuple[str, ...]] = [("", nt.quantity("J", "kg·m²"), "u", nt.quantity("J'", "kg·m²"),
                                    nt.quantity("c", "N·m/rad"), nt.quantity("c'", "N·m/rad"))]
    n = len(chain.names)
    for i in range(n):
        c_txt = (num(float(chain.c_given[i]), sig=5), num(float(chain.c[i]), sig=5)) if i < n - 1 else ("", "")
        name = chain.names[i] if chain.names[i] != str(i + 1) else ""      # unnamed: its number once
        rows.append((f"{i + 1} {name}".strip(), num(float(chain.J_given[i]), sig=5), num(float(chain.u[i]), sig=4),
                     num(float(chain.J[i]), sig=5), *c_txt))
    return Table((0.0, 0.0), tuple(rows), align="lrrrrr", size_mm=size, name="table")


def drive_scheme(chain: Any, *, notation: str = "en", page: Page | None = None, title: str | None = None,
                 problem: str = "") -> Scene:
    """The drive and its reduced scheme (see the module docstring).

    Parameters
    ----------
    chain : ReducedChain
        From :func:`graphmethods.dynamics.multimass.reduce_chain`.
    notation : {"en", "ru", "zh"}
    """
    nt = get_notation(notation)
    sheet = SheetFrame(nt=nt, page=page, title=title or nt.word("drive.title"), problem=problem, title_block=True,
                       default_page=Page("A4", "landscape", frame=True))
    x0, _, x1, _ = sheet.box
    n = len(chain.names)
    # the two schemes share the page's height above the notes, each in its half; the chain spans the width the
    # table leaves (it filled a third of the page with 32 mm discs)
    row = (sheet.caption_y - 24.0 - sheet.top) / 2.0
    size = LABEL_MM
    num, sep = nt.number, nt.list_separator
    table = _table(chain, nt, size)
    tx = x1 - table.width_mm - 4.0
    texts = {key: _row_texts(chain, nt, key) for key in ("given", "reduced")}
    last = max(_width(Text((0.0, 0.0), t[k][-1], size_mm=size)) for t in texts.values() for k in (1, 2) if t[k])
    left, right = x0 + 24.0, min(x0 + 0.52 * (x1 - x0), tx - 3.0 - last / 2)       # the last labels clear the table
    xs = [left + (right - left) * i / max(n - 1, 1) for i in range(n)]
    # the labels' levels (a long chain staggers them) take their height from the discs: a scheme, not to scale
    level = {key: (_count([t[0]], [(xs[j] + xs[j + 1]) / 2 for j in range(n - 1)], size),
                   _count([t[1], t[2]], xs, size)) for key, t in texts.items()}
    up = max(lc for lc, _ in level.values()) * 1.4 * size
    down = max(lj for _, lj in level.values()) * 2.6 * size
    h_max = min(0.55 * row - up - down, 48.0)
    els: list[Any] = [sheet.header()]
    for r, key in enumerate(("given", "reduced")):
        y = sheet.top + r * row + max(0.275 * row - 9.0, 3.0) + 9.0 + up + h_max / 2
        els += _row(chain, nt, key, texts[key], xs, y, h_max=h_max, up=up, size=size)
    els.append(replace(table, at=(max(right + 10.0, tx), sheet.top + 8.0)))
    freq = sep.join(f"{num(float(w), sig=4)}" for w in chain.natural_frequencies)
    els.append(Text((x0, sheet.caption_y - 16.0), f"{nt.word('drive.freq')}{nt.colon}ω = {freq} {nt.unit('rad/s')}",
                    size_mm=size, name="frequencies"))
    rigid = (f"{nt.sym('dynamics.J_e')} = ΣJ' = {num(chain.J_e, sig=5)} {nt.unit('kg·m²')}{sep}"
             f"{nt.sym('dynamics.M_e')} = ΣM' = {num(chain.M_e, sig=5)} {nt.unit('N·m')}")
    els.append(Text((x0, sheet.caption_y - 9.0), f"{nt.word('drive.rigid')}{nt.colon}{rigid}",
                    size_mm=size, name="rigid"))
    return Scene(sheet.page(()), tuple(els), title=sheet.title, notation=nt.code, name="drive-scheme")
