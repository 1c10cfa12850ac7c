"""`physcensis report`: the HTML gallery of a folder of scenes."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from physcensis.cli.errors import reports_errors
from physcensis.cli.options import console


@reports_errors
def report(
    folder: Annotated[
        Path,
        typer.Argument(help="a folder of scene folders (generate, solve, batch, bench clutter --out, eval compare)"),
    ],
    embed: Annotated[
        bool, typer.Option("--embed", help="put the images inside the page: one portable file, larger")
    ] = False,
    overwrite: Annotated[
        bool, typer.Option("--overwrite", help="replace an index.html there that physcensis did not write")
    ] = False,
) -> None:
    """Write FOLDER/index.html: every scene's render, layout, prompt, method, metrics and failures, sortable and
    filterable; it opens from the file system, no server needed. With FOLDER/results.jsonl (eval compare), its rows
    are the cards."""
    from physcensis.gallery import collect_cards, write_page

    cards = collect_cards(folder)
    page = write_page(folder, cards, embed=embed, overwrite=overwrite)
    count = len(cards)
    console.print(
        f"wrote {escape(str(page))} ({count} scene{'s' if count != 1 else ''}); open it in a browser", soft_wrap=True
    )
