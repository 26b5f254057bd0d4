"""Lecture build-up (issue 20): constructions step by step, and their slides, frames, animation and page."""

import collections
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from graphmethods.errors import InputError, OutputExistsError
from graphmethods.render import steps as R, svg
from graphmethods.render.recording import record
from graphmethods.scene import Page, markup
from graphmethods.scene.steps import NEW_COLOUR, OLD_COLOUR
from graphmethods.sheets import calculus as C, kinematics as K, steps as S
from graphmethods.sheets.energy import energy_indicator
from graphmethods.sheets.forces import force_plans, zhukovsky_forces
from graphmethods.sheets.wittenbauer import wittenbauer_diagram
from graphmethods.sheets.work_diagrams import work_diagrams
from graphmethods.sheets.zhukovsky_lever import zhukovsky_lever

SVG = "{http://www.w3.org/2000/svg}"
LINKAGES = tuple(S.LINKAGES)
CASES = ([(c, "velocity-plan") for c in LINKAGES] + [(c, "acceleration-plan") for c in LINKAGES]
         + [(c, "energy-indicator") for c in ("W1", "W2", "W3", "W4", "press")]
         + [(c, "wittenbauer") for c in ("press", "shaper", "four-bar")]
         + [(c, "kinematic-diagrams") for c in ("press", "shaper")]
         + [(c, "work-diagrams") for c in ("press", "W3")]
         + [(c, "zhukovsky-load") for c in ("press", "four-bar")]
         + [(c, "force-plans") for c in LINKAGES + ("six-bar-press",)]
         + [(c, "zhukovsky-lever") for c in LINKAGES]
         + [(c, "kinematic-scheme") for c in LINKAGES])


@pytest.fixture(scope="module")
def built():
    cache = {}

    def get(case, figure, lang="en", page="slide"):
        key = (case, figure, lang, page)
        if key not in cache:
            cache[key] = S.build(case, figure, notation=lang, page=page)
        return cache[key]
    return get


def _leaves(scene, *, geometry_only=False):
    """The drawing calls of a scene as a multiset: kind, data and (unless geometry only) style."""
    out = collections.Counter()
    for c in record(scene).calls:
        if c.kind in ("path", "polygon", "circle"):
            out[(c.kind, c.data) if geometry_only else (c.kind, c.data, c.style)] += 1
        elif c.kind == "text":
            lab = c.data
            out[("text", lab.x, lab.y, lab.runs, lab.size_mm) if geometry_only else ("text", lab)] += 1
    return out


def _includes(big: collections.Counter, small: collections.Counter) -> bool:
    return not (small - big)


# ----------------------------------------------------------------------------- the step model

@pytest.mark.parametrize("case,figure", CASES, ids=[f"{c}-{f}" for c, f in CASES])
def test_each_step_draws_the_previous_ones_and_the_last_is_the_finished_figure(built, case, figure):
    bu = built(case, figure)
    assert len(bu) >= 4
    prev = None
    for k in range(1, len(bu) + 1):
        now = _leaves(bu.scene_at(k))
        if prev is not None:
            assert _includes(now, prev), f"step {k} lost something step {k - 1} drew"
            assert sum(now.values()) > sum(prev.values()), f"step {k} draws nothing new"
        prev = now
    assert record(bu.scene_at(len(bu))).calls == record(bu.figure).calls


DIRECT = [("press", "velocity-plan"), ("shaper", "velocity-plan"), ("W1", "energy-indicator"),
          ("press", "wittenbauer"), ("press", "kinematic-diagrams"), ("W3", "work-diagrams"),
          ("press", "zhukovsky-load"), ("slotted-lever", "kinematic-scheme"), ("shaper", "acceleration-plan"),
          ("shaper", "force-plans"), ("four-bar", "zhukovsky-lever")]


