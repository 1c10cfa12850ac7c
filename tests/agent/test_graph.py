"""The scene graph between a prompt and the planner: the offline reading's graph plans the same scene as the reading
itself, a model's graph is checked and sent back with what is wrong, and `--llm-writes graph` plans, varies and
reports from the model's graph (a scripted server plays the model)."""

from __future__ import annotations

import json
from typing import Any

import numpy as np
import pytest

from physcensis.agent.base import AgentContext
from physcensis.agent.graph import (
    PLACES,
    GraphError,
    SceneGraph,
    graph_of,
    graph_schema,
    parse_graph,
    request_of,
)
from physcensis.agent.graph_planner import GRAPH_ATTEMPTS
from physcensis.agent.planner import OfflinePlanner
from physcensis.agent.reading import SceneRequest
from physcensis.api import generate
from physcensis.bench.prompt_suite import SUITES, load_suite
from physcensis.physics.mujoco_engine import MujocoEngine
from physcensis.physics.render import image_centres
from physcensis.scene import Scene, Support

from .fake_server import FakeOpenAI, use_loopback_only

TABLE = Support(kind="table", size=(1.2, 0.8))


def _object(oid: str, name: str, count: int = 1, relation: str = "none", of: list[str] | None = None, **more: Any):
    base = {"id": oid, "name": name, "count": count, "words": [], "arrangement": "none", "groups": 0, "where": ""}
    return base | {"relation": relation, "of": of or []} | more


def _graph(*objects: dict[str, Any], diners: int = 0, style: str = "tidy") -> str:
    return json.dumps({"objects": list(objects), "diners": diners, "style": style})


BOWL_OF_APPLES = _graph(
    _object("bowl", "bowl", words=["blue"]),
    _object("apple", "apple", 3, "in", ["bowl"]),
    _object("mug", "mug", 2, "right of", ["bowl"]),
)


class _FromGraph(OfflinePlanner):
    """The offline planner planning from the graph of its own reading."""

    def read(self, prompt: str) -> SceneRequest:
        graph = SceneGraph.model_validate_json(graph_of(super().read(prompt)).model_dump_json())
        return request_of(graph, self.lexicon, prompt)


@pytest.mark.parametrize(
    "prompt",
    [
        "a bowl with three apples in it and two mugs to its right",  # contents, a side
        "two stacks of plates next to a basket of bread",  # stacks in groups, a holder's contents
        "a vase between a lamp and a stack of three books",  # between two named things
        "four saucers with a teacup on each saucer",  # one per holder
        "a dining table set for four with a vase in the center",  # diners, the centre
        "a potted plant in the back left corner and a laptop",  # a place on the support
        "a mug, a glass and a teacup, each on its own coaster",  # each on a holder of its own
        "a fruit bowl with a candle on either side of it",
        "a rice bowl with a pair of chopsticks resting across its rim",  # on a container: across its rim
        "a cup balanced precariously on the edge of a book",  # the scene's style
        "a teapot on a tray, four cups on saucers around it",  # as many saucers as cups
    ],
)
def test_the_readings_graph_plans_the_readings_scene(prompt: str) -> None:
    context = AgentContext(prompt, TABLE, ())
    assert _FromGraph(variety="none").plan(context) == OfflinePlanner(variety="none").plan(context)


def test_every_suite_prompts_graph_checks_and_names_what_the_reading_found() -> None:
    planner = OfflinePlanner()
    for case in (case for path in SUITES.values() for case in load_suite(path)):
        request = planner.read(case["prompt"])
        graph = parse_graph(graph_of(request).model_dump_json())  # the model's checks pass on the reading's graph
        assert len(graph.objects) == len(request.mentions), case["id"]
        for o, m in zip(graph.objects, request.mentions, strict=True):
            assert o.name == m.phrase and (o.count == 0) == (m.plural and not m.explicit_count), case["id"]
            assert o.where in PLACES, case["id"]  # what the schema lets a model write


