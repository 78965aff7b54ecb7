#pragma once
// An Evaluation as a table for people (stdout) and as JSON for scripts. Rotations are reported
// in degrees, translations in metres; JSON keys carry the unit (`translation_m`, `rotation_deg`).

#include <iosfwd>
#include <nlohmann/json.hpp>

#include "antslam/eval/evaluation.hpp"

namespace antslam::eval {

void print_table(std::ostream& out, const Evaluation& evaluation);

nlohmann::json to_json(const Evaluation& evaluation);

}  // namespace antslam::eval
