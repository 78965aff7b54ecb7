#pragma once
// The named ACO variants: the one table that the dispatch (variants.hpp), the programs' option
// checks and help texts, and the tests all read. Adding a variant starts with a row here.

#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace antslam::aco {

enum class Variant { ant_system, elitist, rank_based, acs, mmas, hybrid };

struct VariantInfo {
  Variant variant;
  std::string_view name;     ///< the name options and files use
  std::string_view summary;  ///< one line for help texts: what it is and where it comes from
};

inline constexpr std::array<VariantInfo, 6> kVariants{{
    {Variant::ant_system, "as", "Ant System (Dorigo, Maniezzo & Colorni 1996)"},
    {Variant::elitist, "eas", "elitist Ant System: extra deposit on the best-so-far"},
    {Variant::rank_based, "ras", "rank-based Ant System (Bullnheimer, Hartl & Strauss 1999)"},
    {Variant::acs, "acs", "Ant Colony System (Dorigo & Gambardella 1997)"},
    {Variant::mmas, "mmas", "MAX-MIN Ant System (Stuetzle & Hoos 2000)"},
    {Variant::hybrid, "hybrid", "the AntSLAM hybrid (Algorithm 2)"},
}};

constexpr std::string_view to_string(Variant v) {
  for (const VariantInfo& info : kVariants)
    if (info.variant == v) return info.name;
  return "?";
}

/// GoogleTest and logs print the name.
inline void PrintTo(Variant v, std::ostream* os) { *os << to_string(v); }

constexpr std::optional<Variant> parse_variant(std::string_view name) {
  for (const VariantInfo& info : kVariants)
    if (info.name == name) return info.variant;
  return std::nullopt;
}

/// Every variant, in table order.
inline std::vector<Variant> all_variants() {
  std::vector<Variant> all;
  for (const VariantInfo& info : kVariants) all.push_back(info.variant);
  return all;
}

/// The names, in table order ("as", "eas", ...).
inline std::vector<std::string> variant_names() {
  std::vector<std::string> names;
  for (const VariantInfo& info : kVariants) names.emplace_back(info.name);
  return names;
}

}  // namespace antslam::aco
