"""The library's memory budget: what an item holds, and which items to drop when over budget
(docs/design.md#server).

Every item of the library (a mesh with its basis and bundles, a song with its spectrogram, a
rig with its modes, a mapping) is charged the bytes of the arrays and bundles it keeps. The
items form a least-recently-used list: each lookup moves an item to the end, and when the total
exceeds the budget the items at the front are dropped until it fits — except the ones in use
(a basis being solved), which are never dropped.
"""

from __future__ import annotations

import dataclasses
import sys
import threading
from collections import OrderedDict

import numpy as np

from eigendance.errors import InputError
from eigendance.limits import size_text

DEFAULT_BUDGET = 4 << 30  # bytes


def footprint(*objects, depth: int = 6) -> int:
    """Bytes held by numpy arrays and bytes objects reachable from `objects` through dataclass
    fields, object attributes, dicts, lists and tuples (each counted once).

    Parameters
    ----------
    *objects : what to measure.
    depth : how deep to follow references.

    Returns
    -------
    int, bytes.
    """
    seen: set[int] = set()

    def size(value, level: int) -> int:
        if id(value) in seen or level > depth or value is None:
            return 0
        seen.add(id(value))
        if isinstance(value, np.ndarray):
            base = value.base if isinstance(value.base, np.ndarray) else value
            if base is not value:  # a view: count the array it looks into, once
                if id(base) in seen:
                    return 0
                seen.add(id(base))
            return int(base.nbytes)
        if isinstance(value, bytes | bytearray):
            return len(value)
        if isinstance(value, str | int | float | bool | complex):
            return sys.getsizeof(value)
        if isinstance(value, dict):
            return sum(size(v, level + 1) for v in value.values())
        if isinstance(value, list | tuple | set | frozenset):
            return sum(size(v, level + 1) for v in value)
        if dataclasses.is_dataclass(value):
            return sum(size(getattr(value, f.name, None), level + 1)
                       for f in dataclasses.fields(value))
        attributes = getattr(value, "__dict__", None)
        return sum(size(v, level + 1) for v in attributes.values()) if attributes else 0

    return sum(size(value, 0) for value in objects)


class Budget:
    """Charges per key (bytes) in least-recently-used order, within `limit` bytes.

    Parameters
    ----------
    limit : the budget, bytes.

    Example
    -------
    >>> budget = Budget(100)
    >>> budget.charge("a", 60), budget.charge("b", 30), budget.touch("a")
    ([], [], None)
    >>> budget.charge("c", 40)   # over by 30: "b" is the least recently used
    ['b']
    >>> budget.charge("d", 90, busy=lambda key: key == "a")   # "a" (60) is in use: cannot fit
    >>> budget.used, list(budget.sizes)
    (100, ['a', 'c'])
    """

    def __init__(self, limit: int = DEFAULT_BUDGET):
        self.limit = int(limit)
        self.sizes: OrderedDict[str, int] = OrderedDict()
        self.lock = threading.Lock()

    @property
    def used(self) -> int:
        """Bytes charged now."""
        return sum(self.sizes.values())

    def touch(self, key: str) -> None:
        """Mark `key` as the most recently used.

        Parameters
        ----------
        key : a charged key (others are ignored).
        """
        with self.lock:
            if key in self.sizes:
                self.sizes.move_to_end(key)

    def charge(self, key: str, size: int, busy=lambda key: False) -> list[str] | None:
        """Charge `key` `size` bytes (now the most recently used) and drop what no longer fits.

        Parameters
        ----------
        key : the item's key.
        size : its bytes.
        busy : key → whether that key is in use (never dropped).

        Returns
        -------
        list of the keys dropped so that the total fits, least recently used first (never `key`
        itself nor a busy one); None, and nothing changed, when it cannot fit even so.
        """
        with self.lock:
            others = [(other, used) for other, used in self.sizes.items() if other != key]
            kept = sum(used for other, used in others if busy(other))
            if kept + size > self.limit:
                return None
            self.sizes[key] = int(size)
            self.sizes.move_to_end(key)
            dropped, total = [], sum(self.sizes.values())
            for other, used in others:
                if total <= self.limit:
                    break
                if not busy(other):
                    del self.sizes[other]
                    total -= used
                    dropped.append(other)
            return dropped

    def release(self, key: str) -> None:
        """Forget a key's charge (an item removed).

        Parameters
        ----------
        key : the key.
        """
        with self.lock:
            self.sizes.pop(key, None)


def refusal(size: int, limit: int, what: str) -> InputError:
    """Why an item of `size` bytes cannot be charged: more than the whole budget (413), or more
    than the bases being computed leave free (409: wait for them, or remove items).

    Parameters
    ----------
    size : the item's bytes.
    limit : the budget, bytes.
    what : the item in words ("cat.obj: a basis of 150 harmonics of 7949 vertices").

    Returns
    -------
    InputError to raise.
    """
    if size > limit:
        return InputError(f"{what} would take {size_text(size)} of memory, more than the "
                          f"library's budget of {size_text(limit)}", status=413)
    return InputError(f"{what} would take {size_text(size)} of memory; the library's budget "
                      f"of {size_text(limit)} is held by bases being computed (wait for them "
                      "or remove some)", status=409)
