"""``graphmethods gallery``: build every figure of the gallery (one catalogue row per figure).

The figures are the rows of :mod:`graphmethods.gallery.catalogue` (each has ``build() -> Scene``),
so the command works from an installed package. In a source checkout each figure's committed golden
SVG is ``gallery/<name>.svg``, which the tests compare with. This command builds every figure into
a folder, never over an existing file unless ``--force``; ``--regenerate`` rewrites the golden files
of a source checkout on purpose (and the PNGs of rows with ``png=True``); ``--dir`` builds your own
folder of scripts (each ``<name>.py`` defines ``build() -> Scene``) instead.

    graphmethods gallery --out gallery-out          # SVG of every figure
    graphmethods gallery --out gallery-out --png    # and PNG
    graphmethods gallery --out gallery-out --dxf    # and DXF (1 unit = 1 mm, layers by role)
    graphmethods gallery --regenerate               # rewrite gallery/*.svg (and marked PNGs), from the project folder

Heavy modules (the sheets, matplotlib) are imported only when the command runs.
"""

from __future__ import annotations

import difflib
import importlib.util
import pathlib
import sys
from types import ModuleType

from graphmethods.errors import GraphmethodsError, InputError, OutputExistsError

DEFAULT_DIR = "gallery"     # where --regenerate writes the golden files: the source checkout's gallery/
DEFAULT_OUT = "gallery-out"
PNG_DPI = 150


def scripts(directory) -> list[pathlib.Path]:
    """The gallery scripts in a folder of your own (``*.py`` not starting with ``_``), sorted by name."""
    d = pathlib.Path(directory)
    if not d.is_dir():
        raise InputError(f"gallery folder {d} not found; give an existing folder of scripts to --dir")
    found = sorted(p for p in d.glob("*.py") if not p.name.startswith("_"))
    if not found:
        raise InputError(f"no gallery scripts (*.py) in {d}")
    return found


def load(path) -> ModuleType:
    """Import one gallery script of a folder as a module (it is not on sys.path)."""
    path = pathlib.Path(path)
    spec = importlib.util.spec_from_file_location(f"graphmethods_gallery_{path.stem}", path)
    if spec is None or spec.loader is None:
        raise InputError(f"{path}: not a Python script that can be imported")
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except Exception as exc:                # a script is code: its failure is named, not a traceback
        raise InputError(f"{path}: the script does not load ({type(exc).__name__}: {exc}); "
                         f"nothing was written") from None
    _check_module(module, str(path))
    return module


def _check_module(module: ModuleType, where: str) -> None:
    if not callable(getattr(module, "build", None)):
        raise InputError(f"{where}: a gallery script must define build() returning a Scene")


def figures(directory=None) -> list:
    """(name, figure) of every figure: the catalogue's rows, or the scripts of ``directory`` (modules);
    each has ``build()``."""
    if directory is not None:
        return [(p.stem, load(p)) for p in scripts(directory)]
    from graphmethods import gallery as builtin

    return [(name, builtin.figure(name)) for name in builtin.figure_names()]


def build(figure):
    """The scene a figure builds: a built-in figure's name or catalogue row, a module, or a script's path."""
    from graphmethods.gallery import Figure
    from graphmethods.scene import Scene

    if isinstance(figure, (ModuleType, Figure)):
        module, where = figure, getattr(figure, "__name__", None) or f"graphmethods.gallery: {figure.name}"
    elif isinstance(figure, pathlib.Path) or str(figure).endswith(".py"):
        module, where = load(figure), str(figure)
    else:
        from graphmethods import gallery as builtin

        if figure not in builtin.figure_names():
            raise InputError(f"no built-in figure {figure!r}")
        module, where = builtin.figure(figure), f"graphmethods.gallery: {figure}"
    scene = module.build()
    if not isinstance(scene, Scene):
        raise InputError(f"{where}: build() returned {type(scene).__name__}, not a Scene")
    return scene


def canonical(svg_text: str) -> str:
    """An SVG document in XML canonical form (C14N 2.0): attribute order, quoting and
    empty-element syntax no longer matter, text and layout do."""
    import xml.etree.ElementTree as ET

    return ET.canonicalize(xml_data=svg_text)


def svg_diff(expected: str, actual: str, *, name: str = "figure", context: int = 2) -> str | None:
    """None when two SVG documents are the same after canonicalisation, else a readable unified diff."""
    a, b = canonical(expected), canonical(actual)
    if a == b:
        return None
    diff = difflib.unified_diff(a.splitlines(), b.splitlines(), fromfile=f"{name} (committed)",
                                tofile=f"{name} (built now)", lineterm="", n=context)
    return "\n".join(diff)


