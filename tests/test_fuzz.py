"""Fuzzing what enters the toolkit (issue 14): problem files, answers files, the flywheel and
kinematics command lines, the public API, and the writing of file sets.

Every input must give either a clean refusal (exit 2 and one line on stderr, or an error of our
own type at the API) or a finite result; never a traceback, a hang, a NaN/infinity in the output,
or a partial set of files. The normal run is fast (well under a minute); the longer run is marked
``fuzz_long`` and skipped unless asked for::

    python -m pytest -p no:cacheprovider -m fuzz_long tests/test_fuzz.py

Set ``GRAPHMETHODS_FUZZ_REPORT=FILE`` to append the counts (inputs, clean errors, results,
tracebacks, non-finite, hangs, partial sets) of each test to FILE as JSON lines.
"""

from __future__ import annotations

import collections
import contextlib
import errno
import io
import json
import math
import os
import pathlib
import re
import signal

import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings, strategies as st

from graphmethods import cli
from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import check_delta, fluctuation, flywheel, mean_speed, transfer
from graphmethods.errors import GraphmethodsError, OutputError
from graphmethods.kinematics import case_from_dict
from graphmethods.render.files import write_set
from graphmethods.sheets.check import validate_answers
from graphmethods.units import count, real

DATA = pathlib.Path(__file__).resolve().parents[1] / "graphmethods" / "problems" / "data"
# every shipped problem file: the group form, the cams and the drawn form (drawn/NAME), mutated alike
CASES = {str(p.relative_to(DATA).with_suffix("")): json.loads(p.read_text(encoding="utf-8"))
         for p in sorted(DATA.glob("*.json")) + sorted((DATA / "drawn").glob("*.json"))}
# A call that uses more than HANG_S seconds of this process's CPU time hangs. CPU time, not wall time: on a
# machine shared by other runs a fast answer can take many times longer by the clock. HANG_WALL_S is the
# clock's backstop, for a call that waits instead of computing.
HANG_S = 20
HANG_WALL_S = 300
# no "explain" phase: its line tracing slows every call tenfold and would pass for a hang
PHASES = [Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink]
FAST = settings(deadline=None, max_examples=int(os.environ.get("GRAPHMETHODS_FUZZ_EXAMPLES", "60")), phases=PHASES,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
LONG = settings(deadline=None, max_examples=int(os.environ.get("GRAPHMETHODS_FUZZ_LONG_EXAMPLES", "1500")),
                phases=PHASES, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])

COUNTS: dict[str, collections.Counter] = collections.defaultdict(collections.Counter)
CURRENT = ["?"]          # the test whose inputs are being counted


@pytest.fixture(autouse=True)
def _report_counts(request):
    CURRENT[0] = request.node.name
    yield
    path = os.environ.get("GRAPHMETHODS_FUZZ_REPORT")
    c = COUNTS.pop(request.node.name, None)
    if path and c:
        with open(path, "a", encoding="utf-8") as fh:
            fh.write(json.dumps({"test": request.node.name, **c}) + "\n")


class Hang(Exception):
    pass


@contextlib.contextmanager
def time_limit(seconds: float, wall_seconds: float = HANG_WALL_S):
    """Raise :class:`Hang` after ``seconds`` of the process's CPU time (SIGPROF) or ``wall_seconds`` by the clock."""
    def on_cpu(*_):
        raise Hang(f"no answer within {seconds} s of CPU time")

    def on_wall(*_):
        raise Hang(f"no answer within {wall_seconds} s")
    old_cpu, old_wall = signal.signal(signal.SIGPROF, on_cpu), signal.signal(signal.SIGALRM, on_wall)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    signal.setitimer(signal.ITIMER_REAL, wall_seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGPROF, old_cpu)
        signal.signal(signal.SIGALRM, old_wall)


def test_the_time_limit_counts_cpu_time_not_waiting():
    """A busy loop is stopped by CPU time; sleeping (what a loaded machine looks like to a call) is not counted."""
    import time

    with time_limit(0.2):
        time.sleep(0.4)
    with pytest.raises(Hang, match="CPU time"), time_limit(0.2):
        while True:
            pass


def _no_constant(name):
    raise AssertionError(f"non-finite number {name} in JSON output")


NONFINITE_WORD = re.compile(r"(?<![\w.])[-+]?(inf|nan|Infinity|NaN)(?![\w])")


