#include "antslam/mapping/verdict.hpp"

#include <cmath>
#include <cstdio>

namespace antslam::mapping {

Verdict judge(const frontend::FrontendResult& frontend, const MappingResult& mapping,
              const VerdictSettings& s) {
  Verdict v;
  const slam::FragmentSet& set = frontend.fragment_set;
  v.closures = mapping.after.size();
  for (std::size_t c = 0; c < mapping.after.size(); ++c) {
    const double m = mapping.after[c].mahalanobis;
    if (m > s.closure_sigmas) v.outside.push_back(c);
    if (m > v.largest_closure) {
      v.largest_closure = m;
      v.largest_closure_index = c;
    }
  }
  const std::vector<slam::Pose2> alignments = slam::relative_alignments(mapping.frames);
  for (std::size_t i = 0; i < alignments.size(); ++i) {
    const double m = std::sqrt(set.fragments[i + 1].alignment->mahalanobis_squared(alignments[i]));
    if (m > v.largest_alignment) {
      v.largest_alignment = m;
      v.largest_alignment_fragment = i + 1;
    }
  }
  v.scans = frontend.scans.size();
  for (const frontend::ScanRecord& r : frontend.scans) v.fallbacks += r.matched_by_scan() ? 0U : 1U;
  const bool many_fallbacks =
      static_cast<double>(v.fallbacks) > s.fallback_share * static_cast<double>(v.scans);
  v.doubtful = !v.outside.empty() || v.largest_alignment > s.alignment_sigmas || many_fallbacks;

  char buffer[512];
  std::string closures;
  if (v.closures > 0) {
    std::snprintf(
        buffer, sizeof buffer, "%zu of %zu closures within %.0f sigma (largest %.2f, %zu-%zu)",
        v.closures - v.outside.size(), v.closures, s.closure_sigmas, v.largest_closure,
        set.closures[v.largest_closure_index].from, set.closures[v.largest_closure_index].to);
    closures = buffer;
  }
  std::snprintf(buffer, sizeof buffer,
                "verdict: %s: %s; %zu of %zu scans on odometry (scan-matcher fallbacks); largest "
                "alignment residual %.2f sigma (fragment %zu)",
                v.doubtful ? "DOUBTFUL map" : "consistent map", closures.c_str(), v.fallbacks,
                v.scans, v.largest_alignment, v.largest_alignment_fragment);
  v.line = buffer;
  return v;
}

}  // namespace antslam::mapping
