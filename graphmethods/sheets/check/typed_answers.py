"""The answers file (TOML): its schema, reading it, and each answer typed and checked before any
computation (a number, a list of numbers, a position, a sense of rotation).
"""

from __future__ import annotations

import math
import pathlib
import sys
from typing import TYPE_CHECKING

from graphmethods.errors import InputError
from graphmethods.sheets.check import acceleration as ca
from graphmethods.units import MAX_POSITIONS, count, read_text, real

if TYPE_CHECKING:
    pass

#: the answers file: section -> allowed keys (top-level keys: problem, student)
SCHEMA = {
    "page": ("size", "orientation"),
    "moment_diagram": ("mu_M", "mu_phi", "mu_phi_deg", "areas_mm2", "origin_mm"),
    "energy_indicator": ("mu_E", "step_mm", "arrows_mm", "origin_mm"),
    "velocity_plan": ("position", "positions", "mu_v", "pa_mm", "pb_mm", "ab_mm", "ps2_mm", "origin_mm"),
    "energy_mass": ("positions", "mu_J", "mu_T", "tan_psi_max", "tan_psi_min", "kl_mm", "omega_max_at",
                    "omega_min_at", "origin_mm"),
    "acceleration_plan": ca.SECTION_KEYS,           # its vectors' keys depend on the linkage
    "results": ("M_d", "works_J", "delta_W_max", "omega_m", "omega_max", "omega_min", "omega_max_at",
                "omega_min_at", "J_F", "v_A", "v_B", "v_BA", "v_S2", "omega_2", "omega_2_sense"),
}
TOP_LEVEL = ("problem", "student")

#: What each key of the answers file holds (the number policy of graphmethods.units applies to all):
#: "scale" a positive number, "count" the number of positions m, "index" a position number,
#: "list" a flat list of numbers, "xy" two numbers, "at" a point label, an angle or a list of positions,
#: "text" text; any other key a number.
KEY_KINDS = {
    "size": "text", "orientation": "text", "omega_2_sense": "text",
    "mu_M": "scale", "mu_phi": "scale", "mu_phi_deg": "scale", "mu_E": "scale", "mu_v": "scale",
    "mu_J": "scale", "mu_T": "scale", "step_mm": "scale",
    "positions": "count", "position": "index",
    "areas_mm2": "list", "arrows_mm": "list", "works_J": "list", "origin_mm": "xy",
    "omega_max_at": "at", "omega_min_at": "at",
}


# ----------------------------------------------------------------------------- TOML

def load_toml(text: str, *, source: str = "<answers>") -> dict:
    """TOML text as a dict, read by the standard ``tomllib`` (Python ≥ 3.11) or its backport ``tomli``.

    >>> load_toml('problem = "W1"\\n[results]\\nJ_F = 1.5e-1  # kg·m²')
    {'problem': 'W1', 'results': {'J_F': 0.15}}
    """
    if sys.version_info >= (3, 11):
        import tomllib
    else:                                # Python 3.10: the same parser, installed as a dependency
        import tomli as tomllib
    _toml_depth(text, source)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{source}: not valid TOML ({' '.join(str(exc).split())})") from None
    except RecursionError:
        raise InputError(f"{source}: TOML nested more than {MAX_TOML_DEPTH} levels deep (MAX_TOML_DEPTH)") from None


#: Deepest nesting of arrays and inline tables an answers file may have (its lists are flat: one level)
MAX_TOML_DEPTH = 50


def _toml_depth(text: str, source: str) -> None:
    """Refuse arrays or inline tables nested deeper than :data:`MAX_TOML_DEPTH` before the recursive parser
    sees them (strings and comments skipped)."""
    level = line = 0
    quote = ""
    escaped = comment = False
    for ch in text:
        if ch == "\n":
            line += 1
            comment = False
        if comment:
            continue
        if quote:
            if escaped:
                escaped = False
            elif ch == "\\" and quote == '"':
                escaped = True
            elif ch == quote:
                quote = ""
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            comment = True
        elif ch in "[{":
            level += 1
            if level > MAX_TOML_DEPTH:
                raise InputError(f"{source}, line {line + 1}: arrays or tables nested more than {MAX_TOML_DEPTH} "
                                 f"levels deep (MAX_TOML_DEPTH); an answer is a number, text or a flat list")
        elif ch in "]}":
            level = max(level - 1, 0)


