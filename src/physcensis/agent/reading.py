"""Read a scene prompt compositionally: noun phrases, the relations between them and their arrangement.

A small grammar over lemmatised tokens (no phrase templates):

* a noun phrase is `quantity? (arrangement "of")? quantity? adjective* noun`, so "two stacks of plates", "a stack
  of 5 books", "rows of three cans", "a pair of mugs", "several jars" and "monitors" are all read by the same rule;
  words after the noun ("stacked", "in two rows", "side by side", ", one of three and one of four") refine it;
* nouns are the catalogue's own names (categories, kinds, synonyms, longest match first), so a category added to
  the catalogue is read with no change here; a noun the catalogue does not know, introduced by an article or a
  number ("a lamp", "three gizmos"), is kept for retrieval's generated fallback;
* the words between two noun phrases relate them: a holder and its contents ("full of", "holding", "with", "of"),
  a position ("in", "on", "beside", "in front of", "left of", "around"), or a list ("and", ","). Whether a noun
  holds things inside (a cavity) or on top (a flat carrier) comes from its asset's annotations (`Lexicon.role`).
"""

from __future__ import annotations

import re
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field, replace

from physcensis.agent import spelling
from physcensis.agent.numerals import NUMERALS
from physcensis.agent.parse import WordClasses, parse
from physcensis.assets.catalogue import Catalogue
from physcensis.assets.text import MODIFIERS, SPELLINGS, STOPWORDS, lemma, plural

MOST = 40  # the most objects one noun phrase asks for
SMALL_M = 0.16  # a thing no longer than this rests on any carrier ("a mug on a coaster")
LOOSE = {"few": 3, "several": 4, "couple": 2, "pair": 2, "both": 2, "single": 1}  # counts said loosely
VAGUE = {
    "some",
    "many",
    "lots",
    "lot",
    "plenty",
    "various",
    "assorted",
    "numerous",
    "more",
    "multiple",
    "bunch",
    "handful",
    "tons",
    "loads",
}
MANY = {"many", "lots", "lot", "plenty", "numerous", "bunch", "handful", "loads", "tons"}  # more than a few: >= 5
ARRANGE_NOUNS = {
    "stack": "stack",
    "tower": "stack",
    "pyramid": "stack",
    "pile": "pile",
    "heap": "pile",
    "row": "row",
    "line": "row",
    "column": "column",
}
# Said after a plural: the things fill the room they are given ("toy cars everywhere", "cans packed tightly").
FILL_WORDS = ("everywhere", "all over", "packed tightly", "tightly packed", "packed in", "crammed", "covering")
# "UNIT of NOUN" names one NOUN ("a tube of toothpaste", "two bars of soap"); a container unit holds its NOUNs
# ("a bowl of apples") unless the catalogue names "NOUN UNIT" as one thing ("a jar of honey": a honey jar).
NAMING_UNITS = {
    "tube",
    "bar",
    "roll",
    "sheet",
    "pack",
    "packet",
    "piece",
    "stick",
    "slice",
    "loaf",
    "ream",
    "block",
    "pad",
}
UNITS = set(NAMING_UNITS)
UNITS |= {"bottle", "jar", "can", "tin", "box", "carton", "bag", "pot", "tub", "cup", "glass", "mug", "bowl", "basket"}
UNITS |= {"crate", "bucket", "tray", "plate", "deck"}
TRAILING_UNITS = {"tube", "roll", "bar", "sheet", "pack", "packet", "stick", "piece", "slice", "ream"}  # "paper roll"
IRREGULAR_PLURALS = {"dice"}
# Things named in the plural that are one object: "a pair of pliers" is one pair.
PAIRED = {"pliers", "scissors", "tongs", "tweezers", "sunglasses", "safety glasses", "nail clippers", "headphones"}
PAIRED |= {
    "earbuds",
    "binoculars",
    "shoes",
    "slippers",
    "work gloves",
    "clothes",
}  # plural as written (the catalogue names the category by its plural)
# A participle or adjective that makes a bare mass noun several pieces ("crumpled paper", "loose change").
SCATTERED = {"loose", "scattered", "crumpled", "spare", "stray", "assorted", "random", "strewn", "spilled", "spilt"}
ARTICLES = {"a", "an", "another", "one"}
DETERMINERS = {"the", "its", "their", "my", "your", "his", "her", "this", "that", "these", "those", "each", "every"}
NUMBERS = {**NUMERALS, **LOOSE, "a": 1, "an": 1}  # every word read as a count
UNDER_WORDS = ("under", "underneath", "beneath", "below")  # "a saucer under each cup": the cup rests on the saucer
# Words that name the support things stand on ("the windowsill"): never objects to place, nor missing ones.
SUPPORT_WORDS = frozenset(
    """table desk counter countertop worktop workbench bench stand nightstand shelf bookshelf bookcase cabinet
    cupboard dresser sideboard windowsill sill ledge mantel mantelpiece vanity floor ground surface tabletop
    island""".split()
)
# Words that name scenes, supports, places or contents, never objects to place.
_SCENE_WORDS = (
    " ".join(SUPPORT_WORDS)
    + """
room kitchen bathroom bedroom office pantry garage playroom
nursery playmat rug carpet area corner space setup scene arrangement display collection assortment variety
selection mix group set spread tabletop island people person guest diner kid kids child student school middle
center centre side edge rim top bottom front back left right end row line column pyramid stack pile heap tower
circle semicircle cluster formation
size height colour color shape length width kind type shade pattern triangle grid
dinner breakfast lunch picnic meal party juice coffee tea jam oil spice soda water wine milk cereal soup
everything anything something thing item object stuff dish cutlery utensil silverware toy fruit way order style
bunch lot plenty number couple pair dozen each other one another time neat mess clutter supply essential accessory
belonging decoration high tall deep wide apiece second third bit little touch distance gap
"""
)
# Times and occasions a scene is set at ("after a long day", "the night before an exam"): never things to place.
OCCASIONS = frozenset(
    """day night morning afternoon evening weekend week hour minute moment today tonight yesterday tomorrow session
monday tuesday wednesday thursday friday saturday sunday exam test experiment demo benchmark simulation project
""".split()
)
PEOPLE = {"guest", "person", "people", "diner", "kid", "child", "children", "student", "player", "friend", "adult",
          "pupil", "visitor", "customer", "colleague", "participant", "attendee", "client", "sibling", "boy", "girl",
          "man", "men", "woman", "women", "teenager", "toddler", "worker", "employee", "coworker", "roommate",
          "teammate", "cousin", "grandchild", "grandparent", "parent"}  # fmt: skip
NOT_OBJECTS = {(w,) for w in (*_SCENE_WORDS.split(), *OCCASIONS, *PEOPLE)} | {("orange", "juice"), ("apple", "juice")}
AGENTS = {"robot", "robots"}  # who a scene is for ("for a robot to tidy up"), unless a toy one is asked for
# words the reading knows as no thing: never read as a misspelt catalogue word
_NEVER_RESPELT = {w for (w,) in (o for o in NOT_OBJECTS if len(o) == 1)} | OCCASIONS | PEOPLE | AGENTS | STOPWORDS
# Scene words that name one thing when a single one is counted ("a bar of soap on a dish"; "dishes" is a collective).
ONE_OF_A_KIND = {"dish": ("small", "dish")}
# Collective words that stand for several categories.
COLLECTIVES = {
    "cutlery": ("fork", "knife", "spoon"),
    "silverware": ("fork", "knife", "spoon"),
    "utensils": ("fork", "knife", "spoon"),
    "dishes": ("plate",),
    "fruit": ("apple", "orange", "banana"),
    "fruits": ("apple", "orange", "banana"),
    "toys": ("toy block", "ball", "toy truck"),
}
# The relation words between two noun phrases (articles removed), longest first where they share words.
HOLDS = (
    "full of",
    "filled with",
    "packed with",
    "stuffed with",
    "loaded with",
    "heaped with",
    "piled with",
    "stacked with",
    "crammed with",
    "containing",
    "holding",
    "carrying",
    "that hold",
    "which hold",
    "that contain",
    "hold",
    "contain",
    "carry",
    "that holds",
    "which holds",
    "that contains",
    "holds",
    "contains",
    "carries",
    "with",
    "of",
)
POSITIONS = (
    ("on each side of", "sides"),
    ("on either side of", "sides"),
    ("on both sides of", "sides"),
    ("at each side of", "sides"),
    ("either side of", "sides"),
    ("each side of", "sides"),
    ("at each end of", "ends"),
    ("at either end of", "ends"),
    ("at both ends of", "ends"),
    ("each end of", "ends"),
    ("either end of", "ends"),
    ("in front of", "front"),
    ("front of", "front"),
    ("behind", "behind"),
    ("in back of", "behind"),
    ("back of", "behind"),
    ("to left of", "left"),
    ("on left of", "left"),
    ("left of", "left"),
    ("left side of", "left"),  # "on the left side of the laptop": a side of it, not a laptop held "of" a mug
    ("left hand side of", "left"),
    ("to right of", "right"),
    ("on right of", "right"),
    ("right of", "right"),
    ("right side of", "right"),
    ("right hand side of", "right"),
    ("front side of", "front"),
    ("back side of", "behind"),
    ("far side of", "behind"),
    ("on other side of", "other"),  # the side opposite the one said before (`_other_sides`)
    ("other side of", "other"),
    ("next to", "beside"),
    ("beside", "beside"),
    ("besides", "beside"),
    ("alongside", "beside"),
    ("near", "beside"),
    ("close to", "beside"),
    ("by", "beside"),
    ("around", "around"),
    ("surrounding", "around"),
    ("flank", "sides"),  # "two candles flank a vase"
    ("flanking", "sides"),
    *((f"{near} to {who} than", "front") for near in ("nearer", "closer") for who in ("me", "you", "us", "viewer")),
    *((f"{far} from {who} than", "behind") for far in ("further", "farther") for who in ("me", "you", "us", "viewer")),
    ("in between", "between"),
    ("between", "between"),
    ("on top of", "on"),
    ("top of", "on"),
    ("edge of", "on"),
    ("on", "on"),
    ("onto", "on"),
    ("atop", "on"),
    ("upon", "on"),
    ("across", "on"),
    ("over", "on"),
    ("inside of", "in"),
    ("inside", "in"),
    ("into", "in"),
    ("within", "in"),
    ("in", "in"),
)
# "A surrounded by B": B stands around A (the other way round from POSITIONS, which place the phrase before the words).
PASSIVE_POSITIONS = (
    ("surrounded by", "around"),
    ("encircled by", "around"),
    ("ringed by", "around"),
    ("circled by", "around"),
    ("flanked by", "sides"),
)
LIST_WORDS = {",", "and", "or", "plus", "as well as", ", and", ", plus"}
CENTRE_WORDS = ("in the middle", "in the center", "in the centre", "centre of", "center of", "centered", "centred")
# A place on the support said after a noun phrase ("in the corner of the room", "at the back of the shelf", "on the
# left", "at one end of the table", "along the edge"): the words of each side, as the viewer says them.
REGION_SIDES = {"back": "back", "rear": "back", "far": "back", "top": "back", "front": "front", "near": "front",
                "bottom": "front", "left": "left", "right": "right"}  # fmt: skip
_REGION_SIDE_WORDS = "far|back|rear|front|near|top|bottom|left|right"
_CORNER = re.compile(
    rf"\b(?:in|into|at|on|by|to) (?:the|a|one|its|their) ((?:(?:{_REGION_SIDE_WORDS})(?:[ -]hand)?[ -])*)corners?\b"
)
_BAND = re.compile(r"\b(?:on|at|along|against|to|towards|toward|near|by|in) (?:the|its|their) (?:far |very )?"
                   r"(far|back|rear|front|near|left|right)(?:[ -]hand)?"
                   r"(?: (?:side|half|edge|end|part|wall|row))?\b")  # fmt: skip
SIDE_OF_REGION = {"left": "left", "right": "right", "front": "front", "back": "behind"}
_END = re.compile(r"\b(?:at|on|by) (?:one|the|an?) (?:(?:far|other) )?end\b")
# "at the other end", "in the opposite corner": across from the place said before
_OTHER_PLACE = re.compile(r"\b(?:at|on|by|in|into|to) the (?:other|opposite) (end|corner)\b")
_EDGE = re.compile(r"\b(?:along|at|near|by|on|against|to) (?:the|its|their) (edge|wall)\b")
_BOTH_ENDS = re.compile(r"\b(?:at|on|by) (?:each|either|both) (?:end|side)s? of (?:the|its|their) (\w+)")
_BY_THE_VIEWER = re.compile(
    r"\b(closest|nearest|close|near|next|furthest|farthest|far|away) (?:to |from )?"
    r"(?:me|you|us|the viewer|the camera)\b"
)
RIM_WORDS = ("across its rim", "across the rim", "on its rim")
PRONOUNS = {"it", "them", "one", "its"}
ROW_WORDS = ("in a row", "in a line", "lined up", "side by side", "in rows", "in a neat row", "next to each other")
ROW_WORDS_2: tuple[str, ...] = (
    "beside each other",
    "evenly spaced",
    "spaced evenly",
    "in one row",
    "aligned",
    "in line",
    "in a neat line",
)
ROW_WORDS_2 += (
    "in a straight line",
    "in a straight row",
    "in a long row",
    "in a long line",
    "lined along",
    "in a single row",
)
STACK_WORDS = (
    *("stacked", "in a stack", "in stacks", "on top of each other", "on top of one another", "nested"),
    *("one on top of the other", "one on top of another", "one atop the other", "one atop another"),
    *("one inside the other", "one inside another", "one in the other", "inside each other", "inside one another"),
)
PILE_WORDS = ("piled", "in a pile", "in a heap", "heaped", "in piles")
SCATTER_WORDS = ("scattered", "strewn", "spread out", "randomly", "here and there")


@dataclass
class Mention:
    category: str
    count: int
    phrase: str  # the words that named it, singular ("wine glass")
    adjectives: tuple[str, ...]
    start: int  # token span, quantity and adjectives included
    end: int
    plural: bool
    explicit_count: bool
    contents: list[int] = field(default_factory=list)  # mentions inside it
    on: int | None = None  # the mention it rests on
    beside: int | None = None  # the mention it stands next to; `side` says where
    stacked: bool = False  # a stack or a pile
    centre: bool = False
    around: int | None = None  # arranged around this mention
    per: int | None = None  # one of these per instance of that mention ("sandwiches on plates")
    side: str = "beside"  # beside | left | right | front | behind | between (two of `beside`'s objects)
    second: int | None = None  # "between A and B": B (A is `beside`), B standing to the viewer's right of A
    known: bool = True  # a catalogue noun; False: kept for the generated fallback
    arrangement: str = ""  # "" | stack | pile | row | column | scatter
    groups: int = 0  # how many stacks or rows were asked for (0: not said)
    sizes: tuple[int, ...] = ()  # objects per stack or row, when said
    spaced: bool = False  # "evenly spaced"
    held_by: int | None = None  # the holder whose list ("full of", "with") named it
    alias: int | None = None  # "the laptop" naming a laptop mentioned before: that mention
    least: int = 0  # "lots of", "everywhere", "crumpled paper": at least this many when no number is said
    loose: str | None = None  # "few" or "several": the count was said loosely (a seed may draw another)
    collective: bool = False  # one of the categories a collective word ("cutlery") stands for
    # where on the support, as the viewer says it: words of corner | end | edge | back | front | left | right
    region: tuple[str, ...] = ()
    on_side: str = ""  # on its carrier, on this side of it as the viewer says it ("a tray with cups on the left")


@dataclass
class SceneRequest:
    mentions: list[Mention]
    diners: int = 0
    messy: bool = False
    rows: bool = False
    dense: bool = False  # as many as possible / very cluttered
    fragile: bool = False  # precariously, balanced on the edge
    stable: bool = False
    tokens: list[str] = field(default_factory=list)


_SIZE = r"\d+(?:[.,]\d+)?"
_MEASURE = re.compile(
    rf"\b{_SIZE}(?:\s*[x\u00d7]\s*{_SIZE}){{1,2}}\s*-?\s*(?:cm|mm|m|inch|inches|in|ft|\")?(?![a-z])"  # 40 x 30 cm
    rf"|\b{_SIZE}\s*-?\s*(?:cm|mm|m|inch|inches|ft|foot|feet|ml|l|litre|liter|litres|liters|oz|kg|lb|lbs)\b"
    r"|\b[ab][3-6]\b"
)
_NUMBER_COMPOUND = re.compile(rf"\b(?:\d+|{'|'.join(NUMERALS)})-(?!high\b|tall\b)([a-z]+)\b")


_PLACE_AHEAD = (
    r"(?=(?:in front of|behind|next to|beside|by|to (?:the|its|their) (?:left|right)|left of|right of|on top of"
    r"|under|below|above|between|inside|in|on|at|along|against)\b)"
)
# An adverb that only says how close ("just behind it", "right next to", "slightly to the left of"); "right" not
# after "the", "to" or "far" ("on the right in a basket").
_HEDGE_BEFORE_A_PLACE = re.compile(
    r"\b(?:just|directly|immediately|slightly|somewhat|a (?:little|bit|touch)|(?<!the )(?<!to )(?<!far )right)\s+"
    + _PLACE_AHEAD,
    re.IGNORECASE,
)


def tokenize(text: str) -> list[str]:
    text = re.sub(r"\s*[&+]\s*", " and ", text.lower().replace("\u2019", "'"))  # "3 apples & 2 pears"
    text = re.sub(r"\b(there|here|it|that)'s\b", r"\1 is", text)  # "and there's an hourglass"
    text = _MEASURE.sub(" ", text)  # "a 15 cm ruler", "a 40 x 30 cm board", "an A4 notebook": sizes, not counts
    text = re.sub(r"\b(\d+)\s*[x\u00d7]\b", r"\1", text)  # "2x mugs"
    text = _NUMBER_COMPOUND.sub(r"\1", text)  # "a 3-tier cake stand": one stand (not "a five-high stack")
    text = re.sub(r"\b([a-z]+)\s+[x\u00d7]\s*(\d+)\b", r"\2 \1", text)  # "mugs x4"
    text = re.sub(r"(?<![a-z])'([a-z][^']*?)'(?![a-z])", r"\1", text)  # quoted words: 'mugs'
    text = re.sub(r"\bthe (?:two|both) of them\b", "them", text)  # "between the two of them"
    text = re.sub(r"\bon one side of\b", "to the left of", text)  # "... on one side of it and a photo on the other"
    text = re.sub(r"\bon one side\b", "to its left", text)
    text = re.sub(r"\bon the other(?=\s*(?:[,.;]|and\b|$))", "on the other side", text)
    text = re.sub(r"\bthe other side\b(?! of)", "the other side of it", text)  # of what was just named
    text = re.sub(r"\b(on|at) (either|each|both) (sides?|ends?)\b(?! of)(?=\s*(?:[,.;]|$))", r"\1 \2 \3 of it", text)
    text = _HEDGE_BEFORE_A_PLACE.sub("", text)  # "just in front of them", "right behind it", "a bit to the left of"
    text = re.sub(r"\ba single (?=(?:straight |neat |long )*(?:row|line|file|column)\b)", "a ", text)
    words = re.findall(r"[a-z]+(?:'[a-z]+|(?<=s)'(?![a-z]))?|\d+|[,:;.]", text)  # "a boy's", "the dolls'"
    return _partitives_dropped([t if t not in (":", ";", ".") else "," for t in words])


_PARTITIVE_HEADS = {"each", "every", "either", "both", "all"}


def _partitives_dropped(tokens: list[str]) -> list[str]:
    """ "beside each of the two laptops" reads as "beside each two laptops", "both of the mugs" as "both mugs": the
    partitive "of the" between a distributive word and its noun names no holder."""
    out: list[str] = []
    k = 0
    while k < len(tokens):
        out.append(tokens[k])
        one = 1 if tokens[k + 1 : k + 2] == ["one"] else 0  # "each one of the saucers"
        if tokens[k] in _PARTITIVE_HEADS and tokens[k + 1 + one : k + 2 + one] == ["of"]:
            k += 2 + one
            if tokens[k : k + 1] == ["them"] and out[-1] in ("each", "every"):  # "a cup on every one of them"
                out[-1], k = "each", k + 1
                continue
            if tokens[k : k + 1] and tokens[k] in ("the", "these", "those", "my", "your", "our", "their", "its"):
                k += 1
            continue
        k += 1
    return out


def singular(word: str) -> str:
    """The catalogue's lemma, and the plural in -ys it keeps ("trays", "toys", "keys")."""
    base = lemma(word)
    return word[:-1] if base == word and len(word) > 3 and word.endswith(("ays", "eys", "oys", "uys")) else base


