"""Classic textbook problems as data: the worked examples W1–W4 and (later) linkage problems."""

from graphmethods.problems.cycle import CycleProblem
from graphmethods.problems.worked_examples import all_examples, w1, w2, w3, w4_drawing, w4_exact

__all__ = ["CycleProblem", "all_examples", "w1", "w2", "w3", "w4_drawing", "w4_exact"]
