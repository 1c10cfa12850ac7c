"""The paper's ranking of methods: a vision model ranks the methods' renders of one prompt, best first.

Every group of rows that share a prompt and a seed (one render per method) is shown to the model several times
(`draws`), the pictures in a fresh seeded order each time so that no method gains from its place; the answer is read
as picture numbers, best first. A method's rank in a group is its mean over the draws that could be read (1 is
best); `mean_ranks` averages those over the groups. A draw whose answer names no full order is dropped and counted.
"""

from __future__ import annotations

import logging
import re
import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from physcensis.agent.base import AgentError
from physcensis.agent.vqa import image_message
from physcensis.fileio import read_in_folder
from physcensis.llm.client import LLMRequestError, RetryPolicy, chat_completion, reply_text
from physcensis.llm.providers import connect
from physcensis.settings import API_KEY_ENV, DEFAULT_PROVIDER

log = logging.getLogger(__name__)

DRAWS = 3
MAX_RENDER_BYTES = 16 * 2**20
RANK_KEY = "vlm_rank"  # the row metric: the method's mean rank in its group (1 is best)


def question(prompt: str, count: int) -> str:
    example = ", ".join(str(k) for k in range(count, 0, -1))
    return (
        f"These {count} pictures, numbered 1 to {count} in the order shown, are candidate 3-D scenes for the request: "
        f'"{prompt.strip()}". Rank them from best to worst by how well each shows what was asked and how physically '
        "plausible it is (everything resting, nothing floating or passing through anything). Answer with the "
        f"picture numbers only, best first, separated by commas, for example: {example}"
    )


def read_ranking(text: str, count: int) -> list[int] | None:
    """The picture numbers (0-based) in the order the answer gives, best first; the one left out last when all
    but one are named; None when the answer names no full order."""
    seen: list[int] = []
    for match in re.finditer(r"\d+", text):
        number = int(match.group()) - 1
        if 0 <= number < count and number not in seen:
            seen.append(number)
    if len(seen) == count - 1:
        seen += [k for k in range(count) if k not in seen]
    return seen if len(seen) == count else None


@dataclass
class GroupRanks:
    """One prompt and seed: each method's ranks over the draws read (1 is best), and the draws that were not."""

    prompt_id: str
    seed: int
    ranks: dict[str, list[int]] = field(default_factory=dict)
    unread: int = 0
    error: str | None = None

    def mean(self, method: str) -> float | None:
        values = self.ranks.get(method)
        return statistics.mean(values) if values else None


@dataclass(frozen=True)
class Ranker:
    """Asks `model` at `base_url` to rank pictures."""

    model: str
    base_url: str | None = None
    draws: int = DRAWS
    seed: int = 0
    timeout_s: float = 120.0
    api_key_env: str = API_KEY_ENV
    provider: str = DEFAULT_PROVIDER
    sleep: Callable[[float], None] = time.sleep

    def rank_group(self, prompt_id: str, seed: int, prompt: str, renders: dict[str, bytes]) -> GroupRanks:
        """The model's ranks of `renders` (method -> PNG), over `draws` shuffled showings."""
        group = GroupRanks(prompt_id, seed, {method: [] for method in renders})
        methods = sorted(renders)
        rng = np.random.default_rng([self.seed, seed, sum(map(ord, prompt_id))])
        try:
            server = connect(self.base_url, self.api_key_env, self.provider)
        except AgentError as exc:
            group.error = str(exc)
            return group
        try:
            for _ in range(self.draws):
                order = [methods[k] for k in rng.permutation(len(methods))]
                body = {
                    "model": self.model,
                    "messages": [image_message(question(prompt, len(order)), *(renders[m] for m in order))],
                    "temperature": 0.0,
                }
                try:
                    response = chat_completion(
                        server,
                        body,
                        policy=RetryPolicy(max_retries=2, backoff_s=1.0),
                        timeout_s=self.timeout_s,
                        label=f"ranking by {self.model} at {server.url}",
                        sleep=self.sleep,
                    )
                except LLMRequestError as exc:
                    group.error = str(exc)
                    log.warning("ranking unavailable: %s", exc)
                    break
                text, _ = reply_text(response)
                ranking = read_ranking(text, len(order))
                if ranking is None:
                    group.unread += 1
                    continue
                for place, picture in enumerate(ranking, start=1):
                    group.ranks[order[picture]].append(place)
        finally:
            server.close()
        return group


def rank_rows(rows: list[dict[str, Any]], out: Path, ranker: Ranker) -> list[GroupRanks]:
    """Rank every group of `rows` (results.jsonl rows under `out`) with two or more renders, and set each ranked
    row's RANK_KEY metric to its method's mean rank in its group."""
    groups: dict[tuple[str, int], list[dict[str, Any]]] = {}
    for row in rows:
        groups.setdefault((row["prompt_id"], row["seed"]), []).append(row)
    ranked = []
    for (prompt_id, seed), members in sorted(groups.items()):
        renders = {}
        for row in members:
            png = _render_of(out, row)
            if png is not None:
                renders[row["method"]] = png
        if len(renders) < 2:
            continue
        group = ranker.rank_group(prompt_id, seed, members[0]["prompt"], renders)
        ranked.append(group)
        for row in members:
            mean = group.mean(row["method"])
            if mean is not None:
                row["metrics"][RANK_KEY] = round(mean, 3)
    return ranked


def mean_ranks(groups: list[GroupRanks]) -> dict[str, dict[str, float]]:
    """Per method: the mean and std of its rank over the groups that ranked it, and how many there were."""
    per: dict[str, list[float]] = {}
    for group in groups:
        for method in group.ranks:
            mean = group.mean(method)
            if mean is not None:
                per.setdefault(method, []).append(mean)
    return {
        method: {"mean": statistics.mean(v), "std": statistics.pstdev(v), "groups": float(len(v))}
        for method, v in sorted(per.items(), key=lambda item: statistics.mean(item[1]))
    }


def _render_of(out: Path, row: dict[str, Any]) -> bytes | None:
    """The row's render.png, read as any file of a folder that may not be trusted (no link followed, bounded)."""
    if not row.get("scene_dir"):
        return None
    try:
        return read_in_folder(out, f"{row['scene_dir']}/render.png", MAX_RENDER_BYTES)
    except (OSError, ValueError):
        return None
