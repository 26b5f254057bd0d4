"""Printable worksheets with answer keys: variants from a seed, a student page and a key page each.

Five kinds of worksheet (:data:`KINDS`):

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
                   (:mod:`graphmethods.sheets.acceleration_worksheet`).

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

:func:`write_worksheet` writes one PDF (students' pages, then keys), an SVG per page and a problem
file per variant (which ``graphmethods check`` reads), atomically and never over existing files
unless asked.
"""

from __future__ import annotations

import json
import math
import pathlib
import re
from collections.abc import Callable
from dataclasses import dataclass, fields, replace
from fractions import Fraction
from functools import cached_property
from typing import Any, ClassVar

import numpy as np

from graphmethods.dynamics import excess_work as ew
from graphmethods.dynamics.flywheel import flywheel
from graphmethods.dynamics.moments import MomentCurve
from graphmethods.errors import InputError, OutputExistsError
from graphmethods.scene import (
    Axis,
    Page,
    Scale,
    Scene,
    Table,
    Text,
    Vector,
    in_language,
    markup,
    nice_ticks,
    notation as get_notation,
)
from graphmethods.scene.elements import Element, Line, Point, Region, make_label
from graphmethods.scene.primitives import DASHED, MAIN, THIN, Circle, Path, Polygon, Primitive, Style
from graphmethods.sheets import answers
from graphmethods.titles import Title
from graphmethods.units import MAX_VARIANTS, json_text, omega_from_n

KINDS = ("indicator", "step-moment", "velocity-plan", "wittenbauer", "acceleration-plan")
_KIND_CODE = {"indicator": 1, "step-moment": 2, "velocity-plan": 3, "wittenbauer": 4, "acceleration-plan": 5}
PROBLEM_FORMAT = "graphmethods-worksheet-problem"

# ----------------------------------------------------------------------------- words (en, ru, zh)
# Words and symbols the notation profiles lack (worth merging into scene/notation.py).
WORDS = {
    "variant": ("Variant", "Вариант", "方案"),
    "name": ("Name", "Ф. И. О.", "姓名"),
    "group": ("Group", "Группа", "班级"),
    "date": ("Date", "Дата", "日期"),
    "key": ("ANSWER KEY", "ОТВЕТЫ", "参考答案"),
    "answers": ("Answers", "Ответы", "答案"),
    "data": ("Data", "Исходные данные", "已知数据"),
    "solution": ("Solution", "Решение", "解"),
    "work": ("Calculations", "Вычисления", "计算"),
    "check": ("check a student's answers: graphmethods check {id} ANSWERS.toml",
              "проверка ответов студента: graphmethods check {id} ANSWERS.toml",
              "检查学生答案：graphmethods check {id} ANSWERS.toml"),
    "draw_here": ("Draw here", "Постройте здесь", "在此作图"),
    "interval": ("Interval", "Участок", "区间"),
    "point_end": ("End point", "Точка", "终点"),
    "position": ("Position", "Положение", "位置"),
    "at_point": ("point", "точка", "点"),
    "step": ("arrows {step} mm apart", "шаг {step} мм", "箭头间距 {step} mm"),
    "cw": ("clockwise", "по часовой стрелке", "顺时针"),
    "ccw": ("counterclockwise", "против часовой стрелки", "逆时针"),
    "sense": ("sense", "направление", "转向"),
    "ray_upper": ("ψ_{max} ray", "луч ψ_{max}", "ψ_{max} 射线"),
    "ray_lower": ("ψ_{min} ray", "луч ψ_{min}", "ψ_{min} 射线"),
}

# the title of each kind of worksheet problem (Variant.title)
TITLES = {
    "indicator": Title.of({"en": "Energy indicator diagram and flywheel",
                           "ru": "Векторная диаграмма избыточных работ и маховик",
                           "zh": "能量指示图与飞轮转动惯量"}),
    "step-moment": Title.of({"en": "Flywheel for a given resisting moment",
                             "ru": "Маховик по заданному моменту сопротивления",
                             "zh": "已知阻抗力矩求飞轮转动惯量"}),
    "velocity-plan": Title.of({"en": "Velocity plan of a slider-crank mechanism",
                               "ru": "План скоростей кривошипно-ползунного механизма",
                               "zh": "曲柄滑块机构的速度多边形"}),
    "wittenbauer": Title.of({"en": "Flywheel by the energy–mass (Wittenbauer) diagram",
                             "ru": "Маховик по диаграмме энергомасс (Виттенбауэра)",
                             "zh": "用能量–质量（维滕鲍尔）图求飞轮转动惯量"}),
}

# statements: the given data, then the tasks (one line each); {placeholders} are filled per variant
STATEMENTS = {
    "indicator": (
        ("The areas between the equivalent driving and resisting moment curves of a machine over one cycle "
         "were measured on a drawing made with {mu_M} and {mu_phi} (table; + where {M_d} > {M_r}). The shaft "
         "turns at n = {n}; the permissible coefficient of speed fluctuation is [δ] = {delta}; the machine's own "
         "equivalent moment of inertia is {J_e}.",
         "1) Compute the excess works {A}_{{i}} and the energy levels {E} at the ends of the intervals.",
         "2) Draw the energy indicator diagram at {mu_E} from point a, {step}.",
         "3) Find {dW} and the points where the speed is greatest (ω_{{max}}) and least (ω_{{min}}).",
         "4) Find ω_{{m}}, ω_{{max}}, ω_{{min}} and the flywheel moment of inertia {J_F_sym}."),
        ("Площади между кривыми приведённых движущего момента и момента сопротивления машины за цикл "
         "измерены на чертеже с {mu_M} и {mu_phi} (таблица; «+» где {M_d} > {M_r}). Вал вращается с "
         "n = {n}; допускаемый коэффициент неравномерности хода [δ] = {delta}; приведённый момент инерции "
         "механизма {J_e}.",
         "1) Вычислите избыточные работы {A}_{{i}} и приращения энергии {E} в концах участков.",
         "2) Постройте векторную диаграмму избыточных работ в масштабе {mu_E} от точки a, {step}.",
         "3) Найдите {dW} и точки, где скорость наибольшая (ω_{{max}}) и наименьшая (ω_{{min}}).",
         "4) Найдите ω_{{ср}}, ω_{{max}}, ω_{{min}} и момент инерции маховика {J_F_sym}."),
        ("在一个运动循环中，等效驱动力矩与等效阻抗力矩曲线之间的各块面积是在 {mu_M}、{mu_phi} 的图上量得的"
         "（见表；{M_d} > {M_r} 处为正）。主轴转速 n = {n}，许用速度不均匀系数 [δ] = {delta}，"
         "机械本身的等效转动惯量 {J_e}。",
         "1) 求各区间的盈亏功 {A}_{{i}} 及各区间终点的能量 {E}。",
         "2) 以 {mu_E} 从 a 点作能量指示图，{step}。",
         "3) 求最大盈亏功 {dW} 及速度最大（ω_{{max}}）、最小（ω_{{min}}）的位置。",
         "4) 求 ω_{{m}}、ω_{{max}}、ω_{{min}} 及飞轮转动惯量 {J_F_sym}。"),
    ),
    "step-moment": (
        ("The equivalent resisting moment {M_r} of a machine over one turn of its main shaft is given in the "
         "table ({shape}); the driving moment {M_d} is constant. The shaft turns at n = {n}; [δ] = {delta}; "
         "the machine's own equivalent moment of inertia is {J_e}.",
         "1) Find {M_d} from the work balance over one turn.",
         "2) Draw {M_r} and {M_d} on the grid at {mu_M} and {mu_phi}; hatch the excess areas.",
         "3) Fill in the excess-work table (intervals between the crossings, {A}_{{i}}, {E}).",
         "4) Find {dW}, the angles φ of ω_{{max}} and ω_{{min}}, and the flywheel moment of inertia {J_F_sym}."),
        ("Приведённый момент сопротивления {M_r} машины за один оборот главного вала задан таблицей "
         "({shape}); движущий момент {M_d} постоянен. Вал вращается с n = {n}; [δ] = {delta}; "
         "приведённый момент инерции механизма {J_e}.",
         "1) Найдите {M_d} из равенства работ за оборот.",
         "2) Постройте {M_r} и {M_d} на сетке в масштабах {mu_M} и {mu_phi}; заштрихуйте избыточные площади.",
         "3) Заполните таблицу избыточных работ (участки между пересечениями, {A}_{{i}}, {E}).",
         "4) Найдите {dW}, углы φ для ω_{{max}} и ω_{{min}} и момент инерции маховика {J_F_sym}."),
        ("机械在主轴一转内的等效阻抗力矩 {M_r} 如表所示（{shape}），等效驱动力矩 {M_d} 为常数。"
         "主轴转速 n = {n}，[δ] = {delta}，机械本身的等效转动惯量 {J_e}。",
         "1) 由一转内功的平衡求 {M_d}。",
         "2) 以 {mu_M}、{mu_phi} 在网格上画出 {M_r} 和 {M_d}，并画出盈亏功面积的剖面线。",
         "3) 填写盈亏功计算表（两曲线交点之间的区间、{A}_{{i}}、{E}）。",
         "4) 求 {dW}、ω_{{max}} 与 ω_{{min}} 所在的转角 φ 及飞轮转动惯量 {J_F_sym}。"),
    ),
    "velocity-plan": (
        ("The slider-crank mechanism is drawn at {mu_l} in the position φ = {phi} (crank angle from the x axis): "
         "crank OA = {r}, connecting rod AB = {l}, offset e = {e}, centre of mass S_{{2}} at AS_{{2}} = {AS2}. "
         "The crank turns {sense} at ω_{{1}} = {omega_1}.",
         "1) Draw the velocity plan from the pole p at {mu_v}: pa ⊥ OA, then b on the line through a ⊥ AB "
         "and the line through p ∥ the guide; s_{{2}} on ab by similarity.",
         "2) Measure pa, pb, ab and ps_{{2}} in mm.",
         "3) Find v_{{A}}, v_{{B}}, v_{{BA}}, v_{{S2}} and the angular velocity ω_{{2}} of the rod with its sense."),
        ("Кривошипно-ползунный механизм вычерчен в масштабе {mu_l} в положении φ = {phi} (угол кривошипа от "
         "оси x): кривошип OA = {r}, шатун AB = {l}, эксцентриситет e = {e}, центр масс S_{{2}} при "
         "AS_{{2}} = {AS2}. Кривошип вращается {sense} с ω_{{1}} = {omega_1}.",
         "1) Постройте план скоростей от полюса p в масштабе {mu_v}: pa ⊥ OA, затем b на пересечении линии "
         "через a ⊥ AB и линии через p ∥ направляющей; s_{{2}} на ab по подобию.",
         "2) Измерьте pa, pb, ab и ps_{{2}} в мм.",
         "3) Найдите v_{{A}}, v_{{B}}, v_{{BA}}, v_{{S2}} и угловую скорость шатуна ω_{{2}} с её направлением."),
        ("曲柄滑块机构按 {mu_l} 画在 φ = {phi}（曲柄与 x 轴的夹角）的位置：曲柄 OA = {r}，连杆 AB = {l}，"
         "偏距 e = {e}，质心 S_{{2}} 处 AS_{{2}} = {AS2}。曲柄以 ω_{{1}} = {omega_1} {sense}转动。",
         "1) 以 {mu_v} 从极点 p 作速度多边形：pa ⊥ OA，b 为过 a 作 ⊥ AB 的直线与过 p 作 ∥ 导路的直线之交点；"
         "由影像原理在 ab 上求 s_{{2}}。",
         "2) 量出 pa、pb、ab、ps_{{2}} 的长度（mm）。",
         "3) 求 v_{{A}}、v_{{B}}、v_{{BA}}、v_{{S2}} 及连杆角速度 ω_{{2}} 和它的转向。"),
    ),
    "wittenbauer": (
        ("A slider-crank press (crank r = {r}, rod l = {l}, offset e = {e}; pressing force {F0} over "
         "{force_from}…{force_to} of the working stroke) runs at n = {n} with [δ] = {delta}. The table gives its "
         "equivalent moment of inertia {J_e_sym} and the change of kinetic energy {dT} (from position 0) at the "
         "positions 0…12 of the crank.",
         "1) Plot the energy–mass diagram {dT}({J_e_sym}) at {mu_J} and {mu_T}, the ordinate axis at "
         "{J_e_sym} = 0.",
         "2) Compute tan ψ_{{max}} = μ_{{J}}ω_{{m}}²(1 + δ/2)²/(2μ_{{T}}) and tan ψ_{{min}} = "
         "μ_{{J}}ω_{{m}}²(1 − δ/2)²/(2μ_{{T}}).",
         "3) Draw the ray at ψ_{{max}} touching the curve from above and the ray at ψ_{{min}} touching it from "
         "below; measure the segment kl they cut on the ordinate axis.",
         "4) Find the flywheel moment of inertia {J_F_sym} = μ_{{T}}·kl/(ω_{{m}}²[δ]) and the positions of "
         "ω_{{max}} and ω_{{min}}."),
        ("Кривошипно-ползунный пресс (кривошип r = {r}, шатун l = {l}, эксцентриситет e = {e}; сила "
         "прессования {F0} на участке {force_from}…{force_to} рабочего хода) работает при n = {n}, "
         "[δ] = {delta}. В таблице даны приведённый момент инерции {J_e_sym} и приращение кинетической "
         "энергии {dT} (от положения 0) в положениях кривошипа 0…12.",
         "1) Постройте диаграмму энергомасс {dT}({J_e_sym}) в масштабах {mu_J} и {mu_T}; ось ординат при "
         "{J_e_sym} = 0.",
         "2) Вычислите tg ψ_{{max}} = μ_{{J}}ω_{{ср}}²(1 + δ/2)²/(2μ_{{T}}) и tg ψ_{{min}} = "
         "μ_{{J}}ω_{{ср}}²(1 − δ/2)²/(2μ_{{T}}).",
         "3) Проведите касательную под углом ψ_{{max}} к кривой сверху и под углом ψ_{{min}} снизу; "
         "измерьте отрезок kl, отсекаемый ими на оси ординат.",
         "4) Найдите момент инерции маховика {J_F_sym} = μ_{{T}}·kl/(ω_{{ср}}²[δ]) и положения "
         "ω_{{max}} и ω_{{min}}."),
        ("曲柄滑块压力机（曲柄 r = {r}，连杆 l = {l}，偏距 e = {e}；工作行程的 {force_from}…{force_to} "
         "段受压力 {F0}）的转速 n = {n}，[δ] = {delta}。表中给出曲柄位置 0…12 处的等效转动惯量 "
         "{J_e_sym} 及动能增量 {dT}（自位置 0 起算）。",
         "1) 以 {mu_J}、{mu_T} 作能量–质量图 {dT}({J_e_sym})，纵坐标轴位于 {J_e_sym} = 0 处。",
         "2) 计算 tan ψ_{{max}} = μ_{{J}}ω_{{m}}²(1 + δ/2)²/(2μ_{{T}}) 和 tan ψ_{{min}} = "
         "μ_{{J}}ω_{{m}}²(1 − δ/2)²/(2μ_{{T}})。",
         "3) 作倾角为 ψ_{{max}} 的射线从上方与曲线相切，倾角为 ψ_{{min}} 的射线从下方与曲线相切，"
         "量出它们在纵坐标轴上截得的线段 kl。",
         "4) 求飞轮转动惯量 {J_F_sym} = μ_{{T}}·kl/(ω_{{m}}²[δ]) 及 ω_{{max}}、ω_{{min}} 所在的位置。"),
    ),
}

