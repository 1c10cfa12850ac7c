"""`physcensis report FOLDER --serve`: the report's folder over HTTP on 127.0.0.1, so the page's 3-D viewer can load
each scene.glb by its relative URL (a page opened from the file system cannot).

Read-only and local: bound to 127.0.0.1 only, GET and HEAD only, and only regular files inside the folder, read as
the report reads them (no symbolic link on the way, no `..`, no hidden entry, at most MAX_SERVED_BYTES). A folder is
never listed: `/` and `name/` serve that folder's index.html, if any. A request whose Host is not this server's
address is refused, so a web page cannot reach the server through a name of its own that resolves to 127.0.0.1.
Every answer carries the report page's own Content-Security-Policy, so an HTML file in the folder that physcensis
did not write can run none of its scripts at this address.
"""

from __future__ import annotations

import mimetypes
import os
import stat
import threading
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from urllib.parse import unquote, urlsplit

from physcensis.fileio import BoundError, read_in_folder
from physcensis.gallery.cards import GalleryError

HOST = "127.0.0.1"
MAX_SERVED_BYTES = 512 * 2**20
TYPES = {
    ".html": "text/html; charset=utf-8",
    ".json": "application/json",
    ".jsonl": "application/json",
    ".glb": "model/gltf-binary",
    ".png": "image/png",
    ".jpg": "image/jpeg",
    ".jpeg": "image/jpeg",
}


class ReportServer(ThreadingHTTPServer):
    """A server of one report folder; `url` is the page's address."""

    daemon_threads = True

    def __init__(self, folder: Path, port: int, policy: str) -> None:
        self.folder = folder.resolve()
        self.policy = policy
        try:
            super().__init__((HOST, port), _Handler)
        except OSError as exc:
            raise GalleryError(f"cannot serve on {HOST}:{port} ({exc.strerror or exc}); pick another --port") from None

    @property
    def port(self) -> int:
        return int(self.server_address[1])

    @property
    def url(self) -> str:
        return f"http://{HOST}:{self.port}/"

    def start(self) -> threading.Thread:
        """Serve in a background thread (tests, benchmarks); `shutdown()` then `server_close()` stop it."""
        thread = threading.Thread(target=self.serve_forever, name="physcensis-report-server", daemon=True)
        thread.start()
        return thread


def report_server(folder: Path, port: int = 0, policy: str | None = None) -> ReportServer:
    """A server of `folder` on 127.0.0.1 (`port` 0: a free one), not yet serving. `policy` is the header
    Content-Security-Policy of every answer, by default the one of a report page as this version writes it."""
    if not folder.is_dir():
        raise GalleryError(f"{folder}: {'is not a folder' if folder.exists() else 'no such folder'}")
    if not 0 <= port <= 65535:
        raise GalleryError(f"--port {port}: not a port number (0 to 65535; 0 picks a free one)")
    if policy is None:
        from physcensis.gallery.page import page_policy

        policy = page_policy(served=True)
    return ReportServer(folder, port, policy)


def resolve_request(folder: Path, target: str) -> tuple[HTTPStatus, str]:
    """The file a request's target names, as a path relative to `folder`, with 200; or the refusal's status (404 for
    what is not there or not served, 403 for a symbolic link) with why."""
    path = unquote(urlsplit(target).path)
    if not path.startswith("/") or "\0" in path or "\\" in path:
        return HTTPStatus.NOT_FOUND, "not a path"
    parts = path[1:].split("/")
    if parts[-1] == "":
        parts[-1] = "index.html"  # a folder's page, never its listing
    if any(part in ("", ".", "..") or part.startswith(".") for part in parts):
        return HTTPStatus.NOT_FOUND, "not a path inside the folder"
    current = folder
    for part in parts:
        current = current / part
        try:
            info = current.lstat()
        except OSError:
            return HTTPStatus.NOT_FOUND, "no such file"
        if stat.S_ISLNK(info.st_mode):
            return HTTPStatus.FORBIDDEN, "a symbolic link; not followed"
    if not stat.S_ISREG(info.st_mode):
        return HTTPStatus.NOT_FOUND, "not a regular file"
    return HTTPStatus.OK, "/".join(parts)


class _Handler(BaseHTTPRequestHandler):
    server: ReportServer
    server_version = "physcensis-report"
    sys_version = ""

    def do_GET(self) -> None:  # the name http.server calls
        self._answer(body=True)

    def do_HEAD(self) -> None:
        self._answer(body=False)

    def _refuse_method(self) -> None:
        self._send(HTTPStatus.METHOD_NOT_ALLOWED, b"only GET and HEAD\n", "text/plain", True, {"Allow": "GET, HEAD"})

    do_POST = do_PUT = do_DELETE = do_PATCH = do_OPTIONS = _refuse_method

    def _answer(self, *, body: bool) -> None:
        if not self._host_is_mine():
            self._send(HTTPStatus.FORBIDDEN, b"unknown host\n", "text/plain", body)
            return
        status, found = resolve_request(self.server.folder, self.path)
        if status != HTTPStatus.OK:
            self._send(status, f"{status.phrase}: {found}\n".encode(), "text/plain", body)
            return
        try:
            data = read_in_folder(self.server.folder, found, MAX_SERVED_BYTES)
        except BoundError as exc:
            self._send(HTTPStatus.FORBIDDEN, f"refused: {exc}\n".encode(), "text/plain", body)
            return
        self._send(HTTPStatus.OK, data, _content_type(found), body)

    def _host_is_mine(self) -> bool:
        host = (self.headers.get("Host") or "").strip().lower()
        return host in {f"{HOST}:{self.server.port}", f"localhost:{self.server.port}"}

    def _send(
        self, status: HTTPStatus, data: bytes, kind: str, body: bool, extra: dict[str, str] | None = None
    ) -> None:
        self.send_response(status)
        headers = {
            "Content-Type": kind,
            "Content-Length": str(len(data)),
            "Content-Security-Policy": self.server.policy,
            "X-Content-Type-Options": "nosniff",
            "Cache-Control": "no-store",
            "Referrer-Policy": "no-referrer",
            **(extra or {}),
        }
        for name, value in headers.items():
            self.send_header(name, value)
        self.end_headers()
        if body:
            self.wfile.write(data)

    def log_message(self, format: str, *args: object) -> None:
        pass  # quiet: the command prints its address, not every request


def _content_type(relative: str) -> str:
    suffix = os.path.splitext(relative)[1].lower()
    return TYPES.get(suffix) or mimetypes.guess_type(relative)[0] or "application/octet-stream"
