"""Worksheet "indicator" (W1 style: areas → energy indicator, ΔW_max, J_F), variant 1 of seed 7: the
answer key (the student's page filled in), English notation.
"""

from graphmethods.sheets import worksheets

PNG = True  # also rendered to PNG for the README


def build():
    v = worksheets.variant("indicator", seed=7, number=1)
    return worksheets.key_page(v, notation="en")
