#include "arrays.hpp"

#include <cmath>
#include <stdexcept>

namespace antslam::python {

namespace {

void check_shape(const DoubleArray& array, py::ssize_t columns, const std::string& name,
                 const char* layout) {
  if (array.ndim() != 2 || array.shape(1) != columns)
    throw std::invalid_argument(name + ": expected an (n, " + std::to_string(columns) +
                                ") array of " + layout);
}

void check_finite(const double* row, py::ssize_t columns, py::ssize_t k, const std::string& name) {
  for (py::ssize_t c = 0; c < columns; ++c)
    if (!std::isfinite(row[c]))
      throw std::invalid_argument(name + ": row " + std::to_string(k) + " is not finite");
}

}  // namespace

py::array_t<double> poses_array(std::span<const slam::Pose2> poses) {
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{3}});
  auto v = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    v(k, 0) = poses[i].x;
    v(k, 1) = poses[i].y;
    v(k, 2) = poses[i].theta;
  }
  return out;
}

std::vector<slam::Pose2> poses_from(const DoubleArray& array, const std::string& name) {
  check_shape(array, 3, name, "(x, y, theta)");
  std::vector<slam::Pose2> poses;
  for (py::ssize_t k = 0; k < array.shape(0); ++k) {
    const double* row = array.data(k, 0);
    check_finite(row, 3, k, name);
    poses.push_back(slam::Pose2::from_vector({row[0], row[1], row[2]}));
  }
  return poses;
}

py::array_t<double> trajectory_array(const slam::Trajectory& trajectory) {
  py::array_t<double> out({static_cast<py::ssize_t>(trajectory.size()), py::ssize_t{4}});
  auto v = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    v(k, 0) = trajectory[i].stamp;
    v(k, 1) = trajectory[i].pose.x;
    v(k, 2) = trajectory[i].pose.y;
    v(k, 3) = trajectory[i].pose.theta;
  }
  return out;
}

slam::Trajectory trajectory_from(const DoubleArray& array, const std::string& name) {
  check_shape(array, 4, name, "(t, x, y, theta)");
  slam::Trajectory trajectory;
  for (py::ssize_t k = 0; k < array.shape(0); ++k) {
    const double* row = array.data(k, 0);
    check_finite(row, 4, k, name);
    if (!trajectory.empty() && row[0] < trajectory.back().stamp)
      throw std::invalid_argument(name + ": row " + std::to_string(k) + ": timestamp decreases");
    trajectory.push_back({row[0], slam::Pose2::from_vector({row[1], row[2], row[3]})});
  }
  return trajectory;
}

py::array_t<std::uint32_t> index_array(std::span<const std::uint32_t> values) {
  py::array_t<std::uint32_t> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::array_t<std::uint64_t> pairs_array(std::span<const std::pair<std::size_t, std::size_t>> pairs) {
  py::array_t<std::uint64_t> out({static_cast<py::ssize_t>(pairs.size()), py::ssize_t{2}});
  auto v = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    v(static_cast<py::ssize_t>(k), 0) = pairs[k].first;
    v(static_cast<py::ssize_t>(k), 1) = pairs[k].second;
  }
  return out;
}

std::vector<std::uint32_t> indices_from(const py::handle& values_in, const std::string& name) {
  const py::array array = py::array::ensure(values_in);
  if (!array) throw std::invalid_argument(name + ": expected an array of integers");
  if (array.dtype().kind() != 'i' && array.dtype().kind() != 'u')
    throw std::invalid_argument(name + ": expected integers, got an array of " +
                                std::string(py::str(array.dtype())));
  const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> values(array);
  if (values.ndim() != 1) throw std::invalid_argument(name + ": expected a one-dimensional array");
  std::vector<std::uint32_t> out;
  for (py::ssize_t k = 0; k < values.shape(0); ++k) {
    const std::int64_t v = values.at(k);
    if (v < 0 || v > std::int64_t{0xffffffff})
      throw std::invalid_argument(name + ": entry " + std::to_string(k) + " (" + std::to_string(v) +
                                  ") is not an index");
    out.push_back(static_cast<std::uint32_t>(v));
  }
  return out;
}

}  // namespace antslam::python
