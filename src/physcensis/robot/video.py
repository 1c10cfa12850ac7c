"""A video of an episode's frames: MP4 (H.264, through imageio-ffmpeg's bundled ffmpeg) or an animated GIF (Pillow).

The file is written beside its destination under a temporary name and renamed into place once complete.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from pathlib import Path

import numpy as np

from physcensis.errors import PhyscensisError

SUFFIXES = (".mp4", ".gif")


class VideoError(PhyscensisError):
    """A video cannot be written (unknown suffix, no frames, frames of different sizes, encoder missing)."""


def write_video(frames: Iterable[np.ndarray], path: str | Path, fps: float = 20) -> Path:
    """Write the (H, W, 3) uint8 RGB `frames` as an MP4 or a GIF, chosen by the suffix of `path`; the path."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise VideoError(f"{path}: a video is written as .mp4 or .gif, not {suffix or 'a file without a suffix'!r}")
    if isinstance(fps, bool) or not isinstance(fps, int | float) or not 0 < fps <= 240:
        raise VideoError(f"frames per second must be a number in (0, 240], not {fps!r}")
    if path.is_dir():
        raise VideoError(f"{path} is a folder; give the path of the video file")
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.stem}.{os.getpid()}.tmp{suffix}")  # the encoder reads the format from the suffix
    try:
        count = _write_mp4(_checked(frames), tmp, fps) if suffix == ".mp4" else _write_gif(_checked(frames), tmp, fps)
        if count == 0:
            raise VideoError(f"{path}: no frames to write")
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)
    return path


def _checked(frames: Iterable[np.ndarray]) -> Iterator[np.ndarray]:
    """The frames as contiguous (H, W, 3) uint8 arrays, all of the first one's size."""
    shape: tuple[int, ...] | None = None
    for index, frame in enumerate(frames):
        array = np.asarray(frame)
        if array.ndim == 2:
            array = np.repeat(array[:, :, None], 3, axis=2)
        if array.ndim != 3 or array.shape[2] not in (3, 4) or array.dtype != np.uint8:
            raise VideoError(f"frame {index} is {array.dtype} {array.shape}; frames are (H, W, 3) uint8 RGB images")
        array = np.ascontiguousarray(array[:, :, :3])
        if shape is None:
            shape = array.shape
        elif array.shape != shape:
            raise VideoError(f"frame {index} is {array.shape[1]}x{array.shape[0]}; the first was {shape[1]}x{shape[0]}")
        yield array


def _even(frame: np.ndarray) -> np.ndarray:
    """H.264's 4:2:0 colour needs even sides: repeat the last row or column when one is odd."""
    height, width = frame.shape[:2]
    return np.pad(frame, ((0, height % 2), (0, width % 2), (0, 0)), mode="edge")


def _write_mp4(frames: Iterator[np.ndarray], path: Path, fps: float) -> int:
    try:
        import imageio_ffmpeg
    except ImportError:
        raise VideoError("MP4 videos need imageio-ffmpeg: pip install 'physcensis[robot]' (or write a .gif)") from None
    first = next(frames, None)
    if first is None:
        return 0
    first = _even(first)
    writer = imageio_ffmpeg.write_frames(
        str(path),
        (first.shape[1], first.shape[0]),
        fps=fps,
        codec="libx264",
        macro_block_size=1,
        ffmpeg_log_level="error",
    )
    writer.send(None)  # starts ffmpeg
    count = 0
    try:
        for frame in _chain(first, frames):
            writer.send(_even(frame).tobytes())
            count += 1
    finally:
        writer.close()
    return count


def _chain(first: np.ndarray, rest: Iterator[np.ndarray]) -> Iterator[np.ndarray]:
    yield first
    yield from rest


def _write_gif(frames: Iterator[np.ndarray], path: Path, fps: float) -> int:
    from PIL import Image

    images = [Image.fromarray(frame) for frame in frames]
    if not images:
        return 0
    duration_ms = max(20, round(1000.0 / fps))  # browsers treat shorter GIF delays as 100 ms
    images[0].save(path, format="GIF", save_all=True, append_images=images[1:], duration=duration_ms, loop=0)
    return len(images)
