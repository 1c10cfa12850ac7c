"""Text helpers for retrieval: tokens, a small rule-based lemmatiser, head-noun weighting, sizes."""

from __future__ import annotations

import functools
import itertools
import re

STOPWORDS = frozenset(
    """
a an the of and or with without for to in on at by from into onto over under near next beside behind between
its it this that these those some any each every one two three four five six seven eight nine ten few several
many much lots lot is are be being has have having very really quite just kind sort type piece pieces set pair
pairs stack bunch couple full filled containing holding made look looks looking like style
mm cm m in inch metre meter centimetre centimeter millimetre millimeter about around approximately
""".split()
)
# Words that do not name the object: weak evidence either way.
MODIFIERS = frozenset(
    """
small large big little tiny huge giant tall short long wide narrow thick thin flat round square rectangular
heavy light old new empty clean dirty open closed shiny plain simple classic modern vintage standard regular
""".split()
)
QUANTITY_HEADS = frozenset(
    {"pair", "set", "stack", "bunch", "loaf", "slice", "piece", "couple", "pile", "handful", "row", "box", "pack"}
)
RELATION_WORDS = frozenset(
    {
        "for",
        "to",
        "hold",
        "on",
        "in",
        "with",
        "beside",
        "next",
        "near",
        "under",
        "inside",
        "atop",
        "holding",
        "containing",
        "filled",
        "full",
        "behind",
        "against",
    }
)
IRREGULAR = {  # plurals
    "knives": "knife",
    "leaves": "leaf",
    "loaves": "loaf",
    "shelves": "shelf",
    "mice": "mouse",
    "teeth": "tooth",
    "potatoes": "potato",
    "tomatoes": "tomato",
    "children": "child",
    "halves": "half",
    "glasses": "glass",
    "dishes": "dish",
    "boxes": "box",
    "cacti": "cactus",
    "people": "person",
    "wolves": "wolf",
    "scarves": "scarf",
    "ceramics": "ceramic",
}
# One thing said another way (not a plural: "a drawer organizer" is one organiser).
SPELLINGS = {
    "gray": "grey",
    "color": "colour",
    "colored": "coloured",
    "aluminum": "aluminium",
    "organizer": "organiser",
    "cellphone": "phone",
    "smartphone": "phone",
    "tv": "television",
    "stainless": "steel",
}
_KEEP_S = ("ss", "us", "is", "ys")
# Nouns in -ie, whose plural in -ies is not a -y word's ("cookies": cookie, not cooky; "candies": candy).
_IE_NOUNS = frozenset(
    """cookie brownie smoothie hoodie beanie zombie movie calorie rookie goalie selfie sweetie pixie genie collie
    birdie nightie veggie bootie onesie necktie bowtie goodie freebie magpie boogie talkie walkie budgie""".split()
)
_TOKEN = re.compile(r"[a-z0-9]+")
DOWNWEIGHT = 0.3


def plural(word: str) -> str:
    """The plural of a lowercase singular noun, by rule ("glass": glasses, "knife": knives, "battery": batteries)."""
    if word.endswith(("s", "sh", "ch", "x", "z")):
        return word + "es"
    if word.endswith("fe"):
        return word[:-2] + "ves"
    if word.endswith("y") and not word.endswith(("ay", "ey", "oy", "uy")):
        return word[:-1] + "ies"
    return word + "s"


@functools.lru_cache(maxsize=1 << 16)  # indexing the catalogue asks for the same words a hundred thousand times
def lemma(word: str) -> str:
    """Singular, normalised form of a lowercase word (rule based: plurals and a few spellings)."""
    if word in IRREGULAR:
        return IRREGULAR[word]
    if len(word) > 4 and word.endswith("ies"):
        return word[:-1] if word[:-1] in _IE_NOUNS else word[:-3] + "y"
    if len(word) > 4 and word.endswith(("sses", "ches", "shes", "xes", "zzes", "tzes")):
        return word[:-2]  # "glasses", "boxes", "waltzes" ("sizes", "prizes" keep their e)
    if len(word) > 3 and word.endswith("s") and not word.endswith(_KEEP_S):
        word = word[:-1]
    return SPELLINGS.get(word, word)  # "organizers": organiser


def words(text: str) -> list[str]:
    return [lemma(w) for w in _TOKEN.findall(text.lower())]


def terms(text: str) -> list[str]:
    """Content words (lemmatised, stopwords removed) plus bigrams of neighbouring content words."""
    return list(_terms(text))


@functools.lru_cache(maxsize=1 << 14)  # indexing the catalogue asks for the same names again and again
def _terms(text: str) -> tuple[str, ...]:
    content = [w for w in words(text) if w not in STOPWORDS and not any(ch.isdigit() for ch in w)]
    return (*content, *(f"{a}_{b}" for a, b in itertools.pairwise(content)))


