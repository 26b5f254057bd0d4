"""The table of permissible coefficients of fluctuation [δ] by machine, as data with its source.

The values are the typical permissible [δ] of the textbooks the project follows (the Russian ТММ
course and the Chinese 机械原理 textbooks, as collected in the project's ``shared/domain.md`` §4).
Each row gives a range [δ]_strict … [δ]_lenient: the stricter end (the smaller δ, the larger
flywheel) is the default a designer takes when nothing else is known.

>>> row = machine_row("press")
>>> row.key, round(1 / row.strict), round(1 / row.lenient)
('press-shears', 10, 7)
>>> permissible_delta("ac-generator") == 1 / 300
True
"""

from __future__ import annotations

from dataclasses import dataclass

from graphmethods.errors import InputError

#: Where the table comes from.
SOURCE = ("typical permissible [δ] of the textbooks graphmethods follows (Russian ТММ course, "
          "Chinese 机械原理 textbooks), as collected in shared/domain.md §4")
#: The two ends of a row.
ENDS = ("strict", "lenient")


@dataclass(frozen=True)
class MachineDelta:
    """One row: a kind of machine and its range of permissible [δ] (dimensionless).

    Attributes
    ----------
    key : str
        ASCII name for the command line (``--machine press-shears``).
    names : tuple of str
        The machine in English, Russian and Chinese.
    lenient_denominator, strict_denominator : int
        The range's ends as 1/N: ``lenient`` the larger δ (1/5 for a stone crusher), ``strict`` the
        smaller (1/20); the properties ``lenient`` and ``strict`` give them as numbers.
    """

    key: str
    names: tuple[str, str, str]
    lenient_denominator: int
    strict_denominator: int

    @property
    def lenient(self) -> float:
        return 1.0 / self.lenient_denominator

    @property
    def strict(self) -> float:
        return 1.0 / self.strict_denominator

    def name(self, lang: str = "en") -> str:
        """The machine's name in ``lang`` (en, ru, zh)."""
        return self.names[{"en": 0, "ru": 1, "zh": 2}.get(lang, 0)]

    def range_text(self) -> str:
        """``'1/5 … 1/20'`` (lenient … strict)."""
        return f"1/{self.lenient_denominator} … 1/{self.strict_denominator}"

    def to_dict(self) -> dict[str, object]:
        return {"key": self.key, "en": self.names[0], "ru": self.names[1], "zh": self.names[2],
                "delta_lenient": self.lenient, "delta_strict": self.strict,
                "range": f"1/{self.lenient_denominator}-1/{self.strict_denominator}"}


TABLE: tuple[MachineDelta, ...] = (
    MachineDelta("stone-crusher", ("stone crusher", "камнедробилка", "碎石机"), 5, 20),
    MachineDelta("press-shears", ("press, shears", "прессы, ножницы", "冲床、剪床"), 7, 10),
    MachineDelta("rolling-mill", ("rolling mill", "прокатный стан", "轧钢机"), 10, 20),
    MachineDelta("car-tractor", ("car, tractor", "автомобили, тракторы", "汽车、拖拉机"), 20, 60),
    MachineDelta("machine-tool", ("metal-cutting machine tool", "металлорежущие станки", "金属切削机床"), 30, 40),
    MachineDelta("pump-fan", ("pump, fan", "насосы, вентиляторы", "水泵、风机"), 30, 50),
    MachineDelta("paper-weaving", ("paper and weaving machines", "бумагоделательные и ткацкие машины",
                                   "造纸机、织布机"), 40, 50),
    MachineDelta("spinning-machine", ("spinning machine", "прядильные машины", "纺纱机"), 60, 100),
    MachineDelta("dc-generator", ("DC generator", "генераторы постоянного тока", "直流发电机"), 100, 200),
    MachineDelta("ac-generator", ("AC generator", "генераторы переменного тока", "交流发电机"), 200, 300),
)


def _words(text: str) -> set[str]:
    norm = text.lower().replace("、", ",").replace(" and ", ",").replace(" и ", ",")
    return {w.strip() for w in norm.split(",") if w.strip()}


def machine_row(name: str) -> MachineDelta:
    """The row for ``name``: its key, its name in any language, or one machine of a row
    (``press``, ``shears``, ``насосы``), case-insensitive.

    >>> machine_row("Rolling mill").key
    'rolling-mill'
    """
    want = str(name).strip().lower()
    for row in TABLE:
        if want == row.key or want.replace(" ", "-") == row.key or any(
                want == n.lower() or want in _words(n) for n in row.names):
            return row
    raise InputError(f"machine {name!r} is not in the table of [δ]; give one of: "
                     + ", ".join(r.key for r in TABLE) + " (graphmethods flywheel --delta-table lists them)")


def permissible_delta(name: str, end: str = "strict") -> float:
    """[δ] for the machine ``name`` from the table: the ``strict`` end (default, the smaller δ) or
    the ``lenient`` one.

    >>> round(1 / permissible_delta("stone crusher", "lenient"))
    5
    """
    if end not in ENDS:
        raise InputError(f"end {end!r}: give 'strict' (the smaller δ, the default) or 'lenient'")
    row = machine_row(name)
    return row.strict if end == "strict" else row.lenient


def delta_range() -> tuple[float, float]:
    """The smallest and the largest [δ] in the table.

    >>> [round(1 / d) for d in delta_range()]
    [300, 5]
    """
    return min(r.strict for r in TABLE), max(r.lenient for r in TABLE)


def table_text(lang: str = "en") -> str:
    """The table as aligned text in ``lang`` with its source.

    >>> table_text().splitlines()[1].split()[:2]
    ['stone-crusher', 'stone']
    """
    head = {"en": ("machine", "[δ]"), "ru": ("машина", "[δ]"), "zh": ("机器", "[δ]")}.get(lang, ("machine", "[δ]"))
    width = max(len(r.key) for r in TABLE)
    nw = max(len(r.name(lang)) for r in TABLE)
    lines = [f"{'key'.ljust(width)}  {head[0].ljust(nw)}  {head[1]}"]
    lines += [f"{r.key.ljust(width)}  {r.name(lang).ljust(nw)}  {r.range_text()}" for r in TABLE]
    lines.append(f"source: {SOURCE}; --machine takes the strict end (the smaller δ) unless --machine-end lenient")
    return "\n".join(lines)
