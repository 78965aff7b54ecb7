#pragma once
// Pickling by the text formats the library already writes with round-trip precision and reads
// with its own checks (TSPLIB, fragment-set JSON, g2o): a pickle's state is (format version,
// the text as bytes, extras), so that an object crosses to another process (multiprocessing)
// bit for bit.

#include <pybind11/pybind11.h>

#include <sstream>
#include <stdexcept>
#include <string>

namespace antslam::python {

namespace py = pybind11;

inline constexpr int kPickleVersion = 1;

/// The text `write(out)` produces, as bytes.
template <class Write>
py::bytes text_of(Write&& write) {
  std::ostringstream out;
  write(out);
  return py::bytes(out.str());
}

/// Throws std::invalid_argument (ValueError) unless `state` is a tuple of `size` items whose first
/// is kPickleVersion.
inline void check_pickle_state(const py::tuple& state, std::size_t size, const std::string& type) {
  if (state.size() != size || !py::isinstance<py::int_>(state[0]) ||
      state[0].cast<int>() != kPickleVersion || !py::isinstance<py::bytes>(state[1]))
    throw std::invalid_argument(type + ": not a pickle this antslam reads (format version " +
                                std::to_string(kPickleVersion) + ")");
}

/// An input stream over the text of state[1].
inline std::istringstream text_in(const py::tuple& state) {
  return std::istringstream(state[1].cast<std::string>());
}

}  // namespace antslam::python
