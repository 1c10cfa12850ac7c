"""Place settings: one setting written as a GROUP at the table's near end, copied for every other diner and turned
to face the table's middle; with variety, which pieces and where the diners sit are drawn."""

from __future__ import annotations

from physcensis.agent import choosing
from physcensis.agent.planning.entries import (
    ALIGN_CENTER_FB,
    ALIGN_LEFT,
    BACK_OF,
    COPY_GROUP,
    FACING_BACK,
    FACING_FRONT,
    FACING_LEFT,
    FACING_RIGHT,
    FACING_SAME_AS,
    GROUP,
    LEFT_OF,
    ORIENT_BY_RELATIVE_SIDE,
    PLACE_ON_BASE,
    RIGHT_OF,
    SYMMETRY_ALONG,
    Entry,
    Plan,
)
from physcensis.agent.reading import Mention, SceneRequest
from physcensis.agent.variety import Draws
from physcensis.assets.catalogue import Catalogue

SETTING_ITEMS = ("plate", "fork", "knife", "spoon", "cup", "glass", "wine glass", "napkin")
# What a setting's pieces are looked up as in the catalogue, and words that name variants not laid at a table.
SETTING_NAMES = {"plate": "dinner plate", "fork": "fork", "knife": "table knife", "spoon": "spoon"}
NOT_AT_TABLE = frozenset(
    {"paper", "plastic", "toothbrush", "chef", "paring", "bread", "measuring", "wooden", "baby", "serving", "toy"}
)
CANONICAL_PIECES = {
    "plate": "a round white dinner plate",
    "fork": "a stainless steel dinner fork",
    "knife": "a stainless steel table knife",
    "spoon": "a stainless steel soup spoon",
    "cup": "a white coffee cup",
    "glass": "a clear drinking glass",
    "wine glass": "a clear wine glass",
    "napkin": "a folded red napkin",
}
NAPKIN_WIDTH = 0.12  # a setting's napkin lies folded narrow beside the fork
SETTING_DEPTH = 0.38  # how far a place setting reaches in from the table's edge
SETTING_WIDTH = 0.55  # how much of an edge one place setting takes, with elbow room
# Which way a setting at each edge of the table faces (towards the middle), and the sign of its coordinate.
EDGE_FACING = {
    "front": (FACING_BACK, 1.0),
    "back": (FACING_FRONT, -1.0),
    "left": (FACING_RIGHT, 1.0),
    "right": (FACING_LEFT, -1.0),
}
Seat = tuple[str, float, float]  # the facing rule of a diner's setting and its centre (x, y)


def place_settings(
    plan: Plan,
    request: SceneRequest,
    mentions: list[Mention],
    half: tuple[float, float],
    draws: Draws,
    catalogue: Catalogue,
) -> set[int]:
    """One place setting as a GROUP, copied for every other diner and turned to face the table's middle; the
    mentions the settings stand for (their plates, forks ...)."""
    consumed = {k for k, m in enumerate(mentions) if m.category in SETTING_ITEMS and not m.centre}
    named = {mentions[k].category for k in consumed}
    drink = "wine glass" if "wine glass" in named else "glass" if "glass" in named else "cup"
    items = ["plate", "fork", "knife"] + (["spoon"] if "spoon" in named else []) + [drink]
    items += ["napkin"] if "napkin" in named else []  # "every plate with a napkin beside it"
    hx, hy = half
    ids: dict[str, str] = {}
    for item in items:
        ids[item] = plan.new_id(item)
        plan.anchors.append([ids[item], _setting_piece(item, CANONICAL_PIECES[item], draws, catalogue)])
        plan.anchors += _piece_entries(item, ids, hx)
    group = "group_setting_0"
    plan.anchors.append([group, GROUP, [ids[i] for i in items], {"anchor": ids["plate"]}])
    seats = _seats(request.diners, hx, hy, draws)
    if seats is not None:  # the first diner sits elsewhere too: the setting built at the near end moves there
        facing, x, y = seats[0]
        plan.anchors += [
            [group, PLACE_ON_BASE, "root", {"x": round(x, 3), "y": round(y, 3)}],
            [group, facing, "root", {}],
        ]
    for n in range(1, request.diners):
        facing, x, y = _seat(n, request.diners, hx, hy) if seats is None else seats[n]
        copy = f"group_setting_{n}"
        plan.anchors += [
            [copy, COPY_GROUP, group, {}],
            [copy, PLACE_ON_BASE, "root", {"x": round(x, 3), "y": round(y, 3)}],
            [copy, facing, "root", {}],
        ]
    return consumed


