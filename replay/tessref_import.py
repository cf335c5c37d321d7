#!/usr/bin/python3
"""tessref import CAPTURE --out DIR [--event N]: an application's frame capture as a tessref scene.

`tessref import` runs this script (installed with tessref). CAPTURE is an apitrace trace; N is a
call number, by default the last GL_PATCHES draw of the capture's last frame. DIR receives
scene.json (the frame's draws up to N, docs/draws.md), the buffers, shaders and textures it
names, gpu.png (the driver's image after draw N, from retracing the capture) and report.txt
(what could not be carried, by draw). DIR appears whole or not at all: the files are written to a
sibling folder that is renamed at the end. Exit status 2, with one line on stderr, for a capture
that cannot be imported.
"""

import argparse
import base64
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from apitrace_reader import Call, read_calls  # noqa: E402
from frame_scene import FrameScene, build_scene, set_initial_images  # noqa: E402
from gl_state import DRAW_CALLS, GlState  # noqa: E402
from import_error import ImportFailure  # noqa: E402


def capture_kind(path):
    with open(path, "rb") as f:
        head = f.read(8)
    if head.startswith(b"RDOC"):
        return "renderdoc"
    if head.startswith(b"at") or head.startswith(b"\x1f\x8b"):
        return "apitrace"
    raise ImportFailure("%s is neither a RenderDoc capture (.rdc) nor an apitrace trace (.trace): its first bytes "
                        "are %r" % (path, head))


def is_patches_draw(call):
    return call.name in DRAW_CALLS and call.arg("mode") == "GL_PATCHES"


def import_apitrace(path, event, progress):
    return import_calls(read_calls(path, event), os.path.basename(path), event, progress)


def import_calls(stream, name, event, progress):
    """The frame of a stream of calls (apitrace_reader.Call) up to the draw: the target frame."""
    state = GlState()
    frame = FrameScene(state, name)
    last_frame = None
    calls = 0
    target = None
    for call in stream:
        calls += 1
        if progress and calls % 20000 == 0:
            sys.stderr.write("\rtessref import: %d calls read" % calls)
        try:
            state.apply(call)
            if call.name == "glClear":
                frame.clear(call)
            elif call.name in DRAW_CALLS:
                frame.draw(call)
        except (KeyError, TypeError, ValueError, AttributeError, IndexError, OverflowError) as e:
            # A call whose arguments are not what GL's signature says: a damaged or forged trace.
            raise ImportFailure("call %d (%s): its arguments are not what GL takes (%s: %s)"
                                % (call.no, call.name, type(e).__name__, e))
        if state.api == "gles":
            raise ImportFailure("the trace is of an OpenGL ES context (call %d, %s): tessref replays desktop GL 4.x "
                                "core draws" % (call.no, call.name))
        if event is not None and call.no == event:
            if call.name not in DRAW_CALLS:
                raise ImportFailure("call %d is %s, not a draw call" % (event, call.name))
            if not frame.draws or frame.draws[-1][0] != event:
                reasons = "; ".join(text for no, text in frame.report if no == event)
                raise ImportFailure("draw %d cannot be replayed: %s" % (event, reasons or "see the report"))
            target = frame
            break
        if call.flags & Call.END_FRAME:
            if frame.draws:
                last_frame = frame
            frame = FrameScene(state, name)
    if progress and calls >= 20000:
        sys.stderr.write("\n")
    if event is not None and target is None:
        raise ImportFailure("the trace has no call %d (it ends after %d calls)" % (event, calls))
    if target is None:
        target = frame if frame.draws else last_frame
        if target is None:
            raise ImportFailure("the trace has no draw call")
        patches = [i for i, (no, d, _, _) in enumerate(target.draws) if d["mode"] == "GL_PATCHES"]
        if not patches:
            raise ImportFailure("the trace's last frame has no GL_PATCHES draw that tessref can replay (it has %d "
                                "draw%s of other modes); name a draw with --event"
                                % (len(target.draws), "" if len(target.draws) == 1 else "s"))
        del target.draws[patches[-1] + 1:]
    target_no = target.draws[-1][0] if target.draws else None
    refused = [(no, why) for no, why in target.gpu_refusals if target_no is None or no <= target_no]
    if refused:
        no, why = refused[0]
        raise ImportFailure("the draw at call %d: %s; a trace holds the calls, not what the GPU wrote (capture the "
                            "application with RenderDoc, whose capture holds those bytes)" % (no, why))
    if state.unmodelled:
        for name, (first, count) in sorted(state.unmodelled.items(), key=lambda kv: kv[1][0]):
            target.note(first, "%s (%d call%s from call %d) changes state the importer does not model"
                        % (name, count, "" if count == 1 else "s", first))
    for no, text in state.notes:
        target.note(no, text)
    return target


