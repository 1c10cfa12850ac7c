"""The HTML report: `index.html`, a gallery of scene folders (or of `eval compare`'s results) that opens from the
file system, sortable and filterable without a server."""

from physcensis.gallery.cards import Card, GalleryError, collect_cards
from physcensis.gallery.page import INDEX_NAME, write_page, write_report

__all__ = ["INDEX_NAME", "Card", "GalleryError", "collect_cards", "write_page", "write_report"]
