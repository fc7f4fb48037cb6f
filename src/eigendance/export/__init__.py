"""Exports of the motion to files other tools open (video, glTF, point caches, USD).

Empty until the export issue lands; see docs/design.md#exports.
"""
