// Stepped Timoshenko shafts on bearings (lib/shafts) against closed forms of beam theory and
// statics. The references do not use lib/shafts: the deflection under a load is the unit-load
// (Castigliano) integral of M m / (E I) + V v / (kappa G A) over the statically determinate
// shaft, integrated here by Simpson's rule on each piece where the integrands are quadratic
// (exact); torsion and extension are sums of L / (G J) and L / (E A).
#include "base/errors.h"
#include "shafts/mesh_coupling.h"
#include "shafts/shaft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace gearfem;
using namespace gearfem::shafts;

namespace
{
  constexpr double E = 206e9, nu = 0.3, G = E / (2 * (1 + nu));

  // Cowper's coefficient, restated: solid 6 (1 + nu) / (7 + 6 nu).
  double kappa(double D, double d)
  {
    const double m2 = (d / D) * (d / D);
    return 6 * (1 + nu) * (1 + m2) * (1 + m2) / ((7 + 6 * nu) * (1 + m2) * (1 + m2) + (20 + 12 * nu) * m2);
  }
  double I_of(double D, double d) { return M_PI / 64 * (std::pow(D, 4) - std::pow(d, 4)); }
  double A_of(double D, double d) { return M_PI / 4 * (D * D - d * d); }

  struct Piece
  {
    double z0, z1, D, d;
  };

  /// Unit-load integral over pieces on which M, m, V, v are polynomials of degree <= 1:
  /// the integrand M m is quadratic and Simpson's rule is exact.
  double unit_load(const std::vector<Piece> &pieces, const std::function<double(double)> &M,
                   const std::function<double(double)> &m, const std::function<double(double)> &V,
                   const std::function<double(double)> &v)
  {
    double w = 0;
    for (const auto &p : pieces)
      {
        const double h = p.z1 - p.z0, EI = E * I_of(p.D, p.d), kGA = kappa(p.D, p.d) * G * A_of(p.D, p.d);
        // Sample strictly inside so that a jump of V at a piece end takes the piece's side.
        const double e = 1e-12 * h;
        const auto f = [&](double z) { return M(z) * m(z) / EI + V(z) * v(z) / kGA; };
        w += h / 6 * (f(p.z0 + e) + 4 * f(0.5 * (p.z0 + p.z1)) + f(p.z1 - e));
      }
    return w;
  }

  Shaft stepped(std::vector<Segment> segs)
  {
    Shaft s;
    s.name     = "test shaft";
    s.segments = std::move(segs);
    s.material = {E, nu};
    return s;
  }

  Bearing support(double z, double axial = 0, double torsional = 0)
  {
    Bearing b;
    b.name = "support", b.z = z, b.radial = rigid, b.axial = axial, b.torsional = torsional, b.tilting = 0;
    return b;
  }

  PointLoad force_x(double z, double P)
  {
    PointLoad p;
    p.z = z, p.force = Eigen::Vector3d(P, 0, 0);
    return p;
  }
} // namespace

TEST(Shafts, SimplySupportedUniformShaftMatchesTimoshenkoClosedForm)
{
  // w(L/2) = P L^3 / (48 E I) + P L / (4 kappa G A); between nodes the element's own
  // interpolation gives w(z) = P z (3 L^2 - 4 z^2) / (48 E I) + P z / (2 kappa G A), z <= L/2.
  const double L = 0.4, D = 0.04, P = 1000;
  System sys;
  sys.shafts   = {stepped({{L, D, 0}})};
  sys.bearings = {support(0, rigid, rigid), support(L)};
  const Solution s = solve(sys, {force_x(L / 2, P)});
  const double EI = E * I_of(D, 0), kGA = kappa(D, 0) * G * A_of(D, 0);
  const double w  = P * L * L * L / (48 * EI) + P * L / (4 * kGA);
  EXPECT_NEAR(s.at(0, L / 2).u[ux] / w, 1.0, 1e-9);
  const double z = L / 5;
  const double wz = P * z * (3 * L * L - 4 * z * z) / (48 * EI) + P * z / (2 * kGA);
  EXPECT_NEAR(s.along(sys, 0, z)[ux] / wz, 1.0, 1e-9);
  // The bending slope at the support: theta = P L^2 / (16 E I) (shear adds no end rotation).
  EXPECT_NEAR(s.at(0, 0).u[ry] / (P * L * L / (16 * EI)), 1.0, 1e-9);
  // The y-z plane is the same beam turned: a load in y bends it with the rotation about -x.
  const Solution sy = solve(sys, {PointLoad{0, L / 2, Eigen::Vector3d(0, P, 0), Eigen::Vector3d::Zero()}});
  EXPECT_NEAR(sy.at(0, L / 2).u[uy] / w, 1.0, 1e-9);
  EXPECT_NEAR(sy.at(0, 0).u[rx] / (-P * L * L / (16 * EI)), 1.0, 1e-9);
}

