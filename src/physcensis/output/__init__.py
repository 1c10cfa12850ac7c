"""Output: a solved scene written to its folder (scene.json, report.json, render, layout plot, exports).

This layer sits above both `solve` and `export`, so neither of them has to reach up to write files.
"""

from physcensis.output.scene_assets import open_scene, scene_catalogue
from physcensis.output.scene_folder import DEFAULT_EXPORTS, write_solution

__all__ = ["DEFAULT_EXPORTS", "open_scene", "scene_catalogue", "write_solution"]
