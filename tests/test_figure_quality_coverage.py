"""The figure-quality test over what the other figure-quality modules did not measure (issue 26, lane coverage).

:mod:`tests.test_figure_quality` (A1 sheets at position 3, the A4 figures of linkages, cycles and cams),
:mod:`tests.test_figure_quality_a2`, :mod:`tests.test_figure_quality_dynamics` (flywheel, hyperbola, drive,
motion, build-ups) and :mod:`tests.test_figure_quality_worksheets` (worksheets, check overlays) measure the
figures as the API draws them for the built-in problems. An audit of every command's options found drawings
none of them measured; they are measured here by the same :func:`~graphmethods.sheets.engine.quality.measure`
and :func:`~graphmethods.sheets.engine.quality.faults`:

- **what the command line draws**, captured where it turns scenes into bytes
  (:func:`graphmethods.render.formats.to_bytes`): the flywheel alone as a rim or a disc, the hyperbola of
  ``--machine``, drives of five and seven masses, the motion figures of a start-up by a motor, a run-down
  by a brake and a drag moment, the plans of ``kinematics --phi-deg`` and of a dead centre, sheets signed
  with ``--student/--group/--sheet-no``, the force sheet at other positions and at an angle, the kinematic
  sheet with ``--plan-positions``;
- **figures of the API and the gallery** no module drew: the force figures (scheme, plans, Zhukovsky's lever),
  the equivalent-mass graph, J_e turned 90°, the velocity and acceleration plans of position 0, the gallery's
  figures drawn with options (position 2, the weights, kG·m units, a heavier scheme); the drawn linkages
  (``drawn-four-bar``, ``drawn-six-bar-triad``, ``drawn-slotted-lever``: every command takes them,
  ``graphmethods problems`` does not list them) and a cam with a flat-faced and a knife-edge follower;
- **build-ups** of ``graphmethods steps`` on the linkages the dynamics module leaves out, the cam's profile by
  inversion, and the build-up on an A4 and an A1 page (``--page``);
- **output formats**: every kind of drawing as DXF read back by ezdxf (audit clean, the eight layers, text
  heights of the format's lettering), PNG, and byte-identical SVG, PDF and DXF when drawn twice.

A case that still fails is listed in :data:`tests.figure_quality_known.KNOWN_COVERAGE` with its measured reason
and runs as ``xfail(strict=True)``.
"""

from __future__ import annotations

import contextlib
import functools
import io
import shlex

import pytest

from graphmethods.errors import InputError
from graphmethods.problems import builtin
from graphmethods.sheets.engine.quality import faults, measure

try:
    from figure_quality_known import KNOWN_COVERAGE
except ImportError:                                     # run from the repository root as a package
    from tests.figure_quality_known import KNOWN_COVERAGE

LANGS = ("en", "ru", "zh")
LINKAGES = tuple(p for p in builtin.names() if p not in builtin.CYCLES and p not in builtin.CAMS)
FOUR = ("press", "shaper", "six-bar-press", "engine", "two-slider")

# ----------------------------------------------------------------------------- what the command line draws

