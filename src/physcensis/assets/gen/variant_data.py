"""Built-in asset variants as data: the categories of a generator module read from its JSON file.

Each generator module keeps its geometry in Python (the `@builder` functions and their parameter
dataclasses) and lists its categories and variants in `assets/gen/data/<module>.json`, a list of
categories in the order the catalogue lists them:

    {"category": "soap bar", "kind": "soap bar", "build": "soap_bar",   # the module's @builder by name
     "density": 1050.0, "mass_limits": [0.02, 0.3],                      # the rest of `CategoryDef`'s fields,
     "synonyms": ["soap", ...], "tags": ["bathroom", ...],               # as `define` takes them
     "variants": [
       {"name": "pink_oval", "description": "a pink oval bar of soap", "size": [0.09, 0.06, 0.028],
        "colors": ["PINK", [130, 160, 80], [220, 150, 50, 0.85]],       # a palette name, or rgb(r, g, b[, a])
        "options": {"oval": true},                                       # the builder's parameters
        "synonyms": [...], "tags": [...], "density": ..., "mass": ..., "asset_id": ...},
       ...]}

A variant's options are checked against its builder's parameter dataclass as the file is read, so
an unknown key, a value of the wrong type, an unknown palette name or a misspelt field is refused
with a message naming the file, the category and the variant.
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Callable, Mapping
from importlib import resources
from importlib.abc import Traversable
from pathlib import Path
from typing import Any

from physcensis.assets import palette
from physcensis.assets.model import RGBA
from physcensis.assets.spec import Builder, CategoryDef, OptionError, Variant, VariantDataError, define

DATA_PACKAGE = "physcensis.assets.gen"
DATA_FOLDER = "data"

_REQUIRED = ("category", "kind", "build", "variants")
_CATEGORY_FIELDS = frozenset(f.name for f in dataclasses.fields(CategoryDef)) - set(_REQUIRED)
_VARIANT_REQUIRED = ("name", "description", "size")
_VARIANT_OPTIONAL = frozenset(f.name for f in dataclasses.fields(Variant)) - set(_VARIANT_REQUIRED)
_TUPLE_FIELDS = frozenset({"mass_limits", "friction", "synonyms", "tags"})
_CATEGORY_CHECKS: tuple[tuple[str, Callable[[Any], bool], str], ...] = (  # a category's field, its test, what it is
    ("category", lambda v: isinstance(v, str) and bool(v), "a non-empty string"),
    ("kind", lambda v: isinstance(v, str) and bool(v), "a non-empty string"),
    ("variants", lambda v: isinstance(v, list) and bool(v), "a non-empty list of variants"),
    ("density", lambda v: _is_number(v) and v > 0, "a positive number (kg/m^3)"),
    ("mass_limits", lambda v: _is_pair(v), "two numbers [low, high] (kg)"),
    ("friction", lambda v: _is_pair(v), "two numbers [low, high]"),
    ("support_probability", lambda v: _is_number(v) and 0 <= v <= 1, "a probability"),
    ("has_front", lambda v: isinstance(v, bool), "true or false"),
    ("com_shift", lambda v: _is_number(v) and v >= 0, "a non-negative number"),
    ("synonyms", lambda v: _is_words(v), "a list of strings"),
    ("tags", lambda v: _is_words(v), "a list of strings"),
    ("prefix", lambda v: isinstance(v, str), "a string"),
)
_CHECKS: tuple[tuple[str, Callable[[Any], bool], str], ...] = (  # a variant's field, its test, what it should be
    ("name", lambda v: isinstance(v, str) and bool(v), "a non-empty string"),
    ("description", lambda v: isinstance(v, str), "a string"),
    (
        "size",
        lambda v: isinstance(v, list) and len(v) == 3 and all(_is_number(x) and x > 0 for x in v),
        "three positive numbers (x, y, z metres)",
    ),
    ("colors", lambda v: isinstance(v, list), "a list of colours"),
    ("options", lambda v: isinstance(v, dict), "an object of the builder's parameters"),
    ("tags", lambda v: _is_words(v), "a list of strings"),
    ("synonyms", lambda v: _is_words(v), "a list of strings"),
    ("density", lambda v: _is_number(v) and v > 0, "a positive number (kg/m^3)"),
    ("mass", lambda v: _is_number(v) and v > 0, "a positive number (kg)"),
    ("asset_id", lambda v: isinstance(v, str) and bool(v), "a non-empty string"),
)


def data_file(module: str) -> Traversable:
    """The data file of a generator module (`physcensis.assets.gen.kitchen` or `kitchen`)."""
    return resources.files(DATA_PACKAGE).joinpath(DATA_FOLDER, f"{module.rpartition('.')[2]}.json")


def builtin_categories(module: str, namespace: Mapping[str, Any]) -> tuple[CategoryDef, ...]:
    """The categories of a generator module from its data file; `namespace` (the module's globals) holds
    the builders the file names."""
    return load_categories(data_file(module), namespace)


def load_categories(source: Traversable | Path, namespace: Mapping[str, Any]) -> tuple[CategoryDef, ...]:
    """The categories a data file lists, each built with `define` exactly as a Python table would."""
    try:
        records = json.loads(source.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise VariantDataError(f"{source}: cannot read variant data: {exc}") from exc
    if not isinstance(records, list):
        raise VariantDataError(f"{source}: expected a list of categories, found {type(records).__name__}")
    return tuple(_category(record, namespace, f"{source}", index) for index, record in enumerate(records))


def _category(record: object, namespace: Mapping[str, Any], file: str, index: int) -> CategoryDef:
    if not isinstance(record, dict):
        raise VariantDataError(f"{file}: category #{index} is not an object")
    where = f"{file}: category {record.get('category', f'#{index}')!r} ({record.get('kind', '?')})"
    missing = [key for key in _REQUIRED if key not in record]
    unknown = sorted(set(record) - set(_REQUIRED) - _CATEGORY_FIELDS)
    if missing or unknown:
        raise VariantDataError(f"{where}: {_fields_message(missing, unknown, _CATEGORY_FIELDS)}")
    build = namespace.get(record["build"]) if isinstance(record["build"], str) else None
    if not isinstance(build, Builder):
        raise VariantDataError(f"{where}: build {record['build']!r} is not a @builder of this module")
    for key, check, expected in _CATEGORY_CHECKS:
        if key in record and not check(record[key]):
            raise VariantDataError(f"{where}: {key} {record[key]!r} is not {expected}")
    variants = [_variant(v, f"{where}, variant {_name(v, i)!r}") for i, v in enumerate(record["variants"])]
    extra = {key: _as_tuple(value) if key in _TUPLE_FIELDS else value for key, value in record.items()}
    for key in _REQUIRED:
        del extra[key]
    try:  # define checks every variant's options against the builder's parameter class
        return define(record["category"], record["kind"], build, variants, **extra)
    except OptionError as exc:  # it names the category, the variant and the key; add the file
        raise OptionError(f"{file}: {exc}") from exc


def _name(record: object, index: int) -> object:
    return record.get("name", f"#{index}") if isinstance(record, dict) else f"#{index}"


def _variant(record: object, where: str) -> Variant:
    fields = _checked_fields(record, where)
    for key in ("tags", "synonyms"):
        if key in fields:
            fields[key] = tuple(fields[key])
    size = fields.pop("size")
    colors = fields.pop("colors", [])
    if colors:
        fields["colors"] = tuple(_colour(c, where) for c in colors)
    return Variant(size=(size[0], size[1], size[2]), **fields)


def _checked_fields(record: object, where: str) -> dict[str, Any]:
    """A copy of a variant's record once its fields are known and of the right shape (options unchecked)."""
    if not isinstance(record, dict):
        raise VariantDataError(f"{where}: a variant must be an object")
    missing = [key for key in _VARIANT_REQUIRED if key not in record]
    unknown = sorted(set(record) - set(_VARIANT_REQUIRED) - _VARIANT_OPTIONAL)
    if missing or unknown:
        raise VariantDataError(f"{where}: {_fields_message(missing, unknown, _VARIANT_OPTIONAL)}")
    for key, check, expected in _CHECKS:
        if key in record and not check(record[key]):
            raise VariantDataError(f"{where}: {key} {record[key]!r} is not {expected}")
    return dict(record)


def _colour(value: object, where: str) -> RGBA:
    """A palette name (`"WOOD"`) or `[r, g, b]` / `[r, g, b, alpha]` as `palette.rgb` takes them."""
    if isinstance(value, str):
        colour = getattr(palette, value, None) if value.isupper() else None
        if not isinstance(colour, tuple):
            raise VariantDataError(f"{where}: colour {value!r} is not a palette name")
        return colour
    if (
        isinstance(value, list)
        and len(value) in (3, 4)
        and all(isinstance(c, int) and not isinstance(c, bool) and 0 <= c <= 255 for c in value[:3])
        and (len(value) == 3 or (_is_number(value[3]) and 0 <= value[3] <= 1))
    ):
        return palette.rgb(*value)
    raise VariantDataError(f"{where}: colour {value!r} is neither a palette name nor [r, g, b(, alpha)] (0-255)")


def _is_number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _is_pair(value: object) -> bool:
    return isinstance(value, list) and len(value) == 2 and all(_is_number(x) for x in value)


def _is_words(value: object) -> bool:
    return isinstance(value, list) and all(isinstance(word, str) for word in value)


def _as_tuple(value: object) -> object:
    return tuple(value) if isinstance(value, list) else value


def _fields_message(missing: list[str], unknown: list[str], optional: frozenset[str]) -> str:
    words = []
    if missing:
        words.append(f"missing {', '.join(map(repr, missing))}")
    if unknown:
        words.append(f"unknown field {', '.join(map(repr, unknown))} (optional fields: {', '.join(sorted(optional))})")
    return "; ".join(words)
