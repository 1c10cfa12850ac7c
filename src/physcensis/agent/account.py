"""An account of the reading: for every noun phrase of the prompt (agent/parse.py), what it became in the scene.

Whoever wrote the program (the offline planner or an LLM), the account compares the sentence with the final scene:

* a phrase that names a thing is matched to the placed objects whose own name has that head noun (a category, or a
  synonym or description of the asset ending in it: "a jug" is matched by a pitcher whose synonyms include "jug",
  "some vegetables" is *not* matched by a vegetable peeler, whose name's head is "peeler");
* phrases that name the support ("the table"), the setting ("a kitchen", "four people"), a place on something ("the
  left of", "on top"), an arrangement or unit of another phrase ("two stacks of saucers", "a loaf of bread") or a
  pronoun are said as such;
* a phrase that names a thing and matches nothing is missing, with why: the catalogue has nothing by that name, or
  the scene holds none of it. The report lists it, the printed summary says it and `generate` exits 1.
"""

from __future__ import annotations

import re
from dataclasses import asdict, dataclass
from typing import Any, Literal

from physcensis.agent.graph import RESTING
from physcensis.agent.parse import PLACE_NOUNS, NounPhrase, Parse, parse
from physcensis.agent.reading import (
    AGENTS,
    COLLECTIVES,
    OCCASIONS,
    PEOPLE,
    SUPPORT_WORDS,
    UNITS,
    lexicon_for,
    without_asides,
)
from physcensis.assets.catalogue import Catalogue
from physcensis.assets.errors import AssetError
from physcensis.assets.text import lemma
from physcensis.scene import PlacedObject, Scene
from physcensis.viewpoint import stands_towards

Status = Literal[
    "placed",
    "missing",
    "unread",
    "support",
    "setting",
    "place",
    "landmark",
    "arrangement",
    "contents",
    "detail",
    "reference",
    "elsewhere",
]
# The parse's words for a holder and what it holds ("a vase of flowers", "a bowl full of apples", "a box containing
# toys"): its subject holds its target.
HOLDING_WORDS = {"of", "full of", "fill with", "contain", "hold"}

SETTING_NOUNS = {
    "kitchen", "room", "office", "bathroom", "playroom", "garage", "nursery", "study", "bedroom", "workshop", "pantry",
    "dinner", "breakfast", "lunch", "brunch", "meal", "party", "picnic", "tea", "setting", "scene", "place", "area",
    "space", "people", "person", "guest", "diner", "family", "kid", "child", "adult", "couple", "home", "house",
    "restaurant", "cafe", "store", "shop", "lab", "laboratory", "classroom", "school", "hotel", "bar", "desktop",
    "workspace", "mess", "clutter", "order", "style", "way", "time", "use", "work", "progress", "shed", "fry",
    "cooking", "baking", "water",
    "student", "owner", "user", "worker", "chef", "cook", "baby", "toddler", "teenager", "artist", "player",
}  # fmt: skip
# Things too small or loose to model one by one: "a jar of coffee beans" holds them, whatever its names say.
GRAINS = {"bean", "rice", "sugar", "flour", "salt", "pasta", "nut", "seed", "grain", "lentil", "pea", "candy"}
# Words that name no kind of thing: what they stand for is the planner's choice ("as many objects as possible").
GENERIC_NOUNS = {"object", "thing", "item", "stuff", "everything", "something", "anything", "other", "others", "all",
                 "some", "any", "both", "rest", "none", "everyday", "setup", "supply", "supplies", "essentials",
                 "accessory", "equipment", "gear", "belongings", "necessity"}  # fmt: skip
# Places beside the support that a scene is set by ("by the sink", "near the door"): named, never placed.
LANDMARK_NOUNS = {
    "sink", "door", "window", "wall", "stove", "oven", "fridge", "refrigerator", "bed", "sofa", "couch", "fireplace",
    "doorway", "hallway", "entrance", "radiator", "bathtub", "shower", "stairs", "tap", "burner", "hob", "stovetop",
    "cooktop", "faucet",
}  # fmt: skip
# Words for a property of other things ("gift boxes of different sizes").
DETAIL_NOUNS = {"size", "colour", "color", "shape", "height", "width", "length", "material", "pattern", "shade",
                "kind", "sort", "type", "style", "brand", "flavour", "flavor"}  # fmt: skip