#: (id, command line): each command's drawings, every scene it renders measured
COMMANDS = [
    ("flywheel-rim-alone", "flywheel --areas=-50,550,-100,125,-500,25,-50 --n 600 --delta 1/300 --rim --figure f.svg"
                           " --lang en"),
    ("flywheel-disc-alone", "flywheel --areas=-50,550,-100,125,-500,25,-50 --n 600 --delta 1/300 --disc 0.75 "
                            "--figure f.svg --lang ru"),
    ("flywheel-machine-hyperbola", "flywheel --areas=-50,550,-100,125,-500,25,-50 --n 600 --machine ac-generator "
                                   "--hyperbola h.svg --lang zh"),
    ("flywheel-moments", 'flywheel --M-r "20000 + 9500*sin(2*phi) - 5700*cos(2*phi)" --n 120 --delta 0.05 --rim '
                         "--disc 2 --figure f.svg --hyperbola h.svg --lang ru"),
    ("flywheel-levels", "flywheel --levels 0 -50 500 400 525 25 50 0 --n 120 --delta 1/30 --rim --figure f.svg "
                        "--hyperbola h.svg --lang zh"),
    ("flywheel-J-e", "flywheel --areas=-50,550,-100,125,-500,25,-50 --n 600 --delta 1/300 --J-e 5 --rim 0.75 "
                     "--H-over-B 0.8 --figure f.svg --hyperbola h.svg --lang ru"),
    ("flywheel-small-bore", "flywheel --areas=-50,550,-100,125,-500,25,-50 --n 600 --delta 1/300 --rim 0.5 "
                            "--material steel --disc 0.5 --figure f.svg --lang zh"),
    ("drive-named", "drive --J 0.08,0.5,12 --u 6,2,1 --c 2000,40000 --c-u 6,1 --M 30,0,-160 "
                    "--names motor,gear,crank -o d.svg --lang zh"),
    ("drive-five-masses", "drive --J 0.02,0.08,0.5,3,12 --u 24,6,2,1.5,1 --c 900,2000,40000,60000 --c-u 24,6,2,1 "
                          "--names motor,clutch,gear,shaft,crank -o d.svg --lang en"),
    ("drive-five-masses-ru", "drive --J 0.02,0.08,0.5,3,12 --u 24,6,2,1.5,1 --c 900,2000,40000,60000 "
                             "--c-u 24,6,2,1 -o d.svg --lang ru"),
    ("drive-seven-masses", "drive --J 0.02,0.08,0.5,3,12,1,5 --u 24,6,2,1.5,1,1,1 "
                           "--c 900,2000,40000,60000,3000,70000 --c-u 24,6,2,1,1,1 -o d.svg --lang zh"),
    ("motion-start-up-dc", "motion W3 --omega0 0 --motor dc:M0=120,omega0=15 --until-steady -o m --lang ru"),
    ("motion-run-down", "motion W3 --omega0 10.47 --drive-off-at 0 --brake 20 --t-end 60 -o m --lang en"),
    ("motion-drag", 'motion W4 --omega0 10 --moment "-0.02*omega**2" --t-end 5 -o m --lang zh'),
    ("motion-W4", "motion W4 --turns 1 -o m --lang en"),
    ("motion-press-motor", "motion press --motor induction:P=15000,n=1440,n_sync=1500,lam=2.5 --phi0 180 "
                           "--until-steady -o m --lang en"),
    ("kinematics-angles", "kinematics press --phi-deg 30,100 --figures k --lang ru"),
    ("kinematics-triad-angle", "kinematics triad-six-bar --phi-deg 45 --figures k --lang zh"),
    ("kinematics-dead-centre", "kinematics whitworth --figures k --position 0 --lang en"),
    ("kinematic-sheet-signed", 'kinematics shaper --sheet k.svg --lang ru --student "Иванов И. И." --group МТ-31 '
                               "--sheet-no 1/3"),
    ("kinematic-sheet-plan-position-0", "kinematics two-slider --sheet k.svg --plan-positions 0 --lang en"),
    ("dynamic-sheet-signed-a2", "study press -o d.svg --page A2 --lang zh --student 张三 --group 机械1班 "
                                "--sheet-no 2/3"),
    ("force-sheet-signed", 'forces shaper --position 3 -o f.svg --lang en --student "J. Smith" --group ME-31 '
                           "--sheet-no 2/3"),
    ("force-sheet-position-0", "forces press --position 0 -o f.svg --lang en"),
    ("force-sheet-position-6", "forces press --position 6 -o f.svg --lang ru"),
    ("force-sheet-position-9", "forces shaper --position 9 -o f.svg --lang zh"),
    ("force-sheet-angle", "forces engine --phi-deg 100 -o f.svg --lang en"),
    ("force-sheet-a2-position-9", "forces six-bar-press --position 9 -o f.svg --page A2 --lang ru"),
    ("force-sheet-gravity", "forces press --position 3 --gravity -o f.svg --lang en"),
    ("force-sheet-24-positions", "forces press --position 5 --positions 24 -o f.svg --lang zh"),
    ("kinematic-sheet-8-positions", "kinematics press --sheet k.svg --positions 8 --lang en"),
    ("kinematics-figures-24-positions", "kinematics press --figures k --positions 24 --lang zh"),
    ("dynamic-sheet-8-positions", "study press -o d.svg --positions 8 --lang zh"),
    ("dynamic-sheet-36-positions", "study engine -o d.svg --positions 36 --lang en"),
]


