// The solve-results contract (io/solve_results.h): column definitions, CSV + HDF5 writer,
// HDF5 reader.
#include "io/solve_results.h"

#include "base/atomic_file.h"
#include "io/hdf5_util.h"

#include <cmath>

namespace gearfem::io
{
  namespace
  {
    using namespace hdf5;
    using Columns = std::vector<std::pair<const char *, const char *>>;

    Table make_table(const Columns &cols)
    {
      Table t;
      for (const auto &[n, u] : cols)
        t.add_column(n, u);
      return t;
    }

    // The one definition of the columns (docs/output-format.md documents each).
    const Columns sweep_columns = {
      {"torque", "N m"}, {"position", "-"}, {"roll angle", "deg"},
      {"point (0 none; 1 A; 2 B; 3 C; 4 D; 5 E)", "-"}, {"STE", "um"}, {"STE angle", "urad"},
      {"F_n", "N"}, {"k_secant", "N/m"}, {"k_tangent", "N/m"}, {"k_secant per width", "N/(mm um)"},
      {"k_tangent per width", "N/(mm um)"}, {"pairs in contact", "-"}, {"max load share", "-"},
      {"T1 contact moment", "N m"}, {"T1 reaction", "N m"}, {"T2 z1/(T1 z2)", "-"},
      {"p_max", "MPa"}, {"p_max edge", "MPa"}, {"root stress pinion", "MPa"},
      {"root stress gear", "MPa"}, {"active nodes", "-"}, {"geometry iterations", "-"},
      {"active-set iterations", "-"}, {"load cuts", "-"}, {"complementarity", "-"},
      {"max penetration", "um"}, {"friction force", "N"}, {"power loss", "W"}, {"normal-force power", "W"}, {"time", "s"}};
    const Columns pair_columns = {
      {"torque", "N m"}, {"position", "-"}, {"roll angle", "deg"}, {"pinion tooth", "-"},
      {"gear tooth", "-"}, {"F_n", "N"}, {"load share", "-"}, {"active nodes", "-"},
      {"p_max", "MPa"}, {"p_Hertz", "MPa"}, {"half width", "mm"}, {"a_Hertz", "mm"},
      {"resolved", "-"}, {"edge contact", "-"}, {"slave body", "-"}, {"radius pinion", "mm"},
      {"root stress pinion", "MPa"}, {"root radius pinion", "mm"}, {"root stress gear", "MPa"},
      {"root radius gear", "mm"}, {"friction force", "N"}, {"power loss", "W"}};
    const Columns pressure_columns = {{"torque", "N m"}, {"position", "-"}, {"roll angle", "deg"},
                                      {"pinion tooth", "-"}, {"s", "mm"}, {"radius", "mm"},
                                      {"p", "MPa"}};
    const Columns loa_columns = {{"point (1 A; 2 B; 3 C; 4 D; 5 E)", "-"}, {"roll angle", "deg"}};

    const char *required_sweep[] = {"torque", "roll angle", "STE"};

    /// Fill `out` (columns of `templ` present in group `name`) from the file.
    Table read_group(hid_t file, const Reader &r, const std::string &name, const Table &templ,
                     bool require_all, bool required_group)
    {
      const htri_t e = H5Lexists(file, name.c_str(), H5P_DEFAULT);
      if (e <= 0)
        {
          if (required_group)
            r.fail("/" + name, "", "missing", "a group of column datasets");
          return Table(templ);
        }
      Hid g(H5Gopen2(file, name.c_str(), H5P_DEFAULT), H5Gclose);
      if (!g.valid())
        r.fail("/" + name, "", "not a group or unreadable", "a group");
      Table out;
      std::vector<std::vector<double>> cols;
      const auto headers = templ.headers();
      for (std::size_t c = 0; c < templ.n_columns(); ++c)
        {
          const std::string ds = dataset_name(headers[c]);
          bool required = require_all;
          if (name == "sweep")
            for (const char *q : required_sweep)
              required = required || templ.name(c) == q;
          if (!required && H5Lexists(g.get(), ds.c_str(), H5P_DEFAULT) <= 0)
            continue;
          std::vector<hsize_t> dims;
          cols.push_back(r.dataset(g.get(), "/" + name, ds.c_str(), 1, dims));
          if (cols.size() > 1 && cols.back().size() != cols.front().size())
            r.fail("/" + name + "/" + ds, "", std::to_string(cols.back().size()) + " values",
                   std::to_string(cols.front().size()) + " (the length of the other columns)");
          out.add_column(templ.name(c), templ.unit(c));
        }
      const std::size_t n = cols.empty() ? 0 : cols.front().size();
      for (std::size_t i = 0; i < n; ++i)
        {
          std::vector<double> row(cols.size());
          for (std::size_t c = 0; c < cols.size(); ++c)
            row[c] = cols[c][i];
          out.add_row(row);
        }
      return out;
    }
  } // namespace

  std::string dataset_name(const std::string &header)
  {
    std::string out;
    for (const char c : header)
      out += c == '/' ? std::string(" per ") : std::string(1, c);
    return out;
  }

  SolveResults make_solve_results()
  {
    SolveResults r;
    r.sweep          = make_table(sweep_columns);
    r.pairs          = make_table(pair_columns);
    r.pressure       = make_table(pressure_columns);
    r.line_of_action = make_table(loa_columns);
    return r;
  }

