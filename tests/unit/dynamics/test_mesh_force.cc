// Mesh-force laws and contact logic against closed forms.
#include "common.h"
#include "base/units.h"

#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::dynamics;

// Closed form: zone bookkeeping on a periodic list of breaks.
TEST(MeshForce, LocateZone)
{
  const std::vector<double> br = {0.2, 0.7};
  const double p = 1.0;
  ZoneInfo z = locate_zone(br, p, 0.5);
  EXPECT_EQ(z.zone, 1);
  EXPECT_DOUBLE_EQ(z.prev, 0.2);
  EXPECT_DOUBLE_EQ(z.next, 0.7);
  z = locate_zone(br, p, 3.9);
  EXPECT_EQ(z.zone, 0);
  EXPECT_NEAR(z.prev, 3.7, 1e-12);
  EXPECT_NEAR(z.next, 4.2, 1e-12);
  z = locate_zone(br, p, -0.1);
  EXPECT_EQ(z.zone, 0);
  EXPECT_NEAR(z.prev, -0.3, 1e-12);
  EXPECT_NEAR(z.next, 0.2, 1e-12);
}

// Closed form: over one mesh period two pairs are in contact for the fraction eps - 1, and
// the mean stiffness is (eps - 1) k_double + (2 - eps) k_single.
TEST(MeshForce, PiecewiseConstantZones)
{
  const int z1 = 32;
  const double eps = 1.72, thA = -9.2 * gearfem::units::deg;
  const PiecewiseConstantLaw law(4e8, 7e8, z1, eps, thA);
  const double p = 2 * gearfem::units::pi / z1;
  const int n = 200000;
  int n2 = 0;
  double ksum = 0;
  for (int i = 0; i < n; ++i)
    {
      const double th = thA + p * (i + 0.5) / n;
      const int zone = locate_zone(law.breaks(), p, th).zone;
      n2 += law.pairs_in_contact(th) == 2;
      ksum += law.force(th, 1.0, zone);
    }
  EXPECT_NEAR(double(n2) / n, eps - 1, 1e-4);
  EXPECT_NEAR(ksum / n, law.mean_stiffness(), 1e-4 * law.mean_stiffness());
  // Double contact right after the start of contact A, single just before A + p.
  EXPECT_EQ(law.pairs_in_contact(thA + 1e-6), 2);
  EXPECT_EQ(law.pairs_in_contact(thA + p - 1e-6), 1);
}

namespace
{
  /// A torque table T = r_b k(theta) delta with a smooth known k(theta).
  MeshTable smooth_table(int nt, ThetaInterpolation, double &rb, FourierStiffnessLaw &exact)
  {
    MeshTable t;
    t.period = exact.period();
    rb = 0.04;
    t.base_radius = rb;
    for (int i = 0; i < nt; ++i)
      t.theta.push_back(-0.3 * t.period + t.period * i / nt);
    t.second = {0.0, 5e-6, 1e-5, 2e-5};
    t.values.resize(nt * 4);
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < 4; ++j)
        t.values[i * 4 + j] = rb * exact.force(t.theta[i], t.second[j], 0);
    return t;
  }
} // namespace

// Closed form: interpolation of a table sampled from F = k(theta) delta. Linear in delta
// is exact; in theta the bilinear error falls as h^2, the monotone cubic's faster.
TEST(MeshForce, TableInterpolation)
{
  FourierStiffnessLaw exact(5e8, 20, {-0.1, 0.03});
  double err[2][2];
  for (int interp = 0; interp < 2; ++interp)
    for (int r = 0; r < 2; ++r)
      {
        double rb;
        const auto mode = interp ? ThetaInterpolation::monotone_cubic : ThetaInterpolation::linear;
        const MeshTable t = smooth_table(r ? 64 : 32, mode, rb, exact);
        const TableLaw law(t, mode);
        double e = 0;
        for (int i = 0; i < 997; ++i)
          {
            const double th = 0.013 + exact.period() * 3.1 * i / 997;
            const double d = 1.7e-5 * (i % 7) / 6.0;
            e = std::max(e, std::abs(law.force(th, d, 0) - exact.force(th, d, 0)));
          }
        err[interp][r] = e / (5e8 * 1.7e-5);
        EXPECT_EQ(law.out_of_range_count(), 0);
      }
  EXPECT_NEAR(std::log2(err[0][0] / err[0][1]), 2.0, 0.2); // bilinear: second order
  EXPECT_LT(err[1][1], 0.5 * err[0][1]);                  // cubic better than bilinear
  EXPECT_LT(err[1][1], 1e-3);
}

