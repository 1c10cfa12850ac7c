"""Top-down plot of a layout (layout.png), drawn with Pillow alone (no matplotlib: importing it would cost a batch
worker a second): the support outline, every footprint numbered with its facing arrow, axes and a scale bar in
centimetres, a legend of the numbers' ids beside the plot and the prompt as its title."""

from __future__ import annotations

import functools
import importlib.util
import io
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from physcensis.fileio import atomic_write_bytes
from physcensis.geometry.footprints import Array, rotate
from physcensis.imageio import PNG_LEVEL
from physcensis.scene import Support

PLOT_IN = 6.4  # the support's plot, inches on its longer side
ROWS_PER_COLUMN = 40  # legend lines in one column
LEGEND_COLUMN_IN = 2.3
SCALE_STEPS_CM = (1, 2, 5, 10, 20, 50, 100)
TICK_STEPS_CM = (1.0, 2.0, 2.5, 5.0)  # times a power of ten
DPI = 110
SUPERSAMPLE = 2  # the plot area is drawn this many times larger and shrunk: anti-aliased shapes
CM = 100.0

# matplotlib's tab20 colours, in its order
TAB20 = (
    (31, 119, 180), (174, 199, 232), (255, 127, 14), (255, 187, 120), (44, 160, 44),
    (152, 223, 138), (214, 39, 40), (255, 152, 150), (148, 103, 189), (197, 176, 213),
    (140, 86, 75), (196, 156, 148), (227, 119, 194), (247, 182, 210), (127, 127, 127),
    (199, 199, 199), (188, 189, 34), (219, 219, 141), (23, 190, 207), (158, 218, 229),
)  # fmt: skip
FAILED = (214, 39, 40)  # #d62728
SUPPORT_FACE, SUPPORT_EDGE = (243, 234, 216), (122, 92, 58)  # #f3ead8, #7a5c3a
BLACK = (0, 0, 0)
ALPHA = round(0.55 * 255)  # of the footprints' faces and edges

Font = ImageFont.FreeTypeFont | ImageFont.ImageFont
Colour = tuple[int, int, int]


def _px(points: float) -> float:
    return points * DPI / 72.0


@dataclass(frozen=True)
class _Area:
    """The plot area in the image: its top left pixel, size in pixels, pixels per centimetre and half extents in
    centimetres of what it shows (the support and its margin) across (u) and in depth (v)."""

    left: int
    top: int
    width: int
    height: int
    scale: float
    half_u: float
    half_v: float

    def at(self, x_cm: float, y_cm: float) -> tuple[float, float]:
        """The image pixel of world (x, y) in centimetres: +y to the right, +x (the front) down."""
        return self.left + (y_cm + self.half_u) * self.scale, self.top + (x_cm + self.half_v) * self.scale


