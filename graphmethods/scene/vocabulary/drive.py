"""Words of the drive-scheme figure: a drive of several masses and its reduced scheme.

>>> from graphmethods.scene.notation import get
>>> get("zh").word("drive.shaft")
'轴'
"""

WORDS = {
    "title": ("Drive of several masses and its reduced scheme", "Многомассовый привод и его приведённая схема",
              "多质量传动系统及其等效简图"),
    "given": ("the drive (u = ω_i/ω)", "привод (u = ω_i/ω)", "传动系统 (u = ω_i/ω)"),
    "reduced": ("reduced to the shaft u = 1", "приведённая схема (к валу u = 1)", "等效到 u = 1 的轴"),
    "mass": ("mass", "масса", "质量"),
    "shaft": ("shaft", "вал", "轴"),
    "freq": ("natural frequencies", "собственные частоты", "固有频率"),
    "rigid": ("rigid drive", "жёсткий привод", "刚性传动"),
}

UNITS_RU = {"N·m/rad": "Н·м/рад"}
