"""The gallery's catalogue: one table of the built-in figures, one row per figure.

A row is (name, problem, figure, language, options): the problem it draws (a key of
:func:`problem`), the figure function that draws it (``module.function`` under
:mod:`graphmethods.sheets`), the language of its notation, the function's other options, and a
sentence saying what it shows (``png=True``: the README shows its PNG as well). Adding a figure
is adding a row here; ``graphmethods gallery --regenerate`` then writes its golden SVG.

Nothing heavy is imported until a figure is built.

>>> f = figure("press_velocity_plan_ru")
>>> f.problem, f.figure, f.language
('case:press', 'kinematics.velocity_plan', 'ru')
>>> len({f.name for f in CATALOGUE}) == len(CATALOGUE)
True
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from graphmethods.errors import InputError


@dataclass(frozen=True)
class Figure:
    """One built-in figure: ``figure(problem, notation=language, **options)``.

    Parameters
    ----------
    name : str
        The figure's name (its golden file is ``gallery/<name>.svg``).
    problem : str
        ``kind:key`` of the problem it draws, see :func:`problem`.
    figure : str
        ``module.function`` under :mod:`graphmethods.sheets`.
    language : {"en", "ru", "zh"}
        The notation.
    options : mapping
        The figure function's other keyword arguments.
    about : str
        What the figure shows, one or two sentences.
    png : bool
        The README shows its PNG too (``--regenerate`` rewrites it).
    """

    name: str
    problem: str
    figure: str
    language: str
    options: Mapping[str, Any] = field(default_factory=dict)
    about: str = ""
    png: bool = False

    @property
    def PNG(self) -> bool:      # the attribute name a gallery script of --dir uses
        return self.png

    def build(self) -> Any:
        """The figure's Scene."""
        module, function = self.figure.rsplit(".", 1)
        draw: Callable[..., Any] = getattr(importlib.import_module(f"graphmethods.sheets.{module}"), function)
        source = problem(self.problem)
        args, kwargs = (source.args, source.kwargs) if isinstance(source, Call) else ((source,), {})
        return draw(*args, **kwargs, notation=self.language, **self.options)


@dataclass(frozen=True)
class Call:
    """A problem that a figure function takes as several arguments."""

    args: tuple[Any, ...]
    kwargs: Mapping[str, Any] = field(default_factory=dict)


def _three_mass_drive() -> Any:
    from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain

    return reduce_chain([Mass("motor", 0.08, 6.0, 30.0), Mass("gear", 0.5, 2.0), Mass("crank", 12.0, 1.0, -160.0)],
                        [Shaft("motor shaft", 2.0e3, 6.0), Shaft("output shaft", 4.0e4, 1.0)])


def _w1_flywheels() -> Call:
    """W1's J_F = 43.69 kg·m² at 600 rev/min as a rim and as a disc of mean diameter 750 mm."""
    from graphmethods.dynamics.flywheel import disc_flywheel, rim_flywheel

    J_F = 900 * 575 / (3.141592653589793**2 * 600**2 / 300)
    return Call((rim_flywheel(J_F, n_rpm=600.0, D=0.75), disc_flywheel(J_F, D=0.75, n_rpm=600.0)))


def _w1_hyperbola() -> Call:
    from graphmethods import problems
    from graphmethods.dynamics.flywheel import mean_speed

    w1 = problems.w1()
    return Call((w1.excess_work.delta_W_max,), dict(omega_m=mean_speed(n_rpm=w1.n_rpm), J_e=w1.J_e,
                                                     machine="ac-generator",
                                                     problem=f"{w1.id}, n = {w1.n_rpm:g} rev/min"))


_OTHERS: Mapping[str, Callable[[], Any]] = MappingProxyType({
    "drive:three-mass-drive": _three_mass_drive, "flywheels:w1": _w1_flywheels, "hyperbola:w1": _w1_hyperbola,
})


def problem(key: str) -> Any:
    """The problem a row draws, by ``kind:key``.

    ``case:NAME`` a built-in linkage (:func:`graphmethods.problems.builtin.case`); ``study:NAME`` its
    :class:`~graphmethods.dynamics.study.Study` at 12 positions; ``cycle:w1`` … ``cycle:w4-exact`` a
    worked example; ``cam:NAME`` a built-in cam problem; ``variant:KIND`` worksheet variant 1 of seed 7; and the
    few of their own
    (``drive:three-mass-drive``, ``flywheels:w1``, ``hyperbola:w1``).
    """
    kind, _, name = key.partition(":")
    if kind in ("case", "study"):
        from graphmethods.problems import builtin

        case = builtin.case(name)
        if kind == "case":
            return case
        from graphmethods.dynamics.study import Study

        return Study(case, positions=12)
    if kind == "cycle":
        from graphmethods import problems

        return getattr(problems, name.replace("-", "_"))()
    if kind == "cam":
        from graphmethods.problems import builtin

        return builtin.cam_problem(name)
    if kind == "variant":
        from graphmethods.sheets import worksheets

        return worksheets.variant(name, seed=7, number=1)
    if key in _OTHERS:
        return _OTHERS[key]()
    raise InputError(f"no gallery problem {key!r}")


def _F(name: str, problem: str, figure: str, language: str, options: Mapping[str, Any], about: str, *,
       png: bool = False) -> Figure:
    return Figure(name, problem, figure, language, MappingProxyType(dict(options)), about, png)


