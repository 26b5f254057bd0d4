"""Words of the translating link's figures: its equivalent mass m_e(φ).

>>> from graphmethods.scene.notation import get
>>> get("en").word("translating.legend", cap="6", top="12.5")
'm_e → ∞ at the dead centres (v = 0); drawn up to 6·m_{e,min} = 12.5 kg'
"""

WORDS = {
    "title":  ("Equivalent mass of the translating link m_e(φ)", "Приведённая масса поступательного звена m_e(φ)",
               "移动等效构件的等效质量 m_e(φ)"),
    "legend": ("m_e → ∞ at the dead centres (v = 0); drawn up to {cap}·m_{{e,min}} = {top} kg",
               "m_e → ∞ в мёртвых положениях (v = 0); показано до {cap}·m_{{e,min}} = {top} кг",
               "死点处 m_e → ∞ (v = 0)；画至 {cap}·m_{{e,min}} = {top} kg"),
}
