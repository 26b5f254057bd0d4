"""Speed against error: ``graphmethods bench``.

Each section measures, in one run, the time (median of repeats) and the error of a method against
a reference, and returns rows for a Markdown table and JSON. Ratios are taken within one run, as
these machines are noisy.

>>> t = median_time(lambda: sum(range(100)), repeat=3)
>>> t > 0
True
"""

from __future__ import annotations

import math
import statistics
import subprocess
import sys
import time
from dataclasses import asdict, dataclass, field
from typing import Callable

import numpy as np


@dataclass
class Row:
    """One measured line of the report."""

    section: str
    case: str
    method: str
    size: int | None = None
    seconds: float | None = None
    error: float | None = None
    note: str = ""
    extra: dict = field(default_factory=dict)


def median_time(fn: Callable[[], object], *, repeat: int = 5, min_seconds: float = 0.0) -> float:
    """Median wall time of ``fn()`` over ``repeat`` runs (more runs while under ``min_seconds``)."""
    times = []
    start = time.perf_counter()
    while len(times) < repeat or (time.perf_counter() - start < min_seconds and len(times) < 50):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


# --------------------------------------------------------------------- areas
def zigzag_curves(n_points: int, n_crossings: int, *, seed: int = 0):
    """M_d, M_r point arrays on [0, 2π] with about ``n_crossings`` sign changes of M_d − M_r."""
    rng = np.random.default_rng(seed)
    phi = np.linspace(0.0, 2 * math.pi, n_points)
    M_r = 100 + 40 * np.sin(phi) + rng.normal(0, 0.01, n_points)
    k = max(n_crossings // 2, 1)
    M_d = M_r + 20 * np.sin(k * phi + 0.3)
    M_d = M_d - (np.trapezoid(M_d - M_r, phi) / (2 * math.pi))
    return phi, M_d, M_r


def areas_numpy(phi, M_d, M_r):
    """ΔW_max and Σ|A| by the project's core (numpy)."""
    from graphmethods.dynamics import excess_work as ew
    from graphmethods.dynamics.moments import MomentCurve

    cyc = ew.from_moments(MomentCurve(phi, M_d), MomentCurve(phi, M_r), closure_tol=1e-6)
    return cyc.delta_W_max, float(np.abs(cyc.work).sum())


def areas_shapely(phi, M_d, M_r):
    """ΔW_max and Σ|A| by polygonizing the two curves with shapely (the route we do not take)."""
    import shapely
    from shapely.geometry import LineString

    cap0 = LineString([(phi[0], M_d[0]), (phi[0], M_r[0])])
    cap1 = LineString([(phi[-1], M_d[-1]), (phi[-1], M_r[-1])])
    lines = shapely.union_all([LineString(np.c_[phi, M_d]), LineString(np.c_[phi, M_r]), cap0, cap1])
    polys = shapely.get_parts(shapely.polygonize(shapely.get_parts(lines)))
    if polys.size == 0:
        return 0.0, 0.0
    area = shapely.area(polys)
    pts = shapely.point_on_surface(polys)
    x = shapely.get_x(pts)
    y = shapely.get_y(pts)
    sign = np.where(np.interp(x, phi, M_d) > y, 1.0, -1.0)   # M_d above the point: a gain
    order = np.argsort(shapely.bounds(polys)[:, 0])
    E = np.concatenate(([0.0], np.cumsum((sign * area)[order])))
    return float(E.max() - E.min()), float(area.sum())


def bench_areas(sizes=(10**3, 10**4, 10**5, 10**6), *, crossings=(2, 10**5), repeat=5) -> list[Row]:
    """Areas and ΔW_max: the numpy route against the shapely polygonize route on the same curves."""
    rows = []
    for n in sizes:
        for c in crossings:
            if c * 4 > n:
                continue
            phi, M_d, M_r = zigzag_curves(n, c)
            t_np = median_time(lambda: areas_numpy(phi, M_d, M_r), repeat=repeat)
            t_sh = median_time(lambda: areas_shapely(phi, M_d, M_r), repeat=max(1, repeat // 2))
            dw_np, tot_np = areas_numpy(phi, M_d, M_r)
            dw_sh, tot_sh = areas_shapely(phi, M_d, M_r)
            diff = abs(dw_np - dw_sh) / max(dw_np, 1e-300)
            label = f"{n:.0e} points, {'~' if c > 2 else ''}{c} crossings"
            rows.append(Row("areas", label, "numpy (core)", n, t_np, diff,
                            note=f"ΔW_max {dw_np:.6g} J", extra={"speedup_vs_shapely": t_sh / t_np}))
            rows.append(Row("areas", label, "shapely polygonize", n, t_sh, diff,
                            note=f"ΔW_max {dw_sh:.6g} J", extra={"ratio_to_numpy": t_sh / t_np}))
    return rows


# --------------------------------------------------------------------- start-up
def bench_startup(repeat=5) -> list[Row]:
    """`import graphmethods` and a cold `graphmethods flywheel`, each in a fresh interpreter."""
    def run(code):
        return lambda: subprocess.run([sys.executable, "-c", code], check=True, capture_output=True)

    base = median_time(run("pass"), repeat=repeat)
    imp = median_time(run("import graphmethods"), repeat=repeat)
    cli = median_time(run("from graphmethods.cli import main; main(['flywheel','--areas','50','-550','100','-125',"
                          "'500','-25','50','--n','600','--delta','1/300'])"), repeat=repeat)
    return [
        Row("start-up", "python -c pass", "interpreter alone", seconds=base),
        Row("start-up", "import graphmethods", "fresh process", seconds=imp, note=f"{imp - base:.3f} s over bare Python"),
        Row("start-up", "graphmethods flywheel (W1)", "fresh process", seconds=cli, note=f"{cli - base:.3f} s over bare Python"),
    ]


SECTIONS = {
    "areas": bench_areas,
    "startup": bench_startup,
}


def run_all(*, quick: bool = False, sections=None, progress=None) -> list[Row]:
    """Run the chosen sections (all by default); ``quick`` keeps sizes small for CI."""
    rows: list[Row] = []
    for name, fn in SECTIONS.items():
        if sections and name not in sections:
            continue
        if progress:
            progress(name)
        if quick and name == "areas":
            rows += fn(sizes=(10**3, 10**4, 10**5), crossings=(2, 10**4), repeat=3)
        elif quick and name == "startup":
            rows += fn(repeat=3)
        else:
            rows += fn()
    return rows


def _fmt(v, unit=""):
    if v is None:
        return ""
    if isinstance(v, float):
        return f"{v:.3g}{unit}"
    return str(v)


def to_markdown(rows: list[Row]) -> str:
    """The report as a Markdown table."""
    head = "| section | case | method | time, s | rel. error | note |\n|---|---|---|---|---|---|\n"
    body = []
    for r in rows:
        note = r.note
        for k, v in r.extra.items():
            note += f"{'; ' if note else ''}{k.replace('_', ' ')} {_fmt(v)}"
        body.append(f"| {r.section} | {r.case} | {r.method} | {_fmt(r.seconds)} | {_fmt(r.error)} | {note} |")
    return head + "\n".join(body) + "\n"


def to_json(rows: list[Row]) -> list[dict]:
    return [asdict(r) for r in rows]
