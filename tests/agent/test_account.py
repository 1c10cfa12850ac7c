"""The prompt's parse (agent/parse.py) and the account of what each noun phrase became (agent/account.py): a phrase
matches the objects whose own name has its head noun, and one that names a thing the scene lacks is missing."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from physcensis.agent.account import (
    account_of,
    displaced_phrases,
    graph_displaced,
    graph_sides_missed,
    missing_phrases,
    read_account,
)
from physcensis.agent.base import AgentContext
from physcensis.agent.parse import parse
from physcensis.agent.planner import OfflinePlanner
from physcensis.assets import default_catalogue
from physcensis.bench.prompt_suite import SUITES, load_suite
from physcensis.cli import app
from physcensis.scene import PlacedObject, Placement, Scene, Support


def _relations(text: str) -> set[tuple[str, str, str]]:
    p = parse(text)
    return {(p.phrases[r.subject].head, r.word, p.phrases[r.target].head) for r in p.relations}


def test_phrases_have_their_head_noun_and_count() -> None:
    p = parse("a kitchen counter with a cutting board, three knives, some vegetables and a kettle")
    heads = [(x.head, x.quantity, x.count) for x in p.phrases]
    assert heads == [
        ("counter", "one", None),
        ("board", "one", None),
        ("knife", "exact", 3),
        ("vegetable", "vague", None),
        ("kettle", "one", None),
    ]
    assert parse("a cup on each saucer").phrases[1].quantity == "each"


def test_relations_join_the_phrases_a_person_would() -> None:
    assert _relations("a tray with a teapot, a cup and a sugar bowl") == {
        ("tray", "with", "teapot"),
        ("tray", "with", "cup"),
        ("tray", "with", "bowl"),
    }
    assert _relations("a pot holding a ladle") == {("pot", "hold", "ladle")}
    assert ("bowl", "full of", "apple") in _relations("a bowl full of apples beside a glass pitcher")
    # "it" is the laptop; the pen's side belongs to the pen (the parser hangs it on the laptop)
    assert _relations("a laptop with a notebook in front of it and a pen to the right of the notebook") >= {
        ("notebook", "in front of", "laptop"),
        ("pen", "to the right of", "notebook"),
    }
    # a listed thing with its own place first ("and behind it a bottle") is a phrase of its own, and holds its wine
    relations = _relations("a glass bowl with apples in it, and behind it a bottle of wine")
    assert ("bottle", "of", "wine") in relations and ("bowl", "of", "wine") not in relations
    # a partitive "of" says which ones, not what something holds
    assert not any(word == "of" for _, word, _ in _relations("two saucers with a cup on every one of them"))


def _scene(*descriptions: str) -> Scene:
    catalogue = default_catalogue()
    objects = []
    for k, description in enumerate(descriptions):
        asset = catalogue.resolve(description)
        objects.append(
            PlacedObject(
                id=f"o{k}", description=description, asset=asset.id, category=asset.category,
                position=(0.1 * k, 0.0, 0.0), mass=max(asset.mass, 1e-3), friction=0.5,
            )
        )  # fmt: skip
    return Scene(support=Support(kind="table", size=(1.2, 0.8)), objects=objects)


def _statuses(text: str, scene: Scene) -> dict[str, str]:
    return {a.phrase: a.status for a in account_of(parse(text), scene, default_catalogue())}


def test_a_modifier_that_matches_is_not_the_thing() -> None:
    """A vegetable peeler does not stand for "some vegetables": the head noun decides."""
    text = "a cutting board, a knife and some vegetables on the table"
    statuses = _statuses(text, _scene("a wooden cutting board", "a kitchen knife", "a vegetable peeler"))
    assert statuses == {
        "a cutting board": "placed",
        "a knife": "placed",
        "some vegetables": "missing",
        "the table": "support",
    }


def test_contents_supports_settings_and_places_are_said_as_such() -> None:
    statuses = _statuses(
        "a jug of lemonade and a mug to the left of the tray on a kitchen table for two people",
        _scene("a glass jug", "a white mug", "a serving tray"),
    )
    assert statuses["a jug"] == "placed" and statuses["lemonade"] == "contents"
    assert statuses["the left"] == "place" and statuses["a kitchen table"] == "support"
    assert statuses["two people"] == "setting"


def test_countable_things_a_holder_is_of_are_missing_when_the_scene_lacks_them() -> None:
    """ "a tray of muffins" is a tray and muffins, not a muffin tray: a muffin tin whose synonym is "tray for
    muffins" does not stand for the muffins (a name's head is before "for" or "with"), and plural contents are
    things, not the unmodelled stuff "a mug of coffee" holds."""
    statuses = _statuses("a tray of muffins", _scene("a gold-coloured muffin pan"))
    assert statuses == {"a tray": "placed", "muffins": "missing"}
    assert _statuses("a mug of coffee", _scene("a white mug"))["coffee"] == "contents"


def test_a_dropped_noun_is_missing_and_generate_exits_1(tmp_path: Path) -> None:
    out = tmp_path / "scene"
    result = CliRunner().invoke(app, ["generate", "potatoes in a basket", "--out", str(out), "--export", "none"])
    assert result.exit_code == 1
    assert "'potatoes' -> nothing" in " ".join(result.output.split())
    report = json.loads((out / "report.json").read_text())["generate"]
    assert {"potato"} <= {row["category"] for row in report["missing"]}
    assert [p["status"] for p in report["reading"]["phrases"]] == ["missing", "placed"]


@pytest.mark.long
@pytest.mark.parametrize("suite", ["public", "home"])
def test_every_noun_phrase_of_the_suites_is_accounted_for(suite: str) -> None:
    """No prompt of the suites drops a thing it names without the report saying so: every noun phrase becomes an
    object of the planner's program (or the support, the setting, contents, an arrangement, a place)."""
    catalogue = default_catalogue()
    unaccounted = {}
    for case in load_suite(SUITES[suite]):
        support = Support(kind=case["support"]["kind"], size=tuple(case["support"]["size"]))
        program = json.loads(OfflinePlanner(variety="none").propose(AgentContext(case["prompt"], support, ())))
        declared = [e[1] for e in program if len(e) == 2 and isinstance(e[0], str)]
        missing = missing_phrases(account_of(parse(case["prompt"]), _scene(*declared), catalogue))
        if missing:
            unaccounted[case["id"]] = [row["phrase"] for row in missing]
    assert unaccounted == {}


