"""Where a batch's scenes are made: the driver's own process, a local process pool, or Ray.

Each runner yields one Outcome per task, in whatever order they finish, and keeps only a
bounded number of tasks in flight (every result carries a whole scene folder).
"""

from __future__ import annotations

import concurrent.futures as futures
import contextlib
import ipaddress
import logging
import multiprocessing
import os
import signal
import socket
import time
from collections import Counter, deque
from collections.abc import Iterable, Iterator, Sequence
from multiprocessing.queues import SimpleQueue
from typing import Any
from urllib.parse import urlsplit

from physcensis.batch.prompts import BatchError, Task
from physcensis.batch.worker import (
    Options,
    Outcome,
    Parses,
    SceneMaker,
    StartBoard,
    failure,
    init_local_worker,
    make_scene,
    remove_temp_of,
    run_task,
    timed_out,
    warm_up,
)
from physcensis.redaction import strip_userinfo

log = logging.getLogger(__name__)

IN_FLIGHT_PER_WORKER = 2
MAX_ATTEMPTS = 2  # a task in flight when a worker process died this often is recorded as failed
POLL_S = 0.2  # how often running tasks are checked against the scene timeout


def local_outcomes(
    tasks: Sequence[Task], options: Options, workers: int, maker: SceneMaker = make_scene
) -> Iterator[Outcome]:
    """In this process (one worker, no scene timeout), else in a pool of spawned processes. A task over the scene
    timeout is stopped by killing its worker: that breaks the pool, and the other tasks in flight start again in
    a fresh one (not counted as attempts)."""
    if options.scene_timeout_s is None and (workers == 1 or len(tasks) <= 1):
        for task in tasks:
            yield maker(task, options)
        return
    queue = deque(tasks)
    attempts: Counter[str] = Counter()
    parses = Parses()
    while queue:
        yield from _PoolRound(options, workers, maker, parses).run(queue, attempts)


class _PoolRound:
    """One pool of spawned worker processes, used until the queue is empty or the pool breaks: a worker died, or was
    killed for the scene timeout. The tasks a broken pool still held go back to the queue."""

    def __init__(self, options: Options, workers: int, maker: SceneMaker, parses: Parses) -> None:
        self.options, self.workers, self.maker, self.parses = options, workers, maker, parses
        self.timeout = options.scene_timeout_s
        # spawn: a fresh interpreter per worker; forking a process that holds an OpenGL context is not safe.
        context = multiprocessing.get_context("spawn")
        self.starts = _Starts(context.SimpleQueue() if self.timeout else None)
        import_first = bool(self.timeout) and maker is make_scene  # a timeout must not count the start-up
        self.pool = futures.ProcessPoolExecutor(
            max_workers=workers,
            mp_context=context,
            initializer=init_local_worker,
            initargs=(self.starts.channel, import_first),
        )
        if maker is make_scene:
            # Start every worker now (a pool starts one per task submitted): they import the pipeline while the
            # driver parses the first prompts, which the tasks then carry.
            for _ in range(workers):
                self.pool.submit(warm_up)
        self.in_flight: dict[futures.Future[Outcome], Task] = {}
        self.broken = False
        self.stopped_one = False  # a worker was killed for the scene timeout (rather than dying by itself)

    def run(self, queue: deque[Task], attempts: Counter[str]) -> Iterator[Outcome]:
        try:
            while (queue or self.in_flight) and not self.broken:
                self._submit(queue)
                yield from self._finished()
                if self.timeout and not self.broken:
                    yield from self._stop_overdue(self.timeout)
            yield from self._give_back(queue, attempts)
        except BaseException:
            # Interrupted (Ctrl-C, SIGTERM, the driver stopping early): the scenes in flight would be dropped
            # anyway, and waiting for them could mean waiting for ever on a stuck one.
            _kill_workers(self.pool)
            self.broken = True
            raise
        finally:
            self.pool.shutdown(wait=not self.broken, cancel_futures=True)
            self.starts.close()

    def _submit(self, queue: deque[Task]) -> None:
        while queue and len(self.in_flight) < IN_FLIGHT_PER_WORKER * self.workers:
            task = queue.popleft()
            parsed = self.parses.of(task.prompt) if self.maker is make_scene else None
            self.in_flight[self.pool.submit(run_task, task, self.options, self.maker, None, parsed)] = task

    def _finished(self) -> Iterator[Outcome]:
        done, _ = futures.wait(
            self.in_flight, timeout=POLL_S if self.timeout else None, return_when=futures.FIRST_COMPLETED
        )
        for future in done:
            task = self.in_flight.pop(future)
            try:
                outcome = future.result()
            except futures.process.BrokenProcessPool:
                self.broken = True
                self.in_flight[future] = task  # handled with the others by _give_back
                continue
            yield outcome

    def _stop_overdue(self, timeout: float) -> Iterator[Outcome]:
        for future, task in self.starts.overdue(self.in_flight, timeout):
            del self.in_flight[future]
            self.broken = self.stopped_one = True  # the pool is replaced: the kill breaks it
            yield timed_out(task, timeout)

    def _give_back(self, queue: deque[Task], attempts: Counter[str]) -> Iterator[Outcome]:
        """The tasks still in flight in a broken pool: made again in a fresh pool, or given up."""
        if self.stopped_one:
            yield from _finished_ones(self.in_flight)
            self.starts.stop_all(self.in_flight.values())  # their work is lost with the pool; they start again
        # A worker died (killed, out of memory, crashed): the pool is gone. Every task that was in flight gets
        # another try in a fresh pool; one that was in flight every time is given up.
        for task in self.in_flight.values():
            attempts[task.key] += 0 if self.stopped_one else 1
            if attempts[task.key] >= MAX_ATTEMPTS:
                yield failure(task, f"a worker process died while making it ({MAX_ATTEMPTS} times)")
            else:
                queue.appendleft(task)


