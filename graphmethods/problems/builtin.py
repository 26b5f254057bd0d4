"""The built-in problems by name: what ``graphmethods problems`` lists, and what every command that
takes a problem file also takes (``graphmethods study press``, ``graphmethods kinematics shaper``).

Two kinds: *cycle* problems, given as a cycle of works, areas or moments (the worked examples
W1–W4: ``graphmethods examples``, ``graphmethods check``), and *linkage* problems, given as a
problem file that ships with the package (``graphmethods kinematics``, ``graphmethods study``).

>>> [p.name for p in listing() if p.kind != "cycle"][:4]
['press', 'shaper', 'four-bar', 'slotted-lever']
>>> case("shaper").kind
'shaper'
"""

from __future__ import annotations

import os
import pathlib
from dataclasses import dataclass
from typing import TYPE_CHECKING

from graphmethods.errors import InputError

if TYPE_CHECKING:
    from graphmethods.kinematics.cam.problem import CamProblem
    from graphmethods.kinematics.case import Case

DATA = pathlib.Path(__file__).parent / "data"

#: linkage problems: name -> problem file in ``graphmethods/problems/data``
LINKAGES = {
    "press": "slider_crank_press.json",
    "shaper": "shaper.json",
    "four-bar": "four_bar_rocker.json",
    "slotted-lever": "slotted_lever.json",
    "six-bar-press": "six_bar_press.json",
    "slotting-machine": "slotting_machine.json",
    "whitworth": "whitworth_quick_return.json",
    "two-slider": "two_slider_compressor.json",
    "engine": "single_cylinder_engine.json",
    "scotch-yoke": "scotch_yoke_pump.json",
    "triad-six-bar": "triad_six_bar.json",
}

#: worked files of the drawn form (README): name -> file in ``graphmethods/problems/data/drawn``; every
#: linkage above is also there in the drawn form, as ``drawn/NAME`` (``graphmethods kinematics drawn/shaper``)
DRAWN = {
    "drawn-four-bar": "example_four_bar.json",
    "drawn-slotted-lever": "example_slotted_lever.json",
    "drawn-six-bar-triad": "example_six_bar_triad.json",
}

#: cam problems: name -> ``"kind": "cam"`` problem file in ``graphmethods/problems/data`` (``graphmethods cam NAME``)
CAMS = {
    "shaper-cam": "shaper_feed_cam.json",
    "oscillating-cam": "oscillating_roller_cam.json",
}

#: cycle problems: name -> function of :mod:`graphmethods.problems` that builds it
CYCLES = {"W1": "w1", "W2": "w2", "W3": "w3", "W4": "w4_drawing", "W4-exact": "w4_exact"}


@dataclass(frozen=True)
class BuiltinProblem:
    """One line of ``graphmethods problems``: the name to type, its kind and its English title."""

    name: str
    kind: str
    title: str

    def line(self) -> str:
        """``name  kind  title``, the columns padded for a listing."""
        return f"{self.name:<18}{self.kind:<15}{self.title}"


def names() -> list[str]:
    """Every built-in problem's name, cycle problems first."""
    return [*CYCLES, *LINKAGES, *CAMS]


def _key(name: str) -> str:
    return str(name).strip().lower().replace("_", "-")


def listing() -> list[BuiltinProblem]:
    """The built-in problems with their kind (``cycle``, or the linkage's kind) and English title."""
    import graphmethods.problems as problems
    from graphmethods.kinematics import read_case
    from graphmethods.problems.reference_cases import title_of

    out = []
    for name, func in CYCLES.items():
        p = getattr(problems, func)()
        out.append(BuiltinProblem(name, "cycle", title_of(p).title_in("en")))
    for name, file in LINKAGES.items():
        c = read_case(DATA / file)
        out.append(BuiltinProblem(name, c.kind, title_of(c).title_in("en")))
    for name in CAMS:
        cp = cam_problem(name)
        out.append(BuiltinProblem(name, cp.kind, cp.title.title_in("en")))
    return out