ARRANGEMENT_NOUNS = {
    "stack", "pile", "heap", "tower", "pyramid", "row", "line", "column", "group", "set", "pair", "couple", "bunch",
    "dozen", "handful", "lot", "lots", "plenty", "collection", "assortment", "selection", "variety", "number", "kind",
    "sort", "type", "layer", "level", "cluster", "arrangement", "worth", "amount", "load", "batch", "array", "range",
    "circle", "semicircle", "formation", "scatter",
}  # fmt: skip
# The words of a support ("toys in the box" on `box:0.5x0.4` too); "stand" alone names none: a laptop stand, a cake
# stand that were not placed are missing.
SUPPORT_NOUNS = SUPPORT_WORDS - {"stand"} | {"box"}


@dataclass(frozen=True)
class PhraseAccount:
    phrase: str
    head: str
    status: Status
    asked: int | None  # how many the words ask for, when they say it (exact) or imply one
    placed: int  # objects of the scene matched to it
    became: tuple[str, ...]  # "category (asset id)" of what matched, one per asset
    why: str = ""


@dataclass(frozen=True)
class Reading:
    """The prompt's parse and the account of each of its noun phrases."""

    parse: Parse
    phrases: list[PhraseAccount]

    def to_json(self) -> dict[str, Any]:
        return {"relations": self.parse.to_json()["relations"], "phrases": as_json(self.phrases)}


def read_account(prompt: str, scene: Scene | None, catalogue: Catalogue) -> Reading:
    """Parse the prompt and account for each of its noun phrases in `scene`."""
    parsed = parse(_respelt_text(without_asides(prompt), catalogue))
    return Reading(parsed, account_of(parsed, scene, catalogue))


def _respelt_text(prompt: str, catalogue: Catalogue) -> str:
    """The prompt with the misspelt catalogue words the reading corrects corrected ("a hole puch": a hole punch), so
    the parse reads the phrase the reading read."""
    lexicon = lexicon_for(catalogue)
    words = re.split(r"(\W+)", prompt)
    for i in range(0, len(words), 2):
        before = words[i - 2].lower() if i >= 2 else ""
        if (fixed := lexicon.respelt(words[i].lower(), before)) is not None:
            words[i] = fixed
    return "".join(words)


def stood_in_for(reading: Reading) -> Reading:
    """The reading of a prompt the planner could not read, with the default scene asked for instead: what named
    nothing it knows is said to be unread, not missing (the default scene's objects are all listed as added)."""
    why = "the planner could not read it; the default scene stands in"
    phrases = [
        PhraseAccount(a.phrase, a.head, "unread", a.asked, 0, (), why) if a.status == "missing" else a
        for a in reading.phrases
    ]
    return Reading(reading.parse, phrases)


def account_of(parsed: Parse, scene: Scene | None, catalogue: Catalogue) -> list[PhraseAccount]:
    """What every noun phrase of `parsed` became in `scene` (see the module's doc)."""
    placed = scene.placed if scene is not None else []
    support_words = _support_words(scene)
    units = {r.subject for r in parsed.relations if r.word == "of"}
    accounts = [_account(p, placed, catalogue, support_words, p.index in units) for p in parsed.phrases]
    accounts = [_as_contents(parsed, accounts, k, placed, catalogue) for k in range(len(accounts))]
    return _not_in_their_holders(parsed, accounts, placed, catalogue)


def _not_in_their_holders(
    parsed: Parse, accounts: list[PhraseAccount], placed: list[PlacedObject], catalogue: Catalogue
) -> list[PhraseAccount]:
    """A placed holder's placed contents none of which rests in or on it (or on what does), said as "elsewhere":
    "a vase of flowers" whose flowers did not fit in the vase and stand on the table is not what was asked."""
    parent = {o.id: o.placement.target for o in placed if o.placement is not None and o.placement.target}
    result = list(accounts)
    for r in parsed.relations:
        holder, held = accounts[r.subject], accounts[r.target]
        if r.word not in HOLDING_WORDS or r.shared or holder.status != "placed" or held.status != "placed":
            continue  # a relation a list passed on is the parser's guess: "a bowl of grapes and napkins"
        if holder.head in ARRANGEMENT_NOUNS:
            continue  # "a pair of dice", "a stack of plates": how many and how, not a holder
        holders = {o.id for o in placed if _names(_said(parsed.phrases[r.subject]), o, catalogue)}
        contents = [o.id for o in placed if _names(_said(parsed.phrases[r.target]), o, catalogue)]
        kinds = _collective(held.head)  # "a basket of fruit": the apples and bananas placed
        contents += [o.id for o in placed if o.category in kinds and o.id not in contents]
        if not holders or holders & set(contents) or any(_rests_within(oid, holders, parent) for oid in contents):
            continue  # "a box of nails": one object named by both; or some of it is where it was asked
        why = f"asked in or on {holder.phrase}; {'they stand' if held.placed > 1 else 'it stands'} elsewhere"
        result[r.target] = PhraseAccount(held.phrase, held.head, "elsewhere", held.asked, held.placed, held.became, why)
    return result


