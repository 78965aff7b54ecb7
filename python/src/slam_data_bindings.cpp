// antslam.slam: fragment sets (load, save, synthesize, from pose graphs) and pose graphs (g2o and
// TORO files), with poses as numpy arrays.

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "antslam/io/atomic_file.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/graph_structure.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "pickling.hpp"
#include "slam_types.hpp"

namespace antslam::python {

namespace {

py::tuple scores_tuple(const slam::Scores& s) { return py::make_tuple(s.weight, s.chi2); }

void bind_fragment_set(py::module_& m) {
  py::class_<slam::FragmentSet>(m, "FragmentSet",
                                "N fragments with Gaussians and samples, and loop closures "
                                "(slamgraph/fragment_set.hpp)")
      .def_readwrite("name", &slam::FragmentSet::name)
      .def("__len__", [](const slam::FragmentSet& s) { return s.fragments.size(); })
      .def_property_readonly("fragment_count",
                             [](const slam::FragmentSet& s) { return s.fragments.size(); })
      .def_property_readonly("layer_count", &slam::FragmentSet::layer_count)
      .def_property_readonly("closures",
                             [](const slam::FragmentSet& s) {
                               std::vector<std::pair<std::size_t, std::size_t>> pairs;
                               for (const slam::LoopClosure& c : s.closures)
                                 pairs.emplace_back(c.from, c.to);
                               return pairs;
                             })
      .def_property_readonly(
          "means", [](const slam::FragmentSet& s) { return poses_array(slam::mean_alignments(s)); },
          "The alignment means mu_2..mu_N, (N - 1, 3): the scan matcher's map")
      .def_property(
          "reference", [](const slam::FragmentSet& s) { return poses_array(s.reference); },
          [](slam::FragmentSet& s, const DoubleArray& poses) {
            s.reference = poses_from(poses, "reference");
            slam::validate(s);
          },
          "Ground-truth world frames (N, 3), or an empty array")
      .def(
          "samples",
          [](const slam::FragmentSet& s, std::size_t fragment) {
            if (fragment >= s.fragments.size())
              throw py::index_error("samples: fragment out of range 0.." +
                                    std::to_string(s.fragments.size() - 1));
            return poses_array(s.fragments[fragment].samples);
          },
          py::arg("fragment"), "The M samples of a fragment's alignment (eq. 7), (M, 3)")
      .def(
          "score",
          [](const slam::FragmentSet& s, const DoubleArray& alignments) {
            return scores_tuple(slam::score(s, poses_from(alignments, "alignments")));
          },
          py::arg("alignments"), "(eq. 10 weight, chi2) of N - 1 alignments")
      .def(
          "path_weight",
          [](const slam::FragmentSet& s, const py::object& choice) {
            return slam::path_weight(s, indices_from(choice, "choice"));
          },
          py::arg("choice"), "Eq. (10) of one sample per fragment 2..N")
      .def(
          "world_trajectory",
          [](const slam::FragmentSet& s, const DoubleArray& frames) {
            return trajectory_array(slam::world_trajectory(s, poses_from(frames, "frames")));
          },
          py::arg("frames"), "Every robot pose in W for the fragments' world frames, (k, 4)")
      .def(
          "save",
          [](const slam::FragmentSet& s, const std::filesystem::path& path) {
            io::write_atomically(path,
                                 [&](std::ostream& out) { slam::write_fragment_set(out, s); });
          },
          py::arg("path"), "Writes the set as fragment-set JSON (atomically)")
      .def(py::pickle(
          [](const slam::FragmentSet& s) {
            return py::make_tuple(kPickleVersion, text_of([&](std::ostream& out) {
                                    slam::write_fragment_set(out, s);
                                  }));
          },
          [](const py::tuple& state) {
            check_pickle_state(state, 2, "antslam.slam.FragmentSet");
            std::istringstream in = text_in(state);
            return slam::read_fragment_set(in, "pickled antslam.slam.FragmentSet");
          }))
      .def("__repr__", [](const slam::FragmentSet& s) {
        return "<antslam.slam.FragmentSet '" + s.name + "': " + std::to_string(s.fragments.size()) +
               " fragments, " + std::to_string(s.closures.size()) + " closures>";
      });

  m.def("load", &slam::read_fragment_set_file, py::arg("path"), "Reads a fragment-set JSON");

  py::class_<slam::SynthSettings>(m, "SynthSettings", "slamgraph/synth.hpp")
      .def(py::init<>())
      .def_readwrite("fragments", &slam::SynthSettings::fragments)
      .def_readwrite("samples", &slam::SynthSettings::samples)
      .def_readwrite("loop_length_m", &slam::SynthSettings::loop_length_m)
      .def_readwrite("aspect", &slam::SynthSettings::aspect)
      .def_readwrite("laps", &slam::SynthSettings::laps)
      .def_readwrite("sigma_xy", &slam::SynthSettings::sigma_xy)
      .def_readwrite("sigma_theta", &slam::SynthSettings::sigma_theta)
      .def_readwrite("correlation", &slam::SynthSettings::correlation)
      .def_readwrite("closure_sigma_xy", &slam::SynthSettings::closure_sigma_xy)
      .def_readwrite("closure_sigma_theta", &slam::SynthSettings::closure_sigma_theta)
      .def_readwrite("revisit_radius_m", &slam::SynthSettings::revisit_radius_m)
      .def_readwrite("noise_free", &slam::SynthSettings::noise_free)
      .def_readwrite("trajectory_poses", &slam::SynthSettings::trajectory_poses)
      .def_readwrite("seed", &slam::SynthSettings::seed);
  m.def("synth_preset", &slam::synth_preset, py::arg("name"),
        "paper9, paper15 or paper24 (the paper's environments)");
  m.def("synthesize", &slam::synthesize, py::arg("settings"));
}

void bind_pose_graph(py::module_& m) {
  py::class_<NamedGraph>(m, "PoseGraph",
                         "A 2D pose graph as g2o and TORO files hold it (slamgraph/g2o.hpp)")
      .def_readwrite("name", &NamedGraph::name)
      .def("__len__", [](const NamedGraph& g) { return g.graph.vertices.size(); })
      .def_property(
          "vertices", [](const NamedGraph& g) { return poses_array(g.graph.vertices); },
          [](NamedGraph& g, const DoubleArray& poses) {
            std::vector<slam::Pose2> v = poses_from(poses, "vertices");
            if (v.size() != g.graph.vertices.size())
              throw std::invalid_argument("vertices: got " + std::to_string(v.size()) +
                                          " poses for " + std::to_string(g.graph.vertices.size()) +
                                          " vertices");
            g.graph.vertices = std::move(v);
          },
          "Vertex poses (n, 3): the start of ceres and nlopt")
      .def_property_readonly("edges",
                             [](const NamedGraph& g) {
                               std::vector<std::pair<std::size_t, std::size_t>> pairs;
                               for (const slam::PoseGraphEdge& e : g.graph.edges)
                                 pairs.emplace_back(e.from, e.to);
                               return pairs_array(pairs);
                             })
      .def_property_readonly("measurements",
                             [](const NamedGraph& g) {
                               std::vector<slam::Pose2> z;
                               for (const slam::PoseGraphEdge& e : g.graph.edges)
                                 z.push_back(e.measurement);
                               return poses_array(z);
                             })
      .def_property_readonly(
          "information",
          [](const NamedGraph& g) {
            py::array_t<double> out(
                {static_cast<py::ssize_t>(g.graph.edges.size()), py::ssize_t{3}, py::ssize_t{3}});
            auto v = out.mutable_unchecked<3>();
            for (std::size_t k = 0; k < g.graph.edges.size(); ++k)
              for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                  v(static_cast<py::ssize_t>(k), r, c) = g.graph.edges[k].information(r, c);
            return out;
          })
      .def_property(
          "fixed", [](const NamedGraph& g) { return g.graph.fixed; },
          [](NamedGraph& g, std::vector<std::size_t> fixed) {
            std::sort(fixed.begin(), fixed.end());
            fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
            for (const std::size_t v : fixed)
              if (v >= g.graph.vertices.size())
                throw std::invalid_argument("fixed: vertex " + std::to_string(v) +
                                            " is not in the graph");
            g.graph.fixed = std::move(fixed);
          },
          "Vertices held fixed (FIX lines); empty: vertex 0")
      .def_property_readonly("vertices_from_file",
                             [](const NamedGraph& g) { return g.graph.vertices_from_file; })
      .def(
          "score",
          [](const NamedGraph& g, const DoubleArray& poses) {
            return scores_tuple(slam::score(g.graph, poses_from(poses, "poses")));
          },
          py::arg("poses"), "(eq. 10 weight, chi2) over the edges at the vertex poses")
      .def(
          "fragment_set",
          [](const NamedGraph& g, std::size_t samples, std::uint64_t seed) {
            return slam::fragment_set_from_g2o(g.graph, {samples, seed}, g.name);
          },
          py::arg("samples") = 20, py::arg("seed") = 1,
          "The ants' fragment chain of the graph (needs consecutive vertices joined)")
      .def(
          "save",
          [](const NamedGraph& g, const std::filesystem::path& path) {
            io::write_atomically(
                path, [&](std::ostream& out) { slam::write_pose_graph(out, g.graph, path); });
          },
          py::arg("path"), "Writes g2o lines, or TORO lines for a .graph name (atomically)")
      .def(py::pickle(
          [](const NamedGraph& g) {
            return py::make_tuple(
                kPickleVersion, text_of([&](std::ostream& out) { slam::write_g2o(out, g.graph); }),
                g.name, g.graph.vertices_from_file);
          },
          [](const py::tuple& state) {
            check_pickle_state(state, 4, "antslam.slam.PoseGraph");
            std::istringstream in = text_in(state);
            NamedGraph g{slam::read_g2o(in, "pickled antslam.slam.PoseGraph"),
                         state[2].cast<std::string>()};
            g.graph.vertices_from_file = state[3].cast<bool>();
            return g;
          }))
      .def("__repr__", [](const NamedGraph& g) {
        return "<antslam.slam.PoseGraph '" + g.name +
               "': " + std::to_string(g.graph.vertices.size()) + " vertices, " +
               std::to_string(g.graph.edges.size()) + " edges>";
      });

  m.def(
      "read_graph",
      [](const std::filesystem::path& path) {
        return NamedGraph{slam::read_g2o_file(path), path.string()};
      },
      py::arg("path"), "Reads a pose graph: g2o or TORO lines");
  m.def(
      "graph_of_set",
      [](const slam::FragmentSet& set, const DoubleArray& frames) {
        return NamedGraph{slam::pose_graph_of(set, poses_from(frames, "frames")), set.name};
      },
      py::arg("set"), py::arg("frames"),
      "The pose graph of a fragment set with the given world frames as vertices");
  m.def(
      "chain",
      [](const DoubleArray& a) { return poses_array(slam::chain(poses_from(a, "alignments"))); },
      py::arg("alignments"), "World frames F_1..F_N of N - 1 alignments (eq. 8)");
  m.def(
      "relative_alignments",
      [](const DoubleArray& f) {
        return poses_array(slam::relative_alignments(poses_from(f, "frames")));
      },
      py::arg("frames"), "X_i = F_{i-1}^-1 F_i of world frames (the inverse of chain)");
  m.def(
      "read_reference_poses",
      [](const std::filesystem::path& path) {
        return poses_array(slam::read_reference_poses(path));
      },
      py::arg("path"), "Reference poses: a pose graph's vertices, a TUM file or `x y theta` lines");
}

}  // namespace

void bind_slam_data(py::module_& m) {
  bind_fragment_set(m);
  bind_pose_graph(m);
}

}  // namespace antslam::python
