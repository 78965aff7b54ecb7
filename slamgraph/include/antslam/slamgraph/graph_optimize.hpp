#pragma once
// Every optimizer of optimize.hpp on a pose graph as read from a file (g2o.hpp), with the file's
// vertex estimates as the start and its fixed vertices where the file puts them:
//
//   ceres, ceres-robust  Ceres on the poses of the free vertices, one residual block per edge
//                        oriented from its lower vertex (graph_structure.hpp), the fixed
//                        vertices constant: least squares, or the loss that makes the cost the
//                        eq. (10) weight (ceres_baseline.hpp)
//   nlopt                refine.hpp's NLopt procedure (plain and graduated) on GraphObjective;
//                        box: each position within the vertices' bounding box widened by its
//                        diagonal (at least 1 m), each angle within 2 pi of its start
//   the others           the ants (and random, exhaustive, hybrid+nlopt) choose among samples of
//                        the graph's fragment chain (g2o.hpp: it needs an edge between every two
//                        consecutive vertices, one fixed vertex, and a loop closure); their
//                        frames are moved rigidly so that the fixed vertex keeps its pose
//
// Ceres and NLopt run on any graph whose every vertex is joined to a fixed one by edges
// (several sessions, ids in any order); the fragment chain is built only for the methods that
// need it, and refused with one line where they cannot run. Every result is scored over the
// graph's edges (graph_structure.hpp), the same terms the fragment chain has, so that all
// methods are compared on one objective.

#include <string>
#include <vector>

#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/optimize.hpp"
#include "antslam/slamgraph/trials.hpp"

namespace antslam::slam {

/// Whether a method runs on the fragment chain of a graph (ants, random, exhaustive,
/// hybrid+nlopt) rather than on the graph itself (ceres, ceres-robust, nlopt).
bool needs_fragment_chain(Method m);

/// Runs settings.method on the graph (`source` names it in messages). The result's frames are
/// the vertex poses, its alignments X_i = F_{i-1}^-1 F_i of consecutive vertices, its scores
/// over the graph's edges. settings.initial must be empty (the vertex estimates are the start).
/// Throws std::invalid_argument naming the problem.
OptimizeResult optimize(const PoseGraph& graph, const std::string& source,
                        const OptimizeSettings& settings, const G2oImportSettings& import,
                        const OptimizeObserver& observer = {});

/// Trials of settings.method on the graph as run_trials does for a fragment set; the chain
/// methods share one fragment set (samples seeded by import.seed).
std::vector<OptimizeResult> run_trials(const PoseGraph& graph, const std::string& source,
                                       const OptimizeSettings& settings,
                                       const G2oImportSettings& import, const TrialSettings& trials,
                                       const TrialsObserver& observer = {},
                                       const OptimizeObserver& convergence = {});

}  // namespace antslam::slam