TEST(Shafts, SteppedShaftsInBendingMatchTheUnitLoadIntegral)
{
  // Simply supported: segments 0.1 / 0.15 / 0.1 m of diameters 40 / 55 / 35 mm (the middle one
  // bored 20 mm), load P at c = 0.18 m.
  const double P = 2500, c = 0.18, L = 0.35;
  const std::vector<Segment> segs = {{0.1, 0.040, 0}, {0.15, 0.055, 0.020}, {0.1, 0.035, 0}};
  System sys;
  sys.shafts   = {stepped(segs)};
  sys.bearings = {support(0, rigid, rigid), support(L)};
  const Solution s = solve(sys, {force_x(c, P)});
  const std::vector<Piece> pieces = {{0, 0.1, 0.040, 0}, {0.1, c, 0.055, 0.020}, {c, 0.25, 0.055, 0.020},
                                     {0.25, L, 0.035, 0}};
  const auto M = [&](double z) { return z < c ? P * (L - c) * z / L : P * c * (L - z) / L; };
  const auto V = [&](double z) { return z < c ? P * (L - c) / L : -P * c / L; };
  const double w = unit_load(pieces, M, [&](double z) { return M(z) / P; }, V, [&](double z) { return V(z) / P; });
  EXPECT_NEAR(s.at(0, c).u[ux] / w, 1.0, 1e-9);

  // Overhung: bearings at 0 and a, the load at the free end a + c.
  const double a = 0.25, o = 0.1;
  System oh;
  oh.shafts   = {stepped({{a, 0.05, 0}, {o, 0.04, 0}})};
  oh.bearings = {support(0, rigid, rigid), support(a)};
  const Solution so = solve(oh, {force_x(a + o, P)});
  const std::vector<Piece> op = {{0, a, 0.05, 0}, {a, a + o, 0.04, 0}};
  const auto Mo = [&](double z) { return z < a ? -P * o * z / a : -P * (a + o - z); };
  const auto Vo = [&](double z) { return z < a ? -P * o / a : P; };
  const double wo = unit_load(op, Mo, [&](double z) { return Mo(z) / P; }, Vo, [&](double z) { return Vo(z) / P; });
  EXPECT_NEAR(so.at(0, a + o).u[ux] / wo, 1.0, 1e-9);
  // Splitting the elements (max_element) does not move a nodal answer: the element is exact.
  oh.shafts[0].max_element = 0.013;
  EXPECT_NEAR(solve(oh, {force_x(a + o, P)}).at(0, a + o).u[ux] / wo, 1.0, 1e-9);
}

TEST(Shafts, TorsionAndExtensionOfASteppedShaft)
{
  // theta = T sum L_i / (G J_i); delta = F sum L_i / (E A_i), held at z = 0.
  const std::vector<Segment> segs = {{0.12, 0.045, 0}, {0.08, 0.06, 0.03}, {0.05, 0.03, 0}};
  System sys;
  sys.shafts   = {stepped(segs)};
  sys.bearings = {support(0, rigid, rigid), support(0.25)};
  PointLoad p;
  p.z = 0.25, p.force = Eigen::Vector3d(0, 0, 4000), p.moment = Eigen::Vector3d(0, 0, 150);
  const Solution s = solve(sys, {p});
  double theta = 0, delta = 0;
  for (const auto &g : segs)
    {
      theta += 150 * g.length / (G * 2 * I_of(g.outer_diameter, g.inner_diameter));
      delta += 4000 * g.length / (E * A_of(g.outer_diameter, g.inner_diameter));
    }
  EXPECT_NEAR(s.at(0, 0.25).u[rz] / theta, 1.0, 1e-9);
  EXPECT_NEAR(s.at(0, 0.25).u[uz] / delta, 1.0, 1e-9);
}

