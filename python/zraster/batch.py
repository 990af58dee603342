"""Render every mesh file of folders and lists, here or on a Dask cluster (docs/batch.md).

    import zraster.batch
    records = zraster.batch.render_files(["meshes/"], "out", size=(256, 256), depth="npy")

    from dask.distributed import Client
    records = zraster.batch.render_files(["meshes/"], "out", client=Client("tcp://host:8786"))

The same jobs as ``zraster batch``: the same outputs, byte for byte, the same ``batch.jsonl``
log, skipping what is up to date. From a shell::

    python3 -m zraster.batch --scheduler tcp://HOST:PORT INPUT... -o OUTDIR [options]
"""

import functools
import json
import os
import sys
import time
import uuid
from concurrent.futures import FIRST_COMPLETED, ThreadPoolExecutor, wait

from . import _zraster

__all__ = ["render_files", "main"]


def render_files(inputs, out_dir, client=None, size=None, **options):
    """Renders every mesh file of ``inputs`` into ``out_dir`` as ``zraster batch`` does; returns
    the records of batch.jsonl as dicts, in the inputs' order.

    inputs: a path or a list of paths: files, and folders searched recursively for every format
        the loader reads. A file found in a folder keeps its path under it, a file its name.
    out_dir: the output folder (created). The log batch.jsonl is appended to there.
    client: a dask.distributed.Client: the files are rendered on its workers (each keeps one
        Renderer per thread), which must see ``inputs`` and ``out_dir`` at the same paths (a
        shared file system). None: on threads of this process (``jobs`` at once).
    size: (width, height) of the images; None: the command's default.
    options: the flags of ``zraster batch`` with underscores for dashes (``depth="npy"``,
        ``views=8``, ``shading="phong"``, ``force=True``, ``shard="0/4"``, ...; see
        ``python3 -m zraster.batch --help``). ``progress`` defaults to "none" here.

    A file that cannot be rendered is a record with status "error", never an exception; bad
    options raise zraster.InputError (a ValueError) or TypeError before any work. On a cluster,
    a worker that dies while rendering a file (killed, out of memory) has the file redone on
    another; a file whose workers die three times is an "error" record.
    """
    options.setdefault("progress", "none")
    plan = _zraster._BatchPlan(_arguments(inputs, out_dir, size, options), keyword_names=True)
    return _run(plan, client)


def _paths(inputs):
    if isinstance(inputs, (str, os.PathLike)):
        return [os.fspath(inputs)]
    paths = []
    for item in inputs:
        if not isinstance(item, (str, os.PathLike)):
            raise TypeError(f"inputs: expected paths (str or os.PathLike), got {type(item).__name__}")
        paths.append(os.fspath(item))
    return paths


def _arguments(inputs, out_dir, size, options):
    if not isinstance(out_dir, (str, os.PathLike)):
        raise TypeError(f"out_dir: expected a path (str or os.PathLike), got {type(out_dir).__name__}")
    args = _paths(inputs) + ["-o", os.fspath(out_dir)]
    if size is not None:
        try:
            width, height = (int(v) for v in size)
        except (TypeError, ValueError):
            raise TypeError(f"size: expected (width, height), got {size!r}") from None
        args.append(f"--size={width}x{height}")
    return args + _zraster._batch_flags(**options)


class _Log:
    """batch.jsonl, appended to one whole line per write (O_APPEND), as the command does."""

    def __init__(self, path):
        self._fd = os.open(path, os.O_WRONLY | os.O_APPEND | os.O_CREAT | os.O_CLOEXEC, 0o666)

    def append(self, line):
        os.write(self._fd, (line + "\n").encode())

    def close(self):
        os.close(self._fd)


def _run(plan, client):
    """Runs the plan's jobs; returns the records in the inputs' order. On KeyboardInterrupt no
    further file starts; those in flight finish and are logged, then it is raised again."""
    inputs = plan.inputs
    progress = _zraster._BatchProgress(plan.progress, len(inputs))
    log = _Log(plan.log)
    records = [None] * len(inputs)

    def done(index, line):
        log.append(line)
        record = json.loads(line)
        records[index] = record
        progress.finished(record["input"], record["status"])

    try:
        if client is None:
            _run_here(plan, inputs, progress, done)
        else:
            _run_on_cluster(client, plan, inputs, progress, done)
    finally:
        progress.close()
        log.close()
    return records


def _run_here(plan, inputs, progress, done):
    """The inputs on `plan.jobs` threads of this process, as the command runs them."""
    jobs = _zraster._BatchJobs(plan.argv, plan.jobs)

    def job(index):
        source, stem = inputs[index]
        progress.started(source)
        return jobs.run(source, stem)

    running = {}
    next_index = 0
    with ThreadPoolExecutor(max_workers=plan.jobs) as pool:
        try:
            while next_index < len(inputs) or running:
                # A few files ahead of the threads, not a million futures at once.
                while next_index < len(inputs) and len(running) < 2 * plan.jobs:
                    running[pool.submit(job, next_index)] = next_index
                    next_index += 1
                finished, _ = wait(running, return_when=FIRST_COMPLETED)
                for future in finished:
                    done(running.pop(future), future.result())
        except BaseException:
            for future in running:
                future.cancel()
            for future, index in running.items():
                if not future.cancelled():
                    done(index, future.result())
            raise


