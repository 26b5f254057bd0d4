"""Words of the worksheets: headings, answer boxes, statements' pieces, the shapes of a moment curve,
the mechanisms of the acceleration-plan kind; the symbols the profiles lack; Russian units.

>>> from graphmethods.scene.notation import get
>>> get("ru").sym("worksheets.tan"), get("zh").word("worksheets.unit_rev_min")
('tg', 'r/min')
"""

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
    "point_end": ("End point", "Точка", "终点"),
    "at_point": ("point", "точка", "点"),
    "step": ("arrows {step} mm apart", "шаг {step} мм", "箭头间距 {step} mm"),
    "sense": ("sense", "направление", "转向"),
    "ray_upper": ("ψ_{max} ray", "луч ψ_{max}", "ψ_{max} 射线"),
    "ray_lower": ("ψ_{min} ray", "луч ψ_{min}", "ψ_{min} 射线"),
    "shape_steps": ("steps", "ступенчатый", "阶梯形"),
    "shape_linear": ("piecewise linear", "кусочно-линейный", "折线形"),
    "unit_rev_min": ("rev/min", "об/мин", "r/min"),
    "mech_slider_crank": ("slider-crank mechanism", "Кривошипно-ползунный механизм", "曲柄滑块机构"),
    "mech_slotted_lever": ("crank and slotted lever mechanism", "Кулисный механизм", "摆动导杆机构"),
    "coriolis": (", the Coriolis component 2ω_{3}v_{A3A2} (v_{A3A2} turned 90° in the sense of ω_{3})",
                 ", кориолисово ускорение 2ω_{3}v_{A3A2} (v_{A3A2}, повёрнутое на 90° по ω_{3})",
                 "，哥氏加速度 2ω_{3}v_{A3A2}（v_{A3A2} 沿 ω_{3} 转向转 90°）"),
}

#: symbols the notation profiles lack
SYMBOLS = {
    "mu_l": ("μ_l", "μ_l", "μ_l"),
    "tan": ("tan", "tg", "tan"),
}

UNITS_RU = {"rev/min": "об/мин", "m/s": "м/с", "(m/s)": "(м/с)", "rad/s": "рад/с", "kg·m²": "кг·м²"}
