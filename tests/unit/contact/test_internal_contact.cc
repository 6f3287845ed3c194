// Contact of an external pinion inside a ring (geometry::InternalGearPair, the ring meshed by
// mesh/ring_domain): the unloaded placement puts both drive flanks through C; the loaded
// contact balances the torques as the kinematics require (frictionless forces on the line
// of action: T2 = T1 r_b2/r_b1, a conservation law); the pitch-point pressure of the
// concave-convex contact matches Hertz with the relative curvature 1/rho1 - 1/rho2 (Johnson
// 1985, eqs. 4.43-4.45); the transmission error is positive and its stiffness lies between
// the ISO 6336-1 single stiffness c' bounds of a steel mesh.
#include "base/errors.h"
#include "base/units.h"
#include "contact/gear_contact.h"
#include "post/position.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace gearfem;
using geometry::Vec2;
using units::deg;
using units::mm;
using units::pi;

namespace
{
  /// Pinion z 24 and ring z 60, m 2 mm, 20 deg, x 0.3 / -0.4 (ISO 21771 sign), b 20 mm; the
  /// ring cut by a 20-tooth shaper.
  struct Case
  {
    std::unique_ptr<geometry::InternalGearPair> pair;
    Case(double h_contact)
    {
      geometry::GearParameters p;
      p.name = "Gear 1", p.teeth = 24, p.profile_shift = 0.3, p.face_width = 20 * mm;
      p.rack.module = 2 * mm, p.rack.pressure_angle = 20 * deg;
      geometry::InternalGearParameters r;
      r.name = "Gear 2", r.teeth = 60, r.module = 2 * mm, r.pressure_angle = 20 * deg, r.profile_shift = -0.4;
      r.cutter.teeth = 20, r.cutter.shift = 0.0;
      pair = std::make_unique<geometry::InternalGearPair>(geometry::ToothProfile::generate(p),
                                                          geometry::InternalToothProfile::generate(r));
      pinion.model = mesh::GearMeshParameters::Model::sector, pinion.sector_teeth = 5;
      pinion.h_contact = h_contact, pinion.h_fillet = 0.2 * mm, pinion.h_body = 2 * mm, pinion.fine_teeth = "-1,0,1";
      ring.model = mesh::RingMeshParameters::Model::sector, ring.sector_teeth = 5;
      ring.h_contact = h_contact, ring.h_fillet = 0.2 * mm, ring.h_body = 2 * mm, ring.fine_teeth = "-1,0,1";
      for (auto &m : material)
        m.youngs_modulus = 206e9, m.poisson_ratio = 0.3, m.thickness = 20 * mm;
      fe.degree = 2;
    }
    mesh::GearMeshParameters pinion;
    mesh::RingMeshParameters ring;
    fem::Elasticity material[2];
    fem::FeOptions fe;
  };

  /// Least signed distance [m] of the drive half of pinion tooth k's sampled outline from the ring's (polyline
  /// through its samples), both placed at phi1 (negative: inside the ring material).
  double unloaded_gap(const geometry::InternalGearPair &pair, double phi1, int k = 0)
  {
    const auto P1 = pair.placement(1, phi1), P2 = pair.placement(2, phi1);
    const double turn = 2 * pi * k / pair.teeth(1);
    std::vector<Vec2> tooth;
    for (const auto &p : pair.pinion().sample(0.01 * mm))
      if (p.p.x() <= 0) // the drive (left) half of the tooth
        tooth.push_back(P1.apply(Eigen::Rotation2Dd(turn) * p.p));
    const Vec2 tip = P1.apply(Eigen::Rotation2Dd(turn) * Vec2(0, pair.pinion().radii().tip));
    std::vector<Vec2> ring, rn;
    for (const auto &q : pair.ring().sample_gear(0.01 * mm))
      if ((P2.apply(q.p) - tip).norm() < 8 * mm)
        ring.push_back(P2.apply(q.p)), rn.push_back(P2.apply_vector(q.normal));
    double best = 1e9;
    for (const Vec2 &x : tooth)
      for (std::size_t j = 0; j + 1 < ring.size(); ++j)
        {
          const Vec2 a = ring[j], d = ring[j + 1] - ring[j];
          if (d.norm() > 0.05 * mm)
            continue; // not neighbours along the outline
          const double t = std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
          const Vec2 y   = a + t * d;
          const double g = (x - y).dot(rn[j]) >= 0 ? (x - y).norm() : -(x - y).norm();
          if (std::abs(g) < std::abs(best))
            best = g;
        }
    return best;
  }
} // namespace

