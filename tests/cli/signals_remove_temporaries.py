#!/usr/bin/env python3
"""signals_remove_temporaries.py <candela> <folder>

A render is sent SIGHUP, SIGPIPE, SIGQUIT, SIGXFSZ or SIGXCPU while it writes a large output: it ends by that
signal and leaves neither the output nor a temporary file beside it. With SIGHUP ignored (as under nohup) the same signal changes
nothing: the render goes on and writes its output.
"""
import os
import resource
import signal
import subprocess
import sys
import time


def render_signalled(candela, folder, sig, ignored=False):
    """Starts a render of a large .exr in `folder`, sends `sig` as soon as its temporary output exists, and
    returns its exit status (negative: the signal that ended it)."""
    for name in os.listdir(folder):
        os.remove(os.path.join(folder, name))
    args = [candela, "render", "--backend", "cpu", "--spp", "1", "--max-depth", "1", "--width", "1024",
            "--height", "1024", "--aov", "albedo,normal,depth", "-o", os.path.join(folder, "big.exr")]

    def prepare():
        # The default action of SIGQUIT, SIGXFSZ and SIGXCPU dumps core.
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        if ignored:
            signal.signal(sig, signal.SIG_IGN)

    child = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, preexec_fn=prepare)
    deadline = time.monotonic() + 120
    sent = False
    while child.poll() is None and time.monotonic() < deadline:
        if not sent and any(".tmp-" in name for name in os.listdir(folder)):
            child.send_signal(sig)
            sent = True
        time.sleep(0.001)
    if child.poll() is None:
        child.kill()
    return child.wait(), sent


def main():
    candela, folder = sys.argv[1], os.path.join(sys.argv[2], "signals-remove-temporaries")
    os.makedirs(folder, exist_ok=True)
    failures = []
    for sig in (signal.SIGHUP, signal.SIGPIPE, signal.SIGQUIT, signal.SIGXFSZ, signal.SIGXCPU):
        status, sent = render_signalled(candela, folder, sig)
        left = sorted(os.listdir(folder))
        print(f"{sig.name}: exit status {status}, files left {left}")
        if not sent:
            failures.append(f"{sig.name}: the render ended before its temporary output was seen")
        elif status != -sig or left:
            failures.append(f"{sig.name}: expected the render ended by it and no file left, got {status} and {left}")
    status, sent = render_signalled(candela, folder, signal.SIGHUP, ignored=True)
    left = sorted(os.listdir(folder))
    print(f"ignored SIGHUP: exit status {status}, files {left}")
    if not sent or status != 0 or any(".tmp-" in name for name in left) or "big.exr" not in left:
        failures.append(f"ignored SIGHUP: expected the render to finish its output, got {status} and {left}")
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
