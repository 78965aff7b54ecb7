#pragma once
// Is the map doubtful? What a user can see without a reference: how many loop closures the
// optimised map satisfies (within their 2-sigma ellipse), how often the scan matcher fell back
// to the odometry, and the largest residuals of the closures and of the alignments (an
// alignment bent far beyond its Gaussian means the scan matcher's fragment was wrong or a
// closure pulled it). One line ends the report and the terminal summary.

#include <cstddef>
#include <string>
#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/mapping/optimize_map.hpp"

namespace antslam::mapping {

struct VerdictSettings {
  double closure_sigmas = 2.0;    ///< a closure is satisfied within this Mahalanobis distance
  double alignment_sigmas = 5.0;  ///< an alignment bent further is doubtful (std)
  double fallback_share = 0.05;   ///< more scans than this share on odometry is doubtful
};

struct Verdict {
  std::size_t closures = 0;               ///< loop closures of the set (count)
  std::vector<std::size_t> outside;       ///< closures outside closure_sigmas after optimisation
  std::size_t scans = 0;                  ///< scans of the log (count)
  std::size_t fallbacks = 0;              ///< scans placed by the odometry, not by a match
  double largest_closure = 0.0;           ///< Mahalanobis distance of the worst closure after
  std::size_t largest_closure_index = 0;  ///< which closure (index into the set's closures)
  double largest_alignment = 0.0;         ///< Mahalanobis distance of the most bent alignment
  std::size_t largest_alignment_fragment = 0;  ///< which fragment's alignment
  bool doubtful = false;  ///< a closure outside, an alignment bent beyond alignment_sigmas, or
                          ///< more than fallback_share of the scans on odometry
  std::string line;       ///< "verdict: ..." for people
};

/// The verdict on the best trial's map of `mapping` (frontend: the run that built the set).
Verdict judge(const frontend::FrontendResult& frontend, const MappingResult& mapping,
              const VerdictSettings& settings = {});

}  // namespace antslam::mapping
