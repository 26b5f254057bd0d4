"""W1 (diesel generator, ΔW_max from its excess-work table, n = 600 rev/min): the J_F–[δ] hyperbola
over the table's range of recommended [δ], the AC generator's row as a band and its strict end
[δ] = 1/300 marked with J_F, English notation.
"""

from graphmethods import problems
from graphmethods.dynamics.flywheel import mean_speed
from graphmethods.sheets.flywheel_hyperbola import flywheel_hyperbola


def build():
    w1 = problems.w1()
    return flywheel_hyperbola(w1.excess_work.delta_W_max, omega_m=mean_speed(n_rpm=w1.n_rpm), J_e=w1.J_e,
                              machine="ac-generator",
                              problem=f"{w1.id}, n = {w1.n_rpm:g} rev/min")
