"""`physcensis report`: the HTML gallery of a folder of scenes."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.markup import escape

from physcensis.cli.errors import reports_errors
from physcensis.cli.options import console

if TYPE_CHECKING:
    from physcensis.gallery.serve import ReportServer


@reports_errors
def report(
    folder: Annotated[
        Path,
        typer.Argument(help="a folder of scene folders (generate, solve, batch, bench clutter --out, eval compare)"),
    ],
    embed: Annotated[
        bool,
        typer.Option("--embed", help="put the images and 3-D scenes inside the page: one portable file, larger"),
    ] = False,
    serve: Annotated[
        bool,
        typer.Option(
            "--serve",
            help="then serve the folder on 127.0.0.1 (read-only) until Ctrl-C, so the 3-D view loads each scene.glb",
        ),
    ] = False,
    port: Annotated[int, typer.Option("--port", help="the port of --serve; 0 picks a free one")] = 0,
    overwrite: Annotated[
        bool, typer.Option("--overwrite", help="replace an index.html there that physcensis did not write")
    ] = False,
) -> None:
    """Write FOLDER/index.html: every scene's render, layout, prompt, method, metrics and failures, sortable and
    filterable, and a 3-D view of each scene with a scene.glb; it opens from the file system, no server needed (the
    3-D view then needs --embed, or --serve). With FOLDER/results.jsonl (eval compare), its rows are the cards."""
    from physcensis.gallery import GalleryError, collect_cards, write_page
    from physcensis.gallery.serve import report_server

    if port and not serve:
        raise GalleryError(f"--port {port}: a port is only for --serve")
    server = report_server(folder, port) if serve else None  # a port in use is refused before the page is written
    try:
        cards = collect_cards(folder)
        page = write_page(folder, cards, embed=embed, overwrite=overwrite)
        count = len(cards)
        where = "open it in a browser" if server is None else f"serving it at {server.url} (Ctrl-C stops)"
        console.print(f"wrote {escape(str(page))} ({count} scene{'s' if count != 1 else ''}); {where}", soft_wrap=True)
        if server is not None:
            _serve(server)
    finally:
        if server is not None:
            server.server_close()


def _serve(server: ReportServer) -> None:
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        console.print("stopped serving")
