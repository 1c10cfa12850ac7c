"""The package's import graph against the layers written in docs/DESIGN.md: no import reaches up, no module cycle.

Every import counts: at module level, inside functions and under TYPE_CHECKING (a hidden back-edge is still one).
The layer list is read from DESIGN.md itself (the fenced `layers` block under "## Layers"), so the document and
the code cannot drift apart.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Container, Mapping
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = "physcensis"
PACKAGE_DIR = ROOT / "src" / PACKAGE
DESIGN = ROOT / "docs" / "DESIGN.md"
ROOT_MODULE = "__init__"  # how the layers block names the package's own __init__.py

Graph = Mapping[str, set[str]]  # module -> the modules it imports


# ---- the checker ----------------------------------------------------------------------------------------------------


def read_layers(markdown: str) -> list[list[str]]:
    """The ```layers block under the "## Layers" heading: one layer per line from the top down, the top-level
    packages and modules of a layer separated by spaces; `#` starts a comment."""
    section = re.search(r"^## Layers\n(.*?)(?=^## |\Z)", markdown, re.MULTILINE | re.DOTALL)
    block = re.search(r"^```layers\n(.*?)^```", section.group(1), re.MULTILINE | re.DOTALL) if section else None
    if block is None:
        raise ValueError('docs/DESIGN.md has no ```layers block under a "## Layers" heading')
    layers = [line.split("#", 1)[0].split() for line in block.group(1).splitlines()]
    return [layer for layer in layers if layer]


def module_names(package_dir: Path, package: str = PACKAGE) -> dict[str, Path]:
    """Dotted name -> file of every module of the package (a package's name stands for its __init__.py)."""
    modules = {}
    for path in sorted(package_dir.rglob("*.py")):
        parts = [package, *path.relative_to(package_dir).with_suffix("").parts]
        if parts[-1] == "__init__":
            parts.pop()
        modules[".".join(parts)] = path
    return modules


def _nearest_module(name: str, modules: Container[str]) -> str | None:
    """The module an import of `name` runs: `name` itself, or the nearest package above it that exists."""
    while name and name not in modules:
        name = name.rpartition(".")[0]
    return name or None


def _from_base(node: ast.ImportFrom, module: str, is_package: bool) -> str:
    """The absolute name of `from X import ...` (relative X is taken from the importing module)."""
    if not node.level:
        return node.module or ""
    anchor = module.split(".")
    anchor = anchor[: len(anchor) - node.level + (1 if is_package else 0)]
    return ".".join([*anchor, *([node.module] if node.module else [])])


def _imported(node: ast.Import | ast.ImportFrom, module: str, is_package: bool, modules: Container[str]) -> set[str]:
    """The modules one import statement runs (`from a import b`: the module a.b if there is one, else a)."""
    if isinstance(node, ast.Import):
        names = [alias.name for alias in node.names]
    else:
        base = _from_base(node, module, is_package)
        names = [f"{base}.{alias.name}" if f"{base}.{alias.name}" in modules else base for alias in node.names]
    return {found for name in names if (found := _nearest_module(name, modules)) is not None}


def import_graph(package_dir: Path, package: str = PACKAGE) -> dict[str, set[str]]:
    """module -> the package's modules it imports, wherever in the file the import statement is."""
    modules = module_names(package_dir, package)
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        statements = [node for node in ast.walk(tree) if isinstance(node, ast.Import | ast.ImportFrom)]
        is_package = path.name == "__init__.py"
        graph[name] = {m for node in statements for m in _imported(node, name, is_package, modules)} - {name}
    return graph


def component(module: str) -> str:
    """The top-level package or module a module belongs to: physcensis.solver.layout -> solver."""
    return module.split(".")[1] if "." in module else ROOT_MODULE


def layer_problems(graph: Graph, layers: list[list[str]], package: str = PACKAGE) -> list[str]:
    """Every import between top-level parts that does not go to a lower layer (parts on one line are siblings
    that must not import each other), every part in no layer, and every layer name that is no part."""
    rank = {name: len(layers) - k for k, layer in enumerate(layers) for name in layer}
    present = {component(m) for m in graph}
    problems = [
        f"{package}.{name} is in no layer: add it to the ```layers block under '## Layers' in docs/DESIGN.md"
        f" (one line per layer, top first)"
        for name in sorted(present - set(rank))
    ]
    problems += [
        f"docs/DESIGN.md's layers name {name!r}, which is no module or package of {package}"
        for name in sorted(set(rank) - present)
    ]
    for source in sorted(graph):
        for target in sorted(graph[source]):
            a, b = component(source), component(target)
            if a == b or a not in rank or b not in rank or rank[a] > rank[b]:
                continue
            where = "the same layer as" if rank[a] == rank[b] else "a higher layer than"
            problems.append(f"{source} imports {target}, but {b} is in {where} {a} (docs/DESIGN.md, ## Layers)")
    return problems