def plot_layout(
    path: str | Path,
    support: Support,
    footprints: Mapping[str, tuple[Array, float, float, float]],
    highlight: Sequence[str] = (),
    title: str = "",
) -> Path:
    """Write a PNG of footprints given as id -> (hull, x, y, yaw); `highlight` ids (failed ones) are drawn red."""
    hx, hy = support.half_extents
    ids = sorted(footprints)
    columns = math.ceil(len(ids) / ROWS_PER_COLUMN)
    # The support from above as the viewer sees it (viewpoint.py): world +x (front, towards the viewer) down the
    # page, world +y (the viewer's right) to the right; lengths in centimetres.
    plot_w = PLOT_IN * min(1.0, hy / hx)
    plot_h = max(PLOT_IN * min(1.0, hx / hy), 2.5)
    left, right, bottom, top = 0.75, 0.2 + columns * LEGEND_COLUMN_IN, 0.65, 0.45
    width, height = plot_w + left + right, plot_h + bottom + top
    margin = 0.08 * max(hx, hy) * CM
    half_u, half_v = hy * CM + margin, hx * CM + margin
    scale = min(plot_w * DPI / (2 * half_u), plot_h * DPI / (2 * half_v))
    area_w, area_h = round(2 * half_u * scale), round(2 * half_v * scale)  # centred in its share, as equal aspect
    area = _Area(
        round(left * DPI + (plot_w * DPI - area_w) / 2),
        round(top * DPI + (plot_h * DPI - area_h) / 2),
        area_w,
        area_h,
        scale,
        half_u,
        half_v,
    )
    image = Image.new("RGB", (int(width * DPI), int(height * DPI)), "white")
    placed = [_place(*footprints[oid]) for oid in ids]
    colours = [FAILED if oid in highlight else TAB20[k % 20] for k, oid in enumerate(ids)]
    image.paste(_plot_area(area, hx * CM, hy * CM, margin, placed, colours), (area.left, area.top))
    draw = ImageDraw.Draw(image)
    for k, one in enumerate(placed):
        if one.drawable:
            _text(draw, area.at(one.x, one.y), str(k + 1), _font("DejaVuSans-Bold.ttf", 6.5), "mm")
    _axes(image, draw, area)
    bar = _scale_bar_cm(hy * CM)
    bar_x, bar_y = area.at(hx * CM + 0.55 * margin, -hy * CM + bar + 0.1 * margin)
    _text(draw, (bar_x, bar_y), f"{bar} cm", _font("DejaVuSans.ttf", 7), "lm")
    legend = [f"{k + 1:>3}  {oid}{'  (failed)' if oid in highlight else ''}" for k, oid in enumerate(ids)]
    mono, line_px = _font("DejaVuSansMono.ttf", 6.5), 1.2 * _px(6.5)
    for k, line in enumerate(legend):
        column, row = divmod(k, ROWS_PER_COLUMN)
        xy = ((left + plot_w + 0.2 + column * LEGEND_COLUMN_IN) * DPI, top * DPI + row * line_px)
        _text(draw, xy, line, mono)
    if title:  # a prompt: shown as typed and cut to a line
        line = " ".join(title.split())
        line = line if len(line) <= 110 else line[:109] + "…"
        _text(draw, (image.width / 2, 0.12 * DPI), line, _font("DejaVuSans.ttf", 9), "ma")
    buffer = io.BytesIO()
    # 256 colours lose nothing visible on these flat fills; quantizing and writing them takes half the time of
    # writing RGB (whose PNG filtering is slow) and gives a file less than half the size.
    paletted = image.quantize(256, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)
    paletted.save(buffer, format="png", compress_level=PNG_LEVEL)
    path = Path(path)
    atomic_write_bytes(path, buffer.getvalue())
    return path


@dataclass(frozen=True)
class _Placed:
    """A footprint on the support, in centimetres: its hull's points, centre, yaw and facing arrow's length."""

    pts: Array
    x: float
    y: float
    yaw: float
    reach: float

    @property
    def drawable(self) -> bool:
        return len(self.pts) > 0 and bool(np.isfinite(self.pts).all()) and math.isfinite(self.reach)


def _place(hull: Array, x: float, y: float, yaw: float) -> _Placed:
    pts = (rotate(np.asarray(hull, dtype=float), np.array([yaw]))[0] + [x, y]) * CM
    reach = 0.25 * float(np.ptp(pts[:, 0]) + np.ptp(pts[:, 1])) / 2 if len(pts) else 0.0
    return _Placed(pts, x * CM, y * CM, yaw, reach)