def _killed_worker_error():
    try:
        from distributed import KilledWorker
    except ImportError:
        from distributed.scheduler import KilledWorker
    return KilledWorker


def _run_on_cluster(client, plan, inputs, progress, done):
    """The inputs as tasks on the client's workers; the records come back to this process, which
    writes the log: every input ends in it exactly once, whatever happens to the workers."""
    from distributed import as_completed

    killed_worker = _killed_worker_error()
    threads = sum(client.nthreads().values()) or 1
    window = max(4 * threads, 16)
    batch_id = uuid.uuid4().hex[:12]
    in_flight = {}  # key: (index, future)
    completed = as_completed()
    next_index = 0

    def submit():
        nonlocal next_index
        source, stem = inputs[next_index]
        future = client.submit(_render_on_worker, plan.argv, batch_id, source, stem, pure=False,
                               key=f"zraster-batch-{batch_id}-{next_index}")
        in_flight[future.key] = (next_index, future)
        completed.add(future)
        progress.started(source)
        next_index += 1

    try:
        while next_index < len(inputs) and next_index < window:
            submit()
        for future in completed:
            index, _ = in_flight.pop(future.key)
            source = inputs[index][0]
            try:
                line = future.result()
            except killed_worker:
                line = _zraster._batch_error_record(
                    source, "every Dask worker that rendered it died (killed, or out of memory)")
            except Exception as error:  # noqa: BLE001: the record says what the worker raised
                line = _zraster._batch_error_record(
                    source, f"internal error on the Dask worker: {type(error).__name__}: {error}")
            done(index, line)
            if next_index < len(inputs):
                submit()
    except BaseException:
        # The tasks are cancelled. A file a worker is already rendering still ends there, its
        # outputs whole (written all or nothing) but not logged: a rerun renders them again.
        client.cancel([future for _, future in in_flight.values()])
        raise


@functools.lru_cache(maxsize=8)
def _worker_jobs(argv, batch_id):
    """The settings on a worker, parsed once per batch (argv: a tuple; batch_id: one per call of
    render_files, so that each batch reads the log's records afresh), with the default
    --max-memory shared among the worker's threads."""
    try:
        from distributed import get_worker

        worker = get_worker()
        threads = getattr(worker, "nthreads", None) or worker.state.nthreads
    except (ImportError, ValueError, AttributeError):
        threads = 1
    return _zraster._BatchJobs(list(argv), int(threads))


def _render_on_worker(argv, batch_id, source, stem):
    return _worker_jobs(tuple(argv), batch_id).run(source, stem)


def _summary(records, seconds, log):
    counts = {"ok": 0, "error": 0, "skipped": 0}
    for record in records:
        if record is not None:
            counts[record["status"]] += 1
    done = sum(counts.values())
    rate = done / seconds if seconds > 0 else 0.0
    return (counts, f"{counts['ok']} ok, {counts['error']} failed, {counts['skipped']} skipped in "
                    f"{seconds:.2f} s ({rate:.1f} files/s); log {log}")


_USAGE = """usage: python3 -m zraster.batch [--scheduler ADDRESS] INPUT... -o OUTDIR [options]

Renders every mesh file of INPUT (files, folders, --list FILE) as `zraster batch` does, on the
workers of the Dask scheduler at ADDRESS (tcp://HOST:PORT), or here without --scheduler. The
workers must see the inputs and OUTDIR at the same paths. Exit status: 0 every input ok or
skipped, 3 some failed, 2 bad usage, 1 internal error, 130 interrupted.

  --scheduler ADDRESS   the Dask scheduler (dask.distributed.Client(ADDRESS))
"""


def main(argv=None):
    """`python3 -m zraster.batch`; returns the exit status."""
    args = list(sys.argv[1:] if argv is None else argv)
    scheduler = None
    rest = []
    i = 0
    while i < len(args):
        if args[i] == "--scheduler":
            if i + 1 >= len(args):
                print("zraster.batch: --scheduler: expected an address (tcp://HOST:PORT)",
                      file=sys.stderr)
                return 2
            scheduler = args[i + 1]
            i += 2
            continue
        if args[i].startswith("--scheduler="):
            scheduler = args[i].split("=", 1)[1]
        elif args[i] in ("-h", "--help"):
            print(_USAGE + "\n" + _zraster._batch_help())
            return 0
        else:
            rest.append(args[i])
        i += 1
    start = time.monotonic()
    try:
        plan = _zraster._BatchPlan(rest, keyword_names=False)
    except ValueError as error:
        print(f"zraster.batch: {error}", file=sys.stderr)
        return 2
    client = None
    if scheduler:
        from distributed import Client

        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as error:
            print(f"zraster.batch: --scheduler {scheduler}: cannot connect: {error}",
                  file=sys.stderr)
            return 2
    try:
        records = _run(plan, client)
    except KeyboardInterrupt:
        print("zraster.batch: interrupted; the same command again finishes the rest",
              file=sys.stderr)
        return 130
    finally:
        if client is not None:
            client.close()
    counts, line = _summary(records, time.monotonic() - start, plan.log)
    print(f"zraster.batch: {line}", file=sys.stderr)
    return 3 if counts["error"] else 0


if __name__ == "__main__":
    # Run as `python3 -m zraster.batch`: the tasks sent to the workers must name the module
    # zraster.batch, which they import, not this __main__.
    from zraster import batch as _batch

    sys.exit(_batch.main())