TEST(InternalContact, UnloadedFlanksTouchAtThePitchPoint)
{
  Case c(0.1 * mm);
  const auto &pair = *c.pair;
  EXPECT_GT(pair.contact_ratio(), 1.0);
  std::cout << "eps " << pair.contact_ratio() << ", a " << pair.center_distance() / mm << " mm, alpha_w "
            << pair.mesh().alpha_w / deg << " deg, backlash " << pair.circumferential_backlash() / units::um << " um\n";
  for (const auto &q : pair.line_of_action())
    std::cout << q.name << " " << q.roll_angle / deg << " deg\n";
  for (const double phi : {0.0, 0.3 * (pair.point("E").roll_angle), 0.5 * pair.point("A").roll_angle})
    {
      const double g = unloaded_gap(pair, phi);
      std::cout << "phi1 " << phi / deg << " deg: least gap " << g / units::um << " um\n";
      EXPECT_LT(std::abs(g), 0.05 * units::um) << "phi1 " << phi;
    }
  // The neighbours of the pair in the middle of the single-pair zone: their unloaded
  // separations (a conformal internal mesh keeps them small).
  const double mid = 0.5 * (pair.point("B").roll_angle + pair.point("D").roll_angle);
  for (int k = -2; k <= 2; ++k)
    std::cout << "mid single zone, pinion tooth " << k << ": unloaded gap " << unloaded_gap(pair, mid, k) / units::um
              << " um\n";
}

TEST(InternalContact, TorqueBalanceHertzAndStiffness)
{
  Case c(0.06 * mm);
  const auto &pair = *c.pair;
  contact::ContactOptions opt;
  contact::GearContactModel model(pair, c.pinion, c.ring, c.material, c.fe, opt);
  post::PostOptions po;
  const double mid = 0.5 * (pair.point("B").roll_angle + pair.point("D").roll_angle);
  {
    // Mid single-pair zone at a light load (STE below the neighbours' unloaded gaps, 3.8 and
    // 5.4 um): one pair, forces on the line of action.
    const double T1 = 20.0;
    const auto s    = model.solve(mid, T1);
    const auto r    = post::evaluate_position(model, s, po);
    std::cout << "single zone, " << T1 << " N m: STE " << r.ste / units::um << " um, moments: contact "
              << r.torque_contact << ", bore " << r.torque_reaction << ", ring " << r.torque_gear
              << " N m (u T1 = " << pair.ratio() * T1 << "), pairs " << r.pairs.size() << ", set-up "
              << model.setup_seconds() << " s\n";
    EXPECT_EQ(r.n_pairs, 1);
    // Equilibrium of the pinion, and T2 = T1 r_b2/r_b1 (frictionless, on the line of action).
    EXPECT_NEAR(r.torque_contact, T1, 1e-6 * T1);
    EXPECT_NEAR(r.torque_reaction, T1, 1e-3 * T1);
    EXPECT_NEAR(r.torque_gear, pair.ratio() * T1, 1e-4 * pair.ratio() * T1);
    // Single-pair stiffness per face width: ISO 6336-1 gives c' about 14 N/(mm um) for
    // external steel pairs; the conformal internal contact and the clamped sector edges make
    // this one stiffer, within a factor 2.
    const double k = r.k_secant / (20 * mm) * 1e-9; // N/(mm um)
    std::cout << "k' " << k << " N/(mm um)\n";
    EXPECT_GT(k, 10.0);
    EXPECT_LT(k, 30.0);
  }
  {
    // At 100 N m the STE exceeds the neighbours' gaps: they close and share the load. Each
    // loaded pair other than the main one closed an unloaded separation smaller than the STE.
    const double T1 = 100.0;
    const auto s    = model.solve(mid, T1);
    const auto r    = post::evaluate_position(model, s, po);
    std::cout << "single zone, " << T1 << " N m: STE " << r.ste / units::um << " um, loaded pairs " << r.n_pairs;
    for (const auto &tp : r.pairs)
      std::cout << " (tooth " << tp.pinion_tooth << ", share " << tp.share << ", gap "
                << unloaded_gap(pair, mid, tp.pinion_tooth) / units::um << " um)";
    std::cout << "\n";
    EXPECT_EQ(r.n_pairs, 3);
    for (const auto &tp : r.pairs)
      EXPECT_LT(unloaded_gap(pair, mid, tp.pinion_tooth), r.ste) << "tooth " << tp.pinion_tooth;
    EXPECT_NEAR(r.torque_reaction, T1, 1e-3 * T1);
  }
  const double T1 = 100.0;
  // Hertz, concave-convex, at the pitch point with the force of the pair at C (a pair past
  // E may still carry a little in extended contact).
  const auto s = model.solve(0.0, T1);
  const auto r = post::evaluate_position(model, s, po);
  const auto main = std::max_element(r.pairs.begin(), r.pairs.end(),
                                     [](const auto &a, const auto &b) { return a.share < b.share; });
  ASSERT_NE(main, r.pairs.end());
  const double rho1 = pair.working_pitch_radius(1) * std::sin(pair.mesh().alpha_w);
  const double rho2 = pair.working_pitch_radius(2) * std::sin(pair.mesh().alpha_w);
  const double Rrel = 1 / (1 / rho1 - 1 / rho2), Es = 206e9 / 2, Pl = main->force / (20 * mm);
  const double a = std::sqrt(4 * Pl * Rrel / (pi * Es)), p0 = 2 * Pl / (pi * a);
  std::cout << "C: pairs " << r.pairs.size() << ", share " << main->share << ", p_max " << main->p_max / 1e6
            << " MPa, Hertz " << p0 / 1e6 << " MPa, a " << a / mm << " mm (fit " << main->half_width / mm
            << "), post's Hertz " << main->p_hertz / 1e6 << " MPa, nodes " << main->active_nodes << "\n";
  EXPECT_NEAR(main->p_hertz, p0, 2e-3 * p0); // the post's Hertz: signed radii at the peak node
  EXPECT_NEAR(main->p_max, p0, 0.03 * p0);
  // The ellipse fit through the nodes of a 5-element patch (a/h = 2.7) is the coarser figure.
  EXPECT_NEAR(main->half_width, a, 0.2 * a);
}

