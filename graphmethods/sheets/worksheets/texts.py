"""The worksheets' titles and statements (the given data, then the tasks, per kind, in en / ru / zh), and
a value with its unit as a notation writes it. The words, symbols and units themselves are in
``scene/vocabulary/worksheets.toml`` (``nt.word("worksheets.key")``).

>>> from graphmethods.scene.notation import get
>>> value_unit(43.69, "kg·m²", get("ru"))
'43,69 кг·м²'
"""

from __future__ import annotations

from graphmethods.scene.notation import Notation
from graphmethods.titles import titles

# the title of each kind of worksheet problem (Variant.title)
TITLES = titles({
    "indicator": ("Energy indicator diagram and flywheel", "Векторная диаграмма избыточных работ и маховик",
                  "能量指示图与飞轮转动惯量"),
    "step-moment": ("Flywheel for a given resisting moment", "Маховик по заданному моменту сопротивления",
                    "已知阻抗力矩求飞轮转动惯量"),
    "velocity-plan": ("Velocity plan of a slider-crank mechanism", "План скоростей кривошипно-ползунного механизма",
                      "曲柄滑块机构的速度多边形"),
    "wittenbauer": ("Flywheel by the energy–mass (Wittenbauer) diagram",
                    "Маховик по диаграмме энергомасс (Виттенбауэра)", "用能量–质量（维滕鲍尔）图求飞轮转动惯量"),
})

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


def value_unit(value: float, u: str, nt: Notation, *, sig: int = 4) -> str:
    """``"43.69 kg·m²"`` in the notation's style (decimal mark, units)."""
    return f"{nt.number(value, sig=sig)} {nt.unit(u)}"