@pytest.mark.parametrize("case,figure", DIRECT, ids=[f"{c}-{f}" for c, f in DIRECT])
def test_the_finished_figure_is_what_the_figure_function_draws(case, figure):
    """Built independently with the figure function on the same page, the figure is the last step."""
    page, _, _, tb = S.step_page("slide")
    obj = S.resolve_case(case)
    bu = S.build(case, figure, page=S.SLIDE_PAGE)      # the slide at 1 : 1 (not enlarged for a projector)
    if figure == "velocity-plan":
        pos = K.fullest_position(K._Linkage.of(obj).plans)
        direct = K.velocity_plan(obj, pos, page=page, title_block=tb)
    elif figure == "acceleration-plan":
        from graphmethods.sheets import acceleration as SA

        pr = SA._Problem(obj, m=None, omega_1=None, epsilon_1=0.0)
        direct = SA.acceleration_plan(obj, SA._default_position(pr.plans(), pr.linkage), page=page, title_block=tb)
    elif figure == "energy-indicator":                 # on a slide its vectors spread wider than on paper
        direct = energy_indicator(obj, page=page, title_block=tb,
                                  step_mm=S.slide_step_mm(len(obj.excess_work.work), page))
    elif figure == "kinematic-diagrams":
        direct = C.kinematic_diagrams(obj, page=page, title_block=tb)
    elif figure == "work-diagrams":
        direct = work_diagrams(obj, page=page, title_block=tb)
    elif figure == "kinematic-scheme":
        direct = K.kinematic_scheme(obj, m=12, page=page, title_block=tb)
    elif figure == "zhukovsky-load":
        direct = zhukovsky_lever(obj, page=page, title_block=tb)
    elif figure == "force-plans":
        direct = force_plans(obj, 2, page=page, title_block=tb)
    elif figure == "zhukovsky-lever":
        direct = zhukovsky_forces(obj, 2, page=page, title_block=tb)
    else:
        from graphmethods.dynamics.study import Study

        direct = wittenbauer_diagram(Study(obj, positions=12), page=page, title_block=tb)
    assert record(bu.scene_at(len(bu))).calls == record(direct).calls


SLIDES = CASES[:5] + [("W1", "energy-indicator")]


@pytest.mark.parametrize("case,figure", SLIDES, ids=[f"{c}-{f}" for c, f in SLIDES])
def test_slides_grey_the_earlier_steps_and_colour_the_new_one(built, case, figure):
    bu = built(case, figure)
    for k in range(1, len(bu) + 1):
        rec = record(bu.slide(k))
        colours = collections.Counter()
        for c in rec.calls:
            if "step-caption" in c.groups or any(g == "title" for g in c.groups) or "page" in c.groups:
                continue
            if c.kind == "text":
                colours[c.data.color] += 1
            elif c.kind in ("path", "polygon", "circle"):
                colours[c.style.stroke or c.style.fill] += 1
        assert colours[NEW_COLOUR] > 0
        assert set(colours) <= {NEW_COLOUR, OLD_COLOUR, "#ffffff"}
        assert (colours[OLD_COLOUR] > 0) == (k > 1 and any(
            bu.figure.elements[i].name != "title" for s in bu.steps[:k - 1] for i in s.elements))
        assert rec.texts("step-caption") == [markup.plain(f"{k}. {bu.steps[k - 1].caption}")]
        # the geometry of the slide is that of the figure after step k, plus the caption
        geometry = _leaves(bu.slide(k), geometry_only=True)
        assert _includes(geometry, _leaves(bu.scene_at(k), geometry_only=True))


def test_every_element_belongs_to_one_step_and_a_bad_partition_is_refused():
    from graphmethods.scene import Line, Scene
    from graphmethods.scene.steps import BuildUp, Step, partition

    fig = Scene(Page("A4"), (Line((0, 0), (10, 0), name="a"), Line((0, 0), (0, 10), name="b")))
    with pytest.raises(InputError, match="no step draws the element 'b'"):
        partition(fig, [("A", "a")], caption_box=(0, 0, 10, 10))
    with pytest.raises(InputError, match="exactly once"):
        BuildUp(fig, (Step("A", (0,)), Step("B", (0, 1))), (0, 0, 10, 10))
    with pytest.raises(InputError, match="no element for the step"):
        partition(fig, [("A", ("a", "b")), ("B", "c")], caption_box=(0, 0, 10, 10))
    bu = partition(fig, [("A", "a"), ("B", "b")], caption_box=(0, 0, 10, 10))
    with pytest.raises(InputError, match="from 1 to 2"):
        bu.slide(3)


