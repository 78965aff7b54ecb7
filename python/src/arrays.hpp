#pragma once
// numpy arrays for the library's types: poses as (n, 3) float64 arrays of (x, y, theta),
// trajectories as (n, 4) arrays of (t, x, y, theta), choices and tours as uint32 arrays. Arrays
// from Python are checked: shape and finite values, with one line naming the argument.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "antslam/slamgraph/pose2.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>;

py::array_t<double> poses_array(std::span<const slam::Pose2> poses);
/// Throws std::invalid_argument "NAME: expected an (n, 3) array of (x, y, theta)" or
/// "NAME: row k is not finite".
std::vector<slam::Pose2> poses_from(const DoubleArray& array, const std::string& name);

py::array_t<double> trajectory_array(const slam::Trajectory& trajectory);
/// Throws std::invalid_argument for a shape other than (n, 4), non-finite values, or timestamps
/// that decrease.
slam::Trajectory trajectory_from(const DoubleArray& array, const std::string& name);

py::array_t<std::uint32_t> index_array(std::span<const std::uint32_t> values);
/// Vertex pairs as an (m, 2) array.
py::array_t<std::uint64_t> pairs_array(std::span<const std::pair<std::size_t, std::size_t>> pairs);
/// A one-dimensional array (or sequence) of integers in [0, 2^32) as a vector; throws
/// std::invalid_argument naming the argument and the entry otherwise.
std::vector<std::uint32_t> indices_from(const py::handle& values, const std::string& name);

}  // namespace antslam::python