SHAPES = {"steps": ("steps", "ступенчатый", "阶梯形"), "linear": ("piecewise linear", "кусочно-линейный",
                                                                "折线形")}

#: symbols the notation profiles lack: (en, ru, zh)
SYMBOLS = {
    "J_e": ("J_e", "J_п", "J_e"),
    "J_F": ("J_F", "J_м", "J_F"),
    "omega_m": ("ω_m", "ω_{ср}", "ω_m"),
    "mu_v": ("μ_v", "μ_v", "μ_v"),
    "mu_l": ("μ_l", "μ_l", "μ_l"),
    "mu_J": ("μ_J", "μ_J", "μ_J"),
    "tan": ("tan", "tg", "tan"),
}

#: units the notation profiles lack, ru and zh forms
EXTRA_UNITS = {"rev/min": ("об/мин", "r/min"), "m/s": ("м/с", "m/s"), "(m/s)": ("(м/с)", "(m/s)"),
               "rad/s": ("рад/с", "rad/s"), "kg·m²": ("кг·м²", "kg·m²")}


def word(key: str, nt, **fmt) -> str:
    """A word of the worksheets in the profile's language (``{placeholders}`` filled from ``fmt``)."""
    return in_language(WORDS[key], nt, **fmt)


def sym(key: str, nt) -> str:
    """A symbol of the worksheets: the profile's own (``M_d``, ``delta_W_max`` …) or one of :data:`SYMBOLS`."""
    return in_language(SYMBOLS[key], nt) if key in SYMBOLS else get_notation(nt).sym(key)


def unit(u: str, nt) -> str:
    """A unit as the profile writes it, including the few units the profiles lack."""
    nt = get_notation(nt)
    if u in EXTRA_UNITS and nt.code != "en":
        return EXTRA_UNITS[u][0 if nt.code == "ru" else 1]
    return nt.unit(u)


def quantity(symbol: str, u: str, nt) -> str:
    """``"A, J"`` (en, ru) or ``"A/J"`` (zh), with the units of :func:`unit`."""
    nt = get_notation(nt)
    uu = unit(u, nt)
    if not uu:
        return symbol
    if nt.quantity_style == "slash":
        return f"{symbol}/{uu}" if all(c not in uu for c in "·/ °") else f"{symbol}/({uu})"
    return f"{symbol}, {uu}"


def num(value: float, nt, *, sig: int = 4, plus: bool = False) -> str:
    """A number as the profile writes it (decimal comma in ru, typographic minus)."""
    return get_notation(nt).number(float(value), sig=sig, plus=plus)


def value_unit(value: float, u: str, nt, *, sig: int = 4) -> str:
    """``"43.69 kg·m²"`` in the profile's style."""
    return f"{num(value, nt, sig=sig)} {unit(u, nt)}"


def scale_text(symbol: str, per_mm: float, u: str, nt, *, alt: str = "") -> str:
    """``"μ_M = 10 N·m/mm"`` in the profile's style (``alt``: an equivalent form in brackets)."""
    text = f"{symbol} = {num(per_mm, nt, sig=6)} {unit(u, nt)}/{unit('mm', nt)}"
    return text + (f" ({alt})" if alt else "")


# ----------------------------------------------------------------------------- variants

def _fraction(text) -> Fraction:
    try:
        f = Fraction(str(text))
    except (ValueError, ZeroDivisionError):
        raise InputError(f"delta = {text!r}: give the coefficient of fluctuation as a fraction like 1/30") from None
    if not 0 < f < 1:
        raise InputError(f"delta = {text!r} must lie between 0 and 1")
    return f


class Variant:
    """Base of the worksheet variants: an id, its data as a dict, its expected answers."""

    kind: ClassVar[str] = ""
    __dataclass_fields__: ClassVar[dict[str, Any]]     # every variant is a dataclass (fields() reads them)
    seed: int
    number: int

    @property
    def id(self) -> str:
        """``"KIND:SEED:NUMBER"``; ``graphmethods check`` accepts it in place of a problem file."""
        return f"{self.kind}:{self.seed}:{self.number}"

    @property
    def title(self) -> Title:
        """The worksheet's title in en, ru and zh (``title.title_in(lang)``), the same for every variant of a kind."""
        return TITLES[self.kind]

    def data(self) -> dict:
        """The variant's inputs, JSON-ready (what a problem file holds)."""
        out = {}
        for f in fields(self):
            v = getattr(self, f.name)
            out[f.name] = list(v) if isinstance(v, tuple) else v
        return out

    def answers(self) -> dict:  # pragma: no cover - every kind overrides it
        raise NotImplementedError

    def to_dict(self) -> dict:
        """The problem file: format, kind, id, data and (for reading only) the expected answers."""
        return {"format": PROBLEM_FORMAT, "kind": self.kind, "id": self.id, "data": self.data(),
                "answers": self.answers()}

    def to_json(self) -> str:
        """:meth:`to_dict` as indented JSON text (deterministic)."""
        return json_text(self.to_dict(), indent=1, ensure_ascii=False) + "\n"


class _FlywheelVariant(Variant):
    """A variant that asks for a flywheel: the machine runs at ``n_rpm`` (rev/min) with [δ] given as text."""

    n_rpm: float
    delta: str

    @property
    def delta_value(self) -> float:
        """[δ] as a number."""
        return float(_fraction(self.delta))

    @property
    def omega_m(self) -> float:
        """Mean angular velocity, rad/s."""
        return omega_from_n(self.n_rpm)


@dataclass(frozen=True)
class IndicatorVariant(_FlywheelVariant):
    """W1 style: areas f_i (mm²) measured at μ_M (N·m/mm), μ_φ (rad/mm); n (rev/min), [δ], J_e (kg·m²).

    ``mu_E`` (J/mm) and ``step_mm`` are the stated scale and spacing of the student's energy indicator.

    >>> v = IndicatorVariant(seed=0, number=1, areas_mm2=(500, -5500, 1000, -1250, 5000, -250, 500),
    ...                      mu_M=4.0, mu_phi=0.025, n_rpm=600.0, delta="1/300", J_e=0.0, mu_E=5.0)
    >>> v.excess_work.delta_W_max, round(v.answers()["J_F"], 2)        # W1 at a drawing's scales
    (575.0, 43.69)
    """

    kind: ClassVar[str] = "indicator"
    seed: int
    number: int
    areas_mm2: tuple
    mu_M: float
    mu_phi: float
    n_rpm: float
    delta: str
    J_e: float
    mu_E: float
    step_mm: float = 16.0

    @cached_property
    def excess_work(self):
        return ew.from_areas(self.areas_mm2, mu_M=self.mu_M, mu_phi=self.mu_phi, closure_tol=1e-9)

    @cached_property
    def flywheel(self):
        return flywheel(self.excess_work.delta_W_max, delta=self.delta_value, n_rpm=self.n_rpm, J_e=self.J_e)

    def answers(self) -> dict:
        c, f = self.excess_work, self.flywheel
        return {"works_J": c.work.tolist(), "E_J": c.E.tolist(), "labels": list(c.labels),
                "arrows_mm": (c.work / self.mu_E).tolist(), "delta_W_max": c.delta_W_max,
                "omega_max_at": c.labels[c.index_E_max], "omega_min_at": c.labels[c.index_E_min],
                "omega_m": f.omega_m, "omega_max": f.omega_max, "omega_min": f.omega_min, "J_F": f.J_F}


@dataclass(frozen=True)
class StepMomentVariant(_FlywheelVariant):
    """W3 style: M_r through knots (φ in degrees, a repeated angle is a jump), M_d by work balance.

    ``mu_M`` (N·m/mm) and ``mu_phi_deg`` (°/mm) are the stated scales of the moment diagram.

    >>> v = StepMomentVariant(seed=0, number=1, shape="steps", phi_deg=(0, 45, 45, 360), M_r=(60, 60, 10, 10),
    ...                       n_rpm=100.0, delta="1/20", J_e=0.0, mu_M=0.5, mu_phi_deg=2.5)
    >>> a = v.answers()
    >>> a["M_d"], round(a["delta_W_max"], 2), round(a["J_F"], 3)                      # W3
    (16.25, 34.36, 6.267)
    """

    kind: ClassVar[str] = "step-moment"
    seed: int
    number: int
    shape: str
    phi_deg: tuple
    M_r: tuple
    n_rpm: float
    delta: str
    J_e: float
    mu_M: float
    mu_phi_deg: float

    @property
    def mu_phi(self) -> float:
        """The angle scale in rad/mm."""
        return math.radians(self.mu_phi_deg)

    @cached_property
    def M_r_curve(self) -> MomentCurve:
        return MomentCurve(np.radians(np.asarray(self.phi_deg, dtype=float)), np.asarray(self.M_r, dtype=float))

    @cached_property
    def excess_work(self):
        return ew.from_moments(M_r=self.M_r_curve)

    @property
    def M_d(self) -> float:
        return self.M_r_curve.mean()

    @cached_property
    def flywheel(self):
        return flywheel(self.excess_work.delta_W_max, delta=self.delta_value, n_rpm=self.n_rpm, J_e=self.J_e)

    def steps(self) -> list[tuple[float, float, float]]:
        """(φ from, φ to, M_r) in degrees and N·m for a step curve."""
        p, M = self.phi_deg, self.M_r
        return [(p[i], p[i + 1], M[i]) for i in range(len(p) - 1) if p[i + 1] > p[i]]

    def answers(self) -> dict:
        c, f = self.excess_work, self.flywheel
        area = 1.0 / (self.mu_M * self.mu_phi)
        return {"M_d": self.M_d, "phi_deg": np.degrees(c.phi).tolist(), "labels": list(c.labels),
                "works_J": c.work.tolist(), "E_J": c.E.tolist(), "areas_mm2": (c.work * area).tolist(),
                "delta_W_max": c.delta_W_max, "omega_max_at": c.labels[c.index_E_max],
                "omega_min_at": c.labels[c.index_E_min], "phi_omega_max_deg": math.degrees(c.phi_E_max),
                "phi_omega_min_deg": math.degrees(c.phi_E_min), "omega_m": f.omega_m, "omega_max": f.omega_max,
                "omega_min": f.omega_min, "J_F": f.J_F}


@dataclass(frozen=True)
class PlanVariant(Variant):
    """A slider-crank (crank counterclockwise, slider on the +x side) in one position φ (degrees).

    Lengths in m, ω_1 in rad/s, ``mu_l`` (m/mm) for the scheme, ``mu_v`` ((m/s)/mm) for the plan.

    >>> v = PlanVariant(seed=0, number=1, r=0.1, l=0.4, e=0.0, l_AS2=0.13, phi_deg=60.0, omega_1=10.0,
    ...                 mu_l=0.004, mu_v=0.02)
    >>> a = v.answers()
    >>> a["v_A"], round(a["pa_mm"], 3), round(a["v_B"], 4), round(a["omega_2"], 4), a["omega_2_sense"]
    (1.0, 50.0, 0.9769, 1.2804, 'cw')
    """

    kind: ClassVar[str] = "velocity-plan"
    seed: int
    number: int
    r: float
    l: float
    e: float
    l_AS2: float
    phi_deg: float
    omega_1: float
    mu_l: float
    mu_v: float

    @cached_property
    def mechanism(self):
        from graphmethods.kinematics import SliderCrank

        return SliderCrank(r=self.r, l=self.l, e=self.e, points={"S2": ("AB", self.l_AS2, 0.0)})

    @cached_property
    def positions(self):
        return self.mechanism.positions(phi=[math.radians(self.phi_deg)])

    @cached_property
    def plan(self):
        return self.mechanism.velocity_plans(self.positions, omega_1=self.omega_1)

    def vectors(self) -> dict[str, np.ndarray]:
        """Plan vectors (m/s) by plan label: ``{"p": (0, 0), "a": …, "b": …, "s2": …}``."""
        out: dict[str, np.ndarray] = {}
        for name in self.plan.order:
            out.setdefault(self.plan.label(name), np.asarray(self.plan.v(name)[0], dtype=float))
        return out

    def answers(self) -> dict:
        v = self.vectors()
        seg = {k: float(np.hypot(*(v[b] - v[a]))) for k, (a, b) in SEGMENTS.items()}
        w2 = float(self.plan.omega("AB")[0])
        return {**{f"{k}_mm": s / self.mu_v for k, s in seg.items()},
                "v_A": seg["pa"], "v_B": seg["pb"], "v_BA": seg["ab"], "v_S2": seg["ps2"],
                "omega_2": abs(w2), "omega_2_sense": "ccw" if w2 > 0 else "cw"}


