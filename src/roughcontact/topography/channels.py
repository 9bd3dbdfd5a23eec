"""Which channels of an instrument file hold heights.

An AFM file holds several images of one scan: the height (topography, z sensor) and signals
recorded beside it (phase, oscillation amplitude, feedback error, deflection, friction, current,
surface potential, ...). SurfaceTopography marks most of them as heights (``DataKind.HEIGHT``:
a Bruker phase channel with no unit, an Asylum ``AmplitudeTrace`` in metres), so a contact
computed on them would be a contact on a phase image. Each channel is classified here from
three things, any one of which marks it as *not* holding heights:

* its **name**: one of the words of :data:`SIGNAL_WORDS` (``AmplitudeTrace``, ``PeakForceError``,
  ``NapPotentialTrace``, ``Friction``; words are split at capitals, digits and punctuation);
* its **unit**: a unit that is not a length (``deg``, ``V``, ``A``, ``Hz``, ``N``);
* SurfaceTopography's **data kind**, where it is not ``HEIGHT`` (an Asylum phase channel).

A file whose only name is generic (``Default``, ``Raw``, a matrix without a header) is taken to
hold heights. A channel the rules misjudge can be read anyway with ``treat_as_height=True``
(command line ``--treat-as-height``), but never one whose values are in a unit that is not a
length: that unit cannot be converted to metres.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["SIGNAL_WORDS", "ChannelKind", "classify_channel"]

SIGNAL_WORDS = {
    "error": "a feedback error signal",
    "phase": "a phase signal",
    "amplitude": "an oscillation amplitude",
    "deflection": "a cantilever deflection signal",
    "friction": "a friction (lateral force) signal",
    "lateral": "a lateral force signal",
    "lfm": "a lateral force signal",
    "force": "a force signal",
    "current": "a current",
    "potential": "a surface potential",
    "kpfm": "a surface potential",
    "voltage": "a voltage",
    "bias": "a voltage",
    "frequency": "a frequency shift",
    "dissipation": "a dissipation signal",
    "adhesion": "an adhesion map",
    "modulus": "a modulus map",
    "stiffness": "a stiffness map",
    "dmt": "a modulus map",
    "capacitance": "a capacitance signal",
    "temperature": "a temperature",
    "intensity": "an intensity image",
    "reflectivity": "a reflectivity image",
    "quality": "a measurement quality map",
    "mask": "a mask",
    "valid": "a validity mask",
    "count": "a count",
}
"""Words in a channel name that mark a signal recorded beside the heights, and what it is (the first
word of this table that a name holds says it: ``AmplitudeError`` is an error signal)."""


@dataclass(frozen=True)
class ChannelKind:
    """Whether a channel holds heights, and why not.

    Attributes
    ----------
    is_height : bool
    reason : str
        Empty for a height channel; else what the channel holds and how that was seen
        (``"a phase signal (its name, 'Phase')"``).
    unit_is_length : bool or None
        Whether the file's unit of its values is a length (None: no unit in the file).
    """

    is_height: bool
    reason: str = ""
    unit_is_length: bool | None = None


def _words(name: str) -> list[str]:
    spaced = re.sub(r"(?<=[a-z])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", " ", name)
    return [word.lower() for word in re.split(r"[^A-Za-z]+", spaced) if word]


def classify_channel(
    name: str, unit: str | None, unit_is_length: bool | None, data_kind: str | None = None
) -> ChannelKind:
    """Classify a channel from its name, the unit of its values and SurfaceTopography's data kind.

    Parameters
    ----------
    name : str
        The channel's name as in the file.
    unit : str or None
        The unit of its values as written in the file (None: none given).
    unit_is_length : bool or None
        Whether ``unit`` is a length unit (None when there is no unit).
    data_kind : str, optional
        SurfaceTopography's ``DataKind`` name (``"HEIGHT"``, ``"PHASE"``, ...).

    Returns
    -------
    ChannelKind
    """
    if unit_is_length is False:
        return ChannelKind(False, f"values in {unit!r} (not a length)", False)
    words = set(_words(name))
    for word, what in SIGNAL_WORDS.items():
        if word in words:
            return ChannelKind(False, f"{what} (its name, {name!r})", unit_is_length)
    if data_kind is not None and data_kind.upper() not in ("HEIGHT", ""):
        what = data_kind.lower().replace("_", " ")
        return ChannelKind(False, f"a {what} signal (the file says so)", unit_is_length)
    return ChannelKind(True, "", unit_is_length)
