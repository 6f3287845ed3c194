// The external mesh-force laws of `Dynamics/Mesh force/Law = external` (law_factory.h).
#include "dynamics/law_factory.h"
#include "base/units.h"

#include "analytical/from_geometry.h"
#include "analytical/mesh_cycle.h"
#include "analytical/ricker_load_sharing.h"
#include "base/errors.h"
#include "dynamics/ricker_law.h"
#include "geometry/pair.h"
#include "geometry/profile.h"
#include "io/mesh_table_io.h"

#include <cmath>

namespace gearfem::dynamics
{
  namespace dyn = gearfem::dynamics;

  geometry::GearPair generated_pair(const DynamicsCase &c)
  {
    auto gear = [&](int z, double cf, const char *name) {
      geometry::GearParameters g;
      g.name = name;
      g.teeth = z;
      g.face_width = c.face_width;
      g.rack.module = c.module;
      g.rack.pressure_angle = c.alpha;
      g.rack.addendum = c.addendum;
      g.thickness_allowance = (0.5 - cf) * units::pi * c.module;
      return g;
    };
    geometry::PairParameters pp;
    pp.center_distance = 0.5 * c.module * (c.z1 + c.z2) + c.delta_a;
    return geometry::GearPair(
      geometry::ToothProfile::generate(gear(c.z1, c.thickness1, "Dynamics/Pair (pinion)")),
      geometry::ToothProfile::generate(gear(c.z2, c.thickness2, "Dynamics/Pair (gear)")), pp);
  }

  namespace
  {
    /// Weber/Cornell pair compliance (lib/analytical, plane stress) of the generated pair.
    analytical::PairCompliance pair_compliance(const dyn::DynamicsCase &c,
                                               const geometry::GearPair &pair)
    {
      const analytical::Material mat{c.youngs_modulus, c.poisson_ratio};
      return analytical::pair_compliance(pair, mat, mat);
    }

    /// The torque table T(theta, delta) of Gkimisis 2019 (eqs. 3.10-3.17, with the
    /// corner contacts OA/BΓ) of the Weber/Cornell model (lib/analytical) on the generated
    /// pair, as a dynamics TableLaw:
    /// 128 positions over one mesh period from the start of contact A, 41 compressions on a
    /// geometric grid from 0 to 10 F_static / k_min (k_min: smallest secant mesh stiffness at
    /// F_static).
    std::shared_ptr<const dyn::MeshForceLaw> analytical_table(const dyn::DynamicsCase &c,
                                                              double &backlash,
                                                              std::vector<std::string> &notes)
    {
      const geometry::GearPair pair = generated_pair(c);
      // With the corner contacts OA/BΓ of Gkimisis 2019 (lib/analytical/corner.h): outside A..E a
      // pair carries load once the compression exceeds the rigid corner gap.
      const analytical::MeshModel mm = pair_compliance(c, pair).mesh_model(true);
      const double F = c.input_torque / mm.rb1;
      double kmin = 1e300;
      for (const auto &st : analytical::mesh_cycle(mm, F, 64))
        kmin = std::min(kmin, st.stiffness);
      dyn::MeshTable t;
      t.period = 2 * units::pi / c.z1;
      t.base_radius = mm.rb1;
      const double phiA = (mm.g_A - mm.g_C) / mm.rb1;
      const int nt = 128, nd = 41;
      for (int i = 0; i < nt; ++i)
        t.theta.push_back(phiA + t.period * i / nt);
      // Geometric grid of x (Gkimisis 2019): 0, then x_max 1e-3 q^(j-1) up to x_max = 10 F/k_min,
      // dense where the Hertz term and the corner contacts make T(x) curved.
      const double xmax = 10 * F / kmin, q = std::pow(1e3, 1.0 / (nd - 2));
      t.second.push_back(0.0);
      for (int j = 1; j < nd; ++j)
        t.second.push_back(j + 1 == nd ? xmax : xmax * 1e-3 * std::pow(q, j - 1));
      for (const auto &row : analytical::torque_table(mm, t.theta, t.second))
        t.values.insert(t.values.end(), row.begin(), row.end());
      t.require_covers_load(F);
      if (backlash < 0)
        backlash = pair.normal_backlash();
      notes.push_back("analytical torque table (Weber/Cornell, plane stress, corner contact OA/BG): 128 x 41 "
                     "(geometric delta grid), delta up to " +
                      to_string_g(10 * F / kmin * 1e6) + " um; generated-pair backlash " +
                      to_string_g(pair.normal_backlash() * 1e6) + " um");
      auto law = std::make_shared<dyn::TableLaw>(t, c.theta_interpolation);
      law->set_reference_load(F); // kbar = mean secant stiffness at the static load
      return law;
    }

