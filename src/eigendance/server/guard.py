"""What a request must be before the app sees it, so that no web page can use the server
(docs/design.md#server).

A page the user visits on another site can make the browser send requests to 127.0.0.1; the
browser only keeps it from reading most answers. So, for every request:

- Host: must name the address the server listens on — localhost, 127.0.0.1 or [::1] (and
  the name or address given to ``--host``) with the server's port. A site that makes its own
  name resolve to 127.0.0.1 (DNS rebinding) sends its own name and is refused (400).
- Fetch metadata: a request to ``/api/`` that the browser marks as coming from another site
  (``Sec-Fetch-Site: cross-site`` or ``same-site``: another port or subdomain) is refused
  (403), reads included (an ``<img>`` or ``<script>`` of another page); so is a comma-joined
  value naming either (``same-origin, cross-site``).
- Requests that change the library (any method but GET, HEAD, OPTIONS): an ``Origin`` header,
  where sent, must be this server's own; the content type must not be one a plain HTML form or
  a "simple" cross-origin fetch can send (``text/*``, ``multipart/form-data``,
  ``application/x-www-form-urlencoded``: 415) — the JSON routes ask for ``application/json``.
  Clients other than browsers (curl, scripts) send neither Origin nor Sec-Fetch-Site.
- A path with control characters (``%00``) is refused (400).
- A request that repeats a header the checks read (Host, Origin, Sec-Fetch-Site, Content-Type)
  is refused (400): a proxy or a browser may read the other copy than we did.

Any exception the app does not turn into an answer becomes a 500 with one line of JSON, and one
line on stderr: no traceback reaches the client or the terminal.
"""

from __future__ import annotations

import asyncio
import ipaddress
import json
import socket
import sys

from starlette.requests import ClientDisconnect

from eigendance.errors import one_line

DEFAULT_HOST = "127.0.0.1"
LOOPBACK_NAMES = ("localhost", "127.0.0.1", "[::1]")
WILDCARDS = ("", "0.0.0.0", "::")
SAFE_METHODS = ("GET", "HEAD", "OPTIONS")
# Headers the checks read: each may be sent once.
SINGLE_HEADERS = (b"host", b"origin", b"sec-fetch-site", b"content-type")
# Content types a cross-origin page can send without asking first (no CORS preflight).
FORM_TYPES = ("application/x-www-form-urlencoded", "multipart/form-data", "text/plain")


def is_loopback(host: str) -> bool:
    """Whether a --host value reaches only this machine.

    Parameters
    ----------
    host : the --host value.

    Returns
    -------
    bool.
    """
    if host.lower() == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def exposure_warning(host: str) -> str | None:
    """The warning to print when the server listens where other machines can reach it.

    Parameters
    ----------
    host : the --host value.

    Returns
    -------
    str (one line naming the risk), or None for a loopback address.
    """
    if is_loopback(host):
        return None
    where = "every address of this machine" if host in WILDCARDS else host
    return (f"eigendance: warning: listening on {where}: anyone who can reach this machine on "
            "the network can upload files, start solves and read the library (there is no "
            f"password); leave out --host to listen on {DEFAULT_HOST} only")


def bracketed(name: str) -> str:
    """An IPv6 address as a Host header writes it ([::1]); other names as they are.

    Parameters
    ----------
    name : a host name or address.

    Returns
    -------
    str.
    """
    return f"[{name}]" if ":" in name and not name.startswith("[") else name


class Hosts:
    """The Host header values the server answers: its names with its port.

    Parameters
    ----------
    host : the --host value. Loopback names are always accepted; a non-loopback address adds
        itself, and a wildcard (0.0.0.0, ::) adds any IP address and this machine's own names
        (names a rebinding site cannot send).
    port : the listening port, or None for any.
    """

    def __init__(self, host: str = DEFAULT_HOST, port: int | None = None):
        self.port = port
        self.names = {*LOOPBACK_NAMES, bracketed(host.lower())}
        self.any_address = host in WILDCARDS
        if self.any_address:
            self.names |= {name.lower() for name in (socket.gethostname(), socket.getfqdn())
                           if name}

    def accepts(self, header: str) -> bool:
        """Whether a request's Host header names this server.

        Parameters
        ----------
        header : the Host header's value.

        Returns
        -------
        bool.
        """
        name, port = split_host(header)
        if name is None or (self.port is not None and port != self.port):
            return False
        if name in self.names:
            return True
        if self.any_address:
            try:
                ipaddress.ip_address(name.strip("[]"))
                return True
            except ValueError:
                return False
        return False


