"""The gallery page: one HTML file that opens from the file system, with its data, script and style inside it.

The cards travel as JSON in a `<script type="application/json">` block whose `<`, `>` and `&` are escaped, so no
string from a file can close the block; the script builds the cards with `textContent` only. A Content-Security-
Policy admits exactly the page's own scripts (page.js, dialog.js, the 3-D viewer's) and style by their hashes, so even
markup that got in would not run.
Images and scene.glb files are linked by relative URL, or inlined as base64 with `embed` (one portable file). A file
is embedded only when it is what it says: a regular file inside the report's folder (no symbolic link, see cards.py),
a PNG or a JPEG (an image) or a binary glTF (a glb) by its first bytes, at most MAX_IMAGE_BYTES or MAX_GLB_BYTES, and
all of them together at most MAX_EMBED_BYTES; anything else is refused, naming the file, before the page is written.
The 3-D viewer's script (viewer.py) travels as inert JSON text too, run only when a card's 3-D button is pressed;
each embedded glb sits in its own inert block, read only then. Both come after the page's script, so the cards are
shown before the parser reaches them. A linked glb is fetched by URL, which works when the
page is served (serve.py); opened from a file, the dialog says to use --embed or --serve.
"""

from __future__ import annotations

import base64
import hashlib
import html
import json
from collections.abc import Iterable
from importlib import resources
from pathlib import Path
from typing import Any
from urllib.parse import quote

from physcensis.fileio import OWNER_FILE, OWNER_FORMAT, atomic_write_text, check_output_file, owned_entries
from physcensis.gallery.cards import Card, GalleryError, collect_cards, read_folder_file
from physcensis.gallery.viewer import viewer_script

INDEX_NAME = "index.html"
# How every page this writes begins: an index.html that begins otherwise is a user's, replaced only when asked.
PAGE_START = "<!DOCTYPE html>\n<!-- physcensis report -->\n"
MAX_IMAGE_BYTES = 64 * 2**20
MAX_GLB_BYTES = 64 * 2**20
MAX_EMBED_BYTES = 256 * 2**20  # every embedded file together: the page holds them once more as base64
IMAGE_TYPES = {b"\x89PNG\r\n\x1a\n": "image/png", b"\xff\xd8\xff": "image/jpeg"}  # first bytes -> MIME type
GLB_MAGIC = b"glTF"
_DATA_ESCAPES = {ord("<"): "\\u003c", ord(">"): "\\u003e", ord("&"): "\\u0026"}


def write_report(folder: Path, *, embed: bool = False, overwrite: bool = False) -> Path:
    """Write `folder/index.html`, the gallery of every scene under `folder` (or of the rows of its results.jsonl),
    atomically, and return its path. `GalleryError` when there is nothing to show; `OutputError` when an index.html
    physcensis did not write is there (unless `overwrite`)."""
    folder = Path(folder)
    return write_page(folder, collect_cards(folder), embed=embed, overwrite=overwrite)


def write_page(folder: Path, cards: list[Card], *, embed: bool = False, overwrite: bool = False) -> Path:
    """`write_report` for cards already collected from `folder`."""
    target = check_output_file(folder / INDEX_NAME, overwrite=overwrite, suffixes=[PAGE_START.encode()])
    atomic_write_text(target, render_page(cards, folder, embed=embed))
    _claim_in_scene_folder(folder)
    return target


def render_page(cards: list[Card], folder: Path, *, embed: bool = False) -> str:
    """The page's HTML for these cards; image and folder paths are taken relative to `folder`."""
    script = _asset("page.js")
    dialog = _asset("dialog.js")
    style = _asset("page.css")
    viewer = viewer_script()
    images, spent = _embedded_images(folder, _image_paths(cards)) if embed else ({}, 0)
    glbs = embedded_glbs(folder, _glb_paths(cards), spent) if embed else {}
    data = page_data(cards, folder, embed=embed, images=images, glb_blocks=_glb_block_ids(glbs))
    title = f"physcensis report: {folder.resolve().name or folder}"
    return _TEMPLATE.format(
        policy=html.escape(page_policy()),
        title=html.escape(title),
        where=html.escape(str(folder)),
        style=style,
        data=embed_json(data),
        viewer=embed_json(viewer if any(c.glb for c in cards) else ""),  # no glb, no viewer to run
        glbs=_glb_blocks(glbs),
        dialog=dialog,
        script=script,
    )


