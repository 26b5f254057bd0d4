"""Figures that do not yet meet the drafting standard (issue 26): (problem, figure, language) -> what
fails (empty cells, smallest text, labels crossed, text over text, noise). Each runs as
xfail(strict=True) in tests/test_figure_quality.py; remove an entry when it passes."""

KNOWN: dict[tuple[str, str, str], str] = {
    ('engine', 'force_analysis_sheet', 'en'): '61% empty',
    ('engine', 'force_analysis_sheet', 'ru'): '58% empty',
    ('engine', 'force_analysis_sheet', 'zh'): '62% empty',
    ('four-bar', 'force_analysis_sheet', 'en'): '60% empty',
    ('four-bar', 'force_analysis_sheet', 'ru'): '58% empty',
    ('four-bar', 'force_analysis_sheet', 'zh'): '63% empty',
    ('press', 'force_analysis_sheet', 'en'): '62% empty',
    ('press', 'force_analysis_sheet', 'ru'): '57% empty',
    ('press', 'force_analysis_sheet', 'zh'): '62% empty',
    ('scotch-yoke', 'force_analysis_sheet', 'en'): '69% empty',
    ('scotch-yoke', 'force_analysis_sheet', 'ru'): '65% empty',
    ('scotch-yoke', 'force_analysis_sheet', 'zh'): '69% empty',
    ('shaper', 'force_analysis_sheet', 'en'): '53% empty',
    ('shaper', 'force_analysis_sheet', 'ru'): '54% empty',
    ('shaper', 'force_analysis_sheet', 'zh'): '57% empty',
    ('six-bar-press', 'force_analysis_sheet', 'en'): '53% empty',
    ('six-bar-press', 'force_analysis_sheet', 'zh'): '54% empty',
    ('slotted-lever', 'force_analysis_sheet', 'en'): '61% empty',
    ('slotted-lever', 'force_analysis_sheet', 'ru'): '59% empty',
    ('slotted-lever', 'force_analysis_sheet', 'zh'): '63% empty',
    ('slotting-machine', 'force_analysis_sheet', 'en'): '56% empty',
    ('slotting-machine', 'force_analysis_sheet', 'ru'): '61% empty',
    ('slotting-machine', 'force_analysis_sheet', 'zh'): '58% empty',
    ('triad-six-bar', 'force_analysis_sheet', 'zh'): '52% empty',
    ('two-slider', 'force_analysis_sheet', 'en'): '59% empty',
    ('two-slider', 'force_analysis_sheet', 'ru'): '58% empty',
    ('two-slider', 'force_analysis_sheet', 'zh'): '62% empty',
    ('whitworth', 'force_analysis_sheet', 'en'): '54% empty',
    ('whitworth', 'force_analysis_sheet', 'ru'): '50.2% empty',
    ('whitworth', 'force_analysis_sheet', 'zh'): '56% empty',
}

#: the dynamics figures and the lecture build-ups (tests/test_figure_quality_dynamics.py), the same way
KNOWN_DYNAMICS: dict[tuple[str, str, str], str] = {
    ('W3', 'steps:energy-indicator', 'en'): '51% empty',
    ('W3', 'steps:energy-indicator', 'ru'): '53% empty',
    ('W3', 'steps:energy-indicator', 'zh'): '53% empty',
    ('slotting-machine', 'steps:energy-indicator', 'en'): '53% empty; text 3.08 mm',
    ('engine', 'steps:energy-indicator', 'en'): 'text 3.36 mm',
    ('engine', 'steps:energy-indicator', 'ru'): 'text 3.36 mm',
    ('engine', 'steps:energy-indicator', 'zh'): 'text 3.36 mm',
    ('W3', 'steps:work-diagrams', 'en'): 'text 2.60 mm',
    ('W3', 'steps:work-diagrams', 'ru'): 'text 2.60 mm',
    ('W3', 'steps:work-diagrams', 'zh'): 'text 2.60 mm',
    ('press', 'steps:work-diagrams', 'en'): 'text 2.86 mm; 2 crossed: 200, 400',
    ('press', 'steps:work-diagrams', 'ru'): 'text 2.86 mm; 2 crossed: 200, 400',
    ('press', 'steps:work-diagrams', 'zh'): 'text 2.60 mm',
    ('shaper', 'steps:work-diagrams', 'en'): 'text 2.86 mm',
    ('shaper', 'steps:work-diagrams', 'ru'): 'text 2.86 mm',
    ('shaper', 'steps:work-diagrams', 'zh'): 'text 2.86 mm',
    ('four-bar', 'steps:work-diagrams', 'en'): 'text 2.86 mm; 1 crossed: 10',
    ('slotted-lever', 'steps:work-diagrams', 'en'): 'text 2.60 mm',
    ('six-bar-press', 'steps:work-diagrams', 'en'): 'text 2.86 mm; 1 crossed: 500',
    ('six-bar-press', 'steps:work-diagrams', 'ru'): 'text 2.86 mm; 1 crossed: 500',
    ('six-bar-press', 'steps:work-diagrams', 'zh'): 'text 2.86 mm',
    ('slotting-machine', 'steps:work-diagrams', 'en'): 'text 2.86 mm; 1 crossed: 200',
    ('whitworth', 'steps:work-diagrams', 'en'): 'text 2.86 mm',
    ('two-slider', 'steps:work-diagrams', 'en'): 'text 2.86 mm',
    ('two-slider', 'steps:work-diagrams', 'ru'): 'text 2.86 mm',
    ('two-slider', 'steps:work-diagrams', 'zh'): 'text 2.86 mm',
    ('engine', 'steps:work-diagrams', 'en'): 'text 2.86 mm; 1 crossed: H = 10 mm',
    ('engine', 'steps:work-diagrams', 'ru'): 'text 2.86 mm; 1 crossed: H = 10 мм',
    ('engine', 'steps:work-diagrams', 'zh'): 'text 2.60 mm',
    ('scotch-yoke', 'steps:work-diagrams', 'en'): 'text 2.86 mm',
    ('triad-six-bar', 'steps:work-diagrams', 'en'): 'text 2.86 mm; 1 crossed: 20',
    ('shaper', 'steps:wittenbauer', 'en'): 'text 3.08 mm',
    ('shaper', 'steps:wittenbauer', 'ru'): 'text 3.08 mm',
    ('shaper', 'steps:wittenbauer', 'zh'): 'text 3.08 mm',
    ('six-bar-press', 'steps:wittenbauer', 'en'): '1 crossed: 1',
    ('six-bar-press', 'steps:wittenbauer', 'ru'): '1 crossed: 1',
    ('six-bar-press', 'steps:wittenbauer', 'zh'): '1 crossed: 1',
    ('slotting-machine', 'steps:wittenbauer', 'en'): 'text 3.36 mm',
    ('engine', 'steps:wittenbauer', 'en'): 'text 3.36 mm',
    ('engine', 'steps:wittenbauer', 'ru'): 'text 3.36 mm',
    ('engine', 'steps:wittenbauer', 'zh'): 'text 3.36 mm',
    ('two-slider', 'steps:kinematic-scheme', 'en'): '55% empty',
}

#: the worksheet family (tests/test_figure_quality_worksheets.py): (subject, page, language) -> what fails;
#: subject "KIND:SEED:N" with page "student" or "key", or "PROBLEM ANSWERS-FILE" with page "overlay"
KNOWN_WORKSHEETS: dict[tuple[str, str, str], str] = {
}

#: the A2 sheets (tests/test_figure_quality_a2.py): (problem, sheet, language) -> what fails
KNOWN_A2: dict[tuple[str, str, str], str] = {
}
