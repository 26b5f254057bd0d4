"""Offset slider-crank press: M_d, M_r integrated by the method of chords (pole P, H picked) into the
work diagrams A_d(φ), A_r(φ) and ΔE(φ), with the accuracy against the exact integrals; English notation.
"""

import pathlib

import graphmethods
from graphmethods.dynamics.study import Study
from graphmethods.kinematics import read_case
from graphmethods.sheets import calculus

PRESS = pathlib.Path(graphmethods.__file__).parent / "problems" / "data" / "slider_crank_press.json"


def build():
    return calculus.work_diagrams(Study(read_case(PRESS), positions=12), notation="en")
