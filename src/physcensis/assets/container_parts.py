"""Collision for an open container in milliseconds: a base under its cavity and its wall cut into sectors.

A cup, bowl, bin or box is a base (everything below the cavity's floor) and a wall around the cavity. Cut the wall
into narrow sectors around the cavity's centre and take each sector's convex hull: each hull hugs its piece of wall
and reaches into the cavity only by the sag of a sector's chord (under 2.5 % of the cavity's radius for 15
sectors), so the cavity stays open. That holds for walls that rise steeply (cups, mugs, jars, bins, boxes); a
bowl's wall, sloping down to the middle, would be bridged by its sectors' hulls. CoACD takes seconds to minutes on
thin-walled containers: this is the first try for any mesh with a cavity, and the caller keeps it only when the
parts leave the cavity open.
"""

from __future__ import annotations

import numpy as np
import trimesh

from physcensis.assets.model import Cavity

WALL_SECTORS = 15  # with the base: 16 parts, the import's budget
SURFACE_SAMPLES = 20_000  # points on the surface besides its vertices: large faces are cut at the sector borders
SAMPLE_SEED = 0
SECTOR_OVERLAP_M = 0.002


def _surface_points(mesh: trimesh.Trimesh) -> np.ndarray:
    samples, _ = trimesh.sample.sample_surface(mesh, SURFACE_SAMPLES, seed=SAMPLE_SEED)
    return np.concatenate([np.asarray(mesh.vertices, dtype=float), np.asarray(samples, dtype=float)])


def container_parts(mesh: trimesh.Trimesh, cavity: Cavity, sectors: int = WALL_SECTORS) -> list[np.ndarray]:
    """Point sets whose convex hulls are the container's base and wall sectors (sets too small to be solid are
    left out; the caller makes the hulls)."""
    points = _surface_points(mesh)
    below = points[:, 2] <= cavity.floor_height + 1e-6
    parts = [points[below]] if below.sum() >= 4 else []
    wall = points[~below]
    opening = np.asarray(cavity.opening, dtype=float)
    centre = opening.mean(axis=0)
    angle = np.mod(np.arctan2(wall[:, 1] - centre[1], wall[:, 0] - centre[0]), 2 * np.pi)
    bounds = sector_bounds(opening, centre, sectors)
    ends = np.append(bounds[1:], bounds[0] + 2 * np.pi)
    overlap = SECTOR_OVERLAP_M / np.maximum(np.linalg.norm(wall[:, :2] - centre, axis=1), SECTOR_OVERLAP_M)
    for start, end in zip(bounds, ends, strict=True):
        # a few millimetres past each border too: neighbouring hulls overlap, leaving no slit between them
        within = np.mod(angle - (start - overlap), 2 * np.pi) < (end - start) + 2 * overlap
        piece = wall[within]
        if len(piece) >= 4:
            parts.append(piece)
    return parts


CORNER_TURN = np.radians(20.0)  # a turn of the opening's outline this sharp is a corner: sectors meet there


def sector_bounds(opening: np.ndarray, centre: np.ndarray, sectors: int) -> np.ndarray:
    """Sorted angles (radians, [0, 2 pi)) where wall sectors start. The opening's corners are among them, so a box's
    sector never spans a corner (its hull would cut the corner off the cavity); the other sectors share the arcs
    between corners by their angle. Without corners (a round cup), evenly spaced."""
    corners = _corner_angles(opening, centre)
    if not 2 <= len(corners) <= sectors:
        return np.linspace(0.0, 2 * np.pi, sectors, endpoint=False)
    arcs = np.diff(np.append(corners, corners[0] + 2 * np.pi))
    counts = np.maximum(1, np.floor(arcs / arcs.sum() * sectors)).astype(int)
    while counts.sum() < sectors:
        counts[np.argmax(arcs / counts)] += 1
    starts = [start + arc * np.arange(n) / n for start, arc, n in zip(corners, arcs, counts, strict=True)]
    return np.sort(np.mod(np.concatenate(starts), 2 * np.pi))


def _corner_angles(opening: np.ndarray, centre: np.ndarray) -> np.ndarray:
    """Angles (sorted) of the opening polygon's vertices where its outline turns sharply."""
    before, after = opening - np.roll(opening, 1, axis=0), np.roll(opening, -1, axis=0) - opening
    heading = np.arctan2(after[:, 1], after[:, 0]) - np.arctan2(before[:, 1], before[:, 0])
    turn = np.abs(np.mod(heading + np.pi, 2 * np.pi) - np.pi)
    corners = opening[turn >= CORNER_TURN]
    return np.sort(np.mod(np.arctan2(corners[:, 1] - centre[1], corners[:, 0] - centre[0]), 2 * np.pi))