def _kill_workers(pool: futures.ProcessPoolExecutor) -> None:
    for process in list((getattr(pool, "_processes", None) or {}).values()):  # the executor has no public way
        process.kill()


def _finished_ones(in_flight: dict[futures.Future[Outcome], Task]) -> Iterator[Outcome]:
    """Take out and yield the tasks of an abandoned pool that finished all the same."""
    for future in [f for f in in_flight if f.done() and f.exception() is None]:
        del in_flight[future]
        yield future.result()


class _Starts:
    """Which pool worker runs which task, and since when, as the workers report it (only under a scene timeout)."""

    def __init__(self, channel: SimpleQueue | None) -> None:
        self.channel = channel
        self.since: dict[str, tuple[int, float]] = {}  # task key -> (worker pid, driver's clock at the report)
        self.current: dict[int, str] = {}  # worker pid -> the task it took last
        self.stopped: list[int] = []

    def read(self) -> None:
        while self.channel is not None and not self.channel.empty():
            key, pid = self.channel.get()
            self.since[key] = (pid, time.monotonic())
            self.current[pid] = key

    def worker_of(self, key: str) -> int | None:
        pid, _ = self.since.get(key, (None, 0.0))
        return pid if pid is not None and self.current.get(pid) == key else None

    def overdue(
        self, in_flight: dict[futures.Future[Outcome], Task], timeout_s: float
    ) -> list[tuple[futures.Future[Outcome], Task]]:
        """The tasks running longer than `timeout_s`, their workers killed."""
        self.read()
        now = time.monotonic()
        late = []
        for future, task in in_flight.items():
            pid = self.worker_of(task.key)
            if pid is not None and not future.done() and now - self.since[task.key][1] > timeout_s:
                self._kill(pid)
                late.append((future, task))
        return late

    def stop_all(self, tasks: Iterable[Task]) -> None:
        self.read()
        for task in tasks:
            pid = self.worker_of(task.key)
            if pid is not None:
                self._kill(pid)

    def _kill(self, pid: int) -> None:
        try:
            os.kill(pid, signal.SIGKILL)  # a scene stuck in C code ignores anything milder
        except ProcessLookupError:
            return
        self.stopped.append(pid)

    def close(self) -> None:
        if self.channel is not None:
            self.channel.close()
        for pid in self.stopped:
            remove_temp_of(pid)


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
    from physcensis.agent.factory import llm_agent
    from physcensis.llm.client import LLMRequestError

    agent = llm_agent(options.settings.models)
    if on_ray and _is_loopback(agent.base_url):
        return
    try:
        served = agent.served_models()
    except LLMRequestError as exc:
        raise BatchError(options.redactor().text(f"--llm {options.llm}: {exc}")) from None
    if served and options.llm not in served:
        log.warning(
            "--llm %s: %s lists only %s; going on, as some servers answer to any model name",
            options.llm,
            strip_userinfo(agent.base_url),
            ", ".join(served[:5]) + (" ..." if len(served) > 5 else ""),
        )


