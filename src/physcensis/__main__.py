"""`python -m physcensis` is the `physcensis` command."""

from physcensis.cli import main

main()
