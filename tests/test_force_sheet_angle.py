"""The A1 force sheet at a crank angle between positions (issue 26, lane forceangle): it draws the plan of
accelerations at that angle, as the sheet of a position does, and the plan's a_S is the inertia load's."""

from graphmethods.problems import builtin
from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet


def _texts(element) -> list[str]:
    inner = getattr(element, "elements", None)
    if inner is not None:
        return [t for e in inner for t in _texts(e)]
    text = getattr(element, "text", None)
    return [text] if isinstance(text, str) else []


def test_the_sheet_at_an_angle_draws_the_plan_of_accelerations_there():
    scene = force_analysis_sheet(builtin.case("engine"), phi_deg=100.0, notation="en")
    names = [e.name for e in scene.elements]
    assert "acceleration" in names
    plan = scene.elements[names.index("acceleration")]
    texts = _texts(plan)
    assert any(t.startswith("Acceleration plan") and "100" in t for t in texts)
    assert not any("position 0" in t and t.startswith("Acceleration plan") for t in texts)
