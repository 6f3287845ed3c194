#include "export/force_table.h"

#include "export/grid.h"

#include "base/errors.h"
#include "base/table.h"
#include "base/units.h"

#include <cmath>

namespace gearfem::exports
{
  ForceTable force_table(const io::MeshTable &t, double backlash, double reverse_offset, const std::string &parameter)
  {
    if (t.kind != io::MeshTable::Kind::torque_vs_compression)
      throw InputError("the force table needs a torque table T(theta, delta) (docs/mesh-tables.md); this table holds " +
                       std::string(io::value_quantity(t.kind)));
    ForceTable f;
    f.theta = t.theta, f.period = t.period;
    const double rb = t.base_radius;
    if (t.two_sided())
      {
        if (backlash >= 0 && std::abs(backlash - t.backlash) > 1e-9 * std::max(1e-6, t.backlash))
          throw InputError(parameter, to_string_g(backlash * 1e6) + " um",
                           "< 0 (take the table's) or the table's own " + to_string_g(t.backlash * 1e6) + " um",
                           "a two-sided table brings its backlash and back-contact branch");
        f.backlash = t.backlash, f.delta = t.second;
        f.force.resize(t.values.size());
        for (std::size_t k = 0; k < t.values.size(); ++k)
          f.force[k] = t.values[k] / rb;
        return f;
      }
    if (!(backlash >= 0))
      throw InputError(parameter, "(not set)", "0 to 5000 um",
                       "the table is one-sided (drive flanks only): the force table needs the clearance b along the "
                       "line of action to place the back-contact branch");
    f.backlash = backlash, f.reverse_offset = reverse_offset, f.mapped = true;
    const std::vector<double> &drive = t.second;
    f.delta = io::torque_table_axis(drive, backlash);
    const std::size_t n = t.theta.size(), m = f.delta.size(), md = drive.size();
    f.force.assign(n * m, 0.0);
    // Drive-side columns (the last md of the axis) and back columns (the first md, reversed).
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t d = 0; d < md; ++d)
        {
          f.force[i * m + (m - md) + d] = t.value(i, d) / rb;
          std::vector<double> col(n);
          for (std::size_t r = 0; r < n; ++r)
            col[r] = t.value(r, d);
          // Column index of delta = -b - drive[d] is md - 1 - d.
          f.force[i * m + (md - 1 - d)] = -periodic_linear(t.theta, col, t.period, reverse_offset - t.theta[i]) / rb;
        }
    return f;
  }

  void write_force_csv(const std::filesystem::path &file, const ForceTable &f)
  {
    Table t;
    t.add_column("roll angle", "deg");
    t.add_column("compression", "um");
    t.add_column("force", "N");
    t.add_column("contact (1 drive; 0 clearance; -1 back)", "-");
    for (std::size_t i = 0; i < f.theta.size(); ++i)
      for (std::size_t j = 0; j < f.delta.size(); ++j)
        {
          const double d = f.delta[j];
          const double s = d > 0 ? 1 : (d < -f.backlash * (1 + 1e-12) - 1e-18 ? -1 : 0);
          t.add_row({f.theta[i] / units::deg, d * 1e6, f.at(i, j), s});
        }
    t.write_csv(file, 17);
  }
} // namespace gearfem::exports
