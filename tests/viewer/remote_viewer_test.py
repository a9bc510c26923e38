# SPDX-License-Identifier: Apache-2.0
"""viewer.remote_lcm (run by remote_viewer.sh inside a network namespace of its own).

enteron-lcm-server runs the short bowel over udpm (its device speaks millimetres:
--workspace-scale 0.001, so the viewer must map its commands into the device's frame);
while a hostile sender publishes broken messages on the viewer's channels, enteron-viewer
--lcm --headless captures the remote session with a scripted mouse drag. Then:
  - the viewer saw the session live, drew the bowel (its pink covers a plausible share of the
    picture, shaded), and rejected every broken message (counted), without a crash;
  - the server's command (mapped back into the scene) is the viewer's target;
  - the drag moved the remote tool: the server's own states say its tool 0 moved and pushed
    the bowel (a force on the tool), and the server accepted the viewer's commands and rejected none of them;
  - a second run with the server's mesh (--mesh-hz) draws that mesh;
  - with no server at all, the capture says so and exits 1.
    remote_viewer_test.py WORK_DIR   (environment: SERVER, VIEWER, SCENE, TYPES)
"""
import os
import re
import shutil
import socket
import struct
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from viewer_test import colour_classes  # noqa: E402  (the same colour classes as the local tests)

sys.path.insert(0, os.environ["TYPES"])
from enteron_lcm.enteron import mesh_t, scene_state_t, session_t  # noqa: E402

URL = "udpm://239.255.76.67:7667?ttl=0"
GROUP = ("239.255.76.67", 7667)
WIDTH, HEIGHT = 640, 360


def fail(message):
    print("viewer.remote_lcm: FAILED: " + message, file=sys.stderr)
    sys.exit(1)


def hostile_messages():
    """Broken messages, one of each kind the viewer must refuse: (channel, bytes)."""
    garbage = ("ENTERON_STATE", b"\x00\x01not a message at all")
    state = scene_state_t()
    state.radius_m = 0.0125
    state.num_control_points = 0
    state.num_axis_points = 2
    state.axis_m = [[0.0, 0.0, 0.0], [float("nan"), 0.0, 0.0]]  # well formed, not finite
    state.num_tools = 0
    state.tick = 1 << 40
    nan_state = ("ENTERON_STATE", state.encode())
    truncated = ("ENTERON_STATE", state.encode()[:-5])
    mesh = mesh_t()
    mesh.num_vertices = 3
    mesh.positions_m = [[0.0, 0.0, 0.0]] * 3
    mesh.normals = [[0.0, 0.0, 1.0]] * 3
    mesh.axis_u = [0.0] * 3
    mesh.num_triangles = 1
    mesh.triangles = [[0, 1, 999]]  # a vertex the mesh does not have
    bad_index = ("ENTERON_MESH", mesh.encode())
    session = session_t()
    session.workspace_scale = 1.0
    session.workspace_rotation_wxyz = [1.0, 0.0, 0.0, 0.0]
    session.tick_s = 0.001
    session.scene_json = "{\"intestine\": {\"length\": -1"  # not JSON the library takes
    bad_scene = ("ENTERON_SESSION", session.encode())
    return [garbage, nan_state, truncated, bad_index, bad_scene]