# ----------------------------------------------------------------------------- what the captions say

def test_velocity_plan_steps_follow_the_construction_records(built):
    bu = built("shaper", "velocity-plan")
    plans = K._Linkage.of(S.resolve_case("shaper")).plans
    names = [[bu.figure.elements[i].name for i in s.elements] for s in bu.steps]
    # every construction line is drawn in a step of its own, in the order of the records
    lines = [f"line-{n}-{ln.through}" for n, c in plans.constructions.items() for ln in c.lines]
    steps_of_lines = [next(k for k, ns in enumerate(names) if ln in ns) for ln in lines]
    assert steps_of_lines == sorted(steps_of_lines) and len(set(steps_of_lines)) == len(lines)
    # a point found by intersection appears in the step right after its second line
    for n, c in plans.constructions.items():
        if c.method == "intersection":
            second = next(k for k, ns in enumerate(names) if f"line-{n}-{c.lines[1].through}" in ns)
            assert f"name-{c.label}" in names[second + 1]
    assert "table" in names[-1]


def test_velocity_plan_captions_give_the_values_the_drawing_measures(built):
    bu = built("press", "velocity-plan")
    mu_v = bu.figure.scales()[0].per_mm
    rec = record(bu.figure)
    meet = next(c for c in bu.captions() if "meet" in c)
    got = dict(re.findall(r"(v_\{\w+\}) = ([\d.]+) m/s", meet))
    assert set(got) == {"v_{B}", "v_{BA}"}
    z = bu.enlarged                          # a slide for a projector: μ is per mm of the drawing at 1 : 1
    assert float(got["v_{B}"]) == pytest.approx(rec.vector_length_mm("vector-pb") / z * mu_v, rel=1e-3)
    assert float(got["v_{BA}"]) == pytest.approx(rec.vector_length_mm("vector-ab") / z * mu_v, rel=1e-3)


def test_energy_indicator_captions_give_each_vector_as_drawn(built):
    bu = built("W1", "energy-indicator")
    rec = record(bu.figure)
    for cap, _step in zip(bu.captions()[1:8], bu.steps[1:8]):
        ab, mm = re.search(r"Interval (\w\w):.* ([\d.]+) mm (up|down)", cap).group(1, 2)
        assert rec.vector_length_mm(f"vector-{ab}") / bu.enlarged == pytest.approx(float(mm), rel=1e-3)
    assert "575 J" in bu.captions()[-1]


def test_wittenbauer_caption_gives_the_studys_J_F(built):
    from graphmethods.dynamics.study import Study

    bu = built("press", "wittenbauer")
    J_F = Study(S.resolve_case("press"), positions=12).wittenbauer.J_F
    value = float(re.search(r"= ([\d.]+) kg·m²$", bu.captions()[-1]).group(1))
    assert value == pytest.approx(J_F, rel=1e-3)
    assert [c.split(" ")[0] for c in bu.captions()[:3]] == ["Axes:", "Plot", "Join"]


@pytest.mark.parametrize("lang,script", [("ru", "[А-Яа-я]"), ("zh", "[\u4e00-\u9fff]")])
def test_captions_are_in_the_figures_language(built, lang, script):
    for case, figure in (("press", "velocity-plan"), ("W1", "energy-indicator"), ("press", "wittenbauer")):
        bu = built(case, figure, lang)
        en = built(case, figure, "en")
        assert len(bu) == len(en) and bu.figure.notation == lang
        assert all(re.search(script, c) for c in bu.captions()), bu.captions()


