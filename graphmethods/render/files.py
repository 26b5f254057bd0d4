"""Writing output files safely: atomically, and never over an existing file unless asked.

>>> import tempfile, pathlib
>>> d = pathlib.Path(tempfile.mkdtemp())
>>> write_atomic(d / "a.svg", b"<svg/>").name
'a.svg'
>>> try:
...     write_atomic(d / "a.svg", b"<svg/>")
... except OutputExistsError as exc:
...     print(type(exc).__name__)
OutputExistsError
>>> sorted(p.name for p in d.iterdir())          # no temporary file left behind
['a.svg']
"""

from __future__ import annotations

import os
import pathlib
import secrets

from graphmethods.errors import InputError, OutputExistsError


def write_atomic(path, data: bytes, *, overwrite: bool = False) -> pathlib.Path:
    """Write ``data`` to ``path`` through a temporary file and a rename.

    Readers never see a partial file, an error leaves no file behind, and an
    existing file is kept unless ``overwrite=True``.

    Raises
    ------
    OutputExistsError
        If ``path`` exists and ``overwrite`` is false.
    InputError
        If the directory does not exist.
    """
    path = pathlib.Path(path)
    parent = path.parent if str(path.parent) else pathlib.Path(".")
    if not parent.is_dir():
        raise InputError(f"cannot write {path}: directory {parent} does not exist; create it first")
    if path.is_dir():
        raise InputError(f"cannot write {path}: it is a directory; give a file name")
    if path.exists() and not overwrite:
        raise OutputExistsError(f"{path} exists; pass overwrite=True (or --force) to replace it")
    tmp = parent / f".{path.name}.{secrets.token_hex(6)}.tmp"
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        if overwrite:
            os.replace(tmp, path)
        else:
            try:
                os.link(tmp, path)          # atomic, and fails if the file appeared meanwhile
            except FileExistsError:
                raise OutputExistsError(f"{path} exists; pass overwrite=True (or --force) to replace it") from None
            except OSError:                 # no hard links on this file system
                if path.exists():
                    raise OutputExistsError(f"{path} exists; pass overwrite=True (or --force) to replace it") from None
                os.replace(tmp, path)
    finally:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
    return path
