"""``graphmethods gallery``: build every figure of the gallery (one small script per figure).

Each ``gallery/<name>.py`` defines ``build() -> Scene``; its committed ``<name>.svg`` is
the golden file the tests compare with. This command builds them all into a folder,
never over an existing file unless ``--force``; ``--regenerate`` rewrites the committed
golden files on purpose (and the PNGs of scripts that set ``PNG = True``).

    graphmethods gallery --out gallery-out          # SVG of every figure
    graphmethods gallery --out gallery-out --png    # and PNG
    graphmethods gallery --out gallery-out --dxf    # and DXF (1 unit = 1 mm, layers by role)
    graphmethods gallery --regenerate               # rewrite gallery/*.svg (and marked PNGs)

Heavy modules (the sheets, svgwrite, matplotlib) are imported only when the command runs.
"""

from __future__ import annotations

import difflib
import importlib.util
import pathlib
import sys

from graphmethods.errors import GraphmethodsError, InputError, OutputExistsError

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
    p.add_argument("--dxf", action="store_true", help="also write a DXF of every figure (1 unit = 1 mm, layers by role)")
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
        if args.out is not None and args.out.strip() == "":
            raise InputError("--out is empty; give a folder (it is created if missing)")
        out, overwrite = pathlib.Path(args.out or DEFAULT_OUT), bool(args.force)
        if out.exists() and not out.is_dir():
            raise InputError(f"--out {out} is a file; give a folder")
    jobs = []
    for path in paths:
        try:
            module = load(path)
        except GraphmethodsError:
            raise
        except Exception as exc:
            raise InputError(f"{path}: the script does not load ({type(exc).__name__}: {exc}); nothing was written") from None
        want_png = args.png or (args.regenerate and getattr(module, "PNG", False))
        targets = [out / f"{path.stem}.svg"] + ([out / f"{path.stem}.png"] if want_png else [])
        if getattr(args, "dxf", False) and not args.regenerate:
            targets.append(out / f"{path.stem}.dxf")
        jobs.append((path, module, targets))
    if not overwrite:   # refuse before writing anything, so a refused run leaves no half-built gallery
        existing = [str(t) for _, _, targets in jobs for t in targets if t.exists()]
        if existing:
            more = f" and {len(existing) - 3} more" if len(existing) > 3 else ""
            raise OutputExistsError(f"{', '.join(existing[:3])}{more} exist; use --force to overwrite, "
                                    f"or another --out")
    from graphmethods.render.files import write_set

    blobs, lines = {}, []
    for path, module, targets in jobs:      # build every figure first: a failing script writes nothing
        try:
            scene = module.build()
        except GraphmethodsError as exc:
            raise InputError(f"{path}: {exc}; nothing was written") from None
        except Exception as exc:            # a gallery script is code: its failure is named, not a traceback
            raise InputError(f"{path}: build() failed ({type(exc).__name__}: {exc}); nothing was written") from None
        blobs[targets[0].name] = svg.to_bytes(scene)
        line = f"wrote {targets[0]}"
        for target in targets[1:]:
            if target.suffix == ".png":
                from graphmethods.render import mpl

                blobs[target.name] = mpl.to_png_bytes(scene, dpi=PNG_DPI)
            else:
                from graphmethods.render import dxf

                blobs[target.name] = dxf.to_bytes(scene)
            line += f" and {target.name}"
        scales = "; ".join(s.caption() for s in scene.scales())
        lines.append(line + (f"  ({scales})" if scales else ""))
    write_set(out, blobs, overwrite=overwrite, what="gallery folder")
    for line in lines:
        print(line, file=sys.stdout)
    print(f"{len(jobs)} figures in {out}")
    return 0
