"""Words of the flywheel figures: the rim and disc design sheet and the J_F–[δ] hyperbola.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("flywheel.hyperbola_data", W=100, w=10, J="0,5", wm="ω_{ср}", Je="J_п")
'ΔW_{max} = 100 Дж, ω_{ср} = 10 рад/с, J_п = 0,5 кг·м²'
"""

WORDS = {
    # the design sheet (sheets/flywheel_design.py)
    "design_title": ("Flywheel design: rim and disc", "Конструкция маховика: обод и диск",
                     "飞轮结构设计：轮缘式与盘式"),
    "design_title_rim": ("Flywheel design: rim", "Конструкция маховика: обод", "飞轮结构设计：轮缘式"),
    "design_title_disc": ("Flywheel design: disc", "Конструкция маховика: диск", "飞轮结构设计：盘式"),
    "rim": ("rim (spoked) flywheel", "маховик с ободом (спицевый)", "轮缘式飞轮"),
    "disc": ("solid disc", "сплошной диск", "盘式飞轮"),
    "rim_short": ("rim", "обод", "轮缘式"),
    "disc_short": ("disc", "диск", "盘式"),
    "mass": ("mass m", "масса m", "质量 m"),
    "scale": ("Scale 1 : {k}", "М 1 : {k}", "比例 1 : {k}"),
    "hub_note": ("hub and bore by the usual proportions:", "ступица и отверстие по обычным соотношениям:",
                 "轮毂与轴孔按常用比例："),
    "hub_rule": ("d ≈ 0.15 D, hub ⌀ 1.8 d, length 1.5 d", "d ≈ 0,15 D, ⌀ ступицы 1,8 d, длина 1,5 d",
                 "d ≈ 0.15 D，轮毂直径 1.8 d，长度 1.5 d"),
    "moment": ("flywheel moment mD²", "маховой момент mD²", "飞轮矩 mD²"),
    "speed": ("rim speed", "скорость обода", "轮缘速度"),
    "limit": ("its limit", "допускаемая", "许用速度"),
    "ok": ("within the limit", "в пределах допускаемой", "在许用范围内"),
    "over": ("OVER the limit: a larger D is not allowed; use steel or a smaller n",
             "ПРЕВЫШЕНА: сталь или меньшая частота", "超过许用值：改用钢或降低转速"),
    # the hyperbola (sheets/flywheel_hyperbola.py)
    "hyperbola_title": ("The {JF}–[δ] hyperbola, against 1/[δ]", "Гипербола {JF}–[δ] в координатах 1/[δ]",
                        "{JF}–[δ] 双曲线（横坐标 1/[δ]）"),
    "chosen": ("chosen", "принято", "选定"),
    "hyperbola_formula": ("{JF} = ΔW_{{max}}/({wm}²[δ]) − {Je}",) * 3,
    "hyperbola_data": ("ΔW_{{max}} = {W} J, {wm} = {w} rad/s, {Je} = {J} kg·m²",
                       "ΔW_{{max}} = {W} Дж, {wm} = {w} рад/с, {Je} = {J} кг·м²",
                       "ΔW_{{max}} = {W} J，{wm} = {w} rad/s，{Je} = {J} kg·m²"),
    "hyperbola_range": ("[δ] over the table's range 1/{a} … 1/{b} (recommended [δ] by machine)",
                        "[δ] в пределах таблицы 1/{a} … 1/{b} (рекомендуемые [δ] для машин)",
                        "[δ] 取表中范围 1/{a} … 1/{b}（各类机器的许用 [δ]）"),
}

UNITS_RU = {"kg/m³": "кг/м³"}
