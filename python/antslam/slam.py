"""AntSLAM fragment sets and pose graphs, and every optimizer of `antslam optimize` on them.

    s = antslam.slam.synth("paper15", seed=1)            # or load("set.json"), from_g2o(...)
    r = antslam.slam.optimize(s, method="mmas", iterations=500, seed=1)
    r.weight, r.chi2, r.frames                           # frames: (N, 3) world poses

    g = antslam.slam.read_graph("data/posegraphs/intel.g2o")   # g2o or TORO, FIX lines kept
    r = antslam.slam.optimize(g, method="ceres")         # r.frames: the vertex poses

    spoiled, false = antslam.slam.add_outliers(g, 1000, kind="random", seed=1)
    r = antslam.slam.robust(spoiled, "pcm-aco")          # r.accepted: per loop closure
    c = antslam.slam.consistency(spoiled)                # c.graph: PCM's consistency graph

Methods: as, eas, ras, acs, mmas, hybrid, hybrid+nlopt, nlopt, ceres, ceres-robust, random,
exhaustive. On a pose graph ceres, ceres-robust and nlopt run on the graph itself (from its
vertex poses, fixed vertices held); the others on its fragment chain (docs/slamgraph.md).
"""
import os
from dataclasses import dataclass

import numpy as np

from . import _core, _options

FragmentSet = _core.slam.FragmentSet
PoseGraph = _core.slam.PoseGraph
Result = _core.slam.Result
ConvergencePoint = _core.slam.ConvergencePoint
METHODS = tuple(name.strip() for name in _core.slam.method_names().split(","))

# Every option of `antslam optimize`, by its name here, and the settings attribute it sets.
_OPTIMIZER = dict(
    {name: "aco." + attribute for name, attribute in _options.ENGINE.items()
     if name != "ls_ants"},
    method="method", seed="seed", iterations="iterations", time_limit="time_limit_s",
    backend="backend", hybrid_deposit="aco.hybrid_deposit",
    nlopt_algorithm="refine.algorithm", bound_sigmas="refine.bound_sigmas",
    max_evaluations="refine.max_evaluations", relative_tolerance="refine.relative_tolerance",
    refine_time_limit="refine.time_limit_s", lbfgs_memory="refine.lbfgs_memory",
    graduated="refine.graduated", graduation_factor="refine.graduation_factor",
    refine_each="refine_each_improvement", ceres_iterations="ceres.max_iterations",
    ceres_tolerance="ceres.function_tolerance", ceres_time_limit="ceres.time_limit_s",
    max_paths="max_exhaustive_paths", initial="initial")

_SYNTH = {name: name for name in (
    "fragments", "samples", "loop_length_m", "aspect", "laps", "sigma_xy", "sigma_theta",
    "correlation", "closure_sigma_xy", "closure_sigma_theta", "revisit_radius_m",
    "noise_free", "trajectory_poses", "seed")}


def load(path):
    """Reads a fragment-set JSON (docs/fragment-set-format.md)."""
    return _core.slam.load(os.fspath(path))


def synth(preset=None, **settings):
    """A synthetic fragment set with ground truth (`reference`): a preset (paper9, paper15,
    paper24), with any setting of slamgraph/synth.hpp overriding it (fragments, samples,
    loop_length_m, aspect, laps, sigma_xy, sigma_theta, correlation, closure_sigma_xy,
    closure_sigma_theta, revisit_radius_m, noise_free, trajectory_poses, seed)."""
    s = _core.slam.synth_preset(preset) if preset else _core.slam.SynthSettings()
    _options.apply(s, _SYNTH, settings, "synth")
    return _core.slam.synthesize(s)


def read_graph(path):
    """Reads a 2D pose graph: g2o (VERTEX_SE2, EDGE_SE2, FIX) or TORO (VERTEX2, EDGE2) lines;
    a file without vertices gets poses composed along its edges."""
    return _core.slam.read_graph(os.fspath(path))


