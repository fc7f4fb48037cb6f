"""Messages from a worker process to the server over a socket, received without holding the
interpreter's lock for their size (docs/design.md#server).

A rig's analysis is hundreds of MB (its modal skin and its bundle): unpickled from one message,
as `multiprocessing` does, its copies held the GIL for 0.24 s. Here a message is pickled with
protocol 5: numpy arrays are taken out of band (`pickle.PickleBuffer`), and `bytes` of at least
BIG bytes are taken out by reference (`persistent_id`); both travel raw after the small pickled
rest. The receiver reads each one straight into its final memory — an empty numpy buffer
(`recv_into`) or a new `bytes` (`recv` with MSG_WAITALL) — in system calls that let go of the
GIL, and unpickles the rest over them without a copy.
"""

from __future__ import annotations

import io
import pickle
import socket
import struct

import numpy as np

BIG = 1 << 20  # bytes objects from this size travel out of band
HEAD = struct.Struct("<QQQ")  # pickled rest, bytes objects, buffers


def send(connection: socket.socket, message) -> None:
    """Send a picklable message (module docstring).

    Parameters
    ----------
    connection : a connected stream socket.
    message : the object.
    """
    taken: list[bytes] = []
    buffers: list[pickle.PickleBuffer] = []

    class Pickler(pickle.Pickler):
        def persistent_id(self, obj):
            if type(obj) is bytes and len(obj) >= BIG:
                taken.append(obj)
                return len(taken) - 1
            return None

    file = io.BytesIO()
    Pickler(file, protocol=5, buffer_callback=buffers.append).dump(message)
    raws = [buffer.raw() for buffer in buffers]
    sizes = [len(value) for value in taken] + [raw.nbytes for raw in raws]
    connection.sendall(HEAD.pack(file.tell(), len(taken), len(raws)) +
                       struct.pack(f"<{len(sizes)}Q", *sizes) + file.getbuffer())
    for value in [*taken, *raws]:
        connection.sendall(value)


def receive(connection: socket.socket):
    """Receive a message sent by `send`.

    Parameters
    ----------
    connection : the other end's socket (blocking).

    Returns
    -------
    The object; EOFError when the sender closed or died first.
    """
    length, count, buffered = HEAD.unpack(_bytes(connection, HEAD.size))
    sizes = struct.unpack(f"<{count + buffered}Q", _bytes(connection, 8 * (count + buffered)))
    data = _bytes(connection, length)
    taken = [_bytes(connection, size) for size in sizes[:count]]
    buffers = []
    for size in sizes[count:]:
        buffer = np.empty(size, np.uint8)
        view, done = memoryview(buffer), 0
        while done < size:
            got = connection.recv_into(view[done:], size - done, socket.MSG_WAITALL)
            if not got:
                raise EOFError("the worker process ended")
            done += got
        buffers.append(buffer)

    class Unpickler(pickle.Unpickler):
        def persistent_load(self, key):
            return taken[key]

    return Unpickler(io.BytesIO(data), buffers=buffers).load()


def _bytes(connection: socket.socket, size: int) -> bytes:
    """`size` bytes read into a new bytes object (the GIL released while they arrive)."""
    parts, left = [], size
    while left:
        part = connection.recv(left, socket.MSG_WAITALL)
        if not part:
            raise EOFError("the worker process ended")
        parts.append(part)
        left -= len(part)
    return parts[0] if len(parts) == 1 else b"".join(parts)  # several only after a signal
