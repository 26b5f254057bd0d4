"""``graphmethods kinematics CASE.json``: positions and velocities of a linkage problem file.

CASE is a problem file or a built-in problem's name (``graphmethods kinematics shaper``).

Prints, per position 0…M (position M = position 0), the crank angle and the velocities at the
mean crank speed n_rpm of the file: for the slider-crank press format at least ``phi_deg``
(crank angle from +x, degrees), ``v_B`` (m/s, signed along +x), ``omega_2`` (rod, rad/s,
counterclockwise +) and ``v_S2`` (m/s, magnitude). Sliders' velocities are signed along +x of
their guide, other points' are magnitudes; ``omega_k`` uses the textbook link numbers (crank
= 1) listed under ``links``. Plain text table by default, one JSON object with ``--json``.

``--figures DIR`` also writes the figures of the problem into DIR (created if missing): the
kinematic scheme in M positions, the velocity plans of all positions, one large velocity plan
(``--plan-position K``; by default the working-stroke position whose plan is the fullest figure)
and the table of velocities (drawn, and as Markdown), the acceleration plans of all positions,
the large acceleration plan of the same position and the table of accelerations (at
``--epsilon-1``), in ``--lang en|ru|zh`` and ``--format
svg|pdf|png|dxf``. Existing files are never replaced without ``--force``; every figure is built
before the first file is written, so an error writes nothing.

    graphmethods kinematics press.json --figures out --lang ru --format pdf

``--sheet FILE.svg|.pdf|.dxf`` writes the A1 kinematic-analysis sheet, the course
project's first sheet, in ``--lang``: the scheme in M positions, the velocity plans, the
acceleration plans of ``--plan-positions K[,L,...]`` (default: a working-stroke and a return-stroke
position) and the slider's kinematic diagrams when there is a slider
(:func:`graphmethods.sheets.kinematic_analysis_sheet.kinematic_analysis_sheet`), at the file's mean
speed with ε₁ = 0. An existing file is kept unless ``--force``; on any error nothing is written.

    graphmethods kinematics shaper --sheet shaper-kinematics.pdf --plan-positions 2,9
"""

from __future__ import annotations

import math
from typing import Any

from graphmethods.cli import _sheet
from graphmethods.units import MAX_POSITIONS, check_finite, count, json_text

#: Most positions the figures draw: the velocity table keeps rows at least 4 mm high on its page.
FIGURES_MAX_POSITIONS = 30


def builtin_names() -> str:
    """The built-in linkages' names, for the help texts (from the registry, never typed)."""
    from graphmethods.problems.builtin import LINKAGES

    return ", ".join(LINKAGES)


def add_linkage_case(p) -> None:
    """The positional CASE of a linkage command: a problem file, ``-`` (standard input) or a built-in name."""
    p.add_argument("case", metavar="CASE", help="problem file (.json; - reads it from standard input) or built-in "
                   "linkage: " + builtin_names())


def add_speed(p) -> None:
    """``--n`` or ``--omega``: the crank's mean speed, the same two names on every command."""
    from graphmethods.cli._parser import number

    speed = p.add_mutually_exclusive_group()
    speed.add_argument("--n", type=number, default=None, metavar="N",
                       help="mean crank speed, rev/min (default: the file's n_rpm)")
    speed.add_argument("--omega", type=number, default=None, metavar="W",
                       help="mean crank speed, rad/s (instead of --n)")


def speed_rpm(args) -> float | None:
    """The speed ``--n`` or ``--omega`` gives, in rev/min (None: the file's), refused unless positive."""
    from graphmethods.errors import InputError
    from graphmethods.units import n_from_omega

    if args.n is not None and not args.n > 0:
        raise InputError(f"--n must be a positive speed in rev/min, got {args.n:g}")
    if getattr(args, "omega", None) is not None:
        if not args.omega > 0:
            raise InputError(f"--omega must be a positive speed in rad/s, got {args.omega:g}")
        return n_from_omega(args.omega)
    return args.n