def add_parser(sub) -> None:
    p = sub.add_parser("gallery", help="build every gallery figure (SVG, optionally PNG)",
                       description="Build every figure of the gallery (the textbook figures of the built-in "
                       "problems) into a folder, as scale-true SVG (optionally PNG).")
    p.add_argument("--dir", default=None,
                   help="build the scripts of this folder instead (each <name>.py defines build() -> Scene)")
    p.add_argument("-o", "--out", default=None, help=f"where to write the figures (default: {DEFAULT_OUT})")
    p.add_argument("--quiet", action="store_true", help="no progress line on stderr")
    p.add_argument("--force", action="store_true", help="overwrite existing files")
    p.add_argument("--png", action="store_true", help="also write a PNG of every figure")
    p.add_argument("--dxf", action="store_true",
                   help="also write a DXF of every figure (1 unit = 1 mm, layers by role)")
    p.add_argument("--regenerate", action="store_true",
                   help="in a source checkout: rewrite the committed golden SVGs in gallery/ (or in --dir), "
                        "and the PNGs of figures with PNG = True")
    p.set_defaults(func=run)


def is_source_checkout(root: pathlib.Path) -> bool:
    """True when ``root`` is graphmethods' own source folder: its pyproject.toml names the project and the
    package lies beside it (a user's folder that merely has a ``gallery/`` is not one)."""
    try:
        text = (root / "pyproject.toml").read_text(encoding="utf-8", errors="replace")[:20_000]
    except OSError:
        return False
    return 'name = "graphmethods"' in text and (root / "graphmethods" / "__init__.py").is_file()


def run(args) -> int:

    found = figures(args.dir)
    if args.regenerate:
        if args.out is not None:
            raise InputError("--regenerate rewrites the gallery folder itself; leave out --out")
        out, overwrite = pathlib.Path(args.dir or DEFAULT_DIR), True
        if not out.is_dir():
            raise InputError(f"--regenerate rewrites the golden files of a source checkout: no folder {out} here; "
                             f"run it from the project folder")
        if args.dir is None and not is_source_checkout(out.resolve().parent):
            raise InputError(f"--regenerate rewrites the golden files of a source checkout, and {out.resolve().parent} "
                             f"is none (no pyproject.toml of graphmethods beside graphmethods/); to build the "
                             f"figures here use --out FOLDER")
    else:
        if args.out is not None and args.out.strip() == "":
            raise InputError("--out is empty; give a folder (it is created if missing)")
        out, overwrite = pathlib.Path(args.out or DEFAULT_OUT), bool(args.force)
        if out.exists() and not out.is_dir():
            raise InputError(f"--out {out} is a file; give a folder")
    jobs = []
    for name, module in found:
        want_png = args.png or (args.regenerate and getattr(module, "PNG", False))
        targets = [out / f"{name}.svg"] + ([out / f"{name}.png"] if want_png else [])
        if getattr(args, "dxf", False) and not args.regenerate:
            targets.append(out / f"{name}.dxf")
        jobs.append((name, module, targets))
    if not overwrite:   # refuse before writing anything, so a refused run leaves no half-built gallery
        existing = [str(t) for _, _, targets in jobs for t in targets if t.exists()]
        if existing:
            more = f" and {len(existing) - 3} more" if len(existing) > 3 else ""
            raise OutputExistsError(f"{', '.join(existing[:3])}{more} exist; use --force to overwrite, "
                                    f"or another --out")
    from graphmethods.cli._progress import Progress
    from graphmethods.render import formats
    from graphmethods.render.files import write_set

    blobs, lines = {}, []
    progress = Progress(quiet=args.quiet, label="gallery ")
    for k, (name, module, targets) in enumerate(jobs, start=1):  # build every figure first: a failing script writes
        progress(k, len(jobs), name)                              # nothing
        try:
            scene = build(module)
        except GraphmethodsError as exc:
            raise InputError(f"{name}: {exc}; nothing was written") from None
        except Exception as exc:            # a gallery script is code: its failure is named, not a traceback
            raise InputError(f"{name}: build() failed ({type(exc).__name__}: {exc}); nothing was written") from None
        for target in targets:
            blobs[target.name] = formats.to_bytes(scene, target.suffix, dpi=PNG_DPI)
        line = " and ".join([f"wrote {targets[0]}"] + [t.name for t in targets[1:]])
        scales = "; ".join(s.caption() for s in scene.scales())
        lines.append(line + (f"  ({scales})" if scales else ""))
    progress.done()
    write_set(out, blobs, overwrite=overwrite, what="gallery folder")
    for line in lines:
        print(line, file=sys.stdout)
    print(f"{len(jobs)} figures in {out}")
    return 0