def _plot_area(
    area: _Area,
    hx_cm: float,
    hy_cm: float,
    margin: float,
    placed: Sequence[_Placed],
    colours: Sequence[Colour],
) -> Image.Image:
    """The support, the footprints with their facing arrows and the scale bar, drawn large then shrunk (which
    anti-aliases them); what lies outside the area is cut off."""
    s = SUPERSAMPLE
    panel = Image.new("RGB", (area.width * s, area.height * s), "white")

    def at(x_cm: float, y_cm: float) -> tuple[float, float]:
        u, v = area.at(x_cm, y_cm)
        return (u - area.left) * s, (v - area.top) * s

    edge = round(_px(2.0)) * s  # the support's outline, centred on its edge and on whole pixels: crisp once shrunk
    x0, y0 = at(-hx_cm, -hy_cm)
    x1, y1 = at(hx_cm, hy_cm)
    box = [s * round(c / s) for c in (x0 - edge / 2, y0 - edge / 2, x1 + edge / 2, y1 + edge / 2)]
    ImageDraw.Draw(panel).rectangle(box, fill=SUPPORT_FACE, outline=SUPPORT_EDGE, width=edge)
    faces = ImageDraw.Draw(panel, "RGBA")  # blends each translucent face over those before it
    # Everything black (outlines, arrows, the scale bar) goes on one coverage mask, blended once after shrinking:
    # translucent outlines do not darken where they overlap and the blend costs a quarter of the pixels.
    ink = Image.new("L", panel.size, 0)
    pen = ImageDraw.Draw(ink)
    width = math.ceil(_px(0.8) * s)
    for one, colour in zip(placed, colours, strict=True):
        if one.drawable:
            pts = [at(px, py) for px, py in one.pts]
            if len(pts) >= 3:
                faces.polygon(pts, fill=(*colour, ALPHA))
            pen.line([*pts, pts[0]], fill=ALPHA, width=width, joint="curve")
    shaft = max(1.0, 0.002 * area.width) * s  # quiver's width=0.002 of the axes
    for one in placed:  # facing world (cos yaw, sin yaw): quiver's (sin yaw, -cos yaw) in the plot's (right, up)
        if one.drawable:
            tip = at(one.x + one.reach * math.cos(one.yaw), one.y + one.reach * math.sin(one.yaw))
            _arrow(pen, at(one.x, one.y), tip, shaft)
    bar = _scale_bar_cm(hy_cm)
    bx, by = at(hx_cm + 0.55 * margin, -hy_cm)
    half = _px(2.5) * s / 2
    pen.rectangle((bx, by - half, bx + bar * area.scale * s, by + half), fill=255)
    panel, ink = panel.reduce(s), ink.reduce(s)
    panel.paste(BLACK, (0, 0, *panel.size), ink)
    return panel


def _arrow(pen: ImageDraw.ImageDraw, start: tuple[float, float], tip: tuple[float, float], shaft: float) -> None:
    """quiver's arrow on a coverage mask: a shaft `shaft` wide, a head 4 shafts wide and 5 long (4.5 on the axis)."""
    dx, dy = tip[0] - start[0], tip[1] - start[1]
    length = math.hypot(dx, dy)
    if length <= 0.0:
        return
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    head = min(5 * shaft, length)
    neck = max(0.0, length - 0.9 * head)
    w, hw = shaft / 2, head * 0.4  # a head of 4 shafts by 5, shrunk as a whole on short arrows
    sx, sy = start[0] + ux * neck, start[1] + uy * neck
    x0, y0 = start
    pen.polygon(
        [
            (x0 + nx * w, y0 + ny * w),
            (sx + nx * w, sy + ny * w),
            (sx - nx * w, sy - ny * w),
            (x0 - nx * w, y0 - ny * w),
        ],
        fill=255,
    )
    bx, by = tip[0] - ux * head, tip[1] - uy * head
    pen.polygon([tip, (bx + nx * hw, by + ny * hw), (bx - nx * hw, by - ny * hw)], fill=255)


def _scale_bar_cm(hy_cm: float) -> int:
    """A round length, at most two fifths of the support's half width."""
    return max([s for s in SCALE_STEPS_CM if s <= 0.4 * hy_cm] or [SCALE_STEPS_CM[0]])


