"""The `assets` sub-app, through Typer's test runner."""

from __future__ import annotations

import json
import struct
from pathlib import Path

import trimesh
import yaml
from typer.testing import CliRunner

from physcensis.cli.assets import assets_app

runner = CliRunner()


def test_list_json_counts(cache_dir: Path) -> None:
    result = runner.invoke(assets_app, ["list", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["count"] == len(data["assets"]) >= 250
    assert len(data["categories"]) >= 45
    assert {"id", "category", "description", "size"} <= set(data["assets"][0])


def test_show_search_and_errors(cache_dir: Path) -> None:
    shown = runner.invoke(assets_app, ["show", "wine_glass_red_wine", "--json"])
    assert shown.exit_code == 0
    assert json.loads(shown.stdout)["container"] is True
    found = runner.invoke(assets_app, ["search", "a stack of books", "--json", "-k", "3"])
    payload = json.loads(found.stdout)
    assert len(payload["matches"]) == 3 and payload["matches"][0]["category"] == "book"
    missing = runner.invoke(assets_app, ["show", "no_such_asset"])
    assert missing.exit_code == 2  # an unknown id is a bad argument, as everywhere in the CLI
    assert "no asset with id" in missing.output and "Traceback" not in missing.output
    assert len(missing.output.strip().splitlines()) == 1


def test_import_reports_each_failure(tmp_path: Path, cache_dir: Path) -> None:
    (tmp_path / "cube.stl").write_bytes(trimesh.creation.box((0.05, 0.05, 0.05)).export(file_type="stl"))
    (tmp_path / "library.yaml").write_text(
        yaml.safe_dump({"assets": [{"file": "cube.stl", "category": "toy block"}, {"file": "nope.obj"}]})
    )
    result = runner.invoke(assets_app, ["import", str(tmp_path)])
    assert result.exit_code == 1
    assert (
        "ok  cube" in result.output and "nope.obj" in result.output and "1 assets imported, 1 failed" in result.output
    )


def test_gallery_writes_a_png(tmp_path: Path, cache_dir: Path) -> None:
    out = tmp_path / "sheet.png"
    result = runner.invoke(
        assets_app,
        ["gallery", "--out", str(out), "--category", "apple", "--category", "mug", "--tile", "96", "--cols", "4"],
    )
    assert result.exit_code == 0, result.output
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    assert (width, height) == (4 * 96, 4 * (96 + 16))  # 13 assets in 4 columns -> 4 rows
