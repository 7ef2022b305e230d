"""Quantities with units (pint) for robot programs; plain numbers are taken as SI.

Every value this library sends is converted here, and every conversion checks the dimension: a
speed given in metres, or metres per second where an angular speed is due, raises
:class:`UnitError` instead of sending a wrong number to the robot.

Angles are dimensionless in SI (and in pint), so an angle or angular speed accepts radians,
degrees, revolutions or a plain number (radians); a length or a time does not pass as one.
"""

from __future__ import annotations

import math
from typing import Any, Union

try:
    import pint
except ModuleNotFoundError as missing:  # pragma: no cover - depends on the interpreter
    # A Robot Session puts this package on PYTHONPATH but cannot install pint for the program's
    # interpreter: say what to do instead of a bare "No module named 'pint'".
    raise ModuleNotFoundError(
        "stagecraft_player needs pint for quantities with units: pip install pint "
        "(or apt-get install python3-pint) for the interpreter that runs this program",
        name="pint",
    ) from missing

from .errors import UnitError

#: The registry every quantity of this library lives in. Robot programs use its units (or these
#: shortcuts); quantities from another registry are refused by pint when mixed.
ureg: pint.UnitRegistry[Any] = pint.UnitRegistry()
Quantity = ureg.Quantity

m = ureg.metre
cm = ureg.centimetre
mm = ureg.millimetre
s = ureg.second
ms = ureg.millisecond
rad = ureg.radian
deg = ureg.degree
Hz = ureg.hertz

#: What a parameter accepts: a plain number (SI) or a pint quantity.
QuantityLike = Union[float, int, Any]

# Each kind: the SI unit values are sent in, and a description for error messages.
KINDS: dict[str, tuple[str, str]] = {
    "length": ("m", "a length (e.g. 0.5 * m)"),
    "speed": ("m/s", "a speed (e.g. 0.3 * m/s)"),
    "acceleration": ("m/s**2", "an acceleration (e.g. 0.5 * m/s**2)"),
    "angle": ("rad", "an angle (e.g. 30 * deg)"),
    "angular_speed": ("rad/s", "an angular speed (e.g. 20 * deg/s)"),
    "time": ("s", "a duration (e.g. 2 * s)"),
    "frequency": ("Hz", "a frequency (e.g. 10 * Hz)"),
}


def to_si(value: QuantityLike, kind: str, name: str = "value") -> float:
    """The magnitude of ``value`` in the SI unit of ``kind``, as a float.

    A plain int or float is taken to be in SI already. A quantity of another dimension raises
    :class:`UnitError` naming the parameter, what it should be and what it got.
    """
    unit, description = KINDS[kind]
    if isinstance(value, bool):
        raise UnitError(f"{name}: expected {description}, got the boolean {value!r}")
    if isinstance(value, (int, float)):
        result = float(value)
    elif isinstance(value, pint.Quantity):
        try:
            result = float(value.to(unit).magnitude)
        except pint.DimensionalityError:
            raise UnitError(f"{name}: expected {description}, got {value:~P} "
                            f"(a quantity of dimension {value.dimensionality})") from None
        except (TypeError, ValueError) as e:
            raise UnitError(f"{name}: expected one number as {description}, got {value!r} ({e})") from None
    else:
        raise UnitError(f"{name}: expected {description} or a plain number in {unit}, "
                        f"got {type(value).__name__} {value!r}")
    if math.isnan(result):
        raise UnitError(f"{name}: expected {description}, got NaN")
    return result


def quantity(value: float, unit: str) -> Any:
    """``value`` (in ``unit``) as a pint quantity of this library's registry."""
    return Quantity(value, unit)


class QuantityView:
    """Read-only view of a data record's fields as quantities: ``scan.q.max_range.to("cm")``.

    The record lists its fields' units in a class attribute ``UNITS``; lists become lists of
    quantities.
    """

    def __init__(self, record: Any) -> None:
        self._record = record

    def __getattr__(self, name: str) -> Any:
        units: dict[str, str] = getattr(type(self._record), "UNITS", {})
        if name not in units:
            raise AttributeError(f"{type(self._record).__name__}.{name} has no unit "
                                 f"(fields with units: {', '.join(sorted(units)) or 'none'})")
        value = getattr(self._record, name)
        if isinstance(value, (list, tuple)):
            return [Quantity(v, units[name]) for v in value]
        return Quantity(value, units[name])

    def __dir__(self) -> list[str]:
        return sorted(getattr(type(self._record), "UNITS", {}))