def _axes(image: Image.Image, draw: ImageDraw.ImageDraw, area: _Area) -> None:
    """A frame around the plot area, ticks and their labels in centimetres at a round step and the axes' titles; the
    vertical labels are world x, which grows towards the front (down)."""
    tick, pad = round(_px(3.5)), round(_px(3.5))
    small, label = _font("DejaVuSans.ttf", 7), _font("DejaVuSans.ttf", 8)
    right, bottom = area.left + area.width, area.top + area.height
    draw.rectangle((area.left - 1, area.top - 1, right, bottom), outline=BLACK, width=1)
    for t in _ticks(area.half_u, 40 / area.scale):  # room for a label like −2000
        u = round(area.at(0.0, t)[0])
        draw.line(((u, bottom), (u, bottom + tick)), fill=BLACK, width=1)
        _text(draw, (u, bottom + tick + pad), _number(t), small, "ma")
    widest = 0.0
    for t in _ticks(area.half_v, 20 / area.scale):
        v = round(area.at(t, 0.0)[1])
        draw.line(((area.left - tick, v), (area.left - 1, v)), fill=BLACK, width=1)
        _text(draw, (area.left - tick - pad, v), _number(t), small, "rm")
        widest = max(widest, small.getlength(_printable(_number(t), small)))
    under = bottom + tick + pad + small.getbbox("0")[3] + round(_px(4))
    across = "across, cm: the viewer's left  <  0  >  the viewer's right"
    _text(draw, (area.left + area.width / 2, under), across, label, "ma")
    depth = "depth, cm: back at the top, front (the viewer) at the bottom"
    _, _, text_w, text_h = label.getbbox(depth)
    mask = Image.new("L", (math.ceil(text_w), math.ceil(text_h)), 0)
    ImageDraw.Draw(mask).text((0, 0), depth, fill=255, font=label)
    mask = mask.transpose(Image.Transpose.ROTATE_90)  # reads bottom to top
    x1, y0 = round(area.left - tick - pad - widest - _px(4)), area.top + (area.height - mask.height) // 2
    image.paste(BLACK, (x1 - mask.width, y0, x1, y0 + mask.height), mask)


def _ticks(half: float, least: float) -> list[float]:
    """Multiples of the smallest round step, at least `least`, that gives at most 7 of them in [-half, half]."""
    steps = [m * 10.0**e for e in range(-3, 5) for m in TICK_STEPS_CM]
    step = next((s for s in steps if s >= least and 2 * math.floor(half / s) + 1 <= 7), steps[-1])
    n = math.floor(half / step + 1e-9)
    return [k * step for k in range(-n, n + 1)]


def _number(t: float) -> str:
    return f"{t + 0.0:g}".replace("-", "\u2212")


@functools.cache
def _font(name: str, points: float) -> Font:
    """A DejaVu font from matplotlib's package data (found, never imported), else Pillow's own."""
    folder = _font_folder()
    if folder is not None:
        try:
            return ImageFont.truetype(str(folder / name), _px(points))
        except OSError:
            pass
    try:
        return ImageFont.load_default(size=_px(points))
    except (OSError, ImportError):  # a Pillow without FreeType
        return ImageFont.load_default()


@functools.cache
def _font_folder() -> Path | None:
    try:
        spec = importlib.util.find_spec("matplotlib")
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(list(spec.submodule_search_locations)[0]) / "mpl-data" / "fonts" / "ttf"


def _printable(text: str, font: Font) -> str:
    """`text` as the font engine takes it: lone surrogates replaced, and Latin-1 only for a bitmap font."""
    text = text.encode("utf-8", "replace").decode("utf-8")
    if not isinstance(font, ImageFont.FreeTypeFont):
        text = text.encode("latin-1", "replace").decode("latin-1")
    return text


def _text(draw: ImageDraw.ImageDraw, xy: tuple[float, float], text: str, font: Font, anchor: str = "la") -> None:
    draw.text(xy, _printable(text, font), fill=BLACK, font=font, anchor=anchor)