def drawn_by(argv: str, tmp_path, monkeypatch) -> list:
    """The scenes ``graphmethods ARGV`` renders (nothing is written: the renderer is replaced by a recorder)."""
    from graphmethods import cli
    from graphmethods.render import formats
    from graphmethods.scene import Scene

    scenes: list = []

    def record(obj, suffix, **_):
        scenes.extend([obj] if isinstance(obj, Scene) else list(obj))
        return b""

    monkeypatch.setattr(formats, "to_bytes", record)
    monkeypatch.chdir(tmp_path)
    with contextlib.redirect_stdout(io.StringIO()):
        assert cli.main(shlex.split(argv)) == 0
    assert scenes, f"{argv} drew nothing"
    return scenes


def _xfail(request, key) -> None:
    if key in KNOWN_COVERAGE:
        request.applymarker(pytest.mark.xfail(strict=True, reason=KNOWN_COVERAGE[key]))


@pytest.mark.parametrize("case, argv", COMMANDS, ids=[c for c, _ in COMMANDS])
def test_every_drawing_of_the_command_line_meets_the_standard(case, argv, tmp_path, monkeypatch, request):
    _xfail(request, ("cli", case))
    found = {s.name: faults(measure(s)) for s in drawn_by(argv, tmp_path, monkeypatch)}
    assert {k: v for k, v in found.items() if v} == {}


# ----------------------------------------------------------------------------- figures of the API and gallery

FORCE_FIGURES = ("force_scheme", "force_plans", "zhukovsky_forces")
API = [(p, f, lang) for f in FORCE_FIGURES for p in LINKAGES for lang in LANGS if lang == "en" or p in FOUR]
API += [(p, f, lang) for f in ("equivalent_mass_graph", "inertia_turned") for p in LINKAGES for lang in LANGS
        if lang == "en" or p in FOUR]
API += [(p, f, "en") for f in ("velocity_plan_0", "acceleration_plan_0") for p in LINKAGES]


@functools.cache
def _study(name: str):
    from graphmethods.dynamics.study import Study

    return Study(builtin.case(name), positions=12)


def draw(problem: str, figure: str, lang: str):
    """A figure of the API, or None when the problem cannot have it (the refusal is tested elsewhere)."""
    try:
        if figure in FORCE_FIGURES:
            from graphmethods.sheets import forces

            return getattr(forces, figure)(builtin.case(problem), position=3, notation=lang)
        if figure == "equivalent_mass_graph":
            from graphmethods.sheets.translating_graph import equivalent_mass_graph

            return equivalent_mass_graph(_study(problem), notation=lang)
        if figure == "inertia_turned":
            from graphmethods.sheets.dynamics import inertia_graph

            return inertia_graph(_study(problem), turned=True, notation=lang)
        from graphmethods import sheets

        return getattr(sheets, figure.removesuffix("_0"))(_study(problem), 0, notation=lang)
    except InputError:
        return None


@pytest.mark.parametrize("problem, figure, lang", API, ids=[f"{p}-{f}-{lang}" for p, f, lang in API])
def test_every_figure_of_the_api_meets_the_standard(problem, figure, lang, request):
    _xfail(request, (problem, figure, lang))
    scene = draw(problem, figure, lang)
    if scene is None:
        return
    assert faults(measure(scene)) == []


# ----------------------------------------------------------------------------- the gallery's options


def _optioned() -> list[str]:
    """The gallery's figures drawn with options the other tests do not give (position 2, the weights, a heavier
    scheme, kG·m units, J_e turned, A2): every catalogue row with options but the A1 sheets of position 3."""
    from graphmethods.gallery.catalogue import CATALOGUE

    same = ({"page": "A1"}, {"position": 3, "page": "A1"})
    return [f.name for f in CATALOGUE if f.options and dict(f.options) not in same]


GALLERY = _optioned()


@pytest.mark.parametrize("name", GALLERY)
def test_every_gallery_figure_drawn_with_options_meets_the_standard(name, request):
    from graphmethods.cli import gallery

    _xfail(request, ("gallery", name))
    assert faults(measure(gallery.build(name))) == []


# ----------------------------------------------------------------------------- drawn linkages and cam followers

#: the linkages given as drawn (``graphmethods problems`` does not list them; every command takes them)
DRAWN = ("drawn-four-bar", "drawn-six-bar-triad", "drawn-slotted-lever")
DRAWN_CASES = [(p, "structure_diagram", lang) for p in DRAWN for lang in LANGS]
DRAWN_CASES += [(p, f, "en") for p in DRAWN for f in ("kinematic_scheme", "velocity_plan", "acceleration_plan")]
DRAWN_CASES += [(p, "kinematic_analysis_sheet", "ru") for p in DRAWN]
#: the built-in cams have a roller; a flat face and a knife edge draw otherwise (no combined diagram, faces)
FOLLOWERS = ("flat", "knife")
CAM_CASES = [(c, f, lang) for c in FOLLOWERS for f in ("cam_sheet", "cam_inversion") for lang in LANGS]
CAM_CASES += [(c, f, "en") for c in FOLLOWERS for f in ("cam_motion_diagrams", "cam_combined_diagram",
                                                         "cam_pressure_angle")]


