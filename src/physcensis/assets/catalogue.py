"""The asset catalogue the solver uses: built-in procedural assets plus user libraries.

Built-in assets are generated lazily on first use and cached on disk; search
needs only their text.  `resolve` turns a description into one asset, falling
back to a generated one when nothing matches well enough.
"""

from __future__ import annotations

import logging
import multiprocessing
from collections.abc import Iterable, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from physcensis.assets.build import asset_id, build_asset
from physcensis.assets.builtin import CATEGORY_DEFS
from physcensis.assets.cache import AssetCache, generator_fingerprint
from physcensis.assets.errors import AssetError
from physcensis.assets.fallback import generate
from physcensis.assets.model import Asset, Vec3
from physcensis.assets.retrieval import EmbeddingRetriever, LexicalRetriever, SearchHit, make_retriever
from physcensis.assets.spec import CategoryDef, Variant
from physcensis.assets.text import parse_dimensions, terms
from physcensis.ids import pinned_id

log = logging.getLogger(__name__)
LIBRARY_BONUS = 1.05  # a user's own asset wins ties (and near ties) over a built-in one
KEPT_SEARCHES = 4096  # (description, k) whose ranking a catalogue keeps: a batch asks the same ones scene after scene


def _plain_name(text: str) -> str:
    """A name without case, an article or extra spaces: "A Soda Can" -> "soda can"."""
    words = text.lower().split()
    if words and words[0] in ("a", "an", "the", "one"):
        words = words[1:]
    return " ".join(words)


@dataclass(frozen=True)
class Entry:
    """A catalogue row: an asset's text and size, without its geometry."""

    id: str
    category: str
    kind: str
    description: str
    tags: tuple[str, ...]
    synonyms: tuple[str, ...]
    size: Vec3
    source: str
    definition: tuple[CategoryDef, Variant] | None = None  # built-in generator and variant
    canonical: bool = False  # the first variant of its kind: preferred for plain queries

    @property
    def builtin(self) -> bool:
        return self.definition is not None

    @property
    def prior(self) -> float:
        """Retrieval's weight for this entry: the first variant of a kind wins plain queries; a user's asset wins
        ties with built-in ones."""
        return LIBRARY_BONUS if not self.builtin else 1.0


def builtin_entries(defs: Iterable[CategoryDef] = CATEGORY_DEFS) -> list[Entry]:
    entries = []
    for cat in defs:
        for i, v in enumerate(cat.variants):
            entries.append(
                Entry(
                    asset_id(cat, v),
                    cat.category,
                    cat.kind,
                    v.description,
                    tuple(dict.fromkeys((*cat.tags, *v.tags))),
                    tuple(dict.fromkeys((*cat.synonyms, *v.synonyms))),
                    v.size,
                    "builtin",
                    (cat, v),
                    canonical=i == 0,
                )
            )
    return entries


def _cache_key(entry: Entry) -> str:
    return f"{entry.id}-{generator_fingerprint()}"