def page_policy(*, served: bool = False) -> str:
    """The page's Content-Security-Policy: its own script, dialog, viewer and style by their hashes and nothing else
    run. connect-src 'self' lets the viewer fetch a linked scene.glb when the page is served (report --serve);
    `served` is the header `--serve` sends with every file, which keeps images to the server's own."""
    hashes = " ".join(f"'{_csp_hash(text)}'" for text in (_asset("page.js"), _asset("dialog.js"), viewer_script()))
    images = "'self' data:" if served else "* file: data:"
    return (
        f"default-src 'none'; img-src {images}; connect-src 'self'; style-src '{_csp_hash(_asset('page.css'))}'; "
        f"script-src {hashes}; base-uri 'none'; form-action 'none'" + ("; frame-ancestors 'none'" if served else "")
    )


def page_data(
    cards: list[Card],
    folder: Path,
    *,
    embed: bool = False,
    images: dict[str, str] | None = None,
    glb_blocks: dict[str, str] | None = None,
) -> dict[str, Any]:
    """What the script reads: the cards, the metric and method names in first-seen order, the URL of every relative
    path (images, glbs and scene folders), whether the cards start grouped by prompt and, with `embed`, the images
    themselves as data URIs (`images` when already read) and the id of the block holding each glb (`glb_blocks`)."""
    image_paths = _image_paths(cards)
    paths = image_paths + _glb_paths(cards) + sorted({c.scene_dir for c in cards if c.scene_dir})
    if embed and images is None:
        images = embedded_images(folder, image_paths)
    return {
        "cards": [c.to_json() for c in cards],
        "metrics": _first_seen(name for c in cards for name in c.metrics),
        "methods": _first_seen(c.method for c in cards),
        "urls": {p: _relative_url(p) for p in paths},
        "group_by_prompt": groups_by_prompt(cards),
        "images": images or {},
        "glbs": glb_blocks or {},
    }


def groups_by_prompt(cards: list[Card]) -> bool:
    """Scenes of one method with a prompt made more than once (seeds of a batch) start side by side per prompt; a
    comparison of methods starts in file order."""
    prompts = [c.prompt or c.prompt_id for c in cards]
    return len({c.method for c in cards}) == 1 and len(set(prompts)) < len(prompts)


def embed_json(data: Any) -> str:
    """JSON safe inside a `<script>` element: no `<`, `>` or `&` (so no `</script>` or `<!--`), ASCII only."""
    return json.dumps(data, ensure_ascii=True, allow_nan=False, separators=(",", ":")).translate(_DATA_ESCAPES)


def _image_paths(cards: list[Card]) -> list[str]:
    return sorted({p for c in cards for p in (c.render, c.layout) if p})


def _glb_paths(cards: list[Card]) -> list[str]:
    return sorted({c.glb for c in cards if c.glb})


def _glb_block_ids(glbs: dict[str, str]) -> dict[str, str]:
    """The id of the element holding each embedded glb, by its path."""
    return {path: f"glb-{k}" for k, path in enumerate(glbs)}


def _glb_blocks(glbs: dict[str, str]) -> str:
    """One inert block per embedded glb: base64 has no `<`, `>` or `&`, so it cannot end the element."""
    ids = _glb_block_ids(glbs)
    return "".join(
        f'<script type="application/octet-stream" id="{ids[path]}">{data}</script>\n' for path, data in glbs.items()
    )


def _first_seen(names: Iterable[str]) -> list[str]:
    return list(dict.fromkeys(names))


def _relative_url(path: str) -> str:
    """A relative path as a URL (`#`, `?`, `%` and spaces in folder names would otherwise change what it points at)."""
    return quote(path, safe="/")


def embedded_images(folder: Path, paths: list[str]) -> dict[str, str]:
    """Each image (a path relative to `folder`) as a data URI, read as `read_in_folder` reads; refused when it is not
    a PNG or JPEG, or when the images add up to more than MAX_EMBED_BYTES."""
    return _embedded_images(folder, paths)[0]


def _embedded_images(folder: Path, paths: list[str]) -> tuple[dict[str, str], int]:
    """`embedded_images` and the bytes they take."""
    images: dict[str, str] = {}
    total = 0
    for relative in paths:
        data = read_folder_file(folder, relative, MAX_IMAGE_BYTES)
        total += len(data)
        _check_total(folder, total)
        images[relative] = _data_uri(data, folder / relative)
    return images, total


