// SPDX-License-Identifier: LGPL-3.0-or-later
// A plug-in table (issue 26: kernels, heuristics): rows with a `name`, in a fixed order, that
// may grow at run time (a test's or a plug-in's row), and the list of their names, which the
// public API hands out by reference (kernel_names(), heuristic_names()) and so keeps beside
// the rows. Not locked: rows are added before any lookup runs on another thread.
// Also the fixed form for an enum's names: one table {enumerator, name} per enum, read by
// name_of (instead of a switch per enum, of which there were four alike).
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace exbsp {

template <class Row>
class named_table {
 public:
  explicit named_table(std::vector<Row> rows) : rows_(std::move(rows)) {
    for (const Row& r : rows_) names_.push_back(r.name);
  }
  const std::vector<Row>& rows() const { return rows_; }
  const std::vector<std::string>& names() const { return names_; }
  /// The row called `name`, or nullptr.
  const Row* find(const std::string& name) const {
    for (const Row& r : rows_)
      if (r.name == name) return &r;
    return nullptr;
  }
  void add(Row row) {
    names_.push_back(row.name);
    rows_.push_back(std::move(row));
  }

 private:
  std::vector<Row> rows_;
  std::vector<std::string> names_;
};

/// One row of an enum's name table.
template <class E>
struct enum_name {
  E value;
  const char* name;
};

/// The name of `e` in `table`, or "?" when the table does not list it.
template <class E, std::size_t N>
constexpr const char* name_of(E e, const enum_name<E> (&table)[N]) {
  for (const enum_name<E>& row : table)
    if (row.value == e) return row.name;
  return "?";
}

}  // namespace exbsp
