"""What a request may hold, and how its JSON is read and answered (docs/design.md#server).

JSON bodies are at most JSON_LIMIT bytes, refused from their Content-Length before they are read,
and parsed with `files.read_json`'s rules (nesting within the recursion limit, integers of at
most 40 digits) and without NaN or Infinity. A mapping sent to be bred or saved holds at most
MAX_BANDS transfer values and MAX_HARMONICS amplification and palette values
(`inputs.mapping.check_mapping_size`), so that an answer is at most a few MB. Parsing and
answers of many numbers run in a worker thread.
"""

from __future__ import annotations

import json

from starlette.exceptions import HTTPException
from starlette.requests import Request
from starlette.responses import Response

from eigendance.errors import InputError
from eigendance.files import JSON_INTEGER_DIGITS
from eigendance.music.gallery import check_gallery_size
from eigendance.server.workers import in_worker

JSON_LIMIT = 8 << 20  # bytes of a JSON request body


async def json_body(request: Request):
    """The request's JSON document, read within the limits (see the module docstring).

    Parameters
    ----------
    request : a request with Content-Type application/json (else 415), at most JSON_LIMIT
        bytes (else 413).

    Returns
    -------
    The parsed document (`parse_json`, in a worker thread).
    """
    content_type = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if content_type != "application/json":
        raise HTTPException(415, "send the request body as application/json")
    too_large = HTTPException(413, f"the request body is larger than {JSON_LIMIT >> 20} MiB")
    declared = request.headers.get("content-length", "")
    if declared.isdigit() and int(declared) > JSON_LIMIT:
        raise too_large
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > JSON_LIMIT:
            raise too_large
        chunks.append(chunk)
    return await in_worker(parse_json, b"".join(chunks))


def _json_integer(text: str) -> int:
    if len(text) > JSON_INTEGER_DIGITS:
        raise InputError(f"the request body holds an integer of {len(text.lstrip('-'))} "
                         f"digits (at most {JSON_INTEGER_DIGITS})")
    return int(text)


def _json_constant(name: str):
    raise InputError(f"the request body holds {name}, which JSON does not allow")


def parse_json(body: bytes):
    """A JSON document with the rules of `files.read_json`: UTF-8, nesting within Python's
    recursion limit, integers of at most JSON_INTEGER_DIGITS digits; no NaN or Infinity.

    Parameters
    ----------
    body : the request's bytes.

    Returns
    -------
    The parsed document; InputError (400) naming what is wrong.
    """
    try:
        return json.loads(body, parse_int=_json_integer, parse_constant=_json_constant)
    except InputError:
        raise
    except RecursionError:
        raise InputError("the request body is nested too deeply") from None
    except ValueError:  # UnicodeDecodeError and JSONDecodeError
        raise InputError("the request body is not valid JSON") from None


def json_answer(document, status: int = 200) -> Response:
    """A JSON response (rendered as JSONResponse does); call it in a worker thread when the
    document is large.

    Parameters
    ----------
    document : anything json.dumps takes (no NaN).
    status : the HTTP status.

    Returns
    -------
    Response, application/json.
    """
    return Response(json.dumps(document, ensure_ascii=False, allow_nan=False,
                               separators=(",", ":")).encode(),
                    status_code=status, media_type="application/json")


async def answer(make, status: int = 200) -> Response:
    """A JSON answer built and rendered in a worker thread.

    Parameters
    ----------
    make : () → the JSON document.
    status : the HTTP status.

    Returns
    -------
    Response, application/json.
    """
    return await in_worker(lambda: json_answer(make(), status))


def gallery_size(value) -> int:
    """A gallery size from a request, checked by the library's rule (`check_gallery_size`).

    Parameters
    ----------
    value : the size as sent.

    Returns
    -------
    int; HTTPException 400 with the rule's message.
    """
    try:
        return check_gallery_size(value)
    except InputError as problem:
        raise HTTPException(400, str(problem)) from None