def _piece_entries(item: str, ids: dict[str, str], hx: float) -> list[Entry]:
    """Where one piece of the first setting goes: the plate at the near end, facing the middle; fork and knife
    either side of it, the spoon beside the knife, the drink behind them."""
    oid, plate = ids[item], ids["plate"]
    if item == "plate":
        return [[plate, PLACE_ON_BASE, "root", {"x": round(hx - 0.17, 3), "y": 0.0}], [plate, FACING_BACK, "root", {}]]
    if item == "fork":
        return [
            [oid, PLACE_ON_BASE, "root", {}],
            [oid, RIGHT_OF, plate, {"distance": 0.02}],
            [oid, ALIGN_CENTER_FB, plate, {}],
            [oid, ORIENT_BY_RELATIVE_SIDE, plate, {}],
        ]
    if item == "knife":
        return [
            [oid, PLACE_ON_BASE, "root", {}],
            [oid, SYMMETRY_ALONG, ids["fork"], {"C": plate}],
            [oid, ORIENT_BY_RELATIVE_SIDE, plate, {}],
        ]
    if item == "spoon":
        return [
            [oid, PLACE_ON_BASE, "root", {}],
            [oid, LEFT_OF, ids["knife"], {"distance": 0.015}],
            [oid, ALIGN_CENTER_FB, plate, {}],
            [oid, ORIENT_BY_RELATIVE_SIDE, plate, {}],
        ]
    if item == "napkin":  # outside the fork, folded long side along it
        return [
            [oid, PLACE_ON_BASE, "root", {}],
            [oid, RIGHT_OF, ids["fork"], {"distance": 0.015}],
            [oid, ALIGN_CENTER_FB, plate, {}],
            [oid, FACING_SAME_AS, plate, {}],
        ]
    return [
        [oid, PLACE_ON_BASE, "root", {}],
        [oid, BACK_OF, plate, {"distance": 0.03}],
        [oid, ALIGN_LEFT, ids.get("spoon", ids["knife"]), {}],
        [oid, FACING_SAME_AS, plate, {}],
    ]


def _setting_piece(item: str, canonical: str, draws: Draws, catalogue: Catalogue) -> str:
    """The description of one piece of a place setting: the canonical one, or with variety any variant of the
    piece that suits a dining table (a cream or a white dinner plate, a tumbler or a highball)."""
    if not draws.on:
        return canonical
    words = choosing.words_of([], 0, 0, canonical, ())
    variants = [
        a
        for a in catalogue.variants(SETTING_NAMES.get(item, item))
        if a.category == item
        and not choosing.is_multiple(a)
        and not NOT_AT_TABLE & set(choosing.asset_words(a))
        and (item != "napkin" or min(a.size[:2]) <= NAPKIN_WIDTH)
    ]
    if not variants:
        return canonical
    weights = [1.0 + choosing.word_score(a, words) for a in variants]
    chosen = draws.order(variants, "setting", item, weights=weights)[0]
    return chosen.description if catalogue.resolve(chosen.description).id == chosen.id else canonical


def _seats(diners: int, hx: float, hy: float, draws: Draws) -> list[Seat] | None:
    """Where each diner's setting goes, or None for the canonical seats (`_seat`). With variety the diners sit at
    the ends first or along the sides first, spread along each edge, and the first of them anywhere; every edge holds
    only as many settings as its length gives room for."""
    if not draws.on or diners < 2:
        return None
    length = {"front": 2 * hy, "back": 2 * hy, "left": 2 * hx, "right": 2 * hx}
    room = {edge: int(length[edge] // SETTING_WIDTH) for edge in length}
    ends, sides = ("front", "back"), ("left", "right")
    if length["front"] > length["left"]:
        ends, sides = sides, ends
    plan = draws.pick("round", ["round", "long sides"], "seats")
    tiers = [(*ends, *sides)] if plan == "round" else [sides, ends]
    per_edge = dict.fromkeys(length, 0)
    left = diners
    for tier in tiers:  # deal the diners round the edges of each tier, as far as each has room
        while left and any(per_edge[e] < room[e] for e in tier):
            for edge in tier:
                if left and per_edge[edge] < room[edge]:
                    per_edge[edge] += 1
                    left -= 1
    if left:
        return None  # more diners than the edges hold: the canonical seats
    seats = [_seat_on(edge, i, n, hx, hy, draws) for edge, n in per_edge.items() for i in range(n)]
    first = draws.pick(seats[0], seats, "first seat")
    return [first, *(s for s in seats if s is not first)]


def _seat_on(edge: str, i: int, of: int, hx: float, hy: float, draws: Draws) -> Seat:
    """Setting i of `of` along one edge of the table (spread evenly, shifted a little when there is room)."""
    facing, sign = EDGE_FACING[edge]
    inset = draws.uniform(SETTING_DEPTH / 2, 0.17, 0.21, "inset", edge, i)
    along = hy if edge in ("front", "back") else hx
    spot = -along + 2 * along * (i + 0.5) / of
    slack = max(0.0, (2 * along / of - SETTING_WIDTH) / 2)
    spot += draws.uniform(0.0, -slack, slack, "along", edge, i)
    if edge in ("front", "back"):
        return facing, sign * (hx - inset), spot
    return facing, spot, sign * (hy - inset)


def _seat(n: int, diners: int, hx: float, hy: float) -> Seat:
    """The facing and centre of diner n's copied setting (n >= 1; diner 0's setting is at the near end)."""
    inset = SETTING_DEPTH / 2
    head_seats = [
        (FACING_FRONT, -hx + inset, 0.0),
        (FACING_RIGHT, 0.0, hy - inset),
        (FACING_LEFT, 0.0, -hy + inset),
    ]
    if n <= len(head_seats):  # the far end, then the middle of each side
        return head_seats[n - 1]
    side = 1 if n % 2 else -1  # more diners: along the long sides
    return (
        FACING_RIGHT if side > 0 else FACING_LEFT,
        (-0.5 + (n // 2) / max(1, diners // 2)) * hx,
        side * (hy - inset),
    )
