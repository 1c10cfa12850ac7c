"""Priors for nouns the catalogue does not know: what kind of thing a noun names, and that kind's typical shape,
size range and density.

The kind is read from the description's lemmatised words: the head noun counts most, the words before it in its
phrase less, the rest of the description least; a noun's ending ("...maker", "...box") helps when the word itself is
not listed. A description with no cue at all is a small generic object.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Literal

from physcensis.assets.model import Vec3
from physcensis.assets.text import MODIFIERS, QUANTITY_HEADS, RELATION_WORDS, STOPWORDS, words

Shape = Literal["box", "cylinder", "slab", "rounded", "sphere"]


@dataclass(frozen=True)
class KindPrior:
    """A kind of thing: its stand-in's shape, its smallest and largest typical size (x, y, z) and density."""

    name: str
    shape: Shape
    smallest: Vec3
    largest: Vec3
    density: float  # kg/m^3 of the stand-in's solid (low for hollow things, high for solid ones)
    cues: frozenset[str] = frozenset()
    endings: tuple[str, ...] = ()

    def size_for(self, noun: str) -> Vec3:
        """A size within the range, fixed by the noun (the same noun always gets the same size)."""
        t = int(hashlib.sha1(noun.encode("utf-8")).hexdigest()[:8], 16) / 0xFFFFFFFF
        x, y, z = (lo + t * (hi - lo) for lo, hi in zip(self.smallest, self.largest, strict=True))
        return (x, y, z)


def _cues(text: str) -> frozenset[str]:
    return frozenset(text.split())


KINDS: tuple[KindPrior, ...] = (
    KindPrior(
        "appliance",
        "box",
        (0.18, 0.14, 0.18),
        (0.42, 0.32, 0.38),
        250.0,
        _cues(
            "appliance toaster blender mixer juicer fryer cooker microwave oven grill processor machine maker heater "
            "fan humidifier dehumidifier purifier printer scanner projector vacuum grinder kettle percolator "
            "espresso dishwasher steamer sandwichmaker waffle breadmaker airfryer dehydrator shredder router console"
        ),
        ("maker", "machine", "izer", "iser", "ifier", "ator", "cooker", "fryer", "oven", "washer", "dryer"),
    ),
    KindPrior(
        "bottle-like",
        "cylinder",
        (0.05, 0.05, 0.14),
        (0.10, 0.10, 0.32),
        450.0,
        _cues(
            "bottle flask vial spray aerosol sprayer decanter carafe thermos canteen cologne perfume lotion shampoo "
            "conditioner sanitizer syrup sauce ketchup mustard vinegar soda beer wine whisky liquor potion cruet "
            "atomizer aftershave mouthwash"
        ),
        ("bottle", "flask", "spray"),
    ),
    KindPrior(
        "container",
        "cylinder",
        (0.08, 0.08, 0.08),
        (0.28, 0.28, 0.32),
        250.0,
        _cues(
            "container jug urn canister tub bucket pail tin vessel crock tureen vat cask barrel keg caddy hookah "
            "amphora planter samovar casserole cauldron wok pail hamper bin chest pot jar can box case holder "
            "dispenser cooler lunchbox bento kettle churn trough"
        ),
        ("box", "bin", "pot", "jar", "case", "holder", "tin", "tub", "bucket", "basket", "caddy", "container"),
    ),
    KindPrior(
        "tool",
        "box",
        (0.12, 0.03, 0.02),
        (0.35, 0.08, 0.05),
        900.0,
        _cues(
            "tool chisel awl rasp spanner trowel tongs cutter scraper crowbar tweezers wrench pliers hacksaw saw "
            "plane caliper gauge multimeter soldering iron drill hammer mallet screwdriver pick file stapler clamp "
            "vise spatula grater peeler opener corkscrew ladle whisk skewer knife blade scalpel trimmer clipper "
            "shears secateurs hatchet axe sickle putty spade shovel rake hoe"
        ),
        ("saw", "driver", "cutter", "opener", "peeler", "wrench"),
    ),
    KindPrior(
        "electronics",
        "box",
        (0.06, 0.04, 0.015),
        (0.25, 0.18, 0.06),
        700.0,
        _cues(
            "electronics electronic device gadget charger adapter drive harddrive hub camera controller gamepad "
            "joystick modem radio walkie player ipod kindle ereader pager tracker earbud powerbank battery "
            "smartwatch gps dashcam synthesizer tuner amplifier receiver transmitter thermostat sensor detector "
            "timer meter digital wireless bluetooth usb electric"
        ),
        ("phone", "pad", "cam", "player", "meter"),
    ),
    KindPrior(
        "toy",
        "rounded",
        (0.05, 0.04, 0.05),
        (0.22, 0.16, 0.20),
        250.0,
        _cues(
            "toy figurine figure puppet yoyo robot dinosaur teddy plush plushie rattle doll lego kaleidoscope "
            "yo slinky playset action marionette pinwheel whistle trinket pony unicorn dragon kids child children "
            "nursery playroom"
        ),
        ("toy", "saurus", "osaur"),
    ),
    KindPrior(
        "food",
        "rounded",
        (0.05, 0.05, 0.04),
        (0.16, 0.16, 0.12),
        800.0,
        _cues(
            "food fruit vegetable kiwi mango peach plum avocado melon onion potato tomato pepper cucumber carrot "
            "eggplant aubergine cabbage lettuce pineapple coconut pomegranate egg muffin cupcake donut doughnut "
            "bagel croissant cookie biscuit cake pie cheese pizza burger hamburger sushi burrito taco dumpling "
            "pastry brownie scone waffle pancake lime grapefruit papaya apricot nectarine quince fig squash "
            "pumpkin zucchini courgette turnip beet radish garlic ginger broccoli cauliflower corn loaf baguette "
            "meat steak chicken fish snack candy chocolate bread"
        ),
        ("berry", "fruit", "cake", "nut", "melon", "bread"),
    ),
    KindPrior(
        "soft item",
        "slab",
        (0.20, 0.15, 0.03),
        (0.42, 0.32, 0.09),
        150.0,
        _cues(
            "garment clothing clothes shirt tshirt sweater jumper hoodie cardigan scarf hat cap beanie sock mitten "
            "jacket coat jeans trousers pants shorts dress skirt cloth rag apron bib handkerchief pillow cushion "
            "blanket quilt duvet throw shawl poncho vest bathrobe robe pajamas pyjamas underwear bra leggings "
            "tights serape sarong kaftan kimono glove gloves bag purse pouch tote sack beanbag fabric fleece wool "
            "knitted folded soft"
        ),
        ("shirt", "wear", "cloth", "bag"),
    ),
    KindPrior(
        "furniture-like",
        "box",
        (0.30, 0.30, 0.30),
        (0.70, 0.55, 0.80),
        120.0,
        _cues(
            "furniture stool chair ottoman pouf pouffe cabinet dresser nightstand bench footstool bookcase chest "
            "trunk sideboard console cupboard wardrobe drawer drawers crib cot armchair sofa couch desk"
        ),
        ("stool", "stand", "cabinet", "chair"),
    ),
    KindPrior(
        "flat item",
        "slab",
        (0.10, 0.07, 0.002),
        (0.35, 0.28, 0.015),
        700.0,
        _cues(
            "card postcard poster map ticket letter page sheet leaflet flyer brochure menu booklet mat pad tile "
            "doily photo photograph print receipt newspaper document certificate placemat board tray sheet panel "
            "plaque sign label sticker stencil puzzle canvas folder flat paper cardboard"
        ),
        ("card", "board", "sheet", "mat", "paper"),
    ),
    KindPrior(
        "ornament",
        "cylinder",
        (0.06, 0.06, 0.10),
        (0.18, 0.18, 0.35),
        700.0,
        _cues(
            "ornament decoration statue statuette sculpture bust trophy award figurine idol totem lantern lamp "
            "candlestick incense censer globe snowglobe hourglass bell obelisk urn chalice goblet"
        ),
        ("stick", "ware"),
    ),
)
GENERIC_KIND = KindPrior("object", "box", (0.08, 0.06, 0.05), (0.16, 0.12, 0.11), 500.0)
_NOT_NOUNS = frozenset(
    """red blue green yellow orange purple pink black white grey brown beige gold golden silver wooden wood metal
    metallic plastic ceramic brass copper steel stone marble paper leather cotton woollen velvet rubber
    antique ornate decorative cute fancy pretty ugly shiny matte glossy bright dark pale light colourful""".split()
)


