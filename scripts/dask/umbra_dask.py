#!/usr/bin/python3
"""umbra's sharded jobs on Dask's distributed scheduler, the alternative to
Slurm for pipelines driven from Python (docs/scale.md): each shard is one
`umbra` command run by a Dask worker, the merge runs when every shard has
ended, and the result is the same bytes as the one-process run.

    scripts/dask/umbra_dask.py frame SCENE OUTDIR N [--scheduler ADDR] [-- render options]
    scripts/dask/umbra_dask.py truth OUTDIR N --meshes PATH... [--scheduler ADDR] [-- fuzz real options]

Without --scheduler a LocalCluster of --workers threads (default: the CPUs)
runs the shards here; with it (tcp://host:8786, a `dask scheduler` whose
`dask worker`s share the file system) the cluster does. UMBRA names the
executable (default: umbra on PATH). Exit status: the merge's (0 all
passed, 1 a scene failed, 2 bad input); a shard that could not run makes
the merge refuse, naming it. From Python, `frame(...)` and `truth(...)`
take a dask.distributed Client and return the merge's exit code.
"""
import argparse
import os
import shutil
import subprocess
import sys


def umbra():
    """The executable, as an absolute path (workers may run elsewhere)."""
    name = os.environ.get("UMBRA", "umbra")
    found = shutil.which(name)
    return os.path.abspath(found) if found else name


def run(command):
    """One shard or merge: its exit code (a failing shard still has a part
    worth merging; the merge decides)."""
    return subprocess.run(command, check=False).returncode


def frame(client, scene, out, n, options=()):
    """Tile I of N (umbra render --tile I/N) per task; merged when all
    succeeded, as Slurm's afterok: a frame with a missing tile cannot be
    merged."""
    os.makedirs(out, exist_ok=True)
    tiles = [os.path.join(out, f"tile-{i}.exr") for i in range(n)]
    commands = [[umbra(), "render", scene, "--tile", f"{i}/{n}", "-q", *options, "-o", tiles[i]]
                for i in range(n)]
    codes = client.gather(client.map(run, commands, pure=False))
    failed = [i for i, code in enumerate(codes) if code != 0]
    if failed:
        print(f"umbra_dask: tiles {failed} failed; nothing merged", file=sys.stderr)
        return 1
    return run([umbra(), "merge", *tiles, "-q", "-o", os.path.join(out, "frame.exr")])


def truth(client, out, n, meshes, options=()):
    """The real-model sweep in N shards (umbra fuzz real --shard I/N), merged
    by umbra fuzz merge after every shard ended, pass or fail."""
    os.makedirs(out, exist_ok=True)
    roots = [arg for mesh in meshes for arg in ("--meshes", mesh)]
    parts = [os.path.join(out, f"part-{i}.json") for i in range(n)]
    commands = [[umbra(), "fuzz", "real", *roots, "--shard", f"{i}/{n}", "-q", *options,
                 "--summary", parts[i], "--junit", os.path.join(out, f"part-{i}.xml")]
                for i in range(n)]
    client.gather(client.map(run, commands, pure=False))
    return run([umbra(), "fuzz", "merge", *parts, "-q", "-o", os.path.join(out, "summary.json"),
                "--junit", os.path.join(out, "junit.xml")])


def main(argv):
    before, after = _split(argv)
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("job", choices=["frame", "truth"])
    parser.add_argument("args", nargs="+", help="frame: SCENE OUTDIR N; truth: OUTDIR N")
    parser.add_argument("--meshes", nargs="+", default=[], help="truth: mesh files or folders")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler")
    parser.add_argument("--workers", type=int, default=os.cpu_count(),
                        help="threads of the local cluster (without --scheduler)")
    a = parser.parse_args(before)
    if not shutil.which(umbra()):
        print(f"umbra_dask: no executable '{umbra()}' (set UMBRA or PATH)", file=sys.stderr)
        return 2
    expected = 3 if a.job == "frame" else 2
    if len(a.args) != expected or not a.args[-1].isdigit() or int(a.args[-1]) < 1:
        parser.error(f"{a.job} takes {'SCENE OUTDIR N' if a.job == 'frame' else 'OUTDIR N'}"
                     " with N a positive whole number")
    if a.job == "truth" and not a.meshes:
        parser.error("truth needs --meshes")
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        print("umbra_dask: Dask is not installed (apt-get install python3-distributed)",
              file=sys.stderr)
        return 77
    n = int(a.args[-1])
    if a.scheduler:
        client = Client(a.scheduler)
    else:
        # Threads, not processes: a task only waits for its umbra process.
        client = Client(LocalCluster(n_workers=1, threads_per_worker=a.workers, processes=False,
                                     dashboard_address=None))
    with client:
        if a.job == "frame":
            return frame(client, a.args[0], a.args[1], n, after)
        return truth(client, a.args[0], n, a.meshes, after)


def _split(argv):
    """The arguments before `--` and the umbra options after it."""
    if "--" in argv:
        k = argv.index("--")
        return argv[:k], argv[k + 1:]
    return argv, []


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
