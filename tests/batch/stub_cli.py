"""The real `physcensis` command line, with the batch's scenes made by `stub_scene`.

Run as `python -m tests.batch.stub_cli batch PROMPTS --out DIR ...` from the repository root. The batch command calls
`physcensis.batch.run_batch`; here that is the same function with its `scene_maker` bound to the stub, so everything
else (options, the driver, the pool, signals, the summary and exit codes) is what users run.

The imports are under the `__main__` guard: spawned pool workers import this module again (as `__mp_main__`), and
they need only `stub_scene`, not the command line (a second of imports per worker start).
"""

from __future__ import annotations

if __name__ == "__main__":
    import functools

    import physcensis.batch
    from physcensis.cli import main
    from tests.batch.stub_scenes import stub_scene

    physcensis.batch.run_batch = functools.partial(physcensis.batch.run_batch, scene_maker=stub_scene)
    main()
