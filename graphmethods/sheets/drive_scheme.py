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

from typing import Any

import numpy as np

from graphmethods.scene import Line, Page, Polyline, Scene, Text, notation as get_notation
from graphmethods.scene.elements import Table
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
    J = np.asarray(chain.J, dtype=float)
    # the two schemes share the page's height above the notes, each in its half; the chain spans the width the
    # table leaves (it filled a third of the page with 32 mm discs)
    row = (sheet.caption_y - 24.0 - sheet.top) / 2.0
    h_max = min(0.55 * row, 48.0)

    def heights(values: np.ndarray) -> np.ndarray:
        return h_max * (0.35 + 0.65 * (values / values.max()) ** 0.25)

    h = heights(J)
    left, right = x0 + 28.0, x0 + 0.52 * (x1 - x0)
    xs = [left + (right - left) * i / max(n - 1, 1) for i in range(n)]
    num, sep = nt.number, nt.list_separator
    size = LABEL_MM
    els: list[Any] = [sheet.header()]
    rows_y = ((sheet.top + 0.55 * row, "given"), (sheet.top + row + 0.55 * row, "reduced"))
    for y, key in rows_y:
        reduced = key == "reduced"
        Jr = J if reduced else np.asarray(chain.J_given, dtype=float)
        hh = h if reduced else heights(Jr)
        els.append(Text((x0, y - h_max / 2 - 9.0), nt.word(f"drive.{key}"), size_mm=size + 0.5, bold=True,
                        name=f"heading-{key}"))
        for j in range(n - 1):
            els.append(_spring(xs[j] + 2.5, xs[j + 1] - 2.5, y, f"{key}-shaft-{j + 1}"))
            mid = (xs[j] + xs[j + 1]) / 2
            text = (f"c'_{{{j + 1}}} = {num(float(chain.c[j]), sig=4)} {nt.unit('N·m/rad')}" if reduced else
                    f"c_{{{j + 1}}} = {num(float(chain.c_given[j]), sig=4)} {nt.unit('N·m/rad')}{sep}"
                    f"u = {num(float(chain.u_shafts[j]), sig=4)}")
            els.append(Text((mid, y - 6.0), text, size_mm=size, anchor="middle", name=f"{key}-label-c-{j + 1}"))
        for i in range(n):
            els.append(_disc(xs[i], y, float(hh[i]), f"{key}-disc-{i + 1}", THICK))
            kgm2 = nt.unit("kg·m²")
            text = (f"J'_{{{i + 1}}} = {num(float(J[i]), sig=4)} {kgm2}" if reduced else
                    f"J_{{{i + 1}}} = {num(float(Jr[i]), sig=4)} {kgm2}{sep}u = {num(float(chain.u[i]), sig=4)}")
            els.append(Text((xs[i], y + float(hh[i]) / 2 + 6.0), text, size_mm=size, anchor="middle",
                            name=f"{key}-label-J-{i + 1}"))
            if not reduced and chain.names[i] != str(i + 1):       # a name; an unnamed disc's number is J's index
                els.append(Text((xs[i], y + float(hh[i]) / 2 + 6.0 + 1.5 * size), chain.names[i],
                                size_mm=size - 0.4, anchor="middle", name=f"label-name-{i + 1}"))
        els.append(Line((left - 12.0, y), (left - 2.5, y), style=THIN, name=f"{key}-axis-in"))
    # the table: per mass J', per shaft c'; the frequencies and the rigid drive under it
    rows: list[tuple[str, ...]] = [("", nt.quantity("J", "kg·m²"), "u", nt.quantity("J'", "kg·m²"),
                                    nt.quantity("c", "N·m/rad"), nt.quantity("c'", "N·m/rad"))]
    for i in range(n):
        c_txt = (num(float(chain.c_given[i]), sig=5), num(float(chain.c[i]), sig=5)) if i < n - 1 else ("", "")
        name = chain.names[i] if chain.names[i] != str(i + 1) else ""      # unnamed: its number once
        rows.append((f"{i + 1} {name}".strip(), num(float(chain.J_given[i]), sig=5), num(float(chain.u[i]), sig=4),
                     num(float(J[i]), sig=5), *c_txt))
    table = Table((0.0, 0.0), tuple(rows), align="lrrrrr", size_mm=size, name="table")
    tx = max(right + 10.0, x1 - table.width_mm - 4.0)
    els.append(Table((tx, sheet.top + 8.0), tuple(rows), align="lrrrrr", size_mm=size, name="table"))
    freq = sep.join(f"{num(float(w), sig=4)}" for w in chain.natural_frequencies)
    els.append(Text((x0, sheet.caption_y - 16.0), f"{nt.word('drive.freq')}{nt.colon}ω = {freq} {nt.unit('rad/s')}",
                    size_mm=size, name="frequencies"))
    rigid = (f"{nt.sym('dynamics.J_e')} = ΣJ' = {num(chain.J_e, sig=5)} {nt.unit('kg·m²')}{sep}"
             f"{nt.sym('dynamics.M_e')} = ΣM' = {num(chain.M_e, sig=5)} {nt.unit('N·m')}")
    els.append(Text((x0, sheet.caption_y - 9.0), f"{nt.word('drive.rigid')}{nt.colon}{rigid}",
                    size_mm=size, name="rigid"))
    return Scene(sheet.page(()), tuple(els), title=sheet.title, notation=nt.code, name="drive-scheme")
