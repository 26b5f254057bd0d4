"""The press (problems/data/slider_crank_press.json) step by step for a lecture, en: Zhukovsky's lever
with every force in position 3: the velocity plan of analogues turned 90° as a lever pivoted at p;
each force (the inertia moment as a couple of two forces) at the image of its point, with its
moment about p; the balancing force F_b from Σ M_p = 0; M_b beside the force plans' value.

Committed outputs: press_zhukovsky_lever_en.pdf (one 16:9 slide per step, enlarged for a projector) and
press_zhukovsky_lever_en.html (one page, stepped with the buttons and the arrow keys).
"""

from graphmethods.sheets import steps

FORMATS = ("pdf", "html")


def build():
    return steps.build("press", "zhukovsky-lever", position=3, notation="en")
