"""What enters the toolkit, in one place: numbers, counts, angles, text and JSON; and rev/min <-> rad/s.

The policy for every number that enters (problem files, answers files, the command line, the
public API) is here, and every reader calls it:

* a number is real and finite: ``True``/``False`` are not numbers, NaN and ±inf are refused, and
  so is an integer or a fraction too large for a float (a 400-digit integer);
* a single quantity (a speed, δ, a length, a mass, a scale) is zero or of magnitude between
  :data:`MAGNITUDE_MIN` = 1e-100 and :data:`MAGNITUDE_MAX` = 1e100 in its own unit (m, kg, rev/min,
  ...), so that the squares, products and quotients of a few of them that the methods form (ω²,
  m·v², ΔW/(ω²δ)) stay within the range of a float; then its physical range (δ between 0 and 1, a
  length > 0, ...) is checked by the caller through ``lo``/``hi``. The entries of a list (areas,
  works, levels, ordinates) are summed, never divided by: only their upper bound applies;
* an angle in degrees may be any finite number: it is reduced modulo 360 exactly
  (:func:`angle_deg`) before any trigonometry;
* a count (positions, variants) is a whole number within a named limit (:data:`MAX_POSITIONS`,
  :data:`MAX_VARIANTS`), checked before any work starts;
* results are checked finite before they are printed, drawn or written (:func:`finite_result`,
  :func:`json_text`, which writes JSON with ``allow_nan=False``);
* text is valid Unicode (a lone surrogate such as ``"\\ud800"`` is refused when read), and JSON nested
  deeper than the reader can follow is refused (:func:`json_value`).

Every refusal is an :class:`~graphmethods.errors.InputError` whose message names the value, the
rule and the limit.

>>> parse_number("1/300")
0.0033333333333333335
>>> round(omega_from_n(600.0), 4)
62.8319
>>> real("2.5", "l", unit="m", lo=0, lo_open=True)
2.5
>>> real(True, "delta")
Traceback (most recent call last):
...
graphmethods.errors.InputError: delta = True is a truth value, not a number; give a number such as 0.05
>>> angle_deg(1e20 + 30, "theta_deg") == math.fmod(1e20 + 30, 360.0)
True
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Iterable, Sequence
from fractions import Fraction
from numbers import Integral, Real
from typing import TYPE_CHECKING, Any, SupportsFloat, cast

from graphmethods.errors import InputError

if TYPE_CHECKING:                 # numpy is imported when an array is first made, not with the package
    import numpy as np
    from numpy.typing import NDArray

#: Smallest non-zero magnitude a number entering the toolkit may have, in its own unit.
MAGNITUDE_MIN = 1e-100
#: Largest magnitude a number entering the toolkit may have, in its own unit.
MAGNITUDE_MAX = 1e100
#: Most crank positions per turn a construction is computed for (textbooks use 8 to 48).
MAX_POSITIONS = 100_000
#: Most positions the kinematics core computes at once (the error estimate of the Wittenbauer diagram at
#: MAX_POSITIONS positions refines to 16 times as many).
MAX_POSITIONS_COMPUTED = 2**21
#: Most worksheet variants in one set (and the largest variant number of an id KIND:SEED:N).
MAX_VARIANTS = 1000
#: The coefficient of fluctuation δ lies in 0 < δ < DELTA_MAX everywhere (files, command line, API):
#: textbook values are 1/300 … 1/5, and δ ≥ 1 is no steady running.
DELTA_MAX = 1.0
#: Deepest nesting a JSON input may have (problem files are two levels deep).
MAX_JSON_DEPTH = 100
#: Largest file a reader takes (problem, answers, CSV, SVG, DXF), bytes: a drawing of a course sheet is a
#: few MB; checked before reading.
MAX_INPUT_BYTES = 64 * 1024 * 1024
#: A computed value below this share of its computation's scale is that computation's round-off: it is zero,
#: stored as 0 by the core (an inertia load at a dead centre) and written 0 on paper, never 4.8·10⁻³⁰.
ROUNDOFF = 1e-9


def _shown(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 40 else f"{text[:20]}…({len(text)} characters)"


def real(value: object, name: str, *, unit: str = "", lo: float | None = None, hi: float | None = None,
         lo_open: bool = False, hi_open: bool = False, hint: str = "", tiny_ok: bool = False) -> float:
    """A number entering the toolkit, checked by the policy above, as a float.

    (Over 80 lines only through this docstring, which documents every parameter; the code is 51 lines.)

    Parameters
    ----------
    value : int, float, numpy scalar or str
        The number; a string may be a decimal (``"5e-3"``) or a fraction (``"1/300"``).
    name : str
        What it is, for the message (``"--n"``, ``"press.json: key 'l'"``).
    unit : str
        Its unit, for the message.
    lo, hi : float, optional
        Physical bounds; ``lo_open``/``hi_open`` exclude the bound itself.
    hint : str
        What to do, appended to the message.
    tiny_ok : bool
        Only the upper bound 1e100 applies: for a quantity that is only ever a numerator or a
        term (ΔW_max, J_e), never a divisor.

    Raises
    ------
    InputError
        Not a number, not finite, beyond the magnitudes 1e-100 … 1e100, or outside ``lo``/``hi``.

    Examples
    --------
    >>> real(10**400, "n", unit="rev/min")
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: n = 10000000000000000000…(401 characters) rev/min is outside the magnitudes this toolkit computes with (zero, or 1e-100 to 1e+100); give it in a unit that brings it into that range
    """  # noqa: E501 - a doctest's expected output is one line
    tail = f"; {hint}" if hint else ""
    u = f" {unit}" if unit else ""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        raise InputError(f"{name} = {value!r} is a truth value, not a number{tail or '; give a number such as 0.05'}")
    tiny = False
    try:
        if isinstance(value, (Integral, Real)):
            v = float(value)
        elif isinstance(value, str):
            s = value.strip()
            if "/" in s:
                q = Fraction(s)
                v = float(q)
                tiny = q != 0 and v == 0.0
            else:
                v = float(s)
                if math.isinf(v) and "inf" not in s.lower():
                    raise OverflowError
        else:
            raise InputError(f"{name} must be a number, got {type(value).__name__} {_shown(value)}{tail}")
    except OverflowError:
        v, tiny = math.inf, False
        if not isinstance(value, str) or "inf" not in value.lower():
            raise InputError(f"{name} = {_shown(value)}{u} is outside the magnitudes this toolkit computes with "
                             f"(zero, or {MAGNITUDE_MIN:g} to {MAGNITUDE_MAX:g}); give it in a unit that brings it "
                             f"into that range") from None
    except (ValueError, ZeroDivisionError, TypeError):
        raise InputError(f"{name}: {_shown(value)} is not a number; write e.g. 0.05, 5e-2 or 1/20") from None
    if math.isnan(v):
        raise InputError(f"{name} must be finite, got {_shown(value)} (not finite: NaN){tail}")
    if math.isinf(v):
        raise InputError(f"{name} must be finite, got {_shown(value)} (not finite){tail}")
    if abs(v) > MAGNITUDE_MAX or (not tiny_ok and (tiny or (v != 0.0 and abs(v) < MAGNITUDE_MIN))):
        raise InputError(f"{name} = {_shown(value)}{u} is outside the magnitudes this toolkit computes with "
                         f"(zero, or {MAGNITUDE_MIN:g} to {MAGNITUDE_MAX:g}); give it in a unit that brings it "
                         f"into that range")
    low_bad = lo is not None and (v < lo or (lo_open and v == lo))
    high_bad = hi is not None and (v > hi or (hi_open and v == hi))
    if low_bad or high_bad:
        if lo is not None and hi is not None:
            rule = f"must lie between {lo:g} and {hi:g}" + (" (both excluded)" if lo_open and hi_open else "")
        elif lo == 0 and lo_open:
            rule = "must be positive"
        elif lo is not None:
            rule = f"must be {'>' if lo_open else '≥'} {lo:g}"
        else:
            rule = f"must be {'<' if hi_open else '≤'} {hi:g}"
        raise InputError(f"{name} = {_shown(value)}{u} {rule}{tail}")
    return v


def is_finite(value: object) -> bool:
    """``math.isfinite`` for any number a user may pass: an integer too large for a float (a 400-digit
    integer) is not finite here, where ``math.isfinite`` raises OverflowError.

    >>> is_finite(10**400), is_finite(2.5), is_finite(float("nan"))
    (False, True, False)
    """
    try:
        return math.isfinite(value)  # type: ignore[arg-type]
    except (OverflowError, TypeError, ValueError):
        return False


def angle_deg(value: object, name: str) -> float:
    """An angle in degrees, any finite number, reduced exactly modulo 360 (same sign as given).

    ``math.fmod`` of two floats is exact, so 1e20 + 30 degrees gives the angle the float 1e20 + 30
    stands for, not whatever ``radians(1e20)`` rounds to.

    >>> angle_deg(720.5, "theta_O3_deg"), angle_deg(-90, "theta_O3_deg")
    (0.5, -90.0)
    """
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        raise InputError(f"{name} = {value!r} is a truth value, not an angle; give degrees, e.g. -90")
    if isinstance(value, Integral) and not isinstance(value, bool):
        return float(int(value) % 360) if abs(int(value)) > 2**53 else math.fmod(float(value), 360.0)
    v = real(value, name, unit="°") if not isinstance(value, Real) else float(value)
    if not math.isfinite(v):
        raise InputError(f"{name} = {value!r} is not finite; give an angle in degrees")
    return math.fmod(v, 360.0)


def count(value: object, name: str, *, low: int, high: int, why: str = "") -> int:
    """A whole number ``low ≤ value ≤ high`` (positions, variants), checked before any work starts.

    >>> count(12, "--positions", low=3, high=MAX_POSITIONS)
    12
    >>> count(12.7, "positions", low=3, high=MAX_POSITIONS)
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: positions = 12.7 must be an integer ≥ 3 and ≤ 100000
    """
    limit = f"an integer ≥ {low} and ≤ {high}" + (f" ({why})" if why else "")
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        raise InputError(f"{name} = {value!r} must be {limit}")
    if isinstance(value, str):
        s = value.strip()
        if not (s.lstrip("+-").isdigit() and s.isascii()) or len(s) > 30:     # "²" is a digit, no number
            raise InputError(f"{name} = {_shown(value)} must be {limit}")
        value = int(s)
    if isinstance(value, Integral):
        n = int(value)
    elif isinstance(value, Real) and math.isfinite(float(value)) and float(value).is_integer():
        n = int(float(value))
    else:
        raise InputError(f"{name} = {_shown(value)} must be {limit}")
    if n < low:
        raise InputError(f"{name} = {n} must be at least {low}: {limit}")
    if n > high:
        raise InputError(f"{name} = {_shown(n)} is above the limit {high}: it must be {limit}")
    return n


def finite_result(value: SupportsFloat, name: str, *, unit: str = "", why: str = "") -> float:
    """A computed result, refused when it came out infinite or NaN (an overflow the data caused).

    >>> finite_result(1e300 * 1e10, "J_F", unit="kg·m²")
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: J_F came out inf kg·m²: the data lie outside the range this method can compute; give values of less extreme magnitude
    """  # noqa: E501 - a doctest's expected output is one line
    v = float(value)
    if not math.isfinite(v):
        u = f" {unit}" if unit else ""
        raise InputError(f"{name} came out {v}{u}: " + (why or "the data lie outside the range this method can "
                                                         "compute; give values of less extreme magnitude"))
    return v


def first_nonfinite(obj: object, path: str = "") -> str | None:
    """Where the first infinite or NaN number is in nested dicts, lists and arrays, or None.

    >>> first_nonfinite({"a": [1.0, float("nan")]}), first_nonfinite({"a": 1})
    ('a[1]', None)
    """
    stack: list[tuple[str, Any]] = [(path, obj)]          # (where, a part of any nested data)
    while stack:
        where, x = stack.pop()
        if isinstance(x, float) or (type(x).__module__ == "numpy" and hasattr(x, "dtype") and x.ndim == 0):
            try:
                if not math.isfinite(float(x)):
                    return where or "the value"
            except (TypeError, ValueError):
                pass
        elif isinstance(x, dict):
            stack.extend(reversed([(f"{where}.{k}" if where else str(k), v) for k, v in x.items()]))
        elif isinstance(x, (list, tuple)) or (hasattr(x, "tolist") and not isinstance(x, (str, bytes))):
            items = x.tolist() if hasattr(x, "tolist") else x
            if isinstance(items, list) and all(type(v) is float or type(v) is int for v in items):
                k = next((i for i, v in enumerate(items) if type(v) is float and not math.isfinite(v)), None)
                if k is not None:
                    return f"{where}[{k}]"
                continue                                  # a flat list of numbers: checked at once
            if not isinstance(items, list):
                items = [items]
            stack.extend(reversed([(f"{where}[{i}]", v) for i, v in enumerate(items)]))
    return None


def check_finite(obj: object) -> None:
    """Refuse a result holding an infinity or NaN anywhere (nested dicts, lists, arrays), naming its key.

    >>> check_finite({"E": [0.0, 1.0]})
    >>> check_finite({"E": [0.0, float("nan")]})
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: E[1] came out nan: the data lie outside the range this method can compute; give values of less extreme magnitude
    """  # noqa: E501 - a doctest's expected output is one line
    where = first_nonfinite(obj)
    if where is not None:
        bad: Any = obj                                       # walks down any nested data to the bad number
        try:
            for part in where.replace("[", ".[").split("."):
                bad = bad[int(part[1:-1])] if part.startswith("[") else bad[part]
        except (KeyError, IndexError, TypeError, ValueError):
            bad = float("nan")
        finite_result(bad, where)


def json_text(obj: object, **kwargs: Any) -> str:
    """``json.dumps`` with ``allow_nan=False``: a result holding an infinity or NaN is refused with
    the key named (:func:`check_finite`), never written as ``Infinity`` (which is not JSON).

    >>> json_text({"J_F": 1.5})
    '{"J_F": 1.5}'
    >>> json_text({"J_F": float("inf")})
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: J_F came out inf: the data lie outside the range this method can compute; give values of less extreme magnitude
    """  # noqa: E501 - a doctest's expected output is one line
    check_finite(obj)
    return json.dumps(obj, allow_nan=False, **kwargs)


def check_text(value: str, name: str) -> str:
    """Text that can be written out: a lone surrogate (``"\\ud800"``, half of a UTF-16 pair) is refused.

    >>> check_text("пресс", "name")
    'пресс'
    """
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as exc:
        bad = value[exc.start]
        if "\udc80" <= bad <= "\udcff":     # a byte of a command line or file name that is not UTF-8
            raise InputError(f"{name}: the text holds the byte 0x{ord(bad) - 0xDC00:02x}, which is not UTF-8 (at "
                             f"position {exc.start}); write it in UTF-8") from None
        raise InputError(f"{name}: the text holds {bad!a}, half of a UTF-16 surrogate pair and not a character "
                         f"(at position {exc.start}); write the character itself") from None
    return value


def input_file(path: str | os.PathLike[str], *, missing: str = "no such file", prefix: str = "",
               limit: int | None = None) -> int:
    """Check a user's file before anything reads it: it exists, is a regular file (not ``/dev/zero``, a FIFO,
    a socket or a folder) and holds at most ``limit`` bytes (default :data:`MAX_INPUT_BYTES`); its size.

    >>> input_file("/dev/zero")
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: /dev/zero: not a regular file (a device, a pipe or a folder); give a file
    """
    import pathlib
    import stat

    p = pathlib.Path(path)
    cap = MAX_INPUT_BYTES if limit is None else limit
    try:
        st = os.stat(p)
    except FileNotFoundError:
        raise InputError(f"{prefix}{p}: {missing}") from None
    except (OSError, ValueError) as exc:
        raise InputError(f"{prefix}{p}: cannot read it ({exc.__class__.__name__}: {exc})") from None
    if not stat.S_ISREG(st.st_mode):
        raise InputError(f"{prefix}{p}: not a regular file (a device, a pipe or a folder); give a file")
    if st.st_size > cap:
        raise InputError(f"{prefix}{p}: {st.st_size} bytes, more than the {cap} bytes an input file may hold "
                         f"(MAX_INPUT_BYTES)")
    return int(st.st_size)


def read_bytes(path: str | os.PathLike[str], *, missing: str = "no such file", prefix: str = "",
               limit: int | None = None) -> bytes:
    """The bytes of a user's file, read only after :func:`input_file` has passed it, and never more than
    ``limit`` bytes (a file that grows while read is refused too).

    >>> read_bytes("/no/such/drawing.svg", missing="no such drawing")
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: /no/such/drawing.svg: no such drawing
    """
    cap = MAX_INPUT_BYTES if limit is None else limit
    input_file(path, missing=missing, prefix=prefix, limit=cap)
    try:
        with open(path, "rb") as fh:
            data = fh.read(cap + 1)
    except FileNotFoundError:
        raise InputError(f"{prefix}{path}: {missing}") from None
    except (OSError, ValueError) as exc:
        raise InputError(f"{prefix}{path}: cannot read it ({exc.__class__.__name__}: {exc})") from None
    if len(data) > cap:
        raise InputError(f"{prefix}{path}: more than the {cap} bytes an input file may hold (MAX_INPUT_BYTES)")
    return data


def read_text(path: str | os.PathLike[str], *, missing: str = "no such file", prefix: str = "") -> str:
    """The UTF-8 text of a user's file (a byte-order mark, as Excel and Notepad write it, dropped), or one
    :class:`InputError` line: ``{prefix}{path}: {missing}`` when it does not exist, ``{prefix}{path}: cannot
    read it (...)`` when it cannot be read, a refusal when it is no regular file or too large
    (:func:`read_bytes`).

    >>> read_text("/no/such/answers.toml", missing="no such answers file")
    Traceback (most recent call last):
    ...
    graphmethods.errors.InputError: /no/such/answers.toml: no such answers file
    """
    data = read_bytes(path, missing=missing, prefix=prefix)
    try:
        return data.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as exc:
        raise InputError(f"{prefix}{path}: not UTF-8 text (byte {exc.start}: {data[exc.start:exc.start + 1]!r}); "
                         f"save it as UTF-8") from None


def json_value(text: str, source: str) -> Any:
    """Parse JSON text entering the toolkit: nesting deeper than :data:`MAX_JSON_DEPTH` and text that is
    not valid Unicode are refused with one line naming ``source``.

    >>> json_value('{"r": 0.1}', "case.json")
    {'r': 0.1}
    """
    depth = level = 0
    in_string = escaped = False
    for ch in text:                      # the depth without recursion (json.loads would recurse)
        if in_string:
            if escaped:
                escaped = False
            elif ch == "\\":
                escaped = True
            elif ch == '"':
                in_string = False
        elif ch == '"':
            in_string = True
        elif ch in "[{":
            level += 1
            depth = max(depth, level)
            if depth > MAX_JSON_DEPTH:
                raise InputError(f"{source}: JSON nested more than {MAX_JSON_DEPTH} levels deep; a problem file is "
                                 f"one object of numbers and text")
        elif ch in "]}":
            level -= 1
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"{source}: not valid JSON (line {exc.lineno}, column {exc.colno}: {exc.msg})") from None
    except (ValueError, RecursionError) as exc:   # e.g. an integer of more than 4300 digits
        raise InputError(f"{source}: not usable JSON ({exc})") from None
    stack = [("", data)]
    while stack:
        where, x = stack.pop()
        if isinstance(x, str):
            check_text(x, f"{source}: {where or 'text'}")
        elif isinstance(x, dict):
            for k, v in x.items():
                check_text(k, f"{source}: a key")
                stack.append((f"key {k!r}" if not where else f"{where}.{k}", v))
        elif isinstance(x, list):
            stack.extend((f"{where}[{i}]", v) for i, v in enumerate(x))
    return data


def parse_number(text: str | float | int, *, name: str = "value") -> float:
    """Parse a finite number given as ``"0.05"``, ``"1/300"``, ``"5e-3"`` or a float.

    Raises
    ------
    InputError
        If the text is not a number or fraction, is NaN or infinite, or is beyond the
        magnitudes 1e-100 … 1e100 (see :func:`real`).
    """
    return real(text, name)


def omega_from_n(n_rpm: float) -> float:
    """Angular speed in rad/s from a speed in rev/min: ω = π n / 30."""
    return math.pi * n_rpm / 30.0


def n_from_omega(omega: float) -> float:
    """Speed in rev/min from an angular speed in rad/s: n = 30 ω / π."""
    return 30.0 * omega / math.pi


#: Convenient drawing numbers, × 10^k (domain.md §1); some textbooks also allow 1.5 and 3.
CONVENIENT = (1.0, 2.0, 2.5, 4.0, 5.0)
CONVENIENT_WIDE = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0)


def _candidates(value: float, series: Sequence[float]) -> list[float]:
    if not (value > 0 and math.isfinite(value)):
        raise InputError(f"a convenient number needs a positive finite value, got {value!r}")
    k = math.floor(math.log10(value))
    # written as decimal literals, so 2.5e-2 is the float nearest 0.025 (not 2.5 × 0.01)
    return sorted(float(f"{float(c)!r}e{kk}") for kk in (k - 1, k, k + 1) for c in series)


def convenient_at_least(value: float, series: Sequence[float] = CONVENIENT) -> float:
    """The smallest convenient number (1, 2, 2.5, 4, 5 × 10^k) not below ``value``.

    >>> convenient_at_least(37.0), convenient_at_least(0.0042), convenient_at_least(2.0)
    (40.0, 0.005, 2.0)
    """
    return next(v for v in _candidates(value, series) if v >= value * (1 - 1e-12))


def convenient_at_most(value: float, series: Sequence[float] = CONVENIENT) -> float:
    """The largest convenient number (1, 2, 2.5, 4, 5 × 10^k) not above ``value``.

    >>> convenient_at_most(37.0), convenient_at_most(0.0042), convenient_at_most(2.5)
    (25.0, 0.004, 2.5)
    """
    return max(v for v in _candidates(value, series) if v <= value * (1 + 1e-12))


def finite_array(values: object, name: str) -> NDArray[np.float64]:
    """A flat, read-only float array of finite numbers, or an InputError naming the first bad entry.

    >>> finite_array([1, 2.5], "areas").tolist()
    [1.0, 2.5]
    """
    import numpy as np

    if isinstance(values, (str, bytes)) or (not hasattr(values, "__len__") and not hasattr(values, "__iter__")):
        raise InputError(f"{name}: expected a list of numbers, got {_shown(values)}")
    if not isinstance(values, np.ndarray):
        # cast: an iterable (checked above); its entries are checked one by one below
        values = list(cast(Iterable[Any], values))
        for i, x in enumerate(values):
            t = type(x)
            if t is float or (t is int and -(10**100) <= x <= 10**100):
                continue
            if t is int:
                values[i] = real(x, f"{name}[{i}]")      # a 400-digit integer: refused with its name
            if isinstance(x, (list, tuple, dict, set)) or (hasattr(x, "__len__") and not isinstance(x, str)):
                raise InputError(f"{name}[{i}]: expected a flat list of numbers, got {_shown(x)}")
            values[i] = real(x, f"{name}[{i}]")
    elif values.dtype == bool:
        raise InputError(f"{name}: expected numbers, got truth values")
    try:
        arr = np.array(values, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise InputError(f"{name}: expected a list of numbers, got {_shown(values)}") from None
    if arr.ndim > 1:
        raise InputError(f"{name}: expected a flat list of numbers, got shape {arr.shape}")
    arr = arr.reshape(-1)
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise InputError(f"{name}[{i}] = {arr[i]!r} is not a finite number; remove or fix it")
    # a list's entries are summed and drawn, never divided by: only the upper bound applies (a tiny
    # entry, e.g. a round-off residue, adds as nothing)
    big = np.abs(arr) > MAGNITUDE_MAX
    if big.any():
        i = int(np.flatnonzero(big)[0])
        real(float(arr[i]), f"{name}[{i}]")
    arr.setflags(write=False)
    return arr
