// Mesh-cycle load sharing: periodic with the pitch, jumps at the
// transitions, pair stiffnesses and loads sum to the totals, equal deflection holds.
#include "analytical/mesh_cycle.h"
#include "base/units.h"
#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::analytical;

namespace
{
  using gearfem::units::pi;

  // A pair with z1 = 20, m 3 mm, eps ~ 1.6, and a tooth-pair compliance that is softest at
  // the ends of contact plus a Weber-like log Hertz term (decreasing with load).
  MeshModel test_model()
  {
    MeshModel m;
    m.rb1 = 0.5 * 0.06 * std::cos(20 * gearfem::units::deg);
    m.base_pitch = 2 * pi * m.rb1 / 20;
    m.g_C = 0.0103;
    m.g_A = m.g_C - 0.8 * m.base_pitch;
    m.g_E = m.g_A + 1.6 * m.base_pitch;
    const double gm = 0.5 * (m.g_A + m.g_E), L = m.g_E - m.g_A;
    m.pair_compliance = [=](double g, double F) {
      const double s = (g - gm) / (0.5 * L);
      return 1.0 / 3.0e8 * (1 + 0.4 * s * s) + 2.0 / (pi * 0.02 * 2.1e11) * (6.0 - 0.5 * std::log(F));
    };
    return m;
  }
} // namespace

TEST(MeshCycle, SumsAndEqualDeflection)
{
  const MeshModel m = test_model();
  for (double phi : {-0.2, -0.05, 0.0, 0.07, 0.15})
    {
      const MeshState s = solve_mesh_position(m, phi, 4000.0);
      double F = 0, k = 0;
      for (std::size_t i = 0; i < s.g.size(); ++i)
        {
          F += s.pair_load[i];
          k += s.pair_stiffness[i];
          // Equal deflection: every pair's own compliance times its own load = STE.
          EXPECT_NEAR(m.pair_compliance(s.g[i], s.pair_load[i]) * s.pair_load[i] / s.deflection, 1, 1e-10);
        }
      EXPECT_NEAR(F / 4000.0, 1.0, 1e-12);
      EXPECT_NEAR(k / s.stiffness, 1.0, 1e-12);
      EXPECT_NEAR(s.stiffness * s.deflection / 4000.0, 1.0, 1e-12);
      // Inverse: the load carried at that compression is the total load.
      EXPECT_NEAR(load_at_compression(m, phi, s.deflection) / 4000.0, 1.0, 1e-9);
    }
}

TEST(MeshCycle, PeriodicWithThePitchAndJumpsAtTransitions)
{
  const MeshModel m = test_model();
  const int n = 400;
  const std::vector<MeshState> c = mesh_cycle(m, 3000.0, n, 2);
  // Period: state i and i + n/2 (one pitch later) are identical.
  for (int i = 0; i < n / 2; ++i)
    EXPECT_NEAR(c[i].stiffness / c[i + n / 2].stiffness, 1.0, 1e-12);
  // Number of pairs: 2 over (eps - 1) of the pitch, 1 elsewhere; the stiffness jumps where
  // the count changes (larger than any step inside a zone).
  int two = 0, jumps = 0;
  double max_inner_step = 0, min_jump = 1e300;
  for (int i = 0; i < n / 2; ++i)
    {
      two += c[i].g.size() == 2;
      const double step = std::abs(c[i + 1].stiffness - c[i].stiffness);
      if (c[i + 1].g.size() != c[i].g.size())
        {
          ++jumps;
          min_jump = std::min(min_jump, step);
        }
      else
        max_inner_step = std::max(max_inner_step, step);
    }
  EXPECT_NEAR(two / double(n / 2), 0.6, 2.0 / (n / 2));
  EXPECT_EQ(jumps, 2);
  EXPECT_GT(min_jump, 10 * max_inner_step);
}

TEST(MeshCycle, TorqueTableIsMonotoneAndZeroWithoutContact)
{
  const MeshModel m = test_model();
  const std::vector<double> phis = {-0.1, 0.0, 0.1};
  const std::vector<double> xs = {-1e-6, 0.0, 5e-6, 1e-5, 2e-5};
  const auto T = torque_table(m, phis, xs);
  for (const auto &row : T)
    {
      EXPECT_EQ(row[0], 0.0);
      EXPECT_EQ(row[1], 0.0);
      EXPECT_GT(row[3], row[2]);
      EXPECT_GT(row[4], row[3]);
      // Hertz softening at low load: T grows faster than linearly in x.
      EXPECT_GT(row[4], 2 * row[3]);
    }
}

TEST(MeshCycle, BadInput)
{
  MeshModel m = test_model();
  EXPECT_THROW(solve_mesh_position(m, 0.0, -1.0), gearfem::InputError);
  m.pair_compliance = nullptr;
  EXPECT_THROW(solve_mesh_position(m, 0.0, 1.0), gearfem::InputError);
}
