"""The report's data: cards from results.jsonl and from plain scene folders, what the page embeds, and its escaping."""

from __future__ import annotations

import html
import json
import math
import re
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from physcensis.cli import app
from physcensis.fileio import OutputError, check_output_dir, output_directory
from physcensis.gallery import INDEX_NAME, GalleryError, collect_cards, write_report
from physcensis.gallery.page import embed_json, groups_by_prompt, page_data, render_page
from tests.gallery.folders import HOSTILE, results_file, row, scene_folder

runner = CliRunner()


def embedded_data(page: str) -> dict:
    """The JSON the page carries, read back as the browser's JSON.parse would."""
    block = re.search(r'<script type="application/json" id="gallery-data">(.*?)</script>', page, re.DOTALL)
    assert block is not None
    return json.loads(block.group(1))


# ---- results.jsonl --------------------------------------------------------------------------------------------------


def test_cards_from_results_are_its_rows_with_their_own_method_metrics_and_failures(tmp_path: Path) -> None:
    scene_folder(tmp_path / "scenes" / "a", prompt="ignored: the row's prompt wins")
    scene_folder(tmp_path / "scenes" / "b", layout=False)
    results_file(
        tmp_path,
        [
            row("two cups side by side", "random", 3, "scenes/a", {"relation_accuracy": 0.5, "attempts": 4}),
            row("a pen in a cup", "llm-only", 1, "scenes/b", {"relation_accuracy": 1, "note": "text", "flag": True}),
            row("a pen in a cup", "ours", 1, "scenes/missing", {"settle_distance_m": float("nan")}, ["pen_0: fell"]),
        ],
    )
    scene_folder(tmp_path / "stray", prompt="a folder no row names")  # rows are the cards, not the folders
    cards = collect_cards(tmp_path)
    assert [(c.prompt, c.method, c.seed) for c in cards] == [
        ("two cups side by side", "random", 3),
        ("a pen in a cup", "llm-only", 1),
        ("a pen in a cup", "ours", 1),
    ]
    assert cards[0].metrics == {"relation_accuracy": 0.5, "attempts": 4.0}
    assert cards[1].metrics == {"relation_accuracy": 1.0}  # strings and booleans are not metrics
    assert cards[2].metrics == {"settle_distance_mm": None}  # NaN shows as missing
    assert (cards[0].render, cards[0].layout) == ("scenes/a/render.png", "scenes/a/layout.png")
    assert (cards[1].render, cards[1].layout) == ("scenes/b/render.png", None)
    assert (cards[2].render, cards[2].layout, cards[2].failures, cards[2].ok) == (None, None, ["pen_0: fell"], False)
    data = page_data(cards, tmp_path)
    assert data["methods"] == ["random", "llm-only", "ours"]  # the order compare ran them in
    assert data["metrics"] == ["relation_accuracy", "attempts", "settle_distance_mm"]
    assert data["images"] == {}


def test_a_results_file_with_no_rows_or_a_broken_line_is_a_clear_error_a_torn_last_line_is_left_out(
    tmp_path: Path,
) -> None:
    (tmp_path / "results.jsonl").write_text("\n")
    with pytest.raises(GalleryError, match="results.jsonl has no rows"):
        collect_cards(tmp_path)
    (tmp_path / "results.jsonl").write_text(json.dumps(row("a cup", "ours", 0, "x", {})) + "\n{not json\n")
    with pytest.raises(GalleryError, match="line 2 is not JSON"):
        collect_cards(tmp_path)
    # A last line torn by a killed run (no newline after it) is left out, as eval compare leaves it out.
    (tmp_path / "results.jsonl").write_text(json.dumps(row("a cup", "ours", 0, "x", {})) + '\n{"prompt": "a ca')
    assert [c.prompt for c in collect_cards(tmp_path)] == ["a cup"]


# ---- plain scene folders --------------------------------------------------------------------------------------------