def head_phrase(text: str) -> list[str]:
    """The content words that say what the query is, its noun last: those before "of" (not after a quantity: "a box
    of gelatin" keeps going), a relation word or a relative clause ("some vegetables"; "a rolling blade for slicing
    pizza": rolling, blade; "a blue present wrapped with a ribbon": blue, present, wrapped)."""
    content: list[str] = []
    for w in words(text):
        if content and w == "of" and content[-1] in QUANTITY_HEADS:
            continue
        if content and (w == "of" or w in RELATION_WORDS or w in ("that", "which", "who", "where")):
            break
        if w not in STOPWORDS and not any(ch.isdigit() for ch in w):
            content.append(w)
    return content


def query_weights(text: str) -> dict[str, float]:
    """Weighted query terms: the head phrase counts fully, words after "of", "in", "with"... less.

    "a bowl of apples" is a bowl; "a pair of chopsticks" is chopsticks (quantity
    heads such as pair, stack, slice do not demote what follows).
    """
    raw = words(text)
    weights: dict[str, float] = {}
    weight = 1.0
    previous: str | None = None
    content: list[tuple[str, float]] = []  # (word, weight) of the content words so far
    for w in raw:
        if content and ((w == "of" and content[-1][0] not in QUANTITY_HEADS) or w in RELATION_WORDS):
            weight = DOWNWEIGHT
        if w in STOPWORDS or any(ch.isdigit() for ch in w):
            previous = None
            continue
        factor = 0.4 if w in MODIFIERS else 1.0
        content.append((w, weight * factor))
        weights[w] = max(weights.get(w, 0.0), weight * factor)
        if previous is not None:
            bigram = f"{previous}_{w}"
            weights[bigram] = max(weights.get(bigram, 0.0), weight)
        previous = w
    return weights


_UNITS = {
    "mm": 0.001,
    "millimetre": 0.001,
    "millimeter": 0.001,
    "cm": 0.01,
    "centimetre": 0.01,
    "centimeter": 0.01,
    "m": 1.0,
    "metre": 1.0,
    "meter": 1.0,
    "in": 0.0254,
    "inch": 0.0254,
    "inche": 0.0254,
}
_NUMBER = r"(\d+(?:\.\d+)?)"
_TRIPLE = re.compile(_NUMBER + r"\s*[x×*]\s*" + _NUMBER + r"\s*[x×*]\s*" + _NUMBER + r"\s*(mm|cm|m|in)\b")
_PAIR = re.compile(_NUMBER + r"\s*[x×*]\s*" + _NUMBER + r"\s*(mm|cm|m|in)\b")
_SINGLE = re.compile(
    _NUMBER + r"\s*-?\s*(mm|cm|m|in|inch|inches|millimetres?|millimeters?|centimetres?|centimeters?|metres?|meters?)\b"
    r"(?:\s+(tall|high|long|wide|deep|across|diameter|in diameter))?"
)


def _unit(name: str) -> float:
    return _UNITS.get(name.rstrip("s") if name not in ("m", "in") else name, _UNITS.get(name, 1.0))


def parse_dimensions(text: str) -> dict[str, float]:
    """Dimensions written in a description, in metres.

    Returns keys among x, y, z (full triple "20x10x5 cm" = x, y, z; a pair is
    x, y), height, length, width, diameter, or size (a bare "30 cm").
    """
    lower = text.lower()
    m = _TRIPLE.search(lower)
    if m:
        s = _unit(m.group(4))
        return {"x": float(m.group(1)) * s, "y": float(m.group(2)) * s, "z": float(m.group(3)) * s}
    m = _PAIR.search(lower)
    if m:
        s = _unit(m.group(3))
        return {"x": float(m.group(1)) * s, "y": float(m.group(2)) * s}
    out: dict[str, float] = {}
    for m in _SINGLE.finditer(lower):
        value = float(m.group(1)) * _unit(m.group(2))
        word = m.group(3) or ""
        key = {
            "tall": "height",
            "high": "height",
            "long": "length",
            "wide": "width",
            "deep": "depth",
            "across": "diameter",
            "diameter": "diameter",
            "in diameter": "diameter",
        }.get(word, "size")
        out.setdefault(key, value)
    return out


SIZE_WORDS: dict[str, tuple[float, float, float]] = {
    "tiny": (0.5, 0.5, 0.5),
    "mini": (0.6, 0.6, 0.6),
    "small": (0.75, 0.75, 0.75),
    "little": (0.75, 0.75, 0.75),
    "large": (1.35, 1.35, 1.35),
    "big": (1.35, 1.35, 1.35),
    "huge": (1.8, 1.8, 1.8),
    "giant": (2.0, 2.0, 2.0),
    "tall": (1.0, 1.0, 1.5),
    "short": (1.0, 1.0, 0.7),
    "long": (1.5, 1.0, 1.0),
    "wide": (1.0, 1.4, 1.0),
    "flat": (1.0, 1.0, 0.35),
    "thin": (1.0, 1.0, 0.5),
    "thick": (1.0, 1.0, 1.5),
}


def size_factors(text: str) -> tuple[float, float, float]:
    """Multiplicative (x, y, z) scale from size words in a description."""
    fx = fy = fz = 1.0
    for w in words(text):
        if w in SIZE_WORDS:
            ax, ay, az = SIZE_WORDS[w]
            fx, fy, fz = fx * ax, fy * ay, fz * az
    return fx, fy, fz