def strongly_connected(graph: Graph) -> list[set[str]]:
    """Tarjan's strongly connected components of the graph, in the order they close."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[set[str]] = []

    def close(root: str) -> set[str]:
        members: set[str] = set()
        while root not in members:
            members.add(stack.pop())
        return members

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        for succ in sorted(graph.get(node, ())):
            if succ not in index:
                visit(succ)
                low[node] = min(low[node], low[succ])
            elif succ in stack:
                low[node] = min(low[node], index[succ])
        if low[node] == index[node]:
            found.append(close(node))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def cycles(graph: Graph) -> list[list[str]]:
    """One import cycle (a, b, ..., a) per strongly connected component of more than one module."""
    return [_cycle_within(graph, members) for members in strongly_connected(graph) if len(members) > 1]


def _cycle_within(graph: Graph, members: set[str]) -> list[str]:
    """A closed path through a strongly connected set, from its first module back to it (breadth first: short)."""
    start = min(members)
    came_from: dict[str, str] = {}
    frontier = [start]
    while frontier:
        following = []
        for node in frontier:
            for succ in sorted(graph.get(node, ())):
                if succ == start:
                    path = [node]
                    while path[-1] != start:
                        path.append(came_from[path[-1]])
                    return [start, *reversed(path[:-1]), start]
                if succ in members and succ not in came_from:
                    came_from[succ] = node
                    following.append(succ)
        frontier = following
    raise AssertionError(f"{sorted(members)} is not strongly connected")


# ---- the package as it is -----------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def graph() -> dict[str, set[str]]:
    return import_graph(PACKAGE_DIR)


@pytest.mark.slow
def test_every_import_goes_to_a_lower_layer_of_the_design(graph: dict[str, set[str]]) -> None:
    problems = layer_problems(graph, read_layers(DESIGN.read_text(encoding="utf-8")))
    assert not problems, "\n".join(problems)


def test_no_module_imports_itself_back_through_others(graph: dict[str, set[str]]) -> None:
    found = cycles(graph)
    assert not found, "import cycles:\n" + "\n".join(" -> ".join(cycle) for cycle in found)


def test_the_graph_sees_function_level_imports(graph: dict[str, set[str]]) -> None:
    # api imports the VQA scorer only when a VLM is asked for, export each writer only when its format is written:
    # such imports are edges like any other
    assert "physcensis.agent.vqa" in graph["physcensis.api"]
    assert "physcensis.export.urdf" in graph["physcensis.export"]


# ---- the checker can fail -------------------------------------------------------------------------------------------


def _fake_package(tmp_path: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        path = tmp_path / "pkg" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return tmp_path / "pkg"


def test_imports_inside_functions_relative_and_under_type_checking_are_edges(tmp_path: Path) -> None:
    package = _fake_package(
        tmp_path,
        {
            "__init__.py": "",
            "low/__init__.py": "from .core import thing\n",
            "low/core.py": "def f():\n    from pkg.high import back\n",
            "low/other.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    import pkg.high.deep\n",
            "high/__init__.py": "from pkg import low\nfrom pkg.low import core, thing\n",
            "high/deep.py": "import os\nfrom . import missing\n",
        },
    )
    graph = import_graph(package, "pkg")
    assert graph["pkg.low"] == {"pkg.low.core"}
    assert graph["pkg.low.core"] == {"pkg.high"}
    assert graph["pkg.low.other"] == {"pkg.high.deep"}
    assert graph["pkg.high"] == {"pkg.low", "pkg.low.core"}
    assert graph["pkg.high.deep"] == {"pkg.high"}  # `from . import missing`: an attribute of the package


def test_a_back_edge_to_a_higher_layer_fails() -> None:
    graph = {"pkg.physics.engine": {"pkg.export.bodies"}, "pkg.export.bodies": {"pkg.physics.engine"}}
    problems = layer_problems(graph, [["export"], ["physics"]], "pkg")
    assert problems == [
        "pkg.physics.engine imports pkg.export.bodies, but export is in a higher layer than physics "
        "(docs/DESIGN.md, ## Layers)"
    ]


def test_siblings_in_one_layer_must_not_import_each_other() -> None:
    graph = {"pkg.program.model": {"pkg.assets.model"}, "pkg.assets.model": set()}
    problems = layer_problems(graph, [["program", "assets"]], "pkg")
    assert problems == [
        "pkg.program.model imports pkg.assets.model, but assets is in the same layer as program "
        "(docs/DESIGN.md, ## Layers)"
    ]
    assert layer_problems(graph, [["program"], ["assets"]], "pkg") == []


def test_a_package_in_no_layer_and_a_layer_naming_nothing_fail() -> None:
    graph: dict[str, set[str]] = {"pkg": set(), "pkg.newthing": set(), "pkg.solve.x": set()}
    problems = layer_problems(graph, [[ROOT_MODULE], ["solve", "gone"]], "pkg")
    assert problems == [
        "pkg.newthing is in no layer: add it to the ```layers block under '## Layers' in docs/DESIGN.md "
        "(one line per layer, top first)",
        "docs/DESIGN.md's layers name 'gone', which is no module or package of pkg",
    ]


def test_a_cycle_is_found_and_reported_as_a_path() -> None:
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set(), "e": {"a"}}
    assert cycles(graph) == [["a", "b", "c", "a"]]
    assert cycles({"a": {"b"}, "b": set()}) == []
    assert cycles({"x": {"y"}, "y": {"x"}, "p": {"q"}, "q": {"p"}}) == [["p", "q", "p"], ["x", "y", "x"]]


def test_the_layers_block_is_read_from_its_section_only() -> None:
    text = (
        "# T\n\n## Layers\n\nTop first.\n\n```layers\ncli  # the command\n\napi agent\nscene\n```\n\n"
        "## Next\n\n```layers\nnot this\n```\n"
    )
    assert read_layers(text) == [["cli"], ["api", "agent"], ["scene"]]
    with pytest.raises(ValueError, match="no ```layers block"):
        read_layers("## Components\n\n```\ncli\n```\n")