def add_parser(sub) -> None:
    from graphmethods.cli._parser import integer, number, numbers

    p = sub.add_parser(
        "kinematics", help="positions, velocities and accelerations of a linkage (plans, figures, the A1 sheet)",
        description="Positions 0…M of a linkage (a problem file, or a built-in linkage: " + builtin_names()
                    + ") and its velocities and accelerations at the file's mean crank speed, from the plans.")
    add_linkage_case(p)
    p.add_argument("--positions", "-m", type=integer, default=12, metavar="M",
                   help="number of equal crank steps per turn (default 12; positions 0…M)")
    p.add_argument("--position", type=integer, default=None, metavar="K",
                   help="print (and with --figures draw the plans of) position K of 0…M only")
    p.add_argument("--phi-deg", type=numbers, default=None, metavar="A[,B,...]",
                   help="analyse at these crank angles (degrees from +x, counterclockwise) instead of M positions; "
                        "with --figures, the plans at each angle")
    p.add_argument("--epsilon-1", type=number, default=0.0, metavar="E",
                   help="crank angular acceleration, rad/s², + when the crank speeds up (default 0)")
    add_speed(p)
    p.add_argument("--json", action="store_true", help="print one JSON object whose 'positions' is the list")
    p.add_argument("--figures", metavar="DIR", default=None,
                   help="also write the figures (scheme, velocity plans, one large plan, velocity table, the same "
                        "for accelerations) into DIR; with --phi-deg, the scheme and the plans at those angles")
    p.add_argument("--lang", choices=("en", "ru", "zh"), default="en", help="notation of the figures (default en)")
    p.add_argument("--format", choices=("svg", "pdf", "png", "dxf"), default=None, dest="fig_format",
                   help="file format of the figures (default svg; dxf: 1 unit = 1 mm, layers by role; the table is "
                        "also written as Markdown), and of the sheet when it goes to standard output (--sheet -)")
    p.add_argument("--plan-position", type=integer, default=None, metavar="K",
                   help="the position drawn as one large velocity plan (default: --position, else the fullest plan "
                        "of the working stroke)")
    p.add_argument("--sheet", metavar="FILE.svg|.pdf|.png|.dxf|-", default=None,
                   help="also write the kinematic-analysis sheet (scheme, velocity plans, acceleration plans, the "
                        "slider's diagrams; scale-true); - writes it to standard output in --format, and nothing else")
    p.add_argument("--page", type=_a1_only, default="A1", metavar="{A1}",
                   help="sheet size: A1 only (the sheet's four parts need it)")
    p.add_argument("--plan-positions", default=None, metavar="K[,L,...]",
                   help="the positions whose acceleration plans the sheet draws (1 to 4, as many as fit beside the "
                        "sheet's other parts: a message says how many a linkage has room for; default: a "
                        "working-stroke and a return-stroke position)")
    p.add_argument("--force", action="store_true", help="overwrite existing figure files")
    _sheet.add_signature_options(p)
    p.set_defaults(func=run)


def _a1_only(page: str) -> str:
    """``--page``: A1, the one page the kinematic-analysis sheet is drawn on; any other refused with the reason
    (argparse writes it as one line, exit 2)."""
    import argparse

    if page.upper() != "A1":
        raise argparse.ArgumentTypeError(f"{page!r}: the kinematic-analysis sheet is drawn on A1 only (its four "
                                         f"parts, scheme, velocity plans, acceleration plans and the slider's "
                                         f"diagrams, need it)")
    return "A1"


def _clean(x: float) -> float:
    x = float(x)
    return 0.0 if x == 0.0 else x


def _phi_list(text: str) -> list[float]:
    """Crank angles from ``--phi-deg A[,B,...]`` (degrees)."""
    from graphmethods.errors import InputError

    out = []
    for part in str(text).split(","):
        try:
            x = float(part)
        except ValueError:
            raise InputError(f"--phi-deg: {part.strip()!r} is not an angle in degrees; "
                             "give e.g. 30 or 0,90,180") from None
        if not math.isfinite(x):
            raise InputError(f"--phi-deg: {part.strip()!r} must be a finite angle in degrees")
        out.append(x)
    return out


def _position_list(text: str) -> list[int]:
    """Position numbers from ``--plan-positions K[,L,...]``."""
    from graphmethods.errors import InputError

    out = []
    for part in str(text).split(","):
        try:
            out.append(int(part))
        except ValueError:
            raise InputError(f"--plan-positions: {part.strip()!r} is not a position number; give e.g. 2 or 2,9"
                             ) from None
    return out


