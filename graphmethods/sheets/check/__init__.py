"""Checking a hand drawing: what a student measured and wrote, against the exact construction at the
student's own scales, with a diagnosis of the usual mistakes and an overlay to print on film.

The answers file (TOML) holds the student's scales and page, the lengths and areas they measured and
the values they wrote (see :data:`SCHEMA` and the examples in ``graphmethods/problems/data/answers``)::

    student = "A. Student"
    [page]
    size = "A4"
    orientation = "landscape"
    [energy_indicator]
    mu_E = 5.0                       # J/mm
    arrows_mm = [-10, 110, -20, 25, -100, 5, -10]
    [results]
    delta_W_max = 575.0              # J
    omega_max_at = "e"
    J_F = 43.69                      # kg·m²

Each item gets the expected value at the student's scales, the deviation and a verdict:

``ok``       within the tolerance;
``carried``  wrong, but it follows (within tolerance) from the student's own earlier wrong values:
             not a new mistake;
``wrong``    a new mistake; when the value fits one of the usual mistakes (:data:`MISTAKES`, each a
             hypothesis "recompute with this mistake": it is diagnosed when the student's value
             matches it within tolerance and the correct value does not), that mistake is named.

Tolerances (documented rules):

* a length measured on the drawing: ±0.5 mm (:data:`TOL_MM`);
* an area measured between curves: ±0.5 mm × the region's perimeter at the student's scales (the
  band half a millimetre wide along its boundary); when the region's shape is not known (areas
  given as data), the perimeter of the square of that area, 4√|f|;
* a value computed without drawing (ω_m, tan ψ, works from given areas): 0.1 % (:data:`TOL_REL`,
  four significant figures);
* a derived value: first-order worst case propagation of the tolerances of the measured values it
  comes from (e.g. ΔW_max: the sum of the work tolerances of the intervals between E_max and
  E_min; J_F = μ_T·kl/(ω_m²δ): μ_T·0.5 mm/(ω_m²δ)), plus 0.1 %;
* a position (where ω_max occurs): every point whose level is within the ΔW_max tolerance of the
  extreme (Wittenbauer: every vertex within 0.5 mm of the touching ray) is accepted.

The package, by concern: :mod:`.typed_answers` (the answers file), :mod:`.problems` (what is checked
against), :mod:`.report` (items, verdicts, the checker), :mod:`.hypotheses` (the constructions recomputed
and the usual mistakes), :mod:`.acceleration` (an acceleration plan), :mod:`.checking` (:func:`check`),
:mod:`.overlay`, :mod:`.cad` (drawings read from DXF or SVG) and :mod:`.classcheck` (a class at once).

>>> rep = check("W1", {"energy_indicator": {"mu_E": 5.0, "arrows_mm": [-10, 110, -20, 25, -100, 5, -10]},
...                    "results": {"delta_W_max": 575.0, "J_F": 0.4795}})
>>> [(i.key, i.verdict) for i in rep.items if i.verdict != "ok"], [m.code for m in rep.mistakes]
([('results.J_F', 'wrong')], ['n_as_omega'])
"""

__all__ = [
    "KEY_KINDS", "MISTAKES", "PROBLEM_IDS", "SCHEMA", "TOL_MM", "TOL_REL", "TOP_LEVEL", "CheckReport",
    "CycleData", "Item", "LinkageData", "Mistake", "check", "load_problem", "load_toml", "read_answers",
    "validate_answers",
]

from graphmethods.sheets.check.checking import check
from graphmethods.sheets.check.problems import PROBLEM_IDS, CycleData, LinkageData, load_problem
from graphmethods.sheets.check.report import MISTAKES, CheckReport, Item, Mistake
from graphmethods.sheets.check.tolerances import TOL_MM, TOL_REL
from graphmethods.sheets.check.typed_answers import (
    KEY_KINDS,
    SCHEMA,
    TOP_LEVEL,
    load_toml,
    read_answers,
    validate_answers,
)