@pytest.mark.parametrize(
    ("reply", "named"),
    [
        ("I cannot do that", "no JSON object"),
        ('{"objects": [', "not valid JSON"),
        (_graph(_object("a", "apple", 1, "in", ["bowl"])), "'bowl', which is no object's id"),
        (_graph(_object("a", "apple", 1, "in", [])), "object 'a': relation 'in' takes 1 id(s)"),
        (_graph(_object("a", "apple", 1, "on", ["a"])), "object 'a': it cannot be on itself"),
        (_graph(_object("a", "apple"), _object("a", "pear")), "two objects share this id"),
        (_graph(_object("a", "apple", 1, "on top of", ["b"]), _object("b", "book")), "relation 'on top of'"),
        (_graph(_object("a", "apple", where="upstairs")), "where 'upstairs'"),
        (_graph(_object("a", "mug", 1, "on", ["b"]), _object("b", "book", 1, "on", ["a"])), "in a circle"),
        (_graph(_object("a", "apple", count=-1)), "objects.0.count"),
        (_graph(_object("a", "apple"), style="chaotic"), "style 'chaotic'"),
        (json.dumps({"objects": [], "diners": 0, "style": "tidy", "table": 1}), "table"),
    ],
)
def test_a_graph_that_cannot_be_used_is_named_where_it_is_wrong(reply: str, named: str) -> None:
    with pytest.raises(GraphError, match=None) as caught:
        parse_graph(reply)
    assert named in str(caught.value)


def test_between_one_id_of_several_and_a_code_fence_are_taken() -> None:
    reply = "Here it is:\n```json\n" + _graph(_object("vase", "vase", 1, "between", ["c"]), _object("c", "candle", 2))
    graph = parse_graph(reply + "\n```")
    request = request_of(graph, OfflinePlanner().lexicon)
    vase, candles = request.mentions
    assert (vase.beside, vase.side, candles.count) == (1, "between", 2)


def test_the_schema_sent_is_strict() -> None:
    def strict(node: dict[str, Any]) -> None:
        if node.get("type") == "object":
            assert set(node["required"]) == set(node["properties"]) and node["additionalProperties"] is False
            for child in node["properties"].values():
                strict(child)
        if node.get("type") == "array":
            strict(node["items"])

    schema = graph_schema()
    strict(schema)
    assert "$ref" not in json.dumps(schema)
    SceneGraph.model_validate(json.loads(BOWL_OF_APPLES))  # an example of the schema is a graph


def _centres(scene: Scene) -> dict[str, tuple[float, float]]:
    return image_centres(MujocoEngine().build(scene), scene, view="iso")  # type: ignore[arg-type]


@pytest.mark.physics
def test_the_models_graph_becomes_the_scene_and_the_report_says_so(monkeypatch: pytest.MonkeyPatch) -> None:
    use_loopback_only(monkeypatch, "test-key")
    bad = _graph(_object("x", "apple", 1, "in", ["nothing"]))
    with FakeOpenAI(replies=[bad, BOWL_OF_APPLES]) as server:
        generated = generate(
            "a blue bowl of apples and two mugs", llm="m", base_url=server.base_url, llm_writes="graph"
        )
        sent = server.requests
    assert len(sent) == 2  # the bad graph went back once, with what was wrong in it
    assert "'nothing', which is no object's id" in sent[1]["messages"][-1]["content"]
    assert sent[0]["response_format"]["json_schema"]["schema"] == graph_schema()
    assert generated.solution is not None and generated.solution.ok
    scene = generated.solution.scene
    by_category: dict[str, list[Any]] = {}
    for o in scene.placed:
        by_category.setdefault(o.category, []).append(o)
    assert {c: len(v) for c, v in by_category.items()} == {"bowl": 1, "apple": 3, "mug": 2}
    (bowl,) = by_category["bowl"]
    size = OfflinePlanner().catalogue.get(bowl.asset).size
    centre, radius = np.array(bowl.position[:2]), max(size[:2]) / 2
    for apple in by_category["apple"]:  # in the bowl: within its rim, above its base
        assert np.linalg.norm(np.array(apple.position[:2]) - centre) < radius
        assert bowl.position[2] < apple.position[2] < bowl.position[2] + size[2]
    centres = _centres(scene)
    assert all(centres[m.id][0] > centres[bowl.id][0] for m in by_category["mug"])  # right of it, as seen
    report = generated.report()["generate"]
    assert report["scene_graph"]["source"] == "model"
    assert [o["name"] for o in report["scene_graph"]["graph"]["objects"]] == ["bowl", "apple", "mug"]
    assert report["requested"] == {"bowl": 1, "apple": 3, "mug": 2} and report["missing"] == []
    rows = [row for row in generated.transcript if "graph_request" in row]
    assert len(rows) == 2 and all(row["seconds"] is not None for row in rows)
    assert generated.result.transcript[0]["note"].startswith("scene graph from the model: bowl, apple ×3 in bowl")


