#include "antslam/slamgraph/study_input.hpp"

#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/graph_optimize.hpp"

namespace antslam::slam {

std::size_t StudyInput::poses() const {
  return graph ? graph->vertices.size() : set->fragments.size();
}

std::string StudyInput::size_text() const {
  if (graph)
    return "N = " + std::to_string(graph->vertices.size()) + " vertices, " +
           std::to_string(graph->edges.size()) + " edges" +
           (graph->vertices_from_file ? "" : ", poses composed along the edges");
  return "N = " + std::to_string(set->fragments.size()) + ", " +
         std::to_string(set->closures.size()) +
         (set->closures.size() == 1 ? " closure" : " closures");
}

PoseGraph StudyInput::map_graph(std::span<const Pose2> frames) const {
  if (!graph) return pose_graph_of(*set, frames);
  PoseGraph map = *graph;
  map.vertices.assign(frames.begin(), frames.end());
  return map;
}

Trajectory StudyInput::trajectory(std::span<const Pose2> frames) const {
  if (set) return world_trajectory(*set, frames);
  Trajectory t;
  for (std::size_t i = 0; i < frames.size(); ++i) t.push_back({static_cast<double>(i), frames[i]});
  return t;
}

StudyInput read_study_input(const std::filesystem::path& path) {
  StudyInput input;
  input.source = path.string();
  if (is_pose_graph_file(path))
    input.graph = read_g2o_file(path);
  else
    input.set = read_fragment_set_file(path);
  return input;
}

void read_study_reference(StudyInput& input, const std::filesystem::path& path) {
  input.reference = input.graph ? reference_poses(input.graph->vertices.size(), {}, path)
                                : reference_frames(*input.set, path);
}

std::vector<OptimizeResult> run_trials(const StudyInput& input, const OptimizeSettings& settings,
                                       const G2oImportSettings& import, const TrialSettings& trials,
                                       const TrialsObserver& observer,
                                       const OptimizeObserver& convergence) {
  if (input.graph)
    return run_trials(*input.graph, input.source, settings, import, trials, observer, convergence);
  return run_trials(*input.set, settings, trials, observer, convergence);
}

}  // namespace antslam::slam