def from_g2o(graph, samples=20, seed=1):
    """The fragment set of a pose graph (a PoseGraph or a file): vertex i is fragment i, the
    edges between consecutive vertices its alignments with `samples` samples each."""
    if not isinstance(graph, PoseGraph):
        graph = read_graph(graph)
    return graph.fragment_set(samples, seed)


def optimizer_settings(method="hybrid", **options):
    """The settings object of `antslam optimize` with the given options (see optimize)."""
    s = _core.slam.OptimizeSettings()
    _options.apply(s, _OPTIMIZER, dict(options, method=method), "optimize")
    return s


def _run(subject, trials, threads, samples, observer, progress, settings):
    if isinstance(subject, PoseGraph):
        return _core.slam.optimize_graph(subject, settings, samples, trials, threads, observer,
                                         progress)
    if isinstance(subject, FragmentSet):
        return _core.slam.optimize_set(subject, settings, trials, threads, observer, progress)
    raise TypeError(f"optimize(): expected a FragmentSet or a PoseGraph, got "
                    f"{type(subject).__name__}")


def optimize(subject, method="hybrid", *, threads=1, samples=20, observer=None, **options):
    """One run of `method` on a FragmentSet or a PoseGraph: what `antslam optimize` does with
    --trials 1 (the run is seeded with trial_seed(seed, 0), so the same seed gives the same
    result as the program). threads: the ants' threads; samples: per alignment of a pose graph's
    fragment chain. observer(point) hears every improvement (a ConvergencePoint).

    Options (defaults as the program's): seed, iterations, time_limit, backend, ants, rho,
    alpha, beta, p0, q0, xi, elite_weight, rank_width, p_best, restarts, glob_best_freq,
    tau_max, tau_init, hybrid_deposit, nlopt_algorithm (lbfgs, slsqp, bobyqa), bound_sigmas,
    max_evaluations, relative_tolerance, refine_time_limit, lbfgs_memory, graduated,
    graduation_factor, refine_each, ceres_iterations, ceres_tolerance, ceres_time_limit,
    max_paths, initial ((N - 1, 3) alignments: the start of nlopt and ceres on a set)."""
    settings = optimizer_settings(method, **options)
    try:
        return _run(subject, 1, threads, samples, observer, None, settings)[0]
    except _core.Interrupted as stopped:
        stopped.result = stopped.result[0] if stopped.result else None
        raise


@dataclass(frozen=True)
class Study:
    """Independent trials of one method (what `antslam optimize --trials T` summarizes)."""
    results: list          #: every trial's Result, in trial order
    summary: object        #: statistics of weight, chi2 and time over the trials

    @property
    def best_trial(self):
        return self.summary.best_trial

    @property
    def best(self):
        return self.results[self.summary.best_trial]

    @property
    def weight(self):
        return self.summary.weight

    @property
    def chi2(self):
        return self.summary.chi2


def study(subject, method="hybrid", trials=20, *, threads=1, samples=20, progress=None,
          **options):
    """`trials` independent trials (trial t seeded with trial_seed(seed, t)), spread over
    `threads`; the results do not depend on the threads. progress(finished) is called after
    each trial. Options as in optimize."""
    settings = optimizer_settings(method, **options)
    try:
        results = _run(subject, trials, threads, samples, None, progress, settings)
    except _core.Interrupted as stopped:  # trials 0 to k - 1, as in the whole study
        stopped.result = (Study(stopped.result, _core.slam.summarize(
            subject.name, settings, stopped.result)) if stopped.result else None)
        raise
    return Study(results, _core.slam.summarize(subject.name, settings, results))


chain = _core.slam.chain
relative_alignments = _core.slam.relative_alignments
read_reference_poses = _core.slam.read_reference_poses
graph_of_set = _core.slam.graph_of_set
trial_seed = _core.slam.trial_seed