@pytest.mark.physics
@pytest.mark.long
def test_seeds_vary_the_scene_of_one_graph(monkeypatch: pytest.MonkeyPatch) -> None:
    use_loopback_only(monkeypatch, "test-key")
    scenes = []
    with FakeOpenAI(replies=[BOWL_OF_APPLES, BOWL_OF_APPLES]) as server:
        for seed in (0, 1):
            generated = generate(
                "a bowl of apples and mugs", llm="m", base_url=server.base_url, llm_writes="graph", seed=seed
            )
            assert generated.solution is not None
            scenes.append({o.id: np.array(o.position) for o in generated.solution.scene.placed})
        assert len(server.requests) == 2  # one graph per run
    moved = [np.linalg.norm(scenes[0][k][:2] - scenes[1][k][:2]) for k in scenes[0] if k in scenes[1]]
    assert max(moved) > 0.05


def test_no_usable_graph_leaves_the_offline_readings_graph_said_as_such(monkeypatch: pytest.MonkeyPatch) -> None:
    from physcensis.agent.factory import make_agent
    from physcensis.settings import RunSettings

    use_loopback_only(monkeypatch, "test-key")
    with FakeOpenAI(replies=["no idea"] * GRAPH_ATTEMPTS) as server:
        settings = RunSettings.from_options(llm="m", base_url=server.base_url, llm_writes="graph")
        agent = make_agent(settings, OfflinePlanner().catalogue)
        reading = agent.graph_reading("three mugs on a tray")  # type: ignore[attr-defined]
        assert len(server.requests) == GRAPH_ATTEMPTS
    assert reading.source == "offline reading" and "no usable scene graph in 3 replies" in reading.why
    assert [o.name for o in reading.graph.objects] == ["mug", "tray"]
    assert any("the offline reading's graph stands in" in note for note in agent.transcript_notes)


def test_a_local_server_is_shown_the_offline_readings_graph_as_a_draft(monkeypatch: pytest.MonkeyPatch) -> None:
    from physcensis.agent.factory import make_agent
    from physcensis.settings import RunSettings

    use_loopback_only(monkeypatch, "test-key")
    for hint, shown in (("auto", True), ("off", False)):
        with FakeOpenAI(replies=[BOWL_OF_APPLES]) as server:
            settings = RunSettings.from_options(llm="m", base_url=server.base_url, llm_writes="graph", hint=hint)
            make_agent(settings, OfflinePlanner().catalogue).graph_reading("a tray with two cups")  # type: ignore[attr-defined]
            asked = server.requests[0]["messages"][-1]["content"]
        assert ("draft" in asked and '"name": "tray"' in asked) == shown


@pytest.mark.parametrize(
    ("name", "category", "known"),
    [
        ("red coffee mugs", "mug", True),  # the head noun, in the plural, with its modifiers
        ("bowl of fruit", "bowl", True),  # a container of something is the container
        ("bar of soap", "soap bar", True),  # a measure of something is that thing
        ("box of crayons", "crayons", True),  # a catalogue name with "of" in it
        ("mug holder", "holder", False),  # a modifier that is a catalogue noun is not the head
    ],
)
def test_an_objects_name_is_read_by_its_head_noun(name: str, category: str, known: bool) -> None:
    graph = parse_graph(_graph(_object("a", name)))
    (m,) = request_of(graph, OfflinePlanner().lexicon).mentions
    assert (m.category, m.known) == (category, known)


def test_the_setting_a_model_lists_as_an_object_is_the_support() -> None:
    graph = parse_graph(
        _graph(
            _object("desk", "desk", words=["messy"]), _object("pen", "pencil", 3, "on", ["desk"]), _object("m", "mug")
        )
    )
    request = request_of(graph, OfflinePlanner().lexicon)
    assert [(m.category, m.on) for m in request.mentions] == [("pencil", None), ("mug", None)]


def test_a_server_without_structured_output_gets_the_graph_asked_in_plain_text(monkeypatch: pytest.MonkeyPatch) -> None:
    from physcensis.agent.factory import make_agent
    from physcensis.settings import RunSettings

    use_loopback_only(monkeypatch, "test-key")
    with FakeOpenAI(replies=[BOWL_OF_APPLES], refuse_response_format=True) as server:
        settings = RunSettings.from_options(llm="m", base_url=server.base_url, llm_writes="graph")
        agent = make_agent(settings, OfflinePlanner().catalogue)
        reading = agent.graph_reading("a bowl of apples and two mugs")  # type: ignore[attr-defined]
        answered = [r for r in server.requests if "response_format" not in r]
    assert reading.source == "model" and len(answered) == 1
    assert any("structured output refused" in note for note in agent.transcript_notes)