#: the segments of a slider-crank's velocity plan: name -> (from, to) plan points
SEGMENTS = {"pa": ("p", "a"), "pb": ("p", "b"), "ab": ("a", "b"), "ps2": ("p", "s2")}


@dataclass(frozen=True)
class EnergyMassVariant(_FlywheelVariant):
    """A press given by its table J_e (kg·m²) and ΔT (J) at positions 0…m, with n, [δ] and μ_J, μ_T.

    ``press`` holds the linkage data the table was computed from (shown in the statement).

    >>> v = EnergyMassVariant(seed=0, number=1, press={}, phi_deg=(0, 90, 180, 270, 360),
    ...                       J_e=(1.0, 0.8, 1.0, 1.2, 1.0), delta_T=(0.0, 40.0, 0.0, -40.0, 0.0),
    ...                       n_rpm=190.98593171027443, delta="1/25", mu_J=0.005, mu_T=1.0)
    >>> round(v.result.kl_mm, 3), round(v.answers()["J_F"], 4)
    (144.032, 9.002)
    """

    kind: ClassVar[str] = "wittenbauer"
    seed: int
    number: int
    press: dict
    phi_deg: tuple
    J_e: tuple
    delta_T: tuple
    n_rpm: float
    delta: str
    mu_J: float
    mu_T: float

    def __hash__(self):          # the press dict is not hashable
        return hash((self.kind, self.seed, self.number))

    @property
    def m(self) -> int:
        return len(self.J_e) - 1

    @cached_property
    def result(self):
        from graphmethods.dynamics.wittenbauer import wittenbauer

        return wittenbauer(J_e=self.J_e, delta_T=self.delta_T, omega_m=self.omega_m, delta=self.delta_value,
                           mu_J=self.mu_J, mu_T=self.mu_T, phi=np.radians(np.asarray(self.phi_deg, dtype=float)))

    def answers(self) -> dict:
        r = self.result
        return {"tan_psi_max": r.tan_psi_max, "tan_psi_min": r.tan_psi_min, "k_mm": r.k_mm, "l_mm": r.l_mm,
                "kl_mm": r.kl_mm, "J_F": r.J_F, "omega_max_at": list(r.index_omega_max),
                "omega_min_at": list(r.index_omega_min)}


_CLASSES = {"indicator": IndicatorVariant, "step-moment": StepMomentVariant, "velocity-plan": PlanVariant,
            "wittenbauer": EnergyMassVariant}


def variant_from_dict(d: dict, *, source: str = "<dict>") -> Variant:
    """A variant from a problem file's dict (see :meth:`Variant.to_dict`); ``answers`` are ignored.

    Raises
    ------
    InputError
        If the format, kind or data do not fit (the message names the key).
    """
    if not isinstance(d, dict) or d.get("format") != PROBLEM_FORMAT:
        raise InputError(f"{source}: not a worksheet problem file (expected \"format\": \"{PROBLEM_FORMAT}\")")
    kind = d.get("kind")
    if kind not in _CLASSES:
        raise InputError(f"{source}: unknown worksheet kind {kind!r}; kinds: {', '.join(KINDS)}")
    cls = _CLASSES[kind]
    data = d.get("data")
    if not isinstance(data, dict):
        raise InputError(f"{source}: key 'data' must hold the variant's inputs")
    names = [f.name for f in fields(cls)]
    missing = [n for n in names if n not in data and n != "step_mm"]
    unknown = [k for k in data if k not in names]
    if missing or unknown:
        raise InputError(f"{source}: {'missing ' + repr(missing[0]) if missing else 'unknown ' + repr(unknown[0])} "
                         f"in 'data' for kind {kind}; the keys are {', '.join(names)}")
    kw = {k: tuple(v) if isinstance(v, list) else v for k, v in data.items()}
    try:
        var = cls(**kw)
        var.answers()                 # validate: the data must make a solvable problem
    except InputError as exc:
        raise InputError(f"{source}: {exc}") from None
    except (TypeError, ValueError) as exc:
        raise InputError(f"{source}: bad data ({exc})") from None
    return var


# ----------------------------------------------------------------------------- generators (nice numbers)

_N_RPM = (120.0, 150.0, 180.0, 200.0, 240.0, 300.0, 360.0, 400.0, 450.0, 500.0, 600.0, 720.0, 750.0, 900.0,
          1000.0, 1200.0, 1500.0)
_DELTA = ("1/10", "1/12", "1/15", "1/20", "1/25", "1/30", "1/40", "1/50", "1/60", "1/80", "1/100")
# (μ_M N·m/mm, μ_φ rad/mm) with a round product μ_M·μ_φ ≠ 1 J/mm² (so forgetting it shows)
_AREA_SCALES = ((4.0, 0.025), (10.0, 0.025), (20.0, 0.025), (200.0, 0.025), (5.0, 0.04), (50.0, 0.04),
                (100.0, 0.04), (10.0, 0.05), (50.0, 0.05), (100.0, 0.05), (4.0, 0.05), (2.0, 0.05))


def _pick(rng, seq):
    return seq[int(rng.integers(len(seq)))]


def _nice_below(x: float) -> float:
    """The largest of 1, 2, 2.5, 4, 5 × 10^k not above x (x > 0)."""
    from graphmethods.units import convenient_at_most

    return convenient_at_most(x)


def _pick_scale(span: float, room_mm: float) -> float:
    from graphmethods.scene import pick_scale

    return pick_scale(span, room_mm).per_mm


def _levels_ok(E: np.ndarray, margin: float) -> bool:
    """The highest and lowest running energies are single points, ``margin`` clear of every other level
    (the start/end level included), so a student cannot mistake them."""
    inner = np.sort(np.asarray(E, dtype=float)[1:-1])
    if inner.size < 2:
        return inner.size == 1 and abs(inner[0]) >= margin
    return inner[-1] - max(inner[-2], 0.0) >= margin and min(inner[1], 0.0) - inner[0] >= margin


def _gen_indicator(rng) -> dict:
    k = int(_pick(rng, (5, 6, 7, 7, 8)))
    while True:
        sign = 1 if rng.random() < 0.5 else -1
        units = []
        for i in range(k - 1):
            units.append(sign * int(rng.integers(3, 46)) * (-1) ** i)
        last = -sum(units)
        want = sign * (-1) ** (k - 1)
        if last * want <= 0 or not 3 <= abs(last) <= 60:
            continue
        units.append(last)
        E = np.concatenate(([0], np.cumsum(units)))
        if _levels_ok(E, 3):
            break
    areas = tuple(int(u * 10) for u in units)
    mu_M, mu_phi = _pick(rng, _AREA_SCALES)
    n = _pick(rng, _N_RPM)
    delta = _pick(rng, _DELTA)
    work = np.asarray(areas, dtype=float) * mu_M * mu_phi
    levels = np.concatenate(([0.0], np.cumsum(work)))
    dW = float(levels.max() - levels.min())
    J_total = dW / (omega_from_n(n) ** 2 * float(Fraction(delta)))
    J_e = _nice_below(0.25 * J_total)
    span = float(max(levels.max(), 0.0) - min(levels.min(), 0.0))
    return dict(areas_mm2=areas, mu_M=mu_M, mu_phi=mu_phi, n_rpm=n, delta=delta, J_e=J_e,
                mu_E=_pick_scale(span, 90.0))