# Words that end a head phrase besides the retrieval's relation words ("a lamp along the wall").
PREPOSITIONS = frozenset(
    "along across around above below beneath among through toward towards upon onto into within outside over under "
    "at by from off".split()
)


def noun_phrase(description: str) -> list[str]:
    """The lemmatised words of the description's head phrase, without articles, numbers, colours and materials:
    "a tall brass hookah with a long hose" -> ["hookah"]; "a pair of red clogs" -> ["clog"]."""
    head: list[str] = []
    previous = ""
    for w in words(description):
        if w == "of" and previous in QUANTITY_HEADS:
            head, previous = [], w
            continue
        if head and (w == "of" or w in RELATION_WORDS or w in PREPOSITIONS):
            break
        previous = w
        if w in STOPWORDS or w in MODIFIERS or any(ch.isdigit() for ch in w):
            continue
        head.append(w)
    return [w for w in head[:-1] if w not in _NOT_NOUNS] + head[-1:]  # "a glass bowl", but "a magnifying glass"


def head_noun(description: str) -> str:
    """The noun a reader would name the object by: the head phrase's last word, with the word before it when that
    names a thing too ("espresso machine", "sewing machine"); "object" when the description has none."""
    head = noun_phrase(description)
    if not head:
        return "object"
    if len(head) >= 2 and _compound(head[-2], head[-1]):
        return f"{head[-2]} {head[-1]}"
    return head[-1]


def _compound(first: str, noun: str) -> bool:
    """Whether `first noun` is one name: the first word is a known thing, or a verb's -ing form before a known
    thing ("sewing machine", not "glowing orb")."""
    known = set().union(*(kind.cues for kind in KINDS))
    if first.endswith("ed"):  # "folded", "carved": a state, not a name
        return False
    return first in known or (first.endswith("ing") and noun in known)


def kind_of(description: str) -> KindPrior:
    """The kind of thing a description names (GENERIC_KIND when nothing points to one)."""
    head = noun_phrase(description)
    noun = head[-1] if head else ""
    rest = [w for w in words(description) if w not in head]
    best, best_score = GENERIC_KIND, 0.0
    for kind in KINDS:
        score = 3.0 * (noun in kind.cues) + 1.0 * (bool(noun) and noun.endswith(kind.endings))
        score += sum(w in kind.cues for w in head[:-1]) + 0.5 * sum(w in kind.cues for w in rest)
        if score > best_score:
            best, best_score = kind, score
    return best
