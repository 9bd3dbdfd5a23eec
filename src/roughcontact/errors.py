"""Exceptions raised by roughcontact.

Every error names the offending input (the *field*) and says how to fix it, so a
user reading a CLI message or a traceback knows what to change without reading
the source.
"""

from __future__ import annotations

import math

from .messages import Door, default_option, marked, render


class InputError(ValueError):
    """Invalid user input: a value, a file, a grid or a unit.

    Parameters
    ----------
    field : str
        Name of the offending input, as the user wrote it (argument, config key or file).
    problem : str
        What is wrong with it.
    fix : str, optional
        What the user should do instead. Keys and settings are marked (``«channel=0»``,
        :mod:`roughcontact.messages`) so that each door names them in its words: ``str(error)``
        is the Python door's (``channel=0``), :meth:`text` and :meth:`rendered` give any door's.
    fixes : dict, optional
        A fix that differs in substance between doors, by door: ``"study"``, ``"cli"`` or
        ``"python"``; :meth:`fix_in` falls back to ``fix``.
    """

    def __init__(
        self, field: str, problem: str, fix: str | None = None, *, fixes: dict[str, str] | None = None
    ):
        self.field = field
        self.problem = marked(problem)
        self.fix = None if fix is None else marked(fix)
        self.fixes = {style: marked(text) for style, text in (fixes or {}).items()}
        super().__init__(self.text(Door.PYTHON))

    def fix_in(self, style: str) -> str | None:
        """Return the fix for ``style`` (``"python"``, ``"study"`` or ``"cli"``), still marked."""
        return self.fixes.get(style, self.fix)

    def rendered(self, door: Door | str, option_of=None) -> tuple[str, str, str | None]:
        """Return (field, problem, fix) in the words of ``door`` (:func:`roughcontact.messages.render`).

        A field that is a key (``normal_force``) is named as the door names it (``--normal-force``
        on a command line, through ``option_of``); other fields (a file, ``FILE``, a table's path)
        stay as they are.
        """
        door = Door(door)
        field = self.field
        if door is Door.CLI and field.isidentifier() and field.islower():
            field = (option_of or default_option)(field) or field
        return field, render(self.problem, door, option_of), render(self.fix_in(door.value), door, option_of)

    def text(self, door: Door | str, option_of=None) -> str:
        """Return the whole message, ``FIELD: PROBLEM Fix: FIX``, in the words of ``door``."""
        field, problem, fix = self.rendered(door, option_of)
        return f"{field}: {problem}" + (f" Fix: {fix}" if fix else "")


class UnitError(InputError):
    """A unit string that is unknown or has the wrong physical dimension."""


class UnsupportedFormatError(InputError):
    """A file that no reader understands (unknown, empty, truncated or corrupted)."""


class MissingMetadataError(InputError):
    """A file without its physical scan size or height unit, which the user must give.

    Attributes
    ----------
    missing : dict
        Each missing key (``size``, ``height_unit``) -> an example value (``"5 um"``, ``"nm"``), so
        each front end can say the fix in its own words (a keyword, a study key, an option).
    notes : list of str
        What else helps, in any front end's words (other channels that hold heights).
    """

    def __init__(self, field: str, problem: str, fix: str, missing: dict[str, str], notes: list[str]):
        self.missing = missing
        self.notes = notes
        super().__init__(field, problem, fix)


class UndefinedPointsError(InputError):
    """A file with undefined (missing) points that the user has not asked to fill; ``count`` of them.

    ``allowing`` is set when filling was asked for but would invent more than ``max_filled``
    allows: the ``max_filled`` that would allow it, for each edge to offer in its own words.
    """

    def __init__(self, field: str, problem: str, fix: str, count: int, allowing: float | None = None):
        self.count = count
        self.allowing = allowing
        filling = "add «fill_undefined=true» to fill them by harmonic interpolation, or crop them away."
        super().__init__(
            field, problem, fix, fixes=None if allowing is not None else {"study": filling, "cli": filling}
        )


ROUND_OFF_FLOOR = 1e-5
"""Highest stalled residual taken for a floating-point floor (measured floors: 1e-13 to 1e-6, rising
with the grid); a solve that stalls above it failed, and no looser tolerance is suggested."""


class ConvergenceError(RuntimeError):
    """An iterative solver stopped before reaching its tolerance.

    The unconverged field is never returned as an answer; the residual and the
    iteration count say how far the solver got.

    Parameters
    ----------
    solver : str
        Name of the solver.
    residual : float
        Scale-free residual reached.
    iterations : int
        Iterations performed.
    tolerance : float
        Tolerance that was asked for.
    stalled_at : float, optional
        The lowest residual of a solver that stopped because it stalled (its residual stopped
        falling long before ``max_iterations``): the accuracy the problem reaches in floating
        point, so a tolerance a few times above it can be met.
    cause : str, optional
        Why this problem does not converge, where the caller knows (a scan whose size makes the
        load's displacement dwarf its roughness): said instead of the general advice below, with
        ``fix``.
    fix : str, optional
        What to do about ``cause``.

    Without a cause the advice depends on how the solve ended: stopped at ``max_iterations``
    (more iterations, a looser tolerance knowingly, a finer grid), stalled at a floating-point
    floor (the tolerance that floor allows), or stalled far above round-off (the iteration found
    no answer: a load or a resampled scan).
    """

    def __init__(
        self,
        solver: str,
        residual: float,
        iterations: int,
        tolerance: float,
        stalled_at: float | None = None,
        *,
        cause: str | None = None,
        fix: str | None = None,
    ):
        self.solver = solver
        self.residual = residual
        self.iterations = iterations
        self.tolerance = tolerance
        self.stalled_at = stalled_at
        self.cause = cause
        self.fix = fix or self._advice()
        because = f": {cause}" if cause else ""
        super().__init__(
            f"{solver} did not converge: residual {residual:.3g} > tolerance {tolerance:.3g} "
            f"after {iterations} iterations{because}. Fix: {self.fix}"
        )

    def _advice(self) -> str:
        """Return the general advice of a solve without a known cause (the class docstring)."""
        stalled_at = self.stalled_at
        if stalled_at is None:
            return "raise max_iterations, loosen tolerance knowingly, or refine the grid."
        if self.suggested_tolerance is None:
            return (
                f"the residual stalled at {stalled_at:.3g}, far above round-off: the iteration found no "
                "answer, and a looser tolerance would accept a wrong one. This happens on surfaces "
                "whose heights at the pixel scale are noise (a profilometer trace at its sampling "
                "step): change the load, or resample the scan to a coarser pixel first (in Python: "
                "roughcontact.topography.process.resample)."
            )
        return (
            f"the residual stalled at {stalled_at:.3g} (the floor this problem reaches in floating "
            f"point, which rises with the grid size); ask for {self.suggested_tolerance:g} or more."
        )

    @property
    def suggested_tolerance(self) -> float | None:
        """A tolerance a stalled solve meets: twice ``stalled_at``, rounded up to one digit.

        None when the solve did not stall, or stalled above :data:`ROUND_OFF_FLOOR` (no floating-point
        floor lies there: the iteration failed, and no tolerance should be offered that accepts it).
        """
        if self.stalled_at is None or not 0 < self.stalled_at <= ROUND_OFF_FLOOR:
            return None
        exponent = math.floor(math.log10(2 * self.stalled_at))
        return float(f"{math.ceil(2 * self.stalled_at / 10**exponent)}e{exponent}")
