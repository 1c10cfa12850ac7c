"""The relation checker on hand-built scenes: each relation kind holds where it should and fails where it should not."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest

from physcensis.assets.catalogue import default_catalogue
from physcensis.evaluation.relations import CHECKS, YAW_CHECKS, SceneRelations, check_scene, check_scene_folder
from physcensis.program import parse_program
from physcensis.program.registry import PREDICATES, Effect, YawMode
from physcensis.scene import PlacedObject, Scene, Support, save_scene
from physcensis.solver.objects import yaw_quaternion

SUPPORT = Support(kind="table", size=(1.2, 0.8))
T = SUPPORT.top_height
BOOK, MUG, PLATE = "a hardcover book", "a white ceramic mug", "a white dinner plate"
BOWL, APPLE = "a wooden bowl", "an apple"
Pose = tuple[float, float, float, float]  # x, y, z, yaw


def scene_of(descriptions: dict[str, str], poses: dict[str, Pose], failed: tuple[str, ...] = ()) -> Scene:
    catalogue = default_catalogue()
    objects = []
    for oid, (x, y, z, yaw) in poses.items():
        asset = catalogue.resolve(descriptions[oid])
        objects.append(
            PlacedObject(
                id=oid,
                description=descriptions[oid],
                asset=asset.id,
                category=asset.category,
                position=(x, y, z),
                quaternion=yaw_quaternion(yaw),
                mass=0.3,
                friction=0.5,
                status="failed" if oid in failed else "placed",
                reason="could not be placed" if oid in failed else None,
            )
        )
    return Scene(support=SUPPORT, objects=objects)


@dataclass
class Case:
    """A program of one relation (plus what it needs), the poses where it holds and the poses where it does not."""

    entry: list[Any]
    objects: dict[str, str]
    good: dict[str, Pose]
    bad: dict[str, Pose]
    before: list[list[Any]] = field(default_factory=list)  # entries the relation needs (a group)
    failed: tuple[str, ...] = ()  # objects not placed in the bad scene
    also_bad: dict[str, dict[str, Pose]] = field(default_factory=dict)  # more scenes where it fails, by what is wrong

    def program(self) -> list[list[Any]]:
        return [[oid, d] for oid, d in self.objects.items()] + self.before + [self.entry]

    def checks(self, poses: dict[str, Pose], failed: tuple[str, ...] = ()) -> SceneRelations:
        scene = scene_of(self.objects, poses, failed)
        return check_scene(scene, default_catalogue(), program=parse_program(self.program()))


def books(*ids: str) -> dict[str, str]:
    return dict.fromkeys(ids, BOOK)


def beside(name: str, good: tuple[float, float], bad: tuple[float, float]) -> Case:
    """Book a against book b standing at the centre (a book is 0.24 m deep along x and 0.16 m wide along y)."""
    b = (0.0, 0.0, T, 0.0)
    return Case(
        ["a", name, "b", {}],
        books("a", "b"),
        {"a": (*good, T, 0.0), "b": b},
        {"a": (*bad, T, 0.0), "b": b},
    )


def facing_absolute(name: str) -> Case:
    angle = PREDICATES[name].yaw_rule().angle
    return Case(["m", name, "root", {}], {"m": MUG}, {"m": (0, 0, T, angle)}, {"m": (0, 0, T, angle + 1.0)})


def facing_relative(name: str, b_yaw: float, good: float, bad: float) -> Case:
    """Mug m at y = 0.3 turned relative to mug n at the centre."""
    n = (0.0, 0.0, T, b_yaw)
    return Case(
        ["m", name, "n", {}],
        {"m": MUG, "n": MUG},
        {"m": (0.0, 0.3, T, good), "n": n},
        {"m": (0.0, 0.3, T, bad), "n": n},
    )


GROUP = [["group_g", "GROUP", ["p", "k"], {"anchor": "p"}]]
PAIR = {"p": PLATE, "k": BOOK, "p-group_h": PLATE, "k-group_h": BOOK}
HOME = {"p": (-0.3, 0.0, T, 0.0), "k": (-0.3, 0.2, T, 0.0)}

CASES: dict[str, Case] = {
    "LEFT-OF": beside("LEFT-OF", (0.0, 0.2), (0.0, 0.1)),
    "RIGHT-OF": beside("RIGHT-OF", (0.0, -0.2), (0.0, -0.1)),
    "FRONT-OF": beside("FRONT-OF", (0.3, 0.0), (0.2, 0.0)),
    "BACK-OF": beside("BACK-OF", (-0.3, 0.0), (-0.2, 0.0)),
    "ALIGN-CENTER-LR": beside("ALIGN-CENTER-LR", (0.3, 0.0), (0.3, 0.03)),
    "ALIGN-CENTER-FB": beside("ALIGN-CENTER-FB", (0.0, 0.2), (0.03, 0.2)),
    "ALIGN-LEFT": beside("ALIGN-LEFT", (0.3, 0.0), (0.3, -0.03)),
    "ALIGN-RIGHT": beside("ALIGN-RIGHT", (0.3, 0.0), (0.3, 0.03)),
    "ALIGN-FRONT": beside("ALIGN-FRONT", (0.0, 0.2), (-0.03, 0.2)),
    "ALIGN-BACK": beside("ALIGN-BACK", (0.0, 0.2), (0.03, 0.2)),
    "SYMMETRY-ALONG": Case(
        ["a", "SYMMETRY-ALONG", "b", {"C": "c"}],
        books("a", "b", "c"),
        {"a": (0.1, -0.2, T, 0.0), "b": (0.1, 0.2, T, 0.0), "c": (0.1, 0.0, T, 0.0)},
        {"a": (0.15, -0.2, T, 0.0), "b": (0.1, 0.2, T, 0.0), "c": (0.1, 0.0, T, 0.0)},
    ),
    "FACING-FRONT": facing_absolute("FACING-FRONT"),
    "FACING-BACK": facing_absolute("FACING-BACK"),
    "FACING-LEFT": facing_absolute("FACING-LEFT"),
    "FACING-RIGHT": facing_absolute("FACING-RIGHT"),
    "FACING-TO": facing_relative("FACING-TO", 0.0, -math.pi / 2, 0.0),  # n is at -y from m
    "FACING-SAME-AS": facing_relative("FACING-SAME-AS", 0.7, 0.7, 0.0),
    "FACING-OPPOSITE-TO": facing_relative("FACING-OPPOSITE-TO", 0.7, 0.7 + math.pi, 0.7),
    "RANDOM-ROT": Case(
        ["m", "RANDOM-ROT", "root", {}], {"m": MUG}, {"m": (0, 0, T, 2.0)}, {"m": (0, 0, T, 2.0)}, failed=("m",)
    ),
    # a book beside another lines up best unturned (0.24 m of x overlap) rather than a quarter turned (0.16 m)
    "ORIENT-BY-RELATIVE-SIDE": Case(
        ["a", "ORIENT-BY-RELATIVE-SIDE", "b", {}],
        books("a", "b"),
        {"a": (0.0, 0.3, T, 0.0), "b": (0.0, 0.0, T, 0.0)},
        {"a": (0.0, 0.3, T, math.pi / 2), "b": (0.0, 0.0, T, 0.0)},
    ),
    "PLACE-ON-BASE": Case(
        ["a", "PLACE-ON-BASE", "root", {}], books("a"), {"a": (0.1, 0.1, T, 0.0)}, {"a": (0.1, 0.1, T + 0.05, 0.0)}
    ),
    "PLACE-ON": Case(
        ["k", "PLACE-ON", "p", {}],
        {"k": BOOK, "p": PLATE},
        {"k": (0.0, 0.0, T + 0.025, 0.3), "p": (0.0, 0.0, T, 0.0)},
        {"k": (0.35, 0.0, T, 0.3), "p": (0.0, 0.0, T, 0.0)},
        also_bad={
            "floating": {"k": (0.0, 0.0, T + 0.025 + 0.05, 0.3), "p": (0.0, 0.0, T, 0.0)},
            "sunk": {"k": (0.0, 0.0, T + 0.025 - 0.02, 0.3), "p": (0.0, 0.0, T, 0.0)},  # 20 mm into a 25 mm plate
        },
    ),
    "PLACE-IN": Case(
        [["a"], "PLACE-IN", "w", {}],
        {"a": APPLE, "w": BOWL},
        {"a": (0.02, 0.0, T + 0.01, 0.0), "w": (0.0, 0.0, T, 0.0)},
        {"a": (0.4, 0.0, T, 0.0), "w": (0.0, 0.0, T, 0.0)},
    ),
    "PLACE-ANYWHERE": Case(
        ["a", "PLACE-ANYWHERE", "root", {}],
        books("a", "b"),
        {"a": (0.2, -0.1, T, 1.0), "b": (-0.3, 0.2, T, 0.0)},
        {"a": (0.2, -0.1, 0.0, 1.0), "b": (-0.3, 0.2, T, 0.0)},
        also_bad={
            "floating": {"a": (0.2, -0.1, T + 0.5, 1.0), "b": (-0.3, 0.2, T, 0.0)},
            "sunk into b": {"a": (-0.3, 0.2, T + 0.02, 0.0), "b": (-0.3, 0.2, T, 0.0)},
            "at b's height beside it": {"a": (0.2, -0.1, T + 0.035, 0.0), "b": (-0.3, 0.2, T, 0.0)},
        },
    ),
    "GROUP": Case(GROUP[0], {"p": PLATE, "k": BOOK}, HOME, HOME, failed=("k",)),
    "COPY-GROUP": Case(
        ["group_h", "COPY-GROUP", "group_g", {}],
        PAIR,
        {**HOME, "p-group_h": (0.3, 0.0, T, 0.0), "k-group_h": (0.3, 0.2, T, 0.0)},
        {**HOME, "p-group_h": (0.3, 0.0, T, 0.0), "k-group_h": (0.3, 0.25, T, 0.0)},
        before=GROUP,
    ),
}


def test_every_predicate_kind_has_a_check_and_a_case() -> None:
    assert set(CHECKS) == set(Effect), "an effect without a relation check in evaluation/relations.py CHECKS"
    assert set(YAW_CHECKS) == set(YawMode), "a yaw mode without a relation check in YAW_CHECKS"
    assert set(CASES) == set(PREDICATES), "every registered predicate needs a case here"


@pytest.mark.parametrize("name", sorted(CASES))
def test_each_relation_holds_in_its_good_scene_and_fails_in_its_bad_one(name: str) -> None:
    case = CASES[name]
    good = [c for c in case.checks(case.good).checks if c.predicate == name]
    bad = [c for c in case.checks(case.bad, case.failed).checks if c.predicate == name]
    assert good and all(c.holds for c in good), [c.detail for c in good]
    assert bad and not any(c.holds for c in bad), [c.detail for c in bad]


@pytest.mark.parametrize(
    ("name", "what"), [(name, what) for name, case in sorted(CASES.items()) for what in case.also_bad]
)
def test_each_relation_fails_in_its_other_bad_scenes(name: str, what: str) -> None:
    case = CASES[name]
    bad = [c for c in case.checks(case.also_bad[what]).checks if c.predicate == name]
    assert bad and not any(c.holds for c in bad), [c.detail for c in bad]


@pytest.mark.parametrize("where", ["on the support", "on a book", "in a bowl"])
def test_place_anywhere_holds_where_the_object_rests(where: str) -> None:
    """The solver may set a PLACE-ANYWHERE object on the support, on top of another object, or in a container."""
    objects = {"a": APPLE if where == "in a bowl" else BOOK, "b": BOWL if where == "in a bowl" else BOOK}
    base = {"on the support": T, "on a book": T + 0.035, "in a bowl": T + 0.008}[where]
    poses = {"a": (0.0, 0.0, base, 0.0), "b": (0.0, 0.0, T, 0.0)}
    if where == "on the support":
        poses["b"] = (-0.3, 0.2, T, 0.0)
    program = parse_program([[oid, d] for oid, d in objects.items()] + [["a", "PLACE-ANYWHERE", "root", {}]])
    result = check_scene(scene_of(objects, poses), default_catalogue(), program=program)
    assert [c.holds for c in result.checks] == [True], [c.detail for c in result.checks]


def test_counted_items_are_judged_one_by_one() -> None:
    """[["apple", 2]] in a bowl: the solver's ids for them, one inside and one beside: half the relation holds."""
    objects = {"w": BOWL, "apple_w_0": APPLE, "apple_w_1": APPLE}
    poses = {"w": (0.0, 0.0, T, 0.0), "apple_w_0": (0.0, 0.03, T + 0.01, 0.0), "apple_w_1": (0.35, 0.0, T, 0.0)}
    program = parse_program([["w", BOWL], [[["apple", 2]], "PLACE-IN", "w", {}]])
    result = check_scene(scene_of(objects, poses), default_catalogue(), program=program)
    assert [c.holds for c in result.checks] == [True, False]
    assert result.accuracy == 0.5


