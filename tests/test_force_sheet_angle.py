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


def test_a_thin_plate_of_the_scheme_is_broken_behind_a_label_like_a_thin_line():
    """A ternary link's outline in a thin position (issue 26: S₃ of the drawn six-bar crossed) is broken for
    an inscription (ГОСТ 2.303) as the thin links are; a plate the label does not touch is kept whole."""
    from graphmethods.scene import Group
    from graphmethods.scene.primitives import THIN
    from graphmethods.sheets.kinematic_scheme import _broken_lines
    from graphmethods.sheets.plates import Plate

    crossed = Plate(((0.0, 0.0), (10.0, 0.0), (5.0, 8.0)), outline_style=THIN, hatch=False, name="position-1-BCD")
    away = Plate(((50.0, 0.0), (60.0, 0.0), (55.0, 8.0)), outline_style=THIN, hatch=False, name="position-2-BCD")
    out = _broken_lines([crossed, away], [(4.0, -1.0, 6.0, 1.0)])
    assert isinstance(out[0], Group) and out[0].name == "position-1-BCD"
    (outline,) = out[0].elements                    # the closed outline opened where the label stands
    assert outline.points[0] == (6.4, 0.0) and outline.points[-1] == (3.6, 0.0) and len(outline.points) == 5
    assert out[1] is away


def test_too_many_plan_positions_are_refused_with_the_number_the_sheet_has_room_for(tmp_path, capsys):
    """issue 26: ``kinematics press --sheet --plan-positions 1,4,8,10`` was refused "do not fit on this page"
    though the help allows 1 to 4: the message says how many plans that linkage's sheet has room for."""
    from graphmethods import cli

    target = tmp_path / "k.svg"
    assert cli.main(["kinematics", "press", "--sheet", str(target), "--plan-positions", "1,4,8,10"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "room for 3 acceleration plans" in err[0] and "not 4" in err[0]
    assert not target.exists()
