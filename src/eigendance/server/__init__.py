"""`eigendance serve` / `eigendance demo`: the web app's HTTP server (docs/design.md#server).

Every request first passes `server.guard` (Host, origin and content-type checks); every error
is a one-line JSON object ``{"error": "…"}``, 4xx for bad input, 500 for a failure of ours.
Routes:

- ``GET /api/config`` — rules shared with the page (gallery sizes, the accepted suffixes).
- ``GET /api/library`` — meshes (with basis state), songs and mappings.
- ``GET /api/meshes/{id}/basis.bin`` — the basis as a binary bundle (`binary.basis_bundle`).
- ``GET /api/songs/{id}/spectrogram.bin``, ``GET /api/songs/{id}/audio``.
- ``GET /api/jobs/{id}`` and ``/api/jobs/{id}/events`` (server-sent events) — the progress of a
  basis solve or an export.
- ``POST /api/upload?name=FILE`` — raw body; mesh, audio or mapping JSON by suffix and content.
- ``POST /api/gallery`` ``{mesh, song, size}`` and ``POST /api/breed`` ``{parents, size, seed}``
  — mappings from `eigendance.music` (the one implementation).
- ``GET /api/mappings/{id}``, ``POST /api/mappings?name=`` — saved mappings.
- ``DELETE /api/meshes/{id}``, ``/api/songs/{id}``, ``/api/mappings/{id}``, ``/api/rigs/{id}``
  — remove an item (`Library.remove`).
- ``GET /api/rigs/{id}`` (description), ``/rig.bin`` (`binary.rig_bundle`), ``/skeleton.json``;
  ``POST /api/rigs/{id}/stiffness``, ``/pose``, ``/reset`` (edits answering a new bundle);
  ``POST /api/rig-gallery`` ``{rig, song, size}`` — the initial gallery of mode mappings.
- ``POST /api/export`` ``{mesh | rig, song, mapping, format, start, duration, size?, fps?}`` —
  part of a song as MP4 or glb, rendered in a job (`export_route`); ``GET /api/exports/{id}``
  downloads it.
- ``GET /api/presets`` (?q=, ?favourites=1), ``POST /api/presets`` ``{name, mapping | palette,
  tags, favourite, thumbnail, mesh, replace}``, ``GET``/``PATCH``/``DELETE
  /api/presets/{name}``, ``…/thumbnail.png``, ``…/file`` — presets (`preset_routes`).
- ``GET /api/show/state``, ``/api/show/events``; ``POST /api/show/control`` ``{action,
  value}``, ``/api/show/clock`` — show mode (`show_routes`); ``GET /show`` — the output page.
- ``/`` — the built front end (package folder ``static/``, built from ``web/`` by ``make``).
"""
