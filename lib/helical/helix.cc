#include "helical/helix.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>

namespace gearfem::helical
{
  double LeadModification::mesh_misalignment(double alpha_wt) const
  {
    return slope + misalignment * std::cos(alpha_wt) + deviation * std::sin(alpha_wt);
  }

  geometry::GeometryInput transverse_section(const geometry::GeometryInput &normal, double beta)
  {
    geometry::GeometryInput t = normal;
    const double cb = std::cos(beta);
    for (geometry::GearParameters *g : {&t.gear1, &t.gear2})
      {
        auto &r = g->rack;
        if (r.kind != geometry::RackParameters::Kind::standard)
          throw InputError("Rack/Profile type", "a B-spline profile", "standard (Helical/Rack section = normal)",
                           "the normal section of a B-spline rack is not defined; give the transverse section "
                           "with Helical/Rack section = transverse");
        r.pressure_angle = std::atan(std::tan(r.pressure_angle) / cb);
        r.module /= cb;
        // Lengths in normal modules keep their length: coefficient * m_n = coefficient_t * m_t.
        r.addendum *= cb, r.dedendum *= cb, r.root_radius *= cb, r.tip_radius *= cb;
        g->profile_shift *= cb;
        g->tip_shortening *= cb;
        g->thickness_allowance /= cb;
      }
    return t;
  }

  Helix helix(const HelixInput &in, double m_t, double alpha_t, double r_b1, double b)
  {
    Helix h;
    h.beta       = in.beta;
    h.m_t        = m_t;
    h.m_n        = m_t * std::cos(in.beta);
    h.alpha_t    = alpha_t;
    h.alpha_n    = std::atan(std::tan(alpha_t) * std::cos(in.beta));
    h.beta_b     = std::atan(std::tan(in.beta) * std::cos(alpha_t));
    h.face_width = b;
    h.axial_pitch   = in.beta > 0 ? M_PI * h.m_n / std::sin(in.beta) : INFINITY;
    h.overlap_ratio = b * std::sin(in.beta) / (M_PI * h.m_n);
    h.roll_per_length = in.hand * std::tan(h.beta_b) / r_b1;
    return h;
  }

  std::vector<double> slice_centres(double b, int n)
  {
    std::vector<double> z(std::size_t(std::max(n, 0)));
    for (int k = 0; k < n; ++k)
      z[std::size_t(k)] = -0.5 * b + (k + 0.5) * b / n;
    return z;
  }

  double lead_gap(const LeadModification &m, double z, double b, double alpha_wt)
  {
    const double u = 2 * z / b; // -1 .. 1
    double g       = m.crowning * u * u;
    if (m.end_relief > 0 && m.end_relief_length > 0)
      g += m.end_relief * std::max(0.0, (std::abs(z) - (0.5 * b - m.end_relief_length)) / m.end_relief_length);
    const double f = m.mesh_misalignment(alpha_wt);
    g += f >= 0 ? f * (0.5 * u + 0.5) : f * (0.5 * u - 0.5);
    const auto &pz = m.profile_z, &pg = m.profile_gap;
    if (!pz.empty())
      {
        if (z <= pz.front())
          g += pg.front();
        else if (z >= pz.back())
          g += pg.back();
        else
          {
            const std::size_t i = std::size_t(std::upper_bound(pz.begin(), pz.end(), z) - pz.begin());
            const double t = (z - pz[i - 1]) / (pz[i] - pz[i - 1]);
            g += (1 - t) * pg[i - 1] + t * pg[i];
          }
      }
    return g;
  }

  void check_profile(const LeadModification &m, double b)
  {
    if (m.profile_z.size() != m.profile_gap.size())
      throw InputError("lead profile", std::to_string(m.profile_gap.size()) + " gaps",
                       "one per position (" + std::to_string(m.profile_z.size()) + ")");
    for (std::size_t i = 0; i < m.profile_z.size(); ++i)
      {
        if (!(std::abs(m.profile_z[i]) <= 0.5 * b * (1 + 1e-12)) || (i > 0 && !(m.profile_z[i] > m.profile_z[i - 1])))
          throw InputError("lead profile position", to_string_g(m.profile_z[i] / units::mm) + " mm",
                           "increasing, within -b/2 to b/2 (" + to_string_g(0.5 * b / units::mm) + " mm)");
        if (!(std::abs(m.profile_gap[i]) < 1e-2))
          throw InputError("lead profile gap", to_string_g(m.profile_gap[i] / units::um) + " um", "finite, below 10 mm");
      }
  }

  void check(const HelixInput &in, double b)
  {
    require_range("Helical/Helix angle", in.beta / units::deg, 0.0, 45.0, "deg");
    if (!(in.beta / units::deg < 45.0))
      throw InputError("Helical/Helix angle", to_string_g(in.beta / units::deg) + " deg", "0 to < 45 deg");
    if (in.slices < 1 || in.slices > 201)
      throw InputError("Helical/Slices", std::to_string(in.slices), "1 to 201");
    if (in.coupling_length > b)
      throw InputError("Helical/Coupling length", to_string_g(in.coupling_length / units::mm) + " mm",
                       "-1 (one normal module), 0 (uncoupled) or up to the face width " + to_string_g(b / units::mm) +
                         " mm");
    if (in.model == FaceModel::solid)
      {
        const auto &d = in.solid;
        if (d.element_size < 0)
          throw InputError("Helical/3-D element size", to_string_g(d.element_size / units::mm) + " mm", "0 (m_n/3) or > 0");
        if (d.layers_per_slice < 1 || d.layers_per_slice * in.slices > 400)
          throw InputError("Helical/3-D layers per slice", std::to_string(d.layers_per_slice),
                           "1 to " + std::to_string(std::max(1, 400 / in.slices)) + " (400 layers over the face)");
        if (d.flank_points < 2 || d.flank_points > 50)
          throw InputError("Helical/3-D flank points", std::to_string(d.flank_points), "2 to 50");
        if (d.sector_teeth < 1 || d.sector_teeth > 9 || d.sector_teeth % 2 == 0)
          throw InputError("Helical/3-D sector teeth", std::to_string(d.sector_teeth), "odd, 1 to 9");
      }
    const auto &m = in.lead;
    check_profile(m, b);
    require_range("Helical/Crowning", m.crowning / units::um, 0.0, 1000.0, "um");
    require_range("Helical/End relief", m.end_relief / units::um, 0.0, 1000.0, "um");
    require_range("Helical/End relief length", m.end_relief_length / units::mm, 0.0, 0.5 * b / units::mm, "mm");
    if (m.end_relief > 0 && !(m.end_relief_length > 0))
      throw InputError("Helical/End relief length", "0 mm", "> 0 mm and <= b/2 = " + to_string_g(0.5 * b / units::mm) +
                                                              " mm", "an end relief needs its length");
    for (const auto &[name, v] : {std::pair<const char *, double>{"Helical/Helix slope deviation", m.slope},
                                  {"Helical/Misalignment", m.misalignment},
                                  {"Helical/Axis deviation", m.deviation}})
      require_range(name, v / units::um, -1000.0, 1000.0, "um");
  }
} // namespace gearfem::helical