def scene_of(frame):
    """build_scene, with a state no GL application can reach (a forged capture's) as an import error."""
    try:
        scene = build_scene(frame)
        json.dumps(scene, allow_nan=False)
        return scene
    except (TypeError, ValueError, KeyError, AttributeError, IndexError, OverflowError) as e:
        raise ImportFailure("the capture's state at the draw is not one GL reaches (%s: %s)" % (type(e).__name__, e))


def eglretrace(arguments):
    """apitrace's retracer on this machine's driver (it needs waffle's surfaceless EGL platform), or
    None when apitrace is not installed."""
    retrace = shutil.which("eglretrace")
    if retrace is None:
        return None
    return subprocess.run([retrace] + arguments, env=dict(os.environ, WAFFLE_PLATFORM="surfaceless_egl"),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)


def retrace_initial_images(path, frame, scene, out_dir):
    """The framebuffer before the frame's first draw, from eglretrace's state dump after the call
    before it: colour attachments as PNG, depth (apitrace's float map) as EXR through oiiotool."""
    color_files, depth_file = [], None
    if frame.first_draw is None:
        return  # the frame begins by clearing all of colour and depth
    result = eglretrace(["-D", str(max(0, frame.first_draw - 1)), path])
    if result is None:
        return set_initial_images(frame, scene, color_files, depth_file)
    try:
        state = json.loads(result.stdout.decode("utf-8", "replace"), strict=False)
        attachments = state.get("framebuffer", {})
    except ValueError:
        attachments = {}
    names = frame.draws[-1][3].get("color_names") or ["GL_BACK"]
    os.makedirs(os.path.join(out_dir, "initial"), exist_ok=True)
    for k, name in enumerate(names[:len(scene["framebuffer"]["color"])]):
        image = attachments.get(name, {})
        data = base64.b64decode(image.get("__data__", "")) if isinstance(image, dict) else b""
        if not data.startswith(b"\x89PNG"):
            color_files.append(None)
            continue
        color_files.append("initial/color%d.png" % k)
        with open(os.path.join(out_dir, color_files[-1]), "wb") as f:
            f.write(data)
    depth = attachments.get("GL_DEPTH_ATTACHMENT", {})
    data = base64.b64decode(depth.get("__data__", "")) if isinstance(depth, dict) else b""
    header = data.split(b"\n", 3)
    if len(header) == 4 and header[0] == b"Pf" and shutil.which("oiiotool"):
        # apitrace writes its float map little-endian but with scale 1, which says big-endian, and
        # its rows top first where a float map's run bottom to top: the header is written again
        # with -1 and the rows in reverse before OpenImageIO reads it.
        width, height = (int(v) for v in header[1].split())
        row = width * 4
        if len(header[3]) != row * height:
            return set_initial_images(frame, scene, color_files, None)
        rows = b"".join(header[3][(height - 1 - y) * row:(height - y) * row] for y in range(height))
        pfm = os.path.join(out_dir, "initial", "depth.pfm")
        with open(pfm, "wb") as f:
            f.write(b"Pf\n" + header[1] + b"\n-1.0\n" + rows)
        if subprocess.run(["oiiotool", pfm, "-o", os.path.join(out_dir, "initial", "depth.exr")],
                          capture_output=True).returncode == 0:
            depth_file = "initial/depth.exr"
        os.remove(pfm)
    set_initial_images(frame, scene, color_files, depth_file)


def retrace_image(path, call_no, out_dir, report):
    """The driver's own image after the draw, by retracing the capture (apitrace's eglretrace)."""
    snap_dir = os.path.join(out_dir, ".snapshots")
    os.mkdir(snap_dir)
    result = eglretrace(["-S", str(call_no), "-s", snap_dir + "/", path])
    if result is None:
        os.rmdir(snap_dir)
        report.append((None, "eglretrace is missing: no gpu.png"))
        return None
    images = sorted(os.listdir(snap_dir))
    name = None
    if result.returncode == 0 and images:
        os.replace(os.path.join(snap_dir, images[-1]), os.path.join(out_dir, "gpu.png"))
        name = "gpu.png"
    else:
        tail = result.stderr.decode("utf-8", "replace").strip().splitlines()[-1:] or ["no image"]
        report.append((None, "eglretrace could not give the image after call %d: %s" % (call_no, tail[0])))
    shutil.rmtree(snap_dir)
    return name