def test_slide_page_is_16_by_9_and_sheet_pages_keep_frame_and_title_block(built):
    page = Page("slide")
    assert (page.width_mm, page.height_mm) == (338.7, 190.5)
    assert page.width_mm / page.height_mm == pytest.approx(16 / 9, rel=1e-3)
    bu = built("press", "velocity-plan", "en", "A4")
    assert bu.figure.page.size == "A4" and bu.figure.page.frame and bu.figure.page.title_block is not None
    x0, y0, x1, y1 = bu.caption_box
    assert y0 >= bu.figure.page.inner_box()[3] - 1e-9          # the caption is under the frame
    # nothing of the figure is drawn in the caption band
    assert bu.figure.bbox()[3] <= y0 + 1e-6
    with pytest.raises(InputError, match="use slide, A4"):
        S.step_page("letter")


# ----------------------------------------------------------------------------- outputs

def _visible_at(doc: str, t: float):
    """Ids of the layers an SMIL player shows at time t (s), from the <animate> elements."""
    root = ET.fromstring(doc.split("?>", 1)[1])
    shown = []
    for g in root.iter(f"{SVG}g"):
        if g.get("data-step") is None:
            continue
        anim = g.find(f"{SVG}animate")
        if anim is None:
            vis = g.get("visibility", "visible")
        else:
            dur = float(anim.get("dur").rstrip("s"))
            times = [float(x) * dur for x in anim.get("keyTimes").split(";")]
            values = anim.get("values").split(";")
            vis = values[max(i for i, t0 in enumerate(times) if t0 <= t % dur)]
        if vis == "visible":
            shown.append(g.get("id"))
    return shown


@pytest.mark.parametrize("case,figure", [("press", "velocity-plan"), ("W1", "energy-indicator"),
                                         ("press", "wittenbauer")])
def test_animated_svg_is_valid_and_its_timing_covers_every_step(built, case, figure):
    bu = built(case, figure)
    n = len(bu)
    doc = R.animated_svg(bu, seconds=2.5)
    root = ET.fromstring(doc.split("?>", 1)[1])
    assert root.tag == f"{SVG}svg" and root.get("viewBox") == f"0 0 {bu.figure.page.width_mm:g} " \
                                                              f"{bu.figure.page.height_mm:g}"
    assert all(el.tag.startswith(SVG) for el in root.iter()), "only SVG elements"
    ids = [el.get("id") for el in root.iter() if el.get("id")]
    assert len(ids) == len(set(ids)), "ids are unique"
    assert "script" not in doc
    anims = list(root.iter(f"{SVG}animate"))
    for a in anims:
        keys = [float(x) for x in a.get("keyTimes").split(";")]
        assert a.get("calcMode") == "discrete" and a.get("repeatCount") == "indefinite"
        assert keys[0] == 0 and keys == sorted(keys) and keys[-1] < 1
        assert len(keys) == len(a.get("values").split(";"))
        assert a.get("dur") == f"{2.5 * n:g}s"
    # at the middle of each step's slot exactly that step shows: earlier steps grey, it in colour
    for k in range(1, n + 1):
        shown = _visible_at(doc, (k - 0.5) * 2.5)
        assert shown == [f"old-{j}" for j in range(1, k)] + [f"new-{k}"] or \
            sorted(shown) == sorted([f"old-{j}" for j in range(1, k)] + [f"new-{k}"]), (k, shown)
    # the slots cover the cycle: just before its end the last step shows, at its start the first
    assert _visible_at(doc, n * 2.5 - 1e-6) == _visible_at(doc, (n - 0.5) * 2.5)
    assert _visible_at(doc, 0.0) == ["new-1"]
    # without SMIL the document shows the last step
    static = [g.get("id") for g in root.iter(f"{SVG}g") if g.get("data-step") and g.get("visibility") != "hidden"]
    assert sorted(static) == sorted([f"old-{j}" for j in range(1, n)] + [f"new-{n}"])


def test_animated_svg_refuses_a_bad_duration(built):
    with pytest.raises(InputError, match="seconds per step"):
        R.animated_svg(built("W1", "energy-indicator"), seconds=float("nan"))