def test_cards_from_folders_find_every_scene_folder_and_read_its_files(tmp_path: Path) -> None:
    scene_folder(
        tmp_path / "batch" / "scenes" / "desk_000",
        prompt=None,
        report_prompt="a lamp and two books on a desk",
        metrics={"settle_distance_m": 0.002, "objects_placed": 3, "per_object": {"lamp_0": 0.0}},
        failed=[("book_1", "no room on the desk")],
        problems=[
            {"severity": "error", "message": "unknown predicate FLOAT"},
            {"severity": "warning", "message": "a warning is no failure"},
        ],
        batch={"prompt_id": "desk", "seed": 1234, "prompt": "a lamp and two books on a desk"},
    )
    scene_folder(tmp_path / "clutter_0007", prompt="clutter", render=False, layout=False)
    pending = {"predicate": "PLACE-IN", "objects": ["pen_0", "pen_1"], "reason": "physics off"}
    scene_folder(tmp_path / "spatial_only", prompt="pens in a cup", pending=[pending])
    scene_folder(tmp_path / ".hidden.123.partial", prompt="a staging folder is not a scene")
    scene_folder(tmp_path / "clutter_0007" / "mjcf", prompt="exports are not searched")
    cards = collect_cards(tmp_path)
    assert [c.scene_dir for c in cards] == ["batch/scenes/desk_000", "clutter_0007", "spatial_only"]
    desk, clutter, spatial_only = cards
    assert (desk.prompt, desk.prompt_id, desk.method, desk.seed, desk.ok) == (
        "a lamp and two books on a desk",
        "desk",
        "ours",
        1234,
        False,
    )
    assert desk.metrics == {"settle_distance_mm": 2.0, "objects_placed": 3.0, "rounds": 3.0, "seconds": 1.5}
    assert desk.failures == ["unknown predicate FLOAT", "book_1: no room on the desk"]
    assert desk.render == "batch/scenes/desk_000/render.png"
    assert (clutter.prompt, clutter.seed, clutter.failures, clutter.render) == ("clutter", 7, [], None)
    assert spatial_only.failures == ["pen_0, pen_1: PLACE-IN pending (physics off)"]


def test_a_scene_folder_given_itself_is_one_card(tmp_path: Path) -> None:
    scene = scene_folder(tmp_path / "one", prompt="a bowl of apples")
    [card] = collect_cards(scene)
    assert (card.scene_dir, card.prompt, card.render) == (".", "a bowl of apples", "render.png")


def test_a_damaged_scene_file_is_a_card_that_says_so(tmp_path: Path) -> None:
    good = scene_folder(tmp_path / "good", prompt="a bowl of apples")
    broken = scene_folder(tmp_path / "broken", prompt="a stack of books")
    (broken / "scene.json").write_text('{"prompt": "a stack of bo')  # cut off mid-write
    cards = {card.scene_dir: card for card in collect_cards(tmp_path)}
    assert not any("scene.json" in f for f in cards[good.name].failures)
    assert any("scene.json could not be read" in f for f in cards[broken.name].failures)


def test_a_folder_with_no_scenes_is_a_clear_error(tmp_path: Path) -> None:
    (tmp_path / "notes.txt").write_text("nothing here")
    with pytest.raises(GalleryError, match="nothing to show: no scene folder"):
        collect_cards(tmp_path)
    with pytest.raises(GalleryError, match="is not a folder"):
        collect_cards(tmp_path / "notes.txt")


# ---- the page -------------------------------------------------------------------------------------------------------


def test_strings_from_files_cannot_leave_the_data_block_and_read_back_unchanged(tmp_path: Path) -> None:
    folder = tmp_path / "<b>bold</b>"
    scene_folder(folder / "s", prompt=HOSTILE, failed=[("x", HOSTILE)])
    page = render_page(collect_cards(folder), folder)
    # The data block's, the viewer code's block, the dialog's and the page script's own: nothing from the files.
    assert page.count("</script>") == 4
    assert "<!--" not in page.split("<!-- physcensis report -->", 1)[1]
    assert "<b>bold</b>" not in page and html.escape("<b>bold</b>") in page  # the folder's name in the title
    data = embedded_data(page)
    assert data["cards"][0]["prompt"] == HOSTILE
    assert data["cards"][0]["failures"] == [f"x: {HOSTILE}"]
    assert set(embed_json({"s": "\u2028<>&"})) <= set(map(chr, range(32, 127)))  # ASCII only: no raw line separator


