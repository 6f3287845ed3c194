#include "batch/design.h"

#include "base/errors.h"
#include "base/number.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

namespace gearfem::batch
{
  namespace
  {
    std::string trim(const std::string &s)
    {
      const auto a = s.find_first_not_of(" \t\r");
      if (a == std::string::npos)
        return "";
      const auto b = s.find_last_not_of(" \t\r");
      return s.substr(a, b - a + 1);
    }

    /// Split one CSV line into trimmed cells; "..." quotes a cell ("" inside is one ").
    std::vector<std::string> csv_cells(const std::string &line, const std::string &where)
    {
      std::vector<std::string> cells;
      std::string cell;
      bool quoted = false, was_quoted = false;
      for (std::size_t i = 0; i < line.size(); ++i)
        {
          const char c = line[i];
          if (quoted)
            {
              if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
                cell += '"', ++i;
              else if (c == '"')
                quoted = false;
              else
                cell += c;
            }
          else if (c == '"' && trim(cell).empty())
            quoted = true, was_quoted = true, cell.clear();
          else if (c == ',')
            {
              cells.push_back(was_quoted ? cell : trim(cell));
              cell.clear(), was_quoted = false;
            }
          else if (!(was_quoted && (c == ' ' || c == '\t' || c == '\r')))
            {
              if (was_quoted)
                throw InputError(where, line, "CSV cells separated by ','",
                                 "text after the closing quote of a cell");
              cell += c;
            }
        }
      if (quoted)
        throw InputError(where, line, "CSV cells separated by ','", "a quote is not closed");
      cells.push_back(was_quoted ? cell : trim(cell));
      return cells;
    }

    bool valid_id(const std::string &id)
    {
      if (id.empty() || id == "." || id == "..")
        return false;
      for (const char c : id)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'))
          return false;
      return true;
    }

    std::string numbered(const std::string &prefix, std::size_t i, std::size_t n)
    {
      const int width = n >= 1000 ? int(std::to_string(n).size()) : 3;
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s_%0*zu", prefix.c_str(), width, i);
      return buf;
    }

    std::string format12(double x)
    {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.12g", x);
      return buf;
    }

    /// Uniform in [0, 1) from the top 53 bits of a 64-bit draw (exact, portable).
    double uniform01(std::mt19937_64 &g) { return double(g() >> 11) * 0x1.0p-53; }
  } // namespace