    /// A mesh table from an HDF5 file (docs/mesh-tables.md), checked against this case:
    /// geometry hash (if given), period 2 pi/z1, base radius r_b1 of the pair and the
    /// static load inside the table.
    std::shared_ptr<const dyn::MeshForceLaw> table_file_law(const dyn::DynamicsCase &c,
                                                            double &backlash,
                                                            std::vector<std::string> &notes)
    {
      const std::string entry = "Dynamics/Mesh force/Table file";
      io::MeshTableFileInfo info;
      dyn::MeshTable t;
      try
        {
          t = io::read_mesh_table(c.table_file, c.table_hash, &info);
        }
      catch (const InputError &e)
        {
          throw InputError(entry + " = " + c.table_file + ": " + e.what());
        }
      const geometry::GearPair pair = generated_pair(c);
      const double period = 2 * units::pi / c.z1, rb1 = analytical::pair_line(pair).rb1;
      if (std::abs(t.period - period) > 1e-9 * period)
        throw InputError(entry, c.table_file + " (period " + to_string_g(t.period) + " rad)",
                         "period 2 pi/z1 = " + to_string_g(period) + " rad (Dynamics/Pair/Pinion teeth = " +
                           std::to_string(c.z1) + ")",
                         "the table belongs to a pinion with another number of teeth");
      if (std::abs(t.base_radius - rb1) > 1e-6 * rb1)
        throw InputError(entry, c.table_file + " (base radius " + to_string_g(t.base_radius * 1e3) + " mm)",
                         "r_b1 = " + to_string_g(rb1 * 1e3) + " mm of Dynamics/Pair",
                         "the table belongs to another module or pressure angle");
      const double F = c.input_torque / rb1;
      try
        {
          t.require_covers_load(F);
        }
      catch (const InputError &e)
        {
          throw InputError(entry + " = " + c.table_file + " does not cover Dynamics/Operating/Input torque = " +
                           to_string_g(c.input_torque) + " N m: " + e.what());
        }
      if (backlash < 0 && !t.two_sided()) // a two-sided table brings its own backlash
        backlash = pair.normal_backlash();
      const bool torque = t.kind == dyn::MeshTable::Kind::torque_vs_compression;
      notes.push_back(std::string("table file ") + c.table_file + ": " + (torque ? "T(theta, delta)" : "k(theta, F)") +
                      " " + std::to_string(t.theta.size()) + " x " + std::to_string(t.second.size()) +
                      ", valid " + to_string_g(info.valid_min * (torque ? 1e6 : 1)) + " .. " +
                      to_string_g(info.valid_max * (torque ? 1e6 : 1)) + (torque ? " um" : " N") +
                      (t.two_sided() ? ", two-sided (backlash " + to_string_g(t.backlash * 1e6) + " um)" : "") +
                      ", geometry hash " + (t.geometry_hash.empty() ? "(none)" : t.geometry_hash) +
                      (c.table_hash.empty() ? " (not checked)" : " (checked)") + ", source: " +
                      info.provenance.source);
      auto law = std::make_shared<dyn::TableLaw>(t, c.theta_interpolation);
      law->set_reference_load(F);
      return law;
    }

    /// Semi-analytical law of Gkimisis 2019 (eqs. 3.18-3.46): the closed-form pair stiffness of
    /// lib/analytical (RickerSemiAnalytical) with Ricker-wavelet load sharing
    /// (dynamics::RickerLoadSharingLaw). Its Hertz term is linearised with the mean mesh
    /// stiffness of the full Weber/Cornell model at the static load (eq. 3.30).
    std::shared_ptr<const dyn::MeshForceLaw> ricker_law(const dyn::DynamicsCase &c,
                                                        double &backlash,
                                                        std::vector<std::string> &notes)
    {
      const geometry::GearPair pair = generated_pair(c);
      const analytical::PairCompliance pc = pair_compliance(c, pair);
      const analytical::MeshModel mm = pc.mesh_model();
      const analytical::PairLine L = pc.line();
      const double F = c.input_torque / L.rb1;
      double kmean = 0;
      const auto cycle = analytical::mesh_cycle(mm, F, 64);
      for (const auto &st : cycle)
        kmean += st.stiffness / cycle.size();
      const analytical::Material mat{c.youngs_modulus, c.poisson_ratio};
      auto sa = std::make_shared<analytical::RickerSemiAnalytical>(
        analytical::involute_tooth(pair.gear(1)), analytical::involute_tooth(pair.gear(2)), mat, mat,
        c.face_width, L, kmean, pc.options(), c.ricker_widening);
      dyn::RickerLawParameters p;
      p.z1 = c.z1;
      p.omega_A = (L.g_A - L.g_C) / L.rb1;
      p.omega_B = (L.g_E - L.g_C) / L.rb1;
      p.c_x = c.ricker_widening;
      p.nominal_compression = F / kmean;
      p.second_pair = c.ricker_centred ? dyn::SecondPair::centred : dyn::SecondPair::thesis;
      const double gC = L.g_C, rb1 = L.rb1;
      auto law = std::make_shared<dyn::RickerLoadSharingLaw>(
        [sa, gC, rb1](double w1, double x) { return sa->pair_stiffness(gC + rb1 * w1, x); }, p);
      if (backlash < 0)
        backlash = pair.normal_backlash();
      notes.push_back("Gkimisis 2019 semi-analytical law: Hertz term linearised at kbar = " +
                      to_string_g(kmean / c.face_width / 1e9) + " N/(mm um) (Weber/Cornell mean at the "
                      "static load), c_x = " + to_string_g(c.ricker_widening / units::deg * 1e-3) +
                      " deg/mm, second pair " + (c.ricker_centred ? "centred" : "as eq. 3.45"));
      return law;
    }

  } // namespace

std::shared_ptr<const MeshForceLaw> external_law(const DynamicsCase &c, double &backlash,
                                                 std::vector<std::string> &notes)
  {
    switch (c.external_source)
      {
        case dyn::ExternalSource::table_file:
          return table_file_law(c, backlash, notes);
        case dyn::ExternalSource::ricker:
          return ricker_law(c, backlash, notes);
        default:
          return analytical_table(c, backlash, notes);
      }
  }
} // namespace gearfem::dynamics
