"""Printable worksheets with answer keys: variants from a seed, a student page and a key page each.

Six kinds of worksheet (:data:`KINDS`):

``indicator``      W1 style: measured areas between M_d and M_r (mm², with μ_M, μ_φ) → excess works,
                   energy levels, the energy indicator diagram at a stated μ_E, ΔW_max, ω_m, ω_max,
                   ω_min and the flywheel J_F = ΔW_max/(ω_m²[δ]) − J_e.
``step-moment``    W3 style: a resisting moment given as steps or as a piecewise-linear curve, M_d
                   constant by work balance → the moment diagram at stated scales, the excess-work
                   table, ΔW_max, where ω_max and ω_min occur, J_F.
``velocity-plan``  a slider-crank in one position (its scheme drawn at μ_l) → the velocity plan at a
                   stated μ_v: pa, pb, ab, ps2 in mm, v_A, v_B, v_BA, v_S2 and ω_2.
``wittenbauer``    a slider-crank press given by its table of J_e and ΔT at positions 0…12 → the
                   energy–mass diagram at stated μ_J, μ_T, tan ψ_max, tan ψ_min, the rays, kl, J_F and
                   the positions of ω_max and ω_min.
``acceleration-plan`` a slider-crank or a slotted lever in one position, its velocities given → the
                   acceleration plan at a stated μ_a, every vector in mm, ε of each link
                   (:mod:`graphmethods.sheets.worksheets.acceleration_plan`).
``cam``            a disc cam with a translating knife or roller follower → the base radius from [α], the
                   profile by inversion at a stated μ_l, s at the marked positions, the largest pressure
                   angles (:mod:`graphmethods.sheets.worksheets.cam`).

Each variant is drawn from its own numpy Generator seeded by (seed, kind, variant number), so a
variant does not depend on how many were asked for; its numbers are "nice" (areas that close
exactly, scales from the convenient series, answers a student reaches with a calculator). A variant
has a student page (statement in en/ru/zh, data table, blank grid and axes at the stated scales,
answer boxes) and an answer-key page: the same page with the construction drawn at those scales and
every answer filled in, so the key laid over a student's sheet shows the differences.

>>> ws = worksheet("indicator", variants=2, seed=7, notation="en")
>>> len(ws.scenes), ws.variants[0].id
(4, 'indicator:7:1')
>>> v = ws.variants[0]
>>> sum(v.areas_mm2) == 0 and v.answers()["J_F"] > 0
True

The package, by concern: :mod:`.variants` (the variants and their random generators), :mod:`.texts`
(titles and statements), :mod:`.elements` (graph paper and the kinematic symbols), :mod:`.constructions`
(what a key draws, which the checker's overlay draws again), :mod:`.pages` (student and key pages), :mod:`.answers` (the
blank answers file), :mod:`.classset` (a class set and its files' contents) and
:mod:`.acceleration_plan` (the ``acceleration-plan`` kind). :func:`contents` gives a class set's files
(one PDF of the students' pages then the keys, an SVG per page, a problem file per variant, which
``graphmethods check`` reads); :func:`graphmethods.cli.worksheet.write_worksheet` writes them,
atomically and never over existing files unless asked.

The kinds with modules of their own (``acceleration-plan``, ``cam``) are imported when first asked for, so a
class set of one kind loads only its own.
"""

import importlib
from typing import TYPE_CHECKING, Any

from graphmethods.scene import markup
from graphmethods.sheets.worksheets import answers
from graphmethods.sheets.worksheets.classset import (
    Worksheet,
    contents,
    dxf_names,
    existing_outputs,
    file_names,
    output_names,
    register,
    worksheet,
)
from graphmethods.sheets.worksheets.constructions import (
    energy_mass_construction,
    extremes,
    moment_regions,
    region_perimeters_mm,
    slider_crank_scheme,
    staircase,
    velocity_plan,
)
from graphmethods.sheets.worksheets.elements import (
    RED,
    ColorText,
    Grid,
    Shapes,
    arc,
    clip_ray,
    ground,
    pin,
    slider,
    wrap,
)
from graphmethods.sheets.worksheets.pages import key_page, student_page
from graphmethods.sheets.worksheets.texts import STATEMENTS, TITLES, value_unit
from graphmethods.sheets.worksheets.variants import (
    KINDS,
    PROBLEM_FORMAT,
    SEGMENTS,
    EnergyMassVariant,
    IndicatorVariant,
    PlanVariant,
    StepMomentVariant,
    Variant,
    energy_mass_from_press,
    parse_id,
    variant,
    variant_from_dict,
    variants,
)

# the acceleration-plan and cam kinds have modules of their own (they draw linkages of several kinds, cams), each
# registering its kind when imported: on first use of the kind (variants.OWN_MODULES), or of the name here
if TYPE_CHECKING:
    from graphmethods.sheets.worksheets import acceleration_plan, cam


def __getattr__(name: str) -> Any:
    """``acceleration_plan`` and ``cam``: the kind's module, imported when first asked for."""
    if name in ("acceleration_plan", "cam"):
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = [
    "KINDS", "PROBLEM_FORMAT", "RED", "SEGMENTS", "STATEMENTS", "TITLES", "ColorText", "EnergyMassVariant",
    "Grid", "IndicatorVariant", "PlanVariant", "Shapes", "StepMomentVariant", "Variant", "Worksheet",
    "acceleration_plan", "answers", "cam", "arc", "clip_ray", "contents", "dxf_names", "energy_mass_construction",
    "energy_mass_from_press", "existing_outputs", "extremes", "file_names", "ground", "key_page",
    "markup", "moment_regions", "output_names", "parse_id", "pin", "region_perimeters_mm",
    "register", "slider", "slider_crank_scheme", "staircase", "student_page",
    "value_unit", "variant", "variant_from_dict", "variants", "velocity_plan", "worksheet", "wrap",
]
