"""Worksheet "step-moment" (W3 style: step or piecewise-linear resisting moment → moment diagram,
J_F), variant 1 of seed 7: the student's page, Russian notation.
"""

from graphmethods.sheets import worksheets


def build():
    v = worksheets.variant("step-moment", seed=7, number=1)
    return worksheets.student_page(v, notation="ru")
