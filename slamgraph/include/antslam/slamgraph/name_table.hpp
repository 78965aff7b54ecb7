#pragma once
// Enum <-> name through a table of {value, name, summary} rows (the robust methods, the kinds of
// false closures, the closure selections of the mapping pipeline): the one lookup both directions
// use.

#include <optional>
#include <string_view>

namespace antslam::slam::detail {

template <class Table, class Value>
std::string_view name_in(const Table& table, Value value) {
  for (const auto& row : table)
    if (row.value == value) return row.name;
  return "?";
}

template <class Table>
auto value_in(const Table& table, std::string_view name)
    -> std::optional<decltype(table.front().value)> {
  for (const auto& row : table)
    if (row.name == name) return row.value;
  return std::nullopt;
}

}  // namespace antslam::slam::detail
