"""Run the benchmarks, write `bench/results/<name>.json` with the machine they ran on, then regenerate the
benchmark tables of docs/BENCHMARKS.md from those files. `python -m physcensis.bench llm --base-url URL --model NAME`
runs the prompt suite against a real model instead (see bench/llm_suite.py)."""

from __future__ import annotations

import argparse
import importlib
import json
import logging
import sys
import time
from pathlib import Path
from typing import Any

from physcensis.bench.report import BENCHMARKS_DOC, update_tables
from physcensis.fileio import atomic_write_text
from physcensis.machine import machine_info

# name -> "module:function" returning a dict of results
BENCHMARKS = {
    "check": "physcensis.bench.check_speed:run",
    "assets": "physcensis.bench.assets_speed:run",
    "import": "physcensis.bench.import_speed:run",
    "spatial": "physcensis.bench.spatial_speed:run",
    "physics": "physcensis.bench.physics_speed:run",
    "place": "physcensis.bench.place_speed:run",
    "stability": "physcensis.bench.stability_speed:run",
    "stability_controls": "physcensis.bench.stability_controls:run",
    "prompts": "physcensis.bench.prompt_suite:run",
    "prompts_home": "physcensis.bench.prompt_suite:run_home",
    "prompts_reading": "physcensis.bench.prompt_suite:run_reading",
    "clutter": "physcensis.bench.clutter:run_all",
    "variety": "physcensis.bench.variety:run_public",
    "variety_home": "physcensis.bench.variety:run_home",
    "batch": "physcensis.bench.batch_throughput:run",
    "crosscheck": "physcensis.bench.bullet_crosscheck:run",
    "crosscheck_genesis": "physcensis.bench.genesis_crosscheck:run",
    "demos": "physcensis.bench.robot_demos:run",
    "compare": "physcensis.bench.method_compare:run",
    "compare_crowded": "physcensis.bench.method_compare:run_crowded",
    "report_open": "physcensis.bench.report_open:run",
}


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, default=Path("bench/results"))
    parser.add_argument("--only", nargs="*", help="run only these benchmarks")
    parser.add_argument("--list", action="store_true", help="list the benchmarks and exit")
    parser.add_argument("--doc", type=Path, default=BENCHMARKS_DOC, help="the document whose tables to regenerate")
    parser.add_argument("--no-doc", action="store_true", help="do not regenerate the document's tables")
    args = parser.parse_args(argv)
    unknown = sorted(set(args.only or ()) - BENCHMARKS.keys())
    if unknown:
        parser.error(f"unknown benchmark(s) {', '.join(unknown)}; choose from {', '.join(BENCHMARKS)}")
    return args


def run_benchmark(name: str, target: str, machine: dict[str, Any], out: Path) -> None:
    """Run one benchmark and write its JSON; a module that cannot be imported is skipped."""
    module_name, function = target.split(":")
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError:
        logging.info("skip %s: %s is not available", name, module_name)
        return
    start = time.perf_counter()
    result = getattr(module, function)()
    record = {"benchmark": name, "machine": machine, "wall_s": round(time.perf_counter() - start, 3), "result": result}
    atomic_write_text(out / f"{name}.json", json.dumps(record, indent=2) + "\n")
    logging.info("%s: %s", name, json.dumps(result))


def refresh_doc(doc: Path, results: Path) -> bool:
    """Regenerate the document's tables; False (logged) when that fails."""
    if not doc.is_file():
        logging.warning("no %s here; its benchmark tables are not regenerated", doc)
        return True
    try:
        changed = update_tables(doc, results)
    except (OSError, ValueError) as exc:
        logging.error("cannot update %s: %s", doc, exc)
        return False
    logging.info("%s: %s", doc, "benchmark tables updated" if changed else "benchmark tables already up to date")
    return True


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["llm"]:  # the prompt suite against a real model: its own options, never part of `make bench`
        from physcensis.bench.llm_suite import main as llm_main

        return llm_main(argv[1:])
    args = parse_args(argv)
    if args.list:
        for name, target in BENCHMARKS.items():
            print(f"{name}\t{target}")
        return 0
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    machine = machine_info()
    failed = []
    for name, target in BENCHMARKS.items():
        if args.only and name not in args.only:
            continue
        try:
            run_benchmark(name, target, machine, args.out)
        except Exception:
            logging.exception("benchmark %s failed; going on with the others", name)
            failed.append(name)
    if not args.no_doc and not refresh_doc(args.doc, args.out):
        failed.append(str(args.doc))
    if failed:
        logging.error("failed: %s", ", ".join(failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
