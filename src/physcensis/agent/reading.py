"""Read a scene prompt: which objects, how many, and how they relate (in, on, stacked, beside, centred).

A small, deterministic reader over the catalogue's own vocabulary (categories, kinds
and synonyms), so any object the catalogue knows by name is understood; unknown
nouns after a number ("three widgets") still become objects for retrieval's
generated fallback.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field

from physcensis.assets.catalogue import Catalogue

# Words that name an exact number of things.
NUMERALS = {
    "two": 2,
    "three": 3,
    "four": 4,
    "five": 5,
    "six": 6,
    "seven": 7,
    "eight": 8,
    "nine": 9,
    "ten": 10,
    "eleven": 11,
    "twelve": 12,
    "dozen": 12,
}
# Every word the reader takes as a count, exact or loose ("a few", "several", "both").
NUMBERS = {
    **NUMERALS,
    "a": 1,
    "an": 1,
    "one": 1,
    "single": 1,
    "pair": 2,
    "couple": 2,
    "few": 3,
    "several": 4,
    "some": 3,
    "many": 6,
    "lots": 6,
    "both": 2,
}
# Words that name scenes, supports or contents, never objects to place.
NOT_OBJECTS = {
    ("table",),
    ("desk",),
    ("counter",),
    ("shelf",),
    ("floor",),
    ("room",),
    ("kitchen",),
    ("people",),
    ("person",),
    ("dinner",),
    ("breakfast",),
    ("lunch",),
    ("picnic",),
    ("spread",),
    ("tabletop",),
    ("orange", "juice"),
    ("apple", "juice"),
    ("coffee",),
    ("tea",),
    ("juice",),
    ("jam",),
    ("oil",),
    ("spices",),
    ("spice",),
    ("soda",),
    ("water",),
    ("wine",),
    ("milk",),
    ("cereal",),
    ("soup",),
    ("set",),
    ("pantry",),
    ("bathroom",),
    ("kids",),
    ("student",),
    ("everything",),
    ("school",),
    ("middle",),
    ("center",),
    ("centre",),
    ("side",),
    ("edge",),
    ("rim",),
    ("rows",),
    ("row",),
    ("top",),
    ("pyramid",),
    ("stack",),
    ("pile",),
    ("sizes",),
    ("dishes",),
    ("cutlery",),
    ("utensils",),
    ("silverware",),
    ("toys",),
    ("objects",),
    ("items",),
    ("things",),
    ("stuff",),
    ("fruit",),
    ("office",),
    ("bookshelf",),
}
# Collective words that stand for several categories.
COLLECTIVES = {
    "cutlery": ("fork", "knife", "spoon"),
    "silverware": ("fork", "knife", "spoon"),
    "utensils": ("fork", "knife", "spoon"),
    "dishes": ("plate",),
    "fruit": ("apple", "orange", "banana"),
    "toys": ("toy block", "ball", "toy truck"),
}
CONTENT_WORDS = ("full of", "packed with", "filled with", "containing", "stuffed with", "loaded with")
STACK_WORDS = ("stack", "stacked", "piled", "pile", "pyramid", "tower", "heap")
CENTRE_WORDS = ("in the middle", "in the center", "in the centre", "centre of", "center of")
BESIDE_WORDS = ("next to", "beside", "alongside", "by the")
RIM_WORDS = ("across its rim", "across the rim", "on its rim")
IN_WORDS = ("in", "inside", "into")  # the last word before a container something is in
ON_WORDS = ("on", "onto", "atop", "across")  # the last word before what something rests on
LIST_JOINS = (",", "and", ", and", "or")
STOP = {
    "the",
    "and",
    "with",
    "of",
    "on",
    "in",
    "a",
    "an",
    "for",
    "to",
    "its",
    "it",
    "some",
    "very",
    "up",
    "at",
    "around",
    "inside",
    "into",
    "onto",
    "is",
    "are",
    "that",
    "which",
    "there",
    "other",
    "each",
    "every",
    "as",
    "possible",
    "top",
    "across",
    "resting",
    "after",
    "waiting",
    "be",
}


@dataclass
class Mention:
    category: str
    count: int
    phrase: str  # the words that named it, singular ("wine glass")
    adjectives: tuple[str, ...]
    start: int  # token span
    end: int
    plural: bool
    explicit_count: bool
    contents: list[int] = field(default_factory=list)  # mentions inside it
    on: int | None = None  # the mention it rests on
    beside: int | None = None
    stacked: bool = False
    centre: bool = False
    around: int | None = None  # arranged around this mention
    per: int | None = None  # one of these per instance of that mention ("sandwiches on plates")


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


def tokenize(text: str) -> list[str]:
    return [t if t not in (":", ";", ".") else "," for t in re.findall(r"[a-z]+(?:'[a-z]+)?|\d+|[,:;.]", text.lower())]


def singular(word: str) -> str:
    if len(word) <= 3 or word.endswith("ss") or word.endswith("us"):
        return word
    if word.endswith("ies"):
        return word[:-3] + "y"
    if word.endswith("ves") and word not in ("gloves",):
        return word[:-3] + ("fe" if word in ("knives", "wives", "lives") else "f")
    if word.endswith(("ches", "shes", "xes", "sses", "oes")):
        return word[:-2]
    if word.endswith("s"):
        return word[:-1]
    return word


class Lexicon:
    """Phrases (tuples of singular words) -> catalogue category, longest match first."""

    def __init__(self, catalogue: Catalogue) -> None:
        self.phrases: dict[tuple[str, ...], str] = {}
        entries = catalogue.entries()
        for level in ("category", "kind", "synonym"):
            for e in entries:
                names = {"category": [e.category], "kind": [e.kind], "synonym": list(e.synonyms)}[level]
                for name in names:
                    key = tuple(singular(w) for w in tokenize(name) if w != ",")
                    if key and key not in self.phrases and key not in NOT_OBJECTS:
                        self.phrases[key] = e.category
        self.longest = max((len(k) for k in self.phrases), default=1)
        self.categories = sorted({e.category for e in entries})

    def match(self, tokens: list[str], i: int) -> tuple[str, int, str] | None:
        """(category, length, phrase) of the longest phrase starting at token i."""
        for n in range(min(self.longest, len(tokens) - i), 0, -1):
            raw = tuple(tokens[i : i + n])
            key = tuple(singular(w) for w in raw)
            if raw in NOT_OBJECTS or key in NOT_OBJECTS:
                return None
            category = self.phrases.get(raw) or self.phrases.get(key)
            if category:
                return category, n, " ".join(key)
        return None


def _count_before(tokens: list[str], i: int) -> tuple[int | None, int]:
    """The number word shortly before token i (skipping adjectives) and where the noun phrase starts."""
    j = i - 1
    start = i
    while (
        j >= 0
        and j >= i - 4
        and tokens[j] not in (",", "and", "with", "of", "on", "in")
        or (j >= 0 and tokens[j] == "of" and j >= 1 and tokens[j - 1] in ("pair", "couple", "lots", "dozen"))
    ):
        word = tokens[j]
        if word.isdigit():
            return int(word), j
        if word in NUMBERS:
            return NUMBERS[word], j
        start = j
        j -= 1
    return None, start


def read_prompt(text: str, lexicon: Lexicon) -> SceneRequest:
    tokens = tokenize(text)
    joined = " ".join(tokens)
    request = SceneRequest(mentions=[], tokens=tokens)
    request.messy = any(
        w in tokens for w in ("messy", "cluttered", "scattered", "untidy", "piled", "random", "chaotic", "strewn")
    )
    request.rows = "rows" in tokens or "row" in tokens or "aligned" in tokens or "lined" in tokens
    request.dense = (
        "as many" in joined
        or "very cluttered" in joined
        or "crammed" in tokens
        or ("packed" in tokens and "with" not in tokens)
        or "full of everything" in joined
    )
    request.fragile = any(
        w in tokens for w in ("precariously", "precarious", "balanced", "teetering", "edge", "fragile", "unstable")
    )
    request.stable = any(w in tokens for w in ("stable", "secure", "securely", "safely"))
    request.diners = _diners(joined)
    i = 0
    while i < len(tokens):
        word = tokens[i]
        if word in COLLECTIVES and not lexicon.match(tokens, i):
            count, start = _count_before(tokens, i)
            for category in COLLECTIVES[word]:
                request.mentions.append(
                    Mention(category, count or 1, category, (), start, i + 1, True, count is not None)
                )
            i += 1
            continue
        found = lexicon.match(tokens, i)
        if not found:
            i += 1
            continue
        category, n, phrase = found
        words = tokens[i : i + n]
        plural = any(singular(w) != w for w in words if w not in ("grapes", "chopsticks", "glass", "ss"))
        count, start = _count_before(tokens, i)
        if words[:2] == ["pair", "of"]:  # "a pair of chopsticks" is two chopsticks
            count, plural = 2 * (count or 1), True
        adjectives = tuple(w for w in tokens[start:i] if w not in STOP and w not in NUMBERS and not w.isdigit())
        explicit = count is not None
        if count is None:
            count = _default_count(category) if plural else 1
        request.mentions.append(
            Mention(category, max(1, min(count, 40)), phrase, adjectives, start, i + n, plural, explicit)
        )
        i += n
    request.mentions = [
        m
        for m in request.mentions
        if not (
            _from_collective(m, tokens)
            and any(o.category == m.category and not _from_collective(o, tokens) for o in request.mentions)
        )
    ]
    _relations(request, tokens)
    _settle_counts(request, tokens)
    return request


def _settle_counts(request: SceneRequest, tokens: list[str]) -> None:
    """Counts the prompt implies without saying: stacks, packed containers, one-per pairings."""
    mentions = request.mentions
    for m in mentions:
        if m.stacked and not m.explicit_count and m.category in STACKABLE:
            m.count = 5 if "pyramid" in tokens else 4 if m.category in ("plate", "book") else 3
    for m in mentions:
        if m.contents and any(w in " ".join(tokens) for w in ("packed", "full of", "filled", "crammed")):
            for j in m.contents:
                if not mentions[j].explicit_count and mentions[j].plural:
                    mentions[j].count = 2 * mentions[j].count
    for m in mentions:
        if m.per is not None and not mentions[m.per].explicit_count:
            mentions[m.per].count = m.count


def _from_collective(m: Mention, tokens: list[str]) -> bool:
    return any(tokens[t] in COLLECTIVES for t in range(m.start, min(m.end, len(tokens))))


def _diners(joined: str) -> int:
    match = re.search(
        r"(?:set(?: up)? for|dinner for|for|table for|meal for|places? for|settings? for) "
        r"(\w+) (?:people|persons|guests|diners)",
        joined,
    )
    if not match:
        match = re.search(r"(?:dinner|lunch|breakfast|meal|table) for (\w+)\b", joined)
    if not match:
        return 0
    word = match.group(1)
    return int(word) if word.isdigit() else NUMBERS.get(word, 0)


def _default_count(category: str) -> int:
    small = {"pencil", "pen", "toy block", "can", "apple", "orange", "jar", "bottle", "book", "ball"}
    return 4 if category in ("toy block",) else 3 if category in small else 2


def _between(tokens: list[str], a: Mention, b: Mention) -> str:
    return " ".join(tokens[a.end : b.start])


def _relations(request: SceneRequest, tokens: list[str]) -> None:
    mentions = request.mentions
    _mark_stacks_and_centres(mentions, tokens)
    _link_contents(mentions, tokens)
    for k in range(len(mentions) - 1):
        _link_neighbours(mentions, tokens, k)
    _link_rims_and_rings(mentions, tokens)


def _mark_stacks_and_centres(mentions: list[Mention], tokens: list[str]) -> None:
    for m in mentions:
        before = tokens[max(0, m.start - 4) : m.start]
        after = " ".join(tokens[m.end : m.end + 6])
        if any(w in before for w in STACK_WORDS) or after.startswith(("stacked", "piled", "in a stack", "in a pile")):
            m.stacked = True
        if any(after.startswith(w) or f" {w}" in " " + after[:20] for w in CENTRE_WORDS):
            m.centre = True


def _link_contents(mentions: list[Mention], tokens: list[str]) -> None:
    """Containers and surfaces followed by their contents: "a bowl full of apples and oranges", "a pen holder with
    six pens", "a cutting board full of apples" (a surface needs a word like "full of"; "a tray with" is no link)."""
    k = 0
    while k < len(mentions) - 1:
        if _holds_what_follows(tokens, mentions[k], mentions[k + 1]):
            k = _take_listed(mentions, tokens, k) + 1
        else:
            k += 1


