"""The one exception type users see: its message is a complete one-line explanation."""


class EigendanceError(ValueError):
    """Bad input or an impossible request. The CLI prints ``str(error)`` on one line, exit 1."""
