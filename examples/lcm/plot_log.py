#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Plots a recorded LCM session of Enteron: the force a device was sent, and the latency.

    lcm-logger session.lcmlog          (while enteron-lcm-server and a device run)
    plot_log.py session.lcmlog --out session.png [--tool N] [--suffix S]

Decodes the log with the Python types lcm-gen makes from bindings/lcm (enteron_lcm, built
in <build>/bindings/lcm/generated/python, installed with the library; --types DIR points
elsewhere). Two panels, over the logger's clock:
  - the force sent to the device (tool_feedback_t.force_N, device frame): x, y, z, |F|;
  - the latency: each command's wait in the server's mailbox (command_age_us, measured
    by the server), and the logger's view of the round trip: from when it received a
    command to when it received the first feedback that applied it (both on the logger's
    clock; it excludes the device's own network legs).
Prints a one-line summary (also a test's pass condition, tests/lcm). Needs python3-matplotlib.
"""

import argparse
import os
import sys


def import_types(types_dir):
    """Imports enteron_lcm.log, from types_dir or the build tree next to this source tree."""
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [types_dir] if types_dir else [None, os.path.join(here, "..", "..", "build", "bindings", "lcm",
                                                                    "generated", "python")]
    for candidate in candidates:
        if candidate:
            sys.path.insert(0, candidate)
        try:
            from enteron_lcm import log  # noqa: E402 (found on the path just set)
            return log
        except ImportError:
            if candidate:
                sys.path.remove(candidate)
    sys.exit("plot_log.py: cannot import enteron_lcm (the generated Python types): pass --types DIR")


def percentile(values, fraction):
    ordered = sorted(values)
    return ordered[int(fraction * (len(ordered) - 1))] if ordered else float("nan")


def main():
    parser = argparse.ArgumentParser(description="Plot the force and the latency of a recorded Enteron LCM session.")
    parser.add_argument("log", help="an LCM log file (lcm-logger)")
    parser.add_argument("--out", default="lcm_session.png", help="the PNG to write (default lcm_session.png)")
    parser.add_argument("--tool", type=int, default=0, help="the tool to plot (default 0)")
    parser.add_argument("--suffix", default="", help="the server's --channel-suffix")
    parser.add_argument("--types", help="the directory holding the package enteron_lcm")
    arguments = parser.parse_args()
    log = import_types(arguments.types)

    command_channel = "ENTERON_TOOL_COMMAND" + arguments.suffix
    feedback_channel = "ENTERON_TOOL_FEEDBACK" + arguments.suffix
    commands = {}  # seq -> the logger's timestamp of the command
    time_s, force, age_us, round_trip = [], [], [], []  # round_trip: (time s, us)
    last_tick, missed, echoed = None, 0, set()
    start = None
    try:
        for event, message in log.messages(arguments.log, channels={command_channel, feedback_channel}):
            if start is None:
                start = event.timestamp_us
            if event.channel == command_channel and isinstance(message, log.tool_command_t):
                if message.tool == arguments.tool:
                    commands.setdefault(message.seq, event.timestamp_us)
                continue
            if not isinstance(message, log.tool_feedback_t) or message.tool != arguments.tool:
                continue
            t = 1e-6 * (event.timestamp_us - start)
            time_s.append(t)
            force.append(message.force_N)
            if last_tick is not None and message.tick > last_tick + 1:
                missed += message.tick - last_tick - 1
            last_tick = message.tick if last_tick is None else max(last_tick, message.tick)
            if message.command_seq >= 0 and message.command_seq not in echoed:
                echoed.add(message.command_seq)
                age_us.append((t, message.command_age_us))
                if message.command_seq in commands:
                    round_trip.append((t, event.timestamp_us - commands[message.command_seq]))
    except (log.LogError, ValueError) as error:
        sys.exit("plot_log.py: %s" % error)
    if not time_s:
        sys.exit("plot_log.py: no tool_feedback_t of tool %d on %s in %s" % (arguments.tool, feedback_channel,
                                                                           arguments.log))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    magnitude = [(x * x + y * y + z * z) ** 0.5 for x, y, z in force]
    figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(10, 7))
    for axis, label in enumerate("xyz"):
        top.plot(time_s, [f[axis] for f in force], linewidth=0.8, label="F" + label)
    top.plot(time_s, magnitude, color="black", linewidth=1.2, label="|F|")
    top.set_ylabel("force sent to the device (N, device frame)")
    top.legend(loc="upper right")
    top.grid(alpha=0.3)
    if age_us:
        bottom.plot([a[0] for a in age_us], [a[1] for a in age_us], ".", markersize=2,
                    label="wait for the tick (command_age_us)")
    if round_trip:
        bottom.plot([r[0] for r in round_trip], [r[1] for r in round_trip], ".", markersize=2,
                    label="command to its feedback, seen by the logger")
    bottom.set_yscale("log")
    bottom.set_ylabel("latency (us)")
    bottom.set_xlabel("time (s, logger's clock)")
    bottom.legend(loc="upper right")
    bottom.grid(alpha=0.3, which="both")
    figure.suptitle("%s: tool %d, %d feedback ticks, %d missed" % (os.path.basename(arguments.log), arguments.tool,
                                                                  len(time_s), missed))
    figure.tight_layout()
    figure.savefig(arguments.out, dpi=110)
    ages = [a[1] for a in age_us]
    trips = [r[1] for r in round_trip]
    print("plot_log.py: %d feedback ticks of tool %d (%d missed), largest |F| %.3f N, wait for the tick median %.0f us, "
          "logger's round trip median %.0f us p99 %.0f us; wrote %s"
          % (len(time_s), arguments.tool, missed, max(magnitude), percentile(ages, 0.5), percentile(trips, 0.5),
             percentile(trips, 0.99), arguments.out))


if __name__ == "__main__":
    main()
