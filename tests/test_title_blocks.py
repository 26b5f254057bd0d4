"""The main inscription of a course sheet: ГОСТ 2.104 form 1 on ru sheets, GB/T 10609.1 on zh sheets,
the simple block on en; the student's name, group and sheet number as options."""

from __future__ import annotations

import pytest

from graphmethods.cli import main
from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.scene import Page, Scene, TitleBlock
from graphmethods.scene.title_blocks import FormBlock
from graphmethods.sheets.force_analysis_sheet import force_analysis_sheet
from graphmethods.sheets.layout import sign_sheet, standard_page

GOST = ("Изм.", "№ докум.", "Подп.", "Дата", "Разраб.", "Пров.", "Т.контр.", "Н.контр.", "Утв.", "Лит.",
        "Масса", "Масштаб")
GB = ("标记", "处数", "分区", "更改文件号", "签名", "年月日", "设计", "审核", "工艺", "批准", "重量", "比例")


def _texts(scene: Scene) -> list[str]:
    return [c.data.text for c in record(scene).calls if c.kind == "text"]


@pytest.mark.parametrize(("lang", "form", "size", "words"), [("ru", "gost", (185.0, 55.0), GOST),
                                                             ("zh", "gb", (180.0, 56.0), GB)])
def test_a_course_sheet_carries_its_languages_standard_block(lang, form, size, words) -> None:
    page = standard_page(Page("A1", frame=True), title="T", problem="p", scales=(), nt=lang)
    assert page.title_block is not None and page.title_block.form == form
    block = page.title_block.table(*page.inner_box()[2:])
    assert isinstance(block, FormBlock) and (block.width_mm, block.height_mm) == size
    assert block.box()[2:] == page.inner_box()[2:]                  # in the frame's bottom-right corner
    signed = sign_sheet(Scene(page=page), student="S", group="G", sheet_no="3", sheets="4")
    texts = _texts(signed)
    assert all(w in texts for w in words), [w for w in words if w not in texts]
    assert "S" in texts and "G" in texts


def test_an_a4_figure_keeps_the_simple_block() -> None:
    page = standard_page(None, title="T", problem="p", scales=(), nt="ru")
    assert page.title_block is not None and page.title_block.form == "simple"


def test_the_force_sheet_of_the_shaper_in_russian_is_signed() -> None:
    scene = sign_sheet(force_analysis_sheet(builtin.case("shaper"), 3, page="A1", notation="ru"),
                       student="Иванов И. И.", group="МТ-31", sheet_no="2", sheets="4")
    texts = _texts(scene)
    assert {"Разраб.", "Иванов И. И.", "МТ-31", "Лист 2", "Листов 4"} <= set(texts)
    assert min(c.data.size_mm for c in record(scene).calls if c.kind == "text" and c.data.text in GOST) >= 3.5


def test_the_english_block_holds_the_students_rows() -> None:
    page = standard_page(Page("A1", frame=True), title="T", problem="p", scales=(), nt="en")
    tb = page.title_block
    assert isinstance(tb, TitleBlock) and [h for h, _ in tb.person] == ["Student", "Group", "Sheet"]
    before = tb.table(800.0, 580.0).height_mm
    signed = sign_sheet(Scene(page=page), student="J. Smith", group="G1", sheet_no="1", sheets="3")
    assert signed.page.title_block.table(800.0, 580.0).height_mm == before    # signing moves nothing
    assert {"J. Smith", "G1", "1/3"} <= set(_texts(signed))


def test_cli_signs_the_sheet_and_refuses_the_options_without_one(tmp_path, capsys) -> None:
    out = tmp_path / "s.svg"
    assert main(["study", "press", "--no-exact", "--sheet", str(out), "--lang", "ru", "--student", "Петров П. П.",
                 "--group", "МТ-31", "--sheet-no", "3/4"]) == 0
    text = out.read_text(encoding="utf-8")
    assert "Петров П. П." in text and "Листов 4" in text
    capsys.readouterr()
    assert main(["study", "press", "--student", "X"]) == 2
    assert "add --sheet" in capsys.readouterr().err


@pytest.mark.parametrize(("form", "head"), [("gost", "Изм."), ("gb", "更改文件号")])
def test_a_narrow_columns_head_is_condensed_at_3_5_mm_inside_its_column(form, head) -> None:
    """ГОСТ 2.304 type A lettering is narrow: "Изм." in ГОСТ 2.104's 7 mm column and "更改文件号" in GB/T
    10609.1's 16 mm one keep 3.5 mm and are condensed (a horizontal scale), never set smaller."""
    from graphmethods.scene.elements import label_bbox
    from graphmethods.scene.primitives import Label, Path, walk

    block = FormBlock.of(form, right=831.0, bottom=584.0, fields={"title": "T", "student": "S"})
    prims = list(walk([block.draw()]))
    labels = [p for p in prims if isinstance(p, Label)]
    assert min(lab.size_mm for lab in labels) >= 3.5
    lab = next(lab for lab in labels if lab.text == head)
    assert 0.6 <= lab.stretch < 1.0
    x0, _, x1, _ = label_bbox(lab)
    # the column's lines either side of the head: the block's sides and the verticals that span its baseline
    verticals = [block.box()[0], block.box()[2]] + [
        p.points[0][0] for p in prims if isinstance(p, Path) and len(p.points) == 2
        and p.points[0][0] == p.points[1][0]
        and min(p.points[0][1], p.points[1][1]) <= lab.y <= max(p.points[0][1], p.points[1][1])]
    left = max(x for x in verticals if x <= lab.x)
    right = min(x for x in verticals if x >= lab.x)
    assert left + 0.5 <= x0 and x1 <= right - 0.5


def test_every_writer_draws_condensed_lettering() -> None:
    """SVG (a horizontal scale about the text's start), PDF (the text matrix) and DXF (the TEXT's width
    factor) all condense the ГОСТ block's "Изм."; the PNG preview sets it smaller to the same width."""
    import io
    import re
    import zlib

    import ezdxf

    from graphmethods.render import dxf, pdf, svg

    scene = Scene(page=standard_page(Page("A1", frame=True), title="T", problem="p", scales=(), nt="ru"))
    lab = next(c.data for c in record(scene).calls if c.kind == "text" and c.data.text == "Изм.")
    k = f"{lab.stretch:g}"
    assert lab.size_mm == 3.5 and lab.stretch < 1.0
    assert any(f'transform="matrix({k} 0 0 1 ' in line and ">Изм.<" in line
               for line in svg.to_string(scene).splitlines())
    streams = re.findall(rb"stream\r?\n(.*?)\r?\nendstream", pdf.to_bytes(scene), re.S)
    ops = b"".join(zlib.decompress(s) if s[:1] == b"x" else s for s in streams)
    assert f"{k} 0 0 -1 ".encode() in ops
    doc = ezdxf.read(io.StringIO(dxf.to_bytes(scene).decode("utf-8")))
    assert [e.dxf.width for e in doc.modelspace().query("TEXT") if e.dxf.text == "Изм."] == [lab.stretch]