// Outside the delta range the stiffness is clamped (linear extrapolation) and counted.
TEST(MeshForce, TableClampingIsCounted)
{
  FourierStiffnessLaw exact(5e8, 20, {});
  double rb;
  const MeshTable t = smooth_table(16, ThetaInterpolation::linear, rb, exact);
  const TableLaw law(t, ThetaInterpolation::linear);
  EXPECT_NEAR(law.force(0.1, 4e-5, 0), 5e8 * 4e-5, 1e-6 * 5e8 * 4e-5);
  EXPECT_EQ(law.out_of_range_count(), 1);
  EXPECT_NEAR(law.mean_secant_stiffness(1e3), 5e8, 1e-6 * 5e8);
}

// A k(theta, F) table with k independent of F is converted to F = k delta exactly.
TEST(MeshForce, StiffnessVersusLoadTable)
{
  MeshTable t;
  t.kind = MeshTable::Kind::stiffness_vs_load;
  t.second_unit = "N";
  t.value_unit = "N/m";
  t.period = 2 * gearfem::units::pi / 25;
  t.base_radius = 0.03;
  for (int i = 0; i < 10; ++i)
    t.theta.push_back(t.period * i / 10);
  t.second = {100, 1000, 5000};
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 3; ++j)
      t.values.push_back(6e8 * (1 + 0.1 * (i % 2)));
  const TableLaw law(t, ThetaInterpolation::linear);
  EXPECT_NEAR(law.force(t.theta[3], 2e-6, 0), 6.6e8 * 2e-6, 1e-3);
  EXPECT_NEAR(law.force(t.theta[4], 2e-6, 0), 6.0e8 * 2e-6, 1e-3);
  EXPECT_THROW(t.require_covers_load(1e4), gearfem::InputError);
  EXPECT_NO_THROW(t.require_covers_load(2e3));
}

// Bad input: missing axes, wrong units, geometry hash mismatch.
TEST(MeshForce, TableBadInput)
{
  FourierStiffnessLaw exact(5e8, 20, {});
  double rb;
  MeshTable t = smooth_table(8, ThetaInterpolation::linear, rb, exact);
  t.geometry_hash = "abc";
  EXPECT_NO_THROW(t.check("abc"));
  EXPECT_THROW(t.check("def"), gearfem::InputError);
  MeshTable u = t;
  u.theta.clear();
  EXPECT_THROW(u.check(), gearfem::InputError);
  u = t;
  u.second_unit = "mm";
  try
    {
      u.check();
      FAIL();
    }
  catch (const gearfem::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("unit"), std::string::npos);
    }
  u = t;
  u.values.pop_back();
  EXPECT_THROW(u.check(), gearfem::InputError);
  EXPECT_THROW(t.require_covers_load(1e9), gearfem::InputError);
}

// Contact logic (Gkimisis 2019, 4.9-4.11): states and the reverse-flank force.
TEST(MeshForce, ContactStatesAndReverseFlank)
{
  ContactLogic c;
  c.backlash = 1e-4;
  EXPECT_EQ(c.state(1e-6), 1);
  EXPECT_EQ(c.state(0.0), 0);
  EXPECT_EQ(c.state(-5e-5), 0);
  EXPECT_EQ(c.state(-1e-4), -1);
  c.reverse_mapping = true;
  c.reverse_offset = 0.3;
  EXPECT_DOUBLE_EQ(c.coast_theta(0.1), 0.2);
  // Back contact of a piecewise law evaluates the coast flank at the mapped position.
  const int z1 = 20;
  auto law = std::make_unique<PiecewiseConstantLaw>(3e8, 6e8, z1, 1.6, -0.1);
  const PiecewiseConstantLaw ref = *law;
  DteModel::Parameters p;
  p.mass = 1, p.static_force = 0, p.zeta = 0;
  DteModel m(std::move(law), c, p);
  State x(2);
  const double th = 0.05, d = -1e-4 - 2e-6;
  MeshMode mode;
  mode.s = -1;
  mode.zone = locate_zone(ref.breaks(), ref.period(), c.coast_theta(th));
  const double expected = -ref.force(0.3 - th, 2e-6, mode.zone.zone);
  EXPECT_NEAR(m.elastic_force(th, d, mode), expected, 1e-9 * std::abs(expected));
  x << d, 0;
  EXPECT_EQ(m.contact_state(0, x), -1);
}