def _state(case, motion, i: int) -> tuple[dict, dict]:
    """``points`` (xy, v, a of every moving point) and ``links`` (ω, ε by textbook number) at position i."""
    fixed = set(case.linkage.ground)
    points = {}
    for name in motion.points:
        if name in fixed or name.startswith("_"):       # "_": the drawn form's hidden points
            continue
        z, v, a = motion.z[name][i], motion.v_[name][i], motion.a_[name][i]
        points[name] = {"xy": [_clean(z.real), _clean(z.imag)], "v": [_clean(v.real), _clean(v.imag)],
                        "a": [_clean(a.real), _clean(a.imag)]}
    links = {k: {"omega": _clean(motion.omega[k][i]), "epsilon": _clean(motion.epsilon[k][i])}
             for k in case.linkage.links}
    return points, links


def table(case, m: int | None = 12, *, phi_deg=None, epsilon_1: float = 0.0, n_rpm: float | None = None) -> dict:
    """The result as a JSON-ready dict (also used by the text output).

    Per position: the flat keys (``phi_deg``, ``v_B``, ``omega_2``, ...) from the velocity plans, and
    the whole state from the kinematics core: ``points`` (xy, v, a of every moving point, m, m/s,
    m/s²) and ``links`` (ω, ε of every link by textbook number, rad/s, rad/s²), at the mean crank
    speed (or ``n_rpm``) with the crank's angular acceleration ``epsilon_1``; at positions 0…m, or at
    the crank angles ``phi_deg`` (degrees).
    """
    import numpy as np

    from graphmethods.units import omega_from_n

    mech = case.mechanism
    omega_1 = case.omega_m if n_rpm is None else omega_from_n(n_rpm)
    if phi_deg is not None:
        phi = np.radians(np.asarray(phi_deg, dtype=float))
        pos = mech.positions(phi=phi)
        motion = case.linkage.motion(phi=phi, omega_1=omega_1, epsilon_1=epsilon_1)
    else:
        pos = mech.positions(m=m)
        motion = case.linkage.motion(m=m, omega_1=omega_1, epsilon_1=epsilon_1)
    plan = mech.velocity_plans(pos, omega_1=omega_1)
    st = pos.strokes
    cols: dict[str, np.ndarray] = {
        "position": pos.index if pos.index is not None else np.full(pos.n, -1),
        "phi_deg": pos.phi_deg if phi_deg is None else np.mod(np.asarray(phi_deg, dtype=float), 360.0),
        "phi_from_start_deg": np.degrees(pos.phi_from_start)}
    units = {"phi_deg": "°", "phi_from_start_deg": "°"}
    if pos.s is not None:
        slider = next(iter(mech.guides))
        cols[f"s_{slider}"] = pos.s
        units[f"s_{slider}"] = "m"
    if pos.psi is not None:
        cols["psi_deg"] = np.degrees(pos.psi)
        units["psi_deg"] = "°"
    fixed = {c.name for c in plan.constructions.values() if c.method == "pole"}
    for name in plan.vectors:
        if name in fixed or name.startswith("_"):
            continue
        key = f"v_{name}"
        cols[key] = plan.v_along_guide(name) if name in mech.guides else plan.speed(name)
        units[key] = "m/s"
        if case.kind == "slider_crank" and name == "B":
            cols["v_BA"] = np.hypot(*(plan.v_rel("B", "A").T))
            units["v_BA"] = "m/s"
        for pin, co, pivot, block, _ in getattr(mech, "slotted_links", ()):
            if name == co and case.kind in ("slotted_lever", "shaper"):
                u = pos.xy(pin) - pos.xy(pivot)
                u = u / np.hypot(u[:, 0], u[:, 1])[:, None]
                rel = plan.v_rel(co, pin)
                cols[f"v_{co}{pin}{block}"] = rel[:, 0] * u[:, 0] + rel[:, 1] * u[:, 1]
                units[f"v_{co}{pin}{block}"] = "m/s"
    for k, link in mech.link_numbers.items():
        if k >= 2:
            cols[f"omega_{k}"] = plan.omega(link)
            units[f"omega_{k}"] = "rad/s"
    for name in motion.points:            # accelerations: sliders signed along their guide, others |a|
        if name in set(case.linkage.ground) or name in fixed:
            continue
        a = np.asarray(motion.a_[name])
        guide = mech.guides.get(name)
        cols[f"a_{name}"] = (a.real * guide[0] + a.imag * guide[1]) if guide is not None else np.abs(a)
        units[f"a_{name}"] = "m/s²"
    for k in mech.link_numbers:
        if k >= 2:
            cols[f"epsilon_{k}"] = np.asarray(motion.epsilon[str(k)], dtype=float)
            units[f"epsilon_{k}"] = "rad/s²"
    info = getattr(case, "drawn", None)
    angles, slides = _drawn_columns(info, motion, cols, units, phi_deg)
    rows = []
    for i in range(pos.n):
        row: dict[str, Any] = {key: (int(v[i]) if key == "position" else _clean(v[i])) for key, v in cols.items()}
        if pos.index is None:
            row["position"] = None
        row["ill_conditioned"] = bool(plan.ill_conditioned[i])
        row["points"], row["links"] = _state(case, motion, i)
        for k, a in angles.items():
            row["links"][k]["angle_deg"] = _clean(a[i])
        if info is not None:
            row["slides"] = [{"block": int(s["block"]), "on": int(s["on"]), "at": s["at"],
                              "v_rel": _clean(s["v_rel"][i]), "a_rel": _clean(s["a_rel"][i]),
                              "a_cor": [_clean(s["a_cor"][i].real), _clean(s["a_cor"][i].imag)]} for s in slides]
        rows.append(row)
    out = {
        "case": case.name, "kind": case.kind, "source": case.source, "n_rpm": case.n_rpm if n_rpm is None else n_rpm,
        "omega_1": omega_1, "epsilon_1": epsilon_1, "sense": "ccw" if mech.sense == 1 else "cw",
        "m": m if phi_deg is None else None,
        "links": {str(k): v for k, v in mech.link_numbers.items()},
        "structure": case.linkage.structure().formula,
        "dof": case.linkage.structure().dof,
        "groups": [{"type": g.kind, "class": g.cls, "order": g.order, "links": list(g.links)}
                   for g in case.linkage.structure().groups],
    }
    if info is not None:
        out["structure"] = info.structure.as_json()
        out["driver"] = {"link": int(info.structure.driver), "phi_0_deg": math.degrees(info.phi_0),
                         "range_deg": None if info.swing is None else [math.degrees(x) for x in info.swing]}
    if st is not None:
        out.update(phi_start_deg=math.degrees(st.phi_start), phi_end_deg=math.degrees(st.phi_end),
                   working_angle_deg=math.degrees(st.working_angle), return_angle_deg=math.degrees(st.return_angle),
                   K=st.K, start=st.start_name)
    if pos.H is not None:
        out["stroke_H"] = pos.H
    if pos.psi_max is not None:
        out["psi_max_deg"] = math.degrees(pos.psi_max)
    out["units"] = units
    out["positions"] = rows
    return out


