"""A three-mass drive (motor 0.08 kg·m² at 6ω, intermediate gear 0.5 kg·m² at 2ω, crankshaft 12 kg·m²;
shafts 2000 N·m/rad at 6ω and 40 000 N·m/rad at ω) and its scheme reduced to the crankshaft,
English notation.
"""

from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain
from graphmethods.sheets.drive_scheme import drive_scheme


def build():
    chain = reduce_chain([Mass("motor", 0.08, 6.0, 30.0), Mass("gear", 0.5, 2.0), Mass("crank", 12.0, 1.0, -160.0)],
                         [Shaft("motor shaft", 2.0e3, 6.0), Shaft("output shaft", 4.0e4, 1.0)])
    return drive_scheme(chain, notation="en")
