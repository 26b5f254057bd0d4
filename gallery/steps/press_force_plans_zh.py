"""The press (problems/data/slider_crank_press.json) step by step for a lecture, zh: the force plans of
position 3 (working stroke, the load on): μ_F; the group RRP (2, 3): the known forces end to end
(R^τ_12 first from the rod's moments about B), the lines of R_03 ⊥ the guide and R^n_12 ∥ AB,
their meeting point, the reactions; the crank's polygon closed by R_01; the table and M_b with its
two checks.

Committed outputs: press_force_plans_zh.pdf (one 16:9 slide per step, enlarged for a projector) and
press_force_plans_zh.html (one page, stepped with the buttons and the arrow keys).
"""

from graphmethods.sheets import steps

FORMATS = ("pdf", "html")


def build():
    return steps.build("press", "force-plans", position=3, notation="zh")
