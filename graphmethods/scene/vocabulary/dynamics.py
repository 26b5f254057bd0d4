"""Symbols, words and units of the dynamics figures: J_e(φ), M_d, M_r(φ), ΔT(φ), ω(φ), ε(φ), the lever.

The notation's own symbols (``M_d``, ``mu_M``, ``T_max``, ``mu_T`` ...) are not repeated here.

>>> from graphmethods.scene.notation import get
>>> get("ru").sym("dynamics.J_e"), get("zh").word("dynamics.lever"), get("ru").unit("rad/s²")
('J_п', '茹可夫斯基杠杆', 'рад/с²')
"""

SYMBOLS = {
    "J_e":       ("J_e",        "J_п",          "J_e"),
    "M_e":       ("M_e",        "M_п",          "M_e"),
    "dT":        ("ΔT",         "ΔT",           "ΔE"),
    "omega":     ("ω",          "ω",            "ω"),
    "omega_m":   ("ω_m",        "ω_{ср}",       "ω_m"),
    "omega_max": ("ω_{max}",    "ω_{max}",      "ω_{max}"),
    "omega_min": ("ω_{min}",    "ω_{min}",      "ω_{min}"),
    "omega_1":   ("ω_1",        "ω_1",          "ω_1"),
    "eps":       ("ε",          "ε",            "ε"),
    "eps_max":   ("ε_{max}",    "ε_{max}",      "ε_{max}"),
    "chi":       ("χ",          "χ",            "χ"),
    "J_F":       ("J_F",        "J_м",          "J_F"),
    "J_0":       ("J_{e0}",     "J_{п0}",       "J_{e0}"),
    "delta":     ("[δ]",        "[δ]",          "[δ]"),
    "mu_J":      ("μ_J",        "μ_J",          "μ_J"),
    "mu_omega":  ("μ_ω",        "μ_ω",          "μ_ω"),
    "mu_eps":    ("μ_ε",        "μ_ε",          "μ_ε"),
    "mu_v":      ("μ_v",        "μ_v",          "μ_v"),
    "mu_F":      ("μ_F",        "μ_F",          "μ_F"),
    "psi_max":   ("ψ_{max}",    "ψ_{max}",      "ψ_{max}"),
    "psi_min":   ("ψ_{min}",    "ψ_{min}",      "ψ_{min}"),
    "dT_max":    ("ΔT_{max}",   "ΔT_{max}",     "ΔE_{max}"),
    "dT_min":    ("ΔT_{min}",   "ΔT_{min}",     "ΔE_{min}"),
    "F":         ("F",          "F_{пс}",       "F_r"),
    "M_F":       ("M_F",        "M_F",          "M_F"),
    "h":         ("h",          "h",            "h"),
}

WORDS = {
    "inertia_graph":   ("Reduced moment of inertia", "Приведённый момент инерции", "等效转动惯量"),
    "inertia_turned":  ("Reduced moment of inertia, turned 90°", "Приведённый момент инерции, повёрнутый на 90°",
                        "等效转动惯量（旋转90°）"),
    "moment_graph":    ("Reduced moments", "Приведённые моменты", "等效力矩"),
    "delta_T_graph":   ("Increment of kinetic energy", "Приращение кинетической энергии", "动能增量"),
    "kinetic_graph":   ("Kinetic energy (exact motion)", "Кинетическая энергия (точное решение)", "动能（精确解）"),
    "speed_graph":     ("Angular velocity of the crank (exact motion)", "Угловая скорость кривошипа (точное решение)",
                        "曲柄角速度（精确解）"),
    "accel_graph":     ("Angular acceleration of the crank (exact motion)",
                        "Угловое ускорение кривошипа (точное решение)", "曲柄角加速度（精确解）"),
    "lever":           ("Zhukovsky lever", "Рычаг Жуковского", "茹可夫斯基杠杆"),
    "position":        ("position", "положение", "位置"),
    "positions":       ("positions", "положений", "个位置"),
    "work_balance":    ("from the work balance", "из баланса работ", "由功平衡"),
    "exact":           ("exact", "точно", "精确"),
    "by_lever":        ("by the lever", "по рычагу", "杠杆法"),
    "by_power":        ("by power", "по мощности", "功率法"),
    "arm":             ("arm", "плечо", "力臂"),
    "force":           ("force", "сила", "力"),
    "lever_moment":    ("moment about p", "момент относительно p", "对p点之矩"),
    "plan_turned":     ("velocity plan turned 90° against ω_1", "план скоростей, повёрнутый на 90° против ω_1",
                        "速度图逆ω_1转90°"),
    "parts":           ("parts", "составляющие", "分量"),
}

UNITS_RU = {"rad/s²": "рад/с²", "(m/s)": "(м/с)", "m/s": "м/с", "rev/min": "об/мин", "kg·m²": "кг·м²"}