def split_host(header: str) -> tuple[str | None, int | None]:
    """'Name:port' → ('name', port).

    Parameters
    ----------
    header : a Host header's value.

    Returns
    -------
    (name, port): port 80 when absent; (None, None) when malformed (a port of other than ASCII
    digits included: "²" is a digit to Python, not to HTTP).

    Example
    -------
    >>> split_host("LocalHost:8765"), split_host("[::1]"), split_host("localhost:8²")
    (('localhost', 8765), ('[::1]', 80), (None, None))
    """
    header = header.strip().lower()
    if header.endswith("]") or ":" not in header:
        name, port = header, "80"
    else:
        name, _, port = header.rpartition(":")
    if not name or not port.isascii() or not port.isdigit() or len(port) > 5:
        return None, None
    return name, int(port)


def header_of(scope, wanted: bytes) -> str | None:
    """A request's header, decoded as Latin-1.

    Parameters
    ----------
    scope : the ASGI scope.
    wanted : the header's name, lower-case bytes.

    Returns
    -------
    str, or None when it is absent.
    """
    for key, value in scope.get("headers", ()):
        if key == wanted:
            return value.decode("latin-1")
    return None


def refusal(scope, hosts: Hosts) -> tuple[int, str] | None:
    """Why a request must be refused (docs/design.md#server: Host, Sec-Fetch-Site, Origin, content
    type, control characters).

    Parameters
    ----------
    scope : the ASGI scope.
    hosts : the Host values the server answers.

    Returns
    -------
    (status, message), or None when the request may pass.
    """
    path = scope.get("path", "")
    if any(ord(character) < 32 or ord(character) == 127 for character in path):
        return 400, "the path holds control characters"
    names = [key for key, _ in scope.get("headers", ())]
    repeated = next((name for name in SINGLE_HEADERS if names.count(name) > 1), None)
    if repeated is not None:
        return 400, f"the request repeats the {repeated.decode().title()} header"
    host = header_of(scope, b"host")
    if host is None or not hosts.accepts(host):
        shown = one_line(host or "(none)", 80)
        return 400, (f"Host '{shown}' is not an address of this server (a page of another "
                     "site reached it through its own name)")
    # Each value of a comma-joined header counts (what a proxy joining two copies sends).
    site = (header_of(scope, b"sec-fetch-site") or "").lower()
    sites = {value.strip() for value in site.split(",")}
    if path.startswith("/api/") and sites & {"cross-site", "same-site"}:
        return 403, "requests from other sites are refused"
    if scope.get("method") in SAFE_METHODS:
        return None
    origin = header_of(scope, b"origin")
    if origin is not None and origin.lower() != f"{scope.get('scheme', 'http')}://{host.lower()}":
        return 403, f"requests from other sites are refused (Origin {one_line(origin, 80)})"
    content_type = (header_of(scope, b"content-type") or "").split(";")[0].strip().lower()
    if content_type in FORM_TYPES or content_type.startswith("text/"):
        return 415, (f"content type '{one_line(content_type, 60)}' is refused (send "
                     "application/json, or application/octet-stream for uploads)")
    return None


async def send_json(send, status: int, message: str) -> None:
    """Send a one-line JSON error response through ASGI.

    Parameters
    ----------
    send : the ASGI send callable.
    status : the HTTP status.
    message : the error.
    """
    body = json.dumps({"error": one_line(message)}, separators=(",", ":")).encode()
    await send({"type": "http.response.start", "status": status,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})


class Guard:
    """ASGI middleware: `refusal` before the app, one line of JSON for any failure after.

    Parameters
    ----------
    app : the ASGI app it guards.
    host : the --host value (`Hosts`).
    port : the listening port (None: any).
    scrub : callable(str) → str applied to failure messages (no library paths).
    """

    def __init__(self, app, host: str = DEFAULT_HOST, port: int | None = None,
                 scrub=lambda text: text):
        self.app, self.hosts, self.scrub = app, Hosts(host, port), scrub

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        try:
            refused = refusal(scope, self.hosts)
        except Exception as error:  # noqa: BLE001 - headers no check foresaw: refused, one line
            refused = 400, f"malformed request headers ({type(error).__name__})"
        if refused is not None:
            return await send_json(send, *refused)
        started = False

        async def tracked(message):
            nonlocal started
            started = started or message["type"] == "http.response.start"
            await send(message)

        try:
            await self.app(scope, receive, tracked)
        except ClientDisconnect:  # the client went away mid-request: nobody to answer
            return
        except asyncio.CancelledError:  # the server is ending and stopped waiting for it
            if not started:
                await send_json(send, 503, "the server is stopping")
            raise
        except Exception as error:  # noqa: BLE001 - every failure of ours ends in one line
            what = self.scrub(f"internal error ({type(error).__name__}: {one_line(error, 200)})")
            print(f"eigendance: {one_line(scope.get('method', ''))} "
                  f"{one_line(scope.get('path', ''), 100)}: {one_line(what)}", file=sys.stderr)
            if not started:
                await send_json(send, 500, what)
