"""The press (problems/data/slider_crank_press.json) step by step for a lecture, ru: the Wittenbauer
energy–mass diagram: the axes, the points of positions 0…11, the curve, the ray at ψ_max, the ray at
ψ_min, k and l, kl, J_F.

Committed outputs: press_wittenbauer_ru.pdf (one 16:9 slide per step) and press_wittenbauer_ru.html (one page,
stepped with the buttons and the arrow keys).
"""

from graphmethods.sheets import steps

FORMATS = ("pdf", "html")


def build():
    return steps.build("press", "wittenbauer", notation="ru")
