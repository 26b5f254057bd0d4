"""The speed ω(φ) and the angular acceleration ε(φ) of the exact steady motion against the crank angle
(split out of :mod:`graphmethods.sheets.dynamics`, whose graph builder they use)."""

from __future__ import annotations

import math

import numpy as np

from graphmethods.scene import Scene, notation as get_notation
from graphmethods.scene.primitives import MAIN
from graphmethods.sheets.dynamics import CurveSpec, MarkSpec, as_study, phi_graph, value_text

# ----------------------------------------------------------------------------- 4. ω(φ) and ε(φ)

def speed_graph(study, *, mu_omega=None, mu_phi=None, notation="en", page=None, title=None,
                title_block: bool = True, name: str = "speed-graph") -> Scene:
    """ω(φ) of the exact steady motion with the exact flywheel for [δ]: ω_m, ω_max and ω_min marked.

    The ω axis starts at a round value below ω_min (its first tick), so the fluctuation
    is visible.

    Examples
    --------
    >>> import pathlib
    >>> from graphmethods.kinematics import read_case
    >>> press = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
    >>> s = speed_graph(press)
    >>> s.element("label-omega_max").text
    'ω_{max} = 32.04 rad/s, φ = 23.22°'
    """
    study = as_study(study)
    nt = get_notation(notation)
    ex = study.exact
    mo = ex.motion
    phi = np.asarray(mo.phi, dtype=float) - float(mo.phi[0])
    w = np.asarray(mo.omega, dtype=float)
    n = get_notation(nt).number
    marks = [MarkSpec("omega_max", ex.phi_omega_max_from_0, ex.omega_max,
                      f"{nt.sym('dynamics.omega_max')} = {value_text(nt, ex.omega_max, 'rad/s')}, φ = "
                      f"{n(math.degrees(ex.phi_omega_max_from_0))}°", True),
             MarkSpec("omega_min", ex.phi_omega_min_from_0, ex.omega_min,
                      f"{nt.sym('dynamics.omega_min')} = {value_text(nt, ex.omega_min, 'rad/s')}, φ = "
                      f"{n(math.degrees(ex.phi_omega_min_from_0))}°", False)]
    levels = [(mo.omega_m, f"{nt.sym('dynamics.omega_m')} = {value_text(nt, mo.omega_m, 'rad/s')}", "omega_m")]
    legend = (f"δ = {n(mo.delta)};  {nt.sym('dynamics.J_F')} = {value_text(nt, ex.J_F, 'kg·m²')} "
              f"({nt.word('dynamics.exact')})")
    return phi_graph(study, nt=nt, title=title or f"{nt.word('dynamics.speed_graph')} ω(φ)", page=page,
                        title_block=title_block, name=name, curves=[CurveSpec("omega", phi, w, MAIN, "")],
                        y_lo=float(min(w.min(), ex.omega_min)), y_hi=float(max(w.max(), ex.omega_max)),
                        y_symbol=nt.sym("dynamics.omega"), y_unit="rad/s", scale_symbol=nt.sym("dynamics.mu_omega"),
                        mu_Y=mu_omega,
                        mu_phi=mu_phi, what="the ω graph", marks=marks, levels=levels, legend=legend, zero=None)


def acceleration_graph(study, *, mu_eps=None, mu_phi=None, notation="en", page=None, title=None,
                       title_block: bool = True, name: str = "acceleration-graph") -> Scene:
    """ε(φ) = (M_e − ½ω² dJ_e/dφ)/(J_F + J_e) of the exact motion: the largest |ε| and χ = |ε|_max/ω_m².

    ε jumps where the load switches on and off.

    Examples
    --------
    >>> import pathlib
    >>> from graphmethods.kinematics import read_case
    >>> press = read_case(pathlib.Path(__file__).parents[1] / "problems" / "data" / "slider_crank_press.json")
    >>> s = acceleration_graph(press, notation="ru")
    >>> s.element("axis-Y").label
    'ε, рад/с²'
    """
    study = as_study(study)
    nt = get_notation(notation)
    mo = study.exact.motion
    phi = np.asarray(mo.phi, dtype=float) - float(mo.phi[0])
    eps = np.asarray(mo.epsilon, dtype=float)
    n = get_notation(nt).number
    p = float(mo.phi_epsilon_max - mo.phi[0])
    eps_text = f"{nt.sym('dynamics.eps_max')} = {value_text(nt, mo.epsilon_max, 'rad/s²')}"
    marks = [MarkSpec("eps_max", p, mo.epsilon_max, f"{eps_text}, φ = {n(math.degrees(p))}°", mo.epsilon_max > 0)]
    legend = (f"{nt.sym('dynamics.chi')} = |{nt.sym('dynamics.eps')}|_{{max}}/{nt.sym('dynamics.omega_m')}² = "
              f"{n(mo.chi)}")
    return phi_graph(study, nt=nt, title=title or f"{nt.word('dynamics.accel_graph')} ε(φ)", page=page,
                        title_block=title_block, name=name, curves=[CurveSpec("eps", phi, eps, MAIN, "")],
                        y_lo=float(min(eps.min(), 0.0)), y_hi=float(max(eps.max(), 0.0)),
                        y_symbol=nt.sym("dynamics.eps"),
                        y_unit="rad/s²", scale_symbol=nt.sym("dynamics.mu_eps"), mu_Y=mu_eps, mu_phi=mu_phi,
                        what="the ε graph", marks=marks, legend=legend, zero=True)