# False loop closures and the robust back ends (`antslam outliers`, `antslam robust`).
RobustResult = _core.slam.RobustResult
ROBUST_METHODS = tuple(name.strip() for name in _core.slam.robust_method_names().split(","))
_OUTLIERS = {"group_size": "group_size", "local_window": "local_window"}
_ROBUST = dict(
    {name: "aco.parameters." + attribute for name, attribute in _options.ENGINE.items()},
    confidence="inlier_confidence", cauchy_scale="cauchy_scale", dcs_phi="dcs_phi",
    shown_noise="shown_noise", check_clique="check_clique", check_phi="check_phi", recalibrate_below="recalibrate_below",
    widen_noise="widen_noise",
    prune_from="prune_from", exact_time_limit="exact_time_limit_s",
    iterations="aco.termination.max_iterations", plateau_steps="aco.plateau_steps",
    proof_nodes="aco.proof_nodes",
    backend="backend", threads="threads")


def add_outliers(graph, count, kind="random", seed=1, **options):
    """The graph with `count` false loop closures appended after its own edges (kind: random,
    local, random-group, local-group; options group_size, local_window), as `antslam outliers`
    writes it: (spoiled PoseGraph, (count, 2) array of the false closures' vertex pairs)."""
    settings = _core.slam.OutlierSettings()
    settings.count, settings.kind, settings.seed = count, kind, seed
    _options.apply(settings, _OUTLIERS, options, "add_outliers")
    return _core.slam.add_outliers(graph, settings)


@dataclass(frozen=True)
class Consistency:
    """The pairwise consistency of a graph's loop closures (PCM, Mangelson et al. 2018), as
    `antslam robust --method pcm-*` tests it before its clique."""
    graph: object  #: antslam.clique graph: vertex k is closure k, an edge a consistent pair
    closures: np.ndarray  #: (m, 2) vertex pairs of the loop closures, in input order
    odometry_consistent: np.ndarray  #: m booleans: closure k agrees with the odometry between
    #: its ends (a closure that does not has no consistent pair)
    threshold: float  #: chi-square (3 dof) bound on a cycle's squared Mahalanobis distance


def consistency(graph, confidence=0.99, *, threads=1, backend="auto"):
    """The consistency graph of the graph's loop closures (slamgraph/consistency.hpp): its
    maximum clique (antslam.clique.aco or exact, with their defaults) is the one `antslam robust
    --method pcm-aco / pcm-exact --confidence C` starts from."""
    return Consistency(*_core.slam.consistency(graph, confidence, threads, backend))


def robust(graph, method="pcm-aco", *, variant=None, seed=1, **options):
    """Decides which loop closures of the graph to trust and optimises it, as `antslam robust`
    does (method: ls, cauchy, dcs, gnc, pcm-exact, pcm-aco; docs/robust-closures.md). Options
    as the program's: confidence, cauchy_scale, dcs_phi, shown_noise (True: decide at the noise
    the graph's short cycles show; result.noise_scale), check_clique (False: the published
    PCM), check_phi (the check's DCS Phi in multiples of the clique's median unary distance; 0:
    dcs_phi), recalibrate_below (the recalibrated check runs when the checked graph's variance
    factor is below it; 0: never), widen_noise (True: an axis stated over 1.25 times narrower
    than the graph's short cycles show is decided at the noise they show; result.widened), prune_from (closures from which the clique search sees only
    what the pruning leaves), exact_time_limit (s), and for pcm-aco
    variant, seed, iterations, plateau_steps, proof_nodes and the engine's parameters (ants,
    rho, ...); backend, threads. The result: poses (n, 3), closures ((m, 2) vertex pairs of the
    loop closures, in input order), accepted (m booleans), clique, check_phi (the Phi the check
    used), variance_factor (the checked graph's) and core (the recalibrated check's clique, None
    where it did not run) (PCM methods), times;
    kept_graph(graph) is the graph `antslam robust` writes."""
    settings = _core.slam.RobustSettings()
    if variant is not None:
        settings.aco.parameters.variant = variant
    settings.aco.parameters.seed = seed
    _options.apply(settings, _ROBUST, options, "robust")
    return _core.slam.solve_robust(graph, method, settings)
