"""The blank answers file of a worksheet kind: what ``graphmethods check`` reads, ready to fill in.

``graphmethods worksheet`` writes one beside each class set (``KIND-answers.toml``). The student (or
the teacher, from the student's sheet) replaces each ``""`` or ``[]`` by what was measured or
written; a key left ``""`` or ``[]`` is not answered and not checked. The keys and units are those
of :data:`graphmethods.sheets.check.SCHEMA`.

>>> text = template("wittenbauer")
>>> "[energy_mass]" in text and 'kl_mm = ""' in text
True
"""

from __future__ import annotations

from graphmethods.errors import InputError

#: per kind: (section, [(key, comment)]) in the order a student works
KEYS: dict[str, tuple[tuple[str, tuple[tuple[str, str], ...]], ...]] = {
    "indicator": (
        ("energy_indicator", (
            ("mu_E", "J per mm: the energy scale you drew the indicator at (μ_E)"),
            ("step_mm", "mm between two arrows along the horizontal"),
            ("arrows_mm", "list: each arrow's length in mm, + up (gain), − down (loss), in order"))),
        ("results", (
            ("works_J", "list: the work of each interval in J, signed, in order"),
            ("delta_W_max", "J: ΔW_max = E_max − E_min"),
            ("omega_max_at", "the letter of the point of ω_max, e.g. \"b\""),
            ("omega_min_at", "the letter of the point of ω_min"),
            ("omega_m", "rad/s: the mean angular speed"),
            ("omega_max", "rad/s"),
            ("omega_min", "rad/s"),
            ("J_F", "kg·m²: the flywheel's moment of inertia"))),
    ),
    "step-moment": (
        ("moment_diagram", (
            ("mu_M", "N·m per mm: the moment scale (μ_M)"),
            ("mu_phi_deg", "degrees per mm: the angle scale (μ_φ); or mu_phi in rad per mm"),
            ("areas_mm2", "list: each area between M_d and M_r in mm², + above M_r, − below, in order"))),
        ("results", (
            ("M_d", "N·m: the driving moment from the work balance"),
            ("works_J", "list: the work of each interval in J, signed, in order"),
            ("delta_W_max", "J: ΔW_max = E_max − E_min"),
            ("omega_max_at", "where ω_max occurs: φ in degrees, or the point's letter"),
            ("omega_min_at", "where ω_min occurs: φ in degrees, or the point's letter"),
            ("omega_m", "rad/s: the mean angular speed"),
            ("omega_max", "rad/s"),
            ("omega_min", "rad/s"),
            ("J_F", "kg·m²: the flywheel's moment of inertia"))),
    ),
    "velocity-plan": (
        ("velocity_plan", (
            ("mu_v", "(m/s) per mm: the velocity scale of your plan (μ_v)"),
            ("pa_mm", "mm: the vector pa"),
            ("pb_mm", "mm: the vector pb"),
            ("ab_mm", "mm: the vector ab"),
            ("ps2_mm", "mm: the vector ps₂"))),
        ("results", (
            ("v_A", "m/s"),
            ("v_B", "m/s"),
            ("v_BA", "m/s"),
            ("v_S2", "m/s"),
            ("omega_2", "rad/s: the connecting rod's angular speed, magnitude"),
            ("omega_2_sense", "\"cw\" or \"ccw\""))),
    ),
    "acceleration-plan": (
        ("acceleration_plan", (
            ("mu_a", "(m/s²) per mm: the acceleration scale of your plan (μ_a)"),
            ("an_A_mm", "mm: a^n_A (only when ε₁ ≠ 0; else a_A is the whole vector πa)"),
            ("at_A_mm", "mm: a^τ_A = ε₁·OA (only when ε₁ ≠ 0)"),
            ("a_A_mm", "mm: πa"),
            ("an_BA_mm", "mm: a^n_BA (slider-crank)"),
            ("at_BA_mm", "mm: a^τ_BA (slider-crank)"),
            ("a_B_mm", "mm: πb"),
            ("a_S2_mm", "mm: πs₂ (slider-crank)"),
            ("ak_A3A2_mm", "mm: the Coriolis component a^k_A3A2 (slotted lever)"),
            ("an_A3O3_mm", "mm: a^n_A3O3 (slotted lever)"),
            ("ar_A3A2_mm", "mm: the relative component a^r_A3A2, along the slot (slotted lever)"),
            ("at_A3O3_mm", "mm: a^τ_A3O3 (slotted lever)"),
            ("a_A3_mm", "mm: πa₃ (slotted lever)"),
            ("a_S3_mm", "mm: πs₃ (slotted lever)"),
            ("epsilon_2", "rad/s²: ε of the connecting rod, magnitude (slider-crank)"),
            ("epsilon_2_sense", "\"cw\" or \"ccw\" (slider-crank)"),
            ("epsilon_3", "rad/s²: ε of the slotted lever, magnitude (slotted lever)"),
            ("epsilon_3_sense", "\"cw\" or \"ccw\" (slotted lever)"))),
    ),
    "cam": (
        ("cam", (
            ("mu_l", "m per mm: the length scale of your profile (μ_l)"),
            ("base_radius", "m: the base radius r_b of the profile"),
            ("pitch_base_radius", "m: the base radius r_0 of the pitch curve (roller)"),
            ("s_mm", "list: s_k in mm at the positions 0, 1, … of the table"),
            ("alpha_max_rise_deg", "degrees: the largest pressure angle of the rise"),
            ("alpha_max_return_deg", "degrees: the largest pressure angle of the return"))),
    ),
    "wittenbauer": (
        ("energy_mass", (
            ("mu_J", "kg·m² per mm: the inertia scale (μ_J)"),
            ("mu_T", "J per mm: the energy scale (μ_T)"),
            ("tan_psi_max", "tan ψ_max, computed"),
            ("tan_psi_min", "tan ψ_min, computed"),
            ("kl_mm", "mm: the segment kl cut by the two rays on the ΔT axis"),
            ("omega_max_at", "the position number where the ψ_max ray touches the curve"),
            ("omega_min_at", "the position number where the ψ_min ray touches the curve"))),
        ("results", (
            ("J_F", "kg·m²: the flywheel's moment of inertia"),)),
    ),
}