TEST(Shafts, BearingAndHousingSpringsAddTheirSeriesCompliance)
{
  // A symmetric load on two equal elastic supports: the supports sink by P/2 (1/k_b + 1/k_h)
  // and the shaft bends as when simply supported.
  const double L = 0.3, D = 0.05, P = 5000, kb = 4e8, kh = 6e8;
  System sys;
  sys.shafts = {stepped({{L, D, 0}})};
  for (const double z : {0.0, L})
    {
      Bearing b;
      b.name = "elastic", b.z = z, b.radial = kb, b.axial = kb, b.torsional = 1e6, b.tilting = 0;
      b.housing = Eigen::MatrixXd::Identity(6, 6) * kh;
      sys.bearings.push_back(b);
    }
  const Solution s = solve(sys, {force_x(L / 2, P)});
  const double EI = E * I_of(D, 0), kGA = kappa(D, 0) * G * A_of(D, 0);
  const double w = P / 2 * (1 / kb + 1 / kh) + P * L * L * L / (48 * EI) + P * L / (4 * kGA);
  EXPECT_NEAR(s.at(0, L / 2).u[ux] / w, 1.0, 1e-9);
  EXPECT_NEAR(s.reactions[0].force.x() / (-P / 2), 1.0, 1e-9);
}

TEST(Shafts, ReactionsBalanceTheLoadsOfTwoCoupledShafts)
{
  // Statics: the bearing reactions balance every force and moment (about the origin) to 1e-9 of
  // the loads, on two in-line shafts joined by a coupling, with tilting and elastic bearings.
  System sys;
  sys.shafts = {stepped({{0.1, 0.04, 0}, {0.2, 0.05, 0}}), stepped({{0.3, 0.045, 0.01}})};
  sys.shafts[0].x = sys.shafts[1].x = 0.15, sys.shafts[0].y = sys.shafts[1].y = -0.02;
  sys.shafts[0].z0 = -0.1, sys.shafts[1].z0 = 0.2;
  Bearing a = support(0.0, rigid, rigid), b = support(0.3);
  b.tilting = 2e5;
  Bearing c = support(0.05), d = support(0.3, 3e8);
  c.shaft = d.shaft = 1, c.radial = 5e8;
  d.tilting = rigid;
  sys.bearings = {a, b, c, d};
  Coupling k;
  k.shaft_a = 0, k.shaft_b = 1, k.z_a = 0.3, k.z_b = 0.0;
  k.stiffness = {1e7, 1e7, 1e7, 1e4, 1e4, 1e6};
  sys.couplings = {k};
  std::vector<PointLoad> loads = {
    {0, 0.17, Eigen::Vector3d(1200, -800, 300), Eigen::Vector3d(15, -20, 40)},
    {1, 0.22, Eigen::Vector3d(-500, 900, -100), Eigen::Vector3d(-5, 8, -40)}};
  const Solution s = solve(sys, loads);
  Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
  double scale = 0;
  const auto at = [&](int shaft, double z) {
    const auto &sh = sys.shafts[std::size_t(shaft)];
    return Eigen::Vector3d(sh.x, sh.y, sh.z0 + z);
  };
  for (const auto &p : loads)
    {
      F += p.force, M += at(p.shaft, p.z).cross(p.force) + p.moment;
      scale = std::max({scale, p.force.norm(), p.moment.norm()});
    }
  for (std::size_t i = 0; i < sys.bearings.size(); ++i)
    {
      const auto &r = s.reactions[i];
      F += r.force, M += at(sys.bearings[i].shaft, sys.bearings[i].z).cross(r.force) + r.moment;
    }
  EXPECT_LE(F.norm(), 1e-9 * scale);
  EXPECT_LE(M.norm(), 1e-9 * scale);
}

TEST(Shafts, BadSystemsAreNamedInputErrors)
{
  System free;
  free.shafts   = {stepped({{0.2, 0.04, 0}})};
  free.bearings = {support(0), support(0.2)}; // no axial and no torsional restraint
  EXPECT_THROW(solve(free, {force_x(0.1, 100)}), InputError);
  System off = free;
  off.bearings[0].axial = off.bearings[0].torsional = rigid;
  EXPECT_THROW(solve(off, {force_x(0.3, 100)}), InputError); // a load beyond the shaft's end
  System bad = off;
  bad.shafts[0].segments[0].inner_diameter = 0.05;
  EXPECT_THROW(solve(bad, {force_x(0.1, 100)}), InputError);
  System apart = off;
  apart.shafts.push_back(stepped({{0.1, 0.04, 0}}));
  apart.shafts[1].x = 0.1;
  apart.bearings.push_back(support(0.05, rigid, rigid));
  apart.bearings.back().shaft = 1, apart.bearings.back().tilting = rigid;
  Coupling offset;
  offset.shaft_a = 0, offset.shaft_b = 1, offset.z_a = 0.2, offset.z_b = 0;
  offset.stiffness = {1e7, 1e7, 1e7, 1e4, 1e4, 1e6};
  apart.couplings = {offset}; // joins two points 0.1 m apart
  EXPECT_THROW(solve(apart, {force_x(0.1, 100)}), InputError);
  System housed = off;
  housed.bearings[1].housing = Eigen::MatrixXd::Identity(6, 6) * 1e8; // a rigid bearing on a housing spring
  EXPECT_THROW(solve(housed, {force_x(0.1, 100)}), InputError);
}

