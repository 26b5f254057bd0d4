"""Words of the cam worksheet and of the check of a student's cam profile, in en / ru / zh.

>>> from graphmethods.scene.notation import get
>>> get("ru").word("camcheck.rise")
'подъём'
"""

WORDS = {
    # the worksheet's statement, by the follower's contact
    "pitch_roller":  ("pitch curve", "центрового профиля", "理论廓线"),
    "pitch_knife":   ("profile", "профиля", "廓线"),
    "rb_roller":     (" and {rb} = {r0} − {rr} of the profile", " и {rb} = {r0} − {rr} профиля",
                      "及实际廓线的 {rb} = {r0} − {rr}"),
    "curves_roller": ("pitch curve, the rollers and the profile (their envelope)",
                      "центровой профиль, ролики и профиль (их огибающую)", "理论廓线、滚子及实际廓线（包络线）"),
    "curves_knife":  ("profile through the points", "профиль через полученные точки", "过各点的廓线"),
    "offset":        (" with the offset e = {e} (on the side that lowers the rise's pressure angle)",
                      " со смещением e = {e} (в сторону, уменьшающую угол давления на подъёме)",
                      "，偏距 e = {e}（在减小推程压力角的一侧）"),
    "dwell2":        (" and dwells over {a}", " и выстаивает {a}", "，再休止 {a}"),
    "rise":          ("rise", "подъём", "推程"),
    "return":        ("return", "опускание", "回程"),
    # the check's items
    "base_radius":   ("base radius r_{b}", "радиус основной шайбы r_{b}", "基圆半径 r_{b}"),
    "pitch_base_radius": ("pitch base radius r_{0}", "радиус центровой окружности r_{0}", "理论廓线基圆半径 r_{0}"),
    "s_at":          ("s at φ = {phi}°", "S при φ = {phi}°", "φ = {phi}° 处的 s"),
    "alpha_rise":    ("largest pressure angle, rise", "наибольший угол давления, подъём", "推程最大压力角"),
    "alpha_return":  ("largest pressure angle, return", "наибольший угол давления, опускание", "回程最大压力角"),
    "profile_dev":   ("profile: largest distance from the exact one", "профиль: наибольшее отклонение от точного",
                      "廓线与精确廓线的最大偏差"),
    "pitch_dev":     ("pitch curve: largest distance from the exact one",
                      "центровой профиль: наибольшее отклонение от точного", "理论廓线与精确廓线的最大偏差"),
    "mu_l":          ("scale μ_{l}", "масштаб μ_{l}", "比例尺 μ_{l}"),
}
