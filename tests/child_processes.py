"""Helpers for tests that run the command line in a child process."""

from __future__ import annotations

import signal


def ctrl_c_as_in_a_terminal() -> None:
    """In the child (a `preexec_fn`): Ctrl-C (SIGINT) handled as a terminal delivers it. A pytest-xdist worker
    ignores SIGINT and a child inherits that, so without this a server under test would never hear it."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
