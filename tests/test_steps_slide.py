"""Slides for a projector (issue 20): the figure laid out on a design page 1/z of the slide and drawn
z : 1, so its text is large enough to read when projected; nothing overlaps or leaves the frame."""

import re

import pytest

from graphmethods.errors import InputError
from graphmethods.kinematics import read_case
from graphmethods.problems import builtin
from graphmethods.render.recording import record
from graphmethods.scene.elements import label_bbox
from graphmethods.scene.steps import PROJECTOR_TEXT
from graphmethods.sheets import steps as S
from graphmethods.sheets.kinematics import _Linkage, fullest_position

BOUND = PROJECTOR_TEXT * 190.5            # 1/40 of the slide's height: 4.76 mm (13.5 pt)
#: the figures whose own layout overlaps already at 1 : 1 (formulas on the comparison tables): not enlarged
#: (the others are enlarged as far as they hold, up to 1/40; the press's velocity plan, energy
#: indicator and force plans reach 1.5…1.8 : 1, the shaper's acceleration plan none)
DENSE = {"kinematic-diagrams", "work-diagrams"}
FIGURES = [("press", "velocity-plan", "en"), ("press", "velocity-plan", "ru"), ("shaper", "velocity-plan", "zh"),
           ("press", "acceleration-plan", "en"), ("shaper", "acceleration-plan", "ru"),
           ("W1", "energy-indicator", "zh"), ("press", "wittenbauer", "ru"), ("press", "zhukovsky-load", "en"),
           ("shaper", "kinematic-scheme", "en"), ("press", "force-plans", "zh"), ("shaper", "force-plans", "ru"),
           ("press", "zhukovsky-lever", "en"), ("four-bar", "zhukovsky-lever", "ru"),
           ("press", "kinematic-diagrams", "en"), ("W3", "work-diagrams", "en")]


@pytest.fixture(scope="module")
def slides():
    cache = {}

    def get(case, figure, lang):
        if (case, figure, lang) not in cache:
            cache[case, figure, lang] = S.build(case, figure, notation=lang)
        return cache[case, figure, lang]
    return get


def _fits(case, figure, lang, z):
    """Does the figure hold on the slide's design page at z : 1: it builds, nothing overlaps or leaves
    the page, and its construction is drawn at least KEEP_SIZE of its size on the 1 : 1 slide?"""
    try:
        bu = S.build(case, figure, notation=lang, page=S.design_slide(z))
    except InputError:
        return False
    ref = {(sc.symbol, sc.unit): sc.per_mm for sc in S.build(case, figure, notation=lang,
                                                              page=S.SLIDE_PAGE).figure.scales()}
    return not S.layout_faults(bu) and all(z / sc.per_mm >= S.KEEP_SIZE / ref[sc.symbol, sc.unit]
                                           for sc in bu.figure.scales() if sc.unit not in ("rad", "°"))


@pytest.mark.parametrize("case,figure,lang", FIGURES, ids=["-".join(f) for f in FIGURES])
def test_slide_text_is_as_large_as_the_layout_allows_up_to_a_40th_of_the_height(slides, case, figure, lang):
    bu = slides(case, figure, lang)
    assert bu.figure.page.size == "SLIDE" and (bu.figure.page.width_mm, bu.figure.page.height_mm) == (338.7, 190.5)
    smallest = min(c.data.size_mm for k in range(1, len(bu) + 1) for c in record(bu.slide(k)).calls
                   if c.kind == "text")
    z = bu.enlarged
    assert smallest == pytest.approx(min(S.smallest_text_mm(bu), smallest), abs=1e-9)
    if figure in DENSE and S.layout_faults(S.build(case, figure, notation=lang, page=S.SLIDE_PAGE)):
        assert z == 1.0                       # a dense figure that does not hold even at 1 : 1 stays at 1 : 1
        return
    if smallest < BOUND - 1e-9:
        # too dense for 1/40: the next larger enlargement does not hold
        larger = [w for w in S.ZOOMS if w > z + 1e-9]
        assert larger and not _fits(case, figure, lang, larger[-1])
    else:
        # and no larger than needed: the next smaller one would make the text too small
        smaller = [w for w in S.ZOOMS if w < z - 1e-9]
        assert smallest / z * smaller[0] < BOUND


