// SPDX-License-Identifier: LGPL-3.0-or-later
// A plug-in table (issue 26: kernels, heuristics): rows with a `name`, in a fixed order, that
// may grow at run time (a test's or a plug-in's row), and the list of their names, which the
// public API hands out by reference (kernel_names(), heuristic_names()) and so keeps beside
// the rows. Not locked: rows are added before any lookup runs on another thread.
#pragma once
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

}  // namespace exbsp
