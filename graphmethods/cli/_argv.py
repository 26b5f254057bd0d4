"""Arguments that argparse would misread: a value starting with ``-`` (a formula, a negative number)."""

from __future__ import annotations


def join_option_values(argv: list[str], options: tuple[str, ...]) -> list[str]:
    """``--M-r -20*sin(phi)`` -> ``--M-r=-20*sin(phi)`` for each option in ``options``.

    >>> join_option_values(["--moment", "-0.02*omega**2", "--t-end", "5"], ("--moment",))
    ['--moment=-0.02*omega**2', '--t-end', '5']
    """
    out, i = [], 0
    while i < len(argv):
        if argv[i] in options and i + 1 < len(argv):
            out.append(f"{argv[i]}={argv[i + 1]}")
            i += 2
            continue
        out.append(argv[i])
        i += 1
    return out
