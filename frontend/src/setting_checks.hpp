#pragma once
// Checks of the settings that the scan matcher and the loop closer validate.

#include <cmath>
#include <stdexcept>
#include <string>

namespace antslam::frontend {

/// `require(ok, field, what)` throws std::invalid_argument("<who>: <field> <what>") unless ok.
struct SettingCheck {
  const char* who;  ///< the component named in the message
  void operator()(bool ok, const char* field, const char* what) const {
    if (!ok) throw std::invalid_argument(std::string(who) + ": " + field + " " + what);
  }
};

inline bool positive(double v) { return v > 0.0 && std::isfinite(v); }

}  // namespace antslam::frontend
