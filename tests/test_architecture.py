"""The house rules: imports only go downward, and importing the package is light."""

import argparse
import ast
import pathlib
import subprocess
import sys

import pytest

PKG = pathlib.Path(__file__).resolve().parents[1] / "graphmethods"

# Layer of each top-level part of the package; a module may import only parts of
# a lower or equal layer (equal: within its own part).
LAYERS = {
    "errors": 0, "compat": 0, "units": 0, "titles": 0, "__init__": 0,
    "kinematics": 1,
    "dynamics": 2,
    "problems": 3,
    "scene": 4,
    "render": 5,
    "sheets": 6,
    "bench_reference": 2, "gallery": 7, "bench": 7, "cli": 8, "__main__": 9,
}


def _part(path: pathlib.Path) -> str:
    rel = path.relative_to(PKG)
    return rel.parts[0].removesuffix(".py")


def _imported_parts(path: pathlib.Path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        names = []
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:  # relative import: resolve against the module's package
                base = path.relative_to(PKG).parts[:-1]
                up = base[: len(base) - (node.level - 1)] if node.level > 1 else base
                mod = ".".join(("graphmethods",) + tuple(up) + ((node.module,) if node.module else ()))
                names = [mod]
                if not node.module:
                    names = [mod + "." + a.name for a in node.names]
            else:
                names = [node.module or ""]
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "import_module"
                and node.args):
            names = [_literal_prefix(node.args[0])]       # an import by name counts as an import
        for name in names:
            parts = name.split(".")
            if parts[0] == "graphmethods" and len(parts) > 1:
                yield parts[1], node.lineno


