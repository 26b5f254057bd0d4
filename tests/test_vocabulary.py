"""One vocabulary: every word, symbol and Russian unit lives in the TOML files of scene/vocabulary/.

The figure modules keep no tables of their own; every key has a text in en, ru and zh with
the same placeholders; every key a figure asks for by its literal name exists.
"""

from __future__ import annotations

import ast
import importlib
import string
from pathlib import Path

import pytest

import graphmethods
from graphmethods.scene import vocabulary

notation = importlib.import_module("graphmethods.scene.notation")  # the package exports a function of that name

PACKAGE = Path(graphmethods.__file__).parent

def _is_text_triple(node: ast.expr) -> bool:
    """(en, ru, zh): three strings, the second with Russian letters (not ("en", "ru", "zh") or suffixes)."""
    return isinstance(node, ast.Tuple) and len(node.elts) == 3 and \
        all(isinstance(e, ast.Constant) and isinstance(e.value, str) for e in node.elts) and \
        any("а" <= c.lower() <= "я" for c in node.elts[1].value)  # type: ignore[attr-defined]


def _is_vocabulary(name: str, node: ast.expr) -> bool:
    """An (en, ru, zh) text, a table of them, a table per language code, or a table of Russian units."""
    if _is_text_triple(node):
        return True
    if not isinstance(node, ast.Dict) or not node.values:
        return False
    keys = {k.value for k in node.keys if isinstance(k, ast.Constant)}
    three_strings = all(isinstance(v, ast.Tuple) and len(v.elts) == 3 and
                        all(isinstance(e, ast.Constant) and isinstance(e.value, str) for e in v.elts)
                        for v in node.values)
    return (three_strings or any(_is_text_triple(v) for v in node.values) or (keys and keys <= {"en", "ru", "zh"})
            or "UNITS_RU" in name.upper())


def _table_lines(tree: ast.Module) -> set[int]:
    """Lines inside module-level assignments (their triples are reported by the table's name)."""
    return {line for node in tree.body if isinstance(node, (ast.Assign, ast.AnnAssign))
            for line in range(node.lineno, (node.end_lineno or node.lineno) + 1)}


def _tables(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found = [f"(en, ru, zh) at line {n.lineno}" for n in ast.walk(tree)
             if isinstance(n, ast.Tuple) and _is_text_triple(n) and n.lineno not in _table_lines(tree)]
    for node in tree.body:
        if isinstance(node, ast.Assign):
            found += [t.id for t in node.targets if isinstance(t, ast.Name) and _is_vocabulary(t.id, node.value)]
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and node.value is not None:
            found += [node.target.id] if _is_vocabulary(node.target.id, node.value) else []
    return found


def _figure_modules() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*.py")
                  if "vocabulary" not in p.parts)


def test_figure_modules_keep_no_vocabulary_of_their_own() -> None:
    offenders = {p.relative_to(PACKAGE).as_posix(): _tables(p) for p in _figure_modules()}
    offenders = {k: v for k, v in offenders.items() if v}
    assert not offenders, f"move these into scene/vocabulary/ (nt.word, nt.sym, nt.unit): {offenders}"


def _placeholders(text: str) -> set[str]:
    return {field for _, field, _, _ in string.Formatter().parse(text) if field is not None}


def _all_triples() -> list[tuple[str, tuple[str, str, str]]]:
    symbols, words, _ = vocabulary.tables()
    return [(f"word {k}", v) for k, v in words.items()] + [(f"symbol {k}", v) for k, v in symbols.items()]



@pytest.mark.parametrize(("key", "triple"), _all_triples(), ids=lambda x: x if isinstance(x, str) else "")
def test_every_key_in_three_languages_with_the_same_placeholders(key: str, triple: tuple[str, str, str]) -> None:
    assert isinstance(triple, tuple) and len(triple) == 3, f"{key}: give (en, ru, zh)"
    assert all(isinstance(t, str) and t.strip() for t in triple), f"{key}: a language is empty"
    if key.startswith("symbol"):
        return  # markup such as M_{ed}, not a format string
    en, ru, zh = (_placeholders(t) for t in triple)
    assert en == ru == zh, f"{key}: placeholders differ: en {en}, ru {ru}, zh {zh}"


def test_one_table_of_russian_units() -> None:
    _, _, units = vocabulary.tables()
    assert units["N·m"] == "Н·м" and units["m/s"] == "м/с" and units["rad/s²"] == "рад/с²"


@pytest.mark.parametrize(("text", "message"), [
    ('[words]\nx = ["en", "ru"]', "give"),                        # a language missing
    ('[words]\nx = ["en", "", "zh"]', "give"),                    # a language empty
    ('[symbols]\nx = 3', "give"),                                 # not a text
    ('[units_ru]\n"m/s" = "м в с"', "units_ru"),                  # Russian units kept outside the one table
    ('[word]\nx = "x"', "tables are"),                           # a misspelt table
])
def test_a_malformed_vocabulary_file_is_refused(text: str, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        vocabulary.parse(text, "example")


def test_every_file_is_a_family_or_the_core() -> None:
    files = sorted(p.stem for p in (PACKAGE / "scene" / "vocabulary").glob("*.toml"))
    assert files == sorted([*vocabulary.families(), vocabulary.CORE])
    assert not [p.name for p in (PACKAGE / "scene" / "vocabulary").glob("*.py") if p.name != "__init__.py"]


def _literal_keys(method: str) -> set[tuple[str, str]]:
    keys = set()
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == method
                    and len(node.args) == 1 and isinstance(node.args[0], ast.Constant)
                    and isinstance(node.args[0].value, str)):
                keys.add((path.relative_to(PACKAGE).as_posix(), node.args[0].value))
    return keys


@pytest.mark.parametrize("method", ["word", "sym"])
def test_every_literal_key_exists(method: str) -> None:
    profile = notation.get("zh")
    table = profile.words if method == "word" else profile.symbols
    missing = sorted((where, key) for where, key in _literal_keys(method) if key not in table)
    assert not missing, f"unknown {method} keys: {missing}"


def test_no_text_kept_twice_under_two_keys() -> None:
    symbols, words, _ = vocabulary.tables()
    for kind, table in (("word", words), ("symbol", symbols)):
        keys_of: dict[tuple[str, str, str], list[str]] = {}
        for key, triple in table.items():
            keys_of.setdefault(triple, []).append(key)
        twice = [keys for keys in keys_of.values() if len(keys) > 1]
        assert not twice, f"the same {kind} under several keys (keep one): {twice}"


def test_a_missing_key_is_a_programming_error_not_bad_input() -> None:
    from graphmethods.errors import InputError

    with pytest.raises(notation.VocabularyError, match="no word 'worksheets.nope'") as caught:
        notation.get("ru").word("worksheets.nope")
    assert not isinstance(caught.value, InputError)
    with pytest.raises(notation.VocabularyError, match="no symbol"):
        notation.get("zh").sym("nope")
