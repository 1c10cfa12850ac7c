"""Built-in variants as data: every generator module's data file loads, and a bad variant in one is refused with a
message naming the file, the category and the variant."""

from __future__ import annotations

import importlib
import json
from pathlib import Path
from typing import Any

import pytest

from physcensis.assets import palette
from physcensis.assets.builtin import CATEGORY_DEFS
from physcensis.assets.errors import AssetError
from physcensis.assets.gen import bathroom
from physcensis.assets.gen.variant_data import DATA_FOLDER, data_file, load_categories
from physcensis.assets.spec import OptionError

DATA = Path(importlib.import_module("physcensis.assets.gen").__file__ or "").parent / DATA_FOLDER
MODULES = sorted(path.stem for path in DATA.glob("*.json"))


def _soap(**variant: Any) -> dict[str, Any]:
    """A one-category table around one variant of the bathroom module's soap bar builder."""
    plain = {"name": "plain", "description": "a bar of soap", "size": [0.09, 0.06, 0.025]}
    odd = {"name": "odd", "description": "an odd bar of soap", "size": [0.09, 0.06, 0.025]}
    return {
        "category": "soap bar",
        "kind": "soap bar",
        "build": "soap_bar",
        "density": 1050.0,
        "mass_limits": [0.02, 0.3],
        "variants": [plain, odd | variant],
    }


def _load(tmp_path: Path, *categories: dict[str, Any]) -> Path:
    path = tmp_path / "soap.json"
    path.write_text(json.dumps(list(categories)))
    load_categories(path, vars(bathroom))
    return path


def test_every_generator_module_has_a_data_file() -> None:
    assert MODULES == sorted(
        ["bathroom", "bottles", "boxes", "household", "kitchen", "office", "organic", "study", "tableware", "toys"]
        + ["utensils", "workshop"]
    )


@pytest.mark.parametrize("module", MODULES)
def test_every_variant_of_a_data_file_loads(module: str) -> None:
    generator = importlib.import_module(f"physcensis.assets.gen.{module}")
    records = json.loads(data_file(module).read_text(encoding="utf-8"))
    categories = load_categories(data_file(module), vars(generator))
    assert [c.category for c in categories] == [r["category"] for r in records]
    assert [[v.name for v in c.variants] for c in categories] == [[v["name"] for v in r["variants"]] for r in records]
    assert categories == generator.CATEGORIES  # what the module defines is what its file says
    assert all(c in CATEGORY_DEFS for c in categories)


def test_colours_are_palette_names_or_rgb(tmp_path: Path) -> None:
    path = tmp_path / "soap.json"
    path.write_text(json.dumps([_soap(colors=["PINK", [130, 160, 80], [220, 150, 50, 0.85]])]))
    (category,) = load_categories(path, vars(bathroom))
    assert category.variants[1].colors == (palette.PINK, palette.rgb(130, 160, 80), palette.rgb(220, 150, 50, 0.85))


def test_an_unknown_option_is_refused_naming_the_file_category_and_variant(tmp_path: Path) -> None:
    with pytest.raises(OptionError) as err:
        _load(tmp_path, _soap(options={"ovl": True}))
    message = str(err.value)
    assert str(tmp_path / "soap.json") in message
    assert "category 'soap bar' (soap bar), variant 'odd'" in message
    assert "unknown option 'ovl' (did you mean 'oval'?)" in message


def test_an_option_of_the_wrong_type_is_refused_naming_the_file_category_and_variant(tmp_path: Path) -> None:
    with pytest.raises(OptionError) as err:
        _load(tmp_path, _soap(options={"oval": "yes"}))
    message = str(err.value)
    assert str(tmp_path / "soap.json") in message
    assert "category 'soap bar' (soap bar), variant 'odd'" in message
    assert "option 'oval' is 'yes', expected True or False" in message


@pytest.mark.parametrize(
    ("variant", "words"),
    [
        ({"colour": ["PINK"]}, "unknown field 'colour'"),
        ({"colors": ["PUCE"]}, "colour 'PUCE' is not a palette name"),
        ({"colors": [[300, 0, 0]]}, "colour [300, 0, 0] is neither"),
        ({"size": [0.09, 0.06]}, "size [0.09, 0.06] is not three positive numbers"),
        ({"synonyms": "soap"}, "synonyms 'soap' is not a list of strings"),
        ({"density": "heavy"}, "density 'heavy' is not a positive number"),
    ],
)
def test_a_malformed_variant_is_refused_naming_the_file_category_and_variant(
    tmp_path: Path, variant: dict[str, Any], words: str
) -> None:
    with pytest.raises(AssetError) as err:
        _load(tmp_path, _soap(**variant))
    message = str(err.value)
    assert str(tmp_path / "soap.json") in message
    assert "category 'soap bar' (soap bar), variant 'odd'" in message
    assert words in message


def test_a_builder_the_module_does_not_have_is_refused(tmp_path: Path) -> None:
    with pytest.raises(AssetError, match=r"soap\.json: category 'soap bar' \(soap bar\): build 'soap_brick'"):
        _load(tmp_path, _soap() | {"build": "soap_brick"})


def test_a_file_that_is_not_a_list_of_categories_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "soap.json"
    path.write_text("{}")
    with pytest.raises(AssetError, match=r"soap\.json: expected a list of categories"):
        load_categories(path, vars(bathroom))