def _columns(res: dict, keys: list[str]) -> list[str]:
    """One table of the text output: a header of the keys with their units, a row per position."""
    head = [k if k not in res["units"] else f"{k} [{res['units'][k]}]" for k in keys]
    width = [max(10, len(h)) for h in head]
    lines = ["  ".join(h.rjust(w) for h, w in zip(head, width))]
    for row in res["positions"]:
        cells = []
        for k, w in zip(keys, width):
            v = row[k]
            cells.append(("-" if v is None else str(v)).rjust(w) if k == "position"
                         else f"{v + 0.0 if abs(v) >= 5e-6 else 0.0:.{3 if k.endswith('_deg') else 5}f}".rjust(w))
        lines.append("  ".join(cells) + ("  ill-conditioned" if row["ill_conditioned"] else ""))
    return lines


def _drawn_columns(info, motion, cols: dict, units: dict, phi_deg=None) -> tuple[dict, list]:
    """A drawn file's link angles and slides over the positions; their flat columns added to ``cols``
    (``angle_k_deg``, ``v_rel_b/o``, ``a_rel_b/o``, ``a_cor_b/o`` its magnitude); the driver's angle as
    the file gives it (inside a swinging driver's range)."""
    import numpy as np

    if info is None:
        return {}, []
    from graphmethods.kinematics.drawn import driver_angles_deg, link_angles, slide_kinematics

    if info.swing is not None:
        cols["phi_deg"] = driver_angles_deg(info, motion, phi_deg)
    angles = link_angles(info, motion)
    for k, a in angles.items():
        cols[f"angle_{k}_deg"] = a
        units[f"angle_{k}_deg"] = "°"
    slides = slide_kinematics(info, motion)
    for s in slides:
        tag = f"{s['block']}/{s['on']}"
        for key, val, unit in (("v_rel", s["v_rel"], "m/s"), ("a_rel", s["a_rel"], "m/s²"),
                               ("a_cor", np.abs(s["a_cor"]), "m/s²")):
            cols[f"{key}_{tag}"] = val
            units[f"{key}_{tag}"] = unit
    return angles, slides