def send_hostile(stop, sent):
    """LCM's UDP multicast small-message format (magic "LC02", sequence number, channel,
    payload) on the namespace's loopback, a few times a second."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
    sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 0)
    sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 1)
    messages = hostile_messages()
    sequence = 0
    while not stop.is_set():
        for channel, payload in messages:
            packet = struct.pack(">II", 0x4C433032, sequence) + channel.encode() + b"\0" + payload
            sock.sendto(packet, GROUP)
            sequence += 1
            sent[0] += 1
        stop.wait(0.2)
    sock.close()


def start_server(work, name, extra):
    out = open(os.path.join(work, name + ".out"), "w")
    server = subprocess.Popen([os.environ["SERVER"], "--scene", os.environ["SCENE"], "--lcm-url", URL,
                               "--workspace-scale", "0.001", "--state-hz", "30", "--quiet"] + extra,
                              stdout=out, stderr=subprocess.STDOUT)
    deadline = time.time() + 20
    while time.time() < deadline:
        with open(out.name) as f:
            if "serving" in f.read():
                return server, out.name
        if server.poll() is not None:
            fail("the server did not start: " + open(out.name).read())
        time.sleep(0.05)
    fail("the server did not start in 20 s")


def stop_server(server, log):
    server.terminate()
    server.wait(timeout=30)
    with open(log) as f:
        return f.read()


def run_viewer(work, args, timeout=240):
    environment = dict(os.environ)
    environment.pop("DISPLAY", None)
    done = subprocess.run([os.environ["VIEWER"], "--lcm", URL, "--headless", "--size", "%dx%d" % (WIDTH, HEIGHT),
                           "--fps", "10"] + args, cwd=work, env=environment, stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, timeout=timeout)
    print(done.stdout + done.stderr)
    return done


def remote_summary(stdout):
    match = re.search(r"remote \S+: (\S+) .*?, (\d+) states, (\d+) meshes, (\d+) sessions, (\d+) rejected, "
                      r"(\d+) late, (\d+) commands sent; tool 0 moved ([0-9.]+) m, "
                      r"sent \(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\) m, "
                      r"the server's command \(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\) m", stdout)
    if not match:
        fail("no remote summary line in the viewer's output")
    keys = ("state", "states", "meshes", "sessions", "rejected", "late", "commands", "moved_m")
    values = [match.group(1)] + [int(match.group(i)) for i in range(2, 8)] + [float(match.group(8))]
    summary = dict(zip(keys, values))
    summary["sent_m"] = [float(match.group(i)) for i in range(9, 12)]
    summary["commanded_m"] = [float(match.group(i)) for i in range(12, 15)]
    return summary


def check_bowel(path, what):
    rgb, pink, _, _ = colour_classes(path)
    share = pink.mean()
    # The short bowel is 0.4 m by 2.5 cm in a 0.5 m box: about 0.7 % of a 640 x 360 picture.
    if not 0.002 < share < 0.6:
        fail("%s: the bowel's pink covers %.3f of the picture" % (what, share))
    if rgb[pink].max(axis=1).std() < 0.03:
        fail("%s: the bowel is a flat fill, not a shaded surface" % what)
    return share


def main():
    work = sys.argv[1]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    # 1. The tube around the state's axis (no mesh), a drag, broken messages alongside.
    server, log = start_server(work, "server", [])
    stop, sent = threading.Event(), [0]
    sender = threading.Thread(target=send_hostile, args=(stop, sent))
    sender.start()
    with open(os.path.join(work, "drag.script"), "w") as f:
        f.write("1.5 screenshot before.png\n"
                "1.6 mouse 320 150 down\n"
                "3.2 mouse 320 215 down\n"
                "5.3 mouse 320 215 up\n")
    try:
        # The tool is held on the bowel for two seconds after the drag: a loaded machine
        # (a sanitizer build) runs the server behind the wall clock, and the contact must
        # still come before the capture ends.
        done = run_viewer(work, ["--seconds", "5.5", "--script", "drag.script", "--screenshot", "last.png"])
    finally:
        stop.set()
        sender.join()
    server_out = stop_server(server, log)
    print(server_out)
    if done.returncode != 0:
        fail("the viewer exited with status %d" % done.returncode)
    summary = remote_summary(done.stdout)
    if summary["states"] < 10 or summary["sessions"] < 1:
        fail("too few messages arrived: %s" % summary)
    if summary["rejected"] < len(hostile_messages()):
        fail("the broken messages were not all rejected (%d sent): %s" % (sent[0], summary))
    if summary["commands"] < 50:
        fail("the drag sent too few commands: %s" % summary)
    if summary["moved_m"] < 0.02:
        fail("the server's tool did not follow the drag: %s" % summary)
    # The viewer sends device units (mm: the inverse of the server's workspace mapping); the
    # server maps them back: its command is where the mouse put the target, to the micrometre.
    error_m = max(abs(a - b) for a, b in zip(summary["sent_m"], summary["commanded_m"]))
    if error_m > 2e-6:  # printed to 1 um
        fail("the server's command %s is not the viewer's target %s (the workspace mapping)" %
             (summary["commanded_m"], summary["sent_m"]))
    force = re.search(r"force plot: \d+ samples, (\d+) non-zero, largest \|F\| ([0-9.]+) N", done.stdout)
    # One clear sample proves that the force travels in the states (a quiet machine shows a
    # dozen; a loaded one has seen the bowel slip from under the tool after the first).
    if not force or int(force.group(1)) < 1 or float(force.group(2)) < 0.02:
        fail("the server's states never showed a force on the tool: the drag did not push the bowel")
    accepted = [int(n) for n in re.findall(r"commands (\d+) accepted", server_out)]
    rejected = [int(n) for n in re.findall(r"accepted (\d+) rejected", server_out)]
    if not accepted or accepted[-1] < 50 or rejected[-1] != 0:
        fail("the server did not accept the viewer's commands: accepted %s, rejected %s" % (accepted, rejected))
    share = check_bowel(os.path.join(work, "last.png"), "the tube")
    before_rgb, _, _, _ = colour_classes(os.path.join(work, "before.png"))
    after_rgb, _, _, _ = colour_classes(os.path.join(work, "last.png"))
    changed = (abs(after_rgb - before_rgb).max(axis=2) > 0.1).mean()
    if changed < 0.002:
        fail("the picture did not change while the tool moved (%.4f of the pixels)" % changed)
    print("viewer.remote_lcm: tube: %d states, %d rejected of %d broken messages sent, %d commands sent, "
          "tool moved %.3f m, pink %.3f, changed %.3f; server accepted %d" %
          (summary["states"], summary["rejected"], sent[0], summary["commands"], summary["moved_m"], share, changed,
           accepted[-1]))

    # 2. The server's own mesh; half way, the skin hidden (key K) and the collision spheres
    # shown (key S).
    server, log = start_server(work, "server_mesh", ["--mesh-hz", "5", "--mesh-skin", "convolution"])
    with open(os.path.join(work, "spheres.script"), "w") as f:
        f.write("2.0 screenshot no_spheres.png\n2.1 key K\n2.1 key S\n")
    done = run_viewer(work, ["--seconds", "3", "--script", "spheres.script", "--screenshot", "mesh.png"])
    stop_server(server, log)
    if done.returncode != 0:
        fail("the viewer (mesh) exited with status %d" % done.returncode)
    summary = remote_summary(done.stdout)
    if summary["meshes"] < 1 or summary["commands"] != 0:
        fail("no mesh arrived, or a viewer that only watched sent commands: %s" % summary)
    if "skin convolution" not in done.stdout:
        fail("the picture is not the server's convolution mesh")
    # A viewer that only watches commands nothing: the server says so in the tool's status bits.
    if "tool 0 status: no command" not in done.stdout:
        fail("the server's STATUS_NO_COMMAND for tool 0 is not shown")
    # The spheres (translucent blue, the state's axis resampled at their count) are where
    # the bowel was: its pixels turn blue (without them, the grey floor would show).
    _, pink, _, _ = colour_classes(os.path.join(work, "no_spheres.png"))
    _, _, blue, _ = colour_classes(os.path.join(work, "mesh.png"))
    covered = blue[pink].mean()
    print("viewer.remote_lcm: collision spheres cover %.2f of where the bowel was" % covered)
    if covered < 0.3:
        fail("no collision spheres drawn where the bowel is (%.2f of its pixels blue)" % covered)
    check_bowel(os.path.join(work, "no_spheres.png"), "the server's mesh")

    # 3. Nobody there.
    done = run_viewer(work, ["--seconds", "0.5"])
    if done.returncode != 1 or "no scene_state_t arrived" not in done.stderr:
        fail("a capture with no server: exit status %d" % done.returncode)
    print("viewer.remote_lcm: passed")


if __name__ == "__main__":
    main()
