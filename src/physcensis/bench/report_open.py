"""Benchmark: how fast `physcensis report`'s page of 100 scenes opens in chromium, and its 3-D view.

Generates one scene ("a mug on a book", with its scene.glb), copies its folder SCENES times, writes the report
linked and with --embed, and opens each page RUNS times from the file system in headless chromium (Playwright
driving the system's chromium: PHYSCENSIS_CHROMIUM, or chromium on the PATH; no browser download). Per page: its
size, and the milliseconds from navigation to the cards shown (page.js marks it), to DOMContentLoaded and to load
(every image decoded), median and worst of the runs; then, on the embedded page, from pressing the first card's 3-D
button to the scene drawn (the viewer's code run for the first time, the glb parsed). The target: the cards of 100
scenes within 2 s. `python -m physcensis.bench --only report_open`.
"""

from __future__ import annotations

import json
import os
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from physcensis.errors import PhyscensisError

SCENES = 100
RUNS = 5
PROMPT = "a mug on a book"
TARGET_S = 2.0
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking", "--disable-sync"]
_TIMINGS = """() => {
  const nav = performance.getEntriesByType("navigation")[0];
  const cards = performance.getEntriesByName("physcensis-cards")[0];
  return { cards: cards ? cards.startTime : null, dom: nav.domContentLoadedEventEnd, load: nav.loadEventEnd };
}"""


def chromium_path() -> str:
    """PHYSCENSIS_CHROMIUM, else chromium or chromium-browser on the PATH."""
    candidates = [os.environ.get("PHYSCENSIS_CHROMIUM"), shutil.which("chromium"), shutil.which("chromium-browser")]
    found = next((c for c in candidates if c and Path(c).is_file()), None)
    if found is None:
        raise PhyscensisError("no chromium found: install it (apt-get install chromium) or set PHYSCENSIS_CHROMIUM")
    return found


def make_scenes(root: Path, count: int) -> Path:
    """`count` copies of one generated scene folder under `root/scenes`."""
    from physcensis.api import generate, write_generated

    first = root / "scenes" / "scene_000"
    write_generated(generate(PROMPT), first, exports=["glb"])
    for k in range(1, count):
        shutil.copytree(first, root / "scenes" / f"scene_{k:03d}")
    return root / "scenes"


def _spread(values: list[float]) -> dict[str, float]:
    return {"median": round(statistics.median(values), 1), "max": round(max(values), 1)}


def time_page(browser: Any, page_path: Path, runs: int) -> dict[str, Any]:
    """Open the page `runs` times, a fresh tab each: milliseconds to the cards, DOMContentLoaded and load."""
    timings: dict[str, list[float]] = {"cards_ms": [], "dom_content_loaded_ms": [], "load_ms": []}
    for _ in range(runs):
        page = browser.new_page(viewport={"width": 1600, "height": 1000})
        page.goto(page_path.as_uri(), wait_until="load")
        page.wait_for_selector("body[data-ready=true]")
        found = page.evaluate(_TIMINGS)
        timings["cards_ms"].append(found["cards"])
        timings["dom_content_loaded_ms"].append(found["dom"])
        timings["load_ms"].append(found["load"])
        page.close()
    return {"html_bytes": page_path.stat().st_size, **{name: _spread(v) for name, v in timings.items()}}


_WATCH_VIEWER = """() => {
  const dialog = document.getElementById("viewer");
  window.__benchViewer = {};
  document.addEventListener("physcensis-view3d", () => { window.__benchViewer.pressed = performance.now(); }, true);
  new MutationObserver(() => { window.__benchViewer[dialog.dataset.state] = performance.now(); })
    .observe(dialog, { attributes: true, attributeFilter: ["data-state"] });
}"""


def time_viewer(browser: Any, page_path: Path) -> float:
    """Milliseconds, in the page, from pressing the first 3-D button to the scene drawn."""
    page = browser.new_page(viewport={"width": 1600, "height": 1000})
    page.goto(page_path.as_uri(), wait_until="load")
    page.evaluate(_WATCH_VIEWER)
    page.locator("button.view3d").first.click()
    page.wait_for_selector("#viewer[data-state=ready], #viewer[data-state=failed]", timeout=60_000)
    marks = page.evaluate("window.__benchViewer")
    page.close()
    if "ready" not in marks:
        raise PhyscensisError("the 3-D view of the benchmark's scene did not open")
    return round(marks["ready"] - marks["pressed"], 1)


def run(scenes: int = SCENES, runs: int = RUNS) -> dict[str, Any]:
    """The report of `scenes` copies of one scene, linked and embedded, opened `runs` times each."""
    from playwright.sync_api import sync_playwright

    from physcensis.gallery import write_report

    executable = chromium_path()
    with tempfile.TemporaryDirectory(prefix="physcensis-report-bench-") as tmp:
        folder = make_scenes(Path(tmp), scenes)
        start = time.perf_counter()
        embedded = shutil.copyfile(write_report(folder, embed=True), Path(tmp) / "embedded.html")  # one file
        written = {"embedded": round(time.perf_counter() - start, 2)}
        start = time.perf_counter()
        pages = {"linked": write_report(folder, overwrite=True), "embedded": embedded}  # linked: beside the scenes
        written["linked"] = round(time.perf_counter() - start, 2)
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=executable, args=CHROMIUM_ARGS)
            try:
                result = {kind: time_page(browser, path, runs) for kind, path in pages.items()}
                viewer_ms = [time_viewer(browser, pages["embedded"]) for _ in range(runs)]
                version = browser.version
            finally:
                browser.close()
    worst = max(result[kind]["cards_ms"]["max"] for kind in pages)
    return {
        "benchmark": "report_open",
        "scenes": scenes,
        "runs": runs,
        "chromium": version,
        "write_report_s": written,
        **result,
        "viewer_open_ms": _spread(viewer_ms),
        "target_s": TARGET_S,
        "within_target": worst <= 1000 * TARGET_S,
    }


if __name__ == "__main__":
    json.dump(run(), sys.stdout, indent=1)
    sys.stdout.write("\n")
