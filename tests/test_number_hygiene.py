"""Number hygiene: one formatter; a value within the round-off of its own computation prints as 0
with its reason, never as 4,796·10⁻³⁰; a dimension on a drawing is in the drawing's unit (mm)."""

from __future__ import annotations

import re

import pytest

from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.scene.notation import get
from graphmethods.scene.numbers import format_value, within_roundoff
from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet

NOISE = re.compile(r"10⁻(⁹|[¹²³⁴⁵⁶⁷⁸⁹][⁰¹²³⁴⁵⁶⁷⁸⁹]+)")     # 10⁻⁹ and smaller


def _texts(scene) -> list[str]:
    return [c.data.text for c in record(scene).calls if c.kind == "text"]


def test_round_off_is_written_zero() -> None:
    assert format_value(4.796e-30, reference=236.6) == "0"
    assert format_value(2.55e-13, reference=50.0) == "0"
    assert format_value(2.55e-3, reference=50.0) == "0.00255"          # small but real
    assert within_roundoff(0.0, 0.0) and not within_roundoff(1e-6, 1.0)


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_zero_says_why(lang: str) -> None:
    text = get(lang).zero("a^n_{BA}", "ω_{2}")
    assert text.startswith("a^n_{BA} = 0 (") and "ω_{2} = 0" in text


@pytest.mark.parametrize("name", sorted(builtin.LINKAGES))
def test_kinematic_sheets_print_no_round_off_noise(name: str) -> None:
    texts = _texts(kinematic_analysis_sheet(builtin.case(name), page="A1", notation="ru"))
    noisy = [t for t in texts if NOISE.search(t)]
    assert not noisy, noisy
    for t in texts:
        if t.startswith("H = "):                            # the stroke as a drawing dimension: mm
            assert t.endswith(" мм"), t


def test_the_two_sliders_resting_rod_is_said_in_words() -> None:
    texts = _texts(kinematic_analysis_sheet(builtin.case("two-slider"), page="A1", notation="en"))
    assert any(re.search(r"a\^n_\{?BA\}? = 0 \(ω_\{?2\}? = 0 in this position\)", t) for t in texts) or \
        any("= 0 (ω" in t and "in this position" in t for t in texts), [t for t in texts if "a" in t][:20]
