// condensed.h5: writer and reader of the condensed cycle (docs/output-format.md).
#include "condensed/cycle.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "io/hdf5_util.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::condensed
{
  namespace
  {
    using namespace io::hdf5;

    /// Columns of the candidate table, in order.
    constexpr const char *candidate_columns =
      "slave_body node slave_tooth master_tooth master_piece master_t slave_code master_code master_corner "
      "x y master_x master_y normal_x normal_y gap force pressure weight arm edge smooth";
    constexpr int n_candidate_columns = 22;

    std::string position_group(std::size_t k)
    {
      std::ostringstream s;
      s << "position_" << std::setw(4) << std::setfill('0') << k;
      return s.str();
    }

    int point_code(const std::string &n)
    {
      const std::string names = "ABCDE";
      const auto p            = n.size() == 1 ? names.find(n[0]) : std::string::npos;
      return p == std::string::npos ? 0 : int(p) + 1;
    }

    /// A compressed-row list: offsets (n + 1) and the flattened entries.
    template <typename Entry, typename Emit>
    void write_rows(const Writer &w, hid_t g, const std::string &prefix, const std::vector<std::vector<Entry>> &rows,
                    int n_fields, const std::vector<std::string> &units, Emit emit)
    {
      std::vector<double> offsets = {0.0};
      std::vector<std::vector<double>> fields(n_fields);
      for (const auto &r : rows)
        {
          for (const auto &e : r)
            emit(e, fields);
          offsets.push_back(double(fields[0].size()));
        }
      w.dataset(g, (prefix + "_offsets").c_str(), {offsets.size()}, offsets, "1");
      static const char *suffix[4][4] = {{"index", "value", "", ""}, {"body", "x", "y", "weight"}};
      for (int f = 0; f < n_fields; ++f)
        w.dataset(g, (prefix + "_" + suffix[n_fields == 4][f]).c_str(), {fields[f].size()}, fields[f], units[f]);
    }

    void write_body(const Writer &w, hid_t f, int b, const CycleBody &body)
    {
      const std::string name = "body" + std::to_string(b + 1);
      Hid g(w.ok_id(H5Gcreate2(f, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), name), H5Gclose);
      w.int_attribute(g.get(), "teeth", body.teeth);
      const std::size_t n = body.x.size();
      w.dataset(g.get(), "universe_x", {n}, body.x, "m");
      w.dataset(g.get(), "universe_y", {n}, body.y, "m");
      w.dataset(g.get(), "universe_component", {n}, std::vector<double>(body.component.begin(), body.component.end()),
                "1");
      const auto rows = hsize_t(body.stress.rows()), cols = hsize_t(body.stress.cols());
      std::vector<double> s(rows * cols);
      for (hsize_t i = 0; i < rows; ++i)
        for (hsize_t j = 0; j < cols; ++j)
          s[i * cols + j] = body.stress(Eigen::Index(i), Eigen::Index(j));
      w.dataset(g.get(), "stress", {rows, cols}, s, "Pa/N", "fillet stress influence (xx, yy, xy per sample)");
      w.dataset(g.get(), "stress_columns", {cols},
                std::vector<double>(body.stress_columns.begin(), body.stress_columns.end()), "1");
      std::vector<double> tooth, first, size, x, y, arc;
      for (const auto &fs : body.fillets)
        {
          tooth.push_back(fs.tooth), first.push_back(fs.first_row), size.push_back(double(fs.size()));
          x.insert(x.end(), fs.x.begin(), fs.x.end());
          y.insert(y.end(), fs.y.begin(), fs.y.end());
          arc.insert(arc.end(), fs.arc.begin(), fs.arc.end());
        }
      w.dataset(g.get(), "fillet_tooth", {tooth.size()}, tooth, "1");
      w.dataset(g.get(), "fillet_first_row", {first.size()}, first, "1");
      w.dataset(g.get(), "fillet_samples", {size.size()}, size, "1");
      w.dataset(g.get(), "fillet_x", {x.size()}, x, "m");
      w.dataset(g.get(), "fillet_y", {y.size()}, y, "m");
      w.dataset(g.get(), "fillet_arc", {arc.size()}, arc, "m");
    }

    void write_scene(const Writer &w, hid_t f, const std::string &name, const contact::CondensedPosition &p)
    {
      Hid g(w.ok_id(H5Gcreate2(f, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), name), H5Gclose);
      w.double_attribute(g.get(), "q_build", p.q_build);
      w.double_attribute(g.get(), "load_build", p.load_build);
      w.double_attribute(g.get(), "load_lo", p.load_lo);
      w.double_attribute(g.get(), "load_hi", p.load_hi);
      w.double_attribute(g.get(), "search_distance", p.search_distance);
      const hsize_t m = p.size();
      w.dataset(g.get(), "placement", {2, 3},
                {p.placement[0].centre.x(), p.placement[0].centre.y(), p.placement[0].angle,
                 p.placement[1].centre.x(), p.placement[1].centre.y(), p.placement[1].angle},
                "m, m, rad");
      std::vector<double> W(m * m);
      for (hsize_t i = 0; i < m; ++i)
        for (hsize_t j = 0; j < m; ++j)
          W[i * m + j] = p.W(Eigen::Index(i), Eigen::Index(j));
      w.dataset(g.get(), "W", {m, m}, W, "m/N", "Delassus operator");
      auto vec = [&](const char *n, const Eigen::VectorXd &v, const char *unit) {
        w.dataset(g.get(), n, {m}, std::vector<double>(v.data(), v.data() + v.size()), unit);
      };
      vec("a", p.a, "m/rad");
      vec("ghat", p.ghat, "m");
      vec("curvature", p.curvature, "m/rad^2");
      vec("D", p.D, "m/N");
      std::vector<double> table;
      for (const auto &c : p.cand)
        {
          const auto &q = c.point;
          table.insert(table.end(), {double(q.slave_body), double(q.node), double(q.slave_tooth),
                                     double(q.master_tooth), double(q.master_piece), q.master_t,
                                     double(q.slave_code), double(q.master_code), double(q.master_corner), q.x.x(),
                                     q.x.y(), q.master_point.x(), q.master_point.y(), q.normal.x(), q.normal.y(),
                                     q.gap, q.force, q.pressure, q.weight, q.arm, double(c.edge), double(c.smooth)});
        }
      w.dataset(g.get(), "candidates", {m, hsize_t(n_candidate_columns)}, table, "SI", candidate_columns);
      std::vector<double> approach;
      for (const auto &c : p.cand)
        approach.push_back(c.point.approach);
      w.dataset(g.get(), "approach", {m}, approach, "m/rad", "n . (v_S - v_M) per unit drive rotation at the build");
      using IV = std::pair<int, double>;
      const auto emit_iv = [](const IV &e, std::vector<std::vector<double>> &fl) {
        fl[0].push_back(e.first), fl[1].push_back(e.second);
      };
      write_rows(w, g.get(), "B1", p.B[0], 2, {"1", "1"}, emit_iv);
      write_rows(w, g.get(), "B2", p.B[1], 2, {"1", "1"}, emit_iv);
      write_rows(w, g.get(), "pressure", p.pressure, 2, {"1", "1/m^2"}, emit_iv);
      write_rows(w, g.get(), "modification", p.modification, 4, {"1", "m", "m", "1"},
                 [](const contact::ModificationSample &e, std::vector<std::vector<double>> &fl) {
                   fl[0].push_back(e.body), fl[1].push_back(e.x.x()), fl[2].push_back(e.x.y()),
                     fl[3].push_back(e.weight);
                 });
    }
  } // namespace

  void write_cycle(const CondensedCycle &c, const std::filesystem::path &file)
  {
    const Writer w(file.string());
    if (c.partial)
      throw InputError("condensed cycle output file", file.string(), "a cycle read in full",
                       "this cycle was read for a torque window only (read_cycle with torques)");
    const QuietHdf5 quiet;
    TemporaryPath tmp(file);
    {
      Hid f(H5Fcreate(tmp.path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      if (!f.valid())
        throw InputError("condensed cycle output file", file.string(), "a writable path in an existing folder");
      w.string_attribute(f.get(), "format", file_format);
      w.string_attribute(f.get(), "format_version", file_format_version);
      w.string_attribute(f.get(), "program", "gearfem condense");
      w.string_attribute(f.get(), "created", utc_now());
      w.string_attribute(f.get(), "model_key", c.key);
      w.string_attribute(f.get(), "geometry_hash", c.geometry_hash);
      w.string_attribute(f.get(), "input", c.input_name);
      if (!c.input_text.empty())
        w.string_attribute(f.get(), "input_text", c.input_text);
      w.string_attribute(f.get(), "method", c.method);
      w.double_attribute(f.get(), "build_torque", c.build_torque);
      w.double_attribute(f.get(), "torque_lo", c.torque_lo);
      w.double_attribute(f.get(), "torque_hi", c.torque_hi);
      w.double_attribute(f.get(), "setup_seconds", c.setup_seconds);
      w.double_attribute(f.get(), "build_seconds", c.build_seconds);
      w.int_attribute(f.get(), "dofs", c.dofs);
      std::vector<double> phi, code;
      for (const auto &[n, p] : c.positions)
        phi.push_back(p), code.push_back(point_code(n));
      w.dataset(f.get(), "roll_angle", {phi.size()}, phi, "rad");
      w.dataset(f.get(), "point_code", {code.size()}, code, "1", "0 none, 1..5 A..E");
      for (int b = 0; b < 2; ++b)
        write_body(w, f.get(), b, c.body[b]);
      for (std::size_t k = 0; k < c.cycle.size(); ++k)
        {
          const std::string name = position_group(k);
          Hid g(w.ok_id(H5Gcreate2(f.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), name), H5Gclose);
          w.int_attribute(g.get(), "scenes", int(c.cycle[k].size()));
          for (std::size_t s = 0; s < c.cycle[k].size(); ++s)
            write_scene(w, g.get(), "scene_" + std::to_string(s), c.cycle[k][s]);
        }
      w.ok(H5Fflush(f.get(), H5F_SCOPE_GLOBAL), "flush");
      w.ok(f.close(), "close");
    }
    tmp.commit();
  }
} // namespace gearfem::condensed
