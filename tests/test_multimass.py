"""Drives of several masses (issue 18 item 5): reduction by the squares of the ratios, the two- and
three-mass natural frequencies against their closed forms, the scheme and the command line."""

import json
import math

import numpy as np
import pytest

from graphmethods.cli import main
from graphmethods.dynamics.multimass import Mass, Shaft, reduce_chain
from graphmethods.dynamics.reduction import Shaft as GearShaft, reduce_drive
from graphmethods.errors import InputError

MASSES = [Mass("motor", 0.08, 6.0, 30.0), Mass("gear", 0.5, 2.0), Mass("crank", 12.0, 1.0, -160.0)]
SHAFTS = [Shaft("motor shaft", 2.0e3, 6.0), Shaft("output shaft", 4.0e4, 1.0)]


def test_reduction_keeps_kinetic_and_elastic_energy():
    d = reduce_chain(MASSES, SHAFTS)
    w = 3.7                                              # any speed of the reference shaft
    T_given = sum(0.5 * m.J * (m.u * w) ** 2 for m in MASSES)
    assert 0.5 * d.J_e * w**2 == pytest.approx(T_given, rel=1e-14)
    dtheta = np.array([0.01, -0.02])                     # twists of the reference shaft's angle
    V_given = sum(0.5 * s.c * (s.u * t) ** 2 for s, t in zip(SHAFTS, dtheta))
    assert float(np.sum(0.5 * d.c * dtheta**2)) == pytest.approx(V_given, rel=1e-14)
    # the rigid drive: the gear-train reduction of dynamics.reduction gives the same J_e and M_e
    r = reduce_drive([GearShaft(m.name, m.J, m.u, m.M) for m in MASSES])
    assert d.J_e == pytest.approx(r.J_e) and d.M_e == pytest.approx(r.M_e)


def test_two_mass_frequency():
    d = reduce_chain([Mass("a", 0.05, 4.0), Mass("b", 2.0)], [Shaft("s", 800.0, 4.0)])
    J1, J2, c = 0.05 * 16, 2.0, 800.0 * 16
    assert d.natural_frequencies.size == 1
    assert d.natural_frequencies[0] == pytest.approx(math.sqrt(c * (J1 + J2) / (J1 * J2)), rel=1e-12)
    # mode: the masses swing against each other, amplitudes inversely as the inertias
    mode = d.modes[:, 0]
    assert mode[1] / mode[0] == pytest.approx(-J1 / J2, rel=1e-10)


def test_three_mass_frequencies_are_the_roots_of_the_biquadratic():
    d = reduce_chain(MASSES, SHAFTS)
    J1, J2, J3 = d.J
    c1, c2 = d.c
    b = c1 / J1 + c1 / J2 + c2 / J2 + c2 / J3
    q = c1 * c2 * (J1 + J2 + J3) / (J1 * J2 * J3)
    roots = sorted(np.sqrt([(b - math.sqrt(b * b - 4 * q)) / 2, (b + math.sqrt(b * b - 4 * q)) / 2]))
    np.testing.assert_allclose(d.natural_frequencies, roots, rtol=1e-10)


def test_bad_drives_are_refused():
    with pytest.raises(InputError, match="two masses or more"):
        reduce_chain(MASSES[:1], [])
    with pytest.raises(InputError, match="joined by 2 shafts"):
        reduce_chain(MASSES, SHAFTS[:1])
    with pytest.raises(InputError, match="u of"):
        reduce_chain([Mass("a", 1.0, 0.0), Mass("b", 1.0)], [Shaft("s", 1.0)])


def test_drive_scheme_writes_the_reduced_values():
    from graphmethods.sheets.drive_scheme import drive_scheme

    d = reduce_chain(MASSES, SHAFTS)
    s = drive_scheme(d, notation="en")
    assert s.element("reduced-label-J-1").text == "J'_{1} = 2.88 kg·m²"        # every label with its unit
    assert s.element("reduced-label-c-1").text.startswith("c'_{1} = 72000")
    assert s.element("given-label-J-1").text == "J_{1} = 0.08 kg·m², u = 6"


def test_drive_on_the_command_line(capsys, tmp_path):
    fig = tmp_path / "drive.svg"
    code = main(["drive", "--J", "0.08,0.5,12", "--u", "6,2,1", "--c", "2000,40000", "--c-u", "6,1",
                 "--M", "30,0,-160", "--json", "--figure", str(fig)])
    out, err = capsys.readouterr()
    assert code == 0, err
    d = json.loads(out)
    assert d["J"] == pytest.approx([2.88, 2.0, 12.0]) and d["M_e"] == pytest.approx(20.0)
    assert fig.exists() and "reduced-disc-3" in fig.read_text(encoding="utf-8")
    before = fig.read_bytes()
    code = main(["drive", "--J", "1,2", "--c", "5", "--figure", str(fig)])
    out, err = capsys.readouterr()
    assert code == 2 and "--force" in err and fig.read_bytes() == before
    code = main(["drive", "--J", "1,2", "--u", "1", "--c", "5"])
    out, err = capsys.readouterr()
    assert code == 2 and "--u" in err and err.count("\n") == 1