def _is_loopback(url: str) -> bool:
    host = urlsplit(url).hostname or ""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def ray_outcomes(
    tasks: Sequence[Task], options: Options, workers: int, address: str | None, maker: SceneMaker = make_scene
) -> Iterator[Outcome]:
    """Tasks on Ray; one over the scene timeout (timed from its start, by an actor) is cancelled with force,
    which kills the Ray worker process running it."""
    import ray

    started_here = _join_ray(address, workers)
    in_flight: dict[Any, Task] = {}  # Ray object ref -> its task
    try:
        timeout = options.scene_timeout_s
        remote = ray.remote(num_cpus=1, max_retries=1)(run_task)
        board = ray.remote(num_cpus=0)(StartBoard).remote() if timeout else None
        queue = deque(tasks)
        limit = IN_FLIGHT_PER_WORKER * max(workers, int(ray.cluster_resources().get("CPU", workers)))
        parses = Parses()
        while queue or in_flight:
            while queue and len(in_flight) < limit:
                task = queue.popleft()
                parsed = parses.of(task.prompt) if maker is make_scene else None
                in_flight[remote.remote(task, options, maker, board, parsed)] = task
            yield from _ray_finished(in_flight, options, POLL_S if timeout else None)
            if timeout and in_flight:
                yield from _ray_overdue(in_flight, board, timeout)
    except BaseException:
        for ref in in_flight:  # interrupted: nothing would collect them, and a cluster would run them on
            with contextlib.suppress(Exception):
                ray.cancel(ref, force=True)
        raise
    finally:
        if started_here:
            ray.shutdown()


def _join_ray(address: str | None, workers: int) -> bool:
    """Join the cluster at `address`, or start a local Ray with `workers` CPUs; True if it was started here."""
    import ray

    if ray.is_initialized():
        return False
    try:
        if address:
            ray.init(address=address, log_to_driver=False)
        else:
            ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
    except Exception as exc:  # Ray raises many kinds; the user needs one line
        raise BatchError(f"cannot start or join Ray ({address or 'local'}): {exc}") from None
    return True


def _ray_finished(in_flight: dict[Any, Task], options: Options, wait_s: float | None) -> Iterator[Outcome]:
    """Take out and yield the tasks that are done (waiting up to `wait_s` for one, or until one is)."""
    import ray

    ready, _ = ray.wait(list(in_flight), num_returns=1, timeout=wait_s)
    for ref in ready:
        task = in_flight.pop(ref)
        try:
            outcome = ray.get(ref)
        except Exception as exc:  # a lost worker or node fails that scene, not the run
            outcome = failure(task, options.redactor().text(f"the Ray task failed: {exc}"))
        yield outcome


def _ray_overdue(in_flight: dict[Any, Task], board: Any, timeout_s: float) -> Iterator[Outcome]:
    """Cancel and yield as failed the tasks running longer than `timeout_s`. `board` is the StartBoard actor's
    handle (Any: Ray's stubs do not type an actor's remote methods)."""
    import ray

    running: dict[str, float] = ray.get(board.running_for.remote([t.key for t in in_flight.values()]))
    for ref, task in list(in_flight.items()):
        if running.get(task.key, 0.0) > timeout_s:
            ray.cancel(ref, force=True)
            del in_flight[ref]
            yield timed_out(task, timeout_s)
