"""Reads an apitrace trace as a stream of calls, through `apitrace pickle --symbolic`.

The pickle stream comes from a file a user was given, so it is unpickled with an allow-list: the
one class apitrace's stream names (unpickle.Pointer, an address) becomes an int subclass here, and
any other class stops the import. Nothing from the trace is executed.
"""

import io
import pickle
import shutil
import subprocess

from import_error import ImportFailure


class Pointer(int):
    """An address the application passed or got back (a mapped buffer, a client array)."""

    def __repr__(self):
        return "Pointer(0x%x)" % int(self)


class _AllowListUnpickler(pickle.Unpickler):
    def find_class(self, module, name):
        if (module, name) == ("unpickle", "Pointer"):
            return Pointer
        raise ImportFailure("the trace's call stream names the class %s.%s, which an apitrace "
                            "pickle stream never holds: the file is not a trace tessref can read" % (module, name))


class Call:
    """One call: its number, name, arguments by name, return value and apitrace's flags."""

    __slots__ = ("no", "name", "args", "ret", "flags")

    # apitrace's call flags (common/trace_model.hpp)
    FAKE = 1
    END_FRAME = 32

    def __init__(self, no, name, args, ret, flags):
        self.no, self.name, self.args, self.ret, self.flags = no, name, args, ret, flags

    def arg(self, key, default=None):
        return self.args.get(key, default)

    def __repr__(self):
        return "%d %s" % (self.no, self.name)


def check_trace_file(path):
    """A truncated or foreign file is refused before apitrace is run on it."""
    with open(path, "rb") as f:
        head = f.read(16)
    # apitrace writes Snappy-framed traces ('at' + chunks) and, with -z, gzip ones.
    if not (head.startswith(b"at") or head.startswith(b"\x1f\x8b")):
        raise ImportFailure("%s is not an apitrace trace (its first bytes are %r)" % (path, head[:8]))


def read_calls(path, last_call=None):
    """Yields the trace's calls in order, up to and including last_call when given."""
    apitrace = shutil.which("apitrace")
    if not apitrace:
        raise ImportFailure("apitrace is not installed (Debian package apitrace): it reads .trace files")
    check_trace_file(path)
    command = [apitrace, "pickle", "--symbolic"]
    if last_call is not None:
        command.append("--calls=0-%d" % last_call)
    command.append(path)
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        stream = io.BufferedReader(process.stdout, 1 << 20)
        unpickler = _AllowListUnpickler(stream)
        count = 0
        while True:
            try:
                item = unpickler.load()
            except EOFError:
                break
            except ImportFailure:
                raise
            except Exception as e:  # a damaged stream: pickle raises many kinds
                raise ImportFailure("the trace's call stream is damaged after %d calls (%s)" % (count, e))
            if not (isinstance(item, tuple) and len(item) == 5 and isinstance(item[0], int) and isinstance(item[1], str)
                    and isinstance(item[2], list)):
                raise ImportFailure("the trace's call stream holds something that is not a call after %d calls" % count)
            no, name, args, ret, flags = item
            try:
                arguments = dict(args)
            except (TypeError, ValueError):
                raise ImportFailure("call %d (%s): its arguments are not name/value pairs" % (no, name))
            count += 1
            yield Call(no, name, arguments, ret, flags)
    finally:
        process.stdout.close()
        err = process.stderr.read().decode("utf-8", "replace")
        process.stderr.close()
        code = process.wait()
    if "unexpected end of file" in err:
        raise ImportFailure("%s is truncated: apitrace read %d calls, then the file ended in the middle of one"
                            % (path, count))
    if code != 0 or (count == 0 and err.strip()):
        raise ImportFailure("apitrace cannot read %s: %s" % (path, err.strip().splitlines()[-1] if err.strip() else
                                                             "exit status %d" % code))
