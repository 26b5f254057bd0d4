"""``graphmethods examples``: solve and print the built-in worked examples W1–W4."""

from __future__ import annotations

from typing import Any

from graphmethods.units import json_text


def add_parser(sub) -> None:
    p = sub.add_parser("examples", help="solve and print the published worked examples W1–W4",
                       description="Solve the published worked examples W1–W4 and print them.")
    p.add_argument("--json", action="store_true", help="print one JSON object per example")
    p.set_defaults(func=run)


def run(args) -> int:
    from graphmethods.problems import all_examples

    results = {}
    for prob in all_examples():
        ew = prob.excess_work
        res: dict[str, Any] = {"title": str(prob.title), "source": prob.source, "excess_work": ew.to_dict(),
               "work_unit": prob.work_unit}
        if prob.n_rpm is not None and prob.delta is not None:
            res["flywheel"] = prob.flywheel().to_dict()
        if prob.omega_0 is not None:
            res["kinetic_energy"] = prob.kinetic_energy().to_dict()
        if prob.note:
            res["note"] = prob.note
        results[prob.id] = res
        if args.json:
            continue
        print(f"== {prob.id}: {prob.title}  [{prob.source}]")
        print(ew.to_text(unit=prob.work_unit))
        if "flywheel" in res:
            fw = res["flywheel"]
            print(f"n = {fw['n_rpm']:.6g} rev/min, [δ] = {fw['delta']:.6g}:  J_F = {fw['J_F']:.4f} kg·m²")
        if "kinetic_energy" in res:
            ke = res["kinetic_energy"]
            print(f"T, {prob.work_unit} = " + ", ".join(f"{t:.4f}" for t in ke["T"])
                  + f"   (J_e = {ke['J_e']:g} {prob.inertia_unit}, T0 = {ke['T0']:g} {prob.work_unit})")
            print("ω, s⁻¹ = " + ", ".join(f"{w:.4f}" for w in ke["omega"])
                  + f"   ω_m = {ke['omega_m']:.4f}, δ = {ke['delta']:.4f}")
        if prob.note:
            print(f"note: {prob.note}")
        print()
    if args.json:
        print(json_text(results, indent=1))
    return 0
