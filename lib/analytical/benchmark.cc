#include "analytical/benchmark.h"
#include "base/units.h"

#include "analytical/from_geometry.h"
#include "analytical/mesh_cycle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <memory>
#include <vector>

namespace gearfem::analytical
{
  namespace
  {
    using units::pi;

    geometry::GearParameters gear(int z, double m, double b)
    {
      geometry::GearParameters g;
      g.teeth = z;
      g.face_width = b;
      g.rack.module = m;
      g.rack.pressure_angle = 20 * units::deg;
      return g;
    }

    /// Median wall time of `repeat` runs [s].
    double time_it(const std::function<void()> &f, int repeat)
    {
      std::vector<double> t;
      for (int i = 0; i < repeat; ++i)
        {
          const auto t0 = std::chrono::steady_clock::now();
          f();
          t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
      std::sort(t.begin(), t.end());
      return t[t.size() / 2];
    }

    void run_case(std::ostream &out, const std::string &name, const geometry::GearPair &pair,
                  const PairModelOptions &o, double bore, double b, double torque, double E)
    {
      std::unique_ptr<PairCompliance> pc;
      const double t_setup = time_it(
        [&] {
          pc = std::make_unique<PairCompliance>(involute_tooth(pair.gear(1), bore), involute_tooth(pair.gear(2), bore),
                                                Material{E, 0.3}, Material{E, 0.3}, b, pair_line(pair), o);
        },
        1);
      const MeshModel mm = pc->mesh_model();
      const double F = torque / pair.base_radius(1);
      std::vector<MeshState> cycle;
      const double t_cycle = time_it([&] { cycle = mesh_cycle(mm, F, 1000); }, 5);
      double kmax = 0;
      for (const auto &s : cycle)
        kmax = std::max(kmax, s.stiffness);
      // k(theta, F): 200 positions x 50 loads (F/10 .. 2F); T(theta, delta): 200 x 50.
      const double t_k = time_it(
        [&] {
          for (int j = 0; j < 50; ++j)
            mesh_cycle(mm, F * (0.1 + 1.9 * j / 49.0), 200);
        },
        1);
      std::vector<double> phis(200), xs(50);
      const double phiA = (mm.g_A - mm.g_C) / mm.rb1, span = mm.base_pitch / mm.rb1;
      for (int i = 0; i < 200; ++i)
        phis[i] = phiA + span * i / 200;
      const double x_ref = F / kmax;
      for (int j = 0; j < 50; ++j)
        xs[j] = x_ref * (-0.2 + 2.2 * j / 49.0);
      const double t_T = time_it([&] { torque_table(mm, phis, xs); }, 1);
      out << std::setprecision(3) << name << " (" << to_string(o.model) << "):\n"
          << "  model set-up (tooth tables, " << o.table_points << " points):  " << t_setup * 1e3 << " ms\n"
          << "  mesh stiffness, one pitch, 1000 positions:   " << t_cycle * 1e3 << " ms (target <= 10 ms)\n"
          << "  k(theta, F) table 200 x 50:                  " << t_k * 1e3 << " ms (target <= 1000 ms)\n"
          << "  T(theta, delta) table 200 x 50:              " << t_T * 1e3 << " ms (target <= 1000 ms)\n"
          << "  (max mesh stiffness " << kmax << " N/m at " << torque << " N m)\n";
    }
  } // namespace

  void benchmark(std::ostream &out)
  {
    out << "analytical benchmark (median of 5 for the 1000-position cycle)\n";
    {
      const geometry::GearPair p(geometry::ToothProfile::generate(gear(23, 4e-3, 70e-3)),
                                 geometry::ToothProfile::generate(gear(69, 4e-3, 70e-3)), {});
      PairModelOptions o;
      run_case(out, "Siasos 2010 23/69 m 4 b 70, E 205 GPa", p, o, 0.0, 70e-3, 500.0, 205e9);
    }
    {
      const geometry::GearPair p(geometry::ToothProfile::generate(gear(62, 2e-3, 20e-3)),
                                 geometry::ToothProfile::generate(gear(62, 2e-3, 20e-3)), {});
      PairModelOptions o;
      o.model = StiffnessModel::potential_energy;
      run_case(out, "62/62 m 2 b 20 bore 35, E 211 GPa", p, o, 17.5e-3, 20e-3, 100.0, 211e9);
    }
  }
} // namespace gearfem::analytical
