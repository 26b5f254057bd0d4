"""Words of the structure diagram: a mechanism split into its driver and its Assur groups.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("structure.group", cls="III", order=3)
'группа III класса, 3-го порядка'
"""

WORDS = {
    "title": ("Structure of the mechanism", "Структура механизма", "机构的结构分析"),
    "driver": ("driving link and frame (class I)", "ведущее звено и стойка (I класс)", "原动件与机架 (I级机构)"),
    "group": ("group of class {cls}, order {order}", "группа {cls} класса, {order}-го порядка",
              "{cls}级杆组, {order}阶"),
    "kind": ("type {kind}", "вид {kind}", "类型 {kind}"),
    "formula": ("structural formula: {formula}", "формула строения: {formula}", "结构式: {formula}"),
    "dof": ("W = 3n − 2p₅ − p₄ = 3·{n} − 2·{p5} − {p4} = {W}", "W = 3n − 2p₅ − p₄ = 3·{n} − 2·{p5} − {p4} = {W}",
            "F = 3n − 2P_{{L}} − P_{{H}} = 3·{n} − 2·{p5} − {p4} = {W}"),
    "class": ("mechanism of class {cls}", "механизм {cls} класса", "{cls}级机构"),
    "outer": ("outer pairs marked ◎, the frame hatched", "внешние пары отмечены ◎, стойка заштрихована",
              "外副以 ◎ 标出, 机架画剖面线"),
}
