"""What the page carries for its 3-D viewer: each card's glb and placed objects, the viewer's code as inert text
admitted by its hash, and with --embed each glb, checked like the images (a regular file, no link, a real glb)."""

from __future__ import annotations

import base64
import hashlib
import html
import json
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.gallery import GalleryError, collect_cards, write_report
from physcensis.gallery.page import render_page
from physcensis.gallery.viewer import viewer_script
from tests.gallery.folders import glb_scene_folder, results_file, row, scene_folder

VENDOR = Path(__file__).parents[2] / "src" / "physcensis" / "gallery" / "vendor"


def blocks(page: str) -> dict[str, str]:
    """The text of every `<script type=... id=...>` block of the page by its id."""
    return dict(re.findall(r'<script type="[^"]+" id="([^"]+)">(.*?)</script>', page, flags=re.S))


def test_a_card_lists_its_glb_and_placed_objects(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "boxes")
    scene_folder(tmp_path / "plain")
    boxes, plain = collect_cards(tmp_path)
    assert (boxes.glb, plain.glb, plain.objects) == ("boxes/scene.glb", None, [])
    assert [o["id"] for o in boxes.objects] == ["box_0", "box_1"]  # lost_0 failed: it is in no glb
    assert boxes.objects[1] == {
        "id": "box_1",
        "asset": "cube_1",
        "category": "box",
        "description": "box number 1",
        "mass": 1.5,
        "friction": 0.6,
        "predicates": ["RIGHT-OF box_0"],
        "p_fail": 0.125,
    }
    assert boxes.objects[0]["predicates"] == ['PLACE-ON-BASE root {"x": 0.0, "y": 0.0}']


def test_a_results_row_finds_the_glb_of_its_scene_folder(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "scenes" / "ours")
    results_file(tmp_path, [row("two boxes", "ours", 0, "scenes/ours", {"relation_accuracy": 1.0})])
    [card] = collect_cards(tmp_path)
    assert card.glb == "scenes/ours/scene.glb" and len(card.objects) == 2


def test_the_viewer_code_is_inert_text_admitted_by_its_hash(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "boxes")
    page = render_page(collect_cards(tmp_path), tmp_path)
    code = json.loads(blocks(page)["viewer-code"])
    assert code == viewer_script() and code.startswith((VENDOR / "three-viewer.min.js").read_text().rstrip())
    digest = base64.b64encode(hashlib.sha256(code.encode()).digest()).decode()
    meta = re.search(r'http-equiv="Content-Security-Policy" content="([^"]+)"', page)
    assert meta is not None
    policy = dict(part.strip().split(" ", 1) for part in html.unescape(meta.group(1)).split(";"))
    assert f"'sha256-{digest}'" in policy["script-src"].split() and len(policy["script-src"].split()) == 3
    assert policy["connect-src"] == "'self'" and policy["default-src"] == "'none'"
    assert "<script src" not in page and '<link rel="stylesheet"' not in page  # nothing from elsewhere
    assert "glb-0" not in blocks(page)  # linked: the glb stays a file


def test_the_vendored_three_is_the_recorded_version() -> None:
    readme = (VENDOR / "README.md").read_text()
    assert "three.js **0.187.0**" in readme and "esbuild **0.28.2**" in readme
    bundle = (VENDOR / "three-viewer.min.js").read_bytes()
    assert b'"187"' in bundle  # three's REVISION
    assert hashlib.sha256(bundle).hexdigest() in readme
    assert (VENDOR / "LICENSE").read_text().startswith("The MIT License")


def test_embed_puts_each_glb_in_its_own_block(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "boxes")
    page = render_page(collect_cards(tmp_path), tmp_path, embed=True)
    data = json.loads(blocks(page)["gallery-data"])
    assert data["glbs"] == {"boxes/scene.glb": "glb-0"}
    assert base64.b64decode(blocks(page)["glb-0"]) == (tmp_path / "boxes" / "scene.glb").read_bytes()


def test_a_glb_that_is_not_one_is_refused_with_embed_and_linked_without(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "boxes", glb=b"<html><script>alert(1)</script>")
    result = CliRunner().invoke(app, ["report", str(tmp_path), "--embed"])
    assert result.exit_code == 2 and "is not a binary glTF (glb) file; refused" in result.output
    assert "Traceback" not in result.output and not (tmp_path / "index.html").exists()
    assert CliRunner().invoke(app, ["report", str(tmp_path)]).exit_code == 0


def test_a_glb_that_is_a_link_is_refused(tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "boxes")
    outside = tmp_path.parent / f"{tmp_path.name}-outside.glb"
    (tmp_path / "boxes" / "scene.glb").rename(outside)
    (tmp_path / "boxes" / "scene.glb").symlink_to(outside)
    with pytest.raises(GalleryError, match="scene.glb: is a symbolic link"):
        write_report(tmp_path)


def test_glbs_count_in_the_embed_limit(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    glb_scene_folder(tmp_path / "boxes")
    images = sum(len((tmp_path / "boxes" / name).read_bytes()) for name in ("render.png", "layout.png"))
    monkeypatch.setattr("physcensis.gallery.page.MAX_EMBED_BYTES", images + 100)  # the images fit, not the glb
    with pytest.raises(GalleryError, match="add up to more than"):
        write_report(tmp_path, embed=True)
