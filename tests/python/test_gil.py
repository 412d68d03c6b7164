"""The GIL is released during a fit: Python code in another thread goes on while the fit runs.

Not a timing assertion of speed: if the fit held the GIL, the counting thread would stand still for the whole fit
(one pause as long as the fit's C++ call: measured 0.74 s of a 0.76 s fit of 9 materials with the release taken
out); released, it counts all along and its longest pause is the interpreter's switch interval (5 ms) or the
scheduler's.
"""
import threading
import time

import metalfit

# About 1 s with every model on one thread, so that the bound below (a quarter of it) is far above a loaded
# machine's scheduling pauses and far below the pause a held GIL makes.
MATERIALS = ["Au", "Cu", "Ag", "Al", "Fe", "Ni", "Ti", "Cr", "Pt", "Pd", "W", "Zn", "Co", "Mo", "Rh", "Ir"]


def test_python_runs_during_a_fit():
    state = {"counter": 0}
    counting = threading.Event()

    def fit():
        counting.wait()  # the main thread is counting before the fit starts
        before = state["counter"]
        begin = time.monotonic()
        state["record"] = metalfit.fit(MATERIALS, models="all", jobs=1)
        state["seconds"] = time.monotonic() - begin
        state["counted_during_fit"] = state["counter"] - before

    worker = threading.Thread(target=fit)
    worker.start()
    longest_pause = 0.0
    last = time.monotonic()
    counting.set()
    while worker.is_alive():
        state["counter"] += 1
        now = time.monotonic()
        longest_pause = max(longest_pause, now - last)
        last = now
    longest_pause = max(longest_pause, time.monotonic() - last)  # a pause that lasted until the fit ended
    worker.join()
    assert set(state["record"]["materials"]) == set(MATERIALS)
    assert state["counted_during_fit"] > 0, state
    assert longest_pause < 0.25 * state["seconds"], (longest_pause, state["seconds"], state["counted_during_fit"])
