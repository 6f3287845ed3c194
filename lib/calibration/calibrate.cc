#include "calibration/calibrate.h"
#include "base/units.h"

#include "analytical/from_geometry.h"
#include "base/errors.h"
#include "io/solve_results.h"

#include <chrono>
#include <iomanip>
#include <sstream>

namespace gearfem::calibration
{
  namespace
  {
    using units::pi;
  }

  std::vector<SteSample> read_fe_samples(const std::vector<std::filesystem::path> &files,
                                             const std::string &hash, const std::string &entry)
  {
    std::vector<SteSample> samples;
    for (const auto &file : files)
      {
        io::SolveResults res;
        try
          {
            res = io::read_solve_results(file);
          }
        catch (const InputError &e)
          {
            throw InputError(entry + ": " + std::string(e.what()));
          }
        const std::string h = res.attributes.at("geometry_hash");
        if (h != hash)
          throw InputError(entry, file.string(), "results of this pair (geometry hash " + hash + ")",
                           "the file was computed for geometry " + h +
                             ": refusing to calibrate against another pair");
        const auto T = res.sweep.column("torque"), phi = res.sweep.column("roll angle"),
                   ste = res.sweep.column("STE");
        for (std::size_t i = 0; i < T.size(); ++i)
          samples.push_back({T[i], phi[i] * units::deg, ste[i] * 1e-6});
      }
    return samples;
  }

  Result calibrate(const an::PairCompliance &pc, const geometry::GearPair &pair,
                   const std::vector<SteSample> &samples, const Options &options)
  {
    Result r;
    for (const auto &s : samples)
      r.torques.insert(s.torque);
    if (r.torques.empty())
      throw InputError("Calibration/Results files", "(no FE positions)", "at least one solved position");
    r.plain.corner        = options.start.corner;
    r.plain.corner_radius = options.start.corner_radius;
    r.before = ste_errors(pc, r.plain, samples);
    r.fit    = fit_factors(pc, samples, options.start, options.mask);
    r.after  = ste_errors(pc, r.fit.factors, samples);
    // Cross-validation: fit without one torque, test on it.
    if (r.torques.size() >= 2)
      for (const double T : r.torques)
        {
          std::vector<SteSample> train, test;
          for (const auto &s : samples)
            (s.torque == T ? test : train).push_back(s);
          const auto f = fit_factors(pc, train, options.start, options.mask);
          r.held_out.emplace_back(T, ste_errors(pc, f.factors, test).front());
          r.held_out_factors.emplace(T, f.factors);
        }
    const auto t0 = std::chrono::steady_clock::now();
    make_tables(CalibratedMesh(pc, r.fit.factors), pc, pair, *r.torques.rbegin(), options.grid, r);
    r.table_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }

  void make_tables(const CalibratedMesh &m, const an::PairCompliance &pc, const geometry::GearPair &pair,
                   double max_fe_torque, const TableGrid &grid, Result &r)
  {
    const double rb1    = m.base_radius();
    const double period = 2 * pi / pair.gear(1).teeth();
    const double phiA   = pair.point("A").roll_angle;
    const std::string hash = geometry::geometry_fingerprint(pair);
    io::MeshTable &kt = r.stiffness, &tt = r.torque, &et = r.ste;
    kt = tt = et = io::MeshTable();
    kt.kind = io::MeshTable::Kind::stiffness_vs_load;
    tt.kind = io::MeshTable::Kind::torque_vs_compression;
    et.kind = io::MeshTable::Kind::ste_vs_torque;
    for (auto *t : {&kt, &tt, &et})
      {
        t->period = period, t->base_radius = rb1, t->geometry_hash = hash;
        for (int i = 0; i < grid.n_theta; ++i)
          t->theta.push_back(phiA + period * i / grid.n_theta);
      }
    r.F_max = grid.load_factor * max_fe_torque / rb1;
    kt.second_unit = "N", kt.value_unit = "N/m";
    for (int j = 0; j < grid.n_load; ++j)
      kt.second.push_back(r.F_max * (j + 1) / grid.n_load);
    r.delta_max = 0;
    for (const double th : kt.theta)
      for (const double F : kt.second)
        {
          const double s = m.ste(th, F);
          kt.values.push_back(F / s);
          r.delta_max = std::max(r.delta_max, s);
        }
    tt.second_unit = "m", tt.value_unit = "N*m";
    std::vector<double> drive;
    for (int j = 0; j < grid.n_load; ++j)
      drive.push_back(r.delta_max * j / (grid.n_load - 1));
    r.reverse_offset = 0;
    if (grid.backlash >= 0)
      {
        // Two-sided: reverse flank below -b, the gap [-b, 0], the drive flank above 0.
        tt.backlash      = grid.backlash;
        r.reverse_offset = reverse_offset(an::involute_tooth(pair.gear(1)), pc.line(), tt.backlash);
      }
    tt.second = io::torque_table_axis(drive, grid.backlash);
    for (const double th : tt.theta)
      for (const double d : tt.second)
        tt.values.push_back(grid.backlash >= 0 ? m.torque(th, d, tt.backlash, r.reverse_offset) :
                                                 rb1 * m.load_at(th, d));
    et.second_unit = "N*m", et.value_unit = "m";
    for (const double F : kt.second)
      et.second.push_back(F * rb1);
    for (std::size_t i = 0; i < kt.theta.size(); ++i)
      for (std::size_t j = 0; j < kt.second.size(); ++j)
        et.values.push_back(kt.second[j] / kt.value(i, j)); // STE = F / k
  }

