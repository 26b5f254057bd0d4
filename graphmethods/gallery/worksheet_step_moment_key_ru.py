"""Worksheet "step-moment" (W3 style: step or piecewise-linear resisting moment → moment diagram,
J_F), variant 1 of seed 7: the answer key (the student's page filled in), Russian notation.
"""

from graphmethods.sheets import worksheets


def build():
    v = worksheets.variant("step-moment", seed=7, number=1)
    return worksheets.key_page(v, notation="ru")
