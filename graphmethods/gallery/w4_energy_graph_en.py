"""W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): kinetic-energy graph T(φ) = T0 + ΔE(φ) from
ω0 = 10 s⁻¹, J_e = 0.8, English notation.
"""

from graphmethods import problems, sheets


def build():
    return sheets.energy_graph(problems.w4_exact(), notation="en", J_e=0.8, omega_0=10.0, work_unit="kG·m")