def _holds_what_follows(tokens: list[str], holder: Mention, first: Mention) -> bool:
    if holder.category not in CONTAINERS | SURFACES:
        return False
    link = _between(tokens, holder, first)
    if any(w in link for w in CONTENT_WORDS):
        return True
    return link in ("of", "with") and (
        "inside" in " ".join(tokens[first.end : first.end + 12]) or holder.category in CONTAINERS
    )


def _take_listed(mentions: list[Mention], tokens: list[str], k: int) -> int:
    """Put the list of mentions after mention k ("apples, pears and plums") on or into it; the list's last index."""
    holder = mentions[k]
    j = k + 1
    while True:
        if holder.category in SURFACES:
            mentions[j].on = k
        else:
            holder.contents.append(j)
        if j + 1 >= len(mentions) or _between(tokens, mentions[j], mentions[j + 1]) not in LIST_JOINS:
            return j
        j += 1


def _link_neighbours(mentions: list[Mention], tokens: list[str], k: int) -> None:
    """The relation the words between mention k and the next one name, if any."""
    m, nxt = mentions[k], mentions[k + 1]
    link = _between(tokens, m, nxt)
    words = link.split()
    last = words[-1] if words else ""
    if "with" in words and "on it" in " ".join(tokens[nxt.end : nxt.end + 3]):
        nxt.on = k  # "a notebook with a pen on it"
    elif (
        last in IN_WORDS
        and not any(w in link for w in CENTRE_WORDS)
        and nxt.category in CONTAINERS
        and k not in nxt.contents
    ):
        nxt.contents.append(k)  # "a toothbrush in a cup"
    elif (last in ON_WORDS or "on top of" in link or "edge of" in link) and m.on is None:
        m.on = k + 1
        if m.plural and nxt.plural:
            m.per = k + 1  # "sandwiches on plates", "cups on saucers"
    elif any(w in link for w in BESIDE_WORDS):
        m.beside = k + 1