class Lexicon:
    """Phrases (tuples of singular words) -> catalogue category, longest match first; and each category's role."""

    def __init__(self, catalogue: Catalogue) -> None:
        self.catalogue = catalogue
        self.phrases: dict[tuple[str, ...], str] = {}
        self.raw: set[tuple[str, ...]] = set()  # category and kind names as written ("chopsticks": not a plural)
        entries = catalogue.entries()
        words: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {}  # variants share most of their names
        for level in ("category", "kind", "synonym"):
            for e in entries:
                names = {"category": [e.category], "kind": [e.kind], "synonym": list(e.synonyms)}[level]
                for name in names:
                    if name not in words:
                        raw = tuple(w for w in tokenize(name) if w != ",")
                        words[name] = raw, tuple(singular(w) for w in raw)
                    raw, key = words[name]
                    if level != "synonym":
                        self.raw.add(raw)
                    if key and key not in self.phrases and (key not in NOT_OBJECTS or level == "category"):
                        self.phrases[key] = e.category
        self.longest = max((len(k) for k in self.phrases), default=1)
        self.pairs = {e.category for e in entries if _names_a_pair(e.description, e.synonyms)} | PAIRED
        self.names: dict[str, set[str]] = {}  # each category's names as written, synonyms included
        for e in entries:
            self.names.setdefault(e.category, set()).update((e.category, e.kind, *e.synonyms))
        self.categories = sorted({e.category for e in entries})
        self.vocabulary = {w for key in self.phrases for w in key} | {w for key in self.raw for w in key}
        self._initials = spelling.by_initial(self.vocabulary)
        self._canonical = {e.category: e.id for e in reversed(entries) if e.canonical or e.category}
        self._roles: dict[str, str] = {}

    def respelt(self, word: str, before: str = "") -> str | None:
        """The catalogue word a misspelt word stands for ("bannana": banana, "botles": bottles; "a hole puch": a
        hole punch, the word `before` it decides between punch and pouch), or None."""
        base = singular(word)
        if word in self.vocabulary or base in self.vocabulary or word in _NEVER_RESPELT or base in _NEVER_RESPELT:
            return None
        fits = [key[1] for key in self.phrases if len(key) == 2 and key[0] == singular(before)] if before else []
        fixed = spelling.correction(base, self._initials, fits)
        if fixed is None:
            return None
        return fixed if base == word else plural(fixed)

    def match(self, tokens: list[str], i: int) -> tuple[str, int, str] | None:
        """(category, length, phrase) of the longest phrase starting at token i."""
        for n in range(min(self.longest, len(tokens) - i), 0, -1):
            raw = tuple(tokens[i : i + n])
            key = tuple(singular(w) for w in raw)
            category = self.phrases.get(raw) or self.phrases.get(key)
            if (raw in NOT_OBJECTS or key in NOT_OBJECTS) and category not in (" ".join(raw), " ".join(key)):
                return None  # a scene word ("table", "set"), unless the catalogue has a category of that name
            if category:
                return category, n, " ".join(key)
        return None

    def one_pair(self, category: str, word: str) -> bool:
        """Whether `word` as written names one object of a pair category in the plural only ("goggles", "sneakers":
        the catalogue has no "goggle")."""
        names = self.names.get(category, set())
        return category in self.pairs and word in names and singular(word) not in names

    def pair_named(self, word: str) -> tuple[str, str] | None:
        """The pair category that `word` (a plural as written) names: "glasses" in "a pair of glasses" is eyewear, a
        name ending in the word ("eyeglasses", "sun glasses"); a closed compound first."""
        found = sorted(
            (" " in name, len(name), category, name)
            for category in self.pairs
            for name in self.names.get(category, ())
            if name.endswith(word) and name != word
        )
        return (found[0][2], found[0][3]) if found else None

    def describes(self, category: str, words: list[str]) -> bool:
        """Whether the catalogue's best asset for `words` is one of `category` ("olive oil bottle": a bottle)."""
        hits = self.catalogue.hits(" ".join(words), 1)
        return bool(hits) and self.catalogue.entry(hits[0].asset_id).category == category

    def fits(self, item: str, holder: str) -> bool:
        """Whether an item's narrow side is shorter than its holder's long side (a ruler stands in a cup, a laptop
        does not lie on a coaster; unknown sizes fit)."""
        a, b = self._canonical.get(item), self._canonical.get(holder)
        if a is None or b is None:
            return True
        x, y, _ = self.catalogue.get(a).size
        hx, hy, _ = self.catalogue.get(b).size
        return min(x, y) < max(hx, hy)

    def fits_on(self, item: str, carrier: str) -> bool:
        """Whether the item can rest on the carrier: its long side at most the carrier's (a laptop does not rest on a
        mouse pad); a small thing always can (a mug's handle overhangs its coaster). Unknown sizes fit."""
        sizes = self._sizes(item, carrier)
        if sizes is None:
            return True
        (x, y), (hx, hy) = sizes
        return max(x, y) <= max(1.05 * max(hx, hy), SMALL_M)

    def fits_on_a_side(self, item: str, holder: str) -> bool:
        """Whether the item fits on one side of its holder, its long side at most two thirds of the holder's ("a tray
        with a teapot on the left": on the tray's left); one that does not stands beside it ("a plate with a fork on
        the left"). Unknown sizes fit."""
        sizes = self._sizes(item, holder)
        if sizes is None:
            return True
        (x, y), (hx, hy) = sizes
        return 1.5 * max(x, y) <= max(hx, hy) and min(x, y) <= min(hx, hy)

    def _sizes(self, item: str, holder: str) -> tuple[tuple[float, float], tuple[float, float]] | None:
        """The footprints of the two categories' canonical assets; None when either is not in the catalogue."""
        a, b = self._canonical.get(item), self._canonical.get(holder)
        if a is None or b is None:
            return None
        (x, y, _), (hx, hy, _) = self.catalogue.entry(a).size, self.catalogue.entry(b).size
        return (x, y), (hx, hy)

    def role(self, category: str) -> str:
        """ "container" (its asset has a cavity, or one of its variants does: an open jar, an open pencil case, so
        "a jar of apples" is a jar with apples in it), "carrier" (flat and a good support) or "" (neither, or
        unknown). The planner draws a variant that holds what goes in it (agent/planning/variants.py)."""
        if category not in self._roles:
            role = _role_of(self.catalogue, self._canonical.get(category))
            if not role and any(
                self.catalogue.get(e.id).cavity is not None for e in self.catalogue.entries() if e.category == category
            ):
                role = "container"
            self._roles[category] = role
        return self._roles[category]


_lexicons: weakref.WeakKeyDictionary[Catalogue, tuple[frozenset[str], Lexicon]] = weakref.WeakKeyDictionary()


def lexicon_for(catalogue: Catalogue) -> Lexicon:
    """The catalogue's lexicon, shared while its contents stay the same: making one reads every name of every entry,
    0.2 s, and a batch worker plans a scene a second with the same catalogue."""
    ids = catalogue.id_set()
    kept = _lexicons.get(catalogue)
    if kept is None or kept[0] != ids:
        kept = _lexicons[catalogue] = (ids, Lexicon(catalogue))
    return kept[1]


def _names_a_pair(description: str, synonyms: tuple[str, ...]) -> bool:
    """An asset that is a pair of things ("a pair of white sneakers", a synonym "pair of gloves")."""
    return description.lower().startswith("a pair of") or any(s.startswith("pair of") for s in synonyms)


def _role_of(catalogue: Catalogue, asset_id: str | None) -> str:
    if asset_id is None:
        return ""
    asset = catalogue.get(asset_id)
    if asset.cavity is not None:
        return "container"
    x, y, z = asset.size
    return "carrier" if asset.support_probability >= 0.75 and z <= 0.3 * min(x, y) else ""


# -- noun phrases ------------------------------------------------------------------------------------------------
@dataclass
class _Quantity:
    """What the words before a noun say about how many and how arranged."""

    count: int | None = None
    explicit: bool = False
    vague: bool = False
    arrangement: str = ""
    groups: int = 0
    size: int | None = None
    least: int = 0
    loose: str | None = None  # "few", "several": a count said loosely
    adjectives: list[str] = field(default_factory=list)


def _number(word: str) -> int | None:
    if word.isdigit():
        return int(word)
    return NUMERALS.get(word)


