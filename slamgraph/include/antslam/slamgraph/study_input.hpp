#pragma once
// What an optimisation study (`antslam optimize`, trials of one method) runs on: a fragment set,
// or a pose graph read as it is (the least-squares methods run on its vertices, the others on
// its fragment chain), with the reference poses of its frames if any.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/optimize.hpp"
#include "antslam/slamgraph/trials.hpp"

namespace antslam::slam {

struct StudyInput {
  std::string source;              ///< the file it was read from (named in messages)
  std::optional<FragmentSet> set;  ///< a fragment set ...
  std::optional<PoseGraph> graph;  ///< ... or a pose graph
  std::vector<Pose2> reference;    ///< per fragment or vertex; empty if none

  /// Fragments or vertices.
  std::size_t poses() const;
  /// "N = 15, 2 closures" or "N = 808 vertices, 827 edges".
  std::string size_text() const;
  /// The map of the given frames as a pose graph: the graph's own edges, or the set's.
  PoseGraph map_graph(std::span<const Pose2> frames) const;
  /// The trajectory of the given frames: the set's world trajectory, or one pose per vertex.
  Trajectory trajectory(std::span<const Pose2> frames) const;
};

/// Reads a pose graph (is_pose_graph_file) or a fragment-set JSON, without a reference.
StudyInput read_study_input(const std::filesystem::path& path);

/// Sets input.reference from `path` (.g2o, .graph, .tum or `x y theta` lines; empty: the
/// fragment set's own ground truth, if it has one).
void read_study_reference(StudyInput& input, const std::filesystem::path& path);

/// The trials of settings.method on the input (run_trials of its set or its graph; `import`
/// makes a graph's fragment chain).
std::vector<OptimizeResult> run_trials(const StudyInput& input, const OptimizeSettings& settings,
                                       const G2oImportSettings& import, const TrialSettings& trials,
                                       const TrialsObserver& observer = {},
                                       const OptimizeObserver& convergence = {});

}  // namespace antslam::slam
