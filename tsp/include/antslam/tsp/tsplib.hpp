#pragma once
// TSPLIB files (Reinelt, "TSPLIB 95"): instances (.tsp) and tours (.tour).
//
// Instances: TYPE TSP with EDGE_WEIGHT_TYPE EUC_2D, CEIL_2D, ATT, GEO or EXPLICIT; explicit
// matrices in every symmetric EDGE_WEIGHT_FORMAT (FULL_MATRIX, UPPER_ROW, LOWER_ROW,
// UPPER_DIAG_ROW, LOWER_DIAG_ROW and the *_COL forms, which equal a row form for a symmetric
// matrix). Malformed input throws std::runtime_error with one line "file:line: problem".

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "antslam/tsp/instance.hpp"

namespace antslam::tsp {

Instance parse_instance(std::istream& in, const std::string& source);
Instance read_instance(const std::filesystem::path& path);

/// Writes a coordinate instance (NODE_COORD_SECTION, shortest round-trip numbers) or an
/// EXPLICIT one (FULL_MATRIX).
void write_instance(std::ostream& out, const Instance& instance);

/// Reads a tour of `n` nodes: TSPLIB TOUR_SECTION ids 1..n ended by -1 (or the end of the file),
/// returned 0-based. Throws on a DIMENSION other than n, ids out of range, repeated or missing
/// nodes.
std::vector<std::uint32_t> parse_tour(std::istream& in, const std::string& source, std::size_t n);
std::vector<std::uint32_t> read_tour(const std::filesystem::path& path, std::size_t n);

/// Writes a 0-based tour as a TSPLIB .tour file (ids 1..n, one per line).
void write_tour(std::ostream& out, std::string_view name, std::span<const std::uint32_t> tour,
                std::string_view comment);

}  // namespace antslam::tsp
