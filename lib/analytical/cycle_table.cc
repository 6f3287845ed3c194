#include "analytical/cycle_table.h"
#include "base/units.h"

#include "analytical/ricker_load_sharing.h"
#include "base/errors.h"
#include "base/roots.h"

#include <chrono>
#include <cmath>

namespace gearfem::analytical
{
  CycleLaw cycle_law_from_string(const std::string &s)
  {
    if (s == "load sharing")
      return CycleLaw::load_sharing;
    if (s == "seed000 ricker")
      return CycleLaw::ricker;
    throw InputError("Analytical/Mesh cycle law", s, "load sharing | seed000 ricker");
  }

  namespace
  {
    struct Row
    {
      double roll_angle, pairs, ste, stiffness;
      std::vector<double> loads; // A side first
    };

    /// Compression x [m] with sa.load(phi1, x) = F: bracket grown geometrically from the
    /// linear guess F/k_mean, then TOMS 748 to 1e-12.
    double ricker_compression(const RickerSemiAnalytical &sa, double phi1, double F, double k_mean)
    {
      double lo = 0.25 * F / k_mean, hi = 4.0 * F / k_mean;
      const auto f = [&](double x) { return sa.load(phi1, x) - F; };
      for (int i = 0; i < 40 && f(lo) > 0; ++i)
        lo *= 0.25;
      for (int i = 0; i < 40 && f(hi) < 0; ++i)
        hi *= 4.0;
      return base::find_root(f, lo, hi, 1e-12, 200, "Ricker law (Gkimisis 2019): load(phi1, x) = F");
    }

    std::vector<Row> ricker_cycle(const CycleInput &in, const std::vector<MeshState> &ls, double F)
    {
      double k_mean = 0;
      for (const auto &s : ls)
        k_mean += s.stiffness / ls.size();
      const RickerSemiAnalytical sa(in.pinion, in.gear, in.m1, in.m2, in.face_width, in.line, k_mean, in.options,
                                     in.ricker_widening);
      const double pitch = in.line.base_pitch / in.line.rb1;
      std::vector<Row> rows;
      for (const auto &s : ls)
        {
          const double phi = s.roll_angle;
          const double x   = ricker_compression(sa, phi, F, k_mean);
          const double other = phi - (phi >= 0.0 ? 1.0 : -1.0) * pitch; // eq. 3.45
          const double F_main  = sa.pair_stiffness(in.line.g_C + in.line.rb1 * phi, x) * x;
          const double F_other = (1.0 - sa.ricker_weight(phi, x)) *
                                 sa.pair_stiffness(in.line.g_C + in.line.rb1 * other, x) * x;
          Row r{phi, 0, x, F / x, {}};
          r.loads = phi >= 0.0 ? std::vector<double>{F_other, F_main} : std::vector<double>{F_main, F_other};
          r.pairs = (F_other > 1e-6 * F ? 1 : 0) + (F_main > 1e-6 * F ? 1 : 0);
          rows.push_back(r);
        }
      return rows;
    }
  } // namespace

  CycleTable mesh_cycle_table(const CycleInput &in, CycleLaw law, const std::vector<double> &torques,
                              int positions)
  {
    if (positions < 2)
      throw InputError("Analytical/Mesh positions", std::to_string(positions), ">= 2");
    CycleTable out;
    auto &t = out.table;
    t.add_column("pinion torque", "N m");
    t.add_column("roll angle", "deg");
    t.add_column("pairs in contact", "-");
    t.add_column("loaded STE", "um");
    t.add_column("mesh stiffness", "N/um");
    for (int j = 1; j <= 3; ++j)
      t.add_column("load pair " + std::to_string(j), "N");

    const PairCompliance pc(in.pinion, in.gear, in.m1, in.m2, in.face_width, in.line, in.options);
    const MeshModel mm = pc.mesh_model(in.corner_contact);
    std::vector<std::vector<Row>> all;
    const auto t0 = std::chrono::steady_clock::now();
    for (const double T : torques)
      {
        if (!(T > 0))
          throw InputError("Rating/Pinion torques", std::to_string(T), "> 0 N m");
        const double F = T / in.line.rb1;
        const auto cycle = mesh_cycle(mm, F, positions);
        if (law == CycleLaw::ricker)
          all.push_back(ricker_cycle(in, cycle, F));
        else
          {
            std::vector<Row> rows;
            for (const auto &s : cycle)
              rows.push_back({s.roll_angle, double(s.g.size()), s.deflection, s.stiffness, s.pair_load});
            all.push_back(rows);
          }
      }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    for (std::size_t i = 0; i < torques.size(); ++i)
      {
        double kmin = 1e300, kmax = 0, ksum = 0;
        for (const Row &r : all[i])
          {
            std::vector<double> row{torques[i], r.roll_angle / units::deg, r.pairs, r.ste * 1e6, r.stiffness * 1e-6,
                                    0, 0, 0};
            for (std::size_t j = 0; j < r.loads.size() && j < 3; ++j)
              row[5 + j] = r.loads[j];
            t.add_row(row);
            kmin = std::min(kmin, r.stiffness), kmax = std::max(kmax, r.stiffness), ksum += r.stiffness;
          }
        out.torques.push_back(torques[i]);
        out.k_min.push_back(kmin), out.k_max.push_back(kmax), out.k_mean.push_back(ksum / all[i].size());
      }
    return out;
  }
} // namespace gearfem::analytical
