"""The checks of values every input kind is made of: numbers and vectors (docs/design.md#errors).

One helper per input kind, as potpourri3d's `validate_mesh` or librosa's `valid_audio`: each
raises one `InputError` naming the input and the field, or returns the value in the form the
code uses. What a whole file is, and its one reading, is the inputs layer's
(`eigendance.inputs`: model, song, mapping; docs/design.md#inputs). The kinds with a module of
their own check there: meshes (`harmonic.mesh.check_mesh`), audio (`music.decode.open_audio` for
the file; the spectrogram's analyser for the sample rate and the samples), mappings
(`Mapping.from_json`; `inputs.mapping.mapping_from`, sizes first), skeletons
(`modal.bodies.check_skeleton`; each JSON item in `modal.skeleton_file`), parts of a song
(`window.Window.of`), command-line numbers (`cli.options.number`, an argparse type over
`number`).
"""

from __future__ import annotations

import json
import math

import numpy as np

from eigendance.errors import InputError
from eigendance.files import finite_number


def shown(value, width: int = 40) -> str:
    """A value from a document (JSON, a request) as a message shows it: short, whatever it is.

    Parameters
    ----------
    value : anything.
    width : the most characters shown (longer text ends in "…").

    Returns
    -------
    str: the JSON text of the value (a string in quotes), else its type's name.

    Example
    -------
    >>> shown("elbow"), shown([1, 2]), shown(float("nan")), shown(object())
    ("'elbow'", '[1, 2]', 'NaN', 'object')
    """
    try:
        text = repr(value) if isinstance(value, str) else json.dumps(value)
    except (TypeError, ValueError, RecursionError):
        text = type(value).__name__
    return text if len(text) <= width else text[:width - 1] + "…"


def number(value, label: str, low: float = -math.inf, high: float = math.inf,
           integer: bool = False, above: bool = False):
    """A number from a document or a request, checked: a real number (not a bool), finite, in
    [low, high] (or (low, high] with `above`), an integer where `integer` says so.

    Parameters
    ----------
    value : the value as given.
    label : how the message names it ("rig.json: body 'arm': \\"radius\\"").
    low, high : the range, inclusive.
    integer : an integer is wanted (a float with an integer value is accepted).
    above : the value must be greater than `low`, not equal.

    Returns
    -------
    float, or int when `integer`.

    Example
    -------
    >>> number(2, "scale", 0, above=True), number(3.0, "size", integer=True)
    (2.0, 3)
    >>> number(True, "scale")
    Traceback (most recent call last):
    eigendance.errors.InputError: scale must be a number, not true
    """
    if isinstance(value, bool | np.bool_) or not isinstance(value, int | float | np.number):
        raise InputError(f"{label} must be a number, not {shown(value)}")
    if not finite_number(value):
        raise InputError(f"{label} is not finite ({shown(value)})")
    if integer and value != int(value):
        raise InputError(f"{label} must be an integer, not {shown(value)}")
    if value > high or value < low or (above and value <= low):
        raise InputError(f"{label} must be {_range(low, high, above)}, not {shown(value)}")
    return int(value) if integer else float(value)


def _range(low: float, high: float, above: bool) -> str:
    """'positive', 'at least 1', 'from 2 to 16' …: the range of `number` in words."""
    if math.isinf(low):
        return f"at most {_bound(high)}"
    if above:
        return "positive" if low == 0 and math.isinf(high) else \
            f"greater than {_bound(low)}" + ("" if math.isinf(high) else
                                               f" and at most {_bound(high)}")
    return f"at least {_bound(low)}" if math.isinf(high) else \
        f"from {_bound(low)} to {_bound(high)}"


def _bound(value: float) -> str:
    """A bound as a message writes it: an integer in full, else 3 significant digits."""
    return str(int(value)) if value == int(value) and abs(value) < 1e16 else f"{value:.3g}"


def vector(value, label: str, length: int = 3, bound: float = math.inf) -> np.ndarray:
    """A list of `length` finite numbers from a document, each within ±bound.

    Parameters
    ----------
    value : the value as given (a list).
    label : how the message names it.
    length : how many numbers.
    bound : the largest magnitude of each.

    Returns
    -------
    (length,) float64.

    Example
    -------
    >>> vector([0, 1, 2.5], "start").tolist()
    [0.0, 1.0, 2.5]
    """
    if not isinstance(value, list) or len(value) != length:
        raise InputError(f"{label} must be a list of {length} numbers, not {shown(value)}")
    result = np.array([number(item, label) for item in value])
    if np.abs(result).max(initial=0.0) > bound:
        raise InputError(f"{label} must lie within ±{bound:.0e}")
    return result


def numbers(value, label: str) -> list[float]:
    """A non-empty list of finite numbers from a document (each through `number`).

    Parameters
    ----------
    value : the value as given (a list).
    label : how the message names it; an item is named label[index].

    Returns
    -------
    list of float.

    Example
    -------
    >>> numbers([1, 2.5], "m.json: transfer")
    [1.0, 2.5]
    """
    if not isinstance(value, list) or not value:
        raise InputError(f"{label} must be a non-empty list of numbers")
    return [number(x, f"{label}[{index}]") for index, x in enumerate(value)]


def finite_vector(vector: np.ndarray, label: str, unit: bool = False) -> None:
    """InputError unless `vector` is a non-empty 1-d array of finite numbers (each in [0, 1]
    when `unit`): the arrays a value is built from in code rather than read.

    Parameters
    ----------
    vector : the array.
    label : how the message names it; an item is named label[index].
    unit : each value must lie in [0, 1].
    """
    if vector.ndim != 1 or len(vector) == 0:
        raise InputError(f"{label} must be a non-empty vector, got shape {vector.shape}")
    bad = np.flatnonzero(~np.isfinite(vector))
    if len(bad):
        raise InputError(f"{label}[{bad[0]}] is not finite ({vector[bad[0]]})")
    if unit:
        bad = np.flatnonzero((vector < 0) | (vector > 1))
        if len(bad):
            raise InputError(f"{label}[{bad[0]}] = {vector[bad[0]]:g} is outside [0, 1]")
