"""The ``--sheet FILE`` option the commands share: the file checked before any work, the scene's bytes."""

from __future__ import annotations

import pathlib

from graphmethods.errors import InputError, OutputExistsError
from graphmethods.scene import Scene

SUFFIXES = (".svg", ".pdf", ".dxf")


def check_sheet_target(text: str, force: bool) -> pathlib.Path:
    """The path of ``--sheet``, refused (before any work) when it cannot or must not be written."""
    if text.strip() == "":
        raise InputError("--sheet is empty; give a file name ending in .svg, .pdf or .dxf")
    path = pathlib.Path(text)
    if path.suffix.lower() not in SUFFIXES:
        raise InputError(f"--sheet {path}: give a file name ending in .svg, .pdf or .dxf")
    parent = path.parent if str(path.parent) else pathlib.Path(".")
    if not parent.is_dir():
        raise InputError(f"--sheet {path}: directory {parent} does not exist; create it first")
    if path.is_dir():
        raise InputError(f"--sheet {path}: it is a directory; give a file name")
    if path.exists() and not force:
        raise OutputExistsError(f"{path} exists; use --force to overwrite it")
    return path


def scene_bytes(scene: Scene, path: pathlib.Path) -> bytes:
    """The scene as the file ``path`` names it: SVG, PDF or DXF (:func:`graphmethods.render.formats.to_bytes`)."""
    from graphmethods.render import formats

    return formats.to_bytes(scene, path.suffix)