@pytest.mark.parametrize(
    ("text", "heads"),
    [
        ("a potting shelf with a watering can, a paint can and a flower vase", ["shelf", "can", "can", "vase"]),
        ("two limes and a peeler resting on a chopping board", ["lime", "peeler", "board"]),
        ("a small clock standing between a desk lamp and a pile of books", ["clock", "lamp", "pile", "book"]),
    ],
)
def test_the_head_noun_survives_the_taggers_slips(text: str, heads: list[str]) -> None:
    """ "can" tagged as a modal, "peeler" as a comparative, "standing" as the noun: the head is still the thing."""
    assert [p.head for p in parse(text).phrases] == heads


def _held(scene: Scene, held: int, holder: int, predicate: str = "PLACE-IN") -> None:
    """Object `held` of the scene rests in (or on) object `holder`."""
    scene.objects[held] = scene.objects[held].model_copy(
        update={"placement": Placement(predicate=predicate, target=scene.objects[holder].id)}
    )


def test_contents_placed_beside_their_holder_are_elsewhere_and_said_so() -> None:
    """ "a vase of flowers" whose flowers stand on the table is not what was asked: the account says where they are
    not; contents in the holder, or on what is in it, are placed."""
    text = "a bowl of apples next to a mug"
    scene = _scene("a glass bowl", "a red apple", "a red apple", "a white mug")
    statuses = _statuses(text, scene)
    assert statuses["apples"] == "elsewhere"
    accounts = account_of(parse(text), scene, default_catalogue())
    (row,) = displaced_phrases(accounts)
    assert row["phrase"] == "apples" and row["placed"] == 2 and "a bowl" in row["why"]
    _held(scene, 1, 0)
    _held(scene, 2, 1, "PLACE-ON")  # the second apple on the first, which is in the bowl
    assert _statuses(text, scene)["apples"] == "placed"
    assert displaced_phrases(account_of(parse(text), scene, default_catalogue())) == []


def test_an_arrangement_or_a_list_passed_relation_is_no_holder() -> None:
    """ "a pair of dice" beside a pair of slippers holds nothing; "napkins" after "a bowl of grapes and" were given the
    bowl only by the list, which a person does not read as in the bowl."""
    scene = _scene("a pair of slippers", "a red dice", "a red dice")
    assert _statuses("a pair of slippers and a pair of dice", scene)["dice"] == "placed"
    scene = _scene("a wide fruit bowl", "a bunch of red grapes", "a red napkin")
    _held(scene, 1, 0)
    statuses = _statuses("a bowl of grapes and napkins", scene)
    assert statuses["grapes"] == "placed" and statuses["napkins"] == "placed"


def _in(scene: Scene, oid: str, holder: str) -> Scene:
    """The scene with object `oid` placed in `holder`."""
    scene.objects = [
        o.model_copy(update={"placement": Placement(predicate="PLACE-IN", target=holder)}) if o.id == oid else o
        for o in scene.objects
    ]
    return scene