def case_path(spec) -> pathlib.Path:
    """The problem file a command reads: ``spec`` itself when it is a file, else the file of the
    built-in linkage problem of that name.

    Raises
    ------
    InputError
        When ``spec`` is neither a file nor a built-in linkage problem (the message names them).
    """
    p = pathlib.Path(str(spec))
    if p.is_file():
        return p
    key = _key(spec)
    for name, file in LINKAGES.items():
        if key == name:
            return DATA / file
        if key == f"drawn/{name}" and (DATA / "drawn" / file).is_file():
            return DATA / "drawn" / file
    if key in DRAWN:
        return DATA / "drawn" / DRAWN[key]
    if key in CAMS:
        raise InputError(f"{spec} is a cam problem: see `graphmethods cam {spec}`")
    if key in {_key(c) for c in CYCLES}:
        raise InputError(f"{spec} is a cycle problem (works, areas or moments), not a linkage: see "
                         f"`graphmethods examples` and `graphmethods check {spec} ANSWERS.toml`; linkage problems: "
                         f"{', '.join(LINKAGES)}")
    if p.exists():
        raise InputError(f"{spec}: a folder, not a problem file")
    raise InputError(f"{spec}: no such problem file, and not a built-in problem (linkages: {', '.join(LINKAGES)}, "
                     f"each also as drawn/NAME; {', '.join(DRAWN)}; see `graphmethods problems`)")


#: the name that stands for standard input wherever a problem file is read
STDIN = "-"


def read_stdin_case():
    """The linkage problem file given on standard input (``graphmethods study - < press.json``)."""
    import sys

    from graphmethods.kinematics.case import case_from_dict
    from graphmethods.units import json_value

    try:
        text = sys.stdin.read()
    except UnicodeDecodeError as exc:
        raise InputError(f"standard input: not UTF-8 text ({exc.reason})") from None
    if not text.strip():
        raise InputError("standard input is empty: give a problem file there (graphmethods problems press --file "
                         "> press.json, edited) or name a file")
    return case_from_dict(json_value(text, "standard input"), source="standard input")


def example_files() -> dict[str, pathlib.Path]:
    """The example students' files that ship with the package (answers files, drawings made in CAD), by
    file name: what ``graphmethods check`` reads in the README's examples.

    >>> "w1_mistakes.toml" in example_files()
    True
    """
    found = sorted([*(DATA / "answers").glob("*.toml"), *(DATA / "drawings").glob("*.dxf"),
                    *(DATA / "drawings").glob("*.svg")], key=lambda p: p.name)
    return {p.name: p for p in found}


def file_text(name: str) -> str:
    """The problem file of a built-in linkage or cam, or an example student's file (by its file name), as it
    ships: to redirect, edit and give back.

    >>> import json
    >>> json.loads(file_text("press"))["r"]
    0.1
    >>> file_text("w1_mistakes.toml").startswith("#")
    True
    """
    return read_text_file(file_path(name))


def file_path(name: str) -> pathlib.Path:
    """Where the file :func:`file_text` prints lies in the installed package."""
    examples = example_files()
    if str(name) in examples:
        return examples[str(name)]
    if _key(name) in CAMS:
        return DATA / CAMS[_key(name)]
    return case_path(name)


def read_text_file(path: pathlib.Path) -> str:
    from graphmethods.units import read_text

    return read_text(path)


def case(spec: str | os.PathLike[str]) -> Case:
    """The linkage problem of a file, a built-in name or ``-`` (standard input), read and validated
    (:func:`graphmethods.kinematics.read_case`)."""
    from graphmethods.kinematics import read_case

    if str(spec) == STDIN:
        return read_stdin_case()
    return read_case(case_path(spec))


def cam_problem(spec: str | os.PathLike[str]) -> CamProblem:
    """The cam problem of a ``"kind": "cam"`` file or a built-in cam name, read and checked
    (:func:`graphmethods.kinematics.cam.read_cam`); an :class:`~graphmethods.errors.InputError` naming the
    built-in cam problems when ``spec`` is neither.

    >>> cam_problem("shaper-cam").contact
    'roller'
    """
    from graphmethods.kinematics.cam import read_cam

    p = pathlib.Path(str(spec))
    if p.is_file():
        return read_cam(p)
    key = _key(str(spec))
    if key in CAMS:
        return read_cam(DATA / CAMS[key])
    if p.exists():
        raise InputError(f"{spec}: a folder, not a problem file")
    raise InputError(f"{spec}: no such problem file, and not a built-in cam problem ({', '.join(CAMS)}; "
                     f"see `graphmethods problems`)")
