"""The report's 3-D viewer script: three.js as vendored in vendor/ (see vendor/README.md), then viewer.js.

The page carries it as inert JSON text and runs it, as one inline script admitted by its hash, only when a card's
3-D button is first pressed: a report of many scenes opens without parsing 600 kB of three.js. One classic script
rather than ES modules, because a page opened from the file system can load no module file and an import map could
only point at files or at `data:`/`blob:` URLs the policy would then have to admit.
"""

from __future__ import annotations

from functools import cache
from importlib import resources

from physcensis.gallery.cards import GalleryError

THREE_BUNDLE = "vendor/three-viewer.min.js"
VIEWER = "viewer.js"


@cache
def viewer_script() -> str:
    """The viewer's whole script text: the three.js bundle (which sets `PhyscensisThree`), then viewer.js."""
    package = resources.files("physcensis.gallery")
    try:
        parts = [package.joinpath(name).read_text(encoding="utf-8") for name in (THREE_BUNDLE, VIEWER)]
    except OSError as exc:
        raise GalleryError(f"the report's 3-D viewer is missing from the installed package ({exc})") from None
    return parts[0].rstrip() + "\n;\n" + parts[1]
