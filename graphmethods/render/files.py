"""Writing output files safely: atomically, and never over an existing file unless asked.

One file is written to a temporary name beside it and renamed (:func:`write_atomic`); a set of
files (a worksheet, a set of figures, the gallery) is written whole into a temporary folder beside
its target and then renamed into place with interrupts held back (:func:`write_set`), so an error or
an interrupt leaves either the old set or the new one, never a mixture. An operating-system error
(read-only file system, permission, full disk, a folder in the way) becomes one
:class:`~graphmethods.errors.OutputError` naming what, where and why.

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

import contextlib
import os
import pathlib
import secrets
import shutil
import signal
import threading
from collections.abc import Iterable, Iterator, Mapping

from graphmethods.errors import InputError, OutputError, OutputExistsError


def os_reason(exc: OSError) -> str:
    """The reason of an OS error in words (``"read-only file system"``), without the errno noise."""
    import errno

    words = {errno.EROFS: "read-only file system", errno.EACCES: "permission denied", errno.EPERM: "not permitted",
             errno.ENOSPC: "no space left on the device", errno.EDQUOT: "disk quota exceeded",
             errno.EISDIR: "a folder is in the way", errno.ENOTDIR: "a file is in the way of a folder",
             errno.EEXIST: "it exists", errno.ENOENT: "a folder on the way does not exist",
             errno.ENAMETOOLONG: "the name is too long"}
    if exc.errno in words:
        return words[exc.errno]
    return (exc.strerror or str(exc) or type(exc).__name__).lower()


def output_error(what: str, path: str | os.PathLike[str], exc: OSError) -> OutputError:
    """One line for an OS error while writing: what, where, why."""
    return OutputError(f"cannot write {what} {path}: {os_reason(exc)}")


def check_target(path: str | os.PathLike[str], *, overwrite: bool = False, what: str = "file",
                 label: str | None = None, remedy: str = "pass overwrite=True (or --force) to replace it"
                 ) -> pathlib.Path:
    """Refuse, before any work, a file name that cannot or must not be written.

    An empty name, a missing directory, a directory, or an existing file without ``overwrite``.
    ``label`` starts the messages (default ``"cannot write PATH"``; the command line names its
    option: ``"--sheet a.svg"``); ``remedy`` ends the message of an existing file.

    >>> check_target("")
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: the file name is empty; give a file name
    """
    if str(path).strip() == "":
        raise InputError(f"the {what} name is empty; give a {what} name")
    target = pathlib.Path(path)
    lead = label or f"cannot write {target}"
    parent = target.parent if str(target.parent) else pathlib.Path(".")
    if not parent.is_dir():
        raise InputError(f"{lead}: directory {parent} does not exist; create it first")
    if target.is_dir():
        raise InputError(f"{lead}: it is a directory; give a file name")
    if target.exists() and not overwrite:
        raise OutputExistsError(f"{target} exists; {remedy}")
    return target


def not_an_input(output: str | os.PathLike[str], *inputs: str | os.PathLike[str] | None, what: str = "output") -> None:
    """Refuse an output file that is one of the command's inputs (the same path, a link to it, the same file),
    even with ``--force``: a student's drawing is never overwritten by its own check.

    >>> not_an_input("in.svg", "./in.svg", what="--overlay")
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: --overlay in.svg is an input of this command (in.svg); give another file name
    """
    out = pathlib.Path(output)
    for given in inputs:
        if given is None:
            continue
        src = pathlib.Path(given)
        try:
            same = os.path.abspath(out) == os.path.abspath(src) or (out.exists() and src.exists()
                                                                   and os.path.samefile(out, src))
        except OSError:
            same = False
        if same:
            raise InputError(f"{what} {out} is an input of this command ({src}); give another file name")


@contextlib.contextmanager
def interrupts_held() -> Iterator[None]:
    """Hold back SIGINT and SIGTERM for the few renames that commit a set (delivered right after)."""
    can = hasattr(signal, "pthread_sigmask") and threading.current_thread() is threading.main_thread()
    if can:
        old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
    try:
        yield
    finally:
        if can:
            signal.pthread_sigmask(signal.SIG_SETMASK, old)


def write_atomic(path: str | os.PathLike[str], data: bytes, *, overwrite: bool = False) -> pathlib.Path:
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
    path = check_target(path, overwrite=overwrite)
    parent = path.parent if str(path.parent) else pathlib.Path(".")
    tmp = parent / f".{path.name}.{secrets.token_hex(6)}.tmp"
    created = False
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        created = True
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
    except OSError as exc:
        raise output_error("file", path, exc) from None
    finally:
        if created:                          # a failed clean-up never hides the first error
            with contextlib.suppress(OSError):
                os.unlink(tmp)
    return path


def _make_folder(folder: pathlib.Path, what: str) -> list[pathlib.Path]:
    """Create ``folder`` and missing parents; the ones created, outermost first (to remove on an error)."""
    made = []
    p = folder
    while not p.exists() and p != p.parent:
        made.append(p)
        p = p.parent
    if p.exists() and not p.is_dir():
        raise InputError(f"{what} {folder}: {p} is a file, not a folder")
    made.reverse()
    for d in made:
        try:
            d.mkdir()
        except FileExistsError:
            pass
        except OSError as exc:
            _remove_folders(made)
            raise output_error("folder", d, exc) from None
    return made


def _remove_folders(made: Iterable[pathlib.Path]) -> None:
    for d in reversed(list(made)):
        with contextlib.suppress(OSError):
            d.rmdir()                        # only if still empty


def write_set(directory: str | os.PathLike[str], files: Mapping[str, bytes], *, overwrite: bool = False,
              stale: Iterable[str] = (),
              what: str = "folder") -> list[pathlib.Path]:
    """Write a set of files (relative path -> bytes) into ``directory`` as a whole.

    The set is written into a temporary folder on ``directory``'s own file system (inside it when it
    exists, beside it when it is new; its parents are created if missing), then moved into place: one
    rename when ``directory`` is new, else a rename per file with SIGINT/SIGTERM held back and every
    replaced file kept until the last rename succeeds. So an error, a full disk or an interrupt leaves
    either the old set or the new one, and no temporary folder; SIGTERM unwinds as SIGINT does (the
    process then exits with status 143). ``stale`` names old files of the same set that the new one no
    longer has (they go too, so that a forced set equals a fresh one).

    Raises
    ------
    OutputExistsError
        If a file of the set exists and ``overwrite`` is false (nothing is written).
    OutputError
        If the file system refuses (the message names what, where and why; nothing is changed).

    Examples
    --------
    >>> import tempfile
    >>> d = pathlib.Path(tempfile.mkdtemp()) / "new" / "set"
    >>> [p.name for p in write_set(d, {"a.svg": b"1", "svg/b.svg": b"2"})]
    ['a.svg', 'b.svg']
    >>> [p.name for p in write_set(d, {"a.svg": b"3"}, overwrite=True, stale=["svg/b.svg"])], (d / "a.svg").read_bytes()
    (['a.svg'], b'3')
    >>> sorted(p.name for p in d.parent.iterdir()), sorted(p.name for p in d.rglob("*"))
    (['set'], ['a.svg', 'svg'])
    """
    if str(directory).strip() == "":
        raise InputError(f"the {what} name is empty; give a {what} (it is created if missing)")
    out = pathlib.Path(directory)
    if out.exists() and not out.is_dir():
        raise InputError(f"{what} {out} is a file; give a folder")
    for name in files:
        rel = pathlib.PurePath(name)
        if rel.is_absolute() or ".." in rel.parts:
            raise InputError(f"{name}: a file of a set must lie inside its folder")
        if (out / name).is_dir():
            raise InputError(f"cannot write {out / name}: a folder is in the way")
    existing = [name for name in files if (out / name).exists()]
    if existing and not overwrite:
        more = f" and {len(existing) - 3} more" if len(existing) > 3 else ""
        raise OutputExistsError(f"{', '.join(str(out / e) for e in existing[:3])}{more} exist; use --force "
                                f"(overwrite=True) to replace them, or another folder")
    stale = [n for n in stale if n not in files and (out / n).is_file()]
    made = _make_folder(out.parent, what) if not out.parent.exists() else []
    # staged on the target's own file system: inside the folder when it exists (it may be a mount point,
    # whose parent lies on another device), beside it when it is new (it will be made where its parent is)
    token = secrets.token_hex(6)
    staging = out / f".staging.{token}.tmp" if out.is_dir() else out.parent / f".{out.name}.{token}.tmp"
    ok = False
    with _terminate_as_exit():
        try:
            _stage_and_swap(staging, out, files, stale, what)
            ok = True
        finally:
            with interrupts_held():                    # a second signal does not cut the clean-up short
                if staging.exists():
                    shutil.rmtree(staging, ignore_errors=True)
                if not ok:
                    _remove_folders(made)
    return [out / name for name in files]


@contextlib.contextmanager
def _terminate_as_exit() -> Iterator[None]:
    """SIGTERM (a ``kill``, a closed session, a CI timeout) unwinds as SIGINT does while a set is written: the
    staging folder is removed and the process then exits with status 128 + 15, as the signal would."""
    main = threading.current_thread() is threading.main_thread()
    old = None
    if main:
        def on_term(signum: int, frame: object) -> None:
            raise SystemExit(128 + signum)
        try:
            old = signal.signal(signal.SIGTERM, on_term)
        except (ValueError, OSError):          # not settable here (an embedded interpreter)
            main = False
    try:
        yield
    finally:
        if main:
            signal.signal(signal.SIGTERM, old if old is not None else signal.SIG_DFL)


def _stage_and_swap(staging: pathlib.Path, out: pathlib.Path, files: Mapping[str, bytes], stale: list[str],
                    what: str) -> None:
    """Write ``files`` into ``staging``, then move them into ``out`` (one rename when ``out`` is new)."""
    try:
        staging.mkdir()
        for name, data in files.items():
            target = staging / name
            target.parent.mkdir(parents=True, exist_ok=True)
            with open(target, "xb") as fh:
                fh.write(data)
    except OSError as exc:
        raise output_error(what, out, exc) from None
    with interrupts_held():
        if not out.exists():
            try:
                os.rename(staging, out)
            except OSError as exc:
                raise output_error(what, out, exc) from None
        else:
            _swap_in(staging, out, list(files), stale, what)


def _swap_in(staging: pathlib.Path, out: pathlib.Path, names: Iterable[str], stale: Iterable[str],
             what: str) -> None:
    """Rename the staged files over ``out``'s, keeping the old ones in ``staging/.old`` until all are in;
    on any error put everything back as it was."""
    backup = staging / ".old"
    done: list[tuple[pathlib.Path, pathlib.Path | None]] = []      # (target, its backup or None)
    new_dirs: list[pathlib.Path] = []
    try:
        for name in list(names) + list(stale):
            target = out / name
            for d in reversed(target.relative_to(out).parents[:-1]):
                if not (out / d).exists():
                    (out / d).mkdir()
                    new_dirs.append(out / d)
            kept = None
            if target.exists():
                kept = backup / name
                kept.parent.mkdir(parents=True, exist_ok=True)
                os.rename(target, kept)
            done.append((target, kept))
            if name in names:
                os.rename(staging / name, target)
    except BaseException as exc:             # an error, or an interrupt the mask could not hold back
        for target, kept in reversed(done):
            with contextlib.suppress(OSError):
                if kept is not None:
                    os.replace(kept, target)
                elif target.exists():
                    target.unlink()
        _remove_folders(new_dirs)
        if isinstance(exc, OSError):
            raise output_error(what, out, exc) from None
        raise