class Catalogue:
    """Built-in assets plus user libraries, with lookup, search and resolution.

    `cache=None` uses the per-user cache directory; pass `cache=False` to build in
    memory only.  `retrieval` is "lexical" (default, offline) or "embedding".
    """

    def __init__(
        self,
        libraries: Sequence[str | Path] = (),
        *,
        builtin: bool = True,
        cache: AssetCache | bool | None = None,
        retrieval: str = "lexical",
    ) -> None:
        self.cache: AssetCache | None = AssetCache() if cache is None or cache is True else (cache or None)
        self.retrieval = retrieval
        self._entries: dict[str, Entry] = {}
        self._assets: dict[str, Asset] = {}
        self._retriever: LexicalRetriever | EmbeddingRetriever | None = None
        self._names: dict[str, tuple[str, list[frozenset[str]]]] | None = None  # user assets' names, on first search
        self._id_set: frozenset[str] | None = None
        self._described: dict[str, str] | None = None  # each asset's own description (plain) -> its id, on first use
        self._ranked: dict[tuple[str, str, int], list[SearchHit]] = {}  # rankings kept until the contents change
        self.errors: list[AssetError] = []
        if builtin:
            for entry in builtin_entries():
                self._entries[entry.id] = entry
        for folder in libraries:
            self.add_library(folder)

    # -- contents -----------------------------------------------------------------
    def add_library(self, folder: str | Path) -> list[AssetError]:
        """Load a user library; its broken entries are returned (and kept in `errors`), the rest is added.
        A library that cannot be read at all raises LibraryError."""
        from physcensis.assets.library import load_library

        result = load_library(folder, cache=self.cache)
        for asset in result.assets:
            if asset.id in self._entries:
                err = AssetError(f"{folder}: asset id {asset.id!r} is already in the catalogue; skipped")
                result.errors.append(err)
                continue
            self._add(asset)
        self.errors.extend(result.errors)
        return result.errors

    def _add(self, asset: Asset) -> None:
        self._entries[asset.id] = Entry(
            asset.id,
            asset.category,
            asset.kind,
            asset.description,
            asset.tags,
            asset.synonyms,
            asset.size,
            asset.source,
        )
        self._assets[asset.id] = asset
        self._retriever, self._names, self._id_set, self._described = None, None, None, None
        self._ranked.clear()

    def with_assets(self, assets: Iterable[Asset]) -> Catalogue:
        """A copy of this catalogue in which `assets` (a scene's own copies of them) replace those of the same id."""
        copy = Catalogue(builtin=False, cache=self.cache or False, retrieval=self.retrieval)
        copy._entries, copy._assets, copy.errors = dict(self._entries), dict(self._assets), list(self.errors)
        for asset in assets:
            copy._add(asset)
        return copy

    def is_builtin(self, asset_id: str) -> bool:
        """Whether the asset is one of the procedural built-ins (False for library and unknown ids)."""
        entry = self._entries.get(asset_id)
        return entry is not None and entry.builtin

    def entries(self) -> list[Entry]:
        return list(self._entries.values())

    def ids(self) -> list[str]:
        return list(self._entries)

    def id_set(self) -> frozenset[str]:
        """Every id, for membership tests (what the program checker validates pinned assets against)."""
        if self._id_set is None:
            self._id_set = frozenset(self._entries)
        return self._id_set

    def categories(self) -> list[str]:
        return sorted({e.category for e in self._entries.values()})

    def __len__(self) -> int:
        return len(self._entries)

    def __contains__(self, asset_id: object) -> bool:
        return asset_id in self._entries

    def entry(self, asset_id: str) -> Entry:
        try:
            return self._entries[asset_id]
        except KeyError:
            raise AssetError(f"no asset with id {asset_id!r} (see `physcensis assets list`)") from None

    def get(self, asset_id: str) -> Asset:
        """The asset with this id, generated (or loaded from the cache) on first use."""
        if asset_id in self._assets:
            return self._assets[asset_id]
        entry = self.entry(asset_id)
        assert entry.definition is not None
        asset = self._load_or_build(entry)
        self._assets[asset_id] = asset
        return asset

    def _load_or_build(self, entry: Entry) -> Asset:
        key = _cache_key(entry)
        if self.cache is not None:
            cached = self.cache.load(key)
            if cached is not None:
                return cached
        assert entry.definition is not None
        asset = build_asset(*entry.definition)
        if self.cache is not None:
            self.cache.store(key, asset)
        return asset

    def all(self) -> list[Asset]:
        return [self.get(i) for i in self._entries]

    # -- retrieval ----------------------------------------------------------------
    @property
    def retriever(self) -> LexicalRetriever | EmbeddingRetriever:
        if self._retriever is None:
            self._retriever = make_retriever(self.retrieval, self.entries())
        return self._retriever

    def hits(self, description: str, k: int = 5) -> list[SearchHit]:
        """Ranked matches (ids and scores only; no geometry is built). First an asset whose id is the query, then
        the user's assets that the query names whole: their description, or words all found in one of their names
        ("duck" for a library's "toy duck", "milk" for its "milk carton"); then retrieval's ranking."""
        key = (self.retrieval, description, k)
        ranked = self._ranked.get(key)
        if ranked is None:
            ranked = self.retriever.search(description, k)
            if len(self._ranked) >= KEPT_SEARCHES:
                self._ranked.clear()
            self._ranked[key] = ranked
        ranked = list(ranked)
        exact = self._exact_matches(description)
        if not exact:
            return ranked
        first = [SearchHit(asset_id, 1.0, 1.0, float("inf"), True) for asset_id in exact[:k]]
        return first + [h for h in ranked if h.asset_id not in exact][: k - len(first)]

    def _exact_matches(self, description: str) -> list[str]:
        query = _plain_name(description)
        if not query:
            return []
        if query in self._entries:
            return [query]
        if self._names is None:
            self._names = self._user_names()
        asked = frozenset(t for t in terms(query) if "_" not in t)
        if not asked:
            return []
        return [
            asset_id
            for asset_id, (described, names) in self._names.items()
            if query == described or any(asked <= name for name in names)
        ]

    def _own_description(self, description: str) -> str | None:
        """The asset whose own description this is (case, an article and spacing aside), or None. The planner
        describes the variants it draws in their own words; 62 of the 2,104 built-in ones did not resolve back to
        themselves (a head noun such as "tube" or "wedge", a size in inches read as a resize)."""
        if self._described is None:
            described: dict[str, str] = {}
            for entry in sorted(self._entries.values(), key=lambda e: e.id):
                described.setdefault(_plain_name(entry.description), entry.id)
            self._described = described
        return self._described.get(_plain_name(description))

    def _user_names(self) -> dict[str, tuple[str, list[frozenset[str]]]]:
        """Each user asset's description (as a plain name) and names (as sets of content words), in id order."""
        out = {}
        for e in sorted((e for e in self._entries.values() if not e.builtin), key=lambda e: e.id):
            names = [frozenset(t for t in terms(n) if "_" not in t) for n in (e.category, e.kind, *e.synonyms)]
            out[e.id] = (_plain_name(e.description), [n for n in names if n])
        return out

    def search(self, description: str, k: int = 5) -> list[tuple[Asset, float]]:
        """The k best assets for a description with their relevance in [0, 1]."""
        return [(self.get(h.asset_id), h.score) for h in self.hits(description, k)]

    def resolve(self, description: str) -> Asset:
        """One asset for a description (see `_resolve`); generated assets are kept so `get` finds them."""
        asset = self._resolve(description)
        self._assets.setdefault(asset.id, asset)
        return self._assets[asset.id]

    def _resolve(self, description: str) -> Asset:
        """One asset for a description: the asset it pins ("asset:ID"), the best match, resized when the
        description gives dimensions, or a generated asset when no match is confident enough (a name that only
        shares a word with it, such as "label maker" and "waffle maker", is not resized into it)."""
        pinned = pinned_id(description)
        if pinned is not None:
            return self.get(pinned)
        own = self._own_description(description)
        if own is not None:  # an asset's own words name it, whatever retrieval makes of them ("a pink tube of ...")
            return self.get(own)
        hits = self.hits(description, 5)
        top = hits[0] if hits else None
        confident = top is not None and top.name_match and top.confidence >= self.retriever.threshold
        template = self._template(top) if confident and top is not None else None
        if confident and top is not None and not parse_dimensions(description):
            return self.get(top.asset_id)
        if template is not None:
            log.info("resolve %r: re-generating %s at the requested size", description, top.asset_id if top else "?")
            return generate(description, template)
        log.info(
            "resolve %r: no confident match (best %s); generating a generic asset",
            description,
            f"{top.asset_id} at {top.confidence:.2f}" if top else "none",
        )
        return generate(description, None)

    def asset_for(self, asset_id: str, description: str) -> Asset:
        """The asset a scene names: by id, or re-generated from its object's description."""
        if asset_id in self._assets or asset_id in self._entries:
            return self.get(asset_id)
        asset = self.resolve(description)
        if asset.id != asset_id:
            raise AssetError(
                f"no asset with id {asset_id!r}; its description resolves to {asset.id!r} instead "
                "(was it made with a user library that is not loaded?)"
            )
        return asset

    def variants(self, description: str, k: int = 8, *, close: float = 0.0) -> list[Asset]:
        """Confident matches of the best hit's category, for variety among repeated objects (only the pinned asset for
        a description that pins one). `close`: only those scoring at least this share of the best hit (a wine bottle's
        category also holds shampoo and water bottles, which "a wine bottle" does not describe)."""
        if pinned_id(description) is not None:
            return [self.resolve(description)]
        hits = [h for h in self.hits(description, k) if h.name_match]
        if not hits:
            return [self.resolve(description)]
        category = self.entry(hits[0].asset_id).category
        floor = close * hits[0].score
        return [self.get(h.asset_id) for h in hits if self.entry(h.asset_id).category == category and h.score >= floor]

    def _template(self, hit: SearchHit) -> tuple[CategoryDef, Variant] | None:
        entry = self._entries.get(hit.asset_id)
        return entry.definition if entry is not None else None