def _link_rims_and_rings(mentions: list[Mention], tokens: list[str]) -> None:
    """ "a spoon across its rim" rests on the last container before it; "chairs around it" ring the last centred or
    free-standing mention before them."""
    for k, m in enumerate(mentions):
        after = " ".join(tokens[m.end : m.end + 5])
        if any(w in after for w in RIM_WORDS):
            holder = _last_before(mentions, k, lambda o: o.category in CONTAINERS)
            if holder is not None:
                m.on = holder
        if "around it" in after or "around the" in after:
            m.around = _last_before(mentions, k, lambda o: o.centre or o.on is None)


def _last_before(mentions: list[Mention], k: int, wanted: Callable[[Mention], bool]) -> int | None:
    """The index of the nearest mention before k that is `wanted`."""
    return next((j for j in range(k - 1, -1, -1) if wanted(mentions[j])), None)


STACKABLE = {"plate", "bowl", "book", "box", "cup", "saucer", "tray", "notebook", "toy block", "napkin", "towel"}
CONTAINERS = {
    "bowl",
    "box",
    "basket",
    "pen holder",
    "cup",
    "mug",
    "glass",
    "jar",
    "pot",
    "vase",
    "pan",
    "pencil case",
    "pitcher",
}
SURFACES = {"plate", "tray", "saucer", "cutting board"}
