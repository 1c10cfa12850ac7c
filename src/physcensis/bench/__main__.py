"""Run the benchmarks and write `bench/results/<name>.json` with the machine they ran on."""

from __future__ import annotations

import argparse
import importlib
import json
import logging
import time
from pathlib import Path

from physcensis.bench.machine import machine_info
from physcensis.fileio import atomic_write_text

# name -> "module:function" returning a dict of results
BENCHMARKS = {
    "check": "physcensis.bench.check_speed:run",
    "assets": "physcensis.bench.assets_speed:run",
    "spatial": "physcensis.bench.spatial_speed:run",
    "physics": "physcensis.bench.physics_speed:run",
    "place": "physcensis.bench.place_speed:run",
    "stability": "physcensis.bench.stability_speed:run",
    "prompts": "physcensis.bench.prompt_suite:run",
    "clutter": "physcensis.bench.clutter:run_all",
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, default=Path("bench/results"))
    parser.add_argument("--only", nargs="*", help="run only these benchmarks")
    args = parser.parse_args()
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    machine = machine_info()
    for name, target in BENCHMARKS.items():
        if args.only and name not in args.only:
            continue
        module_name, function = target.split(":")
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError:
            logging.info("skip %s: %s is not available", name, module_name)
            continue
        start = time.perf_counter()
        result = getattr(module, function)()
        record = {"benchmark": name, "machine": machine, "wall_s": round(time.perf_counter() - start, 3),
                  "result": result}
        atomic_write_text(args.out / f"{name}.json", json.dumps(record, indent=2) + "\n")
        logging.info("%s: %s", name, json.dumps(result))


if __name__ == "__main__":
    main()