def _gen_step_moment(rng) -> dict:
    shape = "steps" if rng.random() < 0.6 else "linear"
    while True:
        if shape == "steps":
            grid = int(_pick(rng, (30, 45)))
            cuts = int(_pick(rng, (2, 3, 3, 4)))
            inner = sorted(int(c) for c in rng.choice(np.arange(1, 360 // grid), size=cuts - 1, replace=False))
            bounds = [0] + [c * grid for c in inner] + [360]
            values = [int(rng.integers(1, 13)) * 5 for _ in range(cuts)]
            if any(a == b for a, b in zip(values, values[1:])):
                continue
            phi: list[float] = []
            M: list[float] = []
            for a, b, m in zip(bounds, bounds[1:], values):
                phi += [a, b]
                M += [m, m]
        else:
            grid = int(_pick(rng, (30, 45)))
            nk = 360 // grid
            peak = int(rng.integers(1, nk // 2 + 1))
            top = int(rng.integers(4, 17)) * 5
            base = int(rng.integers(0, 3)) * 5
            end = int(rng.integers(peak + 1, nk))
            phi = [i * grid for i in range(nk + 1)]
            M = []
            for i in range(nk + 1):
                if i <= peak:
                    M.append(base + (top - base) * i / peak)
                elif i <= end:
                    M.append(top + (base - top) * (i - peak) / (end - peak))
                else:
                    M.append(base)
            if any(float(x) != int(x) for x in M):
                continue
            M = [int(x) for x in M]
        curve = MomentCurve(np.radians(phi), np.asarray(M, dtype=float))
        M_d = curve.mean()
        if abs(M_d * 4 - round(M_d * 4)) > 1e-9:          # M_d a multiple of 0.25 N·m
            continue
        if min(abs(np.asarray(M, dtype=float) - M_d)) < 2.0:     # no stretch on or grazing the M_d line
            continue
        cyc = ew.from_moments(M_r=curve)
        if cyc.work.size < 2 or not _levels_ok(np.asarray(cyc.E), 0.05 * cyc.delta_W_max):
            continue
        break
    n = _pick(rng, _N_RPM[:10])
    delta = _pick(rng, _DELTA[:8])
    dW = cyc.delta_W_max
    J_total = dW / (omega_from_n(n) ** 2 * float(Fraction(delta)))
    J_e = _nice_below(0.25 * J_total)
    M_hi = max(max(M), M_d)
    return dict(shape=shape, phi_deg=tuple(int(p) for p in phi), M_r=tuple(M), n_rpm=n, delta=delta, J_e=J_e,
                mu_M=_pick_scale(M_hi, 60.0), mu_phi_deg=2.5)


def _gen_plan(rng) -> dict:
    r = _pick(rng, (0.05, 0.06, 0.08, 0.1, 0.12, 0.15))
    lam = _pick(rng, (3, 4, 5))
    l = round(r * lam, 3)
    e = _pick(rng, (0.0, 0.0, round(r / 5, 3), round(r / 4, 3)))
    l_AS2 = round(l * _pick(rng, (0.3, 0.35, 0.4)), 3)
    phi = float(_pick(rng, (30, 45, 60, 120, 135, 150, 210, 225, 240, 300, 315, 330)))
    omega_1 = float(_pick(rng, (10, 12, 15, 16, 20, 24, 25, 30)))
    mu_l = _pick_scale(r + l + r, 150.0)
    mu_v = _pick_scale(omega_1 * r, 85.0)
    return dict(r=r, l=l, e=e, l_AS2=l_AS2, phi_deg=phi, omega_1=omega_1, mu_l=mu_l, mu_v=mu_v)


def _gen_press(rng) -> dict:
    r = _pick(rng, (0.08, 0.1, 0.12))
    l = round(r * _pick(rng, (4, 5)), 3)
    return dict(r=r, l=l, e=_pick(rng, (0.0, 0.01, 0.02)), l_AS2=round(l / 3, 3),
                m2=_pick(rng, (6.0, 8.0, 10.0, 12.0)), J_S2=0.0, m3=_pick(rng, (10.0, 12.0, 15.0, 20.0)),
                J1=_pick(rng, (0.3, 0.4, 0.5, 0.6)), F0=_pick(rng, (3000.0, 4000.0, 5000.0, 6000.0, 8000.0)),
                force_from=_pick(rng, (0.05, 0.1, 0.2)), force_to=_pick(rng, (0.8, 0.9, 0.95)),
                n_rpm=_pick(rng, (200.0, 240.0, 300.0, 360.0, 400.0)), delta=_pick(rng, ("1/20", "1/25", "1/30")))


def energy_mass_from_press(press: dict, *, seed: int = 0, number: int = 1, positions: int = 12,
                           room_mm: tuple[float, float] = (150.0, 112.0)) -> EnergyMassVariant:
    """A ``wittenbauer`` variant from a press's data (the keys of ``slider_crank_press.json``).

    The table J_e, ΔT at positions 0…m is computed with :class:`~graphmethods.dynamics.study.Study` and
    rounded as a worksheet prints it (J_e to 0.001 kg·m², ΔT to 1 J); the expected answers are those of
    the rounded table. Scales μ_J, μ_T are picked so that the diagram, with its ordinate axis at J_e = 0
    and the points k and l on it, fits ``room_mm`` (width, height).
    """
    from graphmethods.dynamics.study import Study
    from graphmethods.kinematics import case_from_dict

    data = dict(press)
    J_S2 = data.get("J_S2") or round(data["m2"] * data["l"] ** 2 / 12.0, 3)
    data["J_S2"] = J_S2
    case = case_from_dict({**data, "delta": str(data["delta"])}, source="worksheet press")
    study = Study(case, positions=positions, estimate=False)
    J_e = np.round(np.asarray(study.J_e, dtype=float), 3)
    dT = np.round(np.asarray(study.delta_T, dtype=float), 0)
    J_e[-1], dT[0], dT[-1] = J_e[0], 0.0, 0.0
    phi_deg = np.round(np.degrees(study.phi), 6)
    omega = omega_from_n(data["n_rpm"])
    d = float(_fraction(data["delta"]))
    # the span to fit: from max(ΔT, 0) down to the lower ray's intercept l (x = 0); the intercepts scale
    # with 1/μ_T whatever μ_J is, so fit x first, then y
    mu_J = _pick_scale(float(J_e.max()), room_mm[0] - 25.0)
    b_lo = float(np.min(dT - 0.5 * omega**2 * (1 - d / 2) ** 2 * J_e))
    b_up = float(np.max(dT - 0.5 * omega**2 * (1 + d / 2) ** 2 * J_e))
    top = max(float(dT.max()), 0.0, b_up)
    mu_T = _pick_scale(top - min(b_lo, float(dT.min())), room_mm[1] - 18.0)
    return EnergyMassVariant(seed=seed, number=number, press={k: data[k] for k in sorted(data)},
                             phi_deg=tuple(float(p) for p in phi_deg), J_e=tuple(float(x) for x in J_e),
                             delta_T=tuple(float(x) for x in dT), n_rpm=float(data["n_rpm"]),
                             delta=str(data["delta"]), mu_J=mu_J, mu_T=mu_T)


_GENERATORS: dict[str, Callable] = {"indicator": _gen_indicator, "step-moment": _gen_step_moment,
                                    "velocity-plan": _gen_plan, "wittenbauer": _gen_press}


def _key(params: dict) -> str:
    return json.dumps(params, sort_keys=True, allow_nan=False)


def _check_kind(kind: str) -> str:
    if kind not in KINDS:
        raise InputError(f"unknown worksheet kind {kind!r}; kinds: {', '.join(KINDS)}")
    return kind


def _check_count(value, name: str, low: int, high: int = MAX_VARIANTS) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        raise InputError(f"{name} must be an integer ≥ {low}, got {value!r}")
    if value > high:
        raise InputError(f"{name} = {value} is above the limit {high} (checked before any variant is built)")
    return int(value)


def variants(kind: str, *, count: int, seed: int) -> tuple[Variant, ...]:
    """Variants 1…count of a worksheet kind, reproducible from ``seed`` (an integer ≥ 0).

    Variant k is drawn from ``numpy.random.default_rng([seed, kind, k, attempt])``; a draw equal to an
    earlier variant's is drawn again (``attempt`` + 1), so the variants of a batch differ and variant k
    is the same whatever ``count`` is.

    >>> [v.n_rpm for v in variants("indicator", count=3, seed=1)] == \\
    ...     [v.n_rpm for v in variants("indicator", count=5, seed=1)][:3]
    True
    """
    _check_kind(kind)
    count = _check_count(count, "the number of variants", 1)
    seed = _check_count(seed, "the seed", 0, high=2**63 - 1)
    gen, seen, out = _GENERATORS[kind], set(), []
    for number in range(1, count + 1):
        for attempt in range(100):
            rng = np.random.default_rng([seed, _KIND_CODE[kind], number, attempt])
            params = gen(rng)
            if _key(params) not in seen:
                break
        seen.add(_key(params))
        if kind == "wittenbauer":
            out.append(energy_mass_from_press(params, seed=seed, number=number))
        else:
            out.append(_CLASSES[kind](seed=seed, number=number, **params))
    return tuple(out)


def variant(kind: str, *, seed: int, number: int) -> Variant:
    """Variant ``number`` of ``kind`` for ``seed`` (the same as in any batch of that seed)."""
    return variants(kind, count=_check_count(number, "the variant number", 1), seed=seed)[-1]


def parse_id(text: str) -> Variant | None:
    """The variant an id ``"KIND:SEED:NUMBER"`` names, or None when ``text`` is not such an id.

    >>> parse_id("indicator:7:2").id, parse_id("W1")
    ('indicator:7:2', None)
    """
    m = re.fullmatch(r"([a-z-]+):(\d+):(\d+)", str(text).strip())
    if not m or m.group(1) not in KINDS:
        return None
    if len(m.group(3)) > 6 or int(m.group(3)) > MAX_VARIANTS:
        raise InputError(f"{text}: variant number {m.group(3)[:20]} is above the limit {MAX_VARIANTS} of a worksheet set")
    if len(m.group(2)) > 19 or int(m.group(2)) > 2**63 - 1:
        raise InputError(f"{text}: seed {m.group(2)[:20]}… is above the limit 2**63 − 1")
    return variant(m.group(1), seed=int(m.group(2)), number=int(m.group(3)))


# ----------------------------------------------------------------------------- drawing elements

GRID_MINOR = Style(stroke="#d6d6d6", width_mm=0.1)
GRID_MAJOR = Style(stroke="#aaaaaa", width_mm=0.15)
RED = "#d01818"
WRONG = Style(stroke=RED, width_mm=0.5)
THICK = Style(width_mm=0.7)
TEXT_MM, LINE_MM, SMALL_MM = 3.2, 4.5, 2.7
PAGE = Page("A4", "portrait", frame=True)
X0, X1 = 15.0, 195.0


@dataclass(frozen=True)
class Grid(Element):
    """Graph paper: thin lines every ``step_mm``, darker every ``major_every``-th line, through ``anchor``.

    Drawn as a few zig-zag paths (the joins run along the border, which is drawn anyway), so a
    page of graph paper costs a handful of primitives.

    >>> g = Grid((10, 10, 60, 40), anchor=(20, 30))
    >>> len(g.primitives()), g.xs()[:3]
    (5, (10.0, 15.0, 20.0))
    """

    box: tuple
    anchor: tuple | None = None
    step_mm: float = 5.0
    major_every: int = 2
    name: str = "grid"

    def _ks(self, lo, hi, a):
        s = self.step_mm
        return range(math.ceil((lo - a) / s - 1e-9), math.floor((hi - a) / s + 1e-9) + 1)

    def xs(self) -> tuple[float, ...]:
        x0, _, x1, _ = self.box
        a = (self.anchor or self.box[:2])[0]
        return tuple(a + k * self.step_mm for k in self._ks(x0, x1, a))

    def primitives(self):
        x0, y0, x1, y1 = (float(v) for v in self.box)
        ax, ay = self.anchor or (x0, y0)
        prims = []
        for major in (False, True):
            xs = [ax + k * self.step_mm for k in self._ks(x0, x1, ax) if (k % self.major_every == 0) == major]
            ys = [ay + k * self.step_mm for k in self._ks(y0, y1, ay) if (k % self.major_every == 0) == major]
            style = GRID_MAJOR if major else GRID_MINOR
            for vals, vertical in ((xs, True), (ys, False)):
                if not vals:
                    continue
                pts = []
                for i, v in enumerate(vals):
                    a, b = (y0, y1) if vertical else (x0, x1)
                    ends = (a, b) if i % 2 == 0 else (b, a)
                    pts += [(v, e) for e in ends] if vertical else [(e, v) for e in ends]
                prims.append(Path(tuple(pts), style))
        prims.append(Path(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), GRID_MAJOR, closed=True))
        return tuple(prims)


@dataclass(frozen=True)
class ColorText(Element):
    """A line of text in a colour (a wrong answer in red on an overlay)."""

    at: tuple
    text: str
    size_mm: float = TEXT_MM
    anchor: str = "start"
    valign: str = "baseline"
    bold: bool = False
    color: str = "#000000"
    markup: bool = True
    name: str = "text"

    def primitives(self):
        return (make_label(self.at, self.text, size_mm=self.size_mm, anchor=self.anchor, valign=self.valign,
                           bold=self.bold, markup_=self.markup, color=self.color),)


@dataclass(frozen=True)
class Shapes(Element):
    """Primitives drawn as one element (symbols built from paths and circles)."""

    prims: tuple
    name: str = "shapes"

    def primitives(self):
        return tuple(self.prims)


_TOKEN = re.compile(r"[ \t\n]+|[\u2e80-\u9fff\u3000-\u303f\uff00-\uffef]|[^ \t\n\u2e80-\u9fff\u3000-\u303f\uff00-\uffef]+")
NBSP = "\u00a0"
_NO_LINE_START = set("，。；：、）」』》！？,.;:)")


def wrap(text: str, width_mm: float, size_mm: float) -> list[str]:
    """Break markup text into lines no wider than ``width_mm`` (at spaces, and between CJK characters).

    >>> wrap("one two three four", 20.0, 3.2)
    ['one two', 'three four']
    >>> len(wrap("等效驱动力矩与等效阻抗力矩曲线", 20.0, 3.2))
    3
    """
    lines, cur, space = [], "", False
    for tok in _TOKEN.findall(text):
        if tok.strip(" \t\n") == "":
            space = bool(cur)
            continue
        cand = cur + (" " if space else "") + tok
        if cur and tok[0] not in _NO_LINE_START and markup.text_width_mm(cand, size_mm) > width_mm:
            lines.append(cur)
            cur = tok
        else:
            cur = cand
        space = False
    if cur:
        lines.append(cur)
    return lines


def ground(at, *, width_mm: float = 9.0, name: str = "ground") -> Shapes:
    """A fixed pivot: pin circle on a small triangle standing on a hatched base."""
    x, y = at
    base = y + 4.5
    prims: list[Primitive] = [Path(((x, y), (x - 2.6, base), (x + 2.6, base)), THIN.with_(width_mm=0.35), closed=True),
             Path(((x - width_mm / 2, base), (x + width_mm / 2, base)), THIN.with_(width_mm=0.35))]
    k = int(width_mm // 1.8)
    for i in range(k + 1):
        hx = x - width_mm / 2 + i * width_mm / k
        prims.append(Path(((hx, base), (hx - 1.6, base + 1.8)), THIN))
    prims.append(Circle(x, y, 1.3, THIN.with_(width_mm=0.35, fill="#ffffff")))
    return Shapes(tuple(prims), name=name)


def pin(at, *, name: str = "pin") -> Shapes:
    """A pin joint: a small white circle."""
    return Shapes((Circle(at[0], at[1], 1.2, THIN.with_(width_mm=0.35, fill="#ffffff")),), name=name)


def slider(at, *, w: float = 12.0, h: float = 7.0, guide_mm: float = 40.0, name: str = "slider") -> Shapes:
    """A slider block centred on ``at`` on a horizontal guide hatched underneath."""
    x, y = at
    g = y + h / 2
    prims = [Polygon(((x - w / 2, y - h / 2), (x + w / 2, y - h / 2), (x + w / 2, g), (x - w / 2, g)),
                     THIN.with_(width_mm=0.5, fill="#ffffff")),
             Path(((x - guide_mm / 2, g), (x + guide_mm / 2, g)), THIN.with_(width_mm=0.35))]
    for i in range(int(guide_mm // 2.5) + 1):
        hx = x - guide_mm / 2 + i * 2.5
        prims.append(Path(((hx, g), (hx - 1.6, g + 1.8)), THIN))
    prims.append(Circle(x, y, 1.2, THIN.with_(width_mm=0.35, fill="#ffffff")))
    return Shapes(tuple(prims), name=name)


def arc(centre, radius: float, a0_deg: float, a1_deg: float, *, arrow: bool = False, style: Style = THIN,
        name: str = "arc") -> Shapes:
    """An arc from ``a0_deg`` to ``a1_deg`` (counterclockwise on paper when a1 > a0), optionally with a head."""
    cx, cy = centre
    t = np.radians(np.linspace(a0_deg, a1_deg, max(8, int(abs(a1_deg - a0_deg) / 5) + 2)))
    pts = tuple(zip((cx + radius * np.cos(t)).tolist(), (cy - radius * np.sin(t)).tolist()))
    prims: list[Primitive] = [Path(pts, style)]
    if arrow:
        end = np.array(pts[-1])
        d = end - np.array(pts[-2])
        d /= np.hypot(*d)
        n = np.array([-d[1], d[0]])
        base = end - 2.2 * d
        prims.append(Polygon((tuple(end), tuple(base + 0.8 * n), tuple(base - 0.8 * n))))
    return Shapes(tuple(prims), name=name)


def clip_ray(point, slope: float, box) -> tuple | None:
    """The segment of the line through ``point`` with paper slope ``slope`` (mm up per mm right) inside
    ``box`` (x0, y0, x1, y1), or None when it misses the box."""
    x0, y0, x1, y1 = box
    px, py = point
    # y(x) = py − slope (x − px); clip x so that y0 ≤ y ≤ y1
    lo, hi = x0, x1
    if slope != 0:
        xa = px - (y0 - py) / slope
        xb = px - (y1 - py) / slope
        lo, hi = max(lo, min(xa, xb)), min(hi, max(xa, xb))
    elif not y0 <= py <= y1:
        return None
    if hi <= lo:
        return None
    return ((lo, py - slope * (lo - px)), (hi, py - slope * (hi - px)))


# ----------------------------------------------------------------------------- constructions
# (drawn on the key pages, and by graphmethods.sheets.check on an overlay at a student's scales)

def staircase(first_x: float, y0: float, works, *, mu_E: float, step_mm: float, labels, nt, occ=None,
              wrong: dict | None = None, name: str = "staircase") -> list[Element]:
    """The energy indicator: arrows A_i/μ_E (up for a gain), ``step_mm`` apart, from (first_x, y0).

    ``wrong`` maps an interval index to a student's (wrong) arrow length in mm: that arrow is drawn
    red with the student's value beside it. Returns the elements (vectors named ``vector-ab`` …).
    """
    from graphmethods.sheets.layout import Occupancy

    nt = get_notation(nt)
    occ = occ or Occupancy()
    wrong = wrong or {}
    work = np.asarray(works, dtype=float)
    E = np.concatenate(([0.0], np.cumsum(work)))
    s_E = Scale(sym("mu_E", nt), unit("J", nt), mu_E)
    n = work.size
    xs = [first_x + k * step_mm for k in range(n)]

    def y(v):
        return y0 - s_E.to_mm(float(v))

    els: list[Element] = [Line((first_x - 6.0, y0), (xs[-1] + 6.0, y0), style=DASHED, name=f"{name}-start")]
    for k in range(n - 1):
        els.append(Line((xs[k], y(E[k + 1])), (xs[k + 1], y(E[k + 1])), style=DASHED,
                        name=f"{name}-level-{labels[k + 1]}"))
    vecs = []
    for k in range(n):
        bad = k in wrong
        style = Style(stroke=RED, width_mm=0.45) if bad else Style(width_mm=0.35)
        vec = Vector.of((xs[k], y(E[k])), value=float(work[k]), scale=s_E, angle_deg=90.0, style=style,
                        name=f"vector-{labels[k]}{labels[k + 1]}")
        vecs.append(vec)
    for e in els + vecs:
        occ.add_primitives(e.primitives())
    texts: list[Element] = []
    for k in range(n + 1):
        at = (xs[0], y0) if k == 0 else (xs[k - 1], y(E[k]))
        dirs = ("w", "nw", "sw") if k == 0 else ("e", "ne", "se", "w", "nw", "sw", "n", "s")
        lab = occ.place_label(at, labels[k], dirs, size_mm=TEXT_MM, gap_mm=1.0)
        texts.append(Text((lab.x, lab.y), labels[k], size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-name-{k}"))
    for k, vec in enumerate(vecs):
        text = num(work[k], nt, plus=True)
        lab = occ.place_label(vec.mid, text, ("w", "e", "nw", "sw", "ne", "se"), size_mm=SMALL_MM, gap_mm=1.2)
        texts.append(Text((lab.x, lab.y), text, size_mm=SMALL_MM, anchor=lab.anchor, name=f"{name}-value-{k + 1}"))
        if k in wrong:
            t = f"{num(wrong[k], nt)} {unit('mm', nt)}?"
            lab = occ.place_label(vec.mid, t, ("e", "w", "ne", "se", "nw", "sw"), size_mm=SMALL_MM, gap_mm=3.0)
            texts.append(ColorText((lab.x, lab.y), t, size_mm=SMALL_MM, anchor=lab.anchor, color=RED,
                                   name=f"{name}-student-{k + 1}"))
    return els + vecs + texts


def extremes(first_x: float, y0: float, works, *, mu_E: float, step_mm: float, nt, unit_J: str = "J",
             occ=None, name: str = "extremes") -> list[Element]:
    """E_max and E_min of a staircase marked, their levels carried right, ΔW_max dimensioned."""
    from graphmethods.scene import Dimension

    nt = get_notation(nt)
    work = np.asarray(works, dtype=float)
    E = np.concatenate(([0.0], np.cumsum(work)))
    s_E = Scale("μ", "J", mu_E)
    n = work.size
    i_max, i_min = int(np.argmax(E)), int(np.argmin(E))
    x_end = first_x + (n - 1) * step_mm
    x_dim = x_end + 12.0

    def at(k):
        return (first_x + max(k - 1, 0) * step_mm, y0 - s_E.to_mm(float(E[k])))

    els: list[Element] = []
    for k, key in ((i_max, "max"), (i_min, "min")):
        p = at(k)
        els.append(Line(p, (x_dim + 2.0, p[1]), style=DASHED, name=f"{name}-level-{key}"))
        els.append(Point(p, radius_mm=1.1, filled=False, name=f"{name}-mark-{key}"))
    dW = float(E[i_max] - E[i_min])
    els.append(Dimension((x_dim, at(i_min)[1]), (x_dim, at(i_max)[1]),
                         f"{sym('delta_W_max', nt)} = {num(dW, nt)} {unit(unit_J, nt)}", size_mm=TEXT_MM,
                         name=f"{name}-dimension"))
    if occ is not None:
        for e in els:
            occ.add_primitives(e.primitives())
    return els


def energy_mass_construction(res, *, origin, box, axes=(), nt="en", prefix: str = "key-") -> list[Element]:
    """The energy–mass diagram of a construction ``res`` (its curve, rays, k, l, kl, ψ, position numbers)
    at ``origin`` (page point of J_e = 0, ΔT = 0), inside ``box``, drawn by
    :func:`graphmethods.sheets.wittenbauer.diagram_elements` over the given ``axes`` (which it keeps
    its labels off; its own axes are left out, the page's are drawn instead)."""
    from graphmethods.sheets.dynamics import FastOccupancy
    from graphmethods.sheets.wittenbauer import diagram_elements

    occ = FastOccupancy()
    for a in axes:
        occ.add_primitives(a.primitives())
    J = np.asarray(res.x_mm) * res.mu_J
    T = np.asarray(res.y_mm) * res.mu_T
    ox, oy = origin
    T_hi = min(max(float(T.max()), res.k_mm * res.mu_T, 0.0), (oy - box[1] - 6.0) * res.mu_T)
    T_lo = max(min(float(T.min()), res.l_mm * res.mu_T, 0.0), -(box[3] - oy - 2.0) * res.mu_T)
    els = diagram_elements(res, origin=origin, nt=nt, occ=occ, clip=box, J_to=float(J.max()), T_hi=T_hi,
                           T_lo=T_lo, within=box, prefix=prefix)
    return [e for e in els if e.name not in (f"{prefix}axis-J", f"{prefix}axis-T")]


def velocity_plan(pole, vectors: dict, *, mu_v: float, link_dir, nt="en", wrong: dict | None = None, occ=None,
                  name: str = "plan") -> list[Element]:
    """A slider-crank's velocity plan from ``pole``: pa, pb, ab, ps2 with the construction lines.

    ``vectors`` maps plan labels (p, a, b, s2) to velocities (m/s); ``link_dir`` is the unit vector A→B
    (the line through a is ⊥ AB, the one through p ∥ the guide). ``wrong`` maps a segment (``"pb"``) to
    a student's length in mm: drawn red with the value beside it.
    """
    from graphmethods.sheets.layout import Occupancy

    occ = occ or Occupancy()
    wrong = wrong or {}
    px, py = pole

    def P(v):
        return (px + float(v[0]) / mu_v, py - float(v[1]) / mu_v)

    pts = {k: P(v) for k, v in vectors.items()}
    a, b = np.array(pts["a"]), np.array(pts["b"])
    u = np.array([float(link_dir[0]), -float(link_dir[1])])       # A→B on paper
    n = np.array([-u[1], u[0]])                                   # ⊥ AB on paper
    t = [float((p - a) @ n) for p in (a, b)]
    t0, t1 = min(t) - 12.0, max(t) + 12.0
    els: list[Element] = [
        Line(tuple(a + t0 * n), tuple(a + t1 * n), style=THIN, name=f"{name}-line-perp-AB"),
        Line((min(px, b[0]) - 12.0, py), (max(px, b[0]) + 12.0, py), style=THIN, name=f"{name}-line-guide")]
    for seg, (f, to) in SEGMENTS.items():
        style = Style(stroke=RED, width_mm=0.45) if seg in wrong else Style(width_mm=0.35)
        els.append(Vector(pts[f], pts[to], style=style, name=f"{name}-{seg}"))
    for e in els:
        occ.add_primitives(e.primitives())
    occ.add_box((px - 1.0, py - 1.0, px + 1.0, py + 1.0))
    for lab_text in ("p", "a", "b", "s2"):
        text = "s_{2}" if lab_text == "s2" else lab_text
        lab = occ.place_label(pts[lab_text], text, ("nw", "ne", "sw", "se", "n", "s", "w", "e"), size_mm=TEXT_MM,
                              gap_mm=1.0)
        els.append(Text((lab.x, lab.y), text, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-name-{lab_text}"))
    for seg in SEGMENTS:
        if seg in wrong:
            f, to = SEGMENTS[seg]
            mid = ((pts[f][0] + pts[to][0]) / 2, (pts[f][1] + pts[to][1]) / 2)
            txt = f"{seg} = {num(wrong[seg], nt)} {unit('mm', nt)}?"
            lab = occ.place_label(mid, txt, ("e", "w", "ne", "nw", "se", "sw"), size_mm=SMALL_MM, gap_mm=2.0)
            els.append(ColorText((lab.x, lab.y), txt, size_mm=SMALL_MM, anchor=lab.anchor, color=RED,
                                 name=f"{name}-student-{seg}"))
    return els


def moment_regions(frame, cycle, *, wrong: dict | None = None, nt="en", occ=None,
                   name: str = "moments") -> list[Element]:
    """M_d and M_r drawn through ``frame`` (φ from the period start, rad → mm), the intervals hatched,
    the boundary points a, b, … labelled. ``wrong`` maps an interval index to a student's area (mm²):
    that region is outlined red with the value written in it."""
    from graphmethods.sheets.layout import Occupancy

    occ = occ or Occupancy()
    wrong = wrong or {}
    M_d, M_r = cycle.M_d, cycle.M_r
    phi0 = float(M_d.start)
    els: list[Element] = []
    regions = []
    for i in range(cycle.work.size):
        a, b = float(cycle.phi[i]), float(cycle.phi[i + 1])
        pd, md = _piece(M_d, a, b)
        pr, mr = _piece(M_r, a, b)
        outline = frame.pts(np.concatenate((pd, pr[::-1])) - phi0, np.concatenate((md, mr[::-1])))
        gain = cycle.work[i] > 0
        bad = i in wrong
        regions.append(Region(outline, hatch_angle_deg=45.0 if gain else 135.0, hatch_spacing_mm=2.5,
                              style=Style(stroke=RED, width_mm=0.18) if bad else THIN,
                              outline_style=Style(stroke=RED, width_mm=0.45) if bad else None,
                              name=f"{name}-region-{i + 1}"))
    cd = frame.curve(M_d.phi - phi0, M_d.M, style=MAIN, name=f"{name}-M_d")
    cr = frame.curve(M_r.phi - phi0, M_r.M, style=MAIN, name=f"{name}-M_r")
    els += regions + [cd, cr]
    for e in (cd, cr):
        occ.add_primitives(e.primitives())
    for i in range(cycle.work.size):
        occ.add_primitives(regions[i].primitives())
    for k, ph in enumerate(cycle.phi):
        at = frame.pt(float(ph) - phi0, float(M_d(float(ph))) if k < len(cycle.phi) - 1 else float(M_d.M[-1]))
        lab = occ.place_label(at, cycle.labels[k], ("n", "nw", "ne", "s", "sw", "se"), size_mm=TEXT_MM, gap_mm=1.0)
        els.append(Point(at, radius_mm=0.6, name=f"{name}-dot-{k}"))
        els.append(Text((lab.x, lab.y), cycle.labels[k], size_mm=TEXT_MM, anchor=lab.anchor,
                        name=f"{name}-name-{k}"))
    for i, val in sorted(wrong.items()):
        shape = regions[i].shape()
        c = shape.representative_point()
        txt = f"{num(val, nt)} {unit('mm²', nt)}?"
        lab = occ.place_label((c.x, c.y), txt, ("n", "s", "e", "w", "ne", "se"), size_mm=SMALL_MM, gap_mm=0.5)
        els.append(ColorText((lab.x, lab.y), txt, size_mm=SMALL_MM, anchor=lab.anchor, color=RED,
                             name=f"{name}-student-{i + 1}"))
    for key, _curve, el in (("M_d", M_d, cd), ("M_r", M_r, cr)):
        lab = occ.place_label(el.end, sym(key, nt), ("e", "ne", "se"), size_mm=TEXT_MM, gap_mm=1.5)
        els.append(Text((lab.x, lab.y), sym(key, nt), size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-{key}-name"))
    return els


def _piece(curve, a: float, b: float):
    inner = (curve.phi > a) & (curve.phi < b)
    left_b = curve.limits(np.array([b]))[0][0]
    right_a = curve.limits(np.array([a]))[1][0]
    return (np.concatenate(([a], curve.phi[inner], [b])), np.concatenate(([right_a], curve.M[inner], [left_b])))


def region_perimeters_mm(cycle, *, mu_M: float, mu_phi: float) -> np.ndarray:
    """Perimeter (mm) of each interval's region between M_d and M_r, drawn at μ_M (N·m/mm), μ_φ (rad/mm)."""
    out = []
    for i in range(cycle.work.size):
        a, b = float(cycle.phi[i]), float(cycle.phi[i + 1])
        pd, md = _piece(cycle.M_d, a, b)
        pr, mr = _piece(cycle.M_r, a, b)
        x = np.concatenate((pd, pr[::-1], pd[:1])) / mu_phi
        y = np.concatenate((md, mr[::-1], md[:1])) / mu_M
        out.append(float(np.hypot(np.diff(x), np.diff(y)).sum()))
    return np.asarray(out)


def slider_crank_scheme(O, *, r: float, l: float, e: float, l_AS2: float, phi_deg: float, mu_l: float,
                        nt="en", guide_mm: float = 40.0, name: str = "scheme") -> list[Element]:
    """A slider-crank drawn at μ_l (m/mm) in the position φ: ground at O, crank, rod, slider on its
    guide (the line y = e), S2, the angle φ and the crank's sense."""
    ox, oy = O
    ph = math.radians(phi_deg)
    A = (r * math.cos(ph), r * math.sin(ph))
    xB = A[0] + math.sqrt(l * l - (e - A[1]) ** 2)
    B = (xB, e)
    S = (A[0] + (B[0] - A[0]) * l_AS2 / l, A[1] + (B[1] - A[1]) * l_AS2 / l)

    def P(p):
        return (ox + p[0] / mu_l, oy - p[1] / mu_l)

    pO, pA, pB, pS = P((0.0, 0.0)), P(A), P(B), P(S)
    els: list[Element] = [
        Line((ox - 6.0, oy), (ox + r / mu_l + 14.0, oy), style=Style(width_mm=0.18, dash=(6.0, 1.5, 1.0, 1.5)),
             name=f"{name}-x-axis"),
        arc(pO, 9.0, 0.0, phi_deg, name=f"{name}-phi-arc"),
        arc(pO, 13.0, phi_deg + 18.0, phi_deg + 58.0, arrow=True, name=f"{name}-omega"),
        slider(pB, guide_mm=guide_mm, name=f"{name}-slider"),
        Line(pO, pA, style=THICK, name=f"{name}-crank"),
        Line(pA, pB, style=THICK, name=f"{name}-rod"),
        ground(pO, name=f"{name}-ground"), pin(pA, name=f"{name}-pin-A"),
        Point(pS, radius_mm=0.9, name=f"{name}-S2"),
    ]
    from graphmethods.sheets.layout import Occupancy

    occ = Occupancy()
    for el in els:
        occ.add_primitives(el.primitives())
    phi_lab = None
    for frac in (0.5, 0.35, 0.65, 0.2, 0.8):
        mid = math.radians(phi_deg * frac)
        at = (pO[0] + 9.0 * math.cos(mid), pO[1] - 9.0 * math.sin(mid))
        d = ("e" if math.cos(mid) > 0.4 else "w" if math.cos(mid) < -0.4 else "") + ""
        d = ("n" if math.sin(mid) > 0.4 else "s" if math.sin(mid) < -0.4 else "") + d
        phi_lab = occ.first_free(at, "φ", (d or "n",), (0.8, 2.0), TEXT_MM, None)
        if phi_lab is not None:
            break
    if phi_lab is None:
        phi_lab = make_label((pO[0] + 11.5, pO[1] - 2.0), "φ", size_mm=TEXT_MM, valign="middle")
    occ.add_label(phi_lab)
    w = math.radians(phi_deg + 60.0)
    om_lab = make_label((pO[0] + 15.0 * math.cos(w), pO[1] - 15.0 * math.sin(w)), "ω_{1}", size_mm=TEXT_MM,
                        anchor="start" if math.cos(w) >= 0 else "end", valign="middle")
    texts = [Text((phi_lab.x, phi_lab.y), "φ", size_mm=TEXT_MM, anchor=phi_lab.anchor, name=f"{name}-phi"),
             Text((om_lab.x, om_lab.y), "ω_{1}", size_mm=TEXT_MM, anchor=om_lab.anchor, name=f"{name}-omega-name")]
    for t in texts:
        occ.add_primitives(t.primitives())
    for txt, at, dirs in (("O", pO, ("w", "nw", "sw", "e", "ne")), ("A", pA, ("n", "nw", "ne", "w", "e", "s")),
                          ("B", pB, ("ne", "n", "nw")), ("S_{2}", pS, ("s", "n", "se", "sw", "ne", "nw"))):
        lab = occ.place_label(at, txt, dirs, size_mm=TEXT_MM, gap_mm=2.6 if txt == "O" else 1.8)
        texts.append(Text((lab.x, lab.y), txt, size_mm=TEXT_MM, anchor=lab.anchor, name=f"{name}-name-{txt[0]}"))
    return els + texts


# ----------------------------------------------------------------------------- pages

BOTTOM = 233.0          # the answers and the solution (or the student's calculations) start here
CAPTION_ROOM = 9.0      # the scale captions under a drawing area


def _clean(values, ref: float | None = None) -> np.ndarray:
    """Round-off (below 1e-9 of the largest magnitude) written as 0."""
    x = np.asarray(values, dtype=float)
    ref = float(np.max(np.abs(x))) if ref is None else ref
    return np.where(np.abs(x) <= 1e-9 * max(ref, 1e-300), 0.0, x)


class _Sheet:
    """Builds one A4 portrait page top-down: header, statement, tables, a drawing area, answers.

    Student and key pages of a variant share every position (the key is the student's page filled
    in), so the key laid over a student's sheet lines up.
    """

    def __init__(self, v: Variant, nt, key: bool):
        self.v, self.nt, self.key = v, get_notation(nt), key
        self.els: list[Element] = []
        self.y = 35.0

    def add(self, *els):
        self.els.extend(els)

    def header(self) -> None:
        nt = self.nt
        self.add(Text((X0, 19.0), self.v.title.title_in(nt.code), size_mm=4.6, bold=True, name="title"),
                 Text((X1, 19.0), f"{word('variant', nt)} {self.v.number}", size_mm=4.6, bold=True, anchor="end",
                      name="variant"))
        if self.key:
            self.add(ColorText((X0, 26.0), word("key", nt), size_mm=4.0, bold=True, color=RED, name="key-mark"),
                     Text((X1, 26.0), markup.literal(self.v.id), size_mm=SMALL_MM, anchor="end", name="id"))
        else:
            x = X0
            for key, length in (("name", 62.0), ("group", 30.0), ("date", 28.0)):
                text = word(key, nt) + ":"
                self.add(Text((x, 26.0), text, size_mm=TEXT_MM, name=f"field-{key}"))
                x += markup.text_width_mm(text, TEXT_MM) + 1.5
                self.add(Line((x, 26.8), (x + length, 26.8), style=THIN, name=f"blank-{key}"))
                x += length + 5.0
        self.add(Line((X0, 29.0), (X1, 29.0), style=THIN, name="header-rule"))

    def paragraph(self, text: str, *, indent: float = 0.0, size: float = TEXT_MM, name: str = "statement") -> None:
        for k, line in enumerate(wrap(text, X1 - X0 - indent, size)):
            self.add(Text((X0 + indent, self.y), line, size_mm=size, name=f"{name}-{k}"))
            self.y += size * 1.4
        self.y += 0.6

    def statement(self, fmt: dict) -> None:
        # each filled-in value (a scale, a number with its unit) stays on one line
        fmt = {k: v.replace(" ", NBSP) if isinstance(v, str) else v for k, v in fmt.items()}
        # one tuple of paragraphs per language, picked alike (in_language's triple of texts, without fill)
        parts: tuple[str, ...] = in_language(STATEMENTS[self.v.kind], self.nt)  # type: ignore[arg-type,assignment]
        self.paragraph(parts[0].format(**fmt), name="given")
        for k, task in enumerate(parts[1:]):
            self.paragraph(task.format(**fmt), indent=4.0, name=f"task-{k + 1}")
        self.y += 1.5

    def table(self, rows, *, align: str = "", value_rows=(), size: float = 3.0, row_mm: float = 6.5,
              value_row_mm: float = 8.5, name: str = "table", full: bool = True, width_rows=None) -> Table:
        """A table as wide as the text (``full``), fonts shrunk until it fits; ``value_rows`` are taller.

        ``width_rows`` (the key's filled-in rows) size the columns, so that the student's table with
        blank cells and the key's are the same table.
        """
        rows = tuple(tuple(r) for r in rows)
        measure = rows if width_rows is None else tuple(tuple(r) for r in width_rows)
        for sz in (size, 2.8, 2.6, 2.4, 2.2):
            probe = Table((X0, self.y), measure, size_mm=sz, row_height_mm=row_mm, align=align, padding_mm=1.5,
                          min_col_mm=6.0)
            if probe.width_mm <= X1 - X0:
                break
        else:
            raise InputError(f"{self.v.id}: the table {name} does not fit the page width")
        widths = list(probe.column_widths())
        if full:
            extra = (X1 - X0 - sum(widths)) / max(len(widths) - 1, 1)
            widths = [widths[0]] + [w + extra for w in widths[1:]]
        tables = []
        y = self.y
        for i, row in enumerate(rows):          # rows one by one: value rows taller
            h = value_row_mm if i in value_rows else row_mm
            tables.append(Table((X0, y), (row,), col_widths_mm=tuple(widths), row_height_mm=h, size_mm=sz,
                                header_rows=1 if i == 0 else 0, align=align or "c" * len(row), padding_mm=1.5,
                                bold_rows=(0,) if i == 0 else (), name=f"{name}-row-{i}"))
            y += h
        self.add(*tables)
        self.y = y + 4.0
        return tables[0]

    def drawing_box(self, bottom: float = BOTTOM) -> tuple[float, float]:
        """(top, height) of the drawing area from here down to the captions above ``bottom``."""
        top = self.y
        H = bottom - CAPTION_ROOM - top
        if H < 40.0:
            raise InputError(f"{self.v.id}: the statement and tables leave only {H:.0f} mm for the drawing")
        return top, H

    def caption(self, texts, *, y: float, name: str = "captions") -> None:
        x = X0
        for k, t in enumerate(texts):
            self.add(Text((x, y), t, size_mm=TEXT_MM, name=f"{name}-{k}"))
            x += markup.text_width_mm(t, TEXT_MM) + 8.0

    def footer(self) -> None:
        nt = self.nt
        text = f"graphmethods worksheet {self.v.kind} --seed {self.v.seed} · {word('variant', nt)} {self.v.number}"
        self.add(Text((X0, 284.0), markup.literal(text), size_mm=2.3, name="footer"))
        if self.key:
            self.add(Text((X1, 284.0), markup.literal(word("check", nt, id=self.v.id)), size_mm=2.3, anchor="end",
                          name="footer-check"))

    def scene(self, scales=()) -> Scene:
        self.footer()
        kind = "key" if self.key else "student"
        if self.y > 281.0:
            raise InputError(f"{self.v.id}: the {kind} page runs {self.y - 281.0:.0f} mm past its frame")
        return Scene(PAGE, tuple(self.els), title=f"{self.v.title.title_in(self.nt.code)} — "
                     f"{word('variant', self.nt)} {self.v.number}" + (f" ({word('key', self.nt)})" if self.key else ""),
                     notation=self.nt.code, name=f"{self.v.kind}-{kind}-{self.v.number:02d}",
                     extra_scales=tuple(scales))


def _answers_and_solution(sh: _Sheet, heads, values, lines) -> None:
    """The answer boxes (blank on the student's page) and the worked solution (key) or room to work."""
    nt = sh.nt
    sh.y = max(sh.y, BOTTOM)
    sh.add(Text((X0, sh.y + 3.0), word("answers", nt), size_mm=TEXT_MM + 0.3, bold=True, name="answers-title"))
    sh.y += 5.5
    vals = list(values) if sh.key else [""] * len(heads)
    sh.table((heads, vals), value_rows=(1,), name="answers", value_row_mm=9.0, width_rows=(heads, values))
    sh.add(Text((X0, sh.y + 0.5), word("solution" if sh.key else "work", nt), size_mm=TEXT_MM + 0.3, bold=True,
                name="solution-title"))
    sh.y += 5.0
    if not sh.key:
        return
    for k, line in enumerate(lines):
        for part in wrap(line, X1 - X0 - 4.0, TEXT_MM - 0.2):
            sh.add(Text((X0 + 4.0, sh.y), part, size_mm=TEXT_MM - 0.2, name=f"solution-{k}"))
            sh.y += LINE_MM


def _omega_lines(v, nt) -> list[str]:
    f, om = v.flywheel, sym("omega_m", nt)
    rs = unit("rad/s", nt)
    return [f"{om} = πn/30 = π·{num(v.n_rpm, nt)}/30 = {num(f.omega_m, nt)} {rs};  ω_{{max}} = {om}(1 + δ/2) = "
            f"{num(f.omega_max, nt)} {rs};  ω_{{min}} = {om}(1 − δ/2) = {num(f.omega_min, nt)} {rs}",
            f"{sym('J_F', nt)} = {sym('delta_W_max', nt)}/({om}²[δ]) − {sym('J_e', nt)} = "
            f"{num(f.delta_W_max, nt)}/({num(f.omega_m, nt)}²·{v.delta}) − {num(v.J_e, nt)} = "
            f"{num(f.J_F, nt)} {unit('kg·m²', nt)}"]


def _flywheel_heads(nt) -> list[str]:
    rs = "rad/s"
    return [quantity(sym("omega_m", nt), rs, nt), quantity("ω_{max}", rs, nt), quantity("ω_{min}", rs, nt)]


def _clear_tick_labels(axis: Axis, points) -> Axis:
    """The axis with the tick labels that a polyline (page points) runs through left out."""
    from graphmethods.scene.elements import label_bbox
    from graphmethods.scene.primitives import Label
    from graphmethods.sheets.layout import Occupancy

    occ = Occupancy(pad_mm=0.4)
    occ.add_line(points)
    texts = [p for p in axis.primitives() if isinstance(p, Label)]
    labels = list(axis.tick_labels) if axis.tick_labels is not None else \
        [format_tick(v, axis.decimal) for v in axis.ticks]
    shown = [i for i, v in enumerate(axis.ticks) if labels[i] and not (axis.skip_zero_label and v == 0)]
    for i, lab in zip(shown, texts):
        if not occ.is_free(label_bbox(lab)):
            labels[i] = ""
    return replace(axis, tick_labels=tuple(labels))


def format_tick(v: float, decimal: str) -> str:
    from graphmethods.scene import format_value

    return format_value(v, decimal=decimal)


def _indicator_page(v: IndicatorVariant, nt, key: bool) -> Scene:
    from graphmethods.sheets.layout import Occupancy

    sh = _Sheet(v, nt, key)
    nt = sh.nt
    sh.header()
    c, f = v.excess_work, v.flywheel
    s_M = Scale(sym("mu_M", nt), unit("N·m", nt), v.mu_M)
    s_phi = Scale(sym("mu_phi", nt), unit("rad", nt), v.mu_phi)
    s_E = Scale(sym("mu_E", nt), unit("J", nt), v.mu_E)
    sh.statement(dict(mu_M=s_M.caption(nt), mu_phi=s_phi.caption(nt), M_d=sym("M_d", nt), M_r=sym("M_r", nt),
                      n=value_unit(v.n_rpm, "rev/min", nt), delta=v.delta,
                      J_e=f"{sym('J_e', nt)} = {value_unit(v.J_e, 'kg·m²', nt)}", A=sym("A", nt), E=sym("E", nt),
                      mu_E=s_E.caption(nt), step=word("step", nt, step=num(v.step_mm, nt)),
                      dW=sym("delta_W_max", nt), J_F_sym=sym("J_F", nt)))
    L, n = c.labels, c.work.size
    E = _clean(c.E)
    full = [[word("interval", nt), ""] + [f"{L[i]}–{L[i + 1]}" for i in range(n)],
            [quantity("f", "mm²", nt), ""] + [num(a, nt, plus=True) for a in c.areas_mm2],
            [quantity(sym("A", nt), "J", nt), ""] + [num(a, nt, plus=True, sig=6) for a in c.work],
            [word("point_end", nt), L[0]] + list(L[1:]),
            [quantity(sym("E", nt), "J", nt), num(0, nt)] + [num(e, nt, sig=6) for e in E[1:]]]
    shown = full if key else [r if i not in (2, 4) else r[:2] + [""] * n for i, r in enumerate(full)]
    sh.table(shown, align="l" + "c" * (n + 1), value_rows=(2, 4), name="data", width_rows=full)
    # the drawing area: E axis and graph paper
    top, H = sh.drawing_box()
    ax_x = X0 + 16.0
    first = ax_x + 12.0
    E_hi, E_lo = max(float(E.max()), 0.0), min(float(E.min()), 0.0)
    y0 = top + (H - s_E.to_mm(E_hi - E_lo)) / 2 + s_E.to_mm(E_hi)
    y0 = top + 5.0 * round((y0 - top) / 5.0)              # the origin on a grid line
    sh.add(Grid((X0, top, X1, top + H), anchor=(ax_x, y0), name="grid"))
    v_top, v_bot = s_E.to_value(y0 - top - 6.0), -s_E.to_value(top + H - y0 - 2.0)
    axis = Axis((ax_x, y0), s_E, "y", min_value=v_bot, max_value=v_top,
                ticks=nice_ticks(v_bot, v_top, s_E, min_gap_mm=10.0), label=quantity(sym("E", nt), "J", nt),
                size_mm=SMALL_MM, decimal=nt.decimal, name="axis-E")
    sh.add(axis)
    occ = Occupancy()
    occ.add_primitives(axis.primitives())
    if key:
        sh.add(*staircase(first, y0, c.work, mu_E=v.mu_E, step_mm=v.step_mm, labels=L, nt=nt, occ=occ))
        sh.add(*extremes(first, y0, c.work, mu_E=v.mu_E, step_mm=v.step_mm, nt=nt, occ=occ))
    else:
        sh.add(Point((first, y0), label="a", label_dir="w", size_mm=TEXT_MM, gap_mm=1.5, name="start-a"))
    sh.caption([s_E.caption(nt), word("step", nt, step=num(v.step_mm, nt))], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    i, j = c.index_E_max, c.index_E_min
    _answers_and_solution(
        sh, _flywheel_heads(nt) + [quantity(sym("delta_W_max", nt), "J", nt), f"ω_{{max}}: {word('at_point', nt)}",
                                   f"ω_{{min}}: {word('at_point', nt)}", quantity(sym("J_F", nt), "kg·m²", nt)],
        [num(f.omega_m, nt), num(f.omega_max, nt), num(f.omega_min, nt), num(c.delta_W_max, nt),
         L[c.index_E_max], L[c.index_E_min], num(f.J_F, nt)],
        [f"{sym('A', nt)}_{{i}} = f_{{i}}·{sym('mu_M', nt)}·{sym('mu_phi', nt)} = f_{{i}}·"
         f"{num(v.mu_M * v.mu_phi, nt, sig=6)} {unit('J', nt)}/{unit('mm²', nt)};  "
         f"{sym('delta_W_max', nt)} = {sym('E_max', nt)} − {sym('E_min', nt)} = {num(E[i], nt)} − "
         f"({num(E[j], nt)}) = {num(c.delta_W_max, nt)} {unit('J', nt)}"] + _omega_lines(v, nt))
    return sh.scene((s_E,))


def _step_page(v: StepMomentVariant, nt, key: bool) -> Scene:
    from graphmethods.scene.elements import Frame
    from graphmethods.sheets.layout import Occupancy

    sh = _Sheet(v, nt, key)
    nt = sh.nt
    sh.header()
    c, f = v.excess_work, v.flywheel
    s_M = Scale(sym("mu_M", nt), unit("N·m", nt), v.mu_M)
    s_phi = Scale(sym("mu_phi", nt), unit("rad", nt), v.mu_phi, alt_per_mm=v.mu_phi_deg, alt_unit="°")
    sh.statement(dict(M_r=sym("M_r", nt), M_d=sym("M_d", nt), shape=in_language(SHAPES[v.shape], nt),
                      n=value_unit(v.n_rpm, "rev/min", nt), delta=v.delta,
                      J_e=f"{sym('J_e', nt)} = {value_unit(v.J_e, 'kg·m²', nt)}", mu_M=s_M.caption(nt),
                      mu_phi=s_phi.caption(nt), A=sym("A", nt), E=sym("E", nt), dW=sym("delta_W_max", nt),
                      J_F_sym=sym("J_F", nt)))
    deg = unit("°", nt)
    if v.shape == "steps":
        st = v.steps()
        sh.table([[quantity("φ", "°", nt)] + [f"{num(a, nt)}…{num(b, nt)}" for a, b, _ in st],
                  [quantity(sym("M_r", nt), "N·m", nt)] + [num(m, nt) for _, _, m in st]],
                 align="l" + "c" * len(st), name="data")
    else:
        sh.table([[quantity("φ", "°", nt)] + [num(p, nt) for p in v.phi_deg],
                  [quantity(sym("M_r", nt), "N·m", nt)] + [num(m, nt) for m in v.M_r]],
                 align="l" + "c" * len(v.phi_deg), name="data")
    # the moment diagram: axes at the stated scales on graph paper
    n = c.work.size
    cols = max(n, 6)
    row_mm = 7.0
    table_h = 5 * row_mm + 4.0
    top, H = sh.drawing_box(BOTTOM - table_h)
    M_hi = max(max(v.M_r), v.M_d)
    ax_x = X0 + 16.0
    y0 = top + 5.0 * math.floor((H - 9.0) / 5.0)             # the φ axis near the bottom, on a grid line
    if s_M.to_mm(M_hi) > y0 - top - 10.0:
        raise InputError(f"{v.id}: the moment diagram at {markup.plain(s_M.caption())} does not fit its box")
    sh.add(Grid((X0, top, X1, top + H), anchor=(ax_x, y0), name="grid"))
    frame = Frame((ax_x, y0), s_phi, s_M)
    grid_deg = 45 if all(p % 45 == 0 for p in v.phi_deg) else 30
    ticks = tuple(math.radians(d) for d in range(0, 361, grid_deg))
    ax_phi = Axis((ax_x, y0), s_phi, "x", min_value=0.0, max_value=2 * math.pi, ticks=ticks,
                  tick_labels=tuple(f"{d}{deg}" for d in range(0, 361, grid_deg)), label="φ", size_mm=SMALL_MM,
                  skip_zero_label=True, name="axis-phi")
    m_top = s_M.to_value(y0 - top - 7.0)
    ax_M = Axis((ax_x, y0), s_M, "y", min_value=0.0, max_value=m_top, ticks=nice_ticks(0.0, m_top, s_M, min_gap_mm=8.0),
                label=quantity("M", "N·m", nt), size_mm=SMALL_MM, decimal=nt.decimal, name="axis-M")
    sh.add(ax_phi, ax_M)
    if key:
        occ = Occupancy()
        for a in (ax_phi, ax_M):
            occ.add_primitives(a.primitives())
        sh.add(*moment_regions(frame, c, nt=nt, occ=occ))
    sh.caption([s_phi.caption(nt), s_M.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    # the excess-work table: blank columns for the student, the intervals in the key
    L = c.labels
    E = _clean(c.E)
    pad = [""] * (cols - n)

    def row(values):
        return list(values) + pad

    full = [[word("interval", nt)] + row(f"{L[i]}–{L[i + 1]}" for i in range(n)),
            [quantity("φ", "°", nt)] + row(f"{num(math.degrees(c.phi[i]), nt)}…{num(math.degrees(c.phi[i + 1]), nt)}"
                                           for i in range(n)),
            [quantity("f", "mm²", nt)] + row(num(a / (v.mu_M * v.mu_phi), nt, plus=True) for a in c.work),
            [quantity(sym("A", nt), "J", nt)] + row(num(a, nt, plus=True) for a in c.work),
            [f"{quantity(sym('E', nt), 'J', nt)} ({word('point_end', nt).lower()})"]
            + row(f"{num(E[i + 1], nt)} ({L[i + 1]})" for i in range(n))]
    shown = full if key else [r[:1] + [""] * cols for r in full]
    sh.table(shown, align="l" + "c" * cols, name="excess-work", row_mm=row_mm, width_rows=full)
    if v.shape == "steps":
        md = "(" + " + ".join(f"{num(m, nt)}·{num(b - a, nt)}" for a, b, m in v.steps()) + f")/360 = {num(v.M_d, nt)}"
    else:
        md = f"∫{sym('M_r', nt)}dφ/2π = {num(v.M_d, nt)}"
    _answers_and_solution(
        sh, [quantity(sym("M_d", nt), "N·m", nt), quantity(sym("delta_W_max", nt), "J", nt),
             quantity("φ(ω_{max})", "°", nt), quantity("φ(ω_{min})", "°", nt), quantity(sym("J_F", nt), "kg·m²", nt)],
        [num(v.M_d, nt), num(c.delta_W_max, nt), num(math.degrees(c.phi_E_max), nt), num(math.degrees(c.phi_E_min), nt),
         num(f.J_F, nt)],
        [f"{sym('M_d', nt)} = {md} {unit('N·m', nt)};  {sym('A', nt)}_{{i}} = ∫({sym('M_d', nt)} − "
         f"{sym('M_r', nt)})dφ;  {sym('delta_W_max', nt)} = {num(E.max(), nt)} − ({num(E.min(), nt)}) = "
         f"{num(c.delta_W_max, nt)} {unit('J', nt)}"] + _omega_lines(v, nt)[1:])
    return sh.scene((s_phi, s_M))


def _scheme_points(v: PlanVariant) -> dict:
    ph = math.radians(v.phi_deg)
    A = (v.r * math.cos(ph), v.r * math.sin(ph))
    B = (A[0] + math.sqrt(v.l ** 2 - (v.e - A[1]) ** 2), v.e)
    return {"O": (0.0, 0.0), "A": A, "B": B}


def _plan_layout(v: PlanVariant, top: float, H: float):
    """Pole position so that the plan sits in the middle of its box (the same on both pages)."""
    vec = v.vectors()
    xs = [float(p[0]) / v.mu_v for p in vec.values()]
    ys = [-float(p[1]) / v.mu_v for p in vec.values()]
    cx = (X0 + X1) / 2 - (min(xs) + max(xs)) / 2
    cy = top + H / 2 - (min(ys) + max(ys)) / 2
    return (5.0 * round(cx / 5.0), 5.0 * round(cy / 5.0))


def _plan_page(v: PlanVariant, nt, key: bool) -> Scene:
    from graphmethods.sheets.layout import Occupancy

    sh = _Sheet(v, nt, key)
    nt = sh.nt
    sh.header()
    s_l = Scale(sym("mu_l", nt), unit("m", nt), v.mu_l)
    s_v = Scale(sym("mu_v", nt), unit("(m/s)", nt), v.mu_v)
    sh.statement(dict(mu_l=s_l.caption(nt), mu_v=s_v.caption(nt), phi=f"{num(v.phi_deg, nt)}°",
                      r=value_unit(v.r, "m", nt), l=value_unit(v.l, "m", nt), e=value_unit(v.e, "m", nt),
                      AS2=value_unit(v.l_AS2, "m", nt), sense=word("ccw", nt),
                      omega_1=value_unit(v.omega_1, "rad/s", nt)))
    # the scheme at μ_l, as tall as this position needs
    pts = _scheme_points(v)
    ys = [p[1] for p in pts.values()]
    top = sh.y
    y_hi = max(max(ys) / v.mu_l, 13.0)           # above O: the highest point, or the ω₁ arrow
    y_lo = max(-min(ys) / v.mu_l, 0.0)
    O = (X0 + 6.0 + max(v.r / v.mu_l, 20.0), top + 7.0 + y_hi)
    xB = O[0] + pts["B"][0] / v.mu_l
    guide = min(40.0, 2.0 * (X1 - 1.0 - xB))
    if guide < 14.0:
        raise InputError(f"{v.id}: the scheme at {markup.plain(s_l.caption())} does not fit the page width")
    sh.add(*slider_crank_scheme(O, r=v.r, l=v.l, e=v.e, l_AS2=v.l_AS2, phi_deg=v.phi_deg, mu_l=v.mu_l, nt=nt,
                                guide_mm=guide))
    sh.add(Text((X1, top + 4.0), s_l.caption(nt), size_mm=TEXT_MM, anchor="end", name="caption-mu-l"))
    sh.y = O[1] + max(y_lo, 9.0) + 9.0
    # the plan's box
    top, H = sh.drawing_box()
    pole = _plan_layout(v, top, H)
    sh.add(Grid((X0, top, X1, top + H), anchor=pole, name="grid"))
    if key:
        occ = Occupancy()
        A = v.positions.xy("A")[0]
        B = v.positions.xy("B")[0]
        u = (B - A) / np.hypot(*(B - A))
        sh.add(*velocity_plan(pole, v.vectors(), mu_v=v.mu_v, link_dir=u, nt=nt, occ=occ))
    else:
        sh.add(Point(pole, label="p", label_dir="nw", size_mm=TEXT_MM, name="pole"))
    sh.caption([s_v.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    a = v.answers()
    mm, ms = "mm", "m/s"
    sense = word(a["omega_2_sense"], nt)
    _answers_and_solution(
        sh, [quantity("pa", mm, nt), quantity("pb", mm, nt), quantity("ab", mm, nt), quantity("ps_{2}", mm, nt),
             quantity("v_{A}", ms, nt), quantity("v_{B}", ms, nt), quantity("v_{BA}", ms, nt),
             quantity("v_{S2}", ms, nt), quantity("ω_{2}", "rad/s", nt)],
        [num(a["pa_mm"], nt), num(a["pb_mm"], nt), num(a["ab_mm"], nt), num(a["ps2_mm"], nt), num(a["v_A"], nt),
         num(a["v_B"], nt), num(a["v_BA"], nt), num(a["v_S2"], nt), num(a["omega_2"], nt)],
        [f"v_{{A}} = ω_{{1}}·OA = {num(v.omega_1, nt)}·{num(v.r, nt)} = {num(a['v_A'], nt)} "
         f"{unit('m/s', nt)};  pa = v_{{A}}/{sym('mu_v', nt)} = {num(a['pa_mm'], nt)} {unit('mm', nt)}",
         f"v_{{B}} = pb·{sym('mu_v', nt)} = {num(a['v_B'], nt)} {unit('m/s', nt)};  v_{{BA}} = ab·"
         f"{sym('mu_v', nt)} = {num(a['v_BA'], nt)} {unit('m/s', nt)};  v_{{S2}} = ps_{{2}}·"
         f"{sym('mu_v', nt)} = {num(a['v_S2'], nt)} {unit('m/s', nt)}",
         f"ω_{{2}} = v_{{BA}}/AB = {num(a['v_BA'], nt)}/{num(v.l, nt)} = {num(a['omega_2'], nt)} "
         f"{unit('rad/s', nt)}, {sense}"])
    return sh.scene((s_l, s_v))


def _em_layout(v: EnergyMassVariant, top: float, H: float):
    """The origin (J_e = 0, ΔT = 0) of the energy–mass diagram, the same on both pages."""
    r = v.result
    T = np.asarray(v.delta_T, dtype=float)
    hi = max(float(T.max()) / v.mu_T, 0.0, r.k_mm)
    lo = min(float(T.min()) / v.mu_T, r.l_mm)
    y0 = top + 9.0 + hi + max(0.0, (H - 16.0 - (hi - lo)) / 2)
    return (X0 + 32.0, top + 5.0 * round((y0 - top) / 5.0))


def _em_page(v: EnergyMassVariant, nt, key: bool) -> Scene:

    sh = _Sheet(v, nt, key)
    nt = sh.nt
    sh.header()
    p = v.press
    J_e_sym, dT = sym("J_e", nt), sym("E", nt) if nt.code == "ru" else "ΔT"
    s_J = Scale(sym("mu_J", nt), unit("kg·m²", nt), v.mu_J)
    s_T = Scale(sym("mu_T", nt), unit("J", nt), v.mu_T)
    sh.statement(dict(r=value_unit(p.get("r", 0), "m", nt), l=value_unit(p.get("l", 0), "m", nt),
                      e=value_unit(p.get("e", 0), "m", nt), F0=value_unit(p.get("F0", 0), "N", nt),
                      force_from=num(p.get("force_from", 0), nt), force_to=num(p.get("force_to", 1), nt),
                      n=value_unit(v.n_rpm, "rev/min", nt), delta=v.delta, J_e_sym=J_e_sym, dT=dT,
                      mu_J=s_J.caption(nt), mu_T=s_T.caption(nt), J_F_sym=sym("J_F", nt)))
    sh.table([[word("position", nt)] + [str(k) for k in range(v.m + 1)],
              [quantity(J_e_sym, "kg·m²", nt)] + [num(x, nt) for x in v.J_e],
              [quantity(dT, "J", nt)] + [num(x, nt) for x in v.delta_T]],
             align="l" + "c" * (v.m + 1), name="data", size=2.8)
    r = v.result
    top, H = sh.drawing_box()
    origin = _em_layout(v, top, H)
    if origin[1] - r.l_mm > top + H - 3.0 or origin[1] - max(r.k_mm, max(v.delta_T) / v.mu_T) < top + 3.0:
        raise InputError(f"{v.id}: the energy–mass diagram at {markup.plain(s_T.caption())} does not fit its box")
    box = (X0, top, X1, top + H)
    sh.add(Grid(box, anchor=origin, name="grid"))
    x_max = s_J.to_value(X1 - origin[0] - 14.0)
    y_top, y_bot = s_T.to_value(origin[1] - top - 7.0), -s_T.to_value(top + H - origin[1] - 2.0)
    X = origin[0] + np.asarray(v.J_e) / v.mu_J
    Y = origin[1] - np.asarray(v.delta_T) / v.mu_T
    curve_pts = list(zip(X.tolist(), Y.tolist()))
    ax_J = Axis(origin, s_J, "x", min_value=0.0, max_value=x_max, ticks=nice_ticks(0.0, x_max, s_J, min_gap_mm=12.0),
                label=J_e_sym, size_mm=SMALL_MM, decimal=nt.decimal, skip_zero_label=True, name="axis-J")
    ax_T = Axis(origin, s_T, "y", min_value=y_bot, max_value=y_top, ticks=nice_ticks(y_bot, y_top, s_T, min_gap_mm=10.0),
                label=quantity(dT, "J", nt), size_mm=SMALL_MM, decimal=nt.decimal, name="axis-T")
    ax_J, ax_T = _clear_tick_labels(ax_J, curve_pts), _clear_tick_labels(ax_T, curve_pts)
    sh.add(ax_J, ax_T)
    if key:
        sh.add(*energy_mass_construction(r, origin=origin, box=box, axes=(ax_J, ax_T), nt=nt))
    sh.caption([s_J.caption(nt), s_T.caption(nt)], y=top + H + 5.0)
    sh.y = top + H + CAPTION_ROOM
    tg, om = sym("tan", nt), sym("omega_m", nt)
    _answers_and_solution(
        sh, [f"{tg} ψ_{{max}}", f"{tg} ψ_{{min}}", quantity("kl", "mm", nt),
             f"ω_{{max}}: {word('position', nt).lower()}", f"ω_{{min}}: {word('position', nt).lower()}",
             quantity(sym("J_F", nt), "kg·m²", nt)],
        [num(r.tan_psi_max, nt), num(r.tan_psi_min, nt), num(r.kl_mm, nt),
         ", ".join(str(i) for i in r.index_omega_max), ", ".join(str(i) for i in r.index_omega_min), num(r.J_F, nt)],
        [f"{om} = πn/30 = {num(v.omega_m, nt)} {unit('rad/s', nt)};  {tg} ψ_{{max}} = "
         f"{num(v.mu_J, nt)}·{num(v.omega_m, nt)}²·(1 + {v.delta}/2)²/(2·{num(v.mu_T, nt)}) = "
         f"{num(r.tan_psi_max, nt)};  {tg} ψ_{{min}} = {num(r.tan_psi_min, nt)}",
         f"{sym('J_F', nt)} = {sym('mu_T', nt)}·kl/({om}²[δ]) = {num(v.mu_T, nt)}·{num(r.kl_mm, nt)}/"
         f"({num(v.omega_m, nt)}²·{v.delta}) = {num(r.J_F, nt)} {unit('kg·m²', nt)}"])
    return sh.scene((s_J, s_T))


_PAGES: dict[str, Callable[..., Scene]] = {"indicator": _indicator_page, "step-moment": _step_page, "velocity-plan": _plan_page,
          "wittenbauer": _em_page}


def student_page(v: Variant, *, notation="en") -> Scene:
    """The student's page of a variant: statement, data, graph paper at the stated scales, answer boxes.

    An A4 portrait Scene; its scales (``scene.scales()``) are captioned under the drawing area.

    >>> s = student_page(variant("velocity-plan", seed=7, number=1), notation="ru")
    >>> s.name, [sc.caption("ru") for sc in s.scales()]
    ('velocity-plan-student-01', ['μ_l = 0,005 м/мм', 'μ_v = 0,04 (м/с)/мм'])
    """
    return _PAGES[v.kind](v, notation, False)


def key_page(v: Variant, *, notation="en") -> Scene:
    """The answer key of a variant: the student's page with the construction drawn and the answers filled in.

    >>> v = variant("indicator", seed=7, number=1)
    >>> k = key_page(v)
    >>> k.element("grid") == student_page(v).element("grid"), k.element("vector-ab").length_mm
    (True, 43.75)
    """
    return _PAGES[v.kind](v, notation, True)


# ----------------------------------------------------------------------------- a class set and its files

@dataclass(frozen=True, eq=False)
class Worksheet:
    """The pages of a class set: ``students`` (one per variant), then ``keys`` (same order)."""

    kind: str
    seed: int
    notation: str
    variants: tuple
    students: tuple
    keys: tuple

    @property
    def scenes(self) -> tuple:
        """Every page in print order: the students' pages, then the keys."""
        return self.students + self.keys


def worksheet(kind: str, *, variants: int, seed: int, notation="en", progress=None) -> Worksheet:
    """Variants 1…N of ``kind`` with their student pages and answer keys.

    ``progress(done, total, what)`` is called after each variant (for long batches).
    """
    nt = get_notation(notation)
    vs = globals()["variants"](kind, count=variants, seed=seed)
    students, keys = [], []
    for k, v in enumerate(vs, 1):
        students.append(student_page(v, notation=nt))
        keys.append(key_page(v, notation=nt))
        if progress is not None:
            progress(k, len(vs), "pages")
    return Worksheet(kind, int(seed), nt.code, vs, tuple(students), tuple(keys))


class _Reporting(list):
    """A list that reports its iteration (the PDF writer walks the pages once)."""

    def __init__(self, items, progress):
        super().__init__(items)
        self._progress = progress

    def __iter__(self):
        for k, item in enumerate(super().__iter__(), 1):
            yield item
            if self._progress is not None:
                self._progress(k, len(self), "PDF pages")


def output_names(kind: str, notation, count: int) -> list[str]:
    """The files a worksheet of ``count`` variants writes (relative paths), in writing order.

    >>> output_names("indicator", "ru", 2)[:3]
    ['indicator-ru.pdf', 'svg/indicator-01-student.svg', 'svg/indicator-01-key.svg']
    """
    width = max(2, len(str(count)))
    out = [f"{_check_kind(kind)}-{get_notation(notation).code}.pdf"]
    for k in range(1, count + 1):
        out += [f"svg/{kind}-{k:0{width}d}-student.svg", f"svg/{kind}-{k:0{width}d}-key.svg",
                f"problems/{kind}-{k:0{width}d}.json"]
    return out + [f"{kind}-answers.toml"]


def existing_outputs(out_dir, kind: str, notation, count: int) -> list[pathlib.Path]:
    """The files of such a worksheet that already exist in ``out_dir`` (check before building)."""
    out = pathlib.Path(out_dir)
    return [out / n for n in output_names(kind, notation, count) if (out / n).exists()]


def file_names(ws: Worksheet) -> dict[str, object]:
    """The files of a worksheet, relative path -> list of scenes (the PDF), scene (an SVG) or variant (a
    problem file)."""
    names = iter(output_names(ws.kind, ws.notation, len(ws.variants)))
    out: dict[str, object] = {next(names): list(ws.scenes)}
    for v, s, k in zip(ws.variants, ws.students, ws.keys):
        out[next(names)] = s
        out[next(names)] = k
        out[next(names)] = v
    page = ws.students[0].page
    out[next(names)] = answers.template(ws.kind, page=(page.size, page.orientation), seed=ws.seed)
    return out


def dxf_names(kind: str, n: int) -> list[str]:
    """The DXF pages of a class set of ``n`` variants, relative to its folder (student, key, ...)."""
    return [f"dxf/{kind}-{i:02d}-{part}.dxf" for i in range(1, n + 1) for part in ("student", "key")]


def write_worksheet(ws: Worksheet, out_dir, *, overwrite: bool = False, progress=None,
                    dxf: bool = False) -> list[pathlib.Path]:
    """Write the class set into ``out_dir``: one PDF (students' pages, then keys), an SVG per page in
    ``svg/``, a problem file per variant in ``problems/`` (``graphmethods check`` reads them), a
    blank answers file ``KIND-answers.toml`` (:func:`graphmethods.sheets.answers.template`), and
    with ``dxf`` every page as DXF in ``dxf/`` (1 unit = 1 mm, for students who draw in CAD).

    Everything is built in a temporary folder beside ``out_dir`` and moved in at the end, so an error
    leaves nothing behind; existing files are never replaced unless ``overwrite``.

    Raises
    ------
    OutputExistsError
        If a file to be written exists and ``overwrite`` is false (nothing is written then).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "class"
    >>> [p.name for p in write_worksheet(worksheet("wittenbauer", variants=1, seed=3), out)]
    ['wittenbauer-en.pdf', 'wittenbauer-01-student.svg', 'wittenbauer-01-key.svg', 'wittenbauer-01.json', 'wittenbauer-answers.toml']
    """  # noqa: E501 - a doctest's expected output is one line
    from graphmethods.render import pdf, svg
    from graphmethods.render.files import write_set

    if str(out_dir).strip() == "":
        raise InputError("the worksheet folder name is empty; give a folder (it is created if missing)")
    out = pathlib.Path(out_dir)
    if out.exists() and not out.is_dir():
        raise InputError(f"{out} is a file; give a folder for the worksheet")
    files = file_names(ws)
    existing = [name for name in files if (out / name).exists()]
    if existing and not overwrite:
        more = f" and {len(existing) - 3} more" if len(existing) > 3 else ""
        raise OutputExistsError(f"{', '.join(str(out / e) for e in existing[:3])}{more} exist; use --force "
                                f"(overwrite=True) to replace them, or another folder")
    blobs: dict[str, bytes] = {}
    for name, obj in files.items():
        if isinstance(obj, list):
            blobs[name] = pdf.to_bytes(_Reporting(obj, progress))
        elif isinstance(obj, Scene):
            blobs[name] = svg.to_bytes(obj)
        elif isinstance(obj, str):          # the blank answers file
            blobs[name] = obj.encode("utf-8")
        else:
            assert isinstance(obj, Variant)     # the problem files
            blobs[name] = obj.to_json().encode("utf-8")
    if dxf:
        from graphmethods.render import dxf as dxf_writer

        pages = [s for pair in zip(ws.students, ws.keys) for s in pair]
        blobs.update((name, dxf_writer.to_bytes(s)) for name, s in zip(dxf_names(ws.kind, len(ws.variants)), pages))
    # the old set's variant files that the new set no longer has (a class of 30 replaced by one of 5)
    stale = [f"{sub}/{p.name}" for sub, pattern in (("svg", f"{ws.kind}-*-student.svg"), ("svg", f"{ws.kind}-*-key.svg"),
                                                    ("problems", f"{ws.kind}-*.json"), ("dxf", f"{ws.kind}-*.dxf"))
             for p in sorted((out / sub).glob(pattern))
             if re.fullmatch(rf"{ws.kind}-\d+(-student|-key)?\.(svg|json|dxf)", p.name)]
    write_set(out, blobs, overwrite=overwrite, stale=stale if overwrite else (), what="worksheet folder")
    return [out / name for name in files]


# the acceleration-plan kind has its own module (it draws linkages of several kinds); it registers itself
from graphmethods.sheets import acceleration_worksheet  # noqa: E402,F401
