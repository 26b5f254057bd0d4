"""The table of velocities per position: drawn (:func:`velocity_table`) and as Markdown
(:func:`velocity_table_markdown`), from :func:`velocity_rows`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphmethods.errors import InputError
from graphmethods.scene import Scene, Table, Text, markup, notation as get_notation
from graphmethods.scene.markup import MIN_TEXT_MM
from graphmethods.sheets.layout import TEXT_MM, Sheet
from graphmethods.sheets.linkage_figures import TABLE_MM, _end_extreme, _Linkage, _plans_of, _pos_label, _rel_name

# ----------------------------------------------------------------------------- 3. the table of velocities

@dataclass(frozen=True)
class VelocityTable:
    """The velocities per position as a table: column symbols (markup), units, rows of values.

    Attributes
    ----------
    columns : tuple of str
        Column keys: ``"position"``, ``"phi"`` (crank rotation from position 0, °), then
        ``"v_A"``, ``"v_B"``, …, relative velocities ``"v_BA"``, …, and ``"omega_2"``, ….
    symbols : tuple of str
        Their symbols in markup (``"v_{BA}"``, ``"ω_{2}"``).
    units : tuple of str
        Their units (``""`` for the position).
    labels : tuple of str
        The position labels (``"0 (12)"``, ``"1"``, …, ``"6′"`` for an extreme position between two).
    values : ndarray (rows, columns − 1)
        Everything but the position label: φ in °, velocities in m/s, angular velocities in rad/s
        (sliders signed along +x of their guide, other velocities magnitudes, ω counterclockwise +).
    ill_conditioned : ndarray (rows,) of bool
    omega_1 : float
        Crank speed, rad/s.
    """

    columns: tuple
    symbols: tuple
    units: tuple
    labels: tuple
    values: np.ndarray
    ill_conditioned: np.ndarray
    omega_1: float


def velocity_rows(linkage, *, m: int | None = None, omega_1: float | None = None,
                  extremes: bool = True) -> VelocityTable:
    """The velocities per position that :func:`velocity_table` draws (also as Markdown).

    Rows: positions 0…m−1 and, when the end of the working stroke falls between two numbered
    positions (``extremes``), that extreme position in its place (``6′``).

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> t = velocity_rows(SliderCrank(r=0.1, l=0.4), m=4, omega_1=10.0)
    >>> t.columns
    ('position', 'phi', 'v_A', 'v_B', 'v_BA', 'omega_2')
    >>> t.labels, [round(float(v), 6) for v in t.values[:, 2]]
    (('0 (4)', '1', '2', '3'), [0.0, -1.0, 0.0, 1.0])
    """
    lk, plans, pos, drawn = _plans_of(linkage, m=m, omega_1=omega_1)
    mech = pos.mechanism
    ext = _end_extreme(pos) if extremes else None
    plans_e = None
    if ext is not None and ext.same_as is None:
        plans_e = mech.velocity_plans(mech.positions(phi=[ext.phi]), omega_1=lk.omega_1)
    cols, syms, units, data = ["position", "phi"], ["", "φ"], ["", "°"], []

    def both(fn):
        a = np.asarray(fn(plans), dtype=float)[drawn]
        if plans_e is not None:
            a = np.concatenate([a, np.asarray(fn(plans_e), dtype=float)])
        return a

    data.append(both(lambda pl: np.degrees(pl.positions.phi_from_start)))
    rel = []
    for name, c in plans.constructions.items():
        if c.method == "pole":
            continue
        cols.append(f"v_{name}")
        syms.append(f"v_{{{name}}}")
        units.append("m/s")
        if name in mech.guides:
            data.append(both(lambda pl, n=name: pl.v_along_guide(n)))
        else:
            data.append(both(lambda pl, n=name: pl.speed(n)))
        if c.method == "intersection":
            for ln in c.lines:
                if ln.through != "p":
                    y = next(n for n, cc in plans.constructions.items() if cc.label == ln.through)
                    rel.append((name, y))
    for x, y in rel:
        r = _rel_name(mech, x, y)
        cols.append(f"v_{r}")
        syms.append(f"v_{{{r}}}")
        units.append("m/s")
        data.append(both(lambda pl, a=x, b=y: np.hypot(*pl.v_rel(a, b).T)))
    for num, link in mech.link_numbers.items():
        if num >= 2:
            cols.append(f"omega_{num}")
            syms.append(f"ω_{{{num}}}")
            units.append("rad/s")
            data.append(both(lambda pl, lk_=link: pl.omega(lk_)))
    labels = [_pos_label(pos, k) for k in drawn]
    ill = list(np.asarray(plans.ill_conditioned)[drawn])
    values = np.column_stack(data)
    if plans_e is not None:
        assert ext is not None                 # plans_e is made for ext only
        labels.append(ext.label)
        ill.append(bool(plans_e.ill_conditioned[0]))
        order = np.argsort(values[:, 0], kind="stable")
        values = values[order]
        labels = [labels[i] for i in order]
        ill = [ill[i] for i in order]
    values = np.where(np.abs(values) < 1e-12, 0.0, values)
    values.flags.writeable = False
    return VelocityTable(tuple(cols), tuple(syms), tuple(units), tuple(labels), values,
                         np.asarray(ill, dtype=bool), lk.omega_1)


def _table_cells(t: VelocityTable, nt, *, markup_: bool = True) -> list[list[str]]:
    head = [nt.word("kinematics.position")]
    for sym, u in zip(t.symbols[1:], t.units[1:]):
        s = sym if markup_ else markup.plain(sym) if "{" not in sym else sym.replace("{", "").replace("}", "")
        head.append(nt.quantity(s, u))
    rows = [head]
    # each column with one number of decimals, four digits of its largest value (30, not 30.00; 2293 rad/s²,
    # not 2293.489)
    cols = [nt.column(t.values[:, j], sig=4, reference=float(np.abs(t.values[:, j]).max()))
            for j in range(len(t.units) - 1)]
    for i, lab in enumerate(t.labels):
        rows.append([lab + (" *" if t.ill_conditioned[i] else "")] + [col[i] for col in cols])
    return rows


def velocity_table(linkage, *, m: int | None = None, omega_1: float | None = None, notation="en", page=None,
                   title=None, problem=None, title_block: bool = True, name: str = "velocity-table") -> Scene:
    """The table of velocities per position, drawn (the same rows as :func:`velocity_table_markdown`).

    Columns: position, φ from position 0, the velocity of every point (m/s; sliders signed along
    +x of their guide), the relative velocities of the constructions (v_BA, …) and the angular
    velocities of the links (rad/s, counterclockwise +), at the problem's mean crank speed.
    Ill-conditioned positions are starred and explained under the table.

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> s = velocity_table(SliderCrank(r=0.1, l=0.4), m=6, omega_1=10.0, notation="zh")
    >>> s.element("table").rows[0][:3]
    ('位置', 'φ/(°)', 'v_{A}/(m/s)')
    """
    lk = _Linkage.of(linkage, m=m, omega_1=omega_1)
    nt = get_notation(notation)
    t = velocity_rows(lk.plans, omega_1=None)
    sheet = Sheet(nt=nt, page=page, title=title or nt.word("kinematics.table"),
                   problem=lk.problem if problem is None else problem, title_block=title_block)
    x0, y0, x1, y1 = sheet.box
    rows = tuple(tuple(r) for r in _table_cells(t, nt))
    notes = [lk.speed_text(nt), nt.word("kinematics.signed")]
    if t.ill_conditioned.any():
        notes.append("* " + nt.word("kinematics.ill_note"))
    avail = (sheet.caption_y - 6.0 * len(notes) - 4.0) - (sheet.top + 2.0)
    row_h, size, fits = table_rows(avail, len(rows), most=7.0)
    if not fits:
        raise InputError(f"{len(rows) - 1} positions do not fit on this sheet (rows would be {row_h:.1f} mm); "
                         f"give fewer positions or a larger page")
    probe = Table((0.0, 0.0), rows, align="c" + "r" * (len(rows[0]) - 1), size_mm=size, row_height_mm=row_h)
    if probe.width_mm > x1 - x0:
        raise InputError(f"the table is {probe.width_mm:.0f} mm wide but the sheet leaves {x1 - x0:.0f} mm; "
                         f"give a larger page")
    at = ((x0 + x1) / 2 - probe.width_mm / 2, sheet.top + 2.0)
    table = Table(at, rows, align="c" + "r" * (len(rows[0]) - 1), size_mm=size, row_height_mm=row_h,
                  name="table")
    below = table.bottom_left[1] + 6.0
    texts = [Text((at[0], below + i * 6.0), n_, size_mm=TEXT_MM, name=f"note-{i}") for i, n_ in enumerate(notes)]
    return sheet.scene([sheet.header(), table] + texts, (), name=name)


def table_rows(avail: float, n: int, *, most: float) -> tuple[float, float, bool]:
    """The rows of a table of ``n`` rows in ``avail`` mm: (the row height to give, the text size, whether they
    fit). Rows at most ``most`` mm; text up to :data:`TABLE_MM`, 0.65 of a row; on a course sheet the text is
    lettered up to 3.5 mm and the rows grow with it, so they are given that much smaller.

    >>> table_rows(70.0, 14, most=7.0)[0]
    5.0
    """
    row = min(most, avail / n)
    size = min(TABLE_MM, row * 0.65)
    lettered = max(size, MIN_TEXT_MM.get())
    return row * size / lettered, size, row >= 4.0 and lettered <= row * 0.65 + 1e-9


def velocity_table_markdown(linkage, *, m: int | None = None, omega_1: float | None = None, notation="en") -> str:
    """The table of velocities per position as Markdown (the rows :func:`velocity_table` draws).

    Examples
    --------
    >>> from graphmethods.kinematics import SliderCrank
    >>> print(velocity_table_markdown(SliderCrank(r=0.1, l=0.4), m=4, omega_1=10.0).splitlines()[0])
    | Position | φ, ° | v_A, m/s | v_B, m/s | v_BA, m/s | ω_2, rad/s |
    """
    lk = _Linkage.of(linkage, m=m, omega_1=omega_1)
    nt = get_notation(notation)
    t = velocity_rows(lk.plans, omega_1=None)
    rows = _table_cells(t, nt, markup_=False)
    out = ["| " + " | ".join(rows[0]) + " |", "|" + "|".join(":---:" if j == 0 else "---:" for j in
                                                            range(len(rows[0]))) + "|"]
    out += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    out += ["", lk.speed_text(nt).replace("_1", "₁"), nt.word("kinematics.signed")]
    if t.ill_conditioned.any():
        out.append("* " + nt.word("kinematics.ill_note"))
    return "\n".join(out) + "\n"
