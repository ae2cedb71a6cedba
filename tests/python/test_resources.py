"""No reference or memory leaks over 10^5 calls, and the GIL released while C++ works:
four threads evaluating at once give what one gives."""
import gc
import sys
import threading
import tracemalloc

import numpy as np
import pytest

import pita

CALLS = 100_000


# A leak of one small object per call would hold megabytes after 10^5 calls; what
# stays below this is the interpreter's own caches.
LIMIT = 64 * 1024


def grown(call, calls=CALLS):
    """Bytes Python holds after `calls` calls of `call`, beyond what it held after the first 1000."""
    for _ in range(1000):
        call()
    gc.collect()
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    for _ in range(calls):
        call()
    gc.collect()
    after = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    return after - before


def test_no_leak_in_scalar_calls(figure_one):
    arrows, knots = figure_one
    motion = pita.motion("P6", arrows, knots)
    t = 0.3
    refs = sys.getrefcount(motion), sys.getrefcount(t)
    assert grown(lambda: motion(t)) < LIMIT
    assert (sys.getrefcount(motion), sys.getrefcount(t)) == refs


def test_no_leak_in_array_calls_and_errors(figure_one):
    arrows, knots = figure_one
    motion = pita.motion("P6", arrows, knots)
    times = np.linspace(0, 1, 8)
    refs = sys.getrefcount(times)
    assert grown(lambda: motion(times)) < LIMIT
    assert grown(lambda: pita.ear_power([[0, -1, 1], [1, 0, 0]], times), CALLS // 2) < LIMIT
    assert grown(lambda: pita.sma(arrows[0], arrows[1], times), CALLS // 2) < LIMIT
    assert sys.getrefcount(times) == refs
    # one matrix at one time: ear_power's small path (a list, an array)
    listed, array = [[0, -1, 1], [1, 0, 0]], np.array([[0.0, -1, 1], [1, 0, 0], [0, 0, 1]])
    refs = sys.getrefcount(listed), sys.getrefcount(listed[0]), sys.getrefcount(array)
    assert grown(lambda: pita.ear_power(listed, 0.5)) < LIMIT
    assert grown(lambda: pita.ear_power(array, 0.5)) < LIMIT
    assert (sys.getrefcount(listed), sys.getrefcount(listed[0]), sys.getrefcount(array)) == refs

    def refused():
        try:
            pita.ear_power([[-1, 0, 0], [0, -2, 0]], 0.5)
        except pita.NoSamError:
            pass
    assert grown(refused, CALLS // 10) < LIMIT


def test_four_threads_give_what_one_gives(figure_one):
    arrows, knots = figure_one
    motion = pita.motion("P9", arrows, knots)
    times = np.linspace(-0.5, 1.5, 200_000)
    alone = motion(times)
    results = [None] * 4

    def work(i):
        results[i] = motion(times)
    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for result in results:
        for ours, theirs in zip(result, alone):
            np.testing.assert_array_equal(ours, theirs)


def test_the_gil_is_released_while_evaluating(figure_one):
    """With a switch interval far longer than the call, another Python thread can run
    during the call only if the call releases the GIL."""
    arrows, knots = figure_one
    motion = pita.motion("P6", arrows, knots)
    times = np.linspace(0, 1, 2_000_000)
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1
            if counter[0] % 100 == 0:
                stop.wait(0.0001)   # gives the GIL back now and then
    previous = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    thread = threading.Thread(target=count)
    try:
        thread.start()
        stop.wait(0.01)
        before = counter[0]
        motion(times)
        during = counter[0] - before
    finally:
        stop.set()
        thread.join()
        sys.setswitchinterval(previous)
    assert during > 0
