"""Tasks in words resolved against a scene: explicit ids, the paper's relative form, and every reason one fails."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from physcensis.robot.tasks import Task, TaskError, parse_task
from physcensis.scene import PlacedObject, Scene, Support, load_scene

FRONT = np.pi / 2  # the base at the front edge (-y) facing +y: its left is -x
BACK = -np.pi / 2  # the base at the back edge facing -y: its left is +x


def _object(oid: str, category: str, x: float, y: float, **extra: object) -> PlacedObject:
    return PlacedObject(
        id=oid,
        description=str(extra.pop("description", f"a {category}")),
        asset=f"{category.replace(' ', '_')}_test",
        category=category,
        position=(x, y, 0.75),
        mass=0.3,
        friction=0.5,
        **extra,  # type: ignore[arg-type]
    )


@pytest.fixture(scope="module")
def table() -> Scene:
    """A 1.2 x 0.8 m table: three cups, two plates, a wine glass, a bowl, and a cup that could not be placed."""
    objects = [
        _object("cup_0", "cup", -0.40, 0.10, description="a red coffee cup"),
        _object("cup_1", "cup", 0.05, -0.25, description="a blue tea cup"),
        _object("cup_2", "cup", 0.35, 0.30, description="a white cup"),
        _object("plate_0", "plate", -0.20, 0.25),
        _object("plate_1", "plate", 0.30, -0.05),
        _object("wine_glass_0", "wine glass", 0.10, 0.10),
        _object("bowl_0", "bowl", -0.45, -0.30),
        _object("cup_3", "cup", 0.0, 0.0, status="failed", reason="no room left"),
    ]
    return Scene(support=Support(kind="table", size=(1.2, 0.8)), objects=objects)


def test_explicit_ids(small_scene_dir: Path) -> None:
    scene = load_scene(small_scene_dir / "scene.json")
    assert parse_task("pick cup_0 place-on plate_0", scene, FRONT) == Task(
        "cup_0", "on", "plate_0", "pick cup_0 place-on plate_0"
    )
    task = parse_task("  Pick cup_0   place-in bowl_0 ", scene, FRONT)
    assert (task.pick, task.relation, task.target) == ("cup_0", "in", "bowl_0")
    assert task.explicit == "pick cup_0 place-in bowl_0"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("pick the mug, place in the bowl", ("cup_0", "in", "bowl_0")),  # the fixture's cup_0 is a mug
        ("put the cup on the plate", ("cup_0", "on", "plate_0")),  # the id's noun, and the only one of each
        ("Pick up the coffee mug and put it into the bowl.", ("cup_0", "in", "bowl_0")),
        ("put the white mug on top of the plate", ("cup_0", "on", "plate_0")),
        ("pick up the leftmost mug and place it on the rightmost plate", ("cup_0", "on", "plate_0")),
    ],
)
def test_relative_form_on_the_small_scene(small_scene_dir: Path, text: str, expected: tuple[str, str, str]) -> None:
    task = parse_task(text, load_scene(small_scene_dir / "scene.json"), FRONT)
    assert (task.pick, task.relation, task.target) == expected
    assert task.text == " ".join(text.split())


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("pick up the leftmost cup and place it on the rightmost plate", ("cup_1", "plate_0")),
        ("pick the rightmost cup, place on the leftmost plate", ("cup_2", "plate_1")),
        ("put the frontmost cup on the backmost plate", ("cup_2", "plate_0")),
        ("put the cup on the left on the plate on the right", ("cup_1", "plate_0")),
        ("put the red cup in the bowl", ("cup_0", "bowl_0")),
        ("put the glass on the leftmost plate", ("wine_glass_0", "plate_1")),
        ("pick cup_1 place-on the rightmost plate", ("cup_1", "plate_0")),
        ("take the blue cup from the table and set it on the right plate", ("cup_1", "plate_0")),
    ],
)
def test_sides_are_the_viewers_wherever_the_robot_stands(table: Scene, text: str, expected: tuple[str, str]) -> None:
    """Left is -y, right +y, front +x as the person looking at the default render sees them (viewpoint.py)."""
    for yaw in (FRONT, BACK):
        task = parse_task(text, table, yaw, base_position=(0.0, 0.48 if yaw == BACK else -0.48))
        assert (task.pick, task.target) == expected, yaw


@pytest.mark.parametrize(
    ("text", "front", "back"),
    [
        (
            "put the cup farthest from the robot on the plate nearest to the robot",
            ("cup_2", "plate_1"),
            ("cup_1", "plate_0"),
        ),
        ("move the closest cup onto the furthest plate", ("cup_1", "plate_0"), ("cup_2", "plate_1")),
        ("Place the mug closest to the robot inside the bowl!", ("cup_1", "bowl_0"), ("cup_2", "bowl_0")),
    ],
)
def test_near_and_far_are_the_robots_own(
    table: Scene, text: str, front: tuple[str, str], back: tuple[str, str]
) -> None:
    for yaw, expected in ((FRONT, front), (BACK, back)):
        task = parse_task(text, table, yaw, base_position=(0.0, 0.48 if yaw == BACK else -0.48))
        assert (task.pick, task.target) == expected, yaw


def test_nearest_counts_from_where_the_base_stands(table: Scene) -> None:
    # Without a base position the base is at the middle of the edge behind it; an offset mount changes "nearest".
    assert parse_task("put the nearest cup on plate_1", table, FRONT).pick == "cup_1"
    assert parse_task("put the nearest cup on plate_1", table, FRONT, base_position=(-0.55, -0.48)).pick == "cup_0"


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        (
            "put the teapot on the plate_0",
            "no 'teapot' in this scene; it has: bowl (bowl_0); cup (cup_0, cup_1, cup_2)",
        ),
        ("pick cup_7 place-on plate_0", "no 'cup_7' in this scene"),
        ("put the cup on the leftmost plate", "3 cups: say which (leftmost, rightmost"),
        ("put the leftmost cup on the plate", "2 plates: say which"),
        ("pick cup_0 place-on cup_0", "the same (cup_0)"),
        ("pick the leftmost cup and drop it on itself, the leftmost cup", "the same (cup_1)"),
        ("pick cup_3 place-on plate_0", "cup_3 was not placed in this scene (no room left)"),
        ("pick up the leftmost cup", "no relation given"),
        ("pick cup_0 place-on", "names no target"),
        ("put it on the plate_0", "no object named to pick"),
        ("put the leftmost frontmost cup on plate_0", "use one of frontmost, leftmost, not several"),
        ("pick cup_0 cup_1 place-on plate_0", "several ids given"),
        ("__import__('os').system('true') on plate_0", "no '"),
        ("", "the task is empty"),
        ("x" * 600, "at most 500"),
    ],
)
def test_unresolvable_tasks_say_why(table: Scene, text: str, reason: str) -> None:
    with pytest.raises(TaskError) as caught:
        parse_task(text, table, FRONT)
    assert reason in str(caught.value)


def test_equal_extremes_are_ambiguous() -> None:
    objects = [_object("cup_0", "cup", -0.3, 0.1), _object("cup_1", "cup", -0.3, -0.2), _object("bowl_0", "bowl", 0, 0)]
    scene = Scene(support=Support(kind="table", size=(1.2, 0.8)), objects=objects)
    with pytest.raises(TaskError, match="2 cups are equally frontmost"):
        parse_task("put the frontmost cup in the bowl", scene, FRONT)
    assert parse_task("put the leftmost cup in the bowl", scene, FRONT).pick == "cup_1"  # the viewer's left: -y


def test_ids_keep_their_spelling_and_plain_word_ids() -> None:
    objects = [
        _object("Mug-A", "mug", -0.3, 0.1),
        _object("plate", "plate", 0.2, 0.0),
        _object("plate_1", "plate", -0.2, -0.1),
        _object("tray", "tray", 0.0, 0.2),
    ]
    scene = Scene(support=Support(kind="table", size=(1.2, 0.8)), objects=objects)
    assert parse_task("pick Mug-A PLACE_ON plate", scene, FRONT).explicit == "pick Mug-A place-on plate"
    assert parse_task("put the mug on tray", scene, FRONT).explicit == "pick Mug-A place-on tray"
    # With a superlative, 'plate' is the category again.
    assert parse_task("put the mug on the leftmost plate", scene, FRONT).target == "plate_1"
    with pytest.raises(
        TaskError, match="no 'mug-b' in this scene; it has: mug \\(Mug-A\\); plate \\(plate, plate_1\\)"
    ):
        parse_task("pick Mug-B place-on plate", scene, FRONT)


def test_a_base_pose_that_is_not_a_number(table: Scene) -> None:
    with pytest.raises(TaskError, match="not finite"):
        parse_task("put the leftmost cup on plate_0", table, float("nan"))


def test_a_category_placed_nowhere(table: Scene) -> None:
    only_failed = table.model_copy(update={"objects": [o for o in table.objects if o.id in ("cup_3", "plate_0")]})
    with pytest.raises(TaskError, match=r"no cup was placed in this scene: cup_3 \(no room left\)"):
        parse_task("put the cup on the plate", only_failed, FRONT)


def test_top_and_bottom_pick_by_height_in_a_stack() -> None:
    books = [
        PlacedObject(
            id=f"book_{k}",
            description="a book",
            asset="book_test",
            category="book",
            position=(0.0, 0.0, 0.75 + 0.03 * k),
            mass=0.4,
            friction=0.5,
        )
        for k in range(3)
    ]
    scene = Scene(support=Support(kind="table", size=(1.2, 0.8)), objects=[*books, _object("mug_0", "mug", 0.3, 0.2)])
    assert parse_task("put the mug on the top book", scene, FRONT).target == "book_2"
    assert parse_task("pick the topmost book and place it on the mug", scene, FRONT).pick == "book_2"
    assert parse_task("place the mug onto the lowest book", scene, FRONT).target == "book_0"
    with pytest.raises(TaskError, match="topmost.*bottommost"):
        parse_task("put the mug on the book", scene, FRONT)
