"""One item per distinct content: the library's de-duplication (docs/design.md#server).

A content key names what an item was made from: ("mesh", suffix, SHA-256, k), ("audio", suffix,
SHA-256), ("rig", suffix, SHA-256), ("mapping", SHA-256 of its fields). `Contents` maps each key
to the id of its item; a thread adding a content first `claim`s its key, so that two uploads of
the same bytes at once make one item: the second waits, then answers the first's item.
"""

from __future__ import annotations

import threading
from collections.abc import Callable


class Contents:
    """Content keys → item ids, and the keys being added now.

    Parameters
    ----------
    lock : the library's lock (held while the keys are read or changed).

    Example
    -------
    >>> contents = Contents(threading.RLock())
    >>> contents.claim(("audio", ".wav", "ab"), lambda item_id: None)   # nobody has it: ours
    >>> contents.add(("audio", ".wav", "ab"), "song1"); contents.release(("audio", ".wav", "ab"))
    >>> contents.claim(("audio", ".wav", "ab"), lambda item_id: item_id.upper())
    'SONG1'
    """

    def __init__(self, lock):
        self.lock = lock
        self.ids: dict[tuple, str] = {}  # content key → item id
        self.arriving: dict[tuple, threading.Event] = {}  # keys being added now

    def claim(self, key: tuple, find: Callable):
        """The item with content `key`, or None after reserving `key` for the caller (who must
        `release` it). Waits while another thread adds the same content.

        Parameters
        ----------
        key : the content key.
        find : item id → the item, or None when it is gone.

        Returns
        -------
        The item already there, or None (the caller adds it).
        """
        while True:
            with self.lock:
                item_id = self.ids.get(key)
                if item_id is not None:
                    item = find(item_id)
                    if item is not None:
                        return item
                waiting = self.arriving.get(key)
                if waiting is None:
                    self.arriving[key] = threading.Event()
                    return None
            waiting.wait()

    def release(self, key: tuple) -> None:
        """End a `claim`: threads waiting for the same content look again.

        Parameters
        ----------
        key : the content key claimed.
        """
        with self.lock:
            self.arriving.pop(key).set()

    def add(self, key: tuple | None, item_id: str) -> None:
        """Record that `item_id` holds the content `key` (nothing for None).

        Parameters
        ----------
        key : the content key, or None.
        item_id : the item's id.
        """
        if key is not None:
            with self.lock:
                self.ids[key] = item_id

    def find(self, key: tuple) -> str | None:
        """The id of the item holding the content `key`.

        Parameters
        ----------
        key : the content key.

        Returns
        -------
        str or None.
        """
        with self.lock:
            return self.ids.get(key)

    def forget(self, key: tuple | None, item_id: str) -> None:
        """Forget `key` if `item_id` holds it (an item removed).

        Parameters
        ----------
        key : the content key, or None.
        item_id : the item's id.
        """
        with self.lock:
            if key is not None and self.ids.get(key) == item_id:
                del self.ids[key]