def _literal_prefix(node: ast.expr) -> str:
    """The module name an ``import_module`` call names, or its literal start (an f-string's)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr) and node.values and isinstance(node.values[0], ast.Constant):
        return str(node.values[0].value)
    return ""


#: the upward reaches the architecture allows, each with its reason
UPWARD = {
    ("scene/scene.py", "render"): "a notebook asks the scene for its SVG (Scene._repr_svg_): the writer is looked "
                                  "up by name only when the scene is displayed, so the scene model imports no backend",
}


def test_every_part_has_a_layer():
    for path in PKG.rglob("*.py"):
        assert _part(path) in LAYERS, f"{path}: add its part to LAYERS in this test"


def test_imports_only_go_downward():
    bad = []
    for path in PKG.rglob("*.py"):
        own = _part(path)
        for part, line in _imported_parts(path):
            if part not in LAYERS:
                continue
            if (path.relative_to(PKG).as_posix(), part) in UPWARD:
                continue
            if LAYERS[part] > LAYERS[own] or (LAYERS[part] == LAYERS[own] and part != own and LAYERS[own] > 0):
                bad.append(f"{path.relative_to(PKG.parent)}:{line} imports graphmethods.{part}")
    assert not bad, "imports must go downward only:\n" + "\n".join(bad)


def test_import_graphmethods_is_light():
    code = (
        "import sys, graphmethods, graphmethods.kinematics, graphmethods.dynamics, graphmethods.scene;"
        "heavy = [m for m in ('matplotlib', 'svgwrite', 'shapely', 'ezdxf') if m in sys.modules];"
        "print(','.join(heavy))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"import graphmethods loaded {out.stdout.strip()}"


def test_top_level_help_imports_no_command_module_no_numpy_and_no_argparse():
    code = ("import sys\nfrom graphmethods.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
            "heavy = sorted(m for m in sys.modules if m in ('numpy', 'argparse', 'shutil', 'textwrap')"
            " or m.startswith('graphmethods.cli.'))\n"
            "print(heavy, file=sys.stderr)")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert proc.stderr.strip() == "[]" and "flywheel" in proc.stdout


@pytest.mark.parametrize("flag", ["-h", "--help"])
def test_top_level_help_lists_every_command_with_its_help_line(flag, capsys):
    from graphmethods.cli import COMMANDS, main

    assert main([flag]) == 0
    out = capsys.readouterr().out
    rows = {line.split()[0]: line.split(None, 1)[1] for line in out.splitlines() if line.startswith("  ")}
    assert {name: rows[name] for name in COMMANDS} == {name: line for name, (_, line) in COMMANDS.items()}
    assert out.startswith("usage: graphmethods") and "--version" in out


def test_the_help_lines_of_the_top_level_are_those_of_the_commands():
    from graphmethods.cli import COMMANDS, build_parser

    lazy, full = build_parser(""), build_parser()
    def helps(parser):
        (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
        return {c.dest: c.help for c in sub._choices_actions}
    assert helps(lazy) == helps(full) == {name: line for name, (_, line) in COMMANDS.items()}


def test_no_figure_function_over_80_lines():
    """Issue 16: a figure reads as steps (scales, a frozen layout, element builders), none longer than 80 lines
    (its docstring not counted: the parameters and a running example are documentation, not steps)."""
    import graphmethods

    root = pathlib.Path(graphmethods.__file__).parent / "sheets"
    long = []
    for path in sorted(root.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                length = (node.end_lineno or node.lineno) - node.lineno + 1
                doc = node.body[0] if node.body and isinstance(node.body[0], ast.Expr) and isinstance(
                    getattr(node.body[0], "value", None), ast.Constant) else None
                if doc is not None:
                    length -= (doc.end_lineno or doc.lineno) - doc.lineno + 1
                if length > 80:
                    long.append(f"{path.relative_to(root)}:{node.lineno} {node.name} ({length} lines)")
    assert not long, long


def test_a_flywheel_without_figures_loads_no_figure_layer():
    """`graphmethods flywheel --json` that writes no file is numbers only: no scene, render or sheets (start-up
    time). Its text report speaks --lang with the figures' symbols and digits: the notation of scene, and still
    neither render nor sheets."""
    def layers(*extra: str) -> tuple[str, str]:
        code = ("import sys\nfrom graphmethods.cli import main\n"
                "main(['flywheel', '--areas', '-50', '550', '-100', '125', '-500', '25', '-50', '--n', '600',"
                f" '--delta', '1/300'{''.join(f', {e!r}' for e in extra)}])\n"
                "print(sorted({m.split('.')[1] for m in sys.modules if m.startswith('graphmethods.')"
                " and m.split('.')[1] in ('scene', 'render', 'sheets')}), file=sys.stderr)")
        proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
        return proc.stderr.strip(), proc.stdout

    err, out = layers("--json")
    assert err == "[]" and "J_F" in out
    err, out = layers()
    assert err == "['scene']" and "J_F = 43.69" in out


def test_the_sheets_package_imports_its_modules_when_asked():
    """`import graphmethods.sheets` loads no sheet module; a function is imported when first asked for, and one
    named as its module (cam_sheet, dynamic_analysis_sheet, ...) stays the function whichever is imported first."""
    code = (
        "import sys, importlib\n"
        "import graphmethods.sheets as s\n"
        "print(sorted(m for m in sys.modules if m.startswith('graphmethods.sheets.')))\n"
        "import graphmethods.sheets.dynamic_analysis_sheet, graphmethods.sheets.cam_sheet\n"
        "from graphmethods.sheets import cam_sheet, kinematic_scheme\n"
        "from graphmethods.sheets.dynamic_analysis_sheet import dynamic_analysis_sheet as d\n"
        "fs = [s.cam_sheet, cam_sheet, kinematic_scheme, s.dynamic_analysis_sheet, d, s.energy_indicator]\n"
        "print(all(callable(f) and not isinstance(f, type(sys)) for f in fs), d is s.dynamic_analysis_sheet)\n"
        "print(s.layout.__name__, set(s.__all__) <= set(dir(s)))\n"
        "try:\n    s.no_such_figure\nexcept AttributeError:\n    print('missing')\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split("\n")
    assert out[:4] == ["[]", "True True", "graphmethods.sheets.layout True", "missing"]


def test_a_notation_reads_a_family_of_words_when_first_asked():
    """The vocabulary's core is read at import, a family's file when one of its keys is first asked for; the
    mapping reads every family when iterated, in the order of `vocabulary.tables()`."""
    code = (
        "from graphmethods.scene import vocabulary\n"
        "from graphmethods.scene.notation import get\n"
        "before = vocabulary.family.cache_info().currsize\n"
        "word = get('ru').word('kinematics.plan', k=3)\n"
        "print(before, vocabulary.family.cache_info().currsize, word)\n"
        "symbols, words, _ = vocabulary.tables()\n"
        "en = {k: v[0] for k, v in symbols.items()}\n"
        "print(list(get('zh').words) == list(words), dict(get('en').symbols) == en)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split("\n")
    assert out[:2] == ["1 2 План скоростей, положение 3", "True True"]
