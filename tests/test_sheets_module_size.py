"""Issue 26 item 8: the figure layer's modules stay readable: none of sheets/ over 800 lines (the figure
recipes; the drawing checker's sheets/check/cad.py, 969 lines, is another lane's and not yet held to it)."""

from pathlib import Path

SHEETS = Path(__file__).resolve().parents[1] / "graphmethods" / "sheets"


def test_no_module_of_sheets_is_over_800_lines() -> None:
    long = {p.relative_to(SHEETS).as_posix(): n for p in SHEETS.glob("*.py")
            if (n := len(p.read_text(encoding="utf-8").splitlines())) > 800}
    assert not long, f"split these by textbook concept (a module per figure family): {long}"
