"""Words and symbols of the cam sheet: motion diagrams, the combined diagram, the profile by inversion.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("cam.sheet")
'Синтез кулачкового механизма'
>>> get("zh").sym("cam.alpha"), get("ru").sym("cam.alpha")
('α', 'ϑ')
"""

SYMBOLS = {
    "psi":    ("ψ", "ψ", "ψ"),
    "ds":     ("ds/dφ", "dS/dφ", "ds/dφ"),
    "d2s":    ("d²s/dφ²", "d²S/dφ²", "d²s/dφ²"),
    "dpsi":   ("dψ/dφ", "dψ/dφ", "dψ/dφ"),
    "d2psi":  ("d²ψ/dφ²", "d²ψ/dφ²", "d²ψ/dφ²"),
    "alpha":  ("α", "ϑ", "α"),
    "r_b":    ("r_b", "r_b", "r_b"),
    "r_0":    ("r_0", "r_0", "r_0"),
    "r_r":    ("r_r", "r_р", "r_r"),
    "e":      ("e", "e", "e"),
    "rho":    ("ρ", "ρ", "ρ"),
}

WORDS = {
    "sheet":        ("Cam mechanism design", "Синтез кулачкового механизма", "凸轮机构设计"),
    "d2s_title":    ("Acceleration analogue and its integration by chords", "Аналог ускорения и его интегрирование "
                     "методом хорд", "类加速度线图及其弦线法图解积分"),
    "d2s_title_impulses": ("Acceleration analogue: impulses ∞ at the ends of a uniform phase (hard impacts)",
                           "Аналог ускорения: импульсы ∞ на концах равномерной фазы (жёсткие удары)",
                           "类加速度线图：等速段两端的 ∞ 脉冲（刚性冲击）"),
    "ds_title_exact": ("Velocity analogue", "Аналог скорости", "类速度线图"),
    "ds_title":     ("Velocity analogue (integral of the above)", "Аналог скорости (интеграл верхнего графика)",
                     "类速度线图（上图的积分）"),
    "s_title":      ("Displacement of the follower (integral of the above)", "Перемещение толкателя (интеграл "
                     "верхнего графика)", "从动件位移线图（上图的积分）"),
    "psi_title":    ("Swing of the follower (integral of the above)", "Угол поворота коромысла (интеграл "
                     "верхнего графика)", "摆杆角位移线图（上图的积分）"),
    "combined":     ("Combined ds/dφ–s diagram: tangents at [α], admissible zone of the cam centre",
                     "Совмещённая диаграмма dS/dφ–S: касательные под [ϑ], область центров кулачка",
                     "ds/dφ–s 线图：[α] 切线与凸轮中心许用区"),
    "combined_rocker": ("Combined diagram of the rocker: l·dψ/dφ along the arm, tangents at [α], zone of the cam "
                        "centre", "Совмещённая диаграмма коромысла: l·dψ/dφ по коромыслу, касательные под [ϑ], "
                        "область центров кулачка", "摆动从动件的 l·dψ/dφ 图解：[α] 切线与凸轮中心许用区"),
    "fig_combined": ("Combined ds/dφ–s diagram", "Совмещённая диаграмма dS/dφ–S", "ds/dφ–s 线图"),
    "fig_rocker":   ("Combined diagram of the rocker", "Совмещённая диаграмма коромысла", "摆动从动件的许用区图解"),
    "fig_motion":   ("Motion diagrams of the follower", "Кинематические диаграммы толкателя", "从动件运动线图"),
    "alpha_graph":  ("Pressure angle over the cycle", "Угол давления за цикл", "压力角线图"),
    "rho_graph":    ("Radius of curvature of the profile", "Радиус кривизны профиля", "廓线曲率半径线图"),
    "positions":    ("Division points of the construction", "Точки деления (положения толкателя)",
                     "分点（从动件位置）"),
    "profile":      ("Cam profile by inversion of motion", "Профиль кулачка методом обращения движения",
                     "反转法绘制凸轮廓线"),
    "results":      ("Results", "Результаты", "结果"),
    "pole":         ("P_{k}: H_{k} = {value} mm", "P_{k}: H_{k} = {value} мм", "P_{k}：H_{k} = {value} mm"),
    "alpha_max":    ("{sym}_{{max}} = {value}°", "{sym}_{{max}} = {value}°", "{sym}_{{max}} = {value}°"),
    "row_follower": ("follower", "толкатель", "从动件"),
    "translating":  ("translating", "поступательный", "直动"),
    "oscillating":  ("oscillating", "коромысловый", "摆动"),
    "knife":        ("knife-edge", "острый", "尖顶"),
    "roller":       ("roller", "роликовый", "滚子"),
    "flat":         ("flat-faced", "плоский", "平底"),
    "row_phases":   ("phases: rise, dwell, return", "фазы: подъём, выстой, опускание", "推程、休止、回程运动角"),
    "row_laws":     ("laws of rise / return", "законы подъёма / опускания", "推程 / 回程运动规律"),
    "uniform":      ("uniform", "равномерный", "等速"),
    "parabolic":    ("parabolic", "равноускоренный", "等加速等减速"),
    "harmonic":     ("harmonic", "косинусоидальный", "余弦加速度"),
    "cycloidal":    ("cycloidal", "синусоидальный", "正弦加速度"),
    "polynomial_345": ("3-4-5 polynomial", "полином 3-4-5", "3-4-5多项式"),
    "row_stroke":   ("stroke", "ход толкателя", "行程"),
    "row_limits":   ("permissible pressure angle, rise / return", "допустимый угол давления, подъём / опускание",
                     "许用压力角（推程 / 回程）"),
    "row_base":     ("base radius of the profile", "радиус основной шайбы профиля", "实际廓线基圆半径"),
    "row_pitch":    ("base radius of the pitch curve", "радиус центрового профиля", "理论廓线基圆半径"),
    "row_designed": ("designed: α ≤ [α]", "найден: ϑ ≤ [ϑ]", "设计值：α ≤ [α]"),
    "no_uniform":   ("the cam sheet integrates the acceleration analogue, which is infinite where a uniform phase "
                     "starts and ends (hard impacts): choose another law for the sheet, or use the numbers alone",
                     "лист интегрирует аналог ускорения, который бесконечен в начале и конце равномерной фазы "
                     "(жёсткие удары): выберите другой закон для листа или используйте только числа",
                     "图纸对类加速度进行积分，而等速运动段的起止处类加速度为无穷大（刚性冲击）：请改用其他运动规律，"
                     "或只输出数值"),
    "row_designed_flat": ("designed: ρ ≥ ρ_{min}", "найден: ρ ≥ ρ_{min}", "设计值：ρ ≥ ρ_{min}"),
    "row_given":    ("given", "задан", "给定"),
    "row_offset":   ("offset", "эксцентриситет", "偏距"),
    "row_roller":   ("roller radius", "радиус ролика", "滚子半径"),
    "row_arm":      ("arm, pivot distance", "длина коромысла, межосевое расстояние", "摆杆长度、中心距"),
    "row_alpha":    ("largest pressure angle, rise / return", "наибольший угол давления, подъём / опускание",
                     "最大压力角（推程 / 回程）"),
    "row_rho":      ("smallest radius of curvature of the pitch curve", "наименьший радиус кривизны центрового "
                     "профиля", "理论廓线最小曲率半径"),
    "row_rho_flat": ("smallest radius of curvature of the profile", "наименьший радиус кривизны профиля",
                     "廓线最小曲率半径"),
    "row_undercut": ("undercut", "подрезание", "运动失真（变尖）"),
    "yes":          ("yes", "да", "是"),
    "no":           ("no", "нет", "否"),
    "row_width":    ("face width at least", "ширина тарелки не менее", "平底宽度至少"),
    "row_impacts":  ("impacts", "удары", "冲击"),
    "hard":         ("hard", "жёсткий", "刚性"),
    "soft":         ("soft", "мягкий", "柔性"),
    "none":         ("none", "нет", "无"),
    "row_error":    ("chord integration error in s at the {n} nodes", "погрешность интегрирования хордами в S "
                     "в {n} точках", "弦线法积分的位移误差（{n}个分点）"),
    "inversion":    ("Cam profile by inversion of motion", "Построение профиля кулачка методом обращения движения",
                     "反转法绘制凸轮廓线"),
    "step_base":    ("Centre O and the base circle, to {mu}: the cam stands still, the follower turns by −φ",
                     "Центр O и основная окружность в масштабе {mu}: кулачок неподвижен, толкатель поворачиваем на −φ",
                     "画凸轮中心 O 和基圆（{mu}）：凸轮不动，从动件反转 −φ"),
    "step_lines":   ("Turn the follower back by −φ_k at each division point k (its axis, or the arm from its pivot)",
                     "Поворачиваем толкатель на −φ_k в каждой точке деления k (его ось или коромысло от опоры)",
                     "在各分点 k 将从动件反转 −φ_k（导路或摆杆）"),
    "step_points":  ("Lay off s_k on each turned position: the roller centres (pitch points) B_k",
                     "Откладываем S_k на каждом повёрнутом положении: центры ролика B_k",
                     "在各反转位置上量取 s_k，得滚子中心 B_k"),
    "step_pitch":   ("Join B_0 … B_n by a smooth curve: the pitch curve", "Соединяем B_0 … B_n плавной кривой: "
                     "центровой профиль", "光滑连接 B_0 … B_n，得理论廓线"),
    "step_rollers": ("Draw the roller (or the flat face) in each position", "Строим ролик (или тарелку) в каждом "
                     "положении", "在各位置画出滚子（或平底）"),
    "step_profile": ("The profile is the envelope of the rollers (the faces): r_b = {rb}",
                     "Профиль — огибающая роликов (тарелок): r_b = {rb}", "廓线为滚子（平底）的包络线：r_b = {rb}"),
    "step_alpha":   ("The follower in position 0 and the largest pressure angle {alpha}",
                     "Толкатель в положении 0 и наибольший угол давления {alpha}",
                     "位置 0 的从动件及最大压力角 {alpha}"),
    "row_omega":    ("cam speed", "угловая скорость кулачка", "凸轮角速度"),
}