// A two-sided table (format version 2) carries its own reverse branch: back contact
// evaluates it at the unmapped theta with delta_r = -delta - b (no coast mapping), the gap
// gives 0, and the reverse branch equals the closed form the table was filled with.
TEST(MeshForce, TwoSidedTableReverseBranch)
{
  const double b = 5e-5, rb = 0.04, kd = 3e8, kr = 2e8;
  MeshTable t;
  t.period = 2 * gearfem::units::pi / 20, t.base_radius = rb, t.backlash = b;
  for (int i = 0; i < 16; ++i)
    t.theta.push_back(-0.1 + t.period * i / 16);
  const std::vector<double> d = {0, 1e-5, 2e-5, 4e-5};
  for (auto it = d.rbegin(); it != d.rend(); ++it)
    t.second.push_back(-b - *it);
  for (double x : d)
    t.second.push_back(x);
  for (std::size_t i = 0; i < t.theta.size(); ++i)
    for (double x : t.second)
      t.values.push_back(x > 0 ? rb * kd * (1 + 0.2 * std::sin(20 * t.theta[i])) * x : x < -b ? -rb * kr * (-x - b) : 0.0);
  auto law = std::make_unique<TableLaw>(t, ThetaInterpolation::linear);
  ASSERT_TRUE(law->has_reverse_branch());
  ContactLogic c;
  c.backlash = law->backlash();
  c.reverse_mapping = true; // ignored for a law with its own reverse branch
  c.reverse_offset = 0.3;
  DteModel::Parameters p;
  p.mass = 1, p.static_force = 0, p.zeta = 0;
  DteModel m(std::move(law), c, p);
  MeshMode back;
  back.s = -1;
  const double th = t.theta[5];
  EXPECT_NEAR(m.elastic_force(th, -b - 3e-5, back), -kr * 3e-5, 1e-9 * kr * 3e-5);
  MeshMode gap;
  gap.s = 0;
  EXPECT_EQ(m.elastic_force(th, -0.5 * b, gap), 0.0);
  MeshMode drive;
  drive.s = 1;
  EXPECT_NEAR(m.elastic_force(th, 1.5e-5, drive), kd * (1 + 0.2 * std::sin(20 * th)) * 1.5e-5,
              1e-6 * kd * 1.5e-5);
}

// STE excitation: the fluctuation has zero mean and is interpolated periodically.
TEST(MeshForce, SteExcitation)
{
  const double p = 2 * gearfem::units::pi / 20;
  std::vector<double> th, e;
  for (int i = 0; i < 40; ++i)
    th.push_back(p * i / 40), e.push_back(1e-6 + 2e-7 * std::sin(2 * gearfem::units::pi * i / 40));
  const SteExcitationLaw law(4e8, th, e, p);
  double mean = 0;
  for (int i = 0; i < 400; ++i)
    mean += law.fluctuation(p * i / 400) / 400;
  EXPECT_NEAR(mean, 0.0, 1e-12);
  EXPECT_NEAR(law.fluctuation(p / 4), 2e-7, 1e-9);
  EXPECT_NEAR(law.fluctuation(p / 4 + 7 * p), 2e-7, 1e-9);
  EXPECT_NEAR(law.force(0.1, 1e-5, 0), 4e8 * (1e-5 - law.fluctuation(0.1)), 1e-6);
}
