"""W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): excess-work table, English notation. As
drawn in the lecture: areas in mm² at μ_M = 1 kG·m/mm, μ_φ = 0.075 rad/mm (π taken as 3).
"""

from graphmethods import problems, sheets


def build():
    return sheets.excess_work_table(
        problems.w4_drawing(),
        notation="en",
        work_unit="kG·m",
        moment_unit="kG·m",
    )