def _rests_within(oid: str, holders: set[str], parent: dict[str, str]) -> bool:
    """Whether the object rests in or on one of `holders`, directly or on what does (an apple on apples in a bowl)."""
    seen: set[str] = set()
    while oid in parent and oid not in seen:
        seen.add(oid)
        oid = parent[oid]
        if oid in holders:
            return True
    return False


def displaced_phrases(accounts: list[PhraseAccount]) -> list[dict[str, Any]]:
    """The phrases whose things were placed but not in or on the holder the prompt put them in."""
    return [
        {"category": a.head, "placed": a.placed, "phrase": a.phrase, "why": a.why}
        for a in accounts
        if a.status == "elsewhere"
    ]


def graph_displaced(graph: dict[str, Any] | None, scene: Scene | None) -> list[dict[str, Any]]:
    """What the scene graph the planner planned from put in or on a holder and the scene has elsewhere, counted:
    "two bowls with one spoon in each" whose second spoon did not stay in its bowl and was placed on the table by
    the repair. Only things and holders the scene holds by the graph's names are counted (a substitute is the
    account's to say)."""
    if not graph or scene is None:
        return []
    objects = {g["id"]: g for g in graph.get("objects", []) if isinstance(g, dict) and "id" in g}
    placed = scene.placed
    parent = {o.id: o.placement.target for o in placed if o.placement is not None and o.placement.target}
    rows = []
    for g in objects.values():
        names = [objects[t]["name"] for t in g.get("of", []) if t in objects]
        if g.get("relation") not in RESTING or not names:
            continue
        holders = {o.id for o in placed if o.category in names}
        things = [o.id for o in placed if o.category == g.get("name")]
        if not holders or not things:
            continue
        per_holder = str(g["relation"]).endswith(("each", "own"))
        asked = min(len(things), max(1, int(g.get("count") or len(things))) * (len(holders) if per_holder else 1))
        within = sum(_rests_within(oid, holders, parent) for oid in things)
        if within < asked:
            where = f"{g['relation'].split()[0]} the {' and '.join(sorted(set(names)))}"
            why = f"{asked - within} of {asked} asked {where} {'stand' if asked - within > 1 else 'stands'} elsewhere"
            rows.append({"category": g["name"], "placed": len(things), "phrase": g["name"], "why": why})
    return rows


# The scene graph's side relations and the side each names as the viewer sees it.
GRAPH_SIDES = {"left of": "left", "right of": "right", "in front of": "front", "behind": "behind"}


def graph_sides_missed(graph: dict[str, Any] | None, scene: Scene | None) -> list[dict[str, Any]]:
    """What the scene graph set on a side of another thing ("a cup to the left of the teapot") and the scene has on
    no such side, as the viewer of the default render sees it: not one of the things stands there of any of the
    others. Only things the scene holds by the graph's names are judged (a substitute is the account's to say)."""
    if not graph or scene is None:
        return []
    objects = {g["id"]: g for g in graph.get("objects", []) if isinstance(g, dict) and "id" in g}
    placed = scene.placed
    rows = []
    for g in objects.values():
        word = GRAPH_SIDES.get(str(g.get("relation")))
        names = {objects[t]["name"] for t in g.get("of", []) if t in objects}
        if word is None or not names:
            continue
        things = [o for o in placed if o.category == g.get("name")]
        others = [o for o in placed if o.category in names]
        if not things or not others:
            continue
        if not any(stands_towards(a.position, b.position, word) for a in things for b in others if a.id != b.id):
            why = f"asked {g['relation']} the {' and '.join(sorted(names))} (as the viewer sees it), stands elsewhere"
            rows.append({"category": g["name"], "placed": len(things), "phrase": g["name"], "why": why})
    return rows