@functools.cache
def follower_cam(contact: str):
    """The shaper's feed cam with a flat-faced (no offset) or a knife-edge follower."""
    import json

    from graphmethods.kinematics.cam.problem import cam_from_dict

    data = json.loads((builtin.DATA / "shaper_feed_cam.json").read_text(encoding="utf-8"))
    follower = dict(data["follower"], contact=contact)
    follower.pop("roller_radius")
    if contact == "flat":
        follower.pop("offset")
    return cam_from_dict(dict(data, follower=follower))


@pytest.mark.parametrize("problem, figure, lang", DRAWN_CASES, ids=[f"{p}-{f}-{lang}" for p, f, lang in DRAWN_CASES])
def test_every_drawn_linkage_figure_meets_the_standard(problem, figure, lang, request):
    from graphmethods import sheets
    from graphmethods.sheets.structure_diagram import structure_diagram

    _xfail(request, (problem, figure, lang))
    if figure == "structure_diagram":
        scene = structure_diagram(builtin.case(problem), notation=lang)
    elif figure == "kinematic_analysis_sheet":
        scene = sheets.kinematic_analysis_sheet(builtin.case(problem), notation=lang)
    else:
        scene = getattr(sheets, figure)(_study(problem), notation=lang)
    assert faults(measure(scene)) == []


@pytest.mark.parametrize("contact, figure, lang", CAM_CASES, ids=[f"{c}-{f}-{lang}" for c, f, lang in CAM_CASES])
def test_every_cam_figure_of_a_flat_or_knife_follower_meets_the_standard(contact, figure, lang):
    import importlib

    module = "cam_sheet" if figure in ("cam_sheet", "cam_inversion") else "cam_figures"
    try:
        scene = getattr(importlib.import_module(f"graphmethods.sheets.{module}"), figure)(follower_cam(contact),
                                                                                          notation=lang)
    except InputError:                                  # a flat face has no combined diagram
        assert contact == "flat" and figure == "cam_combined_diagram"
        return
    assert faults(measure(scene)) == []


def test_a_flat_followers_inversion_holds_its_faces_inside_the_drawing():
    """The flat faces were drawn outside the extent the scale was fitted to: on A4 they ran into the title block,
    and the A1 sheet's table printed s = −7,937·10⁻¹⁸ m at a dwell."""
    from graphmethods.render.recording import record
    from graphmethods.sheets.cam_sheet import cam_inversion, cam_sheet

    scene = cam_inversion(follower_cam("flat"), notation="ru")
    faces = [p for e in scene.elements if e.name.startswith("face-") for p in (e.start, e.end)]
    assert faces and max(y for _, y in faces) < scene.page.content_box()[3]      # above the title block
    texts = [c.data.text for c in record(cam_sheet(follower_cam("flat"), notation="ru")).calls if c.kind == "text"]
    assert not any("10⁻" in t for t in texts)


# ----------------------------------------------------------------------------- build-ups not measured elsewhere

OTHER = ("four-bar", "slotted-lever", "slotting-machine", "whitworth", "scotch-yoke", "triad-six-bar")
STEPS = [(p, f, "en", "slide") for p in OTHER
         for f in ("velocity-plan", "acceleration-plan", "force-plans", "zhukovsky-lever")]
STEPS += [("slotted-lever", "kinematic-scheme", "en", "slide")]
STEPS += [(p, "inversion", lang, "slide") for p in builtin.CAMS for lang in LANGS]
STEPS += [("press", f, "en", page) for f in ("velocity-plan", "wittenbauer") for page in ("A4", "A1")]


@pytest.mark.parametrize("problem, figure, lang, page", STEPS, ids=[f"{p}-{f}-{lang}-{pg}" for p, f, lang, pg in STEPS])
def test_every_build_up_meets_the_standard(problem, figure, lang, page, request):
    from graphmethods.sheets import steps

    _xfail(request, (problem, f"steps:{figure}@{page}", lang))
    try:
        bu = steps.build(problem, figure, notation=lang, page=page)
    except InputError:
        return
    assert faults(measure(bu.slide(len(bu)))) == []


