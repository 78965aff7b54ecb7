#pragma once
// QAPLIB instance files (Burkard, Karisch & Rendl 1997): the size n, then the n x n matrix A
// and the n x n matrix B, integers separated by any whitespace (blank lines and CRLF line ends
// included). Every error is one std::runtime_error line naming the file, the line and the
// problem: "data/x.dat:14: entry (3, 7) of A '1.5' is not an integer".

#include <filesystem>
#include <istream>
#include <ostream>
#include <string>

#include "antslam/qap/instance.hpp"

namespace antslam::qap {

/// Reads a .dat file; the instance's name is the file's stem.
Instance read_qaplib(const std::filesystem::path& file);

/// Reads QAPLIB text from `in`; `source` names it in errors.
Instance parse_qaplib(std::istream& in, const std::string& source, const std::string& name = {});

/// Writes n, a blank line, A, a blank line and B, one matrix row a line.
void write_qaplib(std::ostream& out, const Instance& instance);

}  // namespace antslam::qap