def test_a_scene_folder_is_scored_from_its_scene_file_alone(tmp_path: Path) -> None:
    case = CASES["LEFT-OF"]
    scene = scene_of(case.objects, case.bad).model_copy(update={"program": case.program()})
    save_scene(scene, tmp_path / "scene.json")
    result = check_scene_folder(tmp_path)
    assert result.accuracy == 0.0 and len(result.checks) == 1
    assert result.checks[0].measured == pytest.approx(0.02 - 0.08)  # a's right edge 6 cm past b's left one
    json.dumps(result.to_dict())


def test_eval_relations_scores_every_scene_folder_below_a_folder(tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from physcensis.cli import app

    for name, poses in (("good", "good"), ("bad", "bad")):
        case = CASES["FRONT-OF"]
        scene = scene_of(case.objects, getattr(case, poses)).model_copy(update={"program": case.program()})
        (tmp_path / "runs" / name).mkdir(parents=True)
        save_scene(scene, tmp_path / "runs" / name / "scene.json")
    result = CliRunner().invoke(app, ["eval", "relations", str(tmp_path / "runs"), "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert [s["accuracy"] for s in data["scenes"]] == [0.0, 1.0]  # bad, good (sorted by folder)
    assert data["accuracy"] == 0.5
    table = CliRunner().invoke(app, ["eval", "relations", str(tmp_path / "runs")])
    assert table.exit_code == 0 and "FRONT-OF a->b" in table.output


def test_eval_relations_skips_hidden_folders_and_exports_and_reports_a_broken_scene(tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from physcensis.cli import app

    case = CASES["FRONT-OF"]
    scene = scene_of(case.objects, case.good).model_copy(update={"program": case.program()})
    runs = tmp_path / "runs"
    for name in ("good", ".good.1234.abcdefgh.partial", "good/urdf"):  # a staging folder, an export
        (runs / name).mkdir(parents=True)
        save_scene(scene, runs / name / "scene.json")
    (runs / "broken").mkdir()
    (runs / "broken" / "scene.json").write_text("{not json")
    result = CliRunner().invoke(app, ["eval", "relations", str(runs), "--json"])
    assert result.exit_code == 1, result.output
    data = json.loads(result.output[: result.output.rindex("}") + 1])
    assert [Path(s["scene"]).name for s in data["scenes"]] == ["broken", "good"]
    assert data["scenes"][0]["error"] and data["scenes"][1]["accuracy"] == 1.0
    assert data["accuracy"] == 1.0
    table = CliRunner().invoke(app, ["eval", "relations", str(runs)])
    assert table.exit_code == 1 and "error" in table.output and "Traceback" not in table.output


def test_what_a_turned_groups_members_say_of_each_other_is_judged_in_the_groups_frame() -> None:
    """A plate facing back with a book on its right, grouped and then turned a quarter to face left: the book turned
    with the group, so it is no longer right of the plate in the support's frame, and still is in the group's."""
    program = [
        ["p", PLATE],
        ["k", BOOK],
        ["p", "PLACE-ON-BASE", "root", {}],
        ["p", "FACING-BACK", "root", {}],
        ["k", "PLACE-ON-BASE", "root", {}],
        ["k", "RIGHT-OF", "p", {"distance": 0.02}],
        ["k", "FACING-BACK", "root", {}],
        ["group_g", "GROUP", ["p", "k"], {"anchor": "p"}],
        ["group_g", "PLACE-ON-BASE", "root", {"x": 0.2, "y": 0.1}],
        ["group_g", "FACING-LEFT", "root", {}],
    ]
    back, left = PREDICATES["FACING-BACK"].yaw_rule().angle, PREDICATES["FACING-LEFT"].yaw_rule().angle
    turn = left - back
    descriptions = {"p": PLATE, "k": BOOK}
    offset = (0.0, -0.25)  # the book's place beside the plate before the group turned

    def scene(side: float, turned: float, plate: tuple[float, float] = (0.2, 0.1)) -> SceneRelations:
        dx, dy = offset[0], side * offset[1]
        c, s = math.cos(turned), math.sin(turned)
        book = (plate[0] + c * dx - s * dy, plate[1] + s * dx + c * dy)
        poses = {"p": (*plate, T, back + turned), "k": (*book, T, back + turned)}
        return check_scene(scene_of(descriptions, poses), default_catalogue(), program=parse_program(program))

    assert scene(side=1.0, turned=turn).accuracy == 1.0
    # Near the table's side: turned back into the group's frame the book would be off the table, but that it stands
    # on the table is judged where it stands.
    assert scene(side=1.0, turned=turn, plate=(0.3, -0.3)).accuracy == 1.0
    assert scene(side=1.0, turned=0.0).accuracy < 1.0  # not turned as the group's rule says
    wrong = scene(side=-1.0, turned=turn)  # the book on the plate's left, in the group's frame
    assert any(c.predicate == "RIGHT-OF" and not c.holds for c in wrong.checks)