def _text(res: dict) -> str:
    lines = [f"{res['case'] or res['kind']}  ({res['kind']}, {res['source']})",
             f"n = {res['n_rpm']:g} rev/min, ω₁ = {res['omega_1']:.6g} rad/s ({res['sense']}), "
             + (f"m = {res['m']} positions from {res.get('start', 'φ = 0')}" if res["m"] is not None
                else "at the given crank angles"),
             f"structure {res['structure']['formula'] if isinstance(res['structure'], dict) else res['structure']}"
             + (f", W = {res['structure']['dof']}" if isinstance(res["structure"], dict) else "")]
    if "K" in res:
        lines.append(f"working stroke {res['working_angle_deg']:.4f}°, return {res['return_angle_deg']:.4f}°, "
                     f"K = {res['K']:.4f}" + (f", stroke H = {res['stroke_H']:.6g} m" if "stroke_H" in res else "")
                     + (f", swing ψ_max = {res['psi_max_deg']:.4f}°" if "psi_max_deg" in res else ""))
    lines.append("links: " + ", ".join(f"{k} = {v}" for k, v in res["links"].items()))
    keys = [k for k in res["positions"][0] if k not in ("ill_conditioned", "points", "links", "slides")]
    second = [k for k in keys if k.startswith(("a_", "epsilon_"))]
    lines.append("velocities")
    lines += _columns(res, [k for k in keys if k not in second])
    lines.append(f"accelerations (ε₁ = {res['epsilon_1']:g} rad/s²; a slider's along its guide, other points' "
                 f"magnitudes; ε counterclockwise +)")
    lines += _columns(res, ["position", "phi_deg", *second])
    if (res["m"] is not None and len(res["positions"]) == res["m"] + 1
            and (res.get("driver") or {}).get("range_deg") is None):
        lines.append(f"position {res['m']} = position 0")
    return "\n".join(lines)


def figures(case, m: int, *, notation: str = "en", plan_position: int | None = None, epsilon_1: float = 0.0) -> dict:
    """The figures of a problem file as scenes: file suffix -> Scene, plus ``"velocity_table.md"`` -> str.

    Positions and velocity plans are built once (a lazy Study) and shared by every figure; the
    acceleration plans (all positions, the large one of the same position, the table) are at the
    file's mean crank speed and ``epsilon_1``.
    """
    from graphmethods.dynamics.study import Study
    from graphmethods.errors import InputError
    from graphmethods.sheets import acceleration as sa, kinematics as ks

    if m > FIGURES_MAX_POSITIONS:
        raise InputError(f"--figures draws at most {FIGURES_MAX_POSITIONS} positions (the velocity table's rows must "
                         f"stay 4 mm high on its page); give --positions {FIGURES_MAX_POSITIONS} or fewer, or leave "
                         f"out --figures for the numbers alone")
    study = Study(case, positions=m)
    k = ks.fullest_position(study.plans) if plan_position is None else plan_position
    if isinstance(k, bool) or not 0 <= k <= m:
        raise InputError(f"--plan-position {k}: give a position from 0 to {m}")
    plan = ks.velocity_plan(study, k, notation=notation)
    return {
        "kinematic_scheme": ks.kinematic_scheme(study, notation=notation),
        "velocity_plans": ks.velocity_plan_grid(study, notation=notation),
        f"velocity_plan_{k}": plan,
        "velocity_table": ks.velocity_table(study, notation=notation),
        "velocity_table.md": ks.velocity_table_markdown(study, notation=notation),
        "acceleration_plans": sa.acceleration_plan_grid(study, epsilon_1=epsilon_1, notation=notation),
        f"acceleration_plan_{k}": sa.acceleration_plan(study, k, epsilon_1=epsilon_1, notation=notation),
        "acceleration_table": sa.acceleration_table(study, epsilon_1=epsilon_1, notation=notation),
    }