TEST(Shafts, MeshApproachOfAPinionShaftMatchesBendingPlusTorsionClosedForm)
{
  // A spur pinion on a shaft simply supported at 0 and L, held in torsion at z = 0 (the motor);
  // the gear held rigidly at every face position. A line load w over the face [c0, c0 + b] in
  // 10 slices puts P_j = w dz on the pinion along -n at each slice, with its torque r_b1 P_j, so
  // that delta(z) = -sum_j P_j [G(z, c_j) + r_b1^2 min(z, c_j) / (G J)], G the simply supported
  // Timoshenko influence function (Euler b z (L^2 - b^2 - z^2) / (6 L E I) + shear).
  const double L = 0.3, D = 0.045, c0 = 0.1, b = 0.06, w = 2e5, r1 = 0.05, alpha = 20 * M_PI / 180;
  System sys;
  sys.shafts = {stepped({{L, D, 0}}), stepped({{0.1, 0.08, 0}})};
  sys.shafts[1].x = 0.15; // the gear's axis, 150 mm off along x
  sys.bearings = {support(0, rigid, rigid), support(L)};
  MeshLayout mesh;
  mesh.pinion_shaft = 0, mesh.gear_shaft = 1, mesh.pinion_face_start = c0, mesh.gear_face_start = 0.02;
  mesh.face_width = b, mesh.alpha_wt = alpha, mesh.pitch_radius_1 = r1;
  const int N = 10;
  std::vector<double> z, dz(N, b / N), ww(N, w);
  for (int k = 0; k < N; ++k)
    z.push_back((k + 0.5) * b / N);
  for (const double zk : z)
    {
      Bearing hold;
      hold.name = "gear held", hold.shaft = 1, hold.z = mesh.gear_face_start + zk;
      hold.radial = hold.axial = hold.tilting = hold.torsional = rigid;
      sys.bearings.push_back(hold);
    }
  const Solution s = solve(sys, mesh_loads(sys, mesh, z, dz, ww));
  const auto delta = mesh_approach(sys, s, mesh, z);
  const double EI = E * I_of(D, 0), kGA = kappa(D, 0) * G * A_of(D, 0), GJ = G * 2 * I_of(D, 0);
  const double rb1 = r1 * std::cos(alpha);
  const auto Gf = [&](double x, double c) {
    if (x > c)
      x = L - x, c = L - c;
    const double bb = L - c;
    return bb * x * (L * L - bb * bb - x * x) / (6 * L * EI) + x * bb / (L * kGA);
  };
  double worst = 0, mid = 0;
  for (int k = 0; k < N; ++k)
    {
      double ref = 0;
      for (int j = 0; j < N; ++j)
        {
          const double P = w * dz[std::size_t(j)], zk = c0 + z[std::size_t(k)], cj = c0 + z[std::size_t(j)];
          ref -= P * (Gf(zk, cj) + rb1 * rb1 * std::min(zk, cj) / GJ);
        }
      worst = std::max(worst, std::abs(delta[std::size_t(k)] / ref - 1));
      mid = ref;
    }
  EXPECT_LE(worst, 1e-9);
  EXPECT_LT(mid, 0.0); // the shafts give way: the flanks separate
  // The mesh forces balance: the reactions of both shafts' supports carry F and the torques.
  Eigen::Vector3d F = Eigen::Vector3d::Zero();
  for (const auto &r : s.reactions)
    F += r.force;
  EXPECT_LE(F.norm(), 1e-9 * w * b);
  // The force on the gear pushes it away from the pinion: n . e = sin(alpha_wt).
  EXPECT_NEAR(line_of_action(sys, mesh).dot(Eigen::Vector3d::UnitX()), std::sin(alpha), 1e-15);
}