def _as_contents(
    parsed: Parse, accounts: list[PhraseAccount], k: int, placed: list[PlacedObject], catalogue: Catalogue
) -> PhraseAccount:
    """What a placed container is said to be "of" and the scene does not model ("a mug of coffee", "a jar of jam",
    "cans of soda") is its contents, not a missing thing. Countable things ("a tray of muffins") are contents only
    when the holder's own names say it holds them ("jars of spices": a spice jar); a holder whose names say what it
    is for ("a tray for muffins") comes empty, and the things are missing."""
    a = accounts[k]
    if a.status != "missing":
        return a
    holders = [r.subject for r in parsed.relations if r.target == k and r.word in ("of", "full of", "fill with")]
    placed_holders = [h for h in holders if accounts[h].status == "placed"]
    if not placed_holders:
        return a
    if parsed.phrases[k].quantity in ("plural", "exact", "vague") and a.head not in GRAINS:
        objects = [o for o in placed if _names(_said(parsed.phrases[placed_holders[0]]), o, catalogue)]
        if not any(_holds_by_name(o, a.head, catalogue) for o in objects):
            return a
    holder = accounts[placed_holders[0]].phrase
    return PhraseAccount(a.phrase, a.head, "contents", None, 0, (), f"what {holder} holds, not modelled")


def _holds_by_name(obj: PlacedObject, head: str, catalogue: Catalogue) -> bool:
    """Whether the object's names say it is full of `head` ("a spice jar", "a jar of dried herbs"), and none says
    it is only for them ("a tray for muffins")."""
    try:
        asset = catalogue.asset_for(obj.asset, obj.description)
    except AssetError:
        return False
    names = [re.findall(r"[a-z]+", n.lower()) for n in (obj.category, obj.description, *asset.synonyms)]
    said = any(head in {lemma(w) for w in words} for words in names)
    made_for = any("for" in words and head in {lemma(w) for w in words[words.index("for") :]} for words in names)
    return said and not made_for


def missing_phrases(accounts: list[PhraseAccount]) -> list[dict[str, Any]]:
    """The phrases that named a thing the scene does not hold, as `Generated.missing` rows."""
    return [
        {"category": a.head, "asked": a.asked or 1, "placed": 0, "phrase": a.phrase, "why": a.why}
        for a in accounts
        if a.status == "missing"
    ]


def as_json(accounts: list[PhraseAccount]) -> list[dict[str, Any]]:
    return [asdict(a) for a in accounts]


def _account(
    p: NounPhrase, placed: list[PlacedObject], catalogue: Catalogue, support_words: set[str], has_of: bool
) -> PhraseAccount:
    asked = p.count if p.count is not None else 1 if p.quantity == "one" else None
    if p.pronoun or p.head in GENERIC_NOUNS:
        return PhraseAccount(p.text, p.head, "reference", None, 0, (), "stands for things named elsewhere or chosen")
    if matched := _matched(p, placed, catalogue):
        became = tuple(sorted({f"{o.category} ({o.asset})" for o in matched}))
        return PhraseAccount(p.text, p.head, "placed", asked, len(matched), became)
    if p.head in PLACE_NOUNS:
        return PhraseAccount(p.text, p.head, "place", None, 0, ())
    if p.head in support_words:
        return PhraseAccount(p.text, p.head, "support", None, 0, (), "the support the scene stands on")
    if p.head in ARRANGEMENT_NOUNS or (has_of and _is_unit(p.head)):
        return PhraseAccount(p.text, p.head, "arrangement", None, 0, (), "how the things it names are arranged")
    if p.head in LANDMARK_NOUNS:
        return PhraseAccount(p.text, p.head, "landmark", None, 0, (), "a place beside the support, not placed")
    if p.head in DETAIL_NOUNS:
        return PhraseAccount(p.text, p.head, "detail", None, 0, (), "a property of other things")
    if p.head in SETTING_NOUNS | OCCASIONS | AGENTS | PEOPLE or not re.fullmatch(r"[a-z][a-z-]*", p.head):
        why = "who the scene is for" if p.head in AGENTS else "the setting"
        return PhraseAccount(p.text, p.head, "setting", None, 0, (), f"{why}, not a thing to place")
    said = _said(p) | _respelt(p, catalogue)
    known = _catalogue_names(catalogue)
    why = f"the scene holds no {p.head}" if said & known else f"the catalogue has no {p.head} (no asset is named by it)"
    return PhraseAccount(p.text, p.head, "missing", asked, 0, (), why)


