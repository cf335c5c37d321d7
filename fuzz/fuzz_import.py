#!/usr/bin/python3
"""Fuzzes the apitrace importer's state tracker and scene writer (replay/) in process: a trace's
calls, mutated at random (calls dropped, repeated, moved or renamed; arguments replaced by
hostile values: negative, huge, NaN, wrong types, '../' names, short blobs), are imported and
written out. Each input must either import or stop with the importer's error (exit 2 in the
command); any other exception is a finding, and every file written must lie inside the output
folder. Deterministic for a seed.

    fuzz_import.py TRACE SECONDS [--seed N] [--artifacts DIR]
    fuzz_import.py TRACE --executions N [--seed N]   # a fixed number of inputs: the same every run
    fuzz_import.py --rdc CAPTURE --tessref BIN (SECONDS | --executions N)

With --rdc, a RenderDoc capture's bytes are changed at random (1 to 8 bytes) and each copy is
imported by `tessref import` in its own process: exit 0 or 2 is expected; 3 (an importer bug) is
a finding. RenderDoc's own reader crashing on a damaged file, or its replay running past
--timeout (a damaged draw count), is counted apart: the command then exits 2 naming the signal or
the timeout, and writes nothing.

Prints the executions, the imports that succeeded, the refusals and the findings (each with its
traceback and the mutated calls pickled into DIR); exits 1 if there was a finding.
"""
import argparse
import os
import pickle
import random
import shutil
import subprocess
import sys
import tempfile
import time
import traceback

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "replay"))

import gl_state  # noqa: E402
import texture_upload  # noqa: E402
from apitrace_reader import Call, Pointer, read_calls  # noqa: E402
from import_error import ImportFailure  # noqa: E402
from tessref_import import import_calls, scene_of, write_output  # noqa: E402

# Small limits, so that a declared size is refused or allocated quickly (the logic is the same).
gl_state.MAX_BUFFER_BYTES = 1 << 20
texture_upload.MAX_IMAGE_BYTES = 1 << 20

HOSTILE = [None, -1, 0, 1, 3, 16, 2 ** 31, 2 ** 63, -2 ** 63, 1e308, float("nan"), float("-inf"), "../x", "",
           "GL_PATCHES", "GL_TEXTURE_2D", "GL_FLOAT", "GL_TRUE", b"", b"\x00" * 3, b"\xff" * 64, [], [0] * 20,
           [1.5, -2.0], (), ("GL_COLOR_BUFFER_BIT",), Pointer(0x1234), "\x00", "a" * 300]


def mutate(calls, rng, names):
    calls = list(calls)
    for _ in range(rng.randint(1, 4)):
        if not calls:
            break
        i = rng.randrange(len(calls))
        kind = rng.randrange(7)
        if kind == 0:
            del calls[i]
        elif kind == 1:
            calls.insert(rng.randrange(len(calls) + 1), calls[i])
        elif kind == 2:
            j = rng.randrange(len(calls))
            calls[i], calls[j] = calls[j], calls[i]
        elif kind == 3:
            c = calls[i]
            calls[i] = Call(c.no, rng.choice(names), dict(c.args), c.ret, c.flags)
        else:
            c = calls[i]
            args = dict(c.args)
            if args and kind != 6:
                key = rng.choice(sorted(args))
                value = args[key]
                if isinstance(value, (bytes, bytearray)) and value and rng.random() < 0.5:
                    args[key] = value[:rng.randrange(len(value))]
                elif isinstance(value, int) and not isinstance(value, bool) and rng.random() < 0.5:
                    args[key] = value + rng.choice([-1, 1, 256, -256, 1 << 20])
                elif rng.random() < 0.2:
                    del args[key]
                else:
                    args[key] = rng.choice(HOSTILE)
            ret = rng.choice(HOSTILE + [c.ret]) if kind == 6 else c.ret
            calls[i] = Call(c.no, c.name, args, ret, c.flags)
    # Keep call numbers increasing, as a trace's are.
    return [Call(n, c.name, c.args, c.ret, c.flags) for n, c in enumerate(calls)]


def run_one(calls, out_root):
    out = tempfile.mkdtemp(dir=out_root)
    try:
        frame = import_calls(iter(calls), "fuzz.trace", None, False)
        scene = scene_of(frame)
        write_output(frame, scene, "fuzz.trace", "apitrace", frame.draws[-1][0], out, None)
        root = os.path.realpath(out)
        for folder, _, files in os.walk(out):
            for f in files:
                if not os.path.realpath(os.path.join(folder, f)).startswith(root + os.sep):
                    raise AssertionError("wrote %s outside the output folder" % os.path.join(folder, f))
        return "imported"
    except ImportFailure:
        return "refused"
    finally:
        shutil.rmtree(out, ignore_errors=True)