def angle_figures(case, phi_deg, *, notation: str = "en", epsilon_1: float = 0.0) -> dict:
    """The figures at given crank angles (degrees from +x): the scheme in those positions, and the velocity
    and acceleration plans drawn large at each angle (``velocity_plan_30deg``, ``acceleration_plan_30deg``).

    The textbook's own crank angle (a problem that says "at φ = 30°") gets its plans exactly there.
    """
    from graphmethods.dynamics.study import AngleStudy
    from graphmethods.errors import InputError
    from graphmethods.sheets import acceleration as sa, kinematics as ks

    if len(phi_deg) > FIGURES_MAX_POSITIONS:
        raise InputError(f"--figures draws the plans of at most {FIGURES_MAX_POSITIONS} crank angles; give fewer "
                         f"--phi-deg angles")
    from graphmethods.scene.notation import get

    nt = get(notation)
    study = AngleStudy(case, [a % 360.0 for a in phi_deg])
    out: dict = {"kinematic_scheme": ks.kinematic_scheme(study, notation=notation)}
    for i, a in enumerate(phi_deg):
        shown = nt.number(a % 360.0, sig=6)
        tag = f"{a % 360.0:g}".replace(".", "_") + "deg"
        out[f"velocity_plan_{tag}"] = ks.velocity_plan(study, i, notation=notation,
                                                       title=nt.word("kinematics.plan_at", phi=shown))
        out[f"acceleration_plan_{tag}"] = sa.acceleration_plan(
            study, i, epsilon_1=epsilon_1, notation=notation, title=nt.word("acceleration.plan_at", phi=shown))
    return out


def write_figures(case, m: int, directory, *, stem: str, notation: str = "en", fmt: str = "svg",
                  plan_position: int | None = None, overwrite: bool = False, epsilon_1: float = 0.0,
                  phi_deg=None) -> list:
    """Build every figure, then write them all into ``directory`` (created if missing).

    Nothing is written when a figure cannot be built or a file exists (without ``overwrite``);
    the set is written into a temporary folder beside ``directory`` and renamed into place, so an
    error or an interrupt leaves the old set or the new one (:func:`graphmethods.render.files.write_set`).

    Raises
    ------
    OutputExistsError
        If a file exists and ``overwrite`` is false (the message lists them).
    """
    from graphmethods.cli._sheet import write_scene_set
    from graphmethods.errors import InputError

    if str(directory).strip() == "":
        raise InputError("--figures is empty; give a folder (it is created if missing)")
    scenes = (figures(case, m, notation=notation, plan_position=plan_position, epsilon_1=epsilon_1)
              if phi_deg is None else angle_figures(case, phi_deg, notation=notation, epsilon_1=epsilon_1))
    return write_scene_set(scenes, directory, stem=stem, fmt=fmt, overwrite=overwrite)


