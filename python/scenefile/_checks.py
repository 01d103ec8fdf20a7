"""The package's one check of an argument, as the tools check their flags.

A number is a real number (bool is not one, nor a str that spells one),
finite unless the caller holds it as data for validate() to judge, and in
its range; a wrong type is a TypeError and a wrong value a ValueError, each
naming the argument (docs/PYTHON.md, "Arguments").
"""

from __future__ import annotations

import math
from typing import Any, Tuple, Union

import numpy as np

_INF = math.inf


def _describe(value: Any) -> str:
    return type(value).__name__


def real(value: Any, name: str, lowest: float = -_INF, highest: float = _INF, *,
         excluded: Tuple[bool, bool] = (False, False), finite: bool = True) -> float:
    """``value`` as a float: a real number, finite (unless ``finite`` is False),
    in [lowest, highest], an end left out where ``excluded`` says."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer,
                                                                      np.floating)):
        raise TypeError(f"{name} must be a number, not {_describe(value)}")
    number = float(value)
    if not math.isfinite(number):
        if not finite:
            return number
        raise ValueError(f"{name} must be a finite number, not {number}")
    low_out, high_out = excluded
    if number < lowest or number > highest or (low_out and number == lowest) or (
            high_out and number == highest):
        raise ValueError(f"{name} must lie {_range(lowest, highest, excluded)}, not {number:g}")
    return number


def whole(value: Any, name: str, lowest: int, highest: int) -> int:
    """``value`` as an int: a whole number (bool is not one) in [lowest, highest]."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be a whole number, not {_describe(value)}")
    number = int(value)
    if not lowest <= number <= highest:
        raise ValueError(f"{name} must lie between {lowest} and {highest}, not {number}")
    return number


def flag(value: Any, name: str) -> bool:
    """``value`` as a bool: True or False, not a number or a str."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be True or False, not {_describe(value)}")
    return bool(value)


def vector(value: Any, name: str, finite: bool = True) -> Tuple[float, float, float]:
    """Three real numbers, each finite unless ``finite`` is False."""
    items = list(np.asarray(value).reshape(-1)) if isinstance(value, np.ndarray) else value
    try:
        x, y, z = items
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be three numbers") from None
    return (real(x, name, finite=finite), real(y, name, finite=finite),
            real(z, name, finite=finite))


def instance(value: Any, name: str, kind: Union[type, Tuple[type, ...]]) -> Any:
    """``value`` itself, when it is a ``kind``; a TypeError naming it otherwise."""
    if not isinstance(value, kind):
        kinds = kind if isinstance(kind, tuple) else (kind,)
        names = " or ".join(k.__name__ for k in kinds)
        raise TypeError(f"{name} must be a {names}, not {_describe(value)}")
    return value


def _range(lowest: float, highest: float, excluded: Tuple[bool, bool]) -> str:
    if highest == _INF:
        return f"above {lowest:g}" if excluded[0] else f"at {lowest:g} or above"
    if lowest == -_INF:
        return f"below {highest:g}" if excluded[1] else f"at {highest:g} or below"
    ends = {(True, True): ", both excluded", (True, False): f", {lowest:g} excluded",
            (False, True): f", {highest:g} excluded", (False, False): ""}[excluded]
    return f"between {lowest:g} and {highest:g}{ends}"
