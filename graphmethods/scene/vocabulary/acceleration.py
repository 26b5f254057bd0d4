"""Words and Russian units of the acceleration figures: one plan drawn large, the plans of all positions, the table.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("acceleration.plan", k=2), get("ru").unit("(m/s²)")
('План ускорений, положение 2', '(м/с²)')
"""

WORDS = {
    "plan":     ("Acceleration plan, position {k}", "План ускорений, положение {k}", "加速度多边形（位置{k}）"),
    "plan_at":  ("Acceleration plan, φ = {phi}°", "План ускорений, φ = {phi}°", "加速度多边形（φ = {phi}°）"),
    "plans":    ("Acceleration plans", "Планы ускорений", "加速度多边形"),
    "table":    ("Accelerations per position", "Ускорения точек и звеньев по положениям", "各位置的加速度"),
    "value":    ("Acceleration", "Ускорение", "加速度"),
    "assur_point": ("Assur's point", "особая точка Ассура", "阿苏尔点"),
    "legend":   ("solid: known component, dashed: direction known, found by construction",
                 "сплошные — известные составляющие, штриховые — найденные построением",
                 "实线：已知分量；虚线：作图求得"),
    "speed":    ("ω_1 = {w} rad/s, ε_1 = {e} rad/s²", "ω_1 = {w} рад/с, ε_1 = {e} рад/с²",
                 "ω_1 = {w} rad/s，ε_1 = {e} rad/s²"),
    "signed":   ("slider accelerations signed along +x of the guide; others are magnitudes",
                 "ускорения ползунов со знаком по оси x направляющей; остальные — модули",
                 "滑块加速度沿导路 +x 方向为正，其余为大小"),
}

UNITS_RU = {"m/s²": "м/с²", "(m/s²)": "(м/с²)", "rad/s²": "рад/с²"}
