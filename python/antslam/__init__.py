"""antslam from Python: the ant colony engine, the TSP, AntSLAM fragment sets and pose graphs,
the mapping pipeline, trajectory evaluation and maximum cliques, with numpy arrays in and out.

    import antslam
    instance = antslam.tsp.read("data/tsplib/eil51.tsp")
    result = antslam.tsp.solve(instance, variant="mmas", iterations=200, seed=3)
    print(result.length, result.tour[:5])

Long calls release the GIL; Ctrl-C stops them cleanly with antslam.Interrupted, a
KeyboardInterrupt whose `result` is what the run had found (the call's own result type); errors are
ValueError or RuntimeError with the same one-line message as the antslam program. A seed gives
the same result as the program with the same options. docs/python.md has a worked example.
"""
from . import _core
from . import aco, clique, eval, mapping, slam, tsp

Interrupted = _core.Interrupted
__version__ = _core.__version__
__all__ = ["Interrupted", "aco", "clique", "eval", "mapping", "slam", "tsp"]
