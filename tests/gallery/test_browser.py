"""The report in a real headless browser: Playwright drives the system's chromium (Debian's; `.ci/run` installs it),
the page opens from file://, loads without console errors, shows one card per scene, sorts and filters.

Skipped only when no chromium is found (set PHYSCENSIS_CHROMIUM to a chromium binary to use another one)."""

from __future__ import annotations

import os
import shutil
import statistics
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from physcensis.gallery import write_report
from tests.gallery.folders import HOSTILE, results_file, row, scene_folder


def _chromium() -> str | None:
    candidates = [os.environ.get("PHYSCENSIS_CHROMIUM"), shutil.which("chromium"), shutil.which("chromium-browser")]
    return next((c for c in candidates if c and Path(c).is_file()), None)


CHROMIUM = _chromium()
pytestmark = pytest.mark.skipif(
    CHROMIUM is None, reason="no chromium found (apt-get install chromium, as .ci/run does, or set PHYSCENSIS_CHROMIUM)"
)
# As root, without a sandbox; no background traffic (this machine's network is closed), a fresh profile each launch.
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
# Four scenes over two prompts and two methods (one without a metric, one not ok), and a prompt that tries to run
# a script.
ROWS = [
    row("a mug on a coaster", "ours", 0, "scenes/ours_mug", {"relation_accuracy": 1.0, "settle_mm": 0.002}),
    row(
        "a mug on a coaster", "random", 0, "scenes/random_mug", {"relation_accuracy": 0.25, "settle_mm": 0.09}, ["fell"]
    ),
    {  # not ok, with no failure named: the "has failures" filter shows it too
        **row(
            "three books in a stack", "ours", 0, "scenes/ours_books", {"relation_accuracy": 0.75, "settle_mm": 0.004}
        ),
        "ok": False,
    },
    row("three books in a stack", "random", 0, "scenes/random_books", {"relation_accuracy": 0.5}, ["book_2: pending"]),
    row(HOSTILE, "ours", 1, "scenes/hostile", {"relation_accuracy": 0.0, "settle_mm": 0.5}, [HOSTILE]),
]


@pytest.fixture(scope="module")
def compare_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("compare")
    for r in ROWS:
        scene_folder(folder / r["scene_dir"], layout=r["method"] == "ours", render=r["scene_dir"] != "scenes/hostile")
    results_file(folder, ROWS)
    return folder


@pytest.fixture(scope="module")
def report(browser: Any, compare_folder: Path) -> Iterator[Page]:
    """The compare folder's page, loaded once; each test starts from its reset button."""
    view = Page(browser, write_report(compare_folder))
    yield view
    view.page.close()


@pytest.fixture
def view(report: Page) -> Page:
    report.page.click("#reset")
    return report


class Page:
    """One loaded report page and everything it complained about."""

    def __init__(self, browser: Any, path: Path) -> None:
        self.page = browser.new_page(viewport={"width": 1600, "height": 2400})
        self.problems: list[str] = []
        self.page.on("console", self._console)
        self.page.on("pageerror", lambda e: self.problems.append(f"page error: {e}"))
        self.page.on("requestfailed", lambda r: self.problems.append(f"request failed: {r.url}"))
        self.page.goto(path.resolve().as_uri())
        self.page.wait_for_selector("body[data-ready=true]")
        self.page.wait_for_load_state("load")

    def _console(self, message: Any) -> None:
        if message.type == "error":
            self.problems.append(f"console error: {message.text}")

    def visible_prompts(self) -> list[str]:
        """The prompts of the cards shown, top to bottom."""
        return list(self.page.locator("article.card:not([hidden]) .prompt").all_inner_texts())

    def visible_metric(self, name: str) -> list[str]:
        return list(
            self.page.eval_on_selector_all(
                "article.card:not([hidden])",
                "(cards, name) => cards.map(c => { const row = [...c.querySelectorAll('.metrics tr')]"
                ".find(r => r.querySelector('th').textContent === name); return row ? row.cells[1].textContent : '' })",
                name,
            )
        )

    def summary(self) -> list[list[str]]:
        """The per-method table over the cards shown, header first."""
        return list(
            self.page.eval_on_selector_all("#summary tr", "rows => rows.map(r => [...r.cells].map(c => c.textContent))")
        )

    def broken_images(self) -> list[str]:
        return list(self.page.eval_on_selector_all("img", "ims => ims.filter(i => !i.naturalWidth).map(i => i.src)"))


def test_the_page_loads_clean_with_one_card_per_scene_and_hostile_text_as_text(view: Page) -> None:
    assert view.problems == []
    assert view.page.locator("article.card").count() == len(ROWS)
    assert view.visible_prompts() == [r["prompt"] for r in ROWS]
    assert view.page.inner_text("#count") == f"showing {len(ROWS)} of {len(ROWS)} scenes"
    # Four renders and the three "ours" layouts (the hostile scene has a layout and no render).
    assert view.page.locator("img").count() == 4 + 3
    assert view.broken_images() == []
    assert view.page.evaluate("window.__pwned") is None  # the hostile prompt ran nothing
    hostile = view.page.locator("article.card").nth(4)
    assert hostile.locator(".prompt").inner_text() == HOSTILE
    assert hostile.locator(".failures li").inner_text() == HOSTILE


