"""`physcensis view`: a live 3-D viewer of a scene folder in the browser (viser, the `view` extra).

Everything but the server needs no browser and no viser: `scene_view` describes what is shown (one node per placed
object with its meshes, colours, pose and the facts a click shows; the support), `camera` the first camera,
`playback` steps the scene's MuJoCo model from its written poses, `episode` reads a recorded robot demonstration's
poses and `robot_view` the arm's links along it. `server` puts them into a viser server with its buttons.
"""
