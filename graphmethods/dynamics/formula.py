"""Formulas typed by users, such as ``"20000 + 9500*sin(2*phi) - 5700*cos(2*phi)"``, read safely.

The text is parsed by Python's own parser (:mod:`ast`) into a syntax tree, and only a small,
whitelisted grammar is accepted: numbers; the caller's variables (``phi`` and, where allowed,
``omega`` and ``t``); the constants ``pi`` and ``e``; ``+ - * / **`` and unary minus; the
comparisons ``< <= > >=`` (1 where true, 0 where false, for piecewise loads such as
``60*(phi < pi/4) + 10*(phi >= pi/4)``); parentheses; and the functions in :data:`FUNCTIONS`.
Anything else (attribute access, names of Python objects, subscripts, lambdas, strings, keyword
arguments, ``^``) is refused with a message naming the offending token. Nothing is passed to
``eval``: the tree is turned into a nest of numpy closures, so a formula is evaluated vectorised
over arrays. The Greek letters φ, ω and π may be written for phi, omega and pi.

>>> f = Formula("20000 + 9500*sin(2*phi) - 5700*cos(2*phi)")
>>> float(f(phi=0.0))
14300.0
>>> Formula("a + 1")
Traceback (most recent call last):
    ...
graphmethods.errors.InputError: formula 'a + 1': unknown name 'a' at column 1; use phi, pi, e or one of the functions (sin, cos, ...)
"""  # noqa: E501 - a doctest's expected output is one line

from __future__ import annotations

import ast
import math
from collections.abc import Callable
from typing import Any, NoReturn

import numpy as np
from numpy.typing import ArrayLike

from graphmethods.errors import InputError
from graphmethods.kinematics.vectors import FloatArray

__all__ = ["Formula", "FUNCTIONS", "CONSTANTS", "looks_like_formula"]

#: The functions a formula may call: name -> (numpy function, number of arguments).
FUNCTIONS: dict[str, tuple[Callable[..., Any], int]] = {
    "sin": (np.sin, 1), "cos": (np.cos, 1), "tan": (np.tan, 1),
    "asin": (np.arcsin, 1), "acos": (np.arccos, 1), "atan": (np.arctan, 1), "atan2": (np.arctan2, 2),
    "sinh": (np.sinh, 1), "cosh": (np.cosh, 1), "tanh": (np.tanh, 1),
    "exp": (np.exp, 1), "log": (np.log, 1), "log10": (np.log10, 1), "sqrt": (np.sqrt, 1),
    "abs": (np.abs, 1), "sign": (np.sign, 1), "floor": (np.floor, 1), "ceil": (np.ceil, 1),
    "min": (np.minimum, 2), "max": (np.maximum, 2), "mod": (np.mod, 2), "hypot": (np.hypot, 2),
    "radians": (np.radians, 1), "degrees": (np.degrees, 1),
}

#: Named constants.
CONSTANTS = {"pi": math.pi, "e": math.e}

_ALIASES = {"φ": "phi", "ϕ": "phi", "ω": "omega", "π": "pi"}
_BINARY = {ast.Add: np.add, ast.Sub: np.subtract, ast.Mult: np.multiply, ast.Div: np.divide,
           ast.Pow: np.power}
_COMPARE = {ast.Lt: np.less, ast.LtE: np.less_equal, ast.Gt: np.greater, ast.GtE: np.greater_equal}
_SYMBOL = {ast.BitXor: "^", ast.FloorDiv: "//", ast.Mod: "%", ast.MatMult: "@", ast.LShift: "<<",
           ast.RShift: ">>", ast.BitAnd: "&", ast.BitOr: "|", ast.Not: "not", ast.Invert: "~",
           ast.Eq: "==", ast.NotEq: "!=", ast.Is: "is", ast.IsNot: "is not", ast.In: "in",
           ast.NotIn: "not in", ast.And: "and", ast.Or: "or"}
_HINT = {"^": "write ** for a power", "%": "write mod(a, b)", "//": "write floor(a / b)"}
MAX_LENGTH = 2000
MAX_DEPTH = 60

#: the variables' values by name, as a compiled formula reads them
_Env = dict[str, FloatArray]
#: a compiled (sub)formula: its value for the variables (a float for a constant, else an array)
_Fn = Callable[[_Env], "FloatArray | float"]