def _matched(p: NounPhrase, placed: list[PlacedObject], catalogue: Catalogue) -> list[PlacedObject]:
    """The placed objects phrase p names: by its head noun, misspelt or not ("a bannana": a banana), or as one of the
    kinds of a collective word ("cutlery": forks, knives and spoons)."""
    said = _said(p)
    matched = [o for o in placed if _names(said, o, catalogue)]
    if not matched and (respelt := _respelt(p, catalogue)):
        matched = [o for o in placed if _names(respelt, o, catalogue)]
    if not matched:
        kinds = _collective(p.text.split()[-1].lower() if p.text.split() else p.head)
        matched = [o for o in placed if o.category in kinds]
    return matched


def _respelt(p: NounPhrase, catalogue: Catalogue) -> set[str]:
    """The catalogue words the misspelt heads of phrase p stand for (agent/spelling.py), read with the word before
    its last ("a hole puch")."""
    lexicon = lexicon_for(catalogue)
    before = p.text.lower().split()[-2:-1]
    return {fixed for w in _said(p) if (fixed := lexicon.respelt(w, before[0] if before else ""))}


def _said(p: NounPhrase) -> set[str]:
    """The head nouns a phrase names things by: its head's lemma and its last word's."""
    return {p.head, lemma(p.text.split()[-1].lower())} if p.text.split() else {p.head}


def _support_words(scene: Scene | None) -> set[str]:
    words = set(SUPPORT_NOUNS)
    if scene is not None:
        words.add(lemma(scene.support.kind.lower()))
    return words


def _collective(word: str) -> tuple[str, ...]:
    return COLLECTIVES.get(word, ()) or COLLECTIVES.get(f"{word}s", ())


def _is_unit(head: str) -> bool:
    return head in UNITS


def _names(heads: set[str], obj: PlacedObject, catalogue: Catalogue) -> bool:
    """Whether the object's own names have one of `heads` as their head noun (the last word of its category, of a
    synonym of its asset, of its description, or its description's noun before "of": "a loaf of white bread")."""
    return bool(heads & _heads(obj.asset, obj.description, obj.category, catalogue))


_HEADS: dict[tuple[str, str, str], frozenset[str]] = {}


def _heads(asset_id: str, description: str, category: str, catalogue: Catalogue) -> frozenset[str]:
    key = (asset_id, description, category)
    if key not in _HEADS:
        names = [category, description, *_single_word_names(category, catalogue)]
        try:
            asset = catalogue.asset_for(asset_id, description)
            names += [*asset.synonyms, asset.kind, asset.description]
        except AssetError:  # an asset the catalogue no longer has: its own words only
            pass
        heads = set()
        for name in names:
            words = _before_purpose(re.findall(r"[a-z]+", name.lower()))
            if not words:
                continue
            heads.add(lemma(words[-1]))
            if "of" in words[1:]:  # "a loaf of bread", "a bottle of olive oil": the unit and its contents
                heads.add(lemma(words[words.index("of") - 1]))
        _HEADS[key] = frozenset(heads)
    return _HEADS[key]


def _single_word_names(category: str, catalogue: Catalogue) -> list[str]:
    """The one-word names the reading reads as this category, any variant's ("tumbler" is a glass): what the words
    asked by such a name, any thing of the category gives."""
    lexicon = lexicon_for(catalogue)
    return [key[0] for key, named in lexicon.phrases.items() if named == category and len(key) == 1]


_KNOWN: dict[int, frozenset[str]] = {}


def _catalogue_names(catalogue: Catalogue) -> frozenset[str]:
    """The head nouns the catalogue names anything by."""
    key = id(catalogue)
    if key not in _KNOWN:
        heads = set()
        for asset in catalogue.all():
            for name in (asset.category, asset.kind, *asset.synonyms):
                words = _before_purpose(re.findall(r"[a-z]+", name.lower()))
                if words:
                    heads.add(lemma(words[-1]))
        _KNOWN[key] = frozenset(heads)
    return _KNOWN[key]


def _before_purpose(words: list[str]) -> list[str]:
    """A name's words up to what it is for or comes with: "a tray for muffins" is a tray, "a mug with a lid" a
    mug; neither names a muffin or a lid."""
    for k, word in enumerate(words[1:], start=1):
        if word in ("for", "with"):
            return words[:k]
    return words
