"""One render entry per file format, keyed by the file's suffix.

Every format answers the same two calls: :func:`to_bytes` ``(scenes, suffix)`` and :func:`save`
``(scenes, path, overwrite=)``, where ``scenes`` is one :class:`~graphmethods.scene.scene.Scene` or
several. SVG and PNG hold one figure; PDF (one page a scene) and DXF (the figures left to right)
hold several. Each backend is imported only when its format is used (``import graphmethods``
loads neither matplotlib nor ezdxf).

>>> from graphmethods.scene import Scene, Page, Text
>>> scene = Scene(Page("A4"), (Text((10, 10), "M_d"),))
>>> to_bytes(scene, ".svg")[:5], to_bytes([scene, scene], ".pdf")[:5]
(b'<?xml', b'%PDF-')
>>> sorted(FORMATS)
['.dxf', '.pdf', '.png', '.svg']
>>> format_for("sheet.PDF").name
'PDF'
>>> format_for("sheet.eps")
Traceback (most recent call last):
...
graphmethods.errors.InputError: sheet.eps: give a file name ending in .svg, .pdf, .png or .dxf
"""

from __future__ import annotations

import os
import pathlib
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass

from graphmethods.errors import InputError
from graphmethods.render.files import write_atomic
from graphmethods.scene.scene import Scene

Progress = Callable[[int, int, str], None]


@dataclass(frozen=True)
class Options:
    """What a format may be asked besides the scenes.

    Parameters
    ----------
    dpi : float or None
        PNG only: pixels per inch (``None``: the PNG backend's default, 200).
    progress : callable or None
        ``progress(done, total, "PDF pages")``, called as each page of a several-figure file is written.
    """

    dpi: float | None = None
    progress: Progress | None = None


class _Reporting(list[Scene]):
    """The scenes, reporting each one as the writer walks them (the writers walk their pages once)."""

    def __init__(self, items: Sequence[Scene], progress: Progress, what: str) -> None:
        super().__init__(items)
        self._progress, self._what = progress, what

    def __iter__(self) -> Iterator[Scene]:
        for k, item in enumerate(super().__iter__(), 1):
            yield item
            self._progress(k, len(self), self._what)


def _svg(scenes: Sequence[Scene], options: Options) -> bytes:
    from graphmethods.render import svg

    return svg.to_bytes(scenes[0])


def _pdf(scenes: Sequence[Scene], options: Options) -> bytes:
    from graphmethods.render import pdf

    return pdf.to_bytes(scenes if options.progress is None else _Reporting(scenes, options.progress, "PDF pages"))


def _png(scenes: Sequence[Scene], options: Options) -> bytes:
    from graphmethods.render import mpl

    return mpl.to_png_bytes(scenes[0]) if options.dpi is None else mpl.to_png_bytes(scenes[0], dpi=options.dpi)


def _dxf(scenes: Sequence[Scene], options: Options) -> bytes:
    from graphmethods.render import dxf

    return dxf.to_bytes(scenes)


@dataclass(frozen=True)
class Format:
    """A file format: its suffix, its name, whether one file holds several figures, and its writer.

    Parameters
    ----------
    suffix : str
        The file name's ending, lower case with the dot (``".svg"``).
    name : str
        The format's name in messages (``"SVG"``).
    several : bool
        Whether one file holds several scenes (PDF pages, DXF figures side by side).
    write : callable
        The scenes (one or more, in order) and the :class:`Options` -> the file's bytes.
    """

    suffix: str
    name: str
    several: bool
    write: Callable[[Sequence[Scene], Options], bytes]

    def to_bytes(self, scenes: Scene | Iterable[Scene], options: Options = Options()) -> bytes:
        """The file's bytes for one scene or several; the same scenes give the same bytes (PNG: the same
        pixels with one matplotlib).

        Raises
        ------
        InputError
            No scene, something that is not a scene, or several scenes for a one-figure format.
        """
        many = [scenes] if isinstance(scenes, Scene) else list(scenes)
        if not many:
            raise InputError(f"{self.name}: no scenes were given; give at least one figure")
        for i, s in enumerate(many):
            if not isinstance(s, Scene):
                raise InputError(f"{self.name}: item {i + 1} is {type(s).__name__}, not a figure (Scene)")
        if len(many) > 1 and not self.several:
            raise InputError(f"{self.name} holds one figure, got {len(many)}: write them to PDF or DXF, "
                             f"or one {self.suffix} file each")
        return self.write(many, options)


#: The formats by suffix.
FORMATS: dict[str, Format] = {
    ".svg": Format(".svg", "SVG", False, _svg),
    ".pdf": Format(".pdf", "PDF", True, _pdf),
    ".png": Format(".png", "PNG", False, _png),
    ".dxf": Format(".dxf", "DXF", True, _dxf),
}


def format_for(path: str | os.PathLike[str], *, among: Iterable[str] = tuple(FORMATS)) -> Format:
    """The format a file name (or a bare suffix such as ``".pdf"``) asks for, case-insensitive.

    Parameters
    ----------
    path : str or path-like
        A file name, or a suffix with its dot.
    among : iterable of str, optional
        The suffixes allowed here (default: every format).

    Raises
    ------
    InputError
        For a suffix not among them, naming the ones that are.
    """
    text = os.fspath(path)
    suffix = text.lower() if text.startswith(".") and "/" not in text else pathlib.Path(text).suffix.lower()
    allowed = tuple(among)
    if suffix not in allowed or suffix not in FORMATS:
        names = ", ".join(allowed[:-1]) + (" or " if len(allowed) > 1 else "") + allowed[-1]
        raise InputError(f"{text}: give a file name ending in {names}")
    return FORMATS[suffix]


def to_bytes(scenes: Scene | Iterable[Scene], suffix: str, *, dpi: float | None = None,
             progress: Progress | None = None) -> bytes:
    """The bytes of a ``suffix`` file (``".svg"``, ``".pdf"``, ``".png"``, ``".dxf"``) of one scene or several.

    ``dpi`` sets a PNG's resolution (``None``: 200 dpi); ``progress(done, total, what)`` hears of each
    page of a PDF as it is written (see :class:`Options`).
    """
    return format_for(suffix).to_bytes(scenes, Options(dpi=dpi, progress=progress))


def save(scenes: Scene | Iterable[Scene], path: str | os.PathLike[str], *, overwrite: bool = False) -> pathlib.Path:
    """Write one scene or several in the format the file name's suffix names, atomically.

    Raises
    ------
    InputError
        An unknown suffix, or several scenes for SVG or PNG (nothing is written).
    OutputExistsError
        If ``path`` exists and ``overwrite`` is false.

    Returns
    -------
    pathlib.Path
        The path written.
    """
    return write_atomic(path, format_for(path).to_bytes(scenes), overwrite=overwrite)
