"""``graphmethods gallery``: build every figure of the gallery (one small script per figure).

Each ``gallery/<name>.py`` defines ``build() -> Scene``; its committed ``<name>.svg`` is
the golden file the tests compare with. This command builds them all into a folder,
never over an existing file unless ``--force``; ``--regenerate`` rewrites the committed
golden files on purpose (and the PNGs of scripts that set ``PNG = True``).

    graphmethods gallery --out gallery-out          # SVG of every figure
    graphmethods gallery --out gallery-out --png    # and PNG
    graphmethods gallery --regenerate               # rewrite gallery/*.svg (and marked PNGs)

Heavy modules (the sheets, svgwrite, matplotlib) are imported only when the command runs.
"""

from __future__ import annotations

import difflib
import importlib.util
import pathlib
import sys

from graphmethods.errors import InputError, OutputExistsError

DEFAULT_DIR = "gallery"
DEFAULT_OUT = "gallery-out"
PNG_DPI = 150


def scripts(directory) -> list[pathlib.Path]:
    """The gallery scripts in ``directory`` (``*.py`` not starting with ``_``), sorted by name."""
    d = pathlib.Path(directory)
    if not d.is_dir():
        raise InputError(f"gallery folder {d} not found; run from the project folder or give --dir")
    found = sorted(p for p in d.glob("*.py") if not p.name.startswith("_"))
    if not found:
        raise InputError(f"no gallery scripts (*.py) in {d}")
    return found


def load(path) -> object:
    """Import one gallery script as a module (it is not on sys.path)."""
    path = pathlib.Path(path)
    spec = importlib.util.spec_from_file_location(f"graphmethods_gallery_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if not callable(getattr(module, "build", None)):
        raise InputError(f"{path}: a gallery script must define build() returning a Scene")
    return module


def build(path):
    """The scene a gallery script builds."""
    from graphmethods.scene import Scene

    scene = load(path).build()
    if not isinstance(scene, Scene):
        raise InputError(f"{path}: build() returned {type(scene).__name__}, not a Scene")
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
                       description="Build every figure of the gallery: each gallery/<name>.py defines build().")
    p.add_argument("--dir", default=DEFAULT_DIR, help="the gallery folder (default: gallery)")
    p.add_argument("--out", default=None, help=f"where to write the figures (default: {DEFAULT_OUT})")
    p.add_argument("--force", action="store_true", help="overwrite existing files")
    p.add_argument("--png", action="store_true", help="also write a PNG of every figure")
    p.add_argument("--regenerate", action="store_true",
                   help="rewrite the committed golden SVGs in the gallery folder (and PNGs of scripts with PNG = True)")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.render import svg

    paths = scripts(args.dir)
    if args.regenerate:
        if args.out is not None:
            raise InputError("--regenerate rewrites the gallery folder itself; leave out --out")
        out, overwrite = pathlib.Path(args.dir), True
    else:
        out, overwrite = pathlib.Path(args.out or DEFAULT_OUT), bool(args.force)
        out.mkdir(parents=True, exist_ok=True)
    jobs = []
    for path in paths:
        module = load(path)
        want_png = args.png or (args.regenerate and getattr(module, "PNG", False))
        targets = [out / f"{path.stem}.svg"] + ([out / f"{path.stem}.png"] if want_png else [])
        jobs.append((path, module, targets))
    if not overwrite:   # refuse before writing anything, so a refused run leaves no half-built gallery
        existing = [str(t) for _, _, targets in jobs for t in targets if t.exists()]
        if existing:
            more = f" and {len(existing) - 3} more" if len(existing) > 3 else ""
            raise OutputExistsError(f"{', '.join(existing[:3])}{more} exist; use --force to overwrite, "
                                    f"or another --out")
    built = [(module.build(), targets) for _, module, targets in jobs]
    for scene, targets in built:
        if len(targets) > 1:        # a PNG's text needs fonts: refuse (MissingFontError) before writing anything
            from graphmethods.render import mpl

            mpl.check_scene(scene)
    for scene, targets in built:
        svg.save(scene, targets[0], overwrite=overwrite)
        line = f"wrote {targets[0]}"
        if len(targets) > 1:
            from graphmethods.render import mpl

            mpl.save_png(scene, targets[1], dpi=PNG_DPI, overwrite=overwrite)
            line += f" and {targets[1].name}"
        scales = "; ".join(s.caption() for s in scene.scales())
        print(line + (f"  ({scales})" if scales else ""), file=sys.stdout)
    print(f"{len(jobs)} figures in {out}")
    return 0
