"""The gallery's catalogue: one table of the built-in figures, one row per figure.

A row is (name, problem, figure, language, options): the problem it draws (a key of
:func:`problem`), the figure function that draws it (``module.function`` under
:mod:`graphmethods.sheets`), the language of its notation, the function's other options, and a
sentence saying what it shows (``png``: the README shows its PNG as well). The rows are data: one
JSON object per line in ``catalogue.json`` beside this module (``options``, ``png`` left out when
empty or false). Adding a figure is adding a line there; ``graphmethods gallery --regenerate`` then
writes its golden SVG.

Nothing heavy is imported until a figure is built.

>>> f = figure("press_velocity_plan_ru")
>>> f.problem, f.figure, f.language
('case:press', 'kinematics.velocity_plan', 'ru')
>>> len({f.name for f in CATALOGUE}) == len(CATALOGUE)
True
"""

from __future__ import annotations

import importlib
import json
import pathlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from graphmethods.errors import InputError


@dataclass(frozen=True)
class Figure:
    """One built-in figure: ``figure(problem, notation=language, **options)``.

    Parameters
    ----------
    name : str
        The figure's name (its golden file is ``gallery/<name>.svg``).
    problem : str
        ``kind:key`` of the problem it draws, see :func:`problem`.
    figure : str
        ``module.function`` under :mod:`graphmethods.sheets`.
    language : {"en", "ru", "zh"}
        The notation.
    options : mapping
        The figure function's other keyword arguments.
    about : str
        What the figure shows, one or two sentences.
    png : bool
        The README shows its PNG too (``--regenerate`` rewrites it).
    """

    name: str
    problem: str
    figure: str
    language: str
    options: Mapping[str, Any] = field(default_factory=dict)
    about: str = ""
    png: bool = False

    @property
    def PNG(self) -> bool:      # the attribute name a gallery script of --dir uses
        return self.png

    def build(self) -> Any:
        """The figure's Scene."""
        module, function = self.figure.rsplit(".", 1)
        draw: Callable[..., Any] = getattr(importlib.import_module(f"graphmethods.sheets.{module}"), function)
        source = problem(self.problem)
        args, kwargs = (source.args, source.kwargs) if isinstance(source, Call) else ((source,), {})
        return draw(*args, **kwargs, notation=self.language, **self.options)


@dataclass(frozen=True)
class Call:
    """A problem that a figure function takes as several arguments."""

    args: tuple[Any, ...]
    kwargs: Mapping[str, Any] = field(default_factory=dict)


def _three_mass_drive() -> Any:
    from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain

    return reduce_chain([Mass("motor", 0.08, 6.0, 30.0), Mass("gear", 0.5, 2.0), Mass("crank", 12.0, 1.0, -160.0)],
                        [Shaft("motor shaft", 2.0e3, 6.0), Shaft("output shaft", 4.0e4, 1.0)])


def _w1_flywheels() -> Call:
    """W1's J_F = 43.69 kg·m² at 600 rev/min as a rim and as a disc of mean diameter 750 mm."""
    from graphmethods.dynamics.flywheel import disc_flywheel, rim_flywheel

    J_F = 900 * 575 / (3.141592653589793**2 * 600**2 / 300)
    return Call((rim_flywheel(J_F, n_rpm=600.0, D=0.75), disc_flywheel(J_F, D=0.75, n_rpm=600.0)))


def _w1_hyperbola() -> Call:
    from graphmethods import problems
    from graphmethods.dynamics.flywheel import mean_speed

    w1 = problems.w1()
    return Call((w1.excess_work.delta_W_max,), dict(omega_m=mean_speed(n_rpm=w1.n_rpm), J_e=w1.J_e,
                                                     machine="ac-generator",
                                                     problem=f"{w1.id}, n = {w1.n_rpm:g} rev/min"))


_OTHERS: Mapping[str, Callable[[], Any]] = MappingProxyType({
    "drive:three-mass-drive": _three_mass_drive, "flywheels:w1": _w1_flywheels, "hyperbola:w1": _w1_hyperbola,
})


#: the problems read in this process, by key: the figures of one problem share it, and with it what its
#: study has computed (positions, plans, the exact flywheel: cached properties), the way a teacher's
#: session draws one problem's figures in turn. A problem and its results are never changed by a figure.
_READ: dict[str, Any] = {}


def problem(key: str) -> Any:
    """The problem a row draws, by ``kind:key``, read once per process (shared by the rows that draw it;
    see :func:`problem_afresh`).

    >>> problem("study:press") is problem("study:press")
    True
    """
    if key not in _READ:
        _READ[key] = problem_afresh(key)
    return _READ[key]


def problem_afresh(key: str) -> Any:
    """The problem a row draws, by ``kind:key``, read anew.

    ``case:NAME`` a built-in linkage (:func:`graphmethods.problems.builtin.case`); ``study:NAME`` its
    :class:`~graphmethods.dynamics.study.Study` at 12 positions; ``cycle:w1`` … ``cycle:w4-exact`` a
    worked example; ``cam:NAME`` a built-in cam problem; ``variant:KIND`` worksheet variant 1 of seed 7; and the
    few of their own
    (``drive:three-mass-drive``, ``flywheels:w1``, ``hyperbola:w1``).
    """
    kind, _, name = key.partition(":")
    if kind in ("case", "study"):
        from graphmethods.problems import builtin

        case = builtin.case(name)
        if kind == "case":
            return case
        from graphmethods.dynamics.study import Study

        return Study(case, positions=12)
    if kind == "cycle":
        from graphmethods import problems

        return getattr(problems, name.replace("-", "_"))()
    if kind == "cam":
        from graphmethods.problems import builtin

        return builtin.cam_problem(name)
    if kind == "variant":
        from graphmethods.sheets import worksheets

        return worksheets.variant(name, seed=7, number=1)
    if key in _OTHERS:
        return _OTHERS[key]()
    raise InputError(f"no gallery problem {key!r}")


def _row(entry: Mapping[str, Any]) -> Figure:
    """A row of ``catalogue.json`` as a :class:`Figure` (its options read-only)."""
    options = MappingProxyType(dict(entry.get("options", {})))
    return Figure(entry["name"], entry["problem"], entry["figure"], entry["language"], options,
                  entry.get("about", ""), bool(entry.get("png", False)))


def _read_catalogue() -> tuple[Figure, ...]:
    """The rows of ``catalogue.json`` (beside this module; one JSON object per line), in order."""
    text = (pathlib.Path(__file__).with_name("catalogue.json")).read_text(encoding="utf-8")
    return tuple(_row(entry) for entry in json.loads(text))


CATALOGUE: tuple[Figure, ...] = _read_catalogue()

_BY_NAME: Mapping[str, Figure] = MappingProxyType({f.name: f for f in CATALOGUE})


def figure(name: str) -> Figure:
    """The row of one built-in figure, by name (``"press_wittenbauer_en"``)."""
    try:
        return _BY_NAME[name]
    except KeyError:
        raise InputError(f"no built-in figure {name!r}") from None
