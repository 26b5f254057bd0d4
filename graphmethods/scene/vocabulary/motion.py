"""Words of the motion figures: the machine's run ω(t), ω(φ), ε(φ), ε(t), its energy–mass curve T(J),
and the three panels of moments, energy and speed over one cycle.

>>> from graphmethods.scene.notation import get
>>> get("zh").word("motion.speed_t"), get("ru").sym("dynamics.omega_m"), get("ru").unit("rad/s²")
('角速度随时间的变化 ω(t)', 'ω_{ср}', 'рад/с²')
"""

WORDS = {
    "speed_t":          ("Speed against time ω(t)", "Скорость в функции времени ω(t)", "角速度随时间的变化 ω(t)"),
    "speed_phi":        ("Speed against angle ω(φ)", "Скорость в функции угла ω(φ)", "角速度随转角的变化 ω(φ)"),
    "acceleration_phi": ("Angular acceleration ε(φ)", "Угловое ускорение ε(φ)", "角加速度 ε(φ)"),
    "acceleration_t":   ("Angular acceleration ε(t)", "Угловое ускорение ε(t)", "角加速度 ε(t)"),
    "energy_mass":      ("Energy–mass curve of the run T(J)", "Кривая энергия–масса движения T(J)",
                         "运动过程的能量—质量曲线 T(J)"),
    "cycle_panels":     ("Moments, energy and speed over the cycle", "Моменты, энергия и скорость за цикл",
                         "等效力矩、能量与角速度在一个周期内的变化"),
}

UNITS_RU = {"rad/s²": "рад/с²"}
