#pragma once
// Rigid alignment of an estimated trajectory onto the reference: the closed-form least-squares
// solution of Horn (1987) / Umeyama (1991) restricted to SE(2) without scale. With centroids
// mu_e, mu_r and centred positions a_i = e_i - mu_e, b_i = r_i - mu_r, the transform
// T = (R(alpha), t) minimising sum_i |R(alpha) e_i + t - r_i|^2 is
//   alpha = atan2(sum_i a_i x b_i, sum_i a_i . b_i),   t = mu_r - R(alpha) mu_e
// (x is the 2D cross product a.x b.y - a.y b.x). Only positions enter, as in the TUM tools;
// headings are carried along by the transform.

#include <span>

#include "antslam/eval/association.hpp"
#include "antslam/slamgraph/pose2.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval {

/// The transform T with T * estimate ~ reference in the least-squares sense above. If all
/// estimated positions coincide the rotation is undetermined and alpha = 0 (pure translation).
/// Throws std::invalid_argument if `pairs` is empty.
slam::Pose2 align(std::span<const PosePair> pairs);

/// Sum of squared position residuals sum_i |T e_i - r_i|^2 (m^2): the cost align() minimises.
double alignment_cost(std::span<const PosePair> pairs, const slam::Pose2& transform);

/// Every pose of `trajectory` moved by `transform` (transform * pose), stamps unchanged.
slam::Trajectory transformed(const slam::Trajectory& trajectory, const slam::Pose2& transform);

}  // namespace antslam::eval
