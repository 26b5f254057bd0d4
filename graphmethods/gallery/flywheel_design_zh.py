"""W1's flywheel (J_F = 43.69 kg·m² at 600 rev/min) as a cast-iron rim flywheel of mean diameter
750 mm and as a steel disc of the same diameter: sections to scale, dimensioned, with masses, mD²
and rim speeds, Chinese notation.
"""

from graphmethods.dynamics.flywheel import disc_flywheel, rim_flywheel
from graphmethods.sheets.flywheel_design import flywheel_design


def build():
    J_F = 900 * 575 / (3.141592653589793**2 * 600**2 / 300)
    return flywheel_design(rim_flywheel(J_F, n_rpm=600.0, D=0.75), disc_flywheel(J_F, D=0.75, n_rpm=600.0),
                           notation="zh")