def read_answers(path) -> dict:
    """Read and validate an answers file (see :data:`SCHEMA`): numbers, text, lists as tuples.

    >>> import pathlib
    >>> a = read_answers(pathlib.Path(__file__).parents[2] / "problems" / "data" / "answers" / "w3_correct.toml")
    >>> a["moment_diagram"]["areas_mm2"], a["results"]["omega_max_at"]
    ((-1560.0, 1590.0), 0.0)
    """
    p = pathlib.Path(path)
    text = read_text(p, missing="no such answers file")
    return validate_answers(load_toml(text, source=str(p)), source=str(p))


def validate_answers(data: dict, *, source: str = "<answers>") -> dict:
    """Check the sections and keys of an answers dict; numbers become floats, lists tuples of floats."""
    if not isinstance(data, dict):
        raise InputError(f"{source}: the answers must be a table of sections")
    out: dict = {}
    for key, value in data.items():
        if key in TOP_LEVEL:
            if not isinstance(value, str):
                raise InputError(f"{source}: {key} must be text")
            out[key] = value
            continue
        if key not in SCHEMA:
            raise InputError(f"{source}: unknown section or key {key!r}; sections: {', '.join(SCHEMA)} "
                             f"(and {', '.join(TOP_LEVEL)})")
        if not isinstance(value, dict):
            raise InputError(f"{source}: {key!r} must be a [section]")
        sec = {}
        for k, v in value.items():
            if k not in SCHEMA[key]:
                raise InputError(f"{source}: [{key}] has no key {k!r}; its keys are {', '.join(SCHEMA[key])}")
            if (isinstance(v, str) and v == "") or (isinstance(v, (list, tuple)) and len(v) == 0):
                continue                # left blank in a template (sheets.worksheets.answers): not answered
                continue
            kind = KEY_KINDS.get(k, "text" if k.endswith("_sense") else "number")
            sec[k] = _typed_answer(kind, _answer_value(v, f"{source}: [{key}] {k}"), f"{source}: [{key}] {k}")
        if sec or not value:            # a section whose every key is blank is not answered either
            out[key] = sec
    return out


def _typed_answer(kind: str, v, where: str):
    """One answer checked for what its key holds (see :data:`KEY_KINDS`), before any work."""
    if kind == "text":
        if not isinstance(v, str):
            raise InputError(f"{where} must be text, got {v!r}")
        return v
    if kind == "at":
        items = v if isinstance(v, tuple) else (v,)
        if not items:
            raise InputError(f"{where}: give a point label (\"b\"), an angle in degrees or positions [0, 6]")
        for x in items:
            if isinstance(x, tuple):
                raise InputError(f"{where} must be a label, a number or a flat list, got {v!r}")
        return v
    if kind == "list":
        if not isinstance(v, tuple):
            raise InputError(f"{where} must be a list of numbers, e.g. [-10, 110, -20], got {v!r}")
        return tuple(real(x, f"{where}[{i}]") if not isinstance(x, (str, tuple)) else
                     _not_a_number(x, f"{where}[{i}]") for i, x in enumerate(v))
    if kind == "xy":
        if not isinstance(v, tuple) or len(v) != 2:
            raise InputError(f"{where} must be two numbers [x, y] in mm, got {v!r}")
        return tuple(real(x, f"{where}[{i}]") if not isinstance(x, (str, tuple)) else
                     _not_a_number(x, f"{where}[{i}]") for i, x in enumerate(v))
    if isinstance(v, (str, tuple)):
        _not_a_number(v, where)
    if kind == "count":
        return count(v, where, low=3, high=MAX_POSITIONS, why="the number of positions m")
    if kind == "index":
        return count(v, where, low=0, high=MAX_POSITIONS, why="a position number")
    if kind == "scale":
        return real(v, where, lo=0.0, lo_open=True, hint="a scale or a step is a positive number")
    return real(v, where)


def _not_a_number(v, where: str):
    raise InputError(f"{where} must be a number, got {v!r}")


def _answer_value(v, where: str, depth: int = 0):
    if type(v).__module__ == "numpy":     # a numpy scalar or array in an answers dict built in Python
        import numpy as np

        if isinstance(v, np.ndarray):
            v = v.tolist()
        elif isinstance(v, np.generic):
            v = v.item()
    if isinstance(v, bool):
        raise InputError(f"{where}: expected a number or text, got {v!r}")
    if isinstance(v, int):
        return v                          # its size is checked by the number policy (units.real)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise InputError(f"{where}: {v!r} is not finite")
        return v
    if isinstance(v, str):
        return v
    if isinstance(v, (list, tuple)):
        if depth >= 2:
            raise InputError(f"{where}: lists nested too deeply; give a flat list of numbers")
        return tuple(_answer_value(x, where, depth + 1) for x in v)
    raise InputError(f"{where}: expected a number, text or list, got {v!r}")


