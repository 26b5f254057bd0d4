"""The ``--sheet FILE`` option the commands share: the file checked before any work, the scene's bytes."""

from __future__ import annotations

import pathlib
from typing import TYPE_CHECKING

from graphmethods.errors import InputError, OutputExistsError

if TYPE_CHECKING:                      # the numeric commands (flywheel) import this module: no scene at start-up
    from graphmethods.scene import Scene

SUFFIXES = (".svg", ".pdf", ".dxf")


def _endings(suffixes: tuple[str, ...]) -> str:
    """``".svg, .pdf or .dxf"``."""
    return suffixes[0] if len(suffixes) == 1 else f"{', '.join(suffixes[:-1])} or {suffixes[-1]}"


def check_target(text: str, force: bool, *, option: str, suffixes: tuple[str, ...]) -> pathlib.Path:
    """The path an output option (``--sheet``, ``--figure``) names, refused before any work when it
    cannot or must not be written: empty, a suffix not in ``suffixes``, a missing directory, a
    directory, or an existing file without ``--force``."""
    if text.strip() == "":
        raise InputError(f"{option} is empty; give a file name ending in {_endings(suffixes)}")
    path = pathlib.Path(text)
    if path.suffix.lower() not in suffixes:
        raise InputError(f"{option} {path}: give a file name ending in {_endings(suffixes)}")
    parent = path.parent if str(path.parent) else pathlib.Path(".")
    if not parent.is_dir():
        raise InputError(f"{option} {path}: directory {parent} does not exist; create it first")
    if path.is_dir():
        raise InputError(f"{option} {path}: it is a directory; give a file name")
    if path.exists() and not force:
        raise OutputExistsError(f"{path} exists; use --force to overwrite it")
    return path


def check_sheet_target(text: str, force: bool) -> pathlib.Path:
    """The path of ``--sheet``, refused (before any work) when it cannot or must not be written."""
    return check_target(text, force, option="--sheet", suffixes=SUFFIXES)


def scene_bytes(scene: Scene, path: pathlib.Path) -> bytes:
    """The scene as the file ``path`` names it: SVG, PDF or DXF (:func:`graphmethods.render.formats.to_bytes`)."""
    from graphmethods.render import formats

    return formats.to_bytes(scene, path.suffix)


def add_signature_options(p) -> None:
    """``--student``, ``--group``, ``--sheet-no``: the sheet's main inscription (with ``--sheet``)."""
    g = p.add_argument_group("the sheet's main inscription (with --sheet)")
    g.add_argument("--student", default="", metavar="NAME", help="the student's name (Разраб. / 设计)")
    g.add_argument("--group", default="", metavar="GROUP", help="the student's group (or organisation)")
    g.add_argument("--sheet-no", default="", metavar="K[/N]", help="the sheet's number K, or K of N sheets")


def signed(scene: Scene, args) -> Scene:
    """The scene with the student's name, group and sheet number of ``args`` in its main inscription."""
    from graphmethods.sheets.layout import sign_sheet

    k, _, n = str(getattr(args, "sheet_no", "") or "").partition("/")
    return sign_sheet(scene, student=str(getattr(args, "student", "") or "").strip(),
                      group=str(getattr(args, "group", "") or "").strip(), sheet_no=k.strip(), sheets=n.strip())


def check_signature(args) -> None:
    """Refuse the inscription's options without ``--sheet`` (they would be silently lost)."""
    given = [o for o, a in (("--student", "student"), ("--group", "group"), ("--sheet-no", "sheet_no"))
             if str(getattr(args, a, "") or "").strip()]
    if given and getattr(args, "sheet", None) is None:
        raise InputError(f"{', '.join(given)}: for the sheet's main inscription; add --sheet FILE")
