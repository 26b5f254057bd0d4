"""Words of the force analysis: the force plans, Zhukovsky's lever with every force, the forces on the
linkage, the force-analysis sheet and the text report of ``graphmethods forces``.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("forces.plans_title", k=3), get("zh").sym("forces.M_b")
('Планы сил, положение 3', 'M_b')
"""

WORDS = {
    # the force plans (sheets.forces.force_plans)
    "plans_title": ("Force plans, position {k}", "Планы сил, положение {k}", "力多边形，位置 {k}"),
    "plans_title_phi": ("Force plans, φ = {phi}°", "Планы сил, φ = {phi}°", "力多边形，φ = {phi}°"),
    "group": ("group {g}", "группа {g}", "杆组 {g}"),
    "crank": ("crank {g}", "кривошип {g}", "原动件 {g}"),
    "pair": ("pair", "пара", "运动副"),
    "Mb_plans": ("{Mb} from the force plans", "{Mb} по планам сил", "{Mb} 力多边形法"),
    "Mb_lever": ("{Mb} from Zhukovsky's lever", "{Mb} по рычагу Жуковского", "{Mb} 茹可夫斯基杠杆法"),
    "Mb_power": ("{Mb} from the power balance", "{Mb} по балансу мощностей", "{Mb} 功率平衡法"),
    "diff": ("difference", "расхождение", "相对误差"),
    "weights": ("with weights (g = 9.81 m/s²)", "с учётом сил тяжести (g = 9,81 м/с²)", "计入重力 (g = 9.81 m/s²)"),
    "plans_legend": ("known forces solid, unknown dashed",
                     "известные силы сплошные, искомые штриховые",
                     "已知力为实线，待求力为虚线"),
    # Zhukovsky's lever with every force (sheets.forces.zhukovsky_forces)
    "lever_title": ("Zhukovsky's lever with every force, position {k}",
                    "Рычаг Жуковского со всеми силами, положение {k}",
                    "茹可夫斯基杠杆 (全部力), 位置 {k}"),
    "lever_title_phi": ("Zhukovsky's lever with every force, φ = {phi}°",
                        "Рычаг Жуковского со всеми силами, φ = {phi}°",
                        "茹可夫斯基杠杆 (全部力), φ = {phi}°"),
    "turned": ("velocity plan of analogues v/ω₁ turned 90° counterclockwise, pole p",
               "план аналогов скоростей v/ω₁, повёрнутый на 90° против часовой, полюс p",
               "速度类比图 v/ω₁ 逆时针转 90°, 极点 p"),
    "couple": ("a moment M as two forces ±M/l at two points of its link, l apart",
               "момент M заменён парой сил ±M/l в двух точках звена на расстоянии l",
               "力矩 M 以其构件上相距 l 的两点的一对力 ±M/l 代替"),
    "lever_equation": ("Σ M_p = 0:  F_b = {Fb} N at a, ⊥ OA",
                       "Σ M_p = 0:  F_{{ур}} = {Fb} Н в точке a, ⊥ OA",
                       "Σ M_p = 0:  F_b = {Fb} N 作用于 a, ⊥ OA"),
    "lever_result": ("M_b = F_b·l_{{OA}} = {Mb} N·m",
                     "M_{{ур}} = F_{{ур}}·l_{{OA}} = {Mb} Н·м",
                     "M_b = F_b·l_{{OA}} = {Mb} N·m"),
    "lever_plans": ("from the force plans: {Mb} N·m (difference {d} %)",
                    "по планам сил: {Mb} Н·м (расхождение {d} %)",
                    "力多边形法：{Mb} N·m (相对误差 {d} %)"),
    "lever_legend": ("forces at the images of their points", "силы в образах своих точек", "力作用于其点的影像"),
    # the forces on the linkage (sheets.forces.force_scheme)
    "scheme_title": ("Forces on the linkage, position {k}",
                     "Силы, действующие на механизм, положение {k}",
                     "机构上的作用力，位置 {k}"),
    "scheme_title_phi": ("Forces on the linkage, φ = {phi}°",
                         "Силы, действующие на механизм, φ = {phi}°",
                         "机构上的作用力，φ = {phi}°"),
    "inertia": ("inertia forces F_i = −m·a_S at the centres of mass, moments M_i = −J_S·ε",
                "силы инерции F_и = −m·a_S в центрах масс, моменты M_и = −J_S·ε",
                "惯性力 F_I = −m·a_S 作用于质心，惯性力矩 M_I = −J_S·ε"),
    "scheme_balance": ("balancing moment M_b = {Mb} N·m",
                       "уравновешивающий момент M_{{ур}} = {Mb} Н·м",
                       "平衡力矩 M_b = {Mb} N·m"),
    "scheme_legend": ("moments: arcs in their sense", "моменты: дуги в их направлении", "力矩：按其转向的圆弧"),
    # the force-analysis sheet (sheets.force_analysis_sheet)
    "sheet_title": ("Force analysis, position {k}", "Силовой расчёт, положение {k}", "动态静力分析，位置 {k}"),
    "sheet_title_phi": ("Force analysis, φ = {phi}°", "Силовой расчёт, φ = {phi}°", "动态静力分析，φ = {phi}°"),
    "sheet_result": ("Balancing moment on the crank", "Уравновешивающий момент на кривошипе", "曲柄上的平衡力矩"),
    "method": ("method", "способ", "方法"),
    "diff_percent": ("difference, %", "расхождение, %", "相对误差，%"),
    "by_plans": ("force plans", "планы сил", "力多边形法"),
    "by_lever": ("Zhukovsky's lever", "рычаг Жуковского", "茹可夫斯基杠杆法"),
    "by_power": ("power balance", "баланс мощностей", "功率平衡法"),
    # the text report of `graphmethods forces` (cli.forces)
    "report_title": ("Force analysis", "Силовой расчёт", "动态静力分析"),
    "crank_angle": ("crank angle φ", "угол кривошипа φ", "曲柄转角 φ"),
    "omega_1": ("ω₁", "ω₁", "ω₁"),
    "epsilon_1": ("ε₁", "ε₁", "ε₁"),
    "gravity": ("weights", "силы тяжести", "重力"),
    "gravity_yes": ("included (g = 9.81 m/s², −y)", "учтены (g = 9,81 м/с², −y)", "计入 (g = 9.81 m/s², −y)"),
    "gravity_no": ("left out", "не учтены", "不计"),
    "inertia_loads": ("Inertia loads", "Силы и моменты инерции", "惯性力与惯性力矩"),
    "link": ("link", "звено", "构件"),
    "applied_loads": ("Applied loads (the working load and every other external load)",
                      "Внешние нагрузки (сила полезного сопротивления и остальные)",
                      "外载荷 (工作阻力及其他外力)"),
    "load": ("load", "нагрузка", "载荷"),
    "no_load": ("no external load acts in this position", "в этом положении внешних нагрузок нет",
                "此位置无外载荷"),
    "reactions": ("Reactions (force of link i on link j)",
                  "Реакции (сила звена i на звено j)",
                  "运动副反力 (构件 i 对构件 j 的力)"),
    "balancing": ("Balancing moment on the crank (counterclockwise +)",
                  "Уравновешивающий момент на кривошипе (против часовой +)",
                  "曲柄上的平衡力矩 (逆时针为正)"),
    "from_plans": ("from the force plans", "по планам сил", "力多边形法"),
    "from_lever": ("from Zhukovsky's lever", "по рычагу Жуковского", "茹可夫斯基杠杆法"),
    "from_power": ("from the power balance", "по балансу мощностей", "功率平衡法"),
    # the subscripts of the inertia loads and the balancing force or moment (F_и, M_ур in ru; F_I in zh)
    "sub_inertia": ("i", "и", "I"),
    "sub_balance": ("b", "ур", "b"),
}

#: the balancing force and moment on the crank as the books write them (ru: уравновешивающие)
SYMBOLS = {
    "F_b": ("F_b", "F_{ур}", "F_b"),
    "M_b": ("M_b", "M_{ур}", "M_b"),
}