def run_cli(test: str, argv: list[str], *, json_out: bool = False, ok_codes: tuple[int, ...] = (0, 1)) -> int:
    """Run the command in-process and check the contract; count the outcome under ``test``."""
    c = COUNTS[CURRENT[0]]
    c["inputs"] += 1
    out, err = io.StringIO(), io.StringIO()
    try:
        with time_limit(HANG_S), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                code = cli.main([str(a) for a in argv])
            except SystemExit as exc:                 # argparse refusals
                code = exc.code
    except Hang:
        c["hangs"] += 1
        raise AssertionError(f"hang: {argv}") from None
    except BaseException as exc:
        c["tracebacks"] += 1
        raise AssertionError(f"traceback {type(exc).__name__}: {exc} for {argv}") from exc
    o, e = out.getvalue(), err.getvalue()
    if code == 2:
        assert o == "" and e.count("\n") == 1 and "Traceback" not in e, (argv, o, e)
        assert e.startswith("graphmethods"), e
        c["clean_errors"] += 1
        return code
    assert code in ok_codes, (code, argv, e)
    if json_out and code == 0:
        try:
            json.loads(o, parse_constant=_no_constant)
        except AssertionError:
            c["nonfinite"] += 1
            raise
    elif NONFINITE_WORD.search(o):
        c["nonfinite"] += 1
        raise AssertionError(f"non-finite number printed for {argv}:\n{o[:2000]}")
    c["results"] += 1
    return code


def call_api(test: str, fn, *args, **kwargs):
    """Call the API: an error of our own type, or a result whose numbers are all finite."""
    c = COUNTS[CURRENT[0]]
    c["inputs"] += 1
    try:
        with time_limit(HANG_S):
            res = fn(*args, **kwargs)
    except GraphmethodsError as exc:
        assert str(exc) and "\n" not in str(exc), repr(exc)
        c["clean_errors"] += 1
        return None
    except Hang:
        c["hangs"] += 1
        raise AssertionError(f"hang: {fn.__name__}{args}{kwargs}") from None
    except BaseException as exc:
        c["tracebacks"] += 1
        raise AssertionError(f"{type(exc).__name__}: {exc} from {fn.__name__}{args}{kwargs}") from exc
    if not _all_finite(res):
        c["nonfinite"] += 1
        raise AssertionError(f"non-finite result {res!r} from {fn.__name__}{args}{kwargs}")
    c["results"] += 1
    return res


def _all_finite(x) -> bool:
    import numpy as np

    if isinstance(x, float):
        return math.isfinite(x)
    if isinstance(x, np.ndarray):
        return x.dtype.kind not in "fc" or bool(np.isfinite(x).all())
    if isinstance(x, dict):
        return all(_all_finite(v) for v in x.values())
    if isinstance(x, (list, tuple)):
        return all(_all_finite(v) for v in x)
    if hasattr(x, "to_dict"):
        return _all_finite(x.to_dict())
    if hasattr(x, "__dataclass_fields__"):
        return all(_all_finite(getattr(x, f)) for f in x.__dataclass_fields__)
    return True


# ----------------------------------------------------------------------------- hostile values

def plausible(lo: float, hi: float):
    """A number a user would type for a quantity of that range, as text."""
    return st.one_of(st.floats(min_value=lo, max_value=hi).map(lambda x: f"{x:.5g}"),
                     st.integers(min_value=max(1, int(lo)), max_value=max(1, int(hi))).map(str))


def typed(lo: float, hi: float):
    """Mostly plausible, sometimes hostile: most inputs get past the first check."""
    return st.one_of(plausible(lo, hi), plausible(lo, hi), plausible(lo, hi), number_texts())


def positions_text():
    return st.one_of(st.integers(min_value=-5, max_value=200).map(str),
                     st.sampled_from(["12", "100001", "99999999999999999999", "1e3", "12.5", "", "x"]))

def number_texts():
    """What a user types for a number: decimals, fractions, extremes, garbage."""
    return st.one_of(
        st.floats(allow_nan=True, allow_infinity=True).map(repr),
        st.floats(min_value=1e-6, max_value=1e6).map(lambda x: f"{x:.6g}"),
        st.integers(min_value=-10**30, max_value=10**30).map(str),
        st.sampled_from(["1/300", "1/0", "0/0", "1e-320", "1e308", "-1e308", "1e400", "1" + "0" * 400, "1/" + "3" * 400,
                         "nan", "inf", "-inf", "", " ", "abc", "0x10", "1_000", "١٢", "1e", "--5", "½", "0", "-0",
                         "99999999999999999999", "1e-200", "5e-3"]),
        st.text(max_size=8),
    )


