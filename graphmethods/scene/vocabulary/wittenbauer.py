"""Words of the energy–mass (Wittenbauer) diagram and of the A1 dynamic-analysis sheet.

(The graph titles it shares with the dynamics figures, ``dynamics.moment_graph`` and
``dynamics.delta_T_graph``, are not repeated here.)

>>> from graphmethods.scene.notation import get
>>> get("ru").word("wittenbauer.error", m=12)
'оценка погрешности (m = 12)'
"""

WORDS = {
    "wittenbauer":      ("Energy–mass diagram (Wittenbauer)", "Диаграмма энергомасс (Виттенбауэра)",
                         "能量–质量图（维滕鲍尔图）"),
    "dynamic_analysis": ("Dynamic analysis: flywheel by the Wittenbauer method",
                         "Динамический анализ: маховик по методу Виттенбауэра",
                         "动力学分析：维滕鲍尔法求飞轮"),
    "inertia_turned":   ("Reduced moment of inertia, turned 90°", "Приведённый момент инерции (повёрнут на 90°)",
                         "等效转动惯量（旋转90°）"),
    "result":           ("Result", "Результат", "结果"),
    "ordinates":        ("Ordinates at the positions", "Ординаты в положениях механизма", "各位置的纵坐标"),
    "delta":            ("coefficient of fluctuation", "коэффициент неравномерности", "速度不均匀系数"),
    "omega_m":          ("mean angular velocity", "средняя угловая скорость", "平均角速度"),
    "M_d":              ("driving moment", "движущий момент", "等效驱动力矩"),
    "M_r":              ("resisting moment", "момент сопротивления", "等效阻抗力矩"),
    "scale_J":          ("scale of J_e", "масштаб J_п", "J_e比例尺"),
    "scale_T":          ("scale of ΔT", "масштаб ΔT", "ΔE比例尺"),
    "scale_M":          ("scale of M", "масштаб M", "M比例尺"),
    "scale_phi":        ("scale of φ", "масштаб φ", "φ比例尺"),
    "tan_max":          ("upper ray", "верхний луч", "上射线"),
    "tan_min":          ("lower ray", "нижний луч", "下射线"),
    "origin":           ("ordinate axis at", "ось ординат при", "纵轴位于"),
    "k":                ("intercept k", "отрезок k", "截距k"),
    "l":                ("intercept l", "отрезок l", "截距l"),
    "kl":               ("segment kl", "отрезок kl", "线段kl"),
    "J_F":              ("flywheel", "маховик", "飞轮"),
    "at_omega_max":     ("ω_{max} at position", "ω_{max} в положении", "ω_{max}位置"),
    "at_omega_min":     ("ω_{min} at position", "ω_{min} в положении", "ω_{min}位置"),
    "error":            ("error estimate (m = {m})", "оценка погрешности (m = {m})", "误差估计（m = {m}）"),
    "O1_off":           ("beyond the sheet", "за пределами листа", "在图纸之外"),
    "O1_on":            ("O_1", "O_1", "O_1"),
    "none":             ("not estimated", "не оценена", "未估计"),
    "tangents":         ("tangents", "тангенсы", "正切"),
    "tangents_exact":   ("(1 ± δ/2)²", "(1 ± δ/2)²", "(1 ± δ/2)²"),
    "tangents_textbook": ("(1 ± δ)", "(1 ± δ)", "(1 ± δ)"),
}
