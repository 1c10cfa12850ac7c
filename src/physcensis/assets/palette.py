"""Named RGBA colours shared by the generators."""

from __future__ import annotations

from physcensis.assets.model import RGBA


def rgb(r: int, g: int, b: int, a: float = 1.0) -> RGBA:
    return (r / 255.0, g / 255.0, b / 255.0, a)


WHITE = rgb(240, 240, 235)
CREAM = rgb(238, 228, 200)
BLACK = rgb(30, 30, 32)
CHARCOAL = rgb(60, 62, 66)
GREY = rgb(150, 150, 155)
SILVER = rgb(196, 199, 204)
STEEL = rgb(175, 180, 188)
RED = rgb(200, 40, 40)
DARK_RED = rgb(130, 20, 30)
ORANGE = rgb(240, 140, 30)
YELLOW = rgb(245, 205, 40)
LIME = rgb(170, 210, 60)
GREEN = rgb(60, 150, 70)
DARK_GREEN = rgb(30, 90, 45)
TEAL = rgb(40, 150, 150)
SKY = rgb(120, 180, 230)
BLUE = rgb(40, 90, 190)
NAVY = rgb(30, 45, 100)
PURPLE = rgb(120, 60, 160)
PINK = rgb(235, 140, 170)
BROWN = rgb(120, 75, 40)
DARK_BROWN = rgb(70, 45, 25)
WOOD = rgb(180, 130, 80)
LIGHT_WOOD = rgb(215, 180, 130)
BAMBOO = rgb(220, 195, 140)
CARDBOARD = rgb(190, 145, 95)
TERRACOTTA = rgb(190, 95, 60)
GOLD = rgb(212, 175, 55)
BRASS = rgb(200, 165, 80)
GLASS = rgb(190, 225, 240, 0.45)
GREEN_GLASS = rgb(40, 110, 60, 0.85)
AMBER_GLASS = rgb(150, 85, 20, 0.85)
PAPER = rgb(250, 248, 240)
SOIL = rgb(70, 50, 35)
LEAF = rgb(60, 140, 50)
WAX = rgb(245, 240, 225)
