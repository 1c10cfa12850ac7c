"""Where a batch's scenes are made: the driver's own process, a local process pool, or Ray.

Each runner yields one Outcome per task, in whatever order they finish, and keeps only a
bounded number of tasks in flight (every result carries a whole scene folder).
"""

from __future__ import annotations

import concurrent.futures as futures
import ipaddress
import logging
import multiprocessing
import socket
from collections import Counter, deque
from collections.abc import Iterator, Sequence
from typing import Any
from urllib.parse import urlsplit

from physcensis.batch.prompts import BatchError, Task
from physcensis.batch.worker import Options, Outcome, failure, init_local_worker, make_scene

log = logging.getLogger(__name__)

IN_FLIGHT_PER_WORKER = 2
MAX_ATTEMPTS = 2  # a task in flight when a worker process died this often is recorded as failed


def local_outcomes(tasks: Sequence[Task], options: Options, workers: int) -> Iterator[Outcome]:
    if workers == 1 or len(tasks) <= 1:
        for task in tasks:
            yield make_scene(task, options)
        return
    queue = deque(tasks)
    attempts: Counter[str] = Counter()
    # spawn: a fresh interpreter per worker; forking a process that holds an OpenGL context is not safe.
    context = multiprocessing.get_context("spawn")
    while queue:
        pool = futures.ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=init_local_worker)
        in_flight: dict[futures.Future[Outcome], Task] = {}
        broken = False
        try:
            while (queue or in_flight) and not broken:
                while queue and len(in_flight) < IN_FLIGHT_PER_WORKER * workers:
                    task = queue.popleft()
                    in_flight[pool.submit(make_scene, task, options)] = task
                done, _ = futures.wait(in_flight, return_when=futures.FIRST_COMPLETED)
                for future in done:
                    task = in_flight.pop(future)
                    try:
                        yield future.result()
                    except futures.process.BrokenProcessPool:
                        broken = True
                        in_flight[future] = task  # handled with the others below
            # A worker died (killed, out of memory, crashed): the pool is gone. Every task that was in flight
            # gets another try in a fresh pool; one that was in flight every time is given up.
            for task in in_flight.values():
                attempts[task.key] += 1
                if attempts[task.key] >= MAX_ATTEMPTS:
                    yield failure(task, f"a worker process died while making it ({MAX_ATTEMPTS} times)")
                else:
                    queue.appendleft(task)
        finally:
            pool.shutdown(wait=not broken, cancel_futures=True)


def check_ray(address: str | None) -> None:
    """Fail fast, before anything is written: Ray missing, or an address nobody answers at (Ray itself retries
    for minutes)."""
    try:
        import ray  # noqa: F401
    except ImportError:
        raise BatchError("--ray needs the optional extra: pip install 'physcensis[ray]'") from None
    host_port = (address or "").removeprefix("ray://")
    if not address or address == "auto" or ":" not in host_port:
        return
    host, _, port = host_port.rpartition(":")
    try:
        with socket.create_connection((host, int(port)), timeout=5.0):
            pass
    except (OSError, ValueError) as exc:
        raise BatchError(f"cannot reach the Ray cluster at {address}: {exc}") from None


def check_llm(options: Options, on_ray: bool) -> None:
    """Fail fast, before anything is written, when the LLM server does not answer or refuses the key: otherwise
    every scene would spend its retries on it and fail alike. On Ray a loopback server is each node's own, so the
    driver cannot check it."""
    if options.llm is None:
        return
    from physcensis.agent.llm import LLMAgent, LLMRequestError

    agent = LLMAgent(options.llm, base_url=options.base_url)
    if on_ray and _is_loopback(agent.base_url):
        return
    try:
        served = agent.served_models()
    except LLMRequestError as exc:
        raise BatchError(f"--llm {options.llm}: {exc}") from None
    if served and options.llm not in served:
        log.warning("--llm %s: %s lists only %s; going on, as some servers answer to any model name",
                    options.llm, agent.base_url, ", ".join(served[:5]) + (" ..." if len(served) > 5 else ""))


def _is_loopback(url: str) -> bool:
    host = urlsplit(url).hostname or ""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def ray_outcomes(tasks: Sequence[Task], options: Options, workers: int, address: str | None) -> Iterator[Outcome]:
    import ray

    started_here = not ray.is_initialized()
    if started_here:
        try:
            if address:
                ray.init(address=address, log_to_driver=False)
            else:
                ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
        except Exception as exc:  # noqa: BLE001 - Ray raises many kinds; the user needs one line
            raise BatchError(f"cannot start or join Ray ({address or 'local'}): {exc}") from None
    try:
        remote = ray.remote(num_cpus=1, max_retries=1)(make_scene)
        queue = deque(tasks)
        in_flight: dict[Any, Task] = {}
        limit = IN_FLIGHT_PER_WORKER * max(workers, int(ray.cluster_resources().get("CPU", workers)))
        while queue or in_flight:
            while queue and len(in_flight) < limit:
                task = queue.popleft()
                in_flight[remote.remote(task, options)] = task
            ready, _ = ray.wait(list(in_flight), num_returns=1)
            task = in_flight.pop(ready[0])
            try:
                yield ray.get(ready[0])
            except Exception as exc:  # noqa: BLE001 - a lost worker or node fails that scene, not the run
                yield failure(task, f"the Ray task failed: {exc}")
    finally:
        if started_here:
            ray.shutdown()