def hostile_json_values():
    return st.one_of(
        st.floats(allow_nan=False, allow_infinity=False),
        st.floats(min_value=-1e6, max_value=1e6),
        st.integers(min_value=-10**400, max_value=10**400),
        st.sampled_from([0, 1, -1, 1e-320, 1e308, -1e308, 1e200, 1e-200, 1e20, 1e15, True, False, None, "", "1/300",
                         "abc", "\ud800", [], {}, ["four_bar"], [1, 2], {"en": "x"}, 10**400, "1e400", "nan"]),
        st.text(max_size=6),
        st.lists(st.floats(allow_nan=False), max_size=3),
    )


# ----------------------------------------------------------------------------- problem files

def mutated_case(data, base):
    name = data.draw(st.sampled_from(sorted(CASES)))
    case = dict(CASES[name])
    keys = sorted(case)
    for _ in range(data.draw(st.integers(min_value=0, max_value=2))):
        action = data.draw(st.sampled_from(["set", "scale", "scale", "scale", "delete", "add"]))
        key = data.draw(st.sampled_from(keys + ["kind", "name", "n_rpm", "delta", "ground_angle_deg",
                                                "theta_O3_deg", "assembly", "sense"]))
        if action == "set":
            case[key] = data.draw(hostile_json_values())
        elif action == "scale" and isinstance(case.get(key), (int, float)) and not isinstance(case.get(key), bool):
            factor = data.draw(st.sampled_from([0, -1, 1e-100, 1e-30, 1e-8, 1e8, 1e30, 1e99, 1e100, 1.0000001, 10.0,
                                                0.1]))
            try:
                case[key] = case[key] * factor
            except OverflowError:            # a 400-digit integer set before: keep it as it is
                pass
        elif action == "delete":
            case.pop(key, None)
        else:
            case[data.draw(st.text(min_size=1, max_size=5))] = data.draw(hostile_json_values())
    return case


def _write_case(tmp_path, case) -> pathlib.Path:
    p = tmp_path / "case.json"
    try:
        text = json.dumps(case)
    except ValueError:
        text = "{}"
    p.write_text(text, encoding="utf-8")
    return p


@FAST
@given(data=st.data())
def test_fuzz_problem_files_through_kinematics_cli(tmp_path, data):
    case = mutated_case(data, CASES)
    p = _write_case(tmp_path, case)
    m = data.draw(positions_text())
    run_cli("test_fuzz_problem_files_through_kinematics_cli", ["kinematics", p, "--positions", m, "--json"],
            json_out=True)


