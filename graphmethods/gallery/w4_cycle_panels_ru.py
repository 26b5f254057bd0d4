"""W4 (exact data, J_e = 0.8, ω0 = 10 s⁻¹): M_d and M_r, ΔE and ω(φ) on one φ axis, Russian notation.
"""

from graphmethods import problems
from graphmethods.sheets.cycle_panels import cycle_panels


def build():
    return cycle_panels(problems.w4_exact(), notation="ru")
