"""The `physcensis` command line (`physcensis.cli:main` is the console script).

`errors` is its one error path and set of exit codes; the commands live by topic in `programs` (check, predicates),
`scenes` (solve, generate, export, render), `evaluate` (eval settle, stability), `view` (the live 3-D viewer), `batch`,
`bench` and `assets`; `app` puts them together.
"""

from physcensis.cli.app import app, main

__all__ = ["app", "main"]