def embedded_glbs(folder: Path, paths: list[str], spent: int = 0) -> dict[str, str]:
    """Each glb (a path relative to `folder`) in base64, read as the images are; refused when it is not a binary
    glTF, or when they add up, with the `spent` bytes of the images, to more than MAX_EMBED_BYTES."""
    glbs: dict[str, str] = {}
    total = spent
    for relative in paths:
        data = read_folder_file(folder, relative, MAX_GLB_BYTES)
        if not data.startswith(GLB_MAGIC):
            raise GalleryError(f"{folder / relative}: is not a binary glTF (glb) file; refused")
        total += len(data)
        _check_total(folder, total)
        glbs[relative] = base64.b64encode(data).decode("ascii")
    return glbs


def _check_total(folder: Path, total: int) -> None:
    if total > MAX_EMBED_BYTES:
        raise GalleryError(
            f"{folder}: the embedded images and scene files add up to more than {MAX_EMBED_BYTES:,} bytes; "
            "make the report without --embed (the page then links them)"
        )


def _data_uri(data: bytes, path: Path) -> str:
    kind = next((kind for magic, kind in IMAGE_TYPES.items() if data.startswith(magic)), None)
    if kind is None:
        raise GalleryError(f"{path}: is not a PNG or JPEG image; refused")
    return f"data:{kind};base64," + base64.b64encode(data).decode("ascii")


def _asset(name: str) -> str:
    return resources.files("physcensis.gallery").joinpath(name).read_text(encoding="utf-8")


def _csp_hash(text: str) -> str:
    return "sha256-" + base64.b64encode(hashlib.sha256(text.encode("utf-8")).digest()).decode("ascii")


def _claim_in_scene_folder(folder: Path) -> None:
    """A scene folder physcensis wrote lists the entries it owns; index.html joins them, so that solving into the
    folder again neither refuses it as a user's file nor leaves a stale gallery behind."""
    owned = owned_entries(folder)
    if owned is None or INDEX_NAME in owned or not (folder / OWNER_FILE).is_file():
        return
    text = json.dumps({"format": OWNER_FORMAT, "entries": sorted((owned | {INDEX_NAME}) - {OWNER_FILE})}, indent=1)
    atomic_write_text(folder / OWNER_FILE, text + "\n")


_TEMPLATE = (
    PAGE_START
    + """<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="{policy}">
<link rel="icon" href="data:,">
<title>{title}</title>
<style>{style}</style>
</head>
<body>
<div class="top">
<h1>{title} <span class="where">{where}</span></h1>
<div class="controls">
<label>prompt contains <input id="filter-text" type="search" placeholder="filter prompts"></label>
<label>method <select id="filter-method"><option value="">all methods</option></select></label>
<div class="range">
<label>metric <select id="range-metric"><option value="">(range on)</option></select></label>
<label>from <input id="range-min" type="number" step="any"></label>
<label>to <input id="range-max" type="number" step="any"></label>
</div>
<label class="check"><input id="filter-failures" type="checkbox"> has failures</label>
<label class="check"><input id="group-prompt" type="checkbox"> side by side per prompt</label>
<label>sort by <select id="sort-key"><option value="index">file order</option><option value="prompt">prompt</option>\
<option value="method">method</option><option value="seed">seed</option></select></label>
<label>order <select id="sort-order"><option value="asc">ascending</option><option value="desc">descending</option>\
</select></label>
<button id="reset" type="button">reset</button>
<span id="count" role="status"></span>
</div>
</div>
<main>
<table id="summary" class="summary"></table>
<div id="cards"></div>
<p id="empty" hidden>No scene matches the filters.</p>
</main>
<dialog id="viewer" class="viewer" aria-label="3-D view of a scene">
<div class="viewer-bar">
<span id="viewer-title" class="viewer-title"></span>
<span class="viewer-help">drag: orbit · right-drag or shift-drag: pan · wheel: zoom · click an object to see it</span>
<button id="viewer-close" type="button">close</button>
</div>
<div class="viewer-body">
<div id="viewer-stage" class="viewer-stage"></div>
<aside id="viewer-info" class="viewer-info"></aside>
</div>
<p id="viewer-message" class="viewer-message" role="status" hidden></p>
</dialog>
<script type="application/json" id="gallery-data">{data}</script>
<script>{dialog}</script>
<script>{script}</script>
<script type="application/json" id="viewer-code">{viewer}</script>
{glbs}
</body>
</html>
"""
)
