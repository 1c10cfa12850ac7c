"""`physcensis report FOLDER --serve`: the folder over HTTP on 127.0.0.1, read-only, regular files inside it only.

Each request is sent raw (http.client sends the path as given), so `..` and its encodings reach the server."""

from __future__ import annotations

import http.client
import os
import re
import signal
import socket
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.gallery import INDEX_NAME, write_report
from physcensis.gallery.serve import HOST, ReportServer, report_server
from tests.child_processes import ctrl_c_as_in_a_terminal
from tests.gallery.folders import glb_scene_folder

SECRET = "SECRET-TOKEN-0451"


@pytest.fixture(scope="module")
def served(tmp_path_factory: pytest.TempPathFactory) -> Iterator[ReportServer]:
    """A report folder (one scene with a glb) served on a free port; beside it, a secret it must never hand out."""
    tmp_path = tmp_path_factory.mktemp("served")
    (tmp_path / "secret.txt").write_text(SECRET)
    folder = tmp_path / "report"
    glb_scene_folder(folder / "scene")
    write_report(folder)
    (folder / "scene" / "out.txt").symlink_to(tmp_path / "secret.txt")
    (folder / "outside").symlink_to(tmp_path, target_is_directory=True)
    (folder / "scene" / "inside.png").symlink_to(folder / "scene" / "render.png")
    (folder / "scene" / ".hidden").write_text("hidden")
    server = report_server(folder)
    server.start()
    yield server
    server.shutdown()
    server.server_close()


def request(
    server: ReportServer, path: str, method: str = "GET", host: str | None = None
) -> tuple[int, dict[str, str], bytes]:
    connection = http.client.HTTPConnection(HOST, server.port, timeout=10)
    try:
        connection.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
        connection.putheader("Host", host or f"{HOST}:{server.port}")
        connection.endheaders()
        response = connection.getresponse()
        return response.status, dict(response.getheaders()), response.read()
    finally:
        connection.close()


def test_the_page_and_the_scene_files_are_served_with_the_page_policy(served: ReportServer) -> None:
    status, headers, body = request(served, "/")
    assert status == 200 and headers["Content-Type"].startswith("text/html")
    assert body == (served.folder / INDEX_NAME).read_bytes()
    assert "script-src 'sha256-" in headers["Content-Security-Policy"]
    assert "frame-ancestors 'none'" in headers["Content-Security-Policy"]
    assert headers["X-Content-Type-Options"] == "nosniff"
    status, headers, body = request(served, "/scene/scene.glb")
    assert (status, headers["Content-Type"]) == (200, "model/gltf-binary") and body.startswith(b"glTF")
    status, headers, body = request(served, "/scene/scene.glb", method="HEAD")
    assert status == 200 and body == b"" and int(headers["Content-Length"]) > 100
    assert request(served, "/scene/render%2Epng")[0] == 200  # an encoded name is the same name


def test_it_is_bound_to_the_loopback_address_only(served: ReportServer) -> None:
    assert served.server_address[0] == "127.0.0.1" and served.url == f"http://127.0.0.1:{served.port}/"


@pytest.mark.parametrize(
    "path",
    [
        "/../secret.txt",
        "/%2e%2e/secret.txt",
        "/scene/../../secret.txt",
        "/scene/%2E%2E/%2e%2e/secret.txt",
        "/scene/..%2f..%2fsecret.txt",
        "/..\\secret.txt",
        "//etc/passwd",
        "/etc/passwd",
        "/scene/%00",
    ],
)
def test_a_path_out_of_the_folder_is_not_found(served: ReportServer, path: str) -> None:
    status, _, body = request(served, path)
    assert status == 404 and SECRET.encode() not in body


@pytest.mark.parametrize("path", ["/scene/out.txt", "/outside/secret.txt", "/scene/inside.png"])
def test_a_symbolic_link_is_forbidden_even_one_inside_the_folder(served: ReportServer, path: str) -> None:
    status, _, body = request(served, path)
    assert status == 403 and SECRET.encode() not in body


@pytest.mark.parametrize("path", ["/scene/", "/scene", "/.physcensis.json", "/scene/.hidden", "/nothing.png"])
def test_no_folder_is_listed_and_no_hidden_or_missing_file_is_served(served: ReportServer, path: str) -> None:
    status, _, body = request(served, path)
    assert status == 404 and b"scene.glb" not in body


@pytest.mark.parametrize("method", ["POST", "PUT", "DELETE", "PATCH", "OPTIONS"])
def test_only_get_and_head_are_answered(served: ReportServer, method: str) -> None:
    status, headers, _ = request(served, "/index.html", method=method)
    assert status == 405 and headers["Allow"] == "GET, HEAD"


def test_another_host_name_is_refused(served: ReportServer) -> None:
    """A web page whose own name resolves to 127.0.0.1 (DNS rebinding) gets nothing."""
    assert request(served, "/", host=f"attacker.example:{served.port}")[0] == 403
    assert request(served, "/", host=f"localhost:{served.port}")[0] == 200


def test_a_port_in_use_is_one_error_line(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "scene")
    with socket.socket() as taken:
        taken.bind((HOST, 0))
        taken.listen()
        port = taken.getsockname()[1]
        result = CliRunner().invoke(app, ["report", str(tmp_path), "--serve", "--port", str(port)])
    assert result.exit_code == 2 and f"cannot serve on 127.0.0.1:{port}" in result.output
    assert "Traceback" not in result.output and not (tmp_path / INDEX_NAME).exists()


def test_a_port_without_serve_is_refused(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "scene")
    result = CliRunner().invoke(app, ["report", str(tmp_path), "--port", "8123"])
    assert result.exit_code == 2 and "only for --serve" in result.output


@pytest.mark.long
def test_the_command_prints_its_address_serves_and_stops_on_ctrl_c(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "scene")
    command = [sys.executable, "-m", "physcensis", "report", str(tmp_path), "--serve"]
    env = {**os.environ, "COLUMNS": "300"}
    with subprocess.Popen(
        command,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        preexec_fn=ctrl_c_as_in_a_terminal,
    ) as process:
        try:
            assert process.stdout is not None
            line = process.stdout.readline()
            match = re.search(r"serving it at http://127\.0\.0\.1:(\d+)/", line)
            assert match, line
            connection = http.client.HTTPConnection(HOST, int(match.group(1)), timeout=10)
            connection.request("GET", "/scene/scene.glb")
            response = connection.getresponse()
            assert response.status == 200 and response.read().startswith(b"glTF")
            connection.close()
            process.send_signal(signal.SIGINT)
            out, err = process.communicate(timeout=90)  # a loaded machine: two test workers and more
        finally:
            if process.poll() is None:
                process.kill()
    assert process.returncode == 0, err
    assert "stopped serving" in out and "Traceback" not in err