def _sheet_data(case, args, phi_deg, n_rpm):
    """(target, bytes) of ``--sheet`` (checked before any work), or (None, None)."""
    from graphmethods.errors import InputError

    if args.sheet is None:
        if args.plan_positions is not None:
            raise InputError("--plan-positions applies to the sheet; add --sheet FILE")
        return None, None
    from graphmethods.cli._sheet import check_sheet_target, scene_bytes, signed
    from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet

    if phi_deg is not None or n_rpm is not None or args.epsilon_1 != 0.0:
        raise InputError("--sheet draws the positions 0…M at the file's mean speed with ε₁ = 0; leave out "
                         "--phi-deg, --n/--omega and --epsilon-1 (or run them without --sheet)")
    count(args.positions, "--positions", low=3, high=FIGURES_MAX_POSITIONS, why="the sheet draws every position")
    sheet = check_sheet_target(args.sheet, args.force, None if args.sheet != "-" else args.fig_format)
    ks = None if args.plan_positions is None else _position_list(args.plan_positions)
    try:
        scene = kinematic_analysis_sheet(case, m=args.positions, plan_positions=ks, page=args.page,
                                         notation=args.lang)
    except InputError as e:
        room = _plans_room(case, args, ks) if ks is not None and "do not fit" in str(e) else None
        if room is None:
            raise
        raise InputError(f"--plan-positions: the sheet of this linkage has room for {room} acceleration "
                         f"plan{'s' if room > 1 else ''} beside its other parts, not {len(ks)}; give at most "
                         f"{room} positions") from None
    return sheet, scene_bytes(signed(scene, args), sheet)


def _plans_room(case, args, ks: list[int]) -> int | None:
    """How many of the plan positions ``ks`` the kinematic-analysis sheet has room for (the most first), or
    None when not even one fits (the sheet's own refusal then stands)."""
    from graphmethods.errors import InputError
    from graphmethods.sheets.kinematic_analysis_sheet import kinematic_analysis_sheet

    for n in range(len(ks) - 1, 0, -1):
        try:
            kinematic_analysis_sheet(case, m=args.positions, plan_positions=ks[:n], page=args.page,
                                     notation=args.lang)
        except InputError:
            continue
        return n
    return None


def run(args) -> int:
    import pathlib
    import sys

    from graphmethods.cli._sheet import refuse_two_on_stdout, report_stream
    from graphmethods.errors import InputError
    from graphmethods.problems import builtin

    m = count(args.positions, "--positions", low=3, high=MAX_POSITIONS, why="checked before any work")
    if args.position is not None and args.phi_deg is not None:
        raise InputError("--position K picks a position of 0…M, --phi-deg gives crank angles: give one of them")
    if args.position is not None and not 0 <= args.position <= m:
        raise InputError(f"--position {args.position}: give a position from 0 to {m} (--positions {m})")
    if args.sheet is None and args.figures is None and (args.plan_position is not None or args.fig_format
                                                        or args.force or args.lang != "en"):
        raise InputError("--lang, --format, --plan-position and --force apply to the figures; add --figures DIR "
                         "(--lang, --format and --force also to --sheet FILE)")
    n_rpm = speed_rpm(args)
    case = builtin.case(args.case)
    phi_deg = args.phi_deg
    _sheet.check_signature(args)
    sheet, sheet_data = _sheet_data(case, args, phi_deg, n_rpm)
    refuse_two_on_stdout(args.json, sheet)
    res = table(case, m, phi_deg=phi_deg, epsilon_1=args.epsilon_1, n_rpm=n_rpm)
    if args.position is not None:
        res["positions"] = [res["positions"][args.position]]
    written = []
    if args.figures is not None:
        stem = "stdin" if args.case == builtin.STDIN else pathlib.Path(args.case).stem
        plan_position = args.plan_position if args.plan_position is not None else args.position
        written = write_figures(case, m, args.figures, stem=stem, notation=args.lang, fmt=args.fig_format or "svg",
                                plan_position=plan_position, overwrite=args.force, epsilon_1=args.epsilon_1,
                                phi_deg=phi_deg)
    out = report_stream(sheet)
    if args.json:
        if written:
            res["figures"] = [str(p) for p in written]
        print(json_text(res, indent=1), file=out)
    else:
        check_finite(res)          # the same finiteness check before the text is printed
        print(_text(res), file=out)
        for p in written:
            print(f"wrote {p}", file=out)
    if sheet is not None and sheet_data is not None:      # written last: an error above leaves no file behind
        sheet.write(sheet_data, overwrite=args.force)
        if not sheet.to_stdout:
            print(f"wrote {sheet} ({args.page}, {args.lang})", file=sys.stderr if args.json else sys.stdout)
    return 0