def test_sorting_by_a_metric_reorders_the_cards_missing_values_last(view: Page) -> None:
    view.page.select_option("#sort-key", "m:settle_mm")
    assert view.visible_metric("settle_mm") == ["0.002", "0.004", "0.09", "0.5", ""]
    view.page.select_option("#sort-order", "desc")
    assert view.visible_metric("settle_mm") == ["0.5", "0.09", "0.004", "0.002", ""]
    ours = [0.002, 0.004, 0.5]  # the random scene without the metric counts as a scene, not as a value
    assert view.summary() == [
        ["method", "scenes", "with failures", "settle_mm (mean ± std)"],
        ["ours", "3", "2", f"{statistics.fmean(ours):.4g} ± {statistics.pstdev(ours):.4g}"],
        ["random", "2", "2", "0.09 ± 0"],
    ]
    view.page.select_option("#sort-key", "prompt")
    view.page.select_option("#sort-order", "asc")
    assert view.visible_prompts()[0] == HOSTILE  # "<" sorts before letters
    assert view.problems == []


def test_filters_change_what_is_shown(view: Page) -> None:
    view.page.fill("#filter-text", "MUG")
    assert view.visible_prompts() == ["a mug on a coaster"] * 2
    view.page.select_option("#filter-method", "random")
    assert view.visible_metric("relation_accuracy") == ["0.25"]
    assert view.summary()[1:] == [["random", "1", "1"]]
    view.page.fill("#filter-text", "")
    assert view.visible_metric("relation_accuracy") == ["0.25", "0.5"]
    view.page.click("#reset")
    view.page.check("#filter-failures")
    assert len(view.visible_prompts()) == 4  # all but the first: failures listed, or not ok
    view.page.click("#reset")
    view.page.select_option("#range-metric", "relation_accuracy")
    view.page.fill("#range-min", "0.5")
    view.page.fill("#range-max", "0.8")
    assert view.visible_metric("relation_accuracy") == ["0.75", "0.5"]
    view.page.fill("#filter-text", "nothing has this prompt")
    assert view.visible_prompts() == [] and view.page.is_visible("#empty")
    assert view.page.inner_text("#count") == f"showing 0 of {len(ROWS)} scenes"
    assert view.problems == []


def test_an_embedded_page_shows_its_images_away_from_the_scene_folders(
    browser: Any, compare_folder: Path, tmp_path: Path
) -> None:
    alone = tmp_path / "elsewhere.html"
    shutil.copyfile(write_report(compare_folder, embed=True), alone)
    view = Page(browser, alone)
    assert view.page.locator("img").count() == 7
    assert view.broken_images() == []
    assert view.problems == []
    view.page.close()


def test_a_batch_shows_the_scenes_of_one_prompt_side_by_side(browser: Any, tmp_path: Path) -> None:
    for prompt, key in (("a mug on a coaster", "mug"), ("three books in a stack", "books")):
        for k in range(3):
            scene_folder(tmp_path / "scenes" / f"{key}_{k:03d}", prompt=prompt)
    view = Page(browser, write_report(tmp_path))
    groups = view.page.locator("section.group:not([hidden])")
    assert groups.count() == 2  # several seeds of one method: grouped from the start
    assert groups.nth(0).locator(".group-prompt").inner_text() == "three books in a stack"  # books_000 comes first
    assert groups.nth(0).locator("article.card").count() == 3
    boxes = [groups.nth(1).locator("article.card").nth(k).bounding_box() for k in range(3)]
    assert len({round(b["y"]) for b in boxes}) == 1 and boxes[0]["x"] < boxes[1]["x"] < boxes[2]["x"]  # one row
    view.page.fill("#filter-text", "books")
    assert view.page.locator("section.group:not([hidden])").count() == 1
    assert view.page.inner_text("section.group:not([hidden]) .group-count") == "3 scenes"
    view.page.uncheck("#group-prompt")
    assert view.page.locator("section.group").count() == 0 and len(view.visible_prompts()) == 3
    view.page.click("#reset")
    assert view.page.locator("section.group").count() == 2
    assert view.problems == []
    view.page.close()


def test_a_comparison_of_methods_starts_in_file_order_and_groups_when_asked(view: Page) -> None:
    assert view.page.locator("section.group").count() == 0
    view.page.check("#group-prompt")
    prompts = view.page.locator("section.group .group-prompt").all_inner_texts()
    assert prompts == ["a mug on a coaster", "three books in a stack", HOSTILE]
    assert view.visible_prompts() == ["a mug on a coaster"] * 2 + ["three books in a stack"] * 2 + [HOSTILE]
    assert view.problems == []
