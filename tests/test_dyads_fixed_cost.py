"""Issue 19's 12-position fixed cost in the dyads: what was cut must change no bit.

Below KEEP_BELOW positions RRR and RRP keep their arms, plan lines and det from the velocity solution
for the acceleration one; from KEEP_BELOW up they compute them again. Their lengths, a frame guide's
point and direction, the crank's r and i are 0-d arrays instead of Python numbers, and the crank's ω
and ε arrays are kept per (value, n). Each is checked against a computation that does not use it:
the other path at the same angles, the textbook formulas written out with Python numbers (as the
groups computed them before), and a fresh array for −0.0."""

import math

import numpy as np
import pytest

from graphmethods.kinematics.groups import RRP, RRR, Guide
from graphmethods.kinematics.groups.base import KEEP_BELOW, State, cross, dot
from graphmethods.problems import builtin


def _bits(a):
    """The array's bytes: equal bits, signed zeros included."""
    return np.ascontiguousarray(np.broadcast_to(a, np.shape(a))).tobytes()


def _tables(st, n):
    out = {}
    for table in ("z", "v", "a", "omega", "epsilon", "conditioning"):
        for key, value in getattr(st, table).items():
            out[(table, key)] = _bits(np.broadcast_to(value, (st.n,))[:n])
    for group, rel in st.relative.items():
        for key, value in rel.items():
            out[("relative", group, key)] = _bits(np.broadcast_to(value, (st.n,))[:n])
    return out


@pytest.mark.parametrize("name", list(builtin.LINKAGES))
def test_the_kept_and_the_recomputed_path_give_the_same_bits(name):
    lk = builtin.case(name).linkage
    rng = np.random.default_rng(19)
    start = lk.strokes().phi_start if lk.strokes() is not None else 0.0
    phi = start + rng.uniform(0.0, 2 * math.pi, KEEP_BELOW)   # every linkage built in turns fully
    phi[:2] = start, start + math.pi                          # near the extremes: zeros of every sign
    big = lk.solve(phi, omega_1=7.0, epsilon_1=-2.0)         # KEEP_BELOW positions: nothing kept
    small = lk.solve(phi[:13], omega_1=7.0, epsilon_1=-2.0)  # 13 positions: the velocity lines kept
    assert not big.kept and not small.kept                    # each group took out what it kept
    assert _tables(small, 13) == _tables(big, 13)


def _rrr_by_hand(P, Q, vP, vQ, aP, aQ, l1, l2, branch):
    """RRR written out with Python numbers, in the operations' order (positions, ω, ε, a_C)."""
    D = Q - P
    d = np.abs(D)
    prod = (l1 + l2 - d) * (d + l2 - l1) * (d + l1 - l2) * (d + l1 + l2)
    h = np.sqrt(np.maximum(prod, 0.0)) / (2.0 * d)
    a = (l1 * l1 - l2 * l2 + d * d) / (2.0 * d)
    C = P + (a + 1j * branch * h) * (D / d)
    rP, rQ = C - P, C - Q
    e1, e2, rhs = 1j * rP, -1j * rQ, vQ - vP
    det = cross(e1, e2)
    w1, w2 = cross(rhs, e2) / det, cross(e1, rhs) / det
    rhs = aQ - w2 * w2 * rQ - (aP - w1 * w1 * rP)
    eps1, eps2 = cross(rhs, e2) / det, cross(e1, rhs) / det
    return C, w1, w2, vP + 1j * w1 * rP, eps1, eps2, aP - w1 * w1 * rP + 1j * eps1 * rP