def fuzz_rdc(args):
    source = open(args.rdc, "rb").read()
    rng = random.Random(args.seed)
    counts = {"imported": 0, "refused": 0, "renderdoc crashed": 0, "stopped by --timeout": 0, "finding": 0}
    work = tempfile.mkdtemp(prefix="tessref-fuzz-rdc-")
    start, executions = time.monotonic(), 0
    try:
        while time.monotonic() - start < args.seconds and (args.executions is None or executions < args.executions):
            data = bytearray(source)
            for _ in range(rng.randint(1, 8)):
                data[rng.randrange(len(data))] = rng.randrange(256)
            capture = os.path.join(work, "input.rdc")
            with open(capture, "wb") as f:
                f.write(data)
            out = os.path.join(work, "out")
            executions += 1
            try:
                result = subprocess.run([args.tessref, "import", capture, "--out", out, "--timeout", str(args.timeout)],
                                        capture_output=True, timeout=args.timeout + 60)
            except subprocess.TimeoutExpired:
                counts["finding"] += 1
                os.makedirs(args.artifacts, exist_ok=True)
                path = os.path.join(args.artifacts, "rdc-hang-%d.rdc" % counts["finding"])
                shutil.copyfile(capture, path)
                print("finding: the import ran past its --timeout of %d s by a minute, kept as %s" % (args.timeout, path))
                shutil.rmtree(out, ignore_errors=True)
                continue
            stderr = result.stderr.decode("utf-8", "replace")
            if result.returncode == 0:
                counts["imported"] += 1
            elif result.returncode == 2:
                counts["renderdoc crashed" if "died of signal" in stderr else
                       "stopped by --timeout" if "(--timeout)" in stderr else "refused"] += 1
            else:
                counts["finding"] += 1
                os.makedirs(args.artifacts, exist_ok=True)
                path = os.path.join(args.artifacts, "rdc-finding-%d.rdc" % counts["finding"])
                shutil.copyfile(capture, path)
                print("finding (exit %d), kept as %s:\n%s" % (result.returncode, path, stderr[-2000:]))
            leftovers = [n for n in os.listdir(work) if n != "input.rdc"]
            if result.returncode != 0 and leftovers:
                counts["finding"] += 1
                print("a refused import left %s behind" % leftovers)
            shutil.rmtree(out, ignore_errors=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("fuzz_import --rdc: %d executions in %.0f s: %s" % (executions, time.monotonic() - start,
                                                              ", ".join("%d %s" % (v, k) for k, v in counts.items())))
    return 1 if counts["finding"] else 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("trace", nargs="?")
    parser.add_argument("--rdc")
    parser.add_argument("--tessref")
    parser.add_argument("--timeout", type=int, default=60, help="--rdc: seconds after which an import is a hang")
    parser.add_argument("seconds", type=float, nargs="?", default=float("inf"))
    parser.add_argument("--executions", type=int)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--artifacts", default="out/fuzz/fuzz_import/artifacts")
    args = parser.parse_args()
    if args.rdc and args.trace is not None and args.seconds == float("inf"):
        # --rdc takes no trace: its one positional is SECONDS.
        try:
            args.seconds, args.trace = float(args.trace), None
        except ValueError:
            parser.error("--rdc takes SECONDS, not a trace")
    if args.executions is None and args.seconds == float("inf"):
        parser.error("give SECONDS or --executions")
    if args.rdc:
        if not args.tessref:
            parser.error("--rdc needs --tessref BIN")
        return fuzz_rdc(args)
    if not args.trace:
        parser.error("give TRACE or --rdc CAPTURE")
    calls = list(read_calls(args.trace))
    names = sorted({c.name for c in calls})
    rng = random.Random(args.seed)
    counts = {"imported": 0, "refused": 0, "finding": 0}
    sites = {}
    os.makedirs(args.artifacts, exist_ok=True)
    out_root = tempfile.mkdtemp(prefix="tessref-fuzz-import-")
    start = time.monotonic()
    executions = 0
    try:
        assert run_one(calls, out_root) == "imported", "the unmutated trace must import"
        while time.monotonic() - start < args.seconds and (args.executions is None or executions < args.executions):
            mutated = mutate(calls, rng, names)
            executions += 1
            try:
                counts[run_one(mutated, out_root)] += 1
            except Exception:
                counts["finding"] += 1
                tb = traceback.format_exc()
                site = tb.strip().splitlines()[-3] if len(tb.strip().splitlines()) >= 3 else tb
                if site not in sites:
                    sites[site] = tb
                    path = os.path.join(args.artifacts, "finding-%d.pickle" % len(sites))
                    with open(path, "wb") as f:
                        pickle.dump([(c.no, c.name, c.args, c.ret, c.flags) for c in mutated], f)
                    with open(path + ".txt", "w") as f:
                        f.write(tb)
    finally:
        shutil.rmtree(out_root, ignore_errors=True)
    print("fuzz_import: %d executions in %.0f s: %d imported, %d refused, %d findings (%d distinct)"
          % (executions, time.monotonic() - start, counts["imported"], counts["refused"], counts["finding"], len(sites)))
    for tb in sites.values():
        print(tb)
    return 1 if sites else 0


if __name__ == "__main__":
    sys.exit(main())
