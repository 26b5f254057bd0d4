"""Worksheet "indicator" (W1 style: areas → energy indicator, ΔW_max, J_F), variant 1 of seed 7: the
student's page, English notation.
"""

from graphmethods.sheets import worksheets


def build():
    v = worksheets.variant("indicator", seed=7, number=1)
    return worksheets.student_page(v, notation="en")