@FAST
@given(data=st.data())
def test_fuzz_problem_files_raw_text(tmp_path, data):
    text = data.draw(st.one_of(
        st.text(max_size=60),
        st.sampled_from(["[" * 5000 + "]" * 5000, "{" * 50, '{"r": ' + "9" * 5000 + "}", '{"name": "\\ud800"}',
                         '{"kind": ["four_bar"]}', "\ufeff{}", "null", "[]", '"x"', "1e400"]),
        st.builds(lambda c: json.dumps(c)[: len(json.dumps(c)) // 2], st.sampled_from(list(CASES.values()))),
    ))
    p = tmp_path / "case.json"
    p.write_bytes(text.encode("utf-8", "surrogatepass"))
    run_cli("test_fuzz_problem_files_raw_text", ["kinematics", p, "--json"], json_out=True)


@FAST
@given(data=st.data())
def test_fuzz_problem_files_through_the_api(data):
    case = mutated_case(data, CASES)

    def solve(c):
        cs = case_from_dict(c)
        pos = cs.mechanism.positions(m=8)
        plan = cs.mechanism.velocity_plans(pos, omega_1=cs.omega_m)
        return [plan.v(n) for n in plan.vectors]

    call_api("test_fuzz_problem_files_through_the_api", solve, case)


# ----------------------------------------------------------------------------- answers files

ANSWER_KEYS = ["mu_E", "step_mm", "arrows_mm", "origin_mm", "omega_m", "omega_max", "omega_min", "J_F", "delta_W_max",
               "omega_max_at", "omega_min_at", "M_d", "works_J"]


def toml_value():
    return st.one_of(
        number_texts().filter(lambda s: re.fullmatch(r"[-+]?(\d[\d_]*(\.\d+)?([eE][-+]?\d+)?|inf|nan)", s) is not None),
        st.sampled_from(['"abc"', '"12.5"', "[]", "[[1.0], 2.0]", "[1, 2, 3]", "true", '"b"', '["b", "e"]', "[0, 6]",
                         "0", "-5", "1e-320", "1" + "0" * 400, "12.7", "{a = 1}", '"\\ud800"', "[[[[1]]]]"]),
    )


@FAST
@given(data=st.data())
def test_fuzz_answers_files_through_check_cli(tmp_path, data):
    base = {"energy_indicator": {"mu_E": "5.0", "arrows_mm": "[10.0, -110.0, 20.0, -25.0, 100.0, -5.0, 10.0]"},
            "results": {}}
    for _ in range(data.draw(st.integers(min_value=1, max_value=3))):
        key = data.draw(st.sampled_from(ANSWER_KEYS))
        sec = "energy_indicator" if key in ("mu_E", "step_mm", "arrows_mm", "origin_mm") else "results"
        base[sec][key] = data.draw(toml_value())
    text = "".join(f"[{sec}]\n" + "".join(f"{k} = {v}\n" for k, v in kv.items()) for sec, kv in base.items())
    p = tmp_path / "answers.toml"
    p.write_text(text, encoding="utf-8", errors="surrogatepass") if False else p.write_bytes(
        text.encode("utf-8", "surrogatepass"))
    argv = ["check", data.draw(st.sampled_from(["W1", "W2", "indicator:7:3", "indicator:7:99999999999999999999"])), p]
    if data.draw(st.booleans()):
        argv += ["--overlay", tmp_path / "overlay.svg", "--force"]
    run_cli("test_fuzz_answers_files_through_check_cli", argv)


@FAST
@given(data=st.data())
def test_fuzz_answers_dicts_through_the_reader(data):
    values = st.one_of(hostile_json_values(), st.lists(hostile_json_values(), max_size=4),
                       st.lists(st.lists(st.floats(), max_size=2), max_size=2))
    answers = {data.draw(st.sampled_from(["energy_indicator", "results", "energy_mass", "velocity_plan",
                                          "moment_diagram", "page"])):
               data.draw(st.dictionaries(st.sampled_from(ANSWER_KEYS + ["positions", "position", "mu_T", "size"]),
                                         values, max_size=4))}
    call_api("test_fuzz_answers_dicts_through_the_reader", validate_answers, answers)


# ----------------------------------------------------------------------------- the flywheel command

@FAST
@given(data=st.data())
def test_fuzz_flywheel_cli(data):
    n = data.draw(st.integers(min_value=1, max_value=8))
    closing = st.lists(st.floats(min_value=-1e4, max_value=1e4), min_size=1, max_size=n).map(
        lambda xs: [f"{x:.6g}" for x in xs] + [f"{-sum(float(f'{x:.6g}') for x in xs):.6g}"])
    areas = data.draw(st.one_of(closing, closing, closing, st.lists(number_texts(), min_size=1, max_size=n),
                                st.lists(st.sampled_from(["1e99", "-1e99", "1e-99", "5", "-5"]), min_size=2,
                                         max_size=6)))
    levels = data.draw(st.booleans())
    if levels and areas:
        areas = areas + [areas[0]]          # levels return to the first one
    argv = ["flywheel", "--levels" if levels else "--areas", *areas]
    if data.draw(st.booleans()) and (not levels or data.draw(st.booleans())):   # scales belong to areas
        argv += ["--mu-M", data.draw(typed(0.01, 1000)), "--mu-phi-deg", data.draw(typed(0.1, 10))]
    argv += ["--n" if data.draw(st.booleans()) else "--omega", data.draw(typed(1, 3000))]
    argv += ["--delta" if data.draw(st.booleans()) else "--J", data.draw(typed(0.001, 0.5) | typed(0.1, 1e4))]
    if data.draw(st.booleans()):
        argv += ["--J-e", data.draw(typed(0, 10))]
    if data.draw(st.booleans()):
        argv += ["--closure-tol", data.draw(typed(0, 0.2))]
    json_out = data.draw(st.booleans())
    run_cli("test_fuzz_flywheel_cli", argv + (["--json"] if json_out else []), json_out=json_out)


@FAST
@given(data=st.data())
def test_fuzz_kinematics_cli_options(tmp_path, data):
    case = data.draw(st.sampled_from(sorted(CASES)))
    positions = data.draw(positions_text() | number_texts())
    # a valid count in the thousands is no bad input, only a long table (10⁵ positions: 150 MB of JSON,
    # half a minute): such runs are the bench's business, not a hang
    assume(not (re.fullmatch(r"\d+(\.0+)?", positions.strip()) and 5000 < float(positions) <= 100_000))
    argv = ["kinematics", DATA / f"{case}.json", "--positions", positions]
    if data.draw(st.booleans()):
        argv += ["--json"]
    run_cli("test_fuzz_kinematics_cli_options", argv, json_out="--json" in argv)


# ----------------------------------------------------------------------------- the public API

def api_numbers():
    return st.one_of(
        st.floats(allow_nan=True, allow_infinity=True),
        st.integers(min_value=-10**400, max_value=10**400),
        st.sampled_from([True, False, None, "1/300", "abc", 0, 1e-320, 1e308, [1.0], {"a": 1}]),
        st.floats(min_value=1e-3, max_value=1e3),
    )


@FAST
@given(dW=api_numbers(), delta=api_numbers(), n=api_numbers(), J_e=api_numbers(), J=api_numbers())
def test_fuzz_flywheel_api(dW, delta, n, J_e, J):
    t = "test_fuzz_flywheel_api"
    call_api(t, flywheel, dW, delta=delta, n_rpm=n, J_e=J_e)
    call_api(t, flywheel, dW, delta=delta, omega_m=n)
    call_api(t, fluctuation, dW, J=J, n_rpm=n)
    call_api(t, mean_speed, n_rpm=n)
    call_api(t, check_delta, delta)
    call_api(t, transfer, J, omega_from=n, omega_to=delta)
    call_api(t, real, n, "x")
    call_api(t, count, n, "m", low=3, high=1000)


@FAST
@given(values=st.one_of(st.lists(api_numbers(), max_size=6), st.lists(st.floats(), max_size=6), api_numbers()),
       mu=api_numbers(), tol=api_numbers())
def test_fuzz_excess_work_api(values, mu, tol):
    t = "test_fuzz_excess_work_api"
    for fn in (ew.from_work, ew.from_levels):
        res = call_api(t, fn, values)
        if res is not None:
            call_api(t, lambda r: (r.to_text(), r.to_dict(), r.delta_W_max), res)
    call_api(t, ew.from_areas, values, mu_M=mu, mu_phi_deg=mu)
    call_api(t, ew.from_work, values, closure_tol=tol)


# ----------------------------------------------------------------------------- sets of files

@FAST
@given(data=st.data())
def test_fuzz_sets_are_replaced_whole(tmp_path_factory, data):
    """A set replaced with --force: whatever rename fails (an OS error or an interrupt), the folder
    holds the old set or the new one, and no temporary folder is left."""
    c = COUNTS[CURRENT[0]]
    c["inputs"] += 1
    root = tmp_path_factory.mktemp("set")
    out = root / "out"
    names = st.sampled_from(["a.svg", "b.pdf", "svg/c.svg", "svg/d.svg", "problems/e.json"])
    old = data.draw(st.dictionaries(names, st.binary(max_size=5), min_size=1, max_size=5))
    new = data.draw(st.dictionaries(names, st.binary(max_size=5), min_size=1, max_size=5))
    write_set(out, old)
    stale = [n for n in old if n not in new]
    fail_at = data.draw(st.integers(min_value=1, max_value=15))
    how = data.draw(st.sampled_from(["oserror", "interrupt", "disk full"]))
    real_rename, real_open = os.rename, open
    calls = [0]

    def rename(src, dst):
        calls[0] += 1
        if calls[0] == fail_at and how != "disk full":
            raise KeyboardInterrupt if how == "interrupt" else OSError(errno.EIO, "I/O error")
        return real_rename(src, dst)

    def full_open(file, mode="r", *a, **k):
        if "x" in mode and calls[0] + 1 >= fail_at:
            raise OSError(errno.ENOSPC, "No space left on device")
        calls[0] += "x" in mode
        return real_open(file, mode, *a, **k)

    import builtins

    os.rename = rename
    builtins.open = full_open if how == "disk full" else real_open
    try:
        write_set(out, new, overwrite=True, stale=stale)
    except (OutputError, KeyboardInterrupt):
        c["clean_errors"] += 1
    finally:
        os.rename, builtins.open = real_rename, real_open
    got = {str(p.relative_to(out)): p.read_bytes() for p in out.rglob("*") if p.is_file()}
    whole = got in (old, new)
    if not whole:
        c["partial_sets"] += 1
    assert whole, (old, new, got, fail_at, how)
    assert [p.name for p in root.iterdir()] == ["out"], list(root.iterdir())
    c["results"] += 1


# ----------------------------------------------------------------------------- the longer run

@pytest.mark.fuzz_long
@LONG
@given(data=st.data())
def test_fuzz_long_problem_files(tmp_path, data):
    test_fuzz_problem_files_through_kinematics_cli.hypothesis.inner_test(tmp_path, data)


@pytest.mark.fuzz_long
@LONG
@given(data=st.data())
def test_fuzz_long_flywheel_cli(data):
    test_fuzz_flywheel_cli.hypothesis.inner_test(data)


@pytest.mark.fuzz_long
@LONG
@given(data=st.data())
def test_fuzz_long_answers(tmp_path, data):
    test_fuzz_answers_files_through_check_cli.hypothesis.inner_test(tmp_path, data)


@pytest.mark.fuzz_long
@LONG
@given(dW=api_numbers(), delta=api_numbers(), n=api_numbers(), J_e=api_numbers(), J=api_numbers())
def test_fuzz_long_api(dW, delta, n, J_e, J):
    test_fuzz_flywheel_api.hypothesis.inner_test(dW, delta, n, J_e, J)


# ----------------------------------------------------------------------------- issue 31: the new surfaces

def _drawing_problem(name: str) -> str:
    return {"w1": "W1", "press": "press", "slotted": "slotted-lever", "shaper": "shaper-cam"}[name.split("_")[0]]


SHIPPED_SVG = sorted((DATA / "drawings").glob("*.svg"))
SHIPPED_DXF = sorted((DATA / "drawings").glob("*.dxf"))
SVG_ATTRS = ["x", "y", "x1", "y1", "x2", "y2", "width", "height", "viewBox", "font-size", "transform", "d", "style",
             "points", "class", "href"]


def svg_values():
    return st.one_of(number_texts(), st.sampled_from([
        "0 0 0 0", "0 0 -1 5", "1e308", "56.6mm", "1in", "50%", "matrix(0,0,0,0,0,0)", "scale(0)", "skewX(90)",
        "rotate(1e300)", "translate(nan)", "M 0 0 a 1e308 1e308 0 1 0 1 1", "M", "z", "m1,1 1e400,0", "#a",
        "font-size:0;fill:none;marker-end:url(#m)", "fill:url(#none)", "1,2,3", "", "\u0000"]))


@FAST
@given(data=st.data())
def test_fuzz_svg_drawings_through_check_cli(tmp_path, data):
    """A shipped SVG drawing with attributes, elements or bytes changed: a check, or one clean line."""
    src = data.draw(st.sampled_from(SHIPPED_SVG))
    text = src.read_text(encoding="utf-8")
    for _ in range(data.draw(st.integers(min_value=1, max_value=4))):
        how = data.draw(st.sampled_from(["attr", "attr", "cut", "wrap", "use", "bytes"]))
        if how == "attr":
            attr = data.draw(st.sampled_from(SVG_ATTRS))
            value = data.draw(svg_values()).replace('"', "&quot;").replace("<", "&lt;").replace("&", "&amp;")
            hits = [m.start() for m in re.finditer(rf'\s{re.escape(attr)}="', text)]
            if hits:
                at = data.draw(st.sampled_from(hits))
                end = text.index('"', text.index('"', at) + 1)
                text = text[:text.index('"', at) + 1] + value + text[end:]
            else:
                text = text.replace("<path ", f'<path {attr}="{value}" ', 1)
        elif how == "cut":
            text = text[: data.draw(st.integers(min_value=0, max_value=len(text)))]
        elif how == "wrap":
            n = data.draw(st.sampled_from([1, 5, 50, 300, 3000]))
            text = text.replace("<g ", "<g>" * n + "<g ", 1).replace("</svg>", "</g>" * n + "</svg>", 1)
        elif how == "use":
            text = text.replace("</defs>", '<g id="u0"><use href="#u0"/></g></defs><use href="#u0"/>', 1)
        else:
            text = text.replace("a</tspan>", data.draw(st.text(max_size=4)) + "</tspan>", 1)
    p = tmp_path / "drawing.svg"
    p.write_bytes(text.encode("utf-8", "surrogatepass"))
    run_cli("test_fuzz_svg_drawings_through_check_cli", ["check", _drawing_problem(src.name), p])


@FAST
@given(data=st.data())
def test_fuzz_dxf_drawings_through_check_cli(tmp_path, data):
    """A shipped DXF drawing with group-code values replaced or cut: a check, or one clean line."""
    src = data.draw(st.sampled_from(SHIPPED_DXF))
    lines = src.read_text(encoding="utf-8", errors="replace").splitlines()
    for _ in range(data.draw(st.integers(min_value=1, max_value=4))):
        how = data.draw(st.sampled_from(["value", "value", "cut", "escape"]))
        if not lines:
            break
        if how == "value":
            k = data.draw(st.integers(min_value=0, max_value=len(lines) - 1))
            lines[k] = data.draw(st.one_of(number_texts(), st.sampled_from(["INSERT", "BLOCK", "ENDSEC", "EOF", ""])))
        elif how == "cut":
            lines = lines[: data.draw(st.integers(min_value=0, max_value=len(lines)))]
        else:
            k = data.draw(st.integers(min_value=0, max_value=len(lines) - 1))
            lines[k] = lines[k] + data.draw(st.sampled_from(["\\U+03BC", "\\U+", "\\U+ZZZZ", "\\U+0000", "\\P"]))
    p = tmp_path / "drawing.dxf"
    p.write_bytes("\n".join(lines).encode("utf-8", "surrogatepass"))
    run_cli("test_fuzz_dxf_drawings_through_check_cli", ["check", _drawing_problem(src.name), p])


def formula_texts():
    atoms = st.sampled_from(["phi", "1", "0", "1e15", "1e-300", "1e308", "pi", "100", "-5", "2.5"])
    funcs = st.sampled_from(["sin", "cos", "exp", "log", "sqrt", "abs", "tan"])
    ops = st.sampled_from(["+", "-", "*", "/", "**", "<", ">="])
    expr = st.recursive(atoms, lambda inner: st.one_of(
        st.builds(lambda f, a: f"{f}({a})", funcs, inner),
        st.builds(lambda a, o, b: f"({a}{o}{b})", inner, ops, inner)), max_leaves=6)
    return st.one_of(expr, expr.map(lambda e: f"100+{e}"), st.text(max_size=12),
                     st.sampled_from(["100+sin(1e15*phi)", "1/0", "phi**phi**phi**phi", "(" * 200 + "1" + ")" * 200,
                                      "__import__('os')", "100 + 50*sin(phi/2)", "1e400"]))


@FAST
@given(M_r=formula_texts(), M_d=st.one_of(st.none(), formula_texts()), period=st.sampled_from([None, "360", "auto",
                                                                                                "1e-9", "1e9"]))
def test_fuzz_moment_formulas_through_flywheel_cli(M_r, M_d, period):
    argv = ["flywheel", "--M-r", M_r, "--omega", "10", "--J", "5", "--json"]
    if M_d is not None:
        argv += ["--M-d", M_d]
    if period is not None:
        argv += ["--period-deg", period]
    run_cli("test_fuzz_moment_formulas_through_flywheel_cli", argv, json_out=True)


@FAST
@given(data=st.data())
def test_fuzz_toml_answers_raw_text(tmp_path, data):
    """Answers files as bytes: nesting, inline tables, BOMs, cut strings, non-UTF-8."""
    text = data.draw(st.one_of(
        st.text(max_size=80),
        st.sampled_from(["a = " + "[" * 3000 + "]" * 3000, "a = " + "{b = " * 500 + "1" + "}" * 500,
                         "\ufeff[results]\nJ_F = 1", "[results]\nJ_F = \"", "[[results]]", "x = 1e400",
                         "[results]\nJ_F = 0x10", "[energy_indicator]\narrows_mm = [[1], 2]", "\x00"]),
        st.builds(lambda k, v: f"[results]\n{k} = {v}\n", st.sampled_from(ANSWER_KEYS), toml_value())))
    p = tmp_path / "answers.toml"
    raw = text.encode("utf-8", "surrogatepass")
    if data.draw(st.booleans()):
        raw += data.draw(st.binary(max_size=4))
    p.write_bytes(raw)
    run_cli("test_fuzz_toml_answers_raw_text", ["check", "W1", p])


@FAST
@given(data=st.data())
def test_fuzz_class_folders_still_get_their_report(tmp_path, data):
    """A class folder of good and hostile files: exit 0, 1 or 3, and the table names every file."""
    c = COUNTS[CURRENT[0]]
    folder = tmp_path / "class"
    if folder.exists():
        import shutil

        shutil.rmtree(folder)
    folder.mkdir()
    names = []
    for k in range(data.draw(st.integers(min_value=1, max_value=4))):
        kind = data.draw(st.sampled_from(["good", "svg", "dxf", "toml", "empty", "deep", "fifo"]))
        if kind == "good":
            src = data.draw(st.sampled_from(sorted((DATA / "answers").glob("w1_*.toml"))))
            name = f"s{k}.toml"
            (folder / name).write_bytes(src.read_bytes())
        elif kind == "svg":
            name = f"s{k}.svg"
            (folder / name).write_text(data.draw(st.sampled_from([
                '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 0 0"/>', "<svg", "<g>" * 5000,
                (DATA / "drawings" / "w1_mistakes.svg").read_text(encoding="utf-8")])), encoding="utf-8")
        elif kind == "dxf":
            name = f"s{k}.dxf"
            (folder / name).write_bytes((DATA / "drawings" / "w1_mistakes.dxf").read_bytes()[
                : data.draw(st.integers(min_value=0, max_value=5000))])
        elif kind == "toml":
            name = f"s{k}.toml"
            (folder / name).write_bytes(data.draw(st.binary(max_size=40)))
        elif kind == "deep":
            name = f"s{k}.toml"
            (folder / name).write_text("a = " + "[" * 3000 + "]" * 3000, encoding="utf-8")
        elif kind == "fifo":
            name = f"s{k}.toml"
            os.mkfifo(folder / name)
            continue                       # no regular file: not one of the class's files
        else:
            name = f"s{k}.svg"
            (folder / name).write_bytes(b"")
        names.append(name)
    out = tmp_path / "report"
    code = run_cli("test_fuzz_class_folders_still_get_their_report",
                   ["check-class", folder, "--problem", "W1", "--out", out, "--force", "--no-overlays"],
                   ok_codes=(0, 1, 3))
    if not names:                          # only a FIFO: no file to check, refused cleanly (exit 2)
        assert code == 2
        return
    assert code in (0, 1, 3), code
    table = (out / "class.csv").read_text(encoding="utf-8-sig")
    missing = [n for n in names if n not in table]
    if missing:
        c["partial_sets"] += 1
    assert not missing, missing


SIGNAL_SCRIPT = """
import os, signal, sys
from graphmethods.render.files import write_set

class Files(dict):
    def items(self):
        for k, (name, data) in enumerate(super().items()):
            if k == int(sys.argv[2]):
                os.kill(os.getpid(), getattr(signal, sys.argv[3]))
            yield name, data

write_set(sys.argv[1], Files({f"svg/f{i}.svg": b"new" for i in range(int(sys.argv[4]))}), overwrite=True)
"""


@settings(deadline=None, max_examples=int(os.environ.get("GRAPHMETHODS_FUZZ_SIGNAL_EXAMPLES", "8")), phases=PHASES,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(at=st.integers(min_value=0, max_value=5), sig=st.sampled_from(["SIGTERM", "SIGINT"]),
       n=st.integers(min_value=1, max_value=6), existing=st.booleans())
def test_fuzz_signals_during_set_writes(tmp_path_factory, at, sig, n, existing):
    """SIGTERM or SIGINT while a set is staged: the old set or the new one, and no temporary folder."""
    import subprocess
    import sys

    c = COUNTS[CURRENT[0]]
    c["inputs"] += 1
    root = tmp_path_factory.mktemp("sig")
    out = root / "set"
    old = {}
    if existing:
        (out / "svg").mkdir(parents=True)
        for i in range(3):
            (out / "svg" / f"f{i}.svg").write_bytes(b"old")
            old[f"svg/f{i}.svg"] = b"old"
    proc = subprocess.run([sys.executable, "-c", SIGNAL_SCRIPT, str(out), str(at), sig, str(n)],
                          capture_output=True, timeout=60,
                          env=dict(os.environ, PYTHONPATH=str(pathlib.Path(__file__).resolve().parents[1])))
    got = {str(p.relative_to(out)): p.read_bytes() for p in out.rglob("*") if p.is_file()} if out.exists() else {}
    new = {**old, **{f"svg/f{i}.svg": b"new" for i in range(n)}}
    left = [p for p in root.rglob("*") if p.name.endswith(".tmp")]
    if b"Traceback" in proc.stderr and sig == "SIGTERM":
        c["tracebacks"] += 1
    if left or got not in (old, new):
        c["partial_sets"] += 1
    assert not left and got in (old, new), (left, got, proc.stderr[-500:])
    c["results" if proc.returncode == 0 else "clean_errors"] += 1


@FAST
@given(omega=api_numbers(), eps=api_numbers(), m=st.one_of(api_numbers(), st.sampled_from([3, 12, 2**62]),
                                                           st.integers(min_value=-5, max_value=10**400)))
def test_fuzz_linkage_api_numbers(omega, eps, m):
    """A linkage's motion and velocity plans with hostile numbers (400-digit integers, numpy scalars, 1e300)."""
    import numpy as np

    from graphmethods.kinematics.presets import six_bar_press

    t = "test_fuzz_linkage_api_numbers"
    lk = six_bar_press()
    mm = np.int64(m) if isinstance(m, int) and -2**63 <= m < 2**63 and m % 2 else m
    call_api(t, lambda: lk.motion(m=mm, omega_1=omega, epsilon_1=eps).a("D"))
    mech = case_from_dict(CASES["slider_crank_press"]).mechanism
    call_api(t, lambda: [mech.velocity_plans(mech.positions(m=8), omega_1=omega).v(n) for n in ("A", "B")])
