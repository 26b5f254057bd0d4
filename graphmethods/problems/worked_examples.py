"""The published worked examples W1–W4 (domain.md §9) as built-in problems.

Their data are those of the reference cases (``shared/cases/worked_examples.json``, read as they
are by the tests); their titles in en, ru and zh are ours, in :data:`TITLES`, keyed by the case's
id.

>>> [p.id for p in all_examples()]
['W1', 'W2', 'W3', 'W4-drawing', 'W4-exact']
>>> round(w2().flywheel().J_F, 2)       # the source prints 60.16: it used 570 for ΔW_max = 575
60.69
>>> w1().title.title_in("ru")
'Дизель-генератор: векторная диаграмма избыточных работ'
"""

from __future__ import annotations

import math

from graphmethods.dynamics.moments import MomentCurve
from graphmethods.problems.cycle import CycleProblem
from graphmethods.titles import titles

PI = math.pi

# The titles of the worked examples by case id, in the terms of each tradition: ТММ (ru), 机械原理 (zh).
TITLES = titles({
    "W1": ("Diesel generator: energy indicator diagram", "Дизель-генератор: векторная диаграмма избыточных работ",
           "柴油发电机组的能量指示图"),
    "W2": ("Engine crankshaft: excess work from a to h", "Коленчатый вал двигателя: избыточные работы от a до h",
           "发动机曲轴自 a 至 h 各区间的盈亏功"),
    "W3": ("Step resisting moment: flywheel", "Ступенчатый момент сопротивления: маховик",
           "阶梯形阻抗力矩下的飞轮转动惯量"),
    "W4-drawing": ("Kinetic energy graph (lecture drawing, π ≈ 3)",
                   "График кинетической энергии (по чертежу лекции, π ≈ 3)", "动能曲线（讲义作图，π ≈ 3）"),
    "W4-exact": ("Kinetic energy graph (exact data)", "График кинетической энергии (точные данные)",
                 "动能曲线（精确数据）"),
})


def w1() -> CycleProblem:
    """W1: diesel generator, energy indicator diagram (Chinese textbook)."""
    return CycleProblem(
        id="W1", title=TITLES["W1"],
        source="Chinese textbook, diesel generator (energy indicator diagram)",
        work_J=(-50, 550, -100, 125, -500, 25, -50), n_rpm=600.0, delta=1 / 300,
    )


def w2() -> CycleProblem:
    """W2: engine crankshaft, points a…h (Chinese textbook)."""
    return CycleProblem(
        id="W2", title=TITLES["W2"],
        source="Chinese textbook, engine crankshaft example",
        work_J=(-50, 550, -100, 125, -500, 25, -50), n_rpm=120.0, delta=0.06,
        note="the source substituted 570 for ΔW_max = 575: it prints J_F = 60.16 kg·m², which is "
             "900·570/(0.06·π²·120²); 900·575/(0.06·π²·120²) = 60.69",
    )


def w3() -> CycleProblem:
    """W3: step resisting moment, constant driving moment by work balance."""
    return CycleProblem(
        id="W3", title=TITLES["W3"],
        source="Chinese textbook exercise, step resisting moment",
        M_r=MomentCurve.steps([(0.0, PI / 4, 60.0), (PI / 4, 2 * PI, 10.0)]), n_rpm=100.0, delta=0.05,
    )


def w4_drawing() -> CycleProblem:
    """W4 as drawn in the lecture: μ_M = 1 kG·m/mm, 2π = 80 mm with π taken as 3 (μ_φ = 0.075 rad/mm)."""
    return CycleProblem(
        id="W4-drawing", title=TITLES["W4-drawing"],
        source="Russian lecture, kinetic energy graph (units kG·m)",
        areas_mm2=(200, -200, -200, 200), mu_M=1.0, mu_phi=0.075, J_e=0.8, omega_0=10.0,
        note="old units: moments in kG·m, J_e in kG·m·s²; the lecture takes π ≈ 3",
        work_unit="kG·m", inertia_unit="kG·m·s²",
    )


def w4_exact() -> CycleProblem:
    """W4 from the exact data: triangular M_r (0 → 40 at π → 0), M_d = 20, four equal parts."""
    return CycleProblem(
        id="W4-exact", title=TITLES["W4-exact"],
        source="Russian lecture, kinetic energy graph (units kG·m)",
        M_d=MomentCurve.constant(20.0), M_r=MomentCurve.points([0.0, PI, 2 * PI], [0.0, 40.0, 0.0]),
        boundaries=(0.0, PI / 2, PI, 3 * PI / 2, 2 * PI), J_e=0.8, omega_0=10.0,
        note="with exact π each area is 5π = 15.71 kG·m instead of the drawing's 15",
        work_unit="kG·m", inertia_unit="kG·m·s²",
    )


def all_examples() -> list[CycleProblem]:
    """W1, W2, W3, W4 (as drawn) and W4 (exact)."""
    return [w1(), w2(), w3(), w4_drawing(), w4_exact()]