# ----------------------------------------------------------------------------- the output formats

#: one drawing of each kind the toolkit draws: (kind, how to draw it)
KINDS = {
    "kinematic-sheet": lambda: _sheets().kinematic_analysis_sheet(builtin.case("press"), notation="ru"),
    "force-sheet": lambda: _sheets().force_analysis_sheet(_study("press"), position=3, notation="zh"),
    "dynamic-sheet-a2": lambda: _sheets().dynamic_analysis_sheet(_study("engine"), page="A2", notation="en"),
    "a4-figure": lambda: _sheets().velocity_plan(_study("shaper"), notation="zh"),
    "structure-diagram": lambda: _structure("triad-six-bar"),
    "cam-sheet": lambda: _cam_sheet("oscillating-cam"),
    "drive-scheme": lambda: _drawn("drive --J 0.08,0.5,12 --u 6,2,1 --c 2000,40000 --c-u 6,1 -o d.svg --lang ru"),
    "flywheel-design": lambda: _drawn("flywheel --areas=-50,550,-100,125,-500,25,-50 --n 600 --delta 1/300 "
                                      "--rim 0.75 --disc 0.75 --figure f.svg --lang ru"),
    "hyperbola": lambda: _drawn("flywheel --areas=-50,550,-100,125,-500,25,-50 --n 600 --machine ac-generator "
                                "--hyperbola h.svg --lang zh"),
    "motion": lambda: _drawn("motion W4 --turns 1 -o m --lang en"),
    "worksheet-key": lambda: _worksheet_key("wittenbauer"),
    "check-overlay": lambda: _overlay("press", "press_plan_mistakes.toml"),
    "slide": lambda: _slide("press", "velocity-plan"),
}


def _sheets():
    from graphmethods import sheets

    return sheets


def _structure(name: str):
    from graphmethods.sheets.structure_diagram import structure_diagram

    return structure_diagram(builtin.case(name), notation="ru")


def _cam_sheet(name: str):
    from graphmethods.sheets.cam_sheet import cam_sheet

    return cam_sheet(builtin.cam_problem(name), notation="zh")


def _worksheet_key(kind: str):
    from graphmethods.sheets import worksheets

    return worksheets.key_page(worksheets.variant(kind, seed=7, number=1), notation="ru")


def _overlay(problem: str, answers: str):
    from graphmethods.sheets.check import check

    return check(problem, builtin.DATA / "answers" / answers).overlay(notation="en")


def _slide(problem: str, figure: str):
    from graphmethods.sheets import steps

    bu = steps.build(problem, figure, notation="en")
    return bu.slide(len(bu))


def _drawn(argv: str):
    """The first scene a command draws (outside a test's fixtures: the renderer swapped for the call only)."""
    import tempfile

    mp = pytest.MonkeyPatch()
    try:
        with tempfile.TemporaryDirectory() as tmp:
            return drawn_by(argv, tmp, mp)[0]
    finally:
        mp.undo()


@functools.cache
def kind_scene(kind: str):
    return KINDS[kind]()


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_every_kind_of_drawing_as_dxf_reads_back_audited_on_its_layers_at_its_lettering(kind):
    """The DXF of each kind: ezdxf reads it and its audit finds no error, the eight layers are defined and the
    texts on TEXT, their heights the capital height of the format's lettering (sub- and superscripts at 0.7 of
    it; at least as many full-size texts as small ones)."""
    ezdxf = pytest.importorskip("ezdxf")
    from graphmethods.render import dxf, formats
    from graphmethods.scene.elements import CAP
    from graphmethods.sheets.engine.lettering import lettering

    scene = kind_scene(kind)
    doc = ezdxf.read(io.StringIO(formats.to_bytes(scene, ".dxf").decode("utf-8")))
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e.message) for e in auditor.errors][:5]
    assert {name for name, _, _ in dxf.LAYERS.values()} <= {layer.dxf.name for layer in doc.layers}
    texts = [e for e in doc.modelspace() if e.dxftype() == "TEXT"]
    assert texts and {e.dxf.layer for e in texts} == {"TEXT"}
    least = lettering(scene.page).minimum_mm
    heights = [float(e.dxf.height) for e in texts]
    assert min(heights) >= 0.7 * least * CAP - 1e-3, (kind, min(heights))
    small = sum(h < least * CAP - 1e-3 for h in heights)
    assert small <= len(heights) - small


