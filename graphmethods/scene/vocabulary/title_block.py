"""Words of the main inscription (title block) of a sheet: ГОСТ 2.104 form 1 (ru), GB/T 10609.1 (zh)
and the simple block (en) (:mod:`graphmethods.scene.title_blocks`).

>>> from graphmethods.scene.notation import get
>>> get("ru").word("title_block.drawn"), get("zh").word("title_block.drawn")
('Разраб.', '设计')
"""

WORDS = {
    "change":    ("Rev.", "Изм.", "标记"),
    "count":     ("Qty", "Кол.уч.", "处数"),
    "zone":      ("Zone", "Зона", "分区"),
    "sheet":     ("Sheet", "Лист", "第张"),
    "doc":       ("Doc. No.", "№ докум.", "更改文件号"),
    "sign":      ("Sign.", "Подп.", "签名"),
    "date":      ("Date", "Дата", "年月日"),
    "drawn":     ("Drawn", "Разраб.", "设计"),
    "checked":   ("Checked", "Пров.", "审核"),
    "tech":      ("Tech. check", "Т.контр.", "工艺"),
    "norm":      ("Std. check", "Н.контр.", "标准化"),
    "approved":  ("Approved", "Утв.", "批准"),
    "lit":       ("Stage", "Лит.", "阶段标记"),
    "lit_value": ("S", "У", "S"),
    "mass":      ("Mass", "Масса", "重量"),
    "scale":     ("Scale", "Масштаб", "比例"),
    "sheets":    ("Sheets", "Листов", "共张"),
    "of":        ("Sheet {k} of {n}", "Лист {k}, листов {n}", "共 {n} 张 第 {k} 张"),
    "student":   ("Student", "Студент", "学生"),
}