def test_what_the_graph_put_in_each_holder_and_stands_elsewhere_is_counted() -> None:
    """ "two bowls with one spoon in each": the graph asks a spoon in each bowl; a spoon the repair put on the table
    is said, with how many of how many."""
    graph = {
        "objects": [
            {"id": "bowl", "name": "bowl", "count": 2, "relation": "none", "of": []},
            {"id": "spoon", "name": "spoon", "count": 1, "relation": "in each", "of": ["bowl"]},
        ]
    }
    scene = _in(_scene("a white bowl", "a white bowl", "a tea spoon", "a tea spoon"), "o2", "o0")
    assert graph_displaced(graph, scene) == [
        {"category": "spoon", "placed": 2, "phrase": "spoon", "why": "1 of 2 asked in the bowl stands elsewhere"}
    ]
    assert graph_displaced(graph, _in(scene, "o3", "o1")) == []
    assert graph_displaced(graph | {"objects": graph["objects"][:1]}, scene) == []  # nothing asked in anything


def _at(scene: Scene, oid: str, x: float, y: float) -> Scene:
    scene.objects = [o.model_copy(update={"position": (x, y, 0.0)}) if o.id == oid else o for o in scene.objects]
    return scene


def test_what_the_graph_set_on_a_side_and_stands_on_no_such_side_is_said() -> None:
    """ "a cup to the left of the teapot" as the viewer of the default render sees it (their left is world -y): a
    scene whose cup stands to the teapot's right, or in front of it, says so; one whose cup is on its left does not."""
    graph = {
        "objects": [
            {"id": "teapot", "name": "teapot", "count": 1, "relation": "none", "of": []},
            {"id": "cup", "name": "cup", "count": 1, "relation": "left of", "of": ["teapot"]},
        ]
    }
    scene = _at(_at(_scene("a red teapot", "a white coffee cup"), "o0", 0.0, 0.0), "o1", 0.0, 0.2)
    (row,) = graph_sides_missed(graph, scene)
    assert row["category"] == "cup" and "left of the teapot" in row["why"]
    assert graph_sides_missed(graph, _at(scene, "o1", 0.25, -0.05)) != []  # in front, a little to the left
    assert graph_sides_missed(graph, _at(scene, "o1", 0.05, -0.2)) == []
    assert graph_sides_missed(graph | {"objects": graph["objects"][:1]}, scene) == []  # no side asked


def test_a_verb_of_standing_after_a_fronted_place_is_no_head() -> None:
    """ "on either side of the keyboard lie a mouse": the tagger may make "the keyboard lie" one noun phrase, whose
    head is the keyboard (a head "lie" was reported missing)."""
    heads = [p.head for p in parse("On either side of the keyboard lie a mouse and a notebook.").phrases]
    assert "lie" not in heads and "keyboard" in heads


@pytest.mark.parametrize(
    "text",
    [
        "Scatter three apples around, and set a bowl down with a banana to the right of it.",
        "A desk after a long day of work: a laptop and a stapler",
        "a coffee maker and a jar of coffee beans",
        "Potting bench out in the shed: a watering can and a trowel",
        "Stir fry in progress: a wok and a bowl",
        "A potted plant with a saucer beneath it to catch the water",
        "Living room floor for a robot to tidy up: a cushion",
    ],
)
def test_times_places_grains_and_verbs_said_are_no_missing_things(text: str) -> None:
    """What a correct scene of these prompts holds accounts for every phrase: an occasion, the setting, the robot a
    scene is for, a jar's beans, a verb the tagger took for a noun (each was reported missing, exit 1)."""
    support = Support(kind="table", size=(0.8, 1.4))
    program = json.loads(OfflinePlanner(variety="none").propose(AgentContext(text, support, ())))
    declared = [e[1] for e in program if len(e) == 2 and isinstance(e[0], str)]
    assert missing_phrases(account_of(parse(text), _scene(*declared), default_catalogue())) == []


def test_kinds_in_brackets_and_run_together_words_are_no_missing_things() -> None:
    """ "three canisters (flour, sugar, coffee)" names the canisters' kinds and "infront" is "in front": the account
    parses the words the reading reads things from, so neither is said missing."""
    reading = read_account(
        "three canisters (flour, sugar, coffee) and a toy train infront of them",
        _scene("a metal canister", "a metal canister", "a metal canister", "a wooden toy train"),
        default_catalogue(),
    )
    assert all(p.status != "missing" for p in reading.phrases), [(p.phrase, p.status) for p in reading.phrases]