def write_output(frame, scene, capture, capture_kind_name, target_no, out_dir, gpu):
    for name, data in frame.files.contents.items():
        path = os.path.join(out_dir, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    with open(os.path.join(out_dir, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")
    with open(os.path.join(out_dir, "draws.json"), "w") as f:
        json.dump(frame.draw_calls, f, indent=1)
        f.write("\n")
    unit = "event" if capture_kind_name == "renderdoc" else "call"
    lines = ["capture: %s (%s)" % (os.path.abspath(capture), capture_kind_name), "draw: %s %d" % (unit, target_no),
             "gpu image: %s" % (gpu or "none"), "draws in the scene (draws.json):"]
    lines += ["  draw %d: %s %d, %s" % (d["draw"], unit, d[unit], d["name"]) for d in frame.draw_calls]
    lines.append("")
    if frame.report:
        lines.append("not carried, or carried with a caveat:")
        for no, text in frame.report:
            lines.append("  %s%s" % ("%s %d: " % (unit, no) if no is not None else "", text))
    else:
        lines.append("everything the draws read was carried")
    with open(os.path.join(out_dir, "report.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")


def _stop(signum, frame):
    raise SystemExit(2)


def main():
    signal.signal(signal.SIGTERM, _stop)  # tessref import's --timeout: the finally below still runs
    parser = argparse.ArgumentParser(prog="tessref import", description=__doc__.split("\n\n")[0])
    parser.add_argument("capture")
    parser.add_argument("--out", required=True)
    parser.add_argument("--event", type=int)
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    staging = None
    try:
        if not os.path.isfile(args.capture):
            raise ImportFailure("%s is not a file" % args.capture)
        if os.path.lexists(out) and (not os.path.isdir(out) or os.listdir(out)):
            raise ImportFailure("%s already exists and is not an empty folder: choose another --out" % args.out)
        if args.event is not None and args.event < 0:
            raise ImportFailure("--event %d: call numbers start at 0" % args.event)
        kind = capture_kind(args.capture)
        # Everything is written into a hidden sibling of DIR, renamed to DIR at the end; `tessref
        # import` removes it if this process is stopped (--timeout) before it can.
        parent = os.path.dirname(out) or "."
        os.makedirs(parent, exist_ok=True)
        staging = tempfile.mkdtemp(prefix="." + os.path.basename(out) + ".partial-", dir=parent)
        if kind == "renderdoc":
            from renderdoc_import import import_renderdoc
            frame = import_renderdoc(args.capture, args.event, staging)
            gpu = "gpu.png" if "gpu.png" in frame.gpu_images else None
            scene = scene_of(frame)
            target_no = frame.draws[-1][0]
            if frame.first_draw is not None:
                colors, depth = frame.initial_images or ([], None)
                set_initial_images(frame, scene, colors, depth)
        else:
            frame = import_apitrace(args.capture, args.event, not args.quiet)
            scene = scene_of(frame)
            target_no = frame.draws[-1][0]
            gpu = retrace_image(args.capture, target_no, staging, frame.report)
            retrace_initial_images(args.capture, frame, scene, staging)
        write_output(frame, scene, args.capture, kind, target_no, staging, gpu)
        if os.path.isdir(out):
            os.rmdir(out)
        os.rename(staging, out)
        staging = None
        carried = len(scene["draws"])
        unit = "event" if kind == "renderdoc" else "call"
        print("tessref import: %s (%s), %s %d -> %s: scene.json (%d draw%s), %s report.txt (%d note%s)"
              % (args.capture, kind, unit, target_no, args.out, carried, "" if carried == 1 else "s",
                 "gpu.png," if gpu else "no gpu.png,", len(frame.report), "" if len(frame.report) == 1 else "s"))
        for no, text in frame.report:
            print("  %s%s" % ("%s %d: " % (unit, no) if no is not None else "", text))
        return 0
    except ImportFailure as e:
        sys.stderr.write("tessref import: error: %s\n" % e)
        return 2
    except OSError as e:
        sys.stderr.write("tessref import: error: %s\n" % e)
        return 2
    except Exception:  # a bug in the importer: say so, with where, and leave nothing behind
        sys.stderr.write("tessref import: internal error (please report it with the capture):\n%s"
                         % traceback.format_exc())
        return 3
    finally:
        if staging is not None:
            shutil.rmtree(staging, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
