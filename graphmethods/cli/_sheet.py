"""The one-file outputs the commands share (``--sheet``, ``-o/--out``, ``--figure``): the target checked
before any work, ``-`` for standard output, the scene's bytes, the write.

A target is a file name whose suffix names the format, or ``-``: standard output, in the format
``--format`` names; the command then prints nothing else on standard output (its report goes to
standard error), so ``graphmethods kinematics press --sheet - --format svg > sheet.svg`` gives the
drawing alone.
"""

from __future__ import annotations

import pathlib
import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING, TextIO

from graphmethods.errors import InputError, OutputExistsError

if TYPE_CHECKING:                      # the numeric commands (flywheel) import this module: no scene at start-up
    from graphmethods.scene import Scene

#: every format the renderers write (graphmethods.render.formats)
SUFFIXES = (".svg", ".pdf", ".png", ".dxf")
#: the name of standard output wherever one file is written
STDOUT = "-"


@dataclass(frozen=True)
class Target:
    """Where one output goes: ``path`` (None for standard output) and its format's ``suffix`` (``".svg"``)."""

    path: pathlib.Path | None
    suffix: str

    @property
    def to_stdout(self) -> bool:
        return self.path is None

    def __str__(self) -> str:
        return "standard output" if self.path is None else str(self.path)

    def write(self, data: bytes, *, overwrite: bool) -> None:
        """Write ``data``: to standard output as is, or to the file atomically (never over a file
        without ``overwrite``)."""
        if self.path is None:
            sys.stdout.flush()
            sys.stdout.buffer.write(data)
            sys.stdout.buffer.flush()
            return
        from graphmethods.render.files import write_atomic

        write_atomic(self.path, data, overwrite=overwrite)


def _endings(suffixes: tuple[str, ...]) -> str:
    """``".svg, .pdf or .dxf"``."""
    return suffixes[0] if len(suffixes) == 1 else f"{', '.join(suffixes[:-1])} or {suffixes[-1]}"


def check_target(text: str, force: bool, *, option: str, suffixes: tuple[str, ...] = SUFFIXES,
                 fmt: str | None = None) -> Target:
    """The target an output option names, refused before any work when it cannot or must not be written:
    empty, a suffix not in ``suffixes``, a missing directory, a directory, or an existing file without
    ``--force``. ``-`` is standard output in the format ``fmt`` (``--format``, required then); a file's
    suffix must agree with ``fmt`` when both are given."""
    if text.strip() == "":
        raise InputError(f"{option} is empty; give a file name ending in {_endings(suffixes)}, or - for standard "
                         f"output with --format")
    if text == STDOUT:
        if fmt is None:
            raise InputError(f"{option} - writes to standard output: say the format with --format "
                             f"{'|'.join(s[1:] for s in suffixes)}")
        suffix = "." + fmt.lower().lstrip(".")
        if suffix not in suffixes:
            raise InputError(f"{option} -: --format {fmt} is not one of {', '.join(s[1:] for s in suffixes)}")
        return Target(None, suffix)
    path = pathlib.Path(text)
    if path.suffix.lower() not in suffixes:
        raise InputError(f"{option} {path}: give a file name ending in {_endings(suffixes)}")
    if fmt is not None and "." + fmt.lower() != path.suffix.lower():
        raise InputError(f"{option} {path}: the name ends in {path.suffix}, --format says {fmt}; give one of them")
    from graphmethods.render.files import check_target as check_file

    check_file(path, overwrite=force, label=f"{option} {path}", remedy="use --force to overwrite it")
    return Target(path, path.suffix.lower())


def check_sheet_target(text: str, force: bool, fmt: str | None = None) -> Target:
    """The target of ``--sheet``, refused (before any work) when it cannot or must not be written."""
    return check_target(text, force, option="--sheet", fmt=fmt)


def report_stream(*targets: Target | None) -> TextIO:
    """Where a command prints its report: standard error when a drawing goes to standard output."""
    return sys.stderr if any(t is not None and t.to_stdout for t in targets) else sys.stdout


def refuse_two_on_stdout(json: bool, *targets: Target | None) -> None:
    """At most one thing on standard output: ``--json`` and ``-``, or two ``-``, are refused."""
    on = sum(1 for t in targets if t is not None and t.to_stdout)
    if on > 1 or (on and json):
        raise InputError("only one output can go to standard output (-): write the others to files"
                         + (", or leave out --json" if json else ""))


def scene_bytes(scene: Scene, target: Target | pathlib.Path) -> bytes:
    """The scene in the target's format: SVG, PDF, PNG or DXF (:func:`graphmethods.render.formats.to_bytes`)."""
    from graphmethods.render import formats

    return formats.to_bytes(scene, target.suffix)


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


def write_scene_set(scenes: dict, directory, *, stem: str, fmt: str, overwrite: bool) -> list:
    """Write figures (key -> Scene, or key -> text) into ``directory`` as ``<stem>_<key>.<fmt>`` (text as
    ``<stem>_<key>``), all or none: refused when a file exists (without ``overwrite``), written into a
    temporary folder beside it and renamed into place (:func:`graphmethods.render.files.write_set`).

    Raises
    ------
    InputError
        ``directory`` is a file.
    OutputExistsError
        A file exists and ``overwrite`` is false (the message lists them).
    """
    from graphmethods.render.files import write_set

    out = pathlib.Path(directory)
    if out.exists() and not out.is_dir():
        raise InputError(f"--figures {out}: it is a file, not a directory")
    blobs = {}
    for key, obj in scenes.items():
        if isinstance(obj, str):
            blobs[out / f"{stem}_{key}"] = obj.encode("utf-8")
        else:
            from graphmethods.render import formats

            blobs[out / f"{stem}_{key}.{fmt}"] = formats.to_bytes(obj, f".{fmt}")
    if not overwrite:
        existing = [str(p) for p in blobs if p.exists()]
        if existing:
            more = f" and {len(existing) - 2} more" if len(existing) > 2 else ""
            raise OutputExistsError(f"{', '.join(existing[:2])}{more} exist; use --force to overwrite, or another "
                                    f"--figures folder")
    # the set is written into a temporary folder beside DIR and renamed into place as a whole
    write_set(out, {p.name: data for p, data in blobs.items()}, overwrite=overwrite, what="--figures folder")
    return list(blobs)
