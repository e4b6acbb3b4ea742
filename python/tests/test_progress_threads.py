#!/usr/bin/env python3
"""Progress, Ctrl-C and the GIL (issue 53 item 4): the callback sees increasing percents, a
KeyboardInterrupt from it or a SIGINT stops the run cleanly, other threads run meanwhile."""
import os
import signal
import threading
import time
import warnings

import fcvt
from common import BUNNY, check, main

warnings.simplefilter("ignore", UserWarning)
V, F = fcvt.read(BUNNY)


def test_progress_increasing():
    calls = []
    r = fcvt.remesh(V, F, vertices=1000, progress=lambda stage, percent: calls.append((stage, percent)))
    percents = [p for _, p in calls]
    check(len(calls) >= 10, f"only {len(calls)} calls")
    check(all(isinstance(s, str) and isinstance(p, int) for s, p in calls), "stage str, percent int")
    check(percents == sorted(percents), f"percent decreases: {percents}")
    check(percents[0] <= 5 and percents[-1] == 100 and calls[-1][0] == "done", f"first/last: {calls[0]}, {calls[-1]}")
    check({"field", "cvt", "fcvt", "valence"} <= {s.split()[0] for s, _ in calls}, "stages named")
    check(len(r.vertices) > 900, "the run completed")


def test_keyboard_interrupt_from_callback():
    seen = []

    def stop(stage, percent):
        seen.append(percent)
        if stage.startswith("cvt"):
            raise KeyboardInterrupt

    try:
        fcvt.remesh(V, F, vertices=2000, progress=stop)
        raise AssertionError("no KeyboardInterrupt")
    except KeyboardInterrupt:
        pass
    check(seen[-1] < 100, "stopped before the end")
    # Another exception from the callback comes through as itself, and the module still works.
    try:
        fcvt.remesh(V, F, vertices=500, progress=lambda s, p: 1 / 0)
        raise AssertionError("no ZeroDivisionError")
    except ZeroDivisionError:
        pass
    check(len(fcvt.remesh(V, F, vertices=300).vertices) > 250, "a run after the interrupts")


def test_sigint_during_run():
    timer = threading.Timer(0.7, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        fcvt.remesh(V, F, vertices=20000)  # several seconds
        raise AssertionError("no KeyboardInterrupt")
    except KeyboardInterrupt:
        pass
    finally:
        timer.cancel()
    elapsed = time.monotonic() - start
    check(elapsed < 10, f"stopped only after {elapsed:.1f} s")


def test_gil_released():
    count = [0]
    stop = threading.Event()

    def spin():
        while not stop.is_set():
            count[0] += 1

    thread = threading.Thread(target=spin)
    thread.start()
    time.sleep(0.05)
    try:
        before = count[0]
        start = time.monotonic()
        fcvt.remesh(V, F, vertices=3000, threads=1)
        during = count[0] - before
        seconds = time.monotonic() - start
    finally:
        stop.set()
        thread.join()
    # A spinning Python thread counts millions per second; with the GIL held by the run it would
    # count only between the progress calls.
    rate = during / seconds
    check(rate > 100000, f"the other thread counted {during} in {seconds:.2f} s ({rate:.0f}/s)")


if __name__ == "__main__":
    main([test_progress_increasing, test_keyboard_interrupt_from_callback, test_sigint_during_run, test_gil_released])