  std::pair<std::vector<std::string>, std::string> split_path(const std::string &path)
  {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true)
      {
        const auto p = path.find('/', start);
        parts.push_back(trim(path.substr(start, p == std::string::npos ? std::string::npos : p - start)));
        if (p == std::string::npos)
          break;
        start = p + 1;
      }
    for (const auto &p : parts)
      if (p.empty())
        throw InputError("parameter path", "'" + path + "'", "Section/.../Entry, e.g. 'Gear 1/Tip relief amount'",
                         "an empty part");
    std::string entry = parts.back();
    parts.pop_back();
    return {parts, entry};
  }

  DesignSet parse_design_table(const std::string &text, const std::string &name)
  {
    DesignSet set;
    std::istringstream in(text);
    std::string line;
    int line_no = 0, id_col = -1;
    bool have_header = false;
    std::set<std::string> ids;
    while (std::getline(in, line))
      {
        ++line_no;
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#')
          continue;
        const std::string where = "design table " + name + ", row " + std::to_string(line_no);
        auto cells = csv_cells(line, where);
        if (!have_header)
          {
            have_header = true;
            std::set<std::string> seen;
            for (std::size_t c = 0; c < cells.size(); ++c)
              {
                const std::string col = "design table " + name + ", column " + std::to_string(c + 1);
                if (cells[c].empty())
                  throw InputError(col, "(empty header)", "a parameter path such as 'Gear 1/Tip relief amount', or 'id'");
                if (!seen.insert(cells[c]).second)
                  throw InputError(col + " '" + cells[c] + "'", cells[c], "each column once", "duplicate column");
                if (cells[c] == id_column)
                  id_col = int(c);
                else
                  {
                    (void)split_path(cells[c]);
                    set.paths.push_back(cells[c]);
                  }
              }
            if (set.paths.empty())
              throw InputError("design table " + name + ", row " + std::to_string(line_no), line,
                               "a header naming at least one parameter path");
            continue;
          }
        const std::size_t n_cols = set.paths.size() + (id_col >= 0 ? 1 : 0);
        if (cells.size() != n_cols)
          throw InputError(where, std::to_string(cells.size()) + " cells",
                           std::to_string(n_cols) + " cells, one per header column");
        Design d;
        d.origin = "row " + std::to_string(line_no) + " of " + name;
        for (std::size_t c = 0; c < cells.size(); ++c)
          {
            const std::string header = int(c) == id_col ? std::string(id_column) : set.paths[c - (id_col >= 0 && int(c) > id_col)];
            if (cells[c].empty())
              throw InputError("design table " + name + ", column '" + header + "', row " + std::to_string(line_no),
                               "(empty cell)", "a value");
            if (int(c) == id_col)
              d.id = cells[c];
            else
              d.values.push_back(cells[c]);
          }
        if (id_col < 0)
          d.id = numbered("design", set.designs.size() + 1, 0);
        if (!valid_id(d.id))
          throw InputError("design table " + name + ", column 'id', row " + std::to_string(line_no), d.id,
                           "a folder name of letters, digits, '.', '_' and '-'");
        if (!ids.insert(d.id).second)
          throw InputError("design table " + name + ", column 'id', row " + std::to_string(line_no), d.id,
                           "a unique id", "the id appears on an earlier row");
        set.designs.push_back(std::move(d));
      }
    if (!have_header)
      throw InputError("design table " + name, "(empty)", "a header row of parameter paths and one row per design");
    if (set.designs.empty())
      throw InputError("design table " + name, "(no rows)", "at least one design row below the header");
    if (id_col < 0 && set.designs.size() >= 1000)
      for (std::size_t i = 0; i < set.designs.size(); ++i)
        set.designs[i].id = numbered("design", i + 1, set.designs.size());
    return set;
  }

  DesignSet read_design_table(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("Batch/Design table", file, "a readable CSV file", "cannot open it");
    std::ostringstream s;
    s << in.rdbuf();
    return parse_design_table(s.str(), file);
  }

  std::vector<std::pair<std::string, std::vector<std::string>>>
  parse_path_lists(const std::string &entry, const std::string &text, std::size_t expect_items)
  {
    std::vector<std::pair<std::string, std::vector<std::string>>> out;
    std::set<std::string> seen;
    for (const auto &group : split_trimmed(text, ';'))
      {
        if (group.empty())
          continue;
        const auto colon = group.find(':');
        if (colon == std::string::npos)
          throw InputError(entry, group, "'path: v1, v2, ...' groups separated by ';'", "no ':' after the path");
        const std::string path = trim(group.substr(0, colon));
        (void)split_path(path);
        if (!seen.insert(path).second)
          throw InputError(entry, path, "each parameter path once", "duplicate path");
        std::vector<std::string> items;
        for (const auto &v : split_trimmed(group.substr(colon + 1), ','))
          if (!v.empty())
            items.push_back(v);
        if (items.empty())
          throw InputError(entry + " (" + path + ")", "(no values)", "at least one value");
        if (expect_items > 0 && items.size() != expect_items)
          throw InputError(entry + " (" + path + ")", group.substr(colon + 1),
                           std::to_string(expect_items) + " values (low, high)");
        out.emplace_back(path, items);
      }
    if (out.empty())
      throw InputError(entry, "(empty)", "at least one 'path: values' group");
    return out;
  }

  DesignSet full_factorial(const std::vector<std::pair<std::string, std::vector<std::string>>> &lists)
  {
    DesignSet set;
    std::size_t n = 1;
    for (const auto &[path, values] : lists)
      {
        set.paths.push_back(path);
        n *= values.size();
        if (n > 1000000)
          throw InputError("Batch/Factorial", std::to_string(n) + "+ designs", "<= 1000000 designs");
      }
    for (std::size_t i = 0; i < n; ++i)
      {
        Design d;
        d.id     = numbered("ff", i + 1, n);
        d.origin = "factorial design " + std::to_string(i + 1);
        // Mixed radix, the last path varying fastest.
        std::size_t rest = i;
        d.values.resize(lists.size());
        for (std::size_t k = lists.size(); k-- > 0;)
          {
            const auto &v = lists[k].second;
            d.values[k]   = v[rest % v.size()];
            rest /= v.size();
          }
        set.designs.push_back(std::move(d));
      }
    return set;
  }

  DesignSet latin_hypercube(const std::vector<std::pair<std::string, std::pair<double, double>>> &ranges,
                            std::size_t n, std::uint64_t seed)
  {
    if (n < 1 || n > 1000000)
      throw InputError("Batch/Samples", std::to_string(n), "1 to 1000000");
    DesignSet set;
    std::mt19937_64 g(seed);
    std::vector<std::vector<std::string>> columns;
    for (const auto &[path, range] : ranges)
      {
        const auto [lo, hi] = range;
        if (!(lo <= hi))
          throw InputError("Batch/Latin hypercube (" + path + ")", to_string_g(lo) + ", " + to_string_g(hi),
                           "low <= high");
        set.paths.push_back(path);
        std::vector<std::size_t> stratum(n);
        for (std::size_t i = 0; i < n; ++i)
          stratum[i] = i;
        for (std::size_t i = n; i-- > 1;) // Fisher-Yates
          std::swap(stratum[i], stratum[std::size_t(g() % (i + 1))]);
        std::vector<std::string> col(n);
        for (std::size_t i = 0; i < n; ++i)
          col[i] = format12(lo + (hi - lo) * ((double(stratum[i]) + uniform01(g)) / double(n)));
        columns.push_back(std::move(col));
      }
    for (std::size_t i = 0; i < n; ++i)
      {
        Design d;
        d.id     = numbered("lhs", i + 1, n);
        d.origin = "Latin-hypercube sample " + std::to_string(i + 1);
        for (const auto &c : columns)
          d.values.push_back(c[i]);
        set.designs.push_back(std::move(d));
      }
    return set;
  }
} // namespace gearfem::batch
