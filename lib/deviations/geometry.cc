// Single pitch deviations as turned teeth of the mesh.
#include "deviations/geometry.h"

#include "base/errors.h"
#include "base/number.h"
#include "mesh/gear_mesh.h"
#include "deviations/hunting.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gearfem::deviations
{
  void check_geometry_model(const DeviationParameters &p)
  {
    const auto allowed = [](const std::string &value) {
      return value + " with Deviations/Model = geometry: only single pitch deviations are built into the mesh "
                     "(Model = condensed takes every kind)";
    };
    if (p.grade > 0)
      throw InputError("Deviations/Accuracy grade", std::to_string(p.grade), allowed("0"));
    if (p.pitches > 0)
      throw InputError("Deviations/Pitches", std::to_string(p.pitches),
                       "hunting (unused with Deviations/Model = geometry: the positions are those of the Solve "
                       "section)");
    const auto nonzero = [](const std::vector<double> &v) {
      return std::any_of(v.begin(), v.end(), [](double x) { return x != 0; });
    };
    for (int b = 0; b < 2; ++b)
      {
        const auto &g        = p.gear[b];
        const std::string s  = "Deviations/Gear " + std::to_string(b + 1) + "/";
        const auto um        = [](double x) { return to_string_g(x * 1e6) + " um"; };
        if (nonzero(g.f_Ha))
          throw InputError(s + "Profile slope deviation", "non-zero", allowed("none"));
        for (const auto &f : g.form)
          if (f.kind == geometry::ProfileForm::Kind::table ||
              (f.kind == geometry::ProfileForm::Kind::parabolic && f.amplitude != 0))
            throw InputError(s + "Profile form", f.kind == geometry::ProfileForm::Kind::table ? "table" : "parabolic",
                             allowed("none"));
        if (g.flank_offset != 0)
          throw InputError(s + "Flank offset", um(g.flank_offset), allowed("0"));
        if (g.eccentricity != 0)
          throw InputError(s + "Runout", um(2 * g.eccentricity), allowed("0"));
      }
  }

  std::array<std::vector<double>, 2> tooth_angles(const DeviationParameters &p, const geometry::GearPair &pair,
                                                  const geometry::GearPair &meshed)
  {
    check_geometry_model(p);
    const geometry::PairDeviations d = pair_deviations(pair, p.gear[0], p.gear[1]);
    std::array<std::vector<double>, 2> angles;
    for (int b = 0; b < 2; ++b)
      {
        if (d.cumulative[b].empty())
          continue;
        const auto &tooth  = meshed.gear(b + 1);
        const int z        = tooth.teeth();
        const double r_ref = 0.5 * tooth.parameters().rack.module * z;
        const double w     = mesh::max_tooth_angle_step(tooth);
        const std::string entry = "Deviations/Gear " + std::to_string(b + 1) + "/Single pitch deviations";
        if (w == 0)
          throw InputError("Deviations/Model", "geometry",
                           "condensed for gear " + std::to_string(b + 1) + " (pitch deviations in the geometry need "
                           "a root land arc between the teeth)",
                           "its fillets meet at a point, where turned teeth would overlap or leave a gap");
        // delta_k - delta_(k-1) = f_pt,k / r_ref: each root land gives or takes half of it.
        const auto &f = p.gear[b].f_pt;
        for (std::size_t k = 0; k < f.size(); ++k)
          if (std::abs(f[k]) > w * r_ref)
            throw InputError(entry, "f_pt," + std::to_string(k) + " = " + to_string_g(f[k] * 1e6) + " um",
                             "within +-" + to_string_g(w * r_ref * 1e6) + " um with Deviations/Model = geometry",
                             "neighbouring turned teeth meet on their root lands, which keep at least half their "
                             "length");
        angles[b].resize(std::size_t(z));
        for (int k = 0; k < z; ++k)
          angles[b][std::size_t(k)] = d.tooth_rotation(b + 1, k);
        mesh::check_tooth_angles(tooth, angles[b], entry);
      }
    return angles;
  }
} // namespace gearfem::deviations