#: keys whose answer is a list (left blank as ``[]``)
LISTS = frozenset({"arrows_mm", "works_J", "areas_mm2", "s_mm"})


def template(kind: str, *, page: tuple[str, str] = ("A4", "portrait"), problem: str = "",
             seed: int | None = None, lang: str = "en") -> str:
    """The blank answers file of a worksheet kind, as TOML text with a comment on every key.

    Parameters
    ----------
    kind : str
        ``"indicator"``, ``"step-moment"``, ``"velocity-plan"``, ``"wittenbauer"`` or ``"acceleration-plan"``.
    page : (str, str)
        The sheet the student draws on (size, orientation); the worksheet's own page by default.
    problem : str
        The problem id to put in (e.g. ``"indicator:7:3"``); left blank for a class set.
    seed : int, optional
        The class set's seed, named in the comment that says which PROBLEM to check against.
    lang : {"en", "ru", "zh"}
        The language of the comments (the keys are the same in every language).

    Returns
    -------
    str
        TOML text that ``graphmethods check`` reads once its values are filled in.

    Examples
    --------
    >>> print(template("velocity-plan", lang="ru").splitlines()[0])
    # Ответы к заданию «velocity-plan»; скопируйте файл для каждого студента, заполните и запустите
    """
    if kind not in KEYS:
        raise InputError(f"no answers template for kind {kind!r}; kinds: {', '.join(KEYS)}")
    if lang not in ("en", "ru", "zh"):
        raise InputError(f"lang {lang!r}: give en, ru or zh")

    def say(key: str, **fill: str) -> str:
        return comment(key, lang).format(**fill)
    variant = f"{kind}:{'SEED' if seed is None else seed}:N"
    lines = [
        "# " + say("tpl_head", kind=kind),
        "#     graphmethods check PROBLEM THE-COPY.toml",
        "# " + say("tpl_problem", id=variant),
        "# " + say("tpl_file", kind=kind),
        "# " + say("tpl_fill"),
        "# " + say("tpl_blank"),
        f"problem = \"{problem}\"",
        "student = \"\"",
        "",
        "[page]".ljust(28) + "# " + say("tpl_page"),
        f"size = \"{page[0]}\"",
        f"orientation = \"{page[1]}\"",
    ]
    for section, keys in KEYS[kind]:
        lines += ["", f"[{section}]"]
        width = max(len(k) for k, _ in keys) + 5
        for key, english in keys:
            blank = "[]" if key in LISTS else '""'
            text = english if lang == "en" else comment(_COMMENT_KEYS.get((kind, key), f"tpl_{key}"), lang)
            lines.append(f"{key} = {blank}".ljust(width + 3) + f"  # {text}")
    return "\n".join(lines) + "\n"


#: the comments of keys that read differently per kind, or share a word with other keys
_COMMENT_KEYS = {**{(k, f"omega_{w}_at"): f"tpl_omega_{w}_at_{k}" for k in ("indicator", "step-moment", "wittenbauer")
                    for w in ("max", "min")},
                 **{(k, key): "tpl_rad_s" for k in KEYS for key in ("omega_max", "omega_min")},
                 **{(k, key): "tpl_m_s" for k in KEYS for key in ("v_A", "v_B", "v_BA", "v_S2")}}


def comment(key: str, lang: str) -> str:
    """A comment of the answers file in ``lang`` (the vocabulary's check family, plain text)."""
    from graphmethods.scene.notation import get

    return get(lang).word(f"check.{key}")