  void write_table_file(const std::vector<std::pair<std::string, const Table *>> &tables,
                        const std::filesystem::path &file,
                        const std::map<std::string, std::string> &attributes,
                        const std::vector<std::tuple<std::string, std::string, std::vector<std::string>>>
                          &text_columns)
  {
    for (const auto &[name, table] : tables)
      {
        const auto h = table->headers();
        for (std::size_t i = 0; i < table->n_rows(); ++i)
          for (std::size_t c = 0; c < table->n_columns(); ++c)
            if (!std::isfinite(table->row(i)[c])) // the message only for a bad value: this loop is hot
              require_finite_output(table->row(i)[c], file.string(), "dataset '" + name + "/" + h[c] + "'");
      }
    const Writer w(file.string());
    const QuietHdf5 quiet;
    TemporaryPath tmp(file);
    {
      Hid f(H5Fcreate(tmp.path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      if (!f.valid())
        throw InputError("results file", file.string(), "a writable path in an existing folder",
                         "cannot create " + tmp.path().string());
      for (const auto &[k, v] : attributes)
        w.string_attribute(f.get(), k.c_str(), v);
      for (const auto &[name, table] : tables)
        {
          if (table->n_rows() == 0)
            continue;
          Hid g(w.ok_id(H5Gcreate2(f.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        "/" + name),
                H5Gclose);
          const auto h = table->headers();
          for (std::size_t c = 0; c < table->n_columns(); ++c)
            {
              std::vector<double> col(table->n_rows());
              for (std::size_t i = 0; i < table->n_rows(); ++i)
                col[i] = table->row(i)[c];
              w.dataset(g.get(), dataset_name(h[c]).c_str(), {hsize_t(col.size())}, col,
                        table->unit(c));
            }
        }
      for (const auto &[group, name, values] : text_columns)
        {
          const htri_t e = H5Lexists(f.get(), group.c_str(), H5P_DEFAULT);
          Hid g(w.ok_id(e > 0 ? H5Gopen2(f.get(), group.c_str(), H5P_DEFAULT) :
                                H5Gcreate2(f.get(), group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        "/" + group),
                H5Gclose);
          w.string_dataset(g.get(), dataset_name(name).c_str(), values);
        }
      w.ok(H5Fflush(f.get(), H5F_SCOPE_GLOBAL), "flush");
      w.ok(f.close(), "close");
    }
    tmp.commit();
  }

  void write_solve_results(const SolveResults &results, const std::filesystem::path &dir)
  {
    std::map<std::string, std::string> attributes = results.attributes;
    attributes["format"]         = solve_results_format;
    attributes["format_version"] = solve_results_format_version;
    const std::vector<std::pair<std::string, const Table *>> tables = {
      {"sweep", &results.sweep}, {"pairs", &results.pairs}, {"pressure", &results.pressure},
      {"line_of_action", &results.line_of_action}};
    // Check everything first, so that a bad value leaves no partial set of files.
    for (const auto &[name, table] : tables)
      {
        const auto h = table->headers();
        for (std::size_t i = 0; i < table->n_rows(); ++i)
          for (std::size_t c = 0; c < table->n_columns(); ++c)
            if (!std::isfinite(table->row(i)[c]))
              require_finite_output(table->row(i)[c], (dir / (name + ".csv")).string(), "column '" + h[c] + "'");
      }
    for (const auto &[name, table] : tables)
      table->write_csv(dir / (name + ".csv"));
    write_table_file(tables, dir / "results.h5", attributes);
  }

  SolveResults read_solve_results(const std::filesystem::path &file, bool require_all)
  {
    const std::string name = file.string();
    const std::string what = "a results.h5 of `gearfem solve` (docs/output-format.md)";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      throw InputError("results file", name, what, "file not found");
    const QuietHdf5 quiet;
    if (H5Fis_hdf5(name.c_str()) <= 0)
      throw InputError("results file", name, what, "not an HDF5 file (corrupt or wrong file)");
    Hid f(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!f.valid())
      throw InputError("results file", name, what, "cannot be opened: corrupt or truncated HDF5 file");
    const Reader r(name, "results file");
    const std::string format = r.string_attribute(f.get(), "/", "format");
    if (format != solve_results_format)
      r.fail("/", "format", format, solve_results_format, "not the results of `gearfem solve`");
    const std::string version = r.string_attribute(f.get(), "/", "format_version");
    if (version != solve_results_format_version)
      r.fail("/", "format_version", version, solve_results_format_version);
    SolveResults out = make_solve_results();
    out.attributes["format_version"] = version;
    for (const char *a : {"geometry_hash", "program", "method", "input"})
      if (H5Aexists(f.get(), a) > 0)
        out.attributes[a] = r.string_attribute(f.get(), "/", a);
    if (out.attributes.count("geometry_hash") == 0)
      r.fail("/", "geometry_hash", "missing", "the geometry hash of the pair");
    out.sweep    = read_group(f.get(), r, "sweep", out.sweep, require_all, true);
    out.pairs    = read_group(f.get(), r, "pairs", out.pairs, require_all, false);
    out.pressure = read_group(f.get(), r, "pressure", out.pressure, require_all, false);
    out.line_of_action = read_group(f.get(), r, "line_of_action", out.line_of_action, require_all, false);
    if (out.sweep.n_rows() == 0)
      r.fail("/sweep", "", "no rows", "at least one solved position");
    return out;
  }
} // namespace gearfem::io
