"""Words of the number rule: a value within the round-off of its own computation prints as 0, with
its reason (:meth:`graphmethods.scene.notation.Notation.zero`).

>>> from graphmethods.scene.notation import get
>>> get("ru").word("numbers.zero_here", q="ω_{2}")
'ω_{2} = 0 в этом положении'
"""

WORDS = {
    "zero_here": ("{q} = 0 in this position", "{q} = 0 в этом положении", "此位置 {q} = 0"),
}
