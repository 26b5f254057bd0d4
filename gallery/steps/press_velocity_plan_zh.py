"""The press (problems/data/slider_crank_press.json) step by step for a lecture, zh: the velocity plan of
its fullest working-stroke position: the pole and μ_v, pa ⟂ OA, the line through a ⟂ AB, the line
through p ∥ the guide, their meeting point b, s₂ by similarity, the values read off.

Committed outputs: press_velocity_plan_zh.pdf (one 16:9 slide per step) and press_velocity_plan_zh.html (one page,
stepped with the buttons and the arrow keys).
"""

from graphmethods.sheets import steps

FORMATS = ("pdf", "html")


def build():
    return steps.build("press", "velocity-plan", notation="zh")