@pytest.mark.parametrize("case,figure,lang", FIGURES, ids=["-".join(f) for f in FIGURES])
def test_nothing_overlaps_or_leaves_the_frame_and_captions_stay_in_their_box(slides, case, figure, lang):
    bu = slides(case, figure, lang)
    x0, y0, x1, y1 = bu.figure.page.inner_box()
    cx0, cy0, cx1, cy1 = bu.caption_box
    assert x0 <= cx0 and cx1 <= x1 and cy1 <= y1 + 1e-9          # the caption band is inside the slide's margins
    if figure not in DENSE:
        assert S.layout_faults(bu) == []
    for k in range(1, len(bu) + 1):
        rec = record(bu.slide(k))
        lines = [c.data for c in rec.calls if c.kind == "text" and "step-caption" in c.groups]
        assert lines and all(lab.size_mm >= BOUND for lab in lines)
        for lab in lines:
            b = label_bbox(lab)
            assert cx0 <= b[0] and b[2] <= cx1 and cy0 <= b[1] and b[3] <= cy1, (k, lab.text)
        for c in rec.calls:
            if c.kind in ("path", "polygon") and "step-caption" not in c.groups:
                points = c.data[0] if c.kind == "path" else c.data
                assert all(x0 - 0.05 <= x <= x1 + 0.05 and y0 - 0.05 <= y <= cy0 + 0.05 for x, y in points)


def test_the_slide_says_its_enlargement_and_its_scales_are_those_at_one_to_one(slides):
    """A vector drawn on the enlarged slide is z × value/μ long, μ as the figure writes it (checked
    against the kinematics core's v_B), and the slide says "drawn z : 1"."""
    bu = slides("press", "velocity-plan", "en")
    z = bu.enlarged
    note = next(t for t in record(bu.slide(1)).texts("enlarged"))
    assert re.search(rf"drawn {z:g} : 1", note)
    case = read_case(builtin.DATA / builtin.LINKAGES["press"])
    plans = _Linkage.of(case).plans
    k = fullest_position(plans)
    mu_v = bu.figure.scales()[0].per_mm
    v_B = float(plans.speed("B")[k])
    assert record(bu.figure).vector_length_mm("vector-pb") == pytest.approx(z * v_B / mu_v, rel=2e-3)


def test_sheet_pages_are_not_enlarged(slides):
    bu = S.build("press", "force-plans", page="A3")
    assert bu.enlarged == 1.0 and bu.figure.page.size == "A3" and bu.figure.page.frame


@pytest.mark.parametrize("case,lang", [("press", "en"), ("shaper", "ru")])
def test_any_figure_on_a_projector_slide(case, lang):
    """A figure function's figure (here the force scheme) on a slide for a projector: the same
    enlargement rule, nothing out of the slide's margins, and μ as at 1 : 1 (a force's drawn length
    is z·|F|/μ_F, |F| from the force analysis)."""
    from graphmethods.dynamics.forces import case_forces
    from graphmethods.sheets.forces import force_scheme

    c = S.resolve_case(case)
    s = S.projector_figure(lambda pg: force_scheme(c, 3, page=pg, title_block=False, notation=lang))
    assert s.page.size == "SLIDE" and (s.page.width_mm, s.page.height_mm) == (338.7, 190.5)
    note = [n for n in s.notes if n.startswith("drawn")]
    z = float(re.match(r"drawn ([\d.]+) : 1", note[0]).group(1)) if note else 1.0
    x0, y0, x1, y1 = s.page.inner_box()
    rec = record(s)
    for c_ in rec.calls:
        if c_.kind == "text":
            b = label_bbox(c_.data)
            # the last line's descenders may reach CAPTION_GAP_MM into the bottom margin (4 mm)
            assert x0 - 0.05 <= b[0] and b[2] <= x1 + 0.05 and y0 - 0.05 <= b[1] and b[3] <= y1 + S.CAPTION_GAP_MM
    fa = case_forces(c, m=12)
    mu_F = next(sc for sc in s.scales() if "F" in sc.symbol).per_mm
    first = next(f for fs in fa.applied.values() for f in fs if abs(f.F[3]) / mu_F >= 0.3)
    assert rec.vector_length_mm("force-0") == pytest.approx(z * abs(first.F[3]) / mu_F, rel=2e-3)