def looks_like_formula(text: str) -> bool:
    """Whether a command-line value is a formula rather than a plain number.

    >>> looks_like_formula("1/300"), looks_like_formula("5*sin(phi)"), looks_like_formula("-20")
    (False, True, False)
    """
    s = str(text).strip()
    try:
        float(s)
        return False
    except ValueError:
        pass
    parts = s.split("/")
    if len(parts) == 2:
        try:
            float(parts[0])
            float(parts[1])
            return False
        except ValueError:
            pass
    return True


class Formula:
    """A formula in the caller's variables, checked once and evaluated vectorised with numpy.

    Parameters
    ----------
    text : str
        The formula, e.g. ``"20000 + 9500*sin(2*phi)"`` (angles in rad, SI units).
    variables : tuple of str
        The names it may use (default ``("phi",)``); each becomes a keyword of :meth:`__call__`.

    Raises
    ------
    InputError
        Text outside the grammar (the message names the token and its column), an unknown name,
        a wrong number of arguments, or a number too large for a float.

    Examples
    --------
    >>> g = Formula("-200 - 0.5*omega + 30*(phi < pi)", variables=("phi", "omega"))
    >>> g(phi=np.array([1.0, 4.0]), omega=10.0).tolist()
    [-175.0, -205.0]
    >>> sorted(Formula("sin(phi)**2").names)
    ['phi']
    >>> Formula("2^phi")
    Traceback (most recent call last):
        ...
    graphmethods.errors.InputError: formula '2^phi': '^' at column 2 is not allowed; write ** for a power
    """

    def __init__(self, text: str, *, variables: tuple[str, ...] = ("phi",)) -> None:
        if not isinstance(text, str):
            raise InputError(f"a formula is text, not {type(text).__name__}")
        self.text = text
        self.variables = tuple(variables)
        src = text.strip()
        for greek, latin in _ALIASES.items():
            src = src.replace(greek, latin)
        self._src = src
        if not src:
            raise InputError("the formula is empty; write e.g. 20000 + 9500*sin(2*phi)")
        if len(src) > MAX_LENGTH:
            raise InputError(f"the formula is {len(src)} characters long; at most {MAX_LENGTH} are accepted")
        try:
            tree = ast.parse(src, mode="eval")
        except SyntaxError as exc:
            col = f" at column {exc.offset}" if exc.offset else ""
            raise InputError(f"formula {text!r}: not a formula{col} ({exc.msg}); write e.g. "
                             f"20000 + 9500*sin(2*phi)") from None
        except (ValueError, MemoryError, RecursionError):
            raise InputError(f"formula {text!r}: cannot be read; write e.g. 20000 + 9500*sin(2*phi)") from None
        self.names: set[str] = set()
        self._fn = self._compile(tree.body, 0)

    # -- checking and compiling --------------------------------------------------------------
    def _fail(self, node: ast.AST, what: str) -> NoReturn:
        col = getattr(node, "col_offset", None)
        where = f" at column {col + 1}" if col is not None else ""
        raise InputError(f"formula {self.text!r}: {what.format(where=where)}")

    def _token(self, node: ast.AST) -> str:
        seg = ast.get_source_segment(self._src, node)
        return seg if seg else type(node).__name__

    def _compile(self, node: ast.expr, depth: int) -> _Fn:
        """The closure that evaluates ``node`` (checked against the grammar), ``depth`` levels down."""
        if depth > MAX_DEPTH:
            self._fail(node, f"nested deeper than {MAX_DEPTH} levels{{where}}; simplify it")
        d = depth + 1
        if isinstance(node, ast.Constant):
            if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
                self._fail(node, f"{self._token(node)!r}{{where}} is not a number")
            try:
                c = float(node.value)
            except OverflowError:
                self._fail(node, f"the number {self._token(node)[:20]}…{{where}} is too large")
            return lambda env: c
        if isinstance(node, ast.Name):
            name = node.id
            if name in self.variables:
                self.names.add(name)
                return lambda env: env[name]
            if name in CONSTANTS:
                c = CONSTANTS[name]
                return lambda env: c
            if name in FUNCTIONS:
                self._fail(node, f"{name!r}{{where}} is a function; call it, e.g. {name}(phi)")
            allowed = ", ".join(self.variables + tuple(CONSTANTS))
            self._fail(node, f"unknown name {name!r}{{where}}; use {allowed} or one of the functions (sin, cos, ...)")
        if isinstance(node, ast.UnaryOp):
            if isinstance(node.op, (ast.USub, ast.UAdd)):
                inner = self._compile(node.operand, d)
                if isinstance(node.op, ast.USub):
                    return lambda env: np.negative(inner(env))
                return inner
            self._refuse_op(node, node.op)
        if isinstance(node, ast.BinOp):
            op = _BINARY.get(type(node.op))
            if op is None:
                self._refuse_op(node, node.op)
            left, right = self._compile(node.left, d), self._compile(node.right, d)
            return lambda env: op(left(env), right(env))
        if isinstance(node, ast.Compare):
            parts = [self._compile(node.left, d)] + [self._compile(c, d) for c in node.comparators]
            ops: list[Callable[..., Any]] = []
            for o in node.ops:
                f = _COMPARE.get(type(o))
                if f is None:
                    self._refuse_op(node, o)
                ops.append(f)

            def compare(env: _Env) -> FloatArray:
                vals = [p(env) for p in parts]
                out = np.ones(np.broadcast(*[np.asarray(v) for v in vals]).shape, dtype=bool)
                for f, a, b in zip(ops, vals[:-1], vals[1:]):
                    out = out & f(a, b)
                result: FloatArray = out.astype(float)
                return result
            return compare
        if isinstance(node, ast.Call):
            if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
                name = self._token(node.func)
                self._fail(node, f"unknown function {name!r}{{where}}; use one of " + ", ".join(FUNCTIONS))
            if node.keywords:
                self._fail(node.keywords[0].value, "keyword arguments{where} are not allowed")
            fn, nargs = FUNCTIONS[node.func.id]
            if len(node.args) != nargs:
                self._fail(node, f"{node.func.id}(){{where}} takes {nargs} argument{'s' if nargs > 1 else ''}, "
                                 f"got {len(node.args)}")
            args = [self._compile(a, d) for a in node.args]
            if any(isinstance(a, ast.Starred) for a in node.args):  # pragma: no cover - caught by _compile
                self._fail(node, "*arguments{where} are not allowed")
            return lambda env: fn(*[a(env) for a in args])
        self._fail(node, f"{self._token(node)!r}{{where}} is not allowed in a formula "
                         f"(numbers, {', '.join(self.variables)}, pi, e, + - * / **, functions)")

    def _refuse_op(self, node: ast.expr, op: ast.AST) -> NoReturn:
        sym = _SYMBOL.get(type(op), type(op).__name__)
        hint = _HINT.get(sym, "use + - * / ** and the functions")
        # the column of the operator itself: search the source between the operands
        col = node.col_offset
        left = getattr(node, "left", None) or getattr(node, "operand", None)
        if isinstance(node, ast.BinOp) and left is not None and left.end_col_offset is not None:
            pos = self._src.find(sym, left.end_col_offset)
            col = pos if pos >= 0 else col
        raise InputError(f"formula {self.text!r}: {sym!r} at column {col + 1} is not allowed; {hint}")

    # -- evaluation ------------------------------------------------------------------------
    def __call__(self, **values: ArrayLike) -> FloatArray:
        """The formula's value for the given variables (floats or numpy arrays, broadcast).

        Raises
        ------
        InputError
            A variable is missing, or the value is not finite somewhere (the message names where).
        """
        env: _Env = {}
        for name in self.variables:
            if name in values:
                env[name] = np.asarray(values[name], dtype=float)
            elif name in self.names:
                raise InputError(f"formula {self.text!r} uses {name}, but no value was given for it")
        shape = np.broadcast(*env.values()).shape if env else ()
        with np.errstate(all="ignore"):
            out = np.asarray(self._fn(env), dtype=float)
        out = np.broadcast_to(out, shape) if out.shape != shape else out
        if not np.all(np.isfinite(out)):
            i = np.unravel_index(int(np.flatnonzero(~np.isfinite(out))[0]), out.shape) if out.ndim else ()
            at = ", ".join(f"{k} = {float(np.broadcast_to(v, shape)[i]):.6g}" for k, v in env.items())
            raise InputError(f"formula {self.text!r} is not finite ({float(out[i])!r}) at {at or 'every point'}; "
                             f"fix it there")
        return np.array(out, dtype=float)

    def __repr__(self) -> str:
        return f"Formula({self.text!r})"
