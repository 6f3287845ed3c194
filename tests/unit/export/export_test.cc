// lib/export: the grid from mesh tables and solve results, ROSS arrays, the force table.
#include "base/errors.h"
#include "base/units.h"
#include "export/force_table.h"
#include "export/formats.h"
#include "export/grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace gearfem;
  constexpr int z1 = 50;
  const double period = 2 * units::pi / z1, rb = 0.07;

  exports::PairInfo pair_info()
  {
    exports::PairInfo p;
    p.z1 = z1, p.z2 = 50, p.base_radius = rb, p.theta_A = -0.35 * period, p.geometry_hash = "test";
    return p;
  }

  /// T = rb k(theta) (delta + delta^2 / d0), k = 4e8 (1 + 0.1 cos z1 theta), 20 x 11.
  io::MeshTable torque_table()
  {
    io::MeshTable t;
    t.kind = io::MeshTable::Kind::torque_vs_compression;
    t.period = period, t.base_radius = rb;
    for (int i = 0; i < 20; ++i)
      t.theta.push_back(-0.35 * period + period * i / 20);
    for (int j = 0; j <= 10; ++j)
      t.second.push_back(5e-6 * j);
    for (const double th : t.theta)
      for (const double d : t.second)
        t.values.push_back(rb * 4e8 * (1 + 0.1 * std::cos(z1 * th)) * (d + d * d / 20e-6));
    return t;
  }
} // namespace

TEST(Exchange, PeriodicLinearWrapsAndCopiesNodes)
{
  const std::vector<double> x{0.0, 1.0, 2.0}, y{1.0, 3.0, 2.0};
  EXPECT_EQ(exports::periodic_linear(x, y, 3.0, 1.0), 3.0);
  EXPECT_DOUBLE_EQ(exports::periodic_linear(x, y, 3.0, 2.5), 1.5);  // the wrapping segment
  EXPECT_DOUBLE_EQ(exports::periodic_linear(x, y, 3.0, -0.5), 1.5); // one period back
  EXPECT_DOUBLE_EQ(exports::periodic_linear(x, y, 3.0, 7.5), 2.5);  // 7.5 = 1.5 + 2 periods
}

TEST(Exchange, TorqueTableInvertedExactly)
{
  const auto t = torque_table();
  const auto g = exports::grid_from_table(t, pair_info(), {100.0, 300.0}, "Export/Torques");
  ASSERT_EQ(g.theta.size(), 20u);
  for (std::size_t i = 0; i < g.theta.size(); ++i)
    for (std::size_t j = 0; j < 2; ++j)
      {
        // T(theta_i, .) is linear between nodes: re-evaluate it at the exported STE.
        const double d = g.ste_at(i, j);
        const std::size_t k = static_cast<std::size_t>(d / 5e-6);
        const double w = (d - t.second[k]) / 5e-6;
        const double T = (1 - w) * t.value(i, k) + w * t.value(i, k + 1);
        EXPECT_NEAR(T, g.torque[j], 1e-12 * g.torque[j]);
        EXPECT_NEAR(g.k_at(i, j) * g.ste_at(i, j), g.torque[j] / rb, 1e-9);
      }
  EXPECT_THROW(exports::grid_from_table(t, pair_info(), {1e6}, "Export/Torques"), InputError);
  EXPECT_THROW(exports::grid_from_table(t, pair_info(), {}, "Export/Torques"), InputError);
}

TEST(Exchange, RossArraysStartAtContactAndClose)
{
  const auto g = exports::grid_from_table(torque_table(), pair_info(), {200.0}, "Export/Torques");
  const auto r = exports::ross_arrays(g, pair_info());
  ASSERT_EQ(r.theta_range.size(), 21u); // a node at A (-0.35 period) + the closing node
  EXPECT_EQ(r.theta_range.front(), 0.0);
  EXPECT_NEAR(r.theta_range.back(), period, 1e-15);
  EXPECT_EQ(r.stiffness_range[0].front(), r.stiffness_range[0].back());
  EXPECT_EQ(r.stiffness_range[0][0], g.k_at(0, 0));
  EXPECT_EQ(r.stiffness_range[0][5], g.k_at(5, 0));
}

TEST(Exchange, ForceTableMapsTheBackFlank)
{
  const auto t = torque_table();
  const double b = 50e-6, psi = 0.4 * period;
  const auto f = exports::force_table(t, b, psi, "Export/Backlash");
  ASSERT_EQ(f.delta.size(), 11u + 1u + 10u);
  EXPECT_EQ(f.delta[10], -b);
  EXPECT_EQ(f.delta[11], 0.0);
  for (std::size_t i = 0; i < t.theta.size(); ++i)
    {
      EXPECT_EQ(f.at(i, 11), 0.0);
      EXPECT_DOUBLE_EQ(f.at(i, 21), t.value(i, 10) / rb);
      // psi - theta_i falls on a node: theta nodes are spaced period/20 and psi is 8 of them.
      const double th = psi - t.theta[i];
      double m = std::fmod(th - t.theta[0], period);
      if (m < 0)
        m += period;
      const std::size_t r = static_cast<std::size_t>(std::lround(m / (period / 20))) % 20;
      EXPECT_NEAR(f.at(i, 0), -t.value(r, 10) / rb, 1e-9 * t.value(r, 10) / rb);
    }
  EXPECT_THROW(exports::force_table(t, -1, 0, "Export/Backlash"), InputError);
}
