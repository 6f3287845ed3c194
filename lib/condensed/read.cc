// condensed.h5: the reader (docs/output-format.md).
#include "condensed/cycle.h"

#include "base/errors.h"
#include "io/hdf5_util.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::condensed
{
  namespace
  {
    using namespace io::hdf5;

    class GroupReader
    {
    public:
      GroupReader(const Reader &r, hid_t parent, const std::string &path, const std::string &name)
        : r_(r)
        , path_(path + "/" + name)
        , g_(H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0 ? H5Gopen2(parent, name.c_str(), H5P_DEFAULT) : -1,
             H5Gclose)
      {
        if (!g_.valid())
          r_.fail(path_, "", "missing or not a group", "a group");
      }
      std::vector<double> vec(const char *name, std::size_t n = std::size_t(-1)) const
      {
        std::vector<hsize_t> dims;
        auto v = r_.dataset(g_.get(), path_, name, 1, dims);
        if (n != std::size_t(-1) && v.size() != n)
          r_.fail(path_ + "/" + name, "", std::to_string(v.size()) + " values", std::to_string(n) + " values");
        return v;
      }
      std::vector<double> mat(const char *name, std::size_t rows, std::size_t cols) const
      {
        std::vector<hsize_t> dims;
        auto v = r_.dataset(g_.get(), path_, name, 2, dims);
        if ((rows != std::size_t(-1) && dims[0] != rows) || (cols != std::size_t(-1) && dims[1] != cols))
          r_.fail(path_ + "/" + name, "", std::to_string(dims[0]) + " x " + std::to_string(dims[1]),
                  (rows == std::size_t(-1) ? std::string("n") : std::to_string(rows)) + " x " +
                    (cols == std::size_t(-1) ? std::string("n") : std::to_string(cols)));
        last_dims = dims;
        return v;
      }
      /// Compressed rows `prefix`_offsets with fields `names` (equal lengths); n rows. Returns the
      /// fields and the offsets (n + 1, non-decreasing, within the fields), with the first field
      /// checked as an index in [0, range) when range > 0.
      std::pair<std::vector<std::vector<double>>, std::vector<std::size_t>>
      rows(const std::string &prefix, const std::vector<std::string> &names, std::size_t n, std::size_t range) const
      {
        const auto off = vec((prefix + "_offsets").c_str(), n + 1);
        std::vector<std::vector<double>> fields;
        for (const auto &f : names)
          {
            fields.push_back(vec((prefix + "_" + f).c_str()));
            if (fields.back().size() != fields[0].size())
              r_.fail(path_ + "/" + prefix, "", "fields of different lengths", "equal lengths");
          }
        const std::size_t total = fields.empty() ? 0 : fields[0].size();
        std::vector<std::size_t> offsets(n + 1, 0);
        for (std::size_t i = 0; i <= n; ++i)
          {
            if (!(off[i] >= 0 && off[i] <= double(total) && (i == 0 || off[i] >= off[i - 1])))
              r_.fail(path_ + "/" + prefix + "_offsets", "", "not non-decreasing within the entries",
                      "offsets of compressed rows");
            offsets[i] = std::size_t(off[i]);
          }
        if (range > 0)
          for (std::size_t k = offsets[0]; k < offsets[n]; ++k)
            {
              const double e = fields[0][k];
              if (!(e >= 0 && e < double(range) && e == std::floor(e)))
                r_.fail(path_ + "/" + prefix + "_" + names[0], "", to_string_g(e),
                        "an index in [0, " + std::to_string(range) + ")");
            }
        return {std::move(fields), std::move(offsets)};
      }
      hid_t get() const { return g_.get(); }
      const std::string &path() const { return path_; }
      mutable std::vector<hsize_t> last_dims;

    private:
      const Reader &r_;
      std::string path_;
      Hid g_;
    };

    std::vector<std::vector<std::pair<int, double>>> index_value(const GroupReader &g, const std::string &prefix,
                                                                 std::size_t n, std::size_t range)
    {
      std::vector<std::vector<std::pair<int, double>>> out(n);
      const auto [f, off] = g.rows(prefix, {"index", "value"}, n, range);
      for (std::size_t i = 0; i < n; ++i)
        {
          out[i].reserve(off[i + 1] - off[i]);
          for (std::size_t k = off[i]; k < off[i + 1]; ++k)
            out[i].emplace_back(int(f[0][k]), f[1][k]);
        }
      return out;
    }

    void read_body(const Reader &r, hid_t f, int b, CycleBody &body)
    {
      const GroupReader g(r, f, "", "body" + std::to_string(b + 1));
      body.teeth = int(r.integer_attribute(g.get(), g.path(), "teeth", "an integer"));
      body.x     = g.vec("universe_x");
      body.y     = g.vec("universe_y", body.x.size());
      for (const double c : g.vec("universe_component", body.x.size()))
        body.component.push_back(int(c));
      const auto cols = g.vec("stress_columns");
      for (const double c : cols)
        {
          if (!(c >= 0 && c < double(body.x.size())))
            r.fail(g.path() + "/stress_columns", "", to_string_g(c), "a universe index");
          body.stress_columns.push_back(int(c));
        }
      const auto s = g.mat("stress", std::size_t(-1), cols.size());
      const auto rows = Eigen::Index(g.last_dims[0]), nc = Eigen::Index(cols.size());
      body.stress.resize(rows, nc);
      for (Eigen::Index i = 0; i < rows; ++i)
        for (Eigen::Index j = 0; j < nc; ++j)
          body.stress(i, j) = s[std::size_t(i * nc + j)];
      const auto tooth = g.vec("fillet_tooth"), first = g.vec("fillet_first_row", tooth.size()),
                 size = g.vec("fillet_samples", tooth.size());
      const auto x = g.vec("fillet_x"), y = g.vec("fillet_y", x.size()), arc = g.vec("fillet_arc", x.size());
      std::size_t at = 0;
      for (std::size_t t = 0; t < tooth.size(); ++t)
        {
          FilletSamples fs;
          fs.tooth     = int(tooth[t]);
          fs.first_row = int(first[t]);
          const auto n = std::size_t(size[t]);
          if (at + n > x.size() || fs.first_row < 0 || Eigen::Index(fs.first_row + 3 * n) > rows)
            r.fail(g.path() + "/fillet_samples", "", "more samples than stored", "consistent fillet tables");
          fs.x.assign(x.begin() + long(at), x.begin() + long(at + n));
          fs.y.assign(y.begin() + long(at), y.begin() + long(at + n));
          fs.arc.assign(arc.begin() + long(at), arc.begin() + long(at + n));
          at += n;
          body.fillets.push_back(std::move(fs));
        }
    }

    contact::CondensedPosition read_scene(const Reader &r, hid_t f, const std::string &path, const std::string &name,
                                          const std::size_t universe[2])
    {
      const GroupReader g(r, f, path, name);
      contact::CondensedPosition p;
      p.q_build    = r.double_attribute(g.get(), g.path(), "q_build", "rad");
      p.load_build = r.double_attribute(g.get(), g.path(), "load_build", "N m");
      p.load_lo    = r.double_attribute(g.get(), g.path(), "load_lo", "N m");
      p.load_hi    = r.double_attribute(g.get(), g.path(), "load_hi", "N m");
      p.search_distance = r.double_attribute(g.get(), g.path(), "search_distance", "m");
      const auto pl = g.mat("placement", 2, 3);
      for (int b = 0; b < 2; ++b)
        p.placement[b] = {contact::Vec2(pl[3 * b], pl[3 * b + 1]), pl[3 * b + 2]};
      const auto a = g.vec("a");
      const std::size_t m = a.size();
      // W straight into its matrix: the file is row-major, the matrix column-major, and the
      // in-place transpose of the square matrix restores it exactly.
      std::vector<hsize_t> wd;
      r.dataset_into(g.get(), g.path(), "W", 2, wd, [&](hsize_t n) {
        if (n != hsize_t(m) * hsize_t(m))
          r.fail(g.path() + "/W", "", std::to_string(n) + " values", std::to_string(m) + " x " + std::to_string(m));
        p.W.resize(Eigen::Index(m), Eigen::Index(m));
        return p.W.data();
      });
      if (wd[0] != m || wd[1] != m)
        r.fail(g.path() + "/W", "", std::to_string(wd[0]) + " x " + std::to_string(wd[1]),
               std::to_string(m) + " x " + std::to_string(m));
      p.W.transposeInPlace();
      auto ev = [&](const char *n) {
        const auto v = g.vec(n, m);
        return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(m)));
      };
      p.a = ev("a"), p.ghat = ev("ghat"), p.curvature = ev("curvature"), p.D = ev("D");
      const auto t = g.mat("candidates", m, 22);
      p.cand.resize(m);
      for (std::size_t k = 0; k < m; ++k)
        {
          const double *c = t.data() + 22 * k;
          auto &q         = p.cand[k].point;
          if (!(c[0] == 1 || c[0] == 2))
            r.fail(g.path() + "/candidates", "", "slave body " + to_string_g(c[0]), "1 | 2");
          q.slave_body = int(c[0]), q.node = int(c[1]), q.slave_tooth = int(c[2]), q.master_tooth = int(c[3]);
          q.master_piece = int(c[4]), q.master_t = c[5];
          q.slave_code = unsigned(c[6]), q.master_code = unsigned(c[7]), q.master_corner = c[8] != 0;
          q.x = contact::Vec2(c[9], c[10]), q.master_point = contact::Vec2(c[11], c[12]);
          q.normal = contact::Vec2(c[13], c[14]);
          q.gap = c[15], q.force = c[16], q.pressure = c[17], q.weight = c[18], q.arm = c[19];
          p.cand[k].edge = c[20] != 0, p.cand[k].smooth = c[21] != 0;
        }
      // The approach of each candidate at the build (normal-force power); files written before
      // it was kept have none: 0, the normal-force power then reads 0.
      if (H5Lexists(g.get(), "approach", H5P_DEFAULT) > 0)
        {
          const auto approach = g.vec("approach", m);
          for (std::size_t k = 0; k < m; ++k)
            p.cand[k].point.approach = approach[k];
        }
      p.B[0]     = index_value(g, "B1", m, universe[0]);
      p.B[1]     = index_value(g, "B2", m, universe[1]);
      p.pressure = index_value(g, "pressure", m, m);
      p.modification.assign(m, {});
      const auto [mod, off] = g.rows("modification", {"body", "x", "y", "weight"}, m, 0);
      for (std::size_t k = 0; k < m; ++k)
        for (std::size_t e = off[k]; e < off[k + 1]; ++e)
          {
            if (!(mod[0][e] == 1 || mod[0][e] == 2))
              r.fail(g.path() + "/modification_body", "", to_string_g(mod[0][e]), "1 | 2");
            p.modification[k].push_back({int(mod[0][e]), contact::Vec2(mod[1][e], mod[2][e]), mod[3][e]});
          }
      return p;
    }
  } // namespace

  CondensedCycle read_cycle(const std::filesystem::path &file) { return read_cycle(file, {}); }

  CondensedCycle read_cycle(const std::filesystem::path &file, const std::vector<double> &torques)
  {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      throw InputError("condensed cycle file", name, "an existing condensed.h5 (gearfem condense)",
                       "file not found or not a file");
    const QuietHdf5 quiet;
    if (H5Fis_hdf5(name.c_str()) <= 0)
      throw InputError("condensed cycle file", name, "an HDF5 condensed cycle", "not an HDF5 file, or corrupt");
    Hid f(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!f.valid())
      throw InputError("condensed cycle file", name, "a readable HDF5 file", "corrupt or truncated");
    const Reader r(name, "condensed cycle file");
    const std::string format = r.string_attribute(f.get(), "/", "format");
    if (format != file_format)
      r.fail("/", "format", format, file_format, "not a gearfem condensed cycle");
    const std::string version = r.string_attribute(f.get(), "/", "format_version");
    if (version != file_format_version)
      r.fail("/", "format_version", version, file_format_version,
             "this gearfem reads condensed-cycle format version " + std::string(file_format_version));
    CondensedCycle c;
    c.key           = r.string_attribute(f.get(), "/", "model_key");
    c.geometry_hash = r.string_attribute(f.get(), "/", "geometry_hash");
    c.input_name    = r.string_attribute(f.get(), "/", "input");
    if (H5Aexists(f.get(), "input_text") > 0)
      c.input_text = r.string_attribute(f.get(), "/", "input_text");
    c.method        = r.string_attribute(f.get(), "/", "method");
    c.build_torque  = r.double_attribute(f.get(), "/", "build_torque", "N m");
    c.torque_lo     = r.double_attribute(f.get(), "/", "torque_lo", "N m");
    c.torque_hi     = r.double_attribute(f.get(), "/", "torque_hi", "N m");
    c.setup_seconds = r.double_attribute(f.get(), "/", "setup_seconds", "s");
    c.build_seconds = r.double_attribute(f.get(), "/", "build_seconds", "s");
    c.dofs          = int(r.integer_attribute(f.get(), "/", "dofs", "an integer"));
    std::vector<hsize_t> dims;
    const auto phi  = r.dataset(f.get(), "", "roll_angle", 1, dims);
    const auto code = r.dataset(f.get(), "", "point_code", 1, dims);
    if (code.size() != phi.size())
      r.fail("/point_code", "", std::to_string(code.size()) + " values", std::to_string(phi.size()) + " values");
    for (std::size_t k = 0; k < phi.size(); ++k)
      {
        const int pc = int(code[k]);
        c.positions.emplace_back(pc >= 1 && pc <= 5 ? std::string(1, "ABCDE"[pc - 1]) : std::string(), phi[k]);
      }
    for (int b = 0; b < 2; ++b)
      read_body(r, f.get(), b, c.body[b]);
    const std::size_t universe[2] = {c.body[0].x.size(), c.body[1].x.size()};
    // The torque window of a partial read, where it lies inside the stored range.
    double want_lo = c.torque_lo, want_hi = c.torque_hi;
    if (!torques.empty())
      {
        const auto [lo, hi] = std::minmax_element(torques.begin(), torques.end());
        if (*lo >= c.torque_lo * (1 - 1e-12) && *hi <= c.torque_hi * (1 + 1e-12) && *lo <= *hi)
          {
            want_lo = std::max(c.torque_lo, *lo), want_hi = std::min(c.torque_hi, *hi);
            c.partial = want_lo > c.torque_lo || want_hi < c.torque_hi;
            c.torque_lo = want_lo, c.torque_hi = want_hi;
          }
      }
    for (std::size_t k = 0; k < phi.size(); ++k)
      {
        std::ostringstream n;
        n << "position_" << std::setw(4) << std::setfill('0') << k;
        const GroupReader g(r, f.get(), "", n.str());
        const long long ns = r.integer_attribute(g.get(), g.path(), "scenes", "an integer >= 1");
        if (ns < 1 || ns > 1000)
          r.fail(g.path(), "scenes", std::to_string(ns), "1..1000");
        c.cycle.emplace_back();
        for (long long s = 0; s < ns; ++s)
          {
            const std::string scene = "scene_" + std::to_string(s);
            if (c.partial)
              {
                const GroupReader sg(r, g.get(), g.path(), scene);
                const double lo = r.double_attribute(sg.get(), sg.path(), "load_lo", "N m"),
                             hi = r.double_attribute(sg.get(), sg.path(), "load_hi", "N m");
                // Scenes are ascending; CondensedCycle::at gives the first one every torque
                // below its range and the last one every torque above.
                if ((hi < want_lo * (1 - 1e-12) && s + 1 < ns) || (lo > want_hi * (1 + 1e-12) && s > 0))
                  continue;
              }
            c.cycle.back().push_back(read_scene(r, g.get(), g.path(), scene, universe));
          }
        if (c.cycle.back().empty())
          r.fail(g.path(), "scenes", "none for " + to_string_g(want_lo) + " .. " + to_string_g(want_hi) + " N m",
                 "scenes covering the torque range");
      }
    return c;
  }
} // namespace gearfem::condensed