_default: tuple[tuple[object, ...], Catalogue] | None = None  # (the configured libraries, their catalogue)


def default_catalogue() -> Catalogue:
    """The built-in catalogue plus every configured user library (see `libraries.py`), with the per-user disk cache,
    shared within a process while the configured libraries stay the same.  A configured library that cannot be read
    is kept in `errors`, not raised: the commands warn about it and go on with the rest."""
    global _default
    from physcensis.assets.libraries import configured_libraries

    try:
        folders, problem = tuple(configured_libraries()), None
    except AssetError as exc:  # an unreadable config file: say so, use the rest
        folders, problem = (), exc
    key = (*folders, str(problem))
    if _default is not None and _default[0] == key:
        return _default[1]
    catalogue = Catalogue()
    if problem is not None:
        catalogue.errors.append(problem)
    for folder in folders:
        try:
            catalogue.add_library(folder)
        except AssetError as exc:
            catalogue.errors.append(exc)
    _default = (key, catalogue)
    return catalogue


def builtin_cache_paths(cache: AssetCache) -> dict[str, Path]:
    """Where each built-in asset's entry is (or would be) in `cache`, by id."""
    return {entry.id: cache.path(_cache_key(entry)) for entry in builtin_entries()}


def warm_builtin_cache(cache: AssetCache | None = None, workers: int = 2) -> int:
    """Build the built-in assets missing from the disk cache on `workers` processes (on one core a cold cache costs
    minutes) and return how many were missing.  One that fails to build is logged and left out: its first user builds
    it again and sees the error."""
    cache = cache if cache is not None else AssetCache()
    missing = [ident for ident, path in builtin_cache_paths(cache).items() if not path.is_file()]
    if workers <= 1 or len(missing) < 2:
        _build_into(str(cache.root), missing)
        return len(missing)
    count = 8 * workers  # interleaved shares: neighbouring variants cost alike, so every share costs about the same
    shares = [missing[k::count] for k in range(count)]
    with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn")) as pool:  # spawn: no threads
        list(pool.map(_build_into, [str(cache.root)] * count, shares))
    return len(missing)


def _build_into(root: str, ids: list[str]) -> None:
    catalogue = Catalogue(cache=AssetCache(root))
    for ident in ids:
        try:
            catalogue.get(ident)
        except Exception as exc:  # its user rebuilds it and reports the error where it matters
            log.warning("asset %s: cannot build (%s: %s)", ident, exc.__class__.__name__, exc)


def use_libraries(folders: Sequence[str | Path]) -> Catalogue:
    """Make `folders` (a command's --library options) part of the default catalogue, and return it."""
    from physcensis.assets.libraries import choose_libraries

    choose_libraries(folders)
    return default_catalogue()