CATALOGUE: tuple[Figure, ...] = (
    _F("shaper_cam_sheet_en", "cam:shaper-cam", "cam_sheet.cam_sheet", "en", {},
       "The shaper's table-feed cam on its A1 sheet: d²s/dφ² integrated twice by chords, the combined ds/dφ–s "
       "diagram with the tangents at [α] and the zone of the cam centre, α(φ), the profile by inversion, the "
       "results.", png=True),
    _F("oscillating_cam_sheet_zh", "cam:oscillating-cam", "cam_sheet.cam_sheet", "zh", {},
       "The oscillating roller follower's cam on its A1 sheet, Chinese notation: the motion diagrams by chords, "
       "the rocker's combined diagram (l·dψ/dφ along the arm, the tangents at [α], the zone of the cam centre), α(φ), "
       "the profile by inversion with the pivot's arc.", png=True),
    _F("shaper_cam_motion_diagrams_en", "cam:shaper-cam", "cam_figures.cam_motion_diagrams", "en", {},
       "The shaper cam's motion diagrams on A4: d²s/dφ² with its 8 strips per phase and the pole P₁, ds/dφ and s "
       "by the method of chords."),
    _F("oscillating_cam_motion_diagrams_ru", "cam:oscillating-cam", "cam_figures.cam_motion_diagrams", "ru", {},
       "The rocker's swing: d²ψ/dφ², dψ/dφ and ψ by the method of chords, Russian notation, A4."),
    _F("shaper_cam_combined_diagram_en", "cam:shaper-cam", "cam_figures.cam_combined_diagram", "en", {},
       "The combined ds/dφ–s diagram of the shaper cam on A4: the tangents at [α] = 30° and [α]_return = 70°, the "
       "admissible zone of the cam centre and O on its edge at the designed r₀."),
    _F("oscillating_cam_combined_diagram_ru", "cam:oscillating-cam", "cam_figures.cam_combined_diagram", "ru", {},
       "The rocker's combined diagram on A4: the arc of the roller centre about the pivot A, l·dψ/dφ laid along each "
       "arm position, the tangent lines at [ϑ], the zone of the cam centre and O where the circle of radius a about "
       "A meets its edge (the designed r₀), Russian notation.", png=True),
    _F("shaper_cam_pressure_angle_zh", "cam:shaper-cam", "cam_figures.cam_pressure_angle", "zh", {},
       "The pressure angle α(φ) of the shaper cam over the cycle with ±[α] and −[α]_return, Chinese notation, A4."),
    _F("oscillating_cam_profile_zh", "cam:oscillating-cam", "cam_sheet.cam_inversion", "zh", {},
       "The rocker cam's profile by inversion on A4: the pivot's arc, the arm in each turned-back position, the "
       "pitch curve, the rollers and their envelope, the largest pressure angle, Chinese notation."),
    _F("drive_scheme_en", "drive:three-mass-drive", "drive_scheme.drive_scheme", "en", {},
       "A three-mass drive (motor 0.08 kg·m² at 6ω, intermediate gear 0.5 kg·m² at 2ω, crankshaft 12 kg·m²; shafts "
       "2000 N·m/rad at 6ω and 40 000 N·m/rad at ω) and its scheme reduced to the crankshaft, English notation."),
    _F("drive_scheme_ru", "drive:three-mass-drive", "drive_scheme.drive_scheme", "ru", {},
       "A three-mass drive (motor 0.08 kg·m² at 6ω, intermediate gear 0.5 kg·m² at 2ω, crankshaft 12 "
       "kg·m²; shafts 2000 N·m/rad at 6ω and 40 000 N·m/rad at ω) and its scheme reduced to the "
       "crankshaft, Russian notation.", png=True),
    _F("engine_cycle_panels_zh", "study:engine", "cycle_panels.linkage_panels", "zh", {},
       "The single-cylinder engine: the gas moment from the indicator diagram (M_d, a curve) against the "
       "generator's constant M_r, ΔE and ω of the exact steady cycle on one φ axis, Chinese notation.", png=True),
    _F("engine_dynamic_analysis_ru", "study:engine", "wittenbauer.dynamic_analysis_sheet", "ru", dict(page='A2'),
       "The single-cylinder engine's dynamic-analysis sheet (A2): M_d (gas) and M_r, ΔT, J_e turned 90°, the "
       "energy–mass diagram and the flywheel from kl, Russian notation."),
    _F("engine_moment_graph_en", "study:engine", "dynamics.moment_graph", "en", {},
       "The single-cylinder engine: the gas moment from the indicator diagram as the driving moment M_d "
       "(chords through 12 positions, negative on the compression stroke) against the generator's "
       "constant resisting moment M_r from the work balance, English notation.", png=True),
    _F("flywheel_design_ru", "flywheels:w1", "flywheel_design.flywheel_design", "ru", {},
       "W1's flywheel (J_F = 43.69 kg·m² at 600 rev/min) as a cast-iron rim flywheel of mean diameter "
       "750 mm and as a steel disc of the same diameter: sections to scale, dimensioned, with masses, "
       "mD² and rim speeds, Russian notation.", png=True),
    _F("flywheel_design_zh", "flywheels:w1", "flywheel_design.flywheel_design", "zh", {},
       "W1's flywheel (J_F = 43.69 kg·m² at 600 rev/min) as a cast-iron rim flywheel of mean diameter 750 mm and as "
       "a steel disc of the same diameter: sections to scale, dimensioned, with masses, mD² and rim speeds, Chinese "
       "notation."),
    _F("four_bar_acceleration_plan_en", "case:four-bar", "acceleration.acceleration_plan", "en", {},
       "Crank-rocker four-bar (problems/data/four_bar_rocker.json): one large acceleration plan with its "
       "construction lines, the equations under it, the table of vector lengths and ε of the links, English "
       "notation."),
    _F("four_bar_force_analysis_en", "case:four-bar",
       "force_analysis_sheet.force_analysis_sheet", "en", dict(position=2, page='A1'),
       "The crank-rocker four-bar: the A1 force-analysis sheet of position 2 (the course project's second sheet: the "
       "scheme with every force, Zhukovsky's lever, the force plan of each group with each link's own polygon, the "
       "result table of the balancing moment three ways); notation en."),
    _F("four_bar_force_plans_en", "case:four-bar", "forces.force_plans", "en", dict(position=2),
       "The four-bar problem: the force plans of every group and of the crank in position 2, at one μ_F, with every "
       "reaction and the balancing moment three ways (force plans, Zhukovsky's lever, power)."),
    _F("four_bar_force_scheme_en", "case:four-bar", "forces.force_scheme", "en", dict(position=2, gravity=True),
       "The four-bar problem in position 2 with every force on it: inertia forces and moments, weights, the working "
       "load, and the balancing moment on the crank."),
    _F("four_bar_kinematic_analysis_en", "case:four-bar",
       "kinematic_analysis_sheet.kinematic_analysis_sheet", "en", dict(page='A1'),
       "The crank-rocker four-bar: the A1 kinematic-analysis sheet (the course project's first sheet: the scheme in "
       "12 positions, the velocity plans, the acceleration plans of a working-stroke and a return-stroke position, "
       "the slider's kinematic diagrams when there is a slider); notation en."),
    _F("four_bar_zhukovsky_forces_en", "case:four-bar", "forces.zhukovsky_forces", "en", dict(position=2),
       "The four-bar problem: Zhukovsky's lever with every force of the force analysis in position 2 (inertia "
       "forces, moments as pairs of forces, the load) and the balancing force at the image of the crank pin."),
    _F("press_acceleration_graph_en", "study:press", "dynamics.acceleration_graph", "en", {},
       "The press: crank angular acceleration ε(φ) of the exact motion (it jumps where the force switches), the "
       "largest |ε| and Artobolevsky's χ, English notation."),
    _F("press_acceleration_plan_en", "case:press", "acceleration.acceleration_plan", "en", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): one large acceleration plan "
       "with its construction lines, the equations under it, the table of vector lengths and ε of the "
       "links, English notation.", png=True),
    _F("press_acceleration_plan_ru", "case:press", "acceleration.acceleration_plan", "ru", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): one large acceleration plan with its "
       "construction lines, the equations under it, the table of vector lengths and ε of the links, Russian "
       "notation."),
    _F("press_acceleration_plan_zh", "case:press", "acceleration.acceleration_plan", "zh", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): one large acceleration plan with its "
       "construction lines, the equations under it, the table of vector lengths and ε of the links, Chinese "
       "notation."),
    _F("press_acceleration_plans_en", "case:press", "acceleration.acceleration_plan_grid", "en", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the acceleration plans of all positions "
       "to one μ_a, English notation."),
    _F("press_acceleration_plans_ru", "case:press", "acceleration.acceleration_plan_grid", "ru", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the acceleration plans of all positions "
       "to one μ_a, Russian notation."),
    _F("press_acceleration_plans_zh", "case:press", "acceleration.acceleration_plan_grid", "zh", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the acceleration plans of all positions "
       "to one μ_a, Chinese notation."),
    _F("press_acceleration_table_en", "case:press", "acceleration.acceleration_table", "en", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the accelerations of the points and links "
       "per position, English notation."),
    _F("press_acceleration_table_ru", "case:press", "acceleration.acceleration_table", "ru", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the accelerations of the points and links "
       "per position, Russian notation."),
    _F("press_acceleration_table_zh", "case:press", "acceleration.acceleration_table", "zh", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the accelerations of the points and links "
       "per position, Chinese notation."),
    _F("press_cycle_panels_en", "study:press", "cycle_panels.linkage_panels", "en", {},
       "The press: M_d and M_r, ΔE and ω of the exact steady cycle (exact flywheel for [δ] = 0.04) one above the "
       "other on one φ axis, the Chinese chapter's three-panel figure, English notation."),
    _F("press_delta_T_graph_en", "study:press", "dynamics.delta_T_graph", "en", {},
       "The press: increment of kinetic energy ΔT(φ) of the drawn moments, its extremes marked, English notation."),
    _F("press_dynamic_analysis_en", "study:press", "wittenbauer.dynamic_analysis_sheet", "en", dict(page='A1'),
       "The press at 12 positions: the A1 dynamic-analysis sheet (M_d, M_r; ΔT; J_e turned 90°; the energy–mass "
       "diagram with projection lines, rays, k, l, kl; the result table); notation en."),
    _F("press_dynamic_analysis_ru", "study:press", "wittenbauer.dynamic_analysis_sheet", "ru", dict(page='A1'),
       "The press at 12 positions: the A1 dynamic-analysis sheet (M_d, M_r; ΔT; J_e turned 90°; the energy–mass "
       "diagram with projection lines, rays, k, l, kl; the result table); notation ru."),
    _F("press_dynamic_analysis_zh", "study:press", "wittenbauer.dynamic_analysis_sheet", "zh", dict(page='A1'),
       "The press at 12 positions: the A1 dynamic-analysis sheet (M_d, M_r; ΔT; J_e turned 90°; the energy–mass "
       "diagram with projection lines, rays, k, l, kl; the result table); notation zh."),
    _F("press_force_analysis_en", "case:press",
       "force_analysis_sheet.force_analysis_sheet", "en", dict(position=3, page='A1'),
       "The press: the A1 force-analysis sheet of position 3 (the course project's second sheet: the scheme with "
       "every force, Zhukovsky's lever, the force plan of each group with each link's own polygon, the result table "
       "of the balancing moment three ways); notation en."),
    _F("press_force_analysis_ru", "case:press",
       "force_analysis_sheet.force_analysis_sheet", "ru", dict(position=3, page='A1'),
       "The press: the A1 force-analysis sheet of position 3 (the course project's second sheet: the scheme with "
       "every force, Zhukovsky's lever, the force plan of each group with each link's own polygon, the result table "
       "of the balancing moment three ways); notation ru."),
    _F("press_force_analysis_zh", "case:press",
       "force_analysis_sheet.force_analysis_sheet", "zh", dict(position=3, page='A1'),
       "The press: the A1 force-analysis sheet of position 3 (the course project's second sheet: the scheme with "
       "every force, Zhukovsky's lever, the force plan of each group with each link's own polygon, the result table "
       "of the balancing moment three ways); notation zh."),
    _F("press_force_plans_en", "case:press", "forces.force_plans", "en", dict(position=3),
       "The press problem: the force plans of every group and of the crank in position 3, at one μ_F, with every "
       "reaction and the balancing moment three ways (force plans, Zhukovsky's lever, power)."),
    _F("press_force_plans_ru", "case:press", "forces.force_plans", "ru", dict(position=3),
       "The press problem: the force plans of every group and of the crank in position 3, at one μ_F, with every "
       "reaction and the balancing moment three ways (force plans, Zhukovsky's lever, power)."),
    _F("press_force_plans_zh", "case:press", "forces.force_plans", "zh", dict(position=3),
       "The press problem: the force plans of every group and of the crank in position 3, at one μ_F, with every "
       "reaction and the balancing moment three ways (force plans, Zhukovsky's lever, power)."),
    _F("press_force_scheme_en", "case:press", "forces.force_scheme", "en", dict(position=3, gravity=True),
       "The press problem in position 3 with every force on it: inertia forces and moments, weights, the working "
       "load, and the balancing moment on the crank."),
    _F("press_force_scheme_ru", "case:press", "forces.force_scheme", "ru", dict(position=3, gravity=True),
       "The press problem in position 3 with every force on it: inertia forces and moments, weights, the working "
       "load, and the balancing moment on the crank."),
    _F("press_force_scheme_zh", "case:press", "forces.force_scheme", "zh", dict(position=3, gravity=True),
       "The press problem in position 3 with every force on it: inertia forces and moments, weights, the working "
       "load, and the balancing moment on the crank."),
    _F("press_inertia_graph_en", "study:press", "dynamics.inertia_graph", "en", {},
       "The press (offset slider-crank, 12 positions): reduced moment of inertia J_e(φ) and the share of each moving "
       "mass, English notation."),
    _F("press_inertia_turned_en", "study:press", "dynamics.inertia_graph", "en", dict(turned=True),
       "The press: J_e(φ) turned 90° (φ down the page, J_e to the right from 0), ready to project J_e values onto "
       "the energy–mass diagram, English notation."),
    _F("press_kinematic_analysis_en", "case:press",
       "kinematic_analysis_sheet.kinematic_analysis_sheet", "en", dict(page='A1'),
       "The press: the A1 kinematic-analysis sheet (the course project's first sheet: the scheme in 12 positions, "
       "the velocity plans, the acceleration plans of a working-stroke and a return-stroke position, the slider's "
       "kinematic diagrams when there is a slider); notation en."),
    _F("press_kinematic_analysis_ru", "case:press",
       "kinematic_analysis_sheet.kinematic_analysis_sheet", "ru", dict(page='A1'),
       "The press: the A1 kinematic-analysis sheet (the course project's first sheet: the scheme in 12 positions, "
       "the velocity plans, the acceleration plans of a working-stroke and a return-stroke position, the slider's "
       "kinematic diagrams when there is a slider); notation ru."),
    _F("press_kinematic_analysis_zh", "case:press",
       "kinematic_analysis_sheet.kinematic_analysis_sheet", "zh", dict(page='A1'),
       "The press: the A1 kinematic-analysis sheet (the course project's first sheet: the scheme in 12 positions, "
       "the velocity plans, the acceleration plans of a working-stroke and a return-stroke position, the slider's "
       "kinematic diagrams when there is a slider); notation zh."),
    _F("press_kinematic_diagrams_en", "case:press", "calculus.kinematic_diagrams", "en", dict(m=12),
       "Offset slider-crank press: the slider's s(φ), v(φ), a(φ) by graphical differentiation (poles P₁, "
       "P₂, rays, chords), compared with the velocity plans and the analytic values; English notation.", png=True),
    _F("press_kinematic_diagrams_ru", "case:press", "calculus.kinematic_diagrams", "ru", dict(m=12),
       "Offset slider-crank press: the slider's s(φ), v(φ), a(φ) by graphical differentiation (poles P₁, P₂, rays, "
       "chords), compared with the velocity plans and the analytic values; Russian notation."),
    _F("press_kinematic_diagrams_zh", "case:press", "calculus.kinematic_diagrams", "zh", dict(m=12),
       "Offset slider-crank press: the slider's s(φ), v(φ), a(φ) by graphical differentiation (poles P₁, P₂, rays, "
       "chords), compared with the velocity plans and the analytic values; Chinese notation."),
    _F("press_kinematic_scheme_en", "case:press", "kinematics.kinematic_scheme", "en", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the kinematic scheme in 12 "
       "positions to μ_l (position 0 thick, the extreme positions and the stroke H marked), English "
       "notation.", png=True),
    _F("press_kinematic_scheme_ru", "case:press", "kinematics.kinematic_scheme", "ru", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the kinematic scheme in 12 positions to "
       "μ_l (position 0 thick, the extreme positions and the stroke H marked), Russian notation."),
    _F("press_kinematic_scheme_zh", "case:press", "kinematics.kinematic_scheme", "zh", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the kinematic scheme in 12 positions to "
       "μ_l (position 0 thick, the extreme positions and the stroke H marked), Chinese notation."),
    _F("press_moment_graph_en", "study:press", "dynamics.moment_graph", "en", {},
       "The press: reduced moments M_d (constant, by work balance) and M_r through the 12 positions, as the "
       "graphical method draws them, English notation."),
    _F("press_speed_graph_en", "study:press", "dynamics.speed_graph", "en", {},
       "The press: crank speed ω(φ) of the exact steady motion with the exact flywheel for [δ] = 0.04; "
       "ω_m, ω_max and ω_min marked, English notation.", png=True),
    _F("press_velocity_plan_en", "case:press", "kinematics.velocity_plan", "en", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): one large velocity plan with its "
       "construction lines, the table of vector lengths and the angular velocities, English notation."),
    _F("press_velocity_plan_ru", "case:press", "kinematics.velocity_plan", "ru", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): one large velocity plan with its "
       "construction lines, the table of vector lengths and the angular velocities, Russian notation."),
    _F("press_velocity_plan_zh", "case:press", "kinematics.velocity_plan", "zh", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): one large velocity plan with its "
       "construction lines, the table of vector lengths and the angular velocities, Chinese notation."),
    _F("press_velocity_plans_en", "case:press", "kinematics.velocity_plan_grid", "en", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the velocity plans of all 12 positions on "
       "one sheet to one μ_v, English notation."),
    _F("press_velocity_plans_ru", "case:press", "kinematics.velocity_plan_grid", "ru", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the velocity plans of all 12 positions on "
       "one sheet to one μ_v, Russian notation."),
    _F("press_velocity_plans_zh", "case:press", "kinematics.velocity_plan_grid", "zh", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the velocity plans of all 12 positions on "
       "one sheet to one μ_v, Chinese notation."),
    _F("press_velocity_table_en", "case:press", "kinematics.velocity_table", "en", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the table of velocities per position, "
       "English notation."),
    _F("press_velocity_table_ru", "case:press", "kinematics.velocity_table", "ru", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the table of velocities per position, "
       "Russian notation."),
    _F("press_velocity_table_zh", "case:press", "kinematics.velocity_table", "zh", {},
       "Offset slider-crank press (problems/data/slider_crank_press.json): the table of velocities per position, "
       "Chinese notation."),
    _F("press_wittenbauer_en", "study:press", "wittenbauer.wittenbauer_diagram", "en", {},
       "The press at 12 positions: the Wittenbauer energy–mass diagram alone (A4): rays at ψ_max and "
       "ψ_min from the frame to the curve, k, l and kl, and J_F = μ_T·kl/(ω_m²[δ]); notation en.", png=True),
    _F("press_wittenbauer_ru", "study:press", "wittenbauer.wittenbauer_diagram", "ru", {},
       "The press at 12 positions: the Wittenbauer energy–mass diagram alone (A4): rays at ψ_max and ψ_min from the "
       "frame to the curve, k, l and kl, and J_F = μ_T·kl/(ω_m²[δ]); notation ru."),
    _F("press_wittenbauer_zh", "study:press", "wittenbauer.wittenbauer_diagram", "zh", {},
       "The press at 12 positions: the Wittenbauer energy–mass diagram alone (A4): rays at ψ_max and ψ_min from the "
       "frame to the curve, k, l and kl, and J_F = μ_T·kl/(ω_m²[δ]); notation zh."),
    _F("press_work_diagrams_en", "study:press", "calculus.work_diagrams", "en", {},
       "Offset slider-crank press: M_d, M_r integrated by the method of chords (pole P, H picked) into the work "
       "diagrams A_d(φ), A_r(φ) and ΔE(φ), with the accuracy against the exact integrals; English notation."),
    _F("press_work_diagrams_ru", "study:press", "calculus.work_diagrams", "ru", {},
       "Offset slider-crank press: M_d, M_r integrated by the method of chords (pole P, H picked) into "
       "the work diagrams A_d(φ), A_r(φ) and ΔE(φ), with the accuracy against the exact integrals; "
       "Russian notation.", png=True),
    _F("press_work_diagrams_zh", "study:press", "calculus.work_diagrams", "zh", {},
       "Offset slider-crank press: M_d, M_r integrated by the method of chords (pole P, H picked) into the work "
       "diagrams A_d(φ), A_r(φ) and ΔE(φ), with the accuracy against the exact integrals; Chinese notation."),
    _F("press_zhukovsky_forces_en", "case:press", "forces.zhukovsky_forces", "en", dict(position=3),
       "The press problem: Zhukovsky's lever with every force of the force analysis in position 3 (inertia forces, "
       "moments as pairs of forces, the load) and the balancing force at the image of the crank pin."),
    _F("press_zhukovsky_forces_ru", "case:press", "forces.zhukovsky_forces", "ru", dict(position=3),
       "The press problem: Zhukovsky's lever with every force of the force analysis in position 3 (inertia forces, "
       "moments as pairs of forces, the load) and the balancing force at the image of the crank pin."),
    _F("press_zhukovsky_forces_zh", "case:press", "forces.zhukovsky_forces", "zh", dict(position=3),
       "The press problem: Zhukovsky's lever with every force of the force analysis in position 3 (inertia forces, "
       "moments as pairs of forces, the load) and the balancing force at the image of the crank pin."),
    _F("press_zhukovsky_lever_en", "study:press", "dynamics.zhukovsky_lever", "en", {},
       "The press: Zhukovsky's lever at the clearest loaded position: the velocity plan turned 90°, the cutting "
       "force at the image b, its arm h; M_r = F·h·μ_v/ω₁ equals the power method's, English notation."),
    _F("scotch_yoke_equivalent_mass_ru", "study:scotch-yoke", "translating_graph.equivalent_mass_graph", "ru", {},
       "The oil pump's sine mechanism reduced to its translating yoke: m_e(φ) = m3 + (m2 + J1/r²)/sin²φ, "
       "drawn up to 6 m_e,min (m_e → ∞ at the dead centres), Russian notation.", png=True),
    _F("scotch_yoke_equivalent_mass_zh", "study:scotch-yoke", "translating_graph.equivalent_mass_graph", "zh", {},
       "The oil pump's sine mechanism reduced to its translating yoke: m_e(φ) = m3 + (m2 + J1/r²)/sin²φ, drawn up to "
       "6 m_e,min (m_e → ∞ at the dead centres), Chinese notation."),
    _F("scotch_yoke_kinematic_scheme_en", "case:scotch-yoke", "kinematics.kinematic_scheme", "en", dict(thick=2),
       "The sine mechanism (Scotch yoke) of the oil pump: an RPP group on the frame's guide, the yoke's slot drawn "
       "through C in position 2, 12 positions, English notation."),
    _F("scotch_yoke_kinematic_scheme_zh", "case:scotch-yoke", "kinematics.kinematic_scheme", "zh", dict(thick=2),
       "The sine mechanism (Scotch yoke) of the oil pump: an RPP group on the frame's guide, the yoke's "
       "slot drawn through C in position 2, 12 positions, Chinese notation.", png=True),
    _F("shaper_acceleration_plan_en", "case:shaper", "acceleration.acceleration_plan", "en", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): one large acceleration plan with "
       "its construction lines, the equations under it, the table of vector lengths and ε of the links, English "
       "notation."),
    _F("shaper_acceleration_plan_ru", "case:shaper", "acceleration.acceleration_plan", "ru", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): one large acceleration plan with "
       "its construction lines, the equations under it, the table of vector lengths and ε of the links, Russian "
       "notation."),
    _F("shaper_acceleration_plan_zh", "case:shaper", "acceleration.acceleration_plan", "zh", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): one large acceleration plan with "
       "its construction lines, the equations under it, the table of vector lengths and ε of the links, Chinese "
       "notation."),
    _F("shaper_acceleration_plans_en", "case:shaper", "acceleration.acceleration_plan_grid", "en", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the acceleration plans of all "
       "positions to one μ_a, English notation."),
    _F("shaper_acceleration_plans_ru", "case:shaper", "acceleration.acceleration_plan_grid", "ru", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the acceleration plans of all "
       "positions to one μ_a, Russian notation."),
    _F("shaper_acceleration_plans_zh", "case:shaper", "acceleration.acceleration_plan_grid", "zh", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the acceleration plans of all "
       "positions to one μ_a, Chinese notation."),
    _F("shaper_acceleration_table_en", "case:shaper", "acceleration.acceleration_table", "en", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the accelerations of the points "
       "and links per position, English notation."),
    _F("shaper_acceleration_table_ru", "case:shaper", "acceleration.acceleration_table", "ru", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the accelerations of the points "
       "and links per position, Russian notation."),
    _F("shaper_acceleration_table_zh", "case:shaper", "acceleration.acceleration_table", "zh", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the accelerations of the points "
       "and links per position, Chinese notation."),
    _F("shaper_force_analysis_en", "case:shaper",
       "force_analysis_sheet.force_analysis_sheet", "en", dict(position=3, page='A1'),
       "The shaper: the A1 force-analysis sheet of position 3 (the course project's second sheet: the scheme with "
       "every force, Zhukovsky's lever, the force plan of each group with each link's own polygon, the result table "
       "of the balancing moment three ways); notation en."),
    _F("shaper_force_plans_en", "case:shaper", "forces.force_plans", "en", dict(position=2),
       "The shaper problem: the force plans of every group and of the crank in position 2, at one μ_F, with every "
       "reaction and the balancing moment three ways (force plans, Zhukovsky's lever, power)."),
    _F("shaper_force_scheme_en", "case:shaper", "forces.force_scheme", "en", dict(position=2, gravity=True),
       "The shaper problem in position 2 with every force on it: inertia forces and moments, weights, the working "
       "load, and the balancing moment on the crank."),
    _F("shaper_kinematic_analysis_en", "case:shaper",
       "kinematic_analysis_sheet.kinematic_analysis_sheet", "en", dict(page='A1'),
       "The shaper: the A1 kinematic-analysis sheet (the course project's first sheet: the scheme in 12 positions, "
       "the velocity plans, the acceleration plans of a working-stroke and a return-stroke position, the slider's "
       "kinematic diagrams when there is a slider); notation en."),
    _F("shaper_kinematic_scheme_en", "case:shaper", "kinematics.kinematic_scheme", "en", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the kinematic scheme in 12 "
       "positions to μ_l (position 0 thick, the extreme positions and the stroke H marked), English notation."),
    _F("shaper_kinematic_scheme_ru", "case:shaper", "kinematics.kinematic_scheme", "ru", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the kinematic scheme in 12 "
       "positions to μ_l (position 0 thick, the extreme positions and the stroke H marked), Russian notation."),
    _F("shaper_kinematic_scheme_zh", "case:shaper", "kinematics.kinematic_scheme", "zh", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the kinematic scheme in 12 "
       "positions to μ_l (position 0 thick, the extreme positions and the stroke H marked), Chinese notation."),
    _F("shaper_velocity_plan_en", "case:shaper", "kinematics.velocity_plan", "en", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): one large velocity plan with its "
       "construction lines, the table of vector lengths and the angular velocities, English notation."),
    _F("shaper_velocity_plan_ru", "case:shaper", "kinematics.velocity_plan", "ru", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): one large velocity "
       "plan with its construction lines, the table of vector lengths and the angular velocities, "
       "Russian notation.", png=True),
    _F("shaper_velocity_plan_zh", "case:shaper", "kinematics.velocity_plan", "zh", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): one large velocity plan with its "
       "construction lines, the table of vector lengths and the angular velocities, Chinese notation."),
    _F("shaper_velocity_plans_en", "case:shaper", "kinematics.velocity_plan_grid", "en", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the velocity plans of all 12 "
       "positions on one sheet to one μ_v, English notation."),
    _F("shaper_velocity_plans_ru", "case:shaper", "kinematics.velocity_plan_grid", "ru", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the velocity plans of all 12 "
       "positions on one sheet to one μ_v, Russian notation."),
    _F("shaper_velocity_plans_zh", "case:shaper", "kinematics.velocity_plan_grid", "zh", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the velocity plans of all 12 "
       "positions on one sheet to one μ_v, Chinese notation."),
    _F("shaper_velocity_table_en", "case:shaper", "kinematics.velocity_table", "en", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the table of velocities per "
       "position, English notation."),
    _F("shaper_velocity_table_ru", "case:shaper", "kinematics.velocity_table", "ru", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the table of velocities per "
       "position, Russian notation."),
    _F("shaper_velocity_table_zh", "case:shaper", "kinematics.velocity_table", "zh", {},
       "Shaper: slotted lever, connecting link and ram (problems/data/shaper.json): the table of velocities per "
       "position, Chinese notation."),
    _F("shaper_zhukovsky_forces_en", "case:shaper", "forces.zhukovsky_forces", "en", dict(position=2),
       "The shaper problem: Zhukovsky's lever with every force of the force analysis in position 2 (inertia forces, "
       "moments as pairs of forces, the load) and the balancing force at the image of the crank pin."),
    _F("six_bar_press_acceleration_plan_en", "case:six-bar-press", "acceleration.acceleration_plan", "en", {},
       "Six-bar press (a course mechanism: four-bar driving a ram) (problems/data/six_bar_press.json): one large "
       "acceleration plan with its construction lines, the equations under it, the table of vector lengths and ε of "
       "the links, English notation."),
    _F("six_bar_press_force_analysis_en", "case:six-bar-press",
       "force_analysis_sheet.force_analysis_sheet", "en", dict(position=2, page='A1'),
       "The six-bar press: the A1 force-analysis sheet of position 2 (the course project's second sheet: the scheme "
       "with every force, Zhukovsky's lever, the force plan of each group with each link's own polygon, the result "
       "table of the balancing moment three ways); notation en."),
    _F("six_bar_press_kinematic_analysis_en", "case:six-bar-press",
       "kinematic_analysis_sheet.kinematic_analysis_sheet", "en", dict(page='A1'),
       "The six-bar press: the A1 kinematic-analysis sheet (the course project's first sheet: the scheme in 12 "
       "positions, the velocity plans, the acceleration plans of a working-stroke and a return-stroke position, the "
       "slider's kinematic diagrams when there is a slider); notation en."),
    _F("six_bar_press_structure_en", "case:six-bar-press", "structure_diagram.structure_diagram", "en", {},
       "The six-bar press split into its driver and its Assur groups, each apart to one scale with its outer pairs "
       "marked, the structural formula, W and the class (the structural-analysis chapter's figure); "
       "English notation."),
    _F("slotted_lever_acceleration_plan_en", "case:slotted-lever", "acceleration.acceleration_plan", "en", {},
       "Crank and oscillating slotted lever (Coriolis) (problems/data/slotted_lever.json): one large acceleration "
       "plan with its construction lines, the equations under it, the table of vector lengths and ε of the links, "
       "English notation."),
    _F("triad_six_bar_structure_en", "case:triad-six-bar", "structure_diagram.structure_diagram", "en", {},
       "The class III six-bar (problems/data/triad_six_bar.json) split into its driver and its Assur groups, "
       "each apart to one scale with its outer pairs "
       "marked, the structural formula, W and the class (the structural-analysis chapter's figure); "
       "English notation.", png=True),
    _F("triad_six_bar_structure_ru", "case:triad-six-bar", "structure_diagram.structure_diagram", "ru", {},
       "The class III six-bar (problems/data/triad_six_bar.json) split into its driver and its Assur groups, "
       "each apart to one scale with its outer pairs "
       "marked, the structural formula, W and the class (the structural-analysis chapter's figure); "
       "Russian notation."),
    _F("triad_six_bar_structure_zh", "case:triad-six-bar", "structure_diagram.structure_diagram", "zh", {},
       "The class III six-bar (problems/data/triad_six_bar.json) split into its driver and its Assur groups, "
       "each apart to one scale with its outer pairs "
       "marked, the structural formula, W and the class (the structural-analysis chapter's figure); "
       "Chinese notation."),
    _F("w1_energy_indicator_en", "cycle:w1", "energy.energy_indicator", "en", {},
       "W1 (diesel generator, areas only): energy indicator diagram (staircase of excess works), English notation."),
    _F("w1_energy_indicator_ru", "cycle:w1", "energy.energy_indicator", "ru", {},
       "W1 (diesel generator, areas only): energy indicator diagram (staircase of excess works), Russian notation."),
    _F("w1_energy_indicator_zh", "cycle:w1", "energy.energy_indicator", "zh", {},
       "W1 (diesel generator, areas only): energy indicator diagram (staircase of excess works), Chinese "
       "notation.", png=True),
    _F("w1_excess_work_table_en", "cycle:w1", "energy.excess_work_table", "en", {},
       "W1 (diesel generator, areas only): excess-work table, English notation."),
    _F("w1_excess_work_table_ru", "cycle:w1", "energy.excess_work_table", "ru", {},
       "W1 (diesel generator, areas only): excess-work table, Russian notation."),
    _F("w1_excess_work_table_zh", "cycle:w1", "energy.excess_work_table", "zh", {},
       "W1 (diesel generator, areas only): excess-work table, Chinese notation."),
    _F("w1_flywheel_hyperbola_en", "hyperbola:w1", "flywheel_hyperbola.flywheel_hyperbola", "en", {},
       "W1 (diesel generator, ΔW_max from its excess-work table, n = 600 rev/min): the J_F–[δ] hyperbola over the "
       "table's range of recommended [δ], the AC generator's row as a band and its strict end [δ] = 1/300 marked "
       "with J_F, English notation."),
    _F("w2_energy_indicator_en", "cycle:w2", "energy.energy_indicator", "en", {},
       "W2 (engine crankshaft, points a…h): energy indicator diagram (staircase of excess works), English notation."),
    _F("w2_energy_indicator_ru", "cycle:w2", "energy.energy_indicator", "ru", {},
       "W2 (engine crankshaft, points a…h): energy indicator diagram (staircase of excess works), Russian notation."),
    _F("w2_energy_indicator_zh", "cycle:w2", "energy.energy_indicator", "zh", {},
       "W2 (engine crankshaft, points a…h): energy indicator diagram (staircase of excess works), Chinese notation."),
    _F("w2_excess_work_table_en", "cycle:w2", "energy.excess_work_table", "en", {},
       "W2 (engine crankshaft, points a…h): excess-work table, English notation."),
    _F("w2_excess_work_table_ru", "cycle:w2", "energy.excess_work_table", "ru", {},
       "W2 (engine crankshaft, points a…h): excess-work table, Russian notation."),
    _F("w2_excess_work_table_zh", "cycle:w2", "energy.excess_work_table", "zh", {},
       "W2 (engine crankshaft, points a…h): excess-work table, Chinese notation."),
    _F("w3_energy_graph_en", "cycle:w3", "energy.energy_graph", "en", {},
       "W3 (step resisting moment, M_d by work balance): energy graph ΔE(φ), English notation."),
    _F("w3_energy_graph_ru", "cycle:w3", "energy.energy_graph", "ru", {},
       "W3 (step resisting moment, M_d by work balance): energy graph ΔE(φ), Russian notation."),
    _F("w3_energy_graph_zh", "cycle:w3", "energy.energy_graph", "zh", {},
       "W3 (step resisting moment, M_d by work balance): energy graph ΔE(φ), Chinese notation."),
    _F("w3_energy_indicator_en", "cycle:w3", "energy.energy_indicator", "en", {},
       "W3 (step resisting moment, M_d by work balance): energy indicator diagram (staircase of excess works), "
       "English notation."),
    _F("w3_energy_indicator_ru", "cycle:w3", "energy.energy_indicator", "ru", {},
       "W3 (step resisting moment, M_d by work balance): energy indicator diagram (staircase of excess works), "
       "Russian notation."),
    _F("w3_energy_indicator_zh", "cycle:w3", "energy.energy_indicator", "zh", {},
       "W3 (step resisting moment, M_d by work balance): energy indicator diagram (staircase of excess works), "
       "Chinese notation."),
    _F("w3_excess_work_table_en", "cycle:w3", "energy.excess_work_table", "en", {},
       "W3 (step resisting moment, M_d by work balance): excess-work table, English notation."),
    _F("w3_excess_work_table_ru", "cycle:w3", "energy.excess_work_table", "ru", {},
       "W3 (step resisting moment, M_d by work balance): excess-work table, Russian notation."),
    _F("w3_excess_work_table_zh", "cycle:w3", "energy.excess_work_table", "zh", {},
       "W3 (step resisting moment, M_d by work balance): excess-work table, Chinese notation."),
    _F("w3_moment_diagram_en", "cycle:w3", "energy.moment_diagram", "en", {},
       "W3 (step resisting moment, M_d by work balance): moment diagram M_d, M_r with hatched excess- "
       "work areas, English notation.", png=True),
    _F("w3_moment_diagram_ru", "cycle:w3", "energy.moment_diagram", "ru", {},
       "W3 (step resisting moment, M_d by work balance): moment diagram M_d, M_r with hatched excess- work areas, "
       "Russian notation."),
    _F("w3_moment_diagram_zh", "cycle:w3", "energy.moment_diagram", "zh", {},
       "W3 (step resisting moment, M_d by work balance): moment diagram M_d, M_r with hatched excess- work areas, "
       "Chinese notation."),
    _F("w3_work_diagrams_en", "cycle:w3", "calculus.work_diagrams", "en", dict(m=12),
       "W3 (step resisting moment): work diagrams by the method of chords over 12 intervals; the jump lies inside an "
       "interval, so the integral is exact at the interval ends and errs only inside; English notation."),
    _F("w4_cycle_panels_ru", "cycle:w4-exact", "cycle_panels.cycle_panels", "ru", {},
       "W4 (exact data, J_e = 0.8, ω0 = 10 s⁻¹): M_d and M_r, ΔE and ω(φ) on one φ axis, Russian notation."),
    _F("w4_energy_graph_en", "cycle:w4-exact",
       "energy.energy_graph", "en", dict(J_e=0.8, omega_0=10.0, work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): kinetic-energy graph T(φ) = T0 + ΔE(φ) from ω0 = 10 s⁻¹, "
       "J_e = 0.8, English notation."),
    _F("w4_energy_graph_ru", "cycle:w4-exact",
       "energy.energy_graph", "ru", dict(J_e=0.8, omega_0=10.0, work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): kinetic-energy graph T(φ) = T0 + ΔE(φ) from "
       "ω0 = 10 s⁻¹, J_e = 0.8, Russian notation.", png=True),
    _F("w4_energy_graph_zh", "cycle:w4-exact",
       "energy.energy_graph", "zh", dict(J_e=0.8, omega_0=10.0, work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): kinetic-energy graph T(φ) = T0 + ΔE(φ) from ω0 = 10 s⁻¹, "
       "J_e = 0.8, Chinese notation."),
    _F("w4_energy_indicator_en", "cycle:w4-exact", "energy.energy_indicator", "en", dict(work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): energy indicator diagram (staircase of excess works), "
       "English notation."),
    _F("w4_energy_indicator_ru", "cycle:w4-exact", "energy.energy_indicator", "ru", dict(work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): energy indicator diagram (staircase of excess works), "
       "Russian notation."),
    _F("w4_energy_indicator_zh", "cycle:w4-exact", "energy.energy_indicator", "zh", dict(work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): energy indicator diagram (staircase of excess works), "
       "Chinese notation."),
    _F("w4_excess_work_table_en", "cycle:w4-drawing",
       "energy.excess_work_table", "en", dict(work_unit='kG·m', moment_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): excess-work table, English notation. As drawn in the "
       "lecture: areas in mm² at μ_M = 1 kG·m/mm, μ_φ = 0.075 rad/mm (π taken as 3)."),
    _F("w4_excess_work_table_ru", "cycle:w4-drawing",
       "energy.excess_work_table", "ru", dict(work_unit='kG·m', moment_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): excess-work table, Russian notation. As drawn in the "
       "lecture: areas in mm² at μ_M = 1 kG·m/mm, μ_φ = 0.075 rad/mm (π taken as 3)."),
    _F("w4_excess_work_table_zh", "cycle:w4-drawing",
       "energy.excess_work_table", "zh", dict(work_unit='kG·m', moment_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): excess-work table, Chinese notation. As drawn in the "
       "lecture: areas in mm² at μ_M = 1 kG·m/mm, μ_φ = 0.075 rad/mm (π taken as 3)."),
    _F("w4_moment_diagram_en", "cycle:w4-exact",
       "energy.moment_diagram", "en", dict(moment_unit='kG·m', work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): moment diagram M_d, M_r with hatched excess- work areas, "
       "English notation."),
    _F("w4_moment_diagram_ru", "cycle:w4-exact",
       "energy.moment_diagram", "ru", dict(moment_unit='kG·m', work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): moment diagram M_d, M_r with hatched excess- work areas, "
       "Russian notation."),
    _F("w4_moment_diagram_zh", "cycle:w4-exact",
       "energy.moment_diagram", "zh", dict(moment_unit='kG·m', work_unit='kG·m'),
       "W4 (triangular M_r, M_d = 20 kG·m; old units kG·m): moment diagram M_d, M_r with hatched excess- "
       "work areas, Chinese notation.", png=True),
    _F("whitworth_acceleration_plan_zh", "case:whitworth", "acceleration.acceleration_plan", "zh", {},
       "Whitworth quick-return mechanism (a course mechanism: rotating slotted lever and ram) "
       "(problems/data/whitworth_quick_return.json): one large acceleration plan with its construction lines, the "
       "equations under it, the table of vector lengths and ε of the links, Chinese notation."),
    _F("worksheet_indicator_key_en", "variant:indicator", "worksheets.key_page", "en", {},
       "Worksheet \"indicator\" (W1 style: areas → energy indicator, ΔW_max, J_F), variant 1 of seed 7: "
       "the answer key (the student's page filled in), English notation.", png=True),
    _F("worksheet_indicator_student_en", "variant:indicator", "worksheets.student_page", "en", {},
       "Worksheet \"indicator\" (W1 style: areas → energy indicator, ΔW_max, J_F), variant 1 of seed 7: the student's "
       "page, English notation."),
    _F("worksheet_step_moment_key_ru", "variant:step-moment", "worksheets.key_page", "ru", {},
       "Worksheet \"step-moment\" (W3 style: step or piecewise-linear resisting moment → moment diagram, J_F), variant "
       "1 of seed 7: the answer key (the student's page filled in), Russian notation."),
    _F("worksheet_step_moment_student_ru", "variant:step-moment", "worksheets.student_page", "ru", {},
       "Worksheet \"step-moment\" (W3 style: step or piecewise-linear resisting moment → moment diagram, J_F), variant "
       "1 of seed 7: the student's page, Russian notation."),
    _F("worksheet_velocity_plan_key_zh", "variant:velocity-plan", "worksheets.key_page", "zh", {},
       "Worksheet \"velocity-plan\" (a slider-crank in one position → its velocity plan), variant 1 of seed 7: the "
       "answer key (the student's page filled in), Chinese notation."),
    _F("worksheet_velocity_plan_student_zh", "variant:velocity-plan", "worksheets.student_page", "zh", {},
       "Worksheet \"velocity-plan\" (a slider-crank in one position → its velocity plan), variant 1 of seed 7: the "
       "student's page, Chinese notation."),
    _F("worksheet_wittenbauer_key_en", "variant:wittenbauer", "worksheets.key_page", "en", {},
       "Worksheet \"wittenbauer\" (a slider-crank press → energy–mass diagram, kl, J_F), variant 1 of seed "
       "7: the answer key (the student's page filled in), English notation.", png=True),
    _F("worksheet_wittenbauer_student_en", "variant:wittenbauer", "worksheets.student_page", "en", {},
       "Worksheet \"wittenbauer\" (a slider-crank press → energy–mass diagram, kl, J_F), variant 1 of seed 7: the "
       "student's page, English notation."),
)

_BY_NAME: Mapping[str, Figure] = MappingProxyType({f.name: f for f in CATALOGUE})


def figure(name: str) -> Figure:
    """The row of one built-in figure, by name (``"press_wittenbauer_en"``)."""
    try:
        return _BY_NAME[name]
    except KeyError:
        raise InputError(f"no built-in figure {name!r}") from None
