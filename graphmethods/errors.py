"""The exceptions graphmethods raises.

Every error the toolkit raises on bad input is a :class:`GraphmethodsError`;
its message says what is wrong, where, and what to do. The command line prints
the message as one line and exits non-zero.
"""


class GraphmethodsError(Exception):
    """Base class of every error graphmethods raises on purpose."""


class InputError(GraphmethodsError, ValueError):
    """Input that cannot be used: unparsable, out of range, NaN, wrong shape."""


class UnbalancedCycleError(InputError):
    """A cycle whose driving and resisting work do not balance (closure residual too large)."""


class AssemblyError(InputError):
    """A linkage that cannot be assembled at some position (a length condition is violated)."""


class MotionError(GraphmethodsError):
    """A periodic motion that cannot exist (e.g. the driving work cannot sustain the speed)."""


class OutputExistsError(GraphmethodsError):
    """Refusing to overwrite an existing file without being asked (use overwrite=True / --force)."""


class OutputError(GraphmethodsError):
    """A file or folder that cannot be written: read-only file system, no permission, disk full, a folder
    or a file in the way. The message says what, where and why; nothing partial is left behind."""


class NoFlywheelNeeded(MotionError):
    """The answer "no flywheel is needed": the machine's own inertia already keeps δ within [δ].

    Raised where a construction cannot go on (the Wittenbauer rays meet on the curve, so there is no
    origin O1); :meth:`graphmethods.dynamics.study.Study.summary` reports it as J_F = 0, not an error."""


class MissingFontError(GraphmethodsError):
    """Text that no available font can draw in PNG/PDF (e.g. Chinese without a CJK font); nothing is written.

    The message says which characters and how to get a font (install one, or set ``GRAPHMETHODS_CJK_FONT``).
    SVG output does not raise it: the viewer chooses the font there.
    """
