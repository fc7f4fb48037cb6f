"""What one connection may take from the server: time to send its request, and a place among a
bounded number of open connections (docs/design.md#server).

uvicorn closes a connection that stays idle after an answer (``timeout_keep_alive``) and bounds
the size of a request's headers (h11, 16 KiB), but it waits forever for headers that come a byte
at a time or never, and for a body that stops; its ``limit_concurrency`` answers 503 only once
a request's headers have arrived, to every client alike. So clients that open connections and
never finish their headers (slowloris) would hold every file descriptor the process may open,
and the page's own requests would wait. `Connection`, uvicorn's h11 protocol with three more
rules, closes:

- a connection whose request line and headers have not all arrived HEADER_SECONDS after it
  opened (or after its previous answer): 408 with one line of JSON when part of them came;
- a connection that sends no byte of a body we are waiting for during BODY_IDLE_SECONDS;
- beyond MAX_CONNECTIONS open connections, the one that has waited longest for its headers,
  to make room for the new one (so a flood of idle connections cannot shut out the page); when
  every open connection is busy with a request, the new one is answered 503.

Requests that are not HTTP get uvicorn's refusal as one line of JSON (400, or 431 for headers
beyond 16 KiB). The checks run once a second per connection, on the event loop, and cost
microseconds.
"""

from __future__ import annotations

import json
import sys

import h11
from uvicorn.protocols.http.h11_impl import H11Protocol

HEADER_SECONDS = 10.0  # a request line and its headers arrive within this (nginx: 60 s, per read)
BODY_IDLE_SECONDS = 30.0  # a body we wait for may pause this long (nginx: 60 s)
MAX_CONNECTIONS = 256  # open at once (a browser opens at most 6 per server)
CHECK_SECONDS = 1.0


def json_response(status: int, reason: str, message: str) -> bytes:
    """A complete HTTP/1.1 response with one line of JSON that closes the connection.

    Parameters
    ----------
    status : the status code.
    reason : its reason phrase.
    message : the error.

    Returns
    -------
    bytes to write on the transport.

    Example
    -------
    >>> json_response(408, "Request Timeout", "too slow").split(b"\\r\\n")[0]
    b'HTTP/1.1 408 Request Timeout'
    """
    body = json.dumps({"error": message}, separators=(",", ":")).encode()
    return (f"HTTP/1.1 {status} {reason}\r\ncontent-type: application/json\r\n"
            f"content-length: {len(body)}\r\nconnection: close\r\n\r\n").encode() + body


class Connection(H11Protocol):
    """uvicorn's h11 protocol with header and body timeouts and a bound on open connections
    (see the module docstring). Given to uvicorn as ``Config(http=Connection)``."""

    def connection_made(self, transport) -> None:
        """A new connection: its header time starts; beyond MAX_CONNECTIONS, make room.

        Parameters
        ----------
        transport : asyncio's transport of the connection.
        """
        super().connection_made(transport)
        self.waiting_since = self.last_data = self.loop.time()
        self.watch = self.loop.call_later(CHECK_SECONDS, self._check)
        if len(self.connections) > MAX_CONNECTIONS:
            self._make_room()

    def connection_lost(self, exc) -> None:
        """The connection closed: stop watching it.

        Parameters
        ----------
        exc : the error that closed it, or None.
        """
        self.watch.cancel()
        super().connection_lost(exc)

    def data_received(self, data: bytes) -> None:
        """Bytes from the client: the body's idle time starts again.

        Parameters
        ----------
        data : the bytes.
        """
        self.last_data = self.loop.time()
        super().data_received(data)

    def on_response_complete(self) -> None:
        """An answer is sent: the next request's headers are awaited from now."""
        self.waiting_since = self.loop.time()
        super().on_response_complete()

    @property
    def awaiting_headers(self) -> bool:
        """Whether no request is in progress: the connection waits for a request's headers."""
        return self.cycle is None or self.cycle.response_complete

    def _check(self) -> None:
        """Close the connection past its header or body time; else look again later."""
        if self.transport.is_closing():
            return
        now = self.loop.time()
        if self.awaiting_headers:
            if now - self.waiting_since > HEADER_SECONDS:
                self._close(408, "Request Timeout", "the request's headers did not arrive "
                            f"within {HEADER_SECONDS:.0f} s")
                return
        elif self.conn.their_state is h11.SEND_BODY:
            if self.flow.read_paused:  # we are not reading: the app is busy with the body
                self.last_data = now
            elif now - self.last_data > BODY_IDLE_SECONDS:
                self.transport.close()  # the app's receive() sees the client gone
                return
        self.watch = self.loop.call_later(CHECK_SECONDS, self._check)

    def _close(self, status: int, reason: str, message: str) -> None:
        """Close; with a JSON answer when part of a request came (a silent connection, such as a
        browser's spare one, is closed without one)."""
        if self.conn.trailing_data[0] and self.conn.our_state is h11.IDLE:
            self.transport.write(json_response(status, reason, message))
        self.transport.close()

    def _make_room(self) -> None:
        """Beyond MAX_CONNECTIONS: close the connection that has waited longest for its
        headers, or refuse this one when every other is busy with a request."""
        idle = [other for other in self.connections
                if other is not self and isinstance(other, Connection)
                and other.awaiting_headers and not other.transport.is_closing()]
        if idle:
            min(idle, key=lambda other: other.waiting_since).transport.close()
        else:
            self.transport.write(json_response(
                503, "Service Unavailable",
                f"the server has {MAX_CONNECTIONS} connections open; try again"))
            self.transport.close()

    def send_400_response(self, msg: str) -> None:
        """uvicorn's answer to a request h11 cannot parse, as one line of JSON (431 for headers
        larger than h11's limit).

        Parameters
        ----------
        msg : uvicorn's message (h11's own reason is used).
        """
        problem = sys.exc_info()[1]  # called while uvicorn handles h11's RemoteProtocolError
        status = getattr(problem, "error_status_hint", 400)
        detail = f" ({problem})" if problem is not None and str(problem) else ""
        message = f"not a valid HTTP request{detail}"
        reason = {431: "Request Header Fields Too Large"}.get(status, "Bad Request")
        self.transport.write(json_response(status, reason, message[:200]))
        self.transport.close()
