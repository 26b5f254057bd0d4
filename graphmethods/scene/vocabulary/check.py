"""Words of a check's overlay: its heading, how to print it, the wrong items, the usual mistakes named
(typed answers and acceleration plans), in en / ru / zh.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("check.carried")
'следствие предыдущей ошибки'
"""

WORDS = {
    "overlay":        ("Overlay", "Накладка для проверки", "叠加校核图"),
    "heading":        ("{overlay}: {rest}", "{overlay}: {rest}", "{overlay}：{rest}"),
    "howto":          ("print at 100 % (no scaling) on transparent film; check: the bar below is {bar}",
                       "печатать на прозрачной плёнке в масштабе 100 % (без подгонки по размеру); "
                       "проверка: отрезок внизу равен {bar}",
                       "按 100 % 比例（不缩放）打印在透明胶片上；检查：下方线段长 {bar}"),
    # one wrong item; {unit} is empty for a position (the double space it leaves is closed up)
    "item":           ("{label}: {student} (expected {expected}) {unit} — {why}",
                       "{label}: {student} (должно быть {expected}) {unit} — {why}",
                       "{label}：{student}（应为 {expected}）{unit}——{why}"),
    "or":             ("{a} or {b}", "{a} или {b}", "{a} 或 {b}"),
    "carried":        ("carried over", "следствие предыдущей ошибки", "由前面的错误导致"),
    "wrong":          ("wrong", "неверно", "错误"),
    # the items (from Item.key): {i} an interval such as c–d, {omega} a speed such as ω_{max}
    "area":           ("area {i}", "площадь {i}", "面积 {i}"),
    "work":           ("work {i}", "избыточная работа {i}", "盈亏功 {i}"),
    "arrow":          ("arrow {i}", "вектор {i}", "矢量 {i}"),
    "n_areas":        ("number of intervals", "число участков", "区间数"),
    "n_works":        ("number of intervals (works)", "число участков (работы)", "区间数（盈亏功）"),
    "n_arrows":       ("number of arrows", "число векторов", "矢量数"),
    "point_of":       ("point of {omega}", "точка {omega}", "{omega} 所在点"),
    "angle_of":       ("angle of {omega}", "угол φ при {omega}", "{omega} 所在转角 φ"),
    "position_of":    ("position of {omega}", "положение {omega}", "{omega} 所在位置"),
    "sense_of":       ("sense of {omega}", "направление {omega}", "{omega} 的转向"),
    "direction_of":   ("direction of {v}", "направление вектора {v}", "{v} 的方向"),
    # the usual mistakes (the keys of MISTAKES), short
    "sign_flipped":   ("sign flipped in the staircase", "перепутан знак избыточной работы",
                       "盈亏功正负号颠倒"),
    "degrees_as_radians": ("degrees used as radians", "градусы приняты за радианы", "把度当作弧度"),
    "n_as_omega":     ("n (rev/min) used as ω (rad/s)", "n (об/мин) принято за ω (рад/с)",
                       "把 n (r/min) 当作 ω (rad/s)"),
    "scale_forgotten": ("scale factor forgotten", "не учтён масштабный коэффициент", "漏乘比例尺"),
    "scale_twice":    ("scale factor applied twice", "масштабный коэффициент учтён дважды", "比例尺乘了两次"),
    "J_e_not_subtracted": ("{J_e} not subtracted", "не вычтен {J_e}", "未减去 {J_e}"),
    # ω_max = ω_m(1 + δ) for ω_m(1 + δ/2), and squared in tan ψ (and in J_F through ω_max² − ω_min²)
    "delta_not_halved": ("(1 ± δ) instead of (1 ± δ/2)", "(1 ± δ) вместо (1 ± δ/2)", "用 (1 ± δ) 代替了 (1 ± δ/2)"),
    "normal_reversed": ("normal component drawn away from the centre", "нормальное ускорение направлено от центра",
                        "法向分量方向画反"),
    "coriolis_reversed": ("Coriolis sense reversed", "кориолисово ускорение в обратную сторону", "哥氏加速度方向画反"),
    "coriolis_forgotten": ("Coriolis term forgotten", "забыто кориолисово ускорение", "漏了哥氏加速度"),
    "coriolis_factor_2": ("factor 2 missing in 2ω·v", "пропущен множитель 2 в 2ω·v", "2ω·v 中漏了系数 2"),
    "normal_wrong_length": ("ω²·l with the wrong length", "ω²·l с неверной длиной", "ω²·l 用错了杆长"),
    "crank_tangential_forgotten": ("crank's tangential component forgotten", "забыто касательное ускорение кривошипа",
                                   "漏了曲柄的切向加速度"),
}
