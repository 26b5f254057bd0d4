"""W3 (step resisting moment): work diagrams by the method of chords over 12 intervals; the jump lies
inside an interval, so the integral is exact at the interval ends and errs only inside; English notation.
"""

from graphmethods import problems
from graphmethods.sheets import calculus


def build():
    return calculus.work_diagrams(problems.w3(), m=12, notation="en")