@pytest.mark.parametrize("lang", ["en", "ru", "zh"])
def test_html_page_is_self_contained(built, lang):
    bu = built("press", "velocity-plan", lang)
    page = R.html_page(bu)
    assert page.startswith("<!DOCTYPE html>") and f'<html lang="{lang}">' in page
    assert "Content-Security-Policy" in page and "default-src 'none'" in page
    without_ns = page.replace('xmlns="http://www.w3.org/2000/svg"', "")
    for bad in ("http://", "https://", "src=", "href=", "url(", "<link", "<img", "@import", "fetch(", "XMLHttp"):
        assert bad not in without_ns, bad
    # every caption is in the page, and the counter in the page's language
    for c in bu.captions():
        assert R.caption_html(c) in page
    n = len(bu)
    assert {"en": f"Step 1 of {n}", "ru": f"Шаг 1 из {n}", "zh": f"第 1 步，共 {n} 步"}[lang] in page
    # the SVG part parses, with one grey and one coloured layer per step (the last has no grey one)
    svg_part = page[page.index("<svg"):page.index("</svg>") + 6]
    root = ET.fromstring(svg_part)
    layers = [g.get("id") for g in root.iter(f"{SVG}g") if g.get("data-step")]
    assert layers == [x for k in range(1, len(bu) + 1) for x in ((f"old-{k}",) if k < len(bu) else ()) + (f"new-{k}",)]


def test_pdf_has_one_page_per_step_with_its_caption(built):
    from pdf_reading import Pdf

    bu = built("press", "velocity-plan")
    doc = Pdf(R.pdf_bytes(bu))
    pages = doc.pages()
    assert len(pages) == len(bu)
    for k, page in enumerate(pages, start=1):
        box = doc.media_box(page)
        assert box[2] - box[0] == pytest.approx(338.7 * 72 / 25.4, abs=0.01)
        shown = [s.text for s in doc.shown(page)]
        big = [s for s in doc.shown(page) if abs(s.size - bu.caption_mm) < 0.01]     # the caption's main runs
        text = "".join(s.text for s in big)
        assert text.replace(" ", "").startswith(f"{k}.") and "".join(shown)
        main_runs = "".join(t for t, shift in markup.parse(f"{k}. {bu.steps[k - 1].caption}") if shift == 0)
        assert text.replace(" ", "") == main_runs.replace(" ", "")


def test_outputs_are_deterministic():
    a, b = S.build("W1", "energy-indicator", notation="zh"), S.build("W1", "energy-indicator", notation="zh")
    assert R.pdf_bytes(a) == R.pdf_bytes(b)
    assert R.html_page(a) == R.html_page(b)
    assert R.animated_svg(a) == R.animated_svg(b)


def test_frames_are_written_numbered_never_over_a_file_and_never_in_part(tmp_path, built):
    bu = built("W1", "energy-indicator")
    out = R.save(bu, tmp_path / "w1.svg", "svg")
    assert [p.name for p in out] == [f"w1-{k:02d}.svg" for k in range(1, len(bu) + 1)]
    assert out[2].read_text(encoding="utf-8") == svg.to_string(bu.slide(3))
    # one frame exists: nothing is written, the existing file is kept
    for p in out[1:]:
        p.unlink()
    out[0].write_text("mine")
    with pytest.raises(OutputExistsError):
        R.save(bu, tmp_path / "w1.svg", "svg")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["w1-01.svg"] and out[0].read_text() == "mine"
    R.save(bu, tmp_path / "w1.svg", "svg", overwrite=True)
    assert len(list(tmp_path.iterdir())) == len(bu)


# ----------------------------------------------------------------------------- the command line

