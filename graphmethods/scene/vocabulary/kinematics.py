"""Words of the kinematic figures: the scheme in m positions, velocity plans and their table, the A1 sheet.

>>> from graphmethods.scene.notation import get
>>> get("zh").word("kinematics.plan", k=4)
'速度多边形（位置4）'
"""

WORDS = {
    "analysis":     ("Kinematic analysis", "Кинематический анализ", "运动分析"),
    "scheme":       ("Kinematic scheme in {m} positions", "План механизма в {m} положениях",
                     "机构运动简图（{m}个位置）"),
    "plans":        ("Velocity plans", "Планы скоростей", "速度多边形"),
    "plan":         ("Velocity plan, position {k}", "План скоростей, положение {k}", "速度多边形（位置{k}）"),
    "plan_at":  ("Velocity plan, φ = {phi}°", "План скоростей, φ = {phi}°", "速度多边形（φ = {phi}°）"),
    "table":        ("Velocities per position", "Скорости точек и звеньев по положениям", "各位置的速度"),
    "position":     ("Position", "Положение", "位置"),
    "guide":        ("guide", "направляющей", "导路"),
    "ill":          ("ill-conditioned", "плохо обусловлено", "病态"),
    "ill_note":     ("ill-conditioned (construction lines nearly parallel): values from the analytic derivative",
                     "плохо обусловлено (линии построения почти параллельны): значения по аналитической производной",
                     "病态位置（作图线近于平行）：取解析导数值"),
    "ill_frame":    ("heavy dashed frame: ill-conditioned", "жирная штриховая рамка — плохо обусловлено",
                     "粗虚线框：病态位置"),
    "off_scale":    ("off the scale", "вне масштаба", "超出比例"),
    "legend":       ("solid: known vector, dashed: found by construction",
                     "сплошные — известные векторы, штриховые — найденные построением",
                     "实线：已知矢量；虚线：作图求得"),
    "speed":        ("ω_1 = {w} rad/s", "ω_1 = {w} рад/с", "ω_1 = {w} rad/s"),
    "speed_n":      ("ω_1 = {w} rad/s (n = {n} rev/min)", "ω_1 = {w} рад/с (n = {n} об/мин)",
                     "ω_1 = {w} rad/s（n = {n} r/min）"),
    "extremes":     ("extreme positions {a} and {b}", "крайние положения {a} и {b}", "极限位置 {a} 与 {b}"),
    "theta":        ("θ = {t}", "θ = {t}", "极位夹角 θ = {t}"),
    "K":            ("time ratio K = {K}", "коэффициент K = {K}", "行程速比系数 K = {K}"),
    "swing":        ("swing ψ_{{max}} = {p}", "размах ψ_{{max}} = {p}", "摆角 ψ_{{max}} = {p}"),
    "stroke":       ("H = {H} {u}", "H = {H} {u}", "H = {H} {u}"),
    "vector":       ("Vector", "Вектор", "矢量"),
    "length":       ("Length, mm", "Длина, мм", "长度/mm"),
    "value":        ("Velocity", "Скорость", "速度"),
    "ccw":          ("counterclockwise", "против часовой стрелки", "逆时针"),
    "cw":           ("clockwise", "по часовой стрелке", "顺时针"),
    "at_rest":      ("at rest", "покоится", "静止"),
    "signed":       ("slider velocities signed along +x of the guide; others are magnitudes",
                     "скорости ползунов со знаком по оси x направляющей; остальные — модули",
                     "滑块速度沿导路 +x 方向为正，其余为大小"),
    "phi_from":     ("φ from position 0", "φ от положения 0", "φ 自位置0起"),
}

UNITS_RU = {"m/s": "м/с", "(m/s)": "(м/с)", "rad/s": "рад/с", "m": "м", "mm": "мм", "rev/min": "об/мин"}
