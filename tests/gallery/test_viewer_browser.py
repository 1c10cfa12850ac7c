"""The report's 3-D viewer in a real headless browser (the system's chromium, as tests/gallery/test_browser.py drives
it): a card's 3-D button loads the viewer and the scene's glb only when pressed, the canvas draws the scene, every
placed object is pickable and a click on one shows its data; the page asks nothing of the network.

The quick tests use a small hand-made glb (tests/gallery/folders.py); the long ones a scene generated for real."""

from __future__ import annotations

import io
import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from physcensis.gallery import write_report
from physcensis.gallery.serve import ReportServer, report_server
from tests.gallery.folders import GLB_OBJECTS, HOSTILE, glb_scene_folder
from tests.gallery.test_browser import CHROMIUM

pytestmark = pytest.mark.skipif(
    CHROMIUM is None, reason="no chromium found (apt-get install chromium, as .ci/run does, or set PHYSCENSIS_CHROMIUM)"
)
SETTLED = "#viewer[data-state=ready], #viewer[data-state=failed], #viewer[data-state=unavailable]"


@pytest.fixture(scope="module")
def boxes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A report folder of one hand-made scene (two boxes on a slab) whose first box has a hostile description."""
    folder = tmp_path_factory.mktemp("boxes")
    scene = glb_scene_folder(folder / "scene")
    data = json.loads((scene / "scene.json").read_text())
    data["objects"][0]["description"] = HOSTILE
    (scene / "scene.json").write_text(json.dumps(data))
    return folder


class Viewer:
    """A loaded report page, every request it made and everything it complained about."""

    def __init__(self, browser: Any, url: str) -> None:
        self.page = browser.new_page(viewport={"width": 1400, "height": 1000})
        self.requests: list[str] = []
        self.problems: list[str] = []
        self.page.on("request", lambda r: self.requests.append(r.url))
        self.page.on("console", lambda m: self.problems.append(m.text) if m.type == "error" else None)
        self.page.on("pageerror", lambda e: self.problems.append(f"page error: {e}"))
        self.page.on("requestfailed", lambda r: self.problems.append(f"request failed: {r.url}"))
        self.page.goto(url)
        self.page.wait_for_selector("body[data-ready=true]")

    def open(self, card: int = 0) -> str:
        """Press a card's 3-D button; the dialog's state once settled (ready, failed or unavailable)."""
        from playwright.sync_api import TimeoutError as PlaywrightTimeout

        self.page.locator("article.card button.view3d").nth(card).click()
        try:
            self.page.wait_for_selector(SETTLED, timeout=60_000)  # drawn in software, on a busy machine
        except PlaywrightTimeout:
            state = self.page.get_attribute("#viewer", "data-state")
            shown = self.page.inner_text("#viewer-message")
            raise AssertionError(f"the viewer stayed {state!r} ({shown!r}); {self.requests}, {self.problems}") from None
        return str(self.page.get_attribute("#viewer", "data-state"))

    def viewer_loaded(self) -> bool:
        return bool(self.page.evaluate("typeof globalThis.PhyscensisThree !== 'undefined'"))

    def pickable(self) -> list[str]:
        return list(self.page.evaluate("physcensisViewer.ids()"))

    def click_object(self, oid: str) -> str:
        """Click where the viewer shows `oid`; the id the info panel then shows."""
        point = self.page.evaluate("(id) => physcensisViewer.screenPoint(id)", oid)
        assert point is not None, f"{oid} is nowhere to be clicked"
        self.page.mouse.click(point["x"], point["y"])
        return str(self.page.get_attribute("#viewer-info", "data-object"))

    def facts(self) -> dict[str, str]:
        rows = self.page.eval_on_selector_all(
            ".viewer-facts tr", "rows => rows.map(r => [r.cells[0].textContent, r.cells[1].textContent])"
        )
        return dict(rows)

    def colours(self) -> int:
        """Distinct colours (in steps of 16 levels) covering at least 0.2% of the canvas each."""
        from PIL import Image

        image = Image.open(io.BytesIO(self.page.locator("#viewer-stage canvas").screenshot())).convert("RGB")
        quantised = image.point(lambda v: v // 16 * 16)
        counts = quantised.getcolors(maxcolors=1 << 20) or []
        return sum(1 for count, _ in counts if count >= 0.002 * image.width * image.height)

    def close(self) -> None:
        self.page.close()


def assert_offline(requests: list[str], *allowed: str) -> None:
    """Every request the page made was for the page itself, its data: URLs, or the given address."""
    assert requests and all(url.startswith(("file://", "data:", *allowed)) for url in requests), requests


@pytest.mark.long  # 6 s in the browser
def test_the_viewer_loads_only_when_asked_draws_the_scene_and_picks_its_objects(browser: Any, boxes: Path) -> None:
    view = Viewer(browser, write_report(boxes, embed=True, overwrite=True).as_uri())
    assert not view.viewer_loaded() and view.page.locator("button.view3d").count() == 1
    assert view.open() == "ready"
    assert view.viewer_loaded()
    assert sorted(view.pickable()) == sorted(GLB_OBJECTS)  # the placed objects; the failed one is in no glb
    assert view.colours() >= 4  # background, slab, the red and the green box
    assert view.click_object("box_1") == "box_1"
    assert view.page.inner_text("#viewer-info h3") == "box_1"
    assert view.facts() == {
        "asset": "cube_1",
        "category": "box",
        "mass": "1.5 kg",
        "friction": "0.6",
        "p_fail": "0.125",
    }
    assert view.page.locator(".viewer-predicates li").all_inner_texts() == ["RIGHT-OF box_0"]
    assert view.click_object("box_0") == "box_0"
    assert view.page.inner_text(".viewer-description") == HOSTILE and view.page.evaluate("window.__pwned") is None
    assert view.facts()["p_fail"] == "not measured"
    view.page.mouse.click(700, 120)  # the sky above the table: nothing picked
    assert view.page.get_attribute("#viewer-info", "data-object") == ""
    view.page.click("#viewer-close")
    view.page.wait_for_function("globalThis.physcensisViewer === null && !document.getElementById('viewer').open")
    assert view.open() == "ready"  # again, with the code already loaded
    assert view.problems == []
    assert_offline(view.requests)
    view.close()


def test_a_page_opened_from_a_file_without_embed_says_how_to_see_the_scene(browser: Any, boxes: Path) -> None:
    view = Viewer(browser, write_report(boxes, overwrite=True).as_uri())
    assert view.open() == "unavailable"
    message = view.page.inner_text("#viewer-message")
    assert "--embed" in message and "--serve" in message
    assert not view.viewer_loaded()  # nothing was loaded for nothing
    assert view.problems == []
    assert_offline(view.requests)
    view.close()


@pytest.fixture
def server(boxes: Path) -> Iterator[ReportServer]:
    write_report(boxes, overwrite=True)
    served = report_server(boxes)
    served.start()
    yield served
    served.shutdown()
    served.server_close()


def test_a_served_page_loads_the_glb_by_its_url(browser: Any, server: ReportServer) -> None:
    view = Viewer(browser, server.url)
    assert view.open() == "ready"
    assert sorted(view.pickable()) == sorted(GLB_OBJECTS)
    assert view.click_object("box_1") == "box_1"
    assert f"{server.url}scene/scene.glb" in view.requests
    assert view.problems == []
    assert_offline(view.requests, server.url)
    view.close()


def test_a_glb_that_is_not_one_is_said_so(browser: Any, tmp_path: Path) -> None:
    glb_scene_folder(tmp_path / "scene", glb=b"glTF but not really")
    view = Viewer(browser, write_report(tmp_path, embed=True).as_uri())
    assert view.open() == "failed"
    assert "could not be shown" in view.page.inner_text("#viewer-message")
    view.close()


# ---- a scene generated for real --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def mug_on_book(tmp_path_factory: pytest.TempPathFactory) -> Path:
    from physcensis.api import generate, write_generated

    folder = tmp_path_factory.mktemp("generated")
    write_generated(generate("a mug on a book"), folder / "mug", exports=["glb"])
    return folder


def placed_objects(scene: Path) -> dict[str, dict[str, Any]]:
    objects = json.loads((scene / "scene.json").read_text())["objects"]
    return {o["id"]: o for o in objects if o.get("status") == "placed"}


def shown(value: float) -> str:
    """A number as the page shows it: four significant digits, no trailing zeros."""
    text = repr(float(f"{value:.4g}"))
    return text[:-2] if text.endswith(".0") else text


def check_generated(view: Viewer, scene: Path) -> None:
    placed = placed_objects(scene)
    assert view.open() == "ready"
    assert sorted(view.pickable()) == sorted(placed) and len(placed) >= 2
    assert view.colours() >= 4
    for oid, obj in placed.items():
        assert view.click_object(oid) == oid
        facts = view.facts()
        assert facts["asset"] == obj["asset"]
        assert facts["mass"] == f"{shown(obj['mass'])} kg"
    assert view.problems == []


@pytest.mark.long
def test_a_generated_scene_embedded_is_drawn_and_each_object_picked(browser: Any, mug_on_book: Path) -> None:
    view = Viewer(browser, write_report(mug_on_book, embed=True).as_uri())
    check_generated(view, mug_on_book / "mug")
    assert_offline(view.requests)
    view.close()


@pytest.mark.long
def test_a_generated_scene_served_is_drawn_and_each_object_picked(browser: Any, mug_on_book: Path) -> None:
    write_report(mug_on_book, overwrite=True)
    server = report_server(mug_on_book)
    server.start()
    try:
        view = Viewer(browser, server.url)
        check_generated(view, mug_on_book / "mug")
        assert f"{server.url}mug/scene.glb" in view.requests
        assert_offline(view.requests, server.url)
        view.close()
    finally:
        server.shutdown()
        server.server_close()
