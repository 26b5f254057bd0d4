"""Figures that do not yet meet the drafting standard (issue 26): (problem, figure, language) -> what
fails (empty cells, smallest text, labels crossed, text over text, noise). Each runs as
xfail(strict=True) in tests/test_figure_quality.py; remove an entry when it passes."""

KNOWN: dict[tuple[str, str, str], str] = {
    ('engine', 'force_analysis_sheet', 'en'): '65% empty',
    ('engine', 'force_analysis_sheet', 'ru'): '62% empty',
    ('engine', 'force_analysis_sheet', 'zh'): '67% empty',
    ('four-bar', 'force_analysis_sheet', 'en'): '65% empty',
    ('four-bar', 'force_analysis_sheet', 'ru'): '63% empty',
    ('four-bar', 'force_analysis_sheet', 'zh'): '67% empty',
    ('press', 'force_analysis_sheet', 'en'): '65% empty',
    ('press', 'force_analysis_sheet', 'ru'): '63% empty',
    ('press', 'force_analysis_sheet', 'zh'): '68% empty',
    ('scotch-yoke', 'force_analysis_sheet', 'en'): '72% empty',
    ('scotch-yoke', 'force_analysis_sheet', 'ru'): '68% empty',
    ('scotch-yoke', 'force_analysis_sheet', 'zh'): '73% empty',
    ('shaper', 'force_analysis_sheet', 'en'): '64% empty, 1 crossed',
    ('shaper', 'force_analysis_sheet', 'ru'): '68% empty',
    ('shaper', 'force_analysis_sheet', 'zh'): '66% empty, 1 crossed',
    ('six-bar-press', 'force_analysis_sheet', 'en'): '60% empty',
    ('six-bar-press', 'force_analysis_sheet', 'ru'): '57% empty',
    ('six-bar-press', 'force_analysis_sheet', 'zh'): '61% empty',
    ('slotted-lever', 'force_analysis_sheet', 'en'): '68% empty',
    ('slotted-lever', 'force_analysis_sheet', 'ru'): '63% empty',
    ('slotted-lever', 'force_analysis_sheet', 'zh'): '67% empty',
    ('slotting-machine', 'force_analysis_sheet', 'en'): '62% empty, 1 crossed',
    ('slotting-machine', 'force_analysis_sheet', 'ru'): '66% empty',
    ('slotting-machine', 'force_analysis_sheet', 'zh'): '63% empty, 1 crossed',
    ('triad-six-bar', 'force_analysis_sheet', 'en'): '70% empty',
    ('triad-six-bar', 'force_analysis_sheet', 'ru'): '68% empty',
    ('triad-six-bar', 'force_analysis_sheet', 'zh'): '71% empty',
    ('two-slider', 'force_analysis_sheet', 'en'): '65% empty',
    ('two-slider', 'force_analysis_sheet', 'ru'): '69% empty',
    ('two-slider', 'force_analysis_sheet', 'zh'): '67% empty',
    ('whitworth', 'force_analysis_sheet', 'en'): '61% empty',
    ('whitworth', 'force_analysis_sheet', 'ru'): '58% empty, 1 crossed',
    ('whitworth', 'force_analysis_sheet', 'zh'): '63% empty',
    ('triad-six-bar', 'acceleration_plan', 'en'): "the Assur-point equation over the ε column; nDK3 crossed",
    ('triad-six-bar', 'acceleration_plan', 'ru'): "the Assur-point equation over the ε column; nDK3 crossed",
    ('triad-six-bar', 'acceleration_plan', 'zh'): "the Assur-point equation over the ε column; nDK3 crossed",
    ('scotch-yoke', 'structure_diagram', 'en'): "the yoke (link 3) is not drawn, its number lands on the block",
    ('scotch-yoke', 'structure_diagram', 'ru'): "the yoke (link 3) is not drawn, its number lands on the block",
    ('scotch-yoke', 'structure_diagram', 'zh'): "the yoke (link 3) is not drawn, its number lands on the block",
}

#: the worksheet family (tests/test_figure_quality_worksheets.py): (subject, page, language) -> what fails;
#: subject "KIND:SEED:N" with page "student" or "key", or "PROBLEM ANSWERS-FILE" with page "overlay"
KNOWN_WORKSHEETS: dict[tuple[str, str, str], str] = {
}