  Table comparison_table(const Result &r, const an::PairCompliance &pc, const std::vector<SteSample> &samples)
  {
    Table cmp;
    const bool cv = !r.held_out_factors.empty();
    cmp.add_column("torque", "N m");
    cmp.add_column("roll angle", "deg");
    for (const char *n : {"STE FE", "STE before", "STE after"})
      cmp.add_column(n, "um");
    if (cv)
      cmp.add_column("STE held out", "um");
    const CalibratedMesh m0(pc, r.plain), m1(pc, r.fit.factors);
    std::map<double, CalibratedMesh> mcv;
    for (const auto &[T, f] : r.held_out_factors)
      mcv.emplace(T, CalibratedMesh(pc, f));
    const double rb1 = m1.base_radius();
    for (const auto &s : samples)
      {
        const double F = s.torque / rb1;
        std::vector<double> row = {s.torque, s.roll_angle / units::deg, s.ste * 1e6, m0.ste(s.roll_angle, F) * 1e6,
                                   m1.ste(s.roll_angle, F) * 1e6};
        if (cv)
          row.push_back(mcv.at(s.torque).ste(s.roll_angle, F) * 1e6);
        cmp.add_row(row);
      }
    return cmp;
  }

  Table ste_table(const Result &r, const an::PairCompliance &pc)
  {
    const CalibratedMesh m(pc, r.fit.factors);
    Table st;
    st.add_column("roll angle", "deg");
    st.add_column("torque", "N m");
    st.add_column("STE", "um");
    for (const double th : r.stiffness.theta)
      for (const double T : r.torques)
        st.add_row({th / units::deg, T, m.ste(th, T / m.base_radius()) * 1e6});
    return st;
  }

  std::string report(const Result &r, const std::string &model, const std::string &hash, std::size_t n_samples,
                     const std::vector<std::string> &files)
  {
    const auto &fit = r.fit;
    std::ostringstream rep;
    rep << std::setprecision(4);
    rep << "# Calibration of the " << model << " mesh model against FE STE\n\n"
        << "Geometry " << hash << ", " << n_samples << " FE positions, files: ";
    for (const auto &f : files)
      rep << f << " ";
    rep << "\n\n## Fitted factors\n\n| factor | value | standard error |\n|---|---|---|\n";
    for (std::size_t i = 0; i < fit.names.size(); ++i)
      {
        const bool body = fit.names[i] == "body compliance", re = fit.names[i] == "corner radius";
        const double s  = body ? 1e9 : re ? 1e3 : 1.0;
        rep << "| " << fit.names[i] << (body ? " [m/N x 1e-9]" : re ? " [mm]" : " [-]") << " | "
            << fit.values[i] * s << " | " << fit.std_error[i] * s << " |\n";
      }
    rep << "\nRMS relative STE error at the optimum " << fit.rms << ", " << fit.iterations
        << " Levenberg-Marquardt iterations, condition number " << fit.condition << ".\n";
    for (const auto &w : fit.warnings)
      rep << "\nwarning: " << w << "\n";
    rep << "\n## STE error against FE (relative)\n\n| T1 [N m] | before: mean | before: max | after: mean | after: max | "
           "held out: mean | held out: max |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < r.before.size(); ++i)
      {
        rep << "| " << r.before[i].torque << " | " << 100 * r.before[i].mean_abs << " % | "
            << 100 * r.before[i].max_abs << " % | " << 100 * r.after[i].mean_abs << " % | "
            << 100 * r.after[i].max_abs << " % | ";
        bool found = false;
        for (const auto &[T, e] : r.held_out)
          if (T == r.before[i].torque)
            rep << 100 * e.mean_abs << " % | " << 100 * e.max_abs << " % |\n", found = true;
        if (!found)
          rep << "- | - |\n";
      }
    rep << "\n`held out`: factors fitted on the other torques only, tested on this one";
    if (!r.held_out_factors.empty())
      {
        rep << " (beam / foundation / Hertz multipliers, body compliance [m/N x 1e-9], corner radius [mm]):\n\n";
        for (const auto &[T, f] : r.held_out_factors)
          rep << "- without " << T << " N m: " << f.beam << " / " << f.foundation << " / " << f.hertz << ", "
              << f.body * 1e9 << ", " << f.corner_radius * 1e3 << "\n";
      }
    else
      rep << ".\n";
    return rep.str();
  }

  CycleTiming time_cycle(const CalibratedMesh &m, const an::PairCompliance &pc, double torque, int positions)
  {
    const auto &L  = pc.line();
    const double F = torque / L.rb1;
    double sum     = 0;
    const auto t0  = std::chrono::steady_clock::now();
    for (int i = 0; i < positions; ++i)
      sum += m.ste((L.g_A - L.g_C + i * L.base_pitch / positions) / L.rb1, F);
    CycleTiming c;
    c.seconds  = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    c.mean_ste = sum / positions;
    return c;
  }
} // namespace gearfem::calibration
