"""Words, symbols and Russian units of the graphical-calculus sheets: the slider's kinematic diagrams
s, v, a by graphical differentiation and the work diagrams A_d, A_r, ΔE by graphical integration.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("calculus.work_title"), get("ru").sym("calculus.A_d"), get("ru").unit("m/s²")
('Диаграммы работ (графическое интегрирование)', 'A_д', 'м/с²')
"""

WORDS = {
    "kinematic_title": ("Kinematic diagrams of the slider", "Кинематические диаграммы ползуна", "滑块运动线图"),
    "work_title": ("Work diagrams by graphical integration", "Диаграммы работ (графическое интегрирование)",
                   "功线图（图解积分法）"),
    "construction": ("Construction", "Построение", "作图"),
    "against": ("compared with", "сравнение с", "比较对象"),
    "largest": ("max. difference", "расхождение", "最大误差"),
    "on_sheet": ("on the sheet", "на чертеже", "图上"),
    "analytic": ("analytic", "аналитически", "解析解"),
    "plans": ("velocity plans", "планы скоростей", "速度图"),
    "acc_plans": ("acceleration plans", "планы ускорений", "加速度图"),
    "accuracy_work": ("Accuracy against the exact integrals", "Точность относительно точных интегралов",
                      "相对精确积分的作图误差"),
    "at_mid": ("at mid-intervals", "в серединах", "区间中点"),
    "at_positions": ("at the positions", "в положениях", "各位置"),
    "at_ends": ("at interval ends", "на концах участков", "区间端点"),
    "inside": ("inside the chords", "внутри хорд", "弦内"),
    "picked": ("picked to fit", "выбрано по месту", "自动选取"),
    "given": ("given", "задано", "给定"),
    "drawn": ("{M} drawn through the positions", "{M} построен по точкам положений", "{M}按各位置绘制"),
    "comparison": ("Largest differences from the velocity and acceleration plans and the analytic values",
                   "Наибольшие расхождения с планами скоростей, ускорений и аналитическим расчётом",
                   "与速度图、加速度图及解析解的最大误差"),
}

SYMBOLS = {
    "s": ("s", "S", "s"),
    "v": ("v", "V", "v"),
    "a": ("a", "a", "a"),
    "mu_s": ("μ_s", "μ_S", "μ_s"),
    "mu_v": ("μ_v", "μ_V", "μ_v"),
    "mu_a": ("μ_a", "μ_a", "μ_a"),
    "mu_t": ("μ_t", "μ_t", "μ_t"),
    "A_d": ("A_d", "A_д", "W_d"),
    "A_r": ("A_r", "A_с", "W_r"),
    "mu_A": ("μ_A", "μ_A", "μ_W"),
    "P": ("P", "P", "P"),
}

UNITS_RU = {"m/s": "м/с", "m/s²": "м/с²", "m/rad": "м/рад", "m/rad²": "м/рад²", "s": "с", "m": "м", "J": "Дж",
            "N·m": "Н·м", "rad": "рад", "mm": "мм", "kG·m": "кГ·м"}