def test_paths_are_relative_urls_and_embed_inlines_the_images(tmp_path: Path) -> None:
    scene_folder(tmp_path / "run #1 ?50%", prompt="a vase")
    [card] = collect_cards(tmp_path)
    linked = page_data([card], tmp_path)
    assert linked["urls"]["run #1 ?50%/render.png"] == "run%20%231%20%3F50%25/render.png"
    assert linked["urls"]["run #1 ?50%"] == "run%20%231%20%3F50%25"
    embedded = page_data([card], tmp_path, embed=True)
    assert set(embedded["images"]) == {"run #1 ?50%/render.png", "run #1 ?50%/layout.png"}
    render = embedded["images"]["run #1 ?50%/render.png"]
    assert render.startswith("data:image/png;base64,") and len(render) > 40


def test_write_report_replaces_its_own_page_but_not_a_users(tmp_path: Path) -> None:
    scene_folder(tmp_path / "a")
    page = write_report(tmp_path)
    assert page == tmp_path / INDEX_NAME and page.read_text().startswith("<!DOCTYPE html>")
    assert write_report(tmp_path, embed=True) == page  # its own page is replaced
    assert "data:image/png;base64," in page.read_text()
    page.write_text("<html>my own page</html>")
    with pytest.raises(OutputError, match="was not written by physcensis"):
        write_report(tmp_path)
    assert page.read_text() == "<html>my own page</html>"
    write_report(tmp_path, overwrite=True)
    assert "physcensis report" in page.read_text()


def test_a_page_in_a_scene_folder_does_not_make_the_folder_a_users(tmp_path: Path) -> None:
    """solve --out into a scene folder refuses folders holding files physcensis did not write: index.html is listed
    as physcensis's own, and the next solve into the folder replaces it."""
    with output_directory(tmp_path / "scene") as staging:
        scene_folder(staging)
    write_report(tmp_path / "scene")
    check_output_dir(tmp_path / "scene")  # refused (OutputError) if index.html were a user's file
    with output_directory(tmp_path / "scene") as staging:
        scene_folder(staging, prompt="solved again")
    assert not (tmp_path / "scene" / INDEX_NAME).exists()  # the stale gallery went with the old scene


def test_report_command_writes_the_page_and_refuses_an_empty_folder(tmp_path: Path) -> None:
    scene_folder(tmp_path / "out" / "s1")
    scene_folder(tmp_path / "out" / "s2")
    result = runner.invoke(app, ["report", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    assert "2 scenes" in result.output
    assert len(embedded_data((tmp_path / "out" / INDEX_NAME).read_text())["cards"]) == 2
    (tmp_path / "empty").mkdir()
    result = runner.invoke(app, ["report", str(tmp_path / "empty")])
    assert result.exit_code == 2
    assert "nothing to show" in result.output
    assert not (tmp_path / "empty" / INDEX_NAME).exists()


def test_metrics_keep_their_values_with_every_length_in_millimetres(tmp_path: Path) -> None:
    metrics = {"max_penetration_mm": 0.25, "objects_placed": 12, "outside_cm": math.inf, "settle_distance_m": 0.0021}
    scene_folder(tmp_path / "s", metrics=metrics)
    [card] = collect_cards(tmp_path)
    assert card.metrics["max_penetration_mm"] == 0.25 and card.metrics["objects_placed"] == 12
    assert card.metrics["outside_mm"] is None and card.metrics["settle_distance_mm"] == pytest.approx(2.1)
    assert not any(name.endswith(("_m", "_cm")) for name in card.metrics)


def test_a_page_beside_clutter_scenes_does_not_stop_the_next_clutter_run(tmp_path: Path) -> None:
    from physcensis.cli.bench import _clutter_folder

    with output_directory(tmp_path / "no-stack_0003") as staging:
        scene_folder(staging, prompt="clutter")
    write_report(tmp_path)
    _clutter_folder(tmp_path, overwrite=False)  # refused (typer.Exit) if index.html were a user's file
    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(typer.Exit):
        _clutter_folder(tmp_path, overwrite=False)


def test_cards_start_grouped_by_prompt_for_the_seeds_of_one_method(tmp_path: Path) -> None:
    for k in range(2):
        scene_folder(tmp_path / "batch" / f"mug_{k}", prompt="a mug on a coaster")
    scene_folder(tmp_path / "batch" / "books_0", prompt="three books")
    assert page_data(collect_cards(tmp_path / "batch"), tmp_path / "batch")["group_by_prompt"] is True
    scene_folder(tmp_path / "one" / "mug", prompt="a mug on a coaster")
    scene_folder(tmp_path / "one" / "books", prompt="three books")
    assert groups_by_prompt(collect_cards(tmp_path / "one")) is False  # each prompt once: nothing to group
