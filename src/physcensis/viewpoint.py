"""The one viewpoint that words are read from: the person looking at the default render.

That person stands in front of the support (+x) and looks at it, as the default camera does. "left", "right",
"in front of", "behind", "leftmost", "frontmost" in a prompt, in a robot task and in a suite's `expect` block mean what
that person sees: the viewer's left is world −y, the viewer's right +y, the front +x (towards the viewer), behind −x.

The predicates keep the paper's frame, in which a thing's own left is +y (as it has it, facing +x, the viewer): so the
viewer's left is the frame's right, and the reading translates ("a mug to the left of the laptop" -> RIGHT-OF). The
layout plot is drawn as the viewer sees the support from above: front at the bottom, the viewer's left on the left.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal

Word = Literal["left", "right", "front", "behind"]

# The frame's side (the predicates' LEFT-OF / RIGHT-OF / FRONT-OF / BACK-OF) of each side word as the viewer says it.
FRAME_SIDE: dict[str, str] = {"left": "right", "right": "left", "front": "front", "behind": "behind"}

# The world xy direction each side word points to, as the viewer sees it.
DIRECTION: dict[str, tuple[float, float]] = {
    "left": (0.0, -1.0),
    "right": (0.0, 1.0),
    "front": (1.0, 0.0),
    "behind": (-1.0, 0.0),
}


SIDE_MIN_M = 0.01  # a thing this far (centre to centre) towards a side word's direction, and more along it than
# across it, stands on that side of another


def stands_towards(subject: Sequence[float], other: Sequence[float], word: str) -> bool:
    """Whether a thing centred at `subject` (world x, y, ...) stands on the `word` side ("left", "right", "front",
    "behind") of one centred at `other`, as the viewer sees it."""
    direction = DIRECTION[word]
    dx, dy = subject[0] - other[0], subject[1] - other[1]
    along = dx * direction[0] + dy * direction[1]
    across = abs(dx * direction[1] - dy * direction[0])
    return along >= SIDE_MIN_M and along >= across


def frame_side(word: str) -> str:
    """The frame's side for a side word as the viewer says it ("left" -> "right"); other words as they are."""
    return FRAME_SIDE.get(word, word)
