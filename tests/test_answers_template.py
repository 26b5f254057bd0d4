"""The blank answers file written beside a worksheet: every key is one the check reads, and a
template filled in with a variant's own values is accepted by ``check`` as right."""

import json
import re

import pytest

from graphmethods.errors import InputError
from graphmethods.sheets import check, worksheets
from graphmethods.sheets.worksheets import answers

KINDS = ("indicator", "step-moment", "velocity-plan", "wittenbauer")


def _fill(text: str, values: dict) -> str:
    """Replace ``key = ""`` / ``key = []`` lines of the template text by the values (comments kept)."""
    def sub(m):
        key = m.group(1)
        return f"{key} = {json.dumps(values[key])}" if key in values else m.group(0)
    return re.sub(r'^(\w+) = (?:""|\[\])', sub, text, flags=re.M)


def _values(v) -> dict:
    data, ans = v.data(), v.answers()
    out = {}
    for _section, keys in answers.KEYS[v.kind]:
        for key, _ in keys:
            value = data.get(key, ans.get(key))
            if isinstance(value, list) and key not in answers.LISTS:
                value = value[0]                       # a position list: any one of them is right
            if value is not None:
                out[key] = value
    return out


@pytest.mark.parametrize("kind", KINDS)
def test_every_key_of_the_template_is_one_the_check_reads(kind):
    data = check.load_toml(answers.template(kind))
    for section, keys in data.items():
        if isinstance(keys, dict):
            assert set(keys) <= set(check.SCHEMA[section]), section
        else:
            assert section in check.TOP_LEVEL
    assert [s for s, _ in answers.KEYS[kind]] == [s for s in data if s not in ("page",) + check.TOP_LEVEL]


@pytest.mark.parametrize("kind", KINDS)
def test_a_filled_template_is_accepted_and_a_wrong_value_is_not(kind, tmp_path):
    v = worksheets.variant(kind, seed=7, number=2)
    values = _values(v)
    assert len(values) == sum(len(keys) for _, keys in answers.KEYS[kind])   # every key filled
    path = tmp_path / "a.toml"
    path.write_text(_fill(answers.template(kind, problem=v.id), values), encoding="utf-8")
    report = check.check(v.id, path)
    assert report.ok, report.to_text()
    assert {it.key.split("[")[0] for it in report.items} >= {f"results.{k}" for k in ("J_F",) if k in values}
    wrong = dict(values, J_F=values["J_F"] * 1.2) if "J_F" in values else dict(values, pb_mm=values["pb_mm"] + 5)
    path.write_text(_fill(answers.template(kind), wrong), encoding="utf-8")
    assert not check.check(v.id, path).ok


def test_a_blank_template_holds_nothing_to_check_and_says_so(tmp_path):
    path = tmp_path / "blank.toml"
    path.write_text(answers.template("indicator"), encoding="utf-8")
    with pytest.raises(InputError, match="nothing to check"):
        check.check("indicator:7:1", path)
    with pytest.raises(InputError, match="kinds: indicator"):
        answers.template("flywheel")