def _read_quantity(words: list[str]) -> _Quantity:
    """`quantity? (arrangement "of")? quantity? adjective*`: "two stacks of", "a stack of 5", "a pair of red"."""
    q = _Quantity()
    pending: int | None = None
    half = "half" in words  # "half a dozen"
    said = [w for w in words if w != "half"]
    for i, word in enumerate(said):
        base = singular(word)
        value = _number(word)
        if value is not None:
            pending = (pending or 1) * value if word == "dozen" else value
        elif word in ("high", "tall") and pending is not None and _arranged_after(said[i + 1 :]):
            # "a five-high stack of plates" (not "two tall candles")
            q.size, pending = pending, None
        elif base in ARRANGE_NOUNS or word in _PARTICIPLES:
            pending = _read_arrangement(q, word, base, pending)
        elif base in LOOSE:
            pending = _loose_count(word, base, pending)
            q.loose = base if base in ("few", "several") else None
        elif word in VAGUE:
            q.vague = True
            q.least = max(q.least, 5 if word in MANY else 0)
        elif word in ARTICLES or word in DETERMINERS or word == "of":
            continue
        else:
            q.adjectives.append(word)
    _settle_quantity(q, max(1, pending // 2) if half and pending is not None else pending)
    return q


def _arranged_after(words: list[str]) -> bool:
    return any(singular(w) in ARRANGE_NOUNS for w in words)


def _settle_quantity(q: _Quantity, pending: int | None) -> None:
    """The number left over sizes the groups ("a stack of 5") or counts the things."""
    if q.arrangement and pending is not None and q.size is None:
        q.size = pending
    elif pending is not None:
        q.count, q.explicit = pending, True


_PARTICIPLES = {"stacked": "stack", "piled": "pile", "heaped": "pile"}


def _read_arrangement(q: _Quantity, word: str, base: str, pending: int | None) -> int | None:
    """ "two stacks of", "rows of", "a pyramid of" (groups; what follows sizes them); "two stacked plates" (one
    stack, the number counts the things). The number still pending after the word."""
    if word in _PARTICIPLES:
        q.arrangement, q.groups = _PARTICIPLES[word], 1
        return pending
    q.arrangement = ARRANGE_NOUNS[base]
    q.groups = pending or (1 if base == word else 2)  # "rows of three": more than one row
    if word == "pyramid":
        q.size = 5
    return None


def _loose_count(word: str, base: str, pending: int | None) -> int:
    """ "a pair of": 2; "three pairs of": 6; "pairs of" (how many pairs not said): two pairs."""
    if base in ("pair", "couple"):
        return (pending or (2 if word != base else 1)) * LOOSE[base]
    return LOOSE[base]


_BOUNDARY = {
    ",",
    "and",
    "or",
    "with",
    "on",
    "in",
    "into",
    "onto",
    "inside",
    "beside",
    "next",
    "near",
    "behind",
    "between",
}
_BOUNDARY |= {
    "for",
    "per",
    "to",
    "at",
    "by",
    "from",
    "around",
    "across",
    "atop",
    "that",
    "which",
    "than",
    "is",
    "are",
    *UNDER_WORDS,
}
_BOUNDARY |= {"place", "put", "add", "arrange", "lay", "give", "show", "make", "create", "generate", "build", "want",
              "need", "like"}  # fmt: skip  # "Place three shampoo bottles": the verb describes nothing
_BOUNDARY |= {
    "hold", "holds", "holding", "contain", "contains", "containing", "carry", "carries", "carrying", "has", "have",
    "sit", "sits", "stand", "stands", "rests", "lies",
}  # fmt: skip
PASSIVE_WORDS = {phrase.split()[0] for phrase, _ in PASSIVE_POSITIONS}
_POSITION_WORDS = {phrase.split()[0] for phrase, _ in POSITIONS}
_BOUNDARY |= PASSIVE_WORDS  # "a cake surrounded by cupcakes": the noun ends before the participle


def _premodifier_start(tokens: list[str], i: int, floor: int, words: WordClasses) -> int:
    """Where the noun phrase whose noun starts at token i begins (quantity and adjectives), not before `floor`."""
    j = i
    while j - 1 >= max(floor, i - 6):
        word = tokens[j - 1]
        if word == "of" and j - 2 >= floor and singular(tokens[j - 2]) in _OF_HEADS:
            j -= 1
            continue
        if _describes(word, words) and _attributive(tokens, j - 1, floor, words):
            j -= 1  # "a pile of folded towels", "crumpled paper": a participle used as an adjective
            continue
        if word in _BOUNDARY or word == "of" or _verbal(word, words) or word in words.conjunctions:
            break
        j -= 1
    return j


_OF_HEADS = {*ARRANGE_NOUNS, "pair", "couple", "lot", "plenty", "bunch", "handful", "dozen", "number", "load", "ton"}


def _describes(word: str, words: WordClasses) -> bool:
    """A participle or adverb that may describe the noun after it ("folded", "neatly", "cooling"), not a verb that
    ends the phrase ("holding")."""
    gerund = word in words.verbs and word.endswith("ing") and word not in _BOUNDARY
    return word in words.past_participles or word in words.adverbs or gerund


def _attributive(tokens: list[str], j: int, floor: int, words: WordClasses) -> bool:
    """Whether the participle at token j modifies the noun after it: it follows a determiner, a number, "of" or
    "with", or it is one of the scattered-things words."""
    k = j - 1
    while k > floor and tokens[k] in words.adverbs:  # "of neatly folded towels"
        k -= 1
    before = tokens[k] if k >= floor else ","
    return tokens[j] in SCATTERED or before in ARTICLES | DETERMINERS | VAGUE | {"of", "with"} or bool(_number(before))


def _verbal(word: str, words: WordClasses) -> bool:
    """A verb, participle or adverb as the parse tagged it ("sealed", "laid", "standing", "neatly"), not a noun."""
    return (word in words.verbs or word in words.adverbs) and word not in words.nouns


def _is_plural(words: list[str], lexicon: Lexicon) -> bool:
    """A plural noun ("mugs", "books standing upright", "dice"), not a name that ends in s ("chopsticks", "glass")."""
    if words[-1:] and words[-1] in IRREGULAR_PLURALS:
        return True
    return any(singular(w) != w and w not in SPELLINGS for w in words) and tuple(words) not in lexicon.raw


def _noun_at(tokens: list[str], i: int, lexicon: Lexicon, words: WordClasses) -> tuple[str, int, str, bool] | None:
    """(category, length, phrase, known) of a noun starting at token i: a catalogue name, or a noun the catalogue
    does not name, as the parse tagged it, with its adjectives, right after an article or a number ("a lamp", "three
    gizmos", "a red ring")."""
    found = _catalogue_name_at(tokens, i, lexicon)
    if found:  # "a lime green bowl", "a cherry red mug": a colour, not a lime
        return None if _names_a_shade(tokens, i + found[1]) else (*found, True)
    if i == 0:
        return None
    introduced = _introduces_a_noun(tokens, i - 1)
    if introduced and tokens[i] in ONE_OF_A_KIND and (named := lexicon.match(list(ONE_OF_A_KIND[tokens[i]]), 0)):
        return named[0], 1, tokens[i], True
    j = i
    while j < len(tokens) and j < i + 3 and _run_word(tokens[j], words) and not lexicon.match(tokens, j):
        j += 1
    if j < len(tokens) and _run_word(tokens[j], words):
        return None  # the phrase runs on into a catalogue noun ("a red mug")
    while j > i and not _could_be_noun(tokens[j - 1], words):
        j -= 1  # the head is the run's last noun ("a gizmo standing on ...")
    if j == i:
        return None  # no noun: "a very cluttered ...", an adjective before a participle
    head, nxt = tokens[j - 1], tokens[j] if j < len(tokens) else ","
    if not _names_a_thing(head) or not (nxt in _BOUNDARY or nxt in (",", "of") or _verbal(nxt, words)):
        return None
    if not (introduced or _listed_plural(tokens, i, head, nxt)):
        return None
    return singular(head), j - i, " ".join(singular(w) for w in tokens[i:j]), False


def _catalogue_name_at(tokens: list[str], i: int, lexicon: Lexicon) -> tuple[str, int, str] | None:
    """The catalogue's longest name at token i, without a verb said of the thing ("the monitor stands at the back": a
    monitor)."""
    found = lexicon.match(tokens, i)
    if found and _ends_in_its_verb(tokens, i, found[1]):
        found = lexicon.match(tokens[: i + found[1] - 1], i)
    return found


def _ends_in_its_verb(tokens: list[str], i: int, n: int) -> bool:
    """Whether a catalogue name of n words at token i ends in the verb said of the thing before it: "the monitor
    stands at the back", "a laptop rests on it" (one thing, then a verb in -s), not "two monitor stands"."""
    if n < 2 or tokens[i + n - 1] not in ("stands", "rests") or i == 0:
        return False
    one = tokens[i - 1] in ("a", "an", "the", "one", "each", "every", "my", "your", "our", "his", "her", "its", "this")
    return one and i + n < len(tokens) and tokens[i + n] in _VERB_PLACES


_VERB_PLACES = {"at", "on", "in", "by", "beside", "behind", "next", "near", "to", "between", "against", "upright",
                "alone", "along", "inside", "under", "atop", "centred", "centered", "off"}  # fmt: skip


_COLOURS = {"red", "blue", "green", "yellow", "orange", "purple", "pink", "black", "white", "grey", "gray", "brown"}


def _names_a_shade(tokens: list[str], j: int) -> bool:
    """Whether the noun ending before token j names a shade of the colour at j, said of a noun after it, or a style
    ("a toolbox-style layout", "a beach-themed tray")."""
    if tokens[j : j + 1] in (["style"], ["themed"], ["shaped"], ["inspired"]):
        return True
    return j + 1 < len(tokens) and tokens[j] in _COLOURS and tokens[j + 1] not in (*_BOUNDARY, *LIST_WORDS, "of")


def _names_a_thing(head: str) -> bool:
    return not ((singular(head),) in NOT_OBJECTS or (head,) in NOT_OBJECTS or head in MODIFIERS or head in STOPWORDS)


def _run_word(word: str, words: WordClasses) -> bool:
    """A word of a noun phrase the catalogue does not name: a noun, an adjective or a participle ("sliced
    tomatoes", "cooling cookies")."""
    participle = word in words.past_participles or (word in words.verbs and word.endswith("ing"))
    return _premodifier(word, words) or (_content_word(word) and participle)


_QUANTITY_HEADS = {*ARRANGE_NOUNS, "pair", "couple", "lot", "dozen", "set", "bunch", "handful"}


def _introduces_a_noun(tokens: list[str], j: int) -> bool:
    """An article, a number or "a pair of" / "a stack of" at token j: what follows is a noun phrase."""
    word = tokens[j]
    if word == "of":
        return j > 0 and singular(tokens[j - 1]) in _QUANTITY_HEADS
    return word in ARTICLES or word in NUMBERS or word.isdigit() or word in VAGUE


def _listed_plural(tokens: list[str], i: int, head: str, nxt: str) -> bool:
    """A plural noun with no article in a list or after "with" / "of" ("with widgets, gadgets and a mug", "a platter
    of roasted vegetables"); its phrase starts at token i."""
    by_ring = tokens[i - 1] == "by" and i >= 2 and tokens[i - 2] in PASSIVE_WORDS  # "surrounded by pebbles"
    listed = tokens[i - 1] in (",", "and", "or", "with", "of", "plus") or by_ring
    plural = singular(head) != head and head not in SPELLINGS
    return listed and len(head) > 3 and plural and (nxt in _BOUNDARY or nxt == "of")


def _content_word(word: str) -> bool:
    return (
        word.isalpha()
        and word not in _BOUNDARY
        and word not in DETERMINERS
        and word not in NUMBERS
        and word not in VAGUE
        and word != "of"
    )


def _could_be_noun(word: str, words: WordClasses) -> bool:
    """A word the parse tagged a noun ("a ring", "a painting"), not a participle ("a table laid for four")."""
    return _content_word(word) and word in words.nouns


def _premodifier(word: str, words: WordClasses) -> bool:
    """A noun or an adjective: a word of a noun phrase before its head ("a red ring", "a wedding ring")."""
    return _content_word(word) and (word in words.nouns or word in words.adjectives)


def _noun_phrases(tokens: list[str], lexicon: Lexicon, words: WordClasses) -> list[Mention]:
    mentions: list[Mention] = []
    i = 0
    while i < len(tokens):
        floor = mentions[-1].end if mentions else 0
        if tokens[i] in COLLECTIVES and not lexicon.match(tokens, i):
            start = _premodifier_start(tokens, i, floor, words)
            q = _read_quantity(tokens[start:i])
            for category, share in _shares(q, COLLECTIVES[tokens[i]]):
                mentions.append(_mention(category, category, share, start, i + 1, True, True))
                mentions[-1].collective = True
            i += 1
            continue
        found = (
            None if tokens[i] == "dozen" else _unit_of(tokens, i, lexicon, words) or _noun_at(tokens, i, lexicon, words)
        )
        if not found:
            i += 1
            continue
        category, n, phrase, known = found
        if _names_no_thing_here(tokens, i, n, words):
            i += n
            continue
        if mentions and _modifies_next(mentions[-1], tokens, i):
            mentions.pop()  # "a glass pitcher", "a paper cup": the first noun says what the second is made of
            floor = mentions[-1].end if mentions else 0
        n += _trailing_unit(tokens, i + n, lexicon)
        start = _premodifier_start(tokens, i, floor, words)
        q = _read_quantity(tokens[start:i])
        said = tokens[i : i + n]
        if said[:2] == ["pair", "of"] and category not in PAIRED:  # "a pair of chopsticks" is two chopsticks
            q.count, q.explicit = 2 * (q.count or 1), True
        category, phrase, one_pair = _pairs(tokens[start:i], said, category, phrase, q, lexicon)
        plural = (
            not one_pair
            and _is_plural(_number_words(said), lexicon)
            and not (
                said[0] in IRREGULAR_PLURALS and tokens[i - 1 : i] in (["a"], ["an"], ["one"])  # "a dice"
            )
        )
        mentions.append(_mention(category, phrase, q, start, i + n, plural, known))
        i += n
    return mentions


_PERSONAL = {"you", "i", "we", "they", "he", "she", "it"}


def _names_no_thing_here(tokens: list[str], i: int, n: int, words: WordClasses) -> bool:
    """ "Can you give me ...": a modal, not a can; "for a robot to tidy up", "a shelf I want a robot to sort": the
    robot the scene is for, not a toy robot on it."""
    said, after = tokens[i : i + n], tokens[i + n : i + n + 2]
    if said == ["can"] and after[:1] and after[0] in _PERSONAL:
        return True
    if said[-1] not in AGENTS or said[0] == "toy":
        return False
    return "for" in tokens[max(0, i - 2) : i] or (after[:1] == ["to"] and after[1:] != [] and after[1] in words.verbs)


def _shares(q: _Quantity, kinds: tuple[str, ...]) -> list[tuple[str, _Quantity]]:
    """A collective's kinds, each with its share of a number said of the whole: "five fruits" are two apples, two
    oranges and a banana, not five of each."""
    if not (q.explicit and q.count) or q.arrangement:
        return [(kind, q) for kind in kinds]
    counts = [q.count // len(kinds) + (1 if n < q.count % len(kinds) else 0) for n in range(len(kinds))]
    return [(kind, replace(q, count=n)) for kind, n in zip(kinds, counts, strict=True) if n > 0]


def _modifies_next(m: Mention, tokens: list[str], i: int) -> bool:
    """Whether mention m is a singular noun right before the noun at token i, so a modifier of it ("glass" in "a
    glass pitcher", "metal" in "four metal bowls"): English runs two things together only with a word between."""
    word = tokens[m.end - 1]  # singular as written, whatever its count ("3 football trophies": trophies)
    return (
        m.end == i and not m.collective and word.isalpha() and singular(word) == word and word not in IRREGULAR_PLURALS
    )


def _pairs(
    before: list[str], words: list[str], category: str, phrase: str, q: _Quantity, lexicon: Lexicon
) -> tuple[str, str, bool]:
    """(category, phrase, one pair) for a noun whose catalogue asset is already a pair: "a pair of sneakers" and
    "goggles" are one object, "three pairs of gloves" three; "a pair of glasses" names eyewear, not two tumblers."""
    if words[:2] == ["pair", "of"]:
        return category, phrase, category in PAIRED
    said = bool({"pair", "pairs"} & set(before))
    if said and category not in lexicon.pairs and (named := lexicon.pair_named(words[-1])):
        category, phrase = named
    if category in lexicon.pairs and said:
        q.count, q.explicit = max(1, (q.count or 2) // 2), True
        return category, phrase, q.count == 1
    return category, phrase, not said and not q.explicit and lexicon.one_pair(category, words[-1])


def _number_words(words: list[str]) -> list[str]:
    """The words whose number is the phrase's: the unit's in "tubes of toothpaste", "rolls of toilet paper"."""
    return words[:1] if len(words) > 2 and words[1] == "of" and singular(words[0]) in UNITS else words


def _unit_of(tokens: list[str], i: int, lexicon: Lexicon, words: WordClasses) -> tuple[str, int, str, bool] | None:
    """ "UNIT of NOUN" as one thing: the catalogue's "NOUN UNIT" ("a jar of honey": a jar, "jars of spices": spice
    jars) or, for a unit that holds nothing, the NOUN ("a tube of toothpaste"); None when a container unit holds
    its NOUNs ("a bowl of apples") or the words are no unit phrase."""
    unit = singular(tokens[i])
    if unit not in UNITS or tokens[i + 1 : i + 2] != ["of"] or i + 2 >= len(tokens):
        return None
    whole = lexicon.match(tokens, i)
    if whole and whole[1] > 2:
        return None  # the catalogue's own name ("a bar of soap", "a can of paint")
    inner = lexicon.match(tokens, i + 2)
    inner_words = tokens[i + 2 : i + 2 + (inner[1] if inner else 1)]
    compound = lexicon.phrases.get((*(singular(w) for w in inner_words), unit)) or lexicon.phrases.get(
        (singular(inner_words[-1]), unit)  # "a jar of hand cream": the catalogue's cream jar
    )
    holder = lexicon.match([unit], 0)
    holds = bool(holder and lexicon.role(holder[0]) == "container")
    last = inner_words[-1]
    many = singular(last) != last and last not in SPELLINGS or last in IRREGULAR_PLURALS
    length = 2 + len(inner_words)
    if holds and inner is None and tokens[i + 2] in COLLECTIVES and _ends_phrase(tokens, i + 3, words):
        return None  # "a bowl of fruit", "a box of toys": a container and its contents, not a fruit bowl alone
    if holder and inner is None and (described := _container_described(tokens, i, holder, lexicon, words)):
        return described  # "a bottle of olive oil": the catalogue's olive oil bottle
    if holder and inner is None and (singular(inner_words[0]),) in NOT_OBJECTS:
        return holder[0], length, holder[2], True  # "jars of spices", "a bottle of oil": contents, not another thing
    if holder is not None and inner is None and not holds and (closed := _closed_unit(tokens, i, lexicon, words)):
        return holder[0], closed[0], closed[1], True
    if compound and (inner is None or inner[0] == compound or not (holds and many)):
        return compound, length, " ".join((*(singular(w) for w in inner_words), unit)), True
    if inner and not holds and (unit in NAMING_UNITS or not (holder and lexicon.role(holder[0]) == "carrier")):
        return inner[0], length, inner[2], True  # "a sheet of sandpaper", not a sheet of paper with sandpaper on it
    if not inner and not holder and _could_be_noun(inner_words[0], words) and _ends_phrase(tokens, i + 3, words):
        return singular(inner_words[0]), length, singular(inner_words[0]), False  # "a pack of cards": one unknown
    return None


def _closed_unit(tokens: list[str], i: int, lexicon: Lexicon, words: WordClasses) -> tuple[int, str] | None:
    """A closed unit (a tin, a bottle) of what the catalogue has no thing for: "two tins of tomatoes", "tins of baked
    beans" are tins. (length, phrase) or None."""
    end = next((j for j in range(i + 3, i + 6) if _ends_phrase(tokens, j, words)), 0)
    if not end or any(lexicon.match(tokens, j) for j in range(i + 2, end)):
        return None
    return end - i, " ".join((*tokens[i + 2 : end - 1], singular(tokens[end - 1]), singular(tokens[i])))


def _container_described(
    tokens: list[str], i: int, holder: tuple[str, int, str], lexicon: Lexicon, words: WordClasses
) -> tuple[str, int, str, bool] | None:
    """ "UNIT of CONTENTS" (CONTENTS a mass noun the catalogue does not name) as the container when its best asset for
    "CONTENTS UNIT" is one of the unit's category: "a bottle of olive oil", "a jar of pickles", "a tin of paint"."""
    j = i + 2
    while j < len(tokens) and j < i + 5 and _premodifier(tokens[j], words) and not lexicon.match(tokens, j):
        j += 1
    contents = [singular(w) for w in tokens[i + 2 : j]]
    if not contents or not _ends_phrase(tokens, j, words) or contents[-1] != tokens[j - 1]:
        return None  # plural contents are things of their own ("a bowl of avocados")
    named = [*contents, singular(tokens[i])]
    return (holder[0], j - i, " ".join(named), True) if lexicon.describes(holder[0], named) else None


def _ends_phrase(tokens: list[str], j: int, words: WordClasses) -> bool:
    return j >= len(tokens) or tokens[j] in _BOUNDARY or _verbal(tokens[j], words)


def _trailing_unit(tokens: list[str], j: int, lexicon: Lexicon) -> int:
    """1 when a unit word that holds nothing follows the noun ("toilet paper rolls", "a toothpaste tube")."""
    if j < len(tokens) and singular(tokens[j]) in TRAILING_UNITS and not lexicon.match(tokens, j + 1):
        return 1 if (j + 1 >= len(tokens) or tokens[j + 1] != "of") else 0
    return 0


def _aliases(mentions: list[Mention], tokens: list[str]) -> None:
    """ "the laptop", "each mug": a second mention of a thing named before (without a number of its own)."""
    for k, m in enumerate(mentions):
        bare = not (m.plural or m.explicit_count) and tokens[m.start] not in ARTICLES | DETERMINERS
        anchor = bare and m.start > 0 and tokens[m.start - 1] in _ANCHOR_WORDS  # "phone in front of laptop"
        anchor = anchor or (m.start > 0 and tokens[m.start - 1] in ("this", "that", "these", "those"))  # "that jar"
        if (tokens[m.start] in ("the", "its", "this", "that", "each", "every") or anchor) and not m.explicit_count:
            same = (j for j, o in enumerate(mentions[:k]) if o.category == m.category and not _contrasting(m, o))
            m.alias = next(same, None)
        elif tokens[m.start] in ("the", "these", "those") and m.explicit_count:  # "the two plates": the plates said
            same = (j for j, o in enumerate(mentions[:k]) if _same_head(o, m) and o.count == m.count)
            m.alias = next(same, None)


def _same_head(a: Mention, b: Mention) -> bool:
    """Whether two mentions name things of one kind ("the two glasses" after "two wine glasses")."""
    return a.category == b.category or a.category.split()[-1] == b.category.split()[-1]


def _contrasting(a: Mention, b: Mention) -> bool:
    """Whether two mentions of a category name different things: "the small dipping bowl inside the big serving
    bowl" (other words of their own on both sides), not "a coffee mug ... the mug" or "the blue mug"."""
    words_a = {*a.adjectives, *a.phrase.split()} - {*a.category.split(), "of"} - MODIFIERS_SHARED
    words_b = {*b.adjectives, *b.phrase.split()} - {*b.category.split(), "of"} - MODIFIERS_SHARED
    return bool(words_a) and bool(words_b) and not words_a & words_b


MODIFIERS_SHARED = {"pair", "single", "other", "same"}  # words that say nothing of which thing it is


_ANCHOR_WORDS = {"of", "to", "behind", "beside", "near", "by", "on", "in", "onto", "inside", "between", "under"}


def _mention(category: str, phrase: str, q: _Quantity, start: int, end: int, plural: bool, known: bool) -> Mention:
    plural = plural or bool(q.explicit and (q.count or 1) > 1)
    count = max(1, min(MOST, q.count if q.count is not None else (3 if plural else 1)))
    m = Mention(category, count, phrase, tuple(q.adjectives), start, end, plural, q.explicit, known=known)
    m.arrangement, m.groups = q.arrangement, q.groups
    if q.size is not None:
        m.sizes = (q.size,) * max(1, q.groups or 1)
    m.stacked = q.arrangement in ("stack", "pile")
    m.least = q.least
    if q.loose is not None and not q.arrangement and q.count == LOOSE[q.loose]:
        m.loose = q.loose
    return m


def _per_group_counts(mentions: list[Mention], tokens: list[str]) -> list[Mention]:
    """ "three stacks of books, four books each": the second phrase sizes the first one's stacks or rows."""
    kept: list[Mention] = []
    arranged: dict[str, Mention] = {}  # category -> the last kept mention of it with an arrangement
    for m in mentions:
        after = tokens[m.end : m.end + 2]
        each = after[:1] in (["each"], ["apiece"]) or (
            after[:1] in (["per"], ["in"])
            and after[1:] != []
            and (after[1] == "each" or singular(after[1]) in ARRANGE_NOUNS)
        )
        grouped = arranged.get(m.category)
        if each and m.explicit_count and grouped is not None:
            grouped.sizes = (m.count,) * max(1, grouped.groups)
            grouped.count = sum(grouped.sizes)
            continue
        kept.append(m)
        if m.arrangement:
            arranged[m.category] = m
    _bare_sizes_each(kept, tokens)
    return kept


_GROUP_WORDS = {"row", "rows", "stack", "stacks", "pile", "piles", "column", "columns", "line", "lines"}


def _bare_sizes_each(mentions: list[Mention], tokens: list[str]) -> None:
    """ "two stacks of coasters on a tray, three each", "two rows of cans, five in each row": a number with "each"
    (or "per row") and no noun sizes the stacks or rows named last before it; "three in the front row and two in
    the back row" sizes them one by one."""
    said: dict[int, list[tuple[int, int]]] = {}  # grouped mention -> (token, size) said of one of its groups
    for i in range(len(tokens) - 1):
        size = _number(tokens[i])
        if not size or any(m.start <= i < m.end for m in mentions):
            continue
        after = tokens[i + 1 : i + 5]
        each = after[:1] in (["each"], ["apiece"]) or after[:3] in (["in", "each", w] for w in _GROUP_WORDS)
        each = each or after[:2] in (["per", w] for w in _GROUP_WORDS)
        one = after[:2] == ["in", "the"] and bool(set(after[2:4]) & _GROUP_WORDS)  # "three in the front row"
        grouped = next((m for m in reversed(mentions) if m.end <= i and m.arrangement and m.groups), None)
        if grouped is None or not (each or one):
            continue
        if each:
            grouped.sizes = (size,) * grouped.groups
            grouped.count = sum(grouped.sizes)
        else:
            said.setdefault(mentions.index(grouped), []).append((i, size))
    for k, sizes in said.items():
        if len(sizes) == mentions[k].groups:
            mentions[k].sizes = tuple(size for _, size in sizes)
            mentions[k].count = sum(mentions[k].sizes)


def _read_amount(m: Mention, tokens: list[str], stop: int, paired: bool = False) -> None:
    """How many the words around a phrase imply when no number is said: "on each side of" (one per side), "toy
    cars everywhere" (many), "crumpled paper" (a bare mass noun with a scattering word: several), "dice". `paired`:
    the phrase ends a list of two single things ("a mouse and a notebook on either side"), one on each side."""
    after = " ".join(tokens[m.end : stop + 4])
    sides = re.match(r"(?:\w+ )?(?:on|at|to) (each|either|both) (?:side|end)s?\b", after)
    if sides and not (paired and sides.group(1) == "either"):  # "a lamp on each side": one per side; "two chairs
        per_side = m.count if m.explicit_count and sides.group(1) != "either" else 1  # at each end": two per end
        m.count, m.explicit_count, m.plural = 2 * per_side, True, True
    if m.plural and not m.explicit_count and any(after.startswith(w) or f" {w}" in after[:30] for w in FILL_WORDS):
        m.least = max(m.least, 6)
    bare = tokens[m.start] not in ARTICLES | DETERMINERS and not m.explicit_count and not m.plural
    if bare and (set(m.adjectives) & SCATTERED or tokens[m.start] in SCATTERED):
        m.plural, m.count, m.least = True, max(m.count, 3), max(m.least, 3)
    if tokens[m.start : m.end][-1:] == ["dice"] and m.plural and not m.explicit_count:
        m.count = max(2, m.count)


FILLED: tuple[str, ...] = (
    "full of",
    "filled with",
    "packed with",
    "stuffed with",
    "crammed with",
    "loaded with",
    "lined with",
)
FILLED += ("covered with", "covered in", "stocked with", "piled with", "heaped with")


def _fills_the_support(m: Mention, tokens: list[str], floor: int) -> None:
    """ "a spice shelf full of spice jars", "a desk covered with papers": plurals that fill the support itself (a
    scene word, so no mention holds them) are many, as far as the support holds."""
    before = " ".join(tokens[floor : m.start])
    phrase = next((f for f in FILLED if before.endswith(f)), None)
    if phrase is None or not m.plural or m.explicit_count:
        return
    support = before[: -len(phrase)].split()[-1:]
    if support and (singular(support[0]),) in NOT_OBJECTS:
        m.least = max(m.least, 8)


# -- words after a noun phrase ------------------------------------------------------------------------------------
# what may stand between a noun phrase and its place ("three candles of different heights in a row along the back")
_BEFORE_PLACE = re.compile(
    r"^(?:(?:of (?:different|various|varying|assorted|mixed|all) \w+|(?:arranged |standing |placed |set )?"
    r"(?:in an? (?:neat |tight |small |long |straight )?(?:row|line|stack|pile|cluster|group)|side by side|stacked"
    r"|lined up|piled up|evenly spaced))(?: ,)? )+"
)


def _read_postmodifiers(m: Mention, after: list[str]) -> None:
    """ "stacked", "in two rows", "lined up", ", one of three and one of four", "five high" right after the noun
    phrase."""
    text = " ".join(after)
    if any(text.startswith(w) or 0 <= text.find(f" {w}") <= 24 for w in CENTRE_WORDS):
        m.centre = True
    m.region = m.region or _read_region(_BEFORE_PLACE.sub("", text))
    arrangement = _arrangement_word(text[:40])
    if arrangement and not (m.arrangement and arrangement == "stack"):
        m.arrangement = m.arrangement or arrangement
        m.stacked = m.arrangement in ("stack", "pile")
    if m.arrangement in ("row", "column") and ("evenly" in after[:6] or "spaced" in after[:6]):
        m.spaced = True
    _read_groups(m, text)
    _read_group_sizes(m, text)
    if text.startswith(("in pairs", "in twos", "two by two")) and m.count > 1:  # rows of two
        m.arrangement, m.sizes = "row", (2,) * ((m.count + 1) // 2)
    m.stacked = m.arrangement in ("stack", "pile")


_GROUP_NOUNS = {"stack": "stack", "tower": "stack", "pile": "pile", "heap": "pile", "row": "row", "line": "row"}
_GROUP_NOUNS |= {"column": "column", "group": "row", "set": "row", "cluster": "row", "batch": "row", "pair": "row"}
# Participles that may come before "in two rows" ("arranged in two columns of four").
_LEAD = r"(?:(?:[a-z]+ed|set|laid|put|sorted|up|out|neatly) )*(?:in |into |as )?"


OPPOSITE_SIDE = {"left": "right", "right": "left", "front": "behind", "behind": "front"}


def _other_places(mentions: list[Mention]) -> None:
    """ "a toothbrush holder at the left end, and towels at the other end": the end (or corner) across from the place
    said last before; an end or a corner when none was said."""
    for k, m in enumerate(mentions):
        if m.region[:1] != ("other",):
            continue
        kind = m.region[1]
        said = next((o.region for o in reversed(mentions[:k]) if {"left", "right"} & set(o.region)), ())
        across = {"left": "right", "right": "left", "back": "front", "front": "back"}
        sides = tuple(across[w] for w in said if w in across and (kind == "corner" or w in ("left", "right")))
        m.region = (*sides, "corner") if kind == "corner" else (sides or ("end",))


def _other_sides(mentions: list[Mention]) -> None:
    """ "a spoon to its left and a knife on the other side of the bowl": the side opposite the one said of the same
    thing; said of a thing that stands on a side of another ("a fork on its left and a knife on the other side of
    it"), the other side of that other; beside it when no side was said."""

    def anchor(j: int | None) -> int | None:
        return mentions[j].alias if j is not None and mentions[j].alias is not None else j

    for m in mentions:
        if m.side != "other":
            continue
        target = anchor(m.beside)
        said = [o for o in mentions if o is not m and anchor(o.beside) == target and o.side in OPPOSITE_SIDE]
        if not said and target is not None and mentions[target].side in OPPOSITE_SIDE:  # the fork's other side
            said, m.beside = [mentions[target]], mentions[target].beside
        m.side = OPPOSITE_SIDE[said[0].side] if said else "beside"


def _stacked_by_the_verb(m: Mention, tokens: list[str]) -> None:
    """ "stack two tins of tomatoes", "pile the plates": the verb says the arrangement (not "a stack of ...")."""
    verb = tokens[m.start - 1] if m.start > 0 else ""
    if verb in ("stack", "pile") and (m.start < 2 or tokens[m.start - 2] not in ARTICLES) and m.count > 1:
        if not m.arrangement:
            m.arrangement, m.stacked = verb, True


def _read_region(text: str) -> tuple[str, ...]:
    """The place on the support that the words right after a noun phrase give ("in the back left corner of the room"
    -> back, left, corner), or (). A place "of" something named next is a relation to it, not a place on the support
    ("to the left of the laptop": the window of words ends before the laptop)."""
    ends = _BOTH_ENDS.search(text[:40])
    if ends and ends.group(1) in SUPPORT_WORDS:  # "at each end of the shelf": one at either end of the support
        return ("ends",)
    if (other := _OTHER_PLACE.search(text[:30])) is not None and other.start() <= 12:
        return ("other", other.group(1))
    if viewer := _BY_THE_VIEWER.search(text[:30]):  # "closest to me": the front, as the viewer sees it
        return ("front",) if viewer.group(1) in ("closest", "nearest", "close", "near", "next") else ("back",)
    for pattern in (_CORNER, _BAND, _END, _EDGE):
        match = pattern.search(text)
        if match is None or match.start() > 24:
            continue
        rest = text[match.end() :].split()
        if rest[:1] == ["of"] and (len(rest) <= 2 or rest[1] in ("it", "them")):  # "... of (the)" and then the
            continue  # next thing, or "of it": a relation
        words = match.group(1) if pattern.groups else ""
        sides = tuple(dict.fromkeys(REGION_SIDES[w] for w in re.split(r"[ -]", words) if w in REGION_SIDES))
        if pattern is _CORNER:
            return (*sides, "corner")
        if pattern is _BAND:
            return _band_sides(match, text, sides)
        if pattern is _END:
            return ("end",)
        return ("back",) if words == "wall" else ("edge",)
    return ()


def _band_sides(match: re.Match[str], text: str, sides: tuple[str, ...]) -> tuple[str, ...]:
    """The sides of a band of the support ("at the back"), with a second band said right after it ("at the back on
    the left": both); "at the far end" is an end."""
    if match.group(0).endswith(" end") and sides == ("back",):
        return ("end",)
    crossing = ({"back", "left"}, {"back", "right"}, {"front", "left"}, {"front", "right"})
    if (side := re.match(r"[ -](left|right)\b(?! of)", text[match.end() :])) and {side[1], *sides} in crossing:
        return (*sides, side[1])  # "at the back right"
    also = _BAND.match(text[match.end() :].lstrip(" ,"))
    if also and {REGION_SIDES[also.group(1)], *sides} in crossing:
        return (*sides, REGION_SIDES[also.group(1)])
    return sides


_SUPPORTS = "|".join(sorted(SUPPORT_WORDS))
# a place on the support said between a noun and its arrangement
_PLACE_FIRST = re.compile(
    rf"^(?:on|at|along|across) (?:the|my|our|a) (?:[a-z]+ ){{0,2}}?(?:{_SUPPORTS}|left|right|back|front|middle|centre)"
    rf"(?: (?:side|end|edge|half))?(?: of (?:the|my|our) (?:[a-z]+ )?(?:{_SUPPORTS}))? (?=(?:[a-z]+ )?(?:in|into|as) )"
)


def _read_groups(m: Mention, text: str) -> None:
    """ "in two rows", "arranged in two columns of four", "in groups of three", "stacks of 5"."""
    nouns = "|".join(f"{n}s" for n in _GROUP_NOUNS)
    text = _PLACE_FIRST.sub("", text)  # "on the larder shelf in two rows of four"
    match = re.match(rf"{_LEAD}(\w+) ({nouns})(?: of (\w+))?\b", text)
    if match and _number(match.group(1)):
        m.groups = _number(match.group(1)) or 0
        m.arrangement = _GROUP_NOUNS[singular(match.group(2))]
        if match.group(3) and _number(match.group(3)):
            m.sizes = ((_number(match.group(3)) or 1),) * m.groups
        return
    match = re.match(rf"{_LEAD}(?:{nouns}) of (\w+)\b", text)
    if match and _number(match.group(1)):
        size = _number(match.group(1)) or 1
        word = re.search(rf"\b({nouns}) of", text)
        m.arrangement = _GROUP_NOUNS[singular(word.group(1))] if word else "row"
        m.groups = m.groups or (-(-m.count // size) if m.explicit_count else 2)
        m.sizes = (size,)


def _read_group_sizes(m: Mention, text: str) -> None:
    """ ", one of three and one of four", ", one five high and one three high", "each four high", "five high"."""
    if not m.arrangement:
        return
    more = re.search(rf"\b(?:a second|another|a third)(?: ,)? (?:\w+ )?(?:{'|'.join(_GROUP_NOUNS)}) of (\w+)", text)
    if more and _number(more.group(1)):  # "a pile of four books next to a second, smaller pile of two"
        m.sizes = (*(m.sizes or (m.count,)), _number(more.group(1)) or 1)
        m.groups = max(m.groups, len(m.sizes))
        return
    sizes = [_number(w) for w in re.findall(r"(?:one|another|the other)(?: of| with)? (\w+)", text)]
    if sizes and all(sizes):
        m.sizes = tuple(s or 1 for s in sizes)
        m.groups = max(m.groups, len(m.sizes))
        return
    each = re.search(r"\beach(?: of| with)? (\w+)", text) or re.search(r"\b(\w+) (?:high|tall)\b", text)
    if each and _number(each.group(1)):
        m.sizes = ((_number(each.group(1)) or 1),) * max(1, m.groups)


def _arrangement_word(text: str) -> str:
    for words, arrangement in (
        (STACK_WORDS, "stack"),
        (PILE_WORDS, "pile"),
        (ROW_WORDS + ROW_WORDS_2, "row"),
        (SCATTER_WORDS, "scatter"),
    ):
        if any(text.startswith(w) or f" {w}" in text for w in words):
            return arrangement
    if re.match(rf"{_LEAD}\w+ (rows|columns|groups|pairs|sets)\b", text) or re.match(
        rf"{_LEAD}(?:groups|sets) of", text
    ):
        return "row"
    high = re.match(r"(?:\w+ )?(\w+) (?:high|tall)\b", text)
    if high and _number(high.group(1)):
        return "stack"
    return ""


# -- relations ----------------------------------------------------------------------------------------------------
def _link(tokens: list[str], a: Mention, b: Mention) -> str:
    """The words between two noun phrases, articles and determiners left out."""
    dropped = ("the", "a", "an", "its", "their", "his", "her", "this", "that", "these", "those")
    return " ".join(w for w in tokens[a.end : b.start] if w not in dropped)


def _relation(link: str) -> tuple[str, str]:
    """("holds" | "position" | "list" | "", detail) named by the end of a link."""
    candidates = [("holds", phrase, phrase) for phrase in HOLDS] + [("position", p, where) for p, where in POSITIONS]
    ends = [(len(phrase), kind, detail) for kind, phrase, detail in candidates if _ends_with(link, phrase)]
    if ends:
        _, kind, detail = max(ends, key=lambda e: e[0])
        return kind, detail
    if link in LIST_WORDS or link.endswith((" and", " ,", " or", " plus")) or link in ("", ",and"):
        return "list", ""
    return "", ""


def _own_carrier_of_the_one_before(mentions: list[Mention], tokens: list[str], k: int, where: str) -> bool:
    """Whether "on its Y" (or ", on a Y") after mention k is said of the thing before it that stands by k ("a mouse
    to the right of the keyboard on its mouse pad", "a mug to the right of the lamp, on a cork coaster")."""
    start = mentions[k + 1].start
    said = "its" in tokens[start - 1 : start + 1] or tokens[mentions[k].end : mentions[k].end + 1] == [","]
    if where not in ("on", "in") or k == 0 or not said:  # "on its mouse pad", ", on a cork coaster"
        return False
    return mentions[k - 1].beside == k and mentions[k - 1].on is None and mentions[k - 1].held_by is None


def _said_aside(mentions: list[Mention], tokens: list[str], k: int, link: str) -> bool:
    """Whether what follows "with" after mention k stands aside rather than in or on it: ", with a lamp nearby",
    "with a trophy at one end", "with a saucer under each", "with the iron standing between them"."""
    item = mentions[k + 1]
    return (
        (link.startswith(",") and _list_stands_aside(mentions, tokens, k))
        or _at_an_end(item, tokens)
        or tokens[item.end : item.end + 1] in ([w] for w in UNDER_WORDS)
        or _posture_dropped(tokens[item.end : item.end + 3])[:2] == ["between", "them"]
    )


def _ends_with(link: str, phrase: str) -> bool:
    return link == phrase or link.endswith(" " + phrase)


def _relations(mentions: list[Mention], tokens: list[str], lexicon: Lexicon, words: WordClasses) -> None:
    k = 0
    while k < len(mentions) - 1:
        link = _link(tokens, mentions[k], mentions[k + 1])
        if _reversed(mentions, tokens, k, link, lexicon):
            k += 1
            continue
        kind, detail = _relation(link)
        aside = detail == "with" and _said_aside(mentions, tokens, k, link)
        said_of = _said_of(mentions, tokens, k, detail, lexicon) if kind == "holds" else k
        if kind == "holds" and _holds(lexicon, mentions[said_of], detail) and not aside:
            k = _take_listed(mentions, tokens, k, lexicon, detail, said_of)
            continue
        if kind == "position" and _own_carrier_of_the_one_before(mentions, tokens, k, detail):
            thing, carrier = mentions[k - 1], mentions[k + 1]  # "a mouse to the right of the keyboard on its mouse
            if carrier.beside is None:  # pad": the pad stands there, the mouse on it
                carrier.beside, carrier.side = thing.beside, thing.side
            thing.beside = None
            _rest_on_or_in(mentions, k - 1, k + 1, detail, lexicon)
        elif kind == "position":
            _position(mentions, k, detail, lexicon)
            if detail == "between":
                _between_two(mentions, tokens, k)
            _share_with_list(mentions, tokens, k, detail, lexicon)
            if _distributive(mentions, tokens, k) and detail not in ("around", "sides", "ends"):
                _one_per_thing(mentions, k)
        k += 1
    _relations_of_each(mentions, tokens, lexicon, words)
    _kinds_stand_together(mentions)
    _one_on_each_side(mentions, tokens)
    _in_order(mentions, tokens)


def _relations_of_each(mentions: list[Mention], tokens: list[str], lexicon: Lexicon, words: WordClasses) -> None:
    """What each thing's own words after it say: "on it", "to its left", a rim, a ring, a place on the support (and
    a place said after a list, every listed thing's)."""
    for k, m in enumerate(mentions):
        if m.alias is not None and m.per is not None:  # "every mug on a saucer": the mugs named before
            mentions[m.alias].per, mentions[m.alias].on = m.per, m.on
        _pronoun_relation(mentions, tokens, k, lexicon, words)
        _link_rims_and_rings(mentions, tokens, k, m)
        if m.centre and m.held_by is not None:  # "a bowl of lemons in the middle": the bowl is
            m.centre, mentions[m.held_by].centre = False, True
        _place_region(mentions, tokens, k, lexicon)
    for k in range(len(mentions)):
        _share_a_region(mentions, tokens, k)


def _pair_ends(a: Mention, b: Mention, tokens: list[str]) -> bool:
    """Whether b ends a list of two different single things that starts with a ("a mouse and a notebook")."""
    single = not (a.explicit_count or b.explicit_count or a.plural or b.plural) and a.category != b.category
    listed_first = a.start == 0 or tokens[a.start - 1] != ","  # not the end of a longer list
    return single and listed_first and tokens[a.end : b.start] in (["and"], [",", "and"])


def _one_on_each_side(mentions: list[Mention], tokens: list[str]) -> None:
    """ "a clock flanked by a candle and a vase", "on either side of the keyboard lie a mouse and a notebook": two
    different single things on either side stand one on each, the first on the viewer's left."""
    for k in range(1, len(mentions)):
        a, b = mentions[k - 1], mentions[k]
        if b.side != "sides" or b.beside is None or b.count != 1 or not _pair_ends(a, b, tokens):
            continue
        free = not any(x is not None for x in (a.on, a.held_by, a.around)) and a.beside in (None, b.beside)
        if free and b.beside != k - 1:
            a.beside, a.side, b.side = b.beside, "left", "right"
        else:  # not a pair after all ("a vase with a candle and a clock on either side"): a clock on each side
            b.count, b.explicit_count, b.plural = 2, True, True


def _at_an_end(m: Mention, tokens: list[str]) -> bool:
    """Whether the words right after m put it at an end, a corner or an edge of the support, or at its far side
    ("twelve books in a row, with a trophy at one end"): a place of its own, not in or on what it is listed with."""
    after = tokens[m.end : m.end + 6]
    region = _read_region(" ".join(after))
    at_an_end = "end" in after[2:5] and "of" not in after[2:6]  # "at the left end" (of the row or the support)
    return after[:1] in (["at"], ["on"]) and (
        bool({"end", "ends", "corner", "edge"} & set(region)) or (bool(region) and ("far" in after[:4] or at_an_end))
    )


def _kinds_stand_together(mentions: list[Mention]) -> None:
    """ "some fruit on a plate": every kind a collective word stands for is where its words put the last kind."""
    for k, m in enumerate(mentions):
        if not m.collective:
            continue
        kinds = [j for j, o in enumerate(mentions) if o.collective and (o.start, o.end) == (m.start, m.end)]
        if kinds[-1] == k:
            continue
        last = mentions[kinds[-1]]
        if m.on is not None or m.beside is not None or m.around is not None or any(k in h.contents for h in mentions):
            continue
        m.on, m.beside, m.side, m.around, m.region = last.on, last.beside, last.side, last.around, last.region
        for holder in mentions:
            if kinds[-1] in holder.contents:
                holder.contents.insert(holder.contents.index(kinds[-1]), k)


_ORDER_WORDS = {",", "and", "then", "next", "is", "comes", "item", "one", "first", "second", "third", "fourth", "fifth",
                "sixth", "last", "finally"}  # fmt: skip


def _in_order(mentions: list[Mention], tokens: list[str]) -> None:
    """ "a kettle, a teapot and a sugar bowl in a row from left to right": each thing of the list stands to the right
    of the one before it, as the viewer sees it ("from right to left": to its left)."""
    text = " ".join(tokens)
    found = re.search(r"\b(left|right) to (left|right)\b", text)
    if found is None or found.group(1) == found.group(2):
        return
    at = len(text[: found.start()].split())  # the token the direction starts at
    last = max((k for k, m in enumerate(mentions) if m.end <= at), default=None)

    def listed(a: int, b: int) -> bool:  # "a mug, a plate", "the first is a globe, the second is a stack of books"
        link = _link(tokens, mentions[a], mentions[b])
        return _relation(link)[0] == "list" or not set(link.split()) - _ORDER_WORDS

    if last is None:  # said first: "from left to right: a red mug, a blue mug and a green mug"
        last = first = next((k for k, m in enumerate(mentions) if m.start >= at), len(mentions))
        while last + 1 < len(mentions) and listed(last, last + 1):
            last += 1
    else:
        first = last
        while first > 0 and listed(first - 1, first):
            first -= 1
    for k in range(first + 1, last + 1):
        m = mentions[k]
        if all(x is None for x in (m.beside, m.on, m.held_by, m.around)):
            m.beside, m.side, m.region = k - 1, found.group(2), ()


def _reversed(mentions: list[Mention], tokens: list[str], k: int, link: str, lexicon: Lexicon) -> bool:
    """A relation whose words place the thing after them by the thing before ("A surrounded by B", "A flanked by
    B", "A under B"), applied; False when the link says none."""
    passive = next((where for phrase, where in PASSIVE_POSITIONS if _ends_with(link, phrase)), None)
    if passive is not None:
        _stand_by(mentions, tokens, k, passive)
        return True
    if _says_under(link):
        _carries(mentions, tokens, k, lexicon)
        return True
    return False


def _says_under(link: str) -> bool:
    """Whether a link puts the thing before it under the thing after it ("under each of", "right beneath")."""
    words = [w for w in link.split() if w not in ("each", "every", "of", "both", "all", "placed", "set", "sitting")]
    return bool(words) and words[-1] in UNDER_WORDS


def _carries(mentions: list[Mention], tokens: list[str], k: int, lexicon: Lexicon) -> None:
    """ "A under B": B rests on A. With "each" ("a saucer under each of the two teacups"), one A per B."""
    carrier, top = mentions[k], mentions[k + 1]
    for j in _list_from(mentions, tokens, k + 1):  # and the rest of B's list ("beneath a bowl and a spoon")
        _release(mentions, j)
        _rest_on_or_in(mentions, j, k, "on", lexicon)
    if "each" in tokens[carrier.end : top.end] or "every" in tokens[carrier.end : top.end]:
        carrier.count, carrier.plural = max(carrier.count, top.count), top.count > 1
        top.per = k


def _stand_by(mentions: list[Mention], tokens: list[str], k: int, where: str) -> None:
    """ "A surrounded by B", "A flanked by B": B stands around A or on both sides of it; A is mention k, or the holder
    whose contents it is ("a vase of flowers, surrounded by candles": around the vase)."""
    holder = next((h for h, o in enumerate(mentions) if k in o.contents), None)
    subject = holder if holder is not None else k
    for j in _list_from(mentions, tokens, k + 1):  # and the rest of B's list ("a fork, a knife and a spoon")
        ring = mentions[j]
        _release(mentions, j)
        if where == "around":
            ring.around = subject
        else:
            ring.beside, ring.side = subject, where


def _list_from(mentions: list[Mention], tokens: list[str], j: int) -> list[int]:
    """Mention j and the mentions listed after it, up to one with a place of its own ("... and a bowl on the left")."""
    listed = [j]
    while (
        j + 1 < len(mentions)
        and _relation(_link(tokens, mentions[j], mentions[j + 1]))[0] == "list"
        and not _placed_by_own_words(mentions, tokens, j + 1)
    ):
        j += 1
        listed.append(j)
    return listed


def _placed_by_own_words(mentions: list[Mention], tokens: list[str], j: int) -> bool:
    """Whether mention j has a place of its own ("... and a bowl on the left", "... and a jug next to the napkin")."""
    own = mentions[j].region or mentions[j].centre
    after = _relation(_link(tokens, mentions[j], mentions[j + 1]))[0] if j + 1 < len(mentions) else ""
    return bool(own) or after == "position"


def _place_region(mentions: list[Mention], tokens: list[str], k: int, lexicon: Lexicon) -> None:
    """Whose place on the support the words give: what a container holds is where the container is ("a toy bin full
    of trains in the corner"); a thing listed "with" another stands on that side of it ("a laptop with a mug on the
    left"); a thing on a carrier, or said to stand by another, keeps that relation and no place of its own."""
    m = mentions[k]
    if not m.region:
        return
    if _beside_what_it_is_listed_with(mentions, tokens, k, lexicon):
        return
    holder = next((h for h, o in enumerate(mentions) if k in o.contents), m.held_by)  # or the carrier that lists it
    if holder is not None:
        mentions[holder].region = mentions[holder].region or m.region
        m.region = ()
    elif m.on is not None or m.beside is not None or m.around is not None:
        m.region = ()


def _share_a_region(mentions: list[Mention], tokens: list[str], k: int) -> None:
    """ "the kettle and the toaster go at the back": a place on the support said after a list that ended ("and") at
    mention k is every listed thing's, as far back as they are free things with no place of their own."""
    m = mentions[k]
    if not m.region or k == 0 or not _link(tokens, mentions[k - 1], m).endswith(("and", "plus")):
        return
    if m.on is not None or m.beside is not None or m.held_by is not None or m.around is not None:
        return
    if _link(tokens, mentions[k - 1], m) not in ("and", ", and", "plus", ", plus"):
        return
    if (
        _link(tokens, mentions[k - 1], m).startswith(",")
        and k > 1
        and "and" in _link(tokens, mentions[k - 2], mentions[k - 1]).split()
    ):
        return  # "a laptop and a mouse, and a mug at the back": that list ended before
    j = k - 1
    while j >= 0:
        other = mentions[j]
        if _has_a_place(mentions, tokens, j):
            return
        other.region = m.region
        if j == 0 or _link(tokens, mentions[j - 1], other) != ",":  # only a plain list goes on
            return
        j -= 1


def _has_a_place(mentions: list[Mention], tokens: list[str], j: int) -> bool:
    """Whether mention j has a place of its own, or is named as a place ("on the left of the cushion"), or is a
    group that fills its own room ("a row of eight tins"): a place said after it for a list is not its."""
    other = mentions[j]
    if other.region or other.centre or other.on is not None or other.beside is not None or other.alias is not None:
        return True
    if other.held_by is not None or other.around is not None or any(j in o.contents for o in mentions):
        return True
    if other.count > 3 or other.arrangement:
        return True
    before = [w for w in tokens[max(0, other.start - 3) : other.start] if w not in ARTICLES]
    return bool(before[-1:]) and before[-1] in ("of", "then", *_ANCHOR_WORDS)


def _beside_what_it_is_listed_with(mentions: list[Mention], tokens: list[str], k: int, lexicon: Lexicon) -> bool:
    """ "a laptop with a mug on the left and a notebook on the right", "a plate with a fork on the left": a thing of a
    "with" list given a side stands on that side of the thing the list is with, not on the support's side; nor in or
    on it, unless it fits on that side of it (`fits_on_a_side`: "a tray with a teapot on the left" keeps the teapot
    on the tray)."""
    m = mentions[k]
    side = m.region[0] if len(m.region) == 1 and m.region[0] in SIDE_OF_REGION else None
    if "far" in tokens[m.end : m.end + 4] or _said_in_it(tokens[m.end : m.end + 2]):
        return False  # "at the far right": the support's side; "two toothbrushes in it at the far left": the holder's
    anchor = _listed_with(mentions, tokens, k) if side else None
    if side is None or anchor is None or m.beside is not None or m.around is not None:
        return False
    holder = mentions[anchor]
    if m.on not in (None, anchor) or m.held_by not in (None, anchor):
        return False
    if (m.on == anchor or m.held_by == anchor) and lexicon.fits_on_a_side(m.category, holder.category):
        m.region, m.on_side = (), SIDE_OF_REGION[side]  # in or on it, on that side of it
        return True
    if k in holder.contents:
        holder.contents.remove(k)
    m.on = m.held_by = None
    m.beside, m.side, m.region = anchor, SIDE_OF_REGION[side], ()
    return True


def _listed_with(mentions: list[Mention], tokens: list[str], k: int) -> int | None:
    """The thing whose "with" list mention k belongs to: the mention just before the list's first item."""
    j = k
    while j > 0:
        if _starts_with_with(tokens, mentions[j - 1], mentions[j]):
            return j - 1
        if _relation(_link(tokens, mentions[j - 1], mentions[j]))[0] != "list":
            return None
        j -= 1
    return None


def _starts_with_with(tokens: list[str], a: Mention, b: Mention) -> bool:
    """Whether the words between a and b are "with" (", with", "with its"): b is listed with a."""
    return _link(tokens, a, b).lstrip(", ").split()[:1] == ["with"]


def _between_two(mentions: list[Mention], tokens: list[str], k: int) -> None:
    """ "a clock between a desk lamp and a pile of books": the clock stands between two different things, the second
    set to the viewer's right of the first with room for it (the words put neither anywhere, nor the first on the
    right or the second on the left of the support). Said after a
    holder's contents ("a plate of cookies between a milk carton and a glass"), it is the holder that stands there."""
    m, first = mentions[k], k + 1
    if m.held_by is not None and m.beside is None:
        m = mentions[m.held_by]
    second = k + 2
    if second >= len(mentions) or m.beside != first or not _one_thing(mentions[first]):
        return
    if _relation(_link(tokens, mentions[first], mentions[second]))[0] != "list":
        return
    a, b = mentions[first], mentions[second]
    if any(x is not None for x in (a.beside, a.on, a.held_by, b.beside, b.on, b.held_by)):
        return
    m.second = second
    if (
        "right" not in _region_of(mentions, a)
        and "left" not in _region_of(mentions, b)
        and not _placed_by(mentions, first, second)
    ):
        b.beside, b.side = first, "right"


def _placed_by(mentions: list[Mention], j: int, k: int) -> bool:
    """Whether mention j (or the thing it names again) was placed by mention k (or the thing k names again)."""

    def root(x: int) -> int:
        alias = mentions[x].alias
        return x if alias is None else alias

    by = mentions[root(j)].beside
    return by is not None and root(by) == root(k)


def _region_of(mentions: list[Mention], m: Mention) -> tuple[str, ...]:
    """The place on the support of m, or of the thing it names again ("the books" after "a stack of books on the
    left")."""
    return m.region or (mentions[m.alias].region if m.alias is not None else ())


def _one_thing(m: Mention) -> bool:
    """One thing to stand by: a single thing, or one stack ("between a stack of books and a lamp")."""
    return m.count == 1 or (m.stacked and m.groups <= 1)


def _between_the_last_two(mentions: list[Mention], tokens: list[str], k: int) -> None:
    """ "a toaster and a kettle with a bread bin between them", "a plate on the left, a mug on the right, and between
    them a jar": between the last two things that stand on the support by themselves, the second to the viewer's
    right of the first unless the words placed it already."""
    free = [j for j in range(k) if _stands_alone(mentions, j)][-2:]
    if len(free) < 2:
        return
    if not all(_one_thing(mentions[j]) for j in free) and not _on_two_sides(*(mentions[j] for j in free)):
        return  # (a group is an anchor when the other stands on its other side: "four jars on the left, a cookie jar
    first, second = free  # on the right, and the teapot between them")
    m, b = mentions[k], mentions[second]
    m.beside, m.second = first, second
    if b.beside is None and not b.region and not mentions[first].region and not _placed_by(mentions, first, second):
        b.beside, b.side = first, "right"  # (not when the first was placed by the second: "the jar behind the tray")


def _on_two_sides(a: Mention, b: Mention) -> bool:
    """Whether two things are said to stand on the support's left and right, one on each."""
    sides = [set(m.region) & {"left", "right"} for m in (a, b)]
    return len(sides[0]) == 1 and len(sides[1]) == 1 and sides[0] != sides[1]


def _stands_alone(mentions: list[Mention], j: int) -> bool:
    m = mentions[j]
    return m.on is None and m.held_by is None and m.around is None and not any(j in o.contents for o in mentions)


def _holds(lexicon: Lexicon, holder: Mention, phrase: str) -> bool:
    """Whether `holder <phrase> X` puts X in or on the holder: always for "full of", "holding" ...; for "with" and
    "of" only when the holder is a container or a carrier ("a bowl of apples", "a tray with mugs")."""
    if phrase not in ("with", "of"):
        return True
    return bool(holder.known and lexicon.role(holder.category))


def _share_with_list(mentions: list[Mention], tokens: list[str], k: int, where: str, lexicon: Lexicon) -> None:
    """ "two pens and a highlighter inside a pen holder": the whole list before "inside" goes in (or on) it, as far
    back as the items are free and fit. Only a list that ended ("and") at the thing said in it: in "a soap
    dispenser, a toothbrush in a cup, a towel and bottles" the cup holds the toothbrush alone."""
    target = mentions[k + 1]
    if where in SIDE_WORDS or where == "between":
        _share_position(mentions, tokens, k, where)
        return
    if where in ("in", "on") and _link(tokens, mentions[k], target).startswith((", all", "all", ", everything")):
        _all_rest_there(mentions, tokens, k, where, lexicon)
        return
    if where not in ("in", "on") or not (target.known and lexicon.role(target.category)):
        return
    if k > 0 and not _link(tokens, mentions[k - 1], mentions[k]).endswith(("and", "or", "plus")):
        return
    j = k - 1
    while j >= 0 and _relation(_link(tokens, mentions[j], mentions[j + 1]))[0] == "list":
        m = mentions[j]
        if m.on is not None or m.held_by is not None or m.contents or not lexicon.fits(m.category, target.category):
            return
        if where == "on" and not lexicon.fits_on(m.category, target.category):
            return  # "a laptop and a mouse on a mouse pad": the mouse only
        if any(j in o.contents for o in mentions) or _ends_a_clause(mentions, tokens, j):
            return
        if _inventory_item(mentions, tokens, j, k):
            return  # "an egg carton, two bottles of oil, a jar of honey and three lemons in a bowl"
        _rest_on_or_in(mentions, j, k + 1, where, lexicon)
        j -= 1


def _share_position(mentions: list[Mention], tokens: list[str], k: int, where: str) -> None:
    """A side or "between" said of the last thing of a list that ended ("and") at mention k is every listed thing's."""
    if where == "between":
        _share_between(mentions, tokens, k)
    elif k > 0 and _link(tokens, mentions[k - 1], mentions[k]).endswith(("and", "plus")):
        _share_a_side(mentions, tokens, k, where)


def _share_between(mentions: list[Mention], tokens: list[str], k: int) -> None:
    """ "a spinning top and a yo-yo lying between the cushion and the toy bin": both stand between."""
    if k == 0 or _link(tokens, mentions[k - 1], mentions[k]) != "and":
        return
    other = mentions[k - 1]
    if _stands_alone(mentions, k - 1) and other.beside is None and not other.region:
        if not _ends_a_clause(mentions, tokens, k - 1):
            other.beside, other.side, other.second = mentions[k].beside, "between", mentions[k].second


def _all_rest_there(mentions: list[Mention], tokens: list[str], k: int, where: str, lexicon: Lexicon) -> None:
    """ "an egg in an egg cup, a glass of juice, a plate with toast on it and a napkin, all on the tray": every
    thing of the list before "all" that stands free rests on (or in) the thing after it; what is in or on one of
    them stays there."""
    j = k - 1
    while j >= 0 and _relation(_link(tokens, mentions[j], mentions[j + 1]))[0] in ("list", "holds", "position"):
        m = mentions[j]
        free = all(x is None for x in (m.on, m.held_by, m.beside, m.around)) and j != mentions[k + 1].alias
        if free and not any(j in o.contents for o in mentions) and lexicon.fits(m.category, mentions[k + 1].category):
            _rest_on_or_in(mentions, j, k + 1, where, lexicon)
        j -= 1


def _share_a_side(mentions: list[Mention], tokens: list[str], k: int, where: str) -> None:
    """ "a knife and a spoon to the right of the plate": both stand there. Back over the list that ended ("and") at
    mention k, as far as its things are free and are not what they are said to stand by."""
    m = mentions[k]
    if m.beside is None or m.side != where or m.held_by is not None:
        return
    target = m.beside
    anchor = mentions[target].alias if mentions[target].alias is not None else target
    j, stop = k - 1, m.start
    while j >= 0 and _relation(_link(tokens, mentions[j], mentions[j + 1]))[0] == "list":
        if j < k - 1 and "and" in _link(tokens, mentions[j], mentions[j + 1]).split():
            return  # "a laptop and a mouse, and a mug to the left of the laptop": that list ended before
        if j == k - 1 and _link(tokens, mentions[j], mentions[k]).startswith(",") and j > 0:
            if "and" in _link(tokens, mentions[j - 1], mentions[j]).split():
                return
        other = mentions[j]
        if j in (target, anchor) or other.alias in (target, anchor) or _placed_already(mentions, tokens, j, k, stop):
            return
        link = _link(tokens, other, mentions[j + 1])
        own = _own_side(link)
        if own is None and re.sub(r"(?:\s*(?:,|and|plus|or))+$", "", link):
            return  # "two pens lie around, and the stapler sits in front of ...": the pens have words of their own
        other.beside, other.side = target, own or where
        stop = other.start
        j -= 1


def _inventory_item(mentions: list[Mention], tokens: list[str], j: int, k: int) -> bool:
    """Whether mention j, listed before mention k with a comma, is an item of a long list of the scene's things (two
    commas or more) and not of k's kind: a place said of the last item is that item's only ("a sugar bowl, and a jar
    of beans behind the press"); of one kind, it is the group's ("a knife, a fork, and a spoon to the right")."""
    if "," not in tokens[mentions[j].end : mentions[j + 1].start]:
        return False
    commas, i = 0, k
    while i > 0 and _relation(_link(tokens, mentions[i - 1], mentions[i]))[0] == "list":
        commas += "," in tokens[mentions[i - 1].end : mentions[i].start]
        i -= 1
        if mentions[i].region or any(x is not None for x in (mentions[i].on, mentions[i].beside, mentions[i].held_by)):
            break  # "a tool bag at the back, and a hammer, a saw and a level in front of it": the list starts after
    return commas >= 2 and not _of_one_kind(mentions[j].category, mentions[k].category)


def _of_one_kind(a: str, b: str) -> bool:
    """Whether two categories are one, or kinds of one collective ("a knife" and "a fork" are cutlery)."""
    return a == b or any({a, b} <= set(kinds) for kinds in COLLECTIVES.values())


def _placed_already(mentions: list[Mention], tokens: list[str], j: int, k: int, stop: int) -> bool:
    """Whether listed mention j has a place of its own (or is an item of the scene's long list) and so does not share
    the side said of mention k; `stop`: where the words said after it end."""
    other = mentions[j]
    aside = j > 0 and _link(tokens, mentions[j - 1], other).startswith(", with") and other.held_by is None
    if (_ends_a_clause(mentions, tokens, j) and not aside) or other.contents or any(j in o.contents for o in mentions):
        return True  # (", with a salt shaker and a pepper mill to its right": an aside, held by nothing)
    if any(x is not None for x in (other.on, other.held_by, other.beside, other.around)):
        return True
    if {"it", "its", "them", "their"} & set(tokens[other.end : stop]):
        return True  # "a cup to its right and a sugar bowl to its left, and a spoon in front of the cup"
    return _inventory_item(mentions, tokens, j, k)  # "a french press, a sugar bowl, and a jar behind the press"


_OWN_SIDE = re.compile(r"^(?:\w+ )?(?:(?:to|on|at|in) (left|right|front|back)(?: side)?|(behind))(?: ,)? (?:and|plus)$")


def _own_side(link: str) -> str | None:
    """ "a mug to the left and a glass to the right of the jug": the mug's own side, of the same jug."""
    said = _OWN_SIDE.match(link)
    if said is None:
        return None
    return SIDE_OF_REGION[said.group(1)] if said.group(1) else "behind"


def _ends_a_clause(mentions: list[Mention], tokens: list[str], j: int) -> bool:
    """Whether mention j closes a relation of its own ("a laptop on a laptop stand, and a mouse on a mouse pad": the
    stand ends the first clause, so the second clause's "on" is not shared with it)."""
    return j > 0 and _relation(_link(tokens, mentions[j - 1], mentions[j]))[0] in ("position", "holds")


def _one_per_thing(mentions: list[Mention], k: int) -> None:
    """ "four glasses, each on its own coaster": a coaster per glass; "a mug, a glass and a cup, each on its own
    coaster" ("an apple, a pear and a peach, each in its own bowl"): one per thing of the list that shares the
    target."""
    mentions[k].per = k + 1
    for j in range(k):
        if (mentions[j].on == k + 1 or j in mentions[k + 1].contents) and mentions[j].per is None:
            mentions[j].per = k + 1


def _distributive(mentions: list[Mention], tokens: list[str], k: int) -> bool:
    """ "glasses, each on its own coaster", "every mug on a saucer": one target per thing."""
    m = mentions[k]
    link = tokens[m.end : mentions[k + 1].start]
    listed = any(o.on == k + 1 or j in mentions[k + 1].contents for j, o in enumerate(mentions[:k]))  # a list before
    return (m.count > 1 or m.alias is not None or listed) and (
        bool({"each", "own", "apiece"} & set(link)) or tokens[m.start] in ("each", "every")
    )


def _take_listed(
    mentions: list[Mention], tokens: list[str], k: int, lexicon: Lexicon, detail: str, h: int | None = None
) -> int:
    """Put the list after mention k ("apples, pears and plums") in or on it (or on mention `h`, what the words are
    said of); the index after the list: the list ends at a clause boundary (a position phrase, a thing too big for
    the holder) and, after a plain "of", at "and a ..." ("a bowl of apples and a mug")."""
    h = k if h is None else h
    j = k + 1
    closed = _said_back(mentions, tokens, k) is not None
    holder = mentions[h]
    named = mentions[holder.alias] if holder.alias is not None else holder  # "four mugs, and each mug holds"
    each = "each" in tokens[mentions[k].end : mentions[j].start] or tokens[holder.start] in ("each", "every")
    while True:
        _hold(mentions, h, j, lexicon)
        if each and _instances(named) > 1:  # "two plates, each with a sandwich"
            mentions[j].per, mentions[j].count = h, mentions[j].count * _instances(named)
        elif holder.count > 1 and not holder.stacked:  # a stack's items go on its top, not on each level
            mentions[j].per = h  # "two baskets of apples": the apples go into both
        last = j
        if detail != "of" and (end := _end_of_own_contents(mentions, tokens, j, lexicon)) > j:
            own = _relation(_link(tokens, mentions[j], mentions[j + 1]))[1]  # "of", or "with ... on it"
            _take_listed(mentions, tokens, j, lexicon, own)  # "a tray with a plate of toast, a cup ...": the
            last = end  # toast is the plate's, and the tray's list goes on after it
        elif _rests_on_the_next(mentions, tokens, j, lexicon):
            _hold(mentions, h, j + 1, lexicon)  # "the tray carries a cup on a saucer and a spoon": the saucer and
            _rest_on_or_in(mentions, j, j + 1, _link(tokens, mentions[j], mentions[j + 1])[:2], lexicon)  # the
            last = j + 1  # spoon are the tray's too
        if last + 1 >= len(mentions) or _relation(_link(tokens, mentions[last], mentions[last + 1]))[0] != "list":
            return last
        glue = _link(tokens, mentions[last], mentions[last + 1]).split()
        if set(glue) & _CLAUSE_WORDS and not _said_in_it(glue):
            return last  # "a bowl of grapes is behind it, and two mugs": a clause of its own ended the list
        if _list_ends_after(mentions, tokens, h, last, closed, detail, lexicon):
            return last + 1
        j = last + 1


def _rests_on_the_next(mentions: list[Mention], tokens: list[str], j: int, lexicon: Lexicon) -> bool:
    """Whether listed mention j is said to rest on (or in) the next one, a small holder that goes where j goes ("a
    cup on a saucer"), with the list going on after that holder."""
    if j + 2 >= len(mentions):
        return False
    link = " ".join(_posture_dropped(_link(tokens, mentions[j], mentions[j + 1]).split() + ["_"])[:-1])
    if link not in ("on", "in", "on top of"):  # "a cup on a saucer", "two teacups sitting on their saucers"
        return False
    below = mentions[j + 1]
    if not below.known or (below.count != 1 and not below.plural) or lexicon.role(below.category) == "":
        return False
    return _relation(_link(tokens, below, mentions[j + 2]))[0] == "list"


# verbs that say where a thing is ("a jar sits in front of the tray")
_PLACE_VERBS = {"sits", "sit", "stands", "stand", "is", "are", "lies", "lie", "rests", "rest", "goes", "go"}
# words that make the words after a listed thing a clause of its own ("is behind it"), not more of the list
_CLAUSE_WORDS = _PLACE_VERBS | {"it", "them"}


def _said_of(mentions: list[Mention], tokens: list[str], k: int, detail: str, lexicon: Lexicon) -> int:
    """The mention a "with" after mention k is said of: k, or the thing just said to stand by k when only that one
    can hold what the list says is on (or in) it ("a cutting board to the right of the wok with a knife on it": the
    board; "a mug next to a tray with two cups": the tray)."""
    said = _said_back(mentions, tokens, k) if detail == "with" else None
    return _by_role(mentions, k, said[1] if said is not None else detail, lexicon)


def _by_role(mentions: list[Mention], j: int, where: str, lexicon: Lexicon) -> int:
    """Mention j, or the thing said to stand by j when only that one can hold things `where` ("on": a carrier, "in":
    a container, "with": either)."""
    if j > 0 and mentions[j - 1].beside == j and mentions[j - 1].side in SIDE_WORDS:
        by = j - 1
    elif j > 1 and mentions[j - 2].second == j:  # "a tray between the juicer and the cans with two glasses on it"
        by = j - 2
    else:
        return j
    role, other = lexicon.role(mentions[by].category), lexicon.role(mentions[j].category)
    if where in ("on", "in") and role == {"on": "carrier", "in": "container"}[where] != other:
        return by
    if where == "with" and role and not other:  # "a toothbrush holder to the left of the dispenser with two
        return by  # toothbrushes": the holder's
    return j


def _list_ends_after(
    mentions: list[Mention], tokens: list[str], k: int, last: int, closed: bool, detail: str, lexicon: Lexicon
) -> bool:
    """Whether holder k's list ends with mention `last` (the next mention, listed after it, is not held)."""
    nxt = mentions[last + 1]
    between = tokens[mentions[last].end : nxt.start]
    nested = mentions[last].held_by not in (None, k)  # "a tray with a plate with toast on it, a mug": the plate's
    if _said_apart(tokens, between, nxt, nested):
        return True
    if not closed and any(w in " ".join(between) for w in RIM_WORDS):
        return True  # "a bowl with chopsticks across its rim, a spoon and a dish": the rim closes the list
    if not closed and _list_ended_before(tokens, mentions[k].end, mentions[last].end, nxt.start):
        return True  # "a tray holding a teapot and two cups, and a vase": the list had its "and"
    if not closed and tokens[nxt.start] in ("a", "an") and nxt.count == 1 and detail == "of":
        return True  # "a bowl of apples and a mug": the mug is a new object, not a content
    if mentions[k].region and nxt.region and nxt.region != mentions[k].region:
        return True  # "a plate on the left with toast, a mug on the right": another part of the support
    if not closed and "," in between and _listed_between_commas(mentions, tokens, k, nxt):
        return True  # "two mugs, a mug holding three pens, a stapler and a pad": the stapler is the scene's
    if nxt.known and nxt.category == mentions[k].category and tokens[nxt.start] in ("a", "an", "another"):
        return True  # "a basket with apples and a basket with pears": another holder, not a content
    same = {k, mentions[k].alias} - {None}
    if last + 2 < len(mentions) and same & {last + 2, mentions[last + 2].alias}:
        kind, where = _relation(_link(tokens, nxt, mentions[last + 2]))
        if kind == "position" and where not in ("in", "on"):
            return True  # "... and a spoon. Next to the tray there is a teapot": beside the holder, not on it
    return not lexicon.fits(nxt.category, mentions[k].category) and nxt.known  # "cups and a lamp": the lamp stands


def _said_apart(tokens: list[str], between: list[str], nxt: Mention, nested: bool) -> bool:
    """Whether the next listed thing is said apart from the holder's list: after a place on the support ("a basket of
    eggs on the left of the counter and the bread box"), or with a verb of its own ("a tray holding four mugs, and a
    jar of sugar cubes sits in front of the tray"), or after "in it" ("a pot with a ladle in it on the counter, and a
    kettle")."""
    if not nested and (_said_in_it(between) or _places_the_holder(between)):
        return True
    return between[-2:] == [",", "and"] and _has_its_own_verb(tokens, nxt)


def _has_its_own_verb(tokens: list[str], m: Mention) -> bool:
    """Whether a verb of place follows mention m (after what it is "of") before the next comma or "and": the thing
    starts a clause of its own ("and a jar of sugar cubes sits in front of the tray")."""
    for w in tokens[m.end : m.end + 6]:
        if w in (",", "and", "with"):
            return False
        if w in _PLACE_VERBS:
            return True
    return False


def _places_the_holder(between: list[str]) -> bool:
    """Whether the words after a listed thing give a place on the support ("on the left side of the counter", "at
    the left end"): said of the holder, they end its list. A place on the holder ("a plate with a fork on the left")
    names no support and no end."""
    region = _read_region(" ".join(between))
    return bool(region) and bool(set(between) & (SUPPORT_WORDS | {"end", "ends"}))


def _end_of_own_contents(mentions: list[Mention], tokens: list[str], j: int, lexicon: Lexicon) -> int:
    """The last mention of what mention j holds by "of" ("a plate of toast", "a basket of apples and pears") or by a
    "with" list said back "on it" ("a plate with two eggs on it"), as `_take_listed` reads it; j when it holds
    nothing so."""
    if j + 1 >= len(mentions):
        return j
    relation = _relation(_link(tokens, mentions[j], mentions[j + 1]))
    holder = lexicon.role(mentions[j].category) != ""  # "a plate with two eggs on it"; not "oranges with a lemon"
    if holder and relation == ("holds", "with") and (said := _said_back(mentions, tokens, j)) is not None:
        return said[0]
    if relation != ("holds", "of"):
        return j
    if not _holds(lexicon, mentions[j], "of"):
        return j
    end = j + 1
    while end + 1 < len(mentions) and _relation(_link(tokens, mentions[end], mentions[end + 1]))[0] == "list":
        nxt = mentions[end + 1]
        if tokens[nxt.start] in ("a", "an") and nxt.count == 1:
            break
        end += 1
    return end


OF = ("holds", "of")  # a link that names what a thing is of ("a bowl of grapes")


def _list_stands_aside(mentions: list[Mention], tokens: list[str], k: int) -> bool:
    """Whether the list after mention k ends in "nearby", "beside ..." or another position that is not in or on
    (", with a stapler and a roll of tape nearby": beside it, not in it). A listed thing's own contents are part of
    it (", with a bowl of grapes in front of the bottle": the bowl stands in front; it is not in the glasses)."""
    j = k + 1
    while j + 1 < len(mentions) and _relation(_link(tokens, mentions[j], mentions[j + 1])) in (("list", ""), OF):
        j += 1
    after = " ".join(_posture_dropped(tokens[mentions[j].end : mentions[j].end + 5])[:4])  # "standing between"
    if after.startswith(("nearby", "close by", "alongside", "to the side", "aside")):
        return True
    if re.match(r"(?:to|on|at) (?:its|their) (?:left|right|side|front|back)\b", after):
        return True  # ", with the salt shaker to its right": beside the one the list is said of
    if j + 1 < len(mentions):  # ", with a sugar bowl to the right of the tray": the words up to the next thing
        kind, where = _relation(_link(tokens, mentions[j], mentions[j + 1]))
        if kind == "position" and where not in ("in", "on"):
            return True
    return any(after.startswith(phrase) and where not in ("in", "on") for phrase, where in POSITIONS)


def _list_ended_before(tokens: list[str], start: int, end: int, nxt: int) -> bool:
    """Whether a list that already had its last "and" (between `start` and `end`) goes on with ", and" at `end`."""
    return "and" in tokens[start:end] and tokens[end:nxt][:2] == [",", "and"]


_POSTURES = {"lying", "sitting", "resting", "standing", "placed", "laid", "set", "stacked", "propped", "leaning"}


def _posture_dropped(after: list[str]) -> list[str]:
    """The words after a thing without a posture before its place ("lying on it": "on it")."""
    return after[1:] if len(after) > 2 and after[0] in _POSTURES else after


def _said_in_it(after: list[str]) -> bool:
    """Whether the words after a listed thing put it "inside", "in it" or "on it" (back in its holder), "lying on it"
    as well."""
    after = _posture_dropped(after)
    return after[:1] in (["inside"], ["in"], ["on"]) and (
        len(after) == 1 or after[1] in PRONOUNS | {",", "top", "each"}
    )


def _listed_between_commas(mentions: list[Mention], tokens: list[str], k: int, nxt: Mention) -> bool:
    """Whether holder k is itself an item of a comma-separated list and `nxt`, with its own article, is the next
    item of that list rather than more of what k holds (a thing of the same kind as k's first content is more)."""
    if k == 0 or tokens[mentions[k - 1].end : mentions[k].start] != [","] or tokens[nxt.start] not in ("a", "an"):
        return False
    return not _of_one_kind(mentions[k + 1].category, nxt.category)


def _said_back(mentions: list[Mention], tokens: list[str], k: int) -> tuple[int, str] | None:
    """Where the list after mention k is said back "in it" / "inside" or "on it" (so every item belongs to k): the
    last item's index and "in" or "on"; None when the list ends otherwise."""
    for j in range(k + 1, len(mentions)):
        after = tokens[mentions[j].end : mentions[j + 1].start if j + 1 < len(mentions) else len(tokens)]
        if _said_in_it(after):
            return j, "on" if _posture_dropped(after)[0] == "on" else "in"
        if j + 1 >= len(mentions) or _relation(_link(tokens, mentions[j], mentions[j + 1]))[0] != "list":
            return None
    return None


def _hold(mentions: list[Mention], holder: int, item: int, lexicon: Lexicon) -> None:
    m = mentions[item]
    m.held_by = holder
    if lexicon.role(mentions[holder].category) == "carrier" and mentions[holder].known:
        m.on = holder
    elif item not in mentions[holder].contents:
        mentions[holder].contents.append(item)


def _position(mentions: list[Mention], k: int, where: str, lexicon: Lexicon) -> None:
    """Mention k stands `where` relative to mention k + 1 (for a held item, its holder does)."""
    m, target = mentions[k], k + 1
    if where in ("in", "on"):
        _rest_on_or_in(mentions, k, target, where, lexicon)
    elif where == "around":
        _release(mentions, k)  # "a bowl with apples placed around the bowl": around it, not in it
        m.around = target
    elif m.held_by is not None and m.held_by in (target, mentions[target].alias):  # "a tray with glasses on it
        holder = m.held_by
        _release(mentions, k)  # and a mug to the left of the tray": beside the tray, not on it
        m.beside, m.side = holder, where
    elif _on_the_same_carrier(mentions, k, target) and where in SIDE_WORDS:
        m.beside, m.side = target, where  # "a tray with a bowl, a glass and a spoon to the right of the bowl"
    else:
        subject = m.held_by if m.held_by is not None else k
        if mentions[subject].beside is None:
            mentions[subject].beside, mentions[subject].side = target, where


SIDE_WORDS = ("left", "right", "front", "behind", "beside")


def _on_the_same_carrier(mentions: list[Mention], k: int, target: int) -> bool:
    """Whether mention k lies on a carrier that also carries the target (or what the target names again): a side
    said between two things on one tray places them on it, side by side, and does not move the tray."""
    carrier = mentions[k].on
    other = mentions[target]
    anchor = mentions[other.alias] if other.alias is not None else other
    return carrier is not None and mentions[k].held_by == carrier and anchor.on == carrier


def _rest_on_or_in(mentions: list[Mention], k: int, target: int, where: str, lexicon: Lexicon) -> None:
    m, t = mentions[k], mentions[target]
    role = lexicon.role(t.category) if t.known else ""
    holder = m.held_by
    if holder is not None:  # "a tray with two cups on saucers": the saucers take the cups' place on the tray
        if k in mentions[holder].contents:
            mentions[holder].contents.remove(k)
        if t.held_by is None and t.on is None:
            _hold(mentions, holder, target, lexicon)
        m.held_by = None
    if where == "in" and role == "container":
        if k not in t.contents:
            t.contents.append(k)
        m.on = None
    elif where == "on" or role == "carrier":
        m.on = target
        if m.plural and t.plural:
            m.per = target  # "sandwiches on plates", "cups on saucers"


_ARRANGED = re.compile(
    r"^(?:(?:arranged|placed|set|lined up|standing|grouped) )?(?:in an? (?:neat |tight |loose |small )?"
    r"(?:semicircle|circle|row|line|cluster|group|column) |side by side )"
    r"|^, one (?:nested |stacked |sitting |resting )?(?:inside|in|on top of|atop) (?:(?:the )?other|another) , "
)


_SIDE_OF_IT = re.compile(r"(?:(?:to|on|at) (?:its|their)|(further|farther)(?: to)?) (left|right)\b")


def _pronoun_relation(mentions: list[Mention], tokens: list[str], k: int, lexicon: Lexicon, words: WordClasses) -> None:
    """ "with a pen on it", "with four cups beside it", "two coasters, a glass on each", "a mug stands to its
    right": the relation's target is what the clause is about."""
    m = mentions[k]
    stop = mentions[k + 1].start if k + 1 < len(mentions) else len(tokens)
    after = _posture_dropped(_verbs_dropped([w for w in tokens[m.end : stop] if w not in ("the",)], words))
    text = _ARRANGED.sub("", " ".join(after))  # "four cups in a semicircle in front of it": in front of it
    text = re.sub(r"^on top(?= ,| and|$)", "on it", text)  # "each has an eraser on top": on it
    text = re.sub(r"\b(?:each|every) one\b", "each", text)  # "in each one goes a toy robot"
    side = _SIDE_OF_IT.match(text)  # "a mouse to its right", "a mug further right"
    if _ends_or_under_it(mentions, tokens, k, text, lexicon):
        return
    for phrase, where in POSITIONS:
        if where == "around" or (side and where != side.group(2)):
            continue
        bare = where in ("in", "on") and text == phrase and tokens[stop : stop + 1] in ([], [","], ["and"])
        if side or re.match(rf"{phrase} (?:it|them|each(?= ,| and|$))\b", text) or bare:  # "a glass on each"
            referent = _whose_side(mentions, tokens, k, side, where)
            if referent is None:
                said = _says_it(text)
                referent = _referent(mentions, tokens, k, where, lexicon, one=said is True, them=said is False)
            if referent is None or referent == k:
                return
            _relate_to_it(mentions, tokens, k, referent, where, lexicon)
            return


def _relate_to_it(
    mentions: list[Mention], tokens: list[str], k: int, referent: int, where: str, lexicon: Lexicon
) -> None:
    """Mention k stands `where` relative to what "it" refers to: in or on it (and the list before k, one in each),
    or beside it; a thing said "of" its holder ("a bowl of grapes is behind it") leaves the place to the holder."""
    m = mentions[k]
    if where in ("in", "on"):
        if m.held_by != referent and m.on != referent:
            _rest_on_or_in(mentions, k, referent, where, lexicon)
        _list_rests_there(mentions, tokens, k, referent, where, lexicon)
        _one_each(mentions, tokens, k, referent)  # "each of the four glasses has a straw in it"
    elif (holder := _holder_by_of(mentions, tokens, k)) is not None:  # the bowl stands there, the grapes stay in it
        by = _referent(mentions, tokens, holder, where, lexicon)
        if by is not None and by != holder and mentions[holder].beside is None:
            _stand_by_it(mentions, tokens, holder, by, where)
    elif (
        m.on is not None and m.on > k and "," in tokens[m.end : mentions[m.on].start] and _free_carrier(mentions, m.on)
    ):
        _stand_by_it(mentions, tokens, m.on, referent, where)  # "a mouse to the right of it, on a mouse pad": the pad
    elif m.beside is None:
        _stand_by_it(mentions, tokens, k, referent, where)


def _free_carrier(mentions: list[Mention], j: int) -> bool:
    c = mentions[j]
    return c.beside is None and not c.region and c.on is None and c.held_by is None and not c.centre


def _holder_by_of(mentions: list[Mention], tokens: list[str], k: int) -> int | None:
    """The holder mention k is said to be "of" ("a bowl of grapes", "a plate of biscuits"), or None."""
    if k == 0 or _link(tokens, mentions[k - 1], mentions[k]) != "of":
        return None
    held = mentions[k].held_by == k - 1 or k in mentions[k - 1].contents
    return k - 1 if held else None


def _verbs_dropped(after: list[str], words: WordClasses) -> list[str]:
    """The words after a thing without the verb that starts them: "(which) stands to its right", "is placed behind
    it"; not a verb that is the relation ("flanking it")."""
    if len(after) > 1 and after[0] in ("which", "that", "who") and after[1] in words.verbs:
        after = after[1:]  # "a mug which sits to its left"
    while after and after[0] in words.verbs and after[0] not in (*words.nouns, *PASSIVE_WORDS, *_POSITION_WORDS):
        after = after[1:]
    return after


def _stand_by_it(mentions: list[Mention], tokens: list[str], k: int, referent: int, where: str) -> None:
    """ "a desk lamp with a mug beside it": beside, not on or in; "with a bread bin between them": between the two
    things named; "a knife and a spoon on its right": the whole list."""
    _release(mentions, k)
    mentions[k].beside, mentions[k].side = referent, where
    if where == "between":
        _between_the_last_two(mentions, tokens, k)
        return
    _one_each(mentions, tokens, k, referent)
    _share_a_side(mentions, tokens, k, where)


def _whose_side(
    mentions: list[Mention], tokens: list[str], k: int, side: re.Match[str] | None, where: str
) -> int | None:
    """The thing a side said with "its", "it" or "further" is of, when not what "it" is: "a mouse to the right and a
    mug further right": the mouse; "on its left a mug, on its right a phone", "two cups sit in front of it and a
    sugar bowl sits behind it": what the thing before stands by."""
    if side is not None and side.group(1) and k > 0:
        return k - 1
    if side is None and where not in SIDE_WORDS:
        return None
    if side is not None and (across := _across_from(mentions, tokens, k, side.group(2))) is not None:
        return across
    return _same_its(mentions, tokens, k)


def _across_from(mentions: list[Mention], tokens: list[str], k: int, side: str) -> int | None:
    """ "a fork to the left of the plate and a knife to its right", "a glass lies to the multimeter's left, and
    tweezers and a screwdriver to its right": a side said with "its" after the opposite side of a thing is of that
    thing (over the list that ends at mention k)."""
    j = k
    while j > 0 and _link(tokens, mentions[j - 1], mentions[j]) in ("and", ","):
        j -= 1
    if j == 0:
        return None
    before = mentions[j - 1]
    if before.beside is not None and before.side == OPPOSITE_SIDE.get(side):
        return before.beside
    if j > 1 and mentions[j - 2].beside == j - 1 and mentions[j - 2].side == OPPOSITE_SIDE.get(side):
        return j - 1  # "a glass to the left of the multimeter, and tweezers to its right": the multimeter
    return None


def _same_its(mentions: list[Mention], tokens: list[str], k: int) -> int | None:
    """ "on its left a mug, on its right a phone": a side said with "its" right after another one is of the same
    thing, not of the mug."""
    if k == 0 or mentions[k - 1].beside is None:
        return None
    before = " ".join(tokens[mentions[k - 1].end : mentions[k].start])
    said_its = re.match(r"(?:\w+ )?(?:(?:to|on|at) (?:its|their) (?:left|right)|[a-z ]+ (?:it|them))\b", before)
    return mentions[k - 1].beside if said_its and mentions[k - 1].side != "between" else None


def _ends_or_under_it(mentions: list[Mention], tokens: list[str], k: int, text: str, lexicon: Lexicon) -> bool:
    """ "with a cup on either side": at both ends of what the clause is about; "with a plate underneath it": that
    rests on mention k. True when `text` (the words after mention k) said either."""
    m = mentions[k]
    ends = re.match(r"(?:\w+ )?(?:on|at|to) (?:each|either|both) (side|end)s?$", text)  # "a cup on either side"
    under = re.match(rf"(?:right |just )?(?:{'|'.join(UNDER_WORDS)}) (?:it|them|each(?= ,| and|$))\b", text)
    if ends is None and under is None:
        return False
    if ends is not None and m.beside is not None:
        return True  # already beside something: the words said no more
    referent = _referent(mentions, tokens, k)
    if referent is None or referent == k:
        return True
    _release(mentions, k)
    if ends:
        m.beside, m.side = referent, f"{ends.group(1)}s"
    elif under is not None:
        _release(mentions, referent)
        _rest_on_or_in(mentions, referent, k, "on", lexicon)
        top = mentions[referent]
        if under.group(0).endswith("each") and top.count > 1:  # "two cups with a saucer under each": one per cup
            m.count, m.plural, m.explicit_count, top.per = max(m.count, top.count), True, True, k
    return True


def _list_rests_there(
    mentions: list[Mention], tokens: list[str], k: int, referent: int, where: str, lexicon: Lexicon
) -> None:
    """ "with a phone and a pair of earbuds on top of it": the whole list before the relation rests there."""
    j = k - 1
    while j > referent and _relation(_link(tokens, mentions[j], mentions[j + 1]))[0] == "list":
        if any(x is not None for x in (mentions[j].on, mentions[j].held_by, mentions[j].beside)):
            break
        _rest_on_or_in(mentions, j, referent, where, lexicon)
        j -= 1


def _one_each(mentions: list[Mention], tokens: list[str], k: int, referent: int) -> None:
    """ "two laptops, each with a mouse next to it": one per laptop."""
    m, target = mentions[k], mentions[referent]
    between = tokens[target.end : m.start]
    if k > 0 and mentions[k - 1].held_by == referent:  # "two cups, each holding an egg, and a toaster behind them":
        between = tokens[mentions[k - 1].end : m.start]  # the "each" was the eggs'
    each = "each" in between or tokens[target.start] in ("each", "every")
    named = mentions[target.alias] if target.alias is not None else target  # "five plates, and every plate has"
    if m.per is None and _instances(named) > 1 and each:
        m.per, m.count = referent, m.count * _instances(named)


def _instances(m: Mention) -> int:
    """How many things a thing said "each" of stands for: its objects, or its stacks ("two stacks of plates with a
    bowl on top of each stack": two bowls, one on each stack's top)."""
    if m.arrangement == "stack":
        return max(1, m.groups, len(m.sizes))
    return m.count


def _release(mentions: list[Mention], k: int) -> None:
    """Take mention k off the holder whose list named it."""
    m = mentions[k]
    if m.held_by is None:
        return
    holder = mentions[m.held_by]
    if k in holder.contents:
        holder.contents.remove(k)
    if m.on == m.held_by:
        m.on = None
    m.held_by = None


def _says_it(text: str) -> bool | None:
    """Whether the pronoun of a place said after a thing is "it" or "its" (one thing: True) or "them" or "their"
    (several: False); None: neither."""
    found = re.search(r"\b(it|its|them|their)\b", text[:40])
    return None if found is None else found.group(1) in ("it", "its")


def _referent(
    mentions: list[Mention],
    tokens: list[str],
    k: int,
    where: str = "on",
    lexicon: Lexicon | None = None,
    one: bool = False,
    them: bool = False,
) -> int | None:
    """What "it" refers to after mention k (`where` it puts k): the holder it was listed with, the mention before a
    "with" (or the thing said to stand by that one, when only it can hold k: "a plate in front of the toaster with
    toast on it"), or the mention before it."""
    if mentions[k].held_by is not None:
        return mentions[k].held_by
    for j in range(k - 1, -1, -1):
        glue = tokens[mentions[j].end : mentions[j + 1].start]
        if "with" in glue:
            if lexicon is not None and (by := _by_role(mentions, j, where, lexicon)) != j:
                return by
            holder = mentions[j].held_by
            while holder is not None and holder != j:  # "a pot holding a ladle, with a lid beside it": the pot
                j, holder = holder, mentions[holder].held_by
            if where in SIDE_WORDS and glue[:2] == [",", "with"] and j > 0 and mentions[j - 1].beside == j:
                return j - 1  # "the butter dish behind the basket, with the salt shaker to its right": the dish
            return j
    if where in ("in", "on") and "with" in tokens[: mentions[0].start]:  # "a desk with a lamp, a mug and a pen on
        return None  # it": the support; "a desk with a monitor and a keyboard in front of it": the monitor
    if k > 0 and (where in SIDE_WORDS or where == "between") and mentions[k - 1].held_by is not None:
        return mentions[k - 1].held_by  # "two egg cups, each holding an egg, and a toaster behind them": the cups
    return _named_before(mentions, tokens, k, one, them)


def _named_before(mentions: list[Mention], tokens: list[str], k: int, one: bool, them: bool) -> int | None:
    """The thing named before mention k (before the list k ends, when a plural verb follows it), not what rests on k
    itself; "it" is one thing and "them" several."""
    j = k
    if tokens[mentions[k].end : mentions[k].end + 1] in (["are"], ["sit"], ["stand"], ["lie"], ["go"]):
        while j > 0 and _link(tokens, mentions[j - 1], mentions[j]) in ("and", ",", ", and"):
            j -= 1  # "a ruler and two pencils are to the right of it": of what was named before the list
    j -= 1
    while j >= 0 and (k in (mentions[j].on, mentions[j].held_by) or j in mentions[k].contents):
        j -= 1  # "two slices of bread are on a plate in front of it": not the plate's own bread
    if one and j > 0 and _several(mentions[j]) and not _several(mentions[j - 1]) and j in _anchors(mentions[j - 1]):
        j -= 1  # "the teapot between the two plates, and the milk jug behind it": the teapot
    elif them and j >= 0 and not _several(mentions[j]) and (by := mentions[j].beside) is not None:
        if _several(mentions[by]):  # "a pencil case between two books; a ruler in front of them"
            j = by
    return j if j >= 0 else None


def _anchors(m: Mention) -> tuple[int | None, ...]:
    return (m.beside, m.second, m.on, m.held_by)


def _several(m: Mention) -> bool:
    """Whether mention m names several things ("them"), not one thing or one stack ("it")."""
    return m.count > 1 and not m.stacked and not m.collective


def _link_rims_and_rings(mentions: list[Mention], tokens: list[str], k: int, m: Mention) -> None:
    """ "a spoon across its rim" rests on the last container before it; "chairs around it" ring the last centred or
    free-standing mention before them."""
    after = " ".join(tokens[m.end : m.end + 5])
    if any(w in after for w in RIM_WORDS):
        holder = _last_before(mentions, k, lambda o: bool(o.contents) or o.category in ("bowl", "cup", "mug", "pot"))
        if holder is not None:
            m.on = holder
    if "around it" in after or "around them" in after:
        _release(mentions, k)
        m.around = _last_before(mentions, k, lambda o: (o.centre or o.on is None) and o.held_by is None)


def _last_before(mentions: list[Mention], k: int, wanted: Callable[[Mention], bool]) -> int | None:
    """The index of the nearest mention before k that is `wanted`."""
    return next((j for j in range(k - 1, -1, -1) if wanted(mentions[j])), None)


# -- the whole sentence ---------------------------------------------------------------------------------------------
# A place said before what stands there ("to the left of the plate, a fork"; "behind the monitor sits a lamp"): the
# side words, what they are said of, and the words that end them (a comma, a colon or a verb of standing).
_SIDE_PLACE = (
    r"(?:to|on|at)\s+(?:the\s+|its\s+|their\s+)?(?:far\s+|very\s+)?(?:left|right)(?:(?:[\s-]+hand)?\s+side)?"
    r"|in\s+front|in\s+back"
)
_REF = (  # what a fronted place is of; it ends on a word that can end a noun ("in each of the three bowls")
    r"(?:the|a|an|its|their|my|your|this|that|each|every)\s+[a-z][a-z\s'-]*?"
    r"(?<! and)(?<! or)(?<! of)(?<! the)(?<! a)(?<! an)(?<! on)(?<! in)(?<! at)(?<! to)(?<! by)(?<! with)|it|them"
)
# the verb after a fronted place and its comma: "between the lamp and the clock, place a photo"
_THERE = r"there\s+is|there\s+are|there's|there're"
_PUT = (
    r"(?:please\s+)?(?:place|put|set|add|lay|stand|sits?|stands?|lies|lie|rests?|is|are|leave|keep|stack|pile|hang"
    rf"|arrange|position|goes|go|{_THERE})"
)
# a place on the support said first: "at the back of the desk", "along the front edge", "at the far end of the shelf"
_SUPPORT_PLACE = (
    r"(?:at|along|on|in|by|against|across|near|towards?)\s+(?:the|one)\s+(?:far\s+|very\s+|other\s+)?"
    r"(?:(?:front|back|rear|left|right|near|far)(?:[\s-]+hand)?(?:\s+(?:left|right))?"
    r"(?:\s+(?:edge|side|end|half|part|corner|wall|row))?|end|edge|corner|wall)"
    rf"(?P<support>\s+of\s+(?:the|this|my|our)\s+(?:[a-z]+\s+)?(?:{'|'.join(sorted(SUPPORT_WORDS))}))?"
)
_WANT = r"(?:i|we)\s+(?:want|need|have|keep|put|place|would\s+like|'d\s+like|like)"  # "... I want four jars"
_FRONTED = re.compile(
    rf"^(?:(?P<side>{_SIDE_PLACE})(?:\s+of\s+(?P<of>{_REF}))?"  # "on the left", "to the right of the plate"
    rf"|(?P<region>{_SUPPORT_PLACE})(?=\s*[,:]|\s+(?:i|we|there|sits?|stands?|is|are|lies|lie|goes|go|a|an|some)\b)"
    r"|(?P<near>behind|next\s+to|beside|alongside|between|on\s+top\s+of|(?:on|at)\s+(?:either|each|both)\s+"
    r"(?:sides?|ends?)\s+of|on|in|inside|under|underneath)"
    rf"\s+(?P<ref>{_REF}))"
    rf"\s*(?:[,:](?:\s*(?:{_PUT}|{_WANT})\b)?|\s(?:(?:should|will|can|must)\s+)?(?:is|are|sits|sit|stands|stand|lies"
    rf"|lie|rests|rest|goes|go|{_THERE}|{_WANT})\b"
    rf"|(?=\s+(?:a|an|the|some|{'|'.join(NUMERALS)}|\d+)\b)(?!\s+ones?\s*(?:[,.;]|$)))"  # or the thing at once: "on
    # the left a mug" (not "next to the left one, ...": "one" ends a name)
    r"\s*(?P<subject>\S.*)$",
    re.IGNORECASE,
)
_NEEDS_OF = ("left", "right", "front", "back", "side")
# where the first thing of a clause's subject ends, when what follows says what it holds or where it stands
_FIRST_THING_ENDS = re.compile(
    r"(?<=\w)(?=\s+(?:with|holding|containing|carrying|full of|filled with|next to|beside|behind|in front of)\b|,)",
    re.IGNORECASE,
)
_AND_THEN = re.compile(r"(?:,\s*and|\band)\s*,?\s+(?=\S)", re.IGNORECASE)
# where a later fronted place may begin inside a clause ("on the left a mug, on the right a glass")
_NEXT_CLAUSE = re.compile(r",\s*(?:and\s+)?|\s+and\s+,?\s*", re.IGNORECASE)


def _places_after_things(text: str) -> str:
    """Each clause that says a place before what stands there, said the other way round: "on the left side of the
    plate, a fork; on the right side, a knife" reads "a fork on the left side of the plate; a knife on the right
    side of the plate" (a side said with no "of" is of what the clause before named), "on the tray: a teapot and two
    cups" reads "a teapot and two cups on the tray"."""
    parts = re.split(r"([.;]|\s[-\u2013\u2014]+\s)", text)  # sentences, clauses, and asides set off by dashes
    said: str | None = None
    for k in range(0, len(parts), 2):
        parts[k], said = _place_after_thing(parts[k], said)
    return "".join(parts)


def _plain_start(clause: str) -> str:
    """A clause without the words before its place that say no place: "Just to the right of", "Off the tray, to its
    right"; "Left of it" is "to the left of it"."""
    clause = re.sub(r"^(?:just|then|also|directly|immediately|and)\s+", "", clause.strip(), flags=re.IGNORECASE)
    clause = re.sub(r"^off (?:the|its) [a-z ]+?,\s*", "", clause, flags=re.IGNORECASE)
    return re.sub(r"^(left|right) of\b", r"to the \1 of", clause, flags=re.IGNORECASE)


_ON_THE_SUPPORT = re.compile(
    rf"^(?:on|in|at)\s+(?:the|my|our|a|this)\s+(?:(?!of\b|left\b|right\b|back\b|front\b)[a-z'-]+\s+){{0,3}}?"
    rf"({'|'.join(sorted(SUPPORT_WORDS))})\b\s*,?\s*"
    r"(?=\S)(?!of\b)",
    re.IGNORECASE,
)


def _place_after_thing(clause: str, said: str | None) -> tuple[str, str | None]:
    """One clause said place last, and the thing its sides are of (for the next clause)."""
    clause = _plain_start(clause)
    if support := _ON_THE_SUPPORT.match(clause):  # "On the laundry room floor, put ...": the support itself (its
        rest, said = _place_after_thing(clause[support.end() :], said)  # name kept for the kind of scene)
        return f" on the {support[1].lower()},{rest}", said
    found = _FRONTED.match(clause)
    if found is None and ":" in clause:  # "a breakfast table: on the left a plate ..."
        before, after = clause.split(":", 1)
        said_after, said = _place_after_thing(after, said)
        return f" {before}:{said_after}", said
    head = ""
    for joined in _AND_THEN.finditer(clause) if found is None else ():  # "a kettle, and to its right, a toaster"
        found = _FRONTED.match(clause[joined.end() :])
        if found is not None:
            head, clause = clause[: joined.end()].rstrip() + " ", clause[joined.end() :]
            break
    if found is None:
        return f" {head}{clause}" if clause else head, said
    subject = found["subject"]
    if verb := re.search(r"\b(stack|pile)\s*$", clause[: found.start("subject")], re.IGNORECASE):
        subject = f"{verb[1]} {subject}"  # "to the right of the jar, stack two tins": the verb says they stack
    subject, rest = _subject_and_rest(subject)
    said_now, said = _thing_then_place(found, head, subject, said)
    if rest:
        sep = _NEXT_CLAUSE.match(rest)
        assert sep is not None  # `rest` starts where _NEXT_CLAUSE matched
        tail, said = _place_after_thing(rest[sep.end() :], said)
        said_now += rest[: sep.end()].rstrip() + tail
    return said_now, said


def _subject_and_rest(subject: str) -> tuple[str, str]:
    """What a fronted place is said of, and the clauses after it: a list that had its "and" ("a mouse and a notebook,
    and a mug ..."), or another place or verb ("..., put a lamp"), starts a clause of its own."""
    listed = re.search(r"\band\b", subject)
    closed = re.search(r",\s*and\s", subject[listed.end() :]) if listed else None
    if listed and closed and "," not in subject[: listed.start()]:
        cut_at = listed.end() + closed.start()
        return subject[:cut_at], subject[cut_at:]
    for cut in _NEXT_CLAUSE.finditer(subject):
        after = subject[cut.end() :]
        if _FRONTED.match(after) or re.match(rf"(?:and\s+|then\s+)*{_PUT}\s", after, re.IGNORECASE):
            return subject[: cut.start()], subject[cut.start() :]
        if "," in cut[0] and "and" in cut[0] and _CLAUSE_VERB.match(after):
            return subject[: cut.start()], subject[cut.start() :]  # "a jar of buttons, and the scissors lie ..."
    return subject, ""


# a clause's own verb after its subject ("a toothbrush holder holds two toothbrushes", "the tube of toothpaste lies")
_CLAUSE_VERB = re.compile(rf"^[^,]*?\b(?:holds|contains|carries|has|{'|'.join(sorted(_PLACE_VERBS))})\b", re.IGNORECASE)


def _thing_then_place(found: re.Match[str], head: str, subject: str, said: str | None) -> tuple[str, str | None]:
    """The words of a fronted place said after the thing: after the first thing when the place is on the support
    ("on the left a plate with toast": a plate on the left with toast), else after all of it."""
    if found["region"]:  # on the support: its words without the support's name
        where, ref, of = (
            found["region"][: found.start("support") - found.start()] if found["support"] else found["region"],
            None,
            "",
        )
    elif found["side"]:
        where, ref = found["side"], (found["of"] or "").strip() or said
        of = " of" if ref and where.split()[-1].lower() in _NEEDS_OF else ""
    else:
        where, ref, of = found["near"], found["ref"].strip(), ""
        if head and ref.lower() in ("it", "them"):  # "a board, and on it an onion and a knife": what the head named
            head = re.sub(r",?\s*and\s*,?\s*$", " with ", head, flags=re.IGNORECASE)
    listed = found["side"] and re.search(r",|\band\b", subject)
    if head and ref in ("it", "them") and listed and (named := _LAST_THING.search(head)):
        ref = f"the {named[1]}"  # "a tool bag, and in front of it a hammer and a saw": of the bag, not of the hammer
    if ref and ref not in ("it", "them"):
        said = ref
    first = _FIRST_THING_ENDS.search(subject)
    with_list = (
        first is not None
        and (  # "a plate with bread on it", "the butter dish, with a salt shaker to its right"
            not subject[first.start() :].startswith(",")
            or re.match(r",\s*with\b", subject[first.start() :]) is not None
        )
    )
    beside = found["side"] or not re.fullmatch(
        r"on|in|inside|under|underneath|on\s+top\s+of", (found["near"] or "on").lower()
    )
    if first is not None and (not ref or (with_list and (beside or ref.lower() in ("it", "them")))):
        place = f"{where}{of} {ref}" if ref else where  # "in front of it there's a plate with bread on it"
        return f" {head}{subject[: first.start()]} {place}{subject[first.start() :]}", said
    return (f" {head}{subject} {where}{of} {ref}" if ref else f" {head}{subject} {where}"), said


# the thing a clause named last, and the place said of it: "a tool bag at the back, and" -> "tool bag"
_LAST_THING = re.compile(
    rf"\b(?:a|an|the|{'|'.join(NUMERALS)}|\d+)\s+([a-z][a-z'-]*(?:\s+[a-z][a-z'-]*){{0,2}}?)"
    r"(?:\s+(?:sits|stands|is|lies|rests|sit|stand|lie))?(?:\s+(?:at|on|in|to|by|near|along|against)\b[^,]*)?"
    r"\s*,?\s*(?:and\s*)?,?\s*$",
    re.IGNORECASE,
)
_ONE_BEFORE = {"a", "an", "another", "the", "this", "that", "some", *NUMERALS}


def _ones_named(mentions: list[Mention], tokens: list[str], words: WordClasses) -> list[str]:
    """ "one" / "ones" after an adjective stands for the noun named last: "two red mugs and a blue one" is a blue mug,
    "an empty bowl beside a full one" two bowls. Only after an article or a number and one or two adjectives ("each
    one", "one of three" and "one plate" are not)."""
    out = list(tokens)
    for i in range(len(tokens) - 1, 1, -1):
        if tokens[i] not in ("one", "ones"):
            continue
        j = i - 1
        while j > i - 3 and j > 0 and _premodifier(tokens[j], words) and tokens[j] not in ("one", "ones", "other"):
            j -= 1
        if j == i - 1 or tokens[j] not in _ONE_BEFORE:
            continue
        before = [m for m in mentions if m.end <= j and m.known and not m.collective]
        if not before:
            continue
        noun = before[-1].phrase.split()
        out[i : i + 1] = noun[:-1] + [plural(noun[-1]) if tokens[i] == "ones" else noun[-1]]
    return out


# words that start a place or a pose right after a bare number ("and three beside it", "two more on the shelf")
_PART_PLACES = {"on", "in", "inside", "into", "beside", "next", "behind", "near", "by", "at", "under", "underneath",
                "along", "against", "to", "across", "around", "stacked", "standing", "lying", "sitting", "leaning",
                "piled", "lined"}  # fmt: skip
_PART_BREAKS = {":", ",", "-", "(", ";"}


def _counted_parts(mentions: list[Mention], tokens: list[str]) -> list[str]:
    """Bare numbers that count a thing counted before: more of it ("two toy cars on the tray and three beside it",
    "three notebooks on the left, three more on the right") or parts of its count ("four glasses: two on a tray and
    two beside it", "six mugs, two of them on a tray"). The noun is written after each number, and a count the parts
    share out is what the parts leave ("six mugs, two mugs on a tray" -> four and two)."""
    out = list(tokens)
    for m in reversed(mentions):  # "books, four of them, standing in a row": four books
        said = tokens[m.end : m.end + 4]
        if m.plural and not m.explicit_count and len(said) == 4 and said[0] == "," and said[2:] == ["of", "them"]:
            if _number(said[1]):
                out[m.end : m.end + 4] = []
                out.insert(m.start, said[1])
    out = _shares_named(mentions, out)
    if out != tokens:
        return out
    parts = _bare_numbers(mentions, tokens)
    for m in {id(m): m for _, _, m in parts}.values():
        own = [(i, n) for i, n, o in parts if o is m]
        direct = own[0][0] - 1 == m.end and tokens[m.end] in _PART_BREAKS  # "six mugs, two of them ..."
        rest = m.count - sum(n for _, n in own) if direct and m.explicit_count else None
        for i, n in reversed(own):
            noun = m.category.split()
            named = [*noun[:-1], plural(noun[-1]) if n > 1 else noun[-1]]
            replaced = 2 if out[i + 1 : i + 3] == ["of", "them"] else 1 if out[i + 1] == "more" else 0
            out[i + 1 : i + 1 + replaced] = named
        if rest is not None and rest <= 0:  # the parts are the whole count: the words before them go
            out[m.start : m.end + 1] = [""] * (m.end + 1 - m.start)
        elif rest is not None and m.count > rest > 0:
            quantity = next((q for q in range(m.start, m.end) if _number(tokens[q]) == m.count), None)
            if quantity is not None:  # "several pencils, two on erasers": no number to lower
                out[quantity] = str(rest)
    return [w for w in out if w]


def _bare_numbers(mentions: list[Mention], tokens: list[str]) -> list[tuple[int, int, Mention]]:
    """The numbers with no noun of their own that start a place or a pose after a break: (index, number, the counted
    mention they count)."""
    parts: list[tuple[int, int, Mention]] = []
    for i in range(1, len(tokens) - 1):
        n = _number(tokens[i])
        if not n or tokens[i - 1] not in (*_PART_BREAKS, "and", "plus", "while"):
            continue
        after = tokens[i + 1 : i + 3]
        after = after[1:] if after[:1] == ["more"] else tokens[i + 3 : i + 4] if after == ["of", "them"] else after
        if after[:1] != [] and after[0] not in _PART_PLACES:
            continue
        if any(m.start <= i < m.end and (m.known or m.phrase.split()[-1] not in _PART_PLACES) for m in mentions):
            continue  # a number of a noun ("and two mugs"), not a bare one ("two more standing": no noun)
        if n == 1 and {"other", "each", "another", "either", "both", "end", "ends"} & set(tokens[i + 1 : i + 7]):
            continue  # "two plates, one on top of the other", "one in each"
        if _GROUP_WORDS & set(tokens[i + 1 : i + 6]):
            continue  # "two rows of jars, three in the front row and three in the back row": the rows' sizes
        counted = [m for m in mentions if m.end <= i and m.known and (m.plural or m.count > 1)]
        if len(counted) > 1 and _share_of_each(tokens, i, counted[-1]):
            counted.pop()  # "cans go into two crates, three in each crate": three cans
        if counted and counted[-1].end >= i - 10:
            parts.append((i, n, counted[-1]))
    return parts


def _shares_named(mentions: list[Mention], tokens: list[str]) -> list[str]:
    """ "six cans go into two crates, three in each crate": the shares name the cans again, in the crates; things
    named with no number ("apples go into two bowls, three in each bowl") are counted by the shares."""
    out = list(tokens)
    for i in range(len(tokens) - 4, 0, -1):
        holders = [m for m in mentions if m.end <= i and m.count > 1]
        if not holders or not _share_of_each(tokens, i, holders[-1]) or tokens[i - 1] not in _PART_BREAKS:
            continue
        n, h = _number(tokens[i]) or 0, holders[-1]
        said = [m for m in mentions if m.end <= h.start and m.known and m.plural]
        shared = [m for m in said if m.count == n * h.count or not m.explicit_count]
        if shared:
            thing, holder = shared[-1].category.split(), h.category.split()
            named = [*thing[:-1], plural(thing[-1]), tokens[i + 1], "the", *holder[:-1], plural(holder[-1])]
            out[i : i + 4] = ["the", *named]
            if not shared[-1].explicit_count:
                out[shared[-1].start : shared[-1].start] = [str(n * h.count)]
    return out


def _share_of_each(tokens: list[str], i: int, holder: Mention) -> bool:
    """Whether the bare number at token i is said "in (or on) each" of the holder's things ("three in each crate")."""
    said = tokens[i + 1 : i + 4]
    return (
        _number(tokens[i]) is not None
        and len(said) == 3
        and said[0] in ("in", "on", "into", "onto")
        and said[1] in ("each", "every")
        and _names_the_group(singular(said[2]), holder)
    )


def _numbers_named(mentions: list[Mention], tokens: list[str], words: WordClasses) -> list[str]:
    """A number with only adjectives or a participle after it counts the noun named last: "three red apples and two
    green" (two green apples), "three books lying flat and two standing upright". Not a number before "of" or a
    place ("two of them", "three in the cup": a part of what was counted)."""
    out = list(tokens)
    for i in range(len(tokens) - 1, 0, -1):
        if tokens[i] not in NUMERALS or tokens[i - 1] not in ("and", ",", "but", "plus"):
            continue
        j = i + 1
        while j < len(tokens) and j < i + 3 and tokens[j] in words.adjectives and tokens[j] not in words.nouns:
            j += 1
        nxt = tokens[j] if j < len(tokens) else ","
        participle = j == i + 1 and nxt.endswith(("ing", "ed")) and (nxt in words.verbs or tokens[i] == "one")
        if tokens[i] == "one" and (not participle or "other" in tokens[i + 1 : i + 6]):
            continue  # "one of", "each one", "one plate", "one nested inside the other": not a count of the noun
        if not (participle or (j > i + 1 and (nxt in (",", "and", "on", "in", "at", "to") or j == len(tokens)))):
            continue
        before = [m for m in mentions if m.end <= i and m.known and not m.collective]
        if not before or before[-1].end < i - 8:
            continue
        noun = before[-1].category.split()  # the category, not a variant's name ("book lying flat")
        out[j:j] = noun[:-1] + [plural(noun[-1])]
    return out


_PART_STARTS = (("one",), ("the", "other"), ("another",), ("a", "second"), ("the", "second"), ("a", "third"),
                ("the", "third"), ("the", "last"), ("the", "first"))  # fmt: skip
_PART_LINKS = {"with", "of", "holding", "containing", "carrying", "full", "filled", "has", "having", "topped"}


def _part_at(tokens: list[str], i: int, elliptic: bool = False) -> int:
    """How many words start a part of a counted holder at token i ("one with", "the other holding"; after the first
    part, "the other four oranges" with the first part's verb left out); 0: none."""
    for start in _PART_STARTS:
        end = i + len(start)
        if tuple(tokens[i:end]) != start or end >= len(tokens):
            continue
        if tokens[end] in _PART_LINKS:
            sized = tokens[end] == "of" and _number(tokens[end + 1] if end + 1 < len(tokens) else "") is not None
            return 0 if sized else len(start)  # "two stacks, one of three and one of four": sizes, not contents
        if elliptic and start != ("one",) and (_number(tokens[end]) or tokens[end] in ("some", "a", "an")):
            return len(start)
    return 0


def _place_on_the_support(tokens: list[str], i: int) -> int:
    """How many words at token i say a place on the support and end at a comma ("on the floor ,"); 0: none."""
    words = tokens[i : i + 7]
    if not words or words[0] not in ("on", "in", "at") or "," not in words:
        return 0
    said = words[: words.index(",")]
    return len(said) if set(said) & SUPPORT_WORDS else 0


def _parts_named(mentions: list[Mention], tokens: list[str]) -> list[str]:
    """A counted holder said part by part is that many holders, each with its own contents: "two baskets, one with
    three apples and the other with two bananas" reads as "a basket with three apples and a basket with two
    bananas"; "three plates, one with a muffin" as two plates and a plate with a muffin."""
    for m in mentions:
        if not m.known or m.collective or m.count < 2 or m.arrangement or m.stacked:
            continue
        first = m.end + _place_on_the_support(tokens, m.end)  # "two crates on the floor, one with ..."
        first += first < len(tokens) and tokens[first] == ","
        if not _part_at(tokens, first):
            continue
        parts = [first]
        link = tokens[first + _part_at(tokens, first)]  # the verb the other parts may leave out
        i = first + _part_at(tokens, first)
        while i < len(tokens) and len(parts) < m.count:
            if tokens[i - 1] in (",", "and") and _part_at(tokens, i, elliptic=True):
                parts.append(i)
                i += _part_at(tokens, i, elliptic=True)
            else:
                i += 1
        one = ["a", *m.adjectives, *m.phrase.split()]
        rest = m.count - len(parts)
        out = tokens[: m.start]
        if rest:
            words = m.phrase.split()
            out += one if rest == 1 else [str(rest), *m.adjectives, *words[:-1], plural(words[-1])]
            out.append("and" if len(parts) == 1 else ",")
        for k, start in enumerate(parts):
            end = parts[k + 1] if k + 1 < len(parts) else len(tokens)
            said = start + _part_at(tokens, start, elliptic=k > 0)
            out += one + ([] if tokens[said] in _PART_LINKS else [link]) + tokens[said:end]
        return out
    return tokens


def _former_and_latter(mentions: list[Mention], tokens: list[str]) -> list[str]:
    """ "the latter" is the last of the two things named before it, "the former" the first."""
    out = list(tokens)
    for i in range(len(tokens) - 1, 0, -1):
        if tokens[i - 1] != "the" or tokens[i] not in ("former", "latter"):
            continue
        before = [m for m in mentions if m.end <= i - 1 and m.known]
        between = tokens[before[-1].end : i - 1] if before else []
        if before and "," not in between and len(between) <= 5 and _relation(" ".join(between))[0] == "position":
            before = before[:-1]  # "a stack of novels behind the latter": the novels are the subject, not named
        pair = _last_pair(before, tokens)
        if pair is not None:
            out[i : i + 1] = pair[1 if tokens[i] == "latter" else 0].phrase.split()
    return out


def _last_pair(before: list[Mention], tokens: list[str]) -> tuple[Mention, Mention] | None:
    """The two things "the former" and "the latter" are of: the last two said together ("a microphone and a webcam in
    front of the monitor": the microphone and the webcam), else the last two named."""
    for a, b in zip(reversed(before[:-1]), reversed(before[1:]), strict=True):
        if tokens[a.end : b.start] in (["and"], [","], [",", "and"]) or tokens[a.end : b.start + 1][:2] == ["and", "a"]:
            return a, b
    return (before[-2], before[-1]) if len(before) >= 2 else None


def _compound_of(mentions: list[Mention], word: str, i: int) -> list[str]:
    """The words of the thing named before i whose name holds `word` before its noun ("egg box" for "eggs"), when
    nothing named before is a `word` itself; [] otherwise."""
    compound = [m for m in mentions if m.end <= i - 1 and m.known and word in m.phrase.split()[:-1]]
    compound = compound or [  # "the glasses" after "a pair of safety glasses"
        m for m in mentions if m.end <= i - 1 and m.known and len(m.phrase.split()) > 1 and m.phrase.split()[-1] == word
    ]
    if compound and not any(m.category == word for m in mentions if m.end <= i - 1):
        return compound[-1].phrase.split()
    return []


def _short_names(mentions: list[Mention], tokens: list[str]) -> list[str]:
    """ "the stand" after "a laptop stand", "the holder" after "a toothbrush holder": a thing named again by its last
    word, where that word alone names nothing (or something else)."""
    out = list(tokens)
    for i in range(len(tokens) - 1, 0, -1):
        if tokens[i - 1] not in ("the", "this", "that", "those", "these"):
            continue
        if tokens[i] != singular(tokens[i]):  # "the eggs" after "the egg box": the box of them
            out[i : i + 1] = _compound_of(mentions, singular(tokens[i]), i) or out[i : i + 1]
            continue
        group = _GROUP_NOUNS.get(tokens[i])  # "a stack of four books, a clock on top of the stack": the books
        stacked = [m for m in mentions if m.end <= i - 1 and group and m.arrangement == group]
        end = tokens[i - 6 : i - 1] in (["at", "the", side, "end", "of"] for side in ("left", "right"))
        if stacked and (group not in ("row", "line") or end):  # "a bookend at the left end of the row": left of
            words = stacked[-1].phrase.split()  # the books
            out[i : i + 1] = [*words[:-1], plural(words[-1])]
            if end:
                out[i - 6 : i - 2] = ["to", "the", tokens[i - 4]]
            continue
        if tokens[i] in SUPPORT_WORDS and tokens[i] != "stand":
            continue  # "a desk lamp in the corner of the desk": the desk is the support
        here = next((m for m in mentions if m.start <= i < m.end), None)
        if here is not None and here.end != i + 1:
            continue  # a name of more words ("the tape measure")
        earlier = [m for m in mentions if m.end <= i - 1 and m.known and len(m.phrase.split()) > 1]
        if here is not None and any(m.category == here.category for m in earlier):
            continue  # "a coffee mug ... the mug": the same thing by its own name
        if named := _named_by_a_word(earlier, here, tokens[i]):
            out[i : i + 1] = named
    return out


def _named_by_a_word(earlier: list[Mention], here: Mention | None, word: str) -> list[str] | None:
    """The words of the thing named before that `word` names again ("the stand", "the tape": a roll of tape); not a
    word the catalogue names by itself and the earlier name only has in front ("a mouse pad ... the mouse")."""
    named = [m for m in earlier if word in m.phrase.split()]
    if not named or (here is not None and here.known and all(word != m.phrase.split()[-1] for m in named)):
        return None
    return named[-1].phrase.split()


def _shared_heads(mentions: list[Mention], tokens: list[str], words: WordClasses) -> list[str]:
    """ "the flour and sugar canisters" are a flour canister and a sugar canister: two nouns sharing a plural head
    (not colours or other adjectives: "red and blue mugs" are mugs of both colours)."""
    out = list(tokens)
    for m in reversed(mentions):
        i = m.start
        if not (m.plural and not m.explicit_count and m.known and i >= 2 and tokens[i - 1] == "and"):
            continue
        first, head = tokens[i - 2], tokens[m.end - 1]
        if first in ARTICLES | DETERMINERS or _number(first) or any(o.start <= i - 2 < o.end for o in mentions):
            continue
        nouns = [first, tokens[i]]
        if m.end - i < 2 or any(w not in words.nouns or w in words.adjectives for w in nouns):
            continue
        out[i - 2 : m.end] = [first, singular(head), "and", *tokens[i : m.end - 1], singular(head)]
    return out


_MEMBER_SIDES = {"left": "left", "right": "right", "leftmost": "left", "rightmost": "right", "front": "front",
                 "back": "behind", "rear": "behind"}  # fmt: skip
_ORDINALS = {"first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "last"}
_BY_WORDS = (["next", "to"], ["beside"], ["by"], ["near"], ["alongside"])


def _members_named(mentions: list[Mention], tokens: list[str]) -> list[str]:
    """One of several things named by its place among them: "the mug on the left", "the right-hand bin", "the one on
    the left", "the other" (two mugs flank a coffee maker). The reading relates to the group: next to the left one is
    to the left of them (the side it has free), on or in it is on or in one of them."""
    out = list(tokens)
    for i in range(len(tokens) - 1, 0, -1):
        if tokens[i - 1] != "the" or (found := _member_at(mentions, tokens, i)) is None:
            continue
        group, side, end = found
        noun = [*group.category.split()[:-1], plural(group.category.split()[-1])]
        by = next((len(b) for b in _BY_WORDS if tokens[i - 1 - len(b) : i - 1] == b), 0)
        if by and side:  # "next to the mug on the left": to the left of the mugs
            out[i - 1 - by : end] = (
                ["to", "the", side, "of", "the", *noun]
                if side in ("left", "right")
                else (["in", "front", "of", "the", *noun] if side == "front" else ["behind", "the", *noun])
            )
        else:
            out[i:end] = noun
    return out


def _member_at(mentions: list[Mention], tokens: list[str], i: int) -> tuple[Mention, str, int] | None:
    """The group, the member's side and where its words end, for the words at i after "the"."""
    before = [m for m in mentions if m.end <= i - 1 and m.known and (m.count >= 2 or _one_at_each(m, tokens))]
    if not before:
        return None
    words = tokens[i : i + 6]
    if words[:1] == ["other"]:  # "the other", "the other one", "the other bin"
        if "one" in tokens[max(0, i - 6) : i] or words[1:2] in (["side"], ["end"], ["half"], ["corner"], ["edge"]):
            return None  # "two plates, one on top of the other": the pair itself; "the other side": a place
        last = before[-1]
        size = 2 if words[1:2] == ["one"] or singular(words[1] if len(words) > 1 else "") == last.category else 1
        return last, "", i + size
    anchored = i >= 2 and tokens[i - 2] in (*_ANCHOR_WORDS, "beside", "behind")  # not "the first holds nails"
    if words[:1] and words[0] in _ORDINALS and anchored:  # "in front of the fourth", "between the first two"
        row = before[-1]
        more = words[1:2] and (_number(words[1]) or words[1] in ("one", "ones") or singular(words[1]) == row.category)
        return row, "", i + (2 if more else 1)
    hand = words[:1] if words[:1] and words[0] in _MEMBER_SIDES else []
    if hand:  # "the right-hand bin", "the leftmost jar", "the left one"
        at = i + 1 + (1 if words[1:2] == ["hand"] else 0)
        noun = tokens[at] if at < len(tokens) else ""
        if noun == "one":  # "two toy cars in the left one": one of the things set apart, not the cars themselves
            ones = [m for m in before if not _subject_of(m, tokens, i)]
            ones = [m for m in ones if _one_at_each(m, tokens)] or ones
        else:
            ones = [m for m in before if _names_the_group(singular(noun), m)]
        named = ones[-1] if ones else None
        return (named, _MEMBER_SIDES[hand[0]], at + 1) if named is not None else None
    group = next((m for m in reversed(before) if words[:1] in (["one"], [m.category.split()[-1]])), None)
    if group is None or len(group.category.split()) > 1 and words[0] != "one":
        return None
    rest = tokens[i + 1 : i + 4]
    if rest[:2] == ["on", "the"] and len(rest) == 3 and rest[2] in _MEMBER_SIDES:  # "the mug on the left"
        return group, _MEMBER_SIDES[rest[2]], i + 4
    return None


def _subject_of(m: Mention, tokens: list[str], i: int) -> bool:
    """Whether mention m is what the words ending at "the" before token i are said of ("two toy cars in the left
    one": the cars are in one of some other things)."""
    between = tokens[m.end : i - 1]
    return len(between) <= 3 and not {",", "and", "or"} & set(between)


def _one_at_each(m: Mention, tokens: list[str]) -> bool:
    """Whether one thing is said to stand at each of two places ("a storage bin at each end", "a lamp on either
    side"): two of it."""
    after = " ".join(tokens[m.end : m.end + 5])
    return re.match(r"(?:\w+ )?(?:at|on) (?:each|either|both) (?:end|side)s?\b", after) is not None


def _names_the_group(noun: str, m: Mention) -> bool:
    """Whether a noun names mention m's things: its category's head or the unit it was said in ("the right-hand tin"
    of "two tins of paint")."""
    return noun in (m.category.split()[-1], m.phrase.split()[0], m.phrase.split()[-1])


def _respelt(tokens: list[str], lexicon: Lexicon, words: WordClasses) -> list[str]:
    """A noun the catalogue misses by one letter is the catalogue's word ("a bannana"); so is a word the tagger took
    for a verb or an adjective where a noun stands, before a boundary or a catalogue noun ("two wine glases in a
    row", "a coffe mug"), unless it reads as a participle ("lined", "folding")."""
    out = list(tokens)
    for i, t in enumerate(tokens):
        nxt = tokens[i + 1] if i + 1 < len(tokens) else ","
        noun_place = nxt in _BOUNDARY or nxt in LIST_WORDS or singular(nxt) in lexicon.vocabulary
        if t in words.nouns or (noun_place and not t.endswith(("ed", "ing")) and t not in words.adverbs):
            out[i] = lexicon.respelt(t, tokens[i - 1] if i else "") or t
    return out


_POSSESSIVE_SIDE = re.compile(
    r"\b(to|on|at|by) (?:the|its|their) ((?:[a-z-]+ ){0,2}[a-z-]+)['\u2019]s (other|left|right|near|far)(?:[ -]hand)?"
    r"( side)?\b",
    re.IGNORECASE,
)


def _possessive_sides(text: str) -> str:
    """ "to the iron's right" is "to the right of the iron", "on the bowl's other side" "on the other side of the
    bowl"."""
    return _POSSESSIVE_SIDE.sub(lambda m: f"{m[1]} the {m[3]}{m[4] or ''} of the {m[2]}", text)


# "the toaster's on the right", "my phone's charging": "is", not a possessive (a side after it is: "the iron's right")
_IS_CONTRACTED = re.compile(
    r"\b(?!let's)([a-z]+)['\u2019]s\s+(?=(?:on|in|at|by|next|beside|behind|under|over|up|out|off|just|still|now"
    r"|always|usually)\b|(?!\w*thing\b)\w+ing\b)",
    re.IGNORECASE,
)
# the one the sentence is said to ("Robot, please set the table"): no thing of the scene
_ADDRESSED = re.compile(r"^\s*(?:(?:hey|hi|ok|okay|dear|so)\s*,?\s+)?(?:robot|assistant|computer|bot)\s*[,:!]\s*", re.I)


# a bracketed list of bare words after a plural: the kinds of those things, no things of their own
_KINDS_IN_BRACKETS = re.compile(
    r"(?<=[a-z]s)\s*\((?![^)]*\b(?:a|an|the|one|two|three|four|five|six|\d+)\b)[a-z ,'&-]+\)", re.IGNORECASE
)
# "held up by a bookend on either side": with a bookend on either side
_HELD_BY_SIDES = re.compile(
    r"\b(?:held|propped|kept|supported)(?: up| upright| in place)? by "
    r"(?=[a-z\s-]{1,40}?\b(?:on|at) (?:either|each|both) (?:side|end)s?\b)",
    re.IGNORECASE,
)


def without_asides(text: str) -> str:
    """The prompt without a bracketed list of kinds after a plural ("three canisters (flour, sugar, coffee)") and with
    "infront" split: the words the reading reads things from, which the account parses too."""
    return re.sub(r"\binfront\b", "in front", _KINDS_IN_BRACKETS.sub("", text), flags=re.IGNORECASE)


def _plain_words(text: str) -> str:
    """The prompt without the one it is said to, its "is" said in full, its possessive sides said with "of", and
    things "held up by" others on either side said "with" them."""
    text = without_asides(text)  # "three canisters (flour, sugar, coffee)": what each is for
    text = _HELD_BY_SIDES.sub("with ", _IS_CONTRACTED.sub(r"\1 is ", _ADDRESSED.sub("", text)))
    text = _SIDE_SAID_AGAIN.sub(r"to the \2 of \1", _HEDGE_BEFORE_A_PLACE.sub("", text))
    text = _OF_THAT.sub(r"\1 it", text)  # "to the right of that the kettle": of it
    return _possessive_sides(text)


_OF_THAT = re.compile(r"\b(of|beside|behind|by) (?:that|this)(?=\s*(?:[,.;]|the\b|a\b|an\b|is\b|are\b|sits\b|$))", re.I)


# "next to it, on its left": the side of what it stands next to
_SIDE_SAID_AGAIN = re.compile(
    r"\b(?:next to|beside|by) (it|them|the [a-z]+(?: [a-z]+)?),? (?:on|to) (?:its|their|the) (left|right)\b(?! of)",
    re.IGNORECASE,
)


def read_prompt(text: str, lexicon: Lexicon) -> SceneRequest:
    words = parse(text).words  # what each word is, where its spelling cannot say
    tokens = _respelt(tokenize(_places_after_things(_plain_words(text))), lexicon, words)
    request = SceneRequest(mentions=[], tokens=tokens)
    _read_scene_words(request, tokens)
    mentions = _noun_phrases(tokens, lexicon, words)
    said = _spelled_out(mentions, tokens)
    if said is not None:  # "a basket of fruit: three apples ...": read as "a basket holding three apples ..."
        start, end = said
        held = ["holding"] if start and tokens[start - 1] == "of" else []
        tokens = tokens[: start - len(held)] + held + tokens[end:]
        request.tokens = tokens
        mentions = _noun_phrases(tokens, lexicon, words)
    # "two bowls, one of apples and the other of pears": a bowl of each; "a laptop stand ... the stand": the same
    for rewrite in (_parts_named, _short_names, _members_named, _former_and_latter):
        again = rewrite(mentions, tokens)
        if again != tokens:
            tokens = request.tokens = again
            mentions = _noun_phrases(tokens, lexicon, words)
    shared = _shared_heads(mentions, tokens, words)  # "the flour and sugar canisters": two canisters
    if shared != tokens:
        tokens = request.tokens = shared
        mentions = _noun_phrases(tokens, lexicon, words)
    named_again = _ones_named(mentions, tokens, words)  # "two red mugs and a blue one": "a blue mug"
    if named_again == tokens:  # each rewrite reads the mentions' places in the tokens it was given
        named_again = _counted_parts(mentions, tokens)  # "two on a tray and three beside it"
    if named_again == tokens:
        named_again = _numbers_named(mentions, tokens, words)  # "three red apples and two green"
    if named_again != tokens:
        tokens = request.tokens = named_again
        mentions = _noun_phrases(tokens, lexicon, words)
    named = {o.category for o in mentions if not o.collective}
    mentions = [m for m in mentions if not (m.collective and m.category in named)]  # "fruit and two apples"
    mentions = _per_group_counts(mentions, tokens)
    _aliases(mentions, tokens)
    for k, m in enumerate(mentions):
        stop = mentions[k + 1].start if k + 1 < len(mentions) else len(tokens)
        _read_postmodifiers(m, tokens[m.end : min(stop, m.end + 12)])
        _stacked_by_the_verb(m, tokens)
        _read_amount(m, tokens, stop, paired=k > 0 and _pair_ends(mentions[k - 1], m, tokens))
        _fills_the_support(m, tokens, mentions[k - 1].end if k else 0)
    _relations(mentions, tokens, lexicon, words)
    _other_places(mentions)
    _other_sides(mentions)
    mentions = _merge_aliases(_each_after(_merge_aliases(mentions), tokens))
    _settle_counts(mentions, tokens)
    _per_person(mentions, tokens, request.diners)
    _beside_what_is_carried(mentions)
    request.mentions = mentions
    return request


def _per_person(mentions: list[Mention], tokens: list[str], diners: int) -> None:
    """ "a plate for each of the four guests", "one napkin per guest, four guests", "a glass for each guest" at a
    table for four: one (or as many as said) for every person."""
    counted = next((_people_counted(tokens, i) for i in range(1, len(tokens)) if _people(tokens[i])), None)
    _each_person_gets(mentions, tokens, diners or counted or 0)
    for m in mentions:
        after = tokens[m.end : m.end + 4]
        rest = after[1:] if after[:1] == ["per"] else []
        if after[:2] in (["for", "each"], ["for", "every"]):
            rest = after[2:]
        said = _number(rest[0]) if rest else None
        who = rest[1:2] if said else rest[:1]
        if not who or singular(who[0]) not in PEOPLE or m.per is not None:
            continue
        people = said or diners or counted  # "... a napkin per guest, four guests"
        if people and people > 1:
            m.count, m.explicit_count, m.plural = m.count * people, True, True


def _people(word: str) -> bool:
    """Whether a word names several people ("guests", "people", "children")."""
    return word in ("people", "children", "men", "women") or (word != singular(word) and singular(word) in PEOPLE)


def _people_counted(tokens: list[str], i: int) -> int | None:
    """How many the people word at i counts: "four guests", "a pair of pupils", "a couple of friends"."""
    if tokens[i - 1] == "of" and i > 1 and tokens[i - 2] in LOOSE:
        return LOOSE[tokens[i - 2]]
    return _number(tokens[i - 1])


def _each_person_gets(mentions: list[Mention], tokens: list[str], people: int) -> None:
    """ "a desk for two pupils: each gets a notebook with a pencil on it, plus an eraser": the list said after "each"
    of the people is one set per person (what rests on a thing of the set rests on each of them)."""
    if people < 2:
        return
    for i in range(1, len(tokens) - 1):
        if tokens[i] != "each" or not (_people(tokens[i - 1]) or _people(tokens[i - 2]) if i > 1 else False):
            continue
        group = [k for k, m in enumerate(mentions) if m.start > i]
        taken: list[int] = []
        for k in group:
            m = mentions[k]
            if taken and _relation(_link(tokens, mentions[taken[-1]], m))[0] not in ("list", "holds", "position"):
                break
            if taken and (m.region or m.centre):
                break
            taken.append(k)
        for k in taken:
            m = mentions[k]
            if m.per is None and not m.explicit_count and m.count == 1:
                m.count, m.explicit_count, m.plural = people, True, True
                if m.on is not None and m.on in taken:
                    m.per = m.on  # "a notebook with a pencil on it": a pencil on each notebook
        return


def _beside_what_is_carried(mentions: list[Mention]) -> None:
    """ "a tea tray holding a teapot, with a cup to the left of the teapot": a free thing said to stand on a side of
    a thing on a carrier stands on that side of the carrier, which is that side of what the carrier holds too (the
    layout places free things beside free things; on the carrier, the drawn tray may leave no room beside it). Of
    several carriers ("two cups, a saucer under each, and a teapot left of the cups"), beside all of them."""
    for m in mentions:
        if m.beside is None or m.on is not None or m.held_by is not None or m.side not in SIDE_WORDS:
            continue
        carrier = mentions[m.beside].on
        if carrier is not None and carrier != m.beside:
            m.beside = carrier


def _each_after(mentions: list[Mention], tokens: list[str]) -> list[Mention]:
    """A count said per holder after the item: "four saucers with a teacup on each saucer", "two pen holders with
    three pencils in each", "five plates with one apple per plate", "a fork beside each plate": one such item (or as
    many as said) for every holder; "per plate" names the plates again (an alias, merged by the caller)."""
    distributive = {"each", "every", "per"}
    for k, m in enumerate(mentions):
        later = [o for o in mentions if o.start >= m.end]
        stop = min((o.start for o in later), default=len(tokens))
        said = tokens[m.end : stop + 1]
        if not distributive & set(said):
            continue
        holder = next((j for j, o in enumerate(mentions) if k in o.contents), None)
        beside = m.beside if m.side in SIDE_WORDS else None  # "at each end of" is one per end already
        target = next((r for r in (m.per, m.on, m.held_by, holder, beside) if r is not None and r != k), None)
        if target is None and tokens[stop - 1 : stop] == ["per"]:  # "three dolls, a saucer per doll": one each
            again = next((o for o in later if o.start == stop and o.alias is None), None)
            named = [j for j, o in enumerate(mentions[:k]) if again is not None and o.category == again.category]
            if again is not None and named and _instances(mentions[named[-1]]) > 1 and m.count == 1:
                count = _instances(mentions[named[-1]])
                m.count, m.explicit_count, m.plural = count, True, True
                again.alias = named[-1]  # named only to count by: what a list after it said is not the dolls'
                again.on = again.beside = again.around = again.held_by = None
                again.contents = []
            continue
        if target is None or _instances(mentions[target]) < 2:
            continue
        m.per, m.count = target, m.count * _instances(mentions[target])
        m.explicit_count, m.plural = True, True  # as many as the holders, exactly
        again = next((o for o in later if o.start == stop and o.alias is None), None)
        if again is None or again is mentions[target] or again.category != mentions[target].category:
            continue  # "beside each of the two laptops": the laptops themselves, named once
        if distributive & set(tokens[stop - 1 : stop + 1]):  # "each plate"; "per plate" ("per" ends a phrase)
            again.alias = target
    return mentions


def without_the_support(mentions: list[Mention], support_kind: str) -> list[Mention]:
    """The mentions with the one that names the support itself left out ("three mugs packed in a moving box" on a box
    support: the mugs go in the support, not in a second box); what it held or carried stands on the support."""
    named = [
        k
        for k, m in enumerate(mentions)
        if m.category == support_kind
        and m.count == 1
        and (m.contents or any(o.on == k or o.held_by == k for o in mentions))
    ]
    if not named:
        return mentions
    k = named[0]
    kept = [j for j in range(len(mentions)) if j != k]
    index = {j: n for n, j in enumerate(kept)}
    for j in kept:
        m = mentions[j]
        m.contents = [index[c] for c in m.contents if c != k]
        for name in ("on", "beside", "around", "per", "held_by", "alias", "second"):
            value = getattr(m, name)
            setattr(m, name, None if value is None or value == k else index[value])
        if m.side == "between" and m.beside is None:
            m.side = "beside"
    return [mentions[j] for j in kept]


def _merge_aliases(mentions: list[Mention]) -> list[Mention]:
    """A second mention of the same thing ("... and a vase behind the laptop") becomes the first one: its relations
    move there and the indices are renumbered."""
    if all(m.alias is None for m in mentions):
        return mentions
    final = {k: _first_named(mentions, k) for k in range(len(mentions))}
    kept = [k for k, m in enumerate(mentions) if m.alias is None]
    index = {k: kept.index(final[k]) for k in final}
    for k, m in enumerate(mentions):
        if m.alias is not None:
            m.alias = final[k]  # an alias of an alias: of the first
            first = mentions[m.alias]
            _leave_holder(mentions, m, first)
            _beside_a_sibling(mentions, final, first, m)
            _absorb(first, m)
    for new, k in enumerate(kept):
        m = mentions[k]
        m.contents = list(dict.fromkeys(index[j] for j in m.contents if index[j] != new))
        for name in ("on", "beside", "around", "per", "held_by", "second"):
            value = getattr(m, name)
            setattr(m, name, None if value is None or index[value] == new else index[value])
    return [mentions[k] for k in kept]


def _beside_a_sibling(mentions: list[Mention], final: dict[int, int], first: Mention, again: Mention) -> None:
    """ "a microphone and a webcam in front of the monitor, the webcam to the right of the microphone", "a chisel and
    a hammer in front of the saw, the chisel to the left of the hammer": a side said again of a thing, beside one
    that stands where it stands, is its place (it stands there by standing beside that one)."""
    if first.beside is None or again.beside is None or again.side not in ("left", "right"):
        return
    sibling = mentions[final[again.beside]]
    if sibling is first or sibling.beside is None or first.side not in SIDE_WORDS:
        return
    if final[sibling.beside] == final[first.beside] and sibling.side == first.side:
        first.beside, first.side, first.second = again.beside, again.side, None


def _first_named(mentions: list[Mention], k: int) -> int:
    """The mention an alias names in the end (an alias of an alias names the first); a cycle of aliases ends at the
    first of it, which then names itself."""
    seen = {k}
    while (alias := mentions[k].alias) is not None:
        if alias in seen:
            mentions[k].alias = None
            return k
        seen.add(alias)
        k = alias
    return k


def _leave_holder(mentions: list[Mention], again: Mention, first: Mention) -> None:
    """ "a jar of honey and three lemons in a bowl. The jar sits to the right of the bowl": a thing named again
    beside what its list put it in stands beside it, not in it."""
    by, k = again.beside, again.alias
    if by is None or again.side not in SIDE_WORDS or k is None:
        return
    alias = mentions[by].alias
    target = by if alias is None else alias
    holder = mentions[target]
    if target in (first.on, first.held_by) or k in holder.contents:
        if k in holder.contents:
            holder.contents.remove(k)
        first.on = first.held_by = None


def _absorb(first: Mention, again: Mention) -> None:
    """What the second mention of a thing says about it, added to the first."""
    first.contents += again.contents
    if again.side == "between" and first.beside is None and not again.region:
        first.region = ()  # "... a canister and a bread box at the right end. The canister sits between ...": there
    for name in ("on", "beside", "around", "held_by"):
        if getattr(first, name) is None and getattr(again, name) is not None:
            setattr(first, name, getattr(again, name))
    if again.beside is not None and first.beside == again.beside:
        first.side, first.second = again.side, again.second  # "the canister sits between the jar and the box"
    first.centre = first.centre or again.centre
    # "..., with the soap dispenser at the far left"; "a stapler, ... along the front edge, with the stapler furthest
    # to the left": front and left
    axes = ({"back", "front"}, {"left", "right"})
    kept = [w for w in first.region if not any(w in a and a & set(again.region) for a in axes)]
    first.region = tuple(dict.fromkeys([*kept, *again.region])) if again.region else first.region


def _read_scene_words(request: SceneRequest, tokens: list[str]) -> None:
    joined = " ".join(tokens)
    request.messy = any(
        w in tokens for w in ("messy", "cluttered", "scattered", "untidy", "random", "chaotic", "strewn", "piled")
    )
    request.rows = any(w in tokens for w in ("rows", "aligned")) and "everything" in tokens
    request.dense = (
        "as many" in joined
        or "very cluttered" in joined
        or "crammed" in tokens
        or ("packed" in tokens and "with" not in tokens and "packed in" not in joined)  # "mugs packed in a box"
        or "full of everything" in joined
    )
    request.fragile = any(
        w in tokens for w in ("precariously", "precarious", "balanced", "teetering", "fragile", "unstable")
    ) or any(f" {w} the edge" in f" {joined}" for w in ("on", "over", "off"))  # "near the edge": a place
    request.stable = any(w in tokens for w in ("stable", "secure", "securely", "safely"))
    request.diners = _diners(joined)


def _settle_counts(mentions: list[Mention], tokens: list[str]) -> None:
    """Counts the arrangement implies: stacks and rows of given sizes, one-per pairings."""
    for m in mentions:
        if m.arrangement in ("stack", "pile", "row", "column"):
            _arranged_count(m, tokens)
    for k, holder in enumerate(mentions):  # "six eggs in six egg cups": one in each (two each of twelve)
        for j in holder.contents:
            item = mentions[j] if j < len(mentions) else None
            if item is None or item.per is not None or holder.count < 2 or not holder.explicit_count or holder.stacked:
                continue
            if item.explicit_count and item.count % holder.count == 0:
                item.per = k
    for target in {m.per for m in mentions if m.per is not None}:  # as many targets as the things that each have one
        if mentions[target].explicit_count:
            continue
        before = [m.count for m in mentions[:target] if m.per == target]  # "a mug and a glass, each on its own coaster"
        after = [m.count for m in mentions[target + 1 :] if m.per == target]  # "plates, each with a fork and a knife"
        mentions[target].count = sum(before) if before else max(after)


def _arranged_count(m: Mention, tokens: list[str]) -> None:
    m.groups = min(m.groups, 8)
    m.sizes = tuple(max(1, min(size, 12)) for size in m.sizes[:8])  # no tower or row taller than the scene
    if m.sizes and len(m.sizes) < max(1, m.groups):
        m.sizes = (m.sizes[0],) * m.groups
    if m.sizes:
        m.count, m.explicit_count = sum(m.sizes), True
        m.groups = len(m.sizes)
    elif m.arrangement in ("stack", "pile") and (m.count > 1 or m.plural or m.groups):
        groups = max(1, m.groups)
        if m.explicit_count:
            m.sizes = _split(m.count, groups)
        else:
            height = 5 if "pyramid" in tokens else 4
            m.sizes = (height,) * groups
            m.count, m.explicit_count = height * groups, True
    elif m.arrangement in ("row", "column") and m.groups and m.explicit_count:
        m.sizes = _split(m.count, m.groups)
    if m.count < 2 and not m.plural:
        m.arrangement, m.stacked, m.sizes = ("" if m.arrangement != "scatter" else "scatter"), False, ()


def _split(count: int, groups: int) -> tuple[int, ...]:
    """`count` objects in `groups` groups as even as can be, larger groups first."""
    base, extra = divmod(count, groups)
    return tuple(base + (1 if g < extra else 0) for g in range(groups))


_ELABORATION = {",", "like", "such", "as", "including", "namely", "e", "g", "eg"}


def _spelled_out(mentions: list[Mention], tokens: list[str]) -> tuple[int, int] | None:
    """The tokens of a collective word the words go on to spell out, with what introduces the list ("fruit:",
    "fruit such as", "cutlery, namely"): "a basket of fruit: three apples, two pears and a banana" is a basket of
    three apples, two pears and a banana; "fruit and two apples" keeps the collective's other kinds."""
    for m in mentions:
        if not m.collective and tokens[m.end - 1] not in COLLECTIVES:  # "a bowl of fruit" is read as one phrase
            continue
        end = m.end
        while end < len(tokens) and tokens[end] in _ELABORATION:
            end += 1
        listed = next((o for o in mentions if not o.collective and o.start >= m.end), None)
        if end == m.end or listed is None or listed.start > end:
            continue
        group = COLLECTIVES.get(tokens[m.end - 1], ())
        if any(o.category in group for o in mentions if o.start >= m.end):
            return m.end - 1, end
    return None


def _diners(joined: str) -> int:
    match = re.search(
        r"(?:set(?: up)? for|dinner for|for|table for|meal for|places? for|settings? for) "
        r"(\w+) (?:people|persons|guests|diners)",
        joined,
    )
    if not match:
        match = re.search(r"(?:dinner|lunch|breakfast|meal|table|table set|laid) for (\w+)\b", joined)
    if not match:
        return 0
    word = match.group(1)
    return int(word) if word.isdigit() else NUMBERS.get(word, 0)