@pytest.mark.parametrize("kind", ["a4-figure", "drive-scheme", "motion"])
def test_png_of_a_drawing_is_a_png_of_its_page(kind):
    from graphmethods.render import formats

    scene = kind_scene(kind)
    data = formats.to_bytes(scene, ".png", dpi=50)
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    w, h = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    pw, ph = scene.page.width_mm, scene.page.height_mm
    assert abs(w - pw / 25.4 * 50) <= 2 and abs(h - ph / 25.4 * 50) <= 2


@pytest.mark.parametrize("kind", ["structure-diagram", "cam-sheet", "drive-scheme", "flywheel-design", "hyperbola",
                                  "worksheet-key", "check-overlay", "motion"])
@pytest.mark.parametrize("suffix", [".svg", ".pdf", ".dxf"])
def test_the_same_drawing_twice_is_byte_identical(kind, suffix):
    """SVG, PDF and DXF of the kinds :mod:`tests.test_render_pdf` and :mod:`tests.test_render_dxf` do not draw
    twice: a second scene built anew from the same input gives the same bytes."""
    from graphmethods.render import formats

    first = formats.to_bytes(kind_scene(kind), suffix)
    again = formats.to_bytes(KINDS[kind](), suffix)
    assert first == again


@pytest.mark.parametrize("problem, drawing", [("press", "press_plan_mistakes.dxf"), ("W1", "w1_mistakes.dxf"),
                                              ("shaper-cam", "shaper_cam_mistakes.dxf")])
def test_the_check_over_a_students_dxf_reads_back_audited_on_its_layer_and_is_deterministic(problem, drawing):
    """``check P DRAWING.dxf -o film.dxf`` writes the student's DXF with the check added on the layer CHECK (not
    through the scene's renderer, so not drawn by the test of the kinds above): ezdxf's audit finds no error,
    the student's layers stay, the check's texts are lettered for the page (sub- and superscripts at 0.7),
    and the same check gives the same bytes."""
    ezdxf = pytest.importorskip("ezdxf")
    from graphmethods.scene.elements import CAP
    from graphmethods.sheets.check import cad, cam
    from graphmethods.sheets.engine.lettering import lettering

    path = builtin.DATA / "drawings" / drawing
    report = cam.check_drawing(problem, path) if cam.is_cam_problem(problem) else cad.check_drawing(problem, path)
    data = cad.overlay_dxf(report, notation="ru")
    assert data == cad.overlay_dxf(report, notation="ru")
    doc = ezdxf.read(io.StringIO(data.decode("utf-8")))
    assert not doc.audit().has_errors
    own = ezdxf.readfile(path)
    assert {layer.dxf.name for layer in own.layers} | {"CHECK"} <= {layer.dxf.name for layer in doc.layers}
    heights = [float(e.dxf.height) for e in doc.modelspace() if e.dxftype() == "TEXT" and e.dxf.layer == "CHECK"]
    least = lettering(report.page).minimum_mm
    assert heights and min(heights) >= 0.7 * least * CAP - 1e-3


# ----------------------------------------------------------------------------- worksheets of other seeds

#: variants of other seeds than the worksheet test's 7 that broke the standard: an eleven-column answers table
#: set at 2.4 mm (seed 3), the footer's two lines over each other (a seed of two digits), s₃ crossed (seed 11)
SEEDS = [("acceleration-plan", 3, 2, "en"), ("acceleration-plan", 11, 2, "ru"), ("acceleration-plan", 42, 1, "en"),
         ("indicator", 42, 3, "zh"), ("wittenbauer", 11, 1, "ru"), ("cam", 11, 2, "en")]


@pytest.mark.parametrize("kind, seed, number, lang", SEEDS, ids=[f"{k}-{s}-{n}-{lang}" for k, s, n, lang in SEEDS])
def test_worksheets_of_other_seeds_meet_the_standard(kind, seed, number, lang):
    from graphmethods.sheets import worksheets

    try:
        from test_figure_quality_worksheets import page_faults
    except ImportError:                                 # run from the repository root as a package
        from tests.test_figure_quality_worksheets import page_faults
    v = worksheets.variant(kind, seed=seed, number=number)
    assert page_faults(worksheets.student_page(v, notation=lang), key=False) == []
    assert page_faults(worksheets.key_page(v, notation=lang), key=True) == []
