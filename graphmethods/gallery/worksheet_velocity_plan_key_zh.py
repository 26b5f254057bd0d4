"""Worksheet "velocity-plan" (a slider-crank in one position → its velocity plan), variant 1 of seed
7: the answer key (the student's page filled in), Chinese notation.
"""

from graphmethods.sheets import worksheets


def build():
    v = worksheets.variant("velocity-plan", seed=7, number=1)
    return worksheets.key_page(v, notation="zh")
