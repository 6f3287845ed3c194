#pragma once
// Column tables with self-describing headers ("name [unit]"), written as CSV atomically.
#include <filesystem>
#include <string>
#include <vector>

namespace gearfem
{
  class Table
  {
  public:
    /// Add a numeric column; `unit` may be "" for dimensionless or "-".
    void add_column(const std::string &name, const std::string &unit);
    /// Append a row; its size must equal the number of columns.
    void add_row(const std::vector<double> &row);
    std::size_t n_rows() const { return rows_.size(); }
    std::size_t n_columns() const { return names_.size(); }
    const std::vector<double> &row(std::size_t i) const { return rows_[i]; }
    /// The values of the column called `name` (without unit); throws std::logic_error
    /// if there is none.
    std::vector<double> column(const std::string &name) const;
    bool has_column(const std::string &name) const;
    const std::string &name(std::size_t c) const { return names_[c]; }
    const std::string &unit(std::size_t c) const { return units_[c]; }
    /// Header labels "name [unit]".
    std::vector<std::string> headers() const;
    /// Write as CSV with `significant` digits, atomically.
    void write_csv(const std::filesystem::path &file, int significant = 10) const;

  private:
    std::vector<std::string> names_, units_;
    std::vector<std::vector<double>> rows_;
  };

  /// Read a CSV written by Table::write_csv (header row skipped, numbers only).
  std::vector<std::vector<double>> read_csv_numbers(const std::filesystem::path &file,
                                                    std::vector<std::string> *headers = nullptr);
} // namespace gearfem
