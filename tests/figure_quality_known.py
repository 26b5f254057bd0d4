"""Figures that do not yet meet the drafting standard (issue 26): (problem, figure, language) -> what
fails (empty cells, smallest text, labels crossed, text over text, noise). Each runs as
xfail(strict=True) in tests/test_figure_quality.py; remove an entry when it passes."""

KNOWN: dict[tuple[str, str, str], str] = {
}

#: the dynamics figures and the lecture build-ups (tests/test_figure_quality_dynamics.py), the same way
KNOWN_DYNAMICS: dict[tuple[str, str, str], str] = {
    # the zh slides' short lines fill less of the lever's column; the lever stays at the convenient μ_l that fits
    ('engine', 'steps:force-plans', 'zh'): '52% empty',
    ('engine', 'steps:zhukovsky-lever', 'zh'): '51% empty',
    ('two-slider', 'steps:zhukovsky-lever', 'zh'): '56% empty',
}

#: the worksheet family (tests/test_figure_quality_worksheets.py): (subject, page, language) -> what fails;
#: subject "KIND:SEED:N" with page "student" or "key", or "PROBLEM ANSWERS-FILE" with page "overlay"
KNOWN_WORKSHEETS: dict[tuple[str, str, str], str] = {
}

#: the A2 sheets (tests/test_figure_quality_a2.py): (problem, sheet, language) -> what fails
KNOWN_A2: dict[tuple[str, str, str], str] = {
}

#: the drawings of tests/test_figure_quality_coverage.py: ("cli", case) for a command line's drawings,
#: (problem, figure, language) for a figure of the API, (problem, "steps:FIGURE@PAGE", language) for a build-up
KNOWN_COVERAGE: dict[tuple[str, str] | tuple[str, str, str], str] = {
    # the force sheet at an angle between positions
    ("cli", "force-sheet-angle"): "engine, φ = 100°, A1: 57% empty (no M_b(φ) over the cycle at an angle)",
    # the kinematic A1 sheet (lane review3): one plan position only
    ("cli", "kinematic-sheet-plan-position-0"): "two-slider, --plan-positions 0: 53% empty",
    # build-ups (lane slides3)
    ("scotch-yoke", "steps:zhukovsky-lever@slide", "en"): "51% empty",
    ("shaper-cam", "steps:inversion@slide", "en"): "66% empty",
    ("shaper-cam", "steps:inversion@slide", "ru"): "65% empty",
    ("shaper-cam", "steps:inversion@slide", "zh"): "70% empty",
    ("oscillating-cam", "steps:inversion@slide", "ru"): "52% empty",
    ("press", "steps:velocity-plan@A1", "en"): "91% empty; text at 2.8 mm (the A4 figure at 1 : 1 on an A1 page)",
    ("press", "steps:wittenbauer@A1", "en"): "87% empty; text at 2.8 mm (the A4 figure at 1 : 1 on an A1 page)",
}