TEST(InternalContact, PinionTipReliefAsGap)
{
  // A linear tip relief of the pinion (10 um over 1.2 mm of roll length), applied as a gap on
  // the unmodified bodies (Contact/Micro-geometry = gap). Where the relieved band is out of
  // contact (mid single-pair zone, light load) the solution is the unrelieved one; where the
  // pinion tip carries load (the pair past E, in extended contact at 100 N m) the relief
  // lowers that pair's share.
  Case c(0.1 * mm), plain(0.1 * mm);
  geometry::GearParameters p;
  p.name = "Gear 1", p.teeth = 24, p.profile_shift = 0.3, p.face_width = 20 * mm;
  p.rack.module = 2 * mm, p.rack.pressure_angle = 20 * deg;
  p.relief.kind = geometry::TipRelief::Kind::linear, p.relief.amount = 10 * units::um, p.relief.length = 1.2 * mm;
  const geometry::InternalGearPair relieved(geometry::ToothProfile::generate(p), c.pair->ring());
  contact::ContactOptions opt;
  opt.micro_geometry_as_gap = true;
  contact::GearContactModel with(relieved, c.pinion, c.ring, c.material, c.fe, opt, c.pair.get());
  contact::ContactOptions opt0;
  contact::GearContactModel without(*plain.pair, plain.pinion, plain.ring, plain.material, plain.fe, opt0);
  const double mid = 0.5 * (relieved.point("B").roll_angle + relieved.point("D").roll_angle);
  const auto a = with.solve(mid, 20.0), b = without.solve(mid, 20.0);
  std::cout << "mid single zone, 20 N m: rotation with relief " << a.rotation() << ", without " << b.rotation() << "\n";
  EXPECT_NEAR(a.rotation(), b.rotation(), 1e-9 * b.rotation());
  post::PostOptions po;
  const auto ra = post::evaluate_position(with, with.solve(mid, 100.0), po);
  const auto rb = post::evaluate_position(without, without.solve(mid, 100.0), po);
  auto share_of = [](const post::PositionResult &r, int tooth) {
    for (const auto &tp : r.pairs)
      if (tp.pinion_tooth == tooth)
        return tp.share;
    return 0.0;
  };
  std::cout << "100 N m: share of the pair past E (pinion tooth 1) " << share_of(ra, 1) << " with relief, "
            << share_of(rb, 1) << " without; STE " << ra.ste / units::um << " / " << rb.ste / units::um << " um\n";
  EXPECT_LT(share_of(ra, 1), share_of(rb, 1) - 0.02);
  EXPECT_GT(ra.ste, rb.ste);
}