def _rrp_by_hand(P, vP, aP, l, branch, G, angle):
    """RRP on a guide of the frame written out with Python numbers, in the operations' order."""
    u = complex(math.cos(angle), math.sin(angle))
    R = P - G
    h = cross(u, R)
    s = dot(u, R) + branch * np.sqrt(np.maximum((l - h) * (l + h), 0.0))
    C = G + s * u
    rP = C - P
    rhs = vP - 0j - 1j * 0.0 * s * u
    det = cross(u, -1j * rP)
    sd, w = cross(rhs, -1j * rP) / det, cross(u, rhs) / det
    vC = 0j + 1j * 0.0 * s * u + sd * u
    a_guide = 0j + (1j * 0.0 - 0.0 * 0.0) * s * u
    a_k = 2j * 0.0 * sd * u
    rhs = aP - w * w * rP - a_guide - a_k
    sdd, eps = cross(rhs, -1j * rP) / det, cross(u, rhs) / det
    return C, s, sd, w, vC, sdd, eps, a_guide + a_k + sdd * u


def _state(rng, n, names):
    st = State(phi=np.zeros(n))
    for k in names:
        st.z[k] = rng.normal(0.0, 0.1, n) + 1j * rng.normal(0.0, 0.1, n)
        st.v[k] = rng.normal(0.0, 1.0, n) + 1j * rng.normal(0.0, 1.0, n)
        st.a[k] = rng.normal(0.0, 10.0, n) + 1j * rng.normal(0.0, 10.0, n)
    zeros = [0j, complex(-0.0, 0.0), complex(0.0, -0.0)]           # zeros of every sign
    st.v["P"][:3] = zeros[:n]
    return st


@pytest.mark.parametrize("n", [1, 13, KEEP_BELOW])
@pytest.mark.parametrize("branch", [1, -1])
def test_rrr_gives_the_bits_of_its_formulas_with_python_numbers(n, branch):
    rng = np.random.default_rng(n)
    st = _state(rng, n, ("P", "Q"))
    st.z["Q"] = st.z["P"] + 0.3 * np.exp(1j * rng.uniform(0, 2 * math.pi, n))
    g = RRR(P="P", Q="Q", C="C", l_PC=0.25, l_QC=0.2, links=("2", "3"), branch=branch)
    g.positions(st)
    g.velocities(st)
    g.accelerations(st)
    want = _rrr_by_hand(st.z["P"], st.z["Q"], st.v["P"], st.v["Q"], st.a["P"], st.a["Q"], 0.25, 0.2, branch)
    got = (st.z["C"], st.omega["2"], st.omega["3"], st.v["C"], st.epsilon["2"], st.epsilon["3"], st.a["C"])
    assert [_bits(x) for x in got] == [_bits(x) for x in want]


@pytest.mark.parametrize("n", [1, 13, KEEP_BELOW])
@pytest.mark.parametrize("branch", [1, -1])
def test_rrp_on_the_frame_gives_the_bits_of_its_formulas_with_python_numbers(n, branch):
    rng = np.random.default_rng(100 + n)
    st = _state(rng, n, ("P",))
    G, angle = complex(0.01, 0.02), 0.3
    g = RRP(P="P", C="C", l=0.5, guide=Guide("0", G, angle), links=("2", "3"), branch=branch)
    g.positions(st)
    g.velocities(st)
    g.accelerations(st)
    rel = st.relative[g.name]
    want = _rrp_by_hand(st.z["P"], st.v["P"], st.a["P"], 0.5, branch, G, angle)
    got = (st.z["C"], rel["s"], rel["s_dot"], st.omega["2"], st.v["C"], rel["s_ddot"], st.epsilon["2"], st.a["C"])
    assert [_bits(x) for x in got] == [_bits(x) for x in want]
    assert st.e["3"] == complex(math.cos(angle), math.sin(angle))   # the slider's direction stays a number


def test_the_crank_s_kept_epsilon_tells_minus_zero_from_zero():
    lk = builtin.case("press").linkage
    phi = np.linspace(0.0, 1.0, 13)
    plus = lk.solve(phi, omega_1=2.0, epsilon_1=0.0).epsilon["1"]
    minus = lk.solve(phi, omega_1=2.0, epsilon_1=-0.0).epsilon["1"]
    assert not np.signbit(plus).any() and np.signbit(minus).all()
    assert lk.solve(phi, omega_1=2.0, epsilon_1=0.0).epsilon["1"] is plus       # kept per (value, n)
    assert not plus.flags.writeable
