"""The oil pump's sine mechanism reduced to its translating yoke: m_e(φ) = m3 + (m2 + J1/r²)/sin²φ,
drawn up to 6 m_e,min (m_e → ∞ at the dead centres), Russian notation.
"""

from graphmethods.dynamics.study import Study
from graphmethods.problems.builtin import case
from graphmethods.sheets.translating_graph import equivalent_mass_graph

PNG = True  # also rendered to PNG for the README


def build():
    return equivalent_mass_graph(Study(case("scotch-yoke"), positions=12), notation="ru")
