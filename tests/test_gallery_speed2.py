"""Issue 30, second round: the gallery's cheaper paths are the paths they replaced, field by field and bit by
bit. (Times are measured in ``graphmethods bench``, never asserted here.)"""

import dataclasses
import inspect

import pytest

from graphmethods.scene import primitives as P

PRIMITIVES = (P.Style, P.Path, P.Polygon, P.Circle, P.Label, P.Group)


@pytest.mark.parametrize("cls", PRIMITIVES, ids=lambda c: c.__name__)
def test_a_primitives_written_init_takes_its_fields_in_order_with_their_defaults(cls):
    params = list(inspect.signature(cls.__init__).parameters.values())[1:]
    fields = dataclasses.fields(cls)
    assert [p.name for p in params] == [f.name for f in fields]
    assert [p.default for p in params] == [inspect.Parameter.empty if f.default is dataclasses.MISSING
                                          else f.default for f in fields]


def test_a_primitive_is_still_frozen_compared_and_hashed_by_its_fields():
    a = P.Label(1.0, 2.0, (("M", 0), ("d", -1)), 3.5, "middle")
    b = dataclasses.replace(a, anchor="middle")
    assert a == b and hash(a) == hash(b) and a is not b
    assert dataclasses.replace(a, x=3.0) != a
    with pytest.raises(dataclasses.FrozenInstanceError):
        a.x = 5.0  # type: ignore[misc]
    assert repr(P.Group("g", ())) == "Group(name='g', children=())"
    assert P.Path(((0.0, 0.0), (1.0, 0.0))).style is P.THIN and P.Polygon(()).style is P.SOLID_FILL
