"""Long calls release the GIL, and Ctrl-C (SIGINT) ends them cleanly with KeyboardInterrupt
within a fraction of a second, whatever runs: the TSP colony, trials of the SLAM optimizer on
threads, a layered problem with a Python term. An observer's exception ends a run the same way."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import antslam
from conftest import DATA

LONG_RUNS = {
    "tsp": "antslam.tsp.solve(antslam.tsp.read(DATA + '/tsplib/pr1002.tsp'), iterations=0, "
           "time_limit=120, threads=2)",
    "slam": "antslam.slam.study(antslam.slam.synth('paper24'), method='hybrid+nlopt', trials=40, "
            "threads=2, iterations=10**6)",
    "layered": "antslam.aco.solve(np.ones((30, 8)), term=lambda c: float(c.sum()), "
               "iterations=10**7, threads=2)",
}


@pytest.mark.parametrize("what", sorted(LONG_RUNS))
def test_ctrl_c_ends_a_long_run(what):
    script = textwrap.dedent(f"""
        import sys, time
        import numpy as np
        import antslam
        DATA = {str(DATA)!r}
        print("started", flush=True)
        start = time.monotonic()
        try:
            {LONG_RUNS[what]}
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sys.exit(3)
        print("finished", flush=True)
        """)
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                             env=dict(os.environ), preexec_fn=lambda: signal.signal(
                                 signal.SIGINT, signal.SIG_DFL))
    assert child.stdout.readline().strip() == "started"
    time.sleep(1.0)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=60)
    assert (child.returncode, out.strip()) == (3, "interrupted")
    assert time.monotonic() - sent < 10.0  # in practice 0.1 s; generous for sanitizer builds


def test_an_observers_exception_ends_the_run():
    instance = antslam.tsp.read(DATA / "tsplib" / "pr1002.tsp")
    calls = []

    def observer(info):
        calls.append(info.iteration)
        if info.iteration == 3:
            raise RuntimeError("enough")
    with pytest.raises(RuntimeError, match="^enough$"):
        antslam.tsp.solve(instance, iterations=10**6, local_search="none", observer=observer)
    assert calls == [1, 2, 3]


def test_an_interrupt_keeps_the_run_so_far():
    instance = antslam.tsp.read(DATA / "tsplib" / "pr1002.tsp")

    def observer(info):
        if info.iteration == 3:
            raise KeyboardInterrupt
    with pytest.raises(antslam.Interrupted) as stopped:
        antslam.tsp.solve(instance, iterations=10**6, local_search="none", observer=observer)
    assert isinstance(stopped.value, KeyboardInterrupt)
    kept = stopped.value.result
    assert isinstance(kept, antslam.tsp.Result)
    assert (kept.iterations, kept.stop_reason) == (3, "interrupted")
    whole = antslam.tsp.solve(instance, iterations=3, local_search="none")
    assert kept.length == whole.length == instance.tour_length(kept.tour)


def test_an_interrupted_study_keeps_its_first_finished_trials():
    fragments = antslam.slam.synth("paper9")
    whole = antslam.slam.study(fragments, trials=6, iterations=30, seed=4)

    def progress(finished):
        if finished == 2:
            raise KeyboardInterrupt
    with pytest.raises(antslam.Interrupted) as stopped:
        antslam.slam.study(fragments, trials=6, iterations=30, seed=4, progress=progress)
    kept = stopped.value.result
    assert isinstance(kept, antslam.slam.Study)
    assert 2 <= len(kept.results) < 6
    for mine, theirs in zip(kept.results, whole.results):
        assert mine.weight == theirs.weight


def test_an_interrupted_layered_run_keeps_its_best():
    def observer(info):
        if info.iteration == 2:
            raise KeyboardInterrupt
    with pytest.raises(antslam.Interrupted) as stopped:
        antslam.aco.solve(np.ones((30, 8)), iterations=10**6, observer=observer)
    assert isinstance(stopped.value.result, antslam.aco.Result)
    assert stopped.value.result.iterations == 2


def test_ctrl_c_keeps_the_clique_found_so_far():
    rng = np.random.default_rng(1)
    n = 400
    edges = [(i, j) for i in range(n) for j in range(i + 1, n) if rng.random() < 0.5]
    graph = antslam.clique.Graph(n, edges)
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(antslam.Interrupted) as stopped:
        antslam.clique.aco(graph, iterations=10**9, stagnation=0, time_limit=0)
    timer.join()
    kept = stopped.value.result
    assert isinstance(kept, antslam.clique.AcoResult)
    assert kept.stop_reason == "interrupted"
    members = set(kept.vertices.tolist())
    assert len(members) >= 2
    assert all((min(a, b), max(a, b)) in set(edges) for a in members for b in members if a != b)


def test_the_gil_is_released_while_the_ants_run():
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)
    counter = threading.Thread(target=count)
    counter.start()
    before = len(ticks)
    antslam.aco.solve(np.random.default_rng(0).random((60, 20)), iterations=0, time_limit=0.5)
    during = len(ticks) - before
    stop.set()
    counter.join()
    assert during > 20  # the counter ran while the colony did (about 0.5 s / 1 ms)
