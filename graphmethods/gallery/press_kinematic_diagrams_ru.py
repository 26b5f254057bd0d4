"""Offset slider-crank press: the slider's s(φ), v(φ), a(φ) by graphical differentiation (poles P₁, P₂,
rays, chords), compared with the velocity plans and the analytic values; Russian notation.
"""

import pathlib

import graphmethods
from graphmethods.kinematics import read_case
from graphmethods.sheets import calculus

PRESS = pathlib.Path(graphmethods.__file__).parent / "problems" / "data" / "slider_crank_press.json"


def build():
    return calculus.kinematic_diagrams(read_case(PRESS), m=12, notation="ru")