def _run(capsys, *argv):
    from graphmethods.cli import main

    code = main(["steps", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_cli_writes_each_format_and_refuses_to_overwrite(tmp_path, capsys):
    for fmt, name in (("pdf", "a.pdf"), ("html", "a.html"), ("animated-svg", "anim.svg")):
        code, out, err = _run(capsys, "press", "wittenbauer", "--format", fmt, "--lang", "ru",
                              "--out", str(tmp_path / name))
        assert code == 0 and err == "" and (tmp_path / name).stat().st_size > 1000
        assert "8 steps" in out and "  8. " in out
    before = (tmp_path / "a.pdf").read_bytes()
    code, out, err = _run(capsys, "W1", "energy-indicator", "--out", str(tmp_path / "a.pdf"))
    assert code == 2 and len(err.strip().splitlines()) == 1 and "--force" in err
    assert (tmp_path / "a.pdf").read_bytes() == before
    code, _, _ = _run(capsys, "W1", "energy-indicator", "--out", str(tmp_path / "a.pdf"), "--force")
    assert code == 0 and (tmp_path / "a.pdf").read_bytes() != before


def test_cli_default_name_and_positions(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, _ = _run(capsys, "shaper", "velocity-plan", "--position", "3", "--format", "svg", "--page", "A4")
    assert code == 0
    frames = sorted(p.name for p in tmp_path.iterdir())
    assert frames[0] == "shaper_velocity_plan_en-01.svg" and len(frames) == 12
    assert "position 3" in (tmp_path / frames[-1]).read_text(encoding="utf-8")
    (tmp_path / "out").mkdir()
    code, out, _ = _run(capsys, "W2", "energy-indicator", "--format", "html", "--lang", "zh", "--out", "out")
    assert code == 0 and (tmp_path / "out" / "w2_energy_indicator_zh.html").is_file()


@pytest.mark.parametrize("argv,words", [
    (["nope", "velocity-plan"], "not a built-in problem"),
    (["W1", "velocity-plan"], "needs a linkage problem"),
    (["W2", "wittenbauer"], "masses and loads"),
    (["press", "plan"], "use one of velocity-plan"),
    (["press", "velocity-plan", "--position", "99"], "position 99"),
    (["press", "wittenbauer", "--position", "2"], "velocity, acceleration and force plans and Zhukovsky's lever only"),
    (["press", "acceleration-plan", "--position", "12"], "position 12"),
    (["four-bar", "kinematic-diagrams"], "no slider"),
    (["W1", "work-diagrams"], "needs moment curves"),
    (["press", "velocity-plan", "--page", "B5"], "use slide, A4"),
    (["press", "wittenbauer", "-m", "1"], "from 3 to 720"),
    (["W1", "energy-indicator", "--format", "animated-svg", "--seconds", "0"], "seconds per step"),
])
def test_cli_bad_input_is_one_line_and_exit_2_and_writes_nothing(tmp_path, capsys, argv, words):
    code, out, err = _run(capsys, *argv, "--out", str(tmp_path / "x.pdf"))
    assert code == 2
    assert len(err.strip().splitlines()) == 1 and words in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_cli_bad_format_exits_2(capsys):
    from graphmethods.cli import main

    with pytest.raises(SystemExit) as exc:
        main(["steps", "press", "velocity-plan", "--format", "gif"])
    assert exc.value.code == 2


def test_cli_missing_directory_leaves_nothing(tmp_path, capsys):
    code, _, err = _run(capsys, "W1", "energy-indicator", "--format", "svg", "--out", str(tmp_path / "no" / "w.svg"))
    assert code == 2 and "does not exist" in err and list(tmp_path.iterdir()) == []


def test_the_velocity_plan_matches_the_plan_records_in_every_step(built):
    """Each drawn vector's length × μ_v equals the velocity of the records (independent of the steps)."""
    bu = built("four-bar", "velocity-plan")
    plans = K._Linkage.of(S.resolve_case("four-bar")).plans
    k = K.fullest_position(plans)
    mu_v = bu.figure.scales()[0].per_mm
    for j in range(1, len(bu) + 1):
        rec = record(bu.scene_at(j))
        for name in ("A", "B", "S2", "S3"):
            gid = f"vector-p{plans.label(name)}"
            if gid in rec.group_ids():
                assert rec.vector_length_mm(gid) / bu.enlarged * mu_v == pytest.approx(float(plans.speed(name)[k]),
                                                                                       rel=2e-3)
    assert math.isfinite(mu_v) and np.isfinite(plans.speed("B")[k])
