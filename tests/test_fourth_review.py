"""A teacher's fourth review (issue 26, lane review4): one problem, one number everywhere; one regression test
per defect found."""

from __future__ import annotations

import re

import pytest

from graphmethods.dynamics.flywheel import disc_flywheel, rim_flywheel
from graphmethods.errors import InputError
from graphmethods.problems import builtin
from graphmethods.scene import Scale, markup
from graphmethods.scene.primitives import Label, walk

LANGS = ("en", "ru", "zh")


def _texts(scene) -> list[str]:
    return [markup.plain(p.text) for p in walk(e for el in scene.elements for e in el.primitives())
            if isinstance(p, Label)]


# ----------------------------------------------------------------------------- 2. the flywheel's sizes

@pytest.mark.parametrize("lang", LANGS)
def test_flywheel_dimensions_read_as_the_table(lang):
    """The table gave B = 110.5 mm while the dimension read 111 (179.2 against 179). The table's mass and J_F are
    of the computed sizes, so the drawing writes them as the table does (ГОСТ 2.307 allows a decimal size):
    every width in the table stands on the drawing as written there."""
    from graphmethods.scene import notation
    from graphmethods.sheets.flywheel_design import flywheel_design, size_text

    rim, disc = rim_flywheel(43.69, n_rpm=600.0, D=0.75), disc_flywheel(43.69, D=0.75, n_rpm=600.0)
    texts = _texts(flywheel_design(rim, disc, notation=lang))
    nt = notation(lang)
    for p in (rim, disc):
        B = size_text(p.B, nt)
        assert B in texts, (B, texts)
        assert f"{p.B * 1000:.0f}" == B or f"{p.B * 1000:.0f}" not in texts
    assert size_text(0.1105, notation("ru")) == "110,5"


# ----------------------------------------------------------------------------- 3. v_A in the working and the table

@pytest.mark.parametrize("lang", LANGS)
def test_shaper_velocity_plan_table_values_as_the_working(lang):
    """The shaper's velocity plan wrote v_A = ω₁·l_OA = … = 0.6912 m/s and then v_A = 0.691 in its table: the
    table now writes each value as the equations do (four significant digits), so v_A is one number."""
    from graphmethods.sheets.velocity_plans import velocity_plan

    texts = _texts(velocity_plan(builtin.case("shaper"), notation=lang))
    working = next(t for t in texts if t.startswith("vA = ω1·l"))
    value = re.search(r"= ([0-9.,]+) \S+$", working)
    assert value is not None, working
    assert f"vA = {value.group(1)}" in texts, (working, [t for t in texts if t.startswith("vA")])


# ----------------------------------------------------------------------------- 4. the hyperbola's scale and message

def test_hyperbola_scale_names_its_quantity_and_unit():
    """The hyperbola's abscissa scale read "μ_1/δ = 2 /mm": its quantity is 1/[δ], a pure number, so the scale is
    so many of it per millimetre, mm⁻¹ (мм⁻¹ in ru)."""
    from graphmethods.sheets.flywheel_hyperbola import flywheel_hyperbola

    for lang, mm in (("en", "mm"), ("ru", "мм"), ("zh", "mm")):
        scene = flywheel_hyperbola(600.0, omega_m=60.0, machine="ac-generator", notation=lang)
        cap = next(markup.plain(s.caption(lang)) for s in scene.scales() if "δ" in s.symbol)
        assert cap in " ".join(_texts(scene)), cap
        assert cap.startswith("μ1/[δ] = ") and cap.endswith(f" {mm}⁻¹"), cap
        assert " /" not in cap
    assert Scale("μ", "", 2.0).caption("ru") == "μ = 2 мм⁻¹"


def test_scale_that_does_not_fit_says_so_in_one_language():
    """A given μ_J that did not fit said "μJ = 0.0001 кг·м²/mm" in ru: the message is English, its unit too."""
    from graphmethods.sheets.flywheel_hyperbola import flywheel_hyperbola

    with pytest.raises(InputError) as err:
        flywheel_hyperbola(600.0, omega_m=60.0, notation="ru", mu_J=0.0001)
    message = str(err.value)
    assert "kg·m²/mm" in message and not re.search("[а-яА-Я]", message), message
