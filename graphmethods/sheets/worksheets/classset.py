"""A class set: the variants 1...N of a kind with their pages, and the files it is written as (names and
contents; :func:`graphmethods.cli.worksheet.write_worksheet` writes them).
"""

from __future__ import annotations

import pathlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from graphmethods.render import formats
from graphmethods.scene import Scene, notation as get_notation
from graphmethods.sheets.worksheets import answers
from graphmethods.sheets.worksheets.pages import PAGES, key_page, student_page
from graphmethods.sheets.worksheets.texts import STATEMENTS, TITLES
from graphmethods.sheets.worksheets.variants import CLASSES, GENERATORS, Variant, check_kind, variants as make_variants
from graphmethods.titles import Title

# ----------------------------------------------------------------------------- a class set and its files

@dataclass(frozen=True, eq=False)
class Worksheet:
    """The pages of a class set: ``students`` (one per variant), then ``keys`` (same order)."""

    kind: str
    seed: int
    notation: str
    variants: tuple
    students: tuple
    keys: tuple

    @property
    def scenes(self) -> tuple:
        """Every page in print order: the students' pages, then the keys."""
        return self.students + self.keys


def worksheet(kind: str, *, variants: int, seed: int, notation="en", progress=None) -> Worksheet:
    """Variants 1…N of ``kind`` with their student pages and answer keys.

    ``progress(done, total, what)`` is called after each variant (for long batches).
    """
    nt = get_notation(notation)
    vs = make_variants(kind, count=variants, seed=seed)
    students, keys = [], []
    for k, v in enumerate(vs, 1):
        students.append(student_page(v, notation=nt))
        keys.append(key_page(v, notation=nt))
        if progress is not None:
            progress(k, len(vs), "pages")
    return Worksheet(kind, int(seed), nt.code, vs, tuple(students), tuple(keys))


def output_names(kind: str, notation, count: int) -> list[str]:
    """The files a worksheet of ``count`` variants writes (relative paths), in writing order.

    >>> output_names("indicator", "ru", 2)[:3]
    ['indicator-ru.pdf', 'svg/indicator-01-student.svg', 'svg/indicator-01-key.svg']
    """
    width = max(2, len(str(count)))
    out = [f"{check_kind(kind)}-{get_notation(notation).code}.pdf"]
    for k in range(1, count + 1):
        out += [f"svg/{kind}-{k:0{width}d}-student.svg", f"svg/{kind}-{k:0{width}d}-key.svg",
                f"problems/{kind}-{k:0{width}d}.json"]
    return out + [f"{kind}-answers.toml"]


def existing_outputs(out_dir, kind: str, notation, count: int) -> list[pathlib.Path]:
    """The files of such a worksheet that already exist in ``out_dir`` (check before building)."""
    out = pathlib.Path(out_dir)
    return [out / n for n in output_names(kind, notation, count) if (out / n).exists()]


def file_names(ws: Worksheet) -> dict[str, object]:
    """The files of a worksheet, relative path -> list of scenes (the PDF), scene (an SVG) or variant (a
    problem file)."""
    names = iter(output_names(ws.kind, ws.notation, len(ws.variants)))
    out: dict[str, object] = {next(names): list(ws.scenes)}
    for v, s, k in zip(ws.variants, ws.students, ws.keys):
        out[next(names)] = s
        out[next(names)] = k
        out[next(names)] = v
    page = ws.students[0].page
    lang = ws.notation if isinstance(ws.notation, str) else getattr(ws.notation, "code", "en")
    out[next(names)] = answers.template(ws.kind, page=(page.size, page.orientation), seed=ws.seed, lang=lang)
    return out


def dxf_names(kind: str, n: int) -> list[str]:
    """The DXF pages of a class set of ``n`` variants, relative to its folder (student, key, ...)."""
    return [f"dxf/{kind}-{i:02d}-{part}.dxf" for i in range(1, n + 1) for part in ("student", "key")]


def contents(ws: Worksheet, *, progress: Callable[[int, int, str], None] | None = None,
             dxf: bool = False) -> dict[str, bytes]:
    """The files of a class set, relative path -> bytes, in writing order (:func:`output_names`): one PDF
    (students' pages, then keys), an SVG per page in ``svg/``, a problem file per variant in ``problems/``
    (``graphmethods check`` reads them), the blank answers file ``KIND-answers.toml``
    (:func:`graphmethods.sheets.worksheets.answers.template`), and with ``dxf`` every page as DXF in
    ``dxf/`` (1 unit = 1 mm, for students who draw in CAD).

    ``progress(done, total, what)`` hears of each PDF page as it is written.

    >>> from graphmethods.sheets.worksheets import variant
    >>> files = contents(worksheet("wittenbauer", variants=1, seed=3))
    >>> problem = variant("wittenbauer", seed=3, number=1).to_json().encode()
    >>> list(files)[:2], files["problems/wittenbauer-01.json"] == problem
    (['wittenbauer-en.pdf', 'svg/wittenbauer-01-student.svg'], True)
    """
    blobs: dict[str, bytes] = {}
    for name, obj in file_names(ws).items():
        if isinstance(obj, list):
            blobs[name] = formats.to_bytes(obj, ".pdf", progress=progress)
        elif isinstance(obj, Scene):
            blobs[name] = formats.to_bytes(obj, ".svg")
        elif isinstance(obj, str):          # the blank answers file
            blobs[name] = obj.encode("utf-8")
        else:
            assert isinstance(obj, Variant)     # the problem files
            blobs[name] = obj.to_json().encode("utf-8")
    if dxf:
        pages = [s for pair in zip(ws.students, ws.keys) for s in pair]
        names = dxf_names(ws.kind, len(ws.variants))
        blobs.update((name, formats.to_bytes(s, ".dxf")) for name, s in zip(names, pages))
    return blobs


def stale_names(kind: str) -> tuple[tuple[str, str], ...]:
    """The folders and glob patterns of a class set's per-variant files (an old set's files that a new,
    smaller set replacing it must remove), with :data:`VARIANT_FILE` to confirm a match."""
    return (("svg", f"{kind}-*-student.svg"), ("svg", f"{kind}-*-key.svg"), ("problems", f"{kind}-*.json"),
            ("dxf", f"{kind}-*.dxf"))


#: the name of a per-variant file of a kind (``{kind}`` filled in)
VARIANT_FILE = r"{kind}-\d+(-student|-key)?\.(svg|json|dxf)"


def register(kind: str, variant_class: type[Variant], generate: Callable[..., dict[str, Any]],
             page: Callable[..., Scene], title: Title,
             statement: tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]) -> None:
    """Add a worksheet kind kept in a module of its own (as ``acceleration-plan``): its variant class,
    its generator ``generate(rng) -> data``, its page ``page(variant, notation, key) -> Scene``, its
    title and its statement (its paragraphs in en, ru, zh)."""
    CLASSES[kind] = variant_class
    GENERATORS[kind] = generate
    PAGES[kind] = page
    TITLES[kind] = title
    STATEMENTS[kind] = statement
