#include "base/table.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace gearfem
{
  void Table::add_column(const std::string &name, const std::string &unit)
  {
    if (!rows_.empty())
      throw std::logic_error("Table: add columns before rows");
    names_.push_back(name);
    units_.push_back(unit);
  }

  void Table::add_row(const std::vector<double> &row)
  {
    if (row.size() != names_.size())
      throw std::logic_error("Table: row size does not match the number of columns");
    rows_.push_back(row);
  }

  bool Table::has_column(const std::string &name) const
  {
    for (const auto &n : names_)
      if (n == name)
        return true;
    return false;
  }

  std::vector<double> Table::column(const std::string &name) const
  {
    for (std::size_t c = 0; c < names_.size(); ++c)
      if (names_[c] == name)
        {
          std::vector<double> v;
          for (const auto &r : rows_)
            v.push_back(r[c]);
          return v;
        }
    throw std::logic_error("Table: no column " + name);
  }

  std::vector<std::string> Table::headers() const
  {
    std::vector<std::string> h;
    for (std::size_t c = 0; c < names_.size(); ++c)
      h.push_back(units_[c].empty() ? names_[c] : names_[c] + " [" + units_[c] + "]");
    return h;
  }

  void Table::write_csv(const std::filesystem::path &file, int significant) const
  {
    const auto h = headers();
    for (const auto &r : rows_)
      for (std::size_t c = 0; c < r.size(); ++c)
        if (!std::isfinite(r[c]))
          require_finite_output(r[c], file.string(), "column '" + h[c] + "'");
    AtomicOutputFile f(file);
    std::string text;
    for (std::size_t c = 0; c < h.size(); ++c)
      text += (c ? "," : "") + h[c];
    text += '\n';
    // std::to_chars in the general format with `significant` digits writes what printf's
    // %.<significant>g and an ostream with setprecision(significant) write (test_table.cc), at
    // a tenth of the ostream's cost: a condensed cycle's outputs took half of its sweep.
    char cell[64];
    for (const auto &r : rows_)
      {
        for (std::size_t c = 0; c < r.size(); ++c)
          {
            if (c)
              text += ',';
            const auto res = std::to_chars(cell, cell + sizeof(cell), r[c], std::chars_format::general, significant);
            text.append(cell, res.ptr);
          }
        text += '\n';
      }
    f.stream().write(text.data(), std::streamsize(text.size()));
    f.commit();
  }

  std::vector<std::vector<double>> read_csv_numbers(const std::filesystem::path &file,
                                                    std::vector<std::string> *headers)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("cannot open CSV file '" + file.string() + "'");
    std::string line;
    std::vector<std::vector<double>> rows;
    bool first = true;
    std::size_t line_number = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        if (line.empty())
          continue;
        std::stringstream ss(line);
        std::string cell;
        if (first)
          {
            first = false;
            if (headers)
              while (std::getline(ss, cell, ','))
                headers->push_back(cell);
            continue;
          }
        std::vector<double> row;
        while (std::getline(ss, cell, ','))
          row.push_back(parse_double("CSV file '" + file.string() + "', line " +
                                       std::to_string(line_number) + ", column " +
                                       std::to_string(row.size() + 1),
                                     cell));
        rows.push_back(row);
      }
    return rows;
  }
} // namespace gearfem
