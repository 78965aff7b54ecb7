#include "antslam/slamgraph/fragment_set_io.hpp"

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "json_reader.hpp"
#include "json_writer.hpp"
#include "text_lines.hpp"

namespace antslam::slam {

namespace {

using detail::JsonField;
using json = nlohmann::ordered_json;

json trajectory_json(const Trajectory& t) {
  json out = json::array();
  for (const StampedPose& p : t) out.push_back({p.stamp, p.pose.x, p.pose.y, p.pose.theta});
  return out;
}

Trajectory read_trajectory(const JsonField& field) {
  Trajectory t;
  const std::size_t n = field.array_size();
  for (std::size_t k = 0; k < n; ++k) {
    const JsonField p = field.item(k);
    p.array_size(4);
    t.push_back({p.item(0U).number(), Pose2::from_vector({p.item(1U).number(), p.item(2U).number(),
                                                          p.item(3U).number()})});
  }
  return t;
}

Fragment read_fragment(const JsonField& field, bool first) {
  field.only({"exit", "alignment", "samples", "trajectory"});
  Fragment f;
  f.exit = field.at("exit").pose();
  if (field.has("trajectory")) f.trajectory = read_trajectory(field.at("trajectory"));
  if (first) {
    if (field.has("alignment") || field.has("samples"))
      field.fail("the first fragment is the world frame: no alignment or samples");
    return f;
  }
  f.alignment = field.at("alignment").gaussian();
  const JsonField samples = field.at("samples");
  const std::size_t m = samples.array_size();
  if (m == 0) samples.fail("is empty");
  for (std::size_t j = 0; j < m; ++j) f.samples.push_back(samples.item(j).pose());
  return f;
}

LoopClosure read_closure(const JsonField& field, std::size_t fragments) {
  field.only({"from", "to", "anchor", "hypothesis"});
  LoopClosure c;
  const JsonField from = field.at("from"), to = field.at("to");
  c.from = from.integer();
  c.to = to.integer();
  if (c.to >= fragments) to.fail(std::to_string(c.to) + " is not a fragment index");
  if (c.from >= c.to) from.fail("must be smaller than `to`");
  c.anchor = field.at("anchor").pose();
  c.hypothesis = field.at("hypothesis").gaussian();
  return c;
}

}  // namespace

double fragment_set_bytes(std::size_t fragments, std::size_t samples_per_fragment,
                          std::size_t trajectory_poses_per_fragment) {
  // A JSON array of n numbers takes about 32 + 24 n bytes (nlohmann), next to the poses.
  constexpr double kPerPose = sizeof(Pose2) + 32.0 + 24.0 * 3.0;
  constexpr double kPerStampedPose = sizeof(StampedPose) + 32.0 + 24.0 * 4.0;
  constexpr double kPerFragment = sizeof(Fragment) + sizeof(Gaussian2) + 1024.0;
  return static_cast<double>(fragments) *
         (kPerFragment + static_cast<double>(samples_per_fragment) * kPerPose +
          static_cast<double>(trajectory_poses_per_fragment) * kPerStampedPose);
}

void write_fragment_set(std::ostream& out, const FragmentSet& set) {
  validate(set);
  json doc = {{"format", kFragmentSetFormat}, {"version", kFragmentSetVersion}, {"name", set.name}};
  json fragments = json::array();
  for (const Fragment& f : set.fragments) {
    json j = {{"exit", detail::pose_json(f.exit)}};
    if (f.alignment) {
      j["alignment"] = detail::gaussian_json(*f.alignment);
      j["samples"] = detail::poses_json(f.samples);
    }
    if (!f.trajectory.empty()) j["trajectory"] = trajectory_json(f.trajectory);
    fragments.push_back(std::move(j));
  }
  doc["fragments"] = std::move(fragments);
  json closures = json::array();
  for (const LoopClosure& c : set.closures)
    closures.push_back({{"from", c.from},
                        {"to", c.to},
                        {"anchor", detail::pose_json(c.anchor)},
                        {"hypothesis", detail::gaussian_json(c.hypothesis)}});
  doc["closures"] = std::move(closures);
  if (!set.reference.empty()) doc["reference"] = detail::poses_json(set.reference);
  detail::write_json(out, doc);
}

FragmentSet read_fragment_set(std::istream& in, const std::string& source) {
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw std::runtime_error(source + ": read error");
  const nlohmann::json doc = detail::parse_json(text, source);
  const JsonField root(doc, source, "");
  detail::check_header(root, kFragmentSetFormat, kFragmentSetVersion);
  root.only({"format", "version", "name", "fragments", "closures", "reference"});
  FragmentSet set;
  if (root.has("name")) set.name = root.at("name").string();
  const JsonField fragments = root.at("fragments");
  const std::size_t n = fragments.array_size();
  if (n < 2) fragments.fail("a fragment set needs at least 2 fragments, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    set.fragments.push_back(read_fragment(fragments.item(i), i == 0));
  const JsonField closures = root.at("closures");
  const std::size_t c = closures.array_size();
  if (c == 0) closures.fail("a fragment set needs at least one loop closure");
  for (std::size_t k = 0; k < c; ++k) set.closures.push_back(read_closure(closures.item(k), n));
  if (root.has("reference")) {
    const JsonField reference = root.at("reference");
    reference.array_size(n);
    for (std::size_t i = 0; i < n; ++i) set.reference.push_back(reference.item(i).pose());
  }
  try {
    validate(set);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(source + ": " + e.what());
  }
  return set;
}

FragmentSet read_fragment_set_file(const std::filesystem::path& path) {
  std::ifstream in = detail::open_input(path);
  return read_fragment_set(in, path.string());
}

}  // namespace antslam::slam
