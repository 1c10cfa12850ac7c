from __future__ import annotations

import json
from pathlib import Path

import pytest

from physcensis.errors import ProgramParseError
from physcensis.program import Declaration, ItemCount, Relation, load_program, parse_program
from physcensis.program.lenient_json import read_lenient
from physcensis.scene import MAX_PROMPT_CHARS

from ..conftest import EXAMPLES, SHARED_PROGRAMS


def test_strict_json_list() -> None:
    program = parse_program('[["cup_0", "a mug"], ["cup_0", "PLACE-ANYWHERE", "root", {}]]')
    assert program.entries == (
        Declaration(1, "cup_0", "a mug"),
        Relation(2, "cup_0", "PLACE-ANYWHERE", "root", {}, program.relations[0].spec),
    )


def test_object_form_reads_support() -> None:
    program = load_program(EXAMPLES / "dining_4.json")
    assert program.support is not None
    assert program.support.size == (1.4, 1.0)
    assert program.support.top_height == pytest.approx(0.75)


def test_llm_style_text_matches_its_strict_equivalent() -> None:
    program = load_program(EXAMPLES / "desk_llm_style.txt")
    assert [e.object_id for e in program.declarations] == ["monitor_0", "keyboard_0", "mouse_0", "mug_0"]
    assert len(program.entries) == 15
    assert program.read_problems == ()


@pytest.mark.parametrize(
    "text",
    [
        'Sure! Here it is:\n```json\n[["a", "a cup"], ["a", "PLACE-ANYWHERE", "root", {},],]\n```\nEnjoy.',
        "[['a', 'a cup'] ['a', 'place_anywhere', 'root', {}]]",
        '[\n  ["a", "a cup"], // the cup\n  # comment line\n  ["a", "Place-Anywhere", "root", {}]\n]',
        '[["a", "a cup"], /* block */ ["a", "PLACE ANYWHERE", "root", None]]',
        '["a", "a cup"],\n["a", "PLACE-ANYWHERE", "root", {}]',  # no outer brackets
        "[[a, 'a cup'], [a, PLACE-ANYWHERE, root, {}]]",  # bare words
    ],
)
def test_tolerant_forms_give_the_same_program(text: str) -> None:
    program = parse_program(text)
    assert program.to_json() == [["a", "a cup"], ["a", "PLACE-ANYWHERE", "root", {}]]


def test_python_literals_and_bare_references() -> None:
    data = read_lenient('[["k", "SYMMETRY-ALONG", "f", {"C": plate_0, "flag": True, "none": None}]]')
    assert data == [["k", "SYMMETRY-ALONG", "f", {"C": "plate_0", "flag": True, "none": None}]]


def test_predicate_names_are_canonicalised() -> None:
    program = parse_program('[["a","d"],["a","align_center_lr","root",{}],["a","facingFront","root",{}]]')
    assert [r.predicate for r in program.relations] == ["ALIGN-CENTER-LR", "FACING-FRONT"]


def test_place_in_forms() -> None:
    program = parse_program(
        '[["b","a bowl"],["a","an apple"],["c","a cherry"],'
        '[[["apple",3],["orange",2]],"PLACE-IN","b",{}],'
        '["a","PLACE-IN","b",{}],[["a","c"],"PLACE-IN","b",{}]]'
    )
    subjects = [r.subject for r in program.relations]
    assert subjects == [(ItemCount("apple", 3), ItemCount("orange", 2)), ("a",), ("a", "c")]


def test_canonical_output_round_trips() -> None:
    program = load_program(EXAMPLES / "dining_4.json")
    again = parse_program(json.dumps(program.to_json()))
    assert again.to_json() == program.to_json()


@pytest.mark.parametrize("text", ["", "no brackets here", "[[[", '{"support": {}}', "[1, 2"])
def test_text_without_a_program_raises_our_error(text: str) -> None:
    with pytest.raises(ProgramParseError):
        program = parse_program(text)
        assert program.read_problems  # a parsed-but-empty program reports instead


def test_deep_nesting_is_refused_not_a_recursion_error() -> None:
    with pytest.raises(ProgramParseError, match="nested deeper"):
        parse_program("[" * 5000 + "]" * 5000)


def test_shape_problems_are_reported_with_their_index() -> None:
    program = parse_program('[["a","d"], 5, ["a"], ["a", 3, "root", {}], ["a","PLACE-ON-BASE","root",[1]]]')
    indices = sorted(p.index for p in program.read_problems if p.index is not None)
    assert indices == [2, 3, 4, 5]


def _nested(depth: int) -> list[object]:
    value: list[object] = []
    for _ in range(depth):
        value = [value]
    return value


@pytest.mark.parametrize(
    ("entry", "rule", "about"),
    [
        ([3, "a mug"], "bad-entry", None),
        (["cup_0", "PLACE-ON"], "missing-target", "cup_0"),
        (["cup_0", 3], "no-description", "cup_0"),
        (["cup_0", 7, "root", {}], "bad-entry", "cup_0"),
        (["cup_0", "LEFT-OF", 5, [1]], "bad-params", "cup_0"),  # the parameters are read before the target
        (["cup_0", "LEFT-OF", 5, {}], "bad-entry", "cup_0"),
        ([7, "LEFT-OF", "root"], "bad-entry", None),
        ([[1], "PLACE-IN", "bowl_0", {}], "bad-items", None),
        ([[["apple", 10**400]], "PLACE-IN", "bowl_0", {}], "param-range", None),
        (["g", "GROUP", "a", {}], "bad-members", "g"),
        (["cup_0", "LEFT-OF", "root", {"x": _nested(70)}], "bad-entry", None),  # deeper than MAX_DEPTH
    ],
)
def test_each_wrong_entry_shape_is_one_problem_of_its_rule(entry: list[object], rule: str, about: str | None) -> None:
    program = parse_program([entry, ["cup_0", "a mug"]])
    assert [(p.index, p.object, p.severity, p.rule) for p in program.read_problems] == [(1, about, "error", rule)]
    assert program.entries == (Declaration(2, "cup_0", "a mug"),)


def test_object_form_reports_unknown_keys_and_a_prompt_it_cannot_hold() -> None:
    program = parse_program({"program": [["cup_0", "a mug"]], "prompt": "x" * (MAX_PROMPT_CHARS + 1), "colour": 1})
    assert program.prompt is None
    rules = [(p.severity, p.rule) for p in program.read_problems]
    assert rules == [("warning", "unknown-key"), ("error", "bad-prompt")]
    assert parse_program({"program": [["cup_0", "a mug"]], "prompt": 3}).read_problems == ()
    with pytest.raises(ProgramParseError, match='"program" key'):
        parse_program({"prompt": "a mug"})


def test_unreadable_file_names_the_file(tmp_path: Path) -> None:
    with pytest.raises(ProgramParseError, match="missing.json"):
        load_program(tmp_path / "missing.json")


def test_bundled_examples_match_the_shared_bench() -> None:
    """The bundled examples are the shared bench's programs: with ../shared/bench beside the repository, a copy that
    drifted from it (or is missing) fails here; without it there is nothing to compare, and the tests use the copies."""
    shared = sorted(SHARED_PROGRAMS.iterdir()) if SHARED_PROGRAMS.is_dir() else []
    for path in shared:
        assert (EXAMPLES / path.name).is_file(), f"{path.name} is in {SHARED_PROGRAMS} but not bundled"
        assert (EXAMPLES / path.name).read_text() == path.read_text(), path.name
    assert len([p for p in EXAMPLES.iterdir() if p.suffix in {".json", ".txt"}]) >= 6
